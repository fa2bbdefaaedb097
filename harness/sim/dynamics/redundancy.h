/*
 * Redundant constraint rows (docs/architecture.md, the constraint system):
 * found once at set-up from the rank of G M^-1 G^T at the model's initial
 * configuration, taken out of the solves for the run (d->active, d->removed),
 * and named for the notes and the errors.
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

/* Row i's name, e.g. "JOINT/4 REVOLUTE: equation 5 (z_I . y_J)" or
 * "COUPLER/3"; returns text. */
const char *hx_redundancy_name_row(const hx_dynamics *d, int row, char *text, size_t size);

#endif
