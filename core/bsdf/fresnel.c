/* Exact Fresnel equations (Born & Wolf); the conductor form is the one pbrt and Tungsten use. */
#include "bsdf/fresnel.h"

double fresnel_dielectric(double cos_i, double eta, double *cos_t)
{
    double sin_t2 = (1.0 - cos_i * cos_i) / (eta * eta);
    if (sin_t2 >= 1.0) {
        *cos_t = 0.0;
        return 1.0;
    }
    double ct = sqrt(1.0 - sin_t2);
    *cos_t = ct;
    double rs = (cos_i - eta * ct) / (cos_i + eta * ct);
    double rp = (eta * cos_i - ct) / (eta * cos_i + ct);
    return 0.5 * (rs * rs + rp * rp);
}

static double conductor1(double c, double eta, double k)
{
    double c2 = c * c, s2 = 1.0 - c2;
    double t0 = eta * eta - k * k - s2;
    double a2b2 = sqrt(maxd(t0 * t0 + 4.0 * eta * eta * k * k, 0.0));
    double a = sqrt(maxd(0.5 * (a2b2 + t0), 0.0));
    double t1 = a2b2 + c2, t2 = 2.0 * c * a;
    double rs = (t1 - t2) / (t1 + t2);
    double t3 = c2 * a2b2 + s2 * s2, t4 = t2 * s2;
    double rp = rs * (t3 - t4) / (t3 + t4);
    return 0.5 * (rp + rs);
}

rgb fresnel_conductor(double cos_i, rgb eta, rgb k)
{
    double c = clampd(cos_i, 0.0, 1.0);
    return v3(conductor1(c, eta.x, k.x), conductor1(c, eta.y, k.y), conductor1(c, eta.z, k.z));
}
