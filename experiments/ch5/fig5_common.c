/* Shared options, runs and outputs of the Figure 5.5 and 5.6 tools (see fig5_common.h). */
#include "ch5/fig5_common.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "common/cli.h"
#include "path/scene_ready.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

const char *const fig5_kind_name[3] = {"mmlt", "controlled", "root"};

void fig5_parse(int argc, char **argv, struct fig5_cfg *c, const char *usage, long mpp_quick, long mpp_paper,
                int seeds_quick, int seeds_paper)
{
    const char *prog = c->prog;
    c->scene = "scenes/jewelry/scene.json";
    c->scale = getenv("SCALE") && *getenv("SCALE") ? getenv("SCALE") : "quick";
    c->threads = cpu_count();
    c->seed = 1;
    c->mpp = c->seeds = c->width = -1;
    for (int i = 1; i < argc; i++) {
        const char *o = argv[i];
        if (!strcmp(o, "--help") || !strcmp(o, "-h")) {
            fputs(usage, stdout);
            exit(0);
        } else if (!strcmp(o, "--scene")) c->scene = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--scale")) c->scale = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--mpp")) c->mpp = cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, 1L << 30);
        else if (!strcmp(o, "--seeds")) c->seeds = (int)cli_long(prog, o, cli_value(prog, argc, argv, &i), 2, 1000);
        else if (!strcmp(o, "--seed")) c->seed = cli_u64(prog, o, cli_value(prog, argc, argv, &i));
        else if (!strcmp(o, "--threads")) c->threads = (int)cli_long(prog, o, cli_value(prog, argc, argv, &i), 1, 1024);
        else if (!strcmp(o, "--out")) c->out = cli_value(prog, argc, argv, &i);
        else if (!strcmp(o, "--resolution")) {
            const char *v = cli_value(prog, argc, argv, &i);
            if (sscanf(v, "%dx%d", &c->width, &c->height) != 2 || c->width < 8 || c->height < 8)
                cli_fail(prog, "--resolution: expected WxH, got '%s'", v);
        } else cli_fail(prog, "unknown option '%s' (see --help)", o);
    }
    bool paper = !strcmp(c->scale, "paper");
    if (!paper && strcmp(c->scale, "quick")) cli_fail(prog, "--scale: expected quick or paper, got '%s'", c->scale);
    if (c->mpp < 0) c->mpp = paper ? mpp_paper : mpp_quick;
    if (c->seeds < 0) c->seeds = paper ? seeds_paper : seeds_quick;
    if (c->width < 0) {
        c->width = paper ? 320 : 160;
        c->height = paper ? 240 : 120;
    }
    c->seed_paths = paper ? 1000000 : 100000;
    c->max_length = 8;
    mkdir(c->out, 0777);
}

struct scene *fig5_scene(const struct fig5_cfg *c)
{
    char err[1024];
    struct scene *sc = scene_load(c->scene, err, sizeof err);
    if (!sc) {
        fprintf(stderr, "%s\n", err);
        exit(2);
    }
    camera_resize(&sc->cam, c->width, c->height);
    return sc;
}

void fig5_run(const struct scene *sc, const struct fig5_cfg *c, enum small_step kind, uint64_t seed, bool angle,
              struct mlt_result *r)
{
    struct mlt_opts o = {.method = MLT_MMLT, .p_large = c->p_large, .mutations = c->mpp * c->width * c->height,
                         .seed_paths = c->seed_paths, .seed = seed, .threads = c->threads, .max_length = c->max_length,
                         .progress = isatty(2), .small_step = kind, .angle_stats = angle};
    pss_opts_default(&o.pss, camera_film_width(&sc->cam), camera_film_height(&sc->cam));
    o.pss.kernel = KERNEL_GAUSSIAN;
    char err[1024];
    fprintf(stderr, "%s: %s small steps, seed %llu, %ld mutations\n", c->prog, fig5_kind_name[kind],
            (unsigned long long)seed, o.mutations);
    if (!mlt_render(sc, &o, r, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        exit(1);
    }
}

bool fig5_write_linear_png(const struct image *im, double white, const char *path, char *err, size_t errlen)
{
    struct image *g = img_create(im->w, im->h);
    for (int y = 0; y < im->h; y++)
        for (int x = 0; x < im->w; x++) {
            double v = fmin(fmax(img_get(im, x, y).x / white, 0), 1);
            /* the PNG writer applies the sRGB curve: undo it so that the stored grey is linear in v */
            double lin = v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
            img_add(g, x, y, v3s(lin));
        }
    bool ok = img_write_png(g, 1.0, path, err, errlen);
    img_destroy(g);
    return ok;
}

void fig5_write_text(const struct fig5_cfg *c, const char *name, const char *text)
{
    char path[4096], err[1024];
    snprintf(path, sizeof path, "%s/%s", c->out, name);
    if (!write_text_atomic(path, text, err, sizeof err)) {
        fprintf(stderr, "%s\n", err);
        exit(1);
    }
    fprintf(stderr, "%s: wrote %s\n", c->prog, path);
}
