/*
 * Reading numbers out of a USER(...) parameter list, with messages that name
 * the parameter both as the user wrote it (USER position, 1-based) and as the
 * C code sees it (par[k], 0-based).
 */
#ifndef USRSUB_USER_LIST_H
#define USRSUB_USER_LIST_H

#include "usrsub/core/message.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct usrsub_user_list {
    const double *par;
    int npar;
    int next;   /* index of the next unread value */
    int offset; /* how many values precede par[0] in the user's USER list */
} usrsub_user_list;

void usrsub_user_list_init(usrsub_user_list *u, const double *par, int npar, int offset);

/* Next value, which must exist and be finite. */
int usrsub_user_list_real(usrsub_user_list *u, const char *what, double *value,
                          usrsub_message *msg);
/* Next value, which must be an exact integer in [lo, hi]. */
int usrsub_user_list_int(usrsub_user_list *u, const char *what, int lo, int hi, int *value,
                         usrsub_message *msg);
/* Fails when values are left over. */
int usrsub_user_list_end(const usrsub_user_list *u, const char *what, usrsub_message *msg);

#ifdef __cplusplus
}
#endif

#endif
