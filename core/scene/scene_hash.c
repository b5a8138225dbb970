/* The scene's identity for checkpoints: a hash of the loaded data (camera, BSDFs, their textures,
 * geometry and emission), field by field so that struct padding never enters it. A scene file
 * edited in a way that changes nothing loaded still resumes; a changed mesh or texture does not. */
#include "scene/scene_hash.h"
#include "io/checkpoint.h"

#define H(x) (h = hash64(h, &(x), sizeof(x)))
#define HA(p, n) (h = (p) ? hash64(h, (p), (size_t)(n) * sizeof *(p)) : hash64(h, "", 0))

static uint64_t hash_texture(uint64_t h, const struct texture *t)
{
    if (!t) return hash64(h, "-", 1);
    if (t->kind != TEX_BITMAP) { /* (bitmaps hash as they did before there were other kinds) */
        H(t->kind);
        H(t->on);
        H(t->off);
        H(t->res_u);
        return H(t->res_v);
    }
    H(t->w);
    H(t->h);
    H(t->bits);
    return HA(t->rgb, 3 * (size_t)t->w * t->h);
}

static uint64_t hash_bsdf(uint64_t h, const struct bsdf *all, const struct bsdf *b)
{
    H(b->type);
    h = hash64(h, b->name, sizeof b->name);
    H(b->albedo);
    h = hash_texture(h, b->albedo_tex);
    /* textures: hashed only where present, so scenes without them keep their former hash */
    if (b->roughness_tex) h = hash_texture(hash64(h, "r", 1), b->roughness_tex);
    if (b->bump_tex) h = hash_texture(hash64(h, "b", 1), b->bump_tex);
    H(b->eta);
    H(b->k);
    H(b->ior);
    H(b->enable_refraction);
    H(b->dist);
    H(b->roughness);
    H(b->thickness);
    /* nested BSDFs: which slots they nest (hashed only where present, as the textures) */
    for (int i = 0; i < 2; i++)
        if (b->child[i]) {
            long slot = (long)(b->child[i] - all);
            h = hash64(hash64(h, "c", 1), &slot, sizeof slot);
        }
    H(b->alpha);
    H(b->ratio);
    h = hash_texture(h, b->ratio_tex);
    H(b->sigma_a);
    /* leaf BSDFs */
    H(b->transmittance);
    H(b->exponent);
    return H(b->diffuse_ratio);
}

static uint64_t hash_prim(uint64_t h, const struct prim *p)
{
    H(p->kind);
    H(p->bsdf);
    H(p->emission);
    H(p->emissive);
    H(p->nverts);
    H(p->ntris);
    HA(p->p, p->nverts);
    HA(p->n, p->nverts);
    HA(p->uv, 2 * (size_t)p->nverts);
    HA(p->tri, 3 * (size_t)p->ntris);
    H(p->quad_base);
    H(p->quad_edge0);
    H(p->quad_edge1);
    H(p->center);
    H(p->radius);
    H(p->sphere_axis);
    if (p->cube_tangents) h = hash64(h, "t", 1); /* bump tangents from the cube's axes */
    h = hash_texture(h, p->env_tex);
    H(p->env_is_cap);
    H(p->cap_dir);
    H(p->cap_cos);
    return H(p->env_to_world);
}

uint64_t ckpt_scene_hash(const struct scene *sc)
{
    uint64_t h = 0x452821E638D01377ULL;
    const struct camera *c = &sc->cam;
    H(c->pos);
    H(c->basis);
    H(c->fov_deg);
    H(c->width);
    H(c->height);
    H(c->filter);
    if (c->lens_radius > 0) { /* a pinhole hashes as before the thin lens existed */
        H(c->lens_radius);
        H(c->focus_dist);
    }
    H(sc->two_sided_shading);
    H(sc->nbsdfs);
    for (int i = 0; i < sc->nbsdfs; i++)
        h = hash_bsdf(h, sc->bsdfs, &sc->bsdfs[i]);
    H(sc->nprims);
    for (int i = 0; i < sc->nprims; i++)
        h = hash_prim(h, &sc->prims[i]);
    return h;
}
