/*
 * Small 3-vector, 3x3 matrix and quaternion helpers of the harness.
 * Matrices are row-major double[9]; a rotation matrix's columns are the axes
 * of the rotated frame expressed in the reference frame. Quaternions are
 * (w, x, y, z), unit length.
 */
#ifndef HX_BASE_VECMATH_H
#define HX_BASE_VECMATH_H

#include <math.h>
#include <string.h>

static inline void v3_set(double *r, double x, double y, double z)
{
    r[0] = x, r[1] = y, r[2] = z;
}
static inline void v3_copy(double *r, const double *a)
{
    r[0] = a[0], r[1] = a[1], r[2] = a[2];
}
static inline void v3_add(double *r, const double *a, const double *b)
{
    r[0] = a[0] + b[0], r[1] = a[1] + b[1], r[2] = a[2] + b[2];
}
static inline void v3_sub(double *r, const double *a, const double *b)
{
    r[0] = a[0] - b[0], r[1] = a[1] - b[1], r[2] = a[2] - b[2];
}
static inline void v3_scale(double *r, const double *a, double s)
{
    r[0] = a[0] * s, r[1] = a[1] * s, r[2] = a[2] * s;
}
static inline void v3_axpy(double *r, double s, const double *a) /* r += s a */
{
    r[0] += s * a[0], r[1] += s * a[1], r[2] += s * a[2];
}
static inline double v3_dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline double v3_norm(const double *a)
{
    return sqrt(v3_dot(a, a));
}
static inline void v3_cross(double *r, const double *a, const double *b)
{
    const double x = a[1] * b[2] - a[2] * b[1];
    const double y = a[2] * b[0] - a[0] * b[2];
    const double z = a[0] * b[1] - a[1] * b[0];
    r[0] = x, r[1] = y, r[2] = z;
}

static inline void m3_identity(double *m)
{
    memset(m, 0, 9 * sizeof(double));
    m[0] = m[4] = m[8] = 1.0;
}
static inline void m3_copy(double *r, const double *a)
{
    memcpy(r, a, 9 * sizeof(double));
}
/* r = a b */
static inline void m3_mul(double *r, const double *a, const double *b)
{
    double t[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            t[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    memcpy(r, t, sizeof t);
}
/* r = a^T b */
static inline void m3_tmul(double *r, const double *a, const double *b)
{
    double t[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            t[3 * i + j] = a[i] * b[j] + a[3 + i] * b[3 + j] + a[6 + i] * b[6 + j];
    memcpy(r, t, sizeof t);
}
/* r = a b^T */
static inline void m3_mult(double *r, const double *a, const double *b)
{
    double t[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            t[3 * i + j] = a[3 * i] * b[3 * j] + a[3 * i + 1] * b[3 * j + 1] +
                           a[3 * i + 2] * b[3 * j + 2];
    memcpy(r, t, sizeof t);
}
static inline void m3_transpose(double *r, const double *a)
{
    double t[9] = {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]};
    memcpy(r, t, sizeof t);
}
/* r = m v */
static inline void m3_apply(double *r, const double *m, const double *v)
{
    const double x = m[0] * v[0] + m[1] * v[1] + m[2] * v[2];
    const double y = m[3] * v[0] + m[4] * v[1] + m[5] * v[2];
    const double z = m[6] * v[0] + m[7] * v[1] + m[8] * v[2];
    r[0] = x, r[1] = y, r[2] = z;
}
/* r = m^T v */
static inline void m3_tapply(double *r, const double *m, const double *v)
{
    const double x = m[0] * v[0] + m[3] * v[1] + m[6] * v[2];
    const double y = m[1] * v[0] + m[4] * v[1] + m[7] * v[2];
    const double z = m[2] * v[0] + m[5] * v[1] + m[8] * v[2];
    r[0] = x, r[1] = y, r[2] = z;
}

/* Rotation matrix of a unit quaternion. */
static inline void quat_to_matrix(double *m, const double *q)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    m[0] = 1 - 2 * (y * y + z * z), m[1] = 2 * (x * y - w * z), m[2] = 2 * (x * z + w * y);
    m[3] = 2 * (x * y + w * z), m[4] = 1 - 2 * (x * x + z * z), m[5] = 2 * (y * z - w * x);
    m[6] = 2 * (x * z - w * y), m[7] = 2 * (y * z + w * x), m[8] = 1 - 2 * (x * x + y * y);
}

/* Unit quaternion of a rotation matrix (Shepperd's method). */
static inline void quat_from_matrix(double *q, const double *m)
{
    const double tr = m[0] + m[4] + m[8];
    if (tr > 0) {
        const double s = 2.0 * sqrt(tr + 1.0);
        q[0] = 0.25 * s, q[1] = (m[7] - m[5]) / s, q[2] = (m[2] - m[6]) / s,
        q[3] = (m[3] - m[1]) / s;
    } else if (m[0] > m[4] && m[0] > m[8]) {
        const double s = 2.0 * sqrt(1.0 + m[0] - m[4] - m[8]);
        q[0] = (m[7] - m[5]) / s, q[1] = 0.25 * s, q[2] = (m[1] + m[3]) / s,
        q[3] = (m[2] + m[6]) / s;
    } else if (m[4] > m[8]) {
        const double s = 2.0 * sqrt(1.0 + m[4] - m[0] - m[8]);
        q[0] = (m[2] - m[6]) / s, q[1] = (m[1] + m[3]) / s, q[2] = 0.25 * s,
        q[3] = (m[5] + m[7]) / s;
    } else {
        const double s = 2.0 * sqrt(1.0 + m[8] - m[0] - m[4]);
        q[0] = (m[3] - m[1]) / s, q[1] = (m[2] + m[6]) / s, q[2] = (m[5] + m[7]) / s,
        q[3] = 0.25 * s;
    }
}

static inline void quat_normalize(double *q)
{
    const double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; ++k)
        q[k] /= n;
}

/* r = a (x) b */
static inline void quat_mul(double *r, const double *a, const double *b)
{
    const double w = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    const double x = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    const double y = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    const double z = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
    r[0] = w, r[1] = x, r[2] = y, r[3] = z;
}

/* Rotation by angle about a unit axis, as a matrix. */
static inline void m3_axis_angle(double *m, const double *axis, double angle)
{
    const double c = cos(angle), s = sin(angle), t = 1.0 - c;
    const double x = axis[0], y = axis[1], z = axis[2];
    m[0] = t * x * x + c, m[1] = t * x * y - s * z, m[2] = t * x * z + s * y;
    m[3] = t * x * y + s * z, m[4] = t * y * y + c, m[5] = t * y * z - s * x;
    m[6] = t * x * z - s * y, m[7] = t * y * z + s * x, m[8] = t * z * z + c;
}

#endif
