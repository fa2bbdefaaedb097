/*
 * The Adams dataset language (docs/interface.md §9.1): the title line,
 * statements and their continuation lines, comments anywhere outside a
 * quoted string, blank lines, tabs and CRLF, names and keywords in any case
 * and shortened to a unique prefix (an ambiguous one lists the candidates,
 * an unknown one names the statement), degree marks, value lists, END.
 * Each case reads a small dataset and checks the model it gives, or the
 * message naming the file, line and statement.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "expr/evaluate.h"
#include "model/model.h"
#include "test_support.h"

/* A ground, a part 2 (mass 2, CM 20) and its markers, after the title. */
#define HEAD "a title line: never read as a statement\n"
#define GROUND "PART/1, GROUND\nMARKER/10, PART=1\n"
#define BODY "PART/2, MASS=2, CM=20, IP=1,2,3\nMARKER/20, PART=2\n"

static hx_model *parse(const char *text, hx_message *msg)
{
    return hx_model_parse(text, strlen(text), "lang.adm", NULL, msg);
}

static hx_model *read_ok(const char *text)
{
    hx_message msg;
    hx_model *m = parse(text, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    return m;
}

#define expect_error(dataset, ...)                                                          \
    do {                                                                                 \
        hx_message msg_;                                                                 \
        hx_model *m_ = parse((dataset), &msg_);                                             \
        if (m_ != NULL) {                                                                \
            hx_model_free(m_);                                                           \
            fail_msg("read; expected an error");                                         \
        }                                                                                \
        assert_contains(msg_.text, __VA_ARGS__);                                         \
    } while (0)

static const hx_marker *marker(const hx_model *m, int id)
{
    const int k = hx_model_marker(m, id);
    if (k < 0)
        fail_msg("no marker %d", id);
    return &m->markers[k];
}

static void unique_prefixes_and_case(void **state)
{
    (void)state;
    /* MAR = MARKER, PA = PART, Q = QP, JOI = JOINT, REV = REVOLUTE, in any case */
    hx_model *m = read_ok(HEAD "part/1, ground\nmar/10, pa=1\n"
                          "Part/2, Mass=2, CM=20, IP=1,2,3\nMAR/20, PA=2, Q=0,0,0\n"
                          "Marker/21, part=2\njoi/1, rev, i=21, j=10\nend\n");
    assert_int_equal(m->nbodies, 2);
    assert_int_equal(m->njoints, 1);
    assert_int_equal(m->joints[0].type, HX_JOINT_REVOLUTE);
    assert_int_equal(m->markers[m->joints[0].i_marker].id, 21);
    hx_model_free(m);
}

static void ambiguous_and_unknown_names(void **state)
{
    (void)state;
    /* R abbreviates REVOLUTE and RACKPIN: both listed */
    expect_error(HEAD GROUND BODY "MARKER/21, PART=2\nJOINT/1, R, I=21, J=10\nEND\n",
                 "lang.adm:7:", "JOINT/1:", "keyword R", "ambiguous", "REVOLUTE", "RACKPIN");
    /* M abbreviates MARKER, MOTION, ... */
    expect_error(HEAD GROUND "M/20, PART=1\nEND\n", "lang.adm:4:", "M is ambiguous", "MARKER",
                 "MOTION");
    expect_error(HEAD GROUND "PART/2, MASS=1, COLOR=RED\nEND\n", "lang.adm:4:", "PART/2:",
                 "COLOR (column 17) is not a keyword of PART", "MASS");
    expect_error(HEAD GROUND "WIDGET/1, SIZE=2\nEND\n", "lang.adm:4:",
                 "WIDGET is not a statement the harness knows");
    /* an exact name wins over the longer ones it is a prefix of (I, IM, IP) */
    hx_model *m = read_ok(HEAD GROUND BODY "MARKER/21, PART=2\nSFORCE/1, TRANSLATION, I=21,"
                          " J=10, FUNCTION=1\nEND\n");
    assert_int_equal(m->nloads, 1);
    hx_model_free(m);
}

static void degree_marks(void **state)
{
    (void)state;
    hx_model *m = read_ok(HEAD GROUND "MARKER/11, PART=1, REULER=90D, 0d, -45D\n"
                          "MARKER/12, PART=1, REULER=1.5707963267948966, 0, -0.78539816339744828\n"
                          "END\n");
    for (int k = 0; k < 9; ++k)
        assert_close(marker(m, 11)->R0[k], marker(m, 12)->R0[k], 0.0, 1e-16);
    /* x axis of 11: Rz(pi/2) Rz(-pi/4) = Rz(pi/4): (cos 45, sin 45, 0) */
    assert_close(marker(m, 11)->R0[0], sqrt(0.5), 0.0, 1e-15);
    assert_close(marker(m, 11)->R0[3], sqrt(0.5), 0.0, 1e-15);
    hx_model_free(m);
    expect_error(HEAD GROUND "PART/2, MASS=2D, CM=20, IP=1,2,3\nMARKER/20, PART=2\nEND\n",
                 "lang.adm:4:", "PART/2:", "MASS 2D (column 14)", "degree mark");
    expect_error(HEAD GROUND "MARKER/11, PART=1, QP=1,2D,3\nEND\n", "lang.adm:4:", "MARKER/11:",
                 "QP, value 2,", "degree mark");
}

static void continuation_lines_and_comments(void **state)
{
    (void)state;
    hx_model *m = read_ok(HEAD "! a comment line before anything\n\n"
                          "PART/1, GROUND   ! ground, with a comment\n"
                          "MARKER/10, PART=1\n"
                          "PART/2,       ! a comment after a comma\n"
                          ", MASS =      ! between a key and its value\n"
                          ",   2\n"
                          ",   CM = 20,  ! a trailing comma, then a comment\n"
                          "\n"
                          "! a comment line inside the statement\n"
                          "  , IP = 1, 2, ! a list broken\n"
                          ", 3            ! the end of a continuation\n"
                          "MARKER/20, PART=2, QP=1\n"
                          ", 2, 3\n"
                          "MARKER/21, PART = 2, REULER = 90D,\n"
                          ", 0D, 0D\n"
                          "SFORCE/1, ROTATION, I=21, J=10, FUNCTION=STEP(TIME,\n"
                          ", 0, 0, 1, 5)   ! after a comma, the continuation's marks it only\n"
                          "SFORCE/2, ROTATION, I=21, J=10, FUNCTION=STEP(TIME, 0, 0\n"
                          ", 1, 6)         ! elsewhere a comma is a comma, in parentheses too\n"
                          "STRING/5, STRING=\"a!b, c\" ! quoted: no comment, no separator\n"
                          "END\n");
    const hx_body *b = &m->bodies[hx_model_body(m, 2)];
    assert_close(b->mass, 2.0, 0, 0);
    assert_close(b->inertia[8], 3.0, 0, 0);
    assert_close(marker(m, 20)->pos0[2], 3.0, 0, 0);
    assert_close(marker(m, 21)->R0[3], 1.0, 0, 1e-16); /* x axis turned onto y */
    /* STEP(TIME, 0, 0, 1, 5) and STEP(TIME, 0, 0, 1, 6), read across their continuations:
     * at t = 1 their ends, at t = 0.5 half way (the cubic step's middle) */
    hx_frames fr;
    assert_int_equal(hx_frames_init(&fr, m), 0);
    const hx_expr_context c = {&fr, NULL, NULL};
    static const double at[2][2] = {{1.0, 0.5}, {5.0, 2.5}}, at6[2] = {6.0, 3.0};
    for (int i = 0; i < 2; ++i) {
        double v0, v1;
        hx_expr_fault f;
        fr.time = at[0][i];
        assert_int_equal(hx_expr_eval(m->loads[0].value, &c, &v0, &f), 0);
        assert_int_equal(hx_expr_eval(m->loads[1].value, &c, &v1, &f), 0);
        assert_close(v0, at[1][i], 0, 1e-15);
        assert_close(v1, at6[i], 0, 1e-15);
    }
    hx_frames_free(&fr);
    assert_string_equal(hx_model_string(m, 5), "a!b, c");
    hx_model_free(m);
    expect_error(HEAD ", MASS=2\nEND\n", "lang.adm:2:", "continuation line", "no statement");
}

static void title_blank_lines_tabs_and_end(void **state)
{
    (void)state;
    /* the title looks like a statement and is not read; tabs separate; what
     * follows END is not read */
    hx_model *m = read_ok("PART/99, MASS=not a number\n\n\t\n"
                          "\tPART/1,\tGROUND\nMARKER/10,\tPART=1\t\n\n"
                          "END\nGARBAGE/1, !! not read\n");
    assert_int_equal(m->nbodies, 1);
    hx_model_free(m);
    expect_error(HEAD GROUND, "lang.adm:", "no END statement");
    expect_error(HEAD GROUND "END/NOW\nEND\n", "lang.adm:4:", "END:", "NOW", "not a keyword");
}

static void crlf_line_ends(void **state)
{
    (void)state;
    const char *lf = HEAD GROUND BODY "MARKER/21, PART=2, QP=1, 2,\n, 3 ! c\nEND\n";
    char crlf[1024];
    size_t n = 0;
    for (const char *p = lf; *p; ++p) {
        if (*p == '\n')
            crlf[n++] = '\r';
        crlf[n++] = *p;
    }
    crlf[n] = '\0';
    hx_model *a = read_ok(lf), *b = read_ok(crlf);
    assert_int_equal(a->nmarkers, b->nmarkers);
    for (int k = 0; k < a->nmarkers; ++k)
        assert_memory_equal(a->markers[k].pos0, b->markers[k].pos0, sizeof a->markers[k].pos0);
    assert_close(marker(b, 21)->pos0[2], 3.0, 0, 0);
    hx_model_free(a);
    hx_model_free(b);
}

static void value_lists_and_counts(void **state)
{
    (void)state;
    expect_error(HEAD GROUND "MARKER/11, PART=1, QP=1,2\nEND\n", "lang.adm:4:", "MARKER/11:",
                 "QP takes 3 values, not 2");
    expect_error(HEAD GROUND "PART/2, MASS=2, CM=20, IP=1,2,3,4\nMARKER/20, PART=2\nEND\n",
                 "lang.adm:4:", "PART/2:", "IP takes 3 or 6 values, not 4");
    expect_error(HEAD GROUND "MARKER/11, PART=1, QP=1,2,3x\nEND\n", "lang.adm:4:",
                 "QP, value 3, 3x (column 27) is not a number");
    expect_error(HEAD GROUND "MARKER/11, PART=1, FLOATING=1\nEND\n", "FLOATING is a flag");
    expect_error(HEAD GROUND "MARKER/11, PART\nEND\n", "PART needs a value");
    expect_error(HEAD GROUND "MARKER/11, PART=1, QP=1,2,3, QP=1,2,3\nEND\n",
                 "QP is given twice");
    expect_error(HEAD GROUND "MARKER/11, 5, PART=1\nEND\n", "lang.adm:4:", "column 12",
                 "a value with no keyword before it");
    expect_error(HEAD GROUND "MARKER/11 PART=1\nEND\n", "lang.adm:4:", "expected ',' after the statement's id");
    expect_error(HEAD GROUND "MARKER 11, PART=1\nEND\n", "lang.adm:4:", "expected '/'");
}

static void format_by_content(void **state)
{
    (void)state;
    /* a dataset named .xml is a dataset; XML named .adm is XML, with a byte-order mark
     * and blanks before it; each malformed one gets its own reader's message */
    hx_message msg;
    hx_model *m = hx_model_read(test_write_file("dataset.xml", HEAD GROUND "END\n"), NULL, &msg);
    assert_non_null(m);
    hx_model_free(m);
    m = hx_model_read(test_write_file("model.adm", "\xEF\xBB\xBF \n <MotionSolve><Model>"
                                      "<Body_Ground id=\"1\"/></Model></MotionSolve>\n"),
                      NULL, &msg);
    assert_non_null(m);
    assert_int_equal(m->nbodies, 1);
    hx_model_free(m);
    assert_null(hx_model_read(test_write_file("broken.adm", "<MotionSolve><Model>\n"), NULL, &msg));
    assert_contains(msg.text, "broken.adm:", "malformed XML");
    assert_null(hx_model_read(test_write_file("broken.xml", HEAD "PART/1, GROUND,, (\n"), NULL,
                              &msg));
    assert_contains(msg.text, "broken.xml:2:", "PART/1:", "GROUND is a flag");
    assert_null(strstr(msg.text, "XML"));
    static const char bad[] = "title\nPART/1 GROUND\nEND\n";
    assert_null(hx_model_parse(bad, sizeof bad - 1, "p.adm", NULL, &msg));
    assert_contains(msg.text, "p.adm:2:", "expected ',' after the statement's id");
    assert_null(strstr(msg.text, "malformed XML"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(unique_prefixes_and_case),
        cmocka_unit_test(ambiguous_and_unknown_names),
        cmocka_unit_test(degree_marks),
        cmocka_unit_test(continuation_lines_and_comments),
        cmocka_unit_test(title_blank_lines_tabs_and_end),
        cmocka_unit_test(crlf_line_ends),
        cmocka_unit_test(value_lists_and_counts),
        cmocka_unit_test(format_by_content),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
