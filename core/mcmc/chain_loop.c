/* The worker thread's iteration loop (MMLT paper Alg. 1-2; thesis §3.7 step 3). One iteration:
 * pick a chain (MMLT: a length k with probability P(k)), draw the step kind (large with
 * probability p_large; Veach's MLT has none), and hand the chain to the registry of mutations
 * (mutation.h), which makes the step: MCTLS's or fresh numbers for a large step, the small step
 * (under PITP preceded by the technique perturbation). Around it: the budget, the checkpoints'
 * rendezvous, the progress. */
#include "base/util.h"
#include "mcmc/mutation.h"
#include "mcmc/splat_ev.h"
#include "mcmc/veach.h"
#include <stdlib.h>

static void worker_init(struct worker *wk, struct run_job *j, int tid)
{
    const struct mlt_opts *o = j->o;
    *wk = (struct worker){.job = j, .opts = o, .tid = tid, .global_tid = j->g0 + tid};
    wk->path_ctx = (struct path_ctx){.sc = j->sc,
                                     .max_length = o->max_length,
                                     .min_length = o->min_length,
                                     .max_heuristic = o->max_heuristic,
                                     .power_heuristic = o->power_heuristic};
    wk->scratch = xmalloc(sizeof *wk->scratch);
    wk->scratch->nf = (struct nonfinite){{0}};
    wk->scratch->tech_k = 0; /* the MCMC methods split states by technique themselves (tech_split.h) */
    wk->ch = xcalloc((size_t)j->nch, sizeof *wk->ch);
    wk->mctls_buf = xmalloc(sizeof *wk->mctls_buf);
    wk->st = &j->stats[tid];
    wk->img = j->img[tid];
    wk->tech = j->tech ? &j->tech[tid] : NULL;
    wk->angle = j->angle ? &j->angle[tid] : NULL;
    wk->ctrl_fail = j->ctrl_fail[tid];
    wk->mix = j->mix ? &j->mix[tid] : NULL;
    wk->pitp = o->method == MLT_PITP;
    wk->multiplexed = mlt_multiplexed(o->method);
    bool fused = wk->multiplexed && o->fused != FUSED_NONE;
    wk->keep_path = wk->pitp || fused;
    wk->spare = xmalloc(sizeof *wk->spare);
    wk->pitp_scratch = wk->pitp ? xmalloc(sizeof *wk->pitp_scratch) : NULL;
    if (wk->pitp_scratch) pitp_scratch_init(wk->pitp_scratch, j->sc);
    rng_seed(&wk->r, o->seed,
             0x9E3779B97F4A7C15ULL + (uint64_t)wk->global_tid); /* streams and budgets are the job's global thread's */
    wk->track = mlt_multiplexed(o->method) && (o->small_step != SMALL_STEP_PSS || o->angle_stats);
    wk->ctrl = o->small_step != SMALL_STEP_PSS ? xmalloc(sizeof *wk->ctrl) : NULL;
    wk->veach = o->method == MLT_VEACH || fused ? xmalloc(sizeof *wk->veach) : NULL;
    wk->saved = (struct mlt_thread){.ch = wk->ch,
                                    .nk = j->nch,
                                    .r = &wk->r,
                                    .n = &wk->n,
                                    .nonfinite = &wk->scratch->nf,
                                    .st = wk->st,
                                    .ctrl_fail = wk->ctrl_fail,
                                    .img = wk->img,
                                    .len_img = j->len_img ? j->len_img[tid] : NULL,
                                    .angle = wk->angle,
                                    .tech = wk->tech,
                                    .trace = j->trace[tid]};
}

/* Every chain from a seed sample (seed_pass.c), or set up for the state a checkpoint left it in.
 * Under one_chain, the thread's one chain starts at a length drawn as its target weighs them
 * (one_chain.c); its target is f_k(u) over all lengths, so its splats weigh sum_k b_k. */
static void chains_start(struct worker *wk)
{
    const struct run_job *j = wk->job;
    bool one = wk->opts->one_chain, by_length = wk->multiplexed && !one;
    for (int ci = 0; ci < j->nch; ci++) {
        struct chain *c = &wk->ch[ci];
        int kk = !one ? ci : j->resume ? 0 : one_chain_first(wk); /* a resumed chain's k is loaded */
        mutations_chain_alloc(c, wk->opts);
        c->k = kk + 1;
        c->scale = one ? j->res->b : j->scale[kk];
        c->mis_pl = wk->opts->large_step_mis ? wk->opts->p_large : 0;
        c->img = j->len_img ? j->len_img[wk->tid][kk] : wk->img;
        c->dropped = &wk->scratch->nf.len[by_length ? c->k : 0];
        c->trace = &j->trace[wk->tid][ci];
        trace_init(c->trace, by_length ? c->k : 0); /* a resumed run's comes from the checkpoint */
        if (!j->resume) {
            if (c->scale > 0) chain_start(wk, c, kk);
            continue;
        }
        if (!(c->scale > 0)) continue; /* a length without light: never started */
        pss_init(&c->pss, &wk->opts->pss, wk->opts->seed, 0);
        if (wk->keep_path) c->x = xmalloc(sizeof *c->x);
        if (wk->track) c->path = xmalloc(sizeof *c->path);
    }
}

/* The chain of this iteration: MMLT's length k with probability P(k) (the job's kcdf). */
static struct chain *pick_chain(struct worker *wk)
{
    const struct run_job *j = wk->job;
    return &wk->ch[j->nch > 1 ? length_index(j, rng_uniform(&wk->r)) : 0];
}

/* Where the state's contribution lands in the image: the luminance-weighted mean raster column of
 * its splats (one splat for MMLT and PITP). Chains stuck in different parts of the image disagree
 * on it; the luminance of the splats themselves is b_k / P(k) for every state and says nothing. */
static double state_column(const struct chain *c)
{
    double sum = 0, w = 0;
    for (int i = 0; i < c->cur.n; i++) {
        double l = luminance(c->cur.s[i].c);
        sum += l * c->cur.s[i].px;
        w += l;
    }
    return w > 0 ? sum / w : c->cur.s[0].px;
}

/* The per-pixel mixing count (stats/pixel_mixing.h) of the state the chain holds after the
 * iteration: a new visit when it moved and its first splat left the pixel of (px0, py0), the
 * state's before the iteration, or on the chain's first iteration (counted by its trace). */
static void count_pixels(struct pixel_mixing *m, const struct chain *c, bool moved, double px0, double py0)
{
    if (c->cur.n == 0) return; /* a missed length's chain before it found light (progressive_norm.c) */
    long cell = pixmix_cell(m, c->cur.s[0].px, c->cur.s[0].py);
    bool fresh = c->trace->n == 1 || (moved && cell != pixmix_cell(m, px0, py0));
    pixmix_add(m, cell, fresh);
    for (int i = 1; i < c->cur.n; i++)
        pixmix_add(m, pixmix_cell(m, c->cur.s[i].px, c->cur.s[i].py), fresh);
}

/* One iteration of the worker's chains, and its mixing record (stats/chain_trace.h): whether the
 * iteration moved the chain's path (where its first splat lands: every accepted proposal of every
 * mutation moves it almost surely; PITP's perturbation, which keeps the path and changes its
 * technique and with it the target, does not), and on the trace's thinned iterations the state's
 * column and target; and the per-pixel count of its state. Draws nothing. */
static void iterate(struct worker *wk)
{
    const struct mlt_opts *o = wk->opts;
    struct chain *c = pick_chain(wk);
    /* Veach's mutations have no large step (his bidirectional mutation is his independence move) */
    bool large = o->method != MLT_VEACH && rng_uniform(&wk->r) < o->p_large;
    double t_start = o->time_proposals ? now_seconds() : 0;
    double px0 = c->cur.s[0].px, py0 = c->cur.s[0].py;
    if (wk->job->len_img) { /* progressive_norm.c discards a missed length's iterations without light */
        wk->st->iters[c->k]++;
        wk->st->zero_iters[c->k] += !(c->f > 0);
    }
    mutations_iterate(wk, c, large, t_start); /* the registry's steps (mutation.h) */
    bool moved = c->cur.s[0].px != px0 || c->cur.s[0].py != py0;
    if (trace_step(c->trace, moved)) trace_keep(c->trace, state_column(c), c->f);
    if (wk->mix) count_pixels(wk->mix, c, moved, px0, py0);
}

/* Whether iteration n may run: no interruption, and within the time or mutation budget. */
static bool within_budget(const struct worker *wk, long budget)
{
    long n = wk->n;
    if ((n & 255) == 0 && interrupted()) return false;
    if (wk->opts->seconds > 0)
        return (n & 255) != 0 ||
               budget_seconds(wk->opts->cpu_time, wk->opts->threads) - wk->job->t0 < wk->opts->seconds;
    return n < budget;
}

static void report_progress(struct worker *wk)
{
    if ((wk->n & 4095) != 4095) return;
    if (wk->opts->seconds <= 0)
        progress_add(&wk->job->prog, 4096);
    else if (wk->tid == 0)
        progress_set(&wk->job->prog,
                     (long)(1000 * (budget_seconds(wk->opts->cpu_time, wk->opts->threads) - wk->job->t0)));
}

/* The thread's final state into its checkpoint slot, its chains' owed splats, its counts. */
static void worker_finish(struct worker *wk)
{
    struct run_job *j = wk->job;
    if (j->o->ckpt) {
        /* before the final splats: a resumed run makes them itself */
        mlt_thread_save(&j->sync.slot[wk->tid], j->sc, &wk->saved);
        ckpt_sync_finish(&j->sync);
    }
    for (int kk = 0; kk < j->nch; kk++) {
        pay_current(wk->ch[kk].img, &wk->ch[kk]);
        free(wk->ch[kk].path);
        free(wk->ch[kk].x);
        mutations_chain_free(&wk->ch[kk]);
    }
    free(wk->ctrl);
    free(wk->veach);
    j->done[wk->tid] = wk->n;
    nonfinite_add(&wk->st->nonfinite, &wk->scratch->nf);
    free(wk->pitp_scratch);
    free(wk->spare);
    free(wk->mctls_buf);
    free(wk->ch);
    free(wk->scratch);
}

void run_worker(int tid, void *p)
{
    struct worker wk;
    worker_init(&wk, p, tid);
    struct run_job *j = wk.job;
    const struct mlt_opts *o = wk.opts;
    chains_start(&wk);
    bool bad = j->resume && !mlt_thread_load(&j->resume[tid], j->sc, &wk.saved);
    if (bad) atomic_store(&j->resume_bad, true);
    if (j->resume && o->seconds <= 0) progress_add(&j->prog, wk.n);
    long budget = o->mutations / j->stride + (wk.global_tid < o->mutations % j->stride);
    for (; !bad; wk.n++) {
        if (!within_budget(&wk, budget)) break;
        if (o->ckpt && (wk.n & 255) == 0 && ckpt_sync_poll(&j->sync)) {
            mlt_thread_save(&j->sync.slot[tid], j->sc, &wk.saved);
            ckpt_sync_arrive(&j->sync);
        }
        iterate(&wk);
        report_progress(&wk);
    }
    worker_finish(&wk);
}
