/*
 * The [UNITS] block of a property file, and factors that turn its values into
 * the model's units (as c_gtunts reports them). Without model units, or
 * without a [UNITS] block, values are used as they are (and the reader says so).
 */
#ifndef USRSUB_PROPERTY_UNITS_H
#define USRSUB_PROPERTY_UNITS_H

#include "usrsub/core/message.h"
#include "usrsub/readers/teimorbit.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_unit_factors {
    /* file unit / model unit, per base quantity */
    double length, force, mass, time, angle;
    double model_time_seconds; /* the model's time unit in s (1 when it declares none) */
    int converted; /* 0: values used as they are */
} usrsub_unit_factors;

/* Reads [UNITS] (LENGTH, ANGLE, FORCE, MASS, TIME) of f. model_scales: the
 * model's units in SI (NULL when the model declares none). notice receives a
 * sentence when values are used as they are. */
int usrsub_property_units_read(const usrsub_teim_file *f, const double *model_scales,
                               usrsub_unit_factors *factors, usrsub_message *notice,
                               int *has_notice, usrsub_message *msg);

/* Factor of a quantity of dimension force^f length^l time^t angle^a. */
double usrsub_property_units_factor(const usrsub_unit_factors *u, int f, int l, int t, int a);

/* Factors of a bushing direction's displacement (length or angle) and force
 * (force or torque); k = 0..2 translational, 3..5 rotational. */
double usrsub_property_units_displacement_factor(const usrsub_unit_factors *u, int k);
double usrsub_property_units_force_factor(const usrsub_unit_factors *u, int k);

#ifdef __cplusplus
}
#endif

#endif
