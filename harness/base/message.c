/* The harness's error text (message.h). */
#include "base/message.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int hx_fail(hx_message *msg, const char *fmt, ...)
{
    if (msg != NULL) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg->text, sizeof msg->text, fmt, ap);
        va_end(ap);
    }
    return -1;
}

void hx_message_prefix(hx_message *msg, const char *fmt, ...)
{
    if (msg == NULL)
        return;
    char joined[2 * HX_MESSAGE_MAX];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(joined, sizeof joined, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= sizeof joined)
        n = (int)strlen(joined);
    snprintf(joined + n, sizeof joined - (size_t)n, ": %s", msg->text);
    memcpy(msg->text, joined, sizeof msg->text - 1); /* keep the head when too long */
    msg->text[sizeof msg->text - 1] = '\0';
}

void hx_format_values(char *text, size_t size, const double *v, int n, int digits)
{
    size_t used = 0;
    text[0] = '\0';
    for (int k = 0; k < n && used < size; ++k)
        used += (size_t)snprintf(text + used, size - used, k ? " %.*g" : "%.*g", digits, v[k]);
}
