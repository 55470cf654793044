/* sepax tests — the accuracy and stability scenes of docs/scenes.md with known
 * answers: bounce height against restitution squared, sticking and sliding on
 * an incline, Newton's cradle, a zero-gravity pile-up, a base-20 pyramid, a
 * 100:1 mass ratio and recovery from overlap. Every scene runs in the default
 * world settings unless its comment says why not; each prints its measured
 * figure so a run shows the margins. Units: m, kg, s; g = 10; dt = 1/60. */
#include <stdio.h>

#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))

static sx_world *make_world_ex(sx_vec2 gravity, bool sleep) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    def.gravity = gravity;
    def.enable_sleep = sleep;
    w = sx_world_create(&def);
    assert_non_null(w);
    return w;
}

/* The scenes measure the solver, so bodies stay awake: a pile that sleeps
 * would hide any drift after it dozed off. */
static sx_world *make_world(sx_vec2 gravity) { return make_world_ex(gravity, false); }

static sx_body_id add_body(sx_world *w, sx_body_type type, sx_vec2 p, sx_real angle,
                           const sx_shape *shape, sx_real density, sx_real friction,
                           sx_real restitution) {
    sx_collider_def cd = sx_default_collider_def();
    cd.shape = *shape;
    cd.density = density;
    cd.friction = friction;
    cd.restitution = restitution;
    return sx_test_body_turned(w, type, p, angle, &cd);
}

/* The docs/scenes.md ground: a static box 2*hw wide, 2 m tall, top surface at y=0. */
static sx_body_id add_ground(sx_world *w, sx_real half_width, sx_real friction) {
    sx_shape box = sx_box_shape(half_width, SX_R(1.0));
    return add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), SX_R(0.0), &box, SX_R(0.0),
                    friction, SX_R(0.0));
}

static void step_n(sx_world *w, int n) {
    int i;
    for (i = 0; i < n; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
}

/* Deepest overlap of the current contact list, in metres. */
static double max_depth(const sx_world *w) {
    double deepest = 0.0;
    int i, k;
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data c;
        assert_int_equal(sx_world_get_contact(w, i, &c), SX_OK);
        for (k = 0; k < c.count; ++k) {
            if ((double)c.depths[k] > deepest) deepest = (double)c.depths[k];
        }
    }
    return deepest;
}

/* ---- bounce -------------------------------------------------------------- */

/* Drops a body (its lowest point 2 m above the ground, half-height 0.5)
 * with `sub_steps` sub-steps and returns the first rebound's apex height
 * over the drop height; *max_spin (if not NULL): the largest |angular
 * velocity| seen. */
static double bounce_ratio_ex(const sx_shape *shape, sx_real e, int sub_steps, double *lowest_after,
                              double *max_spin) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_body_id b;
    double apex = 0.0, lowest = 10.0, spin = 0.0;
    bool bounced = false;
    int i;
    def.enable_sleep = false;
    def.sub_steps = sub_steps;
    w = sx_world_create(&def);
    assert_non_null(w);
    add_ground(w, SX_R(10.0), SX_R(0.6));
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(2.5)), SX_R(0.0), shape, SX_R(1.0),
                 SX_R(0.6), e);
    for (i = 0; i < 300; ++i) {
        double w_abs = fabs((double)sx_body_get_angular_velocity(w, b));
        if (w_abs > spin) spin = w_abs;
        double y, vy;
        step_n(w, 1);
        y = (double)sx_body_get_position(w, b).y - 0.5;
        vy = (double)sx_body_get_linear_velocity(w, b).y;
        if (!bounced && vy > 0.0) bounced = true;
        if (bounced) {
            if (y > apex) apex = y;
            if (vy < 0.0 && y < apex) break;
        }
        if (i > 60 && y < lowest) lowest = y;
    }
    if (lowest_after != NULL) *lowest_after = lowest;
    if (max_spin != NULL) *max_spin = spin;
    sx_world_destroy(w);
    return apex / 2.0;
}

/* A circle of radius 0.5 dropped from 2 m at the default settings. */
static double bounce_ratio(sx_real e, double *lowest_after) {
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    return bounce_ratio_ex(&ball, e, sx_default_world_def().sub_steps, lowest_after, NULL);
}

static void bounce_apex_over_drop_is_restitution_squared(void **state) {
    static const double es[] = {0.2, 0.5, 0.8};
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        double r = bounce_ratio((sx_real)es[i], NULL);
        double want = es[i] * es[i];
        printf("  bounce e=%.1f: apex/drop %.4f, e^2 %.4f, error %+.2f%%\n", es[i], r, want,
               100.0 * (r - want) / want);
        assert_near(r, want, 0.05 * want);
    }
}

static void bounce_with_zero_restitution_stays_on_the_ground(void **state) {
    double lowest;
    double r = bounce_ratio(SX_R(0.0), &lowest);
    (void)state;
    printf("  bounce e=0: highest rebound %.5f m\n", 2.0 * r);
    /* no rebound beyond the contact tolerance, and no sinking either */
    assert_true(2.0 * r < 0.005);
    assert_true(lowest > -0.005);
}

/* The impact is resolved at its time of impact within the sub-step (the
 * bodies' positions are corrected for it), so the rebound does not depend on
 * where the impact falls on the sub-step grid. The solver before the impact
 * pass bounced to 0.148 instead of 0.25 with 8 sub-steps and to 0.022 with
 * 24. */
static void bounce_height_does_not_depend_on_the_sub_step_count(void **state) {
    static const int subs[] = {1, 2, 3, 8, 24};
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    int i;
    (void)state;
    for (i = 0; i < 5; ++i) {
        double r = bounce_ratio_ex(&ball, SX_R(0.5), subs[i], NULL, NULL);
        printf("  bounce e=0.5, %2d sub-steps: apex/drop %.4f (e^2 0.25)\n", subs[i], r);
        assert_near(r, 0.25, 0.05 * 0.25);
    }
}

/* A box landing flat: its two contact points are resolved together, so it
 * bounces straight up, without the spin that resolving one corner before
 * the other would give it. */
static void box_landing_flat_bounces_straight_without_spin(void **state) {
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    double spin,
        r = bounce_ratio_ex(&box, SX_R(0.5), sx_default_world_def().sub_steps, NULL, &spin);
    (void)state;
    printf("  box e=0.5: apex/drop %.4f (e^2 0.25), largest spin %.2e rad/s\n", r, spin);
    assert_near(r, 0.25, 0.05 * 0.25);
    assert_true(spin < 1e-3);
}

/* Friction acts during an impact, on the impact's own normal impulse: a disc
 * (r 0.5) hitting the ground at vx = 5, vy = -5 m/s with e = 0.5, mu = 0.6,
 * no gravity. The normal impulse is J = (1 + e) m 5 = 7.5 m; stopping the
 * slip takes m 5 / 3 (a disc: 1/m + r^2/I = 3/m), within mu J, so the disc
 * leaves rolling: vx = 5 - 5/3 = 3.333 m/s, w r = -vx, vy = 2.5 m/s, and
 * has lost energy. */
static void oblique_impact_with_friction_leaves_rolling(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id b;
    sx_vec2 v;
    double om, ke0 = 0.5 * 50.0, ke;
    (void)state;
    add_ground(w, SX_R(10.0), SX_R(0.6));
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-3.0), SX_R(1.0)), SX_R(0.0), &ball, SX_R(1.0),
                 SX_R(0.6), SX_R(0.5));
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(5.0), SX_R(-5.0))), SX_OK);
    step_n(w, 30);
    v = sx_body_get_linear_velocity(w, b);
    om = (double)sx_body_get_angular_velocity(w, b);
    ke = 0.5 * ((double)sx_dot(v, v) + 0.125 * om * om); /* per kg: I / m = r^2 / 2 */
    printf("  oblique impact: v (%.4f, %.4f) m/s, w r %.4f m/s (rolling: -vx), energy %.3f of %.3f "
           "J/kg\n",
           (double)v.x, (double)v.y, 0.5 * om, ke, ke0);
    assert_near(v.x, 5.0 - 5.0 / 3.0, 0.01 * 5.0);
    assert_near(v.y, 2.5, 0.02 * 2.5);
    assert_near(0.5 * om, -(double)v.x, 0.01 * 5.0);
    assert_true(ke < ke0);
    sx_world_destroy(w);
}

/* ---- incline ------------------------------------------------------------- */

#define INCLINE_ANGLE 0.25

/* A box of half-extent 0.5 released at rest on a ramp at 0.25 rad with
 * friction mu (both colliders, so the mixed coefficient is mu). Returns the
 * distance slid down the slope after 1 s and 2 s and the speed then. */
static void incline_run_at(double angle, sx_real mu_ramp, sx_real mu_box, double *d1, double *d2,
                           double *v1, double *v2) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_real th = (sx_real)angle;
    sx_shape ramp = sx_box_shape(SX_R(20.0), SX_R(0.5));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_vec2 down = sx_v2(-sx_cos(th), -sx_sin(th)), start;
    sx_body_id b;
    add_body(w, SX_BODY_STATIC, sx_v2_zero(), th, &ramp, SX_R(0.0), mu_ramp, SX_R(0.0));
    start = sx_rotate(sx_rot_make(th), sx_v2(SX_R(8.0), SX_R(1.0)));
    b = add_body(w, SX_BODY_DYNAMIC, start, th, &box, SX_R(1.0), mu_box, SX_R(0.0));
    step_n(w, 60);
    *d1 = (double)sx_dot(sx_sub(sx_body_get_position(w, b), start), down);
    *v1 = (double)sx_dot(sx_body_get_linear_velocity(w, b), down);
    step_n(w, 60);
    *d2 = (double)sx_dot(sx_sub(sx_body_get_position(w, b), start), down);
    *v2 = (double)sx_dot(sx_body_get_linear_velocity(w, b), down);
    sx_world_destroy(w);
}

static void incline_run2(sx_real mu_ramp, sx_real mu_box, double *d1, double *d2, double *v1,
                         double *v2) {
    incline_run_at(INCLINE_ANGLE, mu_ramp, mu_box, d1, d2, v1, v2);
}

static void incline_run(sx_real mu, double *d1, double *d2, double *v1, double *v2) {
    incline_run2(mu, mu, d1, d2, v1, v2);
}

static void incline_box_sticks_when_friction_exceeds_tangent(void **state) {
    static const double mus[] = {0.75, 0.5, 0.35};
    int i;
    (void)state;
    for (i = 0; i < 3; ++i) {
        double d1, d2, v1, v2;
        incline_run((sx_real)mus[i], &d1, &d2, &v1, &v2);
        printf("  incline mu=%.2f (tan 0.2553): slid %.6f m in 2 s\n", mus[i], d2);
        assert_true(d2 < 0.001 && d2 > -0.001);
    }
}

static void incline_box_slides_with_coulomb_acceleration(void **state) {
    static const double mus[] = {0.1, 0.0};
    int i;
    (void)state;
    for (i = 0; i < 2; ++i) {
        double d1, d2, v1, v2, a;
        double want = 10.0 * (sin(INCLINE_ANGLE) - mus[i] * cos(INCLINE_ANGLE));
        incline_run((sx_real)mus[i], &d1, &d2, &v1, &v2);
        a = v2 - v1; /* speed gained in the second second */
        printf("  incline mu=%.2f: a %.4f m/s^2, g(sin-mu cos) %.4f, error %+.2f%%\n", mus[i], a,
               want, 100.0 * (a - want) / want);
        assert_near(a, want, 0.02 * want);
        /* and the distance agrees with a uniformly accelerated start */
        assert_near(d2, 0.5 * want * 4.0, 0.02 * 0.5 * want * 4.0);
    }
}

/* Friction mixes as sqrt(mu_a mu_b): 0.25 on 1.0 gives 0.5, which holds the
 * box at 0.25 rad, where the smaller coefficient alone (0.25 < tan 0.25)
 * would let it slide. */
static void incline_friction_mixes_as_geometric_mean(void **state) {
    double d1, d2, v1, v2;
    (void)state;
    incline_run2(SX_R(1.0), SX_R(0.25), &d1, &d2, &v1, &v2);
    assert_true(d2 < 0.001 && d2 > -0.001);
    incline_run2(SX_R(0.25), SX_R(0.25), &d1, &d2, &v1, &v2);
    assert_true(d2 > 0.01);
}

/* 0.1 on 0.9 mixes to sqrt(0.09) = 0.3, where the arithmetic mean (0.5),
 * the larger (0.9), the smaller (0.1) and the product (0.09) all differ. On
 * a ramp at 0.35 rad (tan 0.365) the box slides at g(sin - 0.3 cos) = 0.61
 * m/s^2; with 0.5 or 0.9 it would stick, with 0.1 or 0.09 it would slide at
 * 2.5 m/s^2. The bound is the one of the single-coefficient slides above
 * (2 %), in both orders of the two colliders. */
static void incline_friction_of_0_1_on_0_9_mixes_to_0_3(void **state) {
    const double angle = 0.35, want = 10.0 * (sin(angle) - 0.3 * cos(angle));
    int order;
    (void)state;
    for (order = 0; order < 2; ++order) {
        double d1, d2, v1, v2, a;
        sx_real ramp = order == 0 ? SX_R(0.1) : SX_R(0.9), box = order == 0 ? SX_R(0.9) : SX_R(0.1);
        incline_run_at(angle, ramp, box, &d1, &d2, &v1, &v2);
        a = v2 - v1;
        printf("  incline 0.35 rad, mu %.1f on %.1f: a %.4f m/s^2, g(sin-0.3 cos) %.4f, error "
               "%+.2f%%\n",
               (double)box, (double)ramp, a, want, 100.0 * (a - want) / want);
        assert_near(a, want, 0.02 * want);
        assert_near(d2, 0.5 * want * 4.0, 0.02 * 0.5 * want * 4.0);
    }
}

/* An impact slower than the restitution threshold (1 m/s by default) does not
 * bounce, whatever the restitution. */
static void slow_impact_below_the_threshold_does_not_bounce(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id b;
    double highest = 0.0;
    int s;
    (void)state;
    add_ground(w, SX_R(10.0), SX_R(0.6));
    /* dropped from 3 cm: lands at 0.77 m/s */
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.53)), SX_R(0.0), &ball, SX_R(1.0),
                 SX_R(0.6), SX_R(0.9));
    for (s = 0; s < 60; ++s) {
        step_n(w, 1);
        if (s > 10 && (double)sx_body_get_position(w, b).y > highest) {
            highest = (double)sx_body_get_position(w, b).y;
        }
    }
    assert_true(highest < 0.5 + 0.001);
    sx_world_destroy(w);
}

/* ---- Newton's cradle -------------------------------------------------------- */

/* Five equal balls r 0.5 in a row along x, centres `spacing` apart (1.001:
 * 1 mm gaps; 1: touching), e = 1, mu = 0, no gravity; the first `moving`
 * balls move at 1 m/s towards the others. `reversed` creates the balls in
 * the opposite order (the moving ones last, at the right, moving left), so
 * the chain of impacts runs against the order of the contact list. Runs 1 s
 * and returns the velocities along the row (v[0] the first moving ball, so
 * +1 is "the way the first ball went"), the momentum and kinetic energy in
 * the same sense, and the mass of one ball. */
static void cradle_run_ex(const sx_world_def *def, sx_real spacing, int moving, bool reversed,
                          double v[5], double *p, double *ke, double *m) {
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id b[5];
    sx_world *w = sx_world_create(def);
    double sense = reversed ? -1.0 : 1.0;
    int i;
    assert_non_null(w);
    for (i = 0; i < 5; ++i) {
        /* ball i of the row, created in row order or in reverse */
        int slot = reversed ? 4 - i : i;
        sx_real x = (sx_real)sense * spacing * (sx_real)slot;
        b[slot] = add_body(w, SX_BODY_DYNAMIC, sx_v2(x, SX_R(0.0)), SX_R(0.0), &ball, SX_R(1.0),
                           SX_R(0.0), SX_R(1.0));
    }
    for (i = 0; i < moving; ++i) {
        assert_int_equal(sx_body_set_linear_velocity(w, b[i], sx_v2((sx_real)sense, SX_R(0.0))),
                         SX_OK);
    }
    step_n(w, 60);
    *p = 0.0;
    *ke = 0.0;
    *m = (double)sx_body_get_mass(w, b[0]);
    for (i = 0; i < 5; ++i) {
        sx_vec2 vi = sx_body_get_linear_velocity(w, b[i]);
        v[i] = sense * (double)vi.x;
        *p += *m * v[i];
        *ke += 0.5 * *m * (double)sx_dot(vi, vi);
    }
    sx_world_destroy(w);
}

/* The scene's world: the default settings in zero gravity (the row lies
 * along x and nothing else acts). The impacts are at 1 m/s, exactly the
 * default restitution threshold, which bounces (approach >= threshold). */
static sx_world_def cradle_def(void) {
    sx_world_def def = sx_default_world_def();
    def.gravity = sx_v2_zero();
    return def;
}

/* Largest |v| of balls first..last. */
static double cradle_residual(const double v[5], int first, int last) {
    double r = 0.0;
    int i;
    for (i = first; i <= last; ++i)
        r = fabs(v[i]) > r ? fabs(v[i]) : r;
    return r;
}

/* The figures every cradle scene must meet: the last `moving` balls leave at
 * >= 0.95 m/s, the others are nearly at rest (|v| <= 1e-3 m/s, 0.1 % of the
 * speed), momentum within 1e-5 relative, no energy gained. */
static void cradle_check(const char *name, const double v[5], double p, double ke, double m,
                         int moving) {
    double residual = cradle_residual(v, 0, 4 - moving), p0 = (double)moving * m;
    double ke0 = 0.5 * (double)moving * m;
    int i;
    printf("  cradle (%s): v %.5f %.5f %.5f %.5f %.5f, others at most %.2e m/s, momentum error "
           "%.2e, energy %.6f of %.6f\n",
           name, v[0], v[1], v[2], v[3], v[4], residual, fabs(p - p0) / p0, ke, ke0);
    for (i = 5 - moving; i < 5; ++i)
        assert_true(v[i] >= 0.95);
    assert_true(residual <= 1e-3);
    assert_near(p, p0, 1e-5 * p0);
    assert_true(ke <= ke0 * (1.0 + 1e-5));
}

/* Without a speculative margin each impact is found in the sub-step it
 * happens in, one after the other, as in the real cradle. */
static void cradle_passes_the_speed_to_the_last_ball(void **state) {
    sx_world_def def = cradle_def();
    double v[5], p, ke, m;
    (void)state;
    def.speculative_slops = SX_R(0.0);
    cradle_run_ex(&def, SX_R(1.001), 1, false, v, &p, &ke, &m);
    cradle_check("no speculative margin", v, p, ke, m, 1);
}

/* With the default margin (20 mm, wider than the 1 mm gaps) all four
 * contacts exist from the first sub-step. Solved together (the solver
 * before the impact pass) the row shared the impact: 0.029 0.029 0.061
 * 0.255 0.626 m/s, 46 % of the energy. The impact pass resolves 0-1, 1-2,
 * 2-3, 3-4 in time-of-impact order within one sub-step. */
static void cradle_with_the_default_world_passes_the_speed_to_the_last_ball(void **state) {
    sx_world_def def = cradle_def();
    double v[5], p, ke, m;
    (void)state;
    cradle_run_ex(&def, SX_R(1.001), 1, false, v, &p, &ke, &m);
    cradle_check("default world", v, p, ke, m, 1);
}

/* The same row created right to left: the contact list (ordered by collider
 * slots) now runs against the chain, which a pass in list order would need
 * four sweeps for; the time order does not care. */
static void cradle_built_in_reverse_order_gives_the_same_answer(void **state) {
    sx_world_def def = cradle_def();
    double v[5], p, ke, m;
    (void)state;
    cradle_run_ex(&def, SX_R(1.001), 1, true, v, &p, &ke, &m);
    cradle_check("created in reverse", v, p, ke, m, 1);
}

/* Five balls touching exactly (centres 1 m apart, separation 0 at every
 * contact). The case most sequential-impulse engines get wrong: with every
 * contact present and touching, a simultaneous solve spreads the impulse
 * over the row (the balls leave together, or the last one slowly). Here:
 * 0-1 has time of impact 0; resolving it gives ball 1 the speed, which makes
 * 1-2 an impact at time 0, and so on: the idealised cradle's answer, the
 * last ball leaves at 1 m/s and the others stop. Asserted, as the gapped
 * row: last >= 0.95 m/s, others <= 1e-3 m/s, momentum 1e-5, no energy
 * gained. */
static void cradle_of_touching_balls_passes_the_speed_to_the_last_ball(void **state) {
    sx_world_def def = cradle_def();
    double v[5], p, ke, m;
    (void)state;
    cradle_run_ex(&def, SX_R(1.0), 1, false, v, &p, &ke, &m);
    cradle_check("touching", v, p, ke, m, 1);
    cradle_run_ex(&def, SX_R(1.0), 1, true, v, &p, &ke, &m);
    cradle_check("touching, created in reverse", v, p, ke, m, 1);
}

/* Two balls swung together: two leave. The second wave meets contacts the
 * first already resolved within the same sub-step. */
static void cradle_with_two_moving_balls_sends_two_away(void **state) {
    sx_world_def def = cradle_def();
    double v[5], p, ke, m;
    (void)state;
    cradle_run_ex(&def, SX_R(1.001), 2, false, v, &p, &ke, &m);
    cradle_check("two moving", v, p, ke, m, 2);
    cradle_run_ex(&def, SX_R(1.0), 2, false, v, &p, &ke, &m);
    cradle_check("two moving, touching", v, p, ke, m, 2);
}

/* Two impacts in one sub-step are resolved in time order. Three equal balls
 * in a row, e = 0.5, no gravity: A moves right at 2 m/s 1 mm from B (at
 * rest), C left at 2 m/s 3 mm from B's other side. A meets B first (A 0.5,
 * B 1.5 m/s), then B meets C (B -1.125, C 0.625), then B meets A again (A
 * -0.71875, B 0.09375), all within the first 2 ms. Taken in the reverse
 * order the answer is the mirror image (A -0.625, B -0.09375, C 0.71875). */
static void impacts_within_a_sub_step_are_resolved_in_time_order(void **state) {
    sx_world_def def = cradle_def();
    sx_world *w = sx_world_create(&def);
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id a, b, c;
    double va, vb, vc;
    (void)state;
    assert_non_null(w);
    a = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-1.001), SX_R(0.0)), SX_R(0.0), &ball, SX_R(1.0),
                 SX_R(0.0), SX_R(0.5));
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), SX_R(0.0), &ball, SX_R(1.0), SX_R(0.0),
                 SX_R(0.5));
    c = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(1.003), SX_R(0.0)), SX_R(0.0), &ball, SX_R(1.0),
                 SX_R(0.0), SX_R(0.5));
    assert_int_equal(sx_body_set_linear_velocity(w, a, sx_v2(SX_R(2.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, c, sx_v2(SX_R(-2.0), SX_R(0.0))), SX_OK);
    step_n(w, 30);
    va = (double)sx_body_get_linear_velocity(w, a).x;
    vb = (double)sx_body_get_linear_velocity(w, b).x;
    vc = (double)sx_body_get_linear_velocity(w, c).x;
    printf("  three balls, two impacts in one sub-step: v %.5f %.5f %.5f (time order -0.71875 "
           "0.09375 0.625)\n",
           va, vb, vc);
    /* the bound: the impacts' arithmetic in float, far below the 0.09 m/s
     * that separates the two orders */
    assert_near(va, -0.71875, 1e-4);
    assert_near(vb, 0.09375, 1e-4);
    assert_near(vc, 0.625, 1e-4);
    sx_world_destroy(w);
}

/* The impact pass keeps the step deterministic: the same calls twice give
 * bit-identical velocities. */
static void cradle_is_bit_identical_when_run_twice(void **state) {
    sx_world_def def = cradle_def();
    double v1[5], v2[5], p1, p2, ke1, ke2, m;
    (void)state;
    cradle_run_ex(&def, SX_R(1.0007), 2, true, v1, &p1, &ke1, &m);
    cradle_run_ex(&def, SX_R(1.0007), 2, true, v2, &p2, &ke2, &m);
    assert_memory_equal(v1, v2, sizeof(v1));
    assert_memory_equal(&ke1, &ke2, sizeof(ke1));
}

/* The impulse of an impact is reported apart from the iterations' impulses:
 * two equal balls touching, the first at 1 m/s, e = 1: the impact pass
 * gives (1 + e) m_eff v = m, and the iterations nothing (the balls part). */
static void impact_impulse_is_reported_apart_from_the_iterations(void **state) {
    sx_world_def def = cradle_def();
    sx_world *w = sx_world_create(&def);
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id a, b;
    sx_contact_data c;
    double m;
    (void)state;
    assert_non_null(w);
    a = add_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), SX_R(0.0), &ball, SX_R(1.0), SX_R(0.0),
                 SX_R(1.0));
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.0), &ball, SX_R(1.0),
                 SX_R(0.0), SX_R(1.0));
    assert_int_equal(sx_body_set_linear_velocity(w, a, sx_v2(SX_R(1.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_solve(w, DT), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 1);
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    m = (double)sx_body_get_mass(w, a);
    assert_near(c.impact_impulses[0], m, 1e-5 * m);
    assert_near(c.normal_impulses[0], 0.0, 1e-9);
    assert_near(sx_body_get_linear_velocity(w, b).x, 1.0, 1e-6);
    assert_near(sx_body_get_linear_velocity(w, a).x, 0.0, 1e-6);
    sx_world_destroy(w);
}

/* A ball jammed between two walls, touching both, at 5 m/s, e = 1: every
 * impact sends it straight into the other wall at time 0. The pass resolves
 * each contact at most SX_IMPACTS_PER_CONTACT times per sub-step, so the
 * step ends; the rest is left to the iterations, which stop the ball (no
 * energy is ever gained, nothing escapes). */
static void ball_jammed_between_two_walls_ends_the_step_and_gains_no_energy(void **state) {
    sx_world_def def = cradle_def();
    sx_world *w = sx_world_create(&def);
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_shape wall = sx_box_shape(SX_R(0.5), SX_R(2.0));
    sx_body_id b;
    double v0 = 5.0, vmax = 0.0;
    int s;
    (void)state;
    assert_non_null(w);
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(-1.0), SX_R(0.0)), SX_R(0.0), &wall, SX_R(0.0),
             SX_R(0.0), SX_R(1.0));
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.0), &wall, SX_R(0.0), SX_R(0.0),
             SX_R(1.0));
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), SX_R(0.0), &ball, SX_R(1.0), SX_R(0.0),
                 SX_R(1.0));
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2((sx_real)v0, SX_R(0.0))), SX_OK);
    for (s = 0; s < 60; ++s) {
        double v;
        step_n(w, 1);
        v = (double)sx_length(sx_body_get_linear_velocity(w, b));
        if (v > vmax) vmax = v;
    }
    printf("  ball jammed between walls at 5 m/s: largest speed after a step %.4f m/s, x %.5f\n",
           vmax, (double)sx_body_get_position(w, b).x);
    assert_true(vmax <= v0 * (1.0 + 1e-5));
    assert_near(sx_body_get_position(w, b).x, 0.0, 0.01);
    sx_world_destroy(w);
}

/* ---- zero-gravity pile-up ------------------------------------------------- */

/* What a zero-gravity pile-up keeps: the largest drifts of the momentum and
 * of the angular momentum about the origin over 3 s, their scales, and the
 * largest kinetic energy and the first. */
typedef struct pileup_drifts {
    double drift, scale, l_drift, l_scale, ke_max, ke0;
} pileup_drifts;

static pileup_drifts run_pileup(void) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_test_rng rng = sx_test_rng_make(20261122u);
    sx_body_id ids[48];
    double p0x = 0.0, p0y = 0.0, scale = 0.0, ke0 = 0.0, ke_max = 0.0, drift = 0.0;
    double l0 = 0.0, l_scale = 0.0, l_drift = 0.0;
    pileup_drifts out;
    int i, s;
    def.gravity = sx_v2_zero();
    def.enable_sleep = false;
    w = sx_world_create(&def);
    assert_non_null(w);
    for (i = 0; i < 48; ++i) {
        double a = 6.283185307179586 * (double)i / 48.0;
        double r = 6.0 + 2.0 * sx_test_rng_unit(&rng);
        sx_vec2 p = sx_v2((sx_real)(r * cos(a)), (sx_real)(r * sin(a)));
        sx_shape shape;
        sx_real speed = sx_test_rng_range(&rng, 2.0, 6.0);
        if (i % 3 == 0) {
            shape = sx_circle_shape(sx_v2_zero(), sx_test_rng_range(&rng, 0.3, 0.6));
        } else if (i % 3 == 1) {
            shape =
                sx_box_shape(sx_test_rng_range(&rng, 0.3, 0.6), sx_test_rng_range(&rng, 0.3, 0.6));
        } else {
            shape = sx_capsule_shape(sx_v2(SX_R(-0.3), SX_R(0.0)), sx_v2(SX_R(0.3), SX_R(0.0)),
                                     SX_R(0.3));
        }
        ids[i] = add_body(w, SX_BODY_DYNAMIC, p, (sx_real)a, &shape,
                          sx_test_rng_range(&rng, 0.5, 2.0), SX_R(0.4), SX_R(0.0));
        assert_int_equal(sx_body_set_linear_velocity(w, ids[i], sx_scale(sx_normalize(p), -speed)),
                         SX_OK);
        assert_int_equal(
            sx_body_set_angular_velocity(w, ids[i], sx_test_rng_range(&rng, -2.0, 2.0)), SX_OK);
    }
    for (i = 0; i < 48; ++i) {
        double m = (double)sx_body_get_mass(w, ids[i]),
               iner = (double)sx_body_get_inertia(w, ids[i]);
        sx_vec2 v = sx_body_get_linear_velocity(w, ids[i]);
        sx_vec2 c = sx_body_get_world_center(w, ids[i]);
        double om = (double)sx_body_get_angular_velocity(w, ids[i]);
        p0x += m * (double)v.x;
        p0y += m * (double)v.y;
        scale += m * (double)sx_length(v);
        ke0 += 0.5 * (m * (double)sx_dot(v, v) + iner * om * om);
        l0 += iner * om + m * ((double)c.x * (double)v.y - (double)c.y * (double)v.x);
        l_scale += iner * fabs(om) + m * (double)sx_length(c) * (double)sx_length(v);
    }
    for (s = 0; s < 180; ++s) {
        double px = 0.0, py = 0.0, ke = 0.0, l = 0.0;
        step_n(w, 1);
        for (i = 0; i < 48; ++i) {
            double m = (double)sx_body_get_mass(w, ids[i]);
            double iner = (double)sx_body_get_inertia(w, ids[i]);
            sx_vec2 v = sx_body_get_linear_velocity(w, ids[i]);
            sx_vec2 c = sx_body_get_world_center(w, ids[i]);
            double om = (double)sx_body_get_angular_velocity(w, ids[i]);
            px += m * (double)v.x;
            py += m * (double)v.y;
            ke += 0.5 * (m * (double)sx_dot(v, v) + iner * om * om);
            l += iner * om + m * ((double)c.x * (double)v.y - (double)c.y * (double)v.x);
        }
        if (fabs(l - l0) > l_drift) l_drift = fabs(l - l0);
        if (ke > ke_max) ke_max = ke;
        if (fabs(px - p0x) > drift) drift = fabs(px - p0x);
        if (fabs(py - p0y) > drift) drift = fabs(py - p0y);
    }
    sx_world_destroy(w);
    out.drift = drift;
    out.scale = scale;
    out.l_drift = l_drift;
    out.l_scale = l_scale;
    out.ke_max = ke_max;
    out.ke0 = ke0;
    return out;
}

static void pileup_conserves_momentum_and_never_gains_energy(void **state) {
    pileup_drifts r = run_pileup();
    double drift = r.drift, scale = r.scale, l_drift = r.l_drift, l_scale = r.l_scale;
    double ke_max = r.ke_max, ke0 = r.ke0;
    (void)state;
    printf("  pileup: momentum drift %.2e of %.2f (%.2e), angular momentum drift %.2e of %.2f "
           "(%.2e), max energy %.6f of %.6f (ratio %.8f)\n",
           drift, scale, drift / scale, l_drift, l_scale, l_drift / l_scale, ke_max, ke0,
           ke_max / ke0);
    /* Every impulse acts equal and opposite at one point, so momentum and
     * angular momentum change only by rounding: the bounds are a few times
     * the drift measured (float 1.5e-7, double 3e-16 of the scale). The
     * angular momentum about the origin also moves with the positional
     * correction (it moves centres, not velocities, which changes c x m v)
     * and with the levers of collide time, fixed over the sub-steps while
     * the bodies move (equal and opposite impulses at points that slid
     * apart): 3.1e-4 of its scale, bound 6e-4. */
#ifdef SX_DOUBLE
    assert_true(drift <= 1e-14 * scale);
#else
    assert_true(drift <= 1e-6 * scale);
#endif
    assert_true(l_drift <= 6e-4 * l_scale);
    assert_true(ke_max <= ke0 * (1.0 + 1e-6));
}

/* ---- pyramid --------------------------------------------------------------- */

static void pyramid_of_base_20_stands_for_10_seconds(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id top = {0, 0};
    sx_vec2 top0, settled = sx_v2_zero();
    double deepest = 0.0, moved, drift;
    int i, j, s;
    (void)state;
    add_ground(w, SX_R(100.0), SX_R(0.6));
    for (i = 0; i < 20; ++i) {
        for (j = i; j < 20; ++j) {
            sx_vec2 p = sx_v2((sx_real)((double)(i + 1) * 0.5 + (double)(j - i) - 10.0),
                              (sx_real)((double)(2 * i + 1) * 0.5));
            top = add_body(w, SX_BODY_DYNAMIC, p, SX_R(0.0), &box, SX_R(1.0), SX_R(0.6), SX_R(0.0));
        }
    }
    top0 = sx_body_get_position(w, top);
    for (s = 0; s < 600; ++s) {
        double d;
        step_n(w, 1);
        d = max_depth(w);
        if (s > 60 && d > deepest) deepest = d;
        if (s == 59) settled = sx_body_get_position(w, top);
    }
    moved = (double)sx_distance(top0, sx_body_get_position(w, top));
    drift = (double)sx_distance(settled, sx_body_get_position(w, top));
    printf("  pyramid20: top box moved %.5f m (y %.5f from %.4f), %.2e m after the first second; "
           "max depth after 1 s %.5f m (slop %.4f)\n",
           moved, (double)sx_body_get_position(w, top).y, (double)top0.y, drift, deepest,
           (double)sx_world_linear_slop(w));
    /* settling: 20 contact layers each sink into the slop, 4 mm in all;
     * then it stands: 8e-5 m of drift in the 9 s after the first second
     * (float and double), bound 3e-4 m. Resting contacts keep within the
     * slop (positional correction pushes only beyond it). */
    assert_true(moved < 0.01);
    assert_true(drift < 3e-4);
    assert_true(deepest < (double)sx_world_linear_slop(w));
    sx_world_destroy(w);
}

/* ---- mass ratio ------------------------------------------------------------- */

static void heavy_box_on_light_box_penetrates_less_than_two_slops(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id light, heavy;
    double deepest = 0.0;
    int s;
    (void)state;
    add_ground(w, SX_R(10.0), SX_R(0.6));
    light = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), SX_R(0.0), &box, SX_R(1.0),
                     SX_R(0.6), SX_R(0.0));
    heavy = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.5)), SX_R(0.0), &box, SX_R(100.0),
                     SX_R(0.6), SX_R(0.0));
    for (s = 0; s < 300; ++s) {
        double d;
        step_n(w, 1);
        d = max_depth(w);
        if (d > deepest) deepest = d;
    }
    printf("  mass ratio 100:1: max depth %.5f m = %.2f slop, heavy box y %.4f\n", deepest,
           deepest / (double)sx_world_linear_slop(w), (double)sx_body_get_position(w, heavy).y);
    /* 1.15 slop deep and 4.4 mm down measured (float and double): the
     * light box's contacts converge less than a uniform stack's, so the
     * bounds are 2 slops, not 1 */
    assert_true(deepest < 2.0 * (double)sx_world_linear_slop(w));
    assert_near(sx_body_get_position(w, heavy).y, 1.5, 2.0 * (double)sx_world_linear_slop(w));
    assert_near(sx_body_get_position(w, light).x, 0.0, 1e-3);
    sx_world_destroy(w);
}

static void wide_plank_on_two_small_boxes_penetrates_less_than_a_third_of_a_slop(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5)), plank = sx_box_shape(SX_R(10.0), SX_R(0.5));
    sx_body_id p;
    double deepest = 0.0;
    int s;
    (void)state;
    add_ground(w, SX_R(20.0), SX_R(0.6));
    add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-9.0), SX_R(0.5)), SX_R(0.0), &box, SX_R(1.0),
             SX_R(0.6), SX_R(0.0));
    add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(9.0), SX_R(0.5)), SX_R(0.0), &box, SX_R(1.0), SX_R(0.6),
             SX_R(0.0));
    /* 20 m x 1 m of density 1: 20 kg on two 1 kg boxes */
    p = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.5)), SX_R(0.0), &plank, SX_R(1.0),
                 SX_R(0.6), SX_R(0.0));
    for (s = 0; s < 300; ++s) {
        double d;
        step_n(w, 1);
        d = max_depth(w);
        if (d > deepest) deepest = d;
    }
    printf("  plank 20:1 on two boxes: max depth %.5f m = %.2f slop, plank y %.4f, angle %.2e\n",
           deepest, deepest / (double)sx_world_linear_slop(w), (double)sx_body_get_position(w, p).y,
           (double)sx_body_get_angle(w, p));
    /* 0.44 mm deep, 0.4 mm down, 1.7e-6 rad measured (float and double);
     * bounds about 3 times that */
    assert_true(deepest < 0.3 * (double)sx_world_linear_slop(w));
    assert_near(sx_body_get_position(w, p).y, 1.5, 0.3 * (double)sx_world_linear_slop(w));
    assert_near(sx_body_get_angle(w, p), 0.0, 1e-5);
    sx_world_destroy(w);
}

/* ---- stack ------------------------------------------------------------------ */

static void column_of_20_boxes_creeps_less_than_a_centimetre_in_10_seconds(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id ids[20];
    sx_vec2 start[20];
    double creep = 0.0;
    int i;
    (void)state;
    add_ground(w, SX_R(10.0), SX_R(0.6));
    for (i = 0; i < 20; ++i) {
        /* alternate rows shifted +-1 cm, as docs/scenes.md's stack20 */
        start[i] = sx_v2((i % 2) ? SX_R(0.01) : SX_R(-0.01), SX_R(0.5) + (sx_real)i);
        ids[i] = add_body(w, SX_BODY_DYNAMIC, start[i], SX_R(0.0), &box, SX_R(1.0), SX_R(0.6),
                          SX_R(0.0));
    }
    step_n(w, 600);
    for (i = 0; i < 20; ++i) {
        double dx = fabs((double)(sx_body_get_position(w, ids[i]).x - start[i].x));
        if (dx > creep) creep = dx;
    }
    printf("  stack20: largest lateral creep %.5f m, top y %.4f (from %.4f)\n", creep,
           (double)sx_body_get_position(w, ids[19]).y, (double)start[19].y);
    assert_true(creep < 0.01);
    assert_near(sx_body_get_position(w, ids[19]).y, start[19].y, 0.05);
    sx_world_destroy(w);
}

/* Top of a column of five boxes after 10 s, the column standing at x. */
static sx_vec2 column_top_after_10_s(sx_real x) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(20.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id top = {0, 0};
    sx_vec2 p;
    int i;
    add_body(w, SX_BODY_STATIC, sx_v2(x, SX_R(-1.0)), SX_R(0.0), &ground, SX_R(0.0), SX_R(0.6),
             SX_R(0.0));
    for (i = 0; i < 5; ++i) {
        top = add_body(w, SX_BODY_DYNAMIC, sx_v2(x, SX_R(0.5) + (sx_real)i), SX_R(0.0), &box,
                       SX_R(1.0), SX_R(0.6), SX_R(0.0));
    }
    step_n(w, 600);
    p = sx_body_get_position(w, top);
    sx_world_destroy(w);
    return p;
}

/* The narrowphase works in A's local frame, so a stack far from the origin
 * (10 km: a float has 1 mm resolution there) rests as it does at the origin. */
static void column_far_from_the_origin_rests_as_at_the_origin(void **state) {
    sx_vec2 near = column_top_after_10_s(SX_R(0.0));
    sx_vec2 far = column_top_after_10_s(SX_R(10000.0));
    (void)state;
    printf("  column of 5: top at y %.5f at the origin, %.5f at x = 1e4 (x drift %.5f)\n",
           (double)near.y, (double)far.y, (double)far.x - 10000.0);
    assert_near(far.y, near.y, 0.002);
    assert_near(far.x, 10000.0, 0.002);
    assert_near(near.x, 0.0, 0.001);
}

/* ---- overlap recovery ------------------------------------------------------- */

static void overlapping_pyramid_separates_without_gaining_speed(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id ids[10];
    double max_speed = 0.0, separated_at = -1.0;
    int i, j, n = 0, s;
    (void)state;
    add_ground(w, SX_R(10.0), SX_R(0.6));
    /* base 4, spacing 0.75 instead of 1: a quarter of every box overlaps its
     * neighbours (and the bottom row the ground) */
    for (i = 0; i < 4; ++i) {
        for (j = i; j < 4; ++j) {
            sx_vec2 p = sx_v2((sx_real)(0.75 * (double)(j - i) + 0.375 * (double)i - 1.125),
                              (sx_real)(0.25 + 0.75 * (double)i));
            ids[n++] =
                add_body(w, SX_BODY_DYNAMIC, p, SX_R(0.0), &box, SX_R(1.0), SX_R(0.6), SX_R(0.0));
        }
    }
    for (s = 0; s < 180; ++s) {
        step_n(w, 1);
        for (i = 0; i < n; ++i) {
            double v = (double)sx_length(sx_body_get_linear_velocity(w, ids[i]));
            if (v > max_speed) max_speed = v;
        }
        if (separated_at < 0.0 && max_depth(w) < 2.0 * (double)sx_world_linear_slop(w)) {
            separated_at = (double)(s + 1) / 60.0;
        }
    }
    printf("  overlap recovery: separated after %.3f s, max speed %.4f m/s, final depth %.5f\n",
           separated_at, max_speed, max_depth(w));
    assert_true(separated_at > 0.0 && separated_at < 2.0);
    /* positions were corrected, not velocities: nothing shoots off, the
     * boxes only pick up what gravity gives them between two corrections
     * (3.4 mm/s measured, float and double; bound 1 cm/s), and end at rest */
    assert_true(max_speed < 0.01);
    for (i = 0; i < n; ++i) {
        assert_true(sx_length(sx_body_get_linear_velocity(w, ids[i])) < SX_R(1e-3));
    }
    sx_world_destroy(w);
}

/* ---- long run --------------------------------------------------------------- */

static void mixed_shapes_in_a_box_run_20_seconds_without_escaping_or_blowing_up(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_test_rng rng = sx_test_rng_make(4242u);
    sx_shape wall = sx_box_shape(SX_R(0.5), SX_R(6.0));
    sx_body_id ids[60];
    double max_speed = 0.0, final_ke = 0.0;
    int i, s;
    (void)state;
    add_ground(w, SX_R(6.0), SX_R(0.6));
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(-5.5), SX_R(6.0)), SX_R(0.0), &wall, SX_R(0.0),
             SX_R(0.6), SX_R(0.0));
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(5.5), SX_R(6.0)), SX_R(0.0), &wall, SX_R(0.0), SX_R(0.6),
             SX_R(0.0));
    for (i = 0; i < 60; ++i) {
        sx_vec2 p = sx_v2(sx_test_rng_range(&rng, -4.0, 4.0), SX_R(1.0) + SX_R(0.9) * (sx_real)i);
        sx_shape shape;
        switch (i % 4) {
        case 0: shape = sx_circle_shape(sx_v2_zero(), sx_test_rng_range(&rng, 0.2, 0.5)); break;
        case 1:
            shape =
                sx_box_shape(sx_test_rng_range(&rng, 0.2, 0.5), sx_test_rng_range(&rng, 0.2, 0.5));
            break;
        case 2:
            shape = sx_capsule_shape(sx_v2(SX_R(-0.3), SX_R(0.0)), sx_v2(SX_R(0.3), SX_R(0.0)),
                                     sx_test_rng_range(&rng, 0.1, 0.3));
            break;
        default: shape = sx_test_random_ngon(&rng, 6, 0.25, 0.5); break;
        }
        ids[i] = add_body(w, SX_BODY_DYNAMIC, p, sx_test_rng_range(&rng, 0.0, 3.0), &shape,
                          SX_R(1.0), SX_R(0.5), (i % 5 == 0) ? SX_R(0.5) : SX_R(0.0));
    }
    for (s = 0; s < 1200; ++s) {
        step_n(w, 1);
        for (i = 0; i < 60; ++i) {
            double v = (double)sx_length(sx_body_get_linear_velocity(w, ids[i]));
            if (v > max_speed) max_speed = v;
        }
    }
    for (i = 0; i < 60; ++i) {
        sx_vec2 p = sx_body_get_position(w, ids[i]), v = sx_body_get_linear_velocity(w, ids[i]);
        assert_true(sx_vec2_is_finite(p) && sx_vec2_is_finite(v));
        /* inside the container: between the walls, above the floor */
        assert_true(p.x > SX_R(-5.0) && p.x < SX_R(5.0));
        assert_true(p.y > SX_R(0.0) && p.y < SX_R(12.0));
        final_ke += 0.5 * (double)sx_body_get_mass(w, ids[i]) * (double)sx_dot(v, v);
    }
    printf("  rain of 60 mixed shapes, 20 s: max speed %.3f m/s (free fall from the top: %.3f), "
           "final kinetic energy %.5f J\n",
           max_speed, sqrt(2.0 * 10.0 * 55.0), final_ke);
    /* no body ever went faster than a fall from the highest start allows */
    assert_true(max_speed < sqrt(2.0 * 10.0 * 55.0) * 1.05);
    /* and the pile has come to rest */
    assert_true(final_ke < 0.05);
    sx_world_destroy(w);
}

/* PILE_N circles and boxes (half-size 0.2..0.5) of restitution 0.9 rain in
 * rows of 40 into a 50 m wide container of the same restitution. Contacts
 * slower than the threshold do not bounce, so the pile must come to rest:
 * after 10 s its kinetic energy is below 0.01 J. The solver before the
 * impact pass left this pile at 36 J (411 J with 1,000 bodies): its
 * restitution pass, run after the iterations on speeds measured before them,
 * kept pumping the deep pile. */
#define PILE_N 600

static void bouncy_pile_comes_to_rest(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_test_rng rng = sx_test_rng_make(777u);
    sx_shape floor_box = sx_box_shape(SX_R(27.0), SX_R(1.0));
    sx_shape wall = sx_box_shape(SX_R(1.0), SX_R(20.0));
    sx_body_id ids[PILE_N];
    double ke = 0.0, highest = 0.0;
    int i;
    (void)state;
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), SX_R(0.0), &floor_box, SX_R(0.0),
             SX_R(0.5), SX_R(0.9));
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(-26.0), SX_R(19.0)), SX_R(0.0), &wall, SX_R(0.0),
             SX_R(0.5), SX_R(0.9));
    add_body(w, SX_BODY_STATIC, sx_v2(SX_R(26.0), SX_R(19.0)), SX_R(0.0), &wall, SX_R(0.0),
             SX_R(0.5), SX_R(0.9));
    for (i = 0; i < PILE_N; ++i) {
        sx_real r = sx_test_rng_range(&rng, 0.2, 0.5);
        sx_shape shape = (i % 2) ? sx_circle_shape(sx_v2_zero(), r) : sx_box_shape(r, r);
        sx_vec2 p = sx_v2(SX_R(-24.375) + SX_R(1.25) * (sx_real)(i % 40),
                          SX_R(1.0) + SX_R(1.25) * (sx_real)(i / 40));
        ids[i] =
            add_body(w, SX_BODY_DYNAMIC, p, (sx_real)i, &shape, SX_R(1.0), SX_R(0.5), SX_R(0.9));
    }
    step_n(w, 600);
    for (i = 0; i < PILE_N; ++i) {
        sx_vec2 v = sx_body_get_linear_velocity(w, ids[i]), p = sx_body_get_position(w, ids[i]);
        double om = (double)sx_body_get_angular_velocity(w, ids[i]);
        ke += 0.5 * ((double)sx_body_get_mass(w, ids[i]) * (double)sx_dot(v, v) +
                     (double)sx_body_get_inertia(w, ids[i]) * om * om);
        assert_true(p.x > SX_R(-25.0) && p.x < SX_R(25.0) && p.y > SX_R(0.0));
        if ((double)p.y > highest) highest = (double)p.y;
    }
    printf("  bouncy pile (%d bodies, e = 0.9): kinetic energy after 10 s %.2e J, top at y %.2f\n",
           PILE_N, ke, highest);
    assert_true(ke < 0.01);
    sx_world_destroy(w);
}

static void kinematic_paddle_pushes_a_box_without_being_pushed_back(void **state) {
    /* with sleeping on: the box dozes off before the paddle reaches it, and
     * the moving paddle must wake it rather than pass through */
    sx_world *w = make_world_ex(sx_v2(SX_R(0.0), SX_R(-10.0)), true);
    sx_shape paddle = sx_box_shape(SX_R(0.25), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id k, b;
    (void)state;
    add_ground(w, SX_R(20.0), SX_R(0.6));
    k = add_body(w, SX_BODY_KINEMATIC, sx_v2(SX_R(-2.0), SX_R(1.0)), SX_R(0.0), &paddle, SX_R(1.0),
                 SX_R(0.6), SX_R(0.0));
    b = add_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), SX_R(0.0), &box, SX_R(1.0),
                 SX_R(0.6), SX_R(0.0));
    assert_int_equal(sx_body_set_linear_velocity(w, k, sx_v2(SX_R(1.0), SX_R(0.0))), SX_OK);
    step_n(w, 180);
    /* 3 s at 1 m/s: the paddle is at x = 1 whatever the box does, and the
     * box (touching it from x = -1.25 on) is pushed ahead of it */
    assert_near(sx_body_get_position(w, k).x, 1.0, 1e-3);
    assert_near(sx_body_get_linear_velocity(w, k).x, 1.0, 0.0);
    assert_true(sx_body_get_position(w, b).x >= SX_R(1.0) + SX_R(0.75) - SX_R(0.01));
    assert_near(sx_body_get_linear_velocity(w, b).x, 1.0, 0.05);
    sx_world_destroy(w);
}

/* world.h: contacts cover each body's motion over the step (the speculative
 * margin grows by the distance it can travel), so a body moving straight at
 * a collider stops at it at any speed. A 0.1 m ball meets a 0.1 m wall at
 * 60 Hz and the default sub-steps from ten start positions spread over one sub-step's
 * travel, at 11 m/s (within the old rule of thumb), 100 m/s (a step's travel
 * is 17 times the wall's thickness) and 1000 m/s: it rests against the near
 * face (within two slops) from every start. */
static void fast_bodies_stop_at_a_thin_wall_at_any_speed(void **state) {
    static const double speeds[3] = {11.0, 100.0, 1000.0};
    const sx_shape wall = sx_box_shape(SX_R(0.05), SX_R(2.0));
    const sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
    int s, k;
    (void)state;
    for (s = 0; s < 3; ++s) {
        double travel = speeds[s] / (60.0 * sx_default_world_def().sub_steps);
        for (k = 0; k < 10; ++k) {
            sx_world *w = make_world(sx_v2_zero());
            sx_body_id b;
            sx_vec2 p;
            (void)add_body(w, SX_BODY_STATIC, sx_v2_zero(), SX_R(0.0), &wall, SX_R(0.0), SX_R(0.0),
                           SX_R(0.0));
            b = add_body(w, SX_BODY_DYNAMIC, sx_v2((sx_real)(-1.0 - 0.1 * k * travel), SX_R(0.0)),
                         SX_R(0.0), &ball, SX_R(1.0), SX_R(0.0), SX_R(0.0));
            assert_int_equal(
                sx_body_set_linear_velocity(w, b, sx_v2((sx_real)speeds[s], SX_R(0.0))), SX_OK);
            step_n(w, 30);
            p = sx_body_get_position(w, b);
            /* against the near face: centre at -0.1, within two slops */
            assert_true(p.x <= SX_R(-0.1) + SX_R(0.01));
            assert_true(p.x >= SX_R(-0.1) - SX_R(0.01));
            sx_world_destroy(w);
        }
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bounce_apex_over_drop_is_restitution_squared),
        cmocka_unit_test(bounce_with_zero_restitution_stays_on_the_ground),
        cmocka_unit_test(bounce_height_does_not_depend_on_the_sub_step_count),
        cmocka_unit_test(box_landing_flat_bounces_straight_without_spin),
        cmocka_unit_test(oblique_impact_with_friction_leaves_rolling),
        cmocka_unit_test(incline_box_sticks_when_friction_exceeds_tangent),
        cmocka_unit_test(incline_box_slides_with_coulomb_acceleration),
        cmocka_unit_test(incline_friction_mixes_as_geometric_mean),
        cmocka_unit_test(incline_friction_of_0_1_on_0_9_mixes_to_0_3),
        cmocka_unit_test(slow_impact_below_the_threshold_does_not_bounce),
        cmocka_unit_test(cradle_passes_the_speed_to_the_last_ball),
        cmocka_unit_test(cradle_with_the_default_world_passes_the_speed_to_the_last_ball),
        cmocka_unit_test(cradle_built_in_reverse_order_gives_the_same_answer),
        cmocka_unit_test(cradle_of_touching_balls_passes_the_speed_to_the_last_ball),
        cmocka_unit_test(cradle_with_two_moving_balls_sends_two_away),
        cmocka_unit_test(impacts_within_a_sub_step_are_resolved_in_time_order),
        cmocka_unit_test(cradle_is_bit_identical_when_run_twice),
        cmocka_unit_test(impact_impulse_is_reported_apart_from_the_iterations),
        cmocka_unit_test(ball_jammed_between_two_walls_ends_the_step_and_gains_no_energy),
        cmocka_unit_test(pileup_conserves_momentum_and_never_gains_energy),
        cmocka_unit_test(pyramid_of_base_20_stands_for_10_seconds),
        cmocka_unit_test(heavy_box_on_light_box_penetrates_less_than_two_slops),
        cmocka_unit_test(wide_plank_on_two_small_boxes_penetrates_less_than_a_third_of_a_slop),
        cmocka_unit_test(column_of_20_boxes_creeps_less_than_a_centimetre_in_10_seconds),
        cmocka_unit_test(column_far_from_the_origin_rests_as_at_the_origin),
        cmocka_unit_test(overlapping_pyramid_separates_without_gaining_speed),
        cmocka_unit_test(mixed_shapes_in_a_box_run_20_seconds_without_escaping_or_blowing_up),
        cmocka_unit_test(bouncy_pile_comes_to_rest),
        cmocka_unit_test(kinematic_paddle_pushes_a_box_without_being_pushed_back),
        cmocka_unit_test(fast_bodies_stop_at_a_thin_wall_at_any_speed),
    };
    return cmocka_run_group_tests_name("scenes", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
