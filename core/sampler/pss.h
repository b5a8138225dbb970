/* The primary-sample-space state of a Markov chain (thesis §3.5-3.8, Kelemen et al. 2002), as a
 * sampler: path code draws its numbers from it exactly as under plain Monte Carlo.
 *
 * A proposal is started with pss_begin(large); numbers are mutated lazily when path code reads
 * them, so only the dimensions a path uses cost anything. pss_accept() keeps the proposal;
 * pss_reject() restores every number touched by it, bit for bit.
 * Small steps: Kelemen's exponential kernel (s1 = 1/1024, s2 = 1/64) or a Gaussian, wrapped to
 * [0, 1). A dimension not read for n iterations receives min(n, 16) small steps at once: any
 * symmetric kernel keeps detailed balance, and this keeps the cost bounded.
 * Annotations (thesis §4.1-4.2): with `rap`, image dims get steps scaled by min(W, H) / W and
 * min(W, H) / H so that steps are isotropic in pixels; with `rap_resolution` additionally by
 * rap_reference / min(W, H) (a fixed step in pixels at every resolution); with `cdc`, small steps
 * leave DIM_DISCRETE numbers unchanged. */
#ifndef PSS_H
#define PSS_H

#include "sampler/sampler.h"
#include <stdint.h>

enum pss_kernel { KERNEL_KELEMEN, KERNEL_GAUSSIAN };

struct pss_opts {
    enum pss_kernel kernel;
    double s1, s2; /* Kelemen: smallest and largest step */
    double sigma;  /* Gaussian: standard deviation */
    bool rap, rap_resolution, cdc;
    int width, height;    /* image, for rap */
    double rap_reference; /* pixels, for rap_resolution (default 1024) */
};
void pss_opts_default(struct pss_opts *o, int width, int height);

struct pss_dim {
    double value, saved;
    uint64_t modified, saved_modified;
    uint64_t stamp; /* the kept proposal that last saved it (pss_begin_kept) */
};

struct pss_sampler {
    struct sampler base;
    struct pss_opts o;
    rng r;
    uint64_t iteration, last_large;
    bool large;
    bool kept;               /* the proposal keeps the numbers it does not set (pss_begin_kept) */
    uint64_t stamp;          /* kept proposals begun */
    double scale_x, scale_y; /* image-dim step factors */
    /* Kelemen's kernel: |step| = s2 (s1/s2)^xi. xi's top 8 bits index kelemen[] = s2 (s1/s2)^(j/256),
     * its next 8 kelemen_fine[] = (s1/s2)^((i + 2^-16) / 2^16) (the offset centres m's cells); its
     * low 15 bits m give the factor 1 + kelemen_slope * m. */
    double kelemen[256], kelemen_fine[256], kelemen_slope;
    struct pss_dim d[STREAM_COUNT][STREAM_DIMS];
    int ntouched;
    uint16_t touched[STREAM_COUNT * STREAM_DIMS];
};

/* The state starts as if after a large step: every number fresh when first read. */
void pss_init(struct pss_sampler *p, const struct pss_opts *o, uint64_t seed, uint64_t stream);
void pss_begin(struct pss_sampler *p, bool large);
/* A proposal that sets its numbers itself (pss_set) and keeps every other number: not an iteration
 * (as pss_replace's changes are not), so a number it reads that the state read last is its value,
 * and one it does not read catches up later as if it had not happened. A fused perturbation's
 * numbers from an inversion (core/mcmc/fused.c), which may keep a whole subpath's numbers without
 * reading them. Ends with pss_accept or pss_reject. */
void pss_begin_kept(struct pss_sampler *p);
void pss_accept(struct pss_sampler *p);
void pss_reject(struct pss_sampler *p);
/* Sets a number as part of the current proposal (restored by pss_reject), e.g. the technique
 * number an MCTLS step selected. */
void pss_set(struct pss_sampler *p, int stream, int index, double u);
/* Outside a proposal: changes the current state itself, as an always-accepted move does (PITP's
 * technique perturbation, core/mcmc/pitp.c). pss_replace sets a number of the current state; pss_forget
 * makes one fresh (uniform, drawn when next read), as if never read since the last large step:
 * the numbers a path stops using are redrawn from their uniform conditional. Neither counts as an
 * iteration, so the lazy catch-up of other numbers is unaffected. */
void pss_replace(struct pss_sampler *p, int stream, int index, double u);
void pss_forget(struct pss_sampler *p, int stream, int index);
/* Copies the current numbers of all dims read so far into u (NAN where never read). */
void pss_export(const struct pss_sampler *p, double (*u)[STREAM_DIMS]);
/* Replaces the state by u (used to start a chain from a seed path); NAN entries stay fresh. */
void pss_import(struct pss_sampler *p, const double (*u)[STREAM_DIMS]);
/* The current state's value of a number, for proposals that compute their numbers themselves
 * (controlled small steps): a number not read since the last accepted large step is an independent
 * uniform under the target, so it is revealed now as a fresh draw, recorded in the proposal. */
double pss_current(struct pss_sampler *p, int stream, int index);
/* The lazy read path code goes through (sampler_next), for one number named directly: fresh after a
 * large step, else the small steps it missed, once per proposal. */
double pss_read(struct pss_sampler *p, int stream, int index, enum dim_kind kind);
/* One small step of value u for a number of the given kind (exposed for tests). */
double pss_small_step(struct pss_sampler *p, enum dim_kind kind, double u);

#endif
