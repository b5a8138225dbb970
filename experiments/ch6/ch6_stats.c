/* Shared analysis of the chapter-6 tools (ch6_stats.h). */
#include "ch6/ch6_stats.h"
#include "base/util.h"
#include "stats/noise_corr.h"
#include <math.h>
#include <stdlib.h>

int ch6_block_relmse(const struct image *a, const struct image *ref, int blk, double eps, double *out, int cap)
{
    int bw = a->w / blk, bh = a->h / blk, n = 0;
    for (int by = 0; by < bh; by++)
        for (int bx = 0; bx < bw; bx++) {
            double s = 0;
            for (int y = by * blk; y < (by + 1) * blk; y++)
                for (int x = bx * blk; x < (bx + 1) * blk; x++) {
                    const double *p = a->px + 3 * ((size_t)y * a->w + x), *r = ref->px + 3 * ((size_t)y * ref->w + x);
                    for (int c = 0; c < 3; c++)
                        s += (p[c] - r[c]) * (p[c] - r[c]) / (r[c] * r[c] + eps);
                }
            if (n < cap) out[n] = s / (3.0 * blk * blk);
            n++;
        }
    return n;
}

double ch6_spread(const double *v, int n)
{
    double m, se;
    if (n < 2) return NAN;
    mean_se(v, n, &m, &se);
    if (m == 0) return NAN;
    return se * sqrt((double)n) / m;
}

double ch6_loglog_slope(const double *x, const double *y, int n)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int k = 0;
    for (int i = 0; i < n; i++) {
        if (!(x[i] > 0 && y[i] > 0)) continue;
        double lx = log(x[i]), ly = log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
        k++;
    }
    double d = k * sxx - sx * sx;
    return k >= 2 && d > 0 ? (k * sxy - sx * sy) / d : NAN;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double ch6_median(double *v, int n)
{
    if (n <= 0) return NAN;
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double ch6_trimmed_relmse(const struct image *a, const struct image *ref, double eps, double drop)
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

double ch6_relmse_scaled(const struct image *a, const struct image *ref, double eps)
{
    double s = mean_lum_scale(a, ref), sum = 0;
    size_t n = (size_t)a->w * a->h * 3;
    for (size_t i = 0; i < n; i++) {
        double d = s * a->px[i] - ref->px[i];
        sum += d * d / (ref->px[i] * ref->px[i] + eps);
    }
    return n ? sum / (double)n : NAN;
}
