/* Inverse random walks, thesis Alg. 2: the numbers that make walk_camera / walk_emitter retrace
 * given vertices. Each block is inverted independently (fixed layout), so a suffix can be
 * re-inverted while the numbers of earlier vertices stay as they are. */
#include "camera.h"
#include "emitter.h"
#include "path.h"

static vec3 dir_to(const struct vertex *a, const struct vertex *b)
{
    double dist2;
    return edge_dir(a, b, &dist2);
}

/* Block i of a subpath: the BSDF sample at v[i] that produced v[i+1]. */
static bool invert_scatter(const struct vertex *v, int i, struct sampler *w)
{
    if (!v[i].bc.b) return false;
    vec3 wi = frame_to_local(&v[i].sh, v[i].wi), wo = frame_to_local(&v[i].sh, dir_to(&v[i], &v[i + 1]));
    return bsdf_invert(&v[i].bc, wi, wo, w);
}

bool invert_camera(const struct path_ctx *pc, const struct vertex *v, int n, int from, struct sampler *w)
{
    for (int i = from; i < n - 1; i++) {
        sampler_begin(w, STREAM_CAMERA, i);
        if (i == 0) {
            double px, py;
            if (!(camera_raster(&pc->sc->cam, dir_to(&v[0], &v[1]), &px, &py) > 0)) return false;
            camera_invert(&pc->sc->cam, px, py, w);
        } else if (!invert_scatter(v, i, w)) {
            return false;
        }
    }
    return true;
}

bool invert_emitter(const struct path_ctx *pc, const struct vertex *v, int n, int from, struct sampler *w)
{
    const struct scene *sc = pc->sc;
    for (int i = from; i < n; i++) {
        sampler_begin(w, STREAM_EMITTER, i);
        if (i == 0 && v[0].kind == VK_ENV) {
            if (!emitter_pick_invert(sc, v[0].prim, w) || !env_invert_dir(sc, env_dir(&v[0]), w) ||
                !env_invert_origin(sc, env_dir(&v[0]), v[0].p, w))
                return false;
        } else if (i == 0) {
            struct emitter_pos pos = {v[0].p, v[0].ng, 0, v[0].tri};
            if (!emitter_pick_invert(sc, v[0].prim, w) || !emitter_invert_pos(sc, v[0].prim, &pos, w)) return false;
            if (n > 1 && !emitter_invert_dir(v[0].ng, dir_to(&v[0], &v[1]), w)) return false;
        } else if (i < n - 1 && !invert_scatter(v, i, w)) {
            return false;
        }
    }
    return true;
}
