/* PSSMLT and MMLT drivers: seed pass, chain start by resampling, Metropolis iterations with
 * expected-value splatting, statistics. See mlt.h for the method definitions. */
#include "mcmc/mlt.h"
#include "base/dist.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "emitter/emitter.h"
#include "io/image_merge.h"
#include "mc/integrator.h"
#include "mcmc/mlt_chain.h"
#include "mcmc/pitp.h"
#include "path/connect.h"
#include <stdlib.h>
#include <string.h>

/* Evaluates the state the sampler describes; returns the scalar target (0 for no contribution).
 * For MMLT and PITP, *tech receives the camera vertex count t and x the path in t's form. */
static double eval_state(enum mlt_method m, const struct path_ctx *pc, struct sampler *s, struct scratch *w, int k,
                         struct pitp_path *x, struct splat_list *out, int *tech, bool *complete)
{
    out->n = 0;
    *tech = 0;
    *complete = false;
    if (m == MLT_PSSMLT) {
        bdpt_splats(pc, s, w, out);
    } else {
        struct connection c;
        bool ok = mmlt_eval(pc, s, k, x, &c);
        *tech = x->t;
        *complete = x->complete;
        if (ok) {
            rgb v = vscale(c.f, c.w * (k + 1));
            if (vfinite(v)) splat_push(out, c.px, c.py, v);
            else w->nonfinite++;
        }
    }
    double f = splat_luminance(out);
    return isfinite(f) && f > 0 ? f : 0;
}

/* MCTLS (thesis Eq. 4.7): the targets of all k + 1 techniques of the subpaths the sampler's numbers
 * give, traced to full length; pi[t] and sp[t] for t = 1..k+1. Returns their sum. */
static double all_techniques(const struct path_ctx *pc, struct sampler *s, struct scratch *w, int k, double *pi,
                             struct splat_list *sp)
{
    int nz = walk_camera(pc, s, w->cam, k + 1);
    int ny = walk_emitter(pc, s, w->emi, k);
    double sum = 0;
    struct connection c;
    for (int t = 1; t <= k + 1; t++) {
        int sv = k + 1 - t;
        pi[t] = 0;
        sp[t].n = 0;
        if (nz < t || ny < sv || !connect_st(pc, w->emi, sv, w->cam, t, k, &c, NULL)) continue;
        rgb v = vscale(c.f, c.w * (k + 1));
        if (!vfinite(v)) {
            w->nonfinite++;
            continue;
        }
        splat_push(&sp[t], c.px, c.py, v);
        pi[t] = splat_luminance(&sp[t]);
        sum += pi[t];
    }
    return sum;
}

struct seed_job {
    const struct scene *sc;
    const struct mlt_opts *o;
    int nk;            /* chains per thread: 1 (PSSMLT) or K (MMLT) */
    double *f;         /* seed_paths * nk targets, index i * nk + (k - 1) */
    int g0, stride;    /* this rank's first global thread; the job's threads (core/dist.h) */
    struct progress prog;
};

static uint64_t seed_stream(long i, int nk, int kk) { return (uint64_t)i * (uint64_t)nk + (uint64_t)kk; }

static void seed_worker(int tid, void *p)
{
    struct seed_job *j = p;
    struct path_ctx pc = {.sc = j->sc, .max_length = j->o->max_length, .min_length = j->o->min_length, .max_heuristic = j->o->max_heuristic};
    struct scratch *w = xmalloc(sizeof *w);
    struct pitp_path *x = xmalloc(sizeof *x);
    struct sampler_independent s;
    struct splat_list l;
    int tech;
    bool complete;
    for (long i = j->g0 + tid; i < j->o->seed_paths; i += j->stride) {
        for (int kk = 0; kk < j->nk; kk++) {
            sampler_independent_init(&s, j->o->seed, seed_stream(i, j->nk, kk));
            j->f[i * j->nk + kk] = eval_state(j->o->method, &pc, &s.base, w, kk + 1, x, &l, &tech, &complete);
        }
        if ((i / j->stride) % 1024 == 0) progress_add(&j->prog, 1024);
    }
    free(x);
    free(w);
}

/* Per-thread MCTLS buffers (k + 2 splat lists each for proposal and current). */
struct mctls_buf {
    double pi[MAX_PATH_LENGTH + 2], xpi[MAX_PATH_LENGTH + 2];
    struct splat_list sp[MAX_PATH_LENGTH + 2], xsp[MAX_PATH_LENGTH + 2];
};

struct run_job {
    const struct scene *sc;
    const struct mlt_opts *o;
    int nk;
    const double *cdf[MAX_PATH_LENGTH + 1]; /* per chain index: seed-pool CDF over i */
    double kcdf[MAX_PATH_LENGTH + 2];       /* length selection */
    double scale[MAX_PATH_LENGTH + 1];      /* per chain index: b_k / P(k) */
    struct image **img;
    struct mlt_stats *stats;
    struct angle_acc *angle; /* per thread, with angle_stats */
    struct tech_acc *tech;   /* per thread, with technique_k */
    long (*ctrl_fail)[2];    /* per thread: forward, reverse */
    long *done;
    int g0, stride;          /* this rank's first global thread; the job's threads (core/dist.h) */
    double t0;
    struct progress prog;
    /* checkpoints (o->ckpt): the rendezvous, the run's normalisation, and on resume each thread's
     * saved state */
    struct ckpt_sync sync;
    const struct mlt_result *res;
    struct ckpt_buf *resume;
    atomic_bool resume_bad;
    double elapsed0; /* chain seconds before the resume */
};

static long pick_cdf(const double *cdf, long n, double u)
{
    long lo = 0, hi = n - 1;
    double x = u * cdf[n - 1];
    while (lo < hi) {
        long mid = (lo + hi) / 2;
        if (cdf[mid] > x) hi = mid;
        else lo = mid + 1;
    }
    return lo;
}

static void splat_list_weighted(struct image *img, const struct splat_list *l, double wgt)
{
    if (wgt <= 0) return;
    for (int i = 0; i < l->n; i++) img_splat(img, l->s[i].px, l->s[i].py, vscale(l->s[i].c, wgt));
}

/* The current state's share of expected-value splatting is deferred: a rejected proposal only adds
 * to `pending`, and the state is splatted once, with the sum, when it is replaced or the run ends. */
static void owe_current(struct chain *c, double a)
{
    if (c->f > 0) c->pending += 1 - a;
}

static void pay_current(struct image *img, struct chain *c)
{
    if (c->f > 0) splat_list_weighted(img, &c->cur, c->pending * c->scale / c->f);
    c->pending = 0;
}

/* Replaces the chain's state by an accepted proposal (splat list l, target f). */
static void move_to(struct image *img, struct chain *c, const struct splat_list *l, double f)
{
    pay_current(img, c);
    c->cur.n = l->n;
    memcpy(c->cur.s, l->s, (size_t)l->n * sizeof *l->s);
    c->f = f;
}

int mctls_pick(const double *pi, int n, double u)
{
    double sum = 0, acc = 0;
    for (int i = 0; i < n; i++) sum += pi[i];
    u *= sum;
    int j = 0;
    for (; j < n - 1; j++)
        if ((acc += pi[j]) > u && pi[j] > 0) break;
    while (j > 0 && pi[j] == 0) j--; /* rounding at the top end */
    return j;
}

double mctls_accept(double ysum, double xsum) { return xsum > 0 ? fmin(1.0, ysum / xsum) : 1.0; }

static bool use_mctls(const struct mlt_opts *o, int k)
{
    if (o->method == MLT_PSSMLT) return false;
    return o->large_step == LARGE_MCTLS || (o->large_step == LARGE_HYBRID && k >= o->hybrid_length);
}

/* PITP after an accepted MCTLS step: the chosen technique's subpaths are prefixes of the ones MCTLS
 * traced to full length; one more connection gives their density ratios. */
static void mctls_keep_path(const struct path_ctx *pc, struct pitp_path *x, const struct scratch *w, int k, int t)
{
    x->k = k;
    x->t = t;
    x->s = k + 1 - t;
    memcpy(x->cam, w->cam, (size_t)t * sizeof *x->cam);
    memcpy(x->emi, w->emi, (size_t)x->s * sizeof *x->emi);
    struct connection c;
    connect_st(pc, x->emi, x->s, x->cam, t, k, &c, x->ratios);
}

/* One MCTLS proposal for chain c; returns the acceptance probability and fills *acc. */
static double mctls_step(const struct path_ctx *pc, struct chain *c, struct scratch *w, struct mctls_buf *b, rng *r,
                         struct image *img, bool *acc, bool *changed, bool *nonzero)
{
    int k = c->k;
    if (!c->xsum_valid) {
        c->xsum = all_techniques(pc, &c->pss.base, w, k, b->xpi, b->xsp);
        c->xsum_valid = true;
    }
    pss_begin(&c->pss, true);
    double ysum = all_techniques(pc, &c->pss.base, w, k, b->pi, b->sp);
    int j = ysum > 0 ? mctls_pick(b->pi + 1, k + 1, rng_uniform(r)) + 1 : 0;
    double a = mctls_accept(ysum, c->xsum);
    if (ysum > 0) splat_list_weighted(img, &b->sp[j], a * c->scale / b->pi[j]);
    owe_current(c, a);
    *nonzero = ysum > 0;
    *acc = ysum > 0 && rng_uniform(r) < a;
    *changed = ysum > 0 && j != c->tech; /* a property of the proposal, not of its acceptance */
    if (*acc) {
        /* the state's technique number: a uniform point of the chosen technique's interval (Eq. 5.6) */
        pss_set(&c->pss, STREAM_TECHNIQUE, 0, invert_discrete((double)(j - 1) / (k + 1), (double)j / (k + 1), rng_uniform(r)));
        pss_accept(&c->pss);
        move_to(img, c, &b->sp[j], b->pi[j]);
        c->tech = j;
        c->xsum = ysum;
        if (c->x) mctls_keep_path(pc, c->x, w, k, j);
    } else {
        pss_reject(&c->pss);
    }
    return a;
}

static void run_worker(int tid, void *p)
{
    struct run_job *j = p;
    const struct mlt_opts *o = j->o;
    struct path_ctx pc = {.sc = j->sc, .max_length = o->max_length, .min_length = o->min_length, .max_heuristic = o->max_heuristic};
    struct scratch *w = xmalloc(sizeof *w);
    w->nonfinite = 0;
    struct chain *ch = xcalloc((size_t)j->nk, sizeof *ch);
    struct mctls_buf *mb = xmalloc(sizeof *mb);
    struct mlt_stats *st = &j->stats[tid];
    struct image *img = j->img[tid];
    struct tech_acc *ta = j->tech ? &j->tech[tid] : NULL;
    bool pitp = o->method == MLT_PITP, multiplexed = o->method != MLT_PSSMLT;
    /* the proposal's path; under PITP swapped with the chain's on accept (no copy, no allocation) */
    struct pitp_path *spare = xmalloc(sizeof *spare);
    struct pitp_scratch *ps = pitp ? xmalloc(sizeof *ps) : NULL;
    if (ps) pitp_scratch_init(ps, j->sc);
    rng r;
    int g = j->g0 + tid; /* streams and budgets are the job's global thread's */
    rng_seed(&r, o->seed, 0x9E3779B97F4A7C15ULL + (uint64_t)g);
    bool track = o->method != MLT_PSSMLT && (o->small_step != SMALL_STEP_PSS || o->angle_stats);
    struct ctrl_sampler *cs = o->small_step != SMALL_STEP_PSS ? xmalloc(sizeof *cs) : NULL;
    bool complete;
    long n = 0;
    struct ckpt_sync *sync = o->ckpt ? &j->sync : NULL;
    struct mlt_thread ts = {ch, j->nk, &r, &n, &w->nonfinite, st, j->ctrl_fail[tid], img, j->angle ? &j->angle[tid] : NULL, ta};
    /* Start every chain from a seed sample resampled in proportion to its target, or from where a
     * checkpoint left it. */
    for (int kk = 0; kk < j->nk; kk++) {
        struct chain *c = &ch[kk];
        c->k = kk + 1;
        c->scale = j->scale[kk];
        if (j->resume) {
            if (!(c->scale > 0)) continue; /* a length without light: never started */
            pss_init(&c->pss, &o->pss, o->seed, 0);
            if (pitp) c->x = xmalloc(sizeof *c->x);
            if (track) c->path = xmalloc(sizeof *c->path);
            continue;
        }
        if (!j->cdf[kk]) continue;
        long i = pick_cdf(j->cdf[kk], o->seed_paths, rng_uniform(&r));
        pss_init(&c->pss, &o->pss, o->seed, seed_stream(i, j->nk, kk));
        if (pitp) c->x = xmalloc(sizeof *c->x);
        struct pitp_path *x0 = pitp ? c->x : spare;
        c->f = eval_state(o->method, &pc, &c->pss.base, w, c->k, x0, &c->cur, &c->tech, &complete);
        if (ta) tech_acc_eval(ta, &pc, w, multiplexed ? c->k : 0, c->tech, &c->cur, true);
        pss_accept(&c->pss);
        if (track) {
            c->path = xmalloc(sizeof *c->path);
            ctrl_path_capture(c->path, x0->cam, c->tech, x0->emi, c->k + 1 - c->tech);
        }
        /* The seed's stream reproduced its path; the mutations get a stream of their own, so that
         * two threads starting from the same seed sample do not run identical chains. */
        rng_seed(&c->pss.r, o->seed, (1ULL << 62) | ((uint64_t)g << 24) | (uint64_t)kk);
    }
    bool bad = j->resume && !mlt_thread_load(&j->resume[tid], j->sc, &ts);
    if (bad) atomic_store(&j->resume_bad, true);
    if (j->resume && o->seconds <= 0) progress_add(&j->prog, n);
    long budget = o->mutations / j->stride + (g < o->mutations % j->stride);
    struct splat_list prop;
    for (; !bad; n++) {
        if ((n & 255) == 0 && interrupted()) break;
        if (o->seconds > 0) {
            if ((n & 255) == 0 && now_seconds() - j->t0 >= o->seconds) break;
        } else if (n >= budget) {
            break;
        }
        if (sync && (n & 255) == 0 && ckpt_sync_poll(sync)) {
            mlt_thread_save(&sync->slot[tid], j->sc, &ts);
            ckpt_sync_arrive(sync);
        }
        int kk = 0;
        if (j->nk > 1) {
            double u = rng_uniform(&r) * j->kcdf[j->nk];
            while (kk < j->nk - 1 && j->kcdf[kk + 1] <= u) kk++;
        }
        struct chain *c = &ch[kk];
        bool large = rng_uniform(&r) < o->p_large;
        double t_start = o->time_proposals ? now_seconds() : 0;
        if (large && use_mctls(o, c->k)) {
            bool acc, changed, nonzero;
            double a = mctls_step(&pc, c, w, mb, &r, img, &acc, &changed, &nonzero);
            stats_record(st, PROPOSAL_MCTLS, c->k, changed, a, acc, nonzero, o->time_proposals ? now_seconds() - t_start : 0);
        } else {
            /* the technique before this iteration: small steps are split by whether they change it */
            int tech0 = c->tech;
            if (pitp && !large) {
                /* PITP: the always-accepted technique perturbation, then MMLT's small step from there */
                int sj;
                double pa;
                struct connection cn;
                bool c_new;
                enum pitp_outcome po = pitp_perturb(&pc, &c->pss, c->x, ps, rng_uniform(&r), &sj, &pa, &cn, &c_new);
                int dt = abs(sj - c->x->s);
                if (po == PITP_MOVED) {
                    dt = abs(c->k + 1 - sj - c->tech);
                    c->tech = c->x->t;
                    c->xsum_valid = false;
                    /* controlled steps start from the current path in the new technique's form */
                    if (track) ctrl_path_capture(c->path, c->x->cam, c->x->t, c->x->emi, c->x->s);
                    if (c_new) {
                        /* the target changed with the technique (refraction, delta vertices): the
                         * state's splat and target follow */
                        struct splat_list l;
                        l.n = 0;
                        splat_push(&l, cn.px, cn.py, vscale(cn.f, cn.w * (c->k + 1)));
                        move_to(img, c, &l, splat_luminance(&l));
                    }
                }
                stats_record_dt(st, PROPOSAL_PITP, c->k, dt != 0, dt, po == PITP_FAILED, pa, po == PITP_SAME || po == PITP_MOVED,
                                true, 0);
            }
            pss_begin(&c->pss, large);
            int tech;
            /* the one dispatch point of the small-step kind: the proposal is traced through the
             * controlled sampler, which also yields the kernel's ratio T(v->u) / T(u->v) */
            bool ctrl = !large && cs;
            if (ctrl) ctrl_begin(cs, &c->pss, c->path, spare->cam, spare->emi, o->small_step);
            double f = eval_state(o->method, &pc, ctrl ? &cs->base : &c->pss.base, w, c->k, spare, &prop, &tech, &complete);
            if (ta) tech_acc_eval(ta, &pc, w, multiplexed ? c->k : 0, tech, &prop, false);
            double tr = ctrl ? ctrl_finish(cs, complete) : 1;
            if (ctrl && cs->fail != CTRL_OK) j->ctrl_fail[tid][cs->fail - 1]++;
            if (o->ctrl_unit_ratio && tr > 0) tr = 1;
            if (tr == 0) f = 0; /* an impossible inversion: nothing this proposal could splat */
            if (!large && o->angle_stats) {
                double dpsi;
                if (complete && tech == c->tech && angle_change(c->path, spare->cam, spare->emi, &dpsi))
                    angle_acc_add(&j->angle[tid], c->cur.s[0].px, c->cur.s[0].py, c->k, dpsi);
                else
                    j->angle[tid].skipped++;
            }
            double a = c->f > 0 ? mind(f * tr / c->f, 1.0) : 1.0;
            /* expected values: the proposal with weight a, the current state with 1 - a */
            if (f > 0) splat_list_weighted(img, &prop, a * c->scale / f);
            owe_current(c, a);
            bool acc = rng_uniform(&r) < a;
            if (ta) tech_acc_step(ta, a, acc, f, c->f, c->scale);
            if (acc) {
                pss_accept(&c->pss);
                move_to(img, c, &prop, f);
                c->xsum_valid = false;
                if (track) ctrl_path_capture(c->path, spare->cam, tech, spare->emi, c->k + 1 - tech);
                if (pitp) {
                    struct pitp_path *t = c->x;
                    c->x = spare;
                    spare = t;
                }
            } else {
                pss_reject(&c->pss);
            }
            stats_record_dt(st, large ? PROPOSAL_LARGE : PROPOSAL_SMALL, multiplexed ? c->k : 0, multiplexed && tech != tech0,
                            multiplexed ? abs(tech - tech0) : 0, false, a, acc, f > 0, o->time_proposals ? now_seconds() - t_start : 0);
            if (acc) c->tech = tech;
        }
        if ((n & 4095) == 4095) {
            if (o->seconds <= 0) progress_add(&j->prog, 4096);
            else if (tid == 0) progress_set(&j->prog, (long)(1000 * (now_seconds() - j->t0)));
        }
    }
    if (sync) {
        /* before the final splats: a resumed run makes them itself */
        mlt_thread_save(&sync->slot[tid], j->sc, &ts);
        ckpt_sync_finish(sync);
    }
    for (int kk = 0; kk < j->nk; kk++) {
        pay_current(img, &ch[kk]);
        free(ch[kk].path);
        free(ch[kk].x);
    }
    free(cs);
    j->done[tid] = n;
    st->nonfinite += w->nonfinite;
    free(ps);
    free(spare);
    free(mb);
    free(ch);
    free(w);
}

/* A checkpoint: the normalisation, the chains' elapsed time, then every thread's state. Called
 * by the rendezvous's last thread, or after the workers ended on an interruption. */
static const char mlt_tag[8] = "MLTRUN1";

static void mlt_save(void *p)
{
    struct run_job *j = p;
    struct ckpt_buf b = {0};
    double elapsed = now_seconds() - j->t0;
    ckpt_put(&b, mlt_tag, sizeof mlt_tag);
    CKPT_PUT(&b, j->res->b_k);
    CKPT_PUT(&b, j->res->b);
    CKPT_PUT(&b, j->res->seed_seconds);
    CKPT_PUT(&b, j->kcdf);
    CKPT_PUT(&b, j->scale);
    CKPT_PUT(&b, elapsed);
    ckpt_save_run(j->o->ckpt, &b, &j->sync);
}

/* The counterpart of mlt_save's header, and each thread's state located for its worker. */
static bool resume_global(struct run_job *rj, char *err, size_t errlen)
{
    struct ckpt_buf *b = rj->o->ckpt->resume;
    struct mlt_result *r = (struct mlt_result *)rj->res;
    char tag[sizeof mlt_tag];
    double elapsed = 0;
    b->pos = 0;
    ckpt_get(b, tag, sizeof tag);
    CKPT_GET(b, r->b_k);
    CKPT_GET(b, r->b);
    CKPT_GET(b, r->seed_seconds);
    CKPT_GET(b, rj->kcdf);
    CKPT_GET(b, rj->scale);
    CKPT_GET(b, elapsed);
    rj->resume = ckpt_resume_threads(b, rj->o->threads);
    if (!rj->resume || memcmp(tag, mlt_tag, sizeof tag)) {
        snprintf(err, errlen, "the checkpoint's state does not fit this run (not an MCMC run of these options)");
        free(rj->resume);
        rj->resume = NULL;
        return false;
    }
    rj->elapsed0 = elapsed;
    return true;
}

/* The seed pass and what it gives: b_k, the length selection and each length's seed-pool CDF. */
static bool normalise(struct run_job *rj, struct mlt_result *r, char *err, size_t errlen)
{
    const struct mlt_opts *o = rj->o;
    double t0 = now_seconds();

    /* The seed pass is dealt over the job's threads; each target is computed by one rank and the
     * others hold 0, so the sum gives every rank the whole pass, exactly. */
    struct seed_job sj = {rj->sc, o, rj->nk, xcalloc((size_t)o->seed_paths * rj->nk, sizeof(double)), rj->g0, rj->stride, {0}};
    progress_init(&sj.prog, "seed pass", o->seed_paths / dist_size(), o->progress);
    parallel_run(o->threads, seed_worker, &sj);
    dist_sum_doubles(sj.f, (size_t)o->seed_paths * rj->nk);
    progress_finish(&sj.prog);

    double total = 0;
    int live = 0;
    for (int kk = 0; kk < rj->nk; kk++) {
        double *cdf = xmalloc((size_t)o->seed_paths * sizeof(double)), acc = 0;
        for (long i = 0; i < o->seed_paths; i++) cdf[i] = acc += sj.f[i * rj->nk + kk];
        r->b_k[kk + 1] = acc / o->seed_paths;
        total += r->b_k[kk + 1];
        if (acc > 0) {
            rj->cdf[kk] = cdf;
            live++;
        } else {
            free(cdf);
        }
    }
    /* Length k is chosen with probability P(k) (b_k / b, or uniform over the lengths with b_k > 0)
     * and its splats weigh b_k / P(k), so every length is estimated without bias either way. */
    for (int kk = 0; kk < rj->nk; kk++) {
        double pk = !rj->cdf[kk] ? 0 : o->uniform_lengths ? 1.0 / live : r->b_k[kk + 1] / total;
        rj->kcdf[kk + 1] = rj->kcdf[kk] + pk;
        rj->scale[kk] = pk > 0 ? r->b_k[kk + 1] / pk : 0;
    }
    r->b = total;
    r->seed_seconds = now_seconds() - t0;
    if (!(total > 0)) {
        if (emitters_count(rj->sc) == 0)
            snprintf(err, errlen, "%s: the scene has no emitter: there is no light to sample", rj->sc->file);
        else
            snprintf(err, errlen, "%s: the seed pass of %ld paths found no light; raise --seed-paths", rj->sc->file, o->seed_paths);
        for (int kk = 0; kk < rj->nk; kk++) free((void *)rj->cdf[kk]);
        free(sj.f);
        return false;
    }
    free(sj.f);
    return true;
}

/* The threads' statistics, merged with their images (io/image_merge.h). */
struct stats_merge {
    const struct mlt_stats *stats;
    const struct angle_acc *angle; /* or NULL */
    struct mlt_stats *stats_out;
    struct angle_acc *angle_out;
};

static void add_thread_stats(void *p, int i)
{
    struct stats_merge *m = p;
    stats_merge(m->stats_out, &m->stats[i]);
    if (m->angle) angle_acc_merge(m->angle_out, &m->angle[i]);
}

bool mlt_render(const struct scene *sc, const struct mlt_opts *o_in, struct mlt_result *r, char *err, size_t errlen)
{
    struct mlt_opts o = *o_in;
    if (o.threads < 1) o.threads = 1;
    int W = sc->cam.width, H = sc->cam.height, T = o.threads;
    int nk = o.method != MLT_PSSMLT ? o.max_length : 1;
    memset(r, 0, sizeof *r);
    if (o.max_length < 1 || o.max_length > MAX_PATH_LENGTH || o.min_length > o.max_length) {
        snprintf(err, errlen, "path lengths %d..%d: the renderer holds paths of 1..%d segments", o.min_length,
                 o.max_length, MAX_PATH_LENGTH);
        return false;
    }
    if (o.small_step != SMALL_STEP_PSS &&
        (o.method == MLT_PSSMLT || o.large_step != LARGE_MMLT || o.pss.kernel != KERNEL_GAUSSIAN || o.pss.cdc)) {
        /* the reverse density needs the Gaussian's (controlled_step.h); MCTLS does not keep the
         * current subpaths; --cdc would make the kernel singular */
        snprintf(err, errlen, "controlled and root small steps need mmlt or pitp, MMLT large steps, the Gaussian kernel and no --cdc");
        return false;
    }
    if (o.technique_k && (o.method == MLT_PITP || o.large_step != LARGE_MMLT || o.technique_k < o.min_length ||
                          o.technique_k > o.max_length)) {
        snprintf(err, errlen,
                 "technique images need pssmlt or mmlt with MMLT large steps and a length within "
                 "--min-length..--max-length");
        return false;
    }
    if (o.technique_k && dist_size() > 1) {
        snprintf(err, errlen, "technique images are not merged across MPI ranks: make them without mpirun");
        return false;
    }
    if (o.angle_stats && (o.method == MLT_PSSMLT || o.large_step != LARGE_MMLT)) {
        snprintf(err, errlen, "angle statistics need mmlt or pitp with MMLT large steps");
        return false;
    }
    struct run_job rj;
    memset(&rj, 0, sizeof rj);
    rj.sc = sc;
    rj.o = &o;
    rj.nk = nk;
    rj.res = r;
    rj.g0 = dist_thread0(T);
    rj.stride = dist_size() * T;
    bool resumed = o.ckpt && o.ckpt->resume;
    if (resumed ? !resume_global(&rj, err, errlen) : !normalise(&rj, r, err, errlen)) return false;
    rj.img = xcalloc((size_t)T, sizeof(struct image *));
    rj.stats = xcalloc((size_t)T, sizeof(struct mlt_stats));
    rj.done = xcalloc((size_t)T, sizeof(long));
    rj.ctrl_fail = xcalloc((size_t)T, sizeof *rj.ctrl_fail);
    if (o.angle_stats) {
        rj.angle = xcalloc((size_t)T, sizeof *rj.angle);
        for (int i = 0; i < T; i++) angle_acc_init(&rj.angle[i], W, H);
    }
    if (o.technique_k) rj.tech = tech_acc_alloc(T, o.technique_k, W, H, sc->cam.filter == FILTER_TENT);
    for (int i = 0; i < T; i++) {
        rj.img[i] = img_create(W, H);
        rj.img[i]->tent = sc->cam.filter == FILTER_TENT;
    }
    rj.t0 = now_seconds() - rj.elapsed0;
    progress_init(&rj.prog, (const char *[]){"pssmlt", "mmlt", "pitp"}[o.method], o.seconds > 0 ? (long)(1000 * o.seconds) : o.mutations / dist_size(),
                  o.progress);
    if (o.ckpt) ckpt_sync_init(&rj.sync, T, o.ckpt->every, mlt_save, &rj);
    parallel_run(T, run_worker, &rj);
    progress_finish(&rj.prog);
    /* Counts over the job's threads (integers: exact in any order), before the image's scale. */
    long counts[5] = {0, 0, 0, interrupted(), atomic_load(&rj.resume_bad)};
    for (int i = 0; i < T; i++) {
        counts[0] += rj.done[i];
        counts[1] += rj.ctrl_fail[i][0];
        counts[2] += rj.ctrl_fail[i][1];
    }
    dist_sum_longs(counts, 5); /* every rank learns of an interruption or a bad resume anywhere */
    r->seconds = now_seconds() - rj.t0;
    r->partial = counts[3] > 0;
    if (o.ckpt) {
        if (interrupted()) mlt_save(&rj); /* Ctrl-C: every thread stored where it stopped */
        ckpt_sync_destroy(&rj.sync);
    }
    free(rj.resume);
    if (counts[4]) {
        snprintf(err, errlen, "the checkpoint's state does not fit this run's chains");
        for (int i = 0; i < T; i++) img_destroy(rj.img[i]);
        free(rj.img);
        free(rj.stats);
        free(rj.done);
        free(rj.ctrl_fail);
        if (rj.angle)
            for (int i = 0; i < T; i++) angle_acc_free(&rj.angle[i]);
        free(rj.angle);
        if (rj.tech)
            for (int i = 0; i < T; i++) tech_acc_free(&rj.tech[i]);
        free(rj.tech);
        return false;
    }
    r->mutations = counts[0];
    r->ctrl_fail_forward = counts[1];
    r->ctrl_fail_reverse = counts[2];
    r->img = img_create(W, H);
    stats_clear(&r->stats);
    if (o.angle_stats) {
        r->angle = xmalloc(sizeof *r->angle);
        angle_acc_init(r->angle, W, H);
    }
    double scale = r->mutations > 0 ? camera_film_area(&sc->cam) / (double)r->mutations : 0;
    struct stats_merge sm = {rj.stats, rj.angle, &r->stats, r->angle};
    struct thread_results tr = {.threads = T, .img = rj.img, .scale = scale, .add = add_thread_stats, .ctx = &sm};
    /* every field the merges add travels; the statistics are flat structs of counts and sums */
    tr.extra[tr.nextra++] = (struct dist_buf){&r->stats, sizeof r->stats};
    if (r->angle) {
        size_t cells = (size_t)W * H;
        tr.extra[tr.nextra++] = (struct dist_buf){r->angle->sum, cells * sizeof *r->angle->sum};
        tr.extra[tr.nextra++] = (struct dist_buf){r->angle->count, cells * sizeof *r->angle->count};
        tr.extra[tr.nextra++] = (struct dist_buf){r->angle->len, sizeof r->angle->len};
        tr.extra[tr.nextra++] = (struct dist_buf){&r->angle->skipped, sizeof r->angle->skipped};
    }
    merge_thread_results(&tr, r->img);
    for (int i = 0; i < T; i++) img_destroy(rj.img[i]);
    if (o.angle_stats) {
        for (int i = 0; i < T; i++) angle_acc_free(&rj.angle[i]);
        free(rj.angle);
    }
    if (rj.tech) r->tech = tech_acc_reduce(rj.tech, T, scale);
    free(rj.ctrl_fail);
    r->nonfinite = r->stats.nonfinite;
    for (int kk = 0; kk < nk; kk++) free((void *)rj.cdf[kk]);
    free(rj.img);
    free(rj.stats);
    free(rj.done);
    return true;
}

void mlt_result_free(struct mlt_result *r)
{
    img_destroy(r->img);
    r->img = NULL;
    if (r->angle) angle_acc_free(r->angle);
    free(r->angle);
    r->angle = NULL;
    tech_acc_destroy(r->tech);
    r->tech = NULL;
}
