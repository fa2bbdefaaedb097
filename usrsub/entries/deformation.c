/* Deformation of the GFOSUB form through the host (deformation.h). */
#include "deformation.h"

#include <math.h>
#include <stdio.h>

#include "host.h"
#include "usrsub/core/rotation.h"
#include "usrsub/core/trig.h"

static int ask(const char *fnc, const int *ipar, int nsize, double *states, int expected,
               char *failed)
{
    if (__builtin_expect(usrsub_host_query_array(fnc, ipar, nsize, states, expected) == 0, 1))
        return 0;
    snprintf(failed, 64, "%s(%d,%d%s)", fnc, ipar[0], ipar[1],
             nsize == 3 ? ",J" : nsize == 4 ? ",J,J" : "");
    return -1;
}

/* The rotation from the host's Euler angles; near rest phi from AZ. */
static int rotation_of(const int ipar[4], int twist, double euler[3], double R[9], char *failed)
{
    if (twist) { /* only an element whose force follows the twist needs phi at rest */
        double st, ct;
        usrsub_sincos(euler[1], &st, &ct);
        if (fabs(st) < USRSUB_REST_TILT) {
            double az;
            if (usrsub_host_query_value("AZ", ipar, 2, &az) != 0) {
                snprintf(failed, 64, "AZ(%d,%d)", ipar[0], ipar[1]);
                return -1;
            }
            euler[2] = usrsub_rest_phi(euler[0], ct, az);
        }
    }
    usrsub_euler313_rotation(euler, R);
    return 0;
}

int usrsub_deformation_measure(int i_marker, int j_marker, usrsub_deformation_needs needs, double d[6],
                        double v[6], double *R, char *failed)
{
    const int ipar[4] = {i_marker, j_marker, j_marker, j_marker};
    double s[6], rotation[9];
    double *Rot = R != NULL ? R : rotation;
    if (needs.translation && needs.rotation) {
        if (ask("DISP", ipar, 3, s, 6, failed) != 0 || rotation_of(ipar, needs.twist, s + 3, Rot, failed) != 0)
            return -1;
        d[0] = s[0], d[1] = s[1], d[2] = s[2];
        usrsub_projection_angles(Rot, d + 3);
    } else if (needs.translation) {
        if (ask("TDISP", ipar, 3, d, 3, failed) != 0)
            return -1;
    } else if (needs.rotation) {
        if (ask("RDISP", ipar, 2, s, 3, failed) != 0 || rotation_of(ipar, needs.twist, s, Rot, failed) != 0)
            return -1;
        usrsub_projection_angles(Rot, d + 3);
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
