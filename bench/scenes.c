/* sepax benchmarks — world-level scenes (/work/shared/SCENES.md) run by sepax,
 * Box2D 2.4 and Chipmunk 7 in the same process, single thread.
 *
 * Every scene is built once as plain data (bench/scenes.h) and each engine
 * makes its own world from it, so the bodies, shapes, densities and
 * frictions are the same numbers for all three, and the code that measures a
 * scene's figure reads body states through one interface. Throughput scenes
 * (large_pyramid, mostly_asleep, rain) report ms per step; accuracy scenes
 * with a known answer or a conserved quantity (bounce, incline, pyramid20,
 * stack20, cradle, projectile, pileup, mass_ratio, overlap_recovery,
 * consistency) sweep the time step and the sub-step or iteration counts and
 * report error against ms per step, drawn as one SVG plot per scene
 * (bench/svg_plot.c). Everything printed is also written to REPORT.md, and
 * every row to scenes.csv; the headline table (does a sepax configuration
 * beat both peers on each scene, or by how much does it miss) ends
 * REPORT.md and is also written alone to headline.md.
 *
 * Timing: wall clock (CLOCK_MONOTONIC) around the stepping only, world
 * creation excluded; the first step of large_pyramid is left out of its
 * timing as SCENES.md says (time steps 2..N). Single runs, no repetitions:
 * the scenes are long enough (>= 0.1 s per engine for the throughput ones)
 * that scheduler noise stays within a few per cent, and they are reported as
 * measured. */
#define _POSIX_C_SOURCE 200809L
#include "scenes.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <sepax/sepax.h>

static const double PI = 3.14159265358979323846;

#ifdef SX_DOUBLE
static const char *const engine_names[SCENE_ENGINE_COUNT] = {"sepax-double", "box2d", "chipmunk"};
#else
static const char *const engine_names[SCENE_ENGINE_COUNT] = {"sepax", "box2d", "chipmunk"};
#endif

/* The printed report goes to stdout and, between code fences, to REPORT.md. */
static FILE *report_file;
static FILE *csv_file;

static void out(const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    if (report_file) {
        va_start(ap, fmt);
        vfprintf(report_file, fmt, ap);
        va_end(ap);
    }
}

/* Throughput results where sepax is slower than a peer (or misses its own
 * target), collected for the headline's "where sepax does not win". */
static char speed_notes[16][200];
static int speed_note_count;

static void speed_note(const char *fmt, ...) {
    if (speed_note_count == 16) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(speed_notes[speed_note_count++], sizeof speed_notes[0], fmt, ap);
    va_end(ap);
}

/* Markdown only (not printed). */
static void md(const char *fmt, ...) {
    if (!report_file) return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(report_file, fmt, ap);
    va_end(ap);
}

static double now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* ---- scene descriptions -------------------------------------------------- */

static int scene_init(scene_def *d, int capacity) {
    d->bodies = malloc((size_t)capacity * sizeof *d->bodies);
    d->count = 0;
    d->capacity = capacity;
    d->gx = 0.0;
    d->gy = -10.0;
    d->sleep = 0;
    return d->bodies != NULL;
}

static void scene_free(scene_def *d) {
    free(d->bodies);
    d->bodies = NULL;
    d->count = d->capacity = 0;
}

static scene_body *scene_add(scene_def *d, int dynamic, double x, double y, double angle) {
    if (d->count == d->capacity) {
        int cap = d->capacity * 2 + 16;
        scene_body *b = realloc(d->bodies, (size_t)cap * sizeof *b);
        if (!b) {
            fprintf(stderr, "sepax_bench: out of memory\n");
            exit(1);
        }
        d->bodies = b;
        d->capacity = cap;
    }
    scene_body *b = &d->bodies[d->count++];
    memset(b, 0, sizeof *b);
    b->dynamic = dynamic;
    b->x = x;
    b->y = y;
    b->angle = angle;
    b->density = 1.0;
    b->friction = 0.6;
    return b;
}

static void set_box(scene_body *b, double hx, double hy) {
    b->shape.kind = BENCH_BOX;
    b->shape.count = 4;
    b->shape.hx = hx;
    b->shape.hy = hy;
    const double c[4][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    memcpy(b->shape.v, c, sizeof c);
}

static void set_circle(scene_body *b, double r) {
    b->shape.kind = BENCH_CIRCLE;
    b->shape.count = 1;
    b->shape.radius = r;
}

static void set_capsule(scene_body *b, double half_length, double r) {
    b->shape.kind = BENCH_CAPSULE;
    b->shape.count = 2;
    b->shape.v[0][0] = -half_length;
    b->shape.v[1][0] = half_length;
    b->shape.radius = r;
}

/* Regular n-gon of circumradius r, centred on its centroid. */
static void set_ngon(scene_body *b, int n, double r) {
    b->shape.kind = BENCH_POLYGON;
    b->shape.count = n;
    for (int i = 0; i < n; ++i) {
        double a = 2.0 * PI * (double)i / (double)n;
        b->shape.v[i][0] = r * cos(a);
        b->shape.v[i][1] = r * sin(a);
    }
}

/* SCENES.md's ground: static box 100 x 1 centred at (0, -1). */
static void add_ground(scene_def *d, double half_width) {
    set_box(scene_add(d, 0, 0.0, -1.0, 0.0), half_width, 1.0);
}

/* ---- the sepax engine ------------------------------------------------------ */

typedef struct sepax_world {
    sx_world *world;
    sx_body_id *ids;
    sx_real dt;
} sepax_world;

static int sepax_shape(const bench_shape *s, sx_shape *o) {
    sx_vec2 p[BENCH_MAX_VERTICES];
    for (int i = 0; i < s->count && i < BENCH_MAX_VERTICES; ++i)
        p[i] = sx_v2((sx_real)s->v[i][0], (sx_real)s->v[i][1]);
    switch (s->kind) {
    case BENCH_CIRCLE: *o = sx_circle_shape(p[0], (sx_real)s->radius); return 1;
    case BENCH_SEGMENT: *o = sx_segment_shape(p[0], p[1]); return 1;
    case BENCH_CAPSULE: *o = sx_capsule_shape(p[0], p[1], (sx_real)s->radius); return 1;
    case BENCH_BOX: *o = sx_box_shape((sx_real)s->hx, (sx_real)s->hy); return 1;
    default: return sx_polygon_shape(p, s->count, (sx_real)s->radius, o) == SX_OK;
    }
}

static void sepax_destroy(void *w) {
    sepax_world *sw = w;
    if (!sw) return;
    sx_world_destroy(sw->world);
    free(sw->ids);
    free(sw);
}

static void *sepax_create(const scene_def *def, const scene_config *cfg) {
    sx_world_def wd = sx_default_world_def();
    wd.gravity = sx_v2((sx_real)def->gx, (sx_real)def->gy);
    wd.sub_steps = cfg->sub_steps;
    wd.velocity_iterations = cfg->vel_iters;
    wd.position_iterations = cfg->pos_iters;
    wd.enable_sleep = def->sleep != 0;
    wd.body_capacity = def->count;
    sepax_world *sw = calloc(1, sizeof *sw);
    if (!sw) return NULL;
    sw->world = sx_world_create(&wd);
    sw->ids = malloc((size_t)(def->count > 0 ? def->count : 1) * sizeof *sw->ids);
    sw->dt = (sx_real)cfg->dt;
    if (!sw->world || !sw->ids) {
        sepax_destroy(sw);
        return NULL;
    }
    for (int i = 0; i < def->count; ++i) {
        const scene_body *b = &def->bodies[i];
        sx_body_def bd = sx_default_body_def();
        bd.type = b->dynamic ? SX_BODY_DYNAMIC : SX_BODY_STATIC;
        bd.position = sx_v2((sx_real)b->x, (sx_real)b->y);
        bd.angle = (sx_real)b->angle;
        bd.linear_velocity = sx_v2((sx_real)b->vx, (sx_real)b->vy);
        sx_collider_def cd = sx_default_collider_def();
        cd.density = (sx_real)b->density;
        cd.friction = (sx_real)b->friction;
        cd.restitution = (sx_real)b->restitution;
        if (!sepax_shape(&b->shape, &cd.shape) ||
            sx_create_body(sw->world, &bd, &sw->ids[i]) != SX_OK ||
            sx_body_add_collider(sw->world, sw->ids[i], &cd, NULL) != SX_OK) {
            sepax_destroy(sw);
            return NULL;
        }
    }
    return sw;
}

static void sepax_step(void *w, int steps) {
    sepax_world *sw = w;
    for (int i = 0; i < steps; ++i)
        sx_world_step(sw->world, sw->dt);
}

static void sepax_get(void *w, int body, scene_state *o) {
    sepax_world *sw = w;
    sx_body_id id = sw->ids[body];
    sx_vec2 p = sx_body_get_position(sw->world, id);
    sx_vec2 v = sx_body_get_linear_velocity(sw->world, id);
    o->x = (double)p.x;
    o->y = (double)p.y;
    o->angle = (double)sx_body_get_angle(sw->world, id);
    o->vx = (double)v.x;
    o->vy = (double)v.y;
    o->w = (double)sx_body_get_angular_velocity(sw->world, id);
}

typedef struct engine {
    void *(*create)(const scene_def *, const scene_config *);
    void (*step)(void *, int);
    void (*get)(void *, int, scene_state *);
    void (*destroy)(void *);
} engine;

static const engine engines[SCENE_ENGINE_COUNT] = {
    {sepax_create, sepax_step, sepax_get, sepax_destroy},
    {scene_box2d_create, scene_box2d_step, scene_box2d_get, scene_box2d_destroy},
    {scene_chipmunk_create, scene_chipmunk_step, scene_chipmunk_get, scene_chipmunk_destroy},
};

/* Each engine's standard knobs: sepax's defaults (4 sub-steps of 4 velocity
 * and 2 position iterations), Box2D 8/3, Chipmunk 8 (SCENES.md). */
static scene_config default_config(int e, double dt) {
    scene_config c = {dt, 1, 8, 3};
    if (e == SCENE_SEPAX) {
        sx_world_def wd = sx_default_world_def();
        c.sub_steps = wd.sub_steps;
        c.vel_iters = wd.velocity_iterations;
        c.pos_iters = wd.position_iterations;
    } else if (e == SCENE_CHIPMUNK) {
        c.pos_iters = 0;
    }
    return c;
}

static void config_name(int e, const scene_config *c, char *buf, size_t size) {
    int hz = (int)lround(1.0 / c->dt);
    if (e == SCENE_SEPAX)
        snprintf(buf, size, "dt=1/%d sub=%d vel=%d pos=%d", hz, c->sub_steps, c->vel_iters,
                 c->pos_iters);
    else if (e == SCENE_BOX2D)
        snprintf(buf, size, "dt=1/%d vel=%d pos=%d", hz, c->vel_iters, c->pos_iters);
    else
        snprintf(buf, size, "dt=1/%d iter=%d", hz, c->vel_iters);
}

/* Cost of one 1/60 s frame of simulated time: the fair cost across time
 * steps (a run at 1/240 takes four steps per frame). */
static double frame_ms(double ms_per_step, const scene_config *c) {
    return ms_per_step * (1.0 / 60.0) / c->dt;
}

static void csv_row(const char *scene, int e, const scene_config *c, int bodies, int steps,
                    double ms, const char *err_name, double err, const char *details) {
    char cfg[96];
    config_name(e, c, cfg, sizeof cfg);
    fprintf(csv_file, "%s,%s,%s,%d,%d,%.6f,%.6f,%s,%.9g,%s\n", scene, engine_names[e], cfg, bodies,
            steps, ms, frame_ms(ms, c), err_name, err, details);
}

/* ---- large_pyramid --------------------------------------------------------- */

static void build_pyramid(scene_def *d, int base, double ground_half) {
    add_ground(d, ground_half);
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j)
            set_box(
                scene_add(d, 1, (i + 1) * 0.5 + (j - i) * 1.0 - base * 0.5, (2 * i + 1) * 0.5, 0.0),
                0.5, 0.5);
}

static int large_pyramid(int steps) {
    scene_def d;
    if (!scene_init(&d, 5100)) return 1;
    build_pyramid(&d, 100, 100.0);
    const int top = d.count - 1;
    out("\n## large_pyramid: base 100 (%d boxes), %d steps of 1/60 s, time of steps 2..%d\n\n",
        d.count - 1, steps, steps);
    md("```\n");
    out("%-12s %-28s %9s %7s %9s %9s\n", "engine", "configuration", "ms/step", "sx/peer", "top y",
        "top dx");
    double ms[SCENE_ENGINE_COUNT] = {0};
    int failures = 0;
    for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
        scene_config c = default_config(e, 1.0 / 60.0);
        void *w = engines[e].create(&d, &c);
        if (!w) {
            fprintf(stderr, "sepax_bench: large_pyramid: %s failed to build\n", engine_names[e]);
            ++failures;
            continue;
        }
        engines[e].step(w, 1);
        double t0 = now_ms();
        engines[e].step(w, steps - 1);
        ms[e] = (now_ms() - t0) / (double)(steps > 1 ? steps - 1 : 1);
        scene_state s;
        engines[e].get(w, top, &s);
        engines[e].destroy(w);
        char cfg[96], det[96];
        config_name(e, &c, cfg, sizeof cfg);
        out("%-12s %-28s %9.2f ", engine_names[e], cfg, ms[e]);
        if (e == SCENE_SEPAX)
            out("%7s", "1");
        else
            out("%7.2f", ms[0] / ms[e]);
        out(" %9.3f %9.3f\n", s.y, s.x);
        snprintf(det, sizeof det, "top_y=%.4f;top_dx=%.4f", s.y, s.x);
        csv_row("large_pyramid", e, &c, d.count - 1, steps, ms[e], "top_y_drop", 99.5 - s.y, det);
    }
    md("```\n");
    out("sx/peer = sepax ms / engine ms (< 1: sepax faster). The top box starts at y 99.5, x 0.\n");
    if (ms[0] > ms[1] || ms[0] > ms[2])
        speed_note("large_pyramid: sepax %.1f ms/step, %.2fx box2d and %.2fx chipmunk", ms[0],
                   ms[1] > 0 ? ms[0] / ms[1] : 0.0, ms[2] > 0 ? ms[0] / ms[2] : 0.0);
    scene_free(&d);
    return failures;
}

/* ---- mostly_asleep (sepax) -------------------------------------------------- */

/* 200 awake boxes: 20 columns of 10, dropped with 0.2 m gaps left of x = 0. */
static void add_awake_group(scene_def *d) {
    for (int c = 0; c < 20; ++c)
        for (int r = 0; r < 10; ++r)
            set_box(scene_add(d, 1, -400.0 + 3.0 * c, 0.7 + 1.2 * r, 0.0), 0.5, 0.5);
}

static double time_sepax(void *w, int steps) {
    double t0 = now_ms();
    sepax_step(w, steps);
    return (now_ms() - t0) / (double)steps;
}

static int mostly_asleep(int resting, int steps) {
    scene_def d;
    if (!scene_init(&d, resting + 300)) return 1;
    d.sleep = 1;
    /* One long ground under both groups. */
    const double extent = 1.5 * resting + 500.0;
    set_box(scene_add(&d, 0, 0.0, -1.0, 0.0), extent, 1.0);
    for (int i = 0; i < resting; ++i)
        set_box(scene_add(&d, 1, 1.5 * i, 0.5, 0.0), 0.5, 0.5);
    scene_def a;
    if (!scene_init(&a, 300)) return 1;
    a.sleep = 1;
    set_box(scene_add(&a, 0, 0.0, -1.0, 0.0), extent, 1.0);
    add_awake_group(&a);

    scene_config c = default_config(SCENE_SEPAX, 1.0 / 60.0);
    sepax_world *w = sepax_create(&d, &c);
    if (!w) return 1;
    /* Let the resting boxes fall asleep, then add the awake group. */
    int settle = 0;
    while (sx_world_awake_body_count(w->world) > 0 && settle < 600) {
        sepax_step(w, 10);
        settle += 10;
    }
    const int asleep = resting - sx_world_awake_body_count(w->world);
    for (int i = 1; i < a.count; ++i) {
        const scene_body *b = &a.bodies[i];
        sx_body_def bd = sx_default_body_def();
        bd.type = SX_BODY_DYNAMIC;
        bd.position = sx_v2((sx_real)b->x, (sx_real)b->y);
        sx_collider_def cd = sx_default_collider_def();
        cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
        sx_body_id id;
        if (sx_create_body(w->world, &bd, &id) != SX_OK ||
            sx_body_add_collider(w->world, id, &cd, NULL) != SX_OK)
            return 1;
    }
    double ms_mixed = time_sepax(w, steps);
    const int awake_after = sx_world_awake_body_count(w->world);
    sepax_destroy(w);
    sepax_world *w2 = sepax_create(&a, &c);
    if (!w2) return 1;
    double ms_alone = time_sepax(w2, steps);
    sepax_destroy(w2);

    out("\n## mostly_asleep (sepax): %d resting boxes (%d asleep after %d settling steps) + 200 "
        "awake, %d steps\n\n",
        resting, asleep, settle, steps);
    md("```\n");
    out("%-34s %9s\n", "world", "ms/step");
    out("%-34s %9.3f\n", "resting + 200 awake", ms_mixed);
    out("%-34s %9.3f\n", "200 awake alone", ms_alone);
    out("%-34s %9.2f   (target <= 2)\n", "ratio", ms_mixed / ms_alone);
    out("%-34s %9d\n", "awake bodies at the end (mixed)", awake_after);
    if (ms_mixed > 2.0 * ms_alone)
        speed_note("mostly_asleep: %d sleeping + 200 awake cost %.1fx the 200 alone (target <= 2)",
                   resting, ms_mixed / ms_alone);
    md("```\n");
    char det[128];
    snprintf(det, sizeof det, "asleep=%d;ms_alone=%.4f;awake_end=%d", asleep, ms_alone,
             awake_after);
    csv_row("mostly_asleep", SCENE_SEPAX, &c, resting + 200, steps, ms_mixed, "cost_ratio",
            ms_mixed / ms_alone, det);
    csv_row("mostly_asleep_alone", SCENE_SEPAX, &c, 200, steps, ms_alone, "cost_ratio", 1.0, "");
    scene_free(&d);
    scene_free(&a);
    return 0;
}

/* ---- rain: mixed shapes into a container ------------------------------------ */

/* n bodies on a jittered grid (2 columns per row and a half, spacing 1.25 m)
 * above a container as wide as the grid: circles, boxes, capsules and 3..8-gons
 * of size 0.2..0.5 m in turn, random angles. All fall at once: a rain that
 * piles up during the timed steps. */
static void build_rain(scene_def *d, int n, uint64_t seed) {
    bench_rng rng = bench_rng_make(seed);
    int cols = (int)ceil(sqrt(2.5 * n));
    double width = 1.25 * cols;
    double half = width * 0.5 + 1.0;
    add_ground(d, half + 1.0);
    set_box(scene_add(d, 0, -half - 0.5, 20.0, 0.0), 0.5, 20.0);
    set_box(scene_add(d, 0, half + 0.5, 20.0, 0.0), 0.5, 20.0);
    for (int i = 0; i < n; ++i) {
        int r = i / cols, col = i % cols;
        double x = -width * 0.5 + 1.25 * (col + 0.5) + bench_rng_range(&rng, -0.1, 0.1);
        double y = 1.0 + 1.25 * r + bench_rng_range(&rng, -0.1, 0.1);
        scene_body *b = scene_add(d, 1, x, y, bench_rng_range(&rng, -PI, PI));
        double s = bench_rng_range(&rng, 0.2, 0.5);
        switch (i % 4) {
        case 0: set_circle(b, s); break;
        case 1: set_box(b, s, s * bench_rng_range(&rng, 0.5, 1.0)); break;
        case 2: set_capsule(b, s * 0.6, s * 0.5); break;
        default: set_ngon(b, 3 + (int)bench_rng_range(&rng, 0.0, 5.999), s); break;
        }
    }
}

static int rain(const int *sizes, int nsizes, int steps, double cap_ms, const char *out_dir) {
    out("\n## rain: mixed shapes (circles, boxes, capsules, 3..8-gons) falling into a container, "
        "time of steps 2..%d of 1/60 s (the first builds the engines' trees)\n\n",
        steps + 1);
    md("```\n");
    out("%-12s %8s %10s %12s %8s\n", "engine", "bodies", "ms/step", "step 1 (ms)", "sx/peer");
    double ms[SCENE_ENGINE_COUNT][8] = {{0}};
    int failures = 0;
    for (int k = 0; k < nsizes; ++k) {
        scene_def d;
        if (!scene_init(&d, sizes[k] + 8)) return 1;
        build_rain(&d, sizes[k], 77);
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
            scene_config c = default_config(e, 1.0 / 60.0);
            /* On 2026-11-23 a peer's first step at 64,000 bodies grew past
             * the machine's 24 GiB and the OOM killer ended the whole run:
             * above 16,000 bodies the peers run only when asked. */
            if (e != SCENE_SEPAX && sizes[k] > 16000 && !getenv("SX_BENCH_RAIN_PEERS_LARGE")) {
                out("%-12s %8d %10s  (skipped above 16,000 bodies: set "
                    "SX_BENCH_RAIN_PEERS_LARGE=1)\n",
                    engine_names[e], sizes[k], "-");
                continue;
            }
            void *w = engines[e].create(&d, &c);
            if (!w) {
                fprintf(stderr, "sepax_bench: rain %d: %s failed to build\n", sizes[k],
                        engine_names[e]);
                ++failures;
                continue;
            }
            /* An engine that would take more than cap_ms stops early: its
             * later, costlier steps (a bigger pile) are then left out, which
             * can only flatter it. */
            double t_first = now_ms();
            engines[e].step(w, 1);
            double t0 = now_ms(), elapsed = 0.0;
            t_first = t0 - t_first;
            int done = 0;
            while (done < steps && elapsed < cap_ms) {
                int chunk = steps - done < 5 ? steps - done : 5;
                engines[e].step(w, chunk);
                done += chunk;
                elapsed = now_ms() - t0;
            }
            ms[e][k] = elapsed / (double)done;
            engines[e].destroy(w);
            out("%-12s %8d %10.3f %12.1f ", engine_names[e], sizes[k], ms[e][k], t_first);
            if (e == SCENE_SEPAX)
                out("%8s", "1");
            else
                out("%8.2f", ms[0][k] / ms[e][k]);
            if (done < steps)
                out("  (stopped after %d steps: %.0f s cap)\n", done, cap_ms / 1000.0);
            else
                out("\n");
            char det[64];
            snprintf(det, sizeof det, "first_step_ms=%.3f", t_first);
            csv_row("rain", e, &c, sizes[k], done, ms[e][k], "none", 0.0, det);
        }
        scene_free(&d);
        if ((ms[1][k] > 0 && ms[0][k] > ms[1][k]) || (ms[2][k] > 0 && ms[0][k] > ms[2][k]))
            speed_note("rain %d: sepax %.2f ms/step, %.2fx box2d and %.2fx chipmunk", sizes[k],
                       ms[0][k], ms[1][k] > 0 ? ms[0][k] / ms[1][k] : 0.0,
                       ms[2][k] > 0 ? ms[0][k] / ms[2][k] : 0.0);
    }
    if (nsizes >= 2) {
        out("log-log slope of ms/step against n (least squares, 1 = linear):");
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int m = 0;
            /* over the sizes the engine ran */
            for (int k = 0; k < nsizes; ++k) {
                if (!(ms[e][k] > 0)) continue;
                double x = log((double)sizes[k]), y = log(ms[e][k]);
                sx += x;
                sy += y;
                sxx += x * x;
                sxy += x * y;
                ++m;
            }
            if (m < 2) continue;
            double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
            out(" %s %.2f", engine_names[e], slope);
        }
        out("\n");
    }
    md("```\n");
    /* the scaling curves: ms per step against bodies, log-log */
    {
        svg_point pts[SCENE_ENGINE_COUNT * 8];
        int np = 0;
        char path[1200];
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
            for (int k = 0; k < nsizes && k < 8; ++k) {
                if (!(ms[e][k] > 0)) continue;
                pts[np].x = (double)sizes[k];
                pts[np].y = ms[e][k];
                pts[np].series = e;
                pts[np].label = "bodies, ms/step";
                ++np;
            }
        }
        snprintf(path, sizeof path, "%s/rain.svg", out_dir);
        if (!svg_plot_write_lines(path, "rain: ms per step against bodies", "bodies", "ms per step",
                                  pts, np, engine_names, SCENE_ENGINE_COUNT)) {
            fprintf(stderr, "sepax_bench: cannot write %s\n", path);
            ++failures;
        }
        md("\n![rain scaling](rain.svg)\n");
    }
    return failures;
}

/* ---- accuracy scenes: knob sweeps ------------------------------------------- */

/* The sweep of one accuracy scene: each engine at dt = 1/30, 1/60, 1/120,
 * 1/240 with its standard knobs, then at 1/60 with fewer and more sub-steps
 * (sepax) or iterations (peers). */
#define SWEEP_MAX 8

static int sweep_configs(int e, scene_config *c) {
    static const int hz[4] = {30, 60, 120, 240};
    int n = 0;
    for (int i = 0; i < 4; ++i)
        c[n++] = default_config(e, 1.0 / hz[i]);
    scene_config base = default_config(e, 1.0 / 60.0);
    if (e == SCENE_SEPAX) {
        static const int subs[3] = {1, 2, 8};
        for (int i = 0; i < 3; ++i) {
            c[n] = base;
            c[n++].sub_steps = subs[i];
        }
    } else {
        static const int iters[3] = {2, 4, 16};
        for (int i = 0; i < 3; ++i) {
            c[n] = base;
            c[n].vel_iters = iters[i];
            if (e == SCENE_BOX2D) c[n].pos_iters = iters[i] >= 8 ? 6 : 2;
            ++n;
        }
    }
    return n;
}

/* What an accuracy scene measures on one run. */
typedef struct acc_result {
    double error;
    double ms;
    char details[160];
} acc_result;

typedef int (*acc_scene_fn)(int e, const scene_config *c, int smoke, acc_result *r);

/* Appends to a result's details, never past the buffer (a blown-up run can
 * print very long numbers). */
static void det_add(acc_result *r, const char *fmt, ...) {
    size_t len = strlen(r->details);
    if (len + 1 >= sizeof r->details) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->details + len, sizeof r->details - len, fmt, ap);
    va_end(ap);
}

static int plot_index;

/* ---- headline table: does sepax beat both peers on a scene? ----------------- */

/* For each accuracy scene: every configuration's ms per 1/60 s frame and
 * error, kept for the dominance check once all sweeps have run. */
typedef struct sweep_point {
    int engine;
    double ms, err;
    char cfg[96];
} sweep_point;

typedef struct sweep_summary {
    char scene[32];
    char metric[64];
    int n;
    sweep_point p[SCENE_ENGINE_COUNT * SWEEP_MAX];
} sweep_summary;

#define SUMMARY_MAX 16
static sweep_summary summaries[SUMMARY_MAX];
static int summary_count;

static int run_sweep(const char *scene, const char *err_name, const char *what, acc_scene_fn fn,
                     const char *out_dir, int smoke) {
    svg_point pts[SCENE_ENGINE_COUNT * SWEEP_MAX];
    static char labels[SCENE_ENGINE_COUNT * SWEEP_MAX][96];
    int np = 0, failures = 0;
    sweep_summary *sum = summary_count < SUMMARY_MAX ? &summaries[summary_count++] : NULL;
    if (sum) {
        snprintf(sum->scene, sizeof sum->scene, "%s", scene);
        snprintf(sum->metric, sizeof sum->metric, "%s", err_name);
        sum->n = 0;
    }
    out("\n## %s: %s\n\n", scene, what);
    md("```\n");
    out("%-12s %-28s %9s %9s %12s  %s\n", "engine", "configuration", "ms/step", "ms/frame",
        err_name, "details");
    double best_err[SCENE_ENGINE_COUNT], std_ms[SCENE_ENGINE_COUNT], std_err[SCENE_ENGINE_COUNT];
    for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
        scene_config cs[SWEEP_MAX];
        int nc = sweep_configs(e, cs);
        best_err[e] = INFINITY;
        std_ms[e] = std_err[e] = 0.0;
        for (int i = 0; i < nc; ++i) {
            acc_result r;
            memset(&r, 0, sizeof r);
            if (!fn(e, &cs[i], smoke, &r)) {
                fprintf(stderr, "sepax_bench: %s: %s failed\n", scene, engine_names[e]);
                ++failures;
                continue;
            }
            char cfg[96];
            config_name(e, &cs[i], cfg, sizeof cfg);
            out("%-12s %-28s %9.4f %9.4f %12.4g  %s\n", engine_names[e], cfg, r.ms,
                frame_ms(r.ms, &cs[i]), r.error, r.details);
            csv_row(scene, e, &cs[i], 0, 0, r.ms, err_name, r.error, r.details);
            snprintf(labels[np], sizeof labels[np], "%s", cfg);
            pts[np].x = frame_ms(r.ms, &cs[i]);
            pts[np].y = r.error;
            pts[np].series = e;
            pts[np].label = labels[np];
            ++np;
            if (sum && sum->n < SCENE_ENGINE_COUNT * SWEEP_MAX) {
                sweep_point *sp = &sum->p[sum->n++];
                sp->engine = e;
                sp->ms = frame_ms(r.ms, &cs[i]);
                sp->err = r.error;
                snprintf(sp->cfg, sizeof sp->cfg, "%s", cfg);
            }
            if (r.error < best_err[e]) best_err[e] = r.error;
            if (i == 1) {
                std_ms[e] = r.ms;
                std_err[e] = r.error;
            }
        }
    }
    out("ms/frame = ms per 1/60 s of simulated time (the plot's x axis). Standard knobs at "
        "1/60 (sepax sub=4, Box2D 8/3, Chipmunk 8): error sepax %.4g, box2d %.4g, chipmunk "
        "%.4g; ms ratio sepax/box2d %.2f, sepax/chipmunk %.2f\n",
        std_err[0], std_err[1], std_err[2], std_ms[1] > 0 ? std_ms[0] / std_ms[1] : 0.0,
        std_ms[2] > 0 ? std_ms[0] / std_ms[2] : 0.0);
    md("```\n");
    char path[1200], file[64];
    snprintf(file, sizeof file, "%s.svg", scene);
    snprintf(path, sizeof path, "%s/%s", out_dir, file);
    char title[160];
    snprintf(title, sizeof title, "%s: %s against ms per 1/60 s frame", scene, err_name);
    if (!svg_plot_write(path, title, "ms per 1/60 s of simulated time", err_name, pts, np,
                        engine_names, SCENE_ENGINE_COUNT)) {
        fprintf(stderr, "sepax_bench: cannot write %s\n", path);
        ++failures;
    }
    md("\n![%s](%s)\n", scene, file);
    ++plot_index;
    return failures;
}

/* bounce: a circle r 0.5 dropped from 2 m (its bottom 2 m above the ground)
 * with restitution e on ground of the same e; the first apex over the drop
 * height against e^2. Error: mean |apex/drop - e^2| over e = 0.2, 0.5, 0.8. */
static int bounce_run(int e, const scene_config *c, int smoke, acc_result *r) {
    static const double es[3] = {0.2, 0.5, 0.8};
    double err = 0.0, ms = 0.0;
    int total_steps = 0;
    for (int k = 0; k < 3; ++k) {
        scene_def d;
        if (!scene_init(&d, 4)) return 0;
        add_ground(&d, 100.0);
        d.bodies[0].restitution = es[k];
        scene_body *b = scene_add(&d, 1, 0.0, 2.5, 0.0);
        set_circle(b, 0.5);
        b->restitution = es[k];
        void *w = engines[e].create(&d, c);
        scene_free(&d);
        if (!w) return 0;
        const int steps = smoke ? 5 : (int)ceil(1.5 / c->dt);
        double apex = -1.0, prev_vy = -1.0;
        int bounced = 0;
        for (int i = 0; i < steps; ++i) {
            double t0 = now_ms();
            engines[e].step(w, 1);
            ms += now_ms() - t0;
            scene_state s;
            engines[e].get(w, 1, &s);
            if (s.vy > 0.0) bounced = 1;
            if (bounced && s.y > apex) apex = s.y;
            if (bounced && prev_vy > 0.0 && s.vy <= 0.0) break;
            prev_vy = s.vy;
            ++total_steps;
        }
        engines[e].destroy(w);
        double ratio = apex > 0.0 ? (apex - 0.5) / 2.0 : 0.0;
        err += fabs(ratio - es[k] * es[k]) / 3.0;
        det_add(r, "e=%.1f:%.4f(%.4f) ", es[k], ratio, es[k] * es[k]);
    }
    r->error = err;
    r->ms = ms / (double)(total_steps > 0 ? total_steps : 1);
    return 1;
}

/* incline: a box (half-extent 0.5) on a static ramp at 0.25 rad; mu = 0.5
 * (sticks: tan 0.25 = 0.2553), 0.1 and 0 (slides at g (sin - mu cos)).
 * Acceleration measured from the velocity along the ramp between t = 0.5 s
 * and 2 s (after the landing transient). Error: mean |a - exact| in m/s^2. */
static int incline_run(int e, const scene_config *c, int smoke, acc_result *r) {
    static const double mus[3] = {0.5, 0.1, 0.0};
    const double th = 0.25, sn = sin(th), cs = cos(th);
    double err = 0.0, ms = 0.0;
    int total_steps = 0;
    for (int k = 0; k < 3; ++k) {
        scene_def d;
        if (!scene_init(&d, 4)) return 0;
        scene_body *ramp = scene_add(&d, 0, 0.0, 0.0, th);
        set_box(ramp, 30.0, 0.5);
        ramp->friction = mus[k];
        /* On the top face, 10 m up the slope. */
        scene_body *b = scene_add(&d, 1, 10.0 * cs - 1.0 * sn, 10.0 * sn + 1.0 * cs, th);
        set_box(b, 0.5, 0.5);
        b->friction = mus[k];
        void *w = engines[e].create(&d, c);
        scene_free(&d);
        if (!w) return 0;
        const int n0 = (int)lround(0.5 / c->dt), n1 = smoke ? n0 + 2 : (int)lround(2.0 / c->dt);
        double v0 = 0.0, v1 = 0.0;
        for (int i = 1; i <= n1; ++i) {
            double t0 = now_ms();
            engines[e].step(w, 1);
            ms += now_ms() - t0;
            ++total_steps;
            scene_state s;
            engines[e].get(w, 1, &s);
            double along = -(s.vx * cs + s.vy * sn); /* down the slope */
            if (i == n0) v0 = along;
            if (i == n1) v1 = along;
        }
        engines[e].destroy(w);
        double a = (v1 - v0) / ((n1 - n0) * c->dt);
        double exact = mus[k] >= tan(th) ? 0.0 : 10.0 * (sn - mus[k] * cs);
        err += fabs(a - exact) / 3.0;
        det_add(r, "mu=%.1f:%.4f(%.4f) ", mus[k], a, exact);
    }
    r->error = err;
    r->ms = ms / (double)(total_steps > 0 ? total_steps : 1);
    return 1;
}

/* Largest overlap beyond the slop between any two boxes of a pyramid, or a
 * box and the ground, measured by sepax's own narrowphase on the reported
 * poses (exact squares: Box2D's 1 cm skin shows as a gap). */
static double pyramid_penetration(void *w, int e, int count) {
    scene_state st[256];
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    double worst = 0.0;
    for (int i = 1; i < count && i < 256; ++i)
        engines[e].get(w, i, &st[i]);
    for (int i = 1; i < count && i < 256; ++i) {
        sx_xform xi =
            sx_xform_make(sx_v2((sx_real)st[i].x, (sx_real)st[i].y), (sx_real)st[i].angle);
        double ground = 0.0 - (st[i].y - 0.5 * (fabs(cos(st[i].angle)) + fabs(sin(st[i].angle))));
        if (ground > worst) worst = ground;
        for (int j = i + 1; j < count && j < 256; ++j) {
            double dx = st[j].x - st[i].x, dy = st[j].y - st[i].y;
            if (dx * dx + dy * dy > 2.1) continue;
            sx_xform xj =
                sx_xform_make(sx_v2((sx_real)st[j].x, (sx_real)st[j].y), (sx_real)st[j].angle);
            sx_manifold m;
            if (sx_collide(&box, xi, &box, xj, &m) > 0)
                for (int k = 0; k < m.count; ++k)
                    if ((double)m.points[k].depth > worst) worst = (double)m.points[k].depth;
        }
    }
    return worst > 0.005 ? worst - 0.005 : 0.0;
}

/* pyramid20: base 20 on the ground, 10 s. Error: the top box's drift, its
 * displacement between t = 1 s (settled) and t = 10 s; also the largest
 * penetration beyond the 5 mm slop (sampled every 0.25 s) and the final
 * top y (starts 19.5). */
static int pyramid20_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 220)) return 0;
    build_pyramid(&d, 20, 100.0);
    const int top = d.count - 1, count = d.count;
    void *w = engines[e].create(&d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(10.0 / c->dt), n1 = (int)lround(1.0 / c->dt);
    const int every = (int)lround(0.25 / c->dt);
    double ms = 0.0, pen = 0.0;
    scene_state s1 = {0, 0, 0, 0, 0, 0}, s;
    for (int i = 1; i <= n; ++i) {
        double t0 = now_ms();
        engines[e].step(w, 1);
        ms += now_ms() - t0;
        if (i == n1) engines[e].get(w, top, &s1);
        if (i % every == 0 || i == n) {
            double p = pyramid_penetration(w, e, count);
            if (p > pen) pen = p;
        }
    }
    engines[e].get(w, top, &s);
    engines[e].destroy(w);
    if (n < n1) s1 = s;
    r->error = hypot(s.x - s1.x, s.y - s1.y);
    if (r->error < 1e-7) r->error = 1e-7;
    r->ms = ms / n;
    snprintf(r->details, sizeof r->details, "top_y=%.4f top_x=%.4f max_pen_beyond_slop=%.4f", s.y,
             s.x, pen);
    return 1;
}

/* stack20: 20 boxes (half-extent 0.5) in a column, alternate rows shifted
 * +-0.01 m, 10 s. Error: the largest lateral creep of a box from where it
 * started; details: top y (starts 19.5) and the largest penetration beyond
 * the slop (as pyramid20). */
static int stack20_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 24)) return 0;
    add_ground(&d, 100.0);
    for (int i = 0; i < 20; ++i)
        set_box(scene_add(&d, 1, i % 2 ? 0.01 : -0.01, 0.5 + i, 0.0), 0.5, 0.5);
    const int count = d.count;
    double x0[24];
    for (int i = 0; i < count; ++i)
        x0[i] = d.bodies[i].x;
    void *w = engines[e].create(&d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(10.0 / c->dt), every = (int)lround(0.25 / c->dt);
    double ms = 0.0, pen = 0.0;
    for (int i = 1; i <= n; ++i) {
        double t0 = now_ms();
        engines[e].step(w, 1);
        ms += now_ms() - t0;
        if (i % every == 0 || i == n) {
            double p = pyramid_penetration(w, e, count);
            if (p > pen) pen = p;
        }
    }
    double creep = 0.0;
    scene_state s;
    for (int i = 1; i < count; ++i) {
        engines[e].get(w, i, &s);
        if (fabs(s.x - x0[i]) > creep) creep = fabs(s.x - x0[i]);
    }
    engines[e].destroy(w);
    r->error = creep > 1e-7 ? creep : 1e-7;
    r->ms = ms / n;
    snprintf(r->details, sizeof r->details, "top_y=%.4f max_pen_beyond_slop=%.4f", s.y, pen);
    return 1;
}

/* cradle: five circles r 0.5 in a row, 1 mm gaps, e = 1, mu = 0, no
 * gravity; the first moves at 1 m/s. After 1 s the last should leave at
 * 1 m/s and the others rest. Error: |v_last - 1| + the sum of the others'
 * |v|; details: momentum and kinetic energy (both start at 0.785 for
 * 0.785 kg bodies). Both Box2D and sepax ignore restitution below 1 m/s
 * approach speed by default (their restitution threshold), exactly this
 * scene's speed. */
static int cradle_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 8)) return 0;
    d.gy = 0.0;
    for (int i = 0; i < 5; ++i) {
        scene_body *b = scene_add(&d, 1, i * 1.001, 0.0, 0.0);
        set_circle(b, 0.5);
        b->friction = 0.0;
        b->restitution = 1.0;
        if (i == 0) b->vx = 1.0;
    }
    void *w = engines[e].create(&d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(1.0 / c->dt);
    double t0 = now_ms();
    engines[e].step(w, n);
    r->ms = (now_ms() - t0) / n;
    double err = 0.0, p = 0.0, ke = 0.0;
    const double m = PI * 0.25;
    scene_state s;
    for (int i = 0; i < 5; ++i) {
        engines[e].get(w, i, &s);
        err += i == 4 ? fabs(s.vx - 1.0) : hypot(s.vx, s.vy);
        p += m * s.vx;
        ke += 0.5 * m * (s.vx * s.vx + s.vy * s.vy);
    }
    engines[e].get(w, 4, &s);
    engines[e].destroy(w);
    r->error = err > 1e-7 ? err : 1e-7;
    snprintf(r->details, sizeof r->details,
             "v_last=%.4f momentum=%.4f energy=%.4f (0.7854, 0.3927)", s.vx, p, ke);
    return 1;
}

/* ---- helpers of the conservation and contact scenes -------------------------- */

/* Mass and moment of inertia of a scene body from its shape and density
 * (boxes, circles and sharp polygons: what these scenes use). */
static void body_mass(const scene_body *b, double *m, double *inertia) {
    const bench_shape *s = &b->shape;
    if (s->kind == BENCH_CIRCLE) {
        *m = b->density * PI * s->radius * s->radius;
        *inertia = 0.5 * *m * s->radius * s->radius;
    } else if (s->kind == BENCH_BOX) {
        *m = b->density * 4.0 * s->hx * s->hy;
        *inertia = *m * (s->hx * s->hx + s->hy * s->hy) / 3.0;
    } else { /* polygon about its centroid (the origin): triangle fan */
        double area = 0.0, i0 = 0.0;
        for (int k = 0; k < s->count; ++k) {
            const double *p = s->v[k], *q = s->v[(k + 1) % s->count];
            double cr = p[0] * q[1] - p[1] * q[0];
            area += 0.5 * cr;
            i0 += cr *
                  (p[0] * p[0] + p[0] * q[0] + q[0] * q[0] + p[1] * p[1] + p[1] * q[1] +
                   q[1] * q[1]) /
                  12.0;
        }
        *m = b->density * area;
        *inertia = b->density * i0;
    }
}

/* Radius of the circle around a shape's local origin that holds it. */
static double shape_reach(const bench_shape *s) {
    if (s->kind == BENCH_BOX) return hypot(s->hx, s->hy);
    double r = 0.0;
    for (int k = 0; k < s->count; ++k) {
        double d = hypot(s->v[k][0], s->v[k][1]);
        if (d > r) r = d;
    }
    return r + s->radius;
}

/* Largest overlap between any two bodies of a scene (dynamic against dynamic
 * or static), measured as pyramid_penetration does: sepax's sx_collide on
 * the poses the engine reports, on the exact shapes of the description (so
 * Box2D's 1 cm polygon skin reads as a gap). Returns the raw depth in m. */
static double scene_max_depth(void *w, int e, const scene_def *d) {
    enum { MAXB = 64 };
    sx_shape sh[MAXB];
    sx_xform xf[MAXB];
    double px[MAXB], py[MAXB], reach[MAXB];
    int n = d->count < MAXB ? d->count : MAXB;
    for (int i = 0; i < n; ++i) {
        const scene_body *b = &d->bodies[i];
        scene_state s = {b->x, b->y, b->angle, 0, 0, 0};
        if (b->dynamic) engines[e].get(w, i, &s);
        if (!sepax_shape(&b->shape, &sh[i])) return 0.0;
        xf[i] = sx_xform_make(sx_v2((sx_real)s.x, (sx_real)s.y), (sx_real)s.angle);
        px[i] = s.x;
        py[i] = s.y;
        reach[i] = shape_reach(&b->shape);
    }
    double worst = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (!d->bodies[i].dynamic && !d->bodies[j].dynamic) continue;
            if (hypot(px[j] - px[i], py[j] - py[i]) > reach[i] + reach[j]) continue;
            sx_manifold m;
            if (sx_collide(&sh[i], xf[i], &sh[j], xf[j], &m) > 0)
                for (int k = 0; k < m.count; ++k)
                    if ((double)m.points[k].depth > worst) worst = (double)m.points[k].depth;
        }
    return worst;
}

/* ---- projectile ------------------------------------------------------------------ */

/* projectile: a circle r 0.5 launched from the origin at (3, 8) m/s, no
 * contacts, 2 s. Error: distance to the parabola at t = n dt; details: the
 * distance to symplectic Euler's closed form with the engine's own step
 * (dt / sub_steps for sepax), i.e. what is left once the integrator's known
 * O(h) error is taken out (rounding, damping, anything else). */
static int projectile_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 2)) return 0;
    const double vx0 = 3.0, vy0 = 8.0, g = 10.0;
    scene_body *b = scene_add(&d, 1, 0.0, 0.0, 0.0);
    set_circle(b, 0.5);
    b->vx = vx0;
    b->vy = vy0;
    void *w = engines[e].create(&d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(2.0 / c->dt);
    double t0 = now_ms();
    engines[e].step(w, n);
    r->ms = (now_ms() - t0) / n;
    scene_state s;
    engines[e].get(w, 0, &s);
    engines[e].destroy(w);
    const double t = n * c->dt;
    const double xe = vx0 * t, ye = vy0 * t - 0.5 * g * t * t;
    /* Symplectic Euler, m steps of h: v_k = vy0 - g h k, y_m = sum h v_k. */
    const int sub = e == SCENE_SEPAX ? c->sub_steps : 1;
    const double h = c->dt / sub, m = (double)n * sub;
    const double y_euler = h * m * vy0 - g * h * h * m * (m + 1.0) * 0.5;
    r->error = hypot(s.x - xe, s.y - ye);
    if (r->error < 1e-9) r->error = 1e-9;
    snprintf(r->details, sizeof r->details,
             "x=%.5f(%.5f) y=%.5f(%.5f) vy=%.4f(%.4f) dev_from_euler=%.3g", s.x, xe, s.y, ye, s.vy,
             vy0 - g * t, hypot(s.x - xe, s.y - y_euler));
    return 1;
}

/* ---- pileup ---------------------------------------------------------------------- */

/* 40 bodies (circles r 0.4 and 0.8 x 0.6 boxes in turn) on a ring of radius
 * 7..9 m, thrown towards its centre at 3..5 m/s with +-0.15 rad of aim
 * error, zero gravity, friction 0.5, restitution 0: they meet around
 * t = 1.8 s and make a pile that keeps the drift of the total momentum. */
static void build_pileup(scene_def *d) {
    bench_rng rng = bench_rng_make(5);
    d->gy = 0.0;
    const int n = 40;
    for (int i = 0; i < n; ++i) {
        double a = 2.0 * PI * (double)i / (double)n;
        double rad = 8.0 + bench_rng_range(&rng, -1.0, 1.0);
        scene_body *b = scene_add(d, 1, rad * cos(a), rad * sin(a), bench_rng_range(&rng, -PI, PI));
        if (i % 2)
            set_box(b, 0.4, 0.3);
        else
            set_circle(b, 0.4);
        double sp = bench_rng_range(&rng, 3.0, 5.0), da = bench_rng_range(&rng, -0.15, 0.15);
        b->vx = -sp * cos(a + da);
        b->vy = -sp * sin(a + da);
        b->friction = 0.5;
    }
}

/* pileup: 4 s. Error: the drift of the linear momentum |P(T) - P(0)| /
 * sum m |v0|, plus that of the angular momentum about the origin
 * |L(T) - L(0)| / sum m |r0| |v0| (contact and friction impulses conserve
 * both; position corrections that move bodies without a matching impulse
 * change L), plus the largest kinetic energy gain max_t KE(t) / KE(0) - 1
 * (clamped at 0: inelastic impacts may only lose energy). Each part and the
 * final KE / KE(0) are in the details. P, L and KE at t = 0 are read back
 * from the engine, so a float engine's rounding of the initial values is
 * not counted as drift. */
static int pileup_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 48)) return 0;
    build_pileup(&d);
    const int count = d.count;
    double mass[48], inertia[48], pscale = 0.0, lscale = 0.0;
    for (int i = 0; i < count; ++i) {
        const scene_body *b = &d.bodies[i];
        body_mass(b, &mass[i], &inertia[i]);
        pscale += mass[i] * hypot(b->vx, b->vy);
        lscale += mass[i] * hypot(b->x, b->y) * hypot(b->vx, b->vy);
    }
    void *w = engines[e].create(&d, c);
    scene_free(&d);
    if (!w) return 0;
    /* Momenta and energy of the state as the engine holds it (its own
     * rounding of the initial values) before and after each step. */
    double now[4] = {0}, start[4] = {0};
    const int n = smoke ? 3 : (int)lround(4.0 / c->dt);
    double ms = 0.0, gain = 0.0;
    for (int k = 0; k <= n; ++k) {
        if (k > 0) {
            double t0 = now_ms();
            engines[e].step(w, 1);
            ms += now_ms() - t0;
        }
        now[0] = now[1] = now[2] = now[3] = 0.0; /* px, py, L, KE */
        for (int i = 0; i < count; ++i) {
            scene_state s;
            engines[e].get(w, i, &s);
            now[0] += mass[i] * s.vx;
            now[1] += mass[i] * s.vy;
            now[2] += mass[i] * (s.x * s.vy - s.y * s.vx) + inertia[i] * s.w;
            now[3] += 0.5 * mass[i] * (s.vx * s.vx + s.vy * s.vy) + 0.5 * inertia[i] * s.w * s.w;
        }
        if (k == 0) memcpy(start, now, sizeof start);
        if (now[3] / start[3] - 1.0 > gain) gain = now[3] / start[3] - 1.0;
    }
    engines[e].destroy(w);
    const double dp = hypot(now[0] - start[0], now[1] - start[1]) / pscale;
    const double dl = fabs(now[2] - start[2]) / lscale;
    r->ms = ms / n;
    r->error = dp + dl + gain;
    if (r->error < 1e-12) r->error = 1e-12;
    snprintf(r->details, sizeof r->details,
             "momentum_drift=%.3g ang_momentum_drift=%.3g energy_gain=%.3g ke_end/ke0=%.4f", dp, dl,
             gain, now[3] / start[3]);
    return 1;
}

/* ---- mass_ratio ------------------------------------------------------------------ */

/* mass_ratio: two cases on SCENES.md's ground, 5 s from rest, boxes placed
 * touching: (a) a 1 m box of density 100 on a 1 m box of density 1 (100:1);
 * (b) a 20 x 1 m plank (density 1, 20 kg) on two 1 m boxes under its ends.
 * Error: the largest penetration beyond the 5 mm slop between any two bodies
 * over the run (every step, sepax narrowphase on the reported poses, as
 * pyramid20; clamped at 1e-6 m for the log plot); details: the raw largest
 * depth of each case and where the top body ends (starts at y 1.5). */
static int mass_ratio_run(int e, const scene_config *c, int smoke, acc_result *r) {
    double worst = 0.0, ms = 0.0;
    int total_steps = 0;
    for (int k = 0; k < 2; ++k) {
        scene_def d;
        if (!scene_init(&d, 4)) return 0;
        add_ground(&d, 100.0);
        if (k == 0) {
            set_box(scene_add(&d, 1, 0.0, 0.5, 0.0), 0.5, 0.5);
            scene_body *heavy = scene_add(&d, 1, 0.0, 1.5, 0.0);
            set_box(heavy, 0.5, 0.5);
            heavy->density = 100.0;
        } else {
            set_box(scene_add(&d, 1, -9.5, 0.5, 0.0), 0.5, 0.5);
            set_box(scene_add(&d, 1, 9.5, 0.5, 0.0), 0.5, 0.5);
            set_box(scene_add(&d, 1, 0.0, 1.5, 0.0), 10.0, 0.5);
        }
        const int top = d.count - 1;
        void *w = engines[e].create(&d, c);
        if (!w) {
            scene_free(&d);
            return 0;
        }
        const int n = smoke ? 3 : (int)lround(5.0 / c->dt);
        double depth = 0.0;
        for (int i = 1; i <= n; ++i) {
            double t0 = now_ms();
            engines[e].step(w, 1);
            ms += now_ms() - t0;
            ++total_steps;
            double dd = scene_max_depth(w, e, &d);
            if (dd > depth) depth = dd;
        }
        scene_state s;
        engines[e].get(w, top, &s);
        engines[e].destroy(w);
        scene_free(&d);
        if (depth - 0.005 > worst) worst = depth - 0.005;
        det_add(r, "%s:max_depth=%.4f top_y=%.4f ", k == 0 ? "100:1" : "plank", depth, s.y);
    }
    r->error = worst > 1e-6 ? worst : 1e-6;
    r->ms = ms / (double)(total_steps > 0 ? total_steps : 1);
    return 1;
}

/* ---- overlap_recovery ------------------------------------------------------------ */

/* overlap_recovery: SCENES.md's base-4 pyramid (10 boxes of half-extent 0.5,
 * 1 kg) created squeezed so that every box overlaps its neighbours and the
 * bottom row the ground by a fraction f of its size (rows and columns f m
 * closer), f = 0.25 and 0.5; 3 s with gravity. Error: the largest speed any
 * box reaches (m/s; the ideal push-out is slow); details per case: the time
 * the deepest overlap first falls below 1 cm (-1: never), the energy
 * gained beyond what separating needs (max over the run of KE + PE minus the
 * larger of the end state's KE + PE and the exact separated pyramid's PE, in
 * J, clamped at 0: the end state counts so that Box2D's skin, which rests
 * its rows higher, is not read as a gain) and the final top y (the exact pyramid's top rests
 * at 3.5). */
static int overlap_run(int e, const scene_config *c, int smoke, acc_result *r) {
    static const double fs[2] = {0.25, 0.5};
    double vmax = 0.0, ms = 0.0;
    int total_steps = 0;
    for (int k = 0; k < 2; ++k) {
        const double f = fs[k], sp = 1.0 - f;
        const int base = 4;
        scene_def d;
        if (!scene_init(&d, 12)) return 0;
        add_ground(&d, 100.0);
        double e_rest = 0.0;
        for (int i = 0; i < base; ++i)
            for (int j = i; j < base; ++j) {
                set_box(scene_add(&d, 1, (i + 1) * 0.5 * sp + (j - i) * sp - base * 0.5 * sp,
                                  0.5 - f + i * sp, 0.0),
                        0.5, 0.5);
                e_rest += 10.0 * (0.5 + i);
            }
        const int count = d.count, top = count - 1;
        void *w = engines[e].create(&d, c);
        if (!w) {
            scene_free(&d);
            return 0;
        }
        const int n = smoke ? 3 : (int)lround(3.0 / c->dt);
        double v = 0.0, emax = -INFINITY, t_sep = -1.0, en = 0.0;
        for (int i = 1; i <= n; ++i) {
            double t0 = now_ms();
            engines[e].step(w, 1);
            ms += now_ms() - t0;
            ++total_steps;
            en = 0.0;
            for (int b = 1; b < count; ++b) {
                scene_state s;
                engines[e].get(w, b, &s);
                double sp2 = s.vx * s.vx + s.vy * s.vy;
                if (sqrt(sp2) > v) v = sqrt(sp2);
                en += 0.5 * sp2 + 0.5 * (1.0 / 6.0) * s.w * s.w + 10.0 * s.y;
            }
            if (en > emax) emax = en;
            if (t_sep < 0.0 && scene_max_depth(w, e, &d) < 0.01) t_sep = i * c->dt;
        }
        scene_state s;
        engines[e].get(w, top, &s);
        engines[e].destroy(w);
        scene_free(&d);
        if (v > vmax) vmax = v;
        det_add(r, "f=%.2f:vmax=%.3f t_sep=%.3f excess_J=%.3f top_y=%.3f ", f, v, t_sep,
                fmax(0.0, emax - fmax(en, e_rest)), s.y);
    }
    r->error = vmax > 1e-7 ? vmax : 1e-7;
    r->ms = ms / (double)(total_steps > 0 ? total_steps : 1);
    return 1;
}

/* ---- consistency ----------------------------------------------------------------- */

/* A chaotic scene: 40 bodies (circles, boxes, pentagons and hexagons of size
 * 0.3..0.5 m in turn, random angles) on a jittered 8 x 5 grid dropped into a
 * container 12 m wide; they tumble and pile up. */
static void build_tumble(scene_def *d) {
    bench_rng rng = bench_rng_make(11);
    add_ground(d, 7.0);
    set_box(scene_add(d, 0, -6.5, 6.0, 0.0), 0.5, 6.0);
    set_box(scene_add(d, 0, 6.5, 6.0, 0.0), 0.5, 6.0);
    for (int i = 0; i < 40; ++i) {
        double x = -4.9 + 1.4 * (i % 8) + bench_rng_range(&rng, -0.1, 0.1);
        double y = 1.5 + 1.4 * (i / 8) + bench_rng_range(&rng, -0.1, 0.1);
        scene_body *b = scene_add(d, 1, x, y, bench_rng_range(&rng, -PI, PI));
        double s = bench_rng_range(&rng, 0.3, 0.5);
        switch (i % 4) {
        case 0: set_circle(b, s); break;
        case 1: set_box(b, s, s * 0.7); break;
        case 2: set_ngon(b, 5, s); break;
        default: set_ngon(b, 6, s); break;
        }
        b->vx = bench_rng_range(&rng, -2.0, 2.0);
    }
}

/* consistency: the tumble scene run for 2 s at dt and again at dt / 2 (all
 * other knobs equal). Error: the RMS distance between the two runs' body
 * positions at t = 1 s (Erez et al.'s consistency measure: a method whose
 * answer moves less when the step is halved is closer to converged); ms per
 * step is the dt run's. Details: the same at 0.25, 0.5, 1 and 2 s. At 0.5 s
 * most bodies are still in flight (the difference is the integrator's, like
 * projectile); by 2 s the pile is chaotic enough that every engine at every
 * setting differs by 0.1-0.5 m (the runs have decorrelated), so 1 s, after
 * the first impacts, is the figure. */
/* RMS distance between the dynamic bodies (from index first) of two worlds. */
static double rms_distance(int e, void *w, void *w2, int first, int count, double *worst) {
    double sum = 0.0;
    *worst = 0.0;
    for (int i = first; i < count; ++i) {
        scene_state a, b;
        engines[e].get(w, i, &a);
        engines[e].get(w2, i, &b);
        double dd = hypot(a.x - b.x, a.y - b.y);
        sum += dd * dd;
        if (dd > *worst) *worst = dd;
    }
    return sqrt(sum / (count - first));
}

static int consistency_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 44)) return 0;
    build_tumble(&d);
    const int count = d.count, first = 3;
    scene_config half = *c;
    half.dt = c->dt * 0.5;
    void *w = engines[e].create(&d, c);
    void *w2 = engines[e].create(&d, &half);
    scene_free(&d);
    if (!w || !w2) {
        if (w) engines[e].destroy(w);
        if (w2) engines[e].destroy(w2);
        return 0;
    }
    static const double marks[4] = {0.25, 0.5, 1.0, 2.0};
    double ms = 0.0, at[4] = {0}, worst = 0.0;
    int done = 0;
    for (int k = 0; k < 4; ++k) {
        const int upto = smoke ? k + 1 : (int)lround(marks[k] / c->dt);
        double t0 = now_ms();
        engines[e].step(w, upto - done);
        ms += now_ms() - t0;
        engines[e].step(w2, 2 * (upto - done));
        done = upto;
        at[k] = rms_distance(e, w, w2, first, count, &worst);
        det_add(r, "t=%.2f:%.3g ", done * c->dt, at[k]);
    }
    engines[e].destroy(w);
    engines[e].destroy(w2);
    r->ms = ms / done;
    r->error = at[2] > 1e-9 ? at[2] : 1e-9;
    det_add(r, "max=%.3g", worst);
    return 1;
}

/* ---- headline table (continued) --------------------------------------------- */

/* Errors within 2 % count as equal (measurement noise, and the floors some
 * metrics clamp to): a peer configuration whose error is at most 2 % above
 * sepax's is taken to reach it. */
#define SUMMARY_ERR_TOL 1.02
/* Costs within 10 % count as equal (timing noise on this shared machine): a
 * sepax configuration must be more than 10 % cheaper than a peer's matching
 * one to beat it. */
#define SUMMARY_MS_TOL 1.10

/* Cheapest configuration of engine e reaching error <= err (x the
 * tolerance); NULL when none does. */
static const sweep_point *cheapest_at(const sweep_summary *s, int e, double err) {
    const sweep_point *best = NULL;
    for (int i = 0; i < s->n; ++i) {
        const sweep_point *q = &s->p[i];
        if (q->engine != e || q->err > err * SUMMARY_ERR_TOL) continue;
        if (!best || q->ms < best->ms) best = q;
    }
    return best;
}

/* Engine e's most accurate configuration (the cheaper one on a tie). */
static const sweep_point *most_accurate(const sweep_summary *s, int e) {
    const sweep_point *best = NULL;
    for (int i = 0; i < s->n; ++i) {
        const sweep_point *q = &s->p[i];
        if (q->engine != e) continue;
        if (!best || q->err < best->err || (q->err == best->err && q->ms < best->ms)) best = q;
    }
    return best;
}

/* Most accurate configuration of engine e costing at most ms; NULL if none. */
static const sweep_point *best_within(const sweep_summary *s, int e, double ms) {
    const sweep_point *best = NULL;
    for (int i = 0; i < s->n; ++i) {
        const sweep_point *q = &s->p[i];
        if (q->engine != e || q->ms > ms) continue;
        if (!best || q->err < best->err || (q->err == best->err && q->ms < best->ms)) best = q;
    }
    return best;
}

/* snprintf that truncates quietly: the table cells nest strings whose
 * bounds the compiler cannot see (and warns about under the sanitizers). */
static void fmt_to(char *buf, size_t size, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, size, fmt, ap);
    va_end(ap);
}

/* Where sepax stands against peer k on one scene, in words, when none of its
 * configurations beats that peer: how much slower it is at the peer's best
 * error, or, when it never reaches that error, how much worse its error is
 * at the peer's cost. */
static void gap_words(const sweep_summary *s, int k, char *buf, size_t size) {
    const sweep_point *pb = most_accurate(s, k);
    if (!pb) {
        fmt_to(buf, size, "%s did not run", engine_names[k]);
        return;
    }
    const sweep_point *sx = cheapest_at(s, SCENE_SEPAX, pb->err);
    if (sx) {
        fmt_to(buf, size, "%.2fx slower than %s at its best error %.3g (%s, %.3g ms)",
               sx->ms / pb->ms, engine_names[k], pb->err, pb->cfg, pb->ms);
        return;
    }
    const sweep_point *eq = best_within(s, SCENE_SEPAX, pb->ms);
    if (eq) {
        fmt_to(buf, size,
               "never reaches %s's best error %.3g (%s, %.3g ms); at that cost sepax's "
               "error is %.3g (%.3gx)",
               engine_names[k], pb->err, pb->cfg, pb->ms, eq->err, eq->err / pb->err);
        return;
    }
    const sweep_point *sb = most_accurate(s, SCENE_SEPAX);
    fmt_to(buf, size,
           "never reaches %s's best error %.3g (%s, %.3g ms); sepax's best is %.3g (%.3gx) "
           "at %.3g ms (%.2fx that cost)",
           engine_names[k], pb->err, pb->cfg, pb->ms, sb ? sb->err : 0.0,
           sb && pb->err > 0 ? sb->err / pb->err : 0.0, sb ? sb->ms : 0.0,
           sb ? sb->ms / pb->ms : 0.0);
}

/* The headline table: for each scene, the sepax configuration that beats
 * both peers (faster than the cheapest configuration of each peer reaching
 * its error, or reaching an error no configuration of that peer reaches),
 * the one with the largest margin; otherwise the gap to each peer it does
 * not beat. Also written alone to out_dir/headline.md for the README. */
static int write_summary(const char *out_dir, int smoke) {
    if (summary_count == 0 && speed_note_count == 0) return 0;
    char path[1200];
    fmt_to(path, sizeof path, "%s/headline.md", out_dir);
    FILE *hf = fopen(path, "w");
    if (!hf) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", path, strerror(errno));
        return 1;
    }
    FILE *saved = report_file;
    out("\n## Headline: does sepax beat both peers?%s\n\n"
        "For each scene: a sepax configuration *beats* a peer when that peer has no "
        "configuration reaching the same error (within 2 %%) at a cost no more than 10 %% above "
        "(ms per 1/60 s frame, this run; a peer that never reaches the error in its sweep is "
        "beaten). "
        "When configurations beat both peers, the row names the most accurate of them and what "
        "each peer needs to match its error, and the cheapest of them; otherwise, for each peer "
        "not beaten, the gap at that "
        "peer's most accurate configuration. Single run, shared machine: costs within ~10 %% "
        "of each other are a tie in practice, and sub-microsecond costs (projectile, incline, "
        "cradle) are mostly call overhead.\n\n",
        smoke ? " (smoke run: a few steps per scene, the verdicts mean nothing)" : "");
    report_file = hf;
    md("| scene | metric | verdict | sepax configuration | sepax ms, error | box2d | chipmunk | "
       "cheapest winner |\n");
    md("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    report_file = saved;
    out("| scene | metric | verdict | sepax configuration | sepax ms, error | box2d | chipmunk "
        "| cheapest winner |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
    int losses = 0;
    char lost[SUMMARY_MAX][1100];
    char reach[SUMMARY_MAX * 2][300];
    int reach_count = 0;
    for (int si = 0; si < summary_count; ++si) {
        const sweep_summary *s = &summaries[si];
        /* The most accurate sepax point that beats both peers (the cheaper
         * on a tie), the cheapest one, and how many of sepax's points do. */
        const sweep_point *win = NULL, *cheap = NULL;
        int nwin = 0, nsx = 0;
        const sweep_point *beats[SCENE_ENGINE_COUNT] = {NULL};
        for (int i = 0; i < s->n; ++i) {
            const sweep_point *q = &s->p[i];
            if (q->engine != SCENE_SEPAX) continue;
            ++nsx;
            int all = 1;
            for (int k = 1; k < SCENE_ENGINE_COUNT; ++k) {
                const sweep_point *pk = cheapest_at(s, k, q->err);
                if (pk && pk->ms <= q->ms * SUMMARY_MS_TOL) {
                    all = 0;
                    continue;
                }
                if (!beats[k] || q->err < beats[k]->err) beats[k] = q;
            }
            if (!all) continue;
            ++nwin;
            if (!win || q->err < win->err || (q->err == win->err && q->ms < win->ms)) win = q;
            if (!cheap || q->ms < cheap->ms || (q->ms == cheap->ms && q->err < cheap->err))
                cheap = q;
        }
        char cell[SCENE_ENGINE_COUNT][480];
        for (int k = 1; k < SCENE_ENGINE_COUNT; ++k) {
            const sweep_point *ref = win ? win : most_accurate(s, SCENE_SEPAX);
            const sweep_point *pk = ref ? cheapest_at(s, k, ref->err) : NULL;
            if (win) {
                if (pk)
                    fmt_to(cell[k], sizeof cell[k],
                           "matches the error at %.3g ms (%s): sepax "
                           "%.2fx its cost",
                           pk->ms, pk->cfg, win->ms / pk->ms);
                else
                    fmt_to(cell[k], sizeof cell[k],
                           "never reaches %.3g (its best: %.3g at %.3g ms)", win->err,
                           most_accurate(s, k) ? most_accurate(s, k)->err : 0.0,
                           most_accurate(s, k) ? most_accurate(s, k)->ms : 0.0);
            } else if (beats[k]) {
                fmt_to(cell[k], sizeof cell[k], "beaten by sepax at %s (%.3g ms, %.3g)",
                       beats[k]->cfg, beats[k]->ms, beats[k]->err);
            } else {
                gap_words(s, k, cell[k], sizeof cell[k]);
            }
        }
        /* A peer whose most accurate configuration reaches an error no
         * sepax configuration reaches: said in its cell and listed below
         * the table, whatever the verdict (a win at the cheap end does not
         * make up for it). */
        const sweep_point *sx_best = most_accurate(s, SCENE_SEPAX);
        for (int k = 1; k < SCENE_ENGINE_COUNT; ++k) {
            const sweep_point *pb = most_accurate(s, k);
            if (!win || !pb || !sx_best || pb->err * SUMMARY_ERR_TOL >= sx_best->err) continue;
            size_t len = strlen(cell[k]);
            fmt_to(cell[k] + len, sizeof cell[k] - len,
                   "; its best, %.3g (%s, %.3g ms), is beyond every sepax configuration (best "
                   "%.3g)",
                   pb->err, pb->cfg, pb->ms, sx_best->err);
            if (reach_count < SUMMARY_MAX * 2) {
                fmt_to(reach[reach_count++], sizeof reach[0],
                       "%s: %s reaches %.3g (%s, %.3g ms); sepax's best is %.3g (%s, %.3g ms)",
                       s->scene, engine_names[k], pb->err, pb->cfg, pb->ms, sx_best->err,
                       sx_best->cfg, sx_best->ms);
            }
        }
        const sweep_point *shown = win ? win : most_accurate(s, SCENE_SEPAX);
        /* A '|' inside a cell would end it: the metric names use it for
         * absolute values. */
        char metric[128];
        size_t mlen = 0;
        for (const char *c = s->metric; *c && mlen + 3 < sizeof metric; ++c) {
            if (*c == '|') metric[mlen++] = '\\';
            metric[mlen++] = *c;
        }
        metric[mlen] = '\0';
        char verdict[64];
        if (win)
            fmt_to(verdict, sizeof verdict, "**sepax wins** (%d of %d configurations)", nwin, nsx);
        else
            fmt_to(verdict, sizeof verdict, "sepax does not win");
        /* The cheapest winner, with the least a peer pays to match it. */
        char cheap_cell[256] = "-";
        if (cheap) {
            double need = INFINITY;
            for (int k = 1; k < SCENE_ENGINE_COUNT; ++k) {
                const sweep_point *pk = cheapest_at(s, k, cheap->err);
                if (pk && pk->ms < need) need = pk->ms;
            }
            if (isfinite(need))
                fmt_to(cheap_cell, sizeof cheap_cell,
                       "%s (%.3g ms, %.3g): %.2fx the cheapest peer match", cheap->cfg, cheap->ms,
                       cheap->err, cheap->ms / need);
            else
                fmt_to(cheap_cell, sizeof cheap_cell, "%s (%.3g ms, %.3g): no peer matches",
                       cheap->cfg, cheap->ms, cheap->err);
        }
        char row[2400];
        fmt_to(row, sizeof row, "| %s | %s | %s | %s | %.3g ms, %.3g | %s | %s | %s |\n", s->scene,
               metric, verdict, shown ? shown->cfg : "-", shown ? shown->ms : 0.0,
               shown ? shown->err : 0.0, cell[1], cell[2], cheap_cell);
        out("%s", row);
        fputs(row, hf);
        if (!win) {
            fmt_to(lost[losses], sizeof lost[losses], "%s (%s; %s)", s->scene,
                   beats[1] ? "beats box2d alone" : cell[1],
                   beats[2] ? "beats chipmunk alone" : cell[2]);
            ++losses;
        }
    }
    if (losses == 0) {
        const char *msg = reach_count ? "\nsepax beats both peers on every accuracy scene of this "
                                        "run, on some only at the cheap end (below).\n"
                                      : "\nsepax beats both peers on every accuracy scene of this "
                                        "run.\n";
        out("%s", msg);
        fputs(msg, hf);
    } else {
        out("\n**Where sepax does not win** (%d of %d scenes):\n", losses, summary_count);
        fprintf(hf, "\n**Where sepax does not win** (%d of %d scenes):\n", losses, summary_count);
        for (int i = 0; i < losses; ++i) {
            out("- %s\n", lost[i]);
            fprintf(hf, "- %s\n", lost[i]);
        }
    }
    if (reach_count > 0) {
        out("\n**Scenes sepax wins only at the cheap end** (a peer reaches an error no sepax "
            "configuration reaches):\n");
        fprintf(hf, "\n**Scenes sepax wins only at the cheap end** (a peer reaches an error no "
                    "sepax configuration reaches):\n");
        for (int i = 0; i < reach_count; ++i) {
            out("- %s\n", reach[i]);
            fprintf(hf, "- %s\n", reach[i]);
        }
    }
    if (speed_note_count > 0) {
        out("\n**Throughput scenes where sepax is slower** (same run, ms per step):\n");
        fprintf(hf, "\n**Throughput scenes where sepax is slower** (same run, ms per step):\n");
        for (int i = 0; i < speed_note_count; ++i) {
            out("- %s\n", speed_notes[i]);
            fprintf(hf, "- %s\n", speed_notes[i]);
        }
    }
    fclose(hf);
    return 0;
}

/* ---- driver ------------------------------------------------------------------ */

int bench_scenes_run(const char *out_dir, int smoke, int level) {
    char path[1200];
    snprintf(path, sizeof path, "%s/scenes.csv", out_dir);
    csv_file = fopen(path, "w");
    if (!csv_file) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", path, strerror(errno));
        return 1;
    }
    fprintf(csv_file,
            "scene,engine,configuration,bodies,steps,ms_per_step,ms_per_frame,error_metric,error,"
            "details\n");
    snprintf(path, sizeof path, "%s/REPORT.md", out_dir);
    report_file = fopen(path, "w");
    if (!report_file) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", path, strerror(errno));
        fclose(csv_file);
        return 1;
    }
    md("# sepax world benchmarks\n\nGenerated by `sepax_bench --scenes%s%s` (sx_real = %s). "
       "Scene definitions: SCENES.md; method: bench/README.md. Data: scenes.csv.\n",
       smoke ? " --smoke" : "",
       level == 1   ? " --quick"
       : level == 2 ? " --full"
                    : "",
       sizeof(sx_real) == sizeof(double) ? "double" : "float");
    printf("\nsepax world scenes%s: sepax, Box2D 2.4, Chipmunk 7 in the same run, single "
           "thread\n",
           smoke ? " (smoke)" : "");

    /* SX_BENCH_SCENE=name runs that scene only (a prefix is enough). */
    const char *only = getenv("SX_BENCH_SCENE");
#define WANT(name) (!only || strncmp(only, name, strlen(only)) == 0)
    int failures = 0;
    if (WANT("large_pyramid"))
        failures += large_pyramid(smoke ? 3 : level == 1 ? 100 : level == 2 ? 500 : 200);
    if (WANT("mostly_asleep")) failures += mostly_asleep(smoke ? 2000 : 20000, smoke ? 3 : 60);
    if (WANT("rain")) {
        static const int smoke_sizes[1] = {200};
        static const int sizes[4] = {1000, 4000, 16000, 64000};
        if (smoke)
            failures += rain(smoke_sizes, 1, 3, 1e3, out_dir);
        else if (level == 1)
            failures += rain(sizes, 2, 60, 5e3, out_dir);
        else if (level == 2)
            failures += rain(sizes, 4, 100, 120e3, out_dir);
        else
            failures += rain(sizes, 3, 100, 8e3, out_dir);
    }
    /* The accuracy sweeps, in report order. */
    static const struct {
        const char *scene, *err_name, *what;
        acc_scene_fn fn;
    } sweeps[] = {
        {"bounce", "mean |apex/drop - e^2|",
         "circle r 0.5 dropped 2 m, e = 0.2, 0.5, 0.8; first apex / drop "
         "against e^2 (details: measured(exact))",
         bounce_run},
        {"incline", "mean |a - exact| m/s^2",
         "box on a 0.25 rad ramp, mu = 0.5 (sticks), 0.1, 0; acceleration "
         "between t = 0.5 and 2 s (details: measured(exact))",
         incline_run},
        {"pyramid20", "top drift m",
         "base-20 pyramid, 10 s; top box displacement between t = 1 s and "
         "10 s; max penetration beyond 5 mm slop (sepax narrowphase on the "
         "poses; Box2D's 1 cm skin reads as 0)",
         pyramid20_run},
        {"stack20", "lateral creep m",
         "20 boxes in a column, alternate rows shifted +-0.01 m, 10 s; "
         "largest lateral creep of a box",
         stack20_run},
        {"cradle", "|v_last - 1| + sum |v_others| m/s",
         "five circles r 0.5, 1 mm gaps, e = 1, mu = 0, no gravity, the first "
         "at 1 m/s; velocities after 1 s",
         cradle_run},
        {"projectile", "|p - parabola| m",
         "circle launched at (3, 8) m/s, no contacts, 2 s; distance to the "
         "parabola (details: measured(exact), distance to symplectic "
         "Euler's closed form at the engine's own step)",
         projectile_run},
        {"pileup", "momentum drift + energy gain",
         "40 circles and boxes thrown together in zero gravity, e = 0, "
         "4 s; |dP| / sum m|v0| + |dL| / sum m|r0||v0| + max(0, max KE / "
         "KE0 - 1)",
         pileup_run},
        {"mass_ratio", "max penetration beyond slop m",
         "density-100 box on a density-1 box on the ground, and a 20 m plank "
         "on two 1 m boxes, 5 s; largest overlap beyond 5 mm (every step, "
         "clamped at 1e-6)",
         mass_ratio_run},
        {"overlap_recovery", "max speed m/s",
         "base-4 pyramid created 25 % and 50 % overlapping (boxes and "
         "ground), 3 s; largest speed reached (details: time to separate, "
         "energy gained beyond separating in J, top y)",
         overlap_run},
        {"consistency", "rms |x(dt) - x(dt/2)| m",
         "40 mixed bodies tumbling into a container, run at dt and at dt/2; "
         "RMS distance between the two runs' positions at t = 1 s (details: "
         "at 0.25, 0.5, 1, 2 s)",
         consistency_run},
    };
    for (size_t k = 0; k < sizeof sweeps / sizeof sweeps[0]; ++k) {
        if (WANT(sweeps[k].scene))
            failures += run_sweep(sweeps[k].scene, sweeps[k].err_name, sweeps[k].what, sweeps[k].fn,
                                  out_dir, smoke);
    }
#undef WANT
    failures += write_summary(out_dir, smoke);
    fclose(csv_file);
    fclose(report_file);
    csv_file = report_file = NULL;
    printf("\nscene rows in %s/scenes.csv, plots and REPORT.md in %s\n", out_dir, out_dir);
    return failures;
}
