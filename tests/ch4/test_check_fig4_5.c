/* make check-fig4.5's comparisons can fail: the committed fig4.5 baseline (seed 1) and an
 * independent committed run (seed 2) agree under bin/check_stats (Sidak alpha = 0.01 over the 66
 * rows: six runs, lengths 2-12), and the same run with one row's acceptance raised by 30 % (> 10
 * standard errors) is rejected. The second comparison, over fig4.5-ratios.csv (with the claims'
 * shares of proposals with light), passes the replicate and rejects MCTLS's share over MMLT's at
 * length 12 set to its acceptance ratio (3.3 for 5.7: no more light than acceptance gain). The
 * third, over fig4.5-trials.csv, passes the replicate and rejects a prediction moved. */
#include <criterion/criterion.h>

#include "support/check_csv.h"

#define BASE "results/baselines/fig4.5/fig4.5.csv"
#define REPL "results/baselines/fig4.5/replicate-seed2.csv"

/* mctls,8's acceptance is 0.0113 +- 0.00024 in the replicate: 0.0147 is 30 % (> 10 standard
 * errors) more. */
Test(check_fig4_5, replicate_passes_perturbed_fails)
{
    check_csv_replicate_and_broken("--key method,length --mean mean_accept --se stderr", BASE, REPL, "mctls,8", 3,
                                   0.0147);
}

#define RBASE "results/baselines/fig4.5/fig4.5-ratios.csv"
#define RREPL "results/baselines/fig4.5/replicate-seed2-ratios.csv"

Test(check_fig4_5, ratios_replicate_passes_light_share_moved_fails)
{
    check_csv_replicate_and_broken("--key ratio,length --mean value --se se", RBASE, RREPL, "light:mctls/mmlt-large,12",
                                   2, 3.3);
}

#define TBASE "results/baselines/fig4.5/fig4.5-trials.csv"
#define TREPL "results/baselines/fig4.5/replicate-seed2-trials.csv"

/* The prediction from independent trials (fig4.5-trials.csv, jackknife errors): the seed-2 run
 * passes; with MCTLS's acceptance given light at length 12 under the mean target moved to its value
 * under Eq. 4.7's sum (0.56 for 0.88: as if the count of techniques with light explained nothing),
 * it fails. */
Test(check_fig4_5, trials_replicate_passes_count_effect_removed_fails)
{
    check_csv_replicate_and_broken("--key length,statistic --mean value --se se", TBASE, TREPL,
                                   "12,given_light_ratio_mean", 2, 0.56);
}
