/* sepax tests — the long-double reference (tests/support/reference.c) checked
 * against answers worked out by hand: circles, boxes (also rotated), a box
 * and a circle in the corner region, rounded polygons, crossing capsules and
 * segments, plus its own internal consistency on random pairs (its direction
 * scores its depth along the projection formula, and no other direction
 * scores less). The narrowphase property tests trust this file. */
#include <math.h>

#include "reference.h"
#include "test_support.h"

/* The reference works in long double on values given exactly (or rounded
 * once to sx_real): hand answers hold to this. */
#define REF_TOL 1e-6

static sx_xform pose(double x, double y, double angle) {
    return sx_xform_make(sx_v2((sx_real)x, (sx_real)y), (sx_real)angle);
}

static sx_ref_result penetration(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    sx_ref_result r;
    assert_true(sx_ref_penetration(a, xa, b, xb, &r));
    return r;
}

static void assert_dir(const sx_ref_result *r, double x, double y, double tol) {
    assert_true(r->direction_defined);
    assert_near(r->dir_x, x, tol);
    assert_near(r->dir_y, y, tol);
}

static void circles_overlapping_give_radius_sum_minus_distance(void **state) {
    sx_shape a = sx_circle_shape(sx_v2_zero(), SX_R(1.0));
    sx_shape b = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(1.25, 0, 0));
    (void)state;
    assert_near(r.depth, 0.25, REF_TOL);
    assert_dir(&r, -1.0, 0.0, REF_TOL);
    assert_int_equal(r.hull_count, 1);
    /* Swapping the arguments flips the direction, keeps the depth. */
    r = penetration(&b, pose(1.25, 0, 0), &a, pose(0, 0, 0));
    assert_near(r.depth, 0.25, REF_TOL);
    assert_dir(&r, 1.0, 0.0, REF_TOL);
}

static void circles_apart_give_minus_gap_and_concentric_has_no_direction(void **state) {
    sx_shape a = sx_circle_shape(sx_v2(SX_R(0.5), SX_R(0.0)), SX_R(1.0));
    sx_shape b = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    /* World centres (0.5, 0) and (0.5, 3): 3 apart, radii 1.5 in all. */
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(0.5, 3.0, 0));
    (void)state;
    assert_near(r.depth, -1.5, REF_TOL);
    assert_dir(&r, 0.0, -1.0, REF_TOL);
    /* Translating A by depth * dir closes the gap exactly. */
    assert_near(r.core_distance, 3.0, REF_TOL);
    r = penetration(&a, pose(-0.5, 0, 0), &b, pose(0, 0, 0));
    assert_near(r.depth, 1.5, REF_TOL);
    assert_false(r.direction_defined);
}

static void point_is_a_circle_of_radius_zero(void **state) {
    sx_shape p = sx_point_shape(sx_v2_zero());
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(2.0));
    sx_ref_result r = penetration(&p, pose(0.5, -1.0, 0.3), &c, pose(0, 0, 0));
    (void)state;
    assert_near(r.depth, 2.0 - sqrt(1.25), REF_TOL);
    assert_dir(&r, 0.5 / sqrt(1.25), -1.0 / sqrt(1.25), REF_TOL);
}

static void boxes_overlap_along_the_shallower_axis(void **state) {
    sx_shape a = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape b = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(1.5, 0.2, 0));
    (void)state;
    assert_near(r.depth, 0.5, REF_TOL);
    assert_dir(&r, -1.0, 0.0, REF_TOL);
    /* The next escape (down, 1.8) is 1.3 longer. */
    assert_near(r.tie_gap, 1.3, REF_TOL);
    assert_near(r.core_distance, -0.5, REF_TOL);
}

static void boxes_apart_diagonally_give_corner_distance(void **state) {
    sx_shape a = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_shape b = sx_box_shape(SX_R(0.5), SX_R(0.5));
    /* Corner (1, 0.5) of A against corner (2, 1.5) of B: gap (1, 1). */
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(2.5, 2.0, 0));
    (void)state;
    assert_near(r.depth, -sqrt(2.0), REF_TOL);
    assert_dir(&r, -sqrt(0.5), -sqrt(0.5), REF_TOL);
}

static void rotated_boxes_rotate_the_answer(void **state) {
    sx_shape a = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape b = sx_box_shape(SX_R(1.0), SX_R(1.0));
    double t = 0.5235987755982988; /* 30 degrees */
    double c = cos(t), s = sin(t);
    /* The axis-aligned case above turned by 30 degrees about the origin. */
    sx_ref_result r =
        penetration(&a, pose(0, 0, t), &b, pose(1.5 * c - 0.2 * s, 1.5 * s + 0.2 * c, t));
    (void)state;
    assert_near(r.depth, 0.5, REF_TOL);
    assert_dir(&r, -c, -s, REF_TOL);
}

static void diamond_corner_into_box_face_is_vertex_depth(void **state) {
    /* A: unit-half box turned 45 degrees, its right vertex at x = sqrt 2.
     * B: half 0.5 box at (1.8, 0), left face at x = 1.3. Along x the vertex
     * is 0.1142 deep; along the diamond's normals 0.434: x wins. */
    sx_shape a = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape b = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_ref_result r = penetration(&a, pose(0, 0, 0.7853981633974483), &b, pose(1.8, 0, 0));
    (void)state;
    assert_near(r.depth, sqrt(2.0) - 1.3, REF_TOL);
    assert_dir(&r, -1.0, 0.0, REF_TOL);
}

static void box_and_circle_in_corner_region_push_along_the_diagonal(void **state) {
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape circle = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    double d = 0.3 * sqrt(2.0);
    sx_ref_result r = penetration(&box, pose(0, 0, 0), &circle, pose(1.3, 1.3, 0));
    (void)state;
    assert_near(r.depth, 0.5 - d, REF_TOL);
    assert_dir(&r, -sqrt(0.5), -sqrt(0.5), REF_TOL);
    r = penetration(&circle, pose(1.3, 1.3, 0), &box, pose(0, 0, 0));
    assert_near(r.depth, 0.5 - d, REF_TOL);
    assert_dir(&r, sqrt(0.5), sqrt(0.5), REF_TOL);
}

static void box_and_circle_centre_inside_escape_through_nearest_face(void **state) {
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(2.0));
    sx_shape circle = sx_circle_shape(sx_v2_zero(), SX_R(0.25));
    /* Circle centre at (0.75, -1.0) in the box: nearest face x = 1 at 0.25. */
    sx_ref_result r = penetration(&circle, pose(0.75, -1.0, 0), &box, pose(0, 0, 0));
    (void)state;
    assert_near(r.depth, 0.5, REF_TOL);
    assert_dir(&r, 1.0, 0.0, REF_TOL);
}

static void rounded_box_rounding_adds_to_the_depth(void **state) {
    sx_vec2 pts[4] = {{SX_R(-1.0), SX_R(-1.0)},
                      {SX_R(1.0), SX_R(-1.0)},
                      {SX_R(1.0), SX_R(1.0)},
                      {SX_R(-1.0), SX_R(1.0)}};
    sx_hull hull;
    sx_shape rounded, point = sx_point_shape(sx_v2_zero());
    sx_ref_result r;
    int i;
    (void)state;
    for (i = 0; i < 4; ++i)
        hull.points[i] = pts[i];
    hull.count = 4;
    assert_int_equal(sx_polygon_from_hull(&hull, SX_R(0.125), &rounded), SX_OK);
    r = penetration(&rounded, pose(0, 0, 0), &point, pose(1.0625, 0.5, 0));
    assert_near(r.depth, 0.0625, REF_TOL);
    assert_dir(&r, -1.0, 0.0, REF_TOL);
    /* In the rounded corner: distance to (1, 1) is 0.1 (a 0.06-0.08 triangle). */
    r = penetration(&rounded, pose(0, 0, 0), &point, pose(1.06, 1.08, 0));
    assert_near(r.depth, 0.025, REF_TOL);
    assert_dir(&r, -0.6, -0.8, REF_TOL);
}

static void crossing_capsules_escape_past_the_nearer_end(void **state) {
    /* A horizontal (-1,0)-(1,0) r 0.2; B vertical x = 0.3 from y -0.4 to 1
     * r 0.3. Escapes: down 0.9, left 1.2, up 1.5, right 1.8. */
    sx_shape a =
        sx_capsule_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.2));
    sx_shape b =
        sx_capsule_shape(sx_v2(SX_R(0.0), SX_R(-0.4)), sx_v2(SX_R(0.0), SX_R(1.0)), SX_R(0.3));
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(0.3, 0, 0));
    (void)state;
    assert_near(r.depth, 0.9, REF_TOL);
    assert_dir(&r, 0.0, -1.0, REF_TOL);
    assert_near(r.tie_gap, 0.3, REF_TOL);
}

static void crossing_segments_and_parallel_segments(void **state) {
    sx_shape a = sx_segment_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)));
    sx_shape b = sx_segment_shape(sx_v2(SX_R(0.2), SX_R(-0.5)), sx_v2(SX_R(0.2), SX_R(2.0)));
    sx_shape c = sx_segment_shape(sx_v2(SX_R(0.5), SX_R(0.3)), sx_v2(SX_R(2.0), SX_R(0.3)));
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(0, 0, 0));
    (void)state;
    assert_near(r.depth, 0.5, REF_TOL);
    assert_dir(&r, 0.0, -1.0, REF_TOL);
    r = penetration(&a, pose(0, 0, 0), &c, pose(0, 0, 0));
    assert_near(r.depth, -0.3, REF_TOL);
    assert_dir(&r, 0.0, -1.0, REF_TOL);
}

static void collinear_overlapping_segments_have_no_unique_direction(void **state) {
    sx_shape a = sx_segment_shape(sx_v2(SX_R(0.0), SX_R(0.0)), sx_v2(SX_R(2.0), SX_R(0.0)));
    sx_shape b = sx_segment_shape(sx_v2(SX_R(1.0), SX_R(0.0)), sx_v2(SX_R(3.0), SX_R(0.0)));
    sx_ref_result r = penetration(&a, pose(0, 0, 0), &b, pose(0, 0, 0));
    (void)state;
    assert_int_equal(r.hull_count, 2);
    assert_near(r.depth, 0.0, REF_TOL);
    assert_false(r.direction_defined);
    assert_near(fabs((double)r.dir_x), 0.0, REF_TOL);
    assert_near(fabs((double)r.dir_y), 1.0, REF_TOL);
    /* Collinear but apart: a gap of 0.5 along the line. */
    r = penetration(&a, pose(0, 0, 0), &b, pose(1.5, 0, 0));
    assert_near(r.depth, -0.5, REF_TOL);
    assert_dir(&r, -1.0, 0.0, REF_TOL);
}

static void segment_against_capsule_side(void **state) {
    sx_shape seg = sx_segment_shape(sx_v2(SX_R(-0.5), SX_R(0.0)), sx_v2(SX_R(0.5), SX_R(0.0)));
    sx_shape cap =
        sx_capsule_shape(sx_v2(SX_R(-2.0), SX_R(0.0)), sx_v2(SX_R(2.0), SX_R(0.0)), SX_R(0.5));
    sx_ref_result r = penetration(&seg, pose(0, 0.3, 0), &cap, pose(0, 0, 0));
    (void)state;
    assert_near(r.depth, 0.2, REF_TOL);
    assert_dir(&r, 0.0, 1.0, REF_TOL);
}

static void depth_along_own_direction_is_depth_and_no_direction_is_shallower(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5EFu);
    int k, i;
    (void)state;
    for (k = 0; k < 300; ++k) {
        sx_shape shapes[2];
        sx_xform poses[2];
        sx_ref_shape placed[2];
        sx_ref_result r;
        long double best = HUGE_VALL;
        for (i = 0; i < 2; ++i) {
            int type = (int)(sx_test_rng_next(&rng) % 4u);
            sx_vec2 p = sx_v2(sx_test_rng_range(&rng, -1, 1), sx_test_rng_range(&rng, -1, 1));
            sx_vec2 q = sx_v2(sx_test_rng_range(&rng, -1, 1), sx_test_rng_range(&rng, -1, 1));
            sx_real rad = sx_test_rng_range(&rng, 0, 0.5);
            if (type == 0) shapes[i] = sx_circle_shape(p, rad);
            if (type == 1) shapes[i] = sx_segment_shape(p, q);
            if (type == 2) shapes[i] = sx_capsule_shape(p, q, rad);
            if (type == 3) {
                shapes[i] = sx_offset_box_shape(sx_test_rng_range(&rng, 0.1, 1),
                                                sx_test_rng_range(&rng, 0.1, 1), p,
                                                sx_test_rng_range(&rng, 0, 3));
            }
            poses[i] =
                pose((double)sx_test_rng_range(&rng, -1, 1), (double)sx_test_rng_range(&rng, -1, 1),
                     (double)sx_test_rng_range(&rng, -3.2, 3.2));
            assert_true(sx_ref_place(&shapes[i], poses[i], &placed[i]));
        }
        assert_true(sx_ref_penetration_placed(&placed[0], &placed[1], &r));
        assert_near(sx_ref_depth_along(&placed[0], &placed[1], r.dir_x, r.dir_y), r.depth, 1e-12);
        for (i = 0; i < 720; ++i) {
            long double t = (long double)i * (acosl(-1.0L) / 360.0L);
            long double d = sx_ref_depth_along(&placed[0], &placed[1], cosl(t), sinl(t));
            assert_true(d >= r.depth - 1e-12L);
            if (d < best) best = d;
        }
        /* Sampling every half degree misses the optimum by at most the
         * extent of the core difference (< 10 here) times the half step. */
        assert_true(best - r.depth <= 10.0L * (acosl(-1.0L) / 720.0L));
        /* Translating A by depth * dir leaves the shapes exactly touching. */
        {
            sx_ref_shape moved = placed[0];
            sx_ref_result t;
            for (i = 0; i < moved.count; ++i) {
                moved.x[i] += r.depth * r.dir_x;
                moved.y[i] += r.depth * r.dir_y;
            }
            assert_true(sx_ref_penetration_placed(&moved, &placed[1], &t));
            if (r.direction_defined) assert_near(t.depth, 0.0, 1e-12);
        }
    }
}

static void rotating_both_poses_rotates_the_reference_direction(void **state) {
    sx_shape a =
        sx_capsule_shape(sx_v2(SX_R(-0.3), SX_R(0.1)), sx_v2(SX_R(0.7), SX_R(0.4)), SX_R(0.2));
    sx_shape b = sx_offset_box_shape(SX_R(0.4), SX_R(0.3), sx_v2(SX_R(0.1), SX_R(0.0)), SX_R(0.3));
    sx_ref_result r0 = penetration(&a, pose(0.1, 0.2, 0.4), &b, pose(0.5, 0.1, -0.2));
    double t = 1.1, c = cos(t), s = sin(t);
    sx_ref_result r1 = penetration(&a, pose(0.1 * c - 0.2 * s, 0.1 * s + 0.2 * c, 0.4 + t), &b,
                                   pose(0.5 * c - 0.1 * s, 0.5 * s + 0.1 * c, -0.2 + t));
    (void)state;
    assert_true(r0.depth > 0.0L);
    /* The poses are rounded to sx_real, so agreement is at that precision. */
    assert_near(r1.depth, r0.depth, 10.0 * SX_TEST_EPS);
    assert_near(r1.dir_x, c * (double)r0.dir_x - s * (double)r0.dir_y, 10.0 * SX_TEST_EPS);
    assert_near(r1.dir_y, s * (double)r0.dir_x + c * (double)r0.dir_y, 10.0 * SX_TEST_EPS);
}

static void point_distance_is_signed_and_has_outward_normal(void **state) {
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_shape cap =
        sx_capsule_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.5));
    sx_shape seg = sx_segment_shape(sx_v2(SX_R(0.0), SX_R(0.0)), sx_v2(SX_R(2.0), SX_R(0.0)));
    sx_shape circle = sx_circle_shape(sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(1.0));
    /* Box turned 90 degrees at (2, 3): world half-extents 0.5 x 1. */
    sx_xform x = pose(2.0, 3.0, 1.5707963267948966);
    long double nx, ny, d;
    (void)state;
    d = sx_ref_distance_to_point(&box, x, 2.0L, 3.0L, &nx, &ny);
    assert_near(d, -0.5, REF_TOL);
    assert_near(fabs((double)nx), 1.0, REF_TOL);
    d = sx_ref_distance_to_point(&box, x, 4.5L, 3.0L, &nx, &ny);
    assert_near(d, 2.0, REF_TOL);
    assert_near(nx, 1.0, REF_TOL);
    assert_near(ny, 0.0, REF_TOL);
    d = sx_ref_distance_to_point(&box, x, 2.5L + 0.3L, 4.0L + 0.4L, &nx, &ny);
    assert_near(d, 0.5, REF_TOL);
    assert_near(nx, 0.6, REF_TOL);
    assert_near(ny, 0.8, REF_TOL);
    d = sx_ref_distance_to_point(&cap, pose(0, 0, 0), 0.25L, 0.25L, &nx, &ny);
    assert_near(d, -0.25, REF_TOL);
    assert_near(ny, 1.0, REF_TOL);
    d = sx_ref_distance_to_point(&cap, pose(0, 0, 0), -2.0L, 0.0L, &nx, &ny);
    assert_near(d, 0.5, REF_TOL);
    assert_near(nx, -1.0, REF_TOL);
    /* On the segment itself: distance 0, the left normal perp(b - a). */
    d = sx_ref_distance_to_point(&seg, pose(0, 0, 0), 1.0L, 0.0L, &nx, &ny);
    assert_near(d, 0.0, REF_TOL);
    assert_near(nx, 0.0, REF_TOL);
    assert_near(ny, 1.0, REF_TOL);
    /* At a circle's centre: -radius and the +x fallback. */
    d = sx_ref_distance_to_point(&circle, pose(0, 0, 0), 1.0L, 0.0L, &nx, &ny);
    assert_near(d, -1.0, REF_TOL);
    assert_near(nx, 1.0, REF_TOL);
    assert_near(ny, 0.0, REF_TOL);
}

static void unplaceable_input_is_reported_not_answered(void **state) {
    sx_shape bad = sx_circle_shape(sx_v2_zero(), SX_R(-1.0));
    sx_shape ok = sx_circle_shape(sx_v2_zero(), SX_R(1.0));
    sx_shape poly = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_ref_result r;
    sx_ref_shape placed;
    (void)state;
    assert_false(sx_ref_penetration(&bad, pose(0, 0, 0), &ok, pose(0, 0, 0), &r));
    assert_false(sx_ref_penetration(NULL, pose(0, 0, 0), &ok, pose(0, 0, 0), &r));
    poly.u.polygon.count = SX_MAX_POLYGON_VERTICES + 1;
    assert_false(sx_ref_place(&poly, pose(0, 0, 0), &placed));
    assert_true(
        isinf((double)sx_ref_distance_to_point(&bad, pose(0, 0, 0), 0.0L, 0.0L, NULL, NULL)));
}

static void angle_between_directions(void **state) {
    (void)state;
    assert_near(sx_ref_angle_between(1.0L, 0.0L, 0.0L, 2.0L), 1.5707963267948966, 1e-15);
    assert_near(sx_ref_angle_between(1.0L, 1.0L, -3.0L, -3.0L), 3.141592653589793, 1e-15);
    assert_near(sx_ref_angle_between(0.0L, 0.0L, 1.0L, 0.0L), 3.141592653589793, 1e-15);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circles_overlapping_give_radius_sum_minus_distance),
        cmocka_unit_test(circles_apart_give_minus_gap_and_concentric_has_no_direction),
        cmocka_unit_test(point_is_a_circle_of_radius_zero),
        cmocka_unit_test(boxes_overlap_along_the_shallower_axis),
        cmocka_unit_test(boxes_apart_diagonally_give_corner_distance),
        cmocka_unit_test(rotated_boxes_rotate_the_answer),
        cmocka_unit_test(diamond_corner_into_box_face_is_vertex_depth),
        cmocka_unit_test(box_and_circle_in_corner_region_push_along_the_diagonal),
        cmocka_unit_test(box_and_circle_centre_inside_escape_through_nearest_face),
        cmocka_unit_test(rounded_box_rounding_adds_to_the_depth),
        cmocka_unit_test(crossing_capsules_escape_past_the_nearer_end),
        cmocka_unit_test(crossing_segments_and_parallel_segments),
        cmocka_unit_test(collinear_overlapping_segments_have_no_unique_direction),
        cmocka_unit_test(segment_against_capsule_side),
        cmocka_unit_test(depth_along_own_direction_is_depth_and_no_direction_is_shallower),
        cmocka_unit_test(rotating_both_poses_rotates_the_reference_direction),
        cmocka_unit_test(point_distance_is_signed_and_has_outward_normal),
        cmocka_unit_test(unplaceable_input_is_reported_not_answered),
        cmocka_unit_test(angle_between_directions),
    };
    return cmocka_run_group_tests_name("reference", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
