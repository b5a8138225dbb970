/* CSV tables written from one column list. A table is an array of struct column (name, printf
 * format, where the value is); the header row is the names joined by commas and each row is every
 * column's format applied to its value, so a column is added, moved or renamed in one place and
 * the header can never disagree with the rows. Readers look columns up by name (csv_read.h).
 *
 *   struct row { const char *method; int seed; double relmse; };
 *   static const struct column cols[] = {
 *       COL_STRING(struct row, "method", method), COL_INT(struct row, "seed", "%d", seed),
 *       COL_DOUBLE(struct row, "relmse", "%.6g", relmse), {0}};
 *   struct table t;
 *   FILE *f = table_open(&t, cols);
 *   csv_meta(f, "scale", "%s", scale);        // metadata lines first
 *   table_row(&t, &(struct row){"mmlt", 1, 0.25});
 *   if (!table_save(&t, "out/runs.csv", err, sizeof err)) ...
 *
 * The whole file is built in memory and written atomically (text_out.h). */
#ifndef TABLE_H
#define TABLE_H

#include "common/text_out.h"
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

enum col_type {
    COL_END = 0, /* ends a column list */
    COL_STR,     /* a const char * member, printed with fmt (default "%s") */
    COL_I,       /* an int member */
    COL_L,       /* a long member */
    COL_D,       /* a double member */
    COL_GET,     /* get(row, arg): a double computed from the row */
};

struct column {
    const char *name; /* the header cell */
    const char *fmt;  /* printf format of one value ("%.6g"); NULL: "%s" */
    enum col_type type;
    size_t off; /* offsetof the member in the row struct (COL_STR, COL_I, COL_L, COL_D) */
    double (*get)(const void *row, int arg);
    int arg; /* passed to get: lets one getter serve a family of columns */
};

#define COL_STRING(T, name, m)                                                                                         \
    {                                                                                                                  \
        name, "%s", COL_STR, offsetof(T, m), NULL, 0                                                                   \
    }
#define COL_INT(T, name, fmt, m)                                                                                       \
    {                                                                                                                  \
        name, fmt, COL_I, offsetof(T, m), NULL, 0                                                                      \
    }
#define COL_LONG(T, name, fmt, m)                                                                                      \
    {                                                                                                                  \
        name, fmt, COL_L, offsetof(T, m), NULL, 0                                                                      \
    }
#define COL_DOUBLE(T, name, fmt, m)                                                                                    \
    {                                                                                                                  \
        name, fmt, COL_D, offsetof(T, m), NULL, 0                                                                      \
    }
#define COL_COMPUTED(name, fmt, fn, a)                                                                                 \
    {                                                                                                                  \
        name, fmt, COL_GET, 0, fn, a                                                                                   \
    }

struct table {
    struct text_out out;
    const struct column *cols; /* terminated by {0} */
    bool header_done;
};

/* Starts a table of cols (which must outlive it); returns the stream for the metadata lines
 * (csv_meta), which go before the first row. */
FILE *table_open(struct table *t, const struct column *cols);
/* The header row (written by the first table_row or by table_save when there is none). */
void table_header(struct table *t);
/* One row: every column's value from row, formatted by its fmt. */
void table_row(struct table *t, const void *row);
/* Writes the table to path atomically and frees it; false with a message in err. */
bool table_save(struct table *t, const char *path, char *err, size_t errlen);

/* The header and one row into f directly (for tests and tables printed elsewhere). */
void table_write_header(FILE *f, const struct column *cols);
void table_write_row(FILE *f, const struct column *cols, const void *row);

#endif
