/* A path's subpaths in any technique's form, from its vertices (path_form.h). Each step repeats
 * what the walk's step does (path_walk.c: scatter_at and trace) with the edge's direction in place
 * of the sampled one, so a form of vertices a walk produced gives that walk's fields back. */
#include "path/path_form.h"
#include "bsdf/bsdf_smooth.h"
#include "camera/camera.h"
#include "emitter/emitter.h"

/* The triangle of a mesh or quad primitive that holds point p (an emitter vertex records no
 * barycentrics, and a quad's no triangle): `tri` when known, else the one p lies in, or nearest to
 * lying in; its barycentrics in *b1, *b2. */
static int point_triangle(const struct prim *pr, int tri, vec3 p, double *b1, double *b2)
{
    double best = INFINITY;
    int found = 0;
    for (int i = tri >= 0 ? tri : 0; i < (tri >= 0 ? tri + 1 : pr->ntris); i++) {
        const int *t = pr->tri + 3 * i;
        vec3 p0 = pr->p[t[0]], e1 = vsub(pr->p[t[1]], p0), e2 = vsub(pr->p[t[2]], p0), q = vsub(p, p0);
        double d11 = vdot(e1, e1), d12 = vdot(e1, e2), d22 = vdot(e2, e2), q1 = vdot(q, e1), q2 = vdot(q, e2);
        double det = d11 * d22 - d12 * d12;
        if (det == 0) continue;
        double c1 = (d22 * q1 - d12 * q2) / det, c2 = (d11 * q2 - d12 * q1) / det;
        double off = maxd(0, -c1) + maxd(0, -c2) + maxd(0, c1 + c2 - 1); /* 0 inside */
        if (off < best) {
            best = off;
            found = i;
            *b1 = c1;
            *b2 = c2;
        }
    }
    return found;
}

/* Vertex x (a surface, or an emitter vertex become a surface hit) as a walk arriving along unit d
 * reaches it: surface_from_hit of the same point, which turns the frame toward the arrival side.
 * x's delta flag is the path's and stays. */
static void arrive(const struct scene *sc, const struct vertex *x, vec3 d, struct vertex *out)
{
    const struct prim *pr = &sc->prims[x->prim];
    struct hit h = {.t = 1, .prim = x->prim, .tri = x->tri, .b1 = x->b1, .b2 = x->b2};
    if (x->kind == VK_EMITTER && pr->kind != PRIM_SPHERE) h.tri = point_triangle(pr, x->tri, x->p, &h.b1, &h.b2);
    surface_from_hit(sc, vsub(x->p, d), d, &h, out);
    out->delta = x->delta;
}

/* The weight and discrete probability of the delta lobe of v's BSDF that sends wi (local) to wo
 * (local, within the delta tolerance): its numbers by inversion, then its sample. */
static bool delta_lobe(const struct vertex *v, vec3 wi, vec3 wo, enum transport mode, struct bsdf_sample *bs)
{
    double u[SAMPLER_BLOCK];
    struct sampler_block blk;
    sampler_block_init(&blk, u, NULL);
    if (!bsdf_invert(&v->bc, wi, wo, &blk.base)) return false;
    for (int i = blk.n; i < SAMPLER_BLOCK; i++)
        u[i] = 0.5;
    sampler_begin(&blk.base, 0, 0);
    return bsdf_sample(&v->bc, wi, &blk.base, mode, bs) && bs->delta && smooth_same_dir(bs->wo, wo);
}

bool path_leave(const struct path_ctx *pc, struct vertex *v, int n, vec3 d, enum transport mode, rgb *beta,
                double *pdf_sa)
{
    const struct scene *sc = pc->sc;
    struct vertex *cur = &v[n - 1];
    *pdf_sa = 0;
    if (cur->kind == VK_ENV) { /* rays leave the origin disc against env_dir (path_walk.c) */
        *pdf_sa = 1.0 / (M_PI * sqr(env_radius(sc)));
        *beta = vscale(vmul(cur->beta, env_radiance(sc, env_dir(cur))), 1.0 / *pdf_sa);
        return vfinite(*beta) && !vzero(*beta);
    }
    if (cur->kind == VK_EMITTER) {
        *pdf_sa = emitter_pdf_dir(cur->ng, d);
        rgb le = emitter_radiance(sc, cur->prim, cur->ng, d);
        if (!(*pdf_sa > 0) || vzero(le)) return false;
        *beta = vscale(vmul(cur->beta, le), fabs(vdot(d, cur->ng)) / *pdf_sa);
        return vfinite(*beta);
    }
    if (n < 2 || cur->kind != VK_SURFACE || !cur->bc.b) return false;
    struct vertex *prev = &v[n - 2];
    vec3 wi = frame_to_local(&cur->sh, cur->wi), wo = frame_to_local(&cur->sh, d);
    if ((vdot(d, cur->ng) > 0) != (wo.z > 0)) return false;
    rgb w;
    double pdf_back = 0;
    if (cur->delta) {
        struct bsdf_sample bs;
        if (!delta_lobe(cur, wi, wo, mode, &bs)) return false;
        w = bs.weight;
    } else {
        *pdf_sa = bsdf_pdf(&cur->bc, wi, wo);
        if (!(*pdf_sa > 0)) return false;
        w = vscale(bsdf_eval(&cur->bc, wi, wo, mode), fabs(wo.z) / *pdf_sa);
        pdf_back = bsdf_pdf(&cur->bc, wo, wi);
    }
    *beta = vmul(cur->beta, w);
    if (mode == TRANSPORT_IMPORTANCE) *beta = vscale(*beta, adjoint_shading_factor(cur, cur->wi, d));
    if (vzero(*beta) || !vfinite(*beta)) return false;
    prev->pdf_rev = cur->delta ? 0 : edge_pdf(pdf_back, cur, prev, vneg(cur->wi), vlen2(vsub(cur->p, prev->p)));
    return true;
}

/* The step from v[n-1] (n >= 1: an emitter vertex or a surface) to path vertex `next`: v[n] = next
 * as the walk reaches it, with its beta and pdf_fwd (and v[n-2].pdf_rev, path_leave). */
static bool step_to(const struct path_ctx *pc, struct vertex *v, int n, const struct vertex *next, enum transport mode)
{
    struct vertex *cur = &v[n - 1], *out = &v[n];
    double dist2, pdf_sa;
    vec3 d = edge_dir(cur, next, &dist2);
    rgb beta;
    if (!path_leave(pc, v, n, d, mode, &beta, &pdf_sa)) return false;
    if (next->kind == VK_ENV) {
        env_vertex(pc->sc, cur->p, d, out);
        out->pdf_fwd = pdf_sa;
    } else {
        arrive(pc->sc, next, d, out);
        out->pdf_fwd = cur->delta ? 0 : edge_pdf(pdf_sa, cur, out, d, dist2);
    }
    out->beta = beta;
    return true;
}

/* The emitter subpath's first vertex from path vertex x (an emitter vertex, a camera hit on an
 * emitter, or the environment), followed by next (or NULL). */
static bool emitter_start(const struct scene *sc, const struct vertex *x, const struct vertex *next, struct vertex *y)
{
    double pick = emitter_pick_prob(sc, x->prim);
    if (x->kind == VK_ENV) {
        vertex_start(y, VK_ENV, x->prim, -1);
        /* a point of the ray, which only the inversion reads (it projects it onto the origin disc
         * along the direction): the vertex the ray reaches, when there is one, since a path moved
         * at x_1 (a fused lens perturbation) keeps x_0's direction but not its ray */
        y->p = next ? next->p : x->p;
        y->ng = y->wi = x->ng;
        y->sh = frame_from_normal(y->ng);
        y->pdf_fwd = pick * env_pdf_dir(sc, env_dir(y));
    } else {
        vec3 n = x->kind == VK_SURFACE && x->flipped ? vneg(x->ng) : x->ng;
        vertex_start(y, VK_EMITTER, x->prim, x->tri);
        y->p = x->p;
        y->ng = n;
        y->sh = frame_from_normal(n);
        y->pdf_fwd = pick * emitter_pdf_pos(sc, x->prim, x->p);
    }
    y->beta = v3s(1.0 / y->pdf_fwd);
    return y->pdf_fwd > 0 && vfinite(y->beta);
}

bool path_emitter_form(const struct path_ctx *pc, const struct vertex *const *x, int n, struct vertex *y)
{
    if (!emitter_start(pc->sc, x[0], n > 1 ? x[1] : NULL, &y[0])) return false;
    for (int i = 1; i < n; i++)
        if (!step_to(pc, y, i, x[i], TRANSPORT_IMPORTANCE)) return false;
    return true;
}

bool path_camera_form(const struct path_ctx *pc, const struct vertex *const *x, int k, int n, struct vertex *z)
{
    const struct scene *sc = pc->sc;
    const struct camera *cam = &sc->cam;
    vertex_start(&z[0], VK_CAMERA, -1, -1);
    z[0].p = x[k]->p;
    z[0].ng = cam->basis.n;
    z[0].sh = cam->basis;
    z[0].beta = v3s(1);
    z[0].pdf_fwd = cam->lens_radius > 0 ? 1.0 / (M_PI * sqr(cam->lens_radius)) : 1;
    if (n == 1) return true;
    double dist2;
    vec3 d = edge_dir(&z[0], x[k - 1], &dist2);
    double pdf = camera_raster(cam, z[0].p, d, &z[0].px, &z[0].py);
    if (!(pdf > 0)) return false;
    if (x[k - 1]->kind == VK_ENV) {
        env_vertex(sc, z[0].p, d, &z[1]);
        z[1].pdf_fwd = pdf;
    } else {
        arrive(sc, x[k - 1], d, &z[1]);
        z[1].pdf_fwd = edge_pdf(pdf, &z[0], &z[1], d, dist2);
    }
    z[1].beta = v3s(1);
    for (int i = 2; i < n; i++)
        if (!step_to(pc, z, i, x[k - i], TRANSPORT_RADIANCE)) return false;
    return true;
}
