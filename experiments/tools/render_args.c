/* bin/render's command line (render_args.h): the option table, its checks, and the run's identity. */
#include "tools/render_args.h"
#include "base/input_limits.h"
#include "base/parallel.h"
#include "common/opts.h"
#include "mcmc/mlt_options.h"
#include "path/path.h"
#include "scene/accel.h"
#include "scene/scene.h"
#include "tools/mlt_cli.h"
#include <stdio.h>
#include <string.h>

static const char *const methods[] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp", "mlt", NULL};
static const char *const samplers[] = {"independent", "sobol", NULL};

/* The small steps' names (mlt_options.c). */
const char *render_small_step_name(enum small_step k) { return mlt_option_find("small_step")->choices[k]; }

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
    struct render_args *a = ctx;
    if (a->scene) opts_fail(prog, "more than one scene given ('%s' and '%s')", a->scene, arg);
    a->scene = arg;
}

#define STR_(x) #x
#define STR(x) STR_(x)

/* The summary line and the input limits (base/input_limits.h), composed from the limits themselves. */
static const char *help_tail(void)
{
    static char t[6144];
    snprintf(t, sizeof t,
             "Prints one summary line: method, samples, seconds, samples/s.\n"
             "pssmlt, mmlt, pitp, mlt also write PREFIX.mixing.csv, the chains' mixing diagnostics: a row per path\n"
             "length (mmlt, pitp) and an `all` row (core/mcmc/docs/outputs.md). rhat_contrib, rhat_target:\n"
             "rank-normalised split-R-hat across the chains of where the state splats (its raster column) and\n"
             "of its target; near 1 the chains agree, above 1.01 they do not yet (that length's image is not\n"
             "to be trusted). ess_total: effective independent draws over the chains (under 100: too few);\n"
             "ess_per_chain_min: the worst chain's; tau: iterations per effective draw (at least `thin`, the\n"
             "traces' thinning). longest_reject_run_max: the most iterations a chain's state stayed unchanged;\n"
             "stuck_share: chains whose run exceeds 1 %% of the chain, 100 iterations and what the length's\n"
             "acceptance explains. startup_z: the first 1 %% of each chain against the rest (|z| > 3: start-up\n"
             "bias). Without --quiet a warning on stderr names the lengths with R-hat > 1.01, ESS < 100 or a\n"
             "stuck chain.\n"
             "With --mixing-image they also write PREFIX.mixing.exr (grey): per pixel, the chains' visits (arrivals of "
             "a chain in\n"
             "the pixel) over the iterations whose current state splatted there (0: none did); 1/value is the\n"
             "mean number of iterations a chain stayed once there. High (near 1): chains move on at every\n"
             "iteration; low: a chain sat there (a stuck state, a splotch, or steps too small to leave the\n"
             "pixel). Compare runs at one resolution (core/mcmc/docs/outputs.md).\n"
             "Input limits (refused with one error line, exit status 2): scene files %ld MB; resolution %d per side\n"
             "and %ld pixels; textures %d per side, %ld texels, %d channels; meshes %ld vertices and triangles;\n"
             "paths %d segments (a larger max_bounces is capped with a warning).\n",
             LIMIT_SCENE_BYTES >> 20, LIMIT_IMAGE_SIDE, LIMIT_IMAGE_PIXELS, LIMIT_TEXTURE_SIDE, LIMIT_TEXTURE_TEXELS,
             LIMIT_TEXTURE_CHANNELS, LIMIT_MESH_ELEMS, MAX_PATH_LENGTH);
    return t;
}

/* --technique-s S --technique-t T: one technique (core/mc/render.h only_s, only_t), both given, a
 * path length within the limit. */
static void technique_arg(struct render_args *a)
{
    int s = a->mc.only_s, t = a->mc.only_t;
    if (s < 0 || t < 1 || s + t - 1 < 1 || s + t - 1 > MAX_PATH_LENGTH)
        opts_fail("render", "--technique-s %d --technique-t %d: S + T - 1 segments must be 1 to %d", s, t,
                  MAX_PATH_LENGTH);
}

/* Whether argv holds the option (opts.h takes no --opt=value). */
static bool given(int argc, char **argv, const char *name)
{
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], name)) return true;
    return false;
}

void render_args_parse(int argc, char **argv, struct render_args *a)
{
    const char *prog = "render";
    struct mlt_opts *m = &a->mlt;
    const struct opt shared[] = {
        {"--method", OPT_CHOICE, .choices = methods, .str = &a->method, .def = "bdpt",
         .help = "estimator (pitp: MMLT with the path-invariant technique perturbation, thesis 5.2; mlt: Veach's MLT, "
                 "path-space state, the bidirectional mutation: core/mcmc/docs/veach.md)"},
        {"--spp", OPT_INT, OPT_DST(a->mc.spp), .arg = "N", .lo = 1, .hi = 1 << 24,
         .help =
             "samples per pixel; for pssmlt/mmlt/pitp/mlt mutations per pixel (default: the scene's renderer.spp, else "
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
        {"--technique-s", OPT_INT, OPT_DST(a->mc.only_s), .arg = "S", .lo = 0, .hi = MAX_PATH_LENGTH,
         .tag = APPLIES_BDPT, .help = "bdpt, with --technique-t: one technique alone, unweighted"},
        {"--technique-t", OPT_INT, OPT_DST(a->mc.only_t), .arg = "T", .lo = 1, .hi = MAX_PATH_LENGTH + 1,
         .tag = APPLIES_BDPT,
         .help = "bdpt: the technique of S emitter and T camera vertices alone, paths of S + T - 1 segments (thesis "
                 "Figs. 3.3, 3.5: what MIS combines)"},
        OPT_MAX_LENGTH(a->mc.max_length, .help = "maximum path length in segments (default: integrator.max_bounces)"),
        OPT_MIN_LENGTH(a->mc.min_length, .hi = MAX_PATH_LENGTH,
                       .help = "leave out paths shorter than K segments (3: no direct lighting; default 1)"),
        OPT_RESOLUTION(a->res, .lo = 1, .hi = LIMIT_IMAGE_SIDE,
                       .expect = "WxH with positive integers, at most " STR(LIMIT_IMAGE_SIDE) " per side",
                       .str = &a->res_arg, .help = "override the camera resolution (same horizontal fov)"),
        OPT_OUT(a->out, .arg = "PREFIX", .help = "output prefix", .def = "out"),
        {"--quiet", OPT_FLAG, OPT_DST(a->quiet), .help = "no progress bar"},
        {"--timing", OPT_FLAG, OPT_DST(a->timing),
         .help = "one line on stderr with the wall-clock seconds of each phase: start-up (the process's start to "
                 "main: loading, libraries), scene load (parse, meshes, textures, BVH), seed pass (MCMC), render, "
                 "output (images, CSVs), total"},
        {"--checkpoint", OPT_DOUBLE, OPT_DST(a->checkpoint), .arg = "SECONDS", .lo = 1e-3, .hi = 1e9,
         .help = "write the run's whole state to PREFIX.ckpt every SECONDS (atomically; Ctrl-C always leaves one); the "
                 "seed pass of pssmlt/mmlt/pitp/mlt is not checkpointed"},
        {"--resume", OPT_STRING, OPT_DST(a->resume), .arg = "FILE",
         .help = "continue the run FILE holds; give the same scene and options (it refuses others); with an --spp "
                 "budget the result is bit-identical to an uninterrupted run, with --time the run gets what its budget "
                 "had left"},
        {"--embree-isa", OPT_CALL, .call = set_isa, .arg = "ISA",
         .help = "Embree's kernels: sse2, sse4.2, avx, avx2 or avx512 (those this CPU runs; default: the best, or the "
                 "environment's PSS_EMBREE_ISA): hit points, so images, differ in the last bits between kernels"},
        {.type = OPT_TEXT,
         .help = "MCMC options (pssmlt, mmlt, pitp, mlt; the mmlt options apply to pitp too; mlt takes the seed pass, "
                 "length, budget and diagnostics options):"},
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
    bool ts = given(argc, argv, "--technique-s"), tt = given(argc, argv, "--technique-t");
    if (ts != tt) opts_fail(prog, "--technique-s and --technique-t: give both (one technique, s and t)");
    if (ts) technique_arg(a);
    /* the options both drivers read */
    m->seconds = a->mc.seconds, m->seed = a->mc.seed, m->threads = a->mc.threads;
    a->mc.progress = m->progress = !a->quiet;
    if (m->pss.rap_resolution) m->pss.rap = true;
    /* controlled steps need the Gaussian's density (mcmc/controlled_step.h) */
    if (m->small_step != SMALL_STEP_PSS) {
        if (given(argc, argv, "--kernel") && m->pss.kernel != KERNEL_GAUSSIAN)
            opts_fail(prog, "--small-step %s: needs --kernel gaussian", render_small_step_name(m->small_step));
        m->pss.kernel = KERNEL_GAUSSIAN;
    }
    if (m->technique_k && !strcmp(a->method, "pitp"))
        opts_fail(prog,
                  "--technique-images: pssmlt and mmlt only (PITP's perturbation moves a state between techniques)");
    mlt_cli_warn_unused(&spec, a->method, argc, argv);
}

/* What the MCMC methods take from the shared options and the scene. */
void render_args_mlt_setup(struct mlt_opts *m, const struct render_args *a, const struct scene *sc)
{
    m->method = !strcmp(a->method, "mmlt")   ? MLT_MMLT
                : !strcmp(a->method, "pitp") ? MLT_PITP
                : !strcmp(a->method, "mlt")  ? MLT_VEACH
                                             : MLT_PSSMLT;
    m->max_length = a->mc.max_length;
    m->min_length = a->mc.min_length;
    m->mutations = (long)a->mc.spp * sc->cam.width * sc->cam.height;
}

/* Every option that changes the numbers a run produces, as one line: a checkpoint resumes only
 * under the same. The MCMC methods' options must be set (mlt_setup) before. */
void render_args_identity(const struct render_args *a, const struct scene *sc, char *buf, size_t n)
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
    if (a->mc.only_t > 0 && len > 0 && (size_t)len < n)
        len += snprintf(buf + len, n - (size_t)len, " technique=%d,%d", a->mc.only_s, a->mc.only_t);
    /* every number-changing MCMC option, from its descriptor: none can be left out */
    if (strcmp(a->method, "pt") && strcmp(a->method, "bdpt") && len > 0 && (size_t)len < n)
        mlt_options_identity(&a->mlt, buf + len, n - (size_t)len);
}
