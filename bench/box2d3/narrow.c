/* sepax benchmarks — the Box2D v3 narrowphase peer: builds v3 shapes from the
 * shared pair descriptions (bench/pairs.h) and runs v3's own manifold and
 * overlap functions on them, the way v3's world calls them.
 *
 * Collide is v3's b2Collide* function for the pair, called as b2UpdateContact
 * (src/contact.c) calls it: through a small adapter of one signature, on the
 * shapes in their local frames and the relative transform of B in A's frame
 * (b2InvMulTransforms of the two world transforms, computed per call: a user
 * holding two bodies' transforms pays it, as sx_collide pays its own move of
 * B into A's frame). The answer is in A's frame. "Collide world" then moves
 * it to world space as sx_collide returns it (the normal rotated, A to B; each
 * point rotated and offset by A's position; depth = -separation), the work
 * b2UpdateContact does to build its world-space anchors.
 *
 * Overlap is what v3's sensors do (src/sensor.c): distance proxies made from
 * both shapes, b2ShapeDistance (GJK) from an empty simplex cache with the
 * radii, and "overlapping" when the distance is below 10 FLT_EPSILON. v3 has
 * no b2TestOverlap.
 *
 * v3 runs every pair type natively but segment-segment (it never collides two
 * segments; its overlap test still runs there): real capsules, rounded
 * polygons (b2MakePolygon with the rounding radius), polygons without a skin.
 * The segment-capsule and segment-polygon functions take the segment first,
 * so those pairs are stored in v3's order and the world normal is negated
 * back. v3 answers speculative points up to 4 x linearSlop (2 cm) apart, so
 * its overlap answer from a manifold is "some point has a negative
 * separation", not "some point". */
#include <box2d/box2d.h>

#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "b3_export.h"
#include "pairs.h"

/* The one signature every manifold function is called through, as in v3's
 * contact table. */
typedef b2LocalManifold b3_collide_fn(const void *a, const void *b, b2Transform xf);

static b2LocalManifold circles(const void *a, const void *b, b2Transform xf) {
    return b2CollideCircles(a, b, xf);
}
static b2LocalManifold segment_circle(const void *a, const void *b, b2Transform xf) {
    return b2CollideSegmentAndCircle(a, b, xf);
}
static b2LocalManifold capsule_circle(const void *a, const void *b, b2Transform xf) {
    return b2CollideCapsuleAndCircle(a, b, xf);
}
static b2LocalManifold segment_capsule(const void *a, const void *b, b2Transform xf) {
    return b2CollideSegmentAndCapsule(a, b, xf);
}
static b2LocalManifold capsules(const void *a, const void *b, b2Transform xf) {
    return b2CollideCapsules(a, b, xf);
}
static b2LocalManifold polygon_circle(const void *a, const void *b, b2Transform xf) {
    return b2CollidePolygonAndCircle(a, b, xf);
}
static b2LocalManifold segment_polygon(const void *a, const void *b, b2Transform xf) {
    return b2CollideSegmentAndPolygon(a, b, xf);
}
static b2LocalManifold polygon_capsule(const void *a, const void *b, b2Transform xf) {
    return b2CollidePolygonAndCapsule(a, b, xf);
}
static b2LocalManifold polygons(const void *a, const void *b, b2Transform xf) {
    return b2CollidePolygons(a, b, xf);
}

/* v3's shape kinds: boxes and rounded polygons are b2Polygon. */
enum { B3_CIRCLE, B3_SEGMENT, B3_CAPSULE, B3_POLYGON };

static int b3_kind(int kind) {
    switch (kind) {
    case BENCH_CIRCLE: return B3_CIRCLE;
    case BENCH_SEGMENT: return B3_SEGMENT;
    case BENCH_CAPSULE: return B3_CAPSULE;
    default: return B3_POLYGON;
    }
}

static size_t geom_size(int kind) {
    switch (kind) {
    case B3_CIRCLE: return sizeof(b2Circle);
    case B3_SEGMENT: return sizeof(b2Segment);
    case B3_CAPSULE: return sizeof(b2Capsule);
    default: return sizeof(b2Polygon);
    }
}

/* The manifold function of a pair of v3 kinds in v3's argument order (larger
 * kind first, but the segment before a capsule or polygon); NULL for two
 * segments. */
static b3_collide_fn *collide_fn(int ka, int kb) {
    /* [A's kind][B's kind], kinds in B3_CIRCLE..B3_POLYGON order */
    static b3_collide_fn *const table[4][4] = {
        {circles, NULL, NULL, NULL},
        {segment_circle, NULL, segment_capsule, segment_polygon},
        {capsule_circle, NULL, capsules, NULL},
        {polygon_circle, NULL, polygon_capsule, polygons},
    };
    return table[ka][kb];
}

static b2Vec2 vec(const double *p) {
    b2Vec2 v = {(float)p[0], (float)p[1]};
    return v;
}

/* True if v3's hull of the points is the polygon as given: the same vertices
 * (b2ComputeHull may start the loop elsewhere), none welded or dropped. */
static int same_polygon(const b2Polygon *p, const b2Vec2 *pts, int count) {
    if (p->count != count) return 0;
    for (int i = 0; i < count; ++i) {
        int found = 0;
        for (int k = 0; k < count && !found; ++k)
            found = p->vertices[k].x == pts[i].x && p->vertices[k].y == pts[i].y;
        if (!found) return 0;
    }
    return 1;
}

static int build_geom(const bench_shape *s, void *out) {
    switch (s->kind) {
    case BENCH_CIRCLE: {
        b2Circle *c = out;
        c->center = vec(s->v[0]);
        c->radius = (float)s->radius;
        return 1;
    }
    case BENCH_SEGMENT: {
        b2Segment *g = out;
        g->point1 = vec(s->v[0]);
        g->point2 = vec(s->v[1]);
        return 1;
    }
    case BENCH_CAPSULE: {
        b2Capsule *c = out;
        c->center1 = vec(s->v[0]);
        c->center2 = vec(s->v[1]);
        c->radius = (float)s->radius;
        return 1;
    }
    case BENCH_BOX: *(b2Polygon *)out = b2MakeBox((float)s->hx, (float)s->hy); return 1;
    default: {
        b2Vec2 pts[BENCH_MAX_VERTICES];
        if (s->count < 3 || s->count > BENCH_MAX_VERTICES) return 0;
        for (int i = 0; i < s->count; ++i)
            pts[i] = vec(s->v[i]);
        b2Hull hull = b2ComputeHull(pts, s->count);
        if (hull.count != s->count) return 0;
        b2Polygon *p = out;
        *p = b2MakePolygon(&hull, (float)s->radius);
        return same_polygon(p, pts, s->count);
    }
    }
}

/* What b2MakeShapeDistanceProxy (src/shape.c) makes of each shape. */
static b2ShapeProxy make_proxy(int kind, const void *g) {
    switch (kind) {
    case B3_CIRCLE: {
        const b2Circle *c = g;
        return b2MakeProxy(&c->center, 1, c->radius);
    }
    case B3_SEGMENT: {
        const b2Segment *s = g;
        return b2MakeProxy(&s->point1, 2, 0.0f);
    }
    case B3_CAPSULE: {
        const b2Capsule *c = g;
        return b2MakeProxy(&c->center1, 2, c->radius);
    }
    default: {
        const b2Polygon *p = g;
        return b2MakeProxy(p->vertices, p->count, p->radius);
    }
    }
}

struct bench_b3_set {
    int kind_a, kind_b; /* v3 kinds, in v3's order */
    int swapped;        /* v3's A is the benchmark pair's B */
    size_t size_a, size_b;
    unsigned char *a, *b; /* n shapes each, size_a / size_b bytes apart */
    b2Transform *xa, *xb;
    int n;
    b3_collide_fn *collide; /* NULL: v3 has no manifold for the pair */
};

/* A v3 manifold moved to world space: what sx_collide answers. */
typedef struct world_point {
    b2Vec2 point;
    float depth;
    uint16_t id;
} world_point;

typedef struct world_manifold {
    b2Vec2 normal;
    world_point points[2];
    int count;
} world_manifold;

static const void *geom_a(const bench_b3_set *s, int i) { return s->a + (size_t)i * s->size_a; }
static const void *geom_b(const bench_b3_set *s, int i) { return s->b + (size_t)i * s->size_b; }

static b2LocalManifold local_manifold(const bench_b3_set *s, int i) {
    return s->collide(geom_a(s, i), geom_b(s, i), b2InvMulTransforms(s->xa[i], s->xb[i]));
}

static void to_world(const b2LocalManifold *m, b2Transform xa, int swapped, world_manifold *w) {
    b2Vec2 n = b2RotateVector(xa.q, m->normal);
    w->normal = swapped ? b2Neg(n) : n;
    w->count = m->pointCount;
    for (int k = 0; k < m->pointCount; ++k) {
        w->points[k].point = b2TransformPoint(xa, m->points[k].point);
        w->points[k].depth = -m->points[k].separation;
        w->points[k].id = m->points[k].id;
    }
}

/* The deepest point's depth; 0 without points (as for every engine). */
static float deepest(const world_manifold *w) {
    float d = 0.0f;
    for (int k = 0; k < w->count; ++k)
        if (k == 0 || w->points[k].depth > d) d = w->points[k].depth;
    return d;
}

static int overlaps_one(const bench_b3_set *s, int i) {
    b2DistanceInput in;
    in.proxyA = make_proxy(s->kind_a, geom_a(s, i));
    in.proxyB = make_proxy(s->kind_b, geom_b(s, i));
    in.transform = b2InvMulTransforms(s->xa[i], s->xb[i]);
    in.useRadii = true;
    b2SimplexCache cache = {0};
    b2DistanceOutput out = b2ShapeDistance(&in, &cache, NULL, 0);
    return out.distance < 10.0f * FLT_EPSILON;
}

static int b3_supports(int ka, int kb, int fn) {
    if (fn == BENCH_FN_OVERLAP) return 1;
    return !(ka == BENCH_SEGMENT && kb == BENCH_SEGMENT);
}

static void b3_free(bench_b3_set *s) {
    if (!s) return;
    free(s->a);
    free(s->b);
    free(s->xa);
    free(s->xb);
    free(s);
}

static bench_b3_set *b3_build(const bench_pair *pairs, int n) {
    if (n <= 0) return NULL;
    bench_b3_set *s = calloc(1, sizeof *s);
    if (!s) return NULL;
    int ka = b3_kind(pairs[0].a.kind), kb = b3_kind(pairs[0].b.kind);
    s->swapped = ka != B3_SEGMENT && kb == B3_SEGMENT;
    s->kind_a = s->swapped ? kb : ka;
    s->kind_b = s->swapped ? ka : kb;
    s->size_a = geom_size(s->kind_a);
    s->size_b = geom_size(s->kind_b);
    s->n = n;
    s->collide = collide_fn(s->kind_a, s->kind_b);
    s->a = calloc((size_t)n, s->size_a);
    s->b = calloc((size_t)n, s->size_b);
    s->xa = malloc((size_t)n * sizeof *s->xa);
    s->xb = malloc((size_t)n * sizeof *s->xb);
    if (!s->a || !s->b || !s->xa || !s->xb) {
        b3_free(s);
        return NULL;
    }
    for (int i = 0; i < n; ++i) {
        const bench_pair *p = &pairs[i];
        const bench_shape *sa = s->swapped ? &p->b : &p->a, *sb = s->swapped ? &p->a : &p->b;
        const bench_pose *pa = s->swapped ? &p->xb : &p->xa, *pb = s->swapped ? &p->xa : &p->xb;
        if (!build_geom(sa, s->a + (size_t)i * s->size_a) ||
            !build_geom(sb, s->b + (size_t)i * s->size_b)) {
            b3_free(s);
            return NULL;
        }
        s->xa[i].p.x = (float)pa->x;
        s->xa[i].p.y = (float)pa->y;
        s->xa[i].q.c = (float)pa->c;
        s->xa[i].q.s = (float)pa->s;
        s->xb[i].p.x = (float)pb->x;
        s->xb[i].p.y = (float)pb->y;
        s->xb[i].q.c = (float)pb->c;
        s->xb[i].q.s = (float)pb->s;
    }
    return s;
}

static double b3_run(const bench_b3_set *s, int fn, int passes) {
    double sum = 0.0;
    const int n = s->n;
    if (fn != BENCH_FN_OVERLAP && !s->collide) return 0.0;
    for (int pass = 0; pass < passes; ++pass) {
        if (fn == BENCH_FN_OVERLAP) {
            for (int i = 0; i < n; ++i)
                sum += overlaps_one(s, i);
        } else if (fn == BENCH_FN_COLLIDE) {
            for (int i = 0; i < n; ++i)
                sum += local_manifold(s, i).pointCount;
        } else {
            for (int i = 0; i < n; ++i) {
                b2LocalManifold m = local_manifold(s, i);
                world_manifold w;
                to_world(&m, s->xa[i], s->swapped, &w);
                /* Only the depth is summed: the barrier keeps the world
                 * points and normal as real stores, as sx_collide's are. */
                __asm__ __volatile__("" : : "r"(&w) : "memory");
                sum += (double)deepest(&w);
            }
        }
    }
    return sum;
}

static void b3_depths(const bench_b3_set *s, double *depth) {
    for (int i = 0; i < s->n; ++i) {
        world_manifold w = {{0.0f, 0.0f}, {{{0.0f, 0.0f}, 0.0f, 0}, {{0.0f, 0.0f}, 0.0f, 0}}, 0};
        if (s->collide) {
            b2LocalManifold m = local_manifold(s, i);
            to_world(&m, s->xa[i], s->swapped, &w);
        }
        depth[i] = (double)deepest(&w);
    }
}

static void b3_overlaps(const bench_b3_set *s, int *overlap) {
    for (int i = 0; i < s->n; ++i)
        overlap[i] = overlaps_one(s, i);
}

static void b3_version(char *out, int size) {
    b2Version v = b2GetVersion();
    snprintf(out, (size_t)size, "Box2D %d.%d.%d", v.major, v.minor, v.revision);
}

const bench_b3_narrow B3_EXPORT(narrow_box2d3_) = {b3_version, b3_supports, b3_build,   b3_free,
                                                   b3_run,     b3_depths,   b3_overlaps};
