/* Sampling against pdf of the new emitters (chi2.h: alpha = 0.01 with the Sidak correction over
 * CHI2_CASES; every case draws N = 1M samples): the cap light's directions, in a parameterisation
 * of the cap built here (not the library's frame), with samples outside the cap counted in the
 * "other" cell (expected empty); the disk's and the cylinder's emitter positions, in polar /
 * height coordinates of the true shapes (the 512-gon misses 2.5e-5 of the disk's area near the
 * rim, about 25 of the 1M samples, far below what a cell's count can show). */
#include <criterion/criterion.h>

#include "support/chi2.h"
#include "support/emit_fixture.h"
#include "support/tmpdir.h"
#include <stdio.h>

#define N 1000000

static char buf[512];

#define EXPECT_PASS(r)                                                                                                 \
    do {                                                                                                               \
        cr_log_info("%s", chi2_describe(&(r), buf, sizeof buf));                                                       \
        fprintf(stderr, "%s\n", buf);                                                                                  \
        cr_assert((r).pass, "%s", buf);                                                                                \
    } while (0)

/* An orthonormal frame (a, b, c) about c by Gram-Schmidt from the world axis least aligned with it. */
struct test_frame {
    vec3 a, b, c;
};
static struct test_frame test_frame(vec3 c)
{
    vec3 seed = fabs(c.x) < 0.6 ? v3(1, 0, 0) : v3(0, 0, 1);
    vec3 a = vnorm(vsub(seed, vscale(c, vdot(seed, c))));
    return (struct test_frame){a, vcross(c, a), c};
}
static double angle_in(const struct test_frame *f, vec3 d)
{
    double phi = atan2(vdot(d, f->b), vdot(d, f->a));
    return phi < 0 ? phi + 2 * M_PI : phi;
}

/* ---- cap light: u = (1 - cos theta) / (1 - cos max), v = phi / 2pi about cap_dir;
 * density pdf * 2 pi (1 - cos max) ---- */
struct cap_ctx {
    struct emit_fixture f;
    struct test_frame fr;
    double cos_max;
};

static bool cap_sample(void *ctx, rng *r, double *u, double *v)
{
    struct cap_ctx *c = ctx;
    struct sampler_rng s;
    sampler_rng_init(&s, r);
    sampler_begin(&s.base, STREAM_EMITTER, 0);
    vec3 d;
    double pdf;
    if (!env_sample_dir(&c->f.sc, &s.base, &d, &pdf)) return false;
    *u = (1 - vdot(d, c->fr.c)) / (1 - c->cos_max);
    *v = angle_in(&c->fr, d) / (2 * M_PI);
    return *u >= 0 && *u < 1 && *v >= 0 && *v < 1;
}
static double cap_pdf(void *ctx, double u, double v)
{
    struct cap_ctx *c = ctx;
    /* the rim itself (u = 1, measure zero) may round either way; Simpson's rule samples it */
    u = fmin(u, 1 - 1e-9);
    double ct = 1 - u * (1 - c->cos_max), st = sqrt(fmax(0.0, 1 - ct * ct)), phi = 2 * M_PI * v;
    vec3 d = vadd(vscale(c->fr.c, ct), vadd(vscale(c->fr.a, st * cos(phi)), vscale(c->fr.b, st * sin(phi))));
    return env_pdf_dir(&c->f.sc, d) * 2 * M_PI * (1 - c->cos_max);
}

static void cap_case(vec3 dir, double deg, uint64_t seed)
{
    struct cap_ctx c;
    fx_init(&c.f, FX_ENV_CONST, true);
    fx_free(&c.f);
    struct prim *e = &c.f.prims[FX_ENV];
    e->env_is_cap = true;
    e->cap_dir = vnorm(dir);
    e->cap_cos = c.cos_max = cos(deg * M_PI / 180);
    char err[256] = "";
    c.f.sc.emitters = emitters_build(&c.f.sc, err, sizeof err);
    cr_assert(c.f.sc.emitters, "%s", err);
    c.fr = test_frame(e->cap_dir);
    struct chi2_result r = chi2_test_2d(cap_sample, cap_pdf, &c, 16, 32, N, seed);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-3, "cap pdf integrates to %g", r.mass);
    fx_free(&c.f);
}

Test(stat_emit_prims, cap_6deg_direction) { cap_case(v3(0.3, 1, -0.4), 6, 201); }
Test(stat_emit_prims, cap_60deg_direction) { cap_case(v3(-1, 0.2, 0.1), 60, 202); }
Test(stat_emit_prims, cap_150deg_direction) { cap_case(v3(0, -1, 0.5), 150, 203); }

/* ---- disk and cylinder positions ---- */
static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "emit-prims-stat"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

static struct scene *load_emitter(const char *prim) { return fx_load_one_prim(tmpdir, prim); }
static void free_emitter(struct scene *s) { fx_free_loaded(s); }

/* The true shapes, as the JSON below states them. */
struct shape_ctx {
    struct scene *sc;
    vec3 centre;
    struct test_frame fr; /* c = the disk's normal / the cylinder's axis */
    double R, H;          /* radius; cylinder half height */
};

/* disk: u = r^2 / R^2, v = phi / 2pi; dA = pi R^2 du dv */
static bool disk_sample(void *ctx, rng *r, double *u, double *v)
{
    struct shape_ctx *c = ctx;
    struct sampler_rng s;
    sampler_rng_init(&s, r);
    sampler_begin(&s.base, STREAM_EMITTER, 0);
    struct emitter_pos pos;
    if (!emitter_sample_pos(c->sc, 0, &s.base, &pos)) return false;
    vec3 d = vsub(pos.p, c->centre);
    cr_assert(fabs(vdot(d, c->fr.c)) < 1e-9 && vdot(pos.n, c->fr.c) > 1 - 1e-12);
    *u = vlen2(d) / (c->R * c->R);
    *v = angle_in(&c->fr, d) / (2 * M_PI);
    return *u < 1;
}
static double disk_pdf(void *ctx, double u, double v)
{
    struct shape_ctx *c = ctx;
    double r = c->R * sqrt(u), phi = 2 * M_PI * v;
    vec3 p = vadd(c->centre, vadd(vscale(c->fr.a, r * cos(phi)), vscale(c->fr.b, r * sin(phi))));
    return emitter_pdf_pos(c->sc, 0, p) * M_PI * c->R * c->R;
}

Test(stat_emit_prims, disk_position, .init = mk_tmp, .fini = rm_tmp)
{
    struct shape_ctx c = {0};
    c.sc = load_emitter("{\"type\": \"disk\", \"bsdf\": \"w\", \"emission\": 1, \"transform\": {\"position\": [0.2, "
                        "1, -0.3], \"scale\": 0.4, \"rotation\": [0, 0, 180]}}");
    c.centre = v3(0.2, 1, -0.3);
    c.R = 0.4;
    c.fr = test_frame(v3(0, -1, 0));
    struct chi2_result r = chi2_test_2d(disk_sample, disk_pdf, &c, 16, 32, N, 204);
    EXPECT_PASS(r);
    free_emitter(c.sc);
}

/* cylinder (axis +y through the centre): u runs over the bottom cap (by r^2 / R^2), the side (by
 * height) and the top cap in shares proportional to their areas, so that dA = A du dv everywhere
 * (A = the true total area) and the density pdf * A is continuous across the joins, which need not
 * fall on cell edges; v = phi / 2pi. */
static void cyl_shares(const struct shape_ctx *c, double *cap, double *side, double *total)
{
    *cap = M_PI * c->R * c->R;
    *side = 4 * M_PI * c->R * c->H;
    *total = 2 * *cap + *side;
}
static bool cyl_sample(void *ctx, rng *r, double *u, double *v)
{
    struct shape_ctx *c = ctx;
    struct sampler_rng s;
    sampler_rng_init(&s, r);
    sampler_begin(&s.base, STREAM_EMITTER, 0);
    struct emitter_pos pos;
    if (!emitter_sample_pos(c->sc, 0, &s.base, &pos)) return false;
    double cap, side, total;
    cyl_shares(c, &cap, &side, &total);
    vec3 d = vsub(pos.p, c->centre);
    double h = vdot(d, c->fr.c), an = vdot(pos.n, c->fr.c);
    *v = angle_in(&c->fr, d) / (2 * M_PI);
    if (fabs(an) > 0.5) {
        cr_assert(fabs(fabs(h) - c->H) < 1e-9 && an * h > 0, "a cap point off its cap");
        double q = (vlen2(d) - h * h) / (c->R * c->R);
        *u = (h < 0 ? 0 : (cap + side) / total) + q * cap / total;
        return q < 1;
    }
    *u = (cap + side * (h + c->H) / (2 * c->H)) / total;
    return fabs(h) < c->H;
}
static double cyl_pdf(void *ctx, double u, double v)
{
    struct shape_ctx *c = ctx;
    double cap, side, total;
    cyl_shares(c, &cap, &side, &total);
    double phi = 2 * M_PI * v, a = u * total, r, h;
    if (a < cap || a >= cap + side) {
        double q = fmin(1.0, (a < cap ? a : a - cap - side) / cap);
        r = c->R * sqrt(q);
        h = a < cap ? -c->H : c->H;
    } else {
        r = c->R;
        h = -c->H + 2 * c->H * (a - cap) / side;
    }
    vec3 rim = vadd(vscale(c->fr.a, r * cos(phi)), vscale(c->fr.b, r * sin(phi)));
    vec3 p = vadd(vadd(c->centre, vscale(c->fr.c, h)), rim);
    return emitter_pdf_pos(c->sc, 0, p) * total;
}

Test(stat_emit_prims, cylinder_position, .init = mk_tmp, .fini = rm_tmp)
{
    struct shape_ctx c = {0};
    c.sc = load_emitter("{\"type\": \"cylinder\", \"bsdf\": \"w\", \"emission\": 1, \"transform\": {\"position\": "
                        "[0, 1, 0], \"scale\": [0.6, 0.5, 0.6]}}");
    c.centre = v3(0, 1, 0);
    c.R = 0.3;
    c.H = 0.25;
    c.fr = test_frame(v3(0, 1, 0));
    struct chi2_result r = chi2_test_2d(cyl_sample, cyl_pdf, &c, 16, 32, N, 205);
    EXPECT_PASS(r);
    free_emitter(c.sc);
}
