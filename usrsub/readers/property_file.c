/* The one TeimOrbit property-file driver (property_file.h). */
#include "usrsub/readers/property_file.h"

#include "usrsub/core/rotation.h"
#include "usrsub/readers/case_compare.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void usrsub_property_file_notice(usrsub_read_report *report, const char *fmt, ...)
{
    char sentence[USRSUB_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sentence, sizeof sentence, fmt, ap);
    va_end(ap);
    const size_t used = report->has_notice ? strlen(report->notice.text) : 0;
    snprintf(report->notice.text + used, sizeof report->notice.text - used, "%s%s",
             report->has_notice ? "; " : "", sentence);
    report->has_notice = 1;
}

static int check_file_type(const usrsub_teim_file *f, const char *file_type,
                           const char *description, usrsub_message *msg)
{
    const usrsub_teim_block *h = usrsub_teim_find_block(f, "HEADER");
    const usrsub_teim_entry *type = usrsub_teim_find_entry(h, "FILE_TYPE");
    if (type == NULL)
        return usrsub_fail(msg, "'%s': no [HEADER] block with FILE_TYPE = '%s'", f->path,
                           file_type);
    if (usrsub_strcasecmp(type->value, file_type) != 0)
        return usrsub_fail(msg, "'%s' line %d: FILE_TYPE is '%s', expected '%s' (%s)", f->path,
                           type->line, type->value, file_type, description);
    return 0;
}

int usrsub_property_file_read(const char *path, const char *file_type, const char *description,
                              const double *model_scales, usrsub_property_body_fn *body,
                              void *ctx, usrsub_read_report *report, usrsub_message *msg)
{
    usrsub_teim_file *f;
    if (usrsub_teim_read(path, &f, msg) != 0)
        return -1;
    usrsub_unit_factors units;
    int status = check_file_type(f, file_type, description, msg);
    if (status == 0) {
        int has_notice = 0;
        usrsub_message notice;
        status = usrsub_property_units_read(f, model_scales, &units, &notice, &has_notice, msg);
        if (status == 0 && has_notice)
            usrsub_property_file_notice(report, "%s", notice.text);
    }
    if (status == 0)
        status = body(f, &units, ctx, report, msg);
    usrsub_teim_free(f);
    return status;
}

int usrsub_property_file_rotation_measure(const usrsub_teim_file *f, int *measure,
                                          usrsub_message *msg)
{
    *measure = USRSUB_PROJECTION_ANGLES;
    const usrsub_teim_entry *e =
        usrsub_teim_find_entry(usrsub_teim_find_block(f, "GLOBAL"), "ROTATION_MEASURE");
    if (e == NULL || usrsub_strcasecmp(e->value, "PROJECTION_ANGLES") == 0)
        return 0;
    if (usrsub_strcasecmp(e->value, "ROTATION_VECTOR") == 0) {
        *measure = USRSUB_ROTATION_VECTOR;
        return 0;
    }
    return usrsub_fail(msg, "'%s' line %d: ROTATION_MEASURE = '%s': expected PROJECTION_ANGLES"
                       " or ROTATION_VECTOR", f->path, e->line, e->value);
}
