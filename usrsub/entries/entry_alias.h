/*
 * Each entry is exported twice: as NAME, and as the lower-case name with a
 * trailing underscore that a Linux solver looks up (Adams' C port header and
 * gfortran spell entries that way; docs/interface.md §1). The second name is
 * an alias of the first: one function, one address.
 */
#ifndef USRSUB_ENTRY_ALIAS_H
#define USRSUB_ENTRY_ALIAS_H

#include "usrsub/solver_abi.h"

/* USRSUB_ENTRY_ALIAS(usrsub_gfosub_fn, gfosub_, GFOSUB), after GFOSUB's definition. */
#define USRSUB_ENTRY_ALIAS(TYPE, ALIAS, NAME) TYPE ALIAS __attribute__((alias(#NAME)));

#endif
