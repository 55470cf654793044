/* sepax benchmarks — the naming of the symbols a Box2D v3 build exports
 * (see bench/box2d3/scenes.c): B3_EXPORT(scene_box2d3_) is
 * scene_box2d3_sse2 in the SSE2 build, and so on. */
#ifndef SEPAX_BENCH_B3_EXPORT_H
#define SEPAX_BENCH_B3_EXPORT_H

#ifndef B3_SUFFIX
#error "B3_SUFFIX must name the Box2D v3 build (set by the Makefile)"
#endif

#define B3_CAT2(a, b) a##b
#define B3_CAT(a, b) B3_CAT2(a, b)
#define B3_EXPORT(name) B3_CAT(name, B3_SUFFIX)

#endif
