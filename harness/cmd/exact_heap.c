/* See exact_heap.h. The cache can only be turned off when the process starts
 * (a glibc tunable read from the environment), hence the re-execution. */
#include "cmd/exact_heap.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define TCACHE_OFF "glibc.malloc.tcache_count=0"

void hx_exact_heap_counts(char **argv)
{
    const char *was = getenv("GLIBC_TUNABLES");
    if (was != NULL && strstr(was, TCACHE_OFF) != NULL)
        return; /* already re-executed, or set by the user */
    char tunables[1024];
    const int n = was != NULL && *was != '\0'
                      ? snprintf(tunables, sizeof tunables, "%s:%s", was, TCACHE_OFF)
                      : snprintf(tunables, sizeof tunables, "%s", TCACHE_OFF);
    if (n < 0 || (size_t)n >= sizeof tunables || setenv("GLIBC_TUNABLES", tunables, 1) != 0)
        return;
    execv("/proc/self/exe", argv);
    /* not re-executed: put the environment back and go on */
    if (was != NULL)
        setenv("GLIBC_TUNABLES", was, 1);
    else
        unsetenv("GLIBC_TUNABLES");
}
