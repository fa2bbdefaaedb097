/*
 * The assembly's report (docs/architecture.md, the constraint system): how
 * far projecting the model's initial state onto the constraints moved each
 * part, as an initial-conditions analysis reports it.
 */
#ifndef HX_SIM_DYNAMICS_ASSEMBLY_H
#define HX_SIM_DYNAMICS_ASSEMBLY_H

#include "sim/dynamics/dynamics.h"

/* A part the assembly moved: its centre of mass's translation (model length)
 * and its rotation (radians, the angle of the turn between the two poses). */
typedef struct hx_assembly_move {
    int body; /* index */
    double translation, rotation;
} hx_assembly_move;

/* Moves below these are not reported (the projection's own rounding). */
#define HX_ASSEMBLY_REPORTED_LENGTH 1e-9 /* of the model's length */
#define HX_ASSEMBLY_REPORTED_ANGLE 1e-9

/* The parts the assembly moved by more than the thresholds, in the model's
 * order, into moves (nbodies of room); returns their count, or -1 with msg
 * (a failed assembly: its message names the joints' equations). */
int hx_assembly_moves(const hx_dynamics *d, hx_assembly_move *moves, hx_message *msg);

#endif
