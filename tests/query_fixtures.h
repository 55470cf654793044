/* sepax tests — fixtures shared by test_query.c and test_raycast.c: building
 * polygons from known CCW vertices, random shapes of every kind (points,
 * circles, segments, capsules, rotated offset boxes, convex and rounded
 * polygons), random placements, random points inside a shape (drawn from the
 * shape's own definition, independent of the queries under test) and the
 * tolerances of the property checks. */
#ifndef SEPAX_TEST_QUERY_FIXTURES_H
#define SEPAX_TEST_QUERY_FIXTURES_H

#include "test_support.h"

/* Tolerance of the random property checks, on shapes of size ~0.2..3 placed
 * within ~10 of the origin: a few operations' rounding at magnitude ~15
 * (float: 15 x 1.2e-7 ~ 2e-6 each), with a margin. */
#ifdef SX_DOUBLE
#define QF_TOL SX_R(1e-10)
#else
#define QF_TOL SX_R(1e-4)
#endif

static inline sx_shape qf_polygon(const sx_vec2 *points, int count, sx_real radius) {
    sx_hull hull;
    sx_shape s;
    int i;
    hull.count = count;
    for (i = 0; i < count; ++i)
        hull.points[i] = points[i];
    assert_int_equal(sx_polygon_from_hull(&hull, radius, &s), SX_OK);
    return s;
}

/* A box of half-extents hw x hh rounded by radius (polygon core). */
static inline sx_shape qf_rounded_box(sx_real hw, sx_real hh, sx_real radius) {
    sx_vec2 v[4];
    v[0] = sx_v2(-hw, -hh);
    v[1] = sx_v2(hw, -hh);
    v[2] = sx_v2(hw, hh);
    v[3] = sx_v2(-hw, hh);
    return qf_polygon(v, 4, radius);
}

static inline sx_xform qf_random_xform(sx_test_rng *rng) {
    return sx_xform_make(
        sx_v2(sx_test_rng_range(rng, -10.0, 10.0), sx_test_rng_range(rng, -10.0, 10.0)),
        sx_test_rng_range(rng, -3.2, 3.2));
}

static inline sx_vec2 qf_random_vec(sx_test_rng *rng, double lo, double hi) {
    return sx_v2(sx_test_rng_range(rng, lo, hi), sx_test_rng_range(rng, lo, hi));
}

/* Convex polygon: n points on an ellipse at sorted angles kept at least
 * 0.3 rad apart (so the builder's welding and collinearity checks never
 * fire), around a random local centre. */
static inline sx_shape qf_random_polygon(sx_test_rng *rng, sx_real radius) {
    sx_vec2 v[SX_MAX_POLYGON_VERTICES];
    int n = 3 + (int)(sx_test_rng_unit(rng) * (SX_MAX_POLYGON_VERTICES - 2));
    double step = 2.0 * 3.14159265358979 / n;
    double a0 = sx_test_rng_unit(rng) * step;
    double ax = 0.3 + 1.7 * sx_test_rng_unit(rng), ay = 0.3 + 1.7 * sx_test_rng_unit(rng);
    sx_vec2 c = qf_random_vec(rng, -1.0, 1.0);
    int i;
    if (n > SX_MAX_POLYGON_VERTICES) n = SX_MAX_POLYGON_VERTICES;
    step = 2.0 * 3.14159265358979 / n;
    for (i = 0; i < n; ++i) {
        double a = a0 + step * i + (step - 0.3) * 0.8 * sx_test_rng_unit(rng);
        v[i] = sx_v2((sx_real)((double)c.x + ax * cos(a)), (sx_real)((double)c.y + ay * sin(a)));
    }
    return qf_polygon(v, n, radius);
}

/* Kinds: 0 point, 1 circle, 2 segment, 3 capsule, 4 offset box, 5 polygon,
 * 6 rounded polygon, 7 rounded box. */
#define QF_KIND_COUNT 8

static inline sx_shape qf_random_shape_of_kind(sx_test_rng *rng, int kind) {
    sx_vec2 c = qf_random_vec(rng, -1.0, 1.0);
    switch (kind) {
    case 0: return sx_point_shape(c);
    case 1: return sx_circle_shape(c, sx_test_rng_range(rng, 0.2, 2.0));
    case 2: return sx_segment_shape(c, sx_add(c, qf_random_vec(rng, -3.0, 3.0)));
    case 3:
        return sx_capsule_shape(c, sx_add(c, qf_random_vec(rng, -3.0, 3.0)),
                                sx_test_rng_range(rng, 0.1, 1.0));
    case 4:
        return sx_offset_box_shape(sx_test_rng_range(rng, 0.2, 2.0),
                                   sx_test_rng_range(rng, 0.2, 2.0), c,
                                   sx_test_rng_range(rng, -3.2, 3.2));
    case 5: return qf_random_polygon(rng, SX_R(0.0));
    case 6: return qf_random_polygon(rng, sx_test_rng_range(rng, 0.05, 0.8));
    default:
        return qf_rounded_box(sx_test_rng_range(rng, 0.2, 2.0), sx_test_rng_range(rng, 0.2, 2.0),
                              sx_test_rng_range(rng, 0.05, 0.8));
    }
}

static inline sx_shape qf_random_shape(sx_test_rng *rng, int *kind) {
    *kind = (int)(sx_test_rng_unit(rng) * QF_KIND_COUNT);
    return qf_random_shape_of_kind(rng, *kind);
}

/* A uniformly random direction scaled by up to `r` (a point of the disc). */
static inline sx_vec2 qf_in_disc(sx_test_rng *rng, sx_real r) {
    double a = sx_test_rng_unit(rng) * 6.283185307179586;
    double k = sqrt(sx_test_rng_unit(rng)) * (double)r;
    return sx_v2((sx_real)(k * cos(a)), (sx_real)(k * sin(a)));
}

/* A local point of the closed shape, from its definition: disc around the
 * centre, point of the segment, segment point plus a disc, convex
 * combination of the vertices plus a disc. */
static inline sx_vec2 qf_local_sample(sx_test_rng *rng, const sx_shape *s) {
    switch (s->type) {
    case SX_SHAPE_CIRCLE: return sx_add(s->u.circle.center, qf_in_disc(rng, s->u.circle.radius));
    case SX_SHAPE_SEGMENT:
        return sx_lerp(s->u.segment.a, s->u.segment.b, (sx_real)sx_test_rng_unit(rng));
    case SX_SHAPE_CAPSULE:
        return sx_add(sx_lerp(s->u.capsule.a, s->u.capsule.b, (sx_real)sx_test_rng_unit(rng)),
                      qf_in_disc(rng, s->u.capsule.radius));
    default: {
        const sx_polygon *p = &s->u.polygon;
        double w[SX_MAX_POLYGON_VERTICES], sum = 0.0, x = 0.0, y = 0.0;
        int i;
        sx_vec2 q;
        for (i = 0; i < p->count; ++i) {
            /* Cubing sharpens the weights so samples reach the corners. */
            double r = sx_test_rng_unit(rng);
            w[i] = r * r * r;
            sum += w[i];
        }
        for (i = 0; i < p->count; ++i) {
            x += w[i] / sum * (double)p->vertices[i].x;
            y += w[i] / sum * (double)p->vertices[i].y;
        }
        q = sx_v2((sx_real)x, (sx_real)y);
        return sx_add(q, qf_in_disc(rng, p->radius));
    }
    }
}

/* The local centroid (segment and capsule: the midpoint). */
static inline sx_vec2 qf_local_center(const sx_shape *s) {
    switch (s->type) {
    case SX_SHAPE_CIRCLE: return s->u.circle.center;
    case SX_SHAPE_SEGMENT: return sx_lerp(s->u.segment.a, s->u.segment.b, SX_R(0.5));
    case SX_SHAPE_CAPSULE: return sx_lerp(s->u.capsule.a, s->u.capsule.b, SX_R(0.5));
    default: return s->u.polygon.centroid;
    }
}

static inline bool qf_is_solid(const sx_shape *s) {
    return !(s->type == SX_SHAPE_SEGMENT ||
             (s->type == SX_SHAPE_CIRCLE && s->u.circle.radius == SX_R(0.0)));
}

/* A hostile coordinate: NaN, infinity, zero, or any magnitude from 1e-38 to
 * 1e38 (clamped to the real type's range) of either sign. */
static inline sx_real qf_wild(sx_test_rng *rng) {
    double u = sx_test_rng_unit(rng);
    double v = (sx_test_rng_unit(rng) - 0.5) * pow(10.0, sx_test_rng_unit(rng) * 76.0 - 38.0);
    if (u < 0.02) return (sx_real)NAN;
    if (u < 0.04) return (sx_real)(u < 0.03 ? INFINITY : -INFINITY);
    if (u < 0.1) return SX_R(0.0);
    return (sx_real)v;
}

static inline sx_vec2 qf_wild_vec(sx_test_rng *rng) { return sx_v2(qf_wild(rng), qf_wild(rng)); }

/* A random shape with hostile coordinates and radius; the transform comes
 * from qf_wild too. */
static inline sx_shape qf_wild_shape(sx_test_rng *rng, sx_xform *x) {
    int kind, j;
    sx_shape s = qf_random_shape(rng, &kind);
    sx_real scale = qf_wild(rng);
    switch (s.type) {
    case SX_SHAPE_CIRCLE:
        s.u.circle.center = qf_wild_vec(rng);
        s.u.circle.radius = sx_absr(qf_wild(rng));
        break;
    case SX_SHAPE_SEGMENT:
        s.u.segment.a = qf_wild_vec(rng);
        s.u.segment.b = qf_wild_vec(rng);
        break;
    case SX_SHAPE_CAPSULE:
        s.u.capsule.a = qf_wild_vec(rng);
        s.u.capsule.b = qf_wild_vec(rng);
        s.u.capsule.radius = sx_absr(qf_wild(rng));
        break;
    default:
        for (j = 0; j < s.u.polygon.count; ++j) {
            s.u.polygon.vertices[j] = sx_scale(s.u.polygon.vertices[j], scale);
        }
        s.u.polygon.radius = sx_absr(qf_wild(rng));
        break;
    }
    *x = sx_xform_make(qf_wild_vec(rng), sx_test_rng_range(rng, -3.2, 3.2));
    return s;
}

#endif /* SEPAX_TEST_QUERY_FIXTURES_H */
