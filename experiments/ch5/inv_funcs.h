/* The sampling functions whose inverses bin/inverse_density tests (thesis §5.1, Eq. 5.3): BSDFs of
 * the committed scenes (each type once, rough ones also at other roughnesses, refracting ones at
 * another IOR), the camera ray (the scene's camera and a thin lens), emitter sampling (light
 * choice, point and direction) and whole paths of one technique (s, t). Each draws one sample
 * forward from fresh uniform numbers, which it records, and inverts the sample it drew with the
 * inverse sampling function of the core (bsdf invert, invert_camera, invert_emitter). */
#ifndef INV_FUNCS_H
#define INV_FUNCS_H

#include "ch5/inv_gof.h"
#include "path/path.h"

enum inv_kind { INV_BSDF, INV_CAMERA, INV_EMITTER, INV_PATH };

struct inv_func {
    char name[96];
    enum inv_kind kind;
    const struct scene *sc;
    struct bsdf b; /* INV_BSDF: a prepared copy of the scene's BSDF with the variant's parameters */
    int s, t;      /* INV_PATH: the technique; INV_CAMERA: t = 2 (the camera vertex and its hit);
                    * INV_EMITTER: s = 2 (the emitter vertex and its hit) */
};

/* A recording sampler: fresh uniform numbers, each kept at its (stream, index). */
struct inv_rec {
    struct sampler base;
    rng r;
    double u[STREAM_COUNT][STREAM_DIMS];
    int hi[STREAM_COUNT]; /* indices >= hi are unset (NAN) */
};

/* One thread's state: the recording sampler, the writer the inverse fills, the sample drawn. */
struct inv_scratch {
    struct inv_rec rec;
    struct sampler_writer w;
    struct vertex y[MAX_SUBPATH_VERTS], z[MAX_SUBPATH_VERTS];
    vec3 wi, wo;
};

void inv_rec_init(struct inv_rec *r, uint64_t seed, uint64_t stream);

/* Appends the BSDF functions of scene sc (types not in *seen yet; *seen a bit set of types) to
 * f[*n...] (capacity cap); returns false when cap is reached. */
bool inv_funcs_bsdf(const struct scene *sc, const char *scene_name, unsigned long *seen, struct inv_func *f, int *n,
                    int cap);
/* Appends the camera, thin lens (sc's camera with a lens; lens_sc is a copy of the scene the
 * function may change), emitter and path functions of a scene, techniques (s, t) of `tech` (pairs,
 * ntech of them). */
bool inv_funcs_scene(const struct scene *sc, struct scene *lens_sc, const char *scene_name, const int (*tech)[2],
                     int ntech, struct inv_func *f, int *n, int cap);

/* Draws sample `i` of f forward from x->rec's fresh numbers; true when it produced a sample (a
 * BSDF direction, a camera or emitter subpath of 2 vertices, a path of technique (s, t) with a
 * non-zero contribution). fwd[INV_SLOTS] receives the numbers it read (NAN elsewhere). */
bool inv_forward(const struct inv_func *f, struct inv_scratch *x, long i, double *fwd);
/* Inverts the sample of the last successful inv_forward; false when the inverse refuses it or
 * returns a number outside [0, 1). inv[INV_SLOTS] receives the numbers it wrote. */
bool inv_inverse(const struct inv_func *f, struct inv_scratch *x, double *inv);

#endif
