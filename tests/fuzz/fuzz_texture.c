/* Fuzz target: a texture file's way into the loader's texture and the environment map, after the
 * decoder: the size and channel checks (io/texels.h), the channel mapping, the non-finite check and
 * gamma decoding (texture_from_rgb), then what the renderer does with it first: lookups at awkward
 * (u, v) and the environment's sampling distribution. The input is fuzz.h's raw texel format;
 * OpenImageIO itself is not fuzzed here. */
#include "emitter/emitter_table.h"
#include "fuzz/fuzz.h"
#include "io/texels.h"
#include "scene/scene.h"
#include <math.h>
#include <stdlib.h>

static void use(const struct texture *t)
{
    static const double uv[][2] = {{0, 0},
                                   {0.5, 0.5},
                                   {1, 1},
                                   {-0.25, 7.75},
                                   {1e300, -1e300},
                                   {NAN, 0.5},
                                   {0.999999999999, 1e-17},
                                   {INFINITY, -INFINITY}};
    for (size_t i = 0; i < sizeof uv / sizeof uv[0]; i++) {
        rgb c = texture_lookup(t, uv[i][0], uv[i][1]);
        if (!vfinite(c)) __builtin_trap(); /* finite texels, convex weights */
    }
    struct scene sc = {.file = "fuzz.json", .bbox_min = v3s(0), .bbox_max = v3s(1)};
    struct prim pr = {.env_tex = (struct texture *)t, .env_to_local = mat4_identity()};
    struct emitter_table tab = {.env_slot = -1};
    char err[512] = "";
    double power = env_build(&tab, &sc, &pr, err, sizeof err, "primitives[0]");
    if (power < 0) {
        fuzz_check_message(err);
        return;
    }
    if (tab.env_map && tab.env_dist.total > 0)
        for (int i = 0; i < 16; i++) {
            double x, y, pdf;
            distrib2d_sample(&tab.env_dist, (i + 0.5) / 16, fmod(0.618034 * i, 1.0), &x, &y, &pdf);
            if (!(x >= 0 && x <= 1 && y >= 0 && y <= 1) || !(pdf >= 0) || !isfinite(pdf)) __builtin_trap();
        }
    env_free(&tab);
}

int fuzz_texture(const uint8_t *data, size_t size)
{
    int w, h, nc, bits;
    float *chan;
    char err[512] = "";
    if (!raw_texels_parse(data, size, "fuzz.tex", &w, &h, &nc, &bits, &chan, err, sizeof err)) {
        fuzz_check_message(err);
        return 0;
    }
    float *rgb = texels_to_rgb(w, h, nc, chan);
    free(chan);
    struct texture *t = texture_from_rgb("fuzz.tex", w, h, rgb, bits, err, sizeof err);
    if (!t) {
        fuzz_check_message(err);
        return 0;
    }
    use(t);
    texture_free(t);
    return 0;
}
