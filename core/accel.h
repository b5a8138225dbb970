/* Ray queries. The only module that includes Embree. */
#ifndef ACCEL_H
#define ACCEL_H

#include "scene.h"

struct hit {
    double t;
    int prim, tri;   /* tri = -1 for spheres */
    double b1, b2;   /* barycentrics of the triangle's vertices 1 and 2 */
};

struct accel *accel_build(const struct scene *sc, char *err, size_t errlen);
void accel_free(struct accel *a);
/* Closest hit with t in (tmin, tmax). */
bool accel_intersect(const struct accel *a, vec3 o, vec3 d, double tmin, double tmax, struct hit *h);
/* Any hit with t in (tmin, tmax). */
bool accel_occluded(const struct accel *a, vec3 o, vec3 d, double tmin, double tmax);

/* Rays the calling thread has cast so far, by query kind: what bin/bench divides by the samples of
 * a 1-thread run (its worker is the calling thread). Per thread, so counting costs the hot paths
 * one increment and no cache-line sharing. */
struct ray_counts {
    unsigned long long closest, shadow;
};
struct ray_counts accel_ray_counts(void);

#endif
