/* Charts 1 and 2 of the CMLT toy and their exact inverses; see cmlt_charts.h. */
#include "cmlt/cmlt_charts.h"
#include <math.h>

static inline double prob_l1(void)
{
    double p1 = CMLT_A1 * (CMLT_EXPK1 - 1.0) / CMLT_K1;
    return p1 / (p1 + CMLT_LE2);
}

bool cmlt_chart_T(int chart, const double u[CMLT_DIMS], struct cmlt_path *x)
{
    if (chart == 1) {
        x->gx = u[0];
        x->gy = u[1];
        double q = prob_l1();
        if (u[2] < q) {
            x->light = CMLT_L1;
            /* emission CDF along x: (exp(K x) - 1)/(exp(K) - 1) */
            x->la = log1p(u[2] / q * (CMLT_EXPK1 - 1.0)) * (1.0 / CMLT_K1);
        } else {
            x->light = CMLT_L2;
            x->la = (u[2] - q) / (1.0 - q);
        }
        x->lb = u[3];
        return true;
    }
    double r = sqrt(u[2]), phi = 2.0 * M_PI * u[3];
    vec3 d = v3(r * cos(phi), r * sin(phi), sqrt(fmax(0.0, 1.0 - u[2])));
    return cmlt_trace(u[0], u[1], d, x);
}

bool cmlt_chart_R(int chart, const struct cmlt_path *x, const double *v, double u[CMLT_DIMS])
{
    (void)v; /* V_i is empty for both charts */
    if (x->light != CMLT_L1 && x->light != CMLT_L2) return false;
    if (chart != 1 && !cmlt_visible(x)) return false; /* T_2 only reaches unblocked light points */
    u[0] = x->gx;
    u[1] = x->gy;
    if (chart == 1) {
        double q = prob_l1();
        if (x->light == CMLT_L1)
            u[2] = q * expm1(CMLT_K1 * x->la) / (CMLT_EXPK1 - 1.0);
        else
            u[2] = q + (1.0 - q) * x->la;
        u[3] = x->lb;
        return true;
    }
    double dx = x->la - x->gx, dy = (x->light == CMLT_L1 ? CMLT_L1_Y : CMLT_L2_Y) - x->gy, dz = x->lb;
    double d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 > 0) || !(dz > 0)) return false;
    u[2] = (dx * dx + dy * dy) / d2;
    double a = atan2(dy, dx) * (1.0 / (2.0 * M_PI));
    u[3] = a < 0 ? a + 1.0 : a;
    if (u[3] >= 1.0) u[3] = 0.0;
    return true;
}
