/* Scrambled (0,2)-sequences: quasi-Monte Carlo numbers for PT and BDPT (`bin/render --sampler
 * sobol`), an alternative to independent numbers, as Tungsten's default sampler and pbrt's.
 *
 * The numbers of one pixel are consecutive points of the first two Sobol dimensions (van der
 * Corput and its Pascal-matrix partner), a (0,2)-sequence: any 2^m consecutive points aligned at a
 * multiple of 2^m put exactly one point in every elementary interval of area 2^-m. A sample's
 * dimensions are taken in pairs (2k, 2k+1); each pair reads the sequence at the sample's index
 * shuffled by a pair-specific nested uniform (Owen) scramble of the index, so that pairs are
 * decorrelated ("padding"), and each dimension is Owen-scrambled with its own seed (Burley,
 * "Practical Hash-based Owen Scrambling", JCGT 2020: a Laine-Karras style hash on the reversed
 * bits). Scrambling keeps the net property and makes every number uniform on [0, 1): estimates
 * stay unbiased. Stateless: a number is a function of (key, sample index, dimension), so threads,
 * passes and checkpoints need nothing more than the independent sampler does. */
#ifndef SOBOL02_H
#define SOBOL02_H

#include <stdint.h>

/* Dimension `dim` of sample `index` of the sequence keyed by `key` (one key per pixel and run
 * seed), a multiple of 2^-32 in [0, 1). */
double sobol02_sample(uint64_t key, uint32_t index, uint32_t dim);

#endif
