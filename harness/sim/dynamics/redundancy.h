/*
 * Redundant constraint rows (docs/architecture.md, the constraint system):
 * found at set-up from the rank of G M^-1 G^T at the model's initial
 * configuration and again where the set-up's assembly takes it, taken out of
 * the solves for the run (d->active, d->removed), and named for the notes and
 * the errors.
 */
#ifndef HX_SIM_DYNAMICS_REDUNDANCY_H
#define HX_SIM_DYNAMICS_REDUNDANCY_H

#include <stddef.h>

#include "sim/dynamics/dynamics.h"

/* Rows in order, each kept when its part independent of the rows kept before
 * it (in the metric M^-1) exceeds HX_REDUNDANCY_TOLERANCE of its own size;
 * the others go to d->removed. y: the model's initial state (unprojected);
 * dd: a data of d. 0, or -1 with msg. */
#define HX_REDUNDANCY_TOLERANCE 1e-6
int hx_redundancy_find(hx_dynamics *d, hx_dynamics_data *dd, const double *y,
                       hx_message *msg);

/* After hx_redundancy_find: the set-up's assembly (hx_constraints_assemble
 * from the model's state) and the rank test again at the configuration it
 * reaches, the set replaced when it differs there, up to
 * HX_REDUNDANCY_PASSES times (a set that changes assembles again from where
 * the last pass left the parts). The set found at the placed configuration
 * stays in d->removed_placed; when the set changed, the positions of the last
 * pass in d->assembled_q, where the run's initial state starts its own
 * projection. An assembly pass that fails leaves the set (the run's start
 * names the failure). 0, or -1 with msg. */
#define HX_REDUNDANCY_PASSES 4
int hx_redundancy_reassess(hx_dynamics *d, hx_dynamics_data *dd, hx_message *msg);

/* The change between the set at the placed configuration and the run's:
 * the rows redundant there and not once assembled into no_longer, those
 * redundant once assembled and not there into now (names separated by ", ",
 * size each); returns how many rows changed (0: the same set). */
int hx_redundancy_change(const hx_dynamics *d, char *no_longer, char *now, size_t size);

/* The run's set replaced: removed (ascending, nremoved) the redundant rows,
 * every other row active, G M^-1 G^T's envelope planned again. A run puts
 * back the set it started with this way. 0, or -1 with msg. */
int hx_redundancy_use(hx_dynamics *d, const int *removed, int nremoved, hx_message *msg);

/* The rank test again at y (at t), where a run's static equilibrium moved the
 * parts (equilibrium.h): when the set differs there it replaces the run's
 * (hx_redundancy_use), and the rows redundant before and not at y go into
 * no_longer, those redundant at y and not before into now (names separated
 * by ", ", size each). Returns how many rows changed (0: the same set), or
 * -1 with msg. */
int hx_redundancy_reexamine(hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                            char *no_longer, char *now, size_t size, hx_message *msg);

/* Row i's name, e.g. "JOINT/4 REVOLUTE: equation 5 (z_I . y_J)" or
 * "COUPLER/3"; returns text. */
const char *hx_redundancy_name_row(const hx_dynamics *d, int row, char *text, size_t size);

#endif
