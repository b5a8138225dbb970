/* Monte Carlo estimators on one camera sample: the path tracer (NEE + MIS between emission hits
 * and light samples) and BDPT (every (s, t) technique, balance heuristic). Both add to `img`
 * contributions whose sum, times width * height / N over N camera samples, estimates each pixel. */
#ifndef INTEGRATOR_H
#define INTEGRATOR_H

#include "io/image.h"
#include "path/path.h"
#include "path/splat.h"

/* Per-thread scratch: subpath arrays allocated once, never in the sample loop. */
struct scratch {
    struct vertex cam[MAX_SUBPATH_VERTS], emi[MAX_SUBPATH_VERTS];
    struct nonfinite nf; /* contributions dropped because they were NaN or infinite */
    int nz, ny;          /* vertex counts of the subpaths bdpt_splats last walked (per-technique images) */
    /* connections evaluated and those with a contribution, since the caller last took them (the
     * MMLT paper's §5 non-zero ratio per connection; mcmc/chain_loop.c moves them to the stats) */
    long conn_tried, conn_nonzero;
    /* > 0: bdpt_splats also keeps the sample's length-tech_k contributions per technique t (the
     * raster position and MIS-weighted colour; tech_on[t] when there is one) for mc/bdpt_tech.h */
    int tech_k;
    bool tech_on[MAX_SPLATS];
    struct splat tech[MAX_SPLATS];
};

void pt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img);
/* BDPT's contributions of one sample: t = 1 splats, then the sum of t >= 2 at z_0's pixel. */
void bdpt_splats(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct splat_list *out);
void bdpt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img);

#endif
