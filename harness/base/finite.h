/* The harness's check that values are finite, on the bits (no branch per
 * value: an all-ones exponent plus one carries into the sign bit). */
#ifndef HX_BASE_FINITE_H
#define HX_BASE_FINITE_H

#include <stdint.h>
#include <string.h>

static inline int hx_all_finite(const double *v, int n)
{
    uint64_t carry = 0;
    for (int k = 0; k < n; ++k) {
        uint64_t bits;
        memcpy(&bits, &v[k], sizeof bits);
        carry |= (bits & 0x7ff0000000000000u) + 0x0010000000000000u;
    }
    return (carry >> 63) == 0;
}

#endif
