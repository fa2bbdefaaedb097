/* The accelerations of markers (acceleration_measures.h). */
#include "frames/acceleration_measures.h"

#include "base/vecmath.h"

void hx_point_acceleration(const hx_frame *body, const double body_acc[6], const double p[3],
                           double out[6])
{
    /* a_P = a_O + alpha x r + w x (w x r), r from the body frame's origin O to P */
    double r[3], t[3], wr[3];
    v3_sub(r, p, body->p);
    v3_copy(out, body_acc);
    v3_cross(t, body_acc + 3, r);
    v3_add(out, out, t);
    v3_cross(wr, body->w, r);
    v3_cross(t, body->w, wr);
    v3_add(out, out, t);
    v3_copy(out + 3, body_acc + 3);
}

double hx_acceleration_value(hx_acceleration_measure m, const hx_frame *const f[4],
                             const double *const a[4])
{
    const int magnitude = m == HX_ACC_M || m == HX_WDT_M;
    const hx_frame *I = f[0], *J = f[1], *K = f[2], *L = magnitude ? f[2] : f[3];
    const double *aI = a[0], *aJ = a[1], *aL = magnitude ? a[2] : a[3];
    double out[3], t[3];
    if (m >= HX_WDT_X) {
        double dw[3];
        v3_sub(dw, I->w, J->w);
        v3_sub(out, aI + 3, aJ + 3);
        v3_cross(t, L->w, dw);
        v3_sub(out, out, t);
    } else {
        double r[3], rdot[3], wr[3];
        v3_sub(r, I->p, J->p);
        v3_sub(rdot, I->v, J->v);
        v3_sub(out, aI, aJ);
        v3_cross(t, aL + 3, r);
        v3_sub(out, out, t);
        v3_cross(t, L->w, rdot);
        v3_axpy(out, -2.0, t);
        v3_cross(wr, L->w, r);
        v3_cross(t, L->w, wr);
        v3_add(out, out, t);
    }
    if (magnitude)
        return v3_norm(out);
    double in_k[3];
    m3_tapply(in_k, K->R, out);
    return in_k[m >= HX_WDT_X ? m - HX_WDT_X : m - HX_ACC_X];
}
