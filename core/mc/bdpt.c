/* Bidirectional path tracer: one camera and one emitter subpath per sample, all (s, t) with
 * 1 <= s + t - 1 <= max_length; t = 1 contributions land at the connection's raster position. */
#include "mc/integrator.h"
#include "path/connect.h"
#include <string.h>

void bdpt_splats(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct splat_list *out)
{
    int K = pc->max_length;
    int nz = walk_camera(pc, s, w->cam, K + 1);
    int ny = walk_emitter(pc, s, w->emi, K);
    w->nz = nz;
    w->ny = ny;
    rgb sum = v3s(0);
    struct connection c;
    out->n = 0;
    if (w->tech_k) memset(w->tech_on, 0, sizeof w->tech_on);
    for (int t = 1; t <= nz; t++)
        for (int s_ = 0; s_ <= ny; s_++) {
            int k = s_ + t - 1;
            if (k < 1 || k > K) continue;
            if (pc->only_t > 0 && (s_ != pc->only_s || t != pc->only_t)) continue;
            w->conn_tried++;
            if (!connect_st(pc, w->emi, s_, w->cam, t, k, &c, NULL)) continue;
            if (pc->only_t > 0) c.w = 1;
            rgb v = vscale(c.f, c.w);
            if (!vfinite(v)) {
                w->nf.len[k]++;
                continue;
            }
            w->conn_nonzero += luminance(v) > 0;
            if (k == w->tech_k) {
                w->tech_on[t] = true;
                w->tech[t] = (struct splat){c.px, c.py, v};
            }
            if (t == 1)
                splat_push(out, c.px, c.py, v);
            else
                sum = vadd(sum, v);
        }
    if (nz > 0) splat_push(out, w->cam[0].px, w->cam[0].py, sum);
}

void bdpt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img)
{
    struct splat_list l;
    bdpt_splats(pc, s, w, &l);
    /* only the camera-pixel sum can be non-finite here: its terms were checked one by one */
    for (int i = 0; i < l.n; i++)
        splat_finite(img, l.s[i].px, l.s[i].py, l.s[i].c, &w->nf.len[0]);
}
