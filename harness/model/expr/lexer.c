/* The tokens of a function expression (lexer.h). */
#include "model/expr/lexer.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void hx_expr_lexer_init(hx_expr_lexer *x, const char *text, size_t length, int line, int column)
{
    x->text = text, x->length = length, x->at = 0, x->line = line, x->column = column;
}

static int peek(const hx_expr_lexer *x, size_t ahead)
{
    return x->at + ahead < x->length ? (unsigned char)x->text[x->at + ahead] : 0;
}

static void advance(hx_expr_lexer *x, size_t count)
{
    for (size_t k = 0; k < count && x->at < x->length; ++k, ++x->at) {
        if (x->text[x->at] == '\n')
            ++x->line, x->column = 1;
        else
            ++x->column;
    }
}

static int is_name_char(int c)
{
    return isalnum(c) || c == '_';
}

/* digits [. digits] | . digits, then [E [+-] digits], then [D] (degrees):
 * a number token, or an error token saying what is wrong */
static void number(hx_expr_lexer *x, hx_expr_token *t)
{
    size_t n = 0;
    int digits = 0, whole = 1;
    while (isdigit(peek(x, n)))
        ++n, ++digits;
    if (peek(x, n) == '.') {
        whole = 0, ++n;
        while (isdigit(peek(x, n)))
            ++n, ++digits;
    }
    if (digits == 0) {
        t->kind = HX_TOKEN_ERROR, t->error = "a '.' that begins no number", t->length = 1;
        return;
    }
    if (peek(x, n) == 'e' || peek(x, n) == 'E') {
        size_t m = n + 1;
        if (peek(x, m) == '+' || peek(x, m) == '-')
            ++m;
        if (!isdigit(peek(x, m))) {
            t->kind = HX_TOKEN_ERROR, t->error = "a number whose exponent has no digits";
            t->length = (int)m;
            return;
        }
        while (isdigit(peek(x, m)))
            ++m;
        whole = 0, n = m;
    }
    char copy[64];
    if (n >= sizeof copy) {
        t->kind = HX_TOKEN_ERROR, t->error = "a number of too many digits", t->length = (int)n;
        return;
    }
    memcpy(copy, x->text + x->at, n);
    copy[n] = '\0';
    errno = 0;
    double value = strtod(copy, NULL);
    const int degrees = (peek(x, n) == 'd' || peek(x, n) == 'D') && !is_name_char(peek(x, n + 1));
    if (degrees)
        value *= M_PI / 180.0, whole = 0, ++n;
    t->length = (int)n;
    if ((errno == ERANGE && !(fabs(value) < 1.0)) || !isfinite(value)) {
        t->kind = HX_TOKEN_ERROR, t->error = "a number too large for a double";
        return;
    }
    if (is_name_char(peek(x, n))) {
        t->kind = HX_TOKEN_ERROR, t->error = "a number run into a name (an operator is missing)";
        t->length = (int)n + 1;
        return;
    }
    t->kind = HX_TOKEN_NUMBER, t->number = value;
    t->whole = whole && value <= (double)INT_MAX ? (long)value : -1;
}

void hx_expr_lex(hx_expr_lexer *x, hx_expr_token *t)
{
    while (x->at < x->length && isspace((unsigned char)x->text[x->at]))
        advance(x, 1);
    memset(t, 0, sizeof *t);
    t->line = x->line, t->column = x->column, t->whole = -1, t->length = 1;
    const int c = peek(x, 0);
    if (x->at >= x->length || c == '\0') {
        t->kind = HX_TOKEN_END, t->length = 0;
        if (x->at < x->length) /* a NUL inside the given length */
            t->kind = HX_TOKEN_ERROR, t->error = "a NUL character inside the text", t->length = 1;
        return;
    }
    if (isdigit(c) || c == '.') {
        number(x, t);
    } else if (isalpha(c)) {
        int n = 0;
        while (is_name_char(peek(x, (size_t)n))) {
            if (n < HX_EXPR_NAME_MAX)
                t->name[n] = (char)toupper(peek(x, (size_t)n));
            ++n;
        }
        t->kind = HX_TOKEN_NAME, t->length = n;
    } else {
        switch (c) {
        case '+': t->kind = HX_TOKEN_PLUS; break;
        case '-': t->kind = HX_TOKEN_MINUS; break;
        case '*':
            t->kind = peek(x, 1) == '*' ? HX_TOKEN_POWER : HX_TOKEN_STAR;
            t->length = t->kind == HX_TOKEN_POWER ? 2 : 1;
            break;
        case '/': t->kind = HX_TOKEN_SLASH; break;
        case '(': t->kind = HX_TOKEN_OPEN; break;
        case ')': t->kind = HX_TOKEN_CLOSE; break;
        case ',': t->kind = HX_TOKEN_COMMA; break;
        case ':': t->kind = HX_TOKEN_COLON; break;
        default: t->kind = HX_TOKEN_ERROR, t->error = "a character the language does not have";
        }
    }
    advance(x, (size_t)t->length);
}

const char *hx_expr_token_text(const hx_expr_token *t, char *text, size_t size)
{
    static const char *const punctuation[] = {
        [HX_TOKEN_PLUS] = "'+'", [HX_TOKEN_MINUS] = "'-'", [HX_TOKEN_STAR] = "'*'",
        [HX_TOKEN_SLASH] = "'/'", [HX_TOKEN_POWER] = "'**'", [HX_TOKEN_OPEN] = "'('",
        [HX_TOKEN_CLOSE] = "')'", [HX_TOKEN_COMMA] = "','", [HX_TOKEN_COLON] = "':'"};
    switch (t->kind) {
    case HX_TOKEN_END: snprintf(text, size, "the end of the expression"); break;
    case HX_TOKEN_NUMBER: snprintf(text, size, "the number %.17g", t->number); break;
    case HX_TOKEN_NAME:
        snprintf(text, size, "the name %s%s", t->name, t->length > HX_EXPR_NAME_MAX ? "..." : "");
        break;
    case HX_TOKEN_ERROR: snprintf(text, size, "%s", t->error); break;
    default: snprintf(text, size, "%s", punctuation[t->kind]); break;
    }
    return text;
}
