/*
 * Unit names and their sizes in SI (metre, newton, kilogram, second, radian).
 * Accepts the TeimOrbit property-file spellings ('mm', 'newton', 'kg_force',
 * 'degree', ...) and MotionSolve's Param_Unit ones (MILLIMETER, KNEWTON, ...),
 * case-insensitively.
 */
#ifndef USRSUB_UNITS_H
#define USRSUB_UNITS_H

#ifdef __cplusplus
extern "C" {
#endif

/* The base quantities the library converts, and the order of its arrays of
 * unit sizes (the model's, as the host reports them, and a file's). */
enum usrsub_unit_kind {
    USRSUB_UNIT_LENGTH = 0, /* metre */
    USRSUB_UNIT_FORCE = 1,  /* newton */
    USRSUB_UNIT_MASS = 2,   /* kilogram */
    USRSUB_UNIT_TIME = 3,   /* second */
    USRSUB_UNIT_ANGLE = 4,  /* radian */
    USRSUB_UNIT_COUNT = 5
};

/* Size of the named unit of the given kind in SI; returns 0, or -1 when the
 * name is unknown for that kind. */
int usrsub_units_size(enum usrsub_unit_kind kind, const char *name, double *si);

/* Comma-separated list of the accepted names of a kind, for messages. */
const char *usrsub_units_names(enum usrsub_unit_kind kind);

#ifdef __cplusplus
}
#endif

#endif
