/* sepax benchmarks — the Box2D 2.4 peer: builds Box2D shapes from the shared
 * pair descriptions and runs Box2D's own narrowphase on them.
 *
 * Collide is b2CollideCircles, b2CollidePolygonAndCircle, b2CollidePolygons,
 * b2CollideEdgeAndCircle and b2CollideEdgeAndPolygon (the functions
 * b2Contact::Evaluate calls); the boolean test is b2TestOverlap (GJK
 * distance, the one Box2D uses for sensors and queries). Box2D 2.4 has no
 * capsule and does not collide two edges, so those pairs are not run.
 *
 * The skin radius. Box2D 2.4 gives every polygon and edge a radius
 * b2_polygonRadius (2 x linearSlop = 1 cm) that is part of its geometry: its
 * manifold separations are measured between the skins. To compare the same
 * sets, each Box2D shape gets exactly the radius of the benchmark shape:
 * 0 for sharp polygons, boxes and segments, the rounding radius for rounded
 * polygons (Box2D handles a polygon radius natively). m_radius is a public
 * field and every collide function reads it; the work Box2D does does not
 * depend on its value. Keeping the default skin instead would make every
 * Box2D polygon 1 cm fatter than the reference and report 1 to 2 cm of depth
 * "error" that is a modelling choice, not an inaccuracy. */
#include <box2d/box2d.h>

#include <cstdio>
#include <vector>

#include "pairs.h"

namespace {

struct Shape {
    int kind;
    b2CircleShape circle;
    b2EdgeShape edge;
    b2PolygonShape polygon;
    const b2Shape *shape() const {
        if (kind == BENCH_CIRCLE) return &circle;
        if (kind == BENCH_SEGMENT) return &edge;
        return &polygon;
    }
};

template <class A, class B> struct Pair {
    A a;
    B b;
    b2Transform xa, xb;
};

b2Transform to_b2(const bench_pose &p) {
    b2Transform x;
    x.p.Set((float)p.x, (float)p.y);
    x.q.c = (float)p.c;
    x.q.s = (float)p.s;
    return x;
}

bool build(const bench_shape &s, b2CircleShape *out) {
    out->m_p.Set((float)s.v[0][0], (float)s.v[0][1]);
    out->m_radius = (float)s.radius;
    return s.kind == BENCH_CIRCLE;
}

bool build(const bench_shape &s, b2EdgeShape *out) {
    out->SetTwoSided(b2Vec2((float)s.v[0][0], (float)s.v[0][1]),
                     b2Vec2((float)s.v[1][0], (float)s.v[1][1]));
    out->m_radius = 0.0f;
    return s.kind == BENCH_SEGMENT;
}

bool build(const bench_shape &s, b2PolygonShape *out) {
    if (s.kind == BENCH_BOX) {
        out->SetAsBox((float)s.hx, (float)s.hy);
    } else if (s.kind == BENCH_POLYGON || s.kind == BENCH_ROUNDED) {
        b2Vec2 v[b2_maxPolygonVertices];
        for (int i = 0; i < s.count; ++i)
            v[i].Set((float)s.v[i][0], (float)s.v[i][1]);
        out->Set(v, s.count);
        if (out->m_count != s.count) return false;
    } else {
        return false;
    }
    out->m_radius = (float)s.radius;
    return true;
}

/* The manifold of one pair, and the shapes' radii for b2WorldManifold. */
inline void collide(b2Manifold *m, const Pair<b2CircleShape, b2CircleShape> &p) {
    b2CollideCircles(m, &p.a, p.xa, &p.b, p.xb);
}
inline void collide(b2Manifold *m, const Pair<b2EdgeShape, b2CircleShape> &p) {
    b2CollideEdgeAndCircle(m, &p.a, p.xa, &p.b, p.xb);
}
inline void collide(b2Manifold *m, const Pair<b2PolygonShape, b2CircleShape> &p) {
    b2CollidePolygonAndCircle(m, &p.a, p.xa, &p.b, p.xb);
}
inline void collide(b2Manifold *m, const Pair<b2EdgeShape, b2PolygonShape> &p) {
    b2CollideEdgeAndPolygon(m, &p.a, p.xa, &p.b, p.xb);
}
inline void collide(b2Manifold *m, const Pair<b2PolygonShape, b2PolygonShape> &p) {
    b2CollidePolygons(m, &p.a, p.xa, &p.b, p.xb);
}
/* Box2D does not collide two edges: only b2TestOverlap runs on them. */
inline void collide(b2Manifold *m, const Pair<b2EdgeShape, b2EdgeShape> &) { m->pointCount = 0; }

template <class P> float deepest(const b2Manifold &m, const P &p) {
    if (m.pointCount == 0) return 0.0f;
    b2WorldManifold wm;
    wm.Initialize(&m, p.xa, p.a.m_radius, p.xb, p.b.m_radius);
    float d = -wm.separations[0];
    for (int i = 1; i < m.pointCount; ++i)
        if (-wm.separations[i] > d) d = -wm.separations[i];
    return d;
}

struct SetBase {
    virtual ~SetBase() {}
    virtual double run(int fn, int passes) const = 0;
    virtual void depths(double *out) const = 0;
    virtual void overlaps(int *out) const = 0;
};

template <class A, class B> struct Set : SetBase {
    std::vector<Pair<A, B>> pairs;

    double run(int fn, int passes) const override {
        double sink = 0.0;
        const Pair<A, B> *p = pairs.data();
        const size_t n = pairs.size();
        for (int pass = 0; pass < passes; ++pass) {
            if (fn == BENCH_FN_OVERLAP) {
                for (size_t i = 0; i < n; ++i)
                    sink += b2TestOverlap(&p[i].a, 0, &p[i].b, 0, p[i].xa, p[i].xb) ? 1.0 : 0.0;
            } else if (fn == BENCH_FN_COLLIDE) {
                for (size_t i = 0; i < n; ++i) {
                    b2Manifold m;
                    collide(&m, p[i]);
                    sink += m.pointCount;
                }
            } else {
                for (size_t i = 0; i < n; ++i) {
                    b2Manifold m;
                    collide(&m, p[i]);
                    sink += deepest(m, p[i]);
                }
            }
        }
        return sink;
    }
    void depths(double *out) const override {
        for (size_t i = 0; i < pairs.size(); ++i) {
            b2Manifold m;
            collide(&m, pairs[i]);
            out[i] = deepest(m, pairs[i]);
        }
    }
    void overlaps(int *out) const override {
        for (size_t i = 0; i < pairs.size(); ++i)
            out[i] = b2TestOverlap(&pairs[i].a, 0, &pairs[i].b, 0, pairs[i].xa, pairs[i].xb);
    }
};

/* Box2D's collide functions take the edge first and the circle last, so the
 * pair is stored in Box2D's order (depth does not depend on it). */
template <class A, class B> SetBase *make_set(const bench_pair *pairs, int n, bool swap) {
    Set<A, B> *set = new Set<A, B>();
    set->pairs.resize((size_t)n);
    for (int i = 0; i < n; ++i) {
        const bench_shape &sa = swap ? pairs[i].b : pairs[i].a;
        const bench_shape &sb = swap ? pairs[i].a : pairs[i].b;
        Pair<A, B> &p = set->pairs[(size_t)i];
        if (!build(sa, &p.a) || !build(sb, &p.b)) {
            delete set;
            return nullptr;
        }
        p.xa = to_b2(swap ? pairs[i].xb : pairs[i].xa);
        p.xb = to_b2(swap ? pairs[i].xa : pairs[i].xb);
    }
    return set;
}

bool is_polygon(int k) { return k == BENCH_BOX || k == BENCH_POLYGON || k == BENCH_ROUNDED; }

} // namespace

struct bench_box2d_set {
    SetBase *impl;
};

extern "C" int bench_box2d_supports(int ka, int kb, int fn) {
    if (ka == BENCH_CAPSULE || kb == BENCH_CAPSULE) return 0;
    if (fn == BENCH_FN_OVERLAP) return 1;
    return !(ka == BENCH_SEGMENT && kb == BENCH_SEGMENT);
}

extern "C" bench_box2d_set *bench_box2d_build(const bench_pair *pairs, int n) {
    if (n <= 0) return nullptr;
    int ka = pairs[0].a.kind, kb = pairs[0].b.kind;
    SetBase *impl = nullptr;
    if (ka == BENCH_CIRCLE && kb == BENCH_CIRCLE)
        impl = make_set<b2CircleShape, b2CircleShape>(pairs, n, false);
    else if (ka == BENCH_SEGMENT && kb == BENCH_CIRCLE)
        impl = make_set<b2EdgeShape, b2CircleShape>(pairs, n, false);
    else if (ka == BENCH_SEGMENT && kb == BENCH_SEGMENT)
        impl = make_set<b2EdgeShape, b2EdgeShape>(pairs, n, false);
    else if (is_polygon(ka) && kb == BENCH_CIRCLE)
        impl = make_set<b2PolygonShape, b2CircleShape>(pairs, n, false);
    else if (is_polygon(ka) && kb == BENCH_SEGMENT)
        impl = make_set<b2EdgeShape, b2PolygonShape>(pairs, n, true);
    else if (is_polygon(ka) && is_polygon(kb))
        impl = make_set<b2PolygonShape, b2PolygonShape>(pairs, n, false);
    if (!impl) return nullptr;
    return new bench_box2d_set{impl};
}

extern "C" void bench_box2d_free(bench_box2d_set *set) {
    if (!set) return;
    delete set->impl;
    delete set;
}

extern "C" double bench_box2d_run(const bench_box2d_set *set, int fn, int passes) {
    return set->impl->run(fn, passes);
}

extern "C" void bench_box2d_depths(const bench_box2d_set *set, double *depth) {
    set->impl->depths(depth);
}

extern "C" void bench_box2d_version(char *out, int size) {
    snprintf(out, (size_t)size, "Box2D %d.%d.%d", b2_version.major, b2_version.minor,
             b2_version.revision);
}

extern "C" void bench_box2d_overlaps(const bench_box2d_set *set, int *overlap) {
    set->impl->overlaps(overlap);
}
