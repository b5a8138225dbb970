/* Shared pieces of the chapter-4 figure tools (ch4_common.h). */
#include "ch4/ch4_common.h"
#include "common/csv_meta.h"
#include "common/reference.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct image *ch4_reference(const struct scene *sc, enum method method, int spp, const char *path, int threads,
                            const char *prog, char *err, size_t errlen)
{
    struct reference_spec spec = {
        .path = path, .method = method, .spp = spp, .seed = 12345, .max_length = sc->max_length, .threads = threads};
    return reference_render_cached(prog, sc, &spec, err, errlen);
}

bool ch4_write_pair(const struct image *im, const char *dir, const char *name, char *err, size_t errlen)
{
    char prefix[4096];
    snprintf(prefix, sizeof prefix, "%s/%s", dir, name);
    return img_write_exr_png(im, prefix, err, errlen);
}

bool ch4_write_error_png(const double *e, int w, int h, double *range, const char *path, char *err, size_t errlen)
{
    size_t n = (size_t)w * h;
    double r = *range;
    if (!(r > 0)) {
        double s2 = 0;
        for (size_t i = 0; i < n; i++)
            s2 += e[i] * e[i];
        r = 3 * sqrt(s2 / n);
        if (!(r > 0)) r = 1;
        *range = r;
    }
    struct image *im = img_create(w, h);
    for (size_t i = 0; i < n; i++) {
        /* img_write_png applies the sRGB curve; pre-invert it so mid-grey means zero error */
        double g = fmin(1, fmax(0, 0.5 + e[i] / (2 * r)));
        double lin = g <= 0.04045 ? g / 12.92 : pow((g + 0.055) / 1.055, 2.4);
        im->px[3 * i] = im->px[3 * i + 1] = im->px[3 * i + 2] = lin;
    }
    bool ok = img_write_png(im, 1, path, err, errlen);
    img_destroy(im);
    return ok;
}

static double lum(const double *p) { return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]; }

double ch4_pixel_noise_var(const struct image *ref)
{
    double s = 0;
    long n = 0;
    for (int y = 0; y < ref->h; y++)
        for (int x = 0; x + 1 < ref->w; x++) {
            const double *p = ref->px + 3 * ((size_t)y * ref->w + x);
            double d = lum(p + 3) - lum(p);
            s += d * d;
            n++;
        }
    return n ? s / n / 2 : 0;
}

bool ch4_show_claims(char *md)
{
    if (md) fputs(md, stderr);
    free(md);
    return md != NULL;
}

void ch4_meta_runs(FILE *f, uint64_t seed, int seeds, int threads)
{
    csv_meta(f, "seeds", "%llu..%llu", (unsigned long long)seed, (unsigned long long)(seed + seeds - 1));
    csv_meta(f, "threads", "%d", threads);
}

void ch4_claim_extreme(struct claims *cl, const char *id, const char *source, const char *claim, const char *stat,
                       const char *const *names, const double *x, int n, const bool *have, int m, int sign, int seeds)
{
    double mean[CH4_MAX_METHODS] = {0}, se[CH4_MAX_METHODS] = {0}, z[CH4_MAX_METHODS];
    if (n > CH4_MAX_METHODS) n = CH4_MAX_METHODS;
    for (int i = 0; i < n; i++)
        mean_se(x + i * seeds, seeds, &mean[i], &se[i]);
    struct verdict v = verdict_extreme(mean, se, have, n, m, sign, seeds, z);
    char zs[512], md[1024];
    claims_versus(names, mean, se, z, n, zs, sizeof zs, md, sizeof md);
    claims_row(cl, id, source, claim, stat, names[m], mean[m], se[m], zs, md, &v);
}

void ch4_stat_row_of(struct ch4_stat_row *row, const double *x, int seeds)
{
    row->seeds = seeds;
    mean_se(x, seeds, &row->mean, &row->se);
}
