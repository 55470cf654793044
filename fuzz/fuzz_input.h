/* sepax fuzzing — shared decoding of fuzzer bytes into reals, points,
 * transforms and shapes, and the invariant check used by every harness.
 *
 * The harnesses take libFuzzer's byte string and read it front to back: each
 * value is one tag byte saying what kind of number follows (a small grid
 * value, a raw bit pattern, NaN, an infinity, a huge or tiny magnitude, a
 * repeat of the previous value, a value one rounding step away from it) and
 * its payload. Most tags give small grid values, so random bytes produce
 * shapes that actually touch and the hostile values appear often enough to
 * be tried everywhere. A string that runs out reads as zeros, so every input
 * decodes to something. The same file builds the libFuzzer targets (clang,
 * make fuzz) and the corpus replay test (gcc, make test); only FZ_FAIL
 * differs: abort() for libFuzzer, a cmocka failure in the replay. */
#ifndef SEPAX_FUZZ_INPUT_H
#define SEPAX_FUZZ_INPUT_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sepax/sepax.h"

/* Reports a broken invariant. libFuzzer treats the abort as a crash and
 * saves the input; the replay test defines its own FZ_FAIL. */
#ifndef FZ_FAIL
#define FZ_FAIL(expr, file, line)                                                                  \
    (fprintf(stderr, "sepax fuzz: invariant broken: %s (%s:%d)\n", expr, file, line), abort())
#endif
#define FZ_CHECK(c)                                                                                \
    do {                                                                                           \
        if (!(c)) FZ_FAIL(#c, __FILE__, __LINE__);                                                 \
    } while (0)

/* The byte reader. `prev` is the last real decoded, for repeats. */
typedef struct fz_reader {
    const uint8_t *data;
    size_t size, pos;
    sx_real prev;
} fz_reader;

static inline fz_reader fz_reader_make(const uint8_t *data, size_t size) {
    fz_reader r;
    r.data = data;
    r.size = size;
    r.pos = 0;
    r.prev = SX_R(0.0);
    return r;
}

static inline uint8_t fz_u8(fz_reader *r) { return r->pos < r->size ? r->data[r->pos++] : 0; }

static inline int fz_int8(fz_reader *r) { return (int)fz_u8(r) - 128; }

static inline int fz_int16(fz_reader *r) {
    int hi = fz_u8(r);
    return (hi << 8 | fz_u8(r)) - 32768;
}

/* A raw sx_real bit pattern (any NaN payload, denormals, the extremes). */
static inline sx_real fz_raw_real(fz_reader *r) {
    unsigned char bytes[sizeof(sx_real)];
    sx_real v;
    size_t i;
    for (i = 0; i < sizeof bytes; ++i)
        bytes[i] = fz_u8(r);
    memcpy(&v, bytes, sizeof v);
    return v;
}

/* Values where arithmetic tends to break: non-finite, the representable
 * extremes, magnitudes around the library's own scales and tolerances. */
static inline sx_real fz_special(unsigned k) {
    switch (k % 20u) {
    case 0: return (sx_real)NAN;
    case 1: return (sx_real)INFINITY;
    case 2: return -(sx_real)INFINITY;
    case 3: return SX_REAL_MAX;
    case 4: return -SX_REAL_MAX;
    case 5: return SX_REAL_EPSILON;
    case 6: return (sx_real)FLT_MIN;
    case 7: return (sx_real)FLT_MIN * SX_R(1e-3); /* a denormal */
    case 8: return SX_HUGE;
    case 9: return -SX_HUGE;
    case 10: return SX_LINEAR_SLOP;
    case 11: return SX_WELD_TOLERANCE;
    case 12: return -SX_R(0.0);
    case 13: return SX_R(1e30);
    case 14: return -SX_R(1e30);
    case 15: return SX_R(1e-30);
    case 16: return sx_sqrt(SX_REAL_MAX);
    case 17: return SX_PI;
    case 18: return SX_R(0.5) * SX_WELD_TOLERANCE;
    default: return SX_R(1.0) + SX_REAL_EPSILON;
    }
}

/* One real: a tag byte, then its payload. */
static inline sx_real fz_real(fz_reader *r) {
    uint8_t tag = fz_u8(r);
    sx_real v;
    switch (tag % 16u) {
    case 6: v = (sx_real)fz_int16(r) / SX_R(256.0); break;
    case 7: v = fz_raw_real(r); break;
    case 8: v = fz_special(fz_u8(r)); break;
    case 9: v = r->prev; break;
    case 10: /* a few rounding steps away from the previous value */
        v = r->prev + (sx_real)fz_int8(r) * SX_REAL_EPSILON * sx_maxr(sx_absr(r->prev), SX_R(1.0));
        break;
    case 11: v = (sx_real)fz_int8(r) * SX_R(1e4); break;
    case 12: v = (sx_real)fz_int8(r) * SX_R(1e-4); break;
    case 13: v = r->prev + (sx_real)fz_int8(r) * SX_WELD_TOLERANCE * SX_R(0.25); break;
    default: v = (sx_real)fz_int8(r) / SX_R(8.0); break;
    }
    if (sx_is_finite(v)) r->prev = v;
    return v;
}

static inline sx_vec2 fz_vec2(fz_reader *r) {
    sx_vec2 v;
    v.x = fz_real(r);
    v.y = fz_real(r);
    return v;
}

/* A transform: usually from an angle (NaN and infinite angles included),
 * sometimes a raw, possibly non-unit rotation. *sane is true when the
 * transform is finite and its rotation came from a finite angle. */
static inline sx_xform fz_xform(fz_reader *r, bool *sane) {
    sx_xform x;
    uint8_t mode = fz_u8(r);
    x.p = fz_vec2(r);
    if (mode % 8u == 7u) {
        x.q.c = fz_real(r);
        x.q.s = fz_real(r);
        *sane = false;
    } else {
        sx_real angle = mode % 8u == 0u ? SX_R(0.0) : fz_real(r);
        x.q = sx_rot_make(angle);
        *sane = sx_is_finite(angle);
    }
    *sane = *sane && sx_xform_is_finite(x);
    return x;
}

/* Most points a decoded cloud or outline may have. */
#define FZ_MAX_POINTS 24

/* count points (count <= FZ_MAX_POINTS); sometimes as a small regular
 * polygon, so valid outlines and hulls are common. */
static inline int fz_points(fz_reader *r, sx_vec2 *points, int max_count) {
    int count = (int)(fz_u8(r) % (unsigned)(max_count + 1)), i;
    uint8_t mode = fz_u8(r);
    if (mode % 4u == 0u && count >= 3) {
        /* A regular polygon, then per-point perturbations. */
        sx_vec2 c = fz_vec2(r);
        sx_real radius = fz_real(r);
        for (i = 0; i < count; ++i) {
            sx_real a = SX_R(2.0) * SX_PI * (sx_real)i / (sx_real)count;
            points[i] = sx_add(c, sx_v2(radius * sx_cos(a), radius * sx_sin(a)));
            if (fz_u8(r) % 4u == 0u) points[i] = sx_add(points[i], fz_vec2(r));
        }
    } else {
        for (i = 0; i < count; ++i)
            points[i] = fz_vec2(r);
    }
    return count;
}

/* A shape of any type: valid ones through the constructors and builders,
 * and raw values (bad radius, garbage polygon fields, an unknown type). */
static inline sx_shape fz_shape(fz_reader *r) {
    sx_shape s;
    sx_vec2 pts[FZ_MAX_POINTS];
    uint8_t kind = fz_u8(r);
    memset(&s, 0, sizeof s);
    switch (kind % 9u) {
    case 0: {
        sx_vec2 c = fz_vec2(r);
        s = sx_circle_shape(c, fz_real(r));
        break;
    }
    case 1: {
        sx_vec2 a = fz_vec2(r);
        s = sx_segment_shape(a, fz_vec2(r));
        break;
    }
    case 2: {
        sx_vec2 a = fz_vec2(r), b = fz_vec2(r);
        s = sx_capsule_shape(a, b, fz_real(r));
        break;
    }
    case 3: {
        sx_real hw = fz_real(r);
        s = sx_box_shape(hw, fz_real(r));
        break;
    }
    case 4: {
        sx_real hw = fz_real(r), hh = fz_real(r);
        sx_vec2 c = fz_vec2(r);
        s = sx_offset_box_shape(hw, hh, c, fz_real(r));
        break;
    }
    case 5:
    case 6: {
        int n = fz_points(r, pts, SX_MAX_POLYGON_VERTICES + 4);
        sx_real radius = kind % 9u == 6u ? fz_real(r) : SX_R(0.0);
        if (sx_polygon_shape(pts, n, radius, &s) != SX_OK) s = sx_box_shape(SX_R(0.5), SX_R(0.25));
        break;
    }
    case 7: { /* raw polygon fields: garbage count, points, normals */
        int i;
        s.type = SX_SHAPE_POLYGON;
        s.u.polygon.count = (int)(fz_u8(r) % (SX_MAX_POLYGON_VERTICES + 4)) - 2;
        for (i = 0; i < SX_MAX_POLYGON_VERTICES; ++i)
            s.u.polygon.vertices[i] = fz_vec2(r);
        for (i = 0; i < SX_MAX_POLYGON_VERTICES; ++i)
            s.u.polygon.normals[i] = sx_normalize(fz_vec2(r));
        s.u.polygon.centroid = fz_vec2(r);
        s.u.polygon.radius = fz_real(r);
        break;
    }
    default: /* an unknown type tag */
        s = sx_point_shape(fz_vec2(r));
        s.type = (sx_shape_type)(SX_SHAPE_TYPE_COUNT + (int)(fz_u8(r) % 3u));
        break;
    }
    return s;
}

/* ---- checks ------------------------------------------------------------- */

static inline bool fz_finite_vec(sx_vec2 v) { return sx_vec2_is_finite(v); }

/* Unit within what a normalisation in sx_real precision can round to. */
static inline bool fz_is_unit(sx_vec2 v) {
    sx_real e = sx_absr(sx_length(v) - SX_R(1.0));
    return sx_vec2_is_finite(v) && e <= SX_R(64.0) * SX_REAL_EPSILON;
}

static inline bool fz_same_bits(sx_vec2 a, sx_vec2 b) { return memcmp(&a, &b, sizeof a) == 0; }

/* The largest coordinate magnitude in a point set (0 for none). */
static inline sx_real fz_extent(const sx_vec2 *p, int count) {
    sx_real m = SX_R(0.0);
    int i;
    for (i = 0; i < count; ++i)
        m = sx_maxr(m, sx_maxr(sx_absr(p[i].x), sx_absr(p[i].y)));
    return m;
}

static inline bool fz_all_finite(const sx_vec2 *p, int count) {
    int i;
    for (i = 0; i < count; ++i)
        if (!sx_vec2_is_finite(p[i])) return false;
    return true;
}

static inline bool fz_is_nan(sx_real v) { return v != v; }

static inline bool fz_aabb_has_nan(sx_aabb b) {
    return fz_is_nan(b.lower.x) || fz_is_nan(b.lower.y) || fz_is_nan(b.upper.x) ||
           fz_is_nan(b.upper.y);
}

/* The largest magnitude among a shape's used coordinates and radius, so
 * "finite output" is only demanded of shapes within the range the library
 * promises (SX_HUGE); larger ones need only avoid NaN. */
static inline sx_real fz_shape_extent(const sx_shape *s) {
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        return sx_maxr(fz_extent(&s->u.circle.center, 1), sx_absr(s->u.circle.radius));
    case SX_SHAPE_SEGMENT:
        return sx_maxr(fz_extent(&s->u.segment.a, 1), fz_extent(&s->u.segment.b, 1));
    case SX_SHAPE_CAPSULE:
        return sx_maxr(sx_maxr(fz_extent(&s->u.capsule.a, 1), fz_extent(&s->u.capsule.b, 1)),
                       sx_absr(s->u.capsule.radius));
    case SX_SHAPE_POLYGON: {
        int n = s->u.polygon.count;
        n = n < 0 ? 0 : (n > SX_MAX_POLYGON_VERTICES ? SX_MAX_POLYGON_VERTICES : n);
        return sx_maxr(fz_extent(s->u.polygon.vertices, n), sx_absr(s->u.polygon.radius));
    }
    default: return SX_R(0.0);
    }
}

static inline bool fz_vec_eq(sx_vec2 a, sx_vec2 b) { return a.x == b.x && a.y == b.y; }

/* Equal by value (as the narrowphase's canonical order compares them): the
 * case where sx_mtv cannot tell the two orders apart. */
static inline bool fz_shapes_identical(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                       sx_xform xb) {
    int i;
    if (!fz_vec_eq(xa.p, xb.p) || xa.q.c != xb.q.c || xa.q.s != xb.q.s || a->type != b->type)
        return false;
    switch (a->type) {
    case SX_SHAPE_CIRCLE:
        return fz_vec_eq(a->u.circle.center, b->u.circle.center) &&
               a->u.circle.radius == b->u.circle.radius;
    case SX_SHAPE_SEGMENT:
        return fz_vec_eq(a->u.segment.a, b->u.segment.a) &&
               fz_vec_eq(a->u.segment.b, b->u.segment.b);
    case SX_SHAPE_CAPSULE:
        return fz_vec_eq(a->u.capsule.a, b->u.capsule.a) &&
               fz_vec_eq(a->u.capsule.b, b->u.capsule.b) &&
               a->u.capsule.radius == b->u.capsule.radius;
    case SX_SHAPE_POLYGON:
        if (a->u.polygon.count != b->u.polygon.count || a->u.polygon.radius != b->u.polygon.radius)
            return false;
        for (i = 0; i < a->u.polygon.count && i < SX_MAX_POLYGON_VERTICES; ++i)
            if (!fz_vec_eq(a->u.polygon.vertices[i], b->u.polygon.vertices[i])) return false;
        return true;
    default: return true;
    }
}

static inline bool fz_status_known(sx_status s) { return (unsigned)s < (unsigned)SX_STATUS_COUNT; }

#endif /* SEPAX_FUZZ_INPUT_H */
