/* Veach's lens perturbation (Veach & Guibas 1997, §5.3.2; docs/veach.md): on a path whose camera end
 * is x_{m-1} x_m S* E (x_{m-1}, x_m not delta, the vertices between x_m and the camera vertex delta),
 * move the raster position by an offset of uniform direction and a radius with density in
 * proportion to 1/r on [r1, r2] (in raster area: 1 / (2 pi r^2 ln(r2 / r1)), symmetric), trace the
 * camera ray through as many delta vertices as before to a non-delta x'_m, and connect x'_m to x_{m-1}.
 *
 * With the offset symmetric, T(y -> x) / T(x -> y) is the ratio of the camera side's densities of
 * the moved vertices (the film's uniform density turned into theirs), so the acceptance is
 * lum F_m(y) / lum F_m(x): both paths' contributions over their density at the split m, the one
 * that samples the moved vertices from the camera (F: radiance mode, veach.h).
 *
 * Veach's lens subpath mutation (§5.4 of Veach's thesis ch. 11, restricted to subpaths of the same
 * form) is the same move with the raster position drawn uniformly over the film and its margin
 * instead of near x's: a new camera subpath wherever it lands, which stratifies the chains over the
 * image. The uniform draw is symmetric too, so its acceptance is the perturbation's. */
#include "camera/camera.h"
#include "mcmc/splat_ev.h"
#include "mcmc/veach.h"
#include "path/path_form.h"
#include <math.h>

/* The camera stream's block 0 from two given image numbers, every other number fresh. */
struct lens_sampler {
    struct sampler base;
    rng *r;
    double u[2];
};

static double lens_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    struct lens_sampler *l = (struct lens_sampler *)s;
    return s->stream == STREAM_CAMERA && s->vertex == 0 && s->offset < 2 ? l->u[s->offset] : rng_uniform(l->r);
}
static const struct sampler_ops lens_ops = {lens_next, NULL, NULL};

/* The index m of the path's last non-delta vertex before the camera, or -1 when the path is not one
 * the perturbation moves (m < 1, or x_{m-1} delta). */
int veach_lens_vertex(const struct veach_state *x)
{
    int m = x->k - 1;
    while (m >= 1 && x->x[m].delta)
        m--;
    return m >= 1 && !x->x[m - 1].delta ? m : -1;
}

/* The offset's radius bounds in pixels: a tenth of a pixel to a tenth of the image's larger side
 * (the harness's choice; Veach gives the shape, not values we could check). */
static void radius_bounds(const struct camera *c, double *r1, double *r2)
{
    *r1 = 0.1;
    *r2 = 0.1 * (c->width > c->height ? c->width : c->height);
}

bool veach_lens_trace(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m, struct veach_scratch *w,
                      double px, double py, const struct vertex **yp)
{
    const struct camera *cam = &pc->sc->cam;
    int mg = camera_margin(cam);
    if (!(px >= -mg && px < cam->width + mg && py >= -mg && py < cam->height + mg)) return false;
    struct lens_sampler ls = {{&lens_ops, 0, 0, 0}, r, {0, 0}};
    struct sampler_block blk;
    sampler_block_init(&blk, ls.u, NULL);
    camera_invert(cam, px, py, &blk.base);
    const struct vertex *xp[MAX_SUBPATH_VERTS];
    for (int i = 0; i <= x->k; i++)
        xp[i] = &x->x[i];
    int t = x->k - m + 1;
    if (!path_camera_form(pc, xp, x->k, 1, w->zs) || walk_extend_from(pc, &ls.base, w->zs, 1, t, STREAM_CAMERA) != t)
        return false;
    for (int j = 1; j < t - 1; j++)
        if (!w->zs[j].delta) return false; /* the same number of delta vertices, then x'_m */
    for (int i = 0; i <= x->k; i++)
        yp[i] = i < m ? xp[i] : &w->zs[x->k - i];
    return true;
}

void veach_lens_offset(const struct camera *cam, rng *r, const struct veach_state *x, double *px, double *py)
{
    double r1, r2;
    radius_bounds(cam, &r1, &r2);
    double rad = r1 * pow(r2 / r1, rng_uniform(r)), phi = 2 * M_PI * rng_uniform(r);
    *px = x->px + rad * cos(phi);
    *py = x->py + rad * sin(phi);
}

bool veach_lens_perturb(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m, struct veach_scratch *w,
                        const struct vertex **yp)
{
    double px, py;
    veach_lens_offset(&pc->sc->cam, r, x, &px, &py);
    return veach_lens_trace(pc, r, x, m, w, px, py, yp);
}

/* The lens subpath mutation's raster position: uniform over the film and its margin. */
static bool resample(const struct path_ctx *pc, rng *r, const struct veach_state *x, int m, struct veach_scratch *w,
                     const struct vertex **yp)
{
    const struct camera *cam = &pc->sc->cam;
    int mg = camera_margin(cam);
    double px = -mg + (cam->width + 2 * mg) * rng_uniform(r), py = -mg + (cam->height + 2 * mg) * rng_uniform(r);
    return veach_lens_trace(pc, r, x, m, w, px, py, yp);
}

/* The lens perturbation (subpath false) or the lens subpath mutation (true) as one iteration. */
static void step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start, bool subpath)
{
    struct veach_scratch *w = wk->veach;
    int m = veach_lens_vertex(x);
    bool refused = m < 0;
    const struct vertex *yp[MAX_SUBPATH_VERTS];
    bool made = !refused && (subpath ? resample : veach_lens_perturb)(&wk->path_ctx, &wk->r, x, m, w, yp) &&
                path_emitter_form(&wk->path_ctx, yp, m, w->ys) &&
                veach_state_set(&w->y, &wk->path_ctx, w->ys, m, w->zs, x->k - m + 1);
    double fy = made ? luminance(w->y.f) : 0, a = 0;
    if (made) {
        double fx = veach_f_at(&wk->path_ctx, x, m, w);
        a = fx > 0 ? fmin(1.0, fy / fx) : 0; /* x not connectable at m: no move, and none back */
        if (wk->opts->lens_broken_t && !subpath && fx > 0 && w->y.px > x->px)
            a = fmin(1.0, fy / (1.1 * fx)); /* tests only */
    }
    veach_decide(wk, c, x, subpath ? PROPOSAL_LENS_SUBPATH : PROPOSAL_LENS, made, refused, a, t_start);
}

void veach_lens_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start)
{
    step(wk, c, x, t_start, false);
}

void veach_lens_subpath_step(struct worker *wk, struct chain *c, struct veach_state *x, double t_start)
{
    step(wk, c, x, t_start, true);
}
