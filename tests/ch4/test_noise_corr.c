/* experiments/ch4/noise_corr: autocorrelation profiles and correlation lengths (thesis Figures
 * 4.1-4.2), on synthetic noise whose correlation lengths are known: white noise plus white noise
 * blurred by an anisotropic Gaussian (standard deviations sx, sy) has the autocorrelation
 * exp(-dx^2 / (4 sx^2)) along x, so corr_length_lag1 must return sqrt(1 + 4 sx^2). */
#include <criterion/criterion.h>
#include <math.h>
#include <stdlib.h>

#include "base/rng.h"
#include "stats/noise_corr.h"

static double gauss(rng *r)
{
    double u = 1 - rng_uniform(r), v = rng_uniform(r);
    return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

/* Periodic separable Gaussian blur of standard deviations sx, sy (kernel cut at 5 s). */
static void blur(double *f, int w, int h, double sx, double sy)
{
    double *t = malloc(sizeof(double) * w * h);
    for (int pass = 0; pass < 2; pass++) {
        double s = pass ? sy : sx;
        int R = (int)ceil(5 * s);
        double *k = malloc(sizeof(double) * (2 * R + 1)), ks = 0;
        for (int i = -R; i <= R; i++)
            ks += k[i + R] = exp(-0.5 * i * i / (s * s));
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                double a = 0;
                for (int i = -R; i <= R; i++)
                    a += k[i + R] * (pass ? f[(size_t)((y + i + h) % h) * w + x] : f[(size_t)y * w + (x + i + w) % w]);
                t[(size_t)y * w + x] = a / ks;
            }
        for (int i = 0; i < w * h; i++)
            f[i] = t[i];
        free(k);
    }
    free(t);
}

/* white part of variance `white` (relative to the blurred part's) on top of blurred noise */
static double *synthetic(int w, int h, double sx, double sy, double white, uint64_t seed)
{
    rng r;
    rng_seed(&r, seed, 7);
    double *f = malloc(sizeof(double) * w * h), *g = malloc(sizeof(double) * w * h);
    for (int i = 0; i < w * h; i++)
        f[i] = gauss(&r);
    blur(f, w, h, sx, sy);
    double v = 0;
    for (int i = 0; i < w * h; i++)
        v += f[i] * f[i];
    v /= w * h;
    for (int i = 0; i < w * h; i++)
        g[i] = f[i] + sqrt(white * v) * gauss(&r) + 3.0; /* and an offset */
    free(f);
    return g;
}

Test(noise_corr, lengths_of_blurred_noise_under_white_noise)
{
    const int w = 512, h = 384, L = 30;
    const double sx = 3.0, sy = 1.5;
    double rx[31], ry[31];
    double *f = synthetic(w, h, sx, sy, 3.0, 1);
    cr_assert(corr_profiles(f, w, h, L, rx, ry));
    cr_assert_float_eq(rx[0], 1.0, 1e-12);
    cr_assert_float_eq(ry[0], 1.0, 1e-12);
    /* white part 3x the blurred part: rho(1) = exp(-1 / (4 s^2)) / 4 */
    cr_assert(fabs(rx[1] - 0.25 * exp(-1 / (4 * sx * sx))) < 0.02, "rho_x(1) = %g", rx[1]);
    cr_assert(fabs(ry[1] - 0.25 * exp(-1 / (4 * sy * sy))) < 0.02, "rho_y(1) = %g", ry[1]);
    double lx = corr_length_lag1(rx, L + 1), ly = corr_length_lag1(ry, L + 1);
    double ex = sqrt(1 + 4 * sx * sx), ey = sqrt(1 + 4 * sy * sy);
    /* the estimate's scatter over seeds is about 2 % here; 8 % fails a length off by a tenth */
    cr_assert(fabs(lx / ex - 1) < 0.08, "l_x = %g, expected %g", lx, ex);
    cr_assert(fabs(ly / ey - 1) < 0.08, "l_y = %g, expected %g", ly, ey);
    cr_assert(fabs(lx / ly / (ex / ey) - 1) < 0.1, "ratio %g, expected %g", lx / ly, ex / ey);
    /* the plain 1/e crossing of rho is pulled below one pixel by the white part */
    cr_assert(corr_length(rx, L + 1, exp(-1)) < 1);
    free(f);
}

Test(noise_corr, isotropic_noise_gives_ratio_one_and_white_noise_no_length)
{
    const int w = 400, h = 300, L = 20;
    double rx[21], ry[21];
    double *f = synthetic(w, h, 2.0, 2.0, 1.0, 2);
    cr_assert(corr_profiles(f, w, h, L, rx, ry));
    double r = corr_length_lag1(rx, L + 1) / corr_length_lag1(ry, L + 1);
    cr_assert(fabs(r - 1) < 0.1, "ratio %g", r);
    free(f);
    /* pure white noise: rho(d >= 1) near 0 */
    rng g;
    rng_seed(&g, 3, 1);
    double *n = malloc(sizeof(double) * w * h);
    for (int i = 0; i < w * h; i++)
        n[i] = gauss(&g);
    cr_assert(corr_profiles(n, w, h, L, rx, ry));
    for (int d = 1; d <= L; d++)
        cr_assert(fabs(rx[d]) < 0.02 && fabs(ry[d]) < 0.02);
    /* a constant field has no profile */
    for (int i = 0; i < w * h; i++)
        n[i] = 1.5;
    cr_assert(!corr_profiles(n, w, h, L, rx, ry));
    free(n);
}

Test(noise_corr, length_interpolates_between_lags)
{
    double rho[6] = {1, 0.8, 0.6, 0.2, 0.1, 0.05};
    /* 1/e = 0.3679 between lag 2 (0.6) and 3 (0.2) */
    cr_assert_float_eq(corr_length(rho, 6, exp(-1)), 2 + (0.6 - exp(-1)) / 0.4, 1e-12);
    /* rho(1) / e = 0.2943 between lag 2 and 3 */
    cr_assert_float_eq(corr_length_lag1(rho, 6), 2 + (0.6 - 0.8 * exp(-1)) / 0.4, 1e-12);
    double flat[4] = {1, 0.9, 0.9, 0.9};
    cr_assert_float_eq(corr_length_lag1(flat, 4), 3, 1e-12);
    double neg[3] = {1, -0.1, 0};
    cr_assert(isnan(corr_length_lag1(neg, 3)));
}

/* error_corr_length, the splotch statistic of Figs. 5.6 and 6.2-6.7 (one definition for both
 * chapters): error alternating in sign from column to column (lag-1 correlation -1 along x: no
 * correlated part, so that axis counts as 1, not NAN) and varying slowly along y (a long length).
 * The mean is then finite, 0.5 (1 + the y length); an error-free render gives NAN. */
Test(noise_corr, an_axis_without_correlation_counts_as_one)
{
    const int w = 128, h = 128;
    struct image *ref = img_create(w, h), *im = img_create(w, h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double e = (x & 1 ? -0.1 : 0.1) * (1 + 0.5 * sin(2 * M_PI * y / 64.0));
            img_add(ref, x, y, (rgb){1, 1, 1});
            img_add(im, x, y, (rgb){1 + e, 1 + e, 1 + e});
        }
    double l = error_corr_length(im, ref);
    cr_expect(!isnan(l) && l > 3 && l <= 0.5 * (1 + 33), "length %g", l);
    cr_expect(isnan(error_corr_length(ref, ref)), "an error-free render has a length");
    img_destroy(im);
    img_destroy(ref);
}

/* corr_profiles_in (the T27 statistic on the rings' pixels of Fig. 5.6): blurred noise (s = 3) on
 * the left half of the field, white noise on the right. Masked to a half, the length is that half's
 * (sqrt(1 + 4 s^2) = 6.08 and 1); a mask of every pixel gives the unmasked profile to the bit; a
 * lag no pair of the mask spans is NAN and ends the length there. */
Test(noise_corr, a_mask_measures_only_its_pixels)
{
    const int w = 512, h = 256, L = 30;
    double *f = synthetic(w, h, 3.0, 3.0, 0.0, 4);
    rng g;
    rng_seed(&g, 5, 1);
    bool *left = malloc(sizeof(bool) * w * h), *all = malloc(sizeof(bool) * w * h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * w + x;
            left[i] = x < w / 2;
            all[i] = true;
            if (!left[i]) f[i] = 3.0 + gauss(&g);
        }
    double rx[31], ry[31], ax[31], ay[31];
    cr_assert(corr_profiles(f, w, h, L, rx, ry));
    cr_assert(corr_profiles_in(f, w, h, all, L, ax, ay));
    for (int d = 0; d <= L; d++)
        cr_assert(rx[d] == ax[d] && ry[d] == ay[d], "lag %d", d);
    cr_assert(corr_profiles_in(f, w, h, left, L, ax, ay));
    double l = 0.5 * (corr_length_lag1(ax, L + 1) + corr_length_lag1(ay, L + 1)), e = sqrt(1 + 4 * 9.0);
    cr_assert(fabs(l / e - 1) < 0.1, "left half: %g, expected %g", l, e);
    for (int i = 0; i < w * h; i++)
        left[i] = !left[i];
    cr_assert(corr_profiles_in(f, w, h, left, L, ax, ay));
    for (int d = 1; d <= L; d++)
        cr_assert(fabs(ax[d]) < 0.03 && fabs(ay[d]) < 0.03, "white half, lag %d: %g %g", d, ax[d], ay[d]);
    /* a 3-pixel-wide column: no horizontal pair beyond lag 2 */
    for (int i = 0; i < w * h; i++)
        left[i] = i % w >= 10 && i % w < 13;
    cr_assert(corr_profiles_in(f, w, h, left, L, ax, ay));
    cr_assert(!isnan(ax[2]) && isnan(ax[3]));
    cr_assert(corr_length_lag1(ax, L + 1) <= 2);
    free(f);
    free(left);
    free(all);
}
