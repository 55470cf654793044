/* sepax — the narrowphase core: overlap, exact penetration (MTV) and contact
 * manifolds of two rounded convex cores (see narrow.h) in one working frame:
 * the core builders, the overlap and MTV, the clipping of manifolds and the
 * entries of the pairs of two cores. The separating axes are in
 * narrow_sat.h, the closest features in narrow_closest.h, a core or polygon
 * against a point (the pairs with a circle) in narrow_point.c.
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
#include "narrow_closest.h"

/* ---- core builders ------------------------------------------------------ */

/* x == NULL keeps the shape's own frame (shape A). */
static sx_vec2 place_point(const sx_xform *x, sx_vec2 v) { return x ? sx_xform_point(*x, v) : v; }
static sx_vec2 place_vector(const sx_xform *x, sx_vec2 v) { return x ? sx_rotate(x->q, v) : v; }

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
    if (c == NULL || !sx_core_radius_ok(c->radius)) return false;
    return core_set_segment(c->a, c->b, c->radius, x, out);
}

/* Places p by the transform x into out (count, radius, storage and
 * pointers): two vertices (and normals) a register, each lane as
 * sx_xform_point and sx_rotate compute it (see sx_xf_rotate), so the
 * placed values do not depend on the width. Stored 16 bytes at a time, the
 * pairs best_face_lanes loads back, so the loads are forwarded from the
 * stores. */
static SX_ALWAYS_INLINE void place_polygon_rel(const sx_polygon *p, sx_xf x, sx_core *out) {
    int i, n = p->count;
    sx_r4 t = sx_r4_low_halves(x, x);
    out->radius = p->radius;
    out->count = n;
    out->v = out->vs;
    out->n = out->ns;
    for (i = 0; i + 1 < n; i += 2) {
        sx_r4_store(&out->vs[i].x, sx_r4_add(sx_xf_rotate(x, sx_r4_load(&p->vertices[i].x)), t));
        sx_r4_store(&out->ns[i].x, sx_xf_rotate(x, sx_r4_load(&p->normals[i].x)));
    }
    if (i < n) {
        sx_r4_store_low(&out->vs[i].x,
                        sx_r4_add(sx_xf_rotate(x, sx_r4_load2(&p->vertices[i].x)), t));
        sx_r4_store_low(&out->ns[i].x, sx_xf_rotate(x, sx_r4_load2(&p->normals[i].x)));
    }
}

bool sx_core_from_polygon(const sx_polygon *p, const sx_xform *x, sx_core *out) {
    int n;
    if (p == NULL || !sx_core_radius_ok(p->radius)) return false;
    n = p->count;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return false;
    out->radius = p->radius;
    out->count = n;
    if (x == NULL) {
        /* Shape A is read in place: no copy. */
        out->v = p->vertices;
        out->n = p->normals;
    } else {
        place_polygon_rel(p, sx_xf_of(x), out);
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
    /* (x - x) summed over every coordinate, two vertices a register: lanes
     * of 0 when all are finite, NaN otherwise, so one test checks it all. */
    sx_r4 sum = sx_r4_zero(), v, m;
    int i;
    for (i = 0; i + 1 < n; i += 2) {
        v = sx_r4_load(&v0[i].x);
        m = sx_r4_load(&n0[i].x);
        sum = sx_r4_add(sum, sx_r4_add(sx_r4_sub(v, v), sx_r4_sub(m, m)));
    }
    if (i < n) {
        v = sx_r4_load2(&v0[i].x);
        m = sx_r4_load2(&n0[i].x);
        sum = sx_r4_add(sum, sx_r4_add(sx_r4_sub(v, v), sx_r4_sub(m, m)));
    }
    return !sx_r4_any_nan(sum);
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

/* Face i of the polygon core ref, or the neighbour tied with it. Two faces
 * of ref bent by 1e-4 rad at a vertex separate inc by the same amount up to
 * rounding, and the SAT's pick of the two may leave inc's deepest vertex
 * (s) beyond its slab, where clipping cuts it off and the depth comes out
 * short. Of two such tied faces the one whose slab the deepest vertex is
 * in, or towards, is the reference; a real corner (the neighbour
 * separating clearly less) keeps face i. The rounding allowance takes in
 * the point the neighbour's separation is measured from: a neighbour
 * running far from the origin is placed with the rounding of its far end,
 * and a difference below that between the two faces says nothing. */
static SX_ALWAYS_INLINE int tied_reference_face(const sx_core *ref, int i, const sx_core *inc,
                                                int s) {
    int nb = slab_neighbour(ref, i, inc->v[s]);
    if (nb >= 0) {
        sx_vec2 v1 = ref->v[i], v2 = ref->v[next_index(ref, i)];
        sx_real tie = SX_DIRECTION_EPSILON *
                      sx_maxr(sx_maxr(max_abs_coord(v1, v2), max_abs_coord(ref->v[nb], ref->v[nb])),
                              max_abs_coord(inc->v[s], inc->v[s]));
        if (face_separation(ref, nb, inc) >= face_separation(ref, i, inc) - tie) return nb;
    }
    return i;
}

/* The incident face of the 2-point or polygon core inc against the
 * reference normal nref: the one most anti-parallel to it. A polygon's is
 * one of the two faces at its deepest vertex s along -nref (its normal is
 * the nearest in angle to -nref), so only those two compete: comparing
 * every face's normal alone lets two faces of a sliver (normals 1e-4 apart)
 * tie in rounding and pick a face far from the deepest vertex. Ties go to
 * the lower index. */
static SX_ALWAYS_INLINE int incident_face(const sx_core *inc, sx_vec2 nref, int s) {
    int prev;
    sx_real dp, ds;
    if (inc->count == 2) return sx_dot(inc->n[1], nref) < sx_dot(inc->n[0], nref) ? 1 : 0;
    prev = s > 0 ? s - 1 : inc->count - 1;
    dp = sx_dot(inc->n[prev], nref);
    ds = sx_dot(inc->n[s], nref);
    return dp < ds || (dp == ds && prev < s) ? prev : s;
}

/* Clips the incident segment w[0]-w[1] to one side of the reference slab,
 * d0 and d1 being its ends' distances inside that side: 0 when both ends
 * are outside, else 2 with the end outside moved to where the segment
 * crosses, at d0 / (d0 - d1) along it. When the ends differ across the side
 * by no more than `noise`, the rounding of their coordinates, the segment
 * runs along the reference normal, that fraction is rounding noise (it
 * could cut a long capsule almost anywhere), and the end outside lies
 * within rounding of the side: it stays as it is. */
static SX_ALWAYS_INLINE int clip_to_side(sx_vec2 w[2], sx_real d0, sx_real d1, sx_real noise) {
    if (d0 < SX_R(0.0) && d1 < SX_R(0.0)) return 0;
    if (d0 < SX_R(0.0) && d1 - d0 > noise) {
        w[0] = sx_lerp(w[0], w[1], d0 / (d0 - d1));
    } else if (d1 < SX_R(0.0) && d0 - d1 > noise) {
        w[1] = sx_lerp(w[1], w[0], d1 / (d1 - d0));
    }
    return 2;
}

/* The incident points of the 2-point or polygon core inc (deepest vertex
 * s) against face i of ref: the incident face's ends clipped to the
 * reference face's slab, in w with their vertex indices in k. Returns their
 * count, 1 or 2. */
static SX_ALWAYS_INLINE int incident_points(const sx_core *ref, int i, const sx_core *inc, int s,
                                            sx_vec2 w[2], int k[2]) {
    sx_vec2 nref = ref->n[i], t = sx_perp(nref);
    sx_vec2 v1 = ref->v[i], v2 = ref->v[next_index(ref, i)];
    sx_real lower, upper, noise;
    int nw;
    k[0] = incident_face(inc, nref, s);
    k[1] = next_index(inc, k[0]);
    w[0] = inc->v[k[0]];
    w[1] = inc->v[k[1]];
    lower = sx_dot(t, v1);
    upper = sx_dot(t, v2);
    noise = SX_DIRECTION_EPSILON * sx_maxr(max_abs_coord(v1, v2), max_abs_coord(w[0], w[1]));
    /* A reference face no wider than that rounding has no slab to clip to:
     * which side of it an incident end lies on is noise, and the ends stay
     * as they are; the depth test of clip_points keeps those that reach the
     * face. */
    if (!(upper - lower > noise)) {
        lower = -SX_REAL_MAX;
        upper = SX_REAL_MAX;
    }
    nw = clip_to_side(w, sx_dot(t, w[0]) - lower, sx_dot(t, w[1]) - lower, noise);
    if (nw == 2) nw = clip_to_side(w, upper - sx_dot(t, w[0]), upper - sx_dot(t, w[1]), noise);
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
    return nw;
}

/* The contact points of the nw incident points w (vertex indices k) against
 * face i of ref, written to out (working frame); returns their count.
 * Points deeper than -margin (less a rounding allowance) are kept; if none
 * is, the deepest one is, so an overlapping pair always reports a contact.
 * The one or two points are scalars, not arrays: indexed by the deepest
 * point, GCC kept them in memory and the loop waited on reloading what it
 * had just stored. */
static SX_ALWAYS_INLINE int clip_points(const sx_core *ref, int i, const sx_core *inc,
                                        const sx_vec2 w[2], const int k[2], int nw, sx_real margin,
                                        bool flip, const sx_manifold_point *exact,
                                        sx_manifold_point out[2]) {
    sx_vec2 nref = ref->n[i];
    sx_vec2 v1 = ref->v[i], v2 = ref->v[next_index(ref, i)];
    sx_real rr = ref->radius + inc->radius, half = ref->radius - inc->radius;
    sx_real sc0, sc1 = SX_R(0.0), d0, d1 = SX_R(0.0), lim, scale, slack;
    sx_vec2 p0, p1 = w[0];
    int deepest = 0, count = 0;
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
        /* Cores apart: the exact contact is the closest-feature point. A
         * single incident point is that contact seen along the face normal,
         * so take the exact one. With two, clipping can slide the deepest
         * incident vertex (a corner or capsule end just past the end of the
         * reference face) along a steep incident face and lose depth: the
         * point that came from that vertex becomes the exact contact. */
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
    return count;
}

/* Clips the incident feature of `inc` against face *face of `ref` (or a
 * face tied with it, see tied_reference_face, written back to *face) and
 * writes the contact points (working frame, see clip_points). flip: ref is
 * B. */
static int clip_face(const sx_core *ref, int *face, const sx_core *inc, sx_real margin, bool flip,
                     const sx_manifold_point *exact, sx_manifold_point out[2]) {
    int i = *face, k[2] = {0, 0}, nw = 1;
    sx_vec2 w[2] = {{SX_R(0.0), SX_R(0.0)}, {SX_R(0.0), SX_R(0.0)}};
    if (inc->count == 1) {
        w[0] = inc->v[0];
    } else {
        int s = support_below(inc, ref->n[i]);
        if (ref->count >= 3) {
            int tied = tied_reference_face(ref, i, inc, s);
            if (tied != i) {
                i = tied;
                *face = tied;
                s = support_below(inc, ref->n[i]);
            }
        }
        nw = incident_points(ref, i, inc, s, w, k);
    }
    return clip_points(ref, i, inc, w, k, nw, margin, flip, exact, out);
}

/* The two argument orders of a same-type pair compute the same separations
 * up to rounding, a few ulps of the coordinates: a signed gap farther from
 * zero than the touch rescue margin plus this wide rounding allowance gets
 * the same touch answer in both orders. */
#define SX_ORDER_ROUNDING (SX_R(1024.0) * SX_REAL_EPSILON)

static bool gap_is_clear(const sx_core *a, const sx_core *b, const sx_sat *sat, sx_real gap) {
    sx_real scale = sx_maxr(sat_pair_scale(a, b, sat), a->radius + b->radius);
    return sx_magnitude(gap) > SX_TOUCH_RESCUE_MARGIN + SX_ORDER_ROUNDING * scale;
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
    sx_xf r = sx_xf_relative(xa, xb);
    bool ok = sx_r4_all_finite(r);
    if (ok && kb == SX_SHAPE_POLYGON) {
        const sx_polygon *pb = (const sx_polygon *)b;
        ok = pb != NULL && sx_core_radius_ok(pb->radius) && pb->count >= 3 &&
             pb->count <= SX_MAX_POLYGON_VERTICES;
        if (ok) place_polygon_rel(pb, r, cb);
    } else if (ok) {
        sx_xform rel = sx_xform_of_xf(r);
        ok = core_of(kb, b, &rel, cb);
    }
    return ok && core_of(ka, a, NULL, ca);
}

static SX_ALWAYS_INLINE int cores_collide(int ka, const void *a, sx_xf xa, int kb, const void *b,
                                          sx_xf xb, sx_real margin, sx_real hysteresis,
                                          sx_manifold *out, bool *clear_cut) {
    sx_core ca, cb;
    int local, count;
    if (clear_cut) *clear_cut = false;
    if (!cores_build(ka, a, xa, kb, b, xb, &ca, &cb)) {
        sx_manifold_clear(out);
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

/* ---- the manifold entries of each pair ---------------------------------- */

/* Each pair's manifold in one function (the fused routines above, and
 * collide.c's general route for what they hand back), inlined into both of
 * its entries: sx_collide_NAME_xf for the typed pair functions and
 * sx_collide_NAME_shapes for the dispatch table (narrow.h), so that
 * sx_collide reaches the work through one call. The reversed order is the
 * dispatch table's business (it mirrors the manifold). The typed entries of
 * the pairs of core types call the out-of-line sx_cores_collide, as
 * sx_collide_NAME always has: only the dispatch table's copy is inlined. */

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
    /* A speculative margin at or above the rescue margin: two points, or a
     * clear-cut pair, is the gated route's answer too (collide_gated), which
     * the world's pairs nearly all are; the route's conversions of the
     * transforms and its calls cost more than this check. */
    bool speculative = !touch_test && margin >= SX_TOUCH_RESCUE_MARGIN;
    int count = 0;
    if (touch_test || speculative) {
        sx_real m = touch_test ? SX_R(0.0) : margin;
        bool clear_cut = false;
        count = inline_cores ? cores_collide(kind, a, xa, kind, b, xb, m, hyst, out, &clear_cut)
                             : sx_cores_collide(kind, a, xa, kind, b, xb, m, hyst, out, &clear_cut);
        if (clear_cut || (speculative && count == 2)) return count;
    }
    switch (kind) {
    case SX_SHAPE_SEGMENT:
        return sx_collide_segments_gated(a, xa, b, xb, margin, hyst, count, touch_test, out);
    case SX_SHAPE_CAPSULE:
        return sx_collide_capsules_gated(a, xa, b, xb, margin, hyst, count, touch_test, out);
    default: return sx_collide_polygons_gated(a, xa, b, xb, margin, hyst, count, touch_test, out);
    }
}

int sx_collide_capsule_segment_xf(const sx_capsule *a, sx_xf_arg xa, const sx_segment *b,
                                  sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_cores_collide(SX_SHAPE_CAPSULE, a, sx_xf_in(xa), SX_SHAPE_SEGMENT, b, sx_xf_in(xb),
                            margin, hyst, out, NULL);
}
int sx_collide_capsule_segment_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,
                                      sx_xf_arg xb, sx_real margin, sx_real hyst,
                                      sx_manifold *out) {
    return cores_collide(SX_SHAPE_CAPSULE, &a->u.capsule, sx_xf_in(xa), SX_SHAPE_SEGMENT,
                         &b->u.segment, sx_xf_in(xb), margin, hyst, out, NULL);
}

int sx_collide_polygon_segment_xf(const sx_polygon *a, sx_xf_arg xa, const sx_segment *b,
                                  sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_cores_collide(SX_SHAPE_POLYGON, a, sx_xf_in(xa), SX_SHAPE_SEGMENT, b, sx_xf_in(xb),
                            margin, hyst, out, NULL);
}
int sx_collide_polygon_segment_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,
                                      sx_xf_arg xb, sx_real margin, sx_real hyst,
                                      sx_manifold *out) {
    return cores_collide(SX_SHAPE_POLYGON, &a->u.polygon, sx_xf_in(xa), SX_SHAPE_SEGMENT,
                         &b->u.segment, sx_xf_in(xb), margin, hyst, out, NULL);
}

int sx_collide_polygon_capsule_xf(const sx_polygon *a, sx_xf_arg xa, const sx_capsule *b,
                                  sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_cores_collide(SX_SHAPE_POLYGON, a, sx_xf_in(xa), SX_SHAPE_CAPSULE, b, sx_xf_in(xb),
                            margin, hyst, out, NULL);
}
int sx_collide_polygon_capsule_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,
                                      sx_xf_arg xb, sx_real margin, sx_real hyst,
                                      sx_manifold *out) {
    return cores_collide(SX_SHAPE_POLYGON, &a->u.polygon, sx_xf_in(xa), SX_SHAPE_CAPSULE,
                         &b->u.capsule, sx_xf_in(xb), margin, hyst, out, NULL);
}

int sx_collide_segments_xf(const sx_segment *a, sx_xf_arg xa, const sx_segment *b, sx_xf_arg xb,
                           sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_SEGMENT, false, a, sx_xf_in(xa), b, sx_xf_in(xb), margin,
                             hyst, out);
}
int sx_collide_segments_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b, sx_xf_arg xb,
                               sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_SEGMENT, true, &a->u.segment, sx_xf_in(xa), &b->u.segment,
                             sx_xf_in(xb), margin, hyst, out);
}

int sx_collide_capsules_xf(const sx_capsule *a, sx_xf_arg xa, const sx_capsule *b, sx_xf_arg xb,
                           sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_CAPSULE, false, a, sx_xf_in(xa), b, sx_xf_in(xb), margin,
                             hyst, out);
}
int sx_collide_capsules_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b, sx_xf_arg xb,
                               sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_CAPSULE, true, &a->u.capsule, sx_xf_in(xa), &b->u.capsule,
                             sx_xf_in(xb), margin, hyst, out);
}

int sx_collide_polygons_xf(const sx_polygon *a, sx_xf_arg xa, const sx_polygon *b, sx_xf_arg xb,
                           sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_POLYGON, false, a, sx_xf_in(xa), b, sx_xf_in(xb), margin,
                             hyst, out);
}
int sx_collide_polygons_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b, sx_xf_arg xb,
                               sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_same_type(SX_SHAPE_POLYGON, true, &a->u.polygon, sx_xf_in(xa), &b->u.polygon,
                             sx_xf_in(xb), margin, hyst, out);
}
