/* The metadata lines of the tools' CSV files: "# KEY VALUE", one per line, before the header row.
 * Every tool writes them through these, so that their form is the same everywhere. */
#ifndef CSV_META_H
#define CSV_META_H

#include <stdio.h>

/* "# KEY VALUE\n", VALUE printf-formatted; with key NULL "# VALUE\n" (a title or a note). */
void csv_meta(FILE *f, const char *key, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* "# commit C\n": the commit this build was made from. */
void csv_meta_commit(FILE *f);
/* What the figure tools' CSV files open with: "# TITLE" (title not NULL), "# scene S", the commit,
 * "# scale S". */
void csv_meta_head(FILE *f, const char *title, const char *scene, const char *scale);

#endif
