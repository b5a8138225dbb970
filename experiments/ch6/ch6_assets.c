/* bin/ch6_assets: writes the generated assets of scenes/living-room and scenes/staircase.
 *   sky EXR: a textured sky (blue gradient, value-noise clouds, dark ground) with a small, very bright
 *     sun (angular radius 1.5 degrees) at a given direction; equirectangular as core/emitter/envmap.c reads
 *     it (column = atan2(z, x) / 2pi + 0.5, row = theta / pi from +y).
 *   wood PNG: rough-plastic albedo texture, growth rings distorted by noise, streaks along u.
 * Deterministic (fixed hash noise, no RNG state), so rerunning reproduces the committed files. */
#include "common/opts.h"
#include "io/image.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static double hash2(int x, int y, int seed)
{
    unsigned h = (unsigned)x * 374761393u + (unsigned)y * 668265263u + (unsigned)seed * 2246822519u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return ((h ^ (h >> 16)) & 0xffffff) / (double)0x1000000;
}

/* Smooth value noise, periodic in x with period px cells. */
static double vnoise(double x, double y, int px, int seed)
{
    int x0 = (int)floor(x), y0 = (int)floor(y);
    double fx = x - x0, fy = y - y0;
    fx = fx * fx * (3 - 2 * fx);
    fy = fy * fy * (3 - 2 * fy);
    int xa = ((x0 % px) + px) % px, xb = (xa + 1) % px;
    double a = hash2(xa, y0, seed), b = hash2(xb, y0, seed), c = hash2(xa, y0 + 1, seed), d = hash2(xb, y0 + 1, seed);
    return (a * (1 - fx) + b * fx) * (1 - fy) + (c * (1 - fx) + d * fx) * fy;
}

static double fbm(double x, double y, int px, int seed, int oct)
{
    double s = 0, amp = 0.5;
    for (int o = 0; o < oct; o++, x *= 2, y *= 2, px *= 2, amp *= 0.5)
        s += amp * vnoise(x, y, px, seed + o);
    return s;
}

static struct image *sky(int w, int h, vec3 sun)
{
    struct image *im = img_create(w, h);
    double sl = sqrt(sun.x * sun.x + sun.y * sun.y + sun.z * sun.z);
    double cos_r = cos(1.5 * M_PI / 180);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double theta = M_PI * (y + 0.5) / h, phi = 2 * M_PI * ((x + 0.5) / w - 0.5);
            vec3 d = {sin(theta) * cos(phi), cos(theta), sin(theta) * sin(phi)};
            double el = d.y;
            rgb c;
            if (el < 0) {
                double g = 0.12 + 0.05 * fbm(8.0 * x / w, 8.0 * y / h, 8, 7, 3);
                c = (rgb){g * 1.1, g, g * 0.8};
            } else {
                double t = pow(1 - el, 3);
                rgb zen = {0.25, 0.45, 1.0}, hor = {0.9, 0.95, 1.1};
                c = (rgb){zen.x + (hor.x - zen.x) * t, zen.y + (hor.y - zen.y) * t, zen.z + (hor.z - zen.z) * t};
                double cl = fbm(16.0 * x / w, 16.0 * y / h, 16, 3, 4);
                cl = cl > 0.5 ? fmin(1, (cl - 0.5) * 3) : 0;
                c = (rgb){c.x + (1.6 - c.x) * cl, c.y + (1.6 - c.y) * cl, c.z + (1.6 - c.z) * cl};
            }
            double cs = (d.x * sun.x + d.y * sun.y + d.z * sun.z) / sl;
            if (cs > cos_r)
                c = (rgb){6000, 5400, 4600};
            else if (cs > cos(6 * M_PI / 180)) { /* a faint halo */
                double k = 4 * (cs - cos(6 * M_PI / 180)) / (1 - cos(6 * M_PI / 180));
                c = (rgb){c.x + 3 * k, c.y + 2.7 * k, c.z + 2.2 * k};
            }
            img_add(im, x, y, c);
        }
    return im;
}

static struct image *wood(int w, int h)
{
    struct image *im = img_create(w, h);
    rgb dark = {0.22, 0.11, 0.05}, light = {0.55, 0.34, 0.17};
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            double u = (x + 0.5) / w, v = (y + 0.5) / h;
            /* rings: distance from an axis along u, bent by noise; streaks: fine noise stretched along u */
            double r = 9 * v + 1.5 * fbm(4 * u, 4 * v, 4, 11, 3);
            double ring = 0.5 + 0.5 * cos(2 * M_PI * r);
            ring = pow(ring, 3);
            double streak = fbm(2 * u, 48 * v, 2, 23, 3);
            double t = fmin(1, fmax(0, 0.25 + 0.6 * ring + 0.4 * (streak - 0.5)));
            rgb c = {light.x + (dark.x - light.x) * t, light.y + (dark.y - light.y) * t,
                     light.z + (dark.z - light.z) * t};
            img_add(im, x, y, c);
        }
    return im;
}

/* --sun X,Y,Z: a direction, not all zero */
static bool parse_sun(const char *v, void *dst, char *why, size_t n)
{
    vec3 *sun = dst;
    if (sscanf(v, "%lf,%lf,%lf", &sun->x, &sun->y, &sun->z) == 3 &&
        sun->x * sun->x + sun->y * sun->y + sun->z * sun->z > 0)
        return true;
    snprintf(why, n, "expected X,Y,Z (not all zero), got '%s'", v);
    return false;
}

int main(int argc, char **argv)
{
    const char *prog = "ch6_assets", *skyp = NULL, *woodp = NULL;
    int size[2] = {0, 0};
    vec3 sun = {0, 0, 0}; /* stays 0 unless --sun is given */
    const struct opt opts[] = {
        {"--sky", OPT_STRING, OPT_DST(skyp), .arg = "FILE",
         .help = "equirectangular HDR sky with a sun toward direction X,Y,Z (y up)"},
        {"--sun", OPT_CALL, .dst = &sun, .call = parse_sun, .arg = "X,Y,Z",
         .help = "the sun's direction (needed by --sky)"},
        {"--wood", OPT_STRING, OPT_DST(woodp), .arg = "FILE", .help = "wood albedo texture (8-bit PNG, sRGB)"},
        {"--size", OPT_WXH, OPT_DST(size), .arg = "WxH", .lo = 8, .hi = 8192, .lo2 = 4, .hi2 = 8192,
         .expect = "WxH between 8x4 and 8192x8192", .help = "(sky default 256x128, wood default 128x128)"},
        {0}};
    opts_parse(
        &(struct opts_spec){
            .prog = prog,
            .usage = "usage: ch6_assets --sky FILE.exr --sun X,Y,Z [--size WxH] | --wood FILE.png [--size WxH]\n",
            .opts = opts},
        argc, argv);
    bool have_sun = sun.x || sun.y || sun.z;
    int w = size[0], h = size[1];
    if (!skyp == !woodp) opts_fail(prog, "give exactly one of --sky or --wood (see --help)");
    if (skyp && !have_sun) opts_fail(prog, "--sky needs --sun X,Y,Z");
    char err[1024];
    bool ok;
    if (skyp) {
        struct image *im = sky(w ? w : 256, h ? h : 128, sun);
        ok = img_write_exr(im, 1, skyp, err, sizeof err);
        img_destroy(im);
    } else {
        struct image *im = wood(w ? w : 128, h ? h : 128);
        ok = img_write_png(im, 1, woodp, err, sizeof err);
        img_destroy(im);
    }
    if (!ok) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    return 0;
}
