/* sepax benchmarks — seeded generation of the shape pairs.
 *
 * Shapes are 0.1 to 2 m across. Random polygons are points on an ellipse at
 * jittered, well-spread angles: points on an ellipse are always in convex
 * position, and the spread keeps every vertex clear of its neighbours' line,
 * so both hull builders (sepax's and Box2D's) keep the polygon exactly as
 * generated. A pair places B along a random direction from A at a fraction of
 * the sum of the two extents in that direction; the long double reference
 * then says whether the pair overlaps, and pairs are redrawn until even
 * indices overlap and odd ones do not (half and half by construction). Every
 * number is rounded to float before it is stored, so each engine reads it
 * exactly. */
#include <math.h>
#include <stddef.h>

#include "pairs.h"

#define BENCH_PI 3.14159265358979323846

/* Polygons whose vertices come closer than this to their neighbours' line,
 * or whose edges are shorter, are redrawn: it is 8 x sepax's weld tolerance
 * (0.25 x 5 mm) and 4 x Box2D's weld distance, far from both. */
#define BENCH_MIN_FEATURE 0.01

bench_rng bench_rng_make(uint64_t seed) {
    bench_rng r;
    r.state = seed;
    return r;
}

static uint64_t rng_next(bench_rng *rng) {
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double bench_rng_range(bench_rng *rng, double lo, double hi) {
    double u = (double)(rng_next(rng) >> 11) * (1.0 / 9007199254740992.0);
    return lo + (hi - lo) * u;
}

const char *bench_kind_name(int kind) {
    static const char *const names[BENCH_KIND_COUNT] = {"circle", "segment", "capsule",
                                                        "box",    "polygon", "rounded"};
    return kind >= 0 && kind < BENCH_KIND_COUNT ? names[kind] : "?";
}

/* The nearest float, kept as a double. The volatile is not decoration: GCC
 * 12 at -O2 vectorises the x/y pair of a pose (SLP) and drops the rounding
 * of a plain (double)(float) cast there (seen here: every B position came
 * out unrounded; -fno-tree-slp-vectorize restores it). A volatile float
 * store cannot be elided. */
static double fl(double x) {
    volatile float f = (float)x;
    return (double)f;
}

static int polygon_is_clear(const bench_shape *s) {
    int n = s->count;
    for (int i = 0; i < n; ++i) {
        const double *p = s->v[(i + n - 1) % n], *q = s->v[i], *r = s->v[(i + 1) % n];
        double dx = r[0] - p[0], dy = r[1] - p[1];
        double len = sqrt(dx * dx + dy * dy);
        double ex = q[0] - p[0], ey = q[1] - p[1];
        double edge = sqrt(ex * ex + ey * ey);
        /* q must lie strictly right of p->r's left side: CCW means the cross
         * product of (r - p) and (q - p) is negative, by at least the margin. */
        double off = -(dx * ey - dy * ex) / len;
        if (!(off > BENCH_MIN_FEATURE) || !(edge > BENCH_MIN_FEATURE)) return 0;
    }
    return 1;
}

static void make_polygon(bench_rng *rng, double max_semi_axis, bench_shape *s) {
    do {
        int n = 3 + (int)bench_rng_range(rng, 0.0, 6.0);
        double ax = bench_rng_range(rng, 0.05, max_semi_axis);
        double ay = ax * bench_rng_range(rng, 0.5, 2.0);
        if (ay < 0.05) ay = 0.05;
        if (ay > max_semi_axis) ay = max_semi_axis;
        double phi = bench_rng_range(rng, -BENCH_PI, BENCH_PI);
        double base = bench_rng_range(rng, 0.0, 2.0 * BENCH_PI);
        double ox = bench_rng_range(rng, -0.2, 0.2), oy = bench_rng_range(rng, -0.2, 0.2);
        double c = cos(phi), sn = sin(phi);
        s->count = n;
        for (int i = 0; i < n; ++i) {
            double t = base + 2.0 * BENCH_PI / n * (i + bench_rng_range(rng, -0.3, 0.3));
            double ex = ax * cos(t), ey = ay * sin(t);
            s->v[i][0] = fl(ox + c * ex - sn * ey);
            s->v[i][1] = fl(oy + sn * ex + c * ey);
        }
    } while (!polygon_is_clear(s));
}

static void make_segment(bench_rng *rng, bench_shape *s) {
    double cx = bench_rng_range(rng, -0.2, 0.2), cy = bench_rng_range(rng, -0.2, 0.2);
    double h = bench_rng_range(rng, 0.05, 1.0);
    double t = bench_rng_range(rng, -BENCH_PI, BENCH_PI);
    s->count = 2;
    s->v[0][0] = fl(cx - h * cos(t));
    s->v[0][1] = fl(cy - h * sin(t));
    s->v[1][0] = fl(cx + h * cos(t));
    s->v[1][1] = fl(cy + h * sin(t));
}

static void make_shape(bench_rng *rng, int kind, bench_shape *s) {
    s->kind = kind;
    s->radius = 0.0;
    s->hx = s->hy = 0.0;
    switch (kind) {
    case BENCH_CIRCLE:
        s->count = 1;
        s->v[0][0] = fl(bench_rng_range(rng, -0.2, 0.2));
        s->v[0][1] = fl(bench_rng_range(rng, -0.2, 0.2));
        s->radius = fl(bench_rng_range(rng, 0.05, 1.0));
        break;
    case BENCH_SEGMENT: make_segment(rng, s); break;
    case BENCH_CAPSULE:
        make_segment(rng, s);
        s->radius = fl(bench_rng_range(rng, 0.05, 0.5));
        break;
    case BENCH_BOX:
        s->hx = fl(bench_rng_range(rng, 0.05, 1.0));
        s->hy = fl(bench_rng_range(rng, 0.05, 1.0));
        s->count = 4;
        s->v[0][0] = -s->hx;
        s->v[0][1] = -s->hy;
        s->v[1][0] = s->hx;
        s->v[1][1] = -s->hy;
        s->v[2][0] = s->hx;
        s->v[2][1] = s->hy;
        s->v[3][0] = -s->hx;
        s->v[3][1] = s->hy;
        break;
    case BENCH_POLYGON: make_polygon(rng, 1.0, s); break;
    default:
        make_polygon(rng, 0.8, s);
        s->radius = fl(bench_rng_range(rng, 0.02, 0.2));
        break;
    }
}

/* Rotations. A float cos/sin pair is never exactly unit: rounding cos and sin
 * leaves c^2 + s^2 off 1 by up to ~1e-7, and an engine that inverts a
 * rotation by transposing it (all of them) then works on a slightly
 * different placement than the reference, which applies (c, s) as given.
 * That is invisible in float but would be the whole error of a double build.
 * So poses draw from a table of float pairs picked for unit length: for each
 * of BENCH_ROTATIONS angles, among the floats within BENCH_ROTATION_SEARCH
 * ulps of cos(angle), the one whose rounded companion sin makes c^2 + s^2
 * closest to 1 (about 1e-11 off; float products are exact in double). */
#define BENCH_ROTATIONS 1024
#define BENCH_ROTATION_SEARCH 2048

typedef struct rotation {
    double c, s;
} rotation;

static rotation unit_rotation(double angle) {
    rotation best = {fl(cos(angle)), fl(sin(angle))};
    double best_err = fabs(best.c * best.c + best.s * best.s - 1.0);
    for (int dir = -1; dir <= 1; dir += 2) {
        float c = (float)cos(angle);
        for (int k = 0; k < BENCH_ROTATION_SEARCH; ++k) {
            c = nextafterf(c, dir < 0 ? -2.0f : 2.0f);
            double cd = (double)c;
            if (cd < -1.0 || cd > 1.0) break;
            double sd = fl(copysign(sqrt(1.0 - cd * cd), sin(angle)));
            double err = fabs(cd * cd + sd * sd - 1.0);
            if (err < best_err) {
                best_err = err;
                best.c = cd;
                best.s = sd;
            }
        }
    }
    return best;
}

static bench_pose make_pose(double x, double y, int rotation_index) {
    static rotation table[BENCH_ROTATIONS];
    static int ready = 0;
    if (!ready) {
        for (int i = 0; i < BENCH_ROTATIONS; ++i)
            table[i] = unit_rotation(-BENCH_PI + 2.0 * BENCH_PI * (i + 0.5) / BENCH_ROTATIONS);
        ready = 1;
    }
    bench_pose p;
    p.x = fl(x);
    p.y = fl(y);
    p.c = table[rotation_index].c;
    p.s = table[rotation_index].s;
    return p;
}

static int random_rotation(bench_rng *rng) {
    return (int)bench_rng_range(rng, 0.0, (double)BENCH_ROTATIONS);
}

void bench_make_pairs(int kind_a, int kind_b, uint64_t seed, bench_pair *pairs, int n) {
    bench_rng rng = bench_rng_make(seed ^ ((uint64_t)(kind_a * 16 + kind_b) << 40));
    for (int i = 0; i < n; ++i) {
        bench_pair *p = &pairs[i];
        int want_overlap = (i % 2) == 0;
        for (;;) {
            make_shape(&rng, kind_a, &p->a);
            make_shape(&rng, kind_b, &p->b);
            /* One draw per statement: the order in which a call's arguments
             * are evaluated is unspecified, and the pairs must not depend on
             * the compiler. */
            double ax = bench_rng_range(&rng, -4.0, 4.0);
            double ay = bench_rng_range(&rng, -4.0, 4.0);
            int rot_a = random_rotation(&rng);
            double dir = bench_rng_range(&rng, -BENCH_PI, BENCH_PI);
            int rot_b = random_rotation(&rng);
            double ux = cos(dir), uy = sin(dir);
            p->xa = make_pose(ax, ay, rot_a);
            bench_pose xb = make_pose(0.0, 0.0, rot_b);
            double reach =
                bench_ref_extent(&p->a, &p->xa, ux, uy) + bench_ref_extent(&p->b, &xb, -ux, -uy);
            double t =
                want_overlap ? bench_rng_range(&rng, 0.1, 1.0) : bench_rng_range(&rng, 0.7, 1.3);
            p->xb = make_pose(p->xa.x + t * reach * ux, p->xa.y + t * reach * uy, rot_b);
            p->ref_depth = bench_ref_depth(&p->a, &p->xa, &p->b, &p->xb);
            if (want_overlap && p->ref_depth >= BENCH_MIN_ABS_DEPTH) break;
            if (!want_overlap && p->ref_depth <= -BENCH_MIN_ABS_DEPTH) break;
        }
    }
}
