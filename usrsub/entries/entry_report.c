/* Wording of the entries' messages (entry_report.h). */
#include "entry_report.h"

#include <stdarg.h>
#include <stdio.h>

#include "host.h"
#include "mutex.h"

/* What has been reported during a call: (routine, element, kind), by the
 * addresses of the constant strings. Only error paths touch it. */
#define REPORTED_MAX 4096
typedef struct reported_key {
    const char *routine, *kind;
    int id;
} reported_key;
static reported_key reported[REPORTED_MAX];
static int reported_count;
static usrsub_mutex reported_lock = USRSUB_MUTEX_INIT;

/* 1 the first time a key is seen (and whenever the table is full). */
static int first_report(const char *routine, int id, const char *kind)
{
    int first = 1;
    usrsub_mutex_lock(&reported_lock);
    for (int k = 0; k < reported_count && first; ++k)
        first = !(reported[k].routine == routine && reported[k].id == id && reported[k].kind == kind);
    if (first && reported_count < REPORTED_MAX)
        reported[reported_count++] = (reported_key){routine, kind, id};
    usrsub_mutex_unlock(&reported_lock);
    return first;
}

void usrsub_entry_report_setup(const char *routine, int id, int set_up_now, const void *model,
                        const usrsub_element_setup_report *report)
{
    if (!set_up_now)
        return;
    char text[USRSUB_MESSAGE_MAX + 64];
    if (report->notices.has_notice) {
        snprintf(text, sizeof text, "%s element %d: %s", routine, id, report->notices.notice.text);
        usrsub_host_report_notice(id, text);
    }
    if (model == NULL) {
        snprintf(text, sizeof text, "%s element %d: %s", routine, id, report->error.text);
        usrsub_host_report_error(id, text);
    }
}

void usrsub_entry_report_error(const char *routine, int id, const char *kind, const char *fmt, ...)
{
    if (kind != NULL && !first_report(routine, id, kind))
        return;
    char what[USRSUB_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    char text[USRSUB_MESSAGE_MAX + 64];
    snprintf(text, sizeof text, "%s element %d: %s", routine, id, what);
    usrsub_host_report_error(id, text);
}

int usrsub_entry_report_arguments_ok(const char *routine, const int *id, const double *par,
                                     const int *npar)
{
    if (id != NULL && npar != NULL && *npar >= 0 && (*npar == 0 || par != NULL))
        return 1;
    usrsub_entry_report_error(routine, id != NULL ? *id : 0, NULL, "called with a missing argument (id,"
                       " par or npar) or a negative npar");
    return 0;
}
