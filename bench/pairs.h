/* sepax benchmarks — the shape pairs every engine is timed on, described once
 * as plain data (no engine types), so the C side (sepax) and the C++ side
 * (Box2D) build their own shapes from the very same numbers. Every stored
 * number is a float value (kept in a double): the float engines read it
 * without rounding, and the long double reference sees exactly the geometry
 * the engines were given. */
#ifndef SEPAX_BENCH_PAIRS_H
#define SEPAX_BENCH_PAIRS_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/** The shape kinds of the benchmark, in "pair function" order: a pair is
 *  named larger kind first (polygon-circle, never circle-polygon). */
typedef enum bench_kind {
    BENCH_CIRCLE = 0,
    BENCH_SEGMENT,
    BENCH_CAPSULE,
    BENCH_BOX,     /**< axis-aligned in its local frame, centred on the origin */
    BENCH_POLYGON, /**< random convex 3..8-gon, sharp corners */
    BENCH_ROUNDED, /**< random convex 3..8-gon with a rounding radius */
    BENCH_KIND_COUNT
} bench_kind;

/** Most core vertices of a benchmark shape (sepax and Box2D both allow 8). */
#define BENCH_MAX_VERTICES 8

/** A shape as a convex core (1 point, 2 segment ends, or a CCW polygon) plus
 *  a rounding radius, in the shape's local frame. Boxes also keep their half
 *  extents (the core is then the four corners). */
typedef struct bench_shape {
    int kind;
    int count;
    double v[BENCH_MAX_VERTICES][2];
    double radius;
    double hx, hy;
} bench_shape;

/** A rigid placement: the rotation is given as its cosine/sine pair (float
 *  values), not an angle, so every engine applies the same rotation. */
typedef struct bench_pose {
    double x, y, c, s;
} bench_pose;

typedef struct bench_pair {
    bench_shape a, b;
    bench_pose xa, xb;
    /** Penetration depth by the long double reference: > 0 overlap, < 0 the
     *  gap between the shapes. */
    double ref_depth;
} bench_pair;

/** splitmix64: same seed, same pairs on every machine. */
typedef struct bench_rng {
    uint64_t state;
} bench_rng;

bench_rng bench_rng_make(uint64_t seed);
/** Uniform double in [lo, hi). */
double bench_rng_range(bench_rng *rng, double lo, double hi);

/** Short name of a kind ("circle", "segment", ...). */
const char *bench_kind_name(int kind);

/** Fills pairs[0..n) with pairs of kind a (the larger kind) and b, about half
 *  of them overlapping (even indices overlap, odd ones are separated), with
 *  |reference depth| >= BENCH_MIN_ABS_DEPTH so that the overlap answer is
 *  unambiguous at float precision. Deterministic in `seed`. */
void bench_make_pairs(int kind_a, int kind_b, uint64_t seed, bench_pair *pairs, int n);

/** Pairs closer to touching than this (metres) are redrawn: within it the
 *  float engines may legitimately disagree with the reference about the
 *  overlap, which would blur what the benchmark reports. */
#define BENCH_MIN_ABS_DEPTH 1e-3

/* ---- the long double reference (bench/reference_depth.c) ---------------- */

/** Signed penetration depth of the placed pair in long double: the distance
 *  from the origin to the boundary of the Minkowski difference A - B,
 *  positive when the origin is inside (overlap), negative for a gap. Exact
 *  up to long double rounding for every kind: cores are convex polygons
 *  (points and segments included), whose penetration is the SAT minimum over
 *  the edge normals of both cores and whose separation is the least vertex-
 *  to-edge distance; the rounding radii add to it. */
double bench_ref_depth(const bench_shape *a, const bench_pose *xa, const bench_shape *b,
                       const bench_pose *xb);

/** The support value of the placed shape along the unit direction (ux, uy),
 *  measured from the pose's origin. */
double bench_ref_extent(const bench_shape *s, const bench_pose *x, double ux, double uy);

/* ---- the Box2D 2.4 peer (bench/peer_box2d.cpp) --------------------------- */

/** What a peer is asked to run on a set of pairs. */
typedef enum bench_fn {
    BENCH_FN_OVERLAP = 0,   /**< the boolean test */
    BENCH_FN_COLLIDE,       /**< the contact manifold in the engine's own form */
    BENCH_FN_COLLIDE_WORLD, /**< the manifold plus its world-space points and depths */
    BENCH_FN_COUNT
} bench_fn;

typedef struct bench_box2d_set bench_box2d_set;

/** True if Box2D 2.4 has the function for this pair of kinds. */
int bench_box2d_supports(int kind_a, int kind_b, int fn);
/** Builds Box2D shapes and transforms for the pairs (NULL when Box2D has no
 *  such shapes, i.e. capsules, or when a polygon does not survive Box2D's own
 *  hull builder unchanged). */
bench_box2d_set *bench_box2d_build(const bench_pair *pairs, int n);
void bench_box2d_free(bench_box2d_set *set);
/** Runs fn over all pairs `passes` times and returns a value that depends on
 *  every result (so no work can be skipped). */
double bench_box2d_run(const bench_box2d_set *set, int fn, int passes);
/** Box2D's penetration depth per pair: the deepest manifold point (its
 *  b2WorldManifold separation, negated), 0 when Box2D reports no point. */
void bench_box2d_depths(const bench_box2d_set *set, double *depth);
/** "Box2D x.y.z", the version of the linked library. */
void bench_box2d_version(char *out, int size);
/** Box2D's overlap answer per pair (b2TestOverlap). */
void bench_box2d_overlaps(const bench_box2d_set *set, int *overlap);

/* ---- the Box2D v3 peer (bench/box2d3/narrow.c) -------------------------- */

typedef struct bench_b3_set bench_b3_set;

/** Box2D v3's narrowphase on the benchmark pairs, one table per v3 build
 *  (bench/box2d3/b3_export.h): the same entry points as the Box2D 2.4 peer
 *  above, with BENCH_FN_COLLIDE = relative transform + b2Collide* (answer in
 *  A's frame) and BENCH_FN_COLLIDE_WORLD = the same moved to world space. */
typedef struct bench_b3_narrow {
    /** "Box2D x.y.z". */
    void (*version)(char *out, int size);
    /** True if v3 has the function for this pair of kinds. */
    int (*supports)(int kind_a, int kind_b, int fn);
    /** v3 shapes and transforms for the pairs; NULL when v3's hull builder
     *  changes a polygon or memory runs out. */
    bench_b3_set *(*build)(const bench_pair *pairs, int n);
    void (*free)(bench_b3_set *set);
    /** Runs fn over all pairs `passes` times; returns a checksum. */
    double (*run)(const bench_b3_set *set, int fn, int passes);
    /** Depth per pair: the deepest manifold point's separation, negated; 0
     *  without points (and on pairs v3 does not collide). */
    void (*depths)(const bench_b3_set *set, double *depth);
    /** Overlap answer per pair (b2ShapeDistance, as v3's sensors use it). */
    void (*overlaps)(const bench_b3_set *set, int *overlap);
} bench_b3_narrow;

/** The SSE2 build's (v3's default on x86-64; its narrowphase is scalar code,
 *  the same in every build). */
extern const bench_b3_narrow narrow_box2d3_sse2;
/** The portable scalar build's (-DBOX2D_DISABLE_SIMD). */
extern const bench_b3_narrow narrow_box2d3_scalar;
/** The AVX2 build's: call it only where the CPU has AVX2. */
extern const bench_b3_narrow narrow_box2d3_avx2;

/* ---- the Chipmunk 7 peer (bench/peer_chipmunk.cpp) ---------------------- */

typedef struct bench_chipmunk_set bench_chipmunk_set;

/** "Chipmunk x.y.z". */
void bench_chipmunk_version(char *out, int size);
/** Builds Chipmunk shapes (every kind exists there) placed by the poses. */
bench_chipmunk_set *bench_chipmunk_build(const bench_pair *pairs, int n);
void bench_chipmunk_free(bench_chipmunk_set *set);
/** cpShapesCollide over all pairs `passes` times; returns a checksum. */
double bench_chipmunk_run(const bench_chipmunk_set *set, int passes);
/** Chipmunk's depth per pair: minus the least contact distance, 0 without
 *  contact points. */
void bench_chipmunk_depths(const bench_chipmunk_set *set, double *depth);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_BENCH_PAIRS_H */
