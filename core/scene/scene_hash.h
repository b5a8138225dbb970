/* The scene's identity for checkpoints (io/checkpoint.h's ckpt_id.scene). */
#ifndef SCENE_HASH_H
#define SCENE_HASH_H

#include "scene/scene.h"
#include <stdint.h>

/* A hash of the loaded data (camera, BSDFs, their textures, geometry and emission), field by
 * field so that struct padding never enters it. */
uint64_t ckpt_scene_hash(const struct scene *sc);

#endif
