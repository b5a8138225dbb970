/* Joining subpaths: contributions and the density bookkeeping at the connection. */
#include "path/connect.h"
#include "camera/camera.h"
#include "emitter/emitter.h"
#include "path/splat.h"

/* Solid-angle density with which vertex `at` (entered from `from_dir`, world, toward its
 * predecessor) scatters into unit direction d; for camera and emitter vertices their own densities. */
static double scatter_pdf(const struct scene *sc, const struct vertex *at, vec3 from_dir, vec3 d)
{
    if (at->kind == VK_CAMERA) return camera_pdf_dir(&sc->cam, at->p, d);
    if (at->kind == VK_ENV) return 1.0 / (M_PI * sqr(env_radius(sc))); /* the origin disc */
    if (at->kind == VK_EMITTER) return emitter_pdf_dir(at->ng, d);
    if (!at->bc.b) return 0;
    return bsdf_pdf(&at->bc, frame_to_local(&at->sh, from_dir), frame_to_local(&at->sh, d));
}

/* The same toward the predecessor of `at` in its own subpath, which lies along at->wi. */
static double pdf_to_prev(const struct scene *sc, const struct vertex *at, vec3 from_dir, const struct vertex *prev)
{
    return edge_pdf(scatter_pdf(sc, at, from_dir, at->wi), at, prev, at->wi, vlen2(vsub(prev->p, at->p)));
}

/* Geometric normal on the emitting side of an emitter hit by a camera walk. */
static vec3 emit_normal(const struct vertex *v) { return v->flipped ? vneg(v->ng) : v->ng; }

/* d: unit direction from y_{s-1} to z_{t-1}, dist2 their squared distance (s >= 1); cam_pdf: for
 * t = 1, the camera's density toward y_{s-1}, already known from the raster lookup. Returns whether
 * any vertex of either subpath is delta: without one there is no chain to unfold. */
static bool densities(const struct path_ctx *pc, const struct vertex *y, int s, const struct vertex *z, int t, vec3 d,
                      double dist2, double cam_pdf, struct mis_path *m)
{
    const struct scene *sc = pc->sc;
    int k = s + t - 1;
    m->k = k;
    bool any_delta = false;
    for (int i = 0; i < s; i++) {
        m->pl[i] = y[i].pdf_fwd;
        m->pc[i] = y[i].pdf_rev;
        any_delta |= m->delta[i] = y[i].delta;
    }
    for (int j = 0; j < t; j++) {
        m->pc[k - j] = z[j].pdf_fwd;
        m->pl[k - j] = z[j].pdf_rev;
        any_delta |= m->delta[k - j] = z[j].delta;
    }
    const struct vertex *zc = &z[t - 1];
    if (s == 0) {
        /* z_{t-1} lies on an emitter: densities of generating it, and z_{t-2} from it, by emission
         * (for the environment: its direction, then the origin disc). */
        double pick = emitter_pick_prob(sc, zc->prim);
        if (zc->kind == VK_ENV) {
            m->pl[0] = pick * env_pdf_dir(sc, env_dir(zc));
            if (t >= 2) m->pl[1] = edge_pdf(scatter_pdf(sc, zc, zc->wi, zc->wi), zc, &z[t - 2], zc->wi, 1);
        } else {
            m->pl[0] = pick * emitter_pdf_pos(sc, zc->prim, zc->p);
            if (t >= 2) {
                double pdf = emitter_pdf_dir(emit_normal(zc), zc->wi);
                m->pl[1] = edge_pdf(pdf, zc, &z[t - 2], zc->wi, vlen2(vsub(z[t - 2].p, zc->p)));
            }
        }
        m->delta[0] = false;
        return any_delta;
    }
    const struct vertex *yc = &y[s - 1];
    vec3 back = vneg(d);
    m->delta[s - 1] = m->delta[s] = false;
    /* camera side generating y_{s-1}, then y_{s-2} */
    m->pc[s - 1] = edge_pdf(t == 1 ? cam_pdf : scatter_pdf(sc, zc, zc->wi, back), zc, yc, back, dist2);
    if (s >= 2) m->pc[s - 2] = pdf_to_prev(sc, yc, d, &y[s - 2]);
    /* emitter side generating z_{t-1}, then z_{t-2} */
    m->pl[s] = edge_pdf(scatter_pdf(sc, yc, yc->wi, d), yc, zc, d, dist2);
    if (t >= 2) m->pl[s + 1] = pdf_to_prev(sc, zc, back, &z[t - 2]);
    return any_delta;
}

/* f at a connection endpoint: the BSDF (no cosine), the emitted radiance, or the importance. */
static rgb endpoint_f(const struct scene *sc, const struct vertex *v, vec3 d, enum transport mode)
{
    if (v->kind == VK_CAMERA) return v3s(camera_pdf_dir(&sc->cam, v->p, d));
    if (v->kind == VK_EMITTER) return emitter_radiance(sc, v->prim, v->ng, d);
    if (v->kind == VK_ENV) return env_radiance(sc, vneg(d)); /* d leaves the environment */
    if (!v->bc.b || v->bc.b->delta_only) return v3s(0);
    rgb f = bsdf_eval(&v->bc, frame_to_local(&v->sh, v->wi), frame_to_local(&v->sh, d), mode);
    return mode == TRANSPORT_IMPORTANCE ? vscale(f, adjoint_shading_factor(v, v->wi, d)) : f;
}

static double endpoint_cos(const struct vertex *v, vec3 d)
{
    if (v->kind == VK_CAMERA || v->kind == VK_ENV) return 1.0;
    if (v->kind == VK_EMITTER) return fabs(vdot(v->ng, d));
    return fabs(vdot(v->sh.n, d));
}

bool connect_st(const struct path_ctx *pc, const struct vertex *y, int s, const struct vertex *z, int t, int max_s,
                struct connection *out, double *ratios)
{
    const struct scene *sc = pc->sc;
    const struct vertex *zc = &z[t - 1];
    out->px = z[0].px;
    out->py = z[0].py;
    if (s + t - 1 < pc->min_length) return false; /* --min-length: a whole length left out, weights unchanged */
    vec3 d = v3s(0);
    double dist2 = 0, cam_pdf = 0;
    bool leak = false; /* Tungsten's thin-lens splat off the film (tests only, camera.h) */
    if (s == 0) {
        if (t < 2) return false;
        if (zc->kind != VK_ENV && (zc->kind != VK_SURFACE || !zc->front || !sc->prims[zc->prim].emissive)) return false;
        out->f = vmul(zc->beta, vertex_emission(sc, zc, zc->wi));
    } else {
        const struct vertex *yc = &y[s - 1];
        if (zc->kind == VK_ENV) return false; /* nothing scatters at infinity */
        d = edge_dir(yc, zc, &dist2);         /* dist2 = 1 from the environment: no falloff */
        if (dist2 == 0) return false;
        if (t == 1 && !((cam_pdf = camera_raster(&sc->cam, zc->p, vneg(d), &out->px, &out->py)) > 0)) {
            if (!sc->cam.tungsten_defects ||
                !((cam_pdf = camera_tungsten_leak(&sc->cam, zc->p, vneg(d), &out->px, &out->py)) > 0))
                return false;
            leak = true;
        }
        rgb fy = endpoint_f(sc, yc, d, TRANSPORT_IMPORTANCE);
        rgb fz = t == 1 ? v3s(cam_pdf) : endpoint_f(sc, zc, vneg(d), TRANSPORT_RADIANCE);
        double g = endpoint_cos(yc, d) * endpoint_cos(zc, d) / dist2;
        out->f = vscale(vmul(vmul(yc->beta, fy), vmul(fz, zc->beta)), g);
        if (vzero(out->f) || !visible(sc, yc, zc)) return false;
    }
    if (vzero(out->f)) return false;
    struct mis_path m;
    if (densities(pc, y, s, z, t, d, dist2, cam_pdf, &m)) { /* no delta vertex: no chain to unfold */
        const struct vertex *x[MAX_PATH_LENGTH + 2];
        for (int i = 0; i <= m.k; i++)
            x[i] = i < s ? &y[i] : &z[m.k - i];
        mis_unfold_delta_chains(&m, x);
    }
    double r[MAX_PATH_LENGTH + 2];
    double *rat = ratios ? ratios : r;
    out->w = mis_weights(&m, s, max_s, rat);
    if (pc->max_heuristic) out->w = mis_max_weight(rat, m.k, s);
    if (pc->power_heuristic) out->w = mis_power_weight(rat, m.k);
    if (leak) out->w = 1;
    out->f = nonfinite_inject(out->f);
    return true;
}
