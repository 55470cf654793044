/* sepax benchmarks — what the world-scene files share (bench/scenes.c: the
 * accuracy sweeps and the headline; bench/throughput.c: the throughput
 * scenes): the engine table, each engine's knobs, the report and CSV
 * writers, and the builders of scene descriptions. Private to bench/. */
#ifndef SEPAX_BENCH_SCENE_COMMON_H
#define SEPAX_BENCH_SCENE_COMMON_H

#include <stddef.h>
#include <stdint.h>

#include <sepax/sepax.h>

#include "scenes.h"

extern const double PI;

/* ---- engines ------------------------------------------------------------- */

/** Every engine of the run, indexed by scene_engine_id. */
extern const scene_engine *const engines[SCENE_ENGINE_COUNT];
extern const char *const engine_names[SCENE_ENGINE_COUNT];
/** Which build each engine is (one line each, for the report). */
extern const char *const engine_builds[SCENE_ENGINE_COUNT];
/** 1 when engine e can run on this CPU (the AVX2 build needs AVX2). */
int engine_runs(int e);
/** 1 for the engines of the accuracy sweeps and the headline: sepax and one
 *  build of each peer (Box2D v3's default SSE2 build; its other builds give
 *  the same physics and appear in the throughput scenes). */
int engine_in_sweeps(int e);
/** Engine e's standard knobs at time step dt: sepax's defaults (5 sub-steps
 *  of 3 velocity passes and 1 position pass), Box2D v3's (4 sub-steps),
 *  Box2D 2.4's 8/3, Chipmunk's 8 iterations. */
scene_config default_config(int e, double dt);
void config_name(int e, const scene_config *c, char *buf, size_t size);
/** Cost of one 1/60 s frame of simulated time. */
double frame_ms(double ms_per_step, const scene_config *c);
double now_ms(void);
/* The wall clock, for runs on several threads (now_ms's process CPU time
 * adds up the threads). */
double wall_ms(void);

/** sepax's shape for a bench shape (0 when the builder refuses it). */
int sepax_shape(const bench_shape *s, sx_shape *o);

/* ---- report --------------------------------------------------------------- */

/** Opens out_dir/scenes.csv and out_dir/REPORT.md (0 on failure). */
int report_open(const char *out_dir);
void report_close(void);
/** Printed to stdout and written to REPORT.md. */
void out(const char *fmt, ...);
/** Written to REPORT.md only. */
void md(const char *fmt, ...);
/** Sends md() to another file (NULL: back to REPORT.md); returns the old one. */
void *report_redirect(void *file);
/** One row of scenes.csv. */
void csv_row(const char *scene, int e, const scene_config *c, int bodies, int steps, double ms,
             const char *err_name, double err, const char *details);
/** A throughput result where sepax is slower than a peer, for the headline. */
void speed_note(const char *fmt, ...);
/** smoke != 0: speed_note records nothing (a smoke run's times judge nothing). */
void speed_notes_smoke(int smoke);
int speed_note_count(void);
const char *speed_note_text(int i);

/* ---- scene descriptions ----------------------------------------------------- */

int scene_init(scene_def *d, int capacity);
void scene_free(scene_def *d);
/** Appends a body (density 1, friction 0.6, at rest); dynamic 0 is static. */
scene_body *scene_add(scene_def *d, int dynamic, double x, double y, double angle);
void set_box(scene_body *b, double hx, double hy);
void set_circle(scene_body *b, double r);
void set_capsule(scene_body *b, double half_length, double r);
/** A two-sided segment from (x0, y0) to (x1, y1) in the body's frame. */
void set_segment(scene_body *b, double x0, double y0, double x1, double y1);
/** A box hx x hy centred at (cx, cy) in the body's frame (a polygon off the
 *  body origin: several such bodies at one origin turn as one, like the
 *  tumbler's walls). */
void set_offset_box(scene_body *b, double hx, double hy, double cx, double cy);
/** Regular n-gon of circumradius r, centred on its centroid. */
void set_ngon(scene_body *b, int n, double r);
/** docs/scenes.md's ground: a static box half_width x 1 centred at (0, -1). */
void add_ground(scene_def *d, double half_width);
/** The boxes of a pyramid of `base` unit boxes (half-extent 0.5), centred on
 *  x = cx, its bottom row resting on y = y0. */
void add_pyramid(scene_def *d, int base, double cx, double y0);
/** docs/scenes.md's pyramid of `base` unit boxes on that ground. */
void build_pyramid(scene_def *d, int base, double ground_half);

/* ---- the throughput scenes (bench/throughput.c) ---------------------------------- */

int large_pyramid(int steps, const char *out_dir);
int mostly_asleep(int resting, int steps, const char *out_dir);
int rain(const int *sizes, int nsizes, int steps, double cap_ms, const char *out_dir);
/* Box2D v3's benchmark scenes, rebuilt from their published descriptions. */
int many_pyramids(int rows, int columns, int steps, const char *out_dir);
int tumbler(int boxes, int steps, const char *out_dir);
int smash(int columns, int rows, int steps, const char *out_dir);
/* Fast projectiles (bullets) at a wall of thin dynamic boxes with a thin
 * static wall behind it; the figure is the number that tunnel through. */
int bullets(int projectiles, int steps, const char *out_dir);

#endif /* SEPAX_BENCH_SCENE_COMMON_H */
