/* OpenImageIO is opened on the first image read, not at start-up nor to write (core/io/oiio.h,
 * core/io/image_encode.h): a render that has written its EXR and PNG has none of its libraries
 * mapped; the files it wrote read back with the same pixels, and hold the very pixels OpenImageIO's
 * own writers gave. Criterion runs each test in a process of its own, so "not yet loaded" is a
 * property of one test alone. */
#include <criterion/criterion.h>

#include "base/util.h"
#include "camera/camera.h"
#include "io/image.h"
#include "io/image_encode.h"
#include "io/oiio.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "support/scenes.h"
#include <math.h>
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

Test(image_io, openimageio_opens_on_first_image_read_only)
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
    snprintf(path, sizeof path, "%s/x.png", dir);
    cr_assert(img_write_png(im, 1.0, path, err, sizeof err), "%s", err);
    unlink(path);
    cr_assert(!oiio_loaded() && !mapped("libOpenImageIO"), "writing an EXR or a PNG opened OpenImageIO");

    snprintf(path, sizeof path, "%s/x.exr", dir);
    struct image *back = img_read(path, err, sizeof err);
    cr_assert(back, "%s", err);
    cr_assert(oiio_loaded() && mapped("libOpenImageIO"), "reading an EXR did not open the module");
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

/* Values that probe each encoder's conversions: negative, above 1, tiny, huge, the 8-bit rounding's
 * half-way points (k + 0.5) / 255 and values 4 floats either side, NaN and infinities. Not one float
 * either side: there OpenImageIO's own vector and scalar paths round the same value differently
 * (255 v + 0.5 truncated in float against roundf), so no encoder matches it everywhere. */
static float probe(int i)
{
    static const float special[] = {0.0f, -0.25f, 1.0f, 1.5f, 1e-30f, 3e38f, 0.5f / 255, 1.5f / 255, 254.5f / 255};
    int ns = (int)(sizeof special / sizeof special[0]);
    if (i < ns) return special[i];
    if (i == ns) return NAN;
    if (i == ns + 1) return INFINITY;
    if (i == ns + 2) return -INFINITY;
    float half = ((float)(i % 256) + 0.5f) / 255.0f;
    float step = half;
    for (int k = 0; k < 4 && i % 3; k++)
        step = nextafterf(step, i % 3 == 1 ? 0 : 1);
    return step;
}

/* Reads `path` through the module: the pixels of either writer's file, compared bit for bit. */
static float *read_all(const char *path, int *w, int *h)
{
    char err[1024];
    int nc;
    float *px;
    cr_assert(oiio_read_channels(path, w, h, &nc, &px, NULL, err, sizeof err), "%s", err);
    cr_assert_eq(nc, 3);
    return px;
}

Test(image_io, encoders_write_the_pixels_openimageio_wrote)
{
    enum { W = 37, H = 41 }; /* not a multiple of a ZIP block's 16 lines */
    static float px[W * H * 3];
    for (int i = 0; i < W * H * 3; i++)
        px[i] = probe(i);
    char dir[] = "/tmp/image-enc-XXXXXX", ours[96], theirs[96], err[1024];
    cr_assert(mkdtemp(dir));
    static const char *const ext[] = {"exr", "png"};
    for (int f = 0; f < 2; f++) {
        snprintf(ours, sizeof ours, "%s/ours.%s", dir, ext[f]);
        snprintf(theirs, sizeof theirs, "%s/theirs.%s", dir, ext[f]);
        unsigned char *bytes;
        size_t len;
        bool ok = f == 0 ? exr_encode_rgb(W, H, px, &bytes, &len, err, sizeof err)
                         : png_encode_rgb8(W, H, px, &bytes, &len, err, sizeof err);
        cr_assert(ok, "%s", err);
        cr_assert(write_chunks(ours, &(struct chunk){bytes, len}, 1, err, sizeof err), "%s", err);
        free(bytes);
        cr_assert(oiio_write(theirs, W, H, 3, px, err, sizeof err), "%s", err);
        int wa, ha, wb, hb;
        float *a = read_all(ours, &wa, &ha), *b = read_all(theirs, &wb, &hb);
        cr_assert(wa == W && ha == H && wb == W && hb == H);
        for (int i = 0; i < W * H * 3; i++)
            cr_assert(!memcmp(&a[i], &b[i], sizeof(float)) || (a[i] != a[i] && b[i] != b[i]),
                      "%s value %d (%.9g): ours reads back as %.9g, OpenImageIO's as %.9g", ext[f], i, (double)px[i],
                      (double)a[i], (double)b[i]);
        free(a);
        free(b);
        unlink(ours);
        unlink(theirs);
    }
    rmdir(dir);
}
