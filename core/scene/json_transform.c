/* Transforms as Tungsten's JsonPtr::get(Mat4f) builds them: axes from look_at/up/x_axis/y_axis/z_axis
 * orthonormalised by Gram-Schmidt in an order that keeps the explicitly given axes, forced right-handed
 * by flipping a non-explicit axis, then scaled, then rotated by rotYXZ; translation in the last column.
 * Without look_at/up/axes this reduces to M = T * R * S (mat4_trs). */
#include "scene/scene_load_internal.h"

static vec3 any_ortho(vec3 a)
{
    vec3 r = fabs(a.x) > fabs(a.y) ? v3(0, 1, 0) : v3(1, 0, 0);
    return vnorm(vcross(a, r));
}

/* a keeps its direction, b is made orthogonal to a, c to both. */
static void gram_schmidt(vec3 *a, vec3 *b, vec3 *c)
{
    *a = vnorm(*a);
    *b = vsub(*b, vscale(*a, vdot(*a, *b)));
    *b = vlen2(*b) < 1e-5 ? any_ortho(*a) : vnorm(*b);
    *c = vsub(*c, vscale(*a, vdot(*a, *c)));
    *c = vsub(*c, vscale(*b, vdot(*b, *c)));
    *c = vlen2(*c) < 1e-5 ? vcross(*a, *b) : vnorm(*c);
}

static bool matrix_form(struct jctx *c, const cJSON *v, const char *path, mat4 *out)
{
    if (cJSON_GetArraySize(v) != 16) return jfail(c, path, "expected an object or an array of 16 numbers");
    for (int i = 0; i < 16; i++) {
        const cJSON *x = cJSON_GetArrayItem(v, i);
        char p[JPATH_MAX];
        jpath_idx(p, path, i);
        if (!jval_number(c, x, p, &out->m[i / 4][i % 4])) return false;
    }
    return true;
}

/* Beyond a million degrees an angle has lost all precision: Tungsten reads it as a float, whose
 * spacing there is 1/16 degree (and a whole degree at 1.6e7), so the scene cannot mean what it says. */
#define MAX_ANGLE_DEG 1e6

static bool rotation_angles(struct jctx *c, const cJSON *v, const char *path, vec3 *rot)
{
    if (!jget_vec3(c, v, path, "rotation", false, rot)) return false;
    const cJSON *r = cJSON_GetObjectItemCaseSensitive(v, "rotation");
    double a[3] = {rot->x, rot->y, rot->z};
    for (int i = 0; i < 3; i++) {
        if (fabs(a[i]) <= MAX_ANGLE_DEG) continue;
        char p[JPATH_MAX], pi[JPATH_MAX];
        jpath_key(p, path, "rotation");
        if (cJSON_IsArray(r)) jpath_idx(pi, p, i);
        return jfail(c, cJSON_IsArray(r) ? pi : p,
                     "expected an angle within +-1e6 degrees (got %g: it has lost all precision)", a[i]);
    }
    return true;
}

bool jval_transform(struct jctx *c, const cJSON *v, const char *path, mat4 *out)
{
    if (cJSON_IsArray(v)) return matrix_form(c, v, path, out);
    if (!cJSON_IsObject(v)) return jfail(c, path, "expected an object or an array of 16 numbers");
    vec3 x = v3(1, 0, 0), y = v3(0, 1, 0), z = v3(0, 0, 1), pos = v3s(0), look;
    if (!jget_vec3(c, v, path, "position", false, &pos)) return false;
    bool ex = false, ey = false, ez = false;
    if (cJSON_GetObjectItemCaseSensitive(v, "look_at")) {
        if (!jget_vec3(c, v, path, "look_at", true, &look)) return false;
        z = vsub(look, pos);
        ez = true;
        char p[JPATH_MAX];
        jpath_key(p, path, "look_at");
        if (vlen2(z) == 0) return jfail(c, p, "must differ from position");
    }
    const char *keys[4] = {"up", "x_axis", "y_axis", "z_axis"};
    vec3 *dst[4] = {&y, &x, &y, &z};
    bool *flag[4] = {&ey, &ex, &ey, &ez};
    for (int i = 0; i < 4; i++) {
        if (!cJSON_GetObjectItemCaseSensitive(v, keys[i])) continue;
        if (!jget_vec3(c, v, path, keys[i], true, dst[i])) return false;
        char p[JPATH_MAX];
        jpath_key(p, path, keys[i]);
        if (vlen2(*dst[i]) == 0) return jfail(c, p, "expected a non-zero vector");
        *flag[i] = true;
    }
    switch ((ez ? 4 : 0) + (ey ? 2 : 0) + (ex ? 1 : 0)) {
    case 1:
        gram_schmidt(&x, &z, &y);
        break;
    case 2:
        gram_schmidt(&y, &z, &x);
        break;
    case 3:
        gram_schmidt(&y, &x, &z);
        break;
    case 5:
        gram_schmidt(&z, &x, &y);
        break;
    default:
        gram_schmidt(&z, &y, &x);
        break;
    }
    if (vdot(vcross(x, y), z) < 0) {
        if (!ex)
            x = vneg(x);
        else if (!ey)
            y = vneg(y);
        else
            z = vneg(z);
    }
    vec3 sc = v3s(1), rot = v3s(0);
    if (!jget_vec3(c, v, path, "scale", false, &sc) || !rotation_angles(c, v, path, &rot)) return false;
    mat4 r = mat4_rot_yxz(rot);
    x = mat4_vector(&r, vscale(x, sc.x));
    y = mat4_vector(&r, vscale(y, sc.y));
    z = mat4_vector(&r, vscale(z, sc.z));
    mat4 m = mat4_identity();
    vec3 cols[4] = {x, y, z, pos};
    for (int j = 0; j < 4; j++) {
        if (!vfinite(cols[j])) return jfail(c, path, "transform is not finite");
        m.m[0][j] = cols[j].x;
        m.m[1][j] = cols[j].y;
        m.m[2][j] = cols[j].z;
    }
    *out = m;
    return true;
}
