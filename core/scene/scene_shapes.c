/* Tungsten's analytic disk and cylinder, loaded as fine triangle meshes (PRIM_MESH) so that Embree's
 * triangles, the mesh shading path (interpolated normals and uv) and the mesh emitter's sampling
 * with its exact inverse serve them unchanged. Facts from Tungsten's Disk.cpp / Cylinder.cpp:
 * - disk: centre M 0, normal normalize(M (0,1,0)) (front side, the emitting one), radius =
 *   max(|M e_x|, |M e_z|): always a circle perpendicular to the normal; uv = (atan2(y, x) / 2pi
 *   + 0.5, r / radius) with x, y the offsets along Tungsten's TangentFrame(n) bitangent and tangent;
 * - cylinder: axis along M e_y through M 0, height |M e_y|, radius 0.5 max(|M e_x|, |M e_z|)
 *   (unit diameter locally), normals outward; side uv = (atan2(z, x) / 2pi + 0.5 of the local
 *   normal, height fraction from the bottom), cap uv = local (x, z) / radius * 0.5 + 0.5;
 *   `capped` (default true) closes both ends.
 * Geometric error of SHAPE_SEGMENTS = 512 segments (vertices on the true circle): distance to
 * the true surface <= radius (1 - cos(pi/512)) = 1.9e-5 radius; area short by (2pi/512)^2/6 =
 * 2.5e-5 (disk) and (pi/512)^2/6 = 6.3e-6 (cylinder side) relatively; shading normals and uv
 * are interpolated from exact vertex values (cylinder side: normals within pi/512 rad of the
 * exact one before normalisation). */
#include "base/util.h"
#include "scene/scene_load_internal.h"
#include <stdlib.h>

#define SHAPE_SEGMENTS 512

static vec3 column(const mat4 *m, int j) { return v3(m->m[0][j], m->m[1][j], m->m[2][j]); }

struct mesh_builder {
    struct prim *p;
    int v, t;
};

static int add_vertex(struct mesh_builder *b, vec3 pos, vec3 n, double u, double v)
{
    struct prim *p = b->p;
    p->p[b->v] = pos;
    if (p->n) p->n[b->v] = n;
    p->uv[2 * b->v] = u;
    p->uv[2 * b->v + 1] = v;
    return b->v++;
}

/* A triangle wound counter-clockwise seen from the side `front` points to (the front side). i0
 * stays first: callers put there the vertex whose two edges are closest to perpendicular, since
 * the mesh emitter inverts a point to barycentrics along the edges from the first vertex, which
 * loses precision when those edges are nearly parallel (thin triangles). */
static void add_tri(struct mesh_builder *b, int i0, int i1, int i2, vec3 front)
{
    struct prim *p = b->p;
    vec3 c = vcross(vsub(p->p[i1], p->p[i0]), vsub(p->p[i2], p->p[i0]));
    bool flip = vdot(c, front) < 0;
    int *t = p->tri + 3 * (size_t)b->t++;
    t[0] = i0;
    t[1] = flip ? i2 : i1;
    t[2] = flip ? i1 : i2;
}

static void alloc_shape(struct prim *p, int nverts, int ntris, bool normals)
{
    p->kind = PRIM_MESH;
    p->nverts = nverts;
    p->ntris = ntris;
    p->p = xcalloc((size_t)nverts, sizeof(vec3));
    p->n = normals ? xcalloc((size_t)nverts, sizeof(vec3)) : NULL;
    p->uv = xcalloc((size_t)nverts * 2, sizeof(double));
    p->tri = xcalloc((size_t)ntris * 3, sizeof(int));
}

static void finish_area(struct prim *p)
{
    p->area = 0;
    for (int i = 0; i < p->ntris; i++) {
        const int *t = p->tri + 3 * (size_t)i;
        p->area += 0.5 * vlen(vcross(vsub(p->p[t[1]], p->p[t[0]]), vsub(p->p[t[2]], p->p[t[0]])));
    }
}

/* Tungsten's TangentFrame(n): the seed axis is y when |n.x| > |n.y|, else x. */
static void tungsten_frame(vec3 n, vec3 *tangent, vec3 *bitangent)
{
    vec3 seed = fabs(n.x) > fabs(n.y) ? v3(0, 1, 0) : v3(1, 0, 0);
    *bitangent = vnorm(vcross(n, seed));
    *tangent = vcross(*bitangent, n);
}

bool build_disk(struct loader *L, const char *path, struct prim *p, const mat4 *m)
{
    vec3 c = column(m, 3), ny = column(m, 1);
    double r = fmax(vlen(column(m, 0)), vlen(column(m, 2)));
    if (!(vlen(ny) > 0) || !(r > 0) || !isfinite(r)) return jfail(&L->c, path, "degenerate transform for disk");
    vec3 n = vnorm(ny), tg, bt;
    tungsten_frame(n, &tg, &bt);
    const int N = SHAPE_SEGMENTS;
    /* ring 0..N (N repeats 0 with u = 1), then one centre per triangle with the segment's mid u */
    alloc_shape(p, 2 * N + 1, N, false);
    struct mesh_builder b = {p, 0, 0};
    for (int k = 0; k <= N; k++) {
        double s, co;
        sincos_turns((double)k / N - 0.5, &s, &co); /* angle from -pi: u = angle / 2pi + 0.5 */
        add_vertex(&b, vadd(c, vadd(vscale(bt, r * co), vscale(tg, r * s))), n, (double)k / N, 1.0);
    }
    for (int k = 0; k < N; k++) {
        int ic = add_vertex(&b, c, n, (k + 0.5) / N, 0.0);
        add_tri(&b, k, k + 1, ic, n);
    }
    finish_area(p);
    return true;
}

bool build_cylinder(struct loader *L, const char *path, struct prim *p, const mat4 *m, bool capped)
{
    vec3 a[3];
    double len[3];
    for (int j = 0; j < 3; j++) {
        len[j] = vlen(column(m, j));
        if (!(len[j] > 0) || !isfinite(len[j])) return jfail(&L->c, path, "degenerate transform for cylinder");
        a[j] = vscale(column(m, j), 1 / len[j]);
    }
    vec3 pos = column(m, 3);
    double R = 0.5 * fmax(len[0], len[2]), H = 0.5 * len[1];
    const int N = SHAPE_SEGMENTS;
    int nv = 2 * (N + 1) + (capped ? 2 * (N + 2) : 0), nt = 2 * N + (capped ? 2 * N : 0);
    alloc_shape(p, nv, nt, true);
    struct mesh_builder b = {p, 0, 0};
    int side0 = b.v;
    for (int k = 0; k <= N; k++) {
        double s, co;
        sincos_turns((double)k / N - 0.5, &s, &co);
        vec3 out = vadd(vscale(a[0], co), vscale(a[2], s)), rim = vmad(pos, out, R);
        add_vertex(&b, vmad(rim, a[1], -H), out, (double)k / N, 0.0);
        add_vertex(&b, vmad(rim, a[1], H), out, (double)k / N, 1.0);
    }
    for (int k = 0; k < N; k++) {
        int b0 = side0 + 2 * k, t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
        double s, co;
        sincos_turns((k + 0.5) / N - 0.5, &s, &co);
        vec3 out = vadd(vscale(a[0], co), vscale(a[2], s));
        add_tri(&b, b1, t1, b0, out); /* right angles at b1 and t0 */
        add_tri(&b, t0, b0, t1, out);
    }
    for (int side = -1; capped && side <= 1; side += 2) {
        vec3 nc = vscale(a[1], side), cc = vmad(pos, a[1], side * H);
        int ic = add_vertex(&b, cc, nc, 0.5, 0.5), ring = b.v;
        for (int k = 0; k <= N; k++) {
            double s, co;
            sincos_turns((double)k / N - 0.5, &s, &co);
            add_vertex(&b, vadd(cc, vadd(vscale(a[0], R * co), vscale(a[2], R * s))), nc, 0.5 * co + 0.5,
                       0.5 * s + 0.5);
        }
        for (int k = 0; k < N; k++)
            add_tri(&b, ring + k, ring + k + 1, ic, nc);
    }
    ASSERT(b.v == nv && b.t == nt);
    finish_area(p);
    return true;
}
