/* The energy of a state of the dynamics. */
#ifndef HX_SIM_DYNAMICS_ENERGY_H
#define HX_SIM_DYNAMICS_ENERGY_H

#include "sim/dynamics/dynamics.h"

/* In force * length units. */
typedef struct hx_energy {
    double total;     /* kinetic + gravity potential + elastic - work of the loads and
                       * of the time-dependent constraints (motions, GCONs of TIME) */
    double kinetic;
    double elastic;   /* the force elements' potential at their deformation */
    double balance;   /* kinetic + gravity potential - work of loads, drives, elements:
                       * constant whatever the elements do (damping included),
                       * so its drift is the integrator's alone */
} hx_energy;

/* The energy at (t, y); dd's kinematics are set to it. */
hx_energy hx_energy_of(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y);

/* Energy the force elements took out between two energies of a run: the work
 * they did not store as elastic energy (total - balance is elastic + their
 * work). */
double hx_dissipated(const hx_energy *e, const hx_energy *e0);

#endif
