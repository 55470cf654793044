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
 * every loop is bounded: a wrap that would need more than SX_HULL_WRAP_CAPACITY
 * raw vertices stops with SX_ERR_CAPACITY. Welding happens during the wrap
 * (points within the tolerance of the current vertex are not candidates);
 * near-collinear vertices are pruned afterwards, closest-to-collinear first,
 * so nothing depends on the order of the input. */
#include "wide.h"

/* Room for the raw wrap before pruning. The exact hull of a cloud whose
 * tolerance-pruned hull fits SX_MAX_POLYGON_VERTICES can still carry extra
 * vertices that are collinear only within the tolerance (rounding noise on
 * an edge, a dense run of nearly straight points); four per edge plus a
 * margin covers realistic clouds. Beyond it the answer is SX_ERR_CAPACITY. */
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

/* Welds consecutive vertices within the tolerance and drops vertices within
 * the tolerance of the line through their neighbours, one at a time, the
 * most collinear first, until neither applies or fewer than 3 remain. */
static void prune(sx_vec2 *v, int *n, sx_wide tol, sx_wide tol2) {
    int iter;
    for (iter = 0; iter < SX_HULL_WRAP_CAPACITY && *n >= 3; ++iter) {
        int i, best = -1;
        sx_wide best_d = SX_W(0.0);
        for (i = 0; i < *n; ++i) {
            int j = (i + 1) % *n;
            sx_wvec2 e = sx_wdiff(v[j], v[i]);
            if (sx_wdot(e, e) <= tol2) break;
        }
        if (i < *n) {
            /* Keep the earlier one (index 0 stays when the pair wraps). */
            remove_at(v, n, i + 1 < *n ? i + 1 : i);
            continue;
        }
        for (i = 0; i < *n; ++i) {
            sx_vec2 prev = v[(i + *n - 1) % *n], next = v[(i + 1) % *n];
            sx_wide d = sx_wline_distance(next, prev, v[i]); /* > 0: convex */
            if (d <= tol && (best < 0 || d < best_d)) {
                best = i;
                best_d = d;
            }
        }
        if (best < 0) return;
        remove_at(v, n, best);
    }
}

sx_status sx_compute_hull(const sx_vec2 *points, int count, sx_real weld_tolerance, sx_hull *out) {
    sx_vec2 raw[SX_HULL_WRAP_CAPACITY];
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
        if (n == SX_HULL_WRAP_CAPACITY) return SX_ERR_CAPACITY;
        raw[n++] = points[q];
        d = edge;
        p = q;
    }

    prune(raw, &n, tol, tol2);
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
