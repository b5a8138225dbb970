/* Controlled small steps (thesis §5.3, Alg. 3-4, Eq. 5.26-5.37): the invert-perturb-sample pattern
 * at every vertex of the proposal, and the four points per vertex that its acceptance ratio needs
 * (see controlled_step.h). */
#include "mcmc/controlled_step.h"
#include <string.h>

void ctrl_path_capture(struct ctrl_path *cp, const struct vertex *cam, int t, const struct vertex *emi, int s)
{
    cp->t = t;
    cp->s = s;
    memcpy(cp->cam, cam, (size_t)t * sizeof *cam);
    memcpy(cp->emi, emi, (size_t)s * sizeof *emi);
}

double ctrl_log_phi(double a, double b, double sigma)
{
    double d = b - a;
    d -= floor(d + 0.5); /* nearest representative in [-1/2, 1/2] */
    /* the three nearest windings; farther ones are below 1e-300 of these for sigma <= 1/8 */
    double e0 = -d * d, e1 = -(d - 1) * (d - 1), e2 = -(d + 1) * (d + 1), inv = 1 / (2 * sigma * sigma);
    double sum = 1 + exp((e1 - e0) * inv) + exp((e2 - e0) * inv);
    return e0 * inv + log(sum) - log(sigma * sqrt(2 * M_PI));
}

/* A delta-only BSDF reaches w only by chance: the direction inverted is that of its lobe nearest w
 * on w's side of the surface. Its lobes are found by sampling with extreme numbers, low or high in
 * each of the first three dimensions, which choose the lobe at each level of nesting: a
 * transparency over a dielectric has two lobes on the far side (straight through and refracted),
 * and all-low or all-high numbers reach only one of them. */
static bool delta_lobe_dir(const struct bsdf_ctx *bc, vec3 wi, vec3 w, vec3 *out)
{
    int k = bc->b->dims < 3 ? bc->b->dims : 3;
    double best = -2;
    for (int m = 0; m < 1 << k; m++) {
        double probe[SAMPLER_BLOCK];
        for (int d = 0; d < SAMPLER_BLOCK; d++)
            probe[d] = (m >> (d < k ? d : k - 1)) & 1 ? 0x1.fffffffffffffp-1 : 0.0;
        struct sampler_block in;
        sampler_block_init(&in, probe, NULL);
        struct bsdf_sample bs;
        if (bsdf_sample(bc, wi, &in.base, TRANSPORT_RADIANCE, &bs) && (bs.wo.z > 0) == (w.z > 0) &&
            vdot(bs.wo, w) > best) {
            best = vdot(bs.wo, w);
            *out = bs.wo;
        }
    }
    return best > -2;
}

/* The numbers (*n of them) with which vertex v, entered along v->wi, scatters toward world
 * direction wo. False when wo is outside the support of v's BSDF. The inversion's fresh numbers
 * (the auxiliary xi of the header) come from the chain's generator r, so a run stays reproducible
 * from its seed. */
static bool invert_at(const struct vertex *v, vec3 wo, rng *r, double *u, int *n)
{
    *n = 0;
    if (!v->bc.b) return false;
    const struct bsdf_ops *ops = bsdf_ops_for(v->bc.b->type);
    if (v->bc.b->dims == 0) return true; /* a mirror draws nothing: the empty vector is its only point */
    vec3 wi = frame_to_local(&v->sh, v->wi), wl = frame_to_local(&v->sh, wo);
    if (v->bc.b->delta_only && !delta_lobe_dir(&v->bc, wi, wl, &wl)) return false;
    struct sampler_block out;
    sampler_block_init(&out, u, r);
    return ops->invert(&v->bc, wi, wl, &out.base) && (*n = out.n, true);
}

static void subpath(const struct ctrl_path *cp, int st, const struct vertex **x, int *n)
{
    *x = st == STREAM_CAMERA ? cp->cam : cp->emi;
    *n = st == STREAM_CAMERA ? cp->t : cp->s;
}

/* Block i >= 1 of the proposal, when the walk reaches y_i (its vertex i is set before it reads
 * the block, path_walk.c): u'_i, then v_i, written into the state. */
static void build_block(struct ctrl_sampler *cs, int st, int i)
{
    struct ctrl_block *b = &cs->blk[st][i];
    const struct vertex *x;
    int n;
    subpath(cs->cur, st, &x, &n);
    b->nv = 0;
    if (i + 1 >= n ||
        !invert_at(&cs->prop[st][i], edge_dir(&x[i], &x[i + 1], &(double){0}), &cs->pss->r, b->up, &b->nv)) {
        cs->fail = CTRL_FAIL_FORWARD;
        return;
    }
    for (int d = 0; d < b->nv; d++) {
        /* the chain's kernel is the Gaussian here (mlt_render checks), so this is one step of phi */
        b->v[d] = cs->kind == SMALL_STEP_ROOT ? b->up[d] : pss_small_step(cs->pss, DIM_CONTINUOUS, b->up[d]);
        if (cs->kind != SMALL_STEP_ROOT) cs->log_fwd += ctrl_log_phi(b->up[d], b->v[d], cs->sigma);
        pss_set(cs->pss, st, i * SAMPLER_BLOCK + d, b->v[d]);
    }
}

static double ctrl_next(struct sampler *s, enum dim_kind kind)
{
    struct ctrl_sampler *cs = (struct ctrl_sampler *)s;
    int st = s->stream, i = s->vertex;
    /* the technique number is kept; the root's numbers take the ordinary lazy small step (Alg. 4
     * line 1), symmetric, so that its density cancels */
    if (st == STREAM_TECHNIQUE) return pss_current(cs->pss, st, 0);
    if (i == 0) return pss_read(cs->pss, st, sampler_index(s), kind);
    if (s->offset == 0 && cs->fail == CTRL_OK) build_block(cs, st, i);
    if (cs->fail != CTRL_OK || s->offset >= cs->blk[st][i].nv) {
        cs->fail = CTRL_FAIL_FORWARD; /* the walk goes on with a dummy number; the proposal is void */
        return 0.5;
    }
    return cs->blk[st][i].v[s->offset];
}
static const struct sampler_ops ctrl_ops = {ctrl_next, NULL, NULL};

void ctrl_begin(struct ctrl_sampler *cs, struct pss_sampler *p, const struct ctrl_path *cur, const struct vertex *cam,
                const struct vertex *emi, enum small_step kind)
{
    cs->base = (struct sampler){&ctrl_ops, 0, 0, 0};
    cs->pss = p;
    cs->cur = cur;
    cs->prop[STREAM_CAMERA] = cam;
    cs->prop[STREAM_EMITTER] = emi;
    cs->kind = kind;
    cs->sigma = p->o.sigma;
    cs->fail = CTRL_OK;
    cs->log_fwd = 0;
    for (int st = STREAM_CAMERA; st <= STREAM_EMITTER; st++) {
        /* u_i of every later scattering vertex, before the proposal overwrites them */
        const struct vertex *x;
        int n;
        subpath(cur, st, &x, &n);
        for (int i = 1; i + 1 < n; i++) {
            struct ctrl_block *b = &cs->blk[st][i];
            b->nu = x[i].bc.b ? x[i].bc.b->dims : 0;
            for (int d = 0; d < b->nu; d++)
                b->u[d] = pss_current(p, st, i * SAMPLER_BLOCK + d);
        }
    }
}

double ctrl_finish(struct ctrl_sampler *cs, bool complete)
{
    if (cs->fail != CTRL_OK || !complete) return 0;
    if (cs->kind == SMALL_STEP_ROOT) return 1;
    double log_rev = 0;
    for (int st = STREAM_CAMERA; st <= STREAM_EMITTER; st++) {
        const struct vertex *x, *y = cs->prop[st];
        int n;
        subpath(cs->cur, st, &x, &n);
        for (int i = 1; i + 1 < n; i++) {
            struct ctrl_block *b = &cs->blk[st][i];
            int nvp;
            /* Alg. 4 line 14: the proposal's direction inverted at the current path's vertex */
            if (!invert_at(&x[i], edge_dir(&y[i], &y[i + 1], &(double){0}), &cs->pss->r, b->vp, &nvp) || nvp != b->nu) {
                cs->fail = CTRL_FAIL_REVERSE;
                return 0;
            }
            for (int d = 0; d < nvp; d++)
                log_rev += ctrl_log_phi(b->vp[d], b->u[d], cs->sigma);
        }
    }
    return exp(log_rev - cs->log_fwd);
}
