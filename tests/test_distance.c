/* sepax tests — distance between shapes (GJK), shape casts and time of
 * impact: analytic cases, random pairs of every kind checked against an
 * independent long-double reference (the exact distance between the cores,
 * from every vertex to every edge), near the origin and 1e4 m away, the
 * never-past-contact promise of the casts sampled along the motion, and
 * hostile input. */
#include <math.h>
#include <string.h>

#include "query_fixtures.h"

#define EPS SX_TEST_EPS

typedef long double ld;

typedef struct ref_core {
    ld x[SX_MAX_POLYGON_VERTICES], y[SX_MAX_POLYGON_VERTICES];
    ld radius;
    int count;
} ref_core;

/* The shape's core in world coordinates, in long double. */
static ref_core ref_place(const sx_shape *s, sx_xform xf) {
    ref_core c;
    sx_vec2 p[SX_MAX_POLYGON_VERTICES];
    int i;
    memset(&c, 0, sizeof(c));
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        p[0] = s->u.circle.center;
        c.radius = s->u.circle.radius;
        c.count = 1;
        break;
    case SX_SHAPE_SEGMENT:
        p[0] = s->u.segment.a;
        p[1] = s->u.segment.b;
        c.count = 2;
        break;
    case SX_SHAPE_CAPSULE:
        p[0] = s->u.capsule.a;
        p[1] = s->u.capsule.b;
        c.radius = s->u.capsule.radius;
        c.count = 2;
        break;
    default:
        c.count = s->u.polygon.count;
        for (i = 0; i < c.count; ++i)
            p[i] = s->u.polygon.vertices[i];
        c.radius = s->u.polygon.radius;
        break;
    }
    for (i = 0; i < c.count; ++i) {
        ld qc = xf.q.c, qs = xf.q.s;
        c.x[i] = (ld)xf.p.x + qc * p[i].x - qs * p[i].y;
        c.y[i] = (ld)xf.p.y + qs * p[i].x + qc * p[i].y;
    }
    return c;
}

static ld ref_point_segment(ld px, ld py, ld ax, ld ay, ld bx, ld by) {
    ld ex = bx - ax, ey = by - ay, ee = ex * ex + ey * ey, t = 0;
    if (ee > 0) t = ((px - ax) * ex + (py - ay) * ey) / ee;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    ex = ax + t * ex - px;
    ey = ay + t * ey - py;
    return sqrtl(ex * ex + ey * ey);
}

/* Distance from every point of a to every edge of b (a point when b has one). */
static ld ref_one_way(const ref_core *a, const ref_core *b) {
    ld best = 1e300L;
    int i, j;
    for (i = 0; i < a->count; ++i) {
        for (j = 0; j < b->count; ++j) {
            int k = (j + 1) % b->count;
            ld d = ref_point_segment(a->x[i], a->y[i], b->x[j], b->y[j], b->x[k], b->y[k]);
            if (d < best) best = d;
        }
    }
    return best;
}

/* The gap between the rounded shapes when their cores are apart (for
 * convex cores the closest pair is a vertex against an edge). */
static ld ref_gap(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    ref_core ca = ref_place(a, xa), cb = ref_place(b, xb);
    ld d1 = ref_one_way(&ca, &cb), d2 = ref_one_way(&cb, &ca);
    return (d1 < d2 ? d1 : d2) - ca.radius - cb.radius;
}

/* Cores apart by SAT's boolean test on the bare cores (radius 0). */
static sx_shape core_of(const sx_shape *s) {
    sx_shape c = *s;
    if (c.type == SX_SHAPE_CIRCLE) c.u.circle.radius = SX_R(0.0);
    if (c.type == SX_SHAPE_CAPSULE) c = sx_segment_shape(s->u.capsule.a, s->u.capsule.b);
    if (c.type == SX_SHAPE_POLYGON) c.u.polygon.radius = SX_R(0.0);
    return c;
}

static void check_random_pairs(sx_vec2 offset, double tol, uint64_t seed) {
    sx_test_rng rng = sx_test_rng_make(seed);
    int i, apart = 0, over = 0;
    for (i = 0; i < 4000; ++i) {
        int ka, kb;
        sx_shape a = qf_random_shape(&rng, &ka), b = qf_random_shape(&rng, &kb);
        sx_xform xa = qf_random_xform(&rng), xb = qf_random_xform(&rng);
        sx_shape ca = core_of(&a), cb = core_of(&b);
        sx_distance_output d, r;
        ld gap;
        /* close enough that a fair share of the pairs cross */
        xb.p = sx_add(xa.p, qf_random_vec(&rng, -4.0, 4.0));
        xa.p = sx_add(xa.p, offset);
        xb.p = sx_add(xb.p, offset);
        assert_int_equal(sx_shape_distance(&a, xa, &b, xb, &d), SX_OK);
        assert_true(sx_is_finite(d.distance) && d.distance >= SX_R(0.0));
        assert_true(sx_vec2_is_finite(d.point_a) && sx_vec2_is_finite(d.point_b));
        if (sx_overlap(&ca, xa, &cb, xb)) {
            /* cores cross: the library's SAT says so, GJK must agree */
            assert_near(d.distance, 0.0, tol);
            ++over;
            continue;
        }
        gap = ref_gap(&a, xa, &b, xb);
        assert_near(d.distance, gap > 0 ? (double)gap : 0.0, tol);
        if (gap > 10 * tol) {
            ++apart;
            assert_false(d.overlap);
            assert_near(sx_length(d.normal), 1.0, tol);
            assert_near(sx_length(sx_sub(d.point_b, d.point_a)), (double)gap, tol);
            /* the points lie on the surfaces, and the normal joins them */
            assert_near(sx_shape_distance_to_point(&a, xa, d.point_a, NULL, NULL), 0.0, 4 * tol);
            assert_near(sx_shape_distance_to_point(&b, xb, d.point_b, NULL, NULL), 0.0, 4 * tol);
            assert_vec2_near(sx_mul_add(d.point_a, d.distance, d.normal), d.point_b, 4 * tol);
            /* swapped arguments: same distance, mirrored normal */
            assert_int_equal(sx_shape_distance(&b, xb, &a, xa, &r), SX_OK);
            assert_near(r.distance, d.distance, tol);
            assert_vec2_near(r.normal, sx_neg(d.normal), 8 * tol / (gap > 1 ? 1.0 : (double)gap));
        } else if (gap < -10 * tol) {
            assert_true(d.overlap);
        }
    }
    /* the draws cover both cases */
    assert_true(apart > 1000);
    assert_true(over > 200);
}

static void random_pairs_match_the_reference_near_the_origin(void **state) {
    (void)state;
    check_random_pairs(sx_v2_zero(), QF_TOL, 11);
}

static void random_pairs_match_the_reference_far_from_the_origin(void **state) {
    (void)state;
    /* float: coordinates near 1e4 carry ~1e-3 of rounding already */
#ifdef SX_DOUBLE
    check_random_pairs(sx_v2(SX_R(1e4), SX_R(-1e4)), 1e-8, 12);
#else
    check_random_pairs(sx_v2(SX_R(1e4), SX_R(-1e4)), 1e-2, 12);
#endif
}

static void circle_and_box_distance_is_analytic(void **state) {
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(0.5)), box = sx_box_shape(SX_R(1.0), SX_R(2.0));
    sx_distance_output d;
    (void)state;
    assert_int_equal(sx_shape_distance(&c, sx_xform_make(sx_v2(SX_R(-4.0), SX_R(1.0)), SX_R(0.3)),
                                       &box, sx_xform_identity(), &d),
                     SX_OK);
    assert_near(d.distance, 2.5, EPS);
    assert_vec2_near(d.normal, sx_v2(SX_R(1.0), SX_R(0.0)), EPS);
    assert_vec2_near(d.point_a, sx_v2(SX_R(-3.5), SX_R(1.0)), EPS);
    assert_vec2_near(d.point_b, sx_v2(SX_R(-1.0), SX_R(1.0)), EPS);
    /* corner region: to the vertex (1, 2) */
    assert_int_equal(sx_shape_distance(&c, sx_xform_make(sx_v2(SX_R(4.0), SX_R(6.0)), SX_R(0.0)),
                                       &box, sx_xform_identity(), &d),
                     SX_OK);
    assert_near(d.distance, 5.0 - 0.5, EPS);
    assert_vec2_near(d.point_b, sx_v2(SX_R(1.0), SX_R(2.0)), EPS);
    assert_vec2_near(d.normal, sx_v2(SX_R(-0.6), SX_R(-0.8)), EPS);
    /* overlapping: zero distance, flagged, the normal of the manifold */
    assert_int_equal(sx_shape_distance(&c, sx_xform_make(sx_v2(SX_R(-1.2), SX_R(0.0)), SX_R(0.0)),
                                       &box, sx_xform_identity(), &d),
                     SX_OK);
    assert_true(d.overlap);
    assert_near(d.distance, 0.0, 0.0);
    assert_vec2_near(d.normal, sx_v2(SX_R(1.0), SX_R(0.0)), EPS);
    /* crossing boxes (cores overlap) */
    assert_int_equal(sx_shape_distance(&box, sx_xform_make(sx_v2(SX_R(0.5), SX_R(0.0)), SX_R(0.0)),
                                       &box, sx_xform_identity(), &d),
                     SX_OK);
    assert_true(d.overlap);
    assert_near(sx_length(d.normal), 1.0, EPS);
}

static void parallel_segments_distance(void **state) {
    sx_shape a = sx_segment_shape(sx_v2(SX_R(-1.0), SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(0.0)));
    sx_shape b =
        sx_capsule_shape(sx_v2(SX_R(-3.0), SX_R(0.0)), sx_v2(SX_R(3.0), SX_R(0.0)), SX_R(0.25));
    sx_distance_output d;
    (void)state;
    assert_int_equal(sx_shape_distance(&a, sx_xform_identity(), &b,
                                       sx_xform_make(sx_v2(SX_R(0.0), SX_R(2.0)), SX_R(0.0)), &d),
                     SX_OK);
    assert_near(d.distance, 1.75, EPS);
    assert_vec2_near(d.normal, sx_v2(SX_R(0.0), SX_R(1.0)), EPS);
    assert_near(d.point_a.y, 0.0, EPS);
    assert_near(d.point_b.y, 1.75, EPS);
    assert_true((double)d.point_a.x >= -1.0 - EPS && (double)d.point_a.x <= 1.0 + EPS);
}

/* ---- shape cast ------------------------------------------------------------ */

static void circle_cast_at_a_box_hits_its_face(void **state) {
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(0.5)), box = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape_cast_output o;
    (void)state;
    assert_int_equal(sx_shape_cast(&c, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)), SX_R(1.0),
                                   &box, sx_xform_make(sx_v2(SX_R(5.0), SX_R(0.2)), SX_R(0.0)), &o),
                     SX_OK);
    assert_true(o.hit);
    assert_near(o.fraction, 0.35, EPS);
    assert_vec2_near(o.normal, sx_v2(SX_R(-1.0), SX_R(0.0)), EPS);
    assert_vec2_near(o.point, sx_v2(SX_R(4.0), SX_R(0.0)), EPS);
    /* short of the box: a miss */
    assert_int_equal(sx_shape_cast(&c, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)), SX_R(0.3),
                                   &box, sx_xform_make(sx_v2(SX_R(5.0), SX_R(0.2)), SX_R(0.0)), &o),
                     SX_OK);
    assert_false(o.hit);
    /* passing above it: a miss */
    assert_int_equal(sx_shape_cast(&c, sx_xform_identity(), sx_v2(SX_R(10.0), SX_R(0.0)), SX_R(1.0),
                                   &box, sx_xform_make(sx_v2(SX_R(5.0), SX_R(1.6)), SX_R(0.0)), &o),
                     SX_OK);
    assert_false(o.hit);
}

static void box_cast_turned_hits_a_segment_with_its_corner(void **state) {
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_shape seg = sx_segment_shape(sx_v2(SX_R(-5.0), SX_R(0.0)), sx_v2(SX_R(5.0), SX_R(0.0)));
    sx_shape_cast_output o;
    double h = 0.5 * sqrt(2.0);
    (void)state;
    assert_int_equal(
        sx_shape_cast(&box, sx_xform_make(sx_v2(SX_R(0.0), SX_R(3.0)), SX_R(0.25) * SX_PI),
                      sx_v2(SX_R(0.0), SX_R(-4.0)), SX_R(1.0), &seg, sx_xform_identity(), &o),
        SX_OK);
    assert_true(o.hit);
    assert_near(o.fraction, (3.0 - h) / 4.0, EPS);
    assert_vec2_near(o.normal, sx_v2(SX_R(0.0), SX_R(1.0)), 10 * EPS);
    assert_vec2_near(o.point, sx_v2(SX_R(0.0), SX_R(0.0)), 10 * EPS);
}

static void overlapping_start_hits_at_zero_with_the_mtv_direction(void **state) {
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(0.5)), box = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape_cast_output o;
    (void)state;
    assert_int_equal(sx_shape_cast(&c, sx_xform_make(sx_v2(SX_R(-1.2), SX_R(0.0)), SX_R(0.0)),
                                   sx_v2(SX_R(10.0), SX_R(0.0)), SX_R(1.0), &box,
                                   sx_xform_identity(), &o),
                     SX_OK);
    assert_true(o.hit);
    assert_near(o.fraction, 0.0, 0.0);
    assert_vec2_near(o.normal, sx_v2(SX_R(-1.0), SX_R(0.0)), EPS);
    /* zero translation: a hit only when touching */
    assert_int_equal(sx_shape_cast(&c, sx_xform_make(sx_v2(SX_R(-3.0), SX_R(0.0)), SX_R(0.0)),
                                   sx_v2_zero(), SX_R(1.0), &box, sx_xform_identity(), &o),
                     SX_OK);
    assert_false(o.hit);
}

/* The cast's fraction is at contact by the reference, and the reference
 * sees a gap at every sampled fraction before it. */
static void random_casts_stop_at_contact_never_past(void **state) {
    sx_test_rng rng = sx_test_rng_make(21);
    int i, hits = 0;
    (void)state;
    for (i = 0; i < 1500; ++i) {
        int ka, kb, k;
        sx_shape a = qf_random_shape(&rng, &ka), b = qf_random_shape(&rng, &kb);
        sx_xform xa = qf_random_xform(&rng), xb = qf_random_xform(&rng), xt = xa;
        sx_vec2 tr = sx_scale(sx_sub(xb.p, xa.p), (sx_real)sx_test_rng_range(&rng, 0.5, 2.0));
        sx_shape_cast_output o;
        tr = sx_add(tr, qf_random_vec(&rng, -2.0, 2.0));
        assert_int_equal(sx_shape_cast(&a, xa, tr, SX_R(1.0), &b, xb, &o), SX_OK);
        if (!o.hit) {
            /* a miss: no sample touches */
            for (k = 0; k <= 200; ++k) {
                xt.p = sx_mul_add(xa.p, (sx_real)(k / 200.0), tr);
                assert_true(!sx_overlap(&a, xt, &b, xb) ||
                            ref_gap(&a, xt, &b, xb) > -(ld)SX_LINEAR_SLOP);
            }
            continue;
        }
        assert_true(o.fraction >= SX_R(0.0) && o.fraction <= SX_R(1.0));
        assert_near(sx_length(o.normal), 1.0, QF_TOL);
        if (o.fraction == SX_R(0.0)) continue;
        ++hits;
        xt.p = sx_mul_add(xa.p, o.fraction, tr);
        /* at the fraction: touching within the cast's target */
        {
            sx_distance_output d;
            assert_int_equal(sx_shape_distance(&a, xt, &b, xb, &d), SX_OK);
            assert_true(d.distance <= SX_CAST_TARGET + SX_TOI_TOLERANCE + QF_TOL);
        }
        for (k = 0; k < 100; ++k) {
            sx_real f = o.fraction * (sx_real)(k / 100.0);
            xt.p = sx_mul_add(xa.p, f, tr);
            assert_false(sx_overlap(&a, xt, &b, xb) && ref_gap(&a, xt, &b, xb) < -(ld)QF_TOL);
        }
    }
    assert_true(hits > 300);
}

/* ---- time of impact ------------------------------------------------------ */

static sx_motion motion(double x0, double y0, double x1, double y1, double a0, double a1) {
    sx_motion m;
    m.local_center = sx_v2_zero();
    m.c0 = sx_v2((sx_real)x0, (sx_real)y0);
    m.c1 = sx_v2((sx_real)x1, (sx_real)y1);
    m.angle0 = (sx_real)a0;
    m.angle1 = (sx_real)a1;
    return m;
}

static sx_xform motion_xf(const sx_motion *m, double t) {
    sx_rot q = sx_rot_make((sx_real)((double)m->angle0 + t * (double)(m->angle1 - m->angle0)));
    sx_xform x;
    x.q = q;
    x.p = sx_sub(sx_lerp(m->c0, m->c1, (sx_real)t), sx_rotate(q, m->local_center));
    return x;
}

static void toi_of_a_head_on_pair_is_analytic(void **state) {
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    sx_motion ma = motion(0, 0, 10, 0, 0, 0), mb = motion(6, 0, 6, 0, 0, 0);
    sx_toi_output o;
    (void)state;
    assert_int_equal(sx_time_of_impact(&c, &ma, &c, &mb, SX_LINEAR_SLOP, &o), SX_OK);
    assert_int_equal(o.state, SX_TOI_HIT);
    /* gap 5 - slop reached after 5 - slop of 10 */
    assert_true((double)o.fraction <= (5.0 - (double)SX_LINEAR_SLOP) / 10.0 + EPS);
    assert_true((double)o.fraction >=
                (5.0 - (double)SX_LINEAR_SLOP - (double)SX_TOI_TOLERANCE) / 10.0 - EPS);
    assert_vec2_near(o.normal, sx_v2(SX_R(1.0), SX_R(0.0)), EPS);
    /* moving apart: separated */
    ma = motion(0, 0, -10, 0, 0, 0);
    assert_int_equal(sx_time_of_impact(&c, &ma, &c, &mb, SX_LINEAR_SLOP, &o), SX_OK);
    assert_int_equal(o.state, SX_TOI_SEPARATED);
    assert_near(o.fraction, 1.0, 0.0);
}

/* A thin blade turning half a turn about its centre meets a ball that the
 * blade's ends pass through: the reference gap stays above zero up to the
 * reported fraction, and is within target + tolerance there. */
static void spinning_blade_toi_stops_before_the_ball(void **state) {
    sx_shape blade = sx_box_shape(SX_R(2.0), SX_R(0.02));
    sx_shape ball = sx_circle_shape(sx_v2_zero(), SX_R(0.1));
    sx_motion mb = motion(0, 1.5, 0, 1.5, 0, 0), ma = motion(0, 0, 0, 0, 0, 3.0);
    sx_toi_output o;
    double target = (double)SX_LINEAR_SLOP;
    int k;
    (void)state;
    assert_int_equal(sx_time_of_impact(&blade, &ma, &ball, &mb, SX_LINEAR_SLOP, &o), SX_OK);
    assert_int_equal(o.state, SX_TOI_HIT);
    for (k = 0; k <= 400; ++k) {
        double t = (double)o.fraction * k / 400.0;
        assert_true(ref_gap(&blade, motion_xf(&ma, t), &ball, sx_xform_make(mb.c0, SX_R(0.0))) >
                    (ld)(target - 1e-4));
    }
    {
        ld g = ref_gap(&blade, motion_xf(&ma, (double)o.fraction), &ball,
                       sx_xform_make(mb.c0, SX_R(0.0)));
        assert_true(g <= (ld)(target + (double)SX_TOI_TOLERANCE + 1e-4));
    }
}

static void check_random_tois(sx_vec2 offset, double tol, uint64_t seed) {
    sx_test_rng rng = sx_test_rng_make(seed);
    int i, hits = 0;
    double target = (double)SX_LINEAR_SLOP;
    for (i = 0; i < 800; ++i) {
        int ka, kb, k;
        sx_shape a = qf_random_shape(&rng, &ka), b = qf_random_shape(&rng, &kb);
        sx_motion ma, mb;
        sx_toi_output o;
        ma.local_center = qf_random_vec(&rng, -1.0, 1.0);
        mb.local_center = qf_random_vec(&rng, -1.0, 1.0);
        ma.c0 = sx_add(qf_random_vec(&rng, -10.0, 10.0), offset);
        mb.c0 = sx_add(qf_random_vec(&rng, -10.0, 10.0), offset);
        ma.c1 = sx_add(mb.c0, qf_random_vec(&rng, -3.0, 3.0));
        mb.c1 = sx_add(mb.c0, qf_random_vec(&rng, -2.0, 2.0));
        ma.angle0 = sx_test_rng_range(&rng, -3.0, 3.0);
        ma.angle1 = ma.angle0 + sx_test_rng_range(&rng, -4.0, 4.0);
        mb.angle0 = sx_test_rng_range(&rng, -3.0, 3.0);
        mb.angle1 = mb.angle0 + sx_test_rng_range(&rng, -1.0, 1.0);
        assert_int_equal(sx_time_of_impact(&a, &ma, &b, &mb, SX_LINEAR_SLOP, &o), SX_OK);
        assert_true(o.fraction >= SX_R(0.0) && o.fraction <= SX_R(1.0));
        if (o.state == SX_TOI_STARTS_CLOSE) continue;
        /* sampled reference: the gap stays above the target up to the answer */
        for (k = 0; k < 300; ++k) {
            double t = (double)o.fraction * k / 300.0;
            sx_xform xa = motion_xf(&ma, t), xb = motion_xf(&mb, t);
            sx_shape ca = core_of(&a), cb = core_of(&b);
            assert_false(sx_overlap(&ca, xa, &cb, xb));
            assert_true(ref_gap(&a, xa, &b, xb) > (ld)(target - tol));
        }
        if (o.state == SX_TOI_HIT) {
            ++hits;
            assert_true(ref_gap(&a, motion_xf(&ma, (double)o.fraction), &b,
                                motion_xf(&mb, (double)o.fraction)) <=
                        (ld)(target + (double)SX_TOI_TOLERANCE + tol));
        }
    }
    assert_true(hits > 150);
}

static void random_tois_are_never_past_contact(void **state) {
    (void)state;
    check_random_tois(sx_v2_zero(), 10.0 * (double)QF_TOL, 31);
}

/* 1e4 m out: float coordinates there are 1e-3 apart, the answer is good to
 * a few of those */
static void random_tois_far_from_the_origin_are_never_past_contact(void **state) {
    (void)state;
#ifdef SX_DOUBLE
    check_random_tois(sx_v2(SX_R(1e4), SX_R(-1e4)), 1e-8, 32);
#else
    check_random_tois(sx_v2(SX_R(1e4), SX_R(-1e4)), 5e-3, 32);
#endif
}

/* ---- hostile input ---------------------------------------------------------- */

static void hostile_input_answers_a_status(void **state) {
    sx_shape c = sx_circle_shape(sx_v2_zero(), SX_R(0.5)), box = sx_box_shape(SX_R(1.0), SX_R(1.0));
    sx_shape bad = sx_circle_shape(sx_v2_zero(), SX_R(-1.0));
    sx_shape nanc = sx_circle_shape(sx_v2((sx_real)NAN, SX_R(0.0)), SX_R(1.0));
    sx_xform id = sx_xform_identity(),
             nanx = sx_xform_make(sx_v2((sx_real)NAN, SX_R(0.0)), SX_R(0.0));
    sx_distance_output d;
    sx_shape_cast_output o;
    sx_toi_output t;
    sx_motion m = motion(0, 0, 1, 0, 0, 0), mn = m;
    sx_real huge = SX_R(1e30);
    (void)state;
    mn.c1.x = (sx_real)INFINITY;
    assert_int_equal(sx_shape_distance(NULL, id, &box, id, &d), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_shape_distance(&c, id, &box, id, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_shape_distance(&bad, id, &box, id, &d), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_shape_distance(&nanc, id, &box, id, &d), SX_ERR_NONFINITE);
    assert_near(d.distance, 0.0, 0.0);
    assert_int_equal(sx_shape_distance(&c, nanx, &box, id, &d), SX_ERR_NONFINITE);
    assert_int_equal(sx_shape_cast(&c, id, sx_v2((sx_real)NAN, SX_R(0.0)), SX_R(1.0), &box, id, &o),
                     SX_ERR_NONFINITE);
    assert_false(o.hit);
    assert_int_equal(sx_shape_cast(&c, id, sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(-1.0), &box, id, &o),
                     SX_ERR_INVALID_ARG);
    assert_int_equal(
        sx_shape_cast(&c, id, sx_v2(SX_R(1.0), SX_R(0.0)), (sx_real)INFINITY, &box, id, &o),
        SX_ERR_NONFINITE);
    /* an enormous translation: a hit or an error, never a NaN */
    {
        sx_status s = sx_shape_cast(&c, sx_xform_make(sx_v2(SX_R(-5.0), SX_R(0.0)), SX_R(0.0)),
                                    sx_v2(huge, SX_R(0.0)), SX_R(1.0), &box, id, &o);
        assert_true(s == SX_OK || s == SX_ERR_NONFINITE);
        if (s == SX_OK) {
            assert_true(o.hit);
            assert_true(sx_is_finite(o.fraction) && sx_vec2_is_finite(o.point) &&
                        sx_vec2_is_finite(o.normal));
            assert_true(o.fraction * huge < SX_R(5.0));
        }
    }
    assert_int_equal(sx_time_of_impact(&c, &m, &box, NULL, SX_R(0.0), &t), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_time_of_impact(&c, &mn, &box, &m, SX_R(0.0), &t), SX_ERR_NONFINITE);
    assert_int_equal(sx_time_of_impact(&c, &m, &box, &m, SX_R(-1.0), &t), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_time_of_impact(&c, &m, &box, &m, (sx_real)NAN, &t), SX_ERR_NONFINITE);
    /* zero motion, overlapping: starts close; zero motion apart: separated */
    m = motion(0, 0, 0, 0, 0, 0);
    assert_int_equal(sx_time_of_impact(&c, &m, &box, &m, SX_LINEAR_SLOP, &t), SX_OK);
    assert_int_equal(t.state, SX_TOI_STARTS_CLOSE);
    mn = motion(5, 0, 5, 0, 0, 0);
    assert_int_equal(sx_time_of_impact(&c, &m, &box, &mn, SX_LINEAR_SLOP, &t), SX_OK);
    assert_int_equal(t.state, SX_TOI_SEPARATED);
    /* enormous speed and spin: an answer, finite */
    m = motion(-5, 0, 1e9, 0, 0, 1e6);
    assert_int_equal(sx_time_of_impact(&box, &m, &c, &mn, SX_LINEAR_SLOP, &t), SX_OK);
    assert_true(sx_is_finite(t.fraction) && t.fraction >= SX_R(0.0) && t.fraction <= SX_R(1.0));
    assert_true(t.state == SX_TOI_HIT || t.state == SX_TOI_ITERATION_LIMIT);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(circle_and_box_distance_is_analytic),
        cmocka_unit_test(parallel_segments_distance),
        cmocka_unit_test(random_pairs_match_the_reference_near_the_origin),
        cmocka_unit_test(random_pairs_match_the_reference_far_from_the_origin),
        cmocka_unit_test(circle_cast_at_a_box_hits_its_face),
        cmocka_unit_test(box_cast_turned_hits_a_segment_with_its_corner),
        cmocka_unit_test(overlapping_start_hits_at_zero_with_the_mtv_direction),
        cmocka_unit_test(random_casts_stop_at_contact_never_past),
        cmocka_unit_test(toi_of_a_head_on_pair_is_analytic),
        cmocka_unit_test(spinning_blade_toi_stops_before_the_ball),
        cmocka_unit_test(random_tois_are_never_past_contact),
        cmocka_unit_test(random_tois_far_from_the_origin_are_never_past_contact),
        cmocka_unit_test(hostile_input_answers_a_status),
    };
    return cmocka_run_group_tests_name("distance", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
