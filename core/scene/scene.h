/* The scene model: what the loader (scene_load.c) produces and everything else reads.
 * Geometry is in world space after loading; transforms are applied once by the loader.
 * Quads, cubes and meshes are triangle meshes (quads keep their parallelogram for analytic
 * emitter sampling); spheres are analytic; infinite_sphere is the environment emitter. */
#ifndef SCENE_H
#define SCENE_H

#include "base/input_limits.h"
#include "base/vecmath.h"
#include <stddef.h>

enum bsdf_type {
    BSDF_NULL, /* no scattering: the path ends here (see README, "null") */
    BSDF_LAMBERT,
    BSDF_MIRROR,
    BSDF_CONDUCTOR,
    BSDF_ROUGH_CONDUCTOR,
    BSDF_DIELECTRIC,
    BSDF_ROUGH_DIELECTRIC,
    BSDF_PLASTIC,
    BSDF_ROUGH_PLASTIC,
    BSDF_THINSHEET,
    BSDF_DIFFUSE_TRANSMISSION,
    BSDF_TRANSPARENCY, /* child[0] = base, alpha = opacity */
    BSDF_SMOOTH_COAT,  /* child[0] = substrate */
    BSDF_ROUGH_COAT,   /* child[0] = substrate */
    BSDF_OREN_NAYAR,
    BSDF_PHONG,
    BSDF_MIXED, /* child[0], child[1] = bsdf0, bsdf1, ratio = weight of bsdf0 */
    BSDF_NTYPES
};

enum mf_dist { MF_BECKMANN, MF_GGX };

/* Deepest nesting of bsdfs inside bsdfs the loader accepts (a cycle of names nests forever). */
#define BSDF_MAX_NESTING 8

/* Textures, as Tungsten's texture types (README, "Textures"): a bitmap (BitmapTexture: RGB floats,
 * row 0 at the top, as OpenImageIO reads it), a checkerboard (CheckerTexture) or a constant
 * (ConstantTexture, as a `{"type": "constant"}` object). The bitmap fields come first so that
 * {w, h, rgb, bits} initialisers stay bitmaps. */
enum texture_kind { TEX_BITMAP, TEX_CHECKER, TEX_CONSTANT };
struct texture {
    int w, h;
    float *rgb; /* w*h*3, linear */
    int bits;   /* bits per channel of an integer-format file (gamma-decoded at load), 0 for float */
    enum texture_kind kind;
    rgb on, off;      /* checker: the two cell values; constant: `on` */
    int res_u, res_v; /* checker: cells along u and v */
};
/* The one lookup every user goes through. Bitmaps: bilinear with wrap-around, texel (i, j) (row j
 * from the top) centred at u = (i + 0.5) / w, v = 1 - (j + 0.5) / h, so v = 0 is the bottom edge
 * (OBJ convention). Checkers: cell (x, y) = (u res_u, v res_v) truncated toward zero, `on` where
 * x xor y is odd, `off` where it is even. */
rgb texture_lookup(const struct texture *t, double u, double v);
/* Tungsten's derivatives() (the height slope a bump map reads): for a bitmap, the bilinear blend
 * of central differences of the texel values (channel mean) two texels apart, d[0] along the
 * texel columns (+u) and d[1] along the rows, which run DOWN the image (-v); zero for checkers and
 * constants. */
void texture_derivs(const struct texture *t, double u, double v, double d[2]);
/* Tungsten's 8-bit gamma table: floor(255 (code/255)^2.2) / 255 (a 2.2 power, not sRGB). */
float texture_gamma_decode(int code);
void texture_free(struct texture *t);
/* Reads an image file (OpenImageIO) into a texture; NULL and a message in err on failure. */
struct texture *texture_load(const char *path, char *err, size_t errlen);
/* The same read as Tungsten's REQUEST_AVERAGE (roughness, bump): every texel's channels replaced
 * by their mean; for an integer file the mean of its raw 8-bit codes, truncated to a code, and NOT
 * gamma-decoded (Tungsten's loadLdr decodes RGB requests only). */
struct texture *texture_load_average(const char *path, char *err, size_t errlen);
/* The loader's half of it, from decoded texels (3 per texel, malloc'ed, owned from here on: kept or
 * freed): refuses non-finite values, gamma-decodes an integer file's `bits`-bit codes. */
struct texture *texture_from_rgb(const char *path, int w, int h, float *px, int bits, char *err, size_t errlen);
/* A checker or constant texture (no texels). */
struct texture *texture_checker(rgb on, rgb off, int res_u, int res_v);
struct texture *texture_constant(rgb value);

struct bsdf {
    enum bsdf_type type;
    char name[64];
    rgb albedo;                 /* lambert, mirror, conductor tint, plastic substrate, ... */
    struct texture *albedo_tex; /* owned; NULL = constant albedo */
    rgb eta, k;                 /* conductors (from `material` or explicit) */
    double ior;                 /* dielectrics and plastics (relative, outside = 1) */
    bool enable_refraction;     /* dielectrics */
    enum mf_dist dist;          /* rough_* */
    double roughness;           /* alpha, as Tungsten's `roughness` */
    double thickness;           /* plastics, thinsheet */
    rgb sigma_a;                /* plastics, thinsheet */
    /* leaf BSDFs: thinsheet uses ior, thickness (default 0.5), sigma_a above; oren_nayar roughness */
    double transmittance; /* diffuse_transmission: share sent to the other side (0.5) */
    double exponent;      /* phong: cosine-lobe exponent (64) */
    double diffuse_ratio; /* phong: weight of the Lambertian lobe (0.2) */
    /* Nested BSDFs (transparency, coats, mixed): slots of the same scene.bsdfs array, which is
     * allocated once, so the pointers stay valid; never NULL for the types that have them. */
    const struct bsdf *child[2];
    /* textures: per-point parameters read at the hit's uv (owned; NULL = none). roughness_tex
     * replaces `roughness` (rough_* types; Tungsten reads its first channel of the average);
     * bump_tex perturbs the shading frame (any type; only the BSDF a primitive names is read,
     * as in Tungsten, where a nested BSDF's bump is ignored). */
    struct texture *roughness_tex;
    struct texture *bump_tex;
    /* Derived by bsdf_prepare() after loading (children first); never read from JSON. */
    double diffuse_fresnel; /* plastics: hemispherical average of the coat's Fresnel (inside) */
    double coat_T;          /* plastics, coats: exp(-2 thickness mean(sigma_a)), the layer's transmittance
                             * in the lobe choice; a constant that every pdf call would recompute */
    int dims;               /* numbers sample() consumes (nested types: their own + children's) */
    bool transmissive;      /* some lobe scatters to the other side: no two-sided flip */
    bool delta_only;        /* every lobe is a Dirac delta: never connect to it */
    bool needs_uv;          /* a texture somewhere in it is read at the hit's uv */
    /* nested BSDFs: parameters from JSON (alpha, ratio, ratio_tex), then derived by bsdf_prepare. */
    double alpha;              /* transparency: opacity, the probability that the base scatters */
    double ratio;              /* mixed: weight of child[0] (bsdf0) when ratio_tex is NULL */
    struct texture *ratio_tex; /* mixed: owned; scalar (texture_load_average), NULL = constant */
    bool refracts;             /* some lobe refracts (a dielectric, or one nested in it) */
    double refract_ior;        /* the ior it refracts with (the first refracting child's) */
    bool pass_through;         /* has a straight-through lobe without refraction (transparency, thinsheet) */
};

enum prim_kind { PRIM_MESH, PRIM_QUAD, PRIM_SPHERE, PRIM_INFINITE_SPHERE };

struct prim {
    enum prim_kind kind;
    int bsdf;     /* index into scene.bsdfs; -1 for the infinite sphere */
    rgb emission; /* constant radiance, front side only; zero = not an emitter */
    bool emissive;
    /* triangles: PRIM_MESH and PRIM_QUAD (two triangles) */
    int nverts, ntris;
    vec3 *p;     /* world positions */
    vec3 *n;     /* world vertex normals when smooth, else NULL */
    double *uv;  /* 2 per vertex or NULL */
    int *tri;    /* 3 per triangle, counter-clockwise seen from the front */
    vec3 *tri_n; /* unit geometric normal per triangle (built by scene_load) */
    /* PRIM_QUAD: p = base + a * edge0 + b * edge1, (a, b) in [0,1]^2; normal = edge1 x edge0 (unit) */
    vec3 quad_base, quad_edge0, quad_edge1, quad_normal;
    /* PRIM_SPHERE */
    vec3 center;
    double radius;
    vec3 sphere_axis[3]; /* unit columns of the transform; local normal = (axis[i] . n), for uv */
    /* textures: a mesh built from a `cube` takes the cube's axes as its bump-map tangents
     * (Cube.cpp), where other meshes take their uv parameterisation's (TriangleMesh.cpp) */
    bool cube_tangents;
    /* PRIM_INFINITE_SPHERE: emission map (NULL = constant `emission`) and its frame */
    struct texture *env_tex; /* owned, lat-long */
    mat4 env_to_world, env_to_local;
    /* primitives: disk and cylinder load as PRIM_MESH tessellations (scene_shapes.c); an
     * infinite_sphere_cap is a PRIM_INFINITE_SPHERE whose constant emission covers only the
     * directions d with dot(d, cap_dir) >= cap_cos (cap_cos = -1: the whole sphere). */
    bool env_is_cap;
    vec3 cap_dir;   /* world, unit: the transform applied to local +y */
    double cap_cos; /* cos(cap_angle) */
    double area;    /* world surface area (0 for the infinite sphere) */
};

enum recon_filter { FILTER_BOX, FILTER_TENT };

struct camera {
    vec3 pos;
    frame basis;    /* s = image right, t = image up, n = viewing direction */
    double fov_deg; /* horizontal */
    int width, height;
    double tan_half_fov; /* horizontal */
    double aspect;       /* width / height */
    enum recon_filter filter;
    /* thin lens: lens_radius is the aperture disc's radius about pos in the (s, t) plane (Tungsten's
     * aperture_size is this radius), 0 for the pinhole; focus_dist is the distance along n of the
     * plane in focus (Tungsten's focus_distance, a plane, not a sphere). tungsten_defects (tests
     * only, never set by the loader; with lens_radius > 0) reproduces Tungsten 0.2.2's
     * ThinlensCamera, whose camera rays for pixel i leave through film [i - 1/2, i + 1/2)
     * (sampleDirection lacks PinholeCamera's + 1/2) while its light-tracing splats (t = 1) stay
     * where the film is and take film positions in [-1/2, 0) into pixel 0 with MIS weight 1
     * (evalDirection's bound is -filter width, its directionPdf is 0 there); its references carry
     * both (tests/mc/test_conformance.c). */
    double lens_radius;
    double focus_dist;
    bool tungsten_defects;
};

/* The camera's set-up (camera_setup.c), part of the model: the basis from position, look_at and
 * up as Tungsten builds it, with the derived fields; camera_resize changes the resolution keeping
 * position, basis and horizontal fov. Sampling and projection are camera/camera.h's. */
void camera_setup(struct camera *c, vec3 pos, vec3 look_at, vec3 up, double fov_deg, int w, int h);
void camera_resize(struct camera *c, int w, int h);

struct emitter_table; /* light selection, built by emitters_build() (emitter.h) */
struct accel;         /* Embree scene, built by accel_build() (accel.h) */

struct scene {
    char *file; /* the scene file, for messages */
    struct bsdf *bsdfs;
    int nbsdfs;
    struct prim *prims;
    int nprims;
    struct camera cam;
    /* Defaults from the integrator/renderer blocks (command-line options override). */
    int max_length; /* path length cap in segments (from Tungsten's max_bounces) */
    int min_length;
    int spp;
    bool two_sided_shading;  /* integrator.enable_two_sided_shading, default true */
    vec3 bbox_min, bbox_max; /* of all finite geometry */
    int env_prim;            /* index of the infinite sphere or -1 */
    struct emitter_table *emitters;
    struct accel *accel;
};

/* Reads a Tungsten JSON scene's model: geometry, BSDF parameters (through `bsdfs`, the BSDF reader:
 * bsdf/bsdf_json.h's scene_load_model passes it), textures, camera, settings, without emitter table
 * and accel (path/scene_ready.h builds those). On bad input returns NULL and writes one line into
 * err: "FILE: JSON.PATH: what was expected". Warnings for unsupported-but-valid features go to stderr. */
struct scene_bsdf_reader;
struct scene *scene_read_model(const char *path, const struct scene_bsdf_reader *bsdfs, char *err, size_t errlen);
/* Frees what scene_read_model allocated (not emitters/accel); NULL is a no-op. */
void scene_model_free(struct scene *s);

#endif
