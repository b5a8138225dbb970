/* Per-technique images of one path length k (MMLT paper §5 and its Fig. 5): for every technique
 * t = 1..k+1 (t camera vertices, s = k + 1 - t emitter vertices) the image of its MIS-weighted
 * contribution, and the number of chain samples in it at each pixel.
 *
 * Contribution: the chain's own expected-value splats of length k, split by technique (the
 * proposal with weight a, the current state with 1 - a, each times b_k / (P(k) f)), so that summed
 * over t they are the length-k part of the rendered image up to rounding.
 * Sample count: after every iteration of the length-k chain, its state counts once at the pixel of
 * the technique it is in. An MMLT state is in one technique (its technique number). A PSSMLT state
 * evaluates every technique of every length at once; it counts once for each technique whose
 * length-k connection is non-zero, at that connection's pixel (the paper's reading: PSSMLT uses
 * BDPT as its sampler and so gives every technique the same samples whatever they contribute).
 *
 * One accumulator per thread tracks that thread's chain of length k (PSSMLT: its one chain); the
 * MCMC driver splits each evaluated state by technique (mcmc/tech_split.c) and hands the split to
 * tech_acc_eval, then calls tech_acc_step after each acceptance decision. Threads are merged in a
 * fixed order. */
#ifndef TECH_IMAGE_H
#define TECH_IMAGE_H

#include "io/image.h"
#include "path/splat.h"
#include <stdio.h>

#define TECH_MAX (MAX_PATH_LENGTH + 2) /* index t = 1..k+1 */

/* One state's length-k contributions per technique (on[t]: non-zero). */
struct tech_split {
    bool on[TECH_MAX];
    struct splat s[TECH_MAX];
};

struct tech_acc {
    int k, w, h;
    struct image *contrib[TECH_MAX]; /* unnormalised per thread; final units after tech_acc_reduce */
    double *count[TECH_MAX];         /* per pixel, row-major */
    long samples;                    /* iterations of the length-k chain */
    struct tech_split cur, prop;     /* the tracked chain's state and its latest proposal */
    bool active;                     /* the latest evaluation was of the tracked chain */
};

void tech_acc_init(struct tech_acc *a, int k, int w, int h, bool tent);
void tech_acc_free(struct tech_acc *a);
/* Per-thread accumulators for T threads, and their merge into one (film scale applied to the
 * contributions, as to the image); the merge frees the per-thread ones. */
struct tech_acc *tech_acc_alloc(int threads, int k, int w, int h, bool tent);
struct tech_acc *tech_acc_reduce(struct tech_acc *per_thread, int threads, double scale);
void tech_acc_destroy(struct tech_acc *a);

/* Whether a tracks the chain of length chain_k (0: PSSMLT's chain, of every length). */
static inline bool tech_acc_tracks(const struct tech_acc *a, int chain_k) { return chain_k == 0 || chain_k == a->k; }
/* After a state of the chain of length chain_k (0: PSSMLT) was evaluated (start: a chain's first
 * state; else a proposal): sp is its length-k split, read only when a tracks that chain. */
void tech_acc_eval(struct tech_acc *a, int chain_k, const struct tech_split *sp, bool start);
/* After the acceptance decision of the evaluated proposal: a its acceptance probability, f and
 * f_cur the proposal's and the current state's targets, scale the chain's b_k / P(k). */
void tech_acc_step(struct tech_acc *a, double acc_prob, bool accepted, double f, double f_cur, double scale);

/* How closely the sample counts follow the contributions. Shares of all samples and of all
 * contribution (luminance) per technique; tv = half the L1 distance between the two share
 * vectors (0: counts proportional to contributions); r = Pearson correlation, over every
 * (block of blk x blk pixels, technique) with samples and contribution, of the block's sample share
 * and contribution share of that technique (the paper's RGB visualisation made a number). */
struct tech_follow {
    double samples[TECH_MAX], contrib[TECH_MAX]; /* totals over the image (contribution: luminance) */
    double sample_share[TECH_MAX], contrib_share[TECH_MAX];
    double tv, r;
    int cells;
};
void tech_follow(const struct tech_acc *a, int blk, struct tech_follow *out);

/* `technique,s,t,samples,sample_share,contribution,contribution_share` rows, then `# tv` and `# r`. */
void tech_acc_write_csv(FILE *f, const struct tech_acc *a, int blk);
/* PREFIX.tech-tT.exr (contribution, RGB) and PREFIX.count-tT.exr (samples, grey) for every t, PNGs of
 * both exposed alike (0.5 / the mean over pixels of the sum over t, of the contributions' luminance
 * and of the counts: a technique's two PNGs look alike where its counts follow its contributions) and PREFIX.tech.csv
 * with `header` on top (follow statistics over 8 x 8 blocks). All written atomically. */
bool tech_acc_write(const struct tech_acc *a, const char *prefix, const char *header, char *err, size_t errlen);

#endif
