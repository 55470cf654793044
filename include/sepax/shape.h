/* sepax — shapes: plain values in local coordinates, placed by an sx_xform.
 *
 * A shape is a type tag and a named union. Circles, segments and capsules are
 * built by value and can be checked with sx_shape_validate(); convex polygons
 * go through a builder (sx_polygon_shape) that takes any point cloud, computes
 * its convex hull, welds near-duplicates, drops collinear points and returns a
 * status when nothing usable is left. Boxes and oriented boxes are polygons
 * with four vertices; a point is a circle of radius zero. Every shape has mass
 * properties and an AABB under a transform. No function here allocates. */
#ifndef SEPAX_SHAPE_H
#define SEPAX_SHAPE_H

#include "base.h"
#include "vecmath.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Most vertices a convex polygon may have (compile-time setting, >= 3). */
#ifndef SX_MAX_POLYGON_VERTICES
#define SX_MAX_POLYGON_VERTICES 8
#endif

typedef enum sx_shape_type {
    SX_SHAPE_CIRCLE = 0, /**< also the point: a circle of radius 0 */
    SX_SHAPE_SEGMENT,
    SX_SHAPE_CAPSULE,
    SX_SHAPE_POLYGON, /**< convex, CCW, optionally rounded; boxes are polygons */
    SX_SHAPE_TYPE_COUNT
} sx_shape_type;

/** A disc. radius 0 is a point. */
typedef struct sx_circle {
    sx_vec2 center;
    sx_real radius;
} sx_circle;

/** A line segment from a to b (two-sided, no thickness). */
typedef struct sx_segment {
    sx_vec2 a, b;
} sx_segment;

/** The set of points within `radius` of the segment a-b. */
typedef struct sx_capsule {
    sx_vec2 a, b;
    sx_real radius;
} sx_capsule;

/** A convex polygon: vertices in counter-clockwise order, no three collinear;
 *  normals[i] is the outward unit normal of the edge vertices[i] ->
 *  vertices[i+1]. `radius` > 0 rounds it (the Minkowski sum with a disc).
 *  Build it with sx_polygon_shape / sx_box_shape; the fields are read-only
 *  for users. */
typedef struct sx_polygon {
    sx_vec2 vertices[SX_MAX_POLYGON_VERTICES];
    sx_vec2 normals[SX_MAX_POLYGON_VERTICES];
    sx_vec2 centroid; /**< area centroid of the core polygon (without rounding) */
    sx_real radius;
    int count;
} sx_polygon;

/** A shape value: `type` says which member of `u` is live. */
typedef struct sx_shape {
    sx_shape_type type;
    union {
        sx_circle circle;
        sx_segment segment;
        sx_capsule capsule;
        sx_polygon polygon;
    } u;
} sx_shape;

/* ---- constructors ------------------------------------------------------- */

/** A circle. Not checked: see sx_shape_validate (negative, NaN or infinite
 *  radius is invalid, and one too large for finite mass properties; zero is
 *  a point). */
SX_API sx_shape sx_circle_shape(sx_vec2 center, sx_real radius);
/** A point: a circle of radius 0. */
SX_API sx_shape sx_point_shape(sx_vec2 p);
/** A segment. Not checked: a zero-length segment is reported degenerate by
 *  sx_shape_validate (the narrowphase still answers for it, as a point). */
SX_API sx_shape sx_segment_shape(sx_vec2 a, sx_vec2 b);
/** A capsule. Not checked: see sx_shape_validate. a == b is a circle. */
SX_API sx_shape sx_capsule_shape(sx_vec2 a, sx_vec2 b, sx_real radius);
/** An axis-aligned box centred on the local origin, half-extents hw x hh.
 *  Not checked: bad extents make a shape that sx_shape_validate reports
 *  (zero: SX_ERR_DEGENERATE; NaN/Inf: SX_ERR_NONFINITE; negative: the
 *  vertices turn clockwise or away from their normals, SX_ERR_INVALID_ARG). */
SX_API sx_shape sx_box_shape(sx_real half_width, sx_real half_height);
/** A box with half-extents hw x hh, centred at `center` and turned by `angle`
 *  radians in the local frame (an oriented, offset box). Not checked, as
 *  sx_box_shape. */
SX_API sx_shape sx_offset_box_shape(sx_real half_width, sx_real half_height, sx_vec2 center,
                                    sx_real angle);

/** Convex hull of up to SX_MAX_POLYGON_VERTICES points, CCW. */
typedef struct sx_hull {
    sx_vec2 points[SX_MAX_POLYGON_VERTICES];
    int count;
} sx_hull;

/** Computes the convex hull of `count` points (any order, any count: the input
 *  is not modified and no memory is allocated; gift wrapping, O(count x hull
 *  size)). Points within `weld_tolerance` of each other are welded (exact
 *  duplicates always are, even at tolerance 0), and hull points within
 *  `weld_tolerance` of the line through their neighbours are dropped as
 *  collinear. Every hull point is one of the input points; the hull is
 *  counter-clockwise, starting at the lowest-x (then lowest-y) point, and
 *  passes sx_validate_hull(out, weld_tolerance). Every input point lies
 *  inside it or within `weld_tolerance` outside (only a dense, slightly
 *  curved run of points, where dropping a collinear vertex and staying within
 *  the tolerance conflict, may reach about twice that).
 *  Errors: SX_ERR_INVALID_ARG (points or out NULL, count < 0, negative or
 *  non-finite tolerance); SX_ERR_NONFINITE (a NaN/Inf coordinate);
 *  SX_ERR_DEGENERATE (fewer than 3 usable points, or zero area);
 *  SX_ERR_CAPACITY (the hull has more than SX_MAX_POLYGON_VERTICES vertices,
 *  or the exact hull before collinear pruning has more than
 *  64 x SX_MAX_POLYGON_VERTICES: nothing is dropped silently). On error
 *  out->count is 0. */
SX_API sx_status sx_compute_hull(const sx_vec2 *points, int count, sx_real weld_tolerance,
                                 sx_hull *out);

/** True if the hull is convex, CCW, with no collinear or coincident points
 *  (each within the given tolerance). */
SX_API bool sx_validate_hull(const sx_hull *hull, sx_real tolerance);

/** Builds a convex polygon from any point cloud: sx_compute_hull with
 *  SX_WELD_TOLERANCE, then unit outward normals and the area centroid.
 *  `radius` >= 0 rounds the corners. Errors as sx_compute_hull, plus
 *  SX_ERR_INVALID_ARG for a negative radius, SX_ERR_NONFINITE for a
 *  non-finite one, and those of sx_polygon_from_hull (SX_ERR_NONFINITE for
 *  a polygon or radius too large for finite mass properties). On error
 *  *out is left unchanged. */
SX_API sx_status sx_polygon_shape(const sx_vec2 *points, int count, sx_real radius, sx_shape *out);

/** As sx_polygon_shape with an explicit weld tolerance (for shapes far smaller
 *  or larger than the default length scale). */
SX_API sx_status sx_polygon_shape_ex(const sx_vec2 *points, int count, sx_real radius,
                                     sx_real weld_tolerance, sx_shape *out);

/** Builds a polygon from a hull (normally sx_compute_hull's output): unit
 *  outward normals (normalised in wider precision) and the area centroid of
 *  the core polygon. Errors: SX_ERR_INVALID_ARG (NULL, count outside
 *  3..SX_MAX_POLYGON_VERTICES, negative radius, or points that are not a
 *  strictly convex counter-clockwise polygon without coincident points, i.e.
 *  sx_validate_hull(hull, 0) fails), SX_ERR_NONFINITE (NaN/Inf point or
 *  radius), SX_ERR_DEGENERATE (exactly zero area, e.g. all points collinear,
 *  or a sliver so far beyond SX_HUGE that its area, summed in wider
 *  precision, rounds to zero or below: no mass properties exist for it),
 *  SX_ERR_NONFINITE (mass properties beyond sx_real, as sx_shape_validate).
 *  What it returns always passes sx_shape_validate. On error *out is left
 *  unchanged. */
SX_API sx_status sx_polygon_from_hull(const sx_hull *hull, sx_real radius, sx_shape *out);

/** Checks a shape value. SX_OK, or: SX_ERR_INVALID_ARG (NULL, unknown type,
 *  negative radius, polygon count outside 3..SX_MAX_POLYGON_VERTICES, polygon
 *  not strictly convex and CCW, or a normal not unit, more than
 *  SX_ANGULAR_SLOP away from its edge's outward direction, or leaning so
 *  that the edge's far end lies off the line through its near end by more
 *  than 64 x SX_REAL_EPSILON x the edge's largest coordinate: what rounding
 *  of the vertices explains, as for an offset box far from the origin);
 *  SX_ERR_NONFINITE
 *  (NaN/Inf in any used field); SX_ERR_DEGENERATE (a segment no longer than
 *  SX_REAL_EPSILON, a polygon of exactly zero area, or one whose area and
 *  centroid rounding cannot resolve, as sx_polygon_from_hull refuses);
 *  SX_ERR_NONFINITE also for a finite shape so large that its area or its
 *  rotational inertia at density 1 overflows sx_real, so that no body could
 *  carry it (float build: a circle of radius above about 3.8e9, a square
 *  of half-extent above about 3.4e9, rounded polygons and capsules alike;
 *  double build: about 1e77; segments have no area and are never refused
 *  for their size).
 *  Checked in that order per field group: count, finiteness, radius, area,
 *  convexity, normals, then the rounded area and centroid, then the mass
 *  properties' range. A
 *  circle of radius 0 (a point) is valid; so is a capsule with a == b (a
 *  circle) or radius 0 (a segment). */
SX_API sx_status sx_shape_validate(const sx_shape *shape);

/* ---- mass properties and bounds ----------------------------------------- */

/** Mass properties of a shape of uniform density. */
typedef struct sx_mass_data {
    sx_real mass;               /**< kg (density x area) */
    sx_vec2 center;             /**< centre of mass, in the shape's local frame */
    sx_real rotational_inertia; /**< kg m^2, about the centre of mass */
} sx_mass_data;

/** Area in square metres (segments: 0; rounded polygons include the rounding:
 *  A + perimeter r + pi r^2). An invalid shape (sx_shape_validate) gives 0. */
SX_API sx_real sx_shape_area(const sx_shape *shape);
/** Area centroid in the local frame, including any rounding (segments: the
 *  midpoint, even of a zero-length one). Otherwise invalid shapes give the
 *  zero vector. */
SX_API sx_vec2 sx_shape_centroid(const sx_shape *shape);
/** Mass, centre of mass and inertia about it for `density` (kg/m^2), summed
 *  in wider precision about a point near the centre (accurate far from the
 *  origin). Capsules are exact (a rectangle plus two half discs); polygons
 *  are a triangle fan; a rounded polygon is exact too: the core, plus one
 *  r-thick rectangle outside each edge, plus a disc sector at each vertex
 *  (the sectors make up one full disc). Segments have no area: zero mass and
 *  inertia, centre at the midpoint. Density 0 gives zero mass and inertia
 *  with the centre at the centroid. Negative or non-finite density, or an
 *  invalid shape, gives all zeros. */
SX_API sx_mass_data sx_shape_mass(const sx_shape *shape, sx_real density);
/** The tight world-space AABB of the shape placed by x (including rounding).
 *  Not validated (hot path), but never NaN: a shape or transform with NaN, a
 *  negative radius, or a polygon count outside 1..SX_MAX_POLYGON_VERTICES
 *  gives the empty box at x.p (at the origin if x.p is not finite). */
SX_API sx_aabb sx_shape_aabb(const sx_shape *shape, sx_xform x);
/** The extent of the shape along `axis` in its local frame: the support
 *  value max over the shape of dot(point, axis) (for a non-unit axis too:
 *  the radius counts |axis| times). NULL, an unknown type, a polygon count
 *  outside 1..SX_MAX_POLYGON_VERTICES or NaN in the shape or axis gives 0. */
SX_API sx_real sx_shape_support(const sx_shape *shape, sx_vec2 axis);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_SHAPE_H */
