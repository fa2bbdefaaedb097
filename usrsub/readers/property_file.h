/*
 * The one driver of the TeimOrbit property files (.gbs, .gbi, .gfj;
 * docs/interface.md §4): read the file, check its [HEADER] FILE_TYPE, work
 * out the unit factors of its [UNITS] block against the model's units, then
 * hand the parsed file to the reader of that kind.
 */
#ifndef USRSUB_READERS_PROPERTY_FILE_H
#define USRSUB_READERS_PROPERTY_FILE_H

#include "usrsub/core/message.h"
#include "usrsub/readers/property_units.h"
#include "usrsub/readers/teimorbit.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What a property-file read produces besides the model: a sentence worth
 * one notice to the user (values used without conversion, a suspicious
 * matrix), when has_notice is set. */
typedef struct usrsub_read_report {
    usrsub_message notice;
    int has_notice;
} usrsub_read_report;

/* Appends a sentence to the report's notice. */
void usrsub_property_file_notice(usrsub_read_report *report, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Reads the blocks of one kind of file into ctx; returns 0 or -1 with msg. */
typedef int usrsub_property_body_fn(const usrsub_teim_file *f, const usrsub_unit_factors *units,
                                    void *ctx, usrsub_read_report *report, usrsub_message *msg);

/* Reads path, checks FILE_TYPE = file_type (its description, e.g. "a bushing
 * property file", goes in the message when it differs), converts units
 * against model_scales (NULL: the model declares none) and calls body. */
int usrsub_property_file_read(const char *path, const char *file_type, const char *description,
                              const double *model_scales, usrsub_property_body_fn *body,
                              void *ctx, usrsub_read_report *report, usrsub_message *msg);

/* [GLOBAL] ROTATION_MEASURE = 'PROJECTION_ANGLES' (the default) or
 * 'ROTATION_VECTOR', of a .gbs or .gfj file (docs/interface.md §3.7). */
int usrsub_property_file_rotation_measure(const usrsub_teim_file *f, int *measure,
                                          usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
