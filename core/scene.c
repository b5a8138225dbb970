/* A render-ready scene: the loaded model plus its emitter table and ray-query structure. */
#include "accel.h"
#include "bsdf.h"
#include "emitter.h"
#include "scene.h"
#include <stdio.h>

struct scene *scene_load(const char *path, char *err, size_t errlen)
{
    struct scene *s = scene_load_model(path, err, errlen);
    if (!s) return NULL;
    for (int i = 0; i < s->nbsdfs; i++) {
        if (s->bsdfs[i].type != BSDF_NULL && !bsdf_ops_for(s->bsdfs[i].type)) {
            snprintf(err, errlen, "%s: bsdfs[%s]: BSDF type not available in this build", path, s->bsdfs[i].name);
            scene_free(s);
            return NULL;
        }
        bsdf_prepare(&s->bsdfs[i]);
    }
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
    scene_model_free(s);
}
