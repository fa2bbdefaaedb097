/* The forces at a marker at an output time (marker_forces.h). */
#include "expr/marker_forces.h"

#include "base/vecmath.h"
#include "model/expr/functions.h"
#include "model/marker_elements.h"

int hx_marker_forces_slots(const hx_model *m)
{
    return m->nroutines + 3 * m->ncouplers + m->ngcons;
}

int hx_marker_forces_slot(const hx_model *m, int function, int index, int joint)
{
    if (function == HX_FN_MOTION)
        return index;
    if (function == HX_FN_COUPLER)
        return m->nroutines + 3 * index + joint;
    return m->nroutines + 3 * m->ncouplers + index;
}

void hx_marker_forces_joint_on_j(const hx_frames *fr, int k, const double on_i[6],
                                 double on_j[6])
{
    const hx_joint *jt = &fr->model->joints[k];
    hx_frame scratch[2];
    const hx_frame *i = hx_frames_marker(fr, jt->i_marker, &scratch[0]);
    const hx_frame *j = hx_frames_marker(fr, jt->j_marker, &scratch[1]);
    double d[3], dxF[3];
    v3_sub(d, i->p, j->p);
    v3_cross(dxF, d, on_i);
    v3_add(on_j + 3, on_i + 3, dxF);
    v3_scale(on_j, on_i, -1.0), v3_scale(on_j + 3, on_j + 3, -1.0);
}

/* An element with markers a and b (b < 0: none) and its twelve values: what
 * acts at marker i between i and j, added to F and T. */
static void add_element(const double *at, int a, int b, int action_only_element, int i, int j,
                        int action_only, double F[3], double T[3])
{
    if (action_only) {
        if (action_only_element && a == i)
            v3_add(F, F, at), v3_add(T, T, at + 3);
        return;
    }
    if (a == i && (j < 0 || b == j))
        v3_add(F, F, at), v3_add(T, T, at + 3);
    if (b == i && b >= 0 && !action_only_element && (j < 0 || a == j))
        v3_add(F, F, at + 6), v3_add(T, T, at + 9);
}

static int missing(hx_expr_fault *fault, const char *what)
{
    fault->kind = HX_EXPR_FAULT_INPUT, fault->function = "";
    fault->what = what, fault->has_argument = 0;
    return -1;
}

int hx_marker_forces_sum(const hx_frames *fr, const hx_expr_outputs *s, int i, int j,
                         int action_only, double F[3], double T[3], hx_expr_fault *fault)
{
    const hx_model *m = fr->model;
    v3_set(F, 0, 0, 0), v3_set(T, 0, 0, 0);
    if (s == NULL || (m->nloads > 0 && s->loads == NULL) ||
        (m->nforces > 0 && s->forces == NULL) || (m->njoints > 0 && s->reactions == NULL) ||
        (hx_marker_forces_slots(m) > 0 && s->constraints == NULL))
        return missing(fault, "no forces were given to read it from (they are known at output"
                       " times only)");
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        const int only = l->action_only || l->j_marker < 0;
        add_element(s->loads + 12 * k, l->i_marker, l->j_marker, only, i, j, action_only, F, T);
    }
    for (int k = 0; k < m->nforces; ++k) {
        const hx_force *f = &m->forces[k];
        add_element(s->forces + 12 * k, f->i_marker, f->j_marker, f->one_body, i, j,
                    action_only, F, T);
    }
    for (int k = 0; k < m->njoints && !action_only; ++k) {
        const hx_joint *jt = &m->joints[k];
        if (!hx_marker_between(jt->i_marker, jt->j_marker, i, j))
            continue;
        double at[12];
        for (int n = 0; n < 6; ++n)
            at[n] = s->reactions[6 * k + n];
        hx_marker_forces_joint_on_j(fr, k, at, at + 6);
        add_element(at, jt->i_marker, jt->j_marker, 0, i, j, 0, F, T);
    }
    for (int k = 0; k < m->nroutines && !action_only; ++k) {
        const hx_routine *r = &m->routines[k];
        if (r->kind == HX_ROUTINE_MOTION && r->joint >= 0)
            add_element(s->constraints + 12 * hx_marker_forces_slot(m, HX_FN_MOTION, k, 0),
                        m->joints[r->joint].i_marker, m->joints[r->joint].j_marker, 0, i, j, 0,
                        F, T);
    }
    for (int k = 0; k < m->ncouplers && !action_only; ++k)
        for (int n = 0; n < m->couplers[k].njoints; ++n) {
            const hx_joint *jt = &m->joints[m->couplers[k].joint[n]];
            add_element(s->constraints + 12 * hx_marker_forces_slot(m, HX_FN_COUPLER, k, n),
                        jt->i_marker, jt->j_marker, 0, i, j, 0, F, T);
        }
    /* a general constraint's at its I marker alone, as an action-only force's */
    for (int k = 0; k < m->ngcons; ++k)
        if (m->gcons[k].i_marker >= 0)
            add_element(s->constraints + 12 * hx_marker_forces_slot(m, HX_FN_GCON, k, 0),
                        m->gcons[k].i_marker, -1, 1, i, j, action_only, F, T);
    return 0;
}
