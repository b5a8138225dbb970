/* Typed getters over cJSON that report bad input as one line, "FILE: JSON.PATH: expectation".
 * The first error wins: later failures never overwrite it, so callers can bail out lazily.
 * Paths are built by the caller (jpath_key/jpath_idx) as it descends; getters append the key. */
#ifndef JSON_GET_H
#define JSON_GET_H

#include "base/vecmath.h"
#include <cjson/cJSON.h>
#include <stdbool.h>
#include <stddef.h>

#define JPATH_MAX 256

struct jctx {
    const char *file; /* scene file as given, for messages */
    char *err;
    size_t errlen;
    bool failed;
};

/* Records "FILE: PATH: message" (or "FILE: message" when path is empty); always returns false. */
bool jfail(struct jctx *c, const char *path, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* One warning line on stderr: "FILE: PATH: warning: message". */
void jwarn(const struct jctx *c, const char *path, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* out = parent.key / parent[i]; the root has an empty path. */
void jpath_key(char out[JPATH_MAX], const char *parent, const char *key);
void jpath_idx(char out[JPATH_MAX], const char *parent, int i);

/* Each getter: absent key and !required → leaves *out untouched, returns true.
 * Wrong type, non-finite value or absent required key → jfail, returns false. */
bool jget_number(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, double *out);
bool jget_int(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, int lo, int hi,
              int *out);
bool jget_bool(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, bool *out);
bool jget_string(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, const char **out);
/* A number (broadcast to all three, as Tungsten's Vec parsing does) or an array of 3 numbers. */
bool jget_vec3(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, vec3 *out);
/* Same, for a value already fetched (path names the value itself). */
bool jval_vec3(struct jctx *c, const cJSON *v, const char *path, vec3 *out);
bool jval_number(struct jctx *c, const cJSON *v, const char *path, double *out);

#endif
