/* sepax — the narrowphase's cheap pairs: a segment, capsule or polygon core
 * (or a polygon read in place, without a core) against one point of radius
 * rb, the circle's centre; and the entries of the pairs with a circle. The
 * routines are those of narrow_core.c written out for a 1-point core (see
 * below), on the separating axes of narrow_sat.h and the closest features
 * of narrow_closest.h. */
#include "narrow_closest.h"

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
    closest_start(out, a->v[0], c);
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
/* The separations sx_dot(nn[i], sx_sub(c, v[i])) of the point cc = [c.x,
 * c.y, c.x, c.y] from faces i..i+3, each computed as that expression
 * computes it; faces past count repeat face 0 (v00, n00: its vertex and
 * normal in both halves), which cannot change a first maximum. */
static SX_ALWAYS_INLINE sx_r4 point_face_lanes(const sx_vec2 *v, const sx_vec2 *nn, int count,
                                               int i, sx_r4 cc, sx_r4 v00, sx_r4 n00) {
    sx_r4 v0 = vertex_pair_lanes(v, i, count, v00), v1 = vertex_pair_lanes(v, i + 2, count, v00);
    sx_r4 m0 = vertex_pair_lanes(nn, i, count, n00), m1 = vertex_pair_lanes(nn, i + 2, count, n00);
    sx_r4 p0 = sx_r4_mul(m0, sx_r4_sub(cc, v0)), p1 = sx_r4_mul(m1, sx_r4_sub(cc, v1));
    return sx_r4_add(sx_r4_evens(p0, p1), sx_r4_odds(p0, p1));
}

/* (x - x) over the vertices and normals of faces i..i+3, padded as
 * point_face_lanes pads them: lanes of 0 when all are finite, NaN
 * otherwise (sx_polygon_values_finite's test). Taken only once the answer
 * is not "apart", from values the face loop has just brought in. */
static SX_ALWAYS_INLINE sx_r4 point_finite_lanes(const sx_vec2 *v, const sx_vec2 *nn, int count,
                                                 int i, sx_r4 v00, sx_r4 n00) {
    sx_r4 v0 = vertex_pair_lanes(v, i, count, v00), v1 = vertex_pair_lanes(v, i + 2, count, v00);
    sx_r4 m0 = vertex_pair_lanes(nn, i, count, n00), m1 = vertex_pair_lanes(nn, i + 2, count, n00);
    return sx_r4_add(sx_r4_add(sx_r4_sub(v0, v0), sx_r4_sub(v1, v1)),
                     sx_r4_add(sx_r4_sub(m0, m0), sx_r4_sub(m1, m1)));
}

/* [p.x, p.y, p.x, p.y]. */
static SX_ALWAYS_INLINE sx_r4 point_twice(const sx_vec2 *p) {
    sx_r4 r = sx_r4_load2(&p->x);
    return sx_r4_low_halves(r, r);
}

/* polygon_point once the closest point is out->vertex, a corner of `face`
 * (i2: the vertex after face). */
static SX_ALWAYS_INLINE int polygon_point_corner(const sx_vec2 *v, const sx_vec2 *nn, int count,
                                                 sx_vec2 c, sx_real limit, int face, int i2,
                                                 sx_polygon_point *out) {
    int vertex = out->vertex;
    /* The corner's region ends at the face past it: beyond, rounding
     * chose the face (see offer_face_walk), and the general route walks
     * on. */
    int side_face = vertex == face ? (face > 0 ? face - 1 : count - 1) : i2;
    sx_real past = sx_dot(sx_sub(c, v[vertex]), sx_v2(-nn[side_face].y, nn[side_face].x));
    sx_real dsq;
    if (vertex == face ? !(past >= SX_R(0.0)) : !(past <= SX_R(0.0))) return -1;
    out->on = v[vertex];
    dsq = sx_distance_sq(out->on, c);
    if (!(dsq < SX_REAL_MAX)) return -1;
    out->distance = sx_sqrt(dsq);
    /* Below SX_SQUARE_SAFE vertex_direction measures the distance scaled,
     * which may decide differently. */
    if (!(out->distance >= SX_SQUARE_SAFE)) return -1;
    if (!(out->distance <= limit)) return 0;
    if (!(out->distance > SX_DIRECTION_EPSILON * max_abs_coord(out->on, c))) return -1;
    out->dir = sx_scale(sx_sub(c, out->on), SX_R(1.0) / out->distance);
    return 1;
}

/* values_finite (may be NULL): whether every vertex and normal is finite,
 * set when the answer is 1 (sx_polygon_values_finite's answer). */
static SX_ALWAYS_INLINE int polygon_point(const sx_vec2 *v, const sx_vec2 *nn, int count, sx_vec2 c,
                                          sx_real limit, sx_polygon_point *out,
                                          bool *values_finite) {
    int face = 0, i2, vertex = -1;
    sx_real best, t;
    sx_vec2 w, n, dir;
    {
        /* Every face's separation four to a register; the first of the
         * largest is the lowest lane equal to the maximum (a scalar loop
         * keeps the first with a strict comparison). Its separation is
         * then taken once more by the scalar expression: the maximum of
         * the lanes may differ from it in the sign of a zero. */
        sx_r4 cc = point_twice(&c), v00 = point_twice(&v[0]), n00 = point_twice(&nn[0]);
        sx_r4 s0, mx;
        sx_m4 bad;
        int mask;
        s0 = point_face_lanes(v, nn, count, 0, cc, v00, n00);
        bad = sx_r4_unordered(s0, s0);
        if (count > 4) {
            sx_r4 s1 = point_face_lanes(v, nn, count, 4, cc, v00, n00);
            bad = sx_m4_or(bad, sx_r4_unordered(s1, s1));
            mx = sx_r4_max_lanes(sx_r4_max(s0, s1));
            mask = sx_m4_bits(sx_r4_eq(s0, mx)) | (sx_m4_bits(sx_r4_eq(s1, mx)) << 4);
        } else {
            mx = sx_r4_max_lanes(s0);
            mask = sx_m4_bits(sx_r4_eq(s0, mx));
        }
        best = sx_r4_first(mx);
        if (sx_m4_any(bad) || !(best <= limit)) return 0;
        face = sx_lowest_bit((uint64_t)mask);
        best = sx_dot(nn[face], sx_sub(c, v[face]));
        if (values_finite) {
            sx_r4 fold = point_finite_lanes(v, nn, count, 0, v00, n00);
            if (count > 4) fold = sx_r4_add(fold, point_finite_lanes(v, nn, count, 4, v00, n00));
            *values_finite = !sx_r4_any_nan(fold);
        }
    }
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
    if (vertex >= 0) return polygon_point_corner(v, nn, count, c, limit, face, i2, out);
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
    if (a == NULL || !sx_core_radius_ok(a->radius) || a->count < 3 ||
        a->count > SX_MAX_POLYGON_VERTICES || b == NULL) {
        sx_manifold_clear(out);
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
        sx_manifold_clear(out);
        return 0;
    }
    c = sx_circle_in_frame(b, xa, xb);
    if (!(sx_is_finite(margin) && margin > SX_R(0.0))) margin = SX_R(0.0);
    local = segment_point_manifold(a0, a1, ra, c, b->radius, margin, out);
    if (local < 0) return -1;
    if (local > 0 && !sx_circle_valid(b, xb, c)) local = 0;
    return sx_world_manifold(out, local, xa);
}

/* ---- the manifold entries of the pairs with a circle -------------------- */

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
    int count = a == NULL || !sx_core_radius_ok(a->radius)
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

int sx_collide_segment_circle_xf(const sx_segment *a, sx_xf_arg xa, const sx_circle *b,
                                 sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_segment_circle(a, sx_xf_in(xa), b, sx_xf_in(xb), margin, hyst, out);
}
int sx_collide_segment_circle_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,
                                     sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_segment_circle(&a->u.segment, sx_xf_in(xa), &b->u.circle, sx_xf_in(xb), margin,
                                  hyst, out);
}

int sx_collide_capsule_circle_xf(const sx_capsule *a, sx_xf_arg xa, const sx_circle *b,
                                 sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_capsule_circle(a, sx_xf_in(xa), b, sx_xf_in(xb), margin, hyst, out);
}
int sx_collide_capsule_circle_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,
                                     sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_capsule_circle(&a->u.capsule, sx_xf_in(xa), &b->u.circle, sx_xf_in(xb), margin,
                                  hyst, out);
}

int sx_collide_polygon_circle_xf(const sx_polygon *a, sx_xf_arg xa, const sx_circle *b,
                                 sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_polygon_circle(a, sx_xf_in(xa), b, sx_xf_in(xb), margin, hyst, out);
}
int sx_collide_polygon_circle_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,
                                     sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out) {
    return collide_polygon_circle(&a->u.polygon, sx_xf_in(xa), &b->u.circle, sx_xf_in(xb), margin,
                                  hyst, out);
}
