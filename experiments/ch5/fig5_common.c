/* Shared options, runs and outputs of the Figure 5.5 and 5.6 tools (see fig5_common.h). */
#include "ch5/fig5_common.h"
#include "base/parallel.h"
#include "base/util.h"
#include "camera/camera.h"
#include "common/csv_meta.h"
#include "common/die.h"
#include "common/opts.h"
#include "common/outdir.h"
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const char *const fig5_kind_name[3] = {"mmlt", "controlled", "root"};

void fig5_parse(int argc, char **argv, struct fig5_cfg *c, const char *about)
{
    int res[2];
    const struct opt opts[] = {OPTS_FIGURE(c->fig, "scenes/jewelry/scene.json", c->fig.out),
                               OPT_RESOLUTION(res, .lo = 8, .hi = INT_MAX, .expect = "WxH", .help = "image size",
                                              .def = "160x120", .paper = "320x240"),
                               {"--mpp", OPT_INT, OPT_DST(c->mpp), .arg = "N", .lo = 1, .hi = 1L << 30,
                                .help = "mutations per pixel", .def = "64", .paper = "1024"},
                               OPT_SEEDS(c->seeds, .help = "independent runs of each small-step kind, seeds S..S+N-1",
                                         .def = "4", .paper = "8"),
                               {0}};
    char usage[64];
    snprintf(usage, sizeof usage, "usage: %s [options]\n", c->prog);
    opts_parse(&(struct opts_spec){.prog = c->prog, .usage = usage, .about = about, .opts = opts, .fig = &c->fig}, argc,
               argv);
    c->width = res[0], c->height = res[1];
    c->seed_paths = c->fig.paper ? 1000000 : 100000;
    c->max_length = 8;
    outdir_require(c->prog, c->fig.out); /* before any work: a bad --out is one line and status 2 */
}

void fig5_meta_head(FILE *f, const struct fig5_cfg *c, const char *title)
{
    csv_meta_head(f, title, c->fig.scene, c->fig.scale);
    csv_meta(f, "resolution", "%dx%d", c->width, c->height);
    csv_meta(f, "mutations_per_pixel", "%ld", c->mpp);
}

void fig5_meta_runs(FILE *f, const struct fig5_cfg *c)
{
    csv_meta(f, "seeds", "%d from %llu", c->seeds, (unsigned long long)c->fig.seed);
    csv_meta(f, "threads", "%d", c->fig.threads);
}

struct scene *fig5_scene(const struct fig5_cfg *c)
{
    struct scene *sc = opts_figure_scene(&c->fig);
    camera_resize(&sc->cam, c->width, c->height);
    return sc;
}

void fig5_run(const struct scene *sc, const struct fig5_cfg *c, enum small_step kind, uint64_t seed, bool angle,
              struct mlt_result *r)
{
    struct mlt_opts o = {.method = MLT_MMLT,
                         .p_large = c->p_large,
                         .mutations = c->mpp * c->width * c->height,
                         .seed_paths = c->seed_paths,
                         .seed = seed,
                         .threads = c->fig.threads,
                         .max_length = c->max_length,
                         .progress = isatty(2),
                         .small_step = kind,
                         .angle_stats = angle};
    pss_opts_default(&o.pss, camera_film_width(&sc->cam), camera_film_height(&sc->cam));
    o.pss.kernel = KERNEL_GAUSSIAN;
    char err[1024];
    fprintf(stderr, "%s: %s small steps, seed %llu, %ld mutations\n", c->prog, fig5_kind_name[kind],
            (unsigned long long)seed, o.mutations);
    if (!mlt_render(sc, &o, r, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
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

void fig5_save_tables(const struct fig5_cfg *c, struct table_set *ts)
{
    char err[4200];
    if (!table_set_save(ts, c->prog, c->fig.out, err, sizeof err)) die(DIE_RUNTIME, c->prog, "%s", err);
}
