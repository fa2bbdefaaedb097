/*
 * The flexible joint (docs/interface.md §3.5): F = P - K d - D ddot against a plain
 * matrix product for full and block-sparse matrices, the partials -K and -D,
 * the blocks and queries a joint needs, the scaled eigenvalue behind the
 * positive semi-definite warning, and the .gfj reader: units per block, the
 * warnings, and each input error naming its line.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"
#include "usrsub/readers/flex_joint_reader.h"

/* Deterministic entries in [-1, 1]. */
static double jitter(unsigned *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return ((*seed >> 8) & 0xffff) / 32767.5 - 1.0;
}

static void force_is_preload_minus_k_d_minus_d_v(void **state)
{
    (void)state;
    unsigned seed = 12345u;
    /* full matrices, then each single 3x3 block (both matrices), then none */
    for (int pattern = -1; pattern <= 4; ++pattern) {
        usrsub_flex_joint j = {0};
        for (int c = 0; c < 6; ++c)
            for (int r = 0; r < 6; ++r) {
                const int block = 2 * (r / 3) + c / 3;
                const int keep = pattern < 0 || block == pattern;
                j.k[r + 6 * c] = keep ? 1000.0 * jitter(&seed) : 0.0;
                j.d[r + 6 * c] = keep ? 10.0 * jitter(&seed) : 0.0;
            }
        for (int i = 0; i < 6; ++i)
            j.preload[i] = 50.0 * jitter(&seed);
        usrsub_flex_joint_prepare(&j);
        double d[6], v[6], F[6], dFdd[36], dFdv[36];
        for (int i = 0; i < 6; ++i)
            d[i] = jitter(&seed), v[i] = 3.0 * jitter(&seed);
        usrsub_flex_joint_force(&j, d, v, F, dFdd, dFdv);
        for (int r = 0; r < 6; ++r) {
            double expected = j.preload[r];
            for (int c = 0; c < 6; ++c)
                expected -= j.k[r + 6 * c] * d[c] + j.d[r + 6 * c] * v[c];
            assert_close(F[r], expected, 1e-13, 1e-12);
        }
        for (int n = 0; n < 36; ++n) {
            assert_true(dFdd[n] == -j.k[n]);
            assert_true(dFdv[n] == -j.d[n]);
        }
        double G[6];
        usrsub_flex_joint_force(&j, d, v, G, NULL, NULL);
        assert_memory_equal(F, G, sizeof F);
        const unsigned expected_blocks = pattern < 0 ? 15u : pattern <= 3 ? 1u << pattern : 0u;
        assert_int_equal(j.k_blocks, expected_blocks);
        assert_int_equal(j.d_blocks, expected_blocks);
    }
}

static void measures_only_what_the_matrices_use(void **state)
{
    (void)state;
    usrsub_flex_joint j = {0};
    j.k[0] = 100.0; /* x on x */
    usrsub_flex_joint_prepare(&j);
    assert_true(j.uses_translation && !j.uses_rotation && !j.uses_velocity);
    j.k[0 + 6 * 5] = 7.0; /* Fx from az: a rotation is measured */
    usrsub_flex_joint_prepare(&j);
    assert_true(j.uses_translation && j.uses_rotation && !j.uses_velocity);
    usrsub_flex_joint r = {0};
    r.k[5 + 6 * 5] = 1.0;
    r.d[3 + 6 * 4] = 0.5; /* damping: rates measured */
    usrsub_flex_joint_prepare(&r);
    assert_true(!r.uses_translation && r.uses_rotation && r.uses_velocity);
    usrsub_flex_joint t = {0};
    t.k[4 + 6 * 1] = 1.0; /* a torque from a translation: only the translation is measured */
    usrsub_flex_joint_prepare(&t);
    assert_true(t.uses_translation && !t.uses_rotation);
}

static void scaled_smallest_eigenvalue(void **state)
{
    (void)state;
    const double identity_like[4] = {1e6, 0, 0, 1e-3}; /* mixed units, positive definite */
    assert_close(usrsub_scaled_smallest_eigenvalue(identity_like, 2), 1.0, 1e-14, 0);
    const double coupled[4] = {4, 1, 1, 4}; /* scaled: [1 .25; .25 1] -> 0.75 */
    assert_close(usrsub_scaled_smallest_eigenvalue(coupled, 2), 0.75, 1e-14, 0);
    const double indefinite[4] = {1, 2, 2, 1}; /* eigenvalues -1 and 3 */
    assert_close(usrsub_scaled_smallest_eigenvalue(indefinite, 2), -1.0, 1e-14, 0);
    const double skew[4] = {2, 3, -3, 2}; /* the symmetric part is 2 I */
    assert_close(usrsub_scaled_smallest_eigenvalue(skew, 2), 1.0, 1e-14, 0);
    /* 3x3 with known eigenvalues: [2 -1 0; -1 2 -1; 0 -1 2] has 2 - sqrt(2) */
    const double tridiagonal[9] = {2, -1, 0, -1, 2, -1, 0, -1, 2};
    assert_close(usrsub_scaled_smallest_eigenvalue(tridiagonal, 3), (2 - sqrt(2.0)) / 2, 1e-13, 0);
    /* singular (positive semi-definite): 0 up to rounding */
    const double singular[4] = {1, 1, 1, 1};
    assert_true(fabs(usrsub_scaled_smallest_eigenvalue(singular, 2)) < 1e-14);
}

/* ---- the .gfj reader ------------------------------------------------------------------ */

static const double model_mm_n_kg_s[5] = {1e-3, 1.0, 1.0, 1.0, 1.0};

static const char *gfj_text(const char *length, const char *force, const char *angle,
                            const char *blocks)
{
    static char text[8192];
    snprintf(text, sizeof text,
             "$ joint\n[HEADER]\nFILE_TYPE = 'gfj'\nFILE_VERSION = '1'\n[UNITS]\nLENGTH = '%s'\n"
             "ANGLE = '%s'\nFORCE = '%s'\nMASS = 'kg'\nTIME = 'second'\n%s",
             length, angle, force, blocks);
    return text;
}

/* A (MATRIX) block whose entry (r, c) is base * (10 r + c + 1) (all 36 distinct). */
static const char *numbered_matrix(const char *block, double base)
{
    static char text[2][2048];
    static int which = 0;
    char *t = text[which ^= 1];
    int len = snprintf(t, 2048, "[%s]\n(MATRIX)\n{ x y z ax ay az }\n", block);
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c)
            len += snprintf(t + len, 2048 - (size_t)len, "%g%s", base * (10 * r + c + 1),
                            c < 5 ? " " : "\n");
    }
    return t;
}

static int read_gfj(const char *name, const char *text, usrsub_flex_joint **j,
                    usrsub_message *notice, int *has_notice, usrsub_message *msg)
{
    usrsub_read_report report = {0};
    const int status = usrsub_flex_joint_read(test_write_file(name, text), model_mm_n_kg_s, j,
                                              &report, msg);
    *notice = report.notice;
    *has_notice = report.has_notice;
    return status;
}

static void reader_converts_each_block_by_its_units(void **state)
{
    (void)state;
    char blocks[6144];
    snprintf(blocks, sizeof blocks, "%s%s[PRELOAD]\n{ fx fy fz tx ty tz }\n1 2 3 4 5 6\n",
             numbered_matrix("STIFFNESS", 1.0), numbered_matrix("DAMPING", 0.5));
    usrsub_flex_joint *j;
    usrsub_message notice, msg;
    int has_notice;
    /* the file in m, kN and degrees; the model in mm, N and radians */
    if (read_gfj("units.gfj", gfj_text("m", "knewton", "degree", blocks), &j, &notice,
                 &has_notice, &msg) != 0)
        fail_msg("%s", msg.text);
    const double deg = M_PI / 180.0;
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) {
            /* force kN -> 1000 N, torque kN m -> 1e6 N mm; per m -> per 1000 mm,
             * per degree -> per deg rad */
            const double force = r < 3 ? 1000.0 : 1e6, per = c < 3 ? 1000.0 : deg;
            const double value = 10 * r + c + 1;
            assert_close(j->k[r + 6 * c], value * force / per, 1e-13, 0);
            assert_close(j->d[r + 6 * c], 0.5 * value * force / per, 1e-13, 0);
        }
    const double preload[6] = {1000, 2000, 3000, 4e6, 5e6, 6e6};
    for (int i = 0; i < 6; ++i)
        assert_close(j->preload[i], preload[i], 1e-14, 0);
    /* 36 distinct entries: not symmetric, and said so once */
    assert_true(has_notice);
    assert_contains(notice.text, "units.gfj", "not symmetric", "not conservative");
    usrsub_flex_joint_free(j);
}

static const char *const symmetric_pd =
    "[STIFFNESS]\n(MATRIX)\n{ x y z ax ay az }\n"
    "100 10 0 0 0 500\n10 100 0 0 0 0\n0 0 100 0 0 0\n0 0 0 1e4 0 0\n0 0 0 0 1e4 0\n500 0 0 0 0 1e4\n";

static void a_sound_joint_reads_without_warnings(void **state)
{
    (void)state;
    usrsub_flex_joint *j;
    usrsub_message notice, msg;
    int has_notice;
    if (read_gfj("sound.gfj", gfj_text("mm", "newton", "radian", symmetric_pd), &j, &notice,
                 &has_notice, &msg) != 0)
        fail_msg("%s", msg.text);
    assert_false(has_notice);
    assert_close(j->k[0 + 6 * 5], 500.0, 0, 0);
    assert_true(j->d_blocks == 0 && !j->uses_velocity); /* no [DAMPING]: none */
    assert_true(j->preload[0] == 0.0 && j->preload[5] == 0.0);
    usrsub_flex_joint_free(j);
}

static void indefinite_matrices_are_warned_about(void **state)
{
    (void)state;
    usrsub_flex_joint *j;
    usrsub_message notice, msg;
    int has_notice;
    /* symmetric, with K_x,az too large for K_xx K_azaz: indefinite */
    const char *indefinite_k =
        "[STIFFNESS]\n(MATRIX)\n{ x y z ax ay az }\n"
        "100 0 0 0 0 2000\n0 100 0 0 0 0\n0 0 100 0 0 0\n0 0 0 1e4 0 0\n0 0 0 0 1e4 0\n2000 0 0 0 0 1e4\n";
    assert_int_equal(read_gfj("indefinite.gfj", gfj_text("mm", "newton", "radian", indefinite_k),
                              &j, &notice, &has_notice, &msg), 0);
    assert_true(has_notice);
    assert_contains(notice.text, "indefinite.gfj", "stiffness matrix is not positive semi-definite");
    assert_true(strstr(notice.text, "not symmetric") == NULL);
    usrsub_flex_joint_free(j);
    char blocks[2048];
    snprintf(blocks, sizeof blocks, "%s[DAMPING]\n(MATRIX)\n{ x y z ax ay az }\n"
             "1 0 0 0 0 0\n0 -1 0 0 0 0\n0 0 1 0 0 0\n0 0 0 1 0 0\n0 0 0 0 1 0\n0 0 0 0 0 1\n",
             symmetric_pd);
    assert_int_equal(read_gfj("pushing.gfj", gfj_text("mm", "newton", "radian", blocks), &j,
                              &notice, &has_notice, &msg), 0);
    assert_contains(notice.text, "pushing.gfj", "damping matrix is not positive semi-definite");
    usrsub_flex_joint_free(j);
}

static void reader_errors_name_the_line(void **state)
{
    (void)state;
    const char *const head = "[STIFFNESS]\n(MATRIX)\n{ x y z ax ay az }\n";
    const char *const row = "1 0 0 0 0 0\n";
    char five_rows[512], seven_rows[512], short_row[512], long_row[512], nan_row[512], inf_row[512];
    snprintf(five_rows, sizeof five_rows, "%s%s%s%s%s%s", head, row, row, row, row, row);
    snprintf(seven_rows, sizeof seven_rows, "%s%s%s%s%s%s%s%s", head, row, row, row, row, row, row, row);
    snprintf(short_row, sizeof short_row, "%s%s%s1 2 3 4 5\n%s%s%s", head, row, row, row, row, row);
    snprintf(long_row, sizeof long_row, "%s%s1 2 3 4 5 6 7\n%s%s%s%s", head, row, row, row, row, row);
    snprintf(nan_row, sizeof nan_row, "%s%s%s%s1 0 nan 0 0 0\n%s%s", head, row, row, row, row, row);
    snprintf(inf_row, sizeof inf_row, "%s%s%s%s%s%s0 0 0 0 0 inf\n", head, row, row, row, row, row);
    /* lines: 1 "$ joint", 2 [HEADER] .. 10 TIME, 11 [STIFFNESS], 12 (MATRIX), 13 {..}, 14.. rows */
    static const struct {
        const char *name;
        const char *blocks;
        const char *const expected[3];
    } cases[] = {
        {"five.gfj", NULL, {"line 13", "[STIFFNESS] matrix has 5 rows", "expected 6"}},
        {"seven.gfj", NULL, {"line 20", "has 7 rows", "expected 6"}},
        {"short.gfj", NULL, {"line 16", "[STIFFNESS] row 3 has 5 entries", "expected 6"}},
        {"long.gfj", NULL, {"line 15", "row 2 has 7 entries", "expected 6"}},
        {"nan.gfj", NULL, {"line 17", "row 4, column 3 is 'nan'", "not a finite number"}},
        {"inf.gfj", NULL, {"line 19", "row 6, column 6 is 'inf'", "not a finite number"}},
        {"order.gfj", "[STIFFNESS]\n(MATRIX)\n{ ax ay az x y z }\n", {"line 13", "columns must be", "X Y Z AX AY AZ"}},
        {"nomatrix.gfj", "[STIFFNESS]\nK = 5\n", {"line 11", "[STIFFNESS] has no (MATRIX) table", "6 rows of 6"}},
        {"nostiffness.gfj", "[DAMPING]\n(MATRIX)\n{ x y z ax ay az }\n", {"no [STIFFNESS] block", "6 rows of 6", "nostiffness.gfj"}},
        {"typo.gfj", "[STIFNESS]\n", {"line 11", "[STIFNESS] is not a flexible-joint block", "PRELOAD"}},
        {"preload.gfj", NULL, {"line 21", "[PRELOAD] must hold a table", "one row"}},
    };
    char preload[1024];
    snprintf(preload, sizeof preload, "%s[PRELOAD]\n{ fx fy fz tx ty tz }\n1 2 3 4 5 6\n1 2 3 4 5 6\n",
             symmetric_pd);
    const char *const generated[] = {five_rows, seven_rows, short_row, long_row, nan_row, inf_row};
    for (size_t n = 0; n < sizeof cases / sizeof cases[0]; ++n) {
        const char *blocks = n < 6 ? generated[n] : cases[n].blocks != NULL ? cases[n].blocks : preload;
        usrsub_flex_joint *j = NULL;
        usrsub_message notice, msg;
        int has_notice;
        assert_int_equal(read_gfj(cases[n].name, gfj_text("mm", "newton", "radian", blocks), &j,
                                  &notice, &has_notice, &msg), -1);
        assert_contains(msg.text, cases[n].name, cases[n].expected[0], cases[n].expected[1],
                        cases[n].expected[2]);
    }
    usrsub_flex_joint *j;
    usrsub_message notice, msg;
    int has_notice;
    assert_int_equal(read_gfj("kind.gfj", "[HEADER]\nFILE_TYPE = 'gbi'\n", &j, &notice,
                              &has_notice, &msg), -1);
    assert_contains(msg.text, "kind.gfj", "line 2", "FILE_TYPE is 'gbi', expected 'gfj'");
    /* finite in the file, infinite in the model's units: 1e307 N/mm is 1e310 N/m (the
     * entries hand -K out as partials without a second look) */
    char huge[512];
    snprintf(huge, sizeof huge, "%s1e307 0 0 0 0 0\n%s%s%s%s%s", head, row, row, row, row, row);
    usrsub_read_report metres = {0};
    const double model_m[5] = {1.0, 1.0, 1.0, 1.0, 1.0};
    assert_int_equal(usrsub_flex_joint_read(test_write_file("huge.gfj", gfj_text("mm", "newton",
                                                                                 "radian", huge)),
                                            model_m, &j, &metres, &msg), -1);
    assert_contains(msg.text, "huge.gfj", "line 14", "row 1, column 1 (1e+307) is out of range");
    usrsub_read_report report = {0};
    assert_int_equal(usrsub_flex_joint_read("/nonexistent/joint.gfj", model_mm_n_kg_s, &j,
                                            &report, &msg), -1);
    assert_contains(msg.text, "/nonexistent/joint.gfj");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(force_is_preload_minus_k_d_minus_d_v),
        cmocka_unit_test(measures_only_what_the_matrices_use),
        cmocka_unit_test(scaled_smallest_eigenvalue),
        cmocka_unit_test(reader_converts_each_block_by_its_units),
        cmocka_unit_test(a_sound_joint_reads_without_warnings),
        cmocka_unit_test(indefinite_matrices_are_warned_about),
        cmocka_unit_test(reader_errors_name_the_line),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
