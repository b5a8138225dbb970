/* experiments/ch4/fig4_5_claims: the thesis's sentences on Fig. 4.5 tested as it states them. MMLT
 * large steps "consistently low" is a level at every length: one length above it contradicts the
 * claim, whatever the shape; "increases with the path length" is a slope. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ch4/fig4_5_claims.h"
#include "support/claims_rows.h"
#include "support/tmpdir.h"

/* MMLT large steps at `mmlt` per length (one length `at` at `bump`), MCTLS growing with the length,
 * standard errors 2 % of the means; every other run a copy of MMLT's. Returns OUT/claims.csv. */
static char *claims_of(double mmlt, int at, double bump)
{
    static struct accept_table t;
    static struct trials_table tr;
    memset(&t, 0, sizeof t);
    t.K = 12;
    for (int v = 0; v < NV; v++)
        for (int k = 1; k <= t.K; k++) {
            double m = v == V_MCTLS ? mmlt * (1 + 0.3 * k) : k == at ? bump : mmlt;
            t.mean[v][k] = m, t.se[v][k] = 0.02 * m;
            t.nonzero[v][k] = 0.1, t.attempts[v][k] = 100000;
        }
    char dir[64], err[256];
    tmpdir_make(dir, sizeof dir, "fig45-claims");
    char *md = fig4_5_claims(&t, &tr, dir, "quick", err, sizeof err);
    cr_assert(md, "%s", err);
    free(md);
    char *csv = claims_rows_read(dir);
    tmpdir_remove(dir);
    return csv;
}

/* The verdict of the row with ID id, "no row" without one. */
static const char *word(const char *csv, const char *id)
{
    const char *v = claims_rows_verdict(csv, id, "");
    return v ? v : "no row";
}

Test(fig4_5_claims, low_at_every_length_is_a_level)
{
    char *csv = claims_of(0.003, 0, 0);
    cr_assert_str_eq(word(csv, "T13"), "holds", "%s", csv);
    cr_assert_str_eq(word(csv, "T15"), "holds"); /* MCTLS's slope */
    cr_assert(claims_rows_verdict(csv, "T16", ""), "the thesis names length 11: a row there");
    /* the thesis's MMLT large step draws among k + 2 techniques: T14 and T16 compare with that one,
     * the harness's k + 1 are its own rows */
    cr_assert(claims_rows_verdict(csv, "T14", "mctls-tries1-t0=") && !claims_rows_verdict(csv, "T14", "mmlt-large="),
              "%s", csv);
    cr_assert(claims_rows_verdict(csv, "harness:T14", "mmlt-large=") && !claims_rows_verdict(csv, "T16", "mmlt-large"),
              "%s", csv);
    free(csv);
    csv = claims_of(0.003, 7, 0.2); /* one length far above "low" */
    cr_assert_str_eq(word(csv, "T13"), "contradicted", "%s", csv);
    free(csv);
}
