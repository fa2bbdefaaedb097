/*
 * run with a command file (docs/interface.md §9.9), in-process with stdout
 * and stderr captured: tests/data/oscillator.adm and the oscillator.acf
 * beside it (two SIMULATE/DYNAMIC segments with different DTOUT) against a
 * single run with the same output times and against the closed form; --acf
 * and --no-acf; the command line over the file; the commands refused by
 * name and file:line; DEACTIVATE, ACTIVATE and ACCGRAV between segments.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cmd/commands.h"
#include "test_support.h"

#define OSCILLATOR DATA_DIR "/oscillator.adm"

/* Runs `run` with args (NULL-terminated), its output captured. */
static void run(const char *const *args, test_captured *c)
{
    const char *argv[32] = {"run"};
    for (int i = 0; args[i] != NULL && i < 30; ++i)
        argv[i + 1] = args[i];
    test_capture(hx_command_run, argv, c);
}

#define MAX_ROWS 64

/* A CSV's rows (header left out) as lines, and their times; the count. */
typedef struct table {
    int n;
    double t[MAX_ROWS], x[MAX_ROWS], y[MAX_ROWS];
    char row[MAX_ROWS][2048];
} table;

static void read_table(const char *path, table *tb)
{
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[2048];
    tb->n = 0;
    assert_non_null(fgets(line, sizeof line, f)); /* the header: t,body2.x,... */
    assert_true(strncmp(line, "t,body2.x,", 10) == 0);
    while (fgets(line, sizeof line, f) != NULL) {
        assert_true(tb->n < MAX_ROWS);
        snprintf(tb->row[tb->n], sizeof tb->row[0], "%s", line);
        assert_int_equal(sscanf(line, "%lf,%lf,%lf", &tb->t[tb->n], &tb->x[tb->n], &tb->y[tb->n]),
                         3);
        tb->n++;
    }
    fclose(f);
}

/* The oscillator's closed form (tests/data/oscillator.adm): released at rest
 * 0.1 m out, zeta omega = c / 2m = 1, omega_d = sqrt(k/m - 1) = sqrt(99). */
static double closed_form(double t)
{
    const double w = sqrt(99.0);
    return 1.0 + 0.1 * exp(-t) * (cos(w * t) + sin(w * t) / w);
}

static int steps_of(const char *out)
{
    const char *p = strstr(out, "steps ");
    assert_non_null(p);
    return atoi(p + 6);
}

/* ---- segments ------------------------------------------------------------------------------ */

static void segments_follow_one_another(void **state)
{
    (void)state;
    test_captured c;
    table seg, one;
    /* MODEL.acf beside MODEL.adm is followed, and said so */
    run((const char *const[]){OSCILLATOR, "--quiet", "--out", test_temp_path("seg.csv"), NULL}, &c);
    assert_int_equal(c.status, 0);
    assert_contains(c.err, "run: following the command file " DATA_DIR "/oscillator.acf");
    assert_contains(c.err, "oscillator.acf:3: note: INTEGRATOR: GSTIFF read and of no effect");
    read_table(test_temp_path("seg.csv"), &seg);
    /* 0 to 1 by 0.1, then 1 to 2 by 0.05: 11 + 20 rows, t = 1 once */
    assert_int_equal(seg.n, 31);
    for (int k = 0; k < seg.n; ++k) {
        const double t = k <= 10 ? 0.1 * k : 1.0 + 0.05 * (k - 10);
        assert_close(seg.t[k], t, 0.0, 1e-12);
        /* ERROR=1e-9 is the tolerance: the closed form to well within 1e-7 */
        assert_close(seg.x[k], closed_form(t), 0.0, 1e-7);
    }
    /* the same with a fixed step, against one run with the same output times
     * (every 0.05 s): the segments' rows are the single run's, digit for
     * digit (the second segment went on from the first's end state) */
    run((const char *const[]){OSCILLATOR, "--quiet", "--integrator", "rk4", "--step", "0.001",
                              "--out", test_temp_path("seg_rk4.csv"), NULL}, &c);
    assert_int_equal(c.status, 0);
    run((const char *const[]){OSCILLATOR, "--no-acf", "--end", "2", "--output-interval", "0.05",
                              "--quiet", "--integrator", "rk4", "--step", "0.001", "--out",
                              test_temp_path("one_rk4.csv"), NULL}, &c);
    assert_int_equal(c.status, 0);
    assert_null(strstr(c.err, "following the command file"));
    read_table(test_temp_path("seg_rk4.csv"), &seg);
    read_table(test_temp_path("one_rk4.csv"), &one);
    assert_int_equal(seg.n, 31);
    assert_int_equal(one.n, 41);
    for (int k = 0; k < seg.n; ++k) {
        const int j = k <= 10 ? 2 * k : k + 10; /* the single run's row at seg's time */
        assert_string_equal(seg.row[k], one.row[j]);
        assert_close(seg.x[k], closed_form(seg.t[k]), 0.0, 1e-7);
    }
}

/* ---- which command file -------------------------------------------------------------------- */

static void acf_and_no_acf(void **state)
{
    (void)state;
    test_captured c;
    table tb;
    const char *acf = test_write_file("short.acf", "elsewhere.adm\n\n"
                                      "SIMULATE/DYNAMIC, END=0.3, STEPS=3\n");
    run((const char *const[]){OSCILLATOR, "--acf", acf, "--quiet", "--out", test_temp_path("a.csv"),
                              NULL}, &c);
    assert_int_equal(c.status, 0);
    assert_contains(c.err, "run: following the command file", "short.acf");
    /* Adams would read the dataset the first line names: the harness runs its own */
    assert_contains(c.err, "short.acf:1: warning: the command file names the dataset"
                    " 'elsewhere.adm'; the model run is " OSCILLATOR);
    read_table(test_temp_path("a.csv"), &tb);
    assert_int_equal(tb.n, 4);
    assert_close(tb.t[3], 0.3, 0.0, 1e-12);
    /* --no-acf: the command line alone, which then needs --end */
    run((const char *const[]){OSCILLATOR, "--no-acf", "--quiet", NULL}, &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "--end T is needed");
    assert_null(strstr(c.err, "following"));
    run((const char *const[]){OSCILLATOR, "--no-acf", "--acf", acf, NULL}, &c);
    assert_int_equal(c.status, 2);
    assert_contains(c.err, "--acf and --no-acf");
    run((const char *const[]){OSCILLATOR, "--acf", test_temp_path("missing.acf"), NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "missing.acf: cannot open the command file");
}

/* ---- the command line over the file -------------------------------------------------------- */

static void options_override_the_file(void **state)
{
    (void)state;
    test_captured c;
    table tb;
    /* --end cuts the run inside the second segment */
    run((const char *const[]){OSCILLATOR, "--end", "1.5", "--quiet", "--out", test_temp_path("e.csv"),
                              NULL}, &c);
    assert_int_equal(c.status, 0);
    read_table(test_temp_path("e.csv"), &tb);
    assert_int_equal(tb.n, 21);
    assert_close(tb.t[20], 1.5, 0.0, 1e-12);
    /* --output-interval replaces both DTOUT */
    run((const char *const[]){OSCILLATOR, "--output-interval", "0.25", "--quiet", "--out",
                              test_temp_path("i.csv"), NULL}, &c);
    assert_int_equal(c.status, 0);
    read_table(test_temp_path("i.csv"), &tb);
    assert_int_equal(tb.n, 9);
    for (int k = 0; k < tb.n; ++k)
        assert_close(tb.t[k], 0.25 * k, 0.0, 1e-12);
    /* ERROR=1e-9 is rtol and atol: --rtol and --atol of 1e-3 take fewer steps,
     * as many as a file whose ERROR is 1e-3 */
    run((const char *const[]){OSCILLATOR, "--quiet", NULL}, &c);
    assert_int_equal(c.status, 0);
    const int fine = steps_of(c.out);
    run((const char *const[]){OSCILLATOR, "--rtol", "1e-3", "--atol", "1e-3", "--quiet", NULL}, &c);
    assert_int_equal(c.status, 0);
    const int coarse = steps_of(c.out);
    assert_true(coarse < fine / 2);
    const char *acf = test_write_file("coarse.acf", "oscillator\n\nINTEGRATOR/ERROR=1E-3\n"
                                      "SIMULATE/DYNAMIC, END=1, DTOUT=0.1\n"
                                      "SIMULATE/DYNAMIC, DURATION=1, DTOUT=0.05\n");
    run((const char *const[]){OSCILLATOR, "--acf", acf, "--quiet", NULL}, &c);
    assert_int_equal(c.status, 0);
    assert_int_equal(steps_of(c.out), coarse);
    assert_null(strstr(c.err, "note: INTEGRATOR")); /* nothing besides ERROR to note */
}

/* ---- refusals ------------------------------------------------------------------------------ */

static void refuse(const char *command, const char *where, const char *what, const char *why)
{
    char text[512];
    snprintf(text, sizeof text, "oscillator\n\nSIMULATE/DYNAMIC, END=1, STEPS=10\n%s\n"
             "SIMULATE/DYNAMIC, END=2, STEPS=10\n", command);
    const char *acf = test_write_file("refused.acf", text);
    test_captured c;
    run((const char *const[]){OSCILLATOR, "--acf", acf, "--quiet", "--out", test_temp_path("r.csv"),
                              NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, where, what, why);
    assert_null(strstr(c.out, "run:")); /* refused before the run */
}

static void what_the_run_cannot_do_is_refused(void **state)
{
    (void)state;
    refuse("DEACTIVATE/JOINT, ID=1", "refused.acf:4: ", "DEACTIVATE/JOINT",
           "the harness switches SFORCE, VFORCE, VTORQUE, GFORCE, SPRINGDAMPER, BUSHING, BEAM"
           " and FIELD, not other elements yet");
    refuse("DEACTIVATE/FIELD, ID=1", "refused.acf:4: ", "DEACTIVATE/FIELD",
           "the model has no FIELD/1\n"); /* its SFORCE/1's id */
    refuse("ACTIVATE/SFORCE, ID=1,2", "refused.acf:4: ", "ACTIVATE/SFORCE",
           "the model has no SFORCE/2\n");
    refuse("DEACTIVATE/GFORCE, ID=1", "refused.acf:4: ", "DEACTIVATE/GFORCE",
           "the model has no GFORCE/1"); /* its SFORCE/1 is a scalar load */
    refuse("DEACTIVATE/SPRINGDAMPER, ID=1", "refused.acf:4: ", "DEACTIVATE/SPRINGDAMPER",
           "the model has no SPRINGDAMPER/1\n"); /* nor a built-in one */
    refuse("VARIABLE/3, FUNCTION=TIME", "refused.acf:4: ", "VARIABLE/3",
           "the model has no VARIABLE/3 given by a FUNCTION");
    refuse("PREFERENCES/SOLVERBIAS=CXX", "refused.acf:4: ", "PREFERENCES",
           "a command the harness does not read");
    refuse("SIMULATE/DYNAMIC, END=0.5, STEPS=5", "refused.acf:4: ", "SIMULATE/DYNAMIC",
           "END=0.5 is not after the time the run has reached, 1");
    /* STOP ends the file: what follows it is not read */
    const char *acf = test_write_file("stop.acf", "oscillator\n\n"
                                      "SIMULATE/DYNAMIC, END=0.2, STEPS=2\nSTOP\nACCGRAV/JGRAV=1\n");
    test_captured c;
    run((const char *const[]){OSCILLATOR, "--acf", acf, "--quiet", NULL}, &c);
    assert_int_equal(c.status, 0);
    assert_contains(c.out, "to t = 0.2\n");
    acf = test_write_file("nothing.acf", "oscillator\n\nSTOP\n");
    run((const char *const[]){OSCILLATOR, "--acf", acf, "--quiet", NULL}, &c);
    assert_int_equal(c.status, 1);
    assert_contains(c.err, "nothing.acf: no SIMULATE command: nothing to run");
}

/* ---- ACTIVATE and DEACTIVATE --------------------------------------------------------------- */

/* tests/data/hanging.adm: at rest on its spring to 0.5 s; the spring
 * deactivated, it falls freely, y = y0 - g (t - 0.5)^2 / 2 (worked in the
 * dataset's comment; DOPRI5 is exact on a quadratic); activated again at
 * 1 s, the spring, stretched 1.23 m more, pulls 245 N against 19.6 N of
 * weight: the fall slows. */
static void a_deactivated_spring_lets_the_mass_fall(void **state)
{
    (void)state;
    const double y0 = -1.0981, g = 9.81;
    const char *acf = test_write_file("hanging.acf", "hanging\n\n"
                                      "SIMULATE/DYNAMIC, END=0.5, STEPS=5\n"
                                      "DEACTIVATE/SFORCE, ID=1\n"
                                      "SIMULATE/DYNAMIC, DURATION=0.5, STEPS=5\n"
                                      "ACTIVATE/SFORCE, ID=1\n"
                                      "SIMULATE/DYNAMIC, END=1.2, STEPS=2\n");
    const char *const integrators[2] = {"dopri5", "bdf"}; /* bdf: its Jacobian without it */
    for (int i = 0; i < 2; ++i) {
        test_captured c;
        table tb;
        run((const char *const[]){DATA_DIR "/hanging.adm", "--acf", acf, "--integrator",
                                  integrators[i], "--quiet", "--out", test_temp_path("fall.csv"),
                                  NULL}, &c);
        assert_int_equal(c.status, 0);
        read_table(test_temp_path("fall.csv"), &tb);
        assert_int_equal(tb.n, 13);
        for (int k = 0; k <= 10; ++k) {
            const double t = 0.1 * k, fall = t > 0.5 ? t - 0.5 : 0.0;
            assert_close(tb.t[k], t, 0.0, 1e-12);
            assert_close(tb.y[k], y0 - 0.5 * g * fall * fall, 0.0, i == 0 ? 1e-8 : 1e-5);
        }
        const double free_fall = y0 - 0.5 * g * 0.7 * 0.7;
        assert_true(tb.y[12] > free_fall + 0.1);
    }
}

/* A 2 kg part held at (1, 0, 0) by a SPRINGDAMPER (1), a BUSHING (2), a
 * BEAM (3) and a linear FIELD (4) to the ground's origin, all four
 * deactivated: it falls freely, y = -9.81 t^2 / 2, x = 1 (each would pull
 * it once it moves; the bushing at once, 1000 N along -x); the BUSHING activated again at 0.3 s pulls it
 * towards the origin. */
static void built_in_forces_are_switched(void **state)
{
    (void)state;
    const char *adm = test_write_file(
        "held.adm", "held\nACCGRAV/JGRAV = -9.81\nPART/1, GROUND\nMARKER/10, PART = 1\n"
                    "PART/2, MASS = 2, CM = 20, IP = 1, 1, 1\nMARKER/20, PART = 2, QP = 1, 0, 0\n"
                    "SPRINGDAMPER/1, TRANSLATION, I = 20, J = 10, K = 100, C = 1, LENGTH = 1\n"
                    "BUSHING/2, I = 20, J = 10, K = 1000, 1000, 1000, KT = 10, 10, 10\n"
                    "BEAM/3, I = 20, J = 10, LENGTH = 1, EMODULUS = 1E6, GMODULUS = 4E5,\n"
                    ", AREA = 1E-2, IXX = 1E-4, IYY = 1E-4, IZZ = 1E-4\n"
                    "FIELD/4, I = 20, J = 10, LENGTH = 1, 0, 0, 0, 0, 0, KMATRIX = 500, 0, 0,\n"
                    ", 0, 0, 0, 0, 500, 0, 0, 0, 0, 0, 0, 500, 0, 0, 0, 0, 0, 0, 5, 0, 0,\n"
                    ", 0, 0, 0, 0, 5, 0, 0, 0, 0, 0, 0, 5\nEND\n");
    const char *acf = test_write_file("held.acf", "held\n\n"
                                      "DEACTIVATE/SPRINGDAMPER, ID=1\n"
                                      "DEACTIVATE/BUSHING, ID=2\n"
                                      "DEACTIVATE/BEAM, ID=3\n"
                                      "DEACTIVATE/FIELD, ID=4\n"
                                      "SIMULATE/DYNAMIC, END=0.3, STEPS=3\n"
                                      "ACTIVATE/BUSHING, ID=2\n"
                                      "SIMULATE/DYNAMIC, END=0.5, STEPS=2\n");
    test_captured c;
    table tb;
    run((const char *const[]){adm, "--acf", acf, "--quiet", "--out",
                              test_temp_path("held.csv"), NULL}, &c);
    if (c.status != 0)
        fail_msg("%s", c.err);
    read_table(test_temp_path("held.csv"), &tb);
    assert_int_equal(tb.n, 6);
    for (int k = 0; k <= 3; ++k) {
        const double t = 0.1 * k;
        assert_close(tb.x[k], 1.0, 0.0, 1e-12);
        assert_close(tb.y[k], -4.905 * t * t, 0.0, 1e-8);
    }
    assert_true(tb.x[5] < 0.5);
}

/* ---- ACCGRAV ------------------------------------------------------------------------------- */

/* A free mass at the origin, at rest, under the dataset's gravity 9.81 along
 * -y to 0.5 s: y = -9.81 t^2 / 2 (y(0.5) = -1.22625, vy(0.5) = -4.905);
 * then ACCGRAV/IGRAV=2, JGRAV=0 (KGRAV not given stays 0): it coasts along
 * y, y = -1.22625 - 4.905 (t - 0.5), and x = 2 (t - 0.5)^2 / 2. DOPRI5 is
 * exact on these polynomials; BDF within its tolerance. */
static void accgrav_changes_gravity_between_segments(void **state)
{
    (void)state;
    const char *adm = test_write_file("falling.adm", "falling\n"
                                      "ACCGRAV/JGRAV = -9.81\n"
                                      "PART/1, GROUND\nMARKER/10, PART = 1\n"
                                      "PART/2, MASS = 2, CM = 20, IP = 1, 1, 1\n"
                                      "MARKER/20, PART = 2, QP = 0, 0, 0\nEND\n");
    const char *acf = test_write_file("falling.acf", "falling\n\n"
                                      "SIMULATE/DYNAMIC, END=0.5, STEPS=5\n"
                                      "ACCGRAV/IGRAV=2, JGRAV=0\n"
                                      "SIMULATE/DYNAMIC, END=1, STEPS=5\n");
    const char *const integrators[2] = {"dopri5", "bdf"};
    for (int i = 0; i < 2; ++i) {
        test_captured c;
        table tb;
        run((const char *const[]){adm, "--acf", acf, "--integrator", integrators[i], "--quiet",
                                  "--out", test_temp_path("falling.csv"), NULL}, &c);
        assert_int_equal(c.status, 0);
        read_table(test_temp_path("falling.csv"), &tb);
        assert_int_equal(tb.n, 11);
        for (int k = 0; k <= 10; ++k) {
            const double t = 0.1 * k, after = t > 0.5 ? t - 0.5 : 0.0;
            const double y = t <= 0.5 ? -4.905 * t * t : -1.22625 - 4.905 * after;
            assert_close(tb.t[k], t, 0.0, 1e-12);
            assert_close(tb.x[k], after * after, 0.0, i == 0 ? 1e-8 : 1e-5);
            assert_close(tb.y[k], y, 0.0, i == 0 ? 1e-8 : 1e-5);
        }
    }
    /* the ACCGRAV moves the potential's zero, it does no work: the energy balance holds
     * across it (24 J of 25 off when it was counted as a change) */
    test_captured c;
    run((const char *const[]){adm, "--acf", acf, "--integrator", "dopri5", "--out",
                              test_temp_path("falling.csv"), NULL}, &c);
    assert_int_equal(c.status, 0);
    const char *change = strstr(c.out, "largest energy change");
    assert_non_null(change);
    const char *open = strchr(change, '(');
    assert_non_null(open);
    assert_true(strtod(open + 1, NULL) < 1e-9);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(segments_follow_one_another),
        cmocka_unit_test(acf_and_no_acf),
        cmocka_unit_test(options_override_the_file),
        cmocka_unit_test(what_the_run_cannot_do_is_refused),
        cmocka_unit_test(a_deactivated_spring_lets_the_mass_fall),
        cmocka_unit_test(built_in_forces_are_switched),
        cmocka_unit_test(accgrav_changes_gravity_between_segments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
