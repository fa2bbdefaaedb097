/*
 * The one state of a model (MuJoCo's data to the model's model): time, the
 * frames of the bodies, and the world frames of the markers the model's
 * elements name, kept current by one kinematics stage. Whoever integrates
 * or probes owns a state; the host answers the library's queries from the
 * state bound to the call (host/call.h), never from anything else.
 */
#ifndef HX_STATE_STATE_H
#define HX_STATE_STATE_H

#include "model/model.h"

/* Pose and velocity of a frame in world coordinates: origin p, orientation R
 * (row-major, columns = axes), velocity of the origin v, angular velocity w. */
typedef struct hx_frame {
    double p[3], R[9], v[3], w[3];
} hx_frame;

typedef struct hx_state {
    const hx_model *model;
    double time;
    hx_frame *bodies;   /* nbodies */
    hx_frame *markers;  /* nmarkers: tracked markers are current after hx_state_update */
    int *moving;        /* tracked markers on moving bodies: what the update recomputes */
    int nmoving;
    /* the Control_Diff states, two per element in the order of their slots
     * (model.h): the value and its rate (DIF and DIF1), ic and ic_dot at first */
    double *diffs;
} hx_state;

/* A state at the model's initial pose and velocities, its markers current.
 * Returns 0, or -1 (out of memory). */
int hx_state_init(hx_state *s, const hx_model *m);
void hx_state_free(hx_state *s);
/* A second state equal to from (a scratch state for a probe); 0 or -1. */
int hx_state_clone(hx_state *to, const hx_state *from);
/* Copies time and frames between two states of the same model. */
void hx_state_copy(hx_state *to, const hx_state *from);

/* The kinematics stage: world frames of the tracked markers of moving bodies
 * from the bodies' frames (those on ground never move). */
void hx_state_update(hx_state *s);

/* World frame of marker index (-1: the world frame) at this state: the kept
 * one when the marker is tracked, else computed into scratch. */
const hx_frame *hx_state_marker(const hx_state *s, int index, hx_frame *scratch);

/* World frame of a marker from its body's frame. */
void hx_marker_frame(const hx_model *m, const hx_frame *body, int marker, hx_frame *out);

extern const hx_frame hx_world_frame;

#endif
