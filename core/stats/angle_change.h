/* Angle change between the current and the proposed path of a small step (thesis Eq. 5.38-5.39),
 * accumulated per pixel of the current path and per path length.
 *
 * Eq. 5.38 sums, over corresponding edges of a subpath and its perturbed version, the angle between
 * their directions; Eq. 5.39 divides the sum over both subpaths by the number of edges. The
 * thesis's denominator, max(0, s - 2) + max(0, t - 2), does not count the s - 1 + t - 1 edges its
 * numerator sums; here the sum is divided by the edges summed, so Delta psi is the mean angle per
 * edge. The connecting edge is excluded (neither subpath samples it); paths of length 1 have no
 * edge left and are ignored, as are proposals whose subpaths end early (no path to compare) or
 * that change the technique (different subpaths). */
#ifndef ANGLE_CHANGE_H
#define ANGLE_CHANGE_H

#include "io/image.h"
#include "path/path.h"
#include "stats/mlt_stats.h"
#include <stdio.h>

/* Eq. 5.38 over the n - 1 edges of two subpaths of n vertices. */
double angle_subpath(const struct vertex *a, const struct vertex *b, int n);
/* Eq. 5.39 between the current subpaths (camera cur_cam[0..t-1], emitter cur_emi[0..s-1]) and a
 * proposal's of the same split (cam, emi); false without edges. */
bool angle_change(const struct vertex *cur_cam, int t, const struct vertex *cur_emi, int s, const struct vertex *cam,
                  const struct vertex *emi, double *dpsi);

/* Per thread; threads are merged in a fixed order. */
struct angle_acc {
    int w, h;
    double *sum, *count;                         /* per pixel */
    struct accept_cell len[MAX_PATH_LENGTH + 1]; /* [0]: all lengths; batch means as mlt_stats */
    long skipped;                                /* small steps without a comparable proposal */
};

void angle_acc_init(struct angle_acc *a, int w, int h);
void angle_acc_free(struct angle_acc *a);
/* One small step's Delta psi, at the current path's raster position (px, py), length k. */
void angle_acc_add(struct angle_acc *a, double px, double py, int k, double dpsi);
void angle_acc_merge(struct angle_acc *dst, const struct angle_acc *src);
/* Mean Delta psi per pixel (grey; 0 where no step started). */
struct image *angle_acc_image(const struct angle_acc *a);
/* `length,steps,mean_dpsi,stderr` rows (stderr: batch means, nan with < 2 batches) and an `all` row. */
void angle_acc_write_csv(FILE *f, const struct angle_acc *a);

#endif
