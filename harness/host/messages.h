/*
 * Where what the libraries say goes: c_errmes and c_usrmes text, the host's
 * own reports about a call (a read outside the declared dependencies, a query
 * it refused), and the STOP request. One per session, shared by the calls
 * bound to it, thread safe.
 */
#ifndef HX_HOST_MESSAGES_H
#define HX_HOST_MESSAGES_H

#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>

#define HX_TEXT_MAX 1024

typedef struct hx_messages {
    pthread_mutex_t lock;
    FILE *stream;          /* where the text is printed (NULL: kept, not printed) */
    int errors, notices;
    char last_error[HX_TEXT_MAX], last_notice[HX_TEXT_MAX];
    _Atomic int stop;      /* c_errmes asked to end the run: read without the lock
                            * after every call, written under it */
    char stop_message[HX_TEXT_MAX];
} hx_messages;

void hx_messages_init(hx_messages *m, FILE *stream);
void hx_messages_destroy(hx_messages *m);
/* Forgets the counts, the texts and the stop request. */
void hx_messages_reset(hx_messages *m);

/* c_errmes: "ERRMES [id]: text" (with STOP when stop is set). */
void hx_messages_error(hx_messages *m, int id, const char *text, int stop);
/* A STOP that a process forked from this one received and printed: this
 * process stops too, without printing the text again. */
void hx_messages_adopt_stop(hx_messages *m, const char *text);
/* c_usrmes: "USRMES:USER [id] TYPE: text". */
void hx_messages_notice(hx_messages *m, int id, const char *type, const char *text);
/* The host's own finding about a call: "host: text". */
void hx_messages_host(hx_messages *m, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

int hx_messages_stopped(const hx_messages *m);

#endif
