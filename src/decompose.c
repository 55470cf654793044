/* sepax — concave polygons: decomposition of a simple outline into convex
 * parts, and point-in-outline by winding number.
 *
 * The decomposition is ear clipping followed by Hertel-Mehlhorn merging.
 * Ear clipping is simple and robust when its only decisions are orientation
 * signs, and those are taken in the wide real of wide.h (double for float
 * input, where the cross product of coordinate differences is nearly always
 * exact; long double for double input). Among the current ears the one with
 * the shortest new diagonal is clipped first: that cuts long thin regions
 * into strips rather than fans, and strips merge into far fewer convex
 * pieces (a spiral strip of 56 points: 27 parts instead of 35).
 *
 * A triangulation alone gives n - 2 parts; merging removes diagonals
 * between neighbouring pieces while their union stays strictly convex and
 * within SX_MAX_POLYGON_VERTICES. Pieces only grow, so the angle at a
 * diagonal's end points and the vertex count only grow too: a merge refused
 * once stays refused, and one greedy pass over the diagonals is final. The
 * result depends on the order of the pass, so four orders are tried
 * (clipping order, reversed, longest and shortest diagonal first) and the
 * one leaving the fewest pieces is kept. Unconstrained Hertel-Mehlhorn gives
 * at most four times the optimal number of convex parts; the vertex cap can
 * add a few more. Each merged piece is accepted with the very predicate that
 * sx_shape_validate applies (sx_validate_hull at tolerance 0), so every part
 * returned is a valid polygon. A direct optimal decomposition (Keil's
 * O(n r^2) dynamic program) would save parts on some outlines but needs
 * O(n^2) memory; on the test outlines (L, U, star, comb, spiral) the merge
 * already reaches the optimum.
 *
 * Memory: the caller's scratch block, sized by sx_decompose_scratch_bytes,
 * linear in the point count; nothing is allocated. Cost: cleaning, the
 * simplicity test, ear clipping and the merge orders are O(n^2) (about 0.3 s
 * for 4000 points), fine for authored outlines. */
#include "sepax/compound.h"
#include "wide.h"

/* Ints per outline point in the scratch block: prev/next links (2), the
 * triangles (3), the diagonals (4), union-find parents and piece sizes (2),
 * the piece vertex lists (SX_MAX_POLYGON_VERTICES), the merge order. */
#define DECOMP_INTS_PER_POINT (12 + SX_MAX_POLYGON_VERTICES)
/* Number of diagonal orders the merge tries (see merge_pieces). */
#define DECOMP_MERGE_ORDERS 4
/* Slack for aligning the caller's block to the strictest member type. */
#define DECOMP_ALIGN 16

typedef struct decomp_work {
    sx_vec2 *pts;
    int *prev, *next;
    int *tri;                                 /* 3 per triangle */
    int *diag_a, *diag_b, *diag_t1, *diag_t2; /* t1 holds b->a, t2 holds a->b */
    int *parent, *pcount, *pverts;
    int *order; /* diagonal order of a merge pass */
} decomp_work;

size_t sx_decompose_scratch_bytes(int count) {
    size_t per = sizeof(sx_vec2) + (size_t)DECOMP_INTS_PER_POINT * sizeof(int);
    /* the triangle indices (3 per point) stay within an int */
    if (count < 3 || count > SX_DECOMPOSE_MAX_POINTS) return 0;
    if ((size_t)count > ((size_t)-1 - (size_t)DECOMP_ALIGN) / per) return 0;
    return (size_t)count * per + (size_t)DECOMP_ALIGN;
}

static sx_wide orient(sx_vec2 a, sx_vec2 b, sx_vec2 c) {
    return sx_wcross(sx_wdiff(b, a), sx_wdiff(c, a));
}

static int sign_of(sx_wide v) { return v > SX_W(0.0) ? 1 : (v < SX_W(0.0) ? -1 : 0); }

/* c lies in the bounding box of a-b (used once a, b, c are known collinear). */
static bool in_box(sx_vec2 a, sx_vec2 b, sx_vec2 c) {
    return sx_minr(a.x, b.x) <= c.x && c.x <= sx_maxr(a.x, b.x) && sx_minr(a.y, b.y) <= c.y &&
           c.y <= sx_maxr(a.y, b.y);
}

/* Closed segments a-b and c-d share a point (crossing or touching). */
static bool segments_meet(sx_vec2 a, sx_vec2 b, sx_vec2 c, sx_vec2 d) {
    int d1 = sign_of(orient(a, b, c)), d2 = sign_of(orient(a, b, d));
    int d3 = sign_of(orient(c, d, a)), d4 = sign_of(orient(c, d, b));
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    if (d1 == 0 && in_box(a, b, c)) return true;
    if (d2 == 0 && in_box(a, b, d)) return true;
    if (d3 == 0 && in_box(c, d, a)) return true;
    if (d4 == 0 && in_box(c, d, b)) return true;
    return false;
}

/* Every raw point strictly between raw indices from and to (cyclically),
 * except those a dropped spike took with it, lies within tol of the line
 * through a and b. */
static bool run_near_line(const sx_vec2 *raw, int n, const int *spiked, int from, int to, sx_vec2 a,
                          sx_vec2 b, sx_wide tol) {
    int j;
    for (j = (from + 1) % n; j != to; j = (j + 1) % n) {
        sx_wide dist;
        if (spiked[j]) continue;
        dist = sx_wline_distance(a, b, raw[j]);
        if (!(dist <= tol && dist >= -tol)) return false;
    }
    return true;
}

/* Copies the n raw points into pts, then welds consecutive near-duplicates
 * and drops near-collinear points (and zero-width spikes) until nothing
 * changes; returns the points left. Each removal can make a neighbour
 * removable, hence the repeated passes. idx[k] is the raw index of pts[k]
 * (kept points stay in raw order), spiked[j] marks a raw point that went
 * with a dropped spike.
 *
 * A near-collinear point goes only if every raw point the new edge stands
 * for (itself and those dropped before between its two neighbours) lies
 * within the tolerance of the new edge's line. Judged against the current
 * neighbours alone, each drop would be within the tolerance of an outline
 * that earlier drops had already moved, and the moves add up: while the
 * chord grows from a fixed neighbour, the point next to that neighbour stays
 * close to the chord's line however far the chord sags from the curve, so a
 * finely drawn circle would collapse to a quadrilateral. A run of raw points within the
 * tolerance of a line encloses, with its chord, at most the tolerance times
 * the distance that loop travels along the line (the run's length plus the
 * chord's), so these drops move the area by at most twice the tolerance
 * times the perimeter. Welds and spikes are not measured this way: a weld
 * moves a vertex by at most the tolerance onto another raw point, and
 * refusing one would leave two consecutive points closer than the
 * tolerance, which outline_is_simple must call a pinch; a spike's sides are
 * within the tolerance of each other, so its points enclose no area worth
 * keeping and no later edge is measured against them. */
static int clean_outline(const sx_vec2 *raw, int n, sx_vec2 *pts, int *idx, int *spiked,
                         sx_real weld_tolerance) {
    const sx_wide tol = (sx_wide)weld_tolerance;
    bool changed = true;
    int m = n, k;
    for (k = 0; k < n; ++k) {
        pts[k] = raw[k];
        idx[k] = k;
        spiked[k] = 0;
    }
    while (changed && m >= 3) {
        int i = 0;
        changed = false;
        while (i < m && m >= 3) {
            int ipv = (i + m - 1) % m, inx = (i + 1) % m;
            sx_vec2 v = pts[i], nx = pts[inx], pv = pts[ipv];
            sx_wvec2 e = sx_wdiff(nx, v);
            sx_wide dist;
            int drop = -1;
            sx_wvec2 base = sx_wdiff(nx, pv);
            if (sx_wdot(e, e) <= tol * tol) {
                drop = inx;
            } else if (sx_wdot(base, base) <= tol * tol) {
                /* A spike whose two sides return to within the tolerance of
                 * where they left: zero width, so its tip goes (the line
                 * through two such close neighbours has no meaningful
                 * direction, and measuring v against it kept a 0.0128 m wide
                 * spike 1e-117 m wide at its base). */
                drop = i;
                for (k = (idx[ipv] + 1) % n; k != idx[inx]; k = (k + 1) % n)
                    spiked[k] = 1;
            } else {
                dist = sx_wline_distance(pv, nx, v);
                if (dist <= tol && dist >= -tol &&
                    run_near_line(raw, n, spiked, idx[ipv], idx[inx], pv, nx, tol)) {
                    drop = i;
                }
            }
            if (drop < 0) {
                ++i;
                continue;
            }
            for (k = drop; k + 1 < m; ++k) {
                pts[k] = pts[k + 1];
                idx[k] = idx[k + 1];
            }
            --m;
            changed = true;
        }
    }
    return m;
}

/* c lies within tol of the closed segment a-b (wide precision; the squares
 * neither overflow nor underflow the wide real for any finite sx_real). */
static bool near_segment(sx_vec2 a, sx_vec2 b, sx_vec2 c, sx_wide tol) {
    sx_wvec2 e = sx_wdiff(b, a), w = sx_wdiff(c, a), u = sx_wdiff(c, b);
    sx_wide cr;
    if (sx_wdot(w, e) <= SX_W(0.0)) return sx_wdot(w, w) <= tol * tol;
    if (sx_wdot(u, e) >= SX_W(0.0)) return sx_wdot(u, u) <= tol * tol;
    cr = sx_wcross(e, w);
    return cr * cr <= tol * tol * sx_wdot(e, e);
}

/* No two non-adjacent edges of the cleaned outline cross, touch or come
 * within the weld tolerance of each other. The tolerance matters where the
 * outline pinches: two points closer than it that are not consecutive (the
 * cleaning welds consecutive ones only) make the outline visit one place
 * twice, and an exact crossing of edges far smaller than the rounding of
 * their other end points (1e-30 against 1e6) has no reliable sign. */
static bool outline_is_simple(const sx_vec2 *pts, int m, sx_real weld_tolerance) {
    const sx_wide tol = (sx_wide)weld_tolerance;
    int i, j;
    for (i = 0; i < m; ++i) {
        sx_vec2 a = pts[i], b = pts[(i + 1) % m];
        for (j = i + 2; j < m; ++j) {
            sx_vec2 c = pts[j], d = pts[(j + 1) % m];
            if (i == 0 && j == m - 1) continue; /* adjacent through the closing edge */
            if ((sx_wide)sx_maxr(c.x, d.x) + tol < (sx_wide)sx_minr(a.x, b.x) ||
                (sx_wide)sx_maxr(a.x, b.x) + tol < (sx_wide)sx_minr(c.x, d.x) ||
                (sx_wide)sx_maxr(c.y, d.y) + tol < (sx_wide)sx_minr(a.y, b.y) ||
                (sx_wide)sx_maxr(a.y, b.y) + tol < (sx_wide)sx_minr(c.y, d.y)) {
                continue;
            }
            if (segments_meet(a, b, c, d) || near_segment(a, b, c, tol) ||
                near_segment(a, b, d, tol) || near_segment(c, d, a, tol) ||
                near_segment(c, d, b, tol)) {
                return false;
            }
        }
    }
    return true;
}

/* A convex polygon with these vertex indices would pass sx_shape_validate. */
static bool piece_valid(const decomp_work *w, const int *idx, int n, sx_hull *h) {
    int i;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return false;
    for (i = 0; i < n; ++i)
        h->points[i] = w->pts[idx[i]];
    h->count = n;
    return sx_validate_hull(h, SX_R(0.0));
}

/* The convex polygon of the merged piece whose root is triangle t. */
static sx_status piece_polygon(const decomp_work *w, int t, sx_shape *out) {
    sx_hull h;
    const int *idx = w->pverts + (size_t)t * (size_t)SX_MAX_POLYGON_VERTICES;
    /* Merging only kept pieces that validate, so this cannot fail. */
    (void)piece_valid(w, idx, w->pcount[t], &h);
    return sx_polygon_from_hull(&h, SX_R(0.0), out);
}

/* No remaining reflex vertex lies in the closed triangle p-i-nx (a vertex on
 * the diagonal p-nx blocks it too). Convex vertices need no test: if one lay
 * inside, a reflex vertex would too, and this keeps an ear status valid
 * when a convex neighbour is clipped. */
static bool is_ear(const decomp_work *w, int p, int i, int nx) {
    sx_vec2 a = w->pts[p], b = w->pts[i], c = w->pts[nx];
    int v;
    for (v = w->next[nx]; v != p; v = w->next[v]) {
        sx_vec2 q = w->pts[v];
        if ((q.x == a.x && q.y == a.y) || (q.x == c.x && q.y == c.y)) continue;
        if (orient(w->pts[w->prev[v]], q, w->pts[w->next[v]]) > SX_W(0.0)) continue;
        if (orient(a, b, q) >= SX_W(0.0) && orient(b, c, q) >= SX_W(0.0) &&
            orient(c, a, q) >= SX_W(0.0)) {
            return false;
        }
    }
    return true;
}

/* Ear status of vertex i: EAR_STRAIGHT for a straight corner or a spike
 * (removable without losing area), EAR_YES for a clippable ear. */
enum { EAR_NO = 0, EAR_YES = 1, EAR_STRAIGHT = 2 };

static int ear_status(const decomp_work *w, int i) {
    int p = w->prev[i], nx = w->next[i];
    sx_wide o = orient(w->pts[p], w->pts[i], w->pts[nx]);
    if (o == SX_W(0.0)) return EAR_STRAIGHT;
    return o > SX_W(0.0) && is_ear(w, p, i, nx) ? EAR_YES : EAR_NO;
}

static void unlink_vertex(decomp_work *w, int i) {
    w->next[w->prev[i]] = w->next[i];
    w->prev[w->next[i]] = w->prev[i];
}

static void emit_triangle(decomp_work *w, int *nt, int a, int b, int c) {
    w->tri[3 * *nt] = a;
    w->tri[3 * *nt + 1] = b;
    w->tri[3 * *nt + 2] = c;
    ++*nt;
}

/* The remaining ear with the shortest new diagonal, or else a straight
 * corner, or -1. Short diagonals clip the polygon in strips rather than
 * fans, and strips merge into far fewer convex pieces. Straight corners go
 * last: dropping one joins its two edges, and the diagonals that ended there
 * no longer match an edge of the triangle that covers it, so fewer merges
 * are possible. */
static int pick_ear(const decomp_work *w, int start) {
    int v = start, best = -1, straight = -1;
    sx_wide best_len2 = SX_W(0.0);
    do {
        int flag = w->order[v];
        if (flag == EAR_STRAIGHT && straight < 0) straight = v;
        if (flag == EAR_YES) {
            sx_wvec2 e = sx_wdiff(w->pts[w->next[v]], w->pts[w->prev[v]]);
            sx_wide len2 = sx_wdot(e, e);
            if (best < 0 || len2 < best_len2) {
                best = v;
                best_len2 = len2;
            }
        }
        v = w->next[v];
    } while (v != start);
    return best >= 0 ? best : straight;
}

/* Ear clipping of the CCW outline; fills the triangles and the diagonals and
 * returns false when no ear can be found (impossible for a simple polygon
 * with exact signs; kept as a refusal rather than a loop). Ear flags live in
 * w->order until the merge needs it; only the clipped vertex's neighbours
 * change status, except that a neighbour turning convex can unblock others,
 * so a full refresh runs before giving up. O(n^2). */
static bool triangulate(decomp_work *w, int m, int *tri_count, int *diag_count) {
    int remaining = m, start = 0, nt = 0, nd = 0, k;
    sx_hull h;
    for (k = 0; k < m; ++k) {
        w->prev[k] = (k + m - 1) % m;
        w->next[k] = (k + 1) % m;
    }
    for (k = 0; k < m; ++k)
        w->order[k] = ear_status(w, k);
    while (remaining > 3) {
        int i = pick_ear(w, start), p, nx;
        if (i < 0) {
            int v = start;
            do {
                w->order[v] = ear_status(w, v);
                v = w->next[v];
            } while (v != start);
            i = pick_ear(w, start);
            if (i < 0) return false;
        }
        p = w->prev[i];
        nx = w->next[i];
        if (w->order[i] == EAR_YES) {
            int idx[3];
            idx[0] = p;
            idx[1] = i;
            idx[2] = nx;
            /* An ear thinner than its own rounding is dropped, not emitted. */
            if (piece_valid(w, idx, 3, &h)) {
                w->diag_a[nd] = p;
                w->diag_b[nd] = nx;
                w->diag_t1[nd] = nt;
                ++nd;
                emit_triangle(w, &nt, p, i, nx);
            }
        }
        unlink_vertex(w, i);
        --remaining;
        start = nx;
        w->order[p] = ear_status(w, p);
        w->order[nx] = ear_status(w, nx);
    }
    {
        int idx[3];
        idx[0] = w->prev[start];
        idx[1] = start;
        idx[2] = w->next[start];
        if (piece_valid(w, idx, 3, &h)) emit_triangle(w, &nt, idx[0], idx[1], idx[2]);
    }
    *tri_count = nt;
    *diag_count = nd;
    return true;
}

static bool tri_has_edge(const int *t, int a, int b) {
    return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
}

static int find_root(int *parent, int t) {
    while (parent[t] != t) {
        parent[t] = parent[parent[t]];
        t = parent[t];
    }
    return t;
}

/* Tries to merge piece rb (which holds directed edge a->b) into ra (which
 * holds b->a). The union runs a .. b around ra, then b's successors in rb
 * up to a; exactly straight corners are dropped, then the result must be a
 * valid convex polygon within the vertex cap. */
static bool try_merge(decomp_work *w, int ra, int rb, int a, int b) {
    const int cap = SX_MAX_POLYGON_VERTICES;
    int *va = w->pverts + (size_t)ra * (size_t)cap, *vb = w->pverts + (size_t)rb * (size_t)cap;
    int ca = w->pcount[ra], cb = w->pcount[rb];
    int merged[2 * SX_MAX_POLYGON_VERTICES], kept[2 * SX_MAX_POLYGON_VERTICES];
    int ka = -1, kb = -1, n = 0, nk = 0, j;
    sx_hull h;
    for (j = 0; j < ca; ++j)
        if (va[j] == a && va[(j + ca - 1) % ca] == b) ka = j;
    for (j = 0; j < cb; ++j)
        if (vb[j] == b && vb[(j + cb - 1) % cb] == a) kb = j;
    if (ka < 0 || kb < 0) return false;
    for (j = 0; j < ca; ++j)
        merged[n++] = va[(ka + j) % ca];
    for (j = 1; j + 1 < cb; ++j)
        merged[n++] = vb[(kb + j) % cb];
    for (j = 0; j < n; ++j) {
        sx_vec2 pv = w->pts[merged[(j + n - 1) % n]], v = w->pts[merged[j]];
        sx_vec2 nx = w->pts[merged[(j + 1) % n]];
        if (orient(pv, v, nx) == SX_W(0.0) &&
            sx_wdot(sx_wdiff(v, pv), sx_wdiff(nx, v)) > SX_W(0.0)) {
            continue;
        }
        kept[nk++] = merged[j];
    }
    if (!piece_valid(w, kept, nk, &h)) return false;
    for (j = 0; j < nk; ++j)
        va[j] = kept[j];
    w->pcount[ra] = nk;
    w->parent[rb] = ra;
    return true;
}

static sx_wide diag_length2(const decomp_work *w, int d) {
    sx_wvec2 e = sx_wdiff(w->pts[w->diag_b[d]], w->pts[w->diag_a[d]]);
    return sx_wdot(e, e);
}

/* Orders the diagonals for one merge pass: 0 clipping order, 1 reversed,
 * 2 longest first, 3 shortest first (insertion sort: O(n^2) like the rest). */
static void order_diagonals(decomp_work *w, int nd, int strategy) {
    int i, j;
    for (i = 0; i < nd; ++i)
        w->order[i] = strategy == 1 ? nd - 1 - i : i;
    if (strategy < 2) return;
    for (i = 1; i < nd; ++i) {
        int d = w->order[i];
        sx_wide len2 = diag_length2(w, d);
        for (j = i; j > 0; --j) {
            sx_wide other = diag_length2(w, w->order[j - 1]);
            if (strategy == 2 ? !(other < len2) : !(other > len2)) break;
            w->order[j] = w->order[j - 1];
        }
        w->order[j] = d;
    }
}

/* One greedy merge pass in the given diagonal order; returns the number of
 * pieces left. */
static int merge_pass(decomp_work *w, int nt, int nd, int strategy) {
    const int cap = SX_MAX_POLYGON_VERTICES;
    int k, t, pieces = nt;
    for (t = 0; t < nt; ++t) {
        w->parent[t] = t;
        w->pcount[t] = 3;
        for (k = 0; k < 3; ++k)
            w->pverts[(size_t)t * (size_t)cap + (size_t)k] = w->tri[3 * t + k];
    }
    order_diagonals(w, nd, strategy);
    for (k = 0; k < nd; ++k) {
        int d = w->order[k], ra, rb;
        if (w->diag_t2[d] < 0) continue; /* the far side was a dropped sliver */
        ra = find_root(w->parent, w->diag_t1[d]);
        rb = find_root(w->parent, w->diag_t2[d]);
        if (ra != rb && try_merge(w, ra, rb, w->diag_a[d], w->diag_b[d])) --pieces;
    }
    return pieces;
}

/* Greedy merging depends on the order of the diagonals; a few orders are
 * tried (each pass is linear) and the one leaving the fewest pieces is
 * kept. */
static void merge_pieces(decomp_work *w, int nt, int nd) {
    int d, t, strategy, best = 0, best_pieces = nt + 1;
    for (d = 0; d < nd; ++d) {
        int a = w->diag_a[d], b = w->diag_b[d], t2 = -1;
        for (t = w->diag_t1[d] + 1; t < nt && t2 < 0; ++t)
            if (tri_has_edge(w->tri + 3 * t, a, b)) t2 = t;
        w->diag_t2[d] = t2;
    }
    for (strategy = 0; strategy < DECOMP_MERGE_ORDERS; ++strategy) {
        int pieces = merge_pass(w, nt, nd, strategy);
        if (pieces < best_pieces) {
            best_pieces = pieces;
            best = strategy;
        }
    }
    if (best != DECOMP_MERGE_ORDERS - 1) (void)merge_pass(w, nt, nd, best);
}

static void *align_up(void *p) {
    uintptr_t u = (uintptr_t)p;
    u = (u + (uintptr_t)(DECOMP_ALIGN - 1)) & ~(uintptr_t)(DECOMP_ALIGN - 1);
    return (void *)u;
}

sx_status sx_decompose_polygon(const sx_vec2 *points, int count, void *scratch,
                               size_t scratch_bytes, sx_shape *parts, int part_capacity,
                               int *part_count, int *triangle_count) {
    return sx_decompose_polygon_ex(points, count, SX_WELD_TOLERANCE, scratch, scratch_bytes, parts,
                                   part_capacity, part_count, triangle_count);
}

sx_status sx_decompose_polygon_ex(const sx_vec2 *points, int count, sx_real weld_tolerance,
                                  void *scratch, size_t scratch_bytes, sx_shape *parts,
                                  int part_capacity, int *part_count, int *triangle_count) {
    decomp_work w;
    size_t need;
    int m, i, nt = 0, nd = 0, roots = 0;
    int *ints;
    if (part_count != NULL) *part_count = 0;
    if (triangle_count != NULL) *triangle_count = 0;
    if (points == NULL || parts == NULL || part_count == NULL || count < 3) {
        return SX_ERR_INVALID_ARG;
    }
    if (!sx_is_finite(weld_tolerance) || weld_tolerance < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    if (scratch == NULL && scratch_bytes > 0) return SX_ERR_INVALID_ARG;
    need = sx_decompose_scratch_bytes(count);
    if (need == 0 || scratch == NULL || scratch_bytes < need) return SX_ERR_CAPACITY;
    for (i = 0; i < count; ++i) {
        if (!sx_vec2_is_finite(points[i])) return SX_ERR_NONFINITE;
    }

    w.pts = (sx_vec2 *)align_up(scratch);
    ints = (int *)(void *)(w.pts + count);
    w.prev = ints;
    w.next = w.prev + count;
    w.tri = w.next + count;
    w.diag_a = w.tri + 3 * (size_t)count;
    w.diag_b = w.diag_a + count;
    w.diag_t1 = w.diag_b + count;
    w.diag_t2 = w.diag_t1 + count;
    w.parent = w.diag_t2 + count;
    w.pcount = w.parent + count;
    w.pverts = w.pcount + count;
    w.order = w.pverts + (size_t)count * (size_t)SX_MAX_POLYGON_VERTICES;

    /* The links are free until the ear clipping: they hold the raw index of
     * each kept point and the spike marks while the outline is cleaned. */
    m = clean_outline(points, count, w.pts, w.prev, w.next, weld_tolerance);
    if (m < 3) return SX_ERR_DEGENERATE;
    if (!outline_is_simple(w.pts, m, weld_tolerance)) return SX_ERR_INVALID_ARG;
    {
        sx_wide area2 = sx_warea2(w.pts, m);
        if (area2 == SX_W(0.0)) return SX_ERR_DEGENERATE;
        if (area2 < SX_W(0.0)) {
            for (i = 0; i < m / 2; ++i) {
                sx_vec2 t = w.pts[i];
                w.pts[i] = w.pts[m - 1 - i];
                w.pts[m - 1 - i] = t;
            }
        }
    }
    if (!triangulate(&w, m, &nt, &nd) || nt == 0) return SX_ERR_DEGENERATE;
    merge_pieces(&w, nt, nd);
    for (i = 0; i < nt; ++i)
        if (w.parent[i] == i) ++roots;
    if (roots > part_capacity) {
        *part_count = roots;
        return SX_ERR_CAPACITY;
    }
    /* A piece whose mass properties overflow sx_real (an outline some 1e9 m
     * across in the float build) cannot be a valid shape: the whole outline
     * is refused, before any part is written, rather than losing pieces. */
    for (i = 0; i < nt; ++i) {
        sx_shape tmp;
        if (w.parent[i] == i && piece_polygon(&w, i, &tmp) == SX_ERR_NONFINITE) {
            return SX_ERR_NONFINITE;
        }
    }
    roots = 0;
    for (i = 0; i < nt; ++i) {
        if (w.parent[i] == i && piece_polygon(&w, i, &parts[roots]) == SX_OK) ++roots;
    }
    /* Far beyond SX_HUGE every piece can fail sx_polygon_from_hull (its
     * area rounds away): no part is no decomposition. */
    if (roots == 0) return SX_ERR_DEGENERATE;
    *part_count = roots;
    if (triangle_count != NULL) *triangle_count = nt;
    return SX_OK;
}

bool sx_point_in_outline(const sx_vec2 *points, int count, sx_vec2 p) {
    int i, winding = 0;
    if (points == NULL || count < 3 || !sx_vec2_is_finite(p)) return false;
    for (i = 0; i < count; ++i) {
        if (!sx_vec2_is_finite(points[i])) return false;
    }
    for (i = 0; i < count; ++i) {
        sx_vec2 a = points[i], b = points[(i + 1) % count];
        sx_wide o = orient(a, b, p);
        if (o == SX_W(0.0) && in_box(a, b, p)) return true;
        /* Upward crossings with p on the left add one, downward with p on
         * the right subtract one (half-open in y, so vertices count once). */
        if (a.y <= p.y) {
            if (b.y > p.y && o > SX_W(0.0)) ++winding;
        } else if (b.y <= p.y && o < SX_W(0.0)) {
            --winding;
        }
    }
    return winding != 0;
}
