/* The BSDF reader of Tungsten scenes (bsdf_json.c), and the scene model loaded with it. The scene
 * loader (scene/) comes before bsdf/ and cannot name this reader: it is handed it, and this is the
 * first folder that knows both halves. */
#ifndef BSDF_JSON_H
#define BSDF_JSON_H

#include "scene/scene.h"

extern const struct scene_bsdf_reader bsdf_json_reader;

/* scene_read_model with this reader: the model as the file describes it, BSDFs checked against
 * their implementations, not yet render-ready (path/scene_ready.h's scene_load is). */
static inline struct scene *scene_load_model(const char *path, char *err, size_t errlen)
{
    return scene_read_model(path, &bsdf_json_reader, err, errlen);
}

#endif
