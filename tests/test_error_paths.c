/*
 * Every error path, table-driven. The library is loaded as a solver loads it
 * and its entries are called directly with the harness as host: for each bad
 * USER list and each bad property file, exactly one error through c_errmes
 * naming the element id, the parameter or the file line, and what was
 * expected; zeros out, on the first call and on the next; nothing crashes or
 * exits. Then each XML model error: an error naming the file and line and
 * what was wrong, and no model.
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "frames/frames.h"
#include "session/session.h"
#include "frames/measures.h"
#include "sim_support.h"
#include "test_support.h"
#include "usrsub/solver_abi.h"

static void *library;
static host_model host;

static const char *const good_gbs =
    "[HEADER]\nFILE_TYPE = 'gbs'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
    "MASS = 'kg'\nTIME = 'second'\n[GLOBAL]\nCOUPLING = 'UNCOUPLED'\n[DIRECTIONS]\n(ACTIVITY)\n"
    "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 1 1 1 1 1\n"
    "[CONSTANT_STIFFNESS_FX]\nK = 1\n[CONSTANT_STIFFNESS_FY]\nK = 1\n[CONSTANT_STIFFNESS_FZ]\nK = 1\n"
    "[CONSTANT_STIFFNESS_TX]\nK = 1\n[CONSTANT_STIFFNESS_TY]\nK = 1\n[CONSTANT_STIFFNESS_TZ]\nK = 1\n";

/* The Reference_Strings the cases name: 201.. good files, 301.. bad ones. */
static const char *strings(void)
{
    static char text[8192];
    char gbi_missing[1024], gfj_short[1024];
    snprintf(gbi_missing, sizeof gbi_missing,
             "[HEADER]\nFILE_TYPE = 'gbi'\n[UNITS]\nLENGTH = 'mm'\nANGLE = 'radian'\nFORCE = 'newton'\n"
             "MASS = 'kg'\nTIME = 'second'\n[MOUNT_LIMITS]\nIMPACT_PARAMETERS_TRA_X_POS = 1 1 1 1 1\n");
    snprintf(gfj_short, sizeof gfj_short,
             "[HEADER]\nFILE_TYPE = 'gfj'\n[STIFFNESS]\n(MATRIX)\n{ x y z ax ay az }\n"
             "1 0 0 0 0 0\n0 1 0 0 0\n0 0 1 0 0 0\n0 0 0 1 0 0\n0 0 0 0 1 0\n0 0 0 0 0 1\n");
    snprintf(text, sizeof text,
             "<Reference_String id=\"201\" string=\"%s\"/>\n"
             "<Reference_String id=\"202\" string=\"" EXAMPLES_DIR "/mount_limits.gbi\"/>\n"
             "<Reference_String id=\"301\" string=\"%s\"/>\n"
             "<Reference_String id=\"302\" string=\"%s\"/>\n"
             "<Reference_String id=\"303\" string=\"%s\"/>\n"
             "<Reference_String id=\"304\" string=\"%s\"/>\n"
             "<Reference_String id=\"305\" string=\"%s\"/>\n"
             "<Reference_String id=\"306\" string=\"%s\"/>\n"
             "<Reference_String id=\"307\" string=\"/nonexistent/file.gbs\"/>\n"
             "<Reference_String id=\"308\" string=\"%s\"/>\n",
             test_write_file("good.gbs", good_gbs),
             test_write_file("bad_number.gbs",
                             "[HEADER]\nFILE_TYPE = 'gbs'\n[DIRECTIONS]\n(ACTIVITY)\n"
                             "{ formulation FX FY FZ TX TY TZ }\n'CONSTANT_STIFFNESS' 1 0 0 0 0 0\n"
                             "[CONSTANT_STIFFNESS_FX]\nK = stiff\n"),
             test_write_file("hydromount.gbs",
                             "[HEADER]\nFILE_TYPE = 'gbs'\n[DIRECTIONS]\n(ACTIVITY)\n"
                             "{ formulation FX FY FZ TX TY TZ }\n'HYDROMOUNT_DAMPING' 1 0 0 0 0 0\n"),
             test_write_file("missing.gbi", gbi_missing), test_write_file("short.gfj", gfj_short),
             test_write_file("table.tbl", "# x y\n0 0\n1 oops\n2 4\n"),
             test_write_file("unclosed.gbs", "[HEADER\nFILE_TYPE = 'gbs'\n"),
             test_write_file("one_row.tbl", "0 0\n"));
    return text;
}

static void set_up(void)
{
    char text[16384];
    snprintf(text, sizeof text,
             "<MotionSolve><Model>\n"
             "<Param_Unit force_unit=\"NEWTON\" mass_unit=\"KILOGRAM\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>\n"
             "%s<Body_Ground id=\"1\"/><Reference_Marker id=\"10\" body_id=\"1\"/>\n"
             "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
             "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"1\"/>\n"
             "</Model></MotionSolve>\n", strings());
    host_model_attach(&host, "host.xml", text);
    host.messages.stream = NULL;
    library = load_library();
}

static void tear_down(void)
{
    dlclose(library);
    host_model_detach(&host);
}

typedef struct error_case {
    const char *entry;
    int id;
    int ndisp;            /* couplers */
    int npar;
    double par[16];
    const char *needles[4];
} error_case;

#define N NAN

static const error_case cases[] = {
    /* couplers: each USER layout */
    {"COUSUB", 101, 2, 2, {1, 5}, {"COUSUB element 101", "1 terms", "relates 2 joints"}},
    {"COUXX", 102, 2, 4, {1, 5, 9, 1}, {"element 102", "USER parameter 3", "code"}},
    {"COUXX2", 103, 2, 5, {2, 7, 1, 1, 1}, {"element 103", "USER parameter 2", "from 0 to 6"}},
    {"COUSUB", 104, 2, 5, {3, 1, 0, 0, 1, 1}, {"element 104", "USER parameter 2", "2"}},
    {"COUSUB", 105, 2, 8, {3, 2, 1, 0, 0, 1, 1, 1}, {"element 105", "strictly increasing", "x"}},
    {"COUSUB", 106, 2, 5, {4, 99, 1, 1, 1}, {"element 106", "Reference_String 99", "table"}},
    {"COUSUB", 107, 2, 5, {4, 305, 1, 1, 1}, {"element 107", "table.tbl' line 3", "two finite numbers"}},
    {"COUSUB", 108, 2, 5, {4, 308, 1, 1, 1}, {"element 108", "one_row.tbl", "2"}},
    {"COUSUB", 109, 2, 4, {1, N, 1, 1}, {"element 109", "USER parameter 2", "finite"}},
    {"COUSUB", 110, 4, 4, {1, 1, 1, 1}, {"element 110", "ndisp is 4", "2 or 3"}},
    {"COUSUB", 111, 2, 6, {1, 1, 1, 1, 1, 1}, {"element 111", "more than 2 terms", "USER parameter 5"}},
    {"COUSUB", 112, 2, 5, {1, 1, 5, 1, 1}, {"element 112", "ends after 5 values", "USER parameter 6"}},
    /* force elements: each USER layout */
    {"GFOSUB", 201, 0, 4, {9, 20, 10, 201}, {"GFOSUB element 201", "par[0]) is 9", "element code"}},
    {"GFOSUB", 202, 0, 4, {1, 20.5, 10, 201}, {"element 202", "is 20.5", "I marker id"}},
    {"GFOSUB", 203, 0, 3, {1, 20, 10}, {"element 203", "USER list ends", ".gbs"}},
    {"GFOSUB", 204, 0, 5, {1, 20, 10, 201, 7}, {"element 204", "no Reference_String 7", ".gbi"}},
    {"GFOSUB", 205, 0, 4, {1, 20, N, 201}, {"element 205", "USER parameter 3", "J marker id"}},
    {"GFOSUB", 206, 0, 4, {1, 999, 10, 201}, {"element 206", "DISP(999,10", "output is zero"}},
    {"FIESUB", 207, 0, 0, {0}, {"FIESUB element 207", "USER list ends", "element code"}},
    {"ABM_BUSHING", 208, 0, 2, {20, 10}, {"ABM_BUSHING element 208", "USER list ends", ".gbs"}},
    {"MOUNT_LIMITS_FIELD", 209, 0, 2, {202, 1}, {"MOUNT_LIMITS_FIELD element 209", "one too many", "USER parameter 2"}},
    {"FLEX_JOINT_FIELD", 210, 0, 1, {201}, {"FLEX_JOINT_FIELD element 210", "FILE_TYPE is 'gbs'", "expected 'gfj'"}},
    /* property files: each names its line */
    {"ABM_BUSHING_FIELD", 301, 0, 1, {301}, {"element 301", "bad_number.gbs' line 8", "not a finite number"}},
    {"ABM_BUSHING_FIELD", 302, 0, 1, {302}, {"element 302", "hydromount.gbs' line 6", "HYDROMOUNT_DAMPING"}},
    {"MOUNT_LIMITS_FIELD", 303, 0, 1, {303}, {"element 303", "missing.gbi' line 9", "IMPACT_PARAMETERS_TRA_X_NEG"}},
    {"FLEX_JOINT_FIELD", 304, 0, 1, {304}, {"element 304", "short.gfj' line 7", "row 2 has 5 entries"}},
    {"ABM_BUSHING_FIELD", 306, 0, 1, {306}, {"element 306", "unclosed.gbs' line 1", "not closed"}},
    {"ABM_BUSHING_FIELD", 307, 0, 1, {307}, {"element 307", "/nonexistent/file.gbs", "cannot open"}},
};

static void call_entry(const error_case *c, double *out)
{
    void *fn = dlsym(library, c->entry);
    assert_non_null(fn);
    int id = c->id, npar = c->npar, ndisp = c->ndisp, iflag = 0, dflag = 0;
    double time = 0.0, par[16];
    memcpy(par, c->par, sizeof par);
    for (int k = 0; k < 81; ++k)
        out[k] = 7.0; /* anything not written stays 7 */
    double disp[6] = {0.1, 0.2, 0.3, 0.01, 0.02, 0.03}, velo[6] = {1, 2, 3, 0.1, 0.2, 0.3};
    if (strncmp(c->entry, "COU", 3) == 0) {
        ((usrsub_coupler_fn *)fn)(&id, &time, par, &npar, disp, &ndisp, &iflag, out);
        for (int k = strcmp(c->entry, "COUSUB") == 0 ? 1 : strcmp(c->entry, "COUXX") == 0 ? ndisp : ndisp * ndisp;
             k < 81; ++k)
            out[k] = 0.0; /* only the outputs the entry owns are checked */
    } else if (strcmp(c->entry, "GFOSUB") == 0 || strcmp(c->entry, "ABM_BUSHING") == 0) {
        ((usrsub_gfosub_fn *)fn)(&id, &time, par, &npar, &dflag, &iflag, out);
        for (int k = 6; k < 81; ++k)
            out[k] = 0.0;
    } else {
        ((usrsub_fiesub_fn *)fn)(&id, &time, par, &npar, disp, velo, &dflag, &iflag, out, out + 6,
                                 out + 42);
        for (int k = 78; k < 81; ++k)
            out[k] = 0.0;
    }
}

static void every_user_layout_and_property_file_error(void **state)
{
    (void)state;
    set_up();
    int mismatches = 0;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const error_case *c = &cases[k];
        hx_messages_reset(&host.messages);
        double out[81];
        call_entry(c, out);
        if (host.messages.errors != 1)
            fail_msg("case %zu (%s %d): %d errors, expected 1", k, c->entry, c->id,
                     host.messages.errors);
        const char *text = host.messages.last_error;
        for (int n = 0; n < 4 && c->needles[n] != NULL; ++n)
            if (strstr(text, c->needles[n]) == NULL) {
                printf("MISMATCH case %zu (%s %d): '%s' is not in: %s\n", k, c->entry, c->id,
                       c->needles[n], text);
                mismatches++;
            }
        for (int i = 0; i < 81; ++i)
            if (out[i] != 0.0)
                fail_msg("case %zu (%s %d): output %d is %g, not 0", k, c->entry, c->id, i, out[i]);
        /* once: the next call is quiet, and zero again */
        call_entry(c, out);
        if (host.messages.errors != 1)
            fail_msg("case %zu (%s %d): reported again: %s", k, c->entry, c->id, host.messages.last_error);
        for (int i = 0; i < 81; ++i)
            assert_true(out[i] == 0.0);
    }
    tear_down();
    assert_int_equal(mismatches, 0);
}

/* ---- XML model errors ----------------------------------------------------------------------- */

static const struct {
    const char *fragment;
    const char *needles[3];
} xml_cases[] = {
    {"<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"abc\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>",
     {"Body_Rigid 3", "mass = \"abc\"", "not a finite number"}},
    {"<Reference_Marker id=\"30\" body_id=\"9\"/>", {"Reference_Marker 30", "body_id 9", "is not a Body_Rigid"}},
    {"<Force_Vector_TwoBody id=\"1\" type=\"ForceAndTorque\" i_marker_id=\"99\" j_floating_marker_id=\"10\""
     " ref_marker_id=\"10\" usrsub_param_string=\"USER(1)\"/>",
     {"Force_Vector_TwoBody 1", "i_marker_id 99", "not a Reference_Marker"}},
    {"<Force_Field id=\"1\" i_marker_id=\"20\" j_marker_id=\"10\" usrsub_param_string=\"USER(1,20,10\"/>",
     {"Force_Field 1", "usrsub_param_string", "expected ',' or ')'"}},
    {"<Constraint_Joint id=\"1\" type=\"GEAR\" i_marker_id=\"20\" j_marker_id=\"10\"/>",
     {"Constraint_Joint 1", "type \"GEAR\"", "FIXED, REVOLUTE"}},
    {"<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"20\" j_marker_id=\"20\"/>",
     {"Constraint_Joint 1", "I and J markers (20, 20)", "on the same body"}},
    {"<Constraint_Coupler id=\"1\" joint1_id=\"7\" freedom_1=\"R\" joint2_id=\"8\" freedom_2=\"R\" coefficients=\"1,2\"/>",
     {"Constraint_Coupler 1", "joint1_id 7", "not a Constraint_Joint"}},
    {"<Reference_Marker id=\"20\" body_id=\"2\"/>", {"Reference_Marker 20", "defined twice", "line 5"}},
    {"<Reference_Marker id=\"30\" body_id=\"2\" a00=\"2\" a11=\"1\" a22=\"1\"/>",
     {"Reference_Marker 30", "direction cosines", "not orthonormal"}},
    {"<Param_Unit force_unit=\"NEWTON\" mass_unit=\"STONE\" length_unit=\"MILLIMETER\" time_unit=\"SECOND\"/>",
     {"Param_Unit", "mass_unit = \"STONE\"", "KILOGRAM"}},
    {"<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"-1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>"
     "<Reference_Marker id=\"30\" body_id=\"3\"/>", {"Body_Rigid 3", "must be positive", "got -1"}},
    {"<Reference_String id=\"5\"/>", {"Reference_String 5", "attribute string is missing", ""}},
    {"<Body_Rigid id=\"3\" cg_id=\"30\"", {"malformed XML", "", ""}},
};

static void every_xml_model_error(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof xml_cases / sizeof xml_cases[0]; ++k) {
        char text[2048], name[32];
        snprintf(text, sizeof text,
                 "<MotionSolve><Model>\n<Body_Ground id=\"1\"/>\n<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
                 "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1\" inertia_xx=\"1\" inertia_yy=\"1\" inertia_zz=\"1\"/>\n"
                 "<Reference_Marker id=\"20\" body_id=\"2\"/>\n%s\n</Model></MotionSolve>\n",
                 xml_cases[k].fragment);
        snprintf(name, sizeof name, "model%zu.xml", k);
        hx_message msg;
        hx_model *m = hx_model_read(test_write_file(name, text), NULL, &msg);
        if (m != NULL)
            fail_msg("case %zu: the model was read", k);
        char where[64];
        snprintf(where, sizeof where, "%s:%d", name, xml_cases[k].needles[0][0] == 'm' ? 7 : 6);
        assert_contains(msg.text, where, xml_cases[k].needles[0], xml_cases[k].needles[1],
                        xml_cases[k].needles[2]);
    }
    /* a missing model file */
    hx_message msg;
    assert_null(hx_model_read("/nonexistent/model.xml", NULL, &msg));
    assert_contains(msg.text, "/nonexistent/model.xml", "cannot open");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_user_layout_and_property_file_error),
        cmocka_unit_test(every_xml_model_error),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
