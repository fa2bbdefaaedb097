/*
 * The Adams dataset language, statement by statement (docs/interface.md
 * §9.1): the lines of a dataset or command file joined into statements
 * (continuation lines, comments, blank lines, CRLF), and each statement's
 * generic parse: its name, its id, its arguments with their values, and
 * where each was written. What the arguments mean is the keyword tables'
 * (keywords.h).
 */
#ifndef HX_MODEL_ADM_STATEMENT_H
#define HX_MODEL_ADM_STATEMENT_H

#include <stddef.h>

#include "base/message.h"

/* A name or a value as written: NUL-terminated text inside the statement's
 * buffer, and the line and column (from 1) of its first character. */
typedef struct hx_adm_token {
    char *text;
    int line, column;
} hx_adm_token;

/* KEYWORD, KEYWORD=value or KEYWORD=v1,v2,...: values[first .. first + count). */
typedef struct hx_adm_argument {
    hx_adm_token keyword;
    int has_equals;
    int first, count;
} hx_adm_argument;

/* Where a piece of a line begins in the joined text. */
typedef struct hx_adm_segment {
    size_t offset;
    int line, column;
} hx_adm_segment;

typedef struct hx_adm_statement {
    hx_adm_token name;
    int line;               /* of its first line */
    int has_id, id;         /* NAME/id */
    hx_adm_token id_text;
    hx_adm_argument *args;
    int nargs, cap_args;
    hx_adm_token *values;
    int nvalues, cap_values;
    char *buffer;           /* the joined text, comments and continuation marks out */
    size_t length, capacity;
    hx_adm_segment *segments;
    int nsegments, cap_segments;
} hx_adm_statement;

/* A dataset's or a command file's text, line by line. */
typedef struct hx_adm_source {
    const char *path;
    const char *text;
    size_t length, pos;
    int line;               /* of the next line to read */
} hx_adm_source;

void hx_adm_source_init(hx_adm_source *src, const char *path, const char *text, size_t length);
/* The next line as it is (its end and a CR before it left out) into *start
 * and *n; 0, or -1 at the end of the text. */
int hx_adm_source_line(hx_adm_source *src, const char **start, size_t *n, int *line);

/* Reads the next statement into st (parsed: name, id, arguments); 1 when one
 * was read, 0 at the end of the text, -1 with "file:line: what" in msg. */
int hx_adm_statement_next(hx_adm_source *src, hx_adm_statement *st, hx_message *msg);
/* Gives the statement's buffer away (the caller frees it); its texts stay
 * valid in it. */
char *hx_adm_statement_take_buffer(hx_adm_statement *st);
void hx_adm_statement_free(hx_adm_statement *st);

/* The line and column of an offset in the joined text. */
void hx_adm_statement_position(const hx_adm_statement *st, size_t offset, int *line, int *column);

#endif
