/* bin/ch6_equal's runs (ch6_equal.h): for each seed, budget and method (interleaved, common/runner.h)
 * one bin/render command line, run in-process, checkpointed and resumable (common/proc.h); its image against the
 * reference and its statistics CSV read by column name and metadata key (common/csv_read.h). */
#include "base/util.h"
#include "ch6/ch6_equal.h"
#include "ch6/ch6_stats.h"
#include "common/csv_read.h"
#include "common/die.h"
#include "common/proc.h"
#include "common/runner.h"
#include "io/image.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* A run of an earlier, interrupted ch6_equal that completed: its CSV is there, not marked partial,
 * and newer than the scene. */
static bool run_complete(const char *exr, const char *csvp, const char *scene)
{
    struct stat sc, sv;
    if (access(exr, R_OK) || (stat(csvp, &sv) == 0 && stat(scene, &sc) == 0 && sv.st_mtime < sc.st_mtime)) return false;
    char *csv = read_whole_file(csvp);
    bool done = csv && !strstr(csv, "\n# PARTIAL");
    free(csv);
    return done;
}

/* The splotch statistics within the figure's insets (--insets), where the thesis points at MMLT's
 * artifacts: in the one it names (--named-inset) or both together, the spread of the blocks, and
 * the mean of the blur shares (the image scaled as a whole, so that an error spread over an inset is
 * not scaled away). */
static void inset_statistics(const struct ch6_equal *e, struct ch6_run *r, const struct image *im)
{
    if (!e->ninsets) return;
    int n = 0, first = e->named_inset ? e->named_inset - 1 : 0, last = e->named_inset ? e->named_inset - 1 : 1;
    r->q[Q_INSET_BLUR8] = 0;
    for (int i = first; i <= last; i++) {
        const int *rc = e->inset[i];
        if (rc[0] + rc[2] > im->w || rc[1] + rc[3] > im->h)
            die(DIE_USAGE, e->prog, "--insets: rectangle %d (%d,%d,%d,%d) lies outside the %dx%d image", i + 1, rc[0],
                rc[1], rc[2], rc[3], im->w, im->h);
        int m = block_relmse_in(im, e->ref, e->blk, e->eps, rc, NULL, e->blocks + n, e->cap - n);
        n += m < e->cap - n ? m : e->cap - n;
        r->q[Q_INSET_BLUR8] +=
            error_blur_share_in(im, e->ref, e->eps, 8, rc, NULL, mean_lum_scale(im, e->ref)) / (last - first + 1);
    }
    r->q[Q_INSET_SPREAD] = block_spread(e->blocks, n);
}

/* The error on glossy surfaces, where the MMLT paper places original MLT's artifacts (Figs. 1, 6):
 * its relMSE, its share surviving an 8 x 8 blur (the splotches; blocks wholly on glossy pixels, the
 * image scaled as a whole) and how it compares with the rest of the image's. */
static void glossy_statistics(const struct ch6_equal *e, struct ch6_run *r, const struct image *im)
{
    if (!e->glossy || !e->nglossy || im->w != e->glossy_w || im->h != e->glossy_h) return;
    r->q[Q_GLOSSY_RELMSE] = relmse_where(im, e->ref, e->eps, e->glossy, true);
    r->q[Q_GLOSSY_BLUR8] = error_blur_share_in(im, e->ref, e->eps, 8, (const int[4]){0, 0, im->w, im->h}, e->glossy,
                                               mean_lum_scale(im, e->ref));
    double rest = relmse_where(im, e->ref, e->eps, e->glossy, false);
    r->q[Q_GLOSSY_RATIO] = rest > 0 && r->q[Q_GLOSSY_RELMSE] > 0 ? log10(r->q[Q_GLOSSY_RELMSE] / rest) : NAN;
}

/* A run's image against the reference (no reference: every image statistic nan). */
static void image_statistics(struct ch6_equal *e, struct ch6_run *r, const struct image *im)
{
    static const enum ch6_q image_q[] = {Q_RELMSE,   Q_RELMSE_SCALED, Q_SPREAD,        Q_BLOCK_MEDIAN, Q_TRIMMED,
                                         Q_BLUR4,    Q_BLUR8,         Q_CORRLEN,       Q_INSET_SPREAD, Q_INSET_BLUR8,
                                         Q_NORM_ERR, Q_BLOCK_MAX,     Q_GLOSSY_RELMSE, Q_GLOSSY_BLUR8, Q_GLOSSY_RATIO};
    for (size_t k = 0; k < sizeof image_q / sizeof *image_q; k++)
        r->q[image_q[k]] = NAN;
    const struct image *ref = e->ref;
    if (!ref) return;
    r->q[Q_RELMSE] = img_relmse(im, ref, e->eps);
    r->q[Q_RELMSE_SCALED] = relmse_scaled(im, ref, e->eps);
    int n = block_relmse(im, ref, e->blk, e->eps, e->blocks, e->cap);
    if (n > e->cap) n = e->cap;
    r->q[Q_SPREAD] = block_spread(e->blocks, n);
    /* A technique that fails in a region fails there by a firefly or two, so its worst block's
     * relMSE is heavy-tailed over seeds; its logarithm is not, and its mean is the geometric mean's
     * (an image without error has no worst region: nan, not -inf in the mean) */
    double worst = 0;
    for (int i = 0; i < n; i++)
        worst = fmax(worst, e->blocks[i]);
    r->q[Q_BLOCK_MAX] = worst > 0 ? log10(worst) : NAN;
    r->q[Q_BLOCK_MEDIAN] = median_of(e->blocks, n);
    r->q[Q_TRIMMED] = trimmed_relmse(im, ref, e->eps, 0.001);
    r->q[Q_BLUR4] = error_blur_share(im, ref, e->eps, 4);
    r->q[Q_BLUR8] = error_blur_share(im, ref, e->eps, 8);
    r->q[Q_CORRLEN] = error_corr_length(im, ref);
    r->q[Q_NORM_ERR] = fabs(img_mean_luminance(im) / e->mlum - 1);
    inset_statistics(e, r, im);
    glossy_statistics(e, r, im);
}

/* Non-zero fraction of the 'total' rows of the render's statistics: all kinds (kind NULL) or one. */
static double nonzero_fraction(const struct ch6_equal *e, const struct csv_file *c, const char *kind)
{
    char err[512];
    int ck = csv_column(c, "kind", err, sizeof err), cl = csv_column(c, "length", err, sizeof err),
        ca = csv_column(c, "attempts", err, sizeof err), cn = csv_column(c, "nonzero", err, sizeof err);
    if (ck < 0 || cl < 0 || ca < 0 || cn < 0) die(DIE_RUNTIME, e->prog, "%s", err);
    double att = 0, nz = 0;
    for (int r = 0; r < c->nrows; r++) {
        if (strcmp(csv_cell(c, r, cl), "total") || (kind && strcmp(csv_cell(c, r, ck), kind))) continue;
        att += csv_number(c, r, ca);
        nz += csv_number(c, r, cn);
    }
    return att > 0 ? nz / att : NAN;
}

/* The run's mixing diagnostics (core/stats/mixing.h), the `all` row of PREFIX.mixing.csv beside the
 * statistics CSV at path: nan where the method has no chains (pt, bdpt). */
static void mixing_statistics(const struct ch6_equal *e, struct ch6_run *r, const char *path)
{
    r->q[Q_RHAT] = r->q[Q_ESS_PER_S] = r->q[Q_STUCK] = r->q[Q_MIX_WARN] = NAN;
    char mpath[4200], err[4400];
    snprintf(mpath, sizeof mpath, "%.*s.mixing.csv", (int)strlen(path) - 4, path);
    if (access(mpath, R_OK)) return;
    struct csv_file *c = csv_load(mpath, err, sizeof err);
    if (!c) die(DIE_RUNTIME, e->prog, "%s", err);
    int cl = csv_column(c, "length", err, sizeof err), c1 = csv_column(c, "rhat_contrib", err, sizeof err),
        c2 = csv_column(c, "rhat_target", err, sizeof err), ce = csv_column(c, "ess_total", err, sizeof err),
        cs = csv_column(c, "stuck_share", err, sizeof err), cw = csv_column(c, "warning", err, sizeof err);
    if (cl < 0 || c1 < 0 || c2 < 0 || ce < 0 || cs < 0 || cw < 0) die(DIE_RUNTIME, e->prog, "%s", err);
    for (int i = 0; i < c->nrows; i++) {
        if (strcmp(csv_cell(c, i, cl), "all")) continue;
        r->q[Q_RHAT] = fmax(csv_number(c, i, c1), csv_number(c, i, c2));
        r->q[Q_ESS_PER_S] = r->seconds > 0 ? csv_number(c, i, ce) / r->seconds : NAN;
        r->q[Q_STUCK] = csv_number(c, i, cs);
        r->q[Q_MIX_WARN] = strcmp(csv_cell(c, i, cw), "ok") != 0;
    }
    csv_free(c);
}

/* The render's statistics CSV: the counts every run reports, and those a method may lack (nan). */
static void render_statistics(const struct ch6_equal *e, struct ch6_run *r, const char *path)
{
    char err[4200];
    struct csv_file *c = csv_load(path, err, sizeof err);
    if (!c) die(DIE_RUNTIME, e->prog, "%s", err);
    /* a Monte Carlo run (pt, bdpt) counts samples where a Markov chain counts mutations */
    bool mc = !isnan(csv_meta_number(c, "samples"));
    if (!csv_meta_require(c, "seconds", &r->seconds, err, sizeof err) ||
        !csv_meta_require(c, mc ? "samples" : "mutations", &r->q[Q_MUTATIONS], err, sizeof err) ||
        !csv_meta_require(c, mc ? "samples_per_second" : "mutations_per_second", &r->q[Q_MPS], err, sizeof err))
        die(DIE_RUNTIME, e->prog, "%s", err);
    if (mc) { /* no proposals, no normalisation */
        r->q[Q_NONZERO] = r->q[Q_LARGE_NONZERO] = r->q[Q_NONZERO_CONN] = r->q[Q_B_RSE] = r->q[Q_B_IMAGE_RSE] = NAN;
        csv_free(c);
        return;
    }
    r->q[Q_NONZERO] = nonzero_fraction(e, c, NULL);
    r->q[Q_LARGE_NONZERO] = nonzero_fraction(e, c, "large");
    double tried = csv_meta_number(c, "connections_evaluated");
    r->q[Q_NONZERO_CONN] = tried > 0 ? csv_meta_number(c, "connections_nonzero") / tried : NAN;
    r->q[Q_B_RSE] = csv_meta_number(c, "b_rse");
    r->q[Q_B_IMAGE_RSE] = csv_meta_number(c, "b_image_rse");
    csv_free(c);
}

/* bin/render's command line of one run into rv; returns the count. */
static int render_argv(struct ch6_equal *e, const struct ch6_method *m, char **rv, char *const *fixed, int nfixed)
{
    int c = 0;
    rv[c++] = e->render;
    rv[c++] = (char *)e->scene;
    /* the shared --render-args first: bin/render keeps an option's last value, so a method's own
     * setting of the same option (its own --seed-paths, say) overrides the shared one */
    for (int k = 0; k < e->extra_c; k++)
        rv[c++] = e->extra_argv[k];
    for (int k = 0; k < m->argc; k++)
        rv[c++] = m->argv[k];
    for (int k = 0; k < nfixed; k++)
        rv[c++] = fixed[k];
    if (e->res) {
        rv[c++] = "--resolution";
        rv[c++] = (char *)e->res;
    }
    if (e->maxlen) {
        rv[c++] = "--max-length";
        rv[c++] = e->maxlen_s;
    }
    return c;
}

/* Renders (or keeps: --reuse, or a complete run of an interrupted earlier invocation) PREFIX.* */
static void render_run(struct ch6_equal *e, const struct ch6_method *m, const char *prefix, int seed, double budget)
{
    char seed_s[32], time_s[32], log[4200], exr[4200], csvp[4200];
    snprintf(seed_s, sizeof seed_s, "%d", seed);
    snprintf(time_s, sizeof time_s, "%g", budget);
    char *fixed[] = {e->spp > 0 ? "--spp"
                     : e->wall  ? "--time"
                                : "--cpu-time",
                     time_s,
                     "--seed",
                     seed_s,
                     "--threads",
                     e->thr,
                     "--min-length",
                     e->minlen_s,
                     "--quiet",
                     "--out",
                     (char *)prefix};
    char *rv[CH6_MAX_ARGS * 2 + 24];
    int c = render_argv(e, m, rv, fixed, (int)(sizeof fixed / sizeof *fixed));
    snprintf(log, sizeof log, "%.4000s.log", prefix);
    snprintf(exr, sizeof exr, "%.4000s.exr", prefix);
    snprintf(csvp, sizeof csvp, "%.4000s.csv", prefix);
    bool keep =
        e->reuse ? !access(exr, R_OK) && !access(csvp, R_OK) : e->ckpt_every > 0 && run_complete(exr, csvp, e->scene);
    char key[8192], err[4200];
    bool cached = false;
    if (!keep && e->cache.dir) {
        if (!run_cache_key(&e->cache, rv, c, key, sizeof key))
            die(DIE_RUNTIME, e->prog, "a run's cache key is too long");
        keep = cached = run_cache_fetch(&e->cache, key, prefix);
    }
    fprintf(stderr, "%s: %s %s seed %d, %g %s%s\n", e->prog, e->name, m->name, seed, budget,
            e->spp > 0 ? "mutations per pixel" : "s",
            cached ? " (from the run cache)"
            : keep ? " (kept from an earlier run)"
                   : "");
    if (!keep) {
        if (proc_render_resumable(e->prog, &e->renderer, rv, c, prefix, e->ckpt_every, log) != 0)
            die(DIE_RUNTIME, e->prog, "a render failed; see %s", log);
        /* only what this build rendered: a run kept from an earlier invocation may be another build's */
        if (e->cache.dir && !run_cache_store(&e->cache, key, prefix, err, sizeof err))
            die(DIE_RUNTIME, e->prog, "--run-cache: %s", err);
    }
    if (keep && e->ckpt_every > 0) {
        /* an interrupt between the render's end and our removal of its checkpoint leaves one
         * beside complete outputs: stale, so it goes now */
        char ck[4200];
        snprintf(ck, sizeof ck, "%.4000s.ckpt", prefix);
        unlink(ck);
    }
}

/* One cell of the grid (common/runner.h's run function): render, then measure. */
static void one_run(void *ctx, int s, int bi, int mi)
{
    struct ch6_equal *e = ctx;
    const struct ch6_method *m = &e->ms[mi];
    int seed = e->first_seed + s;
    char prefix[4096], path[4200], err[4200];
    snprintf(prefix, sizeof prefix, "%.3000s/%.60s-s%d-%s%g", e->runsdir, m->name, seed, e->spp > 0 ? "spp" : "t",
             e->budgets[bi]);
    render_run(e, m, prefix, seed, e->budgets[bi]);
    snprintf(path, sizeof path, "%.4000s.exr", prefix);
    struct image *im = img_read(path, err, sizeof err);
    if (!im) die(DIE_RUNTIME, e->prog, "%s", err);
    if (e->ref && (im->w != e->ref->w || im->h != e->ref->h))
        die(DIE_RUNTIME, e->prog, "image and reference sizes differ: %s", path);
    struct ch6_run *r = &e->R[mi][bi][s];
    image_statistics(e, r, im);
    if (!e->ref) e->expo = 0.5 / img_mean_luminance(im); /* no reference: a PNG is exposed by its own mean */
    if (bi == e->nb - 1 && s == 0) { /* the first seed's image at the largest budget: OUT/<method>.* */
        snprintf(path, sizeof path, "%.3000s/%.60s.png", e->out, m->name);
        if (!img_write_png(im, e->expo, path, err, sizeof err)) die(DIE_RUNTIME, e->prog, "%s", err);
        snprintf(path, sizeof path, "%.3000s/%.60s.exr", e->out, m->name);
        if (!img_write_exr(im, 1, path, err, sizeof err)) die(DIE_RUNTIME, e->prog, "%s", err);
    }
    img_destroy(im);
    snprintf(path, sizeof path, "%.4000s.csv", prefix);
    render_statistics(e, r, path);
    mixing_statistics(e, r, path);
}

void ch6_runs(struct ch6_equal *e)
{
    bool skip[CH6_MAX_METHODS];
    for (int mi = 0; mi < e->nm; mi++)
        skip[mi] = !e->ms[mi].available;
    e->cap = e->ref ? (e->ref->w / e->blk) * (e->ref->h / e->blk) + 1 : 1;
    e->blocks = xmalloc(sizeof(double) * (size_t)e->cap);
    runner_each(&(struct runner_grid){.seeds = e->seeds, .budgets = e->nb, .methods = e->nm, .skip = skip}, one_run, e);
}
