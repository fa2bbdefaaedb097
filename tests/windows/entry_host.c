/*
 * entry_host LIBRARY UTILITY CASES FOLDER OUTPUT
 * entry_host --probe
 *
 * Evaluates every entry of a user-subroutine library on recorded inputs and
 * writes what it returned. One source, built for Linux (dlopen) and for
 * Windows (LoadLibrary), so that scripts/windows.sh can compare usrsub.dll
 * under Wine with libusrsub.so on inputs that differ in nothing
 * (docs/windows.md). UTILITY is the stand-in utility library (asutility.h),
 * loaded first: on Windows usrsub.dll's imports then bind to it, on Linux
 * its symbols are global before LIBRARY is loaded.
 *
 * CASES (tests/windows/model_cases.sh) holds the models' elements: "model",
 * "units 1 TIME LENGTH FORCE MASS" and "string ID TEXT" lines set what
 * c_gtunts and c_gtstrg answer; "coupler", "gfosub", "fiesub" and "yfosub"
 * lines are elements. The host runs in FOLDER, as a solver runs in the
 * model's folder, so that property files named relatively are found.
 *
 * Each element gets an id of its own (elements of different models share
 * ids), then every entry of its kind is called once in the dependency pass
 * (iflag 1, the utilities answering zeros) and at seven points: at rest; a
 * twist at rest (tilt zero: the library asks AZ); then five deformations of
 * growing size in directions drawn from a fixed sequence, with velocities,
 * states and times varied too, and dflag set at every other point.
 *
 * OUTPUT: one line per call, "CASE POINT ENTRY IFLAG DFLAG", the queries and
 * messages (asutility.h), "=", then every output value (%.17g). Exits 1 when
 * an entry is missing, is never called, or reports an error.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asutility.h"
#include "tokens.h"
#include "usrsub/solver_abi.h"

#ifdef _WIN32
#include <direct.h>
#define WIN32_LEAN_AND_MEAN
#include <windows.h>
#else
#include <dlfcn.h>
#include <unistd.h>
#endif

/* ---- the platform: the only difference between the two runs ---------------- */

typedef void (*any_fn)(void);

static void *open_library(const char *path, int global)
{
#ifdef _WIN32
    (void)global; /* imports bind by DLL name to the module already loaded */
    return (void *)LoadLibraryA(path);
#else
    return dlopen(path, RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL));
#endif
}

static any_fn symbol(void *library, const char *name)
{
#ifdef _WIN32
    return (any_fn)GetProcAddress((HMODULE)library, name);
#else
    any_fn fn;
    void *address = dlsym(library, name);
    memcpy(&fn, &address, sizeof fn);
    return fn;
#endif
}

static int change_folder(const char *folder)
{
#ifdef _WIN32
    return _chdir(folder);
#else
    return chdir(folder);
#endif
}

/* ---- the entries ------------------------------------------------------------ */

enum kind { COUPLER, GFOSUB_KIND, FIESUB_KIND, YFOSUB_KIND, STATE_PARTIAL };

typedef struct entry {
    const char *name, *alias;
    enum kind kind;
    any_fn fn;
    long calls;
} entry;

static entry entries[] = {
    {"COUSUB", "cousub_", COUPLER, NULL, 0},
    {"COUXX", "couxx_", COUPLER, NULL, 0},
    {"COUXX2", "couxx2_", COUPLER, NULL, 0},
    {"GFOSUB", "gfosub_", GFOSUB_KIND, NULL, 0},
    {"ABM_BUSHING", "abm_bushing_", GFOSUB_KIND, NULL, 0},
    {"MOUNT_LIMITS", "mount_limits_", GFOSUB_KIND, NULL, 0},
    {"FLEX_JOINT", "flex_joint_", GFOSUB_KIND, NULL, 0},
    {"FIESUB", "fiesub_", FIESUB_KIND, NULL, 0},
    {"ABM_BUSHING_FIELD", "abm_bushing_field_", FIESUB_KIND, NULL, 0},
    {"MOUNT_LIMITS_FIELD", "mount_limits_field_", FIESUB_KIND, NULL, 0},
    {"FLEX_JOINT_FIELD", "flex_joint_field_", FIESUB_KIND, NULL, 0},
    {"YFOSUB", "yfosub_", YFOSUB_KIND, NULL, 0},
    {"YFOXX", "yfoxx_", STATE_PARTIAL, NULL, 0},
    {"YFOXU", "yfoxu_", STATE_PARTIAL, NULL, 0},
    {"YFOYX", "yfoyx_", STATE_PARTIAL, NULL, 0},
    {"YFOYU", "yfoyu_", STATE_PARTIAL, NULL, 0},
};
enum { ENTRY_COUNT = sizeof entries / sizeof entries[0] };

static entry *entry_named(const char *name, enum kind kind)
{
    for (int k = 0; k < ENTRY_COUNT; ++k)
        if (strcmp(entries[k].name, name) == 0 && entries[k].kind == kind)
            return &entries[k];
    return NULL;
}

/* ---- recorded inputs ---------------------------------------------------------- */

enum { POINT_COUNT = 7, MAX_PAR = 512, MAX_STATES = 32, INPUTS = 12 };
static const double growth[POINT_COUNT] = {0.0, 0.0, 0.05, 0.3, 1.0, 2.5, 6.0};

/* A fixed sequence (splitmix64), the same bits on every platform. */
static uint64_t sequence;
static double draw(void) /* in [-1, 1) */
{
    uint64_t z = (sequence += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-52 - 1.0;
}

typedef struct point {
    int index; /* -1: the dependency pass */
    double time;
    int iflag, dflag;
    asutility_motion motion;
    double disp[6], velo[6]; /* FIESUB's: DX DY DZ AX AY AZ, VX .. WZ */
    double joints[3];        /* a coupler's joint displacements */
    double states[MAX_STATES];
} point;

/* Point k of case c: sizes in the models' units (mm, rad, s). */
static void make_point(int c, int k, point *p)
{
    memset(p, 0, sizeof *p);
    p->index = k;
    if (k < 0) {
        p->iflag = 1;
        p->motion.dependency_pass = 1;
        return;
    }
    sequence = (uint64_t)c * 1000003u + (uint64_t)k;
    const double s = growth[k];
    p->time = 0.1 * k + 0.001 * c;
    p->dflag = k % 2;
    double *d = p->motion.disp, *v = p->motion.vel;
    if (k == 1) { /* a twist about z at rest: PSI + PHI, tilt zero */
        d[3] = 0.3 * draw();
        d[5] = 0.2 * draw();
    } else if (k > 1) {
        for (int i = 0; i < 3; ++i)
            d[i] = 2.0 * s * draw();
        d[3] = 3.14159 * draw();
        d[4] = 0.05 * s * fabs(draw());
        d[5] = -d[3] + 0.05 * s * draw();
    }
    for (int i = 0; i < 3; ++i) {
        v[i] = 20.0 * s * draw();
        v[3 + i] = 0.5 * s * draw();
    }
    p->motion.az = d[3] + d[5];
    for (int i = 0; i < 3; ++i) {
        p->disp[i] = d[i];
        p->disp[3 + i] = (k == 1 && i == 2) ? p->motion.az : 0.05 * s * draw();
    }
    memcpy(p->velo, v, sizeof p->velo);
    for (int i = 0; i < 3; ++i)
        p->joints[i] = (k == 1 ? 0.01 : s) * draw();
    for (int i = 0; i < MAX_STATES; ++i)
        p->states[i] = 0.1 * s * draw();
}

/* ---- calls ---------------------------------------------------------------------- */

typedef struct run {
    FILE *out;
    asutility_set_motion_fn *set_motion;
    asutility_take_log_fn *take_log;
    long calls, values;
} run;

static void write_call(run *r, int c, const point *p, entry *e, const double *values, int n)
{
    fprintf(r->out, "%d %d %s %d %d ", c, p->index, e->name, p->iflag, p->dflag);
    for (const char *log = r->take_log(); *log != '\0'; ++log)
        fputc(*log == '\n' ? ' ' : *log, r->out);
    fputc('=', r->out);
    for (int k = 0; k < n; ++k)
        fprintf(r->out, " %.17g", values[k]);
    fputc('\n', r->out);
    e->calls++;
    r->calls++;
    r->values += n;
}

/* Outputs start as a value no entry returns, so that one left unwritten shows. */
static void poison(double *v, int n)
{
    for (int k = 0; k < n; ++k)
        v[k] = -7.25e77;
}

static void call_coupler(run *r, int c, const point *p, int id, double *par, int npar, int ndisp)
{
    double out[9];
    static const char *const names[3] = {"COUSUB", "COUXX", "COUXX2"};
    const int sizes[3] = {1, ndisp, ndisp * ndisp};
    for (int k = 0; k < 3; ++k) {
        entry *e = entry_named(names[k], COUPLER);
        double time = p->time, disp[3];
        int iflag = p->iflag;
        memcpy(disp, p->joints, sizeof disp);
        poison(out, 9);
        ((usrsub_coupler_fn *)e->fn)(&id, &time, par, &npar, disp, &ndisp, &iflag, out);
        write_call(r, c, p, e, out, sizes[k]);
    }
}

static void call_gfosub(run *r, int c, const point *p, entry *e, int id, double *par, int npar)
{
    double time = p->time, result[6];
    int dflag = p->dflag, iflag = p->iflag;
    poison(result, 6);
    ((usrsub_gfosub_fn *)e->fn)(&id, &time, par, &npar, &dflag, &iflag, result);
    write_call(r, c, p, e, result, 6);
}

static void call_fiesub(run *r, int c, const point *p, entry *e, int id, double *par, int npar)
{
    double time = p->time, disp[6], velo[6], out[6 + 36 + 36];
    int dflag = p->dflag, iflag = p->iflag;
    memcpy(disp, p->disp, sizeof disp);
    memcpy(velo, p->velo, sizeof velo);
    poison(out, 78);
    ((usrsub_fiesub_fn *)e->fn)(&id, &time, par, &npar, disp, velo, &dflag, &iflag, out,
                                out + 6, out + 42);
    write_call(r, c, p, e, out, 78);
}

static void call_state(run *r, int c, const point *p, int id, double *par, int npar, int nstate)
{
    double time = p->time, states[MAX_STATES], input[INPUTS];
    double out[(MAX_STATES + 6) * (MAX_STATES + INPUTS)];
    int dflag = p->dflag, iflag = p->iflag, ninput = INPUTS, noutpt = 6;
    memcpy(states, p->states, sizeof states);
    memcpy(input, p->disp, sizeof p->disp);
    memcpy(input + 6, p->velo, sizeof p->velo);
    entry *e = entry_named("YFOSUB", YFOSUB_KIND);
    poison(out, nstate + 6);
    ((usrsub_yfosub_fn *)e->fn)(&id, &time, par, &npar, &dflag, &iflag, &nstate, states,
                                &ninput, input, &noutpt, out, out + nstate);
    write_call(r, c, p, e, out, nstate + 6);
    static const char *const partials[4] = {"YFOXX", "YFOXU", "YFOYX", "YFOYU"};
    const int sizes[4] = {nstate * nstate, nstate * INPUTS, 6 * nstate, 6 * INPUTS};
    for (int k = 0; k < 4; ++k) {
        e = entry_named(partials[k], STATE_PARTIAL);
        poison(out, sizes[k]);
        ((usrsub_state_partial_fn *)e->fn)(&id, &time, par, &npar, &iflag, &nstate, states,
                                           &ninput, input, &noutpt, out);
        write_call(r, c, p, e, out, sizes[k]);
    }
}

/* ---- the cases file ------------------------------------------------------------------ */


/* Up to max numbers from *s; -1 when a token is no number. */
static int read_numbers(char **s, double *v, int max, int *n)
{
    const char *t;
    for (*n = 0; *n < max && (t = token(s)) != NULL; ++*n) {
        char *end;
        v[*n] = strtod(t, &end);
        if (end == t || *end != '\0')
            return -1;
    }
    return 0;
}

/* "NPAR PAR..." */
static int read_list(char **s, double *par, int *npar)
{
    const char *t = token(s);
    const int count = t != NULL ? atoi(t) : -1;
    if (count < 0 || count > MAX_PAR || read_numbers(s, par, count, npar) != 0)
        return -1;
    return *npar == count && token(s) == NULL ? 0 : -1;
}

static int fail(const char *what, const char *detail)
{
    fprintf(stderr, "entry_host: %s%s%s\n", what, detail != NULL ? ": " : "", detail != NULL ? detail : "");
    return 1;
}

static int evaluate(run *r, FILE *cases, asutility_set_model_fn *set_model, int *elements)
{
    static char line[1 << 16];
    static asutility_model model;
    static double par[MAX_PAR];
    int c = 0;
    while (fgets(line, sizeof line, cases) != NULL) {
        line[strcspn(line, "\r\n")] = '\0';
        char *s = line;
        const char *what = token(&s);
        if (what == NULL || what[0] == '#')
            continue;
        if (strcmp(what, "model") == 0) {
            memset(&model, 0, sizeof model);
            set_model(&model);
            continue;
        }
        if (strcmp(what, "units") == 0) {
            double units[5];
            int n;
            if (read_numbers(&s, units, 5, &n) != 0 || n != 5)
                return fail("malformed units", NULL);
            model.units_exist = (int)units[0];
            memcpy(model.scales, units + 1, sizeof model.scales);
            set_model(&model);
            continue;
        }
        if (strcmp(what, "string") == 0) {
            const char *id = token(&s);
            if (id == NULL || model.nstrings == ASUTILITY_STRINGS)
                return fail("malformed string, or too many in a model", NULL);
            model.string_ids[model.nstrings] = atoi(id);
            snprintf(model.strings[model.nstrings], ASUTILITY_STRING_MAX, "%s", s);
            model.nstrings++;
            set_model(&model);
            continue;
        }
        const int id = ++c; /* one id per element, across models */
        entry *e = NULL;
        int size = 0, npar;
        if (strcmp(what, "coupler") == 0 || strcmp(what, "yfosub") == 0) {
            const char *t = token(&s);
            size = t != NULL ? atoi(t) : -1;
        } else if (strcmp(what, "gfosub") == 0 || strcmp(what, "fiesub") == 0) {
            const char *name = token(&s);
            e = entry_named(name != NULL ? name : "", what[0] == 'g' ? GFOSUB_KIND : FIESUB_KIND);
            if (e == NULL)
                return fail("no such entry", name);
        } else
            return fail("unknown line", what);
        if (read_list(&s, par, &npar) != 0 || (what[0] == 'c' && (size < 2 || size > 3)) ||
            (what[0] == 'y' && (size < 0 || size > MAX_STATES)))
            return fail("malformed element", what);
        for (int k = -1; k < POINT_COUNT; ++k) {
            point p;
            make_point(c, k, &p);
            r->set_motion(&p.motion);
            switch (what[0]) {
            case 'c': call_coupler(r, c, &p, id, par, npar, size); break;
            case 'g': call_gfosub(r, c, &p, e, id, par, npar); break;
            case 'f': call_fiesub(r, c, &p, e, id, par, npar); break;
            default: call_state(r, c, &p, id, par, npar, size); break;
            }
        }
    }
    *elements = c;
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 2 && strcmp(argv[1], "--probe") == 0) {
        puts("entry_host runs");
        return 0;
    }
    if (argc != 6) {
        fputs("usage: entry_host LIBRARY UTILITY CASES FOLDER OUTPUT\n", stderr);
        return 2;
    }
    void *utility = open_library(argv[2], 1);
    if (utility == NULL)
        return fail("cannot load the utility library", argv[2]);
    asutility_set_model_fn *set_model = (asutility_set_model_fn *)symbol(utility, "asutility_set_model");
    asutility_errors_fn *errors = (asutility_errors_fn *)symbol(utility, "asutility_errors");
    run r = {NULL, (asutility_set_motion_fn *)symbol(utility, "asutility_set_motion"),
             (asutility_take_log_fn *)symbol(utility, "asutility_take_log"), 0, 0};
    if (set_model == NULL || errors == NULL || r.set_motion == NULL || r.take_log == NULL)
        return fail("the utility library lacks its asutility_ functions", argv[2]);
    void *library = open_library(argv[1], 0);
    if (library == NULL)
        return fail("cannot load the library", argv[1]);
    int failures = 0;
    for (int k = 0; k < ENTRY_COUNT; ++k) {
        entries[k].fn = symbol(library, entries[k].name);
        if (entries[k].fn == NULL || symbol(library, entries[k].alias) != entries[k].fn) {
            failures += fail("an entry is missing, or its two names are two functions", entries[k].name);
            entries[k].fn = NULL;
        }
    }
    FILE *cases = fopen(argv[3], "r");
    if (cases == NULL)
        return fail("cannot read", argv[3]);
    r.out = fopen(argv[5], "wb"); /* "\n" on Windows too */
    if (r.out == NULL)
        return fail("cannot write", argv[5]);
    if (failures > 0)
        return 1;
    if (change_folder(argv[4]) != 0)
        return fail("cannot change to", argv[4]);
    int elements = 0;
    if (evaluate(&r, cases, set_model, &elements) != 0)
        return 1;
    fclose(cases);
    if (fclose(r.out) != 0)
        return fail("cannot write", argv[5]);
    for (int k = 0; k < ENTRY_COUNT; ++k)
        if (entries[k].calls == 0)
            failures += fail("no element calls", entries[k].name);
    if (errors() > 0)
        failures += fail("the library reported errors (above)", NULL);
    printf("entry_host: %d elements, each in the dependency pass and at %d points: %ld calls of"
           " %d entries, %ld values\n", elements, POINT_COUNT, r.calls, ENTRY_COUNT, r.values);
    return failures > 0;
}
