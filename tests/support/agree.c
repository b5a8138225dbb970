#include "support/agree.h"
#include <criterion/criterion.h>
#include <gsl/gsl_cdf.h>
#include <string.h>

void stack_runs(struct stack *out, render_fn render, void *ctx, int reps, uint64_t seed0, int blk)
{
    static double sum[AGREE_MAX_BLOCKS], sum2[AGREE_MAX_BLOCKS];
    double tot[AGREE_MAX_REPS];
    cr_assert(reps >= 2 && reps <= AGREE_MAX_REPS);
    memset(sum, 0, sizeof sum);
    memset(sum2, 0, sizeof sum2);
    int W = 0, H = 0;
    for (int r = 0; r < reps; r++) {
        struct image *im = render(ctx, seed0 + (uint64_t)r);
        W = im->w / blk;
        H = im->h / blk;
        cr_assert(W * H <= AGREE_MAX_BLOCKS);
        tot[r] = img_mean_luminance(im);
        for (int by = 0; by < H; by++)
            for (int bx = 0; bx < W; bx++) {
                double a = 0;
                for (int y = 0; y < blk; y++)
                    for (int x = 0; x < blk; x++)
                        a += luminance(img_get(im, bx * blk + x, by * blk + y));
                a /= blk * blk;
                sum[by * W + bx] += a;
                sum2[by * W + bx] += a * a;
            }
        img_destroy(im);
    }
    out->w = W;
    out->h = H;
    out->reps = reps;
    for (int i = 0; i < W * H; i++) {
        out->m[i] = sum[i] / reps;
        out->v[i] = fmax(0, (sum2[i] - reps * out->m[i] * out->m[i]) / (reps - 1)) / reps;
    }
    double mm = 0, vv = 0;
    for (int r = 0; r < reps; r++)
        mm += tot[r];
    mm /= reps;
    for (int r = 0; r < reps; r++)
        vv += sqr(tot[r] - mm);
    out->mean = mm;
    out->mean_se = sqrt(vv / (reps - 1) / reps);
}

/* Welch-Satterthwaite degrees of freedom for two variances of means with n1, n2 replicates. */
static double welch_dof(double v1, int n1, double v2, int n2)
{
    double d = sqr(v1) / (n1 - 1) + sqr(v2) / (n2 - 1);
    return d > 0 ? sqr(v1 + v2) / d : n1 + n2 - 2;
}

static double welch_p(double m1, double v1, int n1, double m2, double v2, int n2)
{
    double se2 = v1 + v2;
    if (se2 == 0) return m1 == m2 ? 1 : 0;
    double t = fabs(m1 - m2) / sqrt(se2);
    return 2 * gsl_cdf_tdist_Q(t, welch_dof(v1, n1, v2, n2));
}

int stack_compare(const struct stack *a, const struct stack *b, int families, double *pmean, double *worst)
{
    int n = a->w * a->h, fails = 0;
    double alpha = 1 - pow(0.99, 1.0 / ((n + 1) * families));
    *worst = 1;
    for (int i = 0; i < n; i++) {
        double p = welch_p(a->m[i], a->v[i], a->reps, b->m[i], b->v[i], b->reps);
        if (p < *worst) *worst = p;
        if (p < alpha) fails++;
    }
    *pmean = welch_p(a->mean, sqr(a->mean_se), a->reps, b->mean, sqr(b->mean_se), b->reps);
    if (*pmean < alpha) fails++;
    return fails;
}

void mlt_render_ok(const struct scene *sc, const struct mlt_opts *o, struct mlt_result *r)
{
    char err[256];
    cr_assert(mlt_render(sc, o, r, err, sizeof err), "%s", err);
}

struct image *render_mlt(void *p, uint64_t seed)
{
    struct mlt_ctx *c = p;
    struct mlt_opts o = c->o;
    o.seed = seed;
    struct mlt_result r;
    mlt_render_ok(c->sc, &o, &r);
    cr_assert_eq(r.nonfinite, 0);
    return r.img;
}
