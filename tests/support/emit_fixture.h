/* In-memory scenes for the emitter and camera tests (no loader): an emissive parallelogram quad,
 * a two-triangle emissive mesh of unequal areas, an emissive sphere, a non-emissive quad and
 * optionally an environment (16 x 8 lat-long texture with a bright spot and a black row, rotated;
 * or constant). Also a sampler that draws from a caller's rng (for chi2 callbacks). */
#ifndef EMIT_FIXTURE_H
#define EMIT_FIXTURE_H

#include "camera/camera.h"
#include "emitter/emitter.h"

enum { FX_QUAD = 0, FX_MESH = 1, FX_SPHERE = 2, FX_PLAIN = 3, FX_ENV = 4 };
enum fx_env { FX_ENV_NONE, FX_ENV_MAP, FX_ENV_CONST };
#define FX_TEX_W 16
#define FX_TEX_H 8

struct emit_fixture {
    struct scene sc;
    struct prim prims[5];
    vec3 mesh_p[6], plain_p[4];
    int mesh_tri[6], plain_tri[6];
    struct texture tex;
    float texels[FX_TEX_W * FX_TEX_H * 3];
};

/* Fills f; builds the emitter table (asserts success). */
void fx_init(struct emit_fixture *f, enum fx_env env, bool rotate_env);
void fx_free(struct emit_fixture *f);

/* A scene written to DIR/scene.json with one primitive (the JSON object `prim`) and a lambert
 * bsdf "w", loaded by the real loader with its emitter table (asserts success); freed by
 * fx_free_loaded. For emitters the loader builds (disks, cylinders). */
struct scene *fx_load_one_prim(const char *dir, const char *prim);
void fx_free_loaded(struct scene *s);

/* A test camera: basis from frame_from_normal(dir), horizontal half-fov in degrees. */
struct camera fx_camera(vec3 pos, vec3 dir, double half_fov_deg, int w, int h);

/* Smoothstep and its closed-form inverse: folds a cell so that a density vanishes at its edges
 * (lets chi2's Simpson rule integrate piecewise densities exactly-enough cell by cell). */
static inline double fx_ss(double t) { return t * t * (3 - 2 * t); }
static inline double fx_ss_d(double t) { return 6 * t * (1 - t); }
static inline double fx_ss_inv(double y) { return 0.5 - sin(asin(1 - 2 * y) / 3); }

#endif
