/* OpenImageIO is opened on the first image read or write, not at start-up (core/io/oiio.h): a render
 * that has not touched an image has none of its libraries mapped, and the module, once opened,
 * writes and reads back the same pixels. Criterion runs each test in a process of its own, so
 * "not yet loaded" is a property of this test alone. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "io/image.h"
#include "io/oiio.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "support/scenes.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static bool mapped(const char *lib)
{
    FILE *f = fopen("/proc/self/maps", "r");
    cr_assert(f);
    char line[4096];
    bool found = false;
    while (!found && fgets(line, sizeof line, f))
        found = strstr(line, lib) != NULL;
    fclose(f);
    return found;
}

Test(image_io, openimageio_opens_on_first_image_write_only)
{
    cr_assert(!oiio_loaded() && !mapped("libOpenImageIO"), "OpenImageIO mapped before any image I/O");
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 16, 12);
    struct render_opts o = {.method = METHOD_PT, .spp = 2, .seed = 7, .threads = 1, .max_length = 8};
    struct render_stats st;
    struct image *im = render_mc(sc, &o, &st);
    cr_assert(!oiio_loaded() && !mapped("libOpenImageIO"), "rendering opened OpenImageIO");

    char dir[] = "/tmp/image-io-XXXXXX", path[64], err[1024];
    cr_assert(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/x.exr", dir);
    cr_assert(img_write_exr(im, 1.0, path, err, sizeof err), "%s", err);
    cr_assert(oiio_loaded() && mapped("libOpenImageIO"), "writing an EXR did not open the module");

    struct image *back = img_read(path, err, sizeof err);
    cr_assert(back, "%s", err);
    cr_assert(back->w == im->w && back->h == im->h);
    for (size_t i = 0; i < (size_t)im->w * im->h * 3; i++)
        cr_assert_eq(back->px[i], (double)(float)im->px[i], "pixel value %zu: %g read back as %g", i, im->px[i],
                     back->px[i]);
    unlink(path);
    rmdir(dir);
    img_destroy(back);
    img_destroy(im);
    scene_free(sc);
}
