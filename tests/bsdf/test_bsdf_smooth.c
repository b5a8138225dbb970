/* Unit tests of the smooth BSDF families (lambert, mirror, conductor, dielectric, plastic):
 * dispatch and flags, sampled pdf/weight against pdf()/eval(), delta directions and weights,
 * transport-mode scaling, reciprocity, and the inversion round trip sample -> invert -> replay.
 * The statistical tests (chi-square, frequencies, energy, uniformity of inverted numbers) are in
 * test_bsdf_smooth_stat.c. */
#include <criterion/criterion.h>

#include "bsdf/fresnel.h"
#include "sampling/warp.h"
#include "support/bsdf_smooth_util.h"

static double rel_err(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

/* A sampler returning one fixed number, to force a discrete outcome. */
struct fixed_sampler {
    struct sampler base;
    double u;
};
static double fixed_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    return ((struct fixed_sampler *)s)->u;
}
static const struct sampler_ops fixed_ops = {fixed_next, NULL, NULL};
static struct sampler *fixed(struct fixed_sampler *f, double u)
{
    f->base = (struct sampler){&fixed_ops, 0, 0, 0};
    f->u = u;
    return &f->base;
}

Test(bsdf_smooth, dispatch_and_flags)
{
    cr_assert_null(bsdf_ops_for(BSDF_NULL));
    const struct {
        enum bsdf_type t;
        const struct bsdf_ops *ops;
        int dims;
        bool tr, delta;
    } want[] = {
        {BSDF_LAMBERT, &bsdf_lambert_ops, 2, false, false},    {BSDF_MIRROR, &bsdf_conductor_ops, 0, false, true},
        {BSDF_CONDUCTOR, &bsdf_conductor_ops, 0, false, true}, {BSDF_DIELECTRIC, &bsdf_dielectric_ops, 1, true, true},
        {BSDF_PLASTIC, &bsdf_plastic_ops, 3, false, false},
    };
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
        const struct bsdf_ops *o = bsdf_ops_for(want[i].t);
        cr_assert_eq(o, want[i].ops);
        cr_assert_eq(o->dims, want[i].dims);
        cr_assert_eq(o->transmissive, want[i].tr);
        cr_assert_eq(o->delta_only, want[i].delta);
        cr_assert(o->dims <= SAMPLER_BLOCK);
    }
}

/* For continuous samples: out.pdf == pdf(wi, wo) and out.weight == eval |cos wo| / pdf (rel 1e-6);
 * delta samples of plastic report pdf = P(coat) and weight = Fi / P(coat), P(coat) in proportion
 * to Fi against the substrate's T (1 - Fi) mean(albedo). */
static void check_sample_consistency(const struct bsdf *b)
{
    struct bsdf_ctx c = bsdf_ctx_at(b, NULL);
    const struct bsdf_ops *ops = bsdf_ops_for(b->type);
    struct sampler_independent s;
    sampler_independent_init(&s, 11, b->type);
    for (int k = 0; k < N_WI_UP; k++) {
        vec3 wi = wi_up(k);
        int ncont = 0;
        for (int i = 0; i < 20000; i++) {
            struct bsdf_sample o;
            sampler_begin(&s.base, STREAM_CAMERA, 0);
            cr_assert(ops->sample(&c, wi, &s.base, TRANSPORT_RADIANCE, &o));
            cr_assert(fabs(vlen(o.wo) - 1) < 1e-12);
            if (o.delta) {
                double ct, Fi = fresnel_dielectric(wi.z, b->ior, &ct);
                double T = exp(-2 * b->thickness * (b->sigma_a.x + b->sigma_a.y + b->sigma_a.z) / 3);
                double pc = Fi / (Fi + T * (1 - Fi) * (c.albedo.x + c.albedo.y + c.albedo.z) / 3);
                cr_assert_eq(o.lobe, PLASTIC_LOBE_COAT);
                cr_assert(rel_err(o.pdf, pc) < 1e-12);
                cr_assert(rel_err(o.weight.x, Fi / pc) < 1e-12 && o.weight.x == o.weight.z);
                cr_assert(vlen(vsub(o.wo, smooth_reflect(wi))) == 0);
                continue;
            }
            ncont++;
            cr_assert(o.wo.z > 0);
            double p = ops->pdf(&c, wi, o.wo);
            cr_assert(rel_err(o.pdf, p) < 1e-6, "pdf %g vs %g", o.pdf, p);
            rgb f = ops->eval(&c, wi, o.wo, TRANSPORT_RADIANCE);
            for (int ch = 0; ch < 3; ch++)
                cr_assert(rel_err(vget(o.weight, ch), vget(f, ch) * fabs(o.wo.z) / p) < 1e-6);
        }
        cr_assert(ncont > 0);
    }
}

Test(bsdf_smooth, lambert_sample_matches_pdf_and_eval)
{
    struct bsdf b = make_bsdf(BSDF_LAMBERT);
    b.albedo = v3(0.7, 0.5, 0.2);
    check_sample_consistency(&b);
}

Test(bsdf_smooth, plastic_sample_matches_pdf_and_eval)
{
    struct bsdf w = make_bsdf(BSDF_PLASTIC), col = plastic_coloured();
    check_sample_consistency(&w);
    check_sample_consistency(&col);
}

Test(bsdf_smooth, below_horizon_is_black)
{
    struct bsdf l = make_bsdf(BSDF_LAMBERT), p = plastic_coloured();
    const struct bsdf *bs[] = {&l, &p};
    vec3 up = dir_cos_phi(0.6, 1), down = dir_cos_phi(-0.6, 2);
    for (int i = 0; i < 2; i++) {
        struct bsdf_ctx c = bsdf_ctx_at(bs[i], NULL);
        cr_assert(vzero(bsdf_eval(&c, up, down, TRANSPORT_RADIANCE)));
        cr_assert(vzero(bsdf_eval(&c, down, up, TRANSPORT_RADIANCE)));
        cr_assert_eq(bsdf_pdf(&c, up, down), 0);
        struct bsdf_sample o;
        struct fixed_sampler f;
        cr_assert(!bsdf_sample(&c, down, fixed(&f, 0.5), TRANSPORT_RADIANCE, &o));
    }
}

/* Lambert and Tungsten's plastic are symmetric in (wi, wo): (1 - Fi)(1 - Fo) and the absorption
 * path length 1/cos wi + 1/cos wo are both symmetric. */
Test(bsdf_smooth, reciprocity)
{
    struct bsdf l = make_bsdf(BSDF_LAMBERT), pw = make_bsdf(BSDF_PLASTIC), pc = plastic_coloured();
    l.albedo = v3(0.9, 0.4, 0.1);
    const struct bsdf *bs[] = {&l, &pw, &pc};
    rng r;
    rng_seed(&r, 5, 0);
    for (int i = 0; i < 3; i++) {
        struct bsdf_ctx c = bsdf_ctx_at(bs[i], NULL);
        for (int j = 0; j < 10000; j++) {
            vec3 a = warp_cosine_hemisphere(rng_uniform(&r), rng_uniform(&r));
            vec3 b = warp_cosine_hemisphere(rng_uniform(&r), rng_uniform(&r));
            rgb fab = bsdf_eval(&c, a, b, TRANSPORT_RADIANCE), fba = bsdf_eval(&c, b, a, TRANSPORT_RADIANCE);
            for (int ch = 0; ch < 3; ch++)
                cr_assert(rel_err(vget(fab, ch), vget(fba, ch)) < 1e-12);
            cr_assert(vmax(fab) > 0);
        }
    }
}

Test(bsdf_smooth, mirror_and_conductor_reflect)
{
    struct bsdf m = make_bsdf(BSDF_MIRROR), k = make_bsdf(BSDF_CONDUCTOR);
    m.albedo = v3(0.9, 0.8, 0.7);
    k.albedo = v3(0.5, 1, 1);
    for (int i = 0; i < N_WI_UP; i++) {
        vec3 wi = wi_up(i);
        struct bsdf_sample o;
        struct fixed_sampler f;
        struct bsdf_ctx cm = bsdf_ctx_at(&m, NULL), ck = bsdf_ctx_at(&k, NULL);
        cr_assert(bsdf_sample(&cm, wi, fixed(&f, 0.5), TRANSPORT_RADIANCE, &o));
        cr_assert(o.delta && o.pdf == 1 && o.lobe == CONDUCTOR_LOBE_REFLECT);
        cr_assert(o.wo.x == -wi.x && o.wo.y == -wi.y && o.wo.z == wi.z);
        cr_assert(vlen(vsub(o.weight, m.albedo)) == 0);
        cr_assert(vzero(bsdf_eval(&cm, wi, o.wo, TRANSPORT_RADIANCE)) && bsdf_pdf(&cm, wi, o.wo) == 0);
        cr_assert(bsdf_sample(&ck, wi, fixed(&f, 0.5), TRANSPORT_RADIANCE, &o));
        rgb F = fresnel_conductor(wi.z, k.eta, k.k);
        cr_assert(vlen(vsub(o.weight, vmul(k.albedo, F))) < 1e-15);
        cr_assert(o.delta && o.pdf == 1 && vlen(vsub(o.wo, smooth_reflect(wi))) == 0);
        cr_assert(vmax(o.weight) <= 1 && o.weight.x > 0);
        cr_assert(vzero(bsdf_eval(&ck, wi, o.wo, TRANSPORT_RADIANCE)) && bsdf_pdf(&ck, wi, o.wo) == 0);
        cr_assert(!bsdf_sample(&ck, vneg(wi), fixed(&f, 0.5), TRANSPORT_RADIANCE, &o));
    }
}

/* Refraction obeys Snell's law, is reversible, and carries 1/eta^2 only in radiance mode. */
Test(bsdf_smooth, dielectric_refraction_and_modes)
{
    struct bsdf b = make_bsdf(BSDF_DIELECTRIC);
    b.albedo = v3(1, 0.9, 0.8);
    struct bsdf_ctx c = bsdf_ctx_at(&b, NULL);
    struct fixed_sampler f;
    for (int side = 0; side < 2; side++)
        for (int i = 0; i < N_WI_UP; i++) {
            vec3 wi = wi_up(i);
            if (side) wi.z = -wi.z;
            double eta_i = side ? b.ior : 1, eta_t = side ? 1 : b.ior, ct;
            double F = fresnel_dielectric(fabs(wi.z), eta_t / eta_i, &ct);
            struct bsdf_sample o, oi;
            /* u = 0 always reflects (F > 0 for ior != 1). */
            cr_assert(bsdf_sample(&c, wi, fixed(&f, 0.0), TRANSPORT_RADIANCE, &o));
            cr_assert(o.lobe == DIELECTRIC_LOBE_REFLECT && o.delta);
            cr_assert(vlen(vsub(o.wo, smooth_reflect(wi))) == 0);
            cr_assert(rel_err(o.pdf, F) < 1e-15 && vlen(vsub(o.weight, b.albedo)) < 1e-15);
            bool ok = bsdf_sample(&c, wi, fixed(&f, nextafter(1.0, 0.0)), TRANSPORT_RADIANCE, &o);
            if (F >= 1) { /* total internal reflection: u < 1 = F always reflects */
                cr_assert(side == 1 && ok && o.lobe == DIELECTRIC_LOBE_REFLECT && o.pdf == 1);
                cr_assert(vlen(vsub(o.weight, b.albedo)) < 1e-15);
                continue;
            }
            cr_assert(ok && o.lobe == DIELECTRIC_LOBE_REFRACT && o.delta);
            cr_assert(o.wo.z * wi.z < 0 && fabs(vlen(o.wo) - 1) < 1e-14);
            double sin_i = sqrt(1 - wi.z * wi.z), sin_t = sqrt(1 - o.wo.z * o.wo.z);
            cr_assert(fabs(eta_i * sin_i - eta_t * sin_t) < 1e-12);
            cr_assert(vdot(v3(wi.x, wi.y, 0), v3(o.wo.x, o.wo.y, 0)) <= 0); /* other side of the normal */
            cr_assert(rel_err(o.pdf, 1 - F) < 1e-12);
            double scale = sqr(eta_i / eta_t);
            cr_assert(vlen(vsub(o.weight, vscale(b.albedo, scale))) < 1e-14);
            cr_assert(bsdf_sample(&c, wi, fixed(&f, nextafter(1.0, 0.0)), TRANSPORT_IMPORTANCE, &oi));
            cr_assert(vlen(vsub(oi.weight, b.albedo)) < 1e-15 && vlen(vsub(oi.wo, o.wo)) == 0);
            /* reversibility: refracting wo back gives wi */
            struct bsdf_sample back;
            cr_assert(bsdf_sample(&c, o.wo, fixed(&f, nextafter(1.0, 0.0)), TRANSPORT_RADIANCE, &back));
            cr_assert(back.lobe == DIELECTRIC_LOBE_REFRACT && vlen(vsub(back.wo, wi)) < 1e-12);
            cr_assert(vzero(bsdf_eval(&c, wi, o.wo, TRANSPORT_RADIANCE)) && bsdf_pdf(&c, wi, o.wo) == 0);
        }
    /* Grazing from inside (cos 0.05) is beyond the critical angle: total internal reflection. */
    vec3 wi = dir_cos_phi(-0.05, 1);
    struct bsdf_sample o;
    cr_assert(bsdf_sample(&c, wi, fixed(&f, 0.999), TRANSPORT_RADIANCE, &o));
    cr_assert(o.lobe == DIELECTRIC_LOBE_REFLECT && o.pdf == 1);
}

Test(bsdf_smooth, dielectric_without_refraction_reflects_with_weight_F)
{
    struct bsdf b = make_bsdf(BSDF_DIELECTRIC);
    b.enable_refraction = false;
    struct bsdf_ctx c = bsdf_ctx_at(&b, NULL);
    struct fixed_sampler f;
    for (int i = 0; i < N_WI_UP; i++) {
        vec3 wi = wi_up(i);
        double ct, F = fresnel_dielectric(wi.z, b.ior, &ct);
        struct bsdf_sample o;
        cr_assert(bsdf_sample(&c, wi, fixed(&f, 0.999), TRANSPORT_RADIANCE, &o));
        cr_assert(o.lobe == DIELECTRIC_LOBE_REFLECT && o.pdf == 1 && rel_err(o.weight.x, F) < 1e-15);
        /* the refracted direction cannot be inverted */
        static struct sampler_writer w;
        sampler_writer_init(&w, 1, 0);
        sampler_begin(&w.base, STREAM_CAMERA, 0);
        cr_assert(!bsdf_invert(&c, wi, smooth_refract(wi, b.ior, ct), &w.base));
    }
}

Test(bsdf_smooth, invert_rejects_impossible_directions)
{
    static struct sampler_writer w;
    sampler_writer_init(&w, 2, 0);
    struct bsdf l = make_bsdf(BSDF_LAMBERT), m = make_bsdf(BSDF_MIRROR), k = make_bsdf(BSDF_CONDUCTOR),
                d = make_bsdf(BSDF_DIELECTRIC), p = make_bsdf(BSDF_PLASTIC);
    vec3 wi = dir_cos_phi(0.7, 0.4), below = dir_cos_phi(-0.3, 2), other = dir_cos_phi(0.5, 1);
    const struct bsdf *all[] = {&l, &m, &k, &d, &p};
    for (int i = 0; i < 5; i++) {
        struct bsdf_ctx c = bsdf_ctx_at(all[i], NULL);
        sampler_begin(&w.base, STREAM_CAMERA, 0);
        cr_assert(!bsdf_invert(&c, wi, below, &w.base), "family %d accepted a wrong-side direction", i);
        sampler_begin(&w.base, STREAM_CAMERA, 0);
        bool ok = bsdf_invert(&c, wi, other, &w.base);
        cr_assert_eq(ok, !bsdf_ops_for(all[i]->type)->delta_only);
        /* non-transmissive families refuse wi below the surface */
        if (!bsdf_ops_for(all[i]->type)->transmissive) {
            sampler_begin(&w.base, STREAM_CAMERA, 0);
            cr_assert(!bsdf_invert(&c, below, other, &w.base));
        }
    }
    /* a reflection 1e-3 away from the mirror direction is not the delta direction */
    struct bsdf_ctx cm = bsdf_ctx_at(&m, NULL);
    vec3 near = vnorm(vadd(smooth_reflect(wi), v3(10 * SMOOTH_DELTA_TOL, 0, 0)));
    sampler_begin(&w.base, STREAM_CAMERA, 0);
    cr_assert(!bsdf_invert(&cm, wi, near, &w.base));
    /* ... but the same direction through single-precision hit points (1e-5 off) is */
    vec3 noisy = vnorm(vadd(smooth_reflect(wi), v3(0.07 * SMOOTH_DELTA_TOL, -0.07 * SMOOTH_DELTA_TOL, 0)));
    sampler_begin(&w.base, STREAM_CAMERA, 0);
    cr_assert(bsdf_invert(&cm, wi, noisy, &w.base));
}

/* Invert puts exactly `dims` numbers, discrete ones first and annotated so. */
Test(bsdf_smooth, invert_puts_dims_numbers_in_order)
{
    static struct sampler_writer w;
    sampler_writer_init(&w, 4, 0);
    struct bsdf d = make_bsdf(BSDF_DIELECTRIC), p = make_bsdf(BSDF_PLASTIC), l = make_bsdf(BSDF_LAMBERT);
    vec3 wi = dir_cos_phi(0.7, 0.4);
    struct bsdf_ctx cd = bsdf_ctx_at(&d, NULL), cp = bsdf_ctx_at(&p, NULL), cl = bsdf_ctx_at(&l, NULL);
    int base = 2 * SAMPLER_BLOCK;
    sampler_begin(&w.base, STREAM_EMITTER, 2);
    cr_assert(bsdf_invert(&cd, wi, smooth_reflect(wi), &w.base));
    cr_assert(w.kind[STREAM_EMITTER][base] == DIM_DISCRETE && isnan(w.u[STREAM_EMITTER][base + 1]));
    sampler_writer_clear(&w);
    sampler_begin(&w.base, STREAM_EMITTER, 2);
    cr_assert(bsdf_invert(&cp, wi, smooth_reflect(wi), &w.base));
    cr_assert(w.kind[STREAM_EMITTER][base] == DIM_DISCRETE && w.kind[STREAM_EMITTER][base + 1] == DIM_CONTINUOUS &&
              w.kind[STREAM_EMITTER][base + 2] == DIM_CONTINUOUS && isnan(w.u[STREAM_EMITTER][base + 3]));
    sampler_writer_clear(&w);
    sampler_begin(&w.base, STREAM_EMITTER, 2);
    cr_assert(bsdf_invert(&cl, wi, dir_cos_phi(0.5, 1), &w.base));
    cr_assert(w.kind[STREAM_EMITTER][base] == DIM_CONTINUOUS && w.kind[STREAM_EMITTER][base + 1] == DIM_CONTINUOUS &&
              isnan(w.u[STREAM_EMITTER][base + 2]));
}

/* Round trip sample -> invert -> replay for every family: 100k samples per (family, wi), the same
 * wo (1e-6) and lobe must come back in >= 99.9% of cases (in practice all). */
static void roundtrip_family(const struct bsdf *b, const vec3 *wis, int nwi, enum transport mode)
{
    static struct sampler_writer w;
    sampler_writer_init(&w, 99, b->type);
    struct sampler_independent s;
    sampler_independent_init(&s, 7, b->type);
    struct bsdf_ctx c = bsdf_ctx_at(b, NULL);
    const long n = 100000;
    for (int k = 0; k < nwi; k++) {
        long fails[5] = {0};
        for (long i = 0; i < n; i++) {
            struct bsdf_sample o;
            double u0;
            fails[roundtrip_once(&c, wis[k], &s.base, &w, mode, &o, &u0)]++;
        }
        cr_log_info("roundtrip type %d wi (%.3f %.3f %.3f) mode %d: %ld inversion failures, %ld mismatches of %ld",
                    b->type, wis[k].x, wis[k].y, wis[k].z, mode, fails[2], fails[3], n);
        cr_assert_eq(fails[1], 0, "type %d wi %d: forward sampling failed %ld times", b->type, k, fails[1]);
        cr_assert_eq(fails[4], 0, "type %d wi %d: %ld passes used other than dims numbers", b->type, k, fails[4]);
        cr_assert(fails[2] + fails[3] <= n / 1000, "type %d wi %d: %ld inversion failures, %ld mismatches of %ld",
                  b->type, k, fails[2], fails[3], n);
    }
}

Test(bsdf_smooth, roundtrip_reflective_families)
{
    vec3 wis[N_WI_UP];
    for (int i = 0; i < N_WI_UP; i++)
        wis[i] = wi_up(i);
    struct bsdf l = make_bsdf(BSDF_LAMBERT), m = make_bsdf(BSDF_MIRROR), k = make_bsdf(BSDF_CONDUCTOR);
    roundtrip_family(&l, wis, N_WI_UP, TRANSPORT_RADIANCE);
    roundtrip_family(&m, wis, N_WI_UP, TRANSPORT_RADIANCE);
    roundtrip_family(&k, wis, N_WI_UP, TRANSPORT_IMPORTANCE);
}

Test(bsdf_smooth, roundtrip_plastic)
{
    vec3 wis[N_WI_UP];
    for (int i = 0; i < N_WI_UP; i++)
        wis[i] = wi_up(i);
    struct bsdf p = make_bsdf(BSDF_PLASTIC), pc = plastic_coloured();
    roundtrip_family(&p, wis, N_WI_UP, TRANSPORT_RADIANCE);
    roundtrip_family(&pc, wis, N_WI_UP, TRANSPORT_IMPORTANCE);
}

Test(bsdf_smooth, roundtrip_dielectric)
{
    vec3 wis[2 * N_WI_UP];
    for (int i = 0; i < N_WI_UP; i++) {
        wis[i] = wi_up(i);
        wis[N_WI_UP + i] = wi_up(i);
        wis[N_WI_UP + i].z = -wis[N_WI_UP + i].z; /* inside; the last two are beyond the critical angle */
    }
    struct bsdf d = make_bsdf(BSDF_DIELECTRIC), r = make_bsdf(BSDF_DIELECTRIC);
    r.enable_refraction = false;
    roundtrip_family(&d, wis, 2 * N_WI_UP, TRANSPORT_RADIANCE);
    roundtrip_family(&d, wis, 2 * N_WI_UP, TRANSPORT_IMPORTANCE);
    roundtrip_family(&r, wis, 2 * N_WI_UP, TRANSPORT_RADIANCE);
}

/* A delta direction recovered from path vertices (normalised difference of positions, rounding
 * ~1e-16, plus 1e-9 noise) still inverts, to the right lobe, and replays to the exact direction. */
Test(bsdf_smooth, delta_invert_accepts_path_space_rounding)
{
    static struct sampler_writer w;
    sampler_writer_init(&w, 8, 0);
    struct bsdf d = make_bsdf(BSDF_DIELECTRIC);
    struct bsdf_ctx c = bsdf_ctx_at(&d, NULL);
    struct fixed_sampler f;
    for (int side = 0; side < 2; side++)
        for (int lobe = 0; lobe < 2; lobe++) {
            vec3 wi = dir_cos_phi(side ? -0.9 : 0.6, 0.7);
            struct bsdf_sample o, back;
            cr_assert(bsdf_sample(&c, wi, fixed(&f, lobe ? 0.999 : 0.0), TRANSPORT_RADIANCE, &o));
            cr_assert_eq(o.lobe, lobe);
            vec3 x0 = v3(0.3, -1.2, 4.0), x1 = vadd(x0, vscale(o.wo, 3.7));
            vec3 wo = vnorm(vadd(vsub(x1, x0), v3(1e-9, -2e-9, 1e-9)));
            sampler_begin(&w.base, STREAM_CAMERA, 1);
            cr_assert(bsdf_invert(&c, wi, wo, &w.base));
            struct sampler_replay rp;
            sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w.u);
            sampler_begin(&rp.base, STREAM_CAMERA, 1);
            cr_assert(bsdf_sample(&c, wi, &rp.base, TRANSPORT_RADIANCE, &back));
            cr_assert(back.lobe == lobe && vlen(vsub(back.wo, o.wo)) == 0);
        }
}
