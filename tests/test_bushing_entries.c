/*
 * The bushing's entries loaded through dlopen with the harness as host:
 * GFOSUB(1, ...) and ABM_BUSHING agree, GFOSUB and FIESUB forms give the same
 * force at the same state, host queries are only those the bushing needs
 * (in the dependency pass too), a file is parsed once for all elements naming
 * it, and input errors are reported once with zeros out.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "host/invoke.h"
#include "host/binding.h"
#include "session/session.h"
#include "frames/measures.h"
#include "sim_support.h"
#include "test_support.h"

static const char *gbs(const char *name, const char *activity_rows, const char *blocks)
{
    char text[4096];
    snprintf(text, sizeof text,
             "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\n"
             "FORCE = 'newton'\nMASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'CYLINDRICAL'\n"
             "[DIRECTIONS]\n(ACTIVITY)\n{ formulation FX FY FZ TX TY TZ }\n%s%s",
             activity_rows, blocks);
    return test_write_file(name, text);
}

static const char *const six_constant =
    "[CONSTANT_STIFFNESS_FX]\nK = 100\n[CONSTANT_STIFFNESS_FY]\nK = 150\n[CONSTANT_STIFFNESS_FZ]\nK = 80\n"
    "[CONSTANT_STIFFNESS_TX]\nK = 1e4\n[CONSTANT_STIFFNESS_TY]\nK = 2e4\n[CONSTANT_STIFFNESS_TZ]\nK = 3e4\n"
    "[CONSTANT_DAMPING_FX]\nC = 2\n[CONSTANT_DAMPING_FY]\nC = 3\n[CONSTANT_DAMPING_FZ]\nC = 1\n"
    "[CONSTANT_DAMPING_TX]\nC = 20\n[CONSTANT_DAMPING_TY]\nC = 30\n[CONSTANT_DAMPING_TZ]\nC = 10\n";

static const char *const limits_file =
    "[HEADER]\nFILE_TYPE = 'gbi'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n[MOUNT_LIMITS]\n"
    "IMPACT_PARAMETERS_TRA_X_POS = 500 2 10 0.5 0.5\nIMPACT_PARAMETERS_TRA_X_NEG = 500 2 10 0.5 0.5\n"
    "IMPACT_PARAMETERS_TRA_Y_POS = 0 1 0 0 0\nIMPACT_PARAMETERS_TRA_Y_NEG = 0 1 0 0 0\n"
    "IMPACT_PARAMETERS_TRA_Z_POS = 0 1 0 0 0\nIMPACT_PARAMETERS_TRA_Z_NEG = 0 1 0 0 0\n"
    "IMPACT_PARAMETERS_ROT_X_POS = 0 1 0 0 0\nIMPACT_PARAMETERS_ROT_X_NEG = 0 1 0 0 0\n"
    "IMPACT_PARAMETERS_ROT_Y_POS = 0 1 0 0 0\nIMPACT_PARAMETERS_ROT_Y_NEG = 0 1 0 0 0\n"
    "IMPACT_PARAMETERS_ROT_Z_POS = 0 1 0 0 0\nIMPACT_PARAMETERS_ROT_Z_NEG = 0 1 0 0 0\n";

/* A model: body 2 displaced and turned and moving, held to ground by the
 * given force elements; strings 101..104 name the files. */
static const char *model(const char *name, int units, const char *elements)
{
    char text[8192];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n%s"
             "<Reference_String id=\"101\" string=\"%s\"/>\n"
             "<Reference_String id=\"102\" string=\"%s\"/>\n"
             "<Reference_String id=\"103\" string=\"%s\"/>\n"
             "<Reference_String id=\"104\" string=\"%s\"/>\n"
             "<Reference_String id=\"105\" string=\"%s\"/>\n"
             "<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"\n"
             " v_ic_x=\"3\" v_ic_y=\"-2\" v_ic_z=\"1\" w_ic_x=\"0.3\" w_ic_y=\"-0.2\" w_ic_z=\"0.1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.8\" pos_y=\"-0.5\" pos_z=\"0.3\"\n"
             " a00=\"0.995004165\" a10=\"0.0998334166\" a01=\"-0.0998334166\" a11=\"0.995004165\"/>\n"
             "%s</Model></MotionSolve>\n",
             units ? "<Param_Unit length_unit=\"MILLIMETER\" force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" time_unit=\"SECOND\"/>\n" : "",
             gbs("all.gbs", "'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n'CONSTANT_DAMPING' 1 1 1 1 1 1\n", six_constant),
             gbs("translation.gbs", "'CONSTANT_STIFFNESS' 1 1 1 0 0 0\n", six_constant),
             gbs("damped_translation.gbs", "'CONSTANT_STIFFNESS' 1 1 0 0 0 0\n'CONSTANT_DAMPING' 1 0 0 0 0 0\n", six_constant),
             gbs("rotation.gbs", "'CONSTANT_STIFFNESS' 0 0 0 0 0 1\n", six_constant),
             test_write_file("limits.gbi", limits_file), elements);
    return test_write_file(name, text);
}


static void open_session(hx_session *s, const char *path)
{
    hx_message msg;
    if (hx_session_open(s, path, stderr, &msg) != 0)
        fail_msg("%s", msg.text);
}

static void default_named_and_field_forms_agree(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("agree.xml", 1,
                           GFO(1, "(1, 20, 10, 101)", "GFOSUB") GFO(2, "(20, 10, 101)", "ABM_BUSHING")
                           FIE(3, "(1, 101)", "FIESUB") FIE(4, "(101)", "ABM_BUSHING_FIELD")));
    double F[4][6];
    for (int k = 0; k < 2; ++k)
        hx_invoke_force(&s.bindings.items[k], &s.frames, 0, 0, F[k], NULL);
    double disp[6], velo[6], dfd[36], dfv[36];
    hx_force_deformation(&s.frames, 2, disp, velo);
    for (int k = 2; k < 4; ++k)
        hx_invoke_field(&s.bindings.items[k], &s.frames, disp, velo, 0, 0, F[k], dfd, dfv, NULL);
    for (int k = 1; k < 4; ++k)
        for (int i = 0; i < 6; ++i)
            assert_close(F[k][i], F[0][i], 1e-12, 1e-12);
    /* and it is the bushing law at that state, e.g. -(k x + c vx) in x */
    assert_close(F[0][2], -(80 * disp[2] + 1 * velo[2]), 1e-12, 1e-12);
    assert_true(fabs(F[0][5]) > 0.0);
    hx_session_close(&s);
}

static int deps_of(hx_session *s, int k, char *text, size_t size)
{
    hx_binding *b = &s->bindings.items[k];
    hx_call call;
    double out[6];
    hx_binding_call_init(b, &call, 0, &s->frames, 1);
    hx_invoke_force(b, &s->frames, 0, 1, out, &call);
    const int dependency_calls = call.host_calls;
    hx_binding_call_init(b, &call, 0, &s->frames, 0);
    hx_invoke_force(b, &s->frames, 0, 0, out, &call);
    assert_int_equal(call.host_calls, dependency_calls); /* the same queries in both passes */
    assert_int_equal(call.undeclared.count, 0);
    hx_dependencies_text(&b->deps, text, size);
    return call.host_calls;
}

static void queries_only_what_the_bushing_needs(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("skip.xml", 1,
                           GFO(1, "(1, 20, 10, 101)", "GFOSUB") GFO(2, "(1, 20, 10, 102)", "GFOSUB")
                           GFO(3, "(1, 20, 10, 103)", "GFOSUB") GFO(4, "(1, 20, 10, 104)", "GFOSUB")));
    char text[256];
    /* all six, damped; at rest (this state) the twist comes from AZ */
    assert_int_equal(deps_of(&s, 0, text, sizeof text), 3);
    assert_string_equal(text, "DISP(20,10,10) AZ(20,10) VEL(20,10,10,10)");
    assert_int_equal(deps_of(&s, 1, text, sizeof text), 1); /* translations, undamped */
    assert_string_equal(text, "TDISP(20,10,10)");
    assert_int_equal(deps_of(&s, 2, text, sizeof text), 2); /* translations, one damped */
    assert_string_equal(text, "TDISP(20,10,10) TVEL(20,10,10,10)");
    assert_int_equal(deps_of(&s, 3, text, sizeof text), 2); /* a rotation alone, at rest */
    assert_string_equal(text, "RDISP(20,10) AZ(20,10)");
    /* inactive directions return 0 */
    double out[6];
    hx_invoke_force(&s.bindings.items[1], &s.frames, 0, 0, out, NULL);
    for (int i = 3; i < 6; ++i)
        assert_close(out[i], 0.0, 0, 0);
    hx_invoke_force(&s.bindings.items[3], &s.frames, 0, 0, out, NULL);
    for (int i = 0; i < 5; ++i)
        assert_close(out[i], 0.0, 0, 0);
    assert_true(fabs(out[5]) > 0.0);
    hx_session_close(&s);
}

static void a_file_is_parsed_once(void **state)
{
    (void)state;
    /* without model units each parse says "values used as they are" once */
    hx_session s;
    hx_message msg;
    if (hx_session_open(&s, model("once.xml", 0,
                                  GFO(1, "(1, 20, 10, 102)", "GFOSUB") GFO(2, "(1, 20, 10, 102)", "GFOSUB")
                                  FIE(3, "(1, 102)", "FIESUB") GFO(4, "(1, 20, 10, 103)", "GFOSUB")),
                        NULL, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_int_equal(s.messages.notices, 2); /* translation.gbs once, damped_translation.gbs once */
    assert_contains(s.messages.last_notice, "declares no units", "damped_translation.gbs");
    assert_int_equal(s.messages.errors, 0);
    hx_session_close(&s);
}

static void input_errors_are_reported_once(void **state)
{
    (void)state;
    const struct {
        const char *element;
        const char *const needles[3];
    } cases[] = {
        {GFO(7, "(7, 20, 10, 101)", "GFOSUB"), {"GFOSUB element 7", "par[0]) is 7", "element code"}},
        {GFO(8, "(20, 10, 99)", "ABM_BUSHING"), {"ABM_BUSHING element 8", "no Reference_String 99", ".gbs"}},
        {GFO(9, "(20.5, 10, 101)", "ABM_BUSHING"), {"element 9", "par[0]) is 20.5", "I marker"}},
        {GFO(10, "(20, 10, 101, 5)", "ABM_BUSHING"), {"element 10", "no Reference_String 5", ".gbi"}},
        {GFO(13, "(20, 10, 101, 105, 6)", "ABM_BUSHING"), {"element 13", "one too many", "USER parameter 5"}},
        {FIE(14, "(1, 101, 102)", "FIESUB"), {"FIESUB element 14", "FILE_TYPE is 'gbs'", "expected 'gbi'"}},
        {FIE(11, "(1)", "FIESUB"), {"FIESUB element 11", "USER list ends", "Reference_String id"}},

    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char name[32];
        snprintf(name, sizeof name, "error%zu.xml", k);
        expect_one_setup_error(model(name, 1, cases[k].element), cases[k].needles);
    }
}

static void the_host_refusing_a_query(void **state)
{
    (void)state;
    hx_session s;
    hx_message msg;
    assert_int_equal(hx_session_open(&s, model("refused.xml", 1, GFO(5, "(1, 999, 10, 101)", "GFOSUB")), NULL, &msg), -1);
    assert_contains(msg.text, "GFOSUB element 5", "could not answer DISP(999,10", "output is zero");
}

static void non_finite_field_state(void **state)
{
    (void)state;
    hx_session s;
    open_session(&s, model("nan.xml", 1, FIE(3, "(1, 101)", "FIESUB")));
    s.messages.stream = NULL;
    double disp[6] = {0, NAN, 0, 0, 0, 0}, velo[6] = {0}, F[6], dfd[36], dfv[36];
    for (int i = 0; i < 36; ++i)
        dfd[i] = dfv[i] = 1.0;
    hx_invoke_field(&s.bindings.items[0], &s.frames, disp, velo, 0, 0, F, dfd, dfv, NULL);
    assert_contains(s.messages.last_error, "FIESUB element 3", "disp", "not finite");
    for (int i = 0; i < 6; ++i)
        assert_close(F[i], 0.0, 0, 0);
    for (int i = 0; i < 36; ++i) {
        assert_close(dfd[i], 0.0, 0, 0);
        assert_close(dfv[i], 0.0, 0, 0);
    }
    hx_session_close(&s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(default_named_and_field_forms_agree),
        cmocka_unit_test(queries_only_what_the_bushing_needs),
        cmocka_unit_test(a_file_is_parsed_once),
        cmocka_unit_test(input_errors_are_reported_once),
        cmocka_unit_test(the_host_refusing_a_query),
        cmocka_unit_test(non_finite_field_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
