/* Reading a USER(...) list value by value (user_list.h). */
#include "usrsub/readers/user_list.h"

#include <math.h>

void usrsub_user_list_init(usrsub_user_list *u, const double *par, int npar, int offset)
{
    u->par = par;
    u->npar = npar < 0 ? 0 : npar;
    u->next = 0;
    u->offset = offset;
}

static int take(usrsub_user_list *u, const char *what, double *value, usrsub_message *msg)
{
    *value = 0.0;
    if (u->next >= u->npar)
        return usrsub_fail(msg, "the USER list ends after %d values: expected %s at USER"
                           " parameter %d", u->npar + u->offset, what,
                           u->npar + u->offset + 1);
    *value = u->par[u->next++];
    if (!isfinite(*value))
        return usrsub_fail(msg, "USER parameter %d (par[%d]) is %g: expected %s, a finite"
                           " number", u->next + u->offset, u->next - 1, *value, what);
    return 0;
}

int usrsub_user_list_real(usrsub_user_list *u, const char *what, double *value,
                          usrsub_message *msg)
{
    return take(u, what, value, msg);
}

int usrsub_user_list_int(usrsub_user_list *u, const char *what, int lo, int hi, int *value,
                         usrsub_message *msg)
{
    double v = 0.0;
    if (take(u, what, &v, msg) != 0)
        return -1;
    if (v != floor(v) || v < (double)lo || v > (double)hi)
        return usrsub_fail(msg, "USER parameter %d (par[%d]) is %g: expected %s, an integer"
                           " from %d to %d", u->next + u->offset, u->next - 1, v, what, lo,
                           hi);
    *value = (int)v;
    return 0;
}

int usrsub_user_list_end(const usrsub_user_list *u, const char *what, usrsub_message *msg)
{
    if (u->next < u->npar)
        return usrsub_fail(msg, "USER parameter %d (par[%d]) = %g is one too many: %s"
                           " ends at USER parameter %d", u->next + u->offset + 1, u->next,
                           u->par[u->next], what, u->next + u->offset);
    return 0;
}
