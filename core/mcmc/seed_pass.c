/* The seed pass, the normalisation and the chains' start (MMLT paper §4 "Initialization"; thesis
 * §3.7 step 1): seed_paths independent samples of the method's state (per length for MMLT) estimate
 * b_k = E[target] of each length, the length selection P(k) and each chain's splat weight
 * b_k / P(k); a chain starts from a sample of that pool resampled in proportion to its target, so
 * that it starts in its stationary distribution (no start-up bias). */
#include "base/dist.h"
#include "base/util.h"
#include "emitter/emitter.h"
#include "mcmc/mlt_internal.h"
#include "mcmc/tech_split.h"
#include "mcmc/veach.h"
#include "sampling/pick.h"
#include <math.h>
#include <stdlib.h>

/* BDPT's seed samples (seed_bdpt) draw from streams above every pool stream i * nk + kk. */
#define BDPT_SEED_STREAM (1ULL << 61)

struct seed_job {
    const struct scene *sc;
    const struct mlt_opts *o;
    int nk;         /* chains per thread: 1 (PSSMLT) or K (MMLT) */
    double *f;      /* seed_paths * nk targets, index i * nk + (k - 1) */
    double *bk;     /* o->seed_bdpt: the BDPT samples' luminance per length, same index; else NULL */
    int g0, stride; /* this rank's first global thread; the job's threads (base/dist.h) */
    struct progress prog;
};

static void seed_worker(int tid, void *p)
{
    struct seed_job *j = p;
    struct path_ctx pc = {.sc = j->sc,
                          .max_length = j->o->max_length,
                          .min_length = j->o->min_length,
                          .max_heuristic = j->o->max_heuristic,
                          .power_heuristic = j->o->power_heuristic};
    struct scratch *w = xcalloc(1, sizeof *w); /* its counts are not kept: a seed target is never splatted */
    struct mmlt_path *x = xmalloc(sizeof *x);
    struct sampler_independent s;
    struct splat_list l;
    int tech;
    bool complete;
    for (long i = j->g0 + tid; i < j->o->seed_paths; i += j->stride) {
        for (int kk = 0; kk < j->nk; kk++) {
            sampler_independent_init(&s, j->o->seed, seed_stream(i, j->nk, kk));
            j->f[i * j->nk + kk] = eval_state(j->o->method, &pc, &s.base, w, kk + 1, x, &l, &tech, &complete);
        }
        /* One BDPT sample per length, restricted to it, on streams no pool sample uses: the lengths'
         * estimates are independent of each other (one sample for all lengths would correlate them:
         * on ajar a path through the slit counts at every length, and b's error grew 1.4x so) and
         * of the pool. */
        for (int kk = 0; j->bk && kk < j->nk; kk++) {
            struct path_ctx pk = pc;
            pk.min_length = pk.max_length = kk + 1;
            if (kk + 1 < pc.min_length) continue;
            sampler_independent_init(&s, j->o->seed, BDPT_SEED_STREAM | seed_stream(i, j->nk, kk));
            w->tech_k = kk + 1; /* the length's techniques, split as for bdpt --technique-images */
            bdpt_splats(&pk, &s.base, w, &l);
            w->tech_k = 0;
            double v = 0;
            for (int t = 1; t <= kk + 2; t++)
                if (w->tech_on[t]) v += luminance(w->tech[t].c);
            j->bk[i * j->nk + kk] = v;
        }
        if ((i / j->stride) % 1024 == 0) progress_add(&j->prog, 1024);
    }
    free(x);
    free(w);
}

/* The seed pass's targets, index i * nk + kk. It is dealt over the job's threads; each target is
 * computed by one rank and the others hold 0, so the sum gives every rank the whole pass, exactly. */
static double *seed_targets(const struct run_job *rj, double **bk)
{
    const struct mlt_opts *o = rj->o;
    size_t n = (size_t)o->seed_paths * rj->nk;
    struct seed_job sj = {rj->sc, o, rj->nk, xcalloc(n, sizeof(double)), NULL, rj->g0, rj->stride, {0}};
    if (o->seed_bdpt && rj->nk > 1) sj.bk = xcalloc(n, sizeof(double));
    progress_init(&sj.prog, "seed pass", o->seed_paths / dist_size(), o->progress);
    parallel_run(o->threads, seed_worker, &sj);
    dist_sum_doubles(sj.f, n);
    if (sj.bk) dist_sum_doubles(sj.bk, n);
    progress_finish(&sj.prog);
    *bk = sj.bk;
    return sj.f;
}

/* Mean over the seed paths of v[i * nk + kk], and the variance of that mean. */
static void mean_and_var(const double *v, int nk, int kk, long n, double *mean, double *var_mean)
{
    double acc = 0, sq = 0;
    for (long i = 0; i < n; i++) {
        acc += v[i * nk + kk];
        sq += v[i * nk + kk] * v[i * nk + kk];
    }
    *mean = acc / (double)n;
    *var_mean = n > 1 ? fmax(0, sq / (double)n - *mean * *mean) / (double)(n - 1) : 0;
}

bool normalise(struct run_job *rj, struct mlt_result *r, char *err, size_t errlen)
{
    const struct mlt_opts *o = rj->o;
    double t0 = now_seconds();
    double *bk, *f = seed_targets(rj, &bk);
    double total = 0, var_total = 0;
    int live = 0;
    for (int kk = 0; kk < rj->nk; kk++) {
        double *cdf = xmalloc((size_t)o->seed_paths * sizeof(double)), acc = 0;
        for (long i = 0; i < o->seed_paths; i++)
            cdf[i] = acc += f[i * rj->nk + kk];
        /* a length whose pool found nothing has no pool to start from: it is left out under either
         * estimate of b_k (a bias where the seed pass is too small to see the length), unless
         * progressive_norm runs it anyway (below) */
        double mean = 0, var_mean = 0;
        if (acc > 0) mean_and_var(bk ? bk : f, rj->nk, kk, o->seed_paths, &mean, &var_mean);
        r->b_k[kk + 1] = mean;
        r->b_k_rse[kk + 1] = mean > 0 ? sqrt(var_mean) / mean : 0;
        /* the lengths' seed paths are independent streams, so their variances add up in b */
        var_total += var_mean;
        total += r->b_k[kk + 1];
        if (acc > 0 && mean > 0) {
            rj->cdf[kk] = cdf;
            live++;
        } else {
            free(cdf);
        }
    }
    free(f);
    free(bk);
    /* Length k is chosen with probability P(k) (b_k / b, or uniform over the lengths with b_k > 0)
     * and its splats weigh b_k / P(k), so every length is estimated without bias either way. Under
     * progressive_norm a length the pass missed runs too, on a provisional b_k (the smallest it
     * found): the end rescales it to what its large steps found (progressive_norm.c). */
    double bmin = total, bsel[MAX_PATH_LENGTH + 1], bsum = 0;
    for (int kk = 0; kk < rj->nk; kk++)
        if (rj->cdf[kk]) bmin = fmin(bmin, r->b_k[kk + 1]);
    for (int kk = 0; kk < rj->nk; kk++) {
        bool missed = o->progressive_norm && !rj->cdf[kk] && kk + 1 >= o->min_length;
        bsel[kk] = rj->cdf[kk] ? r->b_k[kk + 1] : missed ? bmin : 0;
        bsum += bsel[kk];
        live += missed;
    }
    for (int kk = 0; kk < rj->nk; kk++) {
        double pk = !(bsel[kk] > 0) ? 0 : o->uniform_lengths ? 1.0 / live : bsel[kk] / bsum;
        rj->kcdf[kk + 1] = rj->kcdf[kk] + pk;
        rj->scale[kk] = pk > 0 ? bsel[kk] / pk : 0;
    }
    r->b = total;
    r->b_rse = total > 0 ? sqrt(var_total) / total : 0;
    r->seed_seconds = now_seconds() - t0;
    if (total > 0) return true;
    if (emitters_count(rj->sc) == 0)
        snprintf(err, errlen, "%s: the scene has no emitter: there is no light to sample", rj->sc->file);
    else
        snprintf(err, errlen, "%s: the seed pass of %ld paths found no light; raise --seed-paths", rj->sc->file,
                 o->seed_paths);
    for (int kk = 0; kk < rj->nk; kk++) {
        free((void *)rj->cdf[kk]);
        rj->cdf[kk] = NULL;
    }
    return false;
}

void chain_start(struct worker *wk, struct chain *c, int kk)
{
    const struct run_job *j = wk->job;
    const struct mlt_opts *o = wk->opts;
    /* a length the seed pass missed (progressive_norm) starts from fresh numbers, most likely
     * without light: a chain at a zero target accepts any proposal, so it walks until it finds
     * some (the start-up bias the pool spares the others) */
    uint64_t stream = j->cdf[kk] ? seed_stream(pick_cdf(j->cdf[kk], o->seed_paths, rng_uniform(&wk->r)), j->nk, kk)
                                 : (1ULL << 60) | ((uint64_t)wk->global_tid << 24) | (uint64_t)kk;
    pss_init(&c->pss, &o->pss, o->seed, stream);
    if (wk->keep_path) c->x = xmalloc(sizeof *c->x);
    struct mmlt_path *x0 = wk->keep_path ? c->x : wk->spare;
    bool complete;
    c->f = eval_state(o->method, &wk->path_ctx, &c->pss.base, wk->scratch, c->k, x0, &c->cur, &c->tech, &complete);
    if (wk->tech)
        tech_split_record(wk->tech, &wk->path_ctx, wk->scratch, wk->multiplexed ? c->k : 0, c->tech, &c->cur, true);
    pss_accept(&c->pss);
    if (wk->track) {
        c->path = xmalloc(sizeof *c->path);
        ctrl_path_capture(c->path, x0->cam, c->tech, x0->emi, c->k + 1 - c->tech);
    }
    if (o->method == MLT_VEACH) veach_chain_start(wk, c); /* one of the seed's paths */
    /* The seed's stream reproduced its path; the mutations get a stream of their own, so that two
     * threads starting from the same seed sample do not run identical chains. */
    rng_seed(&c->pss.r, o->seed, (1ULL << 62) | ((uint64_t)wk->global_tid << 24) | (uint64_t)kk);
}
