/* experiments/ch6/ch6_stats: mean and standard error, per-block relMSE and its spread, log-log slope. */
#include <criterion/criterion.h>
#include <math.h>
#include <sys/wait.h>

#include "ch6/ch6_stats.h"

Test(ch6_stats, mean_and_standard_error)
{
    const double x[4] = {1, 2, 3, 6};
    double m, se;
    ch6_mean_se(x, 4, &m, &se);
    cr_assert_float_eq(m, 3, 1e-12);
    cr_assert_float_eq(se, sqrt(14.0 / 3 / 4), 1e-12); /* sample variance 14/3 */
    ch6_mean_se(x, 1, &m, &se);
    cr_assert(isnan(se));
}

/* An error confined to one of four blocks: that block's relMSE, zero elsewhere, and a spread of
 * 2 (sample standard deviation over mean of {v, 0, 0, 0}); the same error spread evenly over every pixel gives spread 0. */
Test(ch6_stats, block_relmse_finds_a_concentrated_error)
{
    struct image *ref = img_create(32, 32), *a = img_create(32, 32), *b = img_create(32, 32);
    for (int y = 0; y < 32; y++)
        for (int x = 0; x < 32; x++) {
            img_add(ref, x, y, (rgb){1, 1, 1});
            img_add(a, x, y, (rgb){x >= 16 && y < 16 ? 2 : 1, x >= 16 && y < 16 ? 2 : 1, x >= 16 && y < 16 ? 2 : 1});
            img_add(b, x, y, (rgb){1.5, 1.5, 1.5});
        }
    double v[8];
    int n = ch6_block_relmse(a, ref, 16, 0.01, v, 8);
    cr_assert_eq(n, 4);
    cr_assert_float_eq(v[0], 0, 1e-12);
    cr_assert_float_eq(v[1], 1 / 1.01, 1e-12);
    cr_assert_float_eq(ch6_spread(v, n), 2, 1e-9);
    n = ch6_block_relmse(b, ref, 16, 0.01, v, 8);
    cr_assert_float_eq(ch6_spread(v, n), 0, 1e-12);
    cr_assert_float_eq(v[0], img_relmse(b, ref, 0.01), 1e-12);
    /* partial blocks are dropped: 32 / 10 = 3 per axis */
    cr_assert_eq(ch6_block_relmse(a, ref, 10, 0.01, v, 8), 9);
    img_destroy(ref);
    img_destroy(a);
    img_destroy(b);
}

Test(ch6_stats, loglog_slope_of_a_power_law)
{
    const double x[5] = {1, 2, 4, 8, 16};
    double y[5];
    for (int i = 0; i < 5; i++) y[i] = 0.3 * pow(x[i], -1.0);
    cr_assert_float_eq(ch6_loglog_slope(x, y, 5), -1, 1e-12);
    y[2] = 0; /* dropped, not logged */
    cr_assert_float_eq(ch6_loglog_slope(x, y, 5), -1, 1e-12);
    cr_assert(isnan(ch6_loglog_slope(x, y, 1)));
}

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char *slurp_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    cr_assert(f, "cannot open %s", path);
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = 0;
    fclose(f);
    return buf;
}

/* bin/ch6_equal end to end on a tiny Cornell box: a method bin/render does not accept is probed,
 * skipped and named; the others get one row per seed and budget, and the table. Bad input: exit 2. */
Test(ch6_tool, skips_a_method_the_renderer_lacks_and_writes_its_tables, .timeout = 120)
{
    char dir[] = "/tmp/ch6-tool-XXXXXX";
    cr_assert(mkdtemp(dir));
    char cmd[1024];
    snprintf(cmd, sizeof cmd,
             BIN_DIR "/ch6_equal --scene scenes/cornell-box/scene.json --out %s/o --methods 'pssmlt,nosuch,big=--method mmlt --p-large 1' "
                     "--seeds 2 --time 0.2 --t0 0.1 --resolution 16x16 --reference-spp 4 --reference %s/ref.exr --min-length 2 "
                     "--render-args '--seed-paths 2000' --render " BIN_DIR "/render >/dev/null 2>&1",
             dir, dir);
    cr_assert_eq(system(cmd), 0, "%s", cmd);
    snprintf(cmd, sizeof cmd, "%s/o/runs.csv", dir);
    const char *runs = slurp_file(cmd);
    cr_assert(strstr(runs, "# method nosuch not available in this build"), "%s", runs);
    cr_assert(strstr(runs, "cornell-box,pssmlt,2,0.2,"), "%s", runs);
    cr_assert(strstr(runs, "cornell-box,big,1,0.1,"), "%s", runs);
    cr_assert(strstr(runs, "# min_length 2"), "%s", runs);
    snprintf(cmd, sizeof cmd, "%s/o/cornell-box.md", dir);
    cr_assert(strstr(slurp_file(cmd), "| nosuch | not available in this build"));
    snprintf(cmd, sizeof cmd, BIN_DIR "/ch6_equal --scene scenes/cornell-box/scene.json --out %s/o --seeds 1 2>/dev/null", dir);
    int st = system(cmd);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 2);
    snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
    cr_assert_eq(system(cmd), 0);
}
