/*
 * The harness's equations of motion, as one right-hand side for the
 * integrators. Bodies are either free (position, unit quaternion, velocity,
 * body-axis angular velocity) or hinged/slid to ground by one joint (the joint
 * coordinate AZ(I,J) or DZ(I,J,J), unwrapped, and its rate). Couplers relate
 * joint coordinates through one Lagrange multiplier each (COUSUB/COUXX for the
 * constraint and its Jacobian, COUXX2 for the velocity-squared term); after a
 * step, positions and velocities are projected back onto the constraints.
 * Forces: gravity, constant loads, and the user force elements (GFOSUB, FIESUB).
 *
 * State layout: [positions (nq) | velocities (nu) | work done by the loads (1)].
 * Units follow the model; mass * acceleration = ucf * force, as in a solver
 * with an inconsistent unit set (mm, kg, s, N has ucf = 1000).
 */
#ifndef HX_DYNAMICS_H
#define HX_DYNAMICS_H

#include "binding.h"
#include "kinematics.h"
#include "session.h"

typedef enum hx_dof_kind { HX_DOF_GROUND, HX_DOF_FREE, HX_DOF_REVOLUTE, HX_DOF_SLIDER } hx_dof_kind;

typedef struct hx_body_dof {
    hx_dof_kind kind;
    int q, u;                   /* offsets of the body's positions and velocities */
    double axis[3], origin[3];  /* joint axis (J marker z, world) and a point on it */
    double coord0;              /* joint coordinate at t = 0 */
    double p0[3], R0[9];        /* body frame at t = 0 */
    double mass;                /* m, or the moment of inertia about the joint axis */
    double inertia[9], inertia_inv[9]; /* free bodies: about the cm, body axes */
} hx_body_dof;

typedef struct hx_dynamics {
    hx_session *s;
    const hx_model *m;
    double ucf;                 /* mass * length / time^2 per force unit */
    hx_body_dof *dof;
    int nq, nu, n;
    int load_work, element_work; /* y indices of the work done by loads and by force elements */
    hx_binding **coupler_binding; /* per coupler; NULL for the built-in form */
    hx_binding **force_binding;   /* per force element */
    double *lambda;             /* multipliers of the last evaluation */
    double *element_load;       /* 6 per force element: F, T on I, world axes */
    const hx_frame **element_frames; /* 3 per force element: I, J, and the axes of its
                                      * result (ref or J), in the host's marker cache */
    unsigned char *world_aligned;    /* per force element: its result axes are the world's
                                      * for good (on ground, unturned) */
    int *element_bodies;             /* 2 per force element: the I and J bodies, -1 for ground */
    double *force, *torque;     /* per body, world, torque about the cm */
    double *scratch;
    long evaluations;
    int failed;
    char message[1024];
    double max_phi, max_phidot; /* largest constraint residuals after projections */
} hx_dynamics;

int hx_dynamics_init(hx_dynamics *d, hx_session *s, usrsub_message *msg);
void hx_dynamics_free(hx_dynamics *d);

/* Initial state from the model, projected onto the couplers. */
int hx_dynamics_initial_state(hx_dynamics *d, double *y);

/* ydot = f(t, y). Returns 0, or -1 (d->message) when an element stopped the
 * run or returned a non-finite value, or the constraints are singular. */
int hx_dynamics_rhs(hx_dynamics *d, double t, const double *y, double *ydot);

/* Bodies' frames of a state into d->s->frames (and the host's view). */
void hx_dynamics_frames(hx_dynamics *d, double t, const double *y);

/* Normalizes quaternions and projects onto the couplers; returns 0 or -1. */
int hx_dynamics_project(hx_dynamics *d, double t, double *y);

/* Largest |phi| and |dphi/dt| of the couplers at a state. */
int hx_dynamics_residuals(hx_dynamics *d, double t, const double *y, double *phi,
                          double *phidot);

/* The energy of a state, in force * length units. */
typedef struct hx_energy {
    double total;     /* kinetic + gravity potential + elastic - work of the loads */
    double kinetic;
    double elastic;   /* the force elements' potential at their deformation */
    double balance;   /* kinetic + gravity potential - work of loads and elements:
                       * constant whatever the elements do (damping included),
                       * so its drift is the integrator's alone */
} hx_energy;

hx_energy hx_dynamics_energy(hx_dynamics *d, double t, const double *y);

/* q <- q + h N(q) u (quaternions by their exact increment), for symplectic Euler. */
void hx_dynamics_advance_positions(hx_dynamics *d, double *y, double h);

/* Generalized force each coupler puts on joint k of its list: G_kj lambda_k. */
double hx_dynamics_coupler_force(hx_dynamics *d, double t, const double *y, int coupler,
                                 int joint);

#endif
