/* The environment emitter (infinite_sphere), following Tungsten's InfiniteSphere, and the
 * directional cap light (infinite_sphere_cap, Tungsten's InfiniteSphereCap).
 *
 * Orientation (Tungsten: InfiniteSphere::directionToUV / uvToDirection, BitmapTexture):
 * a world direction d (from the scene toward the environment) goes to the local frame by
 * env_to_local (rotation; the result is renormalised); local +y is up. With
 *   theta = angle from local +y, phi = atan2(l.z, l.x) in (-pi, pi],
 * the image column is x = phi / (2 pi) + 0.5 (so local +x is the middle column, -x the left
 * edge) and the row counted from the top (row 0 = first row as OpenImageIO reads it) is
 * y = theta / pi (so the top row is up). Tungsten's texture v = 1 - y and u = x.
 * Radiance is the texture's bilinear lookup at (u, v) = (x, 1 - y), wrapping around in both
 * directions as Tungsten's BitmapTexture does (so within half a texel of a pole it blends the top
 * and bottom rows); the texture replaces `emission` when present.
 *
 * Sampling (Tungsten: BitmapTexture::makeSamplable with MAP_SPHERICAL): a 2D piecewise-constant
 * distribution over the texels with weights max_channel(texel) * sin(pi row / h) (the sine at the
 * row's top edge), each then replaced by the largest weight of its 3x3 neighbourhood (wrapping
 * around), so every texel the bilinear lookup can light has a positive density; (u1 -> row,
 * u2 -> column). pdf in solid angle = pdf_xy / (2 pi^2 sin theta) at the sampled point, the
 * lat-long Jacobian; the weights only shape the density, so pdf and inverse stay exact. A
 * constant environment is sampled uniformly over the sphere (world).
 *
 * The cap light: constant radiance for directions within the cap (dot(d, cap_dir) >= cap_cos),
 * sampled uniformly over the cap (warp_uniform_cap about cap_dir in frame_from_normal(cap_dir)).
 *
 * Emitter subpaths start on the disc of radius R (bounding sphere of the finite geometry,
 * enlarged by 0.1 %) perpendicular to d, centred at centre + R d, and travel along -d. */
#include "base/util.h"
#include "emitter/emitter.h"
#include "emitter/emitter_table.h"
#include "sampling/warp.h"
#include <stdio.h>
#include <stdlib.h>

static const struct prim *env(const struct scene *sc, const struct emitter_table **t)
{
    *t = sc->emitters;
    if (!*t || (*t)->env_slot < 0) return NULL;
    return &sc->prims[(*t)->prim[(*t)->env_slot]];
}

/* Each weight becomes the largest of its 3x3 neighbourhood, wrapping around at the image's edges. */
static void dilate_wrapped(double *wt, int w, int h)
{
    double *tmp = xmalloc(sizeof(double) * (size_t)w * (size_t)h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const double *row = wt + (size_t)y * w;
            tmp[(size_t)y * w + x] = fmax(row[x], fmax(row[(x + w - 1) % w], row[(x + 1) % w]));
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double a = tmp[(size_t)((y + h - 1) % h) * w + x], b = tmp[(size_t)((y + 1) % h) * w + x];
            wt[(size_t)y * w + x] = fmax(tmp[(size_t)y * w + x], fmax(a, b));
        }
    free(tmp);
}

double env_build(struct emitter_table *t, const struct scene *sc, const struct prim *pr, char *err, size_t errlen,
                 const char *where)
{
    const char *file = sc->file ? sc->file : "scene";
    vec3 lo = sc->bbox_min, hi = sc->bbox_max;
    if (vfinite(lo) && vfinite(hi) && lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z) {
        t->env_center = vscale(vadd(lo, hi), 0.5);
        t->env_R = 0.5 * vlen(vsub(hi, lo)) * 1.001;
    } else {
        t->env_center = v3s(0);
        t->env_R = 1;
    }
    if (!(t->env_R > 0)) t->env_R = 1e-3;

    const struct texture *tex = pr->env_tex;
    if (pr->env_is_cap) {
        t->env_map = false;
        return 2 * M_PI * (1 - pr->cap_cos) * fmax(0.0, luminance(pr->emission));
    }
    if (!tex) {
        t->env_map = false;
        return 4 * M_PI * fmax(0.0, luminance(pr->emission));
    }
    if (tex->w <= 0 || tex->h <= 0 || !tex->rgb) {
        snprintf(err, errlen, "%s: %s.emission: empty environment map", file, where);
        return -1;
    }
    int w = tex->w, h = tex->h;
    double *wt = xmalloc(sizeof(double) * (size_t)w * (size_t)h);
    double integral = 0;
    for (int y = 0; y < h; y++) {
        double s = sin(M_PI * y / h);
        double dom = (2 * M_PI / w) * (cos(M_PI * y / h) - cos(M_PI * (y + 1) / h));
        for (int x = 0; x < w; x++) {
            const float *c = tex->rgb + 3 * ((size_t)y * w + x);
            rgb v = v3(c[0], c[1], c[2]);
            if (!vfinite(v)) {
                snprintf(err, errlen, "%s: %s.emission: non-finite texel (%d, %d) in the environment map", file, where,
                         x, y);
                free(wt);
                return -1;
            }
            double l = fmax(0.0, luminance(v));
            wt[(size_t)y * w + x] = fmax(0.0, fmax(v.x, fmax(v.y, v.z))) * s;
            integral += l * dom;
        }
    }
    dilate_wrapped(wt, w, h);
    t->env_map = true;
    distrib2d_init(&t->env_dist, wt, w, h);
    free(wt);
    return integral;
}

void env_free(struct emitter_table *t)
{
    if (t->env_map) distrib2d_free(&t->env_dist);
    t->env_map = false;
}

/* World direction -> image coordinates (x = column, y = row from the top, both in [0,1)). */
static void dir_to_xy(const struct prim *pr, vec3 d, double *x, double *y, double *sin_theta)
{
    vec3 l = mat4_vector(&pr->env_to_local, d);
    double st = hypot(l.x, l.z);
    double theta = atan2(st, l.y), phi = atan2(l.z, l.x);
    double xx = phi / (2 * M_PI) + 0.5, yy = theta / M_PI;
    if (xx >= 1) xx -= 1;
    if (xx < 0) xx = 0;
    if (yy >= 1) yy = nextafter(1.0, 0.0);
    *x = xx;
    *y = yy;
    *sin_theta = st / vlen(l);
}

static vec3 xy_to_dir(const struct prim *pr, double x, double y, double *sin_theta)
{
    double st, ct, sp, cp;
    sincos_turns(0.5 * y, &st, &ct); /* theta = pi y */
    sincos_turns(x - 0.5, &sp, &cp); /* phi = 2 pi x - pi */
    *sin_theta = st;
    vec3 l = v3(cp * st, ct, sp * st);
    return vnorm(mat4_vector(&pr->env_to_world, l));
}

static bool in_cap(const struct prim *pr, vec3 d) { return vdot(d, pr->cap_dir) >= pr->cap_cos * vlen(d); }

rgb env_radiance(const struct scene *sc, vec3 d)
{
    const struct emitter_table *t;
    const struct prim *pr = env(sc, &t);
    if (!pr) return v3s(0);
    if (pr->env_is_cap) return in_cap(pr, d) ? pr->emission : v3s(0);
    const struct texture *tex = pr->env_tex;
    if (!tex) return pr->emission;
    double x, y, st;
    dir_to_xy(pr, d, &x, &y, &st);
    return texture_lookup(tex, x, 1 - y);
}

bool env_sample_dir(const struct scene *sc, struct sampler *s, vec3 *d, double *pdf)
{
    const struct emitter_table *t;
    const struct prim *pr = env(sc, &t);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS);
    if (!pr) return false;
    if (pr->env_is_cap) {
        frame f = frame_from_normal(pr->cap_dir);
        *d = vnorm(frame_to_world(&f, warp_uniform_cap(u1, u2, pr->cap_cos)));
        *pdf = warp_uniform_cap_pdf(pr->cap_cos);
        return true;
    }
    if (!t->env_map) {
        *d = warp_uniform_sphere(u1, u2);
        *pdf = warp_uniform_sphere_pdf();
        return true;
    }
    if (!(t->env_dist.total > 0)) return false;
    double x, y, pxy, st;
    distrib2d_sample(&t->env_dist, u1, u2, &x, &y, &pxy);
    *d = xy_to_dir(pr, x, y, &st);
    if (!(st > 0)) return false;
    *pdf = pxy / (2 * M_PI * M_PI * st);
    return *pdf > 0;
}

double env_pdf_dir(const struct scene *sc, vec3 d)
{
    const struct emitter_table *t;
    const struct prim *pr = env(sc, &t);
    if (!pr) return 0;
    if (pr->env_is_cap) return in_cap(pr, d) ? warp_uniform_cap_pdf(pr->cap_cos) : 0;
    if (!t->env_map) return warp_uniform_sphere_pdf();
    double x, y, st;
    dir_to_xy(pr, d, &x, &y, &st);
    if (!(st > 0)) return 0;
    return distrib2d_pdf(&t->env_dist, x, y) / (2 * M_PI * M_PI * st);
}

bool env_invert_dir(const struct scene *sc, vec3 d, struct sampler *w)
{
    const struct emitter_table *t;
    const struct prim *pr = env(sc, &t);
    if (!pr) return false;
    double u1, u2;
    if (pr->env_is_cap) {
        if (!in_cap(pr, d)) return false;
        frame f = frame_from_normal(pr->cap_dir);
        warp_uniform_cap_invert(vnorm(frame_to_local(&f, d)), pr->cap_cos, &u1, &u2);
    } else if (!t->env_map) {
        warp_uniform_sphere_invert(vnorm(d), &u1, &u2);
    } else {
        double x, y, st;
        dir_to_xy(pr, d, &x, &y, &st);
        if (!(st > 0) || !distrib2d_invert(&t->env_dist, x, y, &u1, &u2)) return false;
    }
    sampler_put(w, DIM_CONTINUOUS, u1 >= 1 ? nextafter(1.0, 0.0) : u1);
    sampler_put(w, DIM_CONTINUOUS, u2 >= 1 ? nextafter(1.0, 0.0) : u2);
    return true;
}

double env_radius(const struct scene *sc)
{
    const struct emitter_table *t = sc->emitters;
    return t && t->env_slot >= 0 ? t->env_R : 0;
}

vec3 env_sample_origin(const struct scene *sc, vec3 d, struct sampler *s, double *pdf)
{
    const struct emitter_table *t = sc->emitters;
    ASSERT(t && t->env_slot >= 0);
    double u1 = sampler_next(s, DIM_CONTINUOUS), u2 = sampler_next(s, DIM_CONTINUOUS), x, y;
    warp_disk(u1, u2, &x, &y);
    frame f = frame_from_normal(d);
    double R = t->env_R;
    *pdf = 1.0 / (M_PI * R * R);
    vec3 c = vmad(t->env_center, d, R);
    return vadd(c, vadd(vscale(f.s, R * x), vscale(f.t, R * y)));
}

bool env_invert_origin(const struct scene *sc, vec3 d, vec3 origin, struct sampler *w)
{
    const struct emitter_table *t = sc->emitters;
    if (!t || t->env_slot < 0) return false;
    double R = t->env_R;
    frame f = frame_from_normal(d);
    vec3 v = vsub(origin, vmad(t->env_center, d, R));
    double x = vdot(v, f.s) / R, y = vdot(v, f.t) / R;
    if (!(x * x + y * y <= 1 + 1e-9)) return false;
    double u1, u2;
    warp_disk_invert(x, y, &u1, &u2);
    sampler_put(w, DIM_CONTINUOUS, u1 >= 1 ? nextafter(1.0, 0.0) : u1);
    sampler_put(w, DIM_CONTINUOUS, u2 >= 1 ? nextafter(1.0, 0.0) : u2);
    return true;
}
