/* sepax fuzzing — concave decomposition and the point-in-outline winding test.
 *
 * Outlines come from the bytes in several forms: arbitrary point lists
 * (NaN, Inf, huge, tiny values through fuzz_input.h), star-shaped outlines
 * (simple by construction) in either winding, orthogonal "skyline" outlines
 * (simple and concave by construction), bow-ties and pentagrams (self-
 * intersecting by construction); then duplicates, collinear midpoints, a
 * scale factor and a far offset may be applied to any of them. Checked:
 *
 *  - statuses: count < 3, non-finite points and a bad tolerance give the
 *    documented errors; a clearly crossing outline (bow-tie, pentagram) is
 *    refused; a simple construction at a sane scale is accepted (SX_OK, or
 *    SX_ERR_CAPACITY with the needed count reported);
 *  - parts: each passes sx_shape_validate (convex, counter-clockwise), radius
 *    0, vertices are input points bit for bit, count within the capacity and
 *    count - 2;
 *  - areas: the part areas sum to the outline area within the cleaning
 *    allowance;
 *  - containment: for sample points (a grid over the bounds, decoded points,
 *    part centroids) farther than a band from every outline edge,
 *    sx_point_in_outline agrees with "inside some part", and no point deep
 *    inside a part is deep inside another (the parts do not overlap);
 *  - sx_point_in_outline is unchanged by a cyclic rotation of the outline
 *    (exactly) and by reversing it (away from the edges), false for NULL,
 *    count < 3 and a non-finite point;
 *  - nothing is allocated (sx_live_bytes unchanged). */
#include "fuzz_input.h"

#define DEC_MAX_POINTS 48
#define DEC_SCRATCH_BYTES 32768

/* How the outline was built: what the status must be. */
enum { DEC_ANY, DEC_SIMPLE, DEC_CROSSING };

/* Rounding allowance at a coordinate scale. */
static double dec_round(double scale) {
    return 4096.0 * (double)SX_REAL_EPSILON * (scale > 1.0 ? scale : 1.0);
}

#ifdef SX_DOUBLE
#define DEC_REAL_MIN DBL_MIN
#else
#define DEC_REAL_MIN ((double)FLT_MIN)
#endif

/* The construction's guarantee is kept only while the rounding at the
 * points' current extent stays far below the feature size. */
static void dec_check_rounding(const sx_vec2 *pts, int count, sx_real unit, int *kind) {
    double extent = (double)fz_extent(pts, count);
    if (!(extent <= (double)SX_HUGE) || !((double)unit > 64.0 * dec_round(extent))) *kind = DEC_ANY;
}

/* Distance from p to the segment a-b, in double. */
static double dec_seg_dist(sx_vec2 a, sx_vec2 b, sx_vec2 p) {
    double ex = (double)b.x - (double)a.x, ey = (double)b.y - (double)a.y;
    double px = (double)p.x - (double)a.x, py = (double)p.y - (double)a.y;
    double ll = ex * ex + ey * ey, t = ll > 0.0 ? (px * ex + py * ey) / ll : 0.0;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    px -= t * ex;
    py -= t * ey;
    return sqrt(px * px + py * py);
}

static double dec_outline_dist(const sx_vec2 *pts, int n, sx_vec2 p) {
    double d = HUGE_VAL;
    int i;
    for (i = 0; i < n; ++i) {
        double e = dec_seg_dist(pts[i], pts[(i + 1) % n], p);
        if (e < d) d = e;
    }
    return d;
}

/* Signed distance of p to a counter-clockwise convex polygon: negative
 * inside (minus the smallest edge-line distance), the distance to the
 * boundary outside (edge-line distances alone understate it beyond an
 * acute vertex). */
static double dec_part_depth(const sx_shape *s, sx_vec2 p) {
    const sx_vec2 *v = s->u.polygon.vertices;
    int n = s->u.polygon.count, i;
    double inside = HUGE_VAL;
    for (i = 0; i < n; ++i) {
        sx_vec2 a = v[i], b = v[(i + 1) % n];
        double ex = (double)b.x - (double)a.x, ey = (double)b.y - (double)a.y;
        double len = sqrt(ex * ex + ey * ey);
        double c = (ex * ((double)p.y - (double)a.y) - ey * ((double)p.x - (double)a.x)) / len;
        if (c < 0.0) return dec_outline_dist(v, n, p);
        if (c < inside) inside = c;
    }
    return -inside;
}

static double dec_signed_area(const sx_vec2 *p, int n, double *perimeter) {
    double a = 0.0, per = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        sx_vec2 u = p[i], v = p[(i + 1) % n];
        a += (double)u.x * (double)v.y - (double)u.y * (double)v.x;
        per += sqrt(((double)v.x - (double)u.x) * ((double)v.x - (double)u.x) +
                    ((double)v.y - (double)u.y) * ((double)v.y - (double)u.y));
    }
    *perimeter = per;
    return 0.5 * a;
}

/* Builds the outline; *kind says what the construction guarantees and
 * *unit its feature size (0 when unknown). The points round at every
 * extent they pass through, not only at the last one (a bow-tie moved out
 * to 3e38 and back to the origin comes back as points on a line), so a
 * translation or scale whose rounding is not far below the feature size
 * drops the guarantee there and then. */
static int dec_outline(fz_reader *r, sx_vec2 *pts, int *kind, sx_real *unit, bool *rounded) {
    uint8_t mode = fz_u8(r);
    int count = 0, i;
    *kind = DEC_ANY;
    *unit = SX_R(0.0);
    *rounded = false;
    switch (mode % 6u) {
    case 0:
    case 1: count = fz_points(r, pts, FZ_MAX_POINTS); break;
    case 2: { /* star-shaped around the origin: simple */
        bool cw = fz_u8(r) % 2u;
        count = 3 + (int)(fz_u8(r) % (FZ_MAX_POINTS - 2));
        for (i = 0; i < count; ++i) {
            int k = cw ? count - 1 - i : i;
            sx_real a = SX_R(2.0) * SX_PI * (sx_real)k / (sx_real)count;
            sx_real rad = SX_R(0.25) + (sx_real)fz_u8(r) / SX_R(64.0);
            pts[i] = sx_v2(rad * sx_cos(a), rad * sx_sin(a));
        }
        *kind = DEC_SIMPLE;
        *unit = SX_R(0.25);
        break;
    }
    case 3: { /* skyline: columns of decoded heights over a flat base */
        int cols = 1 + (int)(fz_u8(r) % 10u);
        bool cw = fz_u8(r) % 2u;
        pts[count++] = sx_v2(SX_R(0.0), SX_R(0.0));
        pts[count++] = sx_v2((sx_real)cols, SX_R(0.0));
        for (i = cols; i > 0; --i) {
            sx_real h = SX_R(0.25) * (sx_real)(1 + fz_u8(r) % 16u);
            pts[count++] = sx_v2((sx_real)i, h);
            pts[count++] = sx_v2((sx_real)(i - 1), h);
        }
        if (cw) {
            for (i = 0; i < count / 2; ++i) {
                sx_vec2 t = pts[i];
                pts[i] = pts[count - 1 - i];
                pts[count - 1 - i] = t;
            }
        }
        *kind = DEC_SIMPLE;
        *unit = SX_R(0.25);
        break;
    }
    case 4: { /* bow-tie: two edges cross in the middle */
        sx_real s = SX_R(0.25) + (sx_real)fz_u8(r) / SX_R(16.0);
        pts[0] = sx_v2(SX_R(0.0), SX_R(0.0));
        pts[1] = sx_v2(s, s);
        pts[2] = sx_v2(s, SX_R(0.0));
        pts[3] = sx_v2(SX_R(0.0), s);
        count = 4;
        *kind = DEC_CROSSING;
        *unit = SX_R(0.25) * s;
        break;
    }
    default: { /* pentagram {5/2} */
        sx_real rad = SX_R(0.25) + (sx_real)fz_u8(r) / SX_R(16.0);
        for (i = 0; i < 5; ++i) {
            sx_real a = SX_R(2.0) * SX_PI * (sx_real)(2 * i % 5) / SX_R(5.0);
            pts[i] = sx_v2(rad * sx_cos(a), rad * sx_sin(a));
        }
        count = 5;
        *kind = DEC_CROSSING;
        *unit = SX_R(0.25) * rad;
        break;
    }
    }
    /* Modifiers: repeated points, collinear midpoints, scale, offset, a
     * replaced point. Repeats and midpoints keep the construction's kind. */
    while (count > 0 && count < DEC_MAX_POINTS - 1) {
        uint8_t op = fz_u8(r);
        int at = (int)(fz_u8(r) % (unsigned)count);
        if (op % 8u == 0u) { /* duplicate a point */
            for (i = count; i > at; --i)
                pts[i] = pts[i - 1];
            ++count;
        } else if (op % 8u == 1u) { /* insert the midpoint after it */
            sx_vec2 a = pts[at], b = pts[(at + 1) % count];
            sx_vec2 m = sx_v2(SX_R(0.5) * a.x + SX_R(0.5) * b.x, SX_R(0.5) * a.y + SX_R(0.5) * b.y);
            for (i = count; i > at + 1; --i)
                pts[i] = pts[i - 1];
            pts[at + 1] = m;
            ++count;
            /* a rounded midpoint is within rounding of the edge, and
             * midpoints of midpoints end up a few ulps apart in a zigzag
             * that may touch itself: simple only once the cleaning welds
             * them (see `sane`) */
            *rounded = true;
        } else if (op % 8u == 2u) { /* scale by a decoded factor */
            sx_real f = fz_real(r);
            for (i = 0; i < count; ++i)
                pts[i] = sx_v2(pts[i].x * f, pts[i].y * f);
            *unit = *unit * sx_absr(f);
            if (!(f != SX_R(0.0) && sx_is_finite(f))) *kind = DEC_ANY;
            /* Near the bottom of the range the coordinates lose bits (a
             * scale into the denormals and back up flattens the shape). */
            if (!((double)*unit > 1e6 * DEC_REAL_MIN)) *kind = DEC_ANY;
            dec_check_rounding(pts, count, *unit, kind);
        } else if (op % 8u == 3u) { /* translate by a decoded offset */
            sx_vec2 o = fz_vec2(r);
            for (i = 0; i < count; ++i)
                pts[i] = sx_add(pts[i], o);
            /* the translated points round at their new extent: the kind
             * survives only where that rounding is far below the feature
             * size (the caller checks the final extent the same way) */
            dec_check_rounding(pts, count, *unit, kind);
        } else if (op % 8u == 4u) { /* replace one point by a decoded one */
            pts[at] = fz_vec2(r);
            *kind = DEC_ANY;
        } else {
            break;
        }
    }
    return count;
}

static void dec_check_outline_test(const sx_vec2 *pts, int n, sx_vec2 p, double band) {
    sx_vec2 rot[DEC_MAX_POINTS], rev[DEC_MAX_POINTS];
    bool in = sx_point_in_outline(pts, n, p);
    int i;
    if (n < 1) return;
    for (i = 0; i < n; ++i) {
        rot[i] = pts[(i + 1) % n];
        rev[i] = pts[n - 1 - i];
    }
    FZ_CHECK(sx_point_in_outline(rot, n, p) == in);
    if (fz_all_finite(pts, n) && sx_vec2_is_finite(p) && (double)fz_extent(pts, n) <= 1e100 &&
        (double)fz_extent(&p, 1) <= 1e100 && dec_outline_dist(pts, n, p) > band)
        FZ_CHECK(sx_point_in_outline(rev, n, p) == in);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static unsigned char scratch[DEC_SCRATCH_BYTES];
    fz_reader r = fz_reader_make(data, size);
    sx_vec2 pts[DEC_MAX_POINTS], samples[40];
    sx_shape parts[DEC_MAX_POINTS];
    int kind, count, capacity, part_count = -7, tri = -7, i, j, ns = 0;
    sx_real unit, tol;
    size_t live = sx_live_bytes(), need;
    uint8_t mode;
    sx_status st;
    double scale, band;
    bool finite, sane, rounded;

    count = dec_outline(&r, pts, &kind, &unit, &rounded);
    capacity = 1 + (int)(fz_u8(&r) % DEC_MAX_POINTS);
    mode = fz_u8(&r);
    tol = mode % 4u == 1u ? fz_real(&r) : (mode % 4u == 2u ? SX_R(0.0) : SX_WELD_TOLERANCE);
    need = sx_decompose_scratch_bytes(count);
    FZ_CHECK(need <= sizeof scratch);
    st = sx_decompose_polygon_ex(pts, count, tol, scratch, sizeof scratch, parts, capacity,
                                 &part_count, &tri);
    FZ_CHECK(fz_status_known(st));
    FZ_CHECK(sx_live_bytes() == live);
#ifdef DEC_DEBUG
    fprintf(stderr, "kind %d unit %g tol %g status %d parts %d\n", kind, (double)unit, (double)tol,
            (int)st, part_count);
    for (i = 0; i < count; ++i)
        fprintf(stderr, "  (%.9g, %.9g)\n", (double)pts[i].x, (double)pts[i].y);
#endif

    finite = fz_all_finite(pts, count);
    scale = (double)fz_extent(pts, count);
    band = 8.0 * (double)(sx_is_finite(tol) ? sx_absr(tol) : SX_R(0.0)) + dec_round(scale);
    /* A construction keeps its guarantee when its features are far larger
     * than the tolerance and the rounding at its extent. */
    sane = finite && scale <= (double)SX_HUGE && (double)unit > 64.0 * band &&
           (!rounded || (double)tol > 64.0 * dec_round(scale));

    if (count < 3)
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else if (!(tol >= SX_R(0.0)) || !sx_is_finite(tol))
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else if (!finite)
        FZ_CHECK(st == SX_ERR_NONFINITE);
    else if (sane && kind == DEC_CROSSING)
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else if (sane && kind == DEC_SIMPLE)
        FZ_CHECK(st == SX_OK || st == SX_ERR_CAPACITY);

    if (st == SX_ERR_CAPACITY) {
        FZ_CHECK(part_count > capacity && part_count <= count - 2);
        part_count = 0;
    } else if (st != SX_OK) {
        FZ_CHECK(part_count == 0);
    } else {
        FZ_CHECK(part_count >= 1 && part_count <= capacity && part_count <= count - 2);
        FZ_CHECK(tri >= part_count && tri <= count - 2);
    }

    if (st == SX_OK) {
        double sum = 0.0, perimeter, area = fabs(dec_signed_area(pts, count, &perimeter));
        double allowance;
        for (i = 0; i < part_count; ++i) {
            const sx_polygon *poly = &parts[i].u.polygon;
            FZ_CHECK(parts[i].type == SX_SHAPE_POLYGON);
            FZ_CHECK(sx_shape_validate(&parts[i]) == SX_OK);
            FZ_CHECK(poly->radius == SX_R(0.0));
            for (j = 0; j < poly->count; ++j) {
                int k;
                bool found = false;
                for (k = 0; k < count && !found; ++k)
                    found = fz_same_bits(poly->vertices[j], pts[k]);
                FZ_CHECK(found);
            }
            sum += (double)sx_shape_area(&parts[i]);
        }
        /* Cleaning moves the boundary by at most the tolerance (twice, for
         * repeated drops); the rest is rounding of areas at this scale, and
         * areas near the smallest normal sx_real (tiny outlines) underflow. */
        allowance = 2.0 * perimeter * (double)tol + 1e-4 * area +
                    64.0 * (double)count * (double)SX_REAL_EPSILON * scale * scale +
                    1e6 * (sizeof(sx_real) == sizeof(float) ? (double)FLT_MIN : DBL_MIN);
        if (scale <= (double)SX_HUGE) FZ_CHECK(fabs(sum - area) <= allowance);
    }

    /* Sample points: a 5 x 5 grid over the bounds, decoded points, part
     * centroids. */
    if (finite && count >= 3) {
        sx_aabb b;
        b.lower = b.upper = pts[0];
        for (i = 1; i < count; ++i) {
            b.lower = sx_v2(sx_minr(b.lower.x, pts[i].x), sx_minr(b.lower.y, pts[i].y));
            b.upper = sx_v2(sx_maxr(b.upper.x, pts[i].x), sx_maxr(b.upper.y, pts[i].y));
        }
        for (i = 0; i < 5; ++i) {
            for (j = 0; j < 5; ++j) {
                double fx = (0.5 + (double)i) / 5.0, fy = (0.5 + (double)j) / 5.0;
                samples[ns++] = sx_v2(
                    (sx_real)((double)b.lower.x + fx * ((double)b.upper.x - (double)b.lower.x)),
                    (sx_real)((double)b.lower.y + fy * ((double)b.upper.y - (double)b.lower.y)));
            }
        }
    }
    for (i = 0; i < 3; ++i)
        samples[ns++] = fz_vec2(&r);
    for (i = 0; i < part_count && ns < (int)(sizeof samples / sizeof samples[0]); ++i)
        samples[ns++] = parts[i].u.polygon.centroid;

    /* Each point the cleaning drops moves the boundary by at most the
     * tolerance from the outline before the drop: the parts' union is
     * within (dropped + 1) tolerances of the raw outline. */
    if (st == SX_OK) band += 2.0 * (double)tol * (double)(count - 2 - tri + 1);
    for (i = 0; i < ns; ++i) {
        sx_vec2 p = samples[i];
        dec_check_outline_test(pts, count, p, band);
        if (!sx_vec2_is_finite(p)) FZ_CHECK(!sx_point_in_outline(pts, count, p));
        /* (the harness's own double arithmetic overflows near DBL_MAX) */
        if (st == SX_OK && scale <= (double)SX_HUGE && sx_vec2_is_finite(p) &&
            (double)fz_extent(&p, 1) <= 1e100 && dec_outline_dist(pts, count, p) > band) {
            int deep = 0;
            bool in_part = false;
            /* The parts' boundary lies within the band of the outline's, so
             * a point farther than the band from the outline is inside a
             * part (up to rounding) exactly when it is inside the outline;
             * a tolerance of the band itself would count points just
             * outside the outline as inside a part whose boundary moved
             * towards them. */
            for (j = 0; j < part_count; ++j) {
                double d = dec_part_depth(&parts[j], p);
                if (d <= dec_round(scale)) in_part = true;
                if (d < -band) ++deep;
            }
#ifdef DEC_DEBUG
            fprintf(stderr, "sample (%.9g, %.9g) deep %d in_part %d outline %d\n", (double)p.x,
                    (double)p.y, deep, (int)in_part, (int)sx_point_in_outline(pts, count, p));
            for (j = 0; j < part_count; ++j) {
                int k;
                fprintf(stderr, " part %d depth %g:", j, dec_part_depth(&parts[j], p));
                for (k = 0; k < parts[j].u.polygon.count; ++k)
                    fprintf(stderr, " (%.9g, %.9g)", (double)parts[j].u.polygon.vertices[k].x,
                            (double)parts[j].u.polygon.vertices[k].y);
                fprintf(stderr, "\n");
            }
#endif
            FZ_CHECK(deep <= 1);
            FZ_CHECK(in_part == sx_point_in_outline(pts, count, p));
        }
    }
    FZ_CHECK(!sx_point_in_outline(NULL, count, sx_v2_zero()));
    FZ_CHECK(!sx_point_in_outline(pts, count < 3 ? count : 2, sx_v2_zero()));
    FZ_CHECK(sx_live_bytes() == live);
    return 0;
}
