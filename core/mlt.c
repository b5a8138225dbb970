/* PSSMLT and MMLT drivers: seed pass, chain start by resampling, Metropolis iterations with
 * expected-value splatting, statistics. See mlt.h for the method definitions. */
#include "mlt.h"
#include "connect.h"
#include "integrator.h"
#include "parallel.h"
#include "util.h"
#include <stdlib.h>
#include <string.h>

/* Evaluates the state the sampler describes; returns the scalar target (0 for no contribution).
 * For MMLT, *tech receives the camera vertex count t. */
static double eval_state(enum mlt_method m, const struct path_ctx *pc, struct sampler *s, struct scratch *w, int k,
                         struct splat_list *out, int *tech)
{
    out->n = 0;
    *tech = 0;
    if (m == MLT_PSSMLT) {
        bdpt_splats(pc, s, w, out);
    } else {
        sampler_begin(s, STREAM_TECHNIQUE, 0);
        int t = 1 + (int)((k + 1) * sampler_next(s, DIM_TECHNIQUE));
        if (t > k + 1) t = k + 1;
        int sv = k + 1 - t;
        *tech = t;
        int nz = walk_camera(pc, s, w->cam, t);
        int ny = sv > 0 ? walk_emitter(pc, s, w->emi, sv) : 0;
        struct connection c;
        if (nz == t && ny == sv && connect_st(pc, w->emi, sv, w->cam, t, k, &c, NULL)) {
            rgb v = vscale(c.f, c.w * (k + 1));
            if (vfinite(v)) splat_push(out, c.px, c.py, v);
            else w->nonfinite++;
        }
    }
    double f = splat_luminance(out);
    return isfinite(f) && f > 0 ? f : 0;
}

struct seed_job {
    const struct scene *sc;
    const struct mlt_opts *o;
    int nk;            /* chains per thread: 1 (PSSMLT) or K (MMLT) */
    double *f;         /* seed_paths * nk targets, index i * nk + (k - 1) */
    struct progress prog;
};

static uint64_t seed_stream(long i, int nk, int kk) { return (uint64_t)i * (uint64_t)nk + (uint64_t)kk; }

static void seed_worker(int tid, void *p)
{
    struct seed_job *j = p;
    struct path_ctx pc = {.sc = j->sc, .max_length = j->o->max_length};
    struct scratch *w = xmalloc(sizeof *w);
    struct sampler_independent s;
    struct splat_list l;
    int tech;
    for (long i = tid; i < j->o->seed_paths; i += j->o->threads) {
        for (int kk = 0; kk < j->nk; kk++) {
            sampler_independent_init(&s, j->o->seed, seed_stream(i, j->nk, kk));
            j->f[i * j->nk + kk] = eval_state(j->o->method, &pc, &s.base, w, kk + 1, &l, &tech);
        }
        if ((i / j->o->threads) % 1024 == 0) progress_add(&j->prog, 1024);
    }
    free(w);
}

struct chain {
    struct pss_sampler pss;
    struct splat_list cur;
    double f;
    int k, tech;
};

struct run_job {
    const struct scene *sc;
    const struct mlt_opts *o;
    int nk;
    const double *f;          /* seed targets */
    const double *cdf[MAX_PATH_LENGTH + 1]; /* per chain index: seed-pool CDF over i */
    double kcdf[MAX_PATH_LENGTH + 2];       /* length selection */
    struct image **img;
    struct mlt_stats *stats;
    long *done;
    double t0;
    struct progress prog;
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

static void run_worker(int tid, void *p)
{
    struct run_job *j = p;
    const struct mlt_opts *o = j->o;
    struct path_ctx pc = {.sc = j->sc, .max_length = o->max_length};
    struct scratch *w = xmalloc(sizeof *w);
    w->nonfinite = 0;
    struct chain *ch = xcalloc((size_t)j->nk, sizeof *ch);
    struct mlt_stats *st = &j->stats[tid];
    struct image *img = j->img[tid];
    rng r;
    rng_seed(&r, o->seed, 0x9E3779B97F4A7C15ULL + (uint64_t)tid);
    /* Start every chain from a seed sample resampled in proportion to its target. */
    for (int kk = 0; kk < j->nk; kk++) {
        struct chain *c = &ch[kk];
        c->k = kk + 1;
        if (!j->cdf[kk]) continue;
        long i = pick_cdf(j->cdf[kk], o->seed_paths, rng_uniform(&r));
        pss_init(&c->pss, &o->pss, o->seed, seed_stream(i, j->nk, kk));
        c->f = eval_state(o->method, &pc, &c->pss.base, w, c->k, &c->cur, &c->tech);
        pss_accept(&c->pss);
    }
    long budget = o->mutations / o->threads + (tid < o->mutations % o->threads);
    long n = 0;
    struct splat_list prop;
    for (;; n++) {
        if (o->seconds > 0) {
            if ((n & 255) == 0 && now_seconds() - j->t0 >= o->seconds) break;
        } else if (n >= budget) {
            break;
        }
        int kk = 0;
        if (j->nk > 1) {
            double u = rng_uniform(&r) * j->kcdf[j->nk];
            while (kk < j->nk - 1 && j->kcdf[kk + 1] <= u) kk++;
        }
        struct chain *c = &ch[kk];
        bool large = rng_uniform(&r) < o->p_large;
        pss_begin(&c->pss, large);
        int tech;
        double f = eval_state(o->method, &pc, &c->pss.base, w, c->k, &prop, &tech);
        double a = c->f > 0 ? fmin(1.0, f / c->f) : 1.0;
        /* expected values: the proposal with weight a, the current state with 1 - a */
        if (f > 0) splat_list_weighted(img, &prop, a / f);
        if (c->f > 0) splat_list_weighted(img, &c->cur, (1 - a) / c->f);
        bool acc = rng_uniform(&r) < a;
        stats_record(st, large ? PROPOSAL_LARGE : PROPOSAL_SMALL, o->method == MLT_MMLT ? c->k : 0,
                     o->method == MLT_MMLT && tech != c->tech, a, acc, f > 0);
        if (acc) {
            pss_accept(&c->pss);
            c->cur = prop;
            c->f = f;
            c->tech = tech;
        } else {
            pss_reject(&c->pss);
        }
        if ((n & 4095) == 4095) progress_add(&j->prog, o->seconds > 0 ? 0 : 4096);
    }
    j->done[tid] = n;
    st->nonfinite += w->nonfinite;
    free(ch);
    free(w);
}

bool mlt_render(const struct scene *sc, const struct mlt_opts *o_in, struct mlt_result *r, char *err, size_t errlen)
{
    struct mlt_opts o = *o_in;
    if (o.threads < 1) o.threads = 1;
    int W = sc->cam.width, H = sc->cam.height, T = o.threads;
    int nk = o.method == MLT_MMLT ? o.max_length : 1;
    memset(r, 0, sizeof *r);
    double t0 = now_seconds();

    struct seed_job sj = {sc, &o, nk, xmalloc((size_t)o.seed_paths * nk * sizeof(double)), {0}};
    progress_init(&sj.prog, "seed pass", o.seed_paths, o.progress);
    parallel_run(T, seed_worker, &sj);
    progress_finish(&sj.prog);

    struct run_job rj;
    memset(&rj, 0, sizeof rj);
    rj.sc = sc;
    rj.o = &o;
    rj.nk = nk;
    rj.f = sj.f;
    double total = 0;
    for (int kk = 0; kk < nk; kk++) {
        double *cdf = xmalloc((size_t)o.seed_paths * sizeof(double)), acc = 0;
        for (long i = 0; i < o.seed_paths; i++) cdf[i] = acc += sj.f[i * nk + kk];
        r->b_k[kk + 1] = acc / o.seed_paths;
        total += r->b_k[kk + 1];
        if (acc > 0) rj.cdf[kk] = cdf;
        else free(cdf);
        rj.kcdf[kk + 1] = total;
    }
    r->b = total;
    r->seed_seconds = now_seconds() - t0;
    if (!(total > 0)) {
        snprintf(err, errlen, "%s: the seed pass of %ld paths found no light; raise --seed-paths", sc->file, o.seed_paths);
        for (int kk = 0; kk < nk; kk++) free((void *)rj.cdf[kk]);
        free(sj.f);
        return false;
    }
    rj.img = xcalloc((size_t)T, sizeof(struct image *));
    rj.stats = xcalloc((size_t)T, sizeof(struct mlt_stats));
    rj.done = xcalloc((size_t)T, sizeof(long));
    for (int i = 0; i < T; i++) rj.img[i] = img_create(W, H);
    rj.t0 = now_seconds();
    progress_init(&rj.prog, o.method == MLT_MMLT ? "mmlt" : "pssmlt", o.seconds > 0 ? 1 : o.mutations, o.progress);
    parallel_run(T, run_worker, &rj);
    progress_finish(&rj.prog);
    r->seconds = now_seconds() - rj.t0;
    for (int i = 0; i < T; i++) r->mutations += rj.done[i];
    r->img = img_create(W, H);
    stats_clear(&r->stats);
    double scale = r->mutations > 0 ? (double)W * H * total / (double)r->mutations : 0;
    for (int i = 0; i < T; i++) { /* fixed order: reproducible sums */
        img_accumulate(r->img, rj.img[i], scale);
        stats_merge(&r->stats, &rj.stats[i]);
        img_destroy(rj.img[i]);
    }
    r->nonfinite = r->stats.nonfinite;
    for (int kk = 0; kk < nk; kk++) free((void *)rj.cdf[kk]);
    free(rj.img);
    free(rj.stats);
    free(rj.done);
    free(sj.f);
    return true;
}

void mlt_result_free(struct mlt_result *r)
{
    img_destroy(r->img);
    r->img = NULL;
}
