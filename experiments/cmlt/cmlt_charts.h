/* The two sampling charts (U_i, V_i, T_i, R_i) of the CMLT toy (paper §3 and §5).
 * Both primary spaces are U_i = [0,1)^4 with Lebesgue measure:
 *   chart 1, (s,t) = (1,1): u0,u1 -> ground point (uniform); u2 picks the light with probability
 *            Phi_k/Phi and, rescaled, its x by inverting the emission CDF; u3 -> z (uniform).
 *            Density p1(x) = Le*(l)/Phi (area x area measure).
 *   chart 2, (s,t) = (0,2): u0,u1 -> ground point; u2,u3 -> cosine-weighted direction
 *            (r = sqrt(u2), phi = 2 pi u3); the light point is the first hit of that ray.
 *            Density p2(x) = G(g,l)/pi where visible, 0 elsewhere.
 * Both forward maps are injective on their support, so the reverse sampling spaces V_i are empty
 * and the right inverses R_i are exact inverses: T_i(R_i(x)) = x for every x with f(x) > 0 (Eq. 23),
 * and R_i(T_i(u)) = u. The Jacobian of R_i is the path density p_i (the paper's r_i = 1/p_i in
 * Eq. 28). The argument v is kept for the general (U, V, T, R) interface and ignored. */
#ifndef CMLT_CHARTS_H
#define CMLT_CHARTS_H

#include "cmlt/cmlt_scene.h"

#define CMLT_DIMS 4

/* Forward map T_i. Returns false if u maps to no light point (chart 2: blocked or missed ray);
 * chart 1 always returns a light point, possibly invisible (f = 0). */
bool cmlt_chart_T(int chart, const double u[CMLT_DIMS], struct cmlt_path *x);
/* Right inverse R_i(x, v); false if x is not in the image of T_i. */
bool cmlt_chart_R(int chart, const struct cmlt_path *x, const double *v, double u[CMLT_DIMS]);
/* p_i(x) from an evaluated path. */
static inline double cmlt_chart_pdf(int chart, const struct cmlt_eval *e) { return chart == 1 ? e->p1 : e->p2; }

#endif
