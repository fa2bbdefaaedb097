/*
 * A harness session: a model read, its user elements bound to their libraries,
 * the host attached, and the working directory moved to the model's folder (as
 * a solver run from there sees relative property-file paths). Paths given on
 * the command line are taken relative to the folder the harness started in.
 */
#ifndef HX_SESSION_H
#define HX_SESSION_H

#include <limits.h>

#include "binding.h"
#include "kinematics.h"
#include "model.h"

typedef struct hx_session {
    hx_model *model;
    hx_bindings bindings;
    hx_frame *frames;          /* bodies' frames, initial pose after opening */
    char start_dir[PATH_MAX];  /* where the harness was started */
} hx_session;

int hx_session_open(hx_session *s, const char *model_path, usrsub_message *msg);
void hx_session_close(hx_session *s);

/* An output path as the user meant it (relative to start_dir). */
const char *hx_session_path(const hx_session *s, const char *arg, char *path, size_t size);

#endif
