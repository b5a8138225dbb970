/* bin/ch6_tech: do a run's per-technique sample counts follow the per-technique contributions?
 * (MMLT paper §5, Fig. 5; the images of `bin/render --technique-images K`, core/stats/tech_image.h.)
 *
 * A run's own contribution images cannot be the yardstick for MMLT: every MMLT chain sample carries
 * the same luminance (b_k / P(k)), so its contribution images are its sample counts times a constant
 * and would "follow" them by construction. The contributions are therefore taken from other runs:
 * the mean contribution images of the --ref prefixes, leaving out the scored run when it is one of
 * them (leave one out, so that every run of either method is scored against an independent
 * estimate of the same per-technique images, of about the same quality). For each --run prefix, its
 * sample counts against that mean with tech_follow: tv (half the L1 distance of the technique
 * shares) and r (correlation of the within-block shares over B x B blocks). Writes
 * `run,tv,r,cells,references` rows to OUT.csv (atomically). */
#include "base/util.h"
#include "ch6/ch6_claims.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/table.h"
#include "io/image.h"
#include "stats/tech_image.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static struct image *load(const char *prefix, const char *kind, int t, int w, int h)
{
    char path[4200], err[1024];
    snprintf(path, sizeof path, "%.4000s.%s-t%d.exr", prefix, kind, t);
    struct image *im = img_read(path, err, sizeof err);
    if (!im) die(DIE_USAGE, "ch6_tech", "%s", err);
    if (w > 0 && (im->w != w || im->h != h))
        die(DIE_USAGE, "ch6_tech", "%s is %dx%d, expected %dx%d", path, im->w, im->h, w, h);
    return im;
}

/* A row of the output: one run against the mean of the references */
struct follow_row {
    const char *run;
    double tv, r;
    int cells, references;
};
static const struct column follow_cols[] = {COL_STRING(struct follow_row, "run", run),
                                            COL_DOUBLE(struct follow_row, "tv", "%.6g", tv),
                                            COL_DOUBLE(struct follow_row, "r", "%.6g", r),
                                            COL_INT(struct follow_row, "cells", "%d", cells),
                                            COL_INT(struct follow_row, "references", "%d", references),
                                            {0}};

/* The prefixes after --ref (mode 1) and after --run (mode 2), the tables after --follow (mode 3). */
struct prefixes {
    const char **ref, **run, *follow[2];
    int nref, nrun, nfollow, mode;
};

static void prefix_arg(const char *prog, const char *arg, void *ctx)
{
    struct prefixes *p = ctx;
    if (p->mode == 1)
        p->ref[p->nref++] = arg;
    else if (p->mode == 2)
        p->run[p->nrun++] = arg;
    else if (p->mode == 3 && p->nfollow < 2)
        p->follow[p->nfollow++] = arg;
    else
        opts_fail(prog, "'%s': give prefixes after --ref or --run (see --help)", arg);
}

int main(int argc, char **argv)
{
    const char *prog = "ch6_tech", *out = NULL;
    int k = 0, blk;
    const char *claims = NULL, *scale = "custom", *command = "bin/ch6_tech";
    struct prefixes p = {.ref = xcalloc((size_t)argc, sizeof *p.ref), .run = xcalloc((size_t)argc, sizeof *p.run)};
    const struct opt opts[] = {
        {"--k", OPT_INT, OPT_DST(k), .arg = "K", .lo = 1, .hi = MAX_PATH_LENGTH,
         .help = "the path length of the technique images"},
        {"--block", OPT_INT, OPT_DST(blk), .arg = "B", .lo = 1, .hi = 4096, .help = "block size of the correlation",
         .def = "8"},
        {"--out", OPT_STRING, OPT_DST(out), .arg = "OUT.csv", .help = "the rows run,tv,r,cells,references"},
        {"--ref", OPT_FLAG, OPT_DST(p.mode), .value = 1, .help = "the prefixes that follow are references"},
        {"--run", OPT_FLAG, OPT_DST(p.mode), .value = 2, .help = "the prefixes that follow are the runs scored"},
        {"--claims", OPT_STRING, OPT_DST(claims), .arg = "DIR",
         .help = "instead: DIR/claims.csv and claims.md, the MMLT paper's Fig. 5 claim from two earlier --out tables "
                 "given after --follow (MMLT's, then PSSMLT's)"},
        {"--follow", OPT_FLAG, OPT_DST(p.mode), .value = 3, .help = "the two tables that follow (with --claims)"},
        {"--scale", OPT_STRING, OPT_DST(scale), .arg = "NAME", .help = "the scale, for claims.csv"},
        {"--command", OPT_STRING, OPT_DST(command), .arg = "TEXT", .help = "the command that made it, for claims.csv"},
        {0}};
    opts_parse(
        &(struct opts_spec){
            .prog = prog,
            .usage = "usage: ch6_tech --k K --out OUT.csv [--block B] --ref PREFIX... --run PREFIX...\n",
            .about =
                "  PREFIX: a bin/render --technique-images K output prefix (PREFIX.tech-tT.exr, PREFIX.count-tT.exr)\n",
            .opts = opts,
            .positional = prefix_arg,
            .ctx = &p},
        argc, argv);
    if (claims) {
        if (!k || p.nfollow != 2) opts_fail(prog, "--claims needs --k and two tables after --follow (see --help)");
        char err[1024];
        char *md = ch6_tech_claims(&(struct ch6_tech_claims_in){{p.follow[0], p.follow[1]}, claims, scale, command, k},
                                   err, sizeof err);
        if (!md) die(DIE_RUNTIME, prog, "%s", err);
        fputs(md, stdout);
        free(md);
        free(p.ref);
        free(p.run);
        return 0;
    }
    const char **ref = p.ref, **run = p.run;
    int nref = p.nref, nrun = p.nrun;
    if (!k || !out || !nref || !nrun) opts_fail(prog, "--k, --out, --ref and --run are required (see --help)");
    /* the yardstick: the sum of the reference runs' contribution images */
    struct image *first = load(ref[0], "tech", 1, 0, 0), *sum[TECH_MAX] = {0};
    int w = first->w, h = first->h;
    img_destroy(first);
    struct tech_acc a;
    tech_acc_init(&a, k, w, h, false);
    for (int t = 1; t <= k + 1; t++) {
        sum[t] = img_create(w, h);
        for (int i = 0; i < nref; i++) {
            struct image *im = load(ref[i], "tech", t, w, h);
            img_accumulate(sum[t], im, 1.0);
            img_destroy(im);
        }
    }
    struct table tab;
    FILE *f = table_open(&tab, follow_cols);
    csv_meta(f, NULL,
             "ch6_tech: sample counts of each run against the mean contribution of the %d reference runs (leaving out "
             "the run), %dx%d blocks",
             nref, blk, blk);
    for (int i = 0; i < nrun; i++) {
        bool own = false;
        for (int j = 0; j < nref; j++)
            own |= !strcmp(ref[j], run[i]);
        if (own && nref < 2) opts_fail(prog, "%s: the only reference is the run itself", run[i]);
        int nr = nref - own;
        for (int t = 1; t <= k + 1; t++) {
            memset(a.contrib[t]->px, 0, sizeof(double) * 3 * (size_t)w * h);
            img_accumulate(a.contrib[t], sum[t], 1.0 / nr);
            if (own) {
                struct image *im = load(run[i], "tech", t, w, h);
                img_accumulate(a.contrib[t], im, -1.0 / nr);
                img_destroy(im);
            }
            struct image *im = load(run[i], "count", t, w, h);
            for (size_t p = 0; p < (size_t)w * h; p++)
                a.count[t][p] = im->px[3 * p];
            img_destroy(im);
        }
        struct tech_follow fo;
        tech_follow(&a, blk, &fo);
        table_row(&tab, &(struct follow_row){run[i], fo.tv, fo.r, fo.cells, nr});
    }
    char err[1024];
    if (!table_save(&tab, out, err, sizeof err)) die(DIE_RUNTIME, prog, "%s", err);
    tech_acc_free(&a);
    for (int t = 1; t <= k + 1; t++)
        img_destroy(sum[t]);
    free(ref);
    free(run);
    return 0;
}
