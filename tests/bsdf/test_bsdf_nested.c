/* Unit tests of the nested BSDFs (transparency, smooth_coat, rough_coat, mixed): dims and flags
 * derived from the children, sampled pdf/weight against pdf()/eval(), the fixed block layout,
 * the inversion round trip sample -> invert -> replay, reciprocity, exact furnaces, and the
 * loader's refusals (dims over a vertex's block, textured alpha). The chi-square and energy tests
 * are in test_bsdf_nested_stat.c. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "bsdf/bsdf_json.h"
#include "bsdf/bsdf_nested.h"
#include "sampler/sampler.h"
#include "support/nested_util.h"
#include <unistd.h>

static struct scene *load_cases(void)
{
    char err[1024] = "";
    struct scene *s = nested_scene(nested_bsdfs_json, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

static double rel_err(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

Test(bsdf_nested, dims_and_flags_from_children)
{
    struct scene *s = load_cases();
    static const struct {
        const char *name;
        int dims;
        bool transmissive, delta_only, refracts, pass_through;
    } want[] = {
        {"tr", 3, false, false, false, true},        /* 1 + lambert 2 */
        {"tr_rglass", 4, true, false, true, true},   /* 1 + rough_dielectric 3 */
        {"sc", 3, false, false, false, false},       /* 1 + 2 */
        {"sc_au", 1, false, true, false, false},     /* 1 + conductor 0: both lobes delta */
        {"rc", 3, false, false, false, false},       /* 1 + max(2, 2) */
        {"rc_au", 3, false, false, false, false},    /* 1 + max(2, 0) */
        {"rc_rp", 4, false, false, false, false},    /* 1 + max(2, 3) */
        {"mx", 3, false, false, false, false},       /* 1 + max(2, 0) */
        {"mx_rough", 4, false, false, false, false}, /* 1 + max(2, 3) */
        {"mx_nest", 4, false, false, false, true},   /* 1 + max(rc 3, tr 3) */
        {"mx_glass", 4, true, false, true, false},   /* 1 + max(2, 3) */
        {"mx_white_glass", 3, true, false, true, false},
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        const struct bsdf *b = nested_find(s, want[i].name);
        cr_expect_eq(b->dims, want[i].dims, "%s: dims %d, expected %d", want[i].name, b->dims, want[i].dims);
        cr_expect_eq(b->transmissive, want[i].transmissive, "%s: transmissive", want[i].name);
        cr_expect_eq(b->delta_only, want[i].delta_only, "%s: delta_only", want[i].name);
        cr_expect_eq(b->refracts, want[i].refracts, "%s: refracts", want[i].name);
        cr_expect_eq(b->pass_through, want[i].pass_through, "%s: pass_through", want[i].name);
    }
    cr_expect_eq(nested_find(s, "tr_rglass")->refract_ior, 1.4);
    cr_expect_eq(nested_find(s, "glass")->refract_ior, 1.5);
    scene_model_free(s);
}

/* Every continuous sample reports pdf() and f |wo.z| / pdf; every sample consumes exactly dims
 * numbers (both lobes of every choice). 2000 samples per case and wi. */
Test(bsdf_nested, sample_matches_pdf_eval_and_consumes_dims)
{
    struct scene *s = load_cases();
    rng r;
    rng_seed(&r, 5, 0);
    struct sampler_rng rs;
    sampler_rng_init(&rs, &r);
    for (int k = 0; k < N_NESTED_CASES; k++) {
        struct bsdf_ctx c = bsdf_ctx_at(nested_find(s, nested_cases[k].name), NULL);
        for (int j = 0; j < 6; j++) {
            double cz = (j % 3 == 0 ? 0.9 : j % 3 == 1 ? 0.45 : 0.12) * (j >= 3 && nested_cases[k].below ? -1 : 1);
            vec3 wi = nested_dir(cz, 0.7 + j);
            for (enum transport mode = TRANSPORT_RADIANCE; mode <= TRANSPORT_IMPORTANCE; mode++)
                for (int i = 0; i < 1000; i++) {
                    struct bsdf_sample o;
                    sampler_begin(&rs.base, STREAM_CAMERA, 1);
                    if (!bsdf_sample(&c, wi, &rs.base, mode, &o)) continue;
                    cr_assert_eq(rs.base.offset, c.b->dims, "%s consumed %d numbers, dims %d", nested_cases[k].name,
                                 rs.base.offset, c.b->dims);
                    cr_assert(fabs(vlen(o.wo) - 1) < 1e-9);
                    if (o.delta) {
                        cr_assert(o.pdf > 0 && o.pdf <= 1 + 1e-12, "%s: delta probability %g", nested_cases[k].name,
                                  o.pdf);
                        continue;
                    }
                    double p = bsdf_pdf(&c, wi, o.wo);
                    rgb f = bsdf_eval(&c, wi, o.wo, mode);
                    cr_assert(rel_err(o.pdf, p) < 1e-6, "%s: sampled pdf %g, pdf() %g", nested_cases[k].name, o.pdf, p);
                    rgb w = vscale(f, fabs(o.wo.z) / p);
                    cr_assert(vlen(vsub(w, o.weight)) <= 1e-6 * fmax(1e-3, vlen(w)),
                              "%s: weight (%g %g %g) vs f cos / pdf (%g %g %g)", nested_cases[k].name, o.weight.x,
                              o.weight.y, o.weight.z, w.x, w.y, w.z);
                }
        }
    }
    scene_model_free(s);
}

/* sample -> invert -> replay reproduces wo and the delta flag; invert puts exactly dims
 * numbers in [0, 1). 20000 samples per case (x 2 incident directions); failures below 1e-3,
 * continuous round-trip error below 1e-6. */
Test(bsdf_nested, inversion_roundtrip)
{
    struct scene *s = load_cases();
    static struct sampler_writer w;
    sampler_writer_init(&w, 9, 0);
    rng r;
    rng_seed(&r, 7, 0);
    struct sampler_rng rs;
    sampler_rng_init(&rs, &r);
    for (int k = 0; k < N_NESTED_CASES; k++) {
        struct bsdf_ctx c = bsdf_ctx_at(nested_find(s, nested_cases[k].name), NULL);
        long sampled = 0, failed = 0;
        double worst = 0;
        for (int j = 0; j < 2; j++) {
            vec3 wi = nested_dir((j ? 0.3 : 0.85) * (j && nested_cases[k].below ? -1 : 1), 0.4 + 2 * j);
            for (int i = 0; i < 10000; i++) {
                struct bsdf_sample o, back;
                sampler_begin(&rs.base, STREAM_CAMERA, 1);
                if (!bsdf_sample(&c, wi, &rs.base, TRANSPORT_RADIANCE, &o)) continue;
                sampled++;
                sampler_writer_clear(&w);
                sampler_begin(&w.base, STREAM_CAMERA, 1);
                if (!bsdf_invert(&c, wi, o.wo, &w.base)) {
                    failed++;
                    continue;
                }
                cr_assert_eq(w.base.offset, c.b->dims, "%s: invert put %d numbers, dims %d", nested_cases[k].name,
                             w.base.offset, c.b->dims);
                for (int d = 0; d < c.b->dims; d++) {
                    double u = w.u[STREAM_CAMERA][SAMPLER_BLOCK + d];
                    cr_assert(u >= 0 && u < 1, "%s: number %d = %g", nested_cases[k].name, d, u);
                }
                cr_assert_eq(w.kind[STREAM_CAMERA][SAMPLER_BLOCK], DIM_DISCRETE, "the nested choice comes first");
                struct sampler_replay rp;
                sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w.u);
                sampler_begin(&rp.base, STREAM_CAMERA, 1);
                /* the lobe may differ where two lobes reach wo (the inverse picks one in proportion) */
                if (!bsdf_sample(&c, wi, &rp.base, TRANSPORT_RADIANCE, &back) || back.delta != o.delta) {
                    failed++;
                    continue;
                }
                double e = vlen(vsub(back.wo, o.wo));
                worst = fmax(worst, e);
                if (e > 1e-6) failed++;
            }
        }
        cr_log_info("%s: %ld round trips, %ld failed, max |wo - replay| %.2e", nested_cases[k].name, sampled, failed,
                    worst);
        cr_expect(sampled > 5000, "%s: only %ld samples", nested_cases[k].name, sampled);
        cr_expect(failed <= 1e-3 * sampled, "%s: %ld of %ld round trips failed (worst %g)", nested_cases[k].name,
                  failed, sampled, worst);
    }
    scene_model_free(s);
}

/* Where wo is reachable by two delta lobes (a smooth coat over a conductor: the coat's reflection
 * and the substrate's mirror seen through the coat), the inverse picks each in proportion to its
 * discrete probability (Eq. 5.7 for deltas): over 20000 inversions the coat's share is P within
 * 5 sigma. */
Test(bsdf_nested, two_deltas_in_proportion)
{
    struct scene *s = load_cases();
    static struct sampler_writer w;
    sampler_writer_init(&w, 11, 0);
    struct bsdf_ctx c = bsdf_ctx_at(nested_find(s, "sc_au"), NULL);
    vec3 wi = nested_dir(0.6, 0.3), wo = v3(-wi.x, -wi.y, wi.z);
    /* P from one forward sample with u = 0 (the coat's lobe) */
    double u[SAMPLER_BLOCK] = {0};
    static double vec[STREAM_COUNT][STREAM_DIMS];
    memcpy(&vec[STREAM_CAMERA][SAMPLER_BLOCK], u, sizeof u);
    struct sampler_replay rp;
    sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])vec);
    sampler_begin(&rp.base, STREAM_CAMERA, 1);
    struct bsdf_sample o;
    cr_assert(bsdf_sample(&c, wi, &rp.base, TRANSPORT_RADIANCE, &o) && o.delta && o.lobe == 0);
    double P = o.pdf;
    int n = 20000, coat = 0;
    for (int i = 0; i < n; i++) {
        sampler_writer_clear(&w);
        sampler_begin(&w.base, STREAM_CAMERA, 1);
        cr_assert(bsdf_invert(&c, wi, wo, &w.base));
        coat += w.u[STREAM_CAMERA][SAMPLER_BLOCK] < P;
    }
    double sd = sqrt(P * (1 - P) / n);
    cr_log_info("P(coat) %.4f, inverted share %.4f", P, (double)coat / n);
    cr_expect(fabs((double)coat / n - P) < 5 * sd, "coat share %g, expected %g +- %g", (double)coat / n, P, sd);
    scene_model_free(s);
}

/* f(wi, wo) = f(wo, wi) for the reflecting nested BSDFs (their children are reciprocal, and the
 * coat's in and out factors are symmetric); f_rad(wi, wo) = f_imp(wo, wi) for the transmissive
 * ones. 2000 random pairs each. */
Test(bsdf_nested, reciprocity)
{
    struct scene *s = load_cases();
    rng r;
    rng_seed(&r, 13, 0);
    for (int k = 0; k < N_NESTED_CASES; k++) {
        struct bsdf_ctx c = bsdf_ctx_at(nested_find(s, nested_cases[k].name), NULL);
        double worst = 0;
        for (int i = 0; i < 2000; i++) {
            vec3 a = nested_dir(0.02 + 0.98 * rng_uniform(&r), 2 * M_PI * rng_uniform(&r));
            vec3 b = nested_dir(0.02 + 0.98 * rng_uniform(&r), 2 * M_PI * rng_uniform(&r));
            if (nested_cases[k].below && (i & 1)) b.z = -b.z;
            rgb f1 = bsdf_eval(&c, a, b, TRANSPORT_RADIANCE), f2 = bsdf_eval(&c, b, a, TRANSPORT_IMPORTANCE);
            double e = vlen(vsub(f1, f2)) / fmax(1e-12, vlen(f1));
            if (vlen(f1) > 1e-12) worst = fmax(worst, e);
        }
        cr_expect(worst < 1e-9, "%s: max relative |f_rad(a, b) - f_imp(b, a)| = %g", nested_cases[k].name, worst);
    }
    scene_model_free(s);
}

/* Exact furnaces: a mixed BSDF of a white lambert and a mirror, and a transparency over a white
 * lambert, return weight 1 on every sample (both lobes conserve energy and the weights carry no
 * estimator noise); a mixed of a white lambert and glass returns 1 in importance mode. */
Test(bsdf_nested, exact_furnace)
{
    struct scene *s = load_cases();
    rng r;
    rng_seed(&r, 17, 0);
    struct sampler_rng rs;
    sampler_rng_init(&rs, &r);
    const char *names[] = {"mx_white", "tr_white", "mx_white_glass"};
    for (int k = 0; k < 3; k++) {
        struct bsdf_ctx c = bsdf_ctx_at(nested_find(s, names[k]), NULL);
        for (int i = 0; i < 20000; i++) {
            vec3 wi = nested_dir(0.05 + 0.95 * rng_uniform(&r), 2 * M_PI * rng_uniform(&r));
            struct bsdf_sample o;
            sampler_begin(&rs.base, STREAM_CAMERA, 1);
            cr_assert(bsdf_sample(&c, wi, &rs.base, TRANSPORT_IMPORTANCE, &o), "%s: sample failed", names[k]);
            cr_assert(fabs(o.weight.x - 1) < 1e-9 && fabs(o.weight.y - 1) < 1e-9 && fabs(o.weight.z - 1) < 1e-9,
                      "%s: weight (%g %g %g)", names[k], o.weight.x, o.weight.y, o.weight.z);
        }
    }
    scene_model_free(s);
}

/* ---- loader ---- */

static void expect_refused(const char *bsdfs, const char *expect)
{
    char err[1024] = "";
    struct scene *s = nested_scene(bsdfs, err, sizeof err);
    cr_expect_null(s, "accepted: %s", bsdfs);
    scene_model_free(s);
    cr_expect(strstr(err, expect), "message: %s\n  expected ...%s...", err, expect);
    cr_expect(!strchr(err, '\n'), "message is not one line: %s", err);
}

Test(bsdf_nested, loader_refuses_dims_over_the_vertex_block)
{
    /* mixed over mixed ...: 1 + max(inner, lambert 2) per level; lambert 2 -> 3, 4, ..., 9 */
    char json[4096] = "[{\"name\": \"b0\", \"type\": \"lambert\"}, {\"name\": \"l0\", \"type\": \"lambert\"}";
    for (int i = 1; i <= 6; i++)
        snprintf(json + strlen(json), sizeof json - strlen(json),
                 ", {\"name\": \"l%d\", \"type\": \"mixed\", \"bsdf0\": \"l%d\", \"bsdf1\": \"l0\"}", i, i - 1);
    char ok[4096];
    snprintf(ok, sizeof ok, "%s]", json);
    char err[1024] = "";
    struct scene *s = nested_scene(ok, err, sizeof err);
    cr_assert(s, "6 nested mixed over a lambert need 8 numbers and fit: %s", err);
    cr_expect_eq(nested_find(s, "l6")->dims, 8);
    scene_model_free(s);
    snprintf(json + strlen(json), sizeof json - strlen(json),
             ", {\"name\": \"l7\", \"type\": \"mixed\", \"bsdf0\": \"l6\", \"bsdf1\": \"l0\"}]");
    expect_refused(json, "bsdfs[8]: bsdf \"l7\" needs 9 random numbers per vertex, more than the 8");
    /* inline in a primitive: the primitive's path */
    char err2[1024] = "";
    char dir[128], path[256];
    tmpdir_make(dir, sizeof dir, "nested");
    snprintf(path, sizeof path, "%s/scene.json", dir);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(
        f, "{\"primitives\": [{\"type\": \"quad\", \"bsdf\": {\"type\": \"lambert\"}}, {\"type\": \"quad\", \"bsdf\":");
    for (int i = 0; i < 7; i++)
        fprintf(f, " {\"type\": \"mixed\", \"bsdf1\": \"x\", \"bsdf0\":");
    fprintf(f, " {\"type\": \"lambert\"}");
    for (int i = 0; i < 7; i++)
        fprintf(f, "}");
    fprintf(f, "}], \"bsdfs\": [{\"name\": \"x\", \"type\": \"lambert\"}]}");
    fclose(f);
    s = scene_load_model(path, err2, sizeof err2);
    tmpdir_remove(dir);
    cr_expect_null(s);
    scene_model_free(s);
    cr_expect(strstr(err2, "primitives[1].bsdf: bsdf") && strstr(err2, "needs 9 random numbers"), "%s", err2);
}

Test(bsdf_nested, loader_refuses_textured_alpha_and_bad_numbers)
{
    expect_refused("[{\"name\": \"b0\", \"type\": \"transparency\", \"alpha\": \"cutout.png\"}]",
                   "bsdfs[0].alpha: textured alpha is not supported");
    expect_refused("[{\"name\": \"b0\", \"type\": \"transparency\", \"alpha\": 1.5}]",
                   "bsdfs[0].alpha: expected a number in [0, 1]");
    expect_refused("[{\"name\": \"b0\", \"type\": \"mixed\", \"ratio\": -0.1}]",
                   "bsdfs[0].ratio: expected a number in [0, 1]");
    expect_refused("[{\"name\": \"b0\", \"type\": \"smooth_coat\", \"ior\": 0}]",
                   "bsdfs[0].ior: expected a positive number");
    expect_refused("[{\"name\": \"b0\", \"type\": \"rough_coat\", \"distribution\": \"phong\"}]",
                   "bsdfs[0].distribution: expected \"ggx\" or \"beckmann\"");
    expect_refused("[{\"name\": \"b0\", \"type\": \"mixed\", \"bsdf0\": \"nope\"}]",
                   "bsdfs[0].bsdf0: undefined bsdf \"nope\"");
}

/* Tungsten's defaults (SmoothCoatBsdf, RoughCoatBsdf, TransparencyBsdf, MixedBsdf constructors),
 * and a top-level bsdf named after an inline nested one still resolves to itself. */
Test(bsdf_nested, loader_defaults_and_slots)
{
    char err[1024] = "";
    struct scene *s = nested_scene("[{\"name\": \"b0\", \"type\": \"mixed\", \"bsdf0\": {\"type\": \"smooth_coat\"},"
                                   " \"bsdf1\": {\"type\": \"transparency\"}},"
                                   " {\"name\": \"rc\", \"type\": \"rough_coat\"}]",
                                   err, sizeof err);
    cr_assert(s, "%s", err);
    const struct bsdf *m = nested_find(s, "b0"), *rc = nested_find(s, "rc");
    cr_expect_eq(s->prims[0].bsdf, 0);
    cr_expect_eq(&s->bsdfs[1], rc, "top-level bsdf 1 is slot 1");
    cr_expect_eq(m->ratio, 0.5);
    const struct bsdf *sc = m->child[0], *tr = m->child[1];
    cr_expect_eq(sc->type, BSDF_SMOOTH_COAT);
    cr_expect_eq(sc->ior, 1.3);
    cr_expect_eq(sc->thickness, 1);
    cr_expect_eq(sc->child[0]->type, BSDF_ROUGH_CONDUCTOR, "a coat's default substrate is a rough conductor");
    cr_expect_eq(sc->child[0]->roughness, 0.1);
    cr_expect_eq(tr->type, BSDF_TRANSPARENCY);
    cr_expect_eq(tr->alpha, 1);
    cr_expect_eq(tr->child[0]->type, BSDF_LAMBERT);
    cr_expect_eq(rc->roughness, 0.02);
    cr_expect_eq(rc->dist, MF_GGX);
    cr_expect_eq(rc->ior, 1.3);
    scene_model_free(s);
}

/* A mixed BSDF with a ratio map needs the hit's uv, and reads the map as Tungsten's scalar
 * REQUEST_AVERAGE texture (no gamma table): a code-128 grey texel is 128/255, not 0.2158. */
Test(bsdf_nested, ratio_texture_needs_uv_and_is_not_gamma_decoded)
{
    char err[1024] = "";
    char json[1024], cwd[512];
    cr_assert(getcwd(cwd, sizeof cwd));
    snprintf(json, sizeof json,
             "[{\"name\": \"b0\", \"type\": \"mixed\", \"ratio\": \"%s/tests/data/tungsten/tex-gradient.png\"}]", cwd);
    struct scene *s = nested_scene(json, err, sizeof err);
    cr_assert(s, "%s", err);
    const struct bsdf *m = nested_find(s, "b0");
    cr_expect(m->needs_uv);
    cr_assert(m->ratio_tex);
    /* texel values are k / 255 for integer codes k */
    for (int i = 0; i < m->ratio_tex->w * m->ratio_tex->h; i++) {
        double v = m->ratio_tex->rgb[3 * i] * 255;
        cr_assert(fabs(v - round(v)) < 1e-4, "texel %d = %g / 255", i, v);
    }
    cr_expect(!nested_find(s, "b0")->child[0]->needs_uv);
    scene_model_free(s);
}
