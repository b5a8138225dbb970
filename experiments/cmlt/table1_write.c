/* bin/table1_cmlt's tables (table1.h): per (algorithm, budget) the RMSE mean and standard error over
 * seeds, throughput and acceptance (table1.csv, table1_stats.csv: what `make check-table1-cmlt`
 * compares), every seed's row (table1_seeds.csv), the Markdown beside the paper's Table 1, and the
 * first seed's images. */
#include "base/util.h"
#include "cmlt/table1.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/table_set.h"
#include "common/verdict.h"
#include <math.h>
#include <stdio.h>

void table1_save_or_die(bool ok, const char *err)
{
    if (!ok) die(DIE_RUNTIME, "table1_cmlt", "%s", err);
}

const char *table1_fmt_n(uint64_t n, char *buf, size_t len)
{
    if (n % 1000000 == 0)
        snprintf(buf, len, "%lluM", (unsigned long long)(n / 1000000));
    else if (n % 1000 == 0)
        snprintf(buf, len, "%lluk", (unsigned long long)(n / 1000));
    else
        snprintf(buf, len, "%llu", (unsigned long long)n);
    return buf;
}

/* The run's three CSV tables (table1.csv, table1_stats.csv, table1_seeds.csv): the budget n as
 * unsigned (COL_LONG's "%lu"). */
struct mean_row {
    const char *algorithm;
    long n;
    int seeds;
    double rmse, rmse_se, steps_per_s, acceptance, swap_acceptance;
};
struct seed_row {
    const char *algorithm;
    long n;
    int seed;
    double rmse, b, b1, b2, acceptance, swap_acceptance, seconds;
};
static const struct column mean_cols[] = {COL_STRING(struct mean_row, "algorithm", algorithm),
                                          COL_LONG(struct mean_row, "n", "%lu", n),
                                          COL_DOUBLE(struct mean_row, "rmse", "%.6e", rmse),
                                          {0}};
static const struct column stats_cols[] = {COL_STRING(struct mean_row, "algorithm", algorithm),
                                           COL_LONG(struct mean_row, "n", "%lu", n),
                                           COL_INT(struct mean_row, "seeds", "%d", seeds),
                                           COL_DOUBLE(struct mean_row, "rmse_mean", "%.6e", rmse),
                                           COL_DOUBLE(struct mean_row, "rmse_se", "%.6e", rmse_se),
                                           COL_DOUBLE(struct mean_row, "steps_per_s", "%.4g", steps_per_s),
                                           COL_DOUBLE(struct mean_row, "acceptance", "%.4f", acceptance),
                                           COL_DOUBLE(struct mean_row, "swap_acceptance", "%.4f", swap_acceptance),
                                           {0}};
static const struct column seed_cols[] = {COL_STRING(struct seed_row, "algorithm", algorithm),
                                          COL_LONG(struct seed_row, "n", "%lu", n),
                                          COL_INT(struct seed_row, "seed", "%d", seed),
                                          COL_DOUBLE(struct seed_row, "rmse", "%.6e", rmse),
                                          COL_DOUBLE(struct seed_row, "b", "%.6g", b),
                                          COL_DOUBLE(struct seed_row, "b1", "%.6g", b1),
                                          COL_DOUBLE(struct seed_row, "b2", "%.6g", b2),
                                          COL_DOUBLE(struct seed_row, "acceptance", "%.4f", acceptance),
                                          COL_DOUBLE(struct seed_row, "swap_acceptance", "%.4f", swap_acceptance),
                                          COL_DOUBLE(struct seed_row, "seconds", "%.2f", seconds),
                                          {0}};
enum { T_CSV, T_STATS, T_SEEDS, NTABLES };

/* Every seed's row of one (algorithm, budget), in seed order. */
static void seed_rows(const struct table1_pool *p, int a, int b, struct table *seeds)
{
    for (int s = 0; s < p->o->seeds; s++)
        for (int j = 0; j < p->njobs; j++) {
            const struct table1_job *J = &p->jobs[j];
            if (J->algo != a || J->bidx != b || J->seed_idx != s) continue;
            const struct cmlt_stats *st = &J->st;
            table_row(seeds, &(struct seed_row){cmlt_algo_names[a], (long)J->n, s, J->rmse, st->b[0], st->b[1],
                                                st->b[2], st->steps ? st->acc_sum / st->steps : 0,
                                                st->swaps ? st->swap_acc_sum / st->swaps : 0, st->seconds});
        }
}

/* The rows of one (algorithm, budget): every seed's into T_SEEDS, the mean into T_CSV and T_STATS. */
static void analyse_cell(const struct table1_pool *p, int a, int b, struct table1_summary *sm, struct table *t)
{
    double s1 = 0, s2 = 0, steps = 0, secs = 0, acc = 0, swaps = 0, swacc = 0;
    double va[TABLE1_MAX_SEEDS], vr[TABLE1_MAX_SEEDS];
    int m = 0;
    for (int j = 0; j < p->njobs; j++) {
        const struct table1_job *J = &p->jobs[j];
        if (J->algo != a || J->bidx != b) continue;
        va[m] = J->st.steps ? J->st.acc_sum / J->st.steps : NAN;
        vr[m] = J->st.seconds > 0 ? J->st.steps / J->st.seconds : NAN;
        s1 += J->rmse;
        s2 += J->rmse * J->rmse;
        steps += J->st.steps;
        secs += J->st.seconds;
        acc += J->st.acc_sum;
        swaps += J->st.swaps;
        swacc += J->st.swap_acc_sum;
        m++;
    }
    seed_rows(p, a, b, &t[T_SEEDS]);
    sm->mean[b][a] = s1 / m;
    sm->se[b][a] = m > 1 ? sqrt(fmax(0.0, (s2 - s1 * s1 / m) / (m - 1)) / m) : 0;
    mean_se(va, m, &sm->acc[0][b][a], &sm->acc[1][b][a]);
    mean_se(vr, m, &sm->rate[0][b][a], &sm->rate[1][b][a]);
    struct mean_row row = {cmlt_algo_names[a],
                           (long)p->o->budgets[b],
                           m,
                           sm->mean[b][a],
                           sm->se[b][a],
                           secs > 0 ? steps / secs : 0,
                           steps > 0 ? acc / steps : 0,
                           swaps > 0 ? swacc / swaps : 0};
    table_row(&t[T_CSV], &row);
    table_row(&t[T_STATS], &row);
}

/* table1.md: ours (mean ± standard error over seeds) next to the paper's Table 1. */
static void write_markdown(const struct table1_opts *o, const struct table1_summary *sm, double noise_rmse, FILE *md)
{
    static const double paper[2][CMLT_NALGO] = {{8.287e-2, 4.073e-2, 4.106e-2, 3.663e-2, 3.924e-2, 3.502e-2},
                                                {3.212e-2, 1.488e-2, 1.587e-2, 1.405e-2, 1.467e-2, 1.374e-2}};
    char nb[32];
    fprintf(md,
            "RMSE against the reference (mean ± standard error over %d seeds; same total samples n per "
            "algorithm), next to the paper's Table 1 (their toy, one run).\n\n| algorithm |",
            o->seeds);
    for (int b = 0; b < o->nbudgets; b++)
        fprintf(md, " n = %s |", table1_fmt_n(o->budgets[b], nb, sizeof nb));
    fprintf(md, " paper n = 16M | paper n = 128M |\n| --- |");
    for (int b = 0; b < o->nbudgets; b++)
        fprintf(md, " ---: |");
    fprintf(md, " ---: | ---: |\n");
    for (int a = 0; a < CMLT_NALGO; a++) {
        fprintf(md, "| %s |", cmlt_algo_names[a]);
        for (int b = 0; b < o->nbudgets; b++)
            fprintf(md, " %.3e ± %.1e |", sm->mean[b][a], sm->se[b][a]);
        fprintf(md, " %.3e | %.3e |\n", paper[0][a], paper[1][a]);
    }
    fprintf(md, "\nReference: %d spp stratified MC, own noise RMSE ≈ %.2e. Wall time %.1f s on %d threads.%s\n",
            o->ref_spp, noise_rmse, sm->wall, o->threads, sm->partial ? " **PARTIAL: interrupted.**" : "");
}

/* What the tables' metadata line says: the run's settings (table_set_open's ctx). */
struct run_info {
    const struct table1_opts *o;
    const struct table1_summary *sm;
};

/* The metadata line every table opens with. */
static void write_meta(FILE *f, const void *ctx)
{
    const struct table1_opts *o = ((const struct run_info *)ctx)->o;
    const struct table1_summary *sm = ((const struct run_info *)ctx)->sm;
    csv_meta(f, "table1_cmlt",
             "commit=%s seed=%llu scale=%s seeds=%d threads=%d res=%d ref_spp=%d p_large=%g swap_every=%d seed_frac=%g "
             "seconds=%.1f%s",
             o->commit, (unsigned long long)o->seed, o->scale, o->seeds, o->threads, o->res, o->ref_spp, o->p_large,
             o->swap_every, o->seed_frac, sm->wall, sm->partial ? " PARTIAL (interrupted)" : "");
}

void table1_write_tables(const struct table1_pool *p, struct table1_summary *sm, double noise_rmse, struct text_out *md)
{
    const struct table1_opts *o = p->o;
    struct table_set ts;
    table_set_open(&ts, NTABLES, (const char *[]){"table1.csv", "table1_stats.csv", "table1_seeds.csv"},
                   (const struct column *[]){mean_cols, stats_cols, seed_cols}, write_meta, &(struct run_info){o, sm});
    for (int a = 0; a < CMLT_NALGO; a++)
        for (int b = 0; b < o->nbudgets; b++)
            analyse_cell(p, a, b, sm, ts.t);
    if (text_out_open(md)) write_markdown(o, sm, noise_rmse, md->f);
    char path[1024], err[1100];
    table1_save_or_die(table_set_save(&ts, "table1_cmlt", o->out, err, sizeof err), err);
    snprintf(path, sizeof path, "%s/table1.md", o->out);
    table1_save_or_die(text_out_commit(md, path, err, sizeof err), err);
}

bool table1_write_images(const struct table1_pool *p, char *err, size_t errlen)
{
    const struct table1_opts *o = p->o;
    char path[1024], nb[32];
    for (int b = 0; b < o->nbudgets; b++)
        for (int a = 0; a < CMLT_NALGO; a++) {
            struct image im = {.w = o->res, .h = o->res, .px = p->keep[b * CMLT_NALGO + a]};
            const char *ext[2] = {"exr", "png"};
            for (int e = 0; e < 2; e++) {
                snprintf(path, sizeof path, "%s/%s_%s.%s", o->out, cmlt_algo_names[a],
                         table1_fmt_n(o->budgets[b], nb, sizeof nb), ext[e]);
                bool ok = e ? img_write_png(&im, 1.0, path, err, errlen) : img_write_exr(&im, 1.0, path, err, errlen);
                if (!ok) return false;
            }
        }
    return true;
}
