/*
 * tp_mdi_names.h -- the entry names as a Linux build of Adams-style C code
 * gives them (its port header maps each upper-case name to lower case with a
 * trailing underscore, as gfortran names Fortran routines), for tp_mdi.c.
 */
#ifndef TP_MDI_NAMES_H
#define TP_MDI_NAMES_H

#define SFOSUB sfosub_
#define REQSUB reqsub_

#endif
