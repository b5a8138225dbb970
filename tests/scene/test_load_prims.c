/* Loader tests of disk, cylinder and infinite_sphere_cap: the geometry Tungsten builds (frames,
 * radius, height, front sides, uv), power -> radiance, and one error line per unsupported input. */
#include <criterion/criterion.h>

#include "bsdf/bsdf_json.h"
#include "scene/scene.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "prims-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

/* A scene of one primitive (the JSON object text) in front of a default camera. */
static struct scene *load_prim(const char *prim, char *err, size_t errlen)
{
    char path[512], json[4096];
    snprintf(path, sizeof path, "%s/scene.json", tmpdir);
    snprintf(json, sizeof json,
             "{\"bsdfs\": [{\"name\": \"w\", \"type\": \"lambert\", \"albedo\": 0.5}],\n"
             " \"primitives\": [%s],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 45, \"resolution\": [8, 8],\n"
             "   \"transform\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             prim);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fputs(json, f);
    fclose(f);
    err[0] = 0;
    return scene_load_model(path, err, errlen);
}

static struct scene *load_ok(const char *prim)
{
    char err[1024];
    struct scene *s = load_prim(prim, err, sizeof err);
    cr_assert(s, "should load: %s", err);
    return s;
}

static vec3 tri_cross(const struct prim *p, int t)
{
    const int *i = p->tri + 3 * t;
    return vcross(vsub(p->p[i[1]], p->p[i[0]]), vsub(p->p[i[2]], p->p[i[0]]));
}

Test(load_prims, disk_frame_radius_and_front, .init = mk_tmp, .fini = rm_tmp)
{
    /* rotation [0, 0, 180] turns local +y to -y: a disk facing down, radius = the largest of the
     * x and z scales */
    struct scene *s = load_ok("{\"type\": \"disk\", \"bsdf\": \"w\", \"emission\": 2, \"transform\": "
                              "{\"position\": [1, 2, 3], \"scale\": [0.5, 7, 0.3], \"rotation\": [0, 0, 180]}}");
    const struct prim *p = &s->prims[0];
    cr_assert_eq(p->kind, PRIM_MESH);
    double amax = 0, rmin = 1e9, rmax = 0, area = 0;
    for (int t = 0; t < p->ntris; t++) {
        vec3 c = tri_cross(p, t);
        cr_assert(vdot(vnorm(c), v3(0, -1, 0)) > 1 - 1e-12, "triangle %d faces away from -y", t);
        area += 0.5 * vlen(c);
        amax = fmax(amax, 0.5 * vlen(c));
    }
    for (int i = 0; i < p->nverts; i++) {
        vec3 d = vsub(p->p[i], v3(1, 2, 3));
        cr_assert(fabs(d.y) < 1e-12);
        double r = vlen(d);
        if (r > 1e-9) rmin = fmin(rmin, r), rmax = fmax(rmax, r);
        cr_assert(p->uv[2 * i + 1] >= 0 && p->uv[2 * i + 1] <= 1);
        if (r > 1e-9) cr_assert(fabs(p->uv[2 * i + 1] - 1) < 1e-12, "rim v = r / radius = 1");
    }
    cr_assert(fabs(rmin - 0.5) < 1e-12 && fabs(rmax - 0.5) < 1e-12, "rim radius %g..%g", rmin, rmax);
    cr_assert(fabs(area / (M_PI * 0.25) - 1) < 3e-5, "area %g vs pi r^2 %g", area, M_PI * 0.25);
    cr_assert(fabs(p->area - area) < 1e-12);
    cr_assert(p->emissive && vlen(vsub(p->emission, v3s(2))) == 0);
    scene_model_free(s);
}

Test(load_prims, disk_uv_follows_tungsten_frame, .init = mk_tmp, .fini = rm_tmp)
{
    /* identity: n = +y, TangentFrame(+y): tangent (1,0,0) -> bitangent = n x t = (0,0,-1),
     * tangent = b x n = (1,0,0); u = atan2(d.t, d.b) / 2pi + 0.5 */
    struct scene *s = load_ok("{\"type\": \"disk\", \"bsdf\": \"w\"}");
    const struct prim *p = &s->prims[0];
    for (int i = 0; i < p->nverts; i++) {
        vec3 d = p->p[i];
        if (vlen(d) < 1e-9) continue;
        double u = atan2(d.x, -d.z) / (2 * M_PI) + 0.5;
        double du = fabs(u - p->uv[2 * i]);
        cr_assert(du < 1e-9 || fabs(du - 1) < 1e-9, "vertex %d: u %g, expected %g", i, p->uv[2 * i], u);
    }
    scene_model_free(s);
}

Test(load_prims, cylinder_tungsten_geometry, .init = mk_tmp, .fini = rm_tmp)
{
    /* radius 0.5 max(sx, sz), height sy centred on the position, axis along M e_y */
    struct scene *s = load_ok("{\"type\": \"cylinder\", \"bsdf\": \"w\", \"transform\": "
                              "{\"position\": [0, 1, 0], \"scale\": [0.4, 2, 0.2], \"rotation\": [90, 0, 0]}}");
    const struct prim *p = &s->prims[0];
    cr_assert_eq(p->kind, PRIM_MESH);
    cr_assert(p->n != NULL);
    /* rotation [90, 0, 0] (Rx 90) takes local +y to +z */
    vec3 axis = v3(0, 0, 1), c = v3(0, 1, 0);
    double R = 0.2, H = 1.0, area = 0;
    for (int i = 0; i < p->nverts; i++) {
        vec3 d = vsub(p->p[i], c);
        double h = vdot(d, axis), r = vlen(vsub(d, vscale(axis, h)));
        cr_assert(fabs(h) <= H + 1e-12 && r <= R + 1e-12);
        cr_assert(fabs(fabs(h) - H) < 1e-12 || fabs(r - R) < 1e-12, "vertex %d off the surface", i);
    }
    for (int t = 0; t < p->ntris; t++) {
        vec3 x = tri_cross(p, t);
        const int *v = p->tri + 3 * t;
        vec3 centroid = vscale(vadd(vadd(p->p[v[0]], p->p[v[1]]), p->p[v[2]]), 1.0 / 3);
        vec3 d = vsub(centroid, c);
        double h = vdot(d, axis);
        vec3 out = fabs(fabs(h) - H) < 1e-12 ? vscale(axis, h > 0 ? 1 : -1) : vsub(d, vscale(axis, h));
        cr_assert(vdot(x, out) > 0, "triangle %d winds inward", t);
        cr_assert(vdot(p->n[v[0]], out) > 0);
        area += 0.5 * vlen(x);
    }
    double exact = 2 * M_PI * R * R + 2 * M_PI * R * 2 * H;
    cr_assert(fabs(area / exact - 1) < 3e-5, "area %g vs %g", area, exact);
    scene_model_free(s);

    s = load_ok("{\"type\": \"cylinder\", \"bsdf\": \"w\", \"capped\": false}");
    exact = 2 * M_PI * 0.5 * 1.0;
    cr_assert(fabs(s->prims[0].area / exact - 1) < 1e-5, "uncapped area %g vs %g", s->prims[0].area, exact);
    scene_model_free(s);
}

Test(load_prims, cap_direction_angle_and_power, .init = mk_tmp, .fini = rm_tmp)
{
    /* rotation [90, 0, 0] takes local +y to +z; power P -> radiance P / (2 pi (1 - cos angle)) */
    struct scene *s = load_ok("{\"type\": \"infinite_sphere_cap\", \"cap_angle\": 30, \"power\": [3, 2, 1], "
                              "\"transform\": {\"rotation\": [90, 0, 0]}}");
    const struct prim *p = &s->prims[0];
    cr_assert_eq(p->kind, PRIM_INFINITE_SPHERE);
    cr_assert(p->env_is_cap);
    cr_assert(vlen(vsub(p->cap_dir, v3(0, 0, 1))) < 1e-12);
    cr_assert(fabs(p->cap_cos - cos(M_PI / 6)) < 1e-15);
    double f = 1 / (2 * M_PI * (1 - cos(M_PI / 6)));
    cr_assert(vlen(vsub(p->emission, v3(3 * f, 2 * f, f))) < 1e-12);
    cr_assert_eq(s->env_prim, 0);
    scene_model_free(s);
    s = load_ok("{\"type\": \"infinite_sphere_cap\", \"emission\": 5}");
    cr_assert(fabs(s->prims[0].cap_cos - cos(M_PI / 18)) < 1e-15, "default cap_angle 10");
    cr_assert(vlen(vsub(s->prims[0].cap_dir, v3(0, 1, 0))) < 1e-12);
    scene_model_free(s);
}

struct bad_prim {
    const char *prim, *expect;
};

Test(load_prims, errors_name_the_json_path, .init = mk_tmp, .fini = rm_tmp)
{
    static const struct bad_prim cases[] = {
        {"{\"type\": \"disk\", \"cone_angle\": 0}",
         ": primitives[0].cone_angle: expected an angle in degrees with 0 < cone_angle <= 90"},
        {"{\"type\": \"disk\", \"cone_angle\": 120}",
         ": primitives[0].cone_angle: expected an angle in degrees with 0 < cone_angle <= 90"},
        {"{\"type\": \"disk\", \"cone_angle\": \"wide\"}", ": primitives[0].cone_angle: "},
        {"{\"type\": \"disk\", \"transform\": {\"scale\": [0, 1, 0]}}",
         ": primitives[0]: degenerate transform for disk"},
        {"{\"type\": \"cylinder\", \"capped\": 1}", ": primitives[0].capped: "},
        {"{\"type\": \"cylinder\", \"transform\": {\"scale\": [1, 0, 1]}}",
         ": primitives[0]: degenerate transform for cylinder"},
        {"{\"type\": \"infinite_sphere_cap\", \"cap_angle\": 0}",
         ": primitives[0].cap_angle: expected an angle in degrees with 0 < cap_angle <= 180"},
        {"{\"type\": \"infinite_sphere_cap\", \"cap_angle\": 181}",
         ": primitives[0].cap_angle: expected an angle in degrees with 0 < cap_angle <= 180"},
        {"{\"type\": \"infinite_sphere_cap\", \"skydome\": \"sky\"}",
         ": primitives[0].skydome: a skydome pivot is not supported"},
        {"{\"type\": \"infinite_sphere_cap\", \"emission\": \"sky.png\"}",
         ": primitives[0].emission: textured emission is only supported on infinite_sphere"},
        {"{\"type\": \"infinite_sphere_cap\", \"emission\": 1}, {\"type\": \"infinite_sphere\", \"emission\": 1}",
         ": primitives[1]: only one infinite_sphere is supported (an infinite_sphere_cap counts as one)"},
        {"{\"type\": \"torus\"}",
         ": primitives[0].type: unknown primitive type \"torus\" (supported: quad cube sphere mesh disk cylinder "
         "infinite_sphere infinite_sphere_cap)"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char err[1024];
        struct scene *s = load_prim(cases[i].prim, err, sizeof err);
        cr_expect_null(s, "%s should not load", cases[i].prim);
        if (s) scene_model_free(s);
        cr_expect(strstr(err, cases[i].expect) != NULL, "%s:\n  got      %s\n  expected ...%s...", cases[i].prim, err,
                  cases[i].expect);
        cr_expect(strchr(err, '\n') == NULL, "one line: %s", err);
    }
}
