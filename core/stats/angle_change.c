/* Angle-change statistics of small steps (thesis Eq. 5.38-5.39; see angle_change.h). */
#include "stats/angle_change.h"
#include "base/util.h"
#include <stdlib.h>
#include <string.h>

/* atan2 of |cross| and dot keeps small angles accurate (acos near 1 loses half the digits). */
static double angle_between(vec3 a, vec3 b) { return atan2(vlen(vcross(a, b)), vdot(a, b)); }

double angle_subpath(const struct vertex *a, const struct vertex *b, int n)
{
    double s = 0, d2;
    for (int i = 0; i + 1 < n; i++)
        s += angle_between(edge_dir(&a[i], &a[i + 1], &d2), edge_dir(&b[i], &b[i + 1], &d2));
    return s;
}

bool angle_change(const struct vertex *cur_cam, int t, const struct vertex *cur_emi, int s, const struct vertex *cam,
                  const struct vertex *emi, double *dpsi)
{
    int edges = (t > 1 ? t - 1 : 0) + (s > 1 ? s - 1 : 0);
    if (edges == 0 || t + s - 1 < 2) return false; /* paths of length 1 are ignored */
    *dpsi = (angle_subpath(cur_cam, cam, t) + angle_subpath(cur_emi, emi, s)) / edges;
    return true;
}

void angle_acc_init(struct angle_acc *a, int w, int h)
{
    memset(a, 0, sizeof *a);
    a->w = w;
    a->h = h;
    a->sum = xcalloc((size_t)w * h, sizeof *a->sum);
    a->count = xcalloc((size_t)w * h, sizeof *a->count);
}

void angle_acc_free(struct angle_acc *a)
{
    free(a->sum);
    free(a->count);
    a->sum = a->count = NULL;
}

void angle_acc_add(struct angle_acc *a, double px, double py, int k, double dpsi)
{
    cell_add(&a->len[k], dpsi);
    cell_add(&a->len[0], dpsi);
    if (!(px >= 0 && py >= 0)) return;
    int x = (int)px, y = (int)py;
    if (x >= a->w || y >= a->h) return;
    a->sum[(size_t)y * a->w + x] += dpsi;
    a->count[(size_t)y * a->w + x] += 1;
}

void angle_acc_merge(struct angle_acc *dst, const struct angle_acc *src)
{
    for (size_t i = 0; i < (size_t)dst->w * dst->h; i++) {
        dst->sum[i] += src->sum[i];
        dst->count[i] += src->count[i];
    }
    for (int k = 0; k <= MAX_PATH_LENGTH; k++)
        cell_merge(&dst->len[k], &src->len[k]);
    dst->skipped += src->skipped;
}

struct image *angle_acc_image(const struct angle_acc *a)
{
    struct image *im = img_create(a->w, a->h);
    for (int y = 0; y < a->h; y++)
        for (int x = 0; x < a->w; x++) {
            size_t i = (size_t)y * a->w + x;
            if (a->count[i] > 0) img_add(im, x, y, v3s(a->sum[i] / a->count[i]));
        }
    return im;
}

void angle_acc_write_csv(FILE *f, const struct angle_acc *a)
{
    fprintf(f, "length,steps,mean_dpsi,stderr\n");
    for (int k = 1; k <= MAX_PATH_LENGTH; k++)
        if (a->len[k].attempts > 0)
            fprintf(f, "%d,%ld,%.9g,%.6g\n", k, a->len[k].attempts, cell_mean(&a->len[k]), cell_stderr(&a->len[k]));
    if (a->len[0].attempts > 0)
        fprintf(f, "all,%ld,%.9g,%.6g\n", a->len[0].attempts, cell_mean(&a->len[0]), cell_stderr(&a->len[0]));
}
