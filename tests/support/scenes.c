#include "support/scenes.h"
#include "path/scene_ready.h"
#include <criterion/criterion.h>
#include <glob.h>
#include <stdlib.h>
#include <string.h>

struct scene *test_scene(const char *path)
{
    char err[1024];
    struct scene *s = scene_load(path, err, sizeof err);
    cr_assert(s != NULL, "cannot load %s: %s", path, err);
    return s;
}

const char **test_all_scenes(void)
{
    static const char *list[64];
    static glob_t g;
    static int done;
    if (!done) {
        glob("scenes/*/scene.json", 0, NULL, &g);
        size_t n = g.gl_pathc < 63 ? g.gl_pathc : 63;
        for (size_t i = 0; i < n; i++)
            list[i] = g.gl_pathv[i];
        list[n] = NULL;
        done = 1;
    }
    return list;
}
