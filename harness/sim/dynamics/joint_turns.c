/* The turns of the rotations couplers take between moving bodies (joint_turns.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/vecmath.h"
#include "frames/measures.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/coordinate_rows.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/joint_coordinate.h"
#include "sim/dynamics/joint_turns.h"

#define PI 3.14159265358979323846

int hx_joint_turns_init(hx_dynamics *d, hx_message *msg)
{
    const hx_model *m = d->m;
    d->nturns = 0;
    d->turn_joint = malloc(sizeof(int) * (3 * (size_t)m->ncouplers + 1));
    d->turn_coupler = malloc(sizeof(int) * (3 * (size_t)m->ncouplers + 1));
    if (d->turn_joint == NULL || d->turn_coupler == NULL)
        return hx_fail(msg, "out of memory");
    for (int k = 0; k < m->ncouplers; ++k) {
        const hx_coupler *c = &m->couplers[k];
        for (int i = 0; i < c->njoints; ++i) {
            int known = m->joints[c->joint[i]].reduced || c->freedom[i] != 'R';
            for (int n = 0; n < d->nturns && !known; ++n)
                known = d->turn_joint[n] == c->joint[i];
            if (!known) {
                d->turn_joint[d->nturns] = c->joint[i];
                d->turn_coupler[d->nturns++] = k;
            }
        }
    }
    return 0;
}

/* A ROTATIONAL Force_SpringDamper's angle AZ(I,J) (I's x about J's z) in
 * (-pi, pi] at y, and its rate (the relative angular velocity along J's z). */
static double spring_angle(const hx_dynamics *d, const hx_load *l, const double *y,
                           double *rate)
{
    const hx_marker *mi = &d->m->markers[l->i_marker], *mj = &d->m->markers[l->j_marker];
    hx_frame fi, fj, I, J;
    hx_bodies_frame(d, mi->body, y, &fi);
    hx_bodies_frame(d, mj->body, y, &fj);
    m3_mul(I.R, fi.R, mi->R_local);
    m3_mul(J.R, fj.R, mj->R_local);
    double w[3], R[9];
    v3_sub(w, fi.w, fj.w);
    *rate = w[0] * J.R[2] + w[1] * J.R[5] + w[2] * J.R[8];
    hx_relative_rotation(&I, &J, R);
    return hx_projection_angle(R, 2); /* the AZ loads.c unwraps */
}

void hx_joint_turns_placed(const hx_dynamics *d, hx_dynamics_data *dd)
{
    const hx_model *m = d->m;
    for (int k = 0; k < m->nloads; ++k)
        if (m->loads[k].turn_stiffness != 0.0) {
            const double *ri = m->markers[m->loads[k].i_marker].R0;
            const double *rj = m->markers[m->loads[k].j_marker].R0;
            dd->turn[m->njoints + k] = atan2(ri[0] * rj[1] + ri[3] * rj[4] + ri[6] * rj[7],
                                             ri[0] * rj[0] + ri[3] * rj[3] + ri[6] * rj[6]);
            dd->turn_rate[m->njoints + k] = 0.0;
        }
    for (int j = 0; j < d->m->njoints; ++j) {
        dd->turn[j] = hx_joint_coordinate_placed(d, j);
        dd->turn_rate[j] = 0.0;
    }
    dd->turn_time = 0.0;
}

void hx_joint_turns_start(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y)
{
    for (int n = 0; n < d->nturns; ++n) {
        const int j = d->turn_joint[n];
        hx_joint_coordinate_near(d, j, 'R', y, dd->turn[j], &dd->turn[j], NULL, NULL);
        dd->turn_rate[j] = hx_coordinate_rows_joint_rate(d, j, 'R', y);
    }
    for (int k = 0; k < d->m->nloads; ++k)
        if (d->m->loads[k].turn_stiffness != 0.0) {
            const int n = d->m->njoints + k;
            const double angle = spring_angle(d, &d->m->loads[k], y, &dd->turn_rate[n]);
            dd->turn[n] += remainder(angle - dd->turn[n], 2.0 * PI);
        }
    dd->turn_time = t;
}

int hx_joint_turns_accept(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y)
{
    const double h = t - dd->turn_time;
    for (int n = 0; n < d->nturns; ++n) {
        const int j = d->turn_joint[n];
        const double rate = hx_coordinate_rows_joint_rate(d, j, 'R', y);
        const double guess = dd->turn[j] + 0.5 * h * (dd->turn_rate[j] + rate);
        double value;
        hx_joint_coordinate_near(d, j, 'R', y, guess, &value, NULL, NULL);
        if (!(fabs(value - dd->turn[j]) <= PI))
            return hx_dynamics_fail(dd, "Constraint_Coupler %d: joint %d turned %.3g rad in one"
                                    " step, from t = %.6g to %.6g: more than pi (each step's"
                                    " rotation between two moving bodies is measured from the"
                                    " last accepted one; take smaller steps)",
                                    d->m->couplers[d->turn_coupler[n]].id, d->m->joints[j].id,
                                    value - dd->turn[j], dd->turn_time, t);
        dd->turn[j] = value;
        dd->turn_rate[j] = rate;
    }
    for (int k = 0; k < d->m->nloads; ++k) {
        const hx_load *l = &d->m->loads[k];
        const int n = d->m->njoints + k;
        if (l->turn_stiffness == 0.0)
            continue;
        double rate;
        const double angle = spring_angle(d, l, y, &rate);
        const double guess = dd->turn[n] + 0.5 * h * (dd->turn_rate[n] + rate);
        const double value = guess + remainder(angle - guess, 2.0 * PI);
        if (!(fabs(value - dd->turn[n]) <= PI))
            return hx_dynamics_fail(dd, "Force_SpringDamper %d: turned %.3g rad in one step, from"
                                    " t = %.6g to %.6g: more than pi (its angle's turns are"
                                    " counted from the last accepted step; take smaller steps)",
                                    l->id, value - dd->turn[n], dd->turn_time, t);
        dd->turn[n] = value;
        dd->turn_rate[n] = rate;
    }
    dd->turn_time = t;
    return 0;
}

void hx_joint_turns_copy(const hx_dynamics *d, hx_dynamics_data *to, const hx_dynamics_data *from)
{
    const size_t nj = (size_t)d->m->njoints + (size_t)d->m->nloads; /* the springs' too */
    memcpy(to->turn, from->turn, sizeof(double) * nj);
    memcpy(to->turn_rate, from->turn_rate, sizeof(double) * nj);
    to->turn_time = from->turn_time;
}
