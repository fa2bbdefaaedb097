/*
 * Function expressions in the Adams/MotionSolve language (docs/interface.md
 * §8): the text parsed once into a compact, immutable program, its ids
 * resolved against a model, and the list of what it reads. The evaluator is
 * the layer above the frames (expr/evaluate.h).
 */
#ifndef HX_MODEL_EXPR_EXPR_H
#define HX_MODEL_EXPR_EXPR_H

#include <stddef.h>

#include "base/message.h"
#include "model/model.h"

typedef struct hx_expr_program hx_expr_program;

/* Where the text starts: the file it came from, its line and column (from
 * 1); the text's own newlines move the line on. */
typedef struct hx_expr_source {
    const char *file;
    int line, column;
} hx_expr_source;

/* What a program reads (docs/interface.md §8.6): TIME, a measure of markers,
 * a Reference_Variable's value, a Control_Diff's state or rate, a
 * component of a Reference_Array, a constraint element's force (JOINT,
 * JPRIM, MOTION, COUPLER, GCON), a
 * marker's acceleration (ACCX .. WDTM), a force element's force (SFORCE,
 * VFORCE, VTORQ, GFORCE, FIELD) or the net force at a marker (FX .. TM; these
 * in output expressions only, hx_expr_link_output). Each distinct one is
 * listed once. */
typedef enum hx_expr_input_kind {
    HX_EXPR_INPUT_TIME,
    HX_EXPR_INPUT_MEASURE,
    HX_EXPR_INPUT_VARVAL,
    HX_EXPR_INPUT_DIF,
    HX_EXPR_INPUT_DIF1,
    HX_EXPR_INPUT_ARYVAL,
    HX_EXPR_INPUT_REACTION,
    HX_EXPR_INPUT_ACCELERATION,
    HX_EXPR_INPUT_LOAD,
    HX_EXPR_INPUT_MARKER_FORCE
} hx_expr_input_kind;

typedef struct hx_expr_input {
    hx_expr_input_kind kind;
    int function;     /* its function (model/expr/functions.h: HX_FN_DX ...), -1 for TIME */
    int measure;      /* a measure: frames/measure_functions.h's hx_measure (ORIENT's
                       * HX_MEASURE_ORIENT + base/orientation_systems.h's code) */
    int ids[4];       /* as written, 0 for those left out: the markers of a measure; the
                       * element's id (and ARYVAL's component) of the others */
    int nids;         /* how many were written */
    /* after hx_expr_link: */
    int index[4];     /* a measure, an acceleration: the markers' indices (-1: the world's
                       * origin and axes; ORIENT's I and J first, its system and
                       * component in ids[0], ids[1]);
                       * VARVAL: the variable's index; DIF, DIF1: the Control_Diff's slot;
                       * ARYVAL: the array's index; REACTION: the element's index (a
                       * joint's in model order, primitives among them; a motion's in
                       * m->routines, a coupler's, a general constraint's), the I and J
                       * markers its jflag reads (J -1 for GCON) and rm's (-1: the
                       * world's axes); LOAD: the element's index, in
                       * model->loads (index[1] 0) or model->forces (index[1] 1),
                       * index[3] rm's; MARKER_FORCE: I's, J's (-1: left out or 0,
                       * every element acting at I) and K's (-1: the world's axes) */
    int variable;     /* the variable it reads (VARVAL, ARYVAL of a U array), else -1 */
    int loop;         /* an acceleration, a reaction or an SFORCE's force read within a
                       * right-hand side (hx_expr_link_loop): its slot among the model's
                       * algebraic loop inputs (model/loop_inputs.h), set once the model
                       * is read; else -1 */
    int line, column; /* its first place in the text */
} hx_expr_input;

/* A fault of an evaluation (or of folding a constant at parse time): what,
 * in which function, at which op's place. */
typedef enum hx_expr_fault_kind {
    HX_EXPR_FAULT_NONE,
    HX_EXPR_FAULT_DIVISION_BY_ZERO,
    HX_EXPR_FAULT_DOMAIN,          /* an argument outside the function's domain */
    HX_EXPR_FAULT_NOT_FINITE,      /* a result that is not finite (overflow) */
    HX_EXPR_FAULT_INPUT,           /* an input that is not finite, or not given */
    HX_EXPR_FAULT_PARTIAL,         /* a partial derivative that is not finite */
    HX_EXPR_FAULT_NOT_LINKED       /* evaluated before hx_expr_link, or with another model */
} hx_expr_fault_kind;

typedef struct hx_expr_fault {
    hx_expr_fault_kind kind;
    const char *function; /* the operator or function: "/", "LOG", "DM" */
    const char *what;     /* "division by zero", "its argument is negative" */
    double argument;      /* the value at fault, when has_argument */
    int has_argument;
    int line, column;     /* the op's place in the text */
    double time;          /* the evaluation's time */
} hx_expr_fault;

/* Parses text (length bytes; it need not end with a NUL) into a program.
 * Returns NULL with "file:line:column: what" in msg on an error: an unknown
 * function or name, a wrong argument count, unbalanced parentheses, a
 * missing operand, an empty expression, USER(...) (the readers' to handle),
 * an id that is not a whole number. */
hx_expr_program *hx_expr_parse(const char *text, size_t length, const hx_expr_source *where,
                               hx_message *msg);

/* Resolves the program's ids against model m (marker, variable, Control_Diff,
 * array, spline and curve ids to indices). Returns 0; -1 with
 * "file:line:column: what" naming the id that m does not define. The
 * program then evaluates with frames of m only. */
int hx_expr_link(hx_expr_program *p, const hx_model *m, hx_message *msg);
/* The same for an expression evaluated at output times only, after the
 * accelerations (a request's): it may read the joints' reactions (JOINT,
 * JPRIM), the markers' accelerations (ACCX .. WDTM), the force elements'
 * forces (SFORCE, VFORCE, ...) and the net forces at markers (FX .. TM),
 * which hx_expr_link refuses (a force or variable reading one would close an
 * algebraic loop, or depend on the order of evaluation). */
int hx_expr_link_output(hx_expr_program *p, const hx_model *m, hx_message *msg);
/* The same for a force's, a variable's or a Control_Diff's expression,
 * evaluated within a right-hand side: the accelerations, the constraint
 * elements' and force elements' forces and the forces at markers it reads
 * (all hx_expr_link_output takes) are the inputs of an algebraic loop the
 * dynamics solves (sim/dynamics/algebraic_loop.h), each given its slot by
 * hx_expr_set_loop once the model is read. */
int hx_expr_link_loop(hx_expr_program *p, const hx_model *m, hx_message *msg);
/* A force input standing alone (a user routine's c_sysfnc JOINT .. TM, as
 * host/loop_queries.h makes it: kind, function, ids set): its element's,
 * markers' and rm's indices, as hx_expr_link_loop links an expression's; 0,
 * or -1 with why ("no Constraint_Joint (JOINT) 9 in the model"). */
int hx_expr_link_force(hx_expr_input *in, const hx_model *m, char *why, size_t size);
/* Input k's slot among the model's loop inputs (model/loop_inputs.c). */
void hx_expr_set_loop(hx_expr_program *p, int k, int slot);

void hx_expr_free(hx_expr_program *p);

/* What it reads: hx_expr_input_count entries. */
int hx_expr_input_count(const hx_expr_program *p);
const hx_expr_input *hx_expr_inputs(const hx_expr_program *p);
/* "DM(20,10)", "TIME", "VARVAL(3)" */
const char *hx_expr_input_text(const hx_expr_input *in, char *text, size_t size);

/* 1 with *value when the whole program is one constant, else 0. */
int hx_expr_constant(const hx_expr_program *p, double *value);
/* The file the text came from, as hx_expr_parse was given it. */
const char *hx_expr_file(const hx_expr_program *p);
/* The count of ops (after folding) and the stack depth it needs. */
int hx_expr_op_count(const hx_expr_program *p);
int hx_expr_depth(const hx_expr_program *p);

/* "file:line:column: what at t = time" for a fault of an evaluation (the
 * function, what, and the value at fault when there is one) into msg;
 * returns -1. element, when not NULL, comes before what ("model.adm:12:34:
 * SFORCE/1: LOG: its argument is not above 0 (-2.5) at t = 0.25"). */
int hx_expr_fail(hx_message *msg, const hx_expr_program *p, const hx_expr_fault *f,
                 const char *element);

#endif
