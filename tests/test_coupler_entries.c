/*
 * COUSUB, COUXX, COUXX2 loaded through dlopen with the harness as the host:
 * values, the full column-major COUXX2 matrix, an input error reported once
 * through c_errmes (element id and parameter named, zeros out), a rebuilt
 * element when its USER list changes, and non-finite or odd arguments.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "host/loader.h"
#include "sim_support.h"
#include "test_support.h"
#include "usrsub/core/spline.h"

static hx_loader loader;
static usrsub_coupler_fn *cousub, *couxx, *couxx2;
static host_model host;

static int load(void **state)
{
    (void)state;
    hx_message msg;
    char bound[HX_ENTRY_NAME_MAX];
    void *lib = hx_loader_open(&loader, USRSUB_LIBRARY, &msg);
    assert_non_null(lib);
    cousub = (usrsub_coupler_fn *)hx_loader_entry(lib, USRSUB_LIBRARY, "COUSUB", bound, sizeof bound, &msg);
    couxx = (usrsub_coupler_fn *)hx_loader_entry(lib, USRSUB_LIBRARY, "COUXX", bound, sizeof bound, &msg);
    couxx2 = (usrsub_coupler_fn *)hx_loader_entry(lib, USRSUB_LIBRARY, "COUXX2", bound, sizeof bound, &msg);
    const char *table = test_write_file("steer.tbl", "-1 -2\n0 0\n1 2.5\n2 4\n");
    char xml[1024];
    snprintf(xml, sizeof xml,
             "<MotionSolve><Model><Body_Ground id=\"1\"/>"
             "<Reference_String id=\"100\" string=\"%s\"/></Model></MotionSolve>", table);
    host_model_attach(&host, "strings.xml", xml);
    host.messages.stream = NULL;
    return 0;
}

static int unload(void **state)
{
    (void)state;
    host_model_detach(&host);
    hx_loader_close_all(&loader);
    return 0;
}

static void call(usrsub_coupler_fn *fn, int id, const double *par, int npar, const double *disp,
                 int ndisp, int iflag, double *out)
{
    int i = id, np = npar, nd = ndisp, fl = iflag;
    double t = 0.0, p[64], d[3];
    memcpy(p, par, sizeof(double) * (size_t)npar);
    memcpy(d, disp, sizeof(double) * (size_t)(ndisp < 3 ? ndisp : 3));
    fn(&i, &t, p, &np, d, &nd, &fl, out);
}

static void values_and_full_hessian(void **state)
{
    (void)state;
    hx_messages_reset(&host.messages);
    /* 2 M1 + (1 + M2^2) + table(M3), the table (Reference_String 100) at M3 = 0.5 */
    const double par[] = {1, 2, 2, 2, 1, 0, 1, 4, 100, 1.0};
    const double disp[3] = {0.25, -3.0, 0.5};
    double phi, g[3], H[9];
    for (int k = 0; k < 9; ++k)
        H[k] = 99.0;
    hx_call record;
    hx_call_init(&record, "coupler", 3, "COUSUB", host.model, &host.frames, &host.messages, 1, NULL);
    hx_host_bind(&record);
    call(cousub, 3, par, 10, disp, 3, 1, &phi); /* dependency pass: no queries */
    hx_host_bind(&host.call);
    assert_int_equal(record.host_calls, 0);
    call(cousub, 3, par, 10, disp, 3, 0, &phi);
    call(couxx, 3, par, 10, disp, 3, 0, g);
    call(couxx2, 3, par, 10, disp, 3, 0, H);
    assert_int_equal(host.messages.errors, 0);
    assert_close(g[0], 2.0, 0, 0);
    assert_close(g[1], -6.0, 0, 1e-14);
    /* full 3x3, column-major: diagonal G'' and zeros elsewhere */
    assert_close(H[0], 0.0, 0, 0);
    assert_close(H[4], 2.0, 0, 1e-14);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (i != j)
                assert_close(H[i + 3 * j], 0.0, 0, 0);
    /* the table part agrees with differences of COUSUB */
    const double h = 1e-6;
    double plus[3] = {0.25, -3.0, 0.5 + h}, minus[3] = {0.25, -3.0, 0.5 - h}, fp, fm;
    call(cousub, 3, par, 10, plus, 3, 0, &fp);
    call(cousub, 3, par, 10, minus, 3, 0, &fm);
    assert_close(g[2], (fp - fm) / (2 * h), 1e-8, 1e-8);
    usrsub_spline table;
    const double tx[] = {-1, 0, 1, 2}, ty[] = {-2, 0, 2.5, 4};
    assert_int_equal(usrsub_spline_init(&table, 4, tx, ty, NULL), 0);
    assert_close(phi, 0.5 + 10.0 + usrsub_spline_eval(&table, 0.5).value, 1e-15, 1e-15);
    usrsub_spline_free(&table);
}

static void input_error_reported_once_with_zeros(void **state)
{
    (void)state;
    hx_messages_reset(&host.messages);
    const double bad[] = {1, 1, 2, 9, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    const double disp[2] = {0.1, 0.2};
    double phi = 123.0, g[2] = {5, 5}, H[4] = {5, 5, 5, 5};
    call(cousub, 7, bad, 13, disp, 2, 0, &phi);
    assert_int_equal(host.messages.errors, 1);
    assert_contains(host.messages.last_error, "COUSUB element 7", "term 2 (code 2)", "par[3]) is 9",
                    "0 to 6");
    assert_true(host.messages.stop); /* reported with "STOP" */
    assert_close(phi, 0.0, 0, 0);
    call(couxx, 7, bad, 13, disp, 2, 0, g);
    call(couxx2, 7, bad, 13, disp, 2, 0, H);
    assert_int_equal(host.messages.errors, 1); /* once per element, not per call */
    for (int k = 0; k < 2; ++k)
        assert_close(g[k], 0.0, 0, 0);
    for (int k = 0; k < 4; ++k)
        assert_close(H[k], 0.0, 0, 0);
    /* the element's list is corrected: it is rebuilt and evaluates */
    const double good[] = {1, 1, 1, 3};
    call(cousub, 7, good, 4, disp, 2, 0, &phi);
    assert_close(phi, 0.1 + 0.6, 0, 1e-15);
    assert_int_equal(host.messages.errors, 1);
    hx_messages_reset(&host.messages);
}

static void non_finite_displacement_gives_zeros_and_an_error(void **state)
{
    (void)state;
    hx_messages_reset(&host.messages);
    const double par[] = {1, 1, 1, 3};
    const double disp[2] = {0.1, NAN};
    double phi = 1.0, g[2] = {1, 1};
    call(cousub, 8, par, 4, disp, 2, 0, &phi);
    assert_close(phi, 0.0, 0, 0);
    assert_contains(host.messages.last_error, "COUSUB element 8", "disp[1]", "must be finite");
    call(couxx, 8, par, 4, disp, 2, 0, g);
    assert_close(g[0], 0.0, 0, 0);
    assert_close(g[1], 0.0, 0, 0);
    assert_int_equal(host.messages.errors, 2);
    const double inf[2] = {INFINITY, 0.0};
    double H[4] = {1, 1, 1, 1};
    call(couxx2, 8, par, 4, inf, 2, 0, H);
    for (int k = 0; k < 4; ++k)
        assert_close(H[k], 0.0, 0, 0);
    assert_contains(host.messages.last_error, "COUXX2 element 8", "disp[0]");
    hx_messages_reset(&host.messages);
}

static void ndisp_outside_two_to_three(void **state)
{
    (void)state;
    hx_messages_reset(&host.messages);
    const double par[] = {1, 1, 1, 1, 1, 1, 1, 1};
    const double disp[3] = {1, 2, 3};
    double phi = 5.0;
    call(cousub, 9, par, 8, disp, 4, 0, &phi);
    assert_close(phi, 0.0, 0, 0);
    assert_contains(host.messages.last_error, "COUSUB element 9", "ndisp is 4");
    hx_messages_reset(&host.messages);
}

static void missing_arguments_do_not_crash(void **state)
{
    (void)state;
    hx_messages_reset(&host.messages);
    double phi = 2.0, t = 0.0, disp[2] = {0, 0};
    int nd = 2, np = 2, flag = 0, id = 4;
    double par[2] = {1, 1};
    cousub(NULL, &t, par, &np, disp, &nd, &flag, &phi);
    assert_close(phi, 0.0, 0, 0);
    cousub(&id, &t, NULL, &np, disp, &nd, &flag, &phi);
    cousub(&id, &t, par, &np, NULL, &nd, &flag, &phi);
    cousub(&id, &t, par, &np, disp, &nd, &flag, NULL);
    int negative = -3;
    cousub(&id, &t, par, &negative, disp, &nd, &flag, &phi);
    assert_int_equal(host.messages.errors, 4);
    assert_contains(host.messages.last_error, "element 4", "negative npar");
    hx_messages_reset(&host.messages);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(values_and_full_hessian),
        cmocka_unit_test(input_error_reported_once_with_zeros),
        cmocka_unit_test(non_finite_displacement_gives_zeros_and_an_error),
        cmocka_unit_test(ndisp_outside_two_to_three),
        cmocka_unit_test(missing_arguments_do_not_crash),
    };
    return cmocka_run_group_tests(tests, load, unload);
}
