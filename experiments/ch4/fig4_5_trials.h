/* What sets the shape of Fig. 4.5: the acceptance of MMLT large steps and of MCTLS per length,
 * predicted from independent pairs of subpaths (stats/indep_accept.h: both are independence
 * samplers), split into the share of proposals that carry light and the acceptance of those that
 * do, and with MCTLS's target swapped for the mean over the techniques with light instead of their
 * sum. */
#ifndef FIG4_5_TRIALS_H
#define FIG4_5_TRIALS_H

#include "common/table.h"
#include "sampler/sampler.h"
#include "scene/scene.h"
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

/* The statistics per length, in the CSV's order (each with a jackknife standard error). */
enum trial_stat {
    TS_ACCEPT_MMLT,            /* predicted mean acceptance of an MMLT large step */
    TS_ACCEPT_MCTLS,           /* of MCTLS (Eq. 4.7: target = the sum of the k + 1 trials) */
    TS_ACCEPT_RATIO,           /* MCTLS / MMLT */
    TS_LIGHT_RATIO,            /* share of proposals with light, MCTLS / MMLT = (k + 1) P(n > 0) / E[n] */
    TS_GIVEN_LIGHT_RATIO,      /* the acceptance of proposals with light, MCTLS / MMLT: accept / light ratio */
    TS_TECHNIQUES,             /* E[n | n > 0]: techniques with light of a pair that has any */
    TS_TECHNIQUES_CV,          /* their coefficient of variation over such pairs */
    TS_ACCEPT_MCTLS_MEAN,      /* MCTLS with the target sum / n (the mean over the techniques with light) */
    TS_GIVEN_LIGHT_RATIO_MEAN, /* TS_GIVEN_LIGHT_RATIO with that target */
    TS_COUNT
};
extern const char *const trial_stat_names[TS_COUNT];

struct trials_table {
    int K;
    double value[TS_COUNT][MAX_PATH_LENGTH + 1], se[TS_COUNT][MAX_PATH_LENGTH + 1]; /* [stat][length], 2..K */
};

/* `pairs` independent pairs of subpaths per length 2..K (seed, threads), their k + 1 trials each
 * (mcmc/mctls.h), into t; false when K is out of range. */
bool fig45_trials(const struct scene *sc, int K, long pairs, uint64_t seed, int threads, bool progress,
                  struct trials_table *t);
/* The table's rows, in the columns length,statistic,value,se (fig45_trials_cols). */
struct trial_row {
    int length;
    const char *statistic;
    double value, se;
};
extern const struct column fig45_trials_cols[];
void fig45_trials_rows(struct table *tab, const struct trials_table *t);

#endif
