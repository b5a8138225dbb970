/* The worker thread's iteration loop and the dispatch of its proposals (MMLT paper Alg. 1-2; thesis
 * §3.7 step 3). One iteration: pick a chain (MMLT: a length k with probability P(k)), choose a large
 * step with probability p_large (MCTLS's, mctls.c, or fresh numbers) or a small step (under PITP
 * preceded by the technique perturbation, pitp.c), trace the proposal through the primary-sample-
 * space sampler or the controlled one (controlled_step.c), splat both states with expected values
 * (splat_ev.c) and accept with min(1, f(v) T(v->u) / (f(u) T(u->v))) (MMLT paper Eq. 17-20). */
#include "base/util.h"
#include "mcmc/mlt_internal.h"
#include "mcmc/splat_ev.h"
#include "mcmc/tech_split.h"
#include <stdlib.h>

/* A proposal evaluated: its target (0 after an impossible inversion), the kernel's ratio
 * T(v->u) / T(u->v), its technique and whether its subpaths are complete. */
struct proposal {
    double f, tr;
    int tech;
    bool complete;
};

static double elapsed(const struct mlt_opts *o, double t_start) { return o->time_proposals ? now_seconds() - t_start : 0; }

static void worker_init(struct worker *wk, struct run_job *j, int tid)
{
    const struct mlt_opts *o = j->o;
    *wk = (struct worker){.j = j, .o = o, .tid = tid, .g = j->g0 + tid};
    wk->pc = (struct path_ctx){.sc = j->sc, .max_length = o->max_length, .min_length = o->min_length, .max_heuristic = o->max_heuristic};
    wk->w = xmalloc(sizeof *wk->w);
    wk->w->nf = (struct nonfinite){{0}};
    wk->w->tech_k = 0; /* the MCMC methods split states by technique themselves (tech_split.h) */
    wk->ch = xcalloc((size_t)j->nk, sizeof *wk->ch);
    wk->mb = xmalloc(sizeof *wk->mb);
    wk->st = &j->stats[tid];
    wk->img = j->img[tid];
    wk->ta = j->tech ? &j->tech[tid] : NULL;
    wk->angle = j->angle ? &j->angle[tid] : NULL;
    wk->ctrl_fail = j->ctrl_fail[tid];
    wk->pitp = o->method == MLT_PITP;
    wk->multiplexed = o->method != MLT_PSSMLT;
    wk->spare = xmalloc(sizeof *wk->spare);
    wk->ps = wk->pitp ? xmalloc(sizeof *wk->ps) : NULL;
    if (wk->ps) pitp_scratch_init(wk->ps, j->sc);
    rng_seed(&wk->r, o->seed, 0x9E3779B97F4A7C15ULL + (uint64_t)wk->g); /* streams and budgets are the job's global thread's */
    wk->track = o->method != MLT_PSSMLT && (o->small_step != SMALL_STEP_PSS || o->angle_stats);
    wk->cs = o->small_step != SMALL_STEP_PSS ? xmalloc(sizeof *wk->cs) : NULL;
    wk->ts = (struct mlt_thread){wk->ch, j->nk, &wk->r, &wk->n, &wk->w->nf, wk->st, wk->ctrl_fail, wk->img, wk->angle, wk->ta};
}

/* Every chain from a seed sample (seed_pass.c), or set up for the state a checkpoint left it in. */
static void chains_start(struct worker *wk)
{
    const struct run_job *j = wk->j;
    for (int kk = 0; kk < j->nk; kk++) {
        struct chain *c = &wk->ch[kk];
        c->k = kk + 1;
        c->scale = j->scale[kk];
        c->dropped = &wk->w->nf.len[wk->multiplexed ? c->k : 0];
        if (!j->resume) {
            if (j->cdf[kk]) chain_start(wk, c, kk);
            continue;
        }
        if (!(c->scale > 0)) continue; /* a length without light: never started */
        pss_init(&c->pss, &wk->o->pss, wk->o->seed, 0);
        if (wk->pitp) c->x = xmalloc(sizeof *c->x);
        if (wk->track) c->path = xmalloc(sizeof *c->path);
    }
}

/* The chain of this iteration: MMLT's length k with probability P(k) (the job's kcdf). */
static struct chain *pick_chain(struct worker *wk)
{
    const struct run_job *j = wk->j;
    int kk = 0;
    if (j->nk > 1) {
        double u = rng_uniform(&wk->r) * j->kcdf[j->nk];
        while (kk < j->nk - 1 && j->kcdf[kk + 1] <= u) kk++;
    }
    return &wk->ch[kk];
}

/* PITP (pitp.h): the always-accepted technique perturbation, after which MMLT's small step starts
 * from the current path in the new technique's form. */
static void pitp_perturbation(struct worker *wk, struct chain *c)
{
    int sj;
    double pa;
    struct connection cn;
    bool c_new;
    enum pitp_outcome po = pitp_perturb(&wk->pc, &c->pss, c->x, wk->ps, rng_uniform(&wk->r), &sj, &pa, &cn, &c_new, &wk->w->nf);
    int dt = abs(sj - c->x->s);
    if (po == PITP_MOVED) {
        dt = abs(c->k + 1 - sj - c->tech);
        c->tech = c->x->t;
        c->xsum_valid = false;
        /* controlled steps start from the current path in the new technique's form */
        if (wk->track) ctrl_path_capture(c->path, c->x->cam, c->x->t, c->x->emi, c->x->s);
        if (c_new) {
            /* the target changed with the technique (refraction, delta vertices): the state's
             * splat and target follow */
            struct splat_list l;
            l.n = 0;
            splat_push(&l, cn.px, cn.py, mmlt_contribution(&cn, c->k));
            move_to(wk->img, c, &l, splat_luminance(&l));
        }
    }
    stats_record_dt(wk->st, PROPOSAL_PITP, c->k, dt != 0, dt, po == PITP_FAILED, pa, po == PITP_SAME || po == PITP_MOVED,
                    true, 0);
}

/* A small step's proposal, or a large step of fresh numbers, traced into the worker's scratch. The
 * one dispatch point of the small-step kind: a controlled or root step traces the proposal
 * through the controlled sampler, which also yields the kernel's ratio T(v->u) / T(u->v); the
 * lazy primary-sample-space step's is 1. */
/* The connections the last evaluations counted in the scratch, into the thread's statistics (which
 * the checkpoint holds; the scratch is not). */
static void take_connections(struct worker *wk)
{
    wk->st->conn_tried += wk->w->conn_tried;
    wk->st->conn_nonzero += wk->w->conn_nonzero;
    wk->w->conn_tried = wk->w->conn_nonzero = 0;
}

static void propose(struct worker *wk, struct chain *c, bool large, struct proposal *pr)
{
    const struct mlt_opts *o = wk->o;
    struct ctrl_sampler *cs = large ? NULL : wk->cs;
    pss_begin(&c->pss, large);
    if (cs) ctrl_begin(cs, &c->pss, c->path, wk->spare->cam, wk->spare->emi, o->small_step);
    wk->w->conn_tried = wk->w->conn_nonzero = 0; /* the chain starts' and seed pass's are not counted */
    pr->f = eval_state(o->method, &wk->pc, cs ? &cs->base : &c->pss.base, wk->w, c->k, wk->spare, &wk->prop, &pr->tech,
                       &pr->complete);
    take_connections(wk);
    if (wk->ta) tech_split_record(wk->ta, &wk->pc, wk->w, wk->multiplexed ? c->k : 0, pr->tech, &wk->prop, false);
    pr->tr = cs ? ctrl_finish(cs, pr->complete) : 1;
    if (cs && cs->fail != CTRL_OK) wk->ctrl_fail[cs->fail - 1]++;
    if (o->ctrl_unit_ratio && pr->tr > 0) pr->tr = 1;
    if (pr->tr == 0) pr->f = 0; /* an impossible inversion: nothing this proposal could splat */
}

/* Angle statistics of a small step (stats/angle_change.h): the proposal's subpaths against the
 * current ones, when they are of the same split. */
static void record_angle(struct worker *wk, const struct chain *c, const struct proposal *pr)
{
    const struct ctrl_path *cur = c->path;
    double dpsi;
    if (pr->complete && pr->tech == c->tech &&
        angle_change(cur->cam, cur->t, cur->emi, cur->s, wk->spare->cam, wk->spare->emi, &dpsi))
        angle_acc_add(wk->angle, c->cur.s[0].px, c->cur.s[0].py, c->k, dpsi);
    else
        wk->angle->skipped++;
}

/* The acceptance of a proposal (MMLT paper Eq. 17-20, with the controlled step's kernel ratio),
 * its expected-value splats and its statistics. tech0: the chain's technique before the iteration
 * (small steps are split by whether they change it). */
static void decide(struct worker *wk, struct chain *c, bool large, int tech0, const struct proposal *pr, double t_start)
{
    double a = c->f > 0 ? mind(pr->f * pr->tr / c->f, 1.0) : 1.0;
    splat_ev(wk->img, c, &wk->prop, pr->f, a);
    bool acc = rng_uniform(&wk->r) < a;
    if (wk->ta) tech_acc_step(wk->ta, a, acc, pr->f, c->f, c->scale);
    if (acc) {
        pss_accept(&c->pss);
        move_to(wk->img, c, &wk->prop, pr->f);
        c->xsum_valid = false;
        if (wk->track) ctrl_path_capture(c->path, wk->spare->cam, pr->tech, wk->spare->emi, c->k + 1 - pr->tech);
        if (wk->pitp) {
            struct mmlt_path *t = c->x;
            c->x = wk->spare;
            wk->spare = t;
        }
    } else {
        pss_reject(&c->pss);
    }
    bool m = wk->multiplexed;
    stats_record_dt(wk->st, large ? PROPOSAL_LARGE : PROPOSAL_SMALL, m ? c->k : 0, m && pr->tech != tech0,
                    m ? abs(pr->tech - tech0) : 0, false, a, acc, pr->f > 0, elapsed(wk->o, t_start));
    if (acc) c->tech = pr->tech;
}

/* One iteration of the worker's chains. */
static void iterate(struct worker *wk)
{
    const struct mlt_opts *o = wk->o;
    struct chain *c = pick_chain(wk);
    bool large = rng_uniform(&wk->r) < o->p_large;
    double t_start = o->time_proposals ? now_seconds() : 0;
    if (large && use_mctls(o, c->k)) {
        bool acc, changed, nonzero;
        wk->w->conn_tried = wk->w->conn_nonzero = 0;
        double a = mctls_step(&wk->pc, o, c, wk->w, wk->mb, &wk->r, wk->img, &acc, &changed, &nonzero);
        take_connections(wk);
        stats_record(wk->st, PROPOSAL_MCTLS, c->k, changed, a, acc, nonzero, elapsed(o, t_start));
        return;
    }
    int tech0 = c->tech;
    if (wk->pitp && !large) pitp_perturbation(wk, c);
    struct proposal pr;
    propose(wk, c, large, &pr);
    if (!large && o->angle_stats) record_angle(wk, c, &pr);
    decide(wk, c, large, tech0, &pr, t_start);
}

/* Whether iteration n may run: no interruption, and within the time or mutation budget. */
static bool within_budget(const struct worker *wk, long budget)
{
    long n = wk->n;
    if ((n & 255) == 0 && interrupted()) return false;
    if (wk->o->seconds > 0) return (n & 255) != 0 || budget_seconds(wk->o->cpu_time, wk->o->threads) - wk->j->t0 < wk->o->seconds;
    return n < budget;
}

static void report_progress(struct worker *wk)
{
    if ((wk->n & 4095) != 4095) return;
    if (wk->o->seconds <= 0) progress_add(&wk->j->prog, 4096);
    else if (wk->tid == 0) progress_set(&wk->j->prog, (long)(1000 * (budget_seconds(wk->o->cpu_time, wk->o->threads) - wk->j->t0)));
}

/* The thread's final state into its checkpoint slot, its chains' owed splats, its counts. */
static void worker_finish(struct worker *wk)
{
    struct run_job *j = wk->j;
    if (j->o->ckpt) {
        /* before the final splats: a resumed run makes them itself */
        mlt_thread_save(&j->sync.slot[wk->tid], j->sc, &wk->ts);
        ckpt_sync_finish(&j->sync);
    }
    for (int kk = 0; kk < j->nk; kk++) {
        pay_current(wk->img, &wk->ch[kk]);
        free(wk->ch[kk].path);
        free(wk->ch[kk].x);
    }
    free(wk->cs);
    j->done[wk->tid] = wk->n;
    nonfinite_add(&wk->st->nonfinite, &wk->w->nf);
    free(wk->ps);
    free(wk->spare);
    free(wk->mb);
    free(wk->ch);
    free(wk->w);
}

void run_worker(int tid, void *p)
{
    struct worker wk;
    worker_init(&wk, p, tid);
    struct run_job *j = wk.j;
    const struct mlt_opts *o = wk.o;
    chains_start(&wk);
    bool bad = j->resume && !mlt_thread_load(&j->resume[tid], j->sc, &wk.ts);
    if (bad) atomic_store(&j->resume_bad, true);
    if (j->resume && o->seconds <= 0) progress_add(&j->prog, wk.n);
    long budget = o->mutations / j->stride + (wk.g < o->mutations % j->stride);
    for (; !bad; wk.n++) {
        if (!within_budget(&wk, budget)) break;
        if (o->ckpt && (wk.n & 255) == 0 && ckpt_sync_poll(&j->sync)) {
            mlt_thread_save(&j->sync.slot[tid], j->sc, &wk.ts);
            ckpt_sync_arrive(&j->sync);
        }
        iterate(&wk);
        report_progress(&wk);
    }
    worker_finish(&wk);
}
