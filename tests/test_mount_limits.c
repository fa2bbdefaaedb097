/*
 * Mount limits (docs/interface.md §3.4): hand values on both sides for E = 1, 1.5,
 * 2 and 3, zero in the gap, signs, the STEP ramp of the damping, no sticking,
 * D = 0, continuity at the gap, partials against finite differences (one-sided
 * at the switch points), the six directions kept apart, and the .gbi reader
 * with its units and each input error.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/readers/mount_limits_reader.h"

static const double exponents[4] = {1.0, 1.5, 2.0, 3.0};

static usrsub_limit_side side(int sign, double e, double d)
{
    usrsub_limit_side s = {.direction = 2, .sign = sign, .k = 1000.0, .e = e, .c = 10.0,
                           .d = d, .l = 2.0};
    return s;
}

static double force(const usrsub_limit_side *s, double q, double qdot)
{
    double dq, dqdot;
    return usrsub_limit_side_force(s, q, qdot, &dq, &dqdot);
}

static void hand_values_on_both_sides(void **state)
{
    (void)state;
    /* penetration 1.5 (past the ramp, D = 0.5), closing at 4: K 1.5^E + C 4 */
    const double beyond[4] = {1540.0, 1000.0 * 1.8371173070873836 + 40.0, 2290.0, 3415.0};
    /* penetration 0.25, halfway up the ramp: K 0.25^E + C 4 STEP = K 0.25^E + 20 */
    const double ramp[4] = {270.0, 145.0, 82.5, 35.625};
    for (int n = 0; n < 4; ++n) {
        const usrsub_limit_side pos = side(+1, exponents[n], 0.5), neg = side(-1, exponents[n], 0.5);
        assert_close(force(&pos, 3.5, 4.0), -beyond[n], 1e-14, 0);
        assert_close(force(&neg, -3.5, -4.0), beyond[n], 1e-14, 0);
        assert_close(force(&pos, 2.25, 4.0), -ramp[n], 1e-14, 0);
        assert_close(force(&neg, -2.25, -4.0), ramp[n], 1e-14, 0);
        /* at rest only the spring: K p^E */
        assert_close(force(&pos, 3.5, 0.0), -(beyond[n] - 40.0), 1e-14, 0);
        /* opening slowly (damping smaller than the spring) the force eases */
        assert_close(force(&pos, 3.5, -4.0), -(beyond[n] - 80.0), 1e-14, 0);
    }
}

static void zero_in_the_gap_and_signs(void **state)
{
    (void)state;
    for (int n = 0; n < 4; ++n) {
        const usrsub_limit_side pos = side(+1, exponents[n], 0.5), neg = side(-1, exponents[n], 0.5);
        for (double q = -2.0; q <= 2.0; q += 0.125)
            for (double qdot = -50.0; qdot <= 50.0; qdot += 25.0) {
                double dq = 1, dqdot = 1;
                assert_true(usrsub_limit_side_force(&pos, q, qdot, &dq, &dqdot) == 0.0);
                assert_true(dq == 0.0 && dqdot == 0.0);
                assert_true(force(&neg, q, qdot) == 0.0);
            }
        /* the positive limit pushes back (<= 0) and the negative one forward (>= 0),
         * whatever the rate; each is silent on the other side */
        for (double p = 0.01; p < 4.0; p *= 1.7)
            for (double qdot = -50.0; qdot <= 50.0; qdot += 12.5) {
                assert_true(force(&pos, 2.0 + p, qdot) <= 0.0);
                assert_true(force(&neg, -2.0 - p, qdot) >= 0.0);
                assert_true(force(&pos, -2.0 - p, qdot) == 0.0);
                assert_true(force(&neg, 2.0 + p, qdot) == 0.0);
            }
    }
}

static void a_fast_separating_limit_does_not_pull(void **state)
{
    (void)state;
    const usrsub_limit_side pos = side(+1, 1.0, 0.5), neg = side(-1, 1.0, 0.5);
    double dq, dqdot;
    /* penetration 0.25 opening at 100: spring 250, damping 10 * 100 * 0.5 = 500 */
    assert_true(usrsub_limit_side_force(&pos, 2.25, -100.0, &dq, &dqdot) == 0.0);
    assert_true(dq == 0.0 && dqdot == 0.0);
    assert_true(force(&neg, -2.25, 100.0) == 0.0);
    /* penetration 1.5 opening at 200: 1500 against 2000 */
    assert_true(force(&pos, 3.5, -200.0) == 0.0);
    assert_true(force(&neg, -3.5, 200.0) == 0.0);
    /* just slower than the balance it still pushes */
    assert_close(force(&pos, 3.5, -149.0), -10.0, 1e-12, 0);
}

static void with_d_zero_damping_is_fully_on_at_contact(void **state)
{
    (void)state;
    for (int n = 0; n < 4; ++n) {
        const usrsub_limit_side pos = side(+1, exponents[n], 0.0), neg = side(-1, exponents[n], 0.0);
        double dq, dqdot;
        const double f = usrsub_limit_side_force(&pos, 2.0 + 1e-12, 4.0, &dq, &dqdot);
        assert_close(f, -40.0, 1e-9, 0);
        assert_close(dqdot, -10.0, 0, 0);
        assert_close(force(&neg, -2.0 - 1e-12, -4.0), 40.0, 1e-9, 0);
        /* deeper, the full C qdot plus the spring */
        assert_close(force(&pos, 3.0, 4.0), -1040.0, 1e-14, 0);
    }
}

static void continuous_at_the_gap(void **state)
{
    (void)state;
    const double eps = 1e-9, rates[3] = {-5.0, 0.0, 5.0};
    for (int n = 0; n < 4; ++n)
        for (int r = 0; r < 3; ++r) {
            /* D > 0: continuous at any rate */
            const usrsub_limit_side pos = side(+1, exponents[n], 0.5), neg = side(-1, exponents[n], 0.5);
            const double qdot = rates[r];
            assert_true(fabs(force(&pos, 2.0 + eps, qdot)) < 1e-5);
            assert_true(force(&pos, 2.0 - eps, qdot) == 0.0);
            assert_true(fabs(force(&neg, -2.0 - eps, -qdot)) < 1e-5);
            /* D = 0: continuous when not closing; closing, the damping C qdot
             * switches on at contact (the formula's choice, tested above) */
            const usrsub_limit_side hard = side(+1, exponents[n], 0.0);
            if (qdot <= 0.0)
                assert_true(fabs(force(&hard, 2.0 + eps, qdot)) < 1e-5);
        }
}

static void first_derivative_continuous_when_e_above_one_and_d_positive(void **state)
{
    (void)state;
    for (int n = 1; n < 4; ++n) {
        const usrsub_limit_side pos = side(+1, exponents[n], 0.5);
        /* the slopes (0 on the gap side) vanish at contact: the spring's like
         * p^(E-1), the ramped damping's like p */
        double dq1, dqdot1, dq2, dqdot2;
        const double p1 = 1e-4, p2 = 1e-10;
        usrsub_limit_side_force(&pos, 2.0 + p1, 5.0, &dq1, &dqdot1);
        usrsub_limit_side_force(&pos, 2.0 + p2, 5.0, &dq2, &dqdot2);
        assert_true(fabs(dq2) <= 1.01 * fabs(dq1) * pow(p2 / p1, fmin(exponents[n] - 1.0, 1.0)));
        assert_true(fabs(dq2) < 0.02);
        assert_true(fabs(dqdot2) < 1e-15); /* C STEP: the ramp starts flat */
    }
    /* E = 1 is a kink: the slope jumps to -K at contact */
    const usrsub_limit_side linear = side(+1, 1.0, 0.5);
    double dq, dqdot;
    usrsub_limit_side_force(&linear, 2.0 + 1e-9, 0.0, &dq, &dqdot);
    assert_close(dq, -1000.0, 1e-6, 0);
}

/* Second-order one-sided and central differences of side s in q (which 0) or qdot. */
static void differences(const usrsub_limit_side *s, double q, double qdot, int which, double h,
                        double *central, double *forward, double *backward)
{
    double f[5];
    for (int k = -2; k <= 2; ++k)
        f[k + 2] = which == 0 ? force(s, q + k * h, qdot) : force(s, q, qdot + k * h);
    *central = (f[3] - f[1]) / (2 * h);
    *forward = (-3 * f[2] + 4 * f[3] - f[4]) / (2 * h);
    *backward = (3 * f[2] - 4 * f[1] + f[0]) / (2 * h);
}

static void partials_match_finite_differences(void **state)
{
    (void)state;
    const double ds[2] = {0.5, 0.0};
    int compared = 0;
    for (int n = 0; n < 4; ++n)
        for (int m = 0; m < 2; ++m)
            for (int sign = -1; sign <= 1; sign += 2) {
                const usrsub_limit_side s = side(sign, exponents[n], ds[m]);
                /* penetrations through the ramp and beyond it, both rate signs,
                 * away from the clipping point (spring = damping) */
                for (double p = 0.05; p < 3.0; p += 0.3)
                    for (double rate = -3.0; rate <= 3.0; rate += 1.5) {
                        const double q = sign * (2.0 + p), qdot = sign * rate;
                        double dq, dqdot, c, fw, bw;
                        usrsub_limit_side_force(&s, q, qdot, &dq, &dqdot);
                        differences(&s, q, qdot, 0, 1e-6, &c, &fw, &bw);
                        assert_close(dq, c, 1e-6, 1e-6);
                        differences(&s, q, qdot, 1, 1e-6, &c, &fw, &bw);
                        assert_close(dqdot, c, 1e-6, 1e-6);
                        compared += 2;
                    }
            }
    assert_int_equal(compared, 4 * 2 * 2 * 10 * 5 * 2);
}

static void partials_at_switch_points_are_one_sided_limits(void **state)
{
    (void)state;
    const usrsub_limit_side lin = side(+1, 1.0, 0.0);
    double dq, dqdot, c, fw, bw;
    /* at q = L exactly the element is in the gap: the partials are those of the
     * gap side (backward), and the forward slope is -K */
    usrsub_limit_side_force(&lin, 2.0, 0.0, &dq, &dqdot);
    differences(&lin, 2.0, 0.0, 0, 1e-7, &c, &fw, &bw);
    assert_close(dq, bw, 0, 1e-6);
    assert_close(fw, -1000.0, 1e-6, 0);
    assert_true(fabs(dq - c) > 100.0); /* the central difference straddles the kink */
    /* at the clipping point (spring 250 = damping 10 * 25 at p = 0.25 past the
     * ramp-free gap) the force is clipped to 0 and so are its partials */
    usrsub_limit_side_force(&lin, 2.25, -25.0, &dq, &dqdot);
    differences(&lin, 2.25, -25.0, 1, 1e-7, &c, &fw, &bw);
    assert_true(dqdot == 0.0);
    assert_close(dqdot, bw, 0, 1e-6);  /* opening faster: clipped */
    assert_close(fw, -10.0, 1e-6, 0); /* opening slower: -C */
}

static void directions_are_kept_apart(void **state)
{
    (void)state;
    usrsub_mount_limits m = {0};
    for (int k = 0; k < 6; ++k)
        for (int sign = -1; sign <= 1; sign += 2) {
            usrsub_limit_side *s = &m.side[m.nsides++];
            *s = (usrsub_limit_side){.direction = k, .sign = sign, .k = 100.0 * (k + 1),
                                     .e = 1.0, .c = 0.0, .d = 0.0, .l = 1.0 + k};
        }
    usrsub_mount_limits_prepare(&m);
    assert_true(m.uses_translation && m.uses_rotation);
    assert_false(m.uses_velocity);
    for (int k = 0; k < 6; ++k)
        for (int sign = -1; sign <= 1; sign += 2) {
            double d[6] = {0}, v[6] = {0}, F[6] = {0}, dFdd[36] = {0}, dFdv[36] = {0};
            d[k] = sign * (1.0 + k + 0.5); /* half a unit into direction k's limit */
            usrsub_mount_limits_add(&m, d, v, F, dFdd, dFdv);
            for (int j = 0; j < 6; ++j)
                assert_close(F[j], j == k ? -sign * 50.0 * (k + 1) : 0.0, 1e-14, 0);
            for (int j = 0; j < 36; ++j) {
                assert_close(dFdd[j], j == k + 6 * k ? -100.0 * (k + 1) : 0.0, 1e-14, 0);
                assert_true(dFdv[j] == 0.0);
            }
        }
    /* the limits add to what F already holds */
    double d[6] = {0, 0, 3.5, 0, 0, 0}, v[6] = {0}, F[6] = {1, 2, 3, 4, 5, 6};
    usrsub_mount_limits_add(&m, d, v, F, NULL, NULL);
    assert_close(F[2], 3.0 - 150.0, 1e-14, 0);
    assert_close(F[0], 1.0, 0, 0);
}

/* ---- the .gbi reader ----------------------------------------------------------------- */

static const double model_mm_n_kg_s[5] = {1e-3, 1.0, 1.0, 1.0, 1.0};

static const char *const sides[12] = {"TRA_X_POS", "TRA_X_NEG", "TRA_Y_POS", "TRA_Y_NEG",
                                      "TRA_Z_POS", "TRA_Z_NEG", "ROT_X_POS", "ROT_X_NEG",
                                      "ROT_Y_POS", "ROT_Y_NEG", "ROT_Z_POS", "ROT_Z_NEG"};

/* A .gbi file in length/force/angle units whose side n has line[n] (NULL:
 * "0 1 0 0 1") and extra lines after the sides. */
static const char *gbi_text(const char *length, const char *force, const char *angle,
                            const char *const line[12], const char *extra)
{
    static char text[4096];
    int len = snprintf(text, sizeof text,
                       "$ limits\n[HEADER]\nFILE_TYPE = 'gbi'\nFILE_VERSION = '1'\n"
                       "[UNITS]\nLENGTH = '%s'\nANGLE = '%s'\nFORCE = '%s'\nMASS = 'kg'\n"
                       "TIME = 'second'\n[MOUNT_LIMITS]\n", length, angle, force);
    for (int n = 0; n < 12; ++n)
        len += snprintf(text + len, sizeof text - (size_t)len, "IMPACT_PARAMETERS_%s = %s\n",
                        sides[n], line != NULL && line[n] != NULL ? line[n] : "0 1 0 0 1");
    snprintf(text + len, sizeof text - (size_t)len, "%s", extra);
    return text;
}

static int read_gbi(const char *name, const char *text, usrsub_mount_limits **m,
                    usrsub_message *msg)
{
    usrsub_read_report report = {0};
    return usrsub_mount_limits_read(test_write_file(name, text), model_mm_n_kg_s, m, &report, msg);
}

static void reader_takes_any_separator_and_converts_units(void **state)
{
    (void)state;
    const char *lines[12] = {NULL};
    lines[0] = "3.0e9, 2, 8000, 0.0005, 0.003";  /* N/m^2, N s/m, m */
    lines[5] = "2.0e5\t1\t100\t0.001\t0.0025";   /* tabs */
    lines[11] = "1.0e4 ,1.5,\t 20 0.01 ,0.05";     /* mixed; N m/rad^1.5, rad */
    usrsub_mount_limits *m;
    usrsub_message msg;
    if (read_gbi("units.gbi", gbi_text("m", "newton", "radian", lines, ""), &m, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_int_equal(m->nsides, 3); /* the sides with K = 0 and C = 0 are left out */
    const usrsub_limit_side *x = &m->side[0], *z = &m->side[1], *rz = &m->side[2];
    assert_int_equal(x->direction, 0);
    assert_int_equal(x->sign, 1);
    assert_close(x->k, 3000.0, 1e-12, 0); /* 3e9 N/m^2 = 3000 N/mm^2 */
    assert_close(x->e, 2.0, 0, 0);
    assert_close(x->c, 8.0, 1e-12, 0);    /* N s/m -> N s/mm */
    assert_close(x->d, 0.5, 1e-12, 0);
    assert_close(x->l, 3.0, 1e-12, 0);
    assert_int_equal(z->direction, 2);
    assert_int_equal(z->sign, -1);
    assert_close(z->k, 200.0, 1e-12, 0);
    assert_close(z->l, 2.5, 1e-12, 0);
    assert_int_equal(rz->direction, 5);
    assert_int_equal(rz->sign, -1);
    assert_close(rz->k, 1e7, 1e-12, 0);   /* N m -> N mm; radians stay */
    assert_close(rz->c, 2e4, 1e-12, 0);
    assert_close(rz->l, 0.05, 0, 0);
    assert_true(m->uses_translation && m->uses_rotation && m->uses_velocity);
    usrsub_mount_limits_free(m);
    /* an angle in degrees: K per degree^E and gaps in degrees */
    const char *deg[12] = {NULL};
    deg[6] = "1000 2 0 0 3";
    if (read_gbi("degrees.gbi", gbi_text("mm", "newton", "degree", deg, ""), &m, &msg) != 0)
        fail_msg("%s", msg.text);
    const double rad = M_PI / 180.0;
    assert_close(m->side[0].k, 1000.0 / (rad * rad), 1e-12, 0);
    assert_close(m->side[0].l, 3.0 * rad, 1e-12, 0);
    assert_false(m->uses_velocity);
    usrsub_mount_limits_free(m);
}

static void active_switches_all_limits(void **state)
{
    (void)state;
    const char *lines[12] = {"1 1 1 1 1", "1 1 1 1 1"};
    usrsub_mount_limits *m;
    usrsub_message msg;
    assert_int_equal(read_gbi("off.gbi", gbi_text("mm", "newton", "radian", lines, "ACTIVE = 0\n"),
                              &m, &msg), 0);
    assert_int_equal(m->nsides, 0);
    usrsub_mount_limits_free(m);
    assert_int_equal(read_gbi("on.gbi", gbi_text("mm", "newton", "radian", lines, "ACTIVE = 1\n"),
                              &m, &msg), 0);
    assert_int_equal(m->nsides, 2);
    usrsub_mount_limits_free(m);
    assert_int_equal(read_gbi("bad_active.gbi",
                              gbi_text("mm", "newton", "radian", lines, "ACTIVE = 2\n"), &m, &msg), -1);
    assert_contains(msg.text, "bad_active.gbi", "line 24", "ACTIVE", "expected 0 or 1");
}

static void reader_errors_name_the_line(void **state)
{
    (void)state;
    static const struct {
        int side;
        const char *line;
        const char *const expected[3];
    } cases[] = {
        {0, "-1 1 0 0 1", {"line 12", "IMPACT_PARAMETERS_TRA_X_POS", "K = -1 must not be negative"}},
        {3, "1 1 -2 0 1", {"line 15", "TRA_Y_NEG", "C = -2 must not be negative"}},
        {7, "1 1 0 -0.5 1", {"line 19", "ROT_X_NEG", "D = -0.5 must not be negative"}},
        {11, "1 1 0 0 -1", {"line 23", "ROT_Z_NEG", "L = -1 must not be negative"}},
        {4, "1 0.5 0 0 1", {"line 16", "E = 0.5", "at least 1"}},
        {2, "1 1 0 0", {"line 14", "expected five numbers K E C D L", "'1 1 0 0'"}},
        {9, "1 1 0 0 1 7", {"line 21", "expected five numbers", "'1 1 0 0 1 7'"}},
        {1, "1 two 0 0 1", {"line 13", "TRA_X_NEG", "expected five numbers"}},
    };
    for (size_t n = 0; n < sizeof cases / sizeof cases[0]; ++n) {
        const char *lines[12] = {NULL};
        lines[cases[n].side] = cases[n].line;
        usrsub_mount_limits *m = NULL;
        usrsub_message msg;
        assert_int_equal(read_gbi("bad.gbi", gbi_text("mm", "newton", "radian", lines, ""), &m,
                                  &msg), -1);
        assert_contains(msg.text, "bad.gbi", cases[n].expected[0], cases[n].expected[1],
                        cases[n].expected[2]);
    }
    usrsub_mount_limits *m;
    usrsub_message msg;
    /* a side left out */
    char text[4096];
    snprintf(text, sizeof text, "%s", gbi_text("mm", "newton", "radian", NULL, ""));
    char *rot_y = strstr(text, "IMPACT_PARAMETERS_ROT_Y_POS");
    memcpy(rot_y, "$", 1); /* commented out */
    assert_int_equal(read_gbi("missing.gbi", text, &m, &msg), -1);
    assert_contains(msg.text, "missing.gbi", "line 11", "no IMPACT_PARAMETERS_ROT_Y_POS");
    /* a misspelled key is not dropped silently */
    assert_int_equal(read_gbi("typo.gbi", gbi_text("mm", "newton", "radian", NULL,
                                                   "IMPACT_PARAMETER_TRA_Z_POS = 1 1 1 1 1\n"),
                              &m, &msg), -1);
    assert_contains(msg.text, "typo.gbi", "line 24", "'IMPACT_PARAMETER_TRA_Z_POS' is not a");
    /* the wrong kind of file */
    assert_int_equal(read_gbi("kind.gbi", "[HEADER]\nFILE_TYPE = 'gbs'\n", &m, &msg), -1);
    assert_contains(msg.text, "kind.gbi", "line 2", "FILE_TYPE is 'gbs', expected 'gbi'");
    assert_int_equal(read_gbi("noblock.gbi", "[HEADER]\nFILE_TYPE = 'gbi'\n", &m, &msg), -1);
    assert_contains(msg.text, "noblock.gbi", "no [MOUNT_LIMITS] block");
    /* a file that is not there */
    usrsub_read_report report = {0};
    assert_int_equal(usrsub_mount_limits_read("/nonexistent/limits.gbi", model_mm_n_kg_s, &m,
                                              &report, &msg), -1);
    assert_contains(msg.text, "/nonexistent/limits.gbi");
    /* a unit it does not know */
    assert_int_equal(read_gbi("unit.gbi", gbi_text("parsec", "newton", "radian", NULL, ""), &m,
                              &msg), -1);
    assert_contains(msg.text, "unit.gbi", "parsec");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hand_values_on_both_sides),
        cmocka_unit_test(zero_in_the_gap_and_signs),
        cmocka_unit_test(a_fast_separating_limit_does_not_pull),
        cmocka_unit_test(with_d_zero_damping_is_fully_on_at_contact),
        cmocka_unit_test(continuous_at_the_gap),
        cmocka_unit_test(first_derivative_continuous_when_e_above_one_and_d_positive),
        cmocka_unit_test(partials_match_finite_differences),
        cmocka_unit_test(partials_at_switch_points_are_one_sided_limits),
        cmocka_unit_test(directions_are_kept_apart),
        cmocka_unit_test(reader_takes_any_separator_and_converts_units),
        cmocka_unit_test(active_switches_all_limits),
        cmocka_unit_test(reader_errors_name_the_line),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
