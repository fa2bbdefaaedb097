/*
 * The utilities a user library calls back (include/usrsub/solver_abi.h,
 * docs/interface.md §1, §5), answered for the call bound to the thread. This
 * file holds the harness's only global: that binding, which the ABI forces
 * (the utilities carry no context).
 */
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "host/call.h"
#include "host/utilities.h"
#include "model/units.h"
#include "usrsub/solver_abi.h"

static _Thread_local hx_call *bound;

void hx_host_bind(hx_call *c)
{
    bound = c;
}

void hx_host_unbind(void)
{
    bound = NULL;
}

hx_call *hx_host_bound(void)
{
    return bound;
}

static int is_word(const char *text, const char *word)
{
    if (text == NULL)
        return 0;
    while (*text == ' ')
        ++text;
    const size_t n = strlen(word);
    if (strncasecmp(text, word, n) != 0)
        return 0;
    for (text += n; *text == ' '; ++text)
        ;
    return *text == '\0';
}

void c_errmes(int errflg, const char *msg, int id, const char *endflg)
{
    if (!errflg)
        return;
    const int stop = is_word(endflg, "STOP");
    if (bound != NULL && bound->messages != NULL)
        hx_messages_error(bound->messages, id, msg, stop);
    else
        fprintf(stderr, "ERRMES [%d]%s (outside any call): %s\n", id, stop ? " STOP" : "",
                msg != NULL ? msg : "");
}

void c_usrmes(int msgflg, const char *msg, int id, const char *msgtyp)
{
    if (!msgflg)
        return;
    if (bound != NULL && bound->messages != NULL)
        hx_messages_notice(bound->messages, id, msgtyp, msg);
    else
        fprintf(stderr, "USRMES:USER [%d] %s (outside any call): %s\n", id,
                msgtyp != NULL ? msgtyp : "INFO", msg != NULL ? msg : "");
}

void c_gtstrg(int id, char *string, int *nchars, int *istat)
{
    const char *text = bound != NULL && bound->model != NULL ? hx_model_string(bound->model, id)
                                                             : NULL;
    if (text == NULL || string == NULL || nchars == NULL) {
        if (istat != NULL)
            *istat = -1;
        return;
    }
    const int len = (int)strlen(text);
    const int capacity = *nchars; /* our convention: nchars carries the capacity in */
    if (capacity > 0 && len > capacity) {
        memcpy(string, text, (size_t)capacity);
        *nchars = capacity;
        if (istat != NULL)
            *istat = 1; /* truncated */
        return;
    }
    memcpy(string, text, (size_t)len);
    if (capacity <= 0 || len < capacity)
        string[len] = '\0';
    *nchars = len;
    if (istat != NULL)
        *istat = 0;
}

void c_gtunts(int *exists, double *scales, char *units)
{
    /* The Adams-compatible layout (docs/interface.md §1): exactly four sizes,
     * time, length, force, mass, and twelve characters; nothing beyond them,
     * since callers hold exactly that much. */
    static const enum hx_unit_kind order[USRSUB_GTUNTS_COUNT] = {
        [USRSUB_GTUNTS_TIME] = HX_UNIT_TIME, [USRSUB_GTUNTS_LENGTH] = HX_UNIT_LENGTH,
        [USRSUB_GTUNTS_FORCE] = HX_UNIT_FORCE, [USRSUB_GTUNTS_MASS] = HX_UNIT_MASS};
    const hx_model *m = bound != NULL ? bound->model : NULL;
    const int has = m != NULL && m->has_units;
    if (exists != NULL)
        *exists = has;
    if (!has)
        return;
    for (int k = 0; k < USRSUB_GTUNTS_COUNT; ++k) {
        if (scales != NULL)
            scales[k] = m->unit_scales[order[k]];
        if (units != NULL)
            memcpy(units + 3 * k, hx_unit_abbreviation(order[k], m->unit_scales[order[k]]), 3);
    }
}

/* ---- data access (docs/interface.md §5.2) -------------------------------------------- */

void c_gtaray(int id, double *array, int *number, int *istat)
{
    const hx_model *m = bound != NULL ? bound->model : NULL;
    const int k = m != NULL ? hx_model_array(m, id) : -1;
    if (array == NULL || number == NULL) {
        hx_utility_refused(HX_UTILITY_GTARAY, "no array or count to answer in (a null pointer)");
        if (istat != NULL)
            *istat = 1;
        return;
    }
    if (k < 0 || m->arrays[k].type != HX_ARRAY_IC) {
        hx_utility_refused(HX_UTILITY_GTARAY, "id %d, which names no Reference_Array of type IC"
                           " (the arrays whose numbers the model holds)", id);
        if (istat != NULL)
            *istat = 1;
        return;
    }
    /* number is an output only, as in a solver (callers often leave it
     * unset): the whole array, as long as the model wrote it */
    const hx_array *a = &m->arrays[k];
    memcpy(array, a->numbers, sizeof(double) * (size_t)a->count);
    *number = a->count;
    if (istat != NULL)
        *istat = 0;
}

void c_getstm(double *time)
{
    *time = bound != NULL && bound->frames != NULL ? bound->frames->time : 0.0;
}

void c_timget(double *time)
{
    /* the time of the last converged step: the harness calls an element at
     * states it has accepted or is trying, and answers the call's own time */
    c_getstm(time);
}

void c_getinm(int *value)
{
    *value = 0; /* not interactive: the harness runs from its command line */
}

/* ---- state queries ------------------------------------------------------------------- */

static void report_refused(hx_call *c, const hx_query *q, const char *why)
{
    const double t = c->frames != NULL ? c->frames->time : 0.0;
    hx_note_query(&c->refused, q, t);
    const int fresh = c->reported_refused != NULL ? hx_note_query(c->reported_refused, q, t) : 1;
    if (fresh && c->messages != NULL) {
        char text[64];
        hx_messages_host(c->messages, "%s %d (%s) asked %s %s at t = %g, which the host refuses:"
                         " %s; it answered errflg = 1", c->element, c->id,
                         c->routine != NULL ? c->routine : "?", q->is_array ? "c_sysary" : "c_sysfnc",
                         hx_query_text(q, text, sizeof text), t, why);
    }
}

static void report_undeclared(hx_call *c, const hx_query *q)
{
    const double t = c->frames != NULL ? c->frames->time : 0.0;
    hx_note_query(&c->undeclared, q, t);
    const int fresh =
        c->reported_undeclared != NULL ? hx_note_query(c->reported_undeclared, q, t) : 1;
    if (fresh && c->messages != NULL) {
        char text[64], declared[512];
        hx_messages_host(c->messages, "%s %d (%s) reads %s at t = %g outside the dependencies it"
                         " declared in its dependency pass (%s)", c->element, c->id,
                         c->routine != NULL ? c->routine : "?", hx_query_text(q, text, sizeof text),
                         t, hx_dependencies_text(c->declared, declared, sizeof declared));
    }
}

static int find_declared(hx_call *c, const hx_query *q)
{
    const hx_dependencies *d = c->declared;
    for (int n = 0, k = c->next_declared; n < d->count; ++n, k = k + 1 < d->count ? k + 1 : 0)
        if (hx_query_same(&d->query[k], q)) {
            c->next_declared = k + 1 < d->count ? k + 1 : 0;
            return k;
        }
    return -1;
}

/* An acceleration or a force declared as query k, from the algebraic loop's values in
 * the frames, or a REQSUB's from the output queries' values given with the call
 * (host/loop_queries.h); 0, or -1 refused. */
static int answer_loop(hx_call *c, const hx_query *q, int k, double *values, int count)
{
    for (int i = 0; i < count; ++i) {
        const int slot = c->loop_slot != NULL ? c->loop_slot[k][i] : -1;
        if (slot >= 0 && c->at_output) {
            values[i] = c->answers != NULL ? c->answers[slot] : 0.0;
            continue;
        }
        if (slot < 0 || c->frames->loop == NULL) {
            report_refused(c, q, "the value has no place among the algebraic loop's inputs"
                           " (this call is not an element's within a right-hand side:"
                           " docs/interface.md §5.1)");
            return -1;
        }
        values[i] = c->frames->loop[slot];
    }
    return 0;
}

/* Common path of c_sysary and c_sysfnc: the number of values, or -1. */
static int query(const char *fnc, const int *ipar, int nsize, double *values, int is_array)
{
    hx_call *c = bound;
    if (c == NULL)
        return -1; /* called outside any entry: nothing to answer from */
    ++c->host_calls;
    hx_query q;
    hx_query_make(&q, fnc, ipar, nsize, is_array);
    if (!c->may_query) {
        report_refused(c, &q, "this routine may not call c_sysary or c_sysfnc (its state comes"
                       " in its arguments)");
        return -1;
    }
    if (values == NULL) {
        report_refused(c, &q, "its array for the answer is a null pointer");
        return -1;
    }
    const int count = hx_answer(c->frames, &q, ipar, values);
    if (count < 0) {
        report_refused(c, &q, "not a function and argument list the harness answers (c_sysary: DISP TDISP"
                       " RDISP VEL TVEL RVEL, ACC TACC RACC, ARRAY of an IC Reference_Array;"
                       " c_sysfnc: DX DY DZ DM AX AY AZ PSI THETA PHI YAW PITCH ROLL INCANG VX VY VZ"
                       " VM VR WX WY WZ WM, ACCX ACCY ACCZ ACCM WDTX WDTY WDTZ WDTM, DIF DIF1 of a"
                       " Control_Diff, VARVAL of a Reference_Variable, JOINT JPRIM MOTION COUPLER GCON"
                       " SFORCE VFORCE VTORQ GFORCE FIELD BUSHING BEAM SPDP (id, jflag, comp, rm),"
                       " FX FY FZ TX TY TZ (I[, J[, K]]), FM TM (I[, J]); existing ids):"
                       " docs/interface.md"
                       " §5.1");
        return -1;
    }
    if (c->dependency_pass) {
        for (int k = 0; k < count; ++k)
            values[k] = 0.0; /* the dependency pass sees zeros, as in a solver */
        if (c->declared != NULL && find_declared(c, &q) < 0) {
            if (c->declared->count < HX_MAX_QUERIES)
                c->declared->query[c->declared->count++] = q;
            else
                c->declared->overflow = 1;
        }
        return count;
    }
    /* accelerations and forces: the algebraic loop's inputs (host/loop_queries.h) */
    const int reads = hx_query_reads(&q);
    const int loop_read = reads == HX_READS_ACCELERATIONS || reads == HX_READS_FORCES;
    if (c->declared != NULL) {
        const int k = find_declared(c, &q);
        if (k < 0) {
            report_undeclared(c, &q);
            if (loop_read)
                return -1; /* no place in the loop to answer it from */
        } else {
            if (loop_read && answer_loop(c, &q, k, values, count) != 0)
                return -1;
            c->used |= 1u << k;
            if (k == c->perturb_query && c->perturb_component < count)
                values[c->perturb_component] += c->perturb_delta;
        }
    } else if (loop_read) {
        report_refused(c, &q, "an acceleration or a force is answered only to a routine that"
                       " declared it in its dependency pass (docs/interface.md §5.1)");
        return -1;
    }
    return count;
}

void c_sysary(const char *fnc, const int *ipar, int nsize, double *states, int *nstates,
              int *errflg)
{
    const int count = query(fnc, ipar, nsize, states, 1);
    if (nstates != NULL)
        *nstates = count > 0 ? count : 0;
    if (errflg != NULL)
        *errflg = count > 0 ? 0 : 1;
}

void c_sysfnc(const char *fnc, const int *ipar, int nsize, double *value, int *errflg)
{
    double v[6] = {0};
    const int count = query(fnc, ipar, nsize, v, 0);
    if (value != NULL)
        *value = count == 1 ? v[0] : 0.0;
    if (errflg != NULL)
        *errflg = count == 1 ? 0 : 1;
}
