/* Vertices from ray hits, density conversion, emission and visibility between vertices. */
#include "bsdf/bsdf_smooth.h"
#include "emitter/emitter.h"
#include "path/path.h"
#include "scene/accel.h"

/* Self-intersection offset relative to the coordinates' magnitude (Embree works in float). */
double ray_eps(vec3 p) { return 2e-5 * coord_scale(p); }

/* Tungsten's sphere parametrisation: poles on the local Z axis, u = atan2(y, x) / 2pi + 0.5,
 * v = acos(z) / pi of the local unit normal. */
void sphere_uv(const struct prim *pr, vec3 n, double uv[2])
{
    vec3 l = v3(vdot(pr->sphere_axis[0], n), vdot(pr->sphere_axis[1], n), vdot(pr->sphere_axis[2], n));
    uv[0] = atan2(l.y, l.x) * (0.5 / M_PI) + 0.5;
    uv[1] = acos(fmin(1.0, fmax(-1.0, l.z))) * (1 / M_PI);
}

/* textures: the surface's tangents at a hit, as Tungsten's tangentSpace() gives them (the bump
 * map's slope is added along them, so their length sets its scale): quads their edges (dp/du,
 * dp/dv); triangles the directions of dp/du and dp/dv from the uv parameterisation, unit length,
 * with TriangleMesh's sign (both flipped where the uv map reverses orientation); cubes their unit
 * axes along u and v (Cube.cpp); spheres Tungsten's T = R (-l.y, l.x, l.z) of the local normal l
 * and B = n x T. False where there is none (a mesh without uv or with degenerate uv). */
static bool hit_tangents(const struct prim *pr, const struct vertex *v, vec3 n, vec3 *T, vec3 *B)
{
    if (pr->kind == PRIM_QUAD) {
        *T = pr->quad_edge0;
        *B = pr->quad_edge1;
        return true;
    }
    if (pr->kind == PRIM_SPHERE) {
        const vec3 *a = pr->sphere_axis;
        vec3 l = v3(vdot(a[0], n), vdot(a[1], n), vdot(a[2], n));
        *T = vadd(vadd(vscale(a[0], -l.y), vscale(a[1], l.x)), vscale(a[2], l.z));
        *B = vcross(n, *T);
        return true;
    }
    if (!pr->uv) return false;
    const int *t = pr->tri + 3 * v->tri;
    const double *uv0 = pr->uv + 2 * t[0], *uv1 = pr->uv + 2 * t[1], *uv2 = pr->uv + 2 * t[2];
    vec3 q1 = vsub(pr->p[t[1]], pr->p[t[0]]), q2 = vsub(pr->p[t[2]], pr->p[t[0]]);
    double s1 = uv1[0] - uv0[0], t1 = uv1[1] - uv0[1], s2 = uv2[0] - uv0[0], t2 = uv2[1] - uv0[1];
    double det = s1 * t2 - s2 * t1;
    if (fabs(det) < 1e-6) return false;
    vec3 tu = vsub(vscale(q1, t2), vscale(q2, t1)), tv = vsub(vscale(q2, s1), vscale(q1, s2));
    if (!(vlen2(tu) > 0 && vlen2(tv) > 0)) return false;
    double sign = pr->cube_tangents && det < 0 ? -1 : 1; /* dp/du = tu / det */
    *T = vscale(vnorm(tu), sign);
    *B = vscale(vnorm(tv), sign);
    return true;
}

/* textures: the shading normal a bump map gives at the hit (Tungsten's setupTangentFrame): the
 * tangents T, B get the height slope (du, dv) of texture_derivs as their component along n,
 * T' = T + n (du - n.T), B' = B + n (dv - n.B), and the normal is T' x B' on n's side. So a height
 * rising along T tilts the normal toward -T; along B, the slope's sign is Tungsten's, whose dv runs
 * down the image rows (-v), so a height rising with v tilts the normal toward +B. Falls back to n
 * where there are no tangents or T' x B' vanishes. */
static vec3 bump_normal(const struct prim *pr, const struct vertex *v, const struct texture *bump, const double uv[2],
                        vec3 n)
{
    vec3 T, B;
    if (!hit_tangents(pr, v, n, &T, &B)) return n;
    double d[2];
    texture_derivs(bump, uv[0], uv[1], d);
    T = vmad(T, n, d[0] - vdot(n, T));
    B = vmad(B, n, d[1] - vdot(n, B));
    vec3 m = vcross(T, B);
    double l2 = vlen2(m);
    if (!(l2 > 0) || !isfinite(l2)) return n;
    m = vscale(m, (vdot(m, n) < 0 ? -1 : 1) / sqrt(l2));
    return m;
}

/* textures: the hit's texture coordinates (spheres by sphere_uv of the geometric normal, meshes
 * interpolated; (0, 0) on a mesh without them). */
static void hit_uv(const struct prim *pr, const struct vertex *v, double uv[2])
{
    uv[0] = uv[1] = 0;
    if (pr->kind == PRIM_SPHERE) {
        sphere_uv(pr, v->ng, uv);
        return;
    }
    if (!pr->uv) return;
    const int *t = pr->tri + 3 * v->tri;
    double b0 = 1.0 - v->b1 - v->b2;
    for (int c = 0; c < 2; c++)
        uv[c] = b0 * pr->uv[2 * t[0] + c] + v->b1 * pr->uv[2 * t[1] + c] + v->b2 * pr->uv[2 * t[2] + c];
}

void surface_from_hit(const struct scene *sc, vec3 o, vec3 d, const struct hit *h, struct vertex *v)
{
    const struct prim *pr = &sc->prims[h->prim];
    const struct bsdf *b = pr->bsdf >= 0 && sc->bsdfs[pr->bsdf].type != BSDF_NULL ? &sc->bsdfs[pr->bsdf] : NULL;
    v->kind = VK_SURFACE;
    v->prim = h->prim;
    v->tri = pr->kind == PRIM_SPHERE ? -1 : h->tri;
    v->b1 = h->b1;
    v->b2 = h->b2;
    vec3 ns;
    if (pr->kind == PRIM_SPHERE) {
        vec3 q = vsub(vmad(o, d, h->t), pr->center);
        v->ng = vnorm(q);
        v->p = vmad(pr->center, v->ng, pr->radius); /* back onto the sphere in double precision */
        ns = v->ng;
    } else {
        const int *t = pr->tri + 3 * v->tri;
        vec3 p0 = pr->p[t[0]], p1 = pr->p[t[1]], p2 = pr->p[t[2]];
        v->p = vadd(p0, vadd(vscale(vsub(p1, p0), h->b1), vscale(vsub(p2, p0), h->b2)));
        v->ng = pr->tri_n[v->tri];
        ns = v->ng;
        if (pr->n) {
            double b0 = 1.0 - h->b1 - h->b2;
            vec3 n = vadd(vadd(vscale(pr->n[t[0]], b0), vscale(pr->n[t[1]], h->b1)), vscale(pr->n[t[2]], h->b2));
            if (vlen2(n) > 0) ns = vnorm(n);
            if (vdot(ns, v->ng) < 0) ns = vneg(ns);
        }
    }
    v->wi = vneg(d);
    v->front = vdot(v->ng, v->wi) > 0;
    /* Untextured surfaces (most) take the BSDF's constants and skip the uv: every walk builds
     * one of these per hit, so this path is kept short (instruction counts, issue 29). */
    if (!b) {
        v->bc = (struct bsdf_ctx){.b = NULL};
    } else if (!b->needs_uv) {
        v->bc = (struct bsdf_ctx){.b = b, .albedo = b->albedo, .roughness = b->roughness};
    } else {
        double uv[2];
        hit_uv(pr, v, uv);
        v->bc = bsdf_ctx_textured(b, uv);
        /* A bump map makes the shading frame a function of the hit point alone (its uv and
         * tangents), like an interpolated normal: the BSDF's inversion, which works in this
         * frame, needs nothing more. */
        if (b->bump_tex) ns = bump_normal(pr, v, b->bump_tex, uv, ns);
    }
    /* Two-sided shading: opaque surfaces seen from the back shade as if seen from the front. */
    v->flipped = false;
    if (!v->front && b && sc->two_sided_shading && !b->transmissive) {
        v->ng = vneg(v->ng);
        ns = vneg(ns);
        v->flipped = true;
    }
    v->sh = frame_from_normal(ns);
    v->delta = false;
    v->pdf_fwd = v->pdf_rev = 0;
}

double adjoint_shading_factor(const struct vertex *v, vec3 wi, vec3 wo)
{
    vec3 ns = v->sh.n, ng = v->ng;
    if (ns.x == ng.x && ns.y == ng.y && ns.z == ng.z) return 1.0;
    double den = fabs(vdot(wi, ng)) * fabs(vdot(wo, ns));
    return den > 0 ? fabs(vdot(wi, ns)) * fabs(vdot(wo, ng)) / den : 0.0;
}

double edge_pdf(double pdf, const struct vertex *from, const struct vertex *to, vec3 d, double dist2)
{
    if (to->kind == VK_ENV) return pdf;
    double c = to->kind == VK_CAMERA ? 1.0 : fabs(vdot(to->ng, d));
    if (from->kind == VK_ENV) return pdf * c;
    return dist2 > 0 ? pdf * c / dist2 : 0;
}

vec3 edge_dir(const struct vertex *a, const struct vertex *b, double *dist2)
{
    if (b->kind == VK_ENV || a->kind == VK_ENV) {
        *dist2 = 1;
        return b->kind == VK_ENV ? env_dir(b) : vneg(env_dir(a));
    }
    vec3 d = vsub(b->p, a->p);
    *dist2 = vlen2(d);
    return *dist2 > 0 ? vscale(d, 1.0 / sqrt(*dist2)) : d;
}

rgb vertex_emission(const struct scene *sc, const struct vertex *v, vec3 w)
{
    if (v->kind == VK_ENV) return env_radiance(sc, env_dir(v));
    const struct prim *pr = &sc->prims[v->prim];
    if (!pr->emissive) return v3s(0);
    /* ng may be flipped by two-sided shading; emission follows the geometry's own front. */
    vec3 n = v->flipped ? vneg(v->ng) : v->ng;
    return emitter_radiance(sc, v->prim, n, w);
}

bool visible(const struct scene *sc, const struct vertex *a, const struct vertex *b)
{
    if (a->kind == VK_ENV || b->kind == VK_ENV) {
        const struct vertex *f = a->kind == VK_ENV ? b : a, *e = a->kind == VK_ENV ? a : b;
        double eps = f->kind == VK_CAMERA ? 0 : ray_eps(f->p);
        return !accel_occluded(sc->accel, f->p, env_dir(e), eps, INFINITY);
    }
    vec3 d = vsub(b->p, a->p);
    double dist = vlen(d);
    if (dist == 0) return false;
    d = vscale(d, 1.0 / dist);
    double ea = a->kind == VK_CAMERA ? 0 : ray_eps(a->p), eb = b->kind == VK_CAMERA ? 0 : ray_eps(b->p);
    if (dist <= ea + eb) return true;
    return !accel_occluded(sc->accel, a->p, d, ea, dist - eb);
}

void env_vertex(const struct scene *sc, vec3 p, vec3 d, struct vertex *out)
{
    *out = (struct vertex){.kind = VK_ENV,
                           .p = p,
                           .ng = vneg(d),
                           .sh = frame_from_normal(vneg(d)),
                           .front = true,
                           .prim = sc->env_prim,
                           .tri = -1,
                           .wi = vneg(d)};
}

double vertex_radiance_factor(const struct vertex *v, vec3 wc, vec3 wl)
{
    if (v->kind != VK_SURFACE || !v->bc.b) return 1;
    const struct bsdf *b = v->bc.b;
    if (!b->refracts) return 1; /* b->refracts: a dielectric, also nested in a mixed or transparency BSDF */
    bool out_c = vdot(wc, v->sh.n) > 0, out_l = vdot(wl, v->sh.n) > 0; /* transmissive: never flipped */
    if (out_c == out_l) return 1;
    /* transparency's straight-through lobe crosses without refracting */
    if (b->pass_through && smooth_same_dir(wc, vneg(wl))) return 1;
    double ec = out_c ? 1 : b->refract_ior, el = out_l ? 1 : b->refract_ior;
    return sqr(ec / el);
}
