/*
 * The one way the Jacobian's blocks add into J (jacobian_parts.h): entries
 * into the pattern, a change of a body's loads into its rows, a force's
 * change through its turning axes and lever arms, and the moved frames of
 * the differences.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/difference_step.h"
#include "base/vecmath.h"
#include "host/variable_values.h"
#include "sim/dynamics/bodies.h"
#include "sim/jacobian/jacobian_parts.h"

void hx_jacobian_add(hx_jacobian *jac, int row0, int count, int col, const double *v)
{
    const hx_sparsity *s = &jac->pattern;
    int p = hx_sparsity_find(s, row0, col);
    for (int i = 0; i < count; ++i) {
        if (v[i] == 0.0)
            continue;
        /* a block's rows are consecutive in its column: look up only when not */
        int at = p >= 0 && p + i < s->colptr[col + 1] && s->rowind[p + i] == row0 + i
                     ? p + i : hx_sparsity_find(s, row0 + i, col);
        if (at < 0)
            jac->outside++;
        else
            jac->values[at] += v[i];
    }
}

int hx_jacobian_rows_at(const hx_jacobian *jac, int row0, int count, int col)
{
    const hx_sparsity *s = &jac->pattern;
    const int p = hx_sparsity_find(s, row0, col);
    if (p < 0 || p + count > s->colptr[col + 1])
        return -1;
    for (int i = 1; i < count; ++i)
        if (s->rowind[p + i] != row0 + i)
            return -1;
    return p;
}

int hx_jacobian_body_columns(const hx_dynamics *d, int b, int columns[13])
{
    const hx_body_dof *dof = &d->dof[b];
    const int nq = dof->kind == HX_DOF_FREE ? 7 : dof->kind == HX_DOF_GROUND ? 0 : 1;
    const int nu = dof->kind == HX_DOF_FREE ? 6 : nq;
    for (int i = 0; i < nq; ++i)
        columns[i] = dof->q + i;
    for (int i = 0; i < nu; ++i)
        columns[nq + i] = d->nq + dof->u + i;
    return nq + nu;
}

double hx_jacobian_step(const double *y, int c)
{
    /* the states are lengths, angles, quaternion components and their rates,
     * of order one in model units; the measures are smooth (difference_step.h) */
    return hx_difference_step(y[c], HX_JACOBIAN_EPS, 1.0);
}

void hx_jacobian_move_body(hx_jacobian *jac, int b, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_bodies_frame(d, b, y, &jac->moved.bodies[b]);
    for (int k = jac->body_marker_start[b]; k < jac->body_marker_start[b + 1]; ++k)
        hx_marker_frame(d->m, &jac->moved.bodies[b], jac->body_markers[k],
                        &jac->moved.markers[jac->body_markers[k]]);
    if (d->m->variables_read) {
        /* the variables the loads read, at the moved body; a fault leaves them not
         * finite, which the load's evaluation reports as its input's fault */
        hx_message msg;
        if (hx_variables_values(&jac->moved, d->routine_binding, jac->moved.variables, &msg) != 0)
            for (int k = 0; k < d->m->nvariables; ++k)
                jac->moved.variables[k] = NAN;
    }
}

void hx_jacobian_restore_body(hx_jacobian *jac, int b)
{
    const hx_frames *fr = &jac->dd.frames;
    jac->moved.bodies[b] = fr->bodies[b];
    for (int k = jac->body_marker_start[b]; k < jac->body_marker_start[b + 1]; ++k)
        jac->moved.markers[jac->body_markers[k]] = fr->markers[jac->body_markers[k]];
    memcpy(jac->moved.variables, fr->variables, sizeof(double) * (size_t)jac->d->m->nvariables);
}

void hx_jacobian_applied_force(hx_jacobian *jac, const hx_applied_force *a, int col, int b,
                             const hx_motion *mo, const double dout[6], const int at[2])
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    static const hx_motion still;
    const hx_motion *none = &still;
    /* the motions of the axes, the point, and the two bodies' centres */
    const double *dth_A = b >= 0 && b == a->ba ? mo->dth : none->dth;
    hx_motion point = still;
    if (b >= 0 && b == a->bi)
        hx_point_motion(&dd->frames.bodies[b], mo, a->I, &point);
    double dF[3], dT[3], tmp[3];
    m3_apply(dF, a->R_A, dout);
    m3_apply(dT, a->R_A, dout + 3);
    v3_cross(tmp, dth_A, a->F);
    v3_add(dF, dF, tmp);
    v3_cross(tmp, dth_A, a->T);
    v3_add(dT, dT, tmp);
    for (int side = 0; side < 2; ++side) {
        const int body = side == 0 ? a->bi : a->bj;
        if (d->dof[body].kind == HX_DOF_GROUND)
            continue;
        const double sign = side == 0 ? 1.0 : -1.0;
        /* torque about the body's centre: (p_I - p_body) x F + T */
        double arm[3], darm[3], torque[3], force[3];
        v3_sub(arm, a->I->p, dd->frames.bodies[body].p);
        v3_copy(darm, point.dp);
        if (b == body)
            v3_sub(darm, darm, mo->dp);
        v3_cross(torque, darm, a->F);
        v3_cross(tmp, arm, dF);
        v3_add(torque, torque, tmp);
        v3_add(torque, torque, dT);
        v3_scale(torque, torque, sign);
        v3_scale(force, dF, sign);
        hx_jacobian_body_load(jac, body, col, at != NULL ? at[side] : -1, force, torque);
    }
}

int hx_jacobian_body_rows_at(const hx_jacobian *jac, int b, int col)
{
    const hx_dynamics *d = jac->d;
    const hx_body_dof *dof = &d->dof[b];
    if (dof->kind == HX_DOF_GROUND)
        return -1;
    return hx_jacobian_rows_at(jac, d->nq + dof->u, dof->kind == HX_DOF_FREE ? 6 : 1, col);
}

/* J[row .. row + count - 1, col] += v, at `at` when known. */
static void add_rows(hx_jacobian *jac, int at, int row, int count, int col, const double *v)
{
    if (at < 0) {
        hx_jacobian_add(jac, row, count, col, v);
        return;
    }
    for (int i = 0; i < count; ++i)
        jac->values[at + i] += v[i];
}

void hx_jacobian_body_load(hx_jacobian *jac, int b, int col, int at, const double dF[3],
                         const double dT[3])
{
    const hx_dynamics *d = jac->d;
    const hx_body_dof *dof = &d->dof[b];
    const hx_frame *f = &jac->dd.frames.bodies[b];
    const int row = d->nq + dof->u;
    double v[6];
    switch (dof->kind) {
    case HX_DOF_GROUND:
        return;
    case HX_DOF_FREE: {
        const double *map = jac->load_map + 12 * b; /* hx_body_blocks */
        if (at >= 0) {
            hx_jacobian_free_body_load(jac->values + at, map, 1.0, dF, dT);
            return;
        }
        v3_scale(v, dF, map[0]);
        m3_apply(v + 3, map + 3, dT);
        hx_jacobian_add(jac, row, 6, col, v);
        return;
    }
    case HX_DOF_REVOLUTE: {
        double r[3], ar[3];
        v3_sub(r, f->p, dof->origin);
        v3_cross(ar, dof->axis, r); /* a.(r x F) = (a x r).F */
        v[0] = d->ucf * (v3_dot(dof->axis, dT) + v3_dot(ar, dF)) / dof->mass;
        add_rows(jac, at, row, 1, col, v);
        return;
    }
    case HX_DOF_SLIDER:
        v[0] = d->ucf * v3_dot(dof->axis, dF) / dof->mass;
        add_rows(jac, at, row, 1, col, v);
        return;
    }
}

int hx_jacobian_marker_lists(hx_jacobian *jac)
{
    const hx_model *m = jac->d->m;
    jac->body_marker_start = calloc((size_t)m->nbodies + 2, sizeof(int));
    jac->body_markers = malloc(sizeof(int) * ((size_t)m->nmarkers + 1));
    if (jac->body_marker_start == NULL || jac->body_markers == NULL)
        return -1;
    for (int k = 0; k < m->nmarkers; ++k)
        if (m->markers[k].tracked)
            jac->body_marker_start[m->markers[k].body + 1]++;
    for (int b = 0; b < m->nbodies; ++b)
        jac->body_marker_start[b + 1] += jac->body_marker_start[b];
    int *fill = calloc((size_t)m->nbodies + 1, sizeof(int));
    if (fill == NULL)
        return -1;
    for (int k = 0; k < m->nmarkers; ++k)
        if (m->markers[k].tracked) {
            const int b = m->markers[k].body;
            jac->body_markers[jac->body_marker_start[b] + fill[b]++] = k;
        }
    free(fill);
    return 0;
}

