/* Statistical tests of emitter and camera sampling against their pdfs (chi2.h: alpha = 0.01 with
 * the Sidak correction over CHI2_CASES; every case below draws N = 1M samples unless stated).
 * Piecewise densities (mesh triangles, env texels, the camera's image rectangle) are tested in a
 * parameterisation whose cells align with the pieces, each piece folded by a smoothstep so the
 * density vanishes on piece edges; Simpson's rule then integrates every cell accurately and no
 * cell straddles a discontinuity. */
#include <criterion/criterion.h>

#include "emitter/emitter_table.h"
#include "sampling/warp.h"
#include "support/chi2.h"
#include "support/emit_fixture.h"

#define N 1000000

static struct emit_fixture F;
static char buf[512];

#define EXPECT_PASS(r)                                                                                                 \
    do {                                                                                                               \
        cr_log_info("%s", chi2_describe(&(r), buf, sizeof buf));                                                       \
        cr_assert((r).pass, "%s", buf);                                                                                \
    } while (0)

static void sampler_at(struct sampler_rng *s, rng *r, int stream)
{
    sampler_rng_init(s, r);
    sampler_begin(&s->base, stream, 0);
}

/* ---- light selection: 5 cells, one per prim (the non-emissive one must stay empty) ---- */
static bool pick_sample(void *ctx, rng *r, double *u, double *v)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    double p;
    int prim = emitter_pick(&F.sc, &s.base, &p);
    *u = (prim + fx_ss_inv(rng_uniform(r))) / 5; /* folded inside the cell (see the top) */
    *v = 0.5;
    return prim >= 0;
}
static double pick_pdf(void *ctx, double u, double v)
{
    (void)ctx, (void)v;
    int prim = (int)(u * 5);
    prim = prim > 4 ? 4 : prim;
    return 5 * emitter_pick_prob(&F.sc, prim) * fx_ss_d(u * 5 - prim);
}
Test(stat_emit, pick_frequencies)
{
    fx_init(&F, FX_ENV_MAP, true);
    struct chi2_result r = chi2_test_2d(pick_sample, pick_pdf, NULL, 5, 1, N, 101);
    EXPECT_PASS(r);
    fx_free(&F);
}

/* ---- quad: (a, b) along the edges; density pdf_pos * |e0 x e1| ---- */
static bool quad_sample(void *ctx, rng *r, double *u, double *v)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    struct emitter_pos p;
    if (!emitter_sample_pos(&F.sc, FX_QUAD, &s.base, &p)) return false;
    const struct prim *q = &F.prims[FX_QUAD];
    /* solve p - base = a e0 + b e1 with the normal trick (independent of the library's solver) */
    vec3 x = vsub(p.p, q->quad_base), nn = vcross(q->quad_edge0, q->quad_edge1);
    *u = vdot(vcross(x, q->quad_edge1), nn) / vdot(nn, nn);
    *v = vdot(vcross(q->quad_edge0, x), nn) / vdot(nn, nn);
    return true;
}
static double quad_pdf(void *ctx, double u, double v)
{
    (void)ctx;
    const struct prim *q = &F.prims[FX_QUAD];
    vec3 p = vadd(q->quad_base, vadd(vscale(q->quad_edge0, u), vscale(q->quad_edge1, v)));
    return emitter_pdf_pos(&F.sc, FX_QUAD, p) * vlen(vcross(q->quad_edge0, q->quad_edge1));
}
Test(stat_emit, quad_position)
{
    fx_init(&F, FX_ENV_NONE, false);
    struct chi2_result r = chi2_test_2d(quad_sample, quad_pdf, NULL, 32, 32, N, 102);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-6);
    fx_free(&F);
}

/* ---- mesh: triangle k in x in [k/2, (k+1)/2); inside it s = b1 + b2 (folded), t = b2 / s ---- */
static bool mesh_sample(void *ctx, rng *r, double *u, double *v)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    struct emitter_pos p;
    if (!emitter_sample_pos(&F.sc, FX_MESH, &s.base, &p)) return false;
    vec3 *t = F.mesh_p + 3 * p.tri, e1 = vsub(t[1], t[0]), e2 = vsub(t[2], t[0]), x = vsub(p.p, t[0]);
    vec3 nn = vcross(e1, e2);
    double b1 = vdot(vcross(x, e2), nn) / vdot(nn, nn), b2 = vdot(vcross(e1, x), nn) / vdot(nn, nn);
    double ss = clampd(b1 + b2, 0, 1);
    *u = (p.tri + fx_ss_inv(ss)) / 2;
    *v = ss > 0 ? clampd(b2 / ss, 0, 1) : 0.5;
    return true;
}
static double mesh_pdf(void *ctx, double u, double v)
{
    (void)ctx;
    int k = u < 0.5 ? 0 : 1;
    double sig = 2 * u - k, ss = fx_ss(sig);
    vec3 *t = F.mesh_p + 3 * k;
    double ak = 0.5 * vlen(vcross(vsub(t[1], t[0]), vsub(t[2], t[0])));
    vec3 p = vadd(t[0], vadd(vscale(vsub(t[1], t[0]), ss * (1 - v)), vscale(vsub(t[2], t[0]), ss * v)));
    return emitter_pdf_pos(&F.sc, FX_MESH, p) * 2 * ak * ss * fx_ss_d(sig) * 2;
}
Test(stat_emit, mesh_position_unequal_triangles)
{
    fx_init(&F, FX_ENV_NONE, false);
    struct chi2_result r = chi2_test_2d(mesh_sample, mesh_pdf, NULL, 32, 32, N, 103);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-4, "mass %g", r.mass);
    fx_free(&F);
}

/* ---- sphere: the unit direction from the centre; solid-angle density pdf_pos * r^2 ---- */
static bool sphere_sample(void *ctx, rng *r, vec3 *d)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    struct emitter_pos p;
    if (!emitter_sample_pos(&F.sc, FX_SPHERE, &s.base, &p)) return false;
    *d = vnorm(vsub(p.p, F.prims[FX_SPHERE].center));
    return true;
}
static double sphere_pdf(void *ctx, vec3 d)
{
    (void)ctx;
    const struct prim *sp = &F.prims[FX_SPHERE];
    return emitter_pdf_pos(&F.sc, FX_SPHERE, vmad(sp->center, d, sp->radius)) * sp->radius * sp->radius;
}
Test(stat_emit, sphere_position)
{
    fx_init(&F, FX_ENV_NONE, false);
    struct chi2_result r = chi2_test_dir(sphere_sample, sphere_pdf, NULL, 32, 64, N, 104);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-4);
    fx_free(&F);
}

/* ---- emitted direction about a tilted normal ---- */
static bool edir_sample(void *ctx, rng *r, vec3 *d)
{
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    double pdf;
    *d = emitter_sample_dir(*(vec3 *)ctx, &s.base, &pdf);
    return true;
}
static double edir_pdf(void *ctx, vec3 d) { return emitter_pdf_dir(*(vec3 *)ctx, d); }
Test(stat_emit, emitted_direction)
{
    vec3 n = vnorm(v3(0.3, -0.5, 0.8));
    struct chi2_result r = chi2_test_dir(edir_sample, edir_pdf, &n, 32, 64, N, 105);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-3);
}

/* ---- environment map, in image space: cell = texel subdivided 4 x 4; (x, y) folded per texel.
 * Image coordinates come from Tungsten's formulas (u = atan2(z,x)/2pi + 0.5, v = acos(-y)/pi,
 * row from the top = 1 - v), so the test also pins the orientation. Image-space density =
 * env_pdf_dir * 2 pi^2 sin(theta) * fold Jacobians. ---- */
struct env_ctx {
    bool drop_jacobian; /* the deliberately broken pdf of the failure demonstration */
};
static void img_fold(double t, int n, double *out)
{
    double s = clampd(t, 0, 1) * n;
    int i = (int)s;
    if (i >= n) i = n - 1;
    *out = (i + fx_ss_inv(clampd(s - i, 0, 1))) / n;
}
static bool env_sample(void *ctx, rng *r, double *u, double *v)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    vec3 d;
    double pdf;
    if (!env_sample_dir(&F.sc, &s.base, &d, &pdf)) return false;
    vec3 l = vnorm(mat4_vector(&F.prims[FX_ENV].env_to_local, d));
    double tu = atan2(l.z, l.x) / (2 * M_PI) + 0.5, tv = acos(clampd(-l.y, -1, 1)) / M_PI;
    img_fold(tu, FX_TEX_W, u);
    img_fold(1 - tv, FX_TEX_H, v);
    return true;
}
static double unfold(double t, int n, double *jac)
{
    double s = t * n;
    int i = (int)s;
    if (i >= n) i = n - 1;
    double sig = s - i;
    *jac = fx_ss_d(sig);
    return (i + fx_ss(sig)) / n;
}
static double env_pdf(void *ctx, double u, double v)
{
    struct env_ctx *c = ctx;
    double jx, jy, x = unfold(u, FX_TEX_W, &jx), y = unfold(v, FX_TEX_H, &jy);
    if (jx == 0 || jy == 0) return 0;
    /* Tungsten's uvToDirection with (u, v) = (x, 1 - y) */
    double phi = (x - 0.5) * 2 * M_PI, theta = (1 - y) * M_PI, st = sin(theta);
    vec3 l = v3(cos(phi) * st, -cos(theta), sin(phi) * st);
    vec3 d = vnorm(mat4_vector(&F.prims[FX_ENV].env_to_world, l));
    double p = env_pdf_dir(&F.sc, d);
    if (c->drop_jacobian) p *= st;
    return p * 2 * M_PI * M_PI * st * jx * jy;
}
Test(stat_emit, env_map_direction)
{
    fx_init(&F, FX_ENV_MAP, true);
    struct env_ctx c = {false};
    struct chi2_result r = chi2_test_2d(env_sample, env_pdf, &c, 4 * FX_TEX_W, 4 * FX_TEX_H, N, 106);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-3, "env pdf integrates to %g", r.mass);
    fx_free(&F);
}
/* Failure demonstration kept as a test: the same sampler against a pdf without the 1/sin(theta)
 * lat-long Jacobian must be rejected. */
Test(stat_emit, env_map_rejects_missing_jacobian)
{
    fx_init(&F, FX_ENV_MAP, true);
    struct env_ctx c = {true};
    struct chi2_result r = chi2_test_2d(env_sample, env_pdf, &c, 4 * FX_TEX_W, 4 * FX_TEX_H, N, 106);
    cr_assert(!r.pass, "broken pdf passed: %s", chi2_describe(&r, buf, sizeof buf));
    cr_log_info("missing Jacobian: %s", chi2_describe(&r, buf, sizeof buf));
    fx_free(&F);
}

static bool envc_sample(void *ctx, rng *r, vec3 *d)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    double pdf;
    return env_sample_dir(&F.sc, &s.base, d, &pdf);
}
static double envc_pdf(void *ctx, vec3 d)
{
    (void)ctx;
    return env_pdf_dir(&F.sc, d);
}
Test(stat_emit, env_constant_direction)
{
    fx_init(&F, FX_ENV_CONST, true);
    struct chi2_result r = chi2_test_dir(envc_sample, envc_pdf, NULL, 32, 64, N, 107);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-6);
    fx_free(&F);
}

/* ---- env origin: uniform on the disc (polar coordinates r^2, phi in the frame of d) ---- */
static bool origin_sample(void *ctx, rng *r, double *u, double *v)
{
    vec3 d = *(vec3 *)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_EMITTER);
    double pdf;
    vec3 o = env_sample_origin(&F.sc, d, &s.base, &pdf);
    double R = env_radius(&F.sc);
    vec3 c = vmad(vscale(vadd(F.sc.bbox_min, F.sc.bbox_max), 0.5), d, R);
    /* an arbitrary in-plane basis, independent of the library's frame */
    vec3 a = vnorm(vcross(d, v3(0.36, 0.48, 0.8))), b = vcross(d, a);
    double x = vdot(vsub(o, c), a) / R, y = vdot(vsub(o, c), b) / R;
    *u = x * x + y * y;
    *v = warp_phi(x, y) / (2 * M_PI);
    return true;
}
static double origin_pdf(void *ctx, double u, double v)
{
    (void)ctx, (void)u, (void)v;
    double R = env_radius(&F.sc);
    return M_PI * R * R * (1.0 / (M_PI * R * R)); /* density pi R^2 * pdf_area in (r^2, phi/2pi) */
}
Test(stat_emit, env_origin_disc)
{
    fx_init(&F, FX_ENV_CONST, false);
    vec3 d = vnorm(v3(-0.2, 0.9, 0.4));
    struct chi2_result r = chi2_test_2d(origin_sample, origin_pdf, &d, 32, 32, N, 108);
    EXPECT_PASS(r);
    fx_free(&F);
}

/* ---- camera: angles (alpha, beta) = (atan(x/z), atan(y/z)) over the film (the image, grown by a
 * pixel on every side for the tent filter), folded; density pdf_dir * dOmega/(dalpha dbeta) *
 * dalpha/du * dbeta/dv. Mass = integral of pdf_dir over the film = over the sphere (pdf_dir is 0
 * elsewhere). Box and tent cameras. ---- */
static struct camera CAM;
static double amax(void) { return atan(CAM.tan_half_fov * camera_film_width(&CAM) / CAM.width); }
static double bmax(void) { return atan(CAM.tan_half_fov / CAM.aspect * camera_film_height(&CAM) / CAM.height); }
static bool cam_sample(void *ctx, rng *r, double *u, double *v)
{
    (void)ctx;
    struct sampler_rng s;
    sampler_at(&s, r, STREAM_CAMERA);
    double px, py;
    vec3 d = camera_sample_dir(&CAM, CAM.pos, &s.base, &px, &py, NULL);
    vec3 l = frame_to_local(&CAM.basis, d);
    double al = atan(l.x / l.z), be = atan(l.y / l.z);
    *u = fx_ss_inv(clampd((al / amax() + 1) / 2, 0, 1));
    *v = fx_ss_inv(clampd((be / bmax() + 1) / 2, 0, 1));
    return true;
}
static double cam_pdf(void *ctx, double u, double v)
{
    (void)ctx;
    double ju = fx_ss_d(u), jv = fx_ss_d(v);
    if (ju == 0 || jv == 0) return 0;
    double al = (2 * fx_ss(u) - 1) * amax(), be = (2 * fx_ss(v) - 1) * bmax();
    double x = tan(al), y = tan(be), L = sqrt(1 + x * x + y * y);
    vec3 d = vnorm(frame_to_world(&CAM.basis, v3(x, y, 1)));
    double domega = (1 + x * x) * (1 + y * y) / (L * L * L);
    return camera_pdf_dir(&CAM, CAM.pos, d) * domega * (2 * amax() * ju) * (2 * bmax() * jv);
}
static void camera_direction(enum recon_filter f, uint64_t seed)
{
    CAM = fx_camera(v3(1, 2, 3), v3(1, -0.3, 0.5), 40, 32, 20); /* small: the tent's margin is 6 % of the film */
    CAM.filter = f;
    struct chi2_result r = chi2_test_2d(cam_sample, cam_pdf, NULL, 32, 32, N, seed);
    EXPECT_PASS(r);
    cr_assert(fabs(r.mass - 1) < 1e-4, "integral of pdf_dir = %g", r.mass);
}
Test(stat_emit, camera_direction) { camera_direction(FILTER_BOX, 109); }
Test(stat_emit, camera_direction_tent) { camera_direction(FILTER_TENT, 111); }

/* The integral of camera_pdf_dir over the whole sphere by plain Monte Carlo with uniform
 * directions (N = 1M); tolerance 5 standard errors estimated from the same samples. */
static void camera_pdf_integrates_to_one(enum recon_filter f, uint64_t seed)
{
    CAM = fx_camera(v3(0, 0, 0), v3(0.2, 0.1, -1), 50, 30, 24);
    CAM.filter = f;
    rng r;
    rng_seed(&r, seed, 0);
    double s = 0, s2 = 0;
    for (int i = 0; i < N; i++) {
        vec3 d = warp_uniform_sphere(rng_uniform(&r), rng_uniform(&r));
        double f = camera_pdf_dir(&CAM, CAM.pos, d) * 4 * M_PI;
        s += f;
        s2 += f * f;
    }
    double m = s / N, se = sqrt((s2 / N - m * m) / N);
    cr_assert(fabs(m - 1) < 5 * se, "integral %g +- %g", m, se);
}
Test(stat_emit, camera_pdf_integrates_to_one) { camera_pdf_integrates_to_one(FILTER_BOX, 110); }
Test(stat_emit, camera_pdf_integrates_to_one_tent) { camera_pdf_integrates_to_one(FILTER_TENT, 112); }

/* ---- inverted discrete choices are uniform inside the chosen interval (Eq. 5.6): the position
 * of the written number inside [cdf_k, cdf_k+1) for the light pick (mesh) and for the mesh's
 * triangle pick (larger triangle). n = 200k each, 50 cells. ---- */
#define NDISC 200000
static bool disc_sample(void *ctx, rng *r, double *u, double *v)
{
    static struct sampler_writer w;
    int which = *(int *)ctx;
    sampler_writer_init(&w, rng_u32(r), 0);
    sampler_begin(&w.base, STREAM_EMITTER, 0);
    const struct emitter_table *t = F.sc.emitters;
    int k = t->slot[FX_MESH];
    double lo, hi;
    if (which == 0) {
        cr_assert(emitter_pick_invert(&F.sc, FX_MESH, &w.base));
        lo = t->cdf[k];
        hi = t->cdf[k + 1];
    } else {
        struct emitter_pos p = {v3(3, 0.3, 0.6), v3(0, 0, 0), 0, 1}; /* inside triangle 1 */
        cr_assert(emitter_invert_pos(&F.sc, FX_MESH, &p, &w.base));
        const double *c = t->tri_cdf + t->tri_off[k];
        lo = c[1];
        hi = c[2];
    }
    double x = w.u[STREAM_EMITTER][0];
    cr_assert(x >= lo && x < hi);
    *u = (x - lo) / (hi - lo);
    *v = 0.5;
    return true;
}
static double uniform_pdf(void *ctx, double u, double v)
{
    (void)ctx, (void)u, (void)v;
    return 1;
}
Test(stat_emit, inverted_discrete_uniform_in_interval)
{
    fx_init(&F, FX_ENV_MAP, true);
    for (int which = 0; which < 2; which++) {
        struct chi2_result r = chi2_test_2d(disc_sample, uniform_pdf, &which, 50, 1, NDISC, 111 + which);
        EXPECT_PASS(r);
    }
    fx_free(&F);
}
