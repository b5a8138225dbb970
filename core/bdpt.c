/* Bidirectional path tracer: one camera and one emitter subpath per sample, all (s, t) with
 * 1 <= s + t - 1 <= max_length; t = 1 splats at the connection's raster position. */
#include "connect.h"
#include "integrator.h"

void bdpt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img)
{
    int K = pc->max_length;
    int nz = walk_camera(pc, s, w->cam, K + 1);
    int ny = walk_emitter(pc, s, w->emi, K);
    rgb sum = v3s(0);
    struct connection c;
    for (int t = 1; t <= nz; t++)
        for (int s_ = 0; s_ <= ny; s_++) {
            int k = s_ + t - 1;
            if (k < 1 || k > K) continue;
            if (pc->only_t > 0 && (s_ != pc->only_s || t != pc->only_t)) continue;
            if (!connect_st(pc, w->emi, s_, w->cam, t, k, &c, NULL)) continue;
            if (pc->only_t > 0) c.w = 1;
            if (t == 1) splat_checked(img, w, c.px, c.py, vscale(c.f, c.w));
            else sum = vmad(sum, c.f, c.w);
        }
    splat_checked(img, w, w->cam[0].px, w->cam[0].py, sum);
}
