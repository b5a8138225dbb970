/* Multiplexed MLT's state evaluation and its technique number (see mmlt.h; MMLT paper Eq. 17-20,
 * thesis §3.8 and Eq. 5.6). */
#include "mcmc/mmlt.h"
#include <math.h>

double mmlt_technique_number(int t, int k, double xi)
{
    double u = invert_discrete((double)(t - 1) / (k + 1), (double)t / (k + 1), xi);
    while (1 + (int)((k + 1) * u) < t)
        u = nextafter(u, 1.0);
    while (1 + (int)((k + 1) * u) > t)
        u = nextafter(u, 0.0);
    return u;
}

/* mmlt_eval, the emitter subpath walked, or copied from keep when it is not NULL */
static bool eval(const struct path_ctx *pc, struct sampler *s, int k, const struct mmlt_path *keep, struct mmlt_path *x,
                 struct connection *c)
{
    sampler_begin(s, STREAM_TECHNIQUE, 0);
    int t = mmlt_technique(k, sampler_next(s, DIM_TECHNIQUE));
    int sv = k + 1 - t;
    x->k = k;
    x->t = t;
    x->s = sv;
    int nz = walk_camera(pc, s, x->cam, t), ny = 0;
    if (keep && keep->s == sv) {
        for (int i = 0; i < sv; i++)
            x->emi[i] = keep->emi[i];
        ny = sv;
    } else if (sv > 0) {
        ny = walk_emitter(pc, s, x->emi, sv);
    }
    x->complete = nz == t && ny == sv;
    return x->complete && connect_st(pc, x->emi, sv, x->cam, t, k, c, x->ratios);
}

bool mmlt_eval(const struct path_ctx *pc, struct sampler *s, int k, struct mmlt_path *x, struct connection *c)
{
    return eval(pc, s, k, NULL, x, c);
}

double mmlt_eval_state_keep(const struct path_ctx *pc, struct sampler *s, int k, const struct mmlt_path *keep,
                            struct mmlt_path *x, struct splat_list *out, struct nonfinite *nf)
{
    struct connection c;
    out->n = 0;
    if (eval(pc, s, k, keep, x, &c)) {
        rgb v = mmlt_contribution(&c, k);
        if (vfinite(v))
            splat_push(out, c.px, c.py, v);
        else
            nf->len[k]++;
    }
    double f = splat_luminance(out);
    return isfinite(f) && f > 0 ? f : 0;
}

double mmlt_eval_state(const struct path_ctx *pc, struct sampler *s, int k, struct mmlt_path *x, struct splat_list *out,
                       struct nonfinite *nf)
{
    return mmlt_eval_state_keep(pc, s, k, NULL, x, out, nf);
}
