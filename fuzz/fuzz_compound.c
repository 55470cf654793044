/* sepax fuzzing — concave decomposition and compound colliders.
 *
 * Decoded outlines (arbitrary point lists, and star-shaped outlines, which
 * are simple, in both windings, with hostile values mixed in) go through
 * sx_decompose_polygon(_ex) with fuzzed weld tolerance, scratch size and part
 * capacity; the parts (or decoded shapes at decoded offsets) then form a
 * compound that is validated, bounded, weighed, and tested against a decoded
 * shape and a second compound for overlap, whole-compound MTV, manifolds,
 * ray casts and point containment. Checked: statuses as documented (bad
 * argument, short scratch, non-finite points, capacity with the needed part
 * count reported); every part passes sx_shape_validate and the part areas
 * sum to the outline's area within the cleaning's documented allowance;
 * compound answers never NaN, finite for valid input; the compound overlap
 * is the union of its parts' overlaps; the MTV's bool equals the overlap and
 * after moving by it no part pair penetrates by more than the documented
 * SX_LINEAR_SLOP x 1e-3; manifolds and ray hits are well formed with part
 * indices in range; containment agrees with the parts. */
#include "fuzz_input.h"

#define CMP_MAX_PARTS FZ_MAX_POINTS
#define CMP_SCRATCH_BYTES 16384

static sx_real cmp_round(sx_real scale) {
    return SX_R(1024.0) * SX_REAL_EPSILON * sx_maxr(scale, SX_R(1.0));
}

/* An outline: arbitrary points, or a star-shaped (hence simple) outline
 * whose radii come from the bytes, sometimes clockwise. */
static int cmp_outline(fz_reader *r, sx_vec2 *pts) {
    uint8_t mode = fz_u8(r);
    int count, i;
    if (mode % 3u == 0u) return fz_points(r, pts, FZ_MAX_POINTS);
    count = 3 + (int)(fz_u8(r) % (FZ_MAX_POINTS - 2));
    {
        sx_vec2 c = fz_u8(r) % 4u == 0u ? fz_vec2(r) : sx_v2_zero();
        sx_real unit = fz_u8(r) % 4u == 0u ? sx_absr(fz_real(r)) : SX_R(1.0);
        for (i = 0; i < count; ++i) {
            int k = mode % 3u == 1u ? i : count - 1 - i;
            sx_real a = SX_R(2.0) * SX_PI * (sx_real)k / (sx_real)count;
            sx_real rad = unit * (SX_R(0.25) + (sx_real)fz_u8(r) / SX_R(64.0));
            pts[i] = sx_add(c, sx_v2(rad * sx_cos(a), rad * sx_sin(a)));
            if (fz_u8(r) % 16u == 0u) pts[i] = fz_vec2(r);
        }
    }
    return count;
}

static sx_real cmp_signed_area(const sx_vec2 *p, int n, sx_real *perimeter) {
    double a = 0.0, per = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        sx_vec2 u = p[i], v = p[i + 1 < n ? i + 1 : 0];
        a += (double)u.x * (double)v.y - (double)u.y * (double)v.x;
        per += (double)sx_distance(u, v);
    }
    *perimeter = (sx_real)per;
    return (sx_real)(0.5 * a);
}

/* Decomposes the outline and checks the result; returns the part count (0
 * unless SX_OK). */
static int cmp_decompose(fz_reader *r, const sx_vec2 *pts, int count, sx_shape *parts) {
    static unsigned char scratch[CMP_SCRATCH_BYTES];
    size_t need = sx_decompose_scratch_bytes(count), have;
    int capacity = 1 + (int)(fz_u8(r) % CMP_MAX_PARTS), part_count = -7, tri = -7, i;
    uint8_t mode = fz_u8(r);
    sx_real tol = mode % 4u == 1u ? fz_real(r) : SX_WELD_TOLERANCE;
    bool short_scratch = mode % 8u == 2u && need > 0;
    sx_status st;
    FZ_CHECK(need <= sizeof scratch);
    have = short_scratch ? need - 1 : sizeof scratch;
    if (mode % 4u == 1u)
        st = sx_decompose_polygon_ex(pts, count, tol, scratch, have, parts, capacity, &part_count,
                                     &tri);
    else
        st = sx_decompose_polygon(pts, count, scratch, have, parts, capacity, &part_count, &tri);
    FZ_CHECK(fz_status_known(st));
    if (count < 3)
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else if (short_scratch)
        FZ_CHECK(st == SX_ERR_CAPACITY);
    else if (!(tol >= SX_R(0.0)) || !sx_is_finite(tol))
        FZ_CHECK(st == SX_ERR_INVALID_ARG || st == SX_ERR_NONFINITE);
    else if (!fz_all_finite(pts, count))
        FZ_CHECK(st == SX_ERR_NONFINITE);
    if (st == SX_ERR_CAPACITY && !short_scratch) {
        FZ_CHECK(part_count > capacity);
        return 0;
    }
    if (st != SX_OK) {
        FZ_CHECK(part_count == 0);
        return 0;
    }
    FZ_CHECK(part_count >= 1 && part_count <= capacity && part_count <= count - 2);
    FZ_CHECK(tri >= part_count && tri <= count - 2);
    {
        double sum = 0.0;
        sx_real perimeter, area = sx_absr(cmp_signed_area(pts, count, &perimeter));
        sx_real scale = fz_extent(pts, count), allowance;
        for (i = 0; i < part_count; ++i) {
            FZ_CHECK(parts[i].type == SX_SHAPE_POLYGON);
            FZ_CHECK(sx_shape_validate(&parts[i]) == SX_OK);
            FZ_CHECK(parts[i].u.polygon.radius == SX_R(0.0));
            sum += (double)sx_shape_area(&parts[i]);
        }
        /* Cleaning moves the boundary by at most the weld tolerance (twice,
         * for repeated drops); the rest is rounding of areas at this scale. */
        allowance = SX_R(2.0) * perimeter * tol + SX_R(1e-4) * area +
                    SX_R(64.0) * (sx_real)count * SX_REAL_EPSILON * scale * scale;
        if (scale <= SX_HUGE) FZ_CHECK(sx_absr((sx_real)sum - area) <= allowance);
    }
    {
        sx_vec2 p = fz_vec2(r);
        (void)sx_point_in_outline(pts, count, p);
        FZ_CHECK(!sx_point_in_outline(NULL, count, p));
    }
    return part_count;
}

/* After moving a by mtv, no part pair penetrates by more than the guarantee. */
static void cmp_check_cleared(const sx_compound *a, sx_xform xa, const sx_compound *b, sx_xform xb,
                              sx_vec2 mtv, sx_real scale) {
    int i, j;
    xa.p = sx_add(xa.p, mtv);
    for (i = 0; i < a->count; ++i) {
        sx_xform pa = sx_compound_part_placement(xa, &a->parts[i]);
        for (j = 0; j < b->count; ++j) {
            sx_xform pb = sx_compound_part_placement(xb, &b->parts[j]);
            sx_vec2 v;
            sx_mtv(&a->parts[i].shape, pa, &b->parts[j].shape, pb, &v);
            FZ_CHECK(sx_length(v) <=
                     SX_LINEAR_SLOP * SX_R(1e-3) + cmp_round(scale + sx_length(mtv)));
        }
    }
}

static void cmp_check_manifolds(const sx_compound_manifold *m, int n, int capacity, int parts_a,
                                int parts_b, bool valid) {
    int i, k;
    FZ_CHECK(n >= 0 && n <= capacity);
    for (i = 0; i < n; ++i) {
        FZ_CHECK(m[i].part_a >= 0 && m[i].part_a < parts_a);
        FZ_CHECK(m[i].part_b >= 0 && m[i].part_b < parts_b);
        FZ_CHECK(m[i].manifold.count >= 1 && m[i].manifold.count <= 2);
        FZ_CHECK(!fz_is_nan(m[i].manifold.normal.x) && !fz_is_nan(m[i].manifold.normal.y));
        if (valid) FZ_CHECK(fz_is_unit(m[i].manifold.normal));
        for (k = 0; k < m[i].manifold.count; ++k) {
            FZ_CHECK(!fz_is_nan(m[i].manifold.points[k].depth));
            if (valid) FZ_CHECK(sx_is_finite(m[i].manifold.points[k].depth));
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_reader r = fz_reader_make(data, size);
    sx_vec2 pts[FZ_MAX_POINTS];
    sx_shape parts[CMP_MAX_PARTS];
    sx_compound_part cparts[CMP_MAX_PARTS], bparts[4];
    sx_compound ca, cb;
    sx_shape b;
    sx_xform xa, xb;
    bool sane_a, sane_b, valid, valid_b, overlap, hit;
    sx_real scale;
    sx_vec2 mtv;
    int count = cmp_outline(&r, pts), n, i;

    n = cmp_decompose(&r, pts, count, parts);

    /* Compound a: the decomposition's parts, or decoded shapes at decoded
     * offsets (raw ones included). */
    if (n > 0 && fz_u8(&r) % 2u) {
        for (i = 0; i < n; ++i)
            cparts[i] = sx_compound_part_make(parts[i], sx_xform_identity());
    } else {
        bool sane;
        n = 1 + (int)(fz_u8(&r) % 3u);
        for (i = 0; i < n; ++i) {
            sx_shape s = fz_shape(&r);
            cparts[i] = sx_compound_part_make(s, fz_xform(&r, &sane));
        }
    }
    ca.parts = cparts;
    ca.count = n;
    b = fz_shape(&r);
    xa = fz_xform(&r, &sane_a);
    xb = fz_xform(&r, &sane_b);
    scale = sx_maxr(fz_extent(&xa.p, 1), fz_extent(&xb.p, 1));
    scale = sx_maxr(scale, fz_shape_extent(&b));
    for (i = 0; i < n; ++i)
        scale = sx_maxr(
            scale, sx_maxr(fz_shape_extent(&cparts[i].shape), fz_extent(&cparts[i].offset.p, 1)));
    FZ_CHECK(fz_status_known(sx_compound_validate(&ca)));
    FZ_CHECK(sx_compound_validate(NULL) == SX_ERR_INVALID_ARG);
    valid = sx_compound_validate(&ca) == SX_OK && sx_shape_validate(&b) == SX_OK && sane_a &&
            sane_b && scale <= SX_HUGE;
    for (i = 0; i < n && valid; ++i) {
        /* Offsets from a finite angle only: a raw rotation that passes the
         * 1e-3 unit check is still an unusual placement, but finite. */
        valid = sx_xform_is_finite(cparts[i].offset);
    }

    {
        sx_aabb box = sx_compound_aabb(&ca, xa);
        sx_mass_data md = sx_compound_mass(&ca, SX_R(1.0));
        FZ_CHECK(!fz_aabb_has_nan(box));
        FZ_CHECK(!fz_is_nan(md.mass) && !fz_is_nan(md.rotational_inertia));
        FZ_CHECK(!fz_is_nan(md.center.x) && !fz_is_nan(md.center.y));
        if (valid) {
            FZ_CHECK(sx_aabb_is_valid(box));
            FZ_CHECK(sx_is_finite(md.mass) && md.mass >= SX_R(0.0));
            FZ_CHECK(fz_finite_vec(md.center));
        }
    }

    /* Compound against a shape. */
    overlap = sx_compound_overlap(&ca, xa, &b, xb);
    if (valid) {
        bool any = false;
        for (i = 0; i < n; ++i)
            any = any || sx_overlap(&cparts[i].shape, sx_compound_part_placement(xa, &cparts[i]), &b, xb);
        FZ_CHECK(any == overlap);
    }
    hit = sx_compound_mtv(&ca, xa, &b, xb, &mtv);
    FZ_CHECK(!fz_is_nan(mtv.x) && !fz_is_nan(mtv.y));
    if (valid) {
        sx_compound_part one;
        sx_compound cone;
        FZ_CHECK(hit == overlap);
        FZ_CHECK(fz_finite_vec(mtv));
        one = sx_compound_part_make(b, sx_xform_identity());
        cone.parts = &one;
        cone.count = 1;
        cmp_check_cleared(&ca, xa, &cone, xb, mtv, scale);
    }
    {
        sx_compound_manifold m[8];
        int capacity = 1 + (int)(fz_u8(&r) % 8u);
        int k = sx_compound_collide(&ca, xa, &b, xb, fz_real(&r), m, capacity);
        cmp_check_manifolds(m, k, capacity, n, 1, valid);
    }
    {
        sx_ray_input ray;
        sx_ray_hit h;
        int part = -7;
        bool rh;
        ray.origin = fz_vec2(&r);
        ray.translation = fz_vec2(&r);
        ray.max_fraction = fz_u8(&r) % 2u ? SX_R(1.0) : fz_real(&r);
        rh = sx_compound_ray_cast(&ca, xa, &ray, &h, &part);
        if (rh) {
            FZ_CHECK(part >= 0 && part < n);
            FZ_CHECK(h.hit && h.fraction >= SX_R(0.0) && h.fraction <= ray.max_fraction);
            FZ_CHECK(!fz_is_nan(h.normal.x) && !fz_is_nan(h.normal.y));
            if (valid) FZ_CHECK(fz_is_unit(h.normal) && fz_finite_vec(h.point));
        } else {
            FZ_CHECK(part == -1);
        }
    }
    {
        sx_vec2 p = fz_vec2(&r);
        int part = -7;
        bool in = sx_compound_contains_point(&ca, xa, p, &part), any = false;
        FZ_CHECK(in ? part >= 0 && part < n : part == -1);
        for (i = 0; i < n; ++i)
            any = any || sx_contains_point(&cparts[i].shape, sx_compound_part_placement(xa, &cparts[i]), p);
        if (valid) FZ_CHECK(any == in);
    }

    /* Compound against compound: b's shape plus decoded parts. */
    {
        bool sane, ov2, hit2;
        sx_vec2 mtv2;
        sx_compound_manifold m[8];
        int nb = 1 + (int)(fz_u8(&r) % 4u), k;
        bparts[0] = sx_compound_part_make(b, sx_xform_identity());
        valid_b = valid;
        for (i = 1; i < nb; ++i) {
            sx_shape s = fz_shape(&r);
            bparts[i] = sx_compound_part_make(s, fz_xform(&r, &sane));
            valid_b = valid_b && sane && sx_shape_validate(&s) == SX_OK &&
                      fz_shape_extent(&s) <= SX_HUGE &&
                      fz_extent(&bparts[i].offset.p, 1) <= SX_HUGE;
        }
        cb.parts = bparts;
        cb.count = nb;
        ov2 = sx_compound_overlap_compound(&ca, xa, &cb, xb);
        hit2 = sx_compound_mtv_compound(&ca, xa, &cb, xb, &mtv2);
        FZ_CHECK(!fz_is_nan(mtv2.x) && !fz_is_nan(mtv2.y));
        if (valid_b) {
            FZ_CHECK(ov2 == hit2);
            FZ_CHECK(fz_finite_vec(mtv2));
            cmp_check_cleared(&ca, xa, &cb, xb, mtv2, scale * SX_R(4.0));
        }
        k = sx_compound_collide_compound(&ca, xa, &cb, xb, SX_R(0.0), m, 8);
        cmp_check_manifolds(m, k, 8, n, nb, valid_b);
    }
    return 0;
}
