/* The turns of the rotations couplers take between moving bodies (joint_turns.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

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

void hx_joint_turns_placed(const hx_dynamics *d, hx_dynamics_data *dd)
{
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
    dd->turn_time = t;
    return 0;
}

void hx_joint_turns_copy(const hx_dynamics *d, hx_dynamics_data *to, const hx_dynamics_data *from)
{
    const size_t nj = (size_t)d->m->njoints;
    memcpy(to->turn, from->turn, sizeof(double) * nj);
    memcpy(to->turn_rate, from->turn_rate, sizeof(double) * nj);
    to->turn_time = from->turn_time;
}
