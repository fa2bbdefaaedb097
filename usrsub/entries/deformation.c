/* Deformation of the GFOSUB form through the host (deformation.h). */
#include "deformation.h"

#include <math.h>
#include <stdio.h>

#include "host.h"
#include "usrsub/core/trig.h"

void euler313_to_projection_angles(const double e[3], double a[3])
{
    double sp, cp, st, ct, sf, cf;
    usrsub_sincos(e[0], &sp, &cp);
    usrsub_sincos(e[1], &st, &ct);
    usrsub_sincos(e[2], &sf, &cf);
    /* R = Rz(psi) Rx(theta) Rz(phi); the columns are I's axes in J */
    const double r00 = cp * cf - sp * ct * sf, r10 = sp * cf + cp * ct * sf;
    const double r11 = -sp * sf + cp * ct * cf, r21 = st * cf;
    const double r02 = sp * st, r22 = ct;
    a[0] = usrsub_atan2(r21, r11); /* Y_I . Z_J, Y_I . Y_J */
    a[1] = usrsub_atan2(r02, r22); /* Z_I . X_J, Z_I . Z_J */
    a[2] = usrsub_atan2(r10, r00); /* X_I . Y_J, X_I . X_J */
}

static int ask(const char *fnc, const int *ipar, int nsize, double *states, int expected,
               char *failed)
{
    if (host_query_array(fnc, ipar, nsize, states, expected) == 0)
        return 0;
    snprintf(failed, 64, "%s(%d,%d%s)", fnc, ipar[0], ipar[1],
             nsize == 3 ? ",J" : nsize == 4 ? ",J,J" : "");
    return -1;
}

int measure_deformation(int i_marker, int j_marker, deformation_needs needs, double d[6],
                        double v[6], char *failed)
{
    const int ipar[4] = {i_marker, j_marker, j_marker, j_marker};
    double s[6];
    if (needs.translation && needs.rotation) {
        if (ask("DISP", ipar, 3, s, 6, failed) != 0)
            return -1;
        d[0] = s[0], d[1] = s[1], d[2] = s[2];
        euler313_to_projection_angles(s + 3, d + 3);
    } else if (needs.translation) {
        if (ask("TDISP", ipar, 3, d, 3, failed) != 0)
            return -1;
    } else if (needs.rotation) {
        if (ask("RDISP", ipar, 2, s, 3, failed) != 0)
            return -1;
        euler313_to_projection_angles(s, d + 3);
    }
    if (!needs.velocity)
        return 0;
    if (needs.translation && needs.rotation)
        return ask("VEL", ipar, 4, v, 6, failed);
    if (needs.translation)
        return ask("TVEL", ipar, 4, v, 3, failed);
    if (needs.rotation)
        return ask("RVEL", ipar, 3, v + 3, 3, failed);
    return 0;
}
