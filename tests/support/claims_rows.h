/* Reading a claims.csv (experiments/common/claims.h) in tests: a row's verdict by its ID. */
#ifndef CLAIMS_ROWS_H
#define CLAIMS_ROWS_H

/* DIR/claims.csv's text (caller frees); the test fails if it cannot be read. */
char *claims_rows_read(const char *dir);
/* The verdict word ("holds", "contradicted", "undecided") of the first row whose ID (the first
 * field) is id and whose line contains has ("" for any), or NULL without such a row. */
const char *claims_rows_verdict(const char *csv, const char *id, const char *has);

#endif
