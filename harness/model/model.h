/*
 * The harness's model: the subset of a MotionSolve XML model it supports
 * (docs/interface.md §7). Immutable once read: what changes
 * during a run lives in a state (frames/frames.h). Indices below are positions
 * in the model's arrays; ids are the XML ids.
 */
#ifndef HX_MODEL_MODEL_H
#define HX_MODEL_MODEL_H

#include <stddef.h>
#include <stdio.h>

#include "base/message.h"
#include "model/units.h"
#include "usrsub/solver_abi.h"

/* A function expression parsed and linked (model/expr/expr.h). */
typedef struct hx_expr_program hx_expr_program;

typedef struct hx_user_call {
    char *dll_name;     /* usrsub_dll_name; NULL when absent or "NULL" */
    char *fnc_name;     /* usrsub_fnc_name; NULL for the default name */
    char *der1_name;    /* couplers: usrsub_der1_name (default COUXX) */
    char *der2_name;    /* couplers: usrsub_der2_name (default COUXX2); state equations:
                         * usrsub_der1..4_name (defaults YFOXX, YFOXU, YFOYX, YFOYU) */
    char *der3_name;
    char *der4_name;
    double *par;        /* the numbers of usrsub_param_string's USER(...) */
    int npar;
} hx_user_call;

typedef struct hx_marker {
    int id;
    int body;            /* index of the body it belongs to */
    double pos0[3];      /* world position at t = 0 */
    double R0[9];        /* world orientation at t = 0 (columns: the marker's axes) */
    double r_local[3];   /* position in the body's frame */
    double R_local[9];   /* orientation in the body's frame */
    int local_axes;      /* R_local is the identity: the marker turns with the body's axes */
    int at_body_origin;  /* r_local is zero */
    int tracked;         /* an element, load or joint of the model names it: states keep
                          * its world frame (frames/frames.h) */
    int line;
} hx_marker;

typedef struct hx_body {
    int id;
    int is_ground;
    double mass;
    double inertia[9];   /* about the centre of mass, body axes (a tensor: products of
                          * inertia enter with a minus sign, docs/interface.md §7) */
    int cg_marker;       /* index; the body frame is this marker's frame */
    double p0[3], R0[9]; /* world pose of the body frame at t = 0 */
    double v0[3], w0[3]; /* initial velocity of the cm and angular velocity, world */
    int joint;           /* index of its reduced joint to ground, or -1 (free body) */
    int line;
} hx_body;

enum hx_joint_type {
    HX_JOINT_REVOLUTE, HX_JOINT_TRANSLATIONAL, HX_JOINT_FIXED, HX_JOINT_CYLINDRICAL,
    HX_JOINT_SPHERICAL, HX_JOINT_UNIVERSAL, HX_JOINT_HOOKE, HX_JOINT_PLANAR,
    HX_JOINT_CONVEL, HX_JOINT_RACKPIN, HX_JOINT_SCREW,
    /* the joint primitives (Constraint_Jprim, docs/interface.md §7.14): from here on */
    HX_JOINT_ATPOINT, HX_JOINT_INLINE, HX_JOINT_INPLANE, HX_JOINT_ORIENTATION,
    HX_JOINT_PARALLEL_AXES, HX_JOINT_PERPENDICULAR
};

typedef struct hx_joint {
    int id;
    enum hx_joint_type type;
    int i_marker, j_marker; /* indices; either may be on ground, not both */
    int reduced;            /* a revolute or translational joint, J on ground, that is its I
                             * body's only joint: the body moves in the joint's coordinate
                             * (body.joint); otherwise the joint's equations constrain free
                             * bodies (docs/architecture.md, the layout of y) */
    double pitch_diameter;  /* RACKPIN: the pinion's pitch diameter (> 0) */
    double pitch;           /* SCREW: the travel per turn (not 0; < 0 a left-hand thread) */
    int line;
} hx_joint;

typedef struct hx_coupler {
    int id;
    int njoints;
    int joint[3];             /* indices */
    char freedom[3];          /* each joint's coordinate: 'R' its rotation, 'T' its
                               * translation (docs/interface.md §2) */
    double coefficients[3];   /* built-in form */
    int is_user;              /* 1: user subroutine form */
    hx_user_call user;
    int line;
} hx_coupler;

enum hx_force_interface { HX_FORCE_GFOSUB, HX_FORCE_FIESUB };
/* What a user force element's routine returns: a Force_Vector_TwoBody's by
 * its type, ForceAndTorque (GFOSUB: six values), ForceOnly (VFOSUB: the
 * force) or TorqueOnly (VTOSUB: the torque); a Force_Scalar_TwoBody's by its
 * type (SFOSUB: one value), a force along the line from J to I or a torque
 * about J's z axis. */
enum hx_user_output {
    HX_OUTPUT_FORCE_AND_TORQUE, HX_OUTPUT_FORCE, HX_OUTPUT_TORQUE,
    HX_OUTPUT_SCALAR_FORCE, HX_OUTPUT_SCALAR_TORQUE
};

/* How many values the routine of a force element returns: 6, 3, 3, 1 or 1. */
int hx_force_routine_values(enum hx_user_output part);

typedef struct hx_force {
    int id;
    enum hx_force_interface interface; /* Force_Vector_TwoBody or Force_Field */
    enum hx_user_output part;          /* what its routine returns */
    int one_body;            /* a Force_Vector_OneBody: J is the ground's origin marker, which
                              * takes the reaction (docs/interface.md §7) */
    int i_marker, j_marker;  /* indices; for GFOSUB j is the floating J marker */
    int ref_marker;          /* index of the frame of the results, -1: world */
    hx_user_call user;
    int line;
} hx_force;

/* The marker whose axes a force element's outputs are in: the reference
 * marker of a routine that asks the host for the state (-1: the world's, as
 * for a Force_Scalar_TwoBody), J of a Force_Field (docs/interface.md §3.1). */
int hx_force_output_axes(const hx_force *f);

enum hx_load_kind {
    HX_LOAD_VECTOR,        /* Force_Vector_OneBody, or Force_Vector_TwoBody by expressions:
                            * force/torque at a marker */
    HX_LOAD_SCALAR_TORQUE, /* Force_Scalar_TwoBody TORQUE: about J's z axis */
    HX_LOAD_SCALAR_FORCE   /* Force_Scalar_TwoBody FORCE: along the line I-J */
};

/* What a load stands for: itself, or a built-in element made of it
 * (model/builtin_forces.h), named and read by the force functions as that. */
enum hx_load_builtin {
    HX_LOAD_AS_WRITTEN,   /* a Force_Vector_* or Force_Scalar_TwoBody */
    HX_LOAD_SPRINGDAMPER, /* a Force_SpringDamper: a scalar load */
    HX_LOAD_BUSHING,      /* a Force_Bushing: a vector load, j_marker its J marker */
    HX_LOAD_BEAM,         /* a Force_Beam: a vector load, j_marker its J marker */
    HX_LOAD_FIELD         /* a linear Force_Field: a vector load, j_marker its J marker */
};

typedef struct hx_load {
    int id;
    enum hx_load_kind kind;
    enum hx_load_builtin builtin;
    double turn_stiffness; /* a ROTATIONAL Force_SpringDamper's stiffness, its angle's full
                            * turns counted (sim/dynamics/joint_turns.h); 0 otherwise */
    int i_marker, j_marker, ref_marker; /* indices, -1 when not used; a vector load's j_marker
                                         * (Force_Vector_TwoBody) takes the reaction */
    /* the expressions (docs/interface.md §8), linked against the model; NULL: a
     * component left out, 0 */
    hx_expr_program *force[3], *torque[3]; /* vector loads, in ref_marker axes */
    hx_expr_program *value;                /* scalar loads */
    int action_only;
    int line;
} hx_load;

/* A Reference_Variable: one measure the harness answers itself, or a number,
 * or any function expression (docs/interface.md §7.10, §8). */
typedef struct hx_variable {
    int id;
    char function[3];   /* "DX" .. "WZ" or "DM"; "" for a number */
    int marker_ids[4];  /* as written; the ones left out are 0 (the world) */
    int nmarkers;
    double sign;        /* -1 for a leading minus */
    double number;      /* the value of a plain number */
    hx_expr_program *program; /* an expression beyond one measure, linked; NULL: the above */
    int varsub;         /* type USERSUB: its VARSUB computes the value (routines[routine]) */
    int routine;
    int line;
} hx_variable;

typedef enum hx_array_type { HX_ARRAY_X, HX_ARRAY_U, HX_ARRAY_Y, HX_ARRAY_IC } hx_array_type;

/* A Reference_Array: the numbers of an IC array, the variables of a U array. */
typedef struct hx_array {
    int id;
    hx_array_type type;
    int count;          /* num_element */
    double *numbers;    /* IC: count values */
    int *variable_ids;  /* U: count Reference_Variable ids, as written */
    int *variables;     /* U: their indices */
    int line;
} hx_array;

/* A Force_StateEqn of type USERSUB: a force between two markers with
 * internal states (docs/interface.md §5, §7.10). */
typedef struct hx_stateeqn {
    int id;
    int i_marker, j_marker; /* indices; J is the floating J marker */
    int ref_marker;          /* index of the frame of the outputs */
    int nstate;              /* num_state */
    int ninput;              /* the U array's length (0 without one) */
    int *inputs;             /* ninput variable indices, in the U array's order */
    double *initial;         /* nstate initial states (zeros without an IC array) */
    int x_array, u_array, ic_array; /* indices in arrays[], -1 when none */
    int static_hold;         /* is_static_hold: read, no effect (the harness runs dynamics) */
    hx_user_call user;
    int line;
} hx_stateeqn;

/* A user routine that is not a force (docs/interface.md §7.12): a
 * Post_Request's REQSUB (eight values written with the results), a USERSUB
 * Reference_Variable's VARSUB (one value), a USERSUB Control_Diff's DIFSUB
 * (the rate of one state integrated with the bodies') and a USERSUB
 * Motion_Joint's MOTSUB (a joint's coordinate, rate or acceleration as a
 * function of time). */
enum hx_routine_kind { HX_ROUTINE_REQUEST, HX_ROUTINE_VARIABLE, HX_ROUTINE_DIFF, HX_ROUTINE_MOTION };
#define HX_ROUTINE_KINDS 4

typedef struct hx_routine {
    int id;
    enum hx_routine_kind kind;
    int slot;            /* its place among the model's routines of its kind */
    hx_user_call user;
    /* Control_Diff: ic and ic_dot (its state and rate at t = 0);
     * Motion_Joint: ic_disp and ic_vel */
    double ic[2];
    int ic_given[2];     /* Motion_Joint: whether ic_disp, ic_vel were written (else the
                          * joint's coordinate and rate as the model places it);
                          * Control_Diff: [1] whether ic_dot was */
    int implicit;        /* Control_Diff is_implicit: by expression, expr is a residual
                          * F(DIF1, ...) = 0 the dynamics solves for the rate
                          * (docs/interface.md §7.10); a DIFSUB's is refused by run */
    int static_hold;     /* Control_Diff is_static_hold (read, no effect) */
    int joint_id;        /* Motion_Joint: the joint it drives, as written */
    int joint;           /* its index */
    char val_type;       /* Motion_Joint: 'D', 'V' or 'A': what MOTSUB's value is */
    char motion_type;    /* Motion_Joint: 'R', 'T', or 0 when not written */
    /* Control_Diff type EXPRESSION (docs/interface.md §7.10): its rate, linked; a
     * Motion_Joint type EXPRESSION (§7.12): its value, a function of TIME alone; NULL:
     * a user routine's (DIFSUB, MOTSUB, ...), which has no other field below */
    hx_expr_program *program;
    int reads_variables; /* its program reads VARVAL or ARYVAL of a U array */
    int line;
} hx_routine;

typedef struct hx_string {
    int id;
    char *text;
} hx_string;

/* A Reference_Spline (docs/interface.md §7.11): nz curves y(x) over the same
 * nx x values, at z[0] < z[1] < ...; a curve is nz = 1 at z = 0. Each
 * curve's knot slopes are kept for both methods the host answers. */
typedef struct hx_spline {
    int id;
    int nx, nz;
    double *x;              /* nx, strictly increasing */
    double *z;              /* nz */
    double *y;              /* nz * nx: the curve at z[j] is y + j * nx */
    double *akima_slope;    /* nz * nx: Akima's knot slopes (c_akispl) */
    double *cubic_slope;    /* nz * nx: the natural cubic spline's (c_cubspl) */
    int linear_extrapolate; /* linear_extrap: straight beyond the x values */
    int line;
} hx_spline;

/* A curve (docs/interface.md §8.4): a B-spline of `order` over control
 * points, a three-dimensional curve of the parameter alpha in [-1, 1], as
 * Adams' CURVE statement defines one; CURVE(alpha, iord, comp, id) evaluates
 * it. Filled by no reader yet (model/curve.h checks one and fits one to
 * points on it). */
typedef struct hx_curve {
    int id;
    int order;      /* 2 to 8; 4, the cubic, is the statement's default */
    int closed;     /* the last point repeats the first and the curve closes smoothly */
    int npoints;    /* control points */
    double *points; /* 3 npoints: x y z of each control point */
    int line;
} hx_curve;
/* A controls plant's inputs or outputs (an Adams dataset's PINPUT or
 * POUTPUT, docs/interface.md §9): the VARIABLE ids, in order. */
typedef struct hx_plant_port {
    int id;
    int nvariables;
    int *variable_ids;
    int line;
} hx_plant_port;

/* A request the harness answers itself (docs/interface.md §7.13): eight
 * values at each output time, the CSV's requestID.1 .. requestID.8 in
 * Adams' order. DISPLACEMENT, VELOCITY and ACCELERATION of marker I relative to J in RM's
 * axes (-1: the ground's origin, the world's axes), FORCE at I from the
 * elements between I and J (J -1: the action-only forces at I), or eight
 * expressions (F1..F8, expr1..expr8; NULL: 0). A REQSUB request is a routine. */
enum hx_request_kind {
    HX_REQUEST_DISPLACEMENT, HX_REQUEST_VELOCITY, HX_REQUEST_EXPRESSIONS, HX_REQUEST_ACCELERATION,
    HX_REQUEST_FORCE
};

typedef struct hx_request {
    int id;
    enum hx_request_kind kind;
    int marker_ids[3];   /* I, J, RM as written (0: the world) */
    int markers[3];      /* their indices, -1: the world */
    struct hx_expr_program *f[8]; /* F1 .. F8, linked against the model; NULL: 0 */
    char label[32];      /* in messages: "REQUEST/5", "Post_Request 5" */
    int adams;           /* its components are named F1.. (else expr1..) */
    int line;
} hx_request;

/* An expression a dataset gives (FUNCTION=, FX=, ...) that the harness does
 * not evaluate yet, kept as written for the expression engine: the
 * statement, its id, the keyword, the text and where it begins. */
typedef struct hx_model_expression {
    char statement[16];
    int id;
    char keyword[16];
    char *text;
    int line, column;
} hx_model_expression;

/* A general constraint (Constraint_General, an Adams GCON; docs/interface.md
 * §7.16): an expression of the markers' displacements and rotations and of
 * time that the motion holds at zero, one row of the constraint system. */
typedef struct hx_gcon {
    int id;
    int i_marker_id;          /* the marker its reaction would be read at; 0: none */
    int i_marker;             /* its index, or -1 */
    hx_expr_program *program; /* linked; its inputs checked (gcon_elements.c) */
    int line;
} hx_gcon;

typedef struct hx_model {
    char *path;
    char *dir;               /* folder of the model file */
    int has_units;
    double unit_scales[HX_UNIT_COUNT];
    double gravity[3];
    hx_body *bodies;
    int nbodies;
    int ground;              /* index of the ground body */
    hx_marker *markers;
    int nmarkers;
    hx_joint *joints;
    int njoints;
    hx_coupler *couplers;
    int ncouplers;
    hx_gcon *gcons;          /* the general constraints, in the order read */
    int ngcons;
    hx_force *forces;
    int nforces;
    hx_load *loads;
    int nloads;
    hx_string *strings;
    int nstrings;
    hx_variable *variables;
    int nvariables;
    int *variable_order;     /* the variables' indices, each after those it reads (VARVAL) */
    int *varsub_read_start;  /* per variable, nvariables + 1: where in varsub_reads the
                              * variables its VARSUB declared it reads (c_sysfnc VARVAL)
                              * begin; NULL until the dependency passes (host/variable_reads.h) */
    int *varsub_reads;
    int variables_read;      /* a load's expression reads a variable, a Force_StateEqn's U
                              * array names a VARSUB one, or a routine reads one by c_sysfnc
                              * VARVAL (host/variable_reads.h): the dynamics computes their
                              * values at each evaluation (frames.h) */
    struct hx_loop_input *loop_inputs; /* the algebraic loop's inputs (model/loop_inputs.h):
                              * each distinct acceleration, reaction or SFORCE force a
                              * force, variable or Control_Diff rate reads */
    int nloop_inputs;        /* 0: no loop, and a right-hand side does no work for one */
    struct hx_expr_input *output_queries; /* the distinct accelerations and forces REQSUBs
                              * ask (c_sysfnc ACCZ, JOINT, ...), linked: answered at the
                              * output times alone, no loop's inputs (model/loop_inputs.h) */
    int noutput_queries;
    hx_array *arrays;
    int narrays;
    hx_stateeqn *stateeqns;
    int nstateeqns;
    hx_routine *routines;    /* in the order read */
    int nroutines;
    int *diff_order;         /* the explicit Control_Diffs by expression (routine indices), each after
                              * those whose rate (DIF1) it reads; computed after the DIFSUBs */
    int ndiff_programs;
    int nroutines_of[HX_ROUTINE_KINDS];
    int nwarnings;
    /* elements that act on the dynamics but that the harness does not model:
     * check can verify the user elements, run and bench refuse */
    int nunsimulated;
    char unsimulated[256];   /* the first of them, "Motion_Joint 5 (line 40)" */
    int *marker_slots;       /* open-addressing index from marker id */
    int marker_slot_count;
    hx_spline *splines;
    int nsplines;
    hx_curve *curves;
    int ncurves;
    /* read from an Adams dataset only (docs/interface.md §9) */
    double suggested_error;  /* its INTEGRATOR's ERROR, the tolerance it suggests; 0: none */
    hx_plant_port *pinputs, *poutputs;
    int npinputs, npoutputs;
    hx_model_expression *expressions; /* those of its unsimulated elements */
    int nexpressions;
    hx_request *requests;    /* DISPLACEMENT, VELOCITY and expression requests, in the order read */
    int nrequests;
} hx_model;

/* Reads a model, MotionSolve XML or an Adams dataset, chosen by the text
 * (model_read.c); warnings go to `warnings` (may be NULL). Returns NULL with
 * "file:line: what" in msg on an error. */
hx_model *hx_model_read(const char *path, FILE *warnings, hx_message *msg);
/* The same from text in memory; name stands for the file in messages, and the
 * model's folder is that of name. */
hx_model *hx_model_parse(const char *text, size_t length, const char *name, FILE *warnings,
                         hx_message *msg);
void hx_model_free(hx_model *m);

/* Index of the marker with this id, or -1. */
int hx_model_marker(const hx_model *m, int id);
int hx_model_body(const hx_model *m, int id);
/* Index of the Constraint_Joint with this id (not a primitive), or -1; of the
 * Constraint_Jprim with this id, or -1 (their ids are apart, as Adams' JOINT
 * and JPRIM are). */
int hx_model_joint(const hx_model *m, int id);
int hx_model_primitive(const hx_model *m, int id);
/* A joint type's MotionSolve name ("REVOLUTE", ..., "INLINE", ...), and the
 * type of a name (any case; -1 when none: docs/interface.md §7.14); whether a
 * type is a primitive (Constraint_Jprim), and the element's name. */
const char *hx_joint_type_name(enum hx_joint_type type);
int hx_joint_type_from_name(const char *name);
int hx_joint_type_is_primitive(enum hx_joint_type type);
const char *hx_joint_element_name(enum hx_joint_type type);
const char *hx_model_string(const hx_model *m, int id);
/* Index of the force element written ID, vector:ID or field:ID (the prefix
 * needed when a Force_Vector_TwoBody and a Force_Field share ID); -1 and msg
 * when there is none or two. */
int hx_model_find_force(const hx_model *m, const char *text, int *index, hx_message *msg);
int hx_model_variable(const hx_model *m, int id);
int hx_model_array(const hx_model *m, int id);
/* Index of the Force_StateEqn written ID or stateeqn:ID; -1 and msg when
 * there is none. */
int hx_model_find_stateeqn(const hx_model *m, const char *text, int *index, hx_message *msg);
/* Index of the routine of a kind with this id, or -1. */
int hx_model_routine(const hx_model *m, enum hx_routine_kind kind, int id);
/* "Post_Request", "Reference_Variable", "Control_Diff", "Motion_Joint". */
const char *hx_routine_element_name(enum hx_routine_kind kind);
/* "Force_Vector_TwoBody", "Force_Vector_OneBody", "Force_Scalar_TwoBody" or "Force_Field". */
const char *hx_force_element_name(const hx_force *f);
/* "Force_Vector_OneBody", "Force_Vector_TwoBody" (by expressions) or "Force_Scalar_TwoBody";
 * j_marker must be resolved. */
const char *hx_load_element_name(const hx_load *l);
/* Index of the Reference_Spline with this id, or -1. */
int hx_model_spline(const hx_model *m, int id);
/* Index of the curve with this id, or -1. */
int hx_model_curve(const hx_model *m, int id);

#endif
