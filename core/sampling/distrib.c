/* Piecewise-constant 1D/2D distributions (see distrib.h). */
#include "sampling/distrib.h"
#include "base/util.h"
#include <math.h>
#include <stdlib.h>

double cdf_build(double *cdf, const double *w, int n)
{
    double total = 0;
    cdf[0] = 0;
    for (int i = 0; i < n; i++) {
        total += w[i] > 0 ? w[i] : 0;
        cdf[i + 1] = total;
    }
    if (!(total > 0) || !isfinite(total)) {
        for (int i = 0; i <= n; i++)
            cdf[i] = (double)i / n;
        cdf[n] = 1;
        return 0;
    }
    for (int i = 1; i < n; i++)
        cdf[i] /= total;
    cdf[n] = 1;
    return total;
}

int cdf_find(const double *cdf, int n, double u)
{
    /* For u in [0,1) the largest i with cdf[i] <= u always owns a non-empty interval: an empty
     * one would have cdf[i+1] = cdf[i] <= u, and cdf[n] = 1 > u. */
    if (!(u >= 0)) u = 0;
    if (u >= 1) u = nextafter(1.0, 0.0);
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        int mid = lo + (hi - lo + 1) / 2;
        if (cdf[mid] <= u)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

int cdf_sample_cont(const double *cdf, int n, double u, double *frac)
{
    int i = cdf_find(cdf, n, u);
    double w = cdf[i + 1] - cdf[i];
    double f = w > 0 ? (u - cdf[i]) / w : 0.5;
    if (f < 0) f = 0;
    if (f >= 1) f = nextafter(1.0, 0.0);
    *frac = f;
    return i;
}

double cdf_invert_cont(const double *cdf, int i, double frac)
{
    double u = cdf[i] + frac * (cdf[i + 1] - cdf[i]);
    if (u >= cdf[i + 1] && cdf[i + 1] > cdf[i]) u = nextafter(cdf[i + 1], cdf[i]);
    if (u >= 1) u = nextafter(1.0, 0.0);
    return u;
}

bool distrib2d_init(struct distrib2d *d, const double *w, int nx, int ny)
{
    d->nx = nx;
    d->ny = ny;
    d->marg = xmalloc(sizeof(double) * (size_t)(ny + 1));
    d->cond = xmalloc(sizeof(double) * (size_t)ny * (size_t)(nx + 1));
    double *rows = xmalloc(sizeof(double) * (size_t)ny);
    for (int y = 0; y < ny; y++)
        rows[y] = cdf_build(d->cond + (size_t)y * (nx + 1), w + (size_t)y * nx, nx);
    d->total = cdf_build(d->marg, rows, ny);
    free(rows);
    return d->total > 0;
}

void distrib2d_free(struct distrib2d *d)
{
    free(d->marg);
    free(d->cond);
    d->marg = d->cond = NULL;
    d->total = 0;
}

static double prob(const double *cdf, int i) { return cdf[i + 1] - cdf[i]; }

void distrib2d_sample(const struct distrib2d *d, double u1, double u2, double *x, double *y, double *pdf)
{
    double fy, fx;
    int r = cdf_sample_cont(d->marg, d->ny, u1, &fy);
    const double *c = d->cond + (size_t)r * (d->nx + 1);
    int k = cdf_sample_cont(c, d->nx, u2, &fx);
    *y = (r + fy) / d->ny;
    *x = (k + fx) / d->nx;
    if (*y >= 1) *y = nextafter(1.0, 0.0);
    if (*x >= 1) *x = nextafter(1.0, 0.0);
    *pdf = prob(d->marg, r) * prob(c, k) * d->nx * d->ny;
}

static int cell(double t, int n, double *frac)
{
    double s = t * n;
    int i = (int)floor(s);
    if (i < 0) i = 0;
    if (i > n - 1) i = n - 1;
    double f = s - i;
    *frac = f < 0 ? 0 : f >= 1 ? nextafter(1.0, 0.0) : f;
    return i;
}

double distrib2d_pdf(const struct distrib2d *d, double x, double y)
{
    if (!(d->total > 0) || !(x >= 0 && x <= 1 && y >= 0 && y <= 1)) return 0;
    double fx, fy;
    int r = cell(y, d->ny, &fy), k = cell(x, d->nx, &fx);
    return prob(d->marg, r) * prob(d->cond + (size_t)r * (d->nx + 1), k) * d->nx * d->ny;
}

bool distrib2d_invert(const struct distrib2d *d, double x, double y, double *u1, double *u2)
{
    if (!(d->total > 0) || !(x >= 0 && x <= 1 && y >= 0 && y <= 1)) return false;
    double fx, fy;
    int r = cell(y, d->ny, &fy), k = cell(x, d->nx, &fx);
    const double *c = d->cond + (size_t)r * (d->nx + 1);
    if (!(prob(d->marg, r) > 0) || !(prob(c, k) > 0)) return false;
    *u1 = cdf_invert_cont(d->marg, r, fy);
    *u2 = cdf_invert_cont(c, k, fx);
    return true;
}
