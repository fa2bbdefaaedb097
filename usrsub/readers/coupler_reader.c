/* The coupler's USER list, term by term, and its code-4 table files
 * (coupler_reader.h; docs/interface.md §2). */
#include "usrsub/readers/coupler_reader.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "usrsub/readers/table_file.h"
#include "usrsub/readers/user_list.h"

#define PATH_TEXT_MAX 4096

static int decode_linear(usrsub_coupler_term *t, usrsub_user_list *u, usrsub_message *msg)
{
    return usrsub_user_list_real(u, "the slope s of a code-1 term", &t->slope, msg);
}

static int decode_polynomial(usrsub_coupler_term *t, usrsub_user_list *u, usrsub_message *msg)
{
    if (usrsub_user_list_int(u, "the degree n of a code-2 polynomial", 0,
                             USRSUB_POLYNOMIAL_MAX_DEGREE, &t->poly.degree, msg) != 0)
        return -1;
    for (int k = 0; k <= t->poly.degree; ++k)
        if (usrsub_user_list_real(u, "a polynomial coefficient", &t->poly.a[k], msg) != 0)
            return -1;
    return 0;
}

static int decode_inline_spline(usrsub_coupler_term *t, usrsub_user_list *u,
                                usrsub_message *msg)
{
    int n;
    if (usrsub_user_list_int(u, "the point count n of a code-3 spline", 2, INT_MAX / 2, &n,
                             msg) != 0)
        return -1;
    const int first = u->next + u->offset + 1;
    const int remaining = u->npar - u->next;
    if (2 * n > remaining)
        return usrsub_fail(msg, "a code-3 spline of %d points needs %d values from USER"
                           " parameter %d, but only %d remain", n, 2 * n, first, remaining);
    double *x = malloc(sizeof(double) * (size_t)n);
    double *y = malloc(sizeof(double) * (size_t)n);
    int status = (x == NULL || y == NULL) ? usrsub_fail(msg, "out of memory") : 0;
    for (int i = 0; i < n && status == 0; ++i) {
        status = usrsub_user_list_real(u, "a spline x value", &x[i], msg);
        if (status == 0)
            status = usrsub_user_list_real(u, "a spline y value", &y[i], msg);
    }
    if (status == 0 && usrsub_spline_init(&t->spline, n, x, y, msg) != 0) {
        usrsub_message_prefix(msg, "code-3 spline points from USER parameter %d", first);
        status = -1;
    }
    free(x);
    free(y);
    t->scale = 1.0;
    return status;
}

static int decode_spline_file(usrsub_coupler_term *t, usrsub_user_list *u,
                              usrsub_string_lookup *lookup, void *lookup_ctx,
                              usrsub_message *msg)
{
    int string_id;
    if (usrsub_user_list_int(u, "the Reference_String id of a code-4 table file", 1, INT_MAX,
                             &string_id, msg) != 0)
        return -1;
    if (usrsub_user_list_real(u, "the scale of a code-4 term", &t->scale, msg) != 0)
        return -1;
    char path[PATH_TEXT_MAX];
    if (lookup == NULL || lookup(lookup_ctx, string_id, path, (int)sizeof path) != 0)
        return usrsub_fail(msg, "there is no Reference_String %d for the code-4 table file",
                           string_id);
    double *x, *y;
    int n;
    if (usrsub_table_file_read(path, &x, &y, &n, msg) != 0)
        return -1;
    int status = usrsub_spline_init(&t->spline, n, x, y, msg);
    if (status != 0)
        usrsub_message_prefix(msg, "table file '%s' (Reference_String %d)", path, string_id);
    free(x);
    free(y);
    return status;
}

static int decode_sine(usrsub_coupler_term *t, usrsub_user_list *u, usrsub_message *msg)
{
    if (usrsub_user_list_real(u, "the amplitude a of a code-5 term", &t->amplitude, msg) != 0 ||
        usrsub_user_list_real(u, "the frequency w of a code-5 term", &t->frequency, msg) != 0 ||
        usrsub_user_list_real(u, "the phase p of a code-5 term", &t->phase, msg) != 0)
        return -1;
    return 0;
}

int usrsub_coupler_decode(usrsub_coupler *c, const double *par, int npar, int ndisp,
                          usrsub_string_lookup *lookup, void *lookup_ctx,
                          usrsub_message *msg)
{
    memset(c, 0, sizeof *c);
    if (ndisp < 2 || ndisp > USRSUB_COUPLER_MAX_TERMS)
        return usrsub_fail(msg, "ndisp is %d: a coupler relates 2 or 3 joints", ndisp);
    usrsub_user_list u;
    usrsub_user_list_init(&u, par, npar, 0);
    for (int k = 0; k < ndisp; ++k) {
        usrsub_coupler_term *t = &c->term[k];
        char what[96];
        snprintf(what, sizeof what, "the code (1 to 5) of term %d of %d", k + 1, ndisp);
        if (u.next >= u.npar) {
            usrsub_fail(msg, "the USER list has %d terms, but the coupler relates %d joints"
                        " (one term per joint)", k, ndisp);
            usrsub_coupler_free(c);
            return -1;
        }
        int status = usrsub_user_list_int(&u, what, 1, 5, &t->code, msg);
        if (status == 0) {
            c->nterms = k + 1;
            switch (t->code) {
            case USRSUB_COUPLER_LINEAR: status = decode_linear(t, &u, msg); break;
            case USRSUB_COUPLER_POLYNOMIAL: status = decode_polynomial(t, &u, msg); break;
            case USRSUB_COUPLER_SPLINE: status = decode_inline_spline(t, &u, msg); break;
            case USRSUB_COUPLER_SPLINE_FILE:
                status = decode_spline_file(t, &u, lookup, lookup_ctx, msg);
                break;
            default: status = decode_sine(t, &u, msg); break;
            }
        }
        if (status != 0) {
            if (t->code != 0)
                usrsub_message_prefix(msg, "term %d (code %d)", k + 1, t->code);
            usrsub_coupler_free(c);
            return -1;
        }
    }
    if (u.next < u.npar) {
        usrsub_fail(msg, "the USER list has more than %d terms (USER parameter %d = %g onwards"
                    " is left over), but the coupler relates %d joints (one term per joint)",
                    ndisp, u.next + 1, par[u.next], ndisp);
        usrsub_coupler_free(c);
        return -1;
    }
    return 0;
}

