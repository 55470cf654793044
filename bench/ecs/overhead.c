/* sepax benchmark — what the flecs module costs on top of the plain world.
 *
 * One scene, built twice: 10,000 dynamic bodies (boxes and balls in a
 * 100 x 100 grid) falling onto a wide static ground, once as flecs entities
 * stepped by the SepaxPhysics module (ecs_progress with the fixed step as
 * the frame time) and once as bodies of a plain sx_world stepped by
 * sx_world_step. The module's step does what the plain one does plus the
 * bulk copies between the flecs columns and the world, the contact buffer
 * and the event bookkeeping; the difference of the two is the overhead.
 *
 * The two runs take turns step by step, so a burst of load on this shared
 * machine hits both alike; the first step (which builds contacts and the
 * broadphase) is left out. The module's trajectories are bit-identical to
 * the plain world's (tests/test_ecs.c asserts it), and this program checks
 * it again at the end: a run that diverged would compare different work.
 *
 *   build/bench/sepax_bench_ecs [--steps N] [--out DIR]
 *
 * Prints the table and writes DIR/ecs_overhead.csv (DIR = build/bench). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sepax_flecs.h"

enum { COLUMNS = 100, ROWS = 100, BODIES = COLUMNS * ROWS };

static double now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static sx_vec2 grid_position(int i) {
    return sx_v2((sx_real)(i % COLUMNS) * SX_R(1.2) - SX_R(60.0),
                 SX_R(1.0) + (sx_real)(i / COLUMNS) * SX_R(1.2));
}

static sx_shape grid_shape(int i) {
    return i % 2 ? sx_box_shape(SX_R(0.4), SX_R(0.4)) : sx_circle_shape(sx_v2(0, 0), SX_R(0.4));
}

static sx_shape ground_shape(void) { return sx_box_shape(SX_R(80.0), SX_R(1.0)); }

static ecs_world_t *build_module_scene(ecs_entity_t *bodies) {
    ecs_world_t *world = ecs_init();
    ecs_entity_t ground = ecs_new(world);
    SxTransform t = {{SX_R(0.0), SX_R(-1.0)}, SX_R(0.0)};
    SxCollider c = sx_ecs_collider(ground_shape());
    int i;
    ECS_IMPORT(world, SepaxPhysics);
    ecs_set_ptr(world, ground, SxTransform, &t);
    ecs_set_ptr(world, ground, SxCollider, &c);
    for (i = 0; i < BODIES; ++i) {
        SxBody b = sx_ecs_body(SX_BODY_DYNAMIC);
        ecs_entity_t e = ecs_new(world);
        t.position = grid_position(i);
        t.angle = SX_R(0.0);
        c = sx_ecs_collider(grid_shape(i));
        ecs_set_ptr(world, e, SxTransform, &t);
        ecs_set_ptr(world, e, SxBody, &b);
        ecs_set_ptr(world, e, SxCollider, &c);
        bodies[i] = e;
    }
    return world;
}

/* Static geometry first, then the bodies in entity order: the order in
 * which the module creates them, so both worlds hold the same arrays. */
static sx_world *build_plain_scene(sx_body_id *bodies) {
    sx_world_def wdef = sx_default_world_def();
    sx_world *world = sx_world_create(&wdef);
    sx_body_def bdef = sx_default_body_def();
    sx_collider_def cdef = sx_default_collider_def();
    sx_body_id ground;
    int i;
    if (!world)
        return NULL;
    bdef.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    cdef.shape = ground_shape();
    if (sx_create_body(world, &bdef, &ground) != SX_OK ||
        sx_body_add_collider(world, ground, &cdef, NULL) != SX_OK)
        return NULL;
    bdef.type = SX_BODY_DYNAMIC;
    for (i = 0; i < BODIES; ++i) {
        bdef.position = grid_position(i);
        cdef.shape = grid_shape(i);
        if (sx_create_body(world, &bdef, &bodies[i]) != SX_OK ||
            sx_body_add_collider(world, bodies[i], &cdef, NULL) != SX_OK)
            return NULL;
    }
    return world;
}

int main(int argc, char **argv) {
    const char *out = "build/bench";
    int steps = 120, i, mismatched = 0;
    ecs_entity_t *entities = malloc(BODIES * sizeof *entities);
    sx_body_id *ids = malloc(BODIES * sizeof *ids);
    ecs_world_t *ecs;
    sx_world *plain;
    const SxPhysicsSettings *settings;
    double ms_module = 0.0, ms_plain = 0.0, overhead;
    char path[512];
    FILE *csv;
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--steps") && i + 1 < argc)
            steps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--out") && i + 1 < argc)
            out = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--steps N] [--out DIR]\n", argv[0]);
            return 2;
        }
    }
    if (steps < 2 || !entities || !ids) {
        fprintf(stderr, "sepax_bench_ecs: --steps must be at least 2\n");
        return 2;
    }
    ecs = build_module_scene(entities);
    plain = build_plain_scene(ids);
    if (!plain) {
        fprintf(stderr, "sepax_bench_ecs: building the plain scene failed\n");
        return 1;
    }
    settings = ecs_singleton_get(ecs, SxPhysicsSettings);
    for (i = 0; i < steps; ++i) {
        double t0 = now_ms(), t1, t2;
        ecs_progress(ecs, (ecs_ftime_t)settings->fixed_time_step);
        t1 = now_ms();
        sx_world_step(plain, settings->fixed_time_step);
        t2 = now_ms();
        if (i > 0) {
            ms_module += t1 - t0;
            ms_plain += t2 - t1;
        }
    }
    if (sx_ecs_step_count(ecs) != steps) {
        fprintf(stderr, "sepax_bench_ecs: the module ran %lld fixed steps for %d frames\n",
                (long long)sx_ecs_step_count(ecs), steps);
        return 1;
    }
    for (i = 0; i < BODIES; ++i) {
        sx_vec2 a = ecs_get(ecs, entities[i], SxTransform)->position;
        sx_vec2 b = sx_body_get_position(plain, ids[i]);
        if (memcmp(&a, &b, sizeof a) != 0)
            ++mismatched;
    }
    ms_module /= (double)(steps - 1);
    ms_plain /= (double)(steps - 1);
    overhead = ms_module / ms_plain - 1.0;
    printf("ECS overhead: %d bodies falling onto ground, %d steps of 1/60 s (steps 2..%d timed, "
           "the two runs interleaved)\n",
           BODIES, steps, steps);
    printf("  plain sx_world_step   %9.3f ms/step\n", ms_plain);
    printf("  SepaxPhysics module   %9.3f ms/step\n", ms_module);
    /* a few steps (make bench-smoke) show that the module runs, not what it costs */
    printf("  overhead              %8.1f %%   %s\n", overhead * 100.0,
           steps < 60 ? "(a smoke run of a few steps: nothing is judged)" : "(target <= 10 %)");
    printf("  positions bit-identical: %s\n", mismatched ? "NO" : "yes");
    snprintf(path, sizeof path, "%s/ecs_overhead.csv", out);
    csv = fopen(path, "w");
    if (csv) {
        fprintf(csv, "bodies,steps,ms_plain,ms_module,overhead,bit_identical\n");
        fprintf(csv, "%d,%d,%.4f,%.4f,%.4f,%d\n", BODIES, steps, ms_plain, ms_module, overhead,
                mismatched == 0);
        fclose(csv);
    } else {
        fprintf(stderr, "sepax_bench_ecs: cannot write %s\n", path);
    }
    sx_world_destroy(plain);
    ecs_fini(ecs);
    free(entities);
    free(ids);
    return mismatched ? 1 : 0;
}
