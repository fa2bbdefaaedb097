/*
 * The Adams command file (docs/interface.md §9.9): its first two lines are
 * names, then the commands of a run in order with their lines; each command
 * checked against its keywords like a dataset's statements; any command the
 * harness does not read refused by name and line.
 */
#include <stdio.h>
#include <string.h>

#include "model/adm/command_file.h"
#include "test_support.h"

static hx_command_file *parse_ok(const char *text)
{
    hx_message msg;
    hx_command_file *f = hx_command_file_parse(text, strlen(text), "run.acf", &msg);
    if (f == NULL)
        fail_msg("%s", msg.text);
    return f;
}

#define expect_error(commands, ...)                                                        \
    do {                                                                                   \
        hx_message msg_;                                                                   \
        const char *t_ = (commands);                                                       \
        hx_command_file *f_ = hx_command_file_parse(t_, strlen(t_), "run.acf", &msg_);     \
        if (f_ != NULL) {                                                                  \
            hx_command_file_free(f_);                                                      \
            fail_msg("read; expected an error");                                           \
        }                                                                                  \
        assert_contains(msg_.text, __VA_ARGS__);                                           \
    } while (0)

static void a_run_in_order(void **state)
{
    (void)state;
    hx_command_file *f = parse_ok(
        "powertrain.adm\n"
        "out/powertrain\n"
        "! a comment\n"
        "INTEGRATOR/GSTIFF, ERROR=1.0E-04\n"                       /* line 4 */
        "SIMULATE/DYNAMIC, END=0.4, STEPS=400\n"                   /* line 5 */
        "DEACTIVATE/SFORCE, ID=3, 4\n"                             /* line 6 */
        "variable/7, function = STEP(TIME, 0.4, 0,\n"
        ", 0.5, 1)\n"                                              /* lines 7-8 */
        "ACCGRAV/KGRAV=-9.81\n"                                    /* line 9 */
        "SIM/DYN, DURATION=0.6, DTOUT=1E-3\n"                      /* line 10 */
        "ACTIVATE/GFORCE, RANGE=10, 12\n"                          /* line 11 */
        "SIMULATE/STATIC\n"                                        /* line 12 */
        "STOP\n"
        "NOT READ/AFTER STOP\n");
    assert_string_equal(f->dataset, "powertrain.adm");
    assert_string_equal(f->output, "out/powertrain");
    assert_int_equal(f->ncommands, 9);
    const hx_command *c = f->commands;
    assert_int_equal(c[0].kind, HX_COMMAND_INTEGRATOR);
    assert_string_equal(c[0].integrator, "GSTIFF");
    assert_close(c[0].error, 1e-4, 0, 0);
    assert_int_equal(c[0].line, 4);
    assert_int_equal(c[1].kind, HX_COMMAND_SIMULATE);
    assert_int_equal(c[1].analysis, HX_ANALYSIS_DYNAMIC);
    assert_close(c[1].end, 0.4, 0, 0);
    assert_int_equal(c[1].steps, 400);
    assert_int_equal(c[1].duration, 0);
    assert_int_equal(c[2].kind, HX_COMMAND_DEACTIVATE);
    assert_string_equal(c[2].element, "SFORCE");
    assert_int_equal(c[2].nids, 2);
    assert_int_equal(c[2].ids[1], 4);
    assert_int_equal(c[3].kind, HX_COMMAND_VARIABLE);
    assert_int_equal(c[3].ids[0], 7);
    assert_string_equal(c[3].function, "STEP(TIME, 0.4, 0,   0.5, 1)");
    assert_int_equal(c[3].function_line, 7);
    assert_int_equal(c[3].function_column, 24);
    assert_int_equal(c[4].kind, HX_COMMAND_ACCGRAV);
    assert_int_equal(c[4].gravity_given[0], 0);
    assert_int_equal(c[4].gravity_given[2], 1);
    assert_close(c[4].gravity[2], -9.81, 0, 0);
    assert_int_equal(c[5].duration, 1);
    assert_close(c[5].end, 0.6, 0, 0);
    assert_close(c[5].dtout, 1e-3, 0, 0);
    assert_int_equal(c[5].line, 10);
    assert_int_equal(c[6].kind, HX_COMMAND_ACTIVATE);
    assert_int_equal(c[6].nids, 3);
    assert_int_equal(c[6].ids[2], 12);
    assert_int_equal(c[7].analysis, HX_ANALYSIS_STATIC);
    assert_int_equal(c[8].kind, HX_COMMAND_STOP);
    assert_int_equal(c[8].line, 13);
    assert_string_equal(c[0].settings, ""); /* ERROR alone: nothing else to note */
    hx_command_file_free(f);
    /* INTEGRATOR's settings besides its name and ERROR, named for the run's note */
    f = parse_ok("m.adm\n\nINTEGRATOR/WSTIFF, HMAX=0.01, ERROR=1E-5, KMAX=3\n");
    assert_string_equal(f->commands[0].integrator, "WSTIFF");
    assert_string_equal(f->commands[0].settings, "HMAX, KMAX");
    hx_command_file_free(f);
}

static void commands_refused_and_malformed(void **state)
{
    (void)state;
    expect_error("m.adm\n\nPREFERENCES/SOLVERBIAS=CXX\nSTOP\n", "run.acf:3:", "PREFERENCES",
                 "a command the harness does not read", "SIMULATE");
    expect_error("m.adm\n\nSIMULATE/KINEMATIC, END=1, STEPS=10\n", "run.acf:3:", "SIMULATE:",
                 "KINEMATIC: the harness reads dynamic and static analyses only");
    expect_error("m.adm\n\nSIMULATE/DYNAMIC, END=1\n", "run.acf:3:", "STEPS or DTOUT");
    expect_error("m.adm\n\nSIMULATE/DYNAMIC, STEPS=10\n", "run.acf:3:", "END or DURATION");
    expect_error("m.adm\n\nSIMULATE/DYNAMIC, END=1, STEPS=1.5\n", "run.acf:3:",
                 "STEPS 1.5 (column 32) is not an integer");
    expect_error("m.adm\n\nSIMULATE/DYNAMIC, D=1, STEPS=10\n", "run.acf:3:", "keyword D",
                 "ambiguous", "DYNAMIC, DURATION and DTOUT");
    expect_error("m.adm\n\nDEACTIVATE/SFORCE\n", "run.acf:3:", "DEACTIVATE:",
                 "ID=id[,id...] or RANGE=first,last");
    expect_error("m.adm\n\nDEACTIVATE/ID=3\n", "run.acf:3:", "names no element");
    expect_error("m.adm\n\nVARIABLE/FUNCTION=1\n", "run.acf:3:", "VARIABLE:", "needs a positive id");
    expect_error("m.adm\n\nINTEGRATOR/GSTIFF, WSTIFF\n", "run.acf:3:", "GSTIFF and WSTIFF");
    expect_error("\nout\nSTOP\n", "run.acf:1:", "names the dataset");
    hx_message msg;
    assert_null(hx_command_file_read("/nonexistent/run.acf", &msg));
    assert_contains(msg.text, "/nonexistent/run.acf", "cannot open");
    /* read from a file, CRLF line ends */
    hx_command_file *f = hx_command_file_read(
        test_write_file("crlf.acf", "m.adm\r\nout\r\nSIMULATE/DYNAMIC, END=1, STEPS=10\r\nSTOP\r\n"),
        &msg);
    assert_non_null(f);
    assert_string_equal(f->output, "out");
    assert_int_equal(f->ncommands, 2);
    hx_command_file_free(f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_run_in_order),
        cmocka_unit_test(commands_refused_and_malformed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
