/* sepax tests — concave outlines: decomposition into convex parts and
 * point-in-outline by winding number.
 *
 * Every decomposition is checked against the properties that define it
 * rather than against a fixed answer: each part is a valid convex polygon,
 * the part areas sum to the outline's area, parts do not overlap (pairwise
 * MTV zero, sampled points in exactly one part), and the parts cover exactly
 * what the winding number of the raw outline calls inside. Named outlines
 * (L, U, star, comb, spiral) in both windings also check the part count
 * against the triangle count; random simple outlines (star-shaped and
 * self-avoiding walks, fixed seeds) check the properties at scale. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

#define MAX_OUTLINE 128
#define PI_D 3.14159265358979323846

/* Relative tolerance of the area sum (the brief's 1e-5; the parts carry the
 * outline's own coordinates, so only the area sums' rounding counts). */
#define AREA_REL 1e-5
/* Overlap allowed between two parts sharing an edge, relative to the
 * outline's size: the rounding of an MTV along a shared edge. */
#ifdef SX_DOUBLE
#define OVERLAP_REL 1e-9
#else
#define OVERLAP_REL 1e-5
#endif
/* Sample points this close (relative) to any edge are not classified. */
#define BOUNDARY_REL 1e-3

typedef struct decomp {
    sx_status status;
    sx_shape parts[MAX_OUTLINE];
    int part_count, triangle_count;
} decomp;

static void run_decompose(const sx_vec2 *pts, int n, decomp *d) {
    size_t bytes = sx_decompose_scratch_bytes(n);
    void *scratch = bytes > 0 ? malloc(bytes) : NULL;
    d->status = sx_decompose_polygon(pts, n, scratch, bytes, d->parts, MAX_OUTLINE, &d->part_count,
                                     &d->triangle_count);
    free(scratch);
}

static double outline_area(const sx_vec2 *p, int n) {
    double s = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        const sx_vec2 a = p[i], b = p[(i + 1) % n];
        s += (double)a.x * (double)b.y - (double)a.y * (double)b.x;
    }
    return 0.5 * s;
}

static double seg_distance(sx_vec2 a, sx_vec2 b, double px, double py) {
    double ax = (double)a.x, ay = (double)a.y, ex = (double)b.x - ax, ey = (double)b.y - ay;
    double len2 = ex * ex + ey * ey, t = 0.0, dx, dy;
    if (len2 > 0.0) t = ((px - ax) * ex + (py - ay) * ey) / len2;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    dx = px - (ax + t * ex);
    dy = py - (ay + t * ey);
    return sqrt(dx * dx + dy * dy);
}

static void reverse(sx_vec2 *p, int n) {
    int i;
    for (i = 0; i < n / 2; ++i) {
        sx_vec2 t = p[i];
        p[i] = p[n - 1 - i];
        p[n - 1 - i] = t;
    }
}

/* Checks every defining property of a decomposition of outline p. */
static void check_decomposition(const sx_vec2 *p, int n, const decomp *d, uint64_t seed) {
    sx_aabb box = sx_aabb_from_points(p, n);
    double size = (double)sx_maxr(box.upper.x - box.lower.x, box.upper.y - box.lower.y);
    double area = fabs(outline_area(p, n)), sum = 0.0;
    sx_test_rng rng = sx_test_rng_make(seed);
    int i, j, s;
    assert_int_equal(d->status, SX_OK);
    assert_true(d->part_count >= 1);
    assert_true(d->part_count <= d->triangle_count);
    assert_true(d->triangle_count <= n - 2);
    for (i = 0; i < d->part_count; ++i) {
        assert_int_equal(sx_shape_validate(&d->parts[i]), SX_OK);
        assert_true(d->parts[i].u.polygon.count <= SX_MAX_POLYGON_VERTICES);
        sum += (double)sx_shape_area(&d->parts[i]);
    }
    assert_near(sum, area, AREA_REL * area);
    for (i = 0; i < d->part_count; ++i) {
        for (j = i + 1; j < d->part_count; ++j) {
            sx_vec2 m = sx_v2_zero();
            (void)sx_mtv(&d->parts[i], sx_xform_identity(), &d->parts[j], sx_xform_identity(), &m);
            assert_true((double)sx_length(m) <= OVERLAP_REL * size);
        }
    }
    /* Sampled points: the winding number and the parts agree, and an inside
     * point lies in exactly one part. */
    for (s = 0; s < 300; ++s) {
        sx_vec2 q = sx_v2(sx_test_rng_range(&rng, (double)box.lower.x, (double)box.upper.x),
                          sx_test_rng_range(&rng, (double)box.lower.y, (double)box.upper.y));
        double near_edge = 1e300;
        int inside_parts = 0;
        for (i = 0; i < n; ++i) {
            double dd = seg_distance(p[i], p[(i + 1) % n], (double)q.x, (double)q.y);
            if (dd < near_edge) near_edge = dd;
        }
        for (i = 0; i < d->part_count; ++i) {
            const sx_polygon *pg = &d->parts[i].u.polygon;
            for (j = 0; j < pg->count; ++j) {
                double dd = seg_distance(pg->vertices[j], pg->vertices[(j + 1) % pg->count],
                                         (double)q.x, (double)q.y);
                if (dd < near_edge) near_edge = dd;
            }
        }
        if (near_edge < BOUNDARY_REL * size) continue;
        for (i = 0; i < d->part_count; ++i)
            if (sx_contains_point(&d->parts[i], sx_xform_identity(), q)) ++inside_parts;
        assert_int_equal(inside_parts, sx_point_in_outline(p, n, q) ? 1 : 0);
    }
}

/* ---- named outlines ------------------------------------------------------ */

static int make_l(sx_vec2 *p) {
    static const double c[] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
    int i;
    for (i = 0; i < 6; ++i)
        p[i] = sx_v2((sx_real)c[2 * i], (sx_real)c[2 * i + 1]);
    return 6;
}

static int make_u(sx_vec2 *p) {
    static const double c[] = {0, 0, 3, 0, 3, 2, 2, 2, 2, 1, 1, 1, 1, 2, 0, 2};
    int i;
    for (i = 0; i < 8; ++i)
        p[i] = sx_v2((sx_real)c[2 * i], (sx_real)c[2 * i + 1]);
    return 8;
}

static int make_star(sx_vec2 *p) {
    int i;
    for (i = 0; i < 10; ++i) {
        double a = PI_D / 2.0 + (double)i * PI_D / 5.0, r = (i % 2 == 0) ? 1.0 : 0.4;
        p[i] = sx_v2((sx_real)(r * cos(a)), (sx_real)(r * sin(a)));
    }
    return 10;
}

/* A comb: a 7 x 1 spine with four 1 x 2 teeth standing on it. */
static int make_comb(sx_vec2 *p) { return sx_test_comb_outline(p, 4); }

/* A thick Archimedean spiral strip: out along one edge, back along the
 * other, one and a half turns. */
static int make_spiral(sx_vec2 *p) {
    const int steps = 28;
    int i, n = 0;
    for (i = 0; i < steps; ++i) {
        double t = 3.0 * PI_D * (double)i / (double)(steps - 1), r = 0.6 + 0.3 * t + 0.25;
        p[n++] = sx_v2((sx_real)(r * cos(t)), (sx_real)(r * sin(t)));
    }
    for (i = steps - 1; i >= 0; --i) {
        double t = 3.0 * PI_D * (double)i / (double)(steps - 1), r = 0.6 + 0.3 * t;
        p[n++] = sx_v2((sx_real)(r * cos(t)), (sx_real)(r * sin(t)));
    }
    return n;
}

typedef int make_fn(sx_vec2 *p);

/* Decomposes an outline both ways round; returns the part count (equal for
 * both windings) and checks it against max_parts. */
static int check_named(const char *name, make_fn *make, int max_parts, uint64_t seed) {
    sx_vec2 p[MAX_OUTLINE];
    decomp d;
    int n = make(p), ccw_parts;
    run_decompose(p, n, &d);
    check_decomposition(p, n, &d, seed);
    ccw_parts = d.part_count;
    printf("  %-7s n=%3d triangles=%3d parts=%3d (n-2=%d)\n", name, n, d.triangle_count,
           d.part_count, n - 2);
    assert_int_equal(d.triangle_count, n - 2);
    assert_true(d.part_count <= max_parts);
    reverse(p, n);
    run_decompose(p, n, &d);
    check_decomposition(p, n, &d, seed + 1);
    assert_int_equal(d.triangle_count, n - 2);
    assert_true(d.part_count <= max_parts);
    return ccw_parts;
}

static void l_shape_splits_into_two_parts(void **state) {
    (void)state;
    assert_int_equal(check_named("L", make_l, 2, 11), 2);
}

static void u_shape_splits_into_at_most_four_parts(void **state) {
    (void)state;
    check_named("U", make_u, 4, 12);
}

static void star_merges_below_triangle_count(void **state) {
    (void)state;
    check_named("star", make_star, 6, 13);
}

static void comb_merges_below_triangle_count(void **state) {
    (void)state;
    check_named("comb", make_comb, 8, 14);
}

static void spiral_merges_well_below_triangle_count(void **state) {
    sx_vec2 p[MAX_OUTLINE];
    (void)state;
    /* Thin strip quads: at most about one part per two triangles. */
    check_named("spiral", make_spiral, (make_spiral(p) - 2) / 2 + 2, 15);
}

static void convex_outline_is_one_part(void **state) {
    sx_vec2 p[8];
    decomp d;
    int i;
    (void)state;
    for (i = 0; i < 8; ++i) {
        double a = 2.0 * PI_D * (double)i / 8.0;
        p[i] = sx_v2((sx_real)cos(a), (sx_real)sin(a));
    }
    run_decompose(p, 8, &d);
    check_decomposition(p, 8, &d, 16);
    assert_int_equal(d.part_count, 1);
    assert_int_equal(d.triangle_count, 6);
}

static void collinear_and_duplicate_points_are_cleaned_first(void **state) {
    /* The L with a duplicated corner, a point in the middle of an edge and a
     * near-duplicate (well inside the weld tolerance). */
    sx_vec2 p[9];
    decomp d;
    (void)state;
    p[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    p[1] = sx_v2(SX_R(1.0), SX_R(0.0));
    p[2] = sx_v2(SX_R(2.0), SX_R(0.0));
    p[3] = sx_v2(SX_R(2.0), SX_R(1.0));
    p[4] = sx_v2(SX_R(2.0), SX_R(1.0));
    p[5] = sx_v2(SX_R(1.0), SX_R(1.0));
    p[6] = sx_v2(SX_R(1.0) + SX_WELD_TOLERANCE * SX_R(0.1), SX_R(1.0));
    p[7] = sx_v2(SX_R(1.0), SX_R(2.0));
    p[8] = sx_v2(SX_R(0.0), SX_R(2.0));
    run_decompose(p, 9, &d);
    assert_int_equal(d.status, SX_OK);
    assert_int_equal(d.triangle_count, 4);
    assert_int_equal(d.part_count, 2);
    assert_near(sx_shape_area(&d.parts[0]) + sx_shape_area(&d.parts[1]), 3.0, 1e-5);
}

static void tiny_outline_needs_a_matching_weld_tolerance(void **state) {
    /* The L at millimetre scale: its 1 mm edges are within the default weld
     * tolerance, so corners are welded away; a micrometre tolerance keeps
     * it. */
    sx_vec2 p[6];
    sx_shape parts[8];
    unsigned char scratch[4096];
    int i, n = make_l(p), count = 0, tris = 0;
    (void)state;
    for (i = 0; i < n; ++i)
        p[i] = sx_scale(p[i], SX_R(0.001));
    assert_true(sx_decompose_scratch_bytes(n) <= sizeof scratch);
    if (sx_decompose_polygon(p, n, scratch, sizeof scratch, parts, 8, &count, &tris) == SX_OK) {
        double sum = 0.0;
        for (i = 0; i < count; ++i)
            sum += (double)sx_shape_area(&parts[i]);
        assert_true(fabs(sum - 3e-6) > 3e-7);
    }
    assert_int_equal(
        sx_decompose_polygon_ex(p, n, SX_R(1e-6), scratch, sizeof scratch, parts, 8, &count, &tris),
        SX_OK);
    assert_int_equal(count, 2);
    assert_int_equal(tris, 4);
    assert_near(sx_shape_area(&parts[0]) + sx_shape_area(&parts[1]), 3e-6, 1e-11);
    assert_int_equal(
        sx_decompose_polygon_ex(p, n, SX_R(-1.0), scratch, sizeof scratch, parts, 8, &count, &tris),
        SX_ERR_INVALID_ARG);
    assert_int_equal(sx_decompose_polygon_ex(p, n, (sx_real)NAN, scratch, sizeof scratch, parts, 8,
                                             &count, &tris),
                     SX_ERR_INVALID_ARG);
}

static void outline_far_from_origin_decomposes_like_at_origin(void **state) {
    make_fn *makers[3];
    int k;
    (void)state;
    makers[0] = make_u;
    makers[1] = make_comb;
    makers[2] = make_spiral;
    for (k = 0; k < 3; ++k) {
        sx_vec2 p[MAX_OUTLINE];
        decomp near, far;
        double sum = 0.0, area;
        int n = makers[k](p), i;
        run_decompose(p, n, &near);
        for (i = 0; i < n; ++i)
            p[i] = sx_add(p[i], sx_v2(SX_R(1000.0), SX_R(-1000.0)));
        run_decompose(p, n, &far);
        assert_int_equal(far.status, SX_OK);
        assert_int_equal(far.part_count, near.part_count);
        area = fabs(outline_area(p, n));
        for (i = 0; i < far.part_count; ++i) {
            assert_int_equal(sx_shape_validate(&far.parts[i]), SX_OK);
            sum += (double)sx_shape_area(&far.parts[i]);
        }
        assert_near(sum, area, AREA_REL * area);
    }
}

/* ---- random simple outlines ---------------------------------------------- */

/* No vertex closer than 10 weld tolerances to the line through its
 * neighbours, so cleaning keeps every point and the areas compare exactly. */
static bool well_conditioned(const sx_vec2 *p, int n) {
    int i;
    for (i = 0; i < n; ++i) {
        sx_vec2 a = p[(i + n - 1) % n], b = p[(i + 1) % n];
        double dx = (double)b.x - (double)a.x, dy = (double)b.y - (double)a.y;
        double len = sqrt(dx * dx + dy * dy);
        double dist = seg_distance(a, b, (double)p[i].x, (double)p[i].y);
        if (len == 0.0 || dist < 10.0 * (double)SX_WELD_TOLERANCE) return false;
    }
    return true;
}

static void random_star_shaped_outlines_decompose_exactly(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed01);
    int trial, done = 0, parts = 0, tris = 0;
    (void)state;
    for (trial = 0; done < 40 && trial < 400; ++trial) {
        sx_vec2 p[MAX_OUTLINE];
        double ang[MAX_OUTLINE];
        decomp d;
        int n = 5 + (int)(sx_test_rng_unit(&rng) * 40.0), i, j;
        for (i = 0; i < n; ++i)
            ang[i] = 2.0 * PI_D * sx_test_rng_unit(&rng);
        for (i = 1; i < n; ++i) /* insertion sort */
            for (j = i; j > 0 && ang[j - 1] > ang[j]; --j) {
                double t = ang[j];
                ang[j] = ang[j - 1];
                ang[j - 1] = t;
            }
        for (i = 0; i < n; ++i) {
            double r = 0.2 + 0.8 * sx_test_rng_unit(&rng);
            p[i] = sx_v2((sx_real)(r * cos(ang[i])), (sx_real)(r * sin(ang[i])));
        }
        if (!well_conditioned(p, n)) continue;
        /* Star-shaped about the origin only if no angular gap reaches pi. */
        for (i = 0; i < n; ++i) {
            double gap = (i + 1 < n ? ang[i + 1] : ang[0] + 2.0 * PI_D) - ang[i];
            if (gap >= PI_D * 0.95) break;
        }
        if (i < n) continue;
        if (done % 2 == 1) reverse(p, n);
        run_decompose(p, n, &d);
        check_decomposition(p, n, &d, 100 + (uint64_t)trial);
        parts += d.part_count;
        tris += d.triangle_count;
        ++done;
    }
    assert_int_equal(done, 40);
    printf("  random star-shaped: %d outlines, %d triangles -> %d parts\n", done, tris, parts);
    assert_true(parts < tris);
}

static double dorient(sx_vec2 a, sx_vec2 b, sx_vec2 c) {
    return ((double)b.x - (double)a.x) * ((double)c.y - (double)a.y) -
           ((double)b.y - (double)a.y) * ((double)c.x - (double)a.x);
}

static bool dsegments_meet(sx_vec2 a, sx_vec2 b, sx_vec2 c, sx_vec2 d) {
    double d1 = dorient(a, b, c), d2 = dorient(a, b, d);
    double d3 = dorient(c, d, a), d4 = dorient(c, d, b);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

/* A self-avoiding random walk of n points whose closing edge crosses
 * nothing; false when the walk gets stuck. */
static bool random_walk(sx_test_rng *rng, sx_vec2 *p, int n) {
    double heading = 0.0, x = 0.0, y = 0.0;
    int i, j, tries;
    p[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    for (i = 1; i < n; ++i) {
        for (tries = 0; tries < 60; ++tries) {
            double turn = (sx_test_rng_unit(rng) * 2.0 - 1.0) * 1.6, len;
            bool ok = true;
            sx_vec2 q;
            if (fabs(turn) < 0.05) continue;
            len = 0.3 + 0.7 * sx_test_rng_unit(rng);
            q = sx_v2((sx_real)(x + len * cos(heading + turn)),
                      (sx_real)(y + len * sin(heading + turn)));
            for (j = 0; j + 1 < i - 1 && ok; ++j)
                ok = !dsegments_meet(p[j], p[j + 1], p[i - 1], q);
            if (!ok) continue;
            heading += turn;
            x = (double)q.x;
            y = (double)q.y;
            p[i] = q;
            break;
        }
        if (tries == 60) return false;
    }
    for (j = 1; j + 1 < n - 1; ++j)
        if (dsegments_meet(p[j], p[j + 1], p[n - 1], p[0])) return false;
    return well_conditioned(p, n);
}

static void random_walk_outlines_decompose_exactly(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed02);
    int trial, done = 0, parts = 0, tris = 0;
    (void)state;
    for (trial = 0; done < 30 && trial < 3000; ++trial) {
        sx_vec2 p[MAX_OUTLINE];
        decomp d;
        int n = 6 + (int)(sx_test_rng_unit(&rng) * 30.0);
        if (!random_walk(&rng, p, n)) continue;
        run_decompose(p, n, &d);
        check_decomposition(p, n, &d, 200 + (uint64_t)trial);
        assert_int_equal(d.triangle_count, n - 2);
        parts += d.part_count;
        tris += d.triangle_count;
        ++done;
    }
    assert_int_equal(done, 30);
    printf("  random walks: %d outlines, %d triangles -> %d parts\n", done, tris, parts);
    assert_true(parts < tris);
}

/* ---- bad outlines -------------------------------------------------------- */

static sx_status status_of(const sx_vec2 *p, int n) {
    decomp d;
    run_decompose(p, n, &d);
    return d.status;
}

static void bow_tie_is_refused_as_invalid_argument(void **state) {
    sx_vec2 p[4];
    decomp d;
    (void)state;
    p[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    p[1] = sx_v2(SX_R(1.0), SX_R(1.0));
    p[2] = sx_v2(SX_R(1.0), SX_R(0.0));
    p[3] = sx_v2(SX_R(0.0), SX_R(1.0));
    run_decompose(p, 4, &d);
    assert_int_equal(d.status, SX_ERR_INVALID_ARG);
    assert_int_equal(d.part_count, 0);
    /* An asymmetric bow-tie (non-zero signed area) too. */
    p[1] = sx_v2(SX_R(2.0), SX_R(1.0));
    assert_int_equal(status_of(p, 4), SX_ERR_INVALID_ARG);
}

static void outline_touching_itself_is_refused(void **state) {
    /* Two squares sharing the corner (1, 1): a figure eight. */
    sx_vec2 p[7];
    (void)state;
    p[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    p[1] = sx_v2(SX_R(1.0), SX_R(0.0));
    p[2] = sx_v2(SX_R(1.0), SX_R(1.0));
    p[3] = sx_v2(SX_R(2.0), SX_R(1.0));
    p[4] = sx_v2(SX_R(2.0), SX_R(2.0));
    p[5] = sx_v2(SX_R(1.0), SX_R(2.0));
    p[6] = sx_v2(SX_R(1.0), SX_R(1.0));
    assert_int_equal(status_of(p, 7), SX_ERR_INVALID_ARG);
}

static void collinear_or_duplicate_outlines_are_degenerate(void **state) {
    sx_vec2 p[5];
    int i;
    (void)state;
    for (i = 0; i < 5; ++i)
        p[i] = sx_v2((sx_real)i, SX_R(2.0) * (sx_real)i);
    assert_int_equal(status_of(p, 5), SX_ERR_DEGENERATE);
    p[2] = sx_v2(SX_R(1.5), SX_R(3.0)); /* a collinear there-and-back */
    assert_int_equal(status_of(p, 5), SX_ERR_DEGENERATE);
    for (i = 0; i < 5; ++i)
        p[i] = sx_v2(SX_R(3.0), SX_R(-1.0));
    assert_int_equal(status_of(p, 5), SX_ERR_DEGENERATE);
    p[3] = sx_v2(SX_R(3.0) + SX_WELD_TOLERANCE * SX_R(0.5), SX_R(-1.0));
    assert_int_equal(status_of(p, 5), SX_ERR_DEGENERATE);
}

static void non_finite_points_are_refused(void **state) {
    sx_vec2 p[6];
    (void)state;
    make_l(p);
    p[3].x = (sx_real)NAN;
    assert_int_equal(status_of(p, 6), SX_ERR_NONFINITE);
    make_l(p);
    p[5].y = (sx_real)INFINITY;
    assert_int_equal(status_of(p, 6), SX_ERR_NONFINITE);
    make_l(p);
    p[0].y = -(sx_real)INFINITY;
    assert_int_equal(status_of(p, 6), SX_ERR_NONFINITE);
}

/* Regression (issue 28): parts whose mass properties overflow sx_real are
 * refused by sx_shape_validate, so an outline that large is refused whole
 * (SX_ERR_NONFINITE, parts untouched) instead of yielding invalid parts or
 * silently losing some; at a quarter of the scale it decomposes. */
static void an_outline_too_large_for_finite_mass_is_refused_whole(void **state) {
    const double quartic_root = pow((double)SX_REAL_MAX, 0.25);
    sx_vec2 p[6];
    decomp d, before;
    int i, n = make_l(p);
    (void)state;
    for (i = 0; i < n; ++i)
        p[i] = sx_scale(p[i], (sx_real)(2.0 * quartic_root));
    memset(&d, 0x5A, sizeof d);
    before = d;
    run_decompose(p, n, &d);
    assert_int_equal(d.status, SX_ERR_NONFINITE);
    assert_int_equal(d.part_count, 0);
    assert_true(memcmp(d.parts, before.parts, sizeof d.parts) == 0);
    for (i = 0; i < n; ++i)
        p[i] = sx_scale(p[i], SX_R(0.25));
    run_decompose(p, n, &d);
    assert_int_equal(d.status, SX_OK);
    assert_int_equal(d.part_count, 2);
    for (i = 0; i < d.part_count; ++i) {
        sx_mass_data md = sx_shape_mass(&d.parts[i], SX_R(1.0));
        assert_int_equal(sx_shape_validate(&d.parts[i]), SX_OK);
        assert_true(sx_is_finite(md.mass) && sx_is_finite(md.rotational_inertia));
    }
}

static void bad_arguments_and_capacity_are_reported(void **state) {
    sx_vec2 p[MAX_OUTLINE];
    sx_shape parts[MAX_OUTLINE];
    unsigned char small[8];
    size_t bytes;
    void *scratch;
    int n, count = -1, tris = -1;
    (void)state;
    n = make_comb(p);
    bytes = sx_decompose_scratch_bytes(n);
    assert_true(bytes > 0);
    assert_int_equal(sx_decompose_scratch_bytes(2), 0);
    /* the point limit (issue 28: past it the triangle indices overflow an
     * int): refused before any point is read or any scratch used */
    assert_true(sx_decompose_scratch_bytes(SX_DECOMPOSE_MAX_POINTS) > 0);
    assert_int_equal(sx_decompose_scratch_bytes(SX_DECOMPOSE_MAX_POINTS + 1), 0);
    assert_int_equal(sx_decompose_scratch_bytes(INT_MAX), 0);
    scratch = malloc(bytes);
    assert_int_equal(sx_decompose_polygon(p, SX_DECOMPOSE_MAX_POINTS + 1, scratch, bytes, parts,
                                          MAX_OUTLINE, &count, NULL),
                     SX_ERR_CAPACITY);
    assert_int_equal(
        sx_decompose_polygon(NULL, n, scratch, bytes, parts, MAX_OUTLINE, &count, NULL),
        SX_ERR_INVALID_ARG);
    assert_int_equal(count, 0);
    assert_int_equal(sx_decompose_polygon(p, n, scratch, bytes, NULL, MAX_OUTLINE, &count, NULL),
                     SX_ERR_INVALID_ARG);
    assert_int_equal(sx_decompose_polygon(p, n, scratch, bytes, parts, MAX_OUTLINE, NULL, NULL),
                     SX_ERR_INVALID_ARG);
    assert_int_equal(sx_decompose_polygon(p, 2, scratch, bytes, parts, MAX_OUTLINE, &count, NULL),
                     SX_ERR_INVALID_ARG);
    assert_int_equal(sx_decompose_polygon(p, -1, scratch, bytes, parts, MAX_OUTLINE, &count, NULL),
                     SX_ERR_INVALID_ARG);
    assert_int_equal(sx_decompose_polygon(p, n, NULL, bytes, parts, MAX_OUTLINE, &count, NULL),
                     SX_ERR_INVALID_ARG);
    assert_int_equal(
        sx_decompose_polygon(p, n, small, sizeof small, parts, MAX_OUTLINE, &count, NULL),
        SX_ERR_CAPACITY);
    assert_int_equal(
        sx_decompose_polygon(p, n, scratch, bytes - 1, parts, MAX_OUTLINE, &count, NULL),
        SX_ERR_CAPACITY);
    /* One part of room for a comb: refused, and told how many are needed. */
    assert_int_equal(sx_decompose_polygon(p, n, scratch, bytes, parts, 1, &count, &tris),
                     SX_ERR_CAPACITY);
    assert_true(count > 1);
    {
        int needed = count;
        assert_int_equal(sx_decompose_polygon(p, n, scratch, bytes, parts, needed, &count, &tris),
                         SX_OK);
        assert_int_equal(count, needed);
        assert_int_equal(tris, n - 2);
    }
    /* Any alignment of the scratch block works. */
    {
        unsigned char *raw = (unsigned char *)malloc(bytes + 3);
        assert_int_equal(
            sx_decompose_polygon(p, n, raw + 3, bytes, parts, MAX_OUTLINE, &count, NULL), SX_OK);
        free(raw);
    }
    free(scratch);
}

/* ---- point in outline ---------------------------------------------------- */

static void point_in_outline_follows_the_winding_number(void **state) {
    sx_vec2 p[MAX_OUTLINE];
    int n, k;
    (void)state;
    n = make_u(p);
    for (k = 0; k < 2; ++k) {
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(0.5), SX_R(1.5))));  /* left arm */
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(2.5), SX_R(1.5))));  /* right arm */
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(1.5), SX_R(0.5))));  /* base */
        assert_false(sx_point_in_outline(p, n, sx_v2(SX_R(1.5), SX_R(1.5)))); /* the notch */
        assert_false(sx_point_in_outline(p, n, sx_v2(SX_R(-0.5), SX_R(1.0))));
        assert_false(sx_point_in_outline(p, n, sx_v2(SX_R(1.5), SX_R(2.5))));
        /* On the boundary, including a vertex and the notch floor: inside. */
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(1.5), SX_R(1.0))));
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(2.0), SX_R(2.0))));
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(3.0), SX_R(0.7))));
        /* A ray through vertices (y = 1 passes the notch corners). */
        assert_true(sx_point_in_outline(p, n, sx_v2(SX_R(0.5), SX_R(1.0))));
        assert_false(sx_point_in_outline(p, n, sx_v2(SX_R(3.5), SX_R(1.0))));
        reverse(p, n);
    }
    assert_false(sx_point_in_outline(NULL, n, sx_v2(SX_R(0.5), SX_R(0.5))));
    assert_false(sx_point_in_outline(p, 2, sx_v2(SX_R(0.5), SX_R(0.5))));
    assert_false(sx_point_in_outline(p, n, sx_v2((sx_real)NAN, SX_R(0.5))));
    p[2].x = (sx_real)INFINITY;
    assert_false(sx_point_in_outline(p, n, sx_v2(SX_R(0.5), SX_R(0.5))));
}

/* Regression (make fuzz, double build, harness compound): the outline
 * 0 -> (3.25, -0.0128) -> ~0 -> ~0 -> (12.375, 12.375) -> (-320000, 9.375)
 * has a zero-width spike out to (3.25, -0.0128) whose two sides return to
 * points 1e-117 apart. Cleaning measured the tip against the line through
 * those two neighbours, a line with no meaningful direction, kept the spike,
 * and the parts summed to 2032 m^2 more than the outline. */
static void a_spike_whose_base_is_below_the_tolerance_is_dropped(void **state) {
#ifdef SX_DOUBLE
    const double t1 = 1.1725540106149904e-117, t2 = 4.1955458189010595e-110;
#else
    const double t1 = 1.17e-20, t2 = 4.2e-20;
#endif
    const double xy[] = {0,          0,   0,   0,      3.25,   -0.0128, -t1,
                         -t1 * 1e-3, -t2, -t2, 12.375, 12.375, -320000, 9.375};
    sx_vec2 p[7];
    decomp d;
    double sum = 0.0, area;
    int i;
    (void)state;
    for (i = 0; i < 7; ++i)
        p[i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
    area = fabs(outline_area(p, 7));
    run_decompose(p, 7, &d);
    assert_int_equal(d.status, SX_OK);
    for (i = 0; i < d.part_count; ++i)
        sum += (double)sx_shape_area(&d.parts[i]);
    /* The spike has no area: the parts are the triangle 0, B, C. */
    assert_int_equal(d.part_count, 1);
    assert_near(sum, area, AREA_REL * area);
}

/* Regression (fuzz, double build: double-decompose-parts-exceed-outline-area):
 * the points (1e-30, 1e-30) and (1.68e-305, 2.21e-30) lie within the weld
 * tolerance of each other but are not consecutive, so the cleaned outline
 * pinches there: it visits the origin twice, and its edges towards
 * (1240000, 0.0039) and (70.3, 124.4) cross 1e-30 from the origin, far below
 * the rounding of their far end points. The crossing went undetected, and
 * the decomposition returned SX_OK with parts of 2.64e7 m^2 for an outline
 * of 1.96e7 m^2. A pinch closer than the weld tolerance now counts as the
 * outline touching itself (SX_ERR_INVALID_ARG). */
static void outline_pinched_below_the_weld_tolerance_is_refused(void **state) {
    const double xy[] = {70.3359375, 124.3828125, 1e-30,    1e-30,    1e-30,    -10.875, 1240000,
                         0.0039,     1.68e-305,   2.21e-30, 2.21e-30, 2.21e-30, -16,     750000};
    const double tol = (double)SX_WELD_TOLERANCE;
    sx_vec2 p[7];
    decomp d;
    double sum = 0.0;
    int i, k;
    (void)state;
    for (i = 0; i < 7; ++i)
        p[i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
    run_decompose(p, 7, &d);
    /* Refused, or (were it ever split correctly) parts that sum to the
     * outline's area: never SX_OK with the wrong lobe. */
    if (d.status == SX_OK) {
        double area = fabs(outline_area(p, 7));
        for (i = 0; i < d.part_count; ++i)
            sum += (double)sx_shape_area(&d.parts[i]);
        assert_near(sum, area, AREA_REL * area);
    } else {
        assert_int_equal(d.status, SX_ERR_INVALID_ARG);
        assert_int_equal(d.part_count, 0);
    }
    assert_int_equal(d.status, SX_ERR_INVALID_ARG);

    /* The same at a sane scale: an hourglass whose neck is g wide. Below
     * the weld tolerance it is a pinch (refused); a few tolerances wide it
     * is a simple outline (two or more parts that sum to its area). */
    for (k = 0; k < 3; ++k) {
        const double g = k == 0 ? 0.5 * tol : (k == 1 ? 0.9 * tol : 4.0 * tol);
        sx_vec2 h[6];
        h[0] = sx_v2(SX_R(-1.0), SX_R(-1.0));
        h[1] = sx_v2(SX_R(1.0), SX_R(-1.0));
        h[2] = sx_v2((sx_real)(0.5 * g), SX_R(0.0));
        h[3] = sx_v2(SX_R(1.0), SX_R(1.0));
        h[4] = sx_v2(SX_R(-1.0), SX_R(1.0));
        h[5] = sx_v2((sx_real)(-0.5 * g), SX_R(0.0));
        run_decompose(h, 6, &d);
        if (k < 2) {
            assert_int_equal(d.status, SX_ERR_INVALID_ARG);
            assert_int_equal(d.part_count, 0);
        } else {
            double area = fabs(outline_area(h, 6));
            assert_int_equal(d.status, SX_OK);
            assert_true(d.part_count >= 2);
            for (sum = 0.0, i = 0; i < d.part_count; ++i)
                sum += (double)sx_shape_area(&d.parts[i]);
            assert_near(sum, area, AREA_REL * area);
        }
    }
}

/* Regression (make fuzz, harness decompose, input
 * decompose-ok-without-parts-beyond-huge): an outline with points at 1e24,
 * 1.8e19 and 3.3e35 (far beyond SX_HUGE) next to points at 1e-2 and 16
 * passed the cleaning and the ear clipping, but its one piece failed
 * sx_polygon_from_hull, and the call returned SX_OK with 0 parts. A
 * decomposition without a part is SX_ERR_DEGENERATE now.
 *
 * The cleaning reduced that outline to the triangle (-0.0127, -0.0127),
 * 1.09e24 (1, 1), 3.25e35 (1, 1), dropping the points at 16 m as
 * "collinear" with lines the earlier drops had already moved. Now that a
 * near-collinear drop stays within the tolerance of every raw point it
 * replaces (decompose-collinear-drops-erode-a-curve), the outline keeps its
 * run out along y = x and back, which doubles back on itself
 * (SX_ERR_INVALID_ARG); the triangle itself still takes the path where
 * every piece fails. */
static void an_outline_whose_parts_all_fail_is_degenerate(void **state) {
    const float xy[] = {0x1.cececep+79f,
                        0x1.cececep+79f,
                        0x1.b05002p-126f,
                        0.0f,
                        -16.0f,
                        0.0f,
                        -8.5f,
                        -11.0f,
                        0x1.fffffep+63f,
                        -0x1.a02752p-7f,
                        -0x1.a02d52p-7f,
                        -0x1.a03352p-7f,
                        -0x1.a03952p-7f,
                        -0x1.a03f52p-7f,
                        -0x1.a04552p-7f,
                        -0x1.a04b52p-7f,
                        0x1.cececep+79f,
                        0x1.cececep+79f,
                        0x1.f4cecep+117f,
                        0x1.f4ceb6p+117f,
                        0.0f,
                        -16.0f,
                        -16.0f,
                        -16.0f};
    sx_vec2 p[12];
    decomp d;
    int i;
    (void)state;
    for (i = 0; i < 12; ++i)
        p[i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
    run_decompose(p, 12, &d);
    if (d.status == SX_OK) {
        assert_true(d.part_count >= 1 && d.part_count <= 10);
        for (i = 0; i < d.part_count; ++i)
            assert_int_equal(sx_shape_validate(&d.parts[i]), SX_OK);
    } else {
        assert_int_equal(d.part_count, 0);
    }
#ifndef SX_DOUBLE
    assert_int_equal(d.status, SX_ERR_INVALID_ARG); /* the float case found */
#endif
    p[0] = sx_v2((sx_real)xy[12], (sx_real)xy[13]);
    p[1] = sx_v2((sx_real)xy[16], (sx_real)xy[17]);
    p[2] = sx_v2((sx_real)xy[18], (sx_real)xy[19]);
    run_decompose(p, 3, &d);
    if (d.status == SX_OK) {
        assert_int_equal(d.part_count, 1);
        assert_int_equal(sx_shape_validate(&d.parts[0]), SX_OK);
    } else {
        assert_int_equal(d.part_count, 0);
    }
#ifndef SX_DOUBLE
    assert_int_equal(d.status, SX_ERR_DEGENERATE); /* its area overflows float */
#endif
}

/* The largest distance from a point of p to the nearest edge of a part. */
static double max_distance_to_parts(const sx_vec2 *p, int n, const sx_shape *parts, int count) {
    double worst = 0.0;
    int i, j, k;
    for (k = 0; k < n; ++k) {
        double best = HUGE_VAL;
        for (i = 0; i < count; ++i) {
            const sx_polygon *g = &parts[i].u.polygon;
            for (j = 0; j < g->count; ++j) {
                double dd = seg_distance(g->vertices[j], g->vertices[(j + 1) % g->count],
                                         (double)p[k].x, (double)p[k].y);
                if (dd < best) best = dd;
            }
        }
        if (best > worst) worst = best;
    }
    return worst;
}

static double outline_perimeter(const sx_vec2 *p, int n) {
    double s = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        const sx_vec2 a = p[i], b = p[(i + 1) % n];
        s += hypot((double)b.x - (double)a.x, (double)b.y - (double)a.y);
    }
    return s;
}

/* Regression (make fuzz, harness decompose, input
 * decompose-collinear-drops-erode-a-curve): a 47-point outline close to a
 * circle 31 m across, cleaned with a weld tolerance of 2.125 m, came back as
 * one quadrilateral of 313 m^2 for an outline of 781 m^2, with raw points
 * 11 m outside it. The cleaning dropped each point within the tolerance of
 * the line through its current neighbours; as the chord grew from a fixed
 * neighbour, each drop was measured against an outline the earlier drops
 * had already moved, and the moves added up. The same erosion took 43% of
 * the area of a unit circle drawn with 4000 points at the default
 * tolerance. Checked: the parts keep within twice the tolerance of every
 * raw point (the tolerance, and a weld's move of up to one more) and their
 * area within twice the tolerance times the perimeter of the outline's. */
static void cleaning_does_not_erode_a_densely_drawn_curve(void **state) {
    static const float xy[][2] = {
        {0x1.fcp+4f, -0x1.3cp+3f},         {0x1.f6db08p+4f, -0x1.e8e13ep+2f},
        {0x1.f4488cp+4f, -0x1.a151dcp+2f}, {0x1.f1b612p+4f, -0x1.59c27cp+2f},
        {0x1.e2b1ep+4f, -0x1.ac77f8p+1f},  {0x1.d3adacp+4f, -0x1.4ad5fp+0f},
        {0x1.a455aap+4f, 0x1.0faeep+1f},   {0x1.85ecccp+4f, 0x1.ac0718p+1f},
        {0x1.76b85ep+4f, 0x1.fa3334p+1f},  {0x1.6783fp+4f, 0x1.242fa8p+2f},
        {0x1.44d4e8p+4f, 0x1.4cec2p+2f},   {0x1.2225ep+4f, 0x1.75a898p+2f},
        {0x1.fcp+3f, 0x1.75a898p+2f},      {0x1.b3b43ep+3f, 0x1.75a898p+2f},
        {0x1.6e562cp+3f, 0x1.4cec1ep+2f},  {0x1.28f818p+3f, 0x1.242fa4p+2f},
        {0x1.0a8f3cp+3f, 0x1.fa332ap+1f},  {0x1.d84ccp+2f, 0x1.ac070cp+1f},
        {0x1.5ea95p+2f, 0x1.0faedp+1f},    {0x1.fff2ap+1f, 0x1.a90f4p-2f},
        {0x1.d09aap+1f, -0x1.8152p-7f},    {0x1.a142ap+1f, -0x1.c1246p-2f},
        {0x1.4292ap+1f, -0x1.4ad6p+0f},    {0x1.493dap-1f, -0x1.59c288p+2f},
        {0x1.493dap-2f, -0x1.e8e14ep+2f},  {0x0p+0f, -0x1.3c000ap+3f},
        {0x1.493dcp-1f, -0x1.cb1ec2p+3f},  {0x1.94e22p+0f, -0x1.067102p+4f},
        {0x1.0681ep+1f, -0x1.16e1d4p+4f},  {0x1.4292bp+1f, -0x1.2752a4p+4f},
        {0x1.a142b6p+1f, -0x1.34fb74p+4f}, {0x1.fff2bcp+1f, -0x1.42a442p+4f},
        {0x1.2f516p+2f, -0x1.504d1p+4f},   {0x1.5ea964p+2f, -0x1.5df5ep+4f},
        {0x1.d84cccp+2f, -0x1.7180e4p+4f}, {0x1.28f81ap+3f, -0x1.850be8p+4f},
        {0x1.6e563p+3f, -0x1.8f3b08p+4f},  {0x1.b3b448p+3f, -0x1.996a28p+4f},
        {0x1.2225e4p+4f, -0x1.996a26p+4f}, {0x1.44d4ecp+4f, -0x1.8f3b08p+4f},
        {0x1.4d80aep+4f, -0x1.8caf4p+4f},  {0x1.562c7p+4f, -0x1.8a2378p+4f},
        {0x1.6783f4p+4f, -0x1.850be8p+4f}, {0x1.a455aap+4f, -0x1.5df5dcp+4f},
        {0x1.bc01acp+4f, -0x1.42a43cp+4f}, {0x1.d3adbp+4f, -0x1.27529cp+4f},
        {0x1.f1b614p+4f, -0x1.cb1eb8p+3f}};
    enum { N = (int)(sizeof xy / sizeof xy[0]), DENSE = 4000 };
    static sx_vec2 p[DENSE];
    static sx_shape parts[MAX_OUTLINE];
    const double tol = 2.125, dense_tol = (double)SX_WELD_TOLERANCE;
    size_t bytes = sx_decompose_scratch_bytes(DENSE);
    void *scratch = malloc(bytes);
    double area, sum = 0.0;
    int i, count = 0, tris = 0;
    (void)state;
    assert_non_null(scratch);
    for (i = 0; i < N; ++i)
        p[i] = sx_v2((sx_real)xy[i][0], (sx_real)xy[i][1]);
    assert_int_equal(sx_decompose_polygon_ex(p, N, (sx_real)tol, scratch, bytes, parts, MAX_OUTLINE,
                                             &count, &tris),
                     SX_OK);
    for (i = 0; i < count; ++i)
        sum += (double)sx_shape_area(&parts[i]);
    area = fabs(outline_area(p, N));
    assert_true(fabs(sum - area) <= 2.0 * tol * outline_perimeter(p, N)); /* was 467 > 422 */
    assert_true(max_distance_to_parts(p, N, parts, count) <= 2.0 * tol);  /* was 11.2 */

    /* A unit circle drawn with 4000 points, default tolerance: it was
     * cleaned to a quadrilateral of 1.79 m^2. */
    for (i = 0; i < DENSE; ++i) {
        double a = 2.0 * PI_D * (double)i / (double)DENSE;
        p[i] = sx_v2((sx_real)cos(a), (sx_real)sin(a));
    }
    assert_int_equal(
        sx_decompose_polygon(p, DENSE, scratch, bytes, parts, MAX_OUTLINE, &count, &tris), SX_OK);
    for (sum = 0.0, i = 0; i < count; ++i)
        sum += (double)sx_shape_area(&parts[i]);
    area = fabs(outline_area(p, DENSE));
    assert_true(fabs(sum - area) <= 2.0 * dense_tol * outline_perimeter(p, DENSE));
    assert_true(max_distance_to_parts(p, DENSE, parts, count) <= 2.0 * dense_tol);
    free(scratch);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(l_shape_splits_into_two_parts),
        cmocka_unit_test(u_shape_splits_into_at_most_four_parts),
        cmocka_unit_test(star_merges_below_triangle_count),
        cmocka_unit_test(comb_merges_below_triangle_count),
        cmocka_unit_test(spiral_merges_well_below_triangle_count),
        cmocka_unit_test(convex_outline_is_one_part),
        cmocka_unit_test(collinear_and_duplicate_points_are_cleaned_first),
        cmocka_unit_test(tiny_outline_needs_a_matching_weld_tolerance),
        cmocka_unit_test(outline_far_from_origin_decomposes_like_at_origin),
        cmocka_unit_test(random_star_shaped_outlines_decompose_exactly),
        cmocka_unit_test(random_walk_outlines_decompose_exactly),
        cmocka_unit_test(bow_tie_is_refused_as_invalid_argument),
        cmocka_unit_test(outline_touching_itself_is_refused),
        cmocka_unit_test(collinear_or_duplicate_outlines_are_degenerate),
        cmocka_unit_test(non_finite_points_are_refused),
        cmocka_unit_test(bad_arguments_and_capacity_are_reported),
        cmocka_unit_test(an_outline_too_large_for_finite_mass_is_refused_whole),
        cmocka_unit_test(point_in_outline_follows_the_winding_number),
        cmocka_unit_test(a_spike_whose_base_is_below_the_tolerance_is_dropped),
        cmocka_unit_test(outline_pinched_below_the_weld_tolerance_is_refused),
        cmocka_unit_test(an_outline_whose_parts_all_fail_is_degenerate),
        cmocka_unit_test(cleaning_does_not_erode_a_densely_drawn_curve),
    };
    return cmocka_run_group_tests_name("decompose", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
