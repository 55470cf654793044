/* sepax — private internals shared by the .c files in src/: nothing here is
 * part of the public contract. */
#ifndef SEPAX_CORE_H
#define SEPAX_CORE_H

#include "sepax/sepax.h"

/* Marks a parameter as deliberately unused. */
#define SX_UNUSED(x) ((void)(x))

/* Number of elements of a fixed array. */
#define SX_ARRAY_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

#endif /* SEPAX_CORE_H */
