/* MCMC on a scene without an emitter: mlt_render fails with a message that says so, for every tool
 * that calls it, rather than blaming the size of the seed pass. */
#include <criterion/criterion.h>

#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "support/scenes.h"
#include <string.h>

Test(mlt, no_emitter_is_named_as_the_cause)
{
    struct scene *sc = test_scene("tests/data/no-emitter.json");
    enum mlt_method methods[] = {MLT_PSSMLT, MLT_MMLT};
    for (int i = 0; i < 2; i++) {
        struct mlt_opts o = {.method = methods[i],
                             .p_large = 0.1,
                             .mutations = 1000,
                             .seed_paths = 1000,
                             .threads = 1,
                             .max_length = 4,
                             .seed = 1};
        pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
        struct mlt_result r;
        char err[256] = "";
        cr_assert(!mlt_render(sc, &o, &r, err, sizeof err), "method %d rendered a scene without emitters", i);
        cr_assert(strstr(err, "no emitter") && strstr(err, "no-emitter.json") && !strstr(err, "seed pass"),
                  "method %d: %s", i, err);
    }
    scene_free(sc);
}
