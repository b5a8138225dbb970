/* The statistical baseline checker (bin/check_stats) used by `make check-table1-cmlt` can fail:
 * the committed CMLT baseline passes against itself, and fails against a clearly perturbed copy
 * (every mean scaled by 1.3, i.e. tens of standard errors), a copy with one row shifted by 20
 * standard errors, and a copy missing a row; malformed input gives exit status 2. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef CHECK_STATS_BIN
#define CHECK_STATS_BIN "bin/check_stats"
#endif
#ifndef CMLT_BASELINE
#define CMLT_BASELINE "results/baselines/table1-cmlt/stats-quick.csv"
#endif

/* Copies the baseline to a temporary file, transforming the rmse_mean column (index 3) of data
 * rows: mode 0 copy, 1 scale all by 1.3, 2 shift the first row by 20 se, 3 drop the last row,
 * 4 corrupt a number. */
static void write_variant(const char *out, int mode)
{
    FILE *in = fopen(CMLT_BASELINE, "r"), *f = fopen(out, "w");
    cr_assert(in, "cannot open %s", CMLT_BASELINE);
    cr_assert(f);
    char line[1024];
    int data = 0, total = 0;
    while (fgets(line, sizeof line, in))
        if (line[0] != '#' && strncmp(line, "algorithm,", 10)) total++;
    rewind(in);
    while (fgets(line, sizeof line, in)) {
        if (line[0] == '#' || !strncmp(line, "algorithm,", 10)) {
            fputs(line, f);
            continue;
        }
        data++;
        char alg[64];
        unsigned long long n;
        int seeds;
        double mean, se;
        char rest[512];
        cr_assert(sscanf(line, "%63[^,],%llu,%d,%lf,%lf,%511s", alg, &n, &seeds, &mean, &se, rest) == 6);
        if (mode == 1) mean *= 1.3;
        if (mode == 2 && data == 1) mean += 20 * se;
        if (mode == 3 && data == total) continue;
        if (mode == 4 && data == 2) {
            fprintf(f, "%s,%llu,%d,abc,%g,%s\n", alg, n, seeds, se, rest);
            continue;
        }
        fprintf(f, "%s,%llu,%d,%.17g,%.17g,%s\n", alg, n, seeds, mean, se, rest);
    }
    fclose(in);
    fclose(f);
}

static int run_check(const char *current)
{
    char cmd[2048];
    snprintf(cmd, sizeof cmd, "%s --key algorithm,n --mean rmse_mean --se rmse_se --count seeds %s %s > /dev/null 2>&1",
             CHECK_STATS_BIN, CMLT_BASELINE, current);
    int st = system(cmd);
    cr_assert(st != -1 && WIFEXITED(st), "could not run %s", CHECK_STATS_BIN);
    return WEXITSTATUS(st);
}

Test(cmlt_check, baseline_passes_perturbed_fails)
{
    char dir[] = "/tmp/cmlt-check-XXXXXX", path[256];
    cr_assert(mkdtemp(dir));
    const int expect[5] = {0, 1, 1, 1, 2};
    for (int mode = 0; mode < 5; mode++) {
        snprintf(path, sizeof path, "%s/variant%d.csv", dir, mode);
        write_variant(path, mode);
        int code = run_check(path);
        cr_expect(code == expect[mode], "variant %d: exit status %d, expected %d", mode, code, expect[mode]);
        remove(path);
    }
    rmdir(dir);
}

Test(cmlt_check, help_and_usage)
{
    char cmd[512];
    snprintf(cmd, sizeof cmd, "%s --help > /dev/null", CHECK_STATS_BIN);
    int st = system(cmd);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    snprintf(cmd, sizeof cmd, "%s --bogus 2> /dev/null", CHECK_STATS_BIN);
    st = system(cmd);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 2);
}
