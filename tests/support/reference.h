/* sepax tests — an independent, high-precision reference for the narrowphase.
 *
 * The library answers collision questions by the separating axis theorem in
 * sx_real, in shape A's local frame. This reference answers the same
 * questions another way, in long double, so that the two can be compared:
 * every core vertex is placed in world space, the Minkowski difference of the
 * two cores (every pairwise difference a_i - b_j) is wrapped in its convex
 * hull, and the depth and direction are read off the hull's distance to the
 * origin, with R = ra + rb the summed rounding radii. It uses none of the
 * library's code (only the shape structs), so a shared mistake is unlikely.
 *
 * Conventions (those of sepax's collide.h):
 * - depth > 0: overlap by that much; it is |MTV|. depth < 0: the shapes are
 *   separated by the distance -depth. depth == 0: touching.
 * - dir is a unit vector such that translating A by depth * dir brings the
 *   two shapes exactly into touching contact. For an overlap, depth * dir is
 *   the MTV (the shortest translation of A that separates it from B; it points
 *   away from B) and the manifold normal (from A to B) is -dir.
 *
 * Nothing here calls cmocka or allocates; the benchmark links it too. */
#ifndef SEPAX_TEST_REFERENCE_H
#define SEPAX_TEST_REFERENCE_H

#include <stdbool.h>

#include "sepax/sepax.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest number of points of a core (a polygon's vertex count). */
#define SX_REF_MAX_CORE SX_MAX_POLYGON_VERTICES

/** A shape placed in world space in long double: its core (1 point for a
 *  circle, 2 for a segment or capsule, the vertices of a polygon) and its
 *  rounding radius (0 for a segment or a sharp polygon). */
typedef struct sx_ref_shape {
    long double x[SX_REF_MAX_CORE];
    long double y[SX_REF_MAX_CORE];
    int count;
    long double radius;
} sx_ref_shape;

/** Places `s` by `x` in long double: each core point p becomes
 *  (c px - s py + tx, s px + c py + ty) with the transform's own (c, s), as
 *  stored. Returns false (and count 0) for NULL, an unknown type, a polygon
 *  count outside 3..SX_MAX_POLYGON_VERTICES or a negative radius. */
bool sx_ref_place(const sx_shape *s, sx_xform x, sx_ref_shape *out);

/** The reference answer for one pair. */
typedef struct sx_ref_result {
    /** Signed penetration depth (see the conventions above). */
    long double depth;
    /** Unit direction: A moved by depth * dir just touches B. */
    long double dir_x, dir_y;
    /** Signed distance from the origin to the hull of the core difference:
     *  > 0 outside (the cores are that far apart), <= 0 inside (minus the
     *  distance to the nearest hull edge). depth = R - core_distance. The
     *  direction is ill-conditioned when this is near 0 (cores touching). */
    long double core_distance;
    /** Inside case: how much farther the best escape through an edge of a
     *  different direction is than the best one (0 when two edges tie: the
     *  direction is then a coin toss). Outside case: +infinity (the closest
     *  point of a convex set is unique). */
    long double tie_gap;
    /** False when no direction exists: the cores' difference is a point at the
     *  origin (concentric circles) or a segment through it (dir is then one
     *  of its two normals). */
    bool direction_defined;
    /** Vertices of the difference hull: 1 (a point), 2 (a segment: collinear
     *  cores) or more. */
    int hull_count;
} sx_ref_result;

/** Computes the reference depth and direction of shapes a and b placed by xa
 *  and xb. Returns false (out zeroed) when a shape cannot be placed. */
bool sx_ref_penetration(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                        sx_ref_result *out);

/** As sx_ref_penetration, on shapes already placed. */
bool sx_ref_penetration_placed(const sx_ref_shape *a, const sx_ref_shape *b, sx_ref_result *out);

/** The overlap of the projections of A and B on the unit direction
 *  (dx, dy) (normalised here): how far A must move along +dir to be
 *  separated from B along that axis, ra + rb + max_j dot(b_j, dir) -
 *  min_i dot(a_i, dir). Its minimum over all directions is the reference
 *  depth, reached at dir (the separating axis theorem, computed without a
 *  hull); use it to score a direction that is not the reference's own.
 *  A zero direction returns +infinity. */
long double sx_ref_depth_along(const sx_ref_shape *a, const sx_ref_shape *b, long double dx,
                               long double dy);

/** Signed distance from the world point (px, py) to the boundary of shape s
 *  placed by x, in long double: negative inside. *nx, *ny (either may be
 *  NULL) receive the outward unit normal of the closest boundary point; for a
 *  point exactly on a segment core or at a circle's centre, the fallback of
 *  collide.h: the segment's left normal perp(b - a), or +x. A shape that
 *  cannot be placed gives +infinity (never NaN) and a zero normal. */
long double sx_ref_distance_to_point(const sx_shape *s, sx_xform x, long double px, long double py,
                                     long double *nx, long double *ny);

/** The angle in radians between two directions (each normalised here), in
 *  [0, pi]; pi for a zero vector. */
long double sx_ref_angle_between(long double ax, long double ay, long double bx, long double by);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_TEST_REFERENCE_H */
