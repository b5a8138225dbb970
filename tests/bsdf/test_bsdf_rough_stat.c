/* Statistical tests of the microfacet module and the rough BSDF families.
 *
 * Chi-square (tests/chi2.h): 1M samples per case, equal-area (cos theta, phi) grid of 32 x 64
 * cells for alpha >= 0.3 and 512 x 64 for alpha = 0.1 (the lobe of a sharp microfacet
 * distribution is a thin cap in cos theta: the finer theta grid keeps Simpson's 9 x 9 points per
 * cell accurate there); alpha = 0.01 Sidak-corrected over CHI2_CASES. Failed samples land in the
 * harness's "other" cell, whose expected count is n (1 - integral of pdf). */
#include <criterion/criterion.h>

#include "bsdf/fresnel.h"
#include "support/chi2.h"
#include "support/rough_util.h"
#include <gsl/gsl_cdf.h>
#include <stdlib.h>

#define CHI2_N 1000000L

static void grid_for(double alpha, int *nt, int *np)
{
    *nt = alpha < 0.2 ? 512 : 32;
    *np = 64;
}

/* ---- microfacet normals: sample vs D(m) m.z ---- */

struct mf_ctx {
    enum mf_dist dist;
    double alpha;
};
static bool mf_chi_sample(void *p, rng *r, vec3 *d)
{
    struct mf_ctx *c = p;
    double u1 = rng_uniform(r), u2 = rng_uniform(r);
    *d = mf_sample(c->dist, c->alpha, u1, u2);
    return true;
}
static double mf_chi_pdf(void *p, vec3 d)
{
    struct mf_ctx *c = p;
    return mf_pdf(c->dist, c->alpha, d);
}

/* 6 cases (2 distributions x alpha 0.1, 0.3, 0.7), 1M samples each, alpha 0.01 Sidak. */
Test(stat_bsdf_rough, microfacet_normal_sampling_chi2)
{
    char buf[256];
    for (int d = 0; d < 2; d++)
        for (int a = 0; a < N_ROUGH_ALPHAS; a++) {
            struct mf_ctx c = {d ? MF_GGX : MF_BECKMANN, rough_alphas[a]};
            int nt, np;
            grid_for(c.alpha, &nt, &np);
            struct chi2_result r = chi2_test_dir(mf_chi_sample, mf_chi_pdf, &c, nt, np, CHI2_N, 100 + d * 10 + a);
            cr_log_info("normals dist=%d alpha=%g: %s", d, c.alpha, chi2_describe(&r, buf, sizeof buf));
            cr_expect(r.pass, "dist=%d alpha=%g: %s", d, c.alpha, chi2_describe(&r, buf, sizeof buf));
            cr_expect(fabs(r.mass - 1) < 2e-3, "mass %g", r.mass);
        }
}

/* ---- BSDF sampling vs pdf() ---- */

/* Why not chi2_test_dir: its equal-area map puts the horizon on a cell edge where Simpson's rule
 * evaluates the pdf exactly at wo.z = 0. Rough BSDF pdfs do not vanish at the horizon (the
 * conductor's pdf at grazing wo is D(h) h.z / (4 wi.h) > 0), so the closed rule mis-weights every
 * cell along it: an O(h) error in the expected counts (mass 0.6620 vs 0.6635 exactly for GGX
 * alpha 0.7, enough to fail at 1M samples). Here chi2_test_2d bins (u, v) under a map whose
 * Jacobian vanishes at the horizon, so the binned density is continuous there:
 *   s = 2u - 1,  theta = (pi/2)(1 - s^2) from the normal (s > 0) or from -normal (s < 0),
 *   phi = phi_c + pi g(2v - 1),  g(t) = sinh(k t) / sinh(k)   (g(t) = t for k = 0)
 * with phi_c the azimuth opposite wi (the centre of reflection and refraction lobes). For grazing
 * wi the reflection lobe is compressed across the plane of incidence by the Jacobian
 * 1 / (4 wi.h) (width ~ 2 alpha cos theta_i in phi); k = 5 magnifies phi_c 34-fold.
 * Density in (u, v): pdf(w) |dz/du| |dphi/dv| = pdf 2 pi |s| cos(pi s^2 / 2) * pi k cosh(k t) / sinh(k) * 2. */
struct bsdf_chi_ctx {
    struct rough_case *k;
    double phi_c, kk;
};
static double g_map(double t, double k) { return k == 0 ? t : sinh(k * t) / sinh(k); }
static double g_inv(double y, double k) { return k == 0 ? y : asinh(y * sinh(k)) / k; }
static double g_deriv(double t, double k) { return k == 0 ? 1 : k * cosh(k * t) / sinh(k); }

static vec3 chi_dir(const struct bsdf_chi_ctx *c, double u, double v)
{
    double s = 2 * u - 1, z = (s < 0 ? -1 : 1) * sin(0.5 * M_PI * s * s);
    double r = sqrt(fmax(0.0, 1 - z * z)), phi = c->phi_c + M_PI * g_map(2 * v - 1, c->kk);
    return v3(r * cos(phi), r * sin(phi), z);
}
static bool bsdf_chi_sample(void *p, rng *r, double *u, double *v)
{
    struct bsdf_chi_ctx *c = p;
    struct sampler_rng s;
    sampler_rng_init(&s, r);
    sampler_begin(&s.base, STREAM_CAMERA, 1);
    struct bsdf_sample out;
    if (!c->k->ops->sample(&c->k->c, c->k->wi, &s.base, c->k->mode, &out)) return false;
    vec3 d = out.wo;
    double ss = sqrt(fmax(0.0, 1 - acos(clampd(fabs(d.z), 0, 1)) / (0.5 * M_PI)));
    *u = 0.5 * (1 + (d.z < 0 ? -ss : ss));
    double rel = atan2(d.y, d.x) - c->phi_c;
    rel = remainder(rel, 2 * M_PI); /* in [-pi, pi] */
    *v = 0.5 * (1 + g_inv(rel / M_PI, c->kk));
    return true;
}
static double bsdf_chi_pdf(void *p, double u, double v)
{
    struct bsdf_chi_ctx *c = p;
    double s = 2 * u - 1, jac = 2 * M_PI * fabs(s) * cos(0.5 * M_PI * s * s) * 2 * M_PI * g_deriv(2 * v - 1, c->kk);
    if (jac == 0) return 0;
    return c->k->ops->pdf(&c->k->c, c->k->wi, chi_dir(c, u, v)) * jac;
}

static int run_family_chi2(enum bsdf_type type, bool refraction)
{
    struct rough_case *cases = calloc(MAX_ROUGH_CASES, sizeof *cases);
    int n = rough_cases(type, cases), failed = 0;
    char buf[256], name[256];
    for (int i = 0; i < n; i++) {
        struct rough_case *k = &cases[i];
        k->b.enable_refraction = refraction;
        struct bsdf_chi_ctx c = {k, atan2(-k->wi.y, -k->wi.x), fabs(k->wi.z) < 0.1 ? 5 : 0};
        int nt = k->b.roughness < 0.2 ? 256 : 64, np = 64;
        struct chi2_result r = chi2_test_2d(bsdf_chi_sample, bsdf_chi_pdf, &c, nt, np, CHI2_N, 1000 + i);
        rough_case_name(k, name, sizeof name);
        cr_log_info("%s: %s", name, chi2_describe(&r, buf, sizeof buf));
        cr_expect(r.pass, "%s: %s", name, chi2_describe(&r, buf, sizeof buf));
        failed += !r.pass;
    }
    free(cases);
    return failed;
}

/* 24 cases: 2 distributions x alpha {0.1, 0.3, 0.7} x cos theta_i {0.95, 0.6, 0.25, 0.05};
 * 1M samples each; alpha 0.01 Sidak. */
Test(stat_bsdf_rough, conductor_chi2) { run_family_chi2(BSDF_ROUGH_CONDUCTOR, true); }

/* 48 cases: 2 distributions x alpha {0.1, 0.3, 0.7} x cos theta_i {0.95, 0.6, 0.25, 0.05} x
 * {outside, inside}; 1M samples each; alpha 0.01 Sidak. Inside at cos 0.6 .. 0.05 is beyond the
 * critical angle for most microfacets (TIR: reflection only). */
Test(stat_bsdf_rough, dielectric_chi2) { run_family_chi2(BSDF_ROUGH_DIELECTRIC, true); }

/* The same 48 configurations with enable_refraction = false (reflection only, pdf without F). */
Test(stat_bsdf_rough, dielectric_reflection_only_chi2) { run_family_chi2(BSDF_ROUGH_DIELECTRIC, false); }

/* Failure demonstration kept as a test: a pdf that forgets Tungsten's sampling-roughness widening
 * (D_s with alpha instead of (1.2 - 0.2 sqrt|wi.z|) alpha) must be rejected. Rough dielectric,
 * reflection only, GGX alpha 0.3, cos theta_i 0.6; 1M samples; alpha 0.01 Sidak. */
static double unwidened_pdf(void *p, double u, double v)
{
    struct bsdf_chi_ctx *c = p;
    const struct rough_case *k = c->k;
    double q = bsdf_chi_pdf(p, u, v);
    vec3 wo = chi_dir(c, u, v), m;
    if (q == 0 || !mf_half_reflect(k->wi, wo, &m)) return q;
    return q * mf_D(k->b.dist, k->b.roughness, m) / mf_D(k->b.dist, mf_sample_alpha(k->b.roughness, k->wi.z), m);
}
Test(stat_bsdf_rough, rejects_pdf_without_roughness_widening)
{
    static struct rough_case k;
    k.b = rough_material(BSDF_ROUGH_DIELECTRIC, MF_GGX, 0.3);
    k.b.enable_refraction = false;
    k.wi = dir_cos(0.6, 0.4);
    k.mode = TRANSPORT_RADIANCE;
    rough_case_bind(&k);
    struct bsdf_chi_ctx c = {&k, atan2(-k.wi.y, -k.wi.x), 0};
    char buf[256];
    struct chi2_result good = chi2_test_2d(bsdf_chi_sample, bsdf_chi_pdf, &c, 64, 64, CHI2_N, 900);
    struct chi2_result bad = chi2_test_2d(bsdf_chi_sample, unwidened_pdf, &c, 64, 64, CHI2_N, 900);
    cr_log_info("widened pdf: %s", chi2_describe(&good, buf, sizeof buf));
    cr_log_info("unwidened pdf: %s", chi2_describe(&bad, buf, sizeof buf));
    cr_expect(good.pass, "%s", chi2_describe(&good, buf, sizeof buf));
    cr_expect(!bad.pass, "unwidened pdf accepted: %s", chi2_describe(&bad, buf, sizeof buf));
}

/* 24 cases: 2 distributions x alpha {0.1, 0.3, 0.7} x cos theta_i {0.95, 0.6, 0.25, 0.05};
 * 1M samples each; alpha 0.01 Sidak. */
Test(stat_bsdf_rough, plastic_chi2) { run_family_chi2(BSDF_ROUGH_PLASTIC, true); }

/* ---- white furnace ---- */

/* A perfect white conductor (eta = 0, k = 1 gives F = 1 exactly, albedo 1): the directional
 * albedo int f cos dwo = E[weight] must not exceed 1 (+3 sigma); for alpha = 0.1 at near-normal
 * incidence it must be near 1 (> 0.98: shadowing losses of a smooth surface are small).
 * 1M samples per case, 24 cases. */
Test(stat_bsdf_rough, conductor_white_furnace)
{
    static struct rough_case cases[MAX_ROUGH_CASES];
    int n = rough_cases(BSDF_ROUGH_CONDUCTOR, cases);
    rng r;
    rng_seed(&r, 77, 0);
    struct sampler_rng s;
    sampler_rng_init(&s, &r);
    char name[256];
    for (int i = 0; i < n; i++) {
        struct rough_case *k = &cases[i];
        k->b.eta = v3s(0);
        k->b.k = v3s(1);
        k->b.albedo = v3s(1);
        rough_case_bind(k);
        const long N = 1000000;
        double sum = 0, sum2 = 0;
        for (long j = 0; j < N; j++) {
            struct bsdf_sample out;
            sampler_begin(&s.base, STREAM_CAMERA, 1);
            double w = k->ops->sample(&k->c, k->wi, &s.base, k->mode, &out) ? out.weight.x : 0;
            sum += w;
            sum2 += w * w;
        }
        double mean = sum / N, sd = sqrt(fmax(0, sum2 / N - mean * mean) / N);
        rough_case_name(k, name, sizeof name);
        cr_log_info("furnace %s: %.5f +- %.5f", name, mean, sd);
        cr_expect(mean <= 1 + 3 * sd, "%s: albedo %.5f +- %.5f", name, mean, sd);
        if (k->b.roughness == 0.1 && k->wi.z > 0.9) cr_expect(mean > 0.98, "%s: albedo %.5f", name, mean);
    }
}

/* ---- inverted discrete numbers ---- */

/* Forward sample with uniform numbers, invert wo, look at the inverted discrete number ud'.
 * Thesis Eq. 5.3: given the path, the inverse must return numbers distributed as the forward
 * numbers that produce it. Hence (a) ud' is uniform within its outcome's interval (Eq. 5.6, 5.8),
 * and (b) over successful forward samples, ud' has the same distribution as the forward ud of
 * successful samples (not uniform: reflection fails more often than refraction, the coat more
 * often than the base). For rough plastic (b) holds only if the lobe is picked in proportion to
 * its pdf share (Eq. 5.7). */
struct inv_ctx {
    struct rough_case *cases;
    int n, next;
    struct sampler_writer *w;
};

/* Interval split of the discrete choice for (wi, wo): F(wi.m) or the coat probability. */
static double discrete_split(const struct rough_case *k, vec3 wo)
{
    double ct;
    if (k->b.type == BSDF_ROUGH_DIELECTRIC) {
        bool refl = wo.z * k->wi.z > 0;
        double eta_i = k->wi.z > 0 ? 1 : k->b.ior, eta_o = wo.z > 0 ? 1 : k->b.ior;
        vec3 m;
        if (!(refl ? mf_half_reflect(k->wi, wo, &m) : mf_half_refract(k->wi, wo, eta_i, eta_o, &m))) return NAN;
        return fresnel_dielectric(fabs(vdot(k->wi, m)), k->wi.z > 0 ? k->b.ior : 1 / k->b.ior, &ct);
    }
    double Fi = fresnel_dielectric(k->wi.z, k->b.ior, &ct);
    double T = exp(-2 * k->b.thickness * (k->b.sigma_a.x + k->b.sigma_a.y + k->b.sigma_a.z) / 3);
    vec3 A = k->c.albedo; /* the coat against the substrate's reflected share */
    return Fi / (Fi + T * (1 - Fi) * (A.x + A.y + A.z) / 3);
}

/* One successful forward sample and its inversion: forward ud, inverted ud', split. */
static void inv_draw(struct inv_ctx *c, rng *r, double *ud, double *ud_inv, double *split)
{
    for (;;) {
        struct rough_case *k = &c->cases[c->next++ % c->n];
        struct bsdf_sample out;
        *ud = rng_uniform(r);
        double u1 = rng_uniform(r), u2 = rng_uniform(r);
        double vec[STREAM_COUNT][STREAM_DIMS];
        vec[STREAM_CAMERA][0] = *ud;
        vec[STREAM_CAMERA][1] = u1;
        vec[STREAM_CAMERA][2] = u2;
        struct sampler_replay fw;
        sampler_replay_init(&fw, (const double(*)[STREAM_DIMS])vec);
        sampler_begin(&fw.base, STREAM_CAMERA, 0);
        if (!k->ops->sample(&k->c, k->wi, &fw.base, k->mode, &out)) continue;
        sampler_writer_clear(c->w);
        sampler_begin(&c->w->base, STREAM_CAMERA, 1);
        if (!k->ops->invert(&k->c, k->wi, out.wo, &c->w->base)) continue;
        *ud_inv = c->w->u[STREAM_CAMERA][SAMPLER_BLOCK];
        *split = discrete_split(k, out.wo);
        if (isnan(*split)) continue;
        return;
    }
}

static bool inv_within_sample(void *p, rng *r, double *u, double *v)
{
    double ud, ui, sp;
    inv_draw(p, r, &ud, &ui, &sp);
    *u = ui < sp ? ui / sp : (ui - sp) / (1 - sp);
    *v = 0.5;
    return true;
}
static double uniform_pdf(void *p, double u, double v)
{
    (void)p;
    (void)u;
    (void)v;
    return 1;
}

/* (a) 2 cases {rough dielectric, rough plastic}: n = 100k inversions each, cycling through all
 * configurations of the family (rough_cases); 10 bins; chi2 harness, alpha 0.01 Sidak. */
Test(stat_bsdf_rough, inverted_discrete_uniform_within_interval)
{
    static struct sampler_writer w;
    struct rough_case *cases = calloc(MAX_ROUGH_CASES, sizeof *cases);
    const enum bsdf_type types[] = {BSDF_ROUGH_DIELECTRIC, BSDF_ROUGH_PLASTIC};
    char buf[256];
    for (int t = 0; t < 2; t++) {
        sampler_writer_init(&w, 500 + t, 0);
        struct inv_ctx c = {cases, rough_cases(types[t], cases), 0, &w};
        struct chi2_result r = chi2_test_2d(inv_within_sample, uniform_pdf, &c, 10, 1, 100000, 600 + t);
        cr_log_info("type %d within interval: %s", (int)types[t], chi2_describe(&r, buf, sizeof buf));
        cr_expect(r.pass, "type %d: %s", (int)types[t], chi2_describe(&r, buf, sizeof buf));
    }
    free(cases);
}

/* (b) Two-sample chi-square homogeneity test (equal n: stat = sum (A - B)^2 / (A + B), dof =
 * bins - 1) between forward ud of successful samples (run A) and inverted ud' of an independent
 * run B. 2 cases, n = 1M each run, 20 bins, alpha 0.01 Sidak. */
static double homogeneity_p(const long *a, const long *b, int bins, double *stat)
{
    double x = 0;
    int used = 0;
    for (int i = 0; i < bins; i++)
        if (a[i] + b[i] > 0) {
            x += sqr((double)(a[i] - b[i])) / (double)(a[i] + b[i]);
            used++;
        }
    *stat = x;
    return gsl_cdf_chisq_Q(x, used - 1);
}

Test(stat_bsdf_rough, inverted_discrete_matches_forward)
{
    static struct sampler_writer w;
    struct rough_case *cases = calloc(MAX_ROUGH_CASES, sizeof *cases);
    const enum bsdf_type types[] = {BSDF_ROUGH_DIELECTRIC, BSDF_ROUGH_PLASTIC};
    enum { BINS = 20 };
    const long N = 1000000;
    for (int t = 0; t < 2; t++) {
        long A[BINS] = {0}, B[BINS] = {0};
        rng r;
        rng_seed(&r, 700 + t, 0);
        sampler_writer_init(&w, 800 + t, 0);
        struct inv_ctx c = {cases, rough_cases(types[t], cases), 0, &w};
        for (long i = 0; i < 2 * N; i++) {
            double ud, ui, sp;
            inv_draw(&c, &r, &ud, &ui, &sp);
            if (i % 2 == 0)
                A[(int)(ud * BINS)]++;
            else
                B[(int)(ui * BINS)]++;
        }
        double stat, p = homogeneity_p(A, B, BINS, &stat);
        cr_log_info("type %d forward ud vs inverted ud': chi2=%.1f dof=%d p=%.3g (alpha=%.2g)", (int)types[t], stat,
                    BINS - 1, p, chi2_alpha_sidak());
        cr_expect(p > chi2_alpha_sidak(), "type %d: chi2=%.1f p=%g", (int)types[t], stat, p);
    }
    free(cases);
}
