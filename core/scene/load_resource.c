/* The files a scene names (meshes, textures), found relative to the scene file; the loader's
 * lowest layer, shared by the BSDF and primitive readers (scene_load_internal.h). */
#include "scene/scene_load_internal.h"
#include <stdio.h>
#include <string.h>

bool loader_resource(const struct loader *L, const char *rel, char *out, size_t n)
{
    int k = rel[0] == '/' || !L->dir[0] ? snprintf(out, n, "%s", rel) : snprintf(out, n, "%s/%s", L->dir, rel);
    return k >= 0 && (size_t)k < n;
}

/* checker and constant objects: Tungsten's defaults (CheckerTexture: 0.8 on, 0.2 off, 20 x 20
 * cells; ConstantTexture: 0); colours are numbers or arrays of 3, non-negative. */
static bool color_field(struct loader *L, const cJSON *v, const char *path, const char *key, rgb *out)
{
    if (!jget_vec3(&L->c, v, path, key, false, out)) return false;
    if (out->x < 0 || out->y < 0 || out->z < 0) {
        char p[JPATH_MAX];
        jpath_key(p, path, key);
        return jfail(&L->c, p, "expected non-negative values");
    }
    return true;
}

static bool load_checker(struct loader *L, const cJSON *v, const char *path, struct texture **out)
{
    rgb on = v3s(0.8), off = v3s(0.2);
    int ru = 20, rv = 20;
    if (!color_field(L, v, path, "on_color", &on) || !color_field(L, v, path, "off_color", &off) ||
        !jget_int(&L->c, v, path, "res_u", false, 1, 1 << 30, &ru) ||
        !jget_int(&L->c, v, path, "res_v", false, 1, 1 << 30, &rv))
        return false;
    *out = texture_checker(on, off, ru, rv);
    return true;
}

static bool load_texture(struct loader *L, const cJSON *v, const char *path, bool average, struct texture **out)
{
    const char *file = NULL;
    char fpath[JPATH_MAX];
    snprintf(fpath, sizeof fpath, "%s", path);
    if (cJSON_IsString(v)) {
        file = v->valuestring;
    } else {
        const char *type = NULL;
        if (!jget_string(&L->c, v, path, "type", true, &type)) return false;
        if (strcmp(type, "checker") == 0) return load_checker(L, v, path, out);
        if (strcmp(type, "constant") == 0) {
            rgb c = v3s(0);
            if (!color_field(L, v, path, "value", &c)) return false;
            *out = texture_constant(c);
            return true;
        }
        if (strcmp(type, "bitmap") != 0) {
            char tp[JPATH_MAX];
            jpath_key(tp, path, "type");
            const char *why = refused_feature(REFUSED_TEXTURE, type);
            if (why) return jfail(&L->c, tp, "texture type \"%s\" is not supported: %s", type, why);
            return jfail(&L->c, tp, "texture type \"%s\" is not supported (expected bitmap, checker or constant)",
                         type);
        }
        if (!jget_string(&L->c, v, path, "file", true, &file)) return false;
        jpath_key(fpath, path, "file");
    }
    char full[8192], err[1024];
    if (!loader_resource(L, file, full, sizeof full)) return jfail(&L->c, fpath, "path too long");
    *out = average ? texture_load_average(full, err, sizeof err) : texture_load(full, err, sizeof err);
    if (!*out) return jfail(&L->c, fpath, "cannot load texture: %s", err);
    return true;
}

bool load_texture_value(struct loader *L, const cJSON *v, const char *path, struct texture **out)
{
    return load_texture(L, v, path, false, out);
}

bool load_texture_average(struct loader *L, const cJSON *v, const char *path, struct texture **out)
{
    return load_texture(L, v, path, true, out);
}
