/*
 * The general constraints (gcon_elements.h, docs/interface.md §7.16): built
 * by both readers through one builder, linked once the model is resolved.
 * A constraint's row needs the expression's derivatives in the bodies'
 * positions (sim/dynamics/expression_rows.c): it may read the measures of
 * displacement and rotation and TIME. A velocity makes it nonholonomic, and
 * a variable, a Control_Diff or an array hides positions the harness would
 * have to differentiate through: each is refused with its place.
 */
#include <stdio.h>
#include <string.h>

#include "model/expr/expr.h"
#include "model/expr/functions.h"
#include "model/gcon_elements.h"
#include "model/load_elements.h"
#include "model/xml_attrs.h"

const hx_attr_spec hx_gcon_attrs[] = {
    ID, REQUIRED("expr", HX_ATTR_TEXT), INT("i_marker_id"), IGNORED("is_virtual"),
    TEXT("usrsub_dll_name"), TEXT("usrsub_param_string"), TEXT("usrsub_fnc_name"),
    TEXT("script_name"), TEXT("interpreter"), END};

void hx_build_gcon(hx_draft *d, const hx_element_read *e)
{
    static const char *const user[] = {"usrsub_dll_name", "usrsub_param_string",
                                       "usrsub_fnc_name", "script_name", "interpreter"};
    for (size_t k = 0; k < sizeof user / sizeof user[0]; ++k)
        if (hx_attr_present(e, user[k])) {
            hx_draft_fail(d, e->line, "Constraint_General %d: %s: a general constraint by a user"
                          " routine (GCOSUB) is not simulated; give its expression in expr",
                          e->id, user[k]);
            return;
        }
    hx_model *m = d->m;
    for (int k = 0; k < m->ngcons; ++k)
        if (m->gcons[k].id == e->id) {
            hx_draft_fail(d, e->line, "Constraint_General %d is defined twice (line %d)", e->id,
                          m->gcons[k].line);
            return;
        }
    hx_gcon *g = hx_draft_push(d, (void **)&m->gcons, &m->ngcons, &d->cap_gcons, sizeof *g,
                               NULL, 0);
    if (g == NULL)
        return;
    g->id = e->id;
    g->line = e->line;
    g->i_marker_id = hx_attr_int(e, "i_marker_id", 0);
    g->i_marker = -1;
    hx_draft_parse_expression(d, e, "expr", &g->program);
}

/* Why the row cannot take input in, or NULL when it can. */
static const char *refused(const hx_expr_input *in)
{
    switch (in->kind) {
    case HX_EXPR_INPUT_TIME:
        return NULL;
    case HX_EXPR_INPUT_MEASURE:
        return in->function >= HX_FN_VX && in->function <= HX_FN_WM
                   ? "a velocity makes the constraint nonholonomic, which the harness does not"
                     " simulate (a general constraint reads the markers' displacements and"
                     " rotations and TIME)"
                   : NULL;
    default:
        return "a general constraint reads the markers' displacements and rotations and TIME"
               " (its row is differentiated through them); a variable, a Control_Diff or an"
               " array is not simulated there";
    }
}

int hx_draft_link_gcons(hx_draft *d)
{
    hx_model *m = d->m;
    for (int k = 0; k < m->ngcons; ++k) {
        hx_gcon *g = &m->gcons[k];
        if (g->i_marker_id != 0 && (g->i_marker = hx_model_marker(m, g->i_marker_id)) < 0) {
            hx_draft_fail(d, g->line, "Constraint_General %d: i_marker_id=%d: no Reference_Marker"
                          " %d in the model", g->id, g->i_marker_id, g->i_marker_id);
            return -1;
        }
        hx_message why;
        if (hx_expr_link(g->program, m, &why) != 0) {
            hx_draft_fail_expression(d, "Constraint_General", g->id, "expr", why.text);
            return -1;
        }
        const hx_expr_input *in = hx_expr_inputs(g->program);
        int measures = 0;
        for (int j = 0; j < hx_expr_input_count(g->program); ++j) {
            const char *why_not = refused(&in[j]);
            if (why_not != NULL) {
                char name[64], what[HX_MESSAGE_MAX];
                snprintf(what, sizeof what, "%s:%d:%d: %s: %s", d->path, in[j].line,
                         in[j].column, hx_expr_input_text(&in[j], name, sizeof name), why_not);
                hx_draft_fail_expression(d, "Constraint_General", g->id, "expr", what);
                return -1;
            }
            if (in[j].kind == HX_EXPR_INPUT_MEASURE) {
                ++measures;
                for (int i = 0; i < in[j].nids && i < 4; ++i)
                    if (in[j].index[i] >= 0)
                        m->markers[in[j].index[i]].tracked = 1;
            }
        }
        if (measures == 0) {
            hx_draft_fail(d, g->line, "Constraint_General %d: expr reads no marker: a constraint"
                          " of time alone holds no body", g->id);
            return -1;
        }
    }
    return 0;
}
