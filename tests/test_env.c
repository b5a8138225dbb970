/* The path tracer under an environment emitter (tests/data/env_sphere.json): a convex lambert
 * sphere (albedo 0.5) under a constant white environment has radiance exactly 0.5 everywhere, which
 * holds only if the light samples toward the environment and the escaping BSDF samples are
 * weighted consistently; background pixels are exactly 1. Methods without environment support
 * refuse the scene. */
#include <criterion/criterion.h>

#include "render.h"
#include "scenes.h"

/* 32x32 pixels, 256 spp; the centre 8x8 pixels lie on the sphere. Their mean must be 0.5 within
 * 4 standard errors (from the pixel spread, 64 pixels) and within 1 %. */
Test(stat_env, pt_constant_environment_sphere)
{
    struct scene *sc = test_scene("tests/data/env_sphere.json");
    struct render_opts o = {.method = METHOD_PT, .spp = 256, .seed = 3, .threads = 2, .max_length = 4};
    struct render_stats st;
    struct image *im = render_mc(sc, &o, &st);
    double s = 0, s2 = 0;
    for (int y = 12; y < 20; y++)
        for (int x = 12; x < 20; x++) {
            double v = img_get(im, x, y).y;
            s += v;
            s2 += v * v;
        }
    double m = s / 64, se = sqrt((s2 / 64 - m * m) / 63);
    cr_assert(fabs(m - 0.5) < 4 * se && fabs(m - 0.5) < 0.005, "sphere radiance %g +- %g, expected 0.5", m, se);
    cr_assert(fabs(img_get(im, 0, 0).x - 1) < 1e-12 && fabs(img_get(im, 31, 31).z - 1) < 1e-12, "background is not 1");
    img_destroy(im);
    scene_free(sc);
}
