/* Bushings built by hand for the tests (bushing_support.h). */
#include "bushing_support.h"

#include <string.h>

#include "test_support.h"

void bushing_init(usrsub_bushing *b, int coupling)
{
    memset(b, 0, sizeof *b);
    b->coupling = coupling;
    b->group_epsilon[0] = b->group_epsilon[1] = 1e-9;
    for (int k = 0; k < 6; ++k)
        b->dir[k].disp_scale = b->dir[k].force_scale = 1.0;
}

void bushing_cubic(usrsub_bushing *b, int k, double k1, double k3)
{
    usrsub_cubic_characteristic *c = &b->dir[k].cubic;
    b->dir[k].stiffness = USRSUB_STIFFNESS_CUBIC;
    c->o = 0.0, c->of = 0.0, c->os = k1;
    c->rp = 5.0, c->rpf = 5.0 * k1 + 125.0 * k3, c->ep = 10.0, c->eps = k1 + 300.0 * k3;
    c->rn = -5.0, c->rnf = -c->rpf, c->en = -10.0, c->ens = c->eps;
    usrsub_message msg;
    if (usrsub_cubic_fit(c, &msg) != 0)
        fail_msg("%s", msg.text);
}

void bushing_constant(usrsub_bushing *b, int k, double K)
{
    b->dir[k].stiffness = USRSUB_STIFFNESS_CONSTANT;
    b->dir[k].k = K;
}

void bushing_spline(usrsub_bushing *b, int k, int n, const double *x, const double *y)
{
    b->dir[k].stiffness = USRSUB_STIFFNESS_SPLINE;
    usrsub_message msg;
    if (usrsub_spline_init(&b->dir[k].spline, n, x, y, &msg) != 0)
        fail_msg("%s", msg.text);
}

void bushing_damping(usrsub_bushing *b, int k, double C)
{
    b->dir[k].damped = 1;
    b->dir[k].c = C;
}

void bushing_release(usrsub_bushing *b)
{
    for (int k = 0; k < 6; ++k)
        if (b->dir[k].spline.x != NULL)
            usrsub_spline_free(&b->dir[k].spline);
}
