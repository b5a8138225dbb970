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
 * errors), and OUT/claims.csv and claims.md: the thesis's statements on the figure (§4.3) with
 * their verdicts, and two checks of the chains against the prediction. */
#include "base/parallel.h"
#include "base/util.h"
#include "ch4/ch4_common.h"
#include "ch4/fig4_5_trials.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/table_set.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The runs: the large step, MCTLS's trials (mlt_opts.mctls_tries, 0 = Eq. 4.7) and whether t = 0
 * is counted. */
enum { V_MMLT, V_MCTLS, V_TRIES1, V_TRIES1_T0, V_TRIES2, V_TRIES4, NV };
static const struct variant {
    const char *name;
    enum large_step step;
    int tries;
    bool t0;
} variants[NV] = {
    {"mmlt-large", LARGE_MMLT, 0, false},    {"mctls", LARGE_MCTLS, 0, false},
    {"mctls-tries1", LARGE_MCTLS, 1, false}, {"mctls-tries1-t0", LARGE_MCTLS, 1, true},
    {"mctls-tries2", LARGE_MCTLS, 2, false}, {"mctls-tries4", LARGE_MCTLS, 4, false},
};

/* Mean acceptance and its batch-means standard error per run and length. */
struct accept_table {
    double mean[NV][MAX_PATH_LENGTH + 1], se[NV][MAX_PATH_LENGTH + 1];
    double nonzero[NV][MAX_PATH_LENGTH + 1]; /* share of proposals with a contribution (any trial's, for MCTLS) */
    long attempts[NV][MAX_PATH_LENGTH + 1];
    int K;
};

/* The ratio of run a's acceptance to run b's at length k and its standard error (first-order). */
static void ratio_of(const struct accept_table *t, int a, int b, int k, double *r, double *se)
{
    *r = t->mean[a][k] / t->mean[b][k];
    *se = *r * sqrt(pow(t->se[a][k] / t->mean[a][k], 2) + pow(t->se[b][k] / t->mean[b][k], 2));
}

static void ratio_at(const struct accept_table *t, int k, double *r, double *se)
{
    ratio_of(t, V_MCTLS, V_MMLT, k, r, se);
}

/* MCTLS's share of proposals with a contribution over MMLT large steps' at length k, with its
 * standard error: a large step's proposal does not depend on the state, so both are binomial. */
static void light_ratio(const struct accept_table *t, int k, double *r, double *se)
{
    double p0 = t->nonzero[V_MMLT][k], p1 = t->nonzero[V_MCTLS][k];
    *r = p1 / p0;
    *se = *r * sqrt((1 - p0) / (p0 * t->attempts[V_MMLT][k]) + (1 - p1) / (p1 * t->attempts[V_MCTLS][k]));
}

/* The mean of per-length values over lengths 2..K (equal mutations per length) and its standard
 * error from the per-length ones. */
static void mean_over_lengths(const double *mean, const double *se, int K, double *m, double *m_se)
{
    double v = 0;
    *m = 0;
    for (int k = 2; k <= K; k++)
        *m += mean[k] / (K - 1), v += pow(se[k] / (K - 1), 2);
    *m_se = sqrt(v);
}

/* The chains against their prediction from independent trials (both are independence samplers):
 * the acceptance averaged over lengths 2..K within ±10 %. */
static void claims_predicted(struct claims *cl, const struct accept_table *t, const struct trials_table *tr)
{
    char zs[256], md[512], stat[96];
    const struct {
        int run;
        enum trial_stat stat;
    } pred[2] = {{V_MMLT, TS_ACCEPT_MMLT}, {V_MCTLS, TS_ACCEPT_MCTLS}};
    for (int p = 0; p < 2; p++) {
        double mc, sc, mp, sp;
        mean_over_lengths(t->mean[pred[p].run], t->se[pred[p].run], t->K, &mc, &sc);
        mean_over_lengths(tr->value[pred[p].stat], tr->se[pred[p].stat], t->K, &mp, &sp);
        struct verdict v = verdict_similar(mc, sc, mp, sp, 0.10, 1);
        snprintf(zs, sizeof zs, "predicted10%%=%.2f", v.zmin);
        snprintf(md, sizeof md, "predicted from independent trials %.4g ± %.2g, within ±10 %% (z = %.1f)", mp, sp,
                 v.zmin);
        snprintf(stat, sizeof stat, "acceptance, mean over lengths 2-%d", t->K);
        claims_row(cl, "harness", "harness check",
                   p == 0 ? "MMLT large steps accept as an independence sampler of their target predicts"
                          : "MCTLS accepts as an independence sampler of Eq. 4.7's target predicts",
                   stat, variants[pred[p].run].name, mc, sc, zs, md, &v);
    }
}

/* Thesis §4.3's statements on Figure 4.5: MCTLS above MMLT at every length, up to 5x at the
 * longest, about 1x for short paths; MMLT large steps consistently low. */
static void claims_thesis(struct claims *cl, const struct accept_table *t)
{
    char zs[256], md[512];
    /* MCTLS above MMLT at every length: the smallest z over the lengths decides */
    const bool both[2] = {true, true};
    struct verdict worst = {"holds", INFINITY, -1, 0};
    int at = 2;
    for (int k = 2; k <= t->K; k++) {
        double m[2] = {t->mean[0][k], t->mean[1][k]}, e[2] = {t->se[0][k], t->se[1][k]}, z[2];
        struct verdict v = verdict_extreme(m, e, both, 2, 1, +1, 1, z);
        if (v.zmin < worst.zmin) worst = v, at = k;
    }
    snprintf(zs, sizeof zs, "mmlt-large=%.2f@%d", worst.zmin, at);
    snprintf(md, sizeof md, "MMLT large steps at each length; smallest z = %.1f at length %d", worst.zmin, at);
    claims_row(cl, "T15", "thesis §4.3", "MCTLS is accepted more often than MMLT large steps at every length",
               "mean acceptance per length", "mctls", t->mean[1][at], t->se[1][at], zs, md, &worst);
    double r, rse;
    ratio_at(t, t->K, &r, &rse);
    struct verdict v = verdict_similar(r, rse, 5, 0, 0.25, 1);
    snprintf(zs, sizeof zs, "5x=%.2f", v.zmin);
    snprintf(md, sizeof md, "5 within ±25 %% at length %d (z = %.1f)", t->K, v.zmin);
    claims_row(cl, "harness:T16", "thesis §4.3",
               "MCTLS is up to five times more likely to be accepted at the longest length",
               "acceptance ratio MCTLS / MMLT", "mctls", r, rse, zs, md, &v);
    ratio_at(t, 2, &r, &rse);
    v = verdict_similar(r, rse, 1, 0, 0.25, 1);
    snprintf(zs, sizeof zs, "1x=%.2f", v.zmin);
    snprintf(md, sizeof md, "1 within ±25 %% at length 2 (z = %.1f)", v.zmin);
    claims_row(cl, "harness:T14", "thesis §4.3", "MCTLS is rejected about as often as MMLT large steps for short paths",
               "acceptance ratio MCTLS / MMLT at length 2", "mctls", r, rse, zs, md, &v);
    v = verdict_similar(t->mean[0][t->K], t->se[0][t->K], t->mean[0][2], t->se[0][2], 0.25, 1);
    snprintf(zs, sizeof zs, "length2=%.2f", v.zmin);
    snprintf(md, sizeof md, "length 2: %.4g ± %.2g, within ±25 %% (z = %.1f)", t->mean[0][2], t->se[0][2], v.zmin);
    char stat[96];
    snprintf(stat, sizeof stat, "MMLT large-step acceptance at length %d", t->K);
    claims_row(cl, "harness:T13", "thesis §4.3", "MMLT large steps are consistently low over all path lengths", stat,
               "mmlt-large", t->mean[0][t->K], t->se[0][t->K], zs, md, &v);
}

/* The harness's checks of the drawn trials and the caption's reason (more trials for longer paths,
 * more proposals with light). */
static void claims_trials(struct claims *cl, const struct accept_table *t)
{
    char zs[256], md[512], stat[96];
    double r, rse;
    struct verdict v;
    /* one drawn trial is an MMLT large step (a check of the drawn trials): the acceptance averaged
     * over lengths 2..K (equal mutations per length) within ±5 % */
    double m1, s1, m0, s0;
    mean_over_lengths(t->mean[V_TRIES1], t->se[V_TRIES1], t->K, &m1, &s1);
    mean_over_lengths(t->mean[V_MMLT], t->se[V_MMLT], t->K, &m0, &s0);
    v = verdict_similar(m1, s1, m0, s0, 0.05, 1);
    snprintf(zs, sizeof zs, "mmlt-large5%%=%.2f", v.zmin);
    snprintf(md, sizeof md, "MMLT large steps %.4g ± %.2g within ±5 %% (z = %.1f)", m0, s0, v.zmin);
    snprintf(stat, sizeof stat, "large-step acceptance, mean over lengths 2-%d", t->K);
    claims_row(cl, "harness", "harness check", "MCTLS with one drawn trial is an MMLT large step", stat, "mctls-tries1",
               m1, s1, zs, md, &v);
    /* the thesis's count: its MMLT large steps draw among k + 2 techniques, t = 0 always failing */
    ratio_of(t, V_MCTLS, V_TRIES1_T0, t->K, &r, &rse);
    v = verdict_similar(r, rse, 5, 0, 0.25, 1);
    snprintf(zs, sizeof zs, "5x=%.2f", v.zmin);
    snprintf(md, sizeof md, "5 within ±25 %% at length %d (z = %.1f)", t->K, v.zmin);
    claims_row(cl, "harness:T16", "thesis §4.3",
               "up to five times at the longest length, counting k + 2 techniques as the thesis does",
               "acceptance ratio MCTLS / MMLT large steps among k + 2", "mctls", r, rse, zs, md, &v);
    /* the caption's reason: longer paths give more trials. With a fixed number of trials (4) the
     * ratio to MMLT should then not grow from length 3 (4 techniques) to the longest */
    double r3, rse3;
    ratio_of(t, V_TRIES4, V_MMLT, 3, &r3, &rse3);
    ratio_of(t, V_TRIES4, V_MMLT, t->K, &r, &rse);
    v = verdict_similar(r, rse, r3, rse3, 0.25, 1);
    snprintf(zs, sizeof zs, "length3=%.2f", v.zmin);
    snprintf(md, sizeof md, "length 3: %.3g ± %.2g, within ±25 %% (z = %.1f)", r3, rse3, v.zmin);
    snprintf(stat, sizeof stat, "acceptance ratio, 4 drawn trials / MMLT, at length %d", t->K);
    claims_row(cl, "T17", "thesis Fig. 4.5 caption",
               "MCTLS gains with length because longer paths give more trials: at a fixed number of trials the gain "
               "stays flat",
               stat, "mctls-tries4", r, rse, zs, md, &v);
    /* the caption's reason read directly: MCTLS's proposals carry light more often than MMLT's by
     * a factor that grows with length (longest length against length 3) */
    light_ratio(t, t->K, &r, &rse);
    light_ratio(t, 3, &r3, &rse3);
    double lm[2] = {r, r3}, ls[2] = {rse, rse3}, lz[2];
    const bool two[2] = {true, true};
    v = verdict_extreme(lm, ls, two, 2, 0, +1, 1, lz);
    snprintf(zs, sizeof zs, "length3=%.2f", lz[1]);
    snprintf(md, sizeof md, "length 3: %.3g ± %.2g (z = %.1f)", r3, rse3, lz[1]);
    snprintf(stat, sizeof stat, "share of proposals with light, MCTLS / MMLT, at length %d", t->K);
    claims_row(cl, "T17", "thesis Fig. 4.5 caption", "MCTLS generates more proposals with light for longer paths", stat,
               "mctls", r, rse, zs, md, &v);
}

/* Thesis §4.3 on Figure 4.5. The errors are one run's batch-means errors, so "seeds_needed" counts
 * runs of this budget. */
static char *claims(const struct accept_table *t, const struct trials_table *tr, const char *out, const char *scale,
                    char *err, size_t errlen)
{
    struct claims cl;
    char command[64];
    snprintf(command, sizeof command, "make fig4.5 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.3 on Fig. 4.5, lengths 2-%d (batch-means errors of one run)",
                 t->K);
    claims_thesis(&cl, t);
    claims_trials(&cl, t);
    claims_predicted(&cl, t, tr);
    return claims_finish(&cl, out, err, errlen);
}

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
                        struct accept_table *tab, char *err, size_t errlen)
{
    int K = a->max_length;
    const struct variant *va = &variants[m];
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

/* Every variant's chain over all lengths: OUT/fig4.5.csv, and its acceptances into tab. */
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
    for (int m = 0; m < NV; m++)
        if (!run_variant(a, sc, m, &tb.t[0], tab, err, errlen)) {
            text_out_free(&tb.t[0].out);
            return false;
        }
    return table_set_save(&tb, "fig4_5", a->fig.out, err, errlen);
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
            ratio_of(tab, pairs[p][0], pairs[p][1], k, &row.value, &row.se);
            snprintf(name, sizeof name, "%s/%s", variants[pairs[p][0]].name, variants[pairs[p][1]].name);
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
        light_ratio(tab, k, &row.value, &row.se);
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
    ok = ok && ch4_show_claims(claims(&tab, tr, a.fig.out, a.fig.scale, err, sizeof err));
    free(tr);
    scene_free(sc);
    if (!ok) die(DIE_RUNTIME, "fig4_5", "%s", err);
    return 0;
}
