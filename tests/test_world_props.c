/* sepax tests — what a game changes while the world runs: world def
 * validation with the refused field named, solver settings, a body's
 * enabled flag, gravity scale, damping and fixed rotation, a collider's
 * material and filter, iteration of bodies and colliders, bounds, the
 * sx_<object>_create/destroy names, and the answers to bad input (NULL,
 * NaN, Inf, negative values, stale handles). */
#include <math.h>
#include <string.h>

#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))
/* the default world's sub-step at DT */
#define SUB_H ((double)DT / (double)sx_default_world_def().sub_steps)

static sx_world *make_world(sx_vec2 gravity) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    def.gravity = gravity;
    w = sx_world_create(&def);
    assert_non_null(w);
    return w;
}

static sx_body_id make_body(sx_world *w, sx_body_type type, sx_vec2 p, const sx_shape *shape,
                            sx_collider_id *collider) {
    sx_body_def bd = sx_default_body_def();
    sx_body_id id;
    bd.type = type;
    bd.position = p;
    assert_int_equal(sx_body_create(w, &bd, &id), SX_OK);
    if (shape != NULL) {
        sx_collider_def cd = sx_default_collider_def();
        cd.shape = *shape;
        assert_int_equal(sx_collider_create(w, id, &cd, collider), SX_OK);
    }
    return id;
}

static void steps(sx_world *w, int n) {
    int i;
    for (i = 0; i < n; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
}

static sx_real nan_value(void) { return (sx_real)NAN; }
static sx_real inf_value(void) { return (sx_real)INFINITY; }

/* ---- world def validation ------------------------------------------------------ */

static void world_def_validate_names_the_first_refused_field(void **state) {
    sx_world_def d = sx_default_world_def();
    const char *field = "unset";
    (void)state;
    assert_int_equal(sx_world_def_validate(&d, &field), SX_OK);
    assert_null(field);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_OK);
    assert_int_equal(sx_world_def_validate(NULL, &field), SX_ERR_INVALID_ARG);
    assert_string_equal(field, "def");

#define REFUSED(assignment, status, name)                                                          \
    do {                                                                                           \
        d = sx_default_world_def();                                                                \
        assignment;                                                                                \
        field = NULL;                                                                              \
        assert_int_equal(sx_world_def_validate(&d, &field), status);                               \
        assert_non_null(field);                                                                    \
        assert_string_equal(field, name);                                                          \
        assert_null(sx_world_create(&d));                                                          \
    } while (0)
    REFUSED(d.gravity.y = nan_value(), SX_ERR_NONFINITE, "gravity");
    REFUSED(d.gravity.x = inf_value(), SX_ERR_NONFINITE, "gravity");
    REFUSED(d.sub_steps = 0, SX_ERR_INVALID_ARG, "sub_steps");
    REFUSED(d.velocity_iterations = 0, SX_ERR_INVALID_ARG, "velocity_iterations");
    REFUSED(d.position_iterations = -1, SX_ERR_INVALID_ARG, "position_iterations");
    REFUSED(d.correction_factor = SX_R(1.5), SX_ERR_INVALID_ARG, "correction_factor");
    REFUSED(d.correction_factor = nan_value(), SX_ERR_NONFINITE, "correction_factor");
    REFUSED(d.max_correction_speed = SX_R(0.0), SX_ERR_INVALID_ARG, "max_correction_speed");
    REFUSED(d.restitution_threshold = SX_R(-1.0), SX_ERR_INVALID_ARG, "restitution_threshold");
    REFUSED(d.speculative_slops = -inf_value(), SX_ERR_NONFINITE, "speculative_slops");
    REFUSED(d.length_units_per_meter = SX_R(0.0), SX_ERR_INVALID_ARG, "length_units_per_meter");
    REFUSED(d.body_capacity = -1, SX_ERR_INVALID_ARG, "body_capacity");
    REFUSED(d.sleep_linear_speed = SX_R(-0.5), SX_ERR_INVALID_ARG, "sleep_linear_speed");
    REFUSED(d.sleep_angular_speed = inf_value(), SX_ERR_NONFINITE, "sleep_angular_speed");
    REFUSED(d.time_to_sleep = SX_R(0.0), SX_ERR_INVALID_ARG, "time_to_sleep");
#undef REFUSED
    /* the first refused field in declaration order, non-finite first */
    d = sx_default_world_def();
    d.sub_steps = 0;
    d.time_to_sleep = nan_value();
    assert_int_equal(sx_world_def_validate(&d, &field), SX_ERR_NONFINITE);
    assert_string_equal(field, "time_to_sleep");
}

static void world_solver_settings_change_at_run_time_as_at_creation(void **state) {
    sx_world_def d8 = sx_default_world_def(), got;
    sx_world *a = make_world(sx_v2(SX_R(0.0), SX_R(-10.0))), *b;
    sx_shape ground = sx_box_shape(SX_R(10.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id ba, bb;
    (void)state;
    d8.sub_steps = 8;
    d8.velocity_iterations = 6;
    d8.position_iterations = 3;
    b = sx_world_create(&d8);
    assert_non_null(b);
    make_body(a, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground, NULL);
    make_body(b, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground, NULL);
    ba = make_body(a, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(2.0)), &box, NULL);
    bb = make_body(b, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(2.0)), &box, NULL);
    assert_int_equal(sx_world_set_sub_steps(a, 8), SX_OK);
    assert_int_equal(sx_world_set_iterations(a, 6, 3), SX_OK);
    assert_int_equal(sx_world_get_def(a, &got), SX_OK);
    assert_int_equal(got.sub_steps, 8);
    assert_int_equal(got.velocity_iterations, 6);
    assert_int_equal(got.position_iterations, 3);
    steps(a, 90);
    steps(b, 90);
    /* bit for bit the world created with those settings */
    assert_vec2_near(sx_body_get_position(a, ba), sx_body_get_position(b, bb), 0.0);
    assert_near(sx_body_get_angle(a, ba), sx_body_get_angle(b, bb), 0.0);
    assert_vec2_near(sx_body_get_linear_velocity(a, ba), sx_body_get_linear_velocity(b, bb), 0.0);
    /* refused values leave the settings as they were */
    assert_int_equal(sx_world_set_sub_steps(a, 0), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_set_iterations(a, 0, 2), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_set_iterations(a, 4, -1), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_set_sub_steps(NULL, 4), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_set_iterations(NULL, 4, 2), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_get_def(NULL, &got), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_get_def(a, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_get_def(a, &got), SX_OK);
    assert_int_equal(got.sub_steps, 8);
    assert_int_equal(got.velocity_iterations, 6);
    assert_int_equal(got.position_iterations, 3);
    sx_world_destroy(a);
    sx_world_destroy(b);
}

/* ---- bodies --------------------------------------------------------------------- */

/* sx_body_get_state: the four getters' answers in one call, for a body in
 * flight, a sleeping one and a static one; a stale handle, a NULL world and
 * a NULL out get a status (and the stale handle the getters' zeros). */
static void a_body_state_is_the_getters_answers_in_one_call(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5)), ground = sx_box_shape(SX_R(5.0), SX_R(0.5));
    sx_body_id floor_id, spinner, resting, gone;
    sx_body_state st;
    sx_xform xf;
    int k;
    (void)state;
    floor_id = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, NULL);
    resting = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-3.0), SX_R(0.5)), &box, NULL);
    spinner = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(3.0), SX_R(20.0)), &box, NULL);
    assert_int_equal(sx_body_set_angular_velocity(w, spinner, SX_R(2.0)), SX_OK);
    steps(w, 90); /* the resting box falls asleep; the spinner is still falling */
    for (k = 0; k < 3; ++k) {
        sx_body_id id = k == 0 ? spinner : k == 1 ? resting : floor_id;
        assert_int_equal(sx_body_get_state(w, id, &st), SX_OK);
        xf = sx_body_get_transform(w, id);
        assert_memory_equal(&st.transform, &xf, sizeof xf);
        assert_true(st.linear_velocity.x == sx_body_get_linear_velocity(w, id).x);
        assert_true(st.linear_velocity.y == sx_body_get_linear_velocity(w, id).y);
        assert_true(st.angular_velocity == sx_body_get_angular_velocity(w, id));
        assert_true(st.awake == sx_body_is_awake(w, id));
    }
    assert_int_equal(sx_body_get_state(w, spinner, &st), SX_OK);
    assert_true(st.awake);
    assert_true(st.linear_velocity.y < SX_R(-10.0));
    assert_near(st.angular_velocity, 2.0, 1e-6);
    assert_int_equal(sx_body_get_state(w, resting, &st), SX_OK);
    assert_false(st.awake);
    gone = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(5.0)), &box, NULL);
    assert_int_equal(sx_body_set_linear_velocity(w, gone, sx_v2(SX_R(1.0), SX_R(2.0))), SX_OK);
    assert_int_equal(sx_body_destroy(w, gone), SX_OK);
    assert_int_equal(sx_body_get_state(w, gone, &st), SX_ERR_STALE_HANDLE);
    assert_true(st.transform.p.x == SX_R(0.0) && st.transform.p.y == SX_R(0.0));
    assert_true(st.transform.q.c == SX_R(1.0) && st.transform.q.s == SX_R(0.0));
    assert_true(st.linear_velocity.x == SX_R(0.0) && st.linear_velocity.y == SX_R(0.0));
    assert_true(st.angular_velocity == SX_R(0.0));
    assert_false(st.awake);
    assert_int_equal(sx_body_get_state(NULL, spinner, &st), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_get_state(w, spinner, NULL), SX_ERR_INVALID_ARG);
    sx_world_destroy(w);
}

static void a_body_created_disabled_can_be_enabled_and_falls(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ball;
    (void)state;
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(0.0), SX_R(10.0));
    bd.enabled = false;
    assert_int_equal(sx_body_create(w, &bd, &ball), SX_OK);
    assert_int_equal(sx_collider_create(w, ball, &cd, NULL), SX_OK);
    assert_false(sx_body_is_enabled(w, ball));
    steps(w, 30);
    assert_near(sx_body_get_position(w, ball).y, 10.0, 0.0);
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(0.0), SX_R(10.0)), NULL, NULL), 0);
    assert_int_equal(sx_body_set_enabled(w, ball, true), SX_OK);
    assert_true(sx_body_is_enabled(w, ball));
    assert_true(sx_body_is_awake(w, ball));
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(0.0), SX_R(10.0)), NULL, NULL), 1);
    steps(w, 60);
    /* free fall for 1 s: v = -10 m/s, symplectic Euler's drop 5 m + g h T / 2 */
    assert_near(sx_body_get_linear_velocity(w, ball).y, -10.0, 1e-3);
    assert_near(sx_body_get_position(w, ball).y, 10.0 - 5.0 - 10.0 * SUB_H / 2.0, 1e-3);
    sx_world_destroy(w);
}

static void disabling_a_support_drops_its_contacts_and_what_rested_on_it_falls(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape plank = sx_box_shape(SX_R(2.0), SX_R(0.25)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id support, top;
    sx_real y0;
    (void)state;
    support = make_body(w, SX_BODY_STATIC, sx_v2_zero(), &plank, NULL);
    top = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.75)), &box, NULL);
    steps(w, 120); /* resting, then asleep */
    assert_false(sx_body_is_awake(w, top));
    y0 = sx_body_get_position(w, top).y;
    assert_near(y0, 0.75, 0.01);
    assert_true(sx_world_contact_count(w) > 0);
    assert_int_equal(sx_body_set_enabled(w, support, false), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 0);
    assert_true(sx_body_is_awake(w, top));
    steps(w, 30);
    assert_true(sx_body_get_position(w, top).y < y0 - SX_R(1.0));
    /* enabled again, queries see it again; enabling twice is no change */
    assert_int_equal(sx_body_set_enabled(w, support, true), SX_OK);
    assert_int_equal(sx_body_set_enabled(w, support, true), SX_OK);
    assert_int_equal(sx_world_query_point(w, sx_v2_zero(), NULL, NULL), 1);
    sx_world_destroy(w);
}

static void gravity_scale_and_damping_set_at_run_time_act_at_the_next_step(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &ball, NULL);
    int i;
    double v = 0.0, h = SUB_H;
    (void)state;
    assert_near(sx_body_get_gravity_scale(w, b), 1.0, 0.0);
    assert_int_equal(sx_body_set_gravity_scale(w, b, SX_R(0.0)), SX_OK);
    steps(w, 10);
    assert_near(sx_body_get_linear_velocity(w, b).y, 0.0, 0.0);
    assert_int_equal(sx_body_set_gravity_scale(w, b, SX_R(-0.5)), SX_OK);
    assert_near(sx_body_get_gravity_scale(w, b), -0.5, 0.0);
    steps(w, 60);
    assert_near(sx_body_get_linear_velocity(w, b).y, 5.0, 1e-4);
    /* damping: v <- (v + h g) / (1 + h c) per sub-step */
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2_zero()), SX_OK);
    assert_int_equal(sx_body_set_gravity_scale(w, b, SX_R(1.0)), SX_OK);
    assert_int_equal(sx_body_set_linear_damping(w, b, SX_R(2.0)), SX_OK);
    assert_int_equal(sx_body_set_angular_damping(w, b, SX_R(3.0)), SX_OK);
    assert_near(sx_body_get_linear_damping(w, b), 2.0, 0.0);
    assert_near(sx_body_get_angular_damping(w, b), 3.0, 0.0);
    steps(w, 60);
    for (i = 0; i < 60 * sx_default_world_def().sub_steps; ++i)
        v = (v - h * 10.0) / (1.0 + h * 2.0);
    assert_near(sx_body_get_linear_velocity(w, b).y, v, 1e-3);
    /* bad values change nothing */
    assert_int_equal(sx_body_set_gravity_scale(w, b, nan_value()), SX_ERR_NONFINITE);
    assert_int_equal(sx_body_set_linear_damping(w, b, SX_R(-1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_set_linear_damping(w, b, inf_value()), SX_ERR_NONFINITE);
    assert_int_equal(sx_body_set_angular_damping(w, b, nan_value()), SX_ERR_NONFINITE);
    assert_int_equal(sx_body_set_angular_damping(w, b, SX_R(-0.1)), SX_ERR_INVALID_ARG);
    assert_near(sx_body_get_gravity_scale(w, b), 1.0, 0.0);
    assert_near(sx_body_get_linear_damping(w, b), 2.0, 0.0);
    assert_near(sx_body_get_angular_damping(w, b), 3.0, 0.0);
    sx_world_destroy(w);
}

static void fixed_rotation_set_at_run_time_zeroes_inertia_and_freeing_restores_it(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(0.5)); /* 2 x 1 m, 2 kg at density 1 */
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &box, NULL);
    double inertia = 2.0 * (4.0 + 1.0) / 12.0;
    (void)state;
    assert_near(sx_body_get_inertia(w, b), inertia, 1e-5);
    assert_int_equal(sx_body_set_angular_velocity(w, b, SX_R(2.0)), SX_OK);
    assert_int_equal(sx_body_set_fixed_rotation(w, b, true), SX_OK);
    assert_true(sx_body_is_fixed_rotation(w, b));
    assert_near(sx_body_get_inertia(w, b), 0.0, 0.0);
    assert_near(sx_body_get_angular_velocity(w, b), 0.0, 0.0);
    assert_int_equal(sx_body_apply_torque(w, b, SX_R(100.0)), SX_OK);
    steps(w, 10);
    assert_near(sx_body_get_angle(w, b), 0.0, 0.0);
    assert_int_equal(sx_body_set_fixed_rotation(w, b, false), SX_OK);
    assert_false(sx_body_is_fixed_rotation(w, b));
    assert_near(sx_body_get_inertia(w, b), inertia, 1e-5);
    assert_int_equal(sx_body_apply_angular_impulse(w, b, SX_R(1.0)), SX_OK);
    steps(w, 1);
    assert_near(sx_body_get_angular_velocity(w, b), 1.0 / inertia, 1e-4);
    sx_world_destroy(w);
}

/* ---- colliders -------------------------------------------------------------------- */

static void collider_density_change_recomputes_the_body_mass(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape a = sx_box_shape(SX_R(0.5), SX_R(0.5)),
             c = sx_circle_shape(sx_v2(SX_R(2.0), SX_R(0.0)), SX_R(0.5));
    sx_collider_id ca, cc;
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &a, &ca);
    sx_collider_def cd = sx_default_collider_def();
    (void)state;
    cd.shape = c;
    assert_int_equal(sx_collider_create(w, b, &cd, &cc), SX_OK);
    assert_near(sx_body_get_mass(w, b), 1.0 + 3.14159265358979 * 0.25, 1e-5);
    assert_int_equal(sx_collider_set_density(w, cc, SX_R(0.0)), SX_OK);
    assert_near(sx_collider_get_density(w, cc), 0.0, 0.0);
    assert_near(sx_body_get_mass(w, b), 1.0, 1e-6);
    assert_vec2_near(sx_body_get_local_center(w, b), sx_v2_zero(), 1e-6);
    assert_int_equal(sx_collider_set_density(w, ca, SX_R(3.0)), SX_OK);
    assert_near(sx_body_get_mass(w, b), 3.0, 1e-6);
    assert_vec2_near(sx_body_get_position(w, b), sx_v2_zero(), 0.0);
    assert_int_equal(sx_collider_set_density(w, ca, SX_R(-1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_density(w, ca, nan_value()), SX_ERR_NONFINITE);
    assert_near(sx_body_get_mass(w, b), 3.0, 1e-6);
    sx_world_destroy(w);
}

/* A ball dropped from 2 m onto the ground bounces to e^2 x 2 m; with e set
 * to 0 at run time it stays down. */
static sx_real bounce_apex(sx_real restitution) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(10.0), SX_R(1.0));
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_collider_id cb;
    sx_body_id b;
    sx_real apex = SX_R(0.0);
    bool rebounded = false;
    int i;
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground, NULL);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(2.5)), &ball, &cb);
    assert_int_equal(sx_collider_set_restitution(w, cb, restitution), SX_OK);
    assert_near(sx_collider_get_restitution(w, cb), restitution, 0.0);
    for (i = 0; i < 180; ++i) {
        sx_real y;
        steps(w, 1);
        y = sx_body_get_position(w, b).y - SX_R(0.5);
        if (sx_body_get_linear_velocity(w, b).y > SX_R(0.0)) rebounded = true;
        if (rebounded && y > apex) apex = y;
    }
    sx_world_destroy(w);
    return apex;
}

static void collider_restitution_and_friction_set_at_run_time_change_the_motion(void **state) {
    sx_world *w;
    sx_shape ground = sx_box_shape(SX_R(50.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_collider_id cg, cb;
    sx_body_id b;
    (void)state;
    assert_near(bounce_apex(SX_R(0.5)), 0.5, 0.02);
    assert_near(bounce_apex(SX_R(0.0)), 0.0, 0.01);
    w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    /* a box sliding at 2 m/s on mu = 0 keeps its speed; mu = 0.5 stops it */
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground, &cg);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box, &cb);
    assert_int_equal(sx_collider_set_friction(w, cg, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_collider_set_friction(w, cb, SX_R(0.0)), SX_OK);
    assert_near(sx_collider_get_friction(w, cb), 0.0, 0.0);
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(2.0), SX_R(0.0))), SX_OK);
    steps(w, 60);
    assert_near(sx_body_get_linear_velocity(w, b).x, 2.0, 1e-3);
    assert_int_equal(sx_collider_set_friction(w, cg, SX_R(0.5)), SX_OK);
    assert_int_equal(sx_collider_set_friction(w, cb, SX_R(0.5)), SX_OK);
    /* a = mu g = 5 m/s^2: stopped within 0.4 s */
    steps(w, 30);
    assert_near(sx_body_get_linear_velocity(w, b).x, 0.0, 1e-3);
    assert_int_equal(sx_collider_set_friction(w, cb, SX_R(-0.5)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_friction(w, cb, inf_value()), SX_ERR_NONFINITE);
    assert_int_equal(sx_collider_set_restitution(w, cb, nan_value()), SX_ERR_NONFINITE);
    assert_int_equal(sx_collider_set_restitution(w, cb, SX_R(-1.0)), SX_ERR_INVALID_ARG);
    assert_near(sx_collider_get_friction(w, cb), 0.5, 0.0);
    assert_near(sx_collider_get_restitution(w, cb), 0.0, 0.0);
    sx_world_destroy(w);
}

static void a_filter_set_at_run_time_ends_the_contact_and_lets_the_body_fall(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(10.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_collider_id cb;
    sx_body_id b;
    sx_filter none = {2u, 0u, 0}, got;
    sx_contact_events ev;
    (void)state;
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground, NULL);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box, &cb);
    steps(w, 120);
    assert_false(sx_body_is_awake(w, b));
    assert_int_equal(sx_collider_set_filter(w, cb, none), SX_OK);
    got = sx_collider_get_filter(w, cb);
    assert_int_equal(got.category, 2u);
    assert_int_equal(got.mask, 0u);
    assert_true(sx_body_is_awake(w, b));
    steps(w, 1);
    ev = sx_world_get_contact_events(w);
    assert_int_equal(ev.end_count, 1);
    steps(w, 30);
    assert_true(sx_body_get_position(w, b).y < SX_R(0.0));
    assert_false(sx_collider_is_sensor(w, cb));
    sx_world_destroy(w);
}

/* ---- iteration, bounds, user data --------------------------------------------------- */

static void bodies_and_colliders_are_listed_in_slot_order_without_the_destroyed(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ids[5], got[8];
    sx_collider_id cols[3], gotc[4];
    int i;
    (void)state;
    assert_int_equal(sx_world_get_bodies(w, NULL, 0), 0);
    for (i = 0; i < 5; ++i)
        ids[i] = make_body(w, SX_BODY_DYNAMIC, sx_v2((sx_real)i, SX_R(0.0)), NULL, NULL);
    assert_int_equal(sx_body_destroy(w, ids[1]), SX_OK);
    assert_int_equal(sx_world_get_bodies(w, NULL, 0), 4);
    assert_int_equal(sx_world_get_bodies(w, got, 8), 4);
    assert_true(memcmp(&got[0], &ids[0], sizeof(sx_body_id)) == 0);
    assert_true(memcmp(&got[1], &ids[2], sizeof(sx_body_id)) == 0);
    assert_true(memcmp(&got[3], &ids[4], sizeof(sx_body_id)) == 0);
    /* a short array gets the first ones; the count is still all of them */
    memset(got, 0, sizeof(got));
    assert_int_equal(sx_world_get_bodies(w, got, 2), 4);
    assert_true(memcmp(&got[1], &ids[2], sizeof(sx_body_id)) == 0);
    assert_true(sx_body_id_is_null(got[2]));
    assert_int_equal(sx_world_get_bodies(w, got, -3), 4);
    assert_int_equal(sx_world_get_bodies(NULL, got, 8), 0);
    for (i = 0; i < 3; ++i) {
        cd.shape = sx_offset_box_shape(SX_R(0.5), SX_R(0.5), sx_v2((sx_real)i, SX_R(0.0)), 0);
        assert_int_equal(sx_collider_create(w, ids[0], &cd, &cols[i]), SX_OK);
    }
    assert_int_equal(sx_collider_destroy(w, cols[1]), SX_OK);
    assert_int_equal(sx_body_get_colliders(w, ids[0], gotc, 4), 2);
    assert_true(memcmp(&gotc[0], &cols[0], sizeof(sx_collider_id)) == 0);
    assert_true(memcmp(&gotc[1], &cols[2], sizeof(sx_collider_id)) == 0);
    assert_int_equal(sx_body_get_colliders(w, ids[1], gotc, 4), 0); /* stale */
    assert_int_equal(sx_body_get_colliders(w, ids[2], NULL, 0), 0);
    sx_world_destroy(w);
}

static void bounds_cover_every_collider_at_the_current_transform(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape ball = sx_circle_shape(sx_v2(SX_R(2.0), SX_R(0.0)), SX_R(0.5));
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_collider_id cb;
    sx_body_id b = make_body(w, SX_BODY_KINEMATIC, sx_v2(SX_R(10.0), SX_R(5.0)), &box, &cb);
    sx_body_id bare = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-3.0), SX_R(4.0)), NULL, NULL);
    sx_collider_def cd = sx_default_collider_def();
    sx_aabb a;
    (void)state;
    cd.shape = ball;
    assert_int_equal(sx_collider_create(w, b, &cd, NULL), SX_OK);
    a = sx_body_get_aabb(w, b);
    assert_vec2_near(a.lower, sx_v2(SX_R(9.0), SX_R(4.5)), SX_TEST_EPS);
    assert_vec2_near(a.upper, sx_v2(SX_R(12.5), SX_R(5.5)), SX_TEST_EPS);
    a = sx_collider_get_aabb(w, cb);
    assert_vec2_near(a.upper, sx_v2(SX_R(11.0), SX_R(5.5)), SX_TEST_EPS);
    /* a quarter turn: the ball's centre goes to (10, 7) */
    assert_int_equal(sx_body_set_transform(w, b, sx_v2(SX_R(10.0), SX_R(5.0)), SX_PI / 2), SX_OK);
    a = sx_body_get_aabb(w, b);
    assert_vec2_near(a.lower, sx_v2(SX_R(9.5), SX_R(4.0)), 1e-5);
    assert_vec2_near(a.upper, sx_v2(SX_R(10.5), SX_R(7.5)), 1e-5);
    a = sx_body_get_aabb(w, bare);
    assert_vec2_near(a.lower, sx_v2(SX_R(-3.0), SX_R(4.0)), 0.0);
    assert_vec2_near(a.upper, sx_v2(SX_R(-3.0), SX_R(4.0)), 0.0);
    assert_int_equal(sx_body_destroy(w, b), SX_OK);
    a = sx_body_get_aabb(w, b);
    assert_vec2_near(a.lower, sx_v2_zero(), 0.0);
    assert_vec2_near(a.upper, sx_v2_zero(), 0.0);
    a = sx_collider_get_aabb(w, cb);
    assert_vec2_near(a.upper, sx_v2_zero(), 0.0);
    a = sx_body_get_aabb(NULL, bare);
    assert_vec2_near(a.upper, sx_v2_zero(), 0.0);
    sx_world_destroy(w);
}

static void stale_handles_and_null_worlds_are_refused_by_every_setter(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_collider_id c;
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &box, &c);
    sx_body_id null_body = {0, 0};
    sx_collider_id null_collider = {0, 0};
    sx_filter f = {1u, 1u, 0};
    int marker = 7;
    (void)state;
    assert_int_equal(sx_body_set_user_data(w, b, &marker), SX_OK);
    assert_ptr_equal(sx_body_get_user_data(w, b), &marker);
    assert_int_equal(sx_collider_set_user_data(w, c, &marker), SX_OK);
    assert_ptr_equal(sx_collider_get_user_data(w, c), &marker);
    assert_int_equal(sx_body_destroy(w, b), SX_OK);
    assert_int_equal(sx_body_destroy(w, b), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_destroy(w, c), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_enabled(w, b, false), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_gravity_scale(w, b, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_linear_damping(w, b, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_angular_damping(w, b, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_fixed_rotation(w, b, true), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_user_data(w, b, NULL), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_enabled(w, null_body, true), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_set_friction(w, c, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_set_restitution(w, c, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_set_density(w, c, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_set_filter(w, c, f), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_set_user_data(w, c, NULL), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_set_friction(w, null_collider, SX_R(1.0)), SX_ERR_STALE_HANDLE);
    /* a stale handle wins over a bad value: the handle is checked first */
    assert_int_equal(sx_body_set_gravity_scale(w, b, nan_value()), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_enabled(NULL, b, true), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_set_gravity_scale(NULL, b, SX_R(1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_set_linear_damping(NULL, b, SX_R(1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_set_angular_damping(NULL, b, SX_R(1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_set_fixed_rotation(NULL, b, true), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_set_user_data(NULL, b, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_friction(NULL, c, SX_R(1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_restitution(NULL, c, SX_R(1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_density(NULL, c, SX_R(1.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_filter(NULL, c, f), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_set_user_data(NULL, c, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_create(NULL, NULL, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_destroy(NULL, b), SX_ERR_INVALID_ARG);
    /* getters answer zeros */
    assert_false(sx_body_is_enabled(w, b));
    assert_false(sx_body_is_fixed_rotation(w, b));
    assert_near(sx_body_get_gravity_scale(w, b), 0.0, 0.0);
    assert_near(sx_body_get_linear_damping(NULL, b), 0.0, 0.0);
    assert_near(sx_body_get_angular_damping(w, b), 0.0, 0.0);
    assert_near(sx_collider_get_friction(w, c), 0.0, 0.0);
    assert_near(sx_collider_get_restitution(w, c), 0.0, 0.0);
    assert_near(sx_collider_get_density(NULL, c), 0.0, 0.0);
    assert_int_equal(sx_collider_get_filter(w, c).mask, 0u);
    assert_null(sx_collider_get_user_data(w, c));
    assert_false(sx_collider_is_sensor(w, c));
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_def_validate_names_the_first_refused_field),
        cmocka_unit_test(world_solver_settings_change_at_run_time_as_at_creation),
        cmocka_unit_test(a_body_created_disabled_can_be_enabled_and_falls),
        cmocka_unit_test(disabling_a_support_drops_its_contacts_and_what_rested_on_it_falls),
        cmocka_unit_test(gravity_scale_and_damping_set_at_run_time_act_at_the_next_step),
        cmocka_unit_test(fixed_rotation_set_at_run_time_zeroes_inertia_and_freeing_restores_it),
        cmocka_unit_test(collider_density_change_recomputes_the_body_mass),
        cmocka_unit_test(collider_restitution_and_friction_set_at_run_time_change_the_motion),
        cmocka_unit_test(a_filter_set_at_run_time_ends_the_contact_and_lets_the_body_fall),
        cmocka_unit_test(bodies_and_colliders_are_listed_in_slot_order_without_the_destroyed),
        cmocka_unit_test(bounds_cover_every_collider_at_the_current_transform),
        cmocka_unit_test(stale_handles_and_null_worlds_are_refused_by_every_setter),
        cmocka_unit_test(a_body_state_is_the_getters_answers_in_one_call),
    };
    return cmocka_run_group_tests_name("world_props", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
