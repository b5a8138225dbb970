/* Autocorrelation profiles and correlation lengths of an error field (noise_corr.h). */
#include "stats/noise_corr.h"
#include "base/util.h"
#include "stats/error_stats.h"
#include <math.h>
#include <stdlib.h>

bool corr_profiles(const double *f, int w, int h, int maxlag, double *rho_x, double *rho_y)
{
    ASSERT(maxlag >= 0 && maxlag < w && maxlag < h);
    size_t n = (size_t)w * h;
    double mean = 0;
    for (size_t i = 0; i < n; i++)
        mean += f[i];
    mean /= (double)n;
    double *e = xmalloc(n * sizeof *e), var = 0;
    for (size_t i = 0; i < n; i++) {
        e[i] = f[i] - mean;
        var += e[i] * e[i];
    }
    var /= (double)n;
    if (!(var > 0)) {
        free(e);
        return false;
    }
    for (int d = 0; d <= maxlag; d++) {
        double sx = 0, sy = 0;
        for (int y = 0; y < h; y++) {
            const double *r = e + (size_t)y * w;
            for (int x = 0; x + d < w; x++)
                sx += r[x] * r[x + d];
            if (y + d < h) {
                const double *r2 = e + (size_t)(y + d) * w;
                for (int x = 0; x < w; x++)
                    sy += r[x] * r2[x];
            }
        }
        rho_x[d] = sx / ((double)(w - d) * h) / var;
        rho_y[d] = sy / ((double)(h - d) * w) / var;
    }
    free(e);
    return true;
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
    for (int d = 2; d < n; d++)
        if (rho[d] < lv) return d - 1 + (rho[d - 1] - lv) / (rho[d - 1] - rho[d]);
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

double error_corr_length(const struct image *img, const struct image *ref)
{
    int maxlag = 32;
    if (maxlag >= img->w) maxlag = img->w - 1;
    if (maxlag >= img->h) maxlag = img->h - 1;
    if (maxlag < 2) return NAN;
    double *e = error_field(img, ref), rx[33], ry[33];
    bool ok = corr_profiles(e, img->w, img->h, maxlag, rx, ry);
    free(e);
    if (!ok) return NAN;
    double lx = corr_length_lag1(rx, maxlag + 1), ly = corr_length_lag1(ry, maxlag + 1);
    return 0.5 * ((isnan(lx) ? 1 : lx) + (isnan(ly) ? 1 : ly));
}
