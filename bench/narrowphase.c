/* sepax benchmarks — the narrowphase benchmark: ns per pair of sx_overlap,
 * sx_mtv and sx_collide for every pair of shape kinds, beside Box2D v3 (the
 * headline peer), Box2D 2.4 and Chipmunk 7 on the very same pairs, with each
 * engine's depth error against a long double reference.
 *
 * For each pair type a few thousand seeded pairs (half overlapping) are built
 * once per engine in that engine's own types and timed by looping over the
 * whole array many times; every result feeds a sum that is returned and
 * stored in a volatile sink, so no call can be dropped. The engines are timed
 * in turns within each repetition (sepax overlap, mtv, collide, Box2D v3
 * overlap, collide, ...), so a burst of noise on the shared machine hits them
 * alike, and the best repetition is reported: interference only ever adds
 * time, so the best is the closest to the uncontended cost (the median over
 * best ratio is printed at the end as a noise gauge). Depth errors are taken
 * over the overlapping pairs: sepax's depth is its deepest manifold point
 * (and |mtv| for sx_mtv), Box2D v3's the separation of its deepest manifold
 * point (negated), Box2D 2.4's the deepest b2WorldManifold separation,
 * Chipmunk's the deepest contact distance; an overlapping pair with no
 * contact point counts as depth 0. Two independent long double references
 * (the tests' sx_ref_penetration and bench_ref_depth) must agree, or the run
 * fails. Writes DIR/narrowphase.csv and prints the tables. */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "lifecycle.h"
#include "pairs.h"
#include "reference.h"
#include "scenes.h"
#include "sepax/sepax.h"

/* The two references (the project's sx_ref_penetration on the sepax shapes,
 * bench_ref_depth on the shared descriptions) are computed independently in
 * long double; more disagreement than this means one of them is wrong, and
 * the run fails rather than report errors against a bad reference. */
#define REFERENCE_AGREEMENT 1e-9

/* The engine functions the table has a column for. */
enum {
    ROW_SX_OVERLAP = 0,
    ROW_SX_MTV,
    ROW_SX_COLLIDE,
    ROW_B3_OVERLAP,
    ROW_B3_COLLIDE,
    ROW_B3_COLLIDE_WORLD,
    ROW_B2_OVERLAP,
    ROW_B2_COLLIDE,
    ROW_B2_COLLIDE_WORLD,
    ROW_CP_COLLIDE,
    ROW_COUNT
};

static const char *const row_engine[ROW_COUNT] = {"sepax",  "sepax", "sepax", "box2d3", "box2d3",
                                                  "box2d3", "box2d", "box2d", "box2d",  "chipmunk"};
static const char *const row_function[ROW_COUNT] = {
    "overlap",       "mtv",     "collide", "overlap",       "collide",
    "collide_world", "overlap", "collide", "collide_world", "collide"};

/* Box2D v3's narrowphase is scalar code, the same in its three builds (the
 * run checks that their answers agree): the SSE2 build, v3's default, is the
 * one timed. */
#define B3 narrow_box2d3_sse2

/* The peers' pair sets of one pair type (NULL where a peer cannot run it). */
typedef struct peer_sets {
    const bench_box2d_set *b2;
    const bench_b3_set *b3;
    const bench_chipmunk_set *cp;
} peer_sets;

typedef struct sepax_pair {
    sx_shape a, b;
    sx_xform xa, xb;
} sepax_pair;

typedef struct options {
    int smoke;
    int pairs;
    int reps;
    double target_ms;
    uint64_t seed;
    const char *out_dir;
} options;

/* One row of results for one pair type. */
typedef struct result {
    int available;
    double ns;        /* best repetition, ns per pair */
    double ns_median; /* median repetition: ns_median / ns shows the noise */
    int has_depth;
    double max_err, p99_err;
    int wrong;          /* overlap answers that contradict the reference */
    int worst;          /* index of the pair of largest depth error */
    double worst_depth; /* the engine's depth there */
} result;

static volatile double bench_sink;

static double now_ns(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static sx_vec2 v2(const double *p) { return sx_v2((sx_real)p[0], (sx_real)p[1]); }

static int to_sepax_shape(const bench_shape *s, sx_shape *out) {
    sx_vec2 pts[BENCH_MAX_VERTICES];
    switch (s->kind) {
    case BENCH_CIRCLE: *out = sx_circle_shape(v2(s->v[0]), (sx_real)s->radius); return 1;
    case BENCH_SEGMENT: *out = sx_segment_shape(v2(s->v[0]), v2(s->v[1])); return 1;
    case BENCH_CAPSULE:
        *out = sx_capsule_shape(v2(s->v[0]), v2(s->v[1]), (sx_real)s->radius);
        return 1;
    case BENCH_BOX: *out = sx_box_shape((sx_real)s->hx, (sx_real)s->hy); return 1;
    default:
        for (int i = 0; i < s->count; ++i)
            pts[i] = v2(s->v[i]);
        return sx_polygon_shape(pts, s->count, (sx_real)s->radius, out) == SX_OK &&
               out->u.polygon.count == s->count;
    }
}

static sx_xform to_sepax_xform(const bench_pose *p) {
    sx_xform x;
    x.p = sx_v2((sx_real)p->x, (sx_real)p->y);
    x.q.c = (sx_real)p->c;
    x.q.s = (sx_real)p->s;
    return x;
}

static double sepax_run(const sepax_pair *p, int n, int row, int passes) {
    double sum = 0.0;
    for (int pass = 0; pass < passes; ++pass) {
        if (row == ROW_SX_OVERLAP) {
            for (int i = 0; i < n; ++i)
                sum += sx_overlap(&p[i].a, p[i].xa, &p[i].b, p[i].xb);
        } else if (row == ROW_SX_MTV) {
            for (int i = 0; i < n; ++i) {
                sx_vec2 mtv;
                sx_mtv(&p[i].a, p[i].xa, &p[i].b, p[i].xb, &mtv);
                sum += (double)mtv.x;
            }
        } else {
            for (int i = 0; i < n; ++i) {
                sx_manifold m;
                sum += sx_collide(&p[i].a, p[i].xa, &p[i].b, p[i].xb, &m);
            }
        }
    }
    return sum;
}

/* The peer function of a Box2D row (v3 or 2.4). */
static int row_fn(int row) {
    if (row == ROW_B3_OVERLAP || row == ROW_B2_OVERLAP) return BENCH_FN_OVERLAP;
    if (row == ROW_B3_COLLIDE || row == ROW_B2_COLLIDE) return BENCH_FN_COLLIDE;
    return BENCH_FN_COLLIDE_WORLD;
}

/* Runs one row over all pairs `passes` times; returns the elapsed ns. */
static double time_row(int row, const sepax_pair *sp, const peer_sets *ps, int n, int passes) {
    double t0 = now_ns(), sum;
    if (row <= ROW_SX_COLLIDE)
        sum = sepax_run(sp, n, row, passes);
    else if (row == ROW_CP_COLLIDE)
        sum = bench_chipmunk_run(ps->cp, passes);
    else if (row <= ROW_B3_COLLIDE_WORLD)
        sum = B3.run(ps->b3, row_fn(row), passes);
    else
        sum = bench_box2d_run(ps->b2, row_fn(row), passes);
    double t1 = now_ns();
    bench_sink = bench_sink + sum;
    return t1 - t0;
}

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

static double median(double *v, int n) {
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* Max and 99th percentile of |depth - reference| over overlapping pairs. */
static void depth_errors(const double *ref, const double *depth, int n, double *scratch,
                         result *r) {
    int m = 0;
    double worst = -1.0;
    for (int i = 0; i < n; ++i) {
        if (!(ref[i] > 0.0)) continue;
        scratch[m++] = fabs(depth[i] - ref[i]);
        if (scratch[m - 1] > worst) {
            worst = scratch[m - 1];
            r->worst = i;
            r->worst_depth = depth[i];
        }
    }
    r->has_depth = m > 0;
    if (m == 0) return;
    qsort(scratch, (size_t)m, sizeof *scratch, cmp_double);
    r->max_err = scratch[m - 1];
    int k = (int)ceil(0.99 * m) - 1;
    r->p99_err = scratch[k < 0 ? 0 : k];
}

static int count_wrong(const double *ref, const int *overlap, int n) {
    int wrong = 0;
    for (int i = 0; i < n; ++i)
        wrong += (overlap[i] != 0) != (ref[i] > 0.0);
    return wrong;
}

/* The accuracy side of one pair type: answers of every engine against the
 * reference (untimed). */
static void measure_accuracy(const double *ref, const sepax_pair *sp, const peer_sets *ps, int ka,
                             int kb, int n, result *res) {
    const bench_box2d_set *b2 = ps->b2;
    double *depth = malloc((size_t)n * sizeof *depth);
    double *scratch = malloc((size_t)n * sizeof *scratch);
    int *ovl = malloc((size_t)n * sizeof *ovl);
    if (!depth || !scratch || !ovl) {
        fprintf(stderr, "sepax_bench: out of memory\n");
        exit(1);
    }
    for (int i = 0; i < n; ++i)
        ovl[i] = sx_overlap(&sp[i].a, sp[i].xa, &sp[i].b, sp[i].xb);
    res[ROW_SX_OVERLAP].wrong = count_wrong(ref, ovl, n);

    for (int i = 0; i < n; ++i) {
        sx_vec2 mtv = sx_v2_zero();
        ovl[i] = sx_mtv(&sp[i].a, sp[i].xa, &sp[i].b, sp[i].xb, &mtv);
        depth[i] = hypot((double)mtv.x, (double)mtv.y);
    }
    res[ROW_SX_MTV].wrong = count_wrong(ref, ovl, n);
    depth_errors(ref, depth, n, scratch, &res[ROW_SX_MTV]);

    for (int i = 0; i < n; ++i) {
        sx_manifold m;
        int count = sx_collide(&sp[i].a, sp[i].xa, &sp[i].b, sp[i].xb, &m);
        double d = 0.0;
        for (int k = 0; k < count && k < 2; ++k)
            if (k == 0 || (double)m.points[k].depth > d) d = (double)m.points[k].depth;
        depth[i] = d;
        ovl[i] = count > 0;
    }
    res[ROW_SX_COLLIDE].wrong = count_wrong(ref, ovl, n);
    depth_errors(ref, depth, n, scratch, &res[ROW_SX_COLLIDE]);

    if (res[ROW_B3_OVERLAP].available) {
        B3.overlaps(ps->b3, ovl);
        res[ROW_B3_OVERLAP].wrong = count_wrong(ref, ovl, n);
    }
    if (res[ROW_B3_COLLIDE].available) {
        /* v3 answers speculative points on near pairs: its overlap answer is
         * a point of negative separation, i.e. a positive depth. */
        B3.depths(ps->b3, depth);
        for (int i = 0; i < n; ++i)
            ovl[i] = depth[i] > 0.0;
        res[ROW_B3_COLLIDE].wrong = count_wrong(ref, ovl, n);
        depth_errors(ref, depth, n, scratch, &res[ROW_B3_COLLIDE]);
        res[ROW_B3_COLLIDE_WORLD] = res[ROW_B3_COLLIDE];
    }
    if (b2 && bench_box2d_supports(ka, kb, BENCH_FN_OVERLAP)) {
        bench_box2d_overlaps(b2, ovl);
        res[ROW_B2_OVERLAP].wrong = count_wrong(ref, ovl, n);
    }
    if (b2 && bench_box2d_supports(ka, kb, BENCH_FN_COLLIDE)) {
        bench_box2d_depths(b2, depth);
        for (int i = 0; i < n; ++i)
            ovl[i] = depth[i] > 0.0;
        res[ROW_B2_COLLIDE].wrong = count_wrong(ref, ovl, n);
        depth_errors(ref, depth, n, scratch, &res[ROW_B2_COLLIDE]);
        res[ROW_B2_COLLIDE_WORLD] = res[ROW_B2_COLLIDE];
    }
    if (ps->cp) {
        bench_chipmunk_depths(ps->cp, depth);
        for (int i = 0; i < n; ++i)
            ovl[i] = depth[i] > 0.0;
        res[ROW_CP_COLLIDE].wrong = count_wrong(ref, ovl, n);
        depth_errors(ref, depth, n, scratch, &res[ROW_CP_COLLIDE]);
    }
    free(depth);
    free(scratch);
    free(ovl);
}

static void measure_speed(const sepax_pair *sp, const peer_sets *ps, int n, const options *opt,
                          result *res) {
    int passes[ROW_COUNT];
    double *times = malloc((size_t)(ROW_COUNT * opt->reps) * sizeof *times);
    if (!times) {
        fprintf(stderr, "sepax_bench: out of memory\n");
        exit(1);
    }
    /* One warm-up pass per row sizes its repetitions to about target_ms. */
    for (int r = 0; r < ROW_COUNT; ++r) {
        passes[r] = 1;
        if (!res[r].available || opt->smoke) continue;
        double t = time_row(r, sp, ps, n, 1);
        double want = opt->target_ms * 1e6 / (t > 1.0 ? t : 1.0);
        passes[r] = want < 1.0 ? 1 : (want > 1e6 ? 1000000 : (int)want);
    }
    for (int rep = 0; rep < opt->reps; ++rep)
        for (int r = 0; r < ROW_COUNT; ++r)
            if (res[r].available)
                times[r * opt->reps + rep] =
                    time_row(r, sp, ps, n, passes[r]) / ((double)passes[r] * (double)n);
    for (int r = 0; r < ROW_COUNT; ++r) {
        if (!res[r].available) continue;
        res[r].ns_median = median(&times[r * opt->reps], opt->reps);
        res[r].ns = times[r * opt->reps]; /* sorted by median() */
    }
    free(times);
}

/* ---- the floor of a circle-circle manifold ------------------------------
 * What any function that answers a unit normal, a contact point and a depth
 * for two placed circles must do at least: place both centres, compare the
 * squared distance, and for a touching pair take a square root and a
 * division. No validation, no care for coincident centres or underflow. It
 * is called out of line, as sx_collide and Box2D's functions are, and timed
 * like the table's cells, to show how far below Box2D's b2CollideCircles
 * (which computes neither normal nor depth) such an answer can go. */
static int floor_circles(const sx_circle *a, sx_xform xa, const sx_circle *b, sx_xform xb,
                         sx_manifold *m) {
    sx_vec2 ca = sx_xform_point(xa, a->center), cb = sx_xform_point(xb, b->center);
    sx_vec2 d = sx_sub(cb, ca);
    sx_real r = a->radius + b->radius, dsq = sx_dot(d, d), dist;
    if (dsq > r * r) {
        m->count = 0;
        return 0;
    }
    dist = sx_sqrt(dsq);
    m->normal = dist > SX_R(0.0) ? sx_scale(d, SX_R(1.0) / dist) : sx_v2(SX_R(1.0), SX_R(0.0));
    m->points[0].point = sx_mul_add(ca, SX_R(0.5) * (a->radius + dist - b->radius), m->normal);
    m->points[0].depth = r - dist;
    m->points[0].id = 0;
    m->count = 1;
    return 1;
}

static int (*volatile floor_circles_fn)(const sx_circle *, sx_xform, const sx_circle *, sx_xform,
                                        sx_manifold *) = floor_circles;

/* Best-of-reps ns per pair of the floor and of sx_collide on the same
 * circle pairs, interleaved rep by rep. */
static void measure_floor(const sepax_pair *sp, int n, const options *opt, double *floor_ns,
                          double *sx_ns) {
    int passes = opt->smoke ? 1 : 200;
    *floor_ns = *sx_ns = 1e300;
    for (int rep = 0; rep < opt->reps; ++rep) {
        double t0 = now_ns(), sum = 0.0;
        for (int pass = 0; pass < passes; ++pass) {
            for (int i = 0; i < n; ++i) {
                sx_manifold m;
                sum +=
                    floor_circles_fn(&sp[i].a.u.circle, sp[i].xa, &sp[i].b.u.circle, sp[i].xb, &m);
            }
        }
        double t1 = now_ns();
        double t = (t1 - t0) / ((double)passes * (double)n);
        if (t < *floor_ns) *floor_ns = t;
        bench_sink = bench_sink + sum;
        t0 = now_ns();
        sum = sepax_run(sp, n, ROW_SX_COLLIDE, passes);
        t1 = now_ns();
        t = (t1 - t0) / ((double)passes * (double)n);
        if (t < *sx_ns) *sx_ns = t;
        bench_sink = bench_sink + sum;
    }
}

static int make_dirs(const char *path) {
    char buf[1024];
    size_t len = strlen(path);
    if (len == 0 || len >= sizeof buf) return 0;
    memcpy(buf, path, len + 1);
    for (size_t i = 1; i <= len; ++i) {
        if (buf[i] != '/' && buf[i] != '\0') continue;
        char c = buf[i];
        buf[i] = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) return 0;
        buf[i] = c;
    }
    return 1;
}

static void dump_shape(FILE *f, const char *label, const bench_shape *s, const bench_pose *x) {
    fprintf(f, "  %s: %s radius %.9g, pose p = (%.9g, %.9g) cos/sin = (%.9g, %.9g), core", label,
            bench_kind_name(s->kind), s->radius, x->x, x->y, x->c, x->s);
    for (int i = 0; i < s->count; ++i)
        fprintf(f, " (%.9g, %.9g)", s->v[i][0], s->v[i][1]);
    fprintf(f, "\n");
}

/* The pair of largest depth error of each sepax function and of Box2D v3's
 * collide, with every number needed to replay it (float values printed
 * exactly with %.9g). */
static void dump_worst(FILE *f, const char *name, const bench_pair *pairs, const double *ref,
                       const result *res) {
    static const int rows[] = {ROW_SX_MTV, ROW_SX_COLLIDE, ROW_B3_COLLIDE};
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; ++k) {
        int r = rows[k];
        if (!res[r].available || !res[r].has_depth) continue;
        int i = res[r].worst;
        fprintf(f, "%s %s %s: pair %d, depth %.9g, reference %.12g, error %.3g\n", name,
                row_engine[r], row_function[r], i, res[r].worst_depth, ref[i], res[r].max_err);
        dump_shape(f, "A", &pairs[i].a, &pairs[i].xa);
        dump_shape(f, "B", &pairs[i].b, &pairs[i].xb);
    }
}

static void print_ns(double ns, int available) {
    if (available)
        printf(" %7.1f", ns);
    else
        printf(" %7s", "n/a");
}

static void print_err(const result *r) {
    if (r->available && r->has_depth)
        printf(" %9.2e %9.2e", r->max_err, r->p99_err);
    else
        printf(" %9s %9s", "n/a", "n/a");
}

static void print_ratio(double sx_ns, const result *peer) {
    if (peer->available && peer->ns > 0.0)
        printf(" %6.2f", sx_ns / peer->ns);
    else
        printf(" %6s", "n/a");
}

static void print_wrong(const result *r) {
    if (r->available)
        printf("%d", r->wrong);
    else
        printf("n/a");
}

/* One line of the main table: sepax against Box2D v3. */
static void print_b3_row(const char *name, const result *res) {
    const result *so = &res[ROW_SX_OVERLAP], *sc = &res[ROW_SX_COLLIDE];
    const result *vo = &res[ROW_B3_OVERLAP], *vc = &res[ROW_B3_COLLIDE];
    const result *vw = &res[ROW_B3_COLLIDE_WORLD];
    printf("%-17s", name);
    print_ns(so->ns, 1);
    print_ns(res[ROW_SX_MTV].ns, 1);
    print_ns(sc->ns, 1);
    printf(" |");
    print_ns(vo->ns, vo->available);
    print_ns(vc->ns, vc->available);
    print_ns(vw->ns, vw->available);
    printf(" |");
    print_ratio(sc->ns, vc);
    print_ratio(sc->ns, vw);
    print_ratio(so->ns, vo);
    printf(" %5.1f |", sc->ns / so->ns);
    print_err(sc);
    printf(" |");
    print_err(vc);
    printf(" | %d/%d/%d ", so->wrong, res[ROW_SX_MTV].wrong, sc->wrong);
    print_wrong(vo);
    printf("/");
    print_wrong(vc);
    printf("\n");
}

/* One line of the Box2D 2.4 table. */
static void print_b2_row(const char *name, const result *res) {
    const result *sc = &res[ROW_SX_COLLIDE], *bo = &res[ROW_B2_OVERLAP];
    const result *bc = &res[ROW_B2_COLLIDE], *bw = &res[ROW_B2_COLLIDE_WORLD];
    printf("%-17s", name);
    print_ns(sc->ns, 1);
    printf(" |");
    print_ns(bo->ns, bo->available);
    print_ns(bc->ns, bc->available);
    print_ns(bw->ns, bw->available);
    printf(" |");
    if (bc->available)
        printf(" %5.2f |", sc->ns / bc->ns);
    else
        printf(" %5s |", "n/a");
    print_err(bc);
    printf(" | ");
    print_wrong(bo);
    printf("/");
    print_wrong(bc);
    printf("\n");
}

static void print_floor(double floor_ns, double sx_ns, const result *res) {
    const result *vc = &res[ROW_B3_COLLIDE], *vw = &res[ROW_B3_COLLIDE_WORLD];
    const result *bc = &res[ROW_B2_COLLIDE], *bw = &res[ROW_B2_COLLIDE_WORLD];
    printf("floor of a circle-circle manifold (place, compare, sqrt, divide, store; no "
           "validation; bench/narrowphase.c floor_circles): %.1f ns",
           floor_ns);
    if (vc->available)
        printf(" = %.2f x v3's b2CollideCircles (%.1f ns, normal and separation in A's frame), "
               "%.2f x v3 + world space (%.1f ns)",
               floor_ns / vc->ns, vc->ns, floor_ns / vw->ns, vw->ns);
    if (bc->available)
        printf("%s%.2f x 2.4's b2CollideCircles (%.1f ns, no normal or depth), %.2f x 2.4 + "
               "b2WorldManifold (%.1f ns)",
               vc->available ? ", " : " = ", floor_ns / bc->ns, bc->ns, floor_ns / bw->ns, bw->ns);
    printf("; sx_collide %.1f ns = %.2f x the floor (interleaved with it)\n", sx_ns,
           sx_ns / floor_ns);
}

/* Box2D v3's scalar and AVX2 builds against the timed SSE2 build. */
typedef struct b3_agreement {
    int pairs;     /* pairs compared, per build */
    int avx2;      /* the AVX2 build ran (the CPU has AVX2) */
    int differ[2]; /* depth or overlap answers not the same bits: scalar, AVX2 */
} b3_agreement;

/* Runs the other v3 builds on the pairs and counts the answers that differ
 * from the SSE2 build's: v3's narrowphase is the same scalar C in every
 * build, so any difference would make the timed build unrepresentative. */
static int b3_builds_agree(const bench_pair *pairs, int n, const bench_b3_set *sse2, int ka, int kb,
                           b3_agreement *ag) {
    const bench_b3_narrow *other[2] = {&narrow_box2d3_scalar, &narrow_box2d3_avx2};
    int builds = __builtin_cpu_supports("avx2") ? 2 : 1, ok = 1;
    int collides = B3.supports(ka, kb, BENCH_FN_COLLIDE);
    double *d0 = malloc((size_t)n * sizeof *d0), *d1 = malloc((size_t)n * sizeof *d1);
    int *o0 = malloc((size_t)n * sizeof *o0), *o1 = malloc((size_t)n * sizeof *o1);
    if (!d0 || !d1 || !o0 || !o1) {
        fprintf(stderr, "sepax_bench: out of memory\n");
        exit(1);
    }
    if (collides) B3.depths(sse2, d0);
    B3.overlaps(sse2, o0);
    for (int b = 0; b < builds; ++b) {
        bench_b3_set *set = other[b]->build(pairs, n);
        if (!set) {
            ok = 0;
            continue;
        }
        if (collides) other[b]->depths(set, d1);
        other[b]->overlaps(set, o1);
        for (int i = 0; i < n; ++i)
            ag->differ[b] +=
                (collides && memcmp(&d0[i], &d1[i], sizeof d0[i]) != 0) || o0[i] != o1[i];
        other[b]->free(set);
    }
    ag->pairs += n;
    ag->avx2 = builds == 2;
    free(d0);
    free(d1);
    free(o0);
    free(o1);
    return ok;
}

static void print_b3_agreement(const b3_agreement *ag) {
    printf("Box2D v3 builds (the SSE2 one is timed): on all %d pairs the scalar build answers "
           "%d depths or overlaps differently",
           ag->pairs, ag->differ[0]);
    if (ag->avx2)
        printf(", the AVX2 build %d\n", ag->differ[1]);
    else
        printf("; the AVX2 build was not run (no AVX2 on this CPU)\n");
}

static void usage(void) {
    printf("usage: sepax_bench [--smoke] [--out DIR] [--pairs N] [--reps N] [--seed S]\n"
           "  --smoke    every pair type for a handful of iterations (proves the suite runs)\n"
           "  --out DIR  directory of narrowphase.csv (default build/bench)\n"
           "  --pairs N  pairs per pair type (default 4096)\n"
           "  --reps N   timed repetitions, the best is reported (default 21)\n"
           "  --seed S   seed of the pair generator (default 2024)\n");
}

static int parse(int argc, char **argv, options *o) {
    o->smoke = 0;
    o->pairs = 4096;
    o->reps = 21;
    o->target_ms = 2.0;
    o->seed = 2024;
    o->out_dir = "build/bench";
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--smoke") == 0) {
            o->smoke = 1;
        } else if (strcmp(a, "--out") == 0 && val) {
            o->out_dir = val;
            ++i;
        } else if (strcmp(a, "--pairs") == 0 && val && atoi(val) > 0) {
            o->pairs = atoi(val);
            ++i;
        } else if (strcmp(a, "--reps") == 0 && val && atoi(val) > 0) {
            o->reps = atoi(val);
            ++i;
        } else if (strcmp(a, "--seed") == 0 && val) {
            o->seed = (uint64_t)strtoull(val, NULL, 10);
            ++i;
        } else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage();
            exit(0);
        } else {
            usage();
            return 0;
        }
    }
    if (o->smoke) {
        o->pairs = 64;
        o->reps = 1;
    }
    return 1;
}

int main(int argc, char **argv) {
    options opt;
    /* The world scenes (bench/scenes.c) run after the narrowphase table:
     * --scenes runs them alone, --no-scenes skips them, --quick shortens
     * the large ones, --full runs docs/scenes.md's lengths. These flags are
     * taken out before parse() sees argv. */
    int scenes = 1, scenes_only = 0, scene_level = 0, nargs = 1, lifecycle_only = 0;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--lifecycle") == 0)
            lifecycle_only = 1; /* bench/lifecycle.c alone */
        else if (strcmp(argv[i], "--scenes") == 0)
            scenes_only = 1;
        else if (strcmp(argv[i], "--no-scenes") == 0)
            scenes = 0;
        else if (strcmp(argv[i], "--quick") == 0)
            scene_level = 1;
        else if (strcmp(argv[i], "--full") == 0)
            scene_level = 2;
        else
            argv[nargs++] = argv[i];
    }
    argc = nargs;
    if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0))
        printf("[--lifecycle] only the wake/destroy figures (bench/lifecycle.c)\n"
               "world scenes: [--scenes] only the scenes, [--no-scenes] only the narrowphase,\n"
               "  [--quick] fewer steps in the large scenes, [--full] docs/scenes.md's full lengths\n");
    if (!parse(argc, argv, &opt)) return 2;
    if (!make_dirs(opt.out_dir)) {
        fprintf(stderr, "sepax_bench: cannot create %s: %s\n", opt.out_dir, strerror(errno));
        return 1;
    }
    if (lifecycle_only) return bench_lifecycle_run(opt.out_dir, opt.smoke) ? 1 : 0;
    if (scenes_only) return bench_scenes_run(opt.out_dir, opt.smoke, scene_level) ? 1 : 0;
    char csv_path[1100];
    snprintf(csv_path, sizeof csv_path, "%s/narrowphase.csv", opt.out_dir);
    FILE *csv = fopen(csv_path, "w");
    if (!csv) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", csv_path, strerror(errno));
        return 1;
    }
    fprintf(csv, "pair,engine,function,ns_per_pair,max_depth_err,p99_depth_err,n\n");
    char worst_path[1100];
    snprintf(worst_path, sizeof worst_path, "%s/narrowphase_worst.txt", opt.out_dir);
    FILE *worst = fopen(worst_path, "w");
    if (!worst) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", worst_path, strerror(errno));
        return 1;
    }

    const int n = opt.pairs;
    bench_pair *pairs = malloc((size_t)n * sizeof *pairs);
    sepax_pair *sp = malloc((size_t)n * sizeof *sp);
    double *ref = malloc((size_t)n * sizeof *ref);
    double ref_disagreement = 0.0;
    if (!pairs || !sp || !ref) {
        fprintf(stderr, "sepax_bench: out of memory\n");
        return 1;
    }
    char b2_name[64], b3_name[64], cp_name[64];
    bench_box2d_version(b2_name, (int)sizeof b2_name);
    B3.version(b3_name, (int)sizeof b3_name);
    bench_chipmunk_version(cp_name, (int)sizeof cp_name);
#ifdef SX_DOUBLE
    const char *sepax_engine = "sepax-double";
#else
    const char *sepax_engine = "sepax";
#endif
    printf("sepax narrowphase benchmark%s: sx_real = %s, peers %s (v3, SSE2 build), %s, %s; "
           "%d pairs per type (half overlapping), best of %d reps\n",
           opt.smoke ? " (smoke)" : "", sizeof(sx_real) == sizeof(double) ? "double" : "float",
           b3_name, b2_name, cp_name, n, opt.reps);
    printf("working set: %d pairs x %d bytes per sepax pair (two sx_shape of %d bytes and two "
           "transforms)\n",
           n, (int)sizeof(sepax_pair), (int)sizeof(sx_shape));
    printf("ns per pair; v3 col = B's transform in A's frame + b2Collide* (answer in A's frame), "
           "v3 c+w = the same moved to world space as sx_collide answers;\n"
           "/v3 = sx col / v3 col, /v3+w = sx col / v3 c+w, ovl/v3 = sx ovl / v3 ovl "
           "(< 1: sepax faster); ovl x = sx col / sx ovl;\n"
           "depth errors |depth - reference| in metres over the overlapping pairs "
           "(long double reference); wrong = overlap answers contradicting it\n\n");
    printf("%-17s %7s %7s %7s | %7s %7s %7s | %6s %6s %6s %5s | %9s %9s | %9s %9s | %s\n", "pair",
           "sx ovl", "sx mtv", "sx col", "v3 ovl", "v3 col", "v3 c+w", "/v3", "/v3+w", "ovl/v3",
           "ovl x", "sx max", "sx p99", "v3 max", "v3 p99", "wrong: sx o/m/c v3 o/c");

    int failures = 0, ntypes = 0;
    b3_agreement agree = {0, 0, {0, 0}};
    double floor_ns = 0.0, floor_sx_ns = 0.0;
    const result *floor_res = NULL;
    static result all[BENCH_KIND_COUNT * (BENCH_KIND_COUNT + 1) / 2][ROW_COUNT];
    static char names[BENCH_KIND_COUNT * (BENCH_KIND_COUNT + 1) / 2][40];
    for (int ka = 0; ka < BENCH_KIND_COUNT; ++ka) {
        for (int kb = 0; kb <= ka; ++kb) {
            char name[sizeof names[0]];
            snprintf(name, sizeof name, "%s-%s", bench_kind_name(ka), bench_kind_name(kb));
            bench_make_pairs(ka, kb, opt.seed, pairs, n);
            int ok = 1;
            for (int i = 0; i < n && ok; ++i) {
                ok = to_sepax_shape(&pairs[i].a, &sp[i].a) && to_sepax_shape(&pairs[i].b, &sp[i].b);
                sp[i].xa = to_sepax_xform(&pairs[i].xa);
                sp[i].xb = to_sepax_xform(&pairs[i].xb);
            }
            if (!ok) {
                fprintf(stderr, "sepax_bench: %s: the sepax builder changed a polygon\n", name);
                ++failures;
                continue;
            }
            for (int i = 0; i < n; ++i) {
                sx_ref_result rr;
                if (!sx_ref_penetration(&sp[i].a, sp[i].xa, &sp[i].b, sp[i].xb, &rr)) {
                    fprintf(stderr, "sepax_bench: %s: sx_ref_penetration refused pair %d\n", name,
                            i);
                    return 1;
                }
                ref[i] = (double)rr.depth;
                double gap = fabs(ref[i] - pairs[i].ref_depth);
                if (gap > ref_disagreement) ref_disagreement = gap;
            }
            bench_box2d_set *b2 = bench_box2d_build(pairs, n);
            bench_b3_set *b3 = B3.build(pairs, n);
            bench_chipmunk_set *cp = bench_chipmunk_build(pairs, n);
            peer_sets ps = {b2, b3, cp};
            result *res = all[ntypes];
            snprintf(names[ntypes], sizeof names[ntypes], "%s", name);
            ++ntypes;
            memset(res, 0, sizeof all[0]);
            res[ROW_CP_COLLIDE].available = cp != NULL;
            res[ROW_SX_OVERLAP].available = res[ROW_SX_MTV].available =
                res[ROW_SX_COLLIDE].available = 1;
            res[ROW_B3_OVERLAP].available = b3 && B3.supports(ka, kb, BENCH_FN_OVERLAP);
            res[ROW_B3_COLLIDE].available = res[ROW_B3_COLLIDE_WORLD].available =
                b3 && B3.supports(ka, kb, BENCH_FN_COLLIDE);
            res[ROW_B2_OVERLAP].available = b2 && bench_box2d_supports(ka, kb, BENCH_FN_OVERLAP);
            res[ROW_B2_COLLIDE].available = res[ROW_B2_COLLIDE_WORLD].available =
                b2 && bench_box2d_supports(ka, kb, BENCH_FN_COLLIDE);
            if (!b3) {
                fprintf(stderr, "sepax_bench: %s: Box2D v3 changed a polygon\n", name);
                ++failures;
            }
            if (!b2 && bench_box2d_supports(ka, kb, BENCH_FN_OVERLAP)) {
                fprintf(stderr, "sepax_bench: %s: Box2D changed a polygon\n", name);
                ++failures;
            }

            measure_accuracy(ref, sp, &ps, ka, kb, n, res);
            if (b3 && !b3_builds_agree(pairs, n, b3, ka, kb, &agree)) {
                fprintf(stderr, "sepax_bench: %s: the Box2D v3 builds refused the pairs\n", name);
                ++failures;
            }
            measure_speed(sp, &ps, n, &opt, res);
            if (ka == BENCH_CIRCLE && kb == BENCH_CIRCLE) {
                measure_floor(sp, n, &opt, &floor_ns, &floor_sx_ns);
                floor_res = res;
            }
            print_b3_row(name, res);

            for (int r = 0; r < ROW_COUNT; ++r) {
                if (!res[r].available) continue;
                fprintf(csv, "%s,%s,%s,%.3f,", name,
                        r <= ROW_SX_COLLIDE ? sepax_engine : row_engine[r], row_function[r],
                        res[r].ns);
                if (res[r].has_depth)
                    fprintf(csv, "%.9g,%.9g,%d\n", res[r].max_err, res[r].p99_err, n);
                else
                    fprintf(csv, ",,%d\n", n);
            }
            dump_worst(worst, name, pairs, ref, res);
            bench_box2d_free(b2);
            B3.free(b3);
            bench_chipmunk_free(cp);
        }
    }
    printf("\n%s (Debian's build, asserts compiled in) on the same pairs: b2 col = b2Collide*, "
           "b2 c+wm = + b2WorldManifold, b2 ovl = b2TestOverlap; ratio = sx col / b2 col\n",
           b2_name);
    printf("%-17s %7s | %7s %7s %7s | %5s | %9s %9s | %s\n", "pair", "sx col", "b2 ovl", "b2 col",
           "b2 c+wm", "ratio", "b2 max", "b2 p99", "wrong b2 o/c");
    for (int t = 0; t < ntypes; ++t)
        print_b2_row(names[t], all[t]);
    printf("\n%s (double precision, cpShapesCollide) on the same pairs:\n", cp_name);
    printf("%-17s %7s %7s | %5s | %9s %9s | %s\n", "pair", "sx col", "cp col", "ratio", "cp max",
           "cp p99", "wrong cp");
    for (int t = 0; t < ntypes; ++t) {
        const result *sc = &all[t][ROW_SX_COLLIDE], *cc = &all[t][ROW_CP_COLLIDE];
        printf("%-17s", names[t]);
        print_ns(sc->ns, 1);
        print_ns(cc->ns, cc->available);
        if (cc->available)
            printf(" | %5.2f |", sc->ns / cc->ns);
        else
            printf(" | %5s |", "n/a");
        print_err(cc);
        printf(" | %d\n", cc->wrong);
    }
    printf("\nsx mtv depth = |mtv|; its errors are in %s, the pair of largest error of each "
           "sepax function and of v3's collide in %s. Box2D 2.4 shapes carry the benchmark "
           "shapes' own radii (0 for sharp polygons and segments) instead of "
           "b2_polygonRadius: see bench/peer_box2d.cpp. v3 has no such skin; its manifolds "
           "include speculative points (separation up to 2 cm): its collide counts as "
           "overlapping when a point has a negative separation.\n",
           csv_path, worst_path);
    print_b3_agreement(&agree);
    if (floor_res && floor_ns > 0.0) print_floor(floor_ns, floor_sx_ns, floor_res);
    {
        double gauge[BENCH_KIND_COUNT * (BENCH_KIND_COUNT + 1) / 2 * ROW_COUNT];
        int g = 0;
        for (int t = 0; t < ntypes; ++t)
            for (int r = 0; r < ROW_COUNT; ++r)
                if (all[t][r].available && all[t][r].ns > 0.0)
                    gauge[g++] = all[t][r].ns_median / all[t][r].ns;
        if (g > 0) {
            double med = median(gauge, g);
            printf("timing noise: median/best repetition over all cells: median %.2f, max %.2f\n",
                   med, gauge[g - 1]);
        }
    }
    printf("references: sx_ref_penetration (tests/support/reference.c, hull of the Minkowski "
           "difference) against bench_ref_depth (bench/reference_depth.c, SAT + vertex-edge): "
           "max disagreement %.2e m\n",
           ref_disagreement);
    if (ref_disagreement > REFERENCE_AGREEMENT) {
        fprintf(stderr, "sepax_bench: the two references disagree by %.3g m\n", ref_disagreement);
        ++failures;
    }
    fclose(csv);
    fclose(worst);
    free(ref);
    free(pairs);
    free(sp);
    if (failures) fprintf(stderr, "sepax_bench: %d pair types failed\n", failures);
    failures += bench_lifecycle_run(opt.out_dir, opt.smoke);
    if (scenes) failures += bench_scenes_run(opt.out_dir, opt.smoke, scene_level);
    return failures ? 1 : 0;
}
