/*
 * The loads' expressions read and linked (load_elements.h): each component
 * parsed by the expression engine (model/expr/expr.h) when its element is
 * read, so that an error names the element, the attribute and the
 * file:line:column of the token at fault.
 */
#include "model/load_elements.h"

#include <ctype.h>
#include <string.h>

#include "model/expr/expr.h"

static const char *const vector_attrs[6] = {"fx_expression", "fy_expression", "fz_expression",
                                            "tx_expression", "ty_expression", "tz_expression"};

/* The engine's "file:line:column: what" as "file:line:column: element id:
 * attribute: what" (the draft's first error wins). */
void hx_draft_fail_expression(hx_draft *d, const char *element, int id, const char *attr,
                            const char *text)
{
    if (d->failed)
        return;
    const size_t n = strlen(d->path);
    const char *p = text;
    if (strncmp(text, d->path, n) == 0 && text[n] == ':') {
        const char *q = text + n + 1;
        for (int field = 0; field < 2 && isdigit((unsigned char)*q); ++field) {
            while (isdigit((unsigned char)*q))
                ++q;
            if (*q == ':')
                ++q;
        }
        if (q[0] == ' ')
            p = q + 1;
    }
    if (p == text)
        hx_fail(d->msg, "%s: %s %d: %s: %s", d->path, element, id, attr, text);
    else
        hx_fail(d->msg, "%.*s %s %d: %s: %s", (int)(p - text - 1), text, element, id, attr, p);
    d->failed = 1;
}

int hx_draft_parse_expression(hx_draft *d, const hx_element_read *e, const char *name,
                      hx_expr_program **out)
{
    *out = NULL;
    const int k = hx_attr_find(e, name);
    if (k < 0 || !e->value[k].present)
        return 0;
    const char *text = e->value[k].text;
    const int known = e->value[k].line > 0;
    const hx_expr_source where = {d->path, known ? e->value[k].line : e->line,
                                  known ? e->value[k].column : 1};
    hx_message why;
    *out = hx_expr_parse(text, strlen(text), &where, &why);
    if (*out == NULL) {
        hx_draft_fail_expression(d, e->name, e->id, name, why.text);
        return -1;
    }
    return 0;
}

static hx_load *push_load(hx_draft *d, const hx_element_read *e, enum hx_load_kind kind)
{
    hx_model *m = d->m;
    hx_load *l = hx_draft_push(d, (void **)&m->loads, &m->nloads, &d->cap_loads, sizeof *l,
                               (void **)&d->rloads, sizeof(raw_refs));
    if (l != NULL) {
        l->id = e->id;
        l->kind = kind;
        l->line = e->line;
    }
    return l;
}

void hx_build_vector_load(hx_draft *d, const hx_element_read *e, int i_id, int j_id, int ref_id)
{
    hx_load *l = push_load(d, e, HX_LOAD_VECTOR);
    if (l == NULL)
        return;
    raw_refs *refs = &d->rloads[d->m->nloads - 1];
    refs->ids[0] = i_id, refs->ids[1] = j_id, refs->ids[2] = ref_id;
    for (int k = 0; k < 6; ++k)
        if (hx_draft_parse_expression(d, e, vector_attrs[k], k < 3 ? &l->force[k] : &l->torque[k - 3]) != 0)
            return;
}

void hx_build_scalar_load(hx_draft *d, const hx_element_read *e, int torque,
                          const char *value_attr)
{
    hx_load *l = push_load(d, e, torque ? HX_LOAD_SCALAR_TORQUE : HX_LOAD_SCALAR_FORCE);
    if (l == NULL)
        return;
    l->action_only = hx_attr_number(e, "is_action_only", 0.0) != 0.0;
    if (hx_draft_parse_expression(d, e, value_attr, &l->value) != 0)
        return;
    raw_refs *refs = &d->rloads[d->m->nloads - 1];
    refs->ids[0] = hx_attr_int(e, "i_marker_id", 0);
    refs->ids[1] = hx_attr_int(e, "j_marker_id", 0);
}

static int link_one(hx_draft *d, const hx_load *l, hx_expr_program *p, const char *attr)
{
    if (p == NULL)
        return 0;
    hx_model *m = d->m;
    const char *element = hx_load_element_name(l);
    hx_message why;
    if (hx_expr_link_loop(p, m, &why) != 0) {
        hx_draft_fail_expression(d, element, l->id, attr, why.text);
        return -1;
    }
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int k = 0; k < hx_expr_input_count(p); ++k) {
        if (in[k].kind == HX_EXPR_INPUT_TIME)
            continue;
        const int variable = in[k].variable;
        if (variable >= 0) {
            /* a variable's value, computed before the forces (docs/interface.md §7.10);
             * the Control_Diff states it reads are the load's Jacobian columns too */
            m->variables_read = 1;
            continue;
        }
        if (in[k].kind == HX_EXPR_INPUT_DIF)
            continue; /* a Control_Diff's state, set before the forces (§7.10) */
        if (in[k].kind == HX_EXPR_INPUT_ACCELERATION || in[k].kind == HX_EXPR_INPUT_REACTION ||
            in[k].kind == HX_EXPR_INPUT_LOAD || in[k].kind == HX_EXPR_INPUT_MARKER_FORCE)
            continue; /* an algebraic loop's input (model/loop_inputs.h) */
        if (in[k].kind != HX_EXPR_INPUT_MEASURE) {
            /* a rate (DIF1) is computed after the forces; an IC array is refused as
             * before */
            char name[64], what[HX_MESSAGE_MAX];
            snprintf(what, sizeof what, "%s:%d:%d: %s: a force's expression reads TIME, the"
                     " measures of markers, Control_Diff states (DIF) and variables; a"
                     " Control_Diff's rate (DIF1, computed after the forces) or an IC"
                     " array is not simulated yet", d->path, in[k].line, in[k].column,
                     hx_expr_input_text(&in[k], name, sizeof name));
            hx_draft_fail_expression(d, element, l->id, attr, what);
            return -1;
        }
        for (int i = 0; i < in[k].nids && i < 4; ++i)
            if (in[k].index[i] >= 0)
                m->markers[in[k].index[i]].tracked = 1;
    }
    return 0;
}

int hx_draft_link_loads(hx_draft *d)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->nloads; ++k) {
        const hx_load *l = &m->loads[k];
        if (l->kind != HX_LOAD_VECTOR) {
            if (link_one(d, l, l->value, "val_expression") != 0)
                return -1;
            continue;
        }
        for (int i = 0; i < 6; ++i)
            if (link_one(d, l, i < 3 ? l->force[i] : l->torque[i - 3], vector_attrs[i]) != 0)
                return -1;
    }
    return 0;
}
