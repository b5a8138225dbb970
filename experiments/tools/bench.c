/* bin/bench: throughput on a committed scene. Embree's raw incoherent ray rate, PT and BDPT camera
 * samples and PSSMLT, MMLT and PITP mutations per second on one and two threads (320x180, max length 8
 * by default), the speed-up, the rays each sample or mutation casts, and peak memory with and
 * without image output; or, given several scenes, a table of the 1-thread figures. Numbers are
 * medians over --runs repetitions. */
#include "base/parallel.h"
#include "camera/camera.h"
#include "common/opts.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "sampling/warp.h"
#include "scene/accel.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_d);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Random rays from points inside the scene's box in uniform directions: incoherent by design.
 * They are generated before the clock starts (8192 of them, 0.4 MB, reused in turn) so that the
 * figure is Embree's alone. Closest-hit queries, or with `shadow` any-hit queries of the same rays
 * (unbounded, so they stop at the first surface they cross). */
enum { NRAYS = 1 << 13 };
static double ray_rate(const struct scene *sc, double seconds, bool shadow)
{
    static vec3 org[NRAYS], dir[NRAYS];
    rng r;
    rng_seed(&r, 3, 0);
    vec3 lo = sc->bbox_min, ext = vsub(sc->bbox_max, sc->bbox_min);
    for (int i = 0; i < NRAYS; i++) {
        org[i] = v3(lo.x + ext.x * rng_uniform(&r), lo.y + ext.y * rng_uniform(&r), lo.z + ext.z * rng_uniform(&r));
        dir[i] = warp_uniform_sphere(rng_uniform(&r), rng_uniform(&r));
    }
    long n = 0, hits = 0;
    double t0 = now_seconds();
    while (now_seconds() - t0 < seconds) {
        for (int i = 0; i < NRAYS; i++) {
            struct hit h;
            hits += shadow ? accel_occluded(sc->accel, org[i], dir[i], 0, INFINITY)
                           : accel_intersect(sc->accel, org[i], dir[i], 0, INFINITY, &h);
        }
        n += NRAYS;
    }
    (void)hits;
    return n / (now_seconds() - t0);
}

/* Rays per sample (or mutation), from the calling thread's counters across a 1-thread run. */
struct rays {
    double closest, shadow;
};

static struct rays rays_between(struct ray_counts a, struct ray_counts b, double n)
{
    return (struct rays){(double)(b.closest - a.closest) / n, (double)(b.shadow - a.shadow) / n};
}

/* `per`, when not NULL (1 thread only: the calling thread is then the only worker), receives the
 * rays per sample. */
static double sample_rate(const struct scene *sc, enum method m, int threads, int K, double seconds, struct rays *per)
{
    struct render_opts o = {.method = m, .spp = 1, .seed = 1, .threads = threads, .max_length = K};
    struct render_stats st;
    img_destroy(render_mc(sc, &o, &st));
    o.spp = (int)fmax(1, seconds / st.seconds);
    struct ray_counts c0 = accel_ray_counts();
    img_destroy(render_mc(sc, &o, &st));
    if (per) *per = rays_between(c0, accel_ray_counts(), (double)st.samples);
    return st.samples / st.seconds;
}

/* Mutations per second of the chains alone (the seed pass is excluded), and with `per` (1 thread)
 * the rays per mutation: the rays of a run without mutations, the same seed pass and chain starts,
 * are subtracted. */
static double mutation_rate(const struct scene *sc, enum mlt_method m, enum small_step ss, int threads, int K,
                            double seconds, struct rays *per)
{
    struct mlt_opts o = {.method = m,
                         .p_large = 0.1,
                         .pitp_rate = 1,
                         .seconds = seconds,
                         .seed_paths = 20000,
                         .seed = 1,
                         .threads = threads,
                         .max_length = K,
                         .small_step = ss};
    pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
    if (ss != SMALL_STEP_PSS) o.pss.kernel = KERNEL_GAUSSIAN; /* controlled steps' density (controlled_step.h) */
    struct mlt_result r;
    char err[256];
    /* start - before: the rays of the seed pass and chain starts alone */
    struct ray_counts before = accel_ray_counts(), start = before;
    if (per) {
        struct mlt_opts none = o;
        none.seconds = 0;
        none.mutations = 0;
        if (!mlt_render(sc, &none, &r, err, sizeof err)) return 0;
        mlt_result_free(&r);
        start = accel_ray_counts();
    }
    if (!mlt_render(sc, &o, &r, err, sizeof err)) return 0;
    double rate = r.mutations / r.seconds;
    if (per) {
        struct ray_counts end = accel_ray_counts();
        end.closest -= start.closest - before.closest;
        end.shadow -= start.shadow - before.shadow;
        *per = rays_between(start, end, (double)r.mutations);
    }
    mlt_result_free(&r);
    return rate;
}

/* The cost of PITP's technique move, differential and in the process's CPU seconds (a loaded
 * machine stretches wall time, not CPU time; the main thread waits asleep): PITP at --pitp-rate 1
 * and 0 from the same seed with the same mutation budget make the same iterations, large and small
 * steps alike, after the same seed pass and chain starts, so the difference over the perturbations
 * made is the time of one. Beside it the small step's own time: PITP at P = 0 with --p-large 0,
 * every iteration one of MMLT's small steps, at two budgets (the difference cancels the seed pass
 * and chain starts). One thread, medians over `runs`, the budget about `seconds` of the P = 1
 * chain. NAN when a run fails. */
struct technique_cost {
    double small_us, move_us;
};

/* One run's CPU seconds, and its small steps and perturbations. */
static bool pitp_run(const struct scene *sc, double rate, double p_large, long mutations, int K, double *sec,
                     long *small, long *moves)
{
    struct mlt_opts o = {.method = MLT_PITP,
                         .p_large = p_large,
                         .pitp_rate = rate,
                         .mutations = mutations,
                         .seed_paths = 20000,
                         .seed = 1,
                         .threads = 1,
                         .max_length = K};
    pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
    struct mlt_result r;
    char err[256];
    double t0 = budget_seconds(true, 1);
    if (!mlt_render(sc, &o, &r, err, sizeof err)) return false;
    *sec = budget_seconds(true, 1) - t0;
    *small = r.stats.total[PROPOSAL_SMALL].attempts;
    *moves = r.stats.total[PROPOSAL_PITP].attempts;
    mlt_result_free(&r);
    return *small > 0;
}

static struct technique_cost technique_cost(const struct scene *sc, int runs, double seconds, int K)
{
    struct technique_cost c = {NAN, NAN};
    double s1, s2, move_us[99], small_us[99];
    long small, moves, n = 20000;
    if (!pitp_run(sc, 1, 0.1, n, K, &s1, &small, &moves) || !pitp_run(sc, 1, 0.1, 2 * n, K, &s2, &small, &moves) ||
        !(s2 > s1))
        return c;
    n = (long)(n * seconds / (s2 - s1)); /* the chain alone: the seed pass cancels */
    for (int i = 0; i < runs; i++) {
        double s0, s1, sp, sq;
        long small0, moves0, small1, moves1, smallp, smallq, movesp;
        if (!pitp_run(sc, 0, 0.1, n, K, &s0, &small0, &moves0) || !pitp_run(sc, 1, 0.1, n, K, &s1, &small1, &moves1) ||
            !pitp_run(sc, 0, 0, n, K, &sp, &smallp, &movesp) || !pitp_run(sc, 0, 0, n / 5, K, &sq, &smallq, &movesp) ||
            !(moves1 > 0) || !(smallp > smallq))
            return c;
        move_us[i] = 1e6 * (s1 - s0) / (double)moves1;
        small_us[i] = 1e6 * (sp - sq) / (double)(smallp - smallq);
    }
    c.move_us = median(move_us, runs);
    c.small_us = median(small_us, runs);
    return c;
}

/* Peak memory once an image has been written (OpenEXR and libpng, io/image_encode.h; until
 * 2026-12-06 the first write opened the OpenImageIO module, ~260 libraries and 115 MB). */
static double image_io_peak_mb(const struct scene *sc)
{
    char dir[] = "/tmp/bench-XXXXXX", prefix[64], err[1024];
    if (!mkdtemp(dir)) return NAN;
    snprintf(prefix, sizeof prefix, "%s/img", dir);
    struct image *im = img_create(sc->cam.width, sc->cam.height);
    bool ok = img_write_exr_png(im, prefix, err, sizeof err);
    img_destroy(im);
    if (!ok) fprintf(stderr, "bench: %s\n", err);
    char path[80];
    snprintf(path, sizeof path, "%s.exr", prefix);
    unlink(path);
    snprintf(path, sizeof path, "%s.png", prefix);
    unlink(path);
    rmdir(dir);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ok ? ru.ru_maxrss / 1024.0 : NAN;
}

enum { PT, BDPT, PSSMLT, MMLT, PITP, CTRL, NM };
static const char *method_names[NM] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp", "mmlt --small-step controlled"};

struct figures {
    double closest_rate, shadow_rate; /* Embree's random rays/s */
    double rate[NM][2];               /* samples or mutations/s on 1 and 2 threads */
    struct rays per[NM];              /* on 1 thread */
};

static double method_rate(const struct scene *sc, int m, int threads, int K, double seconds, struct rays *per)
{
    switch (m) {
    case PT:
        return sample_rate(sc, METHOD_PT, threads, K, seconds, per);
    case BDPT:
        return sample_rate(sc, METHOD_BDPT, threads, K, seconds, per);
    case PSSMLT:
        return mutation_rate(sc, MLT_PSSMLT, SMALL_STEP_PSS, threads, K, seconds, per);
    case PITP:
        return mutation_rate(sc, MLT_PITP, SMALL_STEP_PSS, threads, K, seconds, per);
    case CTRL:
        return mutation_rate(sc, MLT_MMLT, SMALL_STEP_CONTROLLED, threads, K, seconds, per);
    default:
        return mutation_rate(sc, MLT_MMLT, SMALL_STEP_PSS, threads, K, seconds, per);
    }
}

/* Medians over `runs` of every figure; with `one_thread` (the table), the 2-thread rates and the
 * shadow-ray rate are left at 0. */
static void measure(const struct scene *sc, int runs, double seconds, int K, bool one_thread, struct figures *f)
{
    enum { NV = 2 + 4 * NM };
    double v[NV][99] = {{0}};
    for (int r = 0; r < runs; r++) {
        v[0][r] = ray_rate(sc, seconds, false);
        if (!one_thread) v[1][r] = ray_rate(sc, seconds, true); /* the table does not show it */
        for (int m = 0; m < NM; m++) {
            struct rays per = {0, 0}; /* stays 0 if a method fails (a scene without light) */
            v[2 + m][r] = method_rate(sc, m, 1, K, seconds, &per);
            v[2 + 2 * NM + m][r] = per.closest;
            v[2 + 3 * NM + m][r] = per.shadow;
        }
        if (one_thread) continue;
        for (int m = 0; m < NM; m++)
            v[2 + NM + m][r] = method_rate(sc, m, 2, K, seconds, NULL);
    }
    f->closest_rate = median(v[0], runs);
    f->shadow_rate = median(v[1], runs);
    for (int m = 0; m < NM; m++) {
        f->rate[m][0] = median(v[2 + m], runs);
        f->rate[m][1] = median(v[2 + NM + m], runs);
        f->per[m] = (struct rays){median(v[2 + 2 * NM + m], runs), median(v[2 + 3 * NM + m], runs)};
    }
}

static void report(const char *path, const struct scene *sc, int runs, double seconds, int K)
{
    struct figures f;
    measure(sc, runs, seconds, K, false, &f);
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    double io_mb = image_io_peak_mb(sc);
    const char *unit[NM] = {"samples", "samples", "mutations", "mutations", "mutations"};
    printf("# %s at 320x180, max length %d, median of %d runs\n", path, K, runs);
    printf("%-44s %12.0f\n", "embree incoherent rays/s (1 thread)", f.closest_rate);
    printf("%-44s %12.0f   any hit, same rays\n", "  as shadow rays", f.shadow_rate);
    for (int m = 0; m < NM; m++) {
        char label[64];
        snprintf(label, sizeof label, "%s %s/s (1 thread)", method_names[m], unit[m]);
        printf("%-44s %12.0f", label, f.rate[m][0]);
        if (m == PSSMLT) printf("   per mutation vs bdpt per sample %.2fx", f.rate[m][0] / f.rate[BDPT][0]);
        if (m == PITP) printf("   time per mutation vs mmlt %.2fx", f.rate[MMLT][0] / f.rate[m][0]);
        if (m == CTRL) printf("   %.2fx mmlt's", f.rate[m][0] / f.rate[MMLT][0]);
        snprintf(label, sizeof label, "%s %s/s (2 threads)", method_names[m], unit[m]);
        printf("\n%-44s %12.0f   speed-up %.2fx\n", label, f.rate[m][1], f.rate[m][1] / f.rate[m][0]);
    }
    /* What the rays alone would take at the random-ray rates: how far the rest could ever go. */
    printf("%-44s %8s %8s   %s\n", "rays per sample or mutation", "closest", "shadow",
           "Embree time at the rates above");
    for (int m = 0; m < NM; m++) {
        double us = 1e6 / f.rate[m][0],
               ray_us = 1e6 * (f.per[m].closest / f.closest_rate + f.per[m].shadow / f.shadow_rate);
        printf("  %-42s %8.2f %8.2f   %.3f of %.3f us (%.0f %%)\n", method_names[m], f.per[m].closest, f.per[m].shadow,
               ray_us, us, 100 * ray_us / us);
    }
    struct technique_cost tc = technique_cost(sc, runs, seconds, K);
    printf("%-44s %12.3f   mmlt's: pitp --pitp-rate 0 --p-large 0 (CPU, 1 thread)\n", "small step (us)", tc.small_us);
    printf("%-44s %12.3f   pitp P = 1 minus P = 0 per perturbation, %.2fx a small step (CPU, 1 thread)\n",
           "technique move (us)", tc.move_us, tc.move_us / tc.small_us);
    printf("%-44s %12.1f\n", "peak resident memory (MB)", ru.ru_maxrss / 1024.0);
    printf("%-44s %12.1f\n", "  after writing EXR + PNG (MB)", io_mb);
}

/* One Markdown row per scene, 1-thread figures only. */
static void table(char **paths, struct scene **sc, int n, int runs, double seconds, int K)
{
    printf("# 320x180, max length %d, 1 thread, median of %d runs of %g s\n", K, runs, seconds);
    printf("| scene | Embree rays/s | PT samples/s | BDPT samples/s | PSSMLT mutations/s | MMLT mutations/s | PITP "
           "mutations/s | "
           "PITP time / MMLT | MMLT controlled mutations/s |\n");
    printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (int i = 0; i < n; i++) {
        struct figures f;
        measure(sc[i], runs, seconds, K, true, &f);
        printf("| %s | %.1f M | %.2f M | %.0f k | %.0f k | %.2f M | %.2f M | %.2fx | %.2f M |\n", paths[i],
               f.closest_rate / 1e6, f.rate[PT][0] / 1e6, f.rate[BDPT][0] / 1e3, f.rate[PSSMLT][0] / 1e3,
               f.rate[MMLT][0] / 1e6, f.rate[PITP][0] / 1e6, f.rate[MMLT][0] / f.rate[PITP][0], f.rate[CTRL][0] / 1e6);
        fflush(stdout);
    }
}

struct scenes {
    char *paths[64];
    int n;
};

static void scene_arg(const char *prog, const char *arg, void *ctx)
{
    struct scenes *s = ctx;
    int max = (int)(sizeof s->paths / sizeof *s->paths);
    if (s->n == max) opts_fail(prog, "at most %d scenes", max);
    s->paths[s->n++] = (char *)arg;
}

int main(int argc, char **argv)
{
    struct scenes ss = {.paths = {"scenes/cornell-box/scene.json"}};
    int runs, K;
    double seconds;
    const struct opt opts[] = {{"--runs", OPT_INT, OPT_DST(runs), .arg = "N", .lo = 1, .hi = 99,
                                .help = "median of N runs of each figure", .def = "3"},
                               {"--seconds", OPT_DOUBLE, OPT_DST(seconds), .arg = "S", .lo = 0.01, .hi = 600,
                                .help = "length of each run", .def = "3"},
                               OPT_MAX_LENGTH(K, .help = "path length cap in segments", .def = "8"),
                               {0}};
    opts_parse(
        &(struct opts_spec){
            .prog = "bench",
            .usage = "usage: bench [SCENE.json ...] [options]\n",
            .about =
                "  Every scene is rendered at 320x180. One scene (default scenes/cornell-box/scene.json): Embree's\n"
                "  ray rate, PT/BDPT samples/s and PSSMLT/MMLT/PITP mutations/s on 1 and 2 threads, rays per sample\n"
                "  or mutation and the time they take at Embree's rate, peak memory.\n"
                "  Several scenes: a Markdown table of the 1-thread figures, one row per scene.\n",
            .opts = opts,
            .positional = scene_arg,
            .ctx = &ss},
        argc, argv);
    char **paths = ss.paths;
    int n = ss.n;
    int nscenes = n ? n : 1;
    struct scene *sc[64];
    char err[1024];
    for (int i = 0; i < nscenes; i++) { /* all loaded first: a bad file fails before any timing */
        sc[i] = scene_load(paths[i], err, sizeof err);
        if (!sc[i]) {
            fprintf(stderr, "%s\n", err);
            return 2;
        }
        camera_resize(&sc[i]->cam, 320, 180);
    }
    if (nscenes == 1)
        report(paths[0], sc[0], runs, seconds, K);
    else
        table(paths, sc, nscenes, runs, seconds, K);
    for (int i = 0; i < nscenes; i++)
        scene_free(sc[i]);
    return 0;
}
