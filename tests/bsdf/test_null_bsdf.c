/* The null BSDF as Tungsten implements it (src/core/bsdfs/NullBsdf.cpp: sample() fails, eval() is
 * 0, so its forward transparency is 0): a black surface that still emits from its front, ends
 * every walk that reaches it and blocks shadow rays. Scene: an emissive null quad at z = 0 in front
 * of a diffuse wall at z = -1, seen from z = 5. */
#include <criterion/criterion.h>

#include "path/connect.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

static struct vertex at(vec3 p)
{
    return (struct vertex){.kind = VK_SURFACE,
                           .p = p,
                           .ng = v3(0, 0, 1),
                           .sh = frame_from_normal(v3(0, 0, 1)),
                           .front = true,
                           .prim = 0,
                           .tri = 0};
}

Test(null_bsdf, ends_walks_emits_and_blocks)
{
    struct scene *sc = test_scene("tests/data/null-light.json");
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    struct vertex z[MAX_SUBPATH_VERTS];
    struct sampler_independent ind;
    int on_null = 0, past_null = 0, direct = 0, emitting = 0;
    for (int i = 0; i < 10000; i++) {
        sampler_independent_init(&ind, 3, (uint64_t)i);
        int n = walk_camera(&pc, &ind.base, z, 9);
        for (int j = 1; j < n; j++) {
            if (z[j].kind != VK_SURFACE || z[j].prim != 1) continue;
            cr_assert_null(z[j].bc.b, "a null surface got a BSDF");
            on_null++;
            if (j != n - 1) past_null++;
            struct connection c;
            if (j > 1) continue; /* from the wall: its unlit back */
            direct++;
            if (connect_st(&pc, NULL, 0, z, 2, 2, &c, NULL)) {
                /* seen from the camera: beta = 1, so f is the emitted radiance itself */
                cr_assert(fabs(c.f.x - 5) < 1e-12 && fabs(c.f.y - 5) < 1e-12, "f = %g", c.f.x);
                emitting++;
            }
        }
    }
    cr_assert_gt(on_null, 500, "the quad covers ~6 %% of the view; only %d hits", on_null);
    cr_assert_eq(past_null, 0, "%d walks went on after a null surface", past_null);
    cr_assert_eq(emitting, direct, "a front hit from the camera did not emit");
    struct vertex cam = {.kind = VK_CAMERA, .p = sc->cam.pos};
    struct vertex hidden = at(v3(0, 0, -1)), seen = at(v3(1.5, 0, -1));
    cr_assert(!visible(sc, &cam, &hidden), "the null quad let a shadow ray through");
    cr_assert(visible(sc, &cam, &seen));
    scene_free(sc);
}
