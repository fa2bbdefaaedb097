/* Redundant constraints and the assembly (docs/architecture.md, the
 * constraint system): the rows found redundant at set-up and named, the runs
 * with them removed against the same mechanisms modelled without redundancy,
 * an inconsistent redundant constraint refused, the assembly's report; the
 * rows found again once assembled: the same for the four-bar placed off its
 * loop, one fewer for the four-bar placed collinear, the change said. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cmd/commands.h"
#include "sim/dynamics/assembly.h"
#include "sim/dynamics/constraints.h"
#include "sim/dynamics/redundancy.h"
#include "sim_support.h"
#include "test_support.h"

#define DATA(name) DATA_DIR "/redundant/" name

/* The names of the rows in list, one a line. */
static void list_names(const hx_dynamics *d, const int *list, int n, char *text, size_t size)
{
    text[0] = '\0';
    for (int k = 0; k < n; ++k) {
        char name[160];
        hx_redundancy_name_row(d, list[k], name, sizeof name);
        strncat(text, name, size - strlen(text) - 2);
        strcat(text, "\n");
    }
}

/* The names of the removed rows, one a line. */
static void removed_names(const hx_dynamics *d, char *text, size_t size)
{
    list_names(d, d->removed, d->nremoved, text, size);
}

/* The largest |phi| / scale of the removed rows along a run. */
static double removed_drift(sim *s)
{
    const hx_dynamics *d = &s->dynamics;
    double *phi = calloc((size_t)d->nrows, sizeof(double));
    double *G = calloc(12 * (size_t)d->nrows, sizeof(double));
    double worst = 0.0;
    for (int r = 0; r < s->path.rows; ++r) {
        assert_int_equal(hx_constraints_rows(d, &s->data, s->path.t[r],
                                             s->path.y + r * s->path.n, phi, G, NULL), 0);
        for (int k = 0; k < d->nremoved; ++k)
            worst = fmax(worst, fabs(phi[d->removed[k]]) / d->rows[d->removed[k]].scale);
    }
    free(phi), free(G);
    return worst;
}

/* The four-bar closed by four revolutes: 20 rows, 17 independent (the loop
 * is planar: joint 4's out-of-plane point row and its two tilts repeat
 * joints 1-3), and the motion of the bundled four-bar, whose spherical and
 * cylindrical joints give exactly the 17. */
static void four_revolutes_close_the_four_bar(void **state)
{
    (void)state;
    sim r, b;
    sim_run(&r, DATA("four_bar_revolutes.adm"), HX_METHOD_DOPRI5, 1e-10, 1.0, 0.01);
    sim_run(&b, "four_bar.adm", HX_METHOD_DOPRI5, 1e-10, 1.0, 0.01);
    assert_int_equal(r.dynamics.nrows, 20);
    assert_int_equal(r.dynamics.nactive, 17);
    char names[2048];
    removed_names(&r.dynamics, names, sizeof names);
    assert_string_equal(names, "JOINT/4 REVOLUTE: equation 3 (x_I - x_J along z)\n"
                               "JOINT/4 REVOLUTE: equation 4 (z_I . x_J)\n"
                               "JOINT/4 REVOLUTE: equation 5 (z_I . y_J)\n");
    assert_int_equal(b.dynamics.nremoved, 0);
    assert_int_equal(r.path.rows, b.path.rows);
    assert_int_equal(r.dynamics.n, b.dynamics.n);
    /* positions and velocities, each run to rtol 1e-10; the loop is planar and
     * its in-plane rows are the same in both models: they agree to the bit */
    double worst = 0.0;
    for (int row = 0; row < r.path.rows; ++row)
        for (int k = 0; k < r.dynamics.nq + r.dynamics.nu; ++k)
            worst = fmax(worst, fabs(sim_state(&r, row, k) - sim_state(&b, row, k)));
    printf("four revolutes against spherical + cylindrical: largest state difference %.3g\n",
           worst);
    assert_true(worst < 1e-8);
    assert_true(removed_drift(&r) < 1e-10);
    sim_close(&r);
    sim_close(&b);
}

/* A door on four hinges along one axis: the first hinge's 5 rows hold it, the
 * other 15 repeat them; it swings as the same door on one (reduced) hinge. */
static void door_on_four_hinges(void **state)
{
    (void)state;
    sim four, one;
    sim_run(&four, DATA("door_four_hinges.adm"), HX_METHOD_DOPRI5, 1e-10, 1.0, 0.01);
    sim_run(&one, DATA("door_one_hinge.adm"), HX_METHOD_DOPRI5, 1e-10, 1.0, 0.01);
    const hx_dynamics *d = &four.dynamics;
    assert_int_equal(d->nrows, 20);
    assert_int_equal(d->nremoved, 15);
    for (int k = 0; k < 15; ++k)
        assert_int_equal(d->removed[k], 5 + k); /* joints 2, 3 and 4 whole */
    const int q = d->dof[1].q, theta = one.dynamics.dof[1].q;
    assert_int_equal(one.dynamics.nrows, 0);
    double worst = 0.0, swing = 0.0;
    for (int row = 0; row < four.path.rows; ++row) {
        swing = fmax(swing, fabs(sim_state(&one, row, theta)));
        /* the centre of mass turns about the z axis from (0.4, 0, 0.75) */
        const double x = sim_state(&four, row, q), y = sim_state(&four, row, q + 1);
        worst = fmax(worst, fabs(remainder(atan2(y, x) - sim_state(&one, row, theta), 2 * M_PI)));
        assert_close(hypot(x, y), 0.4, 0, 1e-12);
        assert_close(sim_state(&four, row, q + 2), 0.75, 0, 1e-12);
    }
    printf("door on four hinges against one: largest angle difference %.3g\n", worst);
    assert_true(worst < 1e-8);
    printf("largest swing %.3g rad\n", swing);
    assert_true(swing > 0.1); /* it did swing */
    assert_true(removed_drift(&four) < 1e-10);
    sim_close(&four);
    sim_close(&one);
}

/* The initial state's projection fails with msg; its text is returned. */
static void initial_failure(const char *path, hx_message *msg)
{
    hx_session s;
    hx_dynamics d;
    assert_int_equal(hx_session_open(&s, path, stderr, msg), 0);
    assert_int_equal(hx_dynamics_init(&d, &s, msg), 0);
    double *y = calloc((size_t)d.n, sizeof(double));
    assert_int_not_equal(hx_dynamics_initial_y(&d, y, msg), 0);
    free(y);
    hx_dynamics_free(&d);
    hx_session_close(&s);
}

/* Hinge 2's pin 1 cm off the axis: its rows are redundant at set-up (the
 * same G), but once hinge 1 is met it is off by 1 cm: the model locks. */
static void inconsistent_redundant_hinge_fails(void **state)
{
    (void)state;
    hx_message msg;
    initial_failure(DATA("door_bent_hinge.adm"), &msg);
    printf("%s\n", msg.text);
    assert_non_null(strstr(msg.text, "a redundant constraint is not consistent at t = 0: JOINT/2"
                                     " REVOLUTE: equation 1 (x_I - x_J along x), removed at the"
                                     " set-up, is off by 0.00667")); /* 0.01 / 1.5, the length */
    assert_non_null(strstr(msg.text, "the model locks"));
}

/* The four-bar's ground pivot 5 m away: no assembly, the joints named. */
static void failed_assembly_names_the_joint(void **state)
{
    (void)state;
    hx_message msg;
    initial_failure(DATA("four_bar_far.adm"), &msg);
    printf("%s\n", msg.text);
    assert_non_null(strstr(msg.text, "cannot be satisfied at t = 0"));
    assert_non_null(strstr(msg.text, "the largest at JOINT/"));
    assert_non_null(strstr(msg.text, ": equation "));
}

/* The moves of a model's assembly; count returned. */
static int moves_of(const char *path, hx_assembly_move *moves, int *ids)
{
    hx_session s;
    hx_dynamics d;
    hx_message msg;
    assert_int_equal(hx_session_open(&s, path, stderr, &msg), 0);
    assert_int_equal(hx_dynamics_init(&d, &s, &msg), 0);
    const int count = hx_assembly_moves(&d, moves, &msg);
    for (int k = 0; k < count; ++k)
        ids[k] = s.model->bodies[moves[k].body].id;
    hx_dynamics_free(&d);
    hx_session_close(&s);
    return count;
}

static void assembly_reports_the_parts_moved(void **state)
{
    (void)state;
    hx_assembly_move moves[8];
    int ids[8];
    /* a block 1 mm off its FIXED seat whose I marker is its centre: the point
     * rows move the centre alone, by 1 mm, and the axes already agree */
    assert_int_equal(moves_of(DATA("block_off.adm"), moves, ids), 1);
    assert_int_equal(ids[0], 2);
    assert_close(moves[0].translation, 1e-3, 0, 1e-12);
    assert_true(moves[0].rotation < 1e-12);
    /* the four-bar with its ground pivot 2 mm off: every bar moves, the
     * rocker the most; nothing reported for the bundled, assembled one */
    assert_int_equal(moves_of(DATA("four_bar_off.adm"), moves, ids), 3);
    assert_int_equal(ids[2], 4);
    assert_true(moves[2].translation > 1e-4 && moves[2].translation < 2e-3);
    assert_true(moves[2].rotation > 1e-3 && moves[2].rotation < 0.02);
    assert_int_equal(moves_of(EXAMPLES_DIR "/four_bar.adm", moves, ids), 0);
}

/* The largest |phi| / scale and |dphi/dt| of every row (active and removed)
 * along a run: the projection holds both to 1e-10. */
static void assert_residuals_held(sim *s)
{
    for (int row = 0; row < s->path.rows; ++row) {
        double phi, phidot;
        assert_int_equal(hx_constraints_residuals(&s->dynamics, &s->data, s->path.t[row],
                                                  s->path.y + row * s->path.n, &phi, &phidot),
                         0);
        assert_true(phi <= 1e-10);
        assert_true(phidot <= 1e-10);
    }
}

#define FOUR_BAR_REMOVED                                                                       \
    "JOINT/4 REVOLUTE: equation 3 (x_I - x_J along z)\n"                                       \
    "JOINT/4 REVOLUTE: equation 4 (z_I . x_J)\n"                                               \
    "JOINT/4 REVOLUTE: equation 5 (z_I . y_J)\n"

/* The four-bar dataset `file` (tests/data) run by DOPRI5 for 1 s: the rows
 * redundant where the model places them are `placed`, those removed for the
 * run FOUR_BAR_REMOVED, `changes` rows differ between the two (those no longer
 * redundant named in no_longer, none newly so), and every residual, the
 * removed rows' too, held along the run. */
static void run_four_bar(sim *s, const char *file, const char *placed, int changes,
                         const char *no_longer)
{
    char path[512];
    snprintf(path, sizeof path, DATA("%s"), file);
    sim_run(s, path, HX_METHOD_DOPRI5, 1e-10, 1.0, 0.01);
    const hx_dynamics *d = &s->dynamics;
    char names[2048], was[1024], now[1024];
    list_names(d, d->removed_placed, d->nremoved_placed, names, sizeof names);
    assert_string_equal(names, placed);
    removed_names(d, names, sizeof names);
    assert_string_equal(names, FOUR_BAR_REMOVED);
    assert_int_equal(hx_redundancy_change(d, was, now, sizeof now), changes);
    assert_string_equal(was, no_longer);
    assert_string_equal(now, "");
    assert_residuals_held(s);
    assert_true(removed_drift(s) < 1e-10);
}

/* The four-bar of four revolutes with its ground pivot 2 mm off: the assembly
 * moves every bar, and the rank at the assembled configuration is the placed
 * one's: the same three rows removed, no change said, the run started from
 * the model's state as before; the run's residuals, the removed rows' too,
 * held. */
static void four_bar_off_keeps_its_redundant_rows(void **state)
{
    (void)state;
    sim s;
    run_four_bar(&s, "four_bar_off.adm", FOUR_BAR_REMOVED, 0, "");
    assert_null(s.dynamics.assembled_q);
    sim_close(&s);
}

/* The four-bar placed with its bars along x (crank 1, coupler 2, rocker 1)
 * and its ground pivot at (3.6, 0.5), off the line: there the bars'
 * x velocities are three unknowns for four joints' x rows, so joint 4's x
 * row is redundant as well as its out-of-plane three. Assembled (the rocker
 * lifted onto the pivot) the bars are not collinear and only the three are:
 * the set-up says which row it kept ("... redundant where the model places
 * them, is not: kept"), the run starts where that set was found, holds every
 * residual, and swings. Without the second look the removed x row is off by
 * 0.0585 of the model's size once the others are met: the run stops (the model
 * would lock). */
static void collinear_four_bar_changes_its_redundant_rows(void **state)
{
    (void)state;
    sim s;
    run_four_bar(&s, "four_bar_collinear.adm",
                 "JOINT/4 REVOLUTE: equation 1 (x_I - x_J along x)\n" FOUR_BAR_REMOVED, 1,
                 "JOINT/4 REVOLUTE: equation 1 (x_I - x_J along x)");
    const hx_dynamics *d = &s.dynamics;
    assert_non_null(d->assembled_q);
    /* the crank's centre swung (it starts at rest; gravity moves it) */
    const int q = d->dof[1].q;
    double swing = 0.0;
    for (int row = 0; row < s.path.rows; ++row)
        swing = fmax(swing, hypot(sim_state(&s, row, q) - sim_state(&s, 0, q),
                                  sim_state(&s, row, q + 1) - sim_state(&s, 0, q + 1)));
    printf("collinear four-bar: the crank's centre moved up to %.3g\n", swing);
    assert_true(swing > 0.01);
    sim_close(&s);
    /* run says it, before the rows it removes */
    test_captured c;
    test_capture(hx_command_run,
                 (const char *const[]){"run", DATA("four_bar_collinear.adm"), "--end", "0.01",
                                       "--quiet", NULL},
                 &c);
    assert_int_equal(c.status, 0);
    assert_non_null(strstr(c.err, "run: note: the assembly moved the parts to where JOINT/4"
                                  " REVOLUTE: equation 1 (x_I - x_J along x), redundant where"
                                  " the model places them, is not: kept\n"
                                  "run: note: JOINT/4 REVOLUTE: equation 3"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(four_revolutes_close_the_four_bar),
        cmocka_unit_test(door_on_four_hinges),
        cmocka_unit_test(inconsistent_redundant_hinge_fails),
        cmocka_unit_test(failed_assembly_names_the_joint),
        cmocka_unit_test(assembly_reports_the_parts_moved),
        cmocka_unit_test(four_bar_off_keeps_its_redundant_rows),
        cmocka_unit_test(collinear_four_bar_changes_its_redundant_rows),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
