/*
 * The energy of a state (sim/dynamics/energy.h): the elastic energy of every
 * element from one copy of the frames, and its independence of how a model
 * is written.
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


int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_energy_of_every_element_from_one_copy_of_the_frames),
        cmocka_unit_test(the_elastic_energy_does_not_depend_on_how_the_model_is_written),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
