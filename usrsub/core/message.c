/* Error text of the core and the readers (see message.h). */
#include "usrsub/core/message.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int usrsub_fail(usrsub_message *msg, const char *fmt, ...)
{
    if (msg != NULL) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg->text, sizeof msg->text, fmt, ap);
        va_end(ap);
    }
    return -1;
}

void usrsub_message_prefix(usrsub_message *msg, const char *fmt, ...)
{
    if (msg == NULL)
        return;
    char prefix[USRSUB_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(prefix, sizeof prefix, fmt, ap);
    va_end(ap);
    char joined[2 * USRSUB_MESSAGE_MAX + 2];
    snprintf(joined, sizeof joined, "%s: %s", prefix, msg->text);
    memcpy(msg->text, joined, sizeof msg->text - 1); /* keep the head when too long */
    msg->text[sizeof msg->text - 1] = '\0';
}
