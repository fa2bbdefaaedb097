/*
 * Error text produced by the physics core and the property-file readers.
 * The core never talks to a host: it fills a message and returns an error
 * status; the entry adapter prefixes the element and reports it once.
 */
#ifndef USRSUB_MESSAGE_H
#define USRSUB_MESSAGE_H

#ifdef __cplusplus
extern "C" {
#endif

#define USRSUB_MESSAGE_MAX 768

typedef struct usrsub_message {
    char text[USRSUB_MESSAGE_MAX];
} usrsub_message;

/* Writes the formatted text into msg (when msg is not NULL); returns -1 so that
 * a reader can write `return usrsub_fail(msg, ...);`. */
int usrsub_fail(usrsub_message *msg, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Puts "prefix: " in front of the text already in msg. */
void usrsub_message_prefix(usrsub_message *msg, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

#ifdef __cplusplus
}
#endif

#endif
