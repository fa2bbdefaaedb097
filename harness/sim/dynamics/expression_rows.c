/*
 * The general constraints' rows (expression_rows.h). With p_M a marker's
 * origin, p_b its body's origin, d = p_I - p_J and a the measuring axis, a
 * body's motion (dx world, a turn dtheta world about p_b) moves a measure:
 *   DX, DY, DZ (I, J, K)  d . a_K:  I's body dx . a + dtheta . ((p_I - p_b) x a),
 *                         J's the same negated, K's body dtheta . (a x d);
 *   DM (I, J)             |d|: the same with a = d / |d| (0 where I and J meet);
 *   AX, AY, AZ (I, J)     atan2(s, c), s = a_I . b_J, c = a_I . c_J (the axes of
 *                         measures.c): I's body dtheta . g, J's -dtheta . g,
 *                         g = (c (a_I x b_J) - s (a_I x c_J)) / (s^2 + c^2);
 *   the other rotations (PSI .. ROLL, INCANG) by four-point differences of
 *   the measure alone (error about 1e-13), its body turned and moved by 1e-3
 *   (rad, or of its distance from the origin), a jump of 2 pi taken out.
 * The row is sum_j df/dm_j dm_j, f's partials from the expression engine's
 * adjoint, the turn put in body axes for a free body (omega in body axes, as
 * every row: joint_equations.h), along the axis for a hinged or slid body.
 * phidot = G u + df/dt. gamma = -(dG/dt u + d(df/dt)/dt) is minus the rate
 * of phidot along the motion with u held, by four-point differences in time
 * over the bodies' exact paths (a free body's centre straight, its turn about
 * its fixed omega; a hinged body about its axis), the step 1e-3 of the time
 * the fastest body takes to turn a radian or move the model's length: its
 * error is about 1e-13 of phidot's terms (small enough that the BDF
 * Jacobian's differences of the constraint stage stay near 1e-8), and the
 * projection after each step corrects what it leaves.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "base/difference_step.h"
#include "base/vecmath.h"
#include "expr/evaluate.h"
#include "frames/measure_functions.h"
#include "model/expr/functions.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/expression_rows.h"
#include "sim/dynamics/failure.h"

#define TWO_PI 6.283185307179586476925
#define MEASURE_EPS 1e-3 /* the rotation measures' four-point differences */
#define TIME_EPS 1e-3    /* gamma's four-point differences, of the motion's time scale */

static int marker_body(const hx_model *m, int index)
{
    return index < 0 ? -1 : m->markers[index].body;
}

static int is_displacement(int function)
{
    return function >= HX_FN_DX && function <= HX_FN_DM;
}

int hx_expression_rows_init(hx_dynamics *d, double length, hx_message *msg)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->ngcons; ++k) {
        const hx_gcon *g = &m->gcons[k];
        hx_constraint_row *r = &d->rows[d->gcon_first + k];
        const hx_expr_input *in = hx_expr_inputs(g->program);
        int next = 0, displacement = 0;
        for (int j = 0; j < hx_expr_input_count(g->program); ++j) {
            if (in[j].kind != HX_EXPR_INPUT_MEASURE)
                continue;
            displacement |= is_displacement(in[j].function);
            for (int i = 0; i < 4; ++i) {
                const int body = marker_body(m, in[j].index[i]);
                if (body < 0 || d->dof[body].kind == HX_DOF_GROUND)
                    continue;
                int seen = 0;
                for (int b = 0; b < r->nblocks; ++b)
                    seen |= r->body[b] == body;
                if (seen)
                    continue;
                const int width = d->dof[body].kind == HX_DOF_FREE ? 6 : 1;
                if (r->nblocks == HX_CONSTRAINT_ROW_BLOCKS || next + width > 6 * HX_CONSTRAINT_ROW_BLOCKS)
                    return hx_fail(msg, "Constraint_General %d (line %d): its markers are on more"
                                   " than %d moving bodies, more than a row of the constraint"
                                   " system holds", g->id, g->line, HX_CONSTRAINT_ROW_BLOCKS);
                const int n = r->nblocks++;
                r->body[n] = body, r->u[n] = d->dof[body].u, r->width[n] = width;
                r->slot[n] = next;
                next += width;
            }
        }
        if (r->nblocks == 0)
            return hx_fail(msg, "Constraint_General %d (line %d): its markers are all on ground,"
                           " so it holds no moving body", g->id, g->line);
        hx_constraint_row_sort(r);
        if (next > 12)
            d->row_values = 6 * HX_CONSTRAINT_ROW_BLOCKS;
        r->scale = displacement ? length : 1.0;
    }
    return 0;
}

int hx_expression_rows_timed(const hx_dynamics *d, int k)
{
    const hx_expr_program *p = d->m->gcons[k].program;
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j)
        if (in[j].kind == HX_EXPR_INPUT_TIME)
            return 1;
    return 0;
}

size_t hx_expression_rows_work_size(const hx_dynamics *d)
{
    size_t most = 0;
    for (int k = 0; k < d->m->ngcons; ++k) {
        const hx_expr_program *p = d->m->gcons[k].program;
        const size_t need = (size_t)hx_expr_input_count(p) + hx_expr_scratch_size(p);
        most = need > most ? need : most;
    }
    return most;
}

static void add_point(double tw[6], int on, const double p[3], const double pb[3],
                      const double a[3], double sign)
{
    if (!on)
        return;
    double lever[3], c[3];
    v3_sub(lever, p, pb);
    v3_cross(c, lever, a);
    v3_axpy(tw, sign, a);
    v3_axpy(tw + 3, sign, c);
}

/* The measure with body's frame moved by step along direction c (0..2 a
 * translation, 3..5 a turn about its origin, world axes). */
static double moved_measure(const hx_model *m, const hx_frame *fb, const hx_expr_input *in,
                            const hx_frame *const f[4], const int on[4], int c, double step)
{
    hx_frame moved = *fb, mf[4];
    if (c < 3) {
        moved.p[c] += step;
    } else {
        double axis[3] = {0.0, 0.0, 0.0}, turn[9];
        axis[c - 3] = 1.0;
        m3_axis_angle(turn, axis, step);
        m3_mul(moved.R, turn, fb->R);
    }
    const hx_frame *g[4];
    for (int i = 0; i < 4; ++i) {
        g[i] = f[i];
        if (on[i]) {
            hx_marker_frame(m, &moved, in->index[i], &mf[i]);
            g[i] = &mf[i];
        }
    }
    return hx_measure_value((hx_measure)in->measure, g);
}

/* A rotation measure's twist by four-point differences of the measure alone:
 * (8 (m(h) - m(-h)) - (m(2h) - m(-2h))) / 12h, each difference wrapped. */
static void differenced_twist(const hx_model *m, const hx_frame *fb, const hx_expr_input *in,
                              const hx_frame *const f[4], const int on[4], double tw[6])
{
    for (int c = 0; c < 6; ++c) {
        const double h = c < 3 ? hx_difference_step(v3_norm(fb->p), MEASURE_EPS, 1.0)
                               : MEASURE_EPS;
        double diff[2];
        for (int k = 1; k <= 2; ++k) {
            diff[k - 1] = moved_measure(m, fb, in, f, on, c, k * h) -
                          moved_measure(m, fb, in, f, on, c, -k * h);
            if (in->function != HX_FN_INCANG)
                diff[k - 1] = remainder(diff[k - 1], TWO_PI);
        }
        tw[c] = (8.0 * diff[0] - diff[1]) / (12.0 * h);
    }
}

/* AX, AY, AZ: atan2(a_I . b_J, a_I . c_J) with the axes measures.c takes. */
static void angle_twist(const hx_expr_input *in, const hx_frame *const f[4], const int on[4],
                        double tw[6])
{
    static const int axes[3][3] = {{1, 2, 1}, {2, 0, 2}, {0, 1, 0}}; /* a_I, b_J, c_J */
    const int *k = axes[in->function - HX_FN_AX];
    double a[3], b[3], c[3], ab[3], ac[3], g[3];
    v3_set(a, f[0]->R[k[0]], f[0]->R[3 + k[0]], f[0]->R[6 + k[0]]);
    v3_set(b, f[1]->R[k[1]], f[1]->R[3 + k[1]], f[1]->R[6 + k[1]]);
    v3_set(c, f[1]->R[k[2]], f[1]->R[3 + k[2]], f[1]->R[6 + k[2]]);
    const double s = v3_dot(a, b), co = v3_dot(a, c), n = s * s + co * co;
    if (n == 0.0)
        return;
    v3_cross(ab, a, b);
    v3_cross(ac, a, c);
    for (int i = 0; i < 3; ++i)
        g[i] = (co * ab[i] - s * ac[i]) / n;
    if (on[0])
        v3_add(tw + 3, tw + 3, g);
    if (on[1])
        v3_sub(tw + 3, tw + 3, g);
}

/* The measure's derivative in body's motion: the translation of its origin
 * (tw[0..2]) and its turn about it (tw[3..5]), world axes; 0 when it reads
 * no marker there. */
static int measure_twist(const hx_model *m, const hx_frames *fr, const hx_expr_input *in,
                         int body, double tw[6])
{
    hx_frame scratch[4];
    const hx_frame *f[4];
    int on[4], any = 0;
    memset(tw, 0, sizeof(double) * 6);
    for (int i = 0; i < 4; ++i) {
        on[i] = in->index[i] >= 0 && marker_body(m, in->index[i]) == body;
        any |= on[i];
    }
    if (!any)
        return 0;
    for (int i = 0; i < 4; ++i)
        f[i] = hx_frames_marker(fr, in->index[i], &scratch[i]);
    const double *pb = fr->bodies[body].p;
    double d[3], a[3];
    v3_sub(d, f[0]->p, f[1]->p);
    if (in->function == HX_FN_DM) {
        const double n = v3_norm(d);
        if (n == 0.0)
            return 1;
        v3_scale(a, d, 1.0 / n);
        add_point(tw, on[0], f[0]->p, pb, a, 1.0);
        add_point(tw, on[1], f[1]->p, pb, a, -1.0);
        return 1;
    }
    if (is_displacement(in->function)) {
        const int c = in->function - HX_FN_DX;
        v3_set(a, f[2]->R[c], f[2]->R[3 + c], f[2]->R[6 + c]);
        add_point(tw, on[0], f[0]->p, pb, a, 1.0);
        add_point(tw, on[1], f[1]->p, pb, a, -1.0);
        if (on[2]) {
            double turn[3];
            v3_cross(turn, a, d);
            v3_add(tw + 3, tw + 3, turn);
        }
        return 1;
    }
    if (in->function >= HX_FN_AX && in->function <= HX_FN_AZ)
        angle_twist(in, f, on, tw);
    else
        differenced_twist(m, &fr->bodies[body], in, f, on, tw);
    return 1;
}

/* p times a body's twist coefficients into its block of G. */
static void add_block(const hx_dynamics *d, const hx_constraint_row *r, int blk,
                      const hx_frame *fb, const double tw[6], double p, double *G)
{
    const hx_body_dof *dof = &d->dof[r->body[blk]];
    double *g = G + r->slot[blk];
    if (dof->kind == HX_DOF_FREE) {
        double turn[3];
        m3_tapply(turn, fb->R, tw + 3);
        for (int c = 0; c < 3; ++c)
            g[c] += p * tw[c], g[3 + c] += p * turn[c];
    } else if (dof->kind == HX_DOF_REVOLUTE) {
        double lever[3], v[3];
        v3_sub(lever, fb->p, dof->origin);
        v3_cross(v, dof->axis, lever);
        g[0] += p * (v3_dot(tw, v) + v3_dot(tw + 3, dof->axis));
    } else {
        g[0] += p * v3_dot(tw, dof->axis);
    }
}

/* The row's bodies' frames placed in dd->moved at time t. */
static void place(hx_dynamics_data *dd, const hx_constraint_row *r, const hx_frame *bodies,
                  double t)
{
    dd->moved.time = t;
    for (int b = 0; b < r->nblocks; ++b) {
        dd->moved.bodies[r->body[b]] = bodies[b];
        hx_frames_update_body(&dd->moved, r->body[b]);
    }
}

/* At the frames placed: phi, G (when not NULL), phidot = G u + df/dt with the
 * bodies' velocities in their frames, and df/dt. */
static int terms(const hx_dynamics *d, hx_dynamics_data *dd, int k, double *work, double *phi,
                 double *G, double *phidot, double *ft)
{
    const hx_gcon *g = &d->m->gcons[k];
    const hx_constraint_row *r = &d->rows[d->gcon_first + k];
    const int n = hx_expr_input_count(g->program);
    double *partials = work, *scratch = work + n;
    const hx_expr_context c = {&dd->moved, NULL, NULL};
    hx_expr_fault fault;
    if (hx_expr_eval_partials(g->program, &c, phi, partials, scratch, &fault) != 0) {
        hx_message why;
        char name[32];
        snprintf(name, sizeof name, "GCON/%d", g->id);
        hx_expr_fail(&why, g->program, &fault, name);
        return hx_dynamics_fail(dd, "%s", why.text);
    }
    const hx_expr_input *in = hx_expr_inputs(g->program);
    double rate = 0.0, dt = 0.0;
    double *twist = dd->gcon_twist + 6 * HX_CONSTRAINT_ROW_BLOCKS * k;
    if (G != NULL)
        memset(twist, 0, sizeof(double) * 6 * HX_CONSTRAINT_ROW_BLOCKS);
    for (int j = 0; j < n; ++j) {
        if (in[j].kind == HX_EXPR_INPUT_TIME) {
            dt += partials[j];
            continue;
        }
        if (partials[j] == 0.0)
            continue;
        for (int b = 0; b < r->nblocks; ++b) {
            double tw[6];
            const hx_frame *fb = &dd->moved.bodies[r->body[b]];
            if (!measure_twist(d->m, &dd->moved, &in[j], r->body[b], tw))
                continue;
            rate += partials[j] * (v3_dot(tw, fb->v) + v3_dot(tw + 3, fb->w));
            if (G == NULL)
                continue;
            add_block(d, r, b, fb, tw, partials[j], G);
            for (int e = 0; e < 6; ++e)
                twist[6 * b + e] += partials[j] * tw[e];
        }
    }
    *phidot = rate + dt;
    *ft = dt;
    return 0;
}

/* A body's frame s later along its motion with its velocities held. */
static void advance(const hx_body_dof *dof, const hx_frame *f, double s, hx_frame *out)
{
    *out = *f;
    double turn[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const double w = v3_norm(f->w);
    if (w > 0.0) {
        double axis[3];
        v3_scale(axis, f->w, 1.0 / w);
        m3_axis_angle(turn, axis, s * w);
        m3_mul(out->R, turn, f->R);
    }
    if (dof->kind == HX_DOF_REVOLUTE) {
        double lever[3], moved[3];
        v3_sub(lever, f->p, dof->origin);
        m3_apply(moved, turn, lever);
        v3_add(out->p, dof->origin, moved);
        v3_cross(out->v, f->w, moved);
    } else {
        v3_axpy(out->p, s, f->v);
    }
}

int hx_expression_rows_eval(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                            const double *y, double *work, double *phi, double *G,
                            double *gamma)
{
    const hx_constraint_row *r = &d->rows[d->gcon_first + k];
    hx_frame bodies[HX_CONSTRAINT_ROW_BLOCKS], moved[HX_CONSTRAINT_ROW_BLOCKS];
    double fastest = 1.0;
    for (int b = 0; b < r->nblocks; ++b) {
        hx_bodies_frame(d, r->body[b], y, &bodies[b]);
        fastest = fmax(fastest, fmax(v3_norm(bodies[b].w), v3_norm(bodies[b].v) / r->scale));
    }
    place(dd, r, bodies, t);
    double phidot, ft;
    if (terms(d, dd, k, work, phi, G, &phidot, &ft) != 0)
        return -1;
    if (gamma == NULL)
        return 0;
    const double h = TIME_EPS / fastest;
    double rate[4], value; /* at h, -h, 2h, -2h */
    for (int s = 0; s < 4; ++s) {
        const double step = (s & 1 ? -h : h) * (s < 2 ? 1.0 : 2.0);
        for (int b = 0; b < r->nblocks; ++b)
            advance(&d->dof[r->body[b]], &bodies[b], step, &moved[b]);
        place(dd, r, moved, t + step);
        if (terms(d, dd, k, work, &value, NULL, &rate[s], &ft) != 0)
            return -1;
    }
    *gamma = -(8.0 * (rate[0] - rate[1]) - (rate[2] - rate[3])) / (12.0 * h);
    return 0;
}

int hx_expression_rows_rate(const hx_dynamics *d, hx_dynamics_data *dd, int k, double t,
                            const double *y, double *work, double *rate)
{
    const hx_constraint_row *r = &d->rows[d->gcon_first + k];
    hx_frame bodies[HX_CONSTRAINT_ROW_BLOCKS];
    for (int b = 0; b < r->nblocks; ++b)
        hx_bodies_frame(d, r->body[b], y, &bodies[b]);
    place(dd, r, bodies, t);
    double phi, phidot, ft;
    if (terms(d, dd, k, work, &phi, NULL, &phidot, &ft) != 0)
        return -1;
    *rate = -ft;
    return 0;
}
