/*
 * What a run makes of a command file (docs/interface.md §9.9): its
 * SIMULATE/DYNAMIC commands as segments one after the other (END absolute,
 * DURATION after the time reached; STEPS or DTOUT their output times), its
 * INTEGRATOR's ERROR as the tolerances of the segments after it, and the
 * command line's --end, --output-interval, --rtol and --atol over the file's;
 * ACTIVATE and DEACTIVATE of the force elements (SFORCE, VFORCE, VTORQUE,
 * GFORCE, SPRINGDAMPER, BUSHING, BEAM, FIELD: the loads by expressions or
 * built in, and those calling user routines) and ACCGRAV's gravity, for the
 * segments after them;
 * SIMULATE/STATIC as the next segment's start from the static equilibrium
 * (or a segment of no length, the equilibrium alone, when a switch or the
 * end comes first); VARIABLE/id, FUNCTION= as the variables' definitions of
 * the segments after it (parsed, linked against the model and ordered here,
 * before the run). What the run cannot do yet (switching other elements) is
 * refused by name and file:line.
 */
#ifndef HX_SIM_SIMULATION_COMMAND_SCHEDULE_H
#define HX_SIM_SIMULATION_COMMAND_SCHEDULE_H

#include <stdio.h>

#include "base/message.h"
#include "model/adm/command_file.h"
#include "model/model.h"
#include "model/variable_definitions.h"
#include "sim/simulation/simulation.h"

/* The command line's values, each 0 when not given (the file's then). */
typedef struct hx_command_overrides {
    double t_end, output_interval, rtol, atol;
} hx_command_overrides;

typedef struct hx_command_schedule {
    hx_segment *segments;
    int nsegments;
    double t_end; /* the last segment's end */
    unsigned char *switched_off; /* the segments' flags, nloads + nforces a segment */
    double *gravity;          /* the segments' gravity, 3 a segment (ACCGRAV) */
    hx_variable_definitions *variables; /* one set a VARIABLE command: the definitions
                                         * in force after it (segments point here) */
    int nvariables;
    hx_expr_program **programs; /* the VARIABLE commands' programs, linked */
    int nprograms;
} hx_command_schedule;

/* The schedule of command file f (read from path) for model m, read from
 * model_path; rtol and atol the tolerances before any INTEGRATOR. Notes and
 * warnings (the first line naming another dataset, INTEGRATOR's settings
 * without effect, a DTOUT that does not divide its segment) go to notes
 * (may be NULL). 0, or -1 with "path:line: COMMAND: why" in msg. */
int hx_command_schedule_make(const hx_command_file *f, const char *path, const hx_model *m,
                             const char *model_path,
                             double rtol, double atol, const hx_command_overrides *over,
                             FILE *notes, hx_command_schedule *out, hx_message *msg);
void hx_command_schedule_free(hx_command_schedule *s);

#endif
