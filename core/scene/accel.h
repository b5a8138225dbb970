/* Ray queries. The only module that includes Embree. */
#ifndef ACCEL_H
#define ACCEL_H

#include "scene/scene.h"

struct hit {
    double t;
    int prim, tri; /* tri = -1 for spheres */
    double b1, b2; /* barycentrics of the triangle's vertices 1 and 2 */
};

/* Builds on the instruction set chosen below; fails with a message when PSS_EMBREE_ISA names one
 * this machine cannot run. */
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

/* Embree's instruction set. Embree picks its kernels by the CPU at run time (as glibc's libm does),
 * and the kernels round differently: a hit point differs in its last float bits between an AVX-512
 * and an AVX2 machine. Tests that must hold on every x86-64 machine run once per entry of
 * accel_isas() (tests/isa.h); experiments can pin one for bit-identical images across machines.
 *
 * Names are Embree's "isa=" device settings: "sse2", "sse4.2", "avx", "avx2", "avx512".
 * The default is the environment's PSS_EMBREE_ISA if set (a whole process, e.g. the test runner,
 * on another machine's kernels), else Embree's own choice (the best this CPU runs). */

/* NULL-terminated, lowest first: the ISAs this CPU runs (__builtin_cpu_supports, with the extra
 * features Embree's kernels need) and the linked Embree accepted (a device without error whose
 * native packet widths match the ISA: an Embree built without AVX-512 falls back silently). */
const char *const *accel_isas(void);
/* The ISA of every accel_build from now on; NULL restores the default. Returns false, changing
 * nothing, for a name not in accel_isas(). Process-wide and not thread-safe: call between builds. */
bool accel_set_isa(const char *isa);
/* The ISA accel_build uses: a name from accel_isas(), or NULL for Embree's own choice (or a
 * PSS_EMBREE_ISA this machine cannot run, which accel_build then reports). */
const char *accel_isa(void);

#endif
