/*
 * The harness's error text: a failing function fills a message and returns
 * -1; the caller adds its context in front and passes it up, and the command
 * prints it. The harness keeps its own (it shares no code with the library
 * it verifies).
 */
#ifndef HX_BASE_MESSAGE_H
#define HX_BASE_MESSAGE_H

#include <stddef.h>

#define HX_MESSAGE_MAX 1024

typedef struct hx_message {
    char text[HX_MESSAGE_MAX];
} hx_message;

/* Writes the text into msg (when not NULL); returns -1, so that a function
 * can `return hx_fail(msg, ...);`. */
int hx_fail(hx_message *msg, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Puts "prefix: " in front of the text already in msg. */
void hx_message_prefix(hx_message *msg, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* The n values of v, separated by blanks, each with `digits` significant
 * digits, cut at size. */
void hx_format_values(char *text, size_t size, const double *v, int n, int digits);

#endif
