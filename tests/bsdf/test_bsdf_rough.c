/* Fast unit tests of the microfacet module and the rough BSDF families: normalisation of D,
 * the normal map and its inverse, sampled pdf/weight against pdf()/eval(), reciprocity, and the
 * inversion round trip sample -> invert -> replay (thesis Eq. 5.2). */
#include <criterion/criterion.h>

#include "support/rough_util.h"

static const enum mf_dist dists[] = {MF_BECKMANN, MF_GGX};

/* integral over the hemisphere of D(m) m.z = 2 pi int_0^{pi/2} D(theta) cos sin dtheta = 1;
 * midpoint rule with 400k steps: error << 1e-6 even for alpha = 0.05. */
Test(bsdf_rough, microfacet_D_normalised)
{
    const double alphas[] = {0.05, 0.1, 0.3, 0.7, 1.0};
    for (int d = 0; d < 2; d++)
        for (int a = 0; a < 5; a++) {
            const int n = 400000;
            double s = 0, h = 0.5 * M_PI / n;
            for (int i = 0; i < n; i++) {
                double t = (i + 0.5) * h;
                s += mf_D(dists[d], alphas[a], v3(sin(t), 0, cos(t))) * cos(t) * sin(t);
            }
            s *= 2 * M_PI * h;
            cr_assert(fabs(s - 1) < 1e-5, "dist %d alpha %g: integral %.8f", d, alphas[a], s);
        }
    cr_assert_eq(mf_D(MF_GGX, 0.3, v3(0.6, 0, -0.8)), 0.0);
    cr_assert_eq(mf_D(MF_BECKMANN, 0.3, v3(1, 0, 0)), 0.0);
}

Test(bsdf_rough, microfacet_G1_range_and_sidedness)
{
    rng r;
    rng_seed(&r, 11, 0);
    for (int i = 0; i < 100000; i++) {
        vec3 v = dir_cos(2 * rng_uniform(&r) - 1, 2 * M_PI * rng_uniform(&r));
        vec3 m = mf_sample(dists[i & 1], 0.5, rng_uniform(&r), rng_uniform(&r));
        double g = mf_G1(dists[i & 1], 0.5, v, m);
        /* Walter's rational Beckmann fit overshoots 1 by up to 6e-5 for a in [1.55, 1.6) */
        cr_assert(g >= 0 && g <= 1 + 1e-4, "G1 = %.10g", g);
        if (vdot(v, m) * v.z <= 0) cr_assert_eq(g, 0.0);
    }
    /* normal incidence: no shadowing */
    cr_assert(fabs(mf_G1(MF_GGX, 0.5, v3(0, 0, 1), v3(0, 0, 1)) - 1) < 1e-12);
    cr_assert(fabs(mf_G1(MF_BECKMANN, 0.5, v3(0, 0, 1), v3(0, 0, 1)) - 1) < 1e-12);
}

/* m = sample(u) -> invert(m) = u (to 1e-9) for both distributions over four decades of alpha. */
Test(bsdf_rough, microfacet_normal_map_roundtrip)
{
    const double alphas[] = {0.01, 0.1, 0.3, 0.7, 1.5};
    rng r;
    rng_seed(&r, 5, 0);
    long fails = 0;
    for (int d = 0; d < 2; d++)
        for (int a = 0; a < 5; a++)
            for (int i = 0; i < 100000; i++) {
                double u1 = rng_uniform(&r), u2 = rng_uniform(&r), w1, w2;
                vec3 m = mf_sample(dists[d], alphas[a], u1, u2);
                cr_assert(fabs(vlen(m) - 1) < 1e-12 && m.z > 0);
                if (!mf_invert(dists[d], alphas[a], m, &w1, &w2)) {
                    fails++;
                    continue;
                }
                cr_assert(w1 >= 0 && w1 < 1 && w2 >= 0 && w2 < 1);
                vec3 m2 = mf_sample(dists[d], alphas[a], w1, w2);
                cr_assert(vlen(vsub(m, m2)) < 1e-9, "dist %d alpha %g u=(%.17g,%.17g) -> (%.17g,%.17g)", d, alphas[a],
                          u1, u2, w1, w2);
                cr_assert(fabs(u1 - w1) < 1e-9 || u1 > 1 - 1e-6, "u1 %.17g -> %.17g", u1, w1);
            }
    cr_assert(fails <= 10, "%ld inversions failed", fails);
}

/* For every sampled direction: out.pdf == pdf(wi, wo) and out.weight == eval |cos wo| / pdf
 * (relative 1e-5); lobe indices valid; eval == 0 exactly when pdf says the lobe is impossible. */
static void check_sample_consistency(enum bsdf_type type, bool refraction)
{
    static struct rough_case cases[MAX_ROUGH_CASES];
    int n = rough_cases(type, cases);
    rng r;
    rng_seed(&r, 21, (uint64_t)type);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    char name[256];
    for (int k = 0; k < n; k++) {
        struct rough_case *rc = &cases[k];
        rc->b.enable_refraction = refraction;
        long ok = 0;
        for (int i = 0; i < 20000; i++) {
            struct bsdf_sample out;
            sampler_begin(&s.base, STREAM_CAMERA, 1);
            bool res = rc->ops->sample(&rc->c, rc->wi, &s.base, rc->mode, &out);
            cr_assert_eq(s.base.offset, rc->ops->dims, "sample consumed %d numbers", s.base.offset);
            if (!res) continue;
            ok++;
            rough_case_name(rc, name, sizeof name);
            cr_assert(!out.delta && out.pdf > 0 && fabs(vlen(out.wo) - 1) < 1e-9, "%s", name);
            double p = rc->ops->pdf(&rc->c, rc->wi, out.wo);
            cr_assert(rel_err(p, out.pdf) < 1e-5, "%s: sampled pdf %.10g pdf() %.10g wo=(%g,%g,%g)", name, out.pdf, p,
                      out.wo.x, out.wo.y, out.wo.z);
            rgb f = rc->ops->eval(&rc->c, rc->wi, out.wo, rc->mode);
            rgb w = vscale(f, fabs(out.wo.z) / p);
            for (int ch = 0; ch < 3; ch++)
                cr_assert(fabs(vget(w, ch) - vget(out.weight, ch)) <= 1e-5 * fmax(fabs(vget(w, ch)), 1e-30),
                          "%s: weight %.10g vs eval cos/pdf %.10g (lobe %d)", name, vget(out.weight, ch), vget(w, ch),
                          out.lobe);
            if (type == BSDF_ROUGH_DIELECTRIC) {
                bool refl = out.wo.z * rc->wi.z > 0;
                cr_assert_eq(out.lobe, refl ? 0 : 1);
                cr_assert(refraction || refl);
            } else {
                cr_assert(out.wo.z > 0);
                cr_assert(out.lobe == 0 || (type == BSDF_ROUGH_PLASTIC && out.lobe == 1));
            }
        }
        cr_assert(ok > 1000, "%s: only %ld of 20000 samples succeeded", rough_case_name(rc, name, sizeof name), ok);
    }
}

Test(bsdf_rough, conductor_sample_matches_pdf_and_eval) { check_sample_consistency(BSDF_ROUGH_CONDUCTOR, true); }

/* Random pairs (not only sampled ones): eval(wi, wo) == eval(wo, wi) for the reflection lobes. */
static void check_reflection_reciprocity(enum bsdf_type type)
{
    struct bsdf b = rough_material(type, MF_GGX, 0.3);
    rng r;
    rng_seed(&r, 31, 0);
    for (int i = 0; i < 100000; i++) {
        b.dist = (i & 1) ? MF_GGX : MF_BECKMANN;
        b.roughness = 0.05 + rng_uniform(&r);
        struct bsdf_ctx c = bsdf_ctx_at(&b, NULL);
        double side = (type == BSDF_ROUGH_DIELECTRIC && (i & 2)) ? -1 : 1;
        vec3 wi = dir_cos(side * rng_uniform(&r), 2 * M_PI * rng_uniform(&r));
        vec3 wo = dir_cos(side * rng_uniform(&r), 2 * M_PI * rng_uniform(&r));
        enum transport mode = (i & 4) ? TRANSPORT_RADIANCE : TRANSPORT_IMPORTANCE;
        rgb a = bsdf_eval(&c, wi, wo, mode), bb = bsdf_eval(&c, wo, wi, mode);
        for (int ch = 0; ch < 3; ch++)
            cr_assert(fabs(vget(a, ch) - vget(bb, ch)) <= 1e-9 * fmax(vget(a, ch), 1e-300),
                      "f(wi,wo)=%.12g f(wo,wi)=%.12g", vget(a, ch), vget(bb, ch));
    }
}

Test(bsdf_rough, conductor_reciprocity) { check_reflection_reciprocity(BSDF_ROUGH_CONDUCTOR); }

/* Inversion round trip, >= 100k samples per configuration: sample wo, invert(wi, wo) into a
 * writer, replay the written numbers through sample() -> the same wo within 1e-6. Success
 * (inverted and reproduced) must be >= 99.9 %. The writer's annotations must match the
 * forward order: discrete numbers first, then continuous. */
static void check_inversion(enum bsdf_type type, bool refraction, long per_case)
{
    static struct rough_case cases[MAX_ROUGH_CASES];
    static struct sampler_writer w;
    int n = rough_cases(type, cases);
    rng r;
    rng_seed(&r, 41, (uint64_t)type);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    sampler_writer_init(&w, 43, (uint64_t)type);
    char name[256];
    double min_rate = 1;
    long total = 0;
    for (int k = 0; k < n; k++) {
        struct rough_case *rc = &cases[k];
        rc->b.enable_refraction = refraction;
        long sampled = 0, good = 0;
        double worst = 0;
        for (long i = 0; i < per_case; i++) {
            struct bsdf_sample out, again;
            sampler_begin(&s.base, STREAM_CAMERA, 1);
            if (!rc->ops->sample(&rc->c, rc->wi, &s.base, rc->mode, &out)) continue;
            sampled++;
            sampler_writer_clear(&w);
            sampler_begin(&w.base, STREAM_CAMERA, 1);
            if (!rc->ops->invert(&rc->c, rc->wi, out.wo, &w.base)) continue;
            cr_assert_eq(w.base.offset, rc->ops->dims);
            for (int j = 0; j < rc->ops->dims; j++) {
                double u = w.u[STREAM_CAMERA][SAMPLER_BLOCK + j];
                cr_assert(u >= 0 && u < 1, "inverted number %d = %g", j, u);
                int discrete = type == BSDF_ROUGH_CONDUCTOR ? 0 : 1;
                cr_assert_eq(w.kind[STREAM_CAMERA][SAMPLER_BLOCK + j], j < discrete ? DIM_DISCRETE : DIM_CONTINUOUS);
            }
            struct sampler_replay rp;
            sampler_replay_init(&rp, (const double(*)[STREAM_DIMS])w.u);
            sampler_begin(&rp.base, STREAM_CAMERA, 1);
            if (!rc->ops->sample(&rc->c, rc->wi, &rp.base, rc->mode, &again)) continue;
            double e = vlen(vsub(again.wo, out.wo));
            if (e > worst) worst = e;
            if (e < 1e-6) good++;
        }
        cr_assert(sampled > per_case / 20, "%s", rough_case_name(rc, name, sizeof name));
        cr_assert(good >= 0.999 * sampled, "%s: %ld of %ld round trips (worst %g)",
                  rough_case_name(rc, name, sizeof name), good, sampled, worst);
        min_rate = fmin(min_rate, (double)good / sampled);
        total += sampled;
    }
    cr_log_info("type %d refraction %d: %ld round trips over %d configurations, lowest success rate %.6f", (int)type,
                (int)refraction, total, n, min_rate);
}

Test(bsdf_rough, conductor_inversion_roundtrip) { check_inversion(BSDF_ROUGH_CONDUCTOR, true, 100000); }

Test(bsdf_rough, dielectric_sample_matches_pdf_and_eval)
{
    check_sample_consistency(BSDF_ROUGH_DIELECTRIC, true);
    check_sample_consistency(BSDF_ROUGH_DIELECTRIC, false);
}

Test(bsdf_rough, dielectric_reflection_reciprocity) { check_reflection_reciprocity(BSDF_ROUGH_DIELECTRIC); }

/* Refraction: generalized reciprocity. With K(wi, wo) symmetric, f_imp(wi, wo) = eta_o^2 K and
 * f_rad(wi, wo) = eta_i^2 K, so f_rad(wi, wo) = f_imp(wo, wi) and
 * f_imp(wi, wo) / eta_o^2 = f_imp(wo, wi) / eta_i^2 (Veach Eq. 5.14). Plain reciprocity does not
 * hold: f_imp(wi, wo) / f_imp(wo, wi) = (eta_o / eta_i)^2 -- checked too. */
Test(bsdf_rough, dielectric_refraction_generalized_reciprocity)
{
    struct bsdf b = rough_material(BSDF_ROUGH_DIELECTRIC, MF_GGX, 0.3);
    struct bsdf_ctx c = bsdf_ctx_at(&b, NULL);
    rng r;
    rng_seed(&r, 33, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    long tested = 0;
    for (int i = 0; i < 100000; i++) {
        b.dist = (i & 1) ? MF_GGX : MF_BECKMANN;
        b.roughness = 0.05 + rng_uniform(&r);
        double side = (i & 2) ? -1 : 1;
        vec3 wi = dir_cos(side * rng_uniform(&r), 2 * M_PI * rng_uniform(&r));
        struct bsdf_sample out;
        sampler_begin(&s.base, STREAM_CAMERA, 0);
        if (!bsdf_sample(&c, wi, &s.base, TRANSPORT_IMPORTANCE, &out) || out.lobe != 1) continue;
        vec3 wo = out.wo;
        double eta_i = wi.z > 0 ? 1 : b.ior, eta_o = wo.z > 0 ? 1 : b.ior;
        double f_imp = bsdf_eval(&c, wi, wo, TRANSPORT_IMPORTANCE).x,
               f_rad = bsdf_eval(&c, wi, wo, TRANSPORT_RADIANCE).x;
        double g_imp = bsdf_eval(&c, wo, wi, TRANSPORT_IMPORTANCE).x,
               g_rad = bsdf_eval(&c, wo, wi, TRANSPORT_RADIANCE).x;
        if (!(f_imp > 0)) continue;
        tested++;
        cr_assert(rel_err(f_rad, g_imp) < 1e-9, "f_rad(wi,wo) %.12g f_imp(wo,wi) %.12g", f_rad, g_imp);
        cr_assert(rel_err(g_rad, f_imp) < 1e-9);
        cr_assert(rel_err(f_imp / sqr(eta_o), g_imp / sqr(eta_i)) < 1e-9);
        cr_assert(rel_err(f_imp / g_imp, sqr(eta_o / eta_i)) < 1e-9);
        cr_assert(rel_err(f_rad / f_imp, sqr(eta_i / eta_o)) < 1e-12);
    }
    cr_assert(tested > 10000, "%ld", tested);
}

Test(bsdf_rough, dielectric_inversion_roundtrip)
{
    check_inversion(BSDF_ROUGH_DIELECTRIC, true, 100000);
    check_inversion(BSDF_ROUGH_DIELECTRIC, false, 100000);
}

/* With enable_refraction = false nothing is transmitted. */
Test(bsdf_rough, dielectric_reflection_only)
{
    struct bsdf b = rough_material(BSDF_ROUGH_DIELECTRIC, MF_BECKMANN, 0.5);
    b.enable_refraction = false;
    struct bsdf_ctx c = bsdf_ctx_at(&b, NULL);
    vec3 wi = dir_cos(0.7, 0.2), wo = dir_cos(-0.6, 3.0);
    cr_assert_eq(bsdf_pdf(&c, wi, wo), 0.0);
    cr_assert_eq(bsdf_eval(&c, wi, wo, TRANSPORT_RADIANCE).x, 0.0);
    cr_assert(bsdf_ops_for(BSDF_ROUGH_DIELECTRIC)->transmissive);
}

Test(bsdf_rough, plastic_sample_matches_pdf_and_eval) { check_sample_consistency(BSDF_ROUGH_PLASTIC, true); }

Test(bsdf_rough, plastic_inversion_roundtrip) { check_inversion(BSDF_ROUGH_PLASTIC, true, 100000); }

/* Rough plastic is reciprocal in its coat lobe; the base lobe is symmetric too (product form). */
Test(bsdf_rough, plastic_reciprocity) { check_reflection_reciprocity(BSDF_ROUGH_PLASTIC); }

Test(bsdf_rough, ops_flags)
{
    cr_assert_eq(bsdf_rough_conductor_ops.dims, 2);
    cr_assert_eq(bsdf_rough_dielectric_ops.dims, 3);
    cr_assert_eq(bsdf_rough_plastic_ops.dims, 3);
    cr_assert(!bsdf_rough_conductor_ops.transmissive && !bsdf_rough_plastic_ops.transmissive);
    cr_assert(bsdf_rough_dielectric_ops.transmissive);
    cr_assert(!bsdf_rough_conductor_ops.delta_only && !bsdf_rough_dielectric_ops.delta_only &&
              !bsdf_rough_plastic_ops.delta_only);
}
