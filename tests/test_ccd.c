/* sepax tests — shape casts against the world (closest hit, all hits,
 * filters, sensors, compounds, hostile input) and continuous collision in
 * the step: bullets of every shape at 50-1000 m/s against thin static walls
 * and segments from many offsets and angles (none passes, none ends inside,
 * none gains energy), a spinning blade, a bullet against a thin dynamic
 * box, two bullets against each other. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "test_support.h"

#define EPS SX_TEST_EPS

static bool sx_body_id_equal(sx_body_id a, sx_body_id b) {
    return sx_body_id_to_u64(a) == sx_body_id_to_u64(b);
}

static sx_world *make_world(sx_vec2 gravity) {
    sx_world_def d = sx_default_world_def();
    sx_world *w;
    d.gravity = gravity;
    w = sx_world_create(&d);
    assert_non_null(w);
    return w;
}

/* ---- world shape casts -------------------------------------------------- */

typedef struct hits {
    sx_world_shape_hit h[8];
    int count, stop_after;
} hits;

static bool collect(const sx_world_shape_hit *hit, void *context) {
    hits *c = (hits *)context;
    if (c->count < 8) c->h[c->count] = *hit;
    ++c->count;
    return c->stop_after == 0 || c->count < c->stop_after;
}

static void world_cast_finds_the_closest_and_all_hits(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id b[3];
    sx_world_shape_hit h;
    hits all;
    int i;
    (void)state;
    /* boxes at x = 9, 3, 6 (slot order is not distance order) */
    b[0] = sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(9.0), SX_R(0.0)),
                        sx_box_shape(SX_R(0.5), SX_R(1.0)), NULL);
    b[1] = sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(3.0), SX_R(0.0)),
                        sx_box_shape(SX_R(0.5), SX_R(1.0)), NULL);
    b[2] = sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(6.0), SX_R(0.0)),
                        sx_box_shape(SX_R(0.5), SX_R(1.0)), NULL);
    assert_true(
        sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(20.0), SX_R(0.0)), NULL, &h));
    assert_true(sx_body_id_equal(h.body, b[1]));
    assert_near(h.fraction, 2.0 / 20.0, EPS);
    assert_vec2_near(h.normal, sx_v2(SX_R(-1.0), SX_R(0.0)), EPS);
    assert_vec2_near(h.point, sx_v2(SX_R(2.5), SX_R(0.0)), EPS);
    memset(&all, 0, sizeof(all));
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2(SX_R(20.0), SX_R(0.0)), NULL, collect, &all),
                     3);
    assert_int_equal(all.count, 3);
    for (i = 0; i < 3; ++i) {
        double x = i == 0 ? 9.0 : (i == 1 ? 3.0 : 6.0);
        assert_true(sx_body_id_equal(all.h[i].body, b[i]));
        assert_near(all.h[i].fraction, (x - 1.0) / 20.0, EPS);
    }
    /* the callback stops the walk */
    memset(&all, 0, sizeof(all));
    all.stop_after = 1;
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2(SX_R(20.0), SX_R(0.0)), NULL, collect, &all),
                     1);
    /* too short: nothing */
    assert_false(
        sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(1.5), SX_R(0.0)), NULL, &h));
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2(SX_R(1.5), SX_R(0.0)), NULL, NULL, NULL),
                     0);
    sx_world_destroy(w);
}

static void world_cast_honours_filters_and_skips_sensors(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id near_body, sensor_body, far_body;
    sx_filter f;
    sx_world_shape_hit h;
    (void)state;
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(1.0));
    cd.filter.category = 2;
    bd.position = sx_v2(SX_R(3.0), SX_R(0.0));
    assert_int_equal(sx_create_body(w, &bd, &near_body), SX_OK);
    assert_int_equal(sx_body_add_collider(w, near_body, &cd, NULL), SX_OK);
    cd.filter.category = 1;
    cd.sensor = true;
    bd.position = sx_v2(SX_R(1.5), SX_R(0.0));
    assert_int_equal(sx_create_body(w, &bd, &sensor_body), SX_OK);
    assert_int_equal(sx_body_add_collider(w, sensor_body, &cd, NULL), SX_OK);
    cd.sensor = false;
    bd.position = sx_v2(SX_R(6.0), SX_R(0.0));
    assert_int_equal(sx_create_body(w, &bd, &far_body), SX_OK);
    assert_int_equal(sx_body_add_collider(w, far_body, &cd, NULL), SX_OK);
    /* no filter: the nearest solid collider, past the sensor */
    assert_true(
        sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)), NULL, &h));
    assert_true(sx_body_id_equal(h.body, near_body));
    /* a mask without category 2 passes through it */
    f.category = 1;
    f.mask = 1;
    f.group = 0;
    assert_true(
        sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)), &f, &h));
    assert_true(sx_body_id_equal(h.body, far_body));
    assert_near(h.fraction, 5.0 / 10.0, EPS);
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2(SX_R(10.0), SX_R(0.0)), &f, NULL, NULL),
                     1);
    /* a group the colliders are not in changes nothing */
    f.mask = 0xFFFFFFFFu;
    f.group = -3;
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2(SX_R(10.0), SX_R(0.0)), &f, NULL, NULL),
                     2);
    sx_world_destroy(w);
}

static void world_cast_hostile_input_answers_no_hit(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_shape bad = sx_circle_shape(sx_v2_zero(), SX_R(-0.5));
    sx_world_shape_hit h;
    sx_vec2 t = sx_v2(SX_R(10.0), SX_R(0.0));
    (void)state;
    sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(3.0), SX_R(0.0)), sx_box_shape(SX_R(0.5), SX_R(1.0)),
                 NULL);
    assert_false(sx_world_cast_shape(NULL, &ball, sx_xform_identity(), t, NULL, &h));
    assert_false(sx_world_cast_shape(w, NULL, sx_xform_identity(), t, NULL, &h));
    assert_false(sx_world_cast_shape(w, &ball, sx_xform_identity(), t, NULL, NULL));
    assert_false(sx_world_cast_shape(w, &bad, sx_xform_identity(), t, NULL, &h));
    assert_false(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2((sx_real)NAN, SX_R(0.0)),
                                     NULL, &h));
    assert_near(h.fraction, 0.0, 0.0);
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2((sx_real)INFINITY, SX_R(0.0)), NULL, NULL, NULL),
                     0);
    /* zero translation: only what it already touches */
    assert_false(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2_zero(), NULL, &h));
    assert_true(sx_world_cast_shape(w, &ball, sx_xform_make(sx_v2(SX_R(2.2), SX_R(0.0)), SX_R(0.0)),
                                    sx_v2_zero(), NULL, &h));
    assert_near(h.fraction, 0.0, 0.0);
    sx_world_destroy(w);
}

/* ---- continuous collision in the step ------------------------------------ */

static sx_body_id add(sx_world *w, sx_body_type type, sx_vec2 p, double angle, sx_shape shape,
                      sx_vec2 v, double spin, bool bullet) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    bd.type = type;
    bd.position = p;
    bd.angle = (sx_real)angle;
    bd.linear_velocity = v;
    bd.angular_velocity = (sx_real)spin;
    bd.bullet = bullet;
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    cd.shape = shape;
    cd.friction = SX_R(0.0);
    assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    return id;
}

static double kinetic(const sx_world *w, sx_body_id b) {
    sx_vec2 v = sx_body_get_linear_velocity(w, b);
    double m = (double)sx_body_get_mass(w, b), i = (double)sx_body_get_inertia(w, b);
    double om = (double)sx_body_get_angular_velocity(w, b);
    return 0.5 * m * (double)sx_dot(v, v) + 0.5 * i * om * om;
}

/* The shape of body b's only collider placed where b is. */
static sx_xform xf_of(const sx_world *w, sx_body_id b) { return sx_body_get_transform(w, b); }

/* Depth of overlap of two shapes (0 when apart or touching). */
static double overlap_depth(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    sx_vec2 mtv;
    if (!sx_mtv(a, xa, b, xb, &mtv)) return 0.0;
    return (double)sx_length(mtv);
}

/* Circles, boxes and capsules at 50, 200 and 1000 m/s, straight or turning,
 * at angles of -0.6, 0 and 0.5 rad, from four start offsets across a
 * sub-step's travel, against a static box wall 0.05 or 0.2 m thick and a
 * static segment: each ends on the near side, no deeper in the wall than a
 * resting contact (two slops), with no more kinetic energy than it had. */
static void fast_bodies_never_pass_thin_static_walls(void **state) {
    static const double speeds[3] = {50.0, 200.0, 1000.0};
    static const double angles[3] = {-0.6, 0.0, 0.5};
    static const double thick[2] = {0.05, 0.2};
    /* each shape's thinnest width */
    static const double thin[3] = {0.1, 0.1, 0.06};
    sx_shape shapes[3];
    int si, vi, ai, wi, ki, spin, seg, runs = 0;
    (void)state;
    shapes[0] = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
    shapes[1] = sx_box_shape(SX_R(0.05), SX_R(0.05));
    shapes[2] =
        sx_capsule_shape(sx_v2(SX_R(-0.05), SX_R(0.0)), sx_v2(SX_R(0.05), SX_R(0.0)), SX_R(0.03));
    for (si = 0; si < 3; ++si)
        for (vi = 0; vi < 3; ++vi)
            for (ai = 0; ai < 3; ++ai)
                for (wi = 0; wi < 2; ++wi)
                    for (seg = 0; seg < 2; ++seg)
                        for (spin = 0; spin < 2; ++spin)
                            for (ki = 0; ki < 4; ++ki) {
                                sx_world *w = make_world(sx_v2_zero());
                                double travel = speeds[vi] / 240.0, e0, e1, depth = 0.0;
                                double half = 0.5 * thick[wi];
                                sx_vec2 dir =
                                    sx_v2((sx_real)cos(angles[ai]), (sx_real)sin(angles[ai]));
                                sx_shape wall =
                                    seg ? sx_segment_shape(sx_v2(SX_R(0.0), SX_R(-30.0)),
                                                           sx_v2(SX_R(0.0), SX_R(30.0)))
                                        : sx_box_shape((sx_real)half, SX_R(30.0));
                                sx_vec2 start = sx_scale(dir, (sx_real)(-1.0 - 0.25 * ki * travel));
                                sx_body_id wb, b;
                                sx_vec2 p;
                                int k;
                                if (seg) half = 0.0;
                                wb = add(w, SX_BODY_STATIC, sx_v2_zero(), 0.0, wall, sx_v2_zero(),
                                         0.0, false);
                                b = add(w, SX_BODY_DYNAMIC, start, 0.3 * ki, shapes[si],
                                        sx_scale(dir, (sx_real)speeds[vi]),
                                        spin ? 40.0 + 10.0 * ki : 0.0, false);
                                e0 = kinetic(w, b);
                                for (k = 0; k < 20; ++k) {
                                    assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)),
                                                     SX_OK);
                                    p = sx_body_get_position(w, b);
                                    /* never on the far side */
                                    depth = overlap_depth(&shapes[si], xf_of(w, b), &wall,
                                                          xf_of(w, wb));
                                    /* never past the near face, never
                                     * embedded (a swinging end may dip in
                                     * for a step until its contact is
                                     * found: less than the body's width) */
                                    assert_true((double)p.x < -half);
                                    assert_true(depth < thin[si]);
                                    e1 = kinetic(w, b);
                                    assert_true(e1 <= e0 * (1.0 + 1e-4) + 1e-9);
                                }
                                /* at rest against the wall at the end */
                                assert_true(depth < 2.0 * (double)SX_LINEAR_SLOP);
                                ++runs;
                                sx_world_destroy(w);
                            }
    assert_int_equal(runs, 3 * 3 * 3 * 2 * 2 * 2 * 4);
}

/* The ball's side of the blade: its distance from the blade's axis (signed,
 * positive on the side it starts), or 1 once it is beyond the blade's tips
 * or far from it (the blade may slide off it and fly away). */
static double blade_to_ball(const sx_world *w, sx_body_id blade, sx_vec2 ball) {
    sx_xform x = sx_body_get_transform(w, blade);
    sx_vec2 d = sx_inv_rotate(x.q, sx_sub(ball, x.p));
    if (fabs((double)d.x) > 1.05 || fabs((double)d.y) > 0.5) return 1.0;
    return (double)d.x < 0.0 ? -(double)d.y : (double)d.y;
}

/* A thin blade (2 m x 4 cm) spinning at 60 rad/s (a radian a step) next to
 * a 5 cm ball 0.6 m from its centre: the blade meets the ball (it may then
 * swing about it or slide off its tip) rather than passing through it,
 * static or dynamic (then the blade is a bullet), and gains no energy. */
static void spinning_blade_never_passes_through_a_ball(void **state) {
    int dyn;
    (void)state;
    for (dyn = 0; dyn < 2; ++dyn) {
        sx_world *w = make_world(sx_v2_zero());
        sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
        sx_body_id blade, bb;
        double e0, e1;
        int k;
        bb = add(w, dyn ? SX_BODY_DYNAMIC : SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(0.6)), 0.0, ball,
                 sx_v2_zero(), 0.0, false);
        blade = add(w, SX_BODY_DYNAMIC, sx_v2_zero(), -0.2, sx_box_shape(SX_R(1.0), SX_R(0.02)),
                    sx_v2_zero(), 60.0, dyn != 0);
        e0 = kinetic(w, blade);
        for (k = 0; k < 60; ++k) {
            sx_vec2 bp;
            assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
            bp = sx_body_get_position(w, bb);
            /* it meets the ball (the ball's radius plus the blade's half
             * thickness, less two slops) and never gets across it; pressed
             * on while turning fast, its contact lets it sink by up to a
             * quarter slop a step (world.h, sx_world_continuous) */
            if (k < 2) {
                assert_true(blade_to_ball(w, blade, bp) > 0.07 - 2.0 * (double)SX_LINEAR_SLOP);
            }
            assert_true(blade_to_ball(w, blade, bp) > 0.0);
            e1 = kinetic(w, blade) + (dyn ? kinetic(w, bb) : 0.0);
            assert_true(e1 <= e0 * (1.0 + 1e-4));
        }
        sx_world_destroy(w);
    }
}

/* A 2 cm bullet at 500 m/s at the middle of a free 5 cm x 1 m dynamic box,
 * from four offsets: it never gets past the box's back face, and the two
 * gain no energy. (Hit off centre, the box spins away and may turn over the
 * bullet: only a bullet is swept against dynamic bodies, not the box.) */
static void bullet_never_passes_a_thin_dynamic_box(void **state) {
    int ki;
    (void)state;
    for (ki = 0; ki < 4; ++ki) {
        sx_world *w = make_world(sx_v2_zero());
        sx_body_id box, b;
        double e0, e1;
        int k;
        box = add(w, SX_BODY_DYNAMIC, sx_v2_zero(), 0.0, sx_box_shape(SX_R(0.025), SX_R(0.5)),
                  sx_v2_zero(), 0.0, false);
        b = add(w, SX_BODY_DYNAMIC, sx_v2((sx_real)(-1.0 - 0.4 * ki), SX_R(0.0)), 0.0,
                sx_circle_shape(sx_v2_zero(), SX_R(0.02)), sx_v2(SX_R(500.0), SX_R(0.0)), 0.0,
                true);
        e0 = kinetic(w, b);
        for (k = 0; k < 20; ++k) {
            assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
            /* the box may turn a little: measured in its frame */
            {
                sx_vec2 d =
                    sx_xform_inv_point(sx_body_get_transform(w, box), sx_body_get_position(w, b));
                assert_true((double)d.x < -0.025 + 2.0 * (double)SX_LINEAR_SLOP ||
                            fabs((double)d.y) > 0.5);
            }
            e1 = kinetic(w, b) + kinetic(w, box);
            assert_true(e1 <= e0 * (1.0 + 1e-4));
        }
        sx_world_destroy(w);
    }
}

/* Two 5 cm bullets at 500 m/s each, head on (then 3 cm off centre): they
 * meet instead of passing through each other, never end a step inside
 * each other, and gain no energy. Head on they stop at each other; off
 * centre they meet where they touch and (frictionless) glance off along
 * the tangent there, keeping its share of their speed, 500 x 0.03 / 0.1 of
 * it: far below 500 m/s along the line of flight. */
static void two_bullets_meet_instead_of_passing(void **state) {
    int ki;
    (void)state;
    for (ki = 0; ki < 4; ++ki) {
        sx_world *w = make_world(sx_v2_zero());
        sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
        sx_body_id a, b;
        double e0, e1;
        int k;
        a = add(w, SX_BODY_DYNAMIC, sx_v2((sx_real)(-5.0 - 0.3 * ki), SX_R(0.0)), 0.0, ball,
                sx_v2(SX_R(500.0), SX_R(0.0)), 0.0, true);
        b = add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(5.0), ki == 0 ? SX_R(0.0) : SX_R(0.03)), 0.0, ball,
                sx_v2(SX_R(-500.0), SX_R(0.0)), 0.0, true);
        e0 = kinetic(w, a) + kinetic(w, b);
        for (k = 0; k < 20; ++k) {
            double gap;
            assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
            gap = (double)sx_distance(sx_body_get_position(w, a), sx_body_get_position(w, b)) - 0.1;
            assert_true(gap > -2.0 * (double)SX_LINEAR_SLOP);
            if (ki == 0) assert_true(sx_body_get_position(w, a).x < sx_body_get_position(w, b).x);
            e1 = kinetic(w, a) + kinetic(w, b);
            assert_true(e1 <= e0 * (1.0 + 1e-4));
        }
        /* they met: what passing through would keep, they lost */
        assert_true(fabs((double)sx_body_get_linear_velocity(w, a).x) < 100.0);
        assert_true(fabs((double)sx_body_get_linear_velocity(w, b).x) < 100.0);
        sx_world_destroy(w);
    }
}

/* A volley of spinning bullets (circles, boxes, capsules at 200-1000 m/s,
 * aimed across each other) through a row of thin dynamic boxes at a thin
 * static wall (40 m tall): crossing bullets meet each other at hundreds of
 * m/s, and none may be knocked through the wall. (Levers slid through a
 * sub-step across such a crossing once spun bullets fast enough to pass
 * it.) A bullet deflected far enough to fly around an end of the wall
 * passes its line beyond the end: each step's move across the line is
 * checked, where it crosses. */
static void crossing_spinning_bullets_never_pass_a_thin_wall(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_test_rng rng = sx_test_rng_make(23);
    sx_body_id shots[150];
    sx_vec2 before[150];
    int i, k, passed = 0, around = 0;
    (void)state;
    add(w, SX_BODY_STATIC, sx_v2(SX_R(4.0), SX_R(0.0)), 0.0, sx_box_shape(SX_R(0.05), SX_R(20.0)),
        sx_v2_zero(), 0.0, false);
    for (k = 0; k < 32; ++k) {
        add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), (sx_real)(-4.0 + 0.25 * k + 0.125)), 0.0,
            sx_box_shape(SX_R(0.025), SX_R(0.125)), sx_v2_zero(), 0.0, false);
    }
    for (i = 0; i < 150; ++i) {
        double speed = 200.0 + 800.0 * sx_test_rng_unit(&rng);
        double aim = -0.2 + 0.4 * sx_test_rng_unit(&rng);
        double x = -24.0 + 8.0 * sx_test_rng_unit(&rng), y = -4.0 + 8.0 * sx_test_rng_unit(&rng);
        double angle = -3.0 + 6.0 * sx_test_rng_unit(&rng), spin = -30.0 + 60.0 * sx_test_rng_unit(&rng);
        sx_shape shape = i % 3 == 0   ? sx_circle_shape(sx_v2_zero(), SX_R(0.05))
                         : i % 3 == 1 ? sx_box_shape(SX_R(0.05), SX_R(0.05))
                                      : sx_capsule_shape(sx_v2(SX_R(-0.05), SX_R(0.0)),
                                                         sx_v2(SX_R(0.05), SX_R(0.0)), SX_R(0.03));
        shots[i] = add(w, SX_BODY_DYNAMIC, sx_v2((sx_real)x, (sx_real)(y + x * tan(aim))), angle,
                       shape, sx_v2((sx_real)(speed * cos(aim)), (sx_real)(speed * sin(aim))),
                       spin, true);
    }
    for (k = 0; k < 60; ++k) {
        for (i = 0; i < 150; ++i)
            before[i] = sx_body_get_position(w, shots[i]);
        assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
        for (i = 0; i < 150; ++i) {
            sx_vec2 p = sx_body_get_position(w, shots[i]);
            double t, y;
            if (!((double)before[i].x < 4.05 && !((double)p.x < 4.05))) continue;
            /* where the step's straight move crossed the far face's line:
             * beyond the end (20 m, less a bullet's size) is around it */
            t = (4.05 - (double)before[i].x) / ((double)p.x - (double)before[i].x);
            y = (double)before[i].y + t * ((double)p.y - (double)before[i].y);
            if (fabs(y) > 19.9) {
                ++around;
            } else {
                ++passed;
            }
        }
    }
    printf("  crossing bullets: %d of 150 through the wall, %d around its ends\n", passed, around);
    assert_int_equal(passed, 0);
    sx_world_destroy(w);
}

/* A ball at rest 1 m before a thin wall is knocked on at 150-300 m/s by a
 * fast ball in the same step: its contacts of that step did not look
 * ahead (it was at rest), so only the sweep stops it. Against a static
 * wall it is swept by default; against a thin dynamic box only as a
 * bullet. Neither ball ends past the wall, and no energy is gained. */
static void knocked_body_stops_at_a_thin_wall(void **state) {
    int ki, dyn;
    (void)state;
    for (dyn = 0; dyn < 2; ++dyn) {
        for (ki = 0; ki < 6; ++ki) {
            sx_world *w = make_world(sx_v2_zero());
            sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
            sx_body_id a, b, wall;
            double e0, e1;
            int k;
            wall = add(w, dyn ? SX_BODY_DYNAMIC : SX_BODY_STATIC, sx_v2_zero(), 0.0,
                       sx_box_shape(SX_R(0.025), SX_R(1.0)), sx_v2_zero(), 0.0, false);
            b = add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-1.0), SX_R(0.0)), 0.0, ball, sx_v2_zero(), 0.0,
                    dyn != 0);
            a = add(w, SX_BODY_DYNAMIC, sx_v2((sx_real)(-1.2 - 0.2 * ki), SX_R(0.0)), 0.0, ball,
                    sx_v2(SX_R(300.0), SX_R(0.0)), 0.0, dyn != 0);
            e0 = kinetic(w, a);
            for (k = 0; k < 10; ++k) {
                sx_vec2 wp;
                assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
                wp = sx_xform_inv_point(xf_of(w, wall), sx_body_get_position(w, b));
                assert_true((double)wp.x < -0.025 - 0.05 + 2.0 * (double)SX_LINEAR_SLOP);
                wp = sx_xform_inv_point(xf_of(w, wall), sx_body_get_position(w, a));
                assert_true((double)wp.x < -0.025 - 0.05 + 2.0 * (double)SX_LINEAR_SLOP);
                e1 = kinetic(w, a) + kinetic(w, b) + (dyn ? kinetic(w, wall) : 0.0);
                assert_true(e1 <= e0 * (1.0 + 1e-4));
            }
            sx_world_destroy(w);
        }
    }
}

/* The size gate: a 0.5 m ball at rest, 2.5 cm before a thin static wall
 * (beyond the margin: its contacts of the step do not see the wall), is
 * knocked on by a ball at 6 m/s. It moves a few cm in that step, far more
 * than its collide-time velocity foresaw, but less than its gate (an
 * eighth of its width), so it is not swept: with continuous collision on
 * or off both balls follow the same path bit for bit, and the contact
 * pushes the struck ball back out on its own side. */
static void slow_knocked_body_is_not_swept(void **state) {
    sx_world *w[2];
    sx_body_id a[2], b[2];
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    double most = 0.0;
    int on, k;
    (void)state;
    for (on = 0; on < 2; ++on) {
        w[on] = make_world(sx_v2_zero());
        assert_int_equal(sx_world_enable_continuous(w[on], on != 0), SX_OK);
        (void)add(w[on], SX_BODY_STATIC, sx_v2_zero(), 0.0, sx_box_shape(SX_R(0.025), SX_R(2.0)),
                  sx_v2_zero(), 0.0, false);
        b[on] = add(w[on], SX_BODY_DYNAMIC, sx_v2(SX_R(-0.55), SX_R(0.0)), 0.0, ball, sx_v2_zero(),
                    0.0, false);
        a[on] = add(w[on], SX_BODY_DYNAMIC, sx_v2(SX_R(-1.6), SX_R(0.0)), 0.0, ball,
                    sx_v2(SX_R(6.0), SX_R(0.0)), 0.0, false);
    }
    for (k = 0; k < 30; ++k) {
        sx_vec2 before = sx_body_get_position(w[1], b[1]);
        for (on = 0; on < 2; ++on)
            assert_int_equal(sx_world_step(w[on], SX_R(1.0) / SX_R(60.0)), SX_OK);
        most = fmax(most, (double)sx_distance(before, sx_body_get_position(w[1], b[1])));
        for (on = 0; on < 2; ++on) {
            sx_body_id id = on ? a[1] : b[1], off = on ? a[0] : b[0];
            sx_vec2 p1 = sx_body_get_position(w[1], id), p0 = sx_body_get_position(w[0], off);
            assert_true(p1.x == p0.x && p1.y == p0.y);
            assert_true(sx_body_get_angle(w[1], id) == sx_body_get_angle(w[0], off));
        }
        /* never past the wall's middle */
        assert_true((double)sx_body_get_position(w[1], b[1]).x < -0.5);
    }
    /* the knock moved it more than the stage lists (half the margin) but
     * under its gate (0.125 m) */
    assert_true(most > 0.02 && most < 0.125);
    /* and the contact pushed it back out */
    assert_true((double)sx_body_get_position(w[1], b[1]).x < -0.525 + 2.0 * (double)SX_LINEAR_SLOP);
    for (on = 0; on < 2; ++on)
        sx_world_destroy(w[on]);
}

/* Just above the gate: boxes and capsules spinning a little (so the stage
 * lists them) while moving at 1.05-1.6 times their gate per step at a
 * zero-thickness static segment, from many start gaps: none passes it,
 * none ends more than two slops into it, none gains energy. */
static void body_just_above_the_gate_never_passes_a_thin_wall(void **state) {
    int shape_k, ki, si;
    (void)state;
    for (shape_k = 0; shape_k < 2; ++shape_k) {
        for (si = 0; si < 4; ++si) {
            for (ki = 0; ki < 8; ++ki) {
                sx_world *w = make_world(sx_v2_zero());
                /* half its thinnest extent 0.1 m either way: its gate 2.5 cm */
                sx_shape shape = shape_k == 0 ? sx_box_shape(SX_R(0.3), SX_R(0.1))
                                              : sx_capsule_shape(sx_v2(SX_R(-0.2), SX_R(0.0)),
                                                                 sx_v2(SX_R(0.2), SX_R(0.0)),
                                                                 SX_R(0.1));
                double speed = 60.0 * 0.025 * (1.05 + 0.18 * si), e0, e1;
                sx_body_id body;
                int k;
                (void)add(w, SX_BODY_STATIC, sx_v2_zero(), 0.0,
                          sx_segment_shape(sx_v2(SX_R(-3.0), SX_R(0.0)), sx_v2(SX_R(3.0), SX_R(0.0))),
                          sx_v2_zero(), 0.0, false);
                body = add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), (sx_real)(0.13 + 0.0071 * ki)), 0.0,
                           shape, sx_v2(SX_R(0.0), (sx_real)-speed), 0.8, false);
                e0 = kinetic(w, body);
                for (k = 0; k < 20; ++k) {
                    sx_xform xf;
                    double low;
                    assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
                    xf = sx_body_get_transform(w, body);
                    /* the lowest point of its core, less its rounding */
                    {
                        double hx = shape_k == 0 ? 0.3 : 0.2, hy = shape_k == 0 ? 0.1 : 0.0;
                        double r = shape_k == 0 ? 0.0 : 0.1;
                        low = (double)xf.p.y - fabs((double)xf.q.s) * hx -
                              fabs((double)xf.q.c) * hy - r;
                    }
                    assert_true((double)xf.p.y > 0.0);
                    assert_true(low > -2.0 * (double)SX_LINEAR_SLOP);
                    e1 = kinetic(w, body);
                    assert_true(e1 <= e0 * (1.0 + 1e-4));
                }
                sx_world_destroy(w);
            }
        }
    }
}

/* enable_continuous (default true) turns the whole stage off and on: a
 * ball at rest 1 m before a thin static wall, knocked on at 300 m/s by a
 * fast ball in the same step, passes the wall with it off (its contacts of
 * that step did not look ahead) and stops at the wall with it on. */
static void continuous_collision_turns_off_and_on(void **state) {
    int on;
    sx_world_def got;
    (void)state;
    assert_true(sx_default_world_def().enable_continuous);
    assert_int_equal(sx_world_enable_continuous(NULL, true), SX_ERR_INVALID_ARG);
    for (on = 0; on < 2; ++on) {
        sx_world *w = make_world(sx_v2_zero());
        sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
        sx_body_id b;
        int k;
        assert_int_equal(sx_world_enable_continuous(w, on != 0), SX_OK);
        assert_int_equal(sx_world_get_def(w, &got), SX_OK);
        assert_int_equal(got.enable_continuous, on != 0);
        (void)add(w, SX_BODY_STATIC, sx_v2_zero(), 0.0, sx_box_shape(SX_R(0.025), SX_R(1.0)),
                  sx_v2_zero(), 0.0, false);
        b = add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-1.0), SX_R(0.0)), 0.0, ball, sx_v2_zero(), 0.0,
                false);
        (void)add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-1.2), SX_R(0.0)), 0.0, ball,
                  sx_v2(SX_R(300.0), SX_R(0.0)), 0.0, false);
        for (k = 0; k < 10; ++k)
            assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
        if (on) {
            assert_true((double)sx_body_get_position(w, b).x <
                        -0.075 + 2.0 * (double)SX_LINEAR_SLOP);
        } else {
            assert_true((double)sx_body_get_position(w, b).x > 0.025);
        }
        sx_world_destroy(w);
    }
}

/* A collide of an empty world, then a body created and the rest of the
 * step's stages run by hand: the body had no pose at collide, so it is not
 * swept, and nothing writes a pose it has no room for (the bounds the
 * next stage finds for it once wrote one through a null pointer). */
static void a_body_created_between_collide_and_the_sub_steps_is_not_recorded(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_real h = SX_R(1.0) / SX_R(60.0);
    sx_body_id b;
    (void)state;
    assert_int_equal(sx_world_begin_step(w, h), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    b = add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(4.5), SX_R(4.5)), 0.0,
            sx_box_shape(SX_R(0.5), SX_R(0.5)), sx_v2(SX_R(300.0), SX_R(0.0)), 0.0, false);
    assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
    assert_int_equal(sx_world_solve(w, h), SX_OK);
    assert_int_equal(sx_world_integrate(w, h), SX_OK);
    assert_int_equal(sx_world_separate(w, h), SX_OK);
    assert_int_equal(sx_world_continuous(w), SX_OK);
    /* it moved a whole step unswept: 300 m/s x 1/60 s */
    assert_near(sx_body_get_position(w, b).x, 4.5 + 5.0, 1e-3);
    assert_int_equal(sx_world_step(w, h), SX_OK);
    sx_world_destroy(w);
}

/* A 1 m rod 4 cm thick spinning at 100-200 rad/s while it flies at 30 m/s
 * at a static wall 5 cm thick: its ends sweep far more than its thickness
 * each step, yet it never ends across the wall. */
static void spinning_rod_never_crosses_a_thin_wall(void **state) {
    int ki;
    (void)state;
    for (ki = 0; ki < 8; ++ki) {
        sx_world *w = make_world(sx_v2_zero());
        sx_shape rod = sx_box_shape(SX_R(0.5), SX_R(0.02));
        sx_body_id b;
        double e0, e1;
        int k;
        (void)add(w, SX_BODY_STATIC, sx_v2_zero(), 0.0, sx_box_shape(SX_R(0.025), SX_R(30.0)),
                  sx_v2_zero(), 0.0, false);
        b = add(w, SX_BODY_DYNAMIC, sx_v2((sx_real)(-1.0 - 0.07 * ki), SX_R(0.0)), 0.4 * ki, rod,
                sx_v2(SX_R(30.0), SX_R(0.0)), 100.0 + 15.0 * ki, false);
        e0 = kinetic(w, b);
        for (k = 0; k < 20; ++k) {
            sx_xform x;
            int c;
            assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
            x = xf_of(w, b);
            /* both ends on the near side */
            for (c = -1; c <= 1; c += 2) {
                sx_vec2 end = sx_xform_point(x, sx_v2((sx_real)(0.5 * c), SX_R(0.0)));
                assert_true((double)end.x < -0.025 + 2.0 * (double)SX_LINEAR_SLOP);
            }
            e1 = kinetic(w, b);
            assert_true(e1 <= e0 * (1.0 + 1e-4));
        }
        sx_world_destroy(w);
    }
}

static void bullet_flag_round_trips_and_answers_stale_handles(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_body_id b = add(w, SX_BODY_DYNAMIC, sx_v2_zero(), 0.0,
                       sx_circle_shape(sx_v2_zero(), SX_R(0.1)), sx_v2_zero(), 0.0, false);
    (void)state;
    assert_false(sx_default_body_def().bullet);
    assert_false(sx_body_is_bullet(w, b));
    assert_int_equal(sx_body_set_bullet(w, b, true), SX_OK);
    assert_true(sx_body_is_bullet(w, b));
    assert_int_equal(sx_body_set_bullet(NULL, b, true), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_continuous(NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_continuous(w), SX_OK);
    assert_int_equal(sx_destroy_body(w, b), SX_OK);
    assert_int_equal(sx_body_set_bullet(w, b, true), SX_ERR_STALE_HANDLE);
    assert_false(sx_body_is_bullet(w, b));
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_cast_finds_the_closest_and_all_hits),
        cmocka_unit_test(world_cast_honours_filters_and_skips_sensors),
        cmocka_unit_test(world_cast_hostile_input_answers_no_hit),
        cmocka_unit_test(fast_bodies_never_pass_thin_static_walls),
        cmocka_unit_test(spinning_blade_never_passes_through_a_ball),
        cmocka_unit_test(bullet_never_passes_a_thin_dynamic_box),
        cmocka_unit_test(two_bullets_meet_instead_of_passing),
        cmocka_unit_test(crossing_spinning_bullets_never_pass_a_thin_wall),
        cmocka_unit_test(knocked_body_stops_at_a_thin_wall),
        cmocka_unit_test(spinning_rod_never_crosses_a_thin_wall),
        cmocka_unit_test(slow_knocked_body_is_not_swept),
        cmocka_unit_test(body_just_above_the_gate_never_passes_a_thin_wall),
        cmocka_unit_test(continuous_collision_turns_off_and_on),
        cmocka_unit_test(a_body_created_between_collide_and_the_sub_steps_is_not_recorded),
        cmocka_unit_test(bullet_flag_round_trips_and_answers_stale_handles),
    };
    return cmocka_run_group_tests_name("ccd", tests, sx_test_group_setup, sx_test_group_teardown);
}
