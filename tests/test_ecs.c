/* sepax tests — the flecs module: a real flecs world in each test. Bodies
 * and static geometry from components, a trajectory bit-identical to the
 * plain world's, the fixed tick and its cap, contact events, writes to the
 * components taking effect, deletion in mid-contact, helpers, reflection,
 * and many entities (leaks are ASan's to find in the SAN=1 build). */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "sepax_flecs.h"
#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))

static ecs_world_t *make_world(void) {
    ecs_world_t *world = ecs_init();
    assert_non_null(world);
    ECS_IMPORT(world, SepaxPhysics);
    return world;
}

static void set_gravity(ecs_world_t *world, sx_vec2 g) {
    SxPhysicsSettings *s = ecs_singleton_ensure(world, SxPhysicsSettings);
    s->gravity = g;
}

static ecs_entity_t add_ground(ecs_world_t *world) {
    ecs_entity_t e = ecs_new(world);
    SxTransform t = {{SX_R(0.0), SX_R(-1.0)}, SX_R(0.0)};
    SxCollider c = sx_ecs_collider(sx_box_shape(SX_R(20.0), SX_R(1.0)));
    ecs_set_ptr(world, e, SxTransform, &t);
    ecs_set_ptr(world, e, SxCollider, &c);
    return e;
}

static ecs_entity_t add_dynamic(ecs_world_t *world, sx_vec2 p, sx_shape shape) {
    ecs_entity_t e = ecs_new(world);
    SxTransform t;
    SxBody b = sx_ecs_body(SX_BODY_DYNAMIC);
    SxCollider c = sx_ecs_collider(shape);
    t.position = p;
    t.angle = SX_R(0.0);
    ecs_set_ptr(world, e, SxTransform, &t);
    ecs_set_ptr(world, e, SxBody, &b);
    ecs_set_ptr(world, e, SxCollider, &c);
    return e;
}

static void progress(ecs_world_t *world, int frames, double dt) {
    int i;
    for (i = 0; i < frames; ++i)
        ecs_progress(world, (ecs_ftime_t)dt);
}

static sx_vec2 position_of(ecs_world_t *world, ecs_entity_t e) {
    const SxTransform *t = ecs_get(world, e, SxTransform);
    assert_non_null(t);
    return t->position;
}

static void box_falls_onto_static_ground_and_comes_to_rest(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t box;
    const SxBody *b;
    (void)state;
    add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(3.0)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 240, 1.0 / 60.0);
    /* resting on the surface y = 0, within the linear slop */
    assert_near(position_of(world, box).y, 0.5, 0.01);
    assert_near(position_of(world, box).x, 0.0, 1e-3);
    b = ecs_get(world, box, SxBody);
    assert_non_null(b);
    assert_true(sx_length(b->velocity) < SX_R(0.05));
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 2);
    assert_true(ecs_singleton_get(world, SxContacts)->count >= 1);
    ecs_fini(world);
}

/* The same scene through the module and through sx_world_step: a bouncing,
 * spinning ball and two boxes that land on each other. Every position,
 * angle and velocity must match to the last bit, frame by frame (static
 * geometry is created first, then bodies in entity order, as the module
 * does). */
static void ball_bounce_is_bit_identical_to_the_plain_world(void **state) {
    enum { N = 3 };
    ecs_world_t *world = make_world();
    sx_world_def def = sx_default_world_def();
    sx_world *plain = sx_world_create(&def);
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ids[N], ground_id;
    ecs_entity_t es[N];
    sx_vec2 at[N];
    sx_shape shapes[N];
    int frame, i;
    bool rebounded = false;
    (void)state;
    assert_non_null(plain);
    at[0] = sx_v2(SX_R(0.3), SX_R(4.0));
    shapes[0] = sx_circle_shape(sx_v2(0, 0), SX_R(0.5));
    at[1] = sx_v2(SX_R(4.0), SX_R(1.0));
    shapes[1] = sx_box_shape(SX_R(0.5), SX_R(0.5));
    at[2] = sx_v2(SX_R(4.3), SX_R(3.0));
    shapes[2] = sx_box_shape(SX_R(0.6), SX_R(0.3));

    add_ground(world);
    for (i = 0; i < N; ++i)
        es[i] = add_dynamic(world, at[i], shapes[i]);
    {
        SxCollider c = *ecs_get(world, es[0], SxCollider);
        c.restitution = SX_R(0.7);
        ecs_set_ptr(world, es[0], SxCollider, &c);
        ecs_get_mut(world, es[0], SxBody)->angular_velocity = SX_R(1.5);
    }

    bd.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    assert_int_equal(sx_create_body(plain, &bd, &ground_id), SX_OK);
    cd.shape = sx_box_shape(SX_R(20.0), SX_R(1.0));
    assert_int_equal(sx_body_add_collider(plain, ground_id, &cd, NULL), SX_OK);
    for (i = 0; i < N; ++i) {
        bd.type = SX_BODY_DYNAMIC;
        bd.position = at[i];
        bd.angular_velocity = i == 0 ? SX_R(1.5) : SX_R(0.0);
        assert_int_equal(sx_create_body(plain, &bd, &ids[i]), SX_OK);
        cd.shape = shapes[i];
        cd.restitution = i == 0 ? SX_R(0.7) : SX_R(0.0);
        assert_int_equal(sx_body_add_collider(plain, ids[i], &cd, NULL), SX_OK);
    }

    for (frame = 0; frame < 240; ++frame) {
        ecs_progress(world, (ecs_ftime_t)DT);
        assert_int_equal(sx_world_step(plain, DT), SX_OK);
        for (i = 0; i < N; ++i) {
            const SxTransform *t = ecs_get(world, es[i], SxTransform);
            const SxBody *b = ecs_get(world, es[i], SxBody);
            sx_vec2 p = sx_body_get_position(plain, ids[i]);
            sx_vec2 v = sx_body_get_linear_velocity(plain, ids[i]);
            sx_real angle = sx_body_get_angle(plain, ids[i]);
            sx_real w = sx_body_get_angular_velocity(plain, ids[i]);
            assert_memory_equal(&t->position, &p, sizeof(p));
            assert_memory_equal(&t->angle, &angle, sizeof(angle));
            assert_memory_equal(&b->velocity, &v, sizeof(v));
            assert_memory_equal(&b->angular_velocity, &w, sizeof(w));
            assert_int_equal(b->awake, sx_body_is_awake(plain, ids[i]));
        }
        if (ecs_get(world, es[0], SxBody)->velocity.y > SX_R(2.0)) rebounded = true;
    }
    assert_int_equal(sx_ecs_step_count(world), 240);
    /* the trajectory had contacts in it: the ball came back up, and the
     * second box rests on the first */
    assert_true(rebounded);
    assert_near(position_of(world, es[2]).y, 1.3, 0.02);
    sx_world_destroy(plain);
    ecs_fini(world);
}

static void count_system(ecs_iter_t *it) {
    int *count = (int *)it->ctx;
    ++*count;
}

static void fixed_tick_runs_whole_steps_and_stages_once_per_sub_step(void **state) {
    ecs_world_t *world = make_world();
    int solves = 0;
    ecs_entity_desc_t ed;
    ecs_system_desc_t sd;
    ecs_id_t add[2];
    (void)state;
    ecs_singleton_ensure(world, SxPhysicsSettings)->max_steps_per_frame = 100;
    add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.0)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    /* a game system between the stages */
    memset(&ed, 0, sizeof(ed));
    memset(&sd, 0, sizeof(sd));
    add[0] = ecs_dependson(SxPhysicsSolve);
    add[1] = 0;
    ed.add = add;
    sd.entity = ecs_entity_init(world, &ed);
    sd.callback = count_system;
    sd.ctx = &solves;
    ecs_system_init(world, &sd);

    progress(world, 10, 0.1);
    assert_int_equal(sx_ecs_step_count(world), 60);
    assert_int_equal(solves, 60 * sx_default_world_def().sub_steps);
    ecs_fini(world);

    world = make_world();
    progress(world, 10, 1.0 / 240.0);
    assert_true(sx_ecs_step_count(world) >= 2 && sx_ecs_step_count(world) <= 3);
    ecs_fini(world);
}

static void a_long_frame_runs_at_most_max_steps_and_drops_the_rest(void **state) {
    ecs_world_t *world = make_world();
    (void)state;
    ecs_singleton_ensure(world, SxPhysicsSettings)->max_steps_per_frame = 5;
    progress(world, 1, 1.0);
    assert_int_equal(sx_ecs_step_count(world), 5);
    /* the second long of time is not caught up later */
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_ecs_step_count(world), 6);
    ecs_fini(world);
}

/* Settings out of range run no step (issue 28: sub_steps = INT_MAX made a
 * frame that never returns); back in range, stepping resumes. */
static void sub_steps_beyond_the_limit_run_no_step(void **state) {
    ecs_world_t *world = make_world();
    (void)state;
    ecs_singleton_ensure(world, SxPhysicsSettings)->sub_steps = INT_MAX;
    progress(world, 3, 1.0 / 60.0);
    assert_int_equal(sx_ecs_step_count(world), 0);
    ecs_singleton_ensure(world, SxPhysicsSettings)->sub_steps = SX_MAX_SUB_STEPS + 1;
    progress(world, 3, 1.0 / 60.0);
    assert_int_equal(sx_ecs_step_count(world), 0);
    ecs_singleton_ensure(world, SxPhysicsSettings)->sub_steps = SX_MAX_SUB_STEPS;
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_ecs_step_count(world), 1);
    ecs_fini(world);
}

typedef struct event_log {
    int begins, ends;
    ecs_entity_t watch;
    SxContactEvent last_begin;
} event_log;

static void on_begin(ecs_iter_t *it) {
    event_log *log = (event_log *)it->ctx;
    const SxContactEvent *ev = (const SxContactEvent *)it->param;
    if (ev->self != log->watch) return;
    ++log->begins;
    log->last_begin = *ev;
}

static void on_end(ecs_iter_t *it) {
    event_log *log = (event_log *)it->ctx;
    const SxContactEvent *ev = (const SxContactEvent *)it->param;
    if (ev->self == log->watch) ++log->ends;
}

static void observe(ecs_world_t *world, event_log *log) {
    ecs_observer(world, {.query.terms = {{ecs_id(SxCollider)}},
                         .events = {SxContactBegin},
                         .callback = on_begin,
                         .ctx = log});
    ecs_observer(world, {.query.terms = {{ecs_id(SxCollider)}},
                         .events = {SxContactEnd},
                         .callback = on_end,
                         .ctx = log});
}

static void contact_begin_and_end_reach_observers_exactly_once(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t ground, box;
    event_log log;
    SxTransform up = {{SX_R(0.0), SX_R(10.0)}, SX_R(0.0)};
    (void)state;
    memset(&log, 0, sizeof(log));
    observe(world, &log);
    ground = add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(2.0)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    log.watch = box;
    progress(world, 120, 1.0 / 60.0);
    assert_int_equal(log.begins, 1);
    assert_int_equal(log.ends, 0);
    assert_true(log.last_begin.other == ground);
    /* from the box (self) down to the ground */
    assert_vec2_near(log.last_begin.normal, sx_v2(SX_R(0.0), SX_R(-1.0)), 1e-4);
    assert_near(log.last_begin.point.y, 0.0, 0.05);

    ecs_set_ptr(world, box, SxTransform, &up); /* lift it away */
    progress(world, 2, 1.0 / 60.0);
    assert_int_equal(log.begins, 1);
    assert_int_equal(log.ends, 1);
    ecs_fini(world);
}

static void count_event(ecs_iter_t *it) {
    event_log *log = (event_log *)it->ctx;
    const SxContactEvent *ev = (const SxContactEvent *)it->param;
    if (ev->self != log->watch) return;
    if (it->event == SxSensorBegin) ++log->begins;
    if (it->event == SxSensorEnd) ++log->ends;
    log->last_begin = *ev;
}

static void a_ball_through_a_sensor_gives_one_sensor_begin_and_end(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t sensor = ecs_new(world), ball;
    SxTransform t = {{SX_R(0.0), SX_R(3.0)}, SX_R(0.0)};
    SxCollider c = sx_ecs_collider(sx_box_shape(SX_R(2.0), SX_R(0.25)));
    event_log log;
    (void)state;
    memset(&log, 0, sizeof(log));
    c.sensor = true;
    ecs_set_ptr(world, sensor, SxTransform, &t);
    ecs_set_ptr(world, sensor, SxCollider, &c);
    add_ground(world);
    ball = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(5.0)), sx_circle_shape(sx_v2(0, 0), SX_R(0.3)));
    log.watch = sensor;
    ecs_observer(world, {.query.terms = {{ecs_id(SxCollider)}},
                         .events = {SxSensorBegin, SxSensorEnd},
                         .callback = count_event,
                         .ctx = &log});
    progress(world, 120, 1.0 / 60.0);
    assert_int_equal(log.begins, 1);
    assert_int_equal(log.ends, 1);
    assert_true(log.last_begin.other == ball);
    /* the ball fell through the sensor onto the ground */
    assert_near(position_of(world, ball).y, 0.3, 0.02);
    ecs_fini(world);
}

static void teleport_and_velocity_writes_take_effect_at_the_next_step(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t e;
    SxTransform t = {{SX_R(5.0), SX_R(7.0)}, SX_R(0.25)};
    SxBody *b;
    sx_vec2 p;
    (void)state;
    set_gravity(world, sx_v2(0, 0));
    e = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.0)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 1, 1.0 / 60.0);
    ecs_set_ptr(world, e, SxTransform, &t);
    progress(world, 1, 1.0 / 60.0);
    assert_vec2_near(position_of(world, e), sx_v2(SX_R(5.0), SX_R(7.0)), 1e-6);
    assert_near(ecs_get(world, e, SxTransform)->angle, 0.25, 1e-5);

    b = ecs_get_mut(world, e, SxBody);
    b->velocity = sx_v2(SX_R(3.0), SX_R(-1.5));
    progress(world, 1, 1.0 / 60.0);
    p = position_of(world, e);
    assert_near(p.x, 5.0 + 3.0 / 60.0, 1e-5);
    assert_near(p.y, 7.0 - 1.5 / 60.0, 1e-5);
    assert_vec2_near(ecs_get(world, e, SxBody)->velocity, sx_v2(SX_R(3.0), SX_R(-1.5)), 1e-6);
    ecs_fini(world);
}

static void delete_on_begin(ecs_iter_t *it) {
    const SxContactEvent *ev = (const SxContactEvent *)it->param;
    ecs_entity_t *victim = (ecs_entity_t *)it->ctx;
    if (ev->self == *victim) ecs_delete(it->world, ev->self);
}

/* The copy-in pushes only what the game changed, so a resting box falls
 * asleep under the module as in the plain world, and a write wakes it. */
static void resting_bodies_sleep_and_a_velocity_write_wakes_them(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t box;
    (void)state;
    add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 120, 1.0 / 60.0);
    assert_false(ecs_get(world, box, SxBody)->awake);
    assert_int_equal(sx_world_awake_body_count(sx_ecs_world(world)), 0);
    ecs_get_mut(world, box, SxBody)->velocity = sx_v2(SX_R(0.0), SX_R(3.0));
    progress(world, 1, 1.0 / 60.0);
    assert_true(ecs_get(world, box, SxBody)->awake);
    assert_true(position_of(world, box).y > SX_R(0.5));
    ecs_fini(world);

    /* with sleeping off nothing sleeps */
    world = make_world();
    ecs_singleton_ensure(world, SxPhysicsSettings)->enable_sleep = false;
    add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 120, 1.0 / 60.0);
    assert_true(ecs_get(world, box, SxBody)->awake);
    ecs_fini(world);
}

static void deleting_entities_in_the_middle_of_contacts_is_safe(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t ground, boxes[4], victim;
    const SxContacts *contacts;
    int i;
    (void)state;
    ground = add_ground(world);
    for (i = 0; i < 4; ++i) {
        boxes[i] = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.5) + (sx_real)i * SX_R(1.0)),
                               sx_box_shape(SX_R(0.5), SX_R(0.5)));
    }
    progress(world, 30, 1.0 / 60.0);
    assert_true(ecs_singleton_get(world, SxContacts)->count >= 4);
    /* a box in the middle of the stack, between frames */
    ecs_delete(world, boxes[1]);
    progress(world, 30, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 4);
    /* an entity deleted from an observer while the step is deferred */
    victim =
        add_dynamic(world, sx_v2(SX_R(3.0), SX_R(2.0)), sx_circle_shape(sx_v2(0, 0), SX_R(0.3)));
    ecs_observer(world, {.query.terms = {{ecs_id(SxCollider)}},
                         .events = {SxContactBegin},
                         .callback = delete_on_begin,
                         .ctx = &victim});
    progress(world, 60, 1.0 / 60.0);
    assert_false(ecs_is_alive(world, victim));
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 4);
    /* the ground goes: the rest falls */
    ecs_delete(world, ground);
    progress(world, 60, 1.0 / 60.0);
    assert_true(position_of(world, boxes[0]).y < SX_R(-1.0));
    contacts = ecs_singleton_get(world, SxContacts);
    for (i = 0; i < contacts->count; ++i) {
        assert_true(contacts->items[i].entity_a != ground && contacts->items[i].entity_b != ground);
        assert_true(i == 0 || contacts->items[i - 1].entity_a <= contacts->items[i].entity_a);
    }
    ecs_fini(world);
}

/* The module makes bodies table by table, so when the entities' order
 * differs from the tables' (three tags split a row of boxes), the world lists the
 * contacts out of the entities' order: SxContacts still comes sorted by
 * (entity_a, entity_b), one entry per collider pair, none lost. */
static void contacts_come_sorted_when_the_tables_mix_the_entities(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t tags[3], boxes[12];
    const SxContacts *contacts;
    ecs_entity_t ground;
    int i, with_ground = 0;
    (void)state;
    ground = add_ground(world);
    for (i = 0; i < 3; ++i)
        tags[i] = ecs_new(world);
    for (i = 0; i < 12; ++i) {
        /* side by side, touching: each box meets the ground and its neighbours */
        boxes[i] = add_dynamic(world, sx_v2((sx_real)i * SX_R(1.0) - SX_R(6.0), SX_R(0.5)),
                               sx_box_shape(SX_R(0.5), SX_R(0.5)));
        ecs_add_id(world, boxes[i], tags[i % 3]);
    }
    progress(world, 10, 1.0 / 60.0);
    contacts = ecs_singleton_get(world, SxContacts);
    assert_int_equal(contacts->count, sx_world_contact_count(sx_ecs_world(world)));
    assert_true(contacts->count >= 12);
    for (i = 0; i < contacts->count; ++i) {
        const SxContact *c = &contacts->items[i];
        assert_true(c->entity_a < c->entity_b);
        if (c->entity_a == ground || c->entity_b == ground) ++with_ground;
        if (i > 0) {
            const SxContact *p = &contacts->items[i - 1];
            assert_true(p->entity_a < c->entity_a ||
                        (p->entity_a == c->entity_a && p->entity_b < c->entity_b));
        }
    }
    assert_int_equal(with_ground, 12);
    ecs_fini(world);
}

static void bodies_without_colliders_and_colliders_without_bodies_work(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t bare = ecs_new(world), box;
    SxBody b = sx_ecs_body(SX_BODY_DYNAMIC);
    sx_vec2 before;
    (void)state;
    ecs_set_ptr(world, bare, SxBody, &b); /* SxTransform comes along */
    assert_true(ecs_has(world, bare, SxTransform));
    progress(world, 60, 1.0 / 60.0);
    /* free fall for 1 s: about 5 m (symplectic Euler: a little more) */
    assert_near(position_of(world, bare).y, -5.0, 0.1);

    add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(5.0), SX_R(3.0)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 10, 1.0 / 60.0);
    ecs_remove(world, box, SxBody); /* now static geometry, frozen in the air */
    progress(world, 1, 1.0 / 60.0);
    before = position_of(world, box);
    assert_true(before.y > SX_R(1.0));
    progress(world, 30, 1.0 / 60.0);
    assert_vec2_near(position_of(world, box), before, 0.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 3);
    /* and a body again, which loses its collider and falls through the ground */
    ecs_set_ptr(world, box, SxBody, &b);
    ecs_remove(world, box, SxCollider);
    progress(world, 60, 1.0 / 60.0);
    assert_true(position_of(world, box).y < SX_R(-1.0));
    ecs_fini(world);
}

static void impulse_helper_and_mass_override(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t e;
    SxBody *b;
    (void)state;
    set_gravity(world, sx_v2(0, 0));
    e = add_dynamic(world, sx_v2(0, 0), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    b = ecs_get_mut(world, e, SxBody);
    b->mass = SX_R(4.0);
    ecs_modified(world, e, SxBody);
    progress(world, 1, 1.0 / 60.0);
    sx_ecs_apply_impulse(world, e, sx_v2(SX_R(2.0), SX_R(0.0)));
    progress(world, 1, 1.0 / 60.0);
    assert_vec2_near(ecs_get(world, e, SxBody)->velocity, sx_v2(SX_R(0.5), SX_R(0.0)), 1e-6);
    assert_vec2_near(ecs_get(world, e, SxBody)->impulse, sx_v2(0, 0), 0.0);
    /* a force of 4 N on 4 kg for one step of 1/60 s: +1/60 m/s */
    sx_ecs_apply_force(world, e, sx_v2(SX_R(0.0), SX_R(4.0)));
    progress(world, 1, 1.0 / 60.0);
    assert_near(ecs_get(world, e, SxBody)->velocity.y, 1.0 / 60.0, 1e-6);
    progress(world, 1, 1.0 / 60.0);
    assert_near(ecs_get(world, e, SxBody)->velocity.y, 1.0 / 60.0, 1e-6);
    ecs_fini(world);
}

/* ecs_set on SxCollider of a live body swaps its shape: a box resting on
 * the ground grows from half-extent 0.5 to 1.0 and ends resting 0.5 m
 * higher, with the new shape's mass. */
static void setting_a_new_shape_on_a_resting_body_takes_effect(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t box;
    SxCollider c;
    (void)state;
    add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 30, 1.0 / 60.0);
    assert_near(position_of(world, box).y, 0.5, 0.01);
    c = *ecs_get(world, box, SxCollider);
    c.shape = sx_box_shape(SX_R(1.0), SX_R(1.0));
    ecs_set_ptr(world, box, SxCollider, &c); /* now overlapping the ground by 0.5 m */
    progress(world, 120, 1.0 / 60.0);
    assert_near(position_of(world, box).y, 1.0, 0.01);
    assert_near(position_of(world, box).x, 0.0, 1e-3);
    /* SxBody.mass 0 means "from the colliders": density 1 gives 4 kg now,
     * so an upward impulse of 4 N s (gravity off) leaves at 1 m/s */
    set_gravity(world, sx_v2(0, 0));
    sx_ecs_apply_impulse(world, box, sx_v2(SX_R(0.0), SX_R(4.0)));
    progress(world, 1, 1.0 / 60.0);
    assert_near(ecs_get(world, box, SxBody)->velocity.y, 1.0, 1e-4);
    ecs_fini(world);
}

/* Two flecs worlds each own their own sepax world: different gravity, and
 * stepping one leaves the other untouched. */
static void two_flecs_worlds_step_independently(void **state) {
    ecs_world_t *a = make_world(), *b = make_world();
    ecs_entity_t ea, eb;
    sx_vec2 b_before;
    const double n = 60.0 * sx_default_world_def().sub_steps, fall = (n + 1.0) / (2.0 * n);
    (void)state;
    set_gravity(b, sx_v2(SX_R(0.0), SX_R(-2.0)));
    ea = add_dynamic(a, sx_v2(0, 0), sx_circle_shape(sx_v2(0, 0), SX_R(0.5)));
    eb = add_dynamic(b, sx_v2(0, 0), sx_circle_shape(sx_v2(0, 0), SX_R(0.5)));
    assert_true(sx_ecs_world(a) != sx_ecs_world(b));
    progress(a, 60, 1.0 / 60.0);
    assert_vec2_near(position_of(b, eb), sx_v2(0, 0), 0.0);
    progress(b, 60, 1.0 / 60.0);
    /* symplectic Euler after n sub-steps of h = 1 s / n:
     * y = -g h^2 n (n + 1) / 2 = -g (n + 1) / (2 n) */
    assert_near(position_of(a, ea).y, -10.0 * fall, 1e-4);
    assert_near(position_of(b, eb).y, -2.0 * fall, 1e-4);
    b_before = position_of(b, eb);
    ecs_fini(a); /* destroying one world leaves the other working */
    progress(b, 1, 1.0 / 60.0);
    assert_true(position_of(b, eb).y < b_before.y);
    ecs_fini(b);
}

/* 10,000 entities (a grid of boxes and balls in free fall, then half of
 * them deleted): every one steps, and ASan's leak check in the SAN=1 build
 * sees nothing left behind. */
static void ten_thousand_entities_step_and_are_deleted_cleanly(void **state) {
    enum { N = 10000 };
    ecs_world_t *world = make_world();
    ecs_entity_t *es = malloc(N * sizeof *es);
    const double sub = sx_default_world_def().sub_steps, n = 3.0 * sub, h = 1.0 / (60.0 * sub);
    int i;
    (void)state;
    assert_non_null(es);
    for (i = 0; i < N; ++i) {
        sx_vec2 p = sx_v2((sx_real)(i % 100) * SX_R(1.5), (sx_real)(i / 100) * SX_R(1.5));
        sx_shape s =
            i % 2 ? sx_box_shape(SX_R(0.4), SX_R(0.4)) : sx_circle_shape(sx_v2(0, 0), SX_R(0.4));
        es[i] = add_dynamic(world, p, s);
    }
    progress(world, 3, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), N);
    /* free fall, nothing touches: n sub-steps of h, -10 h^2 (1 + ... + n) */
    for (i = 0; i < N; ++i)
        assert_near(position_of(world, es[i]).y,
                    (double)(i / 100) * 1.5 - 10.0 * h * h * n * (n + 1.0) / 2.0, 1e-4);
    for (i = 0; i < N; i += 2)
        ecs_delete(world, es[i]);
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), N / 2);
    free(es);
    ecs_fini(world);
}

static void components_are_reflected(void **state) {
    ecs_world_t *world = make_world();
    SxTransform t = {{SX_R(1.5), SX_R(-2.0)}, SX_R(0.5)};
    char *json;
    (void)state;
    json = ecs_ptr_to_json(world, ecs_id(SxTransform), &t);
    assert_non_null(json);
    assert_non_null(strstr(json, "\"position\""));
    assert_non_null(strstr(json, "1.5"));
    ecs_os_free(json);
    ecs_fini(world);
}

static void many_entities_step_and_go_without_leaks(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t es[300];
    sx_test_rng rng = sx_test_rng_make(7);
    int i;
    (void)state;
    add_ground(world);
    for (i = 0; i < 300; ++i) {
        sx_vec2 p = sx_v2(sx_test_rng_range(&rng, -15.0, 15.0), sx_test_rng_range(&rng, 1.0, 40.0));
        sx_shape s =
            i % 2 ? sx_box_shape(SX_R(0.3), SX_R(0.2)) : sx_circle_shape(sx_v2(0, 0), SX_R(0.25));
        es[i] = add_dynamic(world, p, s);
    }
    progress(world, 60, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 301);
    for (i = 0; i < 300; i += 2)
        ecs_delete(world, es[i]);
    progress(world, 30, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 151);
    for (i = 1; i < 300; i += 2) {
        sx_vec2 p = position_of(world, es[i]);
        assert_true(p.y > SX_R(-0.1) && p.y < SX_R(41.0));
    }
    ecs_fini(world);
}

/* ---- concave colliders ------------------------------------------------------ */

/* U outline: floor [-1.5, 1.5] x [0, 0.5], walls up to y = 2, notch
 * [-1, 1] x [0.5, 2]. */
static const double u_outline_xy[] = {-1.5, 0,   1.5, 0,   1.5, 2, 1,    2,
                                      1,    0.5, -1,  0.5, -1,  2, -1.5, 2};

typedef struct part_probe {
    const sx_world *world;
    int parts;
} part_probe;

static bool probe_parts(sx_collider_id collider, sx_body_id body, void *context) {
    part_probe *p = (part_probe *)context;
    (void)body;
    p->parts = sx_collider_get_part_count(p->world, collider);
    return true;
}

static void a_concave_outline_entity_collides_as_one_collider(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t u = ecs_new(world), ball, other;
    SxTransform t = {{SX_R(2.0), SX_R(0.0)}, SX_R(0.0)};
    sx_vec2 pts[8];
    const SxCollider *c;
    const SxContacts *contacts;
    event_log log;
    int i, found = 0;
    part_probe probe;
    sx_world_ray_hit hit;
    sx_ray_input ray;
    (void)state;
    memset(&log, 0, sizeof(log));
    observe(world, &log);
    for (i = 0; i < 8; ++i)
        pts[i] = sx_v2((sx_real)u_outline_xy[2 * i], (sx_real)u_outline_xy[2 * i + 1]);
    ecs_set_ptr(world, u, SxTransform, &t);
    assert_int_equal(sx_ecs_set_outline(world, u, pts, 8, NULL), SX_OK);
    c = ecs_get(world, u, SxCollider);
    assert_non_null(c);
    assert_true(c->part_count >= 3);
    assert_non_null(c->parts);
    /* a ball dropped into the notch (the U sits at x = 2) rests on its floor */
    ball =
        add_dynamic(world, sx_v2(SX_R(2.2), SX_R(3.0)), sx_circle_shape(sx_v2_zero(), SX_R(0.4)));
    log.watch = ball;
    progress(world, 180, 1.0 / 60.0);
    assert_near(position_of(world, ball).y, 0.5 + 0.4, 0.01);
    assert_true(position_of(world, ball).x > SX_R(1.4) && position_of(world, ball).x < SX_R(2.6));
    assert_int_equal(log.begins, 1);
    assert_true(log.last_begin.other == u);
    assert_vec2_near(log.last_begin.normal, sx_v2(SX_R(0.0), SX_R(-1.0)), 1e-3);
    contacts = ecs_singleton_get(world, SxContacts);
    for (i = 0; i < contacts->count; ++i) {
        if (contacts->items[i].entity_a == (u < ball ? u : ball) &&
            contacts->items[i].entity_b == (u < ball ? ball : u)) {
            ++found;
        }
    }
    assert_int_equal(found, 1);
    /* the module's world holds the U as one compound collider: the notch is
     * empty, a wall is solid, and a ray down the notch hits the floor */
    assert_int_equal(
        sx_world_query_point(sx_ecs_world(world), sx_v2(SX_R(2.0), SX_R(1.8)), NULL, NULL), 0);
    probe.world = sx_ecs_world(world);
    probe.parts = 0;
    assert_int_equal(
        sx_world_query_point(sx_ecs_world(world), sx_v2(SX_R(0.7), SX_R(1.8)), probe_parts, &probe),
        1);
    assert_int_equal(probe.parts, c->part_count);
    memset(&ray, 0, sizeof(ray));
    ray.origin = sx_v2(SX_R(1.5), SX_R(5.0));
    ray.translation = sx_v2(SX_R(0.0), SX_R(-10.0));
    ray.max_fraction = SX_R(1.0);
    assert_true(sx_world_cast_ray(sx_ecs_world(world), &ray, &hit));
    assert_near(hit.point.y, 0.5, 1e-4);
    assert_int_equal(sx_collider_get_part_count(sx_ecs_world(world), hit.collider), c->part_count);
    /* cloning the entity deep-copies the parts (each copy owns its own) */
    other = ecs_clone(world, 0, u, true);
    assert_true(ecs_get(world, other, SxCollider)->parts != ecs_get(world, u, SxCollider)->parts);
    assert_int_equal(ecs_get(world, other, SxCollider)->part_count, c->part_count);
    ecs_delete(world, other);
    progress(world, 2, 1.0 / 60.0);
    ecs_fini(world);
}

/* Entities deleted from a query callback of the module's world: the world
 * is locked then, so their bodies and colliders leave it at the next fixed
 * step instead of being refused and left behind. */
typedef struct doom_ctx {
    ecs_world_t *world;
    ecs_entity_t body_entity, static_entity;
    int hits;
} doom_ctx;

static bool delete_entities_on_hit(sx_collider_id collider, sx_body_id body, void *context) {
    doom_ctx *d = (doom_ctx *)context;
    (void)collider;
    (void)body;
    if (d->hits++ == 0) {
        ecs_delete(d->world, d->body_entity);
        /* static geometry losing its collider loses its body too */
        ecs_remove(d->world, d->static_entity, SxCollider);
    }
    return true;
}

static void entities_deleted_in_a_query_callback_leave_the_world_at_the_next_step(void **state) {
    ecs_world_t *world = make_world();
    sx_aabb all = sx_aabb_make(sx_v2(SX_R(-50.0), SX_R(-50.0)), sx_v2(SX_R(50.0), SX_R(50.0)));
    doom_ctx d;
    sx_world *w;
    (void)state;
    memset(&d, 0, sizeof(d));
    d.world = world;
    d.static_entity = add_ground(world);
    d.body_entity =
        add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    add_dynamic(world, sx_v2(SX_R(3.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 2, 1.0 / 60.0);
    w = sx_ecs_world(world);
    assert_int_equal(sx_world_body_count(w), 3);
    assert_int_equal(sx_world_query_aabb(w, all, NULL, NULL), 3);
    assert_int_equal(sx_world_query_aabb(w, all, delete_entities_on_hit, &d), 3);
    assert_false(ecs_is_alive(world, d.body_entity));
    progress(world, 1, 1.0 / 60.0);
    /* the deleted box's body and the ground's are gone */
    assert_int_equal(sx_world_body_count(w), 1);
    assert_int_equal(sx_world_query_aabb(w, all, NULL, NULL), 1);
    progress(world, 2, 1.0 / 60.0);
    assert_int_equal(sx_world_query_aabb(w, all, NULL, NULL), 1);
    ecs_fini(world);
}

/* An L compound given through SxCollider.parts on a dynamic body: the
 * component keeps its own copy, the mass override scales the density, and
 * the L comes to rest on the ground. */
static void a_dynamic_compound_collider_from_parts_rests_on_the_ground(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t e = ecs_new(world);
    sx_compound_part parts[2];
    SxTransform t = {{SX_R(0.0), SX_R(2.0)}, SX_R(0.3)};
    SxBody b = sx_ecs_body(SX_BODY_DYNAMIC);
    SxCollider c = sx_ecs_collider(sx_circle_shape(sx_v2_zero(), SX_R(0.1)));
    sx_compound view;
    sx_aabb box;
    (void)state;
    add_ground(world);
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(1.0), SX_R(0.5)),
                                     sx_xform_make(sx_v2(SX_R(1.0), SX_R(0.5)), SX_R(0.0)));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)),
                                     sx_xform_make(sx_v2(SX_R(0.5), SX_R(1.5)), SX_R(0.0)));
    c.parts = parts;
    c.part_count = 2;
    b.mass = SX_R(6.0);
    ecs_set_ptr(world, e, SxTransform, &t);
    ecs_set_ptr(world, e, SxBody, &b);
    ecs_set_ptr(world, e, SxCollider, &c);
    /* ours can go: the component has its own copy */
    assert_true(ecs_get(world, e, SxCollider)->parts != parts);
    memset(parts, 0, sizeof(parts));
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 2);
    progress(world, 300, 1.0 / 60.0);
    view.parts = ecs_get(world, e, SxCollider)->parts;
    view.count = ecs_get(world, e, SxCollider)->part_count;
    assert_int_equal(view.count, 2);
    t = *ecs_get(world, e, SxTransform);
    box = sx_compound_aabb(&view, sx_xform_make(t.position, t.angle));
    /* resting on the ground's top (y = 0) */
    assert_near(box.lower.y, 0.0, 0.01);
    assert_true(sx_length(ecs_get(world, e, SxBody)->velocity) < SX_R(0.05));
    /* 6 kg, as SxBody.mass asks: 6 N s upward (gravity off) gives 1 m/s */
    set_gravity(world, sx_v2(0, 0));
    sx_ecs_apply_impulse(world, e, sx_v2(SX_R(0.0), SX_R(6.0)));
    progress(world, 1, 1.0 / 60.0);
    assert_near(ecs_get(world, e, SxBody)->velocity.y, 1.0, 1e-3);
    /* removing the collider frees the parts (ASan / the leak check) */
    ecs_remove(world, e, SxCollider);
    progress(world, 1, 1.0 / 60.0);
    ecs_fini(world);
}

/* A wide box across two teeth of a comb entity: the world has one contact
 * per touching part pair, SxContacts one entry for the entity pair. */
static void a_box_on_two_teeth_is_one_sx_contact(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t comb = ecs_new(world), box;
    SxTransform t = {{SX_R(0.0), SX_R(0.0)}, SX_R(0.0)};
    sx_vec2 p[12];
    const SxContacts *contacts;
    int n, i, found = 0, world_pairs = 0;
    (void)state;
    /* a spine [0, 5] x [0, 1] with teeth [0,1], [2,3], [4,5] up to y = 3 */
    n = sx_test_comb_outline(p, 3);
    ecs_set_ptr(world, comb, SxTransform, &t);
    assert_int_equal(sx_ecs_set_outline(world, comb, p, n, NULL), SX_OK);
    box = add_dynamic(world, sx_v2(SX_R(1.5), SX_R(4.0)), sx_box_shape(SX_R(1.2), SX_R(0.5)));
    progress(world, 120, 1.0 / 60.0);
    /* on the teeth, not between them */
    assert_near(position_of(world, box).y, 3.5, 0.01);
    for (i = 0; i < sx_world_contact_count(sx_ecs_world(world)); ++i) {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(sx_ecs_world(world), i, &d), SX_OK);
        if (d.count > 0) ++world_pairs;
    }
    assert_int_equal(world_pairs, 2);
    contacts = ecs_singleton_get(world, SxContacts);
    for (i = 0; i < contacts->count; ++i) {
        if (contacts->items[i].entity_a == comb && contacts->items[i].entity_b == box) {
            ++found;
            assert_int_equal(contacts->items[i].point_count, 4);
            assert_vec2_near(contacts->items[i].normal, sx_v2(SX_R(0.0), SX_R(1.0)), 1e-3);
        }
    }
    assert_int_equal(found, 1);
    ecs_fini(world);
}

/* 70 combs with a wide box on two teeth each (two part contacts a pair)
 * and a box on the ground: the module reads the world's 141 contacts in
 * batches, and one comb pair's two part contacts lie across the first
 * batch's end. SxContacts has one entry per entity pair, each the world's
 * first part contact (normal from entity_a to entity_b, point) with every
 * part's points counted. */
static void sx_contacts_follow_the_world_across_read_batches(void **state) {
    enum { COMBS = 70 };
    ecs_world_t *world = make_world();
    ecs_entity_t combs[COMBS];
    SxTransform t;
    sx_vec2 p[12];
    const SxContacts *contacts;
    sx_world *w;
    int n, i, k, straddling = 0;
    (void)state;
    add_ground(world);
    n = sx_test_comb_outline(p, 3);
    for (i = 0; i < COMBS; ++i) {
        combs[i] = ecs_new(world);
        t.position = sx_v2((sx_real)(7 * i) - SX_R(240.0), SX_R(30.0));
        t.angle = SX_R(0.0);
        ecs_set_ptr(world, combs[i], SxTransform, &t);
        assert_int_equal(sx_ecs_set_outline(world, combs[i], p, n, NULL), SX_OK);
        add_dynamic(world, sx_v2(t.position.x + SX_R(1.5), SX_R(34.0)),
                    sx_box_shape(SX_R(1.2), SX_R(0.5)));
    }
    add_dynamic(world, sx_v2(SX_R(0.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    progress(world, 60, 1.0 / 60.0);
    w = sx_ecs_world(world);
    assert_int_equal(sx_world_contact_count(w), 2 * COMBS + 1);
    contacts = ecs_singleton_get(world, SxContacts);
    assert_int_equal(contacts->count, COMBS + 1);
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data d, next;
        ecs_entity_t a, b;
        const SxContact *c = NULL;
        int points;
        assert_int_equal(sx_world_get_contact(w, i, &d), SX_OK);
        points = d.count;
        if (i + 1 < sx_world_contact_count(w)) {
            assert_int_equal(sx_world_get_contact(w, i + 1, &next), SX_OK);
            if (sx_collider_id_to_u64(next.collider_a) == sx_collider_id_to_u64(d.collider_a) &&
                sx_collider_id_to_u64(next.collider_b) == sx_collider_id_to_u64(d.collider_b)) {
                /* a comb pair's second part contact */
                points += next.count;
                straddling += i == 127;
                ++i;
            }
        }
        a = sx_ecs_entity_of(world, d.body_a);
        b = sx_ecs_entity_of(world, d.body_b);
        for (k = 0; k < contacts->count; ++k) {
            const SxContact *e = &contacts->items[k];
            if (e->entity_a == (a < b ? a : b) && e->entity_b == (a < b ? b : a)) c = e;
        }
        assert_non_null(c);
        assert_int_equal(c->point_count, points);
        assert_memory_equal(&c->point, &d.points[0], sizeof(c->point));
        if (a < b) {
            assert_memory_equal(&c->normal, &d.normal, sizeof(c->normal));
        } else {
            sx_vec2 flipped = sx_neg(d.normal);
            assert_memory_equal(&c->normal, &flipped, sizeof(c->normal));
        }
    }
    /* the scene puts a pair across the module's first batch of 128 */
    assert_int_equal(straddling, 1);
    ecs_fini(world);
}

static void bad_outlines_leave_the_entity_untouched(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t e = ecs_new(world);
    sx_vec2 bowtie[4], pts[8];
    int i;
    (void)state;
    bowtie[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    bowtie[1] = sx_v2(SX_R(1.0), SX_R(1.0));
    bowtie[2] = sx_v2(SX_R(1.0), SX_R(0.0));
    bowtie[3] = sx_v2(SX_R(0.0), SX_R(1.0));
    for (i = 0; i < 8; ++i)
        pts[i] = sx_v2((sx_real)u_outline_xy[2 * i], (sx_real)u_outline_xy[2 * i + 1]);
    assert_int_equal(sx_ecs_set_outline(world, e, bowtie, 4, NULL), SX_ERR_INVALID_ARG);
    pts[3].x = (sx_real)NAN;
    assert_int_equal(sx_ecs_set_outline(world, e, pts, 8, NULL), SX_ERR_NONFINITE);
    pts[3].x = SX_R(1.0);
    assert_int_equal(sx_ecs_set_outline(world, e, pts, 2, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_ecs_set_outline(world, e, NULL, 8, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_ecs_set_outline(NULL, e, pts, 8, NULL), SX_ERR_INVALID_ARG);
    assert_false(ecs_has(world, e, SxCollider));
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_world_body_count(sx_ecs_world(world)), 0);
    /* a base collider's material and sensor flag carry over */
    {
        SxCollider base = sx_ecs_collider(sx_box_shape(SX_R(1.0), SX_R(1.0)));
        base.friction = SX_R(0.25);
        assert_int_equal(sx_ecs_set_outline(world, e, pts, 8, &base), SX_OK);
        assert_near(ecs_get(world, e, SxCollider)->friction, 0.25, 0.0);
        assert_true(ecs_get(world, e, SxCollider)->part_count >= 3);
    }
    ecs_delete(world, e);
    assert_int_equal(sx_ecs_set_outline(world, e, pts, 8, NULL), SX_ERR_INVALID_ARG);
    ecs_fini(world);
}

/* A ray cast through the module's world names the entity it hits, and the
 * entity's body is found the other way; stale and foreign handles give 0. */
static void a_ray_cast_names_the_entity_hit(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t ground = add_ground(world), box;
    sx_ray_input ray;
    sx_world_ray_hit hit;
    sx_body_id body, none = {0, 0};
    (void)state;
    box = add_dynamic(world, sx_v2(SX_R(3.0), SX_R(0.5)), sx_box_shape(SX_R(0.5), SX_R(0.5)));
    assert_true(sx_body_id_is_null(sx_ecs_body_of(world, box))); /* no step yet */
    progress(world, 1, 1.0 / 60.0);
    ray.origin = sx_v2(SX_R(3.0), SX_R(10.0));
    ray.translation = sx_v2(SX_R(0.0), SX_R(-20.0));
    ray.max_fraction = SX_R(1.0);
    assert_true(sx_world_cast_ray(sx_ecs_world(world), &ray, &hit));
    assert_int_equal(sx_ecs_entity_of(world, hit.body), box);
    ray.origin.x = SX_R(-5.0);
    assert_true(sx_world_cast_ray(sx_ecs_world(world), &ray, &hit));
    assert_int_equal(sx_ecs_entity_of(world, hit.body), ground);
    body = sx_ecs_body_of(world, box);
    assert_true(sx_body_is_valid(sx_ecs_world(world), body));
    assert_int_equal(sx_ecs_entity_of(world, body), box);
    assert_int_equal(sx_ecs_entity_of(world, none), 0);
    assert_int_equal(sx_ecs_entity_of(NULL, body), 0);
    assert_true(sx_body_id_is_null(sx_ecs_body_of(NULL, box)));
    ecs_delete(world, box);
    assert_int_equal(sx_ecs_entity_of(world, body), 0); /* stale */
    assert_true(sx_body_id_is_null(sx_ecs_body_of(world, box)));
    ecs_fini(world);
}

/* SxPhysicsTime: after frames of 1/100 s at a 1/60 s fixed step the
 * accumulator holds the fraction a renderer interpolates by. */
static void the_interpolation_fraction_is_the_accumulator_over_the_step(void **state) {
    ecs_world_t *world = make_world();
    const SxPhysicsTime *t;
    double acc = 0.0, fixed = 1.0 / 60.0;
    int64_t total = 0;
    int i;
    (void)state;
    for (i = 0; i < 25; ++i) {
        int32_t n = 0;
        ecs_progress(world, (ecs_ftime_t)0.01);
        acc += (double)(ecs_ftime_t)0.01;
        while (acc + 1e-6 * fixed >= fixed) {
            acc -= fixed;
            ++n;
        }
        if (acc < 0.0) acc = 0.0;
        total += n;
        t = ecs_singleton_get(world, SxPhysicsTime);
        assert_non_null(t);
        assert_int_equal(t->frame_steps, n);
        assert_int_equal(t->steps, total);
        assert_true(t->alpha >= SX_R(0.0) && t->alpha < SX_R(1.0));
        assert_near(t->alpha, acc / fixed, 1e-4);
    }
    assert_int_equal(sx_ecs_step_count(world), total);
    ecs_fini(world);
}

/* Iterations set in SxPhysicsSettings reach the world: the module's run is
 * bit for bit a plain world created with the same counts; refused counts
 * leave the world's as they were. */
static void settings_iterations_reach_the_world(void **state) {
    ecs_world_t *world = make_world();
    sx_world_def def = sx_default_world_def(), got;
    sx_world *plain;
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ground, ids[2];
    ecs_entity_t es[2];
    SxPhysicsSettings *s;
    int frame, i;
    (void)state;
    def.sub_steps = 2;
    def.velocity_iterations = 9;
    def.position_iterations = 0;
    plain = sx_world_create(&def);
    assert_non_null(plain);
    s = ecs_singleton_ensure(world, SxPhysicsSettings);
    s->sub_steps = 2;
    s->velocity_iterations = 9;
    s->position_iterations = 0;
    add_ground(world);
    bd.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    assert_int_equal(sx_body_create(plain, &bd, &ground), SX_OK);
    cd.shape = sx_box_shape(SX_R(20.0), SX_R(1.0));
    assert_int_equal(sx_collider_create(plain, ground, &cd, NULL), SX_OK);
    for (i = 0; i < 2; ++i) {
        sx_vec2 p = sx_v2(SX_R(0.2) * (sx_real)i, SX_R(0.5) + SX_R(1.5) * (sx_real)i);
        es[i] = add_dynamic(world, p, sx_box_shape(SX_R(0.5), SX_R(0.5)));
        bd.type = SX_BODY_DYNAMIC;
        bd.position = p;
        assert_int_equal(sx_body_create(plain, &bd, &ids[i]), SX_OK);
        cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
        assert_int_equal(sx_collider_create(plain, ids[i], &cd, NULL), SX_OK);
    }
    for (frame = 0; frame < 90; ++frame) {
        ecs_progress(world, (ecs_ftime_t)DT);
        assert_int_equal(sx_world_step(plain, DT), SX_OK);
    }
    for (i = 0; i < 2; ++i) {
        sx_vec2 p = sx_body_get_position(plain, ids[i]);
        assert_memory_equal(&ecs_get(world, es[i], SxTransform)->position, &p, sizeof(p));
    }
    assert_int_equal(sx_world_get_def(sx_ecs_world(world), &got), SX_OK);
    assert_int_equal(got.velocity_iterations, 9);
    assert_int_equal(got.position_iterations, 0);
    s = ecs_singleton_ensure(world, SxPhysicsSettings);
    s->velocity_iterations = 0;
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_world_get_def(sx_ecs_world(world), &got), SX_OK);
    assert_int_equal(got.velocity_iterations, 9);
    sx_world_destroy(plain);
    ecs_fini(world);
}

/* SxPhysicsSettings.enable_continuous starts as the world's default (on)
 * and a change reaches the world at the next frame. */
static void settings_continuous_reaches_the_world(void **state) {
    ecs_world_t *world = make_world();
    sx_world_def got;
    (void)state;
    assert_true(ecs_singleton_get(world, SxPhysicsSettings)->enable_continuous);
    ecs_singleton_ensure(world, SxPhysicsSettings)->enable_continuous = false;
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_world_get_def(sx_ecs_world(world), &got), SX_OK);
    assert_false(got.enable_continuous);
    ecs_singleton_ensure(world, SxPhysicsSettings)->enable_continuous = true;
    progress(world, 1, 1.0 / 60.0);
    assert_int_equal(sx_world_get_def(sx_ecs_world(world), &got), SX_OK);
    assert_true(got.enable_continuous);
    ecs_fini(world);
}

/* A bullet entity (SxBody.bullet) knocked into a thin dynamic box by a fast
 * ball stops at the box, as in the plain world; ray and shape casts through
 * the module return the entity they hit. */
static void bullet_flag_and_casts_through_the_module(void **state) {
    ecs_world_t *world = make_world();
    ecs_entity_t box, ball, shooter, ground;
    SxBody *b;
    sx_ray_input ray;
    sx_world_ray_hit rh;
    sx_world_shape_hit sh;
    sx_shape probe = sx_circle_shape(sx_v2_zero(), SX_R(0.1));
    int k;
    (void)state;
    set_gravity(world, sx_v2_zero());
    ground = add_ground(world);
    box = add_dynamic(world, sx_v2(SX_R(0.0), SX_R(3.0)), sx_box_shape(SX_R(0.025), SX_R(1.0)));
    ball =
        add_dynamic(world, sx_v2(SX_R(-1.0), SX_R(3.0)), sx_circle_shape(sx_v2_zero(), SX_R(0.05)));
    shooter =
        add_dynamic(world, sx_v2(SX_R(-1.5), SX_R(3.0)), sx_circle_shape(sx_v2_zero(), SX_R(0.05)));
    b = ecs_get_mut(world, ball, SxBody);
    b->bullet = true;
    b = ecs_get_mut(world, shooter, SxBody);
    b->bullet = true;
    b->velocity = sx_v2(SX_R(300.0), SX_R(0.0));
    progress(world, 1, 1.0 / 60.0);
    assert_true(sx_body_is_bullet(sx_ecs_world(world), sx_ecs_body_of(world, ball)));
    assert_false(sx_body_is_bullet(sx_ecs_world(world), sx_ecs_body_of(world, box)));
    for (k = 0; k < 10; ++k) {
        sx_vec2 d;
        progress(world, 1, 1.0 / 60.0);
        d = sx_xform_inv_point(
            sx_body_get_transform(sx_ecs_world(world), sx_ecs_body_of(world, box)),
            position_of(world, ball));
        assert_true((double)d.x < -0.075 + 0.01);
    }
    /* casts: straight down onto the ground, and sideways onto the box */
    ray.origin = sx_v2(SX_R(5.0), SX_R(10.0));
    ray.translation = sx_v2(SX_R(0.0), SX_R(-20.0));
    ray.max_fraction = SX_R(1.0);
    assert_true(sx_ecs_cast_ray(world, &ray, &rh) == ground);
    assert_near(rh.point.y, 0.0, 1e-4);
    assert_true(sx_ecs_cast_shape(world, &probe,
                                  sx_xform_make(sx_v2(SX_R(5.0), SX_R(10.0)), SX_R(0.0)),
                                  sx_v2(SX_R(0.0), SX_R(-20.0)), NULL, &sh) == ground);
    assert_near(sh.point.y, 0.0, 1e-4);
    ray.translation = sx_v2(SX_R(0.0), SX_R(5.0));
    assert_true(sx_ecs_cast_ray(world, &ray, &rh) == 0);
    assert_false(rh.fraction != SX_R(0.0));
    assert_true(sx_ecs_cast_shape(world, NULL, sx_xform_identity(), sx_v2_zero(), NULL, &sh) == 0);
    ecs_fini(world);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_falls_onto_static_ground_and_comes_to_rest),
        cmocka_unit_test(ball_bounce_is_bit_identical_to_the_plain_world),
        cmocka_unit_test(fixed_tick_runs_whole_steps_and_stages_once_per_sub_step),
        cmocka_unit_test(a_long_frame_runs_at_most_max_steps_and_drops_the_rest),
        cmocka_unit_test(sub_steps_beyond_the_limit_run_no_step),
        cmocka_unit_test(contact_begin_and_end_reach_observers_exactly_once),
        cmocka_unit_test(a_ball_through_a_sensor_gives_one_sensor_begin_and_end),
        cmocka_unit_test(teleport_and_velocity_writes_take_effect_at_the_next_step),
        cmocka_unit_test(resting_bodies_sleep_and_a_velocity_write_wakes_them),
        cmocka_unit_test(deleting_entities_in_the_middle_of_contacts_is_safe),
        cmocka_unit_test(bodies_without_colliders_and_colliders_without_bodies_work),
        cmocka_unit_test(impulse_helper_and_mass_override),
        cmocka_unit_test(setting_a_new_shape_on_a_resting_body_takes_effect),
        cmocka_unit_test(two_flecs_worlds_step_independently),
        cmocka_unit_test(ten_thousand_entities_step_and_are_deleted_cleanly),
        cmocka_unit_test(components_are_reflected),
        cmocka_unit_test(many_entities_step_and_go_without_leaks),
        cmocka_unit_test(a_concave_outline_entity_collides_as_one_collider),
        cmocka_unit_test(a_dynamic_compound_collider_from_parts_rests_on_the_ground),
        cmocka_unit_test(a_box_on_two_teeth_is_one_sx_contact),
        cmocka_unit_test(sx_contacts_follow_the_world_across_read_batches),
        cmocka_unit_test(bad_outlines_leave_the_entity_untouched),
        cmocka_unit_test(a_ray_cast_names_the_entity_hit),
        cmocka_unit_test(the_interpolation_fraction_is_the_accumulator_over_the_step),
        cmocka_unit_test(settings_iterations_reach_the_world),
        cmocka_unit_test(settings_continuous_reaches_the_world),
        cmocka_unit_test(entities_deleted_in_a_query_callback_leave_the_world_at_the_next_step),
        cmocka_unit_test(bullet_flag_and_casts_through_the_module),
        cmocka_unit_test(contacts_come_sorted_when_the_tables_mix_the_entities),
    };
    return cmocka_run_group_tests_name("ecs", tests, sx_test_group_setup, sx_test_group_teardown);
}
