/* sepax tests — the world API: settings, handles, bodies and colliders, mass
 * properties, forces and impulses, the step's stages, free flight against
 * symplectic Euler's closed form, bad input, determinism, filtering and
 * memory. Scenes with contacts and known physical answers are in
 * test_scenes.c. */
#include <limits.h>
#include <stdlib.h>
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

static sx_body_id make_body(sx_world *w, sx_body_type type, sx_vec2 p, const sx_shape *shape) {
    sx_body_def bd = sx_default_body_def();
    sx_body_id id;
    bd.type = type;
    bd.position = p;
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    if (shape != NULL) {
        sx_collider_def cd = sx_default_collider_def();
        cd.shape = *shape;
        assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    }
    return id;
}

/* ---- settings --------------------------------------------------------------- */

static void world_create_refuses_bad_settings_with_null(void **state) {
    sx_world_def d;
    sx_world *w;
    (void)state;
    assert_null(sx_world_create(NULL));
    d = sx_default_world_def();
    d.sub_steps = 0;
    assert_null(sx_world_create(&d));
    d = sx_default_world_def();
    d.velocity_iterations = 0;
    assert_null(sx_world_create(&d));
    d = sx_default_world_def();
    d.gravity.y = SX_R(0.0) / SX_R(0.0);
    assert_null(sx_world_create(&d));
    d = sx_default_world_def();
    d.restitution_threshold = SX_R(-1.0);
    assert_null(sx_world_create(&d));
    d = sx_default_world_def();
    d.length_units_per_meter = SX_R(0.0);
    assert_null(sx_world_create(&d));
    d = sx_default_world_def();
    d.correction_factor = SX_R(1.5);
    assert_null(sx_world_create(&d));
    d = sx_default_world_def();
    d.length_units_per_meter = SX_R(100.0);
    d.body_capacity = 100;
    w = sx_world_create(&d);
    assert_non_null(w);
    assert_near(sx_world_linear_slop(w), 0.5, SX_TEST_EPS);
    assert_int_equal(sx_world_body_count(w), 0);
    sx_world_destroy(w);
    sx_world_destroy(NULL);
}

/* Sets the int field of *d to its largest value (valid), one more and
 * INT_MAX (both SX_ERR_CAPACITY, and no world), and leaves it at the
 * largest. */
static void assert_bound(sx_world_def *d, int *field, int largest) {
    *field = largest;
    assert_int_equal(sx_world_def_validate(d, NULL), SX_OK);
    *field = largest + 1;
    assert_int_equal(sx_world_def_validate(d, NULL), SX_ERR_CAPACITY);
    *field = INT_MAX;
    assert_int_equal(sx_world_def_validate(d, NULL), SX_ERR_CAPACITY);
    assert_null(sx_world_create(d));
    *field = largest;
}

/* Regression (issue 28): body_capacity = INT_MAX made the capacity
 * doubling overflow an int, and sx_world_create looped forever at -O2; no
 * upper bound on sub_steps and the iteration counts let INT_MAX make a step
 * that never returns. Each refused value now has its status. */
static void world_def_validate_gives_the_reason_and_bounds_every_size(void **state) {
    sx_world_def d = sx_default_world_def();
    (void)state;
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_OK);
    assert_int_equal(sx_world_def_validate(NULL, NULL), SX_ERR_INVALID_ARG);
    d.sub_steps = 0;
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_ERR_INVALID_ARG);
    d = sx_default_world_def();
    d.time_to_sleep = SX_R(1.0) / SX_R(0.0);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_ERR_NONFINITE);
    d = sx_default_world_def();
    d.body_capacity = -1;
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_ERR_INVALID_ARG);
    /* each bound: accepted at the bound, refused one past it and at INT_MAX */
    d = sx_default_world_def();
    assert_bound(&d, &d.sub_steps, SX_MAX_SUB_STEPS);
    assert_bound(&d, &d.velocity_iterations, SX_MAX_ITERATIONS);
    assert_bound(&d, &d.position_iterations, SX_MAX_ITERATIONS);
    assert_bound(&d, &d.body_capacity, SX_WORLD_MAX_ITEMS);
}

/* An allocator that refuses any block above a limit and records the largest
 * request (a huge reservation is asked for, refused, and leaves nothing). */
typedef struct capped_allocator {
    size_t limit, largest;
} capped_allocator;

static void *capped_alloc(size_t size, void *context) {
    capped_allocator *c = (capped_allocator *)context;
    if (size > c->largest) c->largest = size;
    return size > c->limit ? NULL : malloc(size);
}

static void capped_free(void *memory, size_t size, void *context) {
    (void)size;
    (void)context;
    free(memory);
}

static void the_largest_body_capacity_is_asked_for_once_and_refused_cleanly(void **state) {
    capped_allocator c = {(size_t)1 << 24, 0};
    sx_world_def d = sx_default_world_def();
    size_t live = sx_live_bytes();
    (void)state;
    d.body_capacity = SX_WORLD_MAX_ITEMS;
    sx_set_allocator(capped_alloc, capped_free, &c);
    assert_null(sx_world_create(&d));
    sx_set_allocator(NULL, NULL, NULL);
    /* the exact reservation, not a doubled one: at least a byte per body,
     * and no more than a kilobyte per body */
    assert_true(c.largest >= (size_t)SX_WORLD_MAX_ITEMS);
    assert_true(c.largest / (size_t)SX_WORLD_MAX_ITEMS < 1024);
    assert_true(sx_live_bytes() == live);
}

/* An allocator that refuses everything (the solver's scratch then cannot
 * grow). */
static void *refusing_alloc(size_t size, void *context) {
    (void)size;
    (void)context;
    return NULL;
}

/* The velocity passes work on arrays the solve grows on its first call: when
 * they cannot grow, solve answers SX_ERR_NO_MEMORY and leaves the bodies as
 * they were (no pass on half-gathered data), and the next solve with memory
 * works. The same for the relax passes of soft contacts. */
static void solve_without_memory_for_its_arrays_refuses_and_changes_nothing(void **state) {
    sx_world_def d = sx_default_world_def();
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id b;
    sx_world *w;
    sx_vec2 v0, p0;
    sx_real h = DT / (sx_real)d.sub_steps;
    size_t live = sx_live_bytes();
    int soft;
    (void)state;
    for (soft = 0; soft < 2; ++soft) {
        d.contact_hertz = soft ? SX_R(30.0) : SX_R(0.0);
        w = sx_world_create(&d);
        assert_non_null(w);
        make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
        /* a little overlap, falling: the passes would change the velocity */
        b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.49)), &box);
        assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(0.0), SX_R(-1.0))), SX_OK);
        assert_int_equal(sx_world_begin_step(w, DT), SX_OK);
        assert_int_equal(sx_world_collide(w), SX_OK);
        assert_int_equal(sx_world_contact_count(w), 1);
        v0 = sx_body_get_linear_velocity(w, b);
        p0 = sx_body_get_position(w, b);
        sx_set_allocator(refusing_alloc, capped_free, NULL);
        assert_int_equal(sx_world_solve(w, h), SX_ERR_NO_MEMORY);
        assert_vec2_near(sx_body_get_linear_velocity(w, b), v0, 0.0);
        if (soft) {
            assert_int_equal(sx_world_separate(w, h), SX_ERR_NO_MEMORY);
            assert_vec2_near(sx_body_get_position(w, b), p0, 0.0);
        }
        sx_set_allocator(NULL, NULL, NULL);
        /* with memory: the contact stops the fall */
        assert_int_equal(sx_world_solve(w, h), SX_OK);
        assert_true(sx_body_get_linear_velocity(w, b).y > SX_R(-1e-3));
        assert_int_equal(sx_world_separate(w, h), SX_OK);
        sx_world_destroy(w);
    }
    assert_true(sx_live_bytes() == live);
}

/* A world at the largest sub-step and iteration counts steps, and returns. */
static void a_world_at_the_largest_step_counts_steps_and_returns(void **state) {
    sx_world_def d = sx_default_world_def();
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ground, box;
    sx_world *w;
    sx_vec2 p;
    (void)state;
    d.sub_steps = SX_MAX_SUB_STEPS;
    d.velocity_iterations = SX_MAX_ITERATIONS;
    d.position_iterations = SX_MAX_ITERATIONS;
    w = sx_world_create(&d);
    assert_non_null(w);
    bd.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    cd.shape = sx_box_shape(SX_R(5.0), SX_R(1.0));
    assert_int_equal(sx_create_body(w, &bd, &ground), SX_OK);
    assert_int_equal(sx_body_add_collider(w, ground, &cd, NULL), SX_OK);
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(0.0), SX_R(0.5));
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
    assert_int_equal(sx_create_body(w, &bd, &box), SX_OK);
    assert_int_equal(sx_body_add_collider(w, box, &cd, NULL), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    /* resting on the ground: within a slop of where it started */
    p = sx_body_get_position(w, box);
    assert_near(p.y, 0.5, 0.005);
    assert_near(p.x, 0.0, 1e-4);
    sx_world_destroy(w);
}

/* ---- handles ------------------------------------------------------------------ */

static void body_handles_pack_into_u64_and_go_stale_after_destroy(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_body_id a, b, null_id = {0, 0};
    uint64_t bits;
    (void)state;
    a = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), NULL);
    bits = sx_body_id_to_u64(a);
    assert_true(bits != 0);
    assert_true(sx_body_id_to_u64(sx_body_id_from_u64(bits)) == bits);
    assert_true(sx_body_id_to_u64(null_id) == 0);
    assert_true(sx_body_id_is_null(sx_body_id_from_u64(0)));
    assert_false(sx_body_is_valid(w, null_id));
    assert_true(sx_body_is_valid(w, a));
    assert_int_equal(sx_destroy_body(w, a), SX_OK);
    assert_false(sx_body_is_valid(w, a));
    assert_int_equal(sx_destroy_body(w, a), SX_ERR_STALE_HANDLE);
    /* the slot is reused under a new generation: the old handle stays dead */
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(1.0), SX_R(2.0)), NULL);
    assert_int_equal(b.index, a.index);
    assert_true(b.generation != a.generation);
    assert_false(sx_body_is_valid(w, a));
    assert_int_equal(sx_body_set_linear_velocity(w, a, sx_v2_zero()), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_apply_force(w, a, sx_v2_zero()), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_set_transform(w, a, sx_v2_zero(), SX_R(0.0)), SX_ERR_STALE_HANDLE);
    /* getters on a stale handle answer zeros, and never the new body's data */
    assert_vec2_near(sx_body_get_position(w, a), sx_v2_zero(), 0.0);
    assert_vec2_near(sx_body_get_position(w, b), sx_v2(SX_R(1.0), SX_R(2.0)), 0.0);
    assert_int_equal(sx_world_body_count(w), 1);
    sx_world_destroy(w);
}

static void create_body_rejects_bad_definitions(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_body_def d;
    sx_body_id id;
    (void)state;
    d = sx_default_body_def();
    assert_int_equal(sx_create_body(NULL, &d, &id), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_create_body(w, NULL, &id), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_create_body(w, &d, NULL), SX_ERR_INVALID_ARG);
    d.type = (sx_body_type)7;
    assert_int_equal(sx_create_body(w, &d, &id), SX_ERR_INVALID_ARG);
    assert_true(sx_body_id_is_null(id));
    d = sx_default_body_def();
    d.position.x = SX_R(1.0) / SX_R(0.0);
    assert_int_equal(sx_create_body(w, &d, &id), SX_ERR_NONFINITE);
    d = sx_default_body_def();
    d.linear_damping = SX_R(-0.5);
    assert_int_equal(sx_create_body(w, &d, &id), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_body_count(w), 0);
    sx_world_destroy(w);
}

static void add_collider_validates_shape_and_material(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), NULL), stale;
    sx_collider_def d;
    sx_collider_id c;
    (void)state;
    d = sx_default_collider_def();
    d.shape = sx_circle_shape(sx_v2_zero(), SX_R(-1.0));
    assert_int_equal(sx_body_add_collider(w, b, &d, &c), SX_ERR_INVALID_ARG);
    assert_false(sx_collider_is_valid(w, c));
    d.shape = sx_circle_shape(sx_v2(SX_R(0.0) / SX_R(0.0), SX_R(0.0)), SX_R(1.0));
    assert_int_equal(sx_body_add_collider(w, b, &d, &c), SX_ERR_NONFINITE);
    d.shape = sx_segment_shape(sx_v2_zero(), sx_v2_zero());
    assert_int_equal(sx_body_add_collider(w, b, &d, &c), SX_ERR_DEGENERATE);
    d = sx_default_collider_def();
    d.density = SX_R(-1.0);
    assert_int_equal(sx_body_add_collider(w, b, &d, &c), SX_ERR_INVALID_ARG);
    d = sx_default_collider_def();
    d.friction = SX_R(-0.1);
    assert_int_equal(sx_body_add_collider(w, b, &d, &c), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_add_collider(w, b, NULL, &c), SX_ERR_INVALID_ARG);
    d = sx_default_collider_def();
    assert_int_equal(sx_body_add_collider(w, b, &d, &c), SX_OK);
    assert_true(sx_collider_is_valid(w, c));
    assert_true(sx_body_id_to_u64(sx_collider_get_body(w, c)) == sx_body_id_to_u64(b));
    stale = b;
    assert_int_equal(sx_destroy_body(w, b), SX_OK);
    assert_false(sx_collider_is_valid(w, c));
    assert_int_equal(sx_body_add_collider(w, stale, &d, &c), SX_ERR_STALE_HANDLE);
    sx_world_destroy(w);
}

/* ---- mass ---------------------------------------------------------------------- */

static void mass_and_inertia_come_from_collider_density(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box = sx_box_shape(SX_R(1.0), SX_R(0.5));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(3.0), SX_R(4.0)), NULL), s;
    sx_collider_def d = sx_default_collider_def();
    sx_collider_id second;
    (void)state;
    /* no collider yet: a unit mass that does not rotate */
    assert_near(sx_body_get_mass(w, b), 1.0, 0.0);
    assert_near(sx_body_get_inertia(w, b), 0.0, 0.0);
    d.shape = box;
    d.density = SX_R(2.0);
    assert_int_equal(sx_body_add_collider(w, b, &d, NULL), SX_OK);
    /* 2 x 1 box of density 2: m = 4, I = m (w^2 + h^2) / 12 */
    assert_near(sx_body_get_mass(w, b), 4.0, 4.0 * SX_TEST_EPS);
    assert_near(sx_body_get_inertia(w, b), 4.0 * 5.0 / 12.0, 4.0 * SX_TEST_EPS);
    /* a second, equal box offset by 2 in x: centre of mass moves to x = 1,
     * inertia gains m d^2 for each box about the new centre */
    d.shape = sx_offset_box_shape(SX_R(1.0), SX_R(0.5), sx_v2(SX_R(2.0), SX_R(0.0)), SX_R(0.0));
    assert_int_equal(sx_body_add_collider(w, b, &d, &second), SX_OK);
    assert_near(sx_body_get_mass(w, b), 8.0, 8.0 * SX_TEST_EPS);
    assert_vec2_near(sx_body_get_local_center(w, b), sx_v2(SX_R(1.0), SX_R(0.0)), SX_TEST_EPS);
    assert_vec2_near(sx_body_get_world_center(w, b), sx_v2(SX_R(4.0), SX_R(4.0)),
                     4.0 * SX_TEST_EPS);
    assert_near(sx_body_get_inertia(w, b), 2.0 * (4.0 * 5.0 / 12.0 + 4.0), 16.0 * SX_TEST_EPS);
    /* the origin stays put when the centre of mass moves */
    assert_vec2_near(sx_body_get_position(w, b), sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    assert_int_equal(sx_destroy_collider(w, second), SX_OK);
    assert_near(sx_body_get_mass(w, b), 4.0, 4.0 * SX_TEST_EPS);
    assert_int_equal(sx_destroy_collider(w, second), SX_ERR_STALE_HANDLE);
    /* static bodies have no mass; becoming dynamic gives it back */
    s = make_body(w, SX_BODY_STATIC, sx_v2_zero(), &box);
    assert_near(sx_body_get_mass(w, s), 0.0, 0.0);
    assert_int_equal(sx_body_set_type(w, s, SX_BODY_DYNAMIC), SX_OK);
    assert_near(sx_body_get_mass(w, s), 2.0, 2.0 * SX_TEST_EPS);
    assert_int_equal(sx_body_set_type(w, s, (sx_body_type)9), SX_ERR_INVALID_ARG);
    sx_world_destroy(w);
}

/* ---- free flight ----------------------------------------------------------------- */

static void free_flight_matches_symplectic_euler_bit_for_bit(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.25));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(1.0), SX_R(2.0)), &ball);
    sx_vec2 v0 = sx_v2(SX_R(3.0), SX_R(5.0)), x0 = sx_v2(SX_R(1.0), SX_R(2.0));
    sx_vec2 g = sx_v2(SX_R(0.0), SX_R(-10.0));
    sx_vec2 x = x0, v = v0;
    sx_real h = DT / (sx_real)sx_default_world_def().sub_steps;
    int n, k, sub = sx_default_world_def().sub_steps;
    (void)state;
    assert_int_equal(sx_body_set_linear_velocity(w, b, v0), SX_OK);
    for (n = 1; n <= 120; ++n) {
        double t, hd = (double)h, steps;
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        /* the reference: velocity first, then position with the new velocity */
        for (k = 0; k < sub; ++k) {
            v.x = v.x + h * g.x;
            v.y = v.y + h * g.y;
            x.x = x.x + h * v.x;
            x.y = x.y + h * v.y;
        }
        assert_true(sx_body_get_position(w, b).x == x.x);
        assert_true(sx_body_get_position(w, b).y == x.y);
        assert_true(sx_body_get_linear_velocity(w, b).x == v.x);
        assert_true(sx_body_get_linear_velocity(w, b).y == v.y);
        /* closed form of symplectic Euler after m = n * sub steps of h:
         * x_m = x0 + m h v0 + h^2 g m (m + 1) / 2, up to float rounding */
        steps = (double)(n * sub);
        assert_near(x.y, 2.0 + steps * hd * 5.0 - 10.0 * hd * hd * steps * (steps + 1.0) / 2.0,
                    200.0 * SX_TEST_EPS);
        /* the parabola, within the method's first-order error |g| h t / 2 */
        t = steps * hd;
        assert_near(x.y, 2.0 + 5.0 * t - 5.0 * t * t, 10.0 * hd * t / 2.0 + 200.0 * SX_TEST_EPS);
        assert_near(x.x, 1.0 + 3.0 * t, 100.0 * SX_TEST_EPS);
    }
    assert_int_equal(sx_world_contact_count(w), 0);
    sx_world_destroy(w);
}

/* ---- forces and impulses ------------------------------------------------------- */

static void forces_and_impulses_accumulate_and_clear(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &box);
    double m = (double)sx_body_get_mass(w, b), inertia = (double)sx_body_get_inertia(w, b);
    sx_vec2 v;
    (void)state;
    assert_near(m, 1.0, SX_TEST_EPS);
    assert_int_equal(sx_body_apply_force(w, b, sx_v2(SX_R(3.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_apply_force(w, b, sx_v2(SX_R(3.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    /* both forces act over the whole step: dv = 6 N x dt / m */
    assert_near(sx_body_get_linear_velocity(w, b).x, 6.0 * (double)DT / m, 10.0 * SX_TEST_EPS);
    v = sx_body_get_linear_velocity(w, b);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_vec2_near(sx_body_get_linear_velocity(w, b), v, 0.0);

    assert_int_equal(sx_body_apply_impulse(w, b, sx_v2(SX_R(0.0), SX_R(1.0))), SX_OK);
    assert_int_equal(sx_body_apply_impulse(w, b, sx_v2(SX_R(0.0), SX_R(1.0))), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_near(sx_body_get_linear_velocity(w, b).y, 2.0 / m, SX_TEST_EPS);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_near(sx_body_get_linear_velocity(w, b).y, 2.0 / m, SX_TEST_EPS);

    /* off-centre: an impulse (0, 1) at one unit right of the centre adds
     * angular impulse 1 on top of the linear one */
    assert_int_equal(sx_body_apply_impulse_at_point(
                         w, b, sx_v2(SX_R(0.0), SX_R(1.0)),
                         sx_add(sx_body_get_world_center(w, b), sx_v2(SX_R(1.0), SX_R(0.0)))),
                     SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_near(sx_body_get_linear_velocity(w, b).y, 3.0 / m, 2.0 * SX_TEST_EPS);
    assert_near(sx_body_get_angular_velocity(w, b), 1.0 / inertia, 10.0 * SX_TEST_EPS);
    /* a force at a point: torque r x F over the step */
    assert_int_equal(sx_body_set_angular_velocity(w, b, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_body_apply_force_at_point(
                         w, b, sx_v2(SX_R(0.0), SX_R(-2.0)),
                         sx_add(sx_body_get_world_center(w, b), sx_v2(SX_R(0.5), SX_R(0.0)))),
                     SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_near(sx_body_get_angular_velocity(w, b), -1.0 * (double)DT / inertia,
                10.0 * SX_TEST_EPS);
    assert_int_equal(sx_body_apply_torque(w, b, SX_R(1.0) / SX_R(0.0)), SX_ERR_NONFINITE);
    assert_int_equal(sx_body_apply_force(NULL, b, sx_v2_zero()), SX_ERR_INVALID_ARG);
    sx_world_destroy(w);
}

static void static_and_kinematic_bodies_ignore_forces_and_gravity(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id s = make_body(w, SX_BODY_STATIC, sx_v2_zero(), &box);
    sx_body_id k = make_body(w, SX_BODY_KINEMATIC, sx_v2(SX_R(5.0), SX_R(0.0)), &box);
    int i;
    (void)state;
    assert_int_equal(sx_body_apply_force(w, s, sx_v2(SX_R(100.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_apply_impulse(w, s, sx_v2(SX_R(100.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_apply_impulse(w, k, sx_v2(SX_R(100.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, s, sx_v2(SX_R(1.0), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, k, sx_v2(SX_R(0.0), SX_R(1.0))), SX_OK);
    for (i = 0; i < 60; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_vec2_near(sx_body_get_position(w, s), sx_v2_zero(), 0.0);
    assert_vec2_near(sx_body_get_linear_velocity(w, s), sx_v2_zero(), 0.0);
    /* the kinematic body moves by its velocity only (1 m/s for 1 s) */
    assert_vec2_near(sx_body_get_position(w, k), sx_v2(SX_R(5.0), SX_R(1.0)), 100.0 * SX_TEST_EPS);
    assert_near(sx_body_get_mass(w, k), 0.0, 0.0);
    sx_world_destroy(w);
}

static void teleport_sets_position_and_angle(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box =
        sx_offset_box_shape(SX_R(0.5), SX_R(0.5), sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.0));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), &box);
    (void)state;
    assert_int_equal(sx_body_set_transform(w, b, sx_v2(SX_R(2.0), SX_R(3.0)), SX_R(0.5) * SX_PI),
                     SX_OK);
    assert_vec2_near(sx_body_get_position(w, b), sx_v2(SX_R(2.0), SX_R(3.0)), 0.0);
    assert_near(sx_body_get_angle(w, b), 0.5 * (double)SX_PI, SX_TEST_EPS);
    /* the centre of mass (local (1, 0)) turned a quarter */
    assert_vec2_near(sx_body_get_world_center(w, b), sx_v2(SX_R(2.0), SX_R(4.0)), SX_TEST_EPS);
    assert_int_equal(
        sx_body_set_transform(w, b, sx_v2(SX_R(0.0) / SX_R(0.0), SX_R(0.0)), SX_R(0.0)),
        SX_ERR_NONFINITE);
    assert_vec2_near(sx_body_get_position(w, b), sx_v2(SX_R(2.0), SX_R(3.0)), 0.0);
    sx_world_destroy(w);
}

/* ---- the step ------------------------------------------------------------------- */

/* A small scene with contacts: boxes and circles dropped on a ground box. */
static sx_world *make_drop_scene(sx_body_id *ids, int n) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(20.0), SX_R(1.0));
    sx_test_rng rng = sx_test_rng_make(77u);
    int i;
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
    for (i = 0; i < n; ++i) {
        sx_shape s = (i % 2) ? sx_box_shape(SX_R(0.4), SX_R(0.3))
                             : sx_circle_shape(sx_v2_zero(), SX_R(0.35));
        sx_vec2 p = sx_v2(sx_test_rng_range(&rng, -3.0, 3.0), sx_test_rng_range(&rng, 0.5, 6.0));
        ids[i] = make_body(w, SX_BODY_DYNAMIC, p, &s);
        assert_int_equal(
            sx_body_set_angular_velocity(w, ids[i], sx_test_rng_range(&rng, -3.0, 3.0)), SX_OK);
    }
    return w;
}

static void step_with_bad_time_step_returns_status_and_changes_nothing(void **state) {
    sx_body_id ids[6];
    sx_world *w = make_drop_scene(ids, 6);
    sx_real bad[3];
    sx_vec2 before[6];
    int i, k;
    (void)state;
    bad[0] = SX_R(0.0) / SX_R(0.0);
    bad[1] = SX_R(1.0) / SX_R(0.0);
    bad[2] = -SX_R(1.0) / SX_R(0.0);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    for (i = 0; i < 6; ++i)
        before[i] = sx_body_get_position(w, ids[i]);
    assert_int_equal(sx_world_step(w, SX_R(0.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_step(w, SX_R(-0.01)), SX_ERR_INVALID_ARG);
    for (k = 0; k < 3; ++k) {
        assert_int_equal(sx_world_step(w, bad[k]), SX_ERR_NONFINITE);
        assert_int_equal(sx_world_apply_forces(w, bad[k]), SX_ERR_NONFINITE);
        assert_int_equal(sx_world_solve(w, bad[k]), SX_ERR_NONFINITE);
        assert_int_equal(sx_world_integrate(w, bad[k]), SX_ERR_NONFINITE);
        assert_int_equal(sx_world_separate(w, bad[k]), SX_ERR_NONFINITE);
    }
    assert_int_equal(sx_world_integrate(w, SX_R(0.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_step(NULL, DT), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_collide(NULL), SX_ERR_INVALID_ARG);
    for (i = 0; i < 6; ++i)
        assert_vec2_near(sx_body_get_position(w, ids[i]), before[i], 0.0);
    sx_world_destroy(w);
}

static void same_calls_give_bit_identical_state(void **state) {
    sx_body_id a[12], b[12];
    sx_world *wa = make_drop_scene(a, 12), *wb = make_drop_scene(b, 12);
    int i, s;
    (void)state;
    for (s = 0; s < 120; ++s) {
        assert_int_equal(sx_world_step(wa, DT), SX_OK);
        assert_int_equal(sx_world_step(wb, DT), SX_OK);
    }
    assert_true(sx_world_contact_count(wa) > 0);
    for (i = 0; i < 12; ++i) {
        sx_xform xa = sx_body_get_transform(wa, a[i]), xb = sx_body_get_transform(wb, b[i]);
        sx_vec2 va = sx_body_get_linear_velocity(wa, a[i]),
                vb = sx_body_get_linear_velocity(wb, b[i]);
        assert_memory_equal(&xa, &xb, sizeof(xa));
        assert_memory_equal(&va, &vb, sizeof(va));
    }
    sx_world_destroy(wa);
    sx_world_destroy(wb);
}

static void stages_called_one_by_one_equal_the_step(void **state) {
    sx_body_id a[8], b[8];
    sx_world *wa = make_drop_scene(a, 8), *wb = make_drop_scene(b, 8);
    sx_real h = DT / (sx_real)sx_default_world_def().sub_steps;
    int i, s, k;
    (void)state;
    for (s = 0; s < 90; ++s) {
        assert_int_equal(sx_world_step(wa, DT), SX_OK);
        assert_int_equal(sx_world_begin_step(wb, DT), SX_OK);
        assert_int_equal(sx_world_collide(wb), SX_OK);
        for (k = 0; k < sx_default_world_def().sub_steps; ++k) {
            assert_int_equal(sx_world_apply_forces(wb, h), SX_OK);
            assert_int_equal(sx_world_solve(wb, h), SX_OK);
            assert_int_equal(sx_world_integrate(wb, h), SX_OK);
            assert_int_equal(sx_world_separate(wb, h), SX_OK);
        }
        assert_int_equal(sx_world_continuous(wb), SX_OK);
        assert_int_equal(sx_world_clear_forces(wb), SX_OK);
    }
    for (i = 0; i < 8; ++i) {
        sx_xform xa = sx_body_get_transform(wa, a[i]), xb = sx_body_get_transform(wb, b[i]);
        assert_memory_equal(&xa, &xb, sizeof(xa));
    }
    sx_world_destroy(wa);
    sx_world_destroy(wb);
}

static void resting_box_contact_carries_its_weight(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id b;
    sx_contact_data c;
    sx_real h = DT / (sx_real)sx_default_world_def().sub_steps;
    (void)state;
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box);
    {
        int i;
        for (i = 0; i < 120; ++i)
            assert_int_equal(sx_world_step(w, DT), SX_OK);
    }
    assert_int_equal(sx_world_contact_count(w), 1);
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    assert_int_equal(c.count, 2);
    /* the two points share the weight m g over one sub-step h, and the
     * normal points from the ground (A, the first created) up to the box */
    assert_near(c.normal_impulses[0] + c.normal_impulses[1], 10.0 * (double)h,
                1e-3 * 10.0 * (double)h);
    assert_near(c.normal_impulses[0], c.normal_impulses[1], 1e-2 * 10.0 * (double)h);
    assert_vec2_near(c.normal, sx_v2(SX_R(0.0), SX_R(1.0)), SX_TEST_EPS);
    assert_near(sx_body_get_position(w, b).y, 0.5, (double)sx_world_linear_slop(w));
    assert_int_equal(sx_world_get_contact(w, 1, &c), SX_ERR_INVALID_ARG);
    sx_world_destroy(w);
}

static void filtered_pairs_and_sensors_make_no_contacts(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ids[8];
    int i;
    (void)state;
    bd.type = SX_BODY_DYNAMIC;
    /* pairs of overlapping circles, each pair filtered one way */
    for (i = 0; i < 8; ++i) {
        bd.position = sx_v2(SX_R(10.0) * (sx_real)(i / 2), SX_R(0.5) * (sx_real)(i % 2));
        assert_int_equal(sx_create_body(w, &bd, &ids[i]), SX_OK);
        cd = sx_default_collider_def();
        if (i / 2 == 0) cd.filter.mask = (i % 2) ? 0xFFFFFFFFu : 0xFFFFFFFEu; /* masked out */
        if (i / 2 == 1) cd.filter.group = -3;                                 /* never */
        if (i / 2 == 2) cd.sensor = (i % 2) == 1;                             /* sensor */
        if (i / 2 == 3) {                                                     /* group wins */
            cd.filter.group = 5;
            cd.filter.mask = 0;
        }
        assert_int_equal(sx_body_add_collider(w, ids[i], &cd, NULL), SX_OK);
    }
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 1);
    {
        sx_contact_data c;
        assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
        assert_true(sx_body_id_to_u64(c.body_a) == sx_body_id_to_u64(ids[6]));
        assert_true(sx_body_id_to_u64(c.body_b) == sx_body_id_to_u64(ids[7]));
    }
    sx_world_destroy(w);
}

/* ---- kept manifolds ------------------------------------------------------- */

/* A world without gravity that keeps manifolds by `keep` slops; a body
 * `under` (static ground, top at y = 0, when NULL) and a box of
 * half-extent `h` at p turned by `angle` over it, collided once. */
static sx_world *keep_world(sx_real keep, const sx_collider_def *under, sx_vec2 under_p,
                            sx_real h, sx_vec2 p, sx_real angle, sx_body_id *box) {
    sx_world_def def = sx_default_world_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_world *w;
    def.gravity = sx_v2_zero();
    def.manifold_keep_slops = keep;
    w = sx_world_create(&def);
    assert_non_null(w);
    if (under == NULL) {
        sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0));
        make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
    } else {
        sx_test_body_turned(w, SX_BODY_STATIC, under_p, SX_R(0.0), under);
    }
    cd.shape = sx_box_shape(h, h);
    *box = sx_test_body_turned(w, SX_BODY_DYNAMIC, p, angle, &cd);
    assert_int_equal(sx_world_collide(w), SX_OK);
    return w;
}

/* The one contact of worlds a and b agree to tol. */
static void assert_same_contact(sx_world *a, sx_world *b, double tol) {
    sx_contact_data ca, cb;
    int k;
    assert_int_equal(sx_world_contact_count(a), 1);
    assert_int_equal(sx_world_contact_count(b), 1);
    assert_int_equal(sx_world_get_contact(a, 0, &ca), SX_OK);
    assert_int_equal(sx_world_get_contact(b, 0, &cb), SX_OK);
    assert_int_equal(ca.count, cb.count);
    assert_near(ca.normal.x, cb.normal.x, tol);
    assert_near(ca.normal.y, cb.normal.y, tol);
    for (k = 0; k < ca.count; ++k) {
        assert_near(ca.points[k].x, cb.points[k].x, tol);
        assert_near(ca.points[k].y, cb.points[k].y, tol);
        assert_near(ca.depths[k], cb.depths[k], tol);
    }
}

/* A box resting on the ground keeps its manifold while it moves less than
 * manifold_keep_slops (the points follow half its move, the depths all of
 * its move along the normal: within the tolerance of a fresh search), and
 * gets the fresh search's answer once it moves farther. */
static void a_kept_manifold_follows_small_moves_and_is_found_again_past_the_tolerance(
    void **state) {
    const sx_real keep = SX_R(0.1), tol = keep * SX_R(0.005);
    const sx_vec2 p0 = sx_v2(SX_R(0.3), SX_R(0.499));
    sx_vec2 p1 = sx_v2(p0.x + SX_R(0.4) * tol, p0.y + SX_R(0.2) * tol);
    sx_vec2 p2 = sx_v2(p0.x + SX_R(2.0) * tol, p0.y);
    sx_body_id box, fresh_box;
    sx_world *w = keep_world(keep, NULL, sx_v2_zero(), SX_R(0.5), p0, SX_R(0.0), &box), *fresh;
    sx_contact_data c0, c1;
    int k;
    (void)state;
    assert_int_equal(sx_world_get_contact(w, 0, &c0), SX_OK);
    assert_int_equal(c0.count, 2);
    /* within the tolerance: kept */
    assert_int_equal(sx_body_set_transform(w, box, p1, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_get_contact(w, 0, &c1), SX_OK);
    assert_int_equal(c1.count, 2);
    for (k = 0; k < 2; ++k) {
        assert_near(c1.points[k].x, c0.points[k].x + SX_R(0.2) * tol, 1e-6);
        assert_near(c1.points[k].y, c0.points[k].y + SX_R(0.1) * tol, 1e-6);
        assert_near(c1.depths[k], c0.depths[k] - SX_R(0.2) * tol, 1e-6);
    }
    fresh = keep_world(SX_R(0.0), NULL, sx_v2_zero(), SX_R(0.5), p1, SX_R(0.0), &fresh_box);
    assert_same_contact(w, fresh, tol);
    sx_world_destroy(fresh);
    /* past it: searched again */
    assert_int_equal(sx_body_set_transform(w, box, p2, SX_R(0.0)), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    fresh = keep_world(SX_R(0.0), NULL, sx_v2_zero(), SX_R(0.5), p2, SX_R(0.0), &fresh_box);
    assert_same_contact(w, fresh, 1e-6);
    sx_world_destroy(fresh);
    sx_world_destroy(w);
}

/* A big box resting its face on a diamond's corner: the face is the
 * reference, so the normal turns with the box. Turned about the contact
 * point by four times the keep angle, the box's point stays where it was,
 * and only the turn says the manifold must be found again. */
static void a_kept_manifold_is_found_again_when_the_box_turns_about_its_point(void **state) {
    const sx_real keep = SX_R(0.1), turn = SX_R(4.0) * keep * SX_R(0.005);
    sx_collider_def diamond = sx_default_collider_def();
    sx_vec2 corner, p0 = sx_v2(SX_R(0.2), SX_R(2.0) - SX_R(0.001)), p1;
    sx_vec2 v[4] = {{SX_R(0.0), SX_R(-1.0)}, {SX_R(1.0), SX_R(0.0)}, {SX_R(0.0), SX_R(1.0)},
                    {SX_R(-1.0), SX_R(0.0)}};
    sx_body_id box, fresh_box;
    sx_world *w, *fresh;
    sx_rot q = sx_rot_make(turn);
    (void)state;
    assert_int_equal(sx_polygon_shape(v, 4, SX_R(0.0), &diamond.shape), SX_OK);
    /* the diamond's top corner at (0, 1); the box's bottom face 1 mm below it */
    w = keep_world(keep, &diamond, sx_v2_zero(), SX_R(1.0), p0, SX_R(0.0), &box);
    corner = sx_v2(SX_R(0.0), SX_R(1.0));
    p1 = sx_add(corner, sx_rotate(q, sx_sub(p0, corner)));
    assert_int_equal(sx_body_set_transform(w, box, p1, turn), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    fresh = keep_world(SX_R(0.0), &diamond, sx_v2_zero(), SX_R(1.0), p1, turn, &fresh_box);
    assert_same_contact(w, fresh, 1e-6);
    sx_world_destroy(fresh);
    sx_world_destroy(w);
}

/* A tilted box touching the ground at one corner, its other corner beyond
 * the speculative margin: one point. Given a speed that brings the other
 * corner within the step's reach, the pair is searched again (a kept
 * one-point manifold would miss the second corner). */
static void a_kept_one_point_manifold_is_found_again_when_the_margin_grows(void **state) {
    const sx_real angle = SX_R(0.1);
    sx_real lift = SX_R(0.5) * (sx_cos(angle) + sx_sin(angle)) - SX_R(0.001);
    sx_body_id box;
    sx_world *w = keep_world(SX_R(0.1), NULL, sx_v2_zero(), SX_R(0.5),
                             sx_v2(SX_R(0.0), lift), angle, &box);
    sx_contact_data c;
    (void)state;
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    assert_int_equal(c.count, 1);
    /* a step at rest sets the step's length; then 6 m/s down reaches 0.1 m */
    assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    assert_int_equal(c.count, 1);
    assert_int_equal(sx_body_set_linear_velocity(w, box, sx_v2(SX_R(0.0), SX_R(-6.0))), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    assert_int_equal(c.count, 2);
    sx_world_destroy(w);
}

/* Six boxes side by side at x = 0, 3, .., 15 (their contacts one colour of
 * the wide passes), each on a static support of half-width `support` (0:
 * one wide ground), gravity 10, no sleeping; settled for a second. */
#define ROW_BOXES 6
static sx_world *row_world(sx_real support, sx_body_id *boxes, sx_collider_id *colliders) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    int i;
    def.gravity = sx_v2(SX_R(0.0), SX_R(-10.0));
    def.enable_sleep = false;
    w = sx_world_create(&def);
    assert_non_null(w);
    if (!(support > SX_R(0.0))) {
        sx_shape ground = sx_box_shape(SX_R(20.0), SX_R(1.0));
        make_body(w, SX_BODY_STATIC, sx_v2(SX_R(7.5), SX_R(-1.0)), &ground);
    }
    for (i = 0; i < ROW_BOXES; ++i) {
        sx_real x = SX_R(3.0) * (sx_real)i;
        if (support > SX_R(0.0)) {
            sx_shape post = sx_box_shape(support, SX_R(0.5));
            make_body(w, SX_BODY_STATIC, sx_v2(x, SX_R(-0.5)), &post);
        }
        boxes[i] = sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(x, SX_R(0.5)),
                                sx_box_shape(SX_R(0.5), SX_R(0.5)), &colliders[i]);
    }
    for (i = 0; i < 60; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    return w;
}

/* Pushed by 0.3 of its weight, a box that friction 0.6 held slides at once
 * when its friction goes to 0: 0.05 m/s after one step, and no faster or
 * slower after a second step without the push. Two ways to miss it: a
 * solver lane that outlasts the collide while the manifold is kept must
 * still take the new friction, and the tangent impulse that held the box
 * must not warm-start a contact whose tangent rows are no longer solved. */
static void a_box_slides_at_once_when_its_friction_goes_to_zero(void **state) {
    sx_body_id boxes[ROW_BOXES];
    sx_collider_id colliders[ROW_BOXES];
    sx_world *w = row_world(SX_R(0.0), boxes, colliders);
    sx_real push = SX_R(0.3) * SX_R(10.0) * sx_body_get_mass(w, boxes[0]);
    int i, s;
    (void)state;
    for (s = 0; s < 30; ++s) {
        for (i = 0; i < ROW_BOXES; ++i)
            assert_int_equal(sx_body_apply_force(w, boxes[i], sx_v2(push, SX_R(0.0))), SX_OK);
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    }
    for (i = 0; i < ROW_BOXES; ++i) {
        assert_near(sx_body_get_linear_velocity(w, boxes[i]).x, 0.0, 1e-4);
        assert_int_equal(sx_collider_set_friction(w, colliders[i], SX_R(0.0)), SX_OK);
        assert_int_equal(sx_body_apply_force(w, boxes[i], sx_v2(push, SX_R(0.0))), SX_OK);
    }
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    for (i = 0; i < ROW_BOXES; ++i)
        assert_near(sx_body_get_linear_velocity(w, boxes[i]).x, SX_R(0.3) * SX_R(10.0) * DT, 1e-3);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    for (i = 0; i < ROW_BOXES; ++i)
        assert_near(sx_body_get_linear_velocity(w, boxes[i]).x, SX_R(0.3) * SX_R(10.0) * DT, 1e-3);
    sx_world_destroy(w);
}

/* Each box's larger normal impulse over its smaller one, after a step. */
static void assert_support_split(sx_world *w, double ratio, double tol) {
    int i, n = sx_world_contact_count(w);
    assert_int_equal(n, ROW_BOXES);
    for (i = 0; i < n; ++i) {
        sx_contact_data c;
        sx_real lo, hi;
        assert_int_equal(sx_world_get_contact(w, i, &c), SX_OK);
        assert_int_equal(c.count, 2);
        /* the point further right carries more (the box is right of the middle) */
        lo = c.points[0].x < c.points[1].x ? c.normal_impulses[0] : c.normal_impulses[1];
        hi = c.points[0].x < c.points[1].x ? c.normal_impulses[1] : c.normal_impulses[0];
        assert_true(lo > SX_R(0.0));
        assert_near(hi / lo, ratio, tol);
    }
}

/* A box moved past the keep tolerance gets its manifold searched again and
 * its lane filled again, so its levers follow: 0.1 m right of the middle of
 * a 0.4 m wide post, a box rests 3:1 on the post's corners. So does a box
 * whose manifold a collide without a solve searched (the next collide keeps
 * it, but the lane is older than it): moved back, it rests 1:1 again. */
static void a_lane_is_filled_again_when_its_manifold_was_searched_since(void **state) {
    sx_body_id boxes[ROW_BOXES];
    sx_collider_id colliders[ROW_BOXES];
    sx_world *w = row_world(SX_R(0.2), boxes, colliders);
    int i;
    (void)state;
    assert_support_split(w, 1.0, 0.02);
    for (i = 0; i < ROW_BOXES; ++i) {
        sx_vec2 p = sx_body_get_position(w, boxes[i]);
        assert_int_equal(sx_body_set_transform(w, boxes[i], sx_v2(p.x + SX_R(0.1), p.y),
                                               sx_body_get_angle(w, boxes[i])),
                         SX_OK);
    }
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_support_split(w, 3.0, 0.1);
    for (i = 0; i < ROW_BOXES; ++i) {
        sx_vec2 p = sx_body_get_position(w, boxes[i]);
        assert_int_equal(sx_body_set_transform(w, boxes[i], sx_v2(p.x - SX_R(0.1), p.y),
                                               sx_body_get_angle(w, boxes[i])),
                         SX_OK);
    }
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_support_split(w, 1.0, 0.1);
    sx_world_destroy(w);
}

/* Two boxes touching face to face in free space, turned together by a
 * quarter turn about their middle: their relative pose is the same, so the
 * kept manifold answers, but the contact's normal and levers are world
 * vectors and must turn with them (a held contact keeps them only while A
 * turned less than the keep angle). */
static void a_kept_pair_turned_together_gets_turned_normal(void **state) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_body_id a, b;
    sx_contact_data c;
    sx_real quarter = SX_R(1.5707963267948966);
    (void)state;
    def.gravity = sx_v2_zero();
    w = sx_world_create(&def);
    assert_non_null(w);
    a = sx_test_body(w, SX_BODY_DYNAMIC, sx_v2_zero(), sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
    b = sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.999)),
                     sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    assert_near(c.normal.y, 1.0, 1e-6);
    assert_int_equal(sx_body_set_transform(w, a, sx_v2_zero(), quarter), SX_OK);
    assert_int_equal(sx_body_set_transform(w, b, sx_v2(SX_R(-0.999), SX_R(0.0)), quarter), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, a, sx_v2_zero()), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2_zero()), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_int_equal(sx_world_get_contact(w, 0, &c), SX_OK);
    assert_near(c.normal.x, -1.0, 1e-5);
    assert_near(c.normal.y, 0.0, 1e-5);
    /* and the solver pushed them apart along it, not along the old one */
    assert_true(sx_body_get_linear_velocity(w, b).x <= SX_R(0.0));
    assert_near(sx_body_get_linear_velocity(w, b).y, 0.0, 1e-4);
    sx_world_destroy(w);
}

/* A resting box whose density goes from 1 to 100: the next collide keeps
 * the pair's manifold, but the contact's effective masses must be the new
 * body's (a contact that kept its old ones pushed a hundredth of the
 * support: the box sank, and with huge steps a pair of them left the world
 * as NaN, fuzz input world-held-contact-stale-masses-nan). The support of
 * the step's last sub-step is then m g h. */
static void a_contact_kept_through_a_mass_change_takes_the_new_masses(void **state) {
    sx_body_id boxes[ROW_BOXES];
    sx_collider_id colliders[ROW_BOXES];
    sx_world *w = row_world(SX_R(0.0), boxes, colliders);
    int i, k;
    (void)state;
    for (i = 0; i < ROW_BOXES; ++i)
        assert_int_equal(sx_collider_set_density(w, colliders[i], SX_R(100.0)), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data c;
        double support = 0.0, weight;
        assert_int_equal(sx_world_get_contact(w, i, &c), SX_OK);
        for (k = 0; k < c.count; ++k)
            support += (double)c.normal_impulses[k];
        weight = (double)sx_body_get_mass(w, boxes[i]) * 10.0 * SUB_H;
        assert_near(support, weight, 0.02 * weight);
    }
    sx_world_destroy(w);
}

/* manifold_keep_slops: 0 .. 1, finite. */
static void manifold_keep_slops_is_refused_outside_zero_to_one(void **state) {
    sx_world_def d = sx_default_world_def();
    (void)state;
    d.manifold_keep_slops = SX_R(-0.01);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_ERR_INVALID_ARG);
    d.manifold_keep_slops = SX_R(1.01);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_ERR_INVALID_ARG);
    d.manifold_keep_slops = SX_R(0.0) / SX_R(0.0);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_ERR_NONFINITE);
    assert_null(sx_world_create(&d));
    d.manifold_keep_slops = SX_R(1.0);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_OK);
    d.manifold_keep_slops = SX_R(0.0);
    assert_int_equal(sx_world_def_validate(&d, NULL), SX_OK);
}

static void contact_events_report_begin_once_and_end_once(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0)),
             ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_body_id g = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.5)), &ball);
    sx_contact_events e;
    int s, begins = 0, ends = 0, began_at = -1;
    (void)state;
    e = sx_world_get_contact_events(NULL);
    assert_int_equal(e.begin_count + e.end_count, 0);
    assert_int_equal(sx_world_clear_events(NULL), SX_ERR_INVALID_ARG);
    /* falls 1 m: touches after about 0.45 s, then rests */
    for (s = 0; s < 120; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        e = sx_world_get_contact_events(w);
        if (e.begin_count > 0 && began_at < 0) {
            began_at = s;
            assert_true(sx_body_id_to_u64(e.begin[0].body_a) == sx_body_id_to_u64(g));
            assert_true(sx_body_id_to_u64(e.begin[0].body_b) == sx_body_id_to_u64(b));
            assert_true(sx_collider_is_valid(w, e.begin[0].collider_a));
        }
        begins += e.begin_count;
        ends += e.end_count;
    }
    assert_int_equal(begins, 1);
    assert_int_equal(ends, 0);
    /* sqrt(2 x 1 m / 10) = 0.447 s; the margin reports it up to a step early */
    assert_true(began_at >= 24 && began_at <= 27);
    assert_int_equal(sx_body_set_transform(w, b, sx_v2(SX_R(0.0), SX_R(5.0)), SX_R(0.0)), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    e = sx_world_get_contact_events(w);
    assert_int_equal(e.begin_count, 0);
    assert_int_equal(e.end_count, 1);
    assert_true(sx_body_id_to_u64(e.end[0].body_b) == sx_body_id_to_u64(b));
    assert_int_equal(sx_world_clear_events(w), SX_OK);
    assert_int_equal(sx_world_get_contact_events(w).end_count, 0);
    sx_world_destroy(w);
}

/* Collects the body handles a query reports. */
typedef struct found_bodies {
    uint64_t ids[8];
    int count, stop_after;
} found_bodies;

static bool collect(sx_collider_id collider, sx_body_id body, void *context) {
    found_bodies *f = (found_bodies *)context;
    (void)collider;
    if (f->count < 8) f->ids[f->count] = sx_body_id_to_u64(body);
    f->count++;
    return f->stop_after == 0 || f->count < f->stop_after;
}

static void world_queries_find_the_colliders_at_their_current_place(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5)),
             ball = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_shape probe = sx_circle_shape(sx_v2_zero(), SX_R(0.2));
    sx_body_id a = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(0.0)), &box);
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(3.0), SX_R(0.0)), &ball);
    found_bodies f;
    sx_ray_input ray;
    sx_world_ray_hit hit;
    (void)state;
    memset(&f, 0, sizeof(f));
    assert_int_equal(sx_world_query_aabb(
                         w,
                         sx_aabb_make(sx_v2(SX_R(-1.0), SX_R(-1.0)), sx_v2(SX_R(4.0), SX_R(1.0))),
                         collect, &f),
                     2);
    assert_true(f.ids[0] == sx_body_id_to_u64(a) && f.ids[1] == sx_body_id_to_u64(b));
    /* the callback can stop the query */
    memset(&f, 0, sizeof(f));
    f.stop_after = 1;
    assert_int_equal(sx_world_query_aabb(
                         w,
                         sx_aabb_make(sx_v2(SX_R(-1.0), SX_R(-1.0)), sx_v2(SX_R(4.0), SX_R(1.0))),
                         collect, &f),
                     1);
    /* a point in the box's bounds corner but outside the ball */
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(0.4), SX_R(0.4)), NULL, NULL), 1);
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(3.45), SX_R(0.45)), NULL, NULL), 0);
    /* queries see teleports at once, without a step */
    assert_int_equal(sx_body_set_transform(w, b, sx_v2(SX_R(10.0), SX_R(0.0)), SX_R(0.0)), SX_OK);
    memset(&f, 0, sizeof(f));
    assert_int_equal(sx_world_query_shape(w, &probe,
                                          sx_xform_make(sx_v2(SX_R(10.6), SX_R(0.0)), SX_R(0.0)),
                                          collect, &f),
                     1);
    assert_true(f.ids[0] == sx_body_id_to_u64(b));
    /* a ray along +x from the left hits the box first, at x = -0.5 */
    ray.origin = sx_v2(SX_R(-5.0), SX_R(0.0));
    ray.translation = sx_v2(SX_R(20.0), SX_R(0.0));
    ray.max_fraction = SX_R(1.0);
    assert_true(sx_world_cast_ray(w, &ray, &hit));
    assert_true(sx_body_id_to_u64(hit.body) == sx_body_id_to_u64(a));
    assert_vec2_near(hit.point, sx_v2(SX_R(-0.5), SX_R(0.0)), 10.0 * SX_TEST_EPS);
    assert_vec2_near(hit.normal, sx_v2(SX_R(-1.0), SX_R(0.0)), SX_TEST_EPS);
    assert_near(hit.fraction, 4.5 / 20.0, SX_TEST_EPS);
    /* from the right it hits the ball at x = 10.5 */
    ray.origin = sx_v2(SX_R(15.0), SX_R(0.0));
    ray.translation = sx_v2(SX_R(-20.0), SX_R(0.0));
    assert_true(sx_world_cast_ray(w, &ray, &hit));
    assert_true(sx_body_id_to_u64(hit.body) == sx_body_id_to_u64(b));
    assert_vec2_near(hit.point, sx_v2(SX_R(10.5), SX_R(0.0)), 10.0 * SX_TEST_EPS);
    /* bad input answers nothing */
    ray.translation = sx_v2_zero();
    assert_false(sx_world_cast_ray(w, &ray, &hit));
    assert_false(sx_world_cast_ray(NULL, &ray, &hit));
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(0.0) / SX_R(0.0), SX_R(0.0)), NULL, NULL),
                     0);
    probe.u.circle.radius = SX_R(-1.0);
    assert_int_equal(sx_world_query_shape(w, &probe, sx_xform_identity(), NULL, NULL), 0);
    sx_world_destroy(w);
}

typedef struct draw_counts {
    int shapes, contacts, boxes, static_shapes;
} draw_counts;

static void count_shape(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                        void *context) {
    draw_counts *d = (draw_counts *)context;
    (void)shape;
    (void)xf;
    (void)sensor;
    d->shapes++;
    if (type == SX_BODY_STATIC) d->static_shapes++;
}

static void count_contact(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context) {
    (void)point;
    (void)depth;
    assert_true(sx_is_normalized(normal));
    ((draw_counts *)context)->contacts++;
}

static void count_box(sx_aabb box, void *context) {
    assert_true(sx_aabb_is_valid(box));
    ((draw_counts *)context)->boxes++;
}

static void debug_draw_visits_every_collider_and_contact_point(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_debug_draw dd;
    draw_counts counts;
    int i;
    (void)state;
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
    make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box);
    for (i = 0; i < 10; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    memset(&counts, 0, sizeof(counts));
    memset(&dd, 0, sizeof(dd));
    dd.context = &counts;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(counts.shapes + counts.contacts + counts.boxes, 0);
    dd.draw_shape = count_shape;
    dd.draw_contact = count_contact;
    dd.draw_aabb = count_box;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(counts.shapes, 2);
    assert_int_equal(counts.static_shapes, 1);
    assert_int_equal(counts.boxes, 2);
    assert_int_equal(counts.contacts, 2);
    assert_int_equal(sx_world_draw(w, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_draw(NULL, &dd), SX_ERR_INVALID_ARG);
    sx_world_destroy(w);
}

static void angular_velocity_survives_adding_colliders_and_fixed_rotation_holds(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id spin, fixed;
    (void)state;
    bd.type = SX_BODY_DYNAMIC;
    bd.angular_velocity = SX_R(2.0);
    assert_int_equal(sx_create_body(w, &bd, &spin), SX_OK);
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
    assert_int_equal(sx_body_add_collider(w, spin, &cd, NULL), SX_OK);
    assert_near(sx_body_get_angular_velocity(w, spin), 2.0, 0.0);
    bd.fixed_rotation = true;
    bd.position = sx_v2(SX_R(5.0), SX_R(0.0));
    assert_int_equal(sx_create_body(w, &bd, &fixed), SX_OK);
    assert_int_equal(sx_body_add_collider(w, fixed, &cd, NULL), SX_OK);
    assert_near(sx_body_get_angular_velocity(w, fixed), 0.0, 0.0);
    assert_near(sx_body_get_inertia(w, fixed), 0.0, 0.0);
    assert_int_equal(sx_body_apply_impulse_at_point(w, fixed, sx_v2(SX_R(0.0), SX_R(1.0)),
                                                    sx_v2(SX_R(5.5), SX_R(0.0))),
                     SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_near(sx_body_get_angle(w, fixed), 0.0, 0.0);
    assert_near(sx_body_get_linear_velocity(w, fixed).y, 1.0, SX_TEST_EPS);
    /* a free spin at 2 rad/s for 1 s turns the box by 2 rad */
    {
        int i;
        for (i = 1; i < 60; ++i)
            assert_int_equal(sx_world_step(w, DT), SX_OK);
    }
    assert_near(sx_body_get_angle(w, spin), 2.0, 1e-3);
    sx_world_destroy(w);
}

/* A ground and a column of `n` unit boxes resting on it. */
static sx_world *make_column(bool sleep, sx_body_id *ids, int n) {
    sx_world_def def = sx_default_world_def();
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_world *w;
    int i;
    def.enable_sleep = sleep;
    w = sx_world_create(&def);
    assert_non_null(w);
    make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), &ground);
    for (i = 0; i < n; ++i) {
        ids[i] = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5) + (sx_real)i), &box);
    }
    return w;
}

static void step_seconds(sx_world *w, int seconds) {
    int i;
    for (i = 0; i < 60 * seconds; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
}

static void resting_column_falls_asleep_and_stays_put(void **state) {
    sx_body_id ids[3];
    sx_world *w = make_column(true, ids, 3);
    sx_xform before;
    (void)state;
    assert_int_equal(sx_world_awake_body_count(w), 3);
    step_seconds(w, 2);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    assert_false(sx_body_is_awake(w, ids[2]));
    before = sx_body_get_transform(w, ids[2]);
    step_seconds(w, 1);
    {
        sx_xform after = sx_body_get_transform(w, ids[2]);
        assert_memory_equal(&before, &after, sizeof(before));
    }
    /* the sleeping pile keeps its contacts (no end events) */
    assert_int_equal(sx_world_contact_count(w), 3);
    assert_int_equal(sx_world_get_contact_events(w).end_count, 0);
    sx_world_destroy(w);
    /* and with sleeping off, nothing sleeps */
    w = make_column(false, ids, 3);
    step_seconds(w, 2);
    assert_int_equal(sx_world_awake_body_count(w), 3);
    sx_world_destroy(w);
}

static void pushing_one_sleeping_body_wakes_its_whole_island(void **state) {
    sx_body_id ids[3];
    sx_world *w = make_column(true, ids, 3);
    (void)state;
    step_seconds(w, 2);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    assert_int_equal(sx_body_apply_impulse(w, ids[2], sx_v2(SX_R(0.1), SX_R(0.0))), SX_OK);
    assert_int_equal(sx_world_awake_body_count(w), 3);
    assert_true(sx_body_is_awake(w, ids[0]));
    assert_int_equal(sx_body_set_awake(w, ids[1], false), SX_OK);
    assert_false(sx_body_is_awake(w, ids[1]));
    assert_int_equal(sx_body_set_awake(w, ids[1], true), SX_OK);
    assert_true(sx_body_is_awake(w, ids[1]));
    step_seconds(w, 2);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    /* a new gravity wakes everything */
    assert_int_equal(sx_world_set_gravity(w, sx_v2(SX_R(1.0), SX_R(-10.0))), SX_OK);
    assert_int_equal(sx_world_awake_body_count(w), 3);
    sx_world_destroy(w);
}

static void body_landing_on_a_sleeping_pile_wakes_it(void **state) {
    sx_body_id ids[3], ball;
    sx_world *w = make_column(true, ids, 3);
    sx_shape shape = sx_circle_shape(sx_v2_zero(), SX_R(0.25));
    int s, woke_at = -1;
    (void)state;
    step_seconds(w, 2);
    assert_int_equal(sx_world_awake_body_count(w), 0);
    ball = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(6.0)), &shape);
    for (s = 0; s < 120 && woke_at < 0; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        if (sx_body_is_awake(w, ids[0])) woke_at = s;
    }
    /* it falls 2.75 m (0.74 s) before it touches the top box, then the
     * bottom box wakes with the top one */
    assert_true(woke_at >= 40 && woke_at <= 46);
    assert_true(sx_body_is_awake(w, ball));
    sx_world_destroy(w);
}

static void destroying_the_support_of_a_sleeping_pile_lets_it_fall(void **state) {
    sx_body_id ids[2];
    sx_world *w = make_column(true, ids, 2);
    (void)state;
    step_seconds(w, 2);
    assert_false(sx_body_is_awake(w, ids[1]));
    assert_int_equal(sx_destroy_body(w, ids[0]), SX_OK);
    assert_true(sx_body_is_awake(w, ids[1]));
    step_seconds(w, 1);
    /* it fell the 1 m onto the ground */
    assert_near(sx_body_get_position(w, ids[1]).y, 0.5, 2.0 * (double)sx_world_linear_slop(w));
    sx_world_destroy(w);
}

static void destroying_a_collider_drops_its_contacts_and_lets_the_body_fall(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id g = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), NULL), b;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id floor_collider;
    (void)state;
    cd.shape = ground;
    assert_int_equal(sx_body_add_collider(w, g, &cd, &floor_collider), SX_OK);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.5)), &box);
    step_seconds(w, 1);
    assert_int_equal(sx_world_contact_count(w), 1);
    assert_int_equal(sx_destroy_collider(w, floor_collider), SX_OK);
    assert_int_equal(sx_world_contact_count(w), 0);
    assert_true(sx_body_is_valid(w, g));
    step_seconds(w, 1);
    /* nothing holds it any more: a free fall of about 5 m in 1 s */
    assert_true(sx_body_get_position(w, b).y < SX_R(-4.0));
    /* a static platform teleported from under a sleeping box */
    {
        sx_body_id platform = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(30.0), SX_R(-20.0)), &ground);
        sx_body_id c = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(30.0), SX_R(-18.5)), &box);
        step_seconds(w, 1);
        assert_false(sx_body_is_awake(w, c));
        assert_int_equal(
            sx_body_set_transform(w, platform, sx_v2(SX_R(80.0), SX_R(-20.0)), SX_R(0.0)), SX_OK);
        assert_true(sx_body_is_awake(w, c));
    }
    assert_int_equal(sx_world_update_sleep(w, SX_R(0.0)), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_world_update_sleep(w, SX_R(1.0) / SX_R(0.0)), SX_ERR_NONFINITE);
    assert_int_equal(sx_world_update_sleep(NULL, DT), SX_ERR_INVALID_ARG);
    sx_world_destroy(w);
}

static void sensor_reports_a_ball_falling_through_it_without_touching_it(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape zone = sx_box_shape(SX_R(2.0), SX_R(1.0)),
             ball = sx_circle_shape(sx_v2_zero(), SX_R(0.25));
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id region, b, ignored;
    sx_collider_id sensor;
    sx_sensor_events e;
    int s, began = -1, ended = -1, begins = 0, ends = 0;
    (void)state;
    assert_int_equal(sx_create_body(w, &bd, &region), SX_OK);
    cd.shape = zone;
    cd.sensor = true;
    cd.filter.mask = 1u; /* sees category 1 only */
    assert_int_equal(sx_body_add_collider(w, region, &cd, &sensor), SX_OK);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(3.0)), &ball);
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(1.0), SX_R(3.0));
    assert_int_equal(sx_create_body(w, &bd, &ignored), SX_OK);
    cd = sx_default_collider_def();
    cd.shape = ball;
    cd.filter.category = 2u;
    assert_int_equal(sx_body_add_collider(w, ignored, &cd, NULL), SX_OK);
    for (s = 0; s < 90; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        e = sx_world_get_sensor_events(w);
        if (e.begin_count > 0 && began < 0) {
            began = s;
            assert_true(sx_collider_id_to_u64(e.begin[0].sensor) == sx_collider_id_to_u64(sensor));
            assert_true(sx_body_id_to_u64(e.begin[0].visitor_body) == sx_body_id_to_u64(b));
        }
        if (e.end_count > 0 && ended < 0) ended = s;
        begins += e.begin_count;
        ends += e.end_count;
    }
    /* the ball's bottom reaches y = 1 after falling 1.75 m (0.59 s) and its
     * top leaves y = -1 after 4.25 m (0.92 s); the category-2 ball is never
     * seen */
    assert_int_equal(begins, 1);
    assert_int_equal(ends, 1);
    assert_true(began >= 34 && began <= 36);
    assert_true(ended >= 54 && ended <= 56);
    /* no response: the ball fell freely (4.5 m of free fall in 1.5 s,
     * within the integrator's first-order error) */
    assert_near(sx_body_get_position(w, b).y, 3.0 - 0.5 * 10.0 * 1.5 * 1.5, 0.1);
    assert_int_equal(sx_world_get_sensor_events(NULL).begin_count, 0);
    sx_world_destroy(w);
}

/* A random value: mostly ordinary, sometimes huge, zero, NaN or infinite. */
static sx_real hostile(sx_test_rng *rng) {
    double u = sx_test_rng_unit(rng);
    if (u < 0.03) return SX_R(0.0) / SX_R(0.0);
    if (u < 0.06) return SX_R(1.0) / SX_R(0.0);
    if (u < 0.09) return SX_R(0.0);
    if (u < 0.12) return sx_test_rng_range(rng, -1.0e4, 1.0e4);
    return sx_test_rng_range(rng, -5.0, 5.0);
}

/* Found by fuzz/fuzz_world.c: an impulse of 13 N s at a finite point 1e38 m
 * away gave an infinite angular impulse, and a body without rotational
 * inertia turned it into NaN (inf x 0). Sums that overflow are refused. */
static void overflowing_force_or_impulse_at_a_point_is_refused_not_nan(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-19.0), SX_R(-9.0)), NULL);
    sx_vec2 far = sx_v2(SX_REAL_MAX, SX_R(0.0));
    (void)state;
    assert_int_equal(sx_body_apply_impulse_at_point(w, b, sx_v2(SX_R(13.0), SX_R(-16.0)), far),
                     SX_ERR_NONFINITE);
    assert_int_equal(sx_body_apply_force_at_point(w, b, sx_v2(SX_R(13.0), SX_R(-16.0)), far),
                     SX_ERR_NONFINITE);
    assert_int_equal(sx_body_apply_force(w, b, sx_v2(SX_REAL_MAX, SX_R(0.0))), SX_OK);
    assert_int_equal(sx_body_apply_force(w, b, sx_v2(SX_REAL_MAX, SX_R(0.0))), SX_ERR_NONFINITE);
    assert_int_equal(sx_body_apply_torque(w, b, SX_REAL_MAX), SX_OK);
    assert_int_equal(sx_body_apply_torque(w, b, SX_REAL_MAX), SX_ERR_NONFINITE);
    assert_int_equal(sx_body_apply_angular_impulse(w, b, -SX_REAL_MAX), SX_OK);
    assert_int_equal(sx_body_apply_angular_impulse(w, b, -SX_REAL_MAX), SX_ERR_NONFINITE);
    /* a modest impulse at a modest point still works */
    assert_int_equal(sx_body_apply_impulse_at_point(w, b, sx_v2(SX_R(1.0), SX_R(0.0)),
                                                    sx_v2(SX_R(-19.0), SX_R(-8.0))),
                     SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_false(sx_body_get_angular_velocity(w, b) != sx_body_get_angular_velocity(w, b));
    assert_true(sx_is_finite(sx_body_get_angular_velocity(w, b)));
    sx_world_destroy(w);
}

/* Found by fuzz/fuzz_world.c: a dynamic body with a circle of radius 2.4e28
 * (then a valid shape) had mass inf and its centre of mass inf / inf = NaN.
 * Such a shape is now refused: by sx_shape_validate in the float build (its
 * mass overflows), for reaching beyond SX_HUGE in the double one; a mass
 * that overflows through its density still gives mass SX_REAL_MAX and no
 * NaN. */
static void a_collider_whose_mass_overflows_gives_no_nan(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape huge = sx_circle_shape(sx_v2_zero(), SX_R(2.36e28));
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-20.0), SX_R(-14.625)), NULL);
    sx_collider_def cd = sx_default_collider_def();
    sx_vec2 c;
    int i;
    (void)state;
    cd.shape = huge;
#ifdef SX_DOUBLE
    /* its mass fits a double: refused for reaching beyond SX_HUGE */
    assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_ERR_INVALID_ARG);
#else
    assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_ERR_NONFINITE);
#endif
    cd.shape = sx_circle_shape(sx_v2(SX_R(3.0), SX_R(0.0)), SX_R(1000.0));
    cd.density = SX_REAL_MAX;
    assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_OK);
    c = sx_body_get_world_center(w, b);
    assert_true(sx_vec2_is_finite(c));
    assert_true(sx_body_get_mass(w, b) == SX_REAL_MAX);
    for (i = 0; i < 3; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    c = sx_body_get_position(w, b);
    assert_true(sx_vec2_is_finite(c));
    assert_true(sx_is_finite(sx_body_get_angle(w, b)));
    sx_world_destroy(w);
}

/* Found by fuzz/fuzz_world.c (world-huge-segment-nan): a spinning body with
 * a box and a segment of extent 1e30 met a static box; the narrowphase,
 * beyond SX_HUGE, gave contacts 1e22 deep and the step turned the bodies'
 * state (and the static body's reported velocities) into NaN. Colliders
 * reaching beyond SX_HUGE from the body origin are refused now, plain,
 * compound and outline alike; up to SX_HUGE they are accepted. */
static void colliders_beyond_huge_are_refused(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id out = {7, 7};
    sx_compound_part parts[2];
    sx_compound comp;
    sx_vec2 outline[4];
    sx_body_id a, b;
    int i;
    (void)state;
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(-4.84375), SX_R(-4.6875));
    bd.angular_velocity = SX_R(-16.875);
    assert_int_equal(sx_create_body(w, &bd, &a), SX_OK);
    cd.shape = box;
    assert_int_equal(sx_body_add_collider(w, a, &cd, NULL), SX_OK);
    cd.shape = sx_segment_shape(sx_v2(SX_R(-1e30), SX_R(0.0)), sx_v2(SX_R(1e30), SX_R(0.0)));
    assert_int_equal(sx_shape_validate(&cd.shape), SX_OK);
    assert_int_equal(sx_body_add_collider(w, a, &cd, &out), SX_ERR_INVALID_ARG);
    assert_true(out.index == 0 && out.generation == 0);
    /* a circle whose bounds pass SX_HUGE by its radius, and one within it */
    cd.shape = sx_circle_shape(sx_v2(SX_R(0.75) * SX_HUGE, SX_R(0.0)), SX_R(0.5) * SX_HUGE);
    assert_int_equal(sx_body_add_collider(w, a, &cd, NULL), SX_ERR_INVALID_ARG);
    cd.shape = sx_segment_shape(sx_v2(SX_R(0.0), -SX_HUGE), sx_v2(SX_R(0.0), SX_HUGE));
    cd.density = SX_R(0.0);
    assert_int_equal(sx_body_add_collider(w, a, &cd, &out), SX_OK);
    assert_int_equal(sx_destroy_collider(w, out), SX_OK);
    cd.density = SX_R(1.0);
    /* a compound with a part placed beyond SX_HUGE */
    parts[0] = sx_compound_part_make(box, sx_xform_identity());
    parts[1] =
        sx_compound_part_make(box, sx_xform_make(sx_v2(SX_R(2.0) * SX_HUGE, SX_R(0.0)), SX_R(0.0)));
    comp.parts = parts;
    comp.count = 2;
    assert_int_equal(sx_body_add_compound(w, a, &comp, &cd, NULL), SX_ERR_INVALID_ARG);
    /* an outline with a point beyond SX_HUGE */
    outline[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    outline[1] = sx_v2(SX_R(2.0) * SX_HUGE, SX_R(0.0));
    outline[2] = sx_v2(SX_R(1.0), SX_R(1.0));
    outline[3] = sx_v2(SX_R(0.0), SX_R(1.0));
    assert_int_equal(sx_body_add_outline(w, a, outline, 4, &cd, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_get_mass(w, a) > SX_R(0.99), true);
    assert_true(sx_body_get_mass(w, a) < SX_R(1.01)); /* only the 1 x 1 box */

    /* the reproducer's scene, without the refused segment: no NaN, and the
     * static body's velocities stay zero */
    b = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(-16.0), SX_R(-7.96875)), &box);
    for (i = 0; i < 3; ++i) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        assert_true(sx_vec2_is_finite(sx_body_get_position(w, a)));
        assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, a)));
        assert_true(sx_is_finite(sx_body_get_angular_velocity(w, a)));
        assert_true(sx_body_get_linear_velocity(w, b).x == SX_R(0.0));
        assert_true(sx_body_get_linear_velocity(w, b).y == SX_R(0.0));
        assert_true(sx_body_get_angular_velocity(w, b) == SX_R(0.0));
    }
    sx_world_destroy(w);
}

/* base.h: SX_HUGE is fixed at compile time, in length units, and does not
 * follow a world's length_units_per_meter (issue 28 asked for it to be said
 * precisely). In a world of 100 units per metre, whose slop is 100 times
 * the default's, a collider's extent and a body's speed per sub-step are
 * bounded by the same SX_HUGE units as in the default world. */
static void huge_is_in_length_units_whatever_the_world_scale(void **state) {
    static const sx_real units[2] = {SX_R(1.0), SX_R(100.0)};
    int k;
    (void)state;
    for (k = 0; k < 2; ++k) {
        sx_world_def d = sx_default_world_def();
        sx_body_def bd = sx_default_body_def();
        sx_collider_def cd = sx_default_collider_def();
        sx_world *w;
        sx_body_id b;
        sx_vec2 v;
        d.length_units_per_meter = units[k];
        d.gravity = sx_v2_zero();
        d.sub_steps = 1;
        w = sx_world_create(&d);
        assert_non_null(w);
        assert_near(sx_world_linear_slop(w), 0.005 * (double)units[k], 1e-6 * (double)units[k]);
        bd.type = SX_BODY_DYNAMIC;
        assert_int_equal(sx_create_body(w, &bd, &b), SX_OK);
        cd.shape = sx_box_shape(SX_R(1.01) * SX_HUGE, SX_R(1.0));
        assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_ERR_INVALID_ARG);
        cd.shape = sx_box_shape(SX_R(0.99) * SX_HUGE, SX_R(1.0));
        assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_OK);
        /* 4 SX_HUGE per step of 1 s: limited to SX_HUGE per sub-step */
        assert_int_equal(
            sx_body_set_linear_velocity(w, b, sx_v2(SX_R(4.0) * SX_HUGE, SX_R(0.0))), SX_OK);
        assert_int_equal(sx_world_step(w, SX_R(1.0)), SX_OK);
        v = sx_body_get_linear_velocity(w, b);
        assert_near(v.x, (double)SX_HUGE, 1e-5 * (double)SX_HUGE);
        sx_world_destroy(w);
    }
}

/* Found by fuzz/fuzz_world.c (world-torque-overflow-nan): a force of about
 * 1e3 N at a point 2.6e33 m away is a finite torque of 2.4e36 N m, accepted;
 * on a box of inertia 0.0025 kg m^2 the angular velocity overflowed to
 * infinity in the first sub-step, and after the box hit its neighbour both
 * had NaN positions. The step's speed limit (world.h, SX_MAX_ROTATION) now
 * keeps every body within a quarter turn per sub-step. */
static void a_finite_torque_that_overflows_the_spin_is_limited(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.175), SX_R(0.175));
    sx_body_id a = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-97.08), SX_R(10.9375)), &box);
    sx_body_id b;
    const double h = SUB_H;
    const double wmax = (double)SX_MAX_ROTATION / h;
    int i;
    (void)state;
    (void)make_body(w, SX_BODY_STATIC, sx_v2(SX_R(-20.0), SX_R(-8.0)), NULL);
    b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-97.08), SX_R(10.3125)), &box);
    assert_int_equal(sx_body_apply_force_at_point(w, b, sx_v2(SX_R(-1000.0), SX_R(921.875)),
                                                  sx_v2(SX_R(-2.586e33), SX_R(-14.84))),
                     SX_OK);
    assert_int_equal(sx_body_apply_impulse_at_point(w, b, sx_v2(SX_R(10.3125), SX_R(19.6875)),
                                                    sx_v2(SX_R(-20.0), SX_R(-16.0))),
                     SX_OK);
    for (i = 0; i < 3; ++i) {
        int k;
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        for (k = 0; k < 2; ++k) {
            sx_body_id id = k ? b : a;
            sx_real av = sx_body_get_angular_velocity(w, id);
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, id)));
            assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, id)));
            assert_true(sx_is_finite(sx_body_get_angle(w, id)));
            assert_true(sx_is_finite(av));
            assert_true(fabs((double)av) <= wmax * (1.0 + 1e-5));
        }
    }
    /* the torque spun B (clockwise) up to the limit */
    assert_true((double)sx_body_get_angular_velocity(w, b) < -0.5 * wmax);
    sx_world_destroy(w);
}

/* Found by the 10M fuzz campaign (harness world, input
 * world-kinematic-spin-flt-max-nan): a kinematic box spinning at -FLT_MAX
 * rad/s (finite, so accepted) touching a big dynamic circle. The speed
 * limit reached dynamic bodies in sx_world_apply_forces only, so the solver
 * read the kinematic spin as it was, w x r overflowed and the contact's
 * tangent impulse came out NaN. The solve stage limits every moving body
 * now, also when it is called on its own. Run 2 sets the velocities after
 * steps that left every velocity within the limit, run 3 makes the spinning
 * body then (the world must not go on trusting the limit it met). */
static void a_kinematic_body_spinning_at_flt_max_gives_finite_contacts(void **state) {
    const double h = SUB_H;
    int run;
    (void)state;
    for (run = 0; run < 4; ++run) {
        sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
        sx_shape big = sx_circle_shape(sx_v2(SX_R(-0.125), SX_R(15.875)), SX_R(15.84));
        sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.3));
        sx_body_id ball =
            make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-14.6875), SX_R(-14.6875)), &big);
        sx_body_id kin = {0, 0};
        sx_contact_data cd;
        int i, k, j, contacts = 0;
        /* run 2: the box at rest through ordinary steps, then its spin */
        if (run != 3) kin = make_body(w, SX_BODY_KINEMATIC, sx_v2(SX_R(-20.0), SX_R(7.0)), &box);
        if (run >= 2) {
            for (i = 0; i < 3; ++i)
                assert_int_equal(sx_world_step(w, DT), SX_OK);
        }
        if (run == 3) {
            sx_body_def bd = sx_default_body_def();
            sx_collider_def cdef = sx_default_collider_def();
            bd.type = SX_BODY_KINEMATIC;
            bd.position = sx_v2(SX_R(-20.0), SX_R(7.0));
            bd.angular_velocity = -SX_REAL_MAX;
            assert_int_equal(sx_create_body(w, &bd, &kin), SX_OK);
            cdef.shape = box;
            assert_int_equal(sx_body_add_collider(w, kin, &cdef, NULL), SX_OK);
        } else {
            assert_int_equal(sx_body_set_angular_velocity(w, kin, -SX_REAL_MAX), SX_OK);
        }
        if (run == 1) {
            /* the stages alone: collide, then solve without apply_forces */
            assert_int_equal(sx_body_set_linear_velocity(w, ball, sx_v2(SX_REAL_MAX, SX_R(0.0))),
                             SX_OK);
            assert_int_equal(sx_world_collide(w), SX_OK);
            assert_int_equal(sx_world_solve(w, (sx_real)h), SX_OK);
            assert_true(sx_world_contact_count(w) > 0);
            assert_int_equal(sx_world_get_contact(w, 0, &cd), SX_OK);
            for (j = 0; j < cd.count; ++j) {
                assert_true(sx_is_finite(cd.normal_impulses[j]));
                assert_true(sx_is_finite(cd.tangent_impulses[j]));
            }
            assert_true(fabs((double)sx_body_get_angular_velocity(w, kin)) <=
                        (double)SX_MAX_ROTATION / h * (1.0 + 1e-5));
            assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, ball)));
            assert_true((double)sx_length(sx_body_get_linear_velocity(w, ball)) <=
                        (double)SX_HUGE / h * (1.0 + 1e-5));
        }
        for (i = 0; i < 3; ++i) {
            assert_int_equal(sx_world_step(w, DT), SX_OK);
            /* limited before the solver read it, the spin pushes the ball
             * at about 80 m/s; read as it was, at the speed limit */
            if (run != 1)
                assert_true((double)sx_length(sx_body_get_linear_velocity(w, ball)) < 1e3);
            for (k = 0; k < sx_world_contact_count(w); ++k) {
                assert_int_equal(sx_world_get_contact(w, k, &cd), SX_OK);
                ++contacts;
                assert_true(sx_vec2_is_finite(cd.normal));
                for (j = 0; j < cd.count; ++j) {
                    assert_true(sx_is_finite(cd.depths[j]));
                    assert_true(sx_is_finite(cd.normal_impulses[j]));
                    assert_true(sx_is_finite(cd.tangent_impulses[j]));
                    assert_true(sx_vec2_is_finite(cd.points[j]));
                }
            }
            assert_true(fabs((double)sx_body_get_angular_velocity(w, kin)) <=
                        (double)SX_MAX_ROTATION / h * (1.0 + 1e-5));
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, ball)));
            assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, ball)));
        }
        if (run != 1) assert_true(contacts > 0); /* the box does touch the circle */
        sx_world_destroy(w);
    }
}

/* A velocity the caller sets between steps (here a kinematic box's, at
 * -FLT_MAX) meets the speed limit before the solver reads it, as one set
 * before the first step does: the world must not go on trusting the limit
 * the last step's velocities met. World 1 sets a second body's spin to what
 * it was as well, which makes the limit look again in any case: both give
 * the same bits. */
static void a_velocity_set_between_steps_meets_the_limit_before_the_solver(void **state) {
    sx_world *w[2];
    sx_body_id ball[2], kin[2], idle[2];
    int n, i;
    (void)state;
    for (n = 0; n < 2; ++n) {
        sx_shape big = sx_circle_shape(sx_v2(SX_R(-0.125), SX_R(15.875)), SX_R(15.84));
        sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.3));
        w[n] = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
        ball[n] = make_body(w[n], SX_BODY_DYNAMIC, sx_v2(SX_R(-14.6875), SX_R(-14.6875)), &big);
        kin[n] = make_body(w[n], SX_BODY_KINEMATIC, sx_v2(SX_R(-20.0), SX_R(7.0)), &box);
        idle[n] = make_body(w[n], SX_BODY_KINEMATIC, sx_v2(SX_R(40.0), SX_R(40.0)), &box);
        for (i = 0; i < 3; ++i)
            assert_int_equal(sx_world_step(w[n], DT), SX_OK);
        assert_int_equal(sx_body_set_linear_velocity(w[n], kin[n], sx_v2(SX_R(0.0), -SX_REAL_MAX)),
                         SX_OK);
        if (n == 1) assert_int_equal(sx_body_set_angular_velocity(w[n], idle[n], SX_R(0.0)), SX_OK);
        assert_int_equal(sx_world_step(w[n], DT), SX_OK);
    }
    for (n = 0; n < 2; ++n)
        assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w[n], ball[n])));
    {
        sx_vec2 v0 = sx_body_get_linear_velocity(w[0], ball[0]);
        sx_vec2 v1 = sx_body_get_linear_velocity(w[1], ball[1]);
        assert_memory_equal(&v0, &v1, sizeof(v0));
    }
    for (n = 0; n < 2; ++n)
        sx_world_destroy(w[n]);
}

/* Gives body `a` a sensor of density 2.1e37 (the fuzz input's): its mass
 * overflows and the body gets the mass SX_REAL_MAX. */
static void add_heavy_sensor(sx_world *w, sx_body_id a) {
    sx_collider_def cd = sx_default_collider_def();
    cd.shape = sx_circle_shape(sx_v2(SX_R(-4.0), SX_R(-16.0)), SX_R(15.125));
    cd.density = SX_R(2.1e37);
    cd.sensor = true;
    assert_int_equal(sx_body_add_collider(w, a, &cd, NULL), SX_OK);
    assert_true((double)sx_body_get_mass(w, a) > 1e38);
}

/* Found by the 10M fuzz campaign (harness world, input
 * world-max-mass-against-static-nan): a dynamic body whose sensor of
 * density 2.1e37 gives it the mass SX_REAL_MAX, resting on a static circle.
 * The contact's effective mass (1 / the body's inverse mass, 3.4e38) times
 * its speed overflowed, the impulse was inf and the static body's velocity
 * 0 x inf = NaN. Impulses are bounded now, static and kinematic bodies never
 * take the solver's velocities, and what the impulses do to a light body
 * meets the speed limit. */
static void an_overflowing_contact_impulse_gives_no_nan(void **state) {
    int run;
    (void)state;
    for (run = 0; run < 2; ++run) {
        sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
        sx_shape ball = sx_circle_shape(sx_v2(SX_R(-16.0), SX_R(-13.875)), SX_R(4.5));
        sx_shape rock = sx_circle_shape(sx_v2(SX_R(-16.0), SX_R(-16.0)), SX_R(4.5));
        sx_body_id a = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(4.5), SX_R(4.5)), &ball);
        sx_body_id g = make_body(w, SX_BODY_STATIC, sx_v2(SX_R(5.625), SX_R(4.5)), &rock);
        sx_contact_data data;
        int i, k, j, contacts = 0;
        add_heavy_sensor(w, a);
        assert_int_equal(sx_body_set_angular_velocity(w, a, SX_R(19.84375)), SX_OK);
        for (i = 0; i < 3; ++i) {
            if (run == 0) {
                assert_int_equal(sx_world_step(w, DT), SX_OK);
            } else {
                /* the stages on their own */
                assert_int_equal(sx_world_collide(w), SX_OK);
                assert_int_equal(sx_world_solve(w, DT), SX_OK);
            }
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, a)));
            assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, a)));
            assert_true(sx_is_finite(sx_body_get_angular_velocity(w, a)));
            assert_true(sx_body_get_linear_velocity(w, g).x == SX_R(0.0));
            assert_true(sx_body_get_linear_velocity(w, g).y == SX_R(0.0));
            assert_true(sx_body_get_angular_velocity(w, g) == SX_R(0.0));
            for (k = 0; k < sx_world_contact_count(w); ++k) {
                assert_int_equal(sx_world_get_contact(w, k, &data), SX_OK);
                ++contacts;
                for (j = 0; j < data.count; ++j) {
                    assert_true(sx_is_finite(data.normal_impulses[j]));
                    assert_true(sx_is_finite(data.tangent_impulses[j]));
                    assert_true(sx_is_finite(data.impact_impulses[j]));
                }
            }
        }
        assert_true(contacts > 0);
        sx_world_destroy(w);
    }
}

/* Found by the 10M fuzz campaign (harness world, input
 * world-max-mass-separation-inf): the same heavy body (mass SX_REAL_MAX)
 * overlapping a static circle, stepped with dt = 1.8e19. The separation
 * stage's pseudo-impulse, correction / (1 / SX_REAL_MAX), overflowed, and
 * inf x 1 / mass put the body at -inf. The moves are taken as fractions of
 * the effective mass then: the body is pushed out by the correction, as a
 * light body would be. */
static void separating_a_body_of_the_largest_mass_gives_no_nan(void **state) {
    int run;
    (void)state;
    for (run = 0; run < 2; ++run) {
        sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
        sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
        sx_shape rock = sx_circle_shape(sx_v2(SX_R(0.0), SX_R(0.0)), SX_R(2.0));
        sx_body_id a = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(1.5)), &box);
        sx_vec2 p0;
        (void)make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(0.0)), &rock);
        add_heavy_sensor(w, a);
        p0 = sx_body_get_position(w, a);
        if (run == 0) {
            /* the box is 1 m deep in the rock: one separation pass */
            assert_int_equal(sx_world_collide(w), SX_OK);
            assert_int_equal(sx_world_separate(w, DT / SX_R(4.0)), SX_OK);
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, a)));
            assert_true(sx_body_get_position(w, a).y > p0.y); /* pushed up, out */
        } else {
            assert_int_equal(sx_world_step(w, SX_R(1.8446744e19)), SX_OK);
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, a)));
            assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, a)));
            assert_true(sx_is_finite(sx_body_get_angle(w, a)));
        }
        sx_world_destroy(w);
    }
}

/* Found by the world fuzz harness (fuzz/corpus/world/world-stale-effective-mass-nan):
 * collide, then a collider destroyed, then one stage. The contacts' effective
 * masses were those of the collide, when the body was 100 times heavier:
 * the separation moved it by 100 x its correction (and a body made 10^32
 * times lighter to Inf, then NaN), the solve gave it 100 x the impulse that
 * stops it. Run 0 separates (at most max_correction_speed x h, upwards),
 * run 1 solves (the approach stopped, no rebound). */
static void a_mass_changed_between_collide_and_a_stage_is_seen_by_the_stage(void **state) {
    int run;
    (void)state;
    for (run = 0; run < 2; ++run) {
        sx_world *w = make_world(sx_v2_zero());
        sx_shape ground = sx_box_shape(SX_R(5.0), SX_R(0.5));
        sx_collider_def small = sx_default_collider_def(), big = sx_default_collider_def();
        sx_collider_id big_id;
        sx_real h = DT / SX_R(4.0);
        /* the small circle 3 cm into the ground's top (y = 0.5) */
        sx_body_id a = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.52)), NULL);
        sx_vec2 p0, v;
        (void)make_body(w, SX_BODY_STATIC, sx_v2_zero(), &ground);
        small.shape = sx_circle_shape(sx_v2_zero(), SX_R(0.05));
        big.shape = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
        assert_int_equal(sx_body_add_collider(w, a, &small, NULL), SX_OK);
        assert_int_equal(sx_body_add_collider(w, a, &big, &big_id), SX_OK);
        assert_int_equal(sx_body_set_linear_velocity(w, a, sx_v2(SX_R(0.0), SX_R(-0.5))), SX_OK);
        p0 = sx_body_get_position(w, a);
        assert_int_equal(sx_world_collide(w), SX_OK);
        assert_int_equal(sx_world_contact_count(w), 2);
        assert_int_equal(sx_destroy_collider(w, big_id), SX_OK);
        assert_near(sx_body_get_mass(w, a), 3.14159265 * 0.0025, 1e-6);
        if (run == 0) {
            sx_real dy;
            assert_int_equal(sx_world_separate(w, h), SX_OK);
            dy = sx_body_get_position(w, a).y - p0.y;
            /* beta x (overlap - slop) = 0.2 x 2.5 cm, within 3 m/s x h */
            assert_near(dy, SX_R(0.005), 1e-5);
            assert_true(dy <= SX_R(3.0) * h);
        } else {
            assert_int_equal(sx_world_solve(w, h), SX_OK);
            v = sx_body_get_linear_velocity(w, a);
            assert_near(v.y, SX_R(0.0), 1e-4);
            assert_near(v.x, SX_R(0.0), 1e-4);
        }
        sx_world_destroy(w);
    }
}

/* Found by the 10M fuzz campaign (harness world, input
 * world-denormal-dt-substep-zero): dt = the smallest denormal is a valid
 * time step, but dt / 4 sub-steps rounds to 0, which the stages refuse, and
 * sx_world_step answered SX_ERR_INVALID_ARG. It is one sub-step of dt now. */
static void a_denormal_time_step_is_one_sub_step(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id a = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.45)), &box);
    sx_real tiny[3];
    int i;
    (void)state;
    (void)make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &box);
#ifdef SX_DOUBLE
    tiny[0] = 4.9406564584124654e-324;
#else
    tiny[0] = 1.40129846e-45f;
#endif
    tiny[1] = SX_R(2.0) * tiny[0];
    tiny[2] = SX_R(3.0) * tiny[0];
    for (i = 0; i < 3; ++i) {
        assert_true(tiny[i] > SX_R(0.0));
        assert_int_equal(sx_world_step(w, tiny[i]), SX_OK);
        assert_true(sx_vec2_is_finite(sx_body_get_position(w, a)));
        assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, a)));
        assert_true(sx_is_finite(sx_body_get_angular_velocity(w, a)));
    }
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_true(sx_vec2_is_finite(sx_body_get_position(w, a)));
    sx_world_destroy(w);
}

/* Found by make fuzz (harness world, input world-restitution-1e19-nan): a
 * collider of restitution 3.9e19 (finite, so accepted) overlapping another
 * body flung both out with a rebound of 1e20 m/s and a time-of-impact shift
 * to match, and the step ended with NaN positions; with a restitution near
 * SX_REAL_MAX the impulse itself overflowed. The rebound speed is capped by
 * the speed limit now. */
static void a_huge_restitution_rebounds_at_the_speed_limit(void **state) {
    const double h = SUB_H;
    int r;
    (void)state;
    for (r = 0; r < 2; ++r) {
        sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
        sx_shape ground = sx_box_shape(SX_R(20.0), SX_R(0.5)),
                 box = sx_box_shape(SX_R(0.5), SX_R(0.5));
        sx_body_def bd = sx_default_body_def();
        sx_collider_def cd = sx_default_collider_def();
        sx_body_id b;
        int i;
        (void)make_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), &ground);
        bd.type = SX_BODY_DYNAMIC;
        bd.position = sx_v2(SX_R(0.0), SX_R(0.55));
        bd.linear_velocity = sx_v2(SX_R(0.0), SX_R(-5.0));
        assert_int_equal(sx_create_body(w, &bd, &b), SX_OK);
        cd.shape = box;
        cd.restitution = r == 0 ? SX_R(3.88116e19) : SX_REAL_MAX;
        assert_int_equal(sx_body_add_collider(w, b, &cd, NULL), SX_OK);
        for (i = 0; i < 3; ++i) {
            sx_vec2 v;
            assert_int_equal(sx_world_step(w, DT), SX_OK);
            v = sx_body_get_linear_velocity(w, b);
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, b)));
            assert_true(sx_vec2_is_finite(v));
            assert_true(sx_is_finite(sx_body_get_angular_velocity(w, b)));
            assert_true((double)sx_length(v) <= (double)SX_HUGE / h * (1.0 + 1e-5));
        }
        /* it bounced, upwards, at the limit (less three steps of gravity) */
        assert_true((double)sx_body_get_linear_velocity(w, b).y > 0.5 * (double)SX_HUGE / h);
        sx_world_destroy(w);
    }
}

/* The speed limit bites only above a quarter turn per sub-step: a free spin
 * of 300 rad/s is kept exactly, one of 1000 rad/s becomes SX_MAX_ROTATION /
 * h (471 rad/s at 60 Hz and 5 sub-steps), and a velocity beyond SX_HUGE per
 * sub-step keeps its direction. */
static void the_speed_limit_keeps_direction_and_spares_ordinary_speeds(void **state) {
    sx_world *w = make_world(sx_v2_zero());
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_body_id a = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(0.0)), &box);
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(10.0), SX_R(0.0)), &box);
    const double h = SUB_H;
    sx_vec2 v;
    (void)state;
    assert_int_equal(sx_body_set_angular_velocity(w, a, SX_R(300.0)), SX_OK);
    assert_int_equal(sx_body_set_angular_velocity(w, b, SX_R(-1000.0)), SX_OK);
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(3e38), SX_R(-1e38))), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    assert_near(sx_body_get_angular_velocity(w, a), 300.0, 1e-3);
    assert_near(sx_body_get_angular_velocity(w, b), -(double)SX_MAX_ROTATION / h,
                1e-4 * (double)SX_MAX_ROTATION / h);
    v = sx_body_get_linear_velocity(w, b);
    assert_near(sx_length(v), (double)SX_HUGE / h, 1e-4 * (double)SX_HUGE / h);
    assert_near(v.x / sx_length(v), 3.0 / sqrt(10.0), 1e-4);
    assert_near(v.y / sx_length(v), -1.0 / sqrt(10.0), 1e-4);
    assert_true(sx_vec2_is_finite(sx_body_get_position(w, b)));
    sx_world_destroy(w);
}

/* Found by fuzz/fuzz_world.c: a valid circle of radius 2.2e-18 at about
 * (-16, -10.5) in its body's frame. The body's inertia about its centre of
 * mass is the tiny difference of two near-equal products; its inverse
 * overflowed to inf, and inf x 0 = NaN. Such a body now does not rotate. */
static void a_needle_small_collider_gives_no_nan(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_shape tiny = sx_circle_shape(sx_v2((sx_real)-0x1.0000bcp+4, (sx_real)-0x1.5p+3),
                                    (sx_real)0x1.445214p-59);
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-20.0), SX_R(-16.0)), &tiny);
    int i;
    (void)state;
    assert_int_equal(sx_shape_validate(&tiny), SX_OK);
    assert_true(sx_is_finite(sx_body_get_inertia(w, b)));
    assert_int_equal(sx_body_set_linear_velocity(w, b, sx_v2(SX_R(14.84375), SX_R(-20.0))), SX_OK);
    assert_int_equal(sx_body_apply_torque(w, b, SX_R(3.0)), SX_OK);
    for (i = 0; i < 3; ++i) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        assert_true(sx_vec2_is_finite(sx_body_get_position(w, b)));
        assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, b)));
        assert_true(sx_is_finite(sx_body_get_angular_velocity(w, b)));
        assert_true(sx_is_finite(sx_body_get_angle(w, b)));
    }
    sx_world_destroy(w);
}

static void random_api_calls_never_crash_or_make_nan(void **state) {
    sx_world *w = make_world(sx_v2(SX_R(0.0), SX_R(-10.0)));
    sx_test_rng rng = sx_test_rng_make(99u);
    sx_body_id ids[32];
    int n = 0, s, i;
    (void)state;
    memset(ids, 0, sizeof(ids));
    for (s = 0; s < 600; ++s) {
        double u = sx_test_rng_unit(&rng);
        sx_body_id pick = n > 0 ? ids[(int)(sx_test_rng_unit(&rng) * (double)n)] : ids[0];
        sx_vec2 v = sx_v2(hostile(&rng), hostile(&rng));
        if (u < 0.15 && n < 32) {
            sx_body_def bd = sx_default_body_def();
            sx_collider_def cd = sx_default_collider_def();
            bd.type = (sx_body_type)(sx_test_rng_next(&rng) % 3);
            bd.position =
                sx_v2(sx_test_rng_range(&rng, -5.0, 5.0), sx_test_rng_range(&rng, 0.0, 5.0));
            if (sx_create_body(w, &bd, &ids[n]) == SX_OK) {
                cd.shape = (n % 2) ? sx_box_shape(SX_R(0.3), SX_R(0.4))
                                   : sx_capsule_shape(sx_v2_zero(), sx_v2(SX_R(0.5), SX_R(0.0)),
                                                      SX_R(0.2));
                cd.restitution = sx_test_rng_range(&rng, 0.0, 1.0);
                assert_int_equal(sx_body_add_collider(w, ids[n], &cd, NULL), SX_OK);
                ++n;
            }
        } else if (u < 0.2) {
            (void)sx_destroy_body(w, pick);
        } else if (u < 0.3) {
            (void)sx_body_apply_impulse_at_point(w, pick, v, sx_v2(hostile(&rng), hostile(&rng)));
        } else if (u < 0.35) {
            (void)sx_body_set_transform(w, pick, v, hostile(&rng));
        } else if (u < 0.4) {
            (void)sx_body_set_linear_velocity(w, pick, v);
        } else if (u < 0.45) {
            (void)sx_body_apply_force(w, pick, v);
        } else if (u < 0.48) {
            (void)sx_body_set_type(w, pick, (sx_body_type)(sx_test_rng_next(&rng) % 4));
        } else {
            sx_real dt = sx_test_rng_unit(&rng) < 0.05 ? hostile(&rng) : DT;
            (void)sx_world_step(w, dt);
        }
        for (i = 0; i < n; ++i) {
            if (!sx_body_is_valid(w, ids[i])) continue;
            assert_true(sx_vec2_is_finite(sx_body_get_position(w, ids[i])));
            assert_true(sx_vec2_is_finite(sx_body_get_linear_velocity(w, ids[i])));
            assert_true(sx_is_finite(sx_body_get_angle(w, ids[i])));
        }
    }
    sx_world_destroy(w);
}

static void destroying_bodies_mid_run_and_the_world_frees_everything(void **state) {
    size_t start = sx_live_bytes();
    sx_body_id ids[10];
    sx_world *w;
    int i, s;
    (void)state;
    w = make_drop_scene(ids, 10);
    for (s = 0; s < 90; ++s) {
        assert_int_equal(sx_world_step(w, DT), SX_OK);
        if (s == 60) {
            for (i = 0; i < 10; i += 3)
                assert_int_equal(sx_destroy_body(w, ids[i]), SX_OK);
        }
    }
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data c;
        assert_int_equal(sx_world_get_contact(w, i, &c), SX_OK);
        assert_true(sx_body_is_valid(w, c.body_a) && sx_body_is_valid(w, c.body_b));
    }
    assert_int_equal(sx_world_body_count(w), 11 - 4);
    sx_world_destroy(w);
    assert_true(sx_live_bytes() == start);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(world_create_refuses_bad_settings_with_null),
        cmocka_unit_test(world_def_validate_gives_the_reason_and_bounds_every_size),
        cmocka_unit_test(the_largest_body_capacity_is_asked_for_once_and_refused_cleanly),
        cmocka_unit_test(a_world_at_the_largest_step_counts_steps_and_returns),
        cmocka_unit_test(body_handles_pack_into_u64_and_go_stale_after_destroy),
        cmocka_unit_test(create_body_rejects_bad_definitions),
        cmocka_unit_test(add_collider_validates_shape_and_material),
        cmocka_unit_test(mass_and_inertia_come_from_collider_density),
        cmocka_unit_test(free_flight_matches_symplectic_euler_bit_for_bit),
        cmocka_unit_test(forces_and_impulses_accumulate_and_clear),
        cmocka_unit_test(static_and_kinematic_bodies_ignore_forces_and_gravity),
        cmocka_unit_test(teleport_sets_position_and_angle),
        cmocka_unit_test(step_with_bad_time_step_returns_status_and_changes_nothing),
        cmocka_unit_test(same_calls_give_bit_identical_state),
        cmocka_unit_test(stages_called_one_by_one_equal_the_step),
        cmocka_unit_test(resting_box_contact_carries_its_weight),
        cmocka_unit_test(filtered_pairs_and_sensors_make_no_contacts),
        cmocka_unit_test(contact_events_report_begin_once_and_end_once),
        cmocka_unit_test(a_kept_manifold_follows_small_moves_and_is_found_again_past_the_tolerance),
        cmocka_unit_test(a_kept_manifold_is_found_again_when_the_box_turns_about_its_point),
        cmocka_unit_test(a_kept_one_point_manifold_is_found_again_when_the_margin_grows),
        cmocka_unit_test(manifold_keep_slops_is_refused_outside_zero_to_one),
        cmocka_unit_test(a_box_slides_at_once_when_its_friction_goes_to_zero),
        cmocka_unit_test(a_kept_pair_turned_together_gets_turned_normal),
        cmocka_unit_test(a_contact_kept_through_a_mass_change_takes_the_new_masses),
        cmocka_unit_test(a_lane_is_filled_again_when_its_manifold_was_searched_since),
        cmocka_unit_test(world_queries_find_the_colliders_at_their_current_place),
        cmocka_unit_test(debug_draw_visits_every_collider_and_contact_point),
        cmocka_unit_test(angular_velocity_survives_adding_colliders_and_fixed_rotation_holds),
        cmocka_unit_test(resting_column_falls_asleep_and_stays_put),
        cmocka_unit_test(pushing_one_sleeping_body_wakes_its_whole_island),
        cmocka_unit_test(body_landing_on_a_sleeping_pile_wakes_it),
        cmocka_unit_test(destroying_the_support_of_a_sleeping_pile_lets_it_fall),
        cmocka_unit_test(destroying_a_collider_drops_its_contacts_and_lets_the_body_fall),
        cmocka_unit_test(sensor_reports_a_ball_falling_through_it_without_touching_it),
        cmocka_unit_test(random_api_calls_never_crash_or_make_nan),
        cmocka_unit_test(overflowing_force_or_impulse_at_a_point_is_refused_not_nan),
        cmocka_unit_test(a_collider_whose_mass_overflows_gives_no_nan),
        cmocka_unit_test(colliders_beyond_huge_are_refused),
        cmocka_unit_test(huge_is_in_length_units_whatever_the_world_scale),
        cmocka_unit_test(a_finite_torque_that_overflows_the_spin_is_limited),
        cmocka_unit_test(the_speed_limit_keeps_direction_and_spares_ordinary_speeds),
        cmocka_unit_test(a_huge_restitution_rebounds_at_the_speed_limit),
        cmocka_unit_test(a_kinematic_body_spinning_at_flt_max_gives_finite_contacts),
        cmocka_unit_test(a_velocity_set_between_steps_meets_the_limit_before_the_solver),
        cmocka_unit_test(an_overflowing_contact_impulse_gives_no_nan),
        cmocka_unit_test(separating_a_body_of_the_largest_mass_gives_no_nan),
        cmocka_unit_test(a_mass_changed_between_collide_and_a_stage_is_seen_by_the_stage),
        cmocka_unit_test(a_denormal_time_step_is_one_sub_step),
        cmocka_unit_test(solve_without_memory_for_its_arrays_refuses_and_changes_nothing),
        cmocka_unit_test(a_needle_small_collider_gives_no_nan),
        cmocka_unit_test(destroying_bodies_mid_run_and_the_world_frees_everything),
    };
    return cmocka_run_group_tests_name("world", tests, sx_test_group_setup, sx_test_group_teardown);
}
