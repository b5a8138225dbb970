/* Nested BSDFs for the tests (test_bsdf_nested*.c): loaded through the scene loader from a JSON
 * list of bsdfs, so that children, defaults and the derived fields are the ones a scene gets. */
#ifndef NESTED_UTIL_H
#define NESTED_UTIL_H

#include "bsdf/bsdf.h"
#include "bsdf/bsdf_json.h"
#include "scene/scene.h"
#include "support/tmpdir.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <string.h>

/* Loads a scene whose "bsdfs" array is bsdfs_json (one quad uses the first); NULL and err set when
 * the loader refuses it. */
static inline struct scene *nested_scene(const char *bsdfs_json, char *err, size_t errlen)
{
    char dir[128], path[256];
    tmpdir_make(dir, sizeof dir, "nested");
    snprintf(path, sizeof path, "%s/scene.json", dir);
    FILE *f = fopen(path, "w");
    cr_assert(f);
    fprintf(f,
            "{\"bsdfs\": %s, \"primitives\": [{\"type\": \"quad\", \"bsdf\": \"b0\"}],"
            " \"camera\": {\"type\": \"pinhole\", \"fov\": 40, \"resolution\": [8, 8],"
            " \"transform\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}",
            bsdfs_json);
    fclose(f);
    struct scene *s = scene_load_model(path, err, errlen);
    tmpdir_remove(dir);
    return s;
}

static inline const struct bsdf *nested_find(const struct scene *s, const char *name)
{
    for (int i = 0; i < s->nbsdfs; i++)
        if (!strcmp(s->bsdfs[i].name, name)) return &s->bsdfs[i];
    cr_assert_fail("no bsdf named %s", name);
    return NULL;
}

/* The test materials: every nested type, over continuous, delta and transmissive children, and
 * nested in each other. "b0" only anchors the quad. */
static const char nested_bsdfs_json[] =
    "[{\"name\": \"b0\", \"type\": \"lambert\"},"
    " {\"name\": \"white\", \"type\": \"lambert\", \"albedo\": 1},"
    " {\"name\": \"red\", \"type\": \"lambert\", \"albedo\": [0.7, 0.2, 0.1]},"
    " {\"name\": \"rcu\", \"type\": \"rough_conductor\", \"material\": \"Cu\", \"roughness\": 0.3},"
    " {\"name\": \"au\", \"type\": \"conductor\", \"material\": \"Au\"},"
    " {\"name\": \"mirror\", \"type\": \"mirror\"},"
    " {\"name\": \"glass\", \"type\": \"dielectric\", \"ior\": 1.5},"
    " {\"name\": \"rglass\", \"type\": \"rough_dielectric\", \"ior\": 1.4, \"roughness\": 0.3},"
    " {\"name\": \"rplastic\", \"type\": \"rough_plastic\", \"albedo\": [0.6, 0.1, 0.1], \"roughness\": 0.2},"
    " {\"name\": \"tr\", \"type\": \"transparency\", \"alpha\": 0.6, \"base\": \"red\"},"
    " {\"name\": \"tr_rglass\", \"type\": \"transparency\", \"alpha\": 0.5, \"base\": \"rglass\"},"
    " {\"name\": \"sc\", \"type\": \"smooth_coat\", \"ior\": 1.5, \"thickness\": 0.5, \"sigma_a\": [0.1, 0.5, 1.5],"
    "  \"substrate\": \"red\"},"
    " {\"name\": \"sc_rcu\", \"type\": \"smooth_coat\", \"ior\": 1.5, \"substrate\": \"rcu\"},"
    " {\"name\": \"sc_au\", \"type\": \"smooth_coat\", \"ior\": 1.5, \"substrate\": \"au\"},"
    " {\"name\": \"rc\", \"type\": \"rough_coat\", \"ior\": 1.5, \"roughness\": 0.15, \"substrate\": \"red\"},"
    " {\"name\": \"rc_au\", \"type\": \"rough_coat\", \"ior\": 1.5, \"distribution\": \"beckmann\", \"roughness\": "
    "0.25,"
    "  \"substrate\": \"au\"},"
    " {\"name\": \"rc_rp\", \"type\": \"rough_coat\", \"ior\": 1.3, \"roughness\": 0.3, \"thickness\": 0.2,"
    "  \"sigma_a\": [1, 0.2, 0.5], \"substrate\": \"rplastic\"},"
    " {\"name\": \"mx\", \"type\": \"mixed\", \"ratio\": 0.35, \"bsdf0\": \"red\", \"bsdf1\": \"au\"},"
    " {\"name\": \"mx_rough\", \"type\": \"mixed\", \"ratio\": 0.5, \"bsdf0\": \"rcu\", \"bsdf1\": \"rplastic\","
    "  \"albedo\": [0.9, 0.8, 0.7]},"
    " {\"name\": \"mx_nest\", \"type\": \"mixed\", \"ratio\": 0.4, \"bsdf0\": \"rc\", \"bsdf1\": \"tr\"},"
    " {\"name\": \"mx_glass\", \"type\": \"mixed\", \"ratio\": 0.3, \"bsdf0\": \"red\", \"bsdf1\": \"rglass\"},"
    " {\"name\": \"mx_white\", \"type\": \"mixed\", \"ratio\": 0.45, \"bsdf0\": \"white\", \"bsdf1\": \"mirror\"},"
    " {\"name\": \"mx_white_glass\", \"type\": \"mixed\", \"ratio\": 0.6, \"bsdf0\": \"white\", \"bsdf1\": \"glass\"},"
    " {\"name\": \"tr_white\", \"type\": \"transparency\", \"alpha\": 0.3, \"base\": \"white\"},"
    " {\"name\": \"sc_white\", \"type\": \"smooth_coat\", \"ior\": 1.5, \"substrate\": \"white\"},"
    " {\"name\": \"rc_white\", \"type\": \"rough_coat\", \"ior\": 1.5, \"roughness\": 0.3, \"substrate\": \"white\"}]";

/* The nested materials under test, and whether wi may lie below the surface (transmissive: the
 * path code does not flip their frame). */
static const struct {
    const char *name;
    bool below;
} nested_cases[] = {
    {"tr", false},       {"tr_rglass", true},      {"sc", false},
    {"sc_rcu", false},   {"sc_au", false},         {"rc", false},
    {"rc_au", false},    {"rc_rp", false},         {"mx", false},
    {"mx_rough", false}, {"mx_nest", false},       {"mx_glass", true},
    {"mx_white", false}, {"mx_white_glass", true},
};
#define N_NESTED_CASES (int)(sizeof nested_cases / sizeof nested_cases[0])

static inline vec3 nested_dir(double c, double phi)
{
    double s = sqrt(fmax(0.0, 1.0 - c * c));
    return v3(s * cos(phi), s * sin(phi), c);
}

#endif
