/* PSSMLT's state evaluation: every technique of every length of one pair of subpaths (see
 * pssmlt.h; thesis §3.7, Eq. 3.32-3.35). */
#include "mcmc/pssmlt.h"
#include <math.h>

double pssmlt_eval_state(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct splat_list *out)
{
    out->n = 0;
    bdpt_splats(pc, s, w, out);
    double f = splat_luminance(out);
    return isfinite(f) && f > 0 ? f : 0;
}
