/* sepax — private: the separating-axis test of two cores (see narrow.h):
 * every face of both (and the caps when both have zero area), the largest
 * separation and its face, and the four-lane rows that the closest
 * features reuse.
 *
 * The functions are static and defined here, not in a .c file, because
 * both users (narrow_core.c: two cores; narrow_point.c: a core against a
 * point) need them inlined in their hot loops, where a call per face would
 * cost as much as the face. Each of those two files includes this once;
 * SX_MAYBE_UNUSED marks what only one of them calls. */
#ifndef SEPAX_NARROW_SAT_H
#define SEPAX_NARROW_SAT_H

#include "narrow.h"

static SX_MAYBE_UNUSED int face_count(const sx_core *c) { return c->count >= 2 ? c->count : 0; }

static SX_MAYBE_UNUSED int next_index(const sx_core *c, int i) {
    return i + 1 < c->count ? i + 1 : 0;
}

/* Separation of q from face i of p: how far q's nearest point lies in front
 * of the face's line (negative: q reaches behind it). The loop is
 * branch-free (running minima and a running NaN flag), which matters: it is
 * the inner loop of every polygon pair. A NaN (a 0 x inf product of cores
 * beyond the range) makes the separation unknown, and NaN says so to
 * sat_run. */
static SX_ALWAYS_INLINE sx_real face_separation(const sx_core *p, int i, const sx_core *q) {
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
static SX_MAYBE_UNUSED sx_real cap_separation(const sx_core *p, const sx_core *q, sx_vec2 *axis) {
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

/* The lane loops below hold a polygon's vertices in two registers. */
#if SX_MAX_POLYGON_VERTICES > 8
#error "best_face_lanes and polygon_point take at most eight vertices"
#endif

/* Per-vertex slots of the SAT's records: the lane loops store eight lanes. */
#define SX_VERTEX_SLOTS (SX_MAX_POLYGON_VERTICES > 8 ? SX_MAX_POLYGON_VERTICES : 8)

typedef struct sx_sat {
    sx_real sep_a, sep_b; /* best separation over A's / B's faces (-inf: none) */
    int face_a, face_b;   /* their faces (-1: none) */
    sx_real sep;          /* best over every axis, caps included */
    sx_vec2 axis;         /* unit axis of sep, from A towards B */
    bool has_axes;
    /* mags bit 1: mag_b holds the lane-wise largest magnitudes of B's
     * coordinates (from the SAT's loads); bit 2: mag_a, A's. */
    int mags;
    sx_r4 mag_a, mag_b;
    /* When rows is set (two polygon cores, limit > 0): the separation of
     * each vertex of B from each face of A (rows_b, best_face_lanes's rows)
     * and of A's vertices from B's faces (rows_a), for the closest-feature
     * sweep. */
    bool rows;
    sx_r4 rows_b[2 * SX_VERTEX_SLOTS], rows_a[2 * SX_VERTEX_SLOTS];
} sx_sat;

/* best_face with q's vertices four to a register (structure of arrays): the
 * same separations, each computed as face_separation computes it (no fused
 * operations, the same operand order), so the answers agree bit for bit up
 * to the sign of a zero minimum, which no caller can tell apart. q has 3 or
 * more vertices; lanes past its count repeat vertex 0, which cannot change a
 * minimum. */
static SX_ALWAYS_INLINE sx_r4 vertex_pair_lanes(const sx_vec2 *v, int j, int m, sx_r4 v00) {
    if (j + 1 < m) return sx_r4_load(&v[j].x);
    if (j < m) return sx_r4_load_low(v00, &v[j].x);
    return v00;
}

/* The separations of q's vertices (x, y: four lanes each) from face i of p,
 * as face_separation computes them. */
static SX_ALWAYS_INLINE sx_r4 face_lanes(const sx_core *p, int i, sx_r4 x, sx_r4 y) {
    sx_r4 nx = sx_r4_set1(p->n[i].x), ny = sx_r4_set1(p->n[i].y);
    sx_r4 vx = sx_r4_set1(p->v[i].x), vy = sx_r4_set1(p->v[i].y);
    return sx_r4_add(sx_r4_mul(nx, sx_r4_sub(x, vx)), sx_r4_mul(ny, sx_r4_sub(y, vy)));
}

/* The least of four lanes, or NaN when a lane of `bad` is set. */
static SX_ALWAYS_INLINE sx_real lane_min(sx_r4 lo, sx_m4 bad) {
    return sx_m4_any(bad) ? (sx_real)NAN : sx_r4_first(sx_r4_min_lanes(lo));
}

/* best_face with q's vertices four to a register. With track != 0, the
 * separations of q's vertices from each face i of p (the lanes, as
 * face_separation computes them) are also kept, in rows[2 i] (vertices
 * 0..3) and rows[2 i + 1] (4..7), for the closest-feature sweep; they are
 * complete when the call returns true. */
static SX_ALWAYS_INLINE bool best_face_lanes(const sx_core *p, const sx_core *q, sx_real limit,
                                             sx_real *sep, int *face, sx_real *stop, int track,
                                             sx_r4 *rows, sx_r4 *qmag) {
    int i, n = p->count, m = q->count, f = 0;
    sx_r4 v00 = sx_r4_load2(&q->v[0].x);
    sx_r4 p0, p1, x0, y0;
    sx_real best = SX_NO_SEPARATION, s;
    v00 = sx_r4_low_halves(v00, v00);
    p0 = vertex_pair_lanes(q->v, 0, m, v00);
    p1 = vertex_pair_lanes(q->v, 2, m, v00);
    x0 = sx_r4_evens(p0, p1);
    y0 = sx_r4_odds(p0, p1);
    /* The lane-wise largest magnitudes of q's coordinates, from the values
     * loaded anyway (the clear-cut test's scale; padding repeats vertex 0). */
    *qmag = sx_r4_max(sx_r4_abs(p0), sx_r4_abs(p1));
    if (m <= 4) {
        for (i = 0; i < n; ++i) {
            sx_r4 d = face_lanes(p, i, x0, y0);
            s = lane_min(d, sx_r4_unordered(d, d));
            if (!(s <= limit)) {
                *stop = s;
                return false;
            }
            f = s > best ? i : f;
            best = s > best ? s : best;
            if (track) rows[2 * i] = d;
        }
    } else {
        sx_r4 p2 = vertex_pair_lanes(q->v, 4, m, v00), p3 = vertex_pair_lanes(q->v, 6, m, v00);
        sx_r4 x1 = sx_r4_evens(p2, p3), y1 = sx_r4_odds(p2, p3);
        *qmag = sx_r4_max(*qmag, sx_r4_max(sx_r4_abs(p2), sx_r4_abs(p3)));
        for (i = 0; i < n; ++i) {
            sx_r4 d0 = face_lanes(p, i, x0, y0), d1 = face_lanes(p, i, x1, y1);
            s = lane_min(sx_r4_min(d0, d1), sx_r4_unordered(d0, d1));
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
 * the rows best_face_lanes kept: point_best_face's answer bit for bit (its
 * separations are these lanes; d > m ? d : m is sx_r4_max(d, m)). */
static SX_MAYBE_UNUSED void vertex_faces(const sx_r4 *rows, int n, int m, int32_t *vface,
                                         sx_real *vsep) {
    int i;
    sx_r4 m0 = rows[0], m1 = rows[1];
    sx_i4 f0 = sx_i4_set1(0), f1 = f0;
    for (i = 1; i < n; ++i) {
        sx_r4 d0 = rows[2 * i];
        sx_m4 g0 = sx_r4_gt(d0, m0);
        sx_i4 fi = sx_i4_set1(i);
        m0 = sx_r4_max(d0, m0);
        f0 = sx_i4_select(g0, fi, f0);
        if (m > 4) {
            sx_r4 d1 = rows[2 * i + 1];
            sx_m4 g1 = sx_r4_gt(d1, m1);
            m1 = sx_r4_max(d1, m1);
            f1 = sx_i4_select(g1, fi, f1);
        }
    }
    sx_r4_store(&vsep[0], m0);
    sx_i4_store(&vface[0], f0);
    if (m > 4) {
        sx_r4_store(&vsep[4], m1);
        sx_i4_store(&vface[4], f1);
    }
}

/* The best face of p against q: the first of largest separation. Returns
 * false as soon as a face separates by more than limit (or by NaN), with
 * that separation in *stop. The running maximum is kept without a branch
 * (its comparisons go either way at random); the face index follows it. */
static SX_ALWAYS_INLINE bool best_face(const sx_core *p, const sx_core *q, sx_real limit,
                                       sx_real *sep, int *face, sx_real *stop, sx_sat *sat,
                                       int mag_bit) {
    int i, n = face_count(p), f = 0;
    sx_real best;
    if (n >= 3 && q->count >= 3) {
        sat->mags |= mag_bit;
        return best_face_lanes(p, q, limit, sep, face, stop, 0, NULL,
                               mag_bit == 1 ? &sat->mag_b : &sat->mag_a);
    }
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
    out->rows = false;
    out->mags = 0;
    if (limit > SX_R(0.0) && na >= 3 && nb >= 3) {
        /* Cores apart by less than limit need their closest features,
         * whose sweep starts from each vertex's face of largest
         * separation: the SAT's lanes have what it needs. */
        out->mags = 1;
        if (!best_face_lanes(a, b, limit, &out->sep_a, &out->face_a, &out->sep, 1, out->rows_b,
                             &out->mag_b)) {
            return false;
        }
        out->mags = 3;
        if (!best_face_lanes(b, a, limit, &out->sep_b, &out->face_b, &out->sep, 1, out->rows_a,
                             &out->mag_a)) {
            return false;
        }
        out->rows = true;
    } else {
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

#endif /* SEPAX_NARROW_SAT_H */
