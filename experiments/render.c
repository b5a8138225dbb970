/* bin/render: renders a Tungsten scene with one method and writes PREFIX.exr and PREFIX.png. */
#include "cli.h"
#include "parallel.h"
#include "render.h"
#include "sampler.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static const char *usage =
    "usage: render SCENE.json [options]\n"
    "  --method pt|bdpt     estimator (default bdpt)\n"
    "  --spp N              samples per pixel (default: the scene's renderer.spp, else 16)\n"
    "  --seed S             random seed (default 1); same seed and threads -> same image\n"
    "  --threads T          worker threads (default: all cores)\n"
    "  --max-length K       maximum path length in segments (default: from integrator.max_bounces)\n"
    "  --out PREFIX         output prefix (default out); writes PREFIX.exr (linear) and PREFIX.png\n"
    "  --quiet              no progress bar\n"
    "Prints one summary line: method, samples, seconds, samples/s.\n";

int main(int argc, char **argv)
{
    const char *prog = "render", *scene_path = NULL, *out = "out";
    struct render_opts o = {.method = METHOD_BDPT, .spp = -1, .seed = 1, .threads = cpu_count(), .max_length = -1, .progress = true};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(usage, stdout);
            return 0;
        } else if (!strcmp(a, "--method")) {
            const char *v = cli_value(prog, argc, argv, &i);
            if (!method_parse(v, &o.method)) cli_fail(prog, "--method: expected pt or bdpt, got '%s'", v);
        } else if (!strcmp(a, "--spp")) {
            o.spp = (int)cli_long(prog, a, cli_value(prog, argc, argv, &i), 1, 1 << 24);
        } else if (!strcmp(a, "--seed")) {
            o.seed = cli_u64(prog, a, cli_value(prog, argc, argv, &i));
        } else if (!strcmp(a, "--threads")) {
            o.threads = (int)cli_long(prog, a, cli_value(prog, argc, argv, &i), 1, 1024);
        } else if (!strcmp(a, "--max-length")) {
            o.max_length = (int)cli_long(prog, a, cli_value(prog, argc, argv, &i), 1, MAX_PATH_LENGTH);
        } else if (!strcmp(a, "--out")) {
            out = cli_value(prog, argc, argv, &i);
        } else if (!strcmp(a, "--quiet")) {
            o.progress = false;
        } else if (a[0] == '-') {
            cli_fail(prog, "unknown option '%s' (see --help)", a);
        } else if (scene_path) {
            cli_fail(prog, "more than one scene given ('%s' and '%s')", scene_path, a);
        } else {
            scene_path = a;
        }
    }
    if (!scene_path) cli_fail(prog, "no scene given (see --help)");
    char err[1024];
    struct scene *sc = scene_load(scene_path, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (o.spp < 0) o.spp = sc->spp > 0 ? sc->spp : 16;
    if (o.max_length < 0) o.max_length = sc->max_length;
    if (o.progress) o.progress = isatty(2);
    struct render_stats st;
    struct image *img = render_mc(sc, &o, &st);
    char path[4096];
    int ok = 1;
    snprintf(path, sizeof path, "%s.exr", out);
    ok = ok && img_write_exr(img, 1.0, path, err, sizeof err);
    snprintf(path, sizeof path, "%s.png", out);
    ok = ok && img_write_png(img, 1.0, path, err, sizeof err);
    if (!ok) fprintf(stderr, "%s\n", err);
    else
        printf("%s: %ld samples in %.2f s, %.0f samples/s (%d threads), %ld non-finite dropped\n",
               method_name(o.method), st.samples, st.seconds, st.samples / st.seconds, o.threads, st.nonfinite);
    img_destroy(img);
    scene_free(sc);
    return ok ? 0 : 1;
}
