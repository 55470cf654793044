/* sepax tests — compound colliders: several convex parts acting as one.
 *
 * A U (three boxes), a comb (decomposed from its outline) and an L (two
 * boxes, one given as a rotated box) are the fixtures. Overlap follows the
 * parts exactly (touching counts); the compound MTV is checked by its
 * defining property on many random placements (moving by mtv x (1 + 1e-3)
 * clears every part, moving by mtv x (1 - 1e-3) does not) and against hand
 * computed answers where one part's MTV would push the compound into another
 * part; ray casts against the closest part; bounds against the parts; mass
 * properties against the closed form of the L. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "test_support.h"

#define PI_D 3.14159265358979323846
#define MAX_PARTS 32

/* Relative slack of the MTV property: the brief's 1e-3. */
#define MTV_REL 1e-3
/* MTVs shorter than this are not tested for the (1 - 1e-3) property: the
 * shortened move differs from the full one by less than the rounding of
 * the positions in the float build. */
#define MTV_MIN_CHECKED 1e-2

typedef struct fixture {
    sx_compound_part parts[MAX_PARTS];
    sx_compound c;
} fixture;

static sx_xform at(double x, double y, double angle) {
    return sx_xform_make(sx_v2((sx_real)x, (sx_real)y), (sx_real)angle);
}

/* U: floor [-1.5, 1.5] x [0, 0.5], walls [-1.5, -1] and [1, 1.5] x [0.5, 2];
 * the notch is [-1, 1] x [0.5, 2]. */
static void make_u(fixture *f) {
    f->parts[0] = sx_compound_part_make(sx_box_shape(SX_R(1.5), SX_R(0.25)), at(0.0, 0.25, 0.0));
    f->parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(0.75)), at(-1.25, 1.25, 0.0));
    f->parts[2] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(0.75)), at(1.25, 1.25, 0.0));
    f->c.parts = f->parts;
    f->c.count = 3;
}

/* The comb of test_decompose: a 7 x 1 spine with four 1 x 2 teeth on top
 * (x in [0,1], [2,3], [4,5], [6,7]; tops at y = 3), decomposed. */
static void make_comb(fixture *f) {
    sx_vec2 p[16];
    sx_shape shapes[MAX_PARTS];
    size_t bytes;
    void *scratch;
    int n = sx_test_comb_outline(p, 4), k, count = 0;
    bytes = sx_decompose_scratch_bytes(n);
    scratch = malloc(bytes);
    assert_int_equal(sx_decompose_polygon(p, n, scratch, bytes, shapes, MAX_PARTS, &count, NULL),
                     SX_OK);
    free(scratch);
    for (k = 0; k < count; ++k)
        f->parts[k] = sx_compound_part_make(shapes[k], sx_xform_identity());
    f->c.parts = f->parts;
    f->c.count = count;
}

/* ---- overlap ------------------------------------------------------------- */

static void circle_in_u_notch_overlaps_only_when_touching_walls(void **state) {
    fixture f;
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_xform id = sx_xform_identity();
    int k;
    (void)state;
    make_u(&f);
    assert_int_equal(sx_compound_validate(&f.c), SX_OK);
    /* Free in the notch: the compound's AABB overlaps, no part does. */
    assert_false(sx_compound_overlap(&f.c, id, &ball, at(0.0, 1.25, 0.0)));
    assert_false(sx_compound_overlap(&f.c, id, &ball, at(0.49, 1.25, 0.0)));
    assert_false(sx_compound_overlap(&f.c, id, &ball, at(-0.49, 1.25, 0.0)));
    assert_false(sx_compound_overlap(&f.c, id, &ball, at(0.0, 1.01, 0.0)));
    /* Touching a wall or the floor counts; so does pressing into it. */
    assert_true(sx_compound_overlap(&f.c, id, &ball, at(0.5, 1.25, 0.0)));
    assert_true(sx_compound_overlap(&f.c, id, &ball, at(-0.5, 1.25, 0.0)));
    assert_true(sx_compound_overlap(&f.c, id, &ball, at(0.0, 1.0, 0.0)));
    assert_true(sx_compound_overlap(&f.c, id, &ball, at(0.6, 1.25, 0.0)));
    /* The same answers with the whole scene moved and turned. */
    for (k = 0; k < 8; ++k) {
        sx_xform x = at(100.0 * (double)k - 300.0, 7.0, 0.7 * (double)k);
        sx_vec2 inside = sx_xform_point(x, sx_v2(SX_R(0.0), SX_R(1.25)));
        sx_vec2 touching = sx_xform_point(x, sx_v2(SX_R(0.55), SX_R(1.25)));
        assert_false(
            sx_compound_overlap(&f.c, x, &ball, at((double)inside.x, (double)inside.y, 0.0)));
        assert_true(
            sx_compound_overlap(&f.c, x, &ball, at((double)touching.x, (double)touching.y, 0.0)));
    }
    /* Outside the U entirely. */
    assert_false(sx_compound_overlap(&f.c, id, &ball, at(0.0, 2.6, 0.0)));
    assert_false(sx_compound_overlap(&f.c, id, &ball, at(2.01, 1.0, 0.0)));
}

static void box_over_comb_teeth_collides_with_each_tooth(void **state) {
    fixture f;
    sx_shape bar = sx_box_shape(SX_R(3.4), SX_R(0.5));
    sx_shape peg = sx_box_shape(SX_R(0.4), SX_R(0.6));
    sx_compound_manifold m[MAX_PARTS];
    sx_xform id = sx_xform_identity();
    sx_vec2 mtv;
    int n, i, teeth_hit[4] = {0, 0, 0, 0};
    (void)state;
    make_comb(&f);
    assert_int_equal(sx_compound_validate(&f.c), SX_OK);
    /* A bar lying 0.2 deep on all four teeth. */
    assert_true(sx_compound_overlap(&f.c, id, &bar, at(3.5, 3.3, 0.0)));
    n = sx_compound_collide(&f.c, id, &bar, at(3.5, 3.3, 0.0), SX_R(0.0), m, MAX_PARTS);
    assert_int_equal(n, 4);
    for (i = 0; i < n; ++i) {
        int j;
        assert_int_equal(m[i].part_b, 0);
        assert_vec2_near(m[i].manifold.normal, sx_v2(SX_R(0.0), SX_R(1.0)), 1e-5);
        for (j = 0; j < m[i].manifold.count; ++j) {
            sx_vec2 q = m[i].manifold.points[j].point;
            assert_near(m[i].manifold.points[j].depth, 0.2, 1e-5);
            teeth_hit[(int)(q.x / SX_R(2.0))] = 1;
        }
    }
    for (i = 0; i < 4; ++i)
        assert_int_equal(teeth_hit[i], 1);
    /* The comb moves down by the depth to clear all four teeth at once. */
    assert_true(sx_compound_mtv(&f.c, id, &bar, at(3.5, 3.3, 0.0), &mtv));
    assert_vec2_near(mtv, sx_v2(SX_R(0.0), SX_R(-0.2)), 1e-5);
    /* A peg in a gap between teeth, above the spine: nothing. */
    assert_false(sx_compound_overlap(&f.c, id, &peg, at(1.5, 2.0, 0.0)));
    assert_int_equal(
        sx_compound_collide(&f.c, id, &peg, at(1.5, 2.0, 0.0), SX_R(0.0), m, MAX_PARTS), 0);
    /* Within a margin of 0.15 the two neighbouring teeth are reported, with
     * gaps (negative depths) of 0.1. */
    n = sx_compound_collide(&f.c, id, &peg, at(1.5, 2.0, 0.0), SX_R(0.15), m, MAX_PARTS);
    assert_int_equal(n, 2);
    for (i = 0; i < n; ++i)
        assert_near(m[i].manifold.points[0].depth, -0.1, 1e-5);
    /* The output capacity is respected. */
    assert_int_equal(sx_compound_collide(&f.c, id, &bar, at(3.5, 3.3, 0.0), SX_R(0.0), m, 2), 2);
}

/* ---- minimum translation ------------------------------------------------ */

static void u_mtv_avoids_pushing_into_the_other_wall(void **state) {
    fixture f;
    sx_xform id = sx_xform_identity();
    sx_vec2 mtv, single;
    (void)state;
    make_u(&f);
    /* A ball 0.1 into the right wall only: the compound steps right by 0.1. */
    {
        sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
        assert_true(sx_compound_mtv(&f.c, id, &ball, at(0.6, 1.25, 0.0), &mtv));
        assert_vec2_near(mtv, sx_v2(SX_R(0.1), SX_R(0.0)), 1e-5);
    }
    /* A ball wider than the notch, pressing into both walls and the floor:
     * every sideways push runs into the other wall, so the U must drop until
     * the wall tops pass under the ball: d = 0.5 + sqrt(1.05^2 - 1). */
    {
        sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(1.05));
        double d = 0.5 + sqrt(1.05 * 1.05 - 1.0);
        assert_true(sx_compound_mtv(&f.c, id, &ball, at(0.0, 1.5, 0.0), &mtv));
        assert_vec2_near(mtv, sx_v2(SX_R(0.0), (sx_real)-d), 1e-4);
        /* Any single part's MTV is far shorter and does not clear the rest. */
        assert_true(
            sx_mtv(&f.parts[2].shape, f.parts[2].offset, &ball, at(0.0, 1.5, 0.0), &single));
        assert_true((double)sx_length(single) < 0.1);
        assert_true(sx_compound_overlap(&f.c, at((double)single.x, (double)single.y, 0.0), &ball,
                                        at(0.0, 1.5, 0.0)));
    }
}

static void one_part_compound_mtv_matches_the_narrowphase(void **state) {
    sx_compound_part part;
    sx_compound c;
    sx_test_rng rng = sx_test_rng_make(77);
    int k;
    (void)state;
    part = sx_compound_part_make(sx_box_shape(SX_R(0.6), SX_R(0.3)), at(0.2, -0.1, 0.4));
    c.parts = &part;
    c.count = 1;
    for (k = 0; k < 200; ++k) {
        sx_shape other =
            sx_capsule_shape(sx_v2(SX_R(-0.3), SX_R(0.0)), sx_v2(SX_R(0.3), SX_R(0.1)), SX_R(0.25));
        sx_xform xo = at((double)sx_test_rng_range(&rng, -1.0, 1.0),
                         (double)sx_test_rng_range(&rng, -1.0, 1.0),
                         (double)sx_test_rng_range(&rng, -3.0, 3.0));
        sx_vec2 m1, m2;
        bool o1 = sx_compound_mtv(&c, sx_xform_identity(), &other, xo, &m1);
        bool o2 = sx_mtv(&part.shape, part.offset, &other, xo, &m2);
        assert_int_equal(o1, o2);
        /* Same length (it is the minimum); the direction may differ only on
         * ties. */
        assert_near(sx_length(m1), sx_length(m2), 1e-4);
    }
}

/* Checks the MTV property of compound a (at xa) against the placed shape or
 * compound; returns 1 when a penetrating case was checked. */
static int check_mtv_shape(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    sx_vec2 mtv;
    sx_xform moved = xa;
    double len;
    if (!sx_compound_mtv(a, xa, b, xb, &mtv)) {
        assert_vec2_near(mtv, sx_v2_zero(), 0.0);
        assert_false(sx_compound_overlap(a, xa, b, xb));
        return 0;
    }
    assert_true(sx_compound_overlap(a, xa, b, xb));
    len = (double)sx_length(mtv);
    if (len < MTV_MIN_CHECKED) return 0;
    moved.p = sx_add(xa.p, sx_scale(mtv, (sx_real)(1.0 + MTV_REL)));
    assert_false(sx_compound_overlap(a, moved, b, xb));
    moved.p = sx_add(xa.p, sx_scale(mtv, (sx_real)(1.0 - MTV_REL)));
    assert_true(sx_compound_overlap(a, moved, b, xb));
    return 1;
}

static int check_mtv_compound(const sx_compound *a, sx_xform xa, const sx_compound *b,
                              sx_xform xb) {
    sx_vec2 mtv;
    sx_xform moved = xa;
    if (!sx_compound_mtv_compound(a, xa, b, xb, &mtv)) {
        assert_false(sx_compound_overlap_compound(a, xa, b, xb));
        return 0;
    }
    if ((double)sx_length(mtv) < MTV_MIN_CHECKED) return 0;
    moved.p = sx_add(xa.p, sx_scale(mtv, (sx_real)(1.0 + MTV_REL)));
    assert_false(sx_compound_overlap_compound(a, moved, b, xb));
    moved.p = sx_add(xa.p, sx_scale(mtv, (sx_real)(1.0 - MTV_REL)));
    assert_true(sx_compound_overlap_compound(a, moved, b, xb));
    return 1;
}

static void compound_mtv_separates_in_one_move_on_random_placements(void **state) {
    fixture u, comb;
    sx_test_rng rng = sx_test_rng_make(0xc0ffee);
    int k, checked = 0;
    (void)state;
    make_u(&u);
    make_comb(&comb);
    for (k = 0; k < 600; ++k) {
        const fixture *f = (k % 2 == 0) ? &u : &comb;
        sx_aabb box = sx_compound_aabb(&f->c, sx_xform_identity());
        sx_shape other;
        sx_xform xb = at((double)sx_test_rng_range(&rng, (double)box.lower.x, (double)box.upper.x),
                         (double)sx_test_rng_range(&rng, (double)box.lower.y, (double)box.upper.y),
                         (double)sx_test_rng_range(&rng, -3.0, 3.0));
        switch (k % 3) {
        case 0: other = sx_circle_shape(sx_v2_zero(), sx_test_rng_range(&rng, 0.2, 1.2)); break;
        case 1:
            other =
                sx_box_shape(sx_test_rng_range(&rng, 0.1, 1.5), sx_test_rng_range(&rng, 0.1, 0.8));
            break;
        default:
            other = sx_capsule_shape(sx_v2(SX_R(-0.5), SX_R(0.0)), sx_v2(SX_R(0.5), SX_R(0.0)),
                                     sx_test_rng_range(&rng, 0.1, 0.6));
            break;
        }
        checked += check_mtv_shape(&f->c, at(0.0, 0.0, 0.0), &other, xb);
    }
    printf("  compound vs shape: %d penetrating placements checked\n", checked);
    assert_true(checked > 300);
}

static void compound_vs_compound_mtv_separates_in_one_move(void **state) {
    fixture u, comb;
    sx_test_rng rng = sx_test_rng_make(0xbeef);
    int k, checked = 0;
    (void)state;
    make_u(&u);
    make_comb(&comb);
    for (k = 0; k < 150; ++k) {
        sx_xform xa =
            at((double)sx_test_rng_range(&rng, 0.0, 7.0), (double)sx_test_rng_range(&rng, 0.0, 3.0),
               (double)sx_test_rng_range(&rng, -3.0, 3.0));
        checked += check_mtv_compound(&u.c, xa, &comb.c, sx_xform_identity());
    }
    printf("  compound vs compound: %d penetrating placements checked\n", checked);
    assert_true(checked > 75);
    /* Overlap is symmetric. */
    assert_true(
        sx_compound_overlap_compound(&u.c, at(3.0, 2.0, 0.0), &comb.c, sx_xform_identity()));
    assert_true(
        sx_compound_overlap_compound(&comb.c, sx_xform_identity(), &u.c, at(3.0, 2.0, 0.0)));
    assert_false(
        sx_compound_overlap_compound(&u.c, at(3.5, 3.01, 0.0), &comb.c, sx_xform_identity()));
}

/* The shortest push along angle th that leaves no overlap, scanning the
 * push length in steps of `step` up to `limit` (SX_REAL_MAX if none). */
static double brute_clear(const sx_compound *c, const sx_shape *b, sx_xform xb, double th,
                          double step, double limit) {
    double lam;
    for (lam = 0.0; lam < limit; lam += step) {
        if (!sx_compound_overlap(c, at(lam * cos(th), lam * sin(th), 0.0), b, xb)) return lam;
    }
    return (double)SX_REAL_MAX;
}

static void compound_mtv_is_near_the_brute_force_minimum(void **state) {
    fixture u;
    sx_test_rng rng = sx_test_rng_make(4242);
    int cases = 0, k;
    (void)state;
    make_u(&u);
    while (cases < 12) {
        sx_shape other = (cases % 2 == 1)
                             ? sx_circle_shape(sx_v2_zero(), sx_test_rng_range(&rng, 0.2, 1.2))
                             : sx_box_shape(sx_test_rng_range(&rng, 0.1, 1.2),
                                            sx_test_rng_range(&rng, 0.1, 0.6));
        sx_xform xb = at((double)sx_test_rng_range(&rng, -1.5, 1.5),
                         (double)sx_test_rng_range(&rng, 0.0, 2.0),
                         (double)sx_test_rng_range(&rng, -3.0, 3.0));
        sx_vec2 mtv;
        double ours, brute = 1e30;
        if (!sx_compound_mtv(&u.c, sx_xform_identity(), &other, xb, &mtv)) continue;
        ours = (double)sx_length(mtv);
        if (ours < MTV_MIN_CHECKED) continue;
        for (k = 0; k < 360; ++k) {
            double b = brute_clear(&u.c, &other, xb, 2.0 * PI_D * (double)k / 360.0, 0.005,
                                   brute < 1e29 ? brute : 1.2 * ours);
            if (b < brute) brute = b;
        }
        /* The scan's own resolution: one step, and 1 degree of direction. */
        assert_true(ours <= 1.05 * brute + 0.005);
        ++cases;
    }
}

/* ---- queries ------------------------------------------------------------- */

static void ray_cast_reports_the_nearest_part(void **state) {
    fixture f;
    sx_ray_input ray;
    sx_ray_hit hit;
    sx_test_rng rng = sx_test_rng_make(5);
    sx_xform x = at(2.0, -1.0, 0.3);
    int part, k;
    (void)state;
    make_u(&f);
    /* From the left at notch height: the left wall's outer face. */
    ray.origin = sx_v2(SX_R(-3.0), SX_R(1.25));
    ray.translation = sx_v2(SX_R(6.0), SX_R(0.0));
    ray.max_fraction = SX_R(1.0);
    assert_true(sx_compound_ray_cast(&f.c, sx_xform_identity(), &ray, &hit, &part));
    assert_int_equal(part, 1);
    assert_near(hit.fraction, 0.25, 1e-6);
    assert_vec2_near(hit.normal, sx_v2(SX_R(-1.0), SX_R(0.0)), 1e-6);
    /* From inside the notch: the right wall's inner face. */
    ray.origin = sx_v2(SX_R(0.0), SX_R(1.25));
    ray.translation = sx_v2(SX_R(3.0), SX_R(0.0));
    assert_true(sx_compound_ray_cast(&f.c, sx_xform_identity(), &ray, &hit, &part));
    assert_int_equal(part, 2);
    assert_near(hit.fraction, 1.0 / 3.0, 1e-6);
    /* Straight up out of the notch: a miss. */
    ray.translation = sx_v2(SX_R(0.0), SX_R(3.0));
    assert_false(sx_compound_ray_cast(&f.c, sx_xform_identity(), &ray, &hit, &part));
    assert_int_equal(part, -1);
    assert_false(hit.hit);
    /* Random rays against a placed compound: the closest of the parts. */
    for (k = 0; k < 300; ++k) {
        sx_ray_hit best, h;
        int i, best_part = -1;
        ray.origin = sx_v2(sx_test_rng_range(&rng, -2.0, 6.0), sx_test_rng_range(&rng, -4.0, 3.0));
        ray.translation =
            sx_v2(sx_test_rng_range(&rng, -6.0, 6.0), sx_test_rng_range(&rng, -6.0, 6.0));
        best.fraction = SX_R(2.0);
        for (i = 0; i < f.c.count; ++i) {
            if (sx_ray_cast(&f.parts[i].shape, sx_xform_mul(x, f.parts[i].offset), &ray, &h) &&
                h.fraction < best.fraction) {
                best = h;
                best_part = i;
            }
        }
        assert_int_equal(sx_compound_ray_cast(&f.c, x, &ray, &hit, &part), best_part >= 0);
        assert_int_equal(part, best_part);
        if (best_part >= 0) assert_near(hit.fraction, best.fraction, 0.0);
    }
}

/* First crossing of the ray origin + s * dir (s in [0, 1]) with the outline's
 * edges, in double; 2 when none. */
static double first_crossing(const sx_vec2 *p, int n, sx_vec2 o, sx_vec2 dir) {
    double best = 2.0;
    int i;
    for (i = 0; i < n; ++i) {
        double ax = (double)p[i].x, ay = (double)p[i].y;
        double ex = (double)p[(i + 1) % n].x - ax, ey = (double)p[(i + 1) % n].y - ay;
        double dx = (double)dir.x, dy = (double)dir.y, wx = ax - (double)o.x, wy = ay - (double)o.y;
        double den = dx * ey - dy * ex, s, u;
        if (den == 0.0) continue;
        s = (wx * ey - wy * ex) / den;
        u = (wx * dy - wy * dx) / den;
        if (s >= 0.0 && s <= 1.0 && u >= 0.0 && u <= 1.0 && s < best) best = s;
    }
    return best;
}

static void decomposed_spiral_compound_matches_its_outline(void **state) {
    sx_vec2 p[64];
    sx_shape shapes[64];
    sx_compound_part parts[64];
    sx_compound c;
    sx_test_rng rng = sx_test_rng_make(31);
    size_t bytes;
    void *scratch;
    int n = 0, i, count = 0, hits = 0, inside = 0;
    (void)state;
    for (i = 0; i < 24; ++i) {
        double t = 3.0 * PI_D * (double)i / 23.0, r = 0.85 + 0.3 * t;
        p[n++] = sx_v2((sx_real)(r * cos(t)), (sx_real)(r * sin(t)));
    }
    for (i = 23; i >= 0; --i) {
        double t = 3.0 * PI_D * (double)i / 23.0, r = 0.6 + 0.3 * t;
        p[n++] = sx_v2((sx_real)(r * cos(t)), (sx_real)(r * sin(t)));
    }
    bytes = sx_decompose_scratch_bytes(n);
    scratch = malloc(bytes);
    assert_int_equal(sx_decompose_polygon(p, n, scratch, bytes, shapes, 64, &count, NULL), SX_OK);
    free(scratch);
    for (i = 0; i < count; ++i)
        parts[i] = sx_compound_part_make(shapes[i], sx_xform_identity());
    c.parts = parts;
    c.count = count;
    assert_int_equal(sx_compound_validate(&c), SX_OK);
    /* Rays from outside the outline's box: the first part hit is where the
     * ray first crosses the raw outline. */
    for (i = 0; i < 300; ++i) {
        double a = 2.0 * PI_D * sx_test_rng_unit(&rng);
        sx_ray_input ray;
        sx_ray_hit hit;
        double expect;
        int part;
        ray.origin = sx_v2((sx_real)(6.0 * cos(a)), (sx_real)(6.0 * sin(a)));
        ray.translation =
            sx_sub(sx_v2(sx_test_rng_range(&rng, -2.0, 2.0), sx_test_rng_range(&rng, -2.0, 2.0)),
                   ray.origin);
        ray.max_fraction = SX_R(1.0);
        expect = first_crossing(p, n, ray.origin, ray.translation);
        assert_int_equal(sx_compound_ray_cast(&c, sx_xform_identity(), &ray, &hit, &part),
                         expect <= 1.0);
        if (expect <= 1.0) {
            assert_near(hit.fraction, expect, 1e-5);
            assert_true(part >= 0 && part < count);
            ++hits;
        }
    }
    /* Containment agrees with the winding number away from the boundary. */
    for (i = 0; i < 2000; ++i) {
        sx_vec2 q = sx_v2(sx_test_rng_range(&rng, -4.0, 4.0), sx_test_rng_range(&rng, -4.0, 4.0));
        bool in_outline = sx_point_in_outline(p, n, q);
        double near_edge = 1e30;
        int j;
        for (j = 0; j < n; ++j) {
            sx_vec2 e0 = p[j], e1 = p[(j + 1) % n];
            double ex = (double)e1.x - (double)e0.x, ey = (double)e1.y - (double)e0.y;
            double wx = (double)q.x - (double)e0.x, wy = (double)q.y - (double)e0.y;
            double t = (wx * ex + wy * ey) / (ex * ex + ey * ey), dx, dy;
            t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
            dx = wx - t * ex;
            dy = wy - t * ey;
            if (sqrt(dx * dx + dy * dy) < near_edge) near_edge = sqrt(dx * dx + dy * dy);
        }
        if (near_edge < 1e-4) continue;
        assert_int_equal(sx_compound_contains_point(&c, sx_xform_identity(), q, NULL), in_outline);
        inside += in_outline ? 1 : 0;
    }
    assert_true(hits > 100);
    assert_true(inside > 50);
}

static void point_containment_reports_the_part(void **state) {
    fixture f;
    sx_xform x = at(-4.0, 2.0, 1.1);
    int part;
    (void)state;
    make_u(&f);
    assert_true(
        sx_compound_contains_point(&f.c, x, sx_xform_point(x, sx_v2(SX_R(1.2), SX_R(1.5))), &part));
    assert_int_equal(part, 2);
    assert_true(
        sx_compound_contains_point(&f.c, x, sx_xform_point(x, sx_v2(SX_R(0.0), SX_R(0.2))), &part));
    assert_int_equal(part, 0);
    assert_false(
        sx_compound_contains_point(&f.c, x, sx_xform_point(x, sx_v2(SX_R(0.0), SX_R(1.2))), &part));
    assert_int_equal(part, -1);
    assert_false(sx_compound_contains_point(NULL, x, sx_v2_zero(), &part));
}

static void aabb_contains_every_part(void **state) {
    fixture f;
    sx_test_rng rng = sx_test_rng_make(9);
    int k, i;
    (void)state;
    make_comb(&f);
    for (k = 0; k < 100; ++k) {
        sx_xform x = at((double)sx_test_rng_range(&rng, -50.0, 50.0),
                        (double)sx_test_rng_range(&rng, -50.0, 50.0),
                        (double)sx_test_rng_range(&rng, -4.0, 4.0));
        sx_aabb box = sx_compound_aabb(&f.c, x), u;
        u = sx_shape_aabb(&f.parts[0].shape, sx_xform_mul(x, f.parts[0].offset));
        for (i = 0; i < f.c.count; ++i) {
            sx_aabb pb = sx_shape_aabb(&f.parts[i].shape, sx_xform_mul(x, f.parts[i].offset));
            assert_true(sx_aabb_contains(box, pb));
            u = sx_aabb_union(u, pb);
        }
        /* And it is tight: exactly the union. */
        assert_vec2_near(box.lower, u.lower, 0.0);
        assert_vec2_near(box.upper, u.upper, 0.0);
    }
}

/* ---- mass ---------------------------------------------------------------- */

static void l_from_two_boxes_has_the_mass_of_the_l(void **state) {
    /* L = [0,2] x [0,1] and [0,1] x [1,2]. Closed form: area 3, centroid
     * (5/6, 5/6), polar moment about the origin 6, about the centroid
     * 6 - 3 (2 (5/6)^2) = 11/6 (per unit density). */
    sx_compound_part parts[2];
    sx_compound c;
    sx_mass_data md;
    const double density = 2.5;
    (void)state;
    /* The long box given as a tall box turned by 90 degrees. */
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(1.0)), at(1.0, 0.5, PI_D / 2.0));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(0.5, 1.5, 0.0));
    c.parts = parts;
    c.count = 2;
    md = sx_compound_mass(&c, (sx_real)density);
    assert_near(md.mass, 3.0 * density, 1e-5);
    assert_vec2_near(md.center, sx_v2((sx_real)(5.0 / 6.0), (sx_real)(5.0 / 6.0)), 1e-6);
    assert_near(md.rotational_inertia, 11.0 / 6.0 * density, 1e-5);
    /* The decomposed L outline gives the same. */
    {
        sx_vec2 p[6];
        sx_shape shapes[4];
        sx_compound_part dp[4];
        unsigned char scratch[4096];
        int n = 0, i;
        static const double xy[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
        for (i = 0; i < 6; ++i)
            p[i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
        assert_true(sx_decompose_scratch_bytes(6) <= sizeof scratch);
        assert_int_equal(sx_decompose_polygon(p, 6, scratch, sizeof scratch, shapes, 4, &n, NULL),
                         SX_OK);
        for (i = 0; i < n; ++i)
            dp[i] = sx_compound_part_make(shapes[i], sx_xform_identity());
        c.parts = dp;
        c.count = n;
        md = sx_compound_mass(&c, (sx_real)density);
        assert_near(md.mass, 3.0 * density, 1e-5);
        assert_vec2_near(md.center, sx_v2((sx_real)(5.0 / 6.0), (sx_real)(5.0 / 6.0)), 1e-6);
        assert_near(md.rotational_inertia, 11.0 / 6.0 * density, 1e-5);
    }
    /* Density 0: no mass, centre at the area centroid; bad density: zeros. */
    c.parts = parts;
    c.count = 2;
    md = sx_compound_mass(&c, SX_R(0.0));
    assert_near(md.mass, 0.0, 0.0);
    assert_vec2_near(md.center, sx_v2((sx_real)(5.0 / 6.0), (sx_real)(5.0 / 6.0)), 1e-6);
    md = sx_compound_mass(&c, SX_R(-1.0));
    assert_near(md.mass, 0.0, 0.0);
    assert_vec2_near(md.center, sx_v2_zero(), 0.0);
    md = sx_compound_mass(&c, (sx_real)NAN);
    assert_near(md.rotational_inertia, 0.0, 0.0);
}

/* Regression (fuzz: compound-mass-nan-on-overflow): a part whose mass
 * overflows sx_real used to give centre = inf / inf = NaN and a NaN
 * inertia. The compound now answers as sx_shape_mass does for that part:
 * infinite mass and inertia, a finite centre. The fuzz case was a circle of
 * radius 1e30, which sx_shape_validate now refuses (its mass overflows at
 * any density); the same overflow comes from a valid circle at the largest
 * density. */
static void a_part_too_heavy_for_sx_real_gives_no_nan(void **state) {
    const sx_real density = SX_REAL_MAX;
    sx_shape heavy = sx_circle_shape(sx_v2(SX_R(-16.0), SX_R(-16.0)), SX_R(1e5));
    sx_compound_part parts[2];
    sx_compound c;
    sx_mass_data md, sm = sx_shape_mass(&heavy, density);
    (void)state;
    assert_int_equal(sx_shape_validate(&heavy), SX_OK);
    assert_false(sx_is_finite(sm.mass)); /* the case has teeth: sx_real overflows */
    assert_vec2_near(sm.center, sx_v2(SX_R(-16.0), SX_R(-16.0)), 0.0);
    parts[0] = sx_compound_part_make(heavy, at(-16.0, -16.0, 0.0));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(1.0), SX_R(1.0)), at(100.0, 0.0, 0.0));
    c.parts = parts;
    for (c.count = 1; c.count <= 2; ++c.count) {
        assert_int_equal(sx_compound_validate(&c), SX_OK);
        md = sx_compound_mass(&c, density);
        assert_true(md.mass == sm.mass);
        assert_true(md.rotational_inertia == sm.rotational_inertia);
        /* The box weighs nothing next to the circle (1e-10 of it): the
         * centre is the circle's, offset by the part's placement. */
        assert_vec2_near(md.center, sx_v2(SX_R(-32.0), SX_R(-32.0)), 1e-4);
        md = sx_compound_mass(&c, SX_R(0.0));
        assert_near(md.mass, 0.0, 0.0);
        assert_near(md.rotational_inertia, 0.0, 0.0);
        assert_vec2_near(md.center, sx_v2(SX_R(-32.0), SX_R(-32.0)), 1e-4);
    }
}

/* Every part pair of a (moved by mtv) against b penetrates by at most the
 * compound MTV's guarantee, as sx_mtv measures it. */
static void assert_cleared(const sx_compound *a, sx_xform xa, const sx_compound *b, sx_xform xb,
                           sx_vec2 mtv) {
    int i, j;
    xa.p = sx_add(xa.p, mtv);
    for (i = 0; i < a->count; ++i) {
        for (j = 0; j < b->count; ++j) {
            sx_vec2 v;
            sx_mtv(&a->parts[i].shape, sx_xform_mul(xa, a->parts[i].offset), &b->parts[j].shape,
                   sx_xform_mul(xb, b->parts[j].offset), &v);
            assert_true(sx_length(v) <= SX_LINEAR_SLOP * SX_R(1e-3));
        }
    }
}

/* Regression (fuzz: compound-mtv-stalls-on-far-box-corner): a point (a
 * circle of radius 0) exactly on the corner of a 2e5-wide box part whose
 * centre lies 1.4e5 from the origin, rotated by 133 degrees. In the float
 * build sx_mtv, in the box's frame, finds the point one ulp there (2^-7 m)
 * inside, while the world-frame support functions of the clearing walk put
 * it on the faces and gave a push of 0: the walk stood still in every
 * direction, and the bounding-box fallback (rounded like the supports)
 * returned a push of 3e-33 m that left the 2^-7 m penetration. Now a pair's
 * step is never shorter than its own MTV, and the answer is about one ulp
 * long and clears every pair. */
static void compound_mtv_clears_a_point_on_a_far_box_corner(void **state) {
    const sx_real tiny = (sx_real)0x1.7413ecp-109, h = SX_R(100000.0);
    sx_compound_part ap, bp[2];
    sx_compound a, b, box_only;
    sx_xform xa, xb;
    sx_vec2 mtv, v;
    (void)state;
    ap = sx_compound_part_make(sx_circle_shape(sx_v2_zero(), SX_R(0.0)), sx_xform_identity());
    bp[0] = sx_compound_part_make(sx_circle_shape(sx_v2_zero(), tiny), sx_xform_identity());
    bp[1] = sx_compound_part_make(sx_box_shape(h, h), sx_xform_make(sx_v2(h, h), SX_R(0.0)));
    a.parts = &ap;
    a.count = 1;
    b.parts = bp;
    b.count = 2;
    box_only.parts = &bp[1];
    box_only.count = 1;
    assert_int_equal(sx_compound_validate(&a), SX_OK);
    assert_int_equal(sx_compound_validate(&b), SX_OK);
    xa.p = sx_v2(tiny, tiny);
    xa.q.c = SX_R(1.0);
    xa.q.s = tiny;
    xb.p = xa.p;
#ifdef SX_DOUBLE
    /* the float values are not unit to double precision: the same angle */
    xb.q = sx_rot_make(atan2(0x1.782a64p-1, -0x1.5b567p-1));
#else
    xb.q.c = -0x1.5b567p-1f;
    xb.q.s = 0x1.782a64p-1f;
    /* The case has teeth: the narrowphase sees the corner one ulp deep. */
    assert_true(sx_mtv(&ap.shape, xa, &bp[1].shape, sx_xform_mul(xb, bp[1].offset), &v));
    assert_true(sx_length(v) > SX_LINEAR_SLOP * SX_R(1e-3));
#endif
    (void)v;
    assert_true(sx_compound_mtv_compound(&a, xa, &b, xb, &mtv));
    assert_true(sx_vec2_is_finite(mtv));
    assert_true((double)sx_length(mtv) < 0.05); /* a few ulps of 1e5 in float */
    assert_cleared(&a, xa, &b, xb, mtv);
    /* The box alone, as a plain shape. */
    assert_true(sx_compound_mtv(&a, xa, &bp[1].shape, sx_xform_mul(xb, bp[1].offset), &mtv));
    assert_true(sx_vec2_is_finite(mtv));
    assert_true((double)sx_length(mtv) < 0.05);
    assert_cleared(&a, xa, &box_only, xb, mtv);
}

/* The same rounding along a face (fuzz: compound-mtv-stalls-on-far-box-corner,
 * generalised): a point 1 to 8 float ulps (2^-7 m each) inside a face of a
 * 2e5-wide box 1e5 from the origin, at 40 placements. Two things stopped the
 * walk there, in every direction, so the bounding-box fallback pushed the
 * point out through the whole box (tens of km): the supports giving a push
 * of 0 to a pair sx_mtv still sees penetrating (now floored by its MTV), and,
 * where a push ends with the pair touching within rounding, sx_overlap
 * answering "touching" for further pushes of about an ulp, which the gap
 * probes took for an obstacle ahead and crept on by 0.25% steps until the
 * sweep budget ran out (now only a pair that penetrates at a probe is
 * stepped over). The answer is now the narrowphase's MTV within a few ulps. */
static void compound_mtv_of_a_point_just_inside_a_far_box_face_is_its_mtv(void **state) {
    const sx_real h = SX_R(100000.0);
    sx_shape box = sx_box_shape(h, h);
    sx_compound_part ap, bp;
    sx_compound a, box_only;
    int k;
    (void)state;
    ap = sx_compound_part_make(sx_circle_shape(sx_v2_zero(), SX_R(0.0)), sx_xform_identity());
    bp = sx_compound_part_make(box, sx_xform_identity());
    a.parts = &ap;
    a.count = 1;
    box_only.parts = &bp;
    box_only.count = 1;
    for (k = 0; k < 40; ++k) {
        sx_xform xb = at(3.0 + 1e5 * cos(0.37 * k), -2.0 + 1e5 * sin(0.37 * k), 0.37 * k), xa;
        sx_real depth = SX_R(0.0078125) * (sx_real)(1 + k % 8);
        sx_real along = SX_R(150.0) * (sx_real)((k * 7919) % 1000) - SX_R(80000.0);
        sx_vec2 m, mtv;
        xa = sx_xform_make(sx_xform_point(xb, sx_v2(-h + depth, along)), SX_R(0.0));
        assert_true(sx_mtv(&ap.shape, xa, &box, xb, &m));
        assert_true(sx_compound_mtv(&a, xa, &box, xb, &mtv));
        assert_true(sx_vec2_is_finite(mtv));
        assert_true((double)sx_length(mtv) <= (double)sx_length(m) + 0.05);
        assert_cleared(&a, xa, &box_only, xb, mtv);
    }
}

/* Regression (fuzz: compound-mtv-compound-walk-timeout): two compounds
 * placed 1.8e19 m from the origin (far beyond SX_HUGE, an ulp of 2e12 m)
 * with the same transform. The clearing walk took its supports in world
 * space, where they were noise; every walk crawled through its budget, one
 * call took 2 s, and the answer was a zero MTV for a pair 0.3 m deep. Far
 * out the walk now works from B's origin, so the pair gets the answer it
 * gets at the origin. */
static void compound_mtv_far_beyond_huge_is_the_mtv_at_the_origin(void **state) {
    sx_compound_part ap[3], bp[2];
    sx_compound a, b;
    sx_vec2 near, far;
    sx_xform x0 = sx_xform_make(sx_v2_zero(), SX_R(0.3));
    sx_xform xf = sx_xform_make(sx_v2(SX_R(1.8e19), SX_R(1.8e19)), SX_R(0.3));
    (void)state;
    ap[0] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), sx_xform_identity());
    ap[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(1.0, 0.0, 0.0));
    ap[2] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(2.0, 0.0, 0.0));
    bp[0] = sx_compound_part_make(sx_box_shape(SX_R(1.5), SX_R(0.5)), at(1.0, 0.7, 0.0));
    bp[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(4.0, 0.7, 0.0));
    a.parts = ap;
    a.count = 3;
    b.parts = bp;
    b.count = 2;
    assert_true(sx_compound_mtv_compound(&a, x0, &b, x0, &near));
    assert_true((double)sx_length(near) > 0.2); /* 0.3 m deep along B's bottom face */
    assert_true(sx_compound_mtv_compound(&a, xf, &b, xf, &far));
    assert_true(sx_vec2_is_finite(far));
    assert_near(far.x, near.x, 1e-4);
    assert_near(far.y, near.y, 1e-4);
}

/* Regression (make fuzz, compound-part-rotation-off-unit-long-normal): a
 * part whose offset rotation is 8.2e-5 longer than unit, which
 * sx_compound_validate accepts (1e-3), was placed as given, and its
 * manifold against a segment came back with a normal of length 1.0000819.
 * The part is placed with its rotation made unit: the normal is unit, the
 * manifold is that of the unit placement, and a world holding the compound
 * stores that placement. */
static void part_rotation_off_unit_is_placed_unit(void **state) {
    sx_compound_part part;
    sx_compound c;
    sx_compound_manifold m[2];
    sx_manifold ref;
    sx_shape seg =
        sx_segment_shape(sx_v2(SX_R(-16.0), SX_R(-14.125)), sx_v2(SX_R(-16.0), SX_R(-128.0)));
    sx_xform x = sx_xform_make(sx_v2(SX_R(-128.0), SX_R(-128.0)), SX_R(-2.3356));
    sx_xform off, placed;
    double len;
    (void)state;
    off.p = sx_v2(SX_R(-16.0), SX_R(-128.0));
    off.q.c = SX_R(-0.0128);
    off.q.s = SX_R(-1.0);
    part = sx_compound_part_make(
        sx_segment_shape(sx_v2(SX_R(-16.0), SX_R(15.875)), sx_v2(SX_R(-8.125), SX_R(-15.625))),
        off);
    c.parts = &part;
    c.count = 1;
    assert_int_equal(sx_compound_validate(&c), SX_OK);
    placed = sx_compound_part_placement(sx_xform_identity(), &part);
    assert_near(sx_length(sx_v2(placed.q.c, placed.q.s)), 1.0, 4.0 * (double)SX_REAL_EPSILON);
    assert_near(placed.q.s / placed.q.c, off.q.s / off.q.c,
                1e-6 * fabs((double)(off.q.s / off.q.c)));
    assert_int_equal(sx_compound_collide(&c, x, &seg, x, SX_R(0.0), m, 2), 1);
    len = (double)sx_length(m[0].manifold.normal);
    assert_true(fabs(len - 1.0) <= 64.0 * (double)SX_REAL_EPSILON);
    assert_int_equal(sx_collide(&part.shape, sx_compound_part_placement(x, &part), &seg, x, &ref),
                     m[0].manifold.count);
    assert_true(ref.normal.x == m[0].manifold.normal.x && ref.normal.y == m[0].manifold.normal.y);
    /* A rotation from sx_rot_make is used bit for bit as given. */
    part.offset = sx_xform_make(off.p, SX_R(0.7));
    placed = sx_compound_part_placement(sx_xform_identity(), &part);
    assert_true(placed.q.c == part.offset.q.c && placed.q.s == part.offset.q.s);
    assert_true(placed.p.x == part.offset.p.x && placed.p.y == part.offset.p.y);
}

/* ---- bad input ----------------------------------------------------------- */

static void invalid_compounds_are_reported_and_answered_safely(void **state) {
    fixture f;
    sx_compound empty;
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(1.0));
    sx_compound_manifold m[4];
    sx_vec2 mtv = sx_v2(SX_R(1.0), SX_R(1.0));
    sx_aabb box;
    sx_xform id = sx_xform_identity();
    (void)state;
    make_u(&f);
    empty.parts = f.parts;
    empty.count = 0;
    assert_int_equal(sx_compound_validate(NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_compound_validate(&empty), SX_ERR_INVALID_ARG);
    f.parts[1].offset.p.x = (sx_real)NAN;
    assert_int_equal(sx_compound_validate(&f.c), SX_ERR_NONFINITE);
    make_u(&f);
    f.parts[1].offset.q.c = SX_R(2.0);
    assert_int_equal(sx_compound_validate(&f.c), SX_ERR_INVALID_ARG);
    make_u(&f);
    f.parts[2].shape = sx_circle_shape(sx_v2_zero(), SX_R(-1.0));
    assert_int_equal(sx_compound_validate(&f.c), SX_ERR_INVALID_ARG);
    assert_near(sx_compound_mass(&f.c, SX_R(1.0)).mass, 0.0, 0.0);

    assert_false(sx_compound_overlap(NULL, id, &ball, id));
    assert_false(sx_compound_overlap(&empty, id, &ball, id));
    assert_false(sx_compound_overlap(&f.c, id, NULL, id));
    assert_false(sx_compound_mtv(&empty, id, &ball, id, &mtv));
    assert_vec2_near(mtv, sx_v2_zero(), 0.0);
    assert_false(sx_compound_mtv_compound(&f.c, id, NULL, id, &mtv));
    assert_int_equal(sx_compound_collide(&empty, id, &ball, id, SX_R(0.0), m, 4), 0);
    assert_int_equal(sx_compound_collide(&f.c, id, &ball, id, SX_R(0.0), NULL, 4), 0);
    assert_int_equal(sx_compound_collide(&f.c, id, &ball, id, SX_R(0.0), m, 0), 0);
    box = sx_compound_aabb(&empty, at(3.0, 4.0, 0.0));
    assert_vec2_near(box.lower, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    assert_vec2_near(box.upper, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    box = sx_compound_aabb(&empty, at((double)NAN, 4.0, 0.0));
    assert_vec2_near(box.lower, sx_v2_zero(), 0.0);
    assert_false(sx_compound_ray_cast(NULL, id, NULL, NULL, NULL));
    /* A non-finite placement answers false without NaN. */
    make_u(&f);
    assert_false(sx_compound_mtv(&f.c, at((double)INFINITY, 0.0, 0.0), &ball, id, &mtv));
    assert_true(sx_vec2_is_finite(mtv));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circle_in_u_notch_overlaps_only_when_touching_walls),
        cmocka_unit_test(box_over_comb_teeth_collides_with_each_tooth),
        cmocka_unit_test(u_mtv_avoids_pushing_into_the_other_wall),
        cmocka_unit_test(one_part_compound_mtv_matches_the_narrowphase),
        cmocka_unit_test(compound_mtv_separates_in_one_move_on_random_placements),
        cmocka_unit_test(compound_vs_compound_mtv_separates_in_one_move),
        cmocka_unit_test(compound_mtv_is_near_the_brute_force_minimum),
        cmocka_unit_test(ray_cast_reports_the_nearest_part),
        cmocka_unit_test(point_containment_reports_the_part),
        cmocka_unit_test(decomposed_spiral_compound_matches_its_outline),
        cmocka_unit_test(aabb_contains_every_part),
        cmocka_unit_test(l_from_two_boxes_has_the_mass_of_the_l),
        cmocka_unit_test(a_part_too_heavy_for_sx_real_gives_no_nan),
        cmocka_unit_test(compound_mtv_clears_a_point_on_a_far_box_corner),
        cmocka_unit_test(compound_mtv_of_a_point_just_inside_a_far_box_face_is_its_mtv),
        cmocka_unit_test(compound_mtv_far_beyond_huge_is_the_mtv_at_the_origin),
        cmocka_unit_test(part_rotation_off_unit_is_placed_unit),
        cmocka_unit_test(invalid_compounds_are_reported_and_answered_safely),
    };
    return cmocka_run_group_tests_name("compound", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
