/* Reference_Marker orientation forms (orientation.h). */
#include "model/orientation.h"

#include <math.h>
#include <string.h>

#include "base/vecmath.h"

static const char *const cosines[9] = {"a00", "a01", "a02", "a10", "a11", "a12",
                                       "a20", "a21", "a22"};
static const char *const euler[3] = {"psi", "theta", "phi"};
static const char *const parameters[4] = {"e0", "e1", "e2", "e3"};
static const char *const ypr[3] = {"yaw", "pitch", "roll"};

static int count_present(const hx_element_read *e, const char *const *names, int n)
{
    int c = 0;
    for (int k = 0; k < n; ++k)
        c += hx_attr_present(e, names[k]);
    return c;
}

void hx_rotation_313(double psi, double theta, double phi, double R[9])
{
    const double a[3] = {0, 0, 1}, b[3] = {1, 0, 0};
    double Rz1[9], Rx[9], Rz2[9], tmp[9];
    m3_axis_angle(Rz1, a, psi);
    m3_axis_angle(Rx, b, theta);
    m3_axis_angle(Rz2, a, phi);
    m3_mul(tmp, Rz1, Rx);
    m3_mul(R, tmp, Rz2);
}

/* Direction cosines: orthonormal columns, right-handed; made orthonormal to
 * the last bit. */
static int from_cosines(const hx_element_read *e, double R[9], hx_message *why)
{
    for (int k = 0; k < 9; ++k)
        R[k] = hx_attr_number(e, cosines[k], k % 4 == 0 ? 1.0 : 0.0);
    double RtR[9];
    m3_tmul(RtR, R, R);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (fabs(RtR[3 * i + j] - (i == j)) > 1e-6)
                return hx_fail(why, "the direction cosines a00..a22 are not orthonormal (column"
                               " %d . column %d = %g)", i, j, RtR[3 * i + j]);
    const double x[3] = {R[0], R[3], R[6]}, y[3] = {R[1], R[4], R[7]};
    const double given_z[3] = {R[2], R[5], R[8]};
    hx_axes_from_xy(x, y, R);
    if (v3_dot((double[3]){R[2], R[5], R[8]}, given_z) < 0.0)
        return hx_fail(why, "the direction cosines form a left-handed frame");
    return 0;
}

void hx_axes_from_xy(const double x_in[3], const double y_in[3], double R[9])
{
    double x[3], y[3], z[3];
    v3_scale(x, x_in, 1.0 / v3_norm(x_in));
    v3_cross(z, x, y_in);
    v3_scale(z, z, 1.0 / v3_norm(z));
    v3_cross(y, z, x);
    const double Rn[9] = {x[0], y[0], z[0], x[1], y[1], z[1], x[2], y[2], z[2]};
    memcpy(R, Rn, sizeof Rn);
}

static int from_parameters(const hx_element_read *e, double R[9], hx_message *why)
{
    double q[4];
    for (int k = 0; k < 4; ++k)
        q[k] = hx_attr_number(e, parameters[k], 0.0);
    const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (fabs(norm - 1.0) > 1e-6)
        return hx_fail(why, "the Euler parameters e0..e3 (%g %g %g %g) are not of unit length"
                       " (|e| = %.9g)", q[0], q[1], q[2], q[3], norm);
    for (int k = 0; k < 4; ++k)
        q[k] /= norm;
    quat_to_matrix(R, q);
    return 0;
}

int hx_marker_orientation(const hx_element_read *e, double R[9], hx_message *why)
{
    const int nc = count_present(e, cosines, 9), ne = count_present(e, euler, 3),
              np = count_present(e, parameters, 4), ny = count_present(e, ypr, 3);
    if ((nc > 0) + (ne > 0) + (np > 0) + (ny > 0) > 1)
        return hx_fail(why, "it gives more than one orientation form (a00..a22, psi/theta/phi,"
                       " e0..e3, yaw/pitch/roll): give one");
    if (ny > 0)
        return hx_fail(why, "yaw/pitch/roll is not read by the harness (the sign of the pitch"
                       " axis is not documented for this form); give a00..a22, psi/theta/phi"
                       " or e0..e3");
    if (ne > 0) {
        hx_rotation_313(hx_attr_number(e, "psi", 0.0), hx_attr_number(e, "theta", 0.0),
                        hx_attr_number(e, "phi", 0.0), R);
        return 0;
    }
    if (np > 0) {
        if (np != 4)
            return hx_fail(why, "Euler parameters need all four of e0, e1, e2, e3");
        return from_parameters(e, R, why);
    }
    return from_cosines(e, R, why);
}
