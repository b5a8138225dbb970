/* Loading the committed scenes in tests (paths relative to the repository root, where the test
 * runner is started by `make test`). */
#ifndef TEST_SCENES_H
#define TEST_SCENES_H

#include "scene/scene.h"

/* Loads or fails the current test with the loader's message. */
struct scene *test_scene(const char *path);
/* NULL-terminated list of every scenes/ * /scene.json. */
const char **test_all_scenes(void);

#endif
