/* bin/fig4_6: thesis Figure 4.6. Equal-time renders of the ajar scene with only MMLT large steps,
 * only MCTLS, and the hybrid (MMLT large steps below --hybrid-length, MCTLS from it on), no small
 * steps; relative MSE against a BDPT reference rendered once and cached.
 * Writes OUT/{mmlt-large,mctls,hybrid}.{exr,png}, OUT/fig4.6.csv (method,seconds,mutations,relmse)
 * and OUT/reference.png; the side-by-side PNG and the table come from the Makefile's scripts. */
#include "base/parallel.h"
#include "base/util.h"
#include "common/csv_meta.h"
#include "common/opts.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* DIR/NAME.exr and DIR/NAME.png */
static bool write_pair(const struct image *im, const char *dir, const char *name, char *err, size_t n)
{
    char prefix[4096];
    snprintf(prefix, sizeof prefix, "%s/%s", dir, name);
    return img_write_exr_png(im, prefix, err, n);
}

static struct image *reference(const struct scene *sc, const char *path, int spp, int threads, char *err, size_t n)
{
    char msg[1024];
    struct image *ref = img_read(path, msg, sizeof msg);
    if (ref && ref->w == sc->cam.width && ref->h == sc->cam.height) {
        fprintf(stderr, "fig4.6: using cached reference %s\n", path);
        return ref;
    }
    img_destroy(ref);
    fprintf(stderr, "fig4.6: rendering the BDPT reference (%d spp) into %s\n", spp, path);
    struct render_opts o = {.method = METHOD_BDPT, .spp = spp, .seed = 12345, .threads = threads,
                            .max_length = sc->max_length, .progress = isatty(2)};
    struct render_stats st;
    ref = render_mc(sc, &o, &st);
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash) {
        *slash = 0;
        mkdir(dir, 0777);
    }
    if (!img_write_exr(ref, 1, path, err, n)) {
        img_destroy(ref);
        return NULL;
    }
    return ref;
}

int main(int argc, char **argv)
{
    const char *refpath = NULL;
    struct opts_figure fo;
    double seconds;
    int refspp, hybrid;
    const struct opt opts[] = {
        OPTS_FIGURE(fo, "scenes/ajar/scene.json", "results/fig4.6"),
        {"--seconds", OPT_DOUBLE, OPT_DST(seconds), .arg = "S", .lo = 0.01, .hi = 1e6, .help = "render time per method",
         .def = "20", .paper = "600"},
        OPTS_REFERENCE(refpath, refspp, "BDPT", "results/reference/ajar-bdpt-<spp>.exr", "256", "16384"),
        OPT_HYBRID_LENGTH(hybrid, .help = "hybrid: MCTLS from path length K on, MMLT large steps below", .def = "6"),
        {0}};
    opts_parse(&(struct opts_spec){.prog = "fig4_6", .usage = "usage: fig4_6 [options]\n", .opts = opts, .paper = &fo.paper},
               argc, argv);
    opts_require_image_output("fig4_6");
    char err[1024], defref[256];
    snprintf(defref, sizeof defref, "results/reference/ajar-bdpt-%d.exr", refspp);
    if (!refpath) refpath = defref;
    struct scene *sc = scene_load(fo.scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    mkdir(fo.out, 0777);
    struct image *ref = reference(sc, refpath, refspp, fo.threads, err, sizeof err);
    if (!ref || !write_pair(ref, fo.out, "reference", err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    csv_meta_head(f, "fig4.6: equal-time MMLT large steps vs MCTLS vs hybrid (p_large = 1, no small steps)", fo.scene, fo.scale);
    csv_meta(f, "seed", "%llu", (unsigned long long)fo.seed);
    csv_meta(f, "threads", "%d", fo.threads);
    csv_meta(f, "reference", "%s (%d spp BDPT)", refpath, refspp);
    csv_meta(f, "hybrid_length", "%d", hybrid);
    csv_meta(f, NULL, "relmse = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01)");
    fprintf(f, "method,seconds,mutations,relmse\n");
    const char *names[3] = {"mmlt-large", "mctls", "hybrid"};
    const enum large_step kinds[3] = {LARGE_MMLT, LARGE_MCTLS, LARGE_HYBRID};
    for (int m = 0; m < 3; m++) {
        struct mlt_opts o = {.method = MLT_MMLT, .p_large = 1, .seconds = seconds, .seed_paths = fo.paper ? 1000000 : 100000,
                             .seed = fo.seed, .threads = fo.threads, .max_length = sc->max_length, .progress = isatty(2),
                             .large_step = kinds[m], .hybrid_length = hybrid};
        pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
        fprintf(stderr, "fig4.6: %s for %.0f s\n", names[m], seconds);
        struct mlt_result r;
        if (!mlt_render(sc, &o, &r, err, sizeof err) || !write_pair(r.img, fo.out, names[m], err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        fprintf(f, "%s,%.2f,%ld,%.6g\n", names[m], r.seconds, r.mutations, img_relmse(r.img, ref, 0.01));
        mlt_result_free(&r);
    }
    fclose(f);
    char path[4096];
    snprintf(path, sizeof path, "%s/fig4.6.csv", fo.out);
    bool ok = write_text_atomic(path, buf, err, sizeof err);
    free(buf);
    img_destroy(ref);
    scene_free(sc);
    if (!ok) fprintf(stderr, "%s\n", err);
    return ok ? 0 : 1;
}
