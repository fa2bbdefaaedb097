/* The scalar measures of markers (measure_functions.h). */
#include "frames/measure_functions.h"

#include <math.h>
#include <string.h>

#include "base/orientation_systems.h"
#include "base/vecmath.h"
#include "frames/measures.h"
#include "model/expr/functions.h"

/* the expressions' measures are numbered as their functions (model/expr/compile.c) */
_Static_assert(HX_MEASURE_COUNT == HX_FN_WM + 1 - HX_FN_DX, "the measures follow DX .. WM");

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

hx_measure hx_measure_orient(int system, int component)
{
    return (hx_measure)(HX_MEASURE_ORIENT + hx_orientation_code(system, component));
}

const char *hx_measure_name(hx_measure m)
{
    return m >= HX_MEASURE_ORIENT ? "ORIENT" : table[m].name;
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
    if (m >= HX_MEASURE_ORIENT)
        *least = 1, *most = 2;
    else
        *least = table[m].least, *most = table[m].most;
}

/* ORIENT(system, component, I, J) of the rotation R of I relative to J
 * (docs/interface.md §8.5). */
static double orientation(int code, const double R[9])
{
    const int system = code / HX_ORIENTATION_COMPONENTS + 1;
    const int k = code % HX_ORIENTATION_COMPONENTS; /* the component, from 0 */
    const hx_orientation_system *s = hx_orientation_system_at(system);
    double e[4];
    switch (s->kind) {
    case HX_ORIENTATION_BODY:
        hx_euler_sequence(s->axes, R, e);
        return e[k];
    case HX_ORIENTATION_SPACE: { /* R_c(t3) R_b(t2) R_a(t1): body-fixed c-b-a of t3, t2, t1 */
        const int reversed[3] = {s->axes[2], s->axes[1], s->axes[0]};
        hx_euler_sequence(reversed, R, e);
        return e[2 - k];
    }
    case HX_ORIENTATION_PROJECTION:
        return hx_projection_angle(R, k);
    case HX_ORIENTATION_YPR: /* as YAW, PITCH, ROLL: the pitch negated */
        hx_euler321(R, e);
        return k == 1 ? -e[1] : e[k];
    case HX_ORIENTATION_PARAMETERS:
        hx_euler_parameters(R, e);
        return e[k];
    case HX_ORIENTATION_RODRIGUES: /* none at a half turn: NaN, which the caller faults */
        hx_euler_parameters(R, e);
        return e[0] > 0.0 ? e[k + 1] / e[0] : NAN;
    default: /* HX_ORIENTATION_COSINES: I's axis k / 3 on J's axis k % 3 */
        return R[3 * (k % 3) + k / 3];
    }
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
    if (m >= HX_MEASURE_ORIENT) {
        hx_relative_rotation(I, J, R);
        return orientation(m - HX_MEASURE_ORIENT, R);
    }
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
        hx_euler321(R, a);
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
