/*
 * Param_Unit's unit names (MotionSolve spellings such as MILLIMETER, NEWTON,
 * KILOGRAM, SECOND, KILO_NEWTON or KNEWTON; case and underscores ignored) and
 * their sizes in SI, in the order c_gtunts reports them.
 */
#ifndef HX_MODEL_UNITS_H
#define HX_MODEL_UNITS_H

#include "usrsub/solver_abi.h"

/* Size in SI of the named unit of a kind; 0, or -1 when the name is unknown. */
int hx_unit_size(enum usrsub_unit_kind kind, const char *name, double *si);

/* The accepted names of a kind, for messages. */
const char *hx_unit_names(enum usrsub_unit_kind kind);

#endif
