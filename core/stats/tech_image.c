/* Per-technique contribution and sample-count images of one path length, and how closely the counts
 * follow the contributions (MMLT paper §5, Fig. 5; see tech_image.h). */
#include "stats/tech_image.h"
#include "base/util.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void tech_acc_init(struct tech_acc *a, int k, int w, int h, bool tent)
{
    memset(a, 0, sizeof *a);
    a->k = k;
    a->w = w;
    a->h = h;
    for (int t = 1; t <= k + 1; t++) {
        a->contrib[t] = img_create(w, h);
        a->contrib[t]->tent = tent;
        a->count[t] = xcalloc((size_t)w * h, sizeof(double));
    }
}

void tech_acc_free(struct tech_acc *a)
{
    for (int t = 1; t <= a->k + 1; t++) {
        img_destroy(a->contrib[t]);
        free(a->count[t]);
        a->contrib[t] = NULL;
        a->count[t] = NULL;
    }
}

struct tech_acc *tech_acc_alloc(int threads, int k, int w, int h, bool tent)
{
    struct tech_acc *a = xcalloc((size_t)threads, sizeof *a);
    for (int i = 0; i < threads; i++)
        tech_acc_init(&a[i], k, w, h, tent);
    return a;
}

struct tech_acc *tech_acc_reduce(struct tech_acc *pt, int threads, double scale)
{
    struct tech_acc *r = xmalloc(sizeof *r);
    tech_acc_init(r, pt[0].k, pt[0].w, pt[0].h, pt[0].contrib[1]->tent);
    size_t n = (size_t)r->w * r->h;
    for (int i = 0; i < threads; i++) { /* fixed order: reproducible sums */
        for (int t = 1; t <= r->k + 1; t++) {
            img_accumulate(r->contrib[t], pt[i].contrib[t], scale);
            for (size_t p = 0; p < n; p++)
                r->count[t][p] += pt[i].count[t][p];
        }
        r->samples += pt[i].samples;
        tech_acc_free(&pt[i]);
    }
    free(pt);
    return r;
}

void tech_acc_destroy(struct tech_acc *a)
{
    if (!a) return;
    tech_acc_free(a);
    free(a);
}

void tech_acc_eval(struct tech_acc *a, int chain_k, const struct tech_split *sp, bool start)
{
    a->active = tech_acc_tracks(a, chain_k);
    if (a->active) *(start ? &a->cur : &a->prop) = *sp;
}

static void splat_split(struct tech_acc *a, const struct tech_split *sp, double wgt)
{
    for (int t = 1; t <= a->k + 1; t++)
        if (sp->on[t]) {
            /* the state's own splat with this weight was counted if non-finite: refuse, not count */
            rgb v = vscale(sp->s[t].c, wgt);
            if (vfinite(v)) img_splat(a->contrib[t], sp->s[t].px, sp->s[t].py, v);
        }
}

void tech_acc_step(struct tech_acc *a, double acc_prob, bool accepted, double f, double f_cur, double scale)
{
    if (!a->active) return;
    /* the same weights as the driver's splats of the whole state */
    if (f > 0) splat_split(a, &a->prop, acc_prob * scale / f);
    if (f_cur > 0) splat_split(a, &a->cur, (1 - acc_prob) * scale / f_cur);
    if (accepted) a->cur = a->prop;
    a->samples++;
    for (int t = 1; t <= a->k + 1; t++) {
        const struct splat *s = &a->cur.s[t];
        if (!a->cur.on[t] || !(s->px >= 0 && s->py >= 0 && s->px < a->w && s->py < a->h)) continue;
        a->count[t][(size_t)s->py * a->w + (size_t)s->px] += 1;
    }
}

/* Per (block, technique): the samples and the contribution's luminance. */
static void block_sums(const struct tech_acc *a, int t, int bx, int by, int blk, double *n, double *c)
{
    *n = *c = 0;
    for (int y = by * blk; y < (by + 1) * blk && y < a->h; y++)
        for (int x = bx * blk; x < (bx + 1) * blk && x < a->w; x++) {
            *n += a->count[t][(size_t)y * a->w + x];
            *c += luminance(img_get(a->contrib[t], x, y));
        }
}

void tech_follow(const struct tech_acc *a, int blk, struct tech_follow *o)
{
    memset(o, 0, sizeof *o);
    int nt = a->k + 1, bw = (a->w + blk - 1) / blk, bh = (a->h + blk - 1) / blk;
    double ns = 0, cs = 0, *n = o->samples, *c = o->contrib;
    for (int t = 1; t <= nt; t++) {
        for (size_t p = 0; p < (size_t)a->w * a->h; p++) {
            n[t] += a->count[t][p];
            c[t] +=
                luminance((rgb){a->contrib[t]->px[3 * p], a->contrib[t]->px[3 * p + 1], a->contrib[t]->px[3 * p + 2]});
        }
        ns += n[t];
        cs += c[t];
    }
    for (int t = 1; t <= nt; t++) {
        o->sample_share[t] = ns > 0 ? n[t] / ns : NAN;
        o->contrib_share[t] = cs > 0 ? c[t] / cs : NAN;
        o->tv += 0.5 * fabs(o->sample_share[t] - o->contrib_share[t]);
    }
    /* Pearson r over (block, technique) of the within-block shares */
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    long m = 0;
    for (int by = 0; by < bh; by++)
        for (int bx = 0; bx < bw; bx++) {
            double bn[TECH_MAX], bc[TECH_MAX], tn = 0, tc = 0;
            for (int t = 1; t <= nt; t++) {
                block_sums(a, t, bx, by, blk, &bn[t], &bc[t]);
                tn += bn[t];
                tc += bc[t];
            }
            if (!(tn > 0 && tc > 0)) continue;
            for (int t = 1; t <= nt; t++) {
                double x = bn[t] / tn, y = bc[t] / tc;
                sx += x;
                sy += y;
                sxx += x * x;
                syy += y * y;
                sxy += x * y;
                m++;
            }
        }
    double vx = m * sxx - sx * sx, vy = m * syy - sy * sy;
    o->r = m > 1 && vx > 0 && vy > 0 ? (m * sxy - sx * sy) / sqrt(vx * vy) : NAN;
    o->cells = (int)m;
}

void tech_acc_write_csv(FILE *f, const struct tech_acc *a, int blk)
{
    struct tech_follow fo;
    tech_follow(a, blk, &fo);
    fprintf(f, "# length %d\n# chain_samples %ld\n# block %d\n# tv %.6g\n# r %.6g\n# r_cells %d\n", a->k, a->samples,
            blk, fo.tv, fo.r, fo.cells);
    fprintf(f, "technique,s,t,samples,sample_share,contribution,contribution_share\n");
    for (int t = 1; t <= a->k + 1; t++)
        fprintf(f, "%d,%d,%d,%.0f,%.6g,%.9g,%.6g\n", t, a->k + 1 - t, t, fo.samples[t], fo.sample_share[t],
                fo.contrib[t], fo.contrib_share[t]);
}

bool tech_acc_write(const struct tech_acc *a, const char *prefix, const char *header, char *err, size_t errlen)
{
    char path[4200];
    size_t n = (size_t)a->w * a->h;
    struct image *sum = img_create(a->w, a->h), *cnt = img_create(a->w, a->h);
    double mcount = 0, lum = 0;
    for (int t = 1; t <= a->k + 1; t++) {
        img_accumulate(sum, a->contrib[t], 1.0);
        for (size_t p = 0; p < n; p++)
            mcount += a->count[t][p];
    }
    for (size_t p = 0; p < n; p++)
        lum += luminance((rgb){sum->px[3 * p], sum->px[3 * p + 1], sum->px[3 * p + 2]});
    lum /= (double)n;
    mcount /= (double)n;
    bool ok = true;
    for (int t = 1; t <= a->k + 1 && ok; t++) {
        for (size_t p = 0; p < n; p++)
            cnt->px[3 * p] = cnt->px[3 * p + 1] = cnt->px[3 * p + 2] = a->count[t][p];
        snprintf(path, sizeof path, "%.4000s.tech-t%d.exr", prefix, t);
        ok = img_write_exr(a->contrib[t], 1.0, path, err, errlen);
        snprintf(path, sizeof path, "%.4000s.tech-t%d.png", prefix, t);
        ok = ok && img_write_png(a->contrib[t], lum > 0 ? 0.5 / lum : 1.0, path, err, errlen);
        snprintf(path, sizeof path, "%.4000s.count-t%d.exr", prefix, t);
        ok = ok && img_write_exr(cnt, 1.0, path, err, errlen);
        snprintf(path, sizeof path, "%.4000s.count-t%d.png", prefix, t);
        ok = ok && img_write_png(cnt, mcount > 0 ? 0.5 / mcount : 1.0, path, err, errlen);
    }
    img_destroy(sum);
    img_destroy(cnt);
    if (!ok) return false;
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    fputs(header, f);
    tech_acc_write_csv(f, a, 8);
    fclose(f);
    snprintf(path, sizeof path, "%.4000s.tech.csv", prefix);
    ok = write_text_atomic(path, buf, err, errlen);
    free(buf);
    return ok;
}
