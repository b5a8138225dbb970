/* The MMLT paper's Fig. 5 claim from bin/ch6_tech's "follow" tables (ch6_claims.h). */
#include "ch6/ch6_claims.h"
#include "common/claims.h"
#include "common/csv_read.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Column name's mean and standard error over the rows (the runs) of a follow table. */
static bool column_mean(const struct csv_file *c, const char *name, double *mean, double *se, char *err, size_t errlen)
{
    int col = csv_column(c, name, err, errlen);
    if (col < 0) return false;
    double *v = malloc(sizeof *v * (size_t)(c->nrows ? c->nrows : 1));
    for (int r = 0; r < c->nrows; r++)
        v[r] = csv_number(c, r, col);
    mean_se(v, c->nrows, mean, se);
    free(v);
    return true;
}

char *ch6_tech_claims(const struct ch6_tech_claims_in *in, char *err, size_t errlen)
{
    static const struct {
        const char *col, *claim, *statistic;
        int sign;
    } rows[] = {
        {"tv", "MMLT's sample counts follow the per-technique contributions and PSSMLT's do not (image-wide shares)",
         "tv: half the L1 distance of the technique shares of samples and contributions", -1},
        {"r", "MMLT's sample counts follow the per-technique contributions and PSSMLT's do not (per block)",
         "r: correlation of the within-block technique shares", +1},
    };
    struct csv_file *c[2] = {csv_load(in->follow[0], err, errlen), NULL};
    if (c[0]) c[1] = csv_load(in->follow[1], err, errlen);
    char *md = NULL;
    if (!c[0] || !c[1]) goto done;
    struct claims cl;
    claims_begin(&cl, in->scale, in->command, "The MMLT paper's Fig. 5 claim at path length %d, %d runs per method",
                 in->k, c[0]->nrows);
    for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
        double m[2], s[2];
        if (!column_mean(c[0], rows[i].col, &m[0], &s[0], err, errlen) ||
            !column_mean(c[1], rows[i].col, &m[1], &s[1], err, errlen))
            goto done;
        int seeds = c[0]->nrows < c[1]->nrows ? c[0]->nrows : c[1]->nrows;
        struct verdict v = verdict_pair(m[0], s[0], m[1], s[1], rows[i].sign, seeds);
        claims_row_against(&cl, "M-f", "MMLT paper §5, Fig. 5", rows[i].claim, rows[i].statistic, "mmlt", m[0], s[0],
                           &v, "pssmlt", "pssmlt %.4g ± %.2g", m[1], s[1]);
    }
    md = claims_finish(&cl, in->dir, err, errlen);
done:
    csv_free(c[0]);
    csv_free(c[1]);
    return md;
}
