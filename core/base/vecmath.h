/* Vectors, colours, orthonormal frames and 4x4 affine transforms.
 * Path code works in double precision: inversion round trips (thesis §5.1) must hold to
 * float tolerance, which single precision cannot guarantee after several bounces.
 * Colours reuse vec3 (r, g, b in x, y, z) to keep one set of operators. */
#ifndef VECMATH_H
#define VECMATH_H

#include <math.h>
#include <stdbool.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#define INV_PI (1.0 / M_PI)

typedef struct {
    double x, y, z;
} vec3;
typedef vec3 rgb;

/* fmax and fmin are out-of-line libm calls on x86-64 (their NaN rules keep GCC from using maxsd);
 * these compile to one instruction. With a NaN operand they return b. */
static inline double maxd(double a, double b) { return a > b ? a : b; }
static inline double mind(double a, double b) { return a < b ? a : b; }
static inline vec3 v3(double x, double y, double z) { return (vec3){x, y, z}; }
static inline vec3 v3s(double s) { return (vec3){s, s, s}; }
static inline vec3 vadd(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 vsub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 vmul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 vdivs(vec3 a, double s) { return v3(a.x / s, a.y / s, a.z / s); }
static inline vec3 vscale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 vneg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
/* a + b*s */
static inline vec3 vmad(vec3 a, vec3 b, double s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline double vdot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 vcross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vlen2(vec3 a) { return vdot(a, a); }
static inline double vlen(vec3 a) { return sqrt(vdot(a, a)); }
static inline vec3 vnorm(vec3 a) { return vscale(a, 1.0 / vlen(a)); }
static inline double vmax(vec3 a) { return maxd(a.x, maxd(a.y, a.z)); }
static inline bool vzero(vec3 a) { return a.x == 0 && a.y == 0 && a.z == 0; }
static inline bool vfinite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
static inline double vget(vec3 a, int i) { return i == 0 ? a.x : i == 1 ? a.y : a.z; }
/* Rec. 709 luminance: the scalar target of every MCMC method. */
static inline double luminance(rgb c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

static inline double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }
static inline double sqr(double x) { return x * x; }

/* sin and cos of 2 pi u. Every polar warp needs them, and libm's sincos was 9 % of a path-tracing
 * sample. Reducing u to the nearest quarter turn is exact (4u - q loses no bits), which leaves
 * |x| <= pi/4, where Taylor series to x^15 and x^16 are accurate to 5e-17. The series are
 * evaluated in Estrin's order (pairs, then powers y^2 and y^4): half the dependent multiply-adds
 * of Horner's rule, which made the warps latency-bound. */
static inline void sincos_turns(double u, double *s, double *c)
{
    double t = 4 * u;
    long q = lrint(t);
    double x = (t - (double)q) * (M_PI / 2), y = x * x, y2 = y * y, y4 = y2 * y2;
    double sn =
        x * ((1 - y * (1.0 / 6)) + y2 * (1.0 / 120 - y * (1.0 / 5040)) +
             y4 * ((1.0 / 362880 - y * (1.0 / 39916800)) + y2 * (1.0 / 6227020800 - y * (1.0 / 1307674368000))));
    double cs = (1 - y * 0.5) + y2 * (1.0 / 24 - y * (1.0 / 720)) +
                y4 * ((1.0 / 40320 - y * (1.0 / 3628800)) + y2 * (1.0 / 479001600 - y * (1.0 / 87178291200)) +
                      y4 * (1.0 / 20922789888000));
    switch (q & 3) {
    case 0:
        *s = sn;
        *c = cs;
        break;
    case 1:
        *s = cs;
        *c = -sn;
        break;
    case 2:
        *s = -sn;
        *c = -cs;
        break;
    default:
        *s = -cs;
        *c = sn;
        break;
    }
}

/* Orthonormal frame; local z is the normal. */
typedef struct {
    vec3 s, t, n;
} frame;

frame frame_from_normal(vec3 n);
static inline vec3 frame_to_local(const frame *f, vec3 v) { return v3(vdot(v, f->s), vdot(v, f->t), vdot(v, f->n)); }
static inline vec3 frame_to_world(const frame *f, vec3 v)
{
    return vadd(vadd(vscale(f->s, v.x), vscale(f->t, v.y)), vscale(f->n, v.z));
}

/* Row-major 4x4 matrix; points are column vectors (p' = M p). */
typedef struct {
    double m[4][4];
} mat4;

mat4 mat4_identity(void);
mat4 mat4_mul(const mat4 *a, const mat4 *b);
vec3 mat4_point(const mat4 *m, vec3 p);
vec3 mat4_vector(const mat4 *m, vec3 v);
/* Transforms a normal by the inverse transpose of the upper 3x3 (not normalised). */
vec3 mat4_normal(const mat4 *m, vec3 n);
bool mat4_invert(const mat4 *m, mat4 *out);
/* Tungsten's rotYXZ: rotation by Euler angles in degrees, applied Z first, then X, then Y, equal to
 * Ry(-y) * Rx(x) * Rz(z) in textbook right-handed matrices (a +y angle turns +x towards +z). */
mat4 mat4_rot_yxz(vec3 degrees);
/* M = T * R * S, as Tungsten builds transforms from position/rotation/scale. */
mat4 mat4_trs(vec3 position, vec3 rotation_deg, vec3 scale);

#endif
