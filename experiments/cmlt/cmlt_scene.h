/* The two-light toy of the CMLT paper, §5 (Pantaleoni, "Charted Metropolis Light Transport").
 *
 * Exact geometry (all lengths in scene units, z up):
 *   ground   the square [0,1]x[0,1] in the plane z = 0, normal +z, grey Lambertian, albedo RHO.
 *            Seen by an orthographic camera looking down -z: pixel (i, j) of a W x H image covers
 *            x in [i/W, (i+1)/W), y in [1-(j+1)/H, 1-j/H) (row 0 on top = far side, y = 1).
 *   light 1  unit square in the plane y = L1_Y = -0.03: x in [0,1], z in [0,1], facing +y, just
 *            beyond the ground's near edge y = 0. The gap keeps the geometric term bounded
 *            (G <= 0.325/0.03^2 = 361) but strongly peaked near the edge: that peak is what the
 *            Eq. 13 target of chart 1 (proportional to G) chases.
 *            Emission Le1(x) = A1 exp(K1 x) (1, G0 + G1 x, B0 + B1 x): grows along x and goes
 *            from magenta-red to orange-yellow; max component A1 exp(K1 x).
 *   strip    thin black two-sided occluder in the plane y = STRIP_Y: x in [STRIP_X0, STRIP_X1],
 *            z in [0, 1]: a vertical strip in front of light 1's brightest part.
 *   plate    black occluder in the plane y = 1 covering x, z in [0,1] except a square hole of
 *            half-size HOLE_R centred at (x, z) = (HOLE_X, HOLE_Z).
 *   light 2  unit square in the plane y = L2_Y = 1.05 (just behind the plate): x, z in [0,1],
 *            facing -y, uniform green emission (0, LE2, 0).
 * Path space: pairs x = (ground point g, light point l) with area measure on both; the light point
 * is stored as (light index, la, lb) = (1 or 2, x, z) on the light's unit square.
 * Path contribution f(x) = Le(l) * RHO/pi * G(g, l) * V(g, l); scalar target f* = max component. */
#ifndef CMLT_SCENE_H
#define CMLT_SCENE_H

#include "base/vecmath.h"
#include <stdbool.h>
#include <stdint.h>

#define CMLT_RHO 0.8
#define CMLT_L1_Y (-0.03)
#define CMLT_A1 0.11
#define CMLT_K1 3.0
#define CMLT_EXPK1 20.085536923187668 /* exp(CMLT_K1), checked by a test */
#define CMLT_G0 0.15                  /* light 1's green and blue ramps (red is 1, the max component) */
#define CMLT_G1 0.75
#define CMLT_B0 0.9
#define CMLT_B1 (-0.8)
#define CMLT_STRIP_Y 0.25
#define CMLT_STRIP_X0 0.80
#define CMLT_STRIP_X1 0.84
#define CMLT_HOLE_X 0.5
#define CMLT_HOLE_Z 0.35
#define CMLT_HOLE_R 0.04
#define CMLT_L2_Y 1.05
#define CMLT_LE2 37.5

enum { CMLT_NONE = 0, CMLT_L1 = 1, CMLT_L2 = 2 };

struct cmlt_path {
    double gx, gy; /* ground point (z = 0) */
    int light;     /* CMLT_L1 or CMLT_L2 (CMLT_NONE: not a path, f = 0) */
    double la, lb; /* light point: x and z on the light's unit square */
};

/* Everything the chains need about a path. p1, p2 are the path densities (area x area measure)
 * of chart 1 (ground uniform + light by emission, (s,t) = (1,1)) and chart 2 (ground uniform +
 * cosine direction + ray cast, (s,t) = (0,2)); p2 = 0 where V = 0 (chart 2 cannot produce it). */
struct cmlt_eval {
    rgb f;         /* contribution f(x), includes visibility */
    double fs;     /* f* = max component of f */
    double p1, p2; /* chart densities of the path */
};

/* Scalar emitted powers Phi_k = integral of max-component emission over light k; Phi = sum. */
double cmlt_phi1(void);
double cmlt_phi2(void);
double cmlt_phi(void);

/* Emission of light `light` at (la, lb) and its max component. */
rgb cmlt_le(int light, double la);
double cmlt_le_star(int light, double la);

/* Geometric term and visibility between ground point and light point. */
double cmlt_geom(const struct cmlt_path *x);
bool cmlt_visible(const struct cmlt_path *x);

/* First hit of the ray from ground point (gx, gy, 0) along direction d (d.z > 0): fills the light
 * point of x and returns true if it is an unblocked light point, false if blocked or missed. */
bool cmlt_trace(double gx, double gy, vec3 d, struct cmlt_path *x);

/* f, f*, p1, p2 of a path. */
void cmlt_eval(const struct cmlt_path *x, struct cmlt_eval *e);

/* A hash (FNV-1a over the exact doubles) of what the functions above return on a fixed set of paths
 * and rays: any change to the toy's geometry, emission or visibility changes it, so that a cached
 * reference keyed by it cannot outlive the scene it was computed for. */
uint64_t cmlt_scene_fingerprint(void);

#endif
