/* Pinhole camera basis from position/look_at/up, following Tungsten's conventions:
 * JsonPtr.cpp orthonormalises (forward, up) by Gram-Schmidt and Camera.cpp negates the x axis,
 * so image right = forward x up. With n = forward, t = up, s = n x t the frame is left-handed
 * (s x t = -n): looking down -z with up +y, image right is +x. */
#include "scene/scene.h"

/* Tungsten's fallback when up is (nearly) parallel to the viewing direction. */
static vec3 any_ortho(vec3 a)
{
    vec3 r = fabs(a.x) > fabs(a.y) ? v3(0, 1, 0) : v3(1, 0, 0);
    return vnorm(vcross(a, r));
}

void camera_setup(struct camera *c, vec3 pos, vec3 look_at, vec3 up, double fov_deg, int w, int h)
{
    vec3 n = vnorm(vsub(look_at, pos));
    vec3 t = vsub(up, vscale(n, vdot(n, up)));
    t = vlen2(t) < 1e-5 ? any_ortho(n) : vnorm(t);
    c->pos = pos;
    c->basis.n = n;
    c->basis.t = t;
    c->basis.s = vcross(n, t);
    c->fov_deg = fov_deg;
    c->width = w;
    c->height = h;
    c->tan_half_fov = tan(fov_deg * M_PI / 360.0);
    c->aspect = (double)w / h;
    c->lens_radius = 0; /* a pinhole until the loader reads a thin lens */
    c->focus_dist = 1;
}

void camera_resize(struct camera *c, int w, int h)
{
    c->width = w;
    c->height = h;
    c->aspect = (double)w / h;
}
