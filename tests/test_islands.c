/* sepax tests — what the step skips: sleeping islands (a pyramid that wakes
 * when hit and sleeps again, per-body sleep switch, every force and impulse
 * waking its body's island), the collision filter's
 * truth table, sensors that never push, and a sleeping world that costs no
 * contacts in the solver's list. */
#include <limits.h>
#include <stdio.h>

#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))

static sx_body_id add_body(sx_world *w, sx_body_type type, sx_vec2 p, const sx_shape *shape,
                           bool enable_sleep) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    bd.type = type;
    bd.position = p;
    bd.enable_sleep = enable_sleep;
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    cd.shape = *shape;
    assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    return id;
}

/* Steps until nothing is awake or `max_steps` ran; returns the steps run. */
static int step_until_asleep(sx_world *w, int max_steps) {
    int s;
    for (s = 0; s < max_steps && sx_world_awake_body_count(w) > 0; ++s)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    return s;
}

/* ---- sleeping ------------------------------------------------------------- */

#define BASE 6
#define PYRAMID (BASE * (BASE + 1) / 2)

/* A ground 40 m wide with its top at y = 0 and a pyramid of BASE unit boxes
 * on it, 5 cm apart in a row; ids (NULL: not kept) gets the boxes bottom
 * row first. */
static void add_pyramid(sx_world *w, sx_body_id *ids) {
    sx_shape ground = sx_box_shape(SX_R(20.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    int row, col, n = 0;
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, true);
    for (row = 0; row < BASE; ++row) {
        for (col = 0; col < BASE - row; ++col) {
            sx_real x = SX_R(1.05) * ((sx_real)col - SX_R(0.5) * (sx_real)(BASE - row - 1));
            sx_body_id id =
                add_body(w, SX_BODY_DYNAMIC, sx_v2(x, SX_R(0.5) + (sx_real)row), &box, true);
            if (ids != NULL) ids[n++] = id;
        }
    }
}

static void sleeping_pyramid_wakes_when_a_ball_hits_it_and_sleeps_again(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.3));
    sx_body_id ids[PYRAMID], b;
    sx_world *w;
    int steps, i, woken = 0;
    double top_y;
    (void)state;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_pyramid(w, ids);
    steps = step_until_asleep(w, 600);
    printf("  pyramid of %d asleep after %d steps\n", PYRAMID, steps);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    top_y = (double)sx_body_get_position(w, ids[PYRAMID - 1]).y;
    /* the sleeping pyramid's contacts are kept but solved no more */
    assert_true(sx_world_contact_count(w) >= PYRAMID);

    /* a ball thrown at the bottom row's left box */
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-8.0), SX_R(0.5)), &ball, true);
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(6.0), SX_R(0.0))), SX_OK);
    for (i = 0; i < 120 && woken < PYRAMID; ++i) {
        int k, awake = 0;
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        for (k = 0; k < PYRAMID; ++k)
            awake += sx_body_is_awake(w, ids[k]) ? 1 : 0;
        if (awake > woken) woken = awake;
    }
    /* the hit (after about 1 s of flight) wakes the whole island at once,
     * not only the box it touched */
    assert_int_equal(woken, PYRAMID);
    assert_true(i > 50 && i < 80);
    steps = step_until_asleep(w, 1200);
    printf("  hit at 6 m/s: all %d boxes woke at step %d; asleep again %d steps later; top box "
           "moved %.4f m\n",
           PYRAMID, i, steps, fabs((double)sx_body_get_position(w, ids[PYRAMID - 1]).y - top_y));
    assert_int_equal(sx_world_awake_body_count(w), 0);
    assert_true(steps > 10);
    /* a 0.3 m ball at 6 m/s pushes the base; the pyramid must still stand */
    assert_near(sx_body_get_position(w, ids[PYRAMID - 1]).y, top_y, 0.05);
    sx_world_destroy(w);
}

/* Reads the whole contact list with sx_world_get_contact_pairs in batches
 * of `batch` from `first` on and checks each pair against
 * sx_world_get_contact; returns how many it read. */
static int pairs_match_full_reads(const sx_world *w, int first, int batch) {
    sx_contact_pair got[5];
    int n = sx_world_contact_count(w), i = first, k;
    while (i < n) {
        int read = sx_world_get_contact_pairs(w, i, got, batch);
        assert_int_equal(read, n - i < batch ? n - i : batch);
        for (k = 0; k < read; ++k) {
            sx_contact_data d;
            assert_int_equal(sx_world_get_contact(w, i + k, &d), SX_OK);
            assert_true(sx_body_id_to_u64(got[k].body_a) == sx_body_id_to_u64(d.body_a));
            assert_true(sx_body_id_to_u64(got[k].body_b) == sx_body_id_to_u64(d.body_b));
            assert_true(sx_collider_id_to_u64(got[k].collider_a) ==
                        sx_collider_id_to_u64(d.collider_a));
            assert_true(sx_collider_id_to_u64(got[k].collider_b) ==
                        sx_collider_id_to_u64(d.collider_b));
            assert_int_equal(got[k].part_a, d.part_a);
            assert_int_equal(got[k].part_b, d.part_b);
            assert_int_equal(got[k].count, d.count);
            assert_memory_equal(&got[k].normal, &d.normal, sizeof(d.normal));
            assert_memory_equal(&got[k].points[0], &d.points[0], sizeof(d.points[0]));
            if (d.count == 2) {
                assert_memory_equal(&got[k].points[1], &d.points[1], sizeof(d.points[1]));
            }
        }
        i += read;
    }
    return i - first;
}

/* The light read walks the same list as sx_world_get_contact, the frozen
 * contacts of a sleeping pile and the tombstones of a destroyed body
 * included, and answers bad arguments with 0. */
static void the_light_contact_read_walks_the_list_of_the_full_one(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_compound_part parts[2];
    sx_compound dumbbell;
    sx_collider_def cd = sx_default_collider_def();
    sx_body_def bd = sx_default_body_def();
    sx_body_id ids[PYRAMID], bar;
    sx_contact_pair out[2];
    sx_world *w;
    int count, i, parted = 0;
    (void)state;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_pyramid(w, ids);
    assert_int_equal(step_until_asleep(w, 600) < 600, true);
    /* a compound that stays awake beside the sleeping pyramid: two part
     * pairs with the ground, listed one after the other */
    parts[0].shape = sx_box_shape(SX_R(0.3), SX_R(0.3));
    parts[0].offset = sx_xform_make(sx_v2(SX_R(-1.0), SX_R(0.0)), SX_R(0.0));
    parts[1].shape = sx_circle_shape(sx_v2_zero(), SX_R(0.3));
    parts[1].offset = sx_xform_make(sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.0));
    dumbbell.parts = parts;
    dumbbell.count = 2;
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(10.0), SX_R(0.35));
    bd.enable_sleep = false;
    assert_int_equal(sx_create_body(w, &bd, &bar), SX_OK);
    assert_int_equal(sx_body_add_compound(w, bar, &dumbbell, &cd, NULL), SX_OK);
    for (i = 0; i < 30; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    count = sx_world_contact_count(w);
    assert_true(count >= PYRAMID + 2);
    for (i = 0; i < count; ++i) {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(w, i, &d), SX_OK);
        parted += d.part_a + d.part_b > 0;
    }
    assert_true(parted >= 1);
    assert_int_equal(pairs_match_full_reads(w, 0, 5), count);
    assert_int_equal(pairs_match_full_reads(w, 3, 2), count - 3);
    assert_int_equal(pairs_match_full_reads(w, count - 1, 5), 1);
    /* a destroyed box (the first: its contacts lead the list) leaves
     * tombstones in the sleeping contacts until the next collide: the light
     * read skips them as the full one does */
    assert_int_equal(sx_destroy_body(w, ids[0]), SX_OK);
    assert_true(sx_world_contact_count(w) < count);
    count = sx_world_contact_count(w);
    for (i = 0; i < count; i += 3)
        assert_int_equal(pairs_match_full_reads(w, i, 4), count - i);
    /* bad arguments */
    assert_int_equal(sx_world_get_contact_pairs(NULL, 0, out, 2), 0);
    assert_int_equal(sx_world_get_contact_pairs(w, 0, NULL, 2), 0);
    assert_int_equal(sx_world_get_contact_pairs(w, 0, out, 0), 0);
    assert_int_equal(sx_world_get_contact_pairs(w, 0, out, -1), 0);
    assert_int_equal(sx_world_get_contact_pairs(w, -1, out, 2), 0);
    assert_int_equal(sx_world_get_contact_pairs(w, count, out, 2), 0);
    assert_int_equal(sx_world_get_contact_pairs(w, INT_MAX, out, 2), 0);
    sx_world_destroy(w);
}

/* A pile that falls asleep whole keeps every contact, in the same order,
 * with the impulses of its last solve (what it warm-starts from when it
 * wakes): the store takes the step's list over when most of it freezes. */
static void a_pile_falling_asleep_keeps_every_contact_and_its_impulses(void **state) {
    sx_world_def def = sx_default_world_def();
    static sx_contact_data before[4 * PYRAMID], after;
    sx_world *w;
    int s, i, count = 0;
    (void)state;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_pyramid(w, NULL);
    for (s = 0; s < 600 && sx_world_awake_body_count(w) > 0; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        count = sx_world_contact_count(w);
        assert_true(count <= 4 * PYRAMID);
        for (i = 0; i < count; ++i)
            assert_int_equal(sx_world_get_contact(w, i, &before[i]), SX_OK);
    }
    assert_int_equal(sx_world_awake_body_count(w), 0);
    assert_true(count >= PYRAMID);
    /* the next collide moves them into the store */
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(w), count);
    for (i = 0; i < count; ++i) {
        assert_int_equal(sx_world_get_contact(w, i, &after), SX_OK);
        assert_int_equal(after.collider_a.index, before[i].collider_a.index);
        assert_int_equal(after.collider_b.index, before[i].collider_b.index);
        assert_int_equal(after.count, before[i].count);
        assert_true(after.normal_impulses[0] == before[i].normal_impulses[0]);
        assert_true(after.tangent_impulses[0] == before[i].tangent_impulses[0]);
        assert_true(after.normal_impulses[1] == before[i].normal_impulses[1]);
    }
    sx_world_destroy(w);
}

static void a_body_with_sleep_off_keeps_its_island_awake(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id a, b, c, lone;
    sx_world *w;
    (void)state;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, true);
    a = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-2.0), SX_R(0.5)), &box, true);
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-2.0), SX_R(1.5)), &box, false);
    c = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-2.0), SX_R(2.5)), &box, true);
    lone = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(2.0), SX_R(0.5)), &box, true);
    assert_false(sx_body_is_sleep_enabled(w, b));
    assert_true(sx_body_is_sleep_enabled(w, a));
    step_until_asleep(w, 300);
    /* b never sleeps and neither do a and c, which touch it; the lone box,
     * on another island, does */
    assert_true(sx_body_is_awake(w, a));
    assert_true(sx_body_is_awake(w, b));
    assert_true(sx_body_is_awake(w, c));
    assert_false(sx_body_is_awake(w, lone));
    assert_int_equal(sx_body_set_sleep_enabled(w, b, true), SX_OK);
    assert_true(step_until_asleep(w, 300) < 300);
    assert_false(sx_body_is_awake(w, b));
    /* forbidding sleep wakes the body (and its island) */
    assert_int_equal(sx_body_set_sleep_enabled(w, c, false), SX_OK);
    assert_true(sx_body_is_awake(w, c));
    assert_true(sx_body_is_awake(w, a));
    /* bad input */
    assert_int_equal(sx_body_set_sleep_enabled(NULL, c, true), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_destroy_body(w, lone), SX_OK);
    assert_int_equal(sx_body_set_sleep_enabled(w, lone, true), SX_ERR_STALE_HANDLE);
    assert_false(sx_body_is_sleep_enabled(w, lone));
    assert_false(sx_body_is_sleep_enabled(NULL, a));
    sx_world_destroy(w);
}

/* A body faster than the sleep speeds never counts towards sleep: a ball
 * thrown up at 10 m/s (2 s of flight, four times time_to_sleep) stays
 * awake all the way, and is back on the ground when it lands, not frozen
 * in the air. Only then, at rest, does it fall asleep. */
static void a_ball_in_flight_longer_than_time_to_sleep_stays_awake(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5)), ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_world *w;
    sx_body_id b;
    int s;
    (void)state;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, true);
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &ball, true);
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(0.0), SX_R(10.0))), SX_OK);
    /* up for 1 s, 5 m high, and down for 1 s */
    for (s = 0; s < 115; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        assert_true(sx_body_is_awake(w, b));
    }
    assert_true(step_until_asleep(w, 300) < 300);
    assert_near(sx_body_get_position(w, b).y, 0.5, 0.01);
    sx_world_destroy(w);
}

/* The time to sleep counts from the body's last motion: a ball in zero
 * gravity rests 0.4 s (of the 0.5 s time_to_sleep), moves at 1 m/s for
 * 0.5 s and stops; it must rest another full 0.5 s before it sleeps, not
 * the 0.1 s left from before it moved. */
static void the_time_to_sleep_counts_from_the_last_motion(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_world *w;
    sx_body_id b;
    int s;
    (void)state;
    def.gravity = sx_v2_zero();
    w = sx_world_create(&def);
    assert_non_null(w);
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &ball, true);
    for (s = 0; s < 24; ++s)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_true(sx_body_is_awake(w, b));
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(1.0), SX_R(0.0))), SX_OK);
    for (s = 0; s < 30; ++s)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2_zero()), SX_OK);
    /* 0.4 s at rest again: still awake; by 0.6 s asleep */
    for (s = 0; s < 24; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        assert_true(sx_body_is_awake(w, b));
    }
    for (s = 0; s < 12; ++s)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_false(sx_body_is_awake(w, b));
    sx_world_destroy(w);
}

/* Positional correction moves bodies out of an overlap without giving them
 * speed, so a body being pushed out looks at rest by its speeds; it must
 * not sleep before the overlap is gone. A column of five boxes, each half
 * inside the next and the bottom one half inside the ground, takes several
 * seconds to come apart (about 6 s, test_hostile.c); when the world has
 * fallen asleep, every contact is within twice the slop, the depth at
 * which the sleep test stops counting an overlap as being pushed out. */
static void bodies_pushed_out_of_a_deep_overlap_do_not_sleep_before_it_is_gone(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_shape ground = sx_box_shape(SX_R(10.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_world *w;
    int i, k, steps;
    double deepest = 0.0;
    (void)state;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground, true);
    for (i = 0; i < 5; ++i)
        add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5) * (sx_real)i), &box, true);
    steps = step_until_asleep(w, 1200);
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data c;
        assert_int_equal(sx_world_get_contact(w, i, &c), SX_OK);
        for (k = 0; k < c.count; ++k)
            if ((double)c.depths[k] > deepest) deepest = (double)c.depths[k];
    }
    printf("  column of 5 boxes half inside each other: asleep after %d steps, deepest contact "
           "then %.5f m (slop %.4f)\n",
           steps, deepest, (double)sx_world_linear_slop(w));
    assert_true(steps < 1200);
    assert_true(deepest <= 2.0 * (double)sx_world_linear_slop(w));
    sx_world_destroy(w);
}

/* Each way of pushing a body: force, force at a point, torque, impulse,
 * impulse at a point, angular impulse. */
enum { PUSH_FORCE, PUSH_FORCE_AT, PUSH_TORQUE, PUSH_IMPULSE, PUSH_IMPULSE_AT, PUSH_ANGULAR, PUSHES };

static sx_status push(sx_world *w, sx_body_id b, int how) {
    /* off the centre by 0.4 m, so the pushes at a point also turn it */
    sx_vec2 at = sx_add(sx_body_get_world_center(w, b), sx_v2(SX_R(0.4), SX_R(0.0)));
    switch (how) {
    case PUSH_FORCE: return sx_body_apply_force(w, b, sx_v2(SX_R(0.0), SX_R(120.0)));
    case PUSH_FORCE_AT: return sx_body_apply_force_at_point(w, b, sx_v2(SX_R(0.0), SX_R(120.0)), at);
    case PUSH_TORQUE: return sx_body_apply_torque(w, b, SX_R(60.0));
    case PUSH_IMPULSE: return sx_body_apply_impulse(w, b, sx_v2(SX_R(0.0), SX_R(3.0)));
    case PUSH_IMPULSE_AT:
        return sx_body_apply_impulse_at_point(w, b, sx_v2(SX_R(0.0), SX_R(3.0)), at);
    default: return sx_body_apply_angular_impulse(w, b, SX_R(1.0));
    }
}

/* A force or an impulse on a sleeping body wakes it, and its island, at
 * once: a sleeping body is skipped by the step, so a push left on it would
 * wait (or be lost) until something else woke it. The top box of a
 * sleeping two-box stack is pushed up or turned; right after the call both
 * boxes are awake, and one step later the push shows (the top box moved up
 * by more than 1 cm or turned by more than 0.01 rad: every push above gives
 * at least 1 m/s or 1 rad/s within the step). */
static void every_force_and_impulse_wakes_a_sleeping_body_and_its_island(void **state) {
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    int how;
    (void)state;
    for (how = 0; how < PUSHES; ++how) {
        sx_world_def def = sx_default_world_def();
        sx_world *w = sx_world_create(&def);
        sx_body_id bottom, top;
        sx_vec2 p0;
        sx_real a0;
        assert_non_null(w);
        add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, true);
        bottom = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box, true);
        top = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.5)), &box, true);
        assert_true(step_until_asleep(w, 300) < 300);
        assert_false(sx_body_is_awake(w, top));
        assert_false(sx_body_is_awake(w, bottom));
        p0 = sx_body_get_position(w, top);
        a0 = sx_body_get_angle(w, top);
        assert_int_equal(push(w, top, how), SX_OK);
        assert_true(sx_body_is_awake(w, top));
        assert_true(sx_body_is_awake(w, bottom));
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        assert_true(sx_body_get_position(w, top).y - p0.y > SX_R(0.01) ||
                    sx_absr(sx_body_get_angle(w, top) - a0) > SX_R(0.01));
        sx_world_destroy(w);
    }
}

/* ---- filtering ------------------------------------------------------------ */

typedef struct filter_case {
    uint32_t cat_a, mask_a, cat_b, mask_b;
    int32_t group_a, group_b;
    bool collide;
} filter_case;

static void filter_truth_table_decides_every_pair(void **state) {
    static const filter_case cases[] = {
        /* categories and masks: both sides must accept the other */
        {1u, 0xFFFFFFFFu, 2u, 0xFFFFFFFFu, 0, 0, true},
        {1u, 0xFFFFFFFFu & ~2u, 2u, 0xFFFFFFFFu, 0, 0, false},
        {1u, 0xFFFFFFFFu, 2u, 0xFFFFFFFFu & ~1u, 0, 0, false},
        {1u, 2u, 2u, 1u, 0, 0, true},
        {1u, 0u, 2u, 0xFFFFFFFFu, 0, 0, false},
        {0u, 0xFFFFFFFFu, 2u, 0xFFFFFFFFu, 0, 0, false},
        /* same negative group: never, even when the masks accept */
        {1u, 0xFFFFFFFFu, 2u, 0xFFFFFFFFu, -4, -4, false},
        /* same positive group: always, even when the masks refuse */
        {1u, 0u, 2u, 0u, 7, 7, true},
        /* different groups, or one group 0: the masks decide */
        {1u, 0xFFFFFFFFu, 2u, 0xFFFFFFFFu, -4, -5, true},
        {1u, 0u, 2u, 0xFFFFFFFFu, -4, -5, false},
        {1u, 0xFFFFFFFFu, 2u, 0xFFFFFFFFu, 7, 0, true},
        {1u, 0u, 2u, 0xFFFFFFFFu, 7, 8, false},
    };
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    size_t i;
    (void)state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); ++i) {
        const filter_case *fc = &cases[i];
        sx_world_def def = sx_default_world_def();
        sx_body_def bd = sx_default_body_def();
        sx_collider_def cd = sx_default_collider_def();
        sx_body_id a, b;
        sx_world *w;
        def.gravity = sx_v2_zero();
        w = sx_world_create(&def);
        assert_non_null(w);
        bd.type = SX_BODY_DYNAMIC;
        cd.shape = box;
        assert_int_equal(sx_create_body(w, &bd, &a), SX_OK);
        cd.filter.category = fc->cat_a;
        cd.filter.mask = fc->mask_a;
        cd.filter.group = fc->group_a;
        assert_int_equal(sx_body_add_collider(w, a, &cd, NULL), SX_OK);
        bd.position = sx_v2(SX_R(0.6), SX_R(0.0)); /* 0.4 m overlap */
        assert_int_equal(sx_create_body(w, &bd, &b), SX_OK);
        cd.filter.category = fc->cat_b;
        cd.filter.mask = fc->mask_b;
        cd.filter.group = fc->group_b;
        assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_OK);
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        if (fc->collide) {
            assert_int_equal(sx_world_contact_count(w), 1);
            /* the contact pushes them apart */
            assert_true(sx_body_get_position(w, a).x < SX_R(0.0));
            assert_true(sx_body_get_position(w, b).x > SX_R(0.6));
        } else {
            assert_int_equal(sx_world_contact_count(w), 0);
            assert_true(sx_body_get_linear_velocity(w, a).x == SX_R(0.0));
            assert_true(sx_body_get_position(w, b).x == SX_R(0.6));
        }
        sx_world_destroy(w);
    }
}

static void sensors_report_but_never_push(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_shape zone = sx_box_shape(SX_R(2.0), SX_R(2.0)),
             ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id z, balls[3];
    sx_world *w;
    int i, s, begins = 0;
    (void)state;
    def.gravity = sx_v2_zero();
    w = sx_world_create(&def);
    assert_non_null(w);
    /* a dynamic body whose only collider is a sensor: it must neither push
     * nor be pushed */
    bd.type = SX_BODY_DYNAMIC;
    assert_int_equal(sx_create_body(w, &bd, &z), SX_OK);
    cd.shape = zone;
    cd.sensor = true;
    assert_int_equal(sx_body_add_collider(w, z, &cd, NULL), SX_OK);
    for (i = 0; i < 3; ++i) {
        balls[i] = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-5.0), SX_R(1.5) * (sx_real)(i - 1)),
                            &ball, true);
        assert_int_equal(sx_body_set_linear_velocity(w, balls[i], sx_v2(SX_R(2.0), SX_R(0.0))),
                         SX_OK);
    }
    for (s = 0; s < 300; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        begins += sx_world_get_sensor_events(w).begin_count;
        assert_int_equal(sx_world_contact_count(w), 0);
    }
    assert_int_equal(begins, 3);
    for (i = 0; i < 3; ++i) {
        /* straight through at the same speed */
        assert_true(sx_body_get_linear_velocity(w, balls[i]).x == SX_R(2.0));
        assert_true(sx_body_get_linear_velocity(w, balls[i]).y == SX_R(0.0));
    }
    assert_true(sx_body_get_linear_velocity(w, z).x == SX_R(0.0));
    assert_true(sx_body_get_position(w, z).x == SX_R(0.0));
    sx_world_destroy(w);
}

/* ---- what the world does not use costs nothing -------------------------- */

static void contact_events_are_built_only_when_asked(void **state) {
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    int pass;
    (void)state;
    for (pass = 0; pass < 2; ++pass) {
        sx_world_def def = sx_default_world_def();
        sx_world *w;
        int s, begins = 0, contacts = 0;
        assert_true(def.enable_contact_events);
        def.enable_contact_events = pass == 0;
        w = sx_world_create(&def);
        assert_non_null(w);
        add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, true);
        add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.0)), &box, true);
        for (s = 0; s < 60; ++s) {
            assert_int_equal(sx_world_step(w, DT), SX_OK);
            begins += sx_world_get_contact_events(w).begin_count;
            contacts = sx_world_contact_count(w);
        }
        /* the box lands either way; only the events differ */
        assert_int_equal(contacts, 1);
        assert_int_equal(begins, pass == 0 ? 1 : 0);
        sx_world_destroy(w);
    }
}

/* A pile that falls asleep keeps its contacts and reports no end event;
 * woken by a box falling on it (a wake in the middle of the collide) or by
 * the caller (before the collide), its contacts come back without a begin
 * event: only the new touch begins. */
static void a_sleeping_pile_reports_no_end_and_no_begin_when_it_wakes(void **state) {
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_world_def def = sx_default_world_def();
    sx_world *w = sx_world_create(&def);
    sx_body_id lower, upper, falling;
    sx_contact_events e;
    int s, begins = 0, ends = 0, steps;
    (void)state;
    assert_non_null(w);
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground, true);
    lower = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box, true);
    upper = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.5)), &box, true);
    for (s = 0; s < 5; ++s)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 2);
    /* asleep: no end events, both contacts kept */
    for (steps = 0; steps < 600 && sx_world_awake_body_count(w) > 0; ++steps) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        ends += sx_world_get_contact_events(w).end_count;
    }
    assert_int_equal(sx_world_awake_body_count(w), 0);
    assert_int_equal(ends, 0);
    assert_int_equal(sx_world_contact_count(w), 2);
    /* the caller wakes the pile: the two contacts are back, no event */
    assert_int_equal(sx_body_set_awake(w, upper, true), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    e = sx_world_get_contact_events(w);
    assert_int_equal(e.begin_count + e.end_count, 0);
    assert_int_equal(sx_world_contact_count(w), 2);
    for (steps = 0; steps < 600 && sx_world_awake_body_count(w) > 0; ++steps)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    /* a box falls on the sleeping pile and wakes it as the collide meets it */
    falling = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.2), SX_R(3.0)), &box, true);
    for (s = 0; s < 120; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        e = sx_world_get_contact_events(w);
        begins += e.begin_count;
        ends += e.end_count;
    }
    /* one touch began (the falling box on the upper box), none ended */
    assert_int_equal(begins, 1);
    assert_int_equal(ends, 0);
    assert_int_equal(sx_world_contact_count(w), 3);
    assert_true(sx_body_get_position(w, falling).y < SX_R(2.6));
    (void)lower;
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_sleeping_pile_reports_no_end_and_no_begin_when_it_wakes),
        cmocka_unit_test(sleeping_pyramid_wakes_when_a_ball_hits_it_and_sleeps_again),
        cmocka_unit_test(a_pile_falling_asleep_keeps_every_contact_and_its_impulses),
        cmocka_unit_test(the_light_contact_read_walks_the_list_of_the_full_one),
        cmocka_unit_test(a_body_with_sleep_off_keeps_its_island_awake),
        cmocka_unit_test(every_force_and_impulse_wakes_a_sleeping_body_and_its_island),
        cmocka_unit_test(a_ball_in_flight_longer_than_time_to_sleep_stays_awake),
        cmocka_unit_test(the_time_to_sleep_counts_from_the_last_motion),
        cmocka_unit_test(bodies_pushed_out_of_a_deep_overlap_do_not_sleep_before_it_is_gone),
        cmocka_unit_test(filter_truth_table_decides_every_pair),
        cmocka_unit_test(sensors_report_but_never_push),
        cmocka_unit_test(contact_events_are_built_only_when_asked),
    };
    return cmocka_run_group_tests_name("islands", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
