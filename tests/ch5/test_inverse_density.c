/* experiments/ch5/inv_run, inv_gof: bin/inverse_density's core (thesis Eq. 5.3) at a small sample
 * size on two functions of scenes/cornell-box, the Lambertian BSDF `white` (tested against the
 * uniform density: it never fails forward) and whole paths of technique (s, t) = (1, 2) (against
 * forward numbers: many forward paths are blocked). Significance: alpha = 0.01 family-wise over
 * the 4 p-values (2 functions x {chi-square, KS}), Sidak; n = 20 000 inverted BSDF samples and
 * 5 000 inverted paths, fixed seeds. The same run with every first inverted number scaled by 0.9
 * (a broken inverse) must be rejected for both functions. */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "ch5/inv_run.h"
#include "common/verdict.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

enum { NF = 64 };

static const struct inv_func *named(const struct inv_func *f, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(f[i].name, name)) return &f[i];
    cr_assert_fail("no function %s", name);
    return NULL;
}

/* Runs both functions with the first inverted number scaled by `scale`; the smallest adjusted
 * p-value of each into p[2]. */
static void run_two(double scale, double p[2])
{
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    static struct inv_func f[NF];
    static struct scene lens;
    static const int tech[1][2] = {{1, 2}};
    int n = 0;
    unsigned long seen = 0;
    cr_assert(inv_funcs_bsdf(sc, "cornell-box", &seen, f, &n, NF));
    cr_assert(inv_funcs_scene(sc, &lens, "cornell-box", tech, 1, f, &n, NF));
    const struct inv_func *g[2] = {named(f, n, "bsdf:cornell-box/white"), named(f, n, "path:cornell-box/s=1;t=2")};
    const long N[2] = {20000, 5000};
    struct inv_scratch *x = malloc(sizeof *x);
    for (int i = 0; i < 2; i++) {
        struct inv_result r;
        inv_run(g[i], x, N[i], 7, scale, &r);
        cr_log_info("%s scale %g: %ld inverted, %ld failed, %s, chi2 %.1f (%d) at %s p %.3g, KS D %.4f at %s p %.3g",
                    g[i]->name, scale, r.samples, r.failures, r.uniform ? "uniform" : "forward", r.g.chi2, r.g.chi_dof,
                    r.g.chi_worst, r.g.chi_p_adj, r.g.ks_d, r.g.ks_worst, r.g.ks_p_adj);
        cr_expect(r.samples + r.failures == N[i], "%s: %ld samples of %ld", g[i]->name, r.samples + r.failures, N[i]);
        cr_expect(r.failures <= N[i] / 1000, "%s: %ld inversions failed", g[i]->name, r.failures);
        cr_expect(r.g.chi_tests > 0 && r.g.ks_tests > 0, "%s: nothing tested", g[i]->name);
        cr_expect(r.uniform == (i == 0), "%s: reference %s", g[i]->name, r.uniform ? "uniform" : "forward");
        p[i] = fmin(r.g.chi_p_adj, r.g.ks_p_adj);
    }
    free(x);
    scene_free(sc);
}

Test(stat_inverse_density, intact_inverses_pass)
{
    double p[2], each = inv_sidak_alpha(0.01, 4);
    run_two(1, p);
    cr_expect(p[0] >= each, "lambert: p %.3g below %.3g", p[0], each);
    cr_expect(p[1] >= each, "path (1,2): p %.3g below %.3g", p[1], each);
}

Test(stat_inverse_density, broken_inverse_is_rejected)
{
    double p[2], each = inv_sidak_alpha(0.01, 4);
    run_two(0.9, p);
    cr_expect(p[0] < each, "lambert with a broken inverse: p %.3g not below %.3g", p[0], each);
    cr_expect(p[1] < each, "path (1,2) with a broken inverse: p %.3g not below %.3g", p[1], each);
}

/* Kolmogorov's limiting law at known points (P(K > 1) = 0.26999967, P(K > 1.36) = 0.0494) and the
 * Sidak level of 4 tests at 0.01. */
Test(inverse_density, ks_law_and_sidak)
{
    cr_expect(fabs(inv_ks_q(1.0) - 0.26999967) < 1e-6, "Q(1) = %.8f", inv_ks_q(1.0));
    cr_expect(fabs(inv_ks_q(1.36) - 0.0494) < 2e-4, "Q(1.36) = %.5f", inv_ks_q(1.36));
    cr_expect(fabs(inv_sidak_alpha(0.01, 4) - (1 - pow(0.99, 0.25))) < 1e-12);
    cr_expect(fabs(inv_sidak_p(inv_sidak_alpha(0.01, 4), 4) - 0.01) < 1e-12);
}

/* The ledger's verdict from p-values (common/verdict.h): holds at exactly the Sidak level of m tests,
 * contradicted just below it, and its z margin has the sign of the verdict. */
Test(inverse_density, verdict_no_rejection_at_the_sidak_level)
{
    double each = inv_sidak_alpha(0.01, 88);
    struct verdict at = verdict_no_rejection(each, 0.01, 88), below = verdict_no_rejection(each * 0.999, 0.01, 88);
    struct verdict high = verdict_no_rejection(0.5, 0.01, 88);
    cr_expect_str_eq(at.word, "holds");
    cr_expect_str_eq(below.word, "contradicted");
    cr_expect(below.zmin < 0 && high.zmin > 0 && fabs(at.zmin) < 1e-9, "z %g %g %g", below.zmin, at.zmin, high.zmin);
}
