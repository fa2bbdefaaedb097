/* The scalar measures of markers (measure_functions.h). */
#include "frames/measure_functions.h"

#include <math.h>
#include <string.h>

#include "base/vecmath.h"
#include "frames/measures.h"

static const struct {
    const char *name;
    int least, most;
} table[HX_MEASURE_COUNT] = {
    [HX_MEASURE_DX] = {"DX", 1, 3},     [HX_MEASURE_DY] = {"DY", 1, 3},
    [HX_MEASURE_DZ] = {"DZ", 1, 3},     [HX_MEASURE_DM] = {"DM", 1, 2},
    [HX_MEASURE_AX] = {"AX", 1, 2},     [HX_MEASURE_AY] = {"AY", 1, 2},
    [HX_MEASURE_AZ] = {"AZ", 1, 2},     [HX_MEASURE_PSI] = {"PSI", 1, 2},
    [HX_MEASURE_THETA] = {"THETA", 1, 2}, [HX_MEASURE_PHI] = {"PHI", 1, 2},
    [HX_MEASURE_YAW] = {"YAW", 1, 2},   [HX_MEASURE_PITCH] = {"PITCH", 1, 2},
    [HX_MEASURE_ROLL] = {"ROLL", 1, 2}, [HX_MEASURE_INCANG] = {"INCANG", 3, 3},
    [HX_MEASURE_VX] = {"VX", 1, 4},     [HX_MEASURE_VY] = {"VY", 1, 4},
    [HX_MEASURE_VZ] = {"VZ", 1, 4},     [HX_MEASURE_VM] = {"VM", 1, 3},
    [HX_MEASURE_VR] = {"VR", 1, 3},     [HX_MEASURE_WX] = {"WX", 1, 3},
    [HX_MEASURE_WY] = {"WY", 1, 3},     [HX_MEASURE_WZ] = {"WZ", 1, 3},
    [HX_MEASURE_WM] = {"WM", 1, 2},
};

const char *hx_measure_name(hx_measure m)
{
    return table[m].name;
}

int hx_measure_find(const char *name)
{
    for (int k = 0; k < HX_MEASURE_COUNT; ++k)
        if (strcmp(table[k].name, name) == 0)
            return k;
    return -1;
}

void hx_measure_markers(hx_measure m, int *least, int *most)
{
    *least = table[m].least, *most = table[m].most;
}

/* The 3-2-1 angles of a rotation matrix, R = Rz(a0) Ry(a1) Rx(a2). */
static void angles321(const double R[9], double a[3])
{
    a[0] = atan2(R[3], R[0]);
    a[1] = atan2(-R[6], sqrt(R[0] * R[0] + R[3] * R[3]));
    a[2] = atan2(R[7], R[8]);
}

/* The velocity of I relative to J differentiated in L, in world axes. */
static void rate_in(const hx_frame *I, const hx_frame *J, const hx_frame *L, double v[3])
{
    hx_relative_velocity(I, J, &hx_world_frame, L, v);
}

double hx_measure_value(hx_measure m, const hx_frame *const f[4])
{
    const hx_frame *I = f[0], *J = f[1];
    double R[9], v[3], r[3], a[3];
    switch (m) {
    case HX_MEASURE_DX:
    case HX_MEASURE_DY:
    case HX_MEASURE_DZ:
        hx_displacement(I, J, f[2], v);
        return v[m - HX_MEASURE_DX];
    case HX_MEASURE_DM:
        v3_sub(r, I->p, J->p);
        return v3_norm(r);
    case HX_MEASURE_AX:
    case HX_MEASURE_AY:
    case HX_MEASURE_AZ:
        hx_relative_rotation(I, J, R);
        return hx_projection_angle(R, m - HX_MEASURE_AX);
    case HX_MEASURE_PSI:
    case HX_MEASURE_THETA:
    case HX_MEASURE_PHI:
        hx_relative_euler313(I, J, a);
        return a[m - HX_MEASURE_PSI];
    case HX_MEASURE_YAW:
    case HX_MEASURE_PITCH:
    case HX_MEASURE_ROLL:
        hx_relative_rotation(I, J, R);
        angles321(R, a);
        /* PITCH is the second angle negated, the automotive convention of the
         * vendors' PITCH (docs/interface.md §8.5) */
        return m == HX_MEASURE_PITCH ? -a[1] : a[m - HX_MEASURE_YAW];
    case HX_MEASURE_INCANG: {
        /* the angle at J between J->I and J->K, in [0, pi] */
        double b[3], c[3];
        v3_sub(r, I->p, J->p);
        v3_sub(b, f[2]->p, J->p);
        v3_cross(c, r, b);
        return atan2(v3_norm(c), v3_dot(r, b));
    }
    case HX_MEASURE_VX:
    case HX_MEASURE_VY:
    case HX_MEASURE_VZ:
        hx_relative_velocity(I, J, f[2], f[3], v);
        return v[m - HX_MEASURE_VX];
    case HX_MEASURE_VM:
        rate_in(I, J, f[2], v);
        return v3_norm(v);
    case HX_MEASURE_VR: {
        /* the rate along the line of sight: d|r|/dt, which no frame changes */
        rate_in(I, J, f[2], v);
        v3_sub(r, I->p, J->p);
        const double length = v3_norm(r);
        return length > 0.0 ? v3_dot(v, r) / length : 0.0;
    }
    case HX_MEASURE_WX:
    case HX_MEASURE_WY:
    case HX_MEASURE_WZ:
        hx_relative_angular_velocity(I, J, f[2], v);
        return v[m - HX_MEASURE_WX];
    case HX_MEASURE_WM:
        v3_sub(v, I->w, J->w);
        return v3_norm(v);
    default:
        return 0.0;
    }
}
