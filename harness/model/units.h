/*
 * Param_Unit's unit names (MotionSolve spellings such as MILLIMETER, NEWTON,
 * KILOGRAM, SECOND, KILO_NEWTON or KNEWTON; case and underscores ignored) and
 * their sizes in SI.
 */
#ifndef HX_MODEL_UNITS_H
#define HX_MODEL_UNITS_H

/* The base quantities of a model's units; the order of hx_model.unit_scales. */
enum hx_unit_kind {
    HX_UNIT_LENGTH = 0, /* metre */
    HX_UNIT_FORCE = 1,  /* newton */
    HX_UNIT_MASS = 2,   /* kilogram */
    HX_UNIT_TIME = 3,   /* second */
    HX_UNIT_ANGLE = 4,  /* radian: a model's angles are always radians */
    HX_UNIT_COUNT = 5
};

/* Size in SI of the named unit of a kind; 0, or -1 when the name is unknown. */
int hx_unit_size(enum hx_unit_kind kind, const char *name, double *si);

/* A three-character name of a unit size of a kind, as c_gtunts reports the
 * model's units ("MM ", "N  ", "KG ", "S  ", ...); "   " for a size without one. */
const char *hx_unit_abbreviation(enum hx_unit_kind kind, double si);

/* The accepted names of a kind, for messages. */
const char *hx_unit_names(enum hx_unit_kind kind);

#endif
