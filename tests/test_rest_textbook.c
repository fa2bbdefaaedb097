/*
 * The bushing's torque at rest with a host that splits psi and phi the
 * textbook way (textbook_host.h), with and without a guard near theta = 0:
 * against the bushing law at the exact projection angles, at tilts from 1e-15
 * to 1e-3 rad and with J turned arbitrarily in ground. The host's own
 * psi + phi is shown to be wrong there (by up to radians), so the test would
 * fail for a library that trusted it.
 */
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "rest_scenario.h"
#include "test_support.h"
#include "textbook_host.h"
#include "usrsub/solver_abi.h"

static void torque_is_right_whatever_the_split(void **state)
{
    (void)state;
    void *lib = dlopen(USRSUB_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    if (lib == NULL)
        fail_msg("%s", dlerror());
    usrsub_gfosub_fn *gfosub = (usrsub_gfosub_fn *)dlsym(lib, "ABM_BUSHING");
    usrsub_fiesub_fn *fiesub = (usrsub_fiesub_fn *)dlsym(lib, "ABM_BUSHING_FIELD");
    assert_non_null(gfosub);
    assert_non_null(fiesub);
    textbook_host h;
    memset(&h, 0, sizeof h);
    h.strings[0] = test_write_file("rest.gbs", rest_gbs);
    textbook_host_use(&h);
    double worst_host = 0.0, worst_torque = 0.0;
    int cases = 0;
    for (h.guard = 1; h.guard >= 0; --h.guard)
        for (int k = 0; k < 4; ++k)
            for (double tilt = 1e-15; tilt <= 1.001e-3; tilt *= 10.0) {
                double Rrel[9];
                rest_case(k, tilt, h.RJ, Rrel);
                rest_mul(h.RJ, Rrel, h.RI); /* I held in ground, rounded as a solver holds it */
                for (int i = 0; i < 3; ++i)
                    h.pI[i] = h.pJ[i] = 1.0 + i;
                double exact[3];
                rest_exact_angles(tilt, exact);
                /* the host's own split: psi + phi against the exact twist */
                double R[9], e[3];
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        R[3 * i + j] = h.RJ[i] * h.RI[j] + h.RJ[3 + i] * h.RI[3 + j] +
                                       h.RJ[6 + i] * h.RI[6 + j];
                textbook_euler313(&h, R, e);
                worst_host = fmax(worst_host, fabs(remainder(e[0] + e[2] - exact[2], 2 * M_PI)));
                /* the library through the host, and the law at the exact angles */
                int id = 7, npar = 3, flag = 0;
                double t = 0.0, par[3] = {20, 10, 1}, T[6];
                gfosub(&id, &t, par, &npar, &flag, &flag, T);
                int fid = 8, fnpar = 1;
                double fpar[1] = {1}, disp[6] = {0, 0, 0, exact[0], exact[1], exact[2]};
                double velo[6] = {0}, Tref[6], dfd[36], dfv[36];
                fiesub(&fid, &t, fpar, &fnpar, disp, velo, &flag, &flag, Tref, dfd, dfv);
                const double size = sqrt(Tref[3] * Tref[3] + Tref[4] * Tref[4] + Tref[5] * Tref[5]);
                for (int i = 3; i < 6; ++i)
                    worst_torque = fmax(worst_torque, fabs(T[i] - Tref[i]) / size);
                ++cases;
            }
    printf("%d cases: the textbook host's psi + phi is off by up to %.3g rad; the library's"
           " torque by %.3g relative\n", cases, worst_host, worst_torque);
    assert_true(worst_host > 1e-3); /* the host is as bad as described */
    assert_true(worst_torque < 1e-10);
    assert_int_equal(h.errors, 0);
    dlclose(lib);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(torque_is_right_whatever_the_split),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
