/* sepax tests — the narrowphase: overlap, MTV and manifolds for every pair of
 * shape types, in both argument orders, on configurations whose answers are
 * known analytically (separated, touching, shallow, deep, contained,
 * identical, rotated, vertex and edge contacts), plus the contract's edge
 * cases: exact negation of the MTV under swapped arguments, the box fast path
 * agreeing with the general SAT, translation invariance far from the origin,
 * degenerate shapes, non-finite input, and stable feature ids. */
#include <float.h>
#include <string.h>

#include "../../src/narrow.h"
#include "test_support.h"

#ifdef SX_DOUBLE
#define TOL 1e-9
#else
#define TOL 2e-5
#endif

/* The manifold's deepest point may exceed the MTV by the reference-face
 * hysteresis (collide.h). */
/* pi in double: angles are passed to X() as doubles. */
#define PI 3.14159265358979323846

#define HYSTERESIS (0.02 * (double)SX_LINEAR_SLOP)

static sx_vec2 V(double x, double y) { return sx_v2((sx_real)x, (sx_real)y); }
static sx_xform X(double x, double y, double angle) {
    return sx_xform_make(V(x, y), (sx_real)angle);
}
static sx_xform I(void) { return sx_xform_identity(); }

static sx_shape circle(double x, double y, double r) {
    return sx_circle_shape(V(x, y), (sx_real)r);
}
static sx_shape segment(double ax, double ay, double bx, double by) {
    return sx_segment_shape(V(ax, ay), V(bx, by));
}
static sx_shape capsule(double ax, double ay, double bx, double by, double r) {
    return sx_capsule_shape(V(ax, ay), V(bx, by), (sx_real)r);
}
static sx_shape box(double hw, double hh) { return sx_box_shape((sx_real)hw, (sx_real)hh); }
static sx_shape hull_shape(const double *xy, int n, double radius) {
    sx_hull h;
    sx_shape s;
    int i;
    h.count = n;
    for (i = 0; i < n; ++i)
        h.points[i] = V(xy[2 * i], xy[2 * i + 1]);
    assert_int_equal(sx_polygon_from_hull(&h, (sx_real)radius, &s), SX_OK);
    return s;
}
static sx_shape rounded_box(double hw, double hh, double radius) {
    double xy[8];
    xy[0] = -hw;
    xy[1] = -hh;
    xy[2] = hw;
    xy[3] = -hh;
    xy[4] = hw;
    xy[5] = hh;
    xy[6] = -hw;
    xy[7] = hh;
    return hull_shape(xy, 4, radius);
}

static double deepest(const sx_manifold *m) {
    double d = -1e30;
    int i;
    for (i = 0; i < m->count; ++i) {
        if ((double)m->points[i].depth > d) d = (double)m->points[i].depth;
    }
    return d;
}

/* Checks one configuration in both argument orders through the generic entry
 * points: overlap, MTV (value, and exact negation when swapped), and the
 * manifold (count, unit normal opposite to the MTV, deepest depth equal to
 * the MTV length, depths >= 0, normals opposite when swapped). */
static void check_pair(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, bool overlap,
                       sx_vec2 mtv, double tol) {
    sx_vec2 m1, m2;
    sx_manifold c1, c2;
    int n1, n2, i;
    double len;
    assert_int_equal(sx_overlap(a, xa, b, xb), overlap);
    assert_int_equal(sx_overlap(b, xb, a, xa), overlap);
    assert_int_equal(sx_mtv(a, xa, b, xb, &m1), overlap);
    assert_int_equal(sx_mtv(b, xb, a, xa, &m2), overlap);
    assert_vec2_near(m1, mtv, tol);
    assert_true(m2.x == -m1.x && m2.y == -m1.y);
    n1 = sx_collide(a, xa, b, xb, &c1);
    n2 = sx_collide(b, xb, a, xa, &c2);
    assert_int_equal(n1, c1.count);
    assert_int_equal(n2, c2.count);
    if (!overlap) {
        assert_int_equal(n1, 0);
        assert_int_equal(n2, 0);
        return;
    }
    assert_in_range(n1, 1, 2);
    assert_in_range(n2, 1, 2);
    assert_near(sx_length(c1.normal), 1.0, tol);
    /* Mixed pairs mirror one computation exactly; same-type manifolds follow
     * the caller's order, and near-equal faces (hysteresis) or a zero-area
     * contact may then pick another face. */
    if (a->type != b->type) {
        assert_true(c2.normal.x == -c1.normal.x && c2.normal.y == -c1.normal.y);
    }
    len = (double)sx_length(m1);
    assert_true(deepest(&c1) >= len - tol && deepest(&c1) <= len + tol + HYSTERESIS);
    assert_true(deepest(&c2) >= len - tol && deepest(&c2) <= len + tol + HYSTERESIS);
    /* The normal opposes the MTV. Same-type pairs are left out: their MTV
     * comes from the canonical order and their manifold from the caller's,
     * which may pick the other of two tied faces (the depth still agrees,
     * checked above); the cases below check those normals explicitly. */
    if (len > 10 * tol && a->type != b->type) {
        assert_vec2_near(c1.normal, sx_scale(m1, (sx_real)(-1.0 / len)), 10 * tol);
    }
    for (i = 0; i < n1; ++i) {
        assert_true(c1.points[i].depth >= SX_R(0.0));
        assert_true(sx_vec2_is_finite(c1.points[i].point));
    }
    for (i = 0; i < n2; ++i)
        assert_true(c2.points[i].depth >= SX_R(0.0));
}

/* Asserts the manifold holds exactly the given points (either order). */
static void expect_points(const sx_manifold *m, int count, sx_vec2 p0, sx_vec2 p1, double tol) {
    assert_int_equal(m->count, count);
    if (count == 1) {
        assert_vec2_near(m->points[0].point, p0, tol);
    } else if (sx_distance(m->points[0].point, p0) <= (sx_real)tol) {
        assert_vec2_near(m->points[1].point, p1, tol);
    } else {
        assert_vec2_near(m->points[0].point, p1, tol);
        assert_vec2_near(m->points[1].point, p0, tol);
    }
}

/* ---- circle - circle ---------------------------------------------------- */

static void circles_separated_touching_and_overlapping(void **state) {
    sx_shape a = circle(0, 0, 1), b = circle(0, 0, 1);
    sx_manifold m;
    (void)state;
    check_pair(&a, I(), &b, X(3, 0, 0), false, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(2, 0, 0), true, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(1.5, 0, 0), true, V(-0.5, 0), TOL);
    check_pair(&a, I(), &b, X(0, -1.2, 0.3), true, V(0, 0.8), TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(1.5, 0, 0), &m), 1);
    assert_vec2_near(m.normal, V(1, 0), TOL);
    assert_vec2_near(m.points[0].point, V(0.75, 0), TOL);
    assert_near(m.points[0].depth, 0.5, TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(2, 0, 0), &m), 1);
    assert_near(m.points[0].depth, 0.0, TOL);
    assert_vec2_near(m.points[0].point, V(1, 0), TOL);
    /* Speculative: 0.01 apart, reported with a margin of 0.02 only. */
    assert_int_equal(sx_collide_ex(&a, I(), &b, X(2.01, 0, 0), SX_R(0.02), &m), 1);
    assert_near(m.points[0].depth, -0.01, TOL);
    assert_vec2_near(m.points[0].point, V(1.005, 0), TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(2.01, 0, 0), &m), 0);
    assert_int_equal(m.count, 0);
}

static void swapped_circles_give_exactly_mirrored_answers(void **state) {
    sx_shape a = circle(0.3, -0.2, 0.7), b = circle(-0.1, 0.4, 0.45);
    sx_xform xa = X(100.25, -3.5, 0.7), xb = X(100.5, -3.0, -2.1);
    sx_manifold m1, m2;
    sx_vec2 v1, v2;
    (void)state;
    assert_true(sx_mtv(&a, xa, &b, xb, &v1));
    assert_true(sx_mtv(&b, xb, &a, xa, &v2));
    assert_true(v1.x == -v2.x && v1.y == -v2.y);
    assert_int_equal(sx_collide(&a, xa, &b, xb, &m1), 1);
    assert_int_equal(sx_collide(&b, xb, &a, xa, &m2), 1);
    assert_true(m1.normal.x == -m2.normal.x && m1.normal.y == -m2.normal.y);
    assert_true(m1.points[0].depth == m2.points[0].depth);
    assert_vec2_near(m1.points[0].point, m2.points[0].point, 1e-4);
}

static void circles_with_offset_centres_use_the_local_centres(void **state) {
    sx_shape a = circle(1, 0, 0.5), b = circle(0, 1, 0.5);
    (void)state;
    /* A's centre at (1, 0); B's local (0, 1) turned 90 degrees is (-1, 0),
     * so B placed at x has its centre at x - 1. */
    check_pair(&a, I(), &b, X(1.0, 0, PI / 2), true, V(0, 0), 1e-4);
    check_pair(&a, I(), &b, X(1.2, 0, PI / 2), true, V(0.2, 0), 1e-4);
}

static void concentric_circles_push_by_the_sum_of_radii(void **state) {
    sx_shape a = circle(0, 0, 1), b = circle(0, 0, 0.5);
    sx_vec2 mtv;
    (void)state;
    /* No direction exists: the first circle of the canonical order pushes
     * along its local x axis, so the answer is +-x here. */
    assert_true(sx_mtv(&a, I(), &b, I(), &mtv));
    assert_near(sx_absr(mtv.x), 1.5, TOL);
    assert_near(mtv.y, 0.0, TOL);
    check_pair(&a, I(), &b, I(), true, mtv, TOL);
    assert_true(sx_mtv(&a, X(4, 4, PI / 2), &b, X(4, 4, 0), &mtv));
    assert_near(sx_length(mtv), 1.5, TOL);
    check_pair(&a, X(4, 4, PI / 2), &b, X(4, 4, 0), true, mtv, TOL);
}

static void point_inside_circle_is_pushed_out_radially(void **state) {
    sx_shape p = sx_point_shape(V(0, 0)), c = circle(0, 0, 1);
    (void)state;
    check_pair(&p, X(0.5, 0, 0), &c, I(), true, V(0.5, 0), TOL);
    check_pair(&p, X(0, 1, 0), &c, I(), true, V(0, 0), TOL);
    check_pair(&p, X(0, 1.01, 0), &c, I(), false, V(0, 0), TOL);
}

/* ---- segment - circle --------------------------------------------------- */

static void segment_circle_face_end_and_separated(void **state) {
    sx_shape s = segment(-1, 0, 1, 0), c = circle(0, 0, 0.5);
    sx_manifold m;
    (void)state;
    check_pair(&s, I(), &c, X(0, 2, 0), false, V(0, 0), TOL);
    check_pair(&s, I(), &c, X(0, 0.5, 0), true, V(0, 0), TOL);
    check_pair(&s, I(), &c, X(0, 0.3, 0), true, V(0, -0.2), TOL);
    check_pair(&s, I(), &c, X(0.2, -0.4, 0), true, V(0, 0.1), TOL);
    check_pair(&s, I(), &c, X(1.3, 0, 0), true, V(-0.2, 0), TOL);
    check_pair(&s, I(), &c, X(-1.3, 0.4, 0), true, V(0, 0), TOL);
    check_pair(&s, I(), &c, X(-1.3, 0.41, 0), false, V(0, 0), TOL);
    assert_int_equal(sx_collide(&s, I(), &c, X(0, 0.3, 0), &m), 1);
    assert_vec2_near(m.normal, V(0, 1), TOL);
    assert_vec2_near(m.points[0].point, V(0, -0.1), TOL);
}

static void circle_centred_on_segment_is_pushed_by_full_radius(void **state) {
    sx_shape s = segment(-1, 0, 1, 0), c = circle(0, 0, 0.5);
    sx_vec2 mtv;
    (void)state;
    assert_true(sx_mtv(&s, I(), &c, I(), &mtv));
    assert_near(sx_length(mtv), 0.5, TOL);
    assert_near(mtv.x, 0.0, TOL);
    check_pair(&s, I(), &c, I(), true, mtv, TOL);
}

static void zero_length_segment_acts_as_a_point(void **state) {
    sx_shape s = segment(0.5, 0, 0.5, 0), c = circle(0, 0, 1);
    (void)state;
    check_pair(&s, I(), &c, I(), true, V(0.5, 0), TOL);
    check_pair(&s, X(1, 0, 0), &c, I(), false, V(0, 0), TOL);
    check_pair(&s, X(0.5, 0, 0), &c, I(), true, V(0, 0), TOL);
}

/* ---- segment - segment -------------------------------------------------- */

static void crossing_segments_overlap_by_the_shorter_push(void **state) {
    sx_shape a = segment(-1, 0, 1, 0), b = segment(0.2, -0.3, 0.2, 1);
    (void)state;
    check_pair(&a, I(), &b, I(), true, V(0, -0.3), TOL);
    check_pair(&a, I(), &b, X(5, 5, 0), false, V(0, 0), TOL);
}

static void parallel_and_collinear_segments(void **state) {
    sx_shape a = segment(-1, 0, 1, 0);
    sx_shape above = segment(-1, 0.5, 1, 0.5);
    sx_shape beyond = segment(2, 0, 3, 0);
    sx_shape sharing = segment(0.5, 0, 2, 0);
    sx_shape end_to_end = segment(1, 0, 2, 0);
    sx_shape tee = segment(0, 0, 0, 1);
    (void)state;
    check_pair(&a, I(), &above, I(), false, V(0, 0), TOL);
    check_pair(&a, I(), &beyond, I(), false, V(0, 0), TOL);
    check_pair(&a, I(), &sharing, I(), true, V(0, 0), TOL);
    check_pair(&a, I(), &end_to_end, I(), true, V(0, 0), TOL);
    check_pair(&a, I(), &tee, I(), true, V(0, 0), TOL);
}

static void near_parallel_crossing_segments_have_tiny_depth(void **state) {
    sx_shape a = segment(-1, 0, 1, 0), b = segment(-1, 1e-3, 1, -1e-3);
    sx_vec2 mtv;
    (void)state;
    assert_true(sx_mtv(&a, I(), &b, I(), &mtv));
    /* Each end of B lies 1e-3 off A's line and each end of A 1e-3 x cos off
     * B's: the shorter push is A's end out of B's line, ~0.9999995e-3. */
    assert_near(sx_length(mtv), 0.9999995e-3, 1e-4 * 1e-3 + TOL);
    check_pair(&a, I(), &b, I(), true, mtv, TOL);
}

/* ---- capsule - circle / segment / capsule ------------------------------- */

static void capsule_circle_side_cap_and_inside(void **state) {
    sx_shape k = capsule(-1, 0, 1, 0, 0.5), c = circle(0, 0, 0.25);
    (void)state;
    check_pair(&k, I(), &c, X(0, 1, 0), false, V(0, 0), TOL);
    check_pair(&k, I(), &c, X(0, 0.75, 0), true, V(0, 0), TOL);
    check_pair(&k, I(), &c, X(0.3, 0.6, 0), true, V(0, -0.15), TOL);
    check_pair(&k, I(), &c, X(1.6, 0, 0), true, V(-0.15, 0), TOL);
    check_pair(&k, I(), &c, X(0, -0.1, 0), true, V(0, 0.65), TOL);
    check_pair(&k, X(10, 0, PI / 2), &c, X(10, 1.6, 0), true, V(0, -0.15), TOL);
}

static void degenerate_capsule_is_a_circle(void **state) {
    sx_shape k = capsule(0, 0, 0, 0, 1), c = circle(0, 0, 1);
    (void)state;
    check_pair(&k, I(), &c, X(1.5, 0, 0), true, V(-0.5, 0), TOL);
    check_pair(&k, I(), &c, X(0, 2.5, 0), false, V(0, 0), TOL);
}

static void capsule_segment_crossing_and_parallel(void **state) {
    sx_shape k = capsule(-1, 0, 1, 0, 0.5);
    sx_shape across = segment(0, -0.2, 0, 2);
    sx_shape parallel = segment(-0.5, 0.4, 0.5, 0.4);
    sx_manifold m;
    (void)state;
    /* Cores cross: core depth 0.2 along y, plus the radius. */
    check_pair(&k, I(), &across, I(), true, V(0, -0.7), TOL);
    check_pair(&k, I(), &parallel, I(), true, V(0, -0.1), TOL);
    check_pair(&k, I(), &parallel, X(0, 0.2, 0), false, V(0, 0), TOL);
    assert_int_equal(sx_collide(&k, I(), &parallel, I(), &m), 2);
    expect_points(&m, 2, V(-0.5, 0.45), V(0.5, 0.45), TOL);
}

static void parallel_capsules_give_two_points(void **state) {
    sx_shape a = capsule(-1, 0, 1, 0, 0.5), b = capsule(-1, 0, 1, 0, 0.5);
    sx_manifold m;
    (void)state;
    check_pair(&a, I(), &b, X(0, 0.8, 0), true, V(0, -0.2), TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(0, 0.8, 0), &m), 2);
    expect_points(&m, 2, V(-1, 0.4), V(1, 0.4), TOL);
    assert_near(m.points[0].depth, 0.2, TOL);
    assert_near(m.points[1].depth, 0.2, TOL);
    /* Shifted along: the points are clipped to the overlap of the two. */
    assert_int_equal(sx_collide(&a, I(), &b, X(1.5, 0.8, 0), &m), 2);
    expect_points(&m, 2, V(0.5, 0.4), V(1, 0.4), TOL);
}

static void capsules_end_to_end_and_crossed(void **state) {
    sx_shape a = capsule(-1, 0, 1, 0, 0.5), b = capsule(0, 0, 1.5, 0, 0.5);
    sx_shape cross = capsule(0, -1, 0, 1, 0.25);
    sx_manifold m;
    (void)state;
    check_pair(&a, I(), &b, X(1.5, 0, 0), true, V(-0.5, 0), TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(1.5, 0, 0), &m), 1);
    assert_vec2_near(m.points[0].point, V(1.25, 0), TOL);
    check_pair(&a, I(), &b, X(2.0, 0, 0), true, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(2.1, 0, 0), false, V(0, 0), TOL);
    /* Crossed: the cores cross; the cheapest core push is 0.5 along x (B's
     * face), plus 0.75 of rounding. */
    check_pair(&a, I(), &cross, X(0.5, 0, 0), true, V(-1.25, 0), TOL);
}

/* ---- polygon - circle --------------------------------------------------- */

static void box_circle_face_corner_inside_touching(void **state) {
    sx_shape bx = box(1, 1), c = circle(0, 0, 0.5);
    double d = 1.3 * sqrt(2.0) - sqrt(2.0);
    sx_manifold m;
    (void)state;
    check_pair(&bx, I(), &c, X(3, 0, 0), false, V(0, 0), TOL);
    check_pair(&bx, I(), &c, X(1.5, 0, 0), true, V(0, 0), TOL);
    check_pair(&bx, I(), &c, X(1.3, 0.2, 0), true, V(-0.2, 0), TOL);
    check_pair(&bx, I(), &c, X(0.5, 0, 0), true, V(-1.0, 0), TOL);
    /* Corner region: along the diagonal, depth 0.5 - 0.3 sqrt 2. */
    check_pair(&bx, I(), &c, X(1.3, 1.3, 0), true,
               V(-(0.5 - d) / sqrt(2.0), -(0.5 - d) / sqrt(2.0)), TOL);
    check_pair(&bx, I(), &c, X(1.4, 1.4, 0), false, V(0, 0), TOL);
    assert_int_equal(sx_collide(&bx, I(), &c, X(1.3, 0.2, 0), &m), 1);
    assert_vec2_near(m.points[0].point, V(0.9, 0.2), TOL);
    assert_int_equal(m.points[0].id, SX_FEATURE_ID(1, 0, 0));
}

static void circle_just_inside_a_face_region_uses_the_exact_face_normal(void **state) {
    sx_shape bx = box(1, 1), c = circle(0, 0, 0.5);
    sx_vec2 mtv;
    sx_manifold m;
    (void)state;
    /* The centre projects 5e-5 inside the top face, next to the corner: in
     * float the squared distances to the face and to the corner round to the
     * same value; the face's exact normal must win (the corner's direction
     * would be off by 1.7e-4 rad). */
    assert_true(sx_mtv(&bx, I(), &c, X(1 - 5e-5, 1.3, 0), &mtv));
    assert_near(mtv.x, 0.0, 1e-7);
    assert_near(mtv.y, -0.2, TOL);
    assert_int_equal(sx_collide(&bx, I(), &c, X(1 - 5e-5, 1.3, 0), &m), 1);
    assert_vec2_near(m.normal, V(0, 1), 1e-7);
    assert_vec2_near(m.points[0].point, V(1 - 5e-5, 0.9), TOL);
}

static void rotated_box_and_point(void **state) {
    sx_shape bx = box(1, 1), p = sx_point_shape(V(0, 0));
    (void)state;
    /* A diamond (box turned 45 degrees) at the origin; the point sits 0.1
     * inside the upper-right face, whose normal is (1, 1)/sqrt 2. */
    double s = 0.9;
    check_pair(&bx, X(0, 0, PI / 4), &p, X(s / sqrt(2.0), s / sqrt(2.0), 0), true,
               V(-0.1 / sqrt(2.0), -0.1 / sqrt(2.0)), 1e-4);
    check_pair(&bx, X(0, 0, PI / 4), &p, X(1.42, 0, 0), false, V(0, 0), TOL);
}

static void rounded_polygon_and_circle(void **state) {
    /* Binary-exact sizes so that "touching" is exact in both builds. */
    sx_shape rb = rounded_box(1, 1, 0.125), c = circle(0, 0, 0.5);
    double k = 0.625 / sqrt(2.0);
    (void)state;
    check_pair(&rb, I(), &c, X(1.5, 0, 0), true, V(-0.125, 0), TOL);
    check_pair(&rb, I(), &c, X(1.625, 0, 0), true, V(0, 0), TOL);
    check_pair(&rb, I(), &c, X(1.75, 0, 0), false, V(0, 0), TOL);
    /* Rounded corner touching along the diagonal (1e-6 inside: the exact
     * contact is irrational and would round either way). */
    check_pair(&rb, I(), &c, X(1 + k - 1e-6, 1 + k - 1e-6, 0), true, V(0, 0), 1e-4);
    check_pair(&rb, I(), &c, X(1.01 + k, 1.01 + k, 0), false, V(0, 0), TOL);
}

/* ---- polygon - segment / capsule ---------------------------------------- */

static void box_segment_through_and_resting(void **state) {
    sx_shape bx = box(1, 1);
    sx_shape through = segment(-2, 0.5, 2, 0.5);
    sx_shape on_top = segment(-0.5, 1, 0.5, 1);
    sx_shape hovering = segment(-0.5, 1.01, 0.5, 1.01);
    sx_manifold m;
    (void)state;
    check_pair(&bx, I(), &through, I(), true, V(0, -0.5), TOL);
    check_pair(&bx, I(), &on_top, I(), true, V(0, 0), TOL);
    check_pair(&bx, I(), &hovering, I(), false, V(0, 0), TOL);
    assert_int_equal(sx_collide(&bx, I(), &on_top, I(), &m), 2);
    expect_points(&m, 2, V(-0.5, 1), V(0.5, 1), TOL);
    /* Speculative: within the margin the points come with negative depth. */
    assert_int_equal(sx_collide_ex(&bx, I(), &hovering, I(), SX_R(0.02), &m), 2);
    assert_near(m.points[0].depth, -0.01, TOL);
    assert_int_equal(sx_collide_ex(&bx, I(), &hovering, I(), SX_R(0.005), &m), 0);
}

static void capsule_on_box_face_gives_two_points_tilted_gives_one(void **state) {
    sx_shape bx = box(1, 1), k = capsule(-0.5, 0, 0.5, 0, 0.5);
    sx_manifold m;
    (void)state;
    check_pair(&bx, I(), &k, X(0, 1.4, 0), true, V(0, -0.1), TOL);
    assert_int_equal(sx_collide(&bx, I(), &k, X(0, 1.4, 0), &m), 2);
    expect_points(&m, 2, V(-0.5, 0.95), V(0.5, 0.95), TOL);
    /* Tilted by 0.3 rad: only the low end touches. */
    assert_int_equal(sx_collide(&bx, I(), &k, X(0, 1.4 + 0.5 * sin(0.3), 0.3), &m), 1);
    assert_near(m.points[0].depth, 0.1, 1e-4);
    check_pair(&bx, I(), &k, X(0, 1.4 + 0.5 * sin(0.3), 0.3), true, V(0, -0.1), 1e-4);
    check_pair(&bx, I(), &k, X(0, 1.6, 0), false, V(0, 0), TOL);
    /* Capsule cap against the box corner. */
    check_pair(&bx, I(), &k, X(1.5 + 0.3 / sqrt(2.0), 1 + 0.3 / sqrt(2.0), 0), true,
               V(-0.2 / sqrt(2.0), -0.2 / sqrt(2.0)), 1e-4);
}

static void capsule_through_box_centre(void **state) {
    sx_shape bx = box(2, 1), k = capsule(-3, 0, 3, 0, 0.25);
    (void)state;
    /* Centred: the two faces tie; the first (-y) wins. */
    check_pair(&bx, I(), &k, I(), true, V(0, 1.25), TOL);
    check_pair(&bx, I(), &k, X(0, 0.5, 0), true, V(0, -0.75), TOL);
}

/* ---- polygon - polygon -------------------------------------------------- */

static void boxes_separated_touching_shallow_deep(void **state) {
    sx_shape a = box(1, 1), b = box(0.5, 0.5);
    sx_manifold m;
    (void)state;
    check_pair(&a, I(), &b, X(2, 0.2, 0), false, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(1.5, 0.2, 0), true, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(1.4, 0.2, 0), true, V(-0.1, 0), TOL);
    check_pair(&a, I(), &b, X(0.2, -0.9, 0), true, V(0, 0.6), TOL);
    check_pair(&a, I(), &b, X(0.1, 0.2, 0), true, V(0, -1.3), TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(1.4, 0.2, 0), &m), 2);
    assert_vec2_near(m.normal, V(1, 0), TOL);
    expect_points(&m, 2, V(0.95, -0.3), V(0.95, 0.7), TOL);
    assert_near(m.points[0].depth, 0.1, TOL);
    assert_near(m.points[1].depth, 0.1, TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(1.5, 0.2, 0), &m), 2);
    assert_near(m.points[0].depth, 0.0, TOL);
}

static void identical_boxes_at_the_same_pose(void **state) {
    sx_shape a = box(1, 0.5), b = box(1, 0.5);
    sx_vec2 m1, m2;
    sx_manifold m;
    (void)state;
    /* Identical inputs: both orders are the same call and give the same
     * vector (documented); the depth is the smaller full extent. */
    assert_true(sx_mtv(&a, X(3, 3, 0.2), &b, X(3, 3, 0.2), &m1));
    assert_true(sx_mtv(&b, X(3, 3, 0.2), &a, X(3, 3, 0.2), &m2));
    assert_true(m1.x == m2.x && m1.y == m2.y);
    assert_near(sx_length(m1), 1.0, 1e-4);
    assert_int_equal(sx_collide(&a, X(3, 3, 0.2), &b, X(3, 3, 0.2), &m), 2);
    assert_near(deepest(&m), 1.0, 1e-4);
}

static void diamond_corner_into_box_face_gives_one_point(void **state) {
    sx_shape a = box(1, 1), b = box(0.5, 0.5);
    double h = 0.5 * sqrt(2.0);
    sx_manifold m;
    (void)state;
    check_pair(&a, I(), &b, X(0.3, 1 + h - 0.1, PI / 4), true, V(0, -0.1), 1e-4);
    assert_int_equal(sx_collide(&a, I(), &b, X(0.3, 1 + h - 0.1, PI / 4), &m), 1);
    assert_vec2_near(m.points[0].point, V(0.3, 0.95), 1e-4);
    assert_near(m.points[0].depth, 0.1, 1e-4);
}

static void boxes_vertex_to_vertex(void **state) {
    sx_shape a = box(1, 1), b = box(1, 1);
    double h = sqrt(2.0);
    sx_vec2 mtv;
    (void)state;
    /* Two diamonds corner to corner along x: touching, then overlapping by
     * 0.1 along x; SAT gives the depth along the face normals. */
    check_pair(&a, X(0, 0, PI / 4), &b, X(2 * h - 1e-6, 0, PI / 4), true, V(0, 0), 1e-4);
    check_pair(&a, X(0, 0, PI / 4), &b, X(2 * h + 0.01, 0, PI / 4), false, V(0, 0), TOL);
    assert_true(sx_mtv(&a, X(0, 0, PI / 4), &b, X(2 * h - 0.1, 0, PI / 4), &mtv));
    assert_near(sx_length(mtv), 0.1 / sqrt(2.0), 1e-4);
}

static void box_fast_path_matches_general_path(void **state) {
    sx_shape a = box(1, 0.5), b = box(0.5, 0.25);
    sx_xform quarter;
    sx_vec2 fast, general;
    (void)state;
    quarter.p = V(1.2, 0.3);
    quarter.q.c = SX_R(0.0);
    quarter.q.s = SX_R(1.0);
    /* B turned exactly 90 degrees: its half extents swap to 0.25 x 0.5, so it
     * reaches x in [0.95, 1.45]; overlap along x is 0.05. */
    assert_true(sx_mtv(&a, I(), &b, quarter, &fast));
    assert_vec2_near(fast, V(-0.05, 0), TOL);
    check_pair(&a, I(), &b, quarter, true, V(-0.05, 0), TOL);
    assert_true(sx_mtv(&a, I(), &b, X(1.2, 0.3, PI / 2 + 0.001), &general));
    assert_vec2_near(general, fast, 1e-3);
    quarter.p = V(1.5, 0.3);
    check_pair(&a, I(), &b, quarter, false, V(0, 0), TOL);
    /* Half a turn, and an offset box: still the fast path's axes. */
    {
        sx_shape off = sx_offset_box_shape(SX_R(0.5), SX_R(0.25), V(1, 0), SX_R(0.0));
        sx_xform half;
        half.p = V(0.4, 0.1);
        half.q.c = SX_R(-1.0);
        half.q.s = SX_R(0.0);
        /* off turned half a turn about (0.4, 0.1): its centre goes to
         * (-0.6, 0.1), so it spans x in [-1.1, -0.1], y in [-0.15, 0.35];
         * the cheapest push of A is down by 0.5 + 0.15 (right: 0.9). */
        check_pair(&a, I(), &off, half, true, V(0, -0.65), TOL);
        assert_true(sx_mtv(&a, I(), &off, X(0.4, 0.1, PI + 0.001), &general));
        assert_vec2_near(general, V(0, -0.65), 2e-3);
    }
    assert_false(sx_overlap(&a, I(), &b, X(1.5, 0.3, PI / 2 + 0.001)));
}

static void triangles_from_hand_written_hulls(void **state) {
    const double tri[] = {0, 0, 2, 0, 0, 2};
    const double flipped[] = {0, 0, 1, 1, -1, 1};
    sx_shape a = hull_shape(tri, 3, 0.0), b = hull_shape(flipped, 3, 0.0);
    (void)state;
    /* b is a downward-pointing triangle; moved by (1, 1) its lower-left edge
     * lies on a's hypotenuse x + y = 2 (edge to edge, touching). */
    check_pair(&a, I(), &b, X(1, 1, 0), true, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(1.1, 1.1, 0), false, V(0, 0), TOL);
    check_pair(&a, I(), &b, X(0.9, 0.9, 0), true, V(-0.1, -0.1), TOL);
}

static void rounded_boxes_face_and_corner(void **state) {
    sx_shape a = rounded_box(1, 1, 0.1), b = rounded_box(1, 1, 0.1);
    sx_manifold m;
    double k = 0.2 / sqrt(2.0);
    (void)state;
    /* Cores 0.15 apart, rounding 0.2 in total: 0.05 deep, two points. */
    check_pair(&a, I(), &b, X(2.15, 0.5, 0), true, V(-0.05, 0), TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(2.15, 0.5, 0), &m), 2);
    expect_points(&m, 2, V(1.075, -0.5), V(1.075, 1), TOL);
    check_pair(&a, I(), &b, X(2.25, 0.5, 0), false, V(0, 0), TOL);
    /* Corner to corner along the diagonal, touching (1e-6 inside). */
    check_pair(&a, I(), &b, X(2 + k - 1e-6, 2 + k - 1e-6, 0), true, V(0, 0), 1e-4);
    assert_int_equal(sx_collide(&a, I(), &b, X(2 + k - 1e-6, 2 + k - 1e-6, 0), &m), 1);
    assert_vec2_near(m.normal, V(sqrt(0.5), sqrt(0.5)), 1e-4);
    assert_vec2_near(m.points[0].point, V(1 + 0.5 * k, 1 + 0.5 * k), 1e-4);
}

static void polygon_with_a_tiny_edge(void **state) {
    const double chamfered[] = {-1, -1, 1, -1, 1, 1 - 0.7e-6, 1 - 0.7e-6, 1, -1, 1};
    sx_shape a = hull_shape(chamfered, 5, 0.0), b = box(0.5, 0.5);
    (void)state;
    check_pair(&a, I(), &b, X(1.4, 0.2, 0), true, V(-0.1, 0), TOL);
    check_pair(&a, I(), &b, X(0.2, 1.4, 0), true, V(0, -0.1), TOL);
    check_pair(&a, I(), &b, X(1.6, 1.6, 0), false, V(0, 0), TOL);
}

static void identical_shapes_of_every_type_overlap_fully(void **state) {
    sx_shape c = circle(0, 0, 0.5), k = capsule(-1, 0, 1, 0, 0.25), s = segment(-1, 0, 1, 0);
    sx_vec2 m1, m2;
    sx_manifold m;
    (void)state;
    assert_true(sx_mtv(&c, X(2, 1, 0.5), &c, X(2, 1, 0.5), &m1));
    assert_near(sx_length(m1), 1.0, TOL);
    assert_int_equal(sx_collide(&c, X(2, 1, 0.5), &c, X(2, 1, 0.5), &m), 1);
    assert_near(m.points[0].depth, 1.0, TOL);
    /* A capsule on itself: the cheapest push is across, 2 radii. */
    assert_true(sx_mtv(&k, X(2, 1, 0.5), &k, X(2, 1, 0.5), &m1));
    assert_true(sx_mtv(&k, X(2, 1, 0.5), &k, X(2, 1, 0.5), &m2));
    assert_true(m1.x == m2.x && m1.y == m2.y);
    assert_near(sx_length(m1), 0.5, 1e-4);
    assert_int_equal(sx_collide(&k, X(2, 1, 0.5), &k, X(2, 1, 0.5), &m), 2);
    assert_near(deepest(&m), 0.5, 1e-4);
    /* A segment on itself: zero area, touching. */
    assert_true(sx_mtv(&s, X(2, 1, 0.5), &s, X(2, 1, 0.5), &m1));
    assert_near(sx_length(m1), 0.0, 1e-4);
    assert_true(sx_collide(&s, X(2, 1, 0.5), &s, X(2, 1, 0.5), &m) >= 1);
}

static void one_shape_inside_another(void **state) {
    sx_shape big = box(2, 2), small_box = box(0.25, 0.25), k = capsule(-0.5, 0, 0.5, 0, 0.25);
    sx_shape fat = capsule(-1, 0, 1, 0, 1.5), dot = circle(0, 0, 0.1);
    (void)state;
    /* Capsule inside a box, 0.5 below the top: out through the top face. */
    check_pair(&big, I(), &k, X(0.2, 1.25, 0), true, V(0, -1.0), TOL);
    /* Box inside a fat capsule: out through the capsule's side (1.5 + 0.25
     * from the core, box centre 0.3 above the core line). */
    check_pair(&fat, I(), &small_box, X(0.1, 0.3, 0), true, V(0, -1.45), TOL);
    /* Circle inside a capsule's cap region. */
    check_pair(&fat, I(), &dot, X(1.5, 0, 0), true, V(-1.1, 0), TOL);
}

static void capsule_end_beyond_the_other_end_keeps_its_full_depth(void **state) {
    sx_shape a = capsule(-1, 0, 1, 0, 0.5), b = capsule(0, 0, 0.45, 0.95, 0.1);
    double dx = 0.05, dy = 0.55, d = sqrt(dx * dx + dy * dy), depth = 0.6 - d;
    sx_manifold m;
    (void)state;
    /* B's lower end (1.05, 0.55) sits just past A's end (1, 0): the contact
     * is cap to cap along the line between the two end points. */
    check_pair(&a, I(), &b, X(1.05, 0.55, 0), true, V(-depth * dx / d, -depth * dy / d), TOL);
    assert_true(sx_collide(&a, I(), &b, X(1.05, 0.55, 0), &m) >= 1);
    assert_near(deepest(&m), depth, TOL);
    /* ... and that point lies on the line between the end points, midway
     * between the surfaces (0.5 out of A's end, 0.1 short of B's). */
    {
        int i, k = 0;
        double ux = dx / d, uy = dy / d, along = 0.5 * (0.5 + d - 0.1);
        for (i = 1; i < m.count; ++i) {
            if (m.points[i].depth > m.points[k].depth) k = i;
        }
        assert_vec2_near(m.points[k].point, V(1 + along * ux, along * uy), TOL);
    }
}

static void wide_box_on_narrow_box_is_clipped_at_both_ends(void **state) {
    sx_shape narrow = box(0.5, 0.5), wide = box(2, 0.5);
    sx_manifold m;
    (void)state;
    /* The wide box's bottom face reaches past both ends of the narrow box's
     * top face: both incident points are clipped to the slab. */
    check_pair(&narrow, I(), &wide, X(0.3, 0.95, 0), true, V(0, -0.05), TOL);
    assert_int_equal(sx_collide(&narrow, I(), &wide, X(0.3, 0.95, 0), &m), 2);
    expect_points(&m, 2, V(-0.5, 0.475), V(0.5, 0.475), TOL);
    assert_near(m.points[0].depth, 0.05, TOL);
    assert_near(m.points[1].depth, 0.05, TOL);
    /* Swapped, the wide box's face is A's and the narrow box is incident. */
    assert_int_equal(sx_collide(&wide, X(0.3, 0.95, 0), &narrow, I(), &m), 2);
    expect_points(&m, 2, V(-0.5, 0.475), V(0.5, 0.475), TOL);
    assert_vec2_near(m.normal, V(0, -1), TOL);
}

static void rounded_corners_nearly_aligned_give_the_exact_corner_contact(void **state) {
    sx_shape a = rounded_box(1, 1, 0.1), b = rounded_box(1, 1, 0.1);
    sx_manifold m;
    double x = 1e-3, g = 0.15, d = sqrt(x * x + g * g);
    (void)state;
    /* B's lower-left core corner sits 1e-3 right of and 0.15 above A's
     * upper-right one: the distance exceeds the face separation by only
     * 3.3e-6, so it is a face contact on A's top face, but B's bottom face
     * lies wholly outside that face's slab. The one point is the exact
     * corner-to-corner contact. */
    check_pair(&a, I(), &b, X(2 + x, 2 + g, 0), true, V(-(0.2 - d) * x / d, -(0.2 - d) * g / d),
               TOL);
    assert_int_equal(sx_collide(&a, I(), &b, X(2 + x, 2 + g, 0), &m), 1);
    assert_near(m.points[0].depth, 0.2 - d, TOL);
    assert_vec2_near(m.points[0].point, V(1 + 0.5 * x, 1 + 0.5 * g), TOL);
}

static void coincident_cores_push_along_a_documented_axis(void **state) {
    sx_shape k = capsule(0, 0, 0, 0, 1), c = circle(0, 0, 1), bx = box(1, 1);
    sx_vec2 mtv;
    sx_manifold m;
#ifdef SX_DOUBLE
    double tiny = 1e-15;
#else
    double tiny = 1e-6;
#endif
    (void)state;
    /* A point-like capsule on a circle's centre: no direction exists; the
     * capsule (first in the pair function's order) pushes along its -x. */
    assert_true(sx_mtv(&k, X(3, 4, PI / 2), &c, X(3, 4, 0), &mtv));
    assert_vec2_near(mtv, V(0, -2), TOL);
    assert_true(sx_mtv(&c, X(3, 4, 0), &k, X(3, 4, PI / 2), &mtv));
    assert_vec2_near(mtv, V(0, 2), TOL);
    assert_int_equal(sx_collide(&k, X(3, 4, PI / 2), &c, X(3, 4, 0), &m), 1);
    assert_vec2_near(m.normal, V(0, 1), TOL);
    assert_near(m.points[0].depth, 2.0, TOL);
    /* A circle centre a rounding error outside a box corner: the direction
     * comes from the best separating axis instead of the noisy offset. */
    assert_true(sx_mtv(&bx, I(), &c, X(1 + tiny, 1 + tiny, 0), &mtv));
    assert_near(sx_length(mtv), 1.0, 1e-5);
    assert_true(mtv.x == SX_R(0.0) || mtv.y == SX_R(0.0));
    assert_int_equal(sx_collide(&bx, I(), &c, X(1 + tiny, 1 + tiny, 0), &m), 1);
    assert_near(sx_length(m.normal), 1.0, TOL);
}

/* Two circles whose centres are a rounding error apart but whose squared
 * offset is a normal number (the fast path of sx_collide_circles): the
 * offset has no direction, so the normal is the documented axis (A's local
 * +x or B's local -x, by the canonical order), a unit vector, exactly
 * reversed in the other argument order and in line with the MTV. */
static void nearly_coincident_circles_take_the_documented_axis(void **state) {
#ifdef SX_DOUBLE
    const double tiny = 1e-16;
#else
    const double tiny = 1e-7;
#endif
    sx_shape a = circle(0, 0, 1), b = circle(0, 0, 0.5);
    sx_xform xa = X(3, 4, PI / 2), xb = X(3 + tiny, 4, 0.25);
    sx_manifold m, r;
    sx_vec2 mtv;
    (void)state;
    assert_int_equal(sx_collide(&a, xa, &b, xb, &m), 1);
    assert_int_equal(sx_collide(&b, xb, &a, xa, &r), 1);
    assert_near(sx_length(m.normal), 1.0, TOL);
    assert_true(m.normal.x == -r.normal.x && m.normal.y == -r.normal.y);
    assert_true((m.normal.x == xa.q.c && m.normal.y == xa.q.s) ||
                (m.normal.x == -xb.q.c && m.normal.y == -xb.q.s));
    assert_near(m.points[0].depth, 1.5, TOL);
    assert_near(r.points[0].depth, 1.5, TOL);
    assert_true(sx_mtv(&a, xa, &b, xb, &mtv));
    assert_vec2_near(mtv, sx_scale(m.normal, SX_R(-1.5)), TOL);
    /* Just beyond the rounding band the offset gives the direction. */
    xb = X(3 + 1e-3, 4, 0.25);
    assert_int_equal(sx_collide(&a, xa, &b, xb, &m), 1);
    assert_vec2_near(m.normal, V(1, 0), TOL);
    assert_near(m.points[0].depth, 1.5 - 1e-3, TOL);
}

/* ---- every pair: both orders through the table and the pair functions --- */

static void pair_functions_agree_with_the_dispatch_table(void **state) {
    sx_shape c = circle(0.1, 0, 0.5), s = segment(-0.5, 0.1, 0.6, 0.2);
    sx_shape k = capsule(-0.4, 0, 0.4, 0.1, 0.3), p = box(0.6, 0.4);
    sx_xform xa = X(0.3, -0.2, 0.4), xb = X(0.6, 0.1, -0.7);
    sx_vec2 v, w;
    sx_manifold m1, m2;
    (void)state;
    assert_int_equal(sx_overlap_circles(&c.u.circle, xa, &c.u.circle, xb),
                     sx_overlap(&c, xa, &c, xb));
    assert_int_equal(sx_mtv_circles(&c.u.circle, xa, &c.u.circle, xb, &v),
                     sx_mtv(&c, xa, &c, xb, &w));
    assert_true(v.x == w.x && v.y == w.y);
    assert_int_equal(sx_mtv_segment_circle(&s.u.segment, xa, &c.u.circle, xb, &v),
                     sx_mtv(&s, xa, &c, xb, &w));
    assert_true(v.x == w.x && v.y == w.y);
    assert_int_equal(sx_mtv_polygon_capsule(&p.u.polygon, xa, &k.u.capsule, xb, &v),
                     sx_mtv(&p, xa, &k, xb, &w));
    assert_true(v.x == w.x && v.y == w.y);
    assert_int_equal(sx_mtv(&k, xb, &p, xa, &w), true);
    assert_true(v.x == -w.x && v.y == -w.y);
    assert_int_equal(sx_collide_polygon_segment(&p.u.polygon, xa, &s.u.segment, xb, SX_R(0.0), &m1),
                     sx_collide(&p, xa, &s, xb, &m2));
    assert_true(m1.count > 0);
    assert_true(m1.normal.x == m2.normal.x && m1.normal.y == m2.normal.y);
    assert_int_equal(sx_collide(&s, xb, &p, xa, &m2), m1.count);
    assert_true(m1.normal.x == -m2.normal.x && m1.normal.y == -m2.normal.y);
    assert_int_equal(m2.points[0].id, m1.points[0].id ^ (1u << 16));
    assert_true(m2.points[0].depth == m1.points[0].depth);
}

/* Every ordered pair through the table, on a mildly overlapping scene and a
 * separated one: overlap agrees with mtv, the swapped MTV is the exact
 * negation, and the manifold agrees with the MTV. */
static void every_ordered_pair_is_consistent(void **state) {
    sx_shape shapes[5];
    sx_xform xa = X(0.05, -0.1, 0.35), xb = X(0.45, 0.3, -0.6), far = X(9, 9, 0);
    int i, j;
    (void)state;
    shapes[0] = circle(0.1, 0, 0.5);
    shapes[1] = segment(-0.9, -0.2, 0.9, -0.1);
    shapes[2] = capsule(-0.4, 0, 0.4, 0.1, 0.3);
    shapes[3] = box(0.6, 0.4);
    shapes[4] = rounded_box(0.3, 0.2, 0.15);
    for (i = 0; i < 5; ++i) {
        for (j = 0; j < 5; ++j) {
            sx_vec2 mtv;
            bool hit = sx_mtv(&shapes[i], xa, &shapes[j], xb, &mtv);
            assert_true(hit);
            check_pair(&shapes[i], xa, &shapes[j], xb, true, mtv, TOL);
            check_pair(&shapes[i], xa, &shapes[j], far, false, V(0, 0), TOL);
            /* Moving A by the MTV (plus a hair) separates; by most of it
             * does not. */
            if (sx_length(mtv) > SX_R(1e-3)) {
                sx_xform moved = xa, half = xa;
                moved.p = sx_add(xa.p, sx_scale(mtv, SX_R(1.001)));
                half.p = sx_add(xa.p, sx_scale(mtv, SX_R(0.99)));
                assert_false(sx_overlap(&shapes[i], moved, &shapes[j], xb));
                assert_true(sx_overlap(&shapes[i], half, &shapes[j], xb));
            }
        }
    }
}

/* A random shape of the given type, unit-sized, seeded. Polygons are convex
 * hulls written out directly: points on an ellipse at well-spread angles. */
static sx_shape random_shape(sx_test_rng *rng, int type) {
    switch (type) {
    case SX_SHAPE_CIRCLE:
        return circle(
            (double)sx_test_rng_range(rng, -0.3, 0.3), (double)sx_test_rng_range(rng, -0.3, 0.3),
            sx_test_rng_unit(rng) < 0.1 ? 0.0 : (double)sx_test_rng_range(rng, 0.05, 0.8));
    case SX_SHAPE_SEGMENT:
        return segment((double)sx_test_rng_range(rng, -1, 1), (double)sx_test_rng_range(rng, -1, 1),
                       (double)sx_test_rng_range(rng, -1, 1),
                       (double)sx_test_rng_range(rng, -1, 1));
    case SX_SHAPE_CAPSULE:
        return capsule((double)sx_test_rng_range(rng, -1, 1), (double)sx_test_rng_range(rng, -1, 1),
                       (double)sx_test_rng_range(rng, -1, 1), (double)sx_test_rng_range(rng, -1, 1),
                       (double)sx_test_rng_range(rng, 0, 0.5));
    default: {
        double xy[16], rx = (double)sx_test_rng_range(rng, 0.3, 1),
                       ry = (double)sx_test_rng_range(rng, 0.3, 1);
        double radius = sx_test_rng_unit(rng) < 0.3 ? (double)sx_test_rng_range(rng, 0, 0.2) : 0.0;
        double start = (double)sx_test_rng_range(rng, 0, 6.28318);
        int n = 3 + (int)(sx_test_rng_unit(rng) * 6), i;
        if (sx_test_rng_unit(rng) < 0.3) return box(rx, ry);
        for (i = 0; i < n; ++i) {
            /* Evenly spread angles, jittered by at most a third of a step:
             * gaps stay between 1/3 and 5/3 of 2 pi / n, so the hull is
             * strictly convex. */
            double step = 6.283185307179586 / n;
            double t = start + step * (i + (double)sx_test_rng_range(rng, -0.33, 0.33));
            xy[2 * i] = rx * cos(t);
            xy[2 * i + 1] = ry * sin(t);
        }
        return hull_shape(xy, n, radius);
    }
    }
}

/* Seeded random pairs (including pairs moved to exactly touch by their own
 * MTV): overlap agrees with sx_mtv and with the manifold count, the swapped
 * MTV is the exact negation, the deepest point carries the MTV length, and
 * moving A by the MTV separates the pair. */
static void random_pairs_are_self_consistent(void **state) {
    sx_test_rng rng = sx_test_rng_make(20261122);
    int it;
    (void)state;
    for (it = 0; it < 3000; ++it) {
        int ta = (int)(sx_test_rng_unit(&rng) * 4), tb = (int)(sx_test_rng_unit(&rng) * 4);
        sx_shape a = random_shape(&rng, ta), b = random_shape(&rng, tb);
        sx_xform xa =
            X((double)sx_test_rng_range(&rng, -1, 1), (double)sx_test_rng_range(&rng, -1, 1),
              (double)sx_test_rng_range(&rng, -4, 4));
        sx_xform xb =
            X((double)sx_test_rng_range(&rng, -1, 1), (double)sx_test_rng_range(&rng, -1, 1),
              (double)sx_test_rng_range(&rng, -4, 4));
        sx_vec2 m1, m2;
        sx_manifold c;
        bool hit = sx_mtv(&a, xa, &b, xb, &m1);
        int pass;
        for (pass = 0; pass < 2; ++pass) {
            int n;
            hit = sx_mtv(&a, xa, &b, xb, &m1);
            assert_int_equal(sx_overlap(&a, xa, &b, xb), hit);
            assert_int_equal(sx_overlap(&b, xb, &a, xa), hit);
            assert_int_equal(sx_mtv(&b, xb, &a, xa, &m2), hit);
            assert_true(m2.x == -m1.x && m2.y == -m1.y);
            n = sx_collide(&a, xa, &b, xb, &c);
            assert_int_equal(n > 0, hit);
            if (hit) {
                double len = (double)sx_length(m1);
                double tol = 1e3 * (double)SX_REAL_EPSILON;
                assert_true(deepest(&c) >= len - tol && deepest(&c) <= len + tol + HYSTERESIS);
                if (len > tol) {
                    sx_xform moved = xa;
                    moved.p = sx_add(xa.p, sx_add(m1, sx_scale(m1, (sx_real)(tol / len))));
                    assert_false(sx_overlap(&a, moved, &b, xb));
                }
                /* Second pass: A moved by exactly its MTV (touching up to
                 * rounding), where the orders are most likely to disagree. */
                xa.p = sx_add(xa.p, m1);
            } else {
                break;
            }
        }
    }
}

/* ---- precision, degenerate and hostile input ---------------------------- */

static void far_from_the_origin_gives_the_same_answers(void **state) {
    sx_shape shapes[4];
    double off = 1e5;
    int i, j;
    (void)state;
    shapes[0] = circle(0, 0, 0.5);
    shapes[1] = capsule(-0.5, 0, 0.5, 0, 0.25);
    shapes[2] = box(0.5, 0.5);
    shapes[3] = segment(-0.5, -0.5, 0.5, 0.5);
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            sx_vec2 near0, far0;
            bool h0 = sx_mtv(&shapes[i], X(0, 0, 0.25), &shapes[j], X(0.625, 0.25, -0.5), &near0);
            bool h1 = sx_mtv(&shapes[i], X(off, -off, 0.25), &shapes[j],
                             X(off + 0.625, -off + 0.25, -0.5), &far0);
            assert_int_equal(h0, h1);
            assert_vec2_near(near0, far0, 1e-4);
        }
    }
}

static void non_finite_input_answers_no_contact(void **state) {
    sx_shape good[4], bad[8];
    sx_xform nan_x = X(0, 0, 0), inf_x = X(0, 0, 0);
    sx_vec2 mtv;
    sx_manifold m;
    int i, j;
    (void)state;
    nan_x.p.x = (sx_real)NAN;
    inf_x.q.s = (sx_real)INFINITY;
    good[0] = circle(0, 0, 1);
    good[1] = segment(-1, 0, 1, 0);
    good[2] = capsule(-1, 0, 1, 0, 0.5);
    good[3] = box(1, 1);
    bad[0] = circle(0, 0, 1);
    bad[0].u.circle.radius = (sx_real)NAN;
    bad[1] = capsule(-1, 0, 1, 0, 0.5);
    bad[1].u.capsule.radius = (sx_real)INFINITY;
    bad[2] = segment(-1, 0, 1, 0);
    bad[2].u.segment.b.y = (sx_real)NAN;
    bad[3] = box(1, 1);
    bad[3].u.polygon.vertices[2].x = (sx_real)INFINITY;
    bad[4] = circle(0, 0, -1);
    bad[5] = box(1, 1);
    bad[5].u.polygon.count = 0;
    /* Polygon values are checked only once the answer is not "apart" (a
     * NaN normal, an infinite vertex on the far side): still no contact. */
    bad[6] = box(1, 1);
    bad[6].u.polygon.normals[1].y = (sx_real)NAN;
    bad[7] = box(1, 1);
    bad[7].u.polygon.vertices[0].y = -(sx_real)INFINITY;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            assert_false(sx_overlap(&good[i], nan_x, &good[j], I()));
            assert_false(sx_overlap(&good[i], I(), &good[j], inf_x));
            mtv = V(7, 7);
            assert_false(sx_mtv(&good[i], nan_x, &good[j], I(), &mtv));
            assert_true(mtv.x == SX_R(0.0) && mtv.y == SX_R(0.0));
            assert_int_equal(sx_collide(&good[i], I(), &good[j], inf_x, &m), 0);
            assert_int_equal(m.count, 0);
        }
        for (j = 0; j < 8; ++j) {
            assert_false(sx_overlap(&good[i], I(), &bad[j], I()));
            assert_false(sx_overlap(&bad[j], I(), &good[i], I()));
            mtv = V(7, 7);
            assert_false(sx_mtv(&bad[j], I(), &good[i], I(), &mtv));
            assert_true(mtv.x == SX_R(0.0) && mtv.y == SX_R(0.0));
            assert_int_equal(sx_collide(&good[i], I(), &bad[j], I(), &m), 0);
            assert_int_equal(sx_collide_ex(&bad[j], I(), &good[i], I(), SX_R(1.0), &m), 0);
        }
    }
    /* A non-finite or negative margin is taken as zero. */
    assert_int_equal(sx_collide_ex(&good[3], I(), &good[3], X(2.1, 0, 0), (sx_real)NAN, &m), 0);
    assert_int_equal(sx_collide_ex(&good[3], I(), &good[3], X(2.1, 0, 0), SX_R(-1.0), &m), 0);
    assert_int_equal(sx_collide_ex(&good[3], I(), &good[3], X(2.01, 0, 0), SX_R(0.02), &m), 2);
}

static void null_and_unknown_types_answer_no_contact(void **state) {
    sx_shape a = box(1, 1), odd = box(1, 1);
    sx_vec2 mtv = V(1, 1);
    sx_manifold m;
    (void)state;
    odd.type = SX_SHAPE_TYPE_COUNT;
    assert_false(sx_overlap(NULL, I(), &a, I()));
    assert_false(sx_overlap(&a, I(), &odd, I()));
    assert_false(sx_mtv(&odd, I(), &a, I(), &mtv));
    assert_true(mtv.x == SX_R(0.0) && mtv.y == SX_R(0.0));
    assert_true(sx_mtv(&a, I(), &a, X(1, 0, 0), NULL));
    assert_int_equal(sx_collide(&a, I(), NULL, I(), &m), 0);
    assert_int_equal(sx_collide(&a, I(), &a, X(1, 0, 0), NULL), 2);
}

/* ---- feature ids and reference faces ------------------------------------ */

static void feature_ids_stay_stable_when_b_moves_slightly(void **state) {
    sx_shape a = box(2, 0.5), b = box(0.5, 0.5);
    sx_manifold m0, m1;
    (void)state;
    assert_int_equal(sx_collide(&a, I(), &b, X(0.3, 0.99, 0.01), &m0), 2);
    assert_int_equal(sx_collide(&a, I(), &b, X(0.302, 0.9895, 0.0102), &m1), 2);
    assert_int_equal(m0.points[0].id, m1.points[0].id);
    assert_int_equal(m0.points[1].id, m1.points[1].id);
    assert_true(m0.points[0].id != m0.points[1].id);
    /* A capsule resting on the box keeps its ids while it slides. */
    {
        sx_shape k = capsule(-0.4, 0, 0.4, 0, 0.2);
        assert_int_equal(sx_collide(&a, I(), &k, X(0.0, 0.69, 0), &m0), 2);
        assert_int_equal(sx_collide(&a, I(), &k, X(0.05, 0.695, 0.001), &m1), 2);
        assert_int_equal(m0.points[0].id, m1.points[0].id);
        assert_int_equal(m0.points[1].id, m1.points[1].id);
    }
}

static void reference_face_does_not_flip_between_nearly_equal_faces(void **state) {
    sx_shape a = box(1, 1), b = box(1, 1);
    sx_manifold m;
    (void)state;
    /* Same size boxes overlapping by 0.1 along x: A's +x face and B's -x
     * face are equally good; A keeps the reference (flipped bit clear). */
    assert_int_equal(sx_collide(&a, I(), &b, X(1.9, 0.5, 0), &m), 2);
    assert_int_equal(m.points[0].id >> 16, 0);
    assert_int_equal(m.points[1].id >> 16, 0);
    /* B turned by t: B's face beats A's by about t / 2. With t = 1e-4 that
     * is half of sx_collide's hysteresis (0.02 x the slop, 1e-4 m): still
     * A's face. */
    assert_true(sx_collide(&a, I(), &b, X(1.9, 0.5, 1e-4), &m) >= 1);
    assert_int_equal(m.points[0].id >> 16, 0);
    assert_vec2_near(m.normal, V(1, 0), TOL);
    /* With t = 5e-4 B's face is better by 2.5e-4 m, beyond sx_collide's
     * hysteresis: B's face is the reference, and the depth is the least
     * penetration's. The world's hysteresis (0.1 x the slop, 5e-4 m) still
     * keeps A's face there, so that a contact in a stack does not change
     * faces from step to step. */
    assert_true(sx_collide(&a, I(), &b, X(1.9, 0.5, 5e-4), &m) >= 1);
    assert_int_equal(m.points[0].id >> 16, 1);
    assert_true(sx_collide_world(&a, I(), &b, X(1.9, 0.5, 5e-4), SX_R(0.0), &m) >= 1);
    assert_int_equal(m.points[0].id >> 16, 0);
    assert_vec2_near(m.normal, V(1, 0), TOL);
    /* With t = 0.2 B's face is clearly better and becomes the reference
     * for both; the normal still points from A to B, along B's face normal. */
    assert_true(sx_collide(&a, I(), &b, X(1.9, 0.5, 0.2), &m) >= 1);
    assert_int_equal(m.points[0].id >> 16, 1);
    assert_vec2_near(m.normal, V(cos(0.2), sin(0.2)), 1e-4);
    assert_true(sx_collide_world(&a, I(), &b, X(1.9, 0.5, 0.2), SX_R(0.0), &m) >= 1);
    assert_int_equal(m.points[0].id >> 16, 1);
}

/* Checks a manifold of inputs beyond SX_HUGE: 0 points and a zero normal, or
 * 1..2 finite points with a unit normal (never a zero normal with points). */
static void assert_manifold_sane(const sx_manifold *m, int n) {
    int i;
    assert_true(n >= 0 && n <= 2);
    assert_int_equal(m->count, n);
    if (n == 0) {
        assert_true(m->normal.x == SX_R(0.0) && m->normal.y == SX_R(0.0));
        return;
    }
    assert_near(sx_length(m->normal), 1.0, 64.0 * (double)SX_REAL_EPSILON);
    for (i = 0; i < n; ++i) {
        assert_true(sx_vec2_is_finite(m->points[i].point));
        assert_true(sx_is_finite(m->points[i].depth));
    }
}

/* Regression (fuzz: collide-clip-face-negative-index and
 * collide-mtv-antisymmetry-beyond-huge): a box of half extents SX_REAL_MAX
 * makes every SAT separation -SX_REAL_MAX, which used to equal the "no face
 * yet" sentinel, so no reference face was chosen and the manifold clipped
 * against face -1 (an out-of-bounds read) and the MTV read a normal at index
 * -1 (garbage, so the two argument orders disagreed). */
static void separations_at_the_top_of_the_range_still_choose_a_face(void **state) {
    sx_shape giant = sx_box_shape(SX_REAL_MAX, SX_REAL_MAX), small = box(0.5, 0.25);
    sx_shape seg = segment(15.375, 15.875, 0, -0.125);
    sx_xform x = X(-16, -16, 0);
    sx_manifold m;
    sx_vec2 ab, ba;
    bool hit_ab, hit_ba;
    int n;
    (void)state;
    /* validation refuses it (its mass overflows), but the narrowphase, which
     * does not validate, must still answer for it */
    assert_int_equal(sx_shape_validate(&giant), SX_ERR_NONFINITE);
    n = sx_collide(&giant, x, &small, x, &m);
    assert_manifold_sane(&m, n);
    n = sx_collide(&small, x, &giant, x, &m);
    assert_manifold_sane(&m, n);
    n = sx_collide_ex(&giant, x, &seg, x, (sx_real)SX_SPECULATIVE_DISTANCE, &m);
    assert_manifold_sane(&m, n);

    /* Antisymmetry is unconditional (collide.h), also beyond SX_HUGE. */
    hit_ab = sx_mtv(&seg, x, &giant, x, &ab);
    hit_ba = sx_mtv(&giant, x, &seg, x, &ba);
    assert_true(hit_ab == hit_ba);
    assert_false(ab.x != ab.x || ab.y != ab.y);
    assert_true(ab.x == -ba.x && ab.y == -ba.y);
    hit_ab = sx_mtv(&small, x, &giant, x, &ab);
    hit_ba = sx_mtv(&giant, x, &small, x, &ba);
    assert_true(hit_ab == hit_ba);
    assert_false(ab.x != ab.x || ab.y != ab.y);
    assert_true(ab.x == -ba.x && ab.y == -ba.y);
}

/* Regression (fuzz: collide-margin-loses-touching-contact): two boxes whose
 * faces are a few ulps apart in float. sx_overlap counts them as touching
 * and sx_collide reports 2 points of depth 0; a speculative margin smaller
 * than that rounding gap (1e-9, or a denormal) used to report 0 points. A
 * larger margin must never report fewer points than margin 0. */
static void a_speculative_margin_never_reports_fewer_points_than_margin_0(void **state) {
    sx_shape a = sx_box_shape(SX_R(0.034062501), SX_R(0.0681250021));
    sx_shape b = sx_box_shape(SX_R(0.102187499), SX_R(0.136250004));
    sx_xform xa = sx_xform_make(sx_v2(SX_R(0.136250004), SX_R(0.136250004)), SX_R(0.0));
    sx_xform xb = I();
    const double margins[] = {1e-30, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-2};
    sx_manifold m0, m;
    int n0, n, i, order;
    (void)state;
    for (order = 0; order < 2; ++order) {
        const sx_shape *p = order ? &b : &a, *q = order ? &a : &b;
        sx_xform xp = order ? xb : xa, xq = order ? xa : xb;
        n0 = sx_collide(p, xp, q, xq, &m0);
        assert_int_equal(n0 > 0, sx_overlap(p, xp, q, xq));
#ifndef SX_DOUBLE
        /* The float case the fuzzer found: touching within rounding. */
        assert_int_equal(n0, 2);
        assert_near(m0.points[0].depth, 0.0, 1e-7);
#endif
        for (i = 0; i < (int)(sizeof margins / sizeof margins[0]); ++i) {
            n = sx_collide_ex(p, xp, q, xq, (sx_real)margins[i], &m);
            assert_true(n >= n0);
            if (n > 0) {
                assert_near(sx_length(m.normal), 1.0, 64.0 * (double)SX_REAL_EPSILON);
                assert_true((double)m.points[0].depth >= -margins[i] - 1e-7);
            }
        }
    }
}

/* Regression (fuzz: collide-speck-on-far-edge-speculative-fewer-points): a
 * 1e-30 box touching the edge of a triangle whose far corner lies 1e5 m from
 * its origin. In float, B's vertices placed in A's frame carry ~1 cm of
 * rounding; sx_collide (margin 0) rescues the touch through the other order
 * (its edge: 2 points of depth 0), while a 4 cm speculative margin in this
 * order saw a vertex 1 cm off and stopped at 1 point. A speculative margin
 * must never report fewer points than margin 0, in either order. */
static void a_speck_on_a_far_edge_gets_no_fewer_speculative_points(void **state) {
    sx_vec2 q[3];
    sx_shape a = sx_box_shape(SX_R(0x1.4484cp-100), SX_R(0x1.4484cp-100)), b;
    sx_xform xa, xb;
    const double margins[] = {1e-5, 0x1.451eb8p-5, 0.5};
    sx_manifold m0, m;
    int n0, n, i, order, rot;
    (void)state;
    q[0] = sx_v2(SX_R(-0x1.86ap+16), SX_R(-0x1.86ap+16));
    q[1] = sx_v2(SX_R(0x1.de69acp-8), SX_R(0x1.de69acp-8));
    q[2] = sx_v2(SX_R(-16.0), SX_R(0x1.24p+3));
    assert_int_equal(sx_polygon_shape(q, 3, SX_R(0.0), &b), SX_OK);
    xa.p = sx_v2(SX_R(0x1.24bae2p+3), SX_R(0x1.24bae2p+3));
    xa.q.c = SX_R(-0x1.ec7cdp-1);
    xa.q.s = SX_R(0x1.18000cp-2);
#ifdef SX_DOUBLE
    xa.q = sx_rot_normalize(xa.q); /* unit in float only */
#endif
    for (rot = 0; rot < 2; ++rot) {
        xb.p = xa.p;
        xb.q.c = SX_R(1.0);
        xb.q.s = rot ? SX_R(0.0) : (sx_real)0x1.0628p-136; /* the fuzzer's: a denormal */
        for (order = 0; order < 2; ++order) {
            const sx_shape *p = order ? &b : &a, *r = order ? &a : &b;
            sx_xform xp = order ? xb : xa, xr = order ? xa : xb;
            n0 = sx_collide(p, xp, r, xr, &m0);
            /* A's centre is on B's edge y = x: the pair touches. */
            assert_true(sx_overlap(p, xp, r, xr));
            assert_in_range(n0, 1, 2);
            for (i = 0; i < (int)(sizeof margins / sizeof margins[0]); ++i) {
                n = sx_collide_ex(p, xp, r, xr, (sx_real)margins[i], &m);
                assert_true(n >= n0);
                assert_near(sx_length(m.normal), 1.0, 64.0 * (double)SX_REAL_EPSILON);
                /* the pair touches: no point may claim a gap beyond the
                 * float rounding at 1e5 m */
                assert_true((double)deepest(&m) >= -0.02);
            }
        }
    }
}

/* Regression (fuzz: collide-far-neighbour-face-tie-clips-deep-vertex): a
 * 12 m sliver 8.76 m deep in a quadrilateral whose face 0 runs 1e5 m to a far
 * corner and meets face 1 at a bend of 2.2e-4 rad. Placed in A's frame, the
 * far corner carries ~1 cm of float rounding, so the SAT took face 1 (2 mm
 * less separation, within that noise) and clipping against its slab cut off
 * the sliver's deep end: 1.3 cm reported of 8.76 m. The tie between the two
 * faces now allows for the rounding of the neighbour's far corner. */
static void a_far_neighbour_face_ties_within_its_rounding(void **state) {
    sx_vec2 pa[3], pb[4];
    sx_shape a, b;
    sx_xform xa, xb;
    sx_manifold m;
    sx_vec2 mtv;
    int order, n;
    (void)state;
    pa[0] = sx_v2(SX_R(-0x1.87f322p+3), SX_R(-0x1.a1818p-7));
    pa[1] = sx_v2(SX_R(0x1.1c88a4p-9), SX_R(0x1.0357d2p-11));
    pa[2] = sx_v2(SX_R(0x1.1c88a4p-9), SX_R(0x1.f3795ap-10));
    pb[0] = sx_v2(SX_R(-0x1.86ap+16), SX_R(-0x1.86ap+16));
    pb[1] = sx_v2(SX_R(0x1.de69acp-8), SX_R(0x1.de69acp-8));
    pb[2] = sx_v2(SX_R(0x1.251ebap+3), SX_R(0x1.254002p+3));
    pb[3] = sx_v2(SX_R(-16.0), SX_R(0x1.24p+3));
    assert_int_equal(sx_polygon_shape(pa, 3, SX_R(0.0), &a), SX_OK);
    assert_int_equal(sx_polygon_shape(pb, 4, SX_R(0.0), &b), SX_OK);
    xa.p = sx_v2(SX_R(0x1.25614ap+3), SX_R(0x1.258292p+3));
    xa.q.c = SX_R(-0x1.f044eep-1);
    xa.q.s = SX_R(0x1.f7c24ap-3);
    xb.p = sx_v2(SX_R(0x1.25c522p+3), SX_R(0x1.25e66ap+3));
    xb.q.c = SX_R(-0x1.f1c46ep-1);
    xb.q.s = SX_R(0x1.df8732p-3);
#ifdef SX_DOUBLE
    xa.q = sx_rot_normalize(xa.q); /* unit in float only */
    xb.q = sx_rot_normalize(xb.q);
#endif
    /* Long-double reference (tests/support/reference.c): 8.76100 m along
     * (-0.52189, 0.85302); float rounds coordinates of 1e5 m by ~8 mm. */
    assert_true(sx_mtv(&a, xa, &b, xb, &mtv));
    assert_near(sx_length(mtv), 8.76100, 0.01);
    for (order = 0; order < 2; ++order) {
        n = order ? sx_collide(&b, xb, &a, xa, &m) : sx_collide(&a, xa, &b, xb, &m);
        assert_in_range(n, 1, 2);
        assert_near(deepest(&m), 8.76100, 0.01 + HYSTERESIS);
        assert_near(sx_length(m.normal), 1.0, 64.0 * (double)SX_REAL_EPSILON);
    }
}

/* Regression (make fuzz, 2026-11-25, collide-long-capsule-along-reference-
 * normal-cut-by-rounding; fails c9ef77a too): a capsule 3.4e-7 m long lying
 * at the end of a capsule 1.3e5 m long and 9e4 m thick, the long one's core
 * along the short one's face normal. The short face stayed the reference
 * (the two separations tied within rounding), and clipping cut the long
 * incident segment where its far end, rounded by 8 mm, seemed to cross the
 * 3.4e-7 m slab: at 97 % of its length, with a depth of 0 where the pair
 * overlaps by 9e4 m. An incident face whose ends differ along the face by
 * no more than their rounding is not cut. */
static void a_long_capsule_along_the_reference_normal_is_not_cut_by_rounding(void **state) {
    sx_shape a = sx_capsule_shape(sx_v2(SX_R(1.125), SX_R(1.12499976)),
                                  sx_v2(SX_R(1.12499976), SX_R(1.125)), SX_R(1.125));
    sx_shape b = sx_capsule_shape(sx_v2(SX_R(1.125), SX_R(1.12498999)),
                                  sx_v2(SX_R(90000.0), SX_R(90000.0)), SX_R(90000.0));
    sx_xform x = X(-16.0, -16.0, 0.0);
    sx_manifold m;
    sx_vec2 mtv;
    int order;
    (void)state;
    assert_true(sx_mtv(&a, x, &b, x, &mtv));
    assert_near(sx_length(mtv), 90001.125, 0.05);
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide(&b, x, &a, x, &m) : sx_collide(&a, x, &b, x, &m);
        assert_in_range(n, 1, 2);
        assert_near(deepest(&m), 90001.125, 0.05);
    }
}

/* Regression (make fuzz, 2026-11-25, collide-tiny-reference-face-clips-long-
 * capsule; fails c9ef77a too): a capsule 3.4e-7 m long and 1.125 m thick
 * 6e-5 m beside the end of a capsule 2.8e4 m long, of the same thickness,
 * at 5e-5 rad from the short one's face normal. The short face was the
 * reference, and clipping the long core to its 3.4e-7 m slab (narrower than
 * the 2 mm rounding of the long core's far end) cut it 1.3 m along: 0.93 m
 * reported of a 2.25 m depth. A reference face no wider than the rounding
 * does not clip. */
static void a_reference_face_narrower_than_rounding_does_not_clip(void **state) {
    sx_shape a = sx_capsule_shape(sx_v2(SX_R(1.125), SX_R(1.12499976)),
                                  sx_v2(SX_R(1.12499976), SX_R(1.125)), SX_R(1.125));
    sx_shape b = sx_capsule_shape(sx_v2(SX_R(1.125), SX_R(1.12498951)),
                                  sx_v2(SX_R(-20000.0), SX_R(-20000.0)), SX_R(1.125));
    sx_xform xa, xb;
    sx_manifold m;
    sx_vec2 mtv;
    int order;
    (void)state;
    xa.p = sx_v2(SX_R(1.125), SX_R(1.125));
    xa.q.c = SX_R(0.431190938);
    xa.q.s = SX_R(0.902260721);
    xb.p = sx_v2(SX_R(1.12500036), SX_R(1.12501669));
    xb.q.c = SX_R(0.431146622);
    xb.q.s = SX_R(0.90228188);
    xa.q = sx_rot_normalize(xa.q);
    xb.q = sx_rot_normalize(xb.q);
    assert_true(sx_mtv(&a, xa, &b, xb, &mtv));
    assert_near(sx_length(mtv), 2.25, 0.01);
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide(&b, xb, &a, xa, &m) : sx_collide(&a, xa, &b, xb, &m);
        assert_in_range(n, 1, 2);
        assert_near(deepest(&m), 2.25, 0.01);
    }
}

/* Regression (make fuzz, 2026-11-25, collide-near-collinear-faces-take-
 * the-wrong-corner; fails c9ef77a too): a quad whose first two faces are
 * nearly one line (the first runs to a vertex at (-1e5, -1e5)), 1.71 m from
 * a point in front of its first face, 0.9 m short of the corner between
 * them. The faces separate the point by amounts closer than the rounding of
 * the far vertex, the second was taken as the face of largest separation,
 * and the point lies beyond its start: the corner was taken as the closest
 * feature, 7.96 m away. The MTV reported 1.21 m of a 7.45 m depth against a
 * 9.17 m rounded triangle, and a 9.17 m circle at that point was missed
 * altogether. The closest feature now walks past the corner. */
static void near_collinear_faces_find_the_face_past_the_corner(void **state) {
    const sx_vec2 tri[3] = {{SX_R(-12.2484293), SX_R(-0.0127412677)},
                            {SX_R(0.00217082025), SX_R(0.000494657608)},
                            {SX_R(0.00217082025), SX_R(0.00190534221)}};
    const sx_vec2 quad[4] = {{SX_R(-100000.0), SX_R(-100000.0)},
                             {SX_R(0.00729999971), SX_R(0.00729999971)},
                             {SX_R(9.16062546), SX_R(9.16468811)},
                             {SX_R(-16.0), SX_R(9.125)}};
    const sx_real r = SX_R(9.16875076);
    /* 9.16875076 - 1.71384791 (the gap, taken in double from the placed
     * vertices) */
    const double depth = 7.45490285;
    sx_shape a, b, core, circle;
    sx_xform xa, xb, xc;
    sx_manifold m;
    sx_vec2 mtv;
    int order;
    (void)state;
    assert_int_equal(sx_polygon_shape(tri, 3, SX_R(0.0), &a), SX_OK);
    assert_int_equal(sx_polygon_shape(quad, 4, r, &b), SX_OK);
    assert_int_equal(sx_polygon_shape(quad, 4, SX_R(0.0), &core), SX_OK);
    assert_int_equal(b.u.polygon.count, 4);
    xa.p = sx_v2(SX_R(9.17281342), SX_R(9.17687607));
    xa.q.c = SX_R(-0.0541771352);
    xa.q.s = SX_R(0.998531342);
    xb.p = sx_v2(SX_R(1.62906253), SX_R(1.63312507));
    xb.q.c = SX_R(-0.0850384012);
    xb.q.s = SX_R(0.996377647);
    xa.q = sx_rot_normalize(xa.q);
    xb.q = sx_rot_normalize(xb.q);
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide(&b, xb, &a, xa, &m) : sx_collide(&a, xa, &b, xb, &m);
        assert_true(order ? sx_mtv(&b, xb, &a, xa, &mtv) : sx_mtv(&a, xa, &b, xb, &mtv));
        assert_near(sx_length(mtv), depth, 0.02);
        assert_in_range(n, 1, 2);
        assert_near(deepest(&m), depth, 0.02);
    }
    /* The point of the triangle nearest the quad, as a circle's centre. */
    xc.p = sx_xform_point(xa, tri[0]);
    xc.q = sx_rot_identity();
    circle = sx_circle_shape(sx_v2_zero(), r);
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide(&circle, xc, &core, xb, &m) : sx_collide(&core, xb, &circle, xc, &m);
        assert_true(order ? sx_overlap(&circle, xc, &core, xb) : sx_overlap(&core, xb, &circle, xc));
        assert_true(order ? sx_mtv(&circle, xc, &core, xb, &mtv) : sx_mtv(&core, xb, &circle, xc, &mtv));
        assert_near(sx_length(mtv), depth, 0.02);
        assert_int_equal(n, 1);
        assert_near(deepest(&m), depth, 0.02);
    }
}

/* Regression (make fuzz, double build: sx_compound_overlap disagreed with
 * sx_overlap): two circles whose centres are closer than the square root of
 * the smallest normal real compared squares that underflowed to 0, so two
 * points 1e-265 apart counted as touching. */
static void circles_closer_than_square_underflow_compare_exactly(void **state) {
#ifdef SX_DOUBLE
    const double t = 1e-265;
#else
    const double t = 1e-30;
#endif
    sx_shape p0 = sx_point_shape(sx_v2_zero()), p1 = sx_point_shape(V(t, t));
    sx_shape c1 = circle(t, t, t), c2 = circle(t, t, 2.0 * t);
    sx_manifold m;
    sx_vec2 v;
    (void)state;
    assert_false(sx_overlap(&p0, I(), &p1, I()));
    assert_false(sx_overlap(&p1, I(), &p0, I()));
    assert_false(sx_mtv(&p0, I(), &p1, I(), &v));
    assert_int_equal(sx_collide(&p0, I(), &p1, I(), &m), 0);
    /* |d| = 1.41 t: a circle of radius t around it misses the origin, one of
     * radius 2 t reaches it. */
    assert_false(sx_overlap(&p0, I(), &c1, I()));
    assert_true(sx_overlap(&p0, I(), &c2, I()));
    assert_true(sx_overlap(&c2, I(), &p0, I()));
    assert_int_equal(sx_collide(&p0, I(), &c2, I(), &m), 1);
    assert_int_equal(sx_collide(&p0, I(), &p0, I(), &m), 1); /* coincident points touch */
    /* The same through the core routines: a zero-length capsule (a point
     * core) and a segment end against a point t away. */
    {
        sx_shape cap = capsule(0, t, 0, t, 0), seg = segment(0, t, -1, t);
        assert_false(sx_overlap(&cap, I(), &p1, I()));
        assert_false(sx_overlap(&p1, I(), &cap, I()));
        assert_false(sx_mtv(&cap, I(), &p1, I(), &v));
        assert_int_equal(sx_collide(&cap, I(), &p1, I(), &m), 0);
        assert_false(sx_overlap(&seg, I(), &p1, I()));
        assert_true(sx_overlap(&seg, I(), &c2, I()));
    }
    /* Cores a denormal distance apart: the direction between them is
     * scaled before it is normalised (1 / distance overflows), so the MTV
     * is finite and agrees with sx_overlap (make fuzz, double build). */
    {
        sx_shape cap = capsule(0, 0, -560000, 1270000, 1270000), tri;
        sx_vec2 q[3];
        bool ov, hit;
        q[0] = V(-16, -16);
        q[1] = V(16, -16);
#ifdef SX_DOUBLE
        q[2] = sx_v2((sx_real)(DBL_MIN * 1e-3), SX_R(0.0)); /* denormal */
#else
        q[2] = sx_v2(FLT_MIN * 1e-3f, SX_R(0.0)); /* denormal */
#endif
        assert_int_equal(sx_polygon_shape_ex(q, 3, SX_R(0.0), SX_R(0.0), &tri), SX_OK);
        ov = sx_overlap(&cap, X(-16, -16, 0), &tri, X(-16, -16, 0));
        hit = sx_mtv(&cap, X(-16, -16, 0), &tri, X(-16, -16, 0), &v);
        assert_true(ov && hit);
        assert_true(sx_vec2_is_finite(v));
        assert_near(sx_length(v), 1270000.0, 1.0);
    }
}

/* Both argument orders of a same-transform pair of polygons (given as
 * point lists): the MTV has the expected length, and each manifold's
 * deepest point carries it, up to tol and the reference-face hysteresis. */
static void assert_polygons_deepest_is_mtv(const sx_vec2 *pa, int na, const sx_vec2 *pb, int nb,
                                           sx_xform x, double mtv_len, double tol) {
    sx_shape a, b;
    sx_manifold m;
    sx_vec2 mtv;
    int order;
    assert_int_equal(sx_polygon_shape(pa, na, SX_R(0.0), &a), SX_OK);
    assert_int_equal(sx_polygon_shape(pb, nb, SX_R(0.0), &b), SX_OK);
    assert_int_equal(a.u.polygon.count, na);
    assert_int_equal(b.u.polygon.count, nb);
    assert_true(sx_mtv(&a, x, &b, x, &mtv));
    assert_near(sx_length(mtv), mtv_len, tol);
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide(&b, x, &a, x, &m) : sx_collide(&a, x, &b, x, &m);
        assert_in_range(n, 1, 2);
        assert_true(deepest(&m) >= (double)sx_length(mtv) - tol);
        assert_true(deepest(&m) <= (double)sx_length(mtv) + tol + HYSTERESIS);
    }
}

/* Found by the 10M fuzz campaign (harness collide, input
 * collide-sliver-incident-face-tie): two slivers 70 km and 100 km long, a
 * few centimetres to 16 m wide. The reference face is B's long face, and
 * two faces of A, a 15 m one and the 70 km one, are anti-parallel to it
 * within 1e-7: their dot products with its normal round to the same float,
 * and the first (the short face, far from A's deepest vertex) was clipped,
 * giving 7 mm of an 8.39 m penetration. The incident face now comes from
 * the two faces at the deepest vertex, and the manifold's deepest point
 * carries the MTV. */
static void sliver_incident_face_is_taken_at_the_deepest_vertex(void **state) {
    sx_vec2 pa[4], pb[4];
    (void)state;
    pa[0] = V(-15.25, -0.01360000018030405);
    pa[1] = V(-0.018408283591270447, -0.018408283591270447);
    pa[2] = V(70000.0, -16.013599395751953);
    pa[3] = V(-0.011608300358057022, -0.0019916822202503681);
    pb[0] = V(-16.011608123779297, -16.001991271972656);
    pb[1] = V(-16.001991271972656, -16.011608123779297);
    pb[2] = V(100000.0, -10.881799697875977);
    pb[3] = V(-0.011608299426734447, -0.011608299426734447);
    /* exact penetration: 8.39286 m along B's long face normal */
    assert_polygons_deepest_is_mtv(pa, 4, pb, 4, X(-16.0, -16.0, 0.0), 8.39286, 1e-2);
}

/* Found by the 10M fuzz campaign (harness collide, input
 * collide-bent-reference-face-tie): B is a strip bent by 6e-5 rad at a
 * vertex, and A's corner pokes 2 mm into it next to the bend. B's two faces
 * at the bend separate A by the same amount up to rounding; the SAT took
 * the one whose slab ends just short of A's corner, clipping cut the corner
 * off and the manifold said 1 mm. Of two tied faces the one towards the
 * deepest vertex is the reference now. */
static void bent_reference_face_tie_keeps_the_deepest_corner(void **state) {
    sx_vec2 pa[3], pb[4];
    (void)state;
    pa[0] = sx_v2((sx_real)-0x1.ffee38p+3, (sx_real)0x1.80206ap+0);
    pa[1] = sx_v2((sx_real)-0x1.87f322p+3, (sx_real)-0x1.a1818p-7);
    pa[2] = sx_v2((sx_real)0x1.3a92a2p-9, (sx_real)0x1.3a92a2p-10);
    pb[0] = sx_v2((sx_real)-0x1.fffe2p+3, (sx_real)-0x1.fffbf2p+3);
    pb[1] = sx_v2((sx_real)-0x1.fff322p+3, (sx_real)-0x1.ffff84p+3);
    pb[2] = sx_v2((sx_real)0x1.fc13aap+3, (sx_real)0x1.fc09d4p+3);
    pb[3] = sx_v2((sx_real)0x1.e09fdp-13, (sx_real)0x1.f37958p-10);
    assert_polygons_deepest_is_mtv(pa, 3, pb, 4, X(-16.0, -16.0, 0.0), 2.034e-3, 2e-5);
}

/* Regression (fuzz: collide-tiny-box-touching-no-points): a 1e-30 box on the
 * corner (1e-30, 1e-30) of a quadrilateral whose other corners lie 1e5 away.
 * sx_overlap says the pair touches (in B's frame, the canonical order, the
 * corner is exact), but in A's frame B's faces are placed from 1e5
 * coordinates and carry a rounding error of ~1e-2 m, far above the touch
 * rescue margin, so sx_collide(A, B) used to report 0 points while
 * sx_collide(B, A) reported 2. Now the rescue falls back to the other
 * order's manifold, mirrored, and both orders agree with sx_overlap at
 * margin 0 and never report fewer points at a speculative margin. */
static void tiny_box_on_a_far_corner_touches_in_both_orders(void **state) {
    sx_shape a = sx_box_shape(SX_R(1e-30), SX_R(1e-30)), b;
    sx_vec2 q[4];
    sx_xform xa, xb;
    sx_manifold mab, mba, m;
    const double margins[] = {1e-30, 1e-6, 1e-4, 1e-3, 1e-2, (double)SX_SPECULATIVE_DISTANCE};
    int nab, nba, n, i;
    (void)state;
    q[0] = V(-100000, -99999.9766);
    q[1] = V(1e-30, -100000);
    q[2] = V(1e-30, 1e-30);
    q[3] = V(-99999.9766, 9.125);
    assert_int_equal(sx_polygon_shape(q, 4, SX_R(0.0), &b), SX_OK);
    xa.p = V(9.14781284, 9.14781284);
#ifdef SX_DOUBLE
    /* the float values are not unit to double precision: the same angle */
    xa.q = sx_rot_make(atan2(0.273437679, -0.961889744));
#else
    xa.q.c = (sx_real)-0.961889744;
    xa.q.s = (sx_real)0.273437679;
#endif
    xb.p = xa.p;
    xb.q.c = SX_R(1.0);
#ifdef SX_DOUBLE
    xb.q.s = 1.17554928e-41;
#else
    xb.q.s = FLT_MIN * 1e-3f; /* a denormal angle, 1.18e-41 */
#endif
    assert_true(sx_overlap(&a, xa, &b, xb));
    assert_true(sx_overlap(&b, xb, &a, xa));
    nab = sx_collide(&a, xa, &b, xb, &mab);
    nba = sx_collide(&b, xb, &a, xa, &mba);
    assert_true(nab >= 1 && nab <= 2);
    assert_true(nba >= 1 && nba <= 2);
    assert_int_equal(mab.count, nab);
    assert_near(sx_length(mab.normal), 1.0, 64.0 * (double)SX_REAL_EPSILON);
    for (i = 0; i < nab; ++i) {
        /* The contact is at the shared corner, touching (depth 0 up to the
         * box's size). */
        assert_near(mab.points[i].depth, 0.0, 1e-6);
        assert_near(mab.points[i].point.x, xa.p.x, 1e-5);
        assert_near(mab.points[i].point.y, xa.p.y, 1e-5);
    }
    for (i = 0; i < (int)(sizeof margins / sizeof margins[0]); ++i) {
        n = sx_collide_ex(&a, xa, &b, xb, (sx_real)margins[i], &m);
        assert_true(n >= nab);
        n = sx_collide_ex(&b, xb, &a, xa, (sx_real)margins[i], &m);
        assert_true(n >= nba);
    }
#ifndef SX_DOUBLE
    /* In float, (A, B) at margin 0 is the rescue's mirror of (B, A): the
     * same points, naming the same features, with the flipped bit (which
     * side holds the reference face) toggled, so warm starting matches them
     * whichever order the pair comes in. */
    assert_int_equal(nab, nba);
    for (i = 0; i < nab; ++i)
        assert_int_equal(mab.points[i].id, mba.points[i].id ^ (1u << 16));
#endif
}

/* Regression (make fuzz, harness collide, input
 * collide-far-tiny-octagon-rounded-gap): a tiny octagon (5 mm edges) 1e5 m
 * from a rounded octagon of radius 1e5, 16 m apart. Worked in the rounded
 * octagon's frame, the tiny one's vertices round by ~8 mm (float) while its
 * normals stay exact, so its placed edges point anywhere; the closest-feature
 * sweep took a vertex's distance to a face's line although the vertex lies
 * far beyond the face's ends, and sx_collide(B, A) reported a contact 22 km
 * deep while sx_overlap said apart. The sweep now measures where a vertex
 * projects along the face normal's edge direction. Moved 20 m closer the
 * pair overlaps by about 4 m in both orders. */
static void tiny_octagon_far_from_a_huge_rounded_octagon_is_apart_in_both_orders(void **state) {
    static const double ka[8][2] = {
        {-0.0203999989, -0.0135999992},  {-0.0184083246, -0.0184083246},
        {-0.0135999992, -0.0203999989},  {-0.00879167393, -0.0184083246},
        {-0.00679999962, -0.0135999992}, {-0.00879167393, -0.00879167207},
        {-0.0135999992, -0.00679999962}, {-0.0184083264, -0.00879167579}};
    sx_vec2 qa[8], qb[8];
    sx_shape a, b;
    sx_xform xa, xb = X(-16, -16, 0);
    sx_manifold m;
    sx_vec2 v;
    int i, order;
    (void)state;
    for (i = 0; i < 8; ++i) {
        qa[i] = V(ka[i][0], ka[i][1]);
        /* B's core is A's octagon moved up by 0.0195 */
        qb[i] = V(ka[i][0], ka[i][1] + 0.0195);
    }
    assert_int_equal(sx_polygon_shape(qa, 8, SX_R(0.0), &a), SX_OK);
    assert_int_equal(sx_polygon_shape(qb, 8, SX_R(100000.0), &b), SX_OK);
    xa.p = V(100000.0, -16.0);
    xa.q = sx_rot_make((sx_real)atan2(0.287903309, -0.957659483));
    assert_false(sx_overlap(&a, xa, &b, xb));
    assert_false(sx_overlap(&b, xb, &a, xa));
    assert_false(sx_mtv(&b, xb, &a, xa, &v));
    assert_int_equal(sx_collide(&a, xa, &b, xb, &m), 0);
    assert_int_equal(sx_collide(&b, xb, &a, xa, &m), 0);
    /* 1 m of speculative margin does not reach across the 16 m gap */
    assert_int_equal(sx_collide_ex(&b, xb, &a, xa, SX_R(1.0), &m), 0);
    /* 20 m closer: about 4 m deep (the octagons' own size is < 0.02 m) */
    xa.p = V(99980.0, -16.0);
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide(&b, xb, &a, xa, &m) : sx_collide(&a, xa, &b, xb, &m);
        assert_true(n >= 1);
        assert_near(m.points[0].depth, 4.0, 0.05);
    }
}

/* Regression (make fuzz, harness collide, input
 * collide-point-circles-denormal-normal): two point circles 1.9e-22 apart
 * (float) with a speculative margin. The squared distance, 3.6e-44, is a
 * denormal with a few bits left, so the normal d / |d| came out 0.6 % short
 * of unit length. Below SX_SQUARE_SAFE the direction is now taken from d
 * scaled by its largest component. */
static void speculative_circles_closer_than_square_underflow_get_a_unit_normal(void **state) {
#ifdef SX_DOUBLE
    const double t = 1.89755227e-160;
#else
    const double t = 1.89755227e-22;
#endif
    sx_shape p0 = sx_point_shape(sx_v2_zero()), p1 = sx_point_shape(sx_v2_zero());
    sx_xform xa = I(), xb;
    sx_manifold m;
    int order;
    (void)state;
    xb.p = V(0.0, -t);
    xb.q.c = (sx_real)-0.986081779;
    xb.q.s = (sx_real)-0.166261062;
    for (order = 0; order < 2; ++order) {
        int n = order ? sx_collide_ex(&p1, xb, &p0, xa, SX_R(3.125), &m)
                      : sx_collide_ex(&p0, xa, &p1, xb, SX_R(3.125), &m);
        assert_int_equal(n, 1);
        assert_near(sx_length(m.normal), 1.0, 64.0 * (double)SX_REAL_EPSILON);
        assert_near(m.normal.y, order ? 1.0 : -1.0, 64.0 * (double)SX_REAL_EPSILON);
        assert_near(m.points[0].depth, -t, 1e-6 * t);
    }
}

/* The segment and capsule point routines that build no core
 * (sx_core_segment_point_*, narrow.h) against the general route (the
 * 2-point core through sx_core_point_*). Random points must get the same
 * answers bit for bit; points placed level with an end (where the two find
 * the closest feature from differently rounded directions) the same
 * decisions except within rounding of touching, and values within rounding.
 * The cases the fast routines hand back (-1) are the documented ones. */
static bool same_bits(sx_real x, sx_real y) { return memcmp(&x, &y, sizeof x) == 0; }

static void segment_point_routines_match_the_core_route(void **state) {
    sx_test_rng rng = sx_test_rng_make(4141u);
    int i, level_cases = 0, handed_back = 0, level_decisions_differ = 0;
    (void)state;
    for (i = 0; i < 200000; ++i) {
        sx_vec2 a = V(sx_test_rng_range(&rng, -2, 2), sx_test_rng_range(&rng, -2, 2));
        sx_vec2 b = sx_add(a, V(sx_test_rng_range(&rng, -2, 2), sx_test_rng_range(&rng, -2, 2)));
        sx_real ra = i % 2 ? sx_test_rng_range(&rng, 0, 0.5) : SX_R(0.0);
        sx_real rb = sx_test_rng_range(&rng, 0, 0.5);
        sx_real margin = i % 3 == 0 ? SX_R(0.05) : SX_R(0.0);
        sx_capsule cap = {a, b, ra};
        int kind = i % 4, fo, fm, fc, go, gm, gc;
        sx_vec2 c, e = sx_sub(b, a), fmtv = V(7, 7), gmtv;
        sx_manifold fman, gman;
        sx_core core;
        if (kind == 0) {
            /* Level with an end, at a random height. */
            sx_vec2 end = i % 8 ? a : b;
            c = sx_mul_add(end, sx_test_rng_range(&rng, -1, 1) / sx_length(e), sx_perp(e));
            level_cases++;
        } else if (kind == 1) {
            /* On the segment, or a hair off it. */
            c = sx_lerp(a, b, sx_test_rng_range(&rng, -0.1, 1.1));
            if (i % 8 == 1) c = sx_mul_add(c, SX_R(1e-6), sx_perp(e));
        } else {
            c = sx_add(a, V(sx_test_rng_range(&rng, -3, 3), sx_test_rng_range(&rng, -3, 3)));
        }
        assert_true(sx_core_from_capsule(&cap, NULL, &core));
        go = sx_core_point_overlap(&core, c, rb);
        gm = sx_core_point_mtv(&core, c, rb, &gmtv);
        gc = sx_core_point_manifold(&core, c, rb, margin, &gman);
        fo = sx_core_segment_point_overlap(a, b, ra, c, rb);
        fm = sx_core_segment_point_mtv(a, b, ra, c, rb, &fmtv);
        fc = sx_core_segment_point_manifold(a, b, ra, c, rb, margin, &fman);
        assert_int_equal(go, gm);
        if (fo < 0 || fm < 0 || fc < 0) {
            /* Handed back: only for c on the segment or within rounding of
             * an end (the segments here are long and finite). */
            sx_real d = sx_sqrt(sx_minr(sx_distance_sq(c, a), sx_distance_sq(c, b)));
            sx_real line = sx_absr(sx_cross(e, sx_sub(c, a))) / sx_length(e);
            assert_true(line <= SX_R(1e-5) || d <= SX_R(1e-5));
            handed_back++;
            continue;
        }
        if (kind != 0) {
            assert_int_equal(fo, go);
            assert_int_equal(fm, gm);
            assert_true(same_bits(fmtv.x, gmtv.x) && same_bits(fmtv.y, gmtv.y));
            assert_int_equal(fc, gc);
            assert_int_equal(fman.count, gman.count);
            assert_true(same_bits(fman.normal.x, gman.normal.x) &&
                        same_bits(fman.normal.y, gman.normal.y));
            if (fc > 0) {
                assert_true(same_bits(fman.points[0].point.x, gman.points[0].point.x));
                assert_true(same_bits(fman.points[0].point.y, gman.points[0].point.y));
                assert_true(same_bits(fman.points[0].depth, gman.points[0].depth));
                assert_int_equal(fman.points[0].id, gman.points[0].id);
            }
            continue;
        }
        if (fo != go || fm != gm || fc != gc) {
            /* Level with an end and within rounding of touching. */
            sx_real d = sx_distance(c, i % 8 ? a : b);
            assert_near(d, ra + rb + (fc != gc ? margin : SX_R(0.0)), 1e-5);
            level_decisions_differ++;
            continue;
        }
        assert_int_equal(fo, fm);
        {
            /* An end's direction is c minus the end, rounded: near the end
             * it turns by up to a few ulps of the coordinates over the
             * distance, as it does on the general route's side of the
             * boundary too. */
            double d = (double)sx_distance(c, i % 8 ? a : b);
            double turn = 32.0 * (double)SX_REAL_EPSILON * 4.0 / d;
            if (fm > 0) assert_vec2_near(fmtv, gmtv, TOL + turn * (double)sx_length(gmtv));
            if (fc > 0) {
                assert_vec2_near(fman.normal, gman.normal, TOL + turn);
                assert_vec2_near(fman.points[0].point, gman.points[0].point,
                                 TOL + turn * (double)rb);
                assert_near(fman.points[0].depth, gman.points[0].depth, TOL);
            }
        }
    }
    assert_true(level_cases == 50000);
    /* The hand-backs are the rare points on the segment or at an end. */
    assert_true(handed_back > 0 && handed_back < 8000);
    assert_true(level_decisions_differ < 10);
}

/* The polygon point routines that build no core (sx_core_polygon_point_*,
 * narrow.h) against the general route (the polygon's core through
 * sx_core_point_*): bit for bit wherever they answer, on random polygons,
 * rounded or not, and points inside, outside, on edges and near vertices. */
static void polygon_point_routines_match_the_core_route(void **state) {
    sx_test_rng rng = sx_test_rng_make(4242u);
    int i, handed_back = 0;
    (void)state;
    for (i = 0; i < 100000; ++i) {
        sx_shape shape = sx_test_random_ngon(&rng, 3 + i % 6, 0.3, 1.5);
        sx_polygon *p = &shape.u.polygon;
        sx_real rb = sx_test_rng_range(&rng, 0, 0.5);
        sx_real margin = i % 3 == 0 ? SX_R(0.05) : SX_R(0.0);
        int k = (int)(sx_test_rng_next(&rng) % (uint64_t)p->count), fo, fm, fc, go, gm, gc;
        sx_vec2 c, fmtv = V(7, 7), gmtv;
        sx_manifold fman, gman;
        sx_core core;
        p->radius = i % 2 ? sx_test_rng_range(&rng, 0, 0.3) : SX_R(0.0);
        switch (i % 4) {
        case 0: c = V(sx_test_rng_range(&rng, -3, 3), sx_test_rng_range(&rng, -3, 3)); break;
        case 1: /* on an edge */
            c = sx_lerp(p->vertices[k], p->vertices[(k + 1) % p->count],
                        sx_test_rng_range(&rng, 0, 1));
            break;
        case 2: /* near a vertex */
            c = sx_add(p->vertices[k], V(sx_test_rng_range(&rng, -1e-3, 1e-3),
                                         sx_test_rng_range(&rng, -1e-3, 1e-3)));
            break;
        default: /* level with a vertex, outside its face */
            c = sx_mul_add(p->vertices[k], sx_test_rng_range(&rng, 0, 0.6), p->normals[k]);
            break;
        }
        assert_true(sx_core_from_polygon(p, NULL, &core));
        go = sx_core_point_overlap(&core, c, rb);
        gm = sx_core_point_mtv(&core, c, rb, &gmtv);
        gc = sx_core_point_manifold(&core, c, rb, margin, &gman);
        fo = sx_core_polygon_point_overlap(p, c, rb);
        fm = sx_core_polygon_point_mtv(p, c, rb, &fmtv);
        fc = sx_core_polygon_point_manifold(p, c, rb, margin, &fman);
        if (fo < 0 || fm < 0 || fc < 0) {
            handed_back++;
            continue;
        }
        assert_int_equal(fo, go);
        assert_int_equal(fm, gm);
        assert_true(same_bits(fmtv.x, gmtv.x) && same_bits(fmtv.y, gmtv.y));
        assert_int_equal(fc, gc);
        assert_int_equal(fman.count, gman.count);
        assert_true(same_bits(fman.normal.x, gman.normal.x) &&
                    same_bits(fman.normal.y, gman.normal.y));
        if (fc > 0) {
            assert_true(same_bits(fman.points[0].point.x, gman.points[0].point.x));
            assert_true(same_bits(fman.points[0].point.y, gman.points[0].point.y));
            assert_true(same_bits(fman.points[0].depth, gman.points[0].depth));
            assert_int_equal(fman.points[0].id, gman.points[0].id);
        }
    }
    /* Only points within rounding noise of a vertex are handed back. */
    assert_true(handed_back < 100);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circles_separated_touching_and_overlapping),
        cmocka_unit_test(swapped_circles_give_exactly_mirrored_answers),
        cmocka_unit_test(circles_with_offset_centres_use_the_local_centres),
        cmocka_unit_test(concentric_circles_push_by_the_sum_of_radii),
        cmocka_unit_test(point_inside_circle_is_pushed_out_radially),
        cmocka_unit_test(segment_circle_face_end_and_separated),
        cmocka_unit_test(circle_centred_on_segment_is_pushed_by_full_radius),
        cmocka_unit_test(zero_length_segment_acts_as_a_point),
        cmocka_unit_test(crossing_segments_overlap_by_the_shorter_push),
        cmocka_unit_test(parallel_and_collinear_segments),
        cmocka_unit_test(near_parallel_crossing_segments_have_tiny_depth),
        cmocka_unit_test(capsule_circle_side_cap_and_inside),
        cmocka_unit_test(degenerate_capsule_is_a_circle),
        cmocka_unit_test(capsule_segment_crossing_and_parallel),
        cmocka_unit_test(parallel_capsules_give_two_points),
        cmocka_unit_test(capsules_end_to_end_and_crossed),
        cmocka_unit_test(box_circle_face_corner_inside_touching),
        cmocka_unit_test(circle_just_inside_a_face_region_uses_the_exact_face_normal),
        cmocka_unit_test(rotated_box_and_point),
        cmocka_unit_test(rounded_polygon_and_circle),
        cmocka_unit_test(box_segment_through_and_resting),
        cmocka_unit_test(capsule_on_box_face_gives_two_points_tilted_gives_one),
        cmocka_unit_test(capsule_through_box_centre),
        cmocka_unit_test(boxes_separated_touching_shallow_deep),
        cmocka_unit_test(identical_boxes_at_the_same_pose),
        cmocka_unit_test(diamond_corner_into_box_face_gives_one_point),
        cmocka_unit_test(boxes_vertex_to_vertex),
        cmocka_unit_test(box_fast_path_matches_general_path),
        cmocka_unit_test(triangles_from_hand_written_hulls),
        cmocka_unit_test(rounded_boxes_face_and_corner),
        cmocka_unit_test(polygon_with_a_tiny_edge),
        cmocka_unit_test(identical_shapes_of_every_type_overlap_fully),
        cmocka_unit_test(one_shape_inside_another),
        cmocka_unit_test(capsule_end_beyond_the_other_end_keeps_its_full_depth),
        cmocka_unit_test(wide_box_on_narrow_box_is_clipped_at_both_ends),
        cmocka_unit_test(rounded_corners_nearly_aligned_give_the_exact_corner_contact),
        cmocka_unit_test(coincident_cores_push_along_a_documented_axis),
        cmocka_unit_test(nearly_coincident_circles_take_the_documented_axis),
        cmocka_unit_test(pair_functions_agree_with_the_dispatch_table),
        cmocka_unit_test(every_ordered_pair_is_consistent),
        cmocka_unit_test(random_pairs_are_self_consistent),
        cmocka_unit_test(far_from_the_origin_gives_the_same_answers),
        cmocka_unit_test(non_finite_input_answers_no_contact),
        cmocka_unit_test(null_and_unknown_types_answer_no_contact),
        cmocka_unit_test(feature_ids_stay_stable_when_b_moves_slightly),
        cmocka_unit_test(reference_face_does_not_flip_between_nearly_equal_faces),
        cmocka_unit_test(separations_at_the_top_of_the_range_still_choose_a_face),
        cmocka_unit_test(a_speculative_margin_never_reports_fewer_points_than_margin_0),
        cmocka_unit_test(a_speck_on_a_far_edge_gets_no_fewer_speculative_points),
        cmocka_unit_test(a_far_neighbour_face_ties_within_its_rounding),
        cmocka_unit_test(a_long_capsule_along_the_reference_normal_is_not_cut_by_rounding),
        cmocka_unit_test(a_reference_face_narrower_than_rounding_does_not_clip),
        cmocka_unit_test(near_collinear_faces_find_the_face_past_the_corner),
        cmocka_unit_test(circles_closer_than_square_underflow_compare_exactly),
        cmocka_unit_test(tiny_box_on_a_far_corner_touches_in_both_orders),
        cmocka_unit_test(sliver_incident_face_is_taken_at_the_deepest_vertex),
        cmocka_unit_test(bent_reference_face_tie_keeps_the_deepest_corner),
        cmocka_unit_test(tiny_octagon_far_from_a_huge_rounded_octagon_is_apart_in_both_orders),
        cmocka_unit_test(speculative_circles_closer_than_square_underflow_get_a_unit_normal),
        cmocka_unit_test(segment_point_routines_match_the_core_route),
        cmocka_unit_test(polygon_point_routines_match_the_core_route),
    };
    return cmocka_run_group_tests_name("collide", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
