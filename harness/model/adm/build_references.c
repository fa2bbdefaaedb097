/*
 * VARIABLE, ARRAY, STRING, SPLINE, DIFF and REQUEST (docs/interface.md
 * §9.6) into Reference_Variable, Reference_Array, Reference_String,
 * Reference_Spline, Control_Diff and Post_Request.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/adm/translate.h"
#include "model/request_elements.h"

/* The numbers of a keyword as text, "a b c ...", or the x y pairs of two. */
static char *number_text(const hx_adm_value *a, const hx_adm_value *b)
{
    const int n = a->count;
    char *text = malloc((size_t)n * (b != NULL ? 2 : 1) * 26 + 1);
    if (text == NULL)
        return NULL;
    size_t used = 0;
    text[0] = '\0';
    for (int k = 0; k < n; ++k) {
        used += (size_t)sprintf(text + used, "%.17g ", a->numbers[k]);
        if (b != NULL)
            used += (size_t)sprintf(text + used, "%.17g ", b->numbers[k]);
    }
    return text;
}

int hx_adm_build_variable(hx_adm_reader *r, hx_adm_entry *e)
{
    const char *function = hx_adm_text(e, "FUNCTION");
    hx_adm_element el;
    hx_adm_element_init(&el, "Reference_Variable");
    if (hx_adm_is_user(function)) {
        hx_adm_element_text(&el, "type", "USERSUB");
        if (hx_adm_has(e, "IC"))
            hx_adm_element_number(&el, "ic", hx_adm_number(e, "IC", 0, 0.0));
        if (hx_adm_element_user(r, e, &el, NULL) != 0)
            return -1;
    } else {
        if (hx_adm_no_routine(r, e) != 0)
            return -1;
        hx_adm_element_text(&el, "type", "EXPRESSION");
        hx_adm_element_expression(&el, "expr", e, "FUNCTION");
    }
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_array(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const types[4] = {"X", "U", "Y", "IC"};
    int type = -1, ntypes = 0;
    for (int k = 0; k < 4; ++k)
        if (hx_adm_has(e, types[k]))
            type = k, ++ntypes;
    if (ntypes != 1)
        return hx_adm_fail(r, e, e->line, "give one type of array: X, U, Y or IC");
    const hx_adm_value *size = hx_adm_get(e, "SIZE"), *numbers = hx_adm_get(e, "NUMBERS"),
                       *variables = hx_adm_get(e, "VARIABLES");
    const hx_adm_value *data = type == 1 ? variables : type == 3 ? numbers : NULL;
    if ((type == 1 && numbers->present) || (type == 3 && variables->present) ||
        (type == 0 || type == 2 ? numbers->present || variables->present : 0))
        return hx_adm_fail(r, e, e->line, "an %s array takes %s", types[type],
                           type == 1 ? "VARIABLES" : type == 3 ? "NUMBERS" : "SIZE only");
    if (data == NULL ? !size->present : !data->present)
        return hx_adm_fail(r, e, e->line, "%s is missing", data == NULL ? "SIZE"
                           : type == 1 ? "VARIABLES" : "NUMBERS");
    const int count = data != NULL ? data->count : (int)size->numbers[0];
    if (data != NULL && size->present && (int)size->numbers[0] != count)
        return hx_adm_fail(r, e, size->line, "SIZE=%d but %s gives %d", (int)size->numbers[0],
                           types[type][0] == 'U' ? "VARIABLES" : "NUMBERS", count);
    if (count < 0)
        return hx_adm_fail(r, e, size->line, "SIZE=%d must not be negative", count);
    hx_adm_element el;
    hx_adm_element_init(&el, "Reference_Array");
    hx_adm_element_text(&el, "type", types[type]);
    hx_adm_element_number(&el, "num_element", count);
    char *text = data != NULL ? number_text(data, NULL) : NULL;
    if (data != NULL && text == NULL)
        return hx_adm_fail(r, e, e->line, "out of memory");
    const int status = hx_adm_element_build(r, e, &el, text != NULL ? text : "");
    free(text);
    return status;
}

int hx_adm_build_string(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_adm_element el;
    hx_adm_element_init(&el, "Reference_String");
    hx_adm_element_text(&el, "string", hx_adm_text(e, "STRING"));
    return hx_adm_element_build(r, e, &el, NULL);
}

int hx_adm_build_spline(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const refused[] = {"FILE", "BLOCK", "ROUTINE", "FUNCTION"};
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; ++k)
        if (hx_adm_has(e, refused[k]))
            return hx_adm_fail(r, e, hx_adm_get(e, refused[k])->line, "%s: splines read from a"
                               " file or by a user subroutine are not read by the harness: give"
                               " X= and Y=", refused[k]);
    const hx_adm_value *x = hx_adm_get(e, "X"), *y = hx_adm_get(e, "Y");
    if (x->count != y->count)
        return hx_adm_fail(r, e, y->line, "Y gives %d values for %d X values (a surface, a Y=z, "
                           "y1, ..., yn for each z, is not read)", y->count, x->count);
    hx_adm_element el;
    hx_adm_element_init(&el, "Reference_Spline");
    hx_adm_element_number(&el, "num_xy_pair", x->count);
    if (hx_adm_has(e, "LINEAR_EXTRAPOLATE"))
        hx_adm_element_text(&el, "linear_extrap", "TRUE");
    char *text = number_text(x, y);
    if (text == NULL)
        return hx_adm_fail(r, e, e->line, "out of memory");
    const int status = hx_adm_element_build(r, e, &el, text);
    free(text);
    return status;
}

int hx_adm_build_diff(hx_adm_reader *r, hx_adm_entry *e)
{
    hx_adm_element el;
    hx_adm_element_init(&el, "Control_Diff");
    const int user = hx_adm_is_user(hx_adm_text(e, "FUNCTION"));
    if (!user && hx_adm_no_routine(r, e) != 0)
        return -1;
    hx_adm_element_text(&el, "type", user ? "USERSUB" : "EXPRESSION");
    const hx_adm_value *ic = hx_adm_get(e, "IC");
    if (ic->present)
        hx_adm_element_number(&el, "ic", ic->numbers[0]);
    if (ic->present && ic->count > 1)
        hx_adm_element_number(&el, "ic_dot", ic->numbers[1]);
    if (hx_adm_has(e, "IMPLICIT"))
        hx_adm_element_text(&el, "is_implicit", "TRUE");
    if (hx_adm_has(e, "STATIC_HOLD"))
        hx_adm_element_text(&el, "is_static_hold", "TRUE");
    if (!user)
        hx_adm_element_expression(&el, "expr", e, "FUNCTION");
    else if (hx_adm_element_user(r, e, &el, NULL) != 0)
        return -1;
    return hx_adm_element_build(r, e, &el, NULL);
}

/* A REQUEST the harness answers itself (docs/interface.md §9.6): DISPLACEMENT,
 * VELOCITY or ACCELERATION of I relative to J in RM's axes, FORCE at I from the
 * elements between I and J, or F1..F8, through the one builder of requests
 * (model/request_elements.h). */
static int build_builtin_request(hx_adm_reader *r, hx_adm_entry *e)
{
    static const char *const types[4] = {"DISPLACEMENT", "VELOCITY", "ACCELERATION", "FORCE"};
    static const char *const fs[8] = {"F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8"};
    static const char *const markers[3] = {"I", "J", "RM"};
    int type = -1, nf = 0;
    for (int k = 0; k < 4; ++k)
        if (hx_adm_has(e, types[k])) {
            if (type >= 0)
                return hx_adm_fail(r, e, e->line, "%s and %s: give one of DISPLACEMENT, VELOCITY,"
                                   " ACCELERATION, FORCE, F1..F8 or FUNCTION=USER(...)",
                                   types[type], types[k]);
            type = k;
        }
    for (int k = 0; k < 8; ++k)
        nf += hx_adm_has(e, fs[k]);
    if (type >= 0 && nf > 0)
        return hx_adm_fail(r, e, e->line, "%s with F1..F8: give one or the other", types[type]);
    if (type < 0 && nf == 0)
        return hx_adm_fail(r, e, e->line, "nothing to output: give DISPLACEMENT, VELOCITY,"
                           " ACCELERATION, FORCE, F1..F8 or FUNCTION=USER(...)");
    int ids[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        const hx_adm_value *v = hx_adm_get(e, markers[k]);
        if (!v->present)
            continue;
        if (type < 0)
            return hx_adm_fail(r, e, v->line, "%s (column %d) with F1..F8: the expressions name"
                               " their markers themselves", markers[k], v->column);
        ids[k] = (int)v->numbers[0];
        if ((ids[k] != 0 || k == 0) && hx_adm_find(r, "MARKER", ids[k]) == NULL)
            return hx_adm_fail(r, e, v->value_lines[0], "%s=%d (column %d) names no MARKER"
                               " statement", markers[k], ids[k], v->value_columns[0]);
    }
    if (type >= 0 && !hx_adm_has(e, "I"))
        return hx_adm_fail(r, e, e->line, "%s needs I= (the marker measured)", types[type]);
    char label[48];
    hx_adm_label(e, label, sizeof label);
    hx_request *q = hx_draft_request(r->d, e->id, type == 0   ? HX_REQUEST_DISPLACEMENT
                                                  : type == 1 ? HX_REQUEST_VELOCITY
                                                  : type == 2 ? HX_REQUEST_ACCELERATION
                                                  : type == 3 ? HX_REQUEST_FORCE
                                                              : HX_REQUEST_EXPRESSIONS,
                                     ids, e->line, label);
    if (q == NULL)
        return -1;
    q->adams = 1;
    for (int k = 0; k < 8; ++k) {
        const hx_adm_value *v = hx_adm_get(e, fs[k]);
        if (!v->present)
            continue;
        if (hx_adm_is_user(v->texts[0]))
            return hx_adm_fail(r, e, v->value_lines[0], "%s (column %d): USER(...) is a REQUEST's"
                               " FUNCTION (REQSUB), not a component", fs[k], v->value_columns[0]);
        const hx_expr_source where = {r->path, v->value_lines[0], v->value_columns[0]};
        if (hx_draft_request_expression(r->d, q, k, v->texts[0], &where, label) != 0)
            return -1;
    }
    return 0;
}

int hx_adm_build_request(hx_adm_reader *r, hx_adm_entry *e)
{
    const char *function = hx_adm_text(e, "FUNCTION");
    if (function == NULL) {
        if (hx_adm_no_routine(r, e) != 0)
            return -1;
        return build_builtin_request(r, e);
    }
    if (!hx_adm_is_user(function))
        return hx_adm_fail(r, e, hx_adm_get(e, "FUNCTION")->line, "FUNCTION=%s: a REQUEST's"
                           " FUNCTION is USER(...) (REQSUB); measures are F1=..\\F8=..", function);
    static const char *const others[] = {"DISPLACEMENT", "VELOCITY", "ACCELERATION", "FORCE",
                                         "I", "J", "RM", "F1", "F2", "F3", "F4", "F5", "F6",
                                         "F7", "F8"};
    for (size_t k = 0; k < sizeof others / sizeof others[0]; ++k)
        if (hx_adm_has(e, others[k]))
            return hx_adm_fail(r, e, hx_adm_get(e, others[k])->line, "%s with FUNCTION=USER(...):"
                               " REQSUB computes the eight values", others[k]);
    hx_adm_element el;
    hx_adm_element_init(&el, "Post_Request");
    hx_adm_element_text(&el, "type", "USERSUB");
    if (hx_adm_element_user(r, e, &el, NULL) != 0)
        return -1;
    return hx_adm_element_build(r, e, &el, NULL);
}
