/* sepax fuzzing — point, segment and ray queries on arbitrary shapes.
 *
 * A decoded shape (valid or raw) under a decoded transform is asked
 * sx_contains_point, sx_closest_point, sx_shape_distance_to_point and
 * sx_ray_cast for decoded points and rays, and decoded segment pairs go
 * through sx_intersect_segments and sx_closest_point_on_segment. Checked:
 * nothing is ever NaN, and valid input in the promised range gives finite
 * answers; a ray hit has its fraction in [0, max_fraction], a unit normal
 * and a finite point, a miss zeroes the output; the signed distance agrees
 * with containment outside the boundary band and with the closest point's
 * distance, is never negative for segments and points, and unusable input
 * gets SX_REAL_MAX with zero vectors; segment intersections report
 * parameters in [0, 1] and zero fields for the relations without a point,
 * DEGENERATE for non-finite input; end-point parameters return the end
 * points exactly. */
#include "fuzz_input.h"

/* Rounding allowance at coordinate magnitude `scale`. */
static sx_real qry_round(sx_real scale) {
    return SX_R(256.0) * SX_REAL_EPSILON * sx_maxr(scale, SX_R(1.0));
}

static bool qry_is_zero(sx_vec2 v) { return v.x == SX_R(0.0) && v.y == SX_R(0.0); }

/* unit_rot: the shape validates and the transform's rotation came from a
 * finite angle; a raw non-unit rotation or a garbage polygon is outside the
 * contract and only has to avoid NaN. */
static void qry_ray(const sx_shape *s, sx_xform x, const sx_ray_input *ray, bool unit_rot) {
    sx_ray_hit h;
    bool hit;
    memset(&h, 0x5A, sizeof h);
    hit = sx_ray_cast(s, x, ray, &h);
    FZ_CHECK(hit == h.hit);
    if (hit) {
        FZ_CHECK(h.fraction >= SX_R(0.0) && h.fraction <= ray->max_fraction);
        FZ_CHECK(!fz_is_nan(h.normal.x) && !fz_is_nan(h.normal.y));
        if (unit_rot) FZ_CHECK(fz_is_unit(h.normal));
        FZ_CHECK(fz_finite_vec(h.point));
    } else {
        FZ_CHECK(qry_is_zero(h.point) && qry_is_zero(h.normal) && h.fraction == SX_R(0.0));
    }
    if (!(ray->max_fraction >= SX_R(0.0)) || qry_is_zero(ray->translation)) FZ_CHECK(!hit);
    FZ_CHECK(sx_ray_cast(s, x, ray, NULL) == hit);
}

static void qry_point(const sx_shape *s, sx_xform x, sx_vec2 p, bool unit_rot, bool valid,
                      sx_real scale) {
    sx_vec2 bp, n, cp;
    sx_real d = sx_shape_distance_to_point(s, x, p, &bp, &n);
    bool inside = sx_contains_point(s, x, p);
    sx_real band = SX_LINEAR_SLOP * SX_R(1e-3) + qry_round(scale);
    bool no_interior = s->type == SX_SHAPE_SEGMENT ||
                       (s->type == SX_SHAPE_CIRCLE && s->u.circle.radius == SX_R(0.0));
    cp = sx_closest_point(s, x, p);
    FZ_CHECK(!fz_is_nan(d));
    FZ_CHECK(!fz_is_nan(cp.x) && !fz_is_nan(cp.y));
    FZ_CHECK(!fz_is_nan(bp.x) && !fz_is_nan(bp.y) && !fz_is_nan(n.x) && !fz_is_nan(n.y));
    if (d == SX_REAL_MAX) {
        /* Unusable input or overflow; a genuine distance may also round to
         * SX_REAL_MAX, with a real answer. */
        FZ_CHECK((qry_is_zero(bp) && qry_is_zero(n)) || !valid);
        return;
    }
    FZ_CHECK(sx_is_finite(d) && fz_finite_vec(bp));
    if (unit_rot) FZ_CHECK(fz_is_unit(n));
    if (no_interior) FZ_CHECK(d >= SX_R(0.0));
    if (!valid) return;
    if (d < -band) FZ_CHECK(inside);
    if (d > band) FZ_CHECK(!inside);
    FZ_CHECK(fz_finite_vec(cp));
    if (d < SX_R(0.0)) FZ_CHECK(fz_same_bits(cp, p));
    if (d > SX_R(0.0)) FZ_CHECK(sx_absr(sx_distance(cp, p) - d) <= qry_round(scale + d));
    /* p = boundary_point + d * normal, up to rounding. */
    FZ_CHECK(sx_distance(sx_mul_add(bp, d, n), p) <= qry_round(scale + sx_absr(d)));
}

static void qry_segments(sx_vec2 p1, sx_vec2 p2, sx_vec2 q1, sx_vec2 q2) {
    sx_segment_intersection out;
    sx_segment_relation rel = sx_intersect_segments(p1, p2, q1, q2, &out);
    sx_vec2 pts[4];
    bool finite;
    sx_real t;
    sx_vec2 c;
    pts[0] = p1;
    pts[1] = p2;
    pts[2] = q1;
    pts[3] = q2;
    finite = fz_all_finite(pts, 4);
    FZ_CHECK((unsigned)rel <= (unsigned)SX_SEGMENTS_DEGENERATE);
    FZ_CHECK(rel == out.relation);
    FZ_CHECK(sx_intersect_segments(p1, p2, q1, q2, NULL) == rel);
    if (!finite) FZ_CHECK(rel == SX_SEGMENTS_DEGENERATE);
    if (rel == SX_SEGMENTS_INTERSECT || rel == SX_SEGMENTS_OVERLAP) {
        FZ_CHECK(out.t >= SX_R(0.0) && out.t <= SX_R(1.0));
        FZ_CHECK(out.u >= SX_R(0.0) && out.u <= SX_R(1.0));
        FZ_CHECK(fz_finite_vec(out.point));
        FZ_CHECK(fz_finite_vec(out.overlap_start) && fz_finite_vec(out.overlap_end));
        if (rel == SX_SEGMENTS_INTERSECT) {
            FZ_CHECK(fz_same_bits(out.overlap_start, out.point));
            FZ_CHECK(fz_same_bits(out.overlap_end, out.point));
        }
    } else {
        FZ_CHECK(qry_is_zero(out.point) && out.t == SX_R(0.0) && out.u == SX_R(0.0));
        FZ_CHECK(qry_is_zero(out.overlap_start) && qry_is_zero(out.overlap_end));
    }

    c = sx_closest_point_on_segment(p1, p2, q1, &t);
    FZ_CHECK(!fz_is_nan(c.x) && !fz_is_nan(c.y) && !fz_is_nan(t));
    FZ_CHECK(t >= SX_R(0.0) && t <= SX_R(1.0));
    if (t == SX_R(0.0)) FZ_CHECK(fz_same_bits(c, p1) || !fz_finite_vec(p1));
    if (t == SX_R(1.0)) FZ_CHECK(fz_same_bits(c, p2));
    if (finite && fz_extent(pts, 3) <= SX_HUGE) FZ_CHECK(fz_finite_vec(c));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_reader r = fz_reader_make(data, size);
    sx_shape s = fz_shape(&r);
    bool sane;
    sx_xform x = fz_xform(&r, &sane);
    sx_real scale = sx_maxr(fz_shape_extent(&s), fz_extent(&x.p, 1));
    /* A polygon with garbage fields may carry zero "normals": unit normals
     * are only demanded of shapes that validate. */
    bool shape_ok = sx_shape_validate(&s) == SX_OK;
    bool valid = shape_ok && sane && scale <= SX_HUGE;
    int k, rounds = 1 + (int)(fz_u8(&r) % 4u);

    for (k = 0; k < rounds; ++k) {
        sx_vec2 p = fz_vec2(&r);
        sx_ray_input ray;
        bool p_ok = fz_finite_vec(p) && fz_extent(&p, 1) <= SX_HUGE;
        qry_point(&s, x, p, sane && shape_ok, valid && p_ok, sx_maxr(scale, fz_extent(&p, 1)));
        ray.origin = fz_u8(&r) % 2u ? p : fz_vec2(&r);
        ray.translation = fz_vec2(&r);
        ray.max_fraction = fz_u8(&r) % 2u ? SX_R(1.0) : fz_real(&r);
        qry_ray(&s, x, &ray, sane && shape_ok);
    }
    {
        sx_vec2 p1 = fz_vec2(&r), p2 = fz_vec2(&r), q1 = fz_vec2(&r), q2;
        q2 = fz_u8(&r) % 3u == 0u ? sx_add(q1, sx_sub(p2, p1)) : fz_vec2(&r); /* parallel */
        qry_segments(p1, p2, q1, q2);
    }
    return 0;
}
