/* bin/fig6_1: thesis Figure 6.1. Average acceptance probability of small steps per path length for
 * MMLT and for MMLT with the path-invariant technique perturbation (PITP), each split into small
 * steps whose proposal uses a different technique than the chain had before the iteration (for
 * PITP: before the perturbation) and those that do not. p_large = 0.1, the same seed for both,
 * equal expected mutations per length (acceptance is a property of each length's chain).
 * The budget is split over 4 independent runs; each also runs a pass of lengths 1-6 only (1.5x the
 * budget), where MMLT's technique changes are otherwise too rare for a cell or near its threshold
 * (about 1.5 % of its small steps at length 2). Writes OUT/fig6.1.csv:
 * method,length,technique_changed,attempts,mean_accept,stderr,accepted_fraction,runs,run_se
 * (stderr: batch-means over the merged runs; run_se: standard error of the runs' means; cells with
 * fewer than 16000 proposals are left out), and OUT/fig6.1-pitp.csv: per length, PITP's perturbations, the fraction
 * with j != i, the inversion failures and the mean |j - i|; OUT/fig6.1-mixing.csv: each run's chains'
 * mixing diagnostics per length (common/mixing_runs.h; a warning on stderr as bin/render's); and OUT/claims.csv,
 * OUT/claims.md: the thesis's claims on Fig. 6.1 decided from the runs' means and their standard error over the runs
 * (fig6_1_claims.c).
 */
#include "base/parallel.h"
#include "base/util.h"
#include "ch6/fig6_1_claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/mixing_runs.h"
#include "common/opts.h"
#include "common/table_set.h"
#include "common/verdict.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { RUNS = FIG6_1_RUNS };   /* independent runs per method */
enum { MIN_ATTEMPTS = 16000 }; /* proposals a cell needs to be written */
enum { SHORT_MAX = 6 };        /* the short pass: lengths 1..SHORT_MAX */

/* fig6.1.csv: a row per method, length and technique change */
struct accept_row {
    const char *method;
    int length;
    const char *changed;
    long attempts;
    double mean, se, accepted;
    int runs;
    double run_se;
};
static const struct column accept_cols[] = {COL_STRING(struct accept_row, "method", method),
                                            COL_INT(struct accept_row, "length", "%d", length),
                                            COL_STRING(struct accept_row, "technique_changed", changed),
                                            COL_LONG(struct accept_row, "attempts", "%ld", attempts),
                                            COL_DOUBLE(struct accept_row, "mean_accept", "%.9g", mean),
                                            COL_DOUBLE(struct accept_row, "stderr", "%.9g", se),
                                            COL_DOUBLE(struct accept_row, "accepted_fraction", "%.9g", accepted),
                                            COL_INT(struct accept_row, "runs", "%d", runs),
                                            COL_DOUBLE(struct accept_row, "run_se", "%.9g", run_se),
                                            {0}};
/* fig6.1-pitp.csv: PITP's perturbations per length */
struct pitp_row {
    int length;
    long perturbations;
    double changed;
    long failures;
    double failure_fraction, dtech;
};
static const struct column pitp_cols[] = {COL_INT(struct pitp_row, "length", "%d", length),
                                          COL_LONG(struct pitp_row, "perturbations", "%ld", perturbations),
                                          COL_DOUBLE(struct pitp_row, "changed_fraction", "%.9g", changed),
                                          COL_LONG(struct pitp_row, "failures", "%ld", failures),
                                          COL_DOUBLE(struct pitp_row, "failure_fraction", "%.9g", failure_fraction),
                                          COL_DOUBLE(struct pitp_row, "mean_dtech", "%.9g", dtech),
                                          {0}};

/* The metadata lines of every table. */
static void write_meta(FILE *f, const void *ctx)
{
    const struct opts_accept *a = ctx;
    csv_meta_head(f, "fig6.1: small-step acceptance, MMLT vs PITP, p_large = 0.1, uniform length budgets", a->fig.scene,
                  a->fig.scale);
    csv_meta(f, "seed", "%llu", (unsigned long long)a->fig.seed);
    csv_meta(f, "threads", "%d", a->fig.threads);
    csv_meta(f, "mutations_per_method", "%ld", a->mutations);
    csv_meta(f, "short_pass_mutations_per_method", "%ld (lengths 1..%d)", 3 * a->mutations / 2, SHORT_MAX);
    csv_meta(f, "seed_paths", "%ld", a->fig.paper ? 1000000L : 100000L);
}

static const char *const names[2] = {"mmlt", "pitp"};

/* Method m's RUNS independent runs (seeds seed * 1000 + r, each with its own seed pass), each
 * merged into run[r] and all: a chain that rarely changes technique keeps its acceptance level for
 * longer than a batch, so the batch-means error (plotted, as the thesis does) understates the
 * run-to-run scatter, which run_se (over the runs' means) measures for check-fig6.1. Each run is
 * the main pass, then the short one (its own seed and seed pass; a length's chain does not depend
 * on the longest length, so the two merge). Each run's mixing diagnostics into mx. False with a
 * message in err. */
static bool run_method(const struct scene *sc, const struct opts_accept *a, int m, struct mlt_stats *all,
                       struct mlt_stats run[RUNS], struct mixing_runs *mx, char *err, size_t errlen)
{
    stats_clear(all);
    for (int rr = 0; rr < RUNS; rr++) {
        stats_clear(&run[rr]);
        for (int pass = 0; pass < 2 && (pass == 0 || a->max_length > SHORT_MAX); pass++) {
            int kmax = pass ? SHORT_MAX : a->max_length;
            struct mlt_opts o = {.method = m ? MLT_PITP : MLT_MMLT,
                                 .p_large = 0.1,
                                 .pitp_rate = 1,
                                 .mutations = (pass ? 3 * a->mutations / 2 : a->mutations) / RUNS,
                                 .seed_paths = a->fig.paper ? 1000000 : 100000,
                                 .seed = a->fig.seed * 1000 + (uint64_t)rr + (pass ? 500 : 0),
                                 .threads = a->fig.threads,
                                 .max_length = kmax,
                                 .progress = isatty(2),
                                 .large_step = LARGE_MMLT,
                                 .uniform_lengths = true};
            pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
            fprintf(stderr, "fig6.1: %s run %d of %d, %ld mutations over lengths 1..%d\n", names[m], rr + 1, RUNS,
                    o.mutations, kmax);
            struct mlt_result r;
            if (!mlt_render(sc, &o, &r, err, errlen)) return false;
            char label[64];
            snprintf(label, sizeof label, "%s run %d%s", names[m], rr + 1, pass ? " short" : "");
            mixing_runs_add(mx, label, &r, r.seconds);
            stats_merge(&run[rr], &r.stats);
            stats_merge(all, &r.stats);
            mlt_result_free(&r);
        }
    }
    return true;
}

/* PITP's perturbations at length k over the runs: the share that change the technique and the mean
 * |j - i| of those that change it, their means over the runs and standard errors (cells->moves). */
static void pitp_moves(const struct mlt_stats run[RUNS], int k, struct fig6_1_cells *cells)
{
    double v[3][RUNS];
    int n = 0;
    for (int rr = 0; rr < RUNS; rr++) {
        const struct accept_cell *p = &run[rr].any[PROPOSAL_PITP][k];
        if (!p->attempts) continue;
        long changed = run[rr].cell[PROPOSAL_PITP][k][1].attempts;
        if (!changed) continue;
        v[0][n] = (double)changed / p->attempts;
        v[2][n] = cell_mean(p);
        v[1][n++] = p->sum_dtech / changed; /* |j - i| is 0 when the technique stays */
    }
    if (n < 2) return;
    for (int q = 0; q < 3; q++)
        mean_se(v[q], n, &cells->moves[q][k][0], &cells->moves[q][k][1]);
}

/* Method m's rows of both tables, and its cells for the claims. Cells of fewer than MIN_ATTEMPTS
 * proposals are left out: their errors rest on a few batches, and near the threshold a cell would
 * be there at one seed and not at the next (MMLT's technique changes at lengths 2-3 on ajar:
 * 0.3-14k proposals). */
static void method_rows(int m, const struct mlt_stats *all, const struct mlt_stats run[RUNS],
                        struct fig6_1_cells *cells, struct table_set *ts)
{
    for (int k = 1; k <= cells->K; k++) {
        for (int ch = 0; ch < 2; ch++) {
            const struct accept_cell *c = &all->cell[PROPOSAL_SMALL][k][ch];
            double s1 = 0, s2 = 0;
            int n = 0;
            for (int rr = 0; rr < RUNS; rr++) {
                const struct accept_cell *q = &run[rr].cell[PROPOSAL_SMALL][k][ch];
                if (!q->attempts) continue;
                s1 += cell_mean(q);
                s2 += cell_mean(q) * cell_mean(q);
                n++;
            }
            if (c->attempts < MIN_ATTEMPTS || c->nbatches < 2 || n < 2) continue;
            double rm = s1 / n, run_se = sqrt(fmax(0, (s2 - n * rm * rm) / (n - 1)) / n);
            cells->mean[m][k][ch] = rm;
            cells->se[m][k][ch] = run_se;
            cells->have[m][k][ch] = true;
            table_row(&ts->t[0], &(struct accept_row){names[m], k, ch ? "yes" : "no", c->attempts, cell_mean(c),
                                                      cell_stderr(c), (double)c->accepted / c->attempts, n, run_se});
        }
        const struct accept_cell *p = &all->any[PROPOSAL_PITP][k];
        if (m) pitp_moves(run, k, cells);
        if (m && p->attempts)
            table_row(&ts->t[1],
                      &(struct pitp_row){k, p->attempts, (double)all->cell[PROPOSAL_PITP][k][1].attempts / p->attempts,
                                         p->failed, (double)p->failed / p->attempts, p->sum_dtech / p->attempts});
    }
}

int main(int argc, char **argv)
{
    struct opts_accept a;
    struct scene *sc =
        opts_accept_parse(&a, "fig6_1", "scenes/ajar/scene.json", "results/fig6.1", "8000000", "100000000", argc, argv);
    char err[4200];
    struct table_set ts;
    table_set_open(&ts, 2, (const char *[]){"fig6.1.csv", "fig6.1-pitp.csv"},
                   (const struct column *[]){accept_cols, pitp_cols}, write_meta, &a);
    static struct fig6_1_cells cells;
    static struct mlt_stats all, run[RUNS];
    cells.K = a.max_length;
    struct mixing_runs mx;
    FILE *mf = mixing_runs_open(&mx, "fig6_1", "fig6.1-mixing.csv");
    write_meta(mf, &a);
    for (int m = 0; m < 2; m++) {
        if (!run_method(sc, &a, m, &all, run, &mx, err, sizeof err)) die(DIE_RUNTIME, "fig6_1", "%s", err);
        method_rows(m, &all, run, &cells, &ts);
    }
    if (!table_set_save(&ts, "fig6_1", a.fig.out, err, sizeof err) ||
        !mixing_runs_save(&mx, a.fig.out, err, sizeof err))
        die(DIE_RUNTIME, "fig6_1", "%s", err);
    char *md = fig6_1_claims(&cells, a.fig.out, a.fig.scale, err, sizeof err);
    if (!md) die(DIE_RUNTIME, "fig6_1", "%s", err);
    free(md);
    scene_free(sc);
    return 0;
}
