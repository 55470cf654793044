/* sepax fuzzing — distance, shape cast and time of impact on arbitrary
 * shapes and motions.
 *
 * Two decoded shapes (valid or raw) under decoded transforms go through
 * sx_shape_distance, sx_shape_cast (a decoded translation and max fraction)
 * and sx_time_of_impact (decoded motions and target). Checked: the status is
 * a known one and a failure zeroes the output; nothing is ever NaN; a
 * distance is >= 0 and finite, with a unit normal when the shapes are
 * valid, apart and sanely placed; a cast's fraction lies in [0, max_fraction]
 * and a miss leaves the output zeroed; a time of impact's fraction lies in
 * [0, 1], 1 exactly when separated, and its state is one of the four; the
 * same call answers the same bits twice. */
#include "fuzz_input.h"

static void dst_distance(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                         bool sane) {
    sx_distance_output d, d2;
    sx_status s = sx_shape_distance(a, xa, b, xb, &d);
    FZ_CHECK(fz_status_known(s));
    FZ_CHECK(sx_shape_distance(a, xa, b, xb, &d2) == s);
    FZ_CHECK(memcmp(&d, &d2, sizeof d) == 0);
    FZ_CHECK(!fz_is_nan(d.distance) && !fz_is_nan(d.normal.x) && !fz_is_nan(d.normal.y));
    FZ_CHECK(!fz_is_nan(d.point_a.x) && !fz_is_nan(d.point_a.y));
    FZ_CHECK(!fz_is_nan(d.point_b.x) && !fz_is_nan(d.point_b.y));
    if (s != SX_OK) {
        FZ_CHECK(d.distance == SX_R(0.0) && !d.overlap && d.iterations == 0);
        return;
    }
    FZ_CHECK(d.distance >= SX_R(0.0));
    FZ_CHECK(d.iterations >= 1 && d.iterations <= SX_GJK_MAX_ITERATIONS);
    if (sane && d.distance > SX_R(0.0) && sx_is_finite(d.distance)) {
        FZ_CHECK(fz_is_unit(d.normal));
        FZ_CHECK(!d.overlap);
    }
}

static void dst_cast(const sx_shape *a, sx_xform xa, sx_vec2 tr, sx_real max_fraction,
                     const sx_shape *b, sx_xform xb, bool sane) {
    sx_shape_cast_output o;
    sx_status s = sx_shape_cast(a, xa, tr, max_fraction, b, xb, &o);
    FZ_CHECK(fz_status_known(s));
    FZ_CHECK(!fz_is_nan(o.fraction) && !fz_is_nan(o.normal.x) && !fz_is_nan(o.normal.y));
    FZ_CHECK(!fz_is_nan(o.point.x) && !fz_is_nan(o.point.y));
    FZ_CHECK(o.iterations >= 0 && o.iterations <= SX_TOI_MAX_ITERATIONS);
    if (s != SX_OK || !o.hit) {
        FZ_CHECK(o.fraction == SX_R(0.0) && !o.hit);
        FZ_CHECK(o.normal.x == SX_R(0.0) && o.normal.y == SX_R(0.0));
        return;
    }
    FZ_CHECK(o.fraction >= SX_R(0.0) && o.fraction <= max_fraction);
    if (sane && fz_finite_vec(o.point) && sx_length(o.normal) > SX_R(0.0)) {
        FZ_CHECK(fz_is_unit(o.normal));
    }
}

static void dst_toi(const sx_shape *a, const sx_motion *ma, const sx_shape *b, const sx_motion *mb,
                    sx_real target) {
    sx_toi_output o;
    sx_status s = sx_time_of_impact(a, ma, b, mb, target, &o);
    FZ_CHECK(fz_status_known(s));
    FZ_CHECK(!fz_is_nan(o.fraction) && !fz_is_nan(o.normal.x) && !fz_is_nan(o.normal.y));
    FZ_CHECK(!fz_is_nan(o.point_a.x) && !fz_is_nan(o.point_a.y));
    FZ_CHECK(!fz_is_nan(o.point_b.x) && !fz_is_nan(o.point_b.y));
    FZ_CHECK(o.iterations >= 0 && o.iterations <= SX_TOI_MAX_ITERATIONS);
    if (s != SX_OK) {
        FZ_CHECK(o.fraction == SX_R(0.0) && o.state == SX_TOI_SEPARATED);
        return;
    }
    FZ_CHECK((unsigned)o.state <= (unsigned)SX_TOI_ITERATION_LIMIT);
    FZ_CHECK(o.fraction >= SX_R(0.0) && o.fraction <= SX_R(1.0));
    if (o.state == SX_TOI_SEPARATED) FZ_CHECK(o.fraction == SX_R(1.0));
    if (o.state == SX_TOI_STARTS_CLOSE) FZ_CHECK(o.fraction == SX_R(0.0));
}

static sx_motion dst_motion(fz_reader *r) {
    sx_motion m;
    m.local_center = fz_vec2(r);
    m.c0 = fz_vec2(r);
    m.c1 = fz_u8(r) % 2u ? sx_add(m.c0, fz_vec2(r)) : fz_vec2(r);
    m.angle0 = fz_real(r);
    m.angle1 = fz_u8(r) % 2u ? m.angle0 + fz_real(r) : fz_real(r);
    return m;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_reader r = fz_reader_make(data, size);
    sx_shape a = fz_shape(&r), b = fz_shape(&r);
    bool sane_a, sane_b;
    sx_xform xa = fz_xform(&r, &sane_a), xb = fz_xform(&r, &sane_b);
    sx_real scale = sx_maxr(sx_maxr(fz_shape_extent(&a), fz_shape_extent(&b)),
                            sx_maxr(fz_extent(&xa.p, 1), fz_extent(&xb.p, 1)));
    bool sane = sane_a && sane_b && sx_shape_validate(&a) == SX_OK &&
                sx_shape_validate(&b) == SX_OK && scale <= SX_HUGE;
    sx_vec2 tr = fz_u8(&r) % 2u ? sx_sub(xb.p, xa.p) : fz_vec2(&r);
    sx_real max_fraction = fz_u8(&r) % 2u ? SX_R(1.0) : fz_real(&r);
    sx_motion ma = dst_motion(&r), mb = dst_motion(&r);
    sx_real target = fz_u8(&r) % 2u ? SX_LINEAR_SLOP : fz_real(&r);
    dst_distance(&a, xa, &b, xb, sane);
    dst_cast(&a, xa, tr, max_fraction, &b, xb, sane && fz_extent(&tr, 1) <= SX_HUGE);
    dst_toi(&a, &ma, &b, &mb, target);
    return 0;
}
