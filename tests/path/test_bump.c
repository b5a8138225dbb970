/* Bump maps (README, "Textures"): the shading frame surface_from_hit builds on a bumped BSDF is
 * orthonormal, equals the unbumped frame where the height is constant, and tilts as Tungsten's
 * setupTangentFrame tilts it (the height's texel-difference slope along each primitive's
 * tangents: quad edges, cube axes, TriangleMesh's signed uv directions, the sphere's T); the
 * slope itself is Tungsten's BitmapTexture::derivatives. The inverse walks retrace on the bump and
 * textured-roughness conformance scenes: the frame is a function of the hit point, so the
 * inversion needs nothing more. */
#include <criterion/criterion.h>

#include "io/oiio.h"
#include "path/path.h"
#include "path/scene_ready.h"
#include "scene/accel.h"
#include "support/scenes.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <string.h>

static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "bump-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

static bool near3(vec3 a, vec3 b, double eps) { return vlen(vsub(a, b)) < eps; }

static void write_file(const char *name, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(text, 1, strlen(text), f), strlen(text));
    fclose(f);
}

/* 8 x 8 float height maps: "ru" rises along u (column i: 0.1 i), "rv" rises with v (row j from the
 * top: 0.1 (7 - j)), "c" is flat at 0.5. */
static void write_maps(void)
{
    float ru[8 * 8 * 3], rv[8 * 8 * 3], c[8 * 8 * 3];
    for (int j = 0; j < 8; j++)
        for (int i = 0; i < 8; i++)
            for (int k = 0; k < 3; k++) {
                ru[3 * (8 * j + i) + k] = 0.1f * i;
                rv[3 * (8 * j + i) + k] = 0.1f * (7 - j);
                c[3 * (8 * j + i) + k] = 0.5f;
            }
    const char *names[] = {"ru.exr", "rv.exr", "c.exr"};
    const float *px[] = {ru, rv, c};
    for (int m = 0; m < 3; m++) {
        char path[512], err[512] = "";
        snprintf(path, sizeof path, "%s/%s", tmpdir, names[m]);
        cr_assert(oiio_write(path, 8, 8, 3, px[m], err, sizeof err), "%s", err);
    }
}

/* A ready scene of one primitive whose lambert bsdf has the given `bump` value (or none). */
static struct scene *bump_scene(const char *bump, const char *prim)
{
    char json[4096], path[512], err[1024] = "";
    snprintf(json, sizeof json,
             "{\"bsdfs\": [{\"name\": \"b\", \"type\": \"lambert\"%s%s}],\n"
             " \"primitives\": [%s],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 60, \"resolution\": 16,\n"
             "   \"transform\": {\"position\": [0, 0, 9], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             bump ? ", \"bump\": " : "", bump ? bump : "", prim);
    write_file("scene.json", json);
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    struct scene *s = scene_load(path, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

/* The vertex a ray from o along unit d reaches. */
static struct vertex hit_at(const struct scene *sc, vec3 o, vec3 d)
{
    struct vertex prev = {.kind = VK_CAMERA, .p = o}, v;
    cr_assert(walk_hit(sc, &prev, d, &v), "ray missed");
    return v;
}

static void check_orthonormal(const frame *f)
{
    cr_assert(fabs(vlen(f->s) - 1) < 1e-12 && fabs(vlen(f->t) - 1) < 1e-12 && fabs(vlen(f->n) - 1) < 1e-12);
    cr_assert(fabs(vdot(f->s, f->t)) < 1e-12 && fabs(vdot(f->s, f->n)) < 1e-12 && fabs(vdot(f->t, f->n)) < 1e-12);
    cr_assert(vdot(vcross(f->s, f->t), f->n) > 0, "left-handed frame");
}

/* The 2 x 3 quad in the xz-plane (normal +y), hit at uv (0.55, 0.45), off the diagonal its two
 * triangles share. */
#define QUAD "{\"type\": \"quad\", \"bsdf\": \"b\", \"transform\": {\"scale\": [2, 1, 3]}}"

static struct vertex quad_hit(const char *bump)
{
    struct scene *sc = bump_scene(bump, QUAD);
    struct vertex v = hit_at(sc, v3(0.1, 1, -0.15), v3(0, -1, 0));
    scene_free(sc);
    return v;
}

/* Tungsten's derivatives(): central differences two texels apart, blended bilinearly, d[1] along
 * the rows (down the image). Interior points of the ramps have slope 0.2 per the two texels. */
Test(bump, texture_slope_is_tungstens_texel_difference, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    char path[512], err[512];
    snprintf(path, sizeof path, "%s/ru.exr", tmpdir);
    struct texture *ru = texture_load_average(path, err, sizeof err);
    snprintf(path, sizeof path, "%s/rv.exr", tmpdir);
    struct texture *rv = texture_load_average(path, err, sizeof err);
    cr_assert(ru && rv, "%s", err);
    double d[2];
    for (double u = 0.3; u < 0.7; u += 0.01) {
        texture_derivs(ru, u, 0.5, d);
        cr_assert(fabs(d[0] - 0.2) < 1e-6 && fabs(d[1]) < 1e-12, "u %g: (%g, %g)", u, d[0], d[1]);
        texture_derivs(rv, 0.5, u, d);
        cr_assert(fabs(d[0]) < 1e-12 && fabs(d[1] + 0.2) < 1e-6, "v %g: (%g, %g)", u, d[0], d[1]);
    }
    /* between texel centres 6.5 and 7.5 of the ramp (u = 7/8) the right-hand differences wrap
     * around (0 - 0.6 at column 7): the blend of 0.2 and -0.6 half way */
    texture_derivs(ru, 7.0 / 8, 0.5, d);
    cr_assert(fabs(d[0] - (0.5 * 0.2 + 0.5 * -0.6)) < 1e-6, "%g", d[0]);
    texture_free(ru);
    texture_free(rv);
}

/* A constant height, whether a flat map, a checker (slope 0) or a number (dropped at load), leaves
 * the unbumped frame. */
Test(bump, constant_height_keeps_the_unbumped_frame, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    struct vertex flat = quad_hit(NULL);
    const char *bumps[] = {"\"c.exr\"", "{\"type\": \"checker\", \"res_u\": 3}", "0.5"};
    for (int i = 0; i < 3; i++) {
        struct vertex v = quad_hit(bumps[i]);
        check_orthonormal(&v.sh);
        cr_assert(near3(v.sh.n, flat.sh.n, 1e-12) && near3(v.sh.s, flat.sh.s, 1e-12) && near3(v.sh.t, flat.sh.t, 1e-12),
                  "bump %s: n (%g %g %g)", bumps[i], v.sh.n.x, v.sh.n.y, v.sh.n.z);
        cr_assert(near3(v.ng, flat.ng, 1e-15));
    }
    struct scene *sc = bump_scene("0.5", QUAD);
    cr_assert_null(sc->bsdfs[0].bump_tex);
    scene_free(sc);
}

/* On the quad (T = edge0 = (2, 0, 0), B = edge1 = (0, 0, 3), n = +y) the normal is
 * T' x B' = (T + n du) x (B + n dv) turned to n's side, (-du |B|, |T| |B|, -dv |T|):
 * a height rising along u (du = 0.2) tilts it toward -x; one rising with v (dv = -0.2, rows run
 * down the image) toward +z, Tungsten's sign. */
Test(bump, quad_ramps_tilt_the_normal_as_tungsten, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    struct vertex u = quad_hit("\"ru.exr\""), v = quad_hit("{\"type\": \"bitmap\", \"file\": \"rv.exr\"}");
    check_orthonormal(&u.sh);
    check_orthonormal(&v.sh);
    cr_assert(near3(u.sh.n, vnorm(v3(-0.2 * 3, 6, 0)), 1e-6), "n (%g %g %g)", u.sh.n.x, u.sh.n.y, u.sh.n.z);
    cr_assert(near3(v.sh.n, vnorm(v3(0, 6, 0.2 * 2)), 1e-6), "n (%g %g %g)", v.sh.n.x, v.sh.n.y, v.sh.n.z);
    cr_assert(near3(u.ng, v3(0, 1, 0), 1e-12) && u.front && !u.flipped);
}

/* Cubes take Tungsten's Cube axes (T = +y, B = +z on both x faces): the u ramp tilts the normal
 * toward -y on the +x face and on the -x face alike. */
Test(bump, cube_faces_use_the_cube_axes, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    struct scene *sc = bump_scene("\"ru.exr\"", "{\"type\": \"cube\", \"bsdf\": \"b\"}");
    /* uv (0.55, 0.48), off the faces' diagonals */
    struct vertex p = hit_at(sc, v3(3, 0.05, -0.02), v3(-1, 0, 0)), m = hit_at(sc, v3(-3, 0.05, -0.02), v3(1, 0, 0));
    check_orthonormal(&p.sh);
    check_orthonormal(&m.sh);
    cr_assert(near3(p.sh.n, vnorm(v3(1, -0.2, 0)), 1e-6), "+x: n (%g %g %g)", p.sh.n.x, p.sh.n.y, p.sh.n.z);
    cr_assert(near3(m.sh.n, vnorm(v3(-1, -0.2, 0)), 1e-6), "-x: n (%g %g %g)", m.sh.n.x, m.sh.n.y, m.sh.n.z);
    scene_free(sc);
}

/* Meshes take TriangleMesh's tangents, normalize(q1 t2 - t1 q2) and normalize(q2 s1 - s2 q1), which
 * are dp/du and dp/dv divided by |det| but not by its sign: where the uv map reverses orientation
 * (u = x, v = z on a face whose normal is +y) both point backward and the u ramp tilts the normal
 * toward +x; with v = -z (orientation kept) toward -x, as on the quad. */
Test(bump, mesh_tangents_follow_tungstens_triangle_formula, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    const char *obj = "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\n"
                      "vt %s\nvt %s\nvt %s\nvt %s\nf 1/1 4/4 3/3\nf 1/1 3/3 2/2\n";
    const char *vt[2][4] = {{"0 0", "1 0", "1 1", "0 1"}, {"0 1", "1 1", "1 0", "0 0"}};
    const double tilt[2] = {0.2, -0.2};
    for (int k = 0; k < 2; k++) {
        char text[512];
        snprintf(text, sizeof text, obj, vt[k][0], vt[k][1], vt[k][2], vt[k][3]);
        write_file("m.obj", text);
        struct scene *sc = bump_scene("\"ru.exr\"", "{\"type\": \"mesh\", \"file\": \"m.obj\", \"bsdf\": \"b\"}");
        struct vertex v = hit_at(sc, v3(0.05, 1, -0.02), v3(0, -1, 0));
        check_orthonormal(&v.sh);
        cr_assert(near3(v.sh.n, vnorm(v3(tilt[k], 1, 0)), 1e-6), "uv %d: n (%g %g %g)", k, v.sh.n.x, v.sh.n.y,
                  v.sh.n.z);
        scene_free(sc);
    }
}

/* Spheres: at the local +x point (uv (0.5, 0.5)) Tungsten's T = R (-l.y, l.x, l.z) = +y (the
 * direction of growing u), B = n x T = +z: the u ramp tilts the normal toward -y. */
Test(bump, sphere_uses_tungstens_tangent, .init = mk_tmp, .fini = rm_tmp)
{
    write_maps();
    struct scene *sc = bump_scene("\"ru.exr\"", "{\"type\": \"sphere\", \"bsdf\": \"b\"}");
    struct vertex v = hit_at(sc, v3(3, 0, 0), v3(-1, 0, 0));
    check_orthonormal(&v.sh);
    cr_assert(near3(v.sh.n, vnorm(v3(1, -0.2, 0)), 1e-6), "n (%g %g %g)", v.sh.n.x, v.sh.n.y, v.sh.n.z);
    scene_free(sc);
}

/* Fills every slot with fresh numbers: blocks the inversion cannot determine still replay. */
static void prefill(struct sampler_writer *w, rng *r)
{
    for (int st = 0; st < STREAM_COUNT; st++)
        for (int i = 0; i < STREAM_DIMS; i++)
            w->u[st][i] = rng_uniform(r);
}

/* 20000 camera and 20000 emitter walks of up to 6 segments per scene: invert, replay, and the walk
 * must reach the same vertices (1e-4 of the scene's size); at most 1 in 2000 may fail, the bound of
 * test_path_invert.c. */
static void check_retrace(const char *path)
{
    struct scene *sc = test_scene(path);
    struct path_ctx pc = {.sc = sc, .max_length = 6};
    static struct vertex a[MAX_SUBPATH_VERTS], b[MAX_SUBPATH_VERTS];
    static struct sampler_writer w;
    struct sampler_independent ind;
    struct sampler_replay rep;
    rng r;
    rng_seed(&r, 13, 0);
    sampler_writer_init(&w, 17, 0);
    double tol = 1e-4 * fmax(1.0, vlen(vsub(sc->bbox_max, sc->bbox_min)));
    for (int kind = 0; kind < 2; kind++) {
        int tried = 0, fail = 0;
        for (int i = 0; i < 20000; i++) {
            sampler_independent_init(&ind, 29, (uint64_t)i * 2 + kind);
            int n = kind == 0 ? walk_camera(&pc, &ind.base, a, 7) : walk_emitter(&pc, &ind.base, a, 7);
            if (n < 3) continue;
            tried++;
            prefill(&w, &r);
            bool ok = kind == 0 ? invert_camera(&pc, a, n, 0, &w.base) : invert_emitter(&pc, a, n, 0, &w.base);
            sampler_replay_init(&rep, (const double(*)[STREAM_DIMS])w.u);
            int m = !ok ? 0 : kind == 0 ? walk_camera(&pc, &rep.base, b, 7) : walk_emitter(&pc, &rep.base, b, 7);
            bool same = ok && m >= n;
            for (int j = 0; same && j < n; j++)
                same = a[j].prim == b[j].prim && vlen(vsub(a[j].p, b[j].p)) <= tol;
            if (!same) fail++;
        }
        fprintf(stderr, "bump: %s %s walks: %d of %d did not retrace\n", path, kind ? "emitter" : "camera", fail,
                tried);
        cr_expect(tried > 2000, "%s: only %d walks of >= 3 vertices", path, tried);
        cr_expect(fail <= tried / 2000, "%s: %d of %d walks did not retrace", path, fail, tried);
    }
    scene_free(sc);
}

Test(bump, inverse_walks_retrace_on_bumped_and_rough_textured_scenes)
{
    check_retrace("tests/data/tungsten/bump-map.json");
    check_retrace("tests/data/tungsten/texture-roughness.json");
}
