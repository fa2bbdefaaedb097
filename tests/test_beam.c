/*
 * The linear beam (BEAM / Force_Beam, docs/interface.md §7.17): a beam's six
 * components at a displaced, turned, moving state against its Timoshenko
 * stiffness worked by hand (CRATIO damping, and a CMATRIX whose 21 entries
 * are told apart), its J side with the moment of the offset; a cantilever's
 * static tip deflection and rotation against the textbook's formulas (bending
 * with shear in y and in z, stretch, twist); the BDF Jacobian against
 * differences; the dataset and its XML twin run alike; bad input named with
 * file:line.
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

/* L 2, E 1, G 0.5, A 2, Ixx 5, Iyy 4, Izz 3, ASY 1, ASZ 0:
 *   Py = 12 E Izz ASY / (G A L^2) = 36 / 4 = 9, Pz = 0
 *   K11 = E A / L = 1                K44 = G Ixx / L = 1.25
 *   K22 = 12 E Izz / (L^3 (1 + Py)) = 36 / 80 = 0.45
 *   K26 = -6 E Izz / (L^2 (1 + Py)) = -18 / 40 = -0.45
 *   K66 = (4 + Py) E Izz / (L (1 + Py)) = 39 / 20 = 1.95
 *   K33 = 12 E Iyy / L^3 = 6, K35 = 6 E Iyy / L^2 = 6, K55 = 4 E Iyy / L = 8 */
static const double K[6][6] = {{1, 0, 0, 0, 0, 0},     {0, 0.45, 0, 0, 0, -0.45},
                               {0, 0, 6, 0, 6, 0},     {0, 0, 0, 1.25, 0, 0},
                               {0, 0, 6, 0, 8, 0},     {0, -0.45, 0, 0, 0, 1.95}};

/* J (10) the centre of part 3, turned and moving, spinning about every
 * axis; I (20) the centre of part 2, about (2.1, -0.3, -0.2) from it in its
 * axes, turned from it about every axis and moving otherwise. BEAM/5 damps
 * by CRATIO 0.1, BEAM/6 by a CMATRIX of 1 .. 21 (Adams' lower half by
 * columns: c11 = 1, c21 = 2, .., c61 = 6, c22 = 7, .., c66 = 21). */
#define SECTION "LENGTH=2, EMODULUS=1, GMODULUS=0.5, AREA=2, IXX=5, IYY=4, IZZ=3, ASY=1"
static const char beam[] =
    "beam\n"
    "UNITS/SYSTEM=MKS\n"
    "PART/1, GROUND\n"
    "MARKER/1, PART=1\n"
    "PART/3, MASS=3, CM=10, IP=1,1,1, QG=0.1,-0.1,0.05, REULER=90D,4D,-3D, VX=0.2, VY=0.1,"
    " VZ=-0.3, WX=0.3, WY=-0.2, WZ=0.5, WM=1\n"
    "MARKER/10, PART=3\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0.4,2.0,-0.15, REULER=100D,9D,-5D, VX=0.5, VY=-0.3,"
    " VZ=0.2, WX=0.1, WY=0.2, WZ=0.9, WM=1\n"
    "MARKER/20, PART=2\n"
    "BEAM/5, I=20, J=10, " SECTION ", CRATIO=0.1\n"
    "BEAM/6, I=20, J=10, " SECTION ",\n"
    ", CMATRIX=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21\n"
    "END\n";

/* Adams' lower half by columns into the symmetric 6 x 6 matrix. */
static void lower_half(const double r[21], double C[6][6])
{
    int n = 0;
    for (int col = 0; col < 6; ++col)
        for (int row = col; row < 6; ++row, ++n)
            C[row][col] = C[col][row] = r[n];
}

/* On I in J's axes: -K d - C v, and on J at J: -F and -T - L x F, L I's
 * place from J in J's axes; RJ J's axes (columns) in the world's. */
static void check_beam(const evaluated *e, int id, const double C[6][6], const double d[6],
                       const double v[6], const double L[3], const double RJ[9])
{
    double f[6];
    for (int r = 0; r < 6; ++r) {
        f[r] = 0.0;
        for (int c = 0; c < 6; ++c)
            f[r] -= K[r][c] * d[c] + C[r][c] * v[c];
    }
    expect_sides(e, "BEAM", id, 10, f, L, RJ, 1e-12);
    char text[64];
    snprintf(text, sizeof text, "BEAM(%d,0,1,0)", id);
    EXPECT(e, text, sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]), 1e-12);
}

static void beam_components_by_hand(void **state)
{
    (void)state;
    evaluated e;
    evaluate_text(&e, "beam.adm", beam);
    double L[3], d[6], v[6], RJ[9];
    marker_motion(&e, 20, 10, L, d + 3, v, RJ);
    d[0] = L[0] - 2.0, d[1] = L[1], d[2] = L[2]; /* the stretch from the free length */
    for (int k = 0; k < 6; ++k) /* every entry of K and C acts */
        if (!(fabs(d[k]) > 0.01 && fabs(v[k]) > 0.01))
            fail_msg("d[%d] = %g, v[%d] = %g", k, d[k], k, v[k]);
    double C[6][6];
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c)
            C[r][c] = 0.1 * K[r][c];
    check_beam(&e, 5, C, d, v, L, RJ);
    double r[21];
    for (int k = 0; k < 21; ++k)
        r[k] = k + 1.0;
    lower_half(r, C);
    check_beam(&e, 6, C, d, v, L, RJ);
    release(&e);
}

/* A cantilever: J (10) on ground at the origin, I (20) the centre of a
 * part of 1 kg at (L, 0, 0), no gravity, a constant force and torque on I
 * along the world's (J's) axes (GFORCE/9 of the given components). */
static const char *cantilever(const char *loads)
{
    static char text[2048];
    snprintf(text, sizeof text,
             "cantilever\n"
             "UNITS/SYSTEM=MKS\n"
             "PART/1, GROUND\n"
             "MARKER/10, PART=1\n"
             "MARKER/11, PART=1, FLOATING\n"
             "PART/2, MASS=1, CM=20, IP=1e-3,1e-3,1e-3\n"
             "MARKER/20, PART=2, QP=0.5,0,0\n"
             "BEAM/5, I=20, J=10, LENGTH=0.5, EMODULUS=2.1e11, GMODULUS=8.1e10, AREA=2e-4,\n"
             ", IXX=1.5e-8, IYY=2e-9, IZZ=8e-9, ASY=1.2, ASZ=1.1\n"
             "GFORCE/9, I=20, JFLOAT=11, RM=10, %s\n"
             "END\n",
             loads);
    return text;
}

/* The cantilever moved to its static equilibrium (by differences of the
 * loads): I's place and angles from J, in J's axes. */
static void deflect(const char *loads, double out[6])
{
    hx_session s;
    hx_dynamics d;
    hx_dynamics_data dd;
    hx_message msg;
    if (hx_session_open(&s, test_write_file("cantilever.adm", cantilever(loads)), stderr,
                        &msg) != 0 ||
        hx_dynamics_init(&d, &s, &msg) != 0 || hx_dynamics_data_init(&dd, &d, &msg) != 0)
        fail_msg("%s", msg.text);
    double *y = calloc((size_t)d.n, sizeof *y);
    hx_equilibrium_result result;
    assert_int_equal(hx_dynamics_initial_state(&d, &dd, y), 0);
    if (hx_equilibrium_solve(&d, &dd, NULL, 0.0, y, &result, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_true(result.iterations >= 1);
    const double *q = y + d.dof[1].q; /* the part's centre, then its quaternion */
    const double w = q[3], x = q[4], yq = q[5], z = q[6];
    out[0] = q[0] - 0.5, out[1] = q[1], out[2] = q[2];
    /* the turn's angles: the planar cases turn about one axis only */
    out[3] = 2.0 * atan2(x, w), out[4] = 2.0 * atan2(yq, w), out[5] = 2.0 * atan2(z, w);
    free(y);
    hx_dynamics_data_free(&dd);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

/* Timoshenko's cantilever under an end force P across it: tip deflection
 * P L^3 / (3 E I) + P L AS / (G A), the section's turn P L^2 / (2 E I);
 * along it N L / (E A); twisted by T: T L / (G Ixx). */
static void cantilever_deflects_as_the_textbook_says(void **state)
{
    (void)state;
    const double L = 0.5, E = 2.1e11, G = 8.1e10, A = 2e-4;
    const double P = 200.0, Q = -150.0, N = 5e4, T = 30.0;
    double out[6];
    deflect("FX=0\\, FY=200\\, FZ=0\\, TX=0\\, TY=0\\, TZ=0", out);
    assert_close(out[1], P * L * L * L / (3 * E * 8e-9) + P * L * 1.2 / (G * A), 0, 1e-9);
    assert_close(out[5], P * L * L / (2 * E * 8e-9), 0, 1e-9);
    assert_true(fabs(out[0]) + fabs(out[2]) + fabs(out[3]) + fabs(out[4]) < 1e-12);
    deflect("FX=0\\, FY=0\\, FZ=-150\\, TX=0\\, TY=0\\, TZ=0", out);
    assert_close(out[2], Q * L * L * L / (3 * E * 2e-9) + Q * L * 1.1 / (G * A), 0, 1e-9);
    assert_close(out[4], -Q * L * L / (2 * E * 2e-9), 0, 1e-9);
    assert_true(fabs(out[0]) + fabs(out[1]) + fabs(out[3]) + fabs(out[5]) < 1e-12);
    deflect("FX=5e4\\, FY=0\\, FZ=0\\, TX=30\\, TY=0\\, TZ=0", out);
    assert_close(out[0], N * L / (E * A), 0, 1e-9);
    assert_close(out[3], T * L / (G * 1.5e-8), 0, 1e-9);
    assert_true(fabs(out[1]) + fabs(out[2]) + fabs(out[4]) + fabs(out[5]) < 1e-12);
}

/* BEAM/5 between two moving parts (BDF on its partials), and its XML twin. */
#define TWO_PARTS                                                                              \
    "UNITS/SYSTEM=MKS\n"                                                                       \
    "PART/1, GROUND\n"                                                                         \
    "MARKER/10, PART=1\n"                                                                      \
    "PART/2, MASS=2, CM=20, IP=1,2,3, QG=2.1,0.2,0.1, REULER=10D,20D,30D, VX=0.5, WZ=0.3,"     \
    " WM=10\n"                                                                             \
    "MARKER/20, PART=2\n"                                                                      \
    "PART/3, MASS=3, CM=30, IP=2,2,1, QG=0.1,0,0, REULER=0,0,0, WX=-0.2, WM=10\n"             \
    "MARKER/30, PART=3\n"
static const char beam_run[] =
    "beam run\n" TWO_PARTS
    "BEAM/5, I=20, J=30, LENGTH=2, EMODULUS=100, GMODULUS=40, AREA=0.5, IXX=0.2, IYY=0.1,"
    " IZZ=0.3, ASY=1.2, ASZ=1.1, CRATIO=0.05\n"
    "END\n";
static const char beam_xml[] =
    "<MotionSolve><Model>\n"
    "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"METER\""
    " time_unit=\"SECOND\"/>\n"
    "<Body_Ground id=\"1\"/>\n"
    "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"1\" inertia_yy=\"2\""
    " inertia_zz=\"3\" v_ic_x=\"0.5\" w_ic_z=\"0.3\"/>\n"
    "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"2.1\" pos_y=\"0.2\" pos_z=\"0.1\""
    " psi=\"0.17453292519943295\" theta=\"0.3490658503988659\" phi=\"0.52359877559829882\"/>\n"
    "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"3\" inertia_xx=\"2\" inertia_yy=\"2\""
    " inertia_zz=\"1\" w_ic_x=\"-0.2\"/>\n"
    "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"0.1\"/>\n"
    "<Force_Beam id=\"5\" i_marker_id=\"20\" j_marker_id=\"30\" length=\"2\" E=\"100\""
    " G=\"40\" area=\"0.5\" ixx=\"0.2\" iyy=\"0.1\" izz=\"0.3\" ASY=\"1.2\" ASZ=\"1.1\""
    " cratio=\"0.05\"/>\n"
    "</Model></MotionSolve>\n";

static void beam_runs_on_its_partials_and_as_its_xml_twin(void **state)
{
    (void)state;
    model m, x;
    double *y = model_run_text("beam_run.adm", beam_run, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC,
                               1e-9, 0.5, &m);
    long outside = 0;
    assert_true(jacobian_against_differences(&m.d, 0.5, y, "beam", &outside) < 1e-6);
    assert_int_equal(outside, 0);
    assert_true(fabs(y[m.d.dof[1].q] - 2.1) > 1e-3); /* the beam acted */
    double *yx = model_run_text("beam_run.xml", beam_xml, HX_METHOD_BDF, HX_JACOBIAN_ANALYTIC,
                                1e-9, 0.5, &x);
    assert_int_equal(m.d.n, x.d.n);
    for (int k = 0; k < m.d.n; ++k)
        assert_close(y[k], yx[k], 0, 1e-9);
    free(y), free(yx);
    close_model(&m), close_model(&x);
}

static void bad_input_named(void **state)
{
    (void)state;
    static const char *const cases[][3] = {
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=0, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1",
         "bad.adm:6:", "Force_Beam 5: E = 0: it must be positive"},
        {"BEAM/5, I=20, J=10, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1", "bad.adm:6:",
         "LENGTH is missing (the statement needs it)"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=0, AREA=1, IXX=1, IYY=1, IZZ=1",
         "bad.adm:6:", "BEAM/5: Force_Beam 5: G = 0: it must be positive"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=-1",
         "bad.adm:6:", "Force_Beam 5: izz = -1: it must not be negative"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1,"
         " CRATIO=-0.1", "bad.adm:6:", "Force_Beam 5: cratio = -0.1: it must not be negative"},
        {"BEAM/5, I=20, J=10, LENGTH=1E-300, EMODULUS=1E300, GMODULUS=1, AREA=1, IXX=1, IYY=1,"
         " IZZ=1", "bad.adm:6:", "Force_Beam 5: its stiffness K11 is not a finite number"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1,\n"
         ", FORMULATION=NONLINEAR", "bad.adm:7:", "FORMULATION=NONLINEAR: the harness simulates"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1,\n"
         ", CMATRIX=1,2,3,4,5,6,-7,8,9,10,11,12,13,14,15,16,17,18,19,20,21", "bad.adm:6:",
         "Force_Beam 5: cmatrix: c22 = -7: a damping on the diagonal must not be negative"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1,\n"
         ", FORMULATION=STRING", "bad.adm:7:",
         "BEAM/5: FORMULATION=STRING: the harness simulates the LINEAR one only"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1,\n"
         ", CMATRIX=1,2,3", "bad.adm:7:", "BEAM/5: CMATRIX takes 21 values, not 3"},
        {"BEAM/5, I=20, J=10, LENGTH=1, EMODULUS=1, GMODULUS=1, AREA=1, IXX=1, IYY=1, IZZ=1,\n"
         ", CMATRIX=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21, CRATIO=0.1",
         "bad.adm:7:", "BEAM/5: give CMATRIX or CRATIO, not both"},
    };
    expect_read_errors("bad.adm", "bad\nPART/1, GROUND\nMARKER/10, PART=1\n"
                       "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n", cases,
                       sizeof cases / sizeof cases[0]);
    static const char *const xml[][2] = {
        {"cmatrix=\"1 2\"", "Force_Beam 3: cmatrix holds 2 numbers: it takes 21 (the lower"
                            " half by columns)"},
        {"cmatrix=\"1 2 1.5.3\"", "Force_Beam 3: cmatrix: \"1.5.3\" is not a number"},
        {"cmatrix=\"1\" cratio=\"0.1\"", "Force_Beam 3: give cmatrix or cratio, not both"},
    };
    expect_xml_errors("<Force_Beam id=\"3\" i_marker_id=\"10\" j_marker_id=\"10\" length=\"1\""
                      " E=\"1\" G=\"1\" area=\"1\" ixx=\"1\" iyy=\"1\" izz=\"1\"",
                      xml, sizeof xml / sizeof xml[0]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(beam_components_by_hand),
        cmocka_unit_test(cantilever_deflects_as_the_textbook_says),
        cmocka_unit_test(beam_runs_on_its_partials_and_as_its_xml_twin),
        cmocka_unit_test(bad_input_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
