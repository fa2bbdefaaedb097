/*
 * The harness's equations of motion, as one right-hand side for the
 * integrators. The dynamics owns its state (state/state.h): each evaluation
 * fills the bodies' frames from y, runs the kinematics stage, and calls the
 * elements with that state bound.
 *
 * Bodies are free (position, unit quaternion, velocity, body-axis angular
 * velocity) or hinged/slid to ground by one joint (the joint coordinate
 * AZ(I,J) or DZ(I,J,J), unwrapped, and its rate) (bodies.c). Forces: gravity
 * and loads (loads.c), the user force elements (element_forces.c) and the
 * Force_StateEqn elements, whose internal states are integrated with the
 * bodies' (state_elements.c). Couplers relate joint coordinates through one
 * Lagrange multiplier each, with projection onto the constraints after a
 * step (constraints.c).
 *
 * State layout y: [positions (nq) | velocities (nu) | the Force_StateEqn
 * elements' states (nstates, element by element in the model's order) | work
 * done by the loads | work done by the force elements, Force_StateEqn ones
 * included]. Units follow the model; mass *
 * acceleration = ucf * force, as in a solver with an inconsistent unit set
 * (mm, kg, s, N has ucf = 1000).
 */
#ifndef HX_SIM_DYNAMICS_H
#define HX_SIM_DYNAMICS_H

#include "host/session.h"
#include "state/state.h"

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
    hx_state state;             /* the state of the last evaluation */
    hx_state probe;             /* scratch state for elements at prescribed deformations */
    double ucf;                 /* acceleration = ucf * force / mass */
    hx_body_dof *dof;
    int nq, nu, n;
    int states, nstates;        /* y offset and count of the Force_StateEqn elements' states */
    int load_work, element_work; /* y indices of the work done by loads and by force elements */
    struct hx_state_elements *stateful; /* the Force_StateEqn elements (state_elements.h) */
    hx_binding **coupler_binding; /* per coupler; NULL for the built-in form */
    hx_binding **force_binding;   /* per force element */
    double *lambda;             /* multipliers of the last evaluation */
    double *element_load;       /* 6 per force element: F, T on I, world axes */
    unsigned char *world_aligned; /* per force element: its result axes are the world's
                                   * for good (on ground, unturned) */
    double *force, *torque;     /* per body, world, torque about the cm */
    double *scratch;
    /* Non-NULL: 6 outputs per force element, then 6 per Force_StateEqn, in
     * the element's own axes, that the evaluation applies as they are instead
     * of calling the elements (the Newton matrix's frozen differences,
     * newton_matrix.h); the Force_StateEqn states' rates are then zero. */
    const double *frozen_outputs;
    int failed;
    char message[1024];
    double max_phi, max_phidot; /* largest constraint residuals after projections */
} hx_dynamics;

/* Refuses models with elements the harness does not model (model.h). */
int hx_dynamics_init(hx_dynamics *d, hx_session *s, hx_message *msg);
void hx_dynamics_free(hx_dynamics *d);

/* Initial state from the model, projected onto the couplers. */
int hx_dynamics_initial_state(hx_dynamics *d, double *y);

/* ydot = f(t, y). Returns 0, or -1 (d->message) when an element stopped the
 * run or returned a non-finite value, or the constraints are singular. */
int hx_dynamics_rhs(hx_dynamics *d, double t, const double *y, double *ydot);

/* The kinematics of y into d->state: bodies' frames, then markers. */
void hx_dynamics_set_state(hx_dynamics *d, double t, const double *y);

/* Normalizes quaternions and projects onto the couplers; returns 0 or -1. */
int hx_dynamics_project(hx_dynamics *d, double t, double *y);

/* Largest |phi| and |dphi/dt| of the couplers at a state. */
int hx_dynamics_residuals(hx_dynamics *d, double t, const double *y, double *phi,
                          double *phidot);

/* q <- q + h N(q) u (quaternions by their exact increment), for symplectic Euler. */
void hx_dynamics_advance_positions(hx_dynamics *d, double *y, double h);

/* The energy of a state, in force * length units (energy.c). */
typedef struct hx_energy {
    double total;     /* kinetic + gravity potential + elastic - work of the loads */
    double kinetic;
    double elastic;   /* the force elements' potential at their deformation */
    double balance;   /* kinetic + gravity potential - work of loads and elements:
                       * constant whatever the elements do (damping included),
                       * so its drift is the integrator's alone */
} hx_energy;

hx_energy hx_dynamics_energy(hx_dynamics *d, double t, const double *y);

/* Generalized force coupler puts on joint `joint` of its list: G_kj lambda_k. */
double hx_dynamics_coupler_force(hx_dynamics *d, double t, const double *y, int coupler,
                                 int joint);

/* ---- the parts of an evaluation, for the files of the sim layer ---------------- */

/* Records the first failure in d->message; returns -1. */
int hx_dynamics_fail(hx_dynamics *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* -1 when an element asked to stop the run (c_errmes STOP). */
int hx_dynamics_check_stop(hx_dynamics *d, const hx_binding *b);

/* Body set-up, and the accelerations of the bodies from d->force, d->torque. */
int hx_bodies_init(hx_dynamics *d, hx_message *msg);
void hx_bodies_set_frames(hx_dynamics *d, const double *y);
void hx_bodies_initial_state(const hx_dynamics *d, double *y);
void hx_bodies_accelerations(hx_dynamics *d, const double *y, double *ydot);
/* Adds F at a world point (and a couple T, may be NULL) to a body's force and
 * torque about its centre, with sign; returns their power (0 on ground). */
double hx_apply_load(hx_dynamics *d, int body, const double point[3], const double F[3],
                     const double T[3], double sign);
/* 1/mass of a jointed body's velocity u_index (0 for free bodies). */
double hx_bodies_inverse_mass(const hx_dynamics *d, int u_index);

/* Gravity and the model's loads at time t; returns their power. */
double hx_apply_loads(hx_dynamics *d, double t);
/* The force elements at d->state; *power receives the power of their forces. */
int hx_apply_element_forces(hx_dynamics *d, double *power);
/* The couplers' multipliers into the accelerations udot. */
int hx_apply_constraints(hx_dynamics *d, double t, const double *y, double *udot);

#endif
