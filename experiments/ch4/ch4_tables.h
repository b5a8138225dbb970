/* The CSV tables of a chapter-4 figure tool, written together: each from its own column list
 * (common/table.h), all opening with the same metadata lines, saved into the output folder and
 * listed on one "PROG: wrote DIR/A, DIR/B" line. fig4_1, fig4_2 and fig4_3 write a table per run
 * and one of the statistics over seeds (fig4_1 also the autocorrelation profiles) this way. */
#ifndef CH4_TABLES_H
#define CH4_TABLES_H

#include "common/table.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define CH4_MAX_TABLES 3

struct ch4_tables {
    int n;
    const char *names[CH4_MAX_TABLES]; /* file names in the output folder */
    struct table t[CH4_MAX_TABLES];
};

/* Opens n tables, names[i] from cols[i]; meta(f, ctx) writes the shared metadata lines into each
 * (meta may be NULL: then write them into tb->t[i].out.f). */
void ch4_tables_open(struct ch4_tables *tb, int n, const char *const *names, const struct column *const *cols,
                     void (*meta)(FILE *f, const void *ctx), const void *ctx);
/* One table, OUT/NAME, with metadata lines of its own: they go into the stream returned. */
FILE *ch4_tables_open_one(struct ch4_tables *tb, const char *name, const struct column *cols);
/* Writes every table into dir atomically (they are freed either way) and says so on stderr. False
 * with a message in err at the first failure. */
bool ch4_tables_save(struct ch4_tables *tb, const char *prog, const char *dir, char *err, size_t errlen);

/* The statistics row the figures share: one quantity of one configuration over the seeds (the
 * resolution column is fig4_2's only). */
struct ch4_stat_row {
    const char *config, *quantity;
    int resolution, seeds;
    double mean, se;
};
/* Fills row's mean and se from the seeds values at x (verdict.h's mean_se). */
void ch4_stat_row_of(struct ch4_stat_row *row, const double *x, int seeds);

/* n columns named names[i], each a value of type (COL_STR or COL_D) at off + i * stride in the row,
 * printed with fmt: a family of columns whose names are listed once, beside the quantities. */
void ch4_columns(struct column *c, int n, const char *const *names, enum col_type type, size_t off, size_t stride,
                 const char *fmt);

#endif
