/*
 * MotionSolve's built-in linear force elements (docs/interface.md §7.17):
 * Force_SpringDamper, Force_Bushing, Force_Beam and the linear Force_Field, each built as the expression load
 * that is the same force (load_elements.h), so that the Jacobian's exact
 * partials, the force functions of requests and the energy balance are the
 * loads' own.
 */
#ifndef HX_MODEL_BUILTIN_FORCES_H
#define HX_MODEL_BUILTIN_FORCES_H

#include "model/xml_schema.h"

extern const hx_attr_spec hx_springdamper_attrs[];
extern const hx_attr_spec hx_bushing_attrs[];
extern const hx_attr_spec hx_beam_attrs[];
extern const hx_attr_spec hx_field_attrs[];

/* A Force_SpringDamper: a Force_Scalar_TwoBody whose value is
 * -damping VR(I,J) - stiffness (DM(I,J) - length) + preload (TRANSLATIONAL),
 * or -damping WZ(I,J,J) - stiffness (AZ(I,J) - length) + preload about J's z
 * axis (ROTATIONAL, length the free angle in radians). */
void hx_build_springdamper(hx_draft *d, const hx_element_read *e);

/* A Force_Bushing: a Force_Vector_TwoBody on I in J's axes, J's body taking
 * the reaction; component x: -kx DX(I,J,J) - cx VX(I,J,J,J) + preload_x, and
 * -ktx AX(I,J) - ctx WX(I,J,J) + preload_tx for the torque (y, z alike). */
void hx_build_bushing(hx_draft *d, const hx_element_read *e);

/* A Force_Beam: a Force_Vector_TwoBody on I in J's axes, J's body taking the
 * reaction, of -K d - C v + preload: d I's displacement from J less the free
 * length along J's x and its angles AX AY AZ, v its velocity and angular
 * velocity in J's axes, K Timoshenko's stiffness, C cratio K or cmatrix. */
void hx_build_beam(hx_draft *d, const hx_element_read *e);

/* A linear Force_Field (no user routine): a Force_Vector_TwoBody on I in
 * J's axes, J's body taking the reaction, of -K (d - length) - C v + preload,
 * d and v as a beam's, K from K11 .. K66 (row, column), C from C11 .. C66 or
 * CRATIO K, length from length_x .. length_tz, preload from preload_x .. tz. */
void hx_build_field(hx_draft *d, const hx_element_read *e);

/* The name of the first linear field attribute e has (K11, CRATIO,
 * length_x, ...), or NULL: a Force_Field calls its routine or is linear. */
const char *hx_field_linear_attribute(const hx_element_read *e);

#endif
