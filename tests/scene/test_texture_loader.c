/* The loader's errors for bad texture values (checker, constant, textured roughness, bump): one
 * line "FILE: JSON.PATH: expectation", and bin/render exits with status 2 on them. */
#include <criterion/criterion.h>

#include "bsdf/bsdf_json.h"
#include "scene/scene.h"
#include "support/tmpdir.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#ifndef BIN_DIR
#define BIN_DIR "bin"
#endif

static char tmpdir[256];
static void mk_tmp(void) { tmpdir_make(tmpdir, sizeof tmpdir, "texture-loader-test"); }
static void rm_tmp(void) { tmpdir_remove(tmpdir); }

/* Writes a scene whose bsdfs[0] is `bsdf` into tmpdir, with an infinite_sphere of emission `env`
 * unless NULL; returns its path in out. */
static void write_scene(const char *bsdf, const char *env, char *out, size_t n)
{
    char json[4096], sky[512] = "";
    if (env) snprintf(sky, sizeof sky, ", {\"type\": \"infinite_sphere\", \"emission\": %s}", env);
    snprintf(json, sizeof json,
             "{\"bsdfs\": [%s], \"primitives\": [{\"type\": \"quad\", \"bsdf\": \"a\"}%s],\n"
             " \"camera\": {\"type\": \"pinhole\", \"fov\": 60, \"resolution\": 16,\n"
             "   \"transform\": {\"position\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 1, 0]}}}\n",
             bsdf, sky);
    snprintf(out, n, "%s/scene.json", tmpdir);
    FILE *f = fopen(out, "wb");
    cr_assert(f);
    cr_assert_eq(fwrite(json, 1, strlen(json), f), strlen(json));
    fclose(f);
}

static const struct {
    const char *bsdf, *expect;
} bad[] = {
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"checker\", \"res_u\": 0}}",
     ": bsdfs[0].albedo.res_u: expected an integer in [1, 1073741824]"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"checker\", \"res_v\": 2.5}}",
     ": bsdfs[0].albedo.res_v: expected an integer in [1, 1073741824]"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"checker\", \"on_color\": [1, -0.5, 1]}}",
     ": bsdfs[0].albedo.on_color: expected non-negative values"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"checker\", \"off_color\": \"red\"}}",
     ": bsdfs[0].albedo.off_color: expected a number or an array of 3 numbers"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"constant\", \"value\": -1}}",
     ": bsdfs[0].albedo.value: expected non-negative values"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"wood\"}}",
     ": bsdfs[0].albedo.type: texture type \"wood\" is not supported (expected bitmap, checker or constant)"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"type\": \"blade\"}}",
     ": bsdfs[0].albedo.type: texture type \"blade\" is not supported: procedural aperture textures are not "
     "implemented"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"albedo\": {\"res_u\": 4}}",
     ": bsdfs[0].albedo.type: missing required field"},
    {"{\"name\": \"a\", \"type\": \"rough_conductor\", \"roughness\": \"no-such.png\"}",
     ": bsdfs[0].roughness: cannot load texture"},
    {"{\"name\": \"a\", \"type\": \"rough_dielectric\", \"roughness\": true}",
     ": bsdfs[0].roughness: expected a number, an image file name or a texture object"},
    {"{\"name\": \"a\", \"type\": \"rough_plastic\", \"roughness\": {\"type\": \"checker\", \"res_u\": -3}}",
     ": bsdfs[0].roughness.res_u: expected an integer in [1, 1073741824]"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"bump\": true}",
     ": bsdfs[0].bump: expected a number, an image file name or a texture object"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"bump\": {\"type\": \"bitmap\"}}",
     ": bsdfs[0].bump.file: missing required field"},
    {"{\"name\": \"a\", \"type\": \"rough_conductor\", \"bump\": {\"type\": \"checker\", \"res_v\": 0}}",
     ": bsdfs[0].bump.res_v: expected an integer in [1, 1073741824]"},
    {"{\"name\": \"a\", \"type\": \"lambert\", \"bump\": [1, 2]}",
     ": bsdfs[0].bump: expected a number or an array of 3 numbers"},
};

Test(texture_loader, bad_values_give_one_line_naming_the_json_path, .init = mk_tmp, .fini = rm_tmp)
{
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char path[512], err[1024] = "";
        write_scene(bad[i].bsdf, NULL, path, sizeof path);
        struct scene *s = scene_load_model(path, err, sizeof err);
        cr_expect_null(s, "case %zu loaded but should fail", i);
        scene_model_free(s);
        cr_expect(strncmp(err, path, strlen(path)) == 0, "case %zu: message does not start with the file: %s", i, err);
        cr_expect(strstr(err, bad[i].expect), "case %zu:\n  got      %s\n  expected ...%s...", i, err, bad[i].expect);
        cr_expect(!strchr(err, '\n'), "case %zu: message is not one line", i);
    }
}

/* bin/render on a bad texture value: exit status 2 and one line on stderr naming the path. */
Test(texture_loader, render_exits_with_status_2, .init = mk_tmp, .fini = rm_tmp)
{
    char path[512], cmd[2048], log[600];
    write_scene(bad[0].bsdf, NULL, path, sizeof path);
    snprintf(log, sizeof log, "%s/err.txt", tmpdir);
    snprintf(cmd, sizeof cmd, BIN_DIR "/render %s --spp 1 --quiet --out %s/x 2> %s", path, tmpdir, log);
    int st = system(cmd);
    cr_assert(WIFEXITED(st) && WEXITSTATUS(st) == 2, "status %d", st);
    FILE *f = fopen(log, "rb");
    cr_assert(f);
    char text[2048] = "";
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = 0;
    cr_assert(strstr(text, bad[0].expect), "%s", text);
    cr_assert(n > 0 && strchr(text, '\n') == text + n - 1, "not one line: %s", text);
}

/* The environment's sampling reads texels: a checker sky is refused, a constant one is its value. */
Test(texture_loader, environment_takes_a_bitmap_or_a_constant, .init = mk_tmp, .fini = rm_tmp)
{
    const char *lambert = "{\"name\": \"a\", \"type\": \"lambert\"}";
    char path[512], err[1024] = "";
    write_scene(lambert, "{\"type\": \"checker\"}", path, sizeof path);
    cr_assert_null(scene_load_model(path, err, sizeof err));
    cr_assert(strstr(err, ": primitives[1].emission: an infinite_sphere's emission texture must be a bitmap"), "%s",
              err);
    write_scene(lambert, "{\"type\": \"constant\", \"value\": [0.5, 1, 2]}", path, sizeof path);
    struct scene *s = scene_load_model(path, err, sizeof err);
    cr_assert(s, "%s", err);
    const struct prim *e = &s->prims[s->env_prim];
    cr_assert(!e->env_tex && e->emissive && e->emission.x == 0.5 && e->emission.y == 1 && e->emission.z == 2);
    scene_model_free(s);
}
