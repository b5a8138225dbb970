/* The fuzz build's stand-in for core/scene/accel.c's two ray queries. No target casts a ray, but
 * the checkpoint target links the chains' checkpoint code, and through the mutation registry
 * (core/mcmc/mutation_registry.c) every mutation's step and so the walks. A ray cast here would be a
 * target reaching render code: abort, which libFuzzer reports with the input. */
#include "scene/accel.h"
#include <stdio.h>
#include <stdlib.h>

bool accel_intersect(const struct accel *a, vec3 o, vec3 d, double tmin, double tmax, struct hit *h)
{
    (void)a, (void)o, (void)d, (void)tmin, (void)tmax, (void)h;
    fprintf(stderr, "fuzz: accel_intersect called: the fuzz targets cast no rays\n");
    abort();
}

bool accel_occluded(const struct accel *a, vec3 o, vec3 d, double tmin, double tmax)
{
    (void)a, (void)o, (void)d, (void)tmin, (void)tmax;
    fprintf(stderr, "fuzz: accel_occluded called: the fuzz targets cast no rays\n");
    abort();
}
