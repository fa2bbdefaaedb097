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
static inline int usrsub_finite_all_strided(const double *v, int n, int stride)
{
    uint64_t carry = 0;
    for (int k = 0; k < n; ++k) {
        uint64_t bits;
        memcpy(&bits, &v[k * stride], sizeof bits);
        carry |= (bits & 0x7ff0000000000000u) + 0x0010000000000000u;
    }
    return (carry >> 63) == 0;
}

/* The same over contiguous values, two lanes at a time (SSE2, in every
 * x86-64): the 72 partials of a FIESUB call in 36 steps. */
static inline int usrsub_finite_all(const double *v, int n)
{
    typedef uint64_t lanes __attribute__((vector_size(16)));
    const lanes exponent = {0x7ff0000000000000u, 0x7ff0000000000000u};
    const lanes unit = {0x0010000000000000u, 0x0010000000000000u};
    lanes carry = {0, 0};
    int k = 0;
    for (; k + 2 <= n; k += 2) {
        lanes bits;
        memcpy(&bits, v + k, sizeof bits);
        carry |= (bits & exponent) + unit;
    }
    const uint64_t tail = k < n ? !usrsub_finite_all_strided(v + k, n - k, 1) : 0;
    return ((carry[0] | carry[1]) >> 63 | tail) == 0;
}

#endif
