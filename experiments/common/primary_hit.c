/* Primary hits at pixel centres (primary_hit.h). */
#include "common/primary_hit.h"
#include "camera/camera.h"
#include <math.h>

/* A sampler that hands the camera the two image numbers of one pixel centre. */
struct centre_sampler {
    struct sampler base;
    double u[2];
};
static double centre_next(struct sampler *s, enum dim_kind kind)
{
    (void)kind;
    return ((struct centre_sampler *)s)->u[s->offset];
}
static const struct sampler_ops centre_ops = {centre_next, NULL, NULL};

bool primary_hit(const struct scene *sc, int x, int y, struct hit *h)
{
    int m = camera_margin(&sc->cam);
    struct centre_sampler cs = {
        {&centre_ops, 0, 0, 0},
        {(x + 0.5 + m) / camera_film_width(&sc->cam), (y + 0.5 + m) / camera_film_height(&sc->cam)}};
    double rx, ry;
    vec3 d = camera_sample_dir(&sc->cam, sc->cam.pos, &cs.base, &rx, &ry, NULL);
    return accel_intersect(sc->accel, sc->cam.pos, d, 0, INFINITY, h);
}
