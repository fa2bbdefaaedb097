/*
 * The Newton matrix's rows of the user routines that are not forces
 * (sim/dynamics/routines.h): a Control_Diff's row by central differences of
 * DIFSUB (or of its expression) in its own state and in the columns its
 * declared queries (or its expression) read: the bodies of the markers they
 * name, the Control_Diff states they name, and, for a rate read by DIF1,
 * the columns that rate depends on in turn, the rate computed again at each
 * moved state; an expression's partials in the states it reads by DIF are
 * exact where it reads neither a variable nor a rate. The implicit
 * Control_Diffs' rows by central differences too, their rates solved again
 * together at each moved state (d ydot/dx = -(dF/dydot)^-1 dF/dx, which the
 * differences of the solved rates give). A driven joint's rows, functions of
 * time alone, are zero; an acceleration motion's states between bodies
 * s' = v (1) and v' = f(t) (zero).
 */
#include <stdio.h>
#include <stdlib.h>

#include "expr/evaluate.h"
#include "host/invoke.h"
#include "host/variable_values.h"
#include "model/expr/program.h"
#include "host/queries.h"
#include "sim/dynamics/routines.h"
#include "sim/dynamics/failure.h"
#include "sim/dynamics/implicit_diffs.h"
#include "sim/jacobian/jacobian_parts.h"

static void add_column(int *cols, int *n, int max, int c)
{
    for (int k = 0; k < *n; ++k)
        if (cols[k] == c)
            return;
    if (*n < max)
        cols[(*n)++] = c;
}

/* The routine of the Control_Diff in slot `slot` (-1: none). */
static int diff_routine(const hx_model *m, int slot)
{
    for (int k = 0; k < m->nroutines; ++k)
        if (m->routines[k].kind == HX_ROUTINE_DIFF && m->routines[k].slot == slot)
            return k;
    return -1;
}

/* Whether program p reads a Control_Diff's rate (DIF1). */
static int reads_rate(const hx_expr_program *p)
{
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j)
        if (in[j].kind == HX_EXPR_INPUT_DIF1)
            return 1;
    return 0;
}

static void diff_columns_into(const hx_dynamics *d, int routine, int *cols, int *n, int max,
                              int *implicit_added);
static void program_columns(const hx_dynamics *d, const hx_expr_program *p, int *cols, int *n,
                            int max, int *implicit_added);

/* The columns of the implicit Control_Diffs' rates, solved together: their
 * states and every column their residuals read (once: *implicit_added). */
static void implicit_columns(const hx_dynamics *d, int *cols, int *n, int max,
                             int *implicit_added)
{
    if (*implicit_added)
        return;
    *implicit_added = 1;
    for (int i = 0; i < d->nimplicit; ++i) {
        const hx_routine *r = &d->m->routines[d->implicit[i]];
        add_column(cols, n, max, d->diff_offset + r->slot);
        program_columns(d, r->program, cols, n, max, implicit_added);
    }
}

/* The columns of the body marker `marker` sits on. */
static void marker_columns(const hx_dynamics *d, int marker, int *cols, int *n, int max)
{
    int body_cols[13];
    const int nb = hx_jacobian_body_columns(d, d->m->markers[marker].body, body_cols);
    for (int c = 0; c < nb; ++c)
        add_column(cols, n, max, body_cols[c]);
}

static void variable_columns(const hx_dynamics *d, int k, int *cols, int *n, int max,
                             int *implicit_added);

/* The columns routine binding b's declared queries read (a DIFSUB's, a
 * VARSUB's): the bodies of the markers they name, the states of the
 * Control_Diffs they name, the columns of the variables they read. */
static void declared_columns(const hx_dynamics *d, const hx_binding *b, int *cols, int *n, int max,
                             int *implicit_added)
{
    const hx_model *m = d->m;
    for (int q = 0; b != NULL && q < b->deps.count; ++q) {
        const hx_query *dq = &b->deps.query[q];
        const int reads = hx_query_reads(dq);
        if (reads == HX_READS_VARIABLE) {
            const int k = hx_model_variable(m, dq->ipar[0]);
            if (k >= 0)
                variable_columns(d, k, cols, n, max, implicit_added);
            continue;
        }
        for (int i = 0; i < dq->nsize && i < 4; ++i) {
            if (reads == HX_READS_DIFF) {
                const int k = hx_model_routine(m, HX_ROUTINE_DIFF, dq->ipar[i]);
                if (k >= 0)
                    add_column(cols, n, max, d->diff_offset + m->routines[k].slot);
                break; /* DIF names one element */
            }
            const int marker = reads == HX_READS_MARKERS && dq->ipar[i] != 0
                                   ? hx_model_marker(m, dq->ipar[i]) : -1;
            if (marker >= 0)
                marker_columns(d, marker, cols, n, max);
        }
    }
}

/* The columns variable k reads: its VARSUB's declared ones, its program's,
 * its measure's markers' (they form no cycle: model/variable_programs.c,
 * host/variable_reads.h). */
static void variable_columns(const hx_dynamics *d, int k, int *cols, int *n, int max,
                             int *implicit_added)
{
    const hx_model *m = d->m;
    const hx_variable *v = &m->variables[k];
    if (v->varsub)
        declared_columns(d, d->routine_binding[v->routine], cols, n, max, implicit_added);
    if (v->program != NULL)
        program_columns(d, v->program, cols, n, max, implicit_added);
    for (int i = 0; v->program == NULL && i < v->nmarkers; ++i)
        if (v->marker_ids[i] != 0)
            marker_columns(d, hx_model_marker(m, v->marker_ids[i]), cols, n, max);
}

/* The columns program p reads: the Control_Diff states it names (DIF), the
 * columns of the rates it names (DIF1: the model refuses a cycle of them,
 * model/routine_elements.c), the bodies its markers sit on, through the
 * variables it reads. */
static void program_columns(const hx_dynamics *d, const hx_expr_program *p, int *cols, int *n,
                            int max, int *implicit_added)
{
    const hx_model *m = d->m;
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int j = 0; j < hx_expr_input_count(p); ++j) {
        if (in[j].kind == HX_EXPR_INPUT_DIF)
            add_column(cols, n, max, d->diff_offset + in[j].index[0]);
        if (in[j].kind == HX_EXPR_INPUT_DIF1) {
            const int rate = diff_routine(m, in[j].index[0]);
            if (rate >= 0)
                diff_columns_into(d, rate, cols, n, max, implicit_added);
        }
        if (in[j].variable >= 0)
            variable_columns(d, in[j].variable, cols, n, max, implicit_added);
        for (int i = 0; in[j].kind == HX_EXPR_INPUT_MEASURE && i < in[j].nids && i < 4; ++i)
            if (in[j].index[i] >= 0)
                marker_columns(d, in[j].index[i], cols, n, max);
    }
}

static void diff_columns_into(const hx_dynamics *d, int routine, int *cols, int *n, int max,
                              int *implicit_added)
{
    const hx_model *m = d->m;
    add_column(cols, n, max, d->diff_offset + m->routines[routine].slot);
    if (m->routines[routine].implicit && m->routines[routine].program != NULL) {
        implicit_columns(d, cols, n, max, implicit_added);
        return;
    }
    if (m->routines[routine].program != NULL) {
        program_columns(d, m->routines[routine].program, cols, n, max, implicit_added);
        return;
    }
    declared_columns(d, d->routine_binding[routine], cols, n, max, implicit_added);
}

int hx_diff_columns(const hx_dynamics *d, int routine, int *cols, int max)
{
    int n = 0, implicit_added = 0;
    diff_columns_into(d, routine, cols, &n, max, &implicit_added);
    return n;
}

/* The rates routine k's expression reads by DIF1 computed again at jac->dd's
 * frames (and first those they read in turn), as the routines stage
 * computes them (DIFSUB as for a difference); 0 or -1 (jac->dd.message). */
static int read_rates(hx_jacobian *jac, int k);

/* The implicit rates solved again at jac->dd's frames (the DIFSUB rates
 * their residuals read computed there first), Newton from their rates at
 * the build's state; 0 or -1 (jac->dd.message). */
static int implicit_rates(hx_jacobian *jac)
{
    const hx_dynamics *d = jac->d;
    for (int i = 0; i < d->nimplicit; ++i)
        if (read_rates(jac, d->implicit[i]) != 0)
            return -1;
    return hx_implicit_diffs_solve(d, &jac->dd, NULL);
}

static int read_rates(hx_jacobian *jac, int k)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_expr_program *p = d->m->routines[k].program;
    if (p == NULL)
        return 0;
    const hx_expr_input *in = hx_expr_inputs(p);
    int solved = d->m->routines[k].implicit; /* an implicit one's are solved by the caller */
    for (int j = 0; j < hx_expr_input_count(p); ++j) {
        const int r = in[j].kind == HX_EXPR_INPUT_DIF1 ? diff_routine(d->m, in[j].index[0]) : -1;
        if (r < 0)
            continue;
        if (d->m->routines[r].implicit && d->m->routines[r].program != NULL) {
            if (!solved && implicit_rates(jac) != 0)
                return -1;
            solved = 1;
            continue;
        }
        double rate;
        if (d->m->routines[r].program != NULL) {
            if (read_rates(jac, r) != 0 || hx_routines_diff_expression(d, dd, r, &rate) != 0)
                return -1;
        } else {
            hx_binding *b = d->routine_binding[r];
            hx_invoke_routine(b, &dd->frames, 1, 0, &rate, NULL);
            jac->partial_calls++;
            if (hx_dynamics_check_call(d, dd, b, NULL, 0, "", dd->frames.time) != 0)
                return -1;
        }
        dd->frames.diffs[2 * in[j].index[0] + 1] = rate;
    }
    return 0;
}

/* DIFSUB (or the expression) of routine k at (t, y), jac->dd's kinematics
 * set there, and the variables and the rates it reads (DIF1) computed there;
 * 0 or -1 (jac->dd.message). */
static int diff_rate(hx_jacobian *jac, int k, double t, const double *y, double *rate)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    hx_dynamics_kinematics(d, dd, t, y);
    if (d->m->routines[k].program != NULL) {
        const int rates = reads_rate(d->m->routines[k].program);
        if (d->m->routines[k].reads_variables || (rates && d->diffs_read_variables)) {
            hx_message msg;
            if (hx_variables_values(&dd->frames, d->routine_binding, dd->frames.variables,
                                    &msg) != 0)
                return hx_dynamics_fail(dd, "%s", msg.text);
        }
        if (d->m->routines[k].implicit) { /* solved with the other implicit ones */
            if (implicit_rates(jac) != 0)
                return -1;
            *rate = dd->frames.diffs[2 * d->m->routines[k].slot + 1];
            return 0;
        }
        if (rates && read_rates(jac, k) != 0)
            return -1;
        return hx_routines_diff_expression(d, dd, k, rate);
    }
    hx_message msg; /* a DIFSUB may read variables by c_sysfnc VARVAL (host/variable_reads.h) */
    if (d->m->variables_read &&
        hx_variables_values(&dd->frames, d->routine_binding, dd->frames.variables, &msg) != 0)
        return hx_dynamics_fail(dd, "%s", msg.text);
    hx_binding *b = d->routine_binding[k];
    hx_invoke_routine(b, &dd->frames, 1, 0, rate, NULL); /* dflag: a difference */
    jac->partial_calls++;
    return hx_dynamics_check_call(d, dd, b, NULL, 0, "", t);
}

int hx_routine_blocks_init(hx_jacobian *jac, hx_message *msg)
{
    const hx_dynamics *d = jac->d;
    const int motions = d->m->nroutines_of[HX_ROUTINE_MOTION];
    int *rows = malloc(sizeof(int) * (2 * (size_t)motions + 1));
    if (rows == NULL)
        return hx_fail(msg, "out of memory");
    const int ndriven = hx_routines_driven_rows(d, rows);
    for (int i = 0; i < ndriven; ++i)
        jac->driven[rows[i]] = 1;
    free(rows);
    size_t scratch = 1;
    for (int k = 0; k < d->m->nroutines; ++k)
        if (d->m->routines[k].program != NULL &&
            hx_expr_scratch_size(d->m->routines[k].program) > scratch)
            scratch = hx_expr_scratch_size(d->m->routines[k].program);
    jac->diff_scratch = malloc(sizeof(double) * scratch);
    if (jac->diff_scratch == NULL)
        return hx_fail(msg, "out of memory");
    return 0;
}

/* The exact partials of the expression of routine k in the Control_Diff
 * states it reads by DIF (evaluate.h), where it reads no variable and no
 * rate (a variable's or a rate's dependence on them is taken by differences
 * with the rest):
 * added to its row; their columns marked done. 0 or -1. */
static int diff_exact(hx_jacobian *jac, int k, double t, const double *y, const int *cols, int nc,
                      unsigned char *done)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_routine *r = &d->m->routines[k];
    if (r->program == NULL || r->reads_variables || reads_rate(r->program))
        return 0;
    hx_dynamics_kinematics(d, dd, t, y);
    const hx_expr_context c = {&dd->frames, dd->frames.variables, NULL};
    double value, partials[HX_EXPR_MAX_INPUTS];
    hx_expr_fault fault;
    if (hx_expr_eval_partials(r->program, &c, &value, partials, jac->diff_scratch, &fault) != 0) {
        char element[48];
        hx_message msg;
        snprintf(element, sizeof element, "Control_Diff %d", r->id);
        hx_expr_fail(&msg, r->program, &fault, element);
        return hx_dynamics_fail(dd, "%s", msg.text);
    }
    const hx_expr_input *in = hx_expr_inputs(r->program);
    const int row = d->diff_offset + r->slot;
    for (int j = 0; j < hx_expr_input_count(r->program); ++j) {
        if (in[j].kind != HX_EXPR_INPUT_DIF)
            continue;
        const int col = d->diff_offset + in[j].index[0];
        hx_jacobian_add(jac, row, 1, col, &partials[j]);
        for (int i = 0; i < nc; ++i)
            if (cols[i] == col)
                done[i] = 1;
    }
    return 0;
}

int hx_routine_blocks(hx_jacobian *jac, double t, const double *y)
{
    const hx_dynamics *d = jac->d;
    hx_dynamics_data *dd = &jac->dd;
    const hx_model *m = d->m;
    if (m->nroutines == 0)
        return 0;
    static const double one = 1.0;
    for (int k = 0; k < d->nmotions; ++k)
        if (d->motion_state[k] >= 0)
            hx_jacobian_add(jac, d->motion_state[k], 1, d->motion_state[k] + 1, &one);
    if (m->nroutines_of[HX_ROUTINE_MOTION] > 0)
        for (int p = 0; p < jac->pattern.nnz; ++p)
            if (jac->driven[jac->pattern.rowind[p]])
                jac->values[p] = 0.0;
    double *yp = jac->y;
    int cols[DIFF_COLUMNS_MAX];
    for (int k = 0; k < m->nroutines; ++k) {
        if (m->routines[k].kind != HX_ROUTINE_DIFF)
            continue;
        const int row = d->diff_offset + m->routines[k].slot;
        const int nc = hx_diff_columns(d, k, cols, DIFF_COLUMNS_MAX);
        unsigned char done[DIFF_COLUMNS_MAX] = {0};
        if (diff_exact(jac, k, t, y, cols, nc, done) != 0)
            return -1;
        for (int j = 0; j < nc; ++j) {
            if (done[j])
                continue;
            const int c = cols[j];
            const double h = hx_jacobian_step(y, c);
            double plus, minus;
            yp[c] = y[c] + h;
            const int status = diff_rate(jac, k, t, yp, &plus);
            yp[c] = y[c] - h;
            const int status2 = status == 0 ? diff_rate(jac, k, t, yp, &minus) : -1;
            yp[c] = y[c];
            if (status2 != 0)
                return -1;
            const double slope = (plus - minus) / (2.0 * h);
            hx_jacobian_add(jac, row, 1, c, &slope);
        }
    }
    /* jac->dd's kinematics back at the build's state, and the variables and
     * rates the differences moved */
    hx_dynamics_kinematics(d, dd, t, y);
    int rates = 0;
    for (int k = 0; k < m->nroutines; ++k)
        rates |= m->routines[k].program != NULL && reads_rate(m->routines[k].program);
    if (!rates && !d->diffs_read_variables)
        return 0;
    hx_message msg;
    if ((m->variables_read || d->diffs_read_variables) &&
        hx_variables_values(&dd->frames, d->routine_binding, dd->frames.variables, &msg) != 0)
        return hx_dynamics_fail(dd, "%s", msg.text);
    if (d->nimplicit > 0 && implicit_rates(jac) != 0)
        return -1;
    for (int k = 0; rates && k < m->nroutines; ++k)
        if (m->routines[k].program != NULL && !m->routines[k].implicit &&
            reads_rate(m->routines[k].program) && read_rates(jac, k) != 0)
            return -1;
    return 0;
}
