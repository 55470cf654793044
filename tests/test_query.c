/* sepax tests — point queries (containment, closest point, signed distance)
 * and the segment-segment intersection: analytic cases for every shape on
 * rotated, translated placements (inside, outside, on the boundary, at
 * vertices and rounded corners), every relation of two segments, hostile
 * input, and random properties with fixed seeds checked against points drawn
 * from the shapes' own definitions. */
#include <float.h>
#include <math.h>

#include "query_fixtures.h"

#define EPS SX_TEST_EPS

/* A placement away from the origin and turned, used by the analytic cases:
 * local coordinates are given, world ones derived. */
static sx_xform placed(void) { return sx_xform_make(sx_v2(SX_R(3.0), SX_R(-2.0)), SX_R(0.7)); }

/* A quarter turn with an exact (0, 1) rotation: points on a boundary or at a
 * centre stay exactly there after the transform, so the fallback normals
 * (defined only at exact positions) can be checked. */
static sx_xform placed_exactly(void) {
    sx_xform x;
    x.p = sx_v2(SX_R(3.0), SX_R(-2.0));
    x.q.c = SX_R(0.0);
    x.q.s = SX_R(1.0);
    return x;
}

static sx_vec2 w(sx_xform x, double lx, double ly) {
    return sx_xform_point(x, sx_v2((sx_real)lx, (sx_real)ly));
}

static sx_vec2 wdir(sx_xform x, double lx, double ly) {
    return sx_xform_vector(x, sx_v2((sx_real)lx, (sx_real)ly));
}

/* ---- contains_point ----------------------------------------------------- */

static void circle_contains_inside_and_boundary_but_not_outside(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_circle_shape(sx_v2(SX_R(1.0), SX_R(2.0)), SX_R(1.5));
    (void)state;
    assert_true(sx_contains_point(&s, x, w(x, 1.0, 2.0)));
    assert_true(sx_contains_point(&s, x, w(x, 2.5, 2.0)));
    assert_true(sx_contains_point(&s, x, w(x, 1.0, 0.5)));
    assert_true(sx_contains_point(&s, x, w(x, 1.0, 3.4999)));
    assert_false(sx_contains_point(&s, x, w(x, 1.0, 3.5001)));
    assert_false(sx_contains_point(&s, x, w(x, 2.1, 3.1)));
}

static void point_shape_contains_only_its_point(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_point_shape(sx_v2(SX_R(1.0), SX_R(1.0)));
    (void)state;
    assert_true(sx_contains_point(&s, x, w(x, 1.0, 1.0)));
    assert_false(sx_contains_point(&s, x, w(x, 1.001, 1.0)));
    assert_false(sx_contains_point(&s, x, w(x, 1.0, 0.999)));
}

static void segment_contains_points_on_it_only(void **state) {
    sx_xform x = sx_xform_make(sx_v2(SX_R(-4.0), SX_R(1.0)), SX_R(0.0));
    sx_shape s = sx_segment_shape(sx_v2(SX_R(0.0), SX_R(0.0)), sx_v2(SX_R(2.0), SX_R(0.0)));
    (void)state;
    assert_true(sx_contains_point(&s, x, w(x, 1.0, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 0.0, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 2.0, 0.0)));
    assert_false(sx_contains_point(&s, x, w(x, 1.0, 0.001)));
    assert_false(sx_contains_point(&s, x, w(x, 2.001, 0.0)));
    assert_false(sx_contains_point(&s, x, w(x, -0.001, 0.0)));
}

static void capsule_contains_its_body_and_end_caps(void **state) {
    sx_xform x = placed();
    sx_shape s =
        sx_capsule_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.5));
    (void)state;
    assert_true(sx_contains_point(&s, x, w(x, 0.0, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 0.0, 0.4999)));
    assert_true(sx_contains_point(&s, x, w(x, 1.4999, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 1.3, 0.3)));  /* 0.424 from b */
    assert_false(sx_contains_point(&s, x, w(x, 1.4, 0.4))); /* 0.566 from b */
    assert_false(sx_contains_point(&s, x, w(x, 0.0, 0.5001)));
    assert_false(sx_contains_point(&s, x, w(x, -1.5001, 0.0)));
}

static void box_contains_inside_edges_and_corners_under_a_rotation(void **state) {
    sx_xform x = sx_xform_make(sx_v2(SX_R(5.0), SX_R(5.0)), SX_PI / SX_R(6.0));
    sx_shape s = sx_box_shape(SX_R(2.0), SX_R(1.0));
    (void)state;
    assert_true(sx_contains_point(&s, x, w(x, 0.0, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 1.9999, 0.9999)));
    assert_true(sx_contains_point(&s, x, w(x, -1.9, 0.9)));
    assert_true(sx_contains_point(&s, x, w(x, 2.0, 1.0))); /* a vertex */
    assert_true(sx_contains_point(&s, x, w(x, 2.0, 0.0))); /* an edge */
    assert_false(sx_contains_point(&s, x, w(x, 2.0001, 0.0)));
    assert_false(sx_contains_point(&s, x, w(x, 0.0, -1.0001)));
    assert_false(sx_contains_point(&s, x, w(x, 2.0001, 1.0001)));
}

static void triangle_contains_its_hypotenuse_and_vertices(void **state) {
    sx_vec2 v[3];
    sx_shape s;
    sx_xform x = placed();
    (void)state;
    v[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    v[1] = sx_v2(SX_R(4.0), SX_R(0.0));
    v[2] = sx_v2(SX_R(0.0), SX_R(3.0));
    s = qf_polygon(v, 3, SX_R(0.0));
    assert_true(sx_contains_point(&s, x, w(x, 1.0, 1.0)));
    assert_true(sx_contains_point(&s, x, w(x, 2.0, 1.5))); /* on the hypotenuse */
    assert_true(sx_contains_point(&s, x, w(x, 4.0, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 0.0, 3.0)));
    assert_false(sx_contains_point(&s, x, w(x, 2.001, 1.501)));
    assert_false(sx_contains_point(&s, x, w(x, -0.001, 1.0)));
    assert_false(sx_contains_point(&s, x, w(x, 4.001, 0.0)));
}

/* Regression (fuzz: query-contains-sliver-vertex): the boundary band of a
 * sharp polygon used to be every edge's half-plane widened by the band, and
 * beyond a vertex of angle theta those widened half-planes meet up to
 * band / sin(theta / 2) away: a point 1.7 mm beyond this sliver's tip (340 x
 * the band) counted as contained although its distance is +1.7 mm. */
static void sliver_tip_contains_only_its_band(void **state) {
    sx_vec2 v[3];
    sx_shape s;
    sx_xform far = sx_xform_make(sx_v2(SX_R(-16.0), SX_R(-16.0)), SX_R(0.0));
    sx_xform id = sx_xform_identity();
    const double band = 1e-3 * (double)SX_LINEAR_SLOP, axis = 0.70710678118654752;
    (void)state;
    v[0] = sx_v2(SX_R(0.0012), SX_R(0.0012));
    v[1] = sx_v2(SX_R(6.5), SX_R(6.5));
    v[2] = sx_v2(SX_R(6.5), SX_R(6.5024));
    s = qf_polygon(v, 3, SX_R(0.0));
    assert_int_equal(sx_shape_validate(&s), SX_OK);
    /* The fuzzer's case: local (0, 0), 1.7 mm beyond the tip. */
    assert_true((double)sx_shape_distance_to_point(&s, far, far.p, NULL, NULL) > 1e-3);
    assert_false(sx_contains_point(&s, far, far.p));
    /* Along the axis beyond the tip: inside the band, then just past it. */
    assert_true(sx_contains_point(&s, id, v[0]));
    assert_true(
        sx_contains_point(&s, id, w(id, 0.0012 - 0.4 * band * axis, 0.0012 - 0.4 * band * axis)));
    assert_false(
        sx_contains_point(&s, id, w(id, 0.0012 - 3.0 * band * axis, 0.0012 - 3.0 * band * axis)));
    assert_false(sx_contains_point(
        &s, id, w(id, 0.0012 - 100.0 * band * axis, 0.0012 - 100.0 * band * axis)));
    /* The signed distance there is the distance to the tip (it used to
     * round to 0 from the far vertex of the long edge). */
    assert_near(
        sx_shape_distance_to_point(
            &s, id, w(id, 0.0012 - 3.0 * band * axis, 0.0012 - 3.0 * band * axis), NULL, NULL),
        3.0 * band, 1e-7);
    /* Inside the sliver near its tip, and across its width at the far end. */
    assert_true(sx_contains_point(&s, id, w(id, 0.01, 0.0100005)));
    assert_true(sx_contains_point(&s, id, w(id, 6.5, 6.5012)));
    assert_false(sx_contains_point(&s, id, w(id, 6.5 + 3.0 * band, 6.5012)));
}

/* Regression (make fuzz, double build): a box of denormal half extents
 * (valid: strictly convex, CCW) contained points 5 cm away, because
 * cross(e, p - v) of an edge that short underflowed to 0, "on the line". */
static void denormal_box_contains_only_its_band(void **state) {
#ifdef SX_DOUBLE
    const sx_real tiny = (sx_real)(DBL_MIN * 1e-15);
#else
    const sx_real tiny = (sx_real)(FLT_MIN * 1e-6f);
#endif
    sx_shape s = sx_box_shape(tiny, tiny);
    sx_xform x = sx_xform_make(sx_v2(SX_R(0.0140625), SX_R(0.028125)), SX_R(0.0422));
    const double band = 1e-3 * (double)SX_LINEAR_SLOP;
    (void)state;
    if (sx_shape_validate(&s) != SX_OK) return; /* nothing to check */
    assert_true(sx_contains_point(&s, x, x.p));
    assert_false(sx_contains_point(&s, x, sx_v2(SX_R(0.05625), SX_R(0.06125))));
    assert_true(sx_contains_point(&s, x, w(x, 0.4 * band, 0.0)));
    assert_false(sx_contains_point(&s, x, w(x, 3.0 * band, 0.0)));
    assert_false(sx_contains_point(&s, x, w(x, -3.0 * band, 3.0 * band)));
}

static void rounded_box_contains_its_rounding_but_not_the_sharp_corner(void **state) {
    sx_xform x = placed();
    sx_shape s = qf_rounded_box(SX_R(1.0), SX_R(1.0), SX_R(0.5));
    double k = 1.0 + 0.5 / sqrt(2.0);
    (void)state;
    assert_true(sx_contains_point(&s, x, w(x, 0.0, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 1.4999, 0.0)));
    assert_true(sx_contains_point(&s, x, w(x, 1.45, 1.0)));
    assert_true(sx_contains_point(&s, x, w(x, 1.3, 1.3)));
    assert_true(sx_contains_point(&s, x, w(x, k - 1e-4, k - 1e-4))); /* just inside the arc */
    assert_false(sx_contains_point(&s, x, w(x, k + 1e-4, k + 1e-4)));
    assert_false(sx_contains_point(&s, x, w(x, 1.45, 1.45))); /* in the sharp box's corner */
    assert_false(sx_contains_point(&s, x, w(x, 0.0, -1.5001)));
}

static void contains_answers_false_for_unusable_input(void **state) {
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(1.0));
    sx_shape bad = sx_circle_shape(sx_v2_zero(), SX_R(-1.0));
    sx_shape poly = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_xform x = sx_xform_identity();
    sx_real nan = (sx_real)NAN;
    (void)state;
    assert_false(sx_contains_point(NULL, x, sx_v2_zero()));
    assert_false(sx_contains_point(&bad, x, sx_v2_zero()));
    assert_false(sx_contains_point(&c, x, sx_v2(nan, SX_R(0.0))));
    x.p.x = nan;
    assert_false(sx_contains_point(&c, x, sx_v2_zero()));
    x = sx_xform_identity();
    poly.u.polygon.count = SX_MAX_POLYGON_VERTICES + 1;
    assert_false(sx_contains_point(&poly, x, sx_v2_zero()));
    poly.u.polygon.count = 2;
    assert_false(sx_contains_point(&poly, x, sx_v2_zero()));
    poly = sx_box_shape(SX_R(1.0), SX_R(1.0));
    poly.u.polygon.vertices[1].x = (sx_real)INFINITY;
    assert_false(sx_contains_point(&poly, x, sx_v2_zero()));
    c.type = SX_SHAPE_TYPE_COUNT;
    assert_false(sx_contains_point(&c, x, sx_v2_zero()));
}

/* ---- closest point on a segment ---------------------------------------- */

static void closest_point_on_segment_projects_and_clamps(void **state) {
    sx_vec2 a = sx_v2(SX_R(1.0), SX_R(1.0)), b = sx_v2(SX_R(5.0), SX_R(3.0));
    sx_real t = SX_R(-1.0);
    sx_vec2 q;
    (void)state;
    q = sx_closest_point_on_segment(a, b, sx_v2(SX_R(3.0), SX_R(2.0)), &t);
    assert_vec2_near(q, sx_v2(SX_R(3.0), SX_R(2.0)), EPS);
    assert_near(t, 0.5, EPS);
    q = sx_closest_point_on_segment(a, b, sx_v2(SX_R(1.2), SX_R(3.6)), &t); /* foot (2.2, 1.6) */
    assert_vec2_near(q, sx_v2(SX_R(2.2), SX_R(1.6)), EPS);
    assert_near(t, 0.3, EPS);
    q = sx_closest_point_on_segment(a, b, sx_v2(SX_R(-3.0), SX_R(0.0)), &t);
    assert_true(q.x == a.x && q.y == a.y);
    assert_true(t == SX_R(0.0));
    q = sx_closest_point_on_segment(a, b, sx_v2(SX_R(9.0), SX_R(3.5)), &t);
    assert_true(q.x == b.x && q.y == b.y);
    assert_true(t == SX_R(1.0));
    q = sx_closest_point_on_segment(a, b, sx_v2(SX_R(9.0), SX_R(3.5)), NULL);
    assert_true(q.x == b.x && q.y == b.y);
}

static void closest_point_on_zero_length_or_bad_segment_is_defined(void **state) {
    sx_vec2 a = sx_v2(SX_R(1.0), SX_R(1.0));
    sx_real t = SX_R(-1.0), nan = (sx_real)NAN;
    sx_vec2 q;
    (void)state;
    q = sx_closest_point_on_segment(a, a, sx_v2(SX_R(4.0), SX_R(0.0)), &t);
    assert_true(q.x == a.x && q.y == a.y && t == SX_R(0.0));
    q = sx_closest_point_on_segment(a, sx_v2(SX_R(2.0), SX_R(1.0)), sx_v2(nan, SX_R(0.0)), &t);
    assert_true(q.x == a.x && q.y == a.y && t == SX_R(0.0));
    q = sx_closest_point_on_segment(sx_v2(nan, SX_R(0.0)), a, a, &t);
    assert_true(q.x == SX_R(0.0) && q.y == SX_R(0.0) && t == SX_R(0.0));
    /* Tiny and huge segments keep their direction. */
    q = sx_closest_point_on_segment(sx_v2_zero(), sx_v2(SX_R(1e-30), SX_R(0.0)),
                                    sx_v2(SX_R(0.5e-30), SX_R(1.0)), &t);
    assert_near(t, 0.5, EPS);
    q = sx_closest_point_on_segment(sx_v2(-SX_REAL_MAX / SX_R(2.0), SX_R(0.0)),
                                    sx_v2(SX_REAL_MAX / SX_R(2.0), SX_R(0.0)), sx_v2_zero(), &t);
    assert_near(t, 0.5, EPS);
    assert_true(sx_vec2_is_finite(q));
}

/* ---- closest point on a shape ------------------------------------------- */

static void closest_point_of_each_shape_from_outside(void **state) {
    sx_xform x = placed();
    sx_shape circle = sx_circle_shape(sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(1.0));
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape seg = sx_segment_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)));
    sx_shape cap =
        sx_capsule_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.5));
    sx_shape rbox = qf_rounded_box(SX_R(1.0), SX_R(1.0), SX_R(0.5));
    double k = 1.0 + 0.5 / sqrt(2.0);
    (void)state;
    assert_vec2_near(sx_closest_point(&circle, x, w(x, 5.0, 0.0)), w(x, 2.0, 0.0), EPS);
    assert_vec2_near(sx_closest_point(&box, x, w(x, 3.0, 3.0)), w(x, 1.0, 1.0), EPS);
    assert_vec2_near(sx_closest_point(&box, x, w(x, 3.0, 0.5)), w(x, 1.0, 0.5), EPS);
    assert_vec2_near(sx_closest_point(&seg, x, w(x, 0.25, 2.0)), w(x, 0.25, 0.0), EPS);
    assert_vec2_near(sx_closest_point(&seg, x, w(x, -4.0, -2.0)), w(x, -1.0, 0.0), EPS);
    assert_vec2_near(sx_closest_point(&cap, x, w(x, 0.0, 3.0)), w(x, 0.0, 0.5), EPS);
    assert_vec2_near(sx_closest_point(&cap, x, w(x, 3.0, 0.0)), w(x, 1.5, 0.0), EPS);
    assert_vec2_near(sx_closest_point(&rbox, x, w(x, 3.0, 3.0)), w(x, k, k), EPS);
    assert_vec2_near(sx_closest_point(&rbox, x, w(x, 0.5, -4.0)), w(x, 0.5, -1.5), EPS);
}

static void closest_point_of_a_solid_shape_is_the_point_itself_inside(void **state) {
    sx_xform x = placed();
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape rbox = qf_rounded_box(SX_R(1.0), SX_R(1.0), SX_R(0.5));
    sx_shape circle = sx_circle_shape(sx_v2_zero(), SX_R(2.0));
    sx_vec2 p = w(x, 0.3, -0.6), q;
    (void)state;
    q = sx_closest_point(&box, x, p);
    assert_true(q.x == p.x && q.y == p.y);
    p = w(x, 1.2, 1.1); /* in the rounding */
    q = sx_closest_point(&rbox, x, p);
    assert_true(q.x == p.x && q.y == p.y);
    q = sx_closest_point(&circle, x, p);
    assert_true(q.x == p.x && q.y == p.y);
    q = sx_closest_point(NULL, x, p);
    assert_true(q.x == SX_R(0.0) && q.y == SX_R(0.0));
    q = sx_closest_point(&circle, x, sx_v2((sx_real)INFINITY, SX_R(0.0)));
    assert_true(q.x == SX_R(0.0) && q.y == SX_R(0.0));
}

/* ---- signed distance ---------------------------------------------------- */

/* Checks distance, boundary point and normal, and the identity
 * p = boundary + distance * normal. */
static void check_distance(const sx_shape *s, sx_xform x, sx_vec2 p, double dist, sx_vec2 bp,
                           sx_vec2 n) {
    sx_vec2 got_bp, got_n;
    sx_real d = sx_shape_distance_to_point(s, x, p, &got_bp, &got_n);
    assert_near(d, dist, EPS);
    assert_vec2_near(got_bp, bp, EPS);
    assert_vec2_near(got_n, n, EPS);
    assert_vec2_near(sx_mul_add(got_bp, d, got_n), p, EPS);
}

static void circle_signed_distance_outside_inside_and_at_centre(void **state) {
    sx_xform x = placed_exactly();
    sx_shape s = sx_circle_shape(sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(1.0));
    sx_shape pt = sx_point_shape(sx_v2(SX_R(1.0), SX_R(0.0)));
    (void)state;
    check_distance(&s, x, w(x, 1.0, 3.0), 2.0, w(x, 1.0, 1.0), wdir(x, 0.0, 1.0));
    check_distance(&s, x, w(x, 1.25, 0.0), -0.75, w(x, 2.0, 0.0), wdir(x, 1.0, 0.0));
    /* At the centre: fallback normal world +x. */
    check_distance(&s, x, w(x, 1.0, 0.0), -1.0, sx_add(w(x, 1.0, 0.0), sx_v2(SX_R(1.0), SX_R(0.0))),
                   sx_v2(SX_R(1.0), SX_R(0.0)));
    check_distance(&pt, x, w(x, 1.0, 2.0), 2.0, w(x, 1.0, 0.0), wdir(x, 0.0, 1.0));
    check_distance(&pt, x, w(x, 1.0, 0.0), 0.0, w(x, 1.0, 0.0), sx_v2(SX_R(1.0), SX_R(0.0)));
}

static void segment_distance_is_unsigned_with_left_normal_on_it(void **state) {
    sx_xform x = placed_exactly();
    sx_shape s = sx_segment_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)));
    sx_shape z = sx_segment_shape(sx_v2(SX_R(1.0), SX_R(1.0)), sx_v2(SX_R(1.0), SX_R(1.0)));
    (void)state;
    check_distance(&s, x, w(x, 0.5, -2.0), 2.0, w(x, 0.5, 0.0), wdir(x, 0.0, -1.0));
    check_distance(&s, x, w(x, 4.0, 4.0), 5.0, w(x, 1.0, 0.0), wdir(x, 0.6, 0.8));
    check_distance(&s, x, w(x, 0.5, 0.0), 0.0, w(x, 0.5, 0.0), wdir(x, 0.0, 1.0));
    check_distance(&z, x, w(x, 1.0, 1.0), 0.0, w(x, 1.0, 1.0), sx_v2(SX_R(1.0), SX_R(0.0)));
    check_distance(&z, x, w(x, 1.0, -1.0), 2.0, w(x, 1.0, 1.0), wdir(x, 0.0, -1.0));
}

static void capsule_signed_distance_on_sides_caps_and_core(void **state) {
    sx_xform x = placed_exactly();
    sx_shape s =
        sx_capsule_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.5));
    (void)state;
    check_distance(&s, x, w(x, 0.0, 2.0), 1.5, w(x, 0.0, 0.5), wdir(x, 0.0, 1.0));
    check_distance(&s, x, w(x, -4.0, 0.0), 2.5, w(x, -1.5, 0.0), wdir(x, -1.0, 0.0));
    check_distance(&s, x, w(x, 0.2, -0.1), -0.4, w(x, 0.2, -0.5), wdir(x, 0.0, -1.0));
    check_distance(&s, x, w(x, 0.2, 0.0), -0.5, w(x, 0.2, 0.5), wdir(x, 0.0, 1.0));
}

static void polygon_signed_distance_inside_on_edges_and_at_vertices(void **state) {
    sx_xform x = placed_exactly();
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(2.0));
    double r2 = 1.0 / sqrt(2.0);
    (void)state;
    check_distance(&s, x, w(x, 0.5, 0.2), -0.5, w(x, 1.0, 0.2), wdir(x, 1.0, 0.0));
    check_distance(&s, x, w(x, 0.0, -1.75), -0.25, w(x, 0.0, -2.0), wdir(x, 0.0, -1.0));
    check_distance(&s, x, w(x, 3.0, 0.5), 2.0, w(x, 1.0, 0.5), wdir(x, 1.0, 0.0));
    check_distance(&s, x, w(x, 2.0, 3.0), sqrt(2.0), w(x, 1.0, 2.0), wdir(x, r2, r2));
    check_distance(&s, x, w(x, 1.0, 2.0), 0.0, w(x, 1.0, 2.0), wdir(x, 1.0, 0.0));
    check_distance(&s, x, w(x, -1.0, 0.0), 0.0, w(x, -1.0, 0.0), wdir(x, -1.0, 0.0));
}

static void rounded_polygon_signed_distance_includes_the_radius(void **state) {
    sx_xform x = placed();
    sx_shape s = qf_rounded_box(SX_R(1.0), SX_R(1.0), SX_R(0.5));
    double r2 = 1.0 / sqrt(2.0), k = 1.0 + 0.5 * r2;
    (void)state;
    check_distance(&s, x, w(x, 0.5, 0.0), -1.0, w(x, 1.5, 0.0), wdir(x, 1.0, 0.0));
    check_distance(&s, x, w(x, 1.2, 0.0), -0.3, w(x, 1.5, 0.0), wdir(x, 1.0, 0.0));
    check_distance(&s, x, w(x, 2.0, 2.0), sqrt(2.0) - 0.5, w(x, k, k), wdir(x, r2, r2));
    check_distance(&s, x, w(x, 1.1, 1.1), 0.1 * sqrt(2.0) - 0.5, w(x, k, k), wdir(x, r2, r2));
    check_distance(&s, x, w(x, 0.0, -3.0), 1.5, w(x, 0.0, -1.5), wdir(x, 0.0, -1.0));
}

static void distance_of_unusable_input_is_real_max_with_zero_vectors(void **state) {
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_vec2 bp = sx_v2(SX_R(7.0), SX_R(7.0)), n = bp;
    sx_xform x = sx_xform_identity();
    (void)state;
    assert_true(sx_shape_distance_to_point(&s, x, sx_v2((sx_real)NAN, SX_R(0.0)), &bp, &n) ==
                SX_REAL_MAX);
    assert_true(bp.x == SX_R(0.0) && bp.y == SX_R(0.0) && n.x == SX_R(0.0) && n.y == SX_R(0.0));
    assert_true(sx_shape_distance_to_point(NULL, x, sx_v2_zero(), NULL, NULL) == SX_REAL_MAX);
    x.q.s = (sx_real)INFINITY;
    assert_true(sx_shape_distance_to_point(&s, x, sx_v2_zero(), &bp, NULL) == SX_REAL_MAX);
    s = sx_capsule_shape(sx_v2_zero(), sx_v2_zero(), (sx_real)NAN);
    assert_true(sx_shape_distance_to_point(&s, sx_xform_identity(), sx_v2_zero(), NULL, &n) ==
                SX_REAL_MAX);
}

/* ---- segment-segment intersection --------------------------------------- */

static sx_vec2 v2(double x, double y) { return sx_v2((sx_real)x, (sx_real)y); }

static void check_overlap(sx_segment_intersection *o, sx_vec2 start, sx_vec2 end, double t,
                          double u) {
    assert_int_equal(o->relation, SX_SEGMENTS_OVERLAP);
    assert_vec2_near(o->overlap_start, start, EPS);
    assert_vec2_near(o->overlap_end, end, EPS);
    assert_vec2_near(o->point, start, EPS);
    assert_near(o->t, t, EPS);
    assert_near(o->u, u, EPS);
}

static void crossing_segments_intersect_at_the_exact_point(void **state) {
    sx_segment_intersection o;
    (void)state;
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(4, 4), v2(0, 4), v2(4, 0), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_int_equal(o.relation, SX_SEGMENTS_INTERSECT);
    assert_vec2_near(o.point, v2(2, 2), EPS);
    assert_near(o.t, 0.5, EPS);
    assert_near(o.u, 0.5, EPS);
    assert_vec2_near(o.overlap_start, v2(2, 2), EPS);
    assert_vec2_near(o.overlap_end, v2(2, 2), EPS);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(4, 0), v2(1, -1), v2(1, 3), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_vec2_near(o.point, v2(1, 0), EPS);
    assert_near(o.t, 0.25, EPS);
    assert_near(o.u, 0.25, EPS);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(4, 0), v2(1, -1), v2(1, 3), NULL),
                     SX_SEGMENTS_INTERSECT);
}

static void t_junction_and_shared_corner_intersect_at_the_exact_end_point(void **state) {
    sx_segment_intersection o;
    (void)state;
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(2, 0), v2(1, 0), v2(1, 1), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_true(o.point.x == SX_R(1.0) && o.point.y == SX_R(0.0));
    assert_near(o.t, 0.5, EPS);
    assert_true(o.u == SX_R(0.0));
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(2, 0), v2(2, 0), v2(3, 1), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_true(o.point.x == SX_R(2.0) && o.point.y == SX_R(0.0));
    assert_true(o.t == SX_R(1.0) && o.u == SX_R(0.0));
}

static void t_junction_with_rounded_coordinates_still_intersects(void **state) {
    /* q1 lies on p only up to the rounding of its coordinates. */
    sx_vec2 p1 = v2(0.1, 0.1), p2 = v2(0.7, 0.3);
    sx_segment_intersection o;
    int i;
    (void)state;
    for (i = 1; i < 10; ++i) {
        sx_real t = (sx_real)(0.1 * i);
        sx_vec2 q1 = sx_lerp(p1, p2, t);
        sx_vec2 q2 = sx_add(q1, v2(-0.2, 0.6));
        assert_int_equal(sx_intersect_segments(p1, p2, q1, q2, &o), SX_SEGMENTS_INTERSECT);
        assert_near(o.t, t, EPS);
        assert_true(o.u == SX_R(0.0));
        assert_true(o.point.x == q1.x && o.point.y == q1.y);
        assert_int_equal(sx_intersect_segments(p1, p2, q2, q1, &o), SX_SEGMENTS_INTERSECT);
        assert_true(o.u == SX_R(1.0));
    }
}

static void disjoint_and_parallel_segments_report_no_point(void **state) {
    sx_segment_intersection o;
    (void)state;
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 0), v2(2, -1), v2(2, 1), &o),
                     SX_SEGMENTS_DISJOINT);
    assert_true(o.point.x == SX_R(0.0) && o.point.y == SX_R(0.0) && o.t == SX_R(0.0) &&
                o.u == SX_R(0.0));
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 0), v2(0.5, 0.001), v2(0.5, 1), &o),
                     SX_SEGMENTS_DISJOINT);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 0), v2(0, 1), v2(1, 1), &o),
                     SX_SEGMENTS_PARALLEL);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 0), v2(5, -1e-3), v2(3, -1e-3), &o),
                     SX_SEGMENTS_PARALLEL);
    assert_true(o.overlap_start.x == SX_R(0.0) && o.overlap_end.x == SX_R(0.0));
}

static void collinear_overlapping_segments_give_the_shared_interval(void **state) {
    sx_segment_intersection o;
    (void)state;
    sx_intersect_segments(v2(0, 0), v2(4, 0), v2(2, 0), v2(6, 0), &o);
    check_overlap(&o, v2(2, 0), v2(4, 0), 0.5, 0.0);
    sx_intersect_segments(v2(0, 0), v2(4, 0), v2(6, 0), v2(2, 0), &o);
    check_overlap(&o, v2(2, 0), v2(4, 0), 0.5, 1.0);
    sx_intersect_segments(v2(0, 0), v2(4, 0), v2(1, 0), v2(3, 0), &o);
    check_overlap(&o, v2(1, 0), v2(3, 0), 0.25, 0.0);
    sx_intersect_segments(v2(0, 0), v2(4, 0), v2(-1, 0), v2(5, 0), &o);
    check_overlap(&o, v2(0, 0), v2(4, 0), 0.0, 1.0 / 6.0);
    /* A diagonal line, q running backwards. */
    sx_intersect_segments(v2(1, 1), v2(3, 3), v2(4, 4), v2(2, 2), &o);
    check_overlap(&o, v2(2, 2), v2(3, 3), 0.5, 1.0);
}

static void collinear_segments_touching_at_one_end_overlap_in_one_point(void **state) {
    sx_segment_intersection o;
    (void)state;
    sx_intersect_segments(v2(0, 0), v2(1, 0), v2(1, 0), v2(2, 0), &o);
    check_overlap(&o, v2(1, 0), v2(1, 0), 1.0, 0.0);
    sx_intersect_segments(v2(0, 0), v2(1, 0), v2(-2, 0), v2(0, 0), &o);
    check_overlap(&o, v2(0, 0), v2(0, 0), 0.0, 1.0);
}

static void collinear_disjoint_segments_are_reported_as_such(void **state) {
    sx_segment_intersection o;
    (void)state;
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 0), v2(2, 0), v2(3, 0), &o),
                     SX_SEGMENTS_COLLINEAR_DISJOINT);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 1), v2(-1, -1), v2(-0.01, -0.01), &o),
                     SX_SEGMENTS_COLLINEAR_DISJOINT);
    assert_true(o.t == SX_R(0.0) && o.point.x == SX_R(0.0));
}

static void identical_segments_overlap_entirely(void **state) {
    sx_segment_intersection o;
    (void)state;
    sx_intersect_segments(v2(0.3, 0.7), v2(2.9, -1.1), v2(0.3, 0.7), v2(2.9, -1.1), &o);
    check_overlap(&o, v2(0.3, 0.7), v2(2.9, -1.1), 0.0, 0.0);
    sx_intersect_segments(v2(0.3, 0.7), v2(2.9, -1.1), v2(2.9, -1.1), v2(0.3, 0.7), &o);
    check_overlap(&o, v2(0.3, 0.7), v2(2.9, -1.1), 0.0, 1.0);
}

static void zero_length_segments_are_points(void **state) {
    sx_segment_intersection o;
    (void)state;
    assert_int_equal(sx_intersect_segments(v2(1, 0), v2(1, 0), v2(0, 0), v2(2, 0), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_vec2_near(o.point, v2(1, 0), EPS);
    assert_true(o.t == SX_R(0.0));
    assert_near(o.u, 0.5, EPS);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(2, 0), v2(2, 0), v2(2, 0), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_near(o.t, 1.0, EPS);
    assert_true(o.u == SX_R(0.0));
    assert_int_equal(sx_intersect_segments(v2(1, 1), v2(1, 1), v2(0, 0), v2(2, 0), &o),
                     SX_SEGMENTS_DISJOINT);
    assert_int_equal(sx_intersect_segments(v2(3, 0), v2(3, 0), v2(0, 0), v2(2, 0), &o),
                     SX_SEGMENTS_DISJOINT);
    assert_int_equal(sx_intersect_segments(v2(1, 2), v2(1, 2), v2(1, 2), v2(1, 2), &o),
                     SX_SEGMENTS_INTERSECT);
    assert_vec2_near(o.point, v2(1, 2), 0.0);
    assert_int_equal(sx_intersect_segments(v2(1, 2), v2(1, 2), v2(1, 2.001), v2(1, 2.001), &o),
                     SX_SEGMENTS_DISJOINT);
}

static void near_parallel_segments_follow_the_relative_tolerance(void **state) {
    /* 1e-7 rad apart: below the float tolerance (16 eps ~ 1.9e-6), far above
     * the double one. */
    sx_segment_intersection o;
    sx_segment_relation rel;
    (void)state;
    rel = sx_intersect_segments(v2(0, 0), v2(1, 0), v2(0, -0.5e-7), v2(1, 0.5e-7), &o);
#ifdef SX_DOUBLE
    assert_int_equal(rel, SX_SEGMENTS_INTERSECT);
    assert_near(o.point.x, 0.5, 1e-8);
    assert_near(o.point.y, 0.0, 1e-15);
    assert_near(o.t, 0.5, 1e-8);
    assert_near(o.u, 0.5, 1e-8);
#else
    assert_int_equal(rel, SX_SEGMENTS_OVERLAP);
    assert_vec2_near(o.overlap_start, v2(0, 0), 0.0);
    assert_vec2_near(o.overlap_end, v2(1, 0), 0.0);
#endif
    rel = sx_intersect_segments(v2(0, 0), v2(1, 0), v2(0, 1e-3), v2(1, 1e-3 + 1e-7), &o);
#ifdef SX_DOUBLE
    assert_int_equal(rel, SX_SEGMENTS_DISJOINT); /* the lines meet near x = -1e4 */
#else
    assert_int_equal(rel, SX_SEGMENTS_PARALLEL);
#endif
    /* The tolerance is relative: the same picture scaled by 1e-6 or 1e6
     * gives the same answer. */
    assert_int_equal(
        sx_intersect_segments(v2(0, 0), v2(1e-6, 0), v2(0, 1e-9), v2(1e-6, 1e-9), NULL),
        SX_SEGMENTS_PARALLEL);
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1e6, 0), v2(0, 1e3), v2(1e6, 1e3), NULL),
                     SX_SEGMENTS_PARALLEL);
    assert_int_equal(
        sx_intersect_segments(v2(0, 0), v2(1e-6, 0), v2(2e-7, -1e-7), v2(4e-7, 1e-7), &o),
        SX_SEGMENTS_INTERSECT);
    assert_near(o.point.x, 3e-7, 1e-12);
}

static void non_finite_or_huge_segments_are_degenerate(void **state) {
    sx_segment_intersection o;
    sx_real nan = (sx_real)NAN, inf = (sx_real)INFINITY;
    sx_real big = SX_REAL_MAX / SX_R(4.0);
    (void)state;
    assert_int_equal(sx_intersect_segments(sx_v2(nan, SX_R(0.0)), v2(1, 0), v2(0, 1), v2(1, 1), &o),
                     SX_SEGMENTS_DEGENERATE);
    assert_int_equal(o.relation, SX_SEGMENTS_DEGENERATE);
    assert_true(o.point.x == SX_R(0.0) && o.t == SX_R(0.0) && o.u == SX_R(0.0));
    assert_int_equal(sx_intersect_segments(v2(0, 0), v2(1, 0), v2(0, 1), sx_v2(SX_R(1.0), inf), &o),
                     SX_SEGMENTS_DEGENERATE);
    assert_int_equal(
        sx_intersect_segments(v2(0, 0), sx_v2(-inf, SX_R(0.0)), v2(0, 1), v2(1, 1), NULL),
        SX_SEGMENTS_DEGENERATE);
    assert_int_equal(
        sx_intersect_segments(v2(0, 0), v2(1, 0), sx_v2(big, big), sx_v2(-big, -big), &o),
        SX_SEGMENTS_DEGENERATE);
}

/* Orientation of c relative to a->b in double: exact for float inputs and
 * accurate far beyond the margin used below for double ones. */
static double orient(sx_vec2 a, sx_vec2 b, sx_vec2 c) {
    return ((double)b.x - (double)a.x) * ((double)c.y - (double)a.y) -
           ((double)b.y - (double)a.y) * ((double)c.x - (double)a.x);
}

static void random_segment_pairs_agree_with_orientation_tests(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5e65e6);
    int i, crossing = 0, apart = 0;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        sx_vec2 p1 = qf_random_vec(&rng, -4.0, 4.0), p2 = qf_random_vec(&rng, -4.0, 4.0);
        sx_vec2 q1 = qf_random_vec(&rng, -4.0, 4.0), q2 = qf_random_vec(&rng, -4.0, 4.0);
        sx_segment_intersection o, r;
        double o1 = orient(p1, p2, q1), o2 = orient(p1, p2, q2);
        double o3 = orient(q1, q2, p1), o4 = orient(q1, q2, p2);
        const double margin = 1e-3;
        sx_segment_relation rel = sx_intersect_segments(p1, p2, q1, q2, &o);
        sx_segment_relation rev = sx_intersect_segments(q1, q2, p1, p2, &r);
        assert_int_equal(rel, rev);
        if (o1 * o2 < -margin && o3 * o4 < -margin) {
            crossing++;
            assert_int_equal(rel, SX_SEGMENTS_INTERSECT);
        } else if (o1 * o2 > margin || o3 * o4 > margin) {
            apart++;
            assert_true(rel == SX_SEGMENTS_DISJOINT || rel == SX_SEGMENTS_PARALLEL);
        }
        if (rel == SX_SEGMENTS_INTERSECT) {
            /* The point is on both segments, at the reported parameters, and
             * swapping the segments swaps t and u. */
            assert_vec2_near(o.point, sx_lerp(p1, p2, o.t), QF_TOL);
            assert_vec2_near(o.point, sx_lerp(q1, q2, o.u), QF_TOL);
            assert_near(r.t, o.u, QF_TOL);
            assert_near(r.u, o.t, QF_TOL);
            assert_true(o.t >= SX_R(0.0) && o.t <= SX_R(1.0) && o.u >= SX_R(0.0) &&
                        o.u <= SX_R(1.0));
        }
    }
    /* Both branches were exercised in earnest. */
    assert_true(crossing > 3000 && apart > 3000);
}

static void random_collinear_segments_overlap_exactly_when_their_intervals_do(void **state) {
    /* Four points on a random line at random parameters: the rounding of
     * their coordinates puts them off the line by half an ulp, which the
     * relative tolerance must absorb. It can when each segment is long
     * against the rounding of its coordinates (length >= 0.2 x the largest
     * coordinate here); for shorter ones the direction itself is uncertain
     * by more than 16 eps and the segments are rightly seen as crossing. */
    sx_test_rng rng = sx_test_rng_make(0xc0111);
    int i, overlaps = 0, apart = 0;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        sx_vec2 base = qf_random_vec(&rng, -1.0, 1.0);
        double angle = sx_test_rng_unit(&rng) * 6.283185307179586;
        double len = 0.01 + 10.0 * sx_test_rng_unit(&rng);
        double big = fabs((double)base.x) + fabs((double)base.y) + 1.5 * len;
        double k[4], plo, phi, qlo, qhi;
        sx_vec2 pt[4];
        sx_segment_intersection o;
        sx_segment_relation rel;
        int j;
        for (j = 0; j < 4; ++j) {
            k[j] = sx_test_rng_unit(&rng) * 2.0 - 0.5;
            pt[j] = sx_v2((sx_real)((double)base.x + k[j] * len * cos(angle)),
                          (sx_real)((double)base.y + k[j] * len * sin(angle)));
        }
        plo = fmin(k[0], k[1]);
        phi = fmax(k[0], k[1]);
        qlo = fmin(k[2], k[3]);
        qhi = fmax(k[2], k[3]);
        if ((phi - plo) * len < 0.2 * big || (qhi - qlo) * len < 0.2 * big) continue;
        rel = sx_intersect_segments(pt[0], pt[1], pt[2], pt[3], &o);
        if (fmax(plo, qlo) < fmin(phi, qhi) - 1e-3) {
            double lo = fmax(plo, qlo), hi = fmin(phi, qhi);
            sx_vec2 a = sx_v2((sx_real)((double)base.x + lo * len * cos(angle)),
                              (sx_real)((double)base.y + lo * len * sin(angle)));
            sx_vec2 b = sx_v2((sx_real)((double)base.x + hi * len * cos(angle)),
                              (sx_real)((double)base.y + hi * len * sin(angle)));
            overlaps++;
            assert_int_equal(rel, SX_SEGMENTS_OVERLAP);
            /* overlap_start comes first along p1 -> p2. */
            if (k[0] > k[1]) {
                sx_vec2 tmp = a;
                a = b;
                b = tmp;
            }
            assert_vec2_near(o.overlap_start, a, QF_TOL);
            assert_vec2_near(o.overlap_end, b, QF_TOL);
            assert_vec2_near(o.point, sx_lerp(pt[0], pt[1], o.t), QF_TOL);
            assert_vec2_near(o.point, sx_lerp(pt[2], pt[3], o.u), QF_TOL);
        } else if (fmax(plo, qlo) > fmin(phi, qhi) + 1e-3) {
            apart++;
            assert_int_equal(rel, SX_SEGMENTS_COLLINEAR_DISJOINT);
        }
    }
    assert_true(overlaps > 5000 && apart > 1000);
}

static void point_queries_far_from_origin_keep_precision(void **state) {
    /* A unit box 1e5 from the origin: in float one ulp there is 0.0078, and
     * the local frame keeps the answers within that rounding of the input. */
    sx_xform x = sx_xform_make(sx_v2(SX_R(1e5), SX_R(1e5)), SX_R(0.0));
    sx_xform xr = sx_xform_make(sx_v2(SX_R(1e5), SX_R(-1e5)), SX_R(0.5));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_shape cap = sx_capsule_shape(v2(-0.5, 0), v2(0.5, 0), SX_R(0.25));
    sx_vec2 bp, n;
    (void)state;
    assert_near(sx_shape_distance_to_point(&box, x, v2(1e5 + 0.75, 1e5), &bp, &n), 0.25, 1e-6);
    assert_vec2_near(bp, v2(1e5 + 0.5, 1e5), 1e-6);
    assert_vec2_near(n, v2(1, 0), 1e-6);
    assert_near(sx_shape_distance_to_point(&box, x, v2(1e5 + 0.25, 1e5 - 0.125), NULL, NULL), -0.25,
                1e-6);
    assert_true(sx_contains_point(&box, x, v2(1e5 + 0.5, 1e5 + 0.5)));
    assert_false(sx_contains_point(&box, x, v2(1e5 + 0.5078125, 1e5)));
    /* Turned: the world point is rounded to 0.0078, the answer follows. */
    assert_near(sx_shape_distance_to_point(&cap, xr, w(xr, 0.0, 1.25), NULL, &n), 1.0, 0.01);
    assert_vec2_near(n, wdir(xr, 0.0, 1.0), 0.01);
    assert_true(sx_contains_point(&cap, xr, w(xr, 0.6, 0.1)));
    assert_false(sx_contains_point(&cap, xr, w(xr, 0.0, 0.3)));
}

/* ---- random properties -------------------------------------------------- */

static void random_closest_points_lie_in_the_shape_and_no_sample_is_closer(void **state) {
    sx_test_rng rng = sx_test_rng_make(0xc105e57);
    int i, j, outside = 0;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        int kind;
        sx_shape s = qf_random_shape(&rng, &kind);
        sx_xform x = qf_random_xform(&rng);
        sx_vec2 p = sx_add(sx_xform_point(x, qf_local_center(&s)), qf_random_vec(&rng, -5.0, 5.0));
        sx_vec2 cp = sx_closest_point(&s, x, p);
        sx_real gap = sx_distance(p, cp);
        assert_true(sx_shape_distance_to_point(&s, x, cp, NULL, NULL) <= QF_TOL);
        if (gap > SX_R(0.0)) outside++;
        for (j = 0; j < 24; ++j) {
            sx_vec2 q = sx_xform_point(x, qf_local_sample(&rng, &s));
            assert_true(sx_distance(p, q) >= gap - QF_TOL);
        }
    }
    assert_true(outside > 10000);
}

static void random_signed_distance_sign_matches_containment(void **state) {
    /* sx_contains_point counts points up to this far outside as on the
     * boundary (collide.h). */
    const sx_real band = SX_R(1e-3) * SX_LINEAR_SLOP;
    sx_test_rng rng = sx_test_rng_make(0x519fed);
    int i, inside = 0, outside = 0;
    (void)state;
    for (i = 0; i < 30000; ++i) {
        int kind;
        sx_shape s = qf_random_shape(&rng, &kind);
        sx_xform x = qf_random_xform(&rng);
        sx_vec2 c = sx_xform_point(x, qf_local_center(&s));
        /* Half of the points drawn from the shape, half around it. */
        sx_vec2 p = (i & 1) ? sx_xform_point(x, qf_local_sample(&rng, &s))
                            : sx_add(c, qf_random_vec(&rng, -4.0, 4.0));
        sx_vec2 bp, n;
        sx_real d = sx_shape_distance_to_point(&s, x, p, &bp, &n);
        bool in = sx_contains_point(&s, x, p);
        if (d < -QF_TOL) {
            inside++;
            assert_true(in);
        } else if (d > band + QF_TOL) {
            outside++;
            assert_false(in);
        }
        if (i & 1) assert_true(d <= QF_TOL); /* samples are in the shape */
        /* The boundary point is on the boundary, the normal unit, and
         * p = boundary + d * normal. */
        assert_near(sx_length(n), 1.0, QF_TOL);
        assert_near(sx_shape_distance_to_point(&s, x, bp, NULL, NULL), 0.0, QF_TOL);
        assert_vec2_near(sx_mul_add(bp, d, n), p, QF_TOL);
        if (d < SX_R(0.0)) {
            /* The disc of radius |d| around an inside point is in the shape. */
            sx_vec2 q = sx_add(p, qf_in_disc(&rng, -d * SX_R(0.999)));
            assert_true(sx_shape_distance_to_point(&s, x, q, NULL, NULL) <= QF_TOL);
        }
    }
    assert_true(inside > 8000 && outside > 8000);
}

static void hostile_input_never_crashes_or_yields_nan(void **state) {
    sx_test_rng rng = sx_test_rng_make(0xbad1);
    int i;
    (void)state;
    for (i = 0; i < 40000; ++i) {
        sx_xform x;
        sx_shape s = qf_wild_shape(&rng, &x);
        sx_vec2 p = qf_wild_vec(&rng), bp, n, q;
        sx_vec2 p2 = qf_wild_vec(&rng), q1 = qf_wild_vec(&rng), q2 = qf_wild_vec(&rng);
        sx_segment_intersection o;
        sx_real d = sx_shape_distance_to_point(&s, x, p, &bp, &n), t;
        assert_true(sx_is_finite(d) && sx_vec2_is_finite(bp) && sx_vec2_is_finite(n));
        assert_true(sx_vec2_is_finite(sx_closest_point(&s, x, p)));
        (void)sx_contains_point(&s, x, p);
        q = sx_closest_point_on_segment(p, p2, q1, &t);
        assert_true(sx_vec2_is_finite(q) && t >= SX_R(0.0) && t <= SX_R(1.0));
        (void)sx_intersect_segments(p, p2, q1, q2, &o);
        assert_true(sx_vec2_is_finite(o.point) && sx_vec2_is_finite(o.overlap_start) &&
                    sx_vec2_is_finite(o.overlap_end));
        assert_true(o.t >= SX_R(0.0) && o.t <= SX_R(1.0) && o.u >= SX_R(0.0) && o.u <= SX_R(1.0));
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circle_contains_inside_and_boundary_but_not_outside),
        cmocka_unit_test(point_shape_contains_only_its_point),
        cmocka_unit_test(segment_contains_points_on_it_only),
        cmocka_unit_test(capsule_contains_its_body_and_end_caps),
        cmocka_unit_test(box_contains_inside_edges_and_corners_under_a_rotation),
        cmocka_unit_test(triangle_contains_its_hypotenuse_and_vertices),
        cmocka_unit_test(sliver_tip_contains_only_its_band),
        cmocka_unit_test(denormal_box_contains_only_its_band),
        cmocka_unit_test(rounded_box_contains_its_rounding_but_not_the_sharp_corner),
        cmocka_unit_test(contains_answers_false_for_unusable_input),
        cmocka_unit_test(closest_point_on_segment_projects_and_clamps),
        cmocka_unit_test(closest_point_on_zero_length_or_bad_segment_is_defined),
        cmocka_unit_test(closest_point_of_each_shape_from_outside),
        cmocka_unit_test(closest_point_of_a_solid_shape_is_the_point_itself_inside),
        cmocka_unit_test(circle_signed_distance_outside_inside_and_at_centre),
        cmocka_unit_test(segment_distance_is_unsigned_with_left_normal_on_it),
        cmocka_unit_test(capsule_signed_distance_on_sides_caps_and_core),
        cmocka_unit_test(polygon_signed_distance_inside_on_edges_and_at_vertices),
        cmocka_unit_test(rounded_polygon_signed_distance_includes_the_radius),
        cmocka_unit_test(distance_of_unusable_input_is_real_max_with_zero_vectors),
        cmocka_unit_test(crossing_segments_intersect_at_the_exact_point),
        cmocka_unit_test(t_junction_and_shared_corner_intersect_at_the_exact_end_point),
        cmocka_unit_test(t_junction_with_rounded_coordinates_still_intersects),
        cmocka_unit_test(disjoint_and_parallel_segments_report_no_point),
        cmocka_unit_test(collinear_overlapping_segments_give_the_shared_interval),
        cmocka_unit_test(collinear_segments_touching_at_one_end_overlap_in_one_point),
        cmocka_unit_test(collinear_disjoint_segments_are_reported_as_such),
        cmocka_unit_test(identical_segments_overlap_entirely),
        cmocka_unit_test(zero_length_segments_are_points),
        cmocka_unit_test(near_parallel_segments_follow_the_relative_tolerance),
        cmocka_unit_test(non_finite_or_huge_segments_are_degenerate),
        cmocka_unit_test(random_segment_pairs_agree_with_orientation_tests),
        cmocka_unit_test(random_collinear_segments_overlap_exactly_when_their_intervals_do),
        cmocka_unit_test(point_queries_far_from_origin_keep_precision),
        cmocka_unit_test(random_closest_points_lie_in_the_shape_and_no_sample_is_closer),
        cmocka_unit_test(random_signed_distance_sign_matches_containment),
        cmocka_unit_test(hostile_input_never_crashes_or_yields_nan),
    };
    return cmocka_run_group_tests_name("query", tests, sx_test_group_setup, sx_test_group_teardown);
}
