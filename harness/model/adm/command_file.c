/*
 * The command file reader (command_file.h): the first two lines as names,
 * then statements in the dataset language (statement.c), each checked
 * against the command's keyword table (keywords.c) and kept in order.
 */
#include "model/adm/command_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "model/adm/keywords.h"
#include "model/adm/statement.h"

#define K(name, kind, lo, hi, req) {name, kind, lo, hi, req, 0, NULL, 0}
#define FLAG(name) K(name, HX_ADM_FLAG, 0, 0, 0)
#define REAL(name) K(name, HX_ADM_REAL, 1, 1, 0)
#define KEND {NULL, HX_ADM_FLAG, 0, 0, 0, 0, NULL, 0}

static const hx_adm_keyword simulate[] = {
    FLAG("DYNAMIC"), FLAG("STATIC"), FLAG("KINEMATIC"), FLAG("TRANSIENT"),
    FLAG("INITIAL_CONDITIONS"), REAL("END"), REAL("DURATION"), K("STEPS", HX_ADM_INT, 1, 1, 0),
    REAL("DTOUT"), KEND};

/* the elements Adams activates and deactivates */
#define ELEMENTS                                                                               \
    FLAG("BEAM"), FLAG("BUSHING"), FLAG("CONTACT"), FLAG("COUPLER"), FLAG("CVCV"), FLAG("DIFF"), \
        FLAG("FIELD"), FLAG("FRICTION"), FLAG("GCON"), FLAG("GFORCE"), FLAG("GSE"),              \
        FLAG("JOINT"), FLAG("JPRIM"), FLAG("LSE"), FLAG("MOTION"), FLAG("NFORCE"), FLAG("PTCV"), \
        FLAG("SENSOR"), FLAG("SFORCE"), FLAG("SPRINGDAMPER"), FLAG("TFSISO"), FLAG("VFORCE"),    \
        FLAG("VTORQUE")
static const hx_adm_keyword activate[] = {ELEMENTS, K("ID", HX_ADM_INT, 1, 100000, 0),
                                          K("RANGE", HX_ADM_INT, 2, 2, 0), KEND};
#define NELEMENTS 23

static const hx_adm_keyword variable[] = {K("FUNCTION", HX_ADM_EXPR, 1, 1, 1), KEND};

static const hx_adm_keyword accgrav[] = {REAL("IGRAV"), REAL("JGRAV"), REAL("KGRAV"), KEND};

static const hx_adm_keyword integrator[] = {
    FLAG("GSTIFF"), FLAG("WSTIFF"), FLAG("HHT"), FLAG("NEWMARK"), FLAG("HASTIFF"),
    FLAG("CONSTANT_BDF"), FLAG("RKF45"), FLAG("ABAM"), FLAG("I3"), FLAG("SI1"), FLAG("SI2"),
    REAL("ERROR"), REAL("HMAX"), REAL("HMIN"), REAL("HINIT"), K("KMAX", HX_ADM_INT, 1, 1, 0),
    K("MAXIT", HX_ADM_INT, 1, 1, 0), K("CORRECTOR", HX_ADM_WORD, 1, 1, 0), KEND};
#define NINTEGRATORS 11

static const hx_adm_keyword none[] = {KEND};

static const hx_adm_spec commands[] = {
    {"SIMULATE", HX_ADM_BUILD, HX_ADM_ID_NONE, simulate, NULL, NULL},
    {"ACTIVATE", HX_ADM_BUILD, HX_ADM_ID_NONE, activate, NULL, NULL},
    {"DEACTIVATE", HX_ADM_BUILD, HX_ADM_ID_NONE, activate, NULL, NULL},
    {"VARIABLE", HX_ADM_BUILD, HX_ADM_ID_REQUIRED, variable, NULL, NULL},
    {"ACCGRAV", HX_ADM_BUILD, HX_ADM_ID_NONE, accgrav, NULL, NULL},
    {"INTEGRATOR", HX_ADM_BUILD, HX_ADM_ID_NONE, integrator, NULL, NULL},
    {"STOP", HX_ADM_END, HX_ADM_ID_NONE, none, NULL, NULL},
};
static const int ncommands = (int)(sizeof commands / sizeof commands[0]);

static char *trimmed_copy(const char *p, size_t n)
{
    while (n > 0 && (*p == ' ' || *p == '\t'))
        ++p, --n;
    while (n > 0 && (p[n - 1] == ' ' || p[n - 1] == '\t' || p[n - 1] == '\r'))
        --n;
    char *s = malloc(n + 1);
    if (s != NULL) {
        memcpy(s, p, n);
        s[n] = '\0';
    }
    return s;
}

static hx_command *push(hx_command_file *f, int *capacity)
{
    if (f->ncommands == *capacity) {
        const int cap = *capacity ? 2 * *capacity : 8;
        hx_command *grown = realloc(f->commands, sizeof *grown * (size_t)cap);
        if (grown == NULL)
            return NULL;
        f->commands = grown;
        *capacity = cap;
    }
    hx_command *c = &f->commands[f->ncommands++];
    memset(c, 0, sizeof *c);
    return c;
}

/* The checked command into c; 0 or -1 with what in msg (no position). */
static int fill(const hx_adm_spec *spec, const hx_adm_value *v, const hx_adm_statement *st,
                hx_command *c, hx_message *msg)
{
    const char *name = spec->name;
    if (strcmp(name, "SIMULATE") == 0) {
        c->kind = HX_COMMAND_SIMULATE;
        if (v[2].present || v[3].present || v[4].present)
            return hx_fail(msg, "%s: the harness reads dynamic and static analyses only",
                           simulate[v[2].present ? 2 : v[3].present ? 3 : 4].name);
        if (v[0].present == v[1].present)
            return hx_fail(msg, "give DYNAMIC or STATIC");
        c->analysis = v[0].present ? HX_ANALYSIS_DYNAMIC : HX_ANALYSIS_STATIC;
        if (c->analysis == HX_ANALYSIS_STATIC) {
            for (int k = 5; k < 9; ++k)
                if (v[k].present)
                    return hx_fail(msg, "%s: a static analysis has no time", simulate[k].name);
            return 0;
        }
        if (v[5].present == v[6].present)
            return hx_fail(msg, "a dynamic analysis needs END or DURATION (one of them)");
        if (v[7].present == v[8].present)
            return hx_fail(msg, "a dynamic analysis needs STEPS or DTOUT (one of them)");
        c->duration = v[6].present;
        c->end = v[5].present ? v[5].numbers[0] : v[6].numbers[0];
        if (!(c->end > 0.0) && c->duration)
            return hx_fail(msg, "DURATION=%g must be positive", c->end);
        if (v[7].present && !(v[7].numbers[0] >= 1.0))
            return hx_fail(msg, "STEPS=%g must be at least 1", v[7].numbers[0]);
        if (v[8].present && !(v[8].numbers[0] > 0.0))
            return hx_fail(msg, "DTOUT=%g must be positive", v[8].numbers[0]);
        c->steps = v[7].present ? (int)v[7].numbers[0] : 0;
        c->dtout = v[8].present ? v[8].numbers[0] : 0.0;
        return 0;
    }
    if (strcmp(name, "ACTIVATE") == 0 || strcmp(name, "DEACTIVATE") == 0) {
        c->kind = name[0] == 'A' ? HX_COMMAND_ACTIVATE : HX_COMMAND_DEACTIVATE;
        int element = -1;
        for (int k = 0; k < NELEMENTS; ++k)
            if (v[k].present) {
                if (element >= 0)
                    return hx_fail(msg, "%s and %s: one kind of element a command",
                                   activate[element].name, activate[k].name);
                element = k;
            }
        if (element < 0)
            return hx_fail(msg, "names no element (%s/SFORCE, ID=3)", name);
        snprintf(c->element, sizeof c->element, "%s", activate[element].name);
        const hx_adm_value *id = &v[NELEMENTS], *range = &v[NELEMENTS + 1];
        if (id->present == range->present)
            return hx_fail(msg, "give ID=id[,id...] or RANGE=first,last (one of them)");
        long long n = id->present ? id->count : (long long)range->numbers[1] - range->numbers[0] + 1;
        if (range->present && !(range->numbers[0] >= 1.0 && n >= 1 && n <= 100000))
            return hx_fail(msg, "RANGE=%g,%g is not a range of ids", range->numbers[0],
                           range->numbers[1]);
        if ((c->ids = malloc(sizeof(int) * (size_t)n)) == NULL)
            return hx_fail(msg, "out of memory");
        c->nids = (int)n;
        for (int k = 0; k < c->nids; ++k) {
            c->ids[k] = id->present ? (int)id->numbers[k] : (int)range->numbers[0] + k;
            if (c->ids[k] < 1)
                return hx_fail(msg, "ID=%d is not an id", c->ids[k]);
        }
        return 0;
    }
    if (strcmp(name, "VARIABLE") == 0) {
        c->kind = HX_COMMAND_VARIABLE;
        snprintf(c->element, sizeof c->element, "VARIABLE");
        if ((c->ids = malloc(sizeof(int))) == NULL || (c->function = strdup(v[0].texts[0])) == NULL)
            return hx_fail(msg, "out of memory");
        c->ids[0] = st->id;
        c->nids = 1;
        c->function_line = v[0].value_lines[0];
        c->function_column = v[0].value_columns[0];
        return 0;
    }
    if (strcmp(name, "ACCGRAV") == 0) {
        c->kind = HX_COMMAND_ACCGRAV;
        for (int k = 0; k < 3; ++k)
            if ((c->gravity_given[k] = v[k].present))
                c->gravity[k] = v[k].numbers[0];
        return 0;
    }
    c->kind = HX_COMMAND_INTEGRATOR;
    for (int k = 0; k < NINTEGRATORS; ++k)
        if (v[k].present) {
            if (c->integrator[0] != '\0')
                return hx_fail(msg, "%s and %s: one integrator", c->integrator,
                               integrator[k].name);
            snprintf(c->integrator, sizeof c->integrator, "%s", integrator[k].name);
        }
    if (v[NINTEGRATORS].present) {
        c->error = v[NINTEGRATORS].numbers[0];
        if (!(c->error > 0.0))
            return hx_fail(msg, "ERROR=%g must be positive", c->error);
    }
    for (int k = NINTEGRATORS + 1; integrator[k].name != NULL; ++k)
        if (v[k].present) {
            const size_t n = strlen(c->settings);
            snprintf(c->settings + n, sizeof c->settings - n, "%s%s", n > 0 ? ", " : "",
                     integrator[k].name);
        }
    return 0;
}

static int read_commands(hx_command_file *f, hx_adm_source *src, hx_message *msg)
{
    hx_adm_statement st;
    memset(&st, 0, sizeof st);
    int capacity = 0, status = 0;
    for (;;) {
        const int got = hx_adm_statement_next(src, &st, msg);
        if (got <= 0) {
            status = got;
            break;
        }
        hx_message why;
        const hx_adm_spec *spec = hx_adm_find_spec(commands, ncommands, st.name.text, &why);
        if (spec == NULL) {
            status = hx_fail(msg, "%s:%d: %s: a command the harness does not read (it reads"
                             " SIMULATE, ACTIVATE, DEACTIVATE, VARIABLE, ACCGRAV, INTEGRATOR and"
                             " STOP)%s%s", src->path, st.line, st.name.text,
                             strstr(why.text, "ambiguous") ? ": " : "",
                             strstr(why.text, "ambiguous") ? why.text : "");
            break;
        }
        char label[48];
        snprintf(label, sizeof label, st.has_id ? "%s/%d" : "%s", spec->name, st.id);
        if (spec->id_form == HX_ADM_ID_REQUIRED && (!st.has_id || st.id <= 0)) {
            status = hx_fail(msg, "%s:%d: %s: needs a positive id (%s/id, ...)", src->path,
                             st.line, spec->name, spec->name);
            break;
        }
        if (spec->id_form == HX_ADM_ID_NONE && st.has_id) {
            status = hx_fail(msg, "%s:%d: %s: takes no id", src->path, st.line, label);
            break;
        }
        hx_adm_value *values = NULL;
        int line;
        if (hx_adm_check(spec, &st, &values, &line, &why) != 0) {
            status = hx_fail(msg, "%s:%d: %s: %s", src->path, line, label, why.text);
            hx_adm_values_free(spec, values);
            break;
        }
        hx_command *c = push(f, &capacity);
        if (c == NULL) {
            status = hx_fail(msg, "out of memory");
            hx_adm_values_free(spec, values);
            break;
        }
        c->line = st.line;
        if (spec->role == HX_ADM_END) {
            c->kind = HX_COMMAND_STOP;
            hx_adm_values_free(spec, values);
            break; /* what follows STOP is not read */
        }
        const int filled = fill(spec, values, &st, c, &why);
        hx_adm_values_free(spec, values);
        if (filled != 0) {
            status = hx_fail(msg, "%s:%d: %s: %s", src->path, st.line, label, why.text);
            break;
        }
    }
    hx_adm_statement_free(&st);
    return status;
}

hx_command_file *hx_command_file_parse(const char *text, size_t length, const char *name,
                                       hx_message *msg)
{
    hx_command_file *f = calloc(1, sizeof *f);
    if (f == NULL) {
        hx_fail(msg, "out of memory");
        return NULL;
    }
    hx_adm_source src;
    hx_adm_source_init(&src, name, text != NULL ? text : "", text != NULL ? length : 0);
    const char *p = "";
    size_t n = 0;
    int line = 1, status = 0;
    if (hx_adm_source_line(&src, &p, &n, &line) != 0 || (f->dataset = trimmed_copy(p, n)) == NULL ||
        f->dataset[0] == '\0')
        status = hx_fail(msg, "%s:1: the first line of a command file names the dataset to read",
                         name);
    if (status == 0) {
        if (hx_adm_source_line(&src, &p, &n, &line) != 0)
            p = "", n = 0;
        if ((f->output = trimmed_copy(p, n)) == NULL)
            status = hx_fail(msg, "out of memory");
    }
    if (status == 0)
        status = read_commands(f, &src, msg);
    if (status != 0) {
        hx_command_file_free(f);
        return NULL;
    }
    return f;
}

hx_command_file *hx_command_file_read(const char *path, hx_message *msg)
{
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        hx_fail(msg, "%s is a folder, not a command file", path);
        return NULL;
    }
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        hx_fail(msg, "%s: cannot open the command file: %s", path, strerror(errno));
        return NULL;
    }
    size_t capacity = 4096, n = 0;
    char *text = malloc(capacity);
    while (text != NULL) {
        n += fread(text + n, 1, capacity - n, file);
        if (n < capacity || ferror(file))
            break;
        char *grown = realloc(text, 2 * capacity);
        if (grown == NULL) {
            free(text);
            text = NULL;
        } else {
            text = grown;
            capacity *= 2;
        }
    }
    const int failed = text == NULL || ferror(file);
    fclose(file);
    if (failed) {
        free(text);
        hx_fail(msg, "%s: cannot read the command file", path);
        return NULL;
    }
    hx_command_file *f = hx_command_file_parse(text, n, path, msg);
    free(text);
    return f;
}

void hx_command_file_free(hx_command_file *f)
{
    if (f == NULL)
        return;
    for (int k = 0; k < f->ncommands; ++k) {
        free(f->commands[k].ids);
        free(f->commands[k].function);
    }
    free(f->commands);
    free(f->dataset);
    free(f->output);
    free(f);
}
