/*
 * Force_StateEqn, Reference_Array and Reference_Variable: their descriptions,
 * builders and resolve pass (stateeqn_elements.h). The attribute names
 * are MotionSolve's (docs/interface.md §7.10 gives the sources and what is
 * our reading).
 */
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "model/draft.h"
#include "model/expr/expr.h"
#include "model/load_elements.h"
#include "model/number_list.h"
#include "model/routine_elements.h"
#include "model/stateeqn_elements.h"
#include "model/variable_expression.h"
#include "model/xml_attrs.h"

/* ----  --------------------------------------------------------------------------------------- */

/* The ids of text (blanks, newlines or commas between them): positive
 * integers, as hx_read_numbers answers (model/number_list.h). */
static int read_ids(const char *text, int **out)
{
    double *values = NULL;
    const int count = hx_read_numbers(text, &values);
    if (count < 0)
        return count;
    int *ids = malloc(sizeof(int) * (size_t)(count > 0 ? count : 1));
    if (ids == NULL) {
        free(values);
        return -1;
    }
    for (int k = 0; k < count; ++k) {
        if (!(values[k] >= 1.0 && values[k] <= INT_MAX && values[k] == floor(values[k]))) {
            free(values);
            free(ids);
            return -2 - k;
        }
        ids[k] = (int)values[k];
    }
    free(values);
    *out = ids;
    return count;
}

static int blank(const char *text)
{
    for (; *text != '\0'; ++text)
        if (!isspace((unsigned char)*text))
            return 0;
    return 1;
}

/* ----  --------------------------------------------------------------------------------------- */

const hx_attr_spec hx_variable_attrs[] = {ID, TEXT("type"), TEXT("expr"), TEXT("function"),
                                          REAL("ic"), USER_CALL, END};

void hx_build_variable(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    if (hx_model_variable(m, e->id) >= 0) {
        hx_draft_fail(d, e->line, "Reference_Variable %d is defined twice (line %d)", e->id,
                      m->variables[hx_model_variable(m, e->id)].line);
        return;
    }
    const char *type = hx_attr_text(e, "type");
    if ((type != NULL && strcasecmp(type, "USERSUB") == 0) ||
        (type == NULL && (hx_attr_present(e, "usrsub_param_string") ||
                          hx_attr_present(e, "usrsub_dll_name")))) {
        hx_build_user_variable(d, e);
        return;
    }
    if ((type != NULL && strcasecmp(type, "EXPRESSION") != 0) || hx_attr_present(e, "script_name")) {
        hx_draft_fail(d, e->line, "Reference_Variable %d: type \"%s\": expected EXPRESSION or"
                      " USERSUB", e->id, type != NULL ? type : "(script)");
        return;
    }
    if (hx_attr_present(e, "function")) {
        hx_draft_fail(d, e->line, "Reference_Variable %d: attribute function: MotionSolve names"
                      " the expression expr (type=\"EXPRESSION\" expr=\"DX(20,10,10)\")", e->id);
        return;
    }
    const char *expr = hx_attr_text(e, "expr");
    if (expr == NULL) {
        hx_draft_fail(d, e->line, "Reference_Variable %d: attribute expr is missing", e->id);
        return;
    }
    hx_variable v = {.id = e->id, .line = e->line};
    hx_message why;
    /* one measure or a number as before (the Force_StateEqn inputs' form); any
     * other text is the engine's, linked once the model is whole */
    if (hx_parse_variable_expression(expr, &v, &why) != 0 &&
        hx_draft_parse_expression(d, e, "expr", &v.program) != 0)
        return;
    hx_variable *slot = hx_draft_push(d, (void **)&m->variables, &m->nvariables,
                                      &d->cap_variables, sizeof *slot, NULL, 0);
    if (slot != NULL)
        *slot = v;
}

/* ----  --------------------------------------------------------------------------------------- */

const hx_attr_spec hx_array_attrs[] = {ID, REQUIRED("type", HX_ATTR_TEXT),
                                       REQUIRED("num_element", HX_ATTR_INT), TEXT("variable_id"),
                                       USER_CALL, END};

static const char *const array_type_names[] = {"X", "U", "Y", "IC"};

void hx_build_array(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    const int previous = hx_model_array(m, e->id);
    if (previous >= 0) {
        hx_draft_fail(d, e->line, "Reference_Array %d is defined twice (line %d)", e->id,
                      m->arrays[previous].line);
        return;
    }
    const char *type = hx_attr_text(e, "type");
    int kind = -1;
    for (int k = 0; k < 4; ++k)
        if (strcasecmp(type, array_type_names[k]) == 0)
            kind = k;
    if (kind < 0) {
        hx_draft_fail(d, e->line, "Reference_Array %d: type \"%s\": expected X, U, Y or IC",
                      e->id, type);
        return;
    }
    const int count = hx_attr_int(e, "num_element", 0);
    if (count < 0) {
        hx_draft_fail(d, e->line, "Reference_Array %d: num_element %d must not be negative",
                      e->id, count);
        return;
    }
    if (hx_attr_present(e, "usrsub_param_string") || hx_attr_present(e, "script_name")) {
        hx_draft_fail(d, e->line, "Reference_Array %d: arrays computed by a user subroutine are"
                      " not supported by the harness (give variable_id)", e->id);
        return;
    }
    const char *ids = hx_attr_text(e, "variable_id");
    if (ids != NULL && kind != HX_ARRAY_U) {
        hx_draft_fail(d, e->line, "Reference_Array %d: variable_id belongs to type U arrays, not"
                      " to type %s", e->id, array_type_names[kind]);
        return;
    }
    hx_array *a = hx_draft_push(d, (void **)&m->arrays, &m->narrays, &d->cap_arrays, sizeof *a,
                                NULL, 0);
    if (a == NULL)
        return;
    a->id = e->id;
    a->type = (hx_array_type)kind;
    a->count = count;
    a->line = e->line;
    if (ids == NULL)
        return;
    const int n = read_ids(ids, &a->variable_ids);
    if (n == -1)
        hx_draft_fail(d, e->line, "out of memory");
    else if (n < 0)
        hx_draft_fail(d, e->line, "Reference_Array %d: variable_id = \"%s\": entry %d (from 1)"
                      " is not a positive integer id", e->id, ids, -1 - n);
    else if (n != count)
        hx_draft_fail(d, e->line, "Reference_Array %d: num_element is %d but variable_id holds %d"
                      " ids", e->id, count, n);
}

void hx_array_text(hx_draft *d, int line, const char *text)
{
    hx_array *a = &d->m->arrays[d->m->narrays - 1];
    const char *type = array_type_names[a->type];
    (void)line; /* errors name the element's own line, where its tag opens */
    const int no_data = a->type == HX_ARRAY_X || a->type == HX_ARRAY_Y ||
                        (a->type == HX_ARRAY_U && a->variable_ids != NULL);
    if (no_data) {
        if (!blank(text))
            hx_draft_fail(d, a->line, "Reference_Array %d (type %s): the text between its tags is"
                          " not read%s: leave it empty", a->id, type,
                          a->type == HX_ARRAY_U ? " (its ids are in variable_id)"
                                                : " (the solver fills the array)");
        return;
    }
    int n;
    if (a->type == HX_ARRAY_U)
        n = read_ids(text, &a->variable_ids);
    else
        n = hx_read_numbers(text, &a->numbers);
    if (n == -1) {
        hx_draft_fail(d, a->line, "out of memory");
        return;
    }
    if (n < 0) {
        hx_draft_fail(d, a->line, "Reference_Array %d (type %s): entry %d (from 1) of its data"
                      " is not %s", a->id, type, -1 - n,
                      a->type == HX_ARRAY_U ? "a positive integer id" : "a finite number");
        return;
    }
    if (n != a->count)
        hx_draft_fail(d, a->line, "Reference_Array %d (type %s): num_element is %d but its data"
                      " holds %d %s", a->id, type, a->count, n,
                      a->type == HX_ARRAY_U ? "ids (give them in variable_id or as text)"
                                            : "numbers");
}

/* ----  --------------------------------------------------------------------------------------- */

const hx_attr_spec hx_stateeqn_attrs[] = {
    ID, REQUIRED("type", HX_ATTR_TEXT), REQUIRED("x_array_id", HX_ATTR_INT), INT("u_array_id"),
    INT("ic_array_id"), INT("num_state"), {"is_static_hold", HX_ATTR_BOOL, 0},
    REQUIRED("i_marker_id", HX_ATTR_INT), REQUIRED("j_floating_marker_id", HX_ATTR_INT),
    REQUIRED("ref_marker_id", HX_ATTR_INT), USER_CALL, TEXT("usrsub_der1_name"),
    TEXT("usrsub_der2_name"), TEXT("usrsub_der3_name"), TEXT("usrsub_der4_name"), END};

void hx_build_stateeqn(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->nstateeqns; ++k)
        if (m->stateeqns[k].id == e->id) {
            hx_draft_fail(d, e->line, "Force_StateEqn %d is defined twice (line %d)", e->id,
                          m->stateeqns[k].line);
            return;
        }
    const char *type = hx_attr_text(e, "type");
    if (strcasecmp(type, "USERSUB") != 0) {
        hx_draft_fail(d, e->line, "Force_StateEqn %d: type \"%s\" is not supported by the harness"
                      " (USERSUB: YFOSUB and its partials)", e->id, type);
        return;
    }
    if (!hx_attr_present(e, "num_state")) {
        hx_draft_fail(d, e->line, "Force_StateEqn %d: attribute num_state is missing", e->id);
        return;
    }
    const int nstate = hx_attr_int(e, "num_state", 0);
    if (nstate < 0) {
        hx_draft_fail(d, e->line, "Force_StateEqn %d: num_state %d must not be negative", e->id,
                      nstate);
        return;
    }
    hx_stateeqn *f = hx_draft_push(d, (void **)&m->stateeqns, &m->nstateeqns,
                                    &d->cap_stateeqns, sizeof *f, (void **)&d->rstateeqns,
                                    sizeof(raw_stateeqn));
    if (f == NULL)
        return;
    f->id = e->id;
    f->line = e->line;
    f->nstate = nstate;
    f->static_hold = hx_attr_number(e, "is_static_hold", 0.0) != 0.0;
    f->x_array = f->u_array = f->ic_array = -1;
    raw_stateeqn *raw = &d->rstateeqns[m->nstateeqns - 1];
    raw->marker_ids[0] = hx_attr_int(e, "i_marker_id", 0);
    raw->marker_ids[1] = hx_attr_int(e, "j_floating_marker_id", 0);
    raw->marker_ids[2] = hx_attr_int(e, "ref_marker_id", 0);
    raw->x_array_id = hx_attr_int(e, "x_array_id", 0);
    raw->u_array_id = hx_attr_int(e, "u_array_id", 0);
    raw->ic_array_id = hx_attr_int(e, "ic_array_id", 0);
    hx_draft_user_call(d, e, &f->user);
}

/* ----  --------------------------------------------------------------------------------------- */

static int resolve_variables(hx_draft *d)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->nvariables; ++k) {
        const hx_variable *v = &m->variables[k];
        for (int i = 0; i < v->nmarkers; ++i)
            if (v->marker_ids[i] != 0 && hx_model_marker(m, v->marker_ids[i]) < 0) {
                hx_draft_fail(d, v->line, "Reference_Variable %d: attribute expr names marker %d,"
                              " which is not a Reference_Marker", v->id, v->marker_ids[i]);
                return -1;
            }
    }
    for (int k = 0; k < m->narrays; ++k) {
        hx_array *a = &m->arrays[k];
        if (a->type != HX_ARRAY_U || a->count == 0)
            continue;
        if (a->variable_ids == NULL) {
            hx_draft_fail(d, a->line, "Reference_Array %d (type U): num_element is %d but it names"
                          " no variables (variable_id)", a->id, a->count);
            return -1;
        }
        if ((a->variables = malloc(sizeof(int) * (size_t)a->count)) == NULL) {
            hx_draft_fail(d, a->line, "out of memory");
            return -1;
        }
        for (int i = 0; i < a->count; ++i)
            if ((a->variables[i] = hx_model_variable(m, a->variable_ids[i])) < 0) {
                hx_draft_fail(d, a->line, "Reference_Array %d: variable %d is not a"
                              " Reference_Variable", a->id, a->variable_ids[i]);
                return -1;
            }
    }
    return 0;
}

/* The array attribute of f named `what`, of the type wanted; -1 with the
 * draft failed when it is not one. */
static int array_ref(hx_draft *d, const hx_stateeqn *f, const char *what, int id,
                     hx_array_type wanted, int *index)
{
    *index = hx_model_array(d->m, id);
    if (*index < 0) {
        hx_draft_fail(d, f->line, "Force_StateEqn %d: %s %d is not a Reference_Array", f->id,
                      what, id);
        return -1;
    }
    const hx_array *a = &d->m->arrays[*index];
    if (a->type != wanted) {
        hx_draft_fail(d, f->line, "Force_StateEqn %d: %s %d is a Reference_Array of type %s"
                      " (line %d), not %s", f->id, what, id, array_type_names[a->type], a->line,
                      array_type_names[wanted]);
        return -1;
    }
    return 0;
}

static int resolve_markers(hx_draft *d, hx_stateeqn *f, const raw_stateeqn *raw)
{
    static const char *const names[3] = {"i_marker_id", "j_floating_marker_id", "ref_marker_id"};
    int *index[3] = {&f->i_marker, &f->j_marker, &f->ref_marker};
    hx_model *m = d->m;
    for (int k = 0; k < 3; ++k) {
        *index[k] = hx_model_marker(m, raw->marker_ids[k]);
        if (*index[k] < 0) {
            hx_draft_fail(d, f->line, "Force_StateEqn %d: %s %d is not a Reference_Marker", f->id,
                          names[k], raw->marker_ids[k]);
            return -1;
        }
        m->markers[*index[k]].tracked = 1;
    }
    if (m->markers[f->i_marker].body == m->markers[f->j_marker].body) {
        hx_draft_fail(d, f->line, "Force_StateEqn %d: its I and J markers are on the same body",
                      f->id);
        return -1;
    }
    return 0;
}

static int resolve_arrays(hx_draft *d, hx_stateeqn *f, const raw_stateeqn *raw)
{
    hx_model *m = d->m;
    if (array_ref(d, f, "x_array_id", raw->x_array_id, HX_ARRAY_X, &f->x_array) != 0)
        return -1;
    if (m->arrays[f->x_array].count != f->nstate) {
        hx_draft_fail(d, f->line, "Force_StateEqn %d: num_state is %d but its X array %d holds %d"
                      " elements", f->id, f->nstate, raw->x_array_id, m->arrays[f->x_array].count);
        return -1;
    }
    f->initial = calloc((size_t)f->nstate + 1, sizeof(double));
    if (f->initial == NULL) {
        hx_draft_fail(d, f->line, "out of memory");
        return -1;
    }
    if (raw->ic_array_id != 0) {
        if (array_ref(d, f, "ic_array_id", raw->ic_array_id, HX_ARRAY_IC, &f->ic_array) != 0)
            return -1;
        const hx_array *ic = &m->arrays[f->ic_array];
        if (ic->count != f->nstate) {
            hx_draft_fail(d, f->line, "Force_StateEqn %d: num_state is %d but its IC array %d"
                          " holds %d numbers", f->id, f->nstate, ic->id, ic->count);
            return -1;
        }
        if (f->nstate > 0)
            memcpy(f->initial, ic->numbers, sizeof(double) * (size_t)f->nstate);
    }
    if (raw->u_array_id == 0)
        return 0;
    if (array_ref(d, f, "u_array_id", raw->u_array_id, HX_ARRAY_U, &f->u_array) != 0)
        return -1;
    const hx_array *u = &m->arrays[f->u_array];
    f->ninput = u->count;
    f->inputs = malloc(sizeof(int) * (size_t)(u->count > 0 ? u->count : 1));
    if (f->inputs == NULL) {
        hx_draft_fail(d, f->line, "out of memory");
        return -1;
    }
    for (int i = 0; i < u->count; ++i) {
        f->inputs[i] = u->variables[i];
        const hx_variable *v = &m->variables[u->variables[i]];
        /* an expression of TIME and measures: the harness evaluates it at the
         * frames and differences it for the Jacobian; what other variables,
         * arrays or Control_Diffs hold is computed elsewhere (docs/interface.md §7.10) */
        const hx_expr_input *in = v->program != NULL ? hx_expr_inputs(v->program) : NULL;
        for (int j = 0; v->program != NULL && j < hx_expr_input_count(v->program); ++j)
            if (in[j].kind != HX_EXPR_INPUT_TIME && in[j].kind != HX_EXPR_INPUT_MEASURE) {
                char name[64];
                hx_draft_fail(d, f->line, "Force_StateEqn %d: its U array %d names"
                              " Reference_Variable %d, which reads %s: a Force_StateEqn's input"
                              " reads TIME and measures only (docs/interface.md §7.10)", f->id,
                              u->id, v->id, hx_expr_input_text(&in[j], name, sizeof name));
                return -1;
            }
        if (v->varsub) /* its VARSUB's value, by the variables' stage before the forces */
            m->variables_read = 1;
        for (int j = 0; j < v->nmarkers; ++j) /* states keep the frames its inputs read */
            if (v->marker_ids[j] != 0)
                m->markers[hx_model_marker(m, v->marker_ids[j])].tracked = 1;
    }
    return 0;
}

int hx_draft_resolve_stateeqns(hx_draft *d)
{
    hx_model *m = d->m;
    if (resolve_variables(d) != 0)
        return -1;
    for (int k = 0; k < m->nstateeqns; ++k) {
        hx_stateeqn *f = &m->stateeqns[k];
        const raw_stateeqn *raw = &d->rstateeqns[k];
        if (resolve_markers(d, f, raw) != 0 || resolve_arrays(d, f, raw) != 0)
            return -1;
    }
    return 0;
}
