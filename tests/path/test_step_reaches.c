/* walk_step_reaches (PITP's reverse check, core/mcmc/README.md) against the step it stands for:
 * on every committed scene, for every step of random camera and emitter walks, inverting the step's
 * block toward the vertex the walk reached and asking walk_step_reaches must give the same answer
 * as stepping with walk_extend_to and comparing the vertex it builds (same primitive, point within
 * the retrace tolerance). Both decide by the same ray-free rule or the same ray, so they must agree
 * on every step, not only in distribution; and a target moved off its surface point must be
 * reached by neither. */
#include <criterion/criterion.h>
#include <criterion/logging.h>
#include <string.h>

#include "path/path.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

static bool reached_by_step(const struct path_ctx *pc, struct sampler *s, const struct vertex *v, int n, int st,
                            const struct vertex *to, double tol)
{
    static struct vertex c[MAX_SUBPATH_VERTS];
    memcpy(c, v, (size_t)n * sizeof c[0]);
    return walk_extend_to(pc, s, c, n, st, to) == n + 1 && vertex_same(&c[n], to, tol);
}

static void check_scene(const char *path)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct vertex v[MAX_SUBPATH_VERTS];
    static struct sampler_writer w;
    struct sampler_independent ind;
    struct sampler_replay rep;
    double tol = 1e-4 * fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min)));
    int steps = 0, reached = 0, differ = 0, moved_reached = 0;
    for (int kind = 0; kind < 2; kind++) {
        int st = kind == 0 ? STREAM_CAMERA : STREAM_EMITTER;
        for (int i = 0; i < 3000; i++) {
            sampler_independent_init(&ind, 91, (uint64_t)i * 2 + kind);
            int len = kind == 0 ? walk_camera(&pc, &ind.base, v, 9) : walk_emitter(&pc, &ind.base, v, 8);
            for (int n = kind == 0 ? 1 : 2; n < len; n++) {
                if (v[n].kind != VK_SURFACE) continue;
                sampler_writer_init(&w, 5, (uint64_t)i);
                if (!invert_step(&pc, st, v, n, &v[n], &w.base)) continue;
                sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
                bool a = walk_step_reaches(&pc, &rep.base, v, n, st, &v[n], tol);
                sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
                bool b = reached_by_step(&pc, &rep.base, v, n, st, &v[n], tol);
                steps++;
                reached += a;
                differ += a != b;
                /* the same numbers toward a point 10 tolerances off the surface: reached by neither */
                struct vertex off = v[n];
                off.p = vadd(off.p, vscale(off.ng, 10 * tol));
                sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
                moved_reached += walk_step_reaches(&pc, &rep.base, v, n, st, &off, tol);
            }
        }
    }
    cr_log_info("%s: %d steps, %d reached, %d answers differ from the step's, %d moved targets reached", path, steps,
                reached, differ, moved_reached);
    cr_expect(steps > 500, "%s: only %d steps checked", path, steps);
    cr_expect(reached > steps * 9 / 10, "%s: only %d of %d inverted steps reached", path, reached, steps);
    cr_expect_eq(differ, 0, "%s: walk_step_reaches and the step differ on %d of %d steps", path, differ, steps);
    cr_expect_eq(moved_reached, 0, "%s: %d targets moved off the surface were reached", path, moved_reached);
    scene_free(sc);
}

Test(path, step_reaches_agrees_with_the_step_on_every_scene, .timeout = 300)
{
    cr_assert(test_all_scenes()[0], "no scenes found under scenes/");
    for (const char **s = test_all_scenes(); *s; s++)
        check_scene(*s);
}
