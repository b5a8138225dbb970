/* Veach's caustic perturbation (Veach & Guibas 1997, §5.3.3; docs/veach.md): on a path whose camera
 * end is x_m S+ x_{k-1} E (x_m, x_{k-1} not delta, at least one delta vertex between), turn the
 * direction x_m leaves along by an angle theta with density in proportion to 1/theta on
 * [1e-4, 0.1] rad about it (uniform azimuth: a density in solid angle that depends on the angle
 * between the two directions only, so symmetric), follow it through as many delta vertices as
 * before (an emitter walk with fresh numbers for the lobes' choices) to a non-delta x'_{k-1}, and
 * connect that to the camera vertex.
 *
 * The perturbation's density cancels; what remains of T(y -> x) / T(x -> y) is the ratio of the
 * moved vertices' densities from the direction on, which the emitter side's density at the split
 * k (k emitter vertices, the camera alone) holds together with the density of x_m's own sampling of
 * the direction, p(omega): so a = min(1, lum F_k(y) p(omega') / (lum F_k(x) p(omega))). */
#include "mcmc/veach.h"
#include "path/path_form.h"
#include <math.h>

int veach_caustic_vertex(const struct veach_state *x)
{
    int k = x->k;
    if (k < 3 || x->x[k - 1].delta || !x->x[k - 2].delta) return -1;
    int m = k - 2;
    while (m >= 0 && x->x[m].delta)
        m--;
    /* the environment's direction is its position: turning it would move x_0 */
    return m >= 0 && x->x[m].kind != VK_ENV ? m : -1;
}

vec3 veach_turn(vec3 w, rng *r)
{
    const double t1 = 1e-4, t2 = 0.1; /* radians: the harness's choice, Veach gives the shape */
    double theta = t1 * pow(t2 / t1, rng_uniform(r)), phi = 2 * M_PI * rng_uniform(r);
    frame f = frame_from_normal(w);
    return vnorm(frame_to_world(&f, v3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta))));
}

bool veach_leave_turned(const struct path_ctx *pc, rng *r, struct vertex *v, int n, vec3 omega, int to,
                        enum transport mode, int stream, double *p_new)
{
    rgb beta;
    vec3 d = veach_turn(omega, r);
    if (!path_leave(pc, v, n, d, mode, &beta, p_new) || !(*p_new > 0) || !walk_hit(pc->sc, &v[n - 1], d, &v[n]))
        return false;
    v[n].beta = beta;
    v[n].pdf_fwd = edge_pdf(*p_new, &v[n - 1], &v[n], d, vlen2(vsub(v[n].p, v[n - 1].p)));
    struct sampler_rng fresh;
    sampler_rng_init(&fresh, r);
    if (walk_extend(pc, &fresh.base, v, n + 1, to, stream) != to) return false;
    for (int i = n; i < to - 1; i++)
        if (!v[i].delta) return false; /* as many delta vertices as before, then a non-delta one */
    return true;
}

bool veach_caustic_perturb(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m,
                           struct veach_scratch *w, double *p_old, double *p_new, const struct vertex **yp)
{
    const struct vertex *xp[MAX_SUBPATH_VERTS];
    for (int i = 0; i <= x->k; i++)
        xp[i] = &x->x[i];
    struct vertex *y = w->ys;
    if (!path_emitter_form(pc, xp, m + 1, y)) return false;
    double d2;
    vec3 omega = edge_dir(&y[m], xp[m + 1], &d2);
    rgb beta;
    if (!path_leave(pc, y, m + 1, omega, TRANSPORT_IMPORTANCE, &beta, p_old) ||
        !veach_leave_turned(pc, r, y, m + 1, omega, x->k, TRANSPORT_IMPORTANCE, STREAM_EMITTER, p_new))
        return false;
    for (int i = 0; i <= x->k; i++)
        yp[i] = i < x->k ? &y[i] : xp[i];
    return true;
}

void veach_caustic_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start)
{
    struct veach_scratch *w = wk->veach;
    int m = veach_caustic_vertex(x);
    double p_old = 0, p_new = 0, a = 0;
    bool refused = m < 0;
    const struct vertex *yp[MAX_SUBPATH_VERTS];
    bool made = !refused && veach_caustic_perturb(&wk->path_ctx, &wk->r, x, m, w, &p_old, &p_new, yp) &&
                path_camera_form(&wk->path_ctx, yp, x->k, 1, w->zs) &&
                veach_state_set(&w->y, &wk->path_ctx, w->ys, x->k, w->zs, 1);
    if (made) {
        double fx = veach_f_at(&wk->path_ctx, x, x->k, w);
        a = fx > 0 && p_old > 0 ? fmin(1.0, luminance(w->y.f) * p_new / (fx * p_old)) : 0;
    }
    veach_decide(wk, c, x, PROPOSAL_CAUSTIC, made, refused, a, t_start);
}
