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

#include "core.h"

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
 *  sx_core_mtv, with early outs. */
bool sx_core_overlap(const sx_core *a, const sx_core *b);

/** True if the rounded cores overlap or touch; *mtv (in the working frame)
 *  receives the shortest translation of a separating it from b. */
bool sx_core_mtv(const sx_core *a, const sx_core *b, sx_vec2 *mtv);

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

#endif /* SEPAX_NARROW_H */
