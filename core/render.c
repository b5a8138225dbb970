#include "render.h"
#include "camera.h"
#include "dist.h"
#include "dist_merge.h"
#include "integrator.h"
#include "parallel.h"
#include "util.h"
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
 * independent. The annotation is what makes this possible without touching path code. */
struct pixel_sampler {
    struct sampler base;
    rng r;
    double x0, y0, sx, sy;
};

static double pixel_next(struct sampler *s, enum dim_kind kind)
{
    struct pixel_sampler *p = (struct pixel_sampler *)s;
    double u = rng_uniform(&p->r);
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
    long *nonfinite, *samples;
    struct progress prog;
    int first, count; /* samples first .. first + count - 1 of every pixel */
    uint64_t key;     /* sample i of film cell c draws from stream c * key + i */
    int g0, stride;   /* this rank's first global thread; the job's threads (core/dist.h) */
    /* --time: passes of one sample per pixel until the budget */
    struct pass_barrier passes;
    int spp;          /* passes done */
    double t0;
};

static void worker(int tid, void *p)
{
    struct job *j = p;
    const struct scene *sc = j->sc;
    const struct render_opts *o = j->o;
    struct path_ctx pc = {.sc = sc, .max_length = o->max_length, .min_length = o->min_length, .only_s = o->only_s, .only_t = o->only_t};
    struct scratch *w = xmalloc(sizeof *w);
    w->nonfinite = 0;
    struct image *img = j->img[tid];
    int W = camera_film_width(&sc->cam), H = camera_film_height(&sc->cam);
    struct pixel_sampler s = {{&pixel_ops, 0, 0, 0}, {0, 0}, 0, 0, 1.0 / W, 1.0 / H};
    long done = 0;
    do {
        /* Ctrl-C is honoured within a pixel (every 4096 samples), not only between rows: a row of
         * a high-spp render can take minutes. */
        bool stop = false;
        for (int y = j->g0 + tid; y < H && !stop; y += j->stride) {
            for (int x = 0; x < W && !stop; x++) {
                s.x0 = x;
                s.y0 = y;
                for (int i = j->first; i < j->first + j->count; i++) {
                    if (((i - j->first) & 4095) == 0 && (stop = interrupted())) break;
                    rng_seed(&s.r, o->seed, ((uint64_t)y * W + x) * j->key + (uint64_t)i);
                    if (o->method == METHOD_PT) pt_sample(&pc, &s.base, w, img);
                    else bdpt_sample(&pc, &s.base, w, img);
                    done++;
                }
            }
            if (o->seconds <= 0) progress_add(&j->prog, 1);
        }
    } while (o->seconds > 0 && pass_barrier_arrive(&j->passes));
    j->nonfinite[tid] += w->nonfinite;
    j->samples[tid] += done;
    free(w);
}

/* Called between passes by one thread while the others wait: another pass only if it should end
 * within the budget at the mean pass time so far. Over MPI ranks the slowest rank's time counts
 * and rank 0 decides for all, so that every rank renders the same passes. */
static bool next_pass(void *p)
{
    struct job *j = p;
    j->spp++;
    double elapsed = dist_max_double(now_seconds() - j->t0);
    progress_set(&j->prog, (long)(1000 * elapsed));
    bool more = !(interrupted() || j->spp >= TIME_MODE_MAX_SPP || elapsed * (j->spp + 1) / j->spp > j->o->seconds);
    if (!dist_bcast_bool(more)) return false;
    j->first = j->spp;
    return true;
}

struct image *render_mc(const struct scene *sc, const struct render_opts *o, struct render_stats *st)
{
    int W = sc->cam.width, H = sc->cam.height, T = o->threads < 1 ? 1 : o->threads;
    struct render_opts opts = *o;
    opts.threads = T;
    struct job j = {.sc = sc, .o = &opts, .img = xcalloc((size_t)T, sizeof(struct image *)),
                    .nonfinite = xcalloc((size_t)T, sizeof(long)), .samples = xcalloc((size_t)T, sizeof(long)),
                    .g0 = dist_thread0(T), .stride = dist_size() * T};
    for (int i = 0; i < T; i++) {
        j.img[i] = img_create(W, H);
        j.img[i]->tent = sc->cam.filter == FILTER_TENT;
    }
    double t0 = now_seconds();
    j.t0 = t0;
    int spp = o->spp;
    if (o->seconds > 0) {
        progress_init(&j.prog, method_name(o->method), (long)(1000 * o->seconds), o->progress);
        j.count = 1;
        j.key = TIME_MODE_MAX_SPP;
        j.first = 0;
        pass_barrier_init(&j.passes, T, next_pass, &j);
        parallel_run(T, worker, &j);
        pass_barrier_destroy(&j.passes);
        spp = j.spp;
    } else {
        int rows = 0; /* this rank's */
        for (int y = 0; y < camera_film_height(&sc->cam); y++) rows += y % j.stride >= j.g0 && y % j.stride < j.g0 + T;
        progress_init(&j.prog, method_name(o->method), rows, o->progress);
        j.count = spp;
        j.key = (uint64_t)spp;
        parallel_run(T, worker, &j);
    }
    progress_finish(&j.prog);
    struct image *out = img_create(W, H);
    merge_thread_results(&(struct thread_results){.threads = T, .img = j.img, .scale = 1.0 / spp}, out, NULL, NULL);
    long counts[3] = {0, 0, interrupted()}; /* over the job's threads: integers, exact in any order */
    for (int i = 0; i < T; i++) {
        counts[0] += j.nonfinite[i];
        counts[1] += j.samples[i];
        img_destroy(j.img[i]);
    }
    dist_sum_longs(counts, 3);
    st->nonfinite = counts[0];
    st->samples = counts[1];
    st->seconds = now_seconds() - t0;
    st->spp = spp;
    st->partial = counts[2] > 0;
    free(j.img);
    free(j.nonfinite);
    free(j.samples);
    return out;
}
