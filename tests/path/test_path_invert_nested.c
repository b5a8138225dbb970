/* Inverse random walks (thesis Alg. 2) through the nested BSDFs: on the three conformance scenes
 * that use them (coats, mixed with a ratio map, transparency), the numbers written by invert_camera
 * / invert_emitter make the forward walks retrace the same vertices, as test_path_invert.c checks
 * on scenes/ (the same criteria: all but 1 in 2000 of 20k walks per subpath kind). One instruction
 * set (the default): the ISA dependence is that file's subject. */
#include <criterion/criterion.h>
#include <string.h>

#include "path/path.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

static void prefill(struct sampler_writer *w, rng *r)
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++)
            w->u[st][i] = rng_uniform(r);
}

static bool same_prefix(const struct vertex *a, int na, const struct vertex *b, int nb, double tol)
{
    if (nb < na) return false;
    for (int i = 0; i < na; i++)
        if (vlen(vsub(a[i].p, b[i].p)) > tol || a[i].prim != b[i].prim) return false;
    return true;
}

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
    double tol = 1e-4 * fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min)));
    for (int kind = 0; kind < 2; kind++) {
        int fail = 0, tried = 0;
        for (int i = 0; i < N; i++) {
            sampler_independent_init(&ind, 77, (uint64_t)i * 2 + kind);
            int n = kind == 0 ? walk_camera(&pc, &ind.base, a, 9) : walk_emitter(&pc, &ind.base, a, 8);
            if (n < 2) continue;
            tried++;
            prefill(&w, &r);
            bool ok = kind == 0 ? invert_camera(&pc, a, n, 0, &w.base) : invert_emitter(&pc, a, n, 0, &w.base);
            sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
            int m = !ok ? 0 : kind == 0 ? walk_camera(&pc, &rep.base, b, 9) : walk_emitter(&pc, &rep.base, b, 8);
            if (!ok || !same_prefix(a, n, b, m, tol)) fail++;
        }
        const char *what = kind ? "emitter" : "camera";
        cr_log_info("%s: %s walks %d of %d did not retrace", path, what, fail, tried);
        cr_expect(tried > N / 10, "%s: only %d walks of >= 2 vertices", path, tried);
        cr_expect(fail <= tried / 2000, "%s: %s walks: %d of %d did not retrace", path, what, fail, tried);
    }
    scene_free(sc);
}

Test(path, inverse_walks_retrace_through_nested_bsdfs, .timeout = 300)
{
    check_scene("tests/data/tungsten/bsdf-coat.json");
    check_scene("tests/data/tungsten/bsdf-mixed.json");
    check_scene("tests/data/tungsten/bsdf-transparency.json");
}
