/* Acceptance statistics per proposal kind, path length and technique change, with batch-means
 * standard errors, and their CSV rows (see mlt_stats.h). */
#include "stats/mlt_stats.h"
#include "base/vecmath.h"
#include <math.h>
#include <string.h>

static const char *kind_names[PROPOSAL_KINDS] = {"small",         "large",        "mctls",      "pitp",
                                                 "bidir",         "lens",         "caustic",    "fused-lens",
                                                 "fused-caustic", "lens-subpath", "multichain", "fused-multichain"};
static int kinds = PROPOSAL_BUILTIN;
const char *proposal_name(enum proposal_kind k) { return kind_names[k]; }

int proposal_kind_add(const char *name)
{
    if (kinds == PROPOSAL_KINDS) return -1;
    kind_names[kinds] = name;
    return kinds++;
}

void stats_clear(struct mlt_stats *s) { memset(s, 0, sizeof *s); }

static void record(struct accept_cell *c, double a, bool accepted, bool nonzero, double seconds, int dtech, bool failed)
{
    c->failed += failed;
    c->sum_dtech += dtech;
    c->accepted += accepted;
    c->nonzero += nonzero;
    c->seconds += seconds;
    cell_add(c, a < 1 ? a : 1);
}

void cell_add(struct accept_cell *c, double m)
{
    c->attempts++;
    c->sum_a += m;
    c->batch_sum += m;
    if (++c->batch_n == STATS_BATCH) {
        double b = c->batch_sum / STATS_BATCH;
        c->bsum += b;
        c->bsum2 += b * b;
        c->nbatches++;
        c->batch_sum = 0;
        c->batch_n = 0;
    }
}

void stats_record_dt(struct mlt_stats *s, enum proposal_kind kind, int length, bool changed, int dtech, bool failed,
                     double a, bool accepted, bool nonzero, double seconds)
{
    if (length < 0 || length >= STATS_LENGTHS) length = 0;
    record(&s->cell[kind][length][changed], a, accepted, nonzero, seconds, dtech, failed);
    record(&s->any[kind][length], a, accepted, nonzero, seconds, dtech, failed);
    record(&s->total[kind], a, accepted, nonzero, seconds, dtech, failed);
}

void stats_record(struct mlt_stats *s, enum proposal_kind kind, int length, bool changed, double a, bool accepted,
                  bool nonzero, double seconds)
{
    stats_record_dt(s, kind, length, changed, 0, false, a, accepted, nonzero, seconds);
}

void cell_merge(struct accept_cell *d, const struct accept_cell *s)
{
    d->attempts += s->attempts;
    d->accepted += s->accepted;
    d->nonzero += s->nonzero;
    d->seconds += s->seconds;
    d->sum_a += s->sum_a;
    d->sum_dtech += s->sum_dtech;
    d->failed += s->failed;
    d->nbatches += s->nbatches;
    d->bsum += s->bsum;
    d->bsum2 += s->bsum2;
    /* incomplete batches count in the mean but not in the standard error */
}

void stats_merge(struct mlt_stats *dst, const struct mlt_stats *src)
{
    for (int k = 0; k < PROPOSAL_KINDS; k++) {
        for (int l = 0; l < STATS_LENGTHS; l++) {
            for (int c = 0; c < 2; c++)
                cell_merge(&dst->cell[k][l][c], &src->cell[k][l][c]);
            cell_merge(&dst->any[k][l], &src->any[k][l]);
        }
        cell_merge(&dst->total[k], &src->total[k]);
    }
    nonfinite_add(&dst->nonfinite, &src->nonfinite);
    dst->conn_tried += src->conn_tried;
    dst->conn_nonzero += src->conn_nonzero;
    dst->fused_inverted += src->fused_inverted;
    dst->fused_not_inverted += src->fused_not_inverted;
    for (int l = 0; l < STATS_LENGTHS; l++) {
        dst->large[l].sum += src->large[l].sum;
        dst->large[l].sq += src->large[l].sq;
        dst->large[l].n += src->large[l].n;
        dst->iters[l] += src->iters[l];
        dst->zero_iters[l] += src->zero_iters[l];
    }
}

void target_sum_add(struct target_sum *t, double f)
{
    t->sum += f;
    t->sq += f * f;
    t->n++;
}

double cell_mean(const struct accept_cell *c) { return c->attempts ? c->sum_a / c->attempts : NAN; }

double cell_stderr(const struct accept_cell *c)
{
    if (c->nbatches < 2) return NAN;
    double n = (double)c->nbatches, m = c->bsum / n;
    double var = (c->bsum2 - n * m * m) / (n - 1);
    return sqrt(var > 0 ? var : 0) / sqrt(n);
}

static void row(FILE *f, const char *method, const char *kind, const char *len, const char *changed,
                const struct accept_cell *c)
{
    fprintf(f, "%s,%s,%s,%s,%ld,%.9g,%.9g,%.9g,%ld,%.9g,%ld\n", method, kind, len, changed, c->attempts, cell_mean(c),
            cell_stderr(c), c->attempts ? (double)c->accepted / c->attempts : NAN, c->nonzero,
            c->attempts ? c->sum_dtech / c->attempts : NAN, c->failed);
}

void stats_write_csv(FILE *f, const char *method, const struct mlt_stats *s, bool header)
{
    if (header)
        fprintf(f, "method,kind,length,technique_changed,attempts,mean_accept,stderr,accepted_fraction,nonzero,mean_"
                   "dtech,failed\n");
    char len[16];
    for (int k = 0; k < PROPOSAL_KINDS; k++) {
        for (int l = 0; l < STATS_LENGTHS; l++) {
            if (!s->any[k][l].attempts) continue;
            snprintf(len, sizeof len, "%d", l);
            for (int c = 0; c < 2; c++)
                if (s->cell[k][l][c].attempts)
                    row(f, method, kind_names[k], l ? len : "all", c ? "yes" : "no", &s->cell[k][l][c]);
            row(f, method, kind_names[k], l ? len : "all", "any", &s->any[k][l]);
        }
        if (s->total[k].attempts) row(f, method, kind_names[k], "total", "any", &s->total[k]);
    }
}
