/* The checkpoint's scene identity (core/scene/scene_hash.c): the same file hashes the same, and
 * each loaded field a render reads changes it, including the ones no JSON number holds directly:
 * which BSDFs a nested BSDF nests (swapping a mixed BSDF's two children) and whether a mesh takes
 * its bump tangents from a cube's axes. */
#include <criterion/criterion.h>

#include "bsdf/bsdf_json.h"
#include "scene/scene.h"
#include "scene/scene_hash.h"

#define SCENE "scenes/surfaces/scene.json"

static struct scene *load(void)
{
    char err[1024] = "";
    struct scene *s = scene_load_model(SCENE, err, sizeof err);
    cr_assert(s, "%s", err);
    return s;
}

Test(scene_hash, same_file_same_hash_and_every_read_field_changes_it)
{
    struct scene *a = load(), *b = load();
    uint64_t h = ckpt_scene_hash(a);
    cr_assert_eq(h, ckpt_scene_hash(b), "two loads of " SCENE " hash differently");

    int nested = -1;
    for (int i = 0; i < b->nbsdfs && nested < 0; i++)
        if (b->bsdfs[i].child[0] && b->bsdfs[i].child[1] && b->bsdfs[i].child[0] != b->bsdfs[i].child[1]) nested = i;
    cr_assert_geq(nested, 0, SCENE " has no BSDF nesting two different BSDFs");
    const struct bsdf *c0 = b->bsdfs[nested].child[0];
    b->bsdfs[nested].child[0] = b->bsdfs[nested].child[1];
    b->bsdfs[nested].child[1] = c0;
    cr_expect_neq(ckpt_scene_hash(b), h, "swapping bsdfs[%d]'s children left the hash unchanged", nested);
    b->bsdfs[nested].child[1] = b->bsdfs[nested].child[0];
    b->bsdfs[nested].child[0] = c0;
    cr_assert_eq(ckpt_scene_hash(b), h);

    int cube = -1;
    for (int i = 0; i < b->nprims && cube < 0; i++)
        if (b->prims[i].cube_tangents) cube = i;
    cr_assert_geq(cube, 0, SCENE " has no cube");
    b->prims[cube].cube_tangents = false;
    cr_expect_neq(ckpt_scene_hash(b), h, "the cube's tangent flag left the hash unchanged");
    b->prims[cube].cube_tangents = true;

    b->bsdfs[0].albedo.x += 1e-3;
    cr_expect_neq(ckpt_scene_hash(b), h, "an albedo left the hash unchanged");
    scene_model_free(a);
    scene_model_free(b);
}
