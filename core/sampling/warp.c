/* Square-to-domain warps and their inverses; the polar maps are chosen over Shirley's concentric
 * map because their inverses are closed-form and branch-free. */
#include "sampling/warp.h"

double warp_phi(double x, double y)
{
    double phi = atan2(y, x);
    return phi < 0 ? phi + 2 * M_PI : phi;
}

static double wrap01(double u) { return u >= 1.0 ? u - 1.0 : u; }

void warp_disk(double u1, double u2, double *x, double *y)
{
    double r = sqrt(u1), sn, cs;
    sincos_turns(u2, &sn, &cs);
    *x = r * cs;
    *y = r * sn;
}

void warp_disk_invert(double x, double y, double *u1, double *u2)
{
    *u1 = clampd(x * x + y * y, 0.0, 1.0);
    *u2 = wrap01(warp_phi(x, y) / (2 * M_PI));
}

vec3 warp_cosine_hemisphere(double u1, double u2)
{
    double x, y;
    warp_disk(u1, u2, &x, &y);
    return v3(x, y, sqrt(maxd(1.0 - u1, 0.0)));
}

double warp_cosine_hemisphere_pdf(vec3 d) { return d.z > 0 ? d.z * INV_PI : 0.0; }

void warp_cosine_hemisphere_invert(vec3 d, double *u1, double *u2) { warp_disk_invert(d.x, d.y, u1, u2); }

vec3 warp_uniform_sphere(double u1, double u2)
{
    double z = 1.0 - 2.0 * u1, r = sqrt(maxd(1.0 - z * z, 0.0)), sn, cs;
    sincos_turns(u2, &sn, &cs);
    return v3(r * cs, r * sn, z);
}

double warp_uniform_sphere_pdf(void) { return 1.0 / (4 * M_PI); }

void warp_uniform_sphere_invert(vec3 d, double *u1, double *u2)
{
    *u1 = clampd((1.0 - d.z) * 0.5, 0.0, 1.0);
    *u2 = wrap01(warp_phi(d.x, d.y) / (2 * M_PI));
}

vec3 warp_uniform_cap(double u1, double u2, double cos_max)
{
    double h = u1 * (1.0 - cos_max); /* 1 - z */
    double r = sqrt(maxd(h * (2.0 - h), 0.0)), sn, cs;
    sincos_turns(u2, &sn, &cs);
    return v3(r * cs, r * sn, 1.0 - h);
}

double warp_uniform_cap_pdf(double cos_max) { return 1.0 / (2 * M_PI * (1.0 - cos_max)); }

void warp_uniform_cap_invert(vec3 d, double cos_max, double *u1, double *u2)
{
    double h = d.z > 0 ? (d.x * d.x + d.y * d.y) / (1.0 + d.z) : 1.0 - d.z;
    *u1 = clampd(h / (1.0 - cos_max), 0.0, 1.0);
    *u2 = wrap01(warp_phi(d.x, d.y) / (2 * M_PI));
}

void warp_triangle(double u1, double u2, double *b1, double *b2)
{
    double s = sqrt(u1);
    *b1 = 1.0 - s;
    *b2 = u2 * s;
}

void warp_triangle_invert(double b1, double b2, double *u1, double *u2)
{
    double s = 1.0 - b1;
    *u1 = clampd(s * s, 0.0, 1.0);
    *u2 = s > 0 ? clampd(b2 / s, 0.0, 1.0) : 0.0;
}
