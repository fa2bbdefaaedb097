/* A scalar function value with its first and second derivatives. */
#ifndef USRSUB_JET_H
#define USRSUB_JET_H

typedef struct usrsub_jet {
    double value;
    double d1; /* first derivative */
    double d2; /* second derivative */
} usrsub_jet;

#endif
