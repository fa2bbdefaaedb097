/*
 * The GFOSUB form's deformation of I relative to J, measured through the host
 * (docs/interface.md §3.1): translations DX,DY,DZ(I,J,J), rotations AX,AY,AZ(I,J),
 * rates VX..(I,J,J,J) and WX..(I,J,J), querying only what the element uses,
 * in as few round trips as the host allows (one c_sysary each for the
 * displacements and the rates). The rotation comes as the host's 3-1-3 Euler
 * angles; near rest, where a host may split psi and phi any way, phi is
 * rebuilt from the host's AZ (one c_sysfnc more, only there and only when the
 * force follows the twist about z), so that the
 * result does not depend on the host's split.
 */
#ifndef USRSUB_ENTRIES_DEFORMATION_H
#define USRSUB_ENTRIES_DEFORMATION_H

typedef struct usrsub_deformation_needs {
    int translation, rotation, velocity;
    int twist; /* the rotation about z is used: near rest phi is rebuilt from AZ */
} usrsub_deformation_needs;

/* Fills d and v (the entries not needed are left as they are) and, when R is
 * not NULL and rotations are needed, the rotation of I relative to J
 * (row-major, columns I's axes in J). Returns 0, or -1 with the query the
 * host refused in failed (at least 64 chars). */
int usrsub_deformation_measure(int i_marker, int j_marker, usrsub_deformation_needs needs, double d[6],
                        double v[6], double *R, char *failed);

#endif
