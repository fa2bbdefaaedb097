/* What the host noted of an element over the calls of a check (checks.h):
 * any read outside its declared dependencies, at any time, and any query the
 * host refused, fails it. */
#include <stdio.h>

#include "host/utilities.h"
#include "tools/check/checks.h"

int hx_check_queries(const hx_binding *b, FILE *out)
{
    int failures = 0;
    char text[1024];
    if (b->reported_undeclared.count > 0) {
        fprintf(out, "  %s %d: FAIL: reads outside the dependencies it declared in its dependency"
                " pass: %s\n", b->element, b->id,
                hx_noted_text(&b->reported_undeclared, text, sizeof text));
        ++failures;
    }
    if (b->reported_refused.count > 0) {
        fprintf(out, "  %s %d: FAIL: asks queries the host refuses: %s\n", b->element, b->id,
                hx_noted_text(&b->reported_refused, text, sizeof text));
        ++failures;
    }
    if (b->reported_unoffered != 0) {
        fprintf(out, "  %s %d: FAIL: needs %s, which this host does not offer (docs/interface.md"
                " §5.2)\n", b->element, b->id,
                hx_utilities_text(b->reported_unoffered, text, sizeof text));
        ++failures;
    }
    if (b->reported_misused != 0) {
        fprintf(out, "  %s %d: FAIL: calls %s with arguments the host refuses (see host: above)\n",
                b->element, b->id, hx_utilities_text(b->reported_misused, text, sizeof text));
        ++failures;
    }
    return failures;
}
