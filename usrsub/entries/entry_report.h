/*
 * How the entries word what they tell the host: "ROUTINE element ID: what".
 * Every message leaves through host.c.
 */
#ifndef USRSUB_ENTRY_REPORT_H
#define USRSUB_ENTRY_REPORT_H

#include "element_cache.h"

/* Passes on what a set-up produced (its notice, and its error when the model
 * is NULL), when this call ran it. */
void usrsub_entry_report_setup(const char *routine, int id, int set_up_now, const void *model,
                        const usrsub_element_setup_report *report);

/* An input error found during a call (a non-finite state, a bad argument, a
 * query the host refused), reported once per routine, element and kind (a
 * string constant naming the problem; NULL: every time, for calls that break
 * the calling convention): a host that goes on calling after an error is not
 * flooded with the same sentence. */
void usrsub_entry_report_error(const char *routine, int id, const char *kind, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* 1 when id, npar and par (for npar > 0) are there and npar >= 0; else the
 * call breaks the calling convention, which is reported (every time). */
int usrsub_entry_report_arguments_ok(const char *routine, const int *id, const double *par,
                                     const int *npar);

#endif
