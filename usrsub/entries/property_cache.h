/*
 * Property files parsed once per (kind, real path, model units) and shared by
 * every element that names them; immutable once parsed, freed when the
 * library is unloaded. A file that fails to parse is not kept, so each
 * element naming it reports the error.
 */
#ifndef USRSUB_PROPERTY_CACHE_H
#define USRSUB_PROPERTY_CACHE_H

#include "usrsub/core/message.h"
#include "usrsub/readers/property_file.h"

typedef int usrsub_property_read_fn(const char *path, const double *model_scales, void **property,
                             usrsub_read_report *report, usrsub_message *msg);
typedef void usrsub_property_free_fn(void *property);

/* The parsed property; report receives notices only on the call that parsed it. */
const void *usrsub_property_cache_get(const char *kind, const char *path, const double *model_scales,
                               usrsub_property_read_fn *read, usrsub_property_free_fn *release,
                               usrsub_read_report *report, usrsub_message *msg);

/* Number of files held; for tests. */
int usrsub_property_cache_size(void);

void usrsub_property_cache_clear(void);

#endif
