/*
 * The force elements' blocks of the Jacobian (jacobian.h). With
 * d = p_I - p_J and the deformation disp = (R_J^T d, angles of R_J^T R_I),
 * velo = (R_J^T (v_I - v_J - w_J x d), R_J^T (w_I - w_J)), a motion of the
 * two markers (body_motion.h) changes them by
 *   ddisp_t = R_J^T (dd - dth_J x d)
 *   ddisp_r = A R_J^T (dth_I - dth_J)        A: the angles' slopes in a turn
 *   dvelo_t = R_J^T (dv_I - dv_J - dw_J x d - w_J x dd - dth_J x x)
 *   dvelo_r = R_J^T (dw_I - dw_J - dth_J x (w_I - w_J))
 * and the outputs by dfddis ddisp + dfdvel dvelo; the force they make on the
 * bodies turns and moves with them (hx_jacobian_applied_force).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "host/invoke.h"
#include "base/finite.h"
#include "base/vecmath.h"
#include "sim/dynamics/element_forces.h"
#include "sim/dynamics/failure.h"
#include "sim/jacobian/jacobian_parts.h"
#include "frames/measures.h"

#define TWIN_TOLERANCE 1e-9

/* An element's rows per column: for each of its (up to 3) bodies' 13
 * columns, where its I and J bodies' rows sit. */
#define ELEMENT_ROWS (3 * 13 * 2)

/* The twin's results are in J's axes; the GFOSUB result in the reference
 * marker's: the two compare only when those axes coincide for good. */
static int same_axes(const hx_model *m, const hx_force *f)
{
    if (f->ref_marker == f->j_marker)
        return 1;
    if (f->ref_marker < 0)
        return 0;
    const hx_marker *r = &m->markers[f->ref_marker], *j = &m->markers[f->j_marker];
    return r->body == j->body && memcmp(r->R_local, j->R_local, sizeof r->R_local) == 0;
}

int hx_element_blocks_init(hx_jacobian *jac, hx_message *msg)
{
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    const size_t f1 = (size_t)jac->nf + 1;
    jac->source = calloc(f1, sizeof *jac->source);
    jac->why = calloc(f1 * HX_JACOBIAN_WHY, 1);
    jac->twin_partials = calloc(72 * f1, sizeof(double));
    jac->element_rows = malloc(ELEMENT_ROWS * f1 * sizeof(int));
    if (jac->source == NULL || jac->why == NULL || jac->twin_partials == NULL ||
        jac->element_rows == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < jac->nf; ++k) {
        const hx_force *f = &m->forces[k];
        const hx_binding *b = d->force_binding[k];
        char *why = jac->why + k * HX_JACOBIAN_WHY;
        if (f->interface == HX_FORCE_FIESUB) {
            jac->source[k] = HX_PARTIALS_FIESUB; /* the build's evaluation asks for them */
        } else if (b->twin == NULL) {
            jac->source[k] = HX_PARTIALS_DIFFERENCES;
            snprintf(why, HX_JACOBIAN_WHY, "its library exports no FIESUB twin of %s", b->names[0]);
        } else if (!same_axes(m, f)) {
            jac->source[k] = HX_PARTIALS_DIFFERENCES;
            snprintf(why, HX_JACOBIAN_WHY, "its ref_marker_id is not its J marker, whose axes the"
                     " twin %s answers in", b->twin_name);
        } else {
            jac->source[k] = HX_PARTIALS_TWIN;
        }
    }
    return 0;
}

/* The bodies whose columns move element k's outputs or its load: I's, J's,
 * the outputs' axes' (-1 where none, ground, or one already listed). */
static void element_bodies(const hx_dynamics *d, int k, int bodies[3])
{
    const hx_model *m = d->m;
    const hx_force *f = &m->forces[k];
    const int axes = hx_force_output_axes(f);
    bodies[0] = m->markers[f->i_marker].body;
    bodies[1] = m->markers[f->j_marker].body;
    bodies[2] = axes >= 0 ? m->markers[axes].body : -1;
    for (int i = 0; i < 3; ++i) {
        const int b = bodies[i];
        if (b < 0 || d->dof[b].kind == HX_DOF_GROUND || (i >= 1 && b == bodies[0]) ||
            (i == 2 && b == bodies[1]))
            bodies[i] = -1;
    }
}

void hx_element_blocks_locate(hx_jacobian *jac)
{
    const hx_dynamics *d = jac->d;
    const hx_model *m = d->m;
    for (int k = 0; k < jac->nf; ++k) {
        const hx_force *f = &m->forces[k];
        const int sides[2] = {m->markers[f->i_marker].body, m->markers[f->j_marker].body};
        int bodies[3], *rows = jac->element_rows + ELEMENT_ROWS * k;
        element_bodies(d, k, bodies);
        for (int i = 0; i < ELEMENT_ROWS; ++i)
            rows[i] = -1;
        for (int i = 0; i < 3; ++i) {
            if (bodies[i] < 0)
                continue;
            int columns[13];
            const int count = hx_jacobian_body_columns(d, bodies[i], columns);
            for (int j = 0; j < count; ++j)
                for (int side = 0; side < 2; ++side)
                    rows[(13 * i + j) * 2 + side] =
                        hx_jacobian_body_rows_at(jac, sides[side], columns[j]);
        }
    }
}

/* The twin agrees with the GFOSUB result: each of force and torque to 1e-9
 * of its size (rounding of the two angle measures allowed for). */
static int twin_agrees(const double gfo[6], const double twin[6], double *worst)
{
    *worst = 0.0;
    for (int g = 0; g < 6; g += 3) {
        double size = 0.0;
        for (int i = g; i < g + 3; ++i)
            size = fmax(size, fmax(fabs(gfo[i]), fabs(twin[i])));
        for (int i = g; i < g + 3; ++i)
            if (size > 0.0)
                *worst = fmax(*worst, fabs(gfo[i] - twin[i]) / size);
    }
    return *worst <= TWIN_TOLERANCE;
}

/* The twin's partials at the build's state into jac->twin_partials; 0, or
 * 1 when the twin cannot stand in for the element (it refuses the list, its
 * partials are not finite, or its force differs from the element's), which
 * is then set aside for differences for good, the reason kept. The check is
 * made at every build: the twin is handed projection angles where the GFOSUB
 * measures through the host's 3-1-3 angles, and the two agree only as far as
 * the state allows (docs/architecture.md, the Jacobian). */
static int twin_partials(hx_jacobian *jac, int k)
{
    const hx_dynamics *d = jac->d;
    const hx_frames *fr = &jac->dd.frames;
    hx_binding *b = d->force_binding[k];
    double disp[6], velo[6], field[6], worst = 0.0;
    double *dfd = jac->twin_partials + 72 * k;
    hx_force_deformation(fr, k, disp, velo);
    hx_invoke_twin(b, fr, disp, velo, field, dfd, dfd + 36, &jac->twin_messages);
    jac->partial_calls++;
    const int refused = hx_messages_stopped(&jac->twin_messages);
    const int finite = hx_all_finite(dfd, 72);
    if (!refused && finite && twin_agrees(jac->dd.element_outputs + 6 * k, field, &worst))
        return 0;
    jac->source[k] = HX_PARTIALS_DIFFERENCES;
    char *why = jac->why + k * HX_JACOBIAN_WHY;
    if (refused)
        snprintf(why, HX_JACOBIAN_WHY, "its twin %s refused the list: %.80s", b->twin_name,
                 jac->twin_messages.stop_message);
    else if (!finite)
        snprintf(why, HX_JACOBIAN_WHY, "its twin %s returned non-finite partials at t = %g",
                 b->twin_name, fr->time);
    else
        snprintf(why, HX_JACOBIAN_WHY, "its twin %s differs from it by %.2g (relative) at t = %g",
                 b->twin_name, worst, fr->time);
    hx_messages_reset(&jac->twin_messages);
    return 1;
}

/* A[i + 3 m]: the slope of projection angle i when R_rel turns by e_m (J axes). */
static void angle_slopes(const double R[9], double A[9])
{
    /* AX = atan2(R7, R4), AY = atan2(R2, R8), AZ = atan2(R3, R0) */
    static const int num[3] = {7, 2, 3}, den[3] = {4, 8, 0};
    for (int mdir = 0; mdir < 3; ++mdir) {
        double e[3] = {0, 0, 0}, dR[9];
        e[mdir] = 1.0;
        for (int c = 0; c < 3; ++c) { /* dR = [e]x R, column by column */
            const double col[3] = {R[c], R[3 + c], R[6 + c]};
            double x[3];
            v3_cross(x, e, col);
            dR[c] = x[0], dR[3 + c] = x[1], dR[6 + c] = x[2];
        }
        for (int i = 0; i < 3; ++i) {
            const double a = R[num[i]], b = R[den[i]];
            const double r2 = a * a + b * b;
            A[i + 3 * mdir] = r2 > 0.0 ? (b * dR[num[i]] - a * dR[den[i]]) / r2 : 0.0;
        }
    }
}

/* A motion that leaves the pose as it is (a velocity's column). */
static int still_pose(const hx_motion *mo)
{
    return mo->dp[0] == 0.0 && mo->dp[1] == 0.0 && mo->dp[2] == 0.0 && mo->dth[0] == 0.0 &&
           mo->dth[1] == 0.0 && mo->dth[2] == 0.0;
}

/* The outputs' change by differences of element k alone, its body b moved
 * along column c. */
static int differenced_outputs(hx_jacobian *jac, int k, int b, int c, double dout[6])
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    hx_binding *bind = d->force_binding[k];
    const double keep = jac->y[c], h = hx_jacobian_step(jac->y, c);
    double out[2][6];
    for (int side = 0; side < 2; ++side) {
        jac->y[c] = keep + (side == 0 ? h : -h);
        hx_jacobian_move_body(jac, b, jac->y);
        hx_force_routine_call(bind, &jac->moved, 1, out[side]);
        jac->partial_calls++;
        if (hx_dynamics_check_call(d, dd, bind, out[side], 6, "force", dd->frames.time) != 0) {
            jac->y[c] = keep;
            hx_jacobian_restore_body(jac, b);
            return -1;
        }
    }
    jac->y[c] = keep;
    hx_jacobian_restore_body(jac, b);
    for (int i = 0; i < 6; ++i)
        dout[i] = (out[0][i] - out[1][i]) / (2.0 * h);
    return 0;
}

/* dout = dfddis ddisp + dfdvel dvelo, column by column of the partials
 * (contiguous); a velocity's column leaves the deformation as it is. */
static inline void output_change(const double *dfd, int pose, const double ddisp[6],
                                 const double dvelo[6], double dout[6])
{
    double sum[6] = {0, 0, 0, 0, 0, 0}; /* in registers: dout might alias dfd */
    if (pose)
        for (int c = 0; c < 6; ++c)
            for (int r = 0; r < 6; ++r)
                sum[r] += dfd[r + 6 * c] * ddisp[c];
    for (int c = 0; c < 6; ++c)
        for (int r = 0; r < 6; ++r)
            sum[r] += dfd[36 + r + 6 * c] * dvelo[c];
    for (int r = 0; r < 6; ++r)
        dout[r] = sum[r];
}

/* What the deformation's change needs of an element at the build's state. */
typedef struct pair_geometry {
    const double *R, *w_J;         /* J's axes and turning rate */
    double ARt[9];                 /* the angles' change per turn in world axes: A R^T */
    double dist[3], x[3], dw[3];   /* p_I - p_J, v_I - v_J - w_J x dist, w_I - w_J */
} pair_geometry;

static void pair_geometry_of(const hx_frame *I, const hx_frame *J, pair_geometry *g)
{
    double A[9], Rrel[9], t[3];
    hx_relative_rotation(I, J, Rrel);
    angle_slopes(Rrel, A);
    g->R = J->R;
    g->w_J = J->w;
    for (int i = 0; i < 3; ++i)
        for (int n = 0; n < 3; ++n)
            g->ARt[3 * i + n] =
                A[i] * g->R[3 * n] + A[i + 3] * g->R[3 * n + 1] + A[i + 6] * g->R[3 * n + 2];
    v3_sub(g->dist, I->p, J->p);
    v3_sub(g->x, I->v, J->v);
    v3_cross(t, J->w, g->dist);
    v3_sub(g->x, g->x, t);
    v3_sub(g->dw, I->w, J->w);
}

/* The formulas at the top for a motion pm of I's marker alone (side 0) or of
 * J's alone (side 1). */
static void side_deformation_change(const pair_geometry *g, int side, const hx_motion *pm,
                                    double ddisp[6], double dvelo[6])
{
    double t[3], v[3];
    if (side == 0) {
        m3_tapply(ddisp, g->R, pm->dp);
        m3_apply(ddisp + 3, g->ARt, pm->dth);
        v3_cross(t, g->w_J, pm->dp);
        v3_sub(v, pm->dv, t);
        m3_tapply(dvelo, g->R, v);
        m3_tapply(dvelo + 3, g->R, pm->dw);
        return;
    }
    v3_cross(t, pm->dth, g->dist); /* ddisp_t = -R^T (dp_J + dth_J x d) */
    v3_add(v, pm->dp, t);
    v3_scale(v, v, -1.0);
    m3_tapply(ddisp, g->R, v);
    m3_apply(ddisp + 3, g->ARt, pm->dth);
    v3_scale(ddisp + 3, ddisp + 3, -1.0);
    v3_cross(t, pm->dw, g->dist); /* dvelo_t = -R^T (dv_J + dw_J x d - w_J x dp_J + dth_J x x) */
    v3_add(v, pm->dv, t);
    v3_cross(t, g->w_J, pm->dp);
    v3_sub(v, v, t);
    v3_cross(t, pm->dth, g->x);
    v3_add(v, v, t);
    v3_scale(v, v, -1.0);
    m3_tapply(dvelo, g->R, v);
    v3_cross(t, pm->dth, g->dw); /* dvelo_r = -R^T (dw_J + dth_J x dw) */
    v3_add(v, pm->dw, t);
    v3_scale(v, v, -1.0);
    m3_tapply(dvelo + 3, g->R, v);
}

/* The block of an element with partials (FIESUB's own or its twin's): I
 * and J on two bodies and the outputs in J's axes (element_bodies), so that
 * a column moves one side only; hx_jacobian_applied_force's sums written out
 * for it, the load's rows found once (hx_element_blocks_locate). */
static void block_from_partials(hx_jacobian *jac, int k, const double *y,
                                const hx_applied_force *a, const double *dfd,
                                const int bodies[3], const int *rows)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_frames *fr = &dd->frames;
    const hx_force *f = &d->m->forces[k];
    const hx_frame *I = &fr->markers[f->i_marker], *J = &fr->markers[f->j_marker];
    pair_geometry g;
    pair_geometry_of(I, J, &g);
    const int loaded[2] = {d->dof[a->bi].kind != HX_DOF_GROUND,
                           d->dof[a->bj].kind != HX_DOF_GROUND};
    const int free[2] = {d->dof[a->bi].kind == HX_DOF_FREE, d->dof[a->bj].kind == HX_DOF_FREE};
    double arm[2][3]; /* from each body's centre to the point of application, I */
    v3_sub(arm[0], I->p, fr->bodies[a->bi].p);
    v3_sub(arm[1], I->p, fr->bodies[a->bj].p);
    for (int side = 0; side < 2; ++side) {
        const int b = bodies[side];
        if (b < 0)
            continue;
        int columns[13];
        const int count = hx_jacobian_body_columns(d, b, columns);
        const hx_frame *fb = &fr->bodies[b];
        for (int j = 0; j < count; ++j) {
            hx_motion mo, pm; /* the body's motion, and its marker's (I or J) */
            hx_body_column_motion(d, b, j, y, fb, &mo);
            hx_point_motion(fb, &mo, side == 0 ? I : J, &pm);
            double ddisp[6], dvelo[6], dout[6], dF[3], dT[3], t[3];
            side_deformation_change(&g, side, &pm, ddisp, dvelo);
            output_change(dfd, !still_pose(&mo), ddisp, dvelo, dout);
            m3_apply(dF, a->R_A, dout);
            m3_apply(dT, a->R_A, dout + 3);
            if (side == 1) { /* the axes turn with J's body */
                v3_cross(t, mo.dth, a->F);
                v3_add(dF, dF, t);
                v3_cross(t, mo.dth, a->T);
                v3_add(dT, dT, t);
            }
            /* the arms move by I's motion less their centre's */
            double darm[2][3];
            if (side == 0) {
                v3_sub(darm[0], pm.dp, mo.dp);
                v3_copy(darm[1], pm.dp);
            } else {
                v3_set(darm[0], 0.0, 0.0, 0.0);
                v3_scale(darm[1], mo.dp, -1.0);
            }
            for (int on = 0; on < 2; ++on) {
                if (!loaded[on])
                    continue;
                const double sign = on == 0 ? 1.0 : -1.0;
                const int body = on == 0 ? a->bi : a->bj, at = rows[(13 * side + j) * 2 + on];
                double torque[3], force[3];
                v3_cross(torque, darm[on], a->F);
                v3_cross(t, arm[on], dF);
                v3_add(torque, torque, t);
                v3_add(torque, torque, dT);
                if (free[on] && at >= 0) {
                    hx_jacobian_free_body_load(jac->values + at, jac->load_map + 12 * body, sign, dF,
                                             torque);
                    continue;
                }
                v3_scale(torque, torque, sign);
                v3_scale(force, dF, sign);
                hx_jacobian_body_load(jac, body, columns[j], at, force, torque);
            }
        }
    }
}

/* The block of an element by differences of its outputs alone, its load
 * applied as hx_jacobian_applied_force says. */
static int block_by_differences(hx_jacobian *jac, int k, const double *y,
                                const hx_applied_force *a, const int bodies[3], const int *rows)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    for (int i = 0; i < 3; ++i) {
        const int b = bodies[i];
        if (b < 0)
            continue;
        int columns[13];
        const int count = hx_jacobian_body_columns(d, b, columns);
        for (int j = 0; j < count; ++j) {
            hx_motion mo;
            double dout[6];
            hx_body_column_motion(d, b, j, y, &dd->frames.bodies[b], &mo);
            if (differenced_outputs(jac, k, b, columns[j], dout) != 0)
                return -1;
            hx_jacobian_applied_force(jac, a, columns[j], b, &mo, dout, rows + (13 * i + j) * 2);
        }
    }
    return 0;
}

static int element_block(hx_jacobian *jac, int k, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_model *m = d->m;
    const hx_force *f = &m->forces[k];
    const hx_frames *fr = &dd->frames;
    /* a twin that cannot stand in sets the element aside for differences */
    if (jac->source[k] == HX_PARTIALS_TWIN)
        twin_partials(jac, k);
    hx_applied_force a;
    a.bi = m->markers[f->i_marker].body;
    a.bj = m->markers[f->j_marker].body;
    const int axes = hx_force_output_axes(f);
    a.ba = axes >= 0 ? m->markers[axes].body : -1;
    a.R_A = axes >= 0 ? fr->markers[axes].R : hx_world_frame.R;
    a.I = &fr->markers[f->i_marker];
    v3_copy(a.F, dd->element_load + 6 * k);
    v3_copy(a.T, dd->element_load + 6 * k + 3);
    const int *rows = jac->element_rows + ELEMENT_ROWS * k;
    int bodies[3];
    element_bodies(d, k, bodies);
    if (jac->source[k] == HX_PARTIALS_DIFFERENCES)
        return block_by_differences(jac, k, y, &a, bodies, rows);
    const double *dfd = jac->source[k] == HX_PARTIALS_FIESUB ? dd->element_partials + 72 * k
                                                            : jac->twin_partials + 72 * k;
    if (jac->source[k] == HX_PARTIALS_FIESUB && /* a twin's were checked when taken */
        hx_dynamics_check_call(d, dd, d->force_binding[k], dfd, 72,
                               "value among its partials (dfddis, dfdvel)", fr->time) != 0)
        return -1;
    /* with partials the outputs are in J's axes (hx_element_blocks_init), and
     * I and J are on two bodies (the model's reader refuses one) */
    block_from_partials(jac, k, y, &a, dfd, bodies, rows);
    return 0;
}

int hx_element_blocks(hx_jacobian *jac, double t, const double *y)
{
    (void)t;
    for (int k = 0; k < jac->nf; ++k)
        if (!jac->d->force_off[k] && element_block(jac, k, y) != 0)
            return -1; /* one switched off puts nothing on the bodies, nothing here */
    return 0;
}
