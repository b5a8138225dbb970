#include "stats/dist_merge.h"
#include "base/dist.h"

struct merge {
    const struct thread_results *t;
    struct image *img;
    struct mlt_stats *stats;
    struct angle_acc *angle;
};

static void add_threads(void *p)
{
    struct merge *m = p;
    const struct thread_results *t = m->t;
    for (int i = 0; i < t->threads; i++) { /* fixed order: reproducible sums */
        img_accumulate(m->img, t->img[i], t->scale);
        if (t->stats) stats_merge(m->stats, &t->stats[i]);
        if (t->angle) angle_acc_merge(m->angle, &t->angle[i]);
    }
}

void merge_thread_results(const struct thread_results *t, struct image *img_out, struct mlt_stats *stats_out,
                          struct angle_acc *angle_out)
{
    struct merge m = {t, img_out, stats_out, angle_out};
    size_t px = (size_t)img_out->w * img_out->h;
    /* Every field the merges add travels; the statistics are flat structs of counts and sums. */
    struct dist_buf bufs[6] = {{img_out->px, 3 * px * sizeof *img_out->px}};
    int n = 1;
    if (t->stats) bufs[n++] = (struct dist_buf){stats_out, sizeof *stats_out};
    if (t->angle) {
        size_t cells = (size_t)angle_out->w * angle_out->h;
        bufs[n++] = (struct dist_buf){angle_out->sum, cells * sizeof *angle_out->sum};
        bufs[n++] = (struct dist_buf){angle_out->count, cells * sizeof *angle_out->count};
        bufs[n++] = (struct dist_buf){angle_out->len, sizeof angle_out->len};
        bufs[n++] = (struct dist_buf){&angle_out->skipped, sizeof angle_out->skipped};
    }
    dist_chain(bufs, n, add_threads, &m);
}
