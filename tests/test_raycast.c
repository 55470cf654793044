/* sepax tests — ray casts against every shape: hits at the expected fraction,
 * point and normal on rotated, translated shapes (faces, vertices, end caps,
 * rounded corners, grazing rays), misses, rays starting inside or ending
 * short, hostile input, far-from-origin precision, and random properties with
 * fixed seeds checked against the signed distance of the point queries. */
#include <math.h>

#include "query_fixtures.h"

#define EPS SX_TEST_EPS

static sx_vec2 v2(double x, double y) { return sx_v2((sx_real)x, (sx_real)y); }

static sx_vec2 w(sx_xform x, double lx, double ly) { return sx_xform_point(x, v2(lx, ly)); }

static sx_vec2 wdir(sx_xform x, double lx, double ly) { return sx_xform_vector(x, v2(lx, ly)); }

static sx_ray_input ray_make(sx_vec2 origin, sx_vec2 translation, double max_fraction) {
    sx_ray_input r;
    r.origin = origin;
    r.translation = translation;
    r.max_fraction = (sx_real)max_fraction;
    return r;
}

/* A ray given in the shape's local frame, cast in world space. */
static bool cast_local(const sx_shape *s, sx_xform x, double ox, double oy, double tx, double ty,
                       double max_fraction, sx_ray_hit *hit) {
    sx_ray_input r = ray_make(w(x, ox, oy), wdir(x, tx, ty), max_fraction);
    return sx_ray_cast(s, x, &r, hit);
}

static void check_hit(const sx_ray_hit *h, double fraction, sx_vec2 point, sx_vec2 normal) {
    assert_true(h->hit);
    assert_near(h->fraction, fraction, EPS);
    assert_vec2_near(h->point, point, EPS);
    assert_vec2_near(h->normal, normal, EPS);
}

static void check_miss(const sx_ray_hit *h) {
    assert_false(h->hit);
    assert_true(h->fraction == SX_R(0.0) && h->point.x == SX_R(0.0) && h->normal.x == SX_R(0.0));
}

static sx_xform placed(void) { return sx_xform_make(v2(2.0, 3.0), SX_R(0.4)); }

/* ---- circles and points ------------------------------------------------- */

static void ray_hits_circle_at_the_near_side(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_circle_shape(v2(0.5, 0.0), SX_R(1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -4.5, 0.0, 10.0, 0.0, 1.0, &h));
    check_hit(&h, 0.4, w(x, -0.5, 0.0), wdir(x, -1.0, 0.0));
    /* Off-centre: the chord at height 0.6 starts at x = -0.8 (from the centre). */
    assert_true(cast_local(&s, x, -4.5, 0.6, 10.0, 0.0, 1.0, &h));
    check_hit(&h, 0.42, w(x, -0.3, 0.6), wdir(x, -0.8, 0.6));
}

static void ray_grazing_circle_hits_at_the_tangent_point(void **state) {
    sx_xform x = sx_xform_make(v2(3.0, -1.0), SX_R(0.0));
    sx_shape s = sx_circle_shape(v2(0.0, 0.0), SX_R(1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -5.0, 1.0, 10.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 1.0), v2(0.0, 1.0));
    assert_false(cast_local(&s, x, -5.0, 1.001, 10.0, 0.0, 1.0, &h));
    check_miss(&h);
}

static void ray_misses_circle_behind_beside_or_beyond_its_reach(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_circle_shape(v2(0.0, 0.0), SX_R(1.0));
    sx_ray_hit h;
    (void)state;
    assert_false(cast_local(&s, x, -5.0, 0.0, -10.0, 0.0, 1.0, &h)); /* pointing away */
    assert_false(cast_local(&s, x, -5.0, 0.0, 0.0, 10.0, 1.0, &h));  /* across */
    assert_false(cast_local(&s, x, -5.0, 0.0, 3.0, 0.0, 1.0, &h));   /* ends at x = -2 */
    assert_false(cast_local(&s, x, -5.0, 0.0, 10.0, 0.0, 0.35, &h)); /* max_fraction short */
    assert_true(cast_local(&s, x, -5.0, 0.0, 3.0, 0.0, 1.5, &h));    /* max_fraction long */
    check_hit(&h, 4.0 / 3.0, w(x, -1.0, 0.0), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&s, x, -5.0, 0.0, 10.0, 0.0, 0.4, &h)); /* ends on it */
    check_hit(&h, 0.4, w(x, -1.0, 0.0), wdir(x, -1.0, 0.0));
}

static void ray_starting_inside_circle_hits_at_zero_facing_back(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_circle_shape(v2(0.0, 0.0), SX_R(1.0));
    sx_ray_hit h;
    sx_ray_input r = ray_make(w(x, 0.3, 0.2), v2(3.0, 4.0), 1.0);
    (void)state;
    assert_true(sx_ray_cast(&s, x, &r, &h));
    check_hit(&h, 0.0, r.origin, v2(-0.6, -0.8));
    r.origin = w(x, 1.0, 0.0); /* on the boundary, leaving */
    assert_true(sx_ray_cast(&s, x, &r, &h));
    assert_true(h.fraction == SX_R(0.0));
    r.max_fraction = SX_R(0.0); /* a zero-length cast still sees where it starts */
    assert_true(sx_ray_cast(&s, x, &r, &h));
}

static void ray_through_a_point_shape_hits_it(void **state) {
    sx_xform x = sx_xform_make(v2(1.0, 1.0), SX_R(0.0));
    sx_shape s = sx_point_shape(v2(1.0, 0.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, 0.0, 0.0, 2.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 1.0, 0.0), v2(-1.0, 0.0));
    assert_false(cast_local(&s, x, 0.0, 0.01, 2.0, 0.0, 1.0, &h));
}

/* ---- segments ----------------------------------------------------------- */

static void ray_hits_segment_from_either_side(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_segment_shape(v2(0.0, -1.0), v2(0.0, 1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -2.0, 0.5, 4.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 0.5), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&s, x, 2.0, -0.5, -4.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, -0.5), wdir(x, 1.0, 0.0));
    /* Slanted: from (-1, -1) towards (1, 1) crosses at the origin. */
    assert_true(cast_local(&s, x, -1.0, -1.0, 2.0, 2.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 0.0), wdir(x, -1.0, 0.0));
}

static void ray_through_segment_end_point_hits_and_just_beyond_misses(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_segment_shape(v2(0.0, -1.0), v2(0.0, 1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -2.0, 1.0, 4.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 1.0), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&s, x, -2.0, 3.0, 4.0, -4.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 1.0), wdir(x, -1.0, 0.0));
    assert_false(cast_local(&s, x, -2.0, 1.001, 4.0, 0.0, 1.0, &h));
    assert_false(cast_local(&s, x, -2.0, 0.0, 1.9, 0.0, 1.0, &h));
}

static void ray_along_segment_line_hits_the_near_end(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_segment_shape(v2(0.0, -1.0), v2(0.0, 1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, 0.0, -3.0, 0.0, 4.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, -1.0), wdir(x, 0.0, -1.0));
    assert_true(cast_local(&s, x, 0.0, 5.0, 0.0, -8.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 1.0), wdir(x, 0.0, 1.0));
    assert_false(cast_local(&s, x, 0.0, -3.0, 0.0, -4.0, 1.0, &h)); /* away */
    assert_false(cast_local(&s, x, 0.0, -3.0, 0.0, 1.0, 1.0, &h));  /* short */
    assert_false(cast_local(&s, x, 0.5, -3.0, 0.0, 4.0, 1.0, &h));  /* parallel beside */
    assert_true(cast_local(&s, x, 0.0, 0.25, 0.0, 4.0, 1.0, &h));   /* starting on it */
    check_hit(&h, 0.0, w(x, 0.0, 0.25), wdir(x, 0.0, -1.0));
}

static void near_parallel_ray_crossing_a_segment_hits_it(void **state) {
    /* 1e-7 rad off the segment's line, crossing it at (0, 0): below the
     * float tolerance (16 eps ~ 1.9e-6) the ray runs along the segment and
     * meets its near end; double resolves the crossing. */
    sx_shape s = sx_segment_shape(v2(0.0, -1.0), v2(0.0, 1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, sx_xform_identity(), 3e-7, -3.0, -4e-7, 4.0, 1.0, &h));
#ifdef SX_DOUBLE
    check_hit(&h, 0.75, v2(0.0, 0.0), v2(1.0, 0.0));
#else
    assert_near(h.fraction, 0.5, EPS);
    assert_vec2_near(h.point, v2(0.0, -1.0), EPS);
    assert_vec2_near(h.normal, v2(0.0, -1.0), EPS);
#endif
    /* The same direction 1e-3 to the side never reaches the segment. */
    assert_false(cast_local(&s, sx_xform_identity(), 1e-3, -3.0, -4e-7, 4.0, 1.0, &h));
}

static void ray_starting_on_segment_hits_at_zero(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_segment_shape(v2(0.0, -1.0), v2(0.0, 1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, 0.0, 0.3, 2.0, 0.0, 1.0, &h));
    check_hit(&h, 0.0, w(x, 0.0, 0.3), wdir(x, -1.0, 0.0));
}

/* ---- capsules ----------------------------------------------------------- */

static void ray_hits_capsule_sides_and_end_caps_exactly(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_capsule_shape(v2(-1.0, 0.0), v2(1.0, 0.0), SX_R(0.5));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, 0.3, 3.0, 0.0, -5.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.3, 0.5), wdir(x, 0.0, 1.0));
    assert_true(cast_local(&s, x, 0.3, -3.0, 0.0, 5.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.3, -0.5), wdir(x, 0.0, -1.0));
    assert_true(cast_local(&s, x, 3.0, 0.0, -3.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 1.5, 0.0), wdir(x, 1.0, 0.0));
    /* On the cap, off the axis: x = 1 + sqrt(0.25 - 0.09) = 1.4. */
    assert_true(cast_local(&s, x, 3.0, 0.3, -4.0, 0.0, 1.0, &h));
    check_hit(&h, 0.4, w(x, 1.4, 0.3), wdir(x, 0.8, 0.6));
    assert_true(cast_local(&s, x, -3.0, -0.3, 4.0, 0.0, 1.0, &h));
    check_hit(&h, 0.4, w(x, -1.4, -0.3), wdir(x, -0.8, -0.6));
}

static void ray_grazing_capsule_side_touches_where_cap_meets_side(void **state) {
    sx_xform x = sx_xform_identity();
    sx_shape s = sx_capsule_shape(v2(-1.0, 0.0), v2(1.0, 0.0), SX_R(0.5));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -3.0, 0.5, 6.0, 0.0, 1.0, &h));
    check_hit(&h, 1.0 / 3.0, v2(-1.0, 0.5), v2(0.0, 1.0));
    assert_false(cast_local(&s, x, -3.0, 0.5001, 6.0, 0.0, 1.0, &h));
}

static void ray_misses_capsule_and_starts_inside_it(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_capsule_shape(v2(-1.0, 0.0), v2(1.0, 0.0), SX_R(0.5));
    sx_ray_hit h;
    sx_ray_input r = ray_make(w(x, 1.2, 0.1), v2(0.0, -2.0), 1.0);
    (void)state;
    assert_false(cast_local(&s, x, 1.4, 0.4, 1.0, 1.0, 1.0, &h));  /* outside the cap, leaving */
    assert_false(cast_local(&s, x, 0.0, 3.0, 0.0, -2.0, 1.0, &h)); /* ends at y = 1 */
    assert_true(sx_ray_cast(&s, x, &r, &h));
    check_hit(&h, 0.0, r.origin, v2(0.0, 1.0));
}

static void degenerate_capsules_cast_as_segments_and_circles(void **state) {
    sx_xform x = placed();
    sx_shape thin = sx_capsule_shape(v2(0.0, -1.0), v2(0.0, 1.0), SX_R(0.0));
    sx_shape round = sx_capsule_shape(v2(0.0, 0.0), v2(0.0, 0.0), SX_R(1.0));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&thin, x, -2.0, 0.5, 4.0, 0.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.0, 0.5), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&round, x, -5.0, 0.0, 10.0, 0.0, 1.0, &h));
    check_hit(&h, 0.4, w(x, -1.0, 0.0), wdir(x, -1.0, 0.0));
}

/* ---- polygons ----------------------------------------------------------- */

static void ray_hits_rotated_box_face_with_its_normal(void **state) {
    sx_xform x = sx_xform_make(v2(10.0, -4.0), SX_PI / SX_R(3.0));
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -3.0, 0.2, 6.0, 0.0, 1.0, &h));
    check_hit(&h, 1.0 / 3.0, w(x, -1.0, 0.2), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&s, x, 0.5, 2.5, 0.0, -4.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 0.5, 0.5), wdir(x, 0.0, 1.0));
    /* Slanted onto the right face: from (3, 1.5) along (-2, -1.5). */
    assert_true(cast_local(&s, x, 3.0, 1.5, -4.0, -3.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 1.0, 0.0), wdir(x, 1.0, 0.0));
}

static void ray_through_box_vertex_hits_with_an_adjacent_face_normal(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_ray_hit h;
    sx_vec2 n1 = wdir(x, 1.0, 0.0), n2 = wdir(x, 0.0, 1.0);
    (void)state;
    assert_true(cast_local(&s, x, 3.0, 2.5, -4.0, -4.0, 1.0, &h));
    assert_near(h.fraction, 0.5, EPS);
    assert_vec2_near(h.point, w(x, 1.0, 0.5), EPS);
    assert_true(sx_approx_equal(h.normal, n1, (sx_real)EPS) ||
                sx_approx_equal(h.normal, n2, (sx_real)EPS));
}

static void ray_grazing_box_edge_hits_at_the_corner(void **state) {
    sx_xform x = sx_xform_make(v2(-2.0, 1.0), SX_R(0.0));
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -3.0, 0.5, 6.0, 0.0, 1.0, &h));
    check_hit(&h, 1.0 / 3.0, w(x, -1.0, 0.5), v2(-1.0, 0.0));
    assert_false(cast_local(&s, x, -3.0, 0.5001, 6.0, 0.0, 1.0, &h));
}

static void ray_misses_box_and_starts_inside_or_on_it(void **state) {
    sx_xform x = placed();
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_ray_hit h;
    (void)state;
    assert_false(cast_local(&s, x, -3.0, 0.0, -6.0, 0.0, 1.0, &h));
    assert_false(cast_local(&s, x, -3.0, 0.0, 1.9, 0.0, 1.0, &h));
    assert_false(cast_local(&s, x, -3.0, 0.0, 6.0, 0.0, 0.3, &h));
    assert_false(cast_local(&s, x, -3.0, 0.0, 3.0, 3.0, 1.0, &h)); /* passes above */
    assert_true(cast_local(&s, x, 0.2, 0.1, 1.0, 2.0, 1.0, &h));
    check_hit(&h, 0.0, w(x, 0.2, 0.1), wdir(x, -1.0 / sqrt(5.0), -2.0 / sqrt(5.0)));
    assert_true(cast_local(&s, x, 1.0, 0.1, 1.0, 0.0, 1.0, &h)); /* on the face, leaving */
    check_hit(&h, 0.0, w(x, 1.0, 0.1), wdir(x, -1.0, 0.0));
}

static void ray_hits_triangle_hypotenuse(void **state) {
    sx_vec2 v[3];
    sx_shape s;
    sx_xform x = placed();
    sx_ray_hit h;
    (void)state;
    v[0] = v2(0.0, 0.0);
    v[1] = v2(4.0, 0.0);
    v[2] = v2(0.0, 3.0);
    s = qf_polygon(v, 3, SX_R(0.0));
    /* From (4, 3) towards the origin: meets 3x + 4y = 12 at (2, 1.5). */
    assert_true(cast_local(&s, x, 4.0, 3.0, -4.0, -3.0, 1.0, &h));
    check_hit(&h, 0.5, w(x, 2.0, 1.5), wdir(x, 0.6, 0.8));
}

static void ray_hits_rounded_box_faces_and_corner_arcs_exactly(void **state) {
    sx_xform x = placed();
    sx_shape s = qf_rounded_box(SX_R(1.0), SX_R(1.0), SX_R(0.5));
    sx_ray_hit h;
    double r2 = 1.0 / sqrt(2.0), k = 1.0 + 0.5 * r2;
    double c = 1.0 + sqrt(0.25 - 0.04); /* x where y = 1.2 meets the corner circle */
    (void)state;
    assert_true(cast_local(&s, x, -3.0, 0.3, 6.0, 0.0, 1.0, &h));
    check_hit(&h, 0.25, w(x, -1.5, 0.3), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&s, x, 3.0, 3.0, -3.0, -3.0, 1.0, &h));
    check_hit(&h, (3.0 - k) / 3.0, w(x, k, k), wdir(x, r2, r2));
    assert_true(cast_local(&s, x, 3.0, 1.2, -3.0, 0.0, 1.0, &h));
    check_hit(&h, (3.0 - c) / 3.0, w(x, c, 1.2), wdir(x, (c - 1.0) / 0.5, 0.4));
    assert_false(cast_local(&s, x, 3.0, 1.48, -3.0, 0.4, 1.0, &h)); /* over the arc */
    assert_true(cast_local(&s, x, 1.2, 1.2, 3.0, 0.0, 1.0, &h));    /* in the rounding */
    check_hit(&h, 0.0, w(x, 1.2, 1.2), wdir(x, -1.0, 0.0));
    assert_true(cast_local(&s, x, 0.0, 0.0, 3.0, 0.0, 1.0, &h)); /* in the core */
    assert_true(h.fraction == SX_R(0.0));
}

static void ray_grazing_rounded_box_touches_the_offset_face(void **state) {
    sx_xform x = sx_xform_identity();
    sx_shape s = qf_rounded_box(SX_R(1.0), SX_R(1.0), SX_R(0.5));
    sx_ray_hit h;
    (void)state;
    assert_true(cast_local(&s, x, -3.0, 1.5, 6.0, 0.0, 1.0, &h));
    check_hit(&h, 1.0 / 3.0, v2(-1.0, 1.5), v2(0.0, 1.0));
    assert_false(cast_local(&s, x, -3.0, 1.5001, 6.0, 0.0, 1.0, &h));
}

/* ---- bad input and precision -------------------------------------------- */

static void ray_cast_rejects_zero_negative_and_non_finite_input(void **state) {
    sx_shape s = sx_circle_shape(v2(0.0, 0.0), SX_R(1.0));
    sx_xform x = sx_xform_identity();
    sx_real nan = (sx_real)NAN, inf = (sx_real)INFINITY;
    sx_ray_input r = ray_make(v2(-5.0, 0.0), v2(10.0, 0.0), 1.0);
    sx_ray_hit h;
    (void)state;
    assert_true(sx_ray_cast(&s, x, &r, NULL));
    r.translation = sx_v2_zero();
    assert_false(sx_ray_cast(&s, x, &r, &h));
    check_miss(&h);
    r.origin = sx_v2_zero(); /* even from inside */
    assert_false(sx_ray_cast(&s, x, &r, &h));
    r = ray_make(v2(-5.0, 0.0), v2(10.0, 0.0), -0.1);
    assert_false(sx_ray_cast(&s, x, &r, &h));
    r.max_fraction = nan;
    assert_false(sx_ray_cast(&s, x, &r, &h));
    r.max_fraction = inf;
    assert_false(sx_ray_cast(&s, x, &r, &h));
    r = ray_make(sx_v2(nan, SX_R(0.0)), v2(10.0, 0.0), 1.0);
    assert_false(sx_ray_cast(&s, x, &r, &h));
    r = ray_make(v2(-5.0, 0.0), sx_v2(SX_R(10.0), inf), 1.0);
    assert_false(sx_ray_cast(&s, x, &r, &h));
    check_miss(&h);
    r = ray_make(v2(-5.0, 0.0), v2(10.0, 0.0), 1.0);
    x.q.c = nan;
    assert_false(sx_ray_cast(&s, x, &r, &h));
    x = sx_xform_identity();
    assert_false(sx_ray_cast(NULL, x, &r, &h));
    assert_false(sx_ray_cast(&s, x, NULL, &h));
    s.u.circle.radius = SX_R(-1.0);
    assert_false(sx_ray_cast(&s, x, &r, &h));
}

static void ray_cast_with_tiny_translation_and_huge_fraction_stays_finite(void **state) {
    sx_shape s = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_ray_hit h;
    sx_ray_input r = ray_make(v2(-3.0, 0.0), v2(1e-20, 0.0), 3e20);
    (void)state;
    assert_true(sx_ray_cast(&s, sx_xform_identity(), &r, &h));
    assert_near(h.fraction, 2e20, 2e20 * 1e-5);
    assert_vec2_near(h.point, v2(-1.0, 0.0), 1e-4);
    r = ray_make(v2(-3.0, 0.0), v2(1.0, 0.0), (double)SX_REAL_MAX);
    assert_true(sx_ray_cast(&s, sx_xform_identity(), &r, &h));
    assert_near(h.fraction, 2.0, EPS);
}

static void ray_cast_far_from_origin_keeps_precision(void **state) {
    /* 1e5 in float: one ulp there is 0.0078, the local frame keeps the
     * fraction exact to rounding of the unit-size numbers. */
    sx_xform x = sx_xform_make(v2(1e5, -1e5), SX_R(0.3));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_shape circle = sx_circle_shape(v2(0.0, 0.0), SX_R(1.0));
    sx_shape cap = sx_capsule_shape(v2(0.0, -1.0), v2(0.0, 1.0), SX_R(0.25));
    sx_ray_input r = ray_make(v2(1e5 - 3.0, -1e5), v2(6.0, 0.0), 1.0);
    sx_ray_hit h;
    (void)state;
    assert_true(sx_ray_cast(&circle, x, &r, &h));
    assert_near(h.fraction, 1.0 / 3.0, 1e-5);
    assert_vec2_near(h.point, v2(1e5 - 1.0, -1e5), 0.02);
    assert_vec2_near(h.normal, v2(-1.0, 0.0), 1e-5);
    /* The same world-horizontal ray through the centre of the turned box
     * and capsule: it meets their -x faces 0.5 / cos(0.3) and
     * 0.25 / cos(0.3) before the centre. */
    assert_true(sx_ray_cast(&box, x, &r, &h));
    assert_near(h.fraction, (3.0 - 0.5 / cos(0.3)) / 6.0, 1e-5);
    assert_vec2_near(h.normal, wdir(x, -1.0, 0.0), 1e-5);
    assert_true(sx_ray_cast(&cap, x, &r, &h));
    assert_near(h.fraction, (3.0 - 0.25 / cos(0.3)) / 6.0, 1e-5);
    assert_vec2_near(h.normal, wdir(x, -1.0, 0.0), 1e-5);
}

/* ---- random properties -------------------------------------------------- */

static sx_real dist_at(const sx_shape *s, sx_xform x, const sx_ray_input *r, double f) {
    return sx_shape_distance_to_point(s, x, sx_mul_add(r->origin, (sx_real)f, r->translation), NULL,
                                      NULL);
}

static void random_ray_hits_lie_on_the_boundary_and_misses_stay_outside(void **state) {
    sx_test_rng rng = sx_test_rng_make(0xca57);
    int i, k, hits = 0, misses = 0;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        int kind;
        sx_shape s = qf_random_shape(&rng, &kind);
        sx_xform x = qf_random_xform(&rng);
        sx_vec2 c = sx_xform_point(x, qf_local_center(&s));
        /* Rays from around the shape towards a point near it, reaching
         * somewhere between short of it and well past it. */
        sx_vec2 o = sx_add(c, qf_random_vec(&rng, -6.0, 6.0));
        sx_vec2 target = sx_add(c, qf_random_vec(&rng, -2.5, 2.5));
        sx_ray_input r = ray_make(o, sx_scale(sx_sub(target, o), sx_test_rng_range(&rng, 0.6, 1.6)),
                                  0.3 + 1.2 * sx_test_rng_unit(&rng));
        sx_ray_hit h;
        if (sx_shape_distance_to_point(&s, x, r.origin, NULL, NULL) <= SX_R(0.01)) continue;
        if (sx_ray_cast(&s, x, &r, &h)) {
            hits++;
            assert_true(h.fraction >= SX_R(0.0) && h.fraction <= r.max_fraction);
            assert_near(sx_length(h.normal), 1.0, QF_TOL);
            assert_true(sx_dot(h.normal, r.translation) <= SX_R(0.0));
            assert_vec2_near(h.point, sx_mul_add(r.origin, h.fraction, r.translation), QF_TOL);
            assert_near(sx_shape_distance_to_point(&s, x, h.point, NULL, NULL), 0.0, QF_TOL);
            for (k = 0; k < 16; ++k) {
                assert_true(dist_at(&s, x, &r, (double)h.fraction * k / 16.0) > -QF_TOL);
            }
        } else {
            misses++;
            assert_false(h.hit);
            for (k = 0; k <= 64; ++k) {
                assert_true(dist_at(&s, x, &r, (double)r.max_fraction * k / 64.0) > -QF_TOL);
            }
        }
    }
    assert_true(hits > 4000 && misses > 4000);
}

static void random_ray_aimed_at_the_centroid_from_outside_always_hits(void **state) {
    sx_test_rng rng = sx_test_rng_make(0xa13d);
    int i, tested = 0;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        int kind;
        sx_shape s = qf_random_shape(&rng, &kind);
        sx_xform x = qf_random_xform(&rng);
        sx_vec2 c = sx_xform_point(x, qf_local_center(&s));
        sx_vec2 o = sx_add(c, qf_random_vec(&rng, -8.0, 8.0));
        /* The centroid at fraction 0.5: for a segment it is on the
         * boundary, and a hit exactly at max_fraction is at rounding's mercy. */
        sx_ray_input r = ray_make(o, sx_scale(sx_sub(c, o), SX_R(2.0)), 1.0);
        sx_ray_hit h;
        /* A point is hit only by an exact ray: excluded by contract. */
        if (s.type == SX_SHAPE_CIRCLE && s.u.circle.radius == SX_R(0.0)) continue;
        if (sx_shape_distance_to_point(&s, x, o, NULL, NULL) <= SX_R(0.0)) continue;
        tested++;
        assert_true(sx_ray_cast(&s, x, &r, &h));
        if (s.type == SX_SHAPE_SEGMENT) {
            /* Where a nearly parallel ray crosses a segment is ill-conditioned
             * (the rounding of the ray over sin(angle)), but not whether it
             * does or that the point is on the segment. */
            assert_true(sx_shape_distance_to_point(&s, x, h.point, NULL, NULL) <= QF_TOL);
        } else {
            assert_true(h.fraction <= SX_R(0.5) + QF_TOL);
        }
    }
    assert_true(tested > 15000);
}

static void random_ray_from_inside_hits_at_zero_facing_back(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x1a51de);
    int i;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        int kind;
        sx_shape s = qf_random_shape(&rng, &kind);
        sx_xform x = qf_random_xform(&rng);
        sx_ray_input r = ray_make(sx_xform_point(x, qf_local_sample(&rng, &s)),
                                  qf_random_vec(&rng, -5.0, 5.0), 1.0);
        sx_ray_hit h;
        if (!qf_is_solid(&s)) continue;
        if (sx_shape_distance_to_point(&s, x, r.origin, NULL, NULL) > -QF_TOL) continue;
        assert_true(sx_ray_cast(&s, x, &r, &h));
        assert_true(h.fraction == SX_R(0.0));
        assert_vec2_near(h.normal, sx_scale(r.translation, -SX_R(1.0) / sx_length(r.translation)),
                         QF_TOL);
        assert_true(h.point.x == r.origin.x && h.point.y == r.origin.y);
    }
}

static void random_rays_against_segments_agree_with_segment_intersection(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5e9ca57);
    int i, agreed = 0;
    (void)state;
    for (i = 0; i < 20000; ++i) {
        sx_shape s = qf_random_shape_of_kind(&rng, 2);
        sx_xform x = sx_xform_identity();
        sx_ray_input r =
            ray_make(qf_random_vec(&rng, -3.0, 3.0), qf_random_vec(&rng, -10.0, 10.0), 1.0);
        sx_segment_intersection o;
        sx_ray_hit h;
        bool hit = sx_ray_cast(&s, x, &r, &h);
        sx_segment_relation rel = sx_intersect_segments(r.origin, sx_add(r.origin, r.translation),
                                                        s.u.segment.a, s.u.segment.b, &o);
        if (rel == SX_SEGMENTS_INTERSECT) {
            agreed++;
            assert_true(hit);
            assert_vec2_near(h.point, o.point, QF_TOL);
            assert_near(h.fraction, o.t, QF_TOL);
        } else if (rel == SX_SEGMENTS_DISJOINT || rel == SX_SEGMENTS_PARALLEL) {
            assert_false(hit);
        }
    }
    assert_true(agreed > 2000);
}

static void hostile_input_never_crashes_or_yields_nan(void **state) {
    sx_test_rng rng = sx_test_rng_make(0xbad2);
    int i, hits = 0;
    (void)state;
    for (i = 0; i < 40000; ++i) {
        sx_xform x;
        sx_shape s = qf_wild_shape(&rng, &x);
        sx_ray_input r =
            ray_make(qf_wild_vec(&rng), qf_wild_vec(&rng), (double)sx_absr(qf_wild(&rng)));
        sx_ray_hit h;
        if (sx_ray_cast(&s, x, &r, &h)) {
            hits++;
            assert_true(h.hit && sx_is_finite(h.fraction) && h.fraction >= SX_R(0.0) &&
                        h.fraction <= r.max_fraction);
            assert_true(sx_vec2_is_finite(h.point) && sx_vec2_is_finite(h.normal));
        } else {
            assert_false(h.hit);
        }
    }
    assert_true(hits > 100);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ray_hits_circle_at_the_near_side),
        cmocka_unit_test(ray_grazing_circle_hits_at_the_tangent_point),
        cmocka_unit_test(ray_misses_circle_behind_beside_or_beyond_its_reach),
        cmocka_unit_test(ray_starting_inside_circle_hits_at_zero_facing_back),
        cmocka_unit_test(ray_through_a_point_shape_hits_it),
        cmocka_unit_test(ray_hits_segment_from_either_side),
        cmocka_unit_test(ray_through_segment_end_point_hits_and_just_beyond_misses),
        cmocka_unit_test(ray_along_segment_line_hits_the_near_end),
        cmocka_unit_test(near_parallel_ray_crossing_a_segment_hits_it),
        cmocka_unit_test(ray_starting_on_segment_hits_at_zero),
        cmocka_unit_test(ray_hits_capsule_sides_and_end_caps_exactly),
        cmocka_unit_test(ray_grazing_capsule_side_touches_where_cap_meets_side),
        cmocka_unit_test(ray_misses_capsule_and_starts_inside_it),
        cmocka_unit_test(degenerate_capsules_cast_as_segments_and_circles),
        cmocka_unit_test(ray_hits_rotated_box_face_with_its_normal),
        cmocka_unit_test(ray_through_box_vertex_hits_with_an_adjacent_face_normal),
        cmocka_unit_test(ray_grazing_box_edge_hits_at_the_corner),
        cmocka_unit_test(ray_misses_box_and_starts_inside_or_on_it),
        cmocka_unit_test(ray_hits_triangle_hypotenuse),
        cmocka_unit_test(ray_hits_rounded_box_faces_and_corner_arcs_exactly),
        cmocka_unit_test(ray_grazing_rounded_box_touches_the_offset_face),
        cmocka_unit_test(ray_cast_rejects_zero_negative_and_non_finite_input),
        cmocka_unit_test(ray_cast_with_tiny_translation_and_huge_fraction_stays_finite),
        cmocka_unit_test(ray_cast_far_from_origin_keeps_precision),
        cmocka_unit_test(random_ray_hits_lie_on_the_boundary_and_misses_stay_outside),
        cmocka_unit_test(random_ray_aimed_at_the_centroid_from_outside_always_hits),
        cmocka_unit_test(random_ray_from_inside_hits_at_zero_facing_back),
        cmocka_unit_test(random_rays_against_segments_agree_with_segment_intersection),
        cmocka_unit_test(hostile_input_never_crashes_or_yields_nan),
    };
    return cmocka_run_group_tests_name("raycast", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
