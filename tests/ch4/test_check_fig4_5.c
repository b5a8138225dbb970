/* make check-fig4.5's comparisons can fail: the committed fig4.5 baseline (seed 1) and an
 * independent committed run (seed 2) agree under bin/check_stats (Sidak alpha = 0.01 over the 66
 * rows: six runs, lengths 2-12), and the same run with one row's acceptance raised by 30 % (> 10
 * standard errors) is rejected. The second comparison, over fig4.5-ratios.csv (with the claims'
 * shares of proposals with light), passes the replicate and rejects MCTLS's share over MMLT's at
 * length 12 set to its acceptance ratio (3.3 for 5.7: no more light than acceptance gain). The
 * third, over fig4.5-trials.csv, passes the replicate and rejects a prediction moved. */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "support/check_csv.h"

#define BASE "results/baselines/fig4.5/fig4.5.csv"
#define REPL "results/baselines/fig4.5/replicate-seed2.csv"

static int check(const char *current)
{
    return check_csv_run("--key method,length --mean mean_accept --se stderr", BASE, current);
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

#define RBASE "results/baselines/fig4.5/fig4.5-ratios.csv"
#define RREPL "results/baselines/fig4.5/replicate-seed2-ratios.csv"

Test(check_fig4_5, ratios_replicate_passes_light_share_moved_fails)
{
    check_csv_replicate_and_broken("--key ratio,length --mean value --se se", RBASE, RREPL, "light:mctls/mmlt-large,12", 2,
                                   3.3);
}

#define TBASE "results/baselines/fig4.5/fig4.5-trials.csv"
#define TREPL "results/baselines/fig4.5/replicate-seed2-trials.csv"

/* The prediction from independent trials (fig4.5-trials.csv, jackknife errors): the seed-2 run
 * passes; with MCTLS's acceptance given light at length 12 under the mean target moved to its value
 * under Eq. 4.7's sum (0.56 for 0.88: as if the count of techniques with light explained nothing),
 * it fails. */
Test(check_fig4_5, trials_replicate_passes_count_effect_removed_fails)
{
    check_csv_replicate_and_broken("--key length,statistic --mean value --se se", TBASE, TREPL, "12,given_light_ratio_mean",
                                   2, 0.56);
}
