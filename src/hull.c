/* sepax — convex hull of a point cloud, without allocating, and its validation.
 *
 * The input is const and may hold any number of points, so the hull is found
 * by gift wrapping (Jarvis march): start at the lowest-x (then lowest-y)
 * point, which is always a hull vertex, and repeatedly take the point that
 * every other point lies to the left of. That needs no scratch proportional
 * to n, only a small fixed buffer for the hull itself, and costs O(n h).
 * Three things make it robust. Orientation tests run in a wider real (see
 * wide.h). Each step only considers points strictly ahead of the previous
 * edge (its open left half-plane, plus the ray straight ahead), so the
 * "more clockwise" comparison is a consistent order even when welded or
 * rounding-displaced points sit just outside the hull already built.
 * Orientations within their rounding noise count as collinear, and such
 * ties are decided the same way in both tests (see wrap_step). And every
 * loop is bounded. Welding happens during the wrap (points within the
 * tolerance of the current vertex are not candidates). The wrap records the
 * exact hull as indices into the input (a fixed buffer of
 * SX_HULL_MAX_RAW_VERTICES); near-collinear vertices are then pruned from
 * it, and because the exact hull stays on record, each drop is checked
 * against every point it would leave outside. SX_ERR_CAPACITY comes only
 * when the vertices that survive pruning are too many (or the exact hull
 * overflows that buffer): nothing is dropped silently. */
#include "wide.h"

/* Room for the exact (welded) hull before pruning, as input indices. A
 * cloud whose pruned hull fits SX_MAX_POLYGON_VERTICES can still have many
 * more exact hull vertices that are collinear only within the tolerance
 * (rounding noise along an edge, a dense and nearly straight arc); 64 per
 * allowed vertex covers such clouds, and bounds the wrap's work at O(n) per
 * recorded vertex. A larger exact hull is answered with SX_ERR_CAPACITY. */
#define SX_HULL_MAX_RAW_VERTICES (64 * SX_MAX_POLYGON_VERTICES)

static void hull_clear(sx_hull *out) {
    int i;
    out->count = 0;
    for (i = 0; i < SX_MAX_POLYGON_VERTICES; ++i)
        out->points[i] = sx_v2_zero();
}

/* True if a comes before b in the (x, then y) order the hull starts from. */
static bool lower_left(sx_vec2 a, sx_vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

static sx_wide wabs(sx_wide x) { return x < SX_W(0.0) ? -x : x; }

/* Bound on the rounding of sx_wcross(a, b), where a and b are differences
 * of input points taken in the wide real. IEEE arithmetic rounds each
 * operation once, relative to its exact result: a difference is off by at
 * most half an ulp of the difference itself (never of the points' magnitudes;
 * a difference that cancels is exact), and so are the two products and their
 * difference. Within this bound the sign of the cross product is noise and
 * the two directions count as collinear; outside it the sign is the exact
 * one. (A bound taken from the points' magnitudes instead made every
 * direction along a run of points 1e-34 apart at x = 15 pure noise: the wrap
 * then stopped at the top of the run and lost a hull vertex 7 m away.) */
static sx_wide cross_noise(sx_wvec2 a, sx_wvec2 b) {
    return SX_W(4.0) * SX_WIDE_EPSILON * (wabs(a.x * b.y) + wabs(a.y * b.x));
}

/* The cross product of u with v, where w = v + k u for some k (the
 * difference of the same input point from another base point on u's line):
 * cross(u, v) == cross(u, w) exactly, but the computed forms round
 * differently, and the one with the smaller noise bound is taken. Far from
 * the points, differences from a distant vertex lose their low bits (1e18 +
 * 1.75 and 1e18 + 12.375 round to the same double), while the difference of
 * the two near points is exact: orientations among near points keep their
 * sign even beside a vertex 1e18 away. */
static sx_wide cross_best(sx_wvec2 u, sx_wvec2 v, sx_wvec2 w, sx_wide *noise) {
    sx_wide nv = cross_noise(u, v), nw = cross_noise(u, w);
    if (nw < nv) {
        *noise = nw;
        return sx_wcross(u, w);
    }
    *noise = nv;
    return sx_wcross(u, v);
}

/* One gift-wrapping step from points[p], where d is the direction of the
 * previous edge. Returns the next hull point, or -1 when no point lies
 * ahead (the cloud is collinear, or everything left is welded to p). Orientations within their
 * rounding noise of zero (cross_noise) are ties, decided the same way in
 * both tests: a point collinear with the previous edge within the noise is
 * ahead when it lies beyond p, and of two candidates collinear with p within
 * the noise the farther one wins. Deciding such a tie by the noise's sign
 * instead can let the wrap jump past a point that lies almost on the
 * previous edge's extension and then exclude it as "behind" that edge,
 * although it lies outside the hull by much more than the noise. */
static int wrap_step(const sx_vec2 *points, int count, int prev, int p, sx_wvec2 d, sx_wide tol2,
                     sx_wvec2 *edge) {
    int q = -1, r;
    sx_wvec2 qe = sx_wv(SX_W(0.0), SX_W(0.0));
    for (r = 0; r < count; ++r) {
        sx_wvec2 e = sx_wdiff(points[r], points[p]);
        sx_wide side, c, noise;
        bool take;
        if (sx_wdot(e, e) <= tol2) continue; /* welded to p (and p itself) */
        /* Only points ahead of the previous edge: this keeps every candidate
         * within a half-turn of each other, so the cross product orders them.
         * A side within the noise counts as 0: ahead only beyond p. */
        if (prev >= 0) {
            side = cross_best(d, e, sx_wdiff(points[r], points[prev]), &noise);
        } else {
            side = sx_wcross(d, e);
            noise = cross_noise(d, e);
        }
        if (side < -noise || (side <= noise && sx_wdot(d, e) <= SX_W(0.0))) continue;
        if (q < 0) {
            q = r;
            qe = e;
            continue;
        }
        c = cross_best(qe, e, sx_wdiff(points[r], points[q]), &noise);
        if (c < -noise) {
            take = true; /* e clockwise of qe */
        } else if (c <= noise) {
            /* Collinear within the noise: the farther point wins the tie of
             * two in the same direction. Opposite directions (possible only
             * within the noise of the previous edge's line) go to the one
             * ahead along it. */
            take = sx_wdot(qe, e) > SX_W(0.0) ? sx_wdot(e, e) > sx_wdot(qe, qe)
                                              : sx_wdot(d, e) > sx_wdot(d, qe);
        } else {
            take = false;
        }
        if (take) {
            q = r;
            qe = e;
        }
    }
    *edge = qe;
    return q;
}

/* The wrap's record and the pruning state: raw[] holds the input indices of
 * the exact hull in CCW order; keep[] the positions in raw[] of the
 * vertices still in the hull, in the same order. */
typedef struct hull_work {
    const sx_vec2 *points;
    int count;
    sx_wide tol, tol2;
    int raw[SX_HULL_MAX_RAW_VERTICES];
    int raw_count;
    int keep[SX_HULL_MAX_RAW_VERTICES];
    int n;
} hull_work;

static sx_vec2 kept(const hull_work *w, int i) { return w->points[w->raw[w->keep[i]]]; }

static void drop_kept(hull_work *w, int i) {
    int k;
    for (k = i; k + 1 < w->n; ++k)
        w->keep[k] = w->keep[k + 1];
    --w->n;
}

/* The exact hull vertex strictly between raw positions a and b (going CCW)
 * that lies farthest outside the chord from one to the other: the apex of
 * the cap the chord cuts off. Every input point outside the chord lies in
 * that cap, so its distance (in *height, 0 if nothing is outside) bounds how
 * far any input point would end up outside the hull. Returns the raw
 * position of the apex, or -1 when the span is empty. */
static int cap_apex(const hull_work *w, int a, int b, sx_wide *height) {
    sx_vec2 pa = w->points[w->raw[a]], pb = w->points[w->raw[b]];
    sx_wvec2 e = sx_wdiff(pb, pa);
    sx_wide best = SX_W(0.0), len = sx_wsqrt(sx_wdot(e, e));
    int k, apex = -1;
    for (k = (a + 1) % w->raw_count; k != b; k = (k + 1) % w->raw_count) {
        sx_wide out = -sx_wcross(e, sx_wdiff(w->points[w->raw[k]], pa));
        if (apex < 0 || out > best) {
            best = out;
            apex = k;
        }
    }
    *height = len > SX_W(0.0) && best > SX_W(0.0) ? best / len : SX_W(0.0);
    return apex;
}

/* True if no input point lies more than the tolerance outside the chord
 * a -> b. The exact hull bounds the cap (cap_apex), but points welded away
 * during the wrap may sit up to the tolerance outside the exact hull, so a
 * drop is confirmed against every point once before it is made. */
static bool chord_keeps_points(const hull_work *w, sx_vec2 a, sx_vec2 b) {
    sx_wvec2 e = sx_wdiff(b, a);
    sx_wide limit = -w->tol * sx_wsqrt(sx_wdot(e, e));
    int i;
    for (i = 0; i < w->count; ++i) {
        if (sx_wcross(e, sx_wdiff(w->points[i], a)) < limit) return false;
    }
    return true;
}

/* Welds consecutive vertices within the tolerance and drops vertices within
 * the tolerance of the line through their neighbours, one at a time.
 * Phase 0 makes only drops that leave every input point within the
 * tolerance of the hull, the one that moves the hull least first (dropping
 * the most collinear vertex first instead lets small deviations add up along
 * a dense, slightly curved run). Phase 1 handles the collinear vertices that
 * phase 0 had to keep, most collinear first: such a vertex moves to the apex
 * of the cap its neighbours' chord cuts off when that makes it stand out by
 * more than the tolerance and keeps every point within it; otherwise it is
 * dropped anyway, so the hull never has a collinear triple, and only then
 * can points of a curved run lie up to about twice the tolerance outside.
 * After too many moves (phase 2) it only drops. Stops below 3 vertices. */
static void prune(hull_work *w) {
    bool rejected[SX_HULL_MAX_RAW_VERTICES];
    int iter, phase = 0, moves = 0;
    for (iter = 0; iter < SX_HULL_MAX_RAW_VERTICES; ++iter)
        rejected[iter] = false;
    for (iter = 0; iter < 8 * SX_HULL_MAX_RAW_VERTICES && w->n >= 3; ++iter) {
        int i, best = -1, pa, pb, apex;
        sx_wide best_key = SX_W(0.0), height;
        for (i = 0; i < w->n; ++i) {
            sx_wvec2 e = sx_wdiff(kept(w, (i + 1) % w->n), kept(w, i));
            if (sx_wdot(e, e) <= w->tol2) break;
        }
        if (i < w->n) {
            drop_kept(w, (i + 1) % w->n);
            for (i = 0; i < w->n; ++i)
                rejected[i] = false;
            continue;
        }
        for (i = 0; i < w->n; ++i) {
            int ia = (i + w->n - 1) % w->n, ib = (i + 1) % w->n;
            /* > 0: a convex corner */
            sx_wide key = sx_wline_distance(kept(w, ib), kept(w, ia), kept(w, i));
            if (key > w->tol) continue;
            if (phase == 0) {
                if (rejected[i]) continue;
                cap_apex(w, w->keep[ia], w->keep[ib], &key);
                if (key > w->tol) continue;
            }
            if (best < 0 || key < best_key) {
                best = i;
                best_key = key;
            }
        }
        if (best < 0) {
            if (phase > 0) return;
            phase = 1;
            continue;
        }
        pa = w->keep[(best + w->n - 1) % w->n];
        pb = w->keep[(best + 1) % w->n];
        if (phase == 0 && !chord_keeps_points(w, w->points[w->raw[pa]], w->points[w->raw[pb]])) {
            rejected[best] = true;
            continue;
        }
        if (phase == 1) {
            apex = cap_apex(w, pa, pb, &height);
            if (apex >= 0 && apex != w->keep[best] && height > w->tol) {
                sx_vec2 va = w->points[w->raw[pa]], vb = w->points[w->raw[pb]];
                sx_vec2 v = w->points[w->raw[apex]];
                sx_wvec2 ea = sx_wdiff(v, va), eb = sx_wdiff(vb, v);
                sx_wide ha, hb;
                cap_apex(w, pa, apex, &ha);
                cap_apex(w, apex, pb, &hb);
                if (sx_wdot(ea, ea) > w->tol2 && sx_wdot(eb, eb) > w->tol2 && ha <= w->tol &&
                    hb <= w->tol) {
                    w->keep[best] = apex;
                    if (++moves >= SX_HULL_MAX_RAW_VERTICES) phase = 2;
                    continue;
                }
            }
        }
        drop_kept(w, best);
        for (i = 0; i < w->n; ++i)
            rejected[i] = false;
    }
}

sx_status sx_compute_hull(const sx_vec2 *points, int count, sx_real weld_tolerance, sx_hull *out) {
    hull_work w;
    sx_wvec2 d, edge;
    sx_wide area2 = SX_W(0.0);
    int i, start, p, prev = -1, first;
    if (out == NULL) return SX_ERR_INVALID_ARG;
    hull_clear(out);
    if (points == NULL || count < 0 || !sx_is_finite(weld_tolerance) ||
        weld_tolerance < SX_R(0.0)) {
        return SX_ERR_INVALID_ARG;
    }
    for (i = 0; i < count; ++i) {
        if (!sx_vec2_is_finite(points[i])) return SX_ERR_NONFINITE;
    }
    if (count < 3) return SX_ERR_DEGENERATE;
    w.points = points;
    w.count = count;
    w.tol = (sx_wide)weld_tolerance;
    w.tol2 = w.tol * w.tol;

    start = 0;
    for (i = 1; i < count; ++i) {
        if (lower_left(points[i], points[start])) start = i;
    }
    /* Arriving at the lowest-left point from above: every other point is
     * ahead of this virtual downward edge. */
    d = sx_wv(SX_W(0.0), SX_W(-1.0));
    w.raw[0] = start;
    w.raw_count = 1;
    p = start;
    for (;;) {
        int q = wrap_step(points, count, prev, p, d, w.tol2, &edge);
        sx_wvec2 back;
        if (q < 0) break;
        back = sx_wdiff(points[q], points[start]);
        if (sx_wdot(back, back) <= w.tol2) break; /* closed the loop */
        if (w.raw_count == SX_HULL_MAX_RAW_VERTICES) return SX_ERR_CAPACITY;
        w.raw[w.raw_count++] = q;
        d = edge;
        prev = p;
        p = q;
    }
    for (i = 0; i < w.raw_count; ++i)
        w.keep[i] = i;
    w.n = w.raw_count;

    prune(&w);
    if (w.n < 3) return SX_ERR_DEGENERATE;
    if (w.n > SX_MAX_POLYGON_VERTICES) return SX_ERR_CAPACITY;

    first = 0;
    for (i = 1; i < w.n; ++i) {
        if (lower_left(kept(&w, i), kept(&w, first))) first = i;
    }
    for (i = 0; i < w.n; ++i)
        out->points[i] = kept(&w, (first + i) % w.n);
    for (i = 1; i + 1 < w.n; ++i) {
        area2 += sx_wcross(sx_wdiff(out->points[i], out->points[0]),
                           sx_wdiff(out->points[i + 1], out->points[0]));
    }
    out->count = w.n;
    /* The wrap is convex by construction and pruning keeps it so; the check
     * is the last guard against a cloud too close to degenerate for the
     * wide arithmetic to order. */
    if (!(area2 > SX_W(0.0)) || !sx_validate_hull(out, weld_tolerance)) {
        hull_clear(out);
        return SX_ERR_DEGENERATE;
    }
    return SX_OK;
}

bool sx_validate_hull(const sx_hull *hull, sx_real tolerance) {
    sx_wide tol, tol2;
    int i, j, n;
    if (hull == NULL || !sx_is_finite(tolerance) || tolerance < SX_R(0.0)) return false;
    n = hull->count;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return false;
    for (i = 0; i < n; ++i) {
        if (!sx_vec2_is_finite(hull->points[i])) return false;
    }
    tol = (sx_wide)tolerance;
    tol2 = tol * tol;
    for (i = 0; i < n; ++i) {
        sx_vec2 a = hull->points[i], b = hull->points[(i + 1) % n];
        sx_vec2 prev = hull->points[(i + n - 1) % n];
        sx_wvec2 e = sx_wdiff(b, a);
        if (!(sx_wdot(e, e) > tol2)) return false;
        if (!(sx_wline_distance(b, prev, a) > tol)) return false; /* convex corner */
        /* Every other vertex strictly left of every edge: convex, CCW and
         * wound once (local left turns alone allow a star that winds twice). */
        for (j = 0; j < n; ++j) {
            if (j == i || j == (i + 1) % n) continue;
            if (!(sx_wcross(e, sx_wdiff(hull->points[j], a)) > SX_W(0.0))) return false;
        }
    }
    return true;
}
