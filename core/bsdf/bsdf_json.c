/* The BSDF reader of the scene loader (bsdf_json.h): BSDF blocks of a Tungsten scene, their types,
 * parameters and Tungsten's defaults
 * (the constructors in src/core/bsdfs/): albedo 1; conductors Cu; rough_conductor and rough_dielectric
 * ggx with roughness 0.1; rough_plastic ggx with roughness 0.02; dielectrics and plastics ior 1.5;
 * plastics thickness 1, sigma_a 0; enable_refraction true. Nested BSDFs: transparency alpha 1; coats ior 1.3,
 * thickness 1, sigma_a 0, substrate rough_conductor (Cu, ggx, 0.1); rough_coat ggx, roughness 0.02;
 * mixed ratio 0.5. Leaf BSDFs: thinsheet thickness 0.5; oren_nayar roughness 1;
 * diffuse_transmission transmittance 0.5; phong exponent 64, diffuse_ratio 0.2. It lives in bsdf/,
 * not beside the loader in scene/, because it asks which types are implemented and how many
 * numbers a nested bsdf draws, which only bsdf/ knows. */
#include "bsdf/bsdf_json.h"
#include "base/util.h"
#include "bsdf/bsdf.h"
#include "scene/metals.h"
#include "scene/scene_load_internal.h"
#include <stdio.h>
#include <string.h>

static const char *const type_names[] = {
    [BSDF_NULL] = "null",
    [BSDF_LAMBERT] = "lambert",
    [BSDF_MIRROR] = "mirror",
    [BSDF_CONDUCTOR] = "conductor",
    [BSDF_ROUGH_CONDUCTOR] = "rough_conductor",
    [BSDF_DIELECTRIC] = "dielectric",
    [BSDF_ROUGH_DIELECTRIC] = "rough_dielectric",
    [BSDF_PLASTIC] = "plastic",
    [BSDF_ROUGH_PLASTIC] = "rough_plastic",
    [BSDF_THINSHEET] = "thinsheet",
    [BSDF_DIFFUSE_TRANSMISSION] = "diffuse_transmission",
    [BSDF_TRANSPARENCY] = "transparency",
    [BSDF_SMOOTH_COAT] = "smooth_coat",
    [BSDF_ROUGH_COAT] = "rough_coat",
    [BSDF_OREN_NAYAR] = "oren_nayar",
    [BSDF_PHONG] = "phong",
    [BSDF_MIXED] = "mixed",
};
_Static_assert(sizeof type_names / sizeof type_names[0] == BSDF_NTYPES, "a bsdf type without a name");
#define NTYPES ((int)(sizeof type_names / sizeof type_names[0]))

static void set_defaults(struct bsdf *b, enum bsdf_type t)
{
    memset(b, 0, sizeof *b);
    b->type = t;
    b->albedo = v3s(1);
    metal_lookup("Cu", &b->eta, &b->k);
    b->ior = 1.5;
    b->enable_refraction = true;
    b->dist = MF_GGX;
    b->roughness = t == BSDF_ROUGH_PLASTIC ? 0.02 : t == BSDF_OREN_NAYAR ? 1 : 0.1;
    b->thickness = t == BSDF_THINSHEET ? 0.5 : 1;
    b->sigma_a = v3s(0);
    /* nested BSDFs */
    if (t == BSDF_SMOOTH_COAT || t == BSDF_ROUGH_COAT) b->ior = 1.3;
    if (t == BSDF_ROUGH_COAT) b->roughness = 0.02;
    b->alpha = 1;
    b->ratio = 0.5;
    /* leaf BSDFs */
    b->transmittance = 0.5;
    b->exponent = 64;
    b->diffuse_ratio = 0.2;
}

static bool nonneg(struct jctx *c, const char *path, const char *key, vec3 v)
{
    char p[JPATH_MAX];
    jpath_key(p, path, key);
    if (v.x < 0 || v.y < 0 || v.z < 0) return jfail(c, p, "expected non-negative values");
    return true;
}

/* albedo: number, RGB array, image file name or bitmap object. */
static bool parse_albedo(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "albedo");
    if (!v) return true;
    char p[JPATH_MAX];
    jpath_key(p, path, "albedo");
    if (cJSON_IsString(v) || cJSON_IsObject(v)) {
        /* The texture replaces the constant; albedo stays 1 so that either reading is right. */
        b->albedo = v3s(1);
        return load_texture_value(L, v, p, &b->albedo_tex);
    }
    if (!cJSON_IsNumber(v) && !cJSON_IsArray(v))
        return jfail(&L->c, p, "expected a number, an array of 3 numbers, an image file name or a bitmap texture");
    return jval_vec3(&L->c, v, p, &b->albedo) && nonneg(&L->c, path, "albedo", b->albedo);
}

static bool parse_distribution(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    const char *d = NULL;
    if (!jget_string(&L->c, j, path, "distribution", false, &d)) return false;
    if (!d) return true;
    char p[JPATH_MAX];
    jpath_key(p, path, "distribution");
    if (strcmp(d, "ggx") == 0)
        b->dist = MF_GGX;
    else if (strcmp(d, "beckmann") == 0)
        b->dist = MF_BECKMANN;
    else
        return jfail(&L->c, p, "expected \"ggx\" or \"beckmann\" (got \"%s\")", d);
    return true;
}

static bool parse_roughness(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    const cJSON *r = cJSON_GetObjectItemCaseSensitive(j, "roughness");
    if (!r) return true;
    char p[JPATH_MAX];
    jpath_key(p, path, "roughness");
    if (cJSON_IsString(r) || cJSON_IsObject(r)) return load_texture_average(L, r, p, &b->roughness_tex);
    if (!cJSON_IsNumber(r)) return jfail(&L->c, p, "expected a number, an image file name or a texture object");
    if (!jval_number(&L->c, r, p, &b->roughness)) return false;
    if (b->roughness < 0) return jfail(&L->c, p, "expected a non-negative number");
    return true;
}

/* textures: `bump`, a height map on any bsdf, read as its average (Tungsten's Bsdf::fromJson). A
 * constant height (a number, a constant object) leaves the frame as it is (Tungsten tests
 * isConstant()), so it is dropped here. */
static bool parse_bump(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "bump");
    if (!v) return true;
    char p[JPATH_MAX];
    jpath_key(p, path, "bump");
    if (cJSON_IsNumber(v) || cJSON_IsArray(v)) {
        vec3 c;
        return jval_vec3(&L->c, v, p, &c);
    }
    if (!cJSON_IsString(v) && !cJSON_IsObject(v))
        return jfail(&L->c, p, "expected a number, an image file name or a texture object");
    if (!load_texture_average(L, v, p, &b->bump_tex)) return false;
    if (b->bump_tex->kind == TEX_CONSTANT) {
        texture_free(b->bump_tex);
        b->bump_tex = NULL;
    }
    return true;
}

static bool parse_metal(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    if (!jget_vec3(&L->c, j, path, "eta", false, &b->eta) || !jget_vec3(&L->c, j, path, "k", false, &b->k))
        return false;
    const char *m = NULL;
    if (!jget_string(&L->c, j, path, "material", false, &m)) return false;
    if (m && !metal_lookup(m, &b->eta, &b->k)) {
        char p[JPATH_MAX];
        jpath_key(p, path, "material");
        return jfail(&L->c, p,
                     "unknown metal \"%s\" (known: Ag Al Au Be Cr Cu Cu_palik Hg Ir K Li Mo Nb "
                     "Ni_palik Rh Ta TiN V_palik W)",
                     m);
    }
    return true;
}

static bool parse_ior(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    if (!jget_number(&L->c, j, path, "ior", false, &b->ior)) return false;
    char p[JPATH_MAX];
    jpath_key(p, path, "ior");
    if (b->ior <= 0) return jfail(&L->c, p, "expected a positive number");
    return true;
}

/* A plastic's or a coat's layer: ior, thickness, sigma_a. */
static bool parse_layer(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    struct jctx *c = &L->c;
    if (!parse_ior(L, j, path, b) || !jget_number(c, j, path, "thickness", false, &b->thickness) ||
        !jget_vec3(c, j, path, "sigma_a", false, &b->sigma_a))
        return false;
    char p[JPATH_MAX];
    jpath_key(p, path, "thickness");
    if (b->thickness < 0) return jfail(c, p, "expected a non-negative number");
    return nonneg(c, path, "sigma_a", b->sigma_a);
}

/* nested BSDFs: a probability in [0, 1] at key (transparency's alpha, mixed's constant ratio). */
static bool parse_unit(struct loader *L, const cJSON *v, const char *p, double *out)
{
    if (!jval_number(&L->c, v, p, out)) return false;
    if (!(*out >= 0 && *out <= 1)) return jfail(&L->c, p, "expected a number in [0, 1]");
    return true;
}

static bool parse_alpha(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "alpha");
    if (!v) return true;
    char p[JPATH_MAX];
    jpath_key(p, path, "alpha");
    if (cJSON_IsString(v) || cJSON_IsObject(v))
        return jfail(&L->c, p, "textured alpha is not supported (expected a number in [0, 1])");
    return parse_unit(L, v, p, &b->alpha);
}

/* mixed's ratio: a number, or a bitmap read as Tungsten's REQUEST_AVERAGE scalar texture. */
static bool parse_ratio(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "ratio");
    if (!v) return true;
    char p[JPATH_MAX];
    jpath_key(p, path, "ratio");
    if (cJSON_IsString(v) || cJSON_IsObject(v)) return load_texture_average(L, v, p, &b->ratio_tex);
    return parse_unit(L, v, p, &b->ratio);
}

/* A number in [lo, hi] under key (absent: the default stays). */
static bool number_in(struct loader *L, const cJSON *j, const char *path, const char *key, double lo, double hi,
                      double *out)
{
    if (!jget_number(&L->c, j, path, key, false, out)) return false;
    char p[JPATH_MAX];
    jpath_key(p, path, key);
    if (!(*out >= lo && *out <= hi)) return jfail(&L->c, p, "expected a number in [%g, %g]", lo, hi);
    return true;
}

/* A non-negative number under key (absent: the default stays). */
static bool number_nonneg(struct loader *L, const cJSON *j, const char *path, const char *key, double *out)
{
    if (!jget_number(&L->c, j, path, key, false, out)) return false;
    char p[JPATH_MAX];
    jpath_key(p, path, key);
    if (!(*out >= 0)) return jfail(&L->c, p, "expected a non-negative number");
    return true;
}

static bool parse_thinsheet(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    char p[JPATH_MAX];
    jpath_key(p, path, "thickness");
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(j, "thickness");
    if (cJSON_IsString(t) || cJSON_IsObject(t))
        return jfail(&L->c, p, "textured thickness is not supported (expected a number)");
    bool interference = false;
    if (!parse_ior(L, j, path, b) || !number_nonneg(L, j, path, "thickness", &b->thickness) ||
        !jget_vec3(&L->c, j, path, "sigma_a", false, &b->sigma_a) || !nonneg(&L->c, path, "sigma_a", b->sigma_a) ||
        !jget_bool(&L->c, j, path, "enable_interference", false, &interference))
        return false;
    jpath_key(p, path, "enable_interference");
    if (interference) return jfail(&L->c, p, "thin-film interference is not supported (expected false)");
    return true;
}

/* Tungsten 0.2.2's DiffuseTransmissionBsdf has no fromJson: it never reads `transmittance` and
 * always transmits 0.5. The loader does the same, so that a scene renders as in Tungsten. */
static bool parse_diffuse_transmission(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    double t = b->transmittance;
    if (!number_in(L, j, path, "transmittance", 0, 1, &t)) return false;
    if (t != b->transmittance) {
        char p[JPATH_MAX];
        jpath_key(p, path, "transmittance");
        jwarn(&L->c, p, "Tungsten 0.2.2 ignores this parameter and transmits 0.5; so does this loader");
    }
    return true;
}

static bool parse_phong(struct loader *L, const cJSON *j, const char *path, struct bsdf *b)
{
    return number_nonneg(L, j, path, "exponent", &b->exponent) &&
           number_in(L, j, path, "diffuse_ratio", 0, 1, &b->diffuse_ratio);
}

static bool parse_bsdf(struct loader *L, const cJSON *j, const char *path, const char *default_name, struct bsdf *b);
static int add_bsdf(struct loader *L);
static int find_named(const struct loader *L, const char *name);
static int default_lambert(struct loader *L);

/* A nested bsdf (transparency's base, a coat's substrate, mixed's bsdf0/bsdf1): a top-level name, an
 * inline object, or absent: Tungsten's default, a lambert, except for a coat's substrate, which is
 * a rough_conductor with its defaults (a slot of its own: bsdf_json_slots counts it). */
static bool parse_child(struct loader *L, const cJSON *j, const char *path, const char *key, const struct bsdf **out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, key);
    char p[JPATH_MAX];
    jpath_key(p, path, key);
    if (!v && strcmp(key, "substrate") == 0) {
        int k = add_bsdf(L);
        set_defaults(&L->s->bsdfs[k], BSDF_ROUGH_CONDUCTOR);
        snprintf(L->s->bsdfs[k].name, sizeof L->s->bsdfs[k].name, "default substrate");
        *out = &L->s->bsdfs[k];
        return true;
    }
    if (!v) {
        *out = &L->s->bsdfs[default_lambert(L)];
        return true;
    }
    if (cJSON_IsString(v)) {
        int i = find_named(L, v->valuestring);
        if (i < 0) return jfail(&L->c, p, "undefined bsdf \"%s\" (not in the top-level bsdfs)", v->valuestring);
        *out = &L->s->bsdfs[i];
        return true;
    }
    if (!cJSON_IsObject(v)) return jfail(&L->c, p, "expected a bsdf name or a bsdf object");
    int k = add_bsdf(L);
    *out = &L->s->bsdfs[k];
    return parse_bsdf(L, v, p, p, &L->s->bsdfs[k]);
}

/* Parses one bsdf object into b (which must be zeroed: texture ownership starts here). */
static bool parse_bsdf(struct loader *L, const cJSON *j, const char *path, const char *default_name, struct bsdf *b)
{
    struct jctx *c = &L->c;
    if (!cJSON_IsObject(j)) return jfail(c, path, "expected a bsdf object");
    const char *type = NULL, *name = NULL;
    if (!jget_string(c, j, path, "type", true, &type) || !jget_string(c, j, path, "name", false, &name)) return false;
    int t = 0;
    while (t < NTYPES && !(strcmp(type_names[t], type) == 0 && (t == BSDF_NULL || bsdf_ops_for(t))))
        t++;
    if (t == NTYPES) {
        char p[JPATH_MAX], known[512] = "";
        jpath_key(p, path, "type");
        const char *why = refused_feature(REFUSED_BSDF, type);
        if (why) return jfail(c, p, "bsdf type \"%s\" is not supported: %s", type, why);
        for (int k = 0; k < NTYPES; k++)
            if (k == BSDF_NULL || bsdf_ops_for(k))
                snprintf(known + strlen(known), sizeof known - strlen(known), "%s%s", k ? " " : "", type_names[k]);
        return jfail(c, p, "unknown bsdf type \"%s\" (supported: %s)", type, known);
    }
    set_defaults(b, (enum bsdf_type)t);
    snprintf(b->name, sizeof b->name, "%s", name ? name : default_name);
    if (!parse_albedo(L, j, path, b) || !parse_bump(L, j, path, b)) return false;
    switch (b->type) {
    case BSDF_ROUGH_CONDUCTOR:
        if (!parse_distribution(L, j, path, b) || !parse_roughness(L, j, path, b)) return false;
        /* fall through */
    case BSDF_CONDUCTOR:
        return parse_metal(L, j, path, b);
    case BSDF_ROUGH_DIELECTRIC:
        if (!parse_distribution(L, j, path, b) || !parse_roughness(L, j, path, b)) return false;
        /* fall through */
    case BSDF_DIELECTRIC:
        return parse_ior(L, j, path, b) && jget_bool(c, j, path, "enable_refraction", false, &b->enable_refraction);
    case BSDF_ROUGH_PLASTIC:
        if (!parse_distribution(L, j, path, b) || !parse_roughness(L, j, path, b)) return false;
        /* fall through */
    case BSDF_PLASTIC:
        return parse_layer(L, j, path, b);
    case BSDF_THINSHEET:
        return parse_thinsheet(L, j, path, b);
    case BSDF_DIFFUSE_TRANSMISSION:
        return parse_diffuse_transmission(L, j, path, b);
    case BSDF_OREN_NAYAR:
        return parse_roughness(L, j, path, b);
    case BSDF_PHONG:
        return parse_phong(L, j, path, b);
    /* nested BSDFs */
    case BSDF_TRANSPARENCY:
        return parse_alpha(L, j, path, b) && parse_child(L, j, path, "base", &b->child[0]);
    case BSDF_ROUGH_COAT:
        if (!parse_distribution(L, j, path, b) || !parse_roughness(L, j, path, b)) return false;
        /* fall through */
    case BSDF_SMOOTH_COAT:
        return parse_layer(L, j, path, b) && parse_child(L, j, path, "substrate", &b->child[0]);
    case BSDF_MIXED:
        return parse_ratio(L, j, path, b) && parse_child(L, j, path, "bsdf0", &b->child[0]) &&
               parse_child(L, j, path, "bsdf1", &b->child[1]);
    default:
        return true;
    }
}

static int add_bsdf(struct loader *L)
{
    ASSERT(L->s->nbsdfs < L->bsdf_cap);
    return L->s->nbsdfs++;
}

/* Tungsten gives primitives without a bsdf, and nested bsdfs left out, a default lambert
 * (Primitive::_defaultBsdf); one shared slot. */
static int default_lambert(struct loader *L)
{
    if (L->default_bsdf < 0) {
        L->default_bsdf = add_bsdf(L);
        set_defaults(&L->s->bsdfs[L->default_bsdf], BSDF_LAMBERT);
        snprintf(L->s->bsdfs[L->default_bsdf].name, sizeof L->s->bsdfs[0].name, "default");
    }
    return L->default_bsdf;
}

static const char *const child_keys[] = {"base", "substrate", "bsdf0", "bsdf1"};

static int bsdf_json_slots(const cJSON *v)
{
    if (cJSON_IsArray(v)) {
        int n = 0;
        for (const cJSON *e = v->child; e; e = e->next)
            n += bsdf_json_slots(e);
        return n;
    }
    if (!cJSON_IsObject(v)) return v ? 1 : 0; /* a name (or junk the parser refuses) */
    int n = 1;
    for (size_t k = 0; k < sizeof child_keys / sizeof child_keys[0]; k++)
        n += bsdf_json_slots(cJSON_GetObjectItemCaseSensitive(v, child_keys[k]));
    /* nested BSDFs: a coat without substrate gets a default rough_conductor of its own */
    const cJSON *t = cJSON_GetObjectItemCaseSensitive(v, "type");
    if (cJSON_IsString(t) &&
        (strcmp(t->valuestring, "smooth_coat") == 0 || strcmp(t->valuestring, "rough_coat") == 0) &&
        !cJSON_GetObjectItemCaseSensitive(v, "substrate"))
        n++;
    return n;
}

/* Depth of b's nesting; more than BSDF_MAX_NESTING means a cycle of names (or absurd nesting). */
static int nesting(const struct bsdf *b, int depth)
{
    int d = depth;
    for (int i = 0; i < 2 && d <= BSDF_MAX_NESTING; i++)
        if (b->child[i]) {
            int c = nesting(b->child[i], depth + 1);
            d = c > d ? c : d;
        }
    return d;
}

static bool check_bsdf_nesting(struct loader *L)
{
    for (int i = 0; i < L->s->nbsdfs; i++)
        if (nesting(&L->s->bsdfs[i], 0) > BSDF_MAX_NESTING) {
            char p[JPATH_MAX];
            jpath_idx(p, "bsdfs", i);
            return jfail(&L->c, p, "bsdf \"%s\": nested bsdfs refer to each other in a cycle or nest deeper than %d",
                         L->s->bsdfs[i].name, BSDF_MAX_NESTING);
        }
    /* nested BSDFs: a vertex's block holds SAMPLER_BLOCK numbers. A nested bsdf needs at least as many
     * as any bsdf nested in it, so checking the top-level and the primitives' own bsdfs finds every
     * excess (top-level ones are slots 0..n-1, load_bsdfs; an inline one is a primitive's). */
    bsdf_prepare_all(L->s->bsdfs, L->s->nbsdfs);
    int ntop = L->bsdfs_json ? cJSON_GetArraySize(L->bsdfs_json) : 0;
    char p[JPATH_MAX], q[JPATH_MAX];
    for (int i = 0; i < ntop; i++)
        if (L->s->bsdfs[i].dims > SAMPLER_BLOCK) {
            jpath_idx(p, "bsdfs", i);
            return jfail(&L->c, p,
                         "bsdf \"%s\" needs %d random numbers per vertex, more than the %d of a vertex's block "
                         "(nest fewer bsdfs)",
                         L->s->bsdfs[i].name, L->s->bsdfs[i].dims, SAMPLER_BLOCK);
        }
    for (int i = 0; i < L->s->nprims; i++) {
        int k = L->s->prims[i].bsdf;
        if (k < ntop || L->s->bsdfs[k].dims <= SAMPLER_BLOCK) continue;
        jpath_idx(q, "primitives", i);
        jpath_key(p, q, "bsdf");
        return jfail(&L->c, p,
                     "bsdf \"%s\" needs %d random numbers per vertex, more than the %d of a vertex's block "
                     "(nest fewer bsdfs)",
                     L->s->bsdfs[k].name, L->s->bsdfs[k].dims, SAMPLER_BLOCK);
    }
    return true;
}

static bool load_bsdfs(struct loader *L)
{
    const cJSON *arr = L->bsdfs_json;
    if (!arr) return true;
    if (!cJSON_IsArray(arr)) return jfail(&L->c, "bsdfs", "expected an array of bsdf objects");
    /* Top-level bsdf i is slot i (find_named returns array indices): their slots first, nested ones
     * after them. */
    int n = cJSON_GetArraySize(arr), i = 0;
    for (int k = 0; k < n; k++)
        add_bsdf(L);
    for (const cJSON *j = arr->child; j; j = j->next, i++) {
        char p[JPATH_MAX], def[32];
        jpath_idx(p, "bsdfs", i);
        snprintf(def, sizeof def, "bsdfs[%d]", i);
        if (!parse_bsdf(L, j, p, def, &L->s->bsdfs[i])) return false;
    }
    return true;
}

/* Index of the first top-level bsdf named `name` (Tungsten's findObject), or -1. */
static int find_named(const struct loader *L, const char *name)
{
    int i = 0;
    for (const cJSON *j = L->bsdfs_json ? L->bsdfs_json->child : NULL; j; j = j->next, i++) {
        const cJSON *n = cJSON_GetObjectItemCaseSensitive(j, "name");
        if (cJSON_IsString(n) && strcmp(n->valuestring, name) == 0) return i;
    }
    return -1;
}

static bool load_bsdf_ref(struct loader *L, const cJSON *prim, const char *path, int prim_index, int *out)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(prim, "bsdf");
    char p[JPATH_MAX];
    jpath_key(p, path, "bsdf");
    if (!v) {
        *out = default_lambert(L);
        return true;
    }
    if (cJSON_IsArray(v)) {
        if (cJSON_GetArraySize(v) != 1)
            return jfail(&L->c, p, "per-triangle bsdf arrays are not supported (expected one bsdf)");
        v = v->child;
        char key[JPATH_MAX];
        jpath_key(key, path, "bsdf");
        jpath_idx(p, key, 0);
    }
    if (cJSON_IsString(v)) {
        int i = find_named(L, v->valuestring);
        if (i < 0) return jfail(&L->c, p, "undefined bsdf \"%s\" (not in the top-level bsdfs)", v->valuestring);
        *out = i;
        return true;
    }
    if (!cJSON_IsObject(v)) return jfail(&L->c, p, "expected a bsdf name or a bsdf object");
    char def[32];
    snprintf(def, sizeof def, "inline:%d", prim_index);
    *out = add_bsdf(L);
    return parse_bsdf(L, v, p, def, &L->s->bsdfs[*out]);
}

const struct scene_bsdf_reader bsdf_json_reader = {
    .slots = bsdf_json_slots,
    .load_all = load_bsdfs,
    .load_ref = load_bsdf_ref,
    .check = check_bsdf_nesting,
};
