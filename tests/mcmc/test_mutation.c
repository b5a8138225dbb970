/* The registry of mutations (mcmc/mutation.h): a mutation registered with one line (the toy of
 * toy_mutation.c) runs in real chains, has its statistics rows, and the built-in ones are
 * unchanged beside it. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "mcmc/mlt_options.h"
#include "mcmc/mutation.h"
#include "path/scene_ready.h"
#include "support/scenes.h"
#include <stdlib.h>
#include <string.h>

extern const struct mutation mutation_toy;
extern int toy_kind;

static void run(struct scene *sc, enum mlt_method m, struct mlt_result *r)
{
    struct mlt_opts o;
    mlt_opts_defaults(&o);
    o.method = m;
    o.mutations = 40000;
    o.seed_paths = 5000;
    o.threads = 2;
    o.max_length = 5;
    o.seed = 3;
    pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
    char err[256];
    cr_assert(mlt_render(sc, &o, r, err, sizeof err), "%s", err);
}

/* Criterion runs each test in its own process: the registration stays in this one. */
Test(mutation, a_registered_mutation_runs_and_has_its_row)
{
    toy_kind = mutation_register(&mutation_toy); /* the one line */
    cr_assert_geq(toy_kind, PROPOSAL_BUILTIN);
    struct scene *sc = test_scene("scenes/cornell-box/scene.json");
    camera_resize(&sc->cam, 32, 32);
    for (enum mlt_method m = MLT_PSSMLT; m <= MLT_PITP; m++) {
        struct mlt_result r;
        run(sc, m, &r);
        const struct mlt_stats *st = &r.stats;
        long toy = st->total[toy_kind].attempts, small = st->total[PROPOSAL_SMALL].attempts,
             large = st->total[PROPOSAL_LARGE].attempts + st->total[PROPOSAL_MCTLS].attempts;
        /* one iteration in eight of those that draw a small step, over both threads */
        cr_expect_eq(toy + small + large, r.mutations);
        cr_expect(toy > (toy + small) / 10 && toy < (toy + small) / 6, "toy %ld of %ld small", toy, toy + small);
        cr_expect_gt(st->total[toy_kind].accepted, 0);
        if (m == MLT_PITP) /* the perturbation precedes the small steps only: the toy replaced it */
            cr_expect_eq(st->total[PROPOSAL_PITP].attempts, small);
        char *csv = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&csv, &len);
        stats_write_csv(f, "m", st, true);
        fclose(f);
        cr_expect(strstr(csv, "\nm,toy,total,any,"), "no toy row in\n%s", csv);
        free(csv);
        mlt_result_free(&r);
    }
    scene_free(sc);
}
