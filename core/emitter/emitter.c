/* Area emitters and light selection (emitter.h); the environment lives in envmap.c.
 *
 * Selection weight = emitted power (luminance):
 *   area emitters: area * pi * luminance(emission)  (Lambertian emission from the front side);
 *   environment:   pi R^2 * integral over the sphere of luminance(L(w)) dw, i.e. the flux that
 *                  enters the scene's bounding sphere of radius R (= pi R^2 * 4 pi L when constant).
 * Dimension order at emitter vertex 0 (STREAM_EMITTER): light pick (DIM_DISCRETE); position:
 * meshes triangle pick (DIM_DISCRETE, by area) + 2 DIM_CONTINUOUS (warp_triangle), quads 2
 * (a along edge0, b along edge1), spheres 2 (warp_uniform_sphere); area emitters then take the
 * emitted direction, 2 DIM_CONTINUOUS (cosine about n). */
#include "emitter/emitter.h"
#include "base/util.h"
#include "emitter/emitter_table.h"
#include "sampling/warp.h"
#include <stdio.h>
#include <stdlib.h>

static const struct emitter_table *table(const struct scene *sc)
{
    ASSERT(sc->emitters != NULL);
    return sc->emitters;
}

static double tri_area(const struct prim *pr, int i, vec3 *ng)
{
    vec3 a = pr->p[pr->tri[3 * i]], b = pr->p[pr->tri[3 * i + 1]], c = pr->p[pr->tri[3 * i + 2]];
    vec3 x = vcross(vsub(b, a), vsub(c, a));
    double l = vlen(x);
    if (ng) *ng = l > 0 ? vscale(x, 1.0 / l) : v3(0, 0, 0);
    return 0.5 * l;
}

static double shape_area(const struct prim *pr)
{
    switch (pr->kind) {
    case PRIM_QUAD:
        return vlen(vcross(pr->quad_edge0, pr->quad_edge1));
    case PRIM_SPHERE:
        return 4 * M_PI * pr->radius * pr->radius;
    case PRIM_MESH: {
        double a = 0;
        for (int i = 0; i < pr->ntris; i++)
            a += tri_area(pr, i, NULL);
        return a;
    }
    default:
        return 0;
    }
}

struct emitter_table *emitters_build(const struct scene *sc, char *err, size_t errlen)
{
    const char *file = sc->file ? sc->file : "scene";
    struct emitter_table *t = xcalloc(1, sizeof *t);
    t->nprims = sc->nprims;
    t->slot = xmalloc(sizeof(int) * (size_t)(sc->nprims > 0 ? sc->nprims : 1));
    t->env_slot = -1;
    int n = 0, ntri_cdf = 0;
    for (int i = 0; i < sc->nprims; i++) {
        t->slot[i] = -1;
        if (!sc->prims[i].emissive) continue;
        n++;
        if (sc->prims[i].kind == PRIM_MESH) ntri_cdf += sc->prims[i].ntris + 1;
    }
    t->n = n;
    size_t nn = (size_t)(n > 0 ? n : 1);
    t->prim = xmalloc(sizeof(int) * nn);
    t->power = xcalloc(nn, sizeof(double));
    t->cdf = xmalloc(sizeof(double) * (nn + 1));
    t->area = xcalloc(nn, sizeof(double));
    t->tri_off = xmalloc(sizeof(int) * nn);
    t->tri_cdf = xmalloc(sizeof(double) * (size_t)(ntri_cdf > 0 ? ntri_cdf : 1));
    int k = 0, off = 0;
    for (int i = 0; i < sc->nprims; i++) {
        const struct prim *pr = &sc->prims[i];
        if (!pr->emissive) continue;
        char where[64];
        snprintf(where, sizeof where, "primitives[%d]", i);
        t->prim[k] = i;
        t->slot[i] = k;
        t->tri_off[k] = -1;
        if (!vfinite(pr->emission)) {
            snprintf(err, errlen, "%s: %s.emission: non-finite emission", file, where);
            emitters_free(t);
            return NULL;
        }
        if (pr->kind == PRIM_INFINITE_SPHERE) {
            t->env_slot = k;
            double integral = env_build(t, sc, pr, err, errlen, where);
            if (integral < 0) {
                emitters_free(t);
                return NULL;
            }
            t->power[k] = M_PI * t->env_R * t->env_R * integral;
        } else {
            double a = shape_area(pr);
            if (!(a > 0) || !isfinite(a) || !(pr->area > 0) || !isfinite(pr->area)) {
                snprintf(err, errlen, "%s: %s: zero-area emitter", file, where);
                emitters_free(t);
                return NULL;
            }
            t->area[k] = a;
            t->power[k] = a * M_PI * fmax(0.0, luminance(pr->emission));
            if (pr->kind == PRIM_MESH) {
                double *w = xmalloc(sizeof(double) * (size_t)pr->ntris);
                for (int j = 0; j < pr->ntris; j++)
                    w[j] = tri_area(pr, j, NULL);
                cdf_build(t->tri_cdf + off, w, pr->ntris);
                free(w);
                t->tri_off[k] = off;
                off += pr->ntris + 1;
            }
        }
        k++;
    }
    if (n > 0)
        cdf_build(t->cdf, t->power, n);
    else
        t->cdf[0] = 0, t->cdf[1] = 1;
    t->total_power = 0;
    for (int i = 0; i < n; i++)
        t->total_power += t->power[i];
    return t;
}

void emitters_free(struct emitter_table *t)
{
    if (!t) return;
    env_free(t);
    free(t->prim);
    free(t->power);
    free(t->cdf);
    free(t->slot);
    free(t->area);
    free(t->tri_off);
    free(t->tri_cdf);
    free(t);
}

int emitters_count(const struct scene *sc)
{
    if (sc->emitters) return sc->emitters->n;
    int n = 0;
    for (int i = 0; i < sc->nprims; i++)
        n += sc->prims[i].emissive;
    return n;
}

int emitter_pick(const struct scene *sc, struct sampler *s, double *prob)
{
    const struct emitter_table *t = table(sc);
    double u = sampler_next(s, DIM_DISCRETE);
    if (t->n == 0 || !(t->total_power > 0)) {
        *prob = 0;
        return -1;
    }
    int k = cdf_find(t->cdf, t->n, u);
    *prob = t->cdf[k + 1] - t->cdf[k];
    return t->prim[k];
}

double emitter_pick_prob(const struct scene *sc, int prim)
{
    const struct emitter_table *t = table(sc);
    if (prim < 0 || prim >= t->nprims || t->slot[prim] < 0 || !(t->total_power > 0)) return 0;
    int k = t->slot[prim];
    return t->cdf[k + 1] - t->cdf[k];
}

bool emitter_pick_invert(const struct scene *sc, int prim, struct sampler *w)
{
    double p = emitter_pick_prob(sc, prim);
    if (!(p > 0)) return false;
    const struct emitter_table *t = table(sc);
    int k = t->slot[prim];
    sampler_put(w, DIM_DISCRETE, invert_discrete(t->cdf[k], t->cdf[k + 1], sampler_fresh(w)));
    return true;
}

bool emitter_sample_pos(const struct scene *sc, int prim, struct sampler *s, struct emitter_pos *out)
{
    const struct emitter_table *t = table(sc);
    if (prim < 0 || prim >= t->nprims) return false;
    const struct prim *pr = &sc->prims[prim];
    int k = t->slot[prim];
    if (k < 0 || pr->kind == PRIM_INFINITE_SPHERE) return false;
    out->tri = -1;
    out->pdf = 1.0 / t->area[k];
    if (pr->kind == PRIM_MESH) {
        const double *cdf = t->tri_cdf + t->tri_off[k];
        int i = cdf_find(cdf, pr->ntris, sampler_next(s, DIM_DISCRETE));
        double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS), b1, b2;
        warp_triangle(u1, u2, &b1, &b2);
        vec3 a = pr->p[pr->tri[3 * i]], b = pr->p[pr->tri[3 * i + 1]], c = pr->p[pr->tri[3 * i + 2]];
        out->p = vadd(vadd(vscale(a, 1 - b1 - b2), vscale(b, b1)), vscale(c, b2));
        tri_area(pr, i, &out->n);
        out->tri = i;
    } else if (pr->kind == PRIM_QUAD) {
        double a = sampler_next(s, DIM_CONTINUOUS), b = sampler_next(s, DIM_CONTINUOUS);
        out->p = vadd(pr->quad_base, vadd(vscale(pr->quad_edge0, a), vscale(pr->quad_edge1, b)));
        out->n = pr->quad_normal;
    } else { /* PRIM_SPHERE */
        double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
        vec3 d = warp_uniform_sphere(u1, u2);
        out->p = vmad(pr->center, d, pr->radius);
        out->n = d;
    }
    return true;
}

double emitter_pdf_pos(const struct scene *sc, int prim, vec3 p)
{
    (void)p; /* uniform in area over the whole emitter */
    const struct emitter_table *t = table(sc);
    if (prim < 0 || prim >= t->nprims) return 0;
    int k = t->slot[prim];
    if (k < 0 || sc->prims[prim].kind == PRIM_INFINITE_SPHERE) return 0;
    return 1.0 / t->area[k];
}

/* Coordinates (a, b) of v = a e0 + b e1 by least squares (exact for points in the plane). */
static bool solve2(vec3 e0, vec3 e1, vec3 v, double *a, double *b)
{
    double d00 = vdot(e0, e0), d01 = vdot(e0, e1), d11 = vdot(e1, e1);
    double d20 = vdot(v, e0), d21 = vdot(v, e1);
    double det = d00 * d11 - d01 * d01;
    if (!(fabs(det) > 0)) return false;
    *a = (d11 * d20 - d01 * d21) / det;
    *b = (d00 * d21 - d01 * d20) / det;
    return isfinite(*a) && isfinite(*b);
}

#define INV_TOL 1e-6 /* parameter slack for points on the edge of the emitter */

static double clamp_open(double u)
{
    if (u < 0) return 0;
    if (u >= 1) return nextafter(1.0, 0.0);
    return u;
}

bool emitter_invert_pos(const struct scene *sc, int prim, const struct emitter_pos *pos, struct sampler *w)
{
    const struct emitter_table *t = table(sc);
    if (prim < 0 || prim >= t->nprims) return false;
    const struct prim *pr = &sc->prims[prim];
    int k = t->slot[prim];
    if (k < 0 || pr->kind == PRIM_INFINITE_SPHERE) return false;
    if (pr->kind == PRIM_MESH) {
        int i = pos->tri;
        if (i < 0 || i >= pr->ntris) return false;
        const double *cdf = t->tri_cdf + t->tri_off[k];
        if (!(cdf[i + 1] > cdf[i])) return false;
        vec3 a = pr->p[pr->tri[3 * i]], b = pr->p[pr->tri[3 * i + 1]], c = pr->p[pr->tri[3 * i + 2]];
        double b1, b2;
        if (!solve2(vsub(b, a), vsub(c, a), vsub(pos->p, a), &b1, &b2)) return false;
        if (b1 < -INV_TOL || b2 < -INV_TOL || b1 + b2 > 1 + INV_TOL) return false;
        b1 = maxd(b1, 0.0);
        b2 = maxd(b2, 0.0);
        double u1, u2;
        warp_triangle_invert(b1, b2, &u1, &u2);
        sampler_put(w, DIM_DISCRETE, invert_discrete(cdf[i], cdf[i + 1], sampler_fresh(w)));
        sampler_put(w, DIM_CONTINUOUS, clamp_open(u1));
        sampler_put(w, DIM_CONTINUOUS, clamp_open(u2));
    } else if (pr->kind == PRIM_QUAD) {
        double a, b;
        if (!solve2(pr->quad_edge0, pr->quad_edge1, vsub(pos->p, pr->quad_base), &a, &b)) return false;
        if (a < -INV_TOL || b < -INV_TOL || a > 1 + INV_TOL || b > 1 + INV_TOL) return false;
        sampler_put(w, DIM_CONTINUOUS, clamp_open(a));
        sampler_put(w, DIM_CONTINUOUS, clamp_open(b));
    } else {
        vec3 d = vsub(pos->p, pr->center);
        double l = vlen(d);
        if (!(l > 0)) return false;
        double u1, u2;
        warp_uniform_sphere_invert(vscale(d, 1.0 / l), &u1, &u2);
        sampler_put(w, DIM_CONTINUOUS, clamp_open(u1));
        sampler_put(w, DIM_CONTINUOUS, clamp_open(u2));
    }
    return true;
}

vec3 emitter_sample_dir(vec3 n, struct sampler *s, double *pdf)
{
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    vec3 l = warp_cosine_hemisphere(u1, u2);
    frame f = frame_from_normal(n);
    *pdf = warp_cosine_hemisphere_pdf(l);
    return frame_to_world(&f, l);
}

double emitter_pdf_dir(vec3 n, vec3 d)
{
    double c = vdot(n, d);
    return c > 0 ? c * INV_PI : 0.0;
}

bool emitter_invert_dir(vec3 n, vec3 d, struct sampler *w)
{
    frame f = frame_from_normal(n);
    vec3 l = frame_to_local(&f, d);
    if (!(l.z > 0)) return false;
    double u1, u2;
    warp_cosine_hemisphere_invert(vnorm(l), &u1, &u2);
    sampler_put(w, DIM_CONTINUOUS, clamp_open(u1));
    sampler_put(w, DIM_CONTINUOUS, clamp_open(u2));
    return true;
}

rgb emitter_radiance(const struct scene *sc, int prim, vec3 n, vec3 d)
{
    const struct prim *pr = &sc->prims[prim];
    if (!pr->emissive || !(vdot(n, d) > 0)) return v3s(0);
    return pr->emission;
}
