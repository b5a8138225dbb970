/* Shared analysis of the chapter-6 tools (ch6_stats.h). */
#include "ch6/ch6_stats.h"
#include <math.h>

void ch6_mean_se(const double *x, int n, double *mean, double *se)
{
    double m = 0, v = 0;
    for (int i = 0; i < n; i++) m += x[i];
    m = n > 0 ? m / n : NAN;
    for (int i = 0; i < n; i++) v += (x[i] - m) * (x[i] - m);
    *mean = m;
    *se = n > 1 ? sqrt(v / (n - 1) / n) : NAN;
}

int ch6_block_relmse(const struct image *a, const struct image *ref, int blk, double eps, double *out, int cap)
{
    int bw = a->w / blk, bh = a->h / blk, n = 0;
    for (int by = 0; by < bh; by++)
        for (int bx = 0; bx < bw; bx++) {
            double s = 0;
            for (int y = by * blk; y < (by + 1) * blk; y++)
                for (int x = bx * blk; x < (bx + 1) * blk; x++) {
                    const double *p = a->px + 3 * ((size_t)y * a->w + x), *r = ref->px + 3 * ((size_t)y * ref->w + x);
                    for (int c = 0; c < 3; c++) s += (p[c] - r[c]) * (p[c] - r[c]) / (r[c] * r[c] + eps);
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
    ch6_mean_se(v, n, &m, &se);
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
