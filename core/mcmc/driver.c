/* mlt_render (mlt.h): the options' checks, the run's job and its threads, the checkpoint's run
 * header and the resume, and the merge of the threads' images and statistics into the result
 * (MMLT paper §4; thesis §3.7-3.8). The seed pass is seed_pass.c's, a thread's iterations
 * chain_loop.c's. */
#include "base/dist.h"
#include "base/util.h"
#include "camera/camera.h"
#include "io/image_merge.h"
#include "mcmc/mlt_internal.h"
#include "mcmc/mlt_options.h"
#include <stdlib.h>
#include <string.h>

static bool check_opts(const struct mlt_opts *o, char *err, size_t errlen)
{
    if (o->max_length < 1 || o->max_length > MAX_PATH_LENGTH || o->min_length > o->max_length) {
        snprintf(err, errlen, "path lengths %d..%d: the renderer holds paths of 1..%d segments", o->min_length,
                 o->max_length, MAX_PATH_LENGTH);
        return false;
    }
    return mlt_options_check(o, err, errlen); /* the checks between options (mlt_options.c) */
}

/* A checkpoint: the normalisation, the chains' elapsed time, then every thread's state. Called
 * by the rendezvous's last thread, or after the workers ended on an interruption. */
static const char mlt_tag[8] = "MLTRUN1";

static void mlt_save(void *p)
{
    struct run_job *j = p;
    struct ckpt_buf b = {0};
    double elapsed = budget_seconds(j->o->cpu_time, j->o->threads) - j->t0;
    ckpt_put(&b, mlt_tag, sizeof mlt_tag);
    CKPT_PUT(&b, j->res->b_k);
    CKPT_PUT(&b, j->res->b);
    CKPT_PUT(&b, j->res->b_k_rse);
    CKPT_PUT(&b, j->res->b_rse);
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
    CKPT_GET(b, r->b_k_rse);
    CKPT_GET(b, r->b_rse);
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

/* The threads' accumulators: image, statistics, counts, and the optional angle and technique ones. */
static void job_alloc(struct run_job *rj, const struct scene *sc)
{
    const struct mlt_opts *o = rj->o;
    int W = sc->cam.width, H = sc->cam.height, T = o->threads;
    rj->img = xcalloc((size_t)T, sizeof(struct image *));
    rj->stats = xcalloc((size_t)T, sizeof(struct mlt_stats));
    rj->done = xcalloc((size_t)T, sizeof(long));
    rj->ctrl_fail = xcalloc((size_t)T, sizeof *rj->ctrl_fail);
    rj->trace = xcalloc((size_t)T, sizeof *rj->trace);
    for (int i = 0; i < T; i++)
        rj->trace[i] = xcalloc((size_t)rj->nch, sizeof **rj->trace);
    if (o->angle_stats) {
        rj->angle = xcalloc((size_t)T, sizeof *rj->angle);
        for (int i = 0; i < T; i++)
            angle_acc_init(&rj->angle[i], W, H);
    }
    if (o->technique_k) rj->tech = tech_acc_alloc(T, o->technique_k, W, H, sc->cam.filter == FILTER_TENT);
    if (o->mixing_image) {
        rj->mix = xcalloc((size_t)T, sizeof *rj->mix);
        for (int i = 0; i < T; i++)
            pixmix_init(&rj->mix[i], W, H);
    }
    for (int i = 0; i < T; i++) {
        rj->img[i] = img_create(W, H);
        rj->img[i]->tent = sc->cam.filter == FILTER_TENT;
    }
    if (!o->progressive_norm) return;
    rj->len_img = xcalloc((size_t)T, sizeof *rj->len_img);
    for (int i = 0; i < T; i++) {
        rj->len_img[i] = xcalloc((size_t)rj->nk, sizeof **rj->len_img);
        for (int kk = 0; kk < rj->nk; kk++) {
            rj->len_img[i][kk] = img_create(W, H);
            rj->len_img[i][kk]->tent = rj->img[i]->tent;
        }
    }
}

static void job_free(struct run_job *rj)
{
    int T = rj->o->threads;
    for (int i = 0; i < T; i++) {
        img_destroy(rj->img[i]);
        if (rj->mix) pixmix_free(&rj->mix[i]);
    }
    free(rj->mix);
    if (rj->angle)
        for (int i = 0; i < T; i++)
            angle_acc_free(&rj->angle[i]);
    if (rj->tech)
        for (int i = 0; i < T; i++)
            tech_acc_free(&rj->tech[i]);
    for (int kk = 0; kk < rj->nk; kk++)
        free((void *)rj->cdf[kk]);
    for (int i = 0; i < T; i++)
        free(rj->trace[i]);
    free(rj->trace);
    for (int i = 0; rj->len_img && i < T; i++) {
        for (int kk = 0; kk < rj->nk; kk++)
            img_destroy(rj->len_img[i][kk]);
        free(rj->len_img[i]);
    }
    free(rj->len_img);
    free(rj->img);
    free(rj->stats);
    free(rj->done);
    free(rj->ctrl_fail);
    free(rj->angle);
    free(rj->tech);
    free(rj->resume);
}

/* The threads run; then the counts over the job's threads (integers: exact in any order):
 * mutations, controlled-step failures forward and reverse, interruptions, bad resumes. Every rank
 * learns of an interruption or a bad resume anywhere. */
static void run_threads(struct run_job *rj, long counts[5])
{
    const struct mlt_opts *o = rj->o;
    int T = o->threads;
    rj->t0 = budget_seconds(o->cpu_time, T) - rj->elapsed0;
    progress_init(&rj->prog, (const char *[]){"pssmlt", "mmlt", "pitp", "mlt"}[o->method],
                  o->seconds > 0 ? (long)(1000 * o->seconds) : o->mutations / dist_size(), o->progress);
    if (o->ckpt) ckpt_sync_init(&rj->sync, T, o->ckpt->every, mlt_save, rj);
    parallel_run(T, run_worker, rj);
    progress_finish(&rj->prog);
    counts[0] = counts[1] = counts[2] = 0;
    counts[3] = interrupted();
    counts[4] = atomic_load(&rj->resume_bad);
    for (int i = 0; i < T; i++) {
        counts[0] += rj->done[i];
        counts[1] += rj->ctrl_fail[i][0];
        counts[2] += rj->ctrl_fail[i][1];
    }
    dist_sum_longs(counts, 5);
}

/* The threads' statistics, merged with their images (io/image_merge.h). */
struct stats_merge {
    const struct mlt_stats *stats;
    const struct angle_acc *angle; /* or NULL */
    struct mlt_stats *stats_out;
    struct angle_acc *angle_out;
    struct chain_trace *const *trace; /* per thread, nk (chains per thread) each */
    struct chain_trace *trace_out;    /* per global thread, nk each */
    const struct pixel_mixing *mix;
    struct pixel_mixing *mix_out;
    int nk, g0;
};

static void add_thread_stats(void *p, int i)
{
    struct stats_merge *m = p;
    stats_merge(m->stats_out, &m->stats[i]);
    if (m->angle) angle_acc_merge(m->angle_out, &m->angle[i]);
    if (m->mix) pixmix_merge(m->mix_out, &m->mix[i]);
    /* a gather, not a sum: each global thread's slots are written by its own rank only */
    memcpy(m->trace_out + (size_t)(m->g0 + i) * m->nk, m->trace[i], (size_t)m->nk * sizeof *m->trace_out);
}

/* The threads' images (film scale over the job's mutations), statistics, angle and technique
 * accumulators into the result. */
static void merge_results(struct run_job *rj, const struct scene *sc, struct mlt_result *r)
{
    int W = sc->cam.width, H = sc->cam.height, T = rj->o->threads;
    r->img = img_create(W, H);
    stats_clear(&r->stats);
    if (rj->o->angle_stats) {
        r->angle = xmalloc(sizeof *r->angle);
        angle_acc_init(r->angle, W, H);
    }
    double scale = r->mutations > 0 ? camera_film_area(&sc->cam) / (double)r->mutations : 0;
    r->ntrace = rj->stride * rj->nch;
    r->trace = xcalloc((size_t)r->ntrace, sizeof *r->trace);
    if (rj->mix) {
        r->mix = xmalloc(sizeof *r->mix);
        pixmix_init(r->mix, W, H);
    }
    struct stats_merge sm = {rj->stats, rj->angle, &r->stats, r->angle, rj->trace,
                             r->trace,  rj->mix,   r->mix,    rj->nch,  rj->g0};
    struct thread_results tr = {.threads = T, .img = rj->img, .scale = scale, .add = add_thread_stats, .ctx = &sm};
    /* every field the merges add travels; the statistics are flat structs of counts and sums, the
     * mixing records flat structs */
    tr.extra[tr.nextra++] = (struct dist_buf){&r->stats, sizeof r->stats};
    tr.extra[tr.nextra++] = (struct dist_buf){r->trace, (size_t)r->ntrace * sizeof *r->trace};
    if (r->mix) tr.extra[tr.nextra++] = (struct dist_buf){r->mix->n, 2 * (size_t)W * H * sizeof *r->mix->n};
    if (r->angle) {
        size_t cells = (size_t)W * H;
        tr.extra[tr.nextra++] = (struct dist_buf){r->angle->sum, cells * sizeof *r->angle->sum};
        tr.extra[tr.nextra++] = (struct dist_buf){r->angle->count, cells * sizeof *r->angle->count};
        tr.extra[tr.nextra++] = (struct dist_buf){r->angle->len, sizeof r->angle->len};
        tr.extra[tr.nextra++] = (struct dist_buf){&r->angle->skipped, sizeof r->angle->skipped};
    }
    merge_thread_results(&tr, r->img);
    if (rj->tech) {
        r->tech = tech_acc_reduce(rj->tech, T, scale); /* frees the per-thread ones */
        rj->tech = NULL;
    }
    r->nonfinite = nonfinite_total(&r->stats.nonfinite);
}

bool mlt_render(const struct scene *sc, const struct mlt_opts *o_in, struct mlt_result *r, char *err, size_t errlen)
{
    struct mlt_opts o = *o_in;
    if (o.threads < 1) o.threads = 1;
    memset(r, 0, sizeof *r);
    if (!check_opts(&o, err, errlen)) return false;
    struct run_job rj;
    memset(&rj, 0, sizeof rj);
    rj.sc = sc;
    rj.o = &o;
    rj.nk = mlt_multiplexed(o.method) ? o.max_length : 1;
    rj.nch = o.one_chain ? 1 : rj.nk;
    rj.res = r;
    rj.g0 = dist_thread0(o.threads);
    rj.stride = dist_size() * o.threads;
    bool resumed = o.ckpt && o.ckpt->resume;
    if (resumed ? !resume_global(&rj, err, errlen) : !normalise(&rj, r, err, errlen)) return false;
    job_alloc(&rj, sc);
    long counts[5];
    run_threads(&rj, counts);
    r->seconds = budget_seconds(o.cpu_time, o.threads) - rj.t0;
    r->partial = counts[3] > 0;
    if (o.ckpt) {
        if (interrupted()) mlt_save(&rj); /* Ctrl-C: every thread stored where it stopped */
        ckpt_sync_destroy(&rj.sync);
    }
    bool ok = !counts[4];
    if (ok) {
        r->mutations = counts[0];
        r->ctrl_fail_forward = counts[1];
        r->ctrl_fail_reverse = counts[2];
        normalisation_from_large_steps(&rj, r); /* under progressive_norm, into the threads' images */
        merge_results(&rj, sc, r);
    } else {
        snprintf(err, errlen, "the checkpoint's state does not fit this run's chains");
    }
    job_free(&rj);
    return ok;
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
    free(r->trace);
    r->trace = NULL;
    if (r->mix) pixmix_free(r->mix);
    free(r->mix);
    r->mix = NULL;
}
