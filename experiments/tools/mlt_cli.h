/* bin/render's side of the MCMC option descriptors (core/mcmc/mlt_options.h): its option entries
 * and --help lines, the warnings for options the chosen method does not read, and the options'
 * lines in PREFIX.csv. */
#ifndef MLT_CLI_H
#define MLT_CLI_H

#include "common/opts.h"
#include "mcmc/mlt_options.h"

/* One struct opt per descriptor with a command-line name, writing into m; tag is the descriptor's
 * APPLIES_ bits. Returns how many (at most max). */
size_t mlt_cli_opts(struct mlt_opts *m, struct opt *out, size_t max);
/* One warning line per argument whose entry's tag (APPLIES_ bits; 0: every method) leaves out method. */
void mlt_cli_warn_unused(const struct opts_spec *spec, const char *method, int argc, char **argv);
/* The CSV lines of a descriptor group, "# KEY VALUE". */
void mlt_cli_csv(FILE *f, const struct mlt_opts *m, enum mlt_csv_group g);

#endif
