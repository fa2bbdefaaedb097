/*
 * The library's only door to its host: every call to a host utility
 * (c_errmes, c_usrmes, c_gtstrg, c_gtunts, c_sysary) goes through here, so a
 * host with other prototypes needs a change in host.c alone.
 */
#ifndef USRSUB_HOST_H
#define USRSUB_HOST_H

#include "usrsub/readers/units.h"
#include "usrsub/solver_abi.h"

/* An input error: c_errmes(1, text, id, "STOP"). */
void usrsub_host_report_error(int id, const char *text);
/* c_usrmes(1, text, id, "INFO"). */
void usrsub_host_report_notice(int id, const char *text);

/* Text of Reference_String string_id, NUL-terminated and without Fortran
 * padding. Returns 0, or -1 when the host has no such string. */
int usrsub_host_read_string(int string_id, char *text, int capacity);

/* Sizes of the model's units in SI, in enum usrsub_unit_kind order (angles
 * in radians), from c_gtunts. Returns 1 when the model declares its units, 0
 * when it does not, -1 when the host's sizes are not positive and finite. */
int usrsub_host_model_units(double scales[USRSUB_UNIT_COUNT]);

/* c_sysfnc; returns 0 when the host answered. */
int usrsub_host_query_value(const char *fnc, const int *ipar, int nsize, double *value);

/* c_sysary; returns 0 when the host answered with the expected count. */
int usrsub_host_query_array(const char *fnc, const int *ipar, int nsize, double *states,
                     int expected);

#endif
