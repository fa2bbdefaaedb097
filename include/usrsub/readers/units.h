/*
 * Unit names and their sizes in SI (metre, newton, kilogram, second, radian).
 * Accepts the TeimOrbit property-file spellings ('mm', 'newton', 'kg_force',
 * 'degree', ...) and MotionSolve's Param_Unit ones (MILLIMETER, KNEWTON, ...),
 * case-insensitively.
 */
#ifndef USRSUB_UNITS_H
#define USRSUB_UNITS_H

#include "usrsub/solver_abi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Size of the named unit of the given kind in SI; returns 0, or -1 when the
 * name is unknown for that kind. */
int usrsub_unit_size(enum usrsub_unit_kind kind, const char *name, double *si);

/* Comma-separated list of the accepted names of a kind, for messages. */
const char *usrsub_unit_names(enum usrsub_unit_kind kind);

#ifdef __cplusplus
}
#endif

#endif
