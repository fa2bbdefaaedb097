/* The messages of a session (messages.h). */
#include "host/messages.h"

#include <stdarg.h>
#include <stdatomic.h>
#include <string.h>

void hx_messages_init(hx_messages *m, FILE *stream)
{
    memset(m, 0, sizeof *m);
    pthread_mutex_init(&m->lock, NULL);
    m->stream = stream;
}

void hx_messages_destroy(hx_messages *m)
{
    pthread_mutex_destroy(&m->lock);
}

void hx_messages_reset(hx_messages *m)
{
    pthread_mutex_lock(&m->lock);
    m->errors = m->notices = 0;
    m->last_error[0] = m->last_notice[0] = '\0';
    atomic_store_explicit(&m->stop, 0, memory_order_relaxed);
    m->stop_message[0] = '\0';
    pthread_mutex_unlock(&m->lock);
}

void hx_messages_error(hx_messages *m, int id, const char *text, int stop)
{
    pthread_mutex_lock(&m->lock);
    ++m->errors;
    snprintf(m->last_error, sizeof m->last_error, "%s", text != NULL ? text : "");
    if (stop && !atomic_load_explicit(&m->stop, memory_order_relaxed)) {
        snprintf(m->stop_message, sizeof m->stop_message, "%s", m->last_error);
        atomic_store_explicit(&m->stop, 1, memory_order_release);
    }
    if (m->stream != NULL)
        fprintf(m->stream, "ERRMES [%d]%s: %s\n", id, stop ? " STOP" : "", m->last_error);
    pthread_mutex_unlock(&m->lock);
}

void hx_messages_adopt_stop(hx_messages *m, const char *text)
{
    pthread_mutex_lock(&m->lock);
    ++m->errors;
    snprintf(m->last_error, sizeof m->last_error, "%s", text != NULL ? text : "");
    if (!atomic_load_explicit(&m->stop, memory_order_relaxed)) {
        snprintf(m->stop_message, sizeof m->stop_message, "%s", m->last_error);
        atomic_store_explicit(&m->stop, 1, memory_order_release);
    }
    pthread_mutex_unlock(&m->lock);
}

void hx_messages_notice(hx_messages *m, int id, const char *type, const char *text)
{
    pthread_mutex_lock(&m->lock);
    ++m->notices;
    snprintf(m->last_notice, sizeof m->last_notice, "%s", text != NULL ? text : "");
    if (m->stream != NULL)
        fprintf(m->stream, "USRMES:USER [%d] %s: %s\n", id, type != NULL ? type : "INFO",
                m->last_notice);
    pthread_mutex_unlock(&m->lock);
}

void hx_messages_host(hx_messages *m, const char *fmt, ...)
{
    char text[HX_TEXT_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    pthread_mutex_lock(&m->lock);
    if (m->stream != NULL)
        fprintf(m->stream, "host: %s\n", text);
    pthread_mutex_unlock(&m->lock);
}

int hx_messages_stopped(const hx_messages *m)
{
    /* the stop message is written before the flag (under the lock): whoever
     * sees the flag sees the message */
    return atomic_load_explicit(&m->stop, memory_order_acquire);
}
