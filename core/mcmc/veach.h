/* Veach's MLT (Veach & Guibas 1997; core/mcmc/docs/veach.md): each chain keeps a path in path space
 * and changes it with path-space mutations (veach_bidir.c: the bidirectional mutation), accepted
 * with the path-space densities of the move. The chains start from PSSMLT's seed pool and share its
 * normalisation (veach.c). */
#ifndef VEACH_H
#define VEACH_H

#include "mcmc/mutation.h"

/* A chain's path x[0] (on an emitter) .. x[k] (the camera vertex), in the form of the connection
 * (s, k + 1 - s) it was last evaluated at: its contribution there in radiance mode (C_s times the
 * refraction factors of the emitter subpath's vertices, path.h's vertex_radiance_factor: what the
 * camera measures, whichever side sampled a refracting vertex), raster position, and the density
 * ratios p_j / p_s of every technique j = 0..k of the path (connect_st's). The vertices' delta flags
 * are the path's: a delta vertex scatters through a delta lobe toward both neighbours. */
struct veach_state {
    int k, s;
    rgb f;
    double px, py;
    double ratios[MAX_PATH_LENGTH + 2];
    struct vertex x[MAX_SUBPATH_VERTS];
};

/* A worker's scratch for a proposal (allocated with the worker: the chain loop allocates nothing):
 * the proposal y and its subpaths; the current path re-evaluated at another split, and its subpaths. */
struct veach_scratch {
    struct veach_state y, xm;
    struct vertex ys[MAX_SUBPATH_VERTS], zs[MAX_SUBPATH_VERTS], xs[MAX_SUBPATH_VERTS], xz[MAX_SUBPATH_VERTS];
};

/* The mutations, each one iteration of chain c in state x (veach_bidir.c, veach_lens.c,
 * veach_caustic.c); the entry in the registry (veach.c) picks one per iteration: the lens
 * perturbation with probability mlt_opts.veach_lens, the caustic perturbation with
 * mlt_opts.veach_caustic, the lens subpath mutation with mlt_opts.veach_lens_subpath, the
 * multi-chain perturbation with mlt_opts.veach_multichain, else the bidirectional mutation. */
void veach_bidir_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start);
void veach_lens_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start);
void veach_lens_subpath_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start);
void veach_multichain_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start);
void veach_caustic_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start);
/* lum F_j(x): x's contribution over the density of split j (j emitter vertices), from the state's
 * own connection when it is at j, else from x's forms connected at j (into w's x scratch); 0 when
 * the split cannot connect x. */
double veach_f_at(const struct path_ctx *pc, const struct veach_state *x, int j, struct veach_scratch *w);
/* The lens and caustic perturbations' x_m (veach_lens.c, veach_caustic.c), or -1 when x is not a
 * path they move. */
int veach_lens_vertex(const struct veach_state *x);
int veach_caustic_vertex(const struct veach_state *x);
/* The perturbations themselves (of x at that m), with the generator r: the perturbed path's
 * vertices x'_0..x'_k into yp (pointing into x and w: the lens perturbation's camera subpath w->zs,
 * t = k + 1 - m vertices; the caustic one's emitter subpath w->ys, k vertices), false when it leaves
 * the film or does not keep x's structure. Not connected: Veach's steps connect y at the split
 * their acceptance needs (m, k), the fused perturbations (fused.c) invert it. *p_old, *p_new: x_m's
 * densities of sampling the old and the new direction. */
bool veach_lens_perturb(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m, struct veach_scratch *w,
                        const struct vertex **yp);
bool veach_caustic_perturb(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m,
                           struct veach_scratch *w, double *p_old, double *p_new, const struct vertex **yp);
/* Veach's multi-chain perturbation (veach_multichain.c): x_m as veach_multichain_vertex gives it,
 * the perturbed path into yp (its camera subpath w->zs, k + 1 - m vertices) and *ratio, the product
 * over the perturbed intermediate vertices of their densities of sampling the new direction over
 * the old one (the caustic perturbation's p(omega') / p(omega), once per chain). */
int veach_multichain_vertex(const struct veach_state *x);
bool veach_multichain_perturb(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m,
                              struct veach_scratch *w, double *ratio, const struct vertex **yp);
/* The pieces the perturbations share: the lens perturbation's raster offset (veach_lens.c), x's
 * camera subpath traced anew through (px, py) to x'_m, as many delta vertices between, into yp
 * (the camera subpath in w->zs); the caustic perturbation's turn of a direction (density in
 * proportion to 1/theta on [1e-4, 0.1] rad, uniform azimuth: symmetric; veach_caustic.c). */
void veach_lens_offset(const struct camera *cam, rng *r, const struct veach_state *x, double *px, double *py);
bool veach_lens_trace(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m, struct veach_scratch *w,
                      double px, double py, const struct vertex **yp);
vec3 veach_turn(vec3 w, rng *r);
/* The caustic and multi-chain perturbations' common move: from v[n - 1], leave along omega turned
 * (veach_turn), then walk on with fresh numbers from r through delta vertices only to v[to - 1];
 * *p_new: the density of the turned direction. False when the walk ends elsewhere. */
bool veach_leave_turned(const struct path_ctx *pc, rng *r, struct vertex *v, int n, vec3 omega, int to,
                        enum transport mode, int stream, double *p_new);
/* A proposal's end (the proposal in wk->veach->y when made): its expected-value splats, the draw
 * against acceptance a, the move, and its statistics row of `kind` (failed: refused). */
void veach_decide(struct worker *wk, struct chain *c, struct veach_state *x, int kind, bool made, bool refused,
                  double a, double t_start);

/* The state of connection (s, t) of subpaths y (s vertices) and z (t vertices): false when it has
 * no finite, positive contribution. */
bool veach_state_set(struct veach_state *st, const struct path_ctx *pc, const struct vertex *y, int s,
                     const struct vertex *z, int t);
/* Refraction factors that turn a connection's contribution at s into radiance mode. */
double veach_radiance_factor(const struct vertex *const *x, int s);
/* The state's splat and target into the chain (c->cur, c->f) after the old state is paid for. */
void veach_move_to(struct chain *c, const struct veach_state *st);

/* A chain's state in and out of a checkpoint (the mutation entry's save and load; state NULL: the
 * run is not Veach's). Load checks the length that indexes the arrays: a crafted file is refused,
 * not written through. */
void veach_state_save(struct ckpt_buf *b, const struct scene *sc, const struct chain *c, const void *state);
bool veach_state_load(struct ckpt_buf *b, const struct scene *sc, struct chain *c, void *state);

/* Starts chain c from the seed sample chain_start just evaluated (its subpaths in wk->scratch): one
 * of its connections drawn in proportion to its MIS-weighted luminance, which with the seed drawn
 * in proportion to its target (the sum of those) draws every path in proportion to w_j C_j: an
 * importance resampling whose weight is PSSMLT's b (docs/veach.md, "Start and normalisation"). */
void veach_chain_start(struct worker *wk, struct chain *c);

#endif
