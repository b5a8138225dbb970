/* Emitters and camera: build errors, selection weights, orientation conventions, and inversion
 * round trips (thesis §5.1: sample(invert(x)) == x). Round trips draw >= 100k samples of each
 * kind and require >= 99.9 % to reproduce the point/direction to 1e-7 relative. */
#include <criterion/criterion.h>

#include "emitter/emitter_table.h"
#include "sampling/warp.h"
#include "support/emit_fixture.h"
#include <string.h>

#define NRT 100000
#define RT_TOL 1e-7
#define RT_MIN_OK 0.999

static struct sampler_writer W;

static bool close_rel(vec3 a, vec3 b) { return vlen(vsub(a, b)) <= RT_TOL * (1 + vlen(a)); }

static void replay_begin(struct sampler_replay *r)
{
    sampler_replay_init(r, (const double(*)[STREAM_DIMS])W.u);
    sampler_begin(&r->base, STREAM_EMITTER, 0);
}

Test(emit, build_errors_one_line)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_NONE, false);
    fx_free(&f);
    char err[256];
    f.prims[FX_QUAD].quad_edge1 = v3(0, 0, 0);
    f.prims[FX_QUAD].area = 0;
    cr_assert_null(emitters_build(&f.sc, err, sizeof err));
    cr_assert_str_eq(err, "fixture.json: primitives[0]: zero-area emitter");
    fx_init(&f, FX_ENV_NONE, false);
    fx_free(&f);
    f.prims[FX_SPHERE].emission.y = NAN;
    cr_assert_null(emitters_build(&f.sc, err, sizeof err));
    cr_assert(strstr(err, "fixture.json: primitives[2].emission") == err && !strchr(err, '\n'), "%s", err);
    fx_init(&f, FX_ENV_NONE, false);
    fx_free(&f);
    f.prims[FX_SPHERE].radius = 0;
    f.prims[FX_SPHERE].area = 0;
    cr_assert_null(emitters_build(&f.sc, err, sizeof err));
    cr_assert_str_eq(err, "fixture.json: primitives[2]: zero-area emitter");
    /* a mesh whose triangles are all degenerate (collinear vertices) */
    fx_init(&f, FX_ENV_NONE, false);
    fx_free(&f);
    f.mesh_p[2] = v3(2, 0, 0);
    f.mesh_p[5] = v3(8, 0, 0);
    cr_assert_null(emitters_build(&f.sc, err, sizeof err));
    cr_assert_str_eq(err, "fixture.json: primitives[1]: zero-area emitter");
}

Test(emit, pick_prob_proportional_to_power)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_MAP, true);
    double pw[5] = {0}, tot = 0;
    for (int i = 0; i < 3; i++)
        pw[i] = f.prims[i].area * M_PI * luminance(f.prims[i].emission);
    /* environment: pi R^2 * integral of luminance over the sphere (sum over texels of L dOmega) */
    double R = env_radius(&f.sc), integ = 0;
    for (int y = 0; y < FX_TEX_H; y++)
        for (int x = 0; x < FX_TEX_W; x++) {
            const float *c = f.texels + 3 * (y * FX_TEX_W + x);
            integ += luminance(v3(c[0], c[1], c[2])) * (2 * M_PI / FX_TEX_W) *
                     (cos(M_PI * y / FX_TEX_H) - cos(M_PI * (y + 1) / FX_TEX_H));
        }
    pw[4] = M_PI * R * R * integ;
    for (int i = 0; i < 5; i++)
        tot += pw[i];
    double sum = 0;
    for (int i = 0; i < 5; i++) {
        double p = emitter_pick_prob(&f.sc, i);
        cr_assert(fabs(p - pw[i] / tot) < 1e-12, "prim %d: %g vs %g", i, p, pw[i] / tot);
        sum += p;
    }
    cr_assert(fabs(sum - 1) < 1e-12);
    cr_assert_eq(emitters_count(&f.sc), 4);
    cr_assert_eq(emitter_pick_prob(&f.sc, FX_PLAIN), 0.0);
    /* bounding sphere of the bbox, enlarged by 0.1 % */
    cr_assert(fabs(R - 0.5 * vlen(v3(6, 5, 3)) * 1.001) < 1e-12);
    fx_free(&f);
}

Test(emit, radiance_front_side_only)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_NONE, false);
    vec3 n = f.prims[FX_QUAD].quad_normal;
    cr_assert(fabs(n.y - 1) < 1e-15);
    cr_assert_eq(emitter_radiance(&f.sc, FX_QUAD, n, vnorm(v3(0.3, 1, 0))).x, 1.0);
    cr_assert(vzero(emitter_radiance(&f.sc, FX_QUAD, n, vnorm(v3(0.3, -1, 0)))));
    cr_assert(vzero(emitter_radiance(&f.sc, FX_PLAIN, v3(0, 1, 0), v3(0, 1, 0))));
    /* mesh triangle normals follow the counter-clockwise winding */
    rng r;
    rng_seed(&r, 5, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    for (int i = 0; i < 100; i++) {
        struct emitter_pos pos;
        sampler_begin(&s.base, STREAM_EMITTER, 0);
        cr_assert(emitter_sample_pos(&f.sc, FX_MESH, &s.base, &pos));
        vec3 *p = f.mesh_p + 3 * pos.tri;
        vec3 ng = vnorm(vcross(vsub(p[1], p[0]), vsub(p[2], p[0])));
        cr_assert(vlen(vsub(ng, pos.n)) < 1e-12);
        cr_assert(fabs(vdot(vsub(pos.p, p[0]), ng)) < 1e-12);
    }
    fx_free(&f);
}

/* Independent implementation of Tungsten's InfiniteSphere::directionToUV + BitmapTexture bilinear
 * lookup: u = atan2(z, x) / 2pi + 0.5, v = acos(-y) / pi; texel coordinates (u w - 0.5,
 * (1 - v) h - 0.5) with row 0 on top, the four neighbours wrapped around in both directions. */
static rgb tungsten_env(const struct emit_fixture *f, vec3 d)
{
    vec3 l = vnorm(mat4_vector(&f->prims[FX_ENV].env_to_local, d));
    double u = atan2(l.z, l.x) / (2 * M_PI) + 0.5, v = acos(-l.y) / M_PI;
    double tx = u * FX_TEX_W - 0.5, ty = (1 - v) * FX_TEX_H - 0.5;
    double fx = floor(tx), fy = floor(ty), ax = tx - fx, ay = ty - fy;
    rgb out = v3s(0);
    for (int dy = 0; dy < 2; dy++)
        for (int dx = 0; dx < 2; dx++) {
            int x = (((int)fx + dx) % FX_TEX_W + FX_TEX_W) % FX_TEX_W;
            int y = (((int)fy + dy) % FX_TEX_H + FX_TEX_H) % FX_TEX_H;
            const float *c = f->texels + 3 * (y * FX_TEX_W + x);
            double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay);
            out = vadd(out, vscale(v3(c[0], c[1], c[2]), w));
        }
    return out;
}

/* The direction through the centre of texel (i, j) of the unrotated map: phi = 2 pi (i + 0.5) / w
 * - pi from +x toward +z, theta = pi (j + 0.5) / h from +y. */
static vec3 texel_centre_dir(double i, double j)
{
    double phi = 2 * M_PI * (i + 0.5) / FX_TEX_W - M_PI, theta = M_PI * (j + 0.5) / FX_TEX_H;
    return v3(cos(phi) * sin(theta), cos(theta), sin(phi) * sin(theta));
}

Test(emit, env_orientation_matches_tungsten)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_MAP, false);
    const float *t = f.texels;
#define TEXEL(x, y) v3(t[3 * ((y)*FX_TEX_W + (x))], t[3 * ((y)*FX_TEX_W + (x)) + 1], t[3 * ((y)*FX_TEX_W + (x)) + 2])
    /* identity frame: +y is the top row, +x the middle column, +z three quarters across, -z a
     * quarter; at a texel's centre the bilinear lookup is that texel alone */
    static const int ij[5][2] = {{8, 0}, {8, 3}, {12, 3}, {4, 3}, {15, 4}};
    for (int k = 0; k < 5; k++) {
        rgb got = env_radiance(&f.sc, texel_centre_dir(ij[k][0], ij[k][1])), want = TEXEL(ij[k][0], ij[k][1]);
        cr_assert(vlen(vsub(got, want)) < 1e-9, "texel (%d, %d): %g vs %g", ij[k][0], ij[k][1], got.x, want.x);
    }
    cr_assert(vlen(env_radiance(&f.sc, texel_centre_dir(3, FX_TEX_H - 1))) < 1e-9); /* the black row's centre */
    /* between two texels of a row: their mean */
    rgb mid = env_radiance(&f.sc, texel_centre_dir(8.5, 3));
    cr_assert(vlen(vsub(mid, vscale(vadd(TEXEL(8, 3), TEXEL(9, 3)), 0.5))) < 1e-9);
#undef TEXEL
    fx_free(&f);
    fx_init(&f, FX_ENV_MAP, true);
    rng r;
    rng_seed(&r, 11, 0);
    for (int i = 0; i < 100000; i++) {
        vec3 d = warp_uniform_sphere(rng_uniform(&r), rng_uniform(&r));
        rgb a = env_radiance(&f.sc, d), b = tungsten_env(&f, d);
        cr_assert(vlen(vsub(a, b)) <= 1e-9 * (1 + vlen(b)), "%g vs %g", a.x, b.x);
    }
    fx_free(&f);
}

Test(emit, pick_roundtrip)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_MAP, true);
    rng r;
    rng_seed(&r, 1, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    sampler_writer_init(&W, 2, 0);
    for (int i = 0; i < NRT; i++) {
        double prob, prob2;
        sampler_begin(&s.base, STREAM_EMITTER, 0);
        int p = emitter_pick(&f.sc, &s.base, &prob);
        cr_assert(p >= 0 && p != FX_PLAIN && prob == emitter_pick_prob(&f.sc, p));
        sampler_begin(&W.base, STREAM_EMITTER, 0);
        cr_assert(emitter_pick_invert(&f.sc, p, &W.base));
        cr_assert_eq(W.kind[STREAM_EMITTER][0], DIM_DISCRETE);
        struct sampler_replay rp;
        replay_begin(&rp);
        cr_assert_eq(emitter_pick(&f.sc, &rp.base, &prob2), p);
    }
    cr_assert(!emitter_pick_invert(&f.sc, FX_PLAIN, &W.base));
    fx_free(&f);
}

static void pos_roundtrip(int prim)
{
    struct emit_fixture f;
    fx_init(&f, FX_ENV_NONE, false);
    rng r;
    rng_seed(&r, 3 + prim, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    sampler_writer_init(&W, 4, prim);
    long ok = 0;
    for (int i = 0; i < NRT; i++) {
        struct emitter_pos a, b;
        sampler_begin(&s.base, STREAM_EMITTER, 0);
        cr_assert(emitter_sample_pos(&f.sc, prim, &s.base, &a));
        cr_assert(fabs(a.pdf - emitter_pdf_pos(&f.sc, prim, a.p)) <= 1e-15 * a.pdf);
        cr_assert(fabs(vlen(a.n) - 1) < 1e-12);
        sampler_writer_clear(&W);
        sampler_begin(&W.base, STREAM_EMITTER, 0);
        if (!emitter_invert_pos(&f.sc, prim, &a, &W.base)) continue;
        struct sampler_replay rp;
        replay_begin(&rp);
        cr_assert(emitter_sample_pos(&f.sc, prim, &rp.base, &b));
        ok += close_rel(a.p, b.p) && a.tri == b.tri && close_rel(a.n, b.n);
    }
    cr_assert(ok >= RT_MIN_OK * NRT, "prim %d: %ld of %d", prim, ok, NRT);
    if (prim == FX_MESH) cr_assert_eq(W.kind[STREAM_EMITTER][0], DIM_DISCRETE);
    fx_free(&f);
}

Test(emit, pos_roundtrip_quad) { pos_roundtrip(FX_QUAD); }
Test(emit, pos_roundtrip_mesh) { pos_roundtrip(FX_MESH); }
Test(emit, pos_roundtrip_sphere) { pos_roundtrip(FX_SPHERE); }

Test(emit, dir_roundtrip)
{
    rng r;
    rng_seed(&r, 8, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    sampler_writer_init(&W, 9, 0);
    long ok = 0;
    for (int i = 0; i < NRT; i++) {
        vec3 n = warp_uniform_sphere(rng_uniform(&r), rng_uniform(&r));
        double pdf, pdf2;
        sampler_begin(&s.base, STREAM_EMITTER, 0);
        vec3 d = emitter_sample_dir(n, &s.base, &pdf);
        cr_assert(fabs(pdf - emitter_pdf_dir(n, d)) < 1e-9);
        sampler_writer_clear(&W);
        sampler_begin(&W.base, STREAM_EMITTER, 0);
        if (!emitter_invert_dir(n, d, &W.base)) continue;
        struct sampler_replay rp;
        replay_begin(&rp);
        ok += close_rel(d, emitter_sample_dir(n, &rp.base, &pdf2));
    }
    cr_assert(ok >= RT_MIN_OK * NRT, "%ld", ok);
    cr_assert_eq(emitter_pdf_dir(v3(0, 0, 1), v3(0, 0, -1)), 0.0);
}

static void env_roundtrip(enum fx_env kind)
{
    struct emit_fixture f;
    fx_init(&f, kind, true);
    rng r;
    rng_seed(&r, 12, kind);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    sampler_writer_init(&W, 13, kind);
    long ok = 0, ok_o = 0;
    for (int i = 0; i < NRT; i++) {
        vec3 d, d2;
        double pdf, pdf2;
        sampler_begin(&s.base, STREAM_EMITTER, 0);
        cr_assert(env_sample_dir(&f.sc, &s.base, &d, &pdf));
        cr_assert(fabs(pdf - env_pdf_dir(&f.sc, d)) <= 1e-6 * pdf, "%g vs %g", pdf, env_pdf_dir(&f.sc, d));
        cr_assert(luminance(env_radiance(&f.sc, d)) > 0); /* never samples the black row */
        vec3 o = env_sample_origin(&f.sc, d, &s.base, &pdf2);
        double R = env_radius(&f.sc);
        cr_assert(fabs(pdf2 * M_PI * R * R - 1) < 1e-12);
        /* the origin is outside the bounding sphere, on the environment's side */
        vec3 c = vscale(vadd(f.sc.bbox_min, f.sc.bbox_max), 0.5);
        cr_assert(fabs(vdot(vsub(o, c), d) - R) < 1e-9 * R && vlen(vsub(o, c)) <= sqrt(2) * R + 1e-9);
        sampler_writer_clear(&W);
        sampler_begin(&W.base, STREAM_EMITTER, 0);
        if (!env_invert_dir(&f.sc, d, &W.base)) continue;
        if (!env_invert_origin(&f.sc, d, o, &W.base)) continue;
        struct sampler_replay rp;
        replay_begin(&rp);
        cr_assert(env_sample_dir(&f.sc, &rp.base, &d2, &pdf2));
        ok += close_rel(d, d2);
        ok_o += close_rel(o, env_sample_origin(&f.sc, d, &rp.base, &pdf2));
    }
    cr_assert(ok >= RT_MIN_OK * NRT && ok_o >= RT_MIN_OK * NRT, "%ld %ld", ok, ok_o);
    fx_free(&f);
}

Test(emit, env_map_roundtrip) { env_roundtrip(FX_ENV_MAP); }
Test(emit, env_const_roundtrip) { env_roundtrip(FX_ENV_CONST); }

static void camera_roundtrip(enum recon_filter f)
{
    struct camera c = fx_camera(v3(1, 2, 3), v3(1, -0.3, 0.5), 35, 320, 200);
    c.filter = f;
    int m = camera_margin(&c);
    rng r;
    rng_seed(&r, 21, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    sampler_writer_init(&W, 22, 0);
    long ok = 0;
    for (int i = 0; i < NRT; i++) {
        double px, py, qx, qy, pdf;
        rng r2 = r;
        double ux = rng_uniform(&r2), uy = rng_uniform(&r2);
        sampler_begin(&s.base, STREAM_CAMERA, 0);
        vec3 d = camera_sample_dir(&c, c.pos, &s.base, &px, &py, &pdf);
        cr_assert(px == ux * (320 + 2 * m) - m && py == uy * (200 + 2 * m) - m);
        double pr = camera_raster(&c, c.pos, d, &qx, &qy);
        cr_assert(pr > 0 && fabs(pdf - pr) <= 1e-9 * pr, "sampled pdf %g vs raster pdf %g", pdf, pr);
        cr_assert(fabs(qx - px) < 1e-7 * 320 && fabs(qy - py) < 1e-7 * 200, "%g %g vs %g %g", qx, qy, px, py);
        cr_assert(camera_pdf_dir(&c, c.pos, d) > 0);
        sampler_writer_clear(&W);
        sampler_begin(&W.base, STREAM_CAMERA, 0);
        camera_invert(&c, qx, qy, &W.base);
        cr_assert_eq(W.kind[STREAM_CAMERA][0], DIM_IMAGE_X);
        cr_assert_eq(W.kind[STREAM_CAMERA][1], DIM_IMAGE_Y);
        struct sampler_replay rp;
        sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])W.u);
        sampler_begin(&rp.base, STREAM_CAMERA, 0);
        ok += close_rel(d, camera_sample_dir(&c, c.pos, &rp.base, &qx, &qy, NULL));
    }
    cr_assert(ok >= RT_MIN_OK * NRT, "%ld", ok);
}
Test(emit, camera_raster_and_roundtrip) { camera_roundtrip(FILTER_BOX); }
Test(emit, camera_raster_and_roundtrip_tent) { camera_roundtrip(FILTER_TENT); }

/* The tent's film reaches one pixel beyond the image: 400 px across a 90 degree fov, so a pixel at
 * the right edge is tan = 1 + 2/400 at most. */
Test(emit, camera_tent_film_margin)
{
    struct camera c = fx_camera(v3(0, 0, 0), v3(0, 0, 1), 45, 400, 200);
    c.filter = FILTER_TENT;
    vec3 sd = c.basis.s, td = c.basis.t, nd = c.basis.n;
    double px, py;
    cr_assert(camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(sd, 1.004))), &px, &py) && px > 400 && px < 401, "%g", px);
    cr_assert(!camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(sd, 1.006))), &px, &py));
    cr_assert(camera_raster(&c, c.pos, vnorm(vsub(nd, vscale(sd, 1.004))), &px, &py) && px < 0 && px > -1, "%g", px);
    cr_assert(camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(td, 0.504))), &px, &py) && py < 0 && py > -1, "%g", py);
    cr_assert(!camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(td, 0.506))), &px, &py));
    /* uniform over a film of 402 x 202 pixels: 1 / (A cos^3) with A grown by that ratio */
    double a = 4 * 1.0 / 2 * (402.0 * 202) / (400.0 * 200);
    cr_assert(fabs(camera_pdf_dir(&c, c.pos, nd) - 1.0 / a) < 1e-12);
}

/* Tungsten's pinhole facts: horizontal fov, raster y downward, pdf 1/(A cos^3) with the plane area
 * A = (2 tan)^2 / aspect; behind or outside the image: 0. */
Test(emit, camera_conventions)
{
    struct camera c = fx_camera(v3(0, 0, 0), v3(0, 0, 1), 45, 400, 200);
    vec3 sd = c.basis.s, td = c.basis.t, nd = c.basis.n;
    double px, py;
    cr_assert(camera_raster(&c, c.pos, nd, &px, &py) && fabs(px - 200) < 1e-9 && fabs(py - 100) < 1e-9);
    /* the right edge of the image is 45 degrees off axis (horizontal fov 90) */
    cr_assert(camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(sd, 0.999))), &px, &py) && px > 399 && px < 400);
    cr_assert(!camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(sd, 1.001))), &px, &py));
    /* up (+t) is the top of the image: small raster y; the top edge at tan = 1 / aspect */
    cr_assert(camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(td, 0.499))), &px, &py) && py < 1 && py >= 0);
    cr_assert(!camera_raster(&c, c.pos, vnorm(vadd(nd, vscale(td, 0.501))), &px, &py));
    cr_assert(!camera_raster(&c, c.pos, vneg(nd), &px, &py));
    cr_assert_eq(camera_pdf_dir(&c, c.pos, vneg(nd)), 0.0);
    cr_assert_eq(camera_pdf_dir(&c, c.pos, vnorm(vadd(nd, vscale(sd, 1.001)))), 0.0);
    cr_assert(fabs(camera_pdf_dir(&c, c.pos, nd) - 1.0 / (4 * 1.0 / 2)) < 1e-12);
    vec3 d = vnorm(v3(0.5, 0.25, 1));
    double ct = vdot(d, v3(0, 0, 1));
    vec3 dw = vnorm(frame_to_world(&c.basis, d));
    cr_assert(fabs(camera_pdf_dir(&c, c.pos, dw) - 1.0 / (2 * ct * ct * ct)) < 1e-12);
}
