/* bin/render: renders a Tungsten scene with one method; writes PREFIX.exr, PREFIX.png and, for the
 * MCMC methods, PREFIX.csv with acceptance statistics. Built with MPI=1 and started by mpirun, its
 * ranks share the render (core/dist.h) and rank 0 alone writes the outputs and the summary. */
#include "base/dist.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "common/cli.h"
#include "emitter/emitter.h"
#include "io/checkpoint.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "scene/accel.h"
#include "scene/scene_hash.h"
#include "version.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *usage =
    "usage: render SCENE.json [options]\n"
    "  --method pt|bdpt|pssmlt|mmlt|pitp  estimator (default bdpt; pitp: MMLT with the\n"
    "                       path-invariant technique perturbation, thesis 5.2)\n"
    "  --spp N              samples per pixel; for pssmlt/mmlt/pitp mutations per pixel\n"
    "                       (default: the scene's renderer.spp, else 16)\n"
    "  --time SECONDS       equal-time budget instead of --spp: pssmlt/mmlt chains stop at it\n"
    "                       (the seed pass comes on top); pt/bdpt render whole passes of\n"
    "                       1 spp while the next fits in it\n"
    "  --seed S             random seed (default 1); same seed and threads -> same output\n"
    "  --threads T          worker threads (default: all cores)\n"
    "  --max-length K       maximum path length in segments (default: integrator.max_bounces)\n"
    "  --min-length K       leave out paths shorter than K segments (3: no direct lighting; default 1)\n"
    "  --resolution WxH     override the camera resolution (same horizontal fov)\n"
    "  --out PREFIX         output prefix (default out)\n"
    "  --quiet              no progress bar\n"
    "  --checkpoint SECONDS write the run's whole state to PREFIX.ckpt every SECONDS (atomically;\n"
    "                       Ctrl-C always leaves one); the seed pass of pssmlt/mmlt/pitp is not\n"
    "                       checkpointed\n"
    "  --resume FILE        continue the run FILE holds; give the same scene and options (it refuses\n"
    "                       others); with an --spp budget the result is bit-identical to an\n"
    "                       uninterrupted run, with --time the run gets what its budget had left\n"
    "  --embree-isa ISA     Embree's kernels: sse2, sse4.2, avx, avx2 or avx512 (those this CPU\n"
    "                       runs; default: the best, or the environment's PSS_EMBREE_ISA): hit\n"
    "                       points, so images, differ in the last bits between kernels\n"
    "MCMC options (pssmlt, mmlt, pitp; the mmlt options apply to pitp too):\n"
    "  --p-large P          large-step probability (default 0.1)\n"
    "  --kernel kelemen|gaussian  small-step kernel (default kelemen: s1 = 1/1024, s2 = 1/64)\n"
    "  --sigma S            gaussian small-step standard deviation (default 1/64)\n"
    "  --rap                resolution-aware proposals: image steps corrected for aspect ratio\n"
    "  --rap-resolution     also scale image steps to a fixed size in pixels (thesis 4.1)\n"
    "  --cdc                constrained discrete choices: small steps keep discrete numbers\n"
    "  --seed-paths N       samples of the normalisation seed pass (default 100000)\n"
    "  --large-step mmlt|mctls|hybrid  mmlt's large step (default mmlt; mctls: thesis 4.3)\n"
    "  --hybrid-length K    hybrid: MCTLS from path length K on, MMLT large steps below (default 6)\n"
    "  --uniform-lengths    mmlt: equal mutations per path length instead of in proportion to b_k\n"
    "  --max-heuristic      pssmlt: Kelemen's maximum heuristic instead of the balance heuristic\n"
    "  --small-step pss|controlled|root  mmlt/pitp small step (default pss; controlled: thesis 5.3\n"
    "                       Alg. 4, root: Alg. 3, analysis only); the latter two use the Gaussian kernel\n"
    "  --angle-stats        mmlt, pitp: angle change of every small step, PREFIX.angle.exr and .angle.csv\n"
    "  --technique-images K pssmlt, mmlt (MMLT large steps): per-technique images of path length K\n"
    "                       (MMLT paper 5): PREFIX.tech-tT.exr/.png contribution, PREFIX.count-tT.exr/.png\n"
    "                       chain samples in technique T, PREFIX.tech.csv shares; pssmlt runs slower with it\n"
    "Prints one summary line: method, samples, seconds, samples/s.\n";

struct args {
    const char *scene, *out, *resume;
    double checkpoint;
    char method[16];
    struct render_opts mc;
    struct mlt_opts mlt;
    int width, height;
    bool kernel_given;
};

/* Options that only some methods read; given to another method they would be silently ignored,
 * which would quietly change an experiment. */
static const char *const mcmc_only[] = {"--p-large", "--kernel", "--sigma", "--rap", "--rap-resolution", "--cdc",
                                        "--seed-paths", "--large-step", "--hybrid-length", "--uniform-lengths",
                                        "--max-heuristic", "--small-step", "--angle-stats",
                                        "--technique-images", NULL};
static const char *const mmlt_only[] = {"--large-step", "--hybrid-length", "--uniform-lengths", "--small-step",
                                        "--angle-stats", NULL};
static const char *const pssmlt_only[] = {"--max-heuristic", NULL};

static bool listed(const char *o, const char *const *list)
{
    for (; *list; list++)
        if (!strcmp(o, *list)) return true;
    return false;
}

/* One warning line per option that the chosen method does not read. */
static void warn_unused(const char *prog, int argc, char **argv, const char *method)
{
    bool mcmc = !strcmp(method, "pssmlt") || !strcmp(method, "mmlt") || !strcmp(method, "pitp");
    bool multiplexed = !strcmp(method, "mmlt") || !strcmp(method, "pitp");
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        const char *only = !mcmc && listed(o, mcmc_only)                   ? "pssmlt, mmlt and pitp"
                           : !strcmp(method, "pssmlt") && listed(o, mmlt_only) ? "mmlt and pitp"
                           : multiplexed && listed(o, pssmlt_only) ? "pssmlt"
                                                                              : NULL;
        if (only && !mcmc && !strcmp(o, "--technique-images")) only = "pssmlt and mmlt"; /* not pitp */
        if (only) fprintf(stderr, "%s: warning: %s has no effect with --method %s (it applies to %s)\n", prog, o, method, only);
    }
}

static void parse(int argc, char **argv, struct args *a)
{
    const char *prog = "render";
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
#define VALUE cli_value(prog, argc, argv, &i)
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            fputs(usage, stdout);
            exit(0);
        } else if (!strcmp(o, "--method")) {
            const char *v = VALUE;
            if (strcmp(v, "pt") && strcmp(v, "bdpt") && strcmp(v, "pssmlt") && strcmp(v, "mmlt") && strcmp(v, "pitp"))
                cli_fail(prog, "--method: expected pt, bdpt, pssmlt, mmlt or pitp, got '%s'", v);
            snprintf(a->method, sizeof a->method, "%s", v);
        } else if (!strcmp(o, "--spp")) {
            a->mc.spp = (int)cli_long(prog, o, VALUE, 1, 1 << 24);
        } else if (!strcmp(o, "--time")) {
            a->mc.seconds = a->mlt.seconds = cli_double(prog, o, VALUE, 1e-3, 1e7);
        } else if (!strcmp(o, "--seed")) {
            a->mc.seed = a->mlt.seed = cli_u64(prog, o, VALUE);
        } else if (!strcmp(o, "--threads")) {
            a->mc.threads = a->mlt.threads = (int)cli_long(prog, o, VALUE, 1, 1024);
        } else if (!strcmp(o, "--min-length")) {
            a->mc.min_length = (int)cli_long(prog, o, VALUE, 1, MAX_PATH_LENGTH);
        } else if (!strcmp(o, "--max-length")) {
            a->mc.max_length = (int)cli_long(prog, o, VALUE, 1, MAX_PATH_LENGTH);
        } else if (!strcmp(o, "--resolution")) {
            const char *v = VALUE;
            char extra;
            if (sscanf(v, "%dx%d%c", &a->width, &a->height, &extra) != 2 || a->width < 1 || a->height < 1 ||
                a->width > 1 << 15 || a->height > 1 << 15)
                cli_fail(prog, "--resolution: expected WxH with positive integers, got '%s'", v);
            if ((long)a->width * a->height > SCENE_MAX_PIXELS)
                cli_fail(prog, "--resolution: %s is above the limit of %ld pixels (8192x8192)", v, SCENE_MAX_PIXELS);
        } else if (!strcmp(o, "--out")) {
            a->out = VALUE;
        } else if (!strcmp(o, "--checkpoint")) {
            a->checkpoint = cli_double(prog, o, VALUE, 1e-3, 1e9);
        } else if (!strcmp(o, "--resume")) {
            a->resume = VALUE;
        } else if (!strcmp(o, "--quiet")) {
            a->mc.progress = a->mlt.progress = false;
        } else if (!strcmp(o, "--embree-isa")) {
            const char *v = VALUE;
            if (!accel_set_isa(v)) {
                char list[64] = "";
                for (const char *const *i = accel_isas(); *i; i++)
                    snprintf(list + strlen(list), sizeof list - strlen(list), " %s", *i);
                cli_fail(prog, "--embree-isa: this CPU and Embree run only:%s; got '%s'", list, v);
            }
        } else if (!strcmp(o, "--p-large")) {
            a->mlt.p_large = cli_double(prog, o, VALUE, 0, 1);
        } else if (!strcmp(o, "--kernel")) {
            const char *v = VALUE;
            a->kernel_given = true;
            if (!strcmp(v, "kelemen")) a->mlt.pss.kernel = KERNEL_KELEMEN;
            else if (!strcmp(v, "gaussian")) a->mlt.pss.kernel = KERNEL_GAUSSIAN;
            else cli_fail(prog, "--kernel: expected kelemen or gaussian, got '%s'", v);
        } else if (!strcmp(o, "--sigma")) {
            a->mlt.pss.sigma = cli_double(prog, o, VALUE, 1e-9, 1);
        } else if (!strcmp(o, "--rap")) {
            a->mlt.pss.rap = true;
        } else if (!strcmp(o, "--rap-resolution")) {
            a->mlt.pss.rap = a->mlt.pss.rap_resolution = true;
        } else if (!strcmp(o, "--cdc")) {
            a->mlt.pss.cdc = true;
        } else if (!strcmp(o, "--large-step")) {
            const char *v = VALUE;
            if (!strcmp(v, "mmlt")) a->mlt.large_step = LARGE_MMLT;
            else if (!strcmp(v, "mctls")) a->mlt.large_step = LARGE_MCTLS;
            else if (!strcmp(v, "hybrid")) a->mlt.large_step = LARGE_HYBRID;
            else cli_fail(prog, "--large-step: expected mmlt, mctls or hybrid, got '%s'", v);
        } else if (!strcmp(o, "--hybrid-length")) {
            a->mlt.hybrid_length = (int)cli_long(prog, o, VALUE, 1, MAX_PATH_LENGTH);
        } else if (!strcmp(o, "--max-heuristic")) {
            a->mlt.max_heuristic = true;
        } else if (!strcmp(o, "--small-step")) {
            const char *v = VALUE;
            if (!strcmp(v, "pss")) a->mlt.small_step = SMALL_STEP_PSS;
            else if (!strcmp(v, "controlled")) a->mlt.small_step = SMALL_STEP_CONTROLLED;
            else if (!strcmp(v, "root")) a->mlt.small_step = SMALL_STEP_ROOT;
            else cli_fail(prog, "--small-step: expected pss, controlled or root, got '%s'", v);
        } else if (!strcmp(o, "--angle-stats")) {
            a->mlt.angle_stats = true;
        } else if (!strcmp(o, "--technique-images")) {
            a->mlt.technique_k = (int)cli_long(prog, o, VALUE, 1, MAX_PATH_LENGTH);
        } else if (!strcmp(o, "--uniform-lengths")) {
            a->mlt.uniform_lengths = true;
        } else if (!strcmp(o, "--seed-paths")) {
            a->mlt.seed_paths = cli_long(prog, o, VALUE, 1, 1L << 40);
        } else if (o[0] == '-') {
            cli_fail(prog, "unknown option '%s' (see --help)", o);
        } else if (a->scene) {
            cli_fail(prog, "more than one scene given ('%s' and '%s')", a->scene, o);
        } else {
            a->scene = o;
        }
#undef VALUE
    }
    if (!a->scene) cli_fail(prog, "no scene given (see --help)");
    /* controlled steps need the Gaussian's density (core/controlled_step.h) */
    if (a->mlt.small_step != SMALL_STEP_PSS) {
        if (a->kernel_given && a->mlt.pss.kernel != KERNEL_GAUSSIAN)
            cli_fail(prog, "--small-step %s: needs --kernel gaussian", a->mlt.small_step == SMALL_STEP_ROOT ? "root" : "controlled");
        a->mlt.pss.kernel = KERNEL_GAUSSIAN;
    }
    warn_unused(prog, argc, argv, a->method);
    if (a->mlt.technique_k && !strcmp(a->method, "pitp"))
        cli_fail(prog,
                 "--technique-images: pssmlt and mmlt only (PITP's perturbation moves a state between techniques)");
}

/* PREFIX.angle.exr (mean angle change per pixel, radians) and PREFIX.angle.csv (per length). */
static bool write_angle(const struct args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char path[4096], *buf = NULL;
    size_t len = 0;
    struct image *im = angle_acc_image(r->angle);
    snprintf(path, sizeof path, "%s.angle.exr", a->out);
    bool ok = img_write_exr(im, 1.0, path, err, errlen);
    img_destroy(im);
    FILE *f = open_memstream(&buf, &len);
    fprintf(f, "# render %s --method %s --small-step %s\n# commit %s\n# seed %llu\n# skipped_steps %ld\n", a->scene,
            a->method, (const char *[]){"pss", "controlled", "root"}[a->mlt.small_step], GIT_COMMIT,
            (unsigned long long)a->mlt.seed, r->angle->skipped);
    angle_acc_write_csv(f, r->angle);
    fclose(f);
    snprintf(path, sizeof path, "%s.angle.csv", a->out);
    ok = ok && write_text_atomic(path, buf, err, errlen);
    free(buf);
    return ok;
}

/* The per-technique images and PREFIX.tech.csv (core/tech_image.h). */
static bool write_tech(const struct args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char head[8192];
    snprintf(head, sizeof head,
             "# render %s --method %s --technique-images %d\n# commit %s\n# seed %llu\n"
             "# mutations %ld\n# seconds %.3f\n",
             a->scene, a->method, a->mlt.technique_k, GIT_COMMIT, (unsigned long long)a->mlt.seed, r->mutations, r->seconds);
    return tech_acc_write(r->tech, a->out, head, err, errlen);
}

static bool write_csv(const struct args *a, const struct mlt_result *r, char *err, size_t errlen)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    fprintf(f, "# render %s --method %s\n# commit %s\n# seed %llu\n# threads %d\n# max_length %d\n", a->scene,
            a->method, GIT_COMMIT, (unsigned long long)a->mlt.seed, a->mlt.threads, a->mlt.max_length);
    if (dist_size() > 1) fprintf(f, "# ranks %d\n", dist_size()); /* threads are per rank */
    fprintf(f, "# large_step %s\n# hybrid_length %d\n# uniform_lengths %d\n",
            (const char *[]){"mmlt", "mctls", "hybrid"}[a->mlt.large_step], a->mlt.hybrid_length, a->mlt.uniform_lengths);
    fprintf(f, "# mis %s\n", a->mlt.max_heuristic ? "maximum" : "balance");
    fprintf(f, "# small_step %s\n# sigma %g\n", (const char *[]){"pss", "controlled", "root"}[a->mlt.small_step], a->mlt.pss.sigma);
    if (a->mlt.small_step != SMALL_STEP_PSS)
        fprintf(f, "# controlled_failed_forward %ld\n# controlled_failed_reverse %ld\n", r->ctrl_fail_forward,
                r->ctrl_fail_reverse);
    fprintf(f, "# p_large %g\n# kernel %s\n# rap %d\n# rap_resolution %d\n# cdc %d\n# seed_paths %ld\n", a->mlt.p_large,
            a->mlt.pss.kernel == KERNEL_KELEMEN ? "kelemen" : "gaussian", a->mlt.pss.rap, a->mlt.pss.rap_resolution,
            a->mlt.pss.cdc, a->mlt.seed_paths);
    if (r->partial) fprintf(f, "# PARTIAL: interrupted after %ld mutations\n", r->mutations);
    fprintf(f, "# mutations %ld\n# seconds %.3f\n# seed_seconds %.3f\n# mutations_per_second %.0f\n# nonfinite %ld\n",
            r->mutations, r->seconds, r->seed_seconds, r->mutations / r->seconds, r->nonfinite);
    if (a->mlt.method == MLT_PITP) {
        const struct accept_cell *pc = &r->stats.total[PROPOSAL_PITP];
        fprintf(f, "# pitp_perturbations %ld\n# pitp_failures %ld\n# pitp_failure_fraction %.9g\n", pc->attempts,
                pc->failed, pc->attempts ? (double)pc->failed / pc->attempts : 0.0);
    }
    fprintf(f, "# b %.9g\n", r->b);
    for (int k = 1; k <= a->mlt.max_length && a->mlt.method != MLT_PSSMLT; k++) fprintf(f, "# b_%d %.9g\n", k, r->b_k[k]);
    stats_write_csv(f, a->method, &r->stats, true);
    fclose(f);
    char path[4096];
    snprintf(path, sizeof path, "%s.csv", a->out);
    bool ok = write_text_atomic(path, buf, err, errlen);
    free(buf);
    return ok;
}

/* Every option that changes the numbers a run produces, as one line: a checkpoint resumes only
 * under the same. */
static void options_text(const struct args *a, const struct scene *sc, char *buf, size_t n)
{
    const char *isa = accel_isa();
    if (!isa) /* Embree's own choice: the best this machine runs */
        for (const char *const *i = accel_isas(); *i; i++) isa = *i;
    int len = snprintf(buf, n, "method=%s spp=%d time=%g seed=%llu threads=%d max_length=%d min_length=%d resolution=%dx%d isa=%s",
                       a->method, a->mc.spp, a->mc.seconds, (unsigned long long)a->mc.seed, a->mc.threads,
                       a->mc.max_length, a->mc.min_length, sc->cam.width, sc->cam.height, isa ? isa : "?");
    if (strcmp(a->method, "pt") && strcmp(a->method, "bdpt") && len > 0 && (size_t)len < n) {
        const struct mlt_opts *m = &a->mlt;
        snprintf(buf + len, n - (size_t)len,
                 " p_large=%g kernel=%d sigma=%g rap=%d rap_resolution=%d cdc=%d seed_paths=%ld large_step=%d "
                 "hybrid_length=%d uniform_lengths=%d max_heuristic=%d small_step=%d angle_stats=%d technique_k=%d",
                 m->p_large, m->pss.kernel, m->pss.sigma, m->pss.rap, m->pss.rap_resolution, m->pss.cdc, m->seed_paths,
                 m->large_step, m->hybrid_length, m->uniform_lengths, m->max_heuristic, m->small_step, m->angle_stats,
                 m->technique_k);
    }
}

/* "(4 threads)", or under MPI "(2 ranks x 2 threads)". */
static const char *threads_note(int threads)
{
    static char s[64];
    if (dist_size() > 1) snprintf(s, sizeof s, "%d ranks x %d threads", dist_size(), threads);
    else snprintf(s, sizeof s, "%d threads", threads);
    return s;
}

int main(int argc, char **argv)
{
    dist_init(&argc, &argv);
    struct args a = {.out = "out", .method = "bdpt"};
    a.mc = (struct render_opts){.method = METHOD_BDPT, .spp = -1, .seed = 1, .threads = cpu_count(), .max_length = -1,
                                .progress = true};
    a.mlt = (struct mlt_opts){.p_large = 0.1, .seed_paths = 100000, .seed = 1, .threads = cpu_count(), .progress = true, .hybrid_length = 6};
    pss_opts_default(&a.mlt.pss, 1, 1);
    struct pss_opts cli_pss = a.mlt.pss;
    parse(argc, argv, &a);
    cli_pss = a.mlt.pss;
    cli_require_image_output("render");
    char err[1024];
    struct scene *sc = scene_load(a.scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    bool mcmc = strcmp(a.method, "pt") && strcmp(a.method, "bdpt");
    if (emitters_count(sc) == 0) {
        /* PT and BDPT estimate zero correctly; an MCMC method has no target to sample. */
        fprintf(stderr, mcmc ? "%s: the scene has no emitter: --method %s has no light to sample\n"
                             : "%s: warning: the scene has no emitter; the image will be black\n", a.scene, a.method);
        if (mcmc) {
            scene_free(sc);
            return 2;
        }
    }
    if (a.width) camera_resize(&sc->cam, a.width, a.height);
    if (a.mc.spp < 0) a.mc.spp = sc->spp > 0 ? sc->spp : 16;
    if (a.mc.max_length < 0) a.mc.max_length = sc->max_length;
    if (a.mc.progress && !isatty(2)) a.mc.progress = a.mlt.progress = false;
    /* Checkpoints are always armed: Ctrl-C leaves one even without --checkpoint. Over N > 1 MPI
     * ranks each rank keeps its own threads' state, in PREFIX.ckpt.rankR, and --resume FILE reads
     * FILE.rankR. */
    char ckpt_path[4096], resume_path[4096], opts[1100];
    int N = dist_size(), R = dist_rank();
    snprintf(ckpt_path, sizeof ckpt_path, "%s.ckpt", a.out);
    if (N > 1) snprintf(ckpt_path + strlen(ckpt_path), sizeof ckpt_path - strlen(ckpt_path), ".rank%d", R);
    options_text(&a, sc, opts, sizeof opts);
    snprintf(opts + strlen(opts), sizeof opts - strlen(opts), " ranks=%d", N);
    struct ckpt_ctl ctl = {.path = ckpt_path, .every = a.checkpoint, .id = {ckpt_build_hash(), ckpt_scene_hash(sc), opts}};
    struct ckpt_buf resume = {0};
    if (a.resume) {
        snprintf(resume_path, sizeof resume_path, N > 1 ? "%s.rank%d" : "%s", a.resume, R);
        long failed = !ckpt_read_file(resume_path, &ctl.id, &resume, err, sizeof err), own = failed;
        dist_sum_longs(&failed, 1); /* all ranks resume, or none */
        if (failed) {
            if (own) fprintf(stderr, "render: --resume %s\n", err);
            else fprintf(stderr, "render: --resume %s: %ld of the %d ranks' checkpoints (%s.rankR) are missing, damaged or of another run\n",
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
    if (!strcmp(a.method, "pt") || !strcmp(a.method, "bdpt")) {
        method_parse(a.method, &a.mc.method);
        struct render_stats st;
        struct image *img = render_mc(sc, &a.mc, &st);
        if (st.resume_failed) {
            fprintf(stderr, "render: --resume %s: the checkpoint's state does not fit this run\n", a.resume);
            img_destroy(img);
            ckpt_buf_free(&resume);
            scene_free(sc);
            return 2;
        }
        ok = !dist_root() || img_write_exr_png(img, a.out, err, sizeof err);
        partial = st.partial;
        if (ok && dist_root())
            printf("%s%s: %ld samples (%d spp) in %.2f s, %.0f samples/s (%s), %ld non-finite dropped\n",
                   partial ? "PARTIAL (interrupted) " : "", a.method, st.samples, st.spp, st.seconds, st.samples / st.seconds,
                   threads_note(a.mc.threads), st.nonfinite);
        img_destroy(img);
    } else {
        a.mlt.method = !strcmp(a.method, "mmlt") ? MLT_MMLT : !strcmp(a.method, "pitp") ? MLT_PITP : MLT_PSSMLT;
        a.mlt.max_length = a.mc.max_length;
        a.mlt.min_length = a.mc.min_length;
        if (a.mlt.technique_k && (a.mlt.technique_k > a.mlt.max_length || a.mlt.technique_k < a.mlt.min_length ||
                                  a.mlt.large_step != LARGE_MMLT))
            cli_fail("render",
                     "--technique-images %d: needs a length within --min-length %d..--max-length %d and MMLT "
                     "large steps",
                     a.mlt.technique_k, a.mlt.min_length, a.mlt.max_length);
        a.mlt.mutations = (long)a.mc.spp * sc->cam.width * sc->cam.height;
        a.mlt.pss = cli_pss;
        a.mlt.pss.width = camera_film_width(&sc->cam);
        a.mlt.pss.height = camera_film_height(&sc->cam);
        struct mlt_result r;
        ok = mlt_render(sc, &a.mlt, &r, err, sizeof err);
        if (!ok) {
            fprintf(stderr, "%s%s\n", a.resume ? "render: --resume: " : "", err);
            ckpt_buf_free(&resume);
            scene_free(sc);
            return a.resume ? 2 : 1;
        }
        partial = r.partial;
        ok = !dist_root() || (img_write_exr_png(r.img, a.out, err, sizeof err) && write_csv(&a, &r, err, sizeof err) &&
                              (!r.angle || write_angle(&a, &r, err, sizeof err)) && (!r.tech || write_tech(&a, &r, err, sizeof err)));
        if (ok && dist_root())
            printf("%s%s: %ld mutations in %.2f s (+%.2f s seed pass), %.0f mutations/s (%s), %ld non-finite "
                   "dropped\n",
                   partial ? "PARTIAL (interrupted) " : "", a.method, r.mutations, r.seconds, r.seed_seconds, r.mutations / r.seconds,
                   threads_note(a.mlt.threads), r.nonfinite);
        mlt_result_free(&r);
    }
    if (!ok) fprintf(stderr, "%s\n", err);
    if (ctl.err[0]) fprintf(stderr, "render: warning: %s\n", ctl.err);
    else if (partial && ctl.written) fprintf(stderr, "render: interrupted; continue with --resume %s.ckpt\n", a.out);
    ckpt_buf_free(&resume);
    scene_free(sc);
    return !ok ? 1 : partial ? 130 : 0;
}
