/* Thesis §5.1, Eq. 5.3 (claim T21): "the values returned by the inverse random walk for a path are
 * distributed with the same density as the numbers with which the path was sampled", tested for
 * every sampling function with an inverse (inv_funcs.h) by goodness of fit of the inverted numbers
 * of forward-sampled paths (inv_run.h, inv_gof.h). Writes OUT/inverse_density.csv (one row per
 * function), OUT/inverse_density.md and the claims files; --require-holds makes a verdict other
 * than "holds" exit status 1 (make check-inverse-density). */
#include "base/parallel.h"
#include "base/util.h"
#include "ch5/inv_report.h"
#include "ch5/inv_run.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/outdir.h"
#include "path/scene_ready.h"
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_FUNCS = 160, MAX_SCENES = 16 };

/* The techniques (s, t) of the path functions: lengths 2 and 3, every kind of connection (s = 0
 * hits the emitter, t = 1 connects to the camera). */
static const int techniques[][2] = {{0, 3}, {1, 2}, {2, 1}, {2, 2}, {1, 3}};

struct job {
    struct inv_func *f;
    struct inv_result *r;
    int n;
    long samples, path_samples;
    uint64_t seed;
    const char *broken;
    atomic_int next;
};

static void worker(int tid, void *ctx)
{
    (void)tid;
    struct job *j = ctx;
    struct inv_scratch *x = xmalloc(sizeof *x);
    for (int i; (i = atomic_fetch_add(&j->next, 1)) < j->n;) {
        const struct inv_func *f = &j->f[i];
        long n = f->kind == INV_PATH ? j->path_samples : j->samples;
        inv_run(f, x, n, j->seed, j->broken && !strcmp(j->broken, f->name) ? 0.99 : 1, &j->r[i]);
        fprintf(stderr, "inverse_density: %s: %ld inverted, %ld failed, p = %.3g (chi2), %.3g (KS)\n", f->name,
                j->r[i].samples, j->r[i].failures, j->r[i].g.chi_p_adj, j->r[i].g.ks_p_adj);
    }
    free(x);
}

/* Scene `name` of scenes/, loaded once. */
static struct scene *scene_named(const char *prog, const char *name, char (*names)[64], struct scene **sc, int *n)
{
    for (int i = 0; i < *n; i++)
        if (!strcmp(names[i], name)) return sc[i];
    if (*n == MAX_SCENES) die(DIE_USAGE, prog, "more than %d scenes", MAX_SCENES);
    char path[256], err[1024];
    snprintf(path, sizeof path, "scenes/%.200s/scene.json", name);
    struct scene *s = scene_load(path, err, sizeof err);
    if (!s) die(DIE_USAGE, prog, "%s", err);
    snprintf(names[*n], 64, "%.63s", name);
    sc[*n] = s;
    return sc[(*n)++];
}

/* Every function of the scenes named in the comma-separated lists. */
static int build_funcs(const char *prog, const char *bsdf_list, const char *path_list, struct inv_func *f,
                       struct scene **sc, int *nsc, struct scene *lens)
{
    static char names[MAX_SCENES][64];
    int n = 0, nl = 0;
    unsigned long seen = 0;
    for (int pass = 0; pass < 2; pass++) {
        char buf[1024];
        snprintf(buf, sizeof buf, "%s", pass ? path_list : bsdf_list);
        for (char *save, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
            struct scene *s = scene_named(prog, tok, names, sc, nsc);
            bool ok = pass ? inv_funcs_scene(s, &lens[nl++], tok, techniques, 5, f, &n, MAX_FUNCS)
                           : inv_funcs_bsdf(s, tok, &seen, f, &n, MAX_FUNCS);
            if (!ok || nl == MAX_SCENES) die(DIE_USAGE, prog, "more than %d functions", MAX_FUNCS);
        }
    }
    return n;
}

int main(int argc, char **argv)
{
    const char *prog = "inverse_density";
    struct inv_cfg c = {.prog = prog};
    struct opts_figure fig = {0};
    const struct opt opts[] = {
        OPT_SCALE(fig),
        OPT_SEED(c.seed, .help = "random seed of every function's numbers (with its name)", .def = "1"),
        OPT_THREADS(c.threads, .hi = 1024, .help = "worker threads (default: all cores)", .def_int = cpu_count),
        OPT_OUT(c.out, .arg = "DIR", .help = "output folder", .def = "results/inverse-density"),
        {"--samples", OPT_INT, OPT_DST(c.samples), .arg = "N", .lo = 2000, .hi = 1L << 30,
         .help = "forward samples per pass of a BSDF, camera or emitter function", .def = "200000", .paper = "1000000"},
        {"--path-samples", OPT_INT, OPT_DST(c.path_samples), .arg = "N", .lo = 2000, .hi = 1L << 30,
         .help = "forward samples per pass of a path function", .def = "40000", .paper = "200000"},
        {"--bsdf-scenes", OPT_STRING, OPT_DST(c.bsdf_scenes), .arg = "A,B",
         .help = "scenes of scenes/ whose BSDF types are tested (each type once)",
         .def = "cornell-box,ajar,materials,surfaces"},
        {"--path-scenes", OPT_STRING, OPT_DST(c.path_scenes), .arg = "A,B",
         .help = "scenes of scenes/ whose camera, emitter and paths are tested", .def = "cornell-box,ajar"},
        {"--break-inverse", OPT_STRING, OPT_DST(c.broken), .arg = "NAME",
         .help = "scale the first inverted number of function NAME by 0.99 (a broken inverse the test must reject)"},
        {"--require-holds", OPT_FLAG, OPT_DST(c.require_holds),
         .help = "exit status 1 unless the verdict is \"holds\" (make check-inverse-density)"},
        {0}};
    opts_parse(&(struct opts_spec){.prog = prog,
                                   .usage = "usage: inverse_density [options]\n",
                                   .about = "Thesis Eq. 5.3: are inverted numbers distributed as forward ones?",
                                   .opts = opts,
                                   .fig = &fig},
               argc, argv);
    c.scale = fig.scale;
    outdir_require(prog, c.out);
    static struct inv_func f[MAX_FUNCS];
    static struct inv_result r[MAX_FUNCS];
    struct scene *sc[MAX_SCENES], lens[MAX_SCENES];
    int nsc = 0;
    int n = build_funcs(prog, c.bsdf_scenes, c.path_scenes, f, sc, &nsc, lens);
    bool found = !c.broken;
    for (int i = 0; i < n && !found; i++)
        found = !strcmp(f[i].name, c.broken);
    if (!found) die(DIE_USAGE, prog, "--break-inverse: no function '%s'", c.broken);
    struct job j = {f, r, n, c.samples, c.path_samples, c.seed, c.broken, 0};
    parallel_run(c.threads, worker, &j);
    bool holds = inv_report(&c, f, r, n);
    for (int i = 0; i < nsc; i++)
        scene_free(sc[i]);
    return c.require_holds && !holds ? 1 : 0;
}
