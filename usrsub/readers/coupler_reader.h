/* Decodes a coupler's USER list (docs/interface.md §2) into the core's
 * coupler, reading the table files of code-4 terms. */
#ifndef USRSUB_READERS_COUPLER_READER_H
#define USRSUB_READERS_COUPLER_READER_H

#include "usrsub/core/coupler.h"
#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Looks up the text of a Reference_String (the path of a code-4 table file).
 * Returns 0 and a NUL-terminated text, or -1 when there is no such string. */
typedef int usrsub_string_lookup(void *ctx, int string_id, char *text, int capacity);

/* Decodes the USER list for ndisp joints. A code-4 file's path is taken
 * relative to the working directory, as a solver run from the model's folder
 * sees it. On error writes msg (parameter, file and line) and returns -1. */
int usrsub_coupler_decode(usrsub_coupler *c, const double *par, int npar, int ndisp,
                          usrsub_string_lookup *lookup, void *lookup_ctx,
                          usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
