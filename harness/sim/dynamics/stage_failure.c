/* How a stage of an evaluation fails (stage_failure.h). */
#include "sim/dynamics/stage_failure.h"

#include <stdarg.h>
#include <stdio.h>

int hx_dynamics_fail(hx_dynamics *d, const char *fmt, ...)
{
    if (!d->failed) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(d->message, sizeof d->message, fmt, ap);
        va_end(ap);
        d->failed = 1;
    }
    return -1;
}

int hx_dynamics_check_stop(hx_dynamics *d, const hx_binding *b)
{
    if (hx_messages_stopped(&d->s->messages))
        return hx_dynamics_fail(d, "%s %d stopped the run (c_errmes STOP) at t = %g: %s",
                                b->element, b->id, d->frames.time, d->s->messages.stop_message);
    return 0;
}
