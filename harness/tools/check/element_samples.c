/* Sampled states of force elements (element_samples.h). */
#include "tools/check/element_samples.h"

#include <math.h>

#include "base/vecmath.h"
#include "host/state_inputs.h"
#include "frames/measures.h"

double hx_jitter(unsigned *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return ((*seed >> 8) & 0xffff) / 32767.5 - 1.0;
}

double hx_model_second(const hx_model *m)
{
    return 1.0 / (m->has_units ? m->unit_scales[HX_UNIT_TIME] : 1.0);
}

double hx_sample_time(const hx_model *m, int k)
{
    return k == 0 ? 0.0 : hx_model_second(m) * (double)k / (HX_FORCE_SAMPLES - 1);
}

/* The typical steps of a model: 1 mm, 0.02 rad, and those over 10 ms. */
static void typical_steps(const hx_model *m, double *length, double *angle, double *rate)
{
    const double L = m->has_units ? m->unit_scales[HX_UNIT_LENGTH] : 1e-3;
    const double T = m->has_units ? m->unit_scales[HX_UNIT_TIME] : 1.0;
    const double A = m->has_units ? m->unit_scales[HX_UNIT_ANGLE] : 1.0;
    *length = 1e-3 / L;
    *angle = 0.02 / A;
    *rate = 1.0 / (0.01 / T);
}

/* The amplitude of sample k > 0, in typical steps: 0.5 growing to 10. */
static double amplitude_of(int k)
{
    return 0.5 + 9.5 * (k - 1) / (HX_FORCE_SAMPLES - 2.0);
}

void hx_sample_force_deformation(const hx_session *s, int force, int k, double disp[6],
                             double velo[6], double scale[12])
{
    double length, angle, rate;
    typical_steps(s->model, &length, &angle, &rate);
    for (int i = 0; i < 6; ++i) {
        scale[i] = i < 3 ? length : angle;
        scale[6 + i] = scale[i] * rate;
    }
    hx_force_deformation(&s->frames, force, disp, velo);
    if (k == 0)
        return;
    const double base_twist = disp[5];
    unsigned seed = 2654435761u * (unsigned)k;
    const double amplitude = amplitude_of(k);
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

void hx_sample_model_frames(const hx_session *s, int k, hx_frames *out, double scale[12])
{
    const hx_model *m = s->model;
    double length, angle, rate;
    typical_steps(m, &length, &angle, &rate);
    for (int i = 0; i < 6; ++i) {
        scale[i] = i < 3 ? length : angle;
        scale[6 + i] = scale[i] * rate;
    }
    const double time = out->time;
    hx_frames_copy(out, &s->frames);
    out->time = time;
    if (k == 0)
        return;
    unsigned seed = 2654435761u * (unsigned)k + 31u;
    const double amplitude = amplitude_of(k);
    for (int b = 0; b < m->nbodies; ++b) {
        if (m->bodies[b].is_ground)
            continue;
        hx_frame *f = &out->bodies[b];
        double turn[3], R[9];
        for (int i = 0; i < 3; ++i) {
            f->p[i] += amplitude * scale[i] * hx_jitter(&seed);
            turn[i] = amplitude * scale[3 + i] * hx_jitter(&seed);
            f->v[i] += amplitude * scale[6 + i] * hx_jitter(&seed);
            f->w[i] += amplitude * scale[9 + i] * hx_jitter(&seed);
        }
        const double a = v3_norm(turn);
        if (a > 0.0) {
            v3_scale(turn, turn, 1.0 / a);
            m3_axis_angle(R, turn, a);
            m3_mul(f->R, R, f->R);
        }
    }
    for (int d = 0; d < 2 * m->nroutines_of[HX_ROUTINE_DIFF]; ++d)
        out->diffs[d] += 0.01 * amplitude * (1.0 + fabs(out->diffs[d])) * hx_jitter(&seed);
    hx_frames_update(out);
}

/* A measure's typical step: lengths, angles and their rates; 1 for a number. */
static double input_scale(const hx_variable *v, double length, double angle, double rate)
{
    switch (v->function[0]) {
    case 'D': return length;
    case 'A': return angle;
    case 'V': return length * rate;
    case 'W': return angle * rate;
    default: return 1.0;
    }
}

void hx_sample_stateeqn_states(const hx_session *s, int element, int k, double *states,
                             double *inputs, double *scale)
{
    const hx_model *m = s->model;
    const hx_stateeqn *f = &m->stateeqns[element];
    double length, angle, rate;
    typical_steps(m, &length, &angle, &rate);
    for (int i = 0; i < f->nstate; ++i) {
        states[i] = f->initial[i];
        scale[i] = 1e-3 * length;
    }
    hx_stateeqn_inputs(&s->frames, element, inputs);
    for (int i = 0; i < f->ninput; ++i)
        scale[f->nstate + i] = input_scale(&m->variables[f->inputs[i]], length, angle, rate);
    if (k == 0)
        return;
    unsigned seed = 2654435761u * (unsigned)k + 97u;
    const double amplitude = amplitude_of(k);
    for (int i = 0; i < f->nstate + f->ninput; ++i) {
        double *v = i < f->nstate ? &states[i] : &inputs[i - f->nstate];
        *v += amplitude * scale[i] * hx_jitter(&seed);
    }
}
