/* BSDF interface: eval / pdf / sample / invert side by side, in the local shading frame
 * (z = shading normal).
 *
 * Conventions (every family keeps them):
 *  - wi points toward the previous path vertex, wo is the sampled direction; both away from the
 *    surface, unit length, local coordinates. The path code flips the frame of non-transmissive
 *    surfaces hit from the back (two-sided shading), so they always see wi.z > 0.
 *  - eval returns f(wi, wo) WITHOUT the cosine factor (pbrt's convention); 0 for delta lobes.
 *  - pdf is the solid-angle density of sampling wo given wi over the continuous lobes, including
 *    the probability of choosing that lobe; delta lobes contribute nothing to it.
 *  - sample draws its discrete numbers first, then its continuous ones, a fixed number per family
 *    (bsdf_dims); out->weight = f |cos wo| / pdf, or for a delta lobe the throughput factor
 *    of that lobe divided by its discrete probability.
 *  - transport mode: in TRANSPORT_RADIANCE (camera subpaths), transmission through an interface
 *    is scaled by (eta_wi_side / eta_wo_side)^2; in TRANSPORT_IMPORTANCE it is not (Veach §5.2).
 *  - invert(wi, wo) puts, in the same order, the numbers that make sample reproduce wo
 *    (thesis Eq. 5.4-5.8); discrete choices invert to a uniform point of the outcome's interval
 *    drawn with sampler_fresh(); where several lobes can produce wo, one is picked in proportion
 *    to its share of the pdf. Returns false when wo cannot be produced. */
#ifndef BSDF_H
#define BSDF_H

#include "sampler/sampler.h"
#include "scene/scene.h"

enum transport { TRANSPORT_RADIANCE, TRANSPORT_IMPORTANCE };

/* A BSDF at one surface point: the model plus its texture lookups. Built by bsdf_ctx_at only:
 * nested BSDFs build their children's from the same uv. */
struct bsdf_ctx {
    const struct bsdf *b;
    rgb albedo;       /* b->albedo or the texture at the hit's uv */
    double roughness; /* b->roughness or its texture at the hit's uv */
    float uv[2];      /* the hit's texture coordinates for nested BSDFs' and mixed's lookups (0 where
                       * nothing reads them); float, as every path vertex carries one */
};

/* The context of b at texture coordinates uv (NULL: (0, 0)). */
/* The textured case, out of line. */
struct bsdf_ctx bsdf_ctx_textured(const struct bsdf *b, const double uv[2]);
/* Inline: every surface hit builds one, and most BSDFs read no texture (then uv stays 0: nothing
 * reads it, b->needs_uv covering the nested BSDFs' textures too). */
static inline struct bsdf_ctx bsdf_ctx_at(const struct bsdf *b, const double uv[2])
{
    if (b->needs_uv) return bsdf_ctx_textured(b, uv);
    return (struct bsdf_ctx){.b = b, .albedo = b->albedo, .roughness = b->roughness};
}
/* The context of c's nested BSDF i at the same point. */
static inline struct bsdf_ctx bsdf_child_ctx(const struct bsdf_ctx *c, int i)
{
    const double uv[2] = {c->uv[0], c->uv[1]};
    return bsdf_ctx_at(c->b->child[i], uv);
}

struct bsdf_sample {
    vec3 wo;
    double pdf; /* solid angle (continuous) or discrete probability (delta) */
    rgb weight;
    bool delta;
    int lobe; /* family-specific lobe index, for statistics and tests */
};

struct bsdf_ops {
    int dims; /* numbers consumed by sample(); nested types set bsdf.dims in prepare() */
    bool (*sample)(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode, struct bsdf_sample *out);
    rgb (*eval)(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode);
    double (*pdf)(const struct bsdf_ctx *c, vec3 wi, vec3 wo);
    bool (*invert)(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w);
    bool transmissive; /* can scatter to the other side: no two-sided flip */
    bool delta_only;   /* every lobe is a Dirac delta: never connect to it */
    /* Optional: derived parameters of one BSDF (called after its children's); nested types set
     * b->dims, b->transmissive and b->delta_only from their children here. */
    void (*prepare)(struct bsdf *b);
};

/* Families (one file each). */
extern const struct bsdf_ops bsdf_lambert_ops, bsdf_conductor_ops /* also the mirror */, bsdf_dielectric_ops,
    bsdf_plastic_ops, bsdf_rough_conductor_ops, bsdf_rough_dielectric_ops, bsdf_rough_plastic_ops;
/* nested BSDFs: their children are b->child[0..1] (bsdf_nested.h) */
extern const struct bsdf_ops bsdf_transparency_ops, bsdf_smooth_coat_ops, bsdf_rough_coat_ops, bsdf_mixed_ops;
/* Leaf families of Tungsten's (bsdf_leaf.h). */
extern const struct bsdf_ops bsdf_thinsheet_ops, bsdf_diffuse_transmission_ops, bsdf_oren_nayar_ops, bsdf_phong_ops;
extern const struct bsdf_ops *const bsdf_ops_table[BSDF_NTYPES];

/* The table entry for a type; NULL for BSDF_NULL (no scattering). Inline: every BSDF call on every
 * path vertex dispatches through it. */
static inline const struct bsdf_ops *bsdf_ops_for(enum bsdf_type type)
{
    return (unsigned)type < BSDF_NTYPES ? bsdf_ops_table[type] : NULL;
}

/* Derived parameters (e.g. plastic's diffuse Fresnel, dims, the flags, whether and with which ior
 * it refracts); called after loading, children first; idempotent (the loader calls it to check dims). */
void bsdf_prepare(struct bsdf *b);
/* bsdf_prepare on every BSDF of a scene's array, nested ones before those that hold them. */
void bsdf_prepare_all(struct bsdf *bs, int n);

static inline bool bsdf_sample(const struct bsdf_ctx *c, vec3 wi, struct sampler *s, enum transport mode,
                               struct bsdf_sample *out)
{
    return bsdf_ops_for(c->b->type)->sample(c, wi, s, mode, out);
}
static inline rgb bsdf_eval(const struct bsdf_ctx *c, vec3 wi, vec3 wo, enum transport mode)
{
    return bsdf_ops_for(c->b->type)->eval(c, wi, wo, mode);
}
static inline double bsdf_pdf(const struct bsdf_ctx *c, vec3 wi, vec3 wo)
{
    return bsdf_ops_for(c->b->type)->pdf(c, wi, wo);
}
static inline bool bsdf_invert(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w)
{
    return bsdf_ops_for(c->b->type)->invert(c, wi, wo, w);
}

#endif
