/*
 * The entries' check that no NaN or infinity leaves the library, on the bits:
 * a chain of floating-point tests over 72 partials cost more than the limits
 * it guards. An all-ones exponent plus one carries into the sign bit.
 */
#ifndef USRSUB_FINITE_H
#define USRSUB_FINITE_H

#include <stdint.h>
#include <string.h>

/* 1 when v[0], v[stride], ..., v[(n-1) stride] are all finite. */
static inline int all_finite_strided(const double *v, int n, int stride)
{
    uint64_t carry = 0;
    for (int k = 0; k < n; ++k) {
        uint64_t bits;
        memcpy(&bits, &v[k * stride], sizeof bits);
        carry |= (bits & 0x7ff0000000000000u) + 0x0010000000000000u;
    }
    return (carry >> 63) == 0;
}

static inline int all_finite(const double *v, int n)
{
    return all_finite_strided(v, n, 1);
}

#endif
