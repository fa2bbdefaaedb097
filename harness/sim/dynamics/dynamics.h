/*
 * The harness's equations of motion, as one right-hand side for the
 * integrators. The dynamics owns its state (frames/frames.h): each evaluation
 * fills the bodies' frames from y, runs the kinematics stage, and calls the
 * elements with that state bound.
 *
 * Bodies are free (position, unit quaternion, velocity, body-axis angular
 * velocity) or hinged/slid to ground by one joint (the joint coordinate
 * AZ(I,J) or DZ(I,J,J), unwrapped, and its rate) (bodies.c). Forces: gravity
 * and loads (loads.c), the user force elements (element_forces.c) and the
 * Force_StateEqn elements, whose internal states are integrated with the
 * bodies' (stateeqns.c). Couplers relate joint coordinates through one
 * Lagrange multiplier each, with projection onto the constraints after a
 * step (constraints.c).
 *
 * State layout y: [positions (nq) | velocities (nu) | the Force_StateEqn
 * elements' states (nstates, element by element in the model's order) | the
 * Control_Diff states (ndiffs, routines.h) | work done by the loads | work
 * done by the force elements, Force_StateEqn ones included]. A Motion_Joint
 * drives its joint's coordinate (routines.h). Units follow the model; mass *
 * acceleration = ucf * force, as in a solver with an inconsistent unit set
 * (mm, kg, s, N has ucf = 1000).
 */
#ifndef HX_SIM_DYNAMICS_H
#define HX_SIM_DYNAMICS_H

#include "host/session.h"
#include "frames/frames.h"

typedef enum hx_dof_kind { HX_DOF_GROUND, HX_DOF_FREE, HX_DOF_REVOLUTE, HX_DOF_SLIDER } hx_dof_kind;

typedef struct hx_body_dof {
    hx_dof_kind kind;
    int q, u;                   /* offsets of the body's positions and velocities */
    double axis[3], origin[3];  /* joint axis (J marker z, world) and a point on it */
    double coord0;              /* joint coordinate at t = 0 */
    double mass;                /* m, or the moment of inertia about the joint axis */
    double inertia[9], inertia_inv[9]; /* free bodies: about the cm, body axes */
} hx_body_dof;

typedef struct hx_dynamics {
    hx_session *s;
    const hx_model *m;
    hx_frames frames;           /* the frames of the last evaluation */
    hx_frames probe;             /* scratch state for elements at prescribed deformations */
    double ucf;                 /* acceleration = ucf * force / mass */
    hx_body_dof *dof;
    int nq, nu, n;
    int states, nstates;        /* y offset and count of the Force_StateEqn elements' states */
    int diffs, ndiffs;          /* y offset and count of the Control_Diff states (routines.h) */
    hx_binding **routine_binding; /* per routine of the model (model.h) */
    int *driver;                /* per body: the Motion_Joint routine driving it, or -1 */
    int load_work, element_work; /* y indices of the work done by loads and by force elements */
    struct hx_stateeqns *stateeqns; /* the Force_StateEqn elements (stateeqns.h) */
    hx_binding **coupler_binding; /* per coupler; NULL for the built-in form */
    hx_binding **force_binding;   /* per force element */
    double *lambda;             /* multipliers of the last evaluation */
    double *element_load;       /* 6 per force element: F, T on I, world axes */
    unsigned char *world_aligned; /* per force element: its result axes are the world's
                                   * for good (on ground, unturned) */
    double *force, *torque;     /* per body, world, torque about the cm */
    double *scratch;
    /* What the last evaluation found, for the Newton matrix (sim/newton/),
     * which takes them instead of calling the elements again: */
    double *element_outputs;    /* 6 per force element, in its own result axes */
    double *element_partials;   /* 72 per FIESUB element: dfddis, then dfdvel */
    int field_partials;         /* 1: FIESUB is called with dflag set, as a solver
                                 * asks for partials (the Newton matrix wants them) */
    double *free_accelerations; /* nu: the bodies' udot before the couplers act */
    double *evaluated_y;        /* the y of that evaluation */
    double evaluated_t;
    int evaluated;              /* 1: d->frames and the above belong to (evaluated_t,
                                 * evaluated_y); any other setting of d->frames clears it */
    int failed;
    char message[1024];
    double max_phi, max_phidot; /* largest constraint residuals after projections */
} hx_dynamics;

/* Refuses models with elements the harness does not model (model.h). On
 * failure it has freed what it took (d is zeroed: hx_dynamics_free may still
 * be called on it, and does nothing). */
int hx_dynamics_init(hx_dynamics *d, hx_session *s, hx_message *msg);
void hx_dynamics_free(hx_dynamics *d);

/* Initial state from the model, projected onto the couplers. */
int hx_dynamics_initial_state(hx_dynamics *d, double *y);

/* ydot = f(t, y). Returns 0, or -1 (d->message) when an element stopped the
 * run or returned a non-finite value, or the constraints are singular. */
int hx_dynamics_rhs(hx_dynamics *d, double t, const double *y, double *ydot);

/* The kinematics of y into d->frames: bodies' frames, then markers. */
void hx_dynamics_set_state(hx_dynamics *d, double t, const double *y);

/* How the stages of an evaluation fail: sim/dynamics/stage_failure.h. */

#endif
