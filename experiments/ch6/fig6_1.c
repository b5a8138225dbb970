/* bin/fig6_1: thesis Figure 6.1. Average acceptance probability of small steps per path length for
 * MMLT and for MMLT with the path-invariant technique perturbation (PITP), each split into small
 * steps whose proposal uses a different technique than the chain had before the iteration (for
 * PITP: before the perturbation) and those that do not. p_large = 0.1, the same seed for both,
 * equal expected mutations per length (acceptance is a property of each length's chain).
 * The budget is split over 4 independent runs. Writes OUT/fig6.1.csv:
 * method,length,technique_changed,attempts,mean_accept,stderr,accepted_fraction,runs,run_se
 * (stderr: batch-means over the merged runs; run_se: standard error of the runs' means; cells with
 * fewer than 16000 proposals are left out), and OUT/fig6.1-pitp.csv: per length, PITP's perturbations, the fraction with j != i, the
 * inversion failures and the mean |j - i|. */
#include "base/parallel.h"
#include "base/util.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <unistd.h>

enum { RUNS = 4 };              /* independent runs per method */
enum { MIN_ATTEMPTS = 16000 };  /* proposals a cell needs to be written */

static bool write_file(const char *dir, const char *name, const char *text)
{
    char path[4096], err[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (!write_text_atomic(path, text, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    fprintf(stderr, "fig6.1: wrote %s\n", path);
    return true;
}

int main(int argc, char **argv)
{
    struct opts_accept a;
    struct scene *sc = opts_accept_parse(&a, "fig6_1", "scenes/ajar/scene.json", "results/fig6.1", "8000000", "100000000",
                                         argc, argv);
    bool paper = a.fig.paper;
    long mutations = a.mutations;
    int K = a.max_length, threads = a.fig.threads;
    uint64_t seed = a.fig.seed;
    char err[1024];
    char *buf = NULL, *pbuf = NULL;
    size_t len = 0, plen = 0;
    FILE *f = open_memstream(&buf, &len), *pf = open_memstream(&pbuf, &plen);
    const char *head = "fig6.1: small-step acceptance, MMLT vs PITP, p_large = 0.1, uniform length budgets";
    for (int q = 0; q < 2; q++) {
        FILE *g = q ? pf : f;
        csv_meta_head(g, head, a.fig.scene, a.fig.scale);
        csv_meta(g, "seed", "%llu", (unsigned long long)seed);
        csv_meta(g, "threads", "%d", threads);
        csv_meta(g, "mutations_per_method", "%ld", mutations);
        csv_meta(g, "seed_paths", "%ld", paper ? 1000000L : 100000L);
    }
    fprintf(f, "method,length,technique_changed,attempts,mean_accept,stderr,accepted_fraction,runs,run_se\n");
    fprintf(pf, "length,perturbations,changed_fraction,failures,failure_fraction,mean_dtech\n");
    const char *names[2] = {"mmlt", "pitp"};
    for (int m = 0; m < 2; m++) {
        /* R independent runs (seeds seed * 1000 + r, each with its own seed pass), merged: a chain
         * that rarely changes technique keeps its acceptance level for longer than a batch, so the
         * batch-means error (plotted, as the thesis does) understates the run-to-run scatter, which
         * run_se (over the runs' means) measures for check-fig6.1. */
        static struct mlt_stats all, run[RUNS];
        stats_clear(&all);
        for (int rr = 0; rr < RUNS; rr++) {
            struct mlt_opts o = {.method = m ? MLT_PITP : MLT_MMLT, .p_large = 0.1, .mutations = mutations / RUNS,
                                 .seed_paths = paper ? 1000000 : 100000, .seed = seed * 1000 + (uint64_t)rr,
                                 .threads = threads, .max_length = K, .progress = isatty(2), .large_step = LARGE_MMLT,
                                 .uniform_lengths = true};
            pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
            fprintf(stderr, "fig6.1: %s run %d of %d, %ld mutations over lengths 1..%d\n", names[m], rr + 1, RUNS,
                    o.mutations, K);
            struct mlt_result r;
            if (!mlt_render(sc, &o, &r, err, sizeof err)) {
                fprintf(stderr, "%s\n", err);
                return 1;
            }
            run[rr] = r.stats;
            stats_merge(&all, &r.stats);
            mlt_result_free(&r);
        }
        for (int k = 1; k <= K; k++) {
            for (int ch = 0; ch < 2; ch++) {
                const struct accept_cell *c = &all.cell[PROPOSAL_SMALL][k][ch];
                double s1 = 0, s2 = 0;
                int n = 0;
                for (int rr = 0; rr < RUNS; rr++) {
                    const struct accept_cell *q = &run[rr].cell[PROPOSAL_SMALL][k][ch];
                    if (!q->attempts) continue;
                    s1 += cell_mean(q);
                    s2 += cell_mean(q) * cell_mean(q);
                    n++;
                }
                /* Cells of fewer than MIN_ATTEMPTS proposals are left out: their errors rest on a
                 * few batches, and near the threshold a cell would be there at one seed and not at
                 * the next (MMLT's technique changes at lengths 2-3 on ajar: 0.3-14k proposals) */
                if (c->attempts < MIN_ATTEMPTS || c->nbatches < 2 || n < 2) continue;
                double rm = s1 / n, run_se = sqrt(fmax(0, (s2 - n * rm * rm) / (n - 1)) / n);
                fprintf(f, "%s,%d,%s,%ld,%.9g,%.9g,%.9g,%d,%.9g\n", names[m], k, ch ? "yes" : "no", c->attempts,
                        cell_mean(c), cell_stderr(c), (double)c->accepted / c->attempts, n, run_se);
            }
            const struct accept_cell *p = &all.any[PROPOSAL_PITP][k];
            if (m && p->attempts)
                fprintf(pf, "%d,%ld,%.9g,%ld,%.9g,%.9g\n", k, p->attempts,
                        (double)all.cell[PROPOSAL_PITP][k][1].attempts / p->attempts, p->failed,
                        (double)p->failed / p->attempts, p->sum_dtech / p->attempts);
        }
    }
    fclose(f);
    fclose(pf);
    bool ok = write_file(a.fig.out, "fig6.1.csv", buf) && write_file(a.fig.out, "fig6.1-pitp.csv", pbuf);
    free(buf);
    free(pbuf);
    scene_free(sc);
    return ok ? 0 : 1;
}
