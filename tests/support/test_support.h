/* sepax tests — shared support for the cmocka test programs: cmocka's
 * required includes, SX_ASSERT routed into cmocka failures, real-number
 * comparisons that keep double precision and print both values, a small
 * seeded random generator, and tolerances per build (float or double). */
#ifndef SEPAX_TEST_SUPPORT_H
#define SEPAX_TEST_SUPPORT_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include "sepax/sepax.h"

/* Tolerance for results that should be exact up to rounding of a few
 * operations on unit-size values. */
#ifdef SX_DOUBLE
#define SX_TEST_EPS 1e-12
#else
#define SX_TEST_EPS 1e-5
#endif

/* Routes SX_ASSERT to a cmocka failure (call from a group setup, or first
 * thing in main). */
void sx_test_route_asserts(void);

/* Group setup/teardown pair: routes asserts and checks that every byte
 * allocated through sx_alloc during the group was freed. */
int sx_test_group_setup(void **state);
int sx_test_group_teardown(void **state);

/* Fails the test (printing both expressions and values) unless
 * |a - b| <= tol. Compares in double, whatever sx_real is. */
void sx_test_assert_near(double a, double b, double tol, const char *ea, const char *eb,
                         const char *file, int line);
#define assert_near(a, b, tol)                                                                     \
    sx_test_assert_near((double)(a), (double)(b), (double)(tol), #a, #b, __FILE__, __LINE__)
#define assert_vec2_near(v, w, tol)                                                                \
    do {                                                                                           \
        sx_vec2 v_ = (v), w_ = (w);                                                                \
        sx_test_assert_near((double)v_.x, (double)w_.x, (double)(tol), #v ".x", #w ".x", __FILE__, \
                            __LINE__);                                                             \
        sx_test_assert_near((double)v_.y, (double)w_.y, (double)(tol), #v ".y", #w ".y", __FILE__, \
                            __LINE__);                                                             \
    } while (0)

/* A small deterministic generator (splitmix64): same seed, same sequence on
 * every machine. */
typedef struct sx_test_rng {
    uint64_t state;
} sx_test_rng;

sx_test_rng sx_test_rng_make(uint64_t seed);
uint64_t sx_test_rng_next(sx_test_rng *rng);
/* Uniform double in [0, 1). */
double sx_test_rng_unit(sx_test_rng *rng);
/* Uniform sx_real in [lo, hi). */
sx_real sx_test_rng_range(sx_test_rng *rng, double lo, double hi);

/* A comb outline, counter-clockwise: a (2 teeth - 1) x 1 spine on y in
 * [0, 1] with `teeth` 1 x 2 teeth (x in [2k, 2k + 1]) up to y = 3, the gaps
 * between them down to the spine's top. Writes 4 x teeth points to p and
 * returns that count. */
int sx_test_comb_outline(sx_vec2 *p, int teeth);

/* A random convex n-gon (n <= SX_MAX_POLYGON_VERTICES): vertex k at angle
 * 2 pi k / n, its radius drawn in [rmin, rmax) (one draw per vertex, in
 * order); fails the test if it does not build. */
sx_shape sx_test_random_ngon(sx_test_rng *rng, int n, double rmin, double rmax);

/* A body of `type` at p with one collider of `shape` (default material);
 * *collider (may be NULL) gets the collider's handle. Fails the test if
 * either call fails. */
sx_body_id sx_test_body(sx_world *w, sx_body_type type, sx_vec2 p, sx_shape shape,
                        sx_collider_id *collider);

/* A body of `type` at p turned by `angle` with the one collider *cd (the
 * caller's shape and material, from sx_default_collider_def). Fails the
 * test if either call fails. */
sx_body_id sx_test_body_turned(sx_world *w, sx_body_type type, sx_vec2 p, sx_real angle,
                               const sx_collider_def *cd);

#endif /* SEPAX_TEST_SUPPORT_H */
