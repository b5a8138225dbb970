/* bin/fig4_5: thesis Figure 4.5. Average acceptance probability per path length of MMLT large steps
 * versus multiple correlated-try large steps (MCTLS), both alone (p_large = 1, no small steps),
 * with equal expected mutation budgets per length and the same seeds.
 * Writes OUT/fig4.5.csv: method,length,attempts,mean_accept,stderr,accepted_fraction,seconds
 * (seconds: CPU time spent on that length's proposals), and OUT/claims.csv and claims.md: the
 * thesis's statements on the figure (§4.3) with their verdicts. */
#include "base/parallel.h"
#include "base/util.h"
#include "common/claims.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <math.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Mean acceptance and its batch-means standard error per method and length. */
struct accept_table {
    double mean[2][MAX_PATH_LENGTH + 1], se[2][MAX_PATH_LENGTH + 1];
    int K;
};

/* The ratio MCTLS / MMLT at length k and its standard error (first-order). */
static void ratio_at(const struct accept_table *t, int k, double *r, double *se)
{
    *r = t->mean[1][k] / t->mean[0][k];
    *se = *r * sqrt(pow(t->se[1][k] / t->mean[1][k], 2) + pow(t->se[0][k] / t->mean[0][k], 2));
}

/* Thesis §4.3 on Figure 4.5. The errors are one run's batch-means errors, so "seeds_needed" counts
 * runs of this budget. */
static char *claims(const struct accept_table *t, const char *out, const char *scale, char *err, size_t errlen)
{
    struct claims cl;
    char command[64], zs[256], md[512];
    snprintf(command, sizeof command, "make fig4.5 SCALE=%s", scale);
    claims_begin(&cl, scale, command, "Claims of thesis §4.3 on Fig. 4.5, lengths 2-%d (batch-means errors of one run)", t->K);
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
    claims_row(&cl, "thesis §4.3", "MCTLS is accepted more often than MMLT large steps at every length",
               "mean acceptance per length", "mctls", t->mean[1][at], t->se[1][at], zs, md, &worst);
    double r, rse;
    ratio_at(t, t->K, &r, &rse);
    struct verdict v = verdict_similar(r, rse, 5, 0, 0.25, 1);
    snprintf(zs, sizeof zs, "5x=%.2f", v.zmin);
    snprintf(md, sizeof md, "5 within ±25 %% at length %d (z = %.1f)", t->K, v.zmin);
    claims_row(&cl, "thesis §4.3", "MCTLS is up to five times more likely to be accepted at the longest length",
               "acceptance ratio MCTLS / MMLT", "mctls", r, rse, zs, md, &v);
    ratio_at(t, 2, &r, &rse);
    v = verdict_similar(r, rse, 1, 0, 0.25, 1);
    snprintf(zs, sizeof zs, "1x=%.2f", v.zmin);
    snprintf(md, sizeof md, "1 within ±25 %% at length 2 (z = %.1f)", v.zmin);
    claims_row(&cl, "thesis §4.3", "MCTLS is rejected about as often as MMLT large steps for short paths",
               "acceptance ratio MCTLS / MMLT at length 2", "mctls", r, rse, zs, md, &v);
    v = verdict_similar(t->mean[0][t->K], t->se[0][t->K], t->mean[0][2], t->se[0][2], 0.25, 1);
    snprintf(zs, sizeof zs, "length2=%.2f", v.zmin);
    snprintf(md, sizeof md, "length 2: %.4g ± %.2g, within ±25 %% (z = %.1f)", t->mean[0][2], t->se[0][2], v.zmin);
    char stat[64];
    snprintf(stat, sizeof stat, "MMLT large-step acceptance at length %d", t->K);
    claims_row(&cl, "thesis §4.3", "MMLT large steps are consistently low over all path lengths", stat, "mmlt-large",
               t->mean[0][t->K], t->se[0][t->K], zs, md, &v);
    return claims_finish(&cl, out, err, errlen);
}

int main(int argc, char **argv)
{
    struct opts_accept a;
    struct scene *sc = opts_accept_parse(&a, "fig4_5", "scenes/ajar/scene.json", "results/fig4.5", "3000000", "100000000",
                                         argc, argv);
    const char *out = a.fig.out;
    bool paper = a.fig.paper;
    long mutations = a.mutations;
    int K = a.max_length, threads = a.fig.threads;
    uint64_t seed = a.fig.seed;
    char err[1024];
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    csv_meta_head(f, "fig4.5: MMLT large steps vs MCTLS, p_large = 1, no small steps, uniform length budgets", a.fig.scene,
                  a.fig.scale);
    csv_meta(f, "seed", "%llu", (unsigned long long)seed);
    csv_meta(f, "threads", "%d", threads);
    csv_meta(f, "mutations_per_method", "%ld", mutations);
    fprintf(f, "method,length,attempts,mean_accept,stderr,accepted_fraction,seconds\n");
    const char *names[2] = {"mmlt-large", "mctls"};
    struct accept_table tab = {.K = K};
    for (int m = 0; m < 2; m++) {
        struct mlt_opts o = {.method = MLT_MMLT, .p_large = 1, .mutations = mutations, .seed_paths = paper ? 1000000 : 100000,
                             .seed = seed, .threads = threads, .max_length = K, .progress = isatty(2),
                             .large_step = m ? LARGE_MCTLS : LARGE_MMLT, .uniform_lengths = true, .time_proposals = true};
        pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
        fprintf(stderr, "fig4.5: %s, %ld mutations over lengths 1..%d\n", names[m], mutations, K);
        struct mlt_result r;
        if (!mlt_render(sc, &o, &r, err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        enum proposal_kind kind = m ? PROPOSAL_MCTLS : PROPOSAL_LARGE;
        for (int k = 1; k <= K; k++) {
            /* both technique outcomes together: the figure plots all large steps of a length */
            const struct accept_cell *c = &r.stats.any[kind][k];
            if (!c->attempts) continue;
            fprintf(f, "%s,%d,%ld,%.9g,%.9g,%.9g,%.4f\n", names[m], k, c->attempts, cell_mean(c), cell_stderr(c),
                    (double)c->accepted / c->attempts, c->seconds);
            tab.mean[m][k] = cell_mean(c), tab.se[m][k] = cell_stderr(c);
        }
        mlt_result_free(&r);
    }
    fclose(f);
    char path[4096];
    snprintf(path, sizeof path, "%s/fig4.5.csv", out);
    bool ok = write_text_atomic(path, buf, err, sizeof err);
    free(buf);
    char *md = ok ? claims(&tab, out, a.fig.scale, err, sizeof err) : NULL;
    ok = ok && md;
    if (md) fputs(md, stderr);
    free(md);
    scene_free(sc);
    if (!ok) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    fprintf(stderr, "fig4.5: wrote %s\n", path);
    return 0;
}
