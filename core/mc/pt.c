/* Path tracer: techniques s = 0 (emission hit, or escape to the environment) and s = 1 (a light
 * sample at every vertex), weighted against each other only (balance heuristic).
 *
 * A dedicated loop rather than walk_camera + connect_st: the path tracer needs neither the reverse
 * densities of every vertex nor the full-path MIS arrays, only two densities of each technique's
 * last vertex. The weights are those connect_st gives for max_s = 1:
 *   emission hit at z_k:  1 / (1 + p_light / p_bsdf), both as area densities of z_k (solid angle
 *                         for the environment), p_light including the light-pick probability;
 *                         1 for k = 1 (no light sample at the camera) and after a delta lobe;
 *   light sample at z_i:  1 / (1 + p_bsdf / p_light), same measures.
 * For the environment the origin disc of BDPT's emitter vertex plays no part: only directions.
 *
 * One pass: each vertex's emission hit and light sample are evaluated as the walk reaches it, so
 * no vertex is stored. The numbers come from BDPT's blocks (camera block i for the BSDF sample at
 * vertex i, emitter block i for its light sample): fed the same number in every dimension (a
 * replayed vector), the estimator equals the BDPT machinery restricted to s <= 1 sample for
 * sample (tests/test_pt_twin.c). A sequential sampler hands the numbers out in a different order
 * than BDPT's walk-first one, which changes which numbers land where, not their distribution. */
#include "camera/camera.h"
#include "emitter/emitter.h"
#include "mc/integrator.h"

/* Each technique's term is checked on its own, so that a non-finite one is counted at its length
 * and drops only itself, as in BDPT (the twin test compares the two sample by sample). */
static inline void add_term(rgb *sum, rgb v, struct nonfinite *nf, int k)
{
    v = nonfinite_inject(v);
    if (vfinite(v))
        *sum = vadd(*sum, v);
    else
        nf->len[k]++;
}

struct pt_vertex {
    struct vertex v;  /* kind, p, ng, sh, front, prim, bc, wi (world); VK_ENV: wi = -direction */
    vec3 wi;          /* v.wi in the shading frame */
    rgb beta;         /* throughput arriving at the vertex */
    double pdf_sa;    /* solid-angle density of the direction that reached it */
    bool after_delta; /* ... which a delta lobe chose (or the camera: no light sample there) */
    double dist2;     /* squared length of that segment */
    double eps;       /* ray_eps(v.p) */
};

/* Emitted radiance reaching the camera through z, MIS-weighted against light sampling. */
static rgb emission_hit(const struct scene *sc, const struct pt_vertex *z)
{
    const struct vertex *v = &z->v;
    rgb f;
    if (v->kind == VK_ENV) {
        vec3 d = vneg(v->wi);
        f = vmul(z->beta, env_radiance(sc, d));
        if (vzero(f) || z->after_delta) return f;
        double pl = emitter_pick_prob(sc, sc->env_prim) * env_pdf_dir(sc, d);
        return vscale(f, z->pdf_sa / (z->pdf_sa + pl));
    }
    if (!v->front || !sc->prims[v->prim].emissive) return v3s(0);
    f = vmul(z->beta, vertex_emission(sc, v, v->wi));
    if (vzero(f) || z->after_delta) return f;
    /* Both densities times dist2: one division. */
    double pl = emitter_pick_prob(sc, v->prim) * emitter_pdf_pos(sc, v->prim, v->p) * z->dist2;
    double pb = z->pdf_sa * fabs(vdot(v->ng, v->wi));
    return vscale(f, pb / (pb + pl));
}

/* The MIS-weighted light sample at z, whose BSDF's operations are ops (numbers from the current
 * emitter-stream block).
 * Contribution times weight, f G / p_light * p_light / (p_light + p_bsdf), is
 * f G / (p_light + p_bsdf): one division instead of three. */
static rgb light_sample(const struct scene *sc, struct sampler *s, const struct pt_vertex *z,
                        const struct bsdf_ops *ops)
{
    double pick;
    int prim = emitter_pick(sc, s, &pick);
    if (prim < 0) return v3s(0);
    const struct vertex *v = &z->v;
    if (prim == sc->env_prim) {
        vec3 d;
        double pdf;
        if (!env_sample_dir(sc, s, &d, &pdf) || !(pdf > 0)) return v3s(0);
        /* BDPT's environment vertex draws a point of the origin disc next; the path tracer needs
         * none but skips the numbers so that later blocks line up with it. */
        sampler_next(s, DIM_CONTINUOUS);
        sampler_next(s, DIM_CONTINUOUS);
        vec3 wo = frame_to_local(&v->sh, d);
        rgb f = vmul(vmul(env_radiance(sc, d), ops->eval(&v->bc, z->wi, wo, TRANSPORT_RADIANCE)), z->beta);
        if (vzero(f) || accel_occluded(sc->accel, v->p, d, z->eps, INFINITY)) return v3s(0);
        double pb = ops->pdf(&v->bc, z->wi, wo);
        return vscale(f, fabs(wo.z) / (pick * pdf + pb));
    }
    struct emitter_pos pos;
    if (!emitter_sample_pos(sc, prim, s, &pos) || !(pos.pdf > 0)) return v3s(0);
    vec3 d = vsub(v->p, pos.p); /* from the light toward z, as visible() traces it */
    double dist2 = vlen2(d);
    if (dist2 == 0) return v3s(0);
    /* emitter_radiance looks only at the side d leaves on: no need to wait for the normalisation,
     * and points behind the light skip it. */
    rgb le = emitter_radiance(sc, prim, pos.n, d);
    if (vzero(le)) return v3s(0);
    double dist = sqrt(dist2);
    d = vscale(d, 1.0 / dist);
    vec3 wo = frame_to_local(&v->sh, vneg(d));
    rgb f = vmul(vmul(le, ops->eval(&v->bc, z->wi, wo, TRANSPORT_RADIANCE)), z->beta);
    if (vzero(f)) return v3s(0);
    double ey = ray_eps(pos.p);
    if (dist > ey + z->eps && accel_occluded(sc->accel, pos.p, d, ey, dist - z->eps)) return v3s(0);
    /* Both densities as area densities at the light, times dist2. */
    double cos_y = fabs(vdot(pos.n, d));
    double pb = ops->pdf(&v->bc, z->wi, wo) * cos_y;
    return vscale(f, cos_y * fabs(wo.z) / (pick * pos.pdf * dist2 + pb));
}

void pt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img)
{
    const struct scene *sc = pc->sc;
    int max_verts = pc->max_length + 1;
    double px, py;
    sampler_begin(s, STREAM_CAMERA, 0);
    double pdf_lens;
    vec3 o = camera_sample_lens(&sc->cam, s, &pdf_lens), d = camera_sample_dir(&sc->cam, o, s, &px, &py, NULL);
    double eps = 0;
    struct pt_vertex z = {.beta = v3s(1), .pdf_sa = 0, .after_delta = true};
    rgb sum = v3s(0);
    for (int i = 1; i < max_verts; i++) { /* z becomes vertex i */
        struct hit h;
        if (!accel_intersect(sc->accel, o, d, eps, INFINITY, &h)) {
            if (sc->env_prim >= 0) {
                z.v.kind = VK_ENV;
                z.v.wi = vneg(d);
                if (i >= pc->min_length) add_term(&sum, emission_hit(sc, &z), &w->nf, i);
            }
            break;
        }
        surface_from_hit(sc, o, d, &h, &z.v);
        z.dist2 = vlen2(vsub(z.v.p, o));
        if (i >= pc->min_length) add_term(&sum, emission_hit(sc, &z), &w->nf, i); /* a path of i segments */
        /* The last vertex takes no light sample (it would exceed max_length). */
        if (!z.v.bc.b || i + 1 >= max_verts) break;
        const struct bsdf_ops *ops = bsdf_ops_for(z.v.bc.b->type);
        z.wi = frame_to_local(&z.v.sh, z.v.wi);
        z.eps = ray_eps(z.v.p);
        if (!z.v.bc.b->delta_only && i + 1 >= pc->min_length) {
            sampler_begin(s, STREAM_EMITTER, i);
            add_term(&sum, light_sample(sc, s, &z, ops), &w->nf, i + 1);
        }
        sampler_begin(s, STREAM_CAMERA, i);
        struct bsdf_sample bs;
        if (!ops->sample(&z.v.bc, z.wi, s, TRANSPORT_RADIANCE, &bs)) break;
        vec3 wo = frame_to_world(&z.v.sh, bs.wo);
        /* A shading normal may disagree with the geometry: such directions would leak light. */
        if ((vdot(wo, z.v.ng) > 0) != (bs.wo.z > 0)) break;
        z.beta = vmul(z.beta, bs.weight);
        if (vzero(z.beta) || !vfinite(z.beta)) break;
        o = z.v.p;
        eps = z.eps;
        d = wo;
        z.pdf_sa = bs.pdf;
        z.after_delta = bs.delta;
    }
    splat_finite(img, px, py, sum, &w->nf.len[0]);
}
