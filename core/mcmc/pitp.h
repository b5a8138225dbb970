/* The path-invariant technique perturbation (thesis §5.2, Eq. 5.15-5.25): before each small step,
 * an MMLT chain in state (i, u) with path x = S_i(u) picks a technique j with probability w_j(x)
 * (sampled from the density ratios p_j / p_i the connection already computed: Eq. 5.22-5.25) and
 * moves to (j, v) with S_j(v) = x, always accepted (Eq. 5.20). The path, hence the target
 * (k + 1) w_j f / p_j = (k + 1) f / sum_l p_l (balance heuristic), does not change.
 *
 * Optimised inversion (§5.2.2): the truncated subpath keeps its numbers; the extended subpath keeps
 * its own and inverts only the |j - i| blocks that produce the vertices it gains, each followed by
 * one forward step with those numbers that must reach the vertex it inverted toward (a retrace).
 * A move whose inversion or retrace fails, or whose reverse move (j -> i from the new state) would
 * fail, is rejected: docs/pitp.md argues detailed balance. Numbers the new technique no longer
 * uses are made fresh (uniform), as the reversible-jump pairing of unused dimensions requires.
 *
 * The state's path is MMLT's (struct mmlt_path, mmlt.h), kept in its technique's form by the chain. */
#ifndef PITP_H
#define PITP_H

#include "mcmc/mmlt.h"
#include "sampler/pss.h"

/* Per-thread scratch of the perturbation (no allocation in the chain loop). */
struct pitp_scratch {
    const struct vertex *tgt[MAX_SUBPATH_VERTS]; /* the vertices an extension must reach, in order */
    struct vertex rev[MAX_SUBPATH_VERTS], save[2];
    double ratios[MAX_PATH_LENGTH + 2];
    double tol; /* retrace tolerance: 1e-4 of the scene's size, as the inverse-walk tests use */
};
void pitp_scratch_init(struct pitp_scratch *w, const struct scene *sc);

/* PITP_REJECTED: a path refracting between the two connections, rejected by min(1, f_j / f_i);
 * PITP_FAILED: an inversion or retrace (forward or reverse) failed. */
enum pitp_outcome { PITP_SAME, PITP_MOVED, PITP_REJECTED, PITP_FAILED };

/* One technique perturbation of the chain state (pss, x): u_pick chooses j in proportion to
 * x->ratios; fresh numbers of discrete inversions come from pss's own stream. On
 * PITP_MOVED the current numbers of pss and x (now in j's form) describe (j, v); otherwise both are
 * unchanged. *j_out receives the technique chosen (emitter vertex count), *a the acceptance
 * probability. When the target was re-evaluated (*conn_new set true), *conn holds the new state's
 * connection (its target is (k + 1) w f of it), which the caller's splats must then use. A
 * re-evaluated target that is NaN or infinite fails the move and is counted in nf->len[k]. */
enum pitp_outcome pitp_perturb(const struct path_ctx *ctx, struct pss_sampler *pss, struct mmlt_path *x,
                               struct pitp_scratch *scratch, double u_pick, int *j_out, double *a,
                               struct connection *conn, bool *conn_new, struct nonfinite *nf);

/* Whether the path's target can change with its technique (a refracting or delta vertex: pitp.c);
 * on the other paths the stationary law of the technique given the path is w(x). */
bool pitp_target_may_change(const struct mmlt_path *x);

#endif
