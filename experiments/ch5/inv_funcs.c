/* The sampling functions with inverses (inv_funcs.h). */
#include "ch5/inv_funcs.h"
#include "path/connect.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

static double rec_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    struct inv_rec *r = (struct inv_rec *)s;
    int i = sampler_index(s);
    double u = rng_uniform(&r->r);
    r->u[s->stream][i] = u;
    if (i >= r->hi[s->stream]) r->hi[s->stream] = i + 1;
    return u;
}
static const struct sampler_ops rec_ops = {rec_next, NULL, NULL};

void inv_rec_init(struct inv_rec *r, uint64_t seed, uint64_t stream)
{
    r->base = (struct sampler){&rec_ops, 0, 0, 0};
    rng_seed(&r->r, seed, stream);
    for (int st = 0; st < STREAM_COUNT; st++) {
        for (int i = 0; i < STREAM_DIMS; i++)
            r->u[st][i] = NAN;
        r->hi[st] = 0;
    }
}

static void rec_clear(struct inv_rec *r)
{
    for (int st = 0; st < STREAM_COUNT; st++) {
        for (int i = 0; i < r->hi[st]; i++)
            r->u[st][i] = NAN;
        r->hi[st] = 0;
    }
}

/* The tested slots of a stream vector pair (camera, emitter). */
static void to_slots(const double (*u)[STREAM_DIMS], double *out)
{
    for (int k = 0; k < INV_SLOTS_PER_STREAM; k++) {
        out[k] = u[STREAM_CAMERA][k];
        out[INV_SLOTS_PER_STREAM + k] = u[STREAM_EMITTER][k];
    }
}

static bool reads_roughness(enum bsdf_type t)
{
    return t == BSDF_ROUGH_CONDUCTOR || t == BSDF_ROUGH_DIELECTRIC || t == BSDF_ROUGH_PLASTIC || t == BSDF_ROUGH_COAT ||
           t == BSDF_OREN_NAYAR;
}

static bool reads_ior(enum bsdf_type t)
{
    return t == BSDF_DIELECTRIC || t == BSDF_ROUGH_DIELECTRIC || t == BSDF_THINSHEET || t == BSDF_PLASTIC ||
           t == BSDF_ROUGH_PLASTIC;
}

/* One BSDF function: b with roughness (alpha > 0) or ior (> 0) replaced. */
static bool add_bsdf(const struct bsdf *b, const char *scene_name, double alpha, double ior, struct inv_func *f, int *n,
                     int cap)
{
    if (*n >= cap) return false;
    struct inv_func *g = &f[(*n)++];
    memset(g, 0, sizeof *g);
    g->kind = INV_BSDF;
    g->b = *b;
    int k = snprintf(g->name, sizeof g->name, "bsdf:%s/%s", scene_name, b->name);
    if (alpha > 0) {
        g->b.roughness = alpha;
        g->b.roughness_tex = NULL;
        snprintf(g->name + k, sizeof g->name - (size_t)k, "@alpha=%g", alpha);
    }
    if (ior > 0) {
        g->b.ior = ior;
        snprintf(g->name + k, sizeof g->name - (size_t)k, "@ior=%g", ior);
    }
    bsdf_prepare(&g->b);
    return true;
}

bool inv_funcs_bsdf(const struct scene *sc, const char *scene_name, unsigned long *seen, struct inv_func *f, int *n,
                    int cap)
{
    for (int i = 0; i < sc->nbsdfs; i++) {
        const struct bsdf *b = &sc->bsdfs[i];
        bool black = b->type == BSDF_LAMBERT && !b->albedo_tex && b->albedo.x + b->albedo.y + b->albedo.z == 0;
        if (b->type == BSDF_NULL || black || (*seen >> b->type & 1)) continue;
        *seen |= 1ul << b->type;
        if (!add_bsdf(b, scene_name, 0, 0, f, n, cap)) return false;
        if (reads_roughness(b->type))
            for (int a = 0; a < 2; a++)
                if (!add_bsdf(b, scene_name, a ? 0.5 : 0.05, 0, f, n, cap)) return false;
        if (reads_ior(b->type) && !add_bsdf(b, scene_name, 0, 1.33, f, n, cap)) return false;
    }
    return true;
}

static bool add_path(const struct scene *sc, const char *name, enum inv_kind kind, int s, int t, struct inv_func *f,
                     int *n, int cap)
{
    if (*n >= cap) return false;
    struct inv_func *g = &f[(*n)++];
    memset(g, 0, sizeof *g);
    snprintf(g->name, sizeof g->name, "%s", name);
    g->kind = kind, g->sc = sc, g->s = s, g->t = t;
    return true;
}

bool inv_funcs_scene(const struct scene *sc, struct scene *lens_sc, const char *scene_name, const int (*tech)[2],
                     int ntech, struct inv_func *f, int *n, int cap)
{
    char name[96];
    snprintf(name, sizeof name, "camera:%s", scene_name);
    if (!add_path(sc, name, INV_CAMERA, 0, 2, f, n, cap)) return false;
    /* A thin lens of radius 2 % of the scene's size, focused on its centre. */
    *lens_sc = *sc;
    double size = vlen(vsub(sc->bbox_max, sc->bbox_min));
    vec3 centre = vscale(vadd(sc->bbox_max, sc->bbox_min), 0.5);
    lens_sc->cam.lens_radius = 0.02 * size;
    lens_sc->cam.focus_dist = fmax(1e-3 * size, vdot(vsub(centre, sc->cam.pos), sc->cam.basis.n));
    snprintf(name, sizeof name, "camera-thinlens:%s", scene_name);
    if (!add_path(lens_sc, name, INV_CAMERA, 0, 2, f, n, cap)) return false;
    snprintf(name, sizeof name, "emitter:%s", scene_name);
    if (!add_path(sc, name, INV_EMITTER, 2, 0, f, n, cap)) return false;
    for (int i = 0; i < ntech; i++) {
        snprintf(name, sizeof name, "path:%s/s=%d;t=%d", scene_name, tech[i][0], tech[i][1]);
        if (!add_path(sc, name, INV_PATH, tech[i][0], tech[i][1], f, n, cap)) return false;
    }
    return true;
}

/* Incident directions a BSDF is sampled from, in turn: near-normal, oblique, shallow, and for a
 * transmissive BSDF also from below. */
static vec3 bsdf_wi(const struct bsdf *b, long i)
{
    static const double cosines[] = {0.9, 0.5, 0.15, -0.8, -0.3};
    int k = b->transmissive ? 5 : 3;
    double c = cosines[i % k], phi = 0.7 + 2.1 * (double)(i % 7);
    double s = sqrt(1 - c * c);
    return v3(s * cos(phi), s * sin(phi), c);
}

static const double bsdf_uv[2] = {0.37, 0.61};

bool inv_forward(const struct inv_func *f, struct inv_scratch *x, long i, double *fwd)
{
    rec_clear(&x->rec);
    struct sampler *s = &x->rec.base;
    struct path_ctx pc = {.sc = f->sc, .max_length = 8};
    bool ok;
    if (f->kind == INV_BSDF) {
        struct bsdf_ctx c = bsdf_ctx_at(&f->b, bsdf_uv);
        struct bsdf_sample out;
        x->wi = bsdf_wi(&f->b, i);
        sampler_begin(s, STREAM_CAMERA, 0);
        ok = bsdf_sample(&c, x->wi, s, TRANSPORT_RADIANCE, &out);
        x->wo = out.wo;
    } else {
        int nz = f->t ? walk_camera(&pc, s, x->z, f->t) : 0;
        int ny = f->s ? walk_emitter(&pc, s, x->y, f->s) : 0;
        ok = nz == f->t && ny == f->s;
        if (ok && f->kind == INV_PATH) {
            struct connection c;
            ok = connect_st(&pc, x->y, f->s, x->z, f->t, f->s + f->t - 1, &c, NULL) && vfinite(c.f) &&
                 c.f.x + c.f.y + c.f.z > 0;
        }
    }
    to_slots((const double(*)[STREAM_DIMS])x->rec.u, fwd);
    return ok;
}

bool inv_inverse(const struct inv_func *f, struct inv_scratch *x, double *inv)
{
    sampler_writer_clear(&x->w);
    struct sampler *w = &x->w.base;
    struct path_ctx pc = {.sc = f->sc, .max_length = 8};
    bool ok;
    if (f->kind == INV_BSDF) {
        struct bsdf_ctx c = bsdf_ctx_at(&f->b, bsdf_uv);
        sampler_begin(w, STREAM_CAMERA, 0);
        ok = bsdf_invert(&c, x->wi, x->wo, w);
    } else {
        ok = (!f->t || invert_camera(&pc, x->z, f->t, 0, w)) && (!f->s || invert_emitter(&pc, x->y, f->s, 0, w));
    }
    to_slots((const double(*)[STREAM_DIMS])x->w.u, inv);
    for (int k = 0; ok && k < INV_SLOTS; k++)
        ok = isnan(inv[k]) || (inv[k] >= 0 && inv[k] < 1);
    return ok;
}
