/* sepax sample — a pyramid of boxes on the ground (docs/scenes.md "pyramid20",
 * or any base given on the command line), stepped at 60 Hz. Prints where the
 * top box is once a simulated second and the wall-clock time per step.
 *
 * Build and run from the repository root (after `make`):
 *   cc -std=c99 -O2 -pthread -Iinclude samples/pyramid.c build/libsepax.a -lm -o build/pyramid
 *   ./build/pyramid [base] [seconds] [sleep|nosleep] [workers]
 *
 * The whole program is the plain-C world API: create a world from its
 * default settings, add a static ground and dynamic boxes, step, read the
 * state back, destroy the world. With workers > 1 the world's parallel
 * loops run on a small job system (task_pool.h), to the same bits. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <sepax/sepax.h>

#include "task_pool.h"

static double now_ms(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* Adds a body of the given type at p with one box collider. */
static sx_body_id add_box(sx_world *world, sx_body_type type, sx_vec2 p, sx_real hw, sx_real hh) {
    sx_body_def body = sx_default_body_def();
    sx_collider_def collider = sx_default_collider_def();
    sx_body_id id;
    body.type = type;
    body.position = p;
    if (sx_create_body(world, &body, &id) != SX_OK) {
        fprintf(stderr, "pyramid: could not create a body\n");
        exit(1);
    }
    collider.shape = sx_box_shape(hw, hh);
    collider.density = SX_R(1.0);
    collider.friction = SX_R(0.6);
    if (sx_body_add_collider(world, id, &collider, NULL) != SX_OK) {
        fprintf(stderr, "pyramid: could not add a collider\n");
        exit(1);
    }
    return id;
}

int main(int argc, char **argv) {
    int base = argc > 1 ? atoi(argv[1]) : 20;
    int seconds = argc > 2 ? atoi(argv[2]) : 10;
    bool sleep = !(argc > 3 && strcmp(argv[3], "nosleep") == 0);
    int workers = argc > 4 ? atoi(argv[4]) : 1;
    sx_world_def def = sx_default_world_def();
    sx_task_pool pool;
    sx_world *world;
    sx_body_id top = {0, 0};
    sx_real dt = SX_R(1.0) / SX_R(60.0);
    double elapsed = 0.0;
    int i, j, step;

    if (base < 1 || base > 1000 || seconds < 1 || workers < 1 || workers > SX_TASK_POOL_MAX) {
        fprintf(stderr, "usage: pyramid [base 1..1000] [seconds >= 1] [sleep|nosleep] [workers "
                        "1..16]\n");
        return 2;
    }
    /* gravity (0, -10), 5 sub-steps; a resting pyramid falls asleep unless
     * told not to (then the timing is the solver's) */
    def.enable_sleep = sleep;
    if (workers > 1) {
        if (!sx_task_pool_start(&pool, workers)) return 1;
        sx_task_pool_use(&pool, &def);
    }
    world = sx_world_create(&def);
    if (world == NULL) return 1;

    /* ground: top surface at y = 0 */
    add_box(world, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), SX_R(100.0), SX_R(1.0));
    for (i = 0; i < base; ++i) {
        for (j = i; j < base; ++j) {
            sx_vec2 p =
                sx_v2((sx_real)(i + 1) * SX_R(0.5) + (sx_real)(j - i) - SX_R(0.5) * (sx_real)base,
                      (sx_real)(2 * i + 1) * SX_R(0.5));
            top = add_box(world, SX_BODY_DYNAMIC, p, SX_R(0.5), SX_R(0.5));
        }
    }
    printf("pyramid of base %d: %d boxes, top box at y = %.4f\n", base,
           sx_world_body_count(world) - 1, (double)sx_body_get_position(world, top).y);

    for (step = 1; step <= 60 * seconds; ++step) {
        double start = now_ms();
        sx_world_step(world, dt);
        elapsed += now_ms() - start;
        if (step % 60 == 0) {
            sx_vec2 p = sx_body_get_position(world, top);
            printf("t = %2d s: top box at (%.4f, %.4f), %d contacts, %d bodies awake\n", step / 60,
                   (double)p.x, (double)p.y, sx_world_contact_count(world),
                   sx_world_awake_body_count(world));
        }
    }
    printf("%.3f ms per step (%s build, %d worker%s)\n", elapsed / (double)(60 * seconds),
           sx_real_is_double() ? "double" : "float", workers, workers > 1 ? "s" : "");
    sx_world_destroy(world);
    if (workers > 1) sx_task_pool_stop(&pool);
    return 0;
}
