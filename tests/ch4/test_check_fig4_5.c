/* make check-fig4.5's comparison can fail: the committed fig4.5 baseline (seed 1) and an
 * independent committed run (seed 2) agree under bin/check_stats (Sidak alpha = 0.01 over the 66
 * rows: six runs, lengths 2-12), and the same run with one row's acceptance raised by 30 % (> 10 standard errors) is rejected. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif
#define BASE "results/baselines/fig4.5/fig4.5.csv"
#define REPL "results/baselines/fig4.5/replicate-seed2.csv"

static int check(const char *current)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, BIN_DIR "/check_stats --key method,length --mean mean_accept --se stderr %s %s > /dev/null 2>&1",
             BASE, current);
    int st = system(cmd);
    cr_assert(WIFEXITED(st), "check_stats did not run");
    return WEXITSTATUS(st);
}

/* Writes REPL with mean_accept of the row `key` (method,length) multiplied by `factor`. */
static void perturbed(const char *out, const char *key, double factor)
{
    FILE *in = fopen(REPL, "r"), *f = fopen(out, "w");
    cr_assert(in && f);
    char line[1024];
    size_t kl = strlen(key);
    while (fgets(line, sizeof line, in)) {
        if (strncmp(line, key, kl) || line[kl] != ',') {
            fputs(line, f);
            continue;
        }
        long attempts;
        double mean;
        char rest[512];
        cr_assert(sscanf(line + kl + 1, "%ld,%lf,%511s", &attempts, &mean, rest) == 3);
        fprintf(f, "%s,%ld,%.9g,%s\n", key, attempts, mean * factor, rest);
    }
    fclose(in);
    fclose(f);
}

Test(check_fig4_5, replicate_passes_perturbed_fails)
{
    cr_assert_eq(check(REPL), 0, "two independent runs disagree");
    char tmp[] = "/tmp/fig45-perturbed-XXXXXX";
    int fd = mkstemp(tmp);
    cr_assert(fd >= 0);
    perturbed(tmp, "mctls,8", 1.3);
    cr_assert_eq(check(tmp), 1, "a 30 %% shift of mctls,8 was not detected");
    perturbed(tmp, "mctls,8", 1.0);
    cr_assert_eq(check(tmp), 0, "an unmodified copy failed");
    remove(tmp);
}
