/* Acceptance statistics keyed by (proposal kind, path length, technique changed), with batch-means
 * standard errors of the mean acceptance probability E[min(1, a)] (autocorrelation-aware). */
#ifndef MLT_STATS_H
#define MLT_STATS_H

#include "path/splat.h"
#include "sampler/sampler.h"
#include <stdbool.h>
#include <stdio.h>

/* PROPOSAL_PITP records PITP's technique perturbations (mcmc/pitp.c): "accepted" means carried
 * out; a is 1, or min(1, f_j / f_i) on paths refracting between the connections, and 0 for a
 * failed inversion or retrace (counted in `failed`); technique_changed is j != i. PROPOSAL_BIDIR
 * records Veach's bidirectional mutation (mcmc/veach_bidir.c) by the current path's length;
 * technique_changed: the path's length changed; failed: refused before a path was made (a kept end
 * that scatters through a delta lobe, no room for the added length) or an extension that stopped
 * short. PROPOSAL_LENS and PROPOSAL_CAUSTIC record Veach's lens and caustic perturbations
 * (mcmc/veach_lens.c, veach_caustic.c); failed: a path the perturbation does not move. The
 * PROPOSAL_FUSED_ kinds record the same perturbations fused into MMLT and PITP (mcmc/fused.c) by
 * the chain's length; failed: refused as Veach's are, or the perturbed path not invertible by the
 * chain's technique (an inversion or its retrace failed; those alone in fused_not_inverted).
 * PROPOSAL_LENS_SUBPATH records Veach's lens subpath mutation (veach_lens.c), failed as the lens
 * perturbation's, and PROPOSAL_MULTICHAIN its multi-chain perturbation (veach_multichain.c). */
enum proposal_kind {
    PROPOSAL_SMALL,
    PROPOSAL_LARGE,
    PROPOSAL_MCTLS,
    PROPOSAL_PITP,
    PROPOSAL_BIDIR,
    PROPOSAL_LENS,
    PROPOSAL_CAUSTIC,
    PROPOSAL_FUSED_LENS,
    PROPOSAL_FUSED_CAUSTIC,
    PROPOSAL_LENS_SUBPATH,
    PROPOSAL_MULTICHAIN,
    PROPOSAL_FUSED_MULTICHAIN,
    PROPOSAL_BUILTIN
};
/* Kinds PROPOSAL_BUILTIN.. are the mutations registered at run time (mcmc/mutation.h); a kind
 * without attempts writes no rows, so the CSV of a run without them is unchanged. */
#define PROPOSAL_KINDS (PROPOSAL_BUILTIN + 4)
#define STATS_LENGTHS (MAX_PATH_LENGTH + 1) /* index 0 = all lengths (PSSMLT states) */
#define STATS_BATCH 2048                    /* proposals per batch: long enough for chains stuck ~1/acceptance steps */

struct accept_cell {
    long attempts, accepted, nonzero;
    double sum_a;     /* sum of min(1, a) */
    double batch_sum; /* running batch */
    long batch_n;
    long nbatches;
    double bsum, bsum2; /* sums of batch means and their squares */
    long failed;        /* proposals that could not be constructed (PITP: inversion or retrace) */
    double sum_dtech;   /* sum of |t' - t|: how far proposals move the technique */
    double seconds;     /* time spent on these proposals (not in the CSV rows: they reproduce exactly) */
};

/* Every proposal is recorded three times, each cell a contiguous subsequence of the chain so that
 * batch means apply: by (kind, length, technique changed), by (kind, length), and by kind. */
/* Independent samples of a normalisation constant: the targets of the large steps' fresh numbers,
 * each an unbiased sample of b_k (MMLT paper §4), by chain length (index k; PSSMLT's b at 1). */
struct target_sum {
    double sum, sq;
    long n;
};

struct mlt_stats {
    struct accept_cell cell[PROPOSAL_KINDS][STATS_LENGTHS][2];
    struct accept_cell any[PROPOSAL_KINDS][STATS_LENGTHS];
    struct accept_cell total[PROPOSAL_KINDS];
    struct nonfinite nonfinite;    /* by length, as the rows (path/splat.h) */
    long conn_tried, conn_nonzero; /* connections the chains evaluated, and those with a contribution */
    /* fused perturbations (mcmc/fused.c) made with their new edge unoccluded, so inverted under the
     * chain's technique, and of those the ones whose inversion or retrace failed: the rows' `failed`
     * counts these with the refusals before inversion */
    long fused_inverted, fused_not_inverted;
    struct target_sum large[STATS_LENGTHS];
    /* progressive_norm only: iterations of each length's chains, and those spent at a state
     * without light (a length the seed pass missed starts there) */
    long iters[STATS_LENGTHS], zero_iters[STATS_LENGTHS];
};

void stats_clear(struct mlt_stats *s);
void stats_record(struct mlt_stats *s, enum proposal_kind kind, int length, bool technique_changed, double a,
                  bool accepted, bool nonzero, double seconds);
/* The same with the technique distance |t' - t| of the proposal and whether it failed to be
 * constructed (stats_record: 0 and false). */
void stats_record_dt(struct mlt_stats *s, enum proposal_kind kind, int length, bool technique_changed, int dtech,
                     bool failed, double a, bool accepted, bool nonzero, double seconds);
void target_sum_add(struct target_sum *t, double f);
/* Adds src into dst (threads are merged in a fixed order). */
void stats_merge(struct mlt_stats *dst, const struct mlt_stats *src);
/* One value into a cell's mean and batches (also for other per-proposal statistics, such as the
 * angle change of angle_change.h), and a cell added into another. */
void cell_add(struct accept_cell *c, double x);
void cell_merge(struct accept_cell *dst, const struct accept_cell *src);
/* Mean acceptance, its batch-means standard error (NAN with fewer than 2 batches). */
double cell_mean(const struct accept_cell *c);
double cell_stderr(const struct accept_cell *c);
/* CSV rows (core/mcmc/docs/outputs.md, "Statistics CSV"); header once when `header`. */
void stats_write_csv(FILE *f, const char *method, const struct mlt_stats *s, bool header);
const char *proposal_name(enum proposal_kind k);
/* A kind named `name` for a registered mutation: its index, or -1 when every kind is taken. */
int proposal_kind_add(const char *name);

#endif
