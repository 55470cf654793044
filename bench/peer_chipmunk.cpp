/* sepax benchmarks — the Chipmunk 7 peer (optional third column): builds
 * Chipmunk shapes from the shared pair descriptions and times
 * cpShapesCollide, Chipmunk's public "collide these two shapes" call (the
 * same cpCollide its space runs, GJK/EPA for everything but circles).
 *
 * Chipmunk models every benchmark shape natively: circles, segments with a
 * radius (radius 0: a segment; > 0: a capsule) and polygons with a radius
 * (rounded polygons). Shapes are placed with cpShapeUpdate and the pose's own
 * cos/sin pair, so Chipmunk sees the same rotation as the other engines; it
 * computes in double (cpFloat), which its depth errors reflect. It has no
 * boolean-only test: overlap is not run. Contact distance is negative for
 * overlap, so depth = -min distance over the contact points. The pair is
 * handed over smaller kind first (circle, segment, polygon), Chipmunk's own
 * order: cpShapesCollide negates its normal when it has to swap the shapes
 * but not the distance it then computes from it.
 *
 * Known result: for a circle against a rounded polygon Chipmunk 7.0.3 finds
 * the contact but reports a distance off by twice the polygon's radius (a
 * circle 0.1 m into a square rounded by 0.5 m reads +0.9 m): its contact
 * point on the polygon is offset outwards instead of inwards. The table shows
 * it as a large depth error and "wrong" answers on that row only. */
#include <chipmunk/chipmunk.h>

#include <cstdio>
#include <vector>

#include "pairs.h"

namespace {

cpShape *build(cpBody *body, const bench_shape &s) {
    switch (s.kind) {
    case BENCH_CIRCLE:
        return cpCircleShapeNew(body, s.radius, cpv(s.v[0][0], s.v[0][1]));
    case BENCH_SEGMENT:
    case BENCH_CAPSULE:
        return cpSegmentShapeNew(body, cpv(s.v[0][0], s.v[0][1]), cpv(s.v[1][0], s.v[1][1]),
                                 s.radius);
    default: {
        cpVect v[BENCH_MAX_VERTICES];
        for (int i = 0; i < s.count; ++i) v[i] = cpv(s.v[i][0], s.v[i][1]);
        return cpPolyShapeNewRaw(body, s.count, v, s.radius);
    }
    }
}

cpTransform to_cp(const bench_pose &p) { return cpTransformNewTranspose(p.c, -p.s, p.x, p.s, p.c, p.y); }

double deepest(const cpContactPointSet &set) {
    if (set.count == 0) return 0.0;
    double d = -set.points[0].distance;
    for (int i = 1; i < set.count; ++i)
        if (-set.points[i].distance > d) d = -set.points[i].distance;
    return d;
}

} // namespace

/* cpCollide reads the shapes' body (the rotation of a segment's neighbour
 * tangents, zero here), so every shape hangs off one static body; the pose
 * itself goes through cpShapeUpdate with the exact cos/sin pair. */
struct bench_chipmunk_set {
    cpBody *body;
    std::vector<cpShape *> a, b;
};

extern "C" void bench_chipmunk_version(char *out, int size) {
    snprintf(out, (size_t)size, "Chipmunk %s", cpVersionString);
}

extern "C" bench_chipmunk_set *bench_chipmunk_build(const bench_pair *pairs, int n) {
    bench_chipmunk_set *set = new bench_chipmunk_set();
    set->body = cpBodyNewStatic();
    set->a.resize((size_t)n);
    set->b.resize((size_t)n);
    for (int i = 0; i < n; ++i) {
        set->a[(size_t)i] = build(set->body, pairs[i].b);
        set->b[(size_t)i] = build(set->body, pairs[i].a);
        cpShapeUpdate(set->a[(size_t)i], to_cp(pairs[i].xb));
        cpShapeUpdate(set->b[(size_t)i], to_cp(pairs[i].xa));
    }
    return set;
}

extern "C" void bench_chipmunk_free(bench_chipmunk_set *set) {
    if (!set) return;
    for (cpShape *s : set->a) cpShapeFree(s);
    for (cpShape *s : set->b) cpShapeFree(s);
    cpBodyFree(set->body);
    delete set;
}

extern "C" double bench_chipmunk_run(const bench_chipmunk_set *set, int passes) {
    double sink = 0.0;
    const size_t n = set->a.size();
    for (int pass = 0; pass < passes; ++pass)
        for (size_t i = 0; i < n; ++i) sink += cpShapesCollide(set->a[i], set->b[i]).count;
    return sink;
}

extern "C" void bench_chipmunk_depths(const bench_chipmunk_set *set, double *depth) {
    for (size_t i = 0; i < set->a.size(); ++i) depth[i] = deepest(cpShapesCollide(set->a[i], set->b[i]));
}
