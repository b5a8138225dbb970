/* The mixing diagnostics (core/stats/mixing.h) of a figure's in-process MCMC runs: a table of their
 * own beside the figure's (OUT/NAME: the figure's metadata lines, then per run its rows per path
 * length and its `all` row, labelled by the run, with its seconds and ESS per second), and each
 * run's warning on stderr as bin/render prints it. The figure's other tables are left as they were,
 * so the checks that read them do not change. */
#ifndef MIXING_RUNS_H
#define MIXING_RUNS_H

#include "common/text_out.h"
#include "mcmc/mlt.h"
#include <stdbool.h>
#include <stddef.h>

struct mixing_runs {
    struct text_out out;
    const char *prog, *name; /* the tool (for the warning), the file's name in the output folder */
    bool started;            /* the header written */
};

/* Starts the table; its metadata lines go into the returned stream before the first run. */
FILE *mixing_runs_open(struct mixing_runs *m, const char *prog, const char *name);
/* Run r's rows, labelled run; seconds: the run's chain time for ESS per second (0: untimed). Warns
 * on stderr when a row does. */
void mixing_runs_add(struct mixing_runs *m, const char *run, const struct mlt_result *r, double seconds);
/* Writes DIR/NAME atomically and says so on stderr; false with a message in err. */
bool mixing_runs_save(struct mixing_runs *m, const char *dir, char *err, size_t errlen);

#endif
