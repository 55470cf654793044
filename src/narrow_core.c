/* sepax — the narrowphase core: overlap, exact penetration (MTV) and contact
 * manifolds of two rounded convex cores (see narrow.h) in one working frame.
 *
 * The idea: the Minkowski difference of two rounded cores is the difference
 * of the cores grown by ra + rb. If the cores overlap, the penetration depth
 * is the SAT minimum over the edge normals of both cores (those are the edge
 * normals of the cores' Minkowski difference) plus ra + rb. If the cores are
 * disjoint, the depth is ra + rb minus the core distance, along the
 * closest-point direction; with convex cores the closest pair is always a
 * vertex against an edge or a vertex, so a sweep over those pairs gives it
 * exactly. Both answers are exact up to rounding, which is what the MTV
 * promises. Two-point cores (segments) also get their direction as a "cap"
 * axis in the disjointness test, because a zero-area core makes the edge
 * normals alone an incomplete set (collinear segments, a point beyond the end
 * of a segment). Manifolds clip the incident face against the side planes of
 * the reference face (Sutherland-Hodgman), the reference face chosen by least
 * penetration with hysteresis in favour of A's face. For disjoint rounded
 * cores the closest-feature line gives the exact contact: a vertex-vertex
 * contact is that one point, and a face contact uses it for its deepest
 * point whenever clipping would report less than the exact depth. */
#include "narrow.h"

/* Disjoint rounded cores whose distance exceeds their best face separation
 * by no more than this are treated as a face contact (clipped, up to two
 * points) rather than a vertex contact. Aligned edges (a box resting exactly
 * on another, end points over end points) have distance == face separation
 * only up to rounding; 1 % of the slop catches them. The face normal then
 * differs from the exact direction by at most sqrt(2 x tolerance / distance)
 * radians, while the deepest point itself is the exact closest-feature
 * contact (see clip_face). */
#define SX_FACE_CONTACT_TOLERANCE (SX_R(0.01) * SX_LINEAR_SLOP)

/* A difference of two points computed from coordinates of magnitude `scale`
 * carries an error of a few ulps of scale; below 64 epsilon x scale its
 * direction is noise, and also a point counts as touching within it. */
#define SX_DIRECTION_EPSILON (SX_R(64.0) * SX_REAL_EPSILON)

/* ---- core builders ------------------------------------------------------ */

/* x == NULL keeps the shape's own frame (shape A). */
static sx_vec2 place_point(const sx_xform *x, sx_vec2 v) { return x ? sx_xform_point(*x, v) : v; }
static sx_vec2 place_vector(const sx_xform *x, sx_vec2 v) { return x ? sx_rotate(x->q, v) : v; }

static bool core_radius_ok(sx_real r) { return sx_is_finite(r) && r >= SX_R(0.0); }

#if !SX_NARROW_SSE
/* (x - x) summed over the coordinates of a vertex and its normal: exactly 0
 * when all are finite, NaN otherwise. Summed over a polygon, one branch
 * checks it whole. */
static inline sx_real finite_fold(sx_vec2 v, sx_vec2 m) {
    /* Grouped as a tree: the sums are 0 or NaN whatever the grouping, and
     * a chain of dependent additions is what this loop would wait on. */
    return ((v.x - v.x) + (v.y - v.y)) + ((m.x - m.x) + (m.y - m.y));
}
#endif

/* Builds the 2-point core a-b (or a 1-point core when a-b has no direction).
 * The normal is taken in the shape's frame and rotated, like polygon normals,
 * so it does not depend on the translation. */
static bool core_set_segment(sx_vec2 a, sx_vec2 b, sx_real radius, const sx_xform *x,
                             sx_core *out) {
    sx_real len;
    sx_vec2 t;
    if (!sx_vec2_is_finite(a) || !sx_vec2_is_finite(b)) return false;
    t = sx_normalize_len(sx_sub(b, a), &len);
    out->v = out->vs;
    out->n = out->ns;
    out->radius = radius;
    out->vs[0] = place_point(x, a);
    if (!sx_vec2_is_finite(out->vs[0])) return false;
    if (len == SX_R(0.0)) {
        out->count = 1;
        return true;
    }
    out->vs[1] = place_point(x, b);
    out->ns[0] = place_vector(x, sx_v2(t.y, -t.x));
    out->ns[1] = sx_neg(out->ns[0]);
    out->count = 2;
    return sx_vec2_is_finite(out->vs[1]) && sx_vec2_is_finite(out->ns[0]);
}

bool sx_core_from_segment(const sx_segment *s, const sx_xform *x, sx_core *out) {
    if (s == NULL) return false;
    return core_set_segment(s->a, s->b, SX_R(0.0), x, out);
}

bool sx_core_from_capsule(const sx_capsule *c, const sx_xform *x, sx_core *out) {
    if (c == NULL || !core_radius_ok(c->radius)) return false;
    return core_set_segment(c->a, c->b, c->radius, x, out);
}

#if SX_NARROW_SSE
/* sx_xform_point and sx_rotate of two vertices (and normals) at a time, each
 * lane computed as those compute it (c x - s y as c x + (-s) y, which IEEE
 * arithmetic makes the same number), so the placed values are bit for bit
 * the portable loop's. Stored 16 bytes at a time, the pairs best_face_sse
 * loads back, so the loads are forwarded from the stores. */
static inline __m128 sse_turn(__m128 c, __m128 s, __m128 v) {
    return _mm_add_ps(_mm_mul_ps(c, v),
                      _mm_mul_ps(s, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1))));
}

/* Places p by the transform x = [p.x, p.y, q.c, q.s] into out (count,
 * radius, storage and pointers). */
static inline void place_polygon_rel(const sx_polygon *p, __m128 x, sx_core *out) {
    int i, n = p->count;
    __m128 c = _mm_shuffle_ps(x, x, _MM_SHUFFLE(2, 2, 2, 2));
    __m128 s = _mm_xor_ps(_mm_shuffle_ps(x, x, _MM_SHUFFLE(3, 3, 3, 3)),
                          _mm_setr_ps(SX_R(-0.0), SX_R(0.0), SX_R(-0.0), SX_R(0.0)));
    __m128 t = _mm_movelh_ps(x, x);
    out->radius = p->radius;
    out->count = n;
    out->v = out->vs;
    out->n = out->ns;
    for (i = 0; i + 1 < n; i += 2) {
        __m128 v = _mm_loadu_ps(&p->vertices[i].x), m = _mm_loadu_ps(&p->normals[i].x);
        _mm_storeu_ps(&out->vs[i].x, _mm_add_ps(sse_turn(c, s, v), t));
        _mm_storeu_ps(&out->ns[i].x, sse_turn(c, s, m));
    }
    if (i < n) {
        __m128 v = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&p->vertices[i]);
        __m128 m = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&p->normals[i]);
        _mm_storel_pi((__m64 *)(void *)&out->vs[i], _mm_add_ps(sse_turn(c, s, v), t));
        _mm_storel_pi((__m64 *)(void *)&out->ns[i], sse_turn(c, s, m));
    }
}
#endif

bool sx_core_from_polygon(const sx_polygon *p, const sx_xform *x, sx_core *out) {
    int n;
    if (p == NULL || !core_radius_ok(p->radius)) return false;
    n = p->count;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return false;
    out->radius = p->radius;
    out->count = n;
    if (x == NULL) {
        /* Shape A is read in place: no copy. */
        out->v = p->vertices;
        out->n = p->normals;
    } else {
#if SX_NARROW_SSE
        place_polygon_rel(p, _mm_loadu_ps(&x->p.x), out);
#else
        sx_xform q = *x;
        int i;
        for (i = 0; i < n; ++i) {
            out->vs[i] = sx_xform_point(q, p->vertices[i]);
            out->ns[i] = sx_rotate(q.q, p->normals[i]);
        }
#endif
        out->v = out->vs;
        out->n = out->ns;
    }
    /* The values are checked by sx_core_values_finite, once the answer is
     * not "apart" (see narrow.h). */
    return true;
}

bool sx_core_values_finite(const sx_core *c) {
    return c->count < 3 || sx_polygon_values_finite(c->v, c->n, c->count);
}

bool sx_polygon_values_finite(const sx_vec2 *v0, const sx_vec2 *n0, int n) {
    int i;
#if SX_NARROW_SSE
    /* finite_fold two vertices at a time: lanes of 0 or NaN. */
    __m128 sum = _mm_setzero_ps(), v, m;
    for (i = 0; i + 1 < n; i += 2) {
        v = _mm_loadu_ps(&v0[i].x);
        m = _mm_loadu_ps(&n0[i].x);
        sum = _mm_add_ps(sum, _mm_add_ps(_mm_sub_ps(v, v), _mm_sub_ps(m, m)));
    }
    if (i < n) {
        v = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&v0[i]);
        m = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&n0[i]);
        sum = _mm_add_ps(sum, _mm_add_ps(_mm_sub_ps(v, v), _mm_sub_ps(m, m)));
    }
    return _mm_movemask_ps(_mm_cmpunord_ps(sum, sum)) == 0;
#else
    sx_real acc = SX_R(0.0), acc1 = SX_R(0.0);
    for (i = 0; i + 1 < n; i += 2) {
        acc += finite_fold(v0[i], n0[i]);
        acc1 += finite_fold(v0[i + 1], n0[i + 1]);
    }
    if (i < n) acc += finite_fold(v0[i], n0[i]);
    return acc + acc1 == SX_R(0.0);
#endif
}

/* ---- separating axes ---------------------------------------------------- */

static int face_count(const sx_core *c) { return c->count >= 2 ? c->count : 0; }

static int next_index(const sx_core *c, int i) { return i + 1 < c->count ? i + 1 : 0; }

/* Separation of q from face i of p: how far q's nearest point lies in front
 * of the face's line (negative: q reaches behind it). The loop is
 * branch-free (running minima and a running NaN flag), which matters: it is
 * the inner loop of every polygon pair. A NaN (a 0 x inf product of cores
 * beyond the range) makes the separation unknown, and NaN says so to
 * sat_run. */
static inline sx_real face_separation(const sx_core *p, int i, const sx_core *q) {
    sx_vec2 n = p->n[i], v = p->v[i];
    const sx_vec2 *qv = q->v;
    sx_real best0 = SX_REAL_MAX, best1 = SX_REAL_MAX, d0, d1;
    int j, count = q->count;
    bool nan = false;
    /* Two independent minima (even and odd vertices) halve the dependency
     * chain; an odd count repeats the last vertex. */
    for (j = 0; j + 1 < count; j += 2) {
        d0 = sx_dot(n, sx_sub(qv[j], v));
        d1 = sx_dot(n, sx_sub(qv[j + 1], v));
        nan |= (d0 != d0) | (d1 != d1);
        best0 = d0 < best0 ? d0 : best0;
        best1 = d1 < best1 ? d1 : best1;
    }
    if (j < count) {
        d0 = sx_dot(n, sx_sub(qv[j], v));
        nan |= d0 != d0;
        best0 = d0 < best0 ? d0 : best0;
    }
    if (nan) return (sx_real)NAN;
    return best1 < best0 ? best1 : best0;
}

/* Separation of q from the end caps of the 2-point core p, along p's
 * direction t (out of b) and -t (out of a); *axis gets the better one. */
static sx_real cap_separation(const sx_core *p, const sx_core *q, sx_vec2 *axis) {
    sx_vec2 t = sx_perp(p->n[0]);
    sx_real beyond_b = SX_REAL_MAX, beyond_a = SX_REAL_MAX;
    int j;
    for (j = 0; j < q->count; ++j) {
        sx_real sb = sx_dot(t, sx_sub(q->v[j], p->v[1]));
        sx_real sa = sx_dot(t, sx_sub(p->v[0], q->v[j]));
        if (sb < beyond_b) beyond_b = sb;
        if (sa < beyond_a) beyond_a = sa;
        if (sb != sb || sa != sa) return sb + sa; /* overflow: NaN, see sat_run */
    }
    if (beyond_b >= beyond_a) {
        *axis = t;
        return beyond_b;
    }
    *axis = sx_neg(t);
    return beyond_a;
}

/* "No face yet": below every separation, -inf included, so the first face
 * examined is always taken (the choice tests face < 0 first). */
#define SX_NO_SEPARATION (-(sx_real)INFINITY)

/* Per-vertex slots of the SAT's records: the SSE loops store eight lanes. */
#define SX_VERTEX_SLOTS (SX_MAX_POLYGON_VERTICES > 8 ? SX_MAX_POLYGON_VERTICES : 8)

typedef struct sx_sat {
    sx_real sep_a, sep_b; /* best separation over A's / B's faces (-inf: none) */
    int face_a, face_b;   /* their faces (-1: none) */
    sx_real sep;          /* best over every axis, caps included */
    sx_vec2 axis;         /* unit axis of sep, from A towards B */
    bool has_axes;
#if SX_NARROW_SSE
    /* mags bit 1: mag_b holds the lane-wise largest magnitudes of B's
     * coordinates (from the SAT's loads); bit 2: mag_a, A's. */
    int mags;
    __m128 mag_a, mag_b;
    /* When rows is set (two polygon cores, limit > 0): the separation of
     * each vertex of B from each face of A (rows_b, best_face_sse's rows)
     * and of A's vertices from B's faces (rows_a), for the closest-feature
     * sweep. */
    bool rows;
    __m128 rows_b[2 * SX_VERTEX_SLOTS], rows_a[2 * SX_VERTEX_SLOTS];
#endif
} sx_sat;

#if SX_NARROW_SSE
/* best_face with q's vertices four to a register (structure of arrays): the
 * same separations, each computed as face_separation computes it (no fused
 * operations, the same operand order), so the answers agree bit for bit up
 * to the sign of a zero minimum, which no caller can tell apart. q has 3 or
 * more vertices; lanes past its count repeat vertex 0, which cannot change a
 * minimum. */
static inline __m128 sse_vertex_pair(const sx_vec2 *v, int j, int m, __m128 v00) {
    if (j + 1 < m) return _mm_loadu_ps(&v[j].x);
    if (j < m) return _mm_loadl_pi(v00, (const __m64 *)(const void *)&v[j]);
    return v00;
}

/* The separations of q's vertices (x, y: four lanes each) from face i of p,
 * as face_separation computes them. */
static inline __m128 sse_face_lanes(const sx_core *p, int i, __m128 x, __m128 y) {
    __m128 nx = _mm_set1_ps(p->n[i].x), ny = _mm_set1_ps(p->n[i].y);
    __m128 vx = _mm_set1_ps(p->v[i].x), vy = _mm_set1_ps(p->v[i].y);
    return _mm_add_ps(_mm_mul_ps(nx, _mm_sub_ps(x, vx)), _mm_mul_ps(ny, _mm_sub_ps(y, vy)));
}

/* The least of four lanes (in lane 0), or NaN when a lane of `bad` is set. */
static inline sx_real sse_lane_min(__m128 lo, __m128 bad) {
    lo = _mm_min_ps(lo, _mm_shuffle_ps(lo, lo, _MM_SHUFFLE(1, 0, 3, 2)));
    lo = _mm_min_ps(lo, _mm_shuffle_ps(lo, lo, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_movemask_ps(bad) != 0 ? (sx_real)NAN : _mm_cvtss_f32(lo);
}

/* best_face with q's vertices four to a register. With track != 0, the
 * separations of q's vertices from each face i of p (the lanes, as
 * face_separation computes them) are also kept, in rows[2 i] (vertices
 * 0..3) and rows[2 i + 1] (4..7), for the closest-feature sweep; they are
 * complete when the call returns true. */
static SX_ALWAYS_INLINE bool best_face_sse(const sx_core *p, const sx_core *q, sx_real limit,
                                           sx_real *sep, int *face, sx_real *stop, int track,
                                           __m128 *rows, __m128 *qmag) {
    int i, n = p->count, m = q->count, f = 0;
    __m128 v0 = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&q->v[0]);
    __m128 v00 = _mm_movelh_ps(v0, v0);
    __m128 p0 = sse_vertex_pair(q->v, 0, m, v00), p1 = sse_vertex_pair(q->v, 2, m, v00);
    __m128 x0 = _mm_shuffle_ps(p0, p1, _MM_SHUFFLE(2, 0, 2, 0));
    __m128 y0 = _mm_shuffle_ps(p0, p1, _MM_SHUFFLE(3, 1, 3, 1));
    __m128 sign = _mm_set1_ps(SX_R(-0.0));
    sx_real best = SX_NO_SEPARATION, s;
    /* The lane-wise largest magnitudes of q's coordinates, from the values
     * loaded anyway (the clear-cut test's scale; padding repeats vertex 0). */
    *qmag = _mm_max_ps(_mm_andnot_ps(sign, p0), _mm_andnot_ps(sign, p1));
    if (m <= 4) {
        for (i = 0; i < n; ++i) {
            __m128 d = sse_face_lanes(p, i, x0, y0);
            s = sse_lane_min(d, _mm_cmpunord_ps(d, d));
            if (!(s <= limit)) {
                *stop = s;
                return false;
            }
            f = s > best ? i : f;
            best = s > best ? s : best;
            if (track) rows[2 * i] = d;
        }
    } else {
        __m128 p2 = sse_vertex_pair(q->v, 4, m, v00), p3 = sse_vertex_pair(q->v, 6, m, v00);
        __m128 x1 = _mm_shuffle_ps(p2, p3, _MM_SHUFFLE(2, 0, 2, 0));
        __m128 y1 = _mm_shuffle_ps(p2, p3, _MM_SHUFFLE(3, 1, 3, 1));
        *qmag = _mm_max_ps(*qmag, _mm_max_ps(_mm_andnot_ps(sign, p2), _mm_andnot_ps(sign, p3)));
        for (i = 0; i < n; ++i) {
            __m128 d0 = sse_face_lanes(p, i, x0, y0), d1 = sse_face_lanes(p, i, x1, y1);
            s = sse_lane_min(_mm_min_ps(d0, d1), _mm_cmpunord_ps(d0, d1));
            if (!(s <= limit)) {
                *stop = s;
                return false;
            }
            f = s > best ? i : f;
            best = s > best ? s : best;
            if (track) {
                rows[2 * i] = d0;
                rows[2 * i + 1] = d1;
            }
        }
    }
    *sep = best;
    *face = f;
    return true;
}

/* For each vertex j of q (count m) the face of p (n faces) that separates
 * it the most, the first of largest separation, and that separation, from
 * the rows best_face_sse kept: point_best_face's answer bit for bit (its
 * separations are these lanes; d > m ? d : m is _mm_max_ps(d, m)). */
static void sse_vertex_faces(const __m128 *rows, int n, int m, int *vface, sx_real *vsep) {
    int i;
    __m128 m0 = rows[0], m1 = rows[1];
    __m128i f0 = _mm_setzero_si128(), f1 = f0;
    for (i = 1; i < n; ++i) {
        __m128 d0 = rows[2 * i];
        __m128i g0 = _mm_castps_si128(_mm_cmpgt_ps(d0, m0)), fi = _mm_set1_epi32(i);
        m0 = _mm_max_ps(d0, m0);
        f0 = _mm_or_si128(_mm_and_si128(g0, fi), _mm_andnot_si128(g0, f0));
        if (m > 4) {
            __m128 d1 = rows[2 * i + 1];
            __m128i g1 = _mm_castps_si128(_mm_cmpgt_ps(d1, m1));
            m1 = _mm_max_ps(d1, m1);
            f1 = _mm_or_si128(_mm_and_si128(g1, fi), _mm_andnot_si128(g1, f1));
        }
    }
    _mm_storeu_ps(&vsep[0], m0);
    _mm_storeu_si128((__m128i *)(void *)&vface[0], f0);
    if (m > 4) {
        _mm_storeu_ps(&vsep[4], m1);
        _mm_storeu_si128((__m128i *)(void *)&vface[4], f1);
    }
}
#endif

/* The best face of p against q: the first of largest separation. Returns
 * false as soon as a face separates by more than limit (or by NaN), with
 * that separation in *stop. The running maximum is kept without a branch
 * (its comparisons go either way at random); the face index follows it. */
static SX_ALWAYS_INLINE bool best_face(const sx_core *p, const sx_core *q, sx_real limit,
                                       sx_real *sep, int *face, sx_real *stop, sx_sat *sat,
                                       int mag_bit) {
    int i, n = face_count(p), f = 0;
    sx_real best;
#if SX_NARROW_SSE
    if (n >= 3 && q->count >= 3) {
        sat->mags |= mag_bit;
        return best_face_sse(p, q, limit, sep, face, stop, 0, NULL,
                             mag_bit == 1 ? &sat->mag_b : &sat->mag_a);
    }
#else
    SX_UNUSED(sat);
    SX_UNUSED(mag_bit);
#endif
    if (n == 0) {
        *sep = SX_NO_SEPARATION;
        *face = -1;
        return true;
    }
    best = face_separation(p, 0, q);
    if (!(best <= limit)) {
        *stop = best;
        return false;
    }
    for (i = 1; i < n; ++i) {
        sx_real s = face_separation(p, i, q);
        if (!(s <= limit)) {
            *stop = s;
            return false;
        }
        f = s > best ? i : f;
        best = s > best ? s : best;
    }
    *sep = best;
    *face = f;
    return true;
}

/* The SAT's test of the caps of the 2-point core p against q (p is B when
 * p_is_b: the axis then turns to point from A to B). False, with the
 * separation in out->sep, when they separate by more than limit; otherwise
 * the caps' axis replaces out's when it separates more. */
static SX_ALWAYS_INLINE bool sat_caps(const sx_core *p, const sx_core *q, sx_real limit,
                                      bool p_is_b, sx_sat *out) {
    sx_vec2 axis;
    sx_real s = cap_separation(p, q, &axis);
    if (!(s <= limit)) {
        out->sep = s;
        return false;
    }
    if (s > out->sep) {
        out->sep = s;
        out->axis = p_is_b ? sx_neg(axis) : axis;
    }
    return true;
}

/* Runs SAT over the faces of both cores (and the caps when both have zero
 * area). Returns false as soon as an axis separates by more than `limit`
 * (the cores then lie farther apart than limit), and also when a separation
 * is NaN: coordinates near the top of the range overflowed (0 x inf), no
 * answer can be trusted, and "apart" is the one that needs no face. When it
 * returns true with has_axes, face_a or face_b is a valid face: every
 * separation is then a number (-inf included) and the first face is always
 * taken. */
static SX_ALWAYS_INLINE bool sat_run(const sx_core *a, const sx_core *b, sx_real limit,
                                     sx_sat *out) {
    int na = face_count(a), nb = face_count(b);
#if SX_NARROW_SSE
    out->rows = false;
    out->mags = 0;
    if (limit > SX_R(0.0) && na >= 3 && nb >= 3) {
        /* Cores apart by less than limit need their closest features,
         * whose sweep starts from each vertex's face of largest
         * separation: the SAT's lanes have what it needs. */
        out->mags = 1;
        if (!best_face_sse(a, b, limit, &out->sep_a, &out->face_a, &out->sep, 1, out->rows_b,
                           &out->mag_b)) {
            return false;
        }
        out->mags = 3;
        if (!best_face_sse(b, a, limit, &out->sep_b, &out->face_b, &out->sep, 1, out->rows_a,
                           &out->mag_a)) {
            return false;
        }
        out->rows = true;
    } else
#endif
    {
        if (!best_face(a, b, limit, &out->sep_a, &out->face_a, &out->sep, out, 1)) return false;
        if (!best_face(b, a, limit, &out->sep_b, &out->face_b, &out->sep, out, 2)) return false;
    }
    out->has_axes = na + nb > 0;
    out->axis = sx_v2_zero();
    if (out->face_a >= 0 && out->sep_a >= out->sep_b) {
        out->sep = out->sep_a;
        out->axis = a->n[out->face_a];
    } else if (out->face_b >= 0) {
        out->sep = out->sep_b;
        out->axis = sx_neg(b->n[out->face_b]);
    } else {
        out->sep = SX_NO_SEPARATION;
    }
    if (out->has_axes && a->count <= 2 && b->count <= 2) {
        if (a->count == 2 && !sat_caps(a, b, limit, false, out)) return false;
        if (b->count == 2 && !sat_caps(b, a, limit, true, out)) return false;
    }
    return true;
}

/* ---- closest features of disjoint cores --------------------------------- */

enum { SX_CLOSEST_VERTICES, SX_CLOSEST_FACE_A, SX_CLOSEST_FACE_B };

/* When a point projects just inside a face, its squared distances to the
 * face and to the face's end vertex agree to second order, and rounding of
 * the squares can make the vertex look closer; its direction would then be
 * off by up to sqrt(2 epsilon). Faces therefore win ties within a few ulps of
 * the squared distance: their direction, the face normal, is exact. */
#define SX_CLOSEST_TIE (SX_R(16.0) * SX_REAL_EPSILON)

typedef struct sx_closest {
    sx_real distance; /* core distance */
    sx_real dist_sq;  /* its square, the sweep's comparison key */
    sx_vec2 pa, pb;   /* closest points on the cores */
    sx_vec2 normal;   /* unit, A towards B; zero when it has no direction */
    int kind;         /* SX_CLOSEST_* */
    int ia, ib;       /* vertex indices (VERTICES), or the face index */
} sx_closest;

#if SX_NARROW_SSE
/* The lane-wise largest magnitudes of a core's points, two points a
 * register (unreduced: the caller folds the lanes once). */
static SX_ALWAYS_INLINE __m128 sse_core_magnitudes(const sx_core *c, __m128 m) {
    int i, n = c->count;
    __m128 sign = _mm_set1_ps(SX_R(-0.0));
    for (i = 0; i + 1 < n; i += 2)
        m = _mm_max_ps(m, _mm_andnot_ps(sign, _mm_loadu_ps(&c->v[i].x)));
    if (i < n) {
        m = _mm_max_ps(m, _mm_andnot_ps(sign, _mm_loadl_pi(_mm_setzero_ps(),
                                                           (const __m64 *)(const void *)&c->v[i])));
    }
    return m;
}
#else
/* Largest coordinate magnitude of a core's points. */
static sx_real core_scale(const sx_core *c) {
    sx_real m = SX_R(0.0);
    int i;
    for (i = 0; i < c->count; ++i)
        m = sx_maxr(m, sx_maxr(sx_magnitude(c->v[i].x), sx_magnitude(c->v[i].y)));
    return m;
}
#endif

/* Largest coordinate magnitude of the points of two cores. The largest
 * magnitude of finite values does not depend on the order it is taken in,
 * so the SSE loop's is the portable loop's; with a NaN or an infinity in a
 * core the two may differ, but such a core never gets a manifold point or
 * an overlap, whatever the tests that use this scale say. */
static SX_ALWAYS_INLINE sx_real core_pair_scale(const sx_core *a, const sx_core *b) {
#if SX_NARROW_SSE
    __m128 m = sse_core_magnitudes(b, sse_core_magnitudes(a, _mm_setzero_ps()));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtss_f32(m);
#else
    return sx_maxr(core_scale(a), core_scale(b));
#endif
}

/* core_pair_scale, with the magnitudes the SAT took (sat may be NULL). */
static SX_ALWAYS_INLINE sx_real sat_pair_scale(const sx_core *a, const sx_core *b,
                                               const sx_sat *sat) {
#if SX_NARROW_SSE
    __m128 m;
    if (sat == NULL) return core_pair_scale(a, b);
    m = (sat->mags & 1) ? sat->mag_b : sse_core_magnitudes(b, _mm_setzero_ps());
    m = (sat->mags & 2) ? _mm_max_ps(m, sat->mag_a) : sse_core_magnitudes(a, m);
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = _mm_max_ps(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtss_f32(m);
#else
    SX_UNUSED(sat);
    return core_pair_scale(a, b);
#endif
}

/* The slack of cannot_win: the rounding of a separation computed from
 * coordinates of magnitude `scale` (a few ulps of scale), of the placement
 * of B's points (a few more), and the lean a valid polygon's normals may
 * have (64 ulps of the edge's coordinates), with room to spare. */
#define SX_PRUNE_SLACK (SX_R(256.0) * SX_REAL_EPSILON)

/* Offers the pair (vertex q of one core, edge i of core p) to the sweep.
 * p_is_a says which core owns the edge. Where q projects on the edge is
 * measured along the edge direction of the face's normal, not along the
 * difference of the placed end points: a polygon placed far from the working
 * origin has its vertices rounded while its normals stay exact, and an edge
 * shorter than that rounding (a 5 mm edge at 1e5 m in float) points
 * anywhere; the face case would then take q's distance to the face's line
 * for a q far beyond the face's ends (a 16 m gap reported as 77 km).
 * Returns 0 when q lies over the face, -1 (1) when it lies before its first
 * (past its second) end, the corner offered; with walk (polygon p), 0 too
 * when q lies within that corner's region, past the end of the face beyond
 * the corner (offer_face_walk). */
static SX_ALWAYS_INLINE int offer_edge(const sx_core *p, int i, sx_vec2 q, int q_index, bool p_is_a,
                                       bool walk, sx_closest *best) {
    int i2 = next_index(p, i);
    sx_vec2 v1 = p->v[i], w = sx_sub(q, v1), n = p->n[i], dir = sx_v2(-n.y, n.x);
    sx_real t = sx_dot(w, dir);
    sx_vec2 on_p;
    sx_real dsq, s;
    int face = i, vertex = -1;
    if (t <= SX_R(0.0)) {
        vertex = i;
    } else if (t >= sx_dot(sx_sub(p->v[i2], v1), dir)) {
        vertex = i2;
    }
    if (vertex >= 0) {
        int side = vertex == i ? -1 : 1;
        if (walk) {
            /* q within the corner's region (past the end of the face past
             * the corner) settles the walk (offer_face_walk). */
            int past = vertex == i ? (i > 0 ? i - 1 : p->count - 1) : i2;
            sx_vec2 np = p->n[past];
            sx_real along = sx_dot(vertex == i ? w : sx_sub(q, p->v[i2]), sx_v2(-np.y, np.x));
            if (vertex == i ? along >= SX_R(0.0) : along <= SX_R(0.0)) side = 0;
        }
        on_p = p->v[vertex];
        dsq = sx_distance_sq(on_p, q);
        if (!(dsq < (best->kind == SX_CLOSEST_VERTICES
                         ? best->dist_sq
                         : best->dist_sq * (SX_R(1.0) - SX_CLOSEST_TIE)))) {
            return side;
        }
        best->dist_sq = dsq;
        best->kind = SX_CLOSEST_VERTICES;
        best->ia = p_is_a ? vertex : q_index;
        best->ib = p_is_a ? q_index : vertex;
        best->pa = p_is_a ? on_p : q;
        best->pb = p_is_a ? q : on_p;
        best->normal = sx_v2_zero();
        return side;
    }
    s = sx_dot(w, n);
    if (p->count == 2 && s < SX_R(0.0)) {
        n = p->n[1];
        s = -s;
        face = 1;
    }
    dsq = s * s;
    if (!(dsq < (best->kind == SX_CLOSEST_VERTICES ? best->dist_sq * (SX_R(1.0) + SX_CLOSEST_TIE)
                                                   : best->dist_sq))) {
        return 0;
    }
    on_p = sx_mul_sub(q, s, n);
    best->dist_sq = dsq;
    best->distance = sx_absr(s);
    best->kind = p_is_a ? SX_CLOSEST_FACE_A : SX_CLOSEST_FACE_B;
    best->ia = p_is_a ? face : q_index;
    best->ib = p_is_a ? q_index : face;
    best->pa = p_is_a ? on_p : q;
    best->pb = p_is_a ? q : on_p;
    best->normal = p_is_a ? n : sx_neg(n);
    return 0;
}

/* offer_edge for the face i of polygon core p (count >= 3) that separates q
 * the most, and, while q lies beyond an end of the face offered, the face
 * past that end. In exact arithmetic q then lies in the corner's region
 * and the next face only offers that corner again; but two faces that are
 * nearly one line separate q by amounts closer than their rounding (a far
 * vertex rounds both by its magnitude), and the face found largest may be
 * the one q lies beyond: its corner was then taken, metres from the point
 * on the neighbour face that q lies over (a 1.71 m gap reported as 7.96 m
 * beside a vertex at 1e5 m). The walk offers only real points of p, so it
 * can only bring the answer closer. */
static inline void offer_face_walk(const sx_core *p, int i, sx_vec2 q, int q_index, bool p_is_a,
                                   sx_closest *best) {
    int side = offer_edge(p, i, q, q_index, p_is_a, true, best), k;
    for (k = 1; side != 0 && k < p->count; ++k) {
        i = side < 0 ? (i > 0 ? i - 1 : p->count - 1) : next_index(p, i);
        if (offer_edge(p, i, q, q_index, p_is_a, true, best) != side) break;
    }
}

static inline sx_real max_abs_coord(sx_vec2 a, sx_vec2 b) {
    return sx_maxr(sx_maxr(sx_magnitude(a.x), sx_magnitude(a.y)),
                   sx_maxr(sx_magnitude(b.x), sx_magnitude(b.y)));
}

/* Completes a sweep: a vertex-vertex result gets its distance (the sweep
 * compares squares only, so the root is taken once) and its direction when
 * the points are apart by more than rounding noise. */
static void vertex_direction(sx_closest *c) {
    if (c->kind != SX_CLOSEST_VERTICES) return;
    c->distance = sx_sqrt(c->dist_sq);
    if (c->distance < SX_SQUARE_SAFE) {
        /* The square may have underflowed (points 1e-265 apart would be
         * touching): length and direction of the difference scaled by its
         * largest component instead (1 / distance may overflow here). */
        sx_vec2 d = sx_sub(c->pb, c->pa), u;
        sx_real m = sx_maxr(sx_absr(d.x), sx_absr(d.y)), len;
        if (!(m > SX_R(0.0))) {
            c->distance = SX_R(0.0);
            return;
        }
        u = sx_v2(d.x / m, d.y / m);
        len = sx_length(u);
        c->distance = m * len;
        if (c->distance > SX_DIRECTION_EPSILON * max_abs_coord(c->pa, c->pb)) {
            c->normal = sx_scale(u, SX_R(1.0) / len);
        }
        return;
    }
    if (c->distance > SX_DIRECTION_EPSILON * max_abs_coord(c->pa, c->pb)) {
        c->normal = sx_scale(sx_sub(c->pb, c->pa), SX_R(1.0) / c->distance);
    }
}

/* The face of polygon core p (count >= 3) that separates the point q the
 * most: the first of largest separation, kept without a branch. */
static inline int point_best_face(const sx_core *p, sx_vec2 q) {
    int i, f = 0;
    sx_real best = sx_dot(p->n[0], sx_sub(q, p->v[0]));
    for (i = 1; i < p->count; ++i) {
        sx_real s = sx_dot(p->n[i], sx_sub(q, p->v[i]));
        f = s > best ? i : f;
        best = s > best ? s : best;
    }
    return f;
}

/* True when the vertex q_j, separated by s from the face of p it is offered
 * to (its face of largest separation), cannot be accepted by the sweep as
 * it stands: every candidate offer_edge can make of it is at least s - slack
 * away, slack covering the rounding of s and of the placed vertices and the
 * lean of a valid polygon's normals (sx_shape_validate), and its square, less
 * its own rounding, is already no better than what the sweep would take.
 * Only with a finite best, so that no square near overflow is involved.
 * The bound holds for shapes that sx_shape_validate accepts placed by unit
 * rotations; for raw polygons with arbitrary normals, or raw rotations, the
 * sweep may then keep another candidate than the full sweep would (never a
 * NaN: only the choice among its candidates changes). */
static inline bool cannot_win(sx_real s, sx_real slack, const sx_closest *best) {
    sx_real lb = s - slack, lb2, thr;
    if (!(lb > SX_R(0.0)) || !(best->dist_sq < SX_REAL_MAX)) return false;
    lb2 = lb * lb;
    thr = best->kind == SX_CLOSEST_VERTICES ? best->dist_sq * (SX_R(1.0) + SX_CLOSEST_TIE)
                                            : best->dist_sq;
    return lb2 < SX_REAL_MAX && lb2 * (SX_R(1.0) - SX_R(16.0) * SX_REAL_EPSILON) >= thr;
}

/* Index of the lowest set bit of x (not 0). */
static inline int sx_lowest_bit(uint64_t x) {
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctzll(x);
#else
    int i = 0;
    while (!(x & 1u)) {
        x >>= 1;
        ++i;
    }
    return i;
#endif
}

/* Offers every vertex of q to the edges of p (p_is_a: p is A), edge-major.
 * A polygon p needs only one edge per vertex: for a point outside a convex
 * polygon the closest point lies on the face that separates it the most
 * (see point_closest below; every vertex of q is outside p, the cores being
 * disjoint), so the other edges cannot win the sweep (offer_face_walk adds
 * the faces past a corner, for a face chosen by rounding), and the sweep visits
 * the candidates that can in the order of the full sweep, edge-major, so
 * exact ties resolve as they did. vface and vsep (may be NULL) are each
 * vertex's face of largest separation and that separation, from the SAT;
 * with them, offers that cannot win the sweep (cannot_win) are skipped,
 * which changes nothing of its answer: an offer the sweep would not take
 * leaves it as it was. */
static void offer_vertices(const sx_core *p, const sx_core *q, bool p_is_a, sx_closest *out,
                           const int *vface, const sx_real *vsep, sx_real slack) {
    int i, j, edges = p->count >= 3 ? p->count : p->count - 1;
#if SX_MAX_POLYGON_VERTICES <= 8
    if (p->count >= 3) {
        /* Bit 8 face + j for each vertex j of q: the set bits, lowest
         * first, are the sweep's edge-major order (face, then vertex), and
         * the loop visits only them. */
        uint64_t order = 0u;
        for (j = 0; j < q->count; ++j) {
            int f = vface ? vface[j] : point_best_face(p, q->v[j]);
            order |= (uint64_t)1u << (8 * f + j);
        }
        while (order != 0u) {
            int bit = sx_lowest_bit(order);
            order &= order - 1u;
            i = bit >> 3;
            j = bit & 7;
            if (vsep != NULL && cannot_win(vsep[j], slack, out)) continue;
            offer_face_walk(p, i, q->v[j], j, p_is_a, out);
        }
        return;
    }
#else
    if (p->count >= 3) {
        for (i = 0; i < edges; ++i) {
            for (j = 0; j < q->count; ++j) {
                if ((vface ? vface[j] : point_best_face(p, q->v[j])) != i) continue;
                if (vsep != NULL && cannot_win(vsep[j], slack, out)) continue;
                offer_face_walk(p, i, q->v[j], j, p_is_a, out);
            }
        }
        return;
    }
#endif
    for (i = 0; i < edges; ++i) {
        for (j = 0; j < q->count; ++j)
            (void)offer_edge(p, i, q->v[j], j, p_is_a, false, out);
    }
}

/* Distance and closest features of two disjoint cores: every vertex of one
 * against the edges of the other (A's edges first, so ties keep A's face).
 * sat (may be NULL): the SAT's records, whose per-vertex faces (when it has
 * them) spare the sweep its own search and let it skip hopeless offers. */
static void closest_features(const sx_core *a, const sx_core *b, const sx_sat *sat,
                             sx_closest *out) {
    int ea = a->count >= 3 ? a->count : a->count - 1;
    int eb = b->count >= 3 ? b->count : b->count - 1;
    out->dist_sq = SX_REAL_MAX;
    out->distance = SX_REAL_MAX;
    out->kind = SX_CLOSEST_VERTICES;
    out->ia = 0;
    out->ib = 0;
    out->pa = a->v[0];
    out->pb = b->v[0];
    out->normal = sx_v2_zero();
    SX_UNUSED(sat);
#if SX_NARROW_SSE
    if (sat != NULL && sat->rows) {
        sx_real slack = SX_PRUNE_SLACK * sat_pair_scale(a, b, sat);
        int vface[SX_VERTEX_SLOTS];
        sx_real vsep[SX_VERTEX_SLOTS];
        sse_vertex_faces(sat->rows_b, a->count, b->count, vface, vsep);
        offer_vertices(a, b, true, out, vface, vsep, slack);
        sse_vertex_faces(sat->rows_a, b->count, a->count, vface, vsep);
        offer_vertices(b, a, false, out, vface, vsep, slack);
    } else
#endif
    {
        offer_vertices(a, b, true, out, NULL, NULL, SX_R(0.0));
        offer_vertices(b, a, false, out, NULL, NULL, SX_R(0.0));
    }
    if (ea == 0 && eb == 0) out->dist_sq = sx_distance_sq(a->v[0], b->v[0]);
    vertex_direction(out);
}

/* The direction of a contact whose closest points coincide: the best SAT
 * axis, or A's local +x when there is none (two coincident points). */
static sx_vec2 fallback_normal(const sx_sat *sat) {
    if (sat->has_axes) return sat->axis;
    return sx_v2(SX_R(1.0), SX_R(0.0));
}

/* ---- overlap and MTV ---------------------------------------------------- */

static SX_ALWAYS_INLINE bool core_overlap(const sx_core *a, const sx_core *b) {
    sx_real r = a->radius + b->radius;
    sx_sat sat;
    sx_closest cl;
    if (!sat_run(a, b, r, &sat)) return false;
    if (sat.has_axes && sat.sep <= SX_R(0.0)) return true;
    closest_features(a, b, &sat, &cl);
    return cl.distance <= r;
}

bool sx_core_overlap(const sx_core *a, const sx_core *b) { return core_overlap(a, b); }

static SX_ALWAYS_INLINE bool core_mtv(const sx_core *a, const sx_core *b, sx_vec2 *mtv) {
    sx_real r = a->radius + b->radius;
    sx_sat sat;
    sx_closest cl;
    sx_vec2 n;
    *mtv = sx_v2_zero();
    if (!sat_run(a, b, r, &sat)) return false;
    if (sat.has_axes && sat.sep <= SX_R(0.0)) {
        /* The cores overlap: least penetration over the faces of both. */
        sx_real depth;
        if (sat.face_a >= 0 && sat.sep_a >= sat.sep_b) {
            depth = r - sat.sep_a;
            n = a->n[sat.face_a];
        } else {
            depth = r - sat.sep_b;
            n = sx_neg(b->n[sat.face_b]);
        }
        *mtv = sx_scale(n, -depth);
        return true;
    }
    closest_features(a, b, &sat, &cl);
    if (!(cl.distance <= r)) return false;
    n = cl.normal;
    if (n.x == SX_R(0.0) && n.y == SX_R(0.0)) n = fallback_normal(&sat);
    *mtv = sx_scale(n, cl.distance - r);
    return true;
}

/* ---- manifolds ---------------------------------------------------------- */

/* The deepest vertex of c along -n: the first of least projection, kept
 * without a branch. */
static inline int support_below(const sx_core *c, sx_vec2 n) {
    sx_real lo = SX_REAL_MAX;
    int j, s = 0;
    for (j = 0; j < c->count; ++j) {
        sx_real d = sx_dot(c->v[j], n);
        s = d < lo ? j : s;
        lo = d < lo ? d : lo;
    }
    return s;
}

/* The face of polygon core ref next to face i on the side where the point
 * p lies beyond face i's slab, or -1 when p is within the slab. */
static int slab_neighbour(const sx_core *ref, int i, sx_vec2 p) {
    sx_vec2 t = sx_perp(ref->n[i]);
    sx_real tp = sx_dot(t, p);
    if (tp < sx_dot(t, ref->v[i])) return i > 0 ? i - 1 : ref->count - 1;
    if (tp > sx_dot(t, ref->v[next_index(ref, i)])) return next_index(ref, i);
    return -1;
}

/* Clips the incident feature of `inc` against face *face of `ref` (or a face tied with it, see
 * below, written back to *face) and writes the contact points (working frame). flip: ref is B.
 * Points deeper than -margin (less a rounding allowance) are kept; if none is, the deepest one is,
 * so an overlapping pair always reports a contact. */
static int clip_face(const sx_core *ref, int *face, const sx_core *inc, sx_real margin, bool flip,
                     const sx_manifold_point *exact, sx_manifold_point out[2]) {
    int i = *face;
    sx_vec2 nref = ref->n[i];
    sx_vec2 v1 = ref->v[i], v2 = ref->v[next_index(ref, i)];
    sx_vec2 t = sx_perp(nref);
    sx_vec2 w[2] = {{SX_R(0.0), SX_R(0.0)}, {SX_R(0.0), SX_R(0.0)}};
    int k[2] = {0, 0}, nw, count = 0;
    sx_real scale, slack;
    if (inc->count == 1) {
        w[0] = inc->v[0];
        k[0] = 0;
        nw = 1;
    } else {
        /* The incident face is the one most anti-parallel to the reference
         * normal; its end points are clipped to the reference face's slab. */
        sx_real lower, upper, d0, d1, noise;
        int f = 0, s = support_below(inc, nref);
        if (ref->count >= 3) {
            /* Two faces of ref bent by 1e-4 rad at a vertex separate inc by
             * the same amount up to rounding, and the SAT's pick of the two
             * may leave inc's deepest vertex beyond its slab, where clipping
             * cuts it off (the depth comes out short). Of two
             * such tied faces the one whose slab the deepest vertex is in,
             * or towards, is the reference. A real corner
             * (the neighbour separating clearly less) keeps face i. The
             * rounding allowance takes in the point the neighbour's
             * separation is measured from: a neighbour running 1e5 m to a
             * far corner is placed with ~1 cm of rounding, and a 2 mm
             * difference between the two faces then says nothing (picking
             * on it, a deep penetration could come out a centimetre deep). */
            int nb = slab_neighbour(ref, i, inc->v[s]);
            if (nb >= 0) {
                sx_real tie =
                    SX_DIRECTION_EPSILON *
                    sx_maxr(sx_maxr(max_abs_coord(v1, v2), max_abs_coord(ref->v[nb], ref->v[nb])),
                            max_abs_coord(inc->v[s], inc->v[s]));
                if (face_separation(ref, nb, inc) >= face_separation(ref, i, inc) - tie) {
                    i = nb;
                    *face = nb;
                    nref = ref->n[i];
                    v1 = ref->v[i];
                    v2 = ref->v[next_index(ref, i)];
                    t = sx_perp(nref);
                    s = support_below(inc, nref);
                }
            }
        }
        if (inc->count == 2) {
            f = sx_dot(inc->n[1], nref) < sx_dot(inc->n[0], nref) ? 1 : 0;
        } else {
            /* A polygon's most anti-parallel face is one of the two faces
             * at its deepest vertex along -nref (its normal is the nearest
             * in angle to -nref), so only those two compete. Comparing
             * every face's normal alone lets two faces of a sliver (normals
             * 1e-4 apart) tie in rounding, and the wrong one, a 15 m face
             * away from the deepest vertex 70 km off, reported 7 mm of an
             * 8.4 m penetration. Ties go to the lower index, as before. */
            int prev;
            sx_real dp, ds;
            prev = s > 0 ? s - 1 : inc->count - 1;
            dp = sx_dot(inc->n[prev], nref);
            ds = sx_dot(inc->n[s], nref);
            f = dp < ds || (dp == ds && prev < s) ? prev : s;
        }
        k[0] = f;
        k[1] = next_index(inc, f);
        w[0] = inc->v[k[0]];
        w[1] = inc->v[k[1]];
        nw = 2;
        lower = sx_dot(t, v1);
        upper = sx_dot(t, v2);
        /* An incident face that crosses a side of the slab is cut where it
         * crosses, at d0 / (d0 - d1) along it; when its two ends differ
         * along the face by no more than the rounding of their
         * coordinates, it runs along the reference normal, that fraction
         * is rounding noise (a capsule 1e5 m long beside a capsule
         * 3e-7 m long: cut at 97 % of the long one's length, its depth
         * came out 0 instead of 9e4 m), and the end outside lies within
         * rounding of the side: it stays as it is. */
        noise = SX_DIRECTION_EPSILON * sx_maxr(max_abs_coord(v1, v2), max_abs_coord(w[0], w[1]));
        /* A reference face no wider than that rounding has no slab to
         * clip to: which side of it an incident end lies on is noise (a
         * capsule 3e-7 m long against one 2.8e4 m long that crossed its
         * slab at 5e-5 rad was cut 1.3 m along it: 0.93 m reported of a
         * 2.25 m depth), and the ends stay as they are; the depth test
         * below keeps those that reach the face. */
        if (!(upper - lower > noise)) {
            lower = -SX_REAL_MAX;
            upper = SX_REAL_MAX;
        }
        d0 = sx_dot(t, w[0]) - lower;
        d1 = sx_dot(t, w[1]) - lower;
        if (d0 < SX_R(0.0) && d1 < SX_R(0.0)) {
            nw = 0;
        } else if (d0 < SX_R(0.0) && d1 - d0 > noise) {
            w[0] = sx_lerp(w[0], w[1], d0 / (d0 - d1));
        } else if (d1 < SX_R(0.0) && d0 - d1 > noise) {
            w[1] = sx_lerp(w[1], w[0], d1 / (d1 - d0));
        }
        if (nw == 2) {
            d0 = upper - sx_dot(t, w[0]);
            d1 = upper - sx_dot(t, w[1]);
            if (d0 < SX_R(0.0) && d1 < SX_R(0.0)) {
                nw = 0;
            } else if (d0 < SX_R(0.0) && d1 - d0 > noise) {
                w[0] = sx_lerp(w[0], w[1], d0 / (d0 - d1));
            } else if (d1 < SX_R(0.0) && d0 - d1 > noise) {
                w[1] = sx_lerp(w[1], w[0], d1 / (d1 - d0));
            }
        }
        if (nw == 0) {
            /* The incident face misses the slab entirely (a corner against a
             * short face): keep its end point nearest the reference face. */
            sx_real s0 = sx_dot(nref, sx_sub(inc->v[k[0]], v1));
            sx_real s1 = sx_dot(nref, sx_sub(inc->v[k[1]], v1));
            nw = 1;
            if (s1 < s0) {
                k[0] = k[1];
            }
            w[0] = inc->v[k[0]];
        }
    }
    /* The one or two points as scalars, not arrays: indexed by the
     * deepest point, GCC kept them in memory and the loop waited on
     * reloading what it had just stored. */
    {
        sx_real rr = ref->radius + inc->radius, half = ref->radius - inc->radius;
        sx_real sc0, sc1 = SX_R(0.0), d0, d1 = SX_R(0.0), lim;
        sx_vec2 p0, p1 = w[0];
        int deepest = 0;
        bool keep0, keep1;
        scale = sx_maxr(max_abs_coord(v1, v2), rr);
        sc0 = sx_dot(nref, sx_sub(w[0], v1));
        d0 = rr - sc0;
        scale = sx_maxr(scale, max_abs_coord(w[0], w[0]));
        if (nw == 2) {
            sc1 = sx_dot(nref, sx_sub(w[1], v1));
            d1 = rr - sc1;
            scale = sx_maxr(scale, max_abs_coord(w[1], w[1]));
            deepest = d1 > d0 ? 1 : 0;
        }
        slack = SX_DIRECTION_EPSILON * scale;
        p0 = sx_mul_add(w[0], SX_R(0.5) * (half - sc0), nref);
        if (nw == 2) p1 = sx_mul_add(w[1], SX_R(0.5) * (half - sc1), nref);
        if (exact != NULL && (nw == 1 || exact->depth > (deepest ? d1 : d0) + slack)) {
            /* Cores apart: the exact contact is the closest-feature point.
             * A single incident point is that contact seen along the face
             * normal, so take the exact one. With two, clipping can slide
             * the deepest incident vertex (a corner or capsule end just past
             * the end of the reference face) along a steep incident face
             * and lose depth: the point that came from that vertex becomes
             * the exact contact. */
            int from = 0;
            if (nw == 2) {
                sx_real s0 = sx_dot(nref, sx_sub(inc->v[k[0]], v1));
                sx_real s1 = sx_dot(nref, sx_sub(inc->v[k[1]], v1));
                from = s1 < s0 ? 1 : 0;
            }
            if (from) {
                p1 = exact->point;
                d1 = exact->depth;
            } else {
                p0 = exact->point;
                d0 = exact->depth;
            }
            deepest = from;
        }
        /* Points deeper than -margin (less the rounding allowance); if none
         * is, the deepest one. */
        lim = -margin - slack;
        keep0 = d0 >= lim;
        keep1 = nw == 2 && d1 >= lim;
        if (!keep0 && !keep1) {
            keep0 = deepest == 0;
            keep1 = deepest == 1;
        }
        if (keep0) {
            out[count].point = p0;
            out[count].depth = sx_maxr(d0, -margin);
            out[count].id = SX_FEATURE_ID(i, k[0], flip);
            ++count;
        }
        if (keep1) {
            out[count].point = p1;
            out[count].depth = sx_maxr(d1, -margin);
            out[count].id = SX_FEATURE_ID(i, k[1], flip);
            ++count;
        }
    }
    return count;
}

/* The two argument orders of a same-type pair compute the same separations
 * up to rounding, a few ulps of the coordinates: a signed gap farther from
 * zero than this (the touch rescue margin of collide.c plus a wide rounding
 * allowance) gets the same touch answer in both orders. */
#define SX_ORDER_RESCUE (SX_R(0.01) * SX_LINEAR_SLOP)
#define SX_ORDER_ROUNDING (SX_R(1024.0) * SX_REAL_EPSILON)

static bool gap_is_clear(const sx_core *a, const sx_core *b, const sx_sat *sat, sx_real gap) {
    sx_real scale = sx_maxr(sat_pair_scale(a, b, sat), a->radius + b->radius);
    return sx_magnitude(gap) > SX_ORDER_RESCUE + SX_ORDER_ROUNDING * scale;
}

static SX_ALWAYS_INLINE int core_manifold(const sx_core *a, const sx_core *b, sx_real margin,
                                          sx_real hysteresis, sx_manifold *out, bool *clear_cut) {
    sx_real r = a->radius + b->radius;
    sx_real limit = r + margin;
    sx_sat sat;
    sx_closest cl;
    bool face_contact;
    sx_manifold_point exact_point;
    const sx_manifold_point *exact = NULL;
    out->count = 0;
    out->normal = sx_v2_zero();
    if (!sat_run(a, b, limit, &sat)) {
        if (clear_cut) *clear_cut = gap_is_clear(a, b, &sat, sat.sep - r);
        return 0;
    }
    if (sat.has_axes && sat.sep <= SX_R(0.0)) {
        face_contact = true;
        if (clear_cut) *clear_cut = gap_is_clear(a, b, &sat, sat.sep - r);
    } else {
        sx_vec2 n;
        closest_features(a, b, &sat, &cl);
        if (clear_cut) *clear_cut = gap_is_clear(a, b, &sat, cl.distance - r);
        if (!(cl.distance <= limit)) return 0;
        /* The exact contact of cores apart: on the line between the closest
         * core points, midway between the surfaces. */
        n = cl.normal;
        if (n.x == SX_R(0.0) && n.y == SX_R(0.0)) n = fallback_normal(&sat);
        exact_point.point =
            sx_mul_add(sx_lerp(cl.pa, cl.pb, SX_R(0.5)), SX_R(0.5) * (a->radius - b->radius), n);
        exact_point.depth = sx_maxr(r - cl.distance, -margin);
        exact_point.id = SX_FEATURE_ID(cl.ia, cl.ib, 0);
        exact = &exact_point;
        face_contact = (sat.face_a >= 0 || sat.face_b >= 0) &&
                       (cl.kind != SX_CLOSEST_VERTICES ||
                        cl.distance <= sx_maxr(sat.sep_a, sat.sep_b) + SX_FACE_CONTACT_TOLERANCE);
        if (!face_contact) {
            /* Rounded corner against rounded corner: that one point. */
            out->normal = n;
            out->points[0] = exact_point;
            out->count = 1;
            return 1;
        }
    }
    if (sat.face_b >= 0 && (sat.face_a < 0 || sat.sep_b > sat.sep_a + hysteresis)) {
        int f = sat.face_b;
        out->count = clip_face(b, &f, a, margin, true, exact, out->points);
        out->normal = sx_neg(b->n[f]);
    } else if (sat.face_a >= 0) {
        int f = sat.face_a;
        out->count = clip_face(a, &f, b, margin, false, exact, out->points);
        out->normal = a->n[f];
    }
    return out->count;
}

int sx_core_manifold(const sx_core *a, const sx_core *b, sx_real margin, sx_manifold *out,
                     bool *clear_cut) {
    return core_manifold(a, b, margin, SX_REFERENCE_HYSTERESIS, out, clear_cut);
}

/* The core of a segment, capsule or polygon (kind: its sx_shape_type),
 * placed by *x (NULL: in its own frame). */
static SX_ALWAYS_INLINE bool core_of(int kind, const void *shape, const sx_xform *x, sx_core *out) {
    switch (kind) {
    case SX_SHAPE_SEGMENT: return sx_core_from_segment((const sx_segment *)shape, x, out);
    case SX_SHAPE_CAPSULE: return sx_core_from_capsule((const sx_capsule *)shape, x, out);
    default: return sx_core_from_polygon((const sx_polygon *)shape, x, out);
    }
}

/* The whole pair in one function: the cores, the manifold, the checks of
 * the values and world space, with nothing passed between them through
 * memory that registers can hold. Specialised for each pair of kinds by
 * sx_cores_collide. */
/* Builds the cores of a (in its own frame) and b (placed in a's frame) for
 * the fused routines below, as build_pair in collide.c builds them; false
 * for invalid input (a NULL or bad shape, a non-finite transform). */
static SX_ALWAYS_INLINE bool cores_build(int ka, const void *a, sx_xf xa, int kb, const void *b,
                                         sx_xf xb, sx_core *ca, sx_core *cb) {
    bool ok;
#if SX_NARROW_SSE
    __m128 r = sx_sse_relative_xform(xa, xb);
    ok = sx_sse_finite(r);
    if (ok && kb == SX_SHAPE_POLYGON) {
        const sx_polygon *pb = (const sx_polygon *)b;
        ok = pb != NULL && core_radius_ok(pb->radius) && pb->count >= 3 &&
             pb->count <= SX_MAX_POLYGON_VERTICES;
        if (ok) place_polygon_rel(pb, r, cb);
    } else if (ok) {
        sx_xform rel;
        _mm_storeu_ps(&rel.p.x, r);
        ok = core_of(kb, b, &rel, cb);
    }
#else
    sx_xform rel = sx_xform_inv_mul(*xa, *xb);
    ok = sx_is_finite(((rel.p.x - rel.p.x) + (rel.p.y - rel.p.y)) +
                      ((rel.q.c - rel.q.c) + (rel.q.s - rel.q.s))) &&
         core_of(kb, b, &rel, cb);
#endif
    return ok && core_of(ka, a, NULL, ca);
}

static SX_ALWAYS_INLINE int cores_collide(int ka, const void *a, sx_xf xa, int kb, const void *b,
                                          sx_xf xb, sx_real margin, sx_real hysteresis,
                                          sx_manifold *out, bool *clear_cut) {
    sx_core ca, cb;
    int local, count;
    if (clear_cut) *clear_cut = false;
    if (!cores_build(ka, a, xa, kb, b, xb, &ca, &cb)) {
        memset(out, 0, sizeof(*out));
        return 0;
    }
    if (!(sx_is_finite(margin) && margin > SX_R(0.0))) margin = SX_R(0.0);
    local = core_manifold(&ca, &cb, margin, hysteresis, out, clear_cut);
    if (local > 0 && !(sx_core_values_finite(&ca) && sx_core_values_finite(&cb))) local = 0;
    count = sx_world_manifold(out, local, xa);
    if (clear_cut && count != local) *clear_cut = false;
    return count;
}

bool sx_cores_overlap(int ka, const void *a, sx_xf xa, int kb, const void *b, sx_xf xb) {
    sx_core ca, cb;
    return cores_build(ka, a, xa, kb, b, xb, &ca, &cb) && core_overlap(&ca, &cb) &&
           sx_core_values_finite(&ca) && sx_core_values_finite(&cb);
}

bool sx_cores_mtv(int ka, const void *a, sx_xf xa, int kb, const void *b, sx_xf xb, sx_vec2 *mtv) {
    sx_core ca, cb;
    *mtv = sx_v2_zero();
    return cores_build(ka, a, xa, kb, b, xb, &ca, &cb) && core_mtv(&ca, &cb, mtv) &&
           sx_core_values_finite(&ca) && sx_core_values_finite(&cb);
}

int sx_cores_collide(int ka, const void *a, sx_xf xa, int kb, const void *b, sx_xf xb,
                     sx_real margin, sx_real hysteresis, sx_manifold *out, bool *clear_cut) {
    return cores_collide(ka, a, xa, kb, b, xb, margin, hysteresis, out, clear_cut);
}

/* ---- a core against a point --------------------------------------------- */

/* The cheap pairs (a segment, capsule or polygon A against a circle B) are
 * the routines above with b the 1-point core (c, rb), written out for it: the
 * SAT is A's faces (plus the caps of a 2-point A) against one point, the
 * vertex sweep needs only A's face of largest separation (for a point
 * outside a convex polygon the closest point lies on that face or is one of
 * its end vertices: a face not adjacent to the closest vertex separates the
 * point by less than the adjacent ones, as Box2D's polygon-circle uses), and
 * a face contact is the point itself seen along the face normal, with no
 * clipping. */

/* sat_run for b = the point c. */
static bool point_sat(const sx_core *a, sx_vec2 c, sx_real limit, sx_sat *out) {
    int i, n = face_count(a), face = -1;
    sx_real best = SX_NO_SEPARATION;
    out->sep_b = SX_NO_SEPARATION;
    out->face_b = -1;
    if (n > 0) {
        /* Every face, then one test: a point has few faces to skip, and the
         * running maximum stays free of branches (as in best_face). */
        bool bad;
        best = sx_dot(a->n[0], sx_sub(c, a->v[0]));
        bad = best != best;
        face = 0;
        for (i = 1; i < n; ++i) {
            sx_real s = sx_dot(a->n[i], sx_sub(c, a->v[i]));
            bad |= s != s;
            face = s > best ? i : face;
            best = s > best ? s : best;
        }
        if (bad || !(best <= limit)) return false; /* apart, or NaN: see sat_run */
    }
    out->sep_a = best;
    out->face_a = face;
    out->has_axes = n > 0;
    out->sep = out->sep_a;
    out->axis = out->face_a >= 0 ? a->n[out->face_a] : sx_v2_zero();
    if (a->count == 2) {
        sx_vec2 t = sx_perp(a->n[0]);
        sx_real beyond_b = sx_dot(t, sx_sub(c, a->v[1]));
        sx_real beyond_a = sx_dot(t, sx_sub(a->v[0], c));
        sx_real s = beyond_b >= beyond_a ? beyond_b : beyond_a;
        if (!(s <= limit)) return false;
        if (s > out->sep) {
            out->sep = s;
            out->axis = beyond_b >= beyond_a ? t : sx_neg(t);
        }
    }
    return true;
}

/* closest_features for b = the point c (index 0), A's face of largest
 * separation being sat->face_a. */
static void point_closest(const sx_core *a, sx_vec2 c, const sx_sat *sat, sx_closest *out) {
    out->dist_sq = SX_REAL_MAX;
    out->distance = SX_REAL_MAX;
    out->kind = SX_CLOSEST_VERTICES;
    out->ia = 0;
    out->ib = 0;
    out->pa = a->v[0];
    out->pb = c;
    out->normal = sx_v2_zero();
    if (a->count == 1) {
        out->dist_sq = sx_distance_sq(a->v[0], c);
    } else if (a->count == 2) {
        (void)offer_edge(a, 0, c, 0, true, false, out);
    } else {
        offer_face_walk(a, sat->face_a, c, 0, true, out);
    }
    vertex_direction(out);
}

bool sx_core_point_overlap(const sx_core *a, sx_vec2 c, sx_real rb) {
    sx_real r = a->radius + rb;
    sx_sat sat;
    sx_closest cl;
    if (!point_sat(a, c, r, &sat)) return false;
    if (sat.has_axes && sat.sep <= SX_R(0.0)) return true;
    point_closest(a, c, &sat, &cl);
    return cl.distance <= r;
}

bool sx_core_point_mtv(const sx_core *a, sx_vec2 c, sx_real rb, sx_vec2 *mtv) {
    sx_real r = a->radius + rb;
    sx_sat sat;
    sx_closest cl;
    sx_vec2 n;
    *mtv = sx_v2_zero();
    if (!point_sat(a, c, r, &sat)) return false;
    if (sat.has_axes && sat.sep <= SX_R(0.0)) {
        *mtv = sx_scale(a->n[sat.face_a], -(r - sat.sep_a));
        return true;
    }
    point_closest(a, c, &sat, &cl);
    if (!(cl.distance <= r)) return false;
    n = cl.normal;
    if (n.x == SX_R(0.0) && n.y == SX_R(0.0)) n = fallback_normal(&sat);
    *mtv = sx_scale(n, cl.distance - r);
    return true;
}

/* sx_core_point_manifold once the SAT has not found a separating axis. */
static inline int point_manifold_rest(const sx_core *a, sx_vec2 c, sx_real rb, sx_real margin,
                                      const sx_sat *sat, sx_manifold *out) {
    sx_real r = a->radius + rb;
    sx_closest cl;
    sx_vec2 n;
    sx_manifold_point *p = &out->points[0];
    if (sat->has_axes && sat->sep <= SX_R(0.0)) {
        /* The centre is on the core: clip_face's single incident point. */
        n = a->n[sat->face_a];
        p->point = sx_mul_add(c, SX_R(0.5) * (a->radius - rb - sat->sep_a), n);
        p->depth = sx_maxr(r - sat->sep_a, -margin);
        p->id = SX_FEATURE_ID(sat->face_a, 0, 0);
        out->normal = n;
        out->count = 1;
        return 1;
    }
    point_closest(a, c, sat, &cl);
    if (!(cl.distance <= r + margin)) return 0;
    n = cl.normal;
    if (n.x == SX_R(0.0) && n.y == SX_R(0.0)) n = fallback_normal(sat);
    p->point = sx_mul_add(sx_lerp(cl.pa, cl.pb, SX_R(0.5)), SX_R(0.5) * (a->radius - rb), n);
    p->depth = sx_maxr(r - cl.distance, -margin);
    if (cl.kind == SX_CLOSEST_FACE_A && a->count >= 3) {
        /* A face contact on the face the walk found (offer_face_walk). */
        p->id = SX_FEATURE_ID(cl.ia, 0, 0);
        out->normal = a->n[cl.ia];
    } else if (sat->face_a >= 0 && (cl.kind != SX_CLOSEST_VERTICES ||
                                    cl.distance <= sat->sep_a + SX_FACE_CONTACT_TOLERANCE)) {
        /* A face contact: the exact point, labelled and oriented by the face. */
        p->id = SX_FEATURE_ID(sat->face_a, 0, 0);
        out->normal = a->n[sat->face_a];
    } else {
        p->id = SX_FEATURE_ID(cl.ia, cl.ib, 0);
        out->normal = n;
    }
    out->count = 1;
    return 1;
}

int sx_core_point_manifold(const sx_core *a, sx_vec2 c, sx_real rb, sx_real margin,
                           sx_manifold *out) {
    sx_sat sat;
    out->count = 0;
    out->normal = sx_v2_zero();
    if (!point_sat(a, c, a->radius + rb + margin, &sat)) return 0;
    return point_manifold_rest(a, c, rb, margin, &sat, out);
}

/* A segment or capsule core a-b (in its own frame) against the point c:
 * what point_sat and point_closest find for that 2-point core, with the
 * closest feature found from the unnormalised edge a-b, so that the square
 * root of an end's distance does not wait for the one of the normal (the
 * two run side by side). Same decisions as the general route up to
 * rounding where c lies level with an end. */
typedef struct sx_segment_point {
    sx_vec2 n;        /* unit normal of face 0 (face 1 has -n) */
    int face;         /* the face of largest separation, as point_sat's */
    sx_real sep_a;    /* its separation */
    int vertex;       /* the closest end (0, 1), or -1: a point inside */
    sx_vec2 on;       /* the closest point of a-b */
    sx_vec2 d;        /* c - on for an end, the unit direction to c inside */
    sx_real distance; /* |c - on| */
} sx_segment_point;

/* 1: within `limit` (filled in), 0: apart, -1: the general route answers
 * (ends not finite or closer than normalize_len takes a direction from, a
 * non-finite c or a sum that overflowed, c on the segment, where the
 * SAT's axes decide, or c so close to an end that the square underflows,
 * where vertex_direction measures the distance scaled). */
static inline int segment_point(sx_vec2 a, sx_vec2 b, sx_vec2 c, sx_real limit,
                                sx_segment_point *out) {
    sx_vec2 e = sx_sub(b, a), w = sx_sub(c, a), wb = sx_sub(c, b), t;
    sx_real ee = sx_dot(e, e), along = sx_dot(w, e), len = sx_sqrt(ee), inv, s0, s1, cap;
    inv = SX_R(1.0) / len;
    t = sx_v2(e.x * inv, e.y * inv);
    out->n = sx_v2(t.y, -t.x);
    s0 = sx_dot(out->n, w);
    s1 = sx_dot(sx_neg(out->n), wb);
    out->face = s1 > s0 ? 1 : 0;
    out->sep_a = s1 > s0 ? s1 : s0;
    cap = sx_maxr(sx_dot(t, wb), sx_dot(t, sx_sub(a, c)));
    if (!sx_vec2_is_finite(a) || !sx_vec2_is_finite(b) || !(len > SX_REAL_EPSILON) ||
        !(ee <= SX_REAL_MAX) || !(sx_absr(s0) <= SX_REAL_MAX) || !(sx_absr(s1) <= SX_REAL_MAX)) {
        return -1;
    }
    if (!(out->sep_a <= limit) || !(cap <= limit)) return 0;
    if (!(sx_maxr(out->sep_a, cap) > SX_R(0.0))) return -1;
    /* The end's distance depends on e, not on the normal: past a branch
     * predicted "not apart" it runs beside the normal's root. */
    if (along <= SX_R(0.0) || along >= ee) {
        out->vertex = along <= SX_R(0.0) ? 0 : 1;
        out->on = along <= SX_R(0.0) ? a : b;
        out->d = along <= SX_R(0.0) ? w : wb;
        out->distance = sx_sqrt(sx_dot(out->d, out->d));
        /* Below SX_SQUARE_SAFE vertex_direction measures the distance
         * scaled, which may decide differently. */
        if (!(out->distance >= SX_SQUARE_SAFE)) return -1;
    } else {
        /* Inside: offer_edge's face case. */
        out->vertex = -1;
        out->on = sx_mul_sub(c, s0, out->n);
        out->distance = sx_absr(s0);
        out->d = s0 < SX_R(0.0) ? sx_neg(out->n) : out->n;
    }
    return out->distance <= limit;
}

/* The unit direction from the closest point to c; false where
 * vertex_direction would find none (c within rounding noise of an end). */
static inline bool segment_point_dir(const sx_segment_point *sp, sx_vec2 c, sx_vec2 *dir) {
    if (sp->vertex < 0) {
        *dir = sp->d;
        return true;
    }
    if (!(sp->distance > SX_DIRECTION_EPSILON * max_abs_coord(sp->on, c))) return false;
    *dir = sx_scale(sp->d, SX_R(1.0) / sp->distance);
    return true;
}

int sx_core_segment_point_overlap(sx_vec2 a, sx_vec2 b, sx_real ra, sx_vec2 c, sx_real rb) {
    sx_segment_point sp;
    return segment_point(a, b, c, ra + rb, &sp);
}

int sx_core_segment_point_mtv(sx_vec2 a, sx_vec2 b, sx_real ra, sx_vec2 c, sx_real rb,
                              sx_vec2 *mtv) {
    sx_segment_point sp;
    sx_real r = ra + rb;
    sx_vec2 dir;
    int hit = segment_point(a, b, c, r, &sp);
    if (hit < 0 || (hit > 0 && !segment_point_dir(&sp, c, &dir))) return -1;
    *mtv = hit > 0 ? sx_scale(dir, sp.distance - r) : sx_v2_zero();
    return hit;
}

static SX_ALWAYS_INLINE int segment_point_manifold(sx_vec2 a, sx_vec2 b, sx_real ra, sx_vec2 c,
                                                   sx_real rb, sx_real margin, sx_manifold *out) {
    sx_segment_point sp;
    sx_real r = ra + rb;
    sx_vec2 dir;
    sx_manifold_point *p = &out->points[0];
    int hit = segment_point(a, b, c, r + margin, &sp);
    if (hit < 0 || (hit > 0 && !segment_point_dir(&sp, c, &dir))) return -1;
    out->count = 0;
    out->normal = sx_v2_zero();
    if (hit == 0) return 0;
    p->point = sx_mul_add(sx_lerp(sp.on, c, SX_R(0.5)), SX_R(0.5) * (ra - rb), dir);
    p->depth = sx_maxr(r - sp.distance, -margin);
    if (sp.vertex < 0 || sp.distance <= sp.sep_a + SX_FACE_CONTACT_TOLERANCE) {
        /* A face contact: the exact point, labelled and oriented by the face. */
        p->id = SX_FEATURE_ID(sp.face, 0, 0);
        out->normal = sp.face ? sx_neg(sp.n) : sp.n;
    } else {
        p->id = SX_FEATURE_ID(sp.vertex, 0, 0);
        out->normal = dir;
    }
    out->count = 1;
    return 1;
}

/* ---- a polygon against a point, without a core -------------------------- */

/* point_sat and point_closest for the polygon (v, nn, count >= 3) read in
 * place against the point c, without the core and the sweep's records: the
 * same operations in the same order, so the answers are the general
 * route's bit for bit. */
typedef struct sx_polygon_point {
    int face;         /* the face of largest separation (point_sat's) */
    sx_real sep;      /* its separation; <= 0: c is inside */
    int vertex;       /* the closest vertex, or -1: the closest point is on the face */
    sx_vec2 on;       /* the closest point of the polygon (c outside) */
    sx_vec2 dir;      /* unit direction from on to c (c outside) */
    sx_real distance; /* |c - on| (c outside) */
} sx_polygon_point;

/* 1: within `limit` (filled in), 0: apart (or NaN, as point_sat answers),
 * -1: the general route answers (a square that overflows or underflows,
 * or c within rounding noise of a vertex, where the SAT's axis or
 * vertex_direction's scaling gives the direction). */
#if SX_NARROW_SSE
/* The separations sx_dot(nn[i], sx_sub(c, v[i])) of the point cc = [c.x,
 * c.y, c.x, c.y] from faces i..i+3, each computed as that expression
 * computes it; faces past count repeat face 0 (v00, n00: its vertex and
 * normal in both halves), which cannot change a first maximum. */
static SX_ALWAYS_INLINE __m128 sse_point_faces(const sx_vec2 *v, const sx_vec2 *nn, int count,
                                               int i, __m128 cc, __m128 v00, __m128 n00,
                                               __m128 *fold) {
    __m128 v0 = sse_vertex_pair(v, i, count, v00), v1 = sse_vertex_pair(v, i + 2, count, v00);
    __m128 m0 = sse_vertex_pair(nn, i, count, n00), m1 = sse_vertex_pair(nn, i + 2, count, n00);
    __m128 p0 = _mm_mul_ps(m0, _mm_sub_ps(cc, v0)), p1 = _mm_mul_ps(m1, _mm_sub_ps(cc, v1));
    /* (x - x): 0 for finite x, NaN otherwise (sx_polygon_values_finite's
     * test, on the values loaded anyway). */
    *fold = _mm_add_ps(*fold, _mm_add_ps(_mm_add_ps(_mm_sub_ps(v0, v0), _mm_sub_ps(v1, v1)),
                                         _mm_add_ps(_mm_sub_ps(m0, m0), _mm_sub_ps(m1, m1))));
    return _mm_add_ps(_mm_shuffle_ps(p0, p1, _MM_SHUFFLE(2, 0, 2, 0)),
                      _mm_shuffle_ps(p0, p1, _MM_SHUFFLE(3, 1, 3, 1)));
}

/* The largest of four lanes, in every lane. */
static SX_ALWAYS_INLINE __m128 sse_lane_max(__m128 s) {
    s = _mm_max_ps(s, _mm_shuffle_ps(s, s, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_max_ps(s, _mm_shuffle_ps(s, s, _MM_SHUFFLE(2, 3, 0, 1)));
}
#endif

/* values_finite (may be NULL): whether every vertex and normal is finite,
 * set when the answer is 1 (sx_polygon_values_finite's answer). */
static SX_ALWAYS_INLINE int polygon_point(const sx_vec2 *v, const sx_vec2 *nn, int count, sx_vec2 c,
                                          sx_real limit, sx_polygon_point *out,
                                          bool *values_finite) {
    int face = 0, i2, vertex = -1;
    sx_real best, t, dsq;
    sx_vec2 w, n, dir;
#if SX_NARROW_SSE
    {
        /* Every face's separation four to a register; the first of the
         * largest is the lowest lane equal to the maximum (the scalar loop
         * keeps the first with a strict comparison). Its separation is
         * then taken once more by the scalar expression: the maximum of
         * the lanes may differ from it in the sign of a zero. */
        __m128 cc = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&c);
        __m128 v00 = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&v[0]);
        __m128 n00 = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(const void *)&nn[0]);
        __m128 s0, mx, bad, fold = _mm_setzero_ps();
        int mask;
        cc = _mm_movelh_ps(cc, cc);
        v00 = _mm_movelh_ps(v00, v00);
        n00 = _mm_movelh_ps(n00, n00);
        s0 = sse_point_faces(v, nn, count, 0, cc, v00, n00, &fold);
        bad = _mm_cmpunord_ps(s0, s0);
        if (count > 4) {
            __m128 s1 = sse_point_faces(v, nn, count, 4, cc, v00, n00, &fold);
            bad = _mm_or_ps(bad, _mm_cmpunord_ps(s1, s1));
            mx = sse_lane_max(_mm_max_ps(s0, s1));
            mask = _mm_movemask_ps(_mm_cmpeq_ps(s0, mx)) |
                   (_mm_movemask_ps(_mm_cmpeq_ps(s1, mx)) << 4);
        } else {
            mx = sse_lane_max(s0);
            mask = _mm_movemask_ps(_mm_cmpeq_ps(s0, mx));
        }
        best = _mm_cvtss_f32(mx);
        if (_mm_movemask_ps(bad) != 0 || !(best <= limit)) return 0;
        face = __builtin_ctz((unsigned)mask);
        best = sx_dot(nn[face], sx_sub(c, v[face]));
        if (values_finite) *values_finite = _mm_movemask_ps(_mm_cmpunord_ps(fold, fold)) == 0;
    }
#else
    {
        int i;
        bool bad;
        best = sx_dot(nn[0], sx_sub(c, v[0]));
        bad = best != best;
        for (i = 1; i < count; ++i) {
            sx_real s = sx_dot(nn[i], sx_sub(c, v[i]));
            bad |= s != s;
            face = s > best ? i : face;
            best = s > best ? s : best;
        }
        if (bad || !(best <= limit)) return 0;
        if (values_finite) *values_finite = sx_polygon_values_finite(v, nn, count);
    }
#endif
    out->face = face;
    out->sep = best;
    if (best <= SX_R(0.0)) {
        /* Inside: the caller reads face and sep only (set for tidiness). */
        out->vertex = -1;
        out->on = c;
        out->dir = nn[face];
        out->distance = SX_R(0.0);
        return 1;
    }
    /* offer_edge for the face of largest separation. */
    i2 = face + 1 < count ? face + 1 : 0;
    w = sx_sub(c, v[face]);
    n = nn[face];
    dir = sx_v2(-n.y, n.x);
    t = sx_dot(w, dir);
    if (t <= SX_R(0.0)) {
        vertex = face;
    } else if (t >= sx_dot(sx_sub(v[i2], v[face]), dir)) {
        vertex = i2;
    }
    out->vertex = vertex;
    if (vertex >= 0) {
        /* The corner's region ends at the face past it: beyond, rounding
         * chose the face (see offer_face_walk), and the general route
         * walks on. */
        int side_face = vertex == face ? (face > 0 ? face - 1 : count - 1) : i2;
        sx_real past = sx_dot(sx_sub(c, v[vertex]), sx_v2(-nn[side_face].y, nn[side_face].x));
        if (vertex == face ? !(past >= SX_R(0.0)) : !(past <= SX_R(0.0))) return -1;
        out->on = v[vertex];
        dsq = sx_distance_sq(out->on, c);
        if (!(dsq < SX_REAL_MAX)) return -1;
        out->distance = sx_sqrt(dsq);
        /* Below SX_SQUARE_SAFE vertex_direction measures the distance
         * scaled, which may decide differently. */
        if (!(out->distance >= SX_SQUARE_SAFE)) return -1;
        if (!(out->distance <= limit)) return 0;
        if (!(out->distance > SX_DIRECTION_EPSILON * max_abs_coord(out->on, c))) return -1;
        out->dir = sx_scale(sx_sub(c, out->on), SX_R(1.0) / out->distance);
        return 1;
    }
    t = sx_dot(w, n);
    if (!(t * t <= SX_REAL_MAX)) return -1;
    out->on = sx_mul_sub(c, t, n);
    out->distance = sx_absr(t);
    out->dir = n;
    return out->distance <= limit;
}

int sx_core_polygon_point_overlap(const sx_polygon *a, sx_vec2 c, sx_real rb) {
    sx_polygon_point pp;
    return polygon_point(a->vertices, a->normals, a->count, c, a->radius + rb, &pp, NULL);
}

int sx_core_polygon_point_mtv(const sx_polygon *a, sx_vec2 c, sx_real rb, sx_vec2 *mtv) {
    sx_polygon_point pp;
    sx_real r = a->radius + rb;
    int hit = polygon_point(a->vertices, a->normals, a->count, c, r, &pp, NULL);
    if (hit <= 0) {
        if (hit == 0) *mtv = sx_v2_zero();
        return hit;
    }
    if (pp.sep <= SX_R(0.0)) {
        *mtv = sx_scale(a->normals[pp.face], -(r - pp.sep));
    } else {
        *mtv = sx_scale(pp.dir, pp.distance - r);
    }
    return 1;
}

static SX_ALWAYS_INLINE int polygon_point_manifold(const sx_polygon *a, sx_vec2 c, sx_real rb,
                                                   sx_real margin, sx_manifold *out,
                                                   bool *values_finite) {
    sx_polygon_point pp;
    sx_real r = a->radius + rb;
    sx_manifold_point *p = &out->points[0];
    int hit = polygon_point(a->vertices, a->normals, a->count, c, r + margin, &pp, values_finite);
    if (hit < 0) return -1;
    out->count = 0;
    out->normal = sx_v2_zero();
    if (hit == 0) return 0;
    if (pp.sep <= SX_R(0.0)) {
        /* The centre is inside: clip_face's single incident point. */
        sx_vec2 n = a->normals[pp.face];
        p->point = sx_mul_add(c, SX_R(0.5) * (a->radius - rb - pp.sep), n);
        p->depth = sx_maxr(r - pp.sep, -margin);
        p->id = SX_FEATURE_ID(pp.face, 0, 0);
        out->normal = n;
    } else {
        p->point = sx_mul_add(sx_lerp(pp.on, c, SX_R(0.5)), SX_R(0.5) * (a->radius - rb), pp.dir);
        p->depth = sx_maxr(r - pp.distance, -margin);
        if (pp.vertex < 0 || pp.distance <= pp.sep + SX_FACE_CONTACT_TOLERANCE) {
            /* A face contact: the exact point, labelled and oriented by the face. */
            p->id = SX_FEATURE_ID(pp.face, 0, 0);
            out->normal = a->normals[pp.face];
        } else {
            p->id = SX_FEATURE_ID(pp.vertex, 0, 0);
            out->normal = pp.dir;
        }
    }
    out->count = 1;
    return 1;
}

int sx_core_segment_point_manifold(sx_vec2 a, sx_vec2 b, sx_real ra, sx_vec2 c, sx_real rb,
                                   sx_real margin, sx_manifold *out) {
    return segment_point_manifold(a, b, ra, c, rb, margin, out);
}

int sx_core_polygon_point_manifold(const sx_polygon *a, sx_vec2 c, sx_real rb, sx_real margin,
                                   sx_manifold *out) {
    return polygon_point_manifold(a, c, rb, margin, out, NULL);
}

/* ---- fused entries: a core against a circle ----------------------------- */

static SX_ALWAYS_INLINE int collide_polygon_circle_fused(const sx_polygon *a, sx_xf xa,
                                                         const sx_circle *b, sx_xf xb,
                                                         sx_real margin, sx_manifold *out) {
    sx_vec2 c;
    int local;
    bool finite = false;
    if (a == NULL || !core_radius_ok(a->radius) || a->count < 3 ||
        a->count > SX_MAX_POLYGON_VERTICES || b == NULL) {
        memset(out, 0, sizeof(*out));
        return 0;
    }
    c = sx_circle_in_frame(b, xa, xb);
    if (!(sx_is_finite(margin) && margin > SX_R(0.0))) margin = SX_R(0.0);
    local = polygon_point_manifold(a, c, b->radius, margin, out, &finite);
    if (local < 0) return -1;
    if (local > 0 && !(sx_circle_valid(b, xb, c) && finite)) local = 0;
    return sx_world_manifold(out, local, xa);
}

static SX_ALWAYS_INLINE int collide_segment_circle_fused(sx_vec2 a0, sx_vec2 a1, sx_real ra,
                                                         sx_xf xa, const sx_circle *b, sx_xf xb,
                                                         sx_real margin, sx_manifold *out) {
    sx_vec2 c;
    int local;
    if (b == NULL) {
        memset(out, 0, sizeof(*out));
        return 0;
    }
    c = sx_circle_in_frame(b, xa, xb);
    if (!(sx_is_finite(margin) && margin > SX_R(0.0))) margin = SX_R(0.0);
    local = segment_point_manifold(a0, a1, ra, c, b->radius, margin, out);
    if (local < 0) return -1;
    if (local > 0 && !sx_circle_valid(b, xb, c)) local = 0;
    return sx_world_manifold(out, local, xa);
}

/* ---- the manifold entries of each pair ---------------------------------- */

/* Each pair's manifold in one function (the fused routines above, and
 * collide.c's general route for what they hand back), inlined into both of
 * its entries: sx_collide_NAME_xf for the typed pair functions and
 * sx_collide_NAME_shapes for the dispatch table (narrow.h), so that
 * sx_collide reaches the work through one call. The reversed order is the
 * dispatch table's business (it mirrors the manifold). The typed entries of
 * the pairs of core types call the out-of-line sx_cores_collide, as
 * sx_collide_NAME always has: only the dispatch table's copy is inlined. */

static SX_ALWAYS_INLINE int collide_segment_circle(const sx_segment *a, sx_xf xa,
                                                   const sx_circle *b, sx_xf xb, sx_real margin,
                                                   sx_real hyst, sx_manifold *out) {
    int count = a == NULL
                    ? -1
                    : collide_segment_circle_fused(a->a, a->b, SX_R(0.0), xa, b, xb, margin, out);
    SX_UNUSED(hyst); /* circles have no reference face */
    if (count < 0) count = sx_point_collide_general(SX_SHAPE_SEGMENT, a, xa, b, xb, margin, out);
    return count;
}

static SX_ALWAYS_INLINE int collide_capsule_circle(const sx_capsule *a, sx_xf xa,
                                                   const sx_circle *b, sx_xf xb, sx_real margin,
                                                   sx_real hyst, sx_manifold *out) {
    int count = a == NULL || !core_radius_ok(a->radius)
                    ? -1
                    : collide_segment_circle_fused(a->a, a->b, a->radius, xa, b, xb, margin, out);
    SX_UNUSED(hyst);
    if (count < 0) count = sx_point_collide_general(SX_SHAPE_CAPSULE, a, xa, b, xb, margin, out);
    return count;
}

static SX_ALWAYS_INLINE int collide_polygon_circle(const sx_polygon *a, sx_xf xa,
                                                   const sx_circle *b, sx_xf xb, sx_real margin,
                                                   sx_real hyst, sx_manifold *out) {
    int count = collide_polygon_circle_fused(a, xa, b, xb, margin, out);
    SX_UNUSED(hyst);
    if (count < 0) count = sx_point_collide_general(SX_SHAPE_POLYGON, a, xa, b, xb, margin, out);
    return count;
}

/* Same-type manifolds follow the caller's order, but at margin 0 whether
 * the pair touches is the canonical order's answer; a pair clear of
 * rounding gets the same answer in both orders, and the rest goes to
 * collide.c's gated route (collide_gated). In the canonical order the
 * manifold at margin 0 makes exactly the decisions of the overlap test,
 * and in the other order too unless the pair is within rounding of
 * touching. The clear-cut test comes first: nearly every pair passes it,
 * so the branch predicts, where the order of two random transforms is a
 * coin toss that mispredicts half the time. kind and inline_cores are
 * constants wherever this is inlined, so the branches on them fold away:
 * the dispatch table's entries inline the cores (inline_cores), the typed
 * ones call the out-of-line sx_cores_collide. */
static SX_ALWAYS_INLINE int collide_same_type(int kind, bool inline_cores, const void *a, sx_xf xa,
                                              const void *b, sx_xf xb, sx_real margin, sx_real hyst,
                                              sx_manifold *out) {
    bool touch_test = !(sx_is_finite(margin) && margin > SX_R(0.0));
    int count = 0;
    if (touch_test) {
        bool clear_cut = false;
        count = inline_cores
                    ? cores_collide(kind, a, xa, kind, b, xb, SX_R(0.0), hyst, out, &clear_cut)
                    : sx_cores_collide(kind, a, xa, kind, b, xb, SX_R(0.0), hyst, out, &clear_cut);
        if (clear_cut) return count;
    }
    switch (kind) {
    case SX_SHAPE_SEGMENT:
        return sx_collide_segments_gated(a, xa, b, xb, margin, hyst, count, touch_test, out);
    case SX_SHAPE_CAPSULE:
        return sx_collide_capsules_gated(a, xa, b, xb, margin, hyst, count, touch_test, out);
    default: return sx_collide_polygons_gated(a, xa, b, xb, margin, hyst, count, touch_test, out);
    }
}

int sx_collide_segment_circle_xf(const sx_segment *a, sx_xf xa, const sx_circle *b, sx_xf xb,
                                 sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_segment_circle(a, xa, b, xb, margin, hyst, out);
}
int sx_collide_segment_circle_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                                     sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_segment_circle(&a->u.segment, xa, &b->u.circle, xb, margin, hyst, out);
}

int sx_collide_capsule_circle_xf(const sx_capsule *a, sx_xf xa, const sx_circle *b, sx_xf xb,
                                 sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_capsule_circle(a, xa, b, xb, margin, hyst, out);
}
int sx_collide_capsule_circle_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                                     sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_capsule_circle(&a->u.capsule, xa, &b->u.circle, xb, margin, hyst, out);
}

int sx_collide_polygon_circle_xf(const sx_polygon *a, sx_xf xa, const sx_circle *b, sx_xf xb,
                                 sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_polygon_circle(a, xa, b, xb, margin, hyst, out);
}
int sx_collide_polygon_circle_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                                     sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_polygon_circle(&a->u.polygon, xa, &b->u.circle, xb, margin, hyst, out);
}

int sx_collide_capsule_segment_xf(const sx_capsule *a, sx_xf xa, const sx_segment *b, sx_xf xb,
                                  sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_cores_collide(SX_SHAPE_CAPSULE, a, xa, SX_SHAPE_SEGMENT, b, xb, margin, hyst, out,
                            NULL);
}
int sx_collide_capsule_segment_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                                      sx_real margin, sx_real hyst, sx_manifold *out) {
    return cores_collide(SX_SHAPE_CAPSULE, &a->u.capsule, xa, SX_SHAPE_SEGMENT, &b->u.segment, xb,
                         margin, hyst, out, NULL);
}

int sx_collide_polygon_segment_xf(const sx_polygon *a, sx_xf xa, const sx_segment *b, sx_xf xb,
                                  sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_cores_collide(SX_SHAPE_POLYGON, a, xa, SX_SHAPE_SEGMENT, b, xb, margin, hyst, out,
                            NULL);
}
int sx_collide_polygon_segment_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                                      sx_real margin, sx_real hyst, sx_manifold *out) {
    return cores_collide(SX_SHAPE_POLYGON, &a->u.polygon, xa, SX_SHAPE_SEGMENT, &b->u.segment, xb,
                         margin, hyst, out, NULL);
}

int sx_collide_polygon_capsule_xf(const sx_polygon *a, sx_xf xa, const sx_capsule *b, sx_xf xb,
                                  sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_cores_collide(SX_SHAPE_POLYGON, a, xa, SX_SHAPE_CAPSULE, b, xb, margin, hyst, out,
                            NULL);
}
int sx_collide_polygon_capsule_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                                      sx_real margin, sx_real hyst, sx_manifold *out) {
    return cores_collide(SX_SHAPE_POLYGON, &a->u.polygon, xa, SX_SHAPE_CAPSULE, &b->u.capsule, xb,
                         margin, hyst, out, NULL);
}

int sx_collide_segments_xf(const sx_segment *a, sx_xf xa, const sx_segment *b, sx_xf xb,
                           sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_SEGMENT, false, a, xa, b, xb, margin, hyst, out);
}
int sx_collide_segments_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                               sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_SEGMENT, true, &a->u.segment, xa, &b->u.segment, xb, margin,
                             hyst, out);
}

int sx_collide_capsules_xf(const sx_capsule *a, sx_xf xa, const sx_capsule *b, sx_xf xb,
                           sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_CAPSULE, false, a, xa, b, xb, margin, hyst, out);
}
int sx_collide_capsules_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                               sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_CAPSULE, true, &a->u.capsule, xa, &b->u.capsule, xb, margin,
                             hyst, out);
}

int sx_collide_polygons_xf(const sx_polygon *a, sx_xf xa, const sx_polygon *b, sx_xf xb,
                           sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_POLYGON, false, a, xa, b, xb, margin, hyst, out);
}
int sx_collide_polygons_shapes(const sx_shape *a, sx_xf xa, const sx_shape *b, sx_xf xb,
                               sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_POLYGON, true, &a->u.polygon, xa, &b->u.polygon, xb, margin,
                             hyst, out);
}
