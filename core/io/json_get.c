/* Typed JSON getters with path-carrying error messages (see json_get.h). */
#include "io/json_get.h"
#include "base/util.h"
#include <stdarg.h>
#include <stdio.h>

bool jfail(struct jctx *c, const char *path, const char *fmt, ...)
{
    if (c->failed) return false;
    c->failed = true;
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (path && path[0])
        snprintf(c->err, c->errlen, "%s: %s: %s", c->file, path, msg);
    else
        snprintf(c->err, c->errlen, "%s: %s", c->file, msg);
    if (c->errlen) str_sanitize(c->err);
    return false;
}

void jwarn(const struct jctx *c, const char *path, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    str_sanitize(msg);
    if (path && path[0])
        fprintf(stderr, "%s: %s: warning: %s\n", c->file, path, msg);
    else
        fprintf(stderr, "%s: warning: %s\n", c->file, msg);
}

void jpath_key(char out[JPATH_MAX], const char *parent, const char *key)
{
    if (parent && parent[0])
        snprintf(out, JPATH_MAX, "%s.%s", parent, key);
    else
        snprintf(out, JPATH_MAX, "%s", key);
}

void jpath_idx(char out[JPATH_MAX], const char *parent, int i)
{
    snprintf(out, JPATH_MAX, "%s[%d]", parent ? parent : "", i);
}

/* Fetches obj.key (NULL if absent); a missing required key is an error. */
static const cJSON *member(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required,
                           char kpath[JPATH_MAX])
{
    jpath_key(kpath, path, key);
    const cJSON *v = cJSON_IsObject(obj) ? cJSON_GetObjectItemCaseSensitive(obj, key) : NULL;
    if (!v && required) jfail(c, kpath, "missing required field");
    return v;
}

bool jval_number(struct jctx *c, const cJSON *v, const char *path, double *out)
{
    if (!cJSON_IsNumber(v)) return jfail(c, path, "expected a number");
    /* JSON has no NaN, but an overflowing literal such as 1e999 parses to infinity. */
    if (!isfinite(v->valuedouble)) return jfail(c, path, "expected a finite number");
    *out = v->valuedouble;
    return true;
}

bool jget_number(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, double *out)
{
    char kp[JPATH_MAX];
    const cJSON *v = member(c, obj, path, key, required, kp);
    if (!v) return !required;
    return jval_number(c, v, kp, out);
}

bool jget_int(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, int lo, int hi,
              int *out)
{
    char kp[JPATH_MAX];
    const cJSON *v = member(c, obj, path, key, required, kp);
    if (!v) return !required;
    if (!cJSON_IsNumber(v) || !isfinite(v->valuedouble) || v->valuedouble != floor(v->valuedouble) ||
        v->valuedouble < lo || v->valuedouble > hi)
        return jfail(c, kp, "expected an integer in [%d, %d]", lo, hi);
    *out = (int)v->valuedouble;
    return true;
}

bool jget_bool(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, bool *out)
{
    char kp[JPATH_MAX];
    const cJSON *v = member(c, obj, path, key, required, kp);
    if (!v) return !required;
    if (!cJSON_IsBool(v)) return jfail(c, kp, "expected true or false");
    *out = cJSON_IsTrue(v);
    return true;
}

bool jget_string(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, const char **out)
{
    char kp[JPATH_MAX];
    const cJSON *v = member(c, obj, path, key, required, kp);
    if (!v) return !required;
    if (!cJSON_IsString(v)) return jfail(c, kp, "expected a string");
    *out = v->valuestring;
    return true;
}

bool jval_vec3(struct jctx *c, const cJSON *v, const char *path, vec3 *out)
{
    const char *expect = "expected a number or an array of 3 numbers";
    if (cJSON_IsNumber(v)) {
        double d = 0;
        if (!jval_number(c, v, path, &d)) return false;
        *out = v3s(d);
        return true;
    }
    if (!cJSON_IsArray(v) || cJSON_GetArraySize(v) != 3) return jfail(c, path, "%s", expect);
    double e[3];
    for (int i = 0; i < 3; i++) {
        const cJSON *x = cJSON_GetArrayItem(v, i);
        if (!cJSON_IsNumber(x)) return jfail(c, path, "%s", expect);
        if (!isfinite(x->valuedouble)) return jfail(c, path, "expected finite numbers");
        e[i] = x->valuedouble;
    }
    *out = v3(e[0], e[1], e[2]);
    return true;
}

bool jget_vec3(struct jctx *c, const cJSON *obj, const char *path, const char *key, bool required, vec3 *out)
{
    char kp[JPATH_MAX];
    const cJSON *v = member(c, obj, path, key, required, kp);
    if (!v) return !required;
    return jval_vec3(c, v, kp, out);
}
