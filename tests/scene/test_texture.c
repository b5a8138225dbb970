/* Texture conventions (README, "Textures"): the 8-bit gamma table, which files it applies to,
 * bilinear lookup with wrap-around, and the uv of quads, cubes and spheres. */
#include <criterion/criterion.h>

#include "bsdf/bsdf_json.h"
#include "path/scene_ready.h"
#include "support/tmpdir.h"

#include "io/mesh_io.h"
#include "io/oiio.h"
#include "path/path.h"
#include "scene/accel.h"
#include "scene/scene.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static bool near3(vec3 a, vec3 b, double eps) { return vlen(vsub(a, b)) < eps; }

static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "texture-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

/* A scene in tmpdir with the given primitives (bsdf "t": lambert with albedo TEX) and a camera. */
static struct scene *tmp_scene(const char *tex, const char *prims, bool ready)
{
    char json[4096], path[512], err[1024] = "";
    snprintf(json, sizeof json,
             "{\"bsdfs\": [{\"name\": \"t\", \"type\": \"lambert\", \"albedo\": \"%s\"}],\n"
             " \"primitives\": [%s],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 60, \"resolution\": 16,\n"
             "   \"transform\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             tex, prims);
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(json, 1, strlen(json), f), strlen(json));
    fclose(f);
    struct scene *s = ready ? scene_load(path, err, sizeof err) : scene_load_model(path, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

/* Writes a w x h float RGB image (row 0 on top) into tmpdir; .png is quantised to 8 bits. */
static void write_image(const char *name, int w, int h, const float *px)
{
    char path[512], err[512] = "";
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    cr_assert(oiio_write(path, w, h, 3, px, err, sizeof err), "%s", err);
}

/* The model of a scene of the given primitives with a white 1 x 1 texture (geometry checks). */
static struct scene *white_scene(const char *prims)
{
    float px[3] = {1, 1, 1};
    write_image("w.exr", 1, 1, px);
    return tmp_scene("w.exr", prims, false);
}

/* floor(255 (c/255)^2.2), computed in long double here; the 2.2 power and sRGB differ at these codes
 * (sRGB would give 1.8, 3.3, 11.5, 147.3 of 255 at 20, 30, 60, 200). */
Test(texture, gamma_table_is_the_quantised_2_2_power)
{
    static const int expect[][2] = {{0, 0},   {10, 0},  {20, 0},   {21, 1},    {30, 2},    {40, 4},   {50, 7},
                                    {60, 10}, {64, 12}, {128, 55}, {200, 149}, {254, 252}, {255, 255}};
    for (size_t i = 0; i < sizeof expect / sizeof expect[0]; i++)
        cr_assert_eq(texture_gamma_decode(expect[i][0]), (float)(expect[i][1] / 255.0), "code %d: %g, expected %d/255",
                     expect[i][0], texture_gamma_decode(expect[i][0]) * 255, expect[i][1]);
    for (int c = 0; c < 256; c++) {
        long double x = floorl(255 * powl(c / 255.0L, 2.2L));
        cr_assert_eq(texture_gamma_decode(c), (float)(x / 255), "code %d", c);
        if (c) cr_assert_geq(texture_gamma_decode(c), texture_gamma_decode(c - 1));
    }
}

/* An 8-bit PNG is decoded through the table; the same values in an EXR (float) are not. */
Test(texture, gamma_applies_to_8_bit_files_only, .init = mk_tmp, .fini = rm_tmp)
{
    static const int codes[4][3] = {{128, 21, 255}, {60, 0, 20}, {30, 200, 1}, {254, 50, 40}};
    float px[12];
    for (int i = 0; i < 12; i++)
        px[i] = codes[i / 3][i % 3] / 255.0f;
    write_image("t.png", 2, 2, px);
    write_image("t.exr", 2, 2, px);
    char path[512], err[512] = "";
    snprintf(path, sizeof path, "%s/t.png", tmpdir);
    struct texture *png = texture_load(path, err, sizeof err);
    cr_assert(png, "%s", err);
    snprintf(path, sizeof path, "%s/t.exr", tmpdir);
    struct texture *exr = texture_load(path, err, sizeof err);
    cr_assert(exr, "%s", err);
    cr_assert_eq(png->bits, 8);
    cr_assert_eq(exr->bits, 0);
    for (int i = 0; i < 12; i++) {
        cr_assert_eq(png->rgb[i], texture_gamma_decode(codes[i / 3][i % 3]), "texel value %d", i);
        cr_assert_eq(exr->rgb[i], px[i], "texel value %d", i);
    }
    texture_free(png);
    texture_free(exr);
}

/* A 16-bit PNG keeps only the high byte of each value, then goes through the 8-bit table, as
 * Tungsten's PNG reader (lodepng to 8-bit RGBA) does. */
Test(texture, sixteen_bit_png_uses_the_high_byte)
{
    char err[512] = "";
    struct texture *t = texture_load("tests/data/texture/rgb16.png", err, sizeof err);
    cr_assert(t, "%s", err);
    cr_assert_eq(t->bits, 16);
    /* 0x80FF 0x1500 0xFFFF | 0x3C7F 0x0000 0x14FF / 0x1E00 0xC8C8 0x0100 | 0xFE00 0x3200 0x2800 */
    static const int high[12] = {0x80, 0x15, 0xFF, 0x3C, 0, 0x14, 0x1E, 0xC8, 0x01, 0xFE, 0x32, 0x28};
    for (int i = 0; i < 12; i++)
        cr_assert_eq(t->rgb[i], texture_gamma_decode(high[i]), "texel value %d: %g", i, t->rgb[i] * 255);
    texture_free(t);
}

/* 4 x 2 texture, texel value = 10 * row + column (row 0 on top), all channels alike but blue = 1. */
static float grid[4 * 2 * 3];
static struct texture grid_tex(void)
{
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 4; i++) {
            float *p = grid + 3 * (j * 4 + i);
            p[0] = p[1] = (float)(10 * j + i);
            p[2] = 1;
        }
    return (struct texture){.w = 4, .h = 2, .rgb = grid};
}
static double at(const struct texture *t, double u, double v)
{
    rgb c = texture_lookup(t, u, v);
    cr_assert(c.x == c.y && fabs(c.z - 1) < 1e-12, "(%g %g): (%g %g %g)", u, v, c.x, c.y, c.z);
    return c.x;
}

Test(texture, bilinear_at_centres_between_them_and_across_the_wrap)
{
    struct texture t = grid_tex();
    /* texel centres: column i at u = (i + 0.5)/4, row j (from the top) at v = 1 - (j + 0.5)/2 */
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 4; i++)
            cr_assert_float_eq(at(&t, (i + 0.5) / 4, 1 - (j + 0.5) / 2), 10 * j + i, 1e-12, "texel %d %d", i, j);
    cr_assert_float_eq(at(&t, 0.25, 0.75), 0.5, 1e-12);                 /* halfway between columns 0 and 1 */
    cr_assert_float_eq(at(&t, 0.125 + 0.25 * 0.25, 0.75), 0.25, 1e-12); /* a quarter of the way */
    cr_assert_float_eq(at(&t, 0.375, 0.5), 6, 1e-12);                   /* between rows 0 and 1: (1 + 11)/2 */
    /* edges wrap: u = 0 mixes columns 3 and 0, v = 0 mixes the bottom and top rows */
    cr_assert_float_eq(at(&t, 0, 0.75), 1.5, 1e-12);
    cr_assert_float_eq(at(&t, 1, 0.75), 1.5, 1e-12);
    cr_assert_float_eq(at(&t, 0.375, 0), 6, 1e-12);
    cr_assert_float_eq(at(&t, 0.375, 1), 6, 1e-12);
    cr_assert_float_eq(at(&t, 0.0625, 0.75), 0.75, 1e-12); /* 3/4 of column 0, 1/4 of column 3 */
    /* periodic in u and v, negative coordinates included */
    for (double u = -1.3; u < 1.3; u += 0.1)
        for (double v = -1.3; v < 1.3; v += 0.1) {
            double a = at(&t, u, v);
            cr_assert_float_eq(at(&t, u + 1, v), a, 1e-9);
            cr_assert_float_eq(at(&t, u, v - 2), a, 1e-9);
            cr_assert(a >= 0 && a <= 13);
        }
    cr_assert(isfinite(at(&t, NAN, 0.5)) && isfinite(at(&t, 0.5, INFINITY)) && isfinite(at(&t, 1e300, -1e300)));
}

/* Quad: uv = (0, 0) at base = M (-0.5, 0, -0.5), u along edge0 = M (1,0,0), v along edge1 = M (0,0,1). */
Test(texture, quad_uv_runs_along_edge0_and_edge1, .init = mk_tmp, .fini = rm_tmp)
{
    struct scene *s = white_scene("{\"type\": \"quad\", \"bsdf\": \"t\", \"transform\": {\"position\": [1, 2, 3],"
                                  " \"scale\": [2, 1, 4], \"rotation\": [0, 0, 30]}}");
    const struct prim *p = &s->prims[0];
    vec3 base = p->quad_base;
    for (int i = 0; i < p->nverts; i++) {
        double u = p->uv[2 * i], v = p->uv[2 * i + 1];
        vec3 expect = vadd(base, vadd(vscale(p->quad_edge0, u), vscale(p->quad_edge1, v)));
        cr_assert(near3(p->p[i], expect, 1e-12), "corner %d: uv (%g %g)", i, u, v);
        cr_assert((u == 0 || u == 1) && (v == 0 || v == 1));
    }
    /* edge0 is local X (2 long, turned 30 degrees about Z), edge1 local Z (4 long) */
    cr_assert(near3(p->quad_edge0, v3(2 * cos(M_PI / 6), 2 * sin(M_PI / 6), 0), 1e-12));
    cr_assert(near3(p->quad_edge1, v3(0, 0, 4), 1e-12));
    cr_assert(near3(base, v3(1 - cos(M_PI / 6), 2 - sin(M_PI / 6), 1), 1e-12));
    scene_model_free(s);
}

/* Cube: on the face of axis d, uv = cube-frame position along (d+1)%3 and (d+2)%3, mapped from
 * [-0.5, 0.5] to [0, 1], on both faces of the axis; the frame follows the rotation. */
Test(texture, cube_uv_per_face, .init = mk_tmp, .fini = rm_tmp)
{
    struct scene *s = white_scene("{\"type\": \"cube\", \"bsdf\": \"t\", \"transform\": {\"position\": [0.5, 0, 0]}},"
                                  "{\"type\": \"cube\", \"bsdf\": \"t\", \"transform\": {\"rotation\": [0, 0, 180]}},"
                                  "{\"type\": \"cube\", \"bsdf\": \"t\", \"transform\": {\"rotation\": [180, 0, 0],"
                                  " \"scale\": [1, 2, 3]}}");
    for (int k = 0; k < 3; k++) {
        const struct prim *p = &s->prims[k];
        int faces[3][2] = {{0, 0}, {0, 0}, {0, 0}};
        for (int t = 0; t < p->ntris; t++) {
            const int *tri = p->tri + 3 * t;
            vec3 l[3];
            for (int c = 0; c < 3; c++) {
                vec3 w = p->p[tri[c]];
                /* back to the cube frame: undo the translation, the rotation, the scale */
                if (k == 0)
                    l[c] = vsub(w, v3(0.5, 0, 0));
                else if (k == 1)
                    l[c] = v3(-w.x, -w.y, w.z);
                else
                    l[c] = v3(w.x, -w.y / 2, -w.z / 3);
            }
            int d = -1;
            for (int a = 0; a < 3; a++)
                if (fabs(fabs(vget(l[0], a)) - 0.5) < 1e-12 && fabs(vget(l[1], a) - vget(l[0], a)) < 1e-12 &&
                    fabs(vget(l[2], a) - vget(l[0], a)) < 1e-12)
                    d = a;
            cr_assert(d >= 0, "cube %d triangle %d lies on no face", k, t);
            faces[d][vget(l[0], d) > 0]++;
            for (int c = 0; c < 3; c++) {
                double u = p->uv[2 * tri[c]], v = p->uv[2 * tri[c] + 1];
                cr_assert_float_eq(u, vget(l[c], (d + 1) % 3) + 0.5, 1e-12, "cube %d face %d", k, d);
                cr_assert_float_eq(v, vget(l[c], (d + 2) % 3) + 0.5, 1e-12, "cube %d face %d", k, d);
            }
        }
        for (int d = 0; d < 3; d++)
            cr_assert(faces[d][0] == 2 && faces[d][1] == 2, "cube %d axis %d", k, d);
    }
    scene_model_free(s);
}

Test(texture, sphere_uv_from_the_local_normal, .init = mk_tmp, .fini = rm_tmp)
{
    struct scene *s = white_scene("{\"type\": \"sphere\", \"bsdf\": \"t\"},"
                                  "{\"type\": \"sphere\", \"bsdf\": \"t\", \"transform\": {\"rotation\": [-90, 0, 0],"
                                  " \"scale\": 2}}");
    static const struct {
        int prim;
        vec3 n;
        double u, v;
    } cases[] = {
        {0, {0, 0, 1}, -1, 0},                                /* pole on local +Z: v = 0 (u: any, -1 = not checked) */
        {0, {0, 0, -1}, -1, 1},     {0, {1, 0, 0}, 0.5, 0.5}, /* local +X: u = 0.5 */
        {0, {0, 1, 0}, 0.75, 0.5},                            /* local +Y: u = 0.75 */
        {0, {0, -1, 0}, 0.25, 0.5}, {1, {0, 1, 0}, -1, 0},    /* rotated -90 about X: local +Z is world +Y */
        {1, {0, 0, -1}, 0.75, 0.5},                           /* local +Y is world -Z */
        {1, {1, 0, 0}, 0.5, 0.5},   {1, {0, -0.5, 0.8660254037844386}, 0.25, 2.0 / 3}, /* local (0, -0.866, -0.5) */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double uv[2];
        sphere_uv(&s->prims[cases[i].prim], cases[i].n, uv);
        bool u_ok = cases[i].u < 0 ? uv[0] >= 0 && uv[0] <= 1 : fabs(uv[0] - cases[i].u) < 1e-12;
        cr_assert(u_ok && fabs(uv[1] - cases[i].v) < 1e-12, "case %zu: uv (%g %g)", i, uv[0], uv[1]);
    }
    scene_model_free(s);
}

/* End to end: a ray onto a textured sphere reads the texel at the hit's uv (a texel centre). */
Test(texture, sphere_hit_reads_its_texel, .init = mk_tmp, .fini = rm_tmp)
{
    /* 2 x 2: top row red, green; bottom row blue, white */
    float px[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    write_image("q.exr", 2, 2, px);
    struct scene *s = tmp_scene("q.exr", "{\"type\": \"sphere\", \"bsdf\": \"t\"}", true);
    static const struct {
        vec3 n;
        rgb texel;
    } cases[] = {
        {{0, 0.7071067811865476, -0.7071067811865476}, {0, 1, 0}},  /* uv (0.75, 0.75): top right */
        {{0, -0.7071067811865476, 0.7071067811865476}, {0, 0, 1}},  /* uv (0.25, 0.25): bottom left */
        {{0, -0.7071067811865476, -0.7071067811865476}, {1, 0, 0}}, /* uv (0.25, 0.75): top left */
        {{0, 0.7071067811865476, 0.7071067811865476}, {1, 1, 1}},   /* uv (0.75, 0.25): bottom right */
    };
    for (int i = 0; i < 4; i++) {
        vec3 o = vscale(cases[i].n, 3), d = vneg(cases[i].n);
        struct hit h;
        cr_assert(accel_intersect(s->accel, o, d, 0, INFINITY, &h));
        struct vertex v;
        surface_from_hit(s, o, d, &h, &v);
        cr_assert(near3(v.p, cases[i].n, 1e-6));
        cr_assert(near3(v.bc.albedo, cases[i].texel, 1e-6), "case %d: albedo (%g %g %g)", i, v.bc.albedo.x,
                  v.bc.albedo.y, v.bc.albedo.z);
    }
    scene_free(s);
}

/* .obj: vt as written; a corner without vt reads uv (0, 0) while the other corners keep theirs. */
Test(texture, obj_uv_as_written_and_zero_where_missing, .init = mk_tmp, .fini = rm_tmp)
{
    static const char obj[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                              "vt 0.25 0.5\nvt 0.75 0.125\nvt 1.5 -2\n"
                              "f 1/1 2/2 3/3\nf 1 3/-1 4\n";
    char path[512], err[512] = "";
    snprintf(path, sizeof path, "%s/m.obj", tmpdir);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(obj, 1, sizeof obj - 1, f), sizeof obj - 1);
    fclose(f);
    struct raw_mesh m;
    cr_assert(mesh_load(path, &m, err, sizeof err), "%s", err);
    cr_assert_eq(m.nverts, 6);
    cr_assert(m.uv);
    static const double expect[6][2] = {{0.25, 0.5}, {0.75, 0.125}, {1.5, -2}, {0, 0}, {1.5, -2}, {0, 0}};
    for (int i = 0; i < 6; i++)
        cr_assert(m.uv[2 * i] == expect[i][0] && m.uv[2 * i + 1] == expect[i][1], "corner %d: (%g %g)", i, m.uv[2 * i],
                  m.uv[2 * i + 1]);
    raw_mesh_free(&m);
}

/* A PNG's colour is used as stored, not multiplied by its alpha (OpenImageIO's default): texels
 * (200, 100, 50) at alpha 128 and (30, 60, 254) at alpha 0. */
Test(texture, png_alpha_is_not_multiplied_in)
{
    char err[512] = "";
    struct texture *t = texture_load("tests/data/texture/rgba8.png", err, sizeof err);
    cr_assert(t, "%s", err);
    cr_assert_eq(t->bits, 8);
    static const int codes[6] = {200, 100, 50, 30, 60, 254};
    for (int i = 0; i < 6; i++)
        cr_assert_eq(t->rgb[i], texture_gamma_decode(codes[i]), "texel value %d: %g", i, t->rgb[i] * 255);
    texture_free(t);
}
