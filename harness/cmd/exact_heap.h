/* Makes the C library's count of bytes in use exact for check's set-up
 * footprints (host/binding.c): glibc's per-thread cache keeps freed small
 * blocks, and its statistics count them as in use. */
#ifndef HX_CMD_EXACT_HEAP_H
#define HX_CMD_EXACT_HEAP_H

/* Re-executes the program with that cache off, once; returns (the count
 * then stays approximate) if that cannot be done. */
void hx_exact_heap_counts(char **argv);

#endif
