/* Reads a .gbi mount-limits file (docs/interface.md §3.4, §4). */
#ifndef USRSUB_READERS_MOUNT_LIMITS_READER_H
#define USRSUB_READERS_MOUNT_LIMITS_READER_H

#include "usrsub/core/mount_limits.h"
#include "usrsub/readers/property_file.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Sides with K = 0 and C = 0 (or all, with ACTIVE = 0) are left out.
 * model_scales NULL: the model declares no units. */
int usrsub_mount_limits_read(const char *path, const double *model_scales,
                             usrsub_mount_limits **limits, usrsub_read_report *report,
                             usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
