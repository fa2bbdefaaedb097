/*
 * The force elements' blocks of the Newton matrix (newton_matrix.h). With
 * d = p_I - p_J and the deformation disp = (R_J^T d, angles of R_J^T R_I),
 * velo = (R_J^T (v_I - v_J - w_J x d), R_J^T (w_I - w_J)), a motion of the
 * two markers (body_motion.h) changes them by
 *   ddisp_t = R_J^T (dd - dth_J x d)
 *   ddisp_r = A R_J^T (dth_I - dth_J)        A: the angles' slopes in a turn
 *   dvelo_t = R_J^T (dv_I - dv_J - dw_J x d - w_J x dd - dth_J x x)
 *   dvelo_r = R_J^T (dw_I - dw_J - dth_J x (w_I - w_J))
 * and the outputs by dfddis ddisp + dfdvel dvelo; the force they make on the
 * bodies turns and moves with them (hx_newton_applied_force).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/finite.h"
#include "base/vecmath.h"
#include "sim/dynamics/stage_failure.h"
#include "sim/newton/newton_parts.h"
#include "frames/measures.h"

#define TWIN_TOLERANCE 1e-9

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

int hx_element_blocks_init(hx_newton_matrix *nm, hx_message *msg)
{
    const hx_dynamics *d = nm->d;
    const hx_model *m = d->m;
    const size_t f1 = (size_t)nm->nf + 1;
    nm->source = calloc(f1, sizeof *nm->source);
    nm->why = calloc(f1 * HX_NEWTON_WHY, 1);
    nm->twin_partials = calloc(72 * f1, sizeof(double));
    if (nm->source == NULL || nm->why == NULL || nm->twin_partials == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < nm->nf; ++k) {
        const hx_force *f = &m->forces[k];
        const hx_binding *b = d->force_binding[k];
        char *why = nm->why + k * HX_NEWTON_WHY;
        if (f->interface == HX_FORCE_FIESUB) {
            nm->source[k] = HX_PARTIALS_FIESUB;
            /* the evaluations ask for them from now on; one made without
             * them holds none to reuse */
            if (!nm->d->field_partials)
                nm->d->evaluated = 0;
            nm->d->field_partials = 1;
        } else if (b->twin == NULL) {
            nm->source[k] = HX_PARTIALS_DIFFERENCES;
            snprintf(why, HX_NEWTON_WHY, "its library exports no FIESUB twin of %s", b->names[0]);
        } else if (!same_axes(m, f)) {
            nm->source[k] = HX_PARTIALS_DIFFERENCES;
            snprintf(why, HX_NEWTON_WHY, "its ref_marker_id is not its J marker, whose axes the"
                     " twin %s answers in", b->twin_name);
        } else {
            nm->source[k] = HX_PARTIALS_TWIN;
        }
    }
    return 0;
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

/* The twin's partials at the build's state, or the element set aside for
 * differences (for good: a twin that disagrees once is not the element's). */
static int twin_partials(hx_newton_matrix *nm, int k)
{
    hx_dynamics *d = nm->d;
    const hx_frames *s = &d->frames;
    hx_binding *b = d->force_binding[k];
    double disp[6], velo[6], field[6], worst = 0.0;
    double *dfd = nm->twin_partials + 72 * k;
    hx_force_deformation(s, k, disp, velo);
    hx_invoke_twin(b, s, disp, velo, field, dfd, dfd + 36, &nm->twin_messages);
    nm->partial_calls++;
    const int refused = hx_messages_stopped(&nm->twin_messages);
    const int finite = hx_all_finite(dfd, 72);
    if (!refused && finite && twin_agrees(d->element_outputs + 6 * k, field, &worst))
        return 0;
    nm->source[k] = HX_PARTIALS_DIFFERENCES;
    char *why = nm->why + k * HX_NEWTON_WHY;
    if (refused)
        snprintf(why, HX_NEWTON_WHY, "its twin %s refused the list: %.80s", b->twin_name,
                 nm->twin_messages.stop_message);
    else if (!finite)
        snprintf(why, HX_NEWTON_WHY, "its twin %s returned non-finite partials at t = %g",
                 b->twin_name, s->time);
    else
        snprintf(why, HX_NEWTON_WHY, "its twin %s differs from it by %.2g (relative) at t = %g",
                 b->twin_name, worst, s->time);
    hx_messages_reset(&nm->twin_messages);
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

static void deformation_change(const hx_frame *I, const hx_frame *J, const hx_motion *mI,
                               const hx_motion *mJ, const double A[9], double ddisp[6],
                               double dvelo[6])
{
    double dist[3], ddist[3], x[3], t1[3], t2[3], v[3];
    v3_sub(dist, I->p, J->p);
    v3_sub(ddist, mI->dp, mJ->dp);
    /* ddisp_t */
    v3_cross(t1, mJ->dth, dist);
    v3_sub(v, ddist, t1);
    m3_tapply(ddisp, J->R, v);
    /* ddisp_r */
    double phi[3];
    v3_sub(v, mI->dth, mJ->dth);
    m3_tapply(phi, J->R, v);
    for (int i = 0; i < 3; ++i)
        ddisp[3 + i] = A[i] * phi[0] + A[i + 3] * phi[1] + A[i + 6] * phi[2];
    /* dvelo_t: x = v_I - v_J - w_J x d */
    v3_sub(x, I->v, J->v);
    v3_cross(t1, J->w, dist);
    v3_sub(x, x, t1);
    v3_sub(v, mI->dv, mJ->dv);
    v3_cross(t1, mJ->dw, dist);
    v3_sub(v, v, t1);
    v3_cross(t1, J->w, ddist);
    v3_sub(v, v, t1);
    v3_cross(t2, mJ->dth, x);
    v3_sub(v, v, t2);
    m3_tapply(dvelo, J->R, v);
    /* dvelo_r */
    double dw[3];
    v3_sub(dw, I->w, J->w);
    v3_sub(v, mI->dw, mJ->dw);
    v3_cross(t1, mJ->dth, dw);
    v3_sub(v, v, t1);
    m3_tapply(dvelo + 3, J->R, v);
}

/* The outputs' change by differences of element k alone, its body b moved
 * along column c. */
static int differenced_outputs(hx_newton_matrix *nm, int k, int b, int c, double dout[6])
{
    hx_dynamics *d = nm->d;
    hx_binding *bind = d->force_binding[k];
    const double keep = nm->y[c], h = hx_newton_step(nm->y, c);
    double out[2][6];
    for (int side = 0; side < 2; ++side) {
        nm->y[c] = keep + (side == 0 ? h : -h);
        hx_newton_probe_move(nm, b, nm->y);
        hx_invoke_gfosub(bind, &nm->probe, 1, 0, out[side], NULL);
        nm->partial_calls++;
        if (hx_dynamics_check_stop(d, bind) != 0 || !hx_all_finite(out[side], 6)) {
            nm->y[c] = keep;
            hx_newton_probe_restore(nm, b);
            return hx_dynamics_fail(d, "%s %d returned a non-finite force at t = %g",
                                    bind->element, bind->id, d->frames.time);
        }
    }
    nm->y[c] = keep;
    hx_newton_probe_restore(nm, b);
    for (int i = 0; i < 6; ++i)
        dout[i] = (out[0][i] - out[1][i]) / (2.0 * h);
    return 0;
}

static int element_block(hx_newton_matrix *nm, int k, const double *y)
{
    hx_dynamics *d = nm->d;
    const hx_model *m = d->m;
    const hx_force *f = &m->forces[k];
    const hx_frames *s = &d->frames;
    if (nm->source[k] == HX_PARTIALS_TWIN && twin_partials(nm, k) != 0)
        return 0; /* set aside: the caller runs this element again by differences */
    const hx_frame *I = &s->markers[f->i_marker], *J = &s->markers[f->j_marker];
    hx_applied_force a;
    a.bi = m->markers[f->i_marker].body;
    a.bj = m->markers[f->j_marker].body;
    const int axes = f->interface == HX_FORCE_GFOSUB ? f->ref_marker : f->j_marker;
    a.ba = axes >= 0 ? m->markers[axes].body : -1;
    a.R_A = axes >= 0 ? s->markers[axes].R : hx_world_frame.R;
    a.I = I;
    v3_copy(a.F, d->element_load + 6 * k);
    v3_copy(a.T, d->element_load + 6 * k + 3);
    const double *dfd = nm->source[k] == HX_PARTIALS_FIESUB ? d->element_partials + 72 * k
                                                            : nm->twin_partials + 72 * k;
    double A[9], Rrel[9];
    hx_relative_rotation(I, J, Rrel);
    angle_slopes(Rrel, A);
    const int bodies[3] = {a.bi, a.bj, a.ba};
    for (int i = 0; i < 3; ++i) {
        const int b = bodies[i];
        if (b < 0 || d->dof[b].kind == HX_DOF_GROUND || (i >= 1 && b == bodies[0]) ||
            (i == 2 && b == bodies[1]))
            continue;
        int columns[13];
        const int count = hx_newton_body_columns(d, b, columns);
        const hx_frame *fb = &s->bodies[b];
        for (int j = 0; j < count; ++j) {
            hx_motion mo, mI, mJ;
            static const hx_motion still;
            hx_body_column_motion(d, b, j, y, fb, &mo);
            double dout[6];
            if (nm->source[k] == HX_PARTIALS_DIFFERENCES) {
                if (differenced_outputs(nm, k, b, columns[j], dout) != 0)
                    return -1;
            } else {
                mI = still, mJ = still;
                if (a.bi == b)
                    hx_point_motion(fb, &mo, I, &mI);
                if (a.bj == b)
                    hx_point_motion(fb, &mo, J, &mJ);
                double ddisp[6], dvelo[6];
                deformation_change(I, J, &mI, &mJ, A, ddisp, dvelo);
                for (int r = 0; r < 6; ++r) {
                    double sum = 0.0;
                    for (int c = 0; c < 6; ++c)
                        sum += dfd[r + 6 * c] * ddisp[c] + dfd[36 + r + 6 * c] * dvelo[c];
                    dout[r] = sum;
                }
            }
            hx_newton_applied_force(nm, &a, columns[j], b, &mo, dout);
        }
    }
    return 0;
}

int hx_element_blocks(hx_newton_matrix *nm, double t, const double *y)
{
    (void)t;
    for (int k = 0; k < nm->nf; ++k) {
        const hx_partials_source before = nm->source[k];
        if (element_block(nm, k, y) != 0)
            return -1;
        if (before == HX_PARTIALS_TWIN && nm->source[k] == HX_PARTIALS_DIFFERENCES &&
            element_block(nm, k, y) != 0)
            return -1;
    }
    return 0;
}
