/* Controlled small steps, thesis §5.3 (Alg. 3 and 4, Eq. 5.26-5.37), as a sampler that the MMLT
 * driver evaluates its proposal through, in place of the lazily mutated primary-sample-space state.
 *
 * The current state u traced the subpaths x (camera x_0..x_{t-1}, emitter x_0..x_{s-1}). For each
 * subpath the proposal v is built while the walk traces it (Alg. 4):
 *  - root (block 0): its numbers take the ordinary small step of sampler/pss.c when the walk reads
 *    them (lazy, as in MMLT; a symmetric kernel, so its density cancels);
 *  - block i >= 1, when the walk reaches the proposal's vertex y_i: u'_i = the numbers that make
 *    y_i scatter toward w'_i = dir(x_i -> x_{i+1}) (inversion at y_i with y_i's incoming
 *    direction), v_i = u'_i + one wrapped-Gaussian step (sigma = the chain's --sigma) on every
 *    number, and the walk samples w_i from v_i;
 *  - after the walk, v'_i = the numbers that make x_i scatter toward dir(y_i -> y_{i+1}).
 * T(u -> v) = prod_i phi(v_i - u'_i), T(v -> u) = prod_i phi(u_i - v'_i) over blocks i >= 1 (Eq.
 * 5.35-5.37), phi the wrapped Gaussian density of one step per number: the numbers are perturbed
 * once per proposal, explicitly, so the density is exact (no lazy compounding). The technique
 * number is kept: the path length and split stay those of the current state.
 *
 * Random numbers of the inversions (a uniform point of a discrete outcome's interval, Eq. 5.6-5.8,
 * the lobe picked in proportion to its pdf share, the free numbers of a lobe that ignores them) are
 * auxiliary variables xi, drawn afresh by the forward inversions (u'_i) and again by the reverse
 * ones (v'_i). The ratio is taken conditionally on them: pi(u) q(xi) q(xi') T(u->v | xi) min(1, R)
 * with R = pi(v) T(v->u | xi') / (pi(u) T(u->v | xi)) is symmetric under (u, xi) <-> (v, xi'), so
 * detailed balance holds after integrating xi and xi' out (docs/controlled_step.md).
 *
 * Impossible inversions: u'_i (w'_i outside the support of y_i's BSDF) ends the proposal
 * (`failed`; it stays at u, a self-loop that keeps detailed balance); v'_i makes T(v -> u) = 0 and
 * the proposal is rejected. Delta-only BSDFs: a mirror has no numbers (u'_i empty, always
 * possible); at a smooth dielectric the direction to invert is the one of the lobe on w'_i's side
 * (reflection or refraction at y_i itself), so only the lobe choice carries over.
 *
 * `--small-step root` (Alg. 3) is the same with v_i = u'_i: the proposal copies x's directions.
 * It has no density (a deterministic map), so its chain is for the angle-change analysis only. */
#ifndef CONTROLLED_STEP_H
#define CONTROLLED_STEP_H

#include "path/path.h"
#include "sampler/pss.h"

enum small_step { SMALL_STEP_PSS, SMALL_STEP_CONTROLLED, SMALL_STEP_ROOT };

/* The current state's subpaths, as traced when it was proposed. */
struct ctrl_path {
    int t, s; /* camera and emitter vertex counts; t = 0: none captured */
    struct vertex cam[MAX_SUBPATH_VERTS], emi[MAX_SUBPATH_VERTS];
};
void ctrl_path_capture(struct ctrl_path *cp, const struct vertex *cam, int t, const struct vertex *emi, int s);

/* The four points of each block i >= 1 (Eq. 5.35-5.37), kept for tests and diagnostics:
 * u = current numbers, up = u'_i, v = proposal, vp = v'_i; n* their counts. */
struct ctrl_block {
    double u[SAMPLER_BLOCK], up[SAMPLER_BLOCK], v[SAMPLER_BLOCK], vp[SAMPLER_BLOCK];
    int nu, nv;
};

enum ctrl_fail { CTRL_OK, CTRL_FAIL_FORWARD, CTRL_FAIL_REVERSE };

struct ctrl_sampler {
    struct sampler base;
    struct pss_sampler *pss;
    const struct ctrl_path *cur;
    const struct vertex *prop[2]; /* the walk's arrays: camera, emitter */
    enum small_step kind;
    double sigma;
    enum ctrl_fail fail;
    double log_fwd;                              /* log T(u -> v), blocks >= 1 */
    struct ctrl_block blk[2][MAX_SUBPATH_VERTS]; /* [stream][vertex] */
};

/* Starts a proposal from the current state (pss after pss_begin(p, false), cur its subpaths):
 * keeps the current numbers of the later blocks and binds the vertex arrays the walk will fill. */
void ctrl_begin(struct ctrl_sampler *cs, struct pss_sampler *p, const struct ctrl_path *cur, const struct vertex *cam,
                const struct vertex *emi, enum small_step kind);
/* After the walk traced the proposal into the bound arrays with `complete` subpaths (cur->t and
 * cur->s vertices): T(v -> u) / T(u -> v), or 0 when the proposal failed or cannot be reversed. */
double ctrl_finish(struct ctrl_sampler *cs, bool complete);

/* log of the wrapped Gaussian density of a step from a to b on [0, 1) (exposed for tests). */
double ctrl_log_phi(double a, double b, double sigma);

#endif
