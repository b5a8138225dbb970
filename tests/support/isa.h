/* Running a test under each of Embree's instruction sets (core/scene/accel.h): hit points differ in their
 * last bits between Embree's kernels, so a test of anything that depends on them (inversion,
 * retracing, exact agreement) must hold under every kernel an x86-64 machine may pick, not only
 * under this machine's best one. */
#ifndef TEST_ISA_H
#define TEST_ISA_H

/* Calls fn once per entry of accel_isas(), lowest first, with that ISA set for every scene the call
 * loads (scenes built before keep theirs), then restores the default. Under PSS_EMBREE_ISA (the
 * process emulates one machine) only that ISA. */
void test_each_isa(void (*fn)(const char *isa, void *ctx), void *ctx);

#endif
