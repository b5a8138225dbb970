/* Inverse random walks (thesis Alg. 2): on every committed scene, the numbers written by
 * invert_camera / invert_emitter make the forward walks retrace the same vertices. */
#include <criterion/criterion.h>

#include "path.h"
#include "scenes.h"

/* Fills every slot with fresh numbers: blocks the inversion cannot determine (a direction that
 * left the scene) still replay to something. */
static void prefill(struct sampler_writer *w, rng *r)
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++) w->u[st][i] = rng_uniform(r);
}

static double scene_size(const struct scene *sc) { return fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min))); }

static bool same_prefix(const struct vertex *a, int na, const struct vertex *b, int nb, double tol)
{
    if (nb < na) return false;
    for (int i = 0; i < na; i++)
        if (vlen(vsub(a[i].p, b[i].p)) > tol || a[i].prim != b[i].prim) return false;
    return true;
}

/* 20k camera and 20k emitter walks per scene; >= 99.9 % must retrace (thesis §5.1 tolerance for
 * float geometry); partial inversion of the suffix from vertex 2 must retrace too. */
static void check_scene(const char *path)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct vertex a[MAX_SUBPATH_VERTS], b[MAX_SUBPATH_VERTS];
    static struct sampler_writer w;
    struct sampler_independent ind;
    struct sampler_replay rep;
    rng r;
    rng_seed(&r, 11, 0);
    sampler_writer_init(&w, 5, 0);
    const int N = 20000;
    /* Embree intersects in single precision: each hit is off the exact ray by ~1e-7 of the scene,
     * and grazing bounces in corners amplify that along the walk. */
    double tol = 1e-4 * scene_size(sc);
    for (int kind = 0; kind < 2; kind++) {
        int fail = 0, fail_suffix = 0, tried = 0;
        for (int i = 0; i < N; i++) {
            sampler_independent_init(&ind, 77, (uint64_t)i * 2 + kind);
            int n = kind == 0 ? walk_camera(&pc, &ind.base, a, 9) : walk_emitter(&pc, &ind.base, a, 8);
            if (n < 2) continue;
            tried++;
            prefill(&w, &r);
            bool ok = kind == 0 ? invert_camera(&pc, a, n, 0, &w.base) : invert_emitter(&pc, a, n, 0, &w.base);
            sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
            int m = ok ? (kind == 0 ? walk_camera(&pc, &rep.base, b, 9) : walk_emitter(&pc, &rep.base, b, 8)) : 0;
            if (!ok || !same_prefix(a, n, b, m, tol)) fail++;
            /* suffix only: scramble blocks >= 2 of the stream, re-invert from vertex 2 */
            if (n > 3) {
                int st = kind == 0 ? STREAM_CAMERA : STREAM_EMITTER;
                for (int d = 2 * SAMPLER_BLOCK; d < STREAM_DIMS; d++) w.u[st][d] = rng_uniform(&r);
                ok = kind == 0 ? invert_camera(&pc, a, n, 2, &w.base) : invert_emitter(&pc, a, n, 2, &w.base);
                m = ok ? (kind == 0 ? walk_camera(&pc, &rep.base, b, 9) : walk_emitter(&pc, &rep.base, b, 8)) : 0;
                if (!ok || !same_prefix(a, n, b, m, tol)) fail_suffix++;
            }
        }
        cr_assert(tried > N / 10, "%s: only %d walks of >= 2 vertices", path, tried);
        cr_assert(fail <= tried / 1000, "%s: %s walks: %d of %d did not retrace", path, kind ? "emitter" : "camera", fail, tried);
        cr_assert(fail_suffix <= tried / 1000, "%s: %s suffix inversions: %d of %d failed", path,
                  kind ? "emitter" : "camera", fail_suffix, tried);
    }
    scene_free(sc);
}

Test(path, inverse_walks_retrace_on_every_scene)
{
    const char **s = test_all_scenes();
    cr_assert(s[0], "no scenes found under scenes/");
    for (; *s; s++) check_scene(*s);
}
