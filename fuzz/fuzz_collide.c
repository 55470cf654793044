/* sepax fuzzing — the narrowphase on arbitrary shape pairs and transforms.
 *
 * Two decoded shapes (valid ones of every type, and raw values: bad radii,
 * garbage polygons, unknown types) under decoded transforms (NaN or infinite
 * angles, raw non-unit rotations, huge offsets) go through sx_overlap,
 * sx_mtv, sx_collide and sx_collide_ex in both argument orders and through
 * the typed pair function for their types. Checked: sx_overlap is symmetric
 * and equals sx_mtv's answer; sx_mtv(b, a) is exactly -sx_mtv(a, b); no
 * output is ever NaN and valid input in the promised range gives finite
 * output; a non-overlapping MTV is zero; manifolds have 0..2 points, a unit
 * normal, finite depths no deeper in the gap than the margin, and a zero
 * normal when empty; same-type manifolds have points exactly when sx_overlap
 * is true; different-type manifolds mirror exactly when the arguments swap;
 * the deepest depth matches the MTV's length up to the documented
 * hysteresis; the pair functions answer as the generic ones. */
#include "fuzz_input.h"

/* Rounding allowance for a length computed from coordinates of magnitude
 * `scale`. */
static sx_real col_round(sx_real scale) {
    return SX_R(256.0) * SX_REAL_EPSILON * sx_maxr(scale, SX_R(1.0));
}

/* valid: both shapes validate, both rotations come from finite angles and
 * everything is within SX_HUGE; a raw non-unit rotation, a garbage polygon
 * (whose stored normals may be zero) or overflowing magnitudes only have to
 * avoid NaN. */
static void col_check_manifold(const sx_manifold *m, int n, sx_real margin, bool valid,
                               sx_real scale) {
    int i;
    FZ_CHECK(n >= 0 && n <= 2);
    FZ_CHECK(m->count == n);
    if (n == 0) {
        FZ_CHECK(m->normal.x == SX_R(0.0) && m->normal.y == SX_R(0.0));
        return;
    }
    FZ_CHECK(!fz_is_nan(m->normal.x) && !fz_is_nan(m->normal.y));
    if (valid) FZ_CHECK(fz_is_unit(m->normal));
    for (i = 0; i < n; ++i) {
        FZ_CHECK(!fz_is_nan(m->points[i].depth));
        FZ_CHECK(!fz_is_nan(m->points[i].point.x) && !fz_is_nan(m->points[i].point.y));
        if (valid) {
            FZ_CHECK(sx_is_finite(m->points[i].depth));
            FZ_CHECK(fz_finite_vec(m->points[i].point));
            FZ_CHECK(m->points[i].depth >= -margin - col_round(scale));
        }
    }
}

static sx_real col_max_depth(const sx_manifold *m) {
    sx_real d = m->points[0].depth;
    if (m->count > 1) d = sx_maxr(d, m->points[1].depth);
    return d;
}

/* The typed pair function for (a, b) when that order exists, compared with
 * the generic entry points. */
static void col_check_pair_function(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                    sx_real margin) {
    bool ov = false, hit = false;
    sx_vec2 v = sx_v2_zero(), g;
    sx_manifold m, gm;
    int n = 0;
    memset(&m, 0, sizeof m);
#define COL_PAIR(ta, tb, fa, fb, name)                                                             \
    if (a->type == ta && b->type == tb) {                                                          \
        ov = sx_overlap_##name(&a->u.fa, xa, &b->u.fb, xb);                                        \
        hit = sx_mtv_##name(&a->u.fa, xa, &b->u.fb, xb, &v);                                       \
        n = sx_collide_##name(&a->u.fa, xa, &b->u.fb, xb, margin, &m);                             \
    } else
    COL_PAIR(SX_SHAPE_CIRCLE, SX_SHAPE_CIRCLE, circle, circle, circles)
    COL_PAIR(SX_SHAPE_SEGMENT, SX_SHAPE_CIRCLE, segment, circle, segment_circle)
    COL_PAIR(SX_SHAPE_SEGMENT, SX_SHAPE_SEGMENT, segment, segment, segments)
    COL_PAIR(SX_SHAPE_CAPSULE, SX_SHAPE_CIRCLE, capsule, circle, capsule_circle)
    COL_PAIR(SX_SHAPE_CAPSULE, SX_SHAPE_SEGMENT, capsule, segment, capsule_segment)
    COL_PAIR(SX_SHAPE_CAPSULE, SX_SHAPE_CAPSULE, capsule, capsule, capsules)
    COL_PAIR(SX_SHAPE_POLYGON, SX_SHAPE_CIRCLE, polygon, circle, polygon_circle)
    COL_PAIR(SX_SHAPE_POLYGON, SX_SHAPE_SEGMENT, polygon, segment, polygon_segment)
    COL_PAIR(SX_SHAPE_POLYGON, SX_SHAPE_CAPSULE, polygon, capsule, polygon_capsule)
    COL_PAIR(SX_SHAPE_POLYGON, SX_SHAPE_POLYGON, polygon, polygon, polygons) { return; }
#undef COL_PAIR
    FZ_CHECK(ov == sx_overlap(a, xa, b, xb));
    FZ_CHECK(hit == sx_mtv(a, xa, b, xb, &g));
    FZ_CHECK(fz_same_bits(v, g));
    FZ_CHECK(n == sx_collide_ex(a, xa, b, xb, margin, &gm));
    FZ_CHECK(n == 0 || fz_same_bits(m.normal, gm.normal));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_reader r = fz_reader_make(data, size);
    sx_shape a = fz_shape(&r), b = fz_shape(&r);
    bool sane_a, sane_b;
    sx_xform xa = fz_xform(&r, &sane_a), xb = fz_xform(&r, &sane_b);
    sx_real margin = fz_u8(&r) % 2u ? fz_real(&r) : SX_R(0.0);
    sx_real scale = sx_maxr(sx_maxr(fz_shape_extent(&a), fz_shape_extent(&b)),
                            sx_maxr(fz_extent(&xa.p, 1), fz_extent(&xb.p, 1)));
    /* Valid shapes, sane transforms, everything within SX_HUGE: the output
     * must be finite, not merely free of NaN. */
    bool valid = sx_shape_validate(&a) == SX_OK && sx_shape_validate(&b) == SX_OK && sane_a &&
                 sane_b && scale <= SX_HUGE;
    sx_real eff_margin = sx_is_finite(margin) && margin > SX_R(0.0) ? margin : SX_R(0.0);
    bool ov_ab, ov_ba, hit_ab, hit_ba;
    sx_vec2 mtv_ab, mtv_ba;
    sx_manifold m, m0, m0r;
    int n, n0, n0r;

    ov_ab = sx_overlap(&a, xa, &b, xb);
    ov_ba = sx_overlap(&b, xb, &a, xa);
    FZ_CHECK(ov_ab == ov_ba);

    hit_ab = sx_mtv(&a, xa, &b, xb, &mtv_ab);
    hit_ba = sx_mtv(&b, xb, &a, xa, &mtv_ba);
    /* Beyond SX_HUGE, or with a raw non-unit rotation, the two tests may
     * round differently (the promise there is only: no crash, no NaN). */
    if (valid) {
        FZ_CHECK(hit_ab == ov_ab);
        FZ_CHECK(hit_ba == ov_ba);
        FZ_CHECK(sx_mtv(&a, xa, &b, xb, NULL) == ov_ab);
    }
    FZ_CHECK(!fz_is_nan(mtv_ab.x) && !fz_is_nan(mtv_ab.y));
    /* Exactly negated (== so that +0 and -0 count as the same zero), except
     * for two inputs equal by value, which may give the same vector both
     * ways (values equal up to the sign of a zero may still be ordered). */
    if (fz_shapes_identical(&a, xa, &b, xb))
        FZ_CHECK(fz_vec_eq(mtv_ab, mtv_ba) || (mtv_ab.x == -mtv_ba.x && mtv_ab.y == -mtv_ba.y));
    else
        FZ_CHECK(mtv_ab.x == -mtv_ba.x && mtv_ab.y == -mtv_ba.y);
    if (!hit_ab) FZ_CHECK(mtv_ab.x == SX_R(0.0) && mtv_ab.y == SX_R(0.0));
    if (valid) FZ_CHECK(fz_finite_vec(mtv_ab));

    n = sx_collide_ex(&a, xa, &b, xb, margin, &m);
    col_check_manifold(&m, n, eff_margin, valid, scale);
    n0 = sx_collide(&a, xa, &b, xb, &m0);
    col_check_manifold(&m0, n0, SX_R(0.0), valid, scale);
    n0r = sx_collide(&b, xb, &a, xa, &m0r);
    col_check_manifold(&m0r, n0r, SX_R(0.0), valid, scale);
    if (valid) FZ_CHECK(n >= n0);

    if (valid && a.type == b.type) {
        FZ_CHECK((n0 > 0) == ov_ab);
        FZ_CHECK((n0r > 0) == ov_ab);
    }
    if (valid && a.type != b.type) {
        int i;
        FZ_CHECK(n0 == n0r);
        if (n0 > 0) FZ_CHECK(m0.normal.x == -m0r.normal.x && m0.normal.y == -m0r.normal.y);
        for (i = 0; i < n0 && n0 == n0r; ++i) {
            FZ_CHECK(fz_same_bits(m0.points[i].point, m0r.points[i].point));
            FZ_CHECK(m0.points[i].depth == m0r.points[i].depth);
            FZ_CHECK((m0.points[i].id ^ m0r.points[i].id) == (1u << 16));
        }
    }
    /* The deepest point against the MTV: equal up to the reference-face
     * hysteresis (0.02 x SX_LINEAR_SLOP) and rounding at this scale. */
    if (valid && hit_ab && n0 > 0) {
        sx_real d = col_max_depth(&m0), len = sx_length(mtv_ab);
        FZ_CHECK(sx_absr(d - len) <= SX_R(0.02) * SX_LINEAR_SLOP + col_round(scale));
    }

    col_check_pair_function(&a, xa, &b, xb, margin);
    col_check_pair_function(&b, xb, &a, xa, margin);
    return 0;
}
