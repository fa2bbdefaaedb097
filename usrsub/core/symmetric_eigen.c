/* The smallest eigenvalue of a scaled symmetric part, by cyclic Jacobi
 * rotations (flex_joint.h). Small (n <= 6) and only used
 * when a property file is read. */
#include <math.h>

#include "usrsub/core/flex_joint.h"

double usrsub_scaled_smallest_eigenvalue(const double *a, int n)
{
    double s[6], m[6][6] = {{0}};
    if (n < 1)
        return 0.0;
    if (n > 6)
        n = 6;
    for (int i = 0; i < n; ++i)
        s[i] = a[i + n * i] != 0.0 ? 1.0 / sqrt(fabs(a[i + n * i])) : 1.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            m[i][j] = 0.5 * (a[i + n * j] + a[j + n * i]) * s[i] * s[j];
    for (int sweep = 0; sweep < 60; ++sweep) {
        double off = 0.0, total = 0.0;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                total += m[i][j] * m[i][j];
                if (i != j)
                    off += m[i][j] * m[i][j];
            }
        if (off <= 1e-30 * total)
            break;
        for (int p = 0; p < n - 1; ++p)
            for (int q = p + 1; q < n; ++q) {
                if (m[p][q] == 0.0)
                    continue;
                /* the rotation that zeroes m[p][q] */
                const double theta = 0.5 * (m[q][q] - m[p][p]) / m[p][q];
                const double t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                const double c = 1.0 / sqrt(t * t + 1.0), sn = t * c;
                for (int k = 0; k < n; ++k) { /* columns p and q */
                    const double mkp = m[k][p], mkq = m[k][q];
                    m[k][p] = c * mkp - sn * mkq;
                    m[k][q] = sn * mkp + c * mkq;
                }
                for (int k = 0; k < n; ++k) { /* rows p and q */
                    const double mpk = m[p][k], mqk = m[q][k];
                    m[p][k] = c * mpk - sn * mqk;
                    m[q][k] = sn * mpk + c * mqk;
                }
            }
    }
    double smallest = m[0][0];
    for (int i = 1; i < n; ++i)
        smallest = fmin(smallest, m[i][i]);
    return smallest;
}
