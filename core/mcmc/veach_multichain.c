/* Veach's multi-chain perturbation (Veach's thesis §11.4.3.4; docs/veach.md): on a path whose camera
 * end is x_{m-1} x_m S+ D S+ ... D S* E with x_{m-1}, x_m not delta (the lens perturbation's paths,
 * but with specular chains between non-delta vertices, where it has no x_{m-1} to connect to), move
 * the raster position as the lens perturbation does, trace the camera ray through as many delta
 * vertices as before to the first non-delta vertex, and there, and at every non-delta vertex after
 * it down to x_m, leave along the old path's outgoing direction turned as the caustic perturbation
 * turns it, through as many delta vertices as before; connect x'_m to x_{m-1}.
 *
 * The offset and the turns are symmetric, so T(y -> x) / T(x -> y) is the ratio of the camera
 * side's densities at the split m without the directions the turns replaced: a = min(1, lum F_m(y)
 * prod p(omega'_i) / (lum F_m(x) prod p(omega_i))) over the turned vertices, p their densities of
 * sampling the direction (camera side, radiance mode). */
#include "mcmc/veach.h"
#include "path/path_form.h"
#include <math.h>

/* The first non-delta vertex below c (toward the emitter), or -1. */
static int next_diffuse(const struct veach_state *x, int c)
{
    int n = c - 1;
    while (n >= 0 && x->x[n].delta)
        n--;
    return n;
}

int veach_multichain_vertex(const struct veach_state *x)
{
    int c = next_diffuse(x, x->k);
    /* no delta vertex after the first non-delta one: the lens perturbation's path, or none */
    if (c < 1 || !x->x[c - 1].delta) return -1;
    while (c >= 1 && x->x[c - 1].delta) {
        c = next_diffuse(x, c);
        if (c < 1 || x->x[c].kind == VK_ENV) return -1; /* the chain ends on the emitter */
    }
    return c;
}

bool veach_multichain_perturb(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m,
                              struct veach_scratch *w, double *ratio, const struct vertex **yp)
{
    int k = x->k, c = next_diffuse(x, k);
    double px, py;
    veach_lens_offset(&pc->sc->cam, r, x, &px, &py);
    if (!veach_lens_trace(pc, r, x, c, w, px, py, yp)) return false;
    const struct vertex *xp[MAX_SUBPATH_VERTS];
    for (int i = 0; i <= k; i++)
        xp[i] = &x->x[i];
    /* x's camera subpath down to x_m: the old directions' densities */
    if (!path_camera_form(pc, xp, k, k + 1 - m, w->xz)) return false;
    struct vertex *z = w->zs;
    *ratio = 1;
    for (int n = k + 1 - c; c > m; n = k + 1 - c) { /* z[n - 1] = x'_c */
        int next = next_diffuse(x, c);
        double d2, p_old, p_new;
        rgb beta;
        vec3 omega = edge_dir(xp[c], xp[c - 1], &d2);
        if (!path_leave(pc, w->xz, n, omega, TRANSPORT_RADIANCE, &beta, &p_old) || !(p_old > 0) ||
            !veach_leave_turned(pc, r, z, n, omega, k + 1 - next, TRANSPORT_RADIANCE, STREAM_CAMERA, &p_new))
            return false;
        *ratio *= p_new / p_old;
        c = next;
    }
    for (int i = 0; i <= k; i++)
        yp[i] = i < m ? xp[i] : &z[k - i];
    return true;
}

void veach_multichain_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start)
{
    struct veach_scratch *w = wk->veach;
    int m = veach_multichain_vertex(x);
    double ratio = 0, a = 0;
    bool refused = m < 0;
    const struct vertex *yp[MAX_SUBPATH_VERTS];
    bool made = !refused && veach_multichain_perturb(&wk->path_ctx, &wk->r, x, m, w, &ratio, yp) &&
                path_emitter_form(&wk->path_ctx, yp, m, w->ys) &&
                veach_state_set(&w->y, &wk->path_ctx, w->ys, m, w->zs, x->k + 1 - m);
    if (made) {
        double fx = veach_f_at(&wk->path_ctx, x, m, w);
        a = fx > 0 ? fmin(1.0, luminance(w->y.f) * ratio / fx) : 0;
    }
    veach_decide(wk, c, x, PROPOSAL_MULTICHAIN, made, refused, a, t_start);
}
