/* sepax tests — the broadphase against brute force.
 *
 * A white-box test: it reads the world's private layout to compare the
 * broadphase's pairs, after every collide, with the pairs found by testing
 * every collider against every other on freshly computed bounds. The scene
 * has static, kinematic and dynamic bodies of every shape and concave
 * compounds; bodies fall
 * asleep and wake, are teleported, created and destroyed, kinematic bodies
 * start and stop (one ploughs through the sleeping bodies on the ground),
 * colliders come and go. After every refresh the active sets equal a
 * rebuild from scratch, and after every collide no frozen contact is
 * active. Fixed seeds: the same run every
 * time. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/world_body.h"
#include "../../src/world_broadphase.h"
#include "../../src/world_internal.h"
#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))

/* The kind the broadphase must see for a collider, from the body's state. */
static unsigned char expected_kind(const sx_world *w, int i) {
    const sx_collider *c = &w->colliders[i];
    const sx_body_sim *b;
    if (!c->alive || c->sensor || !w->infos[c->body].enabled) return SX_BP_OUT;
    b = &w->sims[c->body];
    if (w->infos[c->body].type == SX_BODY_DYNAMIC) return b->awake ? SX_BP_AWAKE : SX_BP_ASLEEP;
    if (w->infos[c->body].type == SX_BODY_KINEMATIC &&
        (b->v.x != SX_R(0.0) || b->v.y != SX_R(0.0) || b->w != SX_R(0.0))) {
        return SX_BP_MOVING_KINEMATIC;
    }
    return SX_BP_FIXED;
}

static bool pair_wanted(unsigned char a, unsigned char b) {
    if (a == SX_BP_OUT || b == SX_BP_OUT) return false;
    if (a == SX_BP_AWAKE || b == SX_BP_AWAKE) return true;
    return (a == SX_BP_MOVING_KINEMATIC && b == SX_BP_ASLEEP) ||
           (a == SX_BP_ASLEEP && b == SX_BP_MOVING_KINEMATIC);
}

static int key_cmp(const void *a, const void *b) {
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* Compares the broadphase's pairs with brute force; returns the pair count
 * and adds to *kinematic_asleep the pairs of a moving kinematic collider with
 * a sleeping one. `kind` holds the kinds taken before the collide (a collide
 * wakes the sleeping bodies an awake one touches, after the broadphase
 * ran). */
static int check_pairs(const sx_world *w, const unsigned char *kind, int *kinematic_asleep) {
    int n = w->collider_slots, i, j, count = 0;
    sx_aabb *box = (sx_aabb *)malloc(sizeof(sx_aabb) * (size_t)(n > 0 ? n : 1));
    uint64_t *pairs = (uint64_t *)malloc(sizeof(uint64_t) * (size_t)(n * (n + 1) / 2 + 1));
    assert_non_null(box);
    assert_non_null(pairs);
    for (i = 0; i < n; ++i) {
        const sx_collider *c = &w->colliders[i];
        assert_int_equal(kind[i], w->bp_kind[i]);
        if (kind[i] == SX_BP_OUT) continue;
        box[i] = sx_aabb_fatten(sx_collider_aabb(c, w->sims[c->body].xf), SX_R(0.5) * w->margin);
        /* cached bounds of bodies that do not move must still be exact */
        assert_true(memcmp(&box[i], &w->aabbs[i], sizeof(sx_aabb)) == 0);
    }
    for (i = 0; i < n; ++i) {
        for (j = i + 1; j < n; ++j) {
            if (!pair_wanted(kind[i], kind[j])) continue;
            if (box[j].lower.x > box[i].upper.x || box[j].upper.x < box[i].lower.x ||
                box[j].lower.y > box[i].upper.y || box[j].upper.y < box[i].lower.y) {
                continue;
            }
            pairs[count++] = ((uint64_t)(uint32_t)i << 32) | (uint64_t)(uint32_t)j;
            if (kind[i] != SX_BP_AWAKE && kind[j] != SX_BP_AWAKE) ++*kinematic_asleep;
        }
    }
    qsort(pairs, (size_t)count, sizeof(uint64_t), key_cmp);
    assert_int_equal(count, w->bp.pair_count);
    for (i = 0; i < count; ++i)
        assert_true(pairs[i] == w->bp.pairs[i]);
    free(box);
    free(pairs);
    return count;
}

/* Compares the sensor overlaps with brute force (every sensor against every
 * collider, the same rules: not itself, not a sensor, not on the same body,
 * not static against static, default filters). */
static void check_sensors(const sx_world *w) {
    int i, j, count = 0;
    for (i = 0; i < w->collider_slots; ++i) {
        const sx_collider *s = &w->colliders[i];
        if (!s->alive || !s->sensor || !w->infos[s->body].enabled) continue;
        for (j = 0; j < w->collider_slots; ++j) {
            const sx_collider *c = &w->colliders[j];
            if (!c->alive || c->sensor || c->body == s->body || !w->infos[c->body].enabled)
                continue;
            if (w->infos[c->body].type == SX_BODY_STATIC &&
                w->infos[s->body].type == SX_BODY_STATIC) {
                continue;
            }
            if (!sx_colliders_overlap(s, w->sims[s->body].xf, c, w->sims[c->body].xf)) continue;
            assert_true(count < w->sensor_count);
            assert_true(w->sensor_pairs[count] ==
                        (((uint64_t)(uint32_t)i << 32) | (uint64_t)(uint32_t)j));
            ++count;
        }
    }
    assert_int_equal(count, w->sensor_count);
}

/* The active sets after a refresh equal a rebuild from scratch (the
 * bodies the step moves and the moving colliders, in slot order), however
 * the refresh got there (after wakes and sleeps it redoes only those
 * bodies); and no contact waiting in the frozen store is active. */
static void check_sets(sx_world *w) {
    int i, n = 0;
    assert_int_equal(sx_world_refresh_sets(w), SX_OK);
    for (i = 0; i < w->body_slots; ++i) {
        const sx_body_sim *b = &w->sims[i];
        if (!(w->infos[i].alive && b->moving && b->awake)) continue;
        assert_true(n < w->active_body_count);
        assert_int_equal(w->active_bodies[n], i);
        ++n;
    }
    assert_int_equal(n, w->active_body_count);
    n = 0;
    for (i = 0; i < w->collider_slots; ++i) {
        unsigned char k = expected_kind(w, i);
        assert_int_equal(w->bp_kind[i], k);
        if (k != SX_BP_AWAKE && k != SX_BP_MOVING_KINEMATIC) continue;
        assert_true(n < w->active_collider_count);
        assert_int_equal(w->active_colliders[n], i);
        ++n;
    }
    assert_int_equal(n, w->active_collider_count);
}

static void check_frozen(const sx_world *w) {
    int i;
    for (i = 0; i < w->frozen_count; ++i) {
        if (w->frozen[i].count > 0) assert_false(sx_contact_is_active(w, &w->frozen[i]));
    }
}

static sx_shape random_shape(sx_test_rng *rng) {
    switch (sx_test_rng_next(rng) % 4u) {
    case 0: return sx_circle_shape(sx_v2_zero(), sx_test_rng_range(rng, 0.2, 0.6));
    case 1: return sx_box_shape(sx_test_rng_range(rng, 0.2, 0.7), sx_test_rng_range(rng, 0.2, 0.7));
    case 2:
        return sx_capsule_shape(sx_v2(SX_R(-0.3), SX_R(0.0)), sx_v2(SX_R(0.3), SX_R(0.0)),
                                sx_test_rng_range(rng, 0.1, 0.3));
    default: return sx_segment_shape(sx_v2(SX_R(-0.5), SX_R(0.0)), sx_v2(SX_R(0.5), SX_R(0.1)));
    }
}

static sx_body_id add(sx_world *w, sx_body_type type, sx_vec2 p, const sx_shape *s) {
    return sx_test_body(w, type, p, *s, NULL);
}

#define MAX_IDS 400

static void broadphase_pairs_equal_brute_force_through_sleep_teleport_create_destroy(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_test_rng rng = sx_test_rng_make(20261123u);
    sx_body_id ids[MAX_IDS];
    int count = 0, step, sub, i, total_pairs = 0, max_pairs = 0, asleep_seen = 0, max_sensed = 0;
    int kinematic_asleep = 0, tree_calls = 0, sweep_calls = 0;
    sx_body_id plough;
    sx_shape blade = sx_box_shape(SX_R(1.0), SX_R(0.3));
    sx_world *w;
    sx_shape ground = sx_box_shape(SX_R(40.0), SX_R(0.5));
    static unsigned char kinds[4 * MAX_IDS];
    (void)state;
    def.time_to_sleep = SX_R(0.25); /* many sleep and wake events */
    w = sx_world_create(&def);
    assert_non_null(w);
    add(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground);
    for (i = 0; i < 6; ++i) {
        sx_shape s = random_shape(&rng);
        add(w, SX_BODY_STATIC, sx_v2((sx_real)(-15 + 6 * i), SX_R(1.0)), &s);
    }
    for (i = 0; i < 3; ++i) {
        sx_shape s = sx_box_shape(SX_R(1.0), SX_R(0.2));
        ids[count++] = add(w, SX_BODY_KINEMATIC, sx_v2((sx_real)(-10 + 10 * i), SX_R(3.0)), &s);
    }
    {
        /* sensors: a static zone, one on a kinematic body, one on a dynamic */
        sx_collider_def cd = sx_default_collider_def();
        sx_body_id z = add(w, SX_BODY_STATIC, sx_v2(SX_R(5.0), SX_R(2.0)), &ground);
        cd.sensor = true;
        cd.shape = sx_box_shape(SX_R(3.0), SX_R(2.0));
        assert_int_equal(sx_body_add_collider(w, z, &cd, NULL), SX_OK);
        cd.shape = sx_circle_shape(sx_v2_zero(), SX_R(1.5));
        assert_int_equal(sx_body_add_collider(w, ids[0], &cd, NULL), SX_OK);
        assert_int_equal(sx_body_set_linear_velocity(w, ids[0], sx_v2(SX_R(1.0), SX_R(0.0))),
                         SX_OK);
        ids[count] = add(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(6.0)), &ground);
        assert_int_equal(sx_body_add_collider(w, ids[count++], &cd, NULL), SX_OK);
    }
    {
        /* concave compounds: a static U and two dynamic L outlines */
        static const sx_vec2 u[8] = {{-2, 0},
                                     {2, 0},
                                     {2, 2},
                                     {SX_R(1.5), 2},
                                     {SX_R(1.5), SX_R(0.5)},
                                     {-SX_R(1.5), SX_R(0.5)},
                                     {-SX_R(1.5), 2},
                                     {-2, 2}};
        static const sx_vec2 l[6] = {{0, 0},         {2, 0}, {2, SX_R(0.5)}, {SX_R(0.5), SX_R(0.5)},
                                     {SX_R(0.5), 2}, {0, 2}};
        sx_collider_def cd = sx_default_collider_def();
        sx_body_def bd = sx_default_body_def();
        sx_body_id b;
        bd.position = sx_v2(SX_R(-6.0), SX_R(0.0));
        assert_int_equal(sx_create_body(w, &bd, &b), SX_OK);
        assert_int_equal(sx_body_add_outline(w, b, u, 8, &cd, NULL), SX_OK);
        bd.type = SX_BODY_DYNAMIC;
        for (i = 0; i < 2; ++i) {
            bd.position = sx_v2(SX_R(-7.0) + SX_R(2.5) * (sx_real)i, SX_R(4.0));
            assert_int_equal(sx_create_body(w, &bd, &b), SX_OK);
            assert_int_equal(sx_body_add_outline(w, b, l, 6, &cd, NULL), SX_OK);
            ids[count++] = b;
        }
    }
    /* a kinematic plough sweeping the ground back and forth through the
     * sleeping bodies: the pairs of a moving kinematic body with sleeping
     * ones, which no other pair kind covers (it must find them to wake
     * them) */
    plough = add(w, SX_BODY_KINEMATIC, sx_v2(SX_R(-18.0), SX_R(0.6)), &blade);
    assert_int_equal(sx_body_set_linear_velocity(w, plough, sx_v2(SX_R(2.0), SX_R(0.0))), SX_OK);
    for (i = 0; i < 150; ++i) {
        sx_shape s = random_shape(&rng);
        ids[count++] = add(
            w, SX_BODY_DYNAMIC,
            sx_v2(sx_test_rng_range(&rng, -20.0, 20.0), sx_test_rng_range(&rng, 0.5, 12.0)), &s);
    }
    for (step = 0; step < 1500; ++step) {
        /* one random event per step */
        int pick = (int)(sx_test_rng_next(&rng) % (uint64_t)count);
        sx_body_id b = ids[pick];
        switch (sx_test_rng_next(&rng) % 10u) {
        case 0: /* teleport (also static and sleeping bodies) */
            if (sx_body_is_valid(w, b)) {
                assert_int_equal(sx_body_set_transform(w, b,
                                                       sx_v2(sx_test_rng_range(&rng, -20.0, 20.0),
                                                             sx_test_rng_range(&rng, 0.5, 8.0)),
                                                       sx_test_rng_range(&rng, -3.0, 3.0)),
                                 SX_OK);
            }
            break;
        case 1: /* destroy */
            if (sx_body_is_valid(w, b) && count > 20) {
                assert_int_equal(sx_destroy_body(w, b), SX_OK);
                ids[pick] = ids[--count];
            }
            break;
        case 2: /* create */
            if (count < MAX_IDS) {
                sx_shape s = random_shape(&rng);
                sx_body_type t =
                    sx_test_rng_next(&rng) % 5u == 0 ? SX_BODY_STATIC : SX_BODY_DYNAMIC;
                ids[count++] = add(
                    w, t,
                    sx_v2(sx_test_rng_range(&rng, -20.0, 20.0), sx_test_rng_range(&rng, 0.5, 10.0)),
                    &s);
            }
            break;
        case 3: /* kinematic start or stop, or a push */
            if (sx_body_is_valid(w, b)) {
                sx_vec2 v = sx_test_rng_next(&rng) % 2u == 0
                                ? sx_v2_zero()
                                : sx_v2(sx_test_rng_range(&rng, -2.0, 2.0), SX_R(0.0));
                assert_int_equal(sx_body_set_linear_velocity(w, b, v), SX_OK);
            }
            break;
        case 4: /* put to sleep by hand */
            if (sx_body_is_valid(w, b)) assert_int_equal(sx_body_set_awake(w, b, false), SX_OK);
            break;
        case 5: /* a second collider */
            if (sx_body_is_valid(w, b)) {
                sx_collider_def cd = sx_default_collider_def();
                cd.shape = sx_circle_shape(sx_v2(SX_R(0.4), SX_R(0.0)), SX_R(0.2));
                assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_OK);
            }
            break;
        default: break;
        }
        {
            /* the plough turns at either end, and rests now and then (a
             * kinematic body at rest is FIXED) */
            sx_real x = sx_body_get_position(w, plough).x, vx = sx_body_get_linear_velocity(w, plough).x;
            if (step % 300 == 150) vx = SX_R(0.0);
            if (step % 300 == 180) vx = x > SX_R(0.0) ? SX_R(-2.0) : SX_R(2.0);
            if ((x > SX_R(18.0) && vx > SX_R(0.0)) || (x < SX_R(-18.0) && vx < SX_R(0.0))) vx = -vx;
            assert_int_equal(sx_body_set_linear_velocity(w, plough, sx_v2(vx, SX_R(0.0))), SX_OK);
        }
        assert_int_equal(sx_world_clear_events(w), SX_OK);
        for (sub = 0; sub < def.sub_steps; ++sub) {
            sx_real h = DT / (sx_real)def.sub_steps;
            int pairs, k;
            assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
            check_sets(w);
            assert_true(w->collider_slots <= 4 * MAX_IDS);
            for (k = 0; k < w->collider_slots; ++k)
                kinds[k] = expected_kind(w, k);
            assert_int_equal(sx_world_collide(w), SX_OK);
            pairs = check_pairs(w, kinds, &kinematic_asleep);
            check_frozen(w);
            /* the moving colliders' candidates come from the tree or from
             * the sweep, as many left their fat boxes or few */
            if (w->bp.tree_valid)
                ++tree_calls;
            else
                ++sweep_calls;
            check_sensors(w);
            if (w->sensor_count > max_sensed) max_sensed = w->sensor_count;
            total_pairs += pairs;
            if (pairs > max_pairs) max_pairs = pairs;
            assert_int_equal(sx_world_solve(w, h), SX_OK);
            assert_int_equal(sx_world_integrate(w, h), SX_OK);
            assert_int_equal(sx_world_separate(w, h), SX_OK);
        }
        assert_int_equal(sx_world_clear_forces(w), SX_OK);
        assert_int_equal(sx_world_update_sleep(w, DT), SX_OK);
        for (i = 0; i < count; ++i) {
            if (sx_body_is_valid(w, ids[i]) && !sx_body_is_awake(w, ids[i])) {
                ++asleep_seen;
                break;
            }
        }
    }
    printf("  1500 steps: %d pairs checked (at most %d at once; %d of a moving kinematic body with "
           "a sleeping one), sleeping bodies in %d steps, up to %d sensor overlaps; %d collides "
           "with the tree, %d with the sweep\n",
           total_pairs, max_pairs, kinematic_asleep, asleep_seen, max_sensed, tree_calls,
           sweep_calls);
    /* the scene must exercise what it claims to */
    assert_true(max_pairs > 50);
    assert_true(kinematic_asleep > 20);
    assert_true(asleep_seen > 100);
    assert_true(max_sensed > 3);
    assert_true(tree_calls > 100);
    assert_true(sweep_calls > 20);
    sx_world_destroy(w);
}

/* Two towers of 300 boxes side by side, without gravity: a sweep of the
 * whole world on x met about 150 boxes per box (the rest of its tower) for
 * 2-3 pairs; band by band, a box meets its band's few. A sweep that cheap
 * costs about half a return to the tree per call, so one calm call pays
 * for the return: the first collide sweeps, the second takes the tree;
 * half the boxes thrown out of their fat boxes for a step make the world
 * sweep, and it takes the tree again after one calm call; the pairs stay
 * exact throughout. */
static void a_banded_sweep_meets_few_boxes_and_returns_to_the_tree_with_exact_pairs(
    void **state) {
    enum { TOWER = 300, STEPS = 12 };
    sx_world_def def = sx_default_world_def();
    sx_shape ground = sx_box_shape(SX_R(10.0), SX_R(0.5)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    static unsigned char kinds[2 * TOWER + 1];
    bool tree[STEPS * SX_MAX_SUB_STEPS];
    sx_body_id ids[2 * TOWER];
    sx_world *w;
    int i, step, sub, kinematic_asleep = 0, calls = 0, last_sweep = -1;
    (void)state;
    def.enable_sleep = false;
    def.gravity = sx_v2_zero();
    w = sx_world_create(&def);
    assert_non_null(w);
    add(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground);
    for (i = 0; i < 2 * TOWER; ++i) {
        sx_real x = i % 2 ? SX_R(0.55) : SX_R(-0.55);
        ids[i] = add(w, SX_BODY_DYNAMIC, sx_v2(x, SX_R(0.5) + (sx_real)(i / 2)), &box);
    }
    for (step = 0; step < STEPS; ++step) {
        if (step == 6 || step == 7) {
            /* the towers' upper halves 2 m up in a step, then stopped */
            sx_vec2 v = sx_v2(SX_R(0.0), step == 6 ? SX_R(120.0) : SX_R(0.0));
            for (i = TOWER; i < 2 * TOWER; ++i)
                assert_int_equal(sx_body_set_linear_velocity(w, ids[i], v), SX_OK);
        }
        for (sub = 0; sub < def.sub_steps; ++sub) {
            sx_real h = DT / (sx_real)def.sub_steps;
            int k;
            assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
            for (k = 0; k < w->collider_slots; ++k)
                kinds[k] = expected_kind(w, k);
            assert_int_equal(sx_world_collide(w), SX_OK);
            assert_true(check_pairs(w, kinds, &kinematic_asleep) >= TOWER);
            if (calls == 0) {
                assert_int_equal(w->bp.sweep_boxes, 2 * TOWER);
                assert_true(w->bp.sweep_visits <= (int64_t)4 * w->bp.sweep_boxes);
            }
            tree[calls] = w->bp.tree_valid;
            if (!tree[calls]) last_sweep = calls;
            ++calls;
            assert_int_equal(sx_world_solve(w, h), SX_OK);
            assert_int_equal(sx_world_integrate(w, h), SX_OK);
            assert_int_equal(sx_world_separate(w, h), SX_OK);
        }
        assert_int_equal(sx_world_clear_forces(w), SX_OK);
    }
    /* the first collide swept, the rest until the throw used the tree */
    assert_false(tree[0]);
    for (i = 1; i <= 6 * def.sub_steps; ++i)
        assert_true(tree[i]);
    /* the throw swept (half the boxes out), the stop too; one calm call
     * later the tree served again, and kept serving */
    assert_true(last_sweep > 6 * def.sub_steps && last_sweep <= 7 * def.sub_steps);
    for (i = last_sweep + 1; i < calls; ++i)
        assert_true(tree[i]);
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(broadphase_pairs_equal_brute_force_through_sleep_teleport_create_destroy),
        cmocka_unit_test(
            a_banded_sweep_meets_few_boxes_and_returns_to_the_tree_with_exact_pairs),
    };
    return cmocka_run_group_tests_name("broadphase", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
