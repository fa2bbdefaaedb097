/*
 * The harness's equations of motion, as one right-hand side for the
 * integrators, kept as MuJoCo keeps its model and data apart:
 *   - hx_dynamics, the dynamics' model: what hx_dynamics_init sets up from the
 *     session (the layout of y, each body's degrees of freedom, the elements'
 *     bindings) and nothing changes after;
 *   - hx_dynamics_data, what an evaluation computes, grouped by the stage that
 *     computes it. Whoever evaluates owns a data: the run one, the Jacobian
 *     its own (sim/jacobian/), each tool its own; nothing is shared between
 *     them and no evaluation reads what an earlier one left.
 * One evaluation runs the stages in order, each given what it reads:
 *   kinematics   the bodies' and markers' frames at (t, y)      bodies.c
 *   variables    the Reference_Variable values, when a load reads one
 *                                                    host/variable_values.c
 *   forces       gravity and loads, the user force elements, the
 *                Force_StateEqn elements (their state rates too)  loads.c,
 *                                                    element_forces.c, stateeqns.c
 *   accelerations  the bodies' Newton-Euler accelerations        bodies.c
 *   constraints  the joints' and couplers' multipliers           constraints.c
 *   routines     Control_Diff rates, driven joints                routines.c
 * In a model with an algebraic loop (forces, variables or Control_Diff
 * rates that read accelerations, reactions or SFORCE forces) the stages
 * from the variables to the constraints run until the values they read
 * are those they give (algebraic_loop.c); in any other model once.
 *
 * Bodies are free (position, unit quaternion, velocity, body-axis angular
 * velocity) or hinged/slid to ground by their only joint (the joint coordinate
 * AZ(I,J) or DZ(I,J,J), unwrapped, and its rate). Every other joint and the
 * couplers are rows of one constraint system with a Lagrange multiplier each,
 * with projection onto the constraints after a step (constraints.h); the
 * couplers' rotations between moving bodies are unwrapped against the angles
 * a data holds, which a run moves at its accepted steps (joint_turns.h).
 *
 * State layout y: [positions (nq) | velocities (nu) | the Force_StateEqn
 * elements' states (nstates, element by element in the model's order) | the
 * Control_Diff states (ndiffs, routines.h) | an acceleration motion's displacement
 * and velocity between bodies (2 a motion, routines.h) | work done by the loads and the
 * time-dependent constraints (the motions, the general constraints of TIME) | work
 * done by the force elements, Force_StateEqn ones included]. Units follow the
 * model; mass * acceleration = ucf * force, as in a solver with an
 * inconsistent unit set (mm, kg, s, N has ucf = 1000).
 */
#ifndef HX_SIM_DYNAMICS_DYNAMICS_H
#define HX_SIM_DYNAMICS_DYNAMICS_H

#include "frames/frames.h"
#include "session/session.h"

typedef enum hx_dof_kind { HX_DOF_GROUND, HX_DOF_FREE, HX_DOF_REVOLUTE, HX_DOF_SLIDER } hx_dof_kind;

typedef struct hx_body_dof {
    hx_dof_kind kind;
    int q, u;                   /* offsets of the body's positions and velocities */
    double axis[3], origin[3];  /* joint axis (J marker z, world) and a point on it */
    double coord0;              /* joint coordinate at t = 0 */
    double mass;                /* m, or the moment of inertia about the joint axis */
    double inertia[9], inertia_inv[9]; /* free bodies: about the cm, body axes */
} hx_body_dof;

/* One row of the constraint system G (constraints.c): the blocks of
 * velocities it touches, in ascending u, and where each block's values sit
 * among the row's values (hx_dynamics.row_values: 12, or 36 when a coupler
 * spans joints between bodies: up to 6 bodies). */
#define HX_CONSTRAINT_ROW_BLOCKS 6
typedef struct hx_constraint_row {
    int nblocks;
    int body[HX_CONSTRAINT_ROW_BLOCKS], u[HX_CONSTRAINT_ROW_BLOCKS];
    int width[HX_CONSTRAINT_ROW_BLOCKS], slot[HX_CONSTRAINT_ROW_BLOCKS];
    double scale; /* phi's size for the projection's tolerance: 1, or the model's length */
} hx_constraint_row;

/* Puts a row's blocks in ascending u (the order G's consumers read them in). */
void hx_constraint_row_sort(hx_constraint_row *r);

/* The dynamics' model: set up once, read only afterwards. */
typedef struct hx_dynamics {
    hx_session *s;
    const hx_model *m;
    double ucf;                   /* acceleration = ucf * force / mass */
    hx_body_dof *dof;             /* per body */
    int nq, nu, n;                /* positions, velocities, the whole of y */
    int stateeqn_offset, nstates; /* y offset and count of the Force_StateEqn states */
    int diff_offset, ndiffs;      /* y offset and count of the Control_Diff states */
    int motion_state_offset, nmotion_states; /* y offset and count of the acceleration
                                   * motions' states between bodies (routines.h) */
    int diffs_read_variables;     /* a Control_Diff's expression reads a variable */
    int nimplicit, *implicit;     /* the implicit Control_Diffs by expression (routine
                                   * indices), solved together (implicit_diffs.h) */
    int *implicit_of_slot;        /* per Control_Diff slot: its place in implicit[], or -1 */
    size_t implicit_work;         /* doubles of a data's implicit_work */
    int load_work, element_work;  /* y indices of the work done by loads and the drives
                                   * (motions, GCONs of TIME), and by elements */
    hx_binding **coupler_binding; /* per coupler; NULL for the built-in form */
    int nrows;                    /* constraint rows: the couplers', the joints', then the
                                   * motions' on joints between bodies, the general
                                   * constraints' */
    int motion_first, nmotions;   /* the motions' rows: from motion_first, one a motion */
    int *motion_routine;          /* per motion row: its Motion_Joint routine (model.h) */
    int *motion_state;            /* per motion row: the y index of an acceleration motion's
                                   * displacement state (its velocity state the next), or -1 */
    int gcon_first;               /* the general constraints' rows: from gcon_first, one a
                                   * Constraint_General (expression_rows.h) */
    int row_values;               /* values a row of G keeps (hx_constraint_row) */
    unsigned char *coupler_general; /* per coupler: 1 when a joint of it is not reduced */
    int nturns;                   /* the rotations couplers take between two moving bodies
                                   * (joint_turns.h): */
    int *turn_joint, *turn_coupler; /* per such rotation: its joint, the first coupler on it */
    hx_constraint_row *rows;
    int nactive, *active;         /* the rows the solves take, ascending (all of them but
                                   * the redundant rows found at set-up, at the assembled
                                   * configuration: redundancy.h) */
    int nremoved, *removed;       /* the redundant rows, ascending */
    int nremoved_placed, *removed_placed; /* the redundant rows at the model's placed
                                   * configuration, before the set-up's assembly */
    double *assembled_q;          /* nq: the positions the set-up's assembly reached when
                                   * it changed the redundant rows (the run's projection
                                   * starts there), or NULL */
    int *envelope_first;          /* per active row: the first active row it shares a body
                                   * with (G M^-1 G^T's envelope), or NULL: solved dense */
    size_t *envelope_start;       /* per active row: its place in the envelope's values */
    int *joint_row;               /* per joint: its first row, or -1 (a reduced joint) */
    int *u_body;                  /* per velocity: its body */
    hx_binding **force_binding;   /* per force element */
    hx_binding **routine_binding; /* per routine of the model (model.h) */
    int *driver;                  /* per body: the Motion_Joint routine driving it, or -1 */
    unsigned char *world_aligned; /* per force element: its output axes are the world's for
                                   * good (on ground, unturned) */
    struct hx_stateeqns *stateeqns; /* the Force_StateEqn elements (stateeqns.h) */
    unsigned char *load_off;      /* per load: switched off (a command file's DEACTIVATE,
                                   * docs/interface.md §9.9): it puts nothing on the bodies
                                   * nor in the Jacobian. With force_off and gravity what a
                                   * run changes, only between its segments, when nothing
                                   * evaluates */
    unsigned char *force_off;     /* per force element: the same for the user force
                                   * elements (their routines not called) */
    double *gravity;              /* 3: the gravity the loads and the energy use, the model's
                                   * or a command file's ACCGRAV (§9.9), changed like
                                   * load_off, between segments only */
} hx_dynamics;

/* What the evaluations ask beyond the right-hand side. */
enum {
    HX_EVALUATE_PARTIALS = 1 /* Force_Field elements called with dflag set, their dfddis and
                              * dfdvel kept (a solver asks for partials so) */
};

/* What an evaluation computes, by stage; allocated for one dynamics. */
typedef struct hx_dynamics_data {
    /* kinematics: the frames at the evaluation's (t, y) */
    hx_frames frames;
    /* forces */
    double *force, *torque;       /* per body, world, the torque about its cm */
    double *element_outputs;      /* 6 per force element, in its output axes */
    double *element_load;         /* 6 per force element: F, T on I, world axes */
    double *element_partials;     /* 72 per Force_Field: dfddis, then dfdvel; written only by
                                   * an evaluation asked for HX_EVALUATE_PARTIALS */
    double *stateeqn_outputs;     /* 6 per Force_StateEqn, in its reference marker's axes */
    /* accelerations */
    double *free_accelerations;   /* nu: the bodies' udot before the couplers act */
    /* constraints */
    double *lambda;               /* per constraint row (the couplers' first) */
    double *gcon_twist;           /* per general constraint and block of its row, six: phi's
                                   * derivative in that body's motion (its origin's shift,
                                   * its turn about it; world), the last row evaluated with G
                                   * (expression_rows.h): lambda times it is the force it
                                   * puts on that body */
    double *turn, *turn_rate;     /* per joint, then per load (a ROTATIONAL Force_SpringDamper's
                                   * AZ(I,J)): the angle its rotation is unwrapped against
                                   * and its rate there (joint_turns.h): the model's
                                   * placement, and in a run the last accepted step's */
    double turn_time;             /* the time of those */
    /* the stages' scratch */
    double *constraint_work;      /* G and M^-1 G^T (12 a row), G M^-1 G^T, vectors */
    double *stateeqn_work;        /* one Force_StateEqn's inputs and its call's copies */
    double *loop_work;            /* the algebraic loop's Newton iterates, its matrix and the
                                   * outputs it reads back (algebraic_loop.h); one double
                                   * in a model without a loop */
    hx_frames moved;              /* frames with bodies placed elsewhere (element_at.h) */
    double *implicit_start;       /* per implicit Control_Diff: where Newton starts, the rate
                                   * of the last accepted step (implicit_diffs.h) */
    double *implicit_work;        /* Newton's iterate, residuals, step and matrix */
    /* the first failure (failure.h) */
    int failed;
    char message[1024];
    /* the largest constraint residuals projections have left (constraints.h) */
    double max_phi, max_phidot;
} hx_dynamics_data;

/* Refuses models with elements the harness does not model (model.h). On
 * failure it has freed what it took (d is zeroed: hx_dynamics_free may still
 * be called on it, and does nothing). */
int hx_dynamics_init(hx_dynamics *d, hx_session *s, hx_message *msg);
void hx_dynamics_free(hx_dynamics *d);

/* The same for a data of d. */
int hx_dynamics_data_init(hx_dynamics_data *dd, const hx_dynamics *d, hx_message *msg);
void hx_dynamics_data_free(hx_dynamics_data *dd);

/* Sets d's load_off and force_off from flags (a command file's segment's: a
 * flag per load, then per force element; NULL: every one on). Between
 * evaluations only. */
void hx_dynamics_switch(const hx_dynamics *d, const unsigned char *flags);

/* The model's initial state as given (not projected); 0, or -1 (dd->message). */
int hx_dynamics_model_state(const hx_dynamics *d, hx_dynamics_data *dd, double *y);
/* Initial state from the model, projected onto the couplers; 0, or -1
 * (dd->message). */
int hx_dynamics_initial_state(const hx_dynamics *d, hx_dynamics_data *dd, double *y);
/* The same on a data of its own, for callers that need the state alone; 0,
 * or -1 with msg. */
int hx_dynamics_initial_y(const hx_dynamics *d, double *y, hx_message *msg);

/* ydot = f(t, y), the stages' results in dd; `ask`: HX_EVALUATE_* flags.
 * Returns 0, or -1 (dd->message) when an element stopped the run or returned
 * a non-finite value, or the constraints are singular. */
int hx_dynamics_evaluate(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                         double *ydot, unsigned ask);
/* The stages from the variables to the constraints at dd's kinematics
 * (hx_dynamics_kinematics at (t, y)): ydot's velocities' and states' rates,
 * not the routines'; once, with the algebraic loop's inputs as dd's frames
 * hold them. 0, or -1 (dd->message). */
int hx_dynamics_stages(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                       double *ydot, unsigned ask);

/* The right-hand side alone: hx_dynamics_evaluate asking nothing more. */
int hx_dynamics_rhs(const hx_dynamics *d, hx_dynamics_data *dd, double t, const double *y,
                    double *ydot);

/* The kinematics stage: the bodies' frames, then the markers', at (t, y). */
void hx_dynamics_kinematics(const hx_dynamics *d, hx_dynamics_data *dd, double t,
                            const double *y);

#endif
