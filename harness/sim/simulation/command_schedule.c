/* A command file's run as segments (command_schedule.h). */
#include "sim/simulation/command_schedule.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "model/expr/expr.h"

/* The name of a path without its folder and extension, into out. */
static void stem(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    snprintf(out, size, "%s", slash != NULL ? slash + 1 : path);
    char *dot = strrchr(out, '.');
    if (dot != NULL && dot != out)
        *dot = '\0';
}

/* Adams reads the dataset the first line names; the harness runs the one on
 * its command line, and says so when they differ. */
static void check_names(const hx_command_file *f, const char *path, const char *model_path,
                        FILE *notes)
{
    char named[256], model[256];
    stem(f->dataset, named, sizeof named);
    stem(model_path, model, sizeof model);
    if (notes != NULL && strcasecmp(named, model) != 0)
        fprintf(notes, "%s:1: warning: the command file names the dataset '%s'; the model run"
                " is %s (the command line's)\n", path, f->dataset, model_path);
    if (notes != NULL && f->output[0] != '\0')
        fprintf(notes, "%s:2: note: the outputs' name '%s' is not used (the CSV is --out's)\n",
                path, f->output);
}

/* The loads a switched statement names: scalar or vector ones, as written
 * (SFORCE .. GFORCE) or built in (§7.17); 0, or -1 for another statement. */
static int switched_element(const char *element, int *scalar, enum hx_load_builtin *builtin)
{
    static const struct {
        const char *name;
        int scalar;
        enum hx_load_builtin builtin;
    } switched[8] = {{"SFORCE", 1, HX_LOAD_AS_WRITTEN},       {"VFORCE", 0, HX_LOAD_AS_WRITTEN},
                     {"VTORQUE", 0, HX_LOAD_AS_WRITTEN},      {"GFORCE", 0, HX_LOAD_AS_WRITTEN},
                     {"SPRINGDAMPER", 1, HX_LOAD_SPRINGDAMPER}, {"BUSHING", 0, HX_LOAD_BUSHING},
                     {"BEAM", 0, HX_LOAD_BEAM},               {"FIELD", 0, HX_LOAD_FIELD}};
    for (int k = 0; k < 8; ++k)
        if (strcmp(element, switched[k].name) == 0) {
            *scalar = switched[k].scalar, *builtin = switched[k].builtin;
            return 0;
        }
    return -1;
}

/* Whether statement (SFORCE, ...) names the user force element f, as the
 * dataset's statements are read (docs/interface.md §9.5): an SFORCE a
 * Force_Scalar_TwoBody's routine, a GFORCE, VFORCE or VTORQUE a
 * Force_Vector's of type ForceAndTorque, ForceOnly or TorqueOnly, a FIELD a
 * FIESUB. */
static int names_force(const hx_force *f, const char *statement)
{
    if (f->interface == HX_FORCE_FIESUB)
        return strcmp(statement, "FIELD") == 0;
    switch (f->part) {
    case HX_OUTPUT_FORCE_AND_TORQUE: return strcmp(statement, "GFORCE") == 0;
    case HX_OUTPUT_FORCE: return strcmp(statement, "VFORCE") == 0;
    case HX_OUTPUT_TORQUE: return strcmp(statement, "VTORQUE") == 0;
    case HX_OUTPUT_SCALAR_FORCE:
    case HX_OUTPUT_SCALAR_TORQUE: return strcmp(statement, "SFORCE") == 0;
    }
    return 0;
}

/* ACTIVATE or DEACTIVATE c on the flags of the loads, then of the force
 * elements (docs/interface.md §9.9): SFORCE and SPRINGDAMPER name a scalar
 * load, VFORCE, VTORQUE, GFORCE, BUSHING, BEAM and a linear FIELD a vector
 * one, and each of SFORCE, VFORCE, VTORQUE, GFORCE and FIELD the user force
 * elements of its kind (names_force), by id; 0, or -1 with the reason. */
static int switch_elements(const hx_command *c, const char *path, const hx_model *m,
                           unsigned char *off, hx_message *msg)
{
    const char *what = c->kind == HX_COMMAND_ACTIVATE ? "ACTIVATE" : "DEACTIVATE";
    int scalar;
    enum hx_load_builtin builtin;
    if (switched_element(c->element, &scalar, &builtin) != 0)
        return hx_fail(msg, "%s:%d: %s/%s: the harness switches SFORCE, VFORCE, VTORQUE,"
                       " GFORCE, SPRINGDAMPER, BUSHING, BEAM and FIELD, not other elements yet",
                       path, c->line, what, c->element);
    for (int i = 0; i < c->nids; ++i) {
        int found = 0;
        for (int k = 0; k < m->nloads; ++k)
            if (m->loads[k].id == c->ids[i] && m->loads[k].builtin == builtin &&
                (m->loads[k].kind != HX_LOAD_VECTOR) == scalar) {
                off[k] = c->kind == HX_COMMAND_DEACTIVATE;
                found = 1;
            }
        for (int k = 0; k < m->nforces; ++k)
            if (m->forces[k].id == c->ids[i] && names_force(&m->forces[k], c->element)) {
                off[m->nloads + k] = c->kind == HX_COMMAND_DEACTIVATE;
                found = 1;
            }
        if (!found)
            return hx_fail(msg, "%s:%d: %s/%s: the model has no %s/%d", path, c->line, what,
                           c->element, c->element, c->ids[i]);
    }
    return 0;
}

/* A segment of no length that is the static equilibrium at t alone, under the loads
 * switched off and the gravity so far (a SIMULATE/STATIC that no SIMULATE/DYNAMIC
 * follows before a switch or the end). */
static void equilibrium_alone(hx_command_schedule *out, double t, double rtol, double atol,
                              const unsigned char *off, size_t nflags, const double gravity[3],
                              const hx_variable_definitions *variables)
{
    unsigned char *flags = out->switched_off + (size_t)out->nsegments * nflags;
    memcpy(flags, off, nflags);
    double *g = out->gravity + 3 * (size_t)out->nsegments;
    memcpy(g, gravity, 3 * sizeof(double));
    out->segments[out->nsegments++] = (hx_segment){t, 0.0, rtol, atol, flags, g, 1, variables};
}

/* "file:line:column: VARIABLE/id: FUNCTION: what" from the engine's
 * "file:line:column: what" (why), as a dataset's messages name the element. */
static int fail_function(const char *path, int id, const char *why, hx_message *msg)
{
    const size_t n = strlen(path);
    const char *q = why;
    if (strncmp(why, path, n) == 0 && why[n] == ':') {
        q = why + n + 1;
        for (int field = 0; field < 2 && *q >= '0' && *q <= '9'; ++field) {
            while (*q >= '0' && *q <= '9')
                ++q;
            if (*q == ':')
                ++q;
        }
        if (*q == ' ')
            ++q;
    }
    return hx_fail(msg, "%.*sVARIABLE/%d: FUNCTION: %s", (int)(q - why), why, id, q);
}

/* VARIABLE/id, FUNCTION= (docs/interface.md §9.9): the text parsed where it
 * stands in the command file, linked against m, and a new set of definitions,
 * the one in force (current; NULL the model's) with it, ordered; that set in
 * *current. 0, or -1 with the reason. */
static int redefine(const hx_command *c, const char *path, const hx_model *m,
                    hx_command_schedule *out, const hx_variable_definitions **current,
                    hx_message *msg)
{
    const int id = c->ids[0];
    int k = 0;
    while (k < m->nvariables && m->variables[k].id != id)
        ++k;
    if (k == m->nvariables)
        return hx_fail(msg, "%s:%d: VARIABLE/%d: the model has no VARIABLE/%d given by a"
                       " FUNCTION (Reference_Variable %d)", path, c->line, id, id, id);
    if (m->variables[k].varsub)
        return hx_fail(msg, "%s:%d: VARIABLE/%d: its value is its VARSUB's (FUNCTION=USER, line"
                       " %d), which a command file does not redefine", path, c->line, id,
                       m->variables[k].line);
    hx_message why;
    const hx_expr_source where = {path, c->function_line, c->function_column};
    hx_expr_program *p = hx_expr_parse(c->function, strlen(c->function), &where, &why);
    if (p == NULL)
        return fail_function(path, id, why.text, msg);
    out->programs[out->nprograms++] = p; /* the schedule's from here */
    /* a state equation's input reads TIME and measures only (docs/interface.md §7.10) */
    const hx_expr_input *in = hx_expr_inputs(p);
    for (int a = 0; a < m->narrays; ++a)
        for (int i = 0; m->arrays[a].type == HX_ARRAY_U && i < m->arrays[a].count; ++i)
            for (int j = 0; m->arrays[a].variables[i] == k && j < hx_expr_input_count(p); ++j)
                if (in[j].kind != HX_EXPR_INPUT_TIME && in[j].kind != HX_EXPR_INPUT_MEASURE) {
                    char name[64];
                    return hx_fail(msg, "%s:%d:%d: VARIABLE/%d: FUNCTION: %s: an input of a"
                                   " state equation (the U array %d names it) reads TIME and"
                                   " measures only (docs/interface.md §7.10)", path, in[j].line,
                                   in[j].column, id, hx_expr_input_text(&in[j], name, sizeof name),
                                   m->arrays[a].id);
                }
    if (hx_expr_link(p, m, &why) != 0)
        return fail_function(path, id, why.text, msg);
    hx_variable_definitions *v = &out->variables[out->nvariables];
    if ((*current != NULL ? hx_variable_definitions_copy(v, *current, msg)
                          : hx_variable_definitions_of(v, m, msg)) != 0)
        return -1;
    out->nvariables++;
    if (hx_variable_definitions_redefine(v, m, k, p, path, c->line, &why) != 0)
        return hx_fail(msg, "%s:%d: VARIABLE/%d: %s", path, c->line, id, why.text);
    *current = v;
    return 0;
}

static int refuse(const char *path, const hx_command *c, hx_message *msg)
{
    return hx_fail(msg, "%s:%d: a command the run does not take", path, c->line);
}

/* The command line's --end cuts the schedule there (or draws its last
 * segment on to it); its --output-interval, --rtol and --atol replace every
 * segment's. */
static void apply(hx_command_schedule *s, const hx_command_overrides *over)
{
    if (over->t_end > 0.0) {
        int n = 0;
        double start = 0.0;
        while (n < s->nsegments && start < over->t_end)
            start = s->segments[n++].t_end;
        s->nsegments = n;
        hx_segment *last = &s->segments[n - 1];
        const double from = n > 1 ? s->segments[n - 2].t_end : 0.0;
        last->t_end = over->t_end;
        if (!(last->output_interval > 0.0)) /* a SIMULATE/STATIC last, drawn on */
            last->output_interval = (last->t_end - from) / 1000.0;
    }
    for (int k = 0; k < s->nsegments; ++k) {
        hx_segment *g = &s->segments[k];
        if (over->output_interval > 0.0)
            g->output_interval = over->output_interval;
        if (over->rtol > 0.0)
            g->rtol = over->rtol;
        if (over->atol > 0.0)
            g->atol = over->atol;
    }
    s->t_end = s->segments[s->nsegments - 1].t_end;
}

int hx_command_schedule_make(const hx_command_file *f, const char *path, const hx_model *m,
                             const char *model_path,
                             double rtol, double atol, const hx_command_overrides *over,
                             FILE *notes, hx_command_schedule *out, hx_message *msg)
{
    memset(out, 0, sizeof *out);
    check_names(f, path, model_path, notes);
    const size_t nflags = (size_t)m->nloads + (size_t)m->nforces; /* loads, then force elements */
    unsigned char *off = calloc(nflags + 1, 1); /* those switched off so far */
    if (off == NULL || (f->ncommands > 0 &&
                        ((out->segments = calloc((size_t)f->ncommands, sizeof(hx_segment))) == NULL ||
                         (out->switched_off = calloc((size_t)f->ncommands * nflags + 1, 1)) == NULL ||
                         (out->gravity = calloc(3 * (size_t)f->ncommands, sizeof(double))) ==
                             NULL ||
                         (out->variables = calloc((size_t)f->ncommands, sizeof *out->variables)) ==
                             NULL ||
                         (out->programs = calloc((size_t)f->ncommands, sizeof *out->programs)) ==
                             NULL))) {
        free(off);
        hx_command_schedule_free(out);
        return hx_fail(msg, "out of memory");
    }
    double t = 0.0, gravity[3]; /* the model's until an ACCGRAV changes it */
    memcpy(gravity, m->gravity, sizeof gravity);
    int noted = 0, statics = 0; /* statics: a SIMULATE/STATIC since the last segment */
    const hx_variable_definitions *variables = NULL; /* in force: NULL the model's own */
    for (int k = 0; k < f->ncommands; ++k) {
        const hx_command *c = &f->commands[k];
        if (c->kind == HX_COMMAND_STOP)
            break;
        if (c->kind == HX_COMMAND_INTEGRATOR) {
            if (c->error > 0.0)
                rtol = atol = c->error; /* Adams's ERROR: the local error, relative and absolute */
            if (notes != NULL && !noted && (c->integrator[0] != '\0' || c->settings[0] != '\0')) {
                fprintf(notes, "%s:%d: note: INTEGRATOR: %s%s%s read and of no effect (the"
                        " integrator is --integrator's; ERROR is the run's rtol and atol)\n",
                        path, c->line, c->integrator, c->integrator[0] != '\0' &&
                        c->settings[0] != '\0' ? ", " : "", c->settings);
                noted = 1;
            }
            continue;
        }
        if (statics && (c->kind == HX_COMMAND_ACTIVATE || c->kind == HX_COMMAND_DEACTIVATE ||
                        c->kind == HX_COMMAND_ACCGRAV || c->kind == HX_COMMAND_VARIABLE)) {
            /* the equilibrium is the one under the switches before this command */
            equilibrium_alone(out, t, rtol, atol, off, nflags, gravity, variables);
            statics = 0;
        }
        if (c->kind == HX_COMMAND_VARIABLE) {
            if (redefine(c, path, m, out, &variables, msg) != 0) {
                free(off);
                hx_command_schedule_free(out);
                return -1;
            }
            continue;
        }
        if (c->kind == HX_COMMAND_ACTIVATE || c->kind == HX_COMMAND_DEACTIVATE) {
            if (switch_elements(c, path, m, off, msg) != 0) {
                free(off);
                hx_command_schedule_free(out);
                return -1;
            }
            continue;
        }
        if (c->kind == HX_COMMAND_ACCGRAV) {
            /* the components given, for the segments after it (docs/interface.md §9.9) */
            for (int i = 0; i < 3; ++i)
                if (c->gravity_given[i])
                    gravity[i] = c->gravity[i];
            continue;
        }
        if (c->kind != HX_COMMAND_SIMULATE) {
            free(off);
            hx_command_schedule_free(out);
            return refuse(path, c, msg);
        }
        if (c->analysis == HX_ANALYSIS_STATIC) {
            statics = 1; /* the next segment starts with the equilibrium */
            continue;
        }
        const double end = c->duration ? t + c->end : c->end;
        if (!(end > t)) {
            free(off);
            hx_command_schedule_free(out);
            return hx_fail(msg, "%s:%d: SIMULATE/DYNAMIC: END=%g is not after the time the run"
                           " has reached, %g", path, c->line, end, t);
        }
        const double dt = c->steps > 0 ? (end - t) / c->steps : c->dtout;
        const double outputs = (end - t) / dt;
        if (notes != NULL && fabs(outputs - round(outputs)) > 1e-9 * outputs)
            fprintf(notes, "%s:%d: warning: SIMULATE/DYNAMIC: DTOUT=%g does not divide the"
                    " segment from %g to %g: its last output is before its end\n", path,
                    c->line, dt, t, end);
        unsigned char *flags = out->switched_off + (size_t)out->nsegments * nflags;
        memcpy(flags, off, nflags);
        double *g = out->gravity + 3 * (size_t)out->nsegments;
        memcpy(g, gravity, sizeof gravity);
        out->segments[out->nsegments++] =
            (hx_segment){end, dt, rtol, atol, flags, g, statics, variables};
        statics = 0;
        t = end;
    }
    if (statics) /* a SIMULATE/STATIC last: the equilibrium alone */
        equilibrium_alone(out, t, rtol, atol, off, nflags, gravity, variables);
    free(off);
    if (out->nsegments == 0) {
        hx_command_schedule_free(out);
        return hx_fail(msg, "%s: no SIMULATE command: nothing to run", path);
    }
    apply(out, over);
    return 0;
}

void hx_command_schedule_free(hx_command_schedule *s)
{
    free(s->segments);
    free(s->switched_off);
    free(s->gravity);
    for (int k = 0; k < s->nvariables; ++k)
        hx_variable_definitions_free(&s->variables[k]);
    free(s->variables);
    for (int k = 0; k < s->nprograms; ++k)
        hx_expr_free(s->programs[k]);
    free(s->programs);
    memset(s, 0, sizeof *s);
}
