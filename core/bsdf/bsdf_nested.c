/* Block layout, probing and lobe choice shared by the nested BSDFs (bsdf_nested.h). */
#include "bsdf/bsdf_nested.h"
#include "bsdf/bsdf_smooth.h"

void nested_pad_next(struct sampler *s, int end)
{
    while (s->offset < end)
        sampler_next(s, DIM_CONTINUOUS);
}

void nested_pad_put(struct sampler *w, int end)
{
    while (w->offset < end)
        sampler_put(w, DIM_CONTINUOUS, sampler_fresh(w));
}

/* A block of numbers that an inverse writes and a forward sample then reads back; its fresh
 * numbers come from the caller's writer. */
struct probe_io {
    struct sampler base;
    struct nested_probe *p;
    struct sampler *src;
};

static double probe_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    const struct probe_io *io = (const struct probe_io *)s;
    return s->offset < io->p->n ? io->p->u[s->offset] : 0.5; /* never read: sample reads what invert put */
}

static void probe_put(struct sampler *s, enum dim_kind kind, double u)
{
    struct probe_io *io = (struct probe_io *)s;
    io->p->u[s->offset] = u;
    io->p->kind[s->offset] = kind;
    io->p->n = s->offset + 1;
}

static double probe_fresh(struct sampler *s) { return sampler_fresh(((struct probe_io *)s)->src); }

static const struct sampler_ops probe_ops = {probe_next, probe_put, probe_fresh};

void nested_probe(const struct bsdf_ctx *c, vec3 wi, vec3 wo, struct sampler *w, struct nested_probe *p)
{
    *p = (struct nested_probe){0};
    struct probe_io io = {{&probe_ops, 0, 0, 0}, p, w};
    if (!bsdf_invert(c, wi, wo, &io.base)) return;
    io.base.offset = 0;
    struct bsdf_sample bs;
    if (!bsdf_sample(c, wi, &io.base, TRANSPORT_RADIANCE, &bs)) return;
    if (bs.delta && !smooth_same_dir(bs.wo, wo)) return;
    p->ok = true;
    p->delta = bs.delta;
    p->p_delta = bs.delta ? bs.pdf : 0;
}

void nested_put(struct sampler *w, const struct nested_probe *p)
{
    for (int i = 0; i < p->n; i++)
        sampler_put(w, p->kind[i], p->u[i]);
}

int nested_pick(struct sampler *w, int n, const double *dw, const double *cw)
{
    double sd = 0, sc = 0;
    for (int i = 0; i < n; i++) {
        sd += dw[i];
        sc += cw[i];
    }
    const double *q = sd > 0 ? dw : cw;
    double total = sd > 0 ? sd : sc;
    if (!(total > 0)) return -1;
    double x = sampler_fresh(w) * total;
    int last = -1;
    for (int i = 0; i < n; i++) {
        if (!(q[i] > 0)) continue;
        last = i;
        if (x < q[i]) return i;
        x -= q[i];
    }
    return last; /* rounding left x just past the last weight */
}
