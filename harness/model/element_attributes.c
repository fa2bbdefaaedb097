/* An element's attributes as read, by name (xml_schema.h). */
#include <ctype.h>
#include <strings.h>

#include "model/xml_schema.h"

int hx_attr_find(const hx_element_read *e, const char *name)
{
    const int first = tolower((unsigned char)name[0]);
    for (int k = 0; k < e->nspec; ++k) /* the first letters compared first: builders look
                                         * attributes up by name many times an element */
        if (tolower((unsigned char)e->spec[k].name[0]) == first &&
            strcasecmp(e->spec[k].name, name) == 0)
            return k;
    return -1;
}

int hx_attr_present(const hx_element_read *e, const char *name)
{
    const int k = hx_attr_find(e, name);
    return k >= 0 && e->value[k].present;
}

double hx_attr_number(const hx_element_read *e, const char *name, double fallback)
{
    const int k = hx_attr_find(e, name);
    return k >= 0 && e->value[k].present ? e->value[k].number : fallback;
}

int hx_attr_int(const hx_element_read *e, const char *name, int fallback)
{
    return (int)hx_attr_number(e, name, fallback);
}

const char *hx_attr_text(const hx_element_read *e, const char *name)
{
    const int k = hx_attr_find(e, name);
    return k >= 0 && e->value[k].present ? e->value[k].text : NULL;
}
