/* sepax benchmarks — the engine table and the report plumbing shared by the
 * world scenes (bench/scene_common.h). Every scene is built once as plain
 * data and each engine makes its own world from it, so the bodies, shapes,
 * densities and frictions are the same numbers for every engine, and the
 * code that measures a scene's figure reads body states through one
 * interface (scene_engine). */
#define _POSIX_C_SOURCE 200809L
#include "scene_common.h"

#include "../samples/task_pool.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

const double PI = 3.14159265358979323846;

/* ---- report ------------------------------------------------------------------ */

/* The printed report goes to stdout and, between code fences, to REPORT.md. */
static FILE *report_file;
static FILE *csv_file;

int report_open(const char *out_dir) {
    char path[1200];
    snprintf(path, sizeof path, "%s/scenes.csv", out_dir);
    csv_file = fopen(path, "w");
    if (!csv_file) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", path, strerror(errno));
        return 0;
    }
    fprintf(csv_file,
            "scene,engine,configuration,bodies,steps,ms_per_step,ms_per_frame,error_metric,error,"
            "details\n");
    snprintf(path, sizeof path, "%s/REPORT.md", out_dir);
    report_file = fopen(path, "w");
    if (!report_file) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", path, strerror(errno));
        fclose(csv_file);
        csv_file = NULL;
        return 0;
    }
    return 1;
}

void report_close(void) {
    if (csv_file) fclose(csv_file);
    if (report_file) fclose(report_file);
    csv_file = report_file = NULL;
}

void *report_redirect(void *file) {
    FILE *old = report_file;
    report_file = file;
    return old;
}

void out(const char *fmt, ...) {
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

void md(const char *fmt, ...) {
    if (!report_file) return;
    va_list ap;
    va_start(ap, fmt);
    vfprintf(report_file, fmt, ap);
    va_end(ap);
}

enum { SPEED_NOTES_MAX = 64 };
static char speed_notes[SPEED_NOTES_MAX][240];
static int speed_notes_n, speed_notes_off;

void speed_notes_smoke(int smoke) { speed_notes_off = smoke; }

void speed_note(const char *fmt, ...) {
    if (speed_notes_n == SPEED_NOTES_MAX || speed_notes_off) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(speed_notes[speed_notes_n++], sizeof speed_notes[0], fmt, ap);
    va_end(ap);
}

int speed_note_count(void) { return speed_notes_n; }
const char *speed_note_text(int i) { return speed_notes[i]; }

double now_ms(void) {
    /* The process's CPU time by default: other processes on shared cores do
     * not inflate it (every engine here runs single-threaded);
     * SX_BENCH_CPU_TIME=0 times the wall clock instead. */
    static int cpu = -1;
    struct timespec ts;
    if (cpu < 0) cpu = getenv("SX_BENCH_CPU_TIME") == NULL || atoi(getenv("SX_BENCH_CPU_TIME")) != 0;
    clock_gettime(cpu ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

double wall_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* ---- scene descriptions -------------------------------------------------- */

int scene_init(scene_def *d, int capacity) {
    d->bodies = malloc((size_t)capacity * sizeof *d->bodies);
    d->count = 0;
    d->capacity = capacity;
    d->gx = 0.0;
    d->gy = -10.0;
    d->sleep = 0;
    return d->bodies != NULL;
}

void scene_free(scene_def *d) {
    free(d->bodies);
    d->bodies = NULL;
    d->count = d->capacity = 0;
}

scene_body *scene_add(scene_def *d, int dynamic, double x, double y, double angle) {
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

void set_box(scene_body *b, double hx, double hy) {
    b->shape.kind = BENCH_BOX;
    b->shape.count = 4;
    b->shape.hx = hx;
    b->shape.hy = hy;
    const double c[4][2] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
    memcpy(b->shape.v, c, sizeof c);
}

void set_circle(scene_body *b, double r) {
    b->shape.kind = BENCH_CIRCLE;
    b->shape.count = 1;
    b->shape.radius = r;
}

void set_capsule(scene_body *b, double half_length, double r) {
    b->shape.kind = BENCH_CAPSULE;
    b->shape.count = 2;
    b->shape.v[0][0] = -half_length;
    b->shape.v[1][0] = half_length;
    b->shape.radius = r;
}

void set_segment(scene_body *b, double x0, double y0, double x1, double y1) {
    b->shape.kind = BENCH_SEGMENT;
    b->shape.count = 2;
    b->shape.v[0][0] = x0;
    b->shape.v[0][1] = y0;
    b->shape.v[1][0] = x1;
    b->shape.v[1][1] = y1;
}

void set_offset_box(scene_body *b, double hx, double hy, double cx, double cy) {
    b->shape.kind = BENCH_POLYGON;
    b->shape.count = 4;
    const double c[4][2] = {
        {cx - hx, cy - hy}, {cx + hx, cy - hy}, {cx + hx, cy + hy}, {cx - hx, cy + hy}};
    memcpy(b->shape.v, c, sizeof c);
}

/* Regular n-gon of circumradius r, centred on its centroid. */
void set_ngon(scene_body *b, int n, double r) {
    b->shape.kind = BENCH_POLYGON;
    b->shape.count = n;
    for (int i = 0; i < n; ++i) {
        double a = 2.0 * PI * (double)i / (double)n;
        b->shape.v[i][0] = r * cos(a);
        b->shape.v[i][1] = r * sin(a);
    }
}

/* docs/scenes.md's ground: static box 100 x 1 centred at (0, -1). */
void add_ground(scene_def *d, double half_width) {
    set_box(scene_add(d, 0, 0.0, -1.0, 0.0), half_width, 1.0);
}
void add_pyramid(scene_def *d, int base, double cx, double y0) {
    for (int i = 0; i < base; ++i)
        for (int j = i; j < base; ++j)
            set_box(scene_add(d, 1, cx + (i + 1) * 0.5 + (j - i) * 1.0 - base * 0.5,
                              y0 + (2 * i + 1) * 0.5, 0.0),
                    0.5, 0.5);
}

void build_pyramid(scene_def *d, int base, double ground_half) {
    add_ground(d, ground_half);
    add_pyramid(d, base, 0.0, 0.0);
}

/* ---- the sepax engine ------------------------------------------------------ */

typedef struct sepax_world {
    sx_world *world;
    sx_body_id *ids;
    int count, capacity;
    sx_real dt;
    sx_task_pool *pool; /* scene_config.workers > 1 */
} sepax_world;

int sepax_shape(const bench_shape *s, sx_shape *o) {
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
    if (sw->world) sx_world_destroy(sw->world);
    if (sw->pool) {
        sx_task_pool_stop(sw->pool);
        free(sw->pool);
    }
    free(sw->ids);
    free(sw);
}

static int sepax_add(void *w, const scene_body *b) {
    sepax_world *sw = w;
    if (sw->count == sw->capacity) {
        int cap = sw->capacity * 2 + 16;
        sx_body_id *ids = realloc(sw->ids, (size_t)cap * sizeof *ids);
        if (!ids) return -1;
        sw->ids = ids;
        sw->capacity = cap;
    }
    sx_body_def bd = sx_default_body_def();
    bd.type = b->kinematic ? SX_BODY_KINEMATIC : b->dynamic ? SX_BODY_DYNAMIC : SX_BODY_STATIC;
    bd.position = sx_v2((sx_real)b->x, (sx_real)b->y);
    bd.angle = (sx_real)b->angle;
    bd.linear_velocity = sx_v2((sx_real)b->vx, (sx_real)b->vy);
    bd.angular_velocity = (sx_real)b->w;
    bd.bullet = b->bullet != 0;
    sx_collider_def cd = sx_default_collider_def();
    cd.density = (sx_real)b->density;
    cd.friction = (sx_real)b->friction;
    cd.restitution = (sx_real)b->restitution;
    sx_body_id id;
    if (!sepax_shape(&b->shape, &cd.shape) || sx_create_body(sw->world, &bd, &id) != SX_OK ||
        sx_body_add_collider(sw->world, id, &cd, NULL) != SX_OK)
        return -1;
    sw->ids[sw->count] = id;
    return sw->count++;
}

static void *sepax_create(const scene_def *def, const scene_config *cfg) {
    sx_world_def wd = sx_default_world_def();
    wd.gravity = sx_v2((sx_real)def->gx, (sx_real)def->gy);
    wd.sub_steps = cfg->sub_steps;
    wd.velocity_iterations = cfg->vel_iters;
    wd.position_iterations = cfg->pos_iters;
    wd.enable_sleep = def->sleep != 0;
    wd.body_capacity = def->count;
    /* SX_BENCH_CONTINUOUS=0: its cost, measured against the default */
    wd.enable_continuous =
        getenv("SX_BENCH_CONTINUOUS") == NULL || atoi(getenv("SX_BENCH_CONTINUOUS")) != 0;
    sepax_world *sw = calloc(1, sizeof *sw);
    if (!sw) return NULL;
    if (cfg->workers > 1) {
        sw->pool = calloc(1, sizeof *sw->pool);
        if (!sw->pool || !sx_task_pool_start(sw->pool, cfg->workers)) {
            sepax_destroy(sw);
            return NULL;
        }
        sx_task_pool_use(sw->pool, &wd);
    }
    sw->world = sx_world_create(&wd);
    sw->dt = (sx_real)cfg->dt;
    if (!sw->world) {
        sepax_destroy(sw);
        return NULL;
    }
    for (int i = 0; i < def->count; ++i) {
        if (sepax_add(sw, &def->bodies[i]) < 0) {
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

static int sepax_awake(void *w) {
    sepax_world *sw = w;
    return sx_world_awake_body_count(sw->world);
}

static const scene_engine scene_sepax = {sepax_create,  sepax_step, sepax_get,
                                         sepax_destroy, sepax_add,  sepax_awake};

/* ---- the engine table -------------------------------------------------------- */

const scene_engine *const engines[SCENE_ENGINE_COUNT] = {
    &scene_sepax,    &scene_box2d3_sse2, &scene_box2d,
    &scene_chipmunk, &scene_box2d3_avx2, &scene_box2d3_scalar,
};

const char *const engine_names[SCENE_ENGINE_COUNT] = {
#ifdef SX_DOUBLE
    "sepax-double",
#else
    "sepax",
#endif
    "box2d3",       "box2d", "chipmunk", "box2d3-avx2", "box2d3-scalar",
};

const char *const engine_builds[SCENE_ENGINE_COUNT] = {
    "this build of sepax (-O2, single thread)",
    "Box2D v3 (boxdd-sys 0.6.0, upstream 56edae7), -std=c17 -O2 -DNDEBUG, its default SSE2 "
    "path, workerCount 1",
    "Box2D 2.4.1, Debian's libbox2d (built with its asserts in)",
    "Chipmunk 7.0.3, Debian's libchipmunk (a debug build: asserts and checks in)",
    "Box2D v3 as box2d3 with -DBOX2D_AVX2 -mavx2",
    "Box2D v3 as box2d3 with -DBOX2D_DISABLE_SIMD (portable scalar path)",
};

int engine_runs(int e) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    if (e == SCENE_BOX2D3_AVX2) return __builtin_cpu_supports("avx2");
#endif
    return e != SCENE_BOX2D3_AVX2;
}

int engine_in_sweeps(int e) { return e <= SCENE_CHIPMUNK; }

static int is_box2d3(int e) {
    return e == SCENE_BOX2D3 || e == SCENE_BOX2D3_AVX2 || e == SCENE_BOX2D3_SCALAR;
}

scene_config default_config(int e, double dt) {
    scene_config c = {dt, 1, 8, 3, 1};
    if (e == SCENE_SEPAX) {
        sx_world_def wd = sx_default_world_def();
        c.sub_steps = wd.sub_steps;
        c.vel_iters = wd.velocity_iterations;
        c.pos_iters = wd.position_iterations;
    } else if (is_box2d3(e)) {
        c.sub_steps = 4; /* b2World_Step's documented recommendation */
        c.vel_iters = c.pos_iters = 0;
    } else if (e == SCENE_CHIPMUNK) {
        c.pos_iters = 0;
    }
    return c;
}

void config_name(int e, const scene_config *c, char *buf, size_t size) {
    int hz = (int)lround(1.0 / c->dt);
    char w[24] = "";
    if (c->workers > 1) snprintf(w, sizeof w, " workers=%d", c->workers);
    if (e == SCENE_SEPAX)
        snprintf(buf, size, "dt=1/%d sub=%d vel=%d pos=%d%s", hz, c->sub_steps, c->vel_iters,
                 c->pos_iters, w);
    else if (is_box2d3(e))
        snprintf(buf, size, "dt=1/%d sub=%d%s", hz, c->sub_steps, w);
    else if (e == SCENE_BOX2D)
        snprintf(buf, size, "dt=1/%d calls=%d vel=%d pos=%d", hz, c->sub_steps, c->vel_iters,
                 c->pos_iters);
    else
        snprintf(buf, size, "dt=1/%d calls=%d iter=%d", hz, c->sub_steps, c->vel_iters);
}

/* The fair cost across time steps: a run at 1/240 takes four steps per
 * frame. */
double frame_ms(double ms_per_step, const scene_config *c) {
    return ms_per_step * (1.0 / 60.0) / c->dt;
}

void csv_row(const char *scene, int e, const scene_config *c, int bodies, int steps, double ms,
             const char *err_name, double err, const char *details) {
    if (!csv_file) return;
    char cfg[96];
    config_name(e, c, cfg, sizeof cfg);
    fprintf(csv_file, "%s,%s,%s,%d,%d,%.6f,%.6f,%s,%.9g,%s\n", scene, engine_names[e], cfg, bodies,
            steps, ms, frame_ms(ms, c), err_name, err, details);
}
