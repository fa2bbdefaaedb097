/*
 * The keyword tables of the dataset's statements and the check of a parsed
 * statement against its table (docs/interface.md §9.1): each keyword's kind
 * of value and count, which are required, which statement an id names. A
 * keyword may be shortened to any prefix that no other keyword of the
 * statement shares (or to the shortest the documentation allows, where it
 * names one); an ambiguous one is an error listing the candidates.
 */
#ifndef HX_MODEL_ADM_KEYWORDS_H
#define HX_MODEL_ADM_KEYWORDS_H

#include "base/message.h"
#include "model/adm/statement.h"

typedef enum hx_adm_kind {
    HX_ADM_FLAG,    /* a bare keyword: GROUND, REVOLUTE */
    HX_ADM_ID,      /* ids of other statements, positive integers (0102 is 102) */
    HX_ADM_INT,     /* integers */
    HX_ADM_REAL,    /* finite numbers */
    HX_ADM_ANGLE,   /* finite numbers, radians, or degrees with a trailing D (90D) */
    HX_ADM_POSE,    /* six finite numbers: three lengths, then three angles (a FIELD's LENGTH) */
    HX_ADM_WORD,    /* a name or names separated by ':' (NEWTON, T:R) */
    HX_ADM_TEXT,    /* any text, a quoted string's quotes taken off */
    HX_ADM_EXPR,    /* an expression or USER(...), kept as written with its position */
    HX_ADM_ROUTINE  /* [library::]name, the routines' names */
} hx_adm_kind;

typedef struct hx_adm_keyword {
    const char *name;
    hx_adm_kind kind;
    int min, max;          /* value count; FLAG: 0, 0 */
    unsigned char required;
    unsigned char abbrev;  /* the shortest prefix accepted whatever others share (0: none) */
    const char *refers;    /* ID: the statement whose ids these are */
    short only;            /* counts allowed besides min and max: only these two when 1 (IP) */
} hx_adm_keyword;

/* A keyword's values once checked. */
typedef struct hx_adm_value {
    int present;
    int line, column;      /* of the keyword */
    int count;
    double *numbers;       /* ID, INT, REAL, ANGLE (radians) */
    char **texts;          /* WORD, TEXT, EXPR, ROUTINE */
    int *value_lines, *value_columns; /* where each value begins */
    void *block;           /* the slot after the last keyword's: the allocation every
                            * value of the statement lies in */
} hx_adm_value;

/* How a statement is taken. */
typedef enum hx_adm_role {
    HX_ADM_BUILD,       /* into the model */
    HX_ADM_OUTPUT,      /* output only: accepted and ignored */
    HX_ADM_SETTING,     /* an analysis setting the model has no place for: noted once */
    HX_ADM_UNSIMULATED, /* acts on the dynamics, not modelled: a warning; run refuses */
    HX_ADM_REFUSED,     /* an error naming why */
    HX_ADM_END          /* END */
} hx_adm_role;

enum { HX_ADM_ID_REQUIRED = 1, HX_ADM_ID_NONE = 2, HX_ADM_ID_ANY = 3 };

struct hx_adm_reader;
struct hx_adm_entry;

typedef struct hx_adm_spec {
    const char *name;
    hx_adm_role role;
    int id_form;
    const hx_adm_keyword *keywords; /* ends with a NULL name; NULL: not checked */
    const char *why;                /* UNSIMULATED, REFUSED, SETTING: the reason */
    int (*build)(struct hx_adm_reader *r, struct hx_adm_entry *e);
} hx_adm_spec;

/* The statements of a dataset (statement_table.c) and of a command file
 * (command_file.c). */
extern const hx_adm_spec hx_adm_statements[];
extern const int hx_adm_statement_count;

/* The spec of a statement name (a unique prefix, case aside) in a table;
 * NULL with msg ("NAME is not ...; ambiguous: ...") otherwise. */
const hx_adm_spec *hx_adm_find_spec(const hx_adm_spec *table, int count, const char *name,
                                    hx_message *msg);

/* Checks a parsed statement against its spec's keywords and fills values
 * (one per keyword, allocated: hx_adm_values_free); 0, or -1 with
 * "what, and why" in msg (the caller puts file, line and statement before). */
int hx_adm_check(const hx_adm_spec *spec, const hx_adm_statement *st, hx_adm_value **values,
                 int *line, hx_message *msg);
void hx_adm_values_free(const hx_adm_spec *spec, hx_adm_value *values);
int hx_adm_keyword_count(const hx_adm_spec *spec);
/* The index of a keyword of a spec by its full name (a programming error
 * when absent: -1). */
int hx_adm_keyword_index(const hx_adm_spec *spec, const char *name);

#endif
