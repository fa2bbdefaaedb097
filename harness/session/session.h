/*
 * A harness session: a model read, a state at its initial pose, the
 * libraries of its user elements loaded and bound, their dependency passes
 * run, and the working directory moved to the model's folder (as a solver run
 * from there sees relative property-file paths). Paths given on the command
 * line are taken relative to the folder the harness started in.
 */
#ifndef HX_SESSION_SESSION_H
#define HX_SESSION_SESSION_H

#include <limits.h>
#include <stdio.h>

#include "host/binding.h"
#include "host/messages.h"
#include "model/model.h"
#include "frames/frames.h"

typedef struct hx_session {
    hx_model *model;
    hx_messages messages;
    hx_bindings bindings;
    hx_frames frames;           /* the model's initial pose and velocities, t = 0 */
    char start_dir[PATH_MAX];  /* where the harness was started */
} hx_session;

/* messages: where the libraries' messages and the host's reports are printed
 * (NULL: kept, not printed). Returns 0, or -1 with msg. */
int hx_session_open(hx_session *s, const char *model_path, FILE *messages, hx_message *msg);
void hx_session_close(hx_session *s);

/* An output path as the user meant it (relative to start_dir). */
const char *hx_session_path(const hx_session *s, const char *arg, char *path, size_t size);

#endif
