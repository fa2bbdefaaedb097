/* How a stage of an evaluation fails (failure.h). */
#include "sim/dynamics/failure.h"

#include <stdarg.h>
#include <stdio.h>

#include "base/finite.h"

int hx_dynamics_fail(hx_dynamics_data *dd, const char *fmt, ...)
{
    if (!dd->failed) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(dd->message, sizeof dd->message, fmt, ap);
        va_end(ap);
        dd->failed = 1;
    }
    return -1;
}

int hx_dynamics_check_call(const hx_dynamics *d, hx_dynamics_data *dd, const hx_binding *b,
                           const double *out, int n, const char *what, double t)
{
    if (hx_messages_stopped(&d->s->messages))
        return hx_dynamics_fail(dd, "%s %d stopped the run (c_errmes STOP) at t = %g: %s",
                                b->element, b->id, t, d->s->messages.stop_message);
    if (n > 0 && !hx_all_finite(out, n))
        return hx_dynamics_fail(dd, "%s %d (%s) returned a non-finite %s at t = %g", b->element,
                                b->id, hx_binding_routine(b, 0), what, t);
    return 0;
}
