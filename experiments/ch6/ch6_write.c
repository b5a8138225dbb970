/* bin/ch6_equal's CSV tables (ch6_equal.h), each written from one column list (common/table.h):
 * runs.csv (one row per run), summary.csv (mean and standard error over seeds per method and
 * budget) and stats.csv (the machine-independent statistics at the largest budget, for make
 * check-fig6.N). Scripts read them by column name (scripts/csv-col.awk). */
#include "ch6/ch6_equal.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/table.h"
#include "common/verdict.h"
#include <math.h>
#include <stdio.h>

/* A row of runs.csv */
struct run_row {
    const char *scene, *method;
    int seed;
    double budget;
    const struct ch6_run *r;
};
static double run_q(const void *row, int q) { return ((const struct run_row *)row)->r->q[q]; }
static double run_seconds(const void *row, int q)
{
    (void)q;
    return ((const struct run_row *)row)->r->seconds;
}
#define RUN_Q(name, fmt, q) COL_COMPUTED(name, fmt, run_q, q)
static const struct column run_cols[] = {COL_STRING(struct run_row, "scene", scene),
                                         COL_STRING(struct run_row, "method", method),
                                         COL_INT(struct run_row, "seed", "%d", seed),
                                         COL_DOUBLE(struct run_row, "budget", "%g", budget),
                                         COL_COMPUTED("seconds", "%.3f", run_seconds, 0),
                                         RUN_Q("mutations", "%.0f", Q_MUTATIONS),
                                         RUN_Q("mutations_per_s", "%.0f", Q_MPS),
                                         RUN_Q("relmse", "%.6g", Q_RELMSE),
                                         RUN_Q("block_spread", "%.6g", Q_SPREAD),
                                         RUN_Q("nonzero", "%.6g", Q_NONZERO),
                                         RUN_Q("large_nonzero", "%.6g", Q_LARGE_NONZERO),
                                         RUN_Q("block_median_relmse", "%.6g", Q_BLOCK_MEDIAN),
                                         RUN_Q("trimmed_relmse", "%.6g", Q_TRIMMED),
                                         RUN_Q("blur4_share", "%.6g", Q_BLUR4),
                                         RUN_Q("blur8_share", "%.6g", Q_BLUR8),
                                         RUN_Q("corr_length", "%.6g", Q_CORRLEN),
                                         RUN_Q("nonzero_per_connection", "%.6g", Q_NONZERO_CONN),
                                         RUN_Q("relmse_scaled", "%.6g", Q_RELMSE_SCALED),
                                         RUN_Q("b_rse", "%.6g", Q_B_RSE),
                                         RUN_Q("inset_block_spread", "%.6g", Q_INSET_SPREAD),
                                         RUN_Q("inset_blur8_share", "%.6g", Q_INSET_BLUR8),
                                         RUN_Q("rhat", "%.4g", Q_RHAT),
                                         RUN_Q("ess_per_s", "%.4g", Q_ESS_PER_S),
                                         RUN_Q("stuck_share", "%.4g", Q_STUCK),
                                         RUN_Q("mixing_warning", "%.0f", Q_MIX_WARN),
                                         RUN_Q("norm_error", "%.6g", Q_NORM_ERR),
                                         RUN_Q("b_image_rse", "%.6g", Q_B_IMAGE_RSE),
                                         {0}};

/* A row of summary.csv: each quantity's mean and its standard error over seeds */
struct summary_row {
    const char *scene, *method;
    double budget;
    int seeds;
    double mean[Q_COUNT], se[Q_COUNT];
};
#define SUM_Q(name, q)                                                                                                 \
    COL_DOUBLE(struct summary_row, name, "%.6g", mean[q]), COL_DOUBLE(struct summary_row, name "_se", "%.3g", se[q])
static const struct column summary_cols[] = {COL_STRING(struct summary_row, "scene", scene),
                                             COL_STRING(struct summary_row, "method", method),
                                             COL_DOUBLE(struct summary_row, "budget", "%g", budget),
                                             COL_INT(struct summary_row, "seeds", "%d", seeds),
                                             SUM_Q("relmse", Q_RELMSE),
                                             SUM_Q("block_spread", Q_SPREAD),
                                             SUM_Q("mutations_per_s", Q_MPS),
                                             SUM_Q("nonzero", Q_NONZERO),
                                             SUM_Q("large_nonzero", Q_LARGE_NONZERO),
                                             SUM_Q("block_median_relmse", Q_BLOCK_MEDIAN),
                                             SUM_Q("trimmed_relmse", Q_TRIMMED),
                                             SUM_Q("blur4_share", Q_BLUR4),
                                             SUM_Q("blur8_share", Q_BLUR8),
                                             SUM_Q("corr_length", Q_CORRLEN),
                                             SUM_Q("nonzero_per_connection", Q_NONZERO_CONN),
                                             SUM_Q("relmse_scaled", Q_RELMSE_SCALED),
                                             SUM_Q("b_rse", Q_B_RSE),
                                             SUM_Q("inset_block_spread", Q_INSET_SPREAD),
                                             SUM_Q("inset_blur8_share", Q_INSET_BLUR8),
                                             SUM_Q("rhat", Q_RHAT),
                                             SUM_Q("ess_per_s", Q_ESS_PER_S),
                                             SUM_Q("stuck_share", Q_STUCK),
                                             SUM_Q("mixing_warning", Q_MIX_WARN),
                                             SUM_Q("norm_error", Q_NORM_ERR),
                                             SUM_Q("b_image_rse", Q_B_IMAGE_RSE),
                                             {0}};

/* A row of stats.csv */
struct stat_row {
    const char *scene, *method, *statistic;
    double mean, se;
    int seeds;
};
static const struct column stat_cols[] = {COL_STRING(struct stat_row, "scene", scene),
                                          COL_STRING(struct stat_row, "method", method),
                                          COL_STRING(struct stat_row, "statistic", statistic),
                                          COL_DOUBLE(struct stat_row, "mean", "%.6g", mean),
                                          COL_DOUBLE(struct stat_row, "se", "%.3g", se),
                                          COL_INT(struct stat_row, "seeds", "%d", seeds),
                                          {0}};

static void save(const struct ch6_equal *e, struct table *t, const char *file)
{
    char path[4200], err[4400];
    snprintf(path, sizeof path, "%s/%s", e->out, file);
    if (!table_save(t, path, err, sizeof err)) die(DIE_RUNTIME, e->prog, "%s", err);
}

static void write_runs(const struct ch6_equal *e)
{
    struct table t;
    FILE *f = table_open(&t, run_cols);
    csv_meta(f, NULL, "ch6_equal: equal-time renders of %s", e->scene);
    csv_meta_commit(f);
    if (e->ref)
        csv_meta(f, "reference", "%s (%d spp BDPT)", e->refpath, e->refspp);
    else
        csv_meta(f, "reference", "none (--reference-spp 0: the image statistics are nan)");
    csv_meta(f, "render args", "%s", e->extra_s);
    csv_meta(f, "min_length", "%d", e->minlen);
    if (e->maxlen) csv_meta(f, "max_length", "%d", e->maxlen);
    csv_meta(f, "relmse eps", "= 0.01 * (reference mean luminance %.6g)^2", e->mlum);
    csv_meta(f, NULL,
             "budgets are separate runs with the same seed (no snapshots), methods interleaved seed by seed; %s",
             e->spp > 0 ? "budget = mutations per pixel (--spp)"
             : e->wall  ? "wall-clock --time"
                        : "--cpu-time: CPU seconds per thread");
    for (int mi = 0; mi < e->nm; mi++)
        if (!e->ms[mi].available) csv_meta(f, "method", "%s not available in this build (skipped)", e->ms[mi].name);
    for (int mi = 0; mi < e->nm; mi++)
        for (int bi = 0; e->ms[mi].available && bi < e->nb; bi++)
            for (int s = 0; s < e->seeds; s++)
                table_row(&t, &(struct run_row){e->name, e->ms[mi].name, e->first_seed + s, e->budgets[bi],
                                                &e->R[mi][bi][s]});
    save(e, &t, "runs.csv");
}

/* summary.csv; the means and errors at the largest budget into e->sum */
static void write_summary(struct ch6_equal *e)
{
    struct table t;
    FILE *f = table_open(&t, summary_cols);
    csv_meta(f, NULL, "mean +- standard error over %d seeds", e->seeds);
    if (e->insets) csv_meta(f, "insets", "%s", e->insets); /* for scripts/ch6-figure.sh */
    for (int mi = 0; mi < e->nm; mi++)
        for (int bi = 0; e->ms[mi].available && bi < e->nb; bi++) {
            struct summary_row row = {e->name, e->ms[mi].name, e->budgets[bi], e->seeds, {0}, {0}};
            for (int q = 0; q < Q_COUNT; q++) {
                double v[CH6_MAX_SEEDS];
                for (int s = 0; s < e->seeds; s++)
                    v[s] = e->R[mi][bi][s].q[q];
                mean_se(v, e->seeds, &row.mean[q], &row.se[q]);
                if (bi == e->nb - 1) e->sum[mi][q][0] = row.mean[q], e->sum[mi][q][1] = row.se[q];
            }
            table_row(&t, &row);
        }
    save(e, &t, "summary.csv");
}

/* stats.csv: one row per method and statistic at the largest budget (bin/check_stats --key
 * scene,method,statistic --count seeds). A statistic undefined in a run (the correlation length of
 * an error without a correlated part) is left out of its mean, and its row out when fewer than two
 * runs define it. */
static void write_stats(const struct ch6_equal *e)
{
    static const struct {
        enum ch6_q q;
        const char *name;
    } st[] = {{Q_RELMSE, "relmse"},
              {Q_RELMSE_SCALED, "relmse_scaled"},
              {Q_BLOCK_MEDIAN, "block_median_relmse"},
              {Q_TRIMMED, "trimmed_relmse"},
              {Q_SPREAD, "block_spread"},
              {Q_BLUR4, "blur4_share"},
              {Q_BLUR8, "blur8_share"},
              {Q_CORRLEN, "corr_length"},
              {Q_NONZERO, "nonzero"},
              {Q_LARGE_NONZERO, "large_nonzero"},
              {Q_NONZERO_CONN, "nonzero_per_connection"},
              {Q_B_RSE, "b_rse"},
              {Q_INSET_SPREAD, "inset_block_spread"},
              {Q_INSET_BLUR8, "inset_blur8_share"},
              {Q_RHAT, "rhat"},
              {Q_STUCK, "stuck_share"},
              {Q_NORM_ERR, "norm_error"},
              {Q_B_IMAGE_RSE, "b_image_rse"}}; /* not ESS per second: it depends on the machine's speed */
    struct table t;
    FILE *f = table_open(&t, stat_cols);
    csv_meta(f, NULL, "ch6_equal: mean +- standard error over %d seeds at the largest budget", e->seeds);
    for (int mi = 0; mi < e->nm; mi++)
        for (size_t k = 0; e->ms[mi].available && k < sizeof st / sizeof *st; k++) {
            double v[CH6_MAX_SEEDS];
            struct stat_row row = {e->name, e->ms[mi].name, st[k].name, 0, 0, 0};
            for (int s = 0; s < e->seeds; s++) {
                double x = e->R[mi][e->nb - 1][s].q[st[k].q];
                if (isfinite(x)) v[row.seeds++] = x;
            }
            if (row.seeds < 2) continue;
            mean_se(v, row.seeds, &row.mean, &row.se);
            table_row(&t, &row);
        }
    save(e, &t, "stats.csv");
}

void ch6_write_tables(struct ch6_equal *e)
{
    write_runs(e);
    write_summary(e);
    write_stats(e);
}
