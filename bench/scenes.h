/* sepax benchmarks — world-level scenes run by sepax, Box2D 2.4 and
 * Chipmunk 7 in the same process. A scene is described once as plain data
 * (bodies with one shape each, gravity, sleeping on or off); each engine
 * builds its own world from the very same numbers, steps it with its own
 * knobs (time step, sub-steps, iterations) and reports body states, so the
 * scene code that measures "the figure" (the top box's height, an apex, an
 * acceleration) is the same for all three engines. */
#ifndef SEPAX_BENCH_SCENES_H
#define SEPAX_BENCH_SCENES_H

#include "pairs.h"

#ifdef __cplusplus
extern "C" {
#endif

/** One rigid body with one shape in its local frame (bench_shape: circle,
 *  segment, capsule, box or sharp convex polygon, usually centred on its
 *  centroid; a polygon may sit off the body origin, which a kinematic body
 *  turns about: the tumbler's walls). */
typedef struct scene_body {
    int dynamic;   /**< 0: static (or kinematic, below) */
    int kinematic; /**< moved by its velocity only (dynamic is then 0) */
    double x, y, angle;
    double vx, vy, w;
    bench_shape shape;
    double density, friction, restitution;
    int bullet; /**< continuous collision against dynamic bodies too (sepax, both Box2Ds) */
} scene_body;

typedef struct scene_def {
    scene_body *bodies;
    int count, capacity;
    double gx, gy;
    int sleep; /**< allow sleeping */
} scene_def;

/** The knobs of one run. sub_steps: sepax's and Box2D v3's own sub-steps;
 *  Box2D 2.4 and Chipmunk have none, so for them it is the number of Step
 *  calls of dt / sub_steps each per scene step (how their users sub-step),
 *  and every engine's effective step is dt / sub_steps. Velocity/position
 *  iterations are sepax's and Box2D 2.4's; Chipmunk uses vel_iters as its
 *  iteration count; v3 has none. */
typedef struct scene_config {
    double dt;
    int sub_steps;
    int vel_iters;
    int pos_iters;
    /* 0 or 1: one thread (the default); more: the engine's parallel loops on
     * that many workers (sepax: samples/task_pool.h; Box2D v3: its own
     * scheduler), timed by the wall clock */
    int workers;
} scene_config;

typedef struct scene_state {
    double x, y, angle, vx, vy, w;
} scene_state;

/* ---- the engines, all behind the same four calls ------------------------ */

typedef enum scene_engine_id {
    SCENE_SEPAX = 0,
    SCENE_BOX2D3,        /**< Box2D v3, its default x86-64 build (SSE2) */
    SCENE_BOX2D,         /**< Box2D 2.4 (Debian) */
    SCENE_CHIPMUNK,      /**< Chipmunk 7 (Debian) */
    SCENE_BOX2D3_AVX2,   /**< Box2D v3 with -DBOX2D_AVX2 -mavx2 (run where the CPU has AVX2) */
    SCENE_BOX2D3_SCALAR, /**< Box2D v3 with -DBOX2D_DISABLE_SIMD */
    SCENE_ENGINE_COUNT
} scene_engine_id;

/** An engine behind the scene interface. add places one more body in a
 *  running world and returns its index (-1 on failure); awake counts the
 *  awake bodies (-1 when the engine cannot tell). */
typedef struct scene_engine {
    void *(*create)(const scene_def *def, const scene_config *cfg);
    void (*step)(void *world, int steps);
    void (*get)(void *world, int body, scene_state *out);
    void (*destroy)(void *world);
    int (*add)(void *world, const scene_body *body);
    int (*awake)(void *world);
} scene_engine;

/** The three Box2D v3 builds (bench/peer_box2d3.c, one object each). */
extern const scene_engine scene_box2d3_sse2, scene_box2d3_avx2, scene_box2d3_scalar;

/** Box2D 2.4 (bench/peer_scenes_box2d.cpp). */
extern const scene_engine scene_box2d;
/** Chipmunk 7 (bench/peer_scenes_chipmunk.cpp). Chipmunk mixes friction and
 *  elasticity as products; Box2D and sepax take sqrt(mu_a mu_b) and
 *  max(e_a, e_b). The adapter hands Chipmunk sqrt(mu) and sqrt(e) so that
 *  equal values on both sides mix to the same result in every engine (the
 *  scenes give both sides of a contact the same restitution). */
extern const scene_engine scene_chipmunk;

/** Runs the scene benchmarks (bench/scenes.c). level 0: the default run
 *  (large_pyramid 200 steps, rain to 16k with an 8 s cap per engine and
 *  size); 1 (--quick): fewer steps and sizes; 2 (--full): docs/scenes.md's 500
 *  steps and rain to 64k. smoke: every scene a few steps only. Writes
 *  out_dir/scenes.csv, the SVG plots, REPORT.md and headline.md. Returns the number of
 *  failures (0 when everything ran). */
int bench_scenes_run(const char *out_dir, int smoke, int level);

/* ---- SVG (bench/svg_plot.c) ---------------------------------------------- */

typedef struct svg_point {
    double x, y;
    int series;
    const char *label;
} svg_point;

/** Writes a log-log scatter plot of error (y) against ms per step (x): one
 *  colour per series, each series' Pareto front (no other point of the
 *  series is both faster and more accurate) joined by a line, each point
 *  labelled with its label (the configuration) in small type beside it. A
 *  label ending in " (default)" marks the series' default configuration:
 *  that point gets a ring. Returns 0 when the file cannot be written. */
int svg_plot_write(const char *path, const char *title, const char *xlabel, const char *ylabel,
                   const svg_point *pts, int n, const char *const *series_names, int series_count);
/** The same axes with each series' points joined in x order (a scaling
 *  curve); labels show only as the points' tooltips. */
int svg_plot_write_lines(const char *path, const char *title, const char *xlabel,
                         const char *ylabel, const svg_point *pts, int n,
                         const char *const *series_names, int series_count);
/** Writes a horizontal bar chart on a linear axis from 0 (xlabel: what the
 *  bars measure): for each group (a heading; none when there is one group
 *  with an empty name) one bar per series, in the series' colour of the
 *  other plots, its value printed at its end. values[g * series_count + s]
 *  is series s in group g; a value that is not > 0 reads "not run". Returns
 *  0 when the file cannot be written. */
int svg_bars_write(const char *path, const char *title, const char *xlabel,
                   const char *const *group_names, int group_count, const char *const *series_names,
                   int series_count, const double *values);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_BENCH_SCENES_H */
