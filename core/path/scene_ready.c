/* The render-ready scene (scene_ready.h). */
#include "path/scene_ready.h"
#include "base/util.h"
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_json.h"
#include "emitter/emitter.h"
#include "scene/accel.h"
#include <stdio.h>
#include <stdlib.h>

/* Per-triangle unit normals: every hit needs one, so they are computed once. */
static void build_triangle_normals(struct prim *p)
{
    p->tri_n = xmalloc(sizeof(vec3) * (size_t)(p->ntris ? p->ntris : 1));
    for (int i = 0; i < p->ntris; i++) {
        const int *t = p->tri + 3 * i;
        p->tri_n[i] = vnorm(vcross(vsub(p->p[t[1]], p->p[t[0]]), vsub(p->p[t[2]], p->p[t[0]])));
    }
}

struct scene *scene_load(const char *path, char *err, size_t errlen)
{
    struct scene *s = scene_load_model(path, err, errlen);
    if (!s) return NULL;
    for (int i = 0; i < s->nprims; i++)
        if (s->prims[i].kind == PRIM_MESH || s->prims[i].kind == PRIM_QUAD) build_triangle_normals(&s->prims[i]);
    for (int i = 0; i < s->nbsdfs; i++) {
        if (s->bsdfs[i].type != BSDF_NULL && !bsdf_ops_for(s->bsdfs[i].type)) {
            snprintf(err, errlen, "%s: bsdfs[%s]: BSDF type not available in this build", path, s->bsdfs[i].name);
            scene_free(s);
            return NULL;
        }
    }
    bsdf_prepare_all(s->bsdfs, s->nbsdfs);
    if (!(s->emitters = emitters_build(s, err, errlen)) || !(s->accel = accel_build(s, err, errlen))) {
        scene_free(s);
        return NULL;
    }
    return s;
}

void scene_free(struct scene *s)
{
    if (!s) return;
    emitters_free(s->emitters);
    accel_free(s->accel);
    for (int i = 0; i < s->nprims; i++) {
        free(s->prims[i].tri_n);
        s->prims[i].tri_n = NULL;
    }
    scene_model_free(s);
}
