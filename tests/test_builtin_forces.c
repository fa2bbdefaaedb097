/*
 * The built-in linear force elements (docs/interface.md §7.15, §9.5):
 * SPRINGDAMPER / Force_SpringDamper and BUSHING / Force_Bushing. A mass on a
 * translational spring-damper and a hinged wheel on a rotational one against
 * the damped oscillator's closed form (DOPRI5 and BDF, the BDF Jacobian
 * against differences); a bushing at a displaced, turned, moving state
 * against its six components worked by hand, its J side with the moment of
 * the offset, and SFORCE / BUSHING in requests; the bushing and the GFORCE
 * of the same expressions, the dataset and its XML twin, run bit for bit
 * alike; bad input named with file:line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frames/frames.h"
#include "model_runs.h"
#include "sim_support.h"
#include "test_support.h"

/* The frame of marker id at (t, y). */
static hx_frame marker_at(model *m, double t, const double *y, int id)
{
    double *ydot = model_state(m);
    if (hx_dynamics_evaluate(&m->d, &m->data, t, y, ydot, 0) != 0)
        fail_msg("%s", m->data.message);
    hx_frame scratch;
    const hx_frame f = *hx_frames_marker(&m->data.frames,
                                         hx_model_marker(m->session.model, id), &scratch);
    free(ydot);
    return f;
}

/* The damped oscillator's deviation u'' + 2 s u' + w0^2 u = 0 from u0 at
 * rest: its value and rate at t. */
static void oscillator(double u0, double s, double w0, double t, double *u, double *du)
{
    const double wd = sqrt(w0 * w0 - s * s), e = exp(-s * t);
    *u = u0 * e * (cos(wd * t) + s / wd * sin(wd * t));
    *du = -u0 * e * (w0 * w0 / wd) * sin(wd * t);
}

/* 2 kg on x, K 50, C 2, LENGTH 1, FORCE 5: at rest at 1.1, started at 1.5. */
static const char translational[] =
    "translational\n"
    "UNITS/SYSTEM=MKS\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=1.5,0,0\n"
    "SPRINGDAMPER/5, TRANSLATION, I=20, J=10, K=50, C=2, LENGTH=1, FORCE=5\n"
    "END\n";

/* A wheel (Izz 0.5) on a REVOLUTE about z, KT 8, CT 0.4, ANGLE 0.1, TORQUE
 * 0.2: at rest at 0.125 rad, started at 0.3. */
static const char rotational[] =
    "rotational\n"
    "UNITS/SYSTEM=MKS\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=3, CM=20, IP=1,1,0.5, REULER=0.3,0,0\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, REVOLUTE, I=20, J=10\n"
    "SPRINGDAMPER/6, ROTATIONAL, I=20, J=10, KT=8, CT=0.4, ANGLE=0.1, TORQUE=0.2\n"
    "END\n";

static void check_oscillator(const char *name, const char *text, hx_method method, int rotation)
{
    model m;
    const double t = 1.0;
    double *y = model_run_text(name, text, method, HX_JACOBIAN_ANALYTIC, 1e-10, t, &m);
    const hx_frame f = marker_at(&m, t, y, 20);
    double u, du;
    if (rotation) {
        oscillator(0.3 - 0.125, 0.4, 4.0, t, &u, &du);
        assert_close(atan2(f.R[3], f.R[0]), 0.125 + u, 0, 1e-6);
        assert_close(f.w[2], du, 0, 1e-6);
    } else {
        oscillator(0.4, 0.5, 5.0, t, &u, &du);
        assert_close(f.p[0], 1.1 + u, 0, 1e-6);
        assert_close(f.v[0], du, 0, 1e-6);
    }
    if (method == HX_METHOD_BDF) { /* the partials of the generated expressions */
        long outside = 0;
        assert_true(jacobian_against_differences(&m.d, t, y, name, &outside) < 1e-6);
        assert_int_equal(outside, 0);
    }
    free(y);
    close_model(&m);
}

static void translational_springdamper_is_the_damped_oscillator(void **state)
{
    (void)state;
    check_oscillator("translational.adm", translational, HX_METHOD_DOPRI5, 0);
    check_oscillator("translational.adm", translational, HX_METHOD_BDF, 0);
}

static void rotational_springdamper_is_the_damped_oscillator(void **state)
{
    (void)state;
    check_oscillator("rotational.adm", rotational, HX_METHOD_DOPRI5, 1);
    check_oscillator("rotational.adm", rotational, HX_METHOD_BDF, 1);
}

/* The same wheel at its rest angle 0.125 rad spun at 20 rad/s: the swing
 * u = e^(-s t) (v0 / wd) sin(wd t) (s 0.4, wd = sqrt(16 - 0.16)) reaches 4.4 rad
 * from it, past a half turn, which the spring counts as Adams' does: the
 * hinge's (unwrapped) angle follows 0.125 + u at 0.4 s (past pi) and at 1 s
 * (back), DOPRI5 and BDF. */
static const char spun[] =
    "spun\n"
    "UNITS/SYSTEM=MKS\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=3, CM=20, IP=1,1,0.5, REULER=0.125,0,0, WZ=20\n"
    "MARKER/20, PART=2\n"
    "JOINT/1, REVOLUTE, I=20, J=10\n"
    "SPRINGDAMPER/6, ROTATIONAL, I=20, J=10, KT=8, CT=0.4, ANGLE=0.1, TORQUE=0.2\n"
    "END\n";

static void rotational_springdamper_counts_turns(void **state)
{
    (void)state;
    const double s = 0.4, wd = sqrt(16.0 - 0.16), times[2] = {0.4, 1.0};
    const hx_method methods[2] = {HX_METHOD_DOPRI5, HX_METHOD_BDF};
    for (int k = 0; k < 4; ++k) {
        model m;
        const double t = times[k % 2];
        double *y = model_run_text("spun.adm", spun, methods[k / 2], HX_JACOBIAN_ANALYTIC,
                                   1e-10, t, &m);
        assert_int_equal(m.d.dof[1].kind, HX_DOF_REVOLUTE);
        const double u = exp(-s * t) * 20.0 / wd * sin(wd * t);
        const double du = exp(-s * t) * 20.0 * (cos(wd * t) - s / wd * sin(wd * t));
        assert_close(y[m.d.dof[1].q], 0.125 + u, 0, 1e-6);
        assert_close(y[m.d.nq + m.d.dof[1].u], du, 0, 1e-6);
        if (k % 2 == 0)
            assert_true(0.125 + u > 4.0); /* past a half turn */
        free(y);
        close_model(&m);
    }
}

/* RK4 at 1 s: the wheel turns some 10 rad in its first step, which no turn
 * count can follow: the run stops naming the spring. */
static void a_spring_turned_past_pi_in_one_step_is_refused(void **state)
{
    (void)state;
    assert_contains(sim_rk4_refused("spun_step.adm", spun, 1.0, 2.0),
                    "Force_SpringDamper 6: turned", "in one step, from t = 0 to 1: more than pi");
}

/* J (10) on ground turned a quarter about z (its x the world's y, its y the
 * world's -x); I (20) the centre of part 2 at (1, 2, 3), so (2, -1, 3) in
 * J's axes, turned 0.2 rad about J's x axis (AX 0.2, AY = AZ = 0) and
 * moving. SPRINGDAMPER/6 from 11 at the origin. */
static const char bushing[] =
    "bushing\n"
    "UNITS/SYSTEM=MKS\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1, REULER=90D,0,0\n"
    "MARKER/11, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=1,2,3, REULER=90D,0.2,0, VX=0.5, VY=-0.3, VZ=0.2,"
    " WX=0.1, WY=0.2, WZ=0.3\n"
    "MARKER/20, PART=2\n"
    "BUSHING/5, I=20, J=10, K=10,20,30, C=1,2,3, KT=100,200,300, CT=4,5,6, FORCE=7,8,9,"
    " TORQUE=0.7,0.8,0.9\n"
    "SPRINGDAMPER/6, TRANSLATION, I=20, J=11, K=4, C=0.25, LENGTH=1, FORCE=0.5\n"
    "SFORCE/6, TRANSLATION, I=20, J=11, FUNCTION=1.5\n"
    "SPRINGDAMPER/8, TRANSLATION, I=20, J=11, K=4, C=0.25, LENGTH=1, FORCE=0.5\n"
    "END\n";

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void bushing_components_by_hand(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "bushing.adm", bushing);
    /* the state: displacement and angles exactly; the velocities in J's axes */
    static const struct {
        const char *text;
        double value;
    } placed[6] = {{"DX(20,10,10)", 2.0}, {"DY(20,10,10)", -1.0}, {"DZ(20,10,10)", 3.0},
                   {"AX(20,10)", 0.2},    {"AY(20,10)", 0.0},     {"AZ(20,10)", 0.0}};
    for (int k = 0; k < 6; ++k)
        EXPECT(&e, placed[k].text, placed[k].value, 1e-14);
    const double v[3] = {output(&e, "VX(20,10,10,10)"), output(&e, "VY(20,10,10,10)"),
                         output(&e, "VZ(20,10,10,10)")};
    const double w[3] = {output(&e, "WX(20,10,10)"), output(&e, "WY(20,10,10)"),
                         output(&e, "WZ(20,10,10)")};
    for (int k = 0; k < 3; ++k) /* every term below acts */
        assert_true(fabs(v[k]) > 0.05 && fabs(w[k]) > 0.05);
    /* on I in J's axes: -K d - C v + FORCE, -KT a - CT w + TORQUE */
    const double F[3] = {-10 * 2.0 - 1 * v[0] + 7, -20 * -1.0 - 2 * v[1] + 8,
                         -30 * 3.0 - 3 * v[2] + 9};
    const double T[3] = {-100 * 0.2 - 4 * w[0] + 0.7, -5 * w[1] + 0.8, -6 * w[2] + 0.9};
    char text[64];
    for (int k = 0; k < 3; ++k) {
        snprintf(text, sizeof text, "BUSHING(5,0,%d,10)", k + 2);
        EXPECT(&e, text, F[k], 1e-12);
        snprintf(text, sizeof text, "BUSHING(5,0,%d,10)", k + 6);
        EXPECT(&e, text, T[k], 1e-12);
    }
    EXPECT(&e, "BUSHING(5,0,1,10)", sqrt(dot3(F, F)), 1e-12);
    /* on J at J: -F, and -T - L x F with L = (2, -1, 3) from J to I */
    const double L[3] = {2.0, -1.0, 3.0};
    const double TJ[3] = {-T[0] - (L[1] * F[2] - L[2] * F[1]),
                          -T[1] - (L[2] * F[0] - L[0] * F[2]),
                          -T[2] - (L[0] * F[1] - L[1] * F[0])};
    for (int k = 0; k < 3; ++k) {
        snprintf(text, sizeof text, "BUSHING(5,1,%d,10)", k + 2);
        EXPECT(&e, text, -F[k], 1e-12);
        snprintf(text, sizeof text, "BUSHING(5,1,%d,10)", k + 6);
        EXPECT(&e, text, TJ[k], 1e-12);
    }
    /* the net force at J is the bushing's alone; in the world's axes */
    EXPECT(&e, "TZ(10,20,10)", TJ[2], 1e-12);
    EXPECT(&e, "BUSHING(5,0,2,0)", -F[1], 1e-12); /* the world's x is J's -y */
    /* SPDP (Adams' and MotionSolve's name) reads the spring-damper: -4 (DM - 1)
     * - 0.25 VR + 0.5 along 11 to 20; SFORCE the SFORCE of its id, 1.5, and with
     * no SFORCE of its id (8) the spring-damper */
    const double dm = sqrt(14.0), vr = output(&e, "VR(20,11)");
    const double s = -4 * (dm - 1) - 0.25 * vr + 0.5;
    assert_true(fabs(vr) > 0.05);
    EXPECT(&e, "SPDP(6,0,2,0)", s * 1 / dm, 1e-12);
    EXPECT(&e, "SPDP(6,0,4,0)", s * 3 / dm, 1e-12);
    EXPECT(&e, "SPDP(6,1,3,0)", -s * 2 / dm, 1e-12);
    EXPECT(&e, "SPDP(6,0,1,0)", fabs(s), 1e-12);
    EXPECT(&e, "SFORCE(6,0,2,0)", 1.5 * 1 / dm, 1e-12);
    EXPECT(&e, "SFORCE(8,0,4,0)", s * 3 / dm, 1e-12);
    release(&e);
}

/* BUSHING/5 between two moving parts, and the GFORCE of the same
 * expressions with its floating J (31) on J's part: the same run. */
#define TWO_PARTS                                                                              \
    "UNITS/SYSTEM=MKS\n"                                                                       \
    "PART/1, GROUND\n"                                                                         \
    "MARKER/10, PART=1\n"                                                                      \
    "PART/2, MASS=2, CM=20, IP=1,2,3, QG=1,2,3, REULER=10D,20D,30D, VX=0.5, WZ=0.3, WM=10\n"   \
    "MARKER/20, PART=2\n"                                                                      \
    "PART/3, MASS=3, CM=30, IP=2,2,1, QG=0.5,1.5,2, REULER=90D,0,0, WX=-0.2, WM=10\n"         \
    "MARKER/30, PART=3\n"                                                                      \
    "MARKER/31, PART=3, FLOATING\n"
static const char bushing_run[] =
    "bushing run\n" TWO_PARTS
    "BUSHING/5, I=20, J=30, K=10,20,30, C=1,2,3, KT=100,200,300, CT=4,5,6, FORCE=7,8,9,"
    " TORQUE=0.7,0.8,0.9\n"
    "END\n";
static const char gforce_run[] =
    "gforce run\n" TWO_PARTS
    "GFORCE/5, I=20, JFLOAT=31, RM=30,\n"
    ", FX=-(10)*DX(20,30,30)-(1)*VX(20,30,30,30)+(7)\\\n"
    ", FY=-(20)*DY(20,30,30)-(2)*VY(20,30,30,30)+(8)\\\n"
    ", FZ=-(30)*DZ(20,30,30)-(3)*VZ(20,30,30,30)+(9)\\\n"
    ", TX=-(100)*AX(20,30)-(4)*WX(20,30,30)+(0.7)\\\n"
    ", TY=-(200)*AY(20,30)-(5)*WY(20,30,30)+(0.8)\\\n"
    ", TZ=-(300)*AZ(20,30)-(6)*WZ(20,30,30)+(0.9)\n"
    "END\n";
static const char bushing_xml[] =
    "<MotionSolve><Model>\n"
    "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"METER\""
    " time_unit=\"SECOND\"/>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"2\""
    " inertia_zz=\"3\" v_ic_x=\"0.5\" w_ic_z=\"0.3\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\""
    " psi=\"0.17453292519943295\" theta=\"0.3490658503988659\" phi=\"0.52359877559829882\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"3\" inertia_xx=\"2\" inertia_yy=\"2\""
    " inertia_zz=\"1\" w_ic_x=\"-0.2\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"0.5\" pos_y=\"1.5\" pos_z=\"2\""
    " psi=\"1.5707963267948966\"/>\n"
    "<Force_Bushing id=\"5\" i_marker_id=\"20\" j_marker_id=\"30\" kx=\"10\" ky=\"20\""
    " kz=\"30\" ktx=\"100\" kty=\"200\" ktz=\"300\" cx=\"1\" cy=\"2\" cz=\"3\" ctx=\"4\""
    " cty=\"5\" ctz=\"6\" preload_x=\"7\" preload_y=\"8\" preload_z=\"9\" preload_tx=\"0.7\""
    " preload_ty=\"0.8\" preload_tz=\"0.9\"/>\n"
    "</Model></MotionSolve>\n";

/* The two models from their initial states to t = 0.5: the same states bit
 * for bit (exact), or the same frames of I and J within 1e-12. */
static void same_run(const char *name_a, const char *a, const char *name_b, const char *b,
                     int exact)
{
    model ma, mb;
    double *ya = model_run_text(name_a, a, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-9, 0.5, &ma);
    double *yb = model_run_text(name_b, b, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-9, 0.5, &mb);
    assert_int_equal(ma.d.n, mb.d.n);
    for (int k = 0; k < ma.d.n && exact; ++k)
        if (ya[k] != yb[k])
            fail_msg("%s and %s: y[%d] %.17g and %.17g", name_a, name_b, k, ya[k], yb[k]);
    for (int id = 20; id <= 30; id += 10) {
        const hx_frame fa = marker_at(&ma, 0.5, ya, id), fb = marker_at(&mb, 0.5, yb, id);
        for (int k = 0; k < 3; ++k) {
            assert_close(fa.p[k], fb.p[k], 0, 1e-12);
            assert_close(fa.v[k], fb.v[k], 0, 1e-12);
            assert_close(fa.w[k], fb.w[k], 0, 1e-12);
        }
        for (int k = 0; k < 9; ++k)
            assert_close(fa.R[k], fb.R[k], 0, 1e-12);
    }
    /* the bushing acted: I's frame is not where it started */
    assert_true(fabs(marker_at(&ma, 0.5, ya, 20).p[2] - 3.0) > 1e-3);
    free(ya), free(yb);
    close_model(&ma), close_model(&mb);
}

static void bushing_is_its_gforce_and_its_xml_twin(void **state)
{
    (void)state;
    model m; /* BDF on the bushing's partials: its Jacobian against differences */
    double *y = model_run_text("bushing_bdf.adm", bushing_run, HX_METHOD_BDF,
                               HX_JACOBIAN_ANALYTIC, 1e-9, 0.5, &m);
    long outside = 0;
    assert_true(jacobian_against_differences(&m.d, 0.5, y, "bushing", &outside) < 1e-6);
    assert_int_equal(outside, 0);
    free(y);
    close_model(&m);
    same_run("bushing_run.adm", bushing_run, "gforce_run.adm", gforce_run, 1);
    same_run("bushing_run.adm", bushing_run, "bushing_run.xml", bushing_xml, 0);
}

static void bad_input_named(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"SPRINGDAMPER/5, TRANSLATION, I=20, J=10, C=2",
         "bad.adm:6:", "SPRINGDAMPER/5: TRANSLATIONAL: no stiffness K= given"},
        {"SPRINGDAMPER/5, ROTATION, I=20, J=10, CT=2",
         "bad.adm:6:", "SPRINGDAMPER/5: ROTATIONAL: no stiffness KT= given"},
        {"SPRINGDAMPER/5, ROTATION, I=20, J=10, KT=1,\n, K=2",
         "bad.adm:7:", "K is a TRANSLATIONAL one's"},
        {"SPRINGDAMPER/5, I=20, J=10, K=2", "bad.adm:6:", "give TRANSLATIONAL"},
        {"BUSHING/5, I=20, J=10, K=1,2", "bad.adm:6:", "BUSHING/5: K takes 3 values, not 2"},
        {"BUSHING/5, I=20, J=10, K=1,2,3, STIFF=4", "bad.adm:6:",
         "BUSHING/5: STIFF (column 33) is not a keyword of BUSHING"},
        {"BUSHING/5, I=20, J=10, C=1,-2,3", "bad.adm:6:", "Force_Bushing 5: cy = -2: it must not be negative"},
        {"BUSHING/5, I=20, J=99", "bad.adm:6:", "BUSHING/5: J=99 (column 20) names no MARKER"},
    };
    expect_read_errors("bad.adm", "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                       "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n", cases,
                       sizeof cases / sizeof cases[0]);
    hx_message msg;
    static const char xml[] =
        "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Force_SpringDamper id=\"3\" i_marker_id=\"10\" j_marker_id=\"10\" type=\"LINEAR\""
        " stiffness=\"1\"/>\n</Model></MotionSolve>\n";
    assert_null(hx_model_parse(xml, strlen(xml), "bad.xml", NULL, &msg));
    assert_contains(msg.text, "bad.xml:4:", "Force_SpringDamper 3: type \"LINEAR\"");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(translational_springdamper_is_the_damped_oscillator),
        cmocka_unit_test(rotational_springdamper_is_the_damped_oscillator),
        cmocka_unit_test(rotational_springdamper_counts_turns),
        cmocka_unit_test(a_spring_turned_past_pi_in_one_step_is_refused),
        cmocka_unit_test(bushing_components_by_hand),
        cmocka_unit_test(bushing_is_its_gforce_and_its_xml_twin),
        cmocka_unit_test(bad_input_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
