/* The Monte Carlo render driver for PT and BDPT (render.h): rows dealt to threads, spp or time
 * budgets in whole passes, checkpoints, the merge over threads and ranks. */
#include "mc/render.h"
#include "base/dist.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "io/image_merge.h"
#include "mc/integrator.h"
#include "sampler/sobol02.h"
#include <stdlib.h>
#include <string.h>

static const char *names[] = {"pt", "bdpt"};

const char *method_name(enum method m) { return names[m]; }

bool method_parse(const char *s, enum method *m)
{
    for (int i = 0; i < (int)(sizeof names / sizeof *names); i++)
        if (!strcmp(s, names[i])) {
            *m = (enum method)i;
            return true;
        }
    return false;
}

/* Stratifies camera samples by film cell: the image dims land inside cell (x, y) of the film
 * (camera.h; the image's pixels, plus a one-pixel ring for the tent filter), every other number is
 * independent, or with --sampler sobol a scrambled (0,2)-sequence over the cell's samples
 * (dimension: the number's place in its stream's vector). The annotation is what makes this
 * possible without touching path code. */
struct pixel_sampler {
    struct sampler base;
    rng r;
    double x0, y0, sx, sy;
    bool sobol;
    uint64_t key;   /* the cell's sequence */
    uint32_t index; /* the sample's place in it */
};

static double pixel_next(struct sampler *s, enum dim_kind kind)
{
    struct pixel_sampler *p = (struct pixel_sampler *)s;
    double u = p->sobol ? sobol02_sample(p->key, p->index, (uint32_t)(s->stream * STREAM_DIMS + sampler_index(s)))
                        : rng_uniform(&p->r);
    if (kind == DIM_IMAGE_X) return (p->x0 + u) * p->sx;
    if (kind == DIM_IMAGE_Y) return (p->y0 + u) * p->sy;
    return u;
}
static const struct sampler_ops pixel_ops = {pixel_next, NULL, NULL};

/* Time-budgeted runs key their sampler streams as if for this many samples per pixel. */
#define TIME_MODE_MAX_SPP (1 << 24)

struct job {
    const struct scene *sc;
    const struct render_opts *o;
    struct image **img;
    struct bdpt_tech **tech; /* per thread, with o->tech_k */
    struct nonfinite *nf;    /* per thread */
    long *samples;
    struct progress prog;
    int first, count; /* samples first .. first + count - 1 of every pixel */
    uint64_t key;     /* sample i of film cell c draws from stream c * key + i */
    int g0, stride;   /* this rank's first global thread; the job's threads (core/base/dist.h) */
    /* --time: passes of one sample per pixel until the budget */
    struct pass_barrier passes;
    int spp; /* passes done */
    double t0;
    /* checkpoints (o->ckpt): slots and rendezvous; on resume each thread's saved state */
    struct ckpt_sync sync;
    struct ckpt_buf *resume;
    atomic_bool resume_bad;
    double next_ckpt; /* --time: passes are where checkpoints are taken */
};

/* Where a thread is: the next sample it takes (row, column, sample index). */
struct mc_pos {
    int y, x, i;
};

static void save_thread(struct ckpt_buf *b, const struct job *j, int tid, struct mc_pos at)
{
    b->len = 0;
    CKPT_PUT(b, at);
    CKPT_PUT(b, j->samples[tid]);
    CKPT_PUT(b, j->nf[tid]);
    ckpt_put_image(b, j->img[tid]);
}

/* A position must be one this thread can be at (its rows, inside the film, inside the pass): the
 * checksum vouches for the bytes, not for the numbers the loop indexes pixels with. */
static bool load_thread(struct ckpt_buf *b, struct job *j, int tid, struct mc_pos *at, int W, int H)
{
    CKPT_GET(b, *at);
    CKPT_GET(b, j->samples[tid]);
    CKPT_GET(b, j->nf[tid]);
    ckpt_get_image(b, j->img[tid]);
    int y0 = j->g0 + tid;
    bool pos_ok = at->y >= y0 && (at->y - y0) % j->stride == 0 && at->y <= H + j->stride && at->x >= 0 && at->x <= W &&
                  at->i >= j->first && at->i <= j->first + j->count;
    return !b->short_read && b->pos == b->len && pos_ok;
}

static const char mc_tag[8] = "MCRUN01";

/* A checkpoint: the current pass (= passes completed) and elapsed time, then every thread's slot. */
static void mc_save(void *p)
{
    struct job *j = p;
    struct ckpt_buf b = {0};
    double elapsed = budget_seconds(j->o->cpu_time, j->o->threads) - j->t0;
    ckpt_put(&b, mc_tag, sizeof mc_tag);
    CKPT_PUT(&b, j->first);
    CKPT_PUT(&b, elapsed);
    ckpt_save_run(j->o->ckpt, &b, &j->sync);
}

static bool mc_resume_global(struct job *j, double *elapsed)
{
    struct ckpt_buf *b = j->o->ckpt->resume;
    char tag[sizeof mc_tag];
    b->pos = 0;
    ckpt_get(b, tag, sizeof tag);
    CKPT_GET(b, j->first);
    j->spp = j->first;
    CKPT_GET(b, *elapsed);
    j->resume = ckpt_resume_threads(b, j->o->threads);
    return j->resume && !memcmp(tag, mc_tag, sizeof tag) && j->first >= 0;
}

static void worker(int tid, void *p)
{
    struct job *j = p;
    const struct scene *sc = j->sc;
    const struct render_opts *o = j->o;
    struct path_ctx pc = {
        .sc = sc, .max_length = o->max_length, .min_length = o->min_length, .only_s = o->only_s, .only_t = o->only_t};
    struct scratch *w = xmalloc(sizeof *w);
    struct image *img = j->img[tid];
    int W = camera_film_width(&sc->cam), H = camera_film_height(&sc->cam);
    struct pixel_sampler s = {{&pixel_ops, 0, 0, 0}, {0, 0}, 0, 0, 1.0 / W, 1.0 / H, o->sobol, 0, 0};
    struct ckpt_sync *sync = o->ckpt ? &j->sync : NULL;
    struct mc_pos at = {j->g0 + tid, 0, j->first};
    bool bad = j->resume && !load_thread(&j->resume[tid], j, tid, &at, W, H);
    if (bad) atomic_store(&j->resume_bad, true);
    long done = j->samples[tid];
    w->nf = j->nf[tid];
    w->tech_k = j->tech ? o->tech_k : 0;
    if (o->seconds <= 0) progress_add(&j->prog, (at.y - j->g0 - tid) / j->stride);
    do {
        /* Ctrl-C is honoured within a pixel (every 4096 samples), not only between rows: a row of
         * a high-spp render can take minutes. */
        while (at.y < H && !bad) {
            while (at.x < W) {
                s.x0 = at.x;
                s.y0 = at.y;
                for (; at.i < j->first + j->count; at.i++) {
                    if (((at.i - j->first) & 4095) == 0 && interrupted()) goto stopped;
                    uint64_t cell = (uint64_t)at.y * W + at.x;
                    if (o->sobol) {
                        s.key = cell * 0x9E3779B97F4A7C15ull + o->seed;
                        s.index = (uint32_t)at.i;
                    } else {
                        rng_seed(&s.r, o->seed, cell * j->key + (uint64_t)at.i);
                    }
                    if (o->method == METHOD_PT)
                        pt_sample(&pc, &s.base, w, img);
                    else
                        bdpt_sample(&pc, &s.base, w, img);
                    if (j->tech) bdpt_tech_add(j->tech[tid], w);
                    done++;
                }
                at.x++;
                at.i = j->first;
                if (sync && o->seconds <= 0 && ckpt_sync_poll(sync)) {
                    j->samples[tid] = done;
                    j->nf[tid] = w->nf;
                    save_thread(&sync->slot[tid], j, tid, at);
                    ckpt_sync_arrive(sync);
                }
            }
            at.y += j->stride;
            at.x = 0;
            if (o->seconds <= 0) progress_add(&j->prog, 1);
        }
    stopped:
        j->samples[tid] = done;
        j->nf[tid] = w->nf;
        /* every thread meets the others after a pass, interrupted or not; an interrupted pass
         * ends the run, and `at` keeps where this thread stopped in it */
        if (o->seconds <= 0 || !pass_barrier_arrive(&j->passes)) break;
        at = (struct mc_pos){j->g0 + tid, 0, j->first}; /* next_pass set j->first */
    } while (true);
    if (sync) {
        save_thread(&sync->slot[tid], j, tid, at);
        ckpt_sync_finish(sync);
    }
    free(w);
}

/* Called between passes by one thread while the others wait: another pass only if it should end
 * within the budget at the mean pass time so far. Over MPI ranks the slowest rank's time counts
 * and rank 0 decides for all, so that every rank renders the same passes. A due checkpoint is
 * taken here, where every thread stands at the start of the next pass; rank 0 decides that too,
 * so every rank's checkpoint holds the same pass. */
static bool next_pass(void *p)
{
    struct job *j = p;
    j->spp++;
    double elapsed = dist_max_double(budget_seconds(j->o->cpu_time, j->o->threads) - j->t0);
    progress_set(&j->prog, (long)(1000 * elapsed));
    bool more = !(interrupted() || j->spp >= TIME_MODE_MAX_SPP || elapsed * (j->spp + 1) / j->spp > j->o->seconds);
    if (!dist_bcast_bool(more)) return false;
    j->first = j->spp;
    struct ckpt_ctl *ctl = j->o->ckpt;
    if (ctl && ctl->every > 0 && dist_bcast_bool(now_seconds() >= j->next_ckpt)) {
        for (int i = 0; i < j->o->threads; i++)
            save_thread(&j->sync.slot[i], j, i, (struct mc_pos){j->g0 + i, 0, j->first});
        mc_save(j);
        j->next_ckpt = now_seconds() + ctl->every;
    }
    return true;
}

struct tech_merge {
    struct bdpt_tech *out, **per_thread;
};

static void add_tech(void *ctx, int thread)
{
    struct tech_merge *m = ctx;
    bdpt_tech_accumulate(m->out, m->per_thread[thread]);
}

/* The threads' images, technique sums and counts merged over threads and ranks into the result
 * and st; the job's buffers freed. */
static struct image *finish(struct job *j, const struct render_opts *o, int spp, struct render_stats *st)
{
    const struct scene *sc = j->sc;
    int W = sc->cam.width, H = sc->cam.height, T = j->o->threads;
    free(j->resume);
    struct image *out = img_create(W, H);
    struct thread_results tr = {.threads = T, .img = j->img, .scale = 1.0 / spp};
    struct tech_merge tm = {NULL, j->tech};
    st->tech = NULL;
    if (j->tech) {
        st->tech = bdpt_tech_create(o->tech_k, W, H, sc->cam.filter == FILTER_TENT);
        tr.extra[tr.nextra++] = (struct dist_buf){st->tech->sum, bdpt_tech_bytes(st->tech)};
        tr.add = add_tech;
        tm.out = st->tech;
        tr.ctx = &tm;
    }
    merge_thread_results(&tr, out);
    if (j->tech)
        for (int i = 0; i < T; i++)
            bdpt_tech_free(j->tech[i]);
    free(j->tech);
    /* over the job's threads: integers, exact in any order */
    struct {
        long samples, interrupted, resume_bad;
        struct nonfinite nf;
    } counts = {0, interrupted(), atomic_load(&j->resume_bad), {{0}}};
    for (int i = 0; i < T; i++) {
        nonfinite_add(&counts.nf, &j->nf[i]);
        counts.samples += j->samples[i];
        img_destroy(j->img[i]);
    }
    dist_sum_longs((long *)&counts, sizeof counts / sizeof(long));
    st->nonfinite_len = counts.nf;
    st->nonfinite = nonfinite_total(&counts.nf);
    st->samples = counts.samples;
    st->resume_failed = counts.resume_bad > 0;
    st->seconds = budget_seconds(o->cpu_time, T) - j->t0;
    st->spp = spp;
    st->partial = counts.interrupted > 0;
    free(j->img);
    free(j->nf);
    free(j->samples);
    return out;
}

struct image *render_mc(const struct scene *sc, const struct render_opts *o, struct render_stats *st)
{
    int W = sc->cam.width, H = sc->cam.height, T = o->threads < 1 ? 1 : o->threads;
    ASSERT(o->max_length >= 1 && o->max_length <= MAX_PATH_LENGTH); /* the walks' arrays hold no more */
    struct render_opts opts = *o;
    opts.threads = T;
    struct job j = {.sc = sc,
                    .o = &opts,
                    .img = xcalloc((size_t)T, sizeof(struct image *)),
                    .nf = xcalloc((size_t)T, sizeof(struct nonfinite)),
                    .samples = xcalloc((size_t)T, sizeof(long)),
                    .g0 = dist_thread0(T),
                    .stride = dist_size() * T};
    for (int i = 0; i < T; i++) {
        j.img[i] = img_create(W, H);
        j.img[i]->tent = sc->cam.filter == FILTER_TENT;
    }
    if (o->tech_k > 0) {
        ASSERT(o->method == METHOD_BDPT && o->tech_k <= o->max_length);
        j.tech = xcalloc((size_t)T, sizeof *j.tech);
        for (int i = 0; i < T; i++)
            j.tech[i] = bdpt_tech_create(o->tech_k, W, H, sc->cam.filter == FILTER_TENT);
    }
    double t0 = budget_seconds(o->cpu_time, T), elapsed0 = 0;
    if (o->ckpt && o->ckpt->resume) {
        long bad = !mc_resume_global(&j, &elapsed0);
        /* ranks must agree, and under a time budget be at the same pass: a job stopped between
         * two ranks' writes left checkpoints of different passes, whose passes would not meet */
        if (o->seconds > 0 && dist_max_double(j.first) != -dist_max_double(-j.first)) bad = 1;
        dist_sum_longs(&bad, 1);
        if (bad) atomic_store(&j.resume_bad, true);
    }
    if (o->ckpt) {
        /* periodic checkpoints poll per pixel with a spp budget, and are taken between passes
         * with a time budget (next_pass) */
        ckpt_sync_init(&j.sync, T, o->seconds > 0 ? 0 : o->ckpt->every, mc_save, &j);
        j.next_ckpt = now_seconds() + o->ckpt->every;
    }
    j.t0 = t0 - elapsed0;
    int spp = o->spp;
    if (atomic_load(&j.resume_bad)) {
        progress_init(&j.prog, method_name(o->method), 1, false);
        spp = 1; /* no work: the caller reports the mismatch */
    } else if (o->seconds > 0) {
        progress_init(&j.prog, method_name(o->method), (long)(1000 * o->seconds), o->progress);
        j.count = 1;
        j.key = TIME_MODE_MAX_SPP;
        pass_barrier_init(&j.passes, T, next_pass, &j);
        parallel_run(T, worker, &j);
        pass_barrier_destroy(&j.passes);
        spp = j.spp;
    } else {
        int rows = 0; /* this rank's */
        for (int y = 0; y < camera_film_height(&sc->cam); y++)
            rows += y % j.stride >= j.g0 && y % j.stride < j.g0 + T;
        progress_init(&j.prog, method_name(o->method), rows, o->progress);
        j.count = spp;
        j.key = (uint64_t)spp;
        parallel_run(T, worker, &j);
    }
    progress_finish(&j.prog);
    if (o->ckpt) {
        if (interrupted()) mc_save(&j); /* Ctrl-C: every thread stored where it stopped */
        ckpt_sync_destroy(&j.sync);
    }
    return finish(&j, o, spp, st);
}
