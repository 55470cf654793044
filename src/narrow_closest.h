/* sepax — private: the closest features of two disjoint cores (see
 * narrow.h): the coordinate scales the tolerances are taken from, and the
 * vertex-against-edge and vertex-against-vertex sweep that gives the exact
 * distance and direction, pruned by the SAT's rows.
 *
 * Static functions defined here for the same reason as narrow_sat.h's: both
 * narrow_core.c and narrow_point.c inline them into their hot paths. */
#ifndef SEPAX_NARROW_CLOSEST_H
#define SEPAX_NARROW_CLOSEST_H

#include "narrow_sat.h"

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

/* The sweep's start: no candidate yet (infinite distance), the first
 * vertices pa and pb standing in as the vertex pair. */
static inline void closest_start(sx_closest *out, sx_vec2 pa, sx_vec2 pb) {
    out->dist_sq = SX_REAL_MAX;
    out->distance = SX_REAL_MAX;
    out->kind = SX_CLOSEST_VERTICES;
    out->ia = 0;
    out->ib = 0;
    out->pa = pa;
    out->pb = pb;
    out->normal = sx_v2_zero();
}

/* The lane-wise largest magnitudes of a core's points and m's, two points
 * a register (unreduced: the caller folds the lanes once). */
static SX_ALWAYS_INLINE sx_r4 core_magnitudes(const sx_core *c, sx_r4 m) {
    int i, n = c->count;
    for (i = 0; i + 1 < n; i += 2)
        m = sx_r4_max(m, sx_r4_abs(sx_r4_load(&c->v[i].x)));
    if (i < n) m = sx_r4_max(m, sx_r4_abs(sx_r4_load2(&c->v[i].x)));
    return m;
}

/* Largest coordinate magnitude of the points of two cores. The largest
 * magnitude of finite values does not depend on the order it is taken in;
 * with a NaN or an infinity in a core the order decides, but such a core
 * never gets a manifold point or an overlap, whatever the tests that use
 * this scale say. */
static SX_ALWAYS_INLINE sx_real core_pair_scale(const sx_core *a, const sx_core *b) {
    return sx_r4_first(sx_r4_max_lanes(core_magnitudes(b, core_magnitudes(a, sx_r4_zero()))));
}

/* core_pair_scale, with the magnitudes the SAT took (sat may be NULL). */
static SX_ALWAYS_INLINE sx_real sat_pair_scale(const sx_core *a, const sx_core *b,
                                               const sx_sat *sat) {
    sx_r4 m;
    if (sat == NULL) return core_pair_scale(a, b);
    m = (sat->mags & 1) ? sat->mag_b : core_magnitudes(b, sx_r4_zero());
    m = (sat->mags & 2) ? sx_r4_max(m, sat->mag_a) : core_magnitudes(a, m);
    return sx_r4_first(sx_r4_max_lanes(m));
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
 * for a q far beyond the face's ends, and a gap of metres could come out
 * as kilometres.
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
static SX_MAYBE_UNUSED void vertex_direction(sx_closest *c) {
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
static SX_MAYBE_UNUSED void offer_vertices(const sx_core *p, const sx_core *q, bool p_is_a,
                                           sx_closest *out, const int32_t *vface,
                                           const sx_real *vsep, sx_real slack) {
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
static SX_MAYBE_UNUSED void closest_features(const sx_core *a, const sx_core *b, const sx_sat *sat,
                                             sx_closest *out) {
    int ea = a->count >= 3 ? a->count : a->count - 1;
    int eb = b->count >= 3 ? b->count : b->count - 1;
    closest_start(out, a->v[0], b->v[0]);
    if (sat != NULL && sat->rows) {
        sx_real slack = SX_PRUNE_SLACK * sat_pair_scale(a, b, sat);
        int32_t vface[SX_VERTEX_SLOTS];
        sx_real vsep[SX_VERTEX_SLOTS];
        vertex_faces(sat->rows_b, a->count, b->count, vface, vsep);
        offer_vertices(a, b, true, out, vface, vsep, slack);
        vertex_faces(sat->rows_a, b->count, a->count, vface, vsep);
        offer_vertices(b, a, false, out, vface, vsep, slack);
    } else {
        offer_vertices(a, b, true, out, NULL, NULL, SX_R(0.0));
        offer_vertices(b, a, false, out, NULL, NULL, SX_R(0.0));
    }
    if (ea == 0 && eb == 0) out->dist_sq = sx_distance_sq(a->v[0], b->v[0]);
    vertex_direction(out);
}

/* The direction of a contact whose closest points coincide: the best SAT
 * axis, or A's local +x when there is none (two coincident points). */
static SX_MAYBE_UNUSED sx_vec2 fallback_normal(const sx_sat *sat) {
    if (sat->has_axes) return sat->axis;
    return sx_v2(SX_R(1.0), SX_R(0.0));
}

#endif /* SEPAX_NARROW_CLOSEST_H */
