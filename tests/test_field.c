/*
 * The linear field (FIELD without FUNCTION / Force_Field without a routine,
 * docs/interface.md §7.17): its six components at a displaced, turned, moving
 * state against -K (d - LENGTH) - C v + FORCE worked by hand with an
 * asymmetric K whose 36 entries are told apart (Adams' KMATRIX by columns),
 * damped by CRATIO and by a CMATRIX, angles in degrees and radians; its J side
 * with the moment of the offset; a part hung on a coupled field at its static
 * equilibrium against the linear equations solved by hand; the BDF Jacobian
 * against differences and the XML twin (MotionSolve's K11 .. K66 by row and
 * column) run alike; bad input named with file:line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frames/frames.h"
#include "model/model.h"
#include "model_runs.h"
#include "sim/simulation/equilibrium.h"
#include "sim_support.h"
#include "test_support.h"

#define DEG (3.14159265358979323846 / 180.0)

/* J (10) the centre of part 3, turned and moving, spinning about every
 * axis; I (20) the centre of part 2, turned from it about every axis and
 * moving otherwise (as test_beam's). FIELD/5: KMATRIX 1 .. 36 by columns,
 * CRATIO 0.1; FIELD/6: the same stiffness, a CMATRIX of 0.5 .. 18 by columns
 * and its angles' lengths in degrees. */
#define KMATRIX                                                                                \
    "KMATRIX=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,\n"                                  \
    ",19,20,21,22,23,24,25,26,27,28,29,30,31,32,33,34,35,36"
static const char field[] =
    "field\n"
    "UNITS/SYSTEM=MKS\n"
    "PART/1, GROUND\n"
    "MARKER/1, PART=1\n"
    "PART/3, MASS=3, CM=10, IP=1,1,1, QG=0.1,-0.1,0.05, REULER=90D,4D,-3D, VX=0.2, VY=0.1,"
    " VZ=-0.3, WX=0.3, WY=-0.2, WZ=0.5, WM=1\n"
    "MARKER/10, PART=3\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0.4,2.0,-0.15, REULER=100D,9D,-5D, VX=0.5, VY=-0.3,"
    " VZ=0.2, WX=0.1, WY=0.2, WZ=0.9, WM=1\n"
    "MARKER/20, PART=2\n"
    "FIELD/5, I=20, J=10, " KMATRIX ", CRATIO=0.1,\n"
    ", LENGTH=2, 0.1, -0.2, 0.05, -0.03, 0.02, FORCE=1, 2, 3, 4, 5, 6\n"
    "FIELD/6, I=20, J=10, " KMATRIX ",\n"
    ", CMATRIX=0.5,1,1.5,2,2.5,3,3.5,4,4.5,5,5.5,6,6.5,7,7.5,8,8.5,9,9.5,10,10.5,11,\n"
    ", 11.5,12,12.5,13,13.5,14,14.5,15,15.5,16,16.5,17,17.5,18,\n"
    ", LENGTH=2, 0.1, -0.2, 3D, -2D, 1D\n"
    "END\n";

/* Adams' 36 values by columns (top to bottom, then left to right). */
static void by_columns(const double r[36], double M[6][6])
{
    for (int col = 0; col < 6; ++col)
        for (int row = 0; row < 6; ++row)
            M[row][col] = r[6 * col + row];
}

/* On I in J's axes: F0 - K (d - length) - C v, and on J at J: -F and
 * -T - L x F, L I's place from J in J's axes; RJ J's axes (columns) in the
 * world's. */
static void check_field(const evaluated *e, int id, const double K[6][6], const double C[6][6],
                        const double length[6], const double F0[6], const double d[6],
                        const double v[6], const double L[3], const double RJ[9])
{
    double f[6];
    for (int r = 0; r < 6; ++r) {
        f[r] = F0[r];
        for (int c = 0; c < 6; ++c)
            f[r] -= K[r][c] * (d[c] - length[c]) + C[r][c] * v[c];
    }
    expect_sides(e, "FIELD", id, 10, f, L, RJ, 1e-11);
}

static void field_components_by_hand(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "field.adm", field);
    double L[3], d[6], v[6], RJ[9];
    marker_motion(&e, 20, 10, L, d + 3, v, RJ);
    d[0] = L[0], d[1] = L[1], d[2] = L[2];
    const double length5[6] = {2, 0.1, -0.2, 0.05, -0.03, 0.02};
    const double length6[6] = {2, 0.1, -0.2, 3 * DEG, -2 * DEG, 1 * DEG};
    for (int k = 0; k < 6; ++k) /* every entry of K and C acts */
        if (!(fabs(d[k] - length5[k]) > 0.01 && fabs(d[k] - length6[k]) > 0.01 &&
              fabs(v[k]) > 0.01))
            fail_msg("d[%d] = %g, v[%d] = %g", k, d[k], k, v[k]);
    double r[36], K[6][6], C[6][6];
    for (int k = 0; k < 36; ++k)
        r[k] = k + 1.0;
    by_columns(r, K);
    for (int row = 0; row < 6; ++row)
        for (int col = 0; col < 6; ++col)
            C[row][col] = 0.1 * K[row][col];
    const double F0[6] = {1, 2, 3, 4, 5, 6}, none[6] = {0};
    check_field(&e, 5, K, C, length5, F0, d, v, L, RJ);
    for (int k = 0; k < 36; ++k)
        r[k] = 0.5 * (k + 1.0);
    by_columns(r, C);
    check_field(&e, 6, K, C, length6, none, d, v, L, RJ);
    release(&e);
}

/* A 2 kg part, its centre I (20) at (1, 0, 0), hung from the ground's
 * origin J (10) by a field coupling y and the turn about z (K26 30, K62
 * -20), preloaded 5 N along x and 2 N m about z, under gravity along -y. At
 * rest: FORCE - K (d - LENGTH) + W = 0, W = (0, -19.62, 0, 0, 0, 0), so
 * x = 1 + 5 / 1000 and [400 30; -20 60] (y, az) = (-19.62, 2): det 24600,
 * y = (-19.62 * 60 - 30 * 2) / 24600, az = (400 * 2 - 20 * 19.62) / 24600. */
static const char hung[] =
    "hung\n"
    "UNITS/SYSTEM=MKS\n"
    "ACCGRAV/JGRAV=-9.81\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "FIELD/5, I=20, J=10, LENGTH=1,0,0,0,0,0, FORCE=5,0,0,0,0,2,\n"
    ", KMATRIX=1000,0,0,0,0,0, 0,400,0,0,0,-20, 0,0,500,0,0,0,\n"
    ", 0,0,0,50,0,0, 0,0,0,0,50,0, 0,30,0,0,0,60\n"
    "END\n";

static void hung_part_rests_where_the_equations_say(void **state)
{
    (void)state;
    hx_session s;
    hx_dynamics d;
    hx_dynamics_data dd;
    hx_message msg;
    if (hx_session_open(&s, test_write_file("hung.adm", hung), stderr, &msg) != 0 ||
        hx_dynamics_init(&d, &s, &msg) != 0 || hx_dynamics_data_init(&dd, &d, &msg) != 0)
        fail_msg("%s", msg.text);
    double *y = calloc((size_t)d.n, sizeof *y);
    hx_equilibrium_result result;
    assert_int_equal(hx_dynamics_initial_state(&d, &dd, y), 0);
    if (hx_equilibrium_solve(&d, &dd, NULL, 0.0, y, &result, &msg) != 0)
        fail_msg("%s", msg.text);
    const double *q = y + d.dof[1].q; /* the part's centre, then its quaternion */
    assert_close(q[0], 1.005, 0, 1e-12);
    assert_close(q[1], (-19.62 * 60.0 - 30.0 * 2.0) / 24600.0, 0, 1e-12);
    assert_close(2.0 * atan2(q[6], q[3]), (400.0 * 2.0 - 20.0 * 19.62) / 24600.0, 0, 1e-12);
    assert_true(fabs(q[2]) + fabs(q[4]) + fabs(q[5]) < 1e-12);
    free(y);
    hx_dynamics_data_free(&dd);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

/* An asymmetric, diagonally dominant stiffness: K[r][c] = 50 + 10 r on the
 * diagonal, 1 + 0.1 (6 r + c) off it. */
static double stiffness(int r, int c)
{
    return r == c ? 50.0 + 10.0 * r : 1.0 + 0.1 * (6 * r + c);
}

/* FIELD/5 between two moving parts, as a dataset (KMATRIX by columns) and as
 * its XML twin (K11 .. K66 by row and column). */
static void write_run_models(char *adm, char *xml, size_t size)
{
    int n = snprintf(adm, size,
                     "field run\n"
                     "UNITS/SYSTEM=MKS\n"
                     "PART/1, GROUND\n"
                     "MARKER/10, PART=1\n"
                     "PART/2, MASS=2, CM=20, IP=1,2,3, QG=2.1,0.2,0.1, REULER=10D,20D,30D,"
                     " VX=0.5, WZ=0.3, WM=10\n"
                     "MARKER/20, PART=2\n"
                     "PART/3, MASS=3, CM=30, IP=2,2,1, QG=0.1,0,0, REULER=0,0,0, WX=-0.2,"
                     " WM=10\n"
                     "MARKER/30, PART=3\n"
                     "FIELD/5, I=20, J=30, CRATIO=0.02, LENGTH=2,0,0.1,0.1,0,-0.1,"
                     " FORCE=0,1,0,0,0.5,0,\n, KMATRIX=");
    for (int c = 0; c < 6; ++c)
        for (int r = 0; r < 6; ++r)
            n += snprintf(adm + n, size - (size_t)n, "%.17g%s", stiffness(r, c),
                          r == 5 ? (c == 5 ? "\nEND\n" : ",\n, ") : ",");
    n = snprintf(xml, size,
                 "<MotionSolve><Model>\n"
                 "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"METER\""
                 " time_unit=\"SECOND\"/>\n"
                 "<Body_Ground id=\"1\"/>\n"
                 "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"2\""
                 " inertia_zz=\"3\" v_ic_x=\"0.5\" w_ic_z=\"0.3\"/>\n"
                 "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"2.1\" pos_y=\"0.2\""
                 " pos_z=\"0.1\" psi=\"0.17453292519943295\" theta=\"0.3490658503988659\""
                 " phi=\"0.52359877559829882\"/>\n"
                 "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"3\" inertia_xx=\"2\" inertia_yy=\"2\""
                 " inertia_zz=\"1\" w_ic_x=\"-0.2\"/>\n"
                 "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"0.1\"/>\n"
                 "<Force_Field id=\"5\" i_marker_id=\"20\" j_marker_id=\"30\" CRATIO=\"0.02\""
                 " length_x=\"2\" length_z=\"0.1\" length_tx=\"0.1\" length_tz=\"-0.1\""
                 " preload_y=\"1\" preload_ty=\"0.5\"");
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c)
            n += snprintf(xml + n, size - (size_t)n, " K%d%d=\"%.17g\"", r + 1, c + 1,
                          stiffness(r, c));
    snprintf(xml + n, size - (size_t)n, "/>\n</Model></MotionSolve>\n");
}

static void field_runs_on_its_partials_and_as_its_xml_twin(void **state)
{
    (void)state;
    static char adm[8192], xml[8192];
    write_run_models(adm, xml, sizeof adm);
    model m, x;
    double *y = model_run_text("field_run.adm", adm, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-9,
                               0.5, &m);
    long outside = 0;
    assert_true(jacobian_against_differences(&m.d, 0.5, y, "field", &outside) < 1e-6);
    assert_int_equal(outside, 0);
    assert_true(fabs(y[m.d.dof[1].q] - 2.1) > 1e-3); /* the field acted */
    double *yx = model_run_text("field_run.xml", xml, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC, 1e-9,
                                0.5, &x);
    assert_int_equal(m.d.n, x.d.n);
    for (int k = 0; k < m.d.n; ++k)
        assert_close(y[k], yx[k], 0, 1e-9);
    free(y), free(yx);
    close_model(&m), close_model(&x);
}

#define DIAGONAL36 "1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1"

static void bad_input_named(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"FIELD/5, I=20, J=10", "bad.adm:6:",
         "FIELD/5: Force_Field 5: neither a routine (usrsub_param_string: FIESUB) nor a linear"
         " field's attributes"},
        {"FIELD/5, I=20, J=10, CRATIO=0.1", "bad.adm:6:",
         "FIELD/5: CRATIO without KMATRIX: CRATIO scales the stiffness matrix"},
        {"FIELD/5, I=20, J=10,\n, KMATRIX=1,2,3", "bad.adm:7:",
         "FIELD/5: KMATRIX takes 36 values, not 3"},
        {"FIELD/5, I=20, J=10, KMATRIX=" DIAGONAL36 ",\n, CMATRIX=" DIAGONAL36 ", CRATIO=0.1",
         "bad.adm:7:", "FIELD/5: give CMATRIX or CRATIO, not both"},
        {"FIELD/5, I=20, J=10, FUNCTION=USER(1),\n, CRATIO=0.1", "bad.adm:7:",
         "FIELD/5: CRATIO is a linear FIELD's, and FUNCTION=USER(...) calls FIESUB: give one"
         " of them"},
        {"FIELD/5, I=20, J=10, LENGTH=1D,0,0,0,0,0", "bad.adm:6:",
         "FIELD/5: LENGTH, value 1, 1D (column 29): a degree mark (D) on a value that is not"
         " an angle"},
        {"FIELD/5, I=20, J=10, ROUTINE=lib::fiesub", "bad.adm:6:",
         "FIELD/5: ROUTINE without FUNCTION=USER(...)"},
        {"FIELD/5, I=20, J=10, KMATRIX=1,0,0,0,0,0,0,1,0,0,0,0,0,0,-1,0,0,0,\n"
         ", 0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1", "bad.adm:6:",
         "FIELD/5: Force_Field 5: K33 = -1: a stiffness on the diagonal must not be negative"},
        {"FIELD/5, I=20, J=10, CMATRIX=1,0,0,0,0,0,0,-2,0,0,0,0,0,0,1,0,0,0,\n"
         ", 0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1", "bad.adm:6:",
         "Force_Field 5: C22 = -2: a damping on the diagonal must not be negative"},
        {"FIELD/5, I=20, J=10, CRATIO=1E300, KMATRIX=1E300,0,0,0,0,0,0,1,0,0,0,0,0,0,1,\n"
         ", 0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1", "bad.adm:6:",
         "Force_Field 5: its damping C11 is not a finite number"},
    };
    expect_read_errors("bad.adm", "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                       "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n", cases,
                       sizeof cases / sizeof cases[0]);
    static const char *const xml[][2] = {
        {"usrsub_param_string=\"USER(1)\" K11=\"1\"",
         "Force_Field 3: K11 is a linear field's, and usrsub_param_string names a routine"
         " (FIESUB): give one of them"},
        {"K11=\"1\" C11=\"1\" CRATIO=\"0.1\"",
         "Force_Field 3: give CRATIO or the damping matrix (C11 .. C66), not both"},
        {"K11=\"1\" CRATIO=\"-0.5\"", "Force_Field 3: CRATIO = -0.5: it must not be negative"},
        {"K12=\"x\"", "attribute K12 = \"x\" is not a finite number"},
        {"K67=\"1\"", "attribute K67 is not one the harness reads"},
        {"", "Force_Field 3: neither a routine (usrsub_param_string: FIESUB) nor a linear"
             " field's attributes"},
        {"CRATIO=\"0.1\"", "Force_Field 3: CRATIO without a stiffness entry (K11 .. K66)"},
    };
    expect_xml_errors("<Force_Field id=\"3\" i_marker_id=\"10\" j_marker_id=\"10\"", xml,
                      sizeof xml / sizeof xml[0]);
    /* a second Force_Field of an id, of either form */
    static const char twice[] =
        "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Force_Field id=\"3\" i_marker_id=\"10\" j_marker_id=\"10\" K11=\"1\"/>\n"
        "<Force_Field id=\"3\" i_marker_id=\"10\" j_marker_id=\"10\""
        " usrsub_param_string=\"USER(1)\"/>\n"
        "</Model></MotionSolve>\n";
    hx_message msg;
    assert_null(hx_model_parse(twice, strlen(twice), "bad.xml", NULL, &msg));
    assert_contains(msg.text, "bad.xml:5:", "Force_Field 3 is defined twice (line 4)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(field_components_by_hand),
        cmocka_unit_test(hung_part_rests_where_the_equations_say),
        cmocka_unit_test(field_runs_on_its_partials_and_as_its_xml_twin),
        cmocka_unit_test(bad_input_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
