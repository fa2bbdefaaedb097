/* Helpers of the tests that open a model, run it and compare states (model_runs.h). */
#include "model_runs.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr/expr.h"
#include "sim/dynamics/accelerations.h"
#include "sim/dynamics/constraint_forces.h"
#include "sim/dynamics/reactions.h"
#include "sim/jacobian/jacobian.h"
#include "sim/dynamics/element_outputs.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

void open_model(model *m, const char *path)
{
    hx_message msg;
    memset(m, 0, sizeof *m);
    if (hx_session_open(&m->session, path, stderr, &msg) != 0 ||
        hx_dynamics_init(&m->d, &m->session, &msg) != 0 ||
        hx_dynamics_data_init(&m->data, &m->d, &msg) != 0)
        fail_msg("%s: %s", path, msg.text);
}

double *model_state(const model *m)
{
    double *y = calloc((size_t)m->d.n, sizeof(double));
    assert_non_null(y);
    return y;
}

void model_initial_state(model *m, double *y)
{
    if (hx_dynamics_initial_state(&m->d, &m->data, y) != 0)
        fail_msg("%s", m->data.message);
}

void close_model(model *m)
{
    hx_dynamics_data_free(&m->data);
    hx_dynamics_free(&m->d);
    hx_session_close(&m->session);
}

/* The model from its initial state to t_end; y receives the end state.
 * atol = rtol * atol_ratio. */
hx_simulation_result simulate_with(model *m, hx_method method, hx_jacobian_method jacobian,
                                   double rtol, double atol_ratio, double t_end, double *y)
{
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.jacobian = jacobian;
    so.integration.rtol = rtol;
    so.integration.atol = rtol * atol_ratio;
    so.integration.t_end = t_end;
    so.integration.output_interval = t_end;
    so.skip_energy = 1;
    hx_simulation_result r;
    hx_simulate(&m->d, &so, y, &r);
    return r;
}

hx_simulation_result simulate(model *m, hx_method method, hx_jacobian_method jacobian,
                              double rtol, double t_end, double *y)
{
    return simulate_with(m, method, jacobian, rtol, 1e-3, t_end, y);
}

double *model_run_text(const char *name, const char *text, hx_method method,
                       hx_jacobian_method jacobian, double rtol, double t_end, model *m)
{
    open_model(m, test_write_file(name, text));
    double *y = model_state(m);
    model_initial_state(m, y);
    hx_simulation_result r = simulate(m, method, jacobian, rtol, t_end, y);
    if (r.status != HX_INTEGRATION_OK)
        fail_msg("%s: %s", name, r.message);
    return y;
}

double model_diff_state(const model *m, const double *y, int id)
{
    const hx_model *mm = m->session.model;
    const int k = hx_model_routine(mm, HX_ROUTINE_DIFF, id);
    assert_true(k >= 0);
    return y[m->d.diff_offset + mm->routines[k].slot];
}

double *model_diffs_jacobian_checked(const char *name, const char *text, const char *what,
                                     int first, int last, model *m)
{
    double *y = model_run_text(name, text, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-9, 0.4, m);
    long outside = 0;
    const double worst = jacobian_against_differences(&m->d, 0.4, y, what, &outside);
    if (outside != 0 || !(worst < 1e-6))
        fail_msg("%s: the Jacobian against differences: worst %.3g, %ld outside its sparsity",
                 what, worst, outside);
    model f;
    double *yf = model_run_text(name, text, HX_METHOD_BDF, HX_JACOBIAN_FD, 1e-9, 0.4, &f);
    for (int id = first; id <= last; ++id)
        assert_close(model_diff_state(m, y, id), model_diff_state(&f, yf, id), 1e-6, 1e-9);
    free(yf);
    close_model(&f);
    return y;
}

/* Largest difference of positions and velocities, relative to the largest
 * of each kind (translations, quaternions, velocities, angular velocities and
 * joint coordinates apart): excursions from y0, and velocities at the end or
 * at the start (a motion that has died away is measured against its start). */
double state_difference(const hx_dynamics *d, const double *a, const double *b, const double *y0)
{
    double worst = 0.0;
    for (int pass = 0; pass < 2; ++pass)
        for (int body = 0; body < d->m->nbodies; ++body) {
            const hx_body_dof *dof = &d->dof[body];
            if (dof->kind == HX_DOF_GROUND)
                continue;
            const int free = dof->kind == HX_DOF_FREE;
            const int groups[4][2] = {{dof->q, free ? 3 : 1},
                                      {dof->q + 3, free ? 4 : 0},
                                      {d->nq + dof->u, free ? 3 : 1},
                                      {d->nq + dof->u + 3, free ? 3 : 0}};
            for (int g = 0; g < 4; ++g) {
                double size = 0.0, diff = 0.0;
                for (int i = groups[g][0]; i < groups[g][0] + groups[g][1]; ++i) {
                    const double base = g == 0 ? y0[i] : 0.0;
                    size = fmax(size, fmax(fabs(a[i] - base), fabs(b[i] - base)));
                    if (g >= 2)
                        size = fmax(size, fabs(y0[i]));
                    diff = fmax(diff, fabs(a[i] - b[i]));
                }
                if (size > 1e-9)
                    worst = fmax(worst, diff / size);
            }
        }
    return worst;
}

int is_model(const struct dirent *e)
{
    const size_t n = strlen(e->d_name);
    return n > 4 && strcmp(e->d_name + n - 4, ".xml") == 0;
}


/* A 1 kg body on the test library's FIESUB: soft, damped translations, and
 * rotations on a stiff overdamped spring (|lambda| near 2e4 1/s), reported
 * partials scaled by `scale`. */
const char *scaled_field_model(const char *name, const char *element)
{
    static char xml[4096];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\""
             " time_unit=\"SECOND\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"100\" inertia_yy=\"100\""
             " inertia_zz=\"100\" v_ic_x=\"100\" v_ic_y=\"-40\" w_ic_z=\"2\" w_ic_x=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\"/>\n%s</Model></MotionSolve>\n", element);
    return test_write_file(name, xml);
}

double *bdf_on(const char *path, double rtol, double t_end, hx_simulation_result *r,
               hx_partials_source *source, char *description)
{
    model m;
    open_model(&m, path);
    double *y = model_state(&m);
    *r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, rtol, t_end, y);
    if (description != NULL)
        snprintf(description, 1024, "%s", r->jacobian);
    if (source != NULL) { /* where the partials came from, after the run */
        hx_jacobian jac;
        hx_message msg;
        assert_int_equal(hx_jacobian_init(&jac, &m.d, &msg), 0);
        double *J = calloc((size_t)jac.pattern.nnz + 1, sizeof(double));
        double *fy = model_state(&m);
        assert_non_null(J);
        assert_int_equal(hx_dynamics_rhs(&m.d, &m.data, t_end, y, fy), 0);
        assert_int_equal(hx_jacobian_build(&jac, t_end, y, fy, J), 0);
        *source = jac.source[0];
        hx_jacobian_free(&jac);
        free(J), free(fy);
    }
    close_model(&m);
    return y;
}


void evaluate_text(evaluated *e, const char *name, const char *text)
{
    evaluate_path(e, test_write_file(name, text));
}

void evaluate_path(evaluated *e, const char *path)
{
    open_model(&e->m, path);
    e->y = model_state(&e->m);
    e->ydot = model_state(&e->m);
    model_initial_state(&e->m, e->y);
    if (hx_dynamics_rhs(&e->m.d, &e->m.data, 0.0, e->y, e->ydot) != 0)
        fail_msg("%s", e->m.data.message);
    const hx_model *m = e->m.session.model;
    e->r = calloc(6 * (size_t)m->njoints + 1, sizeof(double));
    e->a = calloc(6 * (size_t)m->nbodies, sizeof(double));
    e->loads = calloc(12 * (size_t)m->nloads + 1, sizeof(double));
    e->forces = calloc(12 * (size_t)m->nforces + 1, sizeof(double));
    assert_non_null(e->r);
    assert_non_null(e->a);
    assert_non_null(e->loads);
    assert_non_null(e->forces);
    hx_reactions_all(&e->m.d, &e->m.data, e->ydot, e->r);
    hx_accelerations_bodies(&e->m.d, &e->m.data, e->ydot, e->a);
    hx_message msg;
    if (hx_element_outputs_loads(&e->m.d, &e->m.data, e->loads, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_element_outputs_forces(&e->m.d, &e->m.data, e->forces);
    e->constraints = calloc(hx_constraint_forces_size(&e->m.d) + 1, sizeof(double));
    assert_non_null(e->constraints);
    if (hx_constraint_forces_all(&e->m.d, &e->m.data, 0.0, e->y, e->ydot, e->constraints) != 0)
        fail_msg("%s", e->m.data.message);
    e->outputs.reactions = e->r, e->outputs.accelerations = e->a;
    e->outputs.loads = e->loads, e->outputs.forces = e->forces;
    e->outputs.constraints = e->constraints;
}

void release(evaluated *e)
{
    free(e->y), free(e->ydot), free(e->r), free(e->a), free(e->loads), free(e->forces);
    free(e->constraints);
    close_model(&e->m);
}

double output(const evaluated *e, const char *text)
{
    hx_message msg;
    hx_expr_program *p = hx_expr_parse(text, strlen(text), NULL, &msg);
    if (p == NULL || hx_expr_link_output(p, e->m.session.model, &msg) != 0)
        fail_msg("%s: %s", text, msg.text);
    const hx_expr_context c = {&e->m.data.frames, NULL, &e->outputs};
    double value;
    hx_expr_fault fault;
    if (hx_expr_eval(p, &c, &value, &fault) != 0)
        fail_msg("%s: fault %s %s", text, fault.function, fault.what);
    hx_expr_free(p);
    return value;
}

void expect_read_errors(const char *name, const char *head, const char *const (*cases)[3],
                        size_t count)
{
    for (size_t k = 0; k < count; ++k) {
        char text[2048];
        snprintf(text, sizeof text, "%s%s\nEND\n", head, cases[k][0]);
        hx_message msg;
        hx_model *m = hx_model_parse(text, strlen(text), name, NULL, &msg);
        if (m != NULL)
            fail_msg("read: %s", cases[k][0]);
        assert_contains(msg.text, cases[k][1], cases[k][2]);
    }
}

void expect_xml_errors(const char *element, const char *const (*cases)[2], size_t count)
{
    for (size_t k = 0; k < count; ++k) {
        char text[2048];
        snprintf(text, sizeof text,
                 "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
                 "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
                 "%s %s/>\n</Model></MotionSolve>\n",
                 element, cases[k][0]);
        hx_message msg;
        if (hx_model_parse(text, strlen(text), "bad.xml", NULL, &msg) != NULL)
            fail_msg("read: %s", cases[k][0]);
        assert_contains(msg.text, "bad.xml:4:", cases[k][1]);
    }
}

void expect_sides(const evaluated *e, const char *name, int id, int jmarker, const double f[6],
                  const double L[3], const double RJ[9], double tol)
{
    char text[64];
    for (int k = 0; k < 3; ++k) {
        snprintf(text, sizeof text, "%s(%d,0,%d,%d)", name, id, k + 2, jmarker);
        EXPECT(e, text, f[k], tol);
        snprintf(text, sizeof text, "%s(%d,0,%d,%d)", name, id, k + 6, jmarker);
        EXPECT(e, text, f[3 + k], tol);
    }
    const double TJ[3] = {-f[3] - (L[1] * f[2] - L[2] * f[1]), -f[4] - (L[2] * f[0] - L[0] * f[2]),
                          -f[5] - (L[0] * f[1] - L[1] * f[0])};
    for (int k = 0; k < 3; ++k) {
        snprintf(text, sizeof text, "%s(%d,1,%d,%d)", name, id, k + 2, jmarker);
        EXPECT(e, text, -f[k], tol);
        snprintf(text, sizeof text, "%s(%d,1,%d,%d)", name, id, k + 6, jmarker);
        EXPECT(e, text, TJ[k], tol);
    }
    for (int k = 0; k < 3; ++k) { /* in the world's axes */
        snprintf(text, sizeof text, "%s(%d,0,%d,0)", name, id, k + 2);
        EXPECT(e, text, RJ[3 * k] * f[0] + RJ[3 * k + 1] * f[1] + RJ[3 * k + 2] * f[2], tol);
    }
}

/* a in the axes R's columns are (R^T a). */
static void in_axes(const double R[9], const double a[3], double out[3])
{
    for (int i = 0; i < 3; ++i)
        out[i] = R[i] * a[0] + R[3 + i] * a[1] + R[6 + i] * a[2];
}

void marker_motion(const evaluated *e, int i, int j, double L[3], double angles[3], double v[6],
                   double RJ[9])
{
    const hx_model *m = e->m.session.model;
    hx_frame si, sj;
    const hx_frame *I = hx_frames_marker(&e->m.data.frames, hx_model_marker(m, i), &si);
    const hx_frame *J = hx_frames_marker(&e->m.data.frames, hx_model_marker(m, j), &sj);
    double dp[3], dv[3], dw[3];
    for (int k = 0; k < 3; ++k)
        dp[k] = I->p[k] - J->p[k], dw[k] = I->w[k] - J->w[k];
    for (int k = 0; k < 3; ++k)
        dv[k] = I->v[k] - J->v[k] - (J->w[(k + 1) % 3] * dp[(k + 2) % 3] -
                                     J->w[(k + 2) % 3] * dp[(k + 1) % 3]);
    in_axes(J->R, dp, L);
    in_axes(J->R, dv, v);
    in_axes(J->R, dw, v + 3);
    memcpy(RJ, J->R, 9 * sizeof *RJ);
    static const char *const names[3] = {"AX", "AY", "AZ"};
    for (int k = 0; k < 3; ++k) {
        char text[48];
        snprintf(text, sizeof text, "%s(%d,%d)", names[k], i, j);
        angles[k] = output(e, text);
    }
}
