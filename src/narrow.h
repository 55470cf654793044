/* sepax — private interface of the narrowphase core (src/narrow_core.c),
 * used by the pair functions and the dispatch table in src/collide.c.
 *
 * Every shape enters the narrowphase as a "core": a convex set of 1, 2 or
 * n >= 3 points plus a rounding radius. A circle is one point, a segment two
 * points with radius 0, a capsule two points with its radius, a polygon its
 * vertices with its rounding radius. A 2-point core is a polygon with two
 * faces, a->b (normal n) and b->a (normal -n), so one SAT, one distance and
 * one clipping routine serve every pair. Both cores of a pair live in A's
 * local frame. */
#ifndef SEPAX_NARROW_H
#define SEPAX_NARROW_H

#include <stddef.h>
#include <string.h>

#include "collide_world.h"
#include "core.h"
#include "sepax/collide.h"
#include "simd.h"

/* Reference-face hysteresis (see collide.h): B's face becomes the reference
 * only when its separation beats A's by more than this. sx_collide and the
 * pair functions, which know nothing of earlier frames, keep it small, so
 * that the depth they report is within it of the least penetration; the
 * world, which asks again every step, takes Box2D's 0.1 x the slop so that
 * a contact between two nearly equal faces does not change faces (and
 * feature ids) from step to step. */
#define SX_REFERENCE_HYSTERESIS (SX_R(0.02) * SX_LINEAR_SLOP)
#define SX_WORLD_REFERENCE_HYSTERESIS (SX_R(0.1) * SX_LINEAR_SLOP)

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

/* Coordinate differences down to this magnitude have squares that keep
 * full precision (d.x^2 stays above the smallest normal real over epsilon);
 * below it squared distances underflow and need scaling first. */
#ifdef SX_DOUBLE
#define SX_SQUARE_SAFE 1e-146
#else
#define SX_SQUARE_SAFE 3e-16f
#endif

/* |x| as a maximum, which compiles without a branch (sx_absr's sign test
 * does not, and in the narrowphase the signs are random, so that test
 * mispredicts half the time). It differs from sx_absr only in the sign of
 * a zero: use it where only comparisons and maxima see the result. */
static inline sx_real sx_magnitude(sx_real x) { return x > -x ? x : -x; }

/* A core's rounding radius as the builders accept it: finite and >= 0. */
static inline bool sx_core_radius_ok(sx_real r) { return sx_is_finite(r) && r >= SX_R(0.0); }

/** A convex core plus radius, in some working frame. Pass it by pointer
 *  only: v and n may point into its own storage. */
typedef struct sx_core {
    /** Points, CCW for count >= 3; count 2: a and b of the segment. Either
     *  vs, or a polygon's own vertices when it is read in place. */
    const sx_vec2 *v;
    /** Outward unit normal of face i (v[i] -> v[(i+1) % count]); unused for
     *  count 1. For count 2, n[1] = -n[0]. */
    const sx_vec2 *n;
    /** Storage for a shape placed into the working frame. */
    sx_vec2 vs[SX_MAX_POLYGON_VERTICES];
    sx_vec2 ns[SX_MAX_POLYGON_VERTICES];
    sx_real radius;
    /** 1 (point), 2 (segment) or 3..SX_MAX_POLYGON_VERTICES (polygon). */
    int count;
} sx_core;

/* Core builders: place the shape by *x into the working frame (x NULL: keep
 * the shape's own frame, as for shape A). Each returns
 * false (and leaves *out unusable) for NULL, a negative or non-finite radius,
 * a polygon count outside 3..SX_MAX_POLYGON_VERTICES or any non-finite value,
 * before or after the transform (a polygon's vertices and normals: see
 * sx_core_values_finite). A zero-length segment or capsule becomes a
 * 1-point core at its end point a. Circles never become cores: the point
 * routines below take their centre. */
bool sx_core_from_segment(const sx_segment *s, const sx_xform *x, sx_core *out);
bool sx_core_from_capsule(const sx_capsule *c, const sx_xform *x, sx_core *out);
bool sx_core_from_polygon(const sx_polygon *p, const sx_xform *x, sx_core *out);

/* sx_core_from_polygon checks the count and the radius only: the values of
 * a polygon core (placed or read in place) are checked by this function,
 * which the caller runs once the answer is not "apart" (a non-finite value
 * can only make the routines below answer "apart", or answer something that
 * this check then rejects; they never index out of the core). True for
 * finite values; segment and capsule cores (checked when built) always
 * pass. */
bool sx_core_values_finite(const sx_core *c);
/* The same check for n >= 3 vertices and normals. */
bool sx_polygon_values_finite(const sx_vec2 *v, const sx_vec2 *n, int count);

/** True if the rounded cores overlap or touch. Same decisions as
 *  sx_cores_mtv, with early outs. */
bool sx_core_overlap(const sx_core *a, const sx_core *b);

/** The contact manifold of a against b in the working frame (normal from a
 *  to b), keeping points with depth >= -margin (margin >= 0). Returns the
 *  point count and fills *out. *clear_cut (may be NULL) is set true when the
 *  rounded cores are so clearly apart or overlapping that sx_core_overlap
 *  gives the same answer with a and b swapped, whatever the rounding. */
int sx_core_manifold(const sx_core *a, const sx_core *b, sx_real margin, sx_manifold *out,
                     bool *clear_cut);

/* The same three answers for b the 1-point core (c, rb), b a circle: no
 * core is built for it, and the SAT, vertex sweep and contact are written
 * out for a single point (see narrow_core.c). */
bool sx_core_point_overlap(const sx_core *a, sx_vec2 c, sx_real rb);
bool sx_core_point_mtv(const sx_core *a, sx_vec2 c, sx_real rb, sx_vec2 *mtv);
int sx_core_point_manifold(const sx_core *a, sx_vec2 c, sx_real rb, sx_real margin,
                           sx_manifold *out);

/* The same three for a the 2-point core of the segment or capsule a0-a1 of
 * radius ra (>= 0, finite) in its own frame, without building the core:
 * the same decisions up to rounding where c lies level with an end. Each
 * answers -1 (and leaves its output untouched) where the general route must
 * answer: a0 or a1 not finite, a0-a1 shorter than a direction can be taken
 * from, c not finite, c on the segment or within rounding noise of an end.
 * Otherwise the overlap answers 1 or 0, the MTV 1 or 0 with *mtv set, the
 * manifold the point count with *out filled. */
int sx_core_segment_point_overlap(sx_vec2 a0, sx_vec2 a1, sx_real ra, sx_vec2 c, sx_real rb);
int sx_core_segment_point_mtv(sx_vec2 a0, sx_vec2 a1, sx_real ra, sx_vec2 c, sx_real rb,
                              sx_vec2 *mtv);
int sx_core_segment_point_manifold(sx_vec2 a0, sx_vec2 a1, sx_real ra, sx_vec2 c, sx_real rb,
                                   sx_real margin, sx_manifold *out);

/* The same three for a the polygon (count 3..SX_MAX_POLYGON_VERTICES,
 * radius >= 0 and finite: the caller checks, as sx_core_from_polygon does)
 * in its own frame, read in place: no core, the same answers bit for bit
 * (the polygon's values are checked by the caller, as for a core). -1 (and
 * the output untouched) where the general route must answer: a square that
 * overflows or underflows, or c within rounding noise of a vertex. */
int sx_core_polygon_point_overlap(const sx_polygon *a, sx_vec2 c, sx_real rb);
int sx_core_polygon_point_mtv(const sx_polygon *a, sx_vec2 c, sx_real rb, sx_vec2 *mtv);
int sx_core_polygon_point_manifold(const sx_polygon *a, sx_vec2 c, sx_real rb, sx_real margin,
                                   sx_manifold *out);

/* ---- shared plumbing of the pair functions ------------------------------ */

/* A transform handed between the narrowphase's functions: four lanes,
 * [p.x, p.y, q.c, q.s]. In the float build it travels in one register, not
 * by address: where a function took the address of its by-value transform,
 * GCC 12 copied it through a 16-byte reload of its two stored 8-byte
 * halves, a failed store forward on every call (calls that are not inlined
 * take an sx_xf_arg). Made with sx_xf_of in the function that holds the
 * transform by value; loaded 8 bytes at a time, as a by-value transform is
 * stored (a 16-byte load of two 8-byte stores cannot be forwarded). */
typedef sx_r4 sx_xf;
static SX_ALWAYS_INLINE sx_xf sx_xf_of(const sx_xform *x) {
    return sx_r4_load2x2(&x->p.x, &x->q.c);
}
/* How a transform crosses a call that is not inlined (the dispatch table's
 * entries): sx_xf_pass of the caller's sx_xform, read back with sx_xf_in.
 * Four floats travel by value in registers; four doubles would be a 32-byte
 * struct, which the x86-64 ABI passes in memory, copied at every call, so
 * the double build passes the caller's transform by address. */
#ifdef SX_DOUBLE
typedef const sx_xform *sx_xf_arg;
static SX_ALWAYS_INLINE sx_xf_arg sx_xf_pass(const sx_xform *x) { return x; }
static SX_ALWAYS_INLINE sx_xf sx_xf_in(sx_xf_arg x) { return sx_xf_of(x); }
#else
typedef sx_xf sx_xf_arg;
static SX_ALWAYS_INLINE sx_xf_arg sx_xf_pass(const sx_xform *x) { return sx_xf_of(x); }
static SX_ALWAYS_INLINE sx_xf sx_xf_in(sx_xf_arg x) { return x; }
#endif
/* The transform back as a value, for the calls into code that takes
 * transforms by value. */
static SX_ALWAYS_INLINE sx_xform sx_xform_of_xf(sx_xf x) {
    sx_xform t;
    sx_r4_store_low(&t.p.x, x);
    sx_r4_store_high(&t.q.c, x);
    return t;
}

/* The two vectors in v turned by the rotation in lanes 2, 3 of x, each lane
 * as sx_rotate computes it (c x - s y as c x + (-s) y, and s x + c y as
 * c y + s x, which IEEE arithmetic makes the same numbers). */
static SX_ALWAYS_INLINE sx_r4 sx_xf_rotate(sx_xf x, sx_r4 v) {
    sx_r4 s =
        sx_r4_flip_signs(sx_r4_splat3(x), sx_r4_set(SX_R(-0.0), SX_R(0.0), SX_R(-0.0), SX_R(0.0)));
    return sx_r4_add(sx_r4_mul(sx_r4_splat2(x), v), sx_r4_mul(s, sx_r4_swap_pairs(v)));
}

/* The two vectors in v turned by the inverse of that rotation, each lane as
 * sx_inv_rotate computes it (-s x + c y as c y + (-s) x). */
static SX_ALWAYS_INLINE sx_r4 sx_xf_inv_rotate(sx_xf x, sx_r4 v) {
    sx_r4 s =
        sx_r4_flip_signs(sx_r4_splat3(x), sx_r4_set(SX_R(0.0), SX_R(-0.0), SX_R(0.0), SX_R(-0.0)));
    return sx_r4_add(sx_r4_mul(sx_r4_splat2(x), v), sx_r4_mul(s, sx_r4_swap_pairs(v)));
}

/* B's placement in A's frame, each component as sx_xform_inv_mul computes
 * it: the offset [dx, dy] and B's rotation [bc, bs] turned back by A's
 * rotation give [c dx + s dy, -s dx + c dy, c bc + s bs, c bs - s bc],
 * which are the offset's sx_inv_rotate and sx_rot_inv_mul. */
static SX_ALWAYS_INLINE sx_xf sx_xf_relative(sx_xf xa, sx_xf xb) {
    return sx_xf_inv_rotate(xa, sx_r4_low_high(sx_r4_sub(xb, xa), xb));
}

/* A circle B's centre in A's frame: the world offset of the positions first
 * (exact for nearby bodies far from the origin), then B's rotated centre,
 * then the rotation into A's frame (lanes 0, 1; the others are unused). */
static SX_ALWAYS_INLINE sx_vec2 sx_circle_in_frame(const sx_circle *b, sx_xf xa, sx_xf xb) {
    sx_r4 w = sx_r4_add(sx_r4_sub(xb, xa), sx_xf_rotate(xb, sx_r4_load2(&b->center.x)));
    sx_vec2 c;
    sx_r4_store_low(&c.x, sx_xf_inv_rotate(xa, w));
    return c;
}

/* The checks of a circle B and of its placed centre c, run only once the
 * answer is not "apart": a NaN or infinity anywhere in B, xb or xa makes c
 * (or the limit a + rb) non-finite, and the point routines answer "apart"
 * for a non-finite c unless the limit is infinite, which an invalid radius
 * is needed for. xa needs no check of its own: both components of the
 * inverse rotation take in both rotation components and both coordinates
 * of the offset. */
static SX_ALWAYS_INLINE bool sx_circle_valid(const sx_circle *b, sx_xf xb, sx_vec2 c) {
    sx_r4 v = sx_r4_set(b->center.x, b->center.y, c.x, c.y);
    return b->radius >= SX_R(0.0) && sx_is_finite(b->radius) &&
           !sx_r4_any_nan(sx_r4_add(sx_r4_sub(xb, xb), sx_r4_sub(v, v)));
}

/* The empty manifold, in two parts: one memset of the double build's
 * 88-byte manifold compiles to `rep stos`, slow to start for so few bytes,
 * on the path of every pair that is apart; each part stays a few stores. */
static SX_ALWAYS_INLINE void sx_manifold_clear(sx_manifold *m) {
    memset(m, 0, offsetof(sx_manifold, points[1]));
    memset(&m->points[1], 0, sizeof(*m) - offsetof(sx_manifold, points[1]));
}

/* Moves a local manifold of `count` points (A's frame) to world space in
 * place and completes it (count set, unused points zeroed); a non-finite
 * result (overflow of huge inputs) becomes 0 points with a zero normal.
 * Returns the count. The normal and the first point are adjacent in
 * sx_manifold: both are turned in one register, each lane as
 * sx_xform_vector and sx_xform_point compute it; one test checks every
 * output. */
static SX_ALWAYS_INLINE int sx_world_manifold(sx_manifold *m, int count, sx_xf xa) {
    if (count > 0) {
        /* Two 8-byte loads, not one of 16: the routines before this store
         * the normal and the point separately (see sx_r4_load2x2). */
        sx_r4 np = sx_r4_load2x2(&m->normal.x, &m->points[0].point.x);
        /* -0 is the identity of addition (+0 would turn a -0 normal
         * component into +0). */
        sx_r4 w = sx_r4_add(sx_xf_rotate(xa, np), sx_r4_low_halves(sx_r4_set1(SX_R(-0.0)), xa));
        sx_r4 depth = sx_r4_set(m->points[0].depth, SX_R(0.0), SX_R(0.0), SX_R(0.0));
        sx_r4 p1 = sx_r4_zero();
        if (count > 1) {
            p1 = sx_r4_add(sx_xf_rotate(xa, sx_r4_load2(&m->points[1].point.x)), xa);
            depth = sx_r4_set(m->points[0].depth, m->points[1].depth, SX_R(0.0), SX_R(0.0));
        }
        sx_r4 rest = sx_r4_low_halves(p1, depth);
        if (!sx_r4_any_nan(sx_r4_add(sx_r4_sub(w, w), sx_r4_sub(rest, rest)))) {
            sx_r4_store_low(&m->normal.x, w);
            sx_r4_store_high(&m->points[0].point.x, w);
            if (count > 1) {
                sx_r4_store_low(&m->points[1].point.x, p1);
            } else {
                m->points[1].point = sx_v2_zero();
                m->points[1].depth = SX_R(0.0);
                m->points[1].id = 0;
            }
            m->count = count;
            return count;
        }
    }
    sx_manifold_clear(m);
    return 0;
}

/* A pair at margin 0 whose manifold found no point although the canonical
 * order says it touches (the two orders round differently by a few ulps) is
 * asked again with this margin and its depths clamped to 0 (collide.c): 1 %
 * of the slop, far above any rounding and far below anything physical. */
#define SX_TOUCH_RESCUE_MARGIN (SX_R(0.01) * SX_LINEAR_SLOP)

/* collide.c's general route, for what the fused routines hand back: the
 * manifold of A (kind: SX_SHAPE_SEGMENT, CAPSULE or POLYGON) against a
 * circle through a core; and for the same-type pairs, what is not a
 * clear-cut pair at margin 0 (count, the fused manifold's answer then,
 * stands when the canonical order is the caller's) or is speculative. */
int sx_point_collide_general(int kind, const void *a, sx_xf xa, const sx_circle *b, sx_xf xb,
                             sx_real margin, sx_manifold *out);
int sx_collide_segments_gated(const sx_segment *a, sx_xf ta, const sx_segment *b, sx_xf tb,
                              sx_real margin, sx_real hyst, int count, bool touch_test,
                              sx_manifold *out);
int sx_collide_capsules_gated(const sx_capsule *a, sx_xf ta, const sx_capsule *b, sx_xf tb,
                              sx_real margin, sx_real hyst, int count, bool touch_test,
                              sx_manifold *out);
int sx_collide_polygons_gated(const sx_polygon *a, sx_xf ta, const sx_polygon *b, sx_xf tb,
                              sx_real margin, sx_real hyst, int count, bool touch_test,
                              sx_manifold *out);

/* ---- fused pair functions (narrow_core.c) ------------------------------- */

/* The manifold of a and b (kinds ka, kb: SX_SHAPE_SEGMENT, CAPSULE or
 * POLYGON, the shapes as those structs) placed by xa and xb, in world
 * space, with reference-face hysteresis `hysteresis`: the cores (b placed
 * in a's frame), the manifold, the value checks and the move to world
 * space together, in one function. Invalid input (a NULL or bad shape, a
 * non-finite transform) gives 0 points and a zeroed *out. out is not NULL;
 * clear_cut (may be NULL) as sx_core_manifold's, false when overflow in
 * world space lost the points. */
int sx_cores_collide(int ka, const void *a, sx_xf xa, int kb, const void *b, sx_xf xb,
                     sx_real margin, sx_real hysteresis, sx_manifold *out, bool *clear_cut);

/* sx_core_overlap of the same cores, with the value checks: what
 * collide.c's pair_overlap answers, in one function. */
bool sx_cores_overlap(int ka, const void *a, sx_xf xa, int kb, const void *b, sx_xf xb);

/* The MTV of the rounded cores (the shortest translation of a separating it
 * from b), with the value checks: the MTV in a's
 * frame (zero when false), as collide.c's pair_mtv takes it before the
 * move to world space. */
bool sx_cores_mtv(int ka, const void *a, sx_xf xa, int kb, const void *b, sx_xf xb, sx_vec2 *mtv);

/* ---- the pairs of shape types --------------------------------------------- */

/* Every unordered pair of shape types, once: X(NAME, type of A, kind of A,
 * union member of A, type of B, kind of B, member of B), A first as in the
 * typed functions sx_overlap_NAME, sx_mtv_NAME and sx_collide_NAME of
 * collide.h. These lists declare the manifold entries below and fill
 * collide.c's dispatch table; the functions themselves are written out
 * (narrow_core.c, and collide.c for two circles). */
#define SX_PAIRS_OF_TWO_TYPES(X)                                                                   \
    X(segment_circle, sx_segment, SX_SHAPE_SEGMENT, segment, sx_circle, SX_SHAPE_CIRCLE, circle)   \
    X(capsule_circle, sx_capsule, SX_SHAPE_CAPSULE, capsule, sx_circle, SX_SHAPE_CIRCLE, circle)   \
    X(polygon_circle, sx_polygon, SX_SHAPE_POLYGON, polygon, sx_circle, SX_SHAPE_CIRCLE, circle)   \
    X(capsule_segment, sx_capsule, SX_SHAPE_CAPSULE, capsule, sx_segment, SX_SHAPE_SEGMENT,        \
      segment)                                                                                     \
    X(polygon_segment, sx_polygon, SX_SHAPE_POLYGON, polygon, sx_segment, SX_SHAPE_SEGMENT,        \
      segment)                                                                                     \
    X(polygon_capsule, sx_polygon, SX_SHAPE_POLYGON, polygon, sx_capsule, SX_SHAPE_CAPSULE, capsule)
#define SX_PAIRS_OF_ONE_TYPE(X)                                                                    \
    X(circles, sx_circle, SX_SHAPE_CIRCLE, circle, sx_circle, SX_SHAPE_CIRCLE, circle)             \
    X(segments, sx_segment, SX_SHAPE_SEGMENT, segment, sx_segment, SX_SHAPE_SEGMENT, segment)      \
    X(capsules, sx_capsule, SX_SHAPE_CAPSULE, capsule, sx_capsule, SX_SHAPE_CAPSULE, capsule)      \
    X(polygons, sx_polygon, SX_SHAPE_POLYGON, polygon, sx_polygon, SX_SHAPE_POLYGON, polygon)

/* The manifold entries of each pair: sx_collide_NAME_xf takes the pair's
 * own structs with the transforms as sx_xf_arg (what the typed pair
 * functions call), sx_collide_NAME_shapes the two sx_shape of the dispatch
 * table; hyst is the reference-face hysteresis, out is not NULL. Both
 * answer as sx_collide_NAME. */
#define SX_DECLARE_MANIFOLD_ENTRIES(NAME, TA, KA, MA, TB, KB, MB)                                  \
    int sx_collide_##NAME##_xf(const TA *a, sx_xf_arg xa, const TB *b, sx_xf_arg xb,               \
                               sx_real margin, sx_real hyst, sx_manifold *out);                    \
    int sx_collide_##NAME##_shapes(const sx_shape *a, sx_xf_arg xa, const sx_shape *b,             \
                                   sx_xf_arg xb, sx_real margin, sx_real hyst, sx_manifold *out);
SX_PAIRS_OF_TWO_TYPES(SX_DECLARE_MANIFOLD_ENTRIES)
SX_PAIRS_OF_ONE_TYPE(SX_DECLARE_MANIFOLD_ENTRIES)
#undef SX_DECLARE_MANIFOLD_ENTRIES

/* The manifold of (B, A) from that of (A, B): same points and depths, the
 * normal reversed, and the flipped bit of every id toggled (the reference
 * face now belongs to the other argument). */
static inline void sx_mirror_manifold(sx_manifold *m) {
    int i;
    m->normal = sx_neg(m->normal);
    for (i = 0; i < m->count; ++i)
        m->points[i].id ^= SX_FEATURE_ID_FLIPPED;
}

#endif /* SEPAX_NARROW_H */
