/* Frames and 4x4 transforms. */
#include "base/vecmath.h"

frame frame_from_normal(vec3 n)
{
    /* Duff et al. 2017, "Building an orthonormal basis, revisited": continuous away from n.z = -1. */
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z), b = n.x * n.y * a;
    frame f;
    f.s = v3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.t = v3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

mat4 mat4_identity(void)
{
    mat4 m = {{{0}}};
    for (int i = 0; i < 4; i++)
        m.m[i][i] = 1.0;
    return m;
}

mat4 mat4_mul(const mat4 *a, const mat4 *b)
{
    mat4 r;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0;
            for (int k = 0; k < 4; k++)
                s += a->m[i][k] * b->m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

vec3 mat4_point(const mat4 *m, vec3 p)
{
    return v3(m->m[0][0] * p.x + m->m[0][1] * p.y + m->m[0][2] * p.z + m->m[0][3],
              m->m[1][0] * p.x + m->m[1][1] * p.y + m->m[1][2] * p.z + m->m[1][3],
              m->m[2][0] * p.x + m->m[2][1] * p.y + m->m[2][2] * p.z + m->m[2][3]);
}

vec3 mat4_vector(const mat4 *m, vec3 v)
{
    return v3(m->m[0][0] * v.x + m->m[0][1] * v.y + m->m[0][2] * v.z,
              m->m[1][0] * v.x + m->m[1][1] * v.y + m->m[1][2] * v.z,
              m->m[2][0] * v.x + m->m[2][1] * v.y + m->m[2][2] * v.z);
}

vec3 mat4_normal(const mat4 *m, vec3 n)
{
    /* Cofactor matrix of the upper 3x3 = det * inverse transpose; the scale is irrelevant. */
    const double(*a)[4] = m->m;
    double c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1], c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2],
           c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0], c10 = a[0][2] * a[2][1] - a[0][1] * a[2][2],
           c11 = a[0][0] * a[2][2] - a[0][2] * a[2][0], c12 = a[0][1] * a[2][0] - a[0][0] * a[2][1],
           c20 = a[0][1] * a[1][2] - a[0][2] * a[1][1], c21 = a[0][2] * a[1][0] - a[0][0] * a[1][2],
           c22 = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    double det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
    vec3 r =
        v3(c00 * n.x + c01 * n.y + c02 * n.z, c10 * n.x + c11 * n.y + c12 * n.z, c20 * n.x + c21 * n.y + c22 * n.z);
    return det < 0 ? vneg(r) : r;
}

bool mat4_invert(const mat4 *m, mat4 *out)
{
    /* Gauss-Jordan with partial pivoting on [M | I]. */
    double a[4][8];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 8; j++)
            a[i][j] = j < 4 ? m->m[i][j] : (j - 4 == i);
    for (int c = 0; c < 4; c++) {
        int piv = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[piv][c])) piv = r;
        if (fabs(a[piv][c]) < 1e-300) return false;
        for (int j = 0; j < 8; j++) {
            double t = a[c][j];
            a[c][j] = a[piv][j];
            a[piv][j] = t;
        }
        double inv = 1.0 / a[c][c];
        for (int j = 0; j < 8; j++)
            a[c][j] *= inv;
        for (int r = 0; r < 4; r++) {
            if (r == c) continue;
            double f = a[r][c];
            for (int j = 0; j < 8; j++)
                a[r][j] -= f * a[c][j];
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            out->m[i][j] = a[i][j + 4];
    return true;
}

static mat4 rot_axis(int axis, double deg)
{
    double r = deg * M_PI / 180.0, c = cos(r), s = sin(r);
    mat4 m = mat4_identity();
    int i = (axis + 1) % 3, j = (axis + 2) % 3;
    m.m[i][i] = c;
    m.m[i][j] = -s;
    m.m[j][i] = s;
    m.m[j][j] = c;
    return m;
}

/* Tungsten's Y angle turns the other way from the textbook's: rows [c,0,-s],[0,1,0],[s,0,c], so +x
 * turns towards +z. Hence Ry(-y) here; X and Z are textbook. */
mat4 mat4_rot_yxz(vec3 deg)
{
    mat4 ry = rot_axis(1, -deg.y), rx = rot_axis(0, deg.x), rz = rot_axis(2, deg.z);
    mat4 yx = mat4_mul(&ry, &rx);
    return mat4_mul(&yx, &rz);
}

mat4 mat4_trs(vec3 position, vec3 rotation_deg, vec3 scale)
{
    mat4 r = mat4_rot_yxz(rotation_deg);
    mat4 m = r;
    for (int i = 0; i < 3; i++) {
        m.m[i][0] *= scale.x;
        m.m[i][1] *= scale.y;
        m.m[i][2] *= scale.z;
    }
    m.m[0][3] = position.x;
    m.m[1][3] = position.y;
    m.m[2][3] = position.z;
    return m;
}
