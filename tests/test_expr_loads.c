/*
 * Forces given by function expressions (docs/interface.md §7.1, §8, §9.5):
 * Force_Scalar_TwoBody's val_expression, Force_Vector_OneBody's and
 * Force_Vector_TwoBody's fx..tz_expression, and the dataset's SFORCE,
 * VFORCE, VTORQUE and GFORCE that become them; their values worked by hand,
 * their reactions, the Jacobian's blocks on every body they read, and every
 * bad input named with its element and file:line:column.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/orientation_systems.h"
#include "base/vecmath.h"
#include "model_runs.h"
#include "sim/dynamics/loads.h"
#include "sim/jacobian/measure_slope.h"
#include "sim_support.h"
#include "test_support.h"

#define HEAD                                                                                   \
    "<MotionSolve><Model>\n"                                                                   \
    "<Body_Ground id=\"1\"/>\n"                                                                \
    "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"                                            \
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1\""           \
    " inertia_zz=\"1\" v_ic_x=\"1\" v_ic_y=\"2\" v_ic_z=\"0.5\"/>\n"                           \
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"3\" pos_y=\"4\"/>\n"                    \
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""           \
    " inertia_zz=\"1\" v_ic_x=\"-0.5\" w_ic_z=\"0.3\"/>\n"                                     \
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"1\" pos_y=\"-1\" pos_z=\"2\"/>\n"
#define TAIL "</Model></MotionSolve>\n"

/* The model opened from text (written as name), its dynamics evaluated at
 * its initial state: y and ydot allocated (the caller frees them). */
static void open_text(model *m, const char *name, const char *xml, double **y, double **ydot)
{
    open_model(m, test_write_file(name, xml));
    *y = model_state(m);
    *ydot = model_state(m);
    model_initial_state(m, *y);
}

static void share_of(model *m, const double *y, int k, hx_load_share *share)
{
    double *ydot = model_state(m);
    assert_int_equal(hx_dynamics_evaluate(&m->d, &m->data, 0.0, y, ydot, 0), 0);
    hx_message msg;
    assert_int_equal(hx_load_share_at(m->session.model, &m->data.frames,
                                      m->data.turn + m->session.model->njoints, k, share, &msg), 0);
    free(ydot);
}

/* The spring-damper law -k (DM - L) - c VR along the line from J to I: I at
 * (3, 4, 0) from J at the origin, moving at (1, 2, 0.5): DM = 5, VR = (3 + 8)/5
 * = 2.2, so the value is -100 (5 - 4) - 2 (2.2) = -104.4, the force on I
 * -104.4 (0.6, 0.8, 0) = (-62.64, -83.52, 0), on ground the reverse. */
static void scalar_force_by_expression_is_the_law(void **state)
{
    (void)state;
    model m;
    double *y, *ydot;
    open_text(&m, "scalar.xml",
              HEAD "<Force_Scalar_TwoBody id=\"4\" type=\"FORCE\" i_marker_id=\"20\""
                   " j_marker_id=\"10\" val_expression=\"-100*(DM(20,10) - 4) - 2*VR(20,10)\"/>\n"
                   TAIL,
              &y, &ydot);
    hx_load_share share;
    share_of(&m, y, 0, &share);
    assert_int_equal(share.count, 2);
    assert_close(share.F[0][0], -62.64, 1e-14, 0);
    assert_close(share.F[0][1], -83.52, 1e-14, 0);
    assert_close(share.F[0][2], 0.0, 0, 1e-14);
    assert_close(share.F[1][0], 62.64, 1e-14, 0);
    /* the body's acceleration: F / m = (-31.32, -41.76, 0) */
    assert_int_equal(hx_dynamics_evaluate(&m.d, &m.data, 0.0, y, ydot, 0), 0);
    const int u = m.d.dof[hx_model_body(m.session.model, 2)].u;
    assert_close(ydot[m.d.nq + u], -31.32, 1e-14, 0);
    assert_close(ydot[m.d.nq + u + 1], -41.76, 1e-14, 0);
    free(y), free(ydot);
    close_model(&m);
}

/* A torque by expression about J's z axis: -5 WZ(30) with body 3 turning at
 * 0.3 rad/s about z: -1.5 about z on body 3, +1.5 on ground. */
static void scalar_torque_by_expression(void **state)
{
    (void)state;
    model m;
    double *y, *ydot;
    open_text(&m, "torque.xml",
              HEAD "<Force_Scalar_TwoBody id=\"5\" type=\"TORQUE\" i_marker_id=\"30\""
                   " j_marker_id=\"10\" val_expression=\"-5*WZ(30)\"/>\n" TAIL,
              &y, &ydot);
    hx_load_share share;
    share_of(&m, y, 0, &share);
    assert_close(share.T[0][2], -1.5, 1e-14, 0);
    assert_close(share.T[0][0], 0.0, 0, 1e-15);
    assert_close(share.T[1][2], 1.5, 1e-14, 0);
    free(y), free(ydot);
    close_model(&m);
}

/* A Force_Vector_TwoBody by expressions, in the axes of a reference marker
 * turned 90 degrees about z (its x is the world's y): fx = -10 DX(20,30),
 * with DX(20,30) = 3 - 1 = 2 in the world's axes, is -20 along the world's
 * y; fy = TIME + 7 = 7 along the world's -x; tz = VZ(20,30) = 0.5 - 0 = 0.5
 * about z. Applied at I on body 2, its reverse at the same point on body 3. */
static void vector_forces_between_two_bodies(void **state)
{
    (void)state;
    model m;
    double *y, *ydot;
    open_text(&m, "vector.xml",
              HEAD "<Reference_Marker id=\"11\" body_id=\"1\" psi=\"1.5707963267948966\"/>\n"
                   "<Force_Vector_TwoBody id=\"6\" type=\"ForceAndTorque\" i_marker_id=\"20\""
                   " j_floating_marker_id=\"30\" ref_marker_id=\"11\""
                   " fx_expression=\"-10*DX(20,30)\" fy_expression=\"TIME + 7\""
                   " tz_expression=\"VZ(20,30)\"/>\n" TAIL,
              &y, &ydot);
    hx_load_share share;
    share_of(&m, y, 0, &share);
    assert_int_equal(share.count, 2);
    assert_int_equal(share.body[0], hx_model_body(m.session.model, 2));
    assert_int_equal(share.body[1], hx_model_body(m.session.model, 3));
    assert_close(share.F[0][0], -7.0, 1e-14, 0);
    assert_close(share.F[0][1], -20.0, 1e-14, 0);
    assert_close(share.T[0][2], 0.5, 1e-14, 0);
    for (int i = 0; i < 3; ++i) {
        assert_close(share.F[1][i], -share.F[0][i], 0, 0);
        assert_close(share.point[1][i], share.point[0][i], 0, 0);
    }
    assert_close(share.point[0][0], 3.0, 0, 0);
    free(y), free(ydot);
    close_model(&m);
}

/* The Jacobian's load blocks on every body an expression reads: a one-body
 * force on body 2 that measures body 3 (no other element joins them), a
 * two-body force and a scalar damper, against differences of the whole
 * right-hand side, away from the start (every input varies). */
static void jacobian_of_expression_loads_equals_differences(void **state)
{
    (void)state;
    model m;
    double *y, *ydot;
    open_text(&m, "jacobian.xml",
              HEAD "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
                   " fx_expression=\"-50*DX(20,30) - 3*VX(20,30)\""
                   " fy_expression=\"-20*DY(20,30,20)*DZ(30,10)\" tz_expression=\"-2*AZ(20,30)\"/>\n"
                   "<Force_Vector_TwoBody id=\"8\" type=\"ForceOnly\" i_marker_id=\"30\""
                   " j_floating_marker_id=\"20\" fz_expression=\"-40*DZ(30,20) - WX(30,20)\"/>\n"
                   "<Force_Scalar_TwoBody id=\"9\" type=\"FORCE\" i_marker_id=\"30\""
                   " j_marker_id=\"10\" val_expression=\"-30*(DM(30,10) - 2) - 0.5*VR(30,10)\"/>\n"
                   TAIL,
              &y, &ydot);
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-9, 0.3, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    long outside = 0;
    const double worst = jacobian_against_differences(&m.d, 0.3, y, "expression loads", &outside);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
    free(y), free(ydot);
    close_model(&m);
}

/* A number in [-1, 1) from a fixed sequence (the test is the same every run). */
static double next(unsigned *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return ((*seed >> 8) & 0xffffff) / 8388608.0 - 1.0;
}

/* Frame f moved by s mo: p + s dp, R turned by s dth (world axes), v + s dv,
 * w + s dw. */
static void moved_frame(const hx_frame *f, const hx_motion *mo, double s, hx_frame *out)
{
    *out = *f;
    if (mo == NULL)
        return;
    double turn[9], axis[3];
    const double angle = s * v3_norm(mo->dth);
    v3_scale(axis, mo->dth, 1.0 / v3_norm(mo->dth));
    m3_axis_angle(turn, axis, angle);
    m3_mul(out->R, turn, f->R);
    v3_axpy(out->p, s, mo->dp);
    v3_axpy(out->v, s, mo->dv);
    v3_axpy(out->w, s, mo->dw);
}

/* Every measure's slope (measure_slope.h), ORIENT's in every system and
 * component among them, against central differences of
 * its value (hx_measure_value) along the same motion, at 40 sets of four
 * frames and motions drawn at random (every position, axis, velocity and
 * angular velocity varies; a frame left still now and then, as the world's
 * is): a wrong sign, factor or index in any formula fails here. */
static void measure_slopes_against_differences(void **state)
{
    (void)state;
    unsigned seed = 7u;
    double worst = 0.0;
    for (int trial = 0; trial < 40; ++trial) {
        hx_frame f[4];
        hx_motion mo[4];
        const hx_motion *m[4];
        for (int a = 0; a < 4; ++a) {
            double axis[3] = {next(&seed), next(&seed), next(&seed)};
            v3_scale(axis, axis, 1.0 / v3_norm(axis));
            m3_axis_angle(f[a].R, axis, 3.0 * next(&seed));
            for (int i = 0; i < 3; ++i) {
                f[a].p[i] = 2.0 * next(&seed), f[a].v[i] = next(&seed), f[a].w[i] = next(&seed);
                mo[a].dp[i] = next(&seed), mo[a].dth[i] = next(&seed);
                mo[a].dv[i] = next(&seed), mo[a].dw[i] = next(&seed);
            }
            m[a] = (trial + a) % 5 == 4 ? NULL : &mo[a];
        }
        const hx_frame *const fp[4] = {&f[0], &f[1], &f[2], &f[3]};
        /* the named measures, then ORIENT's, every system and component */
        hx_measure measures[HX_MEASURE_COUNT + HX_ORIENTATION_SYSTEMS * HX_ORIENTATION_COMPONENTS];
        int count = 0;
        for (int k = 0; k < HX_MEASURE_COUNT; ++k)
            measures[count++] = (hx_measure)k;
        for (int system = 1; system <= HX_ORIENTATION_SYSTEMS; ++system)
            for (int c = 1; c <= hx_orientation_system_at(system)->components; ++c)
                measures[count++] = hx_measure_orient(system, c);
        for (int n = 0; n < count; ++n) {
            const hx_measure k = measures[n];
            const double h = 1e-6;
            hx_frame up[4], down[4];
            for (int a = 0; a < 4; ++a) {
                moved_frame(&f[a], m[a], h, &up[a]);
                moved_frame(&f[a], m[a], -h, &down[a]);
            }
            const hx_frame *const pu[4] = {&up[0], &up[1], &up[2], &up[3]};
            const hx_frame *const pd[4] = {&down[0], &down[1], &down[2], &down[3]};
            const double difference =
                (hx_measure_value((hx_measure)k, pu) - hx_measure_value((hx_measure)k, pd)) / (2 * h);
            const double slope = hx_measure_slope((hx_measure)k, fp, m);
            const double error = fabs(slope - difference) / fmax(1.0, fabs(difference));
            if (error > 1e-6)
                fail_msg("%s (measure %d), trial %d: slope %.12g, differences %.12g",
                         hx_measure_name(k), (int)k, trial, slope, difference);
            worst = fmax(worst, error);
        }
    }
    printf("measure slopes against differences: worst relative error %.3g\n", worst);
}

/* The exact load blocks (load_blocks.c) on every measure an expression may
 * read, against differences of the whole right-hand side at a state away
 * from the start (both bodies turning about every axis, a state's rate
 * moved): a vector load between two bodies in the axes of a marker on the
 * second (its turning enters), a scalar torque about the z of a turned
 * marker on body 2, a scalar force and its action-only twin, each reading
 * DIF(1) too. A sign, a lever arm or a column wrong in any of them fails. */
static void exact_load_blocks_on_every_measure(void **state)
{
    (void)state;
    model m;
    double *y, *ydot;
    open_text(&m, "measures.xml",
              "<MotionSolve><Model>\n"
              "<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
              "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"1.5\""
              " inertia_zz=\"2\" v_ic_x=\"1\" v_ic_y=\"2\" v_ic_z=\"0.5\" w_ic_x=\"0.4\""
              " w_ic_y=\"-0.7\" w_ic_z=\"0.9\"/>\n"
              "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"3\" pos_y=\"4\"/>\n"
              "<Reference_Marker id=\"21\" body_id=\"2\" pos_x=\"3.5\" pos_y=\"4\" pos_z=\"0.3\""
              " psi=\"0.4\" theta=\"0.7\" phi=\"-0.3\"/>\n"
              "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
              " inertia_zz=\"1.2\" v_ic_x=\"-0.5\" w_ic_x=\"-0.2\" w_ic_y=\"0.5\" w_ic_z=\"0.3\"/>\n"
              "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"1\" pos_y=\"-1\" pos_z=\"2\"/>\n"
              "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"1.2\" pos_y=\"-1\" pos_z=\"2.5\""
              " psi=\"-0.6\" theta=\"0.5\" phi=\"1.1\"/>\n"
              "<Control_Diff id=\"1\" type=\"EXPRESSION\" ic=\"0.5\""
              " expr=\"-DIF(1) + 0.1*DX(20,10)\"/>\n"
              "<Force_Vector_TwoBody id=\"8\" type=\"ForceAndTorque\" i_marker_id=\"21\""
              " j_floating_marker_id=\"30\" ref_marker_id=\"31\""
              " fx_expression=\"-3*AX(21,31) + 2*PSI(21,31) - DIF(1)*AZ(31,21)\""
              " fy_expression=\"THETA(21,31)*PHI(21,31) - 5*DY(21,30,31)\""
              " fz_expression=\"YAW(31,21) - PITCH(21,31) + ROLL(21,31) - 4*DZ(21,30)\""
              " tx_expression=\"INCANG(21,10,30) - 0.5*VX(21,30,31,20)\""
              " ty_expression=\"0.1*VM(21,30,31) - WY(21,30,31)\""
              " tz_expression=\"-WM(21,30) + VZ(30,21,20,31)\"/>\n"
              "<Force_Scalar_TwoBody id=\"9\" type=\"TORQUE\" i_marker_id=\"30\""
              " j_marker_id=\"21\" val_expression=\"-4*AY(30,21) - WZ(30,21,21) + DIF(1)\"/>\n"
              "<Force_Scalar_TwoBody id=\"10\" type=\"FORCE\" i_marker_id=\"20\""
              " j_marker_id=\"31\" val_expression=\"-30*(DM(20,31) - 4) - VR(20,31,21)"
              " + DIF(1)*DX(20,30,21)\"/>\n"
              "<Force_Scalar_TwoBody id=\"11\" type=\"FORCE\" i_marker_id=\"30\""
              " j_marker_id=\"21\" is_action_only=\"TRUE\""
              " val_expression=\"-10*(DM(30,21) - 3) - 0.5*VR(30,21)\"/>\n"
              "<Force_Scalar_TwoBody id=\"12\" type=\"TORQUE\" i_marker_id=\"21\""
              " j_marker_id=\"31\" val_expression=\"-2*ORIENT(2,1,21,31) + ORIENT(15,3,21,31)"
              " - 3*ORIENT(27,2,21,31) + ORIENT(28,3,21) - ORIENT(29,6,21,31)"
              " + ORIENT(9,2,31,21)*ORIENT(26,2,21,31) + ORIENT(25,1,21,31)\"/>\n" TAIL,
              &y, &ydot);
    hx_simulation_result r = simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-10, 0.2, y);
    assert_int_equal(r.status, HX_INTEGRATION_OK);
    long outside = 0;
    const double worst = jacobian_against_differences(&m.d, 0.2, y, "every measure", &outside);
    printf("exact load blocks on every measure: worst %.3g against differences\n", worst);
    assert_int_equal(outside, 0);
    assert_true(worst < 1e-6);
    free(y), free(ydot);
    close_model(&m);
}

/* The dataset's statements into the same elements: an SFORCE by an
 * expression equals its XML, a VFORCE between two parts a Force_Vector_TwoBody
 * and a VTORQUE with JFLOAT on ground a Force_Vector_OneBody. */
static void dataset_forces_by_expressions(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "forces.adm",
        "ADAMS/View model\n"
        "PART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=2, CM=20, IP=1,1,1, VX=1, VY=2, VZ=0.5\nMARKER/20, PART=2, QP=3,4,0\n"
        "PART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3, QP=1,-1,2\n"
        "MARKER/31, PART=3, FLOATING\nMARKER/11, PART=1, FLOATING\n"
        "SFORCE/4, TRANSLATION, I=20, J=10,\n"
        ", FUNCTION=-100*(DM(20,10) - 4) - 2*VR(20,10)\n"
        "VFORCE/5, I=20, JFLOAT=31, FX=-10*DX(20,30)\\FZ=3\n"
        "VTORQUE/6, I=30, JFLOAT=11, TZ=-WZ(30)\n"
        "END\n");
    model m;
    open_model(&m, path);
    const hx_model *mm = m.session.model;
    assert_int_equal(mm->nloads, 3);
    assert_int_equal(mm->nunsimulated, 0);
    assert_string_equal(hx_load_element_name(&mm->loads[0]), "Force_Scalar_TwoBody");
    assert_string_equal(hx_load_element_name(&mm->loads[1]), "Force_Vector_TwoBody");
    assert_string_equal(hx_load_element_name(&mm->loads[2]), "Force_Vector_OneBody");
    double *y = model_state(&m);
    model_initial_state(&m, y);
    hx_load_share share;
    share_of(&m, y, 0, &share); /* as the XML's: -104.4 along (0.6, 0.8, 0) */
    assert_close(share.F[0][0], -62.64, 1e-14, 0);
    assert_close(share.F[0][1], -83.52, 1e-14, 0);
    share_of(&m, y, 1, &share); /* -10 (3 - 1) along x, 3 along z, the reverse on part 3 */
    assert_int_equal(share.count, 2);
    assert_close(share.F[0][0], -20.0, 1e-14, 0);
    assert_close(share.F[0][2], 3.0, 1e-14, 0);
    assert_int_equal(share.body[1], hx_model_body(mm, 3));
    assert_close(share.F[1][0], 20.0, 1e-14, 0);
    share_of(&m, y, 2, &share);
    assert_int_equal(share.count, 1);
    free(y);
    close_model(&m);
}

/* Reads text as name; the model must not read, and its message hold each
 * needle. */
static void bad_expressions_are_named(void **state)
{
    (void)state;
    /* line 8 of the text; the column within the attribute's value: the ')' at 19 */
    sim_expect_parse_error("bad.xml",
                 HEAD "<Force_Scalar_TwoBody id=\"4\" type=\"FORCE\" i_marker_id=\"20\""
                      " j_marker_id=\"10\" val_expression=\"-100*(DM(20,10) - )\"/>\n" TAIL,
                 (const char *const[]){"bad.xml:8:19: Force_Scalar_TwoBody 4: val_expression:",
                                       "expected a number", NULL});
    sim_expect_parse_error("unknown.xml",
                 HEAD "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
                      " fy_expression=\"DX(20,99)\"/>\n" TAIL,
                 (const char *const[]){"unknown.xml:8:1: Force_Vector_OneBody 7: fy_expression:",
                                       "no Reference_Marker 99", NULL});
    sim_expect_parse_error("aryval.xml",
                 HEAD "<Reference_Array id=\"3\" type=\"IC\" num_element=\"1\"> 2 </Reference_Array>\n"
                      "<Force_Vector_OneBody id=\"7\" marker_id=\"20\""
                      " fx_expression=\"1 + ARYVAL(3,1)\"/>\n" TAIL,
                 (const char *const[]){"aryval.xml:9:5: Force_Vector_OneBody 7: fx_expression:",
                                       "ARYVAL(3,1)", "not simulated yet", NULL});
    sim_expect_parse_error("routine.xml",
                 HEAD "<Force_Vector_TwoBody id=\"6\" type=\"ForceOnly\" i_marker_id=\"20\""
                      " j_floating_marker_id=\"30\" fx_expression=\"1\""
                      " usrsub_param_string=\"USER(1)\"/>\n" TAIL,
                 (const char *const[]){"Force_Vector_TwoBody 6: fx_expression", "give one of them",
                                       NULL});
    /* a dataset's: the statement, and the column of FOO (the value begins at 12) */
    sim_expect_parse_error("bad.adm",
                 "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=3,4,0\n"
                 "SFORCE/4, TRANSLATION, I=20, J=10,\n"
                 ", FUNCTION=-100*(DM(20,10) - 4) - 2*FOO\nEND\n",
                 (const char *const[]){"bad.adm:7:37: SFORCE/4: Force_Scalar_TwoBody 4:",
                                       "unknown name FOO", NULL});
    sim_expect_parse_error("badid.adm",
                 "ADAMS/View model\nPART/1, GROUND\nMARKER/10, PART=1\n"
                 "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2, QP=3,4,0\n"
                 "GFORCE/4, I=20, JFLOAT=10, FX=0\\TY=DX(20,77)\nEND\n",
                 (const char *const[]){"badid.adm:6:", "GFORCE/4:", "no Reference_Marker 77",
                                       NULL});
}

/* A fault during a run names the element, the file:line:column and the time:
 * 1/(DX(20,10) - 3) divides by zero at the start (DX = 3); SQRT of a negative
 * number is outside its domain. */
static void faults_during_a_run_are_named(void **state)
{
    (void)state;
    static const char *const exprs[2][2] = {{"1/(DX(20,10) - 3)", "division by zero"},
                                            {"SQRT(DX(20,10) - 4)", "SQRT"}};
    for (int k = 0; k < 2; ++k) {
        char xml[4096];
        snprintf(xml, sizeof xml,
                 HEAD "<Force_Scalar_TwoBody id=\"4\" type=\"FORCE\" i_marker_id=\"20\""
                      " j_marker_id=\"10\" val_expression=\"%s\"/>\n" TAIL,
                 exprs[k][0]);
        model m;
        double *y, *ydot;
        open_text(&m, "fault.xml", xml, &y, &ydot);
        assert_int_equal(hx_dynamics_evaluate(&m.d, &m.data, 0.0, y, ydot, 0), -1);
        assert_contains(m.data.message, "fault.xml:8:", "Force_Scalar_TwoBody 4", exprs[k][1],
                        "t = 0");
        free(y), free(ydot);
        close_model(&m);
    }
}

/* The bundled spring_damper.xml (the law as an expression) and its twin by
 * an SFOSUB that computes the same law from c_sysfnc's DM and VR
 * (tp_scalar.c's SPRING_DAMPER) run the same motion to rounding (1e-12): both
 * measure with the harness's one implementation; the SFOSUB's value is turned
 * into a force by the user-force path, whose arithmetic differs in the last
 * bits. */
static void expression_and_sfosub_twins_run_the_same(void **state)
{
    (void)state;
    FILE *f = fopen(EXAMPLES_DIR "/spring_damper.xml", "r");
    assert_non_null(f);
    static char text[8192], changed[8192];
    const size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    const char *law = "val_expression=\"-1000*(DM(20,10) - 10) - 2*VR(20,10)\"";
    const char *at = strstr(text, law);
    assert_non_null(at);
    snprintf(changed, sizeof changed,
             "%.*susrsub_param_string=\"USER(20, 10, 1000, 10, 2)\" usrsub_fnc_name=\"SPRING_DAMPER\""
             " usrsub_dll_name=\"libtp_scalar.so\"%s",
             (int)(at - text), text, at + strlen(law));
    setenv("MS_USERDLL_DIR", TP_LIBRARY_DIR, 1);
    sim a, b;
    sim_run(&a, EXAMPLES_DIR "/spring_damper.xml", HX_METHOD_DOPRI5, 1e-9, 0.05, 0.005);
    sim_run(&b, test_write_file("spring_damper_sfosub.xml", changed), HX_METHOD_DOPRI5, 1e-9,
            0.05, 0.005);
    assert_int_equal(a.path.rows, b.path.rows);
    assert_true(a.path.rows > 5);
    assert_int_equal(a.session.model->nloads, 1); /* the expression is the harness's load */
    assert_int_equal(b.session.model->nforces, 1); /* the twin a user force element */
    /* the positions moved: the spring is working */
    assert_true(fabs(sim_state(&a, a.path.rows - 1, 1) - sim_state(&a, 0, 1)) > 1.0);
    for (int r = 0; r < a.path.rows; ++r)
        for (int k = 0; k < 13; ++k)
            assert_close(sim_state(&a, r, k), sim_state(&b, r, k), 1e-12, 1e-12);
    sim_close(&a);
    sim_close(&b);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scalar_force_by_expression_is_the_law),
        cmocka_unit_test(scalar_torque_by_expression),
        cmocka_unit_test(vector_forces_between_two_bodies),
        cmocka_unit_test(jacobian_of_expression_loads_equals_differences),
        cmocka_unit_test(measure_slopes_against_differences),
        cmocka_unit_test(exact_load_blocks_on_every_measure),
        cmocka_unit_test(dataset_forces_by_expressions),
        cmocka_unit_test(bad_expressions_are_named),
        cmocka_unit_test(faults_during_a_run_are_named),
        cmocka_unit_test(expression_and_sfosub_twins_run_the_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
