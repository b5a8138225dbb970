/* Lazy primary-sample-space mutations with exact restore (see pss.h). */
#include "sampler/pss.h"
#include <math.h>
#include <string.h>

void pss_opts_default(struct pss_opts *o, int width, int height)
{
    *o = (struct pss_opts){KERNEL_KELEMEN, 1.0 / 1024, 1.0 / 64, 1.0 / 64, false, false, false, width, height, 1024};
}

/* Back onto [0, 1); steps shorter than 1 (every Kelemen step) need no floor. */
static double wrap(double u)
{
    if (u < 0)
        u += 1;
    else if (u >= 1)
        u -= 1;
    if (!(u >= 0 && u < 1)) u -= floor(u); /* long Gaussian steps */
    return u >= 1.0 ? 0.0 : u;
}

/* Box-Muller; one normal per call keeps the stream layout simple. Out of line, so that the Kelemen
 * path, which every small step reads, does not carry its spills (MMLT on the Cornell box: 3972 ->
 * 3957 instructions per iteration). */
__attribute__((noinline)) static double gaussian_step(struct pss_sampler *p)
{
    double a = rng_uniform(&p->r), b = rng_uniform(&p->r);
    return p->o.sigma * sqrt(-2.0 * log1p(-a)) * cos(2 * M_PI * b);
}

double pss_small_step(struct pss_sampler *p, enum dim_kind kind, double u)
{
    if (p->o.cdc && kind == DIM_DISCRETE) return u;
    double scale = kind == DIM_IMAGE_X ? p->scale_x : kind == DIM_IMAGE_Y ? p->scale_y : 1.0;
    double step;
    if (p->o.kernel == KERNEL_KELEMEN) {
        /* Kelemen et al. 2002: |step| = s2 exp(-log(s2/s1) xi) with a random sign. One 32-bit draw
         * gives the sign (1 bit) and xi: a coarse cell (8 bits), a fine cell (8 bits) and the
         * position m in the fine cell (15 bits). The two cells are table products; the rest,
         * exp(y) for |y| < log(s2/s1) / 2^16, is 1 + y (relative error < 1e-9 for the default
         * s2/s1 = 16, < 3e-8 up to s2/s1 = 1e6). The dependency chain is kept short and free of
         * branches because path code waits on every number it reads. */
        uint32_t x = rng_u32(&p->r);
        double a = p->kelemen[(x >> 23) & 255u] * p->kelemen_fine[(x >> 15) & 255u];
        step = a + a * (p->kelemen_slope * (double)(x & 0x7FFFu));
        uint64_t bits;
        memcpy(&bits, &step, sizeof bits);
        bits ^= (uint64_t)(x >> 31) << 63; /* the sign, without a branch to mispredict */
        memcpy(&step, &bits, sizeof bits);
    } else {
        step = gaussian_step(p);
    }
    return wrap(u + step * scale);
}

static double pss_next(struct sampler *s, enum dim_kind kind);
static const struct sampler_ops pss_ops = {pss_next, NULL, NULL};

void pss_init(struct pss_sampler *p, const struct pss_opts *o, uint64_t seed, uint64_t stream)
{
    memset(p, 0, sizeof *p);
    p->base.ops = &pss_ops;
    p->o = *o;
    rng_seed(&p->r, seed, stream);
    double log_ratio = log(o->s2 / o->s1);
    /* xi = (j + (i + (m + 1/2) / 2^15) / 2^8) / 2^8; the half cell of m is folded into the fine table */
    for (int j = 0; j < 256; j++) {
        p->kelemen[j] = o->s2 * exp(-log_ratio * j / 256.0);
        p->kelemen_fine[j] = exp(-log_ratio * (j + 0.5 / 32768) / 65536.0);
    }
    p->kelemen_slope = -log_ratio / 2147483648.0;
    double m = fmin(o->width, o->height);
    p->scale_x = p->scale_y = 1.0;
    if (o->rap) {
        p->scale_x = m / o->width;
        p->scale_y = m / o->height;
        if (o->rap_resolution) {
            p->scale_x *= o->rap_reference / m;
            p->scale_y *= o->rap_reference / m;
        }
    }
    /* as after an accepted large step at iteration 1: every dim (modified = 0) is fresh */
    p->iteration = 1;
    p->last_large = 1;
    p->large = false;
}

void pss_begin(struct pss_sampler *p, bool large)
{
    p->iteration++;
    p->large = large;
    p->kept = false;
    p->ntouched = 0;
}

void pss_begin_kept(struct pss_sampler *p)
{
    p->stamp++;
    p->large = false;
    p->kept = true;
    p->ntouched = 0;
}

static void touch(struct pss_sampler *p, int stream, int idx)
{
    struct pss_dim *d = &p->d[stream][idx];
    d->saved = d->value;
    d->saved_modified = d->modified;
    d->stamp = p->stamp;
    p->touched[p->ntouched++] = (uint16_t)(stream * STREAM_DIMS + idx);
}

void pss_set(struct pss_sampler *p, int stream, int index, double u)
{
    struct pss_dim *d = &p->d[stream][index];
    /* saved once per proposal: in a kept one, a number the state read last has modified ==
     * iteration already */
    if (p->kept ? d->stamp != p->stamp : d->modified != p->iteration) touch(p, stream, index);
    d->value = u;
    d->modified = p->iteration;
}

void pss_replace(struct pss_sampler *p, int stream, int index, double u)
{
    struct pss_dim *d = &p->d[stream][index];
    d->value = u;
    d->modified = p->iteration;
}

void pss_forget(struct pss_sampler *p, int stream, int index) { p->d[stream][index].modified = 0; }

/* Outside a proposal (after accept or reject) reads describe the current state: a number never
 * read since the last accepted large step is fresh, any other catches up on the small steps of
 * the accepted iterations it was not read in (which an eager implementation would have applied). */
double pss_read(struct pss_sampler *p, int stream, int idx, enum dim_kind kind)
{
    struct pss_dim *d = &p->d[stream][idx];
    if (d->modified == p->iteration) return d->value; /* already brought up to date */
    touch(p, stream, idx);
    if (p->large || d->modified < p->last_large) {
        /* never read since the last large step (or this is one): a fresh number */
        d->value = rng_uniform(&p->r);
    } else {
        uint64_t n = p->iteration - d->modified;
        if (n > 16) n = 16;
        for (uint64_t i = 0; i < n; i++)
            d->value = pss_small_step(p, kind, d->value);
    }
    d->modified = p->iteration;
    return d->value;
}

static double pss_next(struct sampler *s, enum dim_kind kind)
{
    return pss_read((struct pss_sampler *)s, s->stream, sampler_index(s), kind);
}

void pss_accept(struct pss_sampler *p)
{
    /* Only an accepted large step makes the numbers it did not read stale (fresh when next read). */
    if (p->large) p->last_large = p->iteration;
    p->large = p->kept = false;
    p->ntouched = 0;
}

void pss_reject(struct pss_sampler *p)
{
    for (int i = 0; i < p->ntouched; i++) {
        int st = p->touched[i] / STREAM_DIMS, idx = p->touched[i] % STREAM_DIMS;
        struct pss_dim *d = &p->d[st][idx];
        d->value = d->saved;
        d->modified = d->saved_modified;
    }
    p->ntouched = 0;
    p->large = false;
    /* The rejected proposal did not happen: the next one reuses its iteration number, so lazy
     * catch-up counts only accepted iterations (a kept proposal took none). */
    if (!p->kept) p->iteration--;
    p->kept = false;
}

double pss_current(struct pss_sampler *p, int stream, int index)
{
    const struct pss_dim *d = &p->d[stream][index];
    if (d->modified == p->iteration || (d->modified >= p->last_large && d->modified > 0)) return d->value;
    double u = rng_uniform(&p->r);
    pss_set(p, stream, index, u);
    return u;
}

void pss_export(const struct pss_sampler *p, double (*u)[STREAM_DIMS])
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++)
            u[st][i] = p->d[st][i].modified ? p->d[st][i].value : NAN;
}

void pss_import(struct pss_sampler *p, const double (*u)[STREAM_DIMS])
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++) {
            struct pss_dim *d = &p->d[st][i];
            if (isnan(u[st][i])) {
                d->modified = 0;
            } else {
                d->value = u[st][i];
                d->modified = p->iteration;
            }
        }
}
