/* bin/render as a library call (render_run.h): load, checkpoint and resume, render, write. */
#include "tools/render_run.h"
#include "base/dist.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "common/opts.h"
#include "emitter/emitter.h"
#include "io/checkpoint.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "mcmc/mlt_options.h"
#include "path/scene_ready.h"
#include "scene/accel.h"
#include "scene/scene_hash.h"
#include "tools/render_args.h"
#include "tools/render_write.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

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

/* The normalisation's error moves the whole image's mean: above 1 % say so, once, and what halves it. */
static void warn_normalisation(const struct mlt_result *r, const struct mlt_opts *o)
{
    double e = r->b_image_rse;
    if (e > 0.01)
        fprintf(stderr,
                "render: warning: the normalisation's relative standard error is %.1f %% (--seed-paths %ld%s): the "
                "image's mean is that uncertain; %ld seed paths would bring the seed pass's to 0.5 %%%s\n",
                100 * e, o->seed_paths, o->progressive_norm ? ", --progressive-norm" : "",
                (long)ceil(o->seed_paths * (r->b_rse / 0.005) * (r->b_rse / 0.005)),
                o->progressive_norm ? "" : "; --progressive-norm adds the large steps' samples");
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
static int run_mc(struct render_args *a, const struct scene *sc, const struct ckpt_ctl *ctl, bool *ok, bool *partial,
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
    a->t.rendered = now_seconds();
    if (st.resume_failed) {
        fprintf(stderr, "render: --resume %s: the checkpoint's state does not fit this run\n", a->resume);
        img_destroy(img);
        return 2;
    }
    *ok = ctl->err[0] || !dist_root() ||
          (img_write_exr_png(img, a->out, err, errlen) && render_write_mc_csv(a, &st, err, errlen));
    *partial = st.partial;
    if (*ok && !ctl->err[0] && dist_root())
        printf("%s%s%s: %ld samples (%d spp) in %.2f s, %.0f samples/s (%s), %ld non-finite dropped%s\n",
               *partial ? "PARTIAL (interrupted) " : "", a->method, a->mc.sobol ? " (sobol)" : "", st.samples, st.spp,
               st.seconds, st.samples / st.seconds, threads_note(a->mc.threads), st.nonfinite,
               nonfinite_note(&st.nonfinite_len));
    if (*ok && !ctl->err[0] && dist_root()) warn_nonfinite(st.nonfinite, &st.nonfinite_len);
    if (*ok && !ctl->err[0] && dist_root() && st.tech) *ok = render_write_bdpt_tech(a, &st, img, err, errlen);
    bdpt_tech_free(st.tech);
    img_destroy(img);
    a->t.written = now_seconds();
    return 0;
}

/* --method pssmlt, mmlt or pitp; as run_mc. */
static int run_mcmc(struct render_args *a, const struct scene *sc, const struct ckpt_ctl *ctl, bool *ok, bool *partial,
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
    /* options that rule each other out are bad input: one line and status 2, before any work */
    if (!mlt_options_check(&a->mlt, err, errlen)) opts_fail("render", "%s", err);
    struct mlt_result r;
    char mixing[1024] = "";
    *ok = mlt_render(sc, &a->mlt, &r, err, errlen);
    a->t.rendered = now_seconds();
    a->t.seed_pass = r.seed_seconds;
    if (!*ok) {
        fprintf(stderr, "%s%s\n", a->resume ? "render: --resume: " : "", err);
        return a->resume ? 2 : 1;
    }
    *partial = r.partial;
    *ok = ctl->err[0] || !dist_root() ||
          (img_write_exr_png(r.img, a->out, err, errlen) && render_write_csv(a, &r, err, errlen) &&
           render_write_mixing(a, &r, mixing, sizeof mixing, err, errlen) &&
           (!r.angle || render_write_angle(a, &r, err, errlen)) && (!r.tech || render_write_tech(a, &r, err, errlen)));
    if (*ok && !ctl->err[0] && dist_root())
        printf("%s%s: %ld mutations in %.2f s (+%.2f s seed pass, normalisation rel. s.e. %.2f %%), %.0f mutations/s "
               "(%s), "
               "%ld non-finite dropped%s\n",
               *partial ? "PARTIAL (interrupted) " : "", a->method, r.mutations, r.seconds, r.seed_seconds,
               100 * r.b_image_rse, r.mutations / r.seconds, threads_note(a->mlt.threads), r.nonfinite,
               nonfinite_note(&r.stats.nonfinite));
    if (*ok && !ctl->err[0] && dist_root()) {
        warn_nonfinite(r.nonfinite, &r.stats.nonfinite);
        warn_normalisation(&r, &a->mlt);
        if (*mixing && !a->quiet)
            fprintf(stderr, "render: warning: the chains mix poorly: %s; see %s.mixing.csv\n", mixing, a->out);
    }
    mlt_result_free(&r);
    a->t.written = now_seconds();
    return 0;
}

/* Seconds from the process's start to now (/proc/self/stat's start time, in clock ticks since
 * boot, against CLOCK_BOOTTIME): 10 ms resolution; NAN where /proc is not there. */
static double process_age(void)
{
    FILE *f = fopen("/proc/self/stat", "r");
    if (!f) return NAN;
    char buf[1024];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = 0;
    const char *p = strrchr(buf, ')'); /* the command name may hold spaces */
    unsigned long long start = 0;
    /* after the name: state is field 3, starttime field 22 */
    if (!p ||
        sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %*u %*u %*d %*d %*d %*d %*d %*d %llu", &start) != 1)
        return NAN;
    struct timespec ts;
    clock_gettime(CLOCK_BOOTTIME, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec - (double)start / (double)sysconf(_SC_CLK_TCK);
}

/* --timing's line: where a run's wall time goes, phase by phase. */
static void print_timing(const struct render_args *a)
{
    double render = a->t.rendered - a->t.loaded - a->t.seed_pass;
    fprintf(stderr,
            "render: timing: start-up %.3f s, scene load %.3f s, seed pass %.3f s, render %.3f s, output %.3f s, "
            "total %.3f s (wall clock)\n",
            a->t.startup, a->t.loaded - a->t.main, a->t.seed_pass, render, a->t.written - a->t.rendered,
            a->t.startup + a->t.written - a->t.main);
}

/* The scene, resized and with the defaults it gives (spp, max length); NULL with *status 2 when it
 * cannot be read or an MCMC method has no light to sample. */
static struct scene *load(struct render_args *a, int *status)
{
    char err[1024];
    struct scene *sc = scene_load(a->scene, err, sizeof err);
    *status = 2;
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return NULL;
    }
    bool mcmc = strcmp(a->method, "pt") && strcmp(a->method, "bdpt");
    if (emitters_count(sc) == 0) {
        /* PT and BDPT estimate zero correctly; an MCMC method has no target to sample. */
        fprintf(stderr,
                mcmc ? "%s: the scene has no emitter: --method %s has no light to sample\n"
                     : "%s: warning: the scene has no emitter; the image will be black\n",
                a->scene, a->method);
        if (mcmc) {
            scene_free(sc);
            return NULL;
        }
    }
    if (a->res[0]) camera_resize(&sc->cam, a->res[0], a->res[1]);
    if (a->mc.spp < 0) a->mc.spp = sc->spp > 0 ? sc->spp : 16;
    if (a->mc.max_length < 0) a->mc.max_length = sc->max_length;
    if (a->mc.progress && !isatty(2)) a->mc.progress = a->mlt.progress = false;
    *status = 0;
    return sc;
}

/* A run's checkpoint: where it goes, what it must match, and what --resume read. */
struct ckpt_setup {
    char path[4096], identity[2048];
    struct ckpt_ctl ctl;
    struct ckpt_buf resume;
};

/* Checkpoints are always armed: Ctrl-C leaves one even without --checkpoint. Over N > 1 MPI ranks
 * each rank keeps its own threads' state, in PREFIX.ckpt.rankR, and --resume FILE reads
 * FILE.rankR. False (its line printed) when --resume's file does not fit the run. */
static bool arm_checkpoint(struct render_args *a, const struct scene *sc, struct ckpt_setup *k)
{
    char err[1024], resume_path[4096];
    int N = dist_size(), R = dist_rank();
    snprintf(k->path, sizeof k->path, "%s.ckpt", a->out);
    if (N > 1) snprintf(k->path + strlen(k->path), sizeof k->path - strlen(k->path), ".rank%d", R);
    render_args_identity(a, sc, k->identity, sizeof k->identity);
    snprintf(k->identity + strlen(k->identity), sizeof k->identity - strlen(k->identity), " ranks=%d", N);
    ckpt_remove_stale_temporaries(k->path); /* a run that ends before its first write cleans up too */
    k->ctl = (struct ckpt_ctl){
        .path = k->path, .every = a->checkpoint, .id = {ckpt_build_hash(), ckpt_scene_hash(sc), k->identity}};
    a->mc.ckpt = a->mlt.ckpt = &k->ctl;
    if (!a->resume) return true;
    snprintf(resume_path, sizeof resume_path, N > 1 ? "%s.rank%d" : "%s", a->resume, R);
    long failed = !ckpt_read_file(resume_path, &k->ctl.id, &k->resume, err, sizeof err), own = failed;
    dist_sum_longs(&failed, 1); /* all ranks resume, or none */
    if (!failed) {
        k->ctl.resume = &k->resume;
        return true;
    }
    if (own)
        fprintf(stderr, "render: --resume %s\n", err);
    else
        fprintf(stderr,
                "render: --resume %s: %ld of the %d ranks' checkpoints (%s.rankR) are missing, damaged or of another "
                "run\n",
                a->resume, failed, N, a->resume);
    return false;
}

int render_run(int argc, char **argv)
{
    struct render_args a = {0};
    a.mc = (struct render_opts){.method = METHOD_BDPT, .spp = -1, .max_length = -1};
    pss_opts_default(&a.mlt.pss, 1, 1);
    accel_set_isa(NULL); /* an earlier run's --embree-isa is not this one's */
    a.t.startup = process_age();
    a.t.main = now_seconds();
    render_args_parse(argc, argv, &a);
    const char *inject = getenv("PSS_INJECT_NONFINITE"); /* tests only (path/splat.h) */
    if (inject) nonfinite_inject_every = atol(inject);
    int rc;
    struct scene *sc = load(&a, &rc);
    if (!sc) return rc;
    a.t.loaded = now_seconds();
    render_args_mlt_setup(&a.mlt, &a, sc);
    struct ckpt_setup k = {0};
    char err[1024];
    bool ok = false, partial = false;
    if (!arm_checkpoint(&a, sc, &k))
        rc = 2;
    else {
        interrupt_install();
        rc = strcmp(a.method, "pt") && strcmp(a.method, "bdpt")
                 ? run_mcmc(&a, sc, &k.ctl, &ok, &partial, err, sizeof err)
                 : run_mc(&a, sc, &k.ctl, &ok, &partial, err, sizeof err);
    }
    ckpt_buf_free(&k.resume);
    scene_free(sc);
    if (rc) return rc;
    if (a.timing && ok && dist_root()) print_timing(&a);
    /* A checkpoint that could not be written stopped the run (ckpt_save_run): its line alone, and
     * no outputs, which a full disk would refuse too. */
    if (k.ctl.err[0])
        fprintf(stderr, "render: %s\n", k.ctl.err);
    else if (!ok)
        fprintf(stderr, "render: %s\n", err);
    else if (partial && k.ctl.written)
        fprintf(stderr, "render: interrupted; continue with --resume %s.ckpt\n", a.out);
    return !ok || k.ctl.err[0] ? 1 : partial ? 130 : 0;
}
