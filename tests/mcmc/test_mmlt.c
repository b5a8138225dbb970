/* MMLT's technique number (core/mcmc/mmlt.h): the number that MCTLS's large step and PITP's
 * perturbation store for technique t must select t again through the mapping mmlt_eval reads it
 * with, t = 1 + floor((k + 1) u), in floating point. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "mcmc/mmlt.h"
#include <math.h>

static void check_maps_back(int t, int k, double xi)
{
    double u = mmlt_technique_number(t, k, xi);
    cr_assert(u >= 0 && u < 1, "k %d, t %d, xi %.17g: u %.17g outside [0, 1)", k, t, xi, u);
    cr_assert_eq(mmlt_technique(k, u), t, "k %d, t %d, xi %.17g: u %.17g selects t = %d", k, t, xi, u,
                 mmlt_technique(k, u));
    cr_assert_eq(1 + (int)((k + 1) * u), t, "k %d, t %d, xi %.17g: u %.17g unclamped", k, t, xi, u);
}

/* Every technique of every length, at both ends of its interval (xi = 0, the generator's smallest
 * and largest numbers, the largest double below 1) and at random points. */
Test(mmlt, technique_number_maps_back_exhaustively)
{
    const double ends[] = {0.0, 1.0 / 4294967296.0, 0.5, 1.0 - 1.0 / 4294967296.0, 0x1.fffffffffffffp-1};
    rng r;
    rng_seed(&r, 5, 0);
    for (int k = 1; k <= MAX_PATH_LENGTH; k++)
        for (int t = 1; t <= k + 1; t++) {
            for (size_t i = 0; i < sizeof ends / sizeof *ends; i++)
                check_maps_back(t, k, ends[i]);
            for (int i = 0; i < 64; i++)
                check_maps_back(t, k, rng_uniform(&r));
        }
}

/* Why the number is nudged: the lower bound (t - 1) / (k + 1), rounded in double and multiplied by
 * k + 1, can round below t - 1. For k = 21, t = 16, fl(15 / 22) * 22 < 15, so the uniform point of
 * xi = 0 (which the 32-bit generator draws) would select t = 15. */
Test(mmlt, interval_bound_alone_can_select_the_neighbour)
{
    int k = 21, t = 16;
    double lo = invert_discrete((double)(t - 1) / (k + 1), (double)t / (k + 1), 0.0);
    cr_assert_eq(mmlt_technique(k, lo), t - 1, "the example no longer shows the rounding (u %.17g)", lo);
    check_maps_back(t, k, 0.0);
}
