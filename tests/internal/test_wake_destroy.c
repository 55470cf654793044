/* sepax tests — waking and destroying in worlds of many sleeping islands.
 *
 * A white-box test: besides the public answers (who is awake, which
 * contacts remain), it reads the world's private layout to check that each
 * sleeping island's chain (which a wake walks instead of every body slot)
 * holds exactly the island's members, so a wake visits the island's bodies
 * and no other. The worlds hold hundreds of stacks of one to four boxes, so
 * that an island chain crossing another or a contact removed from the wrong
 * body shows; bodies are destroyed in a scattered order, asleep and awake,
 * with steps in between, and every contact left is checked against the
 * list before each destruction. */
#include <stdlib.h>
#include <string.h>

#include "../../src/world_body.h"
#include "../../src/world_internal.h"
#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))
#define STACKS 100
#define MAX_HEIGHT 4
#define MAX_BODIES (STACKS * MAX_HEIGHT)

typedef struct stacks_world {
    sx_world *w;
    sx_body_id ground;
    sx_body_id bodies[MAX_BODIES];
    int stack_of[MAX_BODIES];
    int count;
} stacks_world;

/* Stacks of 1..MAX_HEIGHT unit boxes (height 1 + k % MAX_HEIGHT) 2 m apart
 * on one static ground, stepped until all sleep: one island per stack. */
static void build_stacks(stacks_world *s) {
    sx_world_def wd = sx_default_world_def();
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    int k, row, steps;
    memset(s, 0, sizeof(*s));
    s->w = sx_world_create(&wd);
    assert_non_null(s->w);
    bd.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    assert_int_equal(sx_create_body(s->w, &bd, &s->ground), SX_OK);
    cd.shape = sx_box_shape(SX_R(2.0) * STACKS, SX_R(1.0));
    assert_int_equal(sx_body_add_collider(s->w, s->ground, &cd, NULL), SX_OK);
    bd.type = SX_BODY_DYNAMIC;
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
    for (k = 0; k < STACKS; ++k) {
        for (row = 0; row < 1 + k % MAX_HEIGHT; ++row) {
            bd.position = sx_v2((sx_real)(2 * k - STACKS), (sx_real)(0.5 + row));
            assert_int_equal(sx_create_body(s->w, &bd, &s->bodies[s->count]), SX_OK);
            assert_int_equal(sx_body_add_collider(s->w, s->bodies[s->count], &cd, NULL), SX_OK);
            s->stack_of[s->count++] = k;
        }
    }
    for (steps = 0; steps < 600 && sx_world_awake_body_count(s->w) > 0; ++steps)
        assert_int_equal(sx_world_step(s->w, DT), SX_OK);
    assert_int_equal(sx_world_awake_body_count(s->w), 0);
}

/* Every sleeping body's island chain, walked from the root, holds exactly
 * the live sleeping bodies of that island, each once. Returns the number of
 * sleeping islands. */
static int check_island_chains(const sx_world *w) {
    int i, islands = 0;
    int *seen = (int *)calloc((size_t)w->body_slots, sizeof(int));
    assert_non_null(seen);
    for (i = 0; i < w->body_slots; ++i) {
        const sx_body_info *info = &w->infos[i];
        int members = 0, walked = 0, j;
        if (!info->alive || w->sims[i].awake || info->island < 0 || info->island != i) continue;
        /* i is a root: its chain against a scan of every slot */
        ++islands;
        for (j = 0; j < w->body_slots; ++j) {
            if (w->infos[j].alive && !w->sims[j].awake && w->infos[j].island == i) ++members;
        }
        for (j = i; j >= 0; j = w->infos[j].island_next) {
            assert_true(w->infos[j].alive);
            assert_false(w->sims[j].awake);
            assert_int_equal(w->infos[j].island, i);
            assert_int_equal(seen[j]++, 0);
            ++walked;
        }
        assert_int_equal(walked, members);
    }
    /* every sleeping body with an island was reached from its root */
    for (i = 0; i < w->body_slots; ++i) {
        if (w->infos[i].alive && !w->sims[i].awake && w->infos[i].island >= 0) {
            assert_int_equal(seen[i], 1);
        }
    }
    free(seen);
    return islands;
}

/* A contact as the public API names it. */
typedef struct contact_key {
    uint64_t a, b;
    int part_a, part_b;
} contact_key;

static int key_cmp(const void *pa, const void *pb) {
    const contact_key *x = (const contact_key *)pa, *y = (const contact_key *)pb;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    if (x->part_a != y->part_a) return x->part_a < y->part_a ? -1 : 1;
    if (x->part_b != y->part_b) return x->part_b < y->part_b ? -1 : 1;
    return 0;
}

/* The world's contacts, sorted; each between live bodies and colliders.
 * *bodies_a/_b (may be NULL) get each contact's bodies in the same order. */
static int snapshot(const sx_world *w, contact_key *keys, sx_body_id *bodies_a,
                    sx_body_id *bodies_b, int capacity) {
    int n = sx_world_contact_count(w), i;
    assert_true(n <= capacity);
    for (i = 0; i < n; ++i) {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(w, i, &d), SX_OK);
        assert_true(sx_body_is_valid(w, d.body_a) && sx_body_is_valid(w, d.body_b));
        assert_true(sx_collider_is_valid(w, d.collider_a) && sx_collider_is_valid(w, d.collider_b));
        assert_true(d.count >= 1 && d.count <= 2);
        keys[i].a = sx_collider_id_to_u64(d.collider_a);
        keys[i].b = sx_collider_id_to_u64(d.collider_b);
        keys[i].part_a = d.part_a;
        keys[i].part_b = d.part_b;
        if (bodies_a != NULL) bodies_a[i] = d.body_a;
        if (bodies_b != NULL) bodies_b[i] = d.body_b;
    }
    {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(w, n, &d), SX_ERR_INVALID_ARG);
    }
    return n;
}

static void sort_keys(contact_key *keys, int n) {
    qsort(keys, (size_t)n, sizeof(contact_key), key_cmp);
}

#define MAX_CONTACTS (4 * MAX_BODIES)

static void waking_one_body_wakes_exactly_its_island(void **state) {
    stacks_world *s = (stacks_world *)malloc(sizeof(stacks_world));
    int i, target = -1, other = -1, contacts;
    (void)state;
    assert_non_null(s);
    build_stacks(s);
    assert_int_equal(check_island_chains(s->w), STACKS);
    contacts = sx_world_contact_count(s->w);
    /* the ground under each stack, and a box on each box */
    assert_int_equal(contacts, s->count);
    /* the middle box of a stack of three, and the top of a stack of four */
    for (i = 0; i < s->count; ++i) {
        if (target < 0 && s->stack_of[i] == 42 && i > 0 && s->stack_of[i - 1] == 42) target = i;
        if (other < 0 && s->stack_of[i] == 71 && i + 1 < s->count && s->stack_of[i + 1] != 71)
            other = i;
    }
    assert_true(target >= 0 && other >= 0);
    assert_int_equal(sx_body_set_awake(s->w, s->bodies[target], true), SX_OK);
    assert_int_equal(
        sx_body_set_linear_velocity(s->w, s->bodies[other], sx_v2(SX_R(0.0), SX_R(0.0))), SX_OK);
    for (i = 0; i < s->count; ++i) {
        bool woken = s->stack_of[i] == 42 || s->stack_of[i] == 71;
        assert_int_equal(sx_body_is_awake(s->w, s->bodies[i]), woken);
    }
    assert_int_equal(sx_world_awake_body_count(s->w), 3 + 4);
    assert_int_equal(check_island_chains(s->w), STACKS - 2);
    /* the woken stacks take their contacts back, the others keep theirs */
    assert_int_equal(sx_world_step(s->w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(s->w), contacts);
    assert_int_equal(sx_world_awake_body_count(s->w), 3 + 4);
    for (i = 0; i < 60 && sx_world_awake_body_count(s->w) > 0; ++i)
        assert_int_equal(sx_world_step(s->w, DT), SX_OK);
    assert_int_equal(check_island_chains(s->w), STACKS);
    /* a new gravity wakes every island */
    assert_int_equal(sx_world_set_gravity(s->w, sx_v2(SX_R(0.0), SX_R(-9.0))), SX_OK);
    assert_int_equal(sx_world_awake_body_count(s->w), s->count);
    assert_int_equal(check_island_chains(s->w), 0);
    assert_int_equal(sx_world_step(s->w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(s->w), contacts);
    sx_world_destroy(s->w);
    free(s);
}

/* Destroys bodies in a scattered order, asleep or awake, with steps in
 * between; after each destruction the contacts are exactly those before
 * minus the destroyed body's, and exactly the bodies of its island and
 * those it touched woke. */
static void destroying_in_any_order_removes_exactly_the_bodys_contacts(void **state) {
    stacks_world *s = (stacks_world *)malloc(sizeof(stacks_world));
    contact_key *before = (contact_key *)malloc(MAX_CONTACTS * sizeof(contact_key));
    contact_key *after = (contact_key *)malloc(MAX_CONTACTS * sizeof(contact_key));
    sx_body_id *ba = (sx_body_id *)malloc(MAX_CONTACTS * sizeof(sx_body_id));
    sx_body_id *bb = (sx_body_id *)malloc(MAX_CONTACTS * sizeof(sx_body_id));
    bool *gone = (bool *)calloc(MAX_BODIES, sizeof(bool));
    bool *may_wake = (bool *)calloc(MAX_BODIES, sizeof(bool));
    bool *was_awake = (bool *)calloc(MAX_BODIES, sizeof(bool));
    int k, destroyed = 0;
    (void)state;
    assert_true(s != NULL && before != NULL && after != NULL && ba != NULL && bb != NULL &&
                gone != NULL && may_wake != NULL && was_awake != NULL);
    build_stacks(s);
    for (k = 0; k < s->count; k += 2) {
        /* 37 is prime to the body count: a scattered order over all stacks */
        int victim = (int)(((long)k * 37) % s->count), n, m, i, expected = 0, island;
        uint32_t slot;
        if (gone[victim]) continue;
        n = snapshot(s->w, before, ba, bb, MAX_CONTACTS);
        slot = s->bodies[victim].index;
        /* who may wake: the victim's island and whoever touches it */
        island = s->w->infos[slot].island;
        for (i = 0; i < s->count; ++i) {
            if (gone[i]) continue;
            was_awake[i] = sx_body_is_awake(s->w, s->bodies[i]);
            may_wake[i] = island >= 0 && s->w->infos[s->bodies[i].index].island == island;
        }
        for (i = 0; i < n; ++i) {
            int j;
            if (ba[i].index != slot && bb[i].index != slot) continue;
            for (j = 0; j < s->count; ++j) {
                if (!gone[j] &&
                    (s->bodies[j].index == ba[i].index || s->bodies[j].index == bb[i].index)) {
                    may_wake[j] = true;
                }
            }
        }
        assert_int_equal(sx_destroy_body(s->w, s->bodies[victim]), SX_OK);
        gone[victim] = true;
        ++destroyed;
        assert_int_equal(sx_world_body_count(s->w), 1 + s->count - destroyed);
        /* what is left: the old list without the victim's contacts */
        for (i = 0; i < n; ++i) {
            if (ba[i].index == slot || bb[i].index == slot) continue;
            before[expected++] = before[i];
        }
        m = snapshot(s->w, after, NULL, NULL, MAX_CONTACTS);
        assert_int_equal(m, expected);
        sort_keys(before, expected);
        sort_keys(after, m);
        assert_memory_equal(before, after, (size_t)m * sizeof(contact_key));
        /* its island and what it touched woke (they may fall), and no one
         * else */
        for (i = 0; i < s->count; ++i) {
            if (gone[i]) continue;
            assert_int_equal(sx_body_is_awake(s->w, s->bodies[i]), was_awake[i] || may_wake[i]);
        }
        check_island_chains(s->w);
        /* now and then a step: the woken stacks' contacts go back to the
         * step's list, so later victims are found there too */
        if (destroyed % 8 == 0) assert_int_equal(sx_world_step(s->w, DT), SX_OK);
    }
    assert_true(destroyed > s->count / 3);
    for (k = 0; k < 300 && sx_world_awake_body_count(s->w) > 0; ++k)
        assert_int_equal(sx_world_step(s->w, DT), SX_OK);
    assert_int_equal(sx_world_awake_body_count(s->w), 0);
    check_island_chains(s->w);
    snapshot(s->w, after, NULL, NULL, MAX_CONTACTS);
    sx_world_destroy(s->w);
    free(s);
    free(before);
    free(after);
    free(ba);
    free(bb);
    free(gone);
    free(may_wake);
    free(was_awake);
}

/* A square of half-extent `half` at p. */
static sx_body_id add_box(sx_world *w, sx_body_type type, sx_vec2 p, sx_real half) {
    return sx_test_body(w, type, p, sx_box_shape(half, half), NULL);
}

typedef struct point_count {
    int points;
} point_count;

static void count_point(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context) {
    (void)point;
    (void)normal;
    (void)depth;
    ((point_count *)context)->points++;
}

/* A destruction between collide and solve (the stages run by hand, as the
 * flecs module does): the destroyed body's contacts must not reach the
 * solver, not even through a new body in the same slot. */
static void stages_after_a_destroy_never_use_its_contacts(void **state) {
    sx_world_def wd = sx_default_world_def();
    sx_world *w;
    sx_body_id ground, a, b, fresh;
    sx_debug_draw dd;
    point_count pc;
    int i, points = 0;
    (void)state;
    wd.gravity = sx_v2(SX_R(0.0), SX_R(-10.0));
    w = sx_world_create(&wd);
    assert_non_null(w);
    ground = add_box(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-5.0)), SX_R(5.0));
    a = add_box(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-2.0), SX_R(0.5)), SX_R(0.5));
    b = add_box(w, SX_BODY_DYNAMIC, sx_v2(SX_R(2.0), SX_R(0.5)), SX_R(0.5));
    for (i = 0; i < 10; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_apply_forces(w, DT / 4), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 2);
    assert_int_equal(sx_destroy_body(w, a), SX_OK);
    /* one contact left, seen alike by the getters and the debug draw */
    assert_int_equal(sx_world_contact_count(w), 1);
    {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(w, 0, &d), SX_OK);
        assert_true(sx_body_id_to_u64(d.body_a) == sx_body_id_to_u64(b) ||
                    sx_body_id_to_u64(d.body_b) == sx_body_id_to_u64(b));
        points = d.count;
        assert_int_equal(sx_world_get_contact(w, 1, &d), SX_ERR_INVALID_ARG);
    }
    memset(&dd, 0, sizeof(dd));
    memset(&pc, 0, sizeof(pc));
    dd.draw_contact = count_point;
    dd.context = &pc;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(pc.points, points);
    /* a new body takes the freed slot, far away and at rest */
    {
        sx_body_def bd = sx_default_body_def();
        bd.type = SX_BODY_DYNAMIC;
        bd.position = sx_v2(SX_R(50.0), SX_R(50.0));
        bd.gravity_scale = SX_R(0.0);
        assert_int_equal(sx_create_body(w, &bd, &fresh), SX_OK);
        assert_int_equal(fresh.index, a.index);
    }
    assert_int_equal(sx_world_solve(w, DT / 4), SX_OK);
    assert_int_equal(sx_world_integrate(w, DT / 4), SX_OK);
    assert_int_equal(sx_world_separate(w, DT / 4), SX_OK);
    assert_true(sx_body_get_linear_velocity(w, fresh).x == SX_R(0.0) &&
                sx_body_get_linear_velocity(w, fresh).y == SX_R(0.0));
    assert_true(sx_body_get_angular_velocity(w, fresh) == SX_R(0.0));
    assert_true(sx_body_get_position(w, fresh).x == SX_R(50.0) &&
                sx_body_get_position(w, fresh).y == SX_R(50.0));
    /* b still rests on the ground */
    assert_near(sx_body_get_position(w, b).y, 0.5, 0.01);
    assert_int_equal(sx_world_clear_forces(w), SX_OK);
    assert_int_equal(sx_world_update_sleep(w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 1);
    (void)ground;
    sx_world_destroy(w);
}

/* Destroying, moving or retyping the static body a sleeping crowd rests on
 * wakes the crowd (and no one on another ground); destroying one collider
 * of a body removes that collider's contacts only. */
static void moving_a_ground_wakes_its_crowd_and_a_collider_takes_only_its_contacts(void **state) {
    sx_world_def wd = sx_default_world_def();
    sx_world *w;
    sx_body_id left, right, middle, crowd[3][40], twin;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id second;
    int side, i, steps, n;
    (void)state;
    w = sx_world_create(&wd);
    assert_non_null(w);
    left = add_box(w, SX_BODY_STATIC, sx_v2(SX_R(-100.0), SX_R(-50.0)), SX_R(50.0));
    right = add_box(w, SX_BODY_STATIC, sx_v2(SX_R(100.0), SX_R(-50.0)), SX_R(50.0));
    middle = add_box(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-200.0)), SX_R(50.0));
    for (side = 0; side < 3; ++side) {
        for (i = 0; i < 40; ++i) {
            sx_real x = (sx_real)((side == 0 ? -140 : side == 1 ? 60 : -40) + 2 * i);
            crowd[side][i] = add_box(w, SX_BODY_DYNAMIC,
                                     sx_v2(x, side == 2 ? SX_R(-149.5) : SX_R(0.5)), SX_R(0.5));
        }
    }
    /* a box with two colliders side by side on the right ground */
    twin = add_box(w, SX_BODY_DYNAMIC, sx_v2(SX_R(145.0), SX_R(0.5)), SX_R(0.5));
    {
        sx_vec2 square[4];
        square[0] = sx_v2(SX_R(0.5), SX_R(-0.5));
        square[1] = sx_v2(SX_R(1.5), SX_R(-0.5));
        square[2] = sx_v2(SX_R(1.5), SX_R(0.5));
        square[3] = sx_v2(SX_R(0.5), SX_R(0.5));
        assert_int_equal(sx_polygon_shape(square, 4, SX_R(0.0), &cd.shape), SX_OK);
    }
    assert_int_equal(sx_body_add_collider(w, twin, &cd, &second), SX_OK);
    for (steps = 0; steps < 600 && sx_world_awake_body_count(w) > 0; ++steps)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    n = sx_world_contact_count(w);
    assert_int_equal(n, 120 + 2);

    /* the middle ground goes: its crowd wakes (to fall), no one else */
    assert_int_equal(sx_destroy_body(w, middle), SX_OK);
    assert_int_equal(sx_world_awake_body_count(w), 40);
    for (i = 0; i < 40; ++i)
        assert_true(sx_body_is_awake(w, crowd[2][i]));
    n -= 40;
    assert_int_equal(sx_world_contact_count(w), n);

    assert_int_equal(sx_body_set_transform(w, left, sx_v2(SX_R(-100.0), SX_R(-50.0)), SX_R(0.0)),
                     SX_OK);
    for (i = 0; i < 40; ++i) {
        assert_true(sx_body_is_awake(w, crowd[0][i]));
        assert_false(sx_body_is_awake(w, crowd[1][i]));
    }
    assert_false(sx_body_is_awake(w, twin));
    assert_int_equal(sx_body_set_type(w, right, SX_BODY_KINEMATIC), SX_OK);
    for (i = 0; i < 40; ++i)
        assert_true(sx_body_is_awake(w, crowd[1][i]));
    assert_true(sx_body_is_awake(w, twin));
    assert_int_equal(sx_world_awake_body_count(w), 121);

    /* the twin's second collider goes, with its one contact */
    assert_int_equal(sx_destroy_collider(w, second), SX_OK);
    assert_int_equal(sx_world_contact_count(w), n - 1);
    for (i = 0; i < n - 1; ++i) {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(w, i, &d), SX_OK);
        assert_true(sx_collider_is_valid(w, d.collider_a) && sx_collider_is_valid(w, d.collider_b));
    }
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(w), n - 1);
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(waking_one_body_wakes_exactly_its_island),
        cmocka_unit_test(destroying_in_any_order_removes_exactly_the_bodys_contacts),
        cmocka_unit_test(stages_after_a_destroy_never_use_its_contacts),
        cmocka_unit_test(moving_a_ground_wakes_its_crowd_and_a_collider_takes_only_its_contacts),
    };
    return cmocka_run_group_tests_name("wake and destroy", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
