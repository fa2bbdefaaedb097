/* The Newton matrix, assembled element by element (newton_matrix.h). */
#include "sim/newton/newton_parts.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"

void hx_newton_add(hx_newton_matrix *nm, int row0, int count, int col, const double *v)
{
    const hx_sparsity *s = &nm->pattern;
    int p = hx_sparsity_find(s, row0, col);
    for (int i = 0; i < count; ++i) {
        if (v[i] == 0.0)
            continue;
        /* a block's rows are consecutive in its column: look up only when not */
        int at = p >= 0 && p + i < s->colptr[col + 1] && s->rowind[p + i] == row0 + i
                     ? p + i : hx_sparsity_find(s, row0 + i, col);
        if (at < 0)
            nm->outside++;
        else
            nm->values[at] += v[i];
    }
}

int hx_newton_rows_at(const hx_newton_matrix *nm, int row0, int count, int col)
{
    const hx_sparsity *s = &nm->pattern;
    const int p = hx_sparsity_find(s, row0, col);
    if (p < 0 || p + count > s->colptr[col + 1])
        return -1;
    for (int i = 1; i < count; ++i)
        if (s->rowind[p + i] != row0 + i)
            return -1;
    return p;
}

int hx_newton_body_columns(const hx_dynamics *d, int b, int columns[13])
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

double hx_newton_step(const double *y, int c)
{
    /* relative above 1, absolute below: the measures are smooth, so central
     * differences of this size are good to about 1e-10 */
    return 1e-5 * fmax(1.0, fabs(y[c]));
}

void hx_newton_probe_move(hx_newton_matrix *nm, int b, const double *y)
{
    const hx_dynamics *d = nm->d;
    hx_bodies_frame(d, b, y, &nm->probe.bodies[b]);
    for (int k = nm->body_marker_start[b]; k < nm->body_marker_start[b + 1]; ++k)
        hx_marker_frame(d->m, &nm->probe.bodies[b], nm->body_markers[k],
                        &nm->probe.markers[nm->body_markers[k]]);
}

void hx_newton_probe_restore(hx_newton_matrix *nm, int b)
{
    const hx_frames *s = &nm->d->frames;
    nm->probe.bodies[b] = s->bodies[b];
    for (int k = nm->body_marker_start[b]; k < nm->body_marker_start[b + 1]; ++k)
        nm->probe.markers[nm->body_markers[k]] = s->markers[nm->body_markers[k]];
}

void hx_newton_applied_force(hx_newton_matrix *nm, const hx_applied_force *a, int col, int b,
                             const hx_motion *mo, const double dout[6], const int at[2])
{
    const hx_dynamics *d = nm->d;
    static const hx_motion still;
    const hx_motion *none = &still;
    /* the motions of the axes, the point, and the two bodies' centres */
    const double *dth_A = b >= 0 && b == a->ba ? mo->dth : none->dth;
    hx_motion point = still;
    if (b >= 0 && b == a->bi)
        hx_point_motion(&d->frames.bodies[b], mo, a->I, &point);
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
        v3_sub(arm, a->I->p, d->frames.bodies[body].p);
        v3_copy(darm, point.dp);
        if (b == body)
            v3_sub(darm, darm, mo->dp);
        v3_cross(torque, darm, a->F);
        v3_cross(tmp, arm, dF);
        v3_add(torque, torque, tmp);
        v3_add(torque, torque, dT);
        v3_scale(torque, torque, sign);
        v3_scale(force, dF, sign);
        hx_newton_body_load(nm, body, col, at != NULL ? at[side] : -1, force, torque);
    }
}

static int body_marker_lists(hx_newton_matrix *nm)
{
    const hx_model *m = nm->d->m;
    nm->body_marker_start = calloc((size_t)m->nbodies + 2, sizeof(int));
    nm->body_markers = malloc(sizeof(int) * ((size_t)m->nmarkers + 1));
    if (nm->body_marker_start == NULL || nm->body_markers == NULL)
        return -1;
    for (int k = 0; k < m->nmarkers; ++k)
        if (m->markers[k].tracked)
            nm->body_marker_start[m->markers[k].body + 1]++;
    for (int b = 0; b < m->nbodies; ++b)
        nm->body_marker_start[b + 1] += nm->body_marker_start[b];
    int *fill = calloc((size_t)m->nbodies + 1, sizeof(int));
    if (fill == NULL)
        return -1;
    for (int k = 0; k < m->nmarkers; ++k)
        if (m->markers[k].tracked) {
            const int b = m->markers[k].body;
            nm->body_markers[nm->body_marker_start[b] + fill[b]++] = k;
        }
    free(fill);
    return 0;
}

int hx_newton_matrix_init(hx_newton_matrix *nm, hx_dynamics *d, hx_message *msg)
{
    memset(nm, 0, sizeof *nm);
    hx_messages_init(&nm->twin_messages, NULL);
    nm->d = d;
    nm->n = d->n;
    nm->m = d->nq + d->nu;
    nm->nf = d->m->nforces;
    const int nc = d->m->ncouplers;
    nm->y = calloc(3 * (size_t)nm->n + 1, sizeof(double));
    nm->coupled = calloc((size_t)d->nu + 1, sizeof(int));
    nm->load_map = calloc(12 * ((size_t)d->m->nbodies + 1), sizeof(double));
    int ok = nm->y != NULL && nm->coupled != NULL && nm->load_map != NULL &&
             body_marker_lists(nm) == 0 && hx_frames_clone(&nm->probe, &d->frames) == 0;
    if (ok) {
        nm->f_plus = nm->y + nm->n;
        nm->f_minus = nm->f_plus + nm->n;
        nm->ncoupled = nc > 0 ? hx_constraints_coupled(d, nm->coupled) : 0;
        const size_t k = (size_t)nm->ncoupled;
        nm->projector = calloc(k * k + 2 * k + (size_t)nc * ((size_t)nc + 1) + 1, sizeof(double));
        nm->coupler_work = nm->projector + k * k;
        nm->coupled_at = calloc(k + 1, sizeof(int));
        ok = nm->projector != NULL && nm->coupled_at != NULL;
    }
    if (!ok || hx_element_blocks_init(nm, msg) != 0 || hx_stateeqn_blocks_init(nm, msg) != 0 ||
        hx_newton_pattern(nm) != 0) {
        hx_newton_matrix_free(nm);
        return hx_fail(msg, "out of memory");
    }
    hx_element_blocks_locate(nm);
    return 0;
}

void hx_newton_matrix_free(hx_newton_matrix *nm)
{
    hx_sparsity_free(&nm->pattern);
    free(nm->source);
    free(nm->why);
    free(nm->twin_partials);
    free(nm->element_rows);
    free(nm->load_map);
    hx_frames_free(&nm->probe);
    free(nm->body_markers);
    free(nm->body_marker_start);
    hx_stateeqn_blocks_free(nm);
    free(nm->coupled);
    free(nm->coupled_at);
    free(nm->projector);
    free(nm->y);
    hx_messages_destroy(&nm->twin_messages);
    memset(nm, 0, sizeof *nm);
}

/* The right-hand side at (t, y) as the dynamics keeps it: the integrator's
 * own last evaluation when it was there (CVODE builds J at the state whose f
 * it has just taken), else one more. */
static int evaluated_at(hx_newton_matrix *nm, double t, const double *y)
{
    hx_dynamics *d = nm->d;
    if (d->evaluated && d->evaluated_t == t &&
        memcmp(d->evaluated_y, y, sizeof(double) * (size_t)nm->n) == 0)
        return 0;
    nm->evaluations++;
    return hx_dynamics_rhs(d, t, y, nm->f_plus);
}

int hx_newton_matrix_build(hx_newton_matrix *nm, double t, const double *y, double *values)
{
    hx_dynamics *d = nm->d;
    if (evaluated_at(nm, t, y) != 0)
        return -1;
    nm->values = values;
    memset(values, 0, sizeof(double) * (size_t)nm->pattern.nnz);
    memcpy(nm->y, y, sizeof(double) * (size_t)nm->n);
    hx_frames_copy(&nm->probe, &d->frames);
    hx_body_blocks(nm, y);
    /* the element calls below may set the dynamics' state: the element
     * blocks, which read it, come first */
    if (hx_element_blocks(nm, t, y) != 0 || hx_load_blocks(nm, t, y) != 0 ||
        hx_stateeqn_blocks(nm, t, y) != 0 || hx_coupler_blocks(nm, t, y) != 0 ||
        hx_routine_blocks(nm, t, y) != 0)
        return -1;
    return 0;
}

void hx_newton_matrix_describe(const hx_newton_matrix *nm, char *text, size_t size)
{
    int counts[3] = {0, 0, 0};
    for (int k = 0; k < nm->nf; ++k)
        counts[nm->source[k]]++;
    int len = snprintf(text, size, "Newton matrix from the elements' partials: %d by FIESUB's own,"
                       " %d by their FIESUB twin, %d by differences of the element alone",
                       counts[0], counts[1], counts[2]);
    for (int k = 0; k < nm->nf && len > 0 && (size_t)len < size; ++k)
        if (nm->source[k] == HX_PARTIALS_DIFFERENCES)
            len += snprintf(text + len, size - (size_t)len, "\n    %s %d by differences: %s",
                            nm->d->force_binding[k]->element, nm->d->force_binding[k]->id,
                            nm->why + k * HX_NEWTON_WHY);
    hx_stateeqn_blocks_describe(nm, text, size);
}
