/* Output folders: mkdir -p with every failure reported. A folder that cannot be made is a bad path
 * from the user, found before any work is done, not an output that silently goes missing later. */
#ifndef OUTDIR_H
#define OUTDIR_H

#include <stdbool.h>
#include <stddef.h>

/* Makes dir and its missing parents (existing folders are fine); false with "cannot create D:
 * strerror" in err, D the first component that failed. */
bool outdir_make(const char *dir, char *err, size_t errlen);
/* outdir_make, or the error line "PROG: cannot create D: strerror" and exit status 2. */
void outdir_require(const char *prog, const char *dir);
/* The folder of a file path made (nothing for a bare file name); as outdir_make. */
bool outdir_make_parent(const char *file, char *err, size_t errlen);

#endif
