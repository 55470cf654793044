/* sepax — point queries (containment, closest point, signed distance) and the
 * segment-segment intersection.
 *
 * Every shape is read as a convex core (a point, a segment or a polygon) grown
 * by a radius, so one signed-distance routine per core answers all of them:
 * the distance to the core's boundary minus the radius, with the closest
 * boundary point and the outward normal beside it. The query point is first
 * moved into the shape's local frame, where the arithmetic happens on small
 * numbers even when the shape sits far from the world origin. The segment
 * intersection solves p1 + t r = q1 + u s with 2D cross products and treats
 * the parallel, collinear and zero-length cases explicitly, each with a
 * tolerance relative to the lengths involved, so the answer does not depend
 * on the units the caller works in. */
#include "query.h"

/* The boundary band of sx_contains_point, as collide.h documents it: a
 * thousandth of the linear slop (5 micrometres at the default scale), wide
 * enough to absorb the rounding of the local-frame transform of a point on
 * the boundary, far below any distance the solver cares about. */
#define SX_CONTAINS_TOLERANCE (SX_R(1.0e-3) * SX_LINEAR_SLOP)

/* A signed distance in the shape's local frame. */
typedef struct local_distance {
    sx_real distance; /* negative inside */
    sx_vec2 point;    /* closest boundary point */
    sx_vec2 normal;   /* outward unit normal at point */
} local_distance;

/* Distance from p to the disc of `radius` around c. `fallback` is the normal
 * used when p is c itself (no direction to measure along). */
static local_distance round_point_distance(sx_vec2 c, sx_real radius, sx_vec2 p, sx_vec2 fallback) {
    local_distance r;
    sx_vec2 d = sx_sub(p, c);
    sx_real len = SX_R(0.0);
    if (sx_query_unit(d, &r.normal)) {
        /* d . unit(d) keeps the length of a tiny d whose squares underflow. */
        len = sx_dot(d, r.normal);
    } else {
        r.normal = fallback;
    }
    r.distance = len - radius;
    r.point = sx_mul_add(c, radius, r.normal);
    return r;
}

/* Distance from p to the segment a-b grown by radius. On the segment itself
 * the normal falls back to the segment's left normal, or to `fallback` when
 * the segment has zero length. */
static local_distance round_segment_distance(sx_vec2 a, sx_vec2 b, sx_real radius, sx_vec2 p,
                                             sx_vec2 fallback) {
    sx_vec2 q = sx_closest_point_on_segment(a, b, p, NULL);
    sx_vec2 left;
    if (sx_query_unit(sx_perp(sx_sub(b, a)), &left)) fallback = left;
    return round_point_distance(q, radius, p, fallback);
}

/* p - v for the end v of edge a-b nearer p (by the 1-norm): a signed
 * distance to the edge's line taken from it rounds to a few ulps of |p - v|
 * rather than of the edge's length. That matters beyond the tip of a
 * sliver, where a point a hair's breadth outside the far edge's line can lie
 * well outside the polygon, and only the nearer end resolves it. */
static sx_vec2 edge_offset(sx_vec2 a, sx_vec2 b, sx_vec2 p) {
    sx_vec2 da = sx_sub(p, a), db = sx_sub(p, b);
    return sx_absr(db.x) + sx_absr(db.y) < sx_absr(da.x) + sx_absr(da.y) ? db : da;
}

/* Distance from p to a (possibly rounded) convex polygon. Inside the core the
 * nearest boundary point lies straight out through the edge of largest
 * separation (the disc of that radius fits inside every half-plane), so one
 * pass over the edge planes answers it; outside, the nearest point of the
 * core boundary is the nearest point over all edges. */
static local_distance polygon_distance(const sx_polygon *poly, sx_vec2 p) {
    local_distance r;
    sx_real best_sep = -SX_REAL_MAX, best_d2 = SX_REAL_MAX;
    sx_vec2 best_q;
    int i, best = 0, n = poly->count;
    for (i = 0; i < n; ++i) {
        sx_real sep = sx_dot(poly->normals[i],
                             edge_offset(poly->vertices[i], poly->vertices[(i + 1) % n], p));
        if (sep > best_sep) {
            best_sep = sep;
            best = i;
        }
    }
    if (best_sep <= SX_R(0.0)) {
        r.normal = poly->normals[best];
        r.distance = best_sep - poly->radius;
        r.point = sx_mul_sub(p, r.distance, r.normal);
        return r;
    }
    best_q = poly->vertices[0];
    for (i = 0; i < n; ++i) {
        sx_vec2 q =
            sx_closest_point_on_segment(poly->vertices[i], poly->vertices[(i + 1) % n], p, NULL);
        sx_real d2 = sx_distance_sq(p, q);
        if (d2 < best_d2) {
            best_d2 = d2;
            best_q = q;
        }
    }
    return round_point_distance(best_q, poly->radius, p, poly->normals[best]);
}

/* The signed distance of local point p to a usable shape. `fallback` is the
 * local direction of world +x, the normal at a circle's centre. */
static local_distance shape_distance(const sx_shape *s, sx_vec2 p, sx_vec2 fallback) {
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        return round_point_distance(s->u.circle.center, s->u.circle.radius, p, fallback);
    case SX_SHAPE_SEGMENT:
        return round_segment_distance(s->u.segment.a, s->u.segment.b, SX_R(0.0), p, fallback);
    case SX_SHAPE_CAPSULE:
        return round_segment_distance(s->u.capsule.a, s->u.capsule.b, s->u.capsule.radius, p,
                                      fallback);
    default: return polygon_distance(&s->u.polygon, p);
    }
}

/* Checks the input and moves p into the shape's frame. False also when the
 * move itself overflows (coordinates near SX_REAL_MAX). */
static bool to_local(const sx_shape *s, sx_xform x, sx_vec2 p, sx_vec2 *local) {
    if (!sx_query_shape_ok(s) || !sx_xform_is_finite(x) || !sx_vec2_is_finite(p)) return false;
    *local = sx_xform_inv_point(x, p);
    return sx_vec2_is_finite(*local);
}

/* The local direction of world +x: the normal at a circle's centre. */
static sx_vec2 local_x_axis(sx_xform x) {
    return sx_xform_inv_vector(x, sx_v2(SX_R(1.0), SX_R(0.0)));
}

/* ---- point queries ------------------------------------------------------ */

bool sx_contains_point(const sx_shape *s, sx_xform x, sx_vec2 p) {
    const sx_real tol = SX_CONTAINS_TOLERANCE;
    sx_vec2 lp;
    if (!to_local(s, x, p, &lp)) return false;
    switch (s->type) {
    case SX_SHAPE_CIRCLE: {
        sx_real r = s->u.circle.radius + tol;
        return sx_distance_sq(lp, s->u.circle.center) <= r * r;
    }
    case SX_SHAPE_SEGMENT: {
        sx_vec2 q = sx_closest_point_on_segment(s->u.segment.a, s->u.segment.b, lp, NULL);
        return sx_distance_sq(lp, q) <= tol * tol;
    }
    case SX_SHAPE_CAPSULE: {
        sx_real r = s->u.capsule.radius + tol;
        sx_vec2 q = sx_closest_point_on_segment(s->u.capsule.a, s->u.capsule.b, lp, NULL);
        return sx_distance_sq(lp, q) <= r * r;
    }
    default: {
        const sx_polygon *poly = &s->u.polygon;
        int i, n = poly->count;
        bool in_band = false;
        if (poly->radius > SX_R(0.0)) return polygon_distance(poly, lp).distance <= tol;
        /* p is left of every CCW edge: inside. cross(u, p - v), u the
         * edge's unit direction, is the signed distance to the edge's line
         * (from the edge's nearer end, see edge_offset), so a point farther
         * than tol right of a line is outside. u is normalised by its
         * largest component first: cross(e, p - v) itself underflows to 0
         * for an edge of denormal length. */
        for (i = 0; i < n; ++i) {
            sx_vec2 v = poly->vertices[i], v2 = poly->vertices[(i + 1) % n], u;
            sx_real c;
            if (!sx_query_unit(sx_sub(v2, v), &u)) continue;
            c = sx_cross(u, edge_offset(v, v2, lp));
            if (c < SX_R(0.0)) {
                if (c < -tol) return false;
                in_band = true;
            }
        }
        /* A point within tol of some edge lines but right of one: the
         * half-planes widened by tol meet up to tol / sin(theta / 2) beyond
         * a vertex of angle theta (hundreds of tol at a sliver's tip), so
         * the band is measured as the true distance to the polygon. */
        return !in_band || polygon_distance(poly, lp).distance <= tol;
    }
    }
}

sx_vec2 sx_closest_point_on_segment(sx_vec2 a, sx_vec2 b, sx_vec2 p, sx_real *t) {
    sx_real u = SX_R(0.0);
    sx_vec2 q = a;
    if (!sx_vec2_is_finite(a) || !sx_vec2_is_finite(b) || !sx_vec2_is_finite(p)) {
        if (!sx_vec2_is_finite(a)) q = sx_v2_zero();
    } else {
        sx_vec2 d = sx_sub(b, a);
        sx_real m = sx_maxr(sx_absr(d.x), sx_absr(d.y));
        /* Dividing by the largest component first keeps d . d from
         * underflowing for tiny segments and from overflowing for huge ones. */
        if (m > SX_R(0.0) && sx_is_finite(m)) {
            sx_vec2 ds = sx_v2(d.x / m, d.y / m);
            sx_vec2 w = sx_sub(p, a);
            u = sx_dot(sx_v2(w.x / m, w.y / m), ds) / sx_dot(ds, ds);
            /* Written so that a NaN from an overflowing p - a lands on 0. */
            if (!(u > SX_R(0.0))) {
                u = SX_R(0.0);
            } else if (!(u < SX_R(1.0))) {
                u = SX_R(1.0);
            }
            /* The end points are returned exactly, not re-derived. */
            q = u == SX_R(0.0) ? a : (u == SX_R(1.0) ? b : sx_mul_add(a, u, d));
        }
    }
    if (t != NULL) *t = u;
    return q;
}

sx_vec2 sx_closest_point(const sx_shape *s, sx_xform x, sx_vec2 p) {
    local_distance ld;
    sx_vec2 lp, q;
    if (!to_local(s, x, p, &lp)) return sx_v2_zero();
    ld = shape_distance(s, lp, local_x_axis(x));
    if (ld.distance <= SX_R(0.0)) return p;
    q = sx_xform_point(x, ld.point);
    return sx_vec2_is_finite(q) ? q : sx_v2_zero();
}

sx_real sx_shape_distance_to_point(const sx_shape *s, sx_xform x, sx_vec2 p,
                                   sx_vec2 *boundary_point, sx_vec2 *normal) {
    local_distance ld;
    sx_vec2 lp, bp = sx_v2_zero(), n = sx_v2_zero();
    sx_real d = SX_REAL_MAX;
    if (to_local(s, x, p, &lp)) {
        ld = shape_distance(s, lp, local_x_axis(x));
        bp = sx_xform_point(x, ld.point);
        n = sx_xform_vector(x, ld.normal);
        d = ld.distance;
        if (!sx_is_finite(d) || !sx_vec2_is_finite(bp) || !sx_vec2_is_finite(n)) {
            d = SX_REAL_MAX;
            bp = sx_v2_zero();
            n = sx_v2_zero();
        }
    }
    if (boundary_point != NULL) *boundary_point = bp;
    if (normal != NULL) *normal = n;
    return d;
}

/* ---- segment-segment intersection --------------------------------------- */

static sx_segment_relation finish(sx_segment_intersection *out, sx_segment_relation relation) {
    if (out != NULL) out->relation = relation;
    return relation;
}

/* Clamps a line parameter known to lie within tolerance of [0, 1]. */
static sx_real clamp01(sx_real t) { return sx_clampr(t, SX_R(0.0), SX_R(1.0)); }

/* A single common point c, with its parameters on both segments. */
static sx_segment_relation single_point(sx_segment_intersection *out, sx_vec2 c, sx_real t,
                                        sx_real u) {
    if (out != NULL) {
        out->point = c;
        out->t = t;
        out->u = u;
        out->overlap_start = c;
        out->overlap_end = c;
    }
    return finish(out, SX_SEGMENTS_INTERSECT);
}

/* Point c against the segment a + v d (d non-zero, length dlen): true and *v
 * in [0, 1] when c lies on it, measured with the relative tolerance against
 * the scale of the configuration. */
static bool point_on_segment(sx_vec2 c, sx_vec2 a, sx_vec2 d, sx_real dlen, sx_real *v) {
    const sx_real tol = SX_QUERY_REL_TOLERANCE;
    sx_vec2 w = sx_sub(c, a);
    sx_real scale = sx_maxr(dlen, sx_length(w));
    sx_real along;
    /* cross(d, w) / |d| is the distance of c from the line. */
    if (sx_absr(sx_cross(d, w)) > tol * scale * dlen) return false;
    along = sx_dot(w, d) / (dlen * dlen);
    if (along < -tol * scale / dlen || along > SX_R(1.0) + tol * scale / dlen) return false;
    *v = clamp01(along);
    return true;
}

/* The two segments p1 p2 and q1 q2 as sx_intersect_segments reads them:
 * r and s their directions, w from p1 to q1, rlen and slen the lengths. */
typedef struct segment_pair {
    sx_vec2 p1, p2, q1, q2;
    sx_vec2 r, s, w;
    sx_real rlen, slen;
} segment_pair;

/* True when the coordinates are large enough for the cross products of
 * sx_intersect_segments to overflow. */
static bool too_large(const segment_pair *g) {
    const sx_real big = SX_R(0.125) * sx_sqrt(SX_REAL_MAX);
    sx_vec2 r = g->r, s = g->s, w = g->w, z = sx_sub(g->q2, g->p1);
    sx_real m =
        sx_maxr(sx_maxr(sx_maxr(sx_absr(r.x), sx_absr(r.y)), sx_maxr(sx_absr(s.x), sx_absr(s.y))),
                sx_maxr(sx_maxr(sx_absr(w.x), sx_absr(w.y)), sx_maxr(sx_absr(z.x), sx_absr(z.y))));
    return !(m <= big);
}

/* Two segments of non-zero length on lines that cross at one point (rxs:
 * r x s, clear of zero): t and u from the cross products. */
static sx_segment_relation crossing(const segment_pair *g, sx_real rxs,
                                    sx_segment_intersection *out) {
    const sx_real tol = SX_QUERY_REL_TOLERANCE;
    sx_real t = sx_cross(g->w, g->s) / rxs;
    sx_real u = sx_cross(g->w, g->r) / rxs;
    sx_real t_tol = tol * sx_maxr(SX_R(1.0), sx_length(g->w) / g->rlen);
    sx_real u_tol = tol * sx_maxr(SX_R(1.0), sx_length(g->w) / g->slen);
    sx_vec2 c;
    if (t < -t_tol || t > SX_R(1.0) + t_tol || u < -u_tol || u > SX_R(1.0) + u_tol) {
        return finish(out, SX_SEGMENTS_DISJOINT);
    }
    /* Within the slack of an end, snap to it: a T-junction reports the
     * exact end point rather than a point a rounding error away. */
    t = t < t_tol ? SX_R(0.0) : (t > SX_R(1.0) - t_tol ? SX_R(1.0) : t);
    u = u < u_tol ? SX_R(0.0) : (u > SX_R(1.0) - u_tol ? SX_R(1.0) : u);
    /* An end point that is part of the answer is returned exactly. */
    if (t == SX_R(0.0)) {
        c = g->p1;
    } else if (t == SX_R(1.0)) {
        c = g->p2;
    } else if (u == SX_R(0.0)) {
        c = g->q1;
    } else if (u == SX_R(1.0)) {
        c = g->q2;
    } else {
        c = sx_mul_add(g->p1, t, g->r);
    }
    return single_point(out, c, t, u);
}

/* Two parallel segments of non-zero length. Collinear when both of q's end
 * points lie on p's line, within the relative tolerance of the
 * configuration's size. */
static sx_segment_relation parallel(const segment_pair *g, sx_segment_intersection *out) {
    const sx_real tol = SX_QUERY_REL_TOLERANCE;
    sx_vec2 p1 = g->p1, p2 = g->p2, q1 = g->q1, q2 = g->q2, r = g->r, w = g->w;
    sx_real rlen = g->rlen;
    sx_real scale = sx_maxr(sx_maxr(rlen, g->slen), sx_maxr(sx_length(w), sx_distance(p1, q2)));
    sx_real rr = rlen * rlen;
    sx_real t0, t1, lo, hi, slack;
    sx_vec2 lo_point, hi_point;
    if (sx_absr(sx_cross(r, w)) > tol * scale * rlen ||
        sx_absr(sx_cross(r, sx_sub(q2, p1))) > tol * scale * rlen) {
        return finish(out, SX_SEGMENTS_PARALLEL);
    }
    /* q's end points as parameters along p; the shared part is the
     * intersection of [t0, t1] (sorted) with [0, 1]. */
    t0 = sx_dot(w, r) / rr;
    t1 = sx_dot(sx_sub(q2, p1), r) / rr;
    slack = tol * scale / rlen;
    if (t0 <= t1) {
        lo = t0;
        lo_point = q1;
        hi = t1;
        hi_point = q2;
    } else {
        lo = t1;
        lo_point = q2;
        hi = t0;
        hi_point = q1;
    }
    if (hi < -slack || lo > SX_R(1.0) + slack) return finish(out, SX_SEGMENTS_COLLINEAR_DISJOINT);
    if (lo <= SX_R(0.0)) {
        lo = SX_R(0.0);
        lo_point = p1;
    } else if (lo >= SX_R(1.0)) {
        lo = SX_R(1.0);
        lo_point = p2;
    }
    if (hi >= SX_R(1.0)) {
        hi = SX_R(1.0);
        hi_point = p2;
    } else if (hi <= SX_R(0.0)) {
        hi = SX_R(0.0);
        hi_point = p1;
    }
    if (out != NULL) {
        sx_real u;
        out->point = lo_point;
        out->t = lo;
        (void)sx_closest_point_on_segment(q1, q2, lo_point, &u);
        out->u = u;
        out->overlap_start = lo_point;
        out->overlap_end = hi < lo ? lo_point : hi_point;
    }
    return finish(out, SX_SEGMENTS_OVERLAP);
}

sx_segment_relation sx_intersect_segments(sx_vec2 p1, sx_vec2 p2, sx_vec2 q1, sx_vec2 q2,
                                          sx_segment_intersection *out) {
    const sx_real tol = SX_QUERY_REL_TOLERANCE;
    segment_pair g;
    sx_real rxs, v;
    if (out != NULL) {
        out->point = sx_v2_zero();
        out->t = SX_R(0.0);
        out->u = SX_R(0.0);
        out->overlap_start = sx_v2_zero();
        out->overlap_end = sx_v2_zero();
    }
    g.p1 = p1;
    g.p2 = p2;
    g.q1 = q1;
    g.q2 = q2;
    g.r = sx_sub(p2, p1);
    g.s = sx_sub(q2, q1);
    g.w = sx_sub(q1, p1);
    if (!sx_vec2_is_finite(g.r) || !sx_vec2_is_finite(g.s) || !sx_vec2_is_finite(g.w) ||
        !sx_vec2_is_finite(p1) || !sx_vec2_is_finite(q1) || too_large(&g)) {
        return finish(out, SX_SEGMENTS_DEGENERATE);
    }
    g.rlen = sx_length(g.r);
    g.slen = sx_length(g.s);

    /* Zero-length segments are points: on the other segment or not. Two
     * points meet only when they are equal. */
    if (!(g.rlen > SX_R(0.0)) && !(g.slen > SX_R(0.0))) {
        if (p1.x == q1.x && p1.y == q1.y) return single_point(out, p1, SX_R(0.0), SX_R(0.0));
        return finish(out, SX_SEGMENTS_DISJOINT);
    }
    if (!(g.rlen > SX_R(0.0))) {
        if (point_on_segment(p1, q1, g.s, g.slen, &v)) return single_point(out, p1, SX_R(0.0), v);
        return finish(out, SX_SEGMENTS_DISJOINT);
    }
    if (!(g.slen > SX_R(0.0))) {
        if (point_on_segment(q1, p1, g.r, g.rlen, &v)) return single_point(out, q1, v, SX_R(0.0));
        return finish(out, SX_SEGMENTS_DISJOINT);
    }
    rxs = sx_cross(g.r, g.s);
    if (sx_absr(rxs) > tol * g.rlen * g.slen) return crossing(&g, rxs, out);
    return parallel(&g, out);
}
