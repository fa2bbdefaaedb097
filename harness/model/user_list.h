/* The numbers of a usrsub_param_string, "USER(p1, p2, ...)" (docs/interface.md §1). */
#ifndef HX_MODEL_USER_LIST_H
#define HX_MODEL_USER_LIST_H

#include "base/message.h"

/* Parses text into newly allocated numbers; 0, or -1 with the reason in msg. */
int hx_parse_user_list(const char *text, double **par, int *npar, hx_message *msg);

#endif
