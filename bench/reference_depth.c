/* sepax benchmarks — the independent depth reference: signed penetration
 * depth of two placed shapes in long double, written without any sepax code
 * so that it can judge sepax and Box2D alike.
 *
 * Every benchmark shape is a convex core (a point, a segment, or a convex
 * polygon) grown by a radius, so A - B is the Minkowski difference of two
 * convex polygons grown by rA + rB, and its signed distance to the origin is
 * the cores' signed distance minus rA + rB. For the cores: the max over the
 * candidate axes (edge normals of both cores; for a segment also its
 * direction) of the gap between the projected intervals separates the two
 * cases. When it is > 0 the cores are apart and their distance is the least
 * vertex-to-edge distance (exact for disjoint convex sets: a closest pair
 * always involves a vertex). Otherwise that max is minus the penetration
 * depth: the Minkowski difference of two convex polygons is a convex polygon
 * whose edge normals are among those axes, so SAT is exact. Extra axes (a
 * segment's direction) can only add candidates the minimum never picks, so
 * they are harmless. Long double keeps the rounding of this computation far
 * below float's (about 1e-19 relative on x86-64). */
#include <math.h>

#include "pairs.h"

typedef struct lv2 {
    long double x, y;
} lv2;

/* The core vertices in world space (the pose's cos/sin taken as given). */
static int world_core(const bench_shape *s, const bench_pose *x, lv2 *out) {
    long double c = (long double)x->c, sn = (long double)x->s;
    for (int i = 0; i < s->count; ++i) {
        long double vx = (long double)s->v[i][0], vy = (long double)s->v[i][1];
        out[i].x = c * vx - sn * vy + (long double)x->x;
        out[i].y = sn * vx + c * vy + (long double)x->y;
    }
    return s->count;
}

/* Appends the unit normal of each core edge (one edge for a segment, plus
 * its direction). */
static int add_axes(const lv2 *v, int n, lv2 *axes, int count) {
    if (n < 2) return count;
    int edges = n == 2 ? 1 : n;
    for (int i = 0; i < edges; ++i) {
        lv2 d = {v[(i + 1) % n].x - v[i].x, v[(i + 1) % n].y - v[i].y};
        long double len = sqrtl(d.x * d.x + d.y * d.y);
        if (!(len > 0.0L)) continue;
        axes[count].x = d.y / len;
        axes[count].y = -d.x / len;
        ++count;
        if (n == 2) {
            axes[count].x = d.x / len;
            axes[count].y = d.y / len;
            ++count;
        }
    }
    return count;
}

static void project(const lv2 *v, int n, lv2 axis, long double *lo, long double *hi) {
    *lo = *hi = v[0].x * axis.x + v[0].y * axis.y;
    for (int i = 1; i < n; ++i) {
        long double p = v[i].x * axis.x + v[i].y * axis.y;
        if (p < *lo) *lo = p;
        if (p > *hi) *hi = p;
    }
}

static long double point_segment_distance(lv2 p, lv2 a, lv2 b) {
    lv2 d = {b.x - a.x, b.y - a.y};
    long double dd = d.x * d.x + d.y * d.y;
    long double t = dd > 0.0L ? ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / dd : 0.0L;
    if (t < 0.0L) t = 0.0L;
    if (t > 1.0L) t = 1.0L;
    long double ex = a.x + t * d.x - p.x, ey = a.y + t * d.y - p.y;
    return sqrtl(ex * ex + ey * ey);
}

/* Least distance from the vertices of p to the core q (its edges, or its
 * single point). */
static long double vertex_to_core(const lv2 *p, int np, const lv2 *q, int nq) {
    long double best = HUGE_VALL;
    int edges = nq == 1 ? 1 : (nq == 2 ? 1 : nq);
    for (int i = 0; i < np; ++i) {
        for (int e = 0; e < edges; ++e) {
            long double d = point_segment_distance(p[i], q[e], q[(e + 1) % nq]);
            if (d < best) best = d;
        }
    }
    return best;
}

double bench_ref_depth(const bench_shape *a, const bench_pose *xa, const bench_shape *b,
                       const bench_pose *xb) {
    lv2 va[BENCH_MAX_VERTICES], vb[BENCH_MAX_VERTICES];
    lv2 axes[2 * BENCH_MAX_VERTICES + 4];
    int na = world_core(a, xa, va), nb = world_core(b, xb, vb);
    int naxes = add_axes(va, na, axes, 0);
    naxes = add_axes(vb, nb, axes, naxes);

    long double sep = -HUGE_VALL;
    for (int i = 0; i < naxes; ++i) {
        long double alo, ahi, blo, bhi;
        project(va, na, axes[i], &alo, &ahi);
        project(vb, nb, axes[i], &blo, &bhi);
        long double gap = blo - ahi > alo - bhi ? blo - ahi : alo - bhi;
        if (gap > sep) sep = gap;
    }
    long double signed_distance;
    if (naxes == 0 || sep > 0.0L) {
        long double dab = vertex_to_core(va, na, vb, nb);
        long double dba = vertex_to_core(vb, nb, va, na);
        signed_distance = dab < dba ? dab : dba;
    } else {
        signed_distance = sep;
    }
    return (double)((long double)a->radius + (long double)b->radius - signed_distance);
}

double bench_ref_extent(const bench_shape *s, const bench_pose *x, double ux, double uy) {
    lv2 v[BENCH_MAX_VERTICES];
    int n = world_core(s, x, v);
    long double best = -HUGE_VALL;
    for (int i = 0; i < n; ++i) {
        long double p = (v[i].x - (long double)x->x) * (long double)ux +
                        (v[i].y - (long double)x->y) * (long double)uy;
        if (p > best) best = p;
    }
    return (double)(best + (long double)s->radius);
}
