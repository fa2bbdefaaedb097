/*
 * What the commands share: option values read with a message that names
 * the option and the value at fault, and output files prepared before any
 * long work (their folder created, the file opened once for writing), with
 * the reason when that fails.
 */
#ifndef HX_CMD_OPTIONS_H
#define HX_CMD_OPTIONS_H

#include <stdio.h>

#include "base/message.h"

/* A finite number; prints "usrsub-harness COMMAND: --OPTION 'TEXT' is not a
 * number" and returns -1 otherwise. */
int hx_option_number(const char *command, const char *option, const char *text, double *out);
/* The same, and above zero. */
int hx_option_positive(const char *command, const char *option, const char *text, double *out);
/* A whole number, at least min. */
int hx_option_count(const char *command, const char *option, const char *text, long min,
                    long *out);
/* BDF's largest order, 1 to 5. */
int hx_option_max_order(const char *command, const char *text, int *out);

/* Creates the folders of path's parent (as mkdir -p does); 0, or -1 with the
 * reason in msg. */
int hx_make_parent_folders(const char *path, hx_message *msg);
/* Creates path's folder and opens path for writing ("w"); NULL with the
 * reason (strerror) in msg. */
FILE *hx_open_output(const char *path, hx_message *msg);

#endif
