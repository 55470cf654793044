/* sepax — the narrowphase entry points: the thirty public pair functions
 * (overlap, MTV and manifold for each unordered pair of shape types) and the
 * generic sx_overlap / sx_mtv / sx_collide / sx_collide_ex, which dispatch
 * through one static table indexed [type of A][type of B].
 *
 * Each pair is computed in one canonical order only, in A's local frame: B is
 * moved into it with sx_xform_inv_mul, the core routines of narrow_core.c do
 * the work, and the answer is rotated (and translated) back. The reverse
 * order of a mixed pair wraps the canonical function and negates; for a
 * same-type pair the overlap and MTV functions pick the order themselves from
 * the inputs (transforms first, then the shape values, compared as bytes), so
 * sx_mtv(b, a) is bitwise the negation of sx_mtv(a, b) whichever order the
 * caller uses. Two identical inputs (same shape value, same transform) are
 * indistinguishable, so both orders are the same call and give the same
 * vector, not its negation. Manifolds of same-type pairs are computed in the
 * caller's order (A's face wins near-ties), so the solver, which always asks
 * in one order, gets feature ids that stay stable while the bodies move; at
 * margin 0 whether they touch at all is still the canonical order's answer,
 * so sx_collide has points exactly when sx_overlap is true. Circles and
 * axis-aligned box pairs take fast paths for overlap and MTV. */
#include <string.h>

#include "narrow.h"

/* ---- shared plumbing ---------------------------------------------------- */

/* (x - x) is 0 for finite x and NaN otherwise: one comparison checks a
 * whole transform. */
static inline bool xform_finite(sx_xform x) {
    return ((x.p.x - x.p.x) + (x.p.y - x.p.y)) + ((x.q.c - x.q.c) + (x.q.s - x.q.s)) == SX_R(0.0);
}

/* B's placement in A's frame; false if either transform is not finite.
 * Checking the result is enough: each of its components is a sum of
 * products that takes in every rotation component of both transforms (and
 * both coordinates of the position difference, times a rotation component
 * of A), so a NaN or infinity in xa or xb makes some component NaN or
 * infinite (inf x 0 is NaN, inf x nonzero is infinite). */
SX_NOINLINE static bool relative_xform(sx_xform xa, sx_xform xb, sx_xform *rel) {
    /* Out of line: inlined, GCC 12 copies xb through a 16-byte reload of
     * its two stored halves, a failed store forward on the hot path. */
    sx_xf r = sx_xf_relative(sx_xf_of(&xa), sx_xf_of(&xb));
    *rel = sx_xform_of_xf(r);
    return sx_r4_all_finite(r);
}

/* Rotates a local MTV to world space; a non-finite result (overflow of huge
 * inputs) is answered as no overlap. */
static bool finish_mtv(bool hit, sx_vec2 local, sx_xform xa, sx_vec2 *mtv) {
    sx_vec2 w = sx_xform_vector(xa, local);
    if (!hit || !sx_vec2_is_finite(w)) {
        if (mtv) *mtv = sx_v2_zero();
        return false;
    }
    if (mtv) *mtv = w;
    return true;
}

/* Moves a local manifold of `count` points to world space in place (see
 * sx_world_manifold). */
static int world_manifold(sx_manifold *m, int count, sx_xform xa) {
    return sx_world_manifold(m, count, sx_xf_of(&xa));
}

static sx_real clean_margin(sx_real margin) {
    return sx_is_finite(margin) && margin > SX_R(0.0) ? margin : SX_R(0.0);
}

static void clear_manifold(sx_manifold *out) {
    if (out) sx_manifold_clear(out);
}

/* Lexicographic order of the bit patterns of two runs of reals: arbitrary
 * but total and deterministic (NaN and -0 included), which is all the
 * canonical order needs. */
static int order_reals(const sx_real *a, const sx_real *b, int n) {
    int i;
    for (i = 0; i < n; ++i) {
#ifdef SX_DOUBLE
        uint64_t ba, bb;
#else
        uint32_t ba, bb;
#endif
        memcpy(&ba, &a[i], sizeof(ba));
        memcpy(&bb, &b[i], sizeof(bb));
        if (ba != bb) return ba < bb ? -1 : 1;
    }
    return 0;
}

static int order_xforms(sx_xform xa, sx_xform xb) {
    sx_real a[4], b[4];
    a[0] = xa.p.x;
    a[1] = xa.p.y;
    a[2] = xa.q.c;
    a[3] = xa.q.s;
    b[0] = xb.p.x;
    b[1] = xb.p.y;
    b[2] = xb.q.c;
    b[3] = xb.q.s;
    return order_reals(a, b, 4);
}

static int order_vecs(const sx_vec2 *a, const sx_vec2 *b, int n) {
    int i, c;
    for (i = 0; i < n; ++i) {
        sx_real ra[2], rb[2];
        ra[0] = a[i].x;
        ra[1] = a[i].y;
        rb[0] = b[i].x;
        rb[1] = b[i].y;
        c = order_reals(ra, rb, 2);
        if (c != 0) return c;
    }
    return 0;
}

/* ---- circle - circle ---------------------------------------------------- */

/* Circles skip the core machinery. The centre offset is the world delta of
 * the positions (exact for nearby bodies far from the origin) plus the
 * difference of the rotated local centres, grouped so that swapping the
 * circles negates it exactly (x - y == -(y - x) in IEEE arithmetic): the
 * squared-distance test, the MTV and the manifold are then antisymmetric
 * without any ordering, except when the centres coincide. */
static sx_vec2 circle_offset(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    return sx_add(sx_sub(xb.p, xa.p),
                  sx_sub(sx_rotate(xb.q, b->center), sx_rotate(xa.q, a->center)));
}

/* |d| <= r. A square of at least SX_SQUARE_SAFE^2 (narrow.h) keeps full
 * precision, and the plain test holds (the common case). Below it the
 * squares underflow, and two points 1e-265 apart would compare as touching:
 * there the test runs on d and r scaled by d's largest component, which
 * keeps it exact up to rounding and still antisymmetric (d and -d scale
 * alike). */
static inline bool within_reach(sx_vec2 d, sx_real r) {
    sx_real dsq = sx_length_sq(d), m, k;
    if (dsq >= SX_SQUARE_SAFE * SX_SQUARE_SAFE) return dsq <= r * r;
    m = sx_maxr(sx_magnitude(d.x), sx_magnitude(d.y));
    if (m == SX_R(0.0)) return r >= SX_R(0.0);
    k = r / m;
    return sx_length_sq(sx_v2(d.x / m, d.y / m)) <= k * k;
}

/* The checks of two circles whose offset and radii are already known to be
 * within reach (a NaN anywhere fails that test): the answer "apart" needs no
 * validation, since invalid input answers it too, so the checks run only on
 * the pairs that touch. a and b are not NULL. */
static bool circles_valid(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    return xform_finite(xa) && xform_finite(xb) &&
           (((a->center.x - a->center.x) + (a->center.y - a->center.y)) +
            ((b->center.x - b->center.x) + (b->center.y - b->center.y))) +
                   ((a->radius - a->radius) + (b->radius - b->radius)) ==
               SX_R(0.0) &&
           a->radius >= SX_R(0.0) && b->radius >= SX_R(0.0);
}

static int order_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    sx_real ra[3], rb[3];
    int c = order_xforms(xa, xb);
    if (c != 0) return c;
    ra[0] = a->center.x;
    ra[1] = a->center.y;
    ra[2] = a->radius;
    rb[0] = b->center.x;
    rb[1] = b->center.y;
    rb[2] = b->radius;
    return order_reals(ra, rb, 3);
}

/* Unit direction from A's centre to B's, and the centre distance. Coincident
 * centres (closer than rounding noise) have no direction: the local +x axis
 * of the circle that comes first in the canonical order, pointing away from
 * it (so the swapped call gets exactly the reversed direction). */
static sx_vec2 circles_direction(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                                 sx_vec2 d, sx_real *dist) {
    sx_real r = a->radius + b->radius, m = sx_maxr(sx_magnitude(d.x), sx_magnitude(d.y));
    if (m < SX_SQUARE_SAFE && m > SX_R(0.0)) {
        /* The square would underflow to a denormal of few bits (centres
         * 1.9e-22 apart in float gave a normal of length 0.994): length
         * and direction of d scaled by its largest component instead. */
        sx_vec2 u = sx_v2(d.x / m, d.y / m);
        sx_real len = sx_length(u);
        *dist = m * len;
        if (*dist > SX_R(64.0) * SX_REAL_EPSILON * sx_maxr(r, m)) {
            return sx_scale(u, SX_R(1.0) / len);
        }
    } else {
        *dist = sx_sqrt(sx_length_sq(d));
        if (*dist > SX_R(64.0) * SX_REAL_EPSILON * sx_maxr(r, m)) {
            return sx_scale(d, SX_R(1.0) / *dist);
        }
    }
    if (order_circles(a, xa, b, xb) > 0) return sx_v2(-xb.q.c, -xb.q.s);
    return sx_v2(xa.q.c, xa.q.s);
}

/* Whether the circles, their offset d and reach `limit` known, touch; if so
 * *n and *dist get the direction and the centre distance. The common case is
 * written out: a square in full precision (within_reach's first test) and a
 * direction d over its length unless the centres coincide within rounding
 * (circles_direction's test, which for a square this large reads
 * dist > 64 epsilon r). collide_circles writes the same steps out itself:
 * calling this helper from it makes GCC 12 spill the by-value transforms and
 * reload them across a store-forwarding stall. */
static inline bool circles_touch(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                                 sx_vec2 d, sx_real limit, sx_vec2 *n, sx_real *dist) {
    sx_real dsq = sx_length_sq(d), r = a->radius + b->radius;
    if (dsq >= SX_SQUARE_SAFE * SX_SQUARE_SAFE) {
        if (!(dsq <= limit * limit && circles_valid(a, xa, b, xb))) return false;
        *dist = sx_sqrt(dsq);
        if (*dist > SX_R(64.0) * SX_REAL_EPSILON * r) {
            *n = sx_scale(d, SX_R(1.0) / *dist);
        } else {
            *n = circles_direction(a, xa, b, xb, d, dist);
        }
        return true;
    }
    if (!(within_reach(d, limit) && circles_valid(a, xa, b, xb))) return false;
    *n = circles_direction(a, xa, b, xb, d, dist);
    return true;
}

bool sx_overlap_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    if (a == NULL || b == NULL) return false;
    return within_reach(circle_offset(a, xa, b, xb), a->radius + b->radius) &&
           circles_valid(a, xa, b, xb);
}

bool sx_mtv_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                    sx_vec2 *mtv) {
    sx_vec2 d, n, v = sx_v2_zero();
    sx_real r, dist;
    bool hit = false;
    if (a != NULL && b != NULL) {
        d = circle_offset(a, xa, b, xb);
        r = a->radius + b->radius;
        if (circles_touch(a, xa, b, xb, d, r, &n, &dist)) {
            v = sx_scale(n, sx_minr(dist - r, SX_R(0.0)));
            hit = sx_vec2_is_finite(v);
            if (!hit) v = sx_v2_zero();
        }
    }
    if (mtv) *mtv = v;
    return hit;
}

/* The body of sx_collide_circles, static so that the dispatch table's entry
 * can inline it (an exported function of a shared library cannot be). */
static inline int collide_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                                  sx_real margin, sx_manifold *m) {
    sx_vec2 d, n = sx_v2_zero(), ca;
    sx_real r, limit, dist = SX_R(0.0), dsq;
    bool touch;
    margin = clean_margin(margin);
    if (a != NULL && b != NULL) {
        d = circle_offset(a, xa, b, xb);
        r = a->radius + b->radius;
        limit = r + margin;
        dsq = sx_length_sq(d);
        if (dsq >= SX_SQUARE_SAFE * SX_SQUARE_SAFE) {
            /* The common case, written out: the square keeps full precision
             * (within_reach's first test), and the direction is d over its
             * length unless the centres coincide within rounding
             * (circles_direction's test, which for a square this large reads
             * dist > 64 epsilon r). */
            touch = dsq <= limit * limit && circles_valid(a, xa, b, xb);
            if (touch) {
                dist = sx_sqrt(dsq);
                n = dist > SX_R(64.0) * SX_REAL_EPSILON * r
                        ? sx_scale(d, SX_R(1.0) / dist)
                        : circles_direction(a, xa, b, xb, d, &dist);
            }
        } else {
            touch = within_reach(d, limit) && circles_valid(a, xa, b, xb);
            if (touch) n = circles_direction(a, xa, b, xb, d, &dist);
        }
        if (touch) {
            ca = sx_xform_point(xa, a->center);
            /* Midway between A's surface (ra along n) and B's (dist - rb). */
            m->points[0].point = sx_mul_add(ca, SX_R(0.5) * (a->radius + dist - b->radius), n);
            m->points[0].depth = sx_maxr(r - dist, -margin);
            m->points[0].id = SX_FEATURE_ID(0, 0, 0);
            m->normal = n;
            if (sx_vec2_is_finite(m->points[0].point) && sx_is_finite(m->points[0].depth)) {
                m->count = 1;
                m->points[1].point = sx_v2_zero();
                m->points[1].depth = SX_R(0.0);
                m->points[1].id = 0;
                return 1;
            }
        }
    }
    sx_manifold_clear(m);
    return 0;
}

/* The manifold entry of two circles. The common case (a square in full
 * precision, centres apart by more than rounding noise) is written out on
 * the transforms' lanes, each lane computed as collide_circles
 * computes it; collide_circles answers the rest. */
int sx_collide_circles_xf(const sx_circle *a, sx_xf_arg pa, const sx_circle *b, sx_xf_arg pb,
                          sx_real margin, sx_real hyst, sx_manifold *out) {
    sx_xf xa = sx_xf_in(pa), xb = sx_xf_in(pb);
    SX_UNUSED(hyst); /* circles have no reference face */
    if (a != NULL && b != NULL) {
        sx_r4 ca = sx_r4_load2(&a->center.x), cb = sx_r4_load2(&b->center.x);
        sx_r4 wa = sx_xf_rotate(xa, ca), wb = sx_xf_rotate(xb, cb);
        sx_r4 d = sx_r4_add(sx_r4_sub(xb, xa), sx_r4_sub(wb, wa));
        sx_real dx = sx_r4_first(d), dy = sx_r4_first(sx_r4_swap_pairs(d));
        sx_real r = a->radius + b->radius, dsq = dx * dx + dy * dy, mg, limit, dist;
        mg = sx_is_finite(margin) && margin > SX_R(0.0) ? margin : SX_R(0.0);
        limit = r + mg;
        if (dsq >= SX_SQUARE_SAFE * SX_SQUARE_SAFE) {
            sx_r4 n, pt;
            sx_real depth;
            if (!(dsq <= limit * limit) ||
                !(!sx_r4_any_nan(sx_r4_add(sx_r4_sub(xa, xa), sx_r4_sub(xb, xb))) &&
                  sx_r4_all_finite(sx_r4_low_halves(ca, cb)) && sx_is_finite(a->radius) &&
                  sx_is_finite(b->radius) && a->radius >= SX_R(0.0) && b->radius >= SX_R(0.0))) {
                sx_manifold_clear(out);
                return 0;
            }
            dist = sx_sqrt(dsq);
            if (dist > SX_R(64.0) * SX_REAL_EPSILON * r) {
                n = sx_r4_mul(sx_r4_set1(SX_R(1.0) / dist), d);
                pt =
                    sx_r4_add(sx_r4_add(wa, xa),
                              sx_r4_mul(sx_r4_set1(SX_R(0.5) * (a->radius + dist - b->radius)), n));
                depth = sx_maxr(r - dist, -mg);
                n = sx_r4_low_halves(n, pt);
                if (sx_r4_all_finite(n) && sx_is_finite(depth)) {
                    sx_r4_store_low(&out->normal.x, n);
                    sx_r4_store_high(&out->points[0].point.x, n);
                    out->points[0].depth = depth;
                    out->points[0].id = SX_FEATURE_ID(0, 0, 0);
                    out->points[1].point = sx_v2_zero();
                    out->points[1].depth = SX_R(0.0);
                    out->points[1].id = 0;
                    out->count = 1;
                    return 1;
                }
                sx_manifold_clear(out);
                return 0;
            }
        }
    }
    return collide_circles(a, sx_xform_of_xf(xa), b, sx_xform_of_xf(xb), margin, out);
}

int sx_collide_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                       sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return collide_circles(a, xa, b, xb, margin, out ? out : &scratch);
}

/* ---- the other pairs: cores in A's frame -------------------------------- */

typedef bool sx_core_builder(const void *shape, const sx_xform *x, sx_core *out);

static bool build_segment(const void *s, const sx_xform *x, sx_core *out) {
    return sx_core_from_segment((const sx_segment *)s, x, out);
}
static bool build_capsule(const void *s, const sx_xform *x, sx_core *out) {
    return sx_core_from_capsule((const sx_capsule *)s, x, out);
}
static bool build_polygon(const void *s, const sx_xform *x, sx_core *out) {
    return sx_core_from_polygon((const sx_polygon *)s, x, out);
}

/* The shape type a builder builds cores of. */
static int builder_kind(sx_core_builder *f) {
    if (f == build_polygon) return SX_SHAPE_POLYGON;
    return f == build_capsule ? SX_SHAPE_CAPSULE : SX_SHAPE_SEGMENT;
}

/* The overlap and MTV of two cores: narrow_core.c's fused routines. The
 * transforms come by address, from the function that holds them by value:
 * passed on by value through the inlined pair functions, GCC 12 copies the
 * transform of B as one 16-byte load of its two stored 8-byte halves, a
 * failed store forward on every call. circle_valid takes B's transform by
 * address for the same reason. */
static bool pair_overlap(sx_core_builder *fa, const void *a, const sx_xform *xa,
                         sx_core_builder *fb, const void *b, const sx_xform *xb) {
    return sx_cores_overlap(builder_kind(fa), a, sx_xf_of(xa), builder_kind(fb), b, sx_xf_of(xb));
}

static bool pair_mtv(sx_core_builder *fa, const void *a, const sx_xform *xa, sx_core_builder *fb,
                     const void *b, const sx_xform *xb, sx_vec2 *mtv) {
    sx_vec2 local;
    bool hit =
        sx_cores_mtv(builder_kind(fa), a, sx_xf_of(xa), builder_kind(fb), b, sx_xf_of(xb), &local);
    return finish_mtv(hit, local, *xa, mtv);
}

static int pair_collide_checked(sx_core_builder *fa, const void *a, sx_xform xa,
                                sx_core_builder *fb, const void *b, sx_xform xb, sx_real margin,
                                sx_real hyst, sx_manifold *out, bool *clear_cut) {
    sx_manifold scratch;
    return sx_cores_collide(builder_kind(fa), a, sx_xf_of(&xa), builder_kind(fb), b, sx_xf_of(&xb),
                            margin, hyst, out ? out : &scratch, clear_cut);
}

static int pair_collide(sx_core_builder *fa, const void *a, sx_xform xa, sx_core_builder *fb,
                        const void *b, sx_xform xb, sx_real margin, sx_real hyst,
                        sx_manifold *out) {
    return pair_collide_checked(fa, a, xa, fb, b, xb, margin, hyst, out, NULL);
}

/* A core against a circle B (segment, capsule or polygon first): B's centre
 * is placed in A's frame (sx_circle_in_frame), and the point routines of
 * narrow_core.c answer without a core for B. */
static inline sx_vec2 circle_in_frame(const sx_circle *b, const sx_xform *xa, const sx_xform *xb) {
    return sx_circle_in_frame(b, sx_xf_of(xa), sx_xf_of(xb));
}

static inline bool circle_valid(const sx_circle *b, const sx_xform *xb, sx_vec2 c) {
    return sx_circle_valid(b, sx_xf_of(xb), c);
}

static bool point_overlap(sx_core_builder *fa, const void *a, sx_xform xa, const sx_circle *b,
                          sx_xform xb) {
    sx_core ca;
    sx_vec2 c;
    if (b == NULL || !fa(a, NULL, &ca)) return false;
    c = circle_in_frame(b, &xa, &xb);
    return sx_core_point_overlap(&ca, c, b->radius) && circle_valid(b, &xb, c) &&
           sx_core_values_finite(&ca);
}

static bool point_mtv(sx_core_builder *fa, const void *a, sx_xform xa, const sx_circle *b,
                      sx_xform xb, sx_vec2 *mtv) {
    sx_core ca;
    sx_vec2 c, local = sx_v2_zero();
    bool hit = false;
    if (b != NULL && fa(a, NULL, &ca)) {
        c = circle_in_frame(b, &xa, &xb);
        hit = sx_core_point_mtv(&ca, c, b->radius, &local) && circle_valid(b, &xb, c) &&
              sx_core_values_finite(&ca);
    }
    return finish_mtv(hit, local, xa, mtv);
}

static int point_collide(sx_core_builder *fa, const void *a, sx_xform xa, const sx_circle *b,
                         sx_xform xb, sx_real margin, sx_manifold *out) {
    sx_core ca;
    sx_vec2 c;
    sx_manifold scratch;
    sx_manifold *m = out ? out : &scratch;
    int local;
    if (b == NULL || !fa(a, NULL, &ca)) {
        clear_manifold(out);
        return 0;
    }
    c = circle_in_frame(b, &xa, &xb);
    local = sx_core_point_manifold(&ca, c, b->radius, clean_margin(margin), m);
    if (local > 0 && !(circle_valid(b, &xb, c) && sx_core_values_finite(&ca))) local = 0;
    return world_manifold(m, local, xa);
}

/* The point routines for a segment or capsule A with ends a0-a1 and radius
 * ra (valid, as its builder checks): its core is never built (see
 * sx_core_segment_point_overlap in narrow.h), and the cases those leave to
 * the general route take point_overlap, point_mtv or point_collide. They
 * stay out of line (SX_NOINLINE): inlined into the dispatch entries, GCC 12
 * spills the by-value transform as two 8-byte halves and reads it back as
 * one 16-byte vector, a failed store forward on every call. */
SX_NOINLINE static bool segment_point_overlap(sx_vec2 a0, sx_vec2 a1, sx_real ra,
                                              sx_core_builder *fa, const void *a, sx_xform xa,
                                              const sx_circle *b, sx_xform xb) {
    sx_vec2 c;
    int hit;
    if (b == NULL) return false;
    c = circle_in_frame(b, &xa, &xb);
    hit = sx_core_segment_point_overlap(a0, a1, ra, c, b->radius);
    if (hit < 0) return point_overlap(fa, a, xa, b, xb);
    return hit > 0 && circle_valid(b, &xb, c);
}

SX_NOINLINE static bool segment_point_mtv(sx_vec2 a0, sx_vec2 a1, sx_real ra, sx_core_builder *fa,
                                          const void *a, sx_xform xa, const sx_circle *b,
                                          sx_xform xb, sx_vec2 *mtv) {
    sx_vec2 c, local = sx_v2_zero();
    int hit = 0;
    if (b != NULL) {
        c = circle_in_frame(b, &xa, &xb);
        hit = sx_core_segment_point_mtv(a0, a1, ra, c, b->radius, &local);
        if (hit < 0) return point_mtv(fa, a, xa, b, xb, mtv);
        hit = hit > 0 && circle_valid(b, &xb, c);
    }
    return finish_mtv(hit, local, xa, mtv);
}

/* The general route after the fused one handed the pair back (narrow.h);
 * the transforms arrive as registers and are rebuilt here, so that the hot
 * caller holds them only in registers (see sx_xf). */
SX_NOINLINE int sx_point_collide_general(int kind, const void *a, sx_xf xa, const sx_circle *b,
                                         sx_xf xb, sx_real margin, sx_manifold *out) {
    sx_core_builder *fa = kind == SX_SHAPE_POLYGON   ? build_polygon
                          : kind == SX_SHAPE_CAPSULE ? build_capsule
                                                     : build_segment;
    return point_collide(fa, a, sx_xform_of_xf(xa), b, sx_xform_of_xf(xb), margin, out);
}

/* A capsule's radius as its builder accepts it. */
static bool capsule_radius_ok(const sx_capsule *a) {
    return a != NULL && sx_is_finite(a->radius) && a->radius >= SX_R(0.0);
}

/* Same-type pairs: overlap and MTV in the canonical order. `order` > 0 means
 * (b, a) is the canonical order. */
static bool pair_overlap_sym(sx_core_builder *f, const void *a, sx_xform xa, const void *b,
                             sx_xform xb, int order) {
    if (order > 0) return pair_overlap(f, b, &xb, f, a, &xa);
    return pair_overlap(f, a, &xa, f, b, &xb);
}

static bool pair_mtv_sym(sx_core_builder *f, const void *a, sx_xform xa, const void *b, sx_xform xb,
                         int order, sx_vec2 *mtv) {
    sx_vec2 v;
    bool hit;
    if (order > 0) {
        hit = pair_mtv(f, b, &xb, f, a, &xa, &v);
        v = hit ? sx_neg(v) : sx_v2_zero();
    } else {
        hit = pair_mtv(f, a, &xa, f, b, &xb, &v);
    }
    if (mtv) *mtv = v;
    return hit;
}

/* The margin-0 manifold of a pair that sx_overlap counts as touching but
 * whose exact gap is a few ulps above zero: asked again with the rescue
 * margin, its depths clamped to 0 (the pair touches). In A's frame B's faces
 * are placed from B's coordinates, and far from B's origin (a tiny A on the
 * corner of a B that spans 1e5 m) their rounding can exceed the rescue
 * margin; the canonical order, which decided the overlap, is then the other
 * one, so its manifold, mirrored, is the answer. */
static int collide_rescue(sx_core_builder *f, const void *a, sx_xform xa, const void *b,
                          sx_xform xb, sx_real hyst, sx_manifold *m) {
    int count = pair_collide(f, a, xa, f, b, xb, SX_TOUCH_RESCUE_MARGIN, hyst, m), i;
    if (count == 0) {
        count = pair_collide(f, b, xb, f, a, xa, SX_TOUCH_RESCUE_MARGIN, hyst, m);
        if (count > 0) sx_mirror_manifold(m);
    }
    for (i = 0; i < count; ++i)
        m->points[i].depth = sx_maxr(m->points[i].depth, SX_R(0.0));
    return count;
}

/* The canonical-order overlap test of a same-type pair. */
typedef bool sx_sym_overlap(const void *a, sx_xform xa, const void *b, sx_xform xb);

/* Same-type manifolds follow the caller's order (stable feature ids), but at
 * margin 0 whether the pair touches at all is the canonical order's answer
 * (`overlap`), so sx_collide reports points exactly when sx_overlap is
 * true. A speculative call (margin > 0) needs no such agreement, but it must
 * never report fewer points than margin 0 does: a margin below the rescue
 * margin would miss a pair that margin 0 rescues as touching (its exact gap
 * lies between the margin and the rounding tolerance), so such a pair is
 * rescued the same way. Larger margins include the rescue margin's points
 * already when the gap is clear of rounding (clear-cut). When it is not,
 * margin 0 may have used the other order's manifold (collide_rescue), which
 * can have more points than this order's: a one-point answer is then
 * compared with it too (a speck touching a long triangle's edge 1e5 m from
 * the triangle's origin: this order saw a vertex 1 cm off, rounding, the
 * other order the edge with two points). */
static int collide_gated(sx_core_builder *f, const void *a, sx_xform xa, const void *b, sx_xform xb,
                         sx_real margin, sx_real hyst, sx_sym_overlap *overlap, sx_manifold *out) {
    sx_manifold m;
    int count;
    if (sx_is_finite(margin) && margin > SX_R(0.0)) {
        int rescued;
        bool clear_cut = false;
        count = pair_collide_checked(f, a, xa, f, b, xb, margin, hyst, out, &clear_cut);
        if (count == 2 || (margin >= SX_TOUCH_RESCUE_MARGIN && clear_cut) ||
            !overlap(a, xa, b, xb)) {
            return count;
        }
        rescued = collide_rescue(f, a, xa, b, xb, hyst, &m);
        if (rescued <= count) return count;
        if (out) *out = m;
        return rescued;
    }
    if (!overlap(a, xa, b, xb)) {
        clear_manifold(out);
        return 0;
    }
    count = pair_collide(f, a, xa, f, b, xb, SX_R(0.0), hyst, &m);
    if (count == 0) count = collide_rescue(f, a, xa, b, xb, hyst, &m);
    if (out) *out = m;
    return count;
}

/* ---- segment - circle --------------------------------------------------- */

bool sx_overlap_segment_circle(const sx_segment *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    if (a == NULL) return false;
    return segment_point_overlap(a->a, a->b, SX_R(0.0), build_segment, a, xa, b, xb);
}
bool sx_mtv_segment_circle(const sx_segment *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                           sx_vec2 *mtv) {
    if (a == NULL) return point_mtv(build_segment, a, xa, b, xb, mtv);
    return segment_point_mtv(a->a, a->b, SX_R(0.0), build_segment, a, xa, b, xb, mtv);
}
int sx_collide_segment_circle(const sx_segment *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                              sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_segment_circle_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                        SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

/* ---- segment - segment -------------------------------------------------- */

/* The order of two segments' or capsules' ends and radii, n = 4 (the ends
 * alone, for segments) or 5 (the radius too). */
static int order_ends(sx_vec2 a0, sx_vec2 a1, sx_real ra, sx_vec2 b0, sx_vec2 b1, sx_real rb,
                      int n) {
    sx_real x[5], y[5];
    x[0] = a0.x;
    x[1] = a0.y;
    x[2] = a1.x;
    x[3] = a1.y;
    x[4] = ra;
    y[0] = b0.x;
    y[1] = b0.y;
    y[2] = b1.x;
    y[3] = b1.y;
    y[4] = rb;
    return order_reals(x, y, n);
}

static int order_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb) {
    int c = order_xforms(xa, xb);
    if (c != 0 || a == NULL || b == NULL) return c;
    return order_ends(a->a, a->b, SX_R(0.0), b->a, b->b, SX_R(0.0), 4);
}

bool sx_overlap_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb) {
    return pair_overlap_sym(build_segment, a, xa, b, xb, order_segments(a, xa, b, xb));
}
static bool overlap_segments_any(const void *a, sx_xform xa, const void *b, sx_xform xb) {
    return sx_overlap_segments((const sx_segment *)a, xa, (const sx_segment *)b, xb);
}
bool sx_mtv_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                     sx_vec2 *mtv) {
    return pair_mtv_sym(build_segment, a, xa, b, xb, order_segments(a, xa, b, xb), mtv);
}
/* sx_collide_segments past the fused manifold: a pair that is not clear-cut,
 * or a speculative call (margin > 0). */
SX_NOINLINE int sx_collide_segments_gated(const sx_segment *a, sx_xf ta, const sx_segment *b,
                                          sx_xf tb, sx_real margin, sx_real hyst, int count,
                                          bool touch_test, sx_manifold *out) {
    sx_xform xa = sx_xform_of_xf(ta), xb = sx_xform_of_xf(tb);
    if (touch_test && order_segments(a, xa, b, xb) <= 0) return count;
    return collide_gated(build_segment, a, xa, b, xb, margin, hyst, overlap_segments_any, out);
}

int sx_collide_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                        sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_segments_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                  SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

/* ---- capsule - circle / segment / capsule ------------------------------- */

bool sx_overlap_capsule_circle(const sx_capsule *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    if (!capsule_radius_ok(a)) return false;
    return segment_point_overlap(a->a, a->b, a->radius, build_capsule, a, xa, b, xb);
}
bool sx_mtv_capsule_circle(const sx_capsule *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                           sx_vec2 *mtv) {
    if (!capsule_radius_ok(a)) return point_mtv(build_capsule, a, xa, b, xb, mtv);
    return segment_point_mtv(a->a, a->b, a->radius, build_capsule, a, xa, b, xb, mtv);
}
int sx_collide_capsule_circle(const sx_capsule *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                              sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_capsule_circle_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                        SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

bool sx_overlap_capsule_segment(const sx_capsule *a, sx_xform xa, const sx_segment *b,
                                sx_xform xb) {
    return pair_overlap(build_capsule, a, &xa, build_segment, b, &xb);
}
bool sx_mtv_capsule_segment(const sx_capsule *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                            sx_vec2 *mtv) {
    return pair_mtv(build_capsule, a, &xa, build_segment, b, &xb, mtv);
}
int sx_collide_capsule_segment(const sx_capsule *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                               sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_capsule_segment_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                         SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

static int order_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb) {
    int c = order_xforms(xa, xb);
    if (c != 0 || a == NULL || b == NULL) return c;
    return order_ends(a->a, a->b, a->radius, b->a, b->b, b->radius, 5);
}

bool sx_overlap_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb) {
    return pair_overlap_sym(build_capsule, a, xa, b, xb, order_capsules(a, xa, b, xb));
}
static bool overlap_capsules_any(const void *a, sx_xform xa, const void *b, sx_xform xb) {
    return sx_overlap_capsules((const sx_capsule *)a, xa, (const sx_capsule *)b, xb);
}
bool sx_mtv_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb,
                     sx_vec2 *mtv) {
    return pair_mtv_sym(build_capsule, a, xa, b, xb, order_capsules(a, xa, b, xb), mtv);
}
/* sx_collide_capsules past the fused manifold: a pair that is not clear-cut,
 * or a speculative call (margin > 0). */
SX_NOINLINE int sx_collide_capsules_gated(const sx_capsule *a, sx_xf ta, const sx_capsule *b,
                                          sx_xf tb, sx_real margin, sx_real hyst, int count,
                                          bool touch_test, sx_manifold *out) {
    sx_xform xa = sx_xform_of_xf(ta), xb = sx_xform_of_xf(tb);
    if (touch_test && order_capsules(a, xa, b, xb) <= 0) return count;
    return collide_gated(build_capsule, a, xa, b, xb, margin, hyst, overlap_capsules_any, out);
}

int sx_collide_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb,
                        sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_capsules_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                  SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

/* ---- polygon - circle / segment / capsule ------------------------------- */

/* The point routines for a polygon A read in place, without a core (see
 * sx_core_polygon_point_overlap in narrow.h); what sx_core_from_polygon
 * refuses, and the cases those hand back, take the general route. Out of
 * line for the reason given at segment_point_overlap. */
static bool polygon_shape_ok(const sx_polygon *a) {
    return a != NULL && sx_is_finite(a->radius) && a->radius >= SX_R(0.0) && a->count >= 3 &&
           a->count <= SX_MAX_POLYGON_VERTICES;
}

SX_NOINLINE static bool polygon_point_overlap(const sx_polygon *a, sx_xform xa, const sx_circle *b,
                                              sx_xform xb) {
    sx_vec2 c;
    int hit;
    if (!polygon_shape_ok(a) || b == NULL) return false;
    c = circle_in_frame(b, &xa, &xb);
    hit = sx_core_polygon_point_overlap(a, c, b->radius);
    if (hit < 0) return point_overlap(build_polygon, a, xa, b, xb);
    return hit > 0 && circle_valid(b, &xb, c) &&
           sx_polygon_values_finite(a->vertices, a->normals, a->count);
}

SX_NOINLINE static bool polygon_point_mtv(const sx_polygon *a, sx_xform xa, const sx_circle *b,
                                          sx_xform xb, sx_vec2 *mtv) {
    sx_vec2 c, local = sx_v2_zero();
    int hit = 0;
    if (polygon_shape_ok(a) && b != NULL) {
        c = circle_in_frame(b, &xa, &xb);
        hit = sx_core_polygon_point_mtv(a, c, b->radius, &local);
        if (hit < 0) return point_mtv(build_polygon, a, xa, b, xb, mtv);
        hit = hit > 0 && circle_valid(b, &xb, c) &&
              sx_polygon_values_finite(a->vertices, a->normals, a->count);
    }
    return finish_mtv(hit, local, xa, mtv);
}

bool sx_overlap_polygon_circle(const sx_polygon *a, sx_xform xa, const sx_circle *b, sx_xform xb) {
    return polygon_point_overlap(a, xa, b, xb);
}
bool sx_mtv_polygon_circle(const sx_polygon *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                           sx_vec2 *mtv) {
    return polygon_point_mtv(a, xa, b, xb, mtv);
}
int sx_collide_polygon_circle(const sx_polygon *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                              sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_polygon_circle_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                        SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

bool sx_overlap_polygon_segment(const sx_polygon *a, sx_xform xa, const sx_segment *b,
                                sx_xform xb) {
    return pair_overlap(build_polygon, a, &xa, build_segment, b, &xb);
}
bool sx_mtv_polygon_segment(const sx_polygon *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                            sx_vec2 *mtv) {
    return pair_mtv(build_polygon, a, &xa, build_segment, b, &xb, mtv);
}
int sx_collide_polygon_segment(const sx_polygon *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                               sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_polygon_segment_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                         SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

bool sx_overlap_polygon_capsule(const sx_polygon *a, sx_xform xa, const sx_capsule *b,
                                sx_xform xb) {
    return pair_overlap(build_polygon, a, &xa, build_capsule, b, &xb);
}
bool sx_mtv_polygon_capsule(const sx_polygon *a, sx_xform xa, const sx_capsule *b, sx_xform xb,
                            sx_vec2 *mtv) {
    return pair_mtv(build_polygon, a, &xa, build_capsule, b, &xb, mtv);
}
int sx_collide_polygon_capsule(const sx_polygon *a, sx_xform xa, const sx_capsule *b, sx_xform xb,
                               sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_polygon_capsule_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                         SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

/* ---- polygon - polygon -------------------------------------------------- */

static int order_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb) {
    sx_real ra[2], rb[2];
    int c = order_xforms(xa, xb);
    if (c != 0 || a == NULL || b == NULL) return c;
    if (a->count != b->count) return a->count < b->count ? -1 : 1;
    if (a->count < 0 || a->count > SX_MAX_POLYGON_VERTICES) return 0;
    ra[0] = a->radius;
    rb[0] = b->radius;
    c = order_reals(ra, rb, 1);
    if (c != 0) return c;
    c = order_vecs(a->vertices, b->vertices, a->count);
    if (c != 0) return c;
    c = order_vecs(a->normals, b->normals, a->count);
    if (c != 0) return c;
    ra[0] = a->centroid.x;
    ra[1] = a->centroid.y;
    rb[0] = b->centroid.x;
    rb[1] = b->centroid.y;
    return order_reals(ra, rb, 2);
}

/* A sharp 4-gon whose normals are exactly the local axes. */
static bool is_axis_box(const sx_polygon *p) {
    int i;
    if (p->count != 4 || p->radius != SX_R(0.0)) return false;
    for (i = 0; i < 4; ++i) {
        sx_vec2 n = p->normals[i];
        bool along_x = n.y == SX_R(0.0) && (n.x == SX_R(1.0) || n.x == SX_R(-1.0));
        bool along_y = n.x == SX_R(0.0) && (n.y == SX_R(1.0) || n.y == SX_R(-1.0));
        if (!along_x && !along_y) return false;
    }
    return true;
}

/* True when the box fast path below applies: two sharp axis boxes whose
 * relative rotation is a multiple of 90 degrees (to within one epsilon of a
 * rotation component, i.e. below rounding). */
static bool box_pair_aligned(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb) {
    sx_rot q;
    if (a == NULL || b == NULL || a->count != 4 || b->count != 4) return false;
    q = sx_rot_inv_mul(xa.q, xb.q);
    if (!(sx_magnitude(q.s) <= SX_REAL_EPSILON || sx_magnitude(q.c) <= SX_REAL_EPSILON)) {
        return false;
    }
    return is_axis_box(a) && is_axis_box(b);
}

/* Fast path for two axis-aligned boxes whose relative rotation is a multiple
 * of 90 degrees (to within one epsilon of a rotation component, i.e. below
 * rounding): SAT over A's four faces against B's bounding interval, which is
 * the same axis set the general SAT would find (B's faces are parallel to
 * A's). Returns false when the pair does not qualify; *hit and *local then
 * are untouched. */
static bool box_fast_path(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb,
                          bool *hit, sx_vec2 *local) {
    sx_xform rel;
    sx_vec2 lo, hi;
    sx_real best = -SX_REAL_MAX;
    int i, face = 0;
    if (!box_pair_aligned(a, xa, b, xb) || !relative_xform(xa, xb, &rel)) return false;
    lo = sx_v2(SX_REAL_MAX, SX_REAL_MAX);
    hi = sx_v2(-SX_REAL_MAX, -SX_REAL_MAX);
    for (i = 0; i < 4; ++i) {
        sx_vec2 v = sx_xform_point(rel, b->vertices[i]);
        if (!sx_vec2_is_finite(v) || !sx_vec2_is_finite(a->vertices[i])) return false;
        lo = sx_vmin(lo, v);
        hi = sx_vmax(hi, v);
    }
    for (i = 0; i < 4; ++i) {
        sx_vec2 n = a->normals[i], v = a->vertices[i];
        sx_real s;
        if (n.x > SX_R(0.0)) {
            s = lo.x - v.x;
        } else if (n.x < SX_R(0.0)) {
            s = v.x - hi.x;
        } else if (n.y > SX_R(0.0)) {
            s = lo.y - v.y;
        } else {
            s = v.y - hi.y;
        }
        if (s > SX_R(0.0)) {
            *hit = false;
            *local = sx_v2_zero();
            return true;
        }
        if (s > best) {
            best = s;
            face = i;
        }
    }
    *hit = true;
    *local = sx_scale(a->normals[face], best);
    return true;
}

static bool overlap_polygons_ordered(const sx_polygon *a, sx_xform xa, const sx_polygon *b,
                                     sx_xform xb) {
    bool hit;
    sx_vec2 local;
    if (box_fast_path(a, xa, b, xb, &hit, &local)) return hit;
    return pair_overlap(build_polygon, a, &xa, build_polygon, b, &xb);
}

static bool mtv_polygons_ordered(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb,
                                 sx_vec2 *mtv) {
    bool hit;
    sx_vec2 local;
    if (box_fast_path(a, xa, b, xb, &hit, &local)) return finish_mtv(hit, local, xa, mtv);
    return pair_mtv(build_polygon, a, &xa, build_polygon, b, &xb, mtv);
}

bool sx_overlap_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb) {
    if (order_polygons(a, xa, b, xb) > 0) return overlap_polygons_ordered(b, xb, a, xa);
    return overlap_polygons_ordered(a, xa, b, xb);
}
static bool overlap_polygons_any(const void *a, sx_xform xa, const void *b, sx_xform xb) {
    return sx_overlap_polygons((const sx_polygon *)a, xa, (const sx_polygon *)b, xb);
}
bool sx_mtv_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb,
                     sx_vec2 *mtv) {
    sx_vec2 v;
    bool hit;
    if (order_polygons(a, xa, b, xb) > 0) {
        hit = mtv_polygons_ordered(b, xb, a, xa, &v);
        v = hit ? sx_neg(v) : sx_v2_zero();
    } else {
        hit = mtv_polygons_ordered(a, xa, b, xb, &v);
    }
    if (mtv) *mtv = v;
    return hit;
}
/* sx_collide_polygons past the fused manifold: a pair that is not
 * clear-cut, or a speculative call (margin > 0). */
SX_NOINLINE int sx_collide_polygons_gated(const sx_polygon *a, sx_xf ta, const sx_polygon *b,
                                          sx_xf tb, sx_real margin, sx_real hyst, int count,
                                          bool touch_test, sx_manifold *out) {
    sx_xform xa = sx_xform_of_xf(ta), xb = sx_xform_of_xf(tb);
    if (touch_test && order_polygons(a, xa, b, xb) <= 0 && !box_pair_aligned(a, xa, b, xb))
        return count;
    return collide_gated(build_polygon, a, xa, b, xb, margin, hyst, overlap_polygons_any, out);
}

int sx_collide_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb,
                        sx_real margin, sx_manifold *out) {
    sx_manifold scratch;
    return sx_collide_polygons_xf(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin,
                                  SX_REFERENCE_HYSTERESIS, out ? out : &scratch);
}

/* ---- the dispatch table ------------------------------------------------- */

/* The overlap and MTV entries of each pair: the typed pair function on the
 * shapes' union members. */
static bool overlap_circles_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    return sx_overlap_circles(&a->u.circle, xa, &b->u.circle, xb);
}
static bool mtv_circles_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                               sx_vec2 *mtv) {
    return sx_mtv_circles(&a->u.circle, xa, &b->u.circle, xb, mtv);
}
int sx_collide_circles_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b, sx_xf_arg xb,
                              sx_real margin, sx_real hyst, sx_manifold *out) {
    return sx_collide_circles_xf(&a->u.circle, xa, &b->u.circle, xb, margin, hyst, out);
}

static bool overlap_segment_circle_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                          sx_xform xb) {
    return sx_overlap_segment_circle(&a->u.segment, xa, &b->u.circle, xb);
}
static bool mtv_segment_circle_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                      sx_xform xb, sx_vec2 *mtv) {
    return sx_mtv_segment_circle(&a->u.segment, xa, &b->u.circle, xb, mtv);
}

static bool overlap_segments_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                    sx_xform xb) {
    return sx_overlap_segments(&a->u.segment, xa, &b->u.segment, xb);
}
static bool mtv_segments_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                sx_vec2 *mtv) {
    return sx_mtv_segments(&a->u.segment, xa, &b->u.segment, xb, mtv);
}

static bool overlap_capsule_circle_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                          sx_xform xb) {
    return sx_overlap_capsule_circle(&a->u.capsule, xa, &b->u.circle, xb);
}
static bool mtv_capsule_circle_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                      sx_xform xb, sx_vec2 *mtv) {
    return sx_mtv_capsule_circle(&a->u.capsule, xa, &b->u.circle, xb, mtv);
}

static bool overlap_capsule_segment_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                           sx_xform xb) {
    return sx_overlap_capsule_segment(&a->u.capsule, xa, &b->u.segment, xb);
}
static bool mtv_capsule_segment_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                       sx_xform xb, sx_vec2 *mtv) {
    return sx_mtv_capsule_segment(&a->u.capsule, xa, &b->u.segment, xb, mtv);
}

static bool overlap_capsules_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                    sx_xform xb) {
    return sx_overlap_capsules(&a->u.capsule, xa, &b->u.capsule, xb);
}
static bool mtv_capsules_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                sx_vec2 *mtv) {
    return sx_mtv_capsules(&a->u.capsule, xa, &b->u.capsule, xb, mtv);
}

static bool overlap_polygon_circle_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                          sx_xform xb) {
    return sx_overlap_polygon_circle(&a->u.polygon, xa, &b->u.circle, xb);
}
static bool mtv_polygon_circle_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                      sx_xform xb, sx_vec2 *mtv) {
    return sx_mtv_polygon_circle(&a->u.polygon, xa, &b->u.circle, xb, mtv);
}

static bool overlap_polygon_segment_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                           sx_xform xb) {
    return sx_overlap_polygon_segment(&a->u.polygon, xa, &b->u.segment, xb);
}
static bool mtv_polygon_segment_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                       sx_xform xb, sx_vec2 *mtv) {
    return sx_mtv_polygon_segment(&a->u.polygon, xa, &b->u.segment, xb, mtv);
}

static bool overlap_polygon_capsule_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                           sx_xform xb) {
    return sx_overlap_polygon_capsule(&a->u.polygon, xa, &b->u.capsule, xb);
}
static bool mtv_polygon_capsule_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                       sx_xform xb, sx_vec2 *mtv) {
    return sx_mtv_polygon_capsule(&a->u.polygon, xa, &b->u.capsule, xb, mtv);
}

static bool overlap_polygons_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b,
                                    sx_xform xb) {
    return sx_overlap_polygons(&a->u.polygon, xa, &b->u.polygon, xb);
}
static bool mtv_polygons_shapes(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                sx_vec2 *mtv) {
    return sx_mtv_polygons(&a->u.polygon, xa, &b->u.polygon, xb, mtv);
}

typedef bool sx_overlap_entry(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb);
typedef bool sx_mtv_entry(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                          sx_vec2 *mtv);
/* Manifold entries take the transforms as sx_xf_arg (in registers where
 * they fit) and an out that is not NULL. */
typedef int sx_collide_entry(const sx_shape *a, sx_xf_arg xa, const sx_shape *b, sx_xf_arg xb,
                             sx_real margin, sx_real hyst, sx_manifold *out);

/* The entries of one ordered pair of types. `swapped`: the pair's
 * functions take the arguments in the other order, so the dispatch swaps
 * them back, negates the MTV and mirrors the manifold. */
typedef struct sx_pair_entry {
    sx_overlap_entry *overlap;
    sx_mtv_entry *mtv;
    sx_collide_entry *collide;
    bool swapped;
} sx_pair_entry;

/* The table, indexed [A's type][B's type], filled from narrow.h's lists of
 * pairs: a pair of two types in both orders, a pair of one type once. */
#define SX_TABLE_BOTH_ORDERS(NAME, TA, KA, MA, TB, KB, MB)                                         \
    [KA][KB] = {overlap_##NAME##_shapes, mtv_##NAME##_shapes, sx_collide_##NAME##_shapes, false},  \
    [KB][KA] = {overlap_##NAME##_shapes, mtv_##NAME##_shapes, sx_collide_##NAME##_shapes, true},
#define SX_TABLE_ONE_ORDER(NAME, TA, KA, MA, TB, KB, MB)                                           \
    [KA][KB] = {overlap_##NAME##_shapes, mtv_##NAME##_shapes, sx_collide_##NAME##_shapes, false},
static const sx_pair_entry sx_pair_table[SX_SHAPE_TYPE_COUNT][SX_SHAPE_TYPE_COUNT] = {
    SX_PAIRS_OF_TWO_TYPES(SX_TABLE_BOTH_ORDERS) SX_PAIRS_OF_ONE_TYPE(SX_TABLE_ONE_ORDER)};
#undef SX_TABLE_BOTH_ORDERS
#undef SX_TABLE_ONE_ORDER

static const sx_pair_entry *pair_entry(const sx_shape *a, const sx_shape *b) {
    if (a == NULL || b == NULL) return NULL;
    if ((unsigned)a->type >= (unsigned)SX_SHAPE_TYPE_COUNT ||
        (unsigned)b->type >= (unsigned)SX_SHAPE_TYPE_COUNT) {
        return NULL;
    }
    return &sx_pair_table[a->type][b->type];
}

/* ---- generic entry points ----------------------------------------------- */

bool sx_overlap(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    const sx_pair_entry *e = pair_entry(a, b);
    if (e == NULL) return false;
    return e->swapped ? e->overlap(b, xb, a, xa) : e->overlap(a, xa, b, xb);
}

/* The reversed orders of sx_mtv and sx_collide: the entry called with the
 * arguments swapped back, the MTV negated, the manifold mirrored. Out of
 * line, so that the canonical orders stay a bare tail call (no stack frame
 * for the reversed order's MTV or its saved out). */
SX_NOINLINE static bool mtv_swapped(const sx_pair_entry *e, const sx_shape *a, sx_xform xa,
                                    const sx_shape *b, sx_xform xb, sx_vec2 *mtv) {
    sx_vec2 v;
    bool hit = e->mtv(b, xb, a, xa, &v);
    if (mtv) *mtv = hit ? sx_neg(v) : sx_v2_zero();
    return hit;
}
SX_NOINLINE static int collide_swapped(const sx_pair_entry *e, const sx_shape *a, sx_xf_arg xa,
                                       const sx_shape *b, sx_xf_arg xb, sx_real margin,
                                       sx_real hyst, sx_manifold *out) {
    e->collide(b, xb, a, xa, margin, hyst, out);
    sx_mirror_manifold(out);
    return out->count;
}

bool sx_mtv(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_vec2 *mtv) {
    const sx_pair_entry *e = pair_entry(a, b);
    if (e == NULL) {
        if (mtv) *mtv = sx_v2_zero();
        return false;
    }
    if (e->swapped) return mtv_swapped(e, a, xa, b, xb, mtv);
    return e->mtv(a, xa, b, xb, mtv);
}

/* Both manifold entry points dispatch here directly (one call layer less
 * for the cheap pairs). */
static inline int collide_dispatch(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                   sx_real margin, sx_real hyst, sx_manifold *out) {
    const sx_pair_entry *e = pair_entry(a, b);
    sx_manifold scratch;
    if (e == NULL) {
        clear_manifold(out);
        return 0;
    }
    if (out == NULL) out = &scratch;
    if (e->swapped)
        return collide_swapped(e, a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin, hyst, out);
    return e->collide(a, sx_xf_pass(&xa), b, sx_xf_pass(&xb), margin, hyst, out);
}

int sx_collide_ex(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_real margin,
                  sx_manifold *out) {
    return collide_dispatch(a, xa, b, xb, margin, SX_REFERENCE_HYSTERESIS, out);
}

int sx_collide(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_manifold *out) {
    return collide_dispatch(a, xa, b, xb, SX_R(0.0), SX_REFERENCE_HYSTERESIS, out);
}

int sx_collide_world(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_real margin,
                     sx_manifold *out) {
    return collide_dispatch(a, xa, b, xb, margin, SX_WORLD_REFERENCE_HYSTERESIS, out);
}
