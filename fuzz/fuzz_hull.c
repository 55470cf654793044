/* sepax fuzzing — polygon building from arbitrary point clouds.
 *
 * Feeds decoded clouds (NaN, infinities, huge and tiny values, duplicates,
 * near-duplicates, collinear runs) to sx_compute_hull, sx_polygon_shape(_ex)
 * and sx_polygon_from_hull, and raw shape values to sx_shape_validate and
 * the mass/area/AABB functions. Checked: every status is a known one and
 * bad input gets the documented status; on success the hull validates, its
 * points are input points, every input point lies inside it within the
 * documented tolerance, and every built polygon passes sx_shape_validate
 * with finite, non-negative area and mass; on failure the output is left as
 * documented; a shape that validates gives finite area, mass and inertia at
 * density 1 whatever its size, and finite bounds within SX_HUGE. */
#include "fuzz_input.h"

/* Slack for "every input point inside the hull": the documented 2 x weld
 * tolerance for curved runs, plus the rounding of the edge test at the
 * cloud's magnitude. */
static sx_real hull_slack(sx_real tol, sx_real extent) {
    return SX_R(2.0) * tol + SX_R(64.0) * SX_REAL_EPSILON * sx_maxr(extent, SX_R(1.0));
}

static void hull_check_contains(const sx_hull *h, const sx_vec2 *pts, int count, sx_real tol) {
    sx_real slack = hull_slack(tol, fz_extent(pts, count));
    int i, j;
    for (i = 0; i < count; ++i) {
        for (j = 0; j < h->count; ++j) {
            sx_vec2 a = h->points[j], b = h->points[j + 1 < h->count ? j + 1 : 0];
            sx_vec2 e = sx_sub(b, a);
            sx_real len = sx_length(e);
            /* Distance of the point outside edge a-b (positive outside for CCW). */
            sx_real out = -sx_cross(e, sx_sub(pts[i], a)) / len;
            if (!(len > SX_R(0.0)) || !sx_is_finite(out)) continue;
            FZ_CHECK(out <= slack);
        }
    }
}

static void hull_check_points_are_input(const sx_hull *h, const sx_vec2 *pts, int count) {
    int i, j;
    for (j = 0; j < h->count; ++j) {
        bool found = false;
        for (i = 0; i < count && !found; ++i)
            found = fz_same_bits(h->points[j], pts[i]);
        FZ_CHECK(found);
    }
}

/* A built polygon: valid, with non-negative area, and finite area, mass and
 * inertia at density 1 at any size (validation refuses a shape whose mass
 * properties overflow); its other properties finite when it lies within the
 * promised range (SX_HUGE), never NaN beyond it. */
static void hull_check_valid_shape(const sx_shape *s) {
    sx_mass_data md;
    sx_real area;
    sx_aabb box;
    FZ_CHECK(sx_shape_validate(s) == SX_OK);
    area = sx_shape_area(s);
    md = sx_shape_mass(s, SX_R(1.0));
    box = sx_shape_aabb(s, sx_xform_identity());
    /* Not > 0: a valid triangle of 1e-25 m sides has an area that underflows. */
    FZ_CHECK(area >= SX_R(0.0));
    FZ_CHECK(md.mass >= SX_R(0.0) && md.rotational_inertia >= SX_R(0.0));
    FZ_CHECK(sx_is_finite(area));
    FZ_CHECK(sx_is_finite(md.mass) && sx_is_finite(md.rotational_inertia));
    FZ_CHECK(!fz_aabb_has_nan(box));
    if (fz_shape_extent(s) <= SX_HUGE) {
        FZ_CHECK(fz_finite_vec(sx_shape_centroid(s)));
        FZ_CHECK(fz_finite_vec(md.center));
        FZ_CHECK(sx_aabb_is_valid(box));
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_reader r = fz_reader_make(data, size);
    sx_vec2 pts[FZ_MAX_POINTS] = {{SX_R(0.0), SX_R(0.0)}};
    int count = fz_points(&r, pts, FZ_MAX_POINTS);
    sx_real tol = fz_u8(&r) % 2u ? fz_real(&r) : SX_WELD_TOLERANCE;
    sx_real radius = fz_u8(&r) % 2u ? fz_real(&r) : SX_R(0.0);
    bool finite = fz_all_finite(pts, count);
    sx_hull hull;
    sx_shape shape, before;
    sx_status st;

    /* The hull. */
    st = sx_compute_hull(pts, count, tol, &hull);
    FZ_CHECK(fz_status_known(st));
    if (!(tol >= SX_R(0.0)) || !sx_is_finite(tol)) {
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    } else if (!finite) {
        /* Which of two applicable errors comes first is not documented. */
        FZ_CHECK(st == SX_ERR_NONFINITE || (count < 3 && st == SX_ERR_DEGENERATE));
    } else if (count < 3) {
        FZ_CHECK(st == SX_ERR_DEGENERATE);
    }
    if (st == SX_OK) {
        FZ_CHECK(hull.count >= 3 && hull.count <= SX_MAX_POLYGON_VERTICES);
        FZ_CHECK(sx_validate_hull(&hull, tol));
        hull_check_points_are_input(&hull, pts, count);
        hull_check_contains(&hull, pts, count, tol);
    } else {
        FZ_CHECK(hull.count == 0);
    }
    FZ_CHECK(sx_compute_hull(NULL, count, tol, &hull) == SX_ERR_INVALID_ARG);
    FZ_CHECK(sx_compute_hull(pts, -1 - count, tol, &hull) == SX_ERR_INVALID_ARG);

    /* The polygon builders: a valid shape, or the documented status with the
     * output untouched. */
    memset(&before, 0xA5, sizeof before);
    shape = before;
    st = sx_polygon_shape_ex(pts, count, radius, tol, &shape);
    FZ_CHECK(fz_status_known(st));
    if (st == SX_OK) {
        hull_check_valid_shape(&shape);
        FZ_CHECK(shape.u.polygon.radius == radius);
    } else {
        FZ_CHECK(memcmp(&shape, &before, sizeof shape) == 0);
    }
    if (radius < SX_R(0.0) || !sx_is_finite(radius)) FZ_CHECK(st != SX_OK);
    if (sx_is_finite(radius) && radius >= SX_R(0.0) && sx_is_finite(tol) && tol >= SX_R(0.0)) {
        if (!finite) FZ_CHECK(st == SX_ERR_NONFINITE || (count < 3 && st == SX_ERR_DEGENERATE));
        if (finite && count < 3) FZ_CHECK(st == SX_ERR_DEGENERATE);
    }

    shape = before;
    st = sx_polygon_shape(pts, count, SX_R(0.0), &shape);
    FZ_CHECK(fz_status_known(st));
    if (st == SX_OK)
        hull_check_valid_shape(&shape);
    else
        FZ_CHECK(memcmp(&shape, &before, sizeof shape) == 0);

    /* sx_polygon_from_hull on a raw hull: the cloud's first points taken as
     * they are (usually not convex), whatever the hull builder said. */
    {
        sx_hull raw;
        int i;
        raw.count = count <= SX_MAX_POLYGON_VERTICES ? count : (int)(fz_u8(&r) % 12u) - 2;
        for (i = 0; i < SX_MAX_POLYGON_VERTICES; ++i)
            raw.points[i] = pts[i % (count > 0 ? count : 1)];
        shape = before;
        st = sx_polygon_from_hull(&raw, radius, &shape);
        FZ_CHECK(fz_status_known(st));
        if (st == SX_OK)
            hull_check_valid_shape(&shape);
        else
            FZ_CHECK(memcmp(&shape, &before, sizeof shape) == 0);
        FZ_CHECK(sx_polygon_from_hull(NULL, radius, &shape) == SX_ERR_INVALID_ARG);
    }

    /* Any shape value: validate never crashes, and a valid shape has finite
     * properties under a sane transform. */
    {
        sx_shape s = fz_shape(&r);
        bool sane;
        sx_xform x = fz_xform(&r, &sane);
        sx_real density = fz_real(&r);
        sx_mass_data md = sx_shape_mass(&s, density);
        sx_aabb box = sx_shape_aabb(&s, x);
        sx_real support = sx_shape_support(&s, fz_vec2(&r));
        st = sx_shape_validate(&s);
        FZ_CHECK(fz_status_known(st));
        bool in_range = fz_shape_extent(&s) <= SX_HUGE;
        FZ_CHECK(!fz_aabb_has_nan(box));
        FZ_CHECK(!fz_is_nan(support));
        FZ_CHECK(!fz_is_nan(md.mass) && !fz_is_nan(md.rotational_inertia));
        FZ_CHECK(!fz_is_nan(md.center.x) && !fz_is_nan(md.center.y));
        FZ_CHECK(!fz_is_nan(sx_shape_area(&s)));
        if (in_range) {
            /* Mass scales with density; past 1e3 kg/m^2 a huge shape may
             * legitimately overflow. */
            if (sx_absr(density) <= SX_R(1e3))
                FZ_CHECK(sx_is_finite(md.mass) && sx_is_finite(md.rotational_inertia));
            FZ_CHECK(fz_finite_vec(md.center));
            FZ_CHECK(sx_is_finite(sx_shape_area(&s)) && fz_finite_vec(sx_shape_centroid(&s)));
        }
        if (st == SX_OK && sane && in_range && fz_extent(&x.p, 1) <= SX_HUGE) {
            FZ_CHECK(sx_aabb_is_valid(box));
        }
        if (st != SX_OK) {
            FZ_CHECK(sx_shape_area(&s) == SX_R(0.0));
            FZ_CHECK(md.mass == SX_R(0.0) && md.rotational_inertia == SX_R(0.0));
        }
        if (st == SX_OK && sx_is_finite(density) && density >= SX_R(0.0)) {
            FZ_CHECK(md.mass >= SX_R(0.0) && md.rotational_inertia >= SX_R(0.0));
        }
        if (st == SX_OK) {
            /* at density 1, finite at any size: validation refuses the rest */
            sx_mass_data unit = sx_shape_mass(&s, SX_R(1.0));
            FZ_CHECK(sx_is_finite(unit.mass) && sx_is_finite(unit.rotational_inertia));
            FZ_CHECK(sx_is_finite(sx_shape_area(&s)));
        }
    }
    return 0;
}
