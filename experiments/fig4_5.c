/* bin/fig4_5: thesis Figure 4.5. Average acceptance probability per path length of MMLT large steps
 * versus multiple correlated-try large steps (MCTLS), both alone (p_large = 1, no small steps),
 * with equal expected mutation budgets per length and the same seeds.
 * Writes OUT/fig4.5.csv: method,length,attempts,mean_accept,stderr,accepted_fraction,seconds
 * (seconds: CPU time spent on that length's proposals). */
#include "cli.h"
#include "mlt.h"
#include "parallel.h"
#include "util.h"
#include "version.h"
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char *usage =
    "usage: fig4_5 [options]\n"
    "  --scene FILE         (default scenes/ajar/scene.json)\n"
    "  --scale quick|paper  budgets (default: $SCALE, else quick)\n"
    "  --mutations N        mutations per method, over all lengths (quick 3000000, paper 100000000)\n"
    "  --max-length K       longest path length (default 12)\n"
    "  --seed S             (default 1)\n"
    "  --threads T          (default: all cores)\n"
    "  --out DIR            (default results/fig4.5)\n";

int main(int argc, char **argv)
{
    const char *prog = "fig4_5", *scene = "scenes/ajar/scene.json", *out = "results/fig4.5";
    const char *scale = getenv("SCALE") && *getenv("SCALE") ? getenv("SCALE") : "quick";
    long mutations = -1;
    int K = 12, threads = cpu_count();
    uint64_t seed = 1;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(o, "--scene")) scene = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--scale")) scale = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--mutations")) mutations = cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, 1L << 40);
        else if (!strcmp(o, "--max-length")) K = (int)cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, MAX_PATH_LENGTH);
        else if (!strcmp(o, "--seed")) seed = cli_u64(prog, o, cli_value(prog, argc, argv, &i));
        else if (!strcmp(o, "--threads")) threads = (int)cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, 1024);
        else if (!strcmp(o, "--out")) out = cli_value(prog, argc, argv, &i);
        else cli_fail(prog, "unknown option '%s' (see --help)", o);
    }
    bool paper = !strcmp(scale, "paper");
    if (!paper && strcmp(scale, "quick")) cli_fail(prog, "--scale: expected quick or paper, got '%s'", scale);
    if (mutations < 0) mutations = paper ? 100000000 : 3000000;
    char err[1024];
    struct scene *sc = scene_load(scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    mkdir(out, 0777);
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    fprintf(f, "# fig4.5: MMLT large steps vs MCTLS, p_large = 1, no small steps, uniform length budgets\n");
    fprintf(f, "# scene %s\n# commit %s\n# scale %s\n# seed %llu\n# threads %d\n# mutations_per_method %ld\n", scene,
            GIT_COMMIT, scale, (unsigned long long)seed, threads, mutations);
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
