/*
 * The Reference_Variable values user routines read through c_sysfnc VARVAL
 * (docs/interface.md §5.1, §7.10): after the dependency passes, the
 * variables each VARSUB declared join the order the variables are computed
 * in (a cycle through a VARSUB refused as a cycle of VARVALs is), and a
 * model whose routines read any has its variables computed at every
 * right-hand side. Only a VARSUB or a DIFSUB, which run after the
 * variables' stage, may read one; any other routine that declares one is
 * refused.
 */
#ifndef HX_HOST_VARIABLE_READS_H
#define HX_HOST_VARIABLE_READS_H

#include "host/binding.h"

/* 0, or -1 with msg ("model.xml:12: Reference_Variable 3 (its VARSUB)
 * reads VARVAL(4), ..." for a cycle; a routine that may not read one;
 * out of memory). */
int hx_bind_variable_reads(hx_model *m, const hx_bindings *bs, hx_message *msg);

#endif
