/* Non-finite contributions (issue 30): no NaN or infinity reaches an image, and every one dropped is
 * counted by path length in bin/render's summary line, its statistics CSV (MCMC methods) and one
 * warning line on stderr. The degenerate scene (tests/data/degenerate.json) carries what could
 * produce them: zero-area triangles and a zero vertex normal (the loader drops and flattens them,
 * with warnings), roughness 0 (clamped to the microfacet minimum) and ior 1. The renderer guards
 * all of these, so the same runs are repeated with PSS_INJECT_NONFINITE (path/splat.h), which makes
 * every n-th contribution NaN or infinite where it is computed; the splat guards themselves are
 * tested by calling them with such values. */
#include <criterion/criterion.h>

#include "io/image.h"
#include "mcmc/splat_ev.h"
#include "path/splat.h"
#include "support/tmpdir.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

#define DEGENERATE "tests/data/degenerate.json"

static char dir[64];
static void make_dir(void) { tmpdir_make(dir, sizeof dir, "nonfinite"); }
static void remove_dir(void) { tmpdir_remove(dir); }
TestSuite(nonfinite, .init = make_dir, .fini = remove_dir);

static const char *methods[] = {"pt", "bdpt", "pssmlt", "mmlt", "pitp"};

/* What one run reported: the summary's total and breakdown, the warning lines. */
struct report {
    long total, by_len[MAX_PATH_LENGTH + 1];
    int warnings;
    char note[2048]; /* the summary's text after "N non-finite dropped" */
};

/* " (length 3: 10, summed lengths: 2)" into by_len; "" leaves it zero. */
static void parse_note(const char *s, long *by_len, const char *what)
{
    memset(by_len, 0, (MAX_PATH_LENGTH + 1) * sizeof *by_len);
    if (!*s) return;
    cr_assert(!strncmp(s, " (", 2), "%s: breakdown '%s'", what, s);
    s += 2;
    while (*s && *s != ')') {
        int k = 0, used = 0;
        long n = 0;
        if (sscanf(s, "length %d: %ld%n", &k, &n, &used) == 2)
            cr_assert(k >= 1 && k <= MAX_PATH_LENGTH, "%s: '%s'", what, s);
        else
            cr_assert(sscanf(s, "summed lengths: %ld%n", &n, &used) == 1 && (k = 0) == 0, "%s: breakdown at '%s'", what,
                      s);
        cr_assert(n > 0 && by_len[k] == 0, "%s: length %d listed as %ld (zero counts are left out, each once)", what, k,
                  n);
        by_len[k] = n;
        s += used;
        if (!strncmp(s, ", ", 2)) s += 2;
    }
    cr_assert(!strcmp(s, ")"), "%s: breakdown ends in '%s'", what, s);
}

static void read_report(const char *method, struct report *r)
{
    char p[128], line[4096];
    memset(r, 0, sizeof *r);
    snprintf(p, sizeof p, "%s/stdout", dir);
    FILE *f = fopen(p, "r");
    cr_assert(f);
    bool found = false;
    while (fgets(line, sizeof line, f)) {
        char *d = strstr(line, " non-finite dropped");
        if (!d || strncmp(line, method, strlen(method))) continue;
        char *num = d;
        while (num > line && num[-1] != ' ')
            num--;
        r->total = strtol(num, NULL, 10);
        snprintf(r->note, sizeof r->note, "%s", d + strlen(" non-finite dropped"));
        r->note[strcspn(r->note, "\n")] = 0;
        found = true;
    }
    fclose(f);
    cr_assert(found, "%s: no summary line", method);
    parse_note(r->note, r->by_len, method);
    snprintf(p, sizeof p, "%s/stderr", dir);
    f = fopen(p, "r");
    cr_assert(f);
    while (fgets(line, sizeof line, f)) {
        char *w = strstr(line, "render: warning: ");
        if (!w || !strstr(line, "non-finite samples dropped")) continue;
        r->warnings++;
        long n = -1;
        cr_assert(sscanf(w, "render: warning: %ld non-finite samples dropped", &n) == 1 && n == r->total,
                  "%s: warning '%s' against a total of %ld", method, line, r->total);
        char *note = strstr(w, "dropped") + strlen("dropped"), *end = strstr(note, "; the scene has degenerate");
        cr_assert(end && (size_t)(end - note) == strlen(r->note) && !strncmp(note, r->note, strlen(r->note)),
                  "%s: the warning's breakdown differs from the summary's: %s", method, line);
    }
    fclose(f);
}

/* `# nonfinite N` and `# nonfinite_by_length a,b,...` (lengths 0..max_length) equal the summary's. */
static void check_csv(const char *method, const struct report *r)
{
    char p[128], line[4096];
    snprintf(p, sizeof p, "%s/%s.csv", dir, method);
    FILE *f = fopen(p, "r");
    cr_assert(f, "%s missing", p);
    long total = -1, sum = 0;
    int lengths = -1;
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "# nonfinite %ld", &total) == 1) continue;
        if (strncmp(line, "# nonfinite_by_length ", 22)) continue;
        lengths = 0;
        for (char *s = line + 22; *s && *s != '\n'; lengths++) {
            char *end;
            long n = strtol(s, &end, 10);
            cr_assert(end > s && lengths <= MAX_PATH_LENGTH, "%s: '%s'", p, line);
            cr_assert_eq(n, r->by_len[lengths], "%s: length %d: %ld in the CSV, %ld in the summary", p, lengths, n,
                         r->by_len[lengths]);
            sum += n;
            s = *end == ',' ? end + 1 : end;
        }
    }
    fclose(f);
    cr_assert_eq(total, r->total, "%s: # nonfinite %ld, summary %ld", p, total, r->total);
    cr_assert_eq(lengths, 9, "%s: %d lengths listed, max_length 8 wants 0..8", p, lengths);
    cr_assert_eq(sum, total, "%s: lengths sum to %ld of %ld", p, sum, total);
}

static void assert_finite_image(const char *method)
{
    char p[128], err[512];
    snprintf(p, sizeof p, "%s/%s.exr", dir, method);
    struct image *im = img_read(p, err, sizeof err);
    cr_assert(im, "%s", err);
    long bad = 0;
    for (size_t i = 0; i < 3 * (size_t)im->w * im->h; i++)
        bad += !isfinite(im->px[i]);
    img_destroy(im);
    cr_assert_eq(bad, 0, "%s: %ld non-finite pixel channels", method, bad);
}

/* Every method on the degenerate scene: finite image, counts consistent among the summary, its
 * breakdown, the CSV and the warning, which appears once iff anything was dropped. inject: "" or
 * "PSS_INJECT_NONFINITE=n ". Returns the totals per method. */
static void run_all(const char *inject, long *totals)
{
    for (int m = 0; m < 5; m++) {
        bool mcmc = m >= 2;
        char cmd[1024];
        snprintf(cmd, sizeof cmd,
                 "%s" BIN_DIR "/render " DEGENERATE " --method %s --spp 8 --threads 2 --seed 3 --quiet --out %s/%s%s"
                 " > %s/stdout 2> %s/stderr",
                 inject, methods[m], dir, methods[m], mcmc ? " --seed-paths 2000" : "", dir, dir);
        int st = system(cmd);
        cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 0, "%s: exit status %d", cmd, WEXITSTATUS(st));
        assert_finite_image(methods[m]);
        struct report r;
        read_report(methods[m], &r);
        long sum = 0;
        for (int k = 0; k <= MAX_PATH_LENGTH; k++)
            sum += r.by_len[k];
        cr_assert_eq(sum, r.total, "%s: the breakdown sums to %ld of %ld", methods[m], sum, r.total);
        cr_assert_eq(r.warnings, r.total > 0, "%s: %d warning lines for %ld dropped", methods[m], r.warnings, r.total);
        if (mcmc) check_csv(methods[m], &r);
        totals[m] = r.total;
    }
}

/* Measured: 0 for every method at this budget (and at 2048 samples or mutations per pixel). */
Test(nonfinite, degenerate_scene_renders_finite_with_every_method)
{
    long totals[5];
    run_all("", totals);
}

/* Every 97th contribution NaN or +Inf in one channel: each method must drop and count some, at
 * lengths of the scene (1..8, or 0 for sums), and still write a finite image. */
Test(nonfinite, injected_values_are_counted_per_length_and_never_splatted)
{
    long totals[5];
    run_all("PSS_INJECT_NONFINITE=97 ", totals);
    for (int m = 0; m < 5; m++)
        cr_assert(totals[m] > 0, "%s: nothing injected was counted", methods[m]);
}

/* The guards at the image: splat_finite, and the MCMC's weighted splats, where a finite colour
 * times the weight of a tiny target can overflow (and a zero channel then gives 0 * inf = NaN). */
Test(nonfinite, splat_sites_refuse_nan_and_inf)
{
    struct image *im = img_create(4, 4);
    long dropped = 0;
    splat_finite(im, 1.5, 1.5, v3(NAN, 1, 1), &dropped);
    splat_finite(im, 1.5, 1.5, v3(1, INFINITY, 1), &dropped);
    splat_finite(im, 1.5, 1.5, v3(1, 1, -INFINITY), &dropped);
    cr_assert_eq(dropped, 3);
    splat_finite(im, 1.5, 1.5, v3(1, 2, 3), &dropped);
    cr_assert_eq(dropped, 3);
    struct splat_list l = {0};
    splat_push(&l, 2.5, 2.5, v3(1e300, 0, 1));
    splat_list_weighted(im, &l, 1e300, &dropped);
    cr_assert_eq(dropped, 4);
    struct chain c = {.f = 1e-320, .scale = 1, .pending = 1, .dropped = &dropped};
    c.cur = l;
    pay_current(im, &c);
    cr_assert_eq(dropped, 5);
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            rgb v = img_get(im, x, y);
            bool lit = x == 1 && y == 1;
            cr_assert(vfinite(v) && (lit ? v.x == 1 && v.y == 2 && v.z == 3 : vzero(v)), "pixel %d,%d", x, y);
        }
    img_destroy(im);
    struct nonfinite a = {{0}}, b = {{0}};
    a.len[0] = 2;
    a.len[MAX_PATH_LENGTH] = 3;
    b.len[3] = 5;
    nonfinite_add(&a, &b);
    cr_assert_eq(nonfinite_total(&a), 10);
}
