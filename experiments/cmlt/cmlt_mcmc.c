/* The six MCMC algorithms of CMLT §5; see cmlt_mcmc.h for the equations each one follows. */
#include "cmlt/cmlt_mcmc.h"
#include "base/parallel.h"
#include "base/rng.h"
#include "base/util.h"
#include "cmlt/cmlt_charts.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *const cmlt_algo_names[CMLT_NALGO] = {"PSS-MLT-1",   "PSS-MLT-2", "PSS-MLT-AVG",
                                                 "PSS-MLT-MIX", "CMLT-EPSM", "CMLT"};

void cmlt_config_default(struct cmlt_config *c)
{
    c->w = c->h = 128;
    c->n = 1u << 20;
    c->n_seed = c->n / 16;
    c->p_large = 0.1;
    c->s1 = 1.0 / 1024;
    c->s2 = 1.0 / 64;
    c->swap_every = 4;
}

double cmlt_swap_ratio(double pi_x1, double pj_x1, double pi_x2, double pj_x2)
{
    return (pi_x2 * pj_x1) / (pi_x1 * pj_x2);
}

double cmlt_epsm_ratio(double pi_x, double pi_y, double p_i_x, double p_i_y) { return (pi_y * p_i_x) / (pi_x * p_i_y); }

/* ---- primary-space kernel ---------------------------------------------------------------- */

#define KTAB 4096
struct kernel {
    double p_large;
    double mag[KTAB]; /* small-step magnitudes */
};

static void kernel_init(struct kernel *k, const struct cmlt_config *c)
{
    k->p_large = c->p_large;
    double L = log(c->s2 / c->s1);
    for (int i = 0; i < KTAB; i++)
        k->mag[i] = c->s2 * exp(-L * (i + 0.5) / KTAB);
}

static inline double u01(rng *r) { return rng_u32(r) * (1.0 / 4294967296.0); }

/* u' = K(u): symmetric in u, u'. */
static inline void kernel_propose(const struct kernel *k, rng *r, const double *u, double *up)
{
    if (u01(r) < k->p_large) {
        for (int d = 0; d < CMLT_DIMS; d++)
            up[d] = u01(r);
        return;
    }
    for (int d = 0; d < CMLT_DIMS; d++) {
        uint32_t b = rng_u32(r);
        double du = k->mag[b >> 20];
        double v = (b & 1u) ? u[d] + du : u[d] - du;
        if (v >= 1.0) v -= 1.0;
        if (v < 0.0) v += 1.0;
        if (v >= 1.0) v = 0.0; /* -tiny + 1 rounds to 1 */
        up[d] = v;
    }
}

/* ---- chains ------------------------------------------------------------------------------ */

enum target { TGT_EQ13, TGT_EQ15, TGT_PATH };

struct state {
    double u[CMLT_DIMS];
    struct cmlt_path x;
    struct cmlt_eval e;
    double pi;  /* target value */
    size_t pix; /* pixel offset (3 * index) */
};

struct chain {
    int chart; /* 1, 2; for TGT_PATH the chart of the next ephemeral step */
    enum target tgt;
    int mis;  /* weight samples by w_chart (PSS-MLT-AVG) */
    double b; /* normalisation (integral of the chain's target) */
    struct state cur;
    double wacc; /* expected-value weight accumulated on the current state */
};

struct ctx {
    int w, h;
    double *img;
    struct kernel k;
    rng r;
    struct cmlt_stats *st;
};

static inline double target_value(const struct chain *c, const struct cmlt_eval *e)
{
    if (!(e->fs > 0)) return 0;
    switch (c->tgt) {
    case TGT_EQ13:
        return e->fs / cmlt_chart_pdf(c->chart, e);
    case TGT_EQ15:
        return e->fs / (e->p1 + e->p2);
    default:
        return e->fs;
    }
}

static inline size_t pixel_of(const struct ctx *cx, const struct cmlt_path *x)
{
    int i = (int)(x->gx * cx->w), j = (int)((1.0 - x->gy) * cx->h);
    if (i >= cx->w) i = cx->w - 1;
    if (j >= cx->h) j = cx->h - 1;
    if (i < 0) i = 0;
    if (j < 0) j = 0;
    return 3 * ((size_t)j * cx->w + i);
}

/* Adds weight * (b f/f* [w_i]) to the pixel of s; the 1/N and pixel-area factors come at the end. */
static inline void splat(struct ctx *cx, const struct chain *c, const struct state *s, double weight)
{
    if (!(weight > 0) || !(s->e.fs > 0)) return;
    double k = weight * c->b / s->e.fs;
    if (c->mis) k *= cmlt_chart_pdf(c->chart, &s->e) / (s->e.p1 + s->e.p2);
    double *p = cx->img + s->pix;
    p[0] += k * s->e.f.x;
    p[1] += k * s->e.f.y;
    p[2] += k * s->e.f.z;
}

static inline void flush(struct ctx *cx, struct chain *c)
{
    splat(cx, c, &c->cur, c->wacc);
    c->wacc = 0;
}

/* Common accept/reject with expected-value splatting. */
static inline void mh_finish(struct ctx *cx, struct chain *c, struct state *prop, double a)
{
    cx->st->steps++;
    cx->st->acc_sum += a;
    if (a > 0) splat(cx, c, prop, a);
    c->wacc += 1.0 - a;
    if (a > 0 && (a >= 1.0 || u01(&cx->r) < a)) {
        flush(cx, c);
        c->cur = *prop;
        cx->st->accepted++;
    }
}

/* One primary-space step (Eq. 13 or Eq. 15 target, symmetric kernel): a = min(1, pi(u')/pi(u)). */
static inline void pss_step(struct ctx *cx, struct chain *c)
{
    struct state p;
    kernel_propose(&cx->k, &cx->r, c->cur.u, p.u);
    double a = 0;
    if (cmlt_chart_T(c->chart, p.u, &p.x)) {
        cmlt_eval(&p.x, &p.e);
        p.pi = target_value(c, &p.e);
        if (p.pi > 0) {
            p.pix = pixel_of(cx, &p.x);
            a = p.pi >= c->cur.pi ? 1.0 : p.pi / c->cur.pi;
        }
    }
    mh_finish(cx, c, &p, a);
}

/* One ephemeral primary-space perturbation through chart c->chart (Eq. 27/28), target f*. */
static inline void epsm_step(struct ctx *cx, struct chain *c)
{
    int i = c->chart;
    c->chart = 3 - i; /* alternate the charts */
    double u[CMLT_DIMS];
    struct state p;
    double a = 0;
    if (cmlt_chart_R(i, &c->cur.x, NULL, u)) { /* move down: u = R_i(x) */
        kernel_propose(&cx->k, &cx->r, u, p.u);
        if (cmlt_chart_T(i, p.u, &p.x)) { /* back up: y = T_i(u') */
            cmlt_eval(&p.x, &p.e);
            p.pi = p.e.fs;
            double py = cmlt_chart_pdf(i, &p.e);
            if (p.pi > 0 && py > 0) {
                p.pix = pixel_of(cx, &p.x);
                double r = cmlt_epsm_ratio(c->cur.pi, p.pi, cmlt_chart_pdf(i, &c->cur.e), py);
                a = r >= 1.0 ? 1.0 : r;
            }
        }
    }
    mh_finish(cx, c, &p, a);
}

/* Replica-exchange chart swap between chain A (chart 1) and chain B (chart 2), Eq. 22-25. */
static void swap_step(struct ctx *cx, struct chain *A, struct chain *B)
{
    const struct cmlt_eval *e1 = &A->cur.e, *e2 = &B->cur.e;
    double r = cmlt_swap_ratio(e1->p1, e1->p2, e2->p1, e2->p2);
    double a = r >= 1.0 ? 1.0 : r;
    cx->st->swaps++;
    cx->st->swap_acc_sum += a;
    if (!(a >= 1.0 || u01(&cx->r) < a)) return;
    struct state sa = B->cur, sb = A->cur; /* A gets x2, B gets x1 */
    if (!cmlt_chart_R(A->chart, &sa.x, NULL, sa.u) || !cmlt_chart_R(B->chart, &sb.x, NULL, sb.u)) return;
    flush(cx, A);
    flush(cx, B);
    /* Eq. 24: pi_1(R_1(x2)) = pi_2(u_2), so the target values carry over unchanged */
    A->cur = sa;
    B->cur = sb;
    cx->st->swaps_accepted++;
}

/* ---- seed pass ---------------------------------------------------------------------------- */

struct reservoir {
    double wsum;
    struct cmlt_path x;
    int have;
};

/* Resampling weight of a seed path for a chain: (chain's path-space target) / (mixture density of
 * the seed pass, (p1 + p2)/2), up to a constant. */
static double seed_weight(const struct chain *c, const struct cmlt_eval *e)
{
    double s = e->p1 + e->p2;
    if (c->tgt == TGT_EQ15) return e->fs * cmlt_chart_pdf(c->chart, e) / (s * s);
    return e->fs / s; /* Eq. 13 and path-space targets are f* in path space */
}

static void seed_pass(struct ctx *cx, struct chain *ch, int nch, uint64_t n_seed, double b[3])
{
    struct reservoir res[2];
    memset(res, 0, sizeof res);
    double acc[3] = {0, 0, 0};
    for (uint64_t k = 0; k < n_seed; k++) {
        for (int t = 1; t <= 2; t++) {
            double u[CMLT_DIMS];
            for (int d = 0; d < CMLT_DIMS; d++)
                u[d] = u01(&cx->r);
            struct cmlt_path x;
            if (!cmlt_chart_T(t, u, &x)) continue;
            struct cmlt_eval e;
            cmlt_eval(&x, &e);
            if (!(e.fs > 0)) continue;
            double s = e.p1 + e.p2;
            acc[0] += e.fs / s;
            acc[1] += e.fs * e.p1 / (s * s);
            acc[2] += e.fs * e.p2 / (s * s);
            for (int c = 0; c < nch; c++) {
                double w = seed_weight(&ch[c], &e);
                res[c].wsum += w;
                if (u01(&cx->r) * res[c].wsum < w) {
                    res[c].x = x;
                    res[c].have = 1;
                }
            }
        }
    }
    for (int i = 0; i < 3; i++)
        b[i] = acc[i] / (double)n_seed;
    for (int c = 0; c < nch; c++) {
        ASSERT(res[c].have); /* the seed pass found no light: n_seed far too small */
        struct state *s = &ch[c].cur;
        s->x = res[c].x;
        cmlt_eval(&s->x, &s->e);
        if (ch[c].tgt != TGT_PATH) ASSERT(cmlt_chart_R(ch[c].chart, &s->x, NULL, s->u));
        s->pi = target_value(&ch[c], &s->e);
        s->pix = pixel_of(cx, &s->x);
        ch[c].wacc = 0;
    }
}

/* ---- driver ------------------------------------------------------------------------------- */

#define BATCH 65536u

void cmlt_run(enum cmlt_algo a, const struct cmlt_config *cfg, uint64_t seed, uint64_t stream, double *img,
              struct cmlt_stats *st, struct progress *progress, const volatile sig_atomic_t *stop)
{
    double t0 = now_seconds();
    memset(st, 0, sizeof *st);
    struct ctx *cx = xmalloc(sizeof *cx);
    cx->w = cfg->w;
    cx->h = cfg->h;
    cx->img = img;
    cx->st = st;
    memset(img, 0, sizeof(double) * 3 * (size_t)cfg->w * cfg->h);
    kernel_init(&cx->k, cfg);
    rng_seed(&cx->r, seed, stream);

    struct chain ch[2];
    memset(ch, 0, sizeof ch);
    int nch = 2;
    switch (a) {
    case CMLT_PSS1:
        nch = 1;
        ch[0] = (struct chain){.chart = 1, .tgt = TGT_EQ13};
        break;
    case CMLT_PSS2:
        nch = 1;
        ch[0] = (struct chain){.chart = 2, .tgt = TGT_EQ13};
        break;
    case CMLT_EPSM:
        nch = 1;
        ch[0] = (struct chain){.chart = 1, .tgt = TGT_PATH};
        break;
    case CMLT_PSS_AVG:
        ch[0] = (struct chain){.chart = 1, .tgt = TGT_EQ13, .mis = 1};
        ch[1] = (struct chain){.chart = 2, .tgt = TGT_EQ13, .mis = 1};
        break;
    default: /* MIX and CMLT */
        ch[0] = (struct chain){.chart = 1, .tgt = TGT_EQ15};
        ch[1] = (struct chain){.chart = 2, .tgt = TGT_EQ15};
        break;
    }
    seed_pass(cx, ch, nch, cfg->n_seed, st->b);
    for (int c = 0; c < nch; c++)
        ch[c].b = ch[c].tgt == TGT_EQ15 ? st->b[ch[c].chart] : st->b[0];

    uint64_t per_chain = cfg->n / (uint64_t)nch, done = 0;
    int swap_every = cfg->swap_every > 0 ? cfg->swap_every : 4;
    while (done < per_chain) {
        uint64_t m = per_chain - done < BATCH ? per_chain - done : BATCH;
        if (a == CMLT_EPSM) {
            for (uint64_t it = 0; it < m; it++)
                epsm_step(cx, &ch[0]);
        } else if (nch == 1) {
            for (uint64_t it = 0; it < m; it++)
                pss_step(cx, &ch[0]);
        } else {
            for (uint64_t it = 0; it < m; it++) {
                pss_step(cx, &ch[0]);
                pss_step(cx, &ch[1]);
                if (a == CMLT_CMLT && (done + it + 1) % (uint64_t)swap_every == 0) swap_step(cx, &ch[0], &ch[1]);
            }
        }
        done += m;
        if (progress) progress_add(progress, (long)(m * (uint64_t)nch));
        if (stop && *stop) {
            st->partial = 1;
            break;
        }
    }
    for (int c = 0; c < nch; c++)
        flush(cx, &ch[c]);
    /* per-chain 1/N and the pixel area (ground area 1): image = W H / N_c sum of splats */
    double scale = done ? (double)cfg->w * cfg->h / (double)done : 0;
    for (size_t i = 0; i < 3 * (size_t)cfg->w * cfg->h; i++)
        img[i] *= scale;
    free(cx);
    st->seconds = now_seconds() - t0;
}
