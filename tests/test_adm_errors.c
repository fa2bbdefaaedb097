/*
 * Bad datasets (docs/interface.md §9): every unknown statement, keyword and
 * abbreviation, wrong value count, bad number, undefined id, missing
 * keyword, duplicate id, USER list that does not parse, ROUTINE that names
 * no library, refused statement: an error naming the file, the line and the
 * statement, and no model. Statements that act on the dynamics and are not
 * modelled are read with a warning naming them (their expressions kept);
 * run refuses such a model, naming the first.
 */
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "model/model.h"
#include "sim_support.h"
#include "test_support.h"

/* A ground with marker 10, a part 2 with markers 20 (its CM) and 21; the
 * fragment from line 7. */
static void dataset(char *out, size_t size, const char *fragment)
{
    snprintf(out, size, "errors\nPART/1, GROUND\nMARKER/10, PART=1\n"
             "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nMARKER/21, PART=2\n%s\nEND\n",
             fragment);
}

static const struct {
    const char *fragment;
    const char *needles[4];
} cases[] = {
    {"WIDGET/3, A=1", {"errors.adm:7:", "WIDGET is not a statement the harness knows", "", ""}},
    {"SFORCE/3, TRANSLATION, I=21, J=10, FUNCTION=1, COLOR=2",
     {"errors.adm:7:", "SFORCE/3:", "COLOR (column 48) is not a keyword of SFORCE", "ACTIONONLY"}},
    {"GFORCE/3, I=21, JFLOAT=10, F=USER(1)",
     {"errors.adm:7:", "GFORCE/3:", "keyword F (column 28) is ambiguous", "FX, FY, FZ and FUNCTION"}},
    {"MARKER/22, PART=2, REULER=1,2", {"errors.adm:7:", "MARKER/22:", "REULER takes 3 values, not 2", ""}},
    {"PART/3, MASS=1.2.3, CM=30, IP=1,1,1\nMARKER/30, PART=3",
     {"errors.adm:7:", "PART/3:", "MASS 1.2.3 (column 14) is not a number", ""}},
    {"PART/3, MASS=1, CM=30, IP=1,1,1e999\nMARKER/30, PART=3",
     {"errors.adm:7:", "PART/3:", "IP, value 3, 1e999", "is not a number"}},
    {"SFORCE/3, TRANSLATION, I=21, J=99, FUNCTION=1",
     {"errors.adm:7:", "SFORCE/3:", "J=99 (column 32) names no MARKER statement", ""}},
    {"SFORCE/3, TRANSLATION, I=21,\n, J=10", {"errors.adm:7:", "SFORCE/3:", "FUNCTION is missing", ""}},
    {"MARKER/20, PART=2", {"errors.adm:7:", "MARKER/20 is defined twice (first at line 5)", "", ""}},
    {"SFORCE/3, TRANSLATION, I=21, J=10,\n, FUNCTION=USER(1, x)",
     {"errors.adm:8:", "SFORCE/3:", "FUNCTION (column 12)", "value 2 is not a number"}},
    {"SFORCE/3, TRANSLATION, I=21, J=10, FUNCTION=USER(1), ROUTINE=::SFOSUB",
     {"errors.adm:7:", "SFORCE/3:", "ROUTINE=::SFOSUB names no library", ""}},
    {"SFORCE/3, TRANSLATION, I=21, J=10, FUNCTION=USER(1), ROUTINE=a::F, b::G",
     {"errors.adm:7:", "SFORCE/3:", "ROUTINE takes 1 value, not 2", ""}},
    {"CONTACT/3, I=21, J=10", {"errors.adm:7:", "CONTACT/3:", "contact needs the parts' geometry", ""}},
    {"SFORCE/, I=21", {"errors.adm:7:", "SFORCE:", "needs a positive id", ""}},
    {"SFORCE/0, I=21", {"errors.adm:7:", "SFORCE:", "needs a positive id", ""}},
    {"UNITS/7, FORCE=NEWTON", {"errors.adm:7:", "UNITS/7:", "takes no id", ""}},
    {"JOINT/3, I=21, J=10", {"errors.adm:7:", "JOINT/3:", "give the joint's type", ""}},
    {"MARKER/22, PART=2, QP=1,0,0\nJOINT/3, REVOLUTE, I=22, J=10",
     {"errors.adm:8:", "JOINT/3:", "Constraint_Joint 3", "must coincide"}},
    {"PART/3, CM=30\nMARKER/30, PART=3", {"errors.adm:7:", "PART/3:", "MASS is missing", ""}},
    {"PART/3, GROUND", {"errors.adm:7:", "Body_Ground 3", "already has a ground body", ""}},
    {"MARKER/22, PART=1, FLOATING, QP=1,2,3",
     {"errors.adm:7:", "MARKER/22:", "QP on a FLOATING marker", ""}},
    {"MARKER/22, PART=2, RM=23\nMARKER/23, PART=2, RM=22",
     {"errors.adm:", "MARKER/2", "RM chain leads back to itself", ""}},
    {"STRING/3", {"errors.adm:7:", "STRING/3:", "STRING is missing", ""}},
    {"SPLINE/3, X=1,2,3,4, Y=1,2,3,4, FILE=curve.txt",
     {"errors.adm:7:", "SPLINE/3:", "FILE: splines read from a file", ""}},
    {"SPLINE/3, X=1,2,3,4, Y=1,2,3", {"errors.adm:7:", "SPLINE/3:", "Y gives 3 values for 4 X values", ""}},
    {"UNITS/FORCE=NEWTONS", {"errors.adm:7:", "UNITS:", "FORCE=NEWTONS is not a unit", "KILO_NEWTON"}},
    {"UNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=MILLIMETER, TIME=SECOND, UCF=1",
     {"errors.adm:7:", "UNITS:", "UCF=1, but the units give 1000", ""}},
    {"FORCE_STATEEQN/3, I=21, JFLOAT=10, RM=10, X=5, FUNCTION=USER(1)",
     {"errors.adm:7:", "FORCE_STATEEQN/3:", "X=5 (column 45) names no ARRAY statement", ""}},
    {"ARRAY/5, X, U, SIZE=2", {"errors.adm:7:", "ARRAY/5:", "one type of array", ""}},
    {"ARRAY/5, IC, NUMBERS=1,2, SIZE=3", {"errors.adm:7:", "ARRAY/5:", "SIZE=3 but NUMBERS gives 2", ""}},
    {"COUPLER/3, JOINTS=1", {"errors.adm:7:", "COUPLER/3:", "JOINTS takes 2 to 3 values, not 1", ""}},
    {"MOTION/3, JOINT=1, FUNCTION=USER(1)", {"errors.adm:7:", "MOTION/3:", "JOINT=1 (column 17) names no JOINT", ""}},
    {"PART/3, MASS=1, CM=30, IP=1,1,1, VM=0\nMARKER/30, PART=3",
     {"errors.adm:7:", "PART/3:", "VM 0", "not an id (a positive integer)"}},
    {"GFORCE/3, I=21, JFLOAT=10, FUNCTION=3.5",
     {"errors.adm:7:", "GFORCE/3:", "FUNCTION=3.5: a GFORCE's FUNCTION is USER(...)", ""}},
    {"COUPLER/3, JOINTS=1, 2, FUNCTION=2*TIME\nJOINT/1, REVOLUTE, I=20, J=10\n"
     "PART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3\nJOINT/2, REVOLUTE, I=30, J=10",
     {"errors.adm:7:", "COUPLER/3:", "FUNCTION=2*TIME: expected USER(...)", ""}},
    /* a ROUTINE beside a FUNCTION that is not USER(...): named at its line */
    {"SFORCE/3, TRANSLATION, I=21, J=10, FUNCTION=1,\n, ROUTINE=lib::SFOSUB",
     {"errors.adm:8:", "SFORCE/3:", "ROUTINE without FUNCTION=USER(...)", ""}},
    {"VARIABLE/3, FUNCTION=TIME,\n, ROUTINE=lib::VARSUB",
     {"errors.adm:8:", "VARIABLE/3:", "ROUTINE without FUNCTION=USER(...)", ""}},
    {"DIFF/3, IC=0, FUNCTION=TIME,\n, ROUTINE=lib::DIFSUB",
     {"errors.adm:8:", "DIFF/3:", "ROUTINE without FUNCTION=USER(...)", ""}},
    {"GCON/3, I=20, FUNCTION=DX(20),\n, ROUTINE=lib::GCOSUB",
     {"errors.adm:8:", "GCON/3:", "ROUTINE without FUNCTION=USER(...)", ""}},
    {"JOINT/1, REVOLUTE, I=20, J=10\nMOTION/3, JOINT=1, FUNCTION=TIME,\n, ROUTINE=lib::MOTSUB",
     {"errors.adm:9:", "MOTION/3:", "ROUTINE without FUNCTION=USER(...)", ""}},
    {"REQUEST/3, DISPLACEMENT, I=20, J=10,\n, ROUTINE=lib::REQSUB",
     {"errors.adm:8:", "REQUEST/3:", "ROUTINE without FUNCTION=USER(...)", ""}},
    /* last: read (every_bad_statement) */
    {"VARIABLE/3, FUNCTION=USER(1), ROUTINE=lib::A\\", {"errors.adm:", "", "", ""}},
};

static void every_bad_statement(void **state)
{
    (void)state;
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        char text[2048];
        dataset(text, sizeof text, cases[k].fragment);
        hx_message msg;
        hx_model *m = hx_model_parse(text, strlen(text), "errors.adm", NULL, &msg);
        if (k == sizeof cases / sizeof cases[0] - 1) { /* a trailing '\' reads (an empty item) */
            assert_non_null(m);
            hx_model_free(m);
            continue;
        }
        if (m != NULL)
            fail_msg("case %zu (%s) was read", k, cases[k].fragment);
        assert_contains(msg.text, cases[k].needles[0], cases[k].needles[1], cases[k].needles[2],
                        cases[k].needles[3]);
    }
}

static void nul_bytes_and_missing_files(void **state)
{
    (void)state;
    static const char text[] = "t\nPART/1, GROUND\nMARKER/1\0, PART=1\nEND\n";
    hx_message msg;
    assert_null(hx_model_parse(text, sizeof text - 1, "nul.adm", NULL, &msg));
    assert_contains(msg.text, "nul.adm:3:", "NUL byte");
    assert_null(hx_model_read("/nonexistent/model.adm", NULL, &msg));
    assert_contains(msg.text, "/nonexistent/model.adm", "cannot open");
}

/* Reads the dataset with its warnings into *warnings (to be freed). */
static hx_model *read_warned(const char *path, char **warnings)
{
    size_t n = 0;
    FILE *w = open_memstream(warnings, &n);
    hx_message msg;
    hx_model *m = hx_model_read(path, w, &msg);
    fclose(w);
    if (m == NULL)
        fail_msg("%s", msg.text);
    return m;
}

static void unsimulated_statements_are_named(void **state)
{
    (void)state;
    char text[4096];
    dataset(text, sizeof text,
            "MARKER/22, PART=2\nPART/3, MASS=1, CM=30, IP=1,1,1\nMARKER/30, PART=3\n"
            "JOINT/3, INLINE, I=21, J=10\n"                          /* line 10 */
            "JOINT/4, REVOLUTE, I=30, J=10\nJOINT/5, TRANSLATIONAL, I=30, J=10\n"
            "COUPLER/1, JOINTS=3, 4, SCALES=1, 2\n"                  /* line 13 */
            "FIELD/4, I=21, J=10,\n, FUNCTION = -100*(DM(21,10) - 5)\n"
            ", - 2*VR(21,10)\n"                                      /* lines 14-16 */
            "NFORCE/1, I=21, 30, JFLOAT=10, LENGTH=1, 1\n"           /* line 17 */
            "INTEGRATOR/GSTIFF, ERROR=1E-4\nEQUILIBRIUM/STABILITY=1\nEQUILIBRIUM/TLIMIT=1\n"
            "VARIABLE/1, FUNCTION=DX(21,10)\nVARIABLE/2, FUNCTION=DX(21,10)+1\n"
            "PINPUT/1, VARIABLES=1, 2\nPOUTPUT/2, VARIABLES=2");
    const char *path = test_write_file("unsimulated.adm", text);
    char *warnings = NULL;
    hx_model *m = read_warned(path, &warnings);
    assert_contains(warnings,
                    "unsimulated.adm:10: warning: JOINT/3: a INLINE joint, a primitive, which the"
                    " harness simulates as a JPRIM",
                    "unsimulated.adm:13: warning: COUPLER/1: it names JOINT/3, which is not simulated",
                    "unsimulated.adm:14: warning: FIELD/4: a FUNCTION expression, which this harness"
                    " does not evaluate yet",
                    "unsimulated.adm:17: warning: NFORCE/1: a multi-point force (NFORCE)",
                    "run and bench refuse the model",
                    "unsimulated.adm:19: note: EQUILIBRIUM is read and has no effect",
                    "unsimulated.adm:18: note: INTEGRATOR: GSTIFF is read");
    /* VARIABLE/2 by an expression is simulated (docs/interface.md §9.6) */
    assert_null(strstr(warnings, "VARIABLE/2"));
    /* the note about EQUILIBRIUM once */
    assert_null(strstr(strstr(warnings, "EQUILIBRIUM") + 1, "EQUILIBRIUM"));
    free(warnings);
    assert_int_equal(m->nunsimulated, 4);
    assert_string_equal(m->unsimulated, "JOINT/3 (line 10)");
    assert_int_equal(m->njoints, 2); /* JOINT/4 and JOINT/5: two joints of PART/3, not reduced */
    assert_int_equal(m->ncouplers, 0);
    assert_int_equal(m->nvariables, 2);
    assert_close(m->suggested_error, 1e-4, 0, 0);
    /* the expression kept as written, joined over its lines, where it begins */
    assert_int_equal(m->nexpressions, 1);
    assert_string_equal(m->expressions[0].statement, "FIELD");
    assert_int_equal(m->expressions[0].id, 4);
    assert_string_equal(m->expressions[0].keyword, "FUNCTION");
    assert_string_equal(m->expressions[0].text, "-100*(DM(21,10) - 5) - 2*VR(21,10)");
    assert_int_equal(m->expressions[0].line, 15);
    assert_int_equal(m->expressions[0].column, 14);
    /* PINPUT and POUTPUT: their VARIABLE ids */
    assert_int_equal(m->npinputs, 1);
    assert_int_equal(m->pinputs[0].nvariables, 2);
    assert_int_equal(m->pinputs[0].variable_ids[1], 2);
    assert_int_equal(m->npoutputs, 1);
    assert_int_equal(m->poutputs[0].id, 2);
    hx_model_free(m);

    /* run refuses it, naming the first */
    char log[1024];
    snprintf(log, sizeof log, "%s/run.log", test_temp_dir());
    fflush(stderr);
    const int saved = dup(2);
    const int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    assert_true(saved >= 0 && fd >= 0);
    dup2(fd, 2);
    close(fd);
    char csv[1024];
    snprintf(csv, sizeof csv, "%s/unsimulated.csv", test_temp_dir());
    const int status = sim_run_csv(path, csv, (const char *const[]){"--end", "0.01", "--quiet", NULL});
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    assert_int_not_equal(status, 0);
    FILE *f = fopen(log, "r");
    char said[2048] = "";
    assert_non_null(f);
    size_t n = fread(said, 1, sizeof said - 1, f);
    said[n] = '\0';
    fclose(f);
    assert_contains(said, "does not simulate", "JOINT/3 (line 10)");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_bad_statement),
        cmocka_unit_test(nul_bytes_and_missing_files),
        cmocka_unit_test(unsimulated_statements_are_named),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
