/* The render-ready scene: the loaded model (scene/scene.h) with its BSDFs prepared, its emitter
 * table and its ray-query structure built, as Tungsten's TraceableScene is built from its Scene. */
#ifndef SCENE_READY_H
#define SCENE_READY_H

#include "scene/scene.h"

/* Loads a Tungsten JSON scene ready to render. On bad input returns NULL and writes one line into
 * err: "FILE: JSON.PATH: what was expected". */
struct scene *scene_load(const char *path, char *err, size_t errlen);
void scene_free(struct scene *s);

#endif
