/* Flexible-joint forces and partials (flex_joint.h). */
#include "usrsub/core/flex_joint.h"

#include <stdlib.h>
#include <string.h>

/* Which 3x3 blocks of a 6x6 column-major matrix are not zero. */
static unsigned nonzero_blocks(const double *m)
{
    unsigned blocks = 0;
    for (int j = 0; j < 6; ++j)
        for (int i = 0; i < 6; ++i)
            if (m[i + 6 * j] != 0.0)
                blocks |= 1u << (2 * (i / 3) + j / 3);
    return blocks;
}

void usrsub_flex_joint_prepare(usrsub_flex_joint *j)
{
    j->k_blocks = nonzero_blocks(j->k);
    j->d_blocks = nonzero_blocks(j->d);
    for (int n = 0; n < 36; ++n) {
        j->minus_k[n] = -j->k[n];
        j->minus_d[n] = -j->d[n];
    }
    /* columns 0-2 act on translations, 3-5 on rotations (bits 0, 2: left blocks) */
    const unsigned left = 1u | 4u, right = 2u | 8u;
    j->uses_translation = ((j->k_blocks | j->d_blocks) & left) != 0;
    j->uses_rotation = ((j->k_blocks | j->d_blocks) & right) != 0;
    j->uses_velocity = j->d_blocks != 0;
    j->uses_twist = 0;
    for (int r = 0; r < 6; ++r)
        j->uses_twist |= j->k[r + 6 * 5] != 0.0;
}

/* F[rows] -= m[rows, columns] x[columns] for each non-zero 3x3 block. */
static void subtract_blocks(const double *m, unsigned blocks, const double x[6], double F[6])
{
    for (; blocks != 0; blocks &= blocks - 1) {
        const int b = __builtin_ctz(blocks);
        const int r = 3 * (b >> 1), c = 3 * (b & 1);
        for (int jj = 0; jj < 3; ++jj) {
            const double *column = m + 6 * (c + jj) + r;
            const double xj = x[c + jj];
            F[r] -= column[0] * xj;
            F[r + 1] -= column[1] * xj;
            F[r + 2] -= column[2] * xj;
        }
    }
}

void usrsub_flex_joint_force(const usrsub_flex_joint *j, const double d[6], const double v[6],
                             double F[6], double *dFdd, double *dFdv)
{
    memcpy(F, j->preload, 6 * sizeof(double));
    subtract_blocks(j->k, j->k_blocks, d, F);
    subtract_blocks(j->d, j->d_blocks, v, F);
    if (dFdd != NULL) {
        memcpy(dFdd, j->minus_k, 36 * sizeof(double));
        memcpy(dFdv, j->minus_d, 36 * sizeof(double));
    }
}

void usrsub_flex_joint_free(usrsub_flex_joint *j)
{
    free(j);
}
