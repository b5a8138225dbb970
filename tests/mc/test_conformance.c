/* Tungsten conformance (tests/data/tungsten, its README defines the scenes and the comparison):
 * every scene rendered with BDPT at the t16 budget (1/16 of Tungsten's reference spp) against
 * Tungsten's own BDPT reference render NAME.ref.exr. Per scene:
 *  (a) relMSE(candidate, ref) <= 1.5 x relMSE(NAME.t16.exr, ref), Tungsten's own render at the
 *      same budget (both contain the reference's noise); the scenes of not_followed below have
 *      their own factor, with the reason;
 *  (b) every 8x8-pixel block mean of luminance agrees with the reference's (two-sided t test);
 *  (c) the image-mean luminance agrees with the reference's (two-sided t test); the ratio is printed.
 * Noise estimate: the candidate is BATCHES independent renders (seeds differ) of t16/BATCHES spp
 * each, summing to the t16 budget; the variance of its block (or image) mean is the batch spread
 * s^2 / BATCHES (BATCHES - 1 degrees of freedom, so the statistic is Student t with that many).
 * The reference, at 16x the spp of the same estimator family, adds k/16 of that variance, where k
 * (Tungsten's variance relative to ours, per scene) is estimated by pooling over all blocks
 * sum (t16 - ref)^2 / ((1 + 1/16) sum var_cand): t16 - ref is Tungsten-vs-Tungsten, so k does not
 * absorb a convention error of ours. k only scales the reference's small share; it is printed.
 * alpha = 0.01 with a Sidak correction over all blocks and image means of all scenes, so the whole
 * suite falsely fails with probability 0.01 (the seeds are fixed: a pass is reproducible).
 * One scene per test; each prints relMSE, Tungsten's t16 relMSE, the block verdict and the mean
 * ratio on stderr. */
#include <criterion/criterion.h>
#include <criterion/parameterized.h>

#include "io/image.h"
#include "mc/render.h"
#include "path/scene_ready.h"
#include "support/agree.h"
#include "support/scenes.h"
#include <gsl/gsl_cdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DIR "tests/data/tungsten/"
#define BATCHES 16
#define BLK 8
#define MAX_BLOCKS 256

struct conf_scene {
    const char *name;
    int w, h; /* the camera's resolution, for the Sidak count before anything is rendered */
};

static const struct conf_scene conf_scenes[] = {
    {"rot-x", 80, 60},
    {"rot-y", 80, 60},
    {"rot-z", 80, 60},
    {"rot-xyz", 80, 60},
    {"transform-matrix", 80, 60},
    {"camera-lookat-up", 112, 70},
    {"camera-matrix", 80, 60},
    {"quad-emit-side", 80, 60},
    {"quad-uv-texture", 96, 72},
    {"cube-uv-texture", 96, 72},
    {"sphere-uv-texture", 96, 72},
    {"mesh-obj-wo3", 96, 72},
    {"env-textured", 80, 60},
    {"env-constant", 80, 60},
    {"power-quad", 80, 60},
    {"power-sphere", 80, 60},
    {"power-mesh", 80, 60},
    {"bsdf-metals", 80, 60},
    {"bsdf-specular", 80, 60},
    {"bsdf-plastic", 80, 60},
    {"filter-box", 64, 64},
    {"filter-tent", 64, 64},
    {"bounces-2", 80, 60},
    {"bounces-3", 80, 60},
    /* nested BSDFs */
    {"bsdf-coat", 80, 60},
    {"bsdf-mixed", 80, 60},
    {"bsdf-transparency", 80, 60},
    {"prim-disk", 80, 60},
    {"prim-cylinder", 80, 60},
    {"env-cap", 80, 60},
    /* textures: checker, textured roughness, bump maps */
    {"texture-checker", 80, 60},
    {"texture-roughness", 80, 60},
    {"bump-map", 80, 60},
    {"camera-thinlens", 80, 60},
    {"bsdf-thinsheet", 80, 60},
    {"bsdf-diffuse-transmission", 80, 60},
    {"bsdf-oren-nayar", 80, 60},
    {"bsdf-phong", 80, 60},
};
#define NSCENES (int)(sizeof conf_scenes / sizeof conf_scenes[0])

/* ===== CONVENTIONS OF TUNGSTEN'S NOT FOLLOWED (scenes/README.md, Tungsten conformance) =====
 * Each entry says how its scene's comparison differs and why; every other scene meets (a)-(c).
 *  - filter-tent: Tungsten's BDPT counts light through the film margin up to twice (its pinhole's
 *    directionPdf is 0 outside the image, so margin light-tracing connections get MIS weight 1;
 *    measured in scenes/README.md, "The tent filter"); our PT and BDPT agree with each other, so the
 *    comparison leaves out the outermost 8-pixel ring.
 *  - bsdf-thinsheet, bsdf-transparency: Tungsten punches its shadow rays through forward lobes
 *    (straight-through transmission) and drops those vertices from its paths; here they are delta
 *    vertices, unbiased (blocks and mean agree) but with connections through them blocked, so the
 *    variance is higher: relMSE 2.0-2.2x and 6.1x Tungsten's t16 (bound: 1.3x that).
 *  - bsdf-coat: Tungsten's rough_coat samples with a weight its eval and pdf do not give (a sampled
 *    substrate weight times wi.z / cos_ti, and a delta substrate blended into the coat's density);
 *    ours keeps sample, eval and pdf consistent and is unbiased here, at 2.0x Tungsten's t16
 *    relMSE (copying Tungsten's blend gave 1.48x).
 *  - bsdf-diffuse-transmission: Tungsten 0.2.2's reference is biased (its sample() reports the
 *    cosine pdf without the lobe choice while its pdf() includes it, so its MIS weights do not sum
 *    to one: image mean 4.6 % below ours, 67 of 80 blocks off; our BDPT reproduces the reference
 *    when given Tungsten's pdf, and our PT and BDPT agree). Not compared.
 *  - prim-disk: Tungsten applies the disk's cone_angle only where a camera path hits the disk (its
 *    emitter paths leave over the whole hemisphere, "TODO: Cone angle" in Disk.cpp), so its BDPT
 *    blends a spot light with a full one where the disk is seen directly; ours emits over the whole
 *    hemisphere in every technique. Every block agrees, the image mean is 0.3 % above (1.0030 +-
 *    0.0006; 1.0006 +- 0.0006 in a throwaway build with Tungsten's camera-hit-only cone), so (c) is
 *    printed, not asserted. */
static const struct {
    const char *name;
    int border;          /* pixels left out on every side */
    double relmse_bound; /* criterion (a)'s factor instead of 1.5; < 0: the reference is not compared */
    bool mean_printed;   /* criterion (c) printed, not asserted */
} not_followed[] = {
    {"filter-tent", BLK, 1.5, false}, {"bsdf-thinsheet", 0, 2.9, false},           {"bsdf-transparency", 0, 7.9, false},
    {"bsdf-coat", 0, 2.6, false},     {"bsdf-diffuse-transmission", 0, -1, false}, {"prim-disk", 0, 1.5, true},
};
/* ===== end ===== */

/* ===== DEFECTS OF TUNGSTEN'S REPRODUCED FOR THE COMPARISON ONLY (core/scene/scene.h) =====
 * Tungsten 0.2.2's ThinlensCamera shifts its camera rays half a pixel against its own light-tracing
 * splats and adds a strip of film outside the image into row and column 0 through light tracing
 * alone. Its BDPT reference is an MIS blend of the two film placements, which no consistent camera
 * reproduces: the renderer's thin lens is the consistent one (the agreement tests hold PT and BDPT
 * to it), and this comparison renders with the defects switched on. Without them 38 of 80 blocks
 * fail (top row and left column 4 to 12 % darker, interior blocks at sharp edges); with a
 * consistent half-pixel shift and the border ring left out still 9. */
static const char *const with_tungsten_defects[] = {"camera-thinlens"};
/* ===== end ===== */

static bool tungsten_defects(const char *name)
{
    for (size_t i = 0; i < sizeof with_tungsten_defects / sizeof *with_tungsten_defects; i++)
        if (!strcmp(name, with_tungsten_defects[i])) return true;
    return false;
}

static int border_of(const char *name)
{
    for (size_t i = 0; i < sizeof not_followed / sizeof *not_followed; i++)
        if (!strcmp(name, not_followed[i].name)) return not_followed[i].border;
    return 0;
}

static bool mean_printed(const char *name)
{
    for (size_t i = 0; i < sizeof not_followed / sizeof *not_followed; i++)
        if (!strcmp(name, not_followed[i].name)) return not_followed[i].mean_printed;
    return false;
}

static double relmse_bound_of(const char *name)
{
    for (size_t i = 0; i < sizeof not_followed / sizeof *not_followed; i++)
        if (!strcmp(name, not_followed[i].name)) return not_followed[i].relmse_bound;
    return 1.5;
}

/* The image without a ring of b pixels (b = 0: a copy). */
static struct image *crop(const struct image *im, int b)
{
    struct image *o = img_create(im->w - 2 * b, im->h - 2 * b);
    for (int y = 0; y < o->h; y++)
        for (int x = 0; x < o->w; x++)
            img_add(o, x, y, img_get(im, x + b, y + b));
    return o;
}

static int nblocks(int w, int h) { return ((w + BLK - 1) / BLK) * ((h + BLK - 1) / BLK); }

/* Mean luminance of each 8x8 block (the last row/column of blocks may be smaller), row-major. */
static void block_means(const struct image *im, double *out)
{
    int bw = (im->w + BLK - 1) / BLK, n = nblocks(im->w, im->h);
    static double cnt[MAX_BLOCKS];
    memset(cnt, 0, sizeof cnt);
    for (int i = 0; i < n; i++)
        out[i] = 0;
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++) {
            int b = (y / BLK) * bw + x / BLK;
            out[b] += luminance(img_get(im, x, y));
            cnt[b]++;
        }
    for (int i = 0; i < n; i++)
        out[i] /= cnt[i];
}

/* The README's relMSE: eps = (0.1 * mean reference luminance)^2. */
static double conf_relmse(const struct image *a, const struct image *ref)
{
    return img_relmse(a, ref, sqr(0.1 * img_mean_luminance(ref)));
}

static struct image *read_exr(const char *name, const char *suffix)
{
    char path[256], err[512];
    snprintf(path, sizeof path, DIR "%s.%s.exr", name, suffix);
    struct image *im = img_read(path, err, sizeof err);
    cr_assert(im, "%s", err);
    return im;
}

/* Two-sided p of a difference d with variance v (Student t, BATCHES - 1 dof). A zero variance
 * (a block black in every batch) passes only if the reference is black to float precision too. */
static double t_p(double d, double v, double scale)
{
    if (!(v > 0)) return fabs(d) <= 1e-6 * scale ? 1 : 0;
    return 2 * gsl_cdf_tdist_Q(fabs(d) / sqrt(v), BATCHES - 1);
}

ParameterizedTestParameters(stat_conformance, tungsten_scene)
{
    static int idx[NSCENES];
    for (int i = 0; i < NSCENES; i++)
        idx[i] = i;
    return cr_make_param_array(int, idx, NSCENES);
}

ParameterizedTest(int *param, stat_conformance, tungsten_scene, .timeout = 300)
{
    const struct conf_scene *cs = &conf_scenes[*param];
    const char *only = getenv("CONFORMANCE_SCENE"); /* run one scene: CONFORMANCE_SCENE=rot-y */
    if (only && strcmp(only, cs->name)) cr_skip_test("CONFORMANCE_SCENE=%s", only);
    if (relmse_bound_of(cs->name) < 0)
        cr_skip_test("%s: Tungsten's reference is biased; not compared (tests/mc/test_conformance.c, not_followed)",
                     cs->name);
    int comparisons = 0;
    for (int i = 0; i < NSCENES; i++) {
        if (relmse_bound_of(conf_scenes[i].name) < 0) continue;
        int b = border_of(conf_scenes[i].name);
        comparisons += nblocks(conf_scenes[i].w - 2 * b, conf_scenes[i].h - 2 * b) + 1;
    }
    double alpha = 1 - pow(1 - 0.01, 1.0 / comparisons);

    char path[256];
    snprintf(path, sizeof path, DIR "%s.json", cs->name);
    struct scene *sc = test_scene(path);
    sc->cam.tungsten_defects = tungsten_defects(cs->name);
    struct image *ref_full = read_exr(cs->name, "ref"), *t16_full = read_exr(cs->name, "t16");
    cr_assert(sc->cam.width == ref_full->w && sc->cam.height == ref_full->h && cs->w == ref_full->w &&
              cs->h == ref_full->h);
    int border = border_of(cs->name);
    struct image *ref = crop(ref_full, border), *t16 = crop(t16_full, border);
    img_destroy(ref_full);
    img_destroy(t16_full);
    int w = ref->w, h = ref->h, nb = nblocks(w, h);
    cr_assert(nb <= MAX_BLOCKS);
    cr_assert(sc->spp % (16 * BATCHES) == 0, "%s: reference spp %d", cs->name, sc->spp);
    int spp = sc->spp / 16 / BATCHES;

    static double bsum[MAX_BLOCKS], bsum2[MAX_BLOCKS], bm[MAX_BLOCKS];
    memset(bsum, 0, sizeof bsum);
    memset(bsum2, 0, sizeof bsum2);
    double msum = 0, msum2 = 0;
    struct image *cand = img_create(w, h);
    for (int b = 0; b < BATCHES; b++) {
        struct render_opts o = {.method = METHOD_BDPT,
                                .spp = spp,
                                .seed = 1000 * (uint64_t)(*param + 1) + b,
                                .threads = 2,
                                .max_length = sc->max_length};
        struct render_stats st;
        struct image *full = render_mc(sc, &o, &st);
        cr_assert_eq(st.nonfinite, 0, "%s: %ld non-finite samples", cs->name, st.nonfinite);
        struct image *im = crop(full, border);
        img_destroy(full);
        block_means(im, bm);
        for (int i = 0; i < nb; i++) {
            bsum[i] += bm[i];
            bsum2[i] += bm[i] * bm[i];
        }
        double m = img_mean_luminance(im);
        msum += m;
        msum2 += m * m;
        img_accumulate(cand, im, 1.0 / BATCHES);
        img_destroy(im);
    }

    static double rb[MAX_BLOCKS], tb[MAX_BLOCKS], vc[MAX_BLOCKS];
    block_means(ref, rb);
    block_means(t16, tb);
    double dev_t16 = 0, var_sum = 0;
    for (int i = 0; i < nb; i++) {
        double m = bsum[i] / BATCHES;
        vc[i] = fmax(0, bsum2[i] - BATCHES * m * m) / (BATCHES - 1) / BATCHES;
        bm[i] = m;
        dev_t16 += sqr(tb[i] - rb[i]);
        var_sum += vc[i];
    }
    double k = var_sum > 0 ? dev_t16 / (var_sum * 17.0 / 16.0) : 1;

    double ref_mean = img_mean_luminance(ref);
    int fails = 0, worst_i = 0;
    double worst = 1;
    for (int i = 0; i < nb; i++) {
        double p = t_p(bm[i] - rb[i], vc[i] * (1 + k / 16), ref_mean);
        if (p < worst) worst = p, worst_i = i;
        fails += p < alpha;
    }
    char list[512] = "";
    for (int i = 0, n = 0, listed = 0; i < nb && fails; i++) { /* the first 10 failing blocks */
        double sd = sqrt(vc[i] * (1 + k / 16)), p = t_p(bm[i] - rb[i], vc[i] * (1 + k / 16), ref_mean);
        if (p >= alpha || listed++ >= 10) continue;
        n += snprintf(list + n, sizeof list - n, " (x%d y%d: %+.1f%%, t %.1f)", i % ((w + BLK - 1) / BLK),
                      i / ((w + BLK - 1) / BLK), 100 * (bm[i] / rb[i] - 1), (bm[i] - rb[i]) / sd);
    }
    double cm = msum / BATCHES, vm = fmax(0, msum2 - BATCHES * cm * cm) / (BATCHES - 1) / BATCHES;
    double pmean = t_p(cm - ref_mean, vm * (1 + k / 16), ref_mean);
    double rel = conf_relmse(cand, ref), rel_t16 = conf_relmse(t16, ref);
    int bw = (w + BLK - 1) / BLK;
    fprintf(stderr,
            "conformance %-17s relMSE %.3e  Tungsten t16 %.3e  (%.2fx)  blocks %s: %d of %d fail (worst p %.1e at "
            "block x%d y%d)  mean ratio %.4f +- %.4f (p %.2g)  k %.2f  alpha %.2e%s%s\n",
            cs->name, rel, rel_t16, rel / rel_t16, fails ? "FAIL" : "pass", fails, nb, worst, worst_i % bw,
            worst_i / bw, cm / ref_mean, sqrt(vm * (1 + k / 16)) / ref_mean, pmean, k, alpha,
            border ? "  [border ring left out]" : "", list);
    img_destroy(cand);
    img_destroy(ref);
    img_destroy(t16);
    scene_free(sc);
    double bound = relmse_bound_of(cs->name);
    cr_expect(rel <= bound * rel_t16, "%s: relMSE %.3e > %.1f x Tungsten's t16 %.3e", cs->name, rel, bound, rel_t16);
    cr_expect(fails == 0, "%s: %d of %d blocks differ from the reference (worst p %.2e < alpha %.2e)", cs->name, fails,
              nb, worst, alpha);
    if (!mean_printed(cs->name))
        cr_expect(pmean >= alpha, "%s: image mean ratio %.4f, p %.2e < alpha %.2e", cs->name, cm / ref_mean, pmean,
                  alpha);
}
