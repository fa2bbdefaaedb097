/* Reads a .gbs bushing property file (docs/interface.md §3.2, §4) into a
 * bushing in the model's units. */
#ifndef USRSUB_READERS_BUSHING_READER_H
#define USRSUB_READERS_BUSHING_READER_H

#include "usrsub/core/bushing.h"
#include "usrsub/readers/property_file.h"

#ifdef __cplusplus
extern "C" {
#endif

/* model_scales NULL when the model declares no units; report receives a
 * sentence worth telling the user (values used without conversion). */
int usrsub_bushing_read(const char *path, const double *model_scales, usrsub_bushing **bushing,
                        usrsub_read_report *report, usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
