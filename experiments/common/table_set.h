/* A tool's CSV tables written together: each from its own column list (table.h), all opening with
 * the same metadata lines, saved into the output folder and listed on one "PROG: wrote DIR/A,
 * DIR/B" line on stderr. The chapter-4 figures write a table per run beside one of the statistics
 * over seeds this way, table1_cmlt its three tables; a table with metadata of its own is a set of
 * one (table_set_open_one).
 *
 *   struct table_set ts;
 *   table_set_open(&ts, 2, (const char *[]){"fig-runs.csv", "fig.csv"},
 *                  (const struct column *[]){run_cols, stat_cols}, write_meta, &cfg);
 *   table_row(&ts.t[0], &run);  table_row(&ts.t[1], &stat);
 *   if (!table_set_save(&ts, prog, out, err, sizeof err)) ...
 *
 * Also here: table_columns, a family of columns named from an array (a figure's quantities), whose
 * names are then listed once. */
#ifndef TABLE_SET_H
#define TABLE_SET_H

#include "common/table.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define TABLE_SET_MAX 4

struct table_set {
    int n;
    const char *names[TABLE_SET_MAX]; /* file names in the output folder */
    struct table t[TABLE_SET_MAX];
};

/* Opens n tables, names[i] from cols[i] (which must outlive the set); meta(f, ctx) writes the shared
 * metadata lines into each. */
void table_set_open(struct table_set *ts, int n, const char *const *names, const struct column *const *cols,
                    void (*meta)(FILE *f, const void *ctx), const void *ctx);
/* One table, OUT/NAME, with metadata lines of its own: they go into the stream returned. */
FILE *table_set_open_one(struct table_set *ts, const char *name, const struct column *cols);
/* Writes every table into dir atomically (all are freed either way) and says so on stderr. False
 * with a message in err at the first failure. */
bool table_set_save(struct table_set *ts, const char *prog, const char *dir, char *err, size_t errlen);

/* Fills c[0..n-1]: columns named names[i], each a value of type (COL_STR, COL_I, COL_L or COL_D) at
 * off + i * stride in the row struct, printed with fmt. */
void table_columns(struct column *c, int n, const char *const *names, enum col_type type, size_t off, size_t stride,
                   const char *fmt);

#endif
