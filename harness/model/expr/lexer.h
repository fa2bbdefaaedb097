/*
 * The tokens of a function expression (docs/interface.md §8.1): numbers
 * (with a D for degrees), names, operators and punctuation, each with its
 * line and column in the source; blanks and line breaks anywhere between
 * tokens.
 */
#ifndef HX_MODEL_EXPR_LEXER_H
#define HX_MODEL_EXPR_LEXER_H

#include <stddef.h>

#define HX_EXPR_NAME_MAX 32 /* characters of a name kept (longer names are no function's) */

typedef enum hx_expr_token_kind {
    HX_TOKEN_END,     /* the end of the text */
    HX_TOKEN_NUMBER,
    HX_TOKEN_NAME,
    HX_TOKEN_PLUS, HX_TOKEN_MINUS, HX_TOKEN_STAR, HX_TOKEN_SLASH, HX_TOKEN_POWER,
    HX_TOKEN_OPEN, HX_TOKEN_CLOSE, HX_TOKEN_COMMA, HX_TOKEN_COLON,
    HX_TOKEN_ERROR    /* a character or number the language has not: `error` says what */
} hx_expr_token_kind;

typedef struct hx_expr_token {
    hx_expr_token_kind kind;
    double number;     /* a number's value (degrees turned into radians) */
    long whole;        /* a number written as digits alone: its value, else -1 */
    char name[HX_EXPR_NAME_MAX + 1]; /* a name in capitals, cut at HX_EXPR_NAME_MAX */
    int length;        /* its characters in the text */
    int line, column;
    const char *error; /* HX_TOKEN_ERROR: what is wrong */
} hx_expr_token;

typedef struct hx_expr_lexer {
    const char *text;
    size_t length, at;
    int line, column;
} hx_expr_lexer;

void hx_expr_lexer_init(hx_expr_lexer *x, const char *text, size_t length, int line, int column);
/* The next token; at the end, HX_TOKEN_END with the place after the text. */
void hx_expr_lex(hx_expr_lexer *x, hx_expr_token *t);
/* "'+'", "the number 2", "the name FOO", "the end of the expression" */
const char *hx_expr_token_text(const hx_expr_token *t, char *text, size_t size);

#endif
