/* Unit tests: vectors, transforms, RNG, warps and their inverses, samplers, Fresnel. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "base/vecmath.h"
#include "bsdf/fresnel.h"
#include "sampler/sampler.h"
#include "sampling/warp.h"

Test(math, frame_is_orthonormal)
{
    rng r;
    rng_seed(&r, 1, 0);
    for (int i = 0; i < 10000; i++) {
        vec3 n = warp_uniform_sphere(rng_uniform(&r), rng_uniform(&r));
        frame f = frame_from_normal(n);
        cr_assert(fabs(vdot(f.s, f.t)) < 1e-12 && fabs(vdot(f.s, f.n)) < 1e-12 && fabs(vdot(f.t, f.n)) < 1e-12);
        cr_assert(fabs(vlen(f.s) - 1) < 1e-12 && fabs(vlen(f.t) - 1) < 1e-12);
        /* right-handed: s x t = n */
        cr_assert(vlen(vsub(vcross(f.s, f.t), n)) < 1e-12);
    }
}

Test(math, mat4_invert_and_trs)
{
    mat4 m = mat4_trs(v3(1, 2, 3), v3(30, 45, 60), v3(2, 3, 4)), inv;
    cr_assert(mat4_invert(&m, &inv));
    mat4 id = mat4_mul(&m, &inv);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            cr_assert(fabs(id.m[i][j] - (i == j)) < 1e-12);
    /* normals stay perpendicular to transformed tangents */
    vec3 t = v3(1, -2, 0.5), n = v3(2, 1, 0);
    cr_assert(fabs(vdot(t, n)) < 1e-12);
    cr_assert(fabs(vdot(mat4_vector(&m, t), mat4_normal(&m, n))) < 1e-9);
}

Test(math, rot_yxz_single_axes)
{
    /* Tungsten's Y angle: rows [c,0,-s],[0,1,0],[s,0,c], so 90 degrees maps +x to +z and +z to -x
     * (the textbook's Ry turns the other way). X and Z alone are textbook. */
    mat4 ry = mat4_rot_yxz(v3(0, 90, 0));
    vec3 z = mat4_vector(&ry, v3(0, 0, 1)), xy = mat4_vector(&ry, v3(1, 0, 0));
    cr_assert(fabs(z.x + 1) < 1e-12 && fabs(z.z) < 1e-12, "got %g %g %g", z.x, z.y, z.z);
    cr_assert(fabs(xy.z - 1) < 1e-12 && fabs(xy.x) < 1e-12, "got %g %g %g", xy.x, xy.y, xy.z);
    mat4 r30 = mat4_rot_yxz(v3(0, 30, 0));
    double c = cos(M_PI / 6), s = sin(M_PI / 6), want[3][3] = {{c, 0, -s}, {0, 1, 0}, {s, 0, c}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            cr_assert(fabs(r30.m[i][j] - want[i][j]) < 1e-12);
    mat4 rx = mat4_rot_yxz(v3(90, 0, 0)), rz = mat4_rot_yxz(v3(0, 0, 90));
    vec3 yx = mat4_vector(&rx, v3(0, 1, 0)), xz = mat4_vector(&rz, v3(1, 0, 0));
    cr_assert(fabs(yx.z - 1) < 1e-12 && fabs(xz.y - 1) < 1e-12);
    /* Z is applied first, then X: rotYXZ(90,0,90) maps +x to +y by Z, then +y to +z by X. */
    mat4 m = mat4_rot_yxz(v3(90, 0, 90));
    vec3 x = mat4_vector(&m, v3(1, 0, 0));
    cr_assert(fabs(x.z - 1) < 1e-12, "got %g %g %g", x.x, x.y, x.z);
    /* then Y: rotYXZ(90,90,90) takes that +z on to -x */
    mat4 m3 = mat4_rot_yxz(v3(90, 90, 90));
    x = mat4_vector(&m3, v3(1, 0, 0));
    cr_assert(fabs(x.x + 1) < 1e-12, "got %g %g %g", x.x, x.y, x.z);
}

Test(math, rng_streams_differ_and_repeat)
{
    rng a, b, c;
    rng_seed(&a, 42, 1);
    rng_seed(&b, 42, 2);
    rng_seed(&c, 42, 1);
    int same = 0;
    for (int i = 0; i < 1000; i++) {
        uint32_t x = rng_u32(&a), y = rng_u32(&b), z = rng_u32(&c);
        same += x == y;
        cr_assert_eq(x, z);
    }
    cr_assert_lt(same, 5);
    double m = 0;
    for (int i = 0; i < 100000; i++) {
        double u = rng_uniform(&a);
        cr_assert(u >= 0 && u < 1);
        m += u;
    }
    cr_assert(fabs(m / 100000 - 0.5) < 0.005); /* 5.5 sigma */
}

static void check_roundtrip(vec3 (*warp)(double, double), void (*inv)(vec3, double *, double *))
{
    rng r;
    rng_seed(&r, 7, 0);
    for (int i = 0; i < 100000; i++) {
        double u1 = rng_uniform(&r), u2 = rng_uniform(&r), w1, w2;
        vec3 d = warp(u1, u2);
        inv(d, &w1, &w2);
        vec3 e = warp(w1, w2);
        cr_assert(vlen(vsub(d, e)) < 1e-9, "u=(%g,%g) -> (%g,%g)", u1, u2, w1, w2);
    }
}

/* The quarter-turn reduction and its series against long-double libm (whose argument 2 pi u keeps
 * 64 bits, so the reference is good to 1e-18): 1M uniform u plus the quadrant edges and negative
 * turns. 3e-16 absolute is little more than one ulp of 1. */
Test(math, sincos_turns_matches_libm)
{
    rng r;
    rng_seed(&r, 7, 0);
    double worst = 0;
    for (int i = 0; i < 1000000 + 12; i++) {
        double u = i < 1000000 ? rng_uniform(&r) : (i - 1000000) * 0.125 - 0.5, s, c;
        sincos_turns(u, &s, &c);
        long double phi = 2 * 3.14159265358979323846264338327950288L * u;
        worst = fmax(worst, fmax(fabs(s - (double)sinl(phi)), fabs(c - (double)cosl(phi))));
    }
    cr_assert(worst < 3e-16, "max error %g", worst);
    double s, c;
    sincos_turns(0.25, &s, &c);
    cr_assert(s == 1 && c == 0);
    sincos_turns(0.5, &s, &c);
    cr_assert(s == 0 && c == -1);
}

Test(math, warp_inverses)
{
    check_roundtrip(warp_cosine_hemisphere, warp_cosine_hemisphere_invert);
    check_roundtrip(warp_uniform_sphere, warp_uniform_sphere_invert);
    rng r;
    rng_seed(&r, 9, 0);
    for (int i = 0; i < 100000; i++) {
        double u1 = rng_uniform(&r), u2 = rng_uniform(&r), b1, b2, w1, w2, c1, c2;
        warp_triangle(u1, u2, &b1, &b2);
        cr_assert(b1 >= 0 && b2 >= 0 && b1 + b2 <= 1 + 1e-12);
        warp_triangle_invert(b1, b2, &w1, &w2);
        warp_triangle(w1, w2, &c1, &c2);
        cr_assert(fabs(b1 - c1) < 1e-9 && fabs(b2 - c2) < 1e-9);
    }
}

Test(math, writer_replay_roundtrip_and_discrete_interval)
{
    static struct sampler_writer w;
    sampler_writer_init(&w, 3, 0);
    sampler_begin(&w.base, STREAM_EMITTER, 2);
    for (int i = 0; i < 1000; i++) {
        double u = invert_discrete(0.25, 0.5, sampler_fresh(&w.base));
        cr_assert(u >= 0.25 && u < 0.5);
    }
    sampler_put(&w.base, DIM_DISCRETE, 0.3);
    sampler_put(&w.base, DIM_CONTINUOUS, 0.7);
    struct sampler_replay r;
    sampler_replay_init(&r, (const double(*)[STREAM_DIMS])w.u);
    sampler_begin(&r.base, STREAM_EMITTER, 2);
    cr_assert_eq(sampler_next(&r.base, DIM_DISCRETE), 0.3);
    cr_assert_eq(sampler_next(&r.base, DIM_CONTINUOUS), 0.7);
    cr_assert_eq(w.kind[STREAM_EMITTER][2 * SAMPLER_BLOCK], DIM_DISCRETE);
    cr_assert(invert_discrete(0.25, 0.5, 1.0) < 0.5);
}

Test(math, fresnel_known_values)
{
    double ct;
    double r0 = fresnel_dielectric(1.0, 1.5, &ct);
    cr_assert(fabs(r0 - 0.04) < 1e-12 && fabs(ct - 1) < 1e-12);
    /* total internal reflection from inside glass beyond the critical angle */
    cr_assert_eq(fresnel_dielectric(cos(45 * M_PI / 180), 1 / 1.5, &ct), 1.0);
    /* a conductor with k = 0 is a dielectric */
    rgb c = fresnel_conductor(0.6, v3s(1.5), v3s(0));
    cr_assert(fabs(c.x - fresnel_dielectric(0.6, 1.5, &ct)) < 1e-12);
    cr_assert(fabs(fresnel_conductor(1.0, v3s(0.2), v3s(3)).y - (sqr(0.8) + 9) / (sqr(1.2) + 9)) < 1e-12);
}
