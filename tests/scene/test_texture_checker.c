/* Checker and constant textures (README, "Textures"): Tungsten's CheckerTexture cell rule at cell
 * centres, on cell edges and across u = 0, the loader's defaults, and that every texture user
 * (here the albedo, read through bsdf_ctx_at) gets them through texture_lookup. */
#include <criterion/criterion.h>

#include "base/rng.h"
#include "bsdf/bsdf.h"
#include "bsdf/bsdf_json.h"
#include "scene/scene.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <string.h>

static bool same3(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

static const rgb ON = {0.8, 0.75, 0.6}, OFF = {0.1, 0.12, 0.15};

/* Tungsten's rule as it computes it: uv scaled in float, converted to int (truncation toward
 * zero), `on` where x xor y is odd. */
static rgb tungsten_checker(double u, double v, int ru, int rv)
{
    int x = (int)((float)u * (float)ru), y = (int)((float)v * (float)rv);
    return ((x ^ y) & 1) ? ON : OFF;
}

Test(texture_checker, cell_centres_alternate)
{
    struct texture *t = texture_checker(ON, OFF, 8, 6);
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 6; j++) {
            double u = (i + 0.5) / 8, v = (j + 0.5) / 6;
            rgb c = texture_lookup(t, u, v);
            cr_assert(same3(c, ((i ^ j) & 1) ? ON : OFF), "cell (%d, %d)", i, j);
            cr_assert(same3(c, tungsten_checker(u, v, 8, 6)), "cell (%d, %d)", i, j);
        }
    /* cell (0, 0) is `off`; the next one along either axis is `on` */
    cr_assert(same3(texture_lookup(t, 0.01, 0.01), OFF));
    cr_assert(same3(texture_lookup(t, 0.2, 0.01), ON));
    cr_assert(same3(texture_lookup(t, 0.01, 0.2), ON));
    texture_free(t);
}

/* An edge belongs to the cell above it (truncation); just below the edge is the cell before. Edges at
 * multiples of 1/8 and 1/4 are exact in binary, so the products are exact integers. */
Test(texture_checker, edges_belong_to_the_upper_cell)
{
    struct texture *t = texture_checker(ON, OFF, 8, 4);
    for (int i = 1; i < 8; i++)
        for (int j = 0; j < 4; j++) {
            double u = i / 8.0, v = (j + 0.5) / 4, below = nextafter(u, 0);
            cr_assert(same3(texture_lookup(t, u, v), ((i ^ j) & 1) ? ON : OFF), "edge u = %d/8, row %d", i, j);
            cr_assert(same3(texture_lookup(t, below, v), (((i - 1) ^ j) & 1) ? ON : OFF), "below u = %d/8", i);
            cr_assert(same3(texture_lookup(t, u, v), tungsten_checker(u, v, 8, 4)));
        }
    for (int j = 1; j < 4; j++) {
        double v = j / 4.0;
        cr_assert(same3(texture_lookup(t, 0.06, v), (j & 1) ? ON : OFF), "edge v = %d/4", j);
        cr_assert(same3(texture_lookup(t, 0.06, nextafter(v, 0)), ((j - 1) & 1) ? ON : OFF));
    }
    /* u = 1 starts the next period: cell 8 */
    cr_assert(same3(texture_lookup(t, 1.0, 0.1), OFF));
    texture_free(t);
}

/* Truncation toward zero: the cells either side of u = 0 (and v = 0) share index 0, so the
 * pattern does not alternate there; further out it continues with two's-complement parity. */
Test(texture_checker, negative_coordinates_as_tungsten_truncates)
{
    struct texture *t = texture_checker(ON, OFF, 4, 4);
    cr_assert(same3(texture_lookup(t, -0.1, 0.1), texture_lookup(t, 0.1, 0.1)));
    cr_assert(same3(texture_lookup(t, 0.1, -0.1), texture_lookup(t, 0.1, 0.1)));
    cr_assert(same3(texture_lookup(t, -0.3, 0.1), ON));  /* x = -1 */
    cr_assert(same3(texture_lookup(t, -0.6, 0.1), OFF)); /* x = -2 */
    /* NaN and out-of-range products fall in cell 0 instead of an undefined conversion */
    cr_assert(same3(texture_lookup(t, NAN, 0.1), OFF));
    cr_assert(same3(texture_lookup(t, 1e300, 0.1), OFF));
    texture_free(t);
}

/* Random points, away from the edges by more than float rounding: the double computation here and
 * Tungsten's float one pick the same cell. */
Test(texture_checker, agrees_with_tungstens_float_rule)
{
    const int res[][2] = {{8, 6}, {3, 3}, {12, 6}, {20, 20}, {1, 7}};
    rng r;
    rng_seed(&r, 3, 0);
    long n = 0;
    for (int k = 0; k < 5; k++) {
        struct texture *t = texture_checker(ON, OFF, res[k][0], res[k][1]);
        for (int i = 0; i < 100000; i++) {
            double u = 3 * rng_uniform(&r) - 1, v = 3 * rng_uniform(&r) - 1;
            double fu = u * res[k][0], fv = v * res[k][1];
            if (fabs(fu - round(fu)) < 1e-5 || fabs(fv - round(fv)) < 1e-5) continue;
            n++;
            cr_assert(same3(texture_lookup(t, u, v), tungsten_checker(u, v, res[k][0], res[k][1])),
                      "res %dx%d at (%.17g, %.17g)", res[k][0], res[k][1], u, v);
        }
        texture_free(t);
    }
    cr_assert(n > 400000);
}

Test(texture_checker, constant_is_its_value_everywhere)
{
    struct texture *t = texture_constant(v3(0.25, 0.5, 1));
    cr_assert(same3(texture_lookup(t, 0.3, 0.7), v3(0.25, 0.5, 1)));
    cr_assert(same3(texture_lookup(t, -5, NAN), v3(0.25, 0.5, 1)));
    double d[2];
    texture_derivs(t, 0.3, 0.7, d);
    cr_assert(d[0] == 0 && d[1] == 0);
    texture_free(t);
}

static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "checker-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

static struct scene *load_bsdfs(const char *bsdfs)
{
    char json[4096], path[512], err[1024] = "";
    snprintf(json, sizeof json,
             "{\"bsdfs\": [%s], \"primitives\": [{\"type\": \"quad\", \"bsdf\": \"a\"}],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 60, \"resolution\": 16,\n"
             "   \"transform\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             bsdfs);
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(json, 1, strlen(json), f), strlen(json));
    fclose(f);
    struct scene *s = scene_load_model(path, err, sizeof err);
    cr_assert(s, "%s", err);
    bsdf_prepare_all(s->bsdfs, s->nbsdfs); /* needs_uv; scene_load does it for a rendered scene */
    return s;
}

/* The loader reads on_color, off_color (number or RGB), res_u, res_v, with CheckerTexture's defaults
 * 0.8, 0.2, 20 x 20; the albedo at a hit's uv comes out of bsdf_ctx_at. */
Test(texture_checker, loaded_as_albedo_and_read_through_the_bsdf_context, .init = mk_tmp, .fini = rm_tmp)
{
    struct scene *s = load_bsdfs(
        "{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"checker\", \"on_color\": [0.8, 0.75, 0.6],"
        " \"off_color\": 0.1, \"res_u\": 8, \"res_v\": 6}},"
        "{\"name\": \"d\", \"type\": \"rough_plastic\", \"albedo\": {\"type\": \"checker\"}},"
        "{\"name\": \"c\", \"type\": \"lambert\", \"albedo\": {\"type\": \"constant\", \"value\": [0.1, 0.2, 0.3]}}");
    const struct bsdf *a = &s->bsdfs[0], *d = &s->bsdfs[1], *c = &s->bsdfs[2];
    cr_assert(a->albedo_tex && a->albedo_tex->kind == TEX_CHECKER && a->needs_uv);
    cr_assert_eq(a->albedo_tex->res_u, 8);
    cr_assert_eq(a->albedo_tex->res_v, 6);
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 6; j++) {
            double uv[2] = {(i + 0.5) / 8, (j + 0.5) / 6};
            struct bsdf_ctx bc = bsdf_ctx_at(a, uv);
            cr_assert(same3(bc.albedo, ((i ^ j) & 1) ? v3(0.8, 0.75, 0.6) : v3s(0.1)), "cell (%d, %d)", i, j);
        }
    cr_assert(d->albedo_tex && d->albedo_tex->kind == TEX_CHECKER);
    cr_assert_eq(d->albedo_tex->res_u, 20);
    cr_assert_eq(d->albedo_tex->res_v, 20);
    double uv0[2] = {0.01, 0.01}, uv1[2] = {0.06, 0.01};
    cr_assert(same3(bsdf_ctx_at(d, uv0).albedo, v3s(0.2)));
    cr_assert(same3(bsdf_ctx_at(d, uv1).albedo, v3s(0.8)));
    cr_assert(c->albedo_tex && c->albedo_tex->kind == TEX_CONSTANT);
    cr_assert(same3(bsdf_ctx_at(c, uv1).albedo, v3(0.1, 0.2, 0.3)));
    scene_model_free(s);
}
