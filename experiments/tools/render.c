/* bin/render: renders a Tungsten scene with one method; writes PREFIX.exr, PREFIX.png and, for the
 * MCMC methods, PREFIX.csv with acceptance statistics. Built with MPI=1 and started by mpirun, its
 * ranks share the render (core/base/dist.h) and rank 0 alone writes the outputs and the summary. */
#include "mc/render.h"
#include "base/dist.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "emitter/emitter.h"
#include "io/checkpoint.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "scene/accel.h"
#include "scene/scene_hash.h"
#include "tools/mlt_cli.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *const methods[] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp", NULL};
static const char *const samplers[] = {"independent", "sobol", NULL};

/* The small steps' names (mlt_options.c). */
static const char *small_step_name(enum small_step k) { return mlt_option_find("small_step")->choices[k]; }

struct args {
    const char *scene, *out, *resume, *method;
    double checkpoint, cpu_seconds;
    struct render_opts mc;
    struct mlt_opts mlt;
    int res[2], sampler;
    const char *res_arg; /* --resolution as given */
    bool quiet;
};

static bool set_isa(const char *v, void *dst, char *why, size_t n)
{
    (void)dst;
    if (accel_set_isa(v)) return true;
    int l = snprintf(why, n, "this CPU and Embree run only:");
    for (const char *const *i = accel_isas(); *i; i++)
        if (l >= 0 && (size_t)l < n) l += snprintf(why + l, n - (size_t)l, " %s", *i);
    if (l >= 0 && (size_t)l < n) snprintf(why + l, n - (size_t)l, "; got '%s'", v);
    return false;
}

static void scene_arg(const char *prog, const char *arg, void *ctx)
{
    struct args *a = ctx;
    if (a->scene) opts_fail(prog, "more than one scene given ('%s' and '%s')", a->scene, arg);
    a->scene = arg;
}

#define STR_(x) #x
#define STR(x) STR_(x)

/* The summary line and the input limits (base/input_limits.h), composed from the limits themselves. */
static const char *help_tail(void)
{
    static char t[1024];
    snprintf(t, sizeof t,
             "Prints one summary line: method, samples, seconds, samples/s.\n"
             "Input limits (refused with one error line, exit status 2): scene files %ld MB; resolution %d per side\n"
             "and %ld pixels; textures %d per side, %ld texels, %d channels; meshes %ld vertices and triangles;\n"
             "paths %d segments (a larger max_bounces is capped with a warning).\n",
             LIMIT_SCENE_BYTES >> 20, LIMIT_IMAGE_SIDE, LIMIT_IMAGE_PIXELS, LIMIT_TEXTURE_SIDE, LIMIT_TEXTURE_TEXELS,
             LIMIT_TEXTURE_CHANNELS, LIMIT_MESH_ELEMS, MAX_PATH_LENGTH);
    return t;
}

/* Whether argv holds the option (opts.h takes no --opt=value). */
static bool given(int argc, char **argv, const char *name)
{
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], name)) return true;
    return false;
}

static void parse(int argc, char **argv, struct args *a)
{
    const char *prog = "render";
    struct mlt_opts *m = &a->mlt;
    const struct opt shared[] = {
        {"--method", OPT_CHOICE, .choices = methods, .str = &a->method, .def = "bdpt",
         .help = "estimator (pitp: MMLT with the path-invariant technique perturbation, thesis 5.2)"},
        {"--spp", OPT_INT, OPT_DST(a->mc.spp), .arg = "N", .lo = 1, .hi = 1 << 24,
         .help = "samples per pixel; for pssmlt/mmlt/pitp mutations per pixel (default: the scene's renderer.spp, else "
                 "16)"},
        {"--time", OPT_DOUBLE, OPT_DST(a->mc.seconds), .arg = "SECONDS", .lo = 1e-3, .hi = 1e7,
         .help =
             "equal-time budget instead of --spp: pssmlt/mmlt chains stop at it (the seed pass comes on top); pt/bdpt "
             "render whole passes of 1 spp while the next fits in it"},
        {"--cpu-time", OPT_DOUBLE, OPT_DST(a->cpu_seconds), .arg = "SECONDS", .lo = 1e-3, .hi = 1e7,
         .help = "as --time, in CPU seconds per thread (the process's CPU time over --threads): other load on the "
                 "machine then changes the wall time, not the work done"},
        OPT_SEED(a->mc.seed, .help = "random seed; same seed and threads -> same output", .def = "1"),
        {"--sampler", OPT_CHOICE, OPT_DST(a->sampler), .choices = samplers, .def = "independent",
         .tag = APPLIES_PT | APPLIES_BDPT,
         .help = "pt/bdpt numbers: independent, or sobol (scrambled (0,2)-sequences per pixel, as Tungsten's default): "
                 "equally unbiased, lower error where stratification pays (pixel area, direct light; not fireflies)"},
        OPT_THREADS(a->mc.threads, .hi = 1024, .help = "worker threads (default: all cores)", .def_int = cpu_count),
        OPT_MAX_LENGTH(a->mc.max_length, .help = "maximum path length in segments (default: integrator.max_bounces)"),
        OPT_MIN_LENGTH(a->mc.min_length, .hi = MAX_PATH_LENGTH,
                       .help = "leave out paths shorter than K segments (3: no direct lighting; default 1)"),
        OPT_RESOLUTION(a->res, .lo = 1, .hi = LIMIT_IMAGE_SIDE,
                       .expect = "WxH with positive integers, at most " STR(LIMIT_IMAGE_SIDE) " per side",
                       .str = &a->res_arg, .help = "override the camera resolution (same horizontal fov)"),
        OPT_OUT(a->out, .arg = "PREFIX", .help = "output prefix", .def = "out"),
        {"--quiet", OPT_FLAG, OPT_DST(a->quiet), .help = "no progress bar"},
        {"--checkpoint", OPT_DOUBLE, OPT_DST(a->checkpoint), .arg = "SECONDS", .lo = 1e-3, .hi = 1e9,
         .help = "write the run's whole state to PREFIX.ckpt every SECONDS (atomically; Ctrl-C always leaves one); the "
                 "seed pass of pssmlt/mmlt/pitp is not checkpointed"},
        {"--resume", OPT_STRING, OPT_DST(a->resume), .arg = "FILE",
         .help = "continue the run FILE holds; give the same scene and options (it refuses others); with an --spp "
                 "budget the result is bit-identical to an uninterrupted run, with --time the run gets what its budget "
                 "had left"},
        {"--embree-isa", OPT_CALL, .call = set_isa, .arg = "ISA",
         .help = "Embree's kernels: sse2, sse4.2, avx, avx2 or avx512 (those this CPU runs; default: the best, or the "
                 "environment's PSS_EMBREE_ISA): hit points, so images, differ in the last bits between kernels"},
        {.type = OPT_TEXT, .help = "MCMC options (pssmlt, mmlt, pitp; the mmlt options apply to pitp too):"},
    };
    /* then the MCMC options, from their descriptors (core/mcmc/mlt_options.h), and the end */
    struct opt opts[sizeof shared / sizeof shared[0] + 32] = {0};
    size_t n = sizeof shared / sizeof shared[0];
    memcpy(opts, shared, sizeof shared);
    n += mlt_cli_opts(m, opts + n, sizeof opts / sizeof opts[0] - n - 1);
    const struct opts_spec spec = {.prog = prog,
                                   .usage = "usage: render SCENE.json [options]\n",
                                   .opts = opts,
                                   .tail = help_tail(),
                                   .positional = scene_arg,
                                   .ctx = a};
    opts_parse(&spec, argc, argv);
    if (!a->scene) opts_fail(prog, "no scene given (see --help)");
    if (a->res[0] && (long)a->res[0] * a->res[1] > LIMIT_IMAGE_PIXELS)
        opts_fail(prog, "--resolution: %s is above the limit of %ld pixels (8192x8192)", a->res_arg,
                  LIMIT_IMAGE_PIXELS);
    if (a->cpu_seconds > 0) {
        if (a->mc.seconds > 0) opts_fail(prog, "--time and --cpu-time: give one budget");
        a->mc.seconds = a->cpu_seconds;
        a->mc.cpu_time = m->cpu_time = true;
    }
    a->mc.sobol = a->sampler == 1;
    /* the options both drivers read */
    m->seconds = a->mc.seconds, m->seed = a->mc.seed, m->threads = a->mc.threads;
    a->mc.progress = m->progress = !a->quiet;
    if (m->pss.rap_resolution) m->pss.rap = true;
    /* controlled steps need the Gaussian's density (mcmc/controlled_step.h) */
    if (m->small_step != SMALL_STEP_PSS) {
        if (given(argc, argv, "--kernel") && m->pss.kernel != KERNEL_GAUSSIAN)
            opts_fail(prog, "--small-step %s: needs --kernel gaussian", small_step_name(m->small_step));
        m->pss.kernel = KERNEL_GAUSSIAN;
    }
    if (m->technique_k && !strcmp(a->method, "pitp"))
        opts_fail(prog,
                  "--technique-images: pssmlt and mmlt only (PITP's perturbation moves a state between techniques)");
    mlt_cli_warn_unused(&spec, a->method, argc, argv);
}

/* The metadata lines every CSV of a run opens with: "# render SCENE --method M EXTRA", the commit
 * and the seed. */
static void meta_head(FILE *f, const struct args *a, const char *extra)
{
    csv_meta(f, "render", "%s --method %s%s", a->scene, a->method, extra);
    csv_meta_commit(f);
    csv_meta(f, "seed", "%llu", (unsigned long long)a->mlt.seed);
}

/* PREFIX.angle.exr (mean angle change per pixel, radians) and PREFIX.angle.csv (per length). */
static bool write_angle(const struct args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char path[4096], extra[64], *buf = NULL;
    size_t len = 0;
    struct image *im = angle_acc_image(r->angle);
    snprintf(path, sizeof path, "%s.angle.exr", a->out);
    bool ok = img_write_exr(im, 1.0, path, err, errlen);
    img_destroy(im);
    FILE *f = open_memstream(&buf, &len);
    snprintf(extra, sizeof extra, " --small-step %s", small_step_name(a->mlt.small_step));
    meta_head(f, a, extra);
    csv_meta(f, "skipped_steps", "%ld", r->angle->skipped);
    angle_acc_write_csv(f, r->angle);
    fclose(f);
    snprintf(path, sizeof path, "%s.angle.csv", a->out);
    ok = ok && write_text_atomic(path, buf, err, errlen);
    free(buf);
    return ok;
}

/* The header of PREFIX.tech.csv: the run's metadata lines, then `# NAME COUNT` (mutations or spp)
 * and `# seconds`. Caller frees. */
static char *tech_head(const struct args *a, const char *name, long count, double seconds)
{
    char extra[64], *head = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&head, &len);
    snprintf(extra, sizeof extra, " --technique-images %d", a->mlt.technique_k);
    meta_head(f, a, extra);
    csv_meta(f, name, "%ld", count);
    csv_meta(f, "seconds", "%.3f", seconds);
    fclose(f);
    return head;
}

/* The per-technique images and PREFIX.tech.csv of pssmlt and mmlt (core/stats/tech_image.h). */
static bool write_tech(const struct args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char *head = tech_head(a, "mutations", r->mutations, r->seconds);
    bool ok = tech_acc_write(r->tech, a->out, head, err, errlen);
    free(head);
    return ok;
}

/* BDPT's (core/mc/bdpt_tech.h). */
static bool write_bdpt_tech(const struct args *a, const struct render_stats *st, const struct image *img, char *err,
                            size_t errlen)
{
    char *head = tech_head(a, "spp", st->spp, st->seconds);
    bool ok = bdpt_tech_write(st->tech, st->spp, img, a->out, head, err, errlen);
    free(head);
    return ok;
}

static bool write_csv(const struct args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    const struct mlt_opts *m = &a->mlt;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    meta_head(f, a, "");
    csv_meta(f, "threads", "%d", m->threads);
    csv_meta(f, "max_length", "%d", m->max_length);
    if (dist_size() > 1) csv_meta(f, "ranks", "%d", dist_size()); /* threads are per rank */
    mlt_cli_csv(f, m, MLT_CSV_BEFORE_COUNTS);                     /* the options (core/mcmc/mlt_options.c) */
    if (m->small_step != SMALL_STEP_PSS) {
        csv_meta(f, "controlled_failed_forward", "%ld", r->ctrl_fail_forward);
        csv_meta(f, "controlled_failed_reverse", "%ld", r->ctrl_fail_reverse);
    }
    mlt_cli_csv(f, m, MLT_CSV_AFTER_COUNTS);
    if (r->partial) csv_meta(f, NULL, "PARTIAL: interrupted after %ld mutations", r->mutations);
    csv_meta(f, "mutations", "%ld", r->mutations);
    csv_meta(f, "seconds", "%.3f", r->seconds);
    csv_meta(f, "clock", "%s", m->cpu_time ? "cpu seconds per thread" : "wall");
    csv_meta(f, "seed_seconds", "%.3f", r->seed_seconds);
    csv_meta(f, "mutations_per_second", "%.0f", r->mutations / r->seconds);
    csv_meta(f, "nonfinite", "%ld", r->nonfinite);
    fputs("# nonfinite_by_length ", f); /* lengths 0..max_length; 0: sums over lengths (path/splat.h) */
    for (int k = 0; k <= m->max_length; k++)
        fprintf(f, k ? ",%ld" : "%ld", r->stats.nonfinite.len[k]);
    fputc('\n', f);
    if (m->method == MLT_PITP) {
        const struct accept_cell *pc = &r->stats.total[PROPOSAL_PITP];
        csv_meta(f, "pitp_perturbations", "%ld", pc->attempts);
        csv_meta(f, "pitp_failures", "%ld", pc->failed);
        csv_meta(f, "pitp_failure_fraction", "%.9g", pc->attempts ? (double)pc->failed / pc->attempts : 0.0);
    }
    /* MMLT paper §5: PSSMLT evaluates every connection of a sample, MMLT one per proposal */
    csv_meta(f, "connections_evaluated", "%ld", r->stats.conn_tried);
    csv_meta(f, "connections_nonzero", "%ld", r->stats.conn_nonzero);
    csv_meta(f, "b", "%.9g", r->b);
    csv_meta(f, "b_rse", "%.6g", r->b_rse);
    for (int k = 1; k <= m->max_length && m->method != MLT_PSSMLT; k++)
        csv_meta(f, NULL, "b_%d %.9g", k, r->b_k[k]);
    for (int k = 1; k <= m->max_length && m->method != MLT_PSSMLT; k++)
        csv_meta(f, NULL, "b_rse_%d %.6g", k, r->b_k_rse[k]);
    stats_write_csv(f, a->method, &r->stats, true);
    fclose(f);
    char path[4096];
    snprintf(path, sizeof path, "%s.csv", a->out);
    bool ok = write_text_atomic(path, buf, err, errlen);
    free(buf);
    return ok;
}

/* What the MCMC methods take from the shared options and the scene. */
static void mlt_setup(struct mlt_opts *m, const struct args *a, const struct scene *sc)
{
    m->method = !strcmp(a->method, "mmlt") ? MLT_MMLT : !strcmp(a->method, "pitp") ? MLT_PITP : MLT_PSSMLT;
    m->max_length = a->mc.max_length;
    m->min_length = a->mc.min_length;
    m->mutations = (long)a->mc.spp * sc->cam.width * sc->cam.height;
}

/* Every option that changes the numbers a run produces, as one line: a checkpoint resumes only
 * under the same. The MCMC methods' options must be set (mlt_setup) before. */
static void options_text(const struct args *a, const struct scene *sc, char *buf, size_t n)
{
    const char *isa = accel_isa();
    if (!isa) /* Embree's own choice: the best this machine runs */
        for (const char *const *i = accel_isas(); *i; i++)
            isa = *i;
    int len = snprintf(
        buf, n, "method=%s spp=%d time=%g%s seed=%llu threads=%d max_length=%d min_length=%d resolution=%dx%d isa=%s",
        a->method, a->mc.spp, a->mc.seconds, a->mc.cpu_time ? "cpu" : "", (unsigned long long)a->mc.seed, a->mc.threads,
        a->mc.max_length, a->mc.min_length, sc->cam.width, sc->cam.height, isa ? isa : "?");
    /* only when not the default, so that checkpoints of independent-number runs stay resumable */
    if (a->mc.sobol && len > 0 && (size_t)len < n) len += snprintf(buf + len, n - (size_t)len, " sampler=sobol");
    /* every number-changing MCMC option, from its descriptor: none can be left out */
    if (strcmp(a->method, "pt") && strcmp(a->method, "bdpt") && len > 0 && (size_t)len < n)
        mlt_options_identity(&a->mlt, buf + len, n - (size_t)len);
}

/* " (length 3: 10, length 4: 2)" for the lengths with a count, "" for none; length 0 holds sums
 * over lengths (path/splat.h). */
static const char *nonfinite_note(const struct nonfinite *nf)
{
    static char s[2048];
    size_t n = 0;
    s[0] = 0;
    for (int k = 0; k <= MAX_PATH_LENGTH && n < sizeof s; k++)
        if (nf->len[k])
            n += (size_t)(k ? snprintf(s + n, sizeof s - n, "%slength %d: %ld", n ? ", " : " (", k, nf->len[k])
                            : snprintf(s + n, sizeof s - n, " (summed lengths: %ld", nf->len[k]));
    if (n && n < sizeof s) snprintf(s + n, sizeof s - n, ")");
    return s;
}

/* Printed once per run when anything was dropped: a count in the summary line is easy to miss. */
static void warn_nonfinite(long total, const struct nonfinite *nf)
{
    if (total > 0)
        fprintf(stderr,
                "render: warning: %ld non-finite samples dropped%s; the scene has degenerate geometry or parameters\n",
                total, nonfinite_note(nf));
}

/* The seed pass's error moves the whole image's mean: above 1 % say so, once, and what halves it. */
static void warn_normalisation(const struct mlt_result *r, long seed_paths)
{
    if (r->b_rse > 0.01)
        fprintf(stderr,
                "render: warning: the normalisation's relative standard error is %.1f %% (--seed-paths %ld): the "
                "image's mean "
                "is that uncertain; %ld seed paths would bring it to 0.5 %%\n",
                100 * r->b_rse, seed_paths, (long)ceil(seed_paths * (r->b_rse / 0.005) * (r->b_rse / 0.005)));
}

/* "(4 threads)", or under MPI "(2 ranks x 2 threads)". */
static const char *threads_note(int threads)
{
    static char s[64];
    if (dist_size() > 1)
        snprintf(s, sizeof s, "%d ranks x %d threads", dist_size(), threads);
    else
        snprintf(s, sizeof s, "%d threads", threads);
    return s;
}

/* --method pt or bdpt; *ok and *partial for the summary, or an exit status (> 0) to stop at. */
static int run_mc(struct args *a, const struct scene *sc, const struct ckpt_ctl *ctl, bool *ok, bool *partial,
                  char *err, size_t errlen)
{
    method_parse(a->method, &a->mc.method);
    struct render_stats st;
    if (a->mlt.technique_k && strcmp(a->method, "pt")) {
        if (a->mlt.technique_k > a->mc.max_length || a->mlt.technique_k < a->mc.min_length)
            opts_fail("render", "--technique-images %d: needs a path length from %d to %d (--min-length, --max-length)",
                      a->mlt.technique_k, a->mc.min_length > 1 ? a->mc.min_length : 1, a->mc.max_length);
        if (a->resume)
            opts_fail(
                "render",
                "--technique-images: bdpt's per-technique sums are not checkpointed; render again without --resume");
        if (dist_size() > 1) {
            if (dist_root())
                fprintf(stderr, "render: technique images are not merged across MPI ranks: make them without mpirun\n");
            return 2;
        }
        a->mc.tech_k = a->mlt.technique_k;
    }
    struct image *img = render_mc(sc, &a->mc, &st);
    if (st.resume_failed) {
        fprintf(stderr, "render: --resume %s: the checkpoint's state does not fit this run\n", a->resume);
        img_destroy(img);
        return 2;
    }
    *ok = ctl->err[0] || !dist_root() || img_write_exr_png(img, a->out, err, errlen);
    *partial = st.partial;
    if (*ok && !ctl->err[0] && dist_root())
        printf("%s%s%s: %ld samples (%d spp) in %.2f s, %.0f samples/s (%s), %ld non-finite dropped%s\n",
               *partial ? "PARTIAL (interrupted) " : "", a->method, a->mc.sobol ? " (sobol)" : "", st.samples, st.spp,
               st.seconds, st.samples / st.seconds, threads_note(a->mc.threads), st.nonfinite,
               nonfinite_note(&st.nonfinite_len));
    if (*ok && !ctl->err[0] && dist_root()) warn_nonfinite(st.nonfinite, &st.nonfinite_len);
    if (*ok && !ctl->err[0] && dist_root() && st.tech) *ok = write_bdpt_tech(a, &st, img, err, errlen);
    bdpt_tech_free(st.tech);
    img_destroy(img);
    return 0;
}

/* --method pssmlt, mmlt or pitp; as run_mc. */
static int run_mcmc(struct args *a, const struct scene *sc, const struct ckpt_ctl *ctl, bool *ok, bool *partial,
                    char *err, size_t errlen)
{
    if (a->mlt.technique_k && (a->mlt.technique_k > a->mlt.max_length || a->mlt.technique_k < a->mlt.min_length ||
                               a->mlt.large_step != LARGE_MMLT))
        opts_fail("render",
                  "--technique-images %d: needs a path length from %d to %d (--min-length, --max-length) and MMLT "
                  "large steps",
                  a->mlt.technique_k, a->mlt.min_length > 1 ? a->mlt.min_length : 1, a->mlt.max_length);
    a->mlt.pss.width = camera_film_width(&sc->cam);
    a->mlt.pss.height = camera_film_height(&sc->cam);
    struct mlt_result r;
    *ok = mlt_render(sc, &a->mlt, &r, err, errlen);
    if (!*ok) {
        fprintf(stderr, "%s%s\n", a->resume ? "render: --resume: " : "", err);
        return a->resume ? 2 : 1;
    }
    *partial = r.partial;
    *ok = ctl->err[0] || !dist_root() ||
          (img_write_exr_png(r.img, a->out, err, errlen) && write_csv(a, &r, err, errlen) &&
           (!r.angle || write_angle(a, &r, err, errlen)) && (!r.tech || write_tech(a, &r, err, errlen)));
    if (*ok && !ctl->err[0] && dist_root())
        printf("%s%s: %ld mutations in %.2f s (+%.2f s seed pass, normalisation rel. s.e. %.2f %%), %.0f mutations/s "
               "(%s), "
               "%ld non-finite dropped%s\n",
               *partial ? "PARTIAL (interrupted) " : "", a->method, r.mutations, r.seconds, r.seed_seconds,
               100 * r.b_rse, r.mutations / r.seconds, threads_note(a->mlt.threads), r.nonfinite,
               nonfinite_note(&r.stats.nonfinite));
    if (*ok && !ctl->err[0] && dist_root()) {
        warn_nonfinite(r.nonfinite, &r.stats.nonfinite);
        warn_normalisation(&r, a->mlt.seed_paths);
    }
    mlt_result_free(&r);
    return 0;
}

int main(int argc, char **argv)
{
    dist_init(&argc, &argv);
    struct args a = {0};
    a.mc = (struct render_opts){.method = METHOD_BDPT, .spp = -1, .max_length = -1};
    pss_opts_default(&a.mlt.pss, 1, 1);
    parse(argc, argv, &a);
    const char *inject = getenv("PSS_INJECT_NONFINITE"); /* tests only (path/splat.h) */
    if (inject) nonfinite_inject_every = atol(inject);
    opts_require_image_output("render");
    char err[1024];
    struct scene *sc = scene_load(a.scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    bool mcmc = strcmp(a.method, "pt") && strcmp(a.method, "bdpt");
    if (emitters_count(sc) == 0) {
        /* PT and BDPT estimate zero correctly; an MCMC method has no target to sample. */
        fprintf(stderr,
                mcmc ? "%s: the scene has no emitter: --method %s has no light to sample\n"
                     : "%s: warning: the scene has no emitter; the image will be black\n",
                a.scene, a.method);
        if (mcmc) {
            scene_free(sc);
            return 2;
        }
    }
    if (a.res[0]) camera_resize(&sc->cam, a.res[0], a.res[1]);
    if (a.mc.spp < 0) a.mc.spp = sc->spp > 0 ? sc->spp : 16;
    if (a.mc.max_length < 0) a.mc.max_length = sc->max_length;
    if (a.mc.progress && !isatty(2)) a.mc.progress = a.mlt.progress = false;
    /* Checkpoints are always armed: Ctrl-C leaves one even without --checkpoint. Over N > 1 MPI
     * ranks each rank keeps its own threads' state, in PREFIX.ckpt.rankR, and --resume FILE reads
     * FILE.rankR. */
    char ckpt_path[4096], resume_path[4096], opts[2048];
    int N = dist_size(), R = dist_rank();
    snprintf(ckpt_path, sizeof ckpt_path, "%s.ckpt", a.out);
    if (N > 1) snprintf(ckpt_path + strlen(ckpt_path), sizeof ckpt_path - strlen(ckpt_path), ".rank%d", R);
    mlt_setup(&a.mlt, &a, sc);
    options_text(&a, sc, opts, sizeof opts);
    snprintf(opts + strlen(opts), sizeof opts - strlen(opts), " ranks=%d", N);
    ckpt_remove_stale_temporaries(ckpt_path); /* a run that ends before its first write cleans up too */
    struct ckpt_ctl ctl = {
        .path = ckpt_path, .every = a.checkpoint, .id = {ckpt_build_hash(), ckpt_scene_hash(sc), opts}};
    struct ckpt_buf resume = {0};
    if (a.resume) {
        snprintf(resume_path, sizeof resume_path, N > 1 ? "%s.rank%d" : "%s", a.resume, R);
        long failed = !ckpt_read_file(resume_path, &ctl.id, &resume, err, sizeof err), own = failed;
        dist_sum_longs(&failed, 1); /* all ranks resume, or none */
        if (failed) {
            if (own)
                fprintf(stderr, "render: --resume %s\n", err);
            else
                fprintf(stderr,
                        "render: --resume %s: %ld of the %d ranks' checkpoints (%s.rankR) are missing, damaged or of "
                        "another run\n",
                        a.resume, failed, N, a.resume);
            ckpt_buf_free(&resume);
            scene_free(sc);
            return 2;
        }
        ctl.resume = &resume;
    }
    a.mc.ckpt = a.mlt.ckpt = &ctl;
    bool ok, partial;
    interrupt_install();
    int rc = strcmp(a.method, "pt") && strcmp(a.method, "bdpt") ? run_mcmc(&a, sc, &ctl, &ok, &partial, err, sizeof err)
                                                                : run_mc(&a, sc, &ctl, &ok, &partial, err, sizeof err);
    if (rc) {
        ckpt_buf_free(&resume);
        scene_free(sc);
        return rc;
    }
    /* A checkpoint that could not be written stopped the run (ckpt_save_run): its line alone, and
     * no outputs, which a full disk would refuse too. */
    if (ctl.err[0])
        fprintf(stderr, "render: %s\n", ctl.err);
    else if (!ok)
        fprintf(stderr, "render: %s\n", err);
    else if (partial && ctl.written)
        fprintf(stderr, "render: interrupted; continue with --resume %s.ckpt\n", a.out);
    ckpt_buf_free(&resume);
    scene_free(sc);
    return !ok || ctl.err[0] ? 1 : partial ? 130 : 0;
}
