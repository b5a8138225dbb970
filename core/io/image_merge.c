/* Per-thread images (and what travels with them) merged over the job (image_merge.h). */
#include "io/image_merge.h"
#include "base/util.h"

struct merge {
    const struct thread_results *t;
    struct image *img;
};

static void add_threads(void *p)
{
    struct merge *m = p;
    const struct thread_results *t = m->t;
    for (int i = 0; i < t->threads; i++) { /* fixed order: reproducible sums */
        img_accumulate(m->img, t->img[i], t->scale);
        if (t->add) t->add(t->ctx, i);
    }
}

void merge_thread_results(const struct thread_results *t, struct image *img_out)
{
    ASSERT(t->nextra >= 0 && t->nextra <= MERGE_MAX_EXTRA);
    struct merge m = {t, img_out};
    size_t px = (size_t)img_out->w * img_out->h;
    struct dist_buf bufs[1 + MERGE_MAX_EXTRA] = {{img_out->px, 3 * px * sizeof *img_out->px}};
    for (int i = 0; i < t->nextra; i++)
        bufs[1 + i] = t->extra[i];
    dist_chain(bufs, 1 + t->nextra, add_threads, &m);
}
