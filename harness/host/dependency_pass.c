/* The dependency pass of every element (dependency_pass.h). */
#include "host/dependency_pass.h"

#include <malloc.h>
#include <stdlib.h>

#include "base/finite.h"
#include "host/element_call.h"

/* Bytes in use in the C library's allocator (mallinfo2: small blocks and
 * mmap'd ones); sanitizers bring their own allocator and answer 0. Exact when
 * glibc's per-thread cache is off (the check command sees to it,
 * cmd/exact_heap.h); otherwise freed small blocks it holds count too. */
static long allocated_bytes(void)
{
    const struct mallinfo2 info = mallinfo2();
    return (long)(info.uordblks + info.hblkhd);
}

int hx_dependency_passes(hx_bindings *bs, const hx_frames *fr)
{
    int size = 1;
    for (int k = 0; k < bs->count; ++k) {
        const int n = hx_element_call_input_count(&bs->items[k]) +
                      hx_element_call_output_count(&bs->items[k]);
        size = n > size ? n : size;
    }
    /* before the first pass: the footprints are the library's alone */
    double *work = malloc(sizeof(double) * (size_t)size);
    if (work == NULL)
        return -1;
    for (int k = 0; k < bs->count; ++k) {
        hx_binding *b = &bs->items[k];
        double *in = work, *out = work + hx_element_call_input_count(b);
        hx_element_call_inputs(b, fr, NULL, in);
        const long before = allocated_bytes();
        const int nout = hx_element_call(b, fr, in, 1, 0, out);
        const long after = allocated_bytes();
        b->setup_bytes = before > 0 || after > 0 ? after - before : -1;
        /* a FIESUB asked without dflag leaves its partials: only its force counts */
        const int counted = b->kind == HX_BIND_FIELD ? 6 : nout;
        if (b->messages != NULL && !hx_all_finite(out, counted))
            hx_messages_host(b->messages, "note: %s %d (%s) returned a non-finite output in"
                             " its dependency pass (iflag set, where the state queries answer"
                             " zeros, as in a solver, which discards these outputs): not a fault",
                             b->element, b->id, hx_binding_routine(b, 0));
        if (b->messages != NULL && hx_messages_stopped(b->messages)) {
            free(work);
            return -1;
        }
    }
    free(work);
    return 0;
}
