/* The orientation systems of ORIENT (orientation_systems.h). */
#include "base/orientation_systems.h"

#include <stddef.h>

#define BODY(a, b, c, text) {HX_ORIENTATION_BODY, {a - 1, b - 1, c - 1}, 3, text}
#define SPACE(a, b, c, text) {HX_ORIENTATION_SPACE, {a - 1, b - 1, c - 1}, 3, text}

static const hx_orientation_system systems[HX_ORIENTATION_SYSTEMS] = {
    BODY(1, 2, 3, "body-fixed 1-2-3 Euler angles"),
    BODY(2, 3, 1, "body-fixed 2-3-1 Euler angles"),
    BODY(3, 1, 2, "body-fixed 3-1-2 Euler angles"),
    BODY(1, 3, 2, "body-fixed 1-3-2 Euler angles"),
    BODY(2, 1, 3, "body-fixed 2-1-3 Euler angles"),
    BODY(3, 2, 1, "body-fixed 3-2-1 Euler angles"),
    BODY(1, 2, 1, "body-fixed 1-2-1 Euler angles"),
    BODY(1, 3, 1, "body-fixed 1-3-1 Euler angles"),
    BODY(2, 1, 2, "body-fixed 2-1-2 Euler angles"),
    BODY(2, 3, 2, "body-fixed 2-3-2 Euler angles"),
    BODY(3, 1, 3, "body-fixed 3-1-3 Euler angles"),
    BODY(3, 2, 3, "body-fixed 3-2-3 Euler angles"),
    SPACE(1, 2, 3, "space-fixed 1-2-3 Euler angles"),
    SPACE(2, 3, 1, "space-fixed 2-3-1 Euler angles"),
    SPACE(3, 1, 2, "space-fixed 3-1-2 Euler angles"),
    SPACE(1, 3, 2, "space-fixed 1-3-2 Euler angles"),
    SPACE(2, 1, 3, "space-fixed 2-1-3 Euler angles"),
    SPACE(3, 2, 1, "space-fixed 3-2-1 Euler angles"),
    SPACE(1, 2, 1, "space-fixed 1-2-1 Euler angles"),
    SPACE(1, 3, 1, "space-fixed 1-3-1 Euler angles"),
    SPACE(2, 1, 2, "space-fixed 2-1-2 Euler angles"),
    SPACE(2, 3, 2, "space-fixed 2-3-2 Euler angles"),
    SPACE(3, 1, 3, "space-fixed 3-1-3 Euler angles"),
    SPACE(3, 2, 3, "space-fixed 3-2-3 Euler angles"),
    {HX_ORIENTATION_PROJECTION, {0, 0, 0}, 3, "the projection angles AX, AY, AZ"},
    {HX_ORIENTATION_YPR, {0, 0, 0}, 3, "YAW, PITCH, ROLL"},
    {HX_ORIENTATION_PARAMETERS, {0, 0, 0}, 4, "the Euler parameters e0, e1, e2, e3"},
    {HX_ORIENTATION_RODRIGUES, {0, 0, 0}, 3, "the Rodrigues parameters e1/e0, e2/e0, e3/e0"},
    {HX_ORIENTATION_COSINES, {0, 0, 0}, 9, "the direction cosines of I's axes in J's"},
};

const hx_orientation_system *hx_orientation_system_at(int system)
{
    return system >= 1 && system <= HX_ORIENTATION_SYSTEMS ? &systems[system - 1] : NULL;
}
