/*
 * Reference_Spline: its description, builder and data (spline_elements.h).
 * The form read is the one MotionSolve's pages show (docs/interface.md
 * §7.11): num_xy_pair, linear_extrap and the x y pairs between the tags.
 */
#include <math.h>
#include <stdlib.h>

#include "base/cubic_curve.h"
#include "model/draft.h"
#include "model/number_list.h"
#include "model/spline_elements.h"
#include "model/xml_attrs.h"

/* the fewest points of a curve (the solver's documentation asks four) */
#define MIN_POINTS 4

const hx_attr_spec hx_spline_attrs[] = {
    ID, INT("num_xy_pair"), {"linear_extrap", HX_ATTR_BOOL, 0}, TEXT("linear_extrapolate"),
    TEXT("file_name"), TEXT("block_name"), USER_CALL, END};

void hx_build_spline(hx_draft *d, const hx_element_read *e)
{
    hx_model *m = d->m;
    const int previous = hx_model_spline(m, e->id);
    if (previous >= 0) {
        hx_draft_fail(d, e->line, "Reference_Spline %d is defined twice (line %d)", e->id,
                      m->splines[previous].line);
        return;
    }
    static const char *const user_form[] = {"usrsub_param_string", "usrsub_dll_name",
                                            "usrsub_fnc_name", "script_name", "interpreter",
                                            "file_name", "block_name"};
    for (size_t k = 0; k < sizeof user_form / sizeof user_form[0]; ++k)
        if (hx_attr_present(e, user_form[k])) {
            hx_draft_fail(d, e->line, "Reference_Spline %d: attribute %s: splines read by a user"
                          " subroutine (SPLINE_READ) are not supported by the harness: give"
                          " num_xy_pair and the x y pairs between its tags", e->id,
                          user_form[k]);
            return;
        }
    if (hx_attr_present(e, "linear_extrapolate")) {
        hx_draft_fail(d, e->line, "Reference_Spline %d: attribute linear_extrapolate: the XML"
                      " names it linear_extrap (linear_extrapolate is the Python interface's"
                      " name)", e->id);
        return;
    }
    if (!hx_attr_present(e, "num_xy_pair")) {
        hx_draft_fail(d, e->line, "Reference_Spline %d: attribute num_xy_pair is missing",
                      e->id);
        return;
    }
    const int count = hx_attr_int(e, "num_xy_pair", 0);
    if (count < MIN_POINTS) {
        hx_draft_fail(d, e->line, "Reference_Spline %d: num_xy_pair is %d: a spline needs at"
                      " least %d points", e->id, count, MIN_POINTS);
        return;
    }
    hx_spline *s = hx_draft_push(d, (void **)&m->splines, &m->nsplines, &d->cap_splines,
                                 sizeof *s, NULL, 0);
    if (s == NULL)
        return;
    s->id = e->id;
    s->nx = count;
    s->nz = 1;
    s->linear_extrapolate = hx_attr_number(e, "linear_extrap", 0.0) != 0.0;
    s->line = e->line;
}

/* The x values, strictly increasing; 0, or -1 with the draft failed. */
static int check_x(hx_draft *d, const hx_spline *s)
{
    for (int k = 1; k < s->nx; ++k)
        if (!(s->x[k] > s->x[k - 1])) {
            hx_draft_fail(d, s->line, "Reference_Spline %d: its x values must increase: point %d"
                          " (x = %.17g) does not lie beyond point %d (x = %.17g)", s->id, k + 1,
                          s->x[k], k, s->x[k - 1]);
            return -1;
        }
    return 0;
}

/* Each curve's knot slopes by both methods, all finite; 0, or -1 with the
 * draft failed. */
static int fit(hx_draft *d, hx_spline *s)
{
    const size_t n = (size_t)s->nx * (size_t)s->nz;
    s->akima_slope = malloc(sizeof(double) * n);
    s->cubic_slope = malloc(sizeof(double) * n);
    if (s->akima_slope == NULL || s->cubic_slope == NULL) {
        hx_draft_fail(d, s->line, "out of memory");
        return -1;
    }
    for (int j = 0; j < s->nz; ++j) {
        const double *y = s->y + (size_t)j * (size_t)s->nx;
        hx_akima_slopes(s->x, y, s->nx, s->akima_slope + (size_t)j * (size_t)s->nx);
        if (hx_natural_cubic_slopes(s->x, y, s->nx, s->cubic_slope + (size_t)j * (size_t)s->nx)
            != 0) {
            hx_draft_fail(d, s->line, "out of memory");
            return -1;
        }
    }
    for (size_t k = 0; k < n; ++k)
        if (!isfinite(s->akima_slope[k]) || !isfinite(s->cubic_slope[k])) {
            hx_draft_fail(d, s->line, "Reference_Spline %d: its numbers are too large for a curve"
                          " through them (a slope overflows)", s->id);
            return -1;
        }
    return 0;
}

void hx_spline_text(hx_draft *d, int line, const char *text)
{
    hx_spline *s = &d->m->splines[d->m->nsplines - 1];
    (void)line; /* errors name the element's own line, where its tag opens */
    double *numbers = NULL;
    const int n = hx_read_numbers(text, &numbers);
    if (n == -1) {
        hx_draft_fail(d, s->line, "out of memory");
        return;
    }
    if (n < 0) {
        hx_draft_fail(d, s->line, "Reference_Spline %d: entry %d (from 1) of its data is not a"
                      " finite number", s->id, -1 - n);
        return;
    }
    if ((long long)n != 2LL * s->nx) {
        hx_draft_fail(d, s->line, "Reference_Spline %d: num_xy_pair is %d but its data holds %d"
                      " numbers (%d x y pairs are %lld)", s->id, s->nx, n, s->nx, 2LL * s->nx);
        free(numbers);
        return;
    }
    s->x = malloc(sizeof(double) * (size_t)s->nx);
    s->y = malloc(sizeof(double) * (size_t)s->nx);
    s->z = calloc(1, sizeof(double));
    if (s->x == NULL || s->y == NULL || s->z == NULL) {
        hx_draft_fail(d, s->line, "out of memory");
        free(numbers);
        return;
    }
    for (int k = 0; k < s->nx; ++k)
        s->x[k] = numbers[2 * k], s->y[k] = numbers[2 * k + 1];
    free(numbers);
    if (check_x(d, s) == 0)
        fit(d, s);
}
