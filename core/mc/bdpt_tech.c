/* BDPT's per-technique images and variances of one path length (bdpt_tech.h). */
#include "mc/bdpt_tech.h"
#include "base/util.h"
#include <stdlib.h>
#include <string.h>

static size_t plane(const struct bdpt_tech *a) { return 3 * (size_t)a->w * a->h; }
size_t bdpt_tech_bytes(const struct bdpt_tech *a) { return 2 * (size_t)(a->k + 1) * plane(a) * sizeof *a->sum; }

struct bdpt_tech *bdpt_tech_create(int k, int w, int h, bool tent)
{
    ASSERT(k >= 1 && k <= MAX_PATH_LENGTH);
    struct bdpt_tech *a = xmalloc(sizeof *a);
    *a = (struct bdpt_tech){k, w, h, tent, NULL};
    a->sum = xcalloc(1, bdpt_tech_bytes(a));
    return a;
}

void bdpt_tech_free(struct bdpt_tech *a)
{
    if (!a) return;
    free(a->sum);
    free(a);
}

/* Technique t's sums (sq: of squares) as an image over the accumulator's memory. */
static struct image view(const struct bdpt_tech *a, int t, bool sq)
{
    return (struct image){a->w, a->h, a->sum + ((size_t)(sq ? a->k + 1 : 0) + (size_t)(t - 1)) * plane(a), a->tent};
}

void bdpt_tech_add(struct bdpt_tech *a, const struct scratch *w)
{
    for (int t = 1; t <= a->k + 1; t++) {
        if (!w->tech_on[t]) continue;
        const struct splat *sp = &w->tech[t];
        struct image c = view(a, t, false), q = view(a, t, true);
        img_splat(&c, sp->px, sp->py, sp->c);
        img_splat(&q, sp->px, sp->py, vmul(sp->c, sp->c));
    }
}

void bdpt_tech_accumulate(struct bdpt_tech *dst, const struct bdpt_tech *src)
{
    ASSERT(dst->k == src->k && dst->w == src->w && dst->h == src->h);
    size_t n = bdpt_tech_bytes(dst) / sizeof *dst->sum;
    for (size_t i = 0; i < n; i++)
        dst->sum[i] += src->sum[i];
}

double bdpt_tech_var(double sum, double sq, long n, double N)
{
    if (N < 2) return 0;
    return maxd(sq - sum * sum / N, 0) / ((double)n * (double)n) * N / (N - 1);
}

static int cmp_desc(const void *x, const void *y)
{
    double a = *(const double *)x, b = *(const double *)y;
    return (a < b) - (a > b);
}

void bdpt_tech_rows(const struct bdpt_tech *a, long n, const struct image *full, struct bdpt_tech_row *rows)
{
    size_t np = (size_t)a->w * a->h;
    double *px = xmalloc(np * sizeof *px);
    for (int t = 1; t <= a->k + 1; t++) {
        struct image c = view(a, t, false), q = view(a, t, true);
        double mean = 0, rv = 0, N = t == 1 ? (double)n * (double)np : (double)n;
        for (size_t p = 0; p < np; p++) {
            double e = 0;
            for (int ch = 0; ch < 3; ch++) {
                size_t i = 3 * p + (size_t)ch;
                e += bdpt_tech_var(c.px[i], q.px[i], n, N) / (sqr(full->px[i]) + 0.01);
            }
            px[p] = e / 3;
            rv += px[p];
            mean += luminance((rgb){c.px[3 * p], c.px[3 * p + 1], c.px[3 * p + 2]}) / (double)n;
        }
        qsort(px, np, sizeof *px, cmp_desc);
        double top = 0;
        for (size_t p = 0; p < (np + 99) / 100; p++)
            top += px[p];
        rows[t - 1] =
            (struct bdpt_tech_row){a->k + 1 - t, t, mean / (double)np, rv / (double)np, rv > 0 ? top / rv : 0};
    }
    free(px);
}

bool bdpt_tech_write(const struct bdpt_tech *a, long n, const struct image *full, const char *prefix,
                     const char *header, char *err, size_t errlen)
{
    struct bdpt_tech_row rows[MAX_PATH_LENGTH + 1];
    bdpt_tech_rows(a, n, full, rows);
    double lum = 0, rv = 0;
    for (int t = 1; t <= a->k + 1; t++) {
        lum += rows[t - 1].mean;
        rv += rows[t - 1].rel_var;
    }
    char path[4200];
    bool ok = true;
    for (int t = 1; t <= a->k + 1 && ok; t++) {
        struct image c = view(a, t, false);
        snprintf(path, sizeof path, "%.4000s.tech-t%d.exr", prefix, t);
        ok = img_write_exr(&c, 1.0 / (double)n, path, err, errlen);
        snprintf(path, sizeof path, "%.4000s.tech-t%d.png", prefix, t);
        ok = ok && img_write_png(&c, (lum > 0 ? 0.5 / lum : 1.0) / (double)n, path, err, errlen);
    }
    if (!ok) return false;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    fputs(header, f);
    fprintf(f, "technique,s,t,mean,rel_var,rel_var_share,top1_share\n");
    for (int t = 1; t <= a->k + 1; t++) {
        const struct bdpt_tech_row *r = &rows[t - 1];
        fprintf(f, "%d,%d,%d,%.9g,%.9g,%.6f,%.6f\n", t, r->s, r->t, r->mean, r->rel_var, rv > 0 ? r->rel_var / rv : 0,
                r->top1);
    }
    fclose(f);
    snprintf(path, sizeof path, "%.4000s.tech.csv", prefix);
    ok = write_text_atomic(path, buf, err, errlen);
    free(buf);
    return ok;
}
