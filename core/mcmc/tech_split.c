/* Per-technique split of a PSSMLT or MMLT state for the technique images (see tech_split.h). */
#include "mcmc/tech_split.h"
#include "path/connect.h"
#include <string.h>

/* PSSMLT: the length-k connections of the subpaths in w, as bdpt_splats weights them. */
static void split_bdpt(int k, const struct path_ctx *pc, const struct scratch *w, struct tech_split *sp)
{
    struct connection c;
    for (int t = 1; t <= k + 1; t++) {
        int s = k + 1 - t;
        if (w->nz < t || w->ny < s || !connect_st(pc, w->emi, s, w->cam, t, k, &c, NULL)) continue;
        rgb v = vscale(c.f, c.w);
        if (!vfinite(v)) continue; /* bdpt_splats drops it too */
        sp->on[t] = true;
        sp->s[t] = (struct splat){c.px, c.py, v};
    }
}

void tech_split_record(struct tech_acc *a, const struct path_ctx *pc, const struct scratch *w, int chain_k, int tech,
                       const struct splat_list *l, bool start)
{
    struct tech_split sp;
    if (tech_acc_tracks(a, chain_k)) {
        memset(&sp, 0, sizeof sp);
        if (chain_k == 0) {
            split_bdpt(a->k, pc, w, &sp);
        } else if (l->n > 0 && tech >= 1 && tech <= a->k + 1) {
            sp.on[tech] = true;
            sp.s[tech] = l->s[0];
        }
    }
    tech_acc_eval(a, chain_k, &sp, start);
}
