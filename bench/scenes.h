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
 *  segment, capsule, box or sharp convex polygon centred on its centroid). */
typedef struct scene_body {
    int dynamic; /**< 0: static */
    double x, y, angle;
    double vx, vy;
    bench_shape shape;
    double density, friction, restitution;
} scene_body;

typedef struct scene_def {
    scene_body *bodies;
    int count, capacity;
    double gx, gy;
    int sleep; /**< allow sleeping */
} scene_def;

/** The knobs of one run. sub_steps is sepax's (the peers have none: 1);
 *  velocity/position iterations are Box2D's; Chipmunk uses vel_iters as its
 *  iteration count. */
typedef struct scene_config {
    double dt;
    int sub_steps;
    int vel_iters;
    int pos_iters;
} scene_config;

typedef struct scene_state {
    double x, y, angle, vx, vy, w;
} scene_state;

/* ---- the engines, all behind the same four calls ------------------------ */

typedef enum scene_engine_id {
    SCENE_SEPAX = 0,
    SCENE_BOX2D,
    SCENE_CHIPMUNK,
    SCENE_ENGINE_COUNT
} scene_engine_id;

/** Builds the engine's world (NULL on failure). */
void *scene_box2d_create(const scene_def *def, const scene_config *cfg);
void scene_box2d_step(void *world, int steps);
void scene_box2d_get(void *world, int body, scene_state *out);
void scene_box2d_destroy(void *world);

/** Chipmunk mixes friction and elasticity as products; Box2D and sepax take
 *  sqrt(mu_a mu_b) and max(e_a, e_b). The adapter hands Chipmunk sqrt(mu)
 *  and sqrt(e) so that equal values on both sides mix to the same result
 *  in all three engines (the scenes give both sides of a contact the same
 *  restitution). */
void *scene_chipmunk_create(const scene_def *def, const scene_config *cfg);
void scene_chipmunk_step(void *world, int steps);
void scene_chipmunk_get(void *world, int body, scene_state *out);
void scene_chipmunk_destroy(void *world);

/** Runs the scene benchmarks (bench/scenes.c). level 0: the default run
 *  (large_pyramid 200 steps, rain to 16k with an 8 s cap per engine and
 *  size); 1 (--quick): fewer steps and sizes; 2 (--full): SCENES.md's 500
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
 *  series is both faster and more accurate) joined by a line. Returns 0 when
 *  the file cannot be written. */
int svg_plot_write(const char *path, const char *title, const char *xlabel, const char *ylabel,
                   const svg_point *pts, int n, const char *const *series_names, int series_count);
/** The same axes with each series' points joined in x order (a scaling
 *  curve). */
int svg_plot_write_lines(const char *path, const char *title, const char *xlabel,
                         const char *ylabel, const svg_point *pts, int n,
                         const char *const *series_names, int series_count);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_BENCH_SCENES_H */
