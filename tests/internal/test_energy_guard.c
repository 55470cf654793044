/* sepax tests — the energy guard's settle (contact_solver.c) on a group the
 * solve gave more energy than its credit.
 *
 * A white-box test: a column of boxes rests on the ground; after a
 * sub-step's solve, the test makes the solve look as if it had thrown the
 * boxes upwards (their velocities 1 m/s above the "before" velocities the
 * guard measures from) with a small credit, and runs the guard
 * again. One factor in (0, 1) must then scale every body's velocity change
 * and every impulse of the group's contacts (which the next sub-step's warm
 * start applies again): a guard that scaled the velocities alone would hand
 * the energy back with the next warm start. */
#include <math.h>
#include <string.h>

#include "../../src/world_body.h"
#include "../../src/world_contact.h"
#include "../../src/world_internal.h"
#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))
#define BOXES 4
#define MAX_POINTS 64

static void a_scaled_group_scales_its_velocity_changes_and_impulses_by_one_factor(void **state) {
    sx_world_def wd = sx_default_world_def();
    sx_body_id boxes[BOXES];
    sx_world *w;
    sx_real h = DT / (sx_real)wd.sub_steps, impulse[MAX_POINTS], factor = SX_R(-1.0);
    sx_vec2 before[BOXES], was[BOXES];
    int i, k, n = 0, slot[BOXES];
    (void)state;
    wd.enable_sleep = false;
    w = sx_world_create(&wd);
    assert_non_null(w);
    sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)),
                 sx_box_shape(SX_R(5.0), SX_R(1.0)), NULL);
    for (i = 0; i < BOXES; ++i) {
        boxes[i] = sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5) + (sx_real)i),
                                sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
        slot[i] = (int)boxes[i].index;
    }
    for (i = 0; i < 30; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    /* one sub-step by its stages, up to the solve (the guard ran in it) */
    assert_int_equal(sx_world_begin_step(w, DT), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
    assert_int_equal(sx_world_solve(w, h), SX_OK);
    assert_true(w->groups_ready);
    assert_int_equal(w->group_member_count, BOXES);
    /* the resting column took energy out: nothing was scaled */
    for (i = 0; i < BOXES; ++i) {
        sx_group_body *g = &w->group_bodies[slot[i]];
        sx_body_sim *b = &w->sims[slot[i]];
        /* the solve "threw" each box up by 1 m/s; a credit of 1 % of it */
        g->v = b->v;
        g->w = b->w;
        b->v = sx_add(b->v, sx_v2(SX_R(0.0), SX_R(1.0)));
        g->credit = SX_R(0.005) / b->inv_mass;
        before[i] = g->v;
        was[i] = b->v;
    }
    for (i = 0; i < w->contact_count; ++i) {
        const sx_contact *c = &w->contacts[i];
        for (k = 0; k < c->count; ++k) {
            assert_true(n < MAX_POINTS);
            impulse[n++] = c->points[k].normal_impulse;
        }
    }
    assert_int_equal(n, 2 * BOXES); /* four faces of two points */
    sx_contacts_energy_guard(w, h);
    /* the one factor: from the first box's velocity change */
    factor = (w->sims[slot[0]].v.y - before[0].y) / (was[0].y - before[0].y);
    assert_true(factor > SX_R(0.0) && factor < SX_R(1.0));
    for (i = 0; i < BOXES; ++i) {
        sx_real f = (w->sims[slot[i]].v.y - before[i].y) / (was[i].y - before[i].y);
        assert_near(f, factor, 1e-5);
    }
    n = 0;
    for (i = 0; i < w->contact_count; ++i) {
        const sx_contact *c = &w->contacts[i];
        for (k = 0; k < c->count; ++k, ++n) {
            /* the contact's impulse x the group's factor, to rounding */
            assert_true(impulse[n] > SX_R(0.0));
            assert_near(c->points[k].normal_impulse, impulse[n] * factor,
                        1e-5 * fabs((double)impulse[n]));
        }
    }
    /* all of the credit spent */
    for (i = 0; i < BOXES; ++i)
        assert_true(w->group_bodies[slot[i]].credit == SX_R(0.0));
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_scaled_group_scales_its_velocity_changes_and_impulses_by_one_factor),
    };
    return cmocka_run_group_tests_name("energy guard", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
