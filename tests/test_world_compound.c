/* sepax tests — compound colliders in the world: attached with
 * sx_body_add_compound or sx_body_add_outline, they act as one collider.
 *
 * Scenes: a ball resting in the notch of a static U (three boxes), a wide
 * box landing on the teeth of a comb outline (and a narrow one falling
 * between them), a box pushed out of a U by the compound MTV. Then the mass
 * of an L against its closed form, queries (ray, point, bounds, shape) that
 * must name the right part and miss the notch, one contact per touching part
 * pair with warm starting per pair, one event per collider pair, debug draw
 * per part, and bad input. */
#include <math.h>
#include <string.h>

#include "test_support.h"

#define DT (SX_R(1.0) / SX_R(60.0))
#define PI_D 3.14159265358979323846

static sx_world *make_world(void) {
    sx_world_def def = sx_default_world_def();
    sx_world *w = sx_world_create(&def);
    assert_non_null(w);
    return w;
}

static sx_body_id make_body(sx_world *w, sx_body_type type, double x, double y) {
    sx_body_def bd = sx_default_body_def();
    sx_body_id id;
    bd.type = type;
    bd.position = sx_v2((sx_real)x, (sx_real)y);
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    return id;
}

static sx_collider_id add_shape(sx_world *w, sx_body_id b, sx_shape shape) {
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id id;
    cd.shape = shape;
    assert_int_equal(sx_body_add_collider(w, b, &cd, &id), SX_OK);
    return id;
}

static sx_xform at(double x, double y, double angle) {
    return sx_xform_make(sx_v2((sx_real)x, (sx_real)y), (sx_real)angle);
}

/* U in its body frame: floor [-1.5, 1.5] x [0, 0.5] (part 0), walls
 * [-1.5, -1] (part 1) and [1, 1.5] (part 2) x [0.5, 2]; the notch is
 * [-1, 1] x [0.5, 2]. */
static sx_collider_id add_u(sx_world *w, sx_body_id b) {
    sx_compound_part parts[3];
    sx_compound c;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id id;
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(1.5), SX_R(0.25)), at(0.0, 0.25, 0.0));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(0.75)), at(-1.25, 1.25, 0.0));
    parts[2] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(0.75)), at(1.25, 1.25, 0.0));
    c.parts = parts;
    c.count = 3;
    assert_int_equal(sx_body_add_compound(w, b, &c, &cd, &id), SX_OK);
    /* the world keeps its own copy: scribbling over ours changes nothing */
    memset(parts, 0, sizeof parts);
    assert_int_equal(sx_collider_get_part_count(w, id), 3);
    return id;
}

static void run(sx_world *w, double seconds) {
    int i, n = (int)(seconds * 60.0 + 0.5);
    for (i = 0; i < n; ++i)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
}

/* ---- scenes ---------------------------------------------------------------- */

static void ball_rests_in_the_notch_of_a_static_u(void **state) {
    sx_world *w = make_world();
    sx_body_id u = make_body(w, SX_BODY_STATIC, 0.0, 0.0), ball;
    sx_collider_id uc = add_u(w, u);
    sx_vec2 p, settled;
    int i, floor_contacts = 0;
    (void)state;
    ball = make_body(w, SX_BODY_DYNAMIC, 0.0, 1.5);
    add_shape(w, ball, sx_circle_shape(sx_v2_zero(), SX_R(0.4)));
    /* thrown sideways: it must hit the right wall and stay in the notch (it
     * rolls back to the left wall, which it meets at about 4 s) */
    assert_int_equal(sx_body_set_linear_velocity(w, ball, sx_v2(SX_R(4.0), SX_R(0.0))), SX_OK);
    run(w, 5.0);
    p = sx_body_get_position(w, ball);
    /* resting on the floor (top at y = 0.5) within two slops, inside the
     * notch's walls */
    assert_near(p.y, 0.5 + 0.4, 2.0 * (double)sx_world_linear_slop(w));
    assert_true((double)p.x >= -1.0 + 0.4 - 0.01 && (double)p.x <= 1.0 - 0.4 + 0.01);
    assert_true(sx_length(sx_body_get_linear_velocity(w, ball)) < SX_R(0.05));
    /* its contact is with the U's floor part */
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data cd;
        assert_int_equal(sx_world_get_contact(w, i, &cd), SX_OK);
        if (sx_collider_id_to_u64(cd.collider_a) != sx_collider_id_to_u64(uc)) continue;
        if (cd.part_a != 0) continue; /* it may lean on a wall too */
        ++floor_contacts;
        assert_near(cd.normal.y, 1.0, 1e-3);
    }
    assert_int_equal(floor_contacts, 1);
    /* and it stays there */
    settled = p;
    run(w, 2.0);
    p = sx_body_get_position(w, ball);
    assert_near(p.x, settled.x, 1e-3);
    assert_near(p.y, settled.y, 1e-3);
    sx_world_destroy(w);
}

static void wide_box_lands_on_the_comb_teeth(void **state) {
    sx_world *w = make_world();
    sx_body_id comb = make_body(w, SX_BODY_STATIC, 0.0, 0.0), box, narrow;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id cc;
    sx_vec2 p[16];
    int n = sx_test_comb_outline(p, 4), i, parts_touched = 0, last_part = -1;
    double slop;
    (void)state;
    assert_int_equal(sx_body_add_outline(w, comb, p, n, &cd, &cc), SX_OK);
    assert_true(sx_collider_get_part_count(w, cc) >= 4);
    slop = (double)sx_world_linear_slop(w);
    /* 2.4 wide, centred over the 1-wide gap between the teeth at x in
     * [2,3] and [4,5] */
    box = make_body(w, SX_BODY_DYNAMIC, 3.5, 5.0);
    add_shape(w, box, sx_box_shape(SX_R(1.2), SX_R(0.6)));
    /* 0.6 wide, over the gap x in [5, 6]: falls between the teeth */
    narrow = make_body(w, SX_BODY_DYNAMIC, 5.5, 5.0);
    add_shape(w, narrow, sx_box_shape(SX_R(0.3), SX_R(0.3)));
    run(w, 3.0);
    /* the wide box rests on the teeth's tops (y = 3) */
    assert_near(sx_body_get_position(w, box).y, 3.0 + 0.6, 2.0 * slop);
    assert_near(sx_body_get_position(w, box).x, 3.5, 0.01);
    assert_near(sx_body_get_angle(w, box), 0.0, 1e-3);
    /* the narrow one on the spine between the teeth (y = 1) */
    assert_near(sx_body_get_position(w, narrow).y, 1.0 + 0.3, 2.0 * slop);
    /* the wide box touches two teeth: one contact per touching part pair,
     * in part order */
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data c;
        assert_int_equal(sx_world_get_contact(w, i, &c), SX_OK);
        if (sx_body_id_to_u64(c.body_b) != sx_body_id_to_u64(box)) continue;
        assert_true(c.part_a > last_part);
        last_part = c.part_a;
        ++parts_touched;
        assert_near(c.normal.y, 1.0, 1e-3);
        assert_true(c.normal_impulses[0] + c.normal_impulses[1] > SX_R(0.0));
    }
    assert_int_equal(parts_touched, 2);
    sx_world_destroy(w);
}

static void contacts_warm_start_per_part_pair_and_report_one_event(void **state) {
    sx_world *w = make_world();
    sx_body_id comb = make_body(w, SX_BODY_STATIC, 0.0, 0.0), box;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id cc, bc;
    sx_contact_events ev;
    sx_vec2 p[16];
    sx_contact_data before[8], after;
    int n = sx_test_comb_outline(p, 4), i, count, begins = 0;
    sx_world_def def = sx_default_world_def();
    (void)state;
    sx_world_destroy(w);
    def.enable_sleep = false;
    w = sx_world_create(&def);
    assert_non_null(w);
    comb = make_body(w, SX_BODY_STATIC, 0.0, 0.0);
    assert_int_equal(sx_body_add_outline(w, comb, p, n, &cd, &cc), SX_OK);
    /* starting 1 cm above the teeth: within the speculative margin */
    box = make_body(w, SX_BODY_DYNAMIC, 3.5, 3.61);
    bc = add_shape(w, box, sx_box_shape(SX_R(1.2), SX_R(0.6)));
    /* the first step: the box lands on two teeth at once, one begin event
     * for the collider pair */
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    ev = sx_world_get_contact_events(w);
    for (i = 0; i < ev.begin_count; ++i) {
        if (sx_collider_id_to_u64(ev.begin[i].collider_b) == sx_collider_id_to_u64(bc)) {
            assert_int_equal(sx_collider_id_to_u64(ev.begin[i].collider_a),
                             sx_collider_id_to_u64(cc));
            ++begins;
        }
    }
    assert_int_equal(begins, 1);
    run(w, 1.0);
    /* warm starting: a new collide carries each part pair's impulses over */
    count = sx_world_contact_count(w);
    assert_int_equal(count, 2);
    for (i = 0; i < count; ++i)
        assert_int_equal(sx_world_get_contact(w, i, &before[i]), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    assert_int_equal(sx_world_contact_count(w), count);
    for (i = 0; i < count; ++i) {
        sx_real held = SX_R(0.0);
        int k;
        assert_int_equal(sx_world_get_contact(w, i, &after), SX_OK);
        assert_int_equal(after.part_a, before[i].part_a);
        assert_int_equal(after.count, before[i].count);
        /* four points on two teeth share the weight in no unique way: a
         * point may hold nothing, each tooth holds some */
        for (k = 0; k < after.count; ++k) {
            held += before[i].normal_impulses[k];
            assert_near(after.normal_impulses[k], before[i].normal_impulses[k], 0.0);
        }
        assert_true(held > SX_R(0.0));
    }
    assert_true(before[0].part_a != before[1].part_a);
    /* no further event while it rests; lifting it off ends the pair once */
    assert_int_equal(sx_body_set_transform(w, box, sx_v2(SX_R(3.5), SX_R(8.0)), SX_R(0.0)), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    ev = sx_world_get_contact_events(w);
    assert_int_equal(ev.begin_count, 0);
    assert_int_equal(ev.end_count, 1);
    assert_int_equal(sx_collider_id_to_u64(ev.end[0].collider_a), sx_collider_id_to_u64(cc));
    sx_world_destroy(w);
}

/* Reports whether the query found collider *(sx_collider_id *)context. */
typedef struct find_ctx {
    sx_collider_id target;
    int found, total;
} find_ctx;

static bool find_fn(sx_collider_id collider, sx_body_id body, void *context) {
    find_ctx *f = (find_ctx *)context;
    (void)body;
    ++f->total;
    if (sx_collider_id_to_u64(collider) == sx_collider_id_to_u64(f->target)) ++f->found;
    return true;
}

static void compound_mtv_separates_the_body_in_one_move(void **state) {
    sx_world *w = make_world();
    sx_body_id u = make_body(w, SX_BODY_STATIC, 1.0, -2.0), box;
    sx_collider_id uc = add_u(w, u);
    sx_compound_part parts[3];
    sx_compound c;
    sx_shape bs = sx_box_shape(SX_R(0.45), SX_R(0.3));
    sx_xform xb, xu;
    sx_vec2 mtv;
    find_ctx f;
    int i, k;
    double slop = (double)sx_world_linear_slop(w);
    (void)state;
    assert_int_equal(sx_body_set_transform(w, u, sx_v2(SX_R(1.0), SX_R(-2.0)), SX_R(0.3)), SX_OK);
    /* the compound as the world holds it */
    for (k = 0; k < 3; ++k)
        assert_int_equal(sx_collider_get_part(w, uc, k, &parts[k]), SX_OK);
    c.parts = parts;
    c.count = 3;
    xu = sx_body_get_transform(w, u);
    /* a box jammed into the lower-left corner of the notch, overlapping the
     * floor and the left wall */
    box = make_body(w, SX_BODY_DYNAMIC, 0.0, 0.0);
    add_shape(w, box, bs);
    xb.q = xu.q;
    xb.p = sx_xform_point(xu, sx_v2(SX_R(-0.8), SX_R(0.55)));
    assert_int_equal(sx_body_set_transform(w, box, xb.p, SX_R(0.3)), SX_OK);
    memset(&f, 0, sizeof f);
    f.target = uc;
    sx_world_query_shape(w, &bs, xb, find_fn, &f);
    assert_int_equal(f.found, 1);
    assert_true(sx_compound_mtv(&c, xu, &bs, xb, &mtv));
    assert_true(sx_length(mtv) > SX_R(0.1));
    /* moving the box by -mtv (the compound by mtv, relatively) leaves no
     * penetration: every contact of the next collide is at most touching */
    xb.p = sx_sub(xb.p, mtv);
    assert_int_equal(sx_body_set_transform(w, box, xb.p, SX_R(0.3)), SX_OK);
    assert_int_equal(sx_world_collide(w), SX_OK);
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data cd;
        assert_int_equal(sx_world_get_contact(w, i, &cd), SX_OK);
        for (k = 0; k < cd.count; ++k)
            assert_true((double)cd.depths[k] <= 1e-3 * slop + 1e-5);
    }
    /* and 0.1% further it overlaps nothing of the U */
    xb.p = sx_sub(xb.p, sx_scale(mtv, SX_R(1e-3)));
    memset(&f, 0, sizeof f);
    f.target = uc;
    sx_world_query_shape(w, &bs, xb, find_fn, &f);
    assert_int_equal(f.found, 0);
    sx_world_destroy(w);
}

/* ---- mass -------------------------------------------------------------------- */

static void l_compound_has_the_analytic_mass_properties(void **state) {
    /* L = [0,2] x [0,1] and [0,1] x [1,2]. Area 3, centroid (5/6, 5/6),
     * polar moment about the centroid 11/6 per unit density. */
    sx_world *w = make_world();
    sx_body_id a = make_body(w, SX_BODY_DYNAMIC, 4.0, -1.0);
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, 0.0, 0.0);
    sx_compound_part parts[2];
    sx_compound c;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id ca, cb;
    sx_vec2 l[6];
    static const double xy[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
    const double density = 2.5;
    int i;
    (void)state;
    cd.density = (sx_real)density;
    /* the long box given as a tall box turned by 90 degrees */
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(1.0)), at(1.0, 0.5, PI_D / 2.0));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(0.5, 1.5, 0.0));
    c.parts = parts;
    c.count = 2;
    assert_int_equal(sx_body_add_compound(w, a, &c, &cd, &ca), SX_OK);
    assert_near(sx_body_get_mass(w, a), 3.0 * density, 1e-5);
    assert_vec2_near(sx_body_get_local_center(w, a),
                     sx_v2((sx_real)(5.0 / 6.0), (sx_real)(5.0 / 6.0)), 1e-5);
    assert_vec2_near(sx_body_get_world_center(w, a),
                     sx_v2((sx_real)(4.0 + 5.0 / 6.0), (sx_real)(-1.0 + 5.0 / 6.0)), 1e-5);
    assert_near(sx_body_get_inertia(w, a), 11.0 / 6.0 * density, 1e-4);
    /* the same L as an outline, in reverse (clockwise) order */
    for (i = 0; i < 6; ++i)
        l[5 - i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
    assert_int_equal(sx_body_add_outline(w, b, l, 6, &cd, &cb), SX_OK);
    assert_near(sx_body_get_mass(w, b), 3.0 * density, 1e-5);
    assert_vec2_near(sx_body_get_local_center(w, b),
                     sx_v2((sx_real)(5.0 / 6.0), (sx_real)(5.0 / 6.0)), 1e-5);
    assert_near(sx_body_get_inertia(w, b), 11.0 / 6.0 * density, 1e-4);
    /* a second collider adds by the parallel-axis theorem: a unit disc at
     * (5/6 + 3, 5/6) of density 2.5 */
    {
        sx_collider_def disc = sx_default_collider_def();
        double md = PI_D * density, total = 3.0 * density + md;
        double cx = (3.0 * density * (5.0 / 6.0) + md * (5.0 / 6.0 + 3.0)) / total;
        double i_l = 11.0 / 6.0 * density + 3.0 * density * (cx - 5.0 / 6.0) * (cx - 5.0 / 6.0);
        double i_d = 0.5 * md + md * (5.0 / 6.0 + 3.0 - cx) * (5.0 / 6.0 + 3.0 - cx);
        disc.density = (sx_real)density;
        disc.shape =
            sx_circle_shape(sx_v2((sx_real)(5.0 / 6.0 + 3.0), (sx_real)(5.0 / 6.0)), SX_R(1.0));
        assert_int_equal(sx_body_add_collider(w, b, &disc, NULL), SX_OK);
        assert_near(sx_body_get_mass(w, b), total, 1e-4);
        assert_near(sx_body_get_local_center(w, b).x, cx, 1e-5);
        assert_near(sx_body_get_inertia(w, b), i_l + i_d, 1e-3);
    }
    /* removing the compound leaves a body without it */
    assert_int_equal(sx_destroy_collider(w, ca), SX_OK);
    assert_near(sx_body_get_mass(w, a), 1.0, 0.0);
    assert_int_equal(sx_collider_get_part_count(w, ca), 0);
    sx_world_destroy(w);
}

/* ---- queries ------------------------------------------------------------------ */

typedef struct draw_ctx {
    int shapes, boxes;
    sx_aabb bounds;
    bool inside;
} draw_ctx;

static void draw_shape(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                       void *context) {
    draw_ctx *d = (draw_ctx *)context;
    sx_aabb b = sx_shape_aabb(shape, xf);
    (void)type;
    (void)sensor;
    ++d->shapes;
    d->inside = d->inside && b.lower.x >= d->bounds.lower.x - SX_R(1e-5) &&
                b.lower.y >= d->bounds.lower.y - SX_R(1e-5) &&
                b.upper.x <= d->bounds.upper.x + SX_R(1e-5) &&
                b.upper.y <= d->bounds.upper.y + SX_R(1e-5);
}

static void draw_box(sx_aabb box, void *context) {
    (void)box;
    ++((draw_ctx *)context)->boxes;
}

static void queries_hit_the_right_part(void **state) {
    sx_world *w = make_world();
    sx_body_id u = make_body(w, SX_BODY_STATIC, 2.0, 1.0);
    sx_collider_id uc = add_u(w, u);
    sx_world_ray_hit hit;
    sx_ray_input ray;
    find_ctx f;
    sx_debug_draw dd;
    draw_ctx d;
    (void)state;
    /* the U sits at (2, 1): floor [0.5, 3.5] x [1, 1.5], walls up to y = 3 */
    memset(&f, 0, sizeof f);
    f.target = uc;
    /* a point in the notch is not in the collider; one in the left wall is */
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(2.0), SX_R(2.0)), find_fn, &f), 0);
    assert_int_equal(sx_world_query_point(w, sx_v2(SX_R(0.7), SX_R(2.5)), find_fn, &f), 1);
    assert_int_equal(f.found, 1);
    /* a box in the notch misses (although inside the U's bounds); one
     * reaching into the right wall hits */
    assert_int_equal(
        sx_world_query_aabb(
            w, sx_aabb_make(sx_v2(SX_R(1.5), SX_R(1.7)), sx_v2(SX_R(2.5), SX_R(2.8))), NULL, NULL),
        0);
    assert_int_equal(
        sx_world_query_aabb(
            w, sx_aabb_make(sx_v2(SX_R(2.5), SX_R(1.7)), sx_v2(SX_R(3.1), SX_R(2.8))), NULL, NULL),
        1);
    /* shapes likewise */
    {
        sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.4));
        assert_int_equal(sx_world_query_shape(w, &ball, at(2.0, 2.2, 0.0), NULL, NULL), 0);
        assert_int_equal(sx_world_query_shape(w, &ball, at(2.0, 1.8, 0.0), NULL, NULL), 1);
    }
    /* a ray down the notch hits the floor (part 0) at y = 1.5 */
    memset(&ray, 0, sizeof ray);
    ray.origin = sx_v2(SX_R(2.2), SX_R(5.0));
    ray.translation = sx_v2(SX_R(0.0), SX_R(-10.0));
    ray.max_fraction = SX_R(1.0);
    assert_true(sx_world_cast_ray(w, &ray, &hit));
    assert_int_equal(sx_collider_id_to_u64(hit.collider), sx_collider_id_to_u64(uc));
    assert_int_equal(hit.part, 0);
    assert_vec2_near(hit.point, sx_v2(SX_R(2.2), SX_R(1.5)), 1e-5);
    assert_vec2_near(hit.normal, sx_v2(SX_R(0.0), SX_R(1.0)), 1e-5);
    /* a ray from the right at wall height hits the right wall (part 2) */
    ray.origin = sx_v2(SX_R(6.0), SX_R(2.5));
    ray.translation = sx_v2(SX_R(-10.0), SX_R(0.0));
    assert_true(sx_world_cast_ray(w, &ray, &hit));
    assert_int_equal(hit.part, 2);
    assert_near(hit.point.x, 3.5, 1e-5);
    /* from inside the notch to the left: the left wall's inner face */
    ray.origin = sx_v2(SX_R(2.0), SX_R(2.5));
    assert_true(sx_world_cast_ray(w, &ray, &hit));
    assert_int_equal(hit.part, 1);
    assert_near(hit.point.x, 1.0, 1e-5);
    assert_near(hit.normal.x, 1.0, 1e-5);
    /* a ray through the notch above the floor, between the walls, misses */
    ray.origin = sx_v2(SX_R(2.0), SX_R(5.0));
    ray.translation = sx_v2(SX_R(0.0), SX_R(-3.2));
    assert_false(sx_world_cast_ray(w, &ray, &hit));
    /* debug draw: one shape per part, one box per collider */
    memset(&dd, 0, sizeof dd);
    memset(&d, 0, sizeof d);
    d.bounds = sx_aabb_make(sx_v2(SX_R(0.5), SX_R(1.0)), sx_v2(SX_R(3.5), SX_R(3.0)));
    d.inside = true;
    dd.draw_shape = draw_shape;
    dd.draw_aabb = draw_box;
    dd.context = &d;
    assert_int_equal(sx_world_draw(w, &dd), SX_OK);
    assert_int_equal(d.shapes, 3);
    assert_int_equal(d.boxes, 1);
    assert_true(d.inside);
    sx_world_destroy(w);
}

static void a_compound_sensor_sees_what_enters_its_parts(void **state) {
    sx_world *w = make_world();
    sx_body_id s = make_body(w, SX_BODY_STATIC, 0.0, 0.0), ball;
    sx_compound_part parts[3];
    sx_compound c;
    sx_collider_def cd = sx_default_collider_def();
    sx_sensor_events ev;
    (void)state;
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(1.5), SX_R(0.25)), at(0.0, 0.25, 0.0));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(0.75)), at(-1.25, 1.25, 0.0));
    parts[2] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(0.75)), at(1.25, 1.25, 0.0));
    c.parts = parts;
    c.count = 3;
    cd.sensor = true;
    assert_int_equal(sx_body_add_compound(w, s, &c, &cd, NULL), SX_OK);
    /* a ball floating in the notch (no gravity) overlaps no part */
    ball = make_body(w, SX_BODY_DYNAMIC, 0.0, 1.3);
    add_shape(w, ball, sx_circle_shape(sx_v2_zero(), SX_R(0.3)));
    assert_int_equal(sx_world_set_gravity(w, sx_v2_zero()), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    ev = sx_world_get_sensor_events(w);
    assert_int_equal(ev.begin_count, 0);
    /* moved into the right wall, it is seen */
    assert_int_equal(sx_body_set_transform(w, ball, sx_v2(SX_R(1.0), SX_R(1.3)), SX_R(0.0)), SX_OK);
    assert_int_equal(sx_world_step(w, DT), SX_OK);
    ev = sx_world_get_sensor_events(w);
    assert_int_equal(ev.begin_count, 1);
    sx_world_destroy(w);
}

static void a_dynamic_l_falls_and_rests_on_the_ground(void **state) {
    /* an L outline, dynamic, dropped turned by 0.4 rad onto a static box:
     * it tips onto a face and comes to rest, both parts able to touch */
    sx_world *w = make_world();
    sx_body_id ground = make_body(w, SX_BODY_STATIC, 0.0, -0.5), l;
    sx_collider_def cd = sx_default_collider_def();
    sx_vec2 p[6];
    static const double xy[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
    sx_aabb box;
    sx_compound_part parts[8];
    sx_compound c;
    int i, n;
    (void)state;
    add_shape(w, ground, sx_box_shape(SX_R(10.0), SX_R(0.5)));
    for (i = 0; i < 6; ++i)
        p[i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
    l = make_body(w, SX_BODY_DYNAMIC, 0.0, 2.0);
    assert_int_equal(sx_body_set_transform(w, l, sx_v2(SX_R(0.0), SX_R(2.0)), SX_R(0.4)), SX_OK);
    {
        sx_collider_id lc;
        assert_int_equal(sx_body_add_outline(w, l, p, 6, &cd, &lc), SX_OK);
        n = sx_collider_get_part_count(w, lc);
        assert_true(n >= 2 && n <= 8);
        for (i = 0; i < n; ++i)
            assert_int_equal(sx_collider_get_part(w, lc, i, &parts[i]), SX_OK);
        assert_int_equal(sx_collider_get_part(w, lc, n, &parts[0]), SX_ERR_INVALID_ARG);
        assert_int_equal(sx_collider_get_part(w, lc, 0, &parts[0]), SX_OK);
    }
    c.parts = parts;
    c.count = n;
    run(w, 5.0);
    box = sx_compound_aabb(&c, sx_body_get_transform(w, l));
    /* lying on the ground (top at y = 0): its lowest point within two slops */
    assert_near(box.lower.y, 0.0, 2.0 * (double)sx_world_linear_slop(w));
    assert_true(sx_length(sx_body_get_linear_velocity(w, l)) < SX_R(0.05));
    assert_true(sx_absr(sx_body_get_angular_velocity(w, l)) < SX_R(0.05));
    assert_true(sx_vec2_is_finite(sx_body_get_position(w, l)));
    sx_world_destroy(w);
}

/* ---- bad input ------------------------------------------------------------------ */

static void bad_outlines_and_compounds_return_statuses(void **state) {
    sx_world *w = make_world();
    sx_body_id b = make_body(w, SX_BODY_DYNAMIC, 0.0, 0.0), dead;
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id out, cid, sq;
    sx_compound_part parts[2];
    sx_compound c;
    sx_vec2 square[4], bowtie[4], line[4], nan_pts[4];
    sx_compound_part part;
    int i;
    (void)state;
    square[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    square[1] = sx_v2(SX_R(1.0), SX_R(0.0));
    square[2] = sx_v2(SX_R(1.0), SX_R(1.0));
    square[3] = sx_v2(SX_R(0.0), SX_R(1.0));
    bowtie[0] = square[0];
    bowtie[1] = square[2];
    bowtie[2] = square[1];
    bowtie[3] = square[3];
    for (i = 0; i < 4; ++i) {
        line[i] = sx_v2((sx_real)i, (sx_real)(2 * i));
        nan_pts[i] = square[i];
    }
    nan_pts[2].y = (sx_real)NAN;
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), sx_xform_identity());
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(1.0, 0.0, 0.0));
    c.parts = parts;
    c.count = 2;
    dead = make_body(w, SX_BODY_STATIC, 0.0, 0.0);
    assert_int_equal(sx_destroy_body(w, dead), SX_OK);

    /* outlines */
    out.index = 7;
    out.generation = 7;
    assert_int_equal(sx_body_add_outline(w, b, nan_pts, 4, &cd, &out), SX_ERR_NONFINITE);
    assert_int_equal(sx_collider_id_to_u64(out), 0u);
    assert_int_equal(sx_body_add_outline(w, b, bowtie, 4, &cd, &out), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_add_outline(w, b, line, 4, &cd, &out), SX_ERR_DEGENERATE);
    assert_int_equal(sx_body_add_outline(w, b, square, 2, &cd, &out), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_add_outline(w, b, NULL, 4, &cd, &out), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_add_outline(w, b, square, 4, NULL, &out), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_add_outline(NULL, b, square, 4, &cd, &out), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_body_add_outline(w, dead, square, 4, &cd, &out), SX_ERR_STALE_HANDLE);
    cd.density = SX_R(-1.0);
    assert_int_equal(sx_body_add_outline(w, b, square, 4, &cd, &out), SX_ERR_INVALID_ARG);
    cd = sx_default_collider_def();
    cd.friction = (sx_real)NAN;
    assert_int_equal(sx_body_add_outline(w, b, square, 4, &cd, &out), SX_ERR_NONFINITE);
    cd = sx_default_collider_def();
    /* a bad def shape is ignored: the outline is the shape */
    cd.shape = sx_circle_shape(sx_v2_zero(), SX_R(-1.0));
    assert_int_equal(sx_body_add_outline(w, b, square, 4, &cd, &sq), SX_OK);
    assert_int_equal(sx_collider_get_part_count(w, sq), 1);
    cd = sx_default_collider_def();

    /* compounds */
    assert_int_equal(sx_body_add_compound(w, b, NULL, &cd, &out), SX_ERR_INVALID_ARG);
    c.count = 0;
    assert_int_equal(sx_body_add_compound(w, b, &c, &cd, &out), SX_ERR_INVALID_ARG);
    c.count = 2;
    c.parts = NULL;
    assert_int_equal(sx_body_add_compound(w, b, &c, &cd, &out), SX_ERR_INVALID_ARG);
    c.parts = parts;
    assert_int_equal(sx_body_add_compound(w, dead, &c, &cd, &out), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_body_add_compound(w, b, &c, NULL, &out), SX_ERR_INVALID_ARG);
    parts[1].offset.p.y = (sx_real)INFINITY;
    assert_int_equal(sx_body_add_compound(w, b, &c, &cd, &out), SX_ERR_NONFINITE);
    parts[1] =
        sx_compound_part_make(sx_circle_shape(sx_v2_zero(), SX_R(-1.0)), sx_xform_identity());
    assert_int_equal(sx_body_add_compound(w, b, &c, &cd, &out), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_id_to_u64(out), 0u);
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.5)), at(1.0, 0.0, 0.0));
    assert_int_equal(sx_body_add_compound(w, b, &c, &cd, &cid), SX_OK);
    /* a body with the failed attempts has only its two good colliders */
    assert_near(sx_body_get_mass(w, b), 3.0, 1e-5);

    /* stale collider handles */
    assert_int_equal(sx_destroy_collider(w, cid), SX_OK);
    assert_int_equal(sx_collider_get_part_count(w, cid), 0);
    assert_int_equal(sx_collider_get_part(w, cid, 0, &part), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_destroy_collider(w, cid), SX_ERR_STALE_HANDLE);
    assert_int_equal(sx_collider_get_part(NULL, cid, 0, &part), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_get_part(w, sq, 0, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_get_part(w, sq, -1, &part), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_get_part(w, sq, 1, &part), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_collider_get_part(w, sq, 0, &part), SX_OK);
    assert_near(sx_shape_area(&part.shape), 1.0, 1e-5);
    assert_int_equal(sx_collider_get_part_count(NULL, sq), 0);
    /* the world still steps without NaN */
    run(w, 0.5);
    assert_true(sx_vec2_is_finite(sx_body_get_position(w, b)));
    sx_world_destroy(w);
}

/* Two dynamic compounds on each other: a U (opening up) on the ground and
 * an L dropped into its notch. Compound against compound makes one contact
 * per touching part pair; both come to rest with the L inside the notch. */
static void a_compound_rests_inside_another_compound(void **state) {
    sx_world *w = make_world();
    sx_body_id ground = make_body(w, SX_BODY_STATIC, 0.0, -0.5), u, l;
    sx_collider_id uc, lc;
    sx_compound_part parts[2];
    sx_compound c;
    sx_collider_def cd = sx_default_collider_def();
    sx_aabb lb;
    int i, pair_contacts = 0;
    double slop;
    (void)state;
    add_shape(w, ground, sx_box_shape(SX_R(10.0), SX_R(0.5)));
    u = make_body(w, SX_BODY_DYNAMIC, 0.0, 0.0);
    uc = add_u(w, u);
    /* a small L: [0, 1] x [0, 0.4] and [0, 0.4] x [0.4, 1], dropped with its
     * corner at (-0.5, 1.5): it falls into the notch [-1, 1] x [0.5, 2] */
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(0.5), SX_R(0.2)), at(0.5, 0.2, 0.0));
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.2), SX_R(0.3)), at(0.2, 0.7, 0.0));
    c.parts = parts;
    c.count = 2;
    l = make_body(w, SX_BODY_DYNAMIC, -0.5, 1.5);
    assert_int_equal(sx_body_add_compound(w, l, &c, &cd, &lc), SX_OK);
    slop = (double)sx_world_linear_slop(w);
    run(w, 4.0);
    /* the U stands on the ground, the L lies on the U's floor (y = 0.5) */
    assert_near(sx_body_get_position(w, u).y, 0.0, 2.0 * slop);
    assert_near(sx_body_get_angle(w, u), 0.0, 1e-2);
    lb = sx_compound_aabb(&c, sx_body_get_transform(w, l));
    assert_near(lb.lower.y, 0.5, 3.0 * slop);
    assert_true(lb.lower.x >= SX_R(-1.0) - SX_R(0.01) && lb.upper.x <= SX_R(1.0) + SX_R(0.01));
    assert_true(sx_length(sx_body_get_linear_velocity(w, l)) < SX_R(0.05));
    /* L on the U's floor: contacts between U part 0 and L parts */
    for (i = 0; i < sx_world_contact_count(w); ++i) {
        sx_contact_data d;
        assert_int_equal(sx_world_get_contact(w, i, &d), SX_OK);
        if (sx_collider_id_to_u64(d.collider_a) != sx_collider_id_to_u64(uc) ||
            sx_collider_id_to_u64(d.collider_b) != sx_collider_id_to_u64(lc)) {
            continue;
        }
        ++pair_contacts;
        assert_true(d.part_a >= 0 && d.part_a < 3 && d.part_b >= 0 && d.part_b < 2);
        if (d.part_a == 0) assert_near(d.normal.y, 1.0, 1e-2);
    }
    assert_true(pair_contacts >= 1);
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ball_rests_in_the_notch_of_a_static_u),
        cmocka_unit_test(wide_box_lands_on_the_comb_teeth),
        cmocka_unit_test(contacts_warm_start_per_part_pair_and_report_one_event),
        cmocka_unit_test(compound_mtv_separates_the_body_in_one_move),
        cmocka_unit_test(l_compound_has_the_analytic_mass_properties),
        cmocka_unit_test(queries_hit_the_right_part),
        cmocka_unit_test(a_compound_sensor_sees_what_enters_its_parts),
        cmocka_unit_test(a_dynamic_l_falls_and_rests_on_the_ground),
        cmocka_unit_test(a_compound_rests_inside_another_compound),
        cmocka_unit_test(bad_outlines_and_compounds_return_statuses),
    };
    return cmocka_run_group_tests_name("world_compound", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
