/* Shared state of the scene loader files. Not a public interface. Calls run one way:
 * scene_load.c (the entry) -> scene_prims.c -> scene_bsdf.c -> load_resource.c (files the scene
 * names), json_transform.c beside them. */
#ifndef SCENE_LOAD_INTERNAL_H
#define SCENE_LOAD_INTERNAL_H

#include "io/json_get.h"
#include "scene/scene.h"

struct loader {
    struct jctx c;
    struct scene *s;
    const cJSON *bsdfs_json; /* top-level "bsdfs" array (or NULL): names resolve against it */
    char dir[4096];          /* directory of the scene file: resources are relative to it */
    int bsdf_cap;            /* s->bsdfs is allocated once with this many slots */
    int default_bsdf;        /* lambert albedo 1 for primitives without "bsdf", or -1 */
};

/* load_resource.c: a resource name resolved relative to the scene file (false if the result does
 * not fit), and a bitmap given as a file name or {"type": "bitmap", "file": ...} (v is the value
 * at path). */
bool loader_resource(const struct loader *L, const char *rel, char *out, size_t n);
bool load_texture_value(struct loader *L, const cJSON *v, const char *path, struct texture **out);
/* The same bitmap as a scalar texture, Tungsten's REQUEST_AVERAGE (no gamma table; mixed's ratio). */
bool load_texture_average(struct loader *L, const cJSON *v, const char *path, struct texture **out);

bool load_bsdfs(struct loader *L);
/* Slots a bsdf value (object, name, array of them) can take in scene.bsdfs, nested ones included. */
int bsdf_json_slots(const cJSON *v);
/* Refuses cycles of named nested bsdfs (after loading). */
bool check_bsdf_nesting(struct loader *L);
/* Resolves prim.bsdf (name, inline object, or absent → Tungsten's default lambert). */
bool load_bsdf_ref(struct loader *L, const cJSON *prim, const char *path, int prim_index, int *out);

bool load_primitives(struct loader *L, const cJSON *arr);

/* scene_refused.c: why a Tungsten type the harness knows by name is not rendered, or NULL when
 * the name is not one of them (then it is simply unknown). */
enum refused_kind { REFUSED_PRIMITIVE, REFUSED_BSDF, REFUSED_TEXTURE, REFUSED_CAMERA };
const char *refused_feature(enum refused_kind kind, const char *name);

/* Tungsten transform: {"position", "scale", "rotation", "look_at", "up", "x_axis", ...} or 16 numbers. */
bool jval_transform(struct jctx *c, const cJSON *v, const char *path, mat4 *out);

#endif
