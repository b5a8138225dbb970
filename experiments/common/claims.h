/* The claims files every figure with a verdict writes: claims.csv (one row per claim and
 * statistic, the rows of the report's claims ledger) and claims.md (the same as a table), both
 * written atomically into the figure's folder. The verdicts come from verdict.h. */
#ifndef CLAIMS_H
#define CLAIMS_H

#include "common/verdict.h"
#include <stddef.h>
#include <stdio.h>

struct claims {
    char *csv, *md;
    size_t clen, mlen;
    FILE *c, *m;
    const char *scale, *command;
    /* Set before claims_row: a note on the runs behind the row (e.g. their chains' mixing
     * diagnostics warn), its `mixing` column and a mark beside its verdict; NULL or "" for none. The
     * verdict stands; the note says how much to trust it. */
    const char *flag;
};

/* Starts both files: `title` heads them (a printf format). */
void claims_begin(struct claims *cl, const char *scale, const char *command, const char *title, ...)
    __attribute__((format(printf, 4, 5)));
/* One row: the claim's catalogue ID (results/claims-catalogue.csv: "T13"; "harness:T13" for the
 * harness's own reading of that claim, another comparison or setting than the source's; "harness"
 * for a check of the harness with no source claim), its source and text, the statistic, the method and its value ± se,
 * the comparison (`versus`: "NAME=z;..." for the CSV, `versus_md` the readable form) and the verdict. */
void claims_row(struct claims *cl, const char *id, const char *source, const char *claim, const char *statistic,
                const char *method, double value, double se, const char *versus, const char *versus_md,
                const struct verdict *v);
/* claims_row against one thing, `against` (a method, or a bound such as "0.5"): the CSV's comparison
 * "AGAINST=z", the table's the printf format `against_md` (what is compared with, "mmlt %.4g ± %.2g"
 * or "below 0.5") followed by " (z = z)", z being v's. */
void claims_row_against(struct claims *cl, const char *id, const char *source, const char *claim, const char *statistic,
                        const char *method, double value, double se, const struct verdict *v, const char *against,
                        const char *against_md, ...) __attribute__((format(printf, 11, 12)));
/* The comparison's two forms for claims_row from verdict_extreme's z over k methods: "NAME=z;..."
 * into versus and "NAME mean ± se (z = z); ..." into versus_md, for the methods whose z is a number. */
void claims_versus(const char *const *names, const double *mean, const double *se, const double *z, int k, char *versus,
                   size_t vlen, char *versus_md, size_t mlen);
/* Writes DIR/claims.csv and DIR/claims.md and returns the Markdown (caller frees), or NULL with one
 * line in err. */
char *claims_finish(struct claims *cl, const char *dir, char *err, size_t errlen);
/* claims_finish, then the Markdown on stderr; on failure its one line there and exit status 1. */
void claims_finish_print(struct claims *cl, const char *dir);

#endif
