/* In-memory test scenes for emitters and camera (see emit_fixture.h). */
#include "support/emit_fixture.h"
#include "bsdf/bsdf_json.h"
#include "scene/scene.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

void fx_init(struct emit_fixture *f, enum fx_env env, bool rotate_env)
{
    memset(f, 0, sizeof *f);
    struct prim *q = &f->prims[FX_QUAD];
    q->kind = PRIM_QUAD;
    q->quad_base = v3(-1, 2, -0.5);
    q->quad_edge0 = v3(2, 0, 0);
    q->quad_edge1 = v3(0.3, 0, 1); /* a sheared parallelogram */
    q->quad_normal = vnorm(vcross(q->quad_edge1, q->quad_edge0));
    q->area = vlen(vcross(q->quad_edge0, q->quad_edge1));
    q->emission = v3(1, 1, 1);
    q->emissive = true;

    struct prim *m = &f->prims[FX_MESH];
    m->kind = PRIM_MESH;
    vec3 mp[6] = {v3(0, 0, 0), v3(1, 0, 0), v3(0, 0, 1), v3(2, 0, 0), v3(5, 0, 0), v3(2, 1, 2)};
    memcpy(f->mesh_p, mp, sizeof mp);
    for (int i = 0; i < 6; i++)
        f->mesh_tri[i] = i;
    m->p = f->mesh_p;
    m->tri = f->mesh_tri;
    m->nverts = 6;
    m->ntris = 2;
    m->area = 0.5 + 0.5 * vlen(vcross(vsub(mp[4], mp[3]), vsub(mp[5], mp[3])));
    m->emission = v3(4, 2, 1);
    m->emissive = true;

    struct prim *s = &f->prims[FX_SPHERE];
    s->kind = PRIM_SPHERE;
    s->center = v3(0, 3, 1);
    s->radius = 0.5;
    s->area = 4 * M_PI * 0.25;
    s->emission = v3(0.5, 1, 2);
    s->emissive = true;

    struct prim *pl = &f->prims[FX_PLAIN];
    pl->kind = PRIM_QUAD;
    pl->quad_base = v3(-1, -1, -1);
    pl->quad_edge0 = v3(4, 0, 0);
    pl->quad_edge1 = v3(0, 0, 3);
    pl->quad_normal = vnorm(vcross(pl->quad_edge1, pl->quad_edge0));
    pl->area = 12;

    int n = 4;
    if (env != FX_ENV_NONE) {
        struct prim *e = &f->prims[FX_ENV];
        e->kind = PRIM_INFINITE_SPHERE;
        e->bsdf = -1;
        e->emissive = true;
        e->env_to_world = rotate_env ? mat4_rot_yxz(v3(20, 35, 10)) : mat4_identity();
        cr_assert(mat4_invert(&e->env_to_world, &e->env_to_local));
        if (env == FX_ENV_CONST) {
            e->emission = v3(0.3, 0.4, 0.5);
        } else {
            e->emission = v3(1, 1, 1);
            for (int y = 0; y < FX_TEX_H; y++)
                for (int x = 0; x < FX_TEX_W; x++) {
                    float *c = f->texels + 3 * (y * FX_TEX_W + x);
                    /* distinct smooth-ish values; the bottom row is black */
                    c[0] = (float)(0.2 + 0.05 * x);
                    c[1] = (float)(0.3 + 0.1 * y);
                    c[2] = (float)(0.1 + 0.01 * (x + FX_TEX_W * y));
                    if (y == FX_TEX_H - 1) c[0] = c[1] = c[2] = 0;
                }
            float *spot = f->texels + 3 * (2 * FX_TEX_W + 11);
            spot[0] = 60, spot[1] = 50, spot[2] = 40;
            f->tex = (struct texture){.w = FX_TEX_W, .h = FX_TEX_H, .rgb = f->texels};
            e->env_tex = &f->tex;
        }
        n = 5;
    }
    f->sc.file = "fixture.json";
    f->sc.prims = f->prims;
    f->sc.nprims = n;
    f->sc.bbox_min = v3(-1, -1, -1);
    f->sc.bbox_max = v3(5, 4, 2);
    f->sc.env_prim = env != FX_ENV_NONE ? FX_ENV : -1;
    char err[256] = "";
    f->sc.emitters = emitters_build(&f->sc, err, sizeof err);
    cr_assert(f->sc.emitters != NULL, "%s", err);
}

void fx_free(struct emit_fixture *f)
{
    emitters_free(f->sc.emitters);
    f->sc.emitters = NULL;
}

struct camera fx_camera(vec3 pos, vec3 dir, double half_fov_deg, int w, int h)
{
    struct camera c = {0};
    c.pos = pos;
    c.basis = frame_from_normal(vnorm(dir));
    c.tan_half_fov = tan(half_fov_deg * M_PI / 180);
    c.fov_deg = 2 * half_fov_deg;
    c.width = w;
    c.height = h;
    c.aspect = (double)w / h;
    c.filter = FILTER_BOX;
    return c;
}

struct scene *fx_load_one_prim(const char *dir, const char *prim)
{
    char path[512], json[4096], err[1024] = "";
    snprintf(path, sizeof path, "%s/scene.json", dir);
    snprintf(json, sizeof json,
             "{\"bsdfs\": [{\"name\": \"w\", \"type\": \"lambert\", \"albedo\": 0.5}], \"primitives\": [%s],"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 45, \"resolution\": [8, 8], \"transform\":"
             " {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}",
             prim);
    FILE *fp = fopen(path, "w");
    cr_assert(fp);
    fputs(json, fp);
    fclose(fp);
    struct scene *s = scene_load_model(path, err, sizeof err);
    cr_assert(s, "%s", err);
    s->emitters = emitters_build(s, err, sizeof err);
    cr_assert(s->emitters, "%s", err);
    return s;
}

void fx_free_loaded(struct scene *s)
{
    emitters_free(s->emitters);
    s->emitters = NULL;
    scene_model_free(s);
}
