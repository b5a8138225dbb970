/* Chi-square goodness-of-fit of a sampler against its density (Mitsuba's test_chisquare habit).
 *
 * The domain is the unit square, split into nx x ny cells; expected counts are the density
 * integrated over each cell (composite Simpson, 9 x 9 points per cell) times the sample count.
 * Samples that are not in the continuous part (delta lobes, absorbed, failed) fall into one extra
 * "other" cell whose expected count is n * (1 - integral of the density). Cells with expected
 * count < 5 are pooled; a sample in a cell of zero density fails the test outright.
 * Directions use the equal-area map (u, v) = ((1 + cos theta) / 2, phi / 2 pi), in which the
 * solid-angle density becomes 4 pi pdf. */
#ifndef CHI2_H
#define CHI2_H

#include "base/rng.h"
#include "base/vecmath.h"
#include <stdbool.h>

/* Total statistical cases across the test suite, for the Sidak correction: every chi2 case uses
 * alpha_i = 1 - (1 - 0.01)^(1 / CHI2_CASES). Overestimating makes each case slightly stricter.
 * Measured: a full run of the suite with PSS_CHI2_LOG=FILE (chi2.c) logs 279 cases, 5 of them
 * deliberately broken samplers or densities that must fail; 300 leaves room for a few more. */
#define CHI2_CASES 300
#define CHI2_ALPHA 0.01

/* Draws one sample; returns false for "other" outcomes (delta lobe, absorbed). */
typedef bool (*chi2_sample2d)(void *ctx, rng *r, double *u, double *v);
typedef double (*chi2_pdf2d)(void *ctx, double u, double v);
typedef bool (*chi2_sample_dir)(void *ctx, rng *r, vec3 *d);
typedef double (*chi2_pdf_dir)(void *ctx, vec3 d);

struct chi2_result {
    double stat, pvalue;
    int dof;
    long zero_pdf_hits; /* samples in cells whose density integrates to 0 */
    double mass;        /* integral of the density over the domain */
    long other;         /* samples in the "other" cell */
    bool pass;          /* pvalue > Sidak-corrected alpha and no zero-pdf hits */
};

struct chi2_result chi2_test_2d(chi2_sample2d sample, chi2_pdf2d pdf, void *ctx, int nx, int ny, long n, uint64_t seed);
struct chi2_result chi2_test_dir(chi2_sample_dir sample, chi2_pdf_dir pdf, void *ctx, int ntheta, int nphi, long n,
                                 uint64_t seed);
double chi2_alpha_sidak(void);
/* One line describing the result, for assertion messages. */
const char *chi2_describe(const struct chi2_result *r, char *buf, int len);

#endif
