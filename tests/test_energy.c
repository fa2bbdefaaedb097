/*
 * The energy of a state (sim/dynamics/energy.h): the elastic energy of every
 * element from one copy of the frames, and its independence of how a model
 * is written; the work of the time-dependent constraints in the balance.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model_runs.h"
#include "sim/dynamics/element_at.h"
#include "sim/dynamics/energy.h"
#include "sim_support.h"
#include "test_support.h"

/* The elastic energy at every output time, at the size of a full vehicle:
 * one copy of the frames serves all its 73 bushings (each moved GFOSUB body
 * put back), so the energy equals the sum of each element's potential from
 * a fresh copy, and leaves the copy as it found it. A body not put back
 * changes the next elements' potentials. */
static void the_energy_of_every_element_from_one_copy_of_the_frames(void **state)
{
    (void)state;
    model m;
    open_model(&m, EXAMPLES_DIR "/full_vehicle.xml");
    const hx_dynamics *d = &m.d;
    hx_dynamics_data *dd = &m.data;
    double *y = model_state(&m);
    /* deformed: the bump under the left wheels has begun */
    simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-6, 0.15, y);
    const double t = 0.15;
    const hx_energy e = hx_energy_of(d, dd, t, y);
    assert_int_equal(memcmp(dd->moved.bodies, dd->frames.bodies,
                            sizeof *dd->frames.bodies * (size_t)d->m->nbodies), 0);
    assert_int_equal(memcmp(dd->moved.markers, dd->frames.markers,
                            sizeof *dd->frames.markers * (size_t)d->m->nmarkers), 0);
    double sum = 0.0;
    int gfosub = 0;
    for (int k = 0; k < d->m->nforces; ++k) {
        hx_frames_copy(&dd->moved, &dd->frames);
        sum += hx_element_potential(d->s, &dd->moved, &dd->frames, k, t);
        gfosub += hx_bindings_find(&d->s->bindings, HX_FAMILY_FORCE, k)->kind != HX_BIND_FIELD;
    }
    printf("  elastic energy %.10g from one copy, %.10g from a copy each (%d GFOSUB elements)\n",
           e.elastic, sum, gfosub);
    assert_true(gfosub >= 20);
    assert_true(fabs(e.elastic) > 0.0);
    assert_true(e.elastic == sum);
    free(y);
    close_model(&m);
}

/* bushing_mount.xml with each of the replacements (from, to) made once. */
static const char *mount_variant(const char *name, const char *const *pairs, int count)
{
    static char text[8192];
    FILE *f = fopen(EXAMPLES_DIR "/bushing_mount.xml", "r");
    assert_non_null(f);
    const size_t size = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[size] = '\0';
    for (int k = 0; k < count; ++k) {
        char *at = strstr(text, pairs[2 * k]);
        if (at == NULL)
            fail_msg("bushing_mount.xml has no %s", pairs[2 * k]);
        const size_t from = strlen(pairs[2 * k]), to = strlen(pairs[2 * k + 1]);
        assert_true(strlen(text) - from + to < sizeof text);
        memmove(at + to, at + from, strlen(at + from) + 1);
        memcpy(at, pairs[2 * k + 1], to);
    }
    return test_write_file(name, text);
}

/* The elastic energy of the four mounts after 0.1 s, the same however the
 * model is written: with ground not the first body (the frames' markers
 * grouped by body start at a moving one), and with mount 1's I on ground
 * (its GFOSUB probed by moving ground's frame, which carries I). */
static void the_elastic_energy_does_not_depend_on_how_the_model_is_written(void **state)
{
    (void)state;
    static const char *const gbs[2] = {"\"mount_linear.gbs\"",
                                       "\"" EXAMPLES_DIR "/mount_linear.gbs\""};
    static const char *const ground_second[6] = {
        gbs[0], gbs[1], "<Body_Ground id=\"1\"/>", "",
        /* after the block's own element */
        "<Reference_Marker id=\"20\"", "<Body_Ground id=\"1\"/><Reference_Marker id=\"20\"",
    };
    static const char *const swapped[6] = {
        gbs[0], gbs[1],
        "i_marker_id=\"21\" j_floating_marker_id=\"11\" ref_marker_id=\"11\"",
        "i_marker_id=\"11\" j_floating_marker_id=\"21\" ref_marker_id=\"21\"",
        "USER(1, 21, 11, 100)", "USER(1, 11, 21, 100)",
    };
    const char *paths[3];
    paths[0] = EXAMPLES_DIR "/bushing_mount.xml";
    paths[1] = mount_variant("mount_ground_second.xml", ground_second, 3);
    paths[2] = mount_variant("mount_swapped.xml", swapped, 3);
    double elastic[3];
    for (int k = 0; k < 3; ++k) {
        model m;
        open_model(&m, paths[k]);
        double *y = model_state(&m);
        simulate(&m, HX_METHOD_DOPRI5, HX_JACOBIAN_ANALYTIC, 1e-11, 0.1, y);
        if (k == 1)
            assert_false(m.d.m->bodies[0].is_ground);
        elastic[k] = hx_energy_of(&m.d, &m.data, 0.1, y).elastic;
        printf("  %s: elastic energy at 0.1 s %.12g\n", paths[k], elastic[k]);
        free(y);
        close_model(&m);
    }
    assert_true(fabs(elastic[0]) > 1e-4); /* wrong ones were 1e3 and more */
    assert_close(elastic[1], elastic[0], 1e-7, 0);
    assert_close(elastic[2], elastic[0], 1e-7, 0);
}

/* A run of the model at path with DOPRI5 at rtol 1e-10 to t_end, output every 0.01 s:
 * the loads and drives did work of the size of the energy by the end (above 0.1), and
 * the largest change of the energy (kinetic + potential + elastic - work of the loads
 * and the drives) and of the balance, relative to the run's scale, are below 1e-6. */
static void assert_work_in_the_balance(const char *path, double t_end)
{
    model m;
    open_model(&m, path);
    double *y = model_state(&m);
    hx_simulation_options so = {0};
    hx_integrator_defaults(&so.integration);
    so.integration.method = HX_METHOD_DOPRI5;
    so.integration.rtol = 1e-10;
    so.integration.atol = 1e-13;
    so.integration.t_end = t_end;
    so.integration.output_interval = 0.01;
    hx_simulation_result r;
    if (hx_simulate(&m.d, &so, y, &r) != 0)
        fail_msg("%s: %s", path, r.message);
    const double energy = r.energy_error_max / r.energy_scale;
    const double balance = r.balance_error_max / r.energy_scale, work = y[m.d.load_work];
    printf("  %s: energy change %.3g, balance %.3g (relative to %.6g), work in %.6g\n", path,
           energy, balance, r.energy_scale, work);
    assert_true(fabs(work) > 0.1); /* the drive did work, of the size of the energy */
    assert_true(energy < 1e-6);
    assert_true(balance < 1e-6);
    free(y);
    close_model(&m);
}

/* The driven slider-crank (tests/data, docs/examples.md): its crank's motion is a row of
 * the constraint system, AZ - 10 t = 0, whose multiplier does the work that keeps the
 * crank at 10 rad/s against the rod and the slider. With the row's power lambda f' in the
 * balance it holds to the integrator's error; without it the run reported a change of
 * 1.66 (relative), and with the power's sign flipped twice as much. */
static void a_driven_row_s_work_is_in_the_balance(void **state)
{
    (void)state;
    assert_work_in_the_balance(DATA_DIR "/driven_slider_crank.xml", 1.0);
}

/* A general constraint driving a free body along DX = 0.1 SIN(TIME) against gravity along
 * -x, and one turning a hinged body (a reduced revolute to ground: the row's block is its
 * one coordinate) through AZ = 0.5 SIN(2 TIME) against gravity along -x: each row's power
 * is -lambda df/dt (DZ = 0, which reads no TIME, is left out of the sum). Without the
 * rows' power the run reported a change of 13.6 (relative), with its sign flipped 27.1. */
static void a_general_constraint_of_time_s_work_is_in_the_balance(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "gcon_driven.xml",
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"-9.81\" grav_y=\"0\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"1.5\" inertia_xx=\"0.2\" inertia_yy=\"0.3\""
        " inertia_zz=\"0.25\" v_ic_x=\"0.1\" w_ic_x=\"0.3\" w_ic_z=\"-0.7\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\"/>\n"
        "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"2\" inertia_xx=\"0.4\" inertia_yy=\"0.3\""
        " inertia_zz=\"0.2\" w_ic_z=\"1\"/>\n"
        "<Reference_Marker id=\"30\" body_id=\"3\" pos_y=\"0.4\"/>\n"
        "<Reference_Marker id=\"31\" body_id=\"3\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"31\" j_marker_id=\"10\"/>\n"
        "<Constraint_General id=\"1\" expr=\"DX(20) - 0.1*SIN(TIME)\"/>\n"
        "<Constraint_General id=\"2\" expr=\"DZ(20)\"/>\n"
        "<Constraint_General id=\"3\" expr=\"AZ(31,10) - 0.5*SIN(2*TIME)\"/>\n"
        "</Model></MotionSolve>\n");
    assert_work_in_the_balance(path, 3.0);
}

/* A Motion_Joint on a reduced revolute (a pendulum's only joint, to ground): the joint is
 * integrated at the motion's rate and acceleration, and the drive's power is the torque
 * that takes the loads' acceleration to the motion's, I (f'' - udot_free), times the
 * rate. Swung through SIN(3 TIME) against gravity. */
static void a_reduced_driven_joint_s_work_is_in_the_balance(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "driven_pendulum.xml",
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.1\""
        " inertia_zz=\"0.05\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.5\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"1\" motion_type=\"R\""
        " val_type=\"D\" expr=\"SIN(3*TIME)\"/>\n"
        "</Model></MotionSolve>\n");
    assert_work_in_the_balance(path, 2.0);
}

/* A Motion_Joint in acceleration on a revolute between two moving links (the second
 * hinged at the first's tip, the first on a revolute to ground): the joint follows the
 * displacement and velocity states integrated from 3 SIN(2 TIME), and the row's power is
 * lambda v, v the velocity state G u is held to. */
static void an_acceleration_row_s_work_is_in_the_balance(void **state)
{
    (void)state;
    const char *path = test_write_file(
        "accelerated_links.xml",
        "<MotionSolve><Model>\n"
        "<Force_Gravity grav_x=\"0\" grav_y=\"-9.81\" grav_z=\"0\"/>\n"
        "<Body_Ground id=\"1\"/>\n"
        "<Reference_Marker id=\"10\" body_id=\"1\"/>\n"
        "<Body_Rigid id=\"2\" cg_id=\"20\" mass=\"2\" inertia_xx=\"0.1\" inertia_yy=\"0.3\""
        " inertia_zz=\"0.3\"/>\n"
        "<Reference_Marker id=\"20\" body_id=\"2\" pos_x=\"0.4\"/>\n"
        "<Reference_Marker id=\"21\" body_id=\"2\"/>\n"
        "<Reference_Marker id=\"22\" body_id=\"2\" pos_x=\"0.8\"/>\n"
        "<Body_Rigid id=\"3\" cg_id=\"30\" mass=\"0.7\" inertia_xx=\"0.02\" inertia_yy=\"0.03\""
        " inertia_zz=\"0.04\"/>\n"
        "<Reference_Marker id=\"30\" body_id=\"3\" pos_x=\"1.1\"/>\n"
        "<Reference_Marker id=\"31\" body_id=\"3\" pos_x=\"0.8\"/>\n"
        "<Constraint_Joint id=\"1\" type=\"REVOLUTE\" i_marker_id=\"21\" j_marker_id=\"10\"/>\n"
        "<Constraint_Joint id=\"2\" type=\"REVOLUTE\" i_marker_id=\"31\" j_marker_id=\"22\"/>\n"
        "<Motion_Joint id=\"1\" type=\"EXPRESSION\" joint_id=\"2\" val_type=\"A\""
        " expr=\"3*SIN(2*TIME)\"/>\n"
        "</Model></MotionSolve>\n");
    assert_work_in_the_balance(path, 2.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_energy_of_every_element_from_one_copy_of_the_frames),
        cmocka_unit_test(the_elastic_energy_does_not_depend_on_how_the_model_is_written),
        cmocka_unit_test(a_driven_row_s_work_is_in_the_balance),
        cmocka_unit_test(a_general_constraint_of_time_s_work_is_in_the_balance),
        cmocka_unit_test(a_reduced_driven_joint_s_work_is_in_the_balance),
        cmocka_unit_test(an_acceleration_row_s_work_is_in_the_balance),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
