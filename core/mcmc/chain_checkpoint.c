/* A worker thread's MLT state (its chains, generator, counts, statistics and images) in and out of a
 * checkpoint payload; see chain.h. */
#include "mcmc/chain.h"
#include "mcmc/mutation.h"
#include "path/path_checkpoint.h"
#include <string.h>

static void put_chain(struct ckpt_buf *b, const struct scene *sc, const struct chain *c)
{
    CKPT_PUT(b, c->pss);
    CKPT_PUT(b, c->cur);
    CKPT_PUT(b, c->f);
    CKPT_PUT(b, c->k);
    CKPT_PUT(b, c->tech);
    CKPT_PUT(b, c->scale);
    CKPT_PUT(b, c->xsum);
    CKPT_PUT(b, c->pending);
    CKPT_PUT(b, c->xsum_valid);
    if (c->path) {
        CKPT_PUT(b, c->path->t);
        CKPT_PUT(b, c->path->s);
        ckpt_put_vertices(b, sc, c->path->cam, MAX_SUBPATH_VERTS);
        ckpt_put_vertices(b, sc, c->path->emi, MAX_SUBPATH_VERTS);
    }
    mutations_chain_save(b, sc, c); /* PITP's path, and the state of any mutation that has one */
}

/* The checksum vouches for the bytes, not for what they mean: every count that later indexes an
 * array is checked here, so that a crafted file is refused rather than written through. */
static bool chain_valid(const struct chain *c)
{
    const struct pss_sampler *p = &c->pss;
    const int dims = STREAM_COUNT * STREAM_DIMS;
    if (p->ntouched < 0 || p->ntouched > dims) return false;
    for (int i = 0; i < p->ntouched; i++)
        if (p->touched[i] >= dims) return false;
    if (c->cur.n < 0 || c->cur.n > MAX_SPLATS) return false;
    const struct ctrl_path *cp = c->path;
    /* the mutations' states check themselves as they load (PITP's path: pitp_step.c) */
    return !cp || (cp->t >= 0 && cp->t <= MAX_SUBPATH_VERTS && cp->s >= 0 && cp->s <= MAX_SUBPATH_VERTS);
}

static bool get_chain(struct ckpt_buf *b, const struct scene *sc, struct chain *c)
{
    /* the sampler's function table is this process's */
    const struct sampler_ops *ops = c->pss.base.ops;
    CKPT_GET(b, c->pss);
    c->pss.base.ops = ops;
    CKPT_GET(b, c->cur);
    CKPT_GET(b, c->f);
    CKPT_GET(b, c->k);
    CKPT_GET(b, c->tech);
    CKPT_GET(b, c->scale);
    CKPT_GET(b, c->xsum);
    CKPT_GET(b, c->pending);
    CKPT_GET(b, c->xsum_valid);
    if (c->path) {
        CKPT_GET(b, c->path->t);
        CKPT_GET(b, c->path->s);
        ckpt_get_vertices(b, sc, c->path->cam, MAX_SUBPATH_VERTS);
        ckpt_get_vertices(b, sc, c->path->emi, MAX_SUBPATH_VERTS);
    }
    if (!mutations_chain_load(b, sc, c)) return false;
    return !b->short_read && chain_valid(c);
}

void mlt_thread_save(struct ckpt_buf *b, const struct scene *sc, const struct mlt_thread *t)
{
    b->len = 0; /* the slot's previous state, its memory kept */
    CKPT_PUT(b, t->nk);
    for (int i = 0; i < t->nk; i++)
        put_chain(b, sc, &t->ch[i]);
    CKPT_PUT(b, *t->r);
    CKPT_PUT(b, *t->n);
    CKPT_PUT(b, *t->nonfinite);
    CKPT_PUT(b, *t->st);
    ckpt_put(b, t->ctrl_fail, 2 * sizeof *t->ctrl_fail);
    ckpt_put_image(b, t->img);
    for (int i = 0; t->len_img && i < t->nk; i++)
        ckpt_put_image(b, t->len_img[i]);
    if (t->angle) {
        size_t np = (size_t)t->angle->w * t->angle->h;
        ckpt_put(b, t->angle->sum, np * sizeof(double));
        ckpt_put(b, t->angle->count, np * sizeof(double));
        CKPT_PUT(b, t->angle->len);
        CKPT_PUT(b, t->angle->skipped);
    }
    if (t->tech) {
        const struct tech_acc *a = t->tech;
        for (int i = 1; i <= a->k + 1; i++) {
            ckpt_put_image(b, a->contrib[i]);
            ckpt_put(b, a->count[i], (size_t)a->w * a->h * sizeof(double));
        }
        CKPT_PUT(b, a->samples);
        CKPT_PUT(b, a->cur);
        CKPT_PUT(b, a->prop);
        CKPT_PUT(b, a->active);
    }
    ckpt_put(b, t->trace, (size_t)t->nk * sizeof *t->trace);
}

/* A mixing record's counts index its trace and step its thinning: checked as the chains' are. */
static bool trace_valid(const struct chain_trace *t)
{
    return t->len >= 0 && t->len < TRACE_CAP && t->stride >= 1 && t->countdown >= 1 && t->countdown <= t->stride &&
           t->n >= 0 && t->moved >= 0 && t->moved <= t->n && t->longest >= t->run && t->run >= 0 && t->k >= 0 &&
           t->k <= MAX_PATH_LENGTH;
}

bool mlt_thread_load(struct ckpt_buf *b, const struct scene *sc, const struct mlt_thread *t)
{
    int nk = 0;
    if (!CKPT_GET(b, nk) || nk != t->nk) return false;
    for (int i = 0; i < t->nk; i++)
        if (!get_chain(b, sc, &t->ch[i])) return false;
    CKPT_GET(b, *t->r);
    CKPT_GET(b, *t->n);
    CKPT_GET(b, *t->nonfinite);
    CKPT_GET(b, *t->st);
    ckpt_get(b, t->ctrl_fail, 2 * sizeof *t->ctrl_fail);
    ckpt_get_image(b, t->img);
    for (int i = 0; t->len_img && i < t->nk; i++)
        ckpt_get_image(b, t->len_img[i]);
    if (t->angle) {
        size_t np = (size_t)t->angle->w * t->angle->h;
        ckpt_get(b, t->angle->sum, np * sizeof(double));
        ckpt_get(b, t->angle->count, np * sizeof(double));
        CKPT_GET(b, t->angle->len);
        CKPT_GET(b, t->angle->skipped);
    }
    if (t->tech) {
        struct tech_acc *a = t->tech;
        for (int i = 1; i <= a->k + 1; i++) {
            ckpt_get_image(b, a->contrib[i]);
            ckpt_get(b, a->count[i], (size_t)a->w * a->h * sizeof(double));
        }
        CKPT_GET(b, a->samples);
        CKPT_GET(b, a->cur);
        CKPT_GET(b, a->prop);
        CKPT_GET(b, a->active);
    }
    ckpt_get(b, t->trace, (size_t)t->nk * sizeof *t->trace);
    for (int i = 0; i < t->nk; i++)
        if (!trace_valid(&t->trace[i])) return false;
    return !b->short_read;
}
