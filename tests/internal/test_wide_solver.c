/* sepax tests — the wide contact solver (contact_solver.c) answers bit for
 * bit what the one-at-a-time pass answers.
 *
 * A white-box test: the same scene runs in worlds that differ only in the
 * solver's private switches: every colour solved one at a time, every
 * colour wide, the default threshold, and the default with the lanes filled
 * afresh at every sub-step instead of kept from the collide. The scene
 * mixes what the lanes must choose between: two-point faces (block solve),
 * one-point contacts (circles), frictionless bodies, a kinematic body, and
 * between sub-steps a density change and a destroyed body (which must make
 * a kept fill refill), and a column made overlapping for the position
 * pass, which takes the solve's colours in all but the last world (that
 * one walks the contacts in their order), and boxes whose lanes the
 * collides keep while the energy guard scales their impulses. Every body's state must be the
 * same bits in all four worlds, with and without restitution (which
 * decides where a kept fill's lanes find their gaps). */
#include <limits.h>
#include <string.h>

#include "../../src/world_body.h"
#include "../../src/world_internal.h"
#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))
#define SUB 4
#define BASE 14
#define WORLDS 4

typedef struct scene {
    sx_world *w;
    sx_body_id ids[256];
    sx_collider_id cols[256];
    int count;
} scene;

/* The circles' restitution: with none in the world, a kept fill finds its
 * lanes' gaps from its frames; with some, from the contacts (which the
 * impact pass reads and shifts). */
static sx_real circle_restitution;

static void add(scene *s, sx_body_type type, sx_real x, sx_real y, sx_shape shape, sx_real friction) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    bd.type = type;
    bd.position = sx_v2(x, y);
    if (type == SX_BODY_KINEMATIC) bd.linear_velocity = sx_v2(SX_R(0.5), SX_R(0.0));
    cd.shape = shape;
    cd.friction = friction;
    if (shape.type == SX_SHAPE_CIRCLE) cd.restitution = circle_restitution;
    assert_int_equal(sx_create_body(s->w, &bd, &s->ids[s->count]), SX_OK);
    assert_int_equal(sx_body_add_collider(s->w, s->ids[s->count], &cd, &s->cols[s->count]), SX_OK);
    s->count++;
}

static void build(scene *s) {
    sx_world_def wd = sx_default_world_def();
    int i, j;
    memset(s, 0, sizeof(*s));
    wd.sub_steps = SUB;
    s->w = sx_world_create(&wd);
    assert_non_null(s->w);
    add(s, SX_BODY_STATIC, SX_R(0.0), SX_R(-1.0), sx_box_shape(SX_R(40.0), SX_R(1.0)), SX_R(0.6));
    for (i = 0; i < BASE; ++i) {
        for (j = i; j < BASE; ++j) {
            sx_real x = (sx_real)(i + 1) * SX_R(0.5) + (sx_real)(j - i) - (sx_real)BASE * SX_R(0.5);
            /* every seventh box frictionless */
            add(s, SX_BODY_DYNAMIC, x, (sx_real)(2 * i + 1) * SX_R(0.5),
                sx_box_shape(SX_R(0.5), SX_R(0.5)), (i + j) % 7 == 0 ? SX_R(0.0) : SX_R(0.6));
        }
    }
    /* circles raining on the pyramid and beside it: one-point contacts */
    for (i = 0; i < 24; ++i) {
        add(s, SX_BODY_DYNAMIC, (sx_real)(i - 12) * SX_R(0.9), SX_R(16.0) + (sx_real)(i % 3),
            sx_circle_shape(sx_v2_zero(), SX_R(0.3)), SX_R(0.4));
    }
    add(s, SX_BODY_KINEMATIC, SX_R(-12.0), SX_R(0.5), sx_box_shape(SX_R(1.0), SX_R(0.5)), SX_R(0.6));
    /* a column made overlapping (10 cm into the ground and each other):
     * work for the position pass */
    for (i = 0; i < 4; ++i) {
        add(s, SX_BODY_DYNAMIC, SX_R(30.0), SX_R(0.4) + SX_R(0.9) * (sx_real)i,
            sx_box_shape(SX_R(0.5), SX_R(0.5)), SX_R(0.6));
    }
    /* two boxes tilted either way, one corner 3.5 cm into the ground and
     * the other just above it: a face's first point or its second alone
     * needs the position pass */
    for (i = 0; i < 2; ++i) {
        sx_real angle = i == 0 ? SX_R(0.04) : SX_R(-0.04);
        add(s, SX_BODY_DYNAMIC, SX_R(33.0) + SX_R(3.0) * (sx_real)i, SX_R(0.4846),
            sx_box_shape(SX_R(0.5), SX_R(0.5)), SX_R(0.6));
        assert_int_equal(sx_body_set_transform(s->w, s->ids[s->count - 1],
                                               sx_v2(SX_R(33.0) + SX_R(3.0) * (sx_real)i, SX_R(0.4846)),
                                               angle),
                         SX_OK);
    }
    /* boxes resting on narrow posts, off their middles: the energy guard
     * scales their sub-steps by a rounding's worth, so the lanes that the
     * collides keep (held) take the scaled impulses back from the contacts */
    for (i = 0; i < 6; ++i) {
        sx_real x = SX_R(44.0) + SX_R(3.0) * (sx_real)i;
        add(s, SX_BODY_STATIC, x, SX_R(0.5), sx_box_shape(SX_R(0.2), SX_R(0.5)), SX_R(0.6));
        add(s, SX_BODY_DYNAMIC, x + SX_R(0.1), SX_R(1.5), sx_box_shape(SX_R(0.5), SX_R(0.5)),
            SX_R(0.6));
    }
}

/* Points of active contacts overlapping beyond the slop at the bodies'
 * current poses: the ones the position pass moves. */
static int overlapping_points(const sx_world *w) {
    int i, k, n = 0;
    for (i = 0; i < w->contact_count; ++i) {
        const sx_contact *c = &w->contacts[i];
        const sx_body_sim *a = &w->sims[c->body_a], *b = &w->sims[c->body_b];
        if (!sx_contact_is_active(w, c)) continue;
        for (k = 0; k < c->count; ++k) {
            const sx_contact_point *p = &c->points[k];
            sx_vec2 d = sx_add(sx_sub(b->center, a->center),
                               sx_sub(sx_rotate(b->xf.q, p->rel_b), sx_rotate(a->xf.q, p->rel_a)));
            n += p->base + sx_dot(d, c->normal) < -w->linear_slop;
        }
    }
    return n;
}

/* Points the position pass had to move, over the run (world 0). */
static int pushed_points;

static void step(scene *s, int k, bool fresh) {
    int i;
    assert_int_equal(sx_world_begin_step(s->w, DT), SX_OK);
    assert_int_equal(sx_world_collide(s->w), SX_OK);
    for (i = 0; i < SUB; ++i) {
        sx_real h = DT / (sx_real)SUB;
        if (k == 30 && i == 2)
            assert_int_equal(sx_collider_set_density(s->w, s->cols[40], SX_R(3.0)), SX_OK);
        if (k == 45 && i == 1) assert_int_equal(sx_destroy_body(s->w, s->ids[60]), SX_OK);
        assert_int_equal(sx_world_apply_forces(s->w, h), SX_OK);
        if (fresh) s->w->fill_valid = false;
        assert_int_equal(sx_world_solve(s->w, h), SX_OK);
        assert_int_equal(sx_world_integrate(s->w, h), SX_OK);
        if (s->w->wide_min_colour == INT_MAX) pushed_points += overlapping_points(s->w);
        /* the fresh world's position pass walks the contacts in their
         * order; the others take the solve's colours */
        if (fresh) s->w->fill_valid = false;
        assert_int_equal(sx_world_separate(s->w, h), SX_OK);
    }
    assert_int_equal(sx_world_continuous(s->w), SX_OK);
    assert_int_equal(sx_world_clear_forces(s->w), SX_OK);
    assert_int_equal(sx_world_update_sleep(s->w, DT), SX_OK);
}

static void same_state(const scene *a, const scene *b) {
    int i;
    for (i = 0; i < a->w->body_slots; ++i) {
        const sx_body_sim *x = &a->w->sims[i], *y = &b->w->sims[i];
        assert_memory_equal(&x->center, &y->center, sizeof(x->center));
        assert_memory_equal(&x->xf, &y->xf, sizeof(x->xf));
        assert_memory_equal(&x->v, &y->v, sizeof(x->v));
        assert_memory_equal(&x->w, &y->w, sizeof(x->w));
    }
}

static void passes_agree(sx_real restitution) {
    scene s[WORLDS];
    int k, i, wide_seen = 0, kept_seen = 0, held_seen = 0;
    circle_restitution = restitution;
    pushed_points = 0;
    for (i = 0; i < WORLDS; ++i)
        build(&s[i]);
    s[0].w->wide_min_colour = INT_MAX; /* one at a time */
    s[1].w->wide_min_colour = 1;       /* every colour wide */
    for (k = 0; k < 90; ++k) {
        for (i = 0; i < WORLDS; ++i) {
            /* world 3 fills afresh at every sub-step */
            step(&s[i], k, i == 3);
        }
        for (i = 1; i < WORLDS; ++i)
            same_state(&s[0], &s[i]);
        wide_seen += s[2].w->bundle_count > 0;
        kept_seen += s[2].w->fill_valid && s[2].w->fill_serial == s[2].w->contact_serial;
        for (i = 0; i < s[2].w->contact_count; ++i)
            held_seen += s[2].w->contacts[i].held;
    }
    /* the scene did exercise the wide lanes and the kept fill */
    assert_true(wide_seen > 60);
    assert_true(kept_seen > 60);
    /* and contacts that kept their manifolds (and so their lanes) */
    assert_true(held_seen > 1000);
    /* and it moved: the circles fell */
    assert_true(s[0].w->sims[sx_body_slot(s[0].w, s[0].ids[1 + BASE * (BASE + 1) / 2])].center.y <
                SX_R(15.0));
    /* the position pass had overlaps to remove, in both orders */
    assert_true(pushed_points > 200);
    /* the worlds took the path the restitution asks for */
    assert_true((s[2].w->bouncy_contacts > 0) == (restitution > SX_R(0.0)));
    for (i = 0; i < WORLDS; ++i)
        sx_world_destroy(s[i].w);
    circle_restitution = SX_R(0.0);
}

static void wide_and_scalar_passes_agree_bit_for_bit(void **state) {
    (void)state;
    passes_agree(SX_R(0.0));
}

static void wide_and_scalar_passes_agree_with_restitution(void **state) {
    (void)state;
    passes_agree(SX_R(0.5));
}

/* Lone boxes on the ground right of the pyramid, the last one on top of
 * the first: contacts that sleep or a disabled body takes out of the solve
 * (a box alone on the ground would not tell: its one block solve is exact
 * from any warm start). */
#define LONE 5

/* The changes between two sub-steps that must end a kept fill (the solver's
 * bodies or active contacts change without a collide), applied alike to
 * every world; lone[] are the lone boxes. */
static void change(scene *s, const int *lone, int k, int i) {
    sx_world *w = s->w;
    if (k == 20 && i == 1) /* a mass */
        assert_int_equal(sx_collider_set_density(w, s->cols[30], SX_R(2.5)), SX_OK);
    if (k == 26 && i == 2) /* a type, and back */
        assert_int_equal(sx_body_set_type(w, s->ids[45], SX_BODY_KINEMATIC), SX_OK);
    if (k == 32 && i == 1)
        assert_int_equal(sx_body_set_type(w, s->ids[45], SX_BODY_DYNAMIC), SX_OK);
    if (k == 38 && i == 1) { /* a stack asleep: its contacts leave the solve */
        assert_int_equal(sx_body_set_awake(w, s->ids[lone[0]], false), SX_OK);
        assert_int_equal(sx_body_set_awake(w, s->ids[lone[4]], false), SX_OK);
    }
    if (k == 38 && i == 3) { /* awake again: its contacts, still listed, rejoin */
        assert_int_equal(sx_body_set_awake(w, s->ids[lone[0]], true), SX_OK);
        assert_int_equal(sx_body_set_awake(w, s->ids[lone[4]], true), SX_OK);
    }
    if (k == 44 && i == 2) /* a contact removed */
        assert_int_equal(sx_destroy_body(w, s->ids[lone[1]]), SX_OK);
    if (k == 50 && i == 1) assert_int_equal(sx_body_set_enabled(w, s->ids[lone[2]], false), SX_OK);
    if (k == 50 && i == 3) /* a mass that leaves the fill's items as they were */
        assert_int_equal(sx_collider_set_density(w, s->cols[lone[3]], SX_R(4.0)), SX_OK);
}

/* A world that keeps its fill between sub-steps (and its colours from
 * collide to collide) and one that fills afresh at every sub-step give the
 * same bits while bodies change between the sub-steps: each change must
 * end the kept fill. */
static void kept_fill_ends_when_the_solver_bodies_change(void **state) {
    scene s[2];
    int lone[LONE], k, i, n, kept = 0;
    (void)state;
    for (n = 0; n < 2; ++n) {
        build(&s[n]);
        s[n].w->def.enable_sleep = false; /* the test puts bodies to sleep */
        for (i = 0; i < LONE; ++i) {
            lone[i] = s[n].count;
            sx_real x = i < LONE - 1 ? SX_R(22.0) + SX_R(3.0) * (sx_real)i : SX_R(22.0);
            add(&s[n], SX_BODY_DYNAMIC, x, i < LONE - 1 ? SX_R(0.5) : SX_R(1.5),
                sx_box_shape(SX_R(0.5), SX_R(0.5)), SX_R(0.6));
        }
    }
    for (k = 0; k < 60; ++k) {
        for (n = 0; n < 2; ++n) {
            sx_world *w = s[n].w;
            assert_int_equal(sx_world_begin_step(w, DT), SX_OK);
            assert_int_equal(sx_world_collide(w), SX_OK);
            for (i = 0; i < SUB; ++i) {
                sx_real h = DT / (sx_real)SUB;
                change(&s[n], lone, k, i);
                assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
                /* world 1 fills afresh at every sub-step */
                if (n == 1) w->fill_valid = false;
                /* world 0 keeps the fill of the sub-step before, unchanged */
                if (n == 0 && i > 0)
                    kept += w->fill_valid && w->fill_epoch == w->solver_epoch &&
                            w->fill_serial == w->contact_serial;
                assert_int_equal(sx_world_solve(w, h), SX_OK);
                assert_int_equal(sx_world_integrate(w, h), SX_OK);
                assert_int_equal(sx_world_separate(w, h), SX_OK);
            }
            assert_int_equal(sx_world_continuous(w), SX_OK);
            assert_int_equal(sx_world_clear_forces(w), SX_OK);
        }
        same_state(&s[0], &s[1]);
    }
    /* most sub-steps after the first took the kept fill without a walk */
    assert_true(kept > 60 * (SUB - 1) - 20);
    for (n = 0; n < 2; ++n)
        sx_world_destroy(s[n].w);
}

/* Six columns of three boxes side by side (each level's contacts one wide
 * colour; a lone box would not tell, as its block solve is exact from any
 * warm start), no sleeping, settled for 20 steps; world 0 solves one at a
 * time, world 1 in lanes. Every body's state must be the same bits. */
static void columns(sx_world *w[2], sx_body_id boxes[2][18]) {
    int i, n, s;
    for (n = 0; n < 2; ++n) {
        sx_world_def wd = sx_default_world_def();
        wd.enable_sleep = false;
        w[n] = sx_world_create(&wd);
        assert_non_null(w[n]);
        sx_test_body(w[n], SX_BODY_STATIC, sx_v2(SX_R(8.0), SX_R(-1.0)),
                     sx_box_shape(SX_R(12.0), SX_R(1.0)), NULL);
        for (i = 0; i < 18; ++i)
            boxes[n][i] = sx_test_body(w[n], SX_BODY_DYNAMIC,
                                       sx_v2(SX_R(3.0) * (sx_real)(i % 6),
                                             SX_R(0.5) + (sx_real)(i / 6)),
                                       sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
    }
    w[0]->wide_min_colour = INT_MAX;
    for (s = 0; s < 20; ++s)
        for (n = 0; n < 2; ++n)
            assert_int_equal(sx_world_step(w[n], DT), SX_OK);
}

static void columns_agree(sx_world *w[2], sx_body_id boxes[2][18]) {
    int i;
    for (i = 0; i < 18; ++i) {
        const sx_body_sim *a = &w[0]->sims[boxes[0][i].index];
        const sx_body_sim *b = &w[1]->sims[boxes[1][i].index];
        assert_memory_equal(&a->center, &b->center, sizeof(a->center));
        assert_memory_equal(&a->xf, &b->xf, sizeof(a->xf));
        assert_memory_equal(&a->v, &b->v, sizeof(a->v));
        assert_memory_equal(&a->w, &b->w, sizeof(a->w));
    }
}

/* The columns' lanes are kept from collide to collide (held). After a
 * step, each contact's impulses are halved as the energy guard's settle
 * would scale them: the next step's warm start must take the halved ones
 * in the held lanes too. */
static void held_lanes_take_the_impulses_the_guard_scaled(void **state) {
    sx_world *w[2];
    sx_body_id boxes[2][18];
    int i, k, n, s, held = 0;
    (void)state;
    columns(w, boxes);
    for (s = 0; s < 10; ++s) {
        for (n = 0; n < 2; ++n) {
            assert_int_equal(sx_world_step(w[n], DT), SX_OK);
            for (i = 0; i < w[n]->contact_count; ++i) {
                sx_contact *c = &w[n]->contacts[i];
                held += n == 1 && c->held;
                for (k = 0; k < c->count; ++k) {
                    c->points[k].normal_impulse *= SX_R(0.5);
                    c->points[k].tangent_impulse *= SX_R(0.5);
                }
            }
            w[n]->fill_fresh = false;
        }
        columns_agree(w, boxes);
    }
    /* the contacts kept their manifolds (most of them, most steps) */
    assert_true(held > 18 * 10 / 2);
    for (n = 0; n < 2; ++n)
        sx_world_destroy(w[n]);
}

/* The resting columns' position pass moves no body, so the next sub-step
 * takes the gaps it found; a box the caller lifts by 2 mm between two
 * sub-steps (the stages run one by one) must end that. */
static void lane_gaps_follow_a_box_moved_between_sub_steps(void **state) {
    sx_world *w[2];
    sx_body_id boxes[2][18];
    sx_real h = DT / SX_R(4.0);
    int i, n;
    (void)state;
    columns(w, boxes);
    for (n = 0; n < 2; ++n) {
        assert_int_equal(sx_world_begin_step(w[n], DT), SX_OK);
        assert_int_equal(sx_world_collide(w[n]), SX_OK);
        for (i = 0; i < 4; ++i) {
            assert_int_equal(sx_world_apply_forces(w[n], h), SX_OK);
            assert_int_equal(sx_world_solve(w[n], h), SX_OK);
            assert_int_equal(sx_world_integrate(w[n], h), SX_OK);
            assert_int_equal(sx_world_separate(w[n], h), SX_OK);
            if (i == 1) {
                sx_vec2 p = sx_body_get_position(w[n], boxes[n][7]);
                /* the pass found the gaps and moved nothing */
                assert_true(n == 0 || w[n]->lane_gaps_current);
                assert_int_equal(sx_body_set_transform(w[n], boxes[n][7],
                                                       sx_v2(p.x, p.y + SX_R(0.002)),
                                                       sx_body_get_angle(w[n], boxes[n][7])),
                                 SX_OK);
            }
        }
        assert_int_equal(sx_world_continuous(w[n]), SX_OK);
        assert_int_equal(sx_world_clear_forces(w[n]), SX_OK);
        assert_int_equal(sx_world_update_sleep(w[n], DT), SX_OK);
    }
    columns_agree(w, boxes);
    for (n = 0; n < 2; ++n)
        sx_world_destroy(w[n]);
}

/* Heavy balls (mass ratio 100) dropped on small ones resting on the ground,
 * eight side by side, six boxes riding a kinematic platform, six on narrow
 * posts and eight frictionless capsules spinning on end: wide colours in
 * which the energy guard scales groups and measures a kinematic body's
 * work. */
static sx_world *guarded_scene(bool platform) {
    sx_world_def wd = sx_default_world_def();
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    sx_world *w;
    int i;
    wd.enable_sleep = false;
    /* 4 sub-steps of 4 passes: in some settings a capsule's group is scaled
     * at every sub-step, and the guard then takes every lane's impulses back */
    wd.sub_steps = 4;
    wd.velocity_iterations = 4;
    w = sx_world_create(&wd);
    assert_non_null(w);
    sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)),
                 sx_box_shape(SX_R(40.0), SX_R(1.0)), NULL);
    for (i = 0; i < 8; ++i) {
        sx_real x = SX_R(3.0) * (sx_real)i;
        sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(x, SX_R(0.25)),
                     sx_circle_shape(sx_v2_zero(), SX_R(0.25)), NULL);
        bd.type = SX_BODY_DYNAMIC;
        bd.position = sx_v2(x + SX_R(0.4), SX_R(2.0));
        assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
        cd.shape = sx_circle_shape(sx_v2_zero(), SX_R(0.8));
        cd.density = SX_R(100.0) * SX_R(0.25) * SX_R(0.25) / (SX_R(0.8) * SX_R(0.8));
        assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    }
    bd = sx_default_body_def();
    /* (without the platform: a static slab, so that no kinematic body's
     * work makes the guard take the impulses back every sub-step) */
    bd.type = platform ? SX_BODY_KINEMATIC : SX_BODY_STATIC;
    bd.position = sx_v2(SX_R(-20.0), SX_R(1.0));
    if (platform) bd.linear_velocity = sx_v2(SX_R(0.5), SX_R(0.0));
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    cd = sx_default_collider_def();
    cd.shape = sx_box_shape(SX_R(8.0), SX_R(0.25));
    assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    for (i = 0; i < 6; ++i) {
        sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(-25.0) + SX_R(2.0) * (sx_real)i, SX_R(1.75)),
                     sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
        /* and boxes on narrow posts, whose groups the guard scales by a
         * rounding's worth */
        sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(30.0) + SX_R(3.0) * (sx_real)i, SX_R(0.5)),
                     sx_box_shape(SX_R(0.2), SX_R(0.5)), NULL);
        sx_test_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(30.1) + SX_R(3.0) * (sx_real)i, SX_R(1.5)),
                     sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
    }
    /* frictionless capsules spinning on end: the warm start at the turned
     * contact point gives energy the guard takes back */
    for (i = 0; i < 8; ++i) {
        bd = sx_default_body_def();
        bd.type = SX_BODY_DYNAMIC;
        bd.position = sx_v2(SX_R(-38.0) + SX_R(1.0) * (sx_real)i, SX_R(0.12));
        bd.angle = SX_R(-1.5707963);
        bd.angular_velocity = SX_R(-5.0) + SX_R(0.5) * (sx_real)i;
        assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
        cd = sx_default_collider_def();
        cd.shape = sx_capsule_shape(sx_v2(SX_R(-0.06), SX_R(0.0)), sx_v2(SX_R(0.06), SX_R(0.0)),
                                    SX_R(0.06));
        cd.density = SX_R(30.0);
        cd.friction = SX_R(0.0);
        assert_int_equal(sx_body_add_collider(w, id, &cd, NULL), SX_OK);
    }
    return w;
}

/* A step by its stages, of `subs` of its sub-steps (a caller may stop
 * early); `hand_back`: every solve hands the impulses back to the contacts
 * (as a step's last does); after each solve, the impulses that
 * sx_world_get_contact reports go into out (four reals a contact). */
static int stage_step(sx_world *w, bool hand_back, int subs, sx_real *out, int *out_count) {
    sx_real h = DT / (sx_real)w->def.sub_steps;
    int i, c, k, in_lanes = 0;
    assert_int_equal(sx_world_begin_step(w, DT), SX_OK);
    if (hand_back) w->step_solves = SX_MAX_SUB_STEPS;
    assert_int_equal(sx_world_collide(w), SX_OK);
    *out_count = 0;
    for (i = 0; i < subs; ++i) {
        assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
        assert_int_equal(sx_world_solve(w, h), SX_OK);
        assert_true(!hand_back || !w->impulses_in_lanes);
        in_lanes += w->impulses_in_lanes;
        for (c = 0; c < sx_world_contact_count(w) && out != NULL; ++c) {
            sx_contact_data d;
            assert_int_equal(sx_world_get_contact(w, c, &d), SX_OK);
            for (k = 0; k < 2; ++k) {
                out[(*out_count)++] = d.normal_impulses[k];
                out[(*out_count)++] = d.tangent_impulses[k];
            }
        }
        assert_int_equal(sx_world_integrate(w, h), SX_OK);
        assert_int_equal(sx_world_separate(w, h), SX_OK);
    }
    assert_int_equal(sx_world_continuous(w), SX_OK);
    assert_int_equal(sx_world_clear_forces(w), SX_OK);
    assert_int_equal(sx_world_update_sleep(w, DT), SX_OK);
    return in_lanes;
}

#define PEEK_MAX 4096

/* sx_world_solve leaves the wide lanes' impulses in the lanes between the
 * sub-steps of a step (all but its last solve); world b hands them back
 * at every solve. sx_world_step (a) and the stages (c) end in b's bits, and
 * sx_world_get_contact between two sub-steps of c reports the impulses b's
 * contacts hold; from the sixth step on, every third step of b and c
 * stops after two of its four sub-steps (c's impulses are still in its
 * lanes when the next collide warm-starts from the contacts, some of them
 * as the heavy balls land). */
static void impulses_left_in_the_lanes_change_no_answer(void **state) {
    static sx_real peek_b[PEEK_MAX], peek_c[PEEK_MAX];
    sx_world *a = guarded_scene(false), *b = guarded_scene(false), *c = guarded_scene(false);
    int s, i, nb, nc, in_lanes = 0;
    (void)state;
    for (s = 0; s < 60; ++s) {
        int subs = s >= 5 && s % 3 == 2 ? 2 : b->def.sub_steps;
        if (s < 5) assert_int_equal(sx_world_step(a, DT), SX_OK);
        assert_true(sx_world_contact_count(b) * 4 * b->def.sub_steps <= PEEK_MAX);
        stage_step(b, true, subs, peek_b, &nb);
        in_lanes += stage_step(c, false, subs, peek_c, &nc);
        assert_int_equal(nb, nc);
        assert_memory_equal(peek_b, peek_c, (size_t)nb * sizeof(sx_real));
        assert_true(!c->impulses_in_lanes || subs == 2);
        for (i = 0; i < a->body_slots; ++i) {
            const sx_body_sim *x = &a->sims[i], *y = &b->sims[i], *z = &c->sims[i];
            assert_memory_equal(&z->xf, &y->xf, sizeof(z->xf));
            assert_memory_equal(&z->v, &y->v, sizeof(z->v));
            assert_memory_equal(&z->w, &y->w, sizeof(z->w));
            /* a's steps are all whole: compared until the first short one */
            if (s >= 5) continue;
            assert_memory_equal(&x->xf, &y->xf, sizeof(x->xf));
            assert_memory_equal(&x->v, &y->v, sizeof(x->v));
            assert_memory_equal(&x->w, &y->w, sizeof(x->w));
        }
    }
    assert_false(a->impulses_in_lanes);
    /* the impulses stayed in the lanes between sub-steps (all 161 times
     * they could in the float build, 72 times in the double build) */
    assert_true(in_lanes > 60 / 2);
    sx_world_destroy(a);
    sx_world_destroy(b);
    sx_world_destroy(c);
}

/* The first sub-step of a step of world w by its stages, up to the solve:
 * world 1 leaves the wide lanes' impulses in the lanes (as every sub-step
 * but a step's last does), world 0 hands them back (its solve counted as
 * past the step's last). */
static void solve_sub_step(sx_world *w, int n, sx_real h) {
    assert_int_equal(sx_world_begin_step(w, DT), SX_OK);
    if (n == 0) w->step_solves = SX_MAX_SUB_STEPS;
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
    assert_int_equal(sx_world_solve(w, h), SX_OK);
}

/* The energy guard reads the contacts' impulses where it measures a
 * kinematic body's work and where it scales a group: a world whose last
 * pass left them in the lanes must hand them back first. Two copies of the
 * scene after 30 steps; one sub-step solved in each, one of them leaving
 * the impulses in the lanes: the guard's measures (the boxes on the moving
 * platform) the same bits. Then the guard made to scale every group (each
 * body 1 m/s faster than before the solve, with a small credit, as
 * test_energy_guard does): the contacts' scaled impulses the same bits. */
static void the_energy_guard_takes_the_impulses_from_the_lanes(void **state) {
    sx_world *w[2];
    sx_real h;
    int n, i, k, s;
    (void)state;
    for (n = 0; n < 2; ++n) {
        w[n] = guarded_scene(true);
        h = DT / (sx_real)w[n]->def.sub_steps;
        for (s = 0; s < 30; ++s)
            assert_int_equal(sx_world_step(w[n], DT), SX_OK);
        solve_sub_step(w[n], n, h);
        assert_true(w[n]->groups_driven && w[n]->bundle_count > 0);
    }
    assert_int_equal(w[0]->group_member_count, w[1]->group_member_count);
    for (i = 0; i < w[0]->group_member_count; ++i) {
        const sx_group_body *x = &w[0]->group_bodies[w[0]->group_members[i]];
        const sx_group_body *y = &w[1]->group_bodies[w[1]->group_members[i]];
        assert_memory_equal(&x->f, &y->f, sizeof(x->f));
        assert_memory_equal(&x->credit, &y->credit, sizeof(x->credit));
    }
    for (n = 0; n < 2; ++n) {
        sx_world_destroy(w[n]);
        w[n] = NULL;
    }
    /* the scaling, on the columns (no kinematic body: no measure before it
     * hands the impulses back) */
    {
        sx_body_id boxes[2][18];
        columns(w, boxes);
        w[0]->wide_min_colour = 0; /* both wide now (the same bits so far) */
        for (n = 0; n < 2; ++n) {
            solve_sub_step(w[n], n, h);
            assert_false(w[n]->groups_driven);
            assert_int_equal(w[n]->impulses_in_lanes, n == 1);
            for (i = 0; i < w[n]->group_member_count; ++i) {
                int slot = w[n]->group_members[i];
                sx_group_body *g = &w[n]->group_bodies[slot];
                sx_body_sim *b = &w[n]->sims[slot];
                g->v = b->v;
                g->w = b->w;
                b->v = sx_add(b->v, sx_v2(SX_R(0.0), SX_R(1.0)));
                g->credit = SX_R(0.005) / b->inv_mass;
            }
            sx_contacts_energy_guard(w[n], h);
            assert_false(w[n]->fill_fresh); /* it scaled */
        }
        assert_int_equal(w[0]->contact_count, w[1]->contact_count);
        for (i = 0; i < w[0]->contact_count; ++i) {
            for (k = 0; k < w[0]->contacts[i].count; ++k) {
                const sx_contact_point *x = &w[0]->contacts[i].points[k];
                const sx_contact_point *y = &w[1]->contacts[i].points[k];
                assert_memory_equal(&x->normal_impulse, &y->normal_impulse, sizeof(sx_real));
                assert_memory_equal(&x->tangent_impulse, &y->tangent_impulse, sizeof(sx_real));
            }
        }
    }
    for (n = 0; n < 2; ++n)
        sx_world_destroy(w[n]);
}

/* The energy guard's groups, kept from collide to collide while the items
 * name the same bodies of the same kinds, against groups linked afresh at
 * every collide: the same members, roots and credits, and the same bits,
 * while bodies change between steps (a type and back, a body destroyed and
 * another made in its slot, a density) and the pile rests in between. */
static void kept_energy_groups_match_relinked_ones(void **state) {
    scene s[2];
    int k, n, i;
    (void)state;
    for (n = 0; n < 2; ++n)
        build(&s[n]);
    for (k = 0; k < 80; ++k) {
        for (n = 0; n < 2; ++n) {
            sx_world *w = s[n].w;
            if (k == 20) {
                assert_int_equal(sx_body_set_type(w, s[n].ids[45], SX_BODY_KINEMATIC), SX_OK);
                assert_int_equal(sx_body_set_linear_velocity(w, s[n].ids[45],
                                                             sx_v2(SX_R(0.2), SX_R(0.0))),
                                 SX_OK);
            }
            if (k == 28) assert_int_equal(sx_body_set_type(w, s[n].ids[45], SX_BODY_DYNAMIC), SX_OK);
            if (k == 36) {
                sx_vec2 p = sx_body_get_position(w, s[n].ids[50]);
                assert_int_equal(sx_destroy_body(w, s[n].ids[50]), SX_OK);
                s[n].ids[50] = sx_test_body(w, SX_BODY_DYNAMIC, p,
                                            sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
            }
            if (k == 44) assert_int_equal(sx_collider_set_density(w, s[n].cols[30], SX_R(2.0)), SX_OK);
            /* world 1 links its groups afresh at every collide */
            if (n == 1) w->groups_linked = false;
            assert_int_equal(sx_world_begin_step(w, DT), SX_OK);
            assert_int_equal(sx_world_collide(w), SX_OK);
            for (i = 0; i < SUB; ++i) {
                sx_real h = DT / (sx_real)SUB;
                assert_int_equal(sx_world_apply_forces(w, h), SX_OK);
                assert_int_equal(sx_world_solve(w, h), SX_OK);
                assert_int_equal(sx_world_integrate(w, h), SX_OK);
                assert_int_equal(sx_world_separate(w, h), SX_OK);
            }
            assert_int_equal(sx_world_continuous(w), SX_OK);
            assert_int_equal(sx_world_clear_forces(w), SX_OK);
            assert_int_equal(sx_world_update_sleep(w, DT), SX_OK);
        }
        same_state(&s[0], &s[1]);
        assert_int_equal(s[0].w->group_member_count, s[1].w->group_member_count);
        assert_memory_equal(s[0].w->group_members, s[1].w->group_members,
                            (size_t)s[0].w->group_member_count * sizeof(int));
        for (i = 0; i < s[0].w->group_member_count; ++i) {
            int slot = s[0].w->group_members[i];
            const sx_group_body *a = &s[0].w->group_bodies[slot], *b = &s[1].w->group_bodies[slot];
            assert_int_equal(a->parent, b->parent);
            assert_memory_equal(&a->credit, &b->credit, sizeof(a->credit));
        }
        assert_true(s[0].w->groups_driven == s[1].w->groups_driven);
    }
    /* world 0 kept its groups across most collides, world 1 never did */
    assert_true(s[1].w->group_epoch - s[0].w->group_epoch > 40u);
    for (n = 0; n < 2; ++n)
        sx_world_destroy(s[n].w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(wide_and_scalar_passes_agree_bit_for_bit),
        cmocka_unit_test(wide_and_scalar_passes_agree_with_restitution),
        cmocka_unit_test(kept_fill_ends_when_the_solver_bodies_change),
        cmocka_unit_test(kept_energy_groups_match_relinked_ones),
        cmocka_unit_test(held_lanes_take_the_impulses_the_guard_scaled),
        cmocka_unit_test(lane_gaps_follow_a_box_moved_between_sub_steps),
        cmocka_unit_test(impulses_left_in_the_lanes_change_no_answer),
        cmocka_unit_test(the_energy_guard_takes_the_impulses_from_the_lanes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
