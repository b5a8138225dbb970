/* Primitives of a Tungsten scene, turned into world-space geometry once.
 * Conventions checked against Tungsten's src/core/primitives:
 * - quad (Quad.cpp): unit square in local XZ centred at the origin, edge0 = M (1,0,0),
 *   edge1 = M (0,0,1), base = M 0 - (edge0 + edge1)/2, front normal = edge1 x edge0 (+y locally);
 * - cube (Cube.cpp): unit cube centred at the origin, analytic in Tungsten with normals always
 *   pointing outward, whatever the sign of det M;
 * - sphere (Sphere.cpp): centre M 0, radius = largest column length of M (unit radius locally);
 * - mesh (TriangleMesh.cpp): front side = counter-clockwise winding of the world-space triangle;
 * - disk, cylinder (Disk.cpp, Cylinder.cpp): fine meshes, see scene_shapes.c;
 * - infinite_sphere_cap (InfiniteSphereCap.cpp): constant radiance from the directions within
 *   cap_angle (degrees, default 10) of normalize(M (0,1,0));
 * - emitters emit on the front side only; "power" becomes radiance through
 *   powerToRadianceFactor: 1/(pi area) for finite shapes, 1/(4 pi) for the infinite sphere,
 *   1/(2 pi (1 - cos cap_angle)) for the cap. */
#include "base/util.h"
#include "io/mesh_io.h"
#include "scene/scene_load_internal.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static vec3 col(const mat4 *m, int j) { return v3(m->m[0][j], m->m[1][j], m->m[2][j]); }

static double det3(const mat4 *m) { return vdot(col(m, 0), vcross(col(m, 1), col(m, 2))); }

static void alloc_tris(struct prim *p, int nverts, int ntris, bool uv)
{
    p->nverts = nverts;
    p->ntris = ntris;
    p->p = xcalloc(nverts ? nverts : 1, sizeof(vec3));
    p->tri = xcalloc(ntris ? (size_t)ntris * 3 : 1, sizeof(int));
    p->uv = uv ? xcalloc(nverts ? (size_t)nverts * 2 : 1, sizeof(double)) : NULL;
}

static double tri_area2(const struct prim *p, int t)
{
    const int *i = p->tri + 3 * (size_t)t;
    return vlen(vcross(vsub(p->p[i[1]], p->p[i[0]]), vsub(p->p[i[2]], p->p[i[0]])));
}

static void build_quad(struct prim *p, const mat4 *m)
{
    vec3 e0 = col(m, 0), e1 = col(m, 2);
    vec3 base = vsub(col(m, 3), vscale(vadd(e0, e1), 0.5));
    vec3 n = vcross(e1, e0);
    p->kind = PRIM_QUAD;
    p->quad_base = base;
    p->quad_edge0 = e0;
    p->quad_edge1 = e1;
    p->area = vlen(n);
    p->quad_normal = p->area > 0 ? vscale(n, 1 / p->area) : v3(0, 0, 0);
    /* Corners in (a, b) order (0,0) (0,1) (1,1) (1,0): (p1-p0) x (p2-p0) = e1 x e0, the front normal.
     * uv = (a, b): u along edge0, v along edge1 from the base corner, as Tungsten 0.2.2 renders
     * (checked against the conformance scene quad-uv-texture; a Quad.cpp in the public repository
     * writes v = 1 - b, which that render contradicts). */
    static const double ab[4][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    static const int tris[6] = {0, 1, 2, 0, 2, 3};
    alloc_tris(p, 4, 2, true);
    for (int i = 0; i < 4; i++) {
        p->p[i] = vadd(base, vadd(vscale(e0, ab[i][0]), vscale(e1, ab[i][1])));
        p->uv[2 * i] = ab[i][0];
        p->uv[2 * i + 1] = ab[i][1];
    }
    memcpy(p->tri, tris, sizeof tris);
}

static void build_cube(struct prim *p, const mat4 *m)
{
    p->kind = PRIM_MESH;
    p->cube_tangents = true;
    alloc_tris(p, 24, 12, true);
    bool flip = det3(m) < 0; /* keep the outward orientation Tungsten's analytic cube has */
    int v = 0, t = 0;
    for (int dim = 0; dim < 3; dim++)
        for (int side = -1; side <= 1; side += 2) {
            int a = (dim + 1) % 3, b = (dim + 2) % 3;
            /* Local corners walk counter-clockwise seen from outside: with (a, b, dim) cyclic,
             * ea x eb = e_dim, so ordering by (+a, +b) winds along +dim; mirror it for the - side. */
            static const double q[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
            for (int k = 0; k < 4; k++) {
                double l[3];
                l[dim] = 0.5 * side;
                l[a] = q[k][0];
                l[b] = q[k][1];
                p->p[v + k] = mat4_point(m, v3(l[0], l[1], l[2]));
                p->uv[2 * (v + k)] = l[a] + 0.5;
                p->uv[2 * (v + k) + 1] = l[b] + 0.5;
            }
            int order[6] = {0, 1, 2, 0, 2, 3};
            bool rev = (side < 0) != flip;
            for (int k = 0; k < 6; k += 3) {
                p->tri[3 * t] = v + order[k];
                p->tri[3 * t + 1] = v + order[rev ? k + 2 : k + 1];
                p->tri[3 * t + 2] = v + order[rev ? k + 1 : k + 2];
                t++;
            }
            v += 4;
        }
    p->area = 0;
    for (int i = 0; i < p->ntris; i++)
        p->area += 0.5 * tri_area2(p, i);
}

static void build_sphere(struct prim *p, const mat4 *m)
{
    p->kind = PRIM_SPHERE;
    p->center = col(m, 3);
    p->radius = fmax(vlen(col(m, 0)), fmax(vlen(col(m, 1)), vlen(col(m, 2))));
    /* Tungsten's rotation part (extractRotation): the columns normalised; its inverse is taken as the
     * transpose, so uv come from dot products with them. */
    for (int j = 0; j < 3; j++) {
        vec3 c = col(m, j);
        double l = vlen(c);
        p->sphere_axis[j] = l > 0 ? vscale(c, 1 / l) : v3(j == 0, j == 1, j == 2);
    }
    p->area = 4 * M_PI * p->radius * p->radius;
}

static bool build_mesh(struct loader *L, const cJSON *j, const char *path, struct prim *p, const mat4 *m)
{
    struct jctx *c = &L->c;
    const char *file = NULL;
    bool smooth = false;
    if (!jget_string(c, j, path, "file", true, &file) || !jget_bool(c, j, path, "smooth", false, &smooth)) return false;
    if (cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(j, "recompute_normals")))
        jwarn(c, path, "recompute_normals is not supported; using the file's normals");
    char fp[JPATH_MAX], full[8192], err[1024];
    jpath_key(fp, path, "file");
    if (!loader_resource(L, file, full, sizeof full)) return jfail(c, fp, "path too long");
    struct raw_mesh r;
    if (!mesh_load(full, &r, err, sizeof err)) return jfail(c, fp, "%s: %s", full, err);
    p->kind = PRIM_MESH;
    alloc_tris(p, r.nverts, r.ntris, r.uv != NULL);
    for (int i = 0; i < r.nverts; i++)
        p->p[i] = mat4_point(m, r.p[i]);
    if (r.uv) memcpy(p->uv, r.uv, (size_t)r.nverts * 2 * sizeof(double));
    /* Keep only triangles with a usable area; a zero cross product has no normal to shade with. */
    int kept = 0;
    p->area = 0;
    for (int t = 0; t < r.ntris; t++) {
        memcpy(p->tri + 3 * (size_t)kept, r.tri + 3 * (size_t)t, 3 * sizeof(int));
        double a2 = tri_area2(p, kept);
        vec3 e1 = vsub(p->p[r.tri[3 * t + 1]], p->p[r.tri[3 * t]]);
        vec3 e2 = vsub(p->p[r.tri[3 * t + 2]], p->p[r.tri[3 * t]]);
        if (!(a2 > 1e-12 * fmax(vlen2(e1), vlen2(e2)))) continue;
        p->area += 0.5 * a2;
        kept++;
    }
    if (kept < r.ntris) jwarn(c, fp, "dropped %d degenerate triangle(s) of %d", r.ntris - kept, r.ntris);
    p->ntris = kept;
    if (smooth && !r.n) jwarn(c, fp, "smooth shading needs vertex normals, the mesh has none: shading flat");
    if (smooth && r.n) {
        /* Shading normals follow the winding's front side; a mirroring transform flips the
         * winding normal, so flip them with it. */
        double sign = det3(m) < 0 ? -1 : 1;
        p->n = xmalloc((size_t)(r.nverts ? r.nverts : 1) * sizeof(vec3));
        for (int i = 0; i < r.nverts && p->n; i++) {
            vec3 n = mat4_normal(m, r.n[i]);
            if (!(vlen2(n) > 0) || !vfinite(n)) {
                jwarn(c, fp, "vertex %d has a zero normal: shading the mesh flat", i);
                free(p->n);
                p->n = NULL;
                break;
            }
            p->n[i] = vscale(vnorm(n), sign);
        }
    }
    raw_mesh_free(&r);
    return true;
}

static bool build_infinite_sphere(struct loader *L, const char *path, struct prim *p, const mat4 *m)
{
    p->kind = PRIM_INFINITE_SPHERE;
    p->bsdf = -1;
    p->cap_cos = -1;
    /* Tungsten keeps only the rotation of the transform (InfiniteSphere::prepareForRender). */
    mat4 r = mat4_identity();
    for (int j = 0; j < 3; j++) {
        vec3 c = col(m, j);
        double l = vlen(c);
        if (!(l > 0)) return jfail(&L->c, path, "degenerate transform for infinite_sphere");
        c = vscale(c, 1 / l);
        r.m[0][j] = c.x;
        r.m[1][j] = c.y;
        r.m[2][j] = c.z;
    }
    p->env_to_world = r;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            p->env_to_local.m[i][j] = r.m[j][i];
    for (int i = 0; i < 4; i++)
        p->env_to_local.m[i][3] = p->env_to_local.m[3][i] = i == 3;
    return true;
}

static bool build_sphere_cap(struct loader *L, const cJSON *j, const char *path, struct prim *p, const mat4 *m)
{
    struct jctx *c = &L->c;
    if (cJSON_GetObjectItemCaseSensitive(j, "skydome")) {
        char sp[JPATH_MAX];
        jpath_key(sp, path, "skydome");
        return jfail(c, sp, "a skydome pivot is not supported (orient the cap with its own transform)");
    }
    double deg = 10;
    if (!jget_number(c, j, path, "cap_angle", false, &deg)) return false;
    if (!(deg > 0 && deg <= 180)) {
        char ap[JPATH_MAX];
        jpath_key(ap, path, "cap_angle");
        return jfail(c, ap, "expected an angle in degrees with 0 < cap_angle <= 180");
    }
    vec3 up = col(m, 1);
    if (!(vlen(up) > 0)) return jfail(c, path, "degenerate transform for infinite_sphere_cap");
    if (!build_infinite_sphere(L, path, p, m)) return false;
    p->env_is_cap = true;
    p->cap_dir = vnorm(up);
    p->cap_cos = cos(deg * (M_PI / 180));
    return true;
}

static bool colour(struct loader *L, const cJSON *v, const char *path, rgb *out)
{
    if (!jval_vec3(&L->c, v, path, out)) return false;
    if (out->x < 0 || out->y < 0 || out->z < 0) return jfail(&L->c, path, "expected non-negative values");
    return true;
}

/* emission / power, after the geometry (power needs the area). */
static bool load_emission(struct loader *L, const cJSON *j, const char *path, struct prim *p)
{
    const cJSON *e = cJSON_GetObjectItemCaseSensitive(j, "emission");
    const cJSON *w = cJSON_GetObjectItemCaseSensitive(j, "power");
    bool env = p->kind == PRIM_INFINITE_SPHERE, cap = env && p->env_is_cap;
    char ep[JPATH_MAX], wp[JPATH_MAX];
    jpath_key(ep, path, "emission");
    jpath_key(wp, path, "power");
    if (w) {
        /* Tungsten: power wins over emission (Primitive::prepareForRender). */
        if (cJSON_IsString(w) || cJSON_IsObject(w))
            return jfail(&L->c, wp, "textured power is not supported (expected a number or an array of 3 numbers)");
        rgb pw;
        if (!colour(L, w, wp, &pw)) return false;
        if (!env && !(p->area > 0) && !vzero(pw)) return jfail(&L->c, path, "zero-area emitter");
        p->emission = cap         ? vscale(pw, 1 / (2 * M_PI * (1 - p->cap_cos)))
                      : env       ? vscale(pw, 1 / (4 * M_PI))
                      : vzero(pw) ? pw
                                  : vscale(pw, 1 / (M_PI * p->area));
    } else if (e && (cJSON_IsString(e) || cJSON_IsObject(e))) {
        if (!env || cap)
            return jfail(&L->c, ep,
                         "textured emission is only supported on infinite_sphere "
                         "(expected a number or an array of 3 numbers)");
        if (!load_texture_value(L, e, ep, &p->env_tex)) return false;
        p->emission = v3s(1);
        /* textures: the environment's sampling reads texels, so only a bitmap (or a constant) */
        if (p->env_tex->kind != TEX_BITMAP) {
            bool constant = p->env_tex->kind == TEX_CONSTANT;
            p->emission = p->env_tex->on;
            texture_free(p->env_tex);
            p->env_tex = NULL;
            if (!constant)
                return jfail(&L->c, ep, "an infinite_sphere's emission texture must be a bitmap (or a constant)");
        }
    } else if (e) {
        if (!colour(L, e, ep, &p->emission)) return false;
    }
    p->emissive = !vzero(p->emission);
    if (p->emissive && !env && !(p->area > 0)) return jfail(&L->c, path, "zero-area emitter");
    return true;
}

/* Tungsten 0.2.2 applies a disk's cone_angle only where a camera path hits the disk and in its
 * path tracer's light sampling; emitter paths leave over the whole cosine hemisphere
 * (Disk::sampleDirection, evalDirectionalEmission: "TODO: Cone angle"), and its BDPT reference is
 * lit as if there were no cone. The harness emits over the whole front hemisphere, so a cone
 * narrower than 90 degrees is accepted with a warning. */
static bool disk_cone(struct loader *L, const cJSON *j, const char *path)
{
    double deg = 90;
    if (!jget_number(&L->c, j, path, "cone_angle", false, &deg)) return false;
    char cp[JPATH_MAX];
    jpath_key(cp, path, "cone_angle");
    if (!(deg > 0 && deg <= 90)) return jfail(&L->c, cp, "expected an angle in degrees with 0 < cone_angle <= 90");
    if (deg < 90)
        jwarn(&L->c, cp,
              "the disk emits over its whole front hemisphere (as Tungsten 0.2.2's emitter paths "
              "and its BDPT reference do); the cone is not applied");
    return true;
}

static bool load_prim(struct loader *L, const cJSON *j, int i)
{
    struct jctx *c = &L->c;
    struct prim *p = &L->s->prims[i];
    char path[JPATH_MAX];
    jpath_idx(path, "primitives", i);
    if (!cJSON_IsObject(j)) return jfail(c, path, "expected a primitive object");
    const char *type = NULL;
    if (!jget_string(c, j, path, "type", true, &type)) return false;
    static const char *const media_keys[] = {"int_medium", "ext_medium"};
    for (int k = 0; k < 2; k++)
        if (cJSON_GetObjectItemCaseSensitive(j, media_keys[k])) {
            char p2[JPATH_MAX];
            jpath_key(p2, path, media_keys[k]);
            return jfail(c, p2, "participating media are not supported");
        }
    if (cJSON_GetObjectItemCaseSensitive(j, "bump") || cJSON_GetObjectItemCaseSensitive(j, "bump_strength"))
        jwarn(c, path, "bump mapping on a primitive is not read (Tungsten reads `bump` on a bsdf); ignored");
    mat4 m = mat4_identity();
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(j, "transform");
    char tp[JPATH_MAX];
    jpath_key(tp, path, "transform");
    if (t && !jval_transform(c, t, tp, &m)) return false;
    bool cap = strcmp(type, "infinite_sphere_cap") == 0, env = cap || strcmp(type, "infinite_sphere") == 0;
    if (!env && !L->bsdf->load_ref(L, j, path, i, &p->bsdf)) return false;
    if (strcmp(type, "quad") == 0)
        build_quad(p, &m);
    else if (strcmp(type, "cube") == 0)
        build_cube(p, &m);
    else if (strcmp(type, "sphere") == 0)
        build_sphere(p, &m);
    else if (strcmp(type, "mesh") == 0) {
        if (!build_mesh(L, j, path, p, &m)) return false;
    } else if (strcmp(type, "disk") == 0) {
        if (!disk_cone(L, j, path) || !build_disk(L, path, p, &m)) return false;
    } else if (strcmp(type, "cylinder") == 0) {
        bool capped = true;
        if (!jget_bool(c, j, path, "capped", false, &capped) || !build_cylinder(L, path, p, &m, capped)) return false;
    } else if (env) {
        if (L->s->env_prim >= 0)
            return jfail(c, path, "only one infinite_sphere is supported (an infinite_sphere_cap counts as one)");
        if (!(cap ? build_sphere_cap(L, j, path, p, &m) : build_infinite_sphere(L, path, p, &m))) return false;
        L->s->env_prim = i;
        if (cJSON_IsFalse(cJSON_GetObjectItemCaseSensitive(j, "sample")))
            jwarn(c, path, "\"sample\": false is ignored; the environment is always sampled");
    } else {
        char p2[JPATH_MAX];
        jpath_key(p2, path, "type");
        const char *why = refused_feature(REFUSED_PRIMITIVE, type);
        if (why) return jfail(c, p2, "primitive type \"%s\" is not supported: %s", type, why);
        return jfail(c, p2,
                     "unknown primitive type \"%s\" (supported: quad cube sphere mesh disk cylinder infinite_sphere "
                     "infinite_sphere_cap)",
                     type);
    }
    return load_emission(L, j, path, p);
}

bool load_primitives(struct loader *L, const cJSON *arr)
{
    int i = 0;
    for (const cJSON *j = arr->child; j; j = j->next, i++)
        if (!load_prim(L, j, i)) return false;
    return true;
}
