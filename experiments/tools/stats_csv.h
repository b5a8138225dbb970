/* The statistics CSV files bin/check_stats compares (a baseline and a current run): rows of a mean
 * and its standard error (and optionally the number of runs behind it), matched by key columns.
 * CSV: a header row, comma-separated fields without quoting, lines starting with '#' ignored.
 * Read here rather than in the tool's main so that tests/fuzz/fuzz_stats_csv.c can reach it. */
#ifndef STATS_CSV_H
#define STATS_CSV_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define STATS_MAXCOL 64
#define STATS_MAXKEY 8
#define STATS_NAME 64   /* longest column name, with its NUL */
#define STATS_LINE 4096 /* longest line, with its newline and NUL */

struct stats_row {
    char key[256]; /* the key columns' fields joined by ',' */
    double mean, se, count;
};

struct stats_table {
    struct stats_row *rows;
    int n;
};

struct stats_cols {
    const char *key[STATS_MAXKEY];
    int nkeys;
    const char *mean, *se, *count; /* count: NULL when not wanted */
};

/* Every data row of the file `name` (for messages), or false with one line "NAME:LINE: what" in
 * err; t then holds nothing. */
bool stats_csv_read(FILE *f, const char *name, const struct stats_cols *cols, struct stats_table *t, char *err,
                    size_t errlen);
/* The header's first column name (check_stats' default key). */
bool stats_csv_first_column(FILE *f, const char *name, char out[STATS_NAME], char *err, size_t errlen);
void stats_table_free(struct stats_table *t);

#endif
