/* Paths as long as Tungsten's default max_bounces (64): every method renders a scene that carries it
 * (end to end through bin/render, so the sanitizer build runs it too), a longer limit is clamped with
 * one warning, and a closed white furnace with albedo 0.9 converges to its exact answer, which a cap
 * at 32 segments would miss by 3.3 %. */
#include <criterion/criterion.h>

#include "bsdf/bsdf_json.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "scene/scene.h"
#include "support/agree.h"
#include "support/scenes.h"
#include "support/tmpdir.h"
#include <gsl/gsl_cdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

#define FURNACE64 "tests/data/furnace-64.json"

static char dir[64];
static void make_dir(void) { tmpdir_make(dir, sizeof dir, "long-paths"); }
static void remove_dir(void) { tmpdir_remove(dir); }

/* The largest path length of a statistics row of the CSV (0 when there is none). */
static int longest_row(const char *csv)
{
    FILE *f = fopen(csv, "r");
    cr_assert(f, "%s missing", csv);
    char line[512];
    int longest = 0;
    while (fgets(line, sizeof line, f)) {
        char method[16], kind[16];
        int len;
        if (sscanf(line, "%15[^,],%15[^,],%d,", method, kind, &len) == 3 && len > longest) longest = len;
    }
    fclose(f);
    return longest;
}

/* Every method on the furnace with max_bounces 64 at 8x8 pixels and 1 sample (mutation) per pixel.
 * MMLT and PITP with equal mutations per length, so that every chain 1..64 takes steps: their
 * statistics must have rows beyond length 32, the old limit. */
Test(long_paths, every_method_renders_max_bounces_64, .init = make_dir, .fini = remove_dir)
{
    const char *methods[] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp"};
    for (int m = 0; m < 5; m++) {
        bool mcmc = m >= 2, per_length = m >= 3;
        char cmd[1024];
        snprintf(cmd, sizeof cmd,
                 BIN_DIR "/render " FURNACE64
                         " --method %s --spp %d --threads 2 --resolution 8x8 --quiet --out %s/%s%s%s"
                         " > %s/log 2>&1",
                 methods[m], per_length ? 16 : 1, dir, methods[m], mcmc ? " --seed-paths 500" : "",
                 per_length ? " --uniform-lengths" : "", dir);
        int st = system(cmd);
        cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 0, "%s: exit status %d", cmd, WEXITSTATUS(st));
        if (per_length) {
            char csv[128];
            snprintf(csv, sizeof csv, "%s/%s.csv", dir, methods[m]);
            int longest = longest_row(csv);
            cr_assert(longest > 32 && longest <= 64, "%s: statistics rows reach length %d", methods[m], longest);
        }
    }
}

/* max_bounces above the renderer's limit loads with one warning, capped at MAX_PATH_LENGTH. */
Test(long_paths, longer_limit_is_clamped, .init = make_dir, .fini = remove_dir)
{
    char scene[128], cmd[512], log[128], line[512];
    snprintf(scene, sizeof scene, "%s/s.json", dir);
    snprintf(cmd, sizeof cmd, "sed 's/\"max_bounces\": 64/\"max_bounces\": 1000/' " FURNACE64 " > %s", scene);
    cr_assert_eq(system(cmd), 0);
    char err[512] = "";
    struct scene *s = scene_load_model(scene, err, sizeof err);
    cr_assert(s, "%s", err);
    cr_assert_eq(s->max_length, MAX_PATH_LENGTH);
    scene_model_free(s);
    snprintf(log, sizeof log, "%s/log", dir);
    snprintf(cmd, sizeof cmd, BIN_DIR "/render %s --method pt --spp 1 --resolution 4x4 --quiet --out %s/o 2> %s", scene,
             dir, log);
    cr_assert_eq(system(cmd), 0);
    FILE *f = fopen(log, "r");
    cr_assert(f);
    int n = 0;
    while (fgets(line, sizeof line, f)) {
        n++;
        cr_assert(
            strstr(line, "integrator.max_bounces: warning: 1000 is above the renderer's limit; paths are capped at 64"),
            "%s", line);
    }
    fclose(f);
    cr_assert_eq(n, 1, "%d lines on stderr", n);
}

struct furnace_ctx {
    const struct scene *sc;
    int method; /* 0 pt, 1 bdpt, 2 mmlt */
};

static struct image *render_furnace(void *p, uint64_t seed)
{
    const struct furnace_ctx *c = p;
    if (c->method < 2) {
        struct render_opts o = {.method = c->method ? METHOD_BDPT : METHOD_PT,
                                .spp = c->method ? 4 : 64,
                                .seed = seed,
                                .threads = 2,
                                .max_length = c->sc->max_length,
                                .min_length = 1};
        struct render_stats st;
        return render_mc(c->sc, &o, &st);
    }
    struct mlt_opts o = {.method = MLT_MMLT,
                         .p_large = 0.1,
                         .mutations = 512L * 16 * 16,
                         .seed_paths = 5000,
                         .seed = seed,
                         .threads = 2,
                         .max_length = c->sc->max_length,
                         .min_length = 1};
    pss_opts_default(&o.pss, c->sc->cam.width, c->sc->cam.height);
    struct mlt_result r;
    char err[256];
    cr_assert(mlt_render(c->sc, &o, &r, err, sizeof err), "%s", err);
    return r.img;
}

/* Le (1 - a^64) / (1 - a) with a = 0.9, Le = 0.5, at 16x16 pixels: PT 64 spp, BDPT 4 spp, MMLT 512
 * mutations per pixel (5000-path seed pass), 4 runs each. The run-to-run mean must contain the exact
 * value (t-test, 3 degrees of freedom, alpha 0.01 Sidak over the 3 methods) and lie within 1 %; the
 * 32-segment cap's value is 3.3 % lower. */
Test(stat_long_paths, furnace_64_bounces_exact_answer)
{
    struct scene *sc = test_scene(FURNACE64);
    cr_assert_eq(sc->max_length, 64);
    const double a = 0.9, exact = 0.5 * (1 - pow(a, 64)) / (1 - a);
    const char *names[] = {"pt", "bdpt", "mmlt"};
    double alpha = 1 - pow(1 - 0.01, 1.0 / 3), tmax = gsl_cdf_tdist_Qinv(alpha / 2, 3);
    for (int m = 0; m < 3; m++) {
        struct furnace_ctx c = {sc, m};
        static struct stack s;
        stack_runs(&s, render_furnace, &c, 4, 100 + 10 * (uint64_t)m, 16);
        double t = fabs(s.mean - exact) / s.mean_se;
        cr_log_info("furnace-64 %s: %.5f +- %.5f vs exact %.5f (t = %.2f, limit %.2f)", names[m], s.mean, s.mean_se,
                    exact, t, tmax);
        cr_assert(t < tmax && fabs(s.mean / exact - 1) < 0.01, "%s: %.5f +- %.5f vs exact %.5f (t = %.2f, limit %.2f)",
                  names[m], s.mean, s.mean_se, exact, t, tmax);
    }
    scene_free(sc);
}
