/* Tungsten features the loader knows by name but does not render. A scene that uses one is refused
 * with one line naming the feature and why, rather than a generic "unknown type": the user learns
 * that the file is valid Tungsten and what the harness leaves out (scenes/README.md, "Refused").
 * The names are those of Tungsten's factories (PrimitiveFactory, BsdfFactory, TextureFactory,
 * CameraFactory). */
#include "scene/scene_load_internal.h"
#include <string.h>

static const struct refused {
    enum refused_kind kind;
    const char *name, *why;
} refused[] = {
    {REFUSED_PRIMITIVE, "curves", "hair curves need a curve intersector and fibre BCSDFs"},
    {REFUSED_PRIMITIVE, "point", "a point light has no area: the path-space inverses need a surface"},
    {REFUSED_PRIMITIVE, "skydome", "the analytic sky model is not implemented (bake it to an infinite_sphere map)"},
    {REFUSED_PRIMITIVE, "instances", "instanced geometry is not implemented (flatten it into meshes)"},
    {REFUSED_PRIMITIVE, "minecraft_map", "voxel maps are not implemented"},
    {REFUSED_BSDF, "hair", "fibre BCSDFs need curve primitives"},
    {REFUSED_BSDF, "lambertian_fiber", "fibre BCSDFs need curve primitives"},
    {REFUSED_BSDF, "rough_wire", "fibre BCSDFs need curve primitives"},
    {REFUSED_BSDF, "forward", "index-matched boundaries of participating media; media are not supported"},
    {REFUSED_TEXTURE, "disk", "procedural aperture textures are not implemented"},
    {REFUSED_TEXTURE, "blade", "procedural aperture textures are not implemented"},
    {REFUSED_TEXTURE, "ies", "IES emission profiles are not implemented"},
    {REFUSED_CAMERA, "equirectangular", "only pinhole and thinlens cameras are implemented"},
    {REFUSED_CAMERA, "cubemap", "only pinhole and thinlens cameras are implemented"},
};

const char *refused_feature(enum refused_kind kind, const char *name)
{
    for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++)
        if (refused[i].kind == kind && strcmp(refused[i].name, name) == 0) return refused[i].why;
    return NULL;
}
