/*
 * An Adams command file (.acf, docs/interface.md §9.9): its first two lines
 * (the dataset to read and the name of the outputs), then the commands of a
 * run in order, each with its line: SIMULATE/DYNAMIC (END, STEPS or DTOUT),
 * SIMULATE/STATIC, ACTIVATE and DEACTIVATE of elements, VARIABLE/id and
 * ACCGRAV redefined for the run, INTEGRATOR (its name and ERROR), STOP. Any
 * other command is refused by name and line. Read here; what a run makes of
 * them is the run driver's.
 */
#ifndef HX_MODEL_ADM_COMMAND_FILE_H
#define HX_MODEL_ADM_COMMAND_FILE_H

#include <stddef.h>

#include "base/message.h"

typedef enum hx_command_kind {
    HX_COMMAND_SIMULATE,
    HX_COMMAND_ACTIVATE,
    HX_COMMAND_DEACTIVATE,
    HX_COMMAND_VARIABLE,   /* VARIABLE/id, FUNCTION=...: redefined for the rest of the run */
    HX_COMMAND_ACCGRAV,
    HX_COMMAND_INTEGRATOR,
    HX_COMMAND_STOP
} hx_command_kind;

typedef enum hx_analysis { HX_ANALYSIS_DYNAMIC, HX_ANALYSIS_STATIC } hx_analysis;

typedef struct hx_command {
    hx_command_kind kind;
    int line;
    /* SIMULATE: the analysis, its end time (END=, or DURATION= after the time
     * reached: duration set), and its output steps (STEPS=) or step (DTOUT=);
     * 0 when not given */
    hx_analysis analysis;
    double end, dtout;
    int duration, steps;
    /* ACTIVATE, DEACTIVATE: the statement (SFORCE, ...) and its ids (RANGE=a,b
     * gives a .. b); VARIABLE: its id */
    char element[24];
    int *ids;
    int nids;
    /* VARIABLE: the expression as written and where it begins */
    char *function;
    int function_line, function_column;
    /* ACCGRAV: the components given (given[k]) */
    double gravity[3];
    int gravity_given[3];
    /* INTEGRATOR: its name ("" when not given), ERROR (0 when not given) and
     * the names of its other settings given ("HMAX, KMAX"; "" when none) */
    char integrator[16];
    double error;
    char settings[64];
} hx_command;

typedef struct hx_command_file {
    char *dataset;   /* the first line: the dataset to read, as written */
    char *output;    /* the second line: the name of the run's outputs ("" when blank) */
    hx_command *commands;
    int ncommands;
} hx_command_file;

/* Reads the command file at path; NULL with "file:line: what" in msg. */
hx_command_file *hx_command_file_read(const char *path, hx_message *msg);
/* The same from text in memory; name stands for the file in messages. */
hx_command_file *hx_command_file_parse(const char *text, size_t length, const char *name,
                                       hx_message *msg);
void hx_command_file_free(hx_command_file *f);

#endif
