/* core/mc/pt.c is a dedicated loop that must stay the BDPT machinery restricted to s <= 1: the same
 * walk, the same random number in every dimension, the same balance weights (connect_st with
 * max_s = 1). This test rebuilds that estimator from walk_camera, sample_emitter_vertex and
 * connect_st and demands the same value for every camera sample, so any drift between the twins
 * (a light-pick probability, a density measure, a number read from the wrong dimension) fails
 * exactly, on every committed scene, whatever its effect on the image mean. Both read one replayed
 * vector per sample: pt.c draws in a different order from BDPT's walk-first one, and the vector
 * makes the order irrelevant while the dimension layout still has to match. Dimensions beyond the
 * blocks a path of max_length can use are NAN, and reading one aborts. Deterministic: no
 * significance level; the tolerance is rounding (1e-9 relative per pixel). */
#include <criterion/criterion.h>

#include "mc/integrator.h"
#include "path/connect.h"
#include "path/scene_ready.h"
#include "support/scenes.h"

/* Thesis-machinery path tracer: z_0..z_{n-1}, then for t = 2..n the emission hit (s = 0) and the
 * light sample from emitter block t - 1 (s = 1) at vertices that can take one, weighted among
 * s <= 1. */
static void generic_pt(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img)
{
    int K = pc->max_length;
    int nz = walk_camera(pc, s, w->cam, K + 1);
    if (nz < 1) return;
    rgb sum = v3s(0);
    struct connection c;
    for (int t = 2; t <= nz; t++) {
        /* a directly seen emitter (k = 1) has no light-sampling rival: s = 1, t = 1 is light tracing */
        if (connect_st(pc, NULL, 0, w->cam, t, t > 2 ? 1 : 0, &c, NULL)) sum = vmad(sum, c.f, c.w);
        const struct vertex *zc = &w->cam[t - 1];
        if (t > K || !zc->bc.b || bsdf_ops_for(zc->bc.b->type)->delta_only) continue; /* draws nothing */
        sampler_begin(s, STREAM_EMITTER, t - 1);
        if (sample_emitter_vertex(pc->sc, s, &w->emi[0]) && connect_st(pc, w->emi, 1, w->cam, t, 1, &c, NULL))
            sum = vmad(sum, c.f, c.w);
    }
    img_splat(img, w->cam[0].px, w->cam[0].py, sum);
}

Test(pt_twin, equals_bdpt_machinery_restricted_to_s_le_1, .timeout = 600)
{
    static struct scratch w;
    for (const char **p = test_all_scenes(); *p; p++) {
        struct scene *sc = test_scene(*p);
        struct path_ctx pc = {.sc = sc, .max_length = 8};
        int W = sc->cam.width, H = sc->cam.height;
        struct image *a = img_create(W, H), *b = img_create(W, H);
        static double u[STREAM_COUNT][STREAM_DIMS];
        for (int st = 0; st < STREAM_COUNT; st++)
            for (int k = 0; k < STREAM_DIMS; k++)
                u[st][k] = NAN;
        rng r;
        rng_seed(&r, 5, 0);
        const int N = 50000;
        for (int i = 0; i < N; i++) {
            for (int st = STREAM_CAMERA; st <= STREAM_EMITTER; st++)
                for (int k = 0; k < (pc.max_length + 1) * SAMPLER_BLOCK; k++)
                    u[st][k] = rng_uniform(&r);
            struct sampler_replay rp;
            sampler_replay_init(&rp, u);
            pt_sample(&pc, &rp.base, &w, a);
            sampler_replay_init(&rp, u);
            generic_pt(&pc, &rp.base, &w, b);
        }
        double worst = 0, total = 0;
        for (long i = 0; i < 3L * W * H; i++) {
            double x = a->px[i], y = b->px[i], m = fmax(fabs(x), fabs(y));
            total += y;
            if (m > 0) worst = fmax(worst, fabs(x - y) / m);
        }
        cr_assert(total > 0, "%s: no light reached the camera in %d samples", *p, N);
        cr_assert(worst < 1e-9, "%s: pt.c and the BDPT machinery differ by %g (relative) in a pixel", *p, worst);
        img_destroy(a);
        img_destroy(b);
        scene_free(sc);
    }
}
