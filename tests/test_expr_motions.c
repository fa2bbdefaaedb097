/*
 * Motion_Joint by expression (docs/interface.md §7.12, §9.4): the time
 * derivatives of an expression of TIME (expr/time_derivative.h) against
 * their closed forms, with the error of f''s difference; a revolute to
 * ground driven by 10D*TIME; a translational joint between two moving
 * bodies driven by 0.1*SIN(2*PI*TIME), its coordinate against the closed
 * form and the constraint residuals; the same motion by expression and by
 * the bundled MOTSUB (SWING, tests/user_libraries/tp_routines.c); a
 * velocity motion integrated, on a reduced joint and between moving bodies;
 * an acceleration motion between moving bodies (translational and revolute,
 * by expression and by MOTSUB, DOPRI5 and BDF) against the closed forms
 * integrated by hand, and one to ground as before;
 * the dataset's MOTION FUNCTION= form (and ACCELERATION, ICVEL on a
 * four-bar's crank) and a driven slider-crank;
 * the expressions refused, with file:line:column.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr/time_derivative.h"
#include "sim/dynamics/bodies.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/coordinate_rows.h"
#include "sim/dynamics/joint_coordinate.h"
#include "sim/dynamics/routines.h"
#include "sim_support.h"
#include "test_support.h"

/* A link (body 2) on a revolute to ground (joint 1, reduced) turned by a
 * torque, and a slider (body 3) on a translational joint (2) along the
 * link's x axis (J's z turned onto x by theta = 90 deg about y): joint 2 is
 * between two moving bodies. Gravity pulls across both. `motions`: the
 * Motion_Joint elements. */
static const char *link_model(const char *motions)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.3\" inertia_zz=\"0.3\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.4\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"0.5\" psi=\"1.5707963267948966\" theta=\"1.5707963267948966\" phi=\"-1.5707963267948966\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"0.7\" inertia_xx=\"0.02\" inertia_yy=\"0.03\" inertia_zz=\"0.04\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"0.5\"/>\n"
             "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"0.5\" psi=\"1.5707963267948966\" theta=\"1.5707963267948966\" phi=\"-1.5707963267948966\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"TRANSLATIONAL\" i_marker_id=\"31\" j_marker_id=\"22\"/>\n"
             "<Force_Scalar_TwoBody id=\"1\" type=\"TORQUE\" i_marker_id=\"21\" j_marker_id=\"10\" val=\"3\"/>\n"
             "%s</Model></MotionSolve>\n",
             motions);
    return text;
}

/* A pendulum (body 2) on a revolute to ground (joint 1), its only joint: a
 * reduced joint, the body's one coordinate. */
static const char *pendulum_model(const char *motions)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.3\" inertia_zz=\"0.3\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.4\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
             "%s</Model></MotionSolve>\n",
             motions);
    return text;
}

static hx_model *clock_model(void)
{
    hx_message msg;
    hx_model *m = hx_model_read(test_write_file("motion_clock.xml", link_model("")), NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    return m;
}

static hx_expr_program *program_of(const char *text, hx_model *m)
{
    hx_message msg;
    const hx_expr_source where = {"motion_clock.xml", 1, 1};
    hx_expr_program *p = hx_expr_parse(text, strlen(text), &where, &msg);
    if (p == NULL || hx_expr_link(p, m, &msg) != 0)
        fail_msg("%s", msg.text);
    return p;
}

/* f = 0.1 sin(2 pi t): f' = 0.2 pi cos(2 pi t) exactly (the partial in TIME),
 * f'' = -0.4 pi^2 sin(2 pi t) by the extrapolated difference of f', whose
 * error is h^4 |f^(6)| / 30 = 1e-16 * 0.1 (2 pi)^6 / 30 = 2e-14 (truncation)
 * and about 2 DBL_EPSILON |f'| / h = 3e-12 (rounding): within 1e-11 at every
 * sampled time; the plain central difference D(h) alone errs by
 * h^2 |f''''| / 6 = 1e-8 * 156 / 6 = 2.6e-7 at its worst, which the
 * extrapolation must beat. */
static void time_derivatives_against_closed_forms(void **state)
{
    (void)state;
    hx_model *m = clock_model();
    hx_expr_program *p = program_of("0.1*SIN(2*PI*TIME)", m);
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    const double w = 2.0 * M_PI;
    double worst2 = 0.0;
    for (int k = 0; k <= 40; ++k) {
        fr.time = -0.3 + 0.0537 * k;
        const double t = fr.time;
        double f[3];
        hx_expr_fault fault;
        for (int iord = 0; iord < 3; ++iord)
            assert_int_equal(hx_time_derivative_eval(p, &fr, iord, &f[iord], &fault), 0);
        assert_close(f[0], 0.1 * sin(w * t), 0, 1e-16);
        assert_close(f[1], 0.1 * w * cos(w * t), 0, 4e-16);
        worst2 = fmax(worst2, fabs(f[2] + 0.1 * w * w * sin(w * t)));
        assert_close(fr.time, t, 0, 0); /* the frames' time is left as it was */
    }
    printf("f'' of 0.1 sin(2 pi t) by the extrapolated difference: worst error %.3g\n", worst2);
    assert_true(worst2 < 1e-11);
    assert_true(worst2 > 0.0); /* a difference, not the closed form */
    /* a constant motion: rate and acceleration 0 */
    hx_expr_free(p);
    p = program_of("0.25", m);
    double value;
    hx_expr_fault fault;
    fr.time = 0.7;
    assert_int_equal(hx_time_derivative_eval(p, &fr, 1, &value, &fault), 0);
    assert_close(value, 0.0, 0, 0);
    assert_int_equal(hx_time_derivative_eval(p, &fr, 2, &value, &fault), 0);
    assert_close(value, 0.0, 0, 0);
    hx_expr_free(p);
    hx_frames_free(&fr);
    hx_model_free(m);
}

/* At the run's start (0 <= t < 2h) f'' reads no time before 0: TIME**2.5 is
 * not defined there. f' = 2.5 t^1.5, f'' = 3.75 sqrt(t): at t = 1, 3.75; at
 * t = 0 the forward difference over f' at 0 .. 4h gives 2.5 sqrt(h) (48 - 36
 * 2^1.5 + 16 3^1.5 - 3 4^1.5) / 12 = 0.0111 (the third derivative is not
 * bounded at 0); a smooth 0.1 sin(2 pi t) near 0 within the forward formula's
 * rounding, 128/12 DBL_EPSILON |f'| / h = 1.5e-11. */
static void time_derivatives_at_the_start(void **state)
{
    (void)state;
    hx_model *m = clock_model();
    hx_expr_program *p = program_of("TIME**2.5", m);
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    double value;
    hx_expr_fault fault;
    fr.time = 0.0;
    assert_int_equal(hx_time_derivative_eval(p, &fr, 2, &value, &fault), 0);
    assert_close(value, 0.0111, 0.01, 0);
    fr.time = 1e-4;
    assert_int_equal(hx_time_derivative_eval(p, &fr, 2, &value, &fault), 0);
    assert_close(value, 3.75e-2, 0.02, 0);
    fr.time = 1.0;
    assert_int_equal(hx_time_derivative_eval(p, &fr, 2, &value, &fault), 0);
    assert_close(value, 3.75, 0, 1e-9);
    hx_expr_free(p);
    p = program_of("0.1*SIN(2*PI*TIME)", m);
    const double w = 2.0 * M_PI, times[3] = {0.0, 5e-5, 1.5e-4};
    for (int k = 0; k < 3; ++k) {
        fr.time = times[k];
        assert_int_equal(hx_time_derivative_eval(p, &fr, 2, &value, &fault), 0);
        assert_close(value, -0.1 * w * w * sin(w * times[k]), 0, 5e-11);
    }
    hx_expr_free(p);
    hx_frames_free(&fr);
    hx_model_free(m);
}

/* The link's revolute to ground (joint 1, its body's one joint: reduced)
 * driven by 10D*TIME against the torque and gravity: its coordinate is
 * 10 deg/s times t, to rounding (the rate 10D is integrated exactly by any
 * Runge-Kutta method). */
typedef double (*closed_form)(double t);

/* The pendulum driven by `motion` (a Motion_Joint on its revolute, joint 1)
 * written to file and run by DOPRI5 at 1e-10 to `end`: its coordinate and
 * rate at every output row against the closed forms q_of and u_of, within
 * tol_q and tol_u. The run is left in s for the caller's own checks. */
static void run_driven_pendulum(sim *s, const char *file, const char *motion, double end,
                                closed_form q_of, closed_form u_of, double tol_q, double tol_u)
{
    sim_run(s, test_write_file(file, pendulum_model(motion)), HX_METHOD_DOPRI5, 1e-10, end, 0.1);
    const int q = sim_joint_q(s, 1), u = sim_joint_u(s, 1);
    for (int row = 0; row < s->path.rows; ++row) {
        const double t = s->path.t[row];
        assert_close(sim_state(s, row, q), q_of(t), 0, tol_q);
        assert_close(sim_state(s, row, u), u_of(t), 0, tol_u);
    }
    assert_true(s->path.t[s->path.rows - 1] > end - 0.01);
}

static double ten_degrees_a_second(double t)
{
    return 10.0 * M_PI / 180.0 * t;
}

static double ten_degrees(double t)
{
    (void)t;
    return 10.0 * M_PI / 180.0;
}

static void revolute_to_ground_by_expression(void **state)
{
    (void)state;
    sim s;
    run_driven_pendulum(&s, "motion_revolute.xml",
                        "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" val_type=\"D\""
                        " expr=\"10D*TIME\"/>\n",
                        2.0, ten_degrees_a_second, ten_degrees, 1e-14, 1e-15);
    assert_int_equal(s.dynamics.dof[1].kind, HX_DOF_REVOLUTE);
    assert_int_equal(s.dynamics.driver[1], 0);
    sim_close(&s);
}

/* The slider's coordinate along the link (joint 2, between two moving
 * bodies) at each output row against f = 0.1 sin(2 pi t), and the
 * residuals of every constraint row (phi, dphi/dt, the motion's included)
 * after the projection: within 1e-10. */
static void check_slider(sim *s, double *worst_a)
{
    for (int row = 0; row < s->path.rows; ++row) {
        const double t = s->path.t[row], *y = s->path.y + (size_t)row * (size_t)s->path.n;
        double a, phi, phidot;
        hx_joint_coordinate_near(&s->dynamics, 1, 'T', y, 0.0, &a, NULL, NULL);
        *worst_a = fmax(*worst_a, fabs(a - 0.1 * sin(2.0 * M_PI * t)));
        assert_int_equal(hx_constraints_residuals(&s->dynamics, &s->data, t, y, &phi, &phidot), 0);
        assert_true(phi <= 1e-10);
        assert_true(phidot <= 1e-10);
    }
}

/* The link's (body 2's) largest rate of turn about z along a run. */
static double link_turned(const sim *s)
{
    double turned = 0.0;
    for (int row = 0; row < s->path.rows; ++row) {
        hx_frame link;
        hx_bodies_frame(&s->dynamics, 1, s->path.y + (size_t)row * (size_t)s->path.n, &link);
        turned = fmax(turned, fabs(link.w[2]));
    }
    return turned;
}

static void translational_between_moving_bodies_by_expression(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "motion_slider.xml",
        link_model("<Motion_Joint id=\"2\" type=\"EXPRESSION\" joint_id=\"2\""
                   " expr=\"0.1*SIN(2*PI*TIME)\"/>\n"));
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, path, methods[k], k == 0 ? 1e-10 : 1e-8, 1.0, 0.05);
        assert_int_equal(s.dynamics.nmotions, 1);
        double worst = 0.0;
        check_slider(&s, &worst);
        printf("%s: the slider's coordinate against 0.1 sin(2 pi t): worst %.3g\n",
               k == 0 ? "DOPRI5" : "BDF", worst);
        assert_true(worst < 1e-10);
        assert_true(link_turned(&s) > 1.0); /* both bodies move */
        sim_close(&s);
    }
}

/* The same motion by expression and by the bundled MOTSUB SWING (a sin(w t),
 * USER(a, w)): f, f' and f'' the same at sampled times (f to the bit, f'
 * to an ulp: the factors are multiplied in another order, f'' to its
 * difference's error), and the two runs' states alike. */
static void expression_against_motsub(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    const char *paths[2] = {
        test_write_file("motion_slider_expr.xml",
                        link_model("<Motion_Joint id=\"2\" type=\"EXPRESSION\" joint_id=\"2\""
                                   " expr=\"0.1*SIN(6.283185307179586*TIME)\"/>\n")),
        test_write_file("motion_slider_motsub.xml",
                        link_model("<Motion_Joint id=\"2\" type=\"USERSUB\" joint_id=\"2\""
                                   " usrsub_param_string=\"USER(0.1, 6.283185307179586)\""
                                   " usrsub_fnc_name=\"SWING\" usrsub_dll_name=\"libtp_routines.so\"/>\n"))};
    sim s[2];
    for (int k = 0; k < 2; ++k)
        sim_run(&s[k], paths[k], HX_METHOD_DOPRI5, 1e-10, 1.0, 0.05);
    for (int i = 0; i < 9; ++i) {
        double f[2][3];
        for (int k = 0; k < 2; ++k) {
            s[k].data.frames.time = 0.123 * i;
            for (int iord = 0; iord < 3; ++iord)
                assert_int_equal(hx_routines_motion(&s[k].dynamics, &s[k].data, 0, iord, &f[k][iord]), 0);
        }
        assert_close(f[0][0], f[1][0], 0, 0);
        assert_close(f[0][1], f[1][1], 0, 2e-16);
        assert_close(f[0][2], f[1][2], 0, 1e-11);
    }
    assert_int_equal(s[0].path.rows, s[1].path.rows);
    double worst = 0.0;
    for (size_t j = 0; j < (size_t)s[0].path.rows * (size_t)s[0].path.n; ++j)
        worst = fmax(worst, fabs(s[0].path.y[j] - s[1].path.y[j]));
    printf("expression against MOTSUB: the states differ by %.3g at most\n", worst);
    assert_true(worst < 1e-9);
    for (int k = 0; k < 2; ++k)
        sim_close(&s[k]);
}

/* A velocity motion on the revolute to ground: f = 2 t from ic_disp = 0.5,
 * so q = 0.5 + t^2, u = 2 t (integrated exactly by DOPRI5). */
static double half_plus_t_squared(double t)
{
    return 0.5 + t * t;
}

static double two_t(double t)
{
    return 2.0 * t;
}

static void velocity_motion_integrated(void **state)
{
    (void)state;
    sim s;
    run_driven_pendulum(&s, "motion_velocity.xml",
                        "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" val_type=\"V\""
                        " ic_disp=\"0.5\" expr=\"2*TIME\"/>\n",
                        1.0, half_plus_t_squared, two_t, 1e-13, 1e-13);
    sim_close(&s);
}

/* A velocity motion on the translational joint between the two moving
 * bodies: f = 0.2 pi cos(2 pi t), the slider's rate, from the coordinate
 * where the model places it (0): the coordinate integrates to
 * 0.1 sin(2 pi t) within the integrator's tolerance, the rate G u is f
 * after every projection, and every row's residuals stay within 1e-10. */
static void velocity_motion_between_moving_bodies(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "motion_slider_velocity.xml",
        link_model("<Motion_Joint id=\"2\" type=\"EXPRESSION\" joint_id=\"2\" val_type=\"V\""
                   " expr=\"0.2*PI*COS(2*PI*TIME)\"/>\n"));
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, path, methods[k], k == 0 ? 1e-10 : 1e-8, 1.0, 0.05);
        assert_int_equal(s.dynamics.nmotions, 1);
        double worst = 0.0, worst_rate = 0.0;
        check_slider(&s, &worst);
        for (int row = 0; row < s.path.rows; ++row) {
            const double t = s.path.t[row], *y = s.path.y + (size_t)row * (size_t)s.path.n;
            const double rate = hx_coordinate_rows_joint_rate(&s.dynamics, 1, 'T', y);
            worst_rate = fmax(worst_rate, fabs(rate - 0.2 * M_PI * cos(2.0 * M_PI * t)));
        }
        printf("%s: a velocity motion between bodies: the coordinate against 0.1 sin(2 pi t)"
               " %.3g, the rate against f %.3g\n", k == 0 ? "DOPRI5" : "BDF", worst, worst_rate);
        assert_true(worst < (k == 0 ? 1e-8 : 1e-5));
        assert_true(worst_rate < 1e-10);
        /* the CSV's motion2.error is the rate less f: 0 after the projection; at a
         * state whose slider moves 1 (length/s) faster, 1 */
        const int last = s.path.rows - 1;
        double *y = malloc(sizeof(double) * (size_t)s.path.n);
        assert_non_null(y);
        memcpy(y, s.path.y + (size_t)last * (size_t)s.path.n, sizeof(double) * (size_t)s.path.n);
        for (int pass = 0; pass < 2; ++pass) {
            char *text = NULL;
            size_t size = 0;
            FILE *f = open_memstream(&text, &size);
            s.data.frames.time = s.path.t[last];
            const hx_expr_outputs none = {0}; /* no REQSUB asks for any */
            assert_int_equal(hx_routines_csv_row(f, &s.dynamics, &s.data, y, &none), 0);
            fclose(f);
            assert_close(strtod(text + 1, NULL), pass, 0, 1e-9);
            free(text);
            /* the slider's velocity along the link's x axis, world: body 3's u */
            hx_frame link;
            hx_bodies_frame(&s.dynamics, 1, y, &link);
            for (int c = 0; c < 3; ++c)
                y[s.dynamics.nq + s.dynamics.dof[2].u + c] += link.R[3 * c];
        }
        free(y);
        sim_close(&s);
    }
}

/* The closed forms of an acceleration motion f = 0.2 sin(2 pi t) from s0 and
 * v0, integrated by hand: v = v0 + (0.2 / 2 pi) (1 - cos 2 pi t),
 * s = s0 + (v0 + 0.2 / 2 pi) t - (0.2 / 4 pi^2) sin 2 pi t. */
static double accel_velocity(double v0, double t)
{
    return v0 + 0.2 / (2.0 * M_PI) * (1.0 - cos(2.0 * M_PI * t));
}

static double accel_displacement(double s0, double v0, double t)
{
    return s0 + (v0 + 0.2 / (2.0 * M_PI)) * t - 0.2 / (4.0 * M_PI * M_PI) * sin(2.0 * M_PI * t);
}

/* Along a run driven in acceleration on joint `joint` (index) in freedom
 * from s0 and v0: the worst distances of the joint's coordinate and rate,
 * and of the motion's two states, from the closed forms; every row's
 * residuals (phi, dphi/dt) after the projection within 1e-10. */
static void check_accelerated(sim *s, int joint, char freedom, double s0, double v0,
                              double worst[3])
{
    const hx_dynamics *d = &s->dynamics;
    assert_int_equal(d->nmotions, 1);
    assert_int_equal(d->nmotion_states, 2);
    const int at = d->motion_state[0];
    assert_int_equal(at, d->load_work - 2);
    worst[0] = worst[1] = worst[2] = 0.0;
    for (int row = 0; row < s->path.rows; ++row) {
        const double t = s->path.t[row], *y = s->path.y + (size_t)row * (size_t)s->path.n;
        const double sc = accel_displacement(s0, v0, t), vc = accel_velocity(v0, t);
        double a, phi, phidot;
        hx_joint_coordinate_near(d, joint, freedom, y, sc, &a, NULL, NULL);
        worst[0] = fmax(worst[0], fabs(a - sc));
        worst[1] = fmax(worst[1], fabs(hx_coordinate_rows_joint_rate(d, joint, freedom, y) - vc));
        worst[2] = fmax(worst[2], fmax(fabs(y[at] - sc), fabs(y[at + 1] - vc)));
        assert_int_equal(hx_constraints_residuals(d, &s->data, t, y, &phi, &phidot), 0);
        assert_true(phi <= 1e-10);
        assert_true(phidot <= 1e-10);
    }
}

/* An acceleration motion on the translational joint between the two moving
 * bodies (val_type A: f = 0.2 sin(2 pi t) the slider's acceleration along
 * the link, from ic_disp = 0.05 and ic_vel = -0.1): by expression with
 * DOPRI5 and BDF, and by the bundled MOTSUB SWING USER(0.2, 2 pi) (its iord
 * 0 the acceleration) with DOPRI5. The coordinate and its rate against the
 * closed forms integrated by hand, the residuals held, the link turned; the
 * BDF run's Jacobian (the states' row s' = v among it) against differences. */
static void acceleration_motion_between_moving_bodies(void **state)
{
    (void)state;
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    const char *paths[2] = {
        test_write_file("motion_slider_acceleration.xml",
                        link_model("<Motion_Joint id=\"2\" type=\"EXPRESSION\" joint_id=\"2\""
                                   " val_type=\"A\" ic_disp=\"0.05\" ic_vel=\"-0.1\""
                                   " expr=\"0.2*SIN(2*PI*TIME)\"/>\n")),
        test_write_file("motion_slider_acceleration_motsub.xml",
                        link_model("<Motion_Joint id=\"2\" type=\"USERSUB\" joint_id=\"2\""
                                   " val_type=\"A\" ic_disp=\"0.05\" ic_vel=\"-0.1\""
                                   " usrsub_param_string=\"USER(0.2, 6.283185307179586)\""
                                   " usrsub_fnc_name=\"SWING\" usrsub_dll_name=\"libtp_routines.so\"/>\n"))};
    static const struct {
        int path;
        hx_method method;
        double rtol, coordinate, rate;
        const char *what;
    } runs[] = {
        {0, HX_METHOD_DOPRI5, 1e-10, 1e-10, 1e-10, "DOPRI5, by expression"},
        {0, HX_METHOD_BDF, 1e-8, 1e-6, 1e-6, "BDF, by expression"},
        {1, HX_METHOD_DOPRI5, 1e-10, 1e-10, 1e-10, "DOPRI5, by MOTSUB"},
    };
    for (size_t k = 0; k < sizeof runs / sizeof runs[0]; ++k) {
        sim s;
        sim_run(&s, paths[runs[k].path], runs[k].method, runs[k].rtol, 1.0, 0.05);
        double worst[3];
        check_accelerated(&s, 1, 'T', 0.05, -0.1, worst);
        printf("%s: an acceleration motion between bodies: the coordinate against the closed"
               " form %.3g, its rate %.3g, the states %.3g\n", runs[k].what, worst[0], worst[1],
               worst[2]);
        assert_true(worst[0] < runs[k].coordinate);
        assert_true(worst[1] < runs[k].rate);
        assert_true(worst[2] < runs[k].coordinate);
        assert_true(link_turned(&s) > 1.0);
        if (runs[k].method == HX_METHOD_BDF) {
            long outside = 0;
            const int last = s.path.rows - 1;
            const double diff = jacobian_against_differences(
                &s.dynamics, s.path.t[last], s.path.y + (size_t)last * (size_t)s.path.n,
                "acceleration motion", &outside);
            assert_true(diff < 1e-5);
            assert_int_equal(outside, 0);
        }
        sim_close(&s);
    }
}

/* Two links: the first (body 2) on a revolute to ground (not its only
 * joint: both bodies are free), the second (body 3) on a revolute (joint 2, between two moving bodies) at the
 * first's tip, both axes along world z; gravity across and a torque on the
 * first. */
static const char *double_link_model(const char *motions)
{
    static char text[4096];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Body_Ground id=\"1\"/>\n"
             "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
             "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.3\" inertia_zz=\"0.3\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.4\"/>\n"
             "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
             "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"0.8\"/>\n"
             "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"0.7\" inertia_xx=\"0.02\" inertia_yy=\"0.03\" inertia_zz=\"0.04\"/>\n"
             "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"1.1\"/>\n"
             "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"0.8\"/>\n"
             "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
             "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"31\" j_marker_id=\"22\"/>\n"
             "<Force_Scalar_TwoBody id=\"1\" type=\"TORQUE\" i_marker_id=\"21\" j_marker_id=\"10\" val=\"3\"/>\n"
             "%s</Model></MotionSolve>\n",
             motions);
    return text;
}

/* The same acceleration on the revolute between the two links, from
 * ic_disp = 0.3 rad and ic_vel = 4 rad/s: the joint turns about 8 rad in
 * 2 s, past pi, so the coordinate is unwrapped against the displacement
 * state; by DOPRI5 and BDF. */
static void acceleration_motion_on_a_revolute_between_bodies(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "motion_hinge_acceleration.xml",
        double_link_model("<Motion_Joint id=\"2\" type=\"EXPRESSION\" joint_id=\"2\""
                          " val_type=\"A\" ic_disp=\"0.3\" ic_vel=\"4\""
                          " expr=\"0.2*SIN(2*PI*TIME)\"/>\n"));
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 2; ++k) {
        sim s;
        sim_run(&s, path, methods[k], k == 0 ? 1e-10 : 1e-8, 2.0, 0.05);
        assert_int_equal(s.dynamics.dof[1].kind, HX_DOF_FREE);
        assert_int_equal(s.dynamics.dof[2].kind, HX_DOF_FREE);
        double worst[3];
        check_accelerated(&s, 1, 'R', 0.3, 4.0, worst);
        printf("%s: an acceleration motion on a revolute between bodies: the angle against"
               " the closed form %.3g, its rate %.3g, the states %.3g\n",
               k == 0 ? "DOPRI5" : "BDF", worst[0], worst[1], worst[2]);
        assert_true(worst[0] < (k == 0 ? 1e-10 : 1e-6));
        assert_true(worst[1] < (k == 0 ? 1e-10 : 1e-6));
        assert_true(s.path.t[s.path.rows - 1] > 1.99);
        assert_true(accel_displacement(0.3, 4.0, 2.0) > 2.0 * M_PI);
        sim_close(&s);
    }
}

/* An acceleration motion on a revolute to ground (a reduced joint) runs as
 * before: the body's own coordinate and rate integrate f from ic_disp and
 * ic_vel (no row, no states of the motion's own). */
static double pendulum_accel_displacement(double t)
{
    return accel_displacement(0.05, -0.1, t);
}

static double pendulum_accel_velocity(double t)
{
    return accel_velocity(-0.1, t);
}

static void acceleration_motion_to_ground(void **state)
{
    (void)state;
    sim s;
    run_driven_pendulum(&s, "motion_pendulum_acceleration.xml",
                        "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" val_type=\"A\""
                        " ic_disp=\"0.05\" ic_vel=\"-0.1\" expr=\"0.2*SIN(2*PI*TIME)\"/>\n",
                        1.0, pendulum_accel_displacement, pendulum_accel_velocity, 1e-10, 1e-10);
    assert_int_equal(s.dynamics.nmotions, 0);
    assert_int_equal(s.dynamics.nmotion_states, 0);
    assert_int_equal(s.dynamics.driver[1], 0);
    sim_close(&s);
}

/* What the readers refuse, each at its file:line (and column for the
 * expression's input). */
static void refused_expressions(void **state)
{
    (void)state;
    static const struct {
        const char *name, *motion, *what[3];
    } cases[] = {
        {"motion_state.xml",
         "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" expr=\"TIME + DX(30, 20)\"/>\n",
         {"motion_state.xml:15:8: Motion_Joint 1: expr: DX(30,20)", "reads TIME alone", ""}},
        {"motion_diff.xml",
         "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" expr=\"VARVAL(4)\"/>\n",
         {"motion_diff.xml:15:", "Motion_Joint 1", "VARVAL"}},
        {"motion_noexpr.xml", "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\"/>\n",
         {"motion_noexpr.xml:15:", "Motion_Joint 1", "attribute expr is missing"}},
        {"motion_both.xml",
         "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" expr=\"TIME\""
         " usrsub_param_string=\"USER(1, 1)\"/>\n",
         {"motion_both.xml:15:", "Motion_Joint 1", "takes no user routine"}},
        {"motion_slider_icdisp.xml",
         "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"2\" val_type=\"V\" ic_disp=\"0.1\""
         " expr=\"TIME\"/>\n",
         {"motion_slider_icdisp.xml:15:", "Motion_Joint 1: ic_disp on joint 2", "leave ic_disp out"}},
        {"motion_user_expr.xml",
         "<Motion_Joint id=\"1\" type=\"USERSUB\" joint_id=\"1\" expr=\"TIME\""
         " usrsub_param_string=\"USER(1, 1)\" usrsub_fnc_name=\"SWING\"/>\n",
         {"motion_user_expr.xml:15:", "Motion_Joint 1", "takes no expr"}},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        hx_message msg;
        hx_model *m = hx_model_read(test_write_file(cases[k].name, link_model(cases[k].motion)),
                                    NULL, &msg);
        if (m != NULL) {
            hx_model_free(m);
            fail_msg("%s was read; expected an error", cases[k].name);
        }
        assert_contains(msg.text, cases[k].what[0], cases[k].what[1], cases[k].what[2]);
    }
}

/* The dataset's form: MOTION/1, JOINT=1, ROTATION, FUNCTION=10D*TIME drives
 * the revolute as the XML's EXPRESSION does; one reading the state is
 * refused at its line and column. */
static void dataset_motion_function(void **state)
{
    (void)state;
    const char *head = "motion\nPART/1, GROUND\nMARKER/10, PART=1\n"
                       "PART/2, MASS=2, CM=20, IP=0.1,0.3,0.3\nMARKER/20, PART=2, QP=0.4,0,0\n"
                       "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\n"
                       "ACCGRAV/JGRAV=-9.81\n";
    char text[1024];
    snprintf(text, sizeof text, "%sMOTION/1, JOINT=1, ROTATION, FUNCTION=10D*TIME\nEND\n", head);
    sim s;
    sim_run(&s, test_write_file("motion.adm", text), HX_METHOD_DOPRI5, 1e-10, 1.0, 0.1);
    assert_int_equal(s.session.model->nunsimulated, 0);
    const int q = sim_joint_q(&s, 1);
    for (int row = 0; row < s.path.rows; ++row)
        assert_close(sim_state(&s, row, q), 10.0 * M_PI / 180.0 * s.path.t[row], 0, 1e-14);
    sim_close(&s);
    snprintf(text, sizeof text, "%sMOTION/1, JOINT=1, ROTATION,\n, FUNCTION=AZ(21, 10)\nEND\n",
             head);
    hx_message msg;
    hx_model *m = hx_model_read(test_write_file("motion_state.adm", text), NULL, &msg);
    if (m != NULL) {
        hx_model_free(m);
        fail_msg("motion_state.adm was read; expected an error");
    }
    assert_contains(msg.text, "motion_state.adm:10:12: MOTION/1: Motion_Joint 1: expr: AZ(21,10)",
                    "reads TIME alone");
}

/* The dataset's form: tests/data/redundant/four_bar_revolutes.adm with
 * MOTION/1, JOINT = 1, ROTATION, ACCELERATION, ICVEL = 2, FUNCTION =
 * 0.5*SIN(2*PI*TIME) on the crank's revolute (not reduced: the crank has two
 * joints): AZ from 0 where the model places it, against 2 t + (0.5 / 2 pi) t -
 * (0.5 / 4 pi^2) sin 2 pi t, by hand. */
static void dataset_acceleration_motion(void **state)
{
    (void)state;
    FILE *f = fopen(DATA_DIR "/redundant/four_bar_revolutes.adm", "r");
    assert_non_null(f);
    static char text[8192];
    const size_t n = fread(text, 1, sizeof text - 256, f);
    fclose(f);
    text[n] = '\0';
    char *end = strstr(text, "\nEND");
    assert_non_null(end);
    snprintf(end, sizeof text - (size_t)(end - text),
             "\nMOTION/1, JOINT = 1, ROTATION, ACCELERATION, ICVEL = 2\n"
             ", FUNCTION = 0.5*SIN(2*PI*TIME)\nEND\n");
    sim s;
    sim_run(&s, test_write_file("four_bar_accelerated.adm", text), HX_METHOD_DOPRI5, 1e-10, 1.0,
            0.05);
    assert_int_equal(s.session.model->nunsimulated, 0);
    assert_int_equal(s.dynamics.nmotion_states, 2);
    double worst = 0.0;
    for (int row = 0; row < s.path.rows; ++row) {
        const double t = s.path.t[row], *y = s.path.y + (size_t)row * (size_t)s.path.n;
        const double closed = 2.0 * t + 0.5 / (2.0 * M_PI) * t -
                              0.5 / (4.0 * M_PI * M_PI) * sin(2.0 * M_PI * t);
        double a;
        hx_joint_coordinate_near(&s.dynamics, 0, 'R', y, closed, &a, NULL, NULL);
        worst = fmax(worst, fabs(a - closed));
    }
    printf("the dataset's acceleration motion on the four-bar's crank: %.3g from the closed"
           " form\n", worst);
    assert_true(worst < 1e-10);
    sim_close(&s);
}

/* The driven slider-crank (tests/data/driven_slider_crank.xml and its
 * dataset twin, MOTION/1 ... FUNCTION = 10*TIME; not among the bundled
 * examples: its crank's acceleration row is zero, which test_jacobian's
 * comparison of every example measures as noise, docs/examples.md): the crank's angle
 * is 10 t and the slider at r cos(10 t) + sqrt(l^2 - r^2 sin^2(10 t)),
 * r = 0.1, l = 0.4 (its cm is at B), at every output; the two readings' runs
 * the same to the bit. */
static void bundled_driven_slider_crank(void **state)
{
    (void)state;
    const char *names[2] = {DATA_DIR "/driven_slider_crank.xml", DATA_DIR "/driven_slider_crank.adm"};
    sim s[2];
    for (int k = 0; k < 2; ++k) {
        sim_run(&s[k], names[k], HX_METHOD_DOPRI5, 1e-10, 2.0, 0.01);
        const hx_dynamics *d = &s[k].dynamics;
        assert_int_equal(d->nmotions, 1);
        const hx_body_dof *crank = &d->dof[1], *slider = &d->dof[3];
        const double r = 0.1, l = 0.4;
        for (int row = 0; row < s[k].path.rows; ++row) {
            const double t = s[k].path.t[row], a = 10.0 * t;
            const double angle = atan2(sim_state(&s[k], row, crank->q + 1),
                                       sim_state(&s[k], row, crank->q));
            assert_close(remainder(angle - a, 2.0 * M_PI), 0.0, 0, 1e-10);
            const double x = r * cos(a) + sqrt(l * l - r * r * sin(a) * sin(a));
            assert_close(sim_state(&s[k], row, slider->q), x, 0, 1e-10);
        }
        assert_true(s[k].path.t[s[k].path.rows - 1] > 1.99);
    }
    assert_int_equal(s[0].path.rows, s[1].path.rows);
    assert_memory_equal(s[0].path.y, s[1].path.y,
                        sizeof(double) * (size_t)s[0].path.rows * (size_t)s[0].path.n);
    for (int k = 0; k < 2; ++k)
        sim_close(&s[k]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(time_derivatives_against_closed_forms),
        cmocka_unit_test(time_derivatives_at_the_start),
        cmocka_unit_test(revolute_to_ground_by_expression),
        cmocka_unit_test(translational_between_moving_bodies_by_expression),
        cmocka_unit_test(expression_against_motsub),
        cmocka_unit_test(velocity_motion_integrated),
        cmocka_unit_test(velocity_motion_between_moving_bodies),
        cmocka_unit_test(acceleration_motion_between_moving_bodies),
        cmocka_unit_test(acceleration_motion_on_a_revolute_between_bodies),
        cmocka_unit_test(acceleration_motion_to_ground),
        cmocka_unit_test(refused_expressions),
        cmocka_unit_test(dataset_motion_function),
        cmocka_unit_test(dataset_acceleration_motion),
        cmocka_unit_test(bundled_driven_slider_crank),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
