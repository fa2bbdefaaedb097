/* Opening and closing a harness session (session.h). */
#include "session.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int hx_session_open(hx_session *s, const char *model_path, usrsub_message *msg)
{
    memset(s, 0, sizeof *s);
    if (getcwd(s->start_dir, sizeof s->start_dir) == NULL)
        snprintf(s->start_dir, sizeof s->start_dir, ".");
    s->model = hx_model_read(model_path, stderr, msg);
    if (s->model == NULL)
        return -1;
    if (chdir(s->model->dir) != 0) {
        usrsub_fail(msg, "cannot enter the model's folder %s: %s", s->model->dir,
                    strerror(errno));
        hx_session_close(s);
        return -1;
    }
    s->frames = calloc((size_t)s->model->nbodies, sizeof *s->frames);
    if (s->frames == NULL) {
        usrsub_fail(msg, "out of memory");
        hx_session_close(s);
        return -1;
    }
    hx_initial_frames(s->model, s->frames);
    hx_host_attach(s->model);
    hx_host_set_frames(s->frames, 0.0);
    if (hx_bind(s->model, &s->bindings, msg) != 0) {
        hx_session_close(s);
        return -1;
    }
    if (hx_dependency_passes(&s->bindings, s->model, s->frames) != 0) {
        usrsub_fail(msg, "an element stopped the run in its dependency pass (c_errmes STOP): %s",
                    hx_host_stop_message());
        hx_session_close(s);
        return -1;
    }
    return 0;
}

void hx_session_close(hx_session *s)
{
    hx_bindings_free(&s->bindings);
    hx_host_attach(NULL);
    hx_model_free(s->model);
    free(s->frames);
    if (s->start_dir[0] != '\0' && chdir(s->start_dir) != 0)
        s->start_dir[0] = '\0';
    s->model = NULL;
    s->frames = NULL;
}

const char *hx_session_path(const hx_session *s, const char *arg, char *path, size_t size)
{
    if (arg[0] == '/')
        snprintf(path, size, "%s", arg);
    else
        snprintf(path, size, "%s/%s", s->start_dir, arg);
    return path;
}
