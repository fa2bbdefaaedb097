/*
 * The implicit integrator (BDF through CVODE) and its Newton matrix from the
 * elements' own partials: the matrix against differences of the whole
 * right-hand side, entry by entry; BDF's order of convergence on a closed
 * form; a deliberately wrong partial that must cost Newton iterations (or
 * steps) but not change the trajectory; a GFOSUB twin that disagrees with its
 * element being set aside; BDF's agreement with DOPRI5 on every bundled model
 * (couplers held by the projection); run with bdf on every model, and its
 * advice on stiff models; the integrators' norm against SUNDIALS' own.
 */
#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cmd/commands.h"
#include "sim/dynamics/element_probe.h"
#include "sim/dynamics/energy.h"
#include "sim/newton/newton_matrix.h"
#include "sim/ode/column_groups.h"
#include "sim_support.h"
#include "test_support.h"
#include "tools/bench/linear_reference.h"

typedef struct model {
    hx_session session;
    hx_dynamics d;
} model;

static void open_model(model *m, const char *path)
{
    hx_message msg;
    memset(m, 0, sizeof *m);
    if (hx_session_open(&m->session, path, stderr, &msg) != 0 ||
        hx_dynamics_init(&m->d, &m->session, &msg) != 0)
        fail_msg("%s: %s", path, msg.text);
}

static void close_model(model *m)
{
    hx_dynamics_free(&m->d);
    hx_session_close(&m->session);
}

/* The model from its initial state to t_end; y receives the end state.
 * atol = rtol * atol_ratio. */
static hx_simulation_result simulate_with(model *m, hx_method method, hx_jacobian jacobian,
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

static hx_simulation_result simulate(model *m, hx_method method, hx_jacobian jacobian,
                                     double rtol, double t_end, double *y)
{
    return simulate_with(m, method, jacobian, rtol, 1e-3, t_end, y);
}

/* Largest difference of positions and velocities, relative to the largest
 * of each kind (translations, quaternions, velocities, angular velocities and
 * joint coordinates apart): excursions from y0, and velocities at the end or
 * at the start (a motion that has died away is measured against its start). */
static double state_difference(const hx_dynamics *d, const double *a, const double *b,
                               const double *y0)
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

static int is_model(const struct dirent *e)
{
    const size_t n = strlen(e->d_name);
    return n > 4 && strcmp(e->d_name + n - 4, ".xml") == 0;
}

/* ---- the Newton matrix against differences of the whole right-hand side ------------ */

static void compare_jacobians(model *m, double t, const double *y, const char *what,
                              hx_partials_source expected)
{
    hx_newton_matrix nm;
    hx_message msg;
    assert_int_equal(hx_newton_matrix_init(&nm, &m->d, &msg), 0);
    for (int k = 0; k < nm.nf; ++k)
        assert_int_equal(nm.source[k], expected);
    hx_newton_matrix_free(&nm);
    long outside = 0;
    const double worst = newton_matrix_against_differences(&m->d, t, y, what, &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
}

/* The Newton matrix of a model after t_end of DOPRI5, against differences,
 * every force element's partials from the expected source. */
static void jacobian_after(const char *path, double t_end, const char *what,
                           hx_partials_source expected)
{
    model m;
    open_model(&m, path);
    double y[64];
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, t_end, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    compare_jacobians(&m, t_end, y, what, expected);
    close_model(&m);
}

/* Rolled by the engine torque, mounts in their limits. */
static void newton_matrix_equals_differences_on_the_powertrain(void **state)
{
    (void)state;
    jacobian_after(EXAMPLES_DIR "/powertrain.xml", 0.6, "powertrain.xml at t = 0.6 s",
                   HX_PARTIALS_TWIN);
}

/* A third party's FIESUB that fills dfddis only when dflag is set and never
 * writes dfdvel (tests/user_libraries/tp_habits_field.c): the Newton matrix
 * asks for them so, and equals the differences. */
static void newton_matrix_asks_a_field_for_its_partials(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    jacobian_after(USER_LIBRARIES_DIR "/tp_habits_field.xml", 0.01,
                   "tp_habits_field.xml at t = 0.01 s", HX_PARTIALS_FIESUB);
}

/* A Control_Diff's row (DIFSUB differenced in what it reads) and a driven
 * joint's rows (zero: a function of time) (tests/user_libraries/tp_routines.c);
 * the OneBody force's partials by differences of the element alone. */
static void newton_matrix_has_the_routines_rows(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    jacobian_after(USER_LIBRARIES_DIR "/tp_routines.xml", 0.02, "tp_routines.xml at t = 0.02 s",
                   HX_PARTIALS_DIFFERENCES);
}

/* Elements with partials on jointed bodies: a revolute and a slider body
 * (one coordinate each) joined to each other both ways, a free body's I on
 * the revolute's J, an I on ground; then a GFOSUB twin with I on the slider
 * and J (its axes) on the revolute. Every body kind on either side of an
 * element, against differences. */
static const char jointed_model[] =
    "<MotionSolve><Model>\n"
    "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\""
    " time_unit=\"SECOND\"/>\n"
    "<Reference_String id=\"401\" string=\"%s/flex_coupled.gfj\"/>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Reference_Marker id=\"10\" body_id=\"1\" pos_x=\"5\" pos_y=\"3\" a00=\"0.8\" a01=\"-0.6\""
    " a02=\"0\" a10=\"0.6\" a11=\"0.8\" a12=\"0\" a20=\"0\" a21=\"0\" a22=\"1\"/>\n"
    "<Reference_Marker id=\"11\" body_id=\"1\" pos_y=\"40\" a00=\"0\" a10=\"1\" a20=\"0\""
    " a01=\"0\" a11=\"0\" a21=\"1\" a02=\"1\" a12=\"0\" a22=\"0\"/>\n"
    "<Reference_Marker id=\"12\" body_id=\"1\" pos_x=\"2\" pos_z=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"2000\" inertia_yy=\"2500\""
    " inertia_zz=\"3000\" w_ic_z=\"2\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"40\" pos_y=\"-30\" pos_z=\"3\"/>\n"
    "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"5\" pos_y=\"3\" a00=\"0.8\" a01=\"-0.6\""
    " a02=\"0\" a10=\"0.6\" a11=\"0.8\" a12=\"0\" a20=\"0\" a21=\"0\" a22=\"1\"/>\n"
    "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"30\" pos_y=\"20\" pos_z=\"2\"/>\n"
    "<Reference_Marker id=\"23\" body_id=\"2\" pos_x=\"-20\" pos_y=\"10\" pos_z=\"-2\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"4\" inertia_xx=\"800\" inertia_yy=\"1000\""
    " inertia_zz=\"1200\" v_ic_z=\"30\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"10\" pos_y=\"40\" pos_z=\"4\"/>\n"
    "<Reference_Marker id=\"31\" body_id=\"3\" pos_y=\"40\" a00=\"0\" a10=\"1\" a20=\"0\""
    " a01=\"0\" a11=\"0\" a21=\"1\" a02=\"1\" a12=\"0\" a22=\"0\"/>\n"
    "<Reference_Marker id=\"32\" body_id=\"3\" pos_x=\"31\" pos_y=\"20.5\" pos_z=\"2.3\"/>\n"
    "<Reference_Marker id=\"33\" body_id=\"3\" pos_x=\"-19\" pos_y=\"10.5\" pos_z=\"-1.5\"/>\n"
    "<Body_Rigid id=\"4\" cg_id=\"40\" mass=\"3\" inertia_xx=\"3000\" inertia_yy=\"4000\""
    " inertia_zz=\"5000\" v_ic_x=\"5\" v_ic_y=\"-3\" v_ic_z=\"2\" w_ic_x=\"0.2\""
    " w_ic_y=\"-0.3\" w_ic_z=\"0.25\"/>\n"
    "<Reference_Marker id=\"40\" body_id=\"4\" pos_x=\"30\" pos_y=\"21\" pos_z=\"1.5\"/>\n"
    "<Reference_Marker id=\"41\" body_id=\"4\" pos_x=\"30.8\" pos_y=\"20.5\" pos_z=\"2.3\""
    " a00=\"0.998300856485\" a01=\"-0.051137192285\" a02=\"-0.027935416720\""
    " a10=\"0.049956680331\" a11=\"0.997891416697\" a12=\"-0.041437308954\""
    " a20=\"0.029995500202\" a21=\"0.039971340336\" a22=\"0.998750500335\"/>\n"
    "<Reference_Marker id=\"42\" body_id=\"4\" pos_x=\"2.5\" pos_y=\"0.4\" pos_z=\"1.2\"/>\n"
    "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
    "<Constraint_Joint id=\"2\" type=\"TRANSLATIONAL\" i_marker_id=\"31\" j_marker_id=\"11\"/>\n"
    "%s</Model></MotionSolve>\n";

static void newton_matrix_on_jointed_bodies_with_partials(void **state)
{
    (void)state;
    static const char fields[] =
        "<Force_Field id=\"1\" i_marker_id=\"22\" j_marker_id=\"32\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
        "<Force_Field id=\"2\" i_marker_id=\"33\" j_marker_id=\"23\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
        "<Force_Field id=\"3\" i_marker_id=\"41\" j_marker_id=\"22\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n"
        "<Force_Field id=\"4\" i_marker_id=\"12\" j_marker_id=\"42\""
        " usrsub_param_string=\"USER(3, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n";
    static const char twin[] =
        "<Force_Vector_TwoBody id=\"11\" type=\"ForceAndTorque\" i_marker_id=\"32\""
        " j_floating_marker_id=\"22\" ref_marker_id=\"22\""
        " usrsub_param_string=\"USER(3, 32, 22, 401)\" usrsub_dll_name=\"libusrsub.so\"/>\n";
    static char text[8192];
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1); /* libusrsub.so is built there too */
    snprintf(text, sizeof text, jointed_model, EXAMPLES_DIR, fields);
    jacobian_after(test_write_file("jointed_fields.xml", text), 0.05,
                   "jointed bodies, four Force_Fields, at t = 0.05 s", HX_PARTIALS_FIESUB);
    snprintf(text, sizeof text, jointed_model, EXAMPLES_DIR, twin);
    jacobian_after(test_write_file("jointed_twin.xml", text), 0.05,
                   "jointed bodies, a GFOSUB twin, at t = 0.05 s", HX_PARTIALS_TWIN);
}

/* The y of a model with Force_StateEqn states, a Control_Diff state after
 * them and loads (suspension_bushing.xml with tp_routines.c's LAG on the arm's
 * angle): every block where the layout puts it, against differences, during
 * the torque ramp. */
static void newton_matrix_with_state_equations_diffs_and_loads(void **state)
{
    (void)state;
    FILE *f = fopen(EXAMPLES_DIR "/suspension_bushing.xml", "r");
    assert_non_null(f);
    static char text[16384], changed[17408];
    const size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    /* the property files by absolute path: the variant is written elsewhere */
    const char *gbs = strstr(text, "string=\"suspension_bushing.gbs\"");
    const char *gbi = strstr(text, "string=\"suspension_bushing.gbi\"");
    const char *end = strstr(text, "</Model>");
    assert_true(gbs != NULL && gbi != NULL && end != NULL && gbs < gbi && gbi < end);
    const int key = (int)strlen("string=\"suspension_bushing.gbs\"");
    snprintf(changed, sizeof changed,
             "%.*sstring=\"%s/suspension_bushing.gbs\"%.*sstring=\"%s/suspension_bushing.gbi\""
             "%.*s<Control_Diff id=\"7\" type=\"USERSUB\" ic=\"0.01\""
             " usrsub_param_string=\"USER(20, 10, 0.01)\" usrsub_fnc_name=\"LAG\""
             " usrsub_dll_name=\"libtp_routines.so\"/>\n%s",
             (int)(gbs - text), text, EXAMPLES_DIR, (int)(gbi - gbs) - key, gbs + key,
             EXAMPLES_DIR, (int)(end - gbi) - key, gbi + key, end);
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    jacobian_after(test_write_file("bushing_and_diff.xml", changed), 0.2,
                   "suspension_bushing.xml with a Control_Diff at t = 0.2 s",
                   HX_PARTIALS_FIESUB /* no force elements */);
}

/* Every bundled model the harness simulates, at a state it reaches (0.05 s
 * of DOPRI5 from the start: loads on, elements deformed), and chains of
 * bodies from scripts/chain_model.sh: the assembled matrix equals the
 * differences entry by entry, and no nonzero lies outside its sparsity. */
static void newton_matrix_equals_differences_on_every_model(void **state)
{
    (void)state;
    struct dirent **names;
    const int count = scandir(EXAMPLES_DIR, &names, is_model, alphasort);
    assert_true(count > 10);
    char paths[64][1024];
    int npaths = 0;
    for (int k = 0; k < count; ++k) {
        if (npaths < 60)
            snprintf(paths[npaths++], sizeof paths[0], "%s/%s", EXAMPLES_DIR, names[k]->d_name);
        free(names[k]);
    }
    free(names);
    static const int links[] = {2, 5};
    for (int k = 0; k < 2; ++k) {
        char command[2048];
        snprintf(paths[npaths], sizeof paths[0], "%s/chain_%d.xml", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp", links[k]);
        snprintf(command, sizeof command, "sh %s/chain_model.sh %d %s", SCRIPTS_DIR, links[k],
                 paths[npaths]);
        assert_int_equal(system(command), 0);
        ++npaths;
    }
    int compared = 0;
    for (int k = 0; k < npaths; ++k) {
        hx_session session;
        hx_dynamics d;
        hx_message msg;
        if (hx_session_open(&session, paths[k], stderr, &msg) != 0)
            fail_msg("%s: %s", paths[k], msg.text);
        if (hx_dynamics_init(&d, &session, &msg) != 0) { /* not simulated: check-only models */
            hx_dynamics_free(&d);
            hx_session_close(&session);
            continue;
        }
        model m = {session, d};
        double *y = calloc((size_t)m.d.n, sizeof(double));
        hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, 0.05, y);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        const char *name = strrchr(paths[k], '/') + 1;
        long outside = 0;
        const double worst = newton_matrix_against_differences(&m.d, 0.05, y, name, &outside);
        assert_int_equal(outside, 0);
        if (worst >= 1e-6)
            fail_msg("%s: the Newton matrix differs from differences by %.2g of a row", name, worst);
        compared++;
        free(y);
        hx_dynamics_free(&m.d);
        hx_session_close(&m.session);
    }
    printf("%d models compared\n", compared);
    assert_true(compared >= 20);
}

/* Differences by column groups (what --jacobian fd uses) on a chain: no two
 * columns of a group share a row of the sparsity, there are far fewer
 * groups than columns, and the grouped matrix equals the matrix of the same
 * differences taken one column at a time. */
static int rhs_of(void *ctx, double t, const double *y, double *ydot)
{
    return hx_dynamics_rhs(ctx, t, y, ydot);
}

static void differences_by_column_groups_equal_them_column_by_column(void **state)
{
    (void)state;
    char path[1024], command[2048];
    snprintf(path, sizeof path, "%s/chain_12.xml", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
    snprintf(command, sizeof command, "sh %s/chain_model.sh 12 %s", SCRIPTS_DIR, path);
    assert_int_equal(system(command), 0);
    model m;
    open_model(&m, path);
    const int n = m.d.n;
    double *y = calloc((size_t)n, sizeof(double)), *fy = calloc((size_t)n, sizeof(double));
    double *h = calloc((size_t)n, sizeof(double)), *work = calloc(2 * (size_t)n, sizeof(double));
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-8, 0.05, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    hx_newton_matrix nm;
    hx_message msg;
    assert_int_equal(hx_newton_matrix_init(&nm, &m.d, &msg), 0);
    const hx_sparsity *sp = &nm.pattern;
    hx_column_groups g;
    assert_int_equal(hx_column_groups_build(&g, sp), 0);
    /* no row shared inside a group */
    int *owner = malloc(sizeof(int) * (size_t)n);
    for (int k = 0; k < g.count; ++k) {
        for (int i = 0; i < n; ++i)
            owner[i] = -1;
        for (int j = g.start[k]; j < g.start[k + 1]; ++j)
            for (int p = sp->colptr[g.columns[j]]; p < sp->colptr[g.columns[j] + 1]; ++p) {
                assert_int_equal(owner[sp->rowind[p]], -1);
                owner[sp->rowind[p]] = g.columns[j];
            }
    }
    printf("chain of 12 bodies: %d states, %d nonzeros, %d column groups\n", n, sp->nnz, g.count);
    assert_true(g.count < n / 3);
    double *grouped = calloc((size_t)sp->nnz, sizeof(double));
    double *single = calloc((size_t)sp->nnz, sizeof(double));
    for (int i = 0; i < n; ++i)
        h[i] = 1e-7 * fmax(1.0, fabs(y[i]));
    assert_int_equal(hx_dynamics_rhs(&m.d, 0.05, y, fy), 0);
    assert_int_equal(hx_grouped_differences(&g, sp, rhs_of, &m.d, 0.05, y, fy, h, m.d.load_work, grouped, work), 0);
    hx_column_groups one = {n, malloc(sizeof(int) * (size_t)(n + 1)), malloc(sizeof(int) * (size_t)n)};
    for (int i = 0; i <= n; ++i)
        one.start[i] = i;
    for (int i = 0; i < n; ++i)
        one.columns[i] = i;
    assert_int_equal(hx_grouped_differences(&one, sp, rhs_of, &m.d, 0.05, y, fy, h, m.d.load_work, single, work), 0);
    /* against each row's largest entry (rows mix units); a column counted in
     * another's row would be wrong by the size of its entry */
    double *row = calloc((size_t)n, sizeof(double)), worst = 0.0;
    for (int p = 0; p < sp->nnz; ++p)
        row[sp->rowind[p]] = fmax(row[sp->rowind[p]], fabs(single[p]));
    for (int p = 0; p < sp->nnz; ++p)
        worst = fmax(worst, row[sp->rowind[p]] > 0.0
                                ? fabs(grouped[p] - single[p]) / row[sp->rowind[p]]
                                : fabs(grouped[p]));
    printf("  grouped against column by column: largest difference %.2g of its row\n", worst);
    assert_true(worst <= 1e-6);
    free(row);
    hx_column_groups_free(&one);
    hx_column_groups_free(&g);
    hx_newton_matrix_free(&nm);
    free(owner), free(grouped), free(single), free(y), free(fy), free(h), free(work);
    close_model(&m);
}

/* ---- order of convergence on a closed form ------------------------------------------ */

/* BDF of highest order q on damped_oscillator.xml to t = 0.02 s (a period)
 * at one tolerance: its steps and its error against the closed form. */
static double bdf_error(int order, double rtol, long *steps, int *last_order)
{
    model m;
    open_model(&m, EXAMPLES_DIR "/damped_oscillator.xml");
    hx_linear_reference ref;
    hx_message msg;
    if (hx_linear_reference_build(&m.d, &ref, &msg) != 0)
        fail_msg("%s", msg.text);
    const double t_end = 0.02;
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_BDF;
    so.integration.max_order = order;
    so.integration.rtol = rtol;
    so.integration.atol = rtol * 1e-3;
    so.integration.t_end = t_end;
    so.integration.output_interval = t_end;
    so.skip_energy = 1;
    double y[64], yref[64];
    hx_simulation_result r;
    assert_int_equal(hx_simulate(&m.d, &so, y, &r), 0);
    *steps = r.stats.steps;
    *last_order = r.stats.last_order;
    memcpy(yref, ref.y0, sizeof(double) * (size_t)m.d.n);
    hx_linear_reference_state(&ref, t_end, yref);
    const double e = state_difference(&m.d, y, yref, ref.y0);
    hx_linear_reference_free(&ref);
    close_model(&m);
    return e;
}

/* CVODE holds no order fixed (it starts at order 1 and takes, up to q, the
 * order that allows the longest step) and fails its error test when its
 * step may not shrink, so the order is measured as the adaptive method
 * converges: error against steps over five tolerances, the slope of their
 * least-squares line in log-log is the order (an error ratio of 2^q per
 * halving of the mean step). */
static void bdf_converges_at_its_order(void **state)
{
    (void)state;
    for (int q = 1; q <= 5; ++q) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        const int points = 5;
        printf("BDF up to order %d:", q);
        for (int k = 0; k < points; ++k) {
            const double rtol = pow(10.0, -(q < 3 ? 2 * q : q + 2) - k);
            long steps;
            int last;
            const double e = bdf_error(q, rtol, &steps, &last);
            assert_int_equal(last, q);
            printf(" %ld steps: %.3g;", steps, e);
            const double x = log((double)steps), yv = log(e);
            sx += x, sy += yv, sxx += x * x, sxy += x * yv;
        }
        const double slope = -(points * sxy - sx * sy) / (points * sxx - sx * sx);
        printf(" order %.2f (error ratio per halving %.3g; 2^q = %d)\n", slope, pow(2.0, slope),
               1 << q);
        assert_true(fabs(slope - q) < 0.35 + 0.1 * q);
    }
}

/* ---- a wrong partial costs iterations, not accuracy ----------------------------------- */

/* A 1 kg body on the test library's FIESUB: soft, damped translations, and
 * rotations on a stiff overdamped spring (|lambda| near 2e4 1/s), reported
 * partials scaled by `scale`. */
static const char *scaled_field_model(const char *name, const char *element)
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

static hx_simulation_result bdf_on(const char *path, double rtol, double t_end, double *y,
                                   hx_partials_source *source, char *description)
{
    model m;
    open_model(&m, path);
    hx_simulation_result r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, rtol, t_end, y);
    if (description != NULL)
        snprintf(description, 1024, "%s", r.newton_matrix);
    if (source != NULL) { /* where the partials came from, after the run */
        hx_newton_matrix nm;
        hx_message msg;
        assert_int_equal(hx_newton_matrix_init(&nm, &m.d, &msg), 0);
        double J[15 * 15];
        assert_int_equal(hx_newton_matrix_build(&nm, t_end, y, J), 0);
        *source = nm.source[0];
        hx_newton_matrix_free(&nm);
    }
    close_model(&m);
    return r;
}

static void a_wrong_partial_costs_newton_iterations_not_accuracy(void **state)
{
    (void)state;
    static const double scales[] = {1.0, 3.0, 0.3};
    double y_right[64], y[64];
    hx_simulation_result right = {0};
    for (int k = 0; k < 3; ++k) {
        char element[512], name[64];
        snprintf(element, sizeof element,
                 "<Force_Field id=\"1\" i_marker_id=\"20\" j_marker_id=\"10\""
                 " usrsub_param_string=\"USER(100, 0.2, 1e6, 2000, %g)\" usrsub_dll_name=\""
                 SCALED_FIELD_LIBRARY "\"/>\n", scales[k]);
        snprintf(name, sizeof name, "scaled_field_%d.xml", k);
        const char *path = scaled_field_model(name, element);
        hx_simulation_result r = bdf_on(path, 1e-8, 0.2, k == 0 ? y_right : y, NULL, NULL);
        const hx_integrator_stats *st = &r.stats;
        printf("partials scaled by %g: %s, %ld steps, %.2f Newton iterations per step, %ld"
               " convergence failures, %ld Jacobians\n", scales[k], hx_status_text(r.status),
               st->steps, (double)st->newton_iterations / (double)st->steps,
               st->convergence_failures, st->jacobians);
        if (k == 0) {
            assert_int_equal(r.status, HX_INTEGRATION_OK);
            right = r;
            continue;
        }
        /* the wrong matrix costs: more iterations a step, or failed iterations
         * and more steps */
        const double per_step = (double)st->newton_iterations / (double)st->steps;
        const double right_per_step = (double)right.stats.newton_iterations /
                                      (double)right.stats.steps;
        assert_true(r.status != HX_INTEGRATION_OK || per_step > 1.25 * right_per_step ||
                    st->convergence_failures > right.stats.convergence_failures + 10);
        /* and where it converges, it converges to the same trajectory */
        if (r.status == HX_INTEGRATION_OK) {
            model m;
            open_model(&m, path);
            double y0[64];
            assert_int_equal(hx_dynamics_initial_state(&m.d, y0), 0);
            const double diff = state_difference(&m.d, y, y_right, y0);
            printf("  end state against the exact partials' run: %.2g\n", diff);
            assert_true(diff < 1e-6);
            close_model(&m);
        }
    }
}

/* A FIESUB whose partials hold a NaN: the run stops with an error naming the
 * element and its partials, none of them in the Newton matrix. */
static void non_finite_partials_stop_the_run_with_their_element(void **state)
{
    (void)state;
    const char *path = scaled_field_model(
        "nan_partials.xml", "<Force_Field id=\"7\" i_marker_id=\"20\" j_marker_id=\"10\""
                            " usrsub_param_string=\"USER(100, 0.2, 1e6, 2000, 1, 1)\""
                            " usrsub_dll_name=\"" SCALED_FIELD_LIBRARY "\"/>\n");
    model m;
    open_model(&m, path);
    double y[64];
    hx_simulation_result r = simulate(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-6, 0.1, y);
    printf("%s: %s\n", hx_status_text(r.status), r.message);
    assert_int_not_equal(r.status, HX_INTEGRATION_OK);
    assert_contains(r.message, "Force_Field 7 returned non-finite partials");
    close_model(&m);
}

/* A GFOSUB element whose FIESUB twin agrees is linearized by the twin; one
 * whose twin does not is set aside for differences of the element alone, and
 * BDF still runs right. */
static void a_twin_that_disagrees_is_set_aside(void **state)
{
    (void)state;
    double y_twin[64], y_alone[64];
    static const double scales[2] = {1.0, 2.0};
    hx_partials_source source[2];
    char description[2][1024], first[512] = "";
    for (int k = 0; k < 2; ++k) {
        char element[512], name[64];
        snprintf(element, sizeof element,
                 "<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"20\""
                 " j_floating_marker_id=\"10\" ref_marker_id=\"10\" usrsub_param_string=\"USER(20,"
                 " 10, 100, 0.2, 1e6, 2000, %g)\" usrsub_fnc_name=\"SCALED_SPRING\""
                 " usrsub_dll_name=\"" SCALED_FIELD_LIBRARY "\"/>\n", scales[k]);
        snprintf(name, sizeof name, "scaled_spring_%d.xml", k);
        const char *path = scaled_field_model(name, element);
        if (k == 0)
            snprintf(first, sizeof first, "%s", path);
        hx_simulation_result r = bdf_on(path, 1e-8, 0.2, k == 0 ? y_twin : y_alone, &source[k],
                                        description[k]);
        assert_int_equal(r.status, HX_INTEGRATION_OK);
        printf("twin scaled by %g: %s\n", scales[k], description[k]);
    }
    assert_int_equal(source[0], HX_PARTIALS_TWIN);
    assert_int_equal(source[1], HX_PARTIALS_DIFFERENCES);
    assert_contains(description[1], "SCALED_SPRING_FIELD differs from it");
    model m;
    open_model(&m, first);
    double y0[64];
    assert_int_equal(hx_dynamics_initial_state(&m.d, y0), 0);
    assert_true(state_difference(&m.d, y_twin, y_alone, y0) < 1e-6);
    close_model(&m);
}

/* ---- BDF against DOPRI5 on every bundled model --------------------------------------- */

static void bdf_agrees_with_dopri5_on_every_bundled_model(void **state)
{
    (void)state;
    struct dirent **names;
    const int count = scandir(EXAMPLES_DIR, &names, is_model, alphasort);
    assert_true(count > 10);
    const double t_end = 0.05, rtol = 1e-12;
    int compared = 0;
    for (int k = 0; k < count; ++k) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, names[k]->d_name);
        hx_session session;
        hx_dynamics d;
        hx_message msg;
        if (hx_session_open(&session, path, NULL, &msg) != 0)
            fail_msg("%s: %s", names[k]->d_name, msg.text);
        if (hx_dynamics_init(&d, &session, &msg) != 0 || d.nq + d.nu == 0) {
            printf("%-28s no dynamics to integrate (rig or check only)\n", names[k]->d_name);
            if (d.dof != NULL)
                hx_dynamics_free(&d);
            hx_session_close(&session);
            free(names[k]);
            continue;
        }
        const int states = d.n;
        hx_dynamics_free(&d);
        hx_session_close(&session);
        if (states > 100) { /* full_vehicle.xml: 1e-12 takes it ~70 000 steps; its Newton
                             * matrix is compared above */
            printf("%-28s %d states: left to the Newton matrix's comparison\n",
                   names[k]->d_name, states);
            free(names[k]);
            continue;
        }
        model m;
        open_model(&m, path);
        double *y0 = calloc(3 * (size_t)m.d.n, sizeof(double)), *a = y0 + m.d.n, *b = a + m.d.n;
        assert_non_null(y0);
        assert_int_equal(hx_dynamics_initial_state(&m.d, y0), 0);
        /* atol = rtol: 1e-12 mm, mm/s, rad (tighter drowns the stiff models' error
         * estimates in rounding) */
        hx_simulation_result ra =
            simulate_with(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, rtol * 0.1, 1.0, t_end, a);
        hx_simulation_result rb =
            simulate_with(&m, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, rtol, 1.0, t_end, b);
        const double diff = state_difference(&m.d, a, b, y0);
        printf("%-28s BDF (%ld steps, %.3f s) against DOPRI5 (%ld steps) at t = %g: %.2g\n",
               names[k]->d_name, rb.stats.steps, rb.seconds, ra.stats.steps, t_end, diff);
        assert_int_equal(ra.status, HX_INTEGRATION_OK);
        assert_int_equal(rb.status, HX_INTEGRATION_OK);
        assert_true(diff < 1e-8);
        /* couplers: CVODE's projection keeps phi = 0 as DOPRI5's does */
        assert_true(rb.max_phi < 1e-12 && rb.max_phidot < 1e-10);
        free(y0);
        close_model(&m);
        free(names[k]);
        compared++;
    }
    free(names);
    assert_true(compared > 10);
}

/* ---- run: bdf on every model, and advice that names the figures ----------------------- */

/* "usrsub-harness run MODEL ARGS..." in-process, its standard output into text. */
static int run_captured(const char *model_path, const char *const *args, char *text, size_t size)
{
    char *argv[32];
    int argc = 0;
    argv[argc++] = "run";
    argv[argc++] = (char *)model_path;
    for (const char *const *a = args; *a != NULL && argc < 31; ++a)
        argv[argc++] = (char *)*a;
    argv[argc] = NULL;
    char path[600];
    snprintf(path, sizeof path, "%s/run_output.txt", test_temp_dir());
    fflush(stdout);
    const int saved = dup(1), fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    assert_true(saved >= 0 && fd >= 0);
    dup2(fd, 1);
    const int status = hx_command_run(argc, argv);
    fflush(stdout);
    dup2(saved, 1);
    close(fd);
    close(saved);
    FILE *f = fopen(path, "r");
    const size_t n = f != NULL ? fread(text, 1, size - 1, f) : 0;
    text[n] = '\0';
    if (f != NULL)
        fclose(f);
    return status;
}

static void run_takes_bdf_on_every_model_and_says_when_it_is_stiff(void **state)
{
    (void)state;
    static char text[16384];
    struct dirent **names;
    const int count = scandir(EXAMPLES_DIR, &names, is_model, alphasort);
    const char *const short_run[] = {"--end", "0.01", "--integrator", "bdf", "--quiet", NULL};
    for (int k = 0; k < count; ++k) {
        char path[1024];
        snprintf(path, sizeof path, "%s/%s", EXAMPLES_DIR, names[k]->d_name);
        const int status = run_captured(path, short_run, text, sizeof text);
        if (status != 0)
            fail_msg("run --integrator bdf %s: exit %d\n%s", names[k]->d_name, status, text);
        assert_contains(text, "finished with bdf", "Newton iterations");
        free(names[k]);
    }
    free(names);
    /* stiff for its run: an explicit method is told why bdf suits it better */
    const char *const explicit_run[] = {"--end", "1.5", "--quiet", "--output-interval", "0.1", NULL};
    assert_int_equal(run_captured(EXAMPLES_DIR "/stiff_powertrain.xml", explicit_run, text,
                                  sizeof text), 0);
    printf("%s", text);
    assert_contains(text, "stiff for this run", "--integrator bdf", "holds dopri5 to steps below");
    /* not stiff: bdf is told that an explicit method is likely cheaper */
    const char *const bdf_run[] = {"--end", "1", "--integrator", "bdf", "--jacobian", "fd",
                                   "--quiet", "--output-interval", "0.1", NULL};
    assert_int_equal(run_captured(EXAMPLES_DIR "/powertrain.xml", bdf_run, text, sizeof text), 0);
    printf("%s", text);
    assert_contains(text, "not stiff for this run", "--integrator dopri5",
                    "differences of the right-hand side in");
    assert_contains(text, "linear solver: dense LU (auto", "column groups", "Newton matrices took");
}

/* KLU's Newton matrix A = I - gamma J, written by the harness in one pass
 * (bdf.c's linear_system), against dense LU's, which CVODE builds itself:
 * on the powertrain the two runs take the same steps, Newton iterations and
 * Jacobians within rounding, and end in the same state. A wrong sign, a
 * missing identity or a Jacobian kept when CVODE asks for a new one shows as
 * Newton iterations and steps. */
static void the_one_pass_newton_matrix_is_cvodes(void **state)
{
    (void)state;
    hx_simulation_result r[2];
    double y[2][64];
    for (int k = 0; k < 2; ++k) {
        model m;
        open_model(&m, EXAMPLES_DIR "/powertrain.xml");
        assert_true(m.d.n <= 64);
        hx_simulation_options so = {0};
        hx_integrator_defaults(&so.integration);
        so.integration.method = HX_METHOD_BDF;
        so.integration.linear_solver = k ? HX_LINEAR_KLU : HX_LINEAR_DENSE;
        so.integration.rtol = 1e-6;
        so.integration.atol = 1e-9;
        so.integration.t_end = so.integration.output_interval = 0.6;
        so.integration.max_steps = 5000; /* five times what it takes: a broken matrix stops */
        so.skip_energy = 1;
        hx_simulate(&m.d, &so, y[k], &r[k]);
        assert_int_equal(r[k].status, HX_INTEGRATION_OK);
        close_model(&m);
    }
    assert_int_equal(r[0].stats.linear_solver, HX_LINEAR_DENSE);
    assert_int_equal(r[1].stats.linear_solver, HX_LINEAR_KLU);
    const hx_integrator_stats *dense = &r[0].stats, *klu = &r[1].stats;
    printf("  powertrain to 0.6 s: dense %ld steps, %ld Newton iterations, %ld Jacobians;"
           " KLU %ld, %ld, %ld\n", dense->steps, dense->newton_iterations, dense->jacobians,
           klu->steps, klu->newton_iterations, klu->jacobians);
    assert_true(labs(klu->steps - dense->steps) <= dense->steps / 20);
    assert_true(labs(klu->newton_iterations - dense->newton_iterations) <=
                dense->newton_iterations / 20);
    assert_true(labs(klu->jacobians - dense->jacobians) <= 2 + dense->jacobians / 10);
    double worst = 0.0;
    for (int i = 0; i < r[0].n; ++i)
        worst = fmax(worst, fabs(y[1][i] - y[0][i]) / (1.0 + fabs(y[0][i])));
    assert_true(worst < 1e-4);
}

/* The elastic energy at every output time, at the size of a full vehicle:
 * one copy of the frames serves all its 73 bushings (each moved GFOSUB body
 * put back), so the energy equals the sum of each element's potential from
 * a fresh copy, and leaves the copy as it found it. A body not put back
 * changes the next elements' potentials. */
static void the_energy_of_every_element_from_one_copy_of_the_frames(void **state)
{
    (void)state;
    model m;
    open_model(&m, EXAMPLES_DIR "/full_vehicle.xml");
    hx_dynamics *d = &m.d;
    double *y = malloc(sizeof(double) * (size_t)d->n);
    assert_non_null(y);
    /* deformed: the bump under the left wheels has begun */
    simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-6, 0.15, y);
    const double t = 0.15;
    const hx_energy e = hx_energy_of(d, t, y);
    assert_int_equal(memcmp(d->probe.bodies, d->frames.bodies,
                            sizeof *d->frames.bodies * (size_t)d->m->nbodies), 0);
    assert_int_equal(memcmp(d->probe.markers, d->frames.markers,
                            sizeof *d->frames.markers * (size_t)d->m->nmarkers), 0);
    double sum = 0.0;
    int gfosub = 0;
    for (int k = 0; k < d->m->nforces; ++k) {
        hx_frames_copy(&d->probe, &d->frames);
        sum += hx_element_potential(d->s, &d->probe, &d->frames, k, t);
        gfosub += hx_binding_of_force(&d->s->bindings, k)->kind != HX_BIND_FIESUB;
    }
    printf("  elastic energy %.10g from one copy, %.10g from a copy each (%d GFOSUB elements)\n",
           e.elastic, sum, gfosub);
    assert_true(gfosub >= 20);
    assert_true(fabs(e.elastic) > 0.0);
    assert_true(e.elastic == sum);
    free(y);
    close_model(&m);
}

/* bushing_mount.xml with each of the replacements (from, to) made once. */
static const char *mount_variant(const char *name, const char *const *pairs, int count)
{
    static char text[8192];
    FILE *f = fopen(EXAMPLES_DIR "/bushing_mount.xml", "r");
    assert_non_null(f);
    const size_t size = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[size] = '\0';
    for (int k = 0; k < count; ++k) {
        char *at = strstr(text, pairs[2 * k]);
        if (at == NULL)
            fail_msg("bushing_mount.xml has no %s", pairs[2 * k]);
        const size_t from = strlen(pairs[2 * k]), to = strlen(pairs[2 * k + 1]);
        assert_true(strlen(text) - from + to < sizeof text);
        memmove(at + to, at + from, strlen(at + from) + 1);
        memcpy(at, pairs[2 * k + 1], to);
    }
    return test_write_file(name, text);
}

/* The elastic energy of the four mounts after 0.1 s, the same however the
 * model is written: with ground not the first body (the frames' markers
 * grouped by body start at a moving one), and with mount 1's I on ground
 * (its GFOSUB probed by moving ground's frame, which carries I). */
static void the_elastic_energy_does_not_depend_on_how_the_model_is_written(void **state)
{
    (void)state;
    static const char *const gbs[2] = {"\"mount_linear.gbs\"",
                                       "\"" EXAMPLES_DIR "/mount_linear.gbs\""};
    static const char *const ground_second[6] = {
        gbs[0], gbs[1], "<Body_Ground id=\"1\"/>", "",
        /* after the block's own element */
        "<Reference_Marker id=\"20\"", "<Body_Ground id=\"1\"/><Reference_Marker id=\"20\"",
    };
    static const char *const swapped[6] = {
        gbs[0], gbs[1],
        "i_marker_id=\"21\" j_floating_marker_id=\"11\" ref_marker_id=\"11\"",
        "i_marker_id=\"11\" j_floating_marker_id=\"21\" ref_marker_id=\"21\"",
        "USER(1, 21, 11, 100)", "USER(1, 11, 21, 100)",
    };
    const char *paths[3];
    paths[0] = EXAMPLES_DIR "/bushing_mount.xml";
    paths[1] = mount_variant("mount_ground_second.xml", ground_second, 3);
    paths[2] = mount_variant("mount_swapped.xml", swapped, 3);
    double elastic[3];
    for (int k = 0; k < 3; ++k) {
        model m;
        open_model(&m, paths[k]);
        double *y = malloc(sizeof(double) * (size_t)m.d.n);
        assert_non_null(y);
        simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-11, 0.1, y);
        if (k == 1)
            assert_false(m.d.m->bodies[0].is_ground);
        elastic[k] = hx_energy_of(&m.d, 0.1, y).elastic;
        printf("  %s: elastic energy at 0.1 s %.12g\n", paths[k], elastic[k]);
        free(y);
        close_model(&m);
    }
    assert_true(fabs(elastic[0]) > 1e-4); /* wrong ones were 1e3 and more */
    assert_close(elastic[1], elastic[0], 1e-7, 0);
    assert_close(elastic[2], elastic[0], 1e-7, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(newton_matrix_equals_differences_on_the_powertrain),
        cmocka_unit_test(newton_matrix_equals_differences_on_every_model),
        cmocka_unit_test(newton_matrix_asks_a_field_for_its_partials),
        cmocka_unit_test(newton_matrix_has_the_routines_rows),
        cmocka_unit_test(newton_matrix_on_jointed_bodies_with_partials),
        cmocka_unit_test(newton_matrix_with_state_equations_diffs_and_loads),
        cmocka_unit_test(differences_by_column_groups_equal_them_column_by_column),
        cmocka_unit_test(the_one_pass_newton_matrix_is_cvodes),
        cmocka_unit_test(the_energy_of_every_element_from_one_copy_of_the_frames),
        cmocka_unit_test(the_elastic_energy_does_not_depend_on_how_the_model_is_written),
        cmocka_unit_test(bdf_converges_at_its_order),
        cmocka_unit_test(a_wrong_partial_costs_newton_iterations_not_accuracy),
        cmocka_unit_test(non_finite_partials_stop_the_run_with_their_element),
        cmocka_unit_test(a_twin_that_disagrees_is_set_aside),
        cmocka_unit_test(bdf_agrees_with_dopri5_on_every_bundled_model),
        cmocka_unit_test(run_takes_bdf_on_every_model_and_says_when_it_is_stiff),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
