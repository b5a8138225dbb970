/* Autocorrelation profiles and correlation lengths of an error field (noise_corr.h). */
#include "stats/noise_corr.h"
#include "base/util.h"
#include "stats/error_stats.h"
#include <math.h>
#include <stdlib.h>

bool corr_profiles_in(const double *f, int w, int h, const bool *mask, int maxlag, double *rho_x, double *rho_y)
{
    ASSERT(maxlag >= 0 && maxlag < w && maxlag < h);
    size_t n = (size_t)w * h, m = 0;
    double mean = 0;
    for (size_t i = 0; i < n; i++)
        if (!mask || mask[i]) mean += f[i], m++;
    if (m == 0) return false;
    mean /= (double)m;
    /* outside the mask e is 0 and flagged out, so a pair counts only with both ends inside */
    double *e = xmalloc(n * sizeof *e), var = 0;
    for (size_t i = 0; i < n; i++) {
        e[i] = !mask || mask[i] ? f[i] - mean : 0;
        var += e[i] * e[i];
    }
    var /= (double)m;
    if (!(var > 0)) {
        free(e);
        return false;
    }
    for (int d = 0; d <= maxlag; d++) {
        double sx = 0, sy = 0, nx = (double)(w - d) * h, ny = (double)(h - d) * w;
        if (mask) nx = ny = 0;
        for (int y = 0; y < h; y++) {
            const double *r = e + (size_t)y * w;
            const bool *mr = mask ? mask + (size_t)y * w : NULL;
            for (int x = 0; x + d < w; x++) {
                sx += r[x] * r[x + d];
                if (mr) nx += mr[x] && mr[x + d];
            }
            if (y + d < h) {
                const double *r2 = e + (size_t)(y + d) * w;
                const bool *mr2 = mask ? mask + (size_t)(y + d) * w : NULL;
                for (int x = 0; x < w; x++) {
                    sy += r[x] * r2[x];
                    if (mr) ny += mr[x] && mr2[x];
                }
            }
        }
        rho_x[d] = nx > 0 ? sx / nx / var : NAN;
        rho_y[d] = ny > 0 ? sy / ny / var : NAN;
    }
    free(e);
    return true;
}

bool corr_profiles(const double *f, int w, int h, int maxlag, double *rho_x, double *rho_y)
{
    return corr_profiles_in(f, w, h, NULL, maxlag, rho_x, rho_y);
}

double corr_length(const double *rho, int n, double level)
{
    for (int d = 1; d < n; d++)
        if (rho[d] < level) return d - 1 + (rho[d - 1] - level) / (rho[d - 1] - rho[d]);
    return n - 1;
}

double corr_length_lag1(const double *rho, int n)
{
    if (n < 2 || !(rho[1] > 0)) return NAN;
    double lv = rho[1] * exp(-1.0);
    for (int d = 2; d < n; d++) {
        if (isnan(rho[d])) return d - 1; /* a masked profile with no pairs this far */
        if (rho[d] < lv) return d - 1 + (rho[d - 1] - lv) / (rho[d - 1] - rho[d]);
    }
    return n - 1;
}

static double lum(const double *p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

double mean_lum_scale(const struct image *img, const struct image *ref)
{
    ASSERT(img->w == ref->w && img->h == ref->h);
    size_t n = (size_t)img->w * img->h;
    double si = 0, sr = 0;
    for (size_t i = 0; i < n; i++) {
        si += lum(img->px + 3 * i);
        sr += lum(ref->px + 3 * i);
    }
    return si > 0 ? sr / si : 1;
}

double *error_field(const struct image *img, const struct image *ref)
{
    size_t n = (size_t)img->w * img->h;
    double s = mean_lum_scale(img, ref);
    double *e = xmalloc(n * sizeof *e);
    for (size_t i = 0; i < n; i++)
        e[i] = s * lum(img->px + 3 * i) - lum(ref->px + 3 * i);
    return e;
}

double error_blur_share_in(const struct image *a, const struct image *ref, double eps, int k, const int rect[4],
                           const bool *mask, double s)
{
    double all = 0, blurred = 0;
    int bw = rect[2] / k, bh = rect[3] / k;
    for (int by = 0; by < bh; by++)
        for (int bx = 0; bx < bw; bx++) {
            int x0 = rect[0] + bx * k, y0 = rect[1] + by * k;
            if (!block_in_mask(mask, a->w, x0, y0, k)) continue;
            for (int c = 0; c < 3; c++) {
                double m = 0;
                for (int y = y0; y < y0 + k; y++)
                    for (int x = x0; x < x0 + k; x++) {
                        size_t i = 3 * ((size_t)y * a->w + x) + (size_t)c;
                        double r = ref->px[i], e = (s * a->px[i] - r) / sqrt(r * r + eps);
                        m += e;
                        all += e * e;
                    }
                m /= (double)k * k;
                blurred += m * m;
            }
        }
    /* per pixel: the blocks' squared means stand for k^2 pixels each */
    return all > 0 ? blurred * k * k / all : NAN;
}

double error_blur_share(const struct image *a, const struct image *ref, double eps, int k)
{
    return error_blur_share_in(a, ref, eps, k, (const int[4]){0, 0, a->w, a->h}, NULL, mean_lum_scale(a, ref));
}

double error_corr_length_in(const struct image *img, const struct image *ref, const bool *mask)
{
    int maxlag = 32;
    if (maxlag >= img->w) maxlag = img->w - 1;
    if (maxlag >= img->h) maxlag = img->h - 1;
    if (maxlag < 2) return NAN;
    double *e = error_field(img, ref), rx[33], ry[33];
    bool ok = corr_profiles_in(e, img->w, img->h, mask, maxlag, rx, ry);
    free(e);
    if (!ok) return NAN;
    double lx = corr_length_lag1(rx, maxlag + 1), ly = corr_length_lag1(ry, maxlag + 1);
    return 0.5 * ((isnan(lx) ? 1 : lx) + (isnan(ly) ? 1 : ly));
}

double error_corr_length(const struct image *img, const struct image *ref)
{
    return error_corr_length_in(img, ref, NULL);
}
