/* Goodness of fit of inverted primary-sample-space numbers (thesis §5.1, Eq. 5.3): the numbers an
 * inverse sampling function returns for forward-sampled paths must have the density of the numbers
 * the forward function was given for the paths it produced.
 *
 * A set holds numbers per dimension slot (SLOT = stream * INV_SLOTS_PER_STREAM + index within the
 * stream, the first INV_BLOCKS blocks of the camera and emitter streams): all values of each slot
 * (for the KS test), a 16-bin histogram per slot and an 8 x 8 histogram per pair of slots of the
 * same block (the block of one vertex: a BSDF's discrete and continuous numbers, the camera's lens
 * and image numbers, the emitter's choice, position and direction). Tests use only the samples in
 * which the slots were defined. Against "uniform" the tests are one-sample (expected counts n / k,
 * Kolmogorov against the identity); against a reference set (forward numbers of successful
 * forward samples, where forward sampling can fail and so conditions the numbers) two-sample
 * (chi-square homogeneity, two-sample Kolmogorov-Smirnov). */
#ifndef INV_GOF_H
#define INV_GOF_H

#include <stdbool.h>
#include <stddef.h>

#define INV_BLOCKS 4 /* vertex blocks per stream that are tested */
#define INV_SLOTS_PER_STREAM (INV_BLOCKS * 8)
#define INV_SLOTS (2 * INV_SLOTS_PER_STREAM)
#define INV_BINS_1D 16
#define INV_BINS_2D 8
#define INV_PAIRS 28         /* pairs of the 8 slots of a block */
#define INV_MIN_SAMPLES 1000 /* a slot or pair with fewer samples (in either set) is not tested */
#define INV_BLOCKS_ALL (2 * INV_BLOCKS)

struct inv_set {
    long n;                /* vectors added */
    long count[INV_SLOTS]; /* values per slot */
    long cap[INV_SLOTS];
    float *val[INV_SLOTS]; /* owned */
    long h1[INV_SLOTS][INV_BINS_1D];
    long h2[INV_BLOCKS_ALL][INV_PAIRS][INV_BINS_2D * INV_BINS_2D];
    long pair_n[INV_BLOCKS_ALL][INV_PAIRS];
};

void inv_set_init(struct inv_set *s);
void inv_set_free(struct inv_set *s);
/* Adds one vector: u[slot] in [0, 1), NAN where the slot is undefined. */
void inv_set_add(struct inv_set *s, const double *u);

/* The result of one function's tests: the chi-square test with the smallest p-value (and its
 * label), the KS test with the smallest p-value, and both p-values Sidak-adjusted over the number
 * of tests of their kind: p_adj = 1 - (1 - p_min)^m. */
struct inv_gof {
    int chi_tests, ks_tests;
    double chi2, chi_p, chi_p_adj;
    int chi_dof;
    char chi_worst[32];
    double ks_d, ks_p, ks_p_adj;
    long ks_n;
    char ks_worst[32];
};

/* Tests `test` against the uniform density (ref NULL) or against the reference set. */
void inv_gof_evaluate(struct inv_set *test, struct inv_set *ref, struct inv_gof *out);

/* The name of a slot: "c3" (camera stream, index 3), "e9". */
void inv_slot_name(int slot, char *buf, size_t n);

/* Kolmogorov's limiting distribution: P(sqrt(n) D > lambda). */
double inv_ks_q(double lambda);

/* Sidak: the per-test level of m tests at family-wise level alpha, and a p-value adjusted over m. */
double inv_sidak_alpha(double alpha, int m);
double inv_sidak_p(double p, int m);

#endif
