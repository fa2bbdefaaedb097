/*
 * Adams' C-style form of the user routines (docs/interface.md §5.3): a
 * mixed-case name (Gfosub, Cousub, ...), a constant record of the element
 * first (its id, its USER list, the ids of its markers or joints), then the
 * time and flags by value, then the results. The harness binds it for an
 * element whose routine has its default name when the library exports none
 * of the classic spellings of that name, and builds the record from the
 * element.
 */
#ifndef HX_HOST_RECORDS_H
#define HX_HOST_RECORDS_H

#include "host/binding.h"

/* Binds the C-style functions of b (its default names, e.g. GFOSUB as
 * Gfosub) in the library `handle`, at `path`, and builds b->record: 0, or -1
 * (out of memory, or a name the library does not export: msg). Not for a
 * YFOSUB, which has no C-style form (binding.c never asks). */
int hx_record_bind(hx_binding *b, void *handle, const char *path, hx_message *msg);
void hx_record_free(struct hx_record *r);

/* Calls of the bound functions, with the classic forms' arguments. */
void hx_record_coupler(hx_binding *b, int which, double time, double *disp, int iflag,
                       double *out);
/* Gfosub, Vfosub, Vtosub, Sfosub, Varsub, Difsub (flag: dflag), Motsub (flag:
 * iord), Reqsub (flag unused). */
void hx_record_values(hx_binding *b, double time, int flag, int iflag, double *result);
void hx_record_fiesub(hx_binding *b, double time, double *disp, double *velo, int dflag,
                      int iflag, double *field, double *dfddis, double *dfdvel);

#endif
