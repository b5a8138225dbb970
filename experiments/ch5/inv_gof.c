/* Goodness of fit of inverted numbers (inv_gof.h). */
#include "ch5/inv_gof.h"
#include "base/util.h"
#include "base/vecmath.h"
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void inv_set_init(struct inv_set *s) { memset(s, 0, sizeof *s); }

void inv_set_free(struct inv_set *s)
{
    for (int i = 0; i < INV_SLOTS; i++)
        free(s->val[i]);
    memset(s, 0, sizeof *s);
}

static int bin(double u, int k)
{
    int b = (int)(u * k);
    return b < 0 ? 0 : b >= k ? k - 1 : b;
}

/* Pair index of slots i < j of one block (0..27). */
static int pair_index(int i, int j) { return i * (15 - i) / 2 + j - i - 1; }

void inv_set_add(struct inv_set *s, const double *u)
{
    s->n++;
    for (int k = 0; k < INV_SLOTS; k++) {
        if (isnan(u[k])) continue;
        if (s->count[k] == s->cap[k]) {
            s->cap[k] = s->cap[k] ? 2 * s->cap[k] : 4096;
            s->val[k] = xrealloc(s->val[k], (size_t)s->cap[k] * sizeof *s->val[k]);
        }
        s->val[k][s->count[k]++] = (float)u[k];
        s->h1[k][bin(u[k], INV_BINS_1D)]++;
    }
    for (int b = 0; b < INV_BLOCKS_ALL; b++)
        for (int i = 0; i < 8; i++) {
            double x = u[b * 8 + i];
            if (isnan(x)) continue;
            for (int j = i + 1; j < 8; j++) {
                double y = u[b * 8 + j];
                if (isnan(y)) continue;
                int p = pair_index(i, j);
                s->pair_n[b][p]++;
                s->h2[b][p][bin(x, INV_BINS_2D) * INV_BINS_2D + bin(y, INV_BINS_2D)]++;
            }
        }
}

void inv_slot_name(int slot, char *buf, size_t n)
{
    snprintf(buf, n, "%c%d", slot < INV_SLOTS_PER_STREAM ? 'c' : 'e', slot % INV_SLOTS_PER_STREAM);
}

double inv_ks_q(double lambda)
{
    if (lambda < 0.2) return 1;
    double q = 0;
    for (int k = 1; k <= 100; k++) {
        double t = exp(-2.0 * k * k * lambda * lambda);
        q += (k % 2 ? 2 : -2) * t;
        if (t < 1e-17) break;
    }
    return q < 0 ? 0 : q > 1 ? 1 : q;
}

double inv_sidak_alpha(double alpha, int m) { return -expm1(log1p(-alpha) / m); }
double inv_sidak_p(double p, int m) { return p >= 1 ? 1 : -expm1(m * log1p(-p)); }

/* Chi-square of k cells: one-sample against equal expected counts (b NULL), or two-sample
 * homogeneity of a against b (cells empty in both dropped). Returns the p-value. */
static double chi2_cells(const long *a, long na, const long *b, long nb, int k, double *stat, int *dof)
{
    double x = 0;
    int used = 0;
    if (!b) {
        double e = (double)na / k;
        for (int i = 0; i < k; i++)
            x += sqr(a[i] - e) / e;
        used = k;
    } else {
        double ka = sqrt((double)nb / na), kb = sqrt((double)na / nb);
        for (int i = 0; i < k; i++)
            if (a[i] + b[i] > 0) {
                x += sqr(ka * a[i] - kb * b[i]) / (double)(a[i] + b[i]);
                used++;
            }
    }
    *stat = x;
    *dof = used - 1;
    return used > 1 ? gsl_cdf_chisq_Q(x, used - 1) : 1;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Kolmogorov-Smirnov statistic of sorted x[0..n-1] against the identity (y NULL) or against sorted
 * y[0..m-1]; returns the p-value (Stephens' finite-n correction of the limiting law). */
static double ks(const float *x, long n, const float *y, long m, double *dmax)
{
    double d = 0;
    if (!y) {
        for (long i = 0; i < n; i++)
            d = fmax(d, fmax((i + 1.0) / n - x[i], x[i] - (double)i / n));
    } else {
        long i = 0, j = 0;
        while (i < n && j < m) {
            float v = x[i] < y[j] ? x[i] : y[j];
            while (i < n && x[i] == v)
                i++;
            while (j < m && y[j] == v)
                j++;
            d = fmax(d, fabs((double)i / n - (double)j / m));
        }
    }
    double ne = y ? (double)n * m / (n + m) : (double)n;
    *dmax = d;
    return inv_ks_q((sqrt(ne) + 0.12 + 0.11 / sqrt(ne)) * d);
}

static void keep_chi(struct inv_gof *o, double p, double stat, int dof, const char *label)
{
    o->chi_tests++;
    if (o->chi_tests > 1 && p >= o->chi_p) return;
    o->chi_p = p, o->chi2 = stat, o->chi_dof = dof;
    snprintf(o->chi_worst, sizeof o->chi_worst, "%s", label);
}

/* The 8 x 8 chi-square of every pair of slots of a block with enough samples. */
static void pair_tests(const struct inv_set *t, const struct inv_set *r, struct inv_gof *o)
{
    for (int b = 0; b < INV_BLOCKS_ALL; b++)
        for (int i = 0; i < 8; i++)
            for (int j = i + 1; j < 8; j++) {
                int p = pair_index(i, j);
                long na = t->pair_n[b][p], nb = r ? r->pair_n[b][p] : INV_MIN_SAMPLES;
                if (na < INV_MIN_SAMPLES || nb < INV_MIN_SAMPLES) continue;
                double stat;
                int dof;
                double pv =
                    chi2_cells(t->h2[b][p], na, r ? r->h2[b][p] : NULL, nb, INV_BINS_2D * INV_BINS_2D, &stat, &dof);
                char a[12], c[12], label[32];
                inv_slot_name(b * 8 + i, a, sizeof a);
                inv_slot_name(b * 8 + j, c, sizeof c);
                snprintf(label, sizeof label, "%s×%s", a, c);
                keep_chi(o, pv, stat, dof, label);
            }
}

void inv_gof_evaluate(struct inv_set *t, struct inv_set *r, struct inv_gof *o)
{
    memset(o, 0, sizeof *o);
    o->chi_p = o->ks_p = 1;
    for (int k = 0; k < INV_SLOTS; k++) {
        long na = t->count[k], nb = r ? r->count[k] : INV_MIN_SAMPLES;
        if (na < INV_MIN_SAMPLES || nb < INV_MIN_SAMPLES) continue;
        char label[32];
        inv_slot_name(k, label, sizeof label);
        double stat, d;
        int dof;
        double pv = chi2_cells(t->h1[k], na, r ? r->h1[k] : NULL, nb, INV_BINS_1D, &stat, &dof);
        keep_chi(o, pv, stat, dof, label);
        qsort(t->val[k], (size_t)na, sizeof(float), cmp_float);
        if (r) qsort(r->val[k], (size_t)nb, sizeof(float), cmp_float);
        pv = ks(t->val[k], na, r ? r->val[k] : NULL, nb, &d);
        o->ks_tests++;
        if (o->ks_tests == 1 || pv < o->ks_p) {
            o->ks_p = pv, o->ks_d = d, o->ks_n = na;
            snprintf(o->ks_worst, sizeof o->ks_worst, "%s", label);
        }
    }
    pair_tests(t, r, o);
    o->chi_p_adj = inv_sidak_p(o->chi_p, o->chi_tests);
    o->ks_p_adj = inv_sidak_p(o->ks_p, o->ks_tests);
}
