/* sepax — concave polygons and compound colliders.
 *
 * A concave (simple) polygon outline is turned into a few convex polygons by
 * sx_decompose_polygon; points can be tested against the raw outline with
 * sx_point_in_outline. A compound is several convex parts, each a shape with
 * its own local offset, that act as one collider: bounds, mass properties,
 * overlap, a minimum translation that clears the whole compound, per-part
 * manifolds, ray casts and point containment. Nothing here allocates: the
 * decomposition works in caller-provided scratch memory, and a compound is a
 * view of a parts array the caller owns. */
#ifndef SEPAX_COMPOUND_H
#define SEPAX_COMPOUND_H

#include "base.h"
#include "collide.h"
#include "vecmath.h"
#include "shape.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- concave polygon outlines ------------------------------------------- */

/** Most points of an outline sx_decompose_polygon takes: 2^29 - 1 (its
 *  triangle indices must fit an int; the work grows as the square of the
 *  count long before, about 0.3 s for 4000 points). */
#define SX_DECOMPOSE_MAX_POINTS 0x1FFFFFFF

/** Bytes of scratch memory sx_decompose_polygon needs for an outline of
 *  `count` points (a fixed linear bound: about (12 + SX_MAX_POLYGON_VERTICES)
 *  ints and one sx_vec2 per point, plus alignment slack). Returns 0 for
 *  count < 3, count above SX_DECOMPOSE_MAX_POINTS, or a count so large the
 *  size would overflow size_t. */
SX_API size_t sx_decompose_scratch_bytes(int count);

/** Splits a simple polygon outline into convex polygons of at most
 *  SX_MAX_POLYGON_VERTICES vertices each.
 *
 *  The outline may wind either way and may be concave. It is cleaned first:
 *  consecutive points within SX_WELD_TOLERANCE are welded, and points within
 *  SX_WELD_TOLERANCE of the line through their neighbours (collinear runs,
 *  zero-width spikes) are dropped, repeatedly, as long as the points dropped
 *  before between those neighbours stay within SX_WELD_TOLERANCE of that
 *  line too (so a densely drawn curve is not worn down: the cleaned outline
 *  keeps within about the tolerance of the raw points). The cleaned outline
 *  is ear clipped (orientation tests in a wider precision) and the triangles
 *  are merged greedily across their diagonals while the union stays strictly
 *  convex and within the vertex cap (Hertel-Mehlhorn), so a polygon with r
 *  reflex vertices gives few parts (never more than the triangle count).
 *  Parts are in the outline's coordinates, counter-clockwise, built by
 *  sx_polygon_from_hull (radius 0), so each passes sx_shape_validate; they
 *  tile the cleaned outline without overlapping, and their areas sum to its
 *  area (up to rounding: an ear thinner than the rounding of its own
 *  orientation test is dropped rather than emitted as an invalid polygon).
 *
 *  scratch: at least sx_decompose_scratch_bytes(count) bytes, any alignment;
 *  not needed after the call. parts: room for part_capacity shapes;
 *  count - 2 always suffices. *part_count receives the number of parts and
 *  *triangle_count (may be NULL) the number of triangles before merging
 *  (count - 2 for an outline with no dropped points).
 *
 *  Errors, checked in this order (parts untouched, *part_count 0 except as
 *  said): SX_ERR_INVALID_ARG (points, parts or part_count NULL, scratch NULL
 *  with scratch_bytes > 0, count < 3); SX_ERR_CAPACITY (count above
 *  SX_DECOMPOSE_MAX_POINTS, or scratch_bytes below
 *  sx_decompose_scratch_bytes(count)); SX_ERR_NONFINITE (a NaN/Inf
 *  coordinate); SX_ERR_DEGENERATE (fewer than 3 points left after cleaning:
 *  duplicates only, all collinear); SX_ERR_INVALID_ARG for an outline that
 *  is not simple: two non-adjacent edges of the cleaned outline cross,
 *  touch, or come within the weld tolerance of each other (a bow-tie, a
 *  figure eight, a vertex on another edge, a pinch: two points closer than
 *  the tolerance that are not consecutive, which the cleaning does not weld
 *  and which would make the outline visit one place twice; split such an
 *  outline into its lobes yourself);
 *  SX_ERR_DEGENERATE for zero area, when no ear can be found in the
 *  precision available (not observed for simple outlines), or when no part
 *  survives (far beyond SX_HUGE, where the parts' areas round away);
 *  SX_ERR_NONFINITE when a part's mass properties would overflow sx_real
 *  (as sx_shape_validate refuses: an outline some 1e9 m across in the float
 *  build); SX_ERR_CAPACITY when more than part_capacity parts are needed
 *  (then *part_count receives the number needed). */
SX_API sx_status sx_decompose_polygon(const sx_vec2 *points, int count, void *scratch,
                                      size_t scratch_bytes, sx_shape *parts, int part_capacity,
                                      int *part_count, int *triangle_count);

/** As sx_decompose_polygon with an explicit weld tolerance for the cleaning
 *  (for outlines far smaller or larger than the default length scale; 0
 *  welds only exact duplicates and drops only exactly collinear points). A
 *  negative or non-finite tolerance is SX_ERR_INVALID_ARG. */
SX_API sx_status sx_decompose_polygon_ex(const sx_vec2 *points, int count, sx_real weld_tolerance,
                                         void *scratch, size_t scratch_bytes, sx_shape *parts,
                                         int part_capacity, int *part_count, int *triangle_count);

/** True if p lies inside the closed outline points[0..count-1] (any winding,
 *  concave allowed) by the nonzero winding rule, evaluated on the raw
 *  outline without decomposing it (crossing signs in a wider precision).
 *  Points exactly on an edge count as inside. For a self-intersecting
 *  outline this is the nonzero-winding region. NULL, count < 3 or any
 *  non-finite input gives false. */
SX_API bool sx_point_in_outline(const sx_vec2 *points, int count, sx_vec2 p);

/* ---- compound colliders ------------------------------------------------- */

/** One convex part of a compound: a shape in its own local frame, placed in
 *  the compound's frame by `offset`. */
typedef struct sx_compound_part {
    sx_shape shape;
    sx_xform offset;
} sx_compound_part;

/** A compound collider: a view of `count` parts that the caller owns (the
 *  compound copies nothing). Parts may overlap each other; the compound is
 *  their union. */
typedef struct sx_compound {
    const sx_compound_part *parts;
    int count;
} sx_compound;

/** A part with the given shape and offset. */
SX_API sx_compound_part sx_compound_part_make(sx_shape shape, sx_xform offset);

/** Where the compound functions (and a world holding the compound as a
 *  collider) place part `p` of a compound placed by x: x times the part's
 *  offset, the offset's rotation scaled to unit length first when it is off
 *  by more than rounding (sx_compound_validate accepts rotations up to 1e-3
 *  off; placed as given they would scale the part and make normals up to
 *  1e-3 too long). Rotations from sx_rot_make are used as they are. */
SX_API sx_xform sx_compound_part_placement(sx_xform x, const sx_compound_part *p);

/** SX_OK, or: SX_ERR_INVALID_ARG (NULL compound, count < 1, parts NULL, a
 *  part's rotation not unit length within 1e-3: within it, the part is
 *  placed with the rotation made unit, see sx_compound_part_placement);
 *  SX_ERR_NONFINITE (a
 *  non-finite offset); otherwise the first failing part's
 *  sx_shape_validate status. The functions below assume a valid compound
 *  (they never crash or produce NaN on a NULL or empty one: they answer
 *  false / 0 / an empty box). */
SX_API sx_status sx_compound_validate(const sx_compound *c);

/** World AABB of the compound placed by x: the union of its parts' AABBs.
 *  An empty or NULL compound gives the empty box at x.p (the origin when
 *  x.p is not finite). */
SX_API sx_aabb sx_compound_aabb(const sx_compound *c, sx_xform x);

/** Mass properties for a uniform density: mass = density x total area,
 *  centre = area-weighted centroid of the parts (in the compound frame), and
 *  rotational inertia about that centre (each part's own inertia moved by
 *  the parallel-axis theorem), summed in a wider precision. Overlapping parts
 *  count twice. Density 0 gives zero mass and inertia with the centre at the
 *  area centroid; negative or non-finite density, or an invalid compound,
 *  gives all zeros. */
SX_API sx_mass_data sx_compound_mass(const sx_compound *c, sx_real density);

/** True if any part of compound a (placed by xa) overlaps shape b (placed by
 *  xb); touching counts. */
SX_API bool sx_compound_overlap(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb);

/** True if any part of a overlaps any part of b; touching counts. */
SX_API bool sx_compound_overlap_compound(const sx_compound *a, sx_xform xa, const sx_compound *b,
                                         sx_xform xb);

/** True if the compound overlaps the shape (touching counts). When mtv is
 *  not NULL it receives a translation of the WHOLE compound that separates
 *  every part from b in one move (zero when nothing penetrates by more than
 *  SX_LINEAR_SLOP x 1e-3).
 *
 *  How: for a push direction d, the shifts along d at which a convex part
 *  pair overlaps form an interval. Starting from 0, the push walks to the
 *  end of the interval of whichever pair still penetrates (each pair's exit
 *  is exact for polygon pairs, from the support functions over the normals
 *  of their Minkowski difference, and bisected with sx_overlap to 1e-6
 *  relative for curved pairs; never shorter than the pair's own sx_mtv,
 *  which far from the origin rounds differently from the world-space
 *  supports), re-checking every pair after each step, since clearing one
 *  pair can run another part into b; a gap between intervals narrower than
 *  1% of the push (probed at 4 points for a pair that penetrates there) is
 *  stepped over. The directions tried: each penetrating pair's MTV
 *  direction, both signs of
 *  the edge normals of its parts, the corner direction meeting two pairs'
 *  MTVs at once (for the first 16 penetrating pairs), and 32 evenly spaced
 *  directions; the best is then refined by a pattern search over the angle
 *  down to about 0.01 degree. The shortest push found is returned.
 *
 *  Guarantee: after translating a by *mtv no part pair penetrates by more
 *  than SX_LINEAR_SLOP x 1e-3 (each is separated or touching), and moving
 *  slightly further (up to 1% more) normally keeps it so: only a grazing
 *  contact narrower than the probe spacing can be missed. The vector is the
 *  shortest found, not a proven global minimum (measured: within 1% of a
 *  brute-force minimum over 720 directions in 298 of 300 random U-vs-disc
 *  or box placements, at worst 5% longer). Cost: a few dozen clearing walks
 *  over all part pairs per penetrating query, so the boolean and manifold
 *  functions are the per-step path; this is for resolving deep overlaps.
 *  Should no direction settle (not observed for valid input), the fallback
 *  pushes along the deepest pair's MTV until the bounding boxes are apart,
 *  which also separates, up to the rounding of the boxes at their
 *  magnitude. */
SX_API bool sx_compound_mtv(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                            sx_vec2 *mtv);

/** As sx_compound_mtv, between two compounds: *mtv moves all of a. */
SX_API bool sx_compound_mtv_compound(const sx_compound *a, sx_xform xa, const sx_compound *b,
                                     sx_xform xb, sx_vec2 *mtv);

/** A manifold between one part of a compound and a shape (part_b 0) or one
 *  part of another compound. */
typedef struct sx_compound_manifold {
    sx_manifold manifold; /**< normal from the part of a towards b, world space */
    int part_a;           /**< index into a's parts */
    int part_b;           /**< index into b's parts (0 for a plain shape) */
} sx_compound_manifold;

/** One manifold per part pair that is touching or within `margin`
 *  (sx_collide_ex), in part order. Writes at most `capacity` entries and
 *  returns the number written (0 for NULL arguments or capacity < 1). */
SX_API int sx_compound_collide(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                               sx_real margin, sx_compound_manifold *out, int capacity);

/** As sx_compound_collide, between two compounds. */
SX_API int sx_compound_collide_compound(const sx_compound *a, sx_xform xa, const sx_compound *b,
                                        sx_xform xb, sx_real margin, sx_compound_manifold *out,
                                        int capacity);

/** Casts a ray against every part (sx_ray_cast) and reports the closest hit
 *  (lowest fraction; on a tie the lower part index). *part (may be NULL)
 *  receives its index, -1 on a miss. Semantics of the hit as sx_ray_cast. */
SX_API bool sx_compound_ray_cast(const sx_compound *c, sx_xform x, const sx_ray_input *ray,
                                 sx_ray_hit *out, int *part);

/** True if p (world) is inside or on any part (sx_contains_point). *part (may
 *  be NULL) receives the first such part's index, -1 when none. */
SX_API bool sx_compound_contains_point(const sx_compound *c, sx_xform x, sx_vec2 p, int *part);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_COMPOUND_H */
