/* An image's error against a reference beyond its relMSE (error_stats.h). */
#include "stats/error_stats.h"
#include "base/util.h"
#include "stats/noise_corr.h"
#include <math.h>
#include <stdlib.h>

bool block_in_mask(const bool *mask, int w, int x0, int y0, int blk)
{
    if (!mask) return true;
    for (int y = y0; y < y0 + blk; y++)
        for (int x = x0; x < x0 + blk; x++)
            if (!mask[(size_t)y * w + x]) return false;
    return true;
}

int block_relmse_in(const struct image *a, const struct image *ref, int blk, double eps, const int rect[4],
                    const bool *mask, double *out, int cap)
{
    int bw = rect[2] / blk, bh = rect[3] / blk, n = 0;
    for (int by = 0; by < bh; by++)
        for (int bx = 0; bx < bw; bx++) {
            if (!block_in_mask(mask, a->w, rect[0] + bx * blk, rect[1] + by * blk, blk)) continue;
            double s = 0;
            for (int y = rect[1] + by * blk; y < rect[1] + (by + 1) * blk; y++)
                for (int x = rect[0] + bx * blk; x < rect[0] + (bx + 1) * blk; x++) {
                    const double *p = a->px + 3 * ((size_t)y * a->w + x), *r = ref->px + 3 * ((size_t)y * ref->w + x);
                    for (int c = 0; c < 3; c++)
                        s += (p[c] - r[c]) * (p[c] - r[c]) / (r[c] * r[c] + eps);
                }
            if (n < cap) out[n] = s / (3.0 * blk * blk);
            n++;
        }
    return n;
}

int block_relmse(const struct image *a, const struct image *ref, int blk, double eps, double *out, int cap)
{
    return block_relmse_in(a, ref, blk, eps, (const int[4]){0, 0, a->w, a->h}, NULL, out, cap);
}

double block_spread(const double *v, int n)
{
    if (n < 2) return NAN;
    double m = 0, q = 0;
    for (int i = 0; i < n; i++)
        m += v[i];
    m /= n;
    for (int i = 0; i < n; i++)
        q += (v[i] - m) * (v[i] - m);
    if (m == 0) return NAN;
    /* the standard error's form (sd / sqrt(n)) times sqrt(n): the same bits as before the move */
    return sqrt(q / (n - 1) / n) * sqrt((double)n) / m;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double median_of(double *v, int n)
{
    if (n <= 0) return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double relmse_where(const struct image *a, const struct image *ref, double eps, const bool *mask, bool in)
{
    double s = 0;
    size_t n = 0, npx = (size_t)a->w * a->h;
    for (size_t i = 0; i < npx; i++) {
        if (mask[i] != in) continue;
        for (int c = 0; c < 3; c++) {
            double p = a->px[3 * i + c], r = ref->px[3 * i + c];
            s += (p - r) * (p - r) / (r * r + eps);
        }
        n++;
    }
    return n ? s / (3.0 * n) : NAN;
}

double trimmed_relmse(const struct image *a, const struct image *ref, double eps, double drop)
{
    size_t n = (size_t)a->w * a->h;
    double *e = xmalloc(n * sizeof *e);
    for (size_t i = 0; i < n; i++) {
        const double *p = a->px + 3 * i, *r = ref->px + 3 * i;
        e[i] = 0;
        for (int c = 0; c < 3; c++)
            e[i] += (p[c] - r[c]) * (p[c] - r[c]) / (r[c] * r[c] + eps);
    }
    qsort(e, n, sizeof *e, cmp_double);
    size_t keep = n - (size_t)floor(drop * (double)n);
    double s = 0;
    for (size_t i = 0; i < keep; i++)
        s += e[i];
    free(e);
    return keep ? s / (3.0 * (double)keep) : NAN;
}

double relmse_scaled(const struct image *a, const struct image *ref, double eps)
{
    double s = mean_lum_scale(a, ref), sum = 0;
    size_t n = (size_t)a->w * a->h * 3;
    for (size_t i = 0; i < n; i++) {
        double d = s * a->px[i] - ref->px[i];
        sum += d * d / (ref->px[i] * ref->px[i] + eps);
    }
    return n ? sum / (double)n : NAN;
}
