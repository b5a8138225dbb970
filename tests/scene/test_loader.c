/* Loader tests: committed scenes load with the geometry Tungsten would build, generated .obj/.wo3
 * meshes load, and every malformed input in tests/data/bad gives its one-line message. */
#include <criterion/criterion.h>

#include "bsdf/bsdf_json.h"
#include "path/scene_ready.h"
#include "support/tmpdir.h"

#include "camera/camera.h"
#include "io/image.h"
#include "path/path.h"
#include "scene/accel.h"
#include "scene/scene.h"
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define EPS 1e-9

static bool near3(vec3 a, vec3 b, double eps) { return vlen(vsub(a, b)) < eps; }

static struct scene *load_ok(const char *path)
{
    char err[1024] = "";
    struct scene *s = scene_load_model(path, err, sizeof err);
    cr_assert(s, "%s should load: %s", path, err);
    return s;
}

/* (p1 - p0) x (p2 - p0) of triangle t: the winding normal, length = 2 * area. */
static vec3 tri_cross(const struct prim *p, int t)
{
    const int *i = p->tri + 3 * t;
    return vcross(vsub(p->p[i[1]], p->p[i[0]]), vsub(p->p[i[2]], p->p[i[0]]));
}

static void check_quad(const struct prim *p, vec3 normal, double area)
{
    cr_assert_eq(p->kind, PRIM_QUAD);
    cr_assert(near3(p->quad_normal, normal, 1e-9), "normal (%g %g %g)", p->quad_normal.x, p->quad_normal.y,
              p->quad_normal.z);
    cr_assert(fabs(p->area - area) < 1e-9, "area %g, expected %g", p->area, area);
    cr_assert_eq(p->ntris, 2);
    double sum = 0;
    for (int t = 0; t < 2; t++) {
        vec3 c = tri_cross(p, t);
        cr_assert(vdot(vnorm(c), normal) > 1 - 1e-9, "triangle %d winds against the quad normal", t);
        sum += 0.5 * vlen(c);
    }
    cr_assert(fabs(sum - area) < 1e-9);
    /* the parallelogram and its normal: normal = edge1 x edge0 */
    cr_assert(near3(vnorm(vcross(p->quad_edge1, p->quad_edge0)), normal, 1e-9));
}

Test(loader, cornell_box)
{
    struct scene *s = load_ok("scenes/cornell-box/scene.json");
    cr_assert_eq(s->nprims, 8);
    cr_assert_eq(s->nbsdfs, 4);
    cr_assert_eq(s->env_prim, -1);
    check_quad(&s->prims[0], v3(0, 1, 0), 4);  /* floor faces up */
    check_quad(&s->prims[1], v3(0, -1, 0), 4); /* ceiling faces down */
    check_quad(&s->prims[2], v3(0, 0, 1), 4);  /* back wall faces the camera */
    check_quad(&s->prims[3], v3(1, 0, 0), 4);  /* left (red) faces +x */
    check_quad(&s->prims[4], v3(-1, 0, 0), 4); /* right (green) faces -x */
    check_quad(&s->prims[7], v3(0, -1, 0), 0.2);
    cr_assert(s->prims[7].emissive && !s->prims[0].emissive);
    cr_assert(near3(s->prims[7].emission, v3(17, 12, 4), EPS));
    cr_assert_str_eq(s->bsdfs[s->prims[3].bsdf].name, "red");
    cr_assert(near3(s->bsdfs[s->prims[3].bsdf].albedo, v3(0.63, 0.065, 0.05), EPS));
    cr_assert_eq(s->max_length, 8);
    cr_assert_eq(s->min_length, 1);
    cr_assert_eq(s->spp, 64);
    cr_assert(s->two_sided_shading);
    cr_assert_eq(s->cam.width, 256);
    cr_assert_eq(s->cam.height, 256);
    cr_assert_eq(s->cam.filter, FILTER_BOX);
    /* looking down -z with up +y: image right is +x (Tungsten negates the JSON x axis) */
    cr_assert(near3(s->cam.basis.n, v3(0, 0, -1), EPS));
    cr_assert(near3(s->cam.basis.s, v3(1, 0, 0), EPS));
    cr_assert(near3(s->cam.basis.t, v3(0, 1, 0), EPS));
    cr_assert(fabs(s->cam.tan_half_fov - tan(22.5 * M_PI / 180)) < EPS);
    cr_assert(near3(s->bbox_min, v3(-1, 0, -1), 1e-9) && near3(s->bbox_max, v3(1, 2, 1), 1e-9));
    scene_model_free(s);
}

/* bin/bench's rays per sample rest on these counters: every query of the calling thread counts,
 * by kind, and another thread's queries do not. */
static void *cast_three(void *sc)
{
    const struct scene *s = sc;
    struct hit h;
    for (int i = 0; i < 3; i++)
        accel_intersect(s->accel, v3(0, 1, 0), v3(0, -1, 0), 0, INFINITY, &h);
    return NULL;
}

Test(loader, ray_counts_count_the_calling_threads_queries)
{
    char err[1024] = "";
    struct scene *s = scene_load("scenes/cornell-box/scene.json", err, sizeof err);
    cr_assert(s, "%s", err);
    struct ray_counts a = accel_ray_counts();
    struct hit h;
    cr_assert(accel_intersect(s->accel, v3(0, 1, 0), v3(0, -1, 0), 0, INFINITY, &h)); /* floor */
    cr_assert(!accel_intersect(s->accel, v3(0, 1, 3), v3(0, 0, 1), 0, INFINITY, &h)); /* out the open front */
    cr_assert(accel_occluded(s->accel, v3(0, 1, 0), v3(0, -1, 0), 0, INFINITY));
    pthread_t th;
    cr_assert(pthread_create(&th, NULL, cast_three, s) == 0);
    pthread_join(th, NULL);
    struct ray_counts b = accel_ray_counts();
    cr_assert_eq(b.closest - a.closest, 2);
    cr_assert_eq(b.shadow - a.shadow, 1);
    scene_free(s);
}

static void check_cube_outward(const struct prim *p, vec3 centre, double area)
{
    cr_assert_eq(p->kind, PRIM_MESH);
    cr_assert_eq(p->ntris, 12);
    double sum = 0;
    for (int t = 0; t < 12; t++) {
        const int *i = p->tri + 3 * t;
        vec3 mid = vscale(vadd(vadd(p->p[i[0]], p->p[i[1]]), p->p[i[2]]), 1.0 / 3);
        cr_assert(vdot(tri_cross(p, t), vsub(mid, centre)) > 0, "cube triangle %d faces inward", t);
        sum += 0.5 * vlen(tri_cross(p, t));
    }
    cr_assert(fabs(sum - area) < 1e-9 && fabs(p->area - area) < 1e-9, "area %g, expected %g", p->area, area);
}

Test(loader, cube_faces_outward)
{
    struct scene *s = load_ok("scenes/cornell-box/scene.json");
    check_cube_outward(&s->prims[5], v3(-0.33, 0.6, -0.3), 2 * (0.6 * 1.2 * 2 + 0.36));
    check_cube_outward(&s->prims[6], v3(0.35, 0.3, 0.35), 6 * 0.36);
    scene_model_free(s);
}

Test(loader, furnace_faces_inward)
{
    struct scene *s = load_ok("scenes/furnace/scene.json");
    cr_assert_eq(s->nprims, 6);
    for (int i = 0; i < 6; i++) {
        const struct prim *p = &s->prims[i];
        vec3 centre = vadd(p->quad_base, vscale(vadd(p->quad_edge0, p->quad_edge1), 0.5));
        cr_assert(vdot(p->quad_normal, vneg(centre)) > 0.99, "wall %d does not face the inside", i);
        cr_assert(p->emissive && fabs(p->area - 4) < 1e-9);
        cr_assert(near3(s->bsdfs[p->bsdf].albedo, v3s(0.5), EPS));
        cr_assert(vdot(tri_cross(p, 0), p->quad_normal) > 0);
    }
    cr_assert_eq(s->max_length, 8);
    scene_model_free(s);
}

/* A temporary directory holding generated scenes and meshes; removed at teardown. */
static char tmpdir[256];

static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "loader-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

static void write_file(const char *name, const void *data, size_t n)
{
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *f = fopen(path, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(data, 1, n, f), n);
    fclose(f);
}

static struct scene *load_tmp_scene(const char *prims)
{
    char json[4096];
    snprintf(json, sizeof json,
             "{\"bsdfs\": [{\"name\": \"m\", \"type\": \"rough_conductor\", \"material\": \"Au\"}],\n"
             " \"primitives\": [%s],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 60, \"resolution\": 100,\n"
             "   \"transform\": {\"position\": [1, 2, 3], \"look_at\": [1, 2, 13], \"up\": [0, 0.5, 0.5]}}}\n",
             prims);
    write_file("scene.json", json, strlen(json));
    char path[512];
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    return load_ok(path);
}

Test(loader, transforms_sphere_camera, .init = mk_tmp, .fini = rm_tmp)
{
    struct scene *s = load_tmp_scene(
        "{\"type\": \"quad\", \"bsdf\": \"m\", \"transform\": {\"position\": [1, 2, 3], \"scale\": [2, 1, 3], "
        "\"rotation\": [0, 90, 0]}},"
        "{\"type\": \"quad\", \"bsdf\": \"m\", \"transform\": [0, 0, -3, 1,  0, 1, 0, 2,  2, 0, 0, 3,  0, 0, 0, 1]},"
        "{\"type\": \"sphere\", \"bsdf\": {\"type\": \"plastic\"}, \"power\": 100, "
        "\"transform\": {\"position\": [4, 5, 6], \"scale\": [1, 3, 2]}}");
    /* rotYXZ(0, 90, 0) maps x to +z and z to -x (Tungsten's Y sign): edge0 = (0, 0, 2),
     * edge1 = (-3, 0, 0), normal edge1 x edge0 = +y */
    for (int i = 0; i < 2; i++) {
        const struct prim *p = &s->prims[i];
        cr_assert(near3(p->quad_edge0, v3(0, 0, 2), 1e-12) && near3(p->quad_edge1, v3(-3, 0, 0), 1e-12));
        cr_assert(near3(p->quad_base, v3(2.5, 2, 2), 1e-12));
        check_quad(p, v3(0, 1, 0), 6);
    }
    const struct prim *sp = &s->prims[2];
    cr_assert_eq(sp->kind, PRIM_SPHERE);
    cr_assert(near3(sp->center, v3(4, 5, 6), EPS) && fabs(sp->radius - 3) < EPS);
    cr_assert(fabs(sp->area - 36 * M_PI) < 1e-9);
    /* power -> radiance: power / (pi * area), Tungsten's powerToRadianceFactor */
    cr_assert(near3(sp->emission, v3s(100 / (M_PI * 36 * M_PI)), 1e-12));
    cr_assert_eq(s->bsdfs[sp->bsdf].type, BSDF_PLASTIC);
    cr_assert_str_eq(s->bsdfs[sp->bsdf].name, "inline:2");
    cr_assert(fabs(s->bsdfs[sp->bsdf].ior - 1.5) < EPS && fabs(s->bsdfs[sp->bsdf].thickness - 1) < EPS);
    const struct bsdf *m = &s->bsdfs[0];
    cr_assert_eq(m->type, BSDF_ROUGH_CONDUCTOR);
    cr_assert_eq(m->dist, MF_GGX);
    cr_assert(fabs(m->roughness - 0.1) < EPS && fabs(m->eta.x - 0.1431189557) < 1e-9);
    /* camera: +z forward, up tilted: Gram-Schmidt keeps up = +y, image right = fwd x up = -x */
    cr_assert(near3(s->cam.basis.n, v3(0, 0, 1), EPS) && near3(s->cam.basis.t, v3(0, 1, 0), EPS));
    cr_assert(near3(s->cam.basis.s, v3(-1, 0, 0), EPS));
    cr_assert(s->cam.width == 100 && s->cam.height == 100 && fabs(s->cam.aspect - 1) < EPS);
    cr_assert_eq(s->max_length, 64); /* Tungsten's default max_bounces */
    cr_assert_eq(s->spp, 32);
    scene_model_free(s);
}

Test(loader, obj_mesh, .init = mk_tmp, .fini = rm_tmp)
{
    const char *obj = "# a unit square as one polygon, plus a triangle by negative indices\n"
                      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                      "vn 0 0 2\n"
                      "g square\nusemtl whatever\ns 1\n"
                      "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
                      "v 0 0 1\nv 1 0 1\nv 0 1 1\n"
                      "f -3/1/-1 -2/2/-1 -1/3/-1\n";
    write_file("m.obj", obj, strlen(obj));
    struct scene *s = load_tmp_scene("{\"type\": \"mesh\", \"file\": \"m.obj\", \"smooth\": true, \"bsdf\": \"m\", "
                                     "\"transform\": {\"scale\": 2, \"position\": [0, 0, -1]}}");
    const struct prim *p = &s->prims[0];
    cr_assert_eq(p->kind, PRIM_MESH);
    cr_assert_eq(p->ntris, 3);
    cr_assert(fabs(p->area - (4 + 2)) < 1e-9, "area %g", p->area);
    cr_assert(p->n && p->uv);
    for (int i = 0; i < p->nverts; i++)
        cr_assert(near3(p->n[i], v3(0, 0, 1), EPS));
    for (int t = 0; t < 3; t++)
        cr_assert(vdot(tri_cross(p, t), v3(0, 0, 1)) > 0);
    const int *last = p->tri + 6;
    cr_assert(near3(p->p[last[0]], v3(0, 0, 1), EPS) && near3(p->p[last[2]], v3(0, 2, 1), EPS));
    cr_assert(fabs(p->uv[2 * last[1]] - 1) < EPS);
    scene_model_free(s);
}

static void put_f32(unsigned char **w, float f)
{
    memcpy(*w, &f, 4);
    *w += 4;
}

static void put_u32(unsigned char **w, unsigned v)
{
    memcpy(*w, &v, 4);
    *w += 4;
}

Test(loader, wo3_mesh_drops_degenerate, .init = mk_tmp, .fini = rm_tmp)
{
    unsigned char buf[8 + 4 * 32 + 8 + 2 * 16], *w = buf;
    unsigned long long nv = 4, nt = 2;
    memcpy(w, &nv, 8);
    w += 8;
    float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {2, 0, 0}};
    for (int i = 0; i < 4; i++) {
        for (int k = 0; k < 3; k++)
            put_f32(&w, v[i][k]);
        put_f32(&w, 0), put_f32(&w, 1), put_f32(&w, 0), put_f32(&w, v[i][0]), put_f32(&w, -v[i][2]);
    }
    memcpy(w, &nt, 8);
    w += 8;
    unsigned tris[2][3] = {{0, 1, 2}, {0, 1, 3}}; /* the second is collinear */
    for (int t = 0; t < 2; t++) {
        for (int k = 0; k < 3; k++)
            put_u32(&w, tris[t][k]);
        put_u32(&w, 0);
    }
    cr_assert_eq((size_t)(w - buf), sizeof buf);
    write_file("m.wo3", buf, sizeof buf);
    struct scene *s = load_tmp_scene("{\"type\": \"mesh\", \"file\": \"m.wo3\", \"smooth\": true, \"bsdf\": \"m\", "
                                     "\"emission\": [1, 2, 3], \"transform\": {\"rotation\": [90, 0, 0]}}");
    const struct prim *p = &s->prims[0];
    cr_assert_eq(p->ntris, 1);
    cr_assert(fabs(p->area - 0.5) < 1e-7);
    cr_assert(p->emissive);
    /* rotation 90 about x maps +y to +z, for the normals and for the winding alike */
    cr_assert(near3(p->n[0], v3(0, 0, 1), 1e-7));
    cr_assert(vdot(vnorm(tri_cross(p, 0)), v3(0, 0, 1)) > 1 - 1e-7);
    scene_model_free(s);
}

Test(loader, missing_scene_file)
{
    char err[512] = "";
    cr_assert_null(scene_load_model("tests/data/bad/no_such_scene.json", err, sizeof err));
    cr_assert(strstr(err, "tests/data/bad/no_such_scene.json: cannot read"), "%s", err);
}

struct bad_case {
    const char *file, *expect;
};

static const struct bad_case bad_cases[] = {
    {"malformed.json", "malformed.json:3:22: malformed JSON"},
    {"empty.json", "empty.json:1:1: malformed JSON"},
    {"toplevel_array.json", "expected a JSON object at the top level"},
    {"missing_primitives.json", ": primitives: missing required field"},
    {"primitives_not_array.json", ": primitives: expected an array"},
    {"media_present.json", ": media: participating media are not supported"},
    {"unknown_prim_type.json", ": primitives[0].type: unknown primitive type \"torus\""},
    {"unknown_bsdf_type.json", ": bsdfs[0].type: unknown bsdf type \"no_such_bsdf\""},
    {"undefined_bsdf.json", ": primitives[0].bsdf: undefined bsdf \"nope\""},
    {"scale_string.json", ": primitives[0].transform.scale: expected a number or an array of 3 numbers"},
    {"scale_two.json", ": primitives[0].transform.scale: expected a number or an array of 3 numbers"},
    {"resolution_negative.json", ": camera.resolution: expected a positive integer"},
    {"resolution_zero.json", ": camera.resolution: expected a positive integer"},
    {"resolution_fraction.json", ": camera.resolution: expected a positive integer"},
    {"matrix_15.json", ": primitives[0].transform: expected an object or an array of 16 numbers"},
    {"mesh_missing_file.json", ": primitives[0].file: tests/data/bad/does_not_exist.obj: cannot open"},
    {"mesh_no_file_key.json", ": primitives[0].file: missing required field"},
    {"mesh_truncated_wo3.json", ": primitives[0].file: tests/data/bad/truncated.wo3: corrupt .wo3"},
    {"mesh_wo3_bad_index.json", "bad_index.wo3: corrupt .wo3: triangle 0 index 7 out of range"},
    {"mesh_obj_bad_index.json", "bad_index.obj: line 4: face index out of range"},
    {"mesh_obj_nan.json", "nan.obj: line 2: non-finite number"},
    {"mesh_ply.json", ": primitives[0].file: tests/data/bad/mesh.ply: unknown mesh format"},
    {"mesh_degenerate_emitter.json", ": primitives[0]: zero-area emitter"},
    {"missing_texture.json", ": primitives[0].bsdf.albedo: cannot load texture"},
    {"texture_checker.json", ": bsdfs[0].albedo.res_u: expected an integer in [1, 1073741824]"},
    {"zero_area_emitter.json", ": primitives[0]: zero-area emitter"},
    {"missing_camera.json", ": camera: missing"},
    {"camera_ortho.json", ": camera.type: unsupported camera type \"orthographic\""},
    {"camera_look_at_position.json", ": camera.transform.look_at: must differ from position"},
    {"max_bounces_zero.json", ": integrator.max_bounces: expected an integer in [1, "},
    {"min_ge_max.json", ": integrator.min_bounces: must be less than max_bounces"},
    {"max_bounces_huge.json", ": integrator.max_bounces: expected an integer in [1, 65536]"},
    {"min_bounces_above_limit.json",
     ": integrator.min_bounces: must be less than 64 (the renderer's path length limit)"},
    {"resolution_too_many_pixels.json", ": camera.resolution: 10000x10000 is 100000000 pixels, above the limit"},
    {"texture_too_large.json", "texture_too_large.png: 16384x8193 texels, above the limit of 134217728"},
    {"albedo_negative.json", ": bsdfs[0].albedo: expected non-negative values"},
    {"albedo_bool.json", ": bsdfs[0].albedo: expected a number, an array of 3 numbers, an image file name"},
    {"albedo_overflow.json", ": bsdfs[0].albedo: expected finite numbers"},
    {"fov_overflow.json", ": camera.fov: expected a finite number"},
    {"unknown_metal.json", ": bsdfs[0].material: unknown metal \"Unobtainium\""},
    {"distribution_phong.json", ": bsdfs[0].distribution: expected \"ggx\" or \"beckmann\""},
    {"roughness_texture.json", ": bsdfs[0].roughness: cannot load texture"},
    {"ior_negative.json", ": bsdfs[0].ior: expected a positive number"},
    {"bsdf_number.json", ": primitives[0].bsdf: expected a bsdf name or a bsdf object"},
    {"emission_texture_quad.json", ": primitives[0].emission: textured emission is only supported on infinite_sphere"},
    {"emission_negative.json", ": primitives[0].emission: expected non-negative values"},
    {"int_medium.json", ": primitives[0].int_medium: participating media are not supported"},
    {"two_env.json", ": primitives[2]: only one infinite_sphere is supported"},
    {"two_sided_string.json", ": integrator.enable_two_sided_shading: expected true or false"},
    {"bsdf_array_two.json", ": primitives[0].bsdf: per-triangle bsdf arrays are not supported"},
    {"prim_not_object.json", ": primitives[0]: expected a primitive object"},
    {"prim_no_type.json", ": primitives[0].type: missing required field"},
    {"rotation_huge.json", ": primitives[3].transform.rotation[1]: expected an angle within +-1e6 degrees"},
    /* Tungsten types the harness knows but does not render: named, with the reason */
    {"refused_bsdf_hair.json",
     ": bsdfs[0].type: bsdf type \"hair\" is not supported: fibre BCSDFs need curve primitives"},
    {"refused_prim_curves.json", ": primitives[0].type: primitive type \"curves\" is not supported: hair curves"},
    {"refused_prim_instances.json", ": primitives[0].type: primitive type \"instances\" is not supported"},
    {"refused_texture_blade.json",
     ": bsdfs[0].albedo.type: texture type \"blade\" is not supported: procedural aperture"},
    {"refused_camera_cubemap.json",
     ": camera.type: camera type \"cubemap\" is not supported: only pinhole and thinlens"},
};

Test(loader, bad_inputs)
{
    size_t n = sizeof bad_cases / sizeof bad_cases[0];
    cr_assert(n >= 25);
    for (size_t i = 0; i < n; i++) {
        char path[256], err[1024] = "";
        snprintf(path, sizeof path, "tests/data/bad/%s", bad_cases[i].file);
        struct scene *s = scene_load_model(path, err, sizeof err);
        cr_expect_null(s, "%s loaded but should fail", path);
        scene_model_free(s);
        cr_expect(strncmp(err, path, strlen(path)) == 0, "%s: message does not start with the file: %s", path, err);
        cr_expect(strstr(err, bad_cases[i].expect), "%s:\n  got      %s\n  expected ...%s...", path, err,
                  bad_cases[i].expect);
        cr_expect(!strchr(err, '\n'), "%s: message is not one line", path);
    }
}

Test(loader, textures_and_environment, .init = mk_tmp, .fini = rm_tmp)
{
    /* 2x2 image: top row red, green; bottom row blue, white */
    struct image *im = img_create(2, 2);
    img_add(im, 0, 0, v3(1, 0, 0));
    img_add(im, 1, 0, v3(0, 1, 0));
    img_add(im, 0, 1, v3(0, 0, 1));
    img_add(im, 1, 1, v3(1, 1, 1));
    char path[512], err[512];
    snprintf(path, sizeof path, "%s/t.exr", tmpdir);
    cr_assert(img_write_exr(im, 1.0, path, err, sizeof err), "%s", err);
    img_destroy(im);
    struct scene *s = load_tmp_scene(
        "{\"type\": \"quad\", \"bsdf\": {\"type\": \"lambert\", \"albedo\": \"t.exr\"}},"
        "{\"type\": \"quad\", \"bsdf\": {\"type\": \"mirror\", \"albedo\": {\"type\": \"bitmap\", \"file\": "
        "\"t.exr\"}}},"
        "{\"type\": \"infinite_sphere\", \"emission\": \"t.exr\", \"transform\": {\"rotation\": [0, 90, 0]}}");
    const struct texture *t = s->bsdfs[s->prims[0].bsdf].albedo_tex;
    cr_assert(t && t->w == 2 && t->h == 2);
    cr_assert(s->bsdfs[s->prims[1].bsdf].albedo_tex);
    /* v = 0 is the bottom row */
    cr_assert(near3(texture_lookup(t, 0.25, 0.25), v3(0, 0, 1), 1e-6));
    cr_assert(near3(texture_lookup(t, 0.75, 0.75), v3(0, 1, 0), 1e-6));
    cr_assert(near3(texture_lookup(t, -0.25, 1.25), v3(1, 1, 1), 1e-6)); /* wraps */
    cr_assert_eq(s->env_prim, 2);
    const struct prim *e = &s->prims[2];
    cr_assert(e->env_tex && e->emissive && e->bsdf == -1);
    vec3 x = mat4_vector(&e->env_to_world, v3(1, 0, 0)); /* Tungsten's +90 about y: +x to +z */
    cr_assert(near3(x, v3(0, 0, 1), 1e-12));
    mat4 id = mat4_mul(&e->env_to_world, &e->env_to_local);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            cr_assert(fabs(id.m[i][j] - (i == j)) < 1e-12);
    scene_model_free(s);
}

/* A hit reads the albedo texture at Tungsten's quad uv = (a, b), in either of the quad's two
 * triangles: rays straight down onto the unit quad in the xz-plane, whose corner (a, b) = (0, 0)
 * is (-0.5, 0, -0.5). The points are texel centres, where the bilinear lookup is the texel. */
Test(loader, textured_hits_read_the_texel_under_them, .init = mk_tmp, .fini = rm_tmp)
{
    struct image *im = img_create(2, 2); /* top row red, green; bottom row blue, white */
    img_add(im, 0, 0, v3(1, 0, 0));
    img_add(im, 1, 0, v3(0, 1, 0));
    img_add(im, 0, 1, v3(0, 0, 1));
    img_add(im, 1, 1, v3(1, 1, 1));
    char path[512], err[512] = "";
    snprintf(path, sizeof path, "%s/t.exr", tmpdir);
    cr_assert(img_write_exr(im, 1.0, path, err, sizeof err), "%s", err);
    img_destroy(im);
    scene_model_free(load_tmp_scene("{\"type\": \"quad\", \"bsdf\": {\"type\": \"lambert\", \"albedo\": \"t.exr\"}}"));
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    struct scene *s = scene_load(path, err, sizeof err);
    cr_assert(s, "%s", err);
    static const struct {
        double x, z;
        rgb texel;
    } cases[] = {
        {-0.25, 0.25, {1, 0, 0}},  /* (a, b) = uv = (0.25, 0.75): top left */
        {0.25, -0.25, {1, 1, 1}},  /* (0.75, 0.25): bottom right */
        {-0.25, -0.25, {0, 0, 1}}, /* (0.25, 0.25): bottom left */
        {0.25, 0.25, {0, 1, 0}},   /* (0.75, 0.75): top right */
    };
    for (int i = 0; i < 4; i++) {
        vec3 o = v3(cases[i].x, 1, cases[i].z), d = v3(0, -1, 0);
        struct hit h;
        cr_assert(accel_intersect(s->accel, o, d, 0, INFINITY, &h));
        struct vertex v;
        surface_from_hit(s, o, d, &h, &v);
        cr_assert(near3(v.p, v3(cases[i].x, 0, cases[i].z), 1e-6));
        cr_assert(near3(v.bc.albedo, cases[i].texel, 1e-6), "case %d: albedo (%g %g %g)", i, v.bc.albedo.x,
                  v.bc.albedo.y, v.bc.albedo.z);
    }
    scene_free(s);
}

/* Every prefix of a valid scene either loads or fails with a message; none crashes or leaks. */
Test(loader, truncated_scenes_fail_cleanly, .init = mk_tmp, .fini = rm_tmp)
{
    FILE *f = fopen("scenes/cornell-box/scene.json", "rb");
    cr_assert(f);
    static char text[1 << 16];
    size_t n = fread(text, 1, sizeof text, f);
    fclose(f);
    char path[512];
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    for (size_t k = 0; k < n; k += 7) {
        write_file("scene.json", text, k);
        char err[1024] = "";
        struct scene *s = scene_load_model(path, err, sizeof err);
        if (!s) cr_assert(strncmp(err, path, strlen(path)) == 0 && strstr(err, "malformed JSON"), "%zu: %s", k, err);
        scene_model_free(s);
    }
}
