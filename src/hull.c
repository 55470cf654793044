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
 * rounding-displaced points sit just outside the hull already built. And
 * every loop is bounded. Welding happens during the wrap (points within the
 * tolerance of the current vertex are not candidates); near-collinear
 * vertices are pruned afterwards, closest-to-collinear first, and also
 * during the wrap whenever its fixed buffer fills up, so a long, nearly
 * straight run of points does not overflow it. SX_ERR_CAPACITY comes only
 * when the vertices that survive pruning are too many: nothing is dropped
 * silently. */
#include "wide.h"

/* Room for the raw wrap. The exact hull of a cloud whose tolerance-pruned
 * hull fits SX_MAX_POLYGON_VERTICES can carry extra vertices that are
 * collinear only within the tolerance (rounding noise on an edge, a dense
 * nearly straight arc); they are pruned from the chain whenever the buffer
 * fills, so its size only sets how often that happens. */
#define SX_HULL_WRAP_CAPACITY (4 * SX_MAX_POLYGON_VERTICES + 32)

static void hull_clear(sx_hull *out) {
    int i;
    out->count = 0;
    for (i = 0; i < SX_MAX_POLYGON_VERTICES; ++i)
        out->points[i] = sx_v2_zero();
}

/* True if a comes before b in the (x, then y) order the hull starts from. */
static bool lower_left(sx_vec2 a, sx_vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

/* One gift-wrapping step from points[p], where d is the direction of the
 * previous edge. Returns the next hull point, or -1 when no point lies ahead
 * (the cloud is collinear, or everything left is welded to p). */
static int wrap_step(const sx_vec2 *points, int count, int p, sx_wvec2 d, sx_wide tol2,
                     sx_wvec2 *edge) {
    int q = -1, r;
    sx_wvec2 qe = sx_wv(SX_W(0.0), SX_W(0.0));
    for (r = 0; r < count; ++r) {
        sx_wvec2 e = sx_wdiff(points[r], points[p]);
        sx_wide side, c;
        if (sx_wdot(e, e) <= tol2) continue; /* welded to p (and p itself) */
        side = sx_wcross(d, e);
        /* Only points ahead of the previous edge: this keeps every candidate
         * within a half-turn of each other, so the cross product orders them. */
        if (side < SX_W(0.0) || (side == SX_W(0.0) && sx_wdot(d, e) <= SX_W(0.0))) continue;
        if (q < 0) {
            q = r;
            qe = e;
            continue;
        }
        c = sx_wcross(qe, e);
        if (c < SX_W(0.0) || (c == SX_W(0.0) && sx_wdot(e, e) > sx_wdot(qe, qe))) {
            q = r;
            qe = e;
        }
    }
    *edge = qe;
    return q;
}

static void remove_at(sx_vec2 *v, int *n, int i) {
    int k;
    for (k = i; k + 1 < *n; ++k)
        v[k] = v[k + 1];
    --*n;
}

/* The cloud being wrapped, with its tolerance. */
typedef struct hull_cloud {
    const sx_vec2 *points;
    int count;
    sx_wide tol, tol2;
} hull_cloud;

/* How far the farthest input point lies outside the chord a -> b when it
 * replaces the hull vertices between a and b. Only points in the cap the
 * chord cuts off can lie on its right, so scanning every point is exact, and
 * it stays exact however many vertices were pruned before. */
static sx_wide chord_deviation(const hull_cloud *c, sx_vec2 a, sx_vec2 b) {
    sx_wvec2 e = sx_wdiff(b, a);
    sx_wide worst = SX_W(0.0), len = sx_wsqrt(sx_wdot(e, e));
    int i;
    for (i = 0; i < c->count; ++i) {
        sx_wide out = -sx_wcross(e, sx_wdiff(c->points[i], a));
        if (out > worst) worst = out;
    }
    return len > SX_W(0.0) ? worst / len : worst;
}

/* The input point farthest outside the chord a -> b (the apex of the cap it
 * cuts off, so a hull vertex), and that distance in *dist. */
static sx_vec2 cap_apex(const hull_cloud *c, sx_vec2 a, sx_vec2 b, sx_wide *dist) {
    sx_wvec2 e = sx_wdiff(b, a);
    sx_wide worst = SX_W(0.0), len = sx_wsqrt(sx_wdot(e, e));
    sx_vec2 apex = a;
    int i;
    for (i = 0; i < c->count; ++i) {
        sx_wide out = -sx_wcross(e, sx_wdiff(c->points[i], a));
        if (out > worst) {
            worst = out;
            apex = c->points[i];
        }
    }
    *dist = len > SX_W(0.0) ? worst / len : SX_W(0.0);
    return apex;
}

/* Welds consecutive vertices within the tolerance and drops vertices within
 * the tolerance of the line through their neighbours, one at a time.
 * Phase 0 makes only drops that leave every input point within the
 * tolerance of the hull, the one that moves the hull least first (dropping
 * the most collinear vertex first instead lets small deviations add up along
 * a dense, slightly curved run). Phase 1 (closed loops) handles the
 * collinear vertices phase 0 had to keep, most collinear first: such a
 * vertex is moved to the apex of the cap its neighbours' chord cuts off when
 * that makes it stand out by more than the tolerance and keeps every point
 * within it; otherwise it is dropped anyway, so the hull never has a
 * collinear triple, and only then can points of a curved run lie up to about
 * twice the tolerance outside. Phase 2, a last resort after too many moves,
 * only drops. A closed loop stops at fewer than 3 vertices; an open chain
 * (the wrap so far) never moves its ends, so the wrap can go on from its
 * last vertex. */
static void prune(const hull_cloud *c, sx_vec2 *v, int *n, bool closed) {
    int iter, phase = 0, moves = 0;
    for (iter = 0; iter < 6 * SX_HULL_WRAP_CAPACITY + 4 && *n >= 3; ++iter) {
        int i, best = -1, pairs = closed ? *n : *n - 1;
        int lo = closed ? 0 : 1, hi = closed ? *n : *n - 1;
        sx_wide best_key = SX_W(0.0);
        sx_vec2 prev, next;
        for (i = 0; i < pairs; ++i) {
            sx_wvec2 e = sx_wdiff(v[(i + 1) % *n], v[i]);
            if (sx_wdot(e, e) <= c->tol2) break;
        }
        if (i < pairs) {
            /* Keep the earlier one, except where that would move index 0
             * (closed) or the chain's last vertex (open). */
            int drop = (closed ? i + 1 < *n : i + 1 < *n - 1) ? i + 1 : i;
            if (drop > 0) {
                remove_at(v, n, drop);
                continue;
            }
        }
        for (i = lo; i < hi; ++i) {
            sx_wide key;
            prev = v[(i + *n - 1) % *n];
            next = v[(i + 1) % *n];
            key = sx_wline_distance(next, prev, v[i]); /* > 0: convex */
            if (key > c->tol) continue;
            if (phase == 0) {
                key = chord_deviation(c, prev, next);
                if (key > c->tol) continue;
            }
            if (best < 0 || key < best_key) {
                best = i;
                best_key = key;
            }
        }
        if (best < 0) {
            if (!closed || phase > 0) return;
            phase = 1;
            continue;
        }
        prev = v[(best + *n - 1) % *n];
        next = v[(best + 1) % *n];
        if (phase == 1) {
            sx_wide height;
            sx_vec2 apex = cap_apex(c, prev, next, &height);
            sx_wvec2 ea = sx_wdiff(apex, prev), eb = sx_wdiff(next, apex);
            if (height > c->tol && sx_wdot(ea, ea) > c->tol2 && sx_wdot(eb, eb) > c->tol2 &&
                chord_deviation(c, prev, apex) <= c->tol &&
                chord_deviation(c, apex, next) <= c->tol) {
                v[best] = apex;
                if (++moves >= SX_HULL_WRAP_CAPACITY) phase = 2;
                continue;
            }
        }
        remove_at(v, n, best);
    }
}

sx_status sx_compute_hull(const sx_vec2 *points, int count, sx_real weld_tolerance, sx_hull *out) {
    sx_vec2 raw[SX_HULL_WRAP_CAPACITY];
    hull_cloud cloud;
    sx_wvec2 d, edge;
    sx_wide tol, tol2, area2 = SX_W(0.0);
    int i, n, start, p, first;
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
    tol = (sx_wide)weld_tolerance;
    tol2 = tol * tol;
    cloud.points = points;
    cloud.count = count;
    cloud.tol = tol;
    cloud.tol2 = tol2;

    start = 0;
    for (i = 1; i < count; ++i) {
        if (lower_left(points[i], points[start])) start = i;
    }
    /* Arriving at the lowest-left point from above: every other point is
     * ahead of this virtual downward edge. */
    d = sx_wv(SX_W(0.0), SX_W(-1.0));
    raw[0] = points[start];
    n = 1;
    p = start;
    for (;;) {
        int q = wrap_step(points, count, p, d, tol2, &edge);
        sx_wvec2 back;
        if (q < 0) break;
        back = sx_wdiff(points[q], points[start]);
        if (sx_wdot(back, back) <= tol2) break; /* closed the loop */
        if (n == SX_HULL_WRAP_CAPACITY) {
            /* Full: make room by pruning the chain built so far (a long run
             * of nearly collinear points); refuse only if nothing goes. */
            prune(&cloud, raw, &n, false);
            if (n == SX_HULL_WRAP_CAPACITY) return SX_ERR_CAPACITY;
        }
        raw[n++] = points[q];
        d = edge;
        p = q;
    }

    prune(&cloud, raw, &n, true);
    if (n < 3) return SX_ERR_DEGENERATE;
    if (n > SX_MAX_POLYGON_VERTICES) return SX_ERR_CAPACITY;

    first = 0;
    for (i = 1; i < n; ++i) {
        if (lower_left(raw[i], raw[first])) first = i;
    }
    for (i = 0; i < n; ++i)
        out->points[i] = raw[(first + i) % n];
    for (i = 1; i + 1 < n; ++i) {
        area2 += sx_wcross(sx_wdiff(out->points[i], out->points[0]),
                           sx_wdiff(out->points[i + 1], out->points[0]));
    }
    out->count = n;
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
