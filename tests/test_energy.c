/* sepax tests — energy at impacts and in pinches: a light body pinched
 * between a heavy one and the ground, at mass ratios of 100 and more, must
 * gain no energy from restitution, from chained impacts or from the solver.
 * The scenes run through fuzz/fuzz_energy.h's audit, which steps the world
 * through the public stages exactly as sx_world_step does (the first test
 * checks that bit for bit) and checks after every sub-step that the total
 * energy stays within its start plus what gravity put in, within rounding
 * (its allowances and where they come from are in that header). Units: m,
 * kg, s; g = 10; dt = 1/60. */
#include <stdio.h>

#include "../fuzz/fuzz_energy.h"
#include "test_support.h"

#define DT (1.0 / 60.0)

static sx_body_id add_ground(sx_world *w, sx_real friction, sx_real restitution) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    bd.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    cd.shape = sx_box_shape(SX_R(50.0), SX_R(1.0));
    cd.friction = friction;
    cd.restitution = restitution;
    assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    return id;
}

static sx_body_id add_ball(sx_world *w, sx_vec2 p, sx_vec2 v, sx_real radius, sx_real density,
                           sx_real friction, sx_real restitution) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    bd.type = SX_BODY_DYNAMIC;
    bd.position = p;
    bd.linear_velocity = v;
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    cd.shape = sx_circle_shape(sx_v2_zero(), radius);
    cd.density = density;
    cd.friction = friction;
    cd.restitution = restitution;
    assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    return id;
}

static double speed_of(const sx_world *w, sx_body_id b) {
    sx_vec2 v = sx_body_get_linear_velocity(w, b);
    return sqrt((double)v.x * (double)v.x + (double)v.y * (double)v.y);
}

/* ---- a heavy ball landing on a pinched small ball --------------------------- */

/* The scene of the report: a small ball (r 0.25, 0.196 kg) resting on the
 * ground, a big one (r 0.8, `density`) dropped on it off-centre from 2 m at
 * 4 m/s, restitution e on the big ball (the ground's and the small ball's
 * are 0, so the pair's is e and the small ball's landings are inelastic);
 * default friction 0.6. bodies[0] is the small ball, bodies[1] the big
 * one. */
static sx_world *pinch_scene(sx_real density, sx_real e, sx_body_id bodies[2]) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    def.enable_sleep = false;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_ground(w, SX_R(0.6), SX_R(0.0));
    bodies[0] = add_ball(w, sx_v2(SX_R(0.0), SX_R(0.25)), sx_v2_zero(), SX_R(0.25), SX_R(1.0),
                         SX_R(0.6), SX_R(0.0));
    bodies[1] = add_ball(w, sx_v2(SX_R(0.5), SX_R(2.0)), sx_v2(SX_R(0.0), SX_R(-4.0)), SX_R(0.8),
                         density, SX_R(0.6), e);
    return w;
}

/* The speed at which the big ball meets the small one: it falls from its
 * start to where the centres are 1.05 m apart (0.5 m aside). */
static double pinch_impact_speed(void) {
    double fall = 2.0 - (0.25 + sqrt(1.05 * 1.05 - 0.5 * 0.5));
    return sqrt(4.0 * 4.0 + 2.0 * 10.0 * fall);
}

/* Runs the scene through the audit for 2 s and checks it: the energy
 * within its budget, the small ball under 2.5 times the impact speed (an
 * elastic impact gives it at most twice the big ball's speed, and its
 * landings are inelastic). */
static void pinch_check(const char *name, sx_real density, sx_real e) {
    sx_body_id b[2];
    sx_world *w = pinch_scene(density, e, b);
    double fastest = 0.0, impact = pinch_impact_speed();
    fz_energy audit;
    int s;
    fz_energy_begin(&audit, w, sx_v2(SX_R(0.0), SX_R(-10.0)), sx_default_world_def().sub_steps, DT,
                    b, NULL, NULL, 2, 0.6);
    for (s = 0; s < 120; ++s) {
        assert_int_equal(fz_energy_step(&audit), SX_OK);
        if (speed_of(w, b[0]) > fastest) fastest = speed_of(w, b[0]);
    }
    printf("  %s: energy %.3f J from %.3f J, most above the budget %.3g J; small ball at most "
           "%.2f m/s (impact %.2f m/s)\n",
           name, audit.energy, audit.start, audit.worst, fastest, impact);
    assert_true(fz_energy_held(&audit));
    assert_true(fastest <= 2.5 * impact);
    sx_world_destroy(w);
}

/* The audit runs the stages of sx_world_step in its order: the same scene
 * stepped both ways ends bit for bit in the same state, so what the audit
 * finds is what sx_world_step does. */
static void the_energy_audit_steps_exactly_as_sx_world_step(void **state) {
    sx_body_id a[2], b[2];
    sx_world *wa = pinch_scene(SX_R(9.765625), SX_R(1.0), a);
    sx_world *wb = pinch_scene(SX_R(9.765625), SX_R(1.0), b);
    fz_energy audit;
    int s, i;
    (void)state;
    fz_energy_begin(&audit, wb, sx_v2(SX_R(0.0), SX_R(-10.0)), sx_default_world_def().sub_steps, DT,
                    b, NULL, NULL, 2, 0.6);
    for (s = 0; s < 40; ++s) {
        assert_int_equal(sx_world_step(wa, (sx_real)DT), SX_OK);
        assert_int_equal(fz_energy_step(&audit), SX_OK);
    }
    for (i = 0; i < 2; ++i) {
        sx_vec2 pa = sx_body_get_position(wa, a[i]), pb = sx_body_get_position(wb, b[i]);
        sx_vec2 va = sx_body_get_linear_velocity(wa, a[i]),
                vb = sx_body_get_linear_velocity(wb, b[i]);
        sx_real aa = sx_body_get_angular_velocity(wa, a[i]),
                ab = sx_body_get_angular_velocity(wb, b[i]);
        assert_memory_equal(&pa, &pb, sizeof pa);
        assert_memory_equal(&va, &vb, sizeof va);
        assert_memory_equal(&aa, &ab, sizeof aa);
    }
    sx_world_destroy(wa);
    sx_world_destroy(wb);
}

/* The report's case: mass ratio 100, e = 1. The impact pass ran after the
 * warm start and bounced the velocity the small ball had from its last
 * support impulses: the energy went from 550 to 1015 J and the small ball
 * left at 65.8 m/s (the impact is at 5.70 m/s). */
static void heavy_ball_on_a_pinched_small_ball_gains_no_energy(void **state) {
    (void)state;
    pinch_check("ratio 100, e = 1", SX_R(9.765625), SX_R(1.0));
}

/* The report's second case: mass ratio 1000, e = 0.5; the small ball left
 * at 91 m/s (the energy stayed in budget: the big ball's dominates). */
static void ratio_1000_with_restitution_one_half_gains_no_energy(void **state) {
    (void)state;
    pinch_check("ratio 1000, e = 0.5", SX_R(97.65625), SX_R(0.5));
}

/* Chained impacts through pinched bodies: a ball of 1000 times the mass of
 * each (r 0.6) lands at 5 m/s, 5 cm off-centre, on a column of four small
 * balls (r 0.15) resting on the ground, e = 1 everywhere but the ground,
 * friction 0.3: every impact runs down the column, and each small ball is
 * pinched between its neighbours. Before the fix the audit found 32 J more
 * than the budget. */
static void heavy_ball_on_a_column_of_small_balls_gains_no_energy(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_body_id b[5];
    fz_energy audit;
    double fastest = 0.0;
    int i, s;
    (void)state;
    def.enable_sleep = false;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_ground(w, SX_R(0.6), SX_R(0.0));
    for (i = 0; i < 4; ++i) {
        b[i] = add_ball(w, sx_v2(SX_R(0.003) * (sx_real)i, SX_R(0.15) + SX_R(0.3) * (sx_real)i),
                        sx_v2_zero(), SX_R(0.15), SX_R(1.0), SX_R(0.3), SX_R(1.0));
    }
    b[4] = add_ball(w, sx_v2(SX_R(0.05), SX_R(2.3)), sx_v2(SX_R(0.0), SX_R(-5.0)), SX_R(0.6),
                    SX_R(62.5), SX_R(0.3), SX_R(1.0)); /* 1000 x 0.15^2 / 0.6^2 */
    fz_energy_begin(&audit, w, def.gravity, def.sub_steps, DT, b, NULL, NULL, 5, 0.6);
    for (s = 0; s < 120; ++s) {
        assert_int_equal(fz_energy_step(&audit), SX_OK);
        for (i = 0; i < 4; ++i)
            fastest = speed_of(w, b[i]) > fastest ? speed_of(w, b[i]) : fastest;
    }
    printf("  column of 4 under a 1000:1 ball: energy %.3f J from %.3f J, most above the budget "
           "%.3g J, fastest small ball %.2f m/s\n",
           audit.energy, audit.start, audit.worst, fastest);
    assert_true(fz_energy_held(&audit));
    sx_world_destroy(w);
}

/* ---- the warm start ------------------------------------------------------------- */

/* A frictionless capsule (caps of radius 0.06 m, 12 cm apart, 0.77 kg)
 * standing on end on the ground and spinning at 5 rad/s, default world, a
 * 30 Hz step: each sub-step the iterations start from the last one's
 * impulses, applied where the turned capsule touches now; what that gives
 * must not exceed what the solver took (on a step that collided every
 * sub-step it gained 4e-4 J above its budget in one second; the audit's
 * rounding allowance is 4e-6 J). */
static void a_spinning_capsule_on_end_gains_no_energy_from_the_warm_start(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id capsule;
    fz_energy audit;
    int s;
    (void)state;
    def.enable_sleep = false;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_ground(w, SX_R(0.0), SX_R(0.0));
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(0.0), SX_R(0.12));
    bd.angle = SX_R(-1.5707963);
    bd.angular_velocity = SX_R(-5.0);
    assert_int_equal(sx_create_body(w, &bd, &capsule), SX_OK);
    cd.shape =
        sx_capsule_shape(sx_v2(SX_R(-0.06), SX_R(0.0)), sx_v2(SX_R(0.06), SX_R(0.0)), SX_R(0.06));
    cd.density = SX_R(30.0);
    cd.friction = SX_R(0.0);
    assert_int_equal(sx_body_add_collider(w, capsule, &cd, NULL), SX_OK);
    fz_energy_begin(&audit, w, def.gravity, def.sub_steps, 1.0 / 30.0, &capsule, NULL, NULL, 1,
                    0.0);
    for (s = 0; s < 30; ++s)
        assert_int_equal(fz_energy_step(&audit), SX_OK);
    printf("  spinning capsule on end: energy %.6f J from %.6f J, most above the budget %.3g J\n",
           audit.energy, audit.start, audit.worst);
    assert_true(fz_energy_held(&audit));
    sx_world_destroy(w);
}

/* ---- continuous collision lifting a bouncing body ---------------------------- */

/* A 1 cm ball (density 0.05) dropped from rest 4.9 mm above a ground, both
 * with restitution 1, 8 sub-steps of 1/240 s: it bounces in the last
 * sub-step, ends closer to the ground than the slop, and the continuous
 * stage puts it back up its path (its straight path from the step's start
 * to its end) with the height paid from its speed. Paid as kinetic energy
 * only, the h (f . v) / 2 term of the energy symplectic Euler keeps (the
 * one that decides how high it goes next) rose by 1.3e-8 J on a 2.3e-6 J
 * start, 0.6 % of it, past the audit's rounding allowance (fuzz input
 * world-ccd-lift-pays-kinetic-energy-only). */
static void a_bouncing_ball_put_back_by_continuous_collision_gains_no_energy(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_body_id ball;
    fz_energy audit;
    sx_vec2 v;
    int s;
    (void)state;
    def.enable_sleep = false;
    def.sub_steps = 8;
    def.velocity_iterations = 8;
    def.position_iterations = 3;
    def.restitution_threshold = SX_R(0.25);
    def.speculative_slops = SX_R(1.0);
    w = sx_world_create(&def);
    assert_non_null(w);
    add_ground(w, SX_R(0.0), SX_R(1.0));
    ball = add_ball(w, sx_v2(SX_R(0.0), SX_R(0.0149)), sx_v2_zero(), SX_R(0.01), SX_R(0.05),
                    SX_R(0.0), SX_R(1.0));
    fz_energy_begin(&audit, w, def.gravity, def.sub_steps, 1.0 / 30.0, &ball, NULL, NULL, 1, 0.0);
    assert_int_equal(fz_energy_step(&audit), SX_OK);
    /* the scene does what it is for: the ball bounced within the step at
     * 8 h g = 0.333 m/s, and the continuous stage lifted it and took the
     * height from that speed */
    v = sx_body_get_linear_velocity(w, ball);
    assert_true(v.y > SX_R(0.2) && v.y < SX_R(0.3));
    for (s = 1; s < 10; ++s)
        assert_int_equal(fz_energy_step(&audit), SX_OK);
    printf("  ball put back by continuous collision: energy %.6g J from %.6g J, most above the "
           "budget %.3g J\n",
           audit.energy, audit.start, audit.worst);
    assert_true(fz_energy_held(&audit));
    sx_world_destroy(w);
}

/* ---- random pinched piles ----------------------------------------------------- */

/* Seeded piles between two walls: 1 to 5 light bodies (circles and boxes,
 * 0.05 to 0.3 m, density 1) under 1 to 3 heavy ones (0.4 to 1 m, density
 * 10^2 to 10^6, thrown down at up to 8 m/s with up to 10 rad/s of spin),
 * restitution 0, 0.5, 1 or any, friction up to 1, 4 s each; before the fix
 * 2 of these 24 went past the budget, one by 10 times its start energy. */
static void random_pinched_piles_at_high_mass_ratios_gain_no_energy(void **state) {
    int seed, failed = 0;
    double worst = -HUGE_VAL;
    (void)state;
    for (seed = 0; seed < 24; ++seed) {
        sx_test_rng rng = sx_test_rng_make(0x9e3779b9u + (uint64_t)seed);
        sx_world_def def = sx_default_world_def();
        sx_world *w;
        sx_body_def bd = sx_default_body_def();
        sx_collider_def cd = sx_default_collider_def();
        sx_body_id b[8], wall;
        double ratio = pow(10.0, 2.0 + 4.0 * sx_test_rng_unit(&rng));
        int light = 1 + (int)(5.0 * sx_test_rng_unit(&rng));
        int heavy = 1 + (int)(3.0 * sx_test_rng_unit(&rng)), n = 0, i, s;
        fz_energy audit;
        def.enable_sleep = false;
        w = sx_world_create(&def);
        assert_non_null(w);
        add_ground(w, sx_test_rng_range(&rng, 0.0, 1.0),
                   sx_test_rng_unit(&rng) < 0.5 ? SX_R(0.0) : sx_test_rng_range(&rng, 0.0, 1.0));
        cd.shape = sx_box_shape(SX_R(0.5), SX_R(3.0));
        for (i = -1; i <= 1; i += 2) {
            bd.position = sx_v2(SX_R(3.0) * (sx_real)i, SX_R(2.0));
            assert_int_equal(sx_create_body(w, &bd, &wall), SX_OK);
            assert_int_equal(sx_body_add_collider(w, wall, &cd, NULL), SX_OK);
        }
        bd.type = SX_BODY_DYNAMIC;
        for (i = 0; i < light + heavy; ++i) {
            bool is_heavy = i >= light;
            double r = is_heavy ? 0.4 + 0.6 * sx_test_rng_unit(&rng)
                                : 0.05 + 0.25 * sx_test_rng_unit(&rng);
            double u = sx_test_rng_unit(&rng);
            bd.position = sx_v2(sx_test_rng_range(&rng, -2.0, 2.0),
                                is_heavy ? sx_test_rng_range(&rng, 1.2, 3.2)
                                         : (sx_real)r + sx_test_rng_range(&rng, 0.0, 0.6));
            bd.linear_velocity = sx_v2(sx_test_rng_range(&rng, -1.0, 1.0),
                                       is_heavy ? sx_test_rng_range(&rng, -8.0, 0.0) : SX_R(0.0));
            bd.angular_velocity = is_heavy ? sx_test_rng_range(&rng, -10.0, 10.0) : SX_R(0.0);
            assert_int_equal(sx_create_body(w, &bd, &b[n]), SX_OK);
            cd.shape =
                sx_test_rng_unit(&rng) < 0.7
                    ? sx_circle_shape(sx_v2_zero(), (sx_real)r)
                    : sx_box_shape((sx_real)r, (sx_real)r * sx_test_rng_range(&rng, 0.5, 1.5));
            cd.density = is_heavy ? (sx_real)ratio : SX_R(1.0);
            cd.friction = sx_test_rng_range(&rng, 0.0, 1.0);
            cd.restitution = u < 0.25   ? SX_R(0.0)
                             : u < 0.5  ? SX_R(0.5)
                             : u < 0.75 ? SX_R(1.0)
                                        : sx_test_rng_range(&rng, 0.0, 1.0);
            assert_int_equal(sx_body_add_collider(w, b[n], &cd, NULL), SX_OK);
            ++n;
        }
        fz_energy_begin(&audit, w, def.gravity, def.sub_steps, DT, b, NULL, NULL, n, 1.0);
        for (s = 0; s < 240; ++s)
            assert_int_equal(fz_energy_step(&audit), SX_OK);
        if (!fz_energy_held(&audit)) {
            ++failed;
            printf("  pile %d (mass ratio %.0f): %.4g J above the budget, start %.4g J\n", seed,
                   ratio, audit.worst, audit.start);
        }
        if (audit.worst / audit.start > worst) worst = audit.worst / audit.start;
        sx_world_destroy(w);
    }
    printf("  24 random pinched piles: %d above the budget; closest to it %.3g of the start\n",
           failed, worst);
    assert_int_equal(failed, 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_energy_audit_steps_exactly_as_sx_world_step),
        cmocka_unit_test(heavy_ball_on_a_pinched_small_ball_gains_no_energy),
        cmocka_unit_test(ratio_1000_with_restitution_one_half_gains_no_energy),
        cmocka_unit_test(heavy_ball_on_a_column_of_small_balls_gains_no_energy),
        cmocka_unit_test(a_spinning_capsule_on_end_gains_no_energy_from_the_warm_start),
        cmocka_unit_test(random_pinched_piles_at_high_mass_ratios_gain_no_energy),
        cmocka_unit_test(a_bouncing_ball_put_back_by_continuous_collision_gains_no_energy),
    };
    return cmocka_run_group_tests_name("energy", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
