/* Inverse random walks (thesis Alg. 2): on every committed scene and under each of Embree's
 * instruction sets, the numbers written by invert_camera / invert_emitter make the forward walks
 * retrace the same vertices. */
#include <criterion/criterion.h>
#include <string.h>

#include "path/path.h"
#include "path/scene_ready.h"
#include "support/isa.h"
#include "support/scenes.h"

/* Fills every slot with fresh numbers: blocks the inversion cannot determine (a direction that
 * left the scene) still replay to something. */
static void prefill(struct sampler_writer *w, rng *r)
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++)
            w->u[st][i] = rng_uniform(r);
}

static double scene_size(const struct scene *sc) { return fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min))); }

static bool same_prefix(const struct vertex *a, int na, const struct vertex *b, int nb, double tol)
{
    if (nb < na) return false;
    for (int i = 0; i < na; i++)
        if (vlen(vsub(a[i].p, b[i].p)) > tol || a[i].prim != b[i].prim) return false;
    return true;
}

static int walk(const struct path_ctx *pc, int kind, struct sampler *s, struct vertex *v)
{
    return kind == 0 ? walk_camera(pc, s, v, 9) : walk_emitter(pc, s, v, 8);
}

static bool invert(const struct path_ctx *pc, int kind, const struct vertex *v, int n, int from, struct sampler *w)
{
    return kind == 0 ? invert_camera(pc, v, n, from, w) : invert_emitter(pc, v, n, from, w);
}

/* 20k camera and 20k emitter walks per scene; all but 1 in 2000 must retrace, and partial inversion
 * of the suffix from vertex 2 must retrace too. Before inversion retraced the walk's own hit points
 * (path_invert.c), up to 23 of 17485 camera walks of scenes/materials failed under Embree's SSE and
 * AVX kernels (18 under AVX2, 11 under AVX-512); since, at most 1 of 16188 emitter walks there,
 * through a chain of refractions in the glass sphere. */
static void check_scene(const char *isa, const char *path)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct vertex a[MAX_SUBPATH_VERTS], b[MAX_SUBPATH_VERTS], c[MAX_SUBPATH_VERTS];
    static struct sampler_writer w;
    struct sampler_independent ind;
    struct sampler_replay rep;
    rng r;
    rng_seed(&r, 11, 0);
    sampler_writer_init(&w, 5, 0);
    const int N = 20000;
    /* Embree intersects in single precision: each hit is off the exact ray by ~1e-7 of the scene,
     * and a chain of refractions in a sphere amplifies that along the walk. */
    double tol = 1e-4 * scene_size(sc);
    for (int kind = 0; kind < 2; kind++) {
        int fail = 0, fail_suffix = 0, tried = 0, suffixes = 0;
        for (int i = 0; i < N; i++) {
            sampler_independent_init(&ind, 77, (uint64_t)i * 2 + kind);
            int n = walk(&pc, kind, &ind.base, a);
            if (n < 2) continue;
            tried++;
            prefill(&w, &r);
            bool ok = invert(&pc, kind, a, n, 0, &w.base);
            sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
            int m = ok ? walk(&pc, kind, &rep.base, b) : 0;
            if (!ok || !same_prefix(a, n, b, m, tol)) fail++;
            /* suffix only: scramble blocks >= 2 of the stream, re-invert from vertex 2. The kept
             * numbers lead the walk to b[0..2] (path.h: v[from] is the walk's own vertex). */
            if (n > 3 && m > 2) {
                suffixes++;
                int st = kind == 0 ? STREAM_CAMERA : STREAM_EMITTER;
                for (int d = 2 * SAMPLER_BLOCK; d < STREAM_DIMS; d++)
                    w.u[st][d] = rng_uniform(&r);
                memcpy(c, a, sizeof c);
                memcpy(c, b, 3 * sizeof c[0]);
                ok = invert(&pc, kind, c, n, 2, &w.base);
                m = ok ? walk(&pc, kind, &rep.base, b) : 0;
                if (!ok || !same_prefix(a, n, b, m, tol)) fail_suffix++;
            }
        }
        const char *what = kind ? "emitter" : "camera";
        cr_log_info("isa %s, %s: %s walks %d of %d did not retrace, suffix inversions %d of %d", isa, path, what, fail,
                    tried, fail_suffix, suffixes);
        cr_expect(tried > N / 10, "%s: only %d walks of >= 2 vertices", path, tried);
        cr_expect(fail <= tried / 2000, "isa %s, %s: %s walks: %d of %d did not retrace", isa, path, what, fail, tried);
        cr_expect(fail_suffix <= suffixes / 2000, "isa %s, %s: %s suffix inversions: %d of %d failed", isa, path, what,
                  fail_suffix, suffixes);
    }
    scene_free(sc);
}

static void check_all(const char *isa, void *ctx)
{
    (void)ctx;
    for (const char **s = test_all_scenes(); *s; s++)
        check_scene(isa, *s);
}

Test(path, inverse_walks_retrace_on_every_scene)
{
    cr_assert(test_all_scenes()[0], "no scenes found under scenes/");
    test_each_isa(check_all, NULL);
}
