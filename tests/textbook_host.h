/*
 * A host of the tests' own, not the harness: it holds I's and J's frames in
 * ground and answers DISP, RDISP, TDISP, VEL, RVEL, AZ, DX..DZ like a solver
 * that computes the relative rotation R_J^T R_I with its ordinary rounding
 * and splits the 3-1-3 Euler angles the textbook way: psi = atan2(R02, -R12)
 * and phi = atan2(R20, R21), two separate atan2 calls of entries that are of
 * the size of the rounding at rest, with a guard only where sin(theta) is
 * below 1e-14 (or no guard at all). The library must be right with it too.
 */
#ifndef TEXTBOOK_HOST_H
#define TEXTBOOK_HOST_H

typedef struct textbook_host {
    double RI[9], RJ[9];    /* world orientations (row-major, columns the axes) */
    double pI[3], pJ[3];
    double wI[3], wJ[3];    /* world angular velocities */
    const char *strings[8]; /* Reference_String 1..8 */
    int guard;              /* 1: put psi + phi in psi below sin(theta) = 1e-14 */
    int errors;
    char last_error[1024];
} textbook_host;

/* The host the utilities answer from (a test's global: the ABI has no context). */
void textbook_host_use(textbook_host *h);

/* Its Euler angles of a rotation, the textbook way. */
void textbook_euler313(const textbook_host *h, const double R[9], double e[3]);

#endif
