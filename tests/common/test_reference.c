/* common/reference.h: an in-process reference is rendered once, reused while the scene and the
 * settings are the same (the image file is not rewritten), rendered again when a setting changes,
 * and its key is exactly the text the figure tools' .key files hold. */
#include "base/util.h"
#include "common/reference.h"
#include "io/image.h"
#include "path/scene_ready.h"
#include "scene/scene_hash.h"
#include "support/scenes.h"
#include <criterion/criterion.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The EXR's inode: a render replaces the file (atomic rename), a cache hit leaves it. */
static ino_t inode(const char *path)
{
    struct stat st;
    cr_assert(stat(path, &st) == 0, "%s missing", path);
    return st.st_ino;
}

static struct image *get(const struct scene *sc, const char *path, int spp)
{
    char err[1024];
    struct reference_spec spec = {
        .path = path, .method = METHOD_PT, .spp = spp, .seed = 12345, .max_length = 5, .threads = 1};
    struct image *im = reference_render_cached("test", sc, &spec, err, sizeof err);
    cr_assert(im, "%s", err);
    return im;
}

Test(common_reference, cached_until_a_setting_changes_and_keyed_by_the_scene)
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 8, 6);
    char dir[] = "/tmp/reference-XXXXXX", path[128], key_path[128], want[256];
    cr_assert(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/sub/pt.exr", dir); /* the folder is made */
    snprintf(key_path, sizeof key_path, "%s/sub/pt.key", dir);
    struct image *a = get(sc, path, 2);
    ino_t first = inode(path);
    struct image *b = get(sc, path, 2);
    cr_assert_eq(inode(path), first, "same scene and settings: the cached file, not a new render");
    cr_assert(a->w == 8 && a->h == 6 && b->w == 8 && b->h == 6);
    for (int i = 0; i < 3 * 8 * 6; i++) /* the EXR holds floats */
        cr_assert(fabs(a->px[i] - b->px[i]) <= 1e-6 * fmax(1, fabs(a->px[i])), "pixel value %d: %g vs %g", i, a->px[i],
                  b->px[i]);
    snprintf(want, sizeof want, "reference-v1 scene=%016llx pt spp=2 seed=12345 max_length=5 resolution=8x6\n",
             (unsigned long long)ckpt_scene_hash(sc));
    char *key = read_whole_file(key_path);
    cr_assert(key && !strcmp(key, want), "key: %s, want %s", key ? key : "(none)", want);
    free(key);
    struct image *c = get(sc, path, 3);
    cr_assert_neq(inode(path), first, "another spp renders again");
    key = read_whole_file(key_path);
    cr_assert(key && strstr(key, " spp=3 "), "key: %s", key ? key : "(none)");
    free(key);
    img_destroy(a), img_destroy(b), img_destroy(c);
    scene_free(sc);
    unlink(path), unlink(key_path);
    snprintf(path, sizeof path, "%s/sub", dir);
    rmdir(path), rmdir(dir);
}
