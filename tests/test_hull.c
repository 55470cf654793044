/* sepax tests — the convex hull builder and the polygon builders on top of it.
 *
 * Random clouds (fixed seeds) are checked against the hull's defining
 * properties rather than against another implementation's output: every
 * input point is inside or within the weld tolerance of the hull, the hull is
 * CCW and strictly convex with no collinear triple, starts at the lowest-x
 * (then lowest-y) vertex, and every vertex is an input point. A reference
 * exact hull (Andrew's monotone chain in double, allocating, test-only)
 * checks the capacity answer: SX_ERR_CAPACITY only when the exact hull
 * really has more than SX_MAX_POLYGON_VERTICES vertices. Then every error
 * status of every builder. */
#include <math.h>
#include <stdlib.h>

#include "test_support.h"

#define MAX_CLOUD 256
#define PI_D 3.14159265358979323846

/* Rounding allowed in the containment check, relative to the cloud's scale.
 * The hull's points are input points and the check runs in double, so only
 * the check's own rounding counts, whatever sx_real is. */
#define REL_ROUND 1e-12

typedef struct dpoint {
    double x, y;
} dpoint;

static double dcross(dpoint o, dpoint a, dpoint b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static int dpoint_cmp(const void *pa, const void *pb) {
    const dpoint *a = (const dpoint *)pa, *b = (const dpoint *)pb;
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    return 0;
}

/* The exact convex hull (collinear points excluded) into h (room for
 * 2 n + 1 points); returns its vertex count. */
static int reference_hull(const sx_vec2 *pts, int n, dpoint *h) {
    dpoint p[MAX_CLOUD];
    int i, k = 0, t;
    for (i = 0; i < n; ++i) {
        p[i].x = (double)pts[i].x;
        p[i].y = (double)pts[i].y;
    }
    qsort(p, (size_t)n, sizeof(dpoint), dpoint_cmp);
    for (i = 0; i < n; ++i) {
        while (k >= 2 && dcross(h[k - 2], h[k - 1], p[i]) <= 0.0)
            --k;
        h[k++] = p[i];
    }
    for (i = n - 2, t = k + 1; i >= 0; --i) {
        while (k >= t && dcross(h[k - 2], h[k - 1], p[i]) <= 0.0)
            --k;
        h[k++] = p[i];
    }
    return k - 1;
}

static int reference_hull_count(const sx_vec2 *pts, int n) {
    dpoint h[2 * MAX_CLOUD + 1];
    return reference_hull(pts, n, h);
}

/* The width of the cloud: the least, over the exact hull's edges, of the
 * farthest hull vertex from that edge's line (0 for fewer than 3 vertices). */
static double reference_width(const sx_vec2 *pts, int n) {
    dpoint h[2 * MAX_CLOUD + 1];
    int k = reference_hull(pts, n, h), i, j;
    double width = 1e300;
    if (k < 3) return 0.0;
    for (i = 0; i < k; ++i) {
        dpoint a = h[i], b = h[(i + 1) % k];
        double len = sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y)), far = 0.0;
        for (j = 0; j < k; ++j)
            far = fmax(far, dcross(a, b, h[j]) / len);
        width = fmin(width, far);
    }
    return width;
}

static double cloud_scale(const sx_vec2 *pts, int n) {
    double s = 1.0;
    int i;
    for (i = 0; i < n; ++i) {
        s = fmax(s, fabs((double)pts[i].x));
        s = fmax(s, fabs((double)pts[i].y));
    }
    return s;
}

/* Largest distance of any input point outside the hull (0 if all inside). */
static double max_outside(const sx_hull *h, const sx_vec2 *pts, int n) {
    double worst = 0.0;
    int i, j;
    for (i = 0; i < h->count; ++i) {
        sx_vec2 a = h->points[i], b = h->points[(i + 1) % h->count];
        double ex = (double)b.x - (double)a.x, ey = (double)b.y - (double)a.y;
        double len = sqrt(ex * ex + ey * ey);
        for (j = 0; j < n; ++j) {
            double d =
                (ex * ((double)pts[j].y - (double)a.y) - ey * ((double)pts[j].x - (double)a.x)) /
                len;
            if (-d > worst) worst = -d;
        }
    }
    return worst;
}

/* The defining properties of a hull built with tolerance tol. */
static void assert_hull_properties(const sx_hull *h, const sx_vec2 *pts, int n, double tol) {
    int i, j;
    double scale = cloud_scale(pts, n);
    assert_true(h->count >= 3 && h->count <= SX_MAX_POLYGON_VERTICES);
    assert_true(sx_validate_hull(h, (sx_real)tol));
    for (i = 0; i < h->count; ++i) {
        sx_vec2 a = h->points[i], b = h->points[(i + 1) % h->count];
        sx_vec2 c = h->points[(i + 2) % h->count];
        bool found = false;
        dpoint da = {(double)a.x, (double)a.y}, db = {(double)b.x, (double)b.y};
        dpoint dc = {(double)c.x, (double)c.y};
        /* strictly convex and CCW, and no triple collinear within the
         * tolerance (the middle point stands off its neighbours' line by
         * more than tol), up to the double rounding of this check */
        assert_true(-dcross(da, dc, db) /
                        sqrt((dc.x - da.x) * (dc.x - da.x) + (dc.y - da.y) * (dc.y - da.y)) >
                    tol - REL_ROUND * scale);
        for (j = 0; j < h->count; ++j) {
            sx_vec2 v = h->points[j];
            dpoint dv = {(double)v.x, (double)v.y};
            if (j == i || j == (i + 1) % h->count) continue;
            assert_true(dcross(da, db, dv) > -REL_ROUND * scale * scale);
        }
        for (j = 0; j < n && !found; ++j)
            found = pts[j].x == a.x && pts[j].y == a.y;
        assert_true(found);
        if (i > 0) {
            assert_true(h->points[0].x < a.x || (h->points[0].x == a.x && h->points[0].y < a.y));
        }
    }
    assert_true(max_outside(h, pts, n) <= tol + REL_ROUND * scale);
}

static sx_vec2 rotated(double r, double angle, double cx, double cy) {
    return sx_v2((sx_real)(cx + r * cos(angle)), (sx_real)(cy + r * sin(angle)));
}

static void shuffle(sx_vec2 *pts, int n, sx_test_rng *rng) {
    int i;
    for (i = n - 1; i > 0; --i) {
        int j = (int)(sx_test_rng_next(rng) % (uint64_t)(i + 1));
        sx_vec2 t = pts[i];
        pts[i] = pts[j];
        pts[j] = t;
    }
}

/* ---- random clouds -------------------------------------------------------- */

static void hull_of_regular_polygon_plus_interior_points_is_the_polygon(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0001u);
    int cloud;
    (void)state;
    for (cloud = 0; cloud < 1500; ++cloud) {
        sx_vec2 pts[MAX_CLOUD], poly[SX_MAX_POLYGON_VERTICES];
        sx_hull h;
        int k = 3 + (int)(sx_test_rng_next(&rng) % (uint64_t)(SX_MAX_POLYGON_VERTICES - 2));
        int inner = (int)(sx_test_rng_next(&rng) % 198u);
        double r = 0.2 + 5.0 * sx_test_rng_unit(&rng), a0 = 6.3 * sx_test_rng_unit(&rng);
        double cx = -10.0 + 20.0 * sx_test_rng_unit(&rng),
               cy = -10.0 + 20.0 * sx_test_rng_unit(&rng);
        if (cloud % 4 == 0) {
            /* unit-size polygons near the largest promised coordinate */
            r = 1.0 + sx_test_rng_unit(&rng);
            cx = 0.9 * (double)SX_HUGE * (sx_test_rng_unit(&rng) < 0.5 ? -1.0 : 1.0);
            cy = -0.9 * (double)SX_HUGE * sx_test_rng_unit(&rng);
        }
        int i, j, n = 0;
        for (i = 0; i < k; ++i) {
            poly[i] = rotated(r, a0 + 2.0 * 3.14159265358979 * i / k, cx, cy);
            pts[n++] = poly[i];
        }
        for (i = 0; i < inner; ++i) {
            /* a random point of the polygon pulled 10% towards its centre */
            int e = (int)(sx_test_rng_next(&rng) % (uint64_t)k);
            double u = sx_test_rng_unit(&rng), v = sx_test_rng_unit(&rng);
            double s = 0.9 * sqrt(u);
            sx_vec2 p0 = poly[e], p1 = poly[(e + 1) % k];
            double ex = (double)p0.x + v * ((double)p1.x - (double)p0.x);
            double ey = (double)p0.y + v * ((double)p1.y - (double)p0.y);
            pts[n++] = sx_v2((sx_real)(cx + s * (ex - cx)), (sx_real)(cy + s * (ey - cy)));
        }
        shuffle(pts, n, &rng);
        assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_OK);
        assert_int_equal(h.count, k);
        assert_hull_properties(&h, pts, n, (double)SX_WELD_TOLERANCE);
        for (i = 0; i < k; ++i) {
            bool found = false;
            for (j = 0; j < k; ++j)
                found = found || (h.points[i].x == poly[j].x && h.points[i].y == poly[j].y);
            assert_true(found);
        }
    }
}

static void hull_of_uniform_clouds_has_hull_properties_or_reports_capacity(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0002u);
    int cloud, ok = 0, capacity = 0;
    (void)state;
    for (cloud = 0; cloud < 2000; ++cloud) {
        sx_vec2 pts[MAX_CLOUD];
        sx_hull h;
        sx_status st;
        int n = 3 + (int)(sx_test_rng_next(&rng) % 198u), i, shape = cloud % 3;
        double scale = cloud % 5 == 0 ? 100.0 : 1.0;
        for (i = 0; i < n; ++i) {
            double x = sx_test_rng_unit(&rng) * 2.0 - 1.0, y = sx_test_rng_unit(&rng) * 2.0 - 1.0;
            if (shape == 1) y *= 0.05; /* a flat sliver */
            if (shape == 2) {          /* a disc: hulls far above the capacity */
                double a = 6.283185307179586 * x, rr = sqrt(fabs(y));
                x = rr * cos(a);
                y = rr * sin(a);
            }
            pts[i] = sx_v2((sx_real)(scale * x), (sx_real)(scale * y));
        }
        st = sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h);
        if (st == SX_OK) {
            ++ok;
            assert_hull_properties(&h, pts, n, (double)SX_WELD_TOLERANCE);
            assert_true(h.count <= reference_hull_count(pts, n));
        } else if (st == SX_ERR_DEGENERATE) {
            /* a sliver of few points can be collinear within the tolerance:
             * then it is thinner than about twice the tolerance */
            assert_int_equal(h.count, 0);
            assert_true(reference_width(pts, n) <= 2.0 * (double)SX_WELD_TOLERANCE);
        } else {
            assert_int_equal(st, SX_ERR_CAPACITY);
            assert_int_equal(h.count, 0);
            assert_true(reference_hull_count(pts, n) > SX_MAX_POLYGON_VERTICES);
            ++capacity;
        }
    }
    /* both outcomes were exercised */
    assert_true(ok > 200);
    assert_true(capacity > 200);
}

static void hull_of_points_on_a_circle_beyond_capacity_is_refused_not_truncated(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0003u);
    int cloud;
    (void)state;
    for (cloud = 0; cloud < 500; ++cloud) {
        sx_vec2 pts[MAX_CLOUD];
        sx_hull h;
        int k = SX_MAX_POLYGON_VERTICES + 1 + (int)(sx_test_rng_next(&rng) % 60u);
        int inner = (int)(sx_test_rng_next(&rng) % 100u), i, n = 0;
        double r = 0.5 + 10.0 * sx_test_rng_unit(&rng), a0 = sx_test_rng_unit(&rng);
        for (i = 0; i < k; ++i)
            pts[n++] = rotated(r, a0 + 6.283185307179586 * i / k, 1.0, -2.0);
        for (i = 0; i < inner; ++i) {
            pts[n++] =
                rotated(0.8 * r * sx_test_rng_unit(&rng), 6.3 * sx_test_rng_unit(&rng), 1.0, -2.0);
        }
        shuffle(pts, n, &rng);
        assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_ERR_CAPACITY);
        assert_int_equal(h.count, 0);
    }
}

static void hull_of_lattice_and_edge_points_keeps_only_the_corners(void **state) {
    sx_vec2 pts[MAX_CLOUD];
    sx_hull h;
    sx_test_rng rng = sx_test_rng_make(0x5eed0004u);
    int i, j, n = 0, cloud;
    (void)state;
    for (i = 0; i < 10; ++i) {
        for (j = 0; j < 10; ++j)
            pts[n++] = sx_v2((sx_real)i, (sx_real)j);
    }
    shuffle(pts, n, &rng);
    assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_int_equal(h.count, 4);
    assert_vec2_near(h.points[0], sx_v2(0, 0), 0.0);
    assert_vec2_near(h.points[1], sx_v2(9, 0), 0.0);
    assert_vec2_near(h.points[2], sx_v2(9, 9), 0.0);
    assert_vec2_near(h.points[3], sx_v2(0, 9), 0.0);
    /* Points on the edges of a rotated triangle, rounded to sx_real: they
     * sit a rounding error either side of the edges and are pruned. */
    for (cloud = 0; cloud < 300; ++cloud) {
        sx_vec2 tri[3];
        double a0 = 6.3 * sx_test_rng_unit(&rng);
        n = 0;
        for (i = 0; i < 3; ++i)
            tri[i] = pts[n++] = rotated(3.0, a0 + 2.0943951023931953 * i, 7.0, 5.0);
        for (i = 0; i < 150; ++i) {
            int e = i % 3;
            double t = sx_test_rng_unit(&rng);
            pts[n++] = sx_v2(
                (sx_real)((double)tri[e].x + t * ((double)tri[(e + 1) % 3].x - (double)tri[e].x)),
                (sx_real)((double)tri[e].y + t * ((double)tri[(e + 1) % 3].y - (double)tri[e].y)));
        }
        shuffle(pts, n, &rng);
        assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_OK);
        assert_int_equal(h.count, 3);
        assert_hull_properties(&h, pts, n, (double)SX_WELD_TOLERANCE);
    }
}

static void hull_of_near_collinear_and_clustered_clouds_is_degenerate(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0005u);
    int cloud;
    (void)state;
    for (cloud = 0; cloud < 500; ++cloud) {
        sx_vec2 pts[MAX_CLOUD];
        sx_hull h;
        int n = 3 + (int)(sx_test_rng_next(&rng) % 150u), i;
        double a = 6.3 * sx_test_rng_unit(&rng), noise = 0.4 * (double)SX_WELD_TOLERANCE;
        for (i = 0; i < n; ++i) {
            double t = 4.0 * sx_test_rng_unit(&rng) - 2.0,
                   s = noise * (2.0 * sx_test_rng_unit(&rng) - 1.0);
            if (cloud % 2 == 0) {
                /* along a line, off it by less than the tolerance */
                pts[i] =
                    sx_v2((sx_real)(t * cos(a) - s * sin(a)), (sx_real)(t * sin(a) + s * cos(a)));
            } else {
                /* a cluster smaller than the tolerance */
                pts[i] = sx_v2((sx_real)(3.0 + noise * t * 0.5), (sx_real)(-1.0 + s));
            }
        }
        assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_ERR_DEGENERATE);
        assert_int_equal(h.count, 0);
    }
}

static void hull_of_a_dense_nearly_straight_arc_is_pruned_not_refused(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0007u);
    int trial;
    (void)state;
    for (trial = 0; trial < 40; ++trial) {
        /* 250 points on an arc whose sagitta over the whole run is below
         * (R = 1000: 0.5 mm) or above (R = 100, 300: 5 mm, 1.7 mm) the weld
         * tolerance: far more raw hull vertices than the wrap's buffer */
        double R = trial % 3 == 0 ? 1000.0 : (trial % 3 == 1 ? 100.0 : 300.0);
        sx_vec2 pts[MAX_CLOUD];
        sx_hull h;
        sx_status st;
        int i, n = 0;
        for (i = 0; i < 250; ++i) {
            double x = -1.0 + 2.0 * i / 249.0;
            pts[n++] = sx_v2((sx_real)x, (sx_real)(sqrt(R * R - x * x) - R));
        }
        pts[n++] = sx_v2(SX_R(0.1), SX_R(-1.0));
        shuffle(pts, n, &rng);
        st = sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h);
        if (R == 1000.0) {
            assert_int_equal(st, SX_OK);
            assert_int_equal(h.count, 3);
        }
        if (st == SX_OK) {
            /* A vertex collinear within the tolerance is moved to its cap's
             * apex rather than dropped when dropping it would leave points
             * of the run more than the tolerance outside. */
            assert_hull_properties(&h, pts, n, (double)SX_WELD_TOLERANCE);
        } else {
            assert_int_equal(st, SX_ERR_CAPACITY);
        }
    }
}

static void hull_of_a_huge_exact_hull_is_refused_in_bounded_time(void **state) {
    /* 20000 points on a circle: the exact hull (after welding) overflows the
     * wrap's record long before the loop closes */
    static sx_vec2 pts[20000];
    sx_hull h;
    int i;
    (void)state;
    for (i = 0; i < 20000; ++i)
        pts[i] = rotated(1.0, 6.283185307179586 * i / 20000.0, 0.0, 0.0);
    assert_int_equal(sx_compute_hull(pts, 20000, SX_WELD_TOLERANCE, &h), SX_ERR_CAPACITY);
    assert_int_equal(h.count, 0);
    /* its first tenth: a 36-degree arc of 2000 points, refused as well */
    assert_int_equal(sx_compute_hull(pts, 2000, SX_WELD_TOLERANCE, &h), SX_ERR_CAPACITY);
}

static void hull_of_jittered_clusters_welds_each_cluster_to_one_vertex(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0008u);
    int cloud;
    (void)state;
    for (cloud = 0; cloud < 500; ++cloud) {
        sx_vec2 pts[MAX_CLOUD], centers[SX_MAX_POLYGON_VERTICES];
        sx_hull h;
        int k = 3 + (int)(sx_test_rng_next(&rng) % (uint64_t)(SX_MAX_POLYGON_VERTICES - 2));
        double a0 = 6.3 * sx_test_rng_unit(&rng), jitter = 0.35 * (double)SX_WELD_TOLERANCE;
        int i, j, n = 0;
        for (i = 0; i < k; ++i)
            centers[i] = rotated(1.0, a0 + 2.0 * PI_D * i / k, 2.0, 3.0);
        for (i = 0; i < k; ++i) {
            int m = 1 + (int)(sx_test_rng_next(&rng) % 20u);
            for (j = 0; j < m; ++j) {
                double dx = jitter * (2.0 * sx_test_rng_unit(&rng) - 1.0);
                double dy = jitter * (2.0 * sx_test_rng_unit(&rng) - 1.0);
                pts[n++] = j == 0 ? centers[i]
                                  : sx_v2((sx_real)((double)centers[i].x + dx),
                                          (sx_real)((double)centers[i].y + dy));
            }
        }
        shuffle(pts, n, &rng);
        assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_OK);
        assert_int_equal(h.count, k);
        assert_hull_properties(&h, pts, n, (double)SX_WELD_TOLERANCE);
        /* one vertex per cluster */
        for (i = 0; i < k; ++i) {
            int hits = 0;
            for (j = 0; j < k; ++j) {
                hits += sx_distance(h.points[j], centers[i]) <= SX_R(2.0) * SX_WELD_TOLERANCE;
            }
            assert_int_equal(hits, 1);
        }
    }
}

static void
hull_of_millimetre_hexagon_is_welded_by_default_and_kept_with_a_small_tolerance(void **state) {
    sx_vec2 pts[SX_MAX_POLYGON_VERTICES];
    sx_hull h;
    int i;
    (void)state;
    for (i = 0; i < 6; ++i)
        pts[i] = rotated(1.0e-3, 2.0 * PI_D * i / 6.0, 0.25, -0.5);
    /* a hexagon of 1 mm radius: neighbouring corners are 1 mm apart, within
     * the default 1.25 mm weld tolerance, so every other corner is welded
     * away and a triangle remains, still holding every corner within it */
    assert_int_equal(sx_compute_hull(pts, 6, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_int_equal(h.count, 3);
    assert_hull_properties(&h, pts, 6, (double)SX_WELD_TOLERANCE);
    assert_int_equal(sx_compute_hull(pts, 6, SX_R(1.0e-6), &h), SX_OK);
    assert_int_equal(h.count, 6);
    assert_hull_properties(&h, pts, 6, 1.0e-6);
}

static void hull_of_grid_snapped_clouds_with_any_tolerance_is_valid_or_refused(void **state) {
    /* Points snapped to a coarse grid: many exact duplicates and exactly
     * collinear runs; tolerance 0 or a fraction of the grid step. */
    sx_test_rng rng = sx_test_rng_make(0x5eed0009u);
    int cloud, ok = 0;
    (void)state;
    for (cloud = 0; cloud < 3000; ++cloud) {
        sx_vec2 pts[MAX_CLOUD];
        sx_hull h;
        sx_status st;
        int n = 1 + (int)(sx_test_rng_next(&rng) % 60u), i;
        int cells = 2 + (int)(sx_test_rng_next(&rng) % 6u);
        double step = cloud % 2 ? 0.125 : 0.1, tol = (cloud % 3) * 0.2 * step;
        /* at tolerance 0 the grid must be binary, so that exactly collinear
         * grid points stay exactly collinear after rounding */
        if (tol == 0.0) step = 0.125;
        for (i = 0; i < n; ++i) {
            pts[i] = sx_v2((sx_real)(step * (double)(sx_test_rng_next(&rng) % (uint64_t)cells)),
                           (sx_real)(step * (double)(sx_test_rng_next(&rng) % (uint64_t)cells)));
        }
        st = sx_compute_hull(pts, n, (sx_real)tol, &h);
        if (st == SX_OK) {
            ++ok;
            assert_hull_properties(&h, pts, n, (double)(sx_real)tol);
        } else {
            assert_int_equal(h.count, 0);
            assert_true(st == SX_ERR_DEGENERATE || st == SX_ERR_CAPACITY);
            if (st == SX_ERR_CAPACITY)
                assert_true(reference_hull_count(pts, n) > SX_MAX_POLYGON_VERTICES);
            if (st == SX_ERR_DEGENERATE && tol == 0.0)
                assert_true(reference_hull_count(pts, n) < 3);
        }
    }
    assert_true(ok > 1000);
}

/* Regression (fuzz: double-hull-point-outside-hull): a run of points along
 * y = x, from (580000, 580000) down to (-16, -16), collinear to within the
 * rounding of the orientation test even in the wide real. The wrap jumped
 * from (580000, 580000) to (-7.375, -7.375) (a noise-level tie) and then left
 * out (-16, -16) as lying "behind" that edge, although it lies 0.0141 outside
 * the closing edge to (-16, -16.02), 11 x the tolerance. Ties within the
 * rounding noise are now decided one way everywhere (the farther point,
 * and a point just behind the previous edge's extension counts as ahead).
 * The float build rounds the cloud and was already right; both must be. */
static void hull_of_a_near_collinear_run_keeps_its_far_end(void **state) {
    static const double xy[] = {-15.625,
                                -16,
                                -16,
                                -16,
                                -16,
                                -16.02,
                                -15.875,
                                -16,
                                -4.5,
                                -4.52,
                                -13,
                                -16,
                                -7.375,
                                -7.374999999999905,
                                -7.3749999999998099,
                                -7.3749999999997149,
                                -7.3749999999996199,
                                -7.3749999999995248,
                                -7.374999999999317,
                                -7.374999999999222,
                                7.25,
                                7.2500000000000933,
                                580000,
                                580000.00000000745};
    sx_vec2 pts[12];
    sx_hull h;
    int i;
    bool has_corner = false;
    (void)state;
    for (i = 0; i < 12; ++i)
        pts[i] = sx_v2((sx_real)xy[2 * i], (sx_real)xy[2 * i + 1]);
    assert_int_equal(sx_compute_hull(pts, 12, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_hull_properties(&h, pts, 12, (double)SX_WELD_TOLERANCE);
    /* (-16, -16) stands 0.0141 off the hull's other vertices' line: it is a
     * corner of the hull. */
    for (i = 0; i < h.count; ++i)
        has_corner = has_corner || (h.points[i].x == SX_R(-16.0) && h.points[i].y == SX_R(-16.0));
    assert_true(has_corner);
    assert_true(max_outside(&h, pts, 12) <= 1e-6);

    /* The noise of a tie is per coordinate: one point 4.5e37 below seven
     * small ones makes every difference from it lose its low bits in y, but
     * not in x, and the small points still order exactly (a bound from the
     * points' whole magnitude took them all as ties and built a 2-gon). */
    {
        static const double far_xy[] = {
            -1.875,   -1.875,  -1.3258252143859863, -3.2008252143859863,
            0.0,      -3.75,   1.3258252143859863,  -3.2008252143859863,
            -122.125, -4.5e37, 1.3258249759674072,  -0.54917454719543457,
            0.0,      0.0,     -1.3258256912231445, -0.54917526245117188};
        for (i = 0; i < 8; ++i)
            pts[i] = sx_v2((sx_real)far_xy[2 * i], (sx_real)far_xy[2 * i + 1]);
        assert_int_equal(sx_compute_hull(pts, 8, SX_WELD_TOLERANCE, &h), SX_OK);
        assert_int_equal(h.count, 5);
        assert_true(max_outside(&h, pts, 8) <= 1e-6);
    }
    /* A point straight below the previous vertex, a hair behind the long
     * previous edge's line, and another straight above it (on that edge):
     * opposite directions within the noise, where "farther wins" alone would
     * walk back up the edge and skip (1.09e24, 2.7e6). */
    {
        static const double tie_xy[] = {
            -15.625, -16,      -16,       -1.75,      -16,        -12.375,
            8.125,   -16,      15.875,    0,          -15.875,    3.875,
            -128,    1.141e18, 1.0918e24, 2738633.75, 2738607.25, 7012.89404296875,
            -7.375,  9.875,    -16,       15.875,     15.875,     15.875};
        for (i = 0; i < 12; ++i)
            pts[i] = sx_v2((sx_real)tie_xy[2 * i], (sx_real)tie_xy[2 * i + 1]);
        assert_int_equal(sx_compute_hull(pts, 12, SX_WELD_TOLERANCE, &h), SX_OK);
        assert_true(max_outside(&h, pts, 12) <= (double)SX_WELD_TOLERANCE);
        for (i = 0, has_corner = false; i < h.count; ++i)
            has_corner = has_corner || (double)h.points[i].x > 1e24;
        assert_true(has_corner);
    }
}

/* A vertical run of points 1e-34 apart at x = -15.125 (tolerance 0): the
 * run's edges are exact (the differences of floats cancel exactly), so
 * their direction is trustworthy however short they are, and the wrap must
 * turn from the top of the run to the corner (-22.5, -0.125) 7 m away. A
 * rounding bound taken from the points' magnitudes (15) instead of the
 * differences made every direction along the run noise, and the hull lost
 * that corner (fuzz: hull-short-run-loses-far-corner). */
static void hull_of_a_run_of_exact_tiny_edges_keeps_the_far_corner(void **state) {
    static const float ys[] = {1.01583363e-34f, 1.32974355e-34f, 1.61292565e-34f,
                               1.83766031e-34f, 1.98194891e-34f, 2.03166727e-34f,
                               1.98194868e-34f, 1.83766019e-34f, 0.0f,
                               4.97183601e-36f, 1.94006848e-35f, 7.01923837e-35f};
    sx_vec2 pts[15];
    sx_hull h;
    int i, n = 0;
    bool has_corner = false;
    (void)state;
    for (i = 0; i < 12; ++i)
        pts[n++] = sx_v2(SX_R(-15.125), (sx_real)ys[i]);
    pts[n++] = sx_v2(SX_R(-19.375), SX_R(-7.75));
    pts[n++] = sx_v2(SX_R(-22.5), SX_R(-0.125));
    pts[n++] = sx_v2(SX_R(-28.0), SX_R(-12.875));
    assert_int_equal(sx_compute_hull(pts, n, SX_R(0.0), &h), SX_OK);
    assert_true(sx_validate_hull(&h, SX_R(0.0)));
    for (i = 0; i < h.count; ++i)
        has_corner = has_corner || (h.points[i].x == SX_R(-22.5) && h.points[i].y == SX_R(-0.125));
    assert_true(has_corner);
    assert_true(max_outside(&h, pts, n) <= 1e-6);
    /* The default tolerance welds the run to one point: the same corner. */
    assert_int_equal(sx_compute_hull(pts, n, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_int_equal(h.count, 4);
    assert_true(max_outside(&h, pts, n) <= (double)SX_WELD_TOLERANCE);
}

/* Two points 10.6 m apart, both 1.1e18 m from the vertex before them: their
 * differences from that vertex round to the same double, but their own
 * difference is exact, and the orientation taken from it orders them (the
 * lower one is the next hull vertex). */
static void hull_orders_near_points_seen_from_a_far_vertex(void **state) {
    sx_vec2 pts[4];
    sx_hull h;
    (void)state;
    pts[0] = sx_v2(SX_R(-128.0), SX_R(1.141e18));
    pts[1] = sx_v2(SX_R(-16.0), SX_R(-1.75));
    pts[2] = sx_v2(SX_R(-16.0), SX_R(-12.375));
    pts[3] = sx_v2(SX_R(8.125), SX_R(-16.0));
    assert_int_equal(sx_compute_hull(pts, 4, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_true(max_outside(&h, pts, 4) <= (double)SX_WELD_TOLERANCE);
    assert_int_equal(h.count, 3);
}

static void hull_starts_at_lowest_x_then_lowest_y_and_runs_ccw(void **state) {
    sx_vec2 pts[5];
    sx_hull h;
    (void)state;
    pts[0] = sx_v2(1, 1);
    pts[1] = sx_v2(0, 1);
    pts[2] = sx_v2(1, 0);
    pts[3] = sx_v2(0, 0);
    pts[4] = sx_v2(SX_R(0.5), SX_R(0.5));
    assert_int_equal(sx_compute_hull(pts, 5, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_int_equal(h.count, 4);
    assert_vec2_near(h.points[0], sx_v2(0, 0), 0.0);
    assert_vec2_near(h.points[1], sx_v2(1, 0), 0.0);
    assert_vec2_near(h.points[2], sx_v2(1, 1), 0.0);
    assert_vec2_near(h.points[3], sx_v2(0, 1), 0.0);
    /* a clockwise input comes out counter-clockwise */
    pts[0] = sx_v2(0, 0);
    pts[1] = sx_v2(0, 2);
    pts[2] = sx_v2(-1, -3);
    assert_int_equal(sx_compute_hull(pts, 3, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_vec2_near(h.points[0], sx_v2(-1, -3), 0.0);
    assert_vec2_near(h.points[1], sx_v2(0, 0), 0.0);
    assert_vec2_near(h.points[2], sx_v2(0, 2), 0.0);
}

static void hull_welds_duplicates_and_near_duplicates(void **state) {
    sx_vec2 pts[12];
    sx_hull h;
    int i;
    sx_real w = SX_R(0.5) * SX_WELD_TOLERANCE;
    (void)state;
    pts[0] = sx_v2(0, 0);
    pts[1] = sx_v2(2, 0);
    pts[2] = sx_v2(1, 2);
    for (i = 0; i < 3; ++i) {
        pts[3 + i] = pts[i];                       /* exact duplicates */
        pts[6 + i] = sx_add(pts[i], sx_v2(w, -w)); /* within the tolerance */
        pts[9 + i] = sx_add(pts[i], sx_v2(-SX_R(0.6) * w, SX_R(0.3) * w));
    }
    assert_int_equal(sx_compute_hull(pts, 12, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_int_equal(h.count, 3);
    assert_hull_properties(&h, pts, 12, (double)SX_WELD_TOLERANCE);
}

static void hull_with_zero_tolerance_keeps_tiny_edges_but_welds_exact_duplicates(void **state) {
    sx_vec2 pts[5];
    sx_hull h;
    (void)state;
    pts[0] = sx_v2(0, 0);
    pts[1] = sx_v2(1, 0);
    pts[2] = sx_v2(0, 1);
    pts[3] = sx_v2(0, 1);
    pts[4] = sx_v2(SX_R(1.0), SX_R(1.0e-6)); /* 1e-6 above (1,0): an extra vertex */
    assert_int_equal(sx_compute_hull(pts, 5, SX_R(0.0), &h), SX_OK);
    assert_int_equal(h.count, 4);
    assert_int_equal(sx_compute_hull(pts, 5, SX_WELD_TOLERANCE, &h), SX_OK);
    assert_int_equal(h.count, 3);
}

/* ---- errors ------------------------------------------------------------------ */

static void compute_hull_reports_every_error(void **state) {
    sx_vec2 pts[4], dup[6];
    sx_hull h;
    int i;
    (void)state;
    pts[0] = sx_v2(0, 0);
    pts[1] = sx_v2(1, 0);
    pts[2] = sx_v2(0, 1);
    pts[3] = sx_v2(1, 1);
    assert_int_equal(sx_compute_hull(NULL, 4, SX_WELD_TOLERANCE, &h), SX_ERR_INVALID_ARG);
    assert_int_equal(h.count, 0);
    assert_int_equal(sx_compute_hull(pts, 4, SX_WELD_TOLERANCE, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_compute_hull(pts, -1, SX_WELD_TOLERANCE, &h), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_compute_hull(pts, 4, SX_R(-1.0e-3), &h), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_compute_hull(pts, 4, (sx_real)NAN, &h), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_compute_hull(pts, 4, (sx_real)INFINITY, &h), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_compute_hull(pts, 0, SX_WELD_TOLERANCE, &h), SX_ERR_DEGENERATE);
    assert_int_equal(sx_compute_hull(pts, 1, SX_WELD_TOLERANCE, &h), SX_ERR_DEGENERATE);
    assert_int_equal(sx_compute_hull(pts, 2, SX_WELD_TOLERANCE, &h), SX_ERR_DEGENERATE);
    for (i = 0; i < 6; ++i)
        dup[i] = sx_v2(SX_R(3.0), SX_R(-2.0));
    assert_int_equal(sx_compute_hull(dup, 6, SX_WELD_TOLERANCE, &h), SX_ERR_DEGENERATE);
    assert_int_equal(sx_compute_hull(dup, 6, SX_R(0.0), &h), SX_ERR_DEGENERATE);
    for (i = 0; i < 6; ++i)
        dup[i] = sx_v2((sx_real)i, SX_R(2.0) * (sx_real)i - SX_R(1.0));
    assert_int_equal(sx_compute_hull(dup, 6, SX_WELD_TOLERANCE, &h), SX_ERR_DEGENERATE);
    assert_int_equal(sx_compute_hull(dup, 6, SX_R(0.0), &h), SX_ERR_DEGENERATE);
    {
        sx_real bad[3];
        int j, k;
        bad[0] = (sx_real)NAN;
        bad[1] = (sx_real)INFINITY;
        bad[2] = -(sx_real)INFINITY;
        for (j = 0; j < 3; ++j) {
            for (k = 0; k < 4; ++k) {
                sx_vec2 q[4];
                for (i = 0; i < 4; ++i)
                    q[i] = pts[i];
                if (k % 2 == 0)
                    q[k].x = bad[j];
                else
                    q[k].y = bad[j];
                assert_int_equal(sx_compute_hull(q, 4, SX_WELD_TOLERANCE, &h), SX_ERR_NONFINITE);
                assert_int_equal(h.count, 0);
            }
        }
    }
}

static void validate_hull_accepts_convex_ccw_and_refuses_the_rest(void **state) {
    sx_hull h;
    (void)state;
    h.count = 4;
    h.points[0] = sx_v2(0, 0);
    h.points[1] = sx_v2(1, 0);
    h.points[2] = sx_v2(1, 1);
    h.points[3] = sx_v2(0, 1);
    assert_true(sx_validate_hull(&h, SX_WELD_TOLERANCE));
    assert_true(sx_validate_hull(&h, SX_R(0.0)));
    assert_false(sx_validate_hull(NULL, SX_WELD_TOLERANCE));
    assert_false(sx_validate_hull(&h, SX_R(-1.0)));
    assert_false(sx_validate_hull(&h, (sx_real)NAN));
    /* tolerance larger than the square's geometry */
    assert_false(sx_validate_hull(&h, SX_R(2.0)));
    /* clockwise */
    h.points[1] = sx_v2(0, 1);
    h.points[3] = sx_v2(1, 0);
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
    /* reflex vertex */
    h.points[1] = sx_v2(1, 0);
    h.points[2] = sx_v2(SX_R(0.3), SX_R(0.3));
    h.points[3] = sx_v2(0, 1);
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
    /* collinear vertex */
    h.points[2] = sx_v2(SX_R(0.5), SX_R(0.5));
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
    /* nearly collinear: fine at zero tolerance, refused at the weld tolerance */
    h.points[2] = sx_v2(SX_R(0.5) + SX_R(0.25) * SX_WELD_TOLERANCE,
                        SX_R(0.5) + SX_R(0.25) * SX_WELD_TOLERANCE);
    assert_true(sx_validate_hull(&h, SX_R(0.0)));
    assert_false(sx_validate_hull(&h, SX_WELD_TOLERANCE));
    /* coincident points */
    h.points[2] = sx_v2(1, 0);
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
    /* a pentagram: every turn is left, but it winds twice */
    {
        int i;
        h.count = 5;
        for (i = 0; i < 5; ++i)
            h.points[i] = rotated(1.0, 4.0 * 3.14159265358979 * i / 5.0, 0.0, 0.0);
        assert_false(sx_validate_hull(&h, SX_R(0.0)));
    }
    h.count = 2;
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
    h.count = SX_MAX_POLYGON_VERTICES + 1;
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
    h.count = 3;
    h.points[0] = sx_v2(0, 0);
    h.points[1] = sx_v2(1, 0);
    h.points[2] = sx_v2(0, (sx_real)NAN);
    assert_false(sx_validate_hull(&h, SX_R(0.0)));
}

static void polygon_shape_reports_every_error_and_leaves_out_unchanged(void **state) {
    sx_vec2 pts[SX_MAX_POLYGON_VERTICES + 4];
    sx_shape s, keep;
    int i;
    (void)state;
    keep = sx_circle_shape(sx_v2(7, 7), 3);
    s = keep;
    pts[0] = sx_v2(0, 0);
    pts[1] = sx_v2(1, 0);
    pts[2] = sx_v2(0, 1);
    assert_int_equal(sx_polygon_shape(NULL, 3, 0, &s), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_shape(pts, 3, 0, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_shape(pts, -3, 0, &s), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_shape(pts, 0, 0, &s), SX_ERR_DEGENERATE);
    assert_int_equal(sx_polygon_shape(pts, 1, 0, &s), SX_ERR_DEGENERATE);
    assert_int_equal(sx_polygon_shape(pts, 2, 0, &s), SX_ERR_DEGENERATE);
    assert_int_equal(sx_polygon_shape(pts, 3, SX_R(-0.1), &s), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_shape(pts, 3, (sx_real)NAN, &s), SX_ERR_NONFINITE);
    assert_int_equal(sx_polygon_shape(pts, 3, (sx_real)INFINITY, &s), SX_ERR_NONFINITE);
    assert_int_equal(sx_polygon_shape_ex(pts, 3, 0, SX_R(-1.0), &s), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_shape_ex(pts, 3, 0, (sx_real)NAN, &s), SX_ERR_INVALID_ARG);
    pts[1].y = (sx_real)NAN;
    assert_int_equal(sx_polygon_shape(pts, 3, 0, &s), SX_ERR_NONFINITE);
    pts[1].y = (sx_real)INFINITY;
    assert_int_equal(sx_polygon_shape(pts, 3, 0, &s), SX_ERR_NONFINITE);
    pts[1].y = -(sx_real)INFINITY;
    assert_int_equal(sx_polygon_shape(pts, 3, 0, &s), SX_ERR_NONFINITE);
    pts[1] = sx_v2(2, 2); /* collinear: zero area */
    pts[2] = sx_v2(1, 1);
    assert_int_equal(sx_polygon_shape(pts, 3, 0, &s), SX_ERR_DEGENERATE);
    for (i = 0; i < 3; ++i)
        pts[i] = sx_v2(1, 1); /* all duplicates */
    assert_int_equal(sx_polygon_shape(pts, 3, 0, &s), SX_ERR_DEGENERATE);
    for (i = 0; i < SX_MAX_POLYGON_VERTICES + 1; ++i) {
        pts[i] = rotated(1.0, 6.283185307179586 * i / (SX_MAX_POLYGON_VERTICES + 1), 0.0, 0.0);
    }
    assert_int_equal(sx_polygon_shape(pts, SX_MAX_POLYGON_VERTICES + 1, 0, &s), SX_ERR_CAPACITY);
    assert_int_equal(sx_polygon_shape(pts, SX_MAX_POLYGON_VERTICES, 0, &s), SX_OK);
    assert_int_equal(s.u.polygon.count, SX_MAX_POLYGON_VERTICES);
    /* out untouched by every failure above */
    s = keep;
    assert_int_equal(sx_polygon_shape(pts, SX_MAX_POLYGON_VERTICES + 1, 0, &s), SX_ERR_CAPACITY);
    assert_int_equal(s.type, SX_SHAPE_CIRCLE);
    assert_near(s.u.circle.radius, 3, 0);
}

static void
polygon_shape_welds_1e6_edges_by_default_and_keeps_them_with_a_tiny_tolerance(void **state) {
    sx_vec2 pts[5];
    sx_shape s;
    int i;
    (void)state;
    pts[0] = sx_v2(-1, -1);
    pts[1] = sx_v2(1, -1);
    pts[2] = sx_v2(SX_R(1.0) + SX_R(1.0e-6), SX_R(-1.0) + SX_R(1.0e-6));
    pts[3] = sx_v2(1, 1);
    pts[4] = sx_v2(-1, 1);
    assert_int_equal(sx_polygon_shape(pts, 5, 0, &s), SX_OK);
    assert_int_equal(s.u.polygon.count, 4);
    assert_int_equal(sx_shape_validate(&s), SX_OK);
    assert_int_equal(sx_polygon_shape_ex(pts, 5, 0, SX_R(1.0e-9), &s), SX_OK);
    assert_int_equal(s.u.polygon.count, 5);
    assert_int_equal(sx_shape_validate(&s), SX_OK);
    for (i = 0; i < 5; ++i)
        assert_true(sx_is_normalized(s.u.polygon.normals[i]));
    /* the tiny edge's outward normal points down-right */
    assert_true(s.u.polygon.normals[1].x > SX_R(0.5) && s.u.polygon.normals[1].y < SX_R(-0.5));
}

static void polygon_shape_far_from_origin_keeps_unit_size_shapes(void **state) {
    sx_test_rng rng = sx_test_rng_make(0x5eed0006u);
    int trial;
    (void)state;
    for (trial = 0; trial < 200; ++trial) {
        sx_vec2 pts[6];
        sx_shape s;
        double cx = 1.0e5 * (2.0 * sx_test_rng_unit(&rng) - 1.0);
        double cy = 1.0e5 * (2.0 * sx_test_rng_unit(&rng) - 1.0);
        int i;
        pts[0] = sx_v2((sx_real)cx, (sx_real)cy);
        pts[1] = sx_v2((sx_real)(cx + 1.0), (sx_real)cy);
        pts[2] = sx_v2((sx_real)(cx + 1.0), (sx_real)(cy + 1.0));
        pts[3] = sx_v2((sx_real)cx, (sx_real)(cy + 1.0));
        pts[4] = sx_v2((sx_real)(cx + 0.5), (sx_real)(cy + 0.5)); /* inside */
        pts[5] = pts[2];                                          /* duplicate */
        assert_int_equal(sx_polygon_shape(pts, 6, 0, &s), SX_OK);
        assert_int_equal(s.u.polygon.count, 4);
        assert_int_equal(sx_shape_validate(&s), SX_OK);
        /* centroid to within the coordinates' own resolution */
        assert_near(s.u.polygon.centroid.x, cx + 0.5, 0.02);
        assert_near(s.u.polygon.centroid.y, cy + 0.5, 0.02);
        for (i = 0; i < 4; ++i)
            assert_true(sx_is_normalized(s.u.polygon.normals[i]));
    }
}

static void polygon_shape_computes_normals_and_centroid(void **state) {
    sx_vec2 pts[3];
    sx_shape s;
    const sx_polygon *p;
    (void)state;
    pts[0] = sx_v2(0, 0);
    pts[1] = sx_v2(3, 0);
    pts[2] = sx_v2(0, 3);
    assert_int_equal(sx_polygon_shape(pts, 3, SX_R(0.25), &s), SX_OK);
    p = &s.u.polygon;
    assert_int_equal(s.type, SX_SHAPE_POLYGON);
    assert_int_equal(p->count, 3);
    assert_near(p->radius, 0.25, 0);
    assert_vec2_near(p->centroid, sx_v2(1, 1), SX_TEST_EPS);
    assert_vec2_near(p->normals[0], sx_v2(0, -1), SX_TEST_EPS);
    assert_vec2_near(p->normals[1], sx_v2(SX_R(0.70710678118654752), SX_R(0.70710678118654752)),
                     SX_TEST_EPS);
    assert_vec2_near(p->normals[2], sx_v2(-1, 0), SX_TEST_EPS);
}

static void polygon_from_hull_refuses_what_is_not_a_ccw_convex_hull(void **state) {
    sx_hull h;
    sx_shape s;
    (void)state;
    h.count = 4;
    h.points[0] = sx_v2(0, 0);
    h.points[1] = sx_v2(1, 0);
    h.points[2] = sx_v2(1, 1);
    h.points[3] = sx_v2(0, 1);
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_OK);
    assert_int_equal(sx_polygon_from_hull(NULL, 0, &s), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_from_hull(&h, 0, NULL), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_from_hull(&h, SX_R(-1.0), &s), SX_ERR_INVALID_ARG);
    assert_int_equal(sx_polygon_from_hull(&h, (sx_real)NAN, &s), SX_ERR_NONFINITE);
    h.count = 2;
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_ERR_INVALID_ARG);
    h.count = SX_MAX_POLYGON_VERTICES + 1;
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_ERR_INVALID_ARG);
    h.count = 4;
    h.points[1] = sx_v2(0, 1); /* clockwise */
    h.points[3] = sx_v2(1, 0);
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_ERR_INVALID_ARG);
    h.points[1] = sx_v2(1, 0); /* reflex */
    h.points[2] = sx_v2(SX_R(0.2), SX_R(0.2));
    h.points[3] = sx_v2(0, 1);
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_ERR_INVALID_ARG);
    h.points[2] = sx_v2(1, (sx_real)INFINITY);
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_ERR_NONFINITE);
    h.points[0] = sx_v2(0, 0); /* collinear: zero area */
    h.points[1] = sx_v2(1, 1);
    h.points[2] = sx_v2(2, 2);
    h.points[3] = sx_v2(3, 3);
    assert_int_equal(sx_polygon_from_hull(&h, 0, &s), SX_ERR_DEGENERATE);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hull_of_regular_polygon_plus_interior_points_is_the_polygon),
        cmocka_unit_test(hull_of_uniform_clouds_has_hull_properties_or_reports_capacity),
        cmocka_unit_test(hull_of_points_on_a_circle_beyond_capacity_is_refused_not_truncated),
        cmocka_unit_test(hull_of_lattice_and_edge_points_keeps_only_the_corners),
        cmocka_unit_test(hull_of_near_collinear_and_clustered_clouds_is_degenerate),
        cmocka_unit_test(hull_of_a_dense_nearly_straight_arc_is_pruned_not_refused),
        cmocka_unit_test(hull_of_a_huge_exact_hull_is_refused_in_bounded_time),
        cmocka_unit_test(hull_of_jittered_clusters_welds_each_cluster_to_one_vertex),
        cmocka_unit_test(
            hull_of_millimetre_hexagon_is_welded_by_default_and_kept_with_a_small_tolerance),
        cmocka_unit_test(hull_of_grid_snapped_clouds_with_any_tolerance_is_valid_or_refused),
        cmocka_unit_test(hull_of_a_near_collinear_run_keeps_its_far_end),
        cmocka_unit_test(hull_of_a_run_of_exact_tiny_edges_keeps_the_far_corner),
        cmocka_unit_test(hull_orders_near_points_seen_from_a_far_vertex),
        cmocka_unit_test(hull_starts_at_lowest_x_then_lowest_y_and_runs_ccw),
        cmocka_unit_test(hull_welds_duplicates_and_near_duplicates),
        cmocka_unit_test(hull_with_zero_tolerance_keeps_tiny_edges_but_welds_exact_duplicates),
        cmocka_unit_test(compute_hull_reports_every_error),
        cmocka_unit_test(validate_hull_accepts_convex_ccw_and_refuses_the_rest),
        cmocka_unit_test(polygon_shape_reports_every_error_and_leaves_out_unchanged),
        cmocka_unit_test(
            polygon_shape_welds_1e6_edges_by_default_and_keeps_them_with_a_tiny_tolerance),
        cmocka_unit_test(polygon_shape_far_from_origin_keeps_unit_size_shapes),
        cmocka_unit_test(polygon_shape_computes_normals_and_centroid),
        cmocka_unit_test(polygon_from_hull_refuses_what_is_not_a_ccw_convex_hull),
    };
    return cmocka_run_group_tests_name("hull", tests, sx_test_group_setup, sx_test_group_teardown);
}
