/* Shared state of the scene loader's files, and what the loader offers the one reader of a scene's
 * part that lives in a later folder: the BSDF reader (bsdf/bsdf_json.c), which must know which
 * BSDF types are implemented and how many numbers each draws. Calls run one way: scene_load.c (the
 * entry) -> scene_prims.c -> the BSDF reader -> load_resource.c (files the scene names),
 * json_transform.c beside them; the BSDF reader is handed to the loader (struct scene_bsdf_reader),
 * so scene/ never names bsdf/ (core/README.md, "Folders"). */
#ifndef SCENE_LOAD_INTERNAL_H
#define SCENE_LOAD_INTERNAL_H

#include "io/json_get.h"
#include "scene/scene.h"

struct loader {
    struct jctx c;
    struct scene *s;
    /* reads the "bsdfs" and each primitive's "bsdf" (bsdf/bsdf_json.c) */
    const struct scene_bsdf_reader *bsdf;
    const cJSON *bsdfs_json; /* top-level "bsdfs" array (or NULL): names resolve against it */
    char dir[4096];          /* directory of the scene file: resources are relative to it */
    int bsdf_cap;            /* s->bsdfs is allocated once with this many slots */
    int default_bsdf;        /* lambert albedo 1 for primitives without "bsdf", or -1 */
};

/* load_resource.c: a resource name resolved relative to the scene file (false if the result does
 * not fit), and a texture given as a file name, {"type": "bitmap", "file": ...}, or a checker or
 * constant object (v is the value at path; v a string or an object). */
bool loader_resource(const struct loader *L, const char *rel, char *out, size_t n);
bool load_texture_value(struct loader *L, const cJSON *v, const char *path, struct texture **out);
/* textures: a texture value (file name, bitmap, checker or constant object) read as Tungsten's
 * REQUEST_AVERAGE reads it (roughness, bump): a bitmap's channels averaged. */
bool load_texture_average(struct loader *L, const cJSON *v, const char *path, struct texture **out);
/* scene_shapes.c: Tungsten's disk and cylinder as fine meshes (path: the primitive, for errors). */
bool build_disk(struct loader *L, const char *path, struct prim *p, const mat4 *m);
bool build_cylinder(struct loader *L, const char *path, struct prim *p, const mat4 *m, bool capped);

/* The BSDF reader (bsdf/bsdf_json.h's bsdf_json_reader), in the order the loader calls it. */
struct scene_bsdf_reader {
    /* Slots a bsdf value (object, name, array of them) can take in scene.bsdfs, nested ones included. */
    int (*slots)(const cJSON *v);
    /* The top-level "bsdfs" array (L->bsdfs_json) into slots 0..n-1. */
    bool (*load_all)(struct loader *L);
    /* Resolves prim.bsdf (name, inline object, or absent → Tungsten's default lambert). */
    bool (*load_ref)(struct loader *L, const cJSON *prim, const char *path, int prim_index, int *out);
    /* After the primitives: refuses cycles of named nested bsdfs and bsdfs that draw more numbers
     * than a vertex's block holds. */
    bool (*check)(struct loader *L);
};

bool load_primitives(struct loader *L, const cJSON *arr);

/* scene_refused.c: why a Tungsten type the harness knows by name is not rendered, or NULL when
 * the name is not one of them (then it is simply unknown). */
enum refused_kind { REFUSED_PRIMITIVE, REFUSED_BSDF, REFUSED_TEXTURE, REFUSED_CAMERA };
const char *refused_feature(enum refused_kind kind, const char *name);

/* Tungsten transform: {"position", "scale", "rotation", "look_at", "up", "x_axis", ...} or 16 numbers. */
bool jval_transform(struct jctx *c, const cJSON *v, const char *path, mat4 *out);

#endif
