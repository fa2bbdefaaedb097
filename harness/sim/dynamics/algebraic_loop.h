/*
 * The algebraic loop (docs/interface.md §8.8): a model whose forces,
 * variables or Control_Diff rates read accelerations (ACCX .. WDTM), joint
 * reactions (JOINT, JPRIM) or SFORCE forces (model/loop_inputs.h), or whose
 * user routines declared accelerations (host/loop_queries.h), has values
 * z that the stages compute only after the loads that read them. At each
 * right-hand side z is solved so that z = g(z), where g(z) runs the stages
 * from the variables to the constraints with the loads reading z
 * (frames.h's loop) and reads z back from the accelerations, reactions and
 * loads they give: Newton's method on z - g(z) = 0, its matrix I - dg/dz by
 * forward differences over z (one evaluation of the stages a loop input) at
 * the first iterate, taken again only when a step does not cut the residual
 * tenfold, started from z = 0 so that f(t, y) is a function of its arguments
 * alone.
 * A model without loop inputs never comes here.
 */
#ifndef HX_SIM_DYNAMICS_ALGEBRAIC_LOOP_H
#define HX_SIM_DYNAMICS_ALGEBRAIC_LOOP_H

#include "sim/dynamics/dynamics.h"

/* Converged when max |z - g(z)| <= HX_LOOP_RTOL max(max |z|, 1); refused after
 * HX_LOOP_ITERATIONS Newton steps, or when I - dg/dz has a pivot not above
 * HX_LOOP_MIN_PIVOT (its scale is the identity's: a loop that does not fix
 * its values, to the differences' noise). */
#define HX_LOOP_RTOL 1e-10
#define HX_LOOP_ITERATIONS 20
#define HX_LOOP_MIN_PIVOT 1e-6

/* The doubles of dd->loop_work a model needs (0 without a loop). */
size_t hx_algebraic_loop_work_size(const hx_dynamics *d);

/* The stages from the variables to the constraints at dd's kinematics (set
 * at (t, y)), with z solved: ydot and dd as hx_dynamics_stages left them at
 * the solution. 0, or -1 (dd->message): a stage failed, or the loop has no
 * solution Newton finds, "the algebraic loop of ACCZ(10) (Force_Scalar_TwoBody
 * 1) ... at t = 0.5: ..., residual 4.8". */
int hx_algebraic_loop_solve(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                            const double *y, double *ydot, unsigned ask);

#endif
