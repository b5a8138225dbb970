/* Emitters: emissive quads, meshes (and cubes), spheres, and the environment (infinite sphere).
 * Every sampling function has its pdf and inverse (thesis §5.1).
 *
 * Emitter vertex 0 of the emitter subpath draws, in this order: the light choice (1 discrete),
 * the position (meshes: 1 discrete triangle choice by area, then 2 continuous; quads and spheres:
 * 2 continuous; environment: a direction by the map's luminance, 2 continuous, then a point on
 * the scene's bounding disc, 2 continuous), then for area emitters the emitted direction
 * (2 continuous, cosine-weighted about the front normal). */
#ifndef EMITTER_H
#define EMITTER_H

#include "sampler/sampler.h"
#include "scene/scene.h"

/* Built once per scene; error (one line) for a zero-area or non-finite emitter. */
struct emitter_table *emitters_build(const struct scene *sc, char *err, size_t errlen);
void emitters_free(struct emitter_table *t);
int emitters_count(const struct scene *sc);

/* Light selection in proportion to emitted power; one DIM_DISCRETE number. Returns the prim. */
int emitter_pick(const struct scene *sc, struct sampler *s, double *prob);
double emitter_pick_prob(const struct scene *sc, int prim);
bool emitter_pick_invert(const struct scene *sc, int prim, struct sampler *w);

/* A point on an area emitter; pdf in the area measure. */
struct emitter_pos {
    vec3 p, n; /* n: unit front normal (sphere: outward) */
    double pdf;
    int tri; /* meshes: the triangle; else -1 */
};
bool emitter_sample_pos(const struct scene *sc, int prim, struct sampler *s, struct emitter_pos *out);
double emitter_pdf_pos(const struct scene *sc, int prim, vec3 p);
bool emitter_invert_pos(const struct scene *sc, int prim, const struct emitter_pos *pos, struct sampler *w);

/* Emitted direction, cosine-weighted about n; pdf in solid angle. */
vec3 emitter_sample_dir(vec3 n, struct sampler *s, double *pdf);
double emitter_pdf_dir(vec3 n, vec3 d);
bool emitter_invert_dir(vec3 n, vec3 d, struct sampler *w);

/* Radiance leaving area emitter `prim` at a point with front normal n in direction d
 * (zero on the back side). */
rgb emitter_radiance(const struct scene *sc, int prim, vec3 n, vec3 d);

/* Environment (sc->env_prim >= 0). `d` is the direction from the scene toward the environment. */
rgb env_radiance(const struct scene *sc, vec3 d);
bool env_sample_dir(const struct scene *sc, struct sampler *s, vec3 *d, double *pdf);
double env_pdf_dir(const struct scene *sc, vec3 d);
bool env_invert_dir(const struct scene *sc, vec3 d, struct sampler *w);
/* Origin of an emitter subpath leaving the environment along -d: a point on the disc of radius
 * R (scene bounding sphere) perpendicular to d, placed outside the scene; pdf = 1 / (pi R^2). */
vec3 env_sample_origin(const struct scene *sc, vec3 d, struct sampler *s, double *pdf);
bool env_invert_origin(const struct scene *sc, vec3 d, vec3 origin, struct sampler *w);
double env_radius(const struct scene *sc);

#endif
