/* bin/ch6_equal: equal-time comparisons of MCMC methods on one scene (thesis chapter 6, Figures
 * 6.2-6.7; the MMLT paper's §5 non-zero ratio; the hybrid-MCTLS study). Every run is a bin/render
 * command line run in-process (tools/render_run.h; --render: by another program), so any method
 * bin/render accepts can be listed; a method it does not accept (probed with `render --method M
 * --help` in a child) is skipped and named in the outputs.
 *
 * For each seed 1..N, budget t0, 2 t0, ..., T seconds and method, in that order (interleaved): a
 * separate render with that seed and a --cpu-time budget (--wall-clock: --time) (the core has no snapshot facility; the
 * doubling budgets are separate runs, not snapshots of one run). Each image is compared with a BDPT reference rendered
 * once and cached: relMSE = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01 m^2), m the reference's mean
 * luminance (the relMSE of both images scaled to a mean of 1, so a dark scene is not all epsilon);
 * PNGs are exposed by 0.5 / m. The spread of the per-block
 * relMSE over B x B blocks (coefficient of variation: 0 = uniform error); mutations/s and the fraction
 * of proposals with non-zero contribution from the render's statistics CSV.
 * With --spp the budget is a number of mutations per pixel instead (one run per seed and method):
 * statistics that do not depend on the machine, which make check-fig6.N compares with a baseline.
 * With --reference-spp 0 there is no reference (the image statistics are nan): only the counts of
 * the render CSVs, for the non-zero ratios.
 * Writes OUT/runs.csv (one row per run), OUT/summary.csv (mean +- standard error over seeds per method
 * and budget), OUT/stats.csv (the same at the largest budget, one row per method and statistic),
 * OUT/NAME.md (the table and the claims), OUT/reference.png and OUT/<method>.png (first seed, budget
 * T), and OUT/glossy-mask.png (the reference, dimmed off the glossy pixels) when the scene has glossy
 * surfaces; all atomically.
 *
 * This file is the orchestration: the options, then the parts of ch6_equal.h in order (scales,
 * methods, reference, runs, tables, report). --scale quick|full|paper applies that scale's rows of
 * ch6_scales.c as if their options were given first on the command line (later options override
 * them); any other --scale is only a name for claims.csv. */
#include "ch6/ch6_equal.h"
#include "base/dist.h"
#include "base/util.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/outdir.h"
#include "io/image.h"
#include "tools/render_run.h"
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Budgets t0, 2 t0, ... up to T (T last even when not a doubling); with --spp one budget. */
static void make_budgets(struct ch6_equal *e, double t0)
{
    if (t0 < 0 || e->spp > 0) t0 = e->T = e->spp > 0 ? e->spp : e->T;
    if (t0 > e->T) opts_fail(e->prog, "--t0 %g is larger than --time %g", t0, e->T);
    for (double b = t0; b <= e->T * (1 + 1e-9) && e->nb < CH6_MAX_BUDGETS; b *= 2)
        e->budgets[e->nb++] = b;
    if (fabs(e->budgets[e->nb - 1] - e->T) > 1e-9 * e->T && e->nb < CH6_MAX_BUDGETS) e->budgets[e->nb++] = e->T;
}

/* The scene's folder name, the label (default: that name) and the renderer: in-process
 * (tools/render_run.h), or the program --render names. */
static void names(struct ch6_equal *e, char *sname, size_t n)
{
    snprintf(sname, n, "%s", e->scene);
    char *sl = strrchr(sname, '/');
    if (sl) *sl = 0;
    sl = strrchr(sname, '/');
    e->scene_name = sl ? sl + 1 : sname;
    if (!e->name) e->name = e->scene_name;
    if (!*e->render) {
        snprintf(e->render, sizeof e->render, "render");
        e->renderer = (struct proc_prog){.main = render_run};
        return;
    }
    if (access(e->render, X_OK)) opts_fail(e->prog, "--render: '%s' is not executable", e->render);
    e->renderer = (struct proc_prog){.path = e->render};
}

/* The command line into e; returns the --methods text. */
/* --insets: two rectangles X,Y,W,H of at least 8 x 8 pixels (the blur's block); whether they lie in
 * the image is checked when the first image is measured (ch6_runs.c). */
static void parse_insets(struct ch6_equal *e)
{
    if (!e->insets) return;
    int(*r)[4] = e->inset, end = 0;
    if (sscanf(e->insets, "%d,%d,%d,%d %d,%d,%d,%d%n", &r[0][0], &r[0][1], &r[0][2], &r[0][3], &r[1][0], &r[1][1],
               &r[1][2], &r[1][3], &end) != 8 ||
        e->insets[end])
        opts_fail(e->prog, "--insets: expected 'X,Y,W,H X,Y,W,H', got '%s'", e->insets);
    for (int i = 0; i < 2; i++)
        if (r[i][0] < 0 || r[i][1] < 0 || r[i][2] < 8 || r[i][3] < 8)
            opts_fail(e->prog, "--insets: rectangle %d needs X, Y >= 0 and W, H >= 8, got '%s'", i + 1, e->insets);
    e->ninsets = 2;
}

static const char *parse(struct ch6_equal *e, int argc, char **argv)
{
    static const char *const studies[] = {"equal-time", "ratio",      "hybrid",        "mmlt-equal", "background",
                                          "cdc",        "mis",        "mmlt-design",   "pitp-rate",  "mmlt-fig4",
                                          "mmlt-fig9",  "fused-door", "fused-caustic", NULL};
    const char *methods, *extra, *render = NULL, *res = NULL;
    double t0 = -1;
    int study;
    const struct opt opts[] = {
        OPT_SCENE(e->scene, .help = "scene JSON"),
        {"--name", OPT_STRING, OPT_DST(e->name), .arg = "NAME",
         .help = "label in the outputs (default: the scene's folder name)"},
        OPT_OUT(e->out, .arg = "DIR", .help = "output folder"),
        {"--methods", OPT_STRING, OPT_DST(methods), .arg = "LIST", .def = "pssmlt,mmlt,pitp",
         .help = "comma-separated methods; an item NAME=ARGS runs bin/render with ARGS (spaces separate them), e.g. "
                 "'mctls=--method mmlt --large-step mctls'"},
        {"--seeds", OPT_INT, OPT_DST(e->seeds), .arg = "N", .lo = 2, .hi = CH6_MAX_SEEDS,
         .help = "seeds 1..N per method and budget", .def = "4"},
        {"--time", OPT_DOUBLE, OPT_DST(e->T), .arg = "T", .lo = 0.01, .hi = 1e6,
         .help = "largest budget in seconds per run", .def = "8"},
        {"--spp", OPT_INT, OPT_DST(e->spp), .arg = "N", .lo = 0, .hi = 1 << 20, .def = "0",
         .help =
             "instead of time budgets, N mutations per pixel per run (bin/render --spp): statistics that do not depend "
             "on the machine's speed, for make check-fig6.N (0: the time budgets)"},
        {"--first-seed", OPT_INT, OPT_DST(e->first_seed), .arg = "S", .lo = 1, .hi = 1 << 20, .def = "1",
         .help = "seeds S .. S+N-1 (a regression check's seeds differ from its baseline's)"},
        {"--t0", OPT_DOUBLE, OPT_DST(t0), .arg = "S", .lo = 0.01, .hi = 1e6,
         .help = "smallest budget; budgets double from it up to T (default T: one budget)"},
        {"--resolution", OPT_WXH, OPT_DST(e->res_wh), .str = &res, .arg = "WxH", .lo = 1, .hi = INT_MAX,
         .expect = "WxH with positive integers", .help = "override the camera (also for the reference)"},
        OPT_REFERENCE(e->refpath,
                      .help =
                          "cached BDPT reference EXR, re-rendered when the scene file's content or the "
                          "reference's settings change (its key: FILE with .key for .exr; default "
                          "results/reference/SCENE-bdpt-WxH-minK-SPP.exr, SCENE the scene's folder: a --name shares "
                          "its scene's references)"),
        {"--reference-spp", OPT_INT, OPT_DST(e->refspp), .arg = "N", .lo = 0, .hi = 1 << 24, .def = "256",
         .help = "BDPT samples per pixel of the reference (0: no reference, only the render CSVs' counts: the "
                 "non-zero ratios)"},
        OPT_MIN_LENGTH(e->minlen, .hi = 64, .def = "1",
                       .help =
                           "paths of K segments or more only, reference and runs (1: all; the thesis's chapter 6 uses "
                           "3: no direct lighting)"),
        {"--max-length", OPT_INT, OPT_DST(e->maxlen), .arg = "K", .lo = 0, .hi = MAX_PATH_LENGTH, .def = "0",
         .help = "paths of at most K segments, reference and runs (0: bin/render's default)"},
        {"--render-args", OPT_STRING, OPT_DST(extra), .arg = "ARGS",
         .help = "extra bin/render options for every run (a method's own setting of the same option wins)",
         .def = "--p-large 0.1"},
        {"--block", OPT_INT, OPT_DST(e->blk), .arg = "B", .lo = 2, .hi = 1024, .help = "block size of the error spread",
         .def = "16"},
        OPT_THREADS(e->threads, .hi = 1024, .help = "threads per run", .def = "2"),
        {"--render", OPT_STRING, OPT_DST(render), .arg = "PATH",
         .help = "run the renders as this program (bin/render's options) instead of in-process: an MPI launcher "
                 "(scripts/mpirun-render.sh) or another build"},
        {"--wall-clock", OPT_FLAG, OPT_DST(e->wall),
         .help =
             "budgets in wall-clock seconds (bin/render --time); default CPU seconds per thread (--cpu-time), which "
             "other processes on the machine do not shift"},
        {"--source", OPT_STRING, OPT_DST(e->source), .arg = "TEXT", .def = "thesis ch. 6",
         .help = "the claims' source item, for claims.csv (e.g. 'thesis Figs. 6.4, 6.7')"},
        {"--command", OPT_STRING, OPT_DST(e->command), .arg = "TEXT", .def = "bin/ch6_equal",
         .help = "the command that reproduces this run, for claims.csv"},
        {"--scale", OPT_STRING, OPT_DST(e->scale), .arg = "NAME", .def = "custom",
         .help = "quick, full or paper: the study's budgets, seeds, lengths, reference, resolution and insets at that "
                 "scale for this scene, as if given first (options given override them; the table of ch6_scales.c); "
                 "any other NAME only names the scale in claims.csv"},
        {"--study", OPT_CHOICE, OPT_DST(study), .choices = studies, .def = "equal-time",
         .help = "whose scales --scale applies and whose claims the runs test: equal-time (make "
                 "fig6.2-6.7), ratio (make mmlt-ratio), hybrid (make hybrid-study), mmlt-equal (make mmlt-equal), "
                 "background (make bdpt-pt), cdc (make cdc-ch6), mis (make mis-robust), mmlt-design (make "
                 "mmlt-design), pitp-rate (make pitp-rate), mmlt-fig4 (make mmlt-fig4), mmlt-fig9 (make mmlt-fig9), "
                 "fused-door or fused-caustic (make fused)"},
        {"--checkpoint", OPT_DOUBLE, OPT_DST(e->ckpt_every), .arg = "S", .lo = 0, .hi = 1e6, .def = "0",
         .help = "every render (reference too) checkpoints every S seconds, and a rerun after an interruption keeps "
                 "the completed runs and resumes the interrupted one (0: off)"},
        {"--insets", OPT_STRING, OPT_DST(e->insets), .arg = "'X,Y,W,H X,Y,W,H'",
         .help = "the figure's two inset rectangles in pixels, recorded in summary.csv for scripts/ch6-figure.sh "
                 "(default: the scale's, for the chapter-6 scenes)"},
        {"--named-inset", OPT_INT, OPT_DST(e->named_inset), .arg = "N", .lo = 0, .hi = 2, .def = "0",
         .help = "the inset statistics over inset N alone, the one the source points at (1 or 2; 0: both together; "
                 "default: the scale's, for the chapter-6 scenes)"},
        {"--reuse", OPT_FLAG, OPT_DST(e->reuse),
         .help = "keep the run files already in OUT/runs (same names) instead of rendering"},
        {"--run-cache", OPT_STRING, OPT_DST(e->run_cache_dir), .arg = "DIR",
         .help = "share runs with other studies through DIR: a run whose build, scene content and bin/render "
                 "options (output options aside) match an entry there is linked from it instead of rendered, and "
                 "every run rendered is added (common/run_cache.h); not with --render (make's figure targets give "
                 "results/run-cache)"},
        {0}};
    const struct opts_spec spec = {
        .prog = e->prog, .usage = "usage: ch6_equal --scene FILE --out DIR [options]\n", .opts = opts};
    char **args = ch6_with_scale(&spec, &argc, argv);
    opts_parse(&spec, argc, args);
    if (args != argv) free(args);
    e->res = res;
    e->study = studies[study];
    snprintf(e->extra_s, sizeof e->extra_s, "%s", extra);
    if (render) snprintf(e->render, sizeof e->render, "%s", render);
    if (!e->scene || !e->out) opts_fail(e->prog, "--scene and --out are required (see --help)");
    if (strlen(e->out) > 2000) opts_fail(e->prog, "--out: path too long");
    make_budgets(e, t0);
    if (access(e->scene, R_OK)) opts_fail(e->prog, "--scene: cannot read '%s'", e->scene);
    parse_insets(e);
    return methods;
}

int main(int argc, char **argv)
{
    static struct ch6_run runs[CH6_MAX_METHODS][CH6_MAX_BUDGETS][CH6_MAX_SEEDS];
    static struct ch6_equal e = {.prog = "ch6_equal", .R = runs};
    char sname[256];
    /* Several copies would each run every render; MPI goes through --render instead (README MPI). */
    dist_refuse_ranks();
    const char *methods = parse(&e, argc, argv);
    names(&e, sname, sizeof sname);
    opts_require_image_input(e.prog);
    ch6_methods_parse(&e, methods);
    snprintf(e.runsdir, sizeof e.runsdir, "%s/runs", e.out);
    outdir_require(e.prog, e.runsdir);
    snprintf(e.minlen_s, sizeof e.minlen_s, "%d", e.minlen);
    snprintf(e.maxlen_s, sizeof e.maxlen_s, "%d", e.maxlen);
    snprintf(e.thr, sizeof e.thr, "%d", e.threads);
    ch6_scene_identity(&e);
    ch6_reference(&e);
    ch6_runs(&e);
    ch6_write_tables(&e);
    ch6_report(&e);
    free(e.blocks);
    free(e.glossy);
    free(e.methods_buf);
    img_destroy(e.ref);
    return 0;
}
