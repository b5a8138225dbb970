/* Random walks, thesis Alg. 1: every number comes from the sampler, in fixed per-vertex blocks. */
#include "base/util.h"
#include "camera/camera.h"
#include "emitter/emitter.h"
#include "path/path.h"

bool walk_hit(const struct scene *sc, const struct vertex *prev, vec3 d, struct vertex *out)
{
    struct hit h;
    double eps = prev->kind == VK_CAMERA ? 0 : ray_eps(prev->p);
    if (!accel_intersect(sc->accel, prev->p, d, eps, INFINITY, &h)) return false;
    surface_from_hit(sc, prev->p, d, &h, out);
    return true;
}

/* Whether the ray from p along unit d is known to reach `to` without being cast: `to` is a surface
 * vertex of the path being re-walked whose segment from p is unoccluded (an edge or the connection
 * of the current path), and d points at it within float noise (PITP's retrace, core/mcmc/docs/pitp.md,
 * "Ray-free retrace"). The bound, 1e-9 of the coordinates' magnitude off the line, is far below
 * the 1e-7 a float ray resolves, so the ray, had it been cast, could only have hit `to` or a
 * surface within float noise of it. Very short segments, which the ray's self-intersection offset
 * may skip, and directions a float ray would resolve differently are left to the ray. *t: the
 * distance along d. */
static bool on_known_segment(vec3 p, vec3 d, const struct vertex *to, double *t)
{
    if (!to || to->kind != VK_SURFACE) return false;
    vec3 e = vsub(to->p, p);
    *t = vdot(e, d);
    if (!(*t > 4 * ray_eps(p))) return false;
    return vlen2(vsub(e, vscale(d, *t))) <= sqr(1e-9 * coord_scale(to->p));
}

/* The vertex the ray from prev along d reaches when on_known_segment says it is `to`: `to`'s own
 * hit point, set up as a hit of this ray. */
static bool known_hit(const struct scene *sc, const struct vertex *prev, vec3 d, const struct vertex *to,
                      struct vertex *out)
{
    double t;
    if (!on_known_segment(prev->p, d, to, &t)) return false;
    struct hit h = {.t = t, .prim = to->prim, .tri = to->tri, .b1 = to->b1, .b2 = to->b2};
    surface_from_hit(sc, prev->p, d, &h, out);
    return true;
}

/* The direction the BSDF sample of the current block sends a walk in from `cur` (a surface with a
 * BSDF, reached along -cur->wi; wi: that direction in its shading frame), and the throughput the
 * next vertex receives. False ends the walk: no sample, a direction on which the shading and the
 * geometric normal disagree (it would leak light), or no throughput left. Writes no vertex. */
static inline bool scatter_dir(struct sampler *s, const struct vertex *cur, vec3 wi, enum transport mode,
                               struct bsdf_sample *bs, vec3 *wo, rgb *beta)
{
    if (!bsdf_sample(&cur->bc, wi, s, mode, bs)) return false;
    *wo = frame_to_world(&cur->sh, bs->wo);
    if ((vdot(*wo, cur->ng) > 0) != (bs->wo.z > 0)) return false;
    rgb b = vmul(cur->beta, bs->weight);
    if (mode == TRANSPORT_IMPORTANCE) b = vscale(b, adjoint_shading_factor(cur, cur->wi, *wo));
    if (vzero(b) || !vfinite(b)) return false;
    *beta = b;
    return true;
}

/* Samples the direction leaving v[n-1] (n >= 2, a surface with a BSDF) from its block: the
 * outgoing direction *d, its solid-angle density *pdf_sa (0 for a delta lobe) and the throughput
 * *beta the next vertex receives; sets v[n-1].delta and v[n-2].pdf_rev. False ends the walk. The
 * incoming direction is -v[n-1].wi, bit for bit the ray that reached it. */
static inline bool scatter_at(struct sampler *s, struct vertex *v, int n, enum transport mode, int stream, vec3 *d,
                              double *pdf_sa, rgb *beta)
{
    struct vertex *prev = &v[n - 2], *cur = &v[n - 1];
    sampler_begin(s, stream, n - 1);
    vec3 wi = frame_to_local(&cur->sh, cur->wi);
    struct bsdf_sample bs;
    if (!scatter_dir(s, cur, wi, mode, &bs, d, beta)) return false;
    cur->delta = bs.delta;
    double dist2 = vlen2(vsub(cur->p, prev->p));
    prev->pdf_rev = bs.delta ? 0 : edge_pdf(bsdf_pdf(&cur->bc, bs.wo, wi), cur, prev, vneg(cur->wi), dist2);
    *pdf_sa = bs.delta ? 0 : bs.pdf;
    return true;
}

/* Whether a step from p along d reaches the surface vertex `to` within tol: without a ray where
 * on_known_segment says so, else by the walk's own ray (vertex_same). */
static bool step_reaches(const struct scene *sc, const struct vertex *from, vec3 d, const struct vertex *to, double tol)
{
    double t;
    if (on_known_segment(from->p, d, to, &t)) return true;
    struct vertex hit;
    return walk_hit(sc, from, d, &hit) && vertex_same(&hit, to, tol);
}

bool walk_step_reaches(const struct path_ctx *pc, struct sampler *s, const struct vertex *v, int n, int stream,
                       const struct vertex *to, double tol)
{
    ASSERT(n >= 2 || (n == 1 && stream == STREAM_CAMERA));
    vec3 d;
    if (n == 1) {
        /* the camera's block 0: the lens point (v[0]'s, within rounding), then the image position */
        const struct camera *cam = &pc->sc->cam;
        double pdf, px, py;
        sampler_begin(s, STREAM_CAMERA, 0);
        vec3 lens = camera_sample_lens(cam, s, &pdf);
        d = camera_sample_dir(cam, lens, s, &px, &py, &pdf);
        return step_reaches(pc->sc, &v[0], d, to, tol);
    }
    const struct vertex *cur = &v[n - 1];
    if (!cur->bc.b) return false;
    struct bsdf_sample bs;
    rgb beta;
    sampler_begin(s, stream, n - 1);
    enum transport mode = stream == STREAM_CAMERA ? TRANSPORT_RADIANCE : TRANSPORT_IMPORTANCE;
    return scatter_dir(s, cur, frame_to_local(&cur->sh, cur->wi), mode, &bs, &d, &beta) &&
           step_reaches(pc->sc, cur, d, to, tol);
}

/* Extends a subpath whose last vertex v[n-1] emits direction d with solid-angle density pdf_sa
 * (0 for a delta lobe); beta is the throughput the next vertex receives. `to`, when not NULL, is
 * the vertex the first step is expected to reach (known_hit). */
static int trace(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int max_verts, vec3 d,
                 double pdf_sa, rgb beta, enum transport mode, int stream, const struct vertex *to)
{
    const struct scene *sc = pc->sc;
    while (n < max_verts) {
        struct vertex *prev = &v[n - 1], *cur = &v[n];
        bool known = known_hit(sc, prev, d, to, cur);
        to = NULL;
        if (!known && !walk_hit(sc, prev, d, cur)) {
            /* A camera subpath that leaves the scene ends on the environment. */
            if (stream == STREAM_CAMERA && sc->env_prim >= 0) {
                env_vertex(sc, prev->p, d, cur);
                cur->beta = beta;
                cur->pdf_fwd = pdf_sa;
                n++;
            }
            break;
        }
        double dist2 = vlen2(vsub(cur->p, prev->p));
        cur->beta = beta;
        cur->pdf_fwd = pdf_sa > 0 ? edge_pdf(pdf_sa, prev, cur, d, dist2) : 0;
        n++;
        if (!cur->bc.b || n >= max_verts) break;
        if (!scatter_at(s, v, n, mode, stream, &d, &pdf_sa, &beta)) break;
    }
    return n;
}

static int camera_walk(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                       const struct vertex *to);
static int emitter_walk(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                        const struct vertex *to);
static int camera_leave(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                        const struct vertex *to);
static int emitter_leave(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                         const struct vertex *to);

static int extend_walk(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int max_verts, int stream,
                       const struct vertex *to)
{
    if (n < 2)
        return stream == STREAM_CAMERA ? camera_walk(pc, s, v, max_verts, to) : emitter_walk(pc, s, v, max_verts, to);
    if (n >= max_verts || !v[n - 1].bc.b) return n;
    enum transport mode = stream == STREAM_CAMERA ? TRANSPORT_RADIANCE : TRANSPORT_IMPORTANCE;
    vec3 d;
    double pdf_sa;
    rgb beta;
    if (!scatter_at(s, v, n, mode, stream, &d, &pdf_sa, &beta)) return n;
    return trace(pc, s, v, n, max_verts, d, pdf_sa, beta, mode, stream, to);
}

int walk_extend(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int max_verts, int stream)
{
    return extend_walk(pc, s, v, n, max_verts, stream, NULL);
}

int walk_extend_from(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int max_verts, int stream)
{
    if (n != 1 || max_verts <= 1) return extend_walk(pc, s, v, n, max_verts, stream, NULL);
    sampler_begin(s, stream, 0);
    if (stream == STREAM_CAMERA) return camera_leave(pc, s, v, max_verts, NULL);
    if (v[0].kind == VK_ENV) { /* a direction: its ray's origin is a point of the origin disc, drawn anew */
        double pdf_disc;
        v[0].p = env_sample_origin(pc->sc, env_dir(&v[0]), s, &pdf_disc);
    }
    return emitter_leave(pc, s, v, max_verts, NULL);
}

int walk_extend_to(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int n, int stream,
                   const struct vertex *to)
{
    return extend_walk(pc, s, v, n, n + 1, stream, to);
}

int walk_camera(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts)
{
    return camera_walk(pc, s, v, max_verts, NULL);
}

static int camera_walk(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                       const struct vertex *to)
{
    const struct camera *cam = &pc->sc->cam;
    if (max_verts < 1) return 0;
    sampler_begin(s, STREAM_CAMERA, 0);
    struct vertex *z = &v[0];
    /* The pinhole's vertex is written in place, its lens point not passed around: every walk
     * starts here (camera_sample_lens and camera_sample_dir, spelt out). */
    bool thin_lens = cam->lens_radius > 0;
    vertex_start(z, VK_CAMERA, -1, -1);
    z->p = cam->pos;
    z->ng = cam->basis.n;
    z->sh = cam->basis;
    z->beta = v3s(1);
    z->pdf_fwd = 1;
    if (thin_lens) z->p = camera_sample_disc(cam, s, &z->pdf_fwd);
    /* A lone camera vertex (light tracing's t = 1) gets its raster position from the connection:
     * drawing a direction would cost two numbers (and, under MCMC, two mutations) for nothing. */
    if (max_verts == 1) return 1;
    return camera_leave(pc, s, v, max_verts, to);
}

/* The primary ray from the camera vertex v[0] (its image position from the current block), and
 * the walk from there. */
static int camera_leave(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                        const struct vertex *to)
{
    const struct camera *cam = &pc->sc->cam;
    struct vertex *z = &v[0];
    double pdf;
    vec3 d = cam->lens_radius > 0 ? camera_sample_dir_lens(cam, z->p, s, &z->px, &z->py, &pdf)
                                  : camera_sample_dir_pinhole(cam, s, &z->px, &z->py, &pdf);
    return trace(pc, s, v, 1, max_verts, d, pdf, v3s(1), TRANSPORT_RADIANCE, STREAM_CAMERA, to);
}

/* A point on area emitter `prim`, chosen with probability pick. */
static bool sample_area_emitter(const struct scene *sc, int prim, double pick, struct sampler *s, struct vertex *y)
{
    struct emitter_pos pos;
    if (!emitter_sample_pos(sc, prim, s, &pos) || !(pos.pdf > 0)) return false;
    vertex_start(y, VK_EMITTER, prim, pos.tri);
    y->p = pos.p;
    y->ng = pos.n;
    y->sh = frame_from_normal(pos.n);
    y->pdf_fwd = pick * pos.pdf;
    y->beta = v3s(1.0 / y->pdf_fwd);
    return true;
}

bool sample_emitter_vertex(const struct scene *sc, struct sampler *s, struct vertex *y)
{
    double pick;
    int prim = emitter_pick(sc, s, &pick);
    if (prim < 0) return false;
    return prim == sc->env_prim ? sample_env_emitter(sc, pick, s, y) : sample_area_emitter(sc, prim, pick, s, y);
}

bool sample_env_emitter(const struct scene *sc, double pick, struct sampler *s, struct vertex *y)
{
    vec3 d;
    double pdf, pdf_disc;
    if (!env_sample_dir(sc, s, &d, &pdf) || !(pdf > 0)) return false;
    vec3 origin = env_sample_origin(sc, d, s, &pdf_disc);
    vertex_start(y, VK_ENV, sc->env_prim, -1);
    y->p = origin;
    y->ng = y->wi = vneg(d);
    y->sh = frame_from_normal(y->ng);
    y->pdf_fwd = pick * pdf;
    y->beta = v3s(1.0 / y->pdf_fwd);
    return true;
}

int walk_emitter(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts)
{
    return emitter_walk(pc, s, v, max_verts, NULL);
}

static int emitter_walk(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                        const struct vertex *to)
{
    const struct scene *sc = pc->sc;
    if (max_verts < 1) return 0;
    sampler_begin(s, STREAM_EMITTER, 0);
    if (!sample_emitter_vertex(sc, s, &v[0])) return 0;
    /* A lone emitter vertex (s = 1) is only connected to: the direction it would emit along is
     * never used (as for the camera in walk_camera). */
    if (max_verts == 1) return 1;
    return emitter_leave(pc, s, v, max_verts, to);
}

/* The ray the emitter vertex v[0] emits (its direction from the current block), and the walk
 * from there. */
static int emitter_leave(const struct path_ctx *pc, struct sampler *s, struct vertex *v, int max_verts,
                         const struct vertex *to)
{
    const struct scene *sc = pc->sc;
    if (v[0].kind == VK_ENV) {
        /* rays leave the origin disc (area density 1 / (pi R^2), cosine 1) against env_dir */
        double pdf_disc = 1.0 / (M_PI * sqr(env_radius(sc)));
        rgb beta = vscale(vmul(v[0].beta, env_radiance(sc, env_dir(&v[0]))), 1.0 / pdf_disc);
        return trace(pc, s, v, 1, max_verts, vneg(env_dir(&v[0])), pdf_disc, beta, TRANSPORT_IMPORTANCE, STREAM_EMITTER,
                     to);
    }
    double pdf_dir;
    vec3 d = emitter_sample_dir(v[0].ng, s, &pdf_dir);
    rgb le = emitter_radiance(sc, v[0].prim, v[0].ng, d);
    double c = fabs(vdot(d, v[0].ng));
    if (!(pdf_dir > 0) || vzero(le)) return 1;
    rgb beta = vscale(vmul(v[0].beta, le), c / pdf_dir);
    return trace(pc, s, v, 1, max_verts, d, pdf_dir, beta, TRANSPORT_IMPORTANCE, STREAM_EMITTER, to);
}
