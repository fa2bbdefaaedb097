/* Wall-clock seconds for the harness's timings (CLOCK_MONOTONIC). */
#ifndef HX_BASE_CLOCK_H
#define HX_BASE_CLOCK_H

#include <time.h>

static inline double hx_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#endif
