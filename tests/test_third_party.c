/*
 * usrsub-harness check on user libraries written independently of this
 * project (tests/third_party/README.md): correct ones pass; each planted bug
 * is caught and named where it is (the routine, the output and input, the
 * query, the signal); the harness survives a crash. The harness runs as a
 * user runs it, as a program, its output read back.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "test_support.h"

/* Runs check on tests/third_party/tp_NAME.xml; returns the exit status and
 * the output (stdout and stderr). */
static int check(const char *name, char *output, size_t size)
{
    /* a sanitizer's own SEGV handler would turn the crash into an exit status */
    setenv("ASAN_OPTIONS", "handle_segv=0:detect_leaks=1", 1);
    char command[2048];
    snprintf(command, sizeof command, "'%s' check '%s/tp_%s.xml' --timeout 5 2>&1", HARNESS_EXE,
             THIRD_PARTY_DIR, name);
    FILE *p = popen(command, "r");
    assert_non_null(p);
    size_t n = fread(output, 1, size - 1, p);
    output[n] = '\0';
    const int status = pclose(p);
    if (!WIFEXITED(status))
        fail_msg("check %s did not exit: status %d; output:\n%s", name, status, output);
    return WEXITSTATUS(status);
}

static char output[65536];

static void expect(const char *name, int status, const char *const *needles,
                   const char *const *absent)
{
    const int got = check(name, output, sizeof output);
    if (got != status)
        fail_msg("check tp_%s: exit %d, expected %d; output:\n%s", name, got, status, output);
    for (; needles != NULL && *needles != NULL; ++needles)
        if (strstr(output, *needles) == NULL)
            fail_msg("check tp_%s: '%s' is not in the output:\n%s", name, *needles, output);
    for (; absent != NULL && *absent != NULL; ++absent)
        if (strstr(output, *absent) != NULL)
            fail_msg("check tp_%s: '%s' should not be in the output:\n%s", name, *absent, output);
}

#define NEEDLES(...) ((const char *const[]){__VA_ARGS__, NULL})

static void correct_libraries_pass(void **state)
{
    (void)state;
    static const char *const good[] = {"good_sysary", "good_sysfnc", "good_field",
                                       "coupler_good"};
    for (size_t k = 0; k < sizeof good / sizeof good[0]; ++k)
        expect(good[k], 0, NEEDLES("1 passed, 0 failed"), NEEDLES("FAIL"));
}

static void a_hidden_state_is_named(void **state)
{
    (void)state;
    expect("hidden_state", 1, NEEDLES("history audit: FAIL: a hidden state"),
           NEEDLES("which no declared query"));
}

static void a_read_at_a_later_time_is_caught(void **state)
{
    (void)state;
    expect("late_query", 1, NEEDLES("reads outside the dependencies", "VX(20,10,10,10)",
                                    "WZ(20,10,10)"), NULL);
}

static void a_wrong_field_partial_is_named_by_row_and_column(void **state)
{
    (void)state;
    expect("wrong_partial", 1, NEEDLES("dfddis[1 + 6*3] = dFy/dax", "FAIL"), NULL);
}

static void a_crash_is_reported_and_survived(void **state)
{
    (void)state;
    expect("crash", 1, NEEDLES("Force_Vector_TwoBody 1: FAIL: crashed with signal 11",
                               "GFOSUB", "libtp_crash.so", "iflag = 0", "1 crashed or hung"),
           NULL);
}

static void a_refused_query_is_reported(void **state)
{
    (void)state;
    expect("bad_query", 1, NEEDLES("host: Force_Vector_TwoBody 1 (GFOSUB) asked c_sysary"
                                   " ACC(20,10,10,10)", "asks queries the host refuses"), NULL);
}

static void a_wrong_couxx_is_reported_as_couxx(void **state)
{
    (void)state;
    expect("coupler_wrong_couxx", 1,
           NEEDLES("COUXX against central differences of COUSUB", "entry 2 (dphi/dM2)",
                   "COUXX2 not judged"), NULL);
    expect("coupler_consistent_wrong", 1,
           NEEDLES("COUXX against central differences of COUSUB", "entry 2 (dphi/dM2)"), NULL);
}

static void a_wrong_couxx2_is_named_by_row_and_column(void **state)
{
    (void)state;
    expect("coupler_wrong_couxx2", 1,
           NEEDLES("row 2, column 2 (d2phi/dM2 dM2)", "FAIL"), NULL);
    const char *couxx = strstr(output, "COUXX against central differences of COUSUB");
    assert_non_null(couxx);
    assert_true(strstr(couxx, ": pass") < strstr(couxx, "\n")); /* COUXX itself passes */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(correct_libraries_pass),
        cmocka_unit_test(a_hidden_state_is_named),
        cmocka_unit_test(a_read_at_a_later_time_is_caught),
        cmocka_unit_test(a_wrong_field_partial_is_named_by_row_and_column),
        cmocka_unit_test(a_crash_is_reported_and_survived),
        cmocka_unit_test(a_refused_query_is_reported),
        cmocka_unit_test(a_wrong_couxx_is_reported_as_couxx),
        cmocka_unit_test(a_wrong_couxx2_is_named_by_row_and_column),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
