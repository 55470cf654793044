/* sepax — the narrowphase: for every pair of shapes, a boolean overlap test,
 * the minimum translation vector (MTV) by the separating axis theorem, the
 * contact manifold the solver needs, and the point, segment and ray queries.
 *
 * Every pair is solved in shape A's local frame: B is moved into A's frame
 * first (sx_xform_inv_mul), the work happens near the origin, and the results
 * are turned back to world space. That keeps precision when both shapes are
 * far from the world origin. Circles, segments and capsules are treated as
 * rounded convex cores (a point or a segment, plus a radius), and polygons as
 * convex cores plus their rounding radius, so every pair reduces to one of a
 * few core routines; cheap pairs (circle-circle, axis-aligned boxes) take fast
 * paths ahead of the general SAT. Nothing here allocates or keeps state.
 *
 * Conventions used throughout:
 * - "Touching counts": shapes whose boundaries meet overlap, with a zero MTV.
 * - The MTV is the shortest translation of A that separates it from B; it
 *   points away from B. sx_mtv(b, a) is exactly -sx_mtv(a, b).
 * - A manifold's normal is a unit vector from A towards B, the direction in
 *   which B must move to separate (so MTV = -normal * max depth). Depth is
 *   positive for overlap, negative for a gap.
 * - Non-finite transforms or shapes never crash and never produce NaN: the
 *   overlap and MTV tests answer false with a zero MTV, collide answers 0
 *   contacts. */
#ifndef SEPAX_COLLIDE_H
#define SEPAX_COLLIDE_H

#include "base.h"
#include "vecmath.h"
#include "shape.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- contact manifold --------------------------------------------------- */

/** The bit of a feature id set when B supplied the reference face: swapping
 *  the arguments of a pair toggles it (sx_collide). */
#define SX_FEATURE_ID_FLIPPED ((uint32_t)1 << 16)

/** Feature id of a manifold point: identifies which features of A and B
 *  produced it, so the solver can match a point across steps (warm starting).
 *  Layout: bits 0-7 the reference feature index, bits 8-15 the incident
 *  feature index, bit 16 (SX_FEATURE_ID_FLIPPED) set when B supplied the
 *  reference face. Stable for as long as the same features touch. */
#define SX_FEATURE_ID(ref_index, inc_index, flipped)                                               \
    ((uint32_t)((uint32_t)((ref_index)&0xFF) | ((uint32_t)((inc_index)&0xFF) << 8) |               \
                ((flipped) ? SX_FEATURE_ID_FLIPPED : (uint32_t)0)))

/** One contact point. */
typedef struct sx_manifold_point {
    /** World-space point midway between the two surfaces along the normal. */
    sx_vec2 point;
    /** Overlap along the normal, in metres: > 0 overlapping, < 0 a gap. */
    sx_real depth;
    /** Feature id (SX_FEATURE_ID). */
    uint32_t id;
} sx_manifold_point;

/** Up to two contact points sharing one normal. */
typedef struct sx_manifold {
    /** World-space unit normal from A towards B (zero when count is 0). */
    sx_vec2 normal;
    sx_manifold_point points[2];
    /** Number of valid points, 0..2. */
    int count;
} sx_manifold;

/* ---- generic entry points (dispatch through one table) ------------------ */

/** True if the shapes overlap; touching counts. The fast path: returns at the
 *  first separating axis and builds no manifold. Invalid or non-finite input
 *  answers false. */
SX_API bool sx_overlap(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb);

/** True if the shapes overlap (touching counts). When mtv is not NULL it
 *  receives the shortest translation of A that separates it from B (the zero
 *  vector when they do not overlap or merely touch). sx_mtv(b, ..., a, ...)
 *  gives exactly (bitwise) the negated vector: each pair is computed in one
 *  canonical order, chosen for same-type pairs from the transforms and then
 *  the shape values. Two identical inputs (same shape value, same transform)
 *  cannot be told apart, so both orders give the same vector. When no
 *  direction exists (coincident circle centres, coincident points) the MTV
 *  runs along the local +x axis of the canonical order's first shape.
 *  Computed by SAT over normalised axes:
 *  the edge normals of both polygons, the segment normal for segments and
 *  capsules, the centre-to-closest-feature axis for circles and rounded
 *  corners, and x/y only for two axis-aligned boxes. */
SX_API bool sx_mtv(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_vec2 *mtv);

/** The contact manifold of two overlapping or touching shapes: returns the
 *  number of points (0..2) and fills *out (out->count too). The normal is
 *  unit, from A to B; each point carries its depth (>= 0 here) and a feature
 *  id stable across frames. For polygon faces the reference face is the one
 *  of least penetration, with hysteresis: B's face is preferred over A's only
 *  when it is better by more than 0.02 x SX_LINEAR_SLOP (1e-4 m), so the
 *  manifold does not flip between two faces equal up to rounding. The
 *  deepest point's depth equals the MTV's length up to that hysteresis. (A
 *  world's contacts use 0.1 x SX_LINEAR_SLOP, Box2D's value: asked every
 *  step, a contact between two nearly equal faces then keeps its face and
 *  feature ids.) For rounded shapes whose cores are apart, a face normal
 *  within 0.01 x SX_LINEAR_SLOP of the exact direction's gap stands in for
 *  it (the points keep their exact depths). Swapped arguments give the
 *  mirrored manifold (same points and depths, normal negated, flipped bit of
 *  each id toggled): exactly so for two different types; two shapes of the
 *  same type are solved in the caller's order (A's face wins near-ties), and
 *  the manifold has points exactly when sx_overlap is true. */
SX_API int sx_collide(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                      sx_manifold *out);

/** As sx_collide, but also reports speculative points of shapes that are
 *  within `margin` metres of touching (depth >= -margin). The solver uses a
 *  margin of SX_SPECULATIVE_DISTANCE. margin < 0 or non-finite is taken as 0. */
SX_API int sx_collide_ex(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                         sx_real margin, sx_manifold *out);

/* ---- pair functions (for callers who know their types) ------------------ */

/* Each pair exists in one argument order below (the "larger" type first);
 * the generic functions above cover the other order. Semantics are those of
 * sx_overlap, sx_mtv and sx_collide_ex. Boxes are polygons; a point is a
 * circle of radius 0. */

SX_API bool sx_overlap_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb);
SX_API bool sx_mtv_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                           sx_vec2 *mtv);
SX_API int sx_collide_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                              sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_segment_circle(const sx_segment *a, sx_xform xa, const sx_circle *b,
                                      sx_xform xb);
SX_API bool sx_mtv_segment_circle(const sx_segment *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                                  sx_vec2 *mtv);
SX_API int sx_collide_segment_circle(const sx_segment *a, sx_xform xa, const sx_circle *b,
                                     sx_xform xb, sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb);
SX_API bool sx_mtv_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                            sx_vec2 *mtv);
SX_API int sx_collide_segments(const sx_segment *a, sx_xform xa, const sx_segment *b, sx_xform xb,
                               sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_capsule_circle(const sx_capsule *a, sx_xform xa, const sx_circle *b,
                                      sx_xform xb);
SX_API bool sx_mtv_capsule_circle(const sx_capsule *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                                  sx_vec2 *mtv);
SX_API int sx_collide_capsule_circle(const sx_capsule *a, sx_xform xa, const sx_circle *b,
                                     sx_xform xb, sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_capsule_segment(const sx_capsule *a, sx_xform xa, const sx_segment *b,
                                       sx_xform xb);
SX_API bool sx_mtv_capsule_segment(const sx_capsule *a, sx_xform xa, const sx_segment *b,
                                   sx_xform xb, sx_vec2 *mtv);
SX_API int sx_collide_capsule_segment(const sx_capsule *a, sx_xform xa, const sx_segment *b,
                                      sx_xform xb, sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb);
SX_API bool sx_mtv_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb,
                            sx_vec2 *mtv);
SX_API int sx_collide_capsules(const sx_capsule *a, sx_xform xa, const sx_capsule *b, sx_xform xb,
                               sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_polygon_circle(const sx_polygon *a, sx_xform xa, const sx_circle *b,
                                      sx_xform xb);
SX_API bool sx_mtv_polygon_circle(const sx_polygon *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                                  sx_vec2 *mtv);
SX_API int sx_collide_polygon_circle(const sx_polygon *a, sx_xform xa, const sx_circle *b,
                                     sx_xform xb, sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_polygon_segment(const sx_polygon *a, sx_xform xa, const sx_segment *b,
                                       sx_xform xb);
SX_API bool sx_mtv_polygon_segment(const sx_polygon *a, sx_xform xa, const sx_segment *b,
                                   sx_xform xb, sx_vec2 *mtv);
SX_API int sx_collide_polygon_segment(const sx_polygon *a, sx_xform xa, const sx_segment *b,
                                      sx_xform xb, sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_polygon_capsule(const sx_polygon *a, sx_xform xa, const sx_capsule *b,
                                       sx_xform xb);
SX_API bool sx_mtv_polygon_capsule(const sx_polygon *a, sx_xform xa, const sx_capsule *b,
                                   sx_xform xb, sx_vec2 *mtv);
SX_API int sx_collide_polygon_capsule(const sx_polygon *a, sx_xform xa, const sx_capsule *b,
                                      sx_xform xb, sx_real margin, sx_manifold *out);

SX_API bool sx_overlap_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb);
SX_API bool sx_mtv_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb,
                            sx_vec2 *mtv);
SX_API int sx_collide_polygons(const sx_polygon *a, sx_xform xa, const sx_polygon *b, sx_xform xb,
                               sx_real margin, sx_manifold *out);
/* ---- point queries ------------------------------------------------------ */

/* All point queries move p into the shape's local frame first. A NULL or
 * unusable shape (unknown type, NaN/Inf coordinate, negative or non-finite
 * radius, polygon count outside 3..SX_MAX_POLYGON_VERTICES), a non-finite
 * transform or a non-finite p is answered as documented per function, never
 * with a NaN. */

/** True if p (world) is inside the shape placed by x, or on its boundary
 *  (within SX_LINEAR_SLOP x 1e-3). Polygons use the cross-product test on
 *  their CCW edges; a rounded polygon contains the points within its radius
 *  of the core polygon. Segments (and points: circles of radius 0) contain
 *  only the points on them, within the same band. Unusable input: false. */
SX_API bool sx_contains_point(const sx_shape *s, sx_xform x, sx_vec2 p);

/** The point of segment a-b closest to p; *t (may be NULL) receives its
 *  parameter in [0, 1] (a + t (b - a)); at t 0 or 1 the end point is returned
 *  exactly. A zero-length segment gives a, t 0. A non-finite input gives a
 *  (the zero vector when a itself is not finite), t 0. */
SX_API sx_vec2 sx_closest_point_on_segment(sx_vec2 a, sx_vec2 b, sx_vec2 p, sx_real *t);

/** The point of the solid shape closest to p (world): p itself when p is
 *  inside or on the boundary (signed distance <= 0), else the closest
 *  boundary point. Segments and points have no interior: their closest point.
 *  Unusable input gives the zero vector. */
SX_API sx_vec2 sx_closest_point(const sx_shape *s, sx_xform x, sx_vec2 p);

/** Signed distance from p (world) to the shape's boundary: negative inside,
 *  never negative for segments and points (circles of radius 0). Rounded
 *  shapes measure to the rounded boundary (core distance minus radius).
 *  *boundary_point (may be NULL) receives the closest boundary point and
 *  *normal (may be NULL) the outward unit normal there, so that
 *  p = boundary_point + distance * normal. Where the direction is undefined
 *  a documented fallback is used: for p exactly on a segment's (or capsule
 *  core's) segment, the segment's left normal perp(b - a); at a circle's
 *  centre, or on a zero-length segment, world +x; for p exactly on a
 *  rounded polygon's core boundary, the normal of the edge of largest
 *  separation.
 *  Unusable input (or a point so far out that the arithmetic overflows
 *  sx_real) returns SX_REAL_MAX with zero vectors. */
SX_API sx_real sx_shape_distance_to_point(const sx_shape *s, sx_xform x, sx_vec2 p,
                                          sx_vec2 *boundary_point, sx_vec2 *normal);

/* ---- segment-segment intersection --------------------------------------- */

typedef enum sx_segment_relation {
    SX_SEGMENTS_DISJOINT = 0,       /**< not parallel (or a point), no common point */
    SX_SEGMENTS_INTERSECT,          /**< exactly one common point */
    SX_SEGMENTS_PARALLEL,           /**< parallel on distinct lines */
    SX_SEGMENTS_COLLINEAR_DISJOINT, /**< on one line, no common point */
    SX_SEGMENTS_OVERLAP,            /**< on one line, sharing a sub-segment (or one point) */
    SX_SEGMENTS_DEGENERATE          /**< an input was non-finite (or too large, see below) */
} sx_segment_relation;

typedef struct sx_segment_intersection {
    sx_segment_relation relation;
    /** INTERSECT: the point, with p = p1 + t (p2 - p1) = q1 + u (q2 - q1).
     *  OVERLAP: point = start of the shared part, t/u its parameters.
     *  t and u are in [0, 1]. Any other relation: all fields zero. */
    sx_vec2 point;
    sx_real t, u;
    /** OVERLAP: the shared sub-segment [overlap_start, overlap_end] along
     *  p1 -> p2 (equal for a single shared end point). INTERSECT: both equal
     *  point. */
    sx_vec2 overlap_start, overlap_end;
} sx_segment_intersection;

/** Intersects segments p1-p2 and q1-q2 by the parametric method: solves
 *  p1 + t r = q1 + u s with r = p2 - p1, s = q2 - q1 via the cross product
 *  r x s. Tolerances are relative (eps = 16 x SX_REAL_EPSILON), so the answer
 *  does not depend on the length unit:
 *  - |r x s| <= eps |r| |s| (the angle's sine below eps) means parallel.
 *    Parallel segments are collinear when both of q's end points lie within
 *    eps x L of p's line, L the largest of |r|, |s| and the distances from p1
 *    to q1 and q2; otherwise PARALLEL. Collinear segments project q's end
 *    points on r; the shared interval of parameters gives OVERLAP (a single
 *    shared end point counts, with overlap_start == overlap_end) or
 *    COLLINEAR_DISJOINT. The ends of the shared part are input end points,
 *    returned exactly.
 *  - Otherwise t and u are accepted within a slack of eps (scaled by the
 *    ratio of the segments' distance to their length) outside [0, 1], and
 *    within that slack of 0 or 1 they snap to it, so a touch at an end point
 *    (T-junction, shared corner) is INTERSECT and reports the end point
 *    exactly, not a recomputed point a rounding error away.
 *  - A zero-length segment is a point: INTERSECT when it lies on the other
 *    segment (its own parameter 0), else DISJOINT. Two zero-length segments
 *    INTERSECT only when exactly equal.
 *  - Any NaN/Inf coordinate, or coordinate differences beyond
 *    sqrt(SX_REAL_MAX) / 8 (where the cross products would overflow), gives
 *    DEGENERATE.
 *  out may be NULL. Returns the relation (also in out->relation). */
SX_API sx_segment_relation sx_intersect_segments(sx_vec2 p1, sx_vec2 p2, sx_vec2 q1, sx_vec2 q2,
                                                 sx_segment_intersection *out);

/* ---- ray casts ---------------------------------------------------------- */

/** A ray from `origin` along `translation`, tested up to `max_fraction` of the
 *  translation (usually 1: the segment origin .. origin + translation). */
typedef struct sx_ray_input {
    sx_vec2 origin;
    sx_vec2 translation;
    sx_real max_fraction;
} sx_ray_input;

/** Where a ray first meets a shape. */
typedef struct sx_ray_hit {
    sx_vec2 point;    /**< world hit point */
    sx_vec2 normal;   /**< world unit surface normal at the hit, facing the ray */
    sx_real fraction; /**< hit = origin + fraction * translation */
    bool hit;
} sx_ray_hit;

/** Casts a ray against a shape placed by x. Returns true and fills *out on a
 *  hit with fraction in [0, max_fraction]; on a miss *out is zeroed with
 *  hit = false (out may be NULL). The cast is exact for every shape (circles
 *  by the quadratic, polygons by clipping against the edge half-planes,
 *  capsules and rounded polygons against their offset edges and corner
 *  circles) and a ray that only grazes a shape hits it. A ray starting inside
 *  a solid shape, or on its boundary, hits at fraction 0 with the normal
 *  opposite to the ray direction. Segments are hit from either side (the
 *  normal is the segment normal facing the ray, even at fraction 0); a ray
 *  along a segment's own line hits its nearer end point with the normal
 *  opposite to the ray. A point (circle of radius 0) is hit only by a ray
 *  passing exactly through it. A zero translation, a NULL or unusable shape
 *  or ray, a non-finite input or max_fraction < 0 returns false, and so does
 *  a cast whose hit point would overflow sx_real. */
SX_API bool sx_ray_cast(const sx_shape *s, sx_xform x, const sx_ray_input *ray, sx_ray_hit *out);

/* ---- distance, shape cast and time of impact ----------------------------- */

/* These work on the convex cores of the shapes (a circle's centre, a
 * segment's or capsule's segment, a polygon's vertices) plus their radii, by
 * GJK on the Minkowski difference of the cores, in A's local frame. Shapes
 * are checked as the point queries check them: a NULL or unusable shape
 * (unknown type, negative or non-finite radius, polygon count outside
 * 3..SX_MAX_POLYGON_VERTICES) answers SX_ERR_INVALID_ARG, a NaN or infinite
 * coordinate, transform or motion SX_ERR_NONFINITE (also when placing one
 * shape in the other's frame, or carrying the answer back to world space,
 * overflows sx_real). On any error the output is zeroed. */

/** Most GJK iterations of one distance query; two cores of at most
 *  SX_MAX_POLYGON_VERTICES points converge long before (each iteration adds
 *  a new support pair or stops). */
#define SX_GJK_MAX_ITERATIONS 32

/** Most conservative-advancement iterations of one shape cast or time of
 *  impact. A pure translation reaches a flat face in one or two; a grazing
 *  pass along a curved surface, or a fast turn, needs more. At the cap the
 *  answer is the last fraction reached, which is never past contact (see
 *  sx_toi_state). */
#define SX_TOI_MAX_ITERATIONS 40

/** Where a shape cast stops short of contact while it iterates (the reported
 *  fraction is then extrapolated to the contact, see sx_shape_cast). */
#define SX_CAST_TARGET (SX_R(0.1) * SX_LINEAR_SLOP)

/** Tolerance of the stopping test of shape casts and times of impact: they
 *  stop once the gap is within this above the target separation. */
#define SX_TOI_TOLERANCE (SX_R(0.05) * SX_LINEAR_SLOP)

/** The distance between two shapes and their closest points. */
typedef struct sx_distance_output {
    /** World point of A closest to B, and of B closest to A (on the rounded
     *  surfaces). Overlapping shapes: both are one point in the overlap. */
    sx_vec2 point_a, point_b;
    /** World unit vector from A towards B (point_b - point_a over the
     *  distance when apart). Overlapping shapes: the contact normal of
     *  sx_collide (zero in the rare case it finds no point). */
    sx_vec2 normal;
    /** Gap in metres, >= 0; 0 when the shapes touch or overlap. */
    sx_real distance;
    /** GJK iterations used (1..SX_GJK_MAX_ITERATIONS). */
    int iterations;
    /** True when the shapes overlap beyond touching (or their cores cross). */
    bool overlap;
} sx_distance_output;

/** The distance between two shapes placed by xa and xb, with their closest
 *  points and the normal from A to B. Exact for every pair up to rounding:
 *  GJK finds the closest features of the cores, and the radii are taken off
 *  along the normal. Symmetric: swapping A and B swaps the points and
 *  negates the normal. SX_OK, or an error as described above. */
SX_API sx_status sx_shape_distance(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                   sx_distance_output *out);

/** Where a cast shape first touches another. */
typedef struct sx_shape_cast_output {
    /** World point of B's surface where A touches it. Starting overlapped:
     *  a point in the overlap. */
    sx_vec2 point;
    /** World unit normal of B's surface at the hit, facing A (against the
     *  cast). Starting overlapped: the direction of sx_mtv (A's way out), or
     *  against the translation when the MTV is zero. */
    sx_vec2 normal;
    /** A touches B after moving fraction x translation. */
    sx_real fraction;
    /** Conservative-advancement iterations used. */
    int iterations;
    bool hit;
} sx_shape_cast_output;

/** Sweeps shape A, placed by xa, along `translation` (world, metres; A does
 *  not turn) up to max_fraction of it, against shape B placed by xb. On a
 *  hit out->hit is true and out->fraction in [0, max_fraction] is where the
 *  rounded surfaces meet: the advancement stops SX_CAST_TARGET short of
 *  contact (within SX_TOI_TOLERANCE) and extrapolates the last gap along
 *  the normal, which is exact for a flat face and never past contact for a
 *  curved one (the gap of two convex shapes under translation is a convex
 *  function of the fraction). Shapes within SX_CAST_TARGET + SX_TOI_TOLERANCE
 *  of each other, or overlapping, at the start hit at fraction 0. A zero
 *  translation hits (at 0) only such shapes. After SX_TOI_MAX_ITERATIONS
 *  the last fraction reached is reported as a hit (it is short of contact).
 *  The work happens in A's frame, so shapes far from the origin keep their
 *  precision. Errors: SX_ERR_INVALID_ARG (NULL, unusable shape,
 *  max_fraction < 0), SX_ERR_NONFINITE (non-finite transform, translation
 *  or max_fraction). */
SX_API sx_status sx_shape_cast(const sx_shape *a, sx_xform xa, sx_vec2 translation,
                               sx_real max_fraction, const sx_shape *b, sx_xform xb,
                               sx_shape_cast_output *out);

/** The motion of a shape over a step: its frame turns about the point
 *  `local_center` (shape frame, usually a body's centre of mass), which
 *  moves in a straight line from c0 to c1 (world) while the angle goes
 *  linearly from angle0 to angle1 (radians; any difference, several turns
 *  included). At fraction t the frame is q = rot(angle0 + t (angle1 -
 *  angle0)), p = c0 + t (c1 - c0) - q local_center. */
typedef struct sx_motion {
    sx_vec2 local_center;
    sx_vec2 c0, c1;
    sx_real angle0, angle1;
} sx_motion;

/** How a time of impact ended. */
typedef enum sx_toi_state {
    SX_TOI_SEPARATED = 0,  /**< no contact over the motion: fraction 1 */
    SX_TOI_HIT,            /**< gap within target .. target + SX_TOI_TOLERANCE at fraction */
    SX_TOI_STARTS_CLOSE,   /**< gap already within target + tolerance (or overlap) at 0 */
    SX_TOI_ITERATION_LIMIT /**< SX_TOI_MAX_ITERATIONS used: fraction is the last
                                reached, where the gap is still above target */
} sx_toi_state;

/** The answer of sx_time_of_impact. */
typedef struct sx_toi_output {
    sx_toi_state state;
    /** In [0, 1]: the first fraction of the motions at which the gap comes
     *  down to the target (see state). */
    sx_real fraction;
    /** World unit normal from A to B at that fraction (zero when separated
     *  or starting overlapped). */
    sx_vec2 normal;
    /** World points of A and B closest to each other at that fraction. */
    sx_vec2 point_a, point_b;
    int iterations;
} sx_toi_output;

/** The first fraction of two motions at which shapes A and B come within
 *  `target` metres (>= 0; a world uses SX_LINEAR_SLOP, so a body stops just
 *  short of contact, never past it). Conservative advancement: at each
 *  iteration the gap d and the normal n come from sx_shape_distance's GJK, and the
 *  motions advance by (d - target) over a bound of how fast any point can
 *  close the gap along n (the relative velocity of the centres along n plus
 *  |turn| x the farthest core point from its centre, for each shape), so no
 *  step can pass the contact. The answer is never past the true time of
 *  impact (up to rounding); see sx_toi_state for the cases. Errors:
 *  SX_ERR_INVALID_ARG (NULL, unusable shape, target < 0),
 *  SX_ERR_NONFINITE (a non-finite motion or target). */
SX_API sx_status sx_time_of_impact(const sx_shape *a, const sx_motion *ma, const sx_shape *b,
                                   const sx_motion *mb, sx_real target, sx_toi_output *out);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_COLLIDE_H */
