/* Mixing diagnostics of a run's Markov chains, per path length and over all (render's
 * PREFIX.mixing.csv; what each number means and how to read it: core/mcmc/docs/outputs.md).
 *
 * From the chains' records (stats/chain_trace.h), grouped by path length (PSSMLT: one group of
 * every thread's chain over all lengths):
 * - R-hat (stats/chain_rhat.h) of the two traced quantities, the chains' traces first brought to one
 *   thinning stride and length (the largest stride among them; the shortest trace);
 * - ESS, bulk as Stan's (rank-normalised split chains, stats/chain_ess.h), the smaller of the two
 *   quantities', in effective draws; per chain the same on the chain alone, the smallest; tau, the
 *   integrated autocorrelation time in chain iterations: iterations traced / ESS. A trace thinned
 *   to stride s cannot see correlation shorter than s: then tau reads about s and the ESS the draws
 *   held (both conservative);
 * - the longest run of iterations that left a chain's state unchanged, exact over every iteration;
 *   a chain is "stuck" when that run exceeds all of: 1 % of its iterations (one state then holds
 *   1 % of the chain's share of the image: a visible splotch); the run that independent rejections
 *   at its length's mean acceptance a would exceed anywhere in its n iterations with probability
 *   0.1 % (log(0.001 / (n a)) / log(1 - a); 0 when no chain of the length ever moved); and 100
 *   iterations (acceptance varies from state to state, which the independent-rejection run
 *   ignores: short chains show runs of a few tens at ordinary states of low acceptance);
 * - start-up: the first 1 % of each chain's traced contribution against the rest, the difference
 *   over its standard error sqrt(var tau_c (1/n1 + 1/n2)) (tau_c the chain's own, in draws),
 *   combined over the chains as sum z_c / sqrt(chains) (Stouffer), a z-score under no start-up
 *   bias. */
#ifndef MIXING_H
#define MIXING_H

#include "stats/chain_trace.h"
#include <stdio.h>

enum mixing_warning {
    MIXING_RHAT = 1,  /* R-hat of either quantity above MIXING_RHAT_MAX (or infinite) */
    MIXING_ESS = 2,   /* ESS under MIXING_ESS_MIN (or not computable: under 4 draws per chain) */
    MIXING_STUCK = 4, /* a chain stuck */
};
#define MIXING_RHAT_MAX 1.01
#define MIXING_ESS_MIN 100.0
#define MIXING_STUCK_MIN 100.0 /* iterations: the shortest run that can count as stuck */

struct mixing_row {
    int k;               /* path length, 0 for PSSMLT's chains over all lengths, -1 for the "all" row */
    int chains;          /* chains that ran at least one iteration */
    long draws;          /* their iterations */
    long thin;           /* the common thinning stride of the traces (the all row: the largest) */
    double rhat_contrib; /* NaN when every value is equal */
    double rhat_target;
    double ess_total, ess_chain_min, tau;
    long longest_max; /* the longest run of unchanged iterations over the chains */
    double stuck_share;
    double startup_z;
    unsigned warn; /* enum mixing_warning bits */
};

/* The rows of the n records t: one per length present (ascending), then the "all" row, which takes
 * the largest R-hat and tau, the smallest ESS per chain, the summed ESS, and stuck share and
 * start-up z over every chain. For a single group (PSSMLT) only the all row. Returns the count
 * (at most max, which must hold every length present plus one). */
int mixing_rows(const struct chain_trace *t, int n, struct mixing_row *rows, int max);
/* The CSV header and rows (after the caller's metadata lines). */
void mixing_write_csv(FILE *f, const struct mixing_row *rows, int n);
/* The same rows for a table of several runs: the header, "run," before the columns above and
 * ",seconds,ess_per_s" after them (ess_total over the run's seconds; NaN when untimed); and one
 * run's rows. */
void mixing_runs_header(FILE *f);
void mixing_write_run(FILE *f, const char *run, const struct mixing_row *rows, int n, double seconds);
/* One line for the run's summary ("R-hat 1.05 at lengths 3, 4; ..."), or false when no row warns. */
bool mixing_warning_line(const struct mixing_row *rows, int n, char *buf, size_t len);

#endif
