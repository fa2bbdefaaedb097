/* Reads a .gfj flexible-joint file (docs/interface.md §3.5, §4). */
#ifndef USRSUB_READERS_FLEX_JOINT_READER_H
#define USRSUB_READERS_FLEX_JOINT_READER_H

#include "usrsub/core/flex_joint.h"
#include "usrsub/readers/property_file.h"

#ifdef __cplusplus
extern "C" {
#endif

/* report receives the sentences worth one warning: values used without
 * conversion, a stiffness that is not symmetric or not positive
 * semi-definite, a damping that is not positive semi-definite. model_scales
 * NULL: the model declares no units. */
int usrsub_flex_joint_read(const char *path, const double *model_scales,
                           usrsub_flex_joint **joint, usrsub_read_report *report,
                           usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
