/* Wording of the entries' messages (entry_report.h). */
#include "entry_report.h"

#include <stdarg.h>
#include <stdio.h>

#include "host.h"

void entry_report_setup(const char *routine, int id, int set_up_now, const void *model,
                        const element_setup_report *report)
{
    if (!set_up_now)
        return;
    char text[USRSUB_MESSAGE_MAX + 64];
    if (report->has_notice) {
        snprintf(text, sizeof text, "%s element %d: %s", routine, id, report->notice.text);
        host_report_notice(id, text);
    }
    if (model == NULL) {
        snprintf(text, sizeof text, "%s element %d: %s", routine, id, report->error.text);
        host_report_error(id, text);
    }
}

void entry_report_error(const char *routine, int id, const char *fmt, ...)
{
    char what[USRSUB_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    char text[USRSUB_MESSAGE_MAX + 64];
    snprintf(text, sizeof text, "%s element %d: %s", routine, id, what);
    host_report_error(id, text);
}
