/* The CMLT §5 toy: emission, visibility, geometric term, ray cast. Geometry in cmlt_scene.h. */
#include "cmlt/cmlt_scene.h"
#include <math.h>
#include <string.h>

double cmlt_phi1(void) { return CMLT_A1 * (CMLT_EXPK1 - 1.0) / CMLT_K1; }
double cmlt_phi2(void) { return CMLT_LE2; }
double cmlt_phi(void) { return cmlt_phi1() + cmlt_phi2(); }

rgb cmlt_le(int light, double la)
{
    if (light == CMLT_L1) {
        double s = CMLT_A1 * exp(CMLT_K1 * la);
        return v3(s, s * (CMLT_G0 + CMLT_G1 * la), s * (CMLT_B0 + CMLT_B1 * la));
    }
    if (light == CMLT_L2) return v3(0, CMLT_LE2, 0);
    return v3s(0);
}

double cmlt_le_star(int light, double la)
{
    if (light == CMLT_L1) return CMLT_A1 * exp(CMLT_K1 * la);
    if (light == CMLT_L2) return CMLT_LE2;
    return 0;
}

static inline bool in_strip(double x) { return x >= CMLT_STRIP_X0 && x <= CMLT_STRIP_X1; }
static inline bool in_hole(double x, double z)
{
    return fabs(x - CMLT_HOLE_X) < CMLT_HOLE_R && fabs(z - CMLT_HOLE_Z) < CMLT_HOLE_R;
}

/* Light point in world space. */
static inline vec3 light_pos(const struct cmlt_path *x)
{
    return v3(x->la, x->light == CMLT_L1 ? CMLT_L1_Y : CMLT_L2_Y, x->lb);
}

double cmlt_geom(const struct cmlt_path *x)
{
    vec3 l = light_pos(x);
    double dx = l.x - x->gx, dy = l.y - x->gy, dz = l.z;
    double d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 > 1e-300)) return 0;
    /* cos at the ground = dz/d; cos at the light = |dy|/d (lights face the ground along y) */
    return dz * fabs(dy) / (d2 * d2);
}

bool cmlt_visible(const struct cmlt_path *x)
{
    double gx = x->gx, gy = x->gy;
    if (x->light == CMLT_L1) {
        if (gy > CMLT_STRIP_Y) { /* segment crosses the strip plane */
            double t = (gy - CMLT_STRIP_Y) / (gy - CMLT_L1_Y);
            if (in_strip(gx + t * (x->la - gx))) return false;
        }
        return true;
    }
    if (x->light == CMLT_L2) {
        double ly = CMLT_L2_Y - gy;
        if (gy < CMLT_STRIP_Y) {
            double t = (CMLT_STRIP_Y - gy) / ly;
            if (in_strip(gx + t * (x->la - gx))) return false;
        }
        double t = (1.0 - gy) / ly;
        return in_hole(gx + t * (x->la - gx), t * x->lb);
    }
    return false;
}

bool cmlt_trace(double gx, double gy, vec3 d, struct cmlt_path *x)
{
    x->gx = gx;
    x->gy = gy;
    x->light = CMLT_NONE;
    if (d.y < 0) {
        if (gy > CMLT_STRIP_Y) {
            double t = (CMLT_STRIP_Y - gy) / d.y;
            if (in_strip(gx + t * d.x) && t * d.z <= 1.0) return false;
        }
        double t = (CMLT_L1_Y - gy) / d.y, hx = gx + t * d.x, hz = t * d.z;
        if (hx < 0 || hx > 1 || hz > 1) return false;
        x->light = CMLT_L1;
        x->la = hx;
        x->lb = hz;
        return true;
    }
    if (d.y > 0) {
        if (gy < CMLT_STRIP_Y) {
            double t = (CMLT_STRIP_Y - gy) / d.y;
            if (in_strip(gx + t * d.x) && t * d.z <= 1.0) return false;
        }
        double t = (1.0 - gy) / d.y, px = gx + t * d.x, pz = t * d.z;
        if (px >= 0 && px <= 1 && pz <= 1 && !in_hole(px, pz)) return false;
        t = (CMLT_L2_Y - gy) / d.y;
        double hx = gx + t * d.x, hz = t * d.z;
        if (hx < 0 || hx > 1 || hz > 1) return false;
        x->light = CMLT_L2;
        x->la = hx;
        x->lb = hz;
        return true;
    }
    return false;
}

void cmlt_eval(const struct cmlt_path *x, struct cmlt_eval *e)
{
    e->f = v3s(0);
    e->fs = e->p1 = e->p2 = 0;
    if (x->light != CMLT_L1 && x->light != CMLT_L2) return;
    rgb le = cmlt_le(x->light, x->la);
    double les = x->light == CMLT_L1 ? le.x : le.y; /* the max component */
    e->p1 = les * (1.0 / (CMLT_A1 * (CMLT_EXPK1 - 1.0) / CMLT_K1 + CMLT_LE2));
    if (!cmlt_visible(x)) return;
    double g = cmlt_geom(x);
    e->p2 = g * (1.0 / M_PI);
    double k = CMLT_RHO / M_PI * g;
    e->f = vscale(le, k);
    e->fs = les * k;
}

static uint64_t fnv(uint64_t h, double v)
{
    unsigned char b[sizeof v];
    memcpy(b, &v, sizeof v);
    for (size_t i = 0; i < sizeof v; i++)
        h = (h ^ b[i]) * 0x100000001b3ull;
    return h;
}

uint64_t cmlt_scene_fingerprint(void)
{
    uint64_t h = 0xcbf29ce484222325ull;
    /* 17 x 17 ground points (the grid's odd step puts some near the strip's shadow and the hole's
     * beam), 9 x 9 points on each light, and 9 x 9 directions per ground point */
    for (int i = 0; i <= 16; i++)
        for (int j = 0; j <= 16; j++) {
            double gx = (i + 0.37) / 17, gy = (j + 0.61) / 17;
            for (int l = CMLT_L1; l <= CMLT_L2; l++)
                for (int a = 0; a <= 8; a++)
                    for (int b = 0; b <= 8; b++) {
                        struct cmlt_path x = {gx, gy, l, (a + 0.29) / 9, (b + 0.53) / 9};
                        struct cmlt_eval e;
                        cmlt_eval(&x, &e);
                        h = fnv(fnv(fnv(fnv(fnv(h, e.f.x), e.f.y), e.f.z), e.p1), e.p2);
                    }
            for (int a = 0; a <= 8; a++)
                for (int b = 0; b <= 8; b++) {
                    double ph = 2 * M_PI * (a + 0.31) / 9, ct = (b + 0.5) / 9, st = sqrt(1 - ct * ct);
                    struct cmlt_path x;
                    bool hit = cmlt_trace(gx, gy, v3(st * cos(ph), st * sin(ph), ct), &x);
                    h = fnv(h, hit ? x.light + x.la + 2 * x.lb : -1);
                }
        }
    return h;
}
