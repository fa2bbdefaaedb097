/*
 * The requests the harness answers itself (docs/interface.md §7.13, §9.6):
 * DISPLACEMENT, VELOCITY and F1..F8 of an Adams REQUEST, the XML
 * Post_Request's MARKER_DISPLACEMENT, MARKER_VELOCITY and EXPRESSION, each
 * of the eight components against values worked by hand at a known state
 * (every component different, so that a swap shows), a run of a free body
 * under gravity with a constant spin against its closed form, the CSV's
 * columns, and every bad request named with its file and line.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "frames/frames.h"
#include "model/model.h"
#include "sim/simulation/requests.h"
#include "sim_support.h"
#include "test_support.h"

static hx_model *parse(const char *text, const char *name, hx_message *msg)
{
    return hx_model_parse(text, strlen(text), name, NULL, msg);
}

/* A ground with J = 10 at (1, 2, 3), world axes, and RM = 11 at the origin
 * turned by the 3-1-3 angles 90, 90, 0 degrees: R = [[0,0,1],[1,0,0],[0,1,0]],
 * its x axis the world's y, its y the world's z, its z the world's x
 * (docs/interface.md §7.4), so that a vector's components in its axes are
 * the world's (y, z, x): each differs from the world's. Part 2 has its CM marker 20 at (4, 6, 3), turned by the 3-1-3 angles
 * 30, 40, 50 degrees; it moves at (1, 2, 3) and turns at (0.1, 0.2, 0.3)
 * rad/s, both in the world's axes (WM = 10). */
#define STATE_DATASET                                                                          \
    "requests\n"                                                                               \
    "PART/1, GROUND\n"                                                                         \
    "MARKER/10, PART=1, QP=1,2,3\n"                                                            \
    "MARKER/11, PART=1, REULER=90D,90D,0\n"                                                      \
    "PART/2, MASS=1, CM=20, IP=1,1,1, VX=1, VY=2, VZ=3, WX=0.1, WY=0.2, WZ=0.3, WM=10\n"     \
    "MARKER/20, PART=2, QP=4,6,3, REULER=30D,40D,50D\n"

static const char known_state[] = STATE_DATASET
    "REQUEST/1, DISPLACEMENT, I=20, J=10, RM=11\n"
    "REQUEST/2, VELOCITY, I=20, J=10, RM=11\n"
    "REQUEST/3, F1=DX(20)\\F2=2*TIME\\F4=DY(20,10)\\\n"
    ", F5=-1.5\\F8=VZ(20)\n"
    "REQUEST/4, DISPLACEMENT, I=20\n"
    "END\n";

static void expect_values(const hx_frames *fr, int k, const double want[8], double tol)
{
    double got[8];
    hx_message msg;
    assert_int_equal(hx_requests_values(fr, k, NULL, NULL, got, &msg), 0);
    for (int j = 0; j < 8; ++j) {
        if (fabs(got[j] - want[j]) > tol)
            fail_msg("request %d component %d: %.15g, expected %.15g",
                     fr->model->requests[k].id, j + 1, got[j], want[j]);
    }
}

static void test_values_at_a_known_state(void **state)
{
    (void)state;
    hx_message msg;
    hx_model *m = parse(known_state, "requests.adm", &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nrequests, 4);
    assert_int_equal(m->requests[0].kind, HX_REQUEST_DISPLACEMENT);
    assert_int_equal(m->requests[1].kind, HX_REQUEST_VELOCITY);
    assert_int_equal(m->requests[2].kind, HX_REQUEST_EXPRESSIONS);
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    fr.time = 0.25;
    const double d2r = M_PI / 180.0;
    /* DISPLACEMENT: p_I - p_J = (4,6,3) - (1,2,3) = (3, 4, 0), |.| = 5; in RM's
     * axes (y, z, x) = (4, 0, 3); F5 none; the angles of I relative to J
     * (world axes): I's own 30, 40, 50 degrees. */
    const double displacement[8] = {5, 4, 0, 3, 0, 30 * d2r, 40 * d2r, 50 * d2r};
    expect_values(&fr, 0, displacement, 1e-12);
    /* VELOCITY: v_I - v_J = (1, 2, 3) (J on ground), |.| = sqrt(14); in RM's
     * axes (2, 3, 1); w_I - w_J = (0.1, 0.2, 0.3), |.| = sqrt(0.14); in RM's
     * axes (0.2, 0.3, 0.1). */
    const double velocity[8] = {sqrt(14.0), 2, 3, 1, sqrt(0.14), 0.2, 0.3, 0.1};
    expect_values(&fr, 1, velocity, 1e-12);
    /* F1..F8: DX(20) = 4, 2 TIME = 0.5, F3 none, DY(20,10) = 6 - 2 = 4, -1.5,
     * F6, F7 none, VZ(20) = 3 */
    const double expressions[8] = {4, 0.5, 0, 4, -1.5, 0, 0, 3};
    expect_values(&fr, 2, expressions, 1e-12);
    /* J and RM left out: the ground's origin and the world's axes; the angles
     * are I's own */
    const double from_ground[8] = {sqrt(61.0), 4, 6, 3, 0, 30 * d2r, 40 * d2r, 50 * d2r};
    expect_values(&fr, 3, from_ground, 1e-12);
    hx_frames_free(&fr);
    hx_model_free(m);
}

/* The same requests as MotionSolve XML: the same numbers. */
static void test_xml_post_request(void **state)
{
    (void)state;
    static const char xml[] =
        "<Model>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\" pos_x=\"1\" pos_y=\"2\" pos_z=\"3\"/>\n"
        "<Reference_Marker id=\"11\" body_id=\"1\" a00=\"0\" a01=\"0\" a02=\"1\" a10=\"1\""
        " a11=\"0\" a12=\"0\" a20=\"0\" a21=\"1\" a22=\"0\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
        " inertia_zz=\"1\" v_ic_x=\"1\" v_ic_y=\"2\" v_ic_z=\"3\" w_ic_x=\"0.1\" w_ic_y=\"0.2\""
        " w_ic_z=\"0.3\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"4\" pos_y=\"6\" pos_z=\"3\""
        " psi=\"0.5235987755982988\" theta=\"0.6981317007977318\" phi=\"0.8726646259971648\"/>\n"
        "<Post_Request id=\"1\" type=\"MARKER_DISPLACEMENT\" i_marker_id=\"20\" j_marker_id=\"10\""
        " ref_marker_id=\"11\" expr1=\"NULL\"/>\n"
        "<Post_Request id=\"2\" type=\"MARKER_VELOCITY\" i_marker_id=\"20\" j_marker_id=\"10\""
        " ref_marker_id=\"11\"/>\n"
        "<Post_Request id=\"3\" type=\"EXPRESSION\" expr1=\"DX(20)\" expr2=\"2*TIME\""
        " expr3=\"NULL\" expr4=\"DY(20,10)\" expr5=\"-1.5\" expr6=\" null \" expr8=\"VZ(20)\"/>\n"
        "</Model>\n";
    hx_message msg;
    hx_model *m = parse(xml, "requests.xml", &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nrequests, 3);
    assert_int_equal(m->nroutines, 0);
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    fr.time = 0.25;
    const double d2r = M_PI / 180.0;
    const double displacement[8] = {5, 4, 0, 3, 0, 30 * d2r, 40 * d2r, 50 * d2r};
    expect_values(&fr, 0, displacement, 1e-12);
    const double velocity[8] = {sqrt(14.0), 2, 3, 1, sqrt(0.14), 0.2, 0.3, 0.1};
    expect_values(&fr, 1, velocity, 1e-12);
    const double expressions[8] = {4, 0.5, 0, 4, -1.5, 0, 0, 3};
    expect_values(&fr, 2, expressions, 1e-12);
    hx_frames_free(&fr);
    hx_model_free(m);
}

/* A free body under gravity (0, 0, -9.81) from (0, 0, 1) at (1, 0, 5), its CM
 * marker turned +90 degrees about x and spinning at 2 rad/s about the
 * world's z (isotropic inertia: the spin stays), run with DOPRI5 to 1 s:
 * p(t) = (t, 0, 1 + 5t - 9.81 t^2/2), v(t) = (1, 0, 5 - 9.81 t); the axes
 * Rz(2t) Rx(90 degrees): psi = 2t, theta = 90 degrees, phi = 0. */
static const char falling[] =
    "falling\n"
    "ACCGRAV/, IGRAV=0, JGRAV=0, KGRAV=-9.81\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, VX=1, VZ=5, WZ=2, WM=10\n"
    "MARKER/20, PART=2, QP=0,0,1, REULER=0,90D,0\n"
    "REQUEST/7, DISPLACEMENT, I=20, J=10\n"
    "REQUEST/8, VELOCITY, I=20, J=10\n"
    "REQUEST/9, F1=TIME\\F2=DZ(20)-1-5*TIME\n"
    "END\n";

static void test_run_of_a_falling_spinning_body(void **state)
{
    (void)state;
    char csv[512];
    const char *model = test_write_file("falling.adm", falling);
    snprintf(csv, sizeof csv, "%s/falling.csv", test_temp_dir());
    const char *const args[] = {"--end", "1", "--output-interval", "0.5", "--rtol", "1e-11",
                                "--atol", "1e-12", "--quiet", NULL};
    assert_int_equal(sim_run_csv(model, csv, args), 0);
    /* the columns, named as a REQSUB's are, in Adams' order */
    const int first = csv_column(csv, "request7.1");
    assert_true(first > 0);
    for (int k = 0; k < 8; ++k) {
        char name[32];
        snprintf(name, sizeof name, "request7.%d", k + 1);
        assert_int_equal(csv_column(csv, name), first + k);
        snprintf(name, sizeof name, "request8.%d", k + 1);
        assert_int_equal(csv_column(csv, name), first + 8 + k);
        snprintf(name, sizeof name, "request9.%d", k + 1);
        assert_int_equal(csv_column(csv, name), first + 16 + k);
    }
    assert_int_equal(csv_column(csv, "energy"), first + 24);
    csv_table t;
    csv_read(csv, &t);
    assert_int_equal(t.rows, 3);
    for (int row = 0; row < 3; ++row) {
        const double time = csv_at(&t, row, 0), g = 9.81;
        const double z = 1 + 5 * time - g * time * time / 2, vz = 5 - g * time;
        const double want[24] = {
            sqrt(time * time + z * z), time, 0, z, 0, 2 * time, M_PI / 2, 0,
            sqrt(1 + vz * vz), 1, 0, vz, 2, 0, 0, 2,
            time, -g * time * time / 2, 0, 0, 0, 0, 0, 0};
        for (int k = 0; k < 24; ++k)
            if (fabs(csv_at(&t, row, first + k) - want[k]) > 1e-8)
                fail_msg("t = %g, column %d: %.12g, expected %.12g", time, first + k,
                         csv_at(&t, row, first + k), want[k]);
    }
    csv_free(&t);
}

/* A fault of an expression at an output time stops the run with its place;
 * at the frames, the message names the file, line, column and component. */
static void test_fault_of_an_expression(void **state)
{
    (void)state;
    static const char text[] = STATE_DATASET "REQUEST/4, F1=1\\F3=LOG(DZ(20)-5)\nEND\n";
    hx_message msg;
    hx_model *m = parse(text, "fault.adm", &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    double got[8];
    assert_int_equal(hx_requests_values(&fr, 0, NULL, NULL, got, &msg), -1);
    assert_contains(msg.text, "fault.adm:7:20: REQUEST/4 F3: LOG");
    hx_frames_free(&fr);
    hx_model_free(m);
    char csv[512];
    const char *model = test_write_file("fault.adm", text);
    snprintf(csv, sizeof csv, "%s/fault.csv", test_temp_dir());
    const char *const args[] = {"--end", "0.1", "--quiet", NULL};
    assert_int_not_equal(sim_run_csv(model, csv, args), 0);
}

/* Bad requests: the file, the line (and column) and what. */
static const struct {
    const char *fragment;
    const char *needles[3];
} bad[] = {
    {"REQUEST/3, ACCELERATION, J=10", {"bad.adm:7:", "REQUEST/3:", "ACCELERATION needs I="}},
    {"REQUEST/3, ACCELERATION, F2=1", {"bad.adm:7:", "REQUEST/3:", "ACCELERATION with F1..F8"}},
    {"REQUEST/3, FORCE, J=10", {"bad.adm:7:", "REQUEST/3:", "FORCE needs I="}},
    {"REQUEST/3, DISPLACEMENT, I=99", {"bad.adm:7:", "REQUEST/3:", "I=99 (column 28) names no MARKER"}},
    {"REQUEST/3, VELOCITY, I=20, RM=98", {"bad.adm:7:", "REQUEST/3:", "RM=98 (column 31) names no"}},
    {"REQUEST/3, DISPLACEMENT, J=10", {"bad.adm:7:", "REQUEST/3:", "DISPLACEMENT needs I="}},
    {"REQUEST/3, DISPLACEMENT, VELOCITY, I=20", {"bad.adm:7:", "REQUEST/3:", "give one of"}},
    {"REQUEST/3, DISPLACEMENT, I=20, F1=1", {"bad.adm:7:", "REQUEST/3:", "with F1..F8"}},
    {"REQUEST/3, F1=DX(20), I=20", {"bad.adm:7:", "REQUEST/3:", "I (column 23) with F1..F8"}},
    {"REQUEST/3, COMMENT=nothing", {"bad.adm:7:", "REQUEST/3:", "nothing to output"}},
    {"REQUEST/3, F1=1\\\n, F2=2*)", {"bad.adm:8:8: REQUEST/3 F2:", "", ""}},
    {"REQUEST/3, F1=1\\F3=DX(20,97)", {"bad.adm:7:20: REQUEST/3 F3:", "no Reference_Marker 97", ""}},
    {"REQUEST/3, F1=USER(1)", {"bad.adm:7:", "REQUEST/3:", "USER(...) is a REQUEST's FUNCTION"}},
    {"REQUEST/3, F1=1\nREQUEST/3, F1=2", {"bad.adm:8:", "REQUEST/3 is defined twice", ""}},
};

static void test_bad_requests(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
        char text[2048];
        snprintf(text, sizeof text,
                 "bad\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
                 "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n%s\nEND\n", bad[k].fragment);
        hx_message msg;
        hx_model *m = parse(text, "bad.adm", &msg);
        if (m != NULL)
            fail_msg("case %zu read: %s", k, bad[k].fragment);
        for (int j = 0; j < 3; ++j)
            if (bad[k].needles[j][0] != '\0' && strstr(msg.text, bad[k].needles[j]) == NULL)
                fail_msg("case %zu: \"%s\" not in \"%s\"", k, bad[k].needles[j], msg.text);
    }
}

static const struct {
    const char *element;
    const char *needles[3];
} bad_xml[] = {
    {"<Post_Request id=\"5\" type=\"MARKER_ACCELERATION\" j_marker_id=\"20\"/>",
     {"bad.xml:5:", "Post_Request 5:", "i_marker_id is missing"}},
    {"<Post_Request id=\"5\" type=\"MARKER_FORCE\" j_marker_id=\"20\"/>",
     {"bad.xml:5:", "Post_Request 5:", "i_marker_id is missing"}},
    {"<Post_Request id=\"5\" type=\"ELEMENTAL_FORCE\" elem_type=\"SFORCE\" jflag=\"0\"/>",
     {"bad.xml:5:", "Post_Request 5: type \"ELEMENTAL_FORCE\"", "not answered"}},
    {"<Post_Request id=\"5\" type=\"MARKER_DISPLACEMENT\"/>",
     {"bad.xml:5:", "Post_Request 5:", "i_marker_id is missing"}},
    {"<Post_Request id=\"5\" type=\"MARKER_DISPLACEMENT\" i_marker_id=\"99\"/>",
     {"bad.xml:5:", "Post_Request 5:", "i_marker_id=99: no Reference_Marker 99"}},
    {"<Post_Request id=\"5\" type=\"MARKER_VELOCITY\" i_marker_id=\"20\" expr2=\"DX(20)\"/>",
     {"bad.xml:5:", "Post_Request 5:", "takes no expr2"}},
    {"<Post_Request id=\"5\" type=\"EXPRESSION\" expr1=\"1\" i_marker_id=\"20\"/>",
     {"bad.xml:5:", "Post_Request 5:", "takes no i_marker_id"}},
    {"<Post_Request id=\"5\" type=\"EXPRESSION\" expr2=\"SIN(\"/>",
     {"bad.xml:5:", "Post_Request 5 expr2:", ""}},
    {"<Post_Request id=\"5\" type=\"EXPRESSION\" expr3=\"DX(20, 96)\"/>",
     {"bad.xml:5:1: Post_Request 5 expr3:", "no Reference_Marker 96", ""}},
    {"<Post_Request id=\"5\" type=\"EXPRESSION\" expr2=\"ORIENT(31, 1, 20)\"/>",
     {"bad.xml:5:8: Post_Request 5 expr2:", "ORIENT: system (argument 1) is 31", ""}},
    {"<Post_Request id=\"5\" type=\"DISPLACEMENT\" i_marker_id=\"20\"/>",
     {"bad.xml:5:", "Post_Request 5: type \"DISPLACEMENT\": expected MARKER_DISPLACEMENT", ""}},
    {"<Post_Request id=\"5\" expr1=\"1\"/>", {"bad.xml:5:", "Post_Request 5:", "type is missing"}},
    {"<Post_Request id=\"5\" type=\"EXPRESSION\" expr1=\"1\"/>\n"
     "<Post_Request id=\"5\" type=\"EXPRESSION\" expr1=\"2\"/>",
     {"bad.xml:6:", "Post_Request 5 is defined twice (line 5)", ""}},
};

/* Requests reading ORIENT, as published datasets' requests do, are written
 * without a warning. (No function of the language is left unanswered, so no
 * request is set aside with a warning for one.) */
static void test_orient_requests_are_written(void **state)
{
    (void)state;
    static const char text[] = STATE_DATASET
        "REQUEST/4, DISPLACEMENT, I=20\n"
        "REQUEST/6, F2=ORIENT(27,1,20,10)\\F3=ORIENT(27,2,20,10)\n"
        "END\n";
    hx_message msg;
    hx_model *m = hx_model_parse(text, strlen(text), "orient.adm", NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nrequests, 2);
    assert_int_equal(m->requests[0].id, 4);
    assert_int_equal(m->requests[1].id, 6);
    assert_int_equal(m->nwarnings, 0);
    hx_model_free(m);
}

static void test_bad_xml_requests(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof bad_xml / sizeof bad_xml[0]; ++k) {
        char text[2048];
        snprintf(text, sizeof text,
                 "<Model>\n<Body_Ground id=\"1\"/>\n"
                 "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\""
                 " inertia_zz=\"1\"/>\n<Reference_Marker id=\"20\" body_id=\"2\"/>\n%s\n</Model>\n",
                 bad_xml[k].element);
        hx_message msg;
        hx_model *m = parse(text, "bad.xml", &msg);
        if (m != NULL)
            fail_msg("case %zu read: %s", k, bad_xml[k].element);
        for (int j = 0; j < 3; ++j)
            if (bad_xml[k].needles[j][0] != '\0' && strstr(msg.text, bad_xml[k].needles[j]) == NULL)
                fail_msg("case %zu: \"%s\" not in \"%s\"", k, bad_xml[k].needles[j], msg.text);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values_at_a_known_state),
        cmocka_unit_test(test_xml_post_request),
        cmocka_unit_test(test_run_of_a_falling_spinning_body),
        cmocka_unit_test(test_fault_of_an_expression),
        cmocka_unit_test(test_bad_requests),
        cmocka_unit_test(test_bad_xml_requests),
        cmocka_unit_test(test_orient_requests_are_written),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
