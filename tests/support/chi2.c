/* Chi-square goodness of fit: binning, Simpson integration of the density, pooling, GSL tail. */
#include "support/chi2.h"
#include "base/util.h"
#include <gsl/gsl_cdf.h>
#include <stdio.h>
#include <stdlib.h>

#define SIMPSON 9 /* points per cell side, odd */

double chi2_alpha_sidak(void) { return 1.0 - pow(1.0 - CHI2_ALPHA, 1.0 / CHI2_CASES); }

static double simpson_w(int i)
{
    if (i == 0 || i == SIMPSON - 1) return 1;
    return (i % 2) ? 4 : 2;
}

struct pooled {
    double exp, obs;
};

static int cmp_exp(const void *a, const void *b)
{
    double x = ((const struct pooled *)a)->exp, y = ((const struct pooled *)b)->exp;
    return (x > y) - (x < y);
}

struct chi2_result chi2_test_2d(chi2_sample2d sample, chi2_pdf2d pdf, void *ctx, int nx, int ny, long n, uint64_t seed)
{
    struct chi2_result res = {0};
    int ncell = nx * ny;
    struct pooled *c = xcalloc((size_t)ncell + 1, sizeof *c);
    rng r;
    rng_seed(&r, seed, 0x2C41);
    for (long i = 0; i < n; i++) {
        double u, v;
        if (!sample(ctx, &r, &u, &v)) {
            c[ncell].obs++;
            res.other++;
            continue;
        }
        int x = (int)(u * nx), y = (int)(v * ny);
        x = x < 0 ? 0 : x >= nx ? nx - 1 : x;
        y = y < 0 ? 0 : y >= ny ? ny - 1 : y;
        c[y * nx + x].obs++;
    }
    double hx = 1.0 / nx, hy = 1.0 / ny, mass = 0;
    for (int y = 0; y < ny; y++)
        for (int x = 0; x < nx; x++) {
            double s = 0;
            for (int j = 0; j < SIMPSON; j++)
                for (int i = 0; i < SIMPSON; i++) {
                    double u = (x + (double)i / (SIMPSON - 1)) * hx, v = (y + (double)j / (SIMPSON - 1)) * hy;
                    s += simpson_w(i) * simpson_w(j) * pdf(ctx, u, v);
                }
            s *= hx * hy / sqr(3.0 * (SIMPSON - 1));
            c[y * nx + x].exp = s * n;
            mass += s;
            if (s == 0 && c[y * nx + x].obs > 0) res.zero_pdf_hits += (long)c[y * nx + x].obs;
        }
    res.mass = mass;
    c[ncell].exp = fmax(0.0, 1.0 - mass) * n;
    /* Pool the smallest cells until every pooled cell expects >= 5. */
    qsort(c, (size_t)ncell + 1, sizeof *c, cmp_exp);
    double pe = 0, po = 0, stat = 0;
    int bins = 0;
    for (int i = 0; i <= ncell; i++) {
        if (c[i].exp == 0 && c[i].obs == 0) continue;
        if (pe + c[i].exp < 5) {
            pe += c[i].exp;
            po += c[i].obs;
            continue;
        }
        double e = c[i].exp + pe, o = c[i].obs + po;
        pe = po = 0;
        stat += sqr(o - e) / e;
        bins++;
    }
    if (pe > 0 || po > 0) {
        if (pe > 0)
            stat += sqr(po - pe) / pe;
        else
            res.zero_pdf_hits += (long)po;
        bins++;
    }
    res.stat = stat;
    res.dof = bins > 1 ? bins - 1 : 1;
    res.pvalue = gsl_cdf_chisq_Q(stat, res.dof);
    res.pass = res.pvalue > chi2_alpha_sidak() && res.zero_pdf_hits == 0;
    free(c);
    /* PSS_CHI2_LOG=FILE: one line per case, so that the count behind CHI2_CASES can be measured
     * (the tests run in separate processes, hence a file, appended to) */
    const char *log = getenv("PSS_CHI2_LOG");
    FILE *f = log ? fopen(log, "a") : NULL;
    if (f) {
        fprintf(f, "%.6g %d %.6g\n", res.stat, res.dof, res.pvalue);
        fclose(f);
    }
    return res;
}

struct dir_ctx {
    chi2_sample_dir sample;
    chi2_pdf_dir pdf;
    void *ctx;
};

static vec3 uv_to_dir(double u, double v)
{
    double z = 2 * u - 1, r = sqrt(fmax(0.0, 1 - z * z)), phi = 2 * M_PI * v;
    return v3(r * cos(phi), r * sin(phi), z);
}

static bool dir_sample(void *p, rng *r, double *u, double *v)
{
    struct dir_ctx *c = p;
    vec3 d;
    if (!c->sample(c->ctx, r, &d)) return false;
    *u = clampd((d.z + 1) * 0.5, 0, 1);
    double phi = atan2(d.y, d.x);
    *v = (phi < 0 ? phi + 2 * M_PI : phi) / (2 * M_PI);
    return true;
}

static double dir_pdf(void *p, double u, double v)
{
    struct dir_ctx *c = p;
    return 4 * M_PI * c->pdf(c->ctx, uv_to_dir(u, v));
}

struct chi2_result chi2_test_dir(chi2_sample_dir sample, chi2_pdf_dir pdf, void *ctx, int ntheta, int nphi, long n,
                                 uint64_t seed)
{
    struct dir_ctx c = {sample, pdf, ctx};
    return chi2_test_2d(dir_sample, dir_pdf, &c, ntheta, nphi, n, seed);
}

const char *chi2_describe(const struct chi2_result *r, char *buf, int len)
{
    snprintf(buf, (size_t)len, "chi2=%.1f dof=%d p=%.3g (alpha=%.2g) mass=%.4f other=%ld zero-pdf hits=%ld", r->stat,
             r->dof, r->pvalue, chi2_alpha_sidak(), r->mass, r->other, r->zero_pdf_hits);
    return buf;
}
