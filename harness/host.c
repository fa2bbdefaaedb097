/* The harness's utility functions for user subroutines (host.h). */
#include "host.h"

#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

#include "usrsub/solver_abi.h"
#include "vecmath.h"

#define HX_TEXT_MAX 1024

static const hx_model *host_model;
static const hx_frame *host_frames;
static double host_time;
static _Thread_local hx_call *current;

static pthread_mutex_t message_lock = PTHREAD_MUTEX_INITIALIZER;
static FILE *message_stream;
static int message_stream_set;
static int stop_requested;
static char stop_message[HX_TEXT_MAX];
static int error_count, notice_count;
static char last_error[HX_TEXT_MAX], last_notice[HX_TEXT_MAX];

void hx_host_attach(const hx_model *m)
{
    host_model = m;
    host_frames = NULL;
}

void hx_host_set_frames(const hx_frame *bodies, double time)
{
    host_frames = bodies;
    host_time = time;
}

void hx_call_init(hx_call *c, const char *element, int id, int dependency_pass,
                  hx_dependencies *declared)
{
    memset(c, 0, sizeof *c);
    c->element = element;
    c->id = id;
    c->dependency_pass = dependency_pass;
    c->declared = declared;
    c->perturb_query = -1;
    if (dependency_pass && declared != NULL)
        memset(declared, 0, sizeof *declared);
}

void hx_host_begin_call(hx_call *c)
{
    current = c;
}

void hx_host_end_call(void)
{
    current = NULL;
}

/* ---- messages ------------------------------------------------------------- */

static FILE *stream(void)
{
    return message_stream_set ? message_stream : stderr;
}

void hx_host_set_message_stream(FILE *f)
{
    message_stream = f;
    message_stream_set = 1;
}

int hx_host_stop_requested(void)
{
    return stop_requested;
}

const char *hx_host_stop_message(void)
{
    return stop_message;
}

void hx_host_clear_stop(void)
{
    pthread_mutex_lock(&message_lock);
    stop_requested = 0;
    stop_message[0] = '\0';
    pthread_mutex_unlock(&message_lock);
}

int hx_host_error_count(void)
{
    return error_count;
}

const char *hx_host_last_error(void)
{
    return last_error;
}

int hx_host_notice_count(void)
{
    return notice_count;
}

const char *hx_host_last_notice(void)
{
    return last_notice;
}

void hx_host_reset_messages(void)
{
    pthread_mutex_lock(&message_lock);
    error_count = notice_count = 0;
    last_error[0] = last_notice[0] = '\0';
    stop_requested = 0;
    stop_message[0] = '\0';
    pthread_mutex_unlock(&message_lock);
}

static int is_word(const char *text, const char *word)
{
    if (text == NULL)
        return 0;
    while (*text == ' ')
        ++text;
    const size_t n = strlen(word);
    if (strncasecmp(text, word, n) != 0)
        return 0;
    for (text += n; *text == ' '; ++text)
        ;
    return *text == '\0';
}

void c_errmes(int errflg, const char *msg, int id, const char *endflg)
{
    if (!errflg)
        return;
    pthread_mutex_lock(&message_lock);
    ++error_count;
    snprintf(last_error, sizeof last_error, "%s", msg != NULL ? msg : "");
    const int stop = is_word(endflg, "STOP");
    if (stop && !stop_requested) {
        stop_requested = 1;
        snprintf(stop_message, sizeof stop_message, "%s", last_error);
    }
    FILE *f = stream();
    if (f != NULL)
        fprintf(f, "ERRMES [%d]%s: %s\n", id, stop ? " STOP" : "", last_error);
    pthread_mutex_unlock(&message_lock);
}

void c_usrmes(int msgflg, const char *msg, int id, const char *msgtyp)
{
    if (!msgflg)
        return;
    pthread_mutex_lock(&message_lock);
    ++notice_count;
    snprintf(last_notice, sizeof last_notice, "%s", msg != NULL ? msg : "");
    FILE *f = stream();
    if (f != NULL)
        fprintf(f, "USRMES:USER [%d] %s: %s\n", id, msgtyp != NULL ? msgtyp : "INFO",
                last_notice);
    pthread_mutex_unlock(&message_lock);
}

void c_gtstrg(int id, char *string, int *nchars, int *istat)
{
    const char *text = host_model != NULL ? hx_model_string(host_model, id) : NULL;
    if (text == NULL || string == NULL || nchars == NULL) {
        if (istat != NULL)
            *istat = -1;
        return;
    }
    const int len = (int)strlen(text);
    const int capacity = *nchars; /* our convention: nchars carries the capacity in */
    if (capacity > 0 && len > capacity) {
        memcpy(string, text, (size_t)capacity);
        *nchars = capacity;
        *istat = 1; /* truncated */
        return;
    }
    memcpy(string, text, (size_t)len);
    if (capacity <= 0 || len < capacity)
        string[len] = '\0';
    *nchars = len;
    *istat = 0;
}

void c_gtunts(int *exists, double *scales, char *units)
{
    (void)units;
    const int has = host_model != NULL && host_model->has_units;
    if (exists != NULL)
        *exists = has;
    if (has && scales != NULL)
        memcpy(scales, host_model->unit_scales, sizeof host_model->unit_scales);
}

/* ---- queries ----------------------------------------------------------------- */

const char *hx_query_text(const hx_query *q, char *text, size_t size)
{
    int n = snprintf(text, size, "%s(", q->fnc);
    for (int k = 0; k < q->nsize && n > 0 && (size_t)n < size; ++k)
        n += snprintf(text + n, size - (size_t)n, k ? ",%d" : "%d", q->ipar[k]);
    if (n > 0 && (size_t)n < size)
        snprintf(text + n, size - (size_t)n, ")");
    return text;
}

const char *hx_dependencies_text(const hx_dependencies *d, char *text, size_t size)
{
    if (d == NULL || d->count == 0) {
        snprintf(text, size, "none");
        return text;
    }
    size_t n = 0;
    text[0] = '\0';
    for (int k = 0; k < d->count && n < size; ++k) {
        char one[64];
        n += (size_t)snprintf(text + n, size - n, k ? " %s" : "%s",
                              hx_query_text(&d->query[k], one, sizeof one));
    }
    return text;
}

static int same_query(const hx_query *a, const hx_query *b)
{
    if (strcmp(a->fnc, b->fnc) != 0 || a->nsize != b->nsize)
        return 0;
    for (int k = 0; k < a->nsize; ++k)
        if (a->ipar[k] != b->ipar[k])
            return 0;
    return 1;
}

static int find_query(const hx_dependencies *d, const hx_query *q)
{
    for (int k = 0; k < d->count; ++k)
        if (same_query(&d->query[k], q))
            return k;
    return -1;
}

typedef struct query_frames {
    hx_frame f[4]; /* I, J, K, L */
} query_frames;

static int frames_for(const hx_model *m, const hx_frame *bodies, const int *ipar, int nsize,
                      int max_size, query_frames *qf)
{
    if (nsize < 1 || nsize > max_size || ipar == NULL || ipar[0] == 0)
        return -1;
    for (int k = 0; k < 4; ++k) {
        const int id = k < nsize ? ipar[k] : 0;
        int index = -1;
        if (id != 0 && (index = hx_model_marker(m, id)) < 0)
            return -1;
        hx_marker_frame(m, bodies, index, &qf->f[k]);
    }
    return 0;
}

int hx_answer_query(const hx_model *m, const hx_frame *bodies, const char *fnc,
                    const int *ipar, int nsize, double *values)
{
    if (m == NULL || bodies == NULL || fnc == NULL)
        return -1;
    query_frames qf;
    hx_frame *I = &qf.f[0], *J = &qf.f[1], *K = &qf.f[2], *L = &qf.f[3];
    double R[9];
    /* c_sysary arrays */
    if (strcmp(fnc, "DISP") == 0 || strcmp(fnc, "TDISP") == 0) {
        if (frames_for(m, bodies, ipar, nsize, 3, &qf) != 0)
            return -1;
        hx_displacement(I, J, K, values);
        if (fnc[0] == 'T')
            return 3;
        hx_relative_rotation(I, J, R);
        hx_euler313(R, values + 3);
        return 6;
    }
    if (strcmp(fnc, "RDISP") == 0) {
        if (frames_for(m, bodies, ipar, nsize, 2, &qf) != 0)
            return -1;
        hx_relative_rotation(I, J, R);
        hx_euler313(R, values);
        return 3;
    }
    if (strcmp(fnc, "VEL") == 0 || strcmp(fnc, "TVEL") == 0) {
        if (frames_for(m, bodies, ipar, nsize, 4, &qf) != 0)
            return -1;
        hx_relative_velocity(I, J, K, L, values);
        if (fnc[0] == 'T')
            return 3;
        hx_relative_angular_velocity(I, J, K, values + 3);
        return 6;
    }
    if (strcmp(fnc, "RVEL") == 0) {
        if (frames_for(m, bodies, ipar, nsize, 3, &qf) != 0)
            return -1;
        hx_relative_angular_velocity(I, J, K, values);
        return 3;
    }
    /* c_sysfnc scalars */
    const int axis = fnc[0] != '\0' && fnc[1] >= 'X' && fnc[1] <= 'Z' && fnc[2] == '\0'
                         ? fnc[1] - 'X' : -1;
    double v[3];
    if (fnc[0] == 'D' && (axis >= 0 || strcmp(fnc, "DM") == 0)) {
        if (frames_for(m, bodies, ipar, nsize, axis >= 0 ? 3 : 2, &qf) != 0)
            return -1;
        if (axis < 0) {
            v3_sub(v, I->p, J->p);
            values[0] = v3_norm(v);
            return 1;
        }
        hx_displacement(I, J, K, v);
    } else if (fnc[0] == 'A' && axis >= 0) {
        if (frames_for(m, bodies, ipar, nsize, 2, &qf) != 0)
            return -1;
        hx_relative_rotation(I, J, R);
        hx_projection_angles(R, v);
    } else if (fnc[0] == 'V' && axis >= 0) {
        if (frames_for(m, bodies, ipar, nsize, 4, &qf) != 0)
            return -1;
        hx_relative_velocity(I, J, K, L, v);
    } else if (fnc[0] == 'W' && axis >= 0) {
        if (frames_for(m, bodies, ipar, nsize, 3, &qf) != 0)
            return -1;
        hx_relative_angular_velocity(I, J, K, v);
    } else {
        return -1;
    }
    values[0] = v[axis];
    return 1;
}

static void warn_undeclared(const hx_call *c, const hx_query *q)
{
    char text[64];
    pthread_mutex_lock(&message_lock);
    FILE *f = stream();
    if (f != NULL)
        fprintf(f, "host: %s %d reads %s outside the dependencies it declared\n",
                c->element ? c->element : "element", c->id, hx_query_text(q, text, sizeof text));
    pthread_mutex_unlock(&message_lock);
}

/* Common path of c_sysary and c_sysfnc. */
static int query(const char *fnc, const int *ipar, int nsize, double *values, int is_array)
{
    hx_call *c = current;
    hx_query q;
    memset(&q, 0, sizeof q);
    snprintf(q.fnc, sizeof q.fnc, "%s", fnc != NULL ? fnc : "");
    q.nsize = nsize;
    q.is_array = is_array;
    for (int k = 0; k < nsize && k < 4 && ipar != NULL; ++k)
        q.ipar[k] = ipar[k];
    double scratch[6];
    const int array_function = strcmp(q.fnc, "DISP") == 0 || strcmp(q.fnc, "TDISP") == 0 ||
                               strcmp(q.fnc, "RDISP") == 0 || strcmp(q.fnc, "VEL") == 0 ||
                               strcmp(q.fnc, "TVEL") == 0 || strcmp(q.fnc, "RVEL") == 0;
    const int count = array_function != is_array
                          ? -1
                          : hx_answer_query(host_model, host_frames, q.fnc, ipar, nsize,
                                            values != NULL ? values : scratch);
    if (c == NULL)
        return count;
    ++c->host_calls;
    if (count < 0)
        return count;
    if (c->dependency_pass) {
        for (int k = 0; k < count; ++k)
            values[k] = 0.0; /* the dependency pass sees zeros, as in a solver */
        if (c->declared != NULL && find_query(c->declared, &q) < 0) {
            if (c->declared->count < HX_MAX_QUERIES)
                c->declared->query[c->declared->count++] = q;
            else
                c->declared->overflow = 1;
        }
        return count;
    }
    if (c->declared != NULL) {
        const int k = find_query(c->declared, &q);
        if (k < 0) {
            if (c->undeclared++ == 0) {
                c->first_undeclared = q;
                warn_undeclared(c, &q);
            }
        } else {
            c->used |= 1u << k;
            if (k == c->perturb_query && c->perturb_component < count)
                values[c->perturb_component] += c->perturb_delta;
        }
    }
    return count;
}

void c_sysary(const char *fnc, const int *ipar, int nsize, double *states, int *nstates,
              int *errflg)
{
    const int count = states != NULL ? query(fnc, ipar, nsize, states, 1) : -1;
    if (nstates != NULL)
        *nstates = count > 0 ? count : 0;
    if (errflg != NULL)
        *errflg = count > 0 ? 0 : 1;
}

void c_sysfnc(const char *fnc, const int *ipar, int nsize, double *value, int *errflg)
{
    double v[6] = {0};
    const int count = query(fnc, ipar, nsize, v, 0);
    if (value != NULL)
        *value = count == 1 ? v[0] : 0.0;
    if (errflg != NULL)
        *errflg = count == 1 ? 0 : 1;
}
