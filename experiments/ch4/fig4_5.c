/* bin/fig4_5: thesis Figure 4.5. Average acceptance probability per path length of MMLT large steps
 * versus multiple correlated-try large steps (MCTLS), both alone (p_large = 1, no small steps),
 * with equal expected mutation budgets per length and the same seeds.
 * Writes OUT/fig4.5.csv: method,length,attempts,mean_accept,stderr,accepted_fraction,seconds
 * (seconds: CPU time spent on that length's proposals). */
#include "base/parallel.h"
#include "base/util.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
        }
        mlt_result_free(&r);
    }
    fclose(f);
    char path[4096];
    snprintf(path, sizeof path, "%s/fig4.5.csv", out);
    bool ok = write_text_atomic(path, buf, err, sizeof err);
    free(buf);
    scene_free(sc);
    if (!ok) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    fprintf(stderr, "fig4.5: wrote %s\n", path);
    return 0;
}
