/* sepax tests — randomized properties of the narrowphase, checked against the
 * independent long-double reference (tests/support/reference.c).
 *
 * For each of the 10 unordered pairs of {circle, segment, capsule, polygon}
 * (points are circles of radius 0, rounded polygons are polygons) we draw
 * PROP_PAIRS random pairs from a fixed seed: sizes 0.1..2 m, convex 3..8-gons
 * from jittered points on an ellipse (a third of them rounded), poses chosen
 * so that about half the pairs overlap. Every pair is checked in both
 * argument orders for: sx_mtv(b, a) == -sx_mtv(a, b) and agreement of sx_mtv's
 * answer with sx_overlap; overlap agreeing with the reference's sign outside a
 * thin band around touching; |MTV| equal to the reference depth; the
 * reference's escape distance along the MTV's direction equal to |MTV| (so
 * even where two directions tie, the one chosen must be a shortest escape);
 * the direction equal to the reference's where that is well conditioned;
 * A moved by MTV (1 + 1e-3) no longer overlapping and by
 * MTV (1 - 1e-3) still overlapping; the same MTV after translating both
 * shapes (by exact offsets) and, rotated, after rotating both about the
 * origin; the manifold's unit normal, depths and contact points; speculative
 * contacts (sx_collide_ex) of shapes within SX_SPECULATIVE_DISTANCE; and the
 * typed pair functions answering exactly as the generic dispatch.
 *
 * Positions are drawn on a 2^-12 m grid so that the translation offsets below
 * add exactly in float: the relative pose of the shapes is then identical, and
 * any difference in the MTV is the library losing precision far from the
 * origin. Violations are counted per check and the first few printed with
 * the full pair, so that a failure can be replayed; every count must be zero.
 * main() prints the accuracy table (depth and angle errors per pair type). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "reference.h"
#include "test_support.h"

#ifndef PROP_PAIRS
#define PROP_PAIRS 100000
#endif

/* Tolerances. Shapes are at most 2 m across and within ~4 m of the origin
 * (1 km in the translation check, where the grid keeps the sums exact).
 * LEN: depth agreement with the reference and every length comparison
 * (the largest depth errors measured are 7.1e-7 m in float and 1.1e-15 m in
 * double: the bounds leave a factor of 14 and 900; angle errors: 6.2e-6 and
 * 3.5e-14 rad against bounds of 1e-4 and 1e-10).
 * SIGN_BAND: overlap must agree with the reference's sign beyond this depth.
 * ANGLE: direction agreement where the reference direction is well
 * conditioned, i.e. its core distance and its tie gap both exceed COND (an
 * error of e in the shapes turns a direction by about e / COND there).
 * HAIR: the absolute extra push in the separation check, a few rounding
 * errors of a 4 m coordinate. MOVE_MIN: the separation check needs 1e-3 of
 * the depth to stand clear of rounding noise. */
#ifdef SX_DOUBLE
#define PROP_LEN_TOL 1e-12
#define PROP_SIGN_BAND 1e-12
#define PROP_ANGLE_TOL 1e-10
#define PROP_COND 1e-4
#define PROP_HAIR 1e-13
#define PROP_MOVE_MIN 1e-6
#define PROP_UNIT_TOL 1e-12
#else
#define PROP_LEN_TOL 1e-5
#define PROP_SIGN_BAND 1e-5
#define PROP_ANGLE_TOL 1e-4
#define PROP_COND 1e-2
#define PROP_HAIR 4e-6
#define PROP_MOVE_MIN 0.02
#define PROP_UNIT_TOL 1e-5
#endif

/* The manifold may keep A's reference face while B's is better by up to
 * 0.02 x SX_LINEAR_SLOP (collide.h), so its depth and normal may trail the
 * MTV by that much. */
#define PROP_HYSTERESIS (0.02 * (double)SX_LINEAR_SLOP)

/* The escape along the manifold's normal may exceed the MTV by more: for
 * rounded cores apart, a face normal within SX_FACE_CONTACT_TOLERANCE of
 * the exact direction stands in for it (collide.h), and with the reference
 * face chosen within the hysteresis the two add up; 0.1 x SX_LINEAR_SLOP,
 * the bound these checks have always held to. */
#define PROP_DIRECTION_SLACK (0.1 * (double)SX_LINEAR_SLOP)

/* The separation check moves A by MTV (1 +- PROP_MOVE_FRACTION). */
#define PROP_MOVE_FRACTION 1e-3

/* Positions lie on this grid (2^-12 m). */
#define PROP_GRID 4096.0

enum prop_kind { KIND_CIRCLE, KIND_SEGMENT, KIND_CAPSULE, KIND_POLYGON, KIND_COUNT };

static const char *const kind_names[KIND_COUNT] = {"circle", "segment", "capsule", "polygon"};

enum prop_check {
    CHECK_MTV_BOOL_IS_OVERLAP,
    CHECK_ANTISYMMETRY,
    CHECK_NO_HIT_ZERO_MTV,
    CHECK_SIGN,
    CHECK_DEPTH,
    CHECK_ESCAPE_ALONG_MTV,
    CHECK_ANGLE,
    CHECK_SEPARATES_AFTER_MTV,
    CHECK_OVERLAPS_BEFORE_MTV,
    CHECK_TRANSLATION,
    CHECK_ROTATION,
    CHECK_MANIFOLD_COUNT,
    CHECK_NORMAL_UNIT,
    CHECK_NORMAL_DIRECTION,
    CHECK_DEEPEST_POINT,
    CHECK_POINT_DEPTH,
    CHECK_DEEPEST_ON_SURFACES,
    CHECK_POINT_NOT_OUTSIDE,
    CHECK_SEPARATED_NO_CONTACT,
    CHECK_PAIR_FUNCTION,
    CHECK_SPECULATIVE,
    CHECK_COUNT
};

static const char *const check_names[CHECK_COUNT] = {
    "sx_mtv bool == sx_overlap",
    "sx_mtv(b,a) == -sx_mtv(a,b)",
    "no overlap -> zero mtv",
    "overlap agrees with reference sign",
    "|mtv| == reference depth",
    "reference escape along mtv == |mtv|",
    "mtv direction == reference direction",
    "A moved by mtv(1+1e-3) separates",
    "A moved by mtv(1-1e-3) still overlaps",
    "translation invariance",
    "rotation invariance",
    "collide count >= 1 on overlap",
    "manifold normal is unit",
    "manifold normal is a best escape (hysteresis)",
    "deepest point depth == |mtv| (hysteresis)",
    "point depth in [0, |mtv| + hysteresis]",
    "deepest point within depth/2 of both surfaces",
    "every point at most depth/2 outside either shape",
    "separated -> no contact",
    "pair function == generic dispatch",
    "speculative contact within the margin",
};

/* How many violations of a check to print in full per pair type. */
#define PROP_PRINT_LIMIT 3

/* Accuracy statistics of one pair type (both orders). */
typedef struct prop_stats {
    int depth_n, angle_n;
    long checks[CHECK_COUNT];
    long violations[CHECK_COUNT];
    long pairs, overlapping, separation_checked, manifolds_checked, speculative_checked;
    double max_depth_err, p99_depth_err, max_angle_err, p99_angle_err, max_escape_excess;
    double max_point_excess;
} prop_stats;

typedef struct prop_row {
    const char *a, *b;
    prop_stats s;
    bool done;
} prop_row;

#define PROP_TYPE_PAIRS 10
static prop_row s_rows[PROP_TYPE_PAIRS];

/* Error samples of the pair type being run (one per ordered overlapping
 * pair), sorted afterwards for the percentiles. */
static double s_depth_err[2 * PROP_PAIRS];
static double s_angle_err[2 * PROP_PAIRS];

/* One drawn pair: the shapes, their poses (angles kept so they can be turned
 * again exactly) and the reference shapes in world space. */
typedef struct prop_pair {
    sx_shape shape[2];
    sx_vec2 pos[2];
    double angle[2];
    sx_xform x[2];
    long index;
} prop_pair;

/* ---- drawing random shapes and poses ------------------------------------ */

static double unit(sx_test_rng *rng) { return sx_test_rng_unit(rng); }
static double uniform(sx_test_rng *rng, double lo, double hi) { return lo + (hi - lo) * unit(rng); }
static sx_real on_grid(double v) { return (sx_real)(floor(v * PROP_GRID + 0.5) / PROP_GRID); }
static sx_vec2 vec(double x, double y) { return sx_v2((sx_real)x, (sx_real)y); }

/* A random shape of the given kind, 0.1..2 m across, and the radius of a disc
 * about the local origin that holds it. */
static sx_shape draw_shape(sx_test_rng *rng, int kind, double *bound) {
    double size = uniform(rng, 0.1, 2.0);
    double cx = uniform(rng, -0.1, 0.1) * size, cy = uniform(rng, -0.1, 0.1) * size;
    double phi = uniform(rng, -3.14159265, 3.14159265);
    double ux = cos(phi), uy = sin(phi);
    double off = sqrt(cx * cx + cy * cy);
    switch (kind) {
    case KIND_CIRCLE: {
        double r = (sx_test_rng_next(rng) % 16u == 0u) ? 0.0 : 0.5 * size;
        *bound = off + r;
        return sx_circle_shape(vec(cx, cy), (sx_real)r);
    }
    case KIND_SEGMENT: {
        double h = 0.5 * size;
        *bound = off + h;
        return sx_segment_shape(vec(cx - h * ux, cy - h * uy), vec(cx + h * ux, cy + h * uy));
    }
    case KIND_CAPSULE: {
        double r = size * uniform(rng, 0.05, 0.45);
        double h = (sx_test_rng_next(rng) % 32u == 0u) ? 0.0 : 0.5 * size - r;
        *bound = off + h + r;
        return sx_capsule_shape(vec(cx - h * ux, cy - h * uy), vec(cx + h * ux, cy + h * uy),
                                (sx_real)r);
    }
    default: {
        for (;;) {
            sx_hull hull;
            sx_shape s;
            int n = 3 + (int)(sx_test_rng_next(rng) % 6u), i;
            double ax = 0.5 * size, ay = 0.5 * size * uniform(rng, 0.3, 1.0);
            double radius =
                (sx_test_rng_next(rng) % 3u == 0u) ? size * uniform(rng, 0.02, 0.2) : 0.0;
            double sector = 2.0 * 3.14159265358979 / (double)n;
            double start = uniform(rng, 0.0, sector);
            hull.count = n;
            for (i = 0; i < n; ++i) {
                /* Jitter inside the middle of each sector keeps the corners
                 * well apart and the polygon clearly convex. */
                double t = start + sector * ((double)i + uniform(rng, 0.2, 0.8));
                double ex = ax * cos(t), ey = ay * sin(t);
                hull.points[i] = vec(cx + ux * ex - uy * ey, cy + uy * ex + ux * ey);
            }
            if (sx_polygon_from_hull(&hull, (sx_real)radius, &s) == SX_OK) {
                *bound = off + ax + radius;
                return s;
            }
        }
    }
    }
}

/* Draws a pair: A near the origin, B at a random bearing from A, at a
 * distance up to `reach` x the sum of their bounding radii. */
static void draw_pair(sx_test_rng *rng, int kind_a, int kind_b, double reach, prop_pair *p) {
    double ba, bb, dist, psi;
    p->shape[0] = draw_shape(rng, kind_a, &ba);
    p->shape[1] = draw_shape(rng, kind_b, &bb);
    p->pos[0] = sx_v2(on_grid(uniform(rng, -2.0, 2.0)), on_grid(uniform(rng, -2.0, 2.0)));
    dist = (ba + bb) * uniform(rng, 0.0, reach);
    psi = uniform(rng, -3.14159265, 3.14159265);
    p->pos[1] = sx_v2(on_grid((double)p->pos[0].x + dist * cos(psi)),
                      on_grid((double)p->pos[0].y + dist * sin(psi)));
    p->angle[0] = uniform(rng, -3.14159265, 3.14159265);
    p->angle[1] = uniform(rng, -3.14159265, 3.14159265);
    p->x[0] = sx_xform_make(p->pos[0], (sx_real)p->angle[0]);
    p->x[1] = sx_xform_make(p->pos[1], (sx_real)p->angle[1]);
}

/* ---- reporting ---------------------------------------------------------- */

static void print_shape(const char *name, const sx_shape *s, sx_xform x) {
    int i;
    printf("    %s pose p=(%.9g, %.9g) q=(c %.9g, s %.9g): ", name, (double)x.p.x, (double)x.p.y,
           (double)x.q.c, (double)x.q.s);
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        printf("circle c=(%.9g, %.9g) r=%.9g\n", (double)s->u.circle.center.x,
               (double)s->u.circle.center.y, (double)s->u.circle.radius);
        break;
    case SX_SHAPE_SEGMENT:
        printf("segment a=(%.9g, %.9g) b=(%.9g, %.9g)\n", (double)s->u.segment.a.x,
               (double)s->u.segment.a.y, (double)s->u.segment.b.x, (double)s->u.segment.b.y);
        break;
    case SX_SHAPE_CAPSULE:
        printf("capsule a=(%.9g, %.9g) b=(%.9g, %.9g) r=%.9g\n", (double)s->u.capsule.a.x,
               (double)s->u.capsule.a.y, (double)s->u.capsule.b.x, (double)s->u.capsule.b.y,
               (double)s->u.capsule.radius);
        break;
    default:
        printf("polygon r=%.9g n=%d:", (double)s->u.polygon.radius, s->u.polygon.count);
        for (i = 0; i < s->u.polygon.count; ++i) {
            printf(" (%.9g, %.9g)", (double)s->u.polygon.vertices[i].x,
                   (double)s->u.polygon.vertices[i].y);
        }
        printf("\n");
        break;
    }
}

/* The context of one ordered check: which pair, which order, and the stats. */
typedef struct prop_ctx {
    const prop_pair *pair;
    int order; /* 0: (shape 0, shape 1); 1: swapped */
    prop_stats *stats;
    const sx_ref_result *ref;
} prop_ctx;

/* Counts one check, and on a violation prints the pair (first few only)
 * with the printf-style detail (formatted only then: the checks run
 * millions of times). */
static bool check(const prop_ctx *c, int which, bool ok, const char *format, ...) {
    c->stats->checks[which]++;
    if (ok) return true;
    if (c->stats->violations[which]++ < PROP_PRINT_LIMIT) {
        const prop_pair *p = c->pair;
        int ia = c->order, ib = 1 - c->order;
        va_list args;
        printf("  VIOLATION [%s] pair #%ld, order %s: ", check_names[which], p->index,
               c->order == 0 ? "(a, b)" : "(b, a)");
        va_start(args, format);
        vprintf(format, args);
        va_end(args);
        printf("\n");
        printf("    reference: depth %.12Lg dir (%.12Lg, %.12Lg) core distance %.6Lg tie gap "
               "%.6Lg%s\n",
               c->ref->depth, c->ref->dir_x, c->ref->dir_y, c->ref->core_distance, c->ref->tie_gap,
               c->ref->direction_defined ? "" : " (no unique direction)");
        print_shape("A", &p->shape[ia], p->x[ia]);
        print_shape("B", &p->shape[ib], p->x[ib]);
    }
    return false;
}

/* ---- the checks --------------------------------------------------------- */

static double max_d(double a, double b) { return a > b ? a : b; }

static double vlen(sx_vec2 v) {
    return sqrt((double)v.x * (double)v.x + (double)v.y * (double)v.y);
}

static sx_xform translated(sx_xform x, double ox, double oy) {
    x.p = sx_v2((sx_real)((double)x.p.x + ox), (sx_real)((double)x.p.y + oy));
    return x;
}

/* The pose turned by angle t about the world origin. */
static sx_xform rotated(sx_vec2 pos, double angle, double t) {
    double c = cos(t), s = sin(t);
    return sx_xform_make(
        vec(c * (double)pos.x - s * (double)pos.y, s * (double)pos.x + c * (double)pos.y),
        (sx_real)(angle + t));
}

static bool well_conditioned(const sx_ref_result *r) {
    return r->direction_defined && r->tie_gap > (long double)PROP_COND &&
           fabsl(r->core_distance) > (long double)PROP_COND;
}

/* The typed pair function of collide.h for (a, b) in its published order
 * (the larger type first): its overlap, MTV and manifold at margin 0.
 * Returns false when (a, b) is not in that order. */
static bool pair_function(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                          bool *overlap, bool *hit, sx_vec2 *mtv, int *count, sx_manifold *man) {
    const sx_polygon *pa = &a->u.polygon;
    const sx_capsule *ca = &a->u.capsule;
    const sx_segment *sa = &a->u.segment;
    switch (a->type * SX_SHAPE_TYPE_COUNT + b->type) {
    case SX_SHAPE_CIRCLE *SX_SHAPE_TYPE_COUNT + SX_SHAPE_CIRCLE:
        *overlap = sx_overlap_circles(&a->u.circle, xa, &b->u.circle, xb);
        *hit = sx_mtv_circles(&a->u.circle, xa, &b->u.circle, xb, mtv);
        *count = sx_collide_circles(&a->u.circle, xa, &b->u.circle, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_SEGMENT *SX_SHAPE_TYPE_COUNT + SX_SHAPE_CIRCLE:
        *overlap = sx_overlap_segment_circle(sa, xa, &b->u.circle, xb);
        *hit = sx_mtv_segment_circle(sa, xa, &b->u.circle, xb, mtv);
        *count = sx_collide_segment_circle(sa, xa, &b->u.circle, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_SEGMENT *SX_SHAPE_TYPE_COUNT + SX_SHAPE_SEGMENT:
        *overlap = sx_overlap_segments(sa, xa, &b->u.segment, xb);
        *hit = sx_mtv_segments(sa, xa, &b->u.segment, xb, mtv);
        *count = sx_collide_segments(sa, xa, &b->u.segment, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_CAPSULE *SX_SHAPE_TYPE_COUNT + SX_SHAPE_CIRCLE:
        *overlap = sx_overlap_capsule_circle(ca, xa, &b->u.circle, xb);
        *hit = sx_mtv_capsule_circle(ca, xa, &b->u.circle, xb, mtv);
        *count = sx_collide_capsule_circle(ca, xa, &b->u.circle, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_CAPSULE *SX_SHAPE_TYPE_COUNT + SX_SHAPE_SEGMENT:
        *overlap = sx_overlap_capsule_segment(ca, xa, &b->u.segment, xb);
        *hit = sx_mtv_capsule_segment(ca, xa, &b->u.segment, xb, mtv);
        *count = sx_collide_capsule_segment(ca, xa, &b->u.segment, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_CAPSULE *SX_SHAPE_TYPE_COUNT + SX_SHAPE_CAPSULE:
        *overlap = sx_overlap_capsules(ca, xa, &b->u.capsule, xb);
        *hit = sx_mtv_capsules(ca, xa, &b->u.capsule, xb, mtv);
        *count = sx_collide_capsules(ca, xa, &b->u.capsule, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_POLYGON *SX_SHAPE_TYPE_COUNT + SX_SHAPE_CIRCLE:
        *overlap = sx_overlap_polygon_circle(pa, xa, &b->u.circle, xb);
        *hit = sx_mtv_polygon_circle(pa, xa, &b->u.circle, xb, mtv);
        *count = sx_collide_polygon_circle(pa, xa, &b->u.circle, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_POLYGON *SX_SHAPE_TYPE_COUNT + SX_SHAPE_SEGMENT:
        *overlap = sx_overlap_polygon_segment(pa, xa, &b->u.segment, xb);
        *hit = sx_mtv_polygon_segment(pa, xa, &b->u.segment, xb, mtv);
        *count = sx_collide_polygon_segment(pa, xa, &b->u.segment, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_POLYGON *SX_SHAPE_TYPE_COUNT + SX_SHAPE_CAPSULE:
        *overlap = sx_overlap_polygon_capsule(pa, xa, &b->u.capsule, xb);
        *hit = sx_mtv_polygon_capsule(pa, xa, &b->u.capsule, xb, mtv);
        *count = sx_collide_polygon_capsule(pa, xa, &b->u.capsule, xb, SX_R(0.0), man);
        return true;
    case SX_SHAPE_POLYGON *SX_SHAPE_TYPE_COUNT + SX_SHAPE_POLYGON:
        *overlap = sx_overlap_polygons(pa, xa, &b->u.polygon, xb);
        *hit = sx_mtv_polygons(pa, xa, &b->u.polygon, xb, mtv);
        *count = sx_collide_polygons(pa, xa, &b->u.polygon, xb, SX_R(0.0), man);
        return true;
    default: return false;
    }
}

/* The typed pair function, where (a, b) is in its order, answers exactly as
 * the generic entry points (which dispatch to it). */
static void check_pair_function(const prop_ctx *c, const sx_shape *a, sx_xform xa,
                                const sx_shape *b, sx_xform xb, bool ov, bool hit, sx_vec2 m) {
    sx_manifold man, gen;
    sx_vec2 pm = sx_v2_zero();
    bool pov = false, phit = false;
    int pn = 0, gn;
    memset(&man, 0, sizeof man);
    memset(&gen, 0, sizeof gen);
    if (!pair_function(a, xa, b, xb, &pov, &phit, &pm, &pn, &man)) return;
    gn = sx_collide(a, xa, b, xb, &gen);
    check(c, CHECK_PAIR_FUNCTION,
          pov == ov && phit == hit && pm.x == m.x && pm.y == m.y && pn == gn &&
              man.normal.x == gen.normal.x && man.normal.y == gen.normal.y &&
              (pn < 1 || man.points[0].depth == gen.points[0].depth),
          "pair function: overlap %d mtv %d (%.9g, %.9g) %d points; generic: overlap %d mtv %d "
          "(%.9g, %.9g) %d points",
          (int)pov, (int)phit, (double)pm.x, (double)pm.y, pn, (int)ov, (int)hit, (double)m.x,
          (double)m.y, gn);
}

/* Shapes apart by less than the speculative distance: sx_collide_ex with
 * that margin reports them, its deepest (least negative) depth is minus the
 * reference gap and its normal is a best separating direction, both up to
 * the reference-face hysteresis. */
static void check_speculative(const prop_ctx *c, const sx_shape *a, sx_xform xa, const sx_shape *b,
                              sx_xform xb, const sx_ref_shape *pa, const sx_ref_shape *pb) {
    double depth = (double)c->ref->depth, deepest = -1e30, along;
    sx_manifold man;
    int n, i;
    bool ok;
    memset(&man, 0, sizeof man);
    n = sx_collide_ex(a, xa, b, xb, SX_SPECULATIVE_DISTANCE, &man);
    c->stats->speculative_checked++;
    for (i = 0; i < n && i < 2; ++i) {
        if ((double)man.points[i].depth > deepest) deepest = (double)man.points[i].depth;
    }
    along =
        (double)sx_ref_depth_along(pa, pb, -(long double)man.normal.x, -(long double)man.normal.y);
    ok = n >= 1 && n <= 2 && n == man.count && fabs(vlen(man.normal) - 1.0) <= PROP_UNIT_TOL &&
         fabs(deepest - depth) <= PROP_HYSTERESIS + PROP_LEN_TOL &&
         along <= depth + PROP_DIRECTION_SLACK + PROP_LEN_TOL;
    check(c, CHECK_SPECULATIVE, ok,
          "gap %.9g: collide_ex gave %d points, deepest depth %.9g, normal (%.9g, %.9g), reference "
          "gap along it %.9g",
          -depth, n, deepest, (double)man.normal.x, (double)man.normal.y, -along);
}

/* Checks the ordered pair (A, B) = (shape[o], shape[1 - o]); `ref` is the
 * reference answer for that order and pa, pb the placed reference shapes. */
static void check_ordered(const prop_pair *p, int o, const sx_ref_shape *pa, const sx_ref_shape *pb,
                          const sx_ref_result *ref, prop_stats *st) {
    static const double offsets[3][2] = {{37.5, -12.25}, {1000.0, -250.0}, {-1000.0, 1000.0}};
    const sx_shape *a = &p->shape[o], *b = &p->shape[1 - o];
    sx_xform xa = p->x[o], xb = p->x[1 - o];
    prop_ctx c;
    sx_vec2 m = sx_v2(SX_R(9.0), SX_R(9.0)), m2 = sx_v2(SX_R(9.0), SX_R(9.0));
    bool ov = sx_overlap(a, xa, b, xb);
    bool hit = sx_mtv(a, xa, b, xb, &m);
    bool hit2 = sx_mtv(b, xb, a, xa, &m2);
    double depth = (double)ref->depth, mlen = vlen(m);
    int i, k;
    c.pair = p;
    c.order = o;
    c.stats = st;
    c.ref = ref;

    check(&c, CHECK_MTV_BOOL_IS_OVERLAP, ov == hit, "sx_overlap %d, sx_mtv %d", (int)ov, (int)hit);
    check(&c, CHECK_ANTISYMMETRY, hit2 == hit && m2.x == -m.x && m2.y == -m.y,
          "mtv(a,b) (%.9g, %.9g) %d, mtv(b,a) (%.9g, %.9g) %d", (double)m.x, (double)m.y, (int)hit,
          (double)m2.x, (double)m2.y, (int)hit2);
    if (!hit) {
        check(&c, CHECK_NO_HIT_ZERO_MTV, m.x == SX_R(0.0) && m.y == SX_R(0.0),
              "no overlap but mtv (%.9g, %.9g)", (double)m.x, (double)m.y);
    }
    if (depth > PROP_SIGN_BAND || depth < -PROP_SIGN_BAND) {
        check(&c, CHECK_SIGN, hit == (depth > 0.0), "reference depth %.9g, sx_mtv says %s", depth,
              hit ? "overlap" : "apart");
    }

    if (!hit && depth < -PROP_SIGN_BAND) {
        sx_manifold man;
        int n = sx_collide(a, xa, b, xb, &man);
        check(&c, CHECK_SEPARATED_NO_CONTACT, n == 0, "collide gave %d points for a gap of %.9g", n,
              -depth);
        if (depth > -0.9 * (double)SX_SPECULATIVE_DISTANCE)
            check_speculative(&c, a, xa, b, xb, pa, pb);
    }
    check_pair_function(&c, a, xa, b, xb, ov, hit, m);
    if (!hit || !(depth > PROP_SIGN_BAND)) return;
    st->overlapping++;

    /* Depth and direction against the reference. */
    {
        double err = fabs(mlen - depth);
        s_depth_err[st->depth_n++] = err;
        check(&c, CHECK_DEPTH, err <= PROP_LEN_TOL, "|mtv| %.12g, reference %.12g (error %.3g)",
              mlen, depth, err);
    }
    if (mlen > 0.0) {
        double along = (double)sx_ref_depth_along(pa, pb, (long double)m.x, (long double)m.y);
        double excess = along - depth;
        if (excess > st->max_escape_excess) st->max_escape_excess = excess;
        check(&c, CHECK_ESCAPE_ALONG_MTV, fabs(along - mlen) <= PROP_LEN_TOL,
              "reference escape along mtv %.12g, |mtv| %.12g", along, mlen);
        if (well_conditioned(ref)) {
            double ang = (double)sx_ref_angle_between((long double)m.x, (long double)m.y,
                                                      ref->dir_x, ref->dir_y);
            s_angle_err[st->angle_n++] = ang;
            check(&c, CHECK_ANGLE, ang <= PROP_ANGLE_TOL,
                  "mtv (%.9g, %.9g) is %.3g rad off the reference", (double)m.x, (double)m.y, ang);
        }
    }

    /* Moving A by its MTV separates; by slightly less it does not. */
    if (mlen > PROP_MOVE_MIN) {
        double s1 = 1.0 + PROP_MOVE_FRACTION + PROP_HAIR / mlen, s2 = 1.0 - PROP_MOVE_FRACTION;
        sx_xform x1 = translated(xa, s1 * (double)m.x, s1 * (double)m.y);
        sx_xform x2 = translated(xa, s2 * (double)m.x, s2 * (double)m.y);
        st->separation_checked++;
        check(&c, CHECK_SEPARATES_AFTER_MTV, !sx_overlap(a, x1, b, xb), "mtv (%.9g, %.9g)",
              (double)m.x, (double)m.y);
        check(&c, CHECK_OVERLAPS_BEFORE_MTV, sx_overlap(a, x2, b, xb), "mtv (%.9g, %.9g)",
              (double)m.x, (double)m.y);
    }

    /* Translating both shapes by an exact offset keeps the MTV. */
    for (k = 0; k < 3; ++k) {
        sx_vec2 mo = sx_v2_zero();
        bool ho = sx_mtv(a, translated(xa, offsets[k][0], offsets[k][1]), b,
                         translated(xb, offsets[k][0], offsets[k][1]), &mo);
        double dlen = fabs(vlen(mo) - mlen);
        double dvec = vlen(sx_v2(mo.x - m.x, mo.y - m.y));
        bool ok = ho && dlen <= PROP_LEN_TOL && (!well_conditioned(ref) || dvec <= PROP_LEN_TOL);
        check(&c, CHECK_TRANSLATION, ok,
              "offset (%g, %g): mtv (%.9g, %.9g) vs (%.9g, %.9g) at origin", offsets[k][0],
              offsets[k][1], (double)mo.x, (double)mo.y, (double)m.x, (double)m.y);
    }

    /* Turning both poses about the origin turns the MTV. */
    {
        const double t = 0.7;
        sx_vec2 mr = sx_v2_zero();
        bool hr = sx_mtv(a, rotated(p->pos[o], p->angle[o], t), b,
                         rotated(p->pos[1 - o], p->angle[1 - o], t), &mr);
        double ex = cos(t) * (double)m.x - sin(t) * (double)m.y;
        double ey = sin(t) * (double)m.x + cos(t) * (double)m.y;
        double dlen = fabs(vlen(mr) - mlen);
        double dvec = sqrt(((double)mr.x - ex) * ((double)mr.x - ex) +
                           ((double)mr.y - ey) * ((double)mr.y - ey));
        bool ok = hr && dlen <= PROP_LEN_TOL &&
                  (!well_conditioned(ref) || dvec <= PROP_LEN_TOL + mlen * PROP_ANGLE_TOL);
        check(&c, CHECK_ROTATION, ok, "turned mtv (%.9g, %.9g), expected (%.9g, %.9g)",
              (double)mr.x, (double)mr.y, ex, ey);
    }

    /* The manifold. */
    {
        sx_manifold man;
        int n;
        memset(&man, 0, sizeof man);
        n = sx_collide(a, xa, b, xb, &man);
        if (!check(&c, CHECK_MANIFOLD_COUNT, n >= 1 && n <= 2 && n == man.count,
                   "collide returned %d, out->count %d", n, man.count)) {
            return;
        }
        st->manifolds_checked++;
        {
            double nl = vlen(man.normal), deepest = -1e30, da_deep = 0.0, db_deep = 0.0;
            double along = (double)sx_ref_depth_along(pa, pb, -(long double)man.normal.x,
                                                      -(long double)man.normal.y);
            check(&c, CHECK_NORMAL_UNIT, fabs(nl - 1.0) <= PROP_UNIT_TOL,
                  "normal (%.9g, %.9g) length %.12g", (double)man.normal.x, (double)man.normal.y,
                  nl);
            check(&c, CHECK_NORMAL_DIRECTION, along <= mlen + PROP_DIRECTION_SLACK + PROP_LEN_TOL,
                  "escape along -normal (%.9g, %.9g) is %.9g, |mtv| %.9g", (double)man.normal.x,
                  (double)man.normal.y, along, mlen);
            for (i = 0; i < n; ++i) {
                const sx_manifold_point *mp = &man.points[i];
                double d = (double)mp->depth;
                double da = (double)sx_ref_distance_to_point(a, xa, (long double)mp->point.x,
                                                             (long double)mp->point.y, NULL, NULL);
                double db = (double)sx_ref_distance_to_point(b, xb, (long double)mp->point.x,
                                                             (long double)mp->point.y, NULL, NULL);
                if (d > deepest) {
                    deepest = d;
                    da_deep = da;
                    db_deep = db;
                }
                check(&c, CHECK_POINT_DEPTH,
                      d >= -PROP_LEN_TOL && d <= mlen + PROP_HYSTERESIS + PROP_LEN_TOL,
                      "point %d depth %.9g, |mtv| %.9g", i, d, mlen);
                check(&c, CHECK_POINT_NOT_OUTSIDE,
                      da <= 0.5 * d + PROP_HYSTERESIS + PROP_LEN_TOL &&
                          db <= 0.5 * d + PROP_HYSTERESIS + PROP_LEN_TOL,
                      "point %d (%.9g, %.9g) depth %.9g: signed distance to A %.9g, to B %.9g", i,
                      (double)mp->point.x, (double)mp->point.y, d, da, db);
            }
            check(&c, CHECK_DEEPEST_POINT, fabs(deepest - mlen) <= PROP_HYSTERESIS + PROP_LEN_TOL,
                  "deepest point %.9g, |mtv| %.9g", deepest, mlen);
            {
                /* The deepest point is exact (up to the hysteresis): it lies
                 * half its depth from each surface. */
                double excess = max_d(fabs(da_deep), fabs(db_deep)) - 0.5 * deepest;
                if (excess > st->max_point_excess) st->max_point_excess = excess;
                check(&c, CHECK_DEEPEST_ON_SURFACES, excess <= PROP_HYSTERESIS + PROP_LEN_TOL,
                      "deepest point depth %.9g: signed distance to A %.9g, to B %.9g", deepest,
                      da_deep, db_deep);
            }
        }
    }
}

static int compare_double(const void *x, const void *y) {
    double a = *(const double *)x, b = *(const double *)y;
    return a < b ? -1 : (a > b ? 1 : 0);
}

static void summarize(double *v, int n, double *max, double *p99) {
    *max = 0.0;
    *p99 = 0.0;
    if (n == 0) return;
    qsort(v, (size_t)n, sizeof *v, compare_double);
    *max = v[n - 1];
    *p99 = v[(int)(0.99 * (double)(n - 1))];
}

/* The pair types: kinds, and the reach (B is drawn within reach x the sum of
 * the bounding radii from A) that makes about half of them overlap, measured
 * with the reference (thin shapes need B closer than round ones). */
static const struct {
    int a, b;
    double reach;
} pair_types[PROP_TYPE_PAIRS] = {
    {KIND_CIRCLE, KIND_CIRCLE, 1.70},   {KIND_SEGMENT, KIND_CIRCLE, 1.12},
    {KIND_SEGMENT, KIND_SEGMENT, 0.57}, {KIND_CAPSULE, KIND_CIRCLE, 1.47},
    {KIND_CAPSULE, KIND_SEGMENT, 0.97}, {KIND_CAPSULE, KIND_CAPSULE, 1.29},
    {KIND_POLYGON, KIND_CIRCLE, 1.46},  {KIND_POLYGON, KIND_SEGMENT, 0.94},
    {KIND_POLYGON, KIND_CAPSULE, 1.25}, {KIND_POLYGON, KIND_POLYGON, 1.26},
};

/* Runs PROP_PAIRS pairs of one type and asserts every check held. */
static void run_pair_type(int row) {
    prop_row *r = &s_rows[row];
    int ka = pair_types[row].a, kb = pair_types[row].b;
    double reach = pair_types[row].reach;
    prop_stats *st = &r->s;
    sx_test_rng rng = sx_test_rng_make(0x5E9A0000ull + (uint64_t)row);
    long i;
    int k;
    bool all_ok = true;
    memset(st, 0, sizeof *st);
    r->a = kind_names[ka];
    r->b = kind_names[kb];
    for (i = 0; i < PROP_PAIRS; ++i) {
        prop_pair p;
        sx_ref_shape placed[2];
        sx_ref_result ref, ref_swapped;
        draw_pair(&rng, ka, kb, reach, &p);
        p.index = i;
        assert_true(sx_ref_place(&p.shape[0], p.x[0], &placed[0]));
        assert_true(sx_ref_place(&p.shape[1], p.x[1], &placed[1]));
        assert_true(sx_ref_penetration_placed(&placed[0], &placed[1], &ref));
        ref_swapped = ref;
        ref_swapped.dir_x = -ref.dir_x;
        ref_swapped.dir_y = -ref.dir_y;
        ref_swapped.core_distance = ref.core_distance;
        st->pairs++;
        check_ordered(&p, 0, &placed[0], &placed[1], &ref, st);
        check_ordered(&p, 1, &placed[1], &placed[0], &ref_swapped, st);
    }
    summarize(s_depth_err, st->depth_n, &st->max_depth_err, &st->p99_depth_err);
    summarize(s_angle_err, st->angle_n, &st->max_angle_err, &st->p99_angle_err);
    r->done = true;
    printf("  %s-%s: %ld pairs x 2 orders, %.1f%% overlapping; depth error max %.3g p99 %.3g; "
           "angle error max %.3g p99 %.3g rad (%d directions); %ld speculative pairs\n",
           r->a, r->b, st->pairs, 100.0 * (double)st->overlapping / (2.0 * (double)st->pairs),
           st->max_depth_err, st->p99_depth_err, st->max_angle_err, st->p99_angle_err, st->angle_n,
           st->speculative_checked);
    for (k = 0; k < CHECK_COUNT; ++k) {
        if (st->violations[k] != 0) {
            printf("  %s-%s: %ld of %ld checks violated: %s\n", r->a, r->b, st->violations[k],
                   st->checks[k], check_names[k]);
            all_ok = false;
        }
    }
    assert_true(all_ok);
    /* Checks that ran too rarely would prove nothing: a third to two thirds
     * of the pairs overlap. */
    assert_true(3 * st->overlapping > 2 * st->pairs);
    assert_true(3 * st->overlapping < 4 * st->pairs);
    /* Shapes within the speculative distance are rarer (about 1 %). */
    assert_true(st->speculative_checked > PROP_PAIRS / 1000);
}

static void circle_circle_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(0);
}
static void segment_circle_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(1);
}
static void segment_segment_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(2);
}
static void capsule_circle_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(3);
}
static void capsule_segment_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(4);
}
static void capsule_capsule_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(5);
}
static void polygon_circle_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(6);
}
static void polygon_segment_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(7);
}
static void polygon_capsule_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(8);
}
static void polygon_polygon_properties_hold_on_random_pairs(void **state) {
    (void)state;
    run_pair_type(9);
}

static void print_table(void) {
    int i;
    printf("\nnarrowphase accuracy against the long-double reference (%s build, %d pairs per type, "
           "both orders)\n",
           sx_real_is_double() ? "double" : "float", PROP_PAIRS);
    printf(
        "| pair | overlapping | max depth error (m) | p99 depth error (m) | max angle error (rad) "
        "| p99 angle error (rad) | max escape excess (m) | max deepest-point offset (m) |\n");
    printf("|---|---|---|---|---|---|---|---|\n");
    for (i = 0; i < PROP_TYPE_PAIRS; ++i) {
        const prop_row *r = &s_rows[i];
        if (!r->done) continue;
        printf("| %s-%s | %.1f%% | %.3g | %.3g | %.3g | %.3g | %.3g | %.3g |\n", r->a, r->b,
               100.0 * (double)r->s.overlapping / (2.0 * (double)r->s.pairs), r->s.max_depth_err,
               r->s.p99_depth_err, r->s.max_angle_err, r->s.p99_angle_err, r->s.max_escape_excess,
               r->s.max_point_excess);
    }
    printf("(angle errors over pairs whose reference direction is well conditioned: core distance "
           "and tie gap > %g m; escape excess: how much farther the reference must move A along "
           "the MTV's direction than along the best one; deepest-point offset: how much farther "
           "than depth/2 the manifold's deepest point lies from either surface)\n\n",
           PROP_COND);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circle_circle_properties_hold_on_random_pairs),
        cmocka_unit_test(segment_circle_properties_hold_on_random_pairs),
        cmocka_unit_test(segment_segment_properties_hold_on_random_pairs),
        cmocka_unit_test(capsule_circle_properties_hold_on_random_pairs),
        cmocka_unit_test(capsule_segment_properties_hold_on_random_pairs),
        cmocka_unit_test(capsule_capsule_properties_hold_on_random_pairs),
        cmocka_unit_test(polygon_circle_properties_hold_on_random_pairs),
        cmocka_unit_test(polygon_segment_properties_hold_on_random_pairs),
        cmocka_unit_test(polygon_capsule_properties_hold_on_random_pairs),
        cmocka_unit_test(polygon_polygon_properties_hold_on_random_pairs),
    };
    int failed = cmocka_run_group_tests_name("collide_properties", tests, sx_test_group_setup,
                                             sx_test_group_teardown);
    print_table();
    return failed;
}
