/*
 * Uniform B-splines of order k (degree k - 1) over control points, as
 * Adams' CURVE statement defines its curves (docs/interface.md §8.4): open
 * (clamped knots: the curve starts at the first control point and ends at
 * the last) or closed (periodic knots: the last control point repeats the
 * first, and the curve closes with continuous derivatives). The parameter u
 * runs over [0, 1] along the whole curve.
 */
#ifndef HX_BASE_BSPLINE_H
#define HX_BASE_BSPLINE_H

#define HX_BSPLINE_MAX_ORDER 8

/* The basis at u (in [0, 1]; a closed curve wraps it, an open one is the
 * caller's to keep inside) for n control points of order k: the k basis
 * functions that do not vanish there and their first three derivatives in u
 * into basis[d][i] (d = 0 .. 3), the i-th for control point (first + i)
 * (modulo n - 1 when closed). 2 <= k <= HX_BSPLINE_MAX_ORDER; open: n >= k;
 * closed: n - 1 >= k. A closed curve of odd order starts half a knot span
 * on (u = 0 at the middle of its first span). */
void hx_bspline_basis(int k, int n, int closed, double u, double basis[4][HX_BSPLINE_MAX_ORDER],
                      int *first);

/* The parameters at which an interpolating curve passes through n points:
 * the knots' Greville abscissae (open), or j / (n - 1) (closed: the knots of
 * an even order, the spans' middles of an odd one); into u[0 .. n - 1]. */
void hx_bspline_sites(int k, int n, int closed, double *u);

#endif
