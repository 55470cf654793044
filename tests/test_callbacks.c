/* sepax tests — user code called back by the world (query callbacks and the
 * debug draw) that turns around and changes the world. The world is locked
 * while a callback runs: creating and destroying bodies and colliders and
 * the step answer SX_ERR_LOCKED, everything else works, in every kind of
 * callback alike; destroying the world from a callback waits for the walk
 * to return. Under SAN=1 these scenes read freed memory before the lock
 * existed (a collider array grown by a draw callback, a compound's parts
 * freed under the draw loop), and a query whose callback created a collider
 * per hit never ended. */
#include <string.h>

#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))

static sx_world *make_world(void) {
    sx_world_def def = sx_default_world_def();
    sx_world *w = sx_world_create(&def);
    assert_non_null(w);
    return w;
}

static int count_colliders(const sx_world *w) {
    sx_aabb all = sx_aabb_make(sx_v2(SX_R(-1e4), SX_R(-1e4)), sx_v2(SX_R(1e4), SX_R(1e4)));
    return sx_world_query_aabb(w, all, NULL, NULL);
}

/* ---- a draw callback that adds colliders ----------------------------------- */

typedef struct adder {
    sx_world *w;
    sx_body_id body;
    int calls;
    int refused;
    int boxes;
} adder;

static void add_on_draw(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                        void *context) {
    adder *a = (adder *)context;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id made;
    (void)xf;
    (void)type;
    (void)sensor;
    /* the shape handed over must still be readable (ASan checks) */
    assert_int_equal(sx_shape_validate(shape), SX_OK);
    /* bounded: without the lock every call made one more collider to draw */
    if (++a->calls > 64) return;
    cd.shape = sx_box_shape(SX_R(0.25), SX_R(0.25));
    if (sx_body_add_collider(a->w, a->body, &cd, &made) == SX_ERR_LOCKED) {
        assert_false(sx_collider_is_valid(a->w, made));
        a->refused++;
    }
}

static void count_box_on_draw(sx_aabb box, void *context) {
    assert_true(sx_aabb_is_valid(box));
    ((adder *)context)->boxes++;
}

static void draw_callback_adding_colliders_is_refused_and_reads_nothing_freed(void **state) {
    sx_world *w = make_world();
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_debug_draw dd;
    adder a;
    int i;
    (void)state;
    memset(&a, 0, sizeof(a));
    /* 16 colliders fill the collider array's first capacity: one more
     * would move it while the draw loop holds a pointer into it */
    for (i = 0; i < 16; ++i)
        a.body = sx_test_body(w, SX_BODY_STATIC, sx_v2((sx_real)(2 * i), SX_R(0.0)), box, NULL);
    a.w = w;
    memset(&dd, 0, sizeof(dd));
    dd.draw_shape = add_on_draw;
    /* drawn after the shape, from the collider the shape's callback saw */
    dd.draw_aabb = count_box_on_draw;
    dd.context = &a;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(a.calls, 16);
    assert_int_equal(a.boxes, 16);
    assert_int_equal(a.refused, 16);
    assert_int_equal(count_colliders(w), 16);
    assert_false(sx_world_is_locked(w));
    /* outside the walk the same call works */
    {
        sx_collider_def cd = sx_default_collider_def();
        assert_int_equal(sx_body_add_collider(w, a.body, &cd, NULL), SX_OK);
        assert_int_equal(count_colliders(w), 17);
    }
    sx_world_destroy(w);
}

/* ---- a draw callback that destroys the compound it draws ------------------- */

typedef struct destroyer {
    sx_world *w;
    sx_body_id body;
    int parts_drawn;
    sx_status status;
} destroyer;

static void destroy_on_draw(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                            void *context) {
    destroyer *d = (destroyer *)context;
    (void)xf;
    (void)type;
    (void)sensor;
    assert_int_equal(sx_shape_validate(shape), SX_OK);
    if (d->parts_drawn++ == 0) d->status = sx_destroy_body(d->w, d->body);
}

static void draw_callback_destroying_a_compound_body_is_refused(void **state) {
    sx_world *w = make_world();
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_compound_part parts[3];
    sx_compound comp;
    sx_debug_draw dd;
    destroyer d;
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        parts[i] =
            sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)),
                                  sx_xform_make(sx_v2((sx_real)(2 * i), SX_R(0.0)), SX_R(0.0)));
    }
    comp.parts = parts;
    comp.count = 3;
    bd.type = SX_BODY_DYNAMIC;
    memset(&d, 0, sizeof(d));
    assert_int_equal(sx_create_body(w, &bd, &d.body), SX_OK);
    assert_int_equal(sx_body_add_compound(w, d.body, &comp, &cd, NULL), SX_OK);
    d.w = w;
    memset(&dd, 0, sizeof(dd));
    dd.draw_shape = destroy_on_draw;
    dd.context = &d;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(d.status, SX_ERR_LOCKED);
    assert_int_equal(d.parts_drawn, 3);
    assert_true(sx_body_is_valid(w, d.body));
    assert_int_equal(sx_destroy_body(w, d.body), SX_OK);
    assert_int_equal(sx_world_body_count(w), 0);
    sx_world_destroy(w);
}

/* ---- a query callback that creates a collider on every hit ----------------- */

typedef struct breeder {
    sx_world *w;
    int hits;
    int refused;
} breeder;

static bool breed_on_hit(sx_collider_id collider, sx_body_id body, void *context) {
    breeder *b = (breeder *)context;
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id made;
    (void)collider;
    (void)body;
    /* bounded: without the lock the query found each new collider and
     * made another one, for ever */
    if (++b->hits > 100) return false;
    bd.position = sx_v2((sx_real)b->hits, SX_R(0.0));
    if (sx_create_body(b->w, &bd, &made) == SX_ERR_LOCKED) {
        assert_true(sx_body_id_is_null(made));
        b->refused++;
        return true;
    }
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_add_collider(b->w, made, &cd, NULL);
    return true;
}

static void query_callback_creating_colliders_ends_and_sees_none_of_them(void **state) {
    sx_world *w = make_world();
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_aabb area = sx_aabb_make(sx_v2(SX_R(-1.0), SX_R(-1.0)), sx_v2(SX_R(200.0), SX_R(1.0)));
    breeder b;
    int i;
    (void)state;
    for (i = 0; i < 3; ++i)
        sx_test_body(w, SX_BODY_STATIC, sx_v2((sx_real)(3 * i), SX_R(0.0)), box, NULL);
    memset(&b, 0, sizeof(b));
    b.w = w;
    assert_int_equal(sx_world_query_aabb(w, area, breed_on_hit, &b), 3);
    assert_int_equal(b.hits, 3);
    assert_int_equal(b.refused, 3);
    assert_int_equal(sx_world_body_count(w), 3);
    sx_world_destroy(w);
}

/* ---- every callback, every call ---------------------------------------------- */

typedef struct prober {
    sx_world *w;
    sx_body_id dynamic, ground;
    sx_collider_id dynamic_collider;
    int probes;
} prober;

/* Each mutating entry point, from inside a callback: the structural ones
 * and the step refuse and change nothing; the others work. */
static void probe_world(prober *p) {
    sx_world *w = p->w;
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_compound_part part =
        sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), sx_xform_identity());
    sx_compound comp;
    sx_vec2 outline[4];
    sx_body_id made;
    sx_collider_id made_collider;
    int bodies = sx_world_body_count(w), colliders = count_colliders(w);
    sx_vec2 where = sx_body_get_position(w, p->dynamic);
    comp.parts = &part;
    comp.count = 1;
    outline[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    outline[1] = sx_v2(SX_R(1.0), SX_R(0.0));
    outline[2] = sx_v2(SX_R(1.0), SX_R(1.0));
    outline[3] = sx_v2(SX_R(0.0), SX_R(1.0));
    p->probes++;
    assert_true(sx_world_is_locked(w));

    assert_int_equal(sx_create_body(w, &bd, &made), SX_ERR_LOCKED);
    assert_int_equal(sx_body_add_collider(w, p->dynamic, &cd, &made_collider), SX_ERR_LOCKED);
    assert_int_equal(sx_body_add_compound(w, p->dynamic, &comp, &cd, NULL), SX_ERR_LOCKED);
    assert_int_equal(sx_body_add_outline(w, p->dynamic, outline, 4, &cd, NULL), SX_ERR_LOCKED);
    assert_int_equal(sx_destroy_collider(w, p->dynamic_collider), SX_ERR_LOCKED);
    assert_int_equal(sx_destroy_body(w, p->dynamic), SX_ERR_LOCKED);
    assert_int_equal(sx_destroy_body(w, p->ground), SX_ERR_LOCKED);
    assert_int_equal(sx_world_step(w, DT), SX_ERR_LOCKED);
    assert_int_equal(sx_world_apply_forces(w, DT), SX_ERR_LOCKED);
    assert_int_equal(sx_world_collide(w), SX_ERR_LOCKED);
    assert_int_equal(sx_world_solve(w, DT), SX_ERR_LOCKED);
    assert_int_equal(sx_world_integrate(w, DT), SX_ERR_LOCKED);
    assert_int_equal(sx_world_separate(w, DT), SX_ERR_LOCKED);
    assert_int_equal(sx_world_clear_forces(w), SX_ERR_LOCKED);
    assert_int_equal(sx_world_update_sleep(w, DT), SX_ERR_LOCKED);
    assert_int_equal(sx_world_body_count(w), bodies);
    assert_int_equal(count_colliders(w), colliders);
    assert_true(sx_collider_is_valid(w, p->dynamic_collider));
    /* nothing moved: the step did not run */
    assert_true(sx_body_get_position(w, p->dynamic).x == where.x &&
                sx_body_get_position(w, p->dynamic).y == where.y);

    assert_int_equal(sx_body_apply_force(w, p->dynamic, sx_v2(SX_R(1.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_apply_impulse(w, p->dynamic, sx_v2(SX_R(0.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_apply_torque(w, p->dynamic, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, p->dynamic, sx_v2(SX_R(0.0), SX_R(0.0))),
                     SX_OK);
    assert_int_equal(sx_body_set_angular_velocity(w, p->dynamic, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_body_set_transform(w, p->dynamic, where, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_body_set_awake(w, p->dynamic, true), SX_OK);
    assert_int_equal(sx_body_set_sleep_enabled(w, p->dynamic, true), SX_OK);
    assert_int_equal(sx_body_set_type(w, p->dynamic, SX_BODY_DYNAMIC), SX_OK);
    assert_int_equal(sx_world_set_gravity(w, sx_v2(SX_R(0.0), SX_R(-10.0))), SX_OK);
    assert_int_equal(sx_world_clear_events(w), SX_OK);
    /* a nested query runs, and its end does not unlock the outer walk */
    assert_int_equal(sx_world_query_point(w, where, NULL, NULL), 1);
    assert_true(sx_world_is_locked(w));
}

static bool probe_on_hit(sx_collider_id collider, sx_body_id body, void *context) {
    (void)collider;
    (void)body;
    probe_world((prober *)context);
    return true;
}

static void probe_on_shape(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                           void *context) {
    (void)shape;
    (void)xf;
    (void)type;
    (void)sensor;
    probe_world((prober *)context);
}

static void probe_on_contact(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context) {
    (void)point;
    (void)normal;
    (void)depth;
    probe_world((prober *)context);
}

static void probe_on_aabb(sx_aabb box, void *context) {
    (void)box;
    probe_world((prober *)context);
}

/* Counts the hits of the inner query run from an outer callback. */
static bool nested_probe(sx_collider_id collider, sx_body_id body, void *context) {
    prober *p = (prober *)context;
    sx_aabb all = sx_aabb_make(sx_v2(SX_R(-100.0), SX_R(-100.0)), sx_v2(SX_R(100.0), SX_R(100.0)));
    (void)collider;
    (void)body;
    /* the inner query calls back too: still locked in it and after it */
    assert_int_equal(sx_world_query_aabb(p->w, all, probe_on_hit, p), 2);
    assert_true(sx_world_is_locked(p->w));
    return false;
}

static void every_callback_refuses_structure_and_the_step_and_allows_the_rest(void **state) {
    sx_world *w = make_world();
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_aabb all = sx_aabb_make(sx_v2(SX_R(-100.0), SX_R(-100.0)), sx_v2(SX_R(100.0), SX_R(100.0)));
    sx_debug_draw dd;
    prober p;
    int i;
    (void)state;
    memset(&p, 0, sizeof(p));
    p.w = w;
    p.ground = sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), ground, NULL);
    p.dynamic =
        sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), box, &p.dynamic_collider);
    for (i = 0; i < 5; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_true(sx_world_contact_count(w) > 0);
    assert_false(sx_world_is_locked(w));
    assert_false(sx_world_is_locked(NULL));

    assert_int_equal(sx_world_query_aabb(w, all, probe_on_hit, &p), 2);
    assert_int_equal(p.probes, 2);
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(0.0), SX_R(0.5)), probe_on_hit, &p), 1);
    assert_int_equal(p.probes, 3);
    assert_int_equal(sx_world_query_shape(w, &box, sx_xform_identity(), probe_on_hit, &p), 2);
    assert_int_equal(p.probes, 5);
    memset(&dd, 0, sizeof(dd));
    dd.context = &p;
    dd.draw_shape = probe_on_shape;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(p.probes, 7);
    dd.draw_shape = NULL;
    dd.draw_aabb = probe_on_aabb;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(p.probes, 9);
    dd.draw_aabb = NULL;
    dd.draw_contact = probe_on_contact;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_true(p.probes > 9);
    p.probes = 0;
    assert_int_equal(sx_world_query_aabb(w, all, nested_probe, &p), 1);
    assert_int_equal(p.probes, 2);

    /* unlocked again: the world steps, and the calls refused before work */
    assert_false(sx_world_is_locked(w));
    for (i = 0; i < 5; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_destroy_body(w, p.dynamic), SX_OK);
    assert_int_equal(sx_world_body_count(w), 1);
    sx_world_destroy(w);
}

/* ---- destroying the world from a callback ------------------------------------ */

typedef struct ender {
    sx_world *w;
    int calls;
    bool nested;
} ender;

static bool end_on_hit(sx_collider_id collider, sx_body_id body, void *context) {
    ender *e = (ender *)context;
    (void)collider;
    (void)body;
    e->calls++;
    if (e->nested) {
        sx_aabb all =
            sx_aabb_make(sx_v2(SX_R(-100.0), SX_R(-100.0)), sx_v2(SX_R(100.0), SX_R(100.0)));
        e->nested = false;
        /* the inner query's callback destroys the world: both walks stop */
        assert_int_equal(sx_world_query_aabb(e->w, all, end_on_hit, e), 1);
        /* still readable until the outer walk returns */
        assert_int_equal(sx_world_body_count(e->w), 5);
        return true;
    }
    sx_world_destroy(e->w);
    assert_true(sx_world_is_locked(e->w));
    return true;
}

static void end_on_contact(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context) {
    ender *e = (ender *)context;
    (void)point;
    (void)normal;
    (void)depth;
    e->calls++;
    sx_world_destroy(e->w);
}

static sx_world *five_boxes(void) {
    sx_world *w = make_world();
    sx_shape ground = sx_box_shape(SX_R(20.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    int i;
    sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), ground, NULL);
    for (i = 0; i < 4; ++i)
        sx_test_body(w, SX_BODY_DYNAMIC, sx_v2((sx_real)(2 * i), SX_R(0.5)), box, NULL);
    for (i = 0; i < 3; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    return w;
}

static void world_destroyed_in_a_callback_goes_when_the_walk_returns(void **state) {
    size_t before = sx_live_bytes();
    sx_aabb all = sx_aabb_make(sx_v2(SX_R(-100.0), SX_R(-100.0)), sx_v2(SX_R(100.0), SX_R(100.0)));
    sx_debug_draw dd;
    ender e;
    (void)state;

    memset(&e, 0, sizeof(e));
    e.w = five_boxes();
    /* the walk stops at the first hit: no callback on a dying world */
    assert_int_equal(sx_world_query_aabb(e.w, all, end_on_hit, &e), 1);
    assert_int_equal(e.calls, 1);
    assert_int_equal(sx_live_bytes(), before);

    memset(&e, 0, sizeof(e));
    e.w = five_boxes();
    e.nested = true;
    assert_int_equal(sx_world_query_aabb(e.w, all, end_on_hit, &e), 1);
    assert_int_equal(e.calls, 2);
    assert_int_equal(sx_live_bytes(), before);

    memset(&e, 0, sizeof(e));
    e.w = five_boxes();
    assert_true(sx_world_contact_count(e.w) >= 4);
    memset(&dd, 0, sizeof(dd));
    dd.draw_contact = end_on_contact;
    dd.context = &e;
    assert_int_equal(sx_world_draw(e.w, &dd), SX_OK);
    assert_int_equal(e.calls, 1);
    assert_int_equal(sx_live_bytes(), before);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(draw_callback_adding_colliders_is_refused_and_reads_nothing_freed),
        cmocka_unit_test(draw_callback_destroying_a_compound_body_is_refused),
        cmocka_unit_test(query_callback_creating_colliders_ends_and_sees_none_of_them),
        cmocka_unit_test(every_callback_refuses_structure_and_the_step_and_allows_the_rest),
        cmocka_unit_test(world_destroyed_in_a_callback_goes_when_the_walk_returns),
    };
    return cmocka_run_group_tests_name("callbacks", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
