/* sepax — base definitions: the real type, status codes, version, the assert
 * and allocator hooks, and the named tolerances.
 *
 * Everything else in sepax includes this header. It holds the only
 * process-wide state in the library: the assert handler and the allocator
 * hooks (set once, before any world exists) and the live-byte counter
 * (atomic); the geometry layers above it keep no state at all. Every
 * tolerance is derived from one length scale, SX_LENGTH_UNITS_PER_METER, so a
 * game that works in pixels or centimetres rescales them all at once.
 *
 * Threads: the math, shape and collide functions are pure and may run on any
 * thread. Worlds share nothing with each other, so different worlds may be
 * created, stepped, queried and destroyed on different threads at the same
 * time without locking (world.h); what they do share is the allocator hooks,
 * which must then be thread-safe themselves (malloc/free, the default, are),
 * and the assert handler, which may be called from any of those threads. */
#ifndef SEPAX_BASE_H
#define SEPAX_BASE_H

#include <float.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- exported symbols --------------------------------------------------- */

/** Marks the library's public functions. The library is compiled with
 *  -fvisibility=hidden, so libsepax.so exports these and nothing else (make
 *  test checks that its exports are exactly the SX_API declarations of these
 *  headers); for a program it is an ordinary declaration. */
#if defined(__GNUC__) || defined(__clang__)
#define SX_API __attribute__((visibility("default")))
#else
#define SX_API
#endif

/* ---- version ------------------------------------------------------------ */

#define SX_VERSION_MAJOR 0
#define SX_VERSION_MINOR 1
#define SX_VERSION_PATCH 0
/** Version as one integer: major * 10000 + minor * 100 + patch. */
#define SX_VERSION (SX_VERSION_MAJOR * 10000 + SX_VERSION_MINOR * 100 + SX_VERSION_PATCH)

/** The version the library was built as (compare with SX_VERSION to detect a
 *  header/library mismatch). */
SX_API int sx_version(void);

/* ---- the real type ------------------------------------------------------ */

/** The scalar type of the whole library: float, or double when built with
 *  -DSX_DOUBLE (make SX_REAL=double). Headers and library must agree;
 *  sx_real_is_double() reports what the library was built with. */
#ifdef SX_DOUBLE
typedef double sx_real;
#define SX_REAL_EPSILON DBL_EPSILON
#define SX_REAL_MAX DBL_MAX
#define SX_R(x) (x)
#else
typedef float sx_real;
#define SX_REAL_EPSILON FLT_EPSILON
#define SX_REAL_MAX FLT_MAX
/** A literal in sx_real precision: SX_R(0.5) is 0.5f in the float build. */
#define SX_R(x) (x##f)
#endif

/** True when the library binary was built with SX_DOUBLE. */
SX_API bool sx_real_is_double(void);

#define SX_PI SX_R(3.14159265358979323846)

/* ---- status ------------------------------------------------------------- */

/** Result of every builder, creator and validating call. SX_OK is zero. */
typedef enum sx_status {
    SX_OK = 0,
    SX_ERR_INVALID_ARG,  /**< null pointer, negative size/radius/density, bad enum */
    SX_ERR_DEGENERATE,   /**< too few usable points, zero length/area */
    SX_ERR_NONFINITE,    /**< NaN or infinity in the input, or in what it
                              implies (a shape whose mass overflows) */
    SX_ERR_CAPACITY,     /**< more than a fixed capacity allows (e.g. hull vertices) */
    SX_ERR_NO_MEMORY,    /**< the allocator hook returned NULL */
    SX_ERR_STALE_HANDLE, /**< the handle's object was destroyed (or never existed) */
    /** the world is running one of its callbacks (a query's or the debug
     *  draw's) and the call would change what the callback walks over */
    SX_ERR_LOCKED,
    SX_STATUS_COUNT
} sx_status;

/** A short constant English description of a status ("ok", "invalid
 *  argument", ...). Unknown values give "unknown status". Never NULL. */
SX_API const char *sx_status_str(sx_status status);

/* ---- assertions --------------------------------------------------------- */

/** Called when an internal contract is violated (SX_ASSERT). The default
 *  handler prints the expression and location to stderr and calls abort().
 *  A replacement may return (the library then continues, which is undefined
 *  for the violated contract) or longjmp out (as the cmocka tests do). */
typedef void sx_assert_fn(const char *expression, const char *file, int line, void *context);

/** Installs the assert handler (NULL restores the default). Not thread-safe:
 *  set it once at start-up, before any world exists or any other thread
 *  calls sepax; the handler itself may then be called from any thread that
 *  uses a world. */
SX_API void sx_set_assert_handler(sx_assert_fn *handler, void *context);

/** Reports a failed assertion through the installed handler. */
SX_API void sx_assert_failed(const char *expression, const char *file, int line);

/** SX_ASSERT(c) checks an internal contract in hot paths. It is on unless
 *  SX_DISABLE_ASSERT is defined when the library is compiled. Bad user input
 *  at API boundaries is answered with an sx_status, never with an assert. */
#ifndef SX_DISABLE_ASSERT
#define SX_ASSERT(c)                                                                               \
    do {                                                                                           \
        if (!(c)) sx_assert_failed(#c, __FILE__, __LINE__);                                        \
    } while (0)
#else
#define SX_ASSERT(c) ((void)0)
#endif

/* ---- allocation --------------------------------------------------------- */

/** Allocator hook: returns a block of at least `size` bytes aligned for any
 *  type, or NULL. */
typedef void *sx_alloc_fn(size_t size, void *context);
/** Free hook: receives the same size that was allocated. */
typedef void sx_free_fn(void *memory, size_t size, void *context);

/** Routes all sepax memory through the given hooks (NULL, NULL restores
 *  malloc/free). Set it once at start-up, before any world exists or any
 *  other thread calls sepax: memory must be freed by the hooks that
 *  allocated it, and the call itself is not thread-safe. When worlds live on
 *  several threads, the hooks are called from all of them at once and must
 *  be thread-safe. */
SX_API void sx_set_allocator(sx_alloc_fn *alloc, sx_free_fn *free_fn, void *context);

/** Allocates through the hook and counts the bytes. size 0 returns NULL.
 *  Thread-safe when the hook is. */
SX_API void *sx_alloc(size_t size);
/** Frees a block from sx_alloc (NULL is ignored). `size` must be the size
 *  passed to sx_alloc. Thread-safe when the hook is. */
SX_API void sx_free(void *memory, size_t size);
/** Bytes currently allocated through sx_alloc and not yet freed, by every
 *  world of every thread (for leak checks). The counter is atomic: it loses
 *  no update when threads allocate at once, and while other threads
 *  allocate it is a snapshot of a moving value. */
SX_API size_t sx_live_bytes(void);

/* ---- tolerances (all from one length scale) ----------------------------- */

/** Length units per metre used by the default tolerances below. A game that
 *  works in pixels at 32 px/m may compile with -DSX_LENGTH_UNITS_PER_METER=32;
 *  worlds can also override it per world at run time. */
#ifndef SX_LENGTH_UNITS_PER_METER
#define SX_LENGTH_UNITS_PER_METER SX_R(1.0)
#endif

/** The linear slop: the contact tolerance of the whole library, 5 mm. Shapes
 *  closer than this are "touching"; the solver allows this much resting
 *  penetration. */
#define SX_LINEAR_SLOP (SX_R(0.005) * SX_LENGTH_UNITS_PER_METER)

/** Angular slop (radians): 2 degrees. */
#define SX_ANGULAR_SLOP (SX_R(2.0) / SX_R(180.0) * SX_PI)

/** Distance under which hull points are welded together: a quarter of the
 *  linear slop. */
#define SX_WELD_TOLERANCE (SX_R(0.25) * SX_LINEAR_SLOP)

/** Speculative distance: contacts are kept for shapes this close, so the
 *  solver sees them before they touch (4 x slop). */
#define SX_SPECULATIVE_DISTANCE (SX_R(4.0) * SX_LINEAR_SLOP)

/** Largest coordinate magnitude the library promises to handle (float build:
 *  1e5 m keeps sub-centimetre resolution; double: 1e9). Inputs beyond it are
 *  answered (no crash, no NaN) but with reduced precision.
 *
 *  SX_HUGE is fixed when the library is compiled, in length units: 1e5 (or
 *  1e9) x SX_LENGTH_UNITS_PER_METER. It does not follow a world's run-time
 *  length_units_per_meter (the geometry layers, which have no world, use it
 *  too). A world uses it twice: a collider must lie within SX_HUGE of its
 *  body's origin in x and y, and a body moves at most SX_HUGE per sub-step.
 *  With length_units_per_meter L above SX_LENGTH_UNITS_PER_METER (a world in
 *  centimetres, L = 100, in a library built at 1) those bounds are 1e5
 *  units, a kilometre, stricter than the precision needs but far above
 *  game speeds and sizes; with L below it (a world in kilometres) they are
 *  looser than the precision of sx_real allows, and coordinates near
 *  SX_HUGE have less resolution than the world's slop. To move SX_HUGE with
 *  the units, build the library with -DSX_LENGTH_UNITS_PER_METER=L. */
#ifdef SX_DOUBLE
#define SX_HUGE (SX_R(1.0e9) * SX_LENGTH_UNITS_PER_METER)
#else
#define SX_HUGE (SX_R(1.0e5) * SX_LENGTH_UNITS_PER_METER)
#endif

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_BASE_H */
