/* End to end through bin/render: outputs appear, bad input gives one error line, exit status 2 and
 * no output files, and a seed reproduces the image bit for bit (EXR pixels, PNG file, CSV rows). */
#include <criterion/criterion.h>

#include "io/image.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

static char dir[64];

static void make_dir(void) { tmpdir_make(dir, sizeof dir, "cli-test"); }
/* Every test of the suite works in its own directory, removed afterwards. */
static void remove_dir(void) { tmpdir_remove(dir); }
TestSuite(cli, .fini = remove_dir);

static void read_text(const char *path, char *buf, size_t n)
{
    FILE *f = fopen(path, "r");
    size_t got = f ? fread(buf, 1, n - 1, f) : 0;
    buf[got] = 0;
    if (f) fclose(f);
}

/* Runs EXE ARGS --quiet; its stderr goes to err (and its stdout to out, if given), its exit status
 * is returned. */
static int run_exe_out(const char *exe, const char *args, char *err, size_t n, char *out, size_t on)
{
    char cmd[2048], errfile[128], outfile[128];
    snprintf(errfile, sizeof errfile, "%s/stderr", dir);
    snprintf(outfile, sizeof outfile, "%s/stdout", dir);
    snprintf(cmd, sizeof cmd, "%s %s --quiet > %s 2> %s", exe, args, outfile, errfile);
    int st = system(cmd);
    cr_assert(WIFEXITED(st));
    read_text(errfile, err, n);
    if (out) read_text(outfile, out, on);
    return WEXITSTATUS(st);
}

static int run_exe(const char *exe, const char *args, char *err, size_t n)
{
    return run_exe_out(exe, args, err, n, NULL, 0);
}
static int run(const char *args, char *err, size_t n) { return run_exe(BIN_DIR "/render", args, err, n); }

static bool exists(const char *name)
{
    char p[256];
    if (snprintf(p, sizeof p, "%s/%s", dir, name) >= (int)sizeof p) return false;
    return access(p, F_OK) == 0;
}

static int lines(const char *s)
{
    int n = 0;
    for (; *s; s++)
        n += *s == '\n';
    return n;
}

Test(cli, bad_inputs_exit_2_with_one_line_and_no_output)
{
    make_dir();
    const char *cases[][2] = {
        {"tests/data/bad/undefined_bsdf.json", "undefined_bsdf.json"},
        {"tests/data/bad/scale_string.json", "transform.scale"},
        {"tests/data/bad/rotation_huge.json", "primitives[3].transform.rotation[1]"},
        {"scenes/does-not-exist.json", "does-not-exist"},
        {"scenes/cornell-box/scene.json --spp 0", "--spp"},
        {"scenes/cornell-box/scene.json --method foo", "--method"},
        {"scenes/cornell-box/scene.json --resolution 10", "--resolution"},
        {"scenes/cornell-box/scene.json --bogus", "--bogus"},
        {"scenes/cornell-box/scene.json --method bdpt --technique-images 9", "--technique-images 9"},
    };
    char err[4096], args[1024];
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        snprintf(args, sizeof args, "%s --out %s/x", cases[i][0], dir);
        int rc = run(args, err, sizeof err);
        cr_assert_eq(rc, 2, "%s: exit %d (%s)", cases[i][0], rc, err);
        cr_assert_eq(lines(err), 1, "%s: expected one error line, got: %s", cases[i][0], err);
        cr_assert(strstr(err, cases[i][1]), "%s: message does not name '%s': %s", cases[i][0], cases[i][1], err);
        cr_assert(!exists("x.exr") && !exists("x.png") && !exists("x.csv"), "%s: output written", cases[i][0]);
    }
}

static void slurp(const char *path, char **buf, long *n)
{
    FILE *f = fopen(path, "rb");
    cr_assert(f, "missing %s", path);
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    rewind(f);
    *buf = malloc((size_t)*n + 1);
    cr_assert_eq(fread(*buf, 1, (size_t)*n, f), (size_t)*n);
    (*buf)[*n] = 0;
    fclose(f);
}

Test(cli, outputs_and_bitwise_reproducibility)
{
    make_dir();
    char err[4096], args[1024], a[256], b[256];
    for (int m = 0; m < 2; m++) {
        const char *method = m ? "mmlt" : "bdpt";
        for (int r = 0; r < 2; r++) {
            snprintf(args, sizeof args,
                     "scenes/cornell-box/scene.json --method %s --spp 2 --resolution 48x32 --threads 2 "
                     "--seed 9 --seed-paths 2000 --out %s/%s%d",
                     method, dir, method, r);
            cr_assert_eq(run(args, err, sizeof err), 0, "%s", err);
        }
        const char *ext[] = {"exr", "png", "csv"};
        for (int e = 0; e < (m ? 3 : 2); e++) {
            snprintf(a, sizeof a, "%s/%s0.%s", dir, method, ext[e]);
            snprintf(b, sizeof b, "%s/%s1.%s", dir, method, ext[e]);
            char *x, *y;
            long nx, ny;
            slurp(a, &x, &nx);
            slurp(b, &y, &ny);
            if (e == 0) { /* EXR: the pixels (OpenImageIO stamps the file with the time) */
                char msg[256];
                struct image *ia = img_read(a, msg, sizeof msg), *ib = img_read(b, msg, sizeof msg);
                cr_assert(ia && ib, "%s", msg);
                cr_assert(memcmp(ia->px, ib->px, sizeof(double) * 3 * 48 * 32) == 0, "%s and %s differ", a, b);
                img_destroy(ia);
                img_destroy(ib);
            } else if (e == 2) { /* CSV: statistics rows only; the metadata has timings */
                char *rx = strstr(x, "\nmethod,"), *ry = strstr(y, "\nmethod,");
                cr_assert(rx && ry);
                cr_assert_str_eq(rx, ry);
            } else {
                cr_assert(nx == ny && memcmp(x, y, (size_t)nx) == 0, "%s and %s differ", a, b);
            }
            free(x);
            free(y);
        }
    }
}

/* Without the OpenImageIO module beside it, bin/render still renders and writes an untextured scene
 * (EXR and PNG need no module, core/io/image_encode.h), and a textured scene is refused at load
 * with one line naming the module, before anything is rendered. */
Test(cli, missing_image_module_refuses_textures_only)
{
    make_dir();
    char exe[128], cmd[256], args[256], err[4096];
    snprintf(exe, sizeof exe, "%s/render", dir);
    snprintf(cmd, sizeof cmd, "cp " BIN_DIR "/render %s", exe);
    cr_assert_eq(system(cmd), 0);
    snprintf(args, sizeof args, "scenes/cornell-box/scene.json --spp 1 --resolution 16x12 --out %s/x", dir);
    int rc = run_exe(exe, args, err, sizeof err);
    cr_assert_eq(rc, 0, "exit %d (%s)", rc, err);
    cr_assert(exists("x.exr") && exists("x.png"));
    snprintf(args, sizeof args, "scenes/living-room/scene.json --spp 4096 --out %s/y", dir);
    rc = run_exe(exe, args, err, sizeof err);
    cr_assert(rc != 0, "a textured scene rendered without the module");
    cr_assert_eq(lines(err), 1, "expected one error line, got: %s", err);
    cr_assert(strstr(err, "oiio.so"), "message does not name the module: %s", err);
    cr_assert(!exists("y.exr") && !exists("y.png"));
}

/* A number from a "# key value" metadata line of a CSV held in memory. */
static double csv_meta(const char *csv, const char *key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "# %s ", key);
    const char *p = strstr(csv, pat);
    cr_assert(p, "no '%s' line in the CSV", key);
    return atof(p + strlen(pat));
}

/* --time stops the chains at the budget, long before the --spp count, and PT/BDPT before the pass
 * that would overrun it; SIGINT stops a run and it still writes its outputs, marked partial: exit
 * status 130, "PARTIAL" in the summary line and, for the MCMC methods, in the CSV. */
Test(cli, time_budget_and_interrupt_write_outputs)
{
    make_dir();
    char err[4096], args[1024], path[256], *csv;
    long n;
    snprintf(args, sizeof args,
             "scenes/cornell-box/scene.json --method mmlt --spp 100000 --time 0.3 --resolution 64x48 "
             "--seed-paths 2000 --out %s/t",
             dir);
    cr_assert_eq(run(args, err, sizeof err), 0, "%s", err);
    snprintf(path, sizeof path, "%s/t.csv", dir);
    slurp(path, &csv, &n);
    double secs = csv_meta(csv, "seconds"), muts = csv_meta(csv, "mutations");
    cr_assert(secs >= 0.3 && secs < 1.5, "--time 0.3 ran the chains for %g s", secs);
    cr_assert(muts > 0 && muts < 100000.0 * 64 * 48, "%g mutations", muts);
    free(csv);
    for (int m = 0; m < 2; m++) {
        snprintf(args, sizeof args,
                 "scenes/cornell-box/scene.json --method %s --spp 100000 --time 0.3 --resolution 32x24 "
                 "--out %s/p",
                 m ? "bdpt" : "pt", dir);
        char out[1024];
        cr_assert_eq(run_exe_out(BIN_DIR "/render", args, err, sizeof err, out, sizeof out), 0, "%s", err);
        long samples = 0;
        int spp = 0;
        double s = 0;
        const char *colon = strchr(out, ':');
        cr_assert(colon && sscanf(colon + 1, " %ld samples (%d spp) in %lf s", &samples, &spp, &s) == 3, "summary: %s",
                  out);
        /* 32 x 24: a pass short enough that a second one fits in 0.3 s under the sanitizers and load */
        cr_assert(spp >= 2 && spp < 100000 && samples == (long)spp * 32 * 24, "%s", out);
        /* slack for a loaded machine, where the last pass can take longer than the mean */
        cr_assert(s >= 0.1 && s < 0.3 * (1 + 2.0 / spp) + 0.5, "--time 0.3: %s", out);
    }

    const char *methods[] = {"pt", "pssmlt"};
    for (int m = 0; m < 2; m++) {
        char cmd[2048];
        snprintf(cmd, sizeof cmd,
                 "(" BIN_DIR "/render scenes/cornell-box/scene.json --method %s --spp 100000 --resolution 64x48 "
                 "--seed-paths 2000 --quiet --out %s/i%d > %s/out%d 2>&1 & pid=$!; sleep 1; kill -INT $pid; wait $pid; "
                 "echo $? > %s/rc%d)",
                 methods[m], dir, m, dir, m, dir, m);
        cr_assert_eq(system(cmd), 0);
        char *rc, *out;
        snprintf(path, sizeof path, "%s/rc%d", dir, m);
        slurp(path, &rc, &n);
        snprintf(path, sizeof path, "%s/out%d", dir, m);
        slurp(path, &out, &n);
        cr_assert_eq(atoi(rc), 130, "%s: exit status %s after SIGINT (%s)", methods[m], rc, out);
        cr_assert(strstr(out, "PARTIAL"), "%s: summary not marked partial: %s", methods[m], out);
        snprintf(path, sizeof path, "i%d.exr", m);
        cr_assert(exists(path), "%s: no image after SIGINT", methods[m]);
        if (m == 1) {
            snprintf(path, sizeof path, "%s/i1.csv", dir);
            slurp(path, &csv, &n);
            cr_assert(strstr(csv, "# PARTIAL"), "CSV not marked partial");
            free(csv);
        }
        free(rc);
        free(out);
    }
}

/* An option the chosen method does not read is named in a warning, not silently dropped. */
Test(cli, options_of_other_methods_warn)
{
    make_dir();
    const char *cases[][3] = {
        {"pt", "--seed-paths 100", "--seed-paths has no effect with --method pt"},
        {"bdpt", "--rap", "--rap has no effect with --method bdpt"},
        {"pssmlt", "--large-step mctls", "--large-step has no effect with --method pssmlt"},
        {"mmlt", "--max-heuristic", "--max-heuristic has no effect with --method mmlt"},
        {"pt", "--technique-images 2", "--technique-images has no effect with --method pt"},
        {"pssmlt", "--seed-bdpt", "--seed-bdpt has no effect with --method pssmlt"},
    };
    char err[4096], args[1024];
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        snprintf(args, sizeof args,
                 "scenes/cornell-box/scene.json --method %s %s --spp 1 --resolution 16x12 "
                 "--seed-paths 200 --out %s/w",
                 cases[i][0], cases[i][1], dir);
        cr_assert_eq(run(args, err, sizeof err), 0, "%s", err);
        cr_assert(strstr(err, cases[i][2]), "%s %s: no warning in: %s", cases[i][0], cases[i][1], err);
    }
}

/* A scene without an emitter: PT and BDPT render it (black) after one warning line naming the file;
 * the MCMC methods, which have no target to sample, stop with one line saying why and exit 2. */
Test(cli, scene_without_emitter)
{
    make_dir();
    const char *scene = "tests/data/no-emitter.json";
    char err[4096], args[1024];
    const char *mc[] = {"pt", "bdpt"}, *mcmc[] = {"pssmlt", "mmlt"};
    for (int i = 0; i < 2; i++) {
        snprintf(args, sizeof args, "%s --method %s --out %s/x", scene, mc[i], dir);
        int rc = run(args, err, sizeof err);
        cr_assert_eq(rc, 0, "%s: exit %d (%s)", mc[i], rc, err);
        cr_assert_eq(lines(err), 1, "%s: expected one warning line, got: %s", mc[i], err);
        cr_assert(strstr(err, scene) && strstr(err, "no emitter"), "%s: warning does not say it: %s", mc[i], err);
        cr_assert(exists("x.exr"), "%s: no image written", mc[i]);
    }
    for (int i = 0; i < 2; i++) {
        snprintf(args, sizeof args, "%s --method %s --out %s/y", scene, mcmc[i], dir);
        int rc = run(args, err, sizeof err);
        cr_assert_eq(rc, 2, "%s: exit %d (%s)", mcmc[i], rc, err);
        cr_assert_eq(lines(err), 1, "%s: expected one error line, got: %s", mcmc[i], err);
        cr_assert(strstr(err, "no emitter") && !strstr(err, "seed pass"), "%s: wrong message: %s", mcmc[i], err);
        cr_assert(!exists("y.exr") && !exists("y.csv"), "%s: output written", mcmc[i]);
    }
}

/* Options of bin/render that rule each other out (mlt_options.c's checks) are bad input: one line
 * naming them, exit status 2, no output, before the seed pass. */
Test(cli, conflicting_mcmc_options_are_refused)
{
    char err[4096];
    make_dir();
    const char *bad[] = {"--method mlt --mlt-lens 0.9 --mlt-caustic 0.2",
                         "--method mmlt --large-step mctls --power-heuristic"};
    const char *want[] = {"render: --mlt-lens, --mlt-caustic, --mlt-lens-subpath and --mlt-multichain: their sum",
                          "render: --power-heuristic: mmlt with"};
    for (int i = 0; i < 2; i++) {
        char args[512];
        snprintf(args, sizeof args, "scenes/cornell-box/scene.json %s --spp 1 --out %s/c", bad[i], dir);
        cr_assert_eq(run(args, err, sizeof err), 2, "%s: %s", bad[i], err);
        cr_assert(strstr(err, want[i]) && lines(err) == 1, "%s: %s", bad[i], err);
        cr_assert(!exists("c.exr"), "%s: output written", bad[i]);
    }
}

/* --scale full: a figure with full-scale defaults takes them (fig4_6's help lists them), one without
 * refuses it in one line with exit status 2 before it renders anything; SCALE=full in the
 * environment is a preference, which such a figure meets at quick. */
Test(cli, scale_full_is_taken_or_refused)
{
    char err[4096], out[8192], cmd[512], errfile[128];
    make_dir();
    cr_assert_eq(run_exe_out(BIN_DIR "/fig4_6", "--help", err, sizeof err, out, sizeof out), 0);
    cr_assert(strstr(out, "(quick 4, paper 600, full 60)") && strstr(out, "(quick 256, paper 16384, full 4096)"), "%s",
              out);
    snprintf(errfile, sizeof errfile, "%s/stderr", dir);
    snprintf(cmd, sizeof cmd, BIN_DIR "/fig4_1 --scale full --out %s/fig4.1 2> %s", dir, errfile);
    int st = system(cmd);
    read_text(errfile, err, sizeof err);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 2, "%s", err);
    cr_assert(!exists("fig4.1"), "fig4_1 --scale full wrote its output folder");
    cr_assert(strstr(err, "fig4_1: --scale full: this figure has the scales quick and paper only") && lines(err) == 1,
              "%s", err);
    /* SCALE=full from the environment (`make figures SCALE=full`) runs it at quick and says so: the
     * missing scene then stops it before it renders */
    snprintf(cmd, sizeof cmd, "SCALE=full " BIN_DIR "/fig4_1 --scene %s/none.json --out %s/fig4.1 2> %s", dir, dir,
             errfile);
    st = system(cmd);
    read_text(errfile, err, sizeof err);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 2, "%s", err);
    cr_assert(strstr(err, "fig4_1: SCALE=full: this figure has no full scale; running it at quick") && lines(err) == 2,
              "%s", err);
}
