/*
 * What a USERSUB Reference_Variable's VARSUB reads, as its dependency pass
 * declared it (docs/interface.md §5.1): the markers and Control_Diff states
 * whose columns a force reading the variable depends on (the Jacobian's
 * pattern and differences, sim/jacobian/).
 */
#ifndef HX_SIM_DYNAMICS_VARSUB_READS_H
#define HX_SIM_DYNAMICS_VARSUB_READS_H

#include "host/queries.h"
#include "sim/dynamics/dynamics.h"

/* Variable k's (a USERSUB one) declared reads of one kind, in the order
 * declared (one may repeat: the callers keep each once), at most max: marker indices (HX_READS_MARKERS) or Control_Diff slots
 * (HX_READS_DIFF). Their count; 0 for any other variable. */
int hx_varsub_reads(const hx_dynamics *d, int k, enum hx_query_reads reads, int *out, int max);

#endif
