/* Internal: the light-selection table built by emitters_build() (emitter.c) and read by the
 * environment code (envmap.c). Not part of the public interface. */
#ifndef EMITTER_TABLE_H
#define EMITTER_TABLE_H

#include "sampling/distrib.h"
#include "scene/scene.h"

struct emitter_table {
    int n;              /* emissive prims, in prim order (including the environment) */
    int *prim;          /* n: prim index of each slot */
    double *power;      /* n: selection weight (see emitters_build) */
    double total_power; /* their sum, computed once */
    double *cdf;        /* n + 1: light selection CDF */
    int nprims;
    int *slot; /* nprims: slot of each prim, -1 if not an emitter */
    /* area emitters, per slot */
    double *area; /* n: surface area used for the pdf (0 for the environment) */
    int *tri_off; /* n: meshes: offset of the triangle CDF in tri_cdf (ntris + 1 entries); else -1 */
    double *tri_cdf;
    /* environment */
    int env_slot;              /* -1 if none */
    bool env_map;              /* sampled by the 2D distribution (else uniform sphere) */
    struct distrib2d env_dist; /* over the lat-long image: x = column, y = row from the top */
    vec3 env_center;           /* bounding sphere of the finite geometry */
    double env_R;
};

/* envmap.c: builds the environment part; returns the integral of luminance over the sphere
 * (sr), or -1 after writing an error. */
double env_build(struct emitter_table *t, const struct scene *sc, const struct prim *pr, char *err, size_t errlen,
                 const char *where);
void env_free(struct emitter_table *t);

#endif
