/* Opening and closing a harness session (session.h). */
#include "session/session.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host/dependency_pass.h"
#include "host/loop_queries.h"
#include "host/variable_reads.h"

int hx_session_open(hx_session *s, const char *model_path, FILE *messages, hx_message *msg)
{
    memset(s, 0, sizeof *s);
    hx_messages_init(&s->messages, messages);
    if (getcwd(s->start_dir, sizeof s->start_dir) == NULL)
        snprintf(s->start_dir, sizeof s->start_dir, ".");
    s->model = hx_model_read(model_path, stderr, msg);
    if (s->model == NULL) {
        hx_session_close(s);
        return -1;
    }
    if (chdir(s->model->dir) != 0) {
        hx_fail(msg, "cannot enter the model's folder %s: %s", s->model->dir, strerror(errno));
        hx_session_close(s);
        return -1;
    }
    if (hx_frames_init(&s->frames, s->model) != 0) {
        hx_fail(msg, "out of memory");
        hx_session_close(s);
        return -1;
    }
    if (hx_bind(s->model, &s->messages, &s->bindings, msg) != 0) {
        hx_session_close(s);
        return -1;
    }
    if (hx_dependency_passes(&s->bindings, &s->frames) != 0) {
        hx_fail(msg, "an element stopped the run in its dependency pass (c_errmes STOP): %s",
                s->messages.stop_message);
        hx_session_close(s);
        return -1;
    }
    /* the accelerations the routines declared join the algebraic loop: the
     * frames made before then get room for them */
    const int loop_inputs = s->model->nloop_inputs;
    if (hx_bind_loop_queries(s->model, &s->bindings, msg) != 0 ||
        hx_bind_variable_reads(s->model, &s->bindings, msg) != 0) {
        hx_session_close(s);
        return -1;
    }
    if (s->model->nloop_inputs != loop_inputs) {
        hx_frames_free(&s->frames);
        if (hx_frames_init(&s->frames, s->model) != 0) {
            hx_fail(msg, "out of memory");
            hx_session_close(s);
            return -1;
        }
    }
    return 0;
}

void hx_session_close(hx_session *s)
{
    hx_bindings_free(&s->bindings);
    hx_frames_free(&s->frames);
    hx_model_free(s->model);
    hx_messages_destroy(&s->messages);
    if (s->start_dir[0] != '\0' && chdir(s->start_dir) != 0)
        s->start_dir[0] = '\0';
    s->model = NULL;
}

const char *hx_session_path(const hx_session *s, const char *arg, char *path, size_t size)
{
    if (arg[0] == '/')
        snprintf(path, size, "%s", arg);
    else
        snprintf(path, size, "%s/%s", s->start_dir, arg);
    return path;
}
