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

static bool load_texture_as(struct loader *L, const cJSON *v, const char *path, bool average, struct texture **out);

bool load_texture_value(struct loader *L, const cJSON *v, const char *path, struct texture **out)
{
    return load_texture_as(L, v, path, false, out);
}

bool load_texture_average(struct loader *L, const cJSON *v, const char *path, struct texture **out)
{
    return load_texture_as(L, v, path, true, out);
}

static bool load_texture_as(struct loader *L, const cJSON *v, const char *path, bool average, struct texture **out)
{
    const char *file = NULL;
    char fpath[JPATH_MAX];
    snprintf(fpath, sizeof fpath, "%s", path);
    if (cJSON_IsString(v)) {
        file = v->valuestring;
    } else {
        const char *type = NULL;
        if (!jget_string(&L->c, v, path, "type", true, &type)) return false;
        if (strcmp(type, "bitmap") != 0)
            return jfail(&L->c, path, "texture type '%s' is not supported (expected a bitmap)", type);
        if (!jget_string(&L->c, v, path, "file", true, &file)) return false;
        jpath_key(fpath, path, "file");
    }
    char full[8192], err[1024];
    if (!loader_resource(L, file, full, sizeof full)) return jfail(&L->c, fpath, "path too long");
    *out = average ? texture_load_average(full, err, sizeof err) : texture_load(full, err, sizeof err);
    if (!*out) return jfail(&L->c, fpath, "cannot load texture: %s", err);
    return true;
}
