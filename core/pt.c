/* Path tracer: techniques s = 0 (emission hit, or escape to the environment) and s = 1 (a light
 * sample at every vertex), weighted against each other only (balance heuristic). The light sample
 * at camera vertex i uses emitter-stream block i. */
#include "connect.h"
#include "integrator.h"

void splat_checked(struct image *img, struct scratch *w, double px, double py, rgb c)
{
    if (!vfinite(c)) {
        w->nonfinite++;
        return;
    }
    img_splat(img, px, py, c);
}

void pt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img)
{
    struct vertex *z = w->cam, y;
    int nz = walk_camera(pc, s, z, pc->max_length + 1);
    rgb sum = v3s(0);
    struct connection c;
    for (int t = 2; t <= nz; t++) {
        int k = t - 1; /* length of the emission-hit path */
        if (connect_st(pc, NULL, 0, z, t, k >= 2 ? 1 : 0, &c, NULL)) sum = vmad(sum, c.f, c.w);
        const struct vertex *zc = &z[t - 1];
        if (t > pc->max_length || !zc->bc.b || bsdf_ops_for(zc->bc.b->type)->delta_only) continue;
        sampler_begin(s, STREAM_EMITTER, t - 1);
        if (sample_emitter_vertex(pc->sc, s, &y) && connect_st(pc, &y, 1, z, t, 1, &c, NULL)) sum = vmad(sum, c.f, c.w);
    }
    splat_checked(img, w, z[0].px, z[0].py, sum);
}
