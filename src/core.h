/* sepax — private base of every layer of src/ (base, shape, collide, world):
 * nothing here is part of the public contract. It includes the base layer
 * only; each file includes the public headers of its own layer and those
 * below (make check-layers). */
#ifndef SEPAX_CORE_H
#define SEPAX_CORE_H

#include "sepax/base.h"
#include "sepax/vecmath.h"

/* Marks a parameter as deliberately unused. */
#define SX_UNUSED(x) ((void)(x))

/* Number of elements of a fixed array. */
#define SX_ARRAY_COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* Keeps a function out of line where inlining it measurably hurts (see its
 * use); a no-op for compilers without the GNU attribute. */
#if defined(__GNUC__) || defined(__clang__)
#define SX_NOINLINE __attribute__((noinline))
#else
#define SX_NOINLINE
#endif

/* A static function of a private header that not every includer calls
 * (narrow_sat.h, narrow_closest.h): no unused-function warning, no change
 * to how it is compiled. */
#if defined(__GNUC__) || defined(__clang__)
#define SX_MAYBE_UNUSED __attribute__((unused))
#else
#define SX_MAYBE_UNUSED
#endif

/* Forces a small helper into its one hot caller, where GCC's own judgement
 * leaves it out of line (see its use). */
#if defined(__GNUC__) || defined(__clang__)
#define SX_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define SX_ALWAYS_INLINE inline
#endif

#endif /* SEPAX_CORE_H */
