/* bin/fig4_6: thesis Figure 4.6. Equal-time renders of the ajar scene with only MMLT large steps,
 * only MCTLS, and the hybrid (MMLT large steps below --hybrid-length, MCTLS from it on), no small
 * steps; relative MSE against a BDPT reference rendered once and cached.
 * Writes OUT/{mmlt-large,mctls,hybrid}.{exr,png}, OUT/fig4.6.csv (method,seconds,mutations,relmse)
 * and OUT/reference.png; the side-by-side PNG and the table come from the Makefile's scripts. */
#include "base/parallel.h"
#include "base/util.h"
#include "common/cli.h"
#include "mc/render.h"
#include "mcmc/mlt.h"
#include "path/scene_ready.h"
#include "version.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *usage =
    "usage: fig4_6 [options]\n"
    "  --scene FILE         (default scenes/ajar/scene.json)\n"
    "  --scale quick|paper  budgets (default: $SCALE, else quick)\n"
    "  --seconds S          render time per method (quick 20, paper 600)\n"
    "  --reference FILE     cached BDPT reference EXR (default results/reference/ajar-bdpt-<spp>.exr)\n"
    "  --reference-spp N    BDPT samples per pixel of the reference (quick 256, paper 16384)\n"
    "  --hybrid-length K    (default 6)\n"
    "  --seed S  --threads T  --out DIR (default results/fig4.6)\n";

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
    const char *prog = "fig4_6", *scene = "scenes/ajar/scene.json", *out = "results/fig4.6", *refpath = NULL;
    const char *scale = getenv("SCALE") && *getenv("SCALE") ? getenv("SCALE") : "quick";
    double seconds = -1;
    int refspp = -1, threads = cpu_count(), hybrid = 6;
    uint64_t seed = 1;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
#define VALUE cli_value(prog, argc, argv, &i)
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(o, "--scene")) scene = VALUE;
        else if (!strcmp(o, "--scale")) scale = VALUE;
        else if (!strcmp(o, "--seconds")) seconds = cli_double(prog, o, VALUE, 0.01, 1e6);
        else if (!strcmp(o, "--reference")) refpath = VALUE;
        else if (!strcmp(o, "--reference-spp")) refspp = (int)cli_long(prog, o, VALUE, 1, 1 << 24);
        else if (!strcmp(o, "--hybrid-length")) hybrid = (int)cli_long(prog, o, VALUE, 1, MAX_PATH_LENGTH);
        else if (!strcmp(o, "--seed")) seed = cli_u64(prog, o, VALUE);
        else if (!strcmp(o, "--threads")) threads = (int)cli_long(prog, o, VALUE, 1, 1024);
        else if (!strcmp(o, "--out")) out = VALUE;
        else cli_fail(prog, "unknown option '%s' (see --help)", o);
#undef VALUE
    }
    bool paper = !strcmp(scale, "paper");
    if (!paper && strcmp(scale, "quick")) cli_fail(prog, "--scale: expected quick or paper, got '%s'", scale);
    cli_require_image_output(prog);
    if (seconds < 0) seconds = paper ? 600 : 20;
    if (refspp < 0) refspp = paper ? 16384 : 256;
    char err[1024], defref[256];
    snprintf(defref, sizeof defref, "results/reference/ajar-bdpt-%d.exr", refspp);
    if (!refpath) refpath = defref;
    struct scene *sc = scene_load(scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    mkdir(out, 0777);
    struct image *ref = reference(sc, refpath, refspp, threads, err, sizeof err);
    if (!ref || !write_pair(ref, out, "reference", err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    fprintf(f, "# fig4.6: equal-time MMLT large steps vs MCTLS vs hybrid (p_large = 1, no small steps)\n");
    fprintf(f, "# scene %s\n# commit %s\n# scale %s\n# seed %llu\n# threads %d\n# reference %s (%d spp BDPT)\n", scene,
            GIT_COMMIT, scale, (unsigned long long)seed, threads, refpath, refspp);
    fprintf(f, "# hybrid_length %d\n# relmse = mean over pixels and channels of (I - R)^2 / (R^2 + 0.01)\n", hybrid);
    fprintf(f, "method,seconds,mutations,relmse\n");
    const char *names[3] = {"mmlt-large", "mctls", "hybrid"};
    const enum large_step kinds[3] = {LARGE_MMLT, LARGE_MCTLS, LARGE_HYBRID};
    for (int m = 0; m < 3; m++) {
        struct mlt_opts o = {.method = MLT_MMLT, .p_large = 1, .seconds = seconds, .seed_paths = paper ? 1000000 : 100000,
                             .seed = seed, .threads = threads, .max_length = sc->max_length, .progress = isatty(2),
                             .large_step = kinds[m], .hybrid_length = hybrid};
        pss_opts_default(&o.pss, sc->cam.width, sc->cam.height);
        fprintf(stderr, "fig4.6: %s for %.0f s\n", names[m], seconds);
        struct mlt_result r;
        if (!mlt_render(sc, &o, &r, err, sizeof err) || !write_pair(r.img, out, names[m], err, sizeof err)) {
            fprintf(stderr, "%s\n", err);
            return 1;
        }
        fprintf(f, "%s,%.2f,%ld,%.6g\n", names[m], r.seconds, r.mutations, img_relmse(r.img, ref, 0.01));
        mlt_result_free(&r);
    }
    fclose(f);
    char path[4096];
    snprintf(path, sizeof path, "%s/fig4.6.csv", out);
    bool ok = write_text_atomic(path, buf, err, sizeof err);
    free(buf);
    img_destroy(ref);
    scene_free(sc);
    if (!ok) fprintf(stderr, "%s\n", err);
    return ok ? 0 : 1;
}
