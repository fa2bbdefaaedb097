/*
 * The frames of a model at one instant (MuJoCo's data to the model's model):
 * time, the frames of the bodies, the world frames of the markers the
 * model's elements name, kept current by one kinematics stage, and the
 * Control_Diff values the host answers DIF with. Whoever integrates or probes
 * owns its frames; the host answers the library's queries from the frames
 * bound to the call (host/call.h), never from anything else. "State" in the
 * harness means the integrator's vector y; "stateeqn" a Force_StateEqn.
 */
#ifndef HX_FRAMES_FRAMES_H
#define HX_FRAMES_FRAMES_H

#include "model/model.h"

/* Pose and velocity of a frame in world coordinates: origin p, orientation R
 * (row-major, columns = axes), velocity of the origin v, angular velocity w. */
typedef struct hx_frame {
    double p[3], R[9], v[3], w[3];
} hx_frame;

typedef struct hx_frames {
    const hx_model *model;
    double time;
    hx_frame *bodies;   /* nbodies */
    hx_frame *markers;  /* nmarkers: tracked markers are current after hx_frames_update */
    int *tracked;       /* the tracked markers, body by body: what the update recomputes
                         * (those of moving bodies) */
    int *first_tracked; /* nbodies + 1: body b's are tracked[first_tracked[b] ..
                         * first_tracked[b + 1] - 1] */
    /* the Control_Diff states, two per element in the order of their slots
     * (model.h): the value and its rate (DIF and DIF1), ic and ic_dot at first */
    double *diffs;
    /* the Reference_Variable values by index, computed after the frames when the
     * model's loads read them (model.h's variables_read; host/variable_values.h) */
    double *variables;
    /* the algebraic loop's inputs by slot (model/loop_inputs.h): what the forces,
     * variables and Control_Diff rates read for an acceleration, a reaction or an
     * SFORCE's force within a right-hand side, the loop's iterate
     * (sim/dynamics/algebraic_loop.h); zeros until a right-hand side sets them */
    double *loop;
} hx_frames;

/* Frames at the model's initial pose and velocities, its markers current.
 * Returns 0, or -1 (out of memory). */
int hx_frames_init(hx_frames *fr, const hx_model *m);
void hx_frames_free(hx_frames *fr);
/* A second set equal to from (scratch frames for a probe); 0 or -1. */
int hx_frames_clone(hx_frames *to, const hx_frames *from);
/* Copies time, frames, Control_Diff, variable and loop values between two sets of the same model. */
void hx_frames_copy(hx_frames *to, const hx_frames *from);

/* The kinematics stage: world frames of the tracked markers of moving bodies
 * from the bodies' frames (those on ground never move). */
void hx_frames_update(hx_frames *fr);

/* The same for one body's tracked markers alone, on ground too (a probe
 * that moved one body, ground included). */
void hx_frames_update_body(hx_frames *fr, int body);
/* Copies one body's frame and its tracked markers' (undoing such a move). */
void hx_frames_copy_body(hx_frames *to, const hx_frames *from, int body);

/* World frame of marker index (-1: the world frame) in these frames: the kept
 * one when the marker is tracked, else computed into scratch. */
const hx_frame *hx_frames_marker(const hx_frames *fr, int index, hx_frame *scratch);

/* World frame of a marker from its body's frame. */
void hx_marker_frame(const hx_model *m, const hx_frame *body, int marker, hx_frame *out);

extern const hx_frame hx_world_frame;

#endif
