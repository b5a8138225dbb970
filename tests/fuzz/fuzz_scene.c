/* Fuzz target: the scene loader as a whole (scene_load_model). The input is a scene file followed by
 * the files it may name, split at a separator line into fixed slots that become files of the same
 * names in a private directory: scene.json, mesh.obj, mesh.wo3 and tex.raw (a texture in fuzz.h's raw
 * texel format, which the fuzz build's stand-in for OpenImageIO reads; under the test runner the real
 * module refuses it). A scene names them as "mesh.obj", "mesh.wo3" and "tex.raw". */
#include "bsdf/bsdf_json.h"
#include "fuzz/fuzz.h"
#include "scene/scene.h"
#include <stdio.h>
#include <string.h>

#define SEPARATOR "\n--8<--\n"

static const char *const slot_name[] = {"scene.json", "mesh.obj", "mesh.wo3", "tex.raw"};
#define SLOTS (sizeof slot_name / sizeof slot_name[0])

int fuzz_scene(const uint8_t *data, size_t size)
{
    const size_t sep = sizeof SEPARATOR - 1;
    char path[256], scene[256];
    size_t at = 0;
    for (size_t i = 0; i < SLOTS; i++) {
        size_t end = size;
        for (size_t k = at; k + sep <= size; k++)
            if (!memcmp(data + k, SEPARATOR, sep)) {
                end = k;
                break;
            }
        if (at > size) end = at; /* the input ended: the remaining slots are empty files */
        fuzz_write(slot_name[i], data + (at < size ? at : size), end > at ? end - at : 0, path, sizeof path);
        if (i == 0) snprintf(scene, sizeof scene, "%s", path);
        at = end + sep;
    }
    char err[1024] = "";
    struct scene *s = scene_load_model(scene, err, sizeof err);
    if (s)
        scene_model_free(s);
    else
        fuzz_check_message(err);
    return 0;
}
