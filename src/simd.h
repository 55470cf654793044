/* sepax — private: lanes of sx_real, the one place SIMD lives.
 *
 * The narrowphase's inner loops (sx_r4, four lanes) and the solver's wide
 * passes (sx_rw, SX_LANES lanes) are written once against these
 * operations. On x86-64 (every CPU there has SSE2) the float build maps
 * sx_r4 to one SSE2 register of four floats and the double build to two
 * registers of two doubles; -DSX_NO_SIMD (make SIMD=0) and other CPUs map
 * it to plain C over four lanes. sx_rw is sx_r4 except with -mavx2 (make
 * SIMD=avx2): eight floats, or four doubles, in one AVX register. Each operation is an
 * IEEE-exact lane-wise operation (no fused multiply-add, no approximate
 * reciprocal) and the scalar fallback reproduces SSE2's rules for min, max
 * and comparisons with NaN, so every path answers bit for bit alike. */
#ifndef SEPAX_SIMD_H
#define SEPAX_SIMD_H

#include <stdint.h>

#include "core.h"

/* SX_SIMD: some SSE2 mapping; SX_SIMD_F64: the double build's pairs of
 * registers (a loop of padded lanes run in plain C costs the double build
 * more than the scalar loop it replaces). */
#if !defined(SX_NO_SIMD) && defined(__SSE2__)
#define SX_SIMD 1
#include <emmintrin.h>
#ifdef SX_DOUBLE
#define SX_SIMD_F64 1
#else
#define SX_SIMD_F64 0
#endif
#else
#define SX_SIMD 0
#define SX_SIMD_F64 0
#endif

#if SX_SIMD && !SX_SIMD_F64

/** Four reals. */
typedef __m128 sx_r4;
/** Four lane masks (all bits set: true, all clear: false). */
typedef __m128 sx_m4;

static SX_ALWAYS_INLINE sx_r4 sx_r4_set1(sx_real a) { return _mm_set1_ps(a); }
/** Lanes 0..3 are a, b, c, d. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_set(sx_real a, sx_real b, sx_real c, sx_real d) {
    return _mm_setr_ps(a, b, c, d);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_zero(void) { return _mm_setzero_ps(); }
/** Four reals from memory, any alignment. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_load(const sx_real *p) { return _mm_loadu_ps(p); }
static SX_ALWAYS_INLINE void sx_r4_store(sx_real *p, sx_r4 a) { _mm_storeu_ps(p, a); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_add(sx_r4 a, sx_r4 b) { return _mm_add_ps(a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_sub(sx_r4 a, sx_r4 b) { return _mm_sub_ps(a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_mul(sx_r4 a, sx_r4 b) { return _mm_mul_ps(a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_div(sx_r4 a, sx_r4 b) { return _mm_div_ps(a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_sqrt(sx_r4 a) { return _mm_sqrt_ps(a); }
/** a < b ? a : b per lane (b when either is NaN). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_min(sx_r4 a, sx_r4 b) { return _mm_min_ps(a, b); }
/** a > b ? a : b per lane (b when either is NaN). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_max(sx_r4 a, sx_r4 b) { return _mm_max_ps(a, b); }
/** -a (the sign bit flipped, NaN and zero included). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_neg(sx_r4 a) { return _mm_xor_ps(a, _mm_set1_ps(-0.0f)); }
/** |a| (the sign bit cleared). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_abs(sx_r4 a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }

static SX_ALWAYS_INLINE sx_m4 sx_r4_lt(sx_r4 a, sx_r4 b) { return _mm_cmplt_ps(a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_le(sx_r4 a, sx_r4 b) { return _mm_cmple_ps(a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_gt(sx_r4 a, sx_r4 b) { return _mm_cmpgt_ps(a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_ge(sx_r4 a, sx_r4 b) { return _mm_cmpge_ps(a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_eq(sx_r4 a, sx_r4 b) { return _mm_cmpeq_ps(a, b); }
/** True where a or b is NaN. */
static SX_ALWAYS_INLINE sx_m4 sx_r4_unordered(sx_r4 a, sx_r4 b) { return _mm_cmpunord_ps(a, b); }

static SX_ALWAYS_INLINE sx_m4 sx_m4_and(sx_m4 a, sx_m4 b) { return _mm_and_ps(a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_m4_or(sx_m4 a, sx_m4 b) { return _mm_or_ps(a, b); }
/** !a && b per lane. */
static SX_ALWAYS_INLINE sx_m4 sx_m4_andnot(sx_m4 a, sx_m4 b) { return _mm_andnot_ps(a, b); }
/** Bit i set when lane i is true. */
static SX_ALWAYS_INLINE int sx_m4_bits(sx_m4 m) { return _mm_movemask_ps(m); }
/** m ? a : b per lane. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_select(sx_m4 m, sx_r4 a, sx_r4 b) {
    return _mm_or_ps(_mm_and_ps(m, a), _mm_andnot_ps(m, b));
}
/** Lane i of a. */
static SX_ALWAYS_INLINE sx_real sx_r4_lane(sx_r4 a, int i) {
    float out[4];
    _mm_storeu_ps(out, a);
    return out[i & 3];
}

#elif SX_SIMD_F64 /* two registers of two doubles */

/** Four reals: lanes 0 and 1 in lo, 2 and 3 in hi. */
typedef struct sx_r4 {
    __m128d lo, hi;
} sx_r4;
/** Four lane masks (all bits set: true, all clear: false), halved alike. */
typedef sx_r4 sx_m4;

static SX_ALWAYS_INLINE sx_r4 sx_r4_halves(__m128d lo, __m128d hi) {
    sx_r4 r;
    r.lo = lo;
    r.hi = hi;
    return r;
}
/* One SSE2 operation on both halves. */
#define SX_PD(op, a, b) sx_r4_halves(op((a).lo, (b).lo), op((a).hi, (b).hi))

static SX_ALWAYS_INLINE sx_r4 sx_r4_set1(sx_real a) {
    __m128d d = _mm_set1_pd(a);
    return sx_r4_halves(d, d);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_set(sx_real a, sx_real b, sx_real c, sx_real d) {
    return sx_r4_halves(_mm_setr_pd(a, b), _mm_setr_pd(c, d));
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_zero(void) {
    return sx_r4_halves(_mm_setzero_pd(), _mm_setzero_pd());
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_load(const sx_real *p) {
    return sx_r4_halves(_mm_loadu_pd(p), _mm_loadu_pd(p + 2));
}
static SX_ALWAYS_INLINE void sx_r4_store(sx_real *p, sx_r4 a) {
    _mm_storeu_pd(p, a.lo);
    _mm_storeu_pd(p + 2, a.hi);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_add(sx_r4 a, sx_r4 b) { return SX_PD(_mm_add_pd, a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_sub(sx_r4 a, sx_r4 b) { return SX_PD(_mm_sub_pd, a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_mul(sx_r4 a, sx_r4 b) { return SX_PD(_mm_mul_pd, a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_div(sx_r4 a, sx_r4 b) { return SX_PD(_mm_div_pd, a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_sqrt(sx_r4 a) {
    return sx_r4_halves(_mm_sqrt_pd(a.lo), _mm_sqrt_pd(a.hi));
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_min(sx_r4 a, sx_r4 b) { return SX_PD(_mm_min_pd, a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_max(sx_r4 a, sx_r4 b) { return SX_PD(_mm_max_pd, a, b); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_neg(sx_r4 a) {
    return SX_PD(_mm_xor_pd, a, sx_r4_set1(SX_R(-0.0)));
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_abs(sx_r4 a) {
    return SX_PD(_mm_andnot_pd, sx_r4_set1(SX_R(-0.0)), a);
}

static SX_ALWAYS_INLINE sx_m4 sx_r4_lt(sx_r4 a, sx_r4 b) { return SX_PD(_mm_cmplt_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_le(sx_r4 a, sx_r4 b) { return SX_PD(_mm_cmple_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_gt(sx_r4 a, sx_r4 b) { return SX_PD(_mm_cmpgt_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_ge(sx_r4 a, sx_r4 b) { return SX_PD(_mm_cmpge_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_eq(sx_r4 a, sx_r4 b) { return SX_PD(_mm_cmpeq_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_unordered(sx_r4 a, sx_r4 b) {
    return SX_PD(_mm_cmpunord_pd, a, b);
}

static SX_ALWAYS_INLINE sx_m4 sx_m4_and(sx_m4 a, sx_m4 b) { return SX_PD(_mm_and_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_m4_or(sx_m4 a, sx_m4 b) { return SX_PD(_mm_or_pd, a, b); }
static SX_ALWAYS_INLINE sx_m4 sx_m4_andnot(sx_m4 a, sx_m4 b) { return SX_PD(_mm_andnot_pd, a, b); }
static SX_ALWAYS_INLINE int sx_m4_bits(sx_m4 m) {
    return _mm_movemask_pd(m.lo) | (_mm_movemask_pd(m.hi) << 2);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_select(sx_m4 m, sx_r4 a, sx_r4 b) {
    return sx_r4_halves(_mm_or_pd(_mm_and_pd(m.lo, a.lo), _mm_andnot_pd(m.lo, b.lo)),
                        _mm_or_pd(_mm_and_pd(m.hi, a.hi), _mm_andnot_pd(m.hi, b.hi)));
}
static SX_ALWAYS_INLINE sx_real sx_r4_lane(sx_r4 a, int i) {
    double out[4];
    sx_r4_store(out, a);
    return out[i & 3];
}

#undef SX_R4_PD
#undef SX_M4_PD

#else /* the portable lanes */

typedef struct sx_r4 {
    sx_real v[4];
} sx_r4;
typedef struct sx_m4 {
    int32_t m[4];
} sx_m4;

static SX_ALWAYS_INLINE sx_r4 sx_r4_set(sx_real a, sx_real b, sx_real c, sx_real d) {
    sx_r4 r;
    r.v[0] = a;
    r.v[1] = b;
    r.v[2] = c;
    r.v[3] = d;
    return r;
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_set1(sx_real a) { return sx_r4_set(a, a, a, a); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_zero(void) { return sx_r4_set1(SX_R(0.0)); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_load(const sx_real *p) {
    return sx_r4_set(p[0], p[1], p[2], p[3]);
}
static SX_ALWAYS_INLINE void sx_r4_store(sx_real *p, sx_r4 a) {
    p[0] = a.v[0];
    p[1] = a.v[1];
    p[2] = a.v[2];
    p[3] = a.v[3];
}

/* One lane-wise operation, written out once for every binary operator.
 * The four lanes are spelled out, not looped over: GCC at -O2 does not
 * unroll a loop of four, and the lanes would then live in memory. */
#define SX_R4_LANE(k, expr)                                                                        \
    {                                                                                              \
        const int i = k;                                                                           \
        r.v[k] = (expr);                                                                           \
    }
#define SX_R4_LANES(expr)                                                                          \
    sx_r4 r;                                                                                       \
    SX_R4_LANE(0, expr) SX_R4_LANE(1, expr) SX_R4_LANE(2, expr) SX_R4_LANE(3, expr) return r
#define SX_M4_LANE(k, expr)                                                                        \
    {                                                                                              \
        const int i = k;                                                                           \
        r.m[k] = (expr) ? -1 : 0;                                                                  \
    }
#define SX_M4_LANES(expr)                                                                          \
    sx_m4 r;                                                                                       \
    SX_M4_LANE(0, expr) SX_M4_LANE(1, expr) SX_M4_LANE(2, expr) SX_M4_LANE(3, expr) return r

static SX_ALWAYS_INLINE sx_r4 sx_r4_add(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] + b.v[i]); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_sub(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] - b.v[i]); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_mul(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] * b.v[i]); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_div(sx_r4 a, sx_r4 b) { SX_R4_LANES(a.v[i] / b.v[i]); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_sqrt(sx_r4 a) { SX_R4_LANES(sx_sqrt(a.v[i])); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_min(sx_r4 a, sx_r4 b) {
    SX_R4_LANES(a.v[i] < b.v[i] ? a.v[i] : b.v[i]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_max(sx_r4 a, sx_r4 b) {
    SX_R4_LANES(a.v[i] > b.v[i] ? a.v[i] : b.v[i]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_neg(sx_r4 a) { SX_R4_LANES(-a.v[i]); }
/* fabs clears the sign bit as SSE does (sx_absr keeps -0's) */
static SX_ALWAYS_INLINE sx_r4 sx_r4_abs(sx_r4 a) { SX_R4_LANES((sx_real)fabs((double)a.v[i])); }

static SX_ALWAYS_INLINE sx_m4 sx_r4_lt(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] < b.v[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_le(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] <= b.v[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_gt(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] > b.v[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_ge(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] >= b.v[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_eq(sx_r4 a, sx_r4 b) { SX_M4_LANES(a.v[i] == b.v[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_r4_unordered(sx_r4 a, sx_r4 b) {
    SX_M4_LANES(a.v[i] != a.v[i] || b.v[i] != b.v[i]);
}

static SX_ALWAYS_INLINE sx_m4 sx_m4_and(sx_m4 a, sx_m4 b) { SX_M4_LANES(a.m[i] && b.m[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_m4_or(sx_m4 a, sx_m4 b) { SX_M4_LANES(a.m[i] || b.m[i]); }
static SX_ALWAYS_INLINE sx_m4 sx_m4_andnot(sx_m4 a, sx_m4 b) { SX_M4_LANES(!a.m[i] && b.m[i]); }
static SX_ALWAYS_INLINE int sx_m4_bits(sx_m4 m) {
    return (m.m[0] ? 1 : 0) | (m.m[1] ? 2 : 0) | (m.m[2] ? 4 : 0) | (m.m[3] ? 8 : 0);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_select(sx_m4 m, sx_r4 a, sx_r4 b) {
    SX_R4_LANES(m.m[i] ? a.v[i] : b.v[i]);
}
static SX_ALWAYS_INLINE sx_real sx_r4_lane(sx_r4 a, int i) { return a.v[i & 3]; }

#undef SX_R4_LANE
#undef SX_R4_LANES
#undef SX_M4_LANE
#undef SX_M4_LANES

#endif /* SX_SIMD */

/* Built on the lanes above, so written once for both paths. */

/** a * b + c, rounded twice (no fused multiply-add: both paths agree). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_mul_add(sx_r4 a, sx_r4 b, sx_r4 c) {
    return sx_r4_add(sx_r4_mul(a, b), c);
}
/** lo <= a <= hi per lane (hi wins when lo > hi; NaN a gives lo). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_clamp(sx_r4 a, sx_r4 lo, sx_r4 hi) {
    return sx_r4_min(hi, sx_r4_max(a, lo));
}
/** True when any lane of m is. */
static SX_ALWAYS_INLINE bool sx_m4_any(sx_m4 m) { return sx_m4_bits(m) != 0; }
/** True when every lane of m is. */
static SX_ALWAYS_INLINE bool sx_m4_all(sx_m4 m) { return sx_m4_bits(m) == 15; }

/* ---- lane moves, integer lanes and reductions ---------------------------
 * What the narrowphase needs besides lane-wise arithmetic: points stored as
 * pairs of reals loaded two or four at a time, lanes moved in a fixed order
 * (named for the order, so that both paths move them alike), feature
 * indices kept in integer lanes beside the reals that choose them. */

#if SX_SIMD && !SX_SIMD_F64

/** Four 32-bit ints. */
typedef __m128i sx_i4;

/** [p[0], p[1], a2, a3]: two reals, 8 bytes, any alignment. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_load_low(sx_r4 a, const sx_real *p) {
    return _mm_loadl_pi(a, (const __m64 *)(const void *)p);
}
/** [a0, a1, p[0], p[1]]. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_load_high(sx_r4 a, const sx_real *p) {
    return _mm_loadh_pi(a, (const __m64 *)(const void *)p);
}
/** Lanes 0 and 1 of a to p[0], p[1]. */
static SX_ALWAYS_INLINE void sx_r4_store_low(sx_real *p, sx_r4 a) {
    _mm_storel_pi((__m64 *)(void *)p, a);
}
/** Lanes 2 and 3 of a to p[0], p[1]. */
static SX_ALWAYS_INLINE void sx_r4_store_high(sx_real *p, sx_r4 a) {
    _mm_storeh_pi((__m64 *)(void *)p, a);
}
/** Lane 0 of a. */
static SX_ALWAYS_INLINE sx_real sx_r4_first(sx_r4 a) { return _mm_cvtss_f32(a); }
/** [a1, a0, a3, a2]. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_swap_pairs(sx_r4 a) {
    return _mm_shuffle_ps(a, a, _MM_SHUFFLE(2, 3, 0, 1));
}
/** [a2, a3, a0, a1]. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_swap_halves(sx_r4 a) {
    return _mm_shuffle_ps(a, a, _MM_SHUFFLE(1, 0, 3, 2));
}
/** [a0, a1, b0, b1]. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_low_halves(sx_r4 a, sx_r4 b) { return _mm_movelh_ps(a, b); }
/** [a0, a1, b2, b3]. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_low_high(sx_r4 a, sx_r4 b) {
    return _mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 2, 1, 0));
}
/** [a0, a2, b0, b2]: the x of two pairs of points. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_evens(sx_r4 a, sx_r4 b) {
    return _mm_shuffle_ps(a, b, _MM_SHUFFLE(2, 0, 2, 0));
}
/** [a1, a3, b1, b3]: their y. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_odds(sx_r4 a, sx_r4 b) {
    return _mm_shuffle_ps(a, b, _MM_SHUFFLE(3, 1, 3, 1));
}
/** Lane 2 of a in every lane. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_splat2(sx_r4 a) {
    return _mm_shuffle_ps(a, a, _MM_SHUFFLE(2, 2, 2, 2));
}
/** Lane 3 of a in every lane. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_splat3(sx_r4 a) {
    return _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 3, 3, 3));
}
/** a with its sign bit flipped in the lanes where s is -0 (s: +0 or -0). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_flip_signs(sx_r4 a, sx_r4 s) { return _mm_xor_ps(a, s); }

static SX_ALWAYS_INLINE sx_i4 sx_i4_set1(int32_t a) { return _mm_set1_epi32(a); }
/** m ? a : b per lane. */
static SX_ALWAYS_INLINE sx_i4 sx_i4_select(sx_m4 m, sx_i4 a, sx_i4 b) {
    __m128i k = _mm_castps_si128(m);
    return _mm_or_si128(_mm_and_si128(k, a), _mm_andnot_si128(k, b));
}
/** Four ints to p[0..3], any alignment. */
static SX_ALWAYS_INLINE void sx_i4_store(int32_t *p, sx_i4 a) {
    _mm_storeu_si128((__m128i *)(void *)p, a);
}

/** Every lane true (all bits set). */
static SX_ALWAYS_INLINE sx_m4 sx_m4_true(void) { return _mm_castsi128_ps(_mm_set1_epi32(-1)); }
/** Rows a, b, c, d of a 4x4 matrix turned into its columns: a becomes
 *  [a0, b0, c0, d0], b [a1, b1, c1, d1], and so on (four records of four
 *  reals into four lanes of each field, and back). */
static SX_ALWAYS_INLINE void sx_r4_transpose(sx_r4 *a, sx_r4 *b, sx_r4 *c, sx_r4 *d) {
    __m128 t0 = _mm_unpacklo_ps(*a, *b), t1 = _mm_unpacklo_ps(*c, *d);
    __m128 t2 = _mm_unpackhi_ps(*a, *b), t3 = _mm_unpackhi_ps(*c, *d);
    *a = _mm_movelh_ps(t0, t1);
    *b = _mm_movehl_ps(t1, t0);
    *c = _mm_movelh_ps(t2, t3);
    *d = _mm_movehl_ps(t3, t2);
}

#elif SX_SIMD_F64

/** Four 32-bit ints. */
typedef __m128i sx_i4;

/* A point of sx_vec2 is one register's two doubles. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_load_low(sx_r4 a, const sx_real *p) {
    return sx_r4_halves(_mm_loadu_pd(p), a.hi);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_load_high(sx_r4 a, const sx_real *p) {
    return sx_r4_halves(a.lo, _mm_loadu_pd(p));
}
static SX_ALWAYS_INLINE void sx_r4_store_low(sx_real *p, sx_r4 a) { _mm_storeu_pd(p, a.lo); }
static SX_ALWAYS_INLINE void sx_r4_store_high(sx_real *p, sx_r4 a) { _mm_storeu_pd(p, a.hi); }
static SX_ALWAYS_INLINE sx_real sx_r4_first(sx_r4 a) { return _mm_cvtsd_f64(a.lo); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_swap_pairs(sx_r4 a) {
    return sx_r4_halves(_mm_shuffle_pd(a.lo, a.lo, 1), _mm_shuffle_pd(a.hi, a.hi, 1));
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_swap_halves(sx_r4 a) { return sx_r4_halves(a.hi, a.lo); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_low_halves(sx_r4 a, sx_r4 b) {
    return sx_r4_halves(a.lo, b.lo);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_low_high(sx_r4 a, sx_r4 b) { return sx_r4_halves(a.lo, b.hi); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_evens(sx_r4 a, sx_r4 b) {
    return sx_r4_halves(_mm_unpacklo_pd(a.lo, a.hi), _mm_unpacklo_pd(b.lo, b.hi));
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_odds(sx_r4 a, sx_r4 b) {
    return sx_r4_halves(_mm_unpackhi_pd(a.lo, a.hi), _mm_unpackhi_pd(b.lo, b.hi));
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_splat2(sx_r4 a) {
    __m128d d = _mm_unpacklo_pd(a.hi, a.hi);
    return sx_r4_halves(d, d);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_splat3(sx_r4 a) {
    __m128d d = _mm_unpackhi_pd(a.hi, a.hi);
    return sx_r4_halves(d, d);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_flip_signs(sx_r4 a, sx_r4 s) {
    return sx_r4_halves(_mm_xor_pd(a.lo, s.lo), _mm_xor_pd(a.hi, s.hi));
}

static SX_ALWAYS_INLINE sx_i4 sx_i4_set1(int32_t a) { return _mm_set1_epi32(a); }
static SX_ALWAYS_INLINE sx_i4 sx_i4_select(sx_m4 m, sx_i4 a, sx_i4 b) {
    /* The low 32 bits of each 64-bit mask, four to a register. */
    __m128i k = _mm_castps_si128(
        _mm_shuffle_ps(_mm_castpd_ps(m.lo), _mm_castpd_ps(m.hi), _MM_SHUFFLE(2, 0, 2, 0)));
    return _mm_or_si128(_mm_and_si128(k, a), _mm_andnot_si128(k, b));
}
static SX_ALWAYS_INLINE void sx_i4_store(int32_t *p, sx_i4 a) {
    _mm_storeu_si128((__m128i *)(void *)p, a);
}

/** Every lane true (all bits set). */
static SX_ALWAYS_INLINE sx_m4 sx_m4_true(void) {
    __m128d t = _mm_castsi128_pd(_mm_set1_epi32(-1));
    return sx_r4_halves(t, t);
}
/** sx_r4_transpose of the float build, on pairs of doubles. */
static SX_ALWAYS_INLINE void sx_r4_transpose(sx_r4 *a, sx_r4 *b, sx_r4 *c, sx_r4 *d) {
    sx_r4 ra = *a, rb = *b, rc = *c, rd = *d;
    *a = sx_r4_halves(_mm_unpacklo_pd(ra.lo, rb.lo), _mm_unpacklo_pd(rc.lo, rd.lo));
    *b = sx_r4_halves(_mm_unpackhi_pd(ra.lo, rb.lo), _mm_unpackhi_pd(rc.lo, rd.lo));
    *c = sx_r4_halves(_mm_unpacklo_pd(ra.hi, rb.hi), _mm_unpacklo_pd(rc.hi, rd.hi));
    *d = sx_r4_halves(_mm_unpackhi_pd(ra.hi, rb.hi), _mm_unpackhi_pd(rc.hi, rd.hi));
}

#else /* the portable lanes */

typedef struct sx_i4 {
    int32_t i[4];
} sx_i4;

static SX_ALWAYS_INLINE sx_r4 sx_r4_load_low(sx_r4 a, const sx_real *p) {
    return sx_r4_set(p[0], p[1], a.v[2], a.v[3]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_load_high(sx_r4 a, const sx_real *p) {
    return sx_r4_set(a.v[0], a.v[1], p[0], p[1]);
}
static SX_ALWAYS_INLINE void sx_r4_store_low(sx_real *p, sx_r4 a) {
    p[0] = a.v[0];
    p[1] = a.v[1];
}
static SX_ALWAYS_INLINE void sx_r4_store_high(sx_real *p, sx_r4 a) {
    p[0] = a.v[2];
    p[1] = a.v[3];
}
static SX_ALWAYS_INLINE sx_real sx_r4_first(sx_r4 a) { return a.v[0]; }
static SX_ALWAYS_INLINE sx_r4 sx_r4_swap_pairs(sx_r4 a) {
    return sx_r4_set(a.v[1], a.v[0], a.v[3], a.v[2]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_swap_halves(sx_r4 a) {
    return sx_r4_set(a.v[2], a.v[3], a.v[0], a.v[1]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_low_halves(sx_r4 a, sx_r4 b) {
    return sx_r4_set(a.v[0], a.v[1], b.v[0], b.v[1]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_low_high(sx_r4 a, sx_r4 b) {
    return sx_r4_set(a.v[0], a.v[1], b.v[2], b.v[3]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_evens(sx_r4 a, sx_r4 b) {
    return sx_r4_set(a.v[0], a.v[2], b.v[0], b.v[2]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_odds(sx_r4 a, sx_r4 b) {
    return sx_r4_set(a.v[1], a.v[3], b.v[1], b.v[3]);
}
static SX_ALWAYS_INLINE sx_r4 sx_r4_splat2(sx_r4 a) { return sx_r4_set1(a.v[2]); }
static SX_ALWAYS_INLINE sx_r4 sx_r4_splat3(sx_r4 a) { return sx_r4_set1(a.v[3]); }
/* Negation flips the sign bit alone in IEEE arithmetic, NaN and zero
 * included, as SSE2's exclusive or with -0 does. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_flip_signs(sx_r4 a, sx_r4 s) {
    return sx_r4_set(signbit(s.v[0]) ? -a.v[0] : a.v[0], signbit(s.v[1]) ? -a.v[1] : a.v[1],
                     signbit(s.v[2]) ? -a.v[2] : a.v[2], signbit(s.v[3]) ? -a.v[3] : a.v[3]);
}

static SX_ALWAYS_INLINE sx_i4 sx_i4_set1(int32_t a) {
    sx_i4 r;
    r.i[0] = r.i[1] = r.i[2] = r.i[3] = a;
    return r;
}
static SX_ALWAYS_INLINE sx_i4 sx_i4_select(sx_m4 m, sx_i4 a, sx_i4 b) {
    sx_i4 r;
    r.i[0] = m.m[0] ? a.i[0] : b.i[0];
    r.i[1] = m.m[1] ? a.i[1] : b.i[1];
    r.i[2] = m.m[2] ? a.i[2] : b.i[2];
    r.i[3] = m.m[3] ? a.i[3] : b.i[3];
    return r;
}
static SX_ALWAYS_INLINE void sx_i4_store(int32_t *p, sx_i4 a) {
    p[0] = a.i[0];
    p[1] = a.i[1];
    p[2] = a.i[2];
    p[3] = a.i[3];
}

static SX_ALWAYS_INLINE sx_m4 sx_m4_true(void) {
    sx_m4 r;
    r.m[0] = r.m[1] = r.m[2] = r.m[3] = -1;
    return r;
}
static SX_ALWAYS_INLINE void sx_r4_transpose(sx_r4 *a, sx_r4 *b, sx_r4 *c, sx_r4 *d) {
    sx_r4 ra = *a, rb = *b, rc = *c, rd = *d;
    *a = sx_r4_set(ra.v[0], rb.v[0], rc.v[0], rd.v[0]);
    *b = sx_r4_set(ra.v[1], rb.v[1], rc.v[1], rd.v[1]);
    *c = sx_r4_set(ra.v[2], rb.v[2], rc.v[2], rd.v[2]);
    *d = sx_r4_set(ra.v[3], rb.v[3], rc.v[3], rd.v[3]);
}

#endif /* SX_SIMD */

/** [p[0], p[1], 0, 0]. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_load2(const sx_real *p) {
    return sx_r4_load_low(sx_r4_zero(), p);
}
/** [lo[0], lo[1], hi[0], hi[1]]: two 8-byte loads, which two 8-byte stores
 *  still in flight can forward to (a 16-byte load of them cannot). */
static SX_ALWAYS_INLINE sx_r4 sx_r4_load2x2(const sx_real *lo, const sx_real *hi) {
    return sx_r4_load_high(sx_r4_load2(lo), hi);
}
/** The least lane of a in every lane: halves first, then pairs, with
 *  sx_r4_min's rule for NaN and signed zeros at each step. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_min_lanes(sx_r4 a) {
    a = sx_r4_min(a, sx_r4_swap_halves(a));
    return sx_r4_min(a, sx_r4_swap_pairs(a));
}
/** The largest lane of a in every lane, in sx_r4_min_lanes's order. */
static SX_ALWAYS_INLINE sx_r4 sx_r4_max_lanes(sx_r4 a) {
    a = sx_r4_max(a, sx_r4_swap_halves(a));
    return sx_r4_max(a, sx_r4_swap_pairs(a));
}
/** True when some lane of a is NaN. */
static SX_ALWAYS_INLINE bool sx_r4_any_nan(sx_r4 a) { return sx_m4_any(sx_r4_unordered(a, a)); }
/** True when no lane of a is NaN or infinite (a - a is 0 for those only). */
static SX_ALWAYS_INLINE bool sx_r4_all_finite(sx_r4 a) { return !sx_r4_any_nan(sx_r4_sub(a, a)); }

/* ---- the solver's lanes: SX_LANES wide ----------------------------------
 * The wide contact solver is written once against sx_rw (SX_LANES reals)
 * and sx_mw (their masks). Built with -mavx2 (make SIMD=avx2), the float
 * build maps them to one AVX register of eight floats and the double build
 * to one of four doubles (faster than sx_r4's two halves); every other
 * build maps them to sx_r4's four lanes. The operations are those of sx_r4
 * lane for lane (the same IEEE operations, SSE2's rules for min, max and
 * NaN in comparisons), so a lane answers alike in every width. */

#if SX_SIMD && !SX_SIMD_F64 && defined(__AVX2__)

#include <immintrin.h>

#define SX_LANES 8

/** SX_LANES reals. */
typedef __m256 sx_rw;
/** SX_LANES lane masks (all bits set: true, all clear: false). */
typedef __m256 sx_mw;

static SX_ALWAYS_INLINE sx_rw sx_rw_set1(sx_real a) { return _mm256_set1_ps(a); }
static SX_ALWAYS_INLINE sx_rw sx_rw_zero(void) { return _mm256_setzero_ps(); }
/** SX_LANES reals from memory, any alignment. */
static SX_ALWAYS_INLINE sx_rw sx_rw_load(const sx_real *p) { return _mm256_loadu_ps(p); }
static SX_ALWAYS_INLINE void sx_rw_store(sx_real *p, sx_rw a) { _mm256_storeu_ps(p, a); }
static SX_ALWAYS_INLINE sx_rw sx_rw_add(sx_rw a, sx_rw b) { return _mm256_add_ps(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_sub(sx_rw a, sx_rw b) { return _mm256_sub_ps(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_mul(sx_rw a, sx_rw b) { return _mm256_mul_ps(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_div(sx_rw a, sx_rw b) { return _mm256_div_ps(a, b); }
/** sx_r4_min's rule: b when either is NaN. */
static SX_ALWAYS_INLINE sx_rw sx_rw_min(sx_rw a, sx_rw b) { return _mm256_min_ps(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_max(sx_rw a, sx_rw b) { return _mm256_max_ps(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_neg(sx_rw a) { return _mm256_xor_ps(a, _mm256_set1_ps(-0.0f)); }

/* The ordered, signalling predicates: SSE2's cmplt, cmple and their
 * swapped forms (false when either is NaN). */
static SX_ALWAYS_INLINE sx_mw sx_rw_lt(sx_rw a, sx_rw b) { return _mm256_cmp_ps(a, b, _CMP_LT_OS); }
static SX_ALWAYS_INLINE sx_mw sx_rw_le(sx_rw a, sx_rw b) { return _mm256_cmp_ps(a, b, _CMP_LE_OS); }
static SX_ALWAYS_INLINE sx_mw sx_rw_gt(sx_rw a, sx_rw b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
static SX_ALWAYS_INLINE sx_mw sx_rw_ge(sx_rw a, sx_rw b) { return _mm256_cmp_ps(a, b, _CMP_GE_OS); }

static SX_ALWAYS_INLINE sx_mw sx_mw_and(sx_mw a, sx_mw b) { return _mm256_and_ps(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_or(sx_mw a, sx_mw b) { return _mm256_or_ps(a, b); }
/** !a && b per lane. */
static SX_ALWAYS_INLINE sx_mw sx_mw_andnot(sx_mw a, sx_mw b) { return _mm256_andnot_ps(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_true(void) {
    return _mm256_castsi256_ps(_mm256_set1_epi32(-1));
}
/** Bit i set when lane i is true. */
static SX_ALWAYS_INLINE int sx_mw_bits(sx_mw m) { return _mm256_movemask_ps(m); }
/** m ? a : b per lane. */
static SX_ALWAYS_INLINE sx_rw sx_rw_select(sx_mw m, sx_rw a, sx_rw b) {
    return _mm256_blendv_ps(b, a, m);
}

/* The 4x4 transpose of sx_r4_transpose within each 128-bit half. */
static SX_ALWAYS_INLINE void sx_rw_transpose_halves(sx_rw *a, sx_rw *b, sx_rw *c, sx_rw *d) {
    __m256 t0 = _mm256_unpacklo_ps(*a, *b), t1 = _mm256_unpacklo_ps(*c, *d);
    __m256 t2 = _mm256_unpackhi_ps(*a, *b), t3 = _mm256_unpackhi_ps(*c, *d);
    *a = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(1, 0, 1, 0));
    *b = _mm256_shuffle_ps(t0, t1, _MM_SHUFFLE(3, 2, 3, 2));
    *c = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(1, 0, 1, 0));
    *d = _mm256_shuffle_ps(t2, t3, _MM_SHUFFLE(3, 2, 3, 2));
}
/** Records of four reals (base + 4 idx[l], l < SX_LANES) turned into lanes:
 *  *a holds every record's first real, *b the second, and so on. */
static SX_ALWAYS_INLINE void sx_rw_gather4(const sx_real *base, const int *idx, sx_rw *a, sx_rw *b,
                                           sx_rw *c, sx_rw *d) {
    /* records l and l + 4 share a register, one per half */
    *a = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + 4 * idx[0])),
                              _mm_loadu_ps(base + 4 * idx[4]), 1);
    *b = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + 4 * idx[1])),
                              _mm_loadu_ps(base + 4 * idx[5]), 1);
    *c = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + 4 * idx[2])),
                              _mm_loadu_ps(base + 4 * idx[6]), 1);
    *d = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(base + 4 * idx[3])),
                              _mm_loadu_ps(base + 4 * idx[7]), 1);
    sx_rw_transpose_halves(a, b, c, d);
}
/** sx_rw_gather4 from records anywhere: lane l's four reals at rec[l]. */
static SX_ALWAYS_INLINE void sx_rw_gather4p(const sx_real *const *rec, sx_rw *a, sx_rw *b,
                                            sx_rw *c, sx_rw *d) {
    *a = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(rec[0])), _mm_loadu_ps(rec[4]), 1);
    *b = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(rec[1])), _mm_loadu_ps(rec[5]), 1);
    *c = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(rec[2])), _mm_loadu_ps(rec[6]), 1);
    *d = _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(rec[3])), _mm_loadu_ps(rec[7]), 1);
    sx_rw_transpose_halves(a, b, c, d);
}
/** sx_rw_gather4 backwards: lane l of a, b, c, d to record idx[l], in lane
 *  order (a record named twice keeps its last lane's values). */
static SX_ALWAYS_INLINE void sx_rw_scatter4(sx_real *base, const int *idx, sx_rw a, sx_rw b,
                                            sx_rw c, sx_rw d) {
    sx_rw_transpose_halves(&a, &b, &c, &d);
    _mm_storeu_ps(base + 4 * idx[0], _mm256_castps256_ps128(a));
    _mm_storeu_ps(base + 4 * idx[1], _mm256_castps256_ps128(b));
    _mm_storeu_ps(base + 4 * idx[2], _mm256_castps256_ps128(c));
    _mm_storeu_ps(base + 4 * idx[3], _mm256_castps256_ps128(d));
    _mm_storeu_ps(base + 4 * idx[4], _mm256_extractf128_ps(a, 1));
    _mm_storeu_ps(base + 4 * idx[5], _mm256_extractf128_ps(b, 1));
    _mm_storeu_ps(base + 4 * idx[6], _mm256_extractf128_ps(c, 1));
    _mm_storeu_ps(base + 4 * idx[7], _mm256_extractf128_ps(d, 1));
}

#elif SX_SIMD_F64 && defined(__AVX2__)

#include <immintrin.h>

/* The double build with -mavx2: four lanes still, in one register of four
 * doubles instead of sx_r4's two of two. */
#define SX_LANES 4

typedef __m256d sx_rw;
typedef __m256d sx_mw;

static SX_ALWAYS_INLINE sx_rw sx_rw_set1(sx_real a) { return _mm256_set1_pd(a); }
static SX_ALWAYS_INLINE sx_rw sx_rw_zero(void) { return _mm256_setzero_pd(); }
static SX_ALWAYS_INLINE sx_rw sx_rw_load(const sx_real *p) { return _mm256_loadu_pd(p); }
static SX_ALWAYS_INLINE void sx_rw_store(sx_real *p, sx_rw a) { _mm256_storeu_pd(p, a); }
static SX_ALWAYS_INLINE sx_rw sx_rw_add(sx_rw a, sx_rw b) { return _mm256_add_pd(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_sub(sx_rw a, sx_rw b) { return _mm256_sub_pd(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_mul(sx_rw a, sx_rw b) { return _mm256_mul_pd(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_div(sx_rw a, sx_rw b) { return _mm256_div_pd(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_min(sx_rw a, sx_rw b) { return _mm256_min_pd(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_max(sx_rw a, sx_rw b) { return _mm256_max_pd(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_neg(sx_rw a) { return _mm256_xor_pd(a, _mm256_set1_pd(-0.0)); }
static SX_ALWAYS_INLINE sx_mw sx_rw_lt(sx_rw a, sx_rw b) { return _mm256_cmp_pd(a, b, _CMP_LT_OS); }
static SX_ALWAYS_INLINE sx_mw sx_rw_le(sx_rw a, sx_rw b) { return _mm256_cmp_pd(a, b, _CMP_LE_OS); }
static SX_ALWAYS_INLINE sx_mw sx_rw_gt(sx_rw a, sx_rw b) { return _mm256_cmp_pd(a, b, _CMP_GT_OS); }
static SX_ALWAYS_INLINE sx_mw sx_rw_ge(sx_rw a, sx_rw b) { return _mm256_cmp_pd(a, b, _CMP_GE_OS); }
static SX_ALWAYS_INLINE sx_mw sx_mw_and(sx_mw a, sx_mw b) { return _mm256_and_pd(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_or(sx_mw a, sx_mw b) { return _mm256_or_pd(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_andnot(sx_mw a, sx_mw b) { return _mm256_andnot_pd(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_true(void) {
    return _mm256_castsi256_pd(_mm256_set1_epi32(-1));
}
static SX_ALWAYS_INLINE int sx_mw_bits(sx_mw m) { return _mm256_movemask_pd(m); }
static SX_ALWAYS_INLINE sx_rw sx_rw_select(sx_mw m, sx_rw a, sx_rw b) {
    return _mm256_blendv_pd(b, a, m);
}
/* A 4x4 transpose of doubles: pairs within each half, then the halves. */
static SX_ALWAYS_INLINE void sx_rw_transpose(sx_rw *a, sx_rw *b, sx_rw *c, sx_rw *d) {
    __m256d t0 = _mm256_unpacklo_pd(*a, *b), t1 = _mm256_unpackhi_pd(*a, *b);
    __m256d t2 = _mm256_unpacklo_pd(*c, *d), t3 = _mm256_unpackhi_pd(*c, *d);
    *a = _mm256_permute2f128_pd(t0, t2, 0x20);
    *b = _mm256_permute2f128_pd(t1, t3, 0x20);
    *c = _mm256_permute2f128_pd(t0, t2, 0x31);
    *d = _mm256_permute2f128_pd(t1, t3, 0x31);
}
static SX_ALWAYS_INLINE void sx_rw_gather4(const sx_real *base, const int *idx, sx_rw *a, sx_rw *b,
                                           sx_rw *c, sx_rw *d) {
    *a = _mm256_loadu_pd(base + 4 * idx[0]);
    *b = _mm256_loadu_pd(base + 4 * idx[1]);
    *c = _mm256_loadu_pd(base + 4 * idx[2]);
    *d = _mm256_loadu_pd(base + 4 * idx[3]);
    sx_rw_transpose(a, b, c, d);
}
static SX_ALWAYS_INLINE void sx_rw_gather4p(const sx_real *const *rec, sx_rw *a, sx_rw *b,
                                            sx_rw *c, sx_rw *d) {
    *a = _mm256_loadu_pd(rec[0]);
    *b = _mm256_loadu_pd(rec[1]);
    *c = _mm256_loadu_pd(rec[2]);
    *d = _mm256_loadu_pd(rec[3]);
    sx_rw_transpose(a, b, c, d);
}
static SX_ALWAYS_INLINE void sx_rw_scatter4(sx_real *base, const int *idx, sx_rw a, sx_rw b,
                                            sx_rw c, sx_rw d) {
    sx_rw_transpose(&a, &b, &c, &d);
    _mm256_storeu_pd(base + 4 * idx[0], a);
    _mm256_storeu_pd(base + 4 * idx[1], b);
    _mm256_storeu_pd(base + 4 * idx[2], c);
    _mm256_storeu_pd(base + 4 * idx[3], d);
}

#else /* sx_r4's four lanes */

#define SX_LANES 4

typedef sx_r4 sx_rw;
typedef sx_m4 sx_mw;

static SX_ALWAYS_INLINE sx_rw sx_rw_set1(sx_real a) { return sx_r4_set1(a); }
static SX_ALWAYS_INLINE sx_rw sx_rw_zero(void) { return sx_r4_zero(); }
static SX_ALWAYS_INLINE sx_rw sx_rw_load(const sx_real *p) { return sx_r4_load(p); }
static SX_ALWAYS_INLINE void sx_rw_store(sx_real *p, sx_rw a) { sx_r4_store(p, a); }
static SX_ALWAYS_INLINE sx_rw sx_rw_add(sx_rw a, sx_rw b) { return sx_r4_add(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_sub(sx_rw a, sx_rw b) { return sx_r4_sub(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_mul(sx_rw a, sx_rw b) { return sx_r4_mul(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_div(sx_rw a, sx_rw b) { return sx_r4_div(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_min(sx_rw a, sx_rw b) { return sx_r4_min(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_max(sx_rw a, sx_rw b) { return sx_r4_max(a, b); }
static SX_ALWAYS_INLINE sx_rw sx_rw_neg(sx_rw a) { return sx_r4_neg(a); }
static SX_ALWAYS_INLINE sx_mw sx_rw_lt(sx_rw a, sx_rw b) { return sx_r4_lt(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_rw_le(sx_rw a, sx_rw b) { return sx_r4_le(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_rw_gt(sx_rw a, sx_rw b) { return sx_r4_gt(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_rw_ge(sx_rw a, sx_rw b) { return sx_r4_ge(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_and(sx_mw a, sx_mw b) { return sx_m4_and(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_or(sx_mw a, sx_mw b) { return sx_m4_or(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_andnot(sx_mw a, sx_mw b) { return sx_m4_andnot(a, b); }
static SX_ALWAYS_INLINE sx_mw sx_mw_true(void) { return sx_m4_true(); }
static SX_ALWAYS_INLINE int sx_mw_bits(sx_mw m) { return sx_m4_bits(m); }
static SX_ALWAYS_INLINE sx_rw sx_rw_select(sx_mw m, sx_rw a, sx_rw b) {
    return sx_r4_select(m, a, b);
}
static SX_ALWAYS_INLINE void sx_rw_gather4(const sx_real *base, const int *idx, sx_rw *a, sx_rw *b,
                                           sx_rw *c, sx_rw *d) {
    *a = sx_r4_load(base + 4 * idx[0]);
    *b = sx_r4_load(base + 4 * idx[1]);
    *c = sx_r4_load(base + 4 * idx[2]);
    *d = sx_r4_load(base + 4 * idx[3]);
    sx_r4_transpose(a, b, c, d);
}
static SX_ALWAYS_INLINE void sx_rw_gather4p(const sx_real *const *rec, sx_rw *a, sx_rw *b,
                                            sx_rw *c, sx_rw *d) {
    *a = sx_r4_load(rec[0]);
    *b = sx_r4_load(rec[1]);
    *c = sx_r4_load(rec[2]);
    *d = sx_r4_load(rec[3]);
    sx_r4_transpose(a, b, c, d);
}
static SX_ALWAYS_INLINE void sx_rw_scatter4(sx_real *base, const int *idx, sx_rw a, sx_rw b,
                                            sx_rw c, sx_rw d) {
    sx_r4_transpose(&a, &b, &c, &d);
    sx_r4_store(base + 4 * idx[0], a);
    sx_r4_store(base + 4 * idx[1], b);
    sx_r4_store(base + 4 * idx[2], c);
    sx_r4_store(base + 4 * idx[3], d);
}

#endif /* SX_LANES */

/** True when any lane of m is. */
static SX_ALWAYS_INLINE bool sx_mw_any(sx_mw m) { return sx_mw_bits(m) != 0; }
/** True when every lane of m is. */
static SX_ALWAYS_INLINE bool sx_mw_all(sx_mw m) { return sx_mw_bits(m) == (1 << SX_LANES) - 1; }
/** Lane i of a (i < SX_LANES). */
static SX_ALWAYS_INLINE sx_real sx_rw_lane(sx_rw a, int i) {
    sx_real out[SX_LANES];
    sx_rw_store(out, a);
    return out[i & (SX_LANES - 1)];
}

#endif /* SEPAX_SIMD_H */
