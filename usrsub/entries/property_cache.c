/* Shared, parsed-once property files (property_cache.h). */
#include "property_cache.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef _WIN32
#include <io.h>
#endif

#include "mutex.h"
#include "usrsub/readers/units.h"

typedef struct property_entry {
    struct property_entry *next;
    char kind[8];
    char *path; /* real path */
    int has_units;
    double units[USRSUB_UNIT_COUNT];
    void *property;
    usrsub_property_free_fn *release;
} property_entry;

static property_entry *entries;
static usrsub_mutex lock = USRSUB_MUTEX_INIT;

static int same_units(const property_entry *e, const double *scales)
{
    if (!e->has_units || scales == NULL)
        return !e->has_units && scales == NULL;
    return memcmp(e->units, scales, sizeof e->units) == 0;
}

/* The cache's key: the file's absolute path, so that two spellings of one file
 * share one parse. realpath also resolves links and fails for a missing file.
 * Windows has no realpath: _fullpath makes the path absolute and normal (drive,
 * backslashes, no . or ..) and _access keeps the failure for a missing file
 * (docs/windows.md). */
static char *real_path(const char *path, char real[PATH_MAX])
{
#ifdef _WIN32
    if (_fullpath(real, path, PATH_MAX) == NULL)
        return NULL;
    return _access(real, 0) == 0 ? real : NULL;
#else
    return realpath(path, real);
#endif
}

const void *usrsub_property_cache_get(const char *kind, const char *path, const double *model_scales,
                               usrsub_property_read_fn *read, usrsub_property_free_fn *release,
                               usrsub_read_report *report, usrsub_message *msg)
{
    char real[PATH_MAX];
    if (real_path(path, real) == NULL)
        return usrsub_fail(msg, "cannot open '%s': %s", path, strerror(errno)), NULL;
    usrsub_mutex_lock(&lock);
    for (property_entry *e = entries; e != NULL; e = e->next)
        if (strcmp(e->kind, kind) == 0 && strcmp(e->path, real) == 0 && same_units(e, model_scales)) {
            usrsub_mutex_unlock(&lock);
            return e->property;
        }
    void *property = NULL;
    property_entry *e = calloc(1, sizeof *e);
    if (e == NULL || (e->path = strdup(real)) == NULL) {
        free(e);
        usrsub_mutex_unlock(&lock);
        return usrsub_fail(msg, "out of memory"), NULL;
    }
    if (read(real, model_scales, &property, report, msg) != 0) {
        free(e->path);
        free(e);
        usrsub_mutex_unlock(&lock);
        return NULL;
    }
    snprintf(e->kind, sizeof e->kind, "%s", kind);
    e->has_units = model_scales != NULL;
    if (model_scales != NULL)
        memcpy(e->units, model_scales, sizeof e->units);
    e->property = property;
    e->release = release;
    e->next = entries;
    entries = e;
    usrsub_mutex_unlock(&lock);
    return property;
}

int usrsub_property_cache_size(void)
{
    int n = 0;
    usrsub_mutex_lock(&lock);
    for (property_entry *e = entries; e != NULL; e = e->next)
        ++n;
    usrsub_mutex_unlock(&lock);
    return n;
}

void usrsub_property_cache_clear(void)
{
    usrsub_mutex_lock(&lock);
    while (entries != NULL) {
        property_entry *next = entries->next;
        entries->release(entries->property);
        free(entries->path);
        free(entries);
        entries = next;
    }
    usrsub_mutex_unlock(&lock);
}

__attribute__((destructor)) static void usrsub_property_cache_unload(void)
{
    usrsub_property_cache_clear();
}
