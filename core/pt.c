/* Path tracer: techniques s = 0 (emission hit, or escape to the environment) and s = 1 (a light
 * sample at every vertex), weighted against each other only (balance heuristic). The light sample
 * at camera vertex i uses emitter-stream block i. */
#include "connect.h"
#include "emitter.h"
#include "integrator.h"

void splat_checked(struct image *img, struct scratch *w, double px, double py, rgb c)
{
    if (!vfinite(c)) {
        w->nonfinite++;
        return;
    }
    img_splat(img, px, py, c);
}

/* Light sample toward the environment from surface vertex z (solid-angle densities throughout). */
static rgb env_light_sample(const struct scene *sc, const struct vertex *z, double pick, struct sampler *s)
{
    vec3 d;
    double pdf;
    if (!env_sample_dir(sc, s, &d, &pdf) || !(pdf > 0)) return v3s(0);
    vec3 wi = frame_to_local(&z->sh, z->wi), wo = frame_to_local(&z->sh, d);
    rgb f = bsdf_eval(&z->bc, wi, wo, TRANSPORT_RADIANCE);
    if (vzero(f) || accel_occluded(sc->accel, z->p, d, ray_eps(z->p), INFINITY)) return v3s(0);
    double p_light = pick * pdf, p_bsdf = bsdf_pdf(&z->bc, wi, wo);
    rgb c = vmul(vmul(z->beta, f), env_radiance(sc, d));
    /* (f Le cos / p_light) times the balance weight p_light / (p_light + p_bsdf) */
    return vscale(c, fabs(wo.z) / (p_light + p_bsdf));
}

void pt_sample(const struct path_ctx *pc, struct sampler *s, struct scratch *w, struct image *img)
{
    const struct scene *sc = pc->sc;
    struct vertex *z = w->cam, y;
    struct escape esc;
    int nz = walk_camera_escape(pc, s, z, pc->max_length + 1, &esc);
    rgb sum = v3s(0);
    struct connection c;
    for (int t = 2; t <= nz; t++) {
        int k = t - 1; /* length of the emission-hit path */
        if (connect_st(pc, NULL, 0, z, t, k >= 2 ? 1 : 0, &c, NULL)) sum = vmad(sum, c.f, c.w);
        const struct vertex *zc = &z[t - 1];
        if (t > pc->max_length || !zc->bc.b || bsdf_ops_for(zc->bc.b->type)->delta_only) continue;
        sampler_begin(s, STREAM_EMITTER, t - 1);
        double pick;
        int prim = emitter_pick(sc, s, &pick);
        if (prim < 0) continue;
        if (prim == sc->env_prim) sum = vadd(sum, env_light_sample(sc, zc, pick, s));
        else if (sample_area_emitter(sc, prim, pick, s, &y) && connect_st(pc, &y, 1, z, t, 1, &c, NULL))
            sum = vmad(sum, c.f, c.w);
    }
    if (esc.escaped && sc->env_prim >= 0) {
        /* The camera ray itself, or a delta lobe, has no competing light sample. */
        double w_mis = 1;
        if (nz >= 2 && esc.pdf_sa > 0) {
            double p_light = emitter_pick_prob(sc, sc->env_prim) * env_pdf_dir(sc, esc.d);
            w_mis = esc.pdf_sa / (esc.pdf_sa + p_light);
        }
        sum = vmad(sum, vmul(esc.beta, env_radiance(sc, esc.d)), w_mis);
    }
    splat_checked(img, w, z[0].px, z[0].py, sum);
}
