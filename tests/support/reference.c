/* sepax tests — the independent long-double reference (see reference.h).
 *
 * The idea: two convex rounded shapes A = coreA + disc(ra) and B = coreB +
 * disc(rb) overlap exactly when the origin lies within R = ra + rb of the
 * Minkowski difference D = coreA - coreB, and translating A by t moves D by
 * t. So everything reduces to the distance between the origin and one convex
 * polygon D, which we get by brute force: all pairwise vertex differences,
 * their convex hull (Andrew's monotone chain), then either the nearest hull
 * edge (origin inside: escape through that edge) or the closest point of the
 * hull (origin outside). This shares no step with the library's separating
 * axis code, which is the point of a reference. Long double gives 64-bit
 * mantissas on x86 (and at least double elsewhere), well beyond either sepax
 * build. */
#include "reference.h"

#include <math.h>
#include <stddef.h>

typedef struct ref_pt {
    long double x, y;
} ref_pt;

/* Every pairwise difference of two cores, and the monotone chain's scratch
 * (it holds at most twice the input, plus one). */
#define REF_MAX_DIFF (SX_REF_MAX_CORE * SX_REF_MAX_CORE)
#define REF_MAX_CHAIN (2 * REF_MAX_DIFF + 1)

/* Hull edges shorter than this fraction of the coordinate scale are rounding
 * artefacts (two differences that coincide in exact arithmetic); their
 * normals mean nothing, so they never decide a direction. Long double
 * rounding is near 1e-19 relative: 1e-13 leaves a wide margin and is still
 * far below any tolerance a test asserts. */
#define REF_TINY_EDGE 1e-13L

/* Two hull normals closer than this (the sine of the angle between them) are
 * the same direction: a tie between them is no ambiguity. */
#define REF_SAME_DIRECTION 1e-9L

static long double ref_cross3(ref_pt o, ref_pt a, ref_pt b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

static bool ref_less(ref_pt a, ref_pt b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

/* Convex hull of pts[0..n) (sorted in place) into hull, counter-clockwise
 * from the lowest-x point, collinear points dropped. Returns its vertex
 * count: 1 when every point coincides, 2 when all are collinear. */
static int ref_hull(ref_pt *pts, int n, ref_pt *hull) {
    int i, j, k, m, lower;
    for (i = 1; i < n; ++i) {
        ref_pt p = pts[i];
        for (j = i; j > 0 && ref_less(p, pts[j - 1]); --j)
            pts[j] = pts[j - 1];
        pts[j] = p;
    }
    m = 0;
    for (i = 0; i < n; ++i) {
        if (m == 0 || pts[i].x != pts[m - 1].x || pts[i].y != pts[m - 1].y) pts[m++] = pts[i];
    }
    if (m <= 1) {
        if (m == 1) hull[0] = pts[0];
        return m;
    }
    k = 0;
    for (i = 0; i < m; ++i) {
        while (k >= 2 && ref_cross3(hull[k - 2], hull[k - 1], pts[i]) <= 0.0L)
            --k;
        hull[k++] = pts[i];
    }
    lower = k + 1;
    for (i = m - 2; i >= 0; --i) {
        while (k >= lower && ref_cross3(hull[k - 2], hull[k - 1], pts[i]) <= 0.0L)
            --k;
        hull[k++] = pts[i];
    }
    return k - 1;
}

/* The point of segment p-q closest to the origin. */
static ref_pt ref_closest_on_segment(ref_pt p, ref_pt q) {
    long double ex = q.x - p.x, ey = q.y - p.y;
    long double ee = ex * ex + ey * ey;
    long double t = 0.0L;
    ref_pt c;
    if (ee > 0.0L) {
        t = -(p.x * ex + p.y * ey) / ee;
        if (t < 0.0L) t = 0.0L;
        if (t > 1.0L) t = 1.0L;
    }
    c.x = p.x + t * ex;
    c.y = p.y + t * ey;
    return c;
}

static long double ref_len(long double x, long double y) { return sqrtl(x * x + y * y); }

bool sx_ref_place(const sx_shape *s, sx_xform x, sx_ref_shape *out) {
    sx_vec2 local[SX_REF_MAX_CORE];
    long double c = (long double)x.q.c, sn = (long double)x.q.s;
    long double tx = (long double)x.p.x, ty = (long double)x.p.y;
    int i, n = 0;
    sx_real radius = SX_R(0.0);
    if (out == NULL) return false;
    out->count = 0;
    out->radius = 0.0L;
    if (s == NULL) return false;
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        local[0] = s->u.circle.center;
        radius = s->u.circle.radius;
        n = 1;
        break;
    case SX_SHAPE_SEGMENT:
        local[0] = s->u.segment.a;
        local[1] = s->u.segment.b;
        n = 2;
        break;
    case SX_SHAPE_CAPSULE:
        local[0] = s->u.capsule.a;
        local[1] = s->u.capsule.b;
        radius = s->u.capsule.radius;
        n = 2;
        break;
    case SX_SHAPE_POLYGON:
        n = s->u.polygon.count;
        if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return false;
        for (i = 0; i < n; ++i)
            local[i] = s->u.polygon.vertices[i];
        radius = s->u.polygon.radius;
        break;
    default: return false;
    }
    if (!(radius >= SX_R(0.0))) return false;
    for (i = 0; i < n; ++i) {
        long double px = (long double)local[i].x, py = (long double)local[i].y;
        out->x[i] = c * px - sn * py + tx;
        out->y[i] = sn * px + c * py + ty;
    }
    out->count = n;
    out->radius = (long double)radius;
    return true;
}

bool sx_ref_penetration_placed(const sx_ref_shape *a, const sx_ref_shape *b, sx_ref_result *out) {
    ref_pt diff[REF_MAX_DIFF];
    ref_pt hull[REF_MAX_CHAIN];
    sx_ref_result r;
    long double scale = 1.0L, radius;
    int i, j, n = 0, h;
    if (out == NULL) return false;
    r.depth = 0.0L;
    r.dir_x = 1.0L;
    r.dir_y = 0.0L;
    r.core_distance = 0.0L;
    r.tie_gap = 0.0L;
    r.direction_defined = false;
    r.hull_count = 0;
    *out = r;
    if (a == NULL || b == NULL || a->count < 1 || b->count < 1) return false;
    for (i = 0; i < a->count; ++i) {
        for (j = 0; j < b->count; ++j) {
            diff[n].x = a->x[i] - b->x[j];
            diff[n].y = a->y[i] - b->y[j];
            if (fabsl(diff[n].x) > scale) scale = fabsl(diff[n].x);
            if (fabsl(diff[n].y) > scale) scale = fabsl(diff[n].y);
            ++n;
        }
    }
    radius = a->radius + b->radius;
    h = ref_hull(diff, n, hull);
    r.hull_count = h;
    if (h == 1) {
        long double d = ref_len(hull[0].x, hull[0].y);
        r.core_distance = d;
        if (d > 0.0L) {
            r.dir_x = hull[0].x / d;
            r.dir_y = hull[0].y / d;
            r.direction_defined = true;
            r.tie_gap = HUGE_VALL;
        }
    } else if (h == 2) {
        ref_pt c = ref_closest_on_segment(hull[0], hull[1]);
        long double d = ref_len(c.x, c.y);
        r.core_distance = d;
        if (d > 0.0L) {
            r.dir_x = c.x / d;
            r.dir_y = c.y / d;
            r.direction_defined = true;
            r.tie_gap = HUGE_VALL;
        } else {
            /* The origin is on the segment: both of its sides are equally
             * short escapes. */
            long double ex = hull[1].x - hull[0].x, ey = hull[1].y - hull[0].y;
            long double len = ref_len(ex, ey);
            r.dir_x = -ey / len;
            r.dir_y = ex / len;
        }
    } else {
        long double min_off = HUGE_VALL, best_nx = 0.0L, best_ny = 0.0L;
        long double nxs[REF_MAX_CHAIN], nys[REF_MAX_CHAIN], offs[REF_MAX_CHAIN];
        bool usable[REF_MAX_CHAIN];
        for (i = 0; i < h; ++i) {
            ref_pt p = hull[i], q = hull[(i + 1) % h];
            long double ex = q.x - p.x, ey = q.y - p.y;
            long double len = ref_len(ex, ey);
            usable[i] = len > REF_TINY_EDGE * scale;
            if (!usable[i]) continue;
            nxs[i] = ey / len;
            nys[i] = -ex / len;
            /* Minus the origin's signed distance to the edge's line: >= 0
             * when the origin is on the inner side. */
            offs[i] = p.x * nxs[i] + p.y * nys[i];
            if (offs[i] < min_off) {
                min_off = offs[i];
                best_nx = nxs[i];
                best_ny = nys[i];
            }
        }
        if (min_off == HUGE_VALL) {
            /* Every edge is a rounding artefact: the hull is a point for all
             * practical purposes. */
            long double d = ref_len(hull[0].x, hull[0].y);
            r.core_distance = d;
            if (d > 0.0L) {
                r.dir_x = hull[0].x / d;
                r.dir_y = hull[0].y / d;
                r.direction_defined = true;
                r.tie_gap = HUGE_VALL;
            }
        } else if (min_off >= 0.0L) {
            long double gap = HUGE_VALL;
            r.core_distance = -min_off;
            r.dir_x = -best_nx;
            r.dir_y = -best_ny;
            r.direction_defined = true;
            for (i = 0; i < h; ++i) {
                long double sine;
                if (!usable[i]) continue;
                sine = fabsl(nxs[i] * best_ny - nys[i] * best_nx);
                if (sine < REF_SAME_DIRECTION && nxs[i] * best_nx + nys[i] * best_ny > 0.0L) {
                    continue;
                }
                if (offs[i] - min_off < gap) gap = offs[i] - min_off;
            }
            r.tie_gap = gap;
        } else {
            long double best = HUGE_VALL;
            ref_pt bc = hull[0];
            for (i = 0; i < h; ++i) {
                ref_pt c = ref_closest_on_segment(hull[i], hull[(i + 1) % h]);
                long double d = ref_len(c.x, c.y);
                if (d < best) {
                    best = d;
                    bc = c;
                }
            }
            r.core_distance = best;
            if (best > 0.0L) {
                r.dir_x = bc.x / best;
                r.dir_y = bc.y / best;
                r.direction_defined = true;
                r.tie_gap = HUGE_VALL;
            } else {
                r.dir_x = -best_nx;
                r.dir_y = -best_ny;
                r.direction_defined = true;
            }
        }
    }
    r.depth = radius - r.core_distance;
    *out = r;
    return true;
}

bool sx_ref_penetration(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                        sx_ref_result *out) {
    sx_ref_shape pa, pb;
    bool ok_a = sx_ref_place(a, xa, &pa);
    bool ok_b = sx_ref_place(b, xb, &pb);
    if (!ok_a || !ok_b) {
        pa.count = 0;
        pb.count = 0;
    }
    return sx_ref_penetration_placed(&pa, &pb, out);
}

long double sx_ref_depth_along(const sx_ref_shape *a, const sx_ref_shape *b, long double dx,
                               long double dy) {
    long double len = ref_len(dx, dy), min_a = HUGE_VALL, max_b = -HUGE_VALL;
    int i;
    if (a == NULL || b == NULL || a->count < 1 || b->count < 1 || !(len > 0.0L)) return HUGE_VALL;
    dx /= len;
    dy /= len;
    for (i = 0; i < a->count; ++i) {
        long double s = a->x[i] * dx + a->y[i] * dy;
        if (s < min_a) min_a = s;
    }
    for (i = 0; i < b->count; ++i) {
        long double s = b->x[i] * dx + b->y[i] * dy;
        if (s > max_b) max_b = s;
    }
    return a->radius + b->radius + max_b - min_a;
}

long double sx_ref_distance_to_point(const sx_shape *s, sx_xform x, long double px, long double py,
                                     long double *nx, long double *ny) {
    sx_ref_shape shape;
    ref_pt core[SX_REF_MAX_CORE], hull[2 * SX_REF_MAX_CORE + 1];
    long double d, out_nx = 0.0L, out_ny = 0.0L, dist;
    int i, h;
    if (nx) *nx = 0.0L;
    if (ny) *ny = 0.0L;
    if (!sx_ref_place(s, x, &shape)) return HUGE_VALL;
    /* Work relative to p: the question becomes the origin's distance to the
     * core moved by -p, as in the pair reference. */
    for (i = 0; i < shape.count; ++i) {
        core[i].x = shape.x[i] - px;
        core[i].y = shape.y[i] - py;
    }
    if (shape.count <= 2) {
        ref_pt c = shape.count == 1 ? core[0] : ref_closest_on_segment(core[0], core[1]);
        d = ref_len(c.x, c.y);
        if (d > 0.0L) {
            out_nx = -c.x / d;
            out_ny = -c.y / d;
        } else {
            long double ex = 0.0L, ey = 0.0L, len = 0.0L;
            if (shape.count == 2) {
                ex = core[1].x - core[0].x;
                ey = core[1].y - core[0].y;
                len = ref_len(ex, ey);
            }
            if (len > 0.0L) {
                out_nx = -ey / len;
                out_ny = ex / len;
            } else {
                out_nx = 1.0L;
                out_ny = 0.0L;
            }
        }
        dist = d - shape.radius;
    } else {
        long double max_off = -HUGE_VALL;
        h = ref_hull(core, shape.count, hull);
        if (h < 3) return HUGE_VALL;
        for (i = 0; i < h; ++i) {
            ref_pt p = hull[i], q = hull[(i + 1) % h];
            long double ex = q.x - p.x, ey = q.y - p.y;
            long double len = ref_len(ex, ey);
            long double enx = ey / len, eny = -ex / len;
            /* The point's signed distance to the edge's line, outside > 0. */
            long double off = -(p.x * enx + p.y * eny);
            if (off > max_off) {
                max_off = off;
                out_nx = enx;
                out_ny = eny;
            }
        }
        if (max_off <= 0.0L) {
            dist = max_off - shape.radius;
        } else {
            long double best = HUGE_VALL;
            for (i = 0; i < h; ++i) {
                ref_pt c = ref_closest_on_segment(hull[i], hull[(i + 1) % h]);
                long double dc = ref_len(c.x, c.y);
                if (dc < best) {
                    best = dc;
                    out_nx = -c.x / dc;
                    out_ny = -c.y / dc;
                }
            }
            dist = best - shape.radius;
        }
    }
    if (nx) *nx = out_nx;
    if (ny) *ny = out_ny;
    return dist;
}

long double sx_ref_angle_between(long double ax, long double ay, long double bx, long double by) {
    long double cross = ax * by - ay * bx, dot = ax * bx + ay * by;
    if (!(ref_len(ax, ay) > 0.0L) || !(ref_len(bx, by) > 0.0L)) return acosl(-1.0L);
    return atan2l(fabsl(cross), dot);
}
