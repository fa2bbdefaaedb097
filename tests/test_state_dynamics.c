/*
 * Force_StateEqn elements in the harness's dynamics (docs/interface.md §5):
 * their states integrated against the library's own equations (LuGre
 * friction: a hinged body under a torque below the breakaway torque
 * mu_s N r_B stops, above it slides at mu_d; the rubber filter's response to
 * a sine on the rig, gain w / sqrt(R^2 + w^2)); the Newton matrix with
 * states against differences of the whole right-hand side, with the
 * library's partial routines and with differences where a library exports
 * none; the energy balance on the bundled model closing at the integrator's
 * accuracy; every integrator finishing on it, and agreeing.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sim/jacobian/jacobian.h"
#include "host/state_inputs.h"
#include "sim/dynamics/stateeqns.h"
#include "sim/simulation/command_schedule.h"
#include "sim_support.h"
#include "test_support.h"

/* ---- models ----------------------------------------------------------------------------- */

/* The twelve inputs of marker 20 relative to marker 10 (the library's U
 * array), an X array of nstate and the element (id 1) with a USER list;
 * initial states ic (NULL: none), as the IC array's text. */
static void state_element_ic(char *out, size_t size, int nstate, const char *user,
                             const char *library, const char *ic)
{
    static const char *const measure[12] = {"DX(20,10,10)", "DY(20,10,10)", "DZ(20,10,10)",
                                            "AX(20,10)", "AY(20,10)", "AZ(20,10)",
                                            "VX(20,10,10,10)", "VY(20,10,10,10)",
                                            "VZ(20,10,10,10)", "WX(20,10,10)", "WY(20,10,10)",
                                            "WZ(20,10,10)"};
    int n = 0;
    for (int k = 0; k < 12; ++k)
        n += snprintf(out + n, size - (size_t)n, "<Reference_Variable id=\"%d\" type=\"EXPRESSION\""
                      " expr=\"%s\"/>\n", k + 1, measure[k]);
    if (ic != NULL)
        n += snprintf(out + n, size - (size_t)n, "<Reference_Array id=\"32\" type=\"IC\""
                      " num_element=\"%d\">%s</Reference_Array>\n", nstate, ic);
    snprintf(out + n, size - (size_t)n,
             "<Reference_Array id=\"30\" type=\"U\" num_element=\"12\" variable_id=\"1 2 3 4 5 6 7 8"
             " 9 10 11 12\"/>\n<Reference_Array id=\"31\" type=\"X\" num_element=\"%d\"/>\n"
             "<Force_StateEqn id=\"1\" type=\"USERSUB\" x_array_id=\"31\" u_array_id=\"30\""
             " ic_array_id=\"%d\" num_state=\"%d\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(%s)\" usrsub_dll_name=\"%s\"/>\n",
             nstate, ic != NULL ? 32 : 0, nstate, user, library);
}

static void state_element(char *out, size_t size, int nstate, const char *user,
                          const char *library)
{
    state_element_ic(out, size, nstate, user, library, NULL);
}

#define UNITS                                                                                  \
    "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\""     \
    " time_unit=\"SECOND\"/>\n"

#define GBS_HEAD                                                                               \
    "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n" \
    "MASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n" \
    "{ formulation FX FY FZ TX TY TZ }\n"

/* A body (Izz = 1000 kg mm^2) hinged about z at the bushing, whose preload
 * along y (1000 N, held by the hinge) is the friction's normal force: mu_s N
 * r_B = 0.5 * 1000 * 10 = 5000 N mm breaks it loose, mu_d N r_B = 3000 N mm
 * holds it back while it slides. A torque about z. The bristles (sigma0 =
 * 1000 /mm, a presliding mode of 1e4 rad/s) are critically damped, and the
 * transition velocity (10 mm/s) is above the presliding rates: a torque
 * applied at once would otherwise break the bushing loose below mu_s N r_B,
 * as LuGre's g(|w|) falls while the body first moves. mount: more of the
 * .gbs (a [MOUNT_STIFFNESS] block, or ""); nstate the element's states;
 * loads the Force_Vector_OneBody elements. Writes NAME.gbs and NAME.xml. */
static const char *hinged_friction_model(const char *name, const char *mount, int nstate,
                                         const char *loads)
{
    char gbs[2048], element[4096], xml[8192];
    snprintf(gbs, sizeof gbs, GBS_HEAD "'CONSTANT_STIFFNESS' 0 1 0 0 0 0\n"
             "[CONSTANT_STIFFNESS_FY]\nK = 1000\n"
             "[PRELOAD_OFFSET_SCALE]\n{ direction P Q H V }\nFY 1000 0 1 1\n"
             "[FRICTION]\nACTIVE = 1\nMU_STATIC = 0.5\nMU_DYNAMIC = 0.3\nTRANSITION_VELOCITY = 10\n"
             "BRISTLE_STIFFNESS = 1000\nBRISTLE_DAMPING = 0.2\nBALL_RADIUS = 10\n%s", mount);
    char gbs_name[128];
    snprintf(gbs_name, sizeof gbs_name, "%s.gbs", name);
    state_element(element, sizeof element, nstate, "1, 301", USRSUB_LIBRARY);
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n" UNITS
             "<Reference_String id=\"301\" string=\"%s\"/>\n<Body_Ground id=\"1\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1000\" inertia_yy=\"1000\""
             " inertia_zz=\"1000\"/>\n<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
             "<Constraint_Joint id=\"5\" type=\"REVOLUTE\" i_marker_id=\"20\" j_marker_id=\"10\"/>\n"
             "%s%s</Model></MotionSolve>\n", test_write_file(gbs_name, gbs), element, loads);
    char xml_name[128];
    snprintf(xml_name, sizeof xml_name, "%s.xml", name);
    return test_write_file(xml_name, xml);
}

/* The hinged body with a constant torque about z. */
static const char *friction_model(const char *name, double torque)
{
    char load[256];
    snprintf(load, sizeof load, "<Force_Vector_OneBody id=\"1\" marker_id=\"20\""
             " tz_expression=\"%g\"/>\n", torque);
    return hinged_friction_model(name, "", 3, load);
}

static void friction_holds_below_breakaway(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, friction_model("stick", 4000.0), HX_METHOD_BDF, 1e-6, 0.05, 0.001);
    const int q = sim_joint_q(&s, 5), u = sim_joint_u(&s, 5), last = s.path.rows - 1;
    /* presliding: the bristles take the torque, sigma0 z r_B N = T, and the
     * body stops after turning by a few z / r_B = 4e-5 rad */
    const int z3 = s.dynamics.stateeqn_offset + 2;
    printf("  4000 N mm: angle %.6g rad, rate %.3g rad/s, bristle %.8g mm at t = 0.05 s\n",
           sim_state(&s, last, q), sim_state(&s, last, u), sim_state(&s, last, z3));
    assert_true(sim_state(&s, last, q) > 4e-5 && sim_state(&s, last, q) < 4e-4);
    assert_true(fabs(sim_state(&s, last, u)) < 1e-6);
    assert_close(sim_state(&s, last, z3), 4000.0 / (1000.0 * 10.0 * 1000.0), 1e-6, 0.0);
    sim_close(&s);
}

static void friction_slides_at_mu_d_above_breakaway(void **state)
{
    (void)state;
    sim s;
    sim_run(&s, friction_model("slide", 6000.0), HX_METHOD_BDF, 1e-6, 0.04, 0.001);
    const int u = sim_joint_u(&s, 5);
    /* sliding: (T - mu_d N r_B) ucf / Izz = (6000 - 3000) 1000 / 1000 */
    const double acceleration = (sim_state(&s, 40, u) - sim_state(&s, 20, u)) / 0.02;
    printf("  6000 N mm: angular acceleration %.8g rad/s^2 between 0.02 and 0.04 s (3000 at"
           " mu_d)\n", acceleration);
    assert_close(acceleration, 3000.0, 1e-5, 0.0);
    sim_close(&s);
}

/* The hinged body of friction_model with a damped mount about z in series
 * with the friction (2e5 N mm/rad, 10 N mm s/rad: the friction's torque can
 * fall with the slip faster than this damping rises), driven through a
 * stick-slip cycle: a torque pulse to 6000 N mm (breakaway 5000: it slips,
 * then sticks), the same pulse the other way. BDF's Newton iterations per step stay
 * those of a smooth model: the node's inertia makes the rates one function. */
static void a_mount_in_series_with_friction_integrates_smoothly(void **state)
{
    (void)state;
    static const char loads[] =
        "<Force_Vector_OneBody id=\"1\" marker_id=\"20\" tz_expression=\"STEP(TIME, 0, 0,"
        " 0.05, 6000)\"/>\n<Force_Vector_OneBody id=\"2\" marker_id=\"20\""
        " tz_expression=\"STEP(TIME, 0.05, 0, 0.07, -6000)\"/>\n"
        "<Force_Vector_OneBody id=\"3\" marker_id=\"20\" tz_expression=\"STEP(TIME, 0.15, 0,"
        " 0.2, -6000)\"/>\n<Force_Vector_OneBody id=\"4\" marker_id=\"20\""
        " tz_expression=\"STEP(TIME, 0.2, 0, 0.22, 6000)\"/>\n";
    const char *model = hinged_friction_model(
        "friction_mount", "[MOUNT_STIFFNESS]\n{ direction K C }\nTZ 2e5 10\n", 5, loads);
    sim s;
    sim_run(&s, model, HX_METHOD_BDF, 1e-6, 0.35, 0.001);
    const hx_integrator_stats *st = &s.result.stats;
    const int u = sim_joint_u(&s, 5);
    double fastest = 0.0;
    for (int row = 0; row < s.path.rows; ++row)
        fastest = fmax(fastest, fabs(sim_state(&s, row, u)));
    const double per_step = (double)st->newton_iterations / (double)st->steps;
    printf("  stick-slip through a damped z mount: %ld steps, %.2f Newton iterations per step,"
           " %ld convergence failures; fastest slip %.4g rad/s, rate at the end %.3g rad/s\n",
           st->steps, per_step, st->convergence_failures, fastest,
           sim_state(&s, s.path.rows - 1, u));
    /* it slipped, and stuck again: over the last 0.05 s the body only rings
     * on the mount (447 rad/s, a few mrad), where a slip would turn it by
     * radians */
    const int q = sim_joint_q(&s, 5), last = s.path.rows - 1;
    const double drift = fabs(sim_state(&s, last, q) - sim_state(&s, last - 50, q));
    printf("  angle moved by %.3g rad over the last 0.05 s\n", drift);
    assert_true(fastest > 10.0);
    assert_true(drift < 0.02);
    /* the same model without the mount: 1.51 iterations per step, 1.9 %% of
     * steps with a convergence failure */
    assert_true(per_step < 2.0);
    assert_true(st->convergence_failures <= 3 * st->steps / 100);
    sim_close(&s);
}

/* A rubber filter along y (R = 30 1/s) on the rig, y = A sin(2 pi f t): the
 * filtered deformation x = A w (w sin wt + R cos wt) / (w^2 + R^2) once the
 * start has died away (e^(-R t)). */
static void rubber_filter_passes_the_sine_with_its_gain(void **state)
{
    (void)state;
    static const char gbs[] =
        GBS_HEAD "'CONSTANT_STIFFNESS' 0 1 0 0 0 0\n'RUBBER_DAMPING' 0 1 0 0 0 0\n"
        "[CONSTANT_STIFFNESS_FY]\nK = 1000\n[RUBBER_DAMPING_FY]\nNPRELOADS = 1\n(PRELOAD_1)\n"
        "R = 30\nK0 = 200\nC0 = 0.5\n";
    char element[4096], xml[8192];
    state_element(element, sizeof element, 1, "1, 302", USRSUB_LIBRARY);
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n" UNITS "<Reference_String id=\"302\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"1\"/>\n<Reference_Marker id=\"20\" body_id=\"2\"/>\n%s"
             "</Model></MotionSolve>\n", test_write_file("rubber.gbs", gbs), element);
    /* (a Reference_String id of its own: the library keeps an element's set-up
     * by its id and USER list while it stays loaded) */
    const char *csv = test_write_file("rubber.csv", "");
    const char *const args[] = {"--element", "1", "--sine", "y,0.5,10", "--end", "1", "--step",
                                "0.0005", NULL};
    assert_int_equal(sim_rig(test_write_file("rubber.xml", xml), csv, args), 0);
    csv_table t;
    csv_read(csv, &t);
    const int x1 = csv_column(csv, "stateeqn1.x1");
    assert_true(x1 == 19);
    const double A = 0.5, w = 2.0 * M_PI * 10.0, R = 30.0, d = w * w + R * R;
    double worst = 0.0, peak = 0.0;
    for (int r = 0; r < t.rows; ++r) {
        const double time = csv_at(&t, r, 0);
        if (time < 0.6)
            continue;
        const double x = A * w * (w * sin(w * time) + R * cos(w * time)) / d;
        worst = fmax(worst, fabs(csv_at(&t, r, x1) - x));
        peak = fmax(peak, fabs(csv_at(&t, r, x1)));
    }
    printf("  rubber filter: amplitude %.8g against A w / sqrt(R^2 + w^2) = %.8g; largest"
           " difference from the closed form %.3g\n", peak, A * w / sqrt(d), worst);
    assert_true(worst < 1e-6 * A);
    csv_free(&t);
}

/* ---- the Newton matrix ---------------------------------------------------------------------- */

/* The assembled Jacobian against differences (sim_support.h): no entry
 * outside its sparsity. */
static double jacobian_error(const hx_dynamics *d, double t, const double *y, const char *what)
{
    long outside = 0;
    const double worst = jacobian_against_differences(d, t, y, what, &outside);
    assert_int_equal(outside, 0);
    return worst;
}

static void jacobian_with_states_equals_differences(void **state)
{
    (void)state;
    /* presliding under the rising torque, sliding, and the mount taking the
     * load along x; not at rest, where the bristles' |w| has a kink that a
     * central difference straddles */
    static const double times[3] = {0.15, 0.225, 0.55};
    for (int k = 0; k < 3; ++k) {
        sim s;
        sim_run(&s, "suspension_bushing.xml", HX_METHOD_DOPRI5, 1e-9, times[k], times[k]);
        char what[64];
        snprintf(what, sizeof what, "suspension_bushing.xml at t = %g s", times[k]);
        const double *y = s.path.y + (s.path.rows - 1) * s.path.n;
        assert_true(jacobian_error(&s.dynamics, times[k], y, what) < 1e-6);
        sim_close(&s);
    }
}

/* The scaled state equation on a free body with a spring-like output; the
 * library given (with or without partial routines), initial states ic. */
static const char *scaled_model_ic(const char *name, const char *library, const char *user,
                                   const char *ic)
{
    char element[4096], xml[8192];
    state_element_ic(element, sizeof element, 2, user, library, ic);
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1\""
             " inertia_zz=\"1\" v_ic_x=\"3\" v_ic_y=\"-1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n%s"
             "</Model></MotionSolve>\n", element);
    return test_write_file(name, xml);
}

static const char *scaled_model(const char *name, const char *library, const char *user)
{
    return scaled_model_ic(name, library, user, NULL);
}

/* ---- inputs given by expressions ------------------------------------------------------------- */

/* The scaled state equation on the free body of scaled_model_ic, its first
 * input an expression of two measures, u0 = DX(20,10,10) + 0.3 DY(30,10,10)^2,
 * the second of another free body (3, drifting along y, which no other input
 * reads), its seventh one of two measures and TIME, u6 = VX - 2 WZ + TIME (of
 * marker 20 from marker 10, the world's axes); the others the usual measures. */
static const char *expression_inputs_model(const char *name, const char *library,
                                           const char *first)
{
    const char *const measure[12] = {
        first != NULL ? first : "DX(20,10,10) + 0.3*DY(30,10,10)**2", "DY(20,10,10)", "DZ(20,10,10)", "AX(20,10)",
        "AY(20,10)", "AZ(20,10)", "VX(20,10,10,10) - 2*WZ(20,10,10) + TIME", "VY(20,10,10,10)",
        "VZ(20,10,10,10)", "WX(20,10,10)", "WY(20,10,10)", "WZ(20,10,10)"};
    char xml[8192];
    int n = snprintf(xml, sizeof xml,
                     "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
                     "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
                     "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1\""
                     " inertia_zz=\"1\" v_ic_x=\"3\" v_ic_y=\"-1\" w_ic_z=\"2\"/>\n"
                     "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n"
                     "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
                     " inertia_zz=\"1\" v_ic_y=\"2\"/>\n"
                     "<Reference_Marker id=\"30\" body_id=\"3\" pos_y=\"0.4\"/>\n");
    for (int k = 0; k < 12; ++k)
        n += snprintf(xml + n, sizeof xml - (size_t)n, "<Reference_Variable id=\"%d\""
                      " expr=\"%s\"/>\n", k + 1, measure[k]);
    snprintf(xml + n, sizeof xml - (size_t)n,
             "<Reference_Array id=\"30\" type=\"U\" num_element=\"12\" variable_id=\"1 2 3 4 5 6 7 8"
             " 9 10 11 12\"/>\n<Reference_Array id=\"31\" type=\"X\" num_element=\"2\"/>\n"
             "<Force_StateEqn id=\"1\" type=\"USERSUB\" x_array_id=\"31\" u_array_id=\"30\""
             " num_state=\"2\" i_marker_id=\"20\" j_floating_marker_id=\"10\""
             " ref_marker_id=\"10\" usrsub_param_string=\"USER(50, 2, 20, 1)\""
             " usrsub_dll_name=\"%s\"/>\n</Model></MotionSolve>\n", library);
    return test_write_file(name, xml);
}

/* The inputs are the expressions' values at the state (worked from the
 * marker's frame), and the Newton matrix, whose dU/dy are differences of
 * the expressions, equals differences of the right-hand side with no entry
 * outside its pattern; with the library's partials and with YFOSUB alone. */
static void inputs_given_by_expressions(void **state)
{
    (void)state;
    const char *const libraries[2] = {SCALED_STATE_LIBRARY, PLAIN_STATE_LIBRARY};
    for (int l = 0; l < 2; ++l) {
        sim s;
        sim_run(&s, expression_inputs_model(l == 0 ? "expr_in.xml" : "expr_in_plain.xml",
                                            libraries[l], NULL),
                HX_METHOD_DOPRI5, 1e-9, 0.3, 0.3);
        const double *y = s.path.y + (s.path.rows - 1) * s.path.n;
        sim_evaluate(&s, 0.3, y);
        double u[12];
        assert_int_equal(hx_stateeqn_inputs(&s.data.frames, 0, u), 0);
        hx_frame scratch, other;
        const hx_frame *f =
            hx_frames_marker(&s.data.frames, hx_model_marker(s.session.model, 20), &scratch);
        const hx_frame *g =
            hx_frames_marker(&s.data.frames, hx_model_marker(s.session.model, 30), &other);
        assert_close(g->p[1], 0.4 + 2.0 * 0.3, 1e-9, 0.0); /* body 3 drifts: y = 0.4 + 2 t */
        assert_true(fabs(f->w[2]) > 0.1); /* every term counts */
        assert_close(u[0], f->p[0] + 0.3 * g->p[1] * g->p[1], 1e-12, 1e-14);
        assert_close(u[1], f->p[1], 1e-12, 1e-14);
        assert_close(u[6], f->v[0] - 2.0 * f->w[2] + 0.3, 1e-12, 1e-14);
        assert_true(jacobian_error(&s.dynamics, 0.3, y, "expression inputs") < 1e-6);
        sim_close(&s);
    }
}

/* The schedule of acf_text (a command file) run on the model at path with
 * method: the end state (malloc'ed) and the result in r. */
static double *scheduled_run(const char *path, const char *acf_text, hx_method method,
                             hx_simulation_result *r)
{
    hx_session session;
    hx_dynamics d;
    hx_message msg;
    if (hx_session_open(&session, path, NULL, &msg) != 0 || hx_dynamics_init(&d, &session, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_command_file *f = hx_command_file_parse(acf_text, strlen(acf_text), "in.acf", &msg);
    hx_command_schedule s;
    const hx_command_overrides none = {0};
    if (f == NULL || hx_command_schedule_make(f, "in.acf", session.model, path, 1e-9, 1e-9, &none,
                                              NULL, &s, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_command_file_free(f);
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = method;
    so.integration.t_end = s.t_end;
    so.skip_energy = 1;
    double *y = calloc((size_t)d.n, sizeof(double));
    assert_non_null(y);
    if (hx_simulate_segments(&d, &so, s.segments, s.nsegments, y, r) != 0)
        fail_msg("%s", r->message);
    hx_command_schedule_free(&s);
    hx_dynamics_free(&d);
    hx_session_close(&session);
    return y;
}

/* A command file's VARIABLE (docs/interface.md §9.9) makes the first input
 * read body 3, which none read before: BDF's pattern holds its columns
 * (nothing outside it) and BDF follows DOPRI5. */
static void an_input_redefined_between_segments(void **state)
{
    (void)state;
    const char *path = expression_inputs_model("expr_redef.xml", SCALED_STATE_LIBRARY,
                                               "DX(20,10,10)");
    static const char acf[] = "expr_redef\n\nSIMULATE/DYNAMIC, END=0.15, STEPS=3\n"
                              "VARIABLE/1, FUNCTION = DX(20,10,10) + 0.3*DY(30,10,10)**2\n"
                              "SIMULATE/DYNAMIC, END=0.4, STEPS=5\n";
    hx_simulation_result r, b;
    double *exact = scheduled_run(path, acf, HX_METHOD_DOPRI5, &r);
    double *bdf = scheduled_run(path, acf, HX_METHOD_BDF, &b);
    assert_int_equal(b.jacobian_outside, 0);
    double worst = 0.0;
    for (int i = 0; i < r.n - 2; ++i) /* not the work accumulators */
        worst = fmax(worst, fabs(bdf[i] - exact[i]));
    assert_true(worst < 1e-3);
    free(exact), free(bdf);
}

/* An input's expression that faults ends the run naming the variable, the
 * function, its file:line:column and the time. */
static void a_faulting_input_ends_the_run(void **state)
{
    (void)state;
    const char *path = expression_inputs_model("expr_fault.xml", SCALED_STATE_LIBRARY,
                                               "LOG(DX(20,10,10) - 10)");
    hx_session session;
    hx_dynamics d;
    hx_message msg;
    if (hx_session_open(&session, path, NULL, &msg) != 0 || hx_dynamics_init(&d, &session, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_DOPRI5;
    so.integration.t_end = 0.01;
    so.integration.output_interval = 0.01;
    hx_simulation_result r;
    assert_int_equal(hx_simulate(&d, &so, NULL, &r), -1);
    assert_contains(r.message, "Force_StateEqn 1: its input ", "expr_fault.xml:", "Reference_Variable 1",
                    "LOG", "at t = 0");
    hx_dynamics_free(&d);
    hx_session_close(&session);
}

/* States so large that their rates overflow: the run ends at once, naming
 * the element, what it returned and when. */
static void a_non_finite_rate_ends_the_run(void **state)
{
    (void)state;
    const char *path = scaled_model_ic("overflow.xml", SCALED_STATE_LIBRARY, "50, 2, 20, 1",
                                       "1e200 -1e200");
    hx_session session;
    hx_dynamics d;
    hx_message msg;
    if (hx_session_open(&session, path, NULL, &msg) != 0 || hx_dynamics_init(&d, &session, &msg) != 0)
        fail_msg("%s", msg.text);
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_RK4;
    so.integration.step = 1e-3;
    so.integration.t_end = 0.01;
    hx_simulation_result r;
    assert_int_equal(hx_simulate(&d, &so, NULL, &r), -1);
    assert_contains(r.message, "Force_StateEqn 1 (", "returned a non-finite state rate at t = 0");
    hx_dynamics_free(&d);
    hx_session_close(&session);
}

static void a_library_without_partials_is_differenced(void **state)
{
    (void)state;
    const char *with = scaled_model("with.xml", SCALED_STATE_LIBRARY, "50, 2, 20, 1");
    const char *plain = scaled_model("plain.xml", PLAIN_STATE_LIBRARY, "50, 2, 20, 1");
    sim a, b, c;
    sim_run(&a, plain, HX_METHOD_DOPRI5, 1e-7, 0.3, 0.3);
    const double *y = a.path.y + (a.path.rows - 1) * a.path.n;
    assert_true(jacobian_error(&a.dynamics, 0.3, y, "scaled_state without partial routines") < 1e-6);
    hx_binding *bp = hx_bindings_find(&a.session.bindings, HX_FAMILY_STATEEQN, 0);
    for (int r = 0; r < 4; ++r)
        assert_null(bp->fn.stateeqn.partial[r]);
    /* BDF on either agrees with DOPRI5 on the end state */
    sim_run(&b, plain, HX_METHOD_BDF, 1e-6, 1.0, 1.0);
    sim_run(&c, with, HX_METHOD_BDF, 1e-6, 1.0, 1.0);
    sim_close(&a);
    sim_run(&a, with, HX_METHOD_DOPRI5, 1e-10, 1.0, 1.0);
    const int n = a.path.n, last = a.path.rows - 1;
    double worst_plain = 0.0, worst_with = 0.0;
    for (int i = 0; i < a.dynamics.load_work; ++i) {
        const double ref = sim_state(&a, last, i);
        worst_plain = fmax(worst_plain, fabs(sim_state(&b, b.path.rows - 1, i) - ref));
        worst_with = fmax(worst_with, fabs(sim_state(&c, c.path.rows - 1, i) - ref));
    }
    printf("  bdf against dopri5 (rtol 1e-10) at t = 1: largest difference %.3g (differences),"
           " %.3g (the library's partials); %ld and %ld steps\n", worst_plain, worst_with,
           b.result.stats.steps, c.result.stats.steps);
    assert_true(worst_plain < 1e-3 && worst_with < 1e-3);
    assert_int_equal(n, c.path.n);
    sim_close(&a), sim_close(&b), sim_close(&c);
}

/* ---- the bundled model ------------------------------------------------------------------------- */

static void energy_balance_closes_at_the_integrators_accuracy(void **state)
{
    (void)state;
    double errors[2];
    static const double tolerance[2] = {1e-6, 1e-10};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, "suspension_bushing.xml", HX_METHOD_DOPRI5, tolerance[k], 1.0, 0.01);
        const hx_simulation_result *r = &s.result;
        errors[k] = r->balance_error_max / r->energy_scale;
        printf("  dopri5 at rtol %g: energy balance error %.3g (relative), the bushing took %.6g"
               " (its work: stored and dissipated)\n", tolerance[k], errors[k], r->dissipated);
        /* the element's work is counted: it is most of what the loads put in */
        assert_true(r->dissipated > 1000.0);
        sim_close(&s);
    }
    assert_true(errors[0] < 1e-6);
    assert_true(errors[1] < 1e-9 && errors[1] < errors[0] / 100.0);
}

/* run --integrator NAME on the bundled model through the slide (0.2 to 0.25
 * s): every one finishes, and their end states agree. */
static void every_integrator_finishes_on_the_bundled_model(void **state)
{
    (void)state;
    static const char *const integrators[][3] = {
        {"bdf", "--rtol", "1e-9"},         {"dopri5", "--rtol", "1e-8"},
        {"dopri5-arkode", "--rtol", "1e-8"}, {"rk4", "--step", "2e-6"},
        {"euler", "--step", "1e-6"},        {"symplectic-euler", "--step", "1e-6"}};
    double reference[8] = {0};
    for (size_t k = 0; k < sizeof integrators / sizeof integrators[0]; ++k) {
        char csv[512];
        snprintf(csv, sizeof csv, "%s/bundled_%s.csv", test_temp_dir(), integrators[k][0]);
        const char *const args[] = {"--end", "0.4", "--integrator", integrators[k][0],
                                    integrators[k][1], integrators[k][2], "--quiet", NULL};
        assert_int_equal(sim_run_csv("suspension_bushing.xml", csv, args), 0);
        static const char *const columns[8] = {"body2.x", "body2.y", "body2.q3", "stateeqn1.x3",
                                               "stateeqn1.x5", "stateeqn1.tz", "stateeqn1.fy",
                                               "body2.wz"};
        csv_table t;
        csv_read(csv, &t);
        double worst = 0.0;
        for (int c = 0; c < 8; ++c) {
            const int column = csv_column(csv, columns[c]);
            assert_true(column > 0);
            const double v = csv_at(&t, t.rows - 1, column);
            if (k == 0)
                reference[c] = v;
            worst = fmax(worst, fabs(v - reference[c]) / fmax(fabs(reference[c]), 1e-3));
        }
        printf("  %-16s end state against bdf at rtol 1e-9: largest relative difference %.3g\n",
               integrators[k][0], worst);
        assert_true(worst < 2e-3);
        csv_free(&t);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(inputs_given_by_expressions),
        cmocka_unit_test(a_faulting_input_ends_the_run),
        cmocka_unit_test(an_input_redefined_between_segments),
        cmocka_unit_test(friction_holds_below_breakaway),
        cmocka_unit_test(friction_slides_at_mu_d_above_breakaway),
        cmocka_unit_test(a_mount_in_series_with_friction_integrates_smoothly),
        cmocka_unit_test(rubber_filter_passes_the_sine_with_its_gain),
        cmocka_unit_test(jacobian_with_states_equals_differences),
        cmocka_unit_test(a_library_without_partials_is_differenced),
        cmocka_unit_test(a_non_finite_rate_ends_the_run),
        cmocka_unit_test(energy_balance_closes_at_the_integrators_accuracy),
        cmocka_unit_test(every_integrator_finishes_on_the_bundled_model),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
