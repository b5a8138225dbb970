/* experiments/ch6/glossy_mask and the statistics measured on it (core/stats: relmse_where and the
 * masked block statistics): the MMLT paper's "artifacts on glossy surfaces" are measured where the
 * first hit is glossy, and only there. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

#include "base/util.h"
#include "common/glossy_mask.h"
#include "path/scene_ready.h"
#include "stats/error_stats.h"
#include "stats/noise_corr.h"

Test(glossy_mask, rough_lobes_are_glossy_and_nested_ones_count)
{
    struct bsdf lam = {.type = BSDF_LAMBERT}, rc = {.type = BSDF_ROUGH_CONDUCTOR}, pl = {.type = BSDF_PLASTIC},
                rp = {.type = BSDF_ROUGH_PLASTIC}, ph = {.type = BSDF_PHONG}, mir = {.type = BSDF_MIRROR};
    cr_expect(!bsdf_is_glossy(&lam) && !bsdf_is_glossy(&pl) && !bsdf_is_glossy(&mir));
    cr_expect(bsdf_is_glossy(&rc) && bsdf_is_glossy(&rp) && bsdf_is_glossy(&ph));
    struct bsdf mix = {.type = BSDF_MIXED, .child = {&lam, &ph}}, mix2 = {.type = BSDF_MIXED, .child = {&lam, &pl}};
    struct bsdf coat = {.type = BSDF_SMOOTH_COAT, .child = {&rc}};
    cr_expect(bsdf_is_glossy(&mix) && !bsdf_is_glossy(&mix2) && bsdf_is_glossy(&coat));
}

/* The gold sphere under the camera: its centre pixels glossy, the plane's corners not, at the
 * scene's resolution and at another. */
Test(glossy_mask, the_sphere_is_glossy_and_the_plane_is_not)
{
    char err[512];
    struct scene *sc = scene_load("tests/data/glossy-sphere.json", err, sizeof err);
    cr_assert(sc, "%s", err);
    for (int r = 0; r < 2; r++) {
        if (r) camera_resize(&sc->cam, 48, 16);
        int w = sc->cam.width, h = sc->cam.height, n;
        bool *m = glossy_mask(sc, &n);
        cr_expect(m[(size_t)(h / 2) * w + w / 2], "the centre pixel of %dx%d is not glossy", w, h);
        cr_expect(!m[0] && !m[w - 1] && !m[(size_t)(h - 1) * w], "a corner of %dx%d is glossy", w, h);
        cr_expect(n > 0 && n < w * h / 2, "%d glossy pixels of %d", n, w * h);
        free(m);
    }
    scene_free(sc);
}

/* An error on the right half only, a mask of the right half: the masked relMSE is the error's, the
 * unmasked one zero; the masked blocks are those wholly in the mask, and a block the mask cuts is
 * left out. */
Test(glossy_mask, statistics_count_only_the_masked_pixels)
{
    enum { W = 32, H = 32 };
    struct image *ref = img_create(W, H), *a = img_create(W, H);
    bool mask[W * H];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            img_add(ref, x, y, (rgb){1, 1, 1});
            double v = x >= 16 ? 2 : 1;
            img_add(a, x, y, (rgb){v, v, v});
            mask[y * W + x] = x >= 16;
        }
    cr_expect_float_eq(relmse_where(a, ref, 0.01, mask, true), 1 / 1.01, 1e-12);
    cr_expect_float_eq(relmse_where(a, ref, 0.01, mask, false), 0, 1e-12);
    double v[8];
    const int all[4] = {0, 0, W, H};
    cr_expect_eq(block_relmse_in(a, ref, 16, 0.01, all, mask, v, 8), 2);
    cr_expect_eq(block_relmse_in(a, ref, 16, 0.01, all, NULL, v, 8), 4);
    mask[5 * W + 20] = false; /* the top right block is cut */
    cr_expect_eq(block_relmse_in(a, ref, 16, 0.01, all, mask, v, 8), 1);
    /* a constant error survives any blur; unscaled (s = 1) so the offset stays */
    cr_expect_float_eq(error_blur_share_in(a, ref, 0.01, 8, all, mask, 1), 1, 1e-12);
    bool none[W * H] = {false};
    cr_expect(isnan(error_blur_share_in(a, ref, 0.01, 8, all, none, 1)));
    cr_expect(isnan(relmse_where(a, ref, 0.01, none, true)));
    img_destroy(ref);
    img_destroy(a);
}

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* Whether FILE holds TEXT. */
static bool file_has(const char *file, const char *text)
{
    char *s = read_whole_file(file);
    cr_assert(s, "cannot read %s", file);
    bool has = strstr(s, text) != NULL;
    free(s);
    return has;
}

/* bin/ch6_equal end to end: on the gold sphere the glossy statistics get their rows and the mask its
 * picture; on the Cornell box (every surface Lambertian) neither is written. */
Test(glossy_mask, ch6_equal_measures_on_glossy_scenes_only, .timeout = 120)
{
    char dir[] = "/tmp/glossy-ch6-XXXXXX", cmd[1200], f[256];
    cr_assert(mkdtemp(dir));
    const char *scene[2] = {"tests/data/glossy-sphere.json", "scenes/cornell-box/scene.json"};
    for (int k = 0; k < 2; k++) {
        snprintf(cmd, sizeof cmd,
                 BIN_DIR "/ch6_equal --scene %s --out %s/%d --methods mmlt --seeds 2 --spp 2 --resolution 32x32 "
                         "--reference-spp 4 --reference %s/ref%d.exr --render-args '--seed-paths 2000' >/dev/null 2>&1",
                 scene[k], dir, k, dir, k);
        cr_assert_eq(system(cmd), 0, "%s", cmd);
        snprintf(f, sizeof f, "%s/%d/stats.csv", dir, k);
        cr_expect_eq(file_has(f, ",mmlt,glossy_relmse,"), k == 0, "%s", f);
        snprintf(f, sizeof f, "%s/%d/glossy-mask.png", dir, k);
        cr_expect_eq(access(f, F_OK) == 0, k == 0, "%s", f);
    }
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    cr_assert_eq(system(cmd), 0);
}
