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

/* Every per-run quantity (ch6_claims.h), in the tables' column order: its name, its format in
 * runs.csv, and whether stats.csv (make check-fig6.N) holds it: not the quantities that depend on
 * the machine's speed or count the run's work (mutations, their rate, ESS per second, the mixing
 * warning). A quantity is added here once; the three tables follow. */
static const struct quantity {
    enum ch6_q q;
    const char *name, *fmt;
    bool checked;
} quantities[] = {
    {Q_MUTATIONS, "mutations", "%.0f", false},
    {Q_MPS, "mutations_per_s", "%.0f", false},
    {Q_RELMSE, "relmse", "%.6g", true},
    {Q_SPREAD, "block_spread", "%.6g", true},
    {Q_NONZERO, "nonzero", "%.6g", true},
    {Q_LARGE_NONZERO, "large_nonzero", "%.6g", true},
    {Q_BLOCK_MEDIAN, "block_median_relmse", "%.6g", true},
    {Q_TRIMMED, "trimmed_relmse", "%.6g", true},
    {Q_BLUR4, "blur4_share", "%.6g", true},
    {Q_BLUR8, "blur8_share", "%.6g", true},
    {Q_CORRLEN, "corr_length", "%.6g", true},
    {Q_NONZERO_CONN, "nonzero_per_connection", "%.6g", true},
    {Q_RELMSE_SCALED, "relmse_scaled", "%.6g", true},
    {Q_B_RSE, "b_rse", "%.6g", true},
    {Q_INSET_SPREAD, "inset_block_spread", "%.6g", true},
    {Q_INSET_BLUR8, "inset_blur8_share", "%.6g", true},
    {Q_RHAT, "rhat", "%.4g", true},
    {Q_ESS_PER_S, "ess_per_s", "%.4g", false},
    {Q_STUCK, "stuck_share", "%.4g", true},
    {Q_MIX_WARN, "mixing_warning", "%.0f", false},
    {Q_NORM_ERR, "norm_error", "%.6g", true},
    {Q_B_IMAGE_RSE, "b_image_rse", "%.6g", true},
    {Q_BLOCK_MAX, "block_max_log10_relmse", "%.6g", true},
    {Q_GLOSSY_RELMSE, "glossy_relmse", "%.6g", true},
    {Q_GLOSSY_BLUR8, "glossy_blur8_share", "%.6g", true},
    {Q_GLOSSY_RATIO, "glossy_log10_relmse_ratio", "%.6g", true},
};
enum { NQ = sizeof quantities / sizeof *quantities };
_Static_assert((int)NQ == (int)Q_COUNT, "every quantity of enum ch6_q has a column");

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

/* A row of summary.csv: each quantity's mean and its standard error over seeds */
struct summary_row {
    const char *scene, *method;
    double budget;
    int seeds;
    double mean[Q_COUNT], se[Q_COUNT];
};
static double sum_mean(const void *row, int q) { return ((const struct summary_row *)row)->mean[q]; }
static double sum_se(const void *row, int q) { return ((const struct summary_row *)row)->se[q]; }

/* The column lists of runs.csv and summary.csv: their leading columns, then one (runs) or two
 * (summary: the mean and "_se") per quantity; the "_se" columns' names are kept in se_names. */
struct ch6_columns {
    struct column run[5 + NQ + 1], summary[4 + 2 * NQ + 1]; /* each ends with {0} */
    char se_names[NQ][48];
};
static void build_columns(struct ch6_columns *c)
{
    *c = (struct ch6_columns){0};
    const struct column run_head[] = {
        COL_STRING(struct run_row, "scene", scene), COL_STRING(struct run_row, "method", method),
        COL_INT(struct run_row, "seed", "%d", seed), COL_DOUBLE(struct run_row, "budget", "%g", budget),
        COL_COMPUTED("seconds", "%.3f", run_seconds, 0)};
    const struct column sum_head[] = {
        COL_STRING(struct summary_row, "scene", scene), COL_STRING(struct summary_row, "method", method),
        COL_DOUBLE(struct summary_row, "budget", "%g", budget), COL_INT(struct summary_row, "seeds", "%d", seeds)};
    int nr = 0, ns = 0;
    for (size_t i = 0; i < sizeof run_head / sizeof *run_head; i++)
        c->run[nr++] = run_head[i];
    for (size_t i = 0; i < sizeof sum_head / sizeof *sum_head; i++)
        c->summary[ns++] = sum_head[i];
    for (int i = 0; i < NQ; i++) {
        const struct quantity *k = &quantities[i];
        snprintf(c->se_names[i], sizeof c->se_names[i], "%s_se", k->name);
        c->run[nr++] = (struct column)COL_COMPUTED(k->name, k->fmt, run_q, k->q);
        c->summary[ns++] = (struct column)COL_COMPUTED(k->name, "%.6g", sum_mean, k->q);
        c->summary[ns++] = (struct column)COL_COMPUTED(c->se_names[i], "%.3g", sum_se, k->q);
    }
}

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

static void write_runs(const struct ch6_equal *e, const struct column *cols)
{
    struct table t;
    FILE *f = table_open(&t, cols);
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
static void write_summary(struct ch6_equal *e, const struct column *cols)
{
    struct table t;
    FILE *f = table_open(&t, cols);
    csv_meta(f, NULL, "mean +- standard error over %d seeds", e->seeds);
    if (e->insets) csv_meta(f, "insets", "%s", e->insets); /* for scripts/ch6-figure.sh */
    if (e->insets && e->named_inset)
        csv_meta(f, "named_inset", "%d (the inset statistics are its own)", e->named_inset);
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
    struct table t;
    FILE *f = table_open(&t, stat_cols);
    csv_meta(f, NULL, "ch6_equal: mean +- standard error over %d seeds at the largest budget", e->seeds);
    for (int mi = 0; mi < e->nm; mi++)
        for (int k = 0; e->ms[mi].available && k < NQ; k++) {
            if (!quantities[k].checked) continue;
            double v[CH6_MAX_SEEDS];
            struct stat_row row = {e->name, e->ms[mi].name, quantities[k].name, 0, 0, 0};
            for (int s = 0; s < e->seeds; s++) {
                double x = e->R[mi][e->nb - 1][s].q[quantities[k].q];
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
    struct ch6_columns cols;
    build_columns(&cols);
    write_runs(e, cols.run);
    write_summary(e, cols.summary);
    write_stats(e);
}
