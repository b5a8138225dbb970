/* Reading the tools' CSV files by name: columns are found through the header row and metadata
 * through the key of their "# key value" line, never by position, so a column added in the middle
 * of a table shifts nothing for its readers. A missing column or key is an error naming the file
 * and what is missing. Cells are split at commas (the tools never quote). */
#ifndef CSV_READ_H
#define CSV_READ_H

#include <stdbool.h>
#include <stddef.h>

struct csv_file {
    char *name;  /* the path, for messages */
    char *text;  /* the file, cut in place into the strings below */
    int ncols;   /* header cells */
    char **head; /* [ncols] */
    int nrows;
    char **cells; /* [nrows * ncols] */
    int nmeta;
    char **meta_key, **meta_val; /* "# key value" lines in file order; value "" when there is none */
};

/* Reads and parses path; NULL with a message in err when it cannot be read, has no header row,
 * or a row has another number of cells than the header. */
struct csv_file *csv_load(const char *path, char *err, size_t errlen);
/* The same from text (taken over: freed by csv_free); name for messages. */
struct csv_file *csv_parse(char *text, const char *name, char *err, size_t errlen);
void csv_free(struct csv_file *c);

/* The index of column name; -1 with "NAME: no column 'name'" in err. */
int csv_column(const struct csv_file *c, const char *name, char *err, size_t errlen);
/* Row r's cell of column col (0 <= col < ncols). */
const char *csv_cell(const struct csv_file *c, int r, int col);
/* The cell as a number (strtod; nan when it is not one). */
double csv_number(const struct csv_file *c, int r, int col);

/* The value of the first "# key value" line; NULL when there is none. */
const char *csv_meta_text(const struct csv_file *c, const char *key);
/* Its leading number (strtod); nan when the line is missing: for keys a file may lack. */
double csv_meta_number(const struct csv_file *c, const char *key);
/* Its leading number; false with "NAME: no '# key' line" in err when the line is missing. */
bool csv_meta_require(const struct csv_file *c, const char *key, double *v, char *err, size_t errlen);

#endif
