/* The harness's utility functions for user subroutines (host.h). */
#include "host.h"

#include <pthread.h>
#include <stdlib.h>
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

/* World frames of the markers elements and loads name, computed once per
 * state (when the frames are set) rather than once per query; those on ground
 * once per model. */
enum { MARKER_UNWATCHED, MARKER_MOVING, MARKER_ON_GROUND };
static hx_frame *marker_cache;
static unsigned char *marker_watched;
static const hx_frame *marker_cache_frames;
static int ground_markers_ready;
static int *moving_markers, moving_count; /* the watched markers not on ground */

static pthread_mutex_t message_lock = PTHREAD_MUTEX_INITIALIZER;
static FILE *message_stream;
static int message_stream_set;
static int stop_requested;
static char stop_message[HX_TEXT_MAX];
static int error_count, notice_count;
static char last_error[HX_TEXT_MAX], last_notice[HX_TEXT_MAX];

static void watch_marker(const hx_model *m, int index)
{
    if (index >= 0 && index < m->nmarkers)
        marker_watched[index] =
            m->bodies[m->markers[index].body].is_ground ? MARKER_ON_GROUND : MARKER_MOVING;
}

void hx_host_attach(const hx_model *m)
{
    host_model = m;
    host_frames = NULL;
    marker_cache_frames = NULL;
    free(marker_cache);
    free(marker_watched);
    free(moving_markers);
    marker_cache = NULL;
    marker_watched = NULL;
    moving_markers = NULL;
    moving_count = 0;
    if (m == NULL || m->nmarkers == 0)
        return;
    marker_cache = calloc((size_t)m->nmarkers, sizeof *marker_cache);
    marker_watched = calloc((size_t)m->nmarkers, 1);
    ground_markers_ready = 0;
    if (marker_cache == NULL || marker_watched == NULL)
        return;
    for (int k = 0; k < m->nforces; ++k)
        watch_marker(m, m->forces[k].i_marker), watch_marker(m, m->forces[k].j_marker),
            watch_marker(m, m->forces[k].ref_marker);
    for (int k = 0; k < m->nloads; ++k)
        watch_marker(m, m->loads[k].i_marker), watch_marker(m, m->loads[k].j_marker),
            watch_marker(m, m->loads[k].ref_marker);
    moving_markers = malloc(sizeof *moving_markers * (size_t)m->nmarkers);
    for (int k = 0; moving_markers != NULL && k < m->nmarkers; ++k)
        if (marker_watched[k] == MARKER_MOVING)
            moving_markers[moving_count++] = k;
}

void hx_host_set_frames(const hx_frame *bodies, double time)
{
    host_frames = bodies;
    host_time = time;
    marker_cache_frames = NULL;
    if (host_model == NULL || bodies == NULL || marker_cache == NULL || marker_watched == NULL)
        return;
    if (!ground_markers_ready || moving_markers == NULL) {
        for (int k = 0; k < host_model->nmarkers; ++k)
            if (marker_watched[k])
                hx_marker_frame(host_model, bodies, k, &marker_cache[k]);
        ground_markers_ready = 1;
    } else {
        for (int n = 0; n < moving_count; ++n)
            hx_marker_frame(host_model, bodies, moving_markers[n], &marker_cache[moving_markers[n]]);
    }
    marker_cache_frames = bodies;
}

const hx_frame *hx_host_marker_slot(int index)
{
    if (index < 0 || marker_watched == NULL || host_model == NULL || index >= host_model->nmarkers ||
        !marker_watched[index])
        return NULL;
    return &marker_cache[index];
}

const hx_frame *hx_host_marker_frame(const hx_frame *bodies, int index, hx_frame *scratch)
{
    if (index >= 0 && bodies == marker_cache_frames && marker_watched[index])
        return &marker_cache[index];
    hx_marker_frame(host_model, bodies, index, scratch);
    return scratch;
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
    if (a->function != b->function || a->nsize != b->nsize)
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

/* Function codes: the arrays, then the scalars (axis added to the base). */
enum {
    F_DISP, F_TDISP, F_RDISP, F_VEL, F_TVEL, F_RVEL, F_DM,
    F_DX, F_AX = F_DX + 3, F_VX = F_AX + 3, F_WX = F_VX + 3, F_COUNT = F_WX + 3
};
static const int max_nsize[F_COUNT] = {3, 3, 2, 4, 4, 3, 2, 3, 3, 3, 2, 2, 2, 4, 4, 4, 3, 3, 3};

static int is(const char *f, const char *name)
{
    while (*name != '\0' && *f == *name)
        ++f, ++name;
    return *name == '\0' && *f == '\0';
}

static int function_code(const char *f)
{
    if (f == NULL || f[0] == '\0')
        return -1;
    const int axis = f[1] >= 'X' && f[1] <= 'Z' && f[2] == '\0' ? f[1] - 'X' : -1;
    switch (f[0]) {
    case 'D':
        return is(f, "DISP") ? F_DISP : is(f, "DM") ? F_DM : axis >= 0 ? F_DX + axis : -1;
    case 'T':
        return is(f, "TDISP") ? F_TDISP : is(f, "TVEL") ? F_TVEL : -1;
    case 'R':
        return is(f, "RDISP") ? F_RDISP : is(f, "RVEL") ? F_RVEL : -1;
    case 'V':
        return is(f, "VEL") ? F_VEL : axis >= 0 ? F_VX + axis : -1;
    case 'A':
        return axis >= 0 ? F_AX + axis : -1;
    case 'W':
        return axis >= 0 ? F_WX + axis : -1;
    default:
        return -1;
    }
}

static const hx_frame world_frame = {{0, 0, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0}};

/* The world frame of a marker id (0: the world), from the cache when it can. */
static const hx_frame *marker_world(const hx_model *m, const hx_frame *bodies, int id,
                                    hx_frame *scratch)
{
    if (id == 0)
        return &world_frame;
    const int index = hx_model_marker(m, id);
    if (index < 0)
        return NULL;
    if (m == host_model)
        return hx_host_marker_frame(bodies, index, scratch);
    hx_marker_frame(m, bodies, index, scratch);
    return scratch;
}

static int answer(const hx_model *m, const hx_frame *bodies, int code, const int *ipar,
                  int nsize, double *values)
{
    if (m == NULL || bodies == NULL || code < 0 || nsize < 1 || nsize > max_nsize[code] ||
        ipar == NULL || ipar[0] == 0)
        return -1;
    hx_frame scratch[4];
    const hx_frame *f[4];
    for (int k = 0; k < 4; ++k) {
        const int id = k < nsize ? ipar[k] : 0;
        /* repeated ids (J, J, J) share one frame */
        f[k] = k > 0 && id == (k - 1 < nsize ? ipar[k - 1] : 0) ? f[k - 1]
                                                                 : marker_world(m, bodies, id, &scratch[k]);
        if (f[k] == NULL)
            return -1;
    }
    const hx_frame *I = f[0], *J = f[1], *K = f[2], *L = f[3];
    double R[9], v[3];
    switch (code) {
    case F_DISP:
    case F_TDISP:
        hx_displacement(I, J, K, values);
        if (code == F_TDISP)
            return 3;
        hx_relative_euler313(I, J, values + 3);
        return 6;
    case F_RDISP:
        hx_relative_euler313(I, J, values);
        return 3;
    case F_VEL:
    case F_TVEL:
        hx_relative_velocity(I, J, K, L, values);
        if (code == F_TVEL)
            return 3;
        hx_relative_angular_velocity(I, J, K, values + 3);
        return 6;
    case F_RVEL:
        hx_relative_angular_velocity(I, J, K, values);
        return 3;
    case F_DM:
        v3_sub(v, I->p, J->p);
        values[0] = v3_norm(v);
        return 1;
    default:
        break;
    }
    if (code < F_AX) {
        hx_displacement(I, J, K, v);
        values[0] = v[code - F_DX];
    } else if (code < F_VX) {
        hx_relative_rotation(I, J, R);
        hx_projection_angles(R, v);
        values[0] = v[code - F_AX];
    } else if (code < F_WX) {
        hx_relative_velocity(I, J, K, L, v);
        values[0] = v[code - F_VX];
    } else {
        hx_relative_angular_velocity(I, J, K, v);
        values[0] = v[code - F_WX];
    }
    return 1;
}

int hx_answer_query(const hx_model *m, const hx_frame *bodies, const char *fnc,
                    const int *ipar, int nsize, double *values)
{
    return answer(m, bodies, function_code(fnc), ipar, nsize, values);
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
    q.function = function_code(fnc);
    q.nsize = nsize;
    q.is_array = is_array;
    for (int k = 0; k < 4; ++k)
        q.ipar[k] = k < nsize && ipar != NULL ? ipar[k] : 0;
    q.fnc[0] = '\0'; /* the text is written only when the query is kept or reported */
    double scratch[6];
    const int array_function = q.function >= F_DISP && q.function <= F_RVEL;
    const int count = q.function < 0 || array_function != is_array
                          ? -1
                          : answer(host_model, host_frames, q.function, ipar, nsize,
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
            snprintf(q.fnc, sizeof q.fnc, "%s", fnc);
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
                snprintf(q.fnc, sizeof q.fnc, "%s", fnc);
                c->first_undeclared = q;
                if (c->warned == NULL || !*c->warned)
                    warn_undeclared(c, &q);
                if (c->warned != NULL)
                    *c->warned = 1;
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
