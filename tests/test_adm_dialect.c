/*
 * Datasets in the form Adams/View exports them (docs/interface.md §9.3):
 * a title naming the model, banner comments, UNITS/ and ACCGRAV/ with their
 * arguments on continuation lines, ids with leading zeros (0102 is 102),
 * parts placed by QG and turned by REULER in degrees, markers turned again
 * inside them, FLOATING markers, IP with six values, initial velocities,
 * GRAPHICS, REQUEST with F2=..\F3=.. and C=, OUTPUT: read into the model
 * the harness simulates, every frame worked by hand below.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "model/model.h"
#include "test_support.h"

static const char dataset[] =
    "ADAMS/View model name: dialect\n"
    "!\n"
    "!-------------------------------- SYSTEM UNITS ---------------------------------\n"
    "!\n"
    "UNITS/\n"
    ", FORCE = NEWTON\n"
    ", MASS = KILOGRAM\n"
    ", LENGTH = METER\n"
    ", TIME = SECOND\n"
    "!\n"
    "!----------------------------------- PARTS -------------------------------------\n"
    "PART/01, GROUND\n"
    "!                       World Coordinate System Marker\n"
    "MARKER/0101, PART = 01\n"
    "!\t\t\t(-45 deg rotation about the X axis)\n"
    "MARKER/0102, PART = 01\n"
    ", QP = 1, 2, 3\n"
    ", REULER = 180D, 45D, 180D\n"
    "MARKER/0104, PART = 01, FLOATING\n"
    "!\n"
    "GRAPHICS/0101\n"
    ", CYLINDER\n"
    ", CM = 0102\n"
    ", LENGTH = .8\n"
    ", RADIUS = 0.05\n"
    "!\n"
    "PART/02\n"
    ", MASS = 2\n"
    ", CM = 0201\n"
    ", IP = 4, 5, 6, 0.5, 0.25, -0.75\n"
    ", QG = 1, 2, 3\n"
    ", REULER = 90D, 90D, 0D\n"
    ", VX = 1, VY = 2, VZ = 3\n"
    ", WX = 0.1, WY = 0.2, WZ = 0.3\n"
    "MARKER/0201, PART = 02\n"
    "MARKER/0202, PART = 02\n"
    ", QP = 0, 0, 1\n"
    ", REULER = 90D, 0D, 0D\n"
    "PART/03, MASS = 1, CM = 0301, IP = 1, 1, 1, VM = 0102, VY = 2\n"
    "MARKER/0301, PART = 03, QP = 5, 0, 0\n"
    "!\n"
    "GFORCE/1\n"
    ", I = 0202\n"
    ", JFLOAT = 0104\n"
    ", RM = 0102\n"
    ", FUNCTION = USER(1, 0202, 0104)\n"
    ", ROUTINE = libusrsub.so::\n"
    "!\n"
    "ACCGRAV/\n"
    ", KGRAV = -9.80665\n"
    "!\n"
    "REQUEST/01, D,I=0201,J=0101,C=DISPLACEMENT: X Y Z PSI THETA PHI (body-fixed-3-1-3)\n"
    "REQUEST/04, F2=ORIENT(27,1,0201,0101)\\F3=ORIENT(27,2,0201,0101)\\F4=ORIENT(27,3,0201,0101)"
    ",C=EULER PARAMETERS\n"
    "OUTPUT/\n"
    ", REQSAVE\n"
    "!RESULTS/\n"
    "!, XRF\n"
    "END\n";

static const hx_marker *marker(const hx_model *m, int id)
{
    const int k = hx_model_marker(m, id);
    if (k < 0)
        fail_msg("no marker %d", id);
    return &m->markers[k];
}

static void assert_frame(const hx_marker *mk, const double p[3], const double R[9])
{
    for (int k = 0; k < 3; ++k)
        assert_close(mk->pos0[k], p[k], 0.0, 1e-15);
    for (int k = 0; k < 9; ++k)
        assert_close(mk->R0[k], R[k], 0.0, 1e-15);
}

static hx_model *read_dataset(void)
{
    hx_message msg;
    hx_model *m = hx_model_read(test_write_file("dialect.adm", dataset), NULL, &msg);
    if (m == NULL)
        fail_msg("%s", msg.text);
    return m;
}

static void frames_worked_by_hand(void **state)
{
    (void)state;
    hx_model *m = read_dataset();
    const double c = sqrt(0.5);
    /* 0102: Rz(180) Rx(45) Rz(180) = Rx(-45): x (1,0,0), y (0,c,-s), z (0,s,c)
     * (rows of R below; columns are the axes) */
    const double p102[3] = {1, 2, 3}, R102[9] = {1, 0, 0, 0, c, c, 0, -c, c};
    assert_frame(marker(m, 102), p102, R102);
    /* part 02: QG (1,2,3), Rz(90) Rx(90) Rz(0): its x along the world's y, y along z,
     * z along x; its CM marker 0201 is its frame */
    const double p201[3] = {1, 2, 3}, R201[9] = {0, 0, 1, 1, 0, 0, 0, 1, 0};
    assert_frame(marker(m, 201), p201, R201);
    /* 0202: QP (0,0,1) along the part's z, the world's x: at (2,2,3); turned by
     * Rz(90) inside the part: its x along the part's y (the world's z), its y along the
     * part's -x (the world's -y), its z along the part's z (the world's x) */
    const double p202[3] = {2, 2, 3}, R202[9] = {0, 0, 1, 0, -1, 0, 1, 0, 0};
    assert_frame(marker(m, 202), p202, R202);
    /* the FLOATING 0104 on ground, floated by GFORCE/1: at its I (0202), with its
     * RM's (0102) axes */
    assert_frame(marker(m, 104), p202, R102);
    assert_int_equal(m->bodies[marker(m, 104)->body].is_ground, 1);
    hx_model_free(m);
}

static void inertia_velocities_and_elements(void **state)
{
    (void)state;
    hx_model *m = read_dataset();
    assert_int_equal(m->nbodies, 3);
    assert_int_equal(m->nunsimulated, 0);
    const hx_body *b = &m->bodies[hx_model_body(m, 2)];
    /* IP = xx, yy, zz, xy, xz, yz, the products positive integrals: the tensor is
     * [[4, -0.5, -0.25], [-0.5, 5, 0.75], [-0.25, 0.75, 6]] about the CM in its axes */
    const double I[9] = {4, -0.5, -0.25, -0.5, 5, 0.75, -0.25, 0.75, 6};
    for (int k = 0; k < 9; ++k)
        assert_close(b->inertia[k], I[k], 0.0, 1e-15);
    /* VX..VZ along the ground's axes; WX..WZ about the CM marker's:
     * 0.1 x_p + 0.2 y_p + 0.3 z_p = 0.1 (0,1,0) + 0.2 (0,0,1) + 0.3 (1,0,0) */
    const double v[3] = {1, 2, 3}, w[3] = {0.3, 0.1, 0.2};
    for (int k = 0; k < 3; ++k) {
        assert_close(b->v0[k], v[k], 0.0, 1e-15);
        assert_close(b->w0[k], w[k], 0.0, 1e-15);
    }
    /* part 03: VY=2 along VM 0102's y axis (0, c, -c) */
    const hx_body *b3 = &m->bodies[hx_model_body(m, 3)];
    assert_close(b3->v0[0], 0.0, 0.0, 1e-15);
    assert_close(b3->v0[1], sqrt(2.0), 0.0, 1e-15);
    assert_close(b3->v0[2], -sqrt(2.0), 0.0, 1e-15);
    assert_close(m->gravity[2], -9.80665, 0, 0);
    assert_int_equal(m->has_units, 1);
    /* GFORCE/1: a GFOSUB with its USER list, J the floating marker, in 0102's axes */
    assert_int_equal(m->nforces, 1);
    const hx_force *f = &m->forces[0];
    assert_int_equal(f->interface, HX_FORCE_GFOSUB);
    assert_int_equal(f->part, HX_OUTPUT_FORCE_AND_TORQUE);
    assert_int_equal(m->markers[f->j_marker].id, 104);
    assert_int_equal(m->markers[f->ref_marker].id, 102);
    assert_string_equal(f->user.dll_name, "libusrsub.so");
    assert_null(f->user.fnc_name);
    assert_int_equal(f->user.npar, 3);
    assert_close(f->user.par[1], 202.0, 0, 0);
    /* REQUESTs without a routine and GRAPHICS produce output only */
    assert_int_equal(m->nroutines, 0);
    hx_model_free(m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(frames_worked_by_hand),
        cmocka_unit_test(inertia_velocities_and_elements),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
