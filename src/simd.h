/* sepax — private: four lanes of sx_real, the one place SIMD lives.
 *
 * The narrowphase's inner loops and the solver's wide passes are written
 * once against these operations. The float build on x86-64 maps them to
 * SSE2 (every x86-64 CPU has it); the double build and -DSX_NO_SIMD
 * (make SIMD=0) map them to plain C over four lanes. Each operation is an
 * IEEE-exact lane-wise operation (no fused multiply-add, no approximate
 * reciprocal) and the scalar fallback reproduces SSE2's rules for min, max
 * and comparisons with NaN, so both paths answer bit for bit alike. */
#ifndef SEPAX_SIMD_H
#define SEPAX_SIMD_H

#include <stdint.h>

#include "core.h"

#if !defined(SX_DOUBLE) && !defined(SX_NO_SIMD) && defined(__SSE2__)
#define SX_SIMD 1
#include <emmintrin.h>
#else
#define SX_SIMD 0
#endif

#if SX_SIMD

/** Four reals. */
typedef __m128 sx_r4;
/** Four lane masks (all bits set: true, all clear: false). */
typedef __m128 sx_m4;

static inline sx_r4 sx_r4_set1(sx_real a) { return _mm_set1_ps(a); }
/** Lanes 0..3 are a, b, c, d. */
static inline sx_r4 sx_r4_set(sx_real a, sx_real b, sx_real c, sx_real d) {
    return _mm_setr_ps(a, b, c, d);
}
static inline sx_r4 sx_r4_zero(void) { return _mm_setzero_ps(); }
/** Four reals from memory, any alignment. */
static inline sx_r4 sx_r4_load(const sx_real *p) { return _mm_loadu_ps(p); }
static inline void sx_r4_store(sx_real *p, sx_r4 a) { _mm_storeu_ps(p, a); }
static inline sx_r4 sx_r4_add(sx_r4 a, sx_r4 b) { return _mm_add_ps(a, b); }
static inline sx_r4 sx_r4_sub(sx_r4 a, sx_r4 b) { return _mm_sub_ps(a, b); }
static inline sx_r4 sx_r4_mul(sx_r4 a, sx_r4 b) { return _mm_mul_ps(a, b); }
static inline sx_r4 sx_r4_div(sx_r4 a, sx_r4 b) { return _mm_div_ps(a, b); }
static inline sx_r4 sx_r4_sqrt(sx_r4 a) { return _mm_sqrt_ps(a); }
/** a < b ? a : b per lane (b when either is NaN). */
static inline sx_r4 sx_r4_min(sx_r4 a, sx_r4 b) { return _mm_min_ps(a, b); }
/** a > b ? a : b per lane (b when either is NaN). */
static inline sx_r4 sx_r4_max(sx_r4 a, sx_r4 b) { return _mm_max_ps(a, b); }
/** -a (the sign bit flipped, NaN and zero included). */
static inline sx_r4 sx_r4_neg(sx_r4 a) { return _mm_xor_ps(a, _mm_set1_ps(-0.0f)); }
/** |a| (the sign bit cleared). */
static inline sx_r4 sx_r4_abs(sx_r4 a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }

static inline sx_m4 sx_r4_lt(sx_r4 a, sx_r4 b) { return _mm_cmplt_ps(a, b); }
static inline sx_m4 sx_r4_le(sx_r4 a, sx_r4 b) { return _mm_cmple_ps(a, b); }
static inline sx_m4 sx_r4_gt(sx_r4 a, sx_r4 b) { return _mm_cmpgt_ps(a, b); }
static inline sx_m4 sx_r4_ge(sx_r4 a, sx_r4 b) { return _mm_cmpge_ps(a, b); }
static inline sx_m4 sx_r4_eq(sx_r4 a, sx_r4 b) { return _mm_cmpeq_ps(a, b); }
/** True where a or b is NaN. */
static inline sx_m4 sx_r4_unordered(sx_r4 a, sx_r4 b) { return _mm_cmpunord_ps(a, b); }

static inline sx_m4 sx_m4_and(sx_m4 a, sx_m4 b) { return _mm_and_ps(a, b); }
static inline sx_m4 sx_m4_or(sx_m4 a, sx_m4 b) { return _mm_or_ps(a, b); }
/** !a && b per lane. */
static inline sx_m4 sx_m4_andnot(sx_m4 a, sx_m4 b) { return _mm_andnot_ps(a, b); }
/** Bit i set when lane i is true. */
static inline int sx_m4_bits(sx_m4 m) { return _mm_movemask_ps(m); }
/** m ? a : b per lane. */
static inline sx_r4 sx_r4_select(sx_m4 m, sx_r4 a, sx_r4 b) {
    return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b));
}
/** Lane i of a. */
static inline sx_real sx_r4_lane(sx_r4 a, int i) {
    float out[4];
    _mm_storeu_ps(out, a);
    return out[i & 3];
}

#else /* the portable lanes */

typedef struct sx_r4 {
    sx_real v[4];
} sx_r4;
typedef struct sx_m4 {
    int32_t m[4];
} sx_m4;

static inline sx_r4 sx_r4_set(sx_real a, sx_real b, sx_real c, sx_real d) {
    sx_r4 r;
    r.v[0] = a;
    r.v[1] = b;
    r.v[2] = c;
    r.v[3] = d;
    return r;
}
static inline sx_r4 sx_r4_set1(sx_real a) { return sx_r4_set(a, a, a, a); }
static inline sx_r4 sx_r4_zero(void) { return sx_r4_set1(SX_R(0.0)); }
static inline sx_r4 sx_r4_load(const sx_real *p) { return sx_r4_set(p[0], p[1], p[2], p[3]); }
static inline void sx_r4_store(sx_real *p, sx_r4 a) {
    p[0] = a.v[0];
    p[1] = a.v[1];
    p[2] = a.v[2];
    p[3] = a.v[3];
}

/* One lane-wise operation, written out once for every binary operator. */
#define SX_R4_LANES(expr)                                                      \
    sx_r4 r;                                                                   \
    int i;                                                                     \
    for (i = 0; i < 4; ++i) r.v[i] = (expr);                                   \
    return r
#define SX_M4_LANES(expr)                                                      \
    sx_m4 r;                                                                   \
    int i;                                                                     \
    for (i = 0; i < 4; ++i) r.m[i] = (expr) ? -1 : 0;                          \
    return r

static inline sx_r4 sx_r4_add(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] + b.v[i]); }
static inline sx_r4 sx_r4_sub(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] - b.v[i]); }
static inline sx_r4 sx_r4_mul(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] * b.v[i]); }
static inline sx_r4 sx_r4_div(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] / b.v[i]); }
static inline sx_r4 sx_r4_sqrt(sx_r4 a) { SX_R4_LANES(sx_sqrt(a.v[i])); }
static inline sx_r4 sx_r4_min(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] < b.v[i] ? a.v[i] : b.v[i]); }
static inline sx_r4 sx_r4_max(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] > b.v[i] ? a.v[i] : b.v[i]); }
static inline sx_r4 sx_r4_neg(sx_r4 a) { SX_R4_LANES(-a.v[i]); }
/* fabs clears the sign bit as SSE does (sx_absr keeps -0's) */
static inline sx_r4 sx_r4_abs(sx_r4 a) { SX_R4_LANES((sx_real)fabs((double)a.v[i])); }

static inline sx_m4 sx_r4_lt(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] < b.v[i]); }
static inline sx_m4 sx_r4_le(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] <= b.v[i]); }
static inline sx_m4 sx_r4_gt(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] > b.v[i]); }
static inline sx_m4 sx_r4_ge(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] >= b.v[i]); }
static inline sx_m4 sx_r4_eq(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] == b.v[i]); }
static inline sx_m4 sx_r4_unordered(sx_r4 a, sx_r4 b) {
    SX_M4_LANES(a.v[i] != a.v[i] || b.v[i] != b.v[i]);
}

static inline sx_m4 sx_m4_and(sx_m4 a, sx_m4 b) { SX_M4_LANES(a.m[i] && b.m[i]); }
static inline sx_m4 sx_m4_or(sx_m4 a, sx_m4 b) { SX_M4_LANES(a.m[i] || b.m[i]); }
static inline sx_m4 sx_m4_andnot(sx_m4 a, sx_m4 b) { SX_M4_LANES(!a.m[i] && b.m[i]); }
static inline int sx_m4_bits(sx_m4 m) {
    return (m.m[0] ? 1 : 0) | (m.m[1] ? 2 : 0) | (m.m[2] ? 4 : 0) | (m.m[3] ? 8 : 0);
}
static inline sx_r4 sx_r4_select(sx_m4 m, sx_r4 a, sx_r4 b) { SX_R4_LANES(m.m[i] ? a.v[i] : b.v[i]); }
static inline sx_real sx_r4_lane(sx_r4 a, int i) { return a.v[i & 3]; }

#undef SX_R4_LANES
#undef SX_M4_LANES

#endif /* SX_SIMD */

/* Built on the lanes above, so written once for both paths. */

/** a * b + c, rounded twice (no fused multiply-add: both paths agree). */
static inline sx_r4 sx_r4_mul_add(sx_r4 a, sx_r4 b, sx_r4 c) { return sx_r4_add(sx_r4_mul(a, b), c); }
/** lo <= a <= hi per lane (hi wins when lo > hi; NaN a gives lo). */
static inline sx_r4 sx_r4_clamp(sx_r4 a, sx_r4 lo, sx_r4 hi) {
    return sx_r4_min(hi, sx_r4_max(a, lo));
}
/** True when any lane of m is. */
static inline bool sx_m4_any(sx_m4 m) { return sx_m4_bits(m) != 0; }
/** True when every lane of m is. */
static inline bool sx_m4_all(sx_m4 m) { return sx_m4_bits(m) == 15; }

#endif /* SEPAX_SIMD_H */
