/*
 * Two-column numeric table files ("x y" per row; blank lines and lines that
 * start with '#' or '$' are ignored; separators are spaces, tabs or a comma).
 */
#ifndef USRSUB_TABLE_FILE_H
#define USRSUB_TABLE_FILE_H

#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reads the whole file into newly allocated x and y arrays. On error writes msg
 * naming the file and the line and returns -1 (nothing allocated). */
int usrsub_table_file_read(const char *path, double **x, double **y, int *n,
                           usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
