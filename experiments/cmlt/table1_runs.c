/* bin/table1_cmlt's runs (table1.h): the cached reference, and the chains of every (seed, budget,
 * algorithm) drawn from one queue by o->threads workers, largest budgets first to balance the load,
 * with a progress bar while they run. */
#include "base/parallel.h"
#include "base/util.h"
#include "cmlt/cmlt_scene.h"
#include "cmlt/table1.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The bar (or, into a log, a line every 10 s) ends with the phase's time, which the logs of long
 * paper-scale runs are read for. */
static void table1_progress_done(struct progress *prog)
{
    progress_finish(prog);
    fprintf(stderr, "%s done in %.1fs\n", prog->label, now_seconds() - prog->start);
}

struct image *table1_reference(const struct table1_opts *o, struct cmlt_ref_result *res)
{
    char path[1024], keypath[1024], key[512], err[512];
    snprintf(path, sizeof path, "%s/reference.exr", o->out);
    snprintf(keypath, sizeof keypath, "%s/reference.key", o->out);
    /* The scene's fingerprint stands for every constant and line of the toy; bump the version when
     * cmlt_reference.c's estimator changes. */
    snprintf(key, sizeof key, "cmlt-reference-v3 res=%d spp=%d scene=%016llx\n", o->res, o->ref_spp,
             (unsigned long long)cmlt_scene_fingerprint());
    FILE *f = fopen(keypath, "r");
    if (f) {
        char line[1024] = "";
        double b0, b1, b2, nr;
        bool ok =
            fgets(line, sizeof line, f) && !strcmp(line, key) && fscanf(f, "%lf %lf %lf %lf", &b0, &b1, &b2, &nr) == 4;
        fclose(f);
        if (ok) {
            struct image *im = img_read(path, err, sizeof err);
            if (im && im->w == o->res && im->h == o->res) {
                *res = (struct cmlt_ref_result){{b0, b1, b2}, nr};
                fprintf(stderr, "reference: cached %s\n", path);
                return im;
            }
            img_destroy(im);
        }
    }
    struct image *im = img_create(o->res, o->res);
    int sq = (int)sqrt((double)o->ref_spp);
    struct progress prog;
    progress_init(&prog, "reference", (long)o->res * o->res * sq * sq, true);
    cmlt_reference(o->res, o->res, o->ref_spp, 0xC3117ull, o->threads, im->px, res, &prog);
    table1_progress_done(&prog);
    table1_save_or_die(img_write_exr(im, 1.0, path, err, sizeof err), err);
    snprintf(path, sizeof path, "%s/reference.png", o->out);
    table1_save_or_die(img_write_png(im, 1.0, path, err, sizeof err), err);
    struct text_out kt;
    if (text_out_open(&kt))
        fprintf(kt.f, "%s%.17g %.17g %.17g %.17g\n", key, res->b[0], res->b[1], res->b[2], res->noise_rmse);
    table1_save_or_die(text_out_save(&kt, keypath, err, sizeof err), err);
    return im;
}

static double rmse(const double *a, const double *b, size_t n)
{
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s += (a[i] - b[i]) * (a[i] - b[i]);
    return sqrt(s / n);
}

static void worker(int tid, void *arg)
{
    (void)tid;
    struct table1_pool *p = arg;
    const struct table1_opts *o = p->o;
    size_t npx = 3 * (size_t)o->res * o->res;
    double *scratch = xmalloc(sizeof(double) * npx);
    for (;;) {
        int k = atomic_fetch_add(&p->next, 1);
        if (k >= p->njobs) break;
        struct table1_job *J = &p->jobs[k];
        struct cmlt_config c;
        cmlt_config_default(&c);
        c.w = c.h = o->res;
        c.n = J->n;
        c.n_seed = (uint64_t)(o->seed_frac * J->n);
        if (c.n_seed < 1024) c.n_seed = 1024;
        c.p_large = o->p_large;
        c.swap_every = o->swap_every;
        double *img = J->seed_idx == 0 ? p->keep[J->bidx * CMLT_NALGO + J->algo] : scratch;
        uint64_t seed = o->seed * 1000003ull + (uint64_t)J->seed_idx;
        uint64_t stream = (uint64_t)J->bidx * 64 + (uint64_t)J->algo;
        cmlt_run((enum cmlt_algo)J->algo, &c, seed, stream, img, &J->st, &p->progress, p->stop);
        J->rmse = p->ref ? rmse(img, p->ref->px, npx) : 0;
    }
    free(scratch);
}

static int cmp_job(const void *a, const void *b)
{
    const struct table1_job *x = a, *y = b; /* largest budgets first, then seed, algorithm: load balance */
    if (x->n != y->n) return x->n < y->n ? 1 : -1;
    if (x->seed_idx != y->seed_idx) return x->seed_idx - y->seed_idx;
    return x->algo - y->algo;
}

void table1_pool_make(struct table1_pool *p)
{
    const struct table1_opts *o = p->o;
    p->njobs = o->seeds * o->nbudgets * CMLT_NALGO;
    p->jobs = xcalloc((size_t)p->njobs, sizeof *p->jobs);
    int k = 0;
    for (int s = 0; s < o->seeds; s++)
        for (int b = 0; b < o->nbudgets; b++)
            for (int a = 0; a < CMLT_NALGO; a++)
                p->jobs[k++] = (struct table1_job){.algo = a, .bidx = b, .seed_idx = s, .n = o->budgets[b]};
    qsort(p->jobs, (size_t)p->njobs, sizeof *p->jobs, cmp_job);
    size_t npx = 3 * (size_t)o->res * o->res;
    p->keep = xmalloc(sizeof(double *) * o->nbudgets * CMLT_NALGO);
    for (int i = 0; i < o->nbudgets * CMLT_NALGO; i++)
        p->keep[i] = xmalloc(sizeof(double) * npx);
}

void table1_pool_free(struct table1_pool *p)
{
    for (int i = 0; i < p->o->nbudgets * CMLT_NALGO; i++)
        free(p->keep[i]);
    free(p->keep);
    free(p->jobs);
}

void table1_pool_run(struct table1_pool *p, const char *what)
{
    const struct table1_opts *o = p->o;
    uint64_t total = 0;
    for (int i = 0; i < p->njobs; i++)
        total +=
            p->jobs[i].n -
            p->jobs[i].n %
                (p->jobs[i].algo == CMLT_PSS1 || p->jobs[i].algo == CMLT_PSS2 || p->jobs[i].algo == CMLT_EPSM ? 1 : 2);
    atomic_init(&p->next, 0);
    progress_init(&p->progress, what, (long)total, true);
    parallel_run(o->threads, worker, p);
    table1_progress_done(&p->progress);
}
