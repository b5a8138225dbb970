/* MIS weights across chains of delta vertices: the density ratio between the techniques on either
 * side of a chain of mirror reflections must be the ratio of the unfolded paths' densities. */
#include <criterion/criterion.h>

#include "camera/camera.h"
#include "emitter/emitter.h"
#include "path/connect.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

static bool is_mirror(const struct vertex *v)
{
    return v->kind == VK_SURFACE && v->bc.b && v->bc.b->type == BSDF_MIRROR;
}

/* Camera walks z_0 (camera), z_1 (floor), z_2 .. z_{t-2} (mirrors), z_{t-1} (light) give the path
 * x_0 = z_{t-1} .. x_k = z_0, k = t - 1. Techniques 1 .. k - 1 join a mirror vertex and cannot make
 * it; technique 0 (the walk hits the light) and technique k (the emitter walk reaches the floor
 * through the mirrors and joins the camera) can. Their densities, with the mirrors' Dirac factors
 * (equal on both sides) left out and L the unfolded length floor - mirrors - light:
 *   p_0 = pcam(floor) * (cos_f / pi) * cos_l / L^2   (pcam: the camera's area density of the floor point)
 *   p_k = (pick / A) * (cos_l / pi) * cos_f / L^2
 * cos_f, cos_l: cosines at the floor and the light with the chain's first and last segment.
 * The per-segment conversion (cos/d^2 of the one segment at each delta vertex) gave 3.50 where the
 * unfolded ratio is 28.7 on the first path found. Tolerance 1e-3: the code takes its cosines from
 * the walk's ray directions, this test from the float-rounded hit points. */
Test(path, mis_ratio_across_specular_chains_is_the_unfolded_paths)
{
    struct scene *sc = test_scene("tests/data/specular-chain.json");
    struct path_ctx pc = {.sc = sc, .max_length = 8};
    static struct vertex z[MAX_SUBPATH_VERTS], y[1];
    double ratios[MAX_PATH_LENGTH + 2];
    int found[3] = {0, 0, 0}; /* paths through 1 and 2 mirrors */
    for (int i = 0; i < 200000 && (found[1] < 50 || found[2] < 50); i++) {
        struct sampler_independent ind;
        sampler_independent_init(&ind, 5, (uint64_t)i);
        int n = walk_camera(&pc, &ind.base, z, 6);
        int mirrors = 0;
        while (2 + mirrors < n && is_mirror(&z[2 + mirrors]))
            mirrors++;
        int t = 3 + mirrors;
        if (mirrors < 1 || mirrors > 2 || n < t || !z[1].bc.b || z[1].bc.b->type != BSDF_LAMBERT) continue;
        const struct vertex *light = &z[t - 1];
        if (light->kind != VK_SURFACE || !light->front || !sc->prims[light->prim].emissive) continue;
        struct connection c;
        cr_assert(connect_st(&pc, y, 0, z, t, t - 1, &c, ratios), "a camera path that hits the light contributes");
        int k = t - 1;
        double L = 0;
        for (int j = 1; j < t - 1; j++)
            L += vlen(vsub(z[j + 1].p, z[j].p));
        vec3 first = vnorm(vsub(z[2].p, z[1].p)), last = vnorm(vsub(light->p, z[t - 2].p));
        double cos_f = fabs(vdot(z[1].ng, first)), cos_l = fabs(vdot(light->ng, last));
        vec3 d_cam = vsub(z[1].p, z[0].p);
        double pcam = camera_pdf_dir(&sc->cam, z[0].p, vnorm(d_cam)) * fabs(vdot(z[1].ng, vnorm(d_cam))) / vlen2(d_cam);
        double p0 = pcam * (cos_f / M_PI) * cos_l / (L * L);
        double pk = emitter_pick_prob(sc, light->prim) * emitter_pdf_pos(sc, light->prim, light->p) * (cos_l / M_PI) *
                    cos_f / (L * L);
        cr_assert_float_eq(ratios[0], 1.0, 1e-12);
        for (int j = 1; j < k; j++)
            cr_assert_eq(ratios[j], 0.0, "technique %d joins a mirror vertex", j);
        cr_assert(fabs(ratios[k] / (pk / p0) - 1) < 1e-3, "%d mirrors: p_k/p_0 = %g, unfolded %g", mirrors, ratios[k],
                  pk / p0);
        found[mirrors]++;
    }
    cr_assert(found[1] >= 50 && found[2] >= 50, "paths through 1 / 2 mirrors: %d / %d", found[1], found[2]);
    scene_free(sc);
}
