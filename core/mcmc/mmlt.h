/* Multiplexed MLT's state evaluation (MMLT paper §3.2, Eq. 17-20 and Alg. 2; thesis §3.8): a state
 * of path length k is a technique number u_tech (STREAM_TECHNIQUE) and the subpaths' numbers. The
 * technique is t = 1 + floor((k + 1) u_tech) camera vertices and s = k + 1 - t emitter vertices
 * (k + 1 techniques: a pinhole cannot be hit, so t = 0 is none), and the target is
 * (k + 1) w_t C_t of their one connection (Eq. 20, the factor k + 1 the uniform technique choice's
 * density). The state's path, in the form of its technique, is what PITP (pitp.h) perturbs and
 * MCTLS (mctls.h) hands on. */
#ifndef MMLT_H
#define MMLT_H

#include "path/connect.h"
#include "path/splat.h"
#include "sampler/sampler.h"

/* An MMLT state's path in the form of its technique: t camera vertices, s = k + 1 - t emitter
 * vertices and ratios[j] = p_j / p_s for the techniques j = 0..k (j emitter vertices; 0 where j
 * cannot produce the path). */
struct mmlt_path {
    int k, t, s;
    bool complete; /* mmlt_eval: both walks reached their full vertex counts */
    double ratios[MAX_PATH_LENGTH + 2];
    struct vertex cam[MAX_SUBPATH_VERTS], emi[MAX_SUBPATH_VERTS];
};

/* The technique (camera vertex count t = 1..k+1) that technique number u in [0, 1) selects. */
static inline int mmlt_technique(int k, double u)
{
    int t = 1 + (int)((k + 1) * u);
    return t > k + 1 ? k + 1 : t;
}

/* The inverse (thesis Eq. 5.6): a uniform point of t's interval [(t - 1) / (k + 1), t / (k + 1)),
 * xi uniform in [0, 1), nudged so that floor((k + 1) u) gives t back in floating point (the bounds,
 * rounded in double and multiplied by k + 1, can land on the neighbouring technique). Every place
 * that sets a state's technique number uses it. */
double mmlt_technique_number(int t, int k, double xi);

/* MMLT's state read from sampler s: the technique, the subpaths and their connection (weight among
 * the techniques 0..k). False when it yields no contribution. */
bool mmlt_eval(const struct path_ctx *pc, struct sampler *s, int k, struct mmlt_path *x, struct connection *c);

/* A connection's share of the target of a length-k state: (k + 1) w_t C_t (Eq. 20). */
static inline rgb mmlt_contribution(const struct connection *c, int k) { return vscale(c->f, c->w * (k + 1)); }

/* The state as the chains use it: mmlt_eval, its splat (none without a contribution; a non-finite
 * one is dropped and counted in nf->len[k]) into out, and the scalar target (its luminance; 0 for
 * none). */
double mmlt_eval_state(const struct path_ctx *pc, struct sampler *s, int k, struct mmlt_path *x, struct splat_list *out,
                       struct nonfinite *nf);
/* The same with keep's emitter subpath copied instead of walked when the state's technique has as
 * many emitter vertices: a proposal that keeps the numbers that walk reads (a fused perturbation
 * that moves only camera-side vertices, core/mcmc/fused.c), whose walk would give those vertices
 * bit for bit. keep NULL: mmlt_eval_state. */
double mmlt_eval_state_keep(const struct path_ctx *pc, struct sampler *s, int k, const struct mmlt_path *keep,
                            struct mmlt_path *x, struct splat_list *out, struct nonfinite *nf);

#endif
