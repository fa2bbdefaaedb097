/* Helpers of the simulating tests (sim_support.h). */
#include "sim_support.h"
#include "host/dependency_pass.h"
#include "sim/jacobian/jacobian.h"

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cmd/commands.h"
#include "frames/measures.h"
#include "test_support.h"

static const char *model_path(const char *model)
{
    static char path[1024];
    if (model[0] == '/')
        snprintf(path, sizeof path, "%s", model);
    else
        snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, model);
    return path;
}

static int observe(void *ctx, const hx_dynamics *d, hx_dynamics_data *dd, double t,
                   const double *y)
{
    trajectory *p = ctx;
    if (p->rows == p->capacity) {
        p->capacity = p->capacity ? 2 * p->capacity : 256;
        p->t = realloc(p->t, sizeof(double) * (size_t)p->capacity);
        p->y = realloc(p->y, sizeof(double) * (size_t)(p->capacity * p->n));
        p->lambda = realloc(p->lambda, sizeof(double) * (size_t)(p->capacity * (p->ncouplers + 1)));
    }
    /* multipliers belong to the last evaluation; evaluate at this state */
    double *ydot = malloc(sizeof(double) * (size_t)p->n);
    hx_dynamics_rhs(d, dd, t, y, ydot);
    free(ydot);
    p->t[p->rows] = t;
    memcpy(p->y + p->rows * p->n, y, sizeof(double) * (size_t)p->n);
    memcpy(p->lambda + p->rows * p->ncouplers, dd->lambda,
           sizeof(double) * (size_t)p->ncouplers);
    p->rows++;
    return 0;
}

void sim_run(sim *s, const char *model, hx_method method, double h, double t_end,
             double output_interval)
{
    memset(s, 0, sizeof *s);
    hx_message msg;
    if (hx_session_open(&s->session, model_path(model), stderr, &msg) != 0)
        fail_msg("%s", msg.text);
    if (hx_dynamics_init(&s->dynamics, &s->session, &msg) != 0 ||
        hx_dynamics_data_init(&s->data, &s->dynamics, &msg) != 0)
        fail_msg("%s", msg.text);
    s->path.n = s->dynamics.n;
    s->path.ncouplers = s->session.model->ncouplers;
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.t_end = t_end;
    if (method == HX_METHOD_DOPRI5) {
        so.integration.rtol = h;
        so.integration.atol = h * 1e-3;
    } else {
        so.integration.step = h;
    }
    so.integration.output_interval = output_interval;
    so.observer = observe;
    so.observer_ctx = &s->path;
    if (hx_simulate(&s->dynamics, &so, NULL, &s->result) != 0)
        fail_msg("simulate %s: %s", model, s->result.message);
}

void sim_evaluate(sim *s, double t, const double *y)
{
    double *ydot = calloc((size_t)s->dynamics.n, sizeof(double));
    assert_non_null(ydot);
    if (hx_dynamics_rhs(&s->dynamics, &s->data, t, y, ydot) != 0)
        fail_msg("%s", s->data.message);
    free(ydot);
}

void sim_close(sim *s)
{
    hx_dynamics_data_free(&s->data);
    hx_dynamics_free(&s->dynamics);
    hx_session_close(&s->session);
    free(s->path.t);
    free(s->path.y);
    free(s->path.lambda);
}

double sim_state(const sim *s, int row, int k)
{
    return s->path.y[row * s->path.n + k];
}

static int joint_body(const sim *s, int joint_id)
{
    const hx_model *m = s->session.model;
    const int j = hx_model_joint(m, joint_id);
    assert_true(j >= 0);
    return m->markers[m->joints[j].i_marker].body;
}

int sim_joint_q(const sim *s, int joint_id)
{
    return s->dynamics.dof[joint_body(s, joint_id)].q;
}

int sim_joint_u(const sim *s, int joint_id)
{
    return s->dynamics.nq + s->dynamics.dof[joint_body(s, joint_id)].u;
}

int sim_check(const char *model)
{
    char *argv[] = {"check", (char *)model_path(model), NULL};
    fflush(stdout);
    return hx_command_check(2, argv);
}

double sim_lambda(const sim *s, int row, int coupler)
{
    return s->path.lambda[row * s->path.ncouplers + coupler];
}

typedef int command_fn(int argc, char **argv);

/* Runs "usrsub-harness NAME MODEL --out CSV ARGS..." in-process. */
static int sim_command(command_fn *command, const char *name, const char *model, const char *csv,
                       const char *const *args)
{
    char *argv[64];
    int argc = 0;
    argv[argc++] = (char *)name;
    argv[argc++] = (char *)model_path(model);
    argv[argc++] = "--out";
    argv[argc++] = (char *)csv;
    for (const char *const *a = args; *a != NULL && argc < 63; ++a)
        argv[argc++] = (char *)*a;
    argv[argc] = NULL;
    fflush(stdout);
    return command(argc, argv);
}

int sim_rig(const char *model, const char *csv, const char *const *args)
{
    return sim_command(hx_command_rig, "rig", model, csv, args);
}

int sim_run_csv(const char *model, const char *csv, const char *const *args)
{
    return sim_command(hx_command_run, "run", model, csv, args);
}

void csv_read(const char *path, csv_table *t)
{
    memset(t, 0, sizeof *t);
    FILE *f = fopen(path, "r");
    if (f == NULL)
        fail_msg("cannot open %s", path);
    char line[8192];
    int capacity = 0;
    if (fgets(line, sizeof line, f) != NULL) /* header */
        for (const char *p = line; *p; ++p)
            t->columns += *p == ',';
    t->columns += 1;
    while (fgets(line, sizeof line, f) != NULL) {
        if (t->rows == capacity) {
            capacity = capacity ? 2 * capacity : 1024;
            t->v = realloc(t->v, sizeof(double) * (size_t)(capacity * t->columns));
        }
        char *p = line;
        for (int c = 0; c < t->columns; ++c) {
            t->v[t->rows * t->columns + c] = strtod(p, &p);
            if (*p == ',')
                ++p;
        }
        t->rows++;
    }
    fclose(f);
}

void host_model_attach(host_model *h, const char *name, const char *xml)
{
    hx_message msg;
    h->model = hx_model_read(test_write_file(name, xml), NULL, &msg);
    if (h->model == NULL)
        fail_msg("%s", msg.text);
    if (hx_frames_init(&h->frames, h->model) != 0)
        fail_msg("out of memory");
    hx_messages_init(&h->messages, stderr);
    hx_call_init(&h->call, "test element", 0, "entry", h->model, &h->frames, &h->messages, 0, NULL);
    hx_host_bind(&h->call);
}

void host_model_detach(host_model *h)
{
    hx_host_unbind();
    hx_messages_destroy(&h->messages);
    hx_frames_free(&h->frames);
    hx_model_free(h->model);
    h->model = NULL;
}

void *load_library(void)
{
    void *library = dlopen(USRSUB_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL)
        fail_msg("%s", dlerror());
    return library;
}

void expect_one_setup_error(const char *model_path, const char *const needles[3])
{
    /* a session's parts by hand, so that its messages can be counted */
    hx_message msg;
    hx_model *m = hx_model_read(model_path, NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    hx_frames state;
    hx_messages messages;
    hx_bindings bindings;
    char start[4096];
    assert_non_null(getcwd(start, sizeof start));
    assert_int_equal(chdir(m->dir), 0); /* relative property files, as a session sees them */
    assert_int_equal(hx_frames_init(&state, m), 0);
    hx_messages_init(&messages, NULL);
    if (hx_bind(m, &messages, &bindings, &msg) != 0)
        fail_msg("%s", msg.text);
    /* the dependency pass reports it and stops the run */
    assert_int_equal(hx_dependency_passes(&bindings, &state), -1);
    assert_int_equal(messages.errors, 1);
    assert_contains(messages.last_error, needles[0], needles[1], needles[2]);
    hx_bindings_free(&bindings);
    hx_messages_destroy(&messages);
    hx_frames_free(&state);
    hx_model_free(m);
    assert_int_equal(chdir(start), 0);
}

int csv_column(const char *path, const char *name)
{
    FILE *f = fopen(path, "r");
    char line[8192];
    int column = -1;
    if (f != NULL && fgets(line, sizeof line, f) != NULL) {
        line[strcspn(line, "\r\n")] = '\0';
        int c = 0;
        for (char *save = NULL, *tok = strtok_r(line, ",", &save); tok != NULL;
             tok = strtok_r(NULL, ",", &save), ++c)
            if (strcmp(tok, name) == 0) {
                column = c;
                break;
            }
    }
    if (f != NULL)
        fclose(f);
    return column;
}

double csv_at(const csv_table *t, int row, int column)
{
    return t->v[row * t->columns + column];
}

void csv_free(csv_table *t)
{
    free(t->v);
    memset(t, 0, sizeof *t);
}

double jacobian_against_differences(const hx_dynamics *d, double t, const double *y,
                                    const char *what, long *outside)
{
    const int n = d->n;
    hx_jacobian nm;
    hx_dynamics_data dd;
    hx_message msg;
    if (hx_jacobian_init(&nm, d, &msg) != 0 || hx_dynamics_data_init(&dd, d, &msg) != 0)
        fail_msg("%s: %s", what, msg.text);
    double *values = calloc((size_t)nm.pattern.nnz + 1, sizeof(double));
    double *A = calloc((size_t)n * (size_t)n, sizeof(double));
    double *D = calloc((size_t)n * (size_t)n, sizeof(double));
    double *shifted = malloc(sizeof(double) * (size_t)n), *up = malloc(sizeof(double) * (size_t)n);
    double *down = malloc(sizeof(double) * (size_t)n);
    unsigned char *in = calloc((size_t)n * (size_t)n, 1);
    assert_non_null(values), assert_non_null(A), assert_non_null(D), assert_non_null(in);
    double *fy = calloc((size_t)n, sizeof(double));
    assert_non_null(fy);
    if (hx_dynamics_rhs(d, &dd, t, y, fy) != 0 || hx_jacobian_build(&nm, t, y, fy, values) != 0)
        fail_msg("%s: %s", what, dd.failed ? dd.message : nm.dd.message);
    free(fy);
    for (int c = 0; c < n; ++c)
        for (int k = nm.pattern.colptr[c]; k < nm.pattern.colptr[c + 1]; ++k) {
            A[(size_t)nm.pattern.rowind[k] + (size_t)n * c] = values[k];
            in[(size_t)nm.pattern.rowind[k] + (size_t)n * c] = 1;
        }
    char described[1024] = "";
    hx_jacobian_describe(&nm, described, sizeof described);
    for (int c = 0; c < n; ++c) {
        const double h = 1e-6 * fmax(1.0, fabs(y[c]));
        for (int side = 0; side < 2; ++side) {
            memcpy(shifted, y, sizeof(double) * (size_t)n);
            shifted[c] += side ? -h : h;
            if (hx_dynamics_rhs(d, &dd, t, shifted, side ? down : up) != 0)
                fail_msg("%s: %s", what, dd.message);
        }
        for (int r = 0; r < n; ++r)
            D[r + (size_t)n * c] = (up[r] - down[r]) / (2.0 * h);
    }
    double worst = 0.0;
    int worst_r = 0, worst_c = 0;
    *outside = nm.outside;
    double largest = 0.0; /* of the whole matrix: a row that is rounding noise (a
                           * slider's vertical acceleration, zero but for the rounding of
                           * the multipliers' solve, 1e-9 by differences) is measured
                           * against 1e-5 of it, not against its own noise */
    for (size_t k = 0; k < (size_t)n * (size_t)n; ++k)
        largest = fmax(largest, fabs(D[k]));
    for (int r = 0; r < n; ++r) {
        if (r == d->load_work || r == d->element_work)
            continue;
        double row = 0.0;
        for (int c = 0; c < n; ++c)
            row = fmax(row, fabs(D[r + (size_t)n * c]));
        /* a row the differences find all zero (a driven joint's) must be
         * zero in the matrix too: measured absolutely */
        const double scale = row > 0.0 ? fmax(row, 1e-5 * largest) : 1.0;
        for (int c = 0; c < n; ++c) {
            const size_t at = r + (size_t)n * c;
            if (!in[at] && fabs(D[at]) > 1e-9 * row) {
                if (*outside < 5)
                    printf("  %s: row %d, column %d is %.6g by differences, outside the sparsity\n",
                           what, r, c, D[at]);
                ++*outside;
            }
            const double e = fabs(A[at] - D[at]) / scale;
            if (e > worst)
                worst = e, worst_r = r, worst_c = c;
        }
    }
    printf("  %s: Jacobian (%d x %d, %d nonzeros) against differences of the whole right-hand"
           " side: largest difference %.2g of its row (row %d, column %d: %.10g against %.10g);"
           " %ld outside the sparsity\n  (%s)\n", what, n, n, nm.pattern.nnz, worst, worst_r,
           worst_c, A[worst_r + (size_t)n * worst_c], D[worst_r + (size_t)n * worst_c], *outside,
           described);
    free(values), free(A), free(D), free(shifted), free(up), free(down), free(in);
    hx_jacobian_free(&nm);
    hx_dynamics_data_free(&dd);
    return worst;
}

hx_model *sim_parse(const char *name, const char *text)
{
    hx_message msg;
    hx_model *m = hx_model_parse(text, strlen(text), name, NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    return m;
}

void sim_expect_parse_error(const char *name, const char *text, const char *const *needles)
{
    hx_message msg;
    hx_model *m = hx_model_parse(text, strlen(text), name, NULL, &msg);
    if (m != NULL) {
        hx_model_free(m);
        fail_msg("%s read", name);
    }
    assert_contains_impl(msg.text, needles, __FILE__, __LINE__);
}

void sim_open_text(sim_opened *o, const char *name, const char *text)
{
    memset(o, 0, sizeof *o);
    hx_message msg;
    if (hx_session_open(&o->s, test_write_file(name, text), stderr, &msg) != 0 ||
        hx_dynamics_init(&o->d, &o->s, &msg) != 0 || hx_dynamics_data_init(&o->dd, &o->d, &msg) != 0)
        fail_msg("%s", msg.text);
}

const char *sim_rk4_refused(const char *name, const char *text, double step, double t_end)
{
    static char message[sizeof((hx_simulation_result *)0)->message];
    sim_opened o;
    sim_open_text(&o, name, text);
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_RK4;
    so.integration.step = step;
    so.integration.t_end = t_end;
    so.integration.output_interval = step;
    hx_simulation_result result;
    assert_int_equal(hx_simulate(&o.d, &so, NULL, &result), -1);
    snprintf(message, sizeof message, "%s", result.message);
    sim_close_opened(&o);
    return message;
}

void sim_close_opened(sim_opened *o)
{
    hx_dynamics_data_free(&o->dd);
    hx_dynamics_free(&o->d);
    hx_session_close(&o->s);
}

double sim_uniform(void)
{
    return 2.0 * rand() / (double)RAND_MAX - 1.0;
}
