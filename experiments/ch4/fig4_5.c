/* bin/fig4_5: thesis Figure 4.5. Average acceptance probability per path length of MMLT large steps
 * versus multiple correlated-try large steps (MCTLS), both alone (p_large = 1, no small steps),
 * with equal expected mutation budgets per length and the same seeds. Then what sets the shape of
 * their ratio: MCTLS with a fixed number N of trials drawn uniformly among the techniques (Eq. 4.5;
 * N = 1 is an MMLT large step taken through MCTLS's code, a check of it), with N = 2 and 4 at every
 * length, and N = 1 drawn among k + 2 techniques as the thesis counts them (t = 0, a hit on the
 * pinhole camera, a try that always fails): the thesis's MMLT large step.
 * Writes OUT/fig4.5.csv: method,length,attempts,mean_accept,stderr,accepted_fraction,seconds
 * (seconds: CPU time spent on that length's proposals), OUT/fig4.5-ratios.csv:
 * ratio,length,value,se (each run's acceptance over MMLT large steps', MCTLS's over the
 * thesis-count MMLT large steps', and "contributing-techniques": the mean number of techniques with
 * a contribution among subpath pairs that have one, from the two runs' shares of such proposals;
 * "light:mctls/mmlt-large": the ratio of those shares), OUT/fig4.5-trials.csv:
 * length,statistic,value,se, both acceptances predicted from independent pairs of subpaths and
 * split into their factors (fig4_5_trials.h; 4x the chains' proposals per length, jackknife
 * errors), OUT/fig4.5-mixing.csv: the chains' mixing diagnostics per variant and length
 * (common/mixing_runs.h; a warning on stderr as bin/render's), and OUT/claims.csv and claims.md: the thesis's
 * statements on the figure (§4.3) with their verdicts, and two checks of the chains against the prediction. */
#include "base/parallel.h"
#include "base/util.h"
#include "ch4/ch4_common.h"
#include "ch4/fig4_5_claims.h"
#include "ch4/fig4_5_trials.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/mixing_runs.h"
#include "common/opts.h"
#include "common/table_set.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* A row of OUT/fig4.5.csv: one variant's large steps of one length. */
struct accept_row {
    const char *method;
    int length;
    long attempts;
    double mean_accept, se, accepted_fraction, seconds;
};
static const struct column accept_cols[] = {
    COL_STRING(struct accept_row, "method", method),
    COL_INT(struct accept_row, "length", "%d", length),
    COL_LONG(struct accept_row, "attempts", "%ld", attempts),
    COL_DOUBLE(struct accept_row, "mean_accept", "%.9g", mean_accept),
    COL_DOUBLE(struct accept_row, "stderr", "%.9g", se),
    COL_DOUBLE(struct accept_row, "accepted_fraction", "%.9g", accepted_fraction),
    COL_DOUBLE(struct accept_row, "seconds", "%.4f", seconds),
    {0}};
/* A row of OUT/fig4.5-ratios.csv. */
struct ratio_row {
    const char *ratio;
    int length;
    double value, se;
};
static const struct column ratio_cols[] = {COL_STRING(struct ratio_row, "ratio", ratio),
                                           COL_INT(struct ratio_row, "length", "%d", length),
                                           COL_DOUBLE(struct ratio_row, "value", "%.6g", value),
                                           COL_DOUBLE(struct ratio_row, "se", "%.3g", se),
                                           {0}};

/* Variant m's chain over all lengths: its rows of OUT/fig4.5.csv, its acceptances into tab. */
static bool run_variant(const struct opts_accept *a, const struct scene *sc, int m, struct table *out,
                        struct mixing_runs *mx, struct accept_table *tab, char *err, size_t errlen)
{
    int K = a->max_length;
    const struct fig4_5_variant *va = &fig4_5_variants[m];
    struct mlt_opts o = {.method = MLT_MMLT,
                         .p_large = 1,
                         .mutations = a->mutations,
                         .seed_paths = a->fig.paper ? 1000000 : 100000,
                         .seed = a->fig.seed,
                         .threads = a->fig.threads,
                         .max_length = K,
                         .progress = isatty(2),
                         .large_step = va->step,
                         .mctls_tries = va->tries,
                         .mctls_count_t0 = va->t0,
                         .uniform_lengths = true,
                         .time_proposals = true};
    pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
    fprintf(stderr, "fig4.5: %s, %ld mutations over lengths 1..%d\n", va->name, a->mutations, K);
    struct mlt_result r;
    if (!mlt_render(sc, &o, &r, err, errlen)) return false;
    mixing_runs_add(mx, va->name, &r, r.seconds);
    enum proposal_kind kind = va->step == LARGE_MMLT ? PROPOSAL_LARGE : PROPOSAL_MCTLS;
    for (int k = 1; k <= K; k++) {
        /* both technique outcomes together: the figure plots all large steps of a length */
        const struct accept_cell *c = &r.stats.any[kind][k];
        if (!c->attempts) continue;
        table_row(out, &(struct accept_row){va->name, k, c->attempts, cell_mean(c), cell_stderr(c),
                                            (double)c->accepted / c->attempts, c->seconds});
        tab->mean[m][k] = cell_mean(c), tab->se[m][k] = cell_stderr(c);
        tab->nonzero[m][k] = (double)c->nonzero / c->attempts, tab->attempts[m][k] = c->attempts;
    }
    mlt_result_free(&r);
    return true;
}

/* Every variant's chain over all lengths: OUT/fig4.5.csv, its chains' mixing diagnostics
 * OUT/fig4.5-mixing.csv (common/mixing_runs.h), and its acceptances into tab. */
static bool run_variants(const struct opts_accept *a, const struct scene *sc, struct accept_table *tab, char *err,
                         size_t errlen)
{
    struct table_set tb;
    FILE *f = table_set_open_one(&tb, "fig4.5.csv", accept_cols);
    csv_meta_head(f, "fig4.5: MMLT large steps vs MCTLS, p_large = 1, no small steps, uniform length budgets",
                  a->fig.scene, a->fig.scale);
    csv_meta(f, NULL,
             "mctls-triesN: MCTLS with N trials drawn uniformly among the k + 1 techniques (Eq. 4.5; N = 1 is "
             "an MMLT large step); -t0: among k + 2, t = 0 a try that always fails (the thesis's count)");
    csv_meta(f, "seed", "%llu", (unsigned long long)a->fig.seed);
    csv_meta(f, "threads", "%d", a->fig.threads);
    csv_meta(f, "mutations_per_method", "%ld", a->mutations);
    table_header(&tb.t[0]);
    struct mixing_runs mx;
    f = mixing_runs_open(&mx, "fig4_5", "fig4.5-mixing.csv");
    csv_meta_head(f, "fig4.5: the mixing diagnostics of the chains behind fig4.5.csv (core/mcmc/docs/outputs.md)",
                  a->fig.scene, a->fig.scale);
    csv_meta(f, "seed", "%llu", (unsigned long long)a->fig.seed);
    csv_meta(f, "threads", "%d", a->fig.threads);
    for (int m = 0; m < NV; m++)
        if (!run_variant(a, sc, m, &tb.t[0], &mx, tab, err, errlen)) {
            text_out_free(&tb.t[0].out);
            text_out_free(&mx.out);
            return false;
        }
    if (!table_set_save(&tb, "fig4_5", a->fig.out, err, errlen)) {
        text_out_free(&mx.out);
        return false;
    }
    return mixing_runs_save(&mx, a->fig.out, err, errlen);
}

/* The ratio rows of OUT/fig4.5-ratios.csv whose shape the figure is about. */
static void write_ratio_rows(int K, const struct accept_table *tab, struct table *out)
{
    const int pairs[][2] = {
        {V_MCTLS, V_MMLT}, {V_MCTLS, V_TRIES1_T0}, {V_TRIES1, V_MMLT}, {V_TRIES2, V_MMLT}, {V_TRIES4, V_MMLT}};
    char name[128];
    for (size_t p = 0; p < sizeof pairs / sizeof *pairs; p++)
        for (int k = 1; k <= K; k++) {
            if (!(tab->mean[pairs[p][0]][k] > 0 && tab->mean[pairs[p][1]][k] > 0)) continue;
            struct ratio_row row = {.ratio = name, .length = k};
            fig4_5_ratio(tab, pairs[p][0], pairs[p][1], k, &row.value, &row.se);
            snprintf(name, sizeof name, "%s/%s", fig4_5_variants[pairs[p][0]].name, fig4_5_variants[pairs[p][1]].name);
            table_row(out, &row);
        }
}

/* OUT/fig4.5-ratios.csv: the ratios whose shape the figure is about, with first-order standard errors. */
static bool write_ratios(const struct opts_accept *a, const struct accept_table *tab, char *err, size_t errlen)
{
    int K = a->max_length;
    struct table_set tb;
    FILE *f = table_set_open_one(&tb, "fig4.5-ratios.csv", ratio_cols);
    csv_meta_head(f, "fig4.5: acceptance ratios per length (first-order standard errors from the batch-means errors)",
                  a->fig.scene, a->fig.scale);
    write_ratio_rows(K, tab, &tb.t[0]);
    /* How many techniques carry light for a pair of subpaths that has any: a large step's proposal
     * is independent of the state, so both shares are binomial; an MMLT large step has a
     * contribution with probability E[n] / (k + 1) and MCTLS's trials with P(n > 0), so
     * E[n | n > 0] = (k + 1) P_mmlt / P_mctls. */
    for (int k = 1; k <= K; k++) {
        double p0 = tab->nonzero[V_MMLT][k], p1 = tab->nonzero[V_MCTLS][k];
        if (!(p0 > 0 && p1 > 0)) continue;
        double v = (k + 1) * p0 / p1;
        double rse = sqrt((1 - p0) / (p0 * tab->attempts[V_MMLT][k]) + (1 - p1) / (p1 * tab->attempts[V_MCTLS][k]));
        table_row(&tb.t[0], &(struct ratio_row){"contributing-techniques", k, v, v * rse});
    }
    for (int k = 1; k <= K; k++) {
        if (!(tab->nonzero[V_MMLT][k] > 0 && tab->nonzero[V_MCTLS][k] > 0)) continue;
        struct ratio_row row = {.ratio = "light:mctls/mmlt-large", .length = k};
        fig4_5_light_ratio(tab, k, &row.value, &row.se);
        table_row(&tb.t[0], &row);
    }
    return table_set_save(&tb, "fig4_5", a->fig.out, err, errlen);
}

/* The prediction from independent trials, four times the chains' proposals per length:
 * OUT/fig4.5-trials.csv. */
static bool run_trials(const struct opts_accept *a, const struct scene *sc, struct trials_table *tr, char *err,
                       size_t errlen)
{
    int K = a->max_length;
    long trial_pairs = 4 * (a->mutations / K);
    fprintf(stderr, "fig4.5: %ld independent pairs of subpaths per length\n", trial_pairs);
    if (!fig45_trials(sc, K, trial_pairs, a->fig.seed, a->fig.threads, isatty(2), tr)) {
        snprintf(err, errlen, "%ld mutations over %d lengths leave too few trials", a->mutations, K);
        return false;
    }
    struct table_set tb;
    FILE *f = table_set_open_one(&tb, "fig4.5-trials.csv", fig45_trials_cols);
    csv_meta_head(f, "fig4.5: acceptance per length predicted from independent pairs of subpaths (jackknife errors)",
                  a->fig.scene, a->fig.scale);
    csv_meta(f, "seed", "%llu", (unsigned long long)a->fig.seed);
    csv_meta(f, "pairs_per_length", "%ld", trial_pairs);
    fig45_trials_rows(&tb.t[0], tr);
    return table_set_save(&tb, "fig4_5", a->fig.out, err, errlen);
}

int main(int argc, char **argv)
{
    struct opts_accept a;
    struct scene *sc =
        opts_accept_parse(&a, "fig4_5", "scenes/ajar/scene.json", "results/fig4.5", "3000000", "100000000", argc, argv);
    char err[1024];
    struct accept_table tab = {.K = a.max_length};
    struct trials_table *tr = xmalloc(sizeof *tr);
    bool ok = run_variants(&a, sc, &tab, err, sizeof err) && write_ratios(&a, &tab, err, sizeof err) &&
              run_trials(&a, sc, tr, err, sizeof err);
    ok = ok && ch4_show_claims(fig4_5_claims(&tab, tr, a.fig.out, a.fig.scale, err, sizeof err));
    free(tr);
    scene_free(sc);
    if (!ok) die(DIE_RUNTIME, "fig4_5", "%s", err);
    return 0;
}
