/* Sampled states of force elements (element_samples.h). */
#include "tools/check/element_samples.h"

#include <math.h>

#include "state/measures.h"

double hx_jitter(unsigned *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return ((*seed >> 8) & 0xffff) / 32767.5 - 1.0;
}

double hx_sample_time(const hx_model *m, int k)
{
    const double second = 1.0 / (m->has_units ? m->unit_scales[USRSUB_UNIT_TIME] : 1.0);
    return k == 0 ? 0.0 : second * (double)k / (HX_FORCE_SAMPLES - 1);
}

void hx_sample_element_state(const hx_session *s, int force, int k, double disp[6],
                             double velo[6], double scale[12])
{
    const hx_model *m = s->model;
    const double L = m->has_units ? m->unit_scales[USRSUB_UNIT_LENGTH] : 1e-3;
    const double T = m->has_units ? m->unit_scales[USRSUB_UNIT_TIME] : 1.0;
    const double A = m->has_units ? m->unit_scales[USRSUB_UNIT_ANGLE] : 1.0;
    const double length = 1e-3 / L, angle = 0.02 / A; /* 1 mm and 0.02 rad */
    for (int i = 0; i < 6; ++i) {
        scale[i] = i < 3 ? length : angle;
        scale[6 + i] = scale[i] / (0.01 / T); /* moved over 10 ms */
    }
    hx_force_deformation(&s->state, force, disp, velo);
    if (k == 0)
        return;
    const double base_twist = disp[5];
    unsigned seed = 2654435761u * (unsigned)k;
    const double amplitude = 0.5 + 9.5 * (k - 1) / (HX_FORCE_SAMPLES - 2.0);
    for (int i = 0; i < 6; ++i) {
        disp[i] += amplitude * scale[i] * hx_jitter(&seed);
        velo[i] += amplitude * scale[6 + i] * hx_jitter(&seed);
    }
    if (k == 1) { /* a twist at rest (I's z axis along J's), where only psi + phi is
                   * defined, of 0.5 to 0.75 rad so that it reaches the gaps of limits */
        const double twist = 25.0 * scale[5] * (1.0 + fabs(disp[5] - base_twist) / scale[5]);
        disp[3] = disp[4] = 0.0;
        disp[5] = base_twist + (disp[5] >= base_twist ? twist : -twist);
    }
}
