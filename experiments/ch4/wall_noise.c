/* PSSMLT on the wall and the measurements of its noise (wall_noise.h). */
#include "ch4/wall_noise.h"
#include "base/util.h"
#include "stats/noise_corr.h"
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

struct image *wall_run(const struct scene *sc, const struct wall_cfg *c, uint64_t seed, const struct image *ref,
                       struct wall_meas *m, char *err, size_t errlen)
{
    int W = sc->cam.width, H = sc->cam.height;
    struct mlt_opts o = {.method = MLT_PSSMLT,
                         .p_large = c->p_large,
                         .mutations = (long)llround(c->mpp * W * H),
                         .seed_paths = c->seed_paths,
                         .seed = seed,
                         .threads = c->threads,
                         .max_length = sc->max_length,
                         .progress = isatty(2)};
    pss_opts_default(&o.pss, W, H);
    o.pss.rap = c->rap || c->rap_resolution;
    o.pss.rap_resolution = c->rap_resolution;
    struct mlt_result r;
    if (!mlt_render(sc, &o, &r, err, errlen)) return NULL;
    *m = (struct wall_meas){0};
    m->accept = cell_mean(&r.stats.total[PROPOSAL_SMALL]);
    m->relmse = img_relmse(r.img, ref, 0.01);
    m->err = error_field(r.img, ref);
    m->rho_x = xmalloc((c->maxlag + 1) * sizeof(double));
    m->rho_y = xmalloc((c->maxlag + 1) * sizeof(double));
    if (!corr_profiles(m->err, W, H, c->maxlag, m->rho_x, m->rho_y)) {
        snprintf(err, errlen, "the error image is constant: no noise to measure");
        wall_meas_free(m);
        mlt_result_free(&r);
        return NULL;
    }
    double s2 = 0, s = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        s += m->err[i];
        s2 += m->err[i] * m->err[i];
    }
    s /= (double)W * H;
    m->err_var = s2 / ((double)W * H) - s * s;
    m->lx = corr_length_lag1(m->rho_x, c->maxlag + 1);
    m->ly = corr_length_lag1(m->rho_y, c->maxlag + 1);
    m->rho1_x = m->rho_x[1];
    m->rho1_y = m->rho_y[1];
    struct image *img = r.img;
    r.img = NULL;
    mlt_result_free(&r);
    return img;
}

void wall_meas_free(struct wall_meas *m)
{
    free(m->rho_x);
    free(m->rho_y);
    free(m->err);
    m->rho_x = m->rho_y = m->err = NULL;
}
