/*
 * The GFOSUB form's deformation of I relative to J, measured through the host
 * (docs/interface.md §3.1): translations DX,DY,DZ(I,J,J), rotations AX,AY,AZ(I,J),
 * rates VX..(I,J,J,J) and WX..(I,J,J), querying only what the element uses,
 * in as few round trips as the host allows (one c_sysary each for the
 * displacements and the rates).
 */
#ifndef USRSUB_DEFORMATION_H
#define USRSUB_DEFORMATION_H

typedef struct deformation_needs {
    int translation, rotation, velocity;
} deformation_needs;

/* Fills d and v (the entries not needed are left as they are). Returns 0, or
 * -1 with the query the host refused in failed (at least 64 chars). */
int measure_deformation(int i_marker, int j_marker, deformation_needs needs, double d[6],
                        double v[6], char *failed);

/* AX, AY, AZ of the rotation with 3-1-3 Euler angles (psi, theta, phi). */
void euler313_to_projection_angles(const double euler[3], double angles[3]);

#endif
