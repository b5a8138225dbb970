/* Reference image of the CMLT toy; see cmlt_reference.h. */
#include "cmlt/cmlt_reference.h"
#include "base/parallel.h"
#include "base/rng.h"
#include "base/util.h"
#include "cmlt/cmlt_scene.h"
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

struct ref_job {
    int w, h, spp, nthreads, id;
    uint64_t seed;
    double *img, *var;
    double b[3];
    struct progress *progress;
};

static inline void add_b(double *b, const struct cmlt_eval *e, double k)
{
    double s = e->p1 + e->p2;
    b[0] += e->fs * k;
    b[1] += e->fs * k * e->p1 / s;
    b[2] += e->fs * k * e->p2 / s;
}

static void *ref_worker(void *arg)
{
    struct ref_job *J = arg;
    int sq = (int)sqrt((double)J->spp);
    if (sq < 1) sq = 1;
    int n = sq * sq;
    double phi1 = cmlt_phi1();
    for (int j = J->id; j < J->h; j += J->nthreads) {
        rng r;
        rng_seed(&r, J->seed, 0x5eedull + (uint64_t)j);
        for (int i = 0; i < J->w; i++) {
            double sum[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
            for (int s = 0; s < n; s++) {
                struct cmlt_path x;
                struct cmlt_eval e;
                rgb c = v3s(0);
                x.gx = (i + (s % sq + rng_uniform(&r)) / sq) / J->w;
                x.gy = 1.0 - (j + (s / sq + rng_uniform(&r)) / sq) / J->h;
                double kb = 1.0 / ((double)n * J->w * J->h); /* b contributions per sample */
                /* light 1 by emission */
                x.light = CMLT_L1;
                x.la = log1p(rng_uniform(&r) * (CMLT_EXPK1 - 1.0)) / CMLT_K1;
                x.lb = rng_uniform(&r);
                cmlt_eval(&x, &e);
                if (e.fs > 0) {
                    double pa = cmlt_le_star(CMLT_L1, x.la) / phi1, k = 1.0 / (pa + e.p2);
                    c = vadd(c, vscale(e.f, k));
                    add_b(J->b, &e, k * kb);
                }
                /* cosine direction, kept on light 1 */
                double u2 = rng_uniform(&r), ph = 2 * M_PI * rng_uniform(&r), rr = sqrt(u2);
                if (cmlt_trace(x.gx, x.gy, v3(rr * cos(ph), rr * sin(ph), sqrt(1 - u2)), &x) && x.light == CMLT_L1) {
                    cmlt_eval(&x, &e);
                    if (e.fs > 0) {
                        double pa = cmlt_le_star(CMLT_L1, x.la) / phi1, k = 1.0 / (pa + e.p2);
                        c = vadd(c, vscale(e.f, k));
                        add_b(J->b, &e, k * kb);
                    }
                }
                /* light 2 through the hole */
                double hx = CMLT_HOLE_X + CMLT_HOLE_R * (2 * rng_uniform(&r) - 1);
                double hz = CMLT_HOLE_Z + CMLT_HOLE_R * (2 * rng_uniform(&r) - 1);
                double lam = (CMLT_L2_Y - x.gy) / (1.0 - x.gy);
                x.light = CMLT_L2;
                x.la = x.gx + lam * (hx - x.gx);
                x.lb = lam * hz;
                if (x.la >= 0 && x.la <= 1 && x.lb <= 1) {
                    cmlt_eval(&x, &e);
                    if (e.fs > 0) {
                        double k = 4 * CMLT_HOLE_R * CMLT_HOLE_R * lam * lam;
                        c = vadd(c, vscale(e.f, k));
                        add_b(J->b, &e, k * kb);
                    }
                }
                for (int q = 0; q < 3; q++) {
                    double v = vget(c, q);
                    sum[q] += v;
                    sum2[q] += v * v;
                }
            }
            double *p = J->img + 3 * ((size_t)j * J->w + i);
            for (int q = 0; q < 3; q++) {
                double m = sum[q] / n;
                p[q] = m;
                J->var[3 * ((size_t)j * J->w + i) + q] = fmax(0.0, sum2[q] / n - m * m) / n;
            }
        }
        if (J->progress) progress_add(J->progress, (long)J->w * n);
    }
    return NULL;
}

void cmlt_reference(int w, int h, int spp, uint64_t seed, int threads, double *img, struct cmlt_ref_result *res,
                    struct progress *progress)
{
    if (threads < 1) threads = 1;
    double *var = xmalloc(sizeof(double) * 3 * (size_t)w * h);
    struct ref_job *jobs = xcalloc((size_t)threads, sizeof *jobs);
    pthread_t *tid = xmalloc(sizeof *tid * (size_t)threads);
    for (int t = 0; t < threads; t++) {
        jobs[t] = (struct ref_job){.w = w,
                                   .h = h,
                                   .spp = spp,
                                   .nthreads = threads,
                                   .id = t,
                                   .seed = seed,
                                   .img = img,
                                   .var = var,
                                   .progress = progress};
        ASSERT(pthread_create(&tid[t], NULL, ref_worker, &jobs[t]) == 0);
    }
    memset(res, 0, sizeof *res);
    for (int t = 0; t < threads; t++) {
        pthread_join(tid[t], NULL);
        for (int q = 0; q < 3; q++)
            res->b[q] += jobs[t].b[q]; /* fixed order: deterministic */
    }
    double v = 0;
    for (size_t i = 0; i < 3 * (size_t)w * h; i++)
        v += var[i];
    res->noise_rmse = sqrt(v / (3.0 * w * h));
    free(var);
    free(jobs);
    free(tid);
}
