/* sepax benchmarks — what waking and destroying cost in a world of sleeping
 * bodies.
 *
 * The world: N dynamic unit boxes resting 0.5 m apart on static shelves of
 * 500 (one island per box: the most islands N bodies can make), stepped at
 * 60 Hz until every box sleeps. On such a world the figures are:
 * sx_world_set_gravity (which wakes every sleeping body), one step of the
 * sleeping world, waking one box and stepping once, and destroying the N
 * boxes one by one. Each should cost what it touches: the wake-all and the
 * destroy-all grow linearly with N (the ns per body column stays flat from
 * 20k to 50k bodies), and waking one box does not make the step scan every
 * sleeping body's contacts. Every
 * figure checks its world afterwards (all awake; no body and no contact
 * left), so a fast wrong answer fails the run.
 *
 * Timing: the process's CPU time (CLOCK_PROCESS_CPUTIME_ID) around the
 * operation only, so other load on a shared machine does not inflate it
 * (everything here runs on one thread); single runs; settling the world is
 * excluded and printed apart. */
#define _POSIX_C_SOURCE 200809L
#include "lifecycle.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <sepax/sepax.h>

#define SHELF_BOXES 500
#define SHELF_SPACING 3.0
/* steps allowed for the boxes to fall asleep (time_to_sleep is 0.5 s: 30) */
#define MAX_SETTLE_STEPS 600

/* CPU time of the process, ms. */
static double now_ms(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

typedef struct life_world {
    sx_world *w;
    sx_body_id *boxes;
    int n;
    double settle_ms;
    int settle_steps;
} life_world;

/* Builds the shelves and n boxes (n a multiple of SHELF_BOXES) and steps
 * until all sleep; false if they do not within MAX_SETTLE_STEPS. */
static int life_build(life_world *lw, int n) {
    sx_world_def wd = sx_default_world_def();
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    int shelves = n / SHELF_BOXES, k;
    double t0;
    wd.body_capacity = n + shelves;
    lw->w = sx_world_create(&wd);
    lw->boxes = (sx_body_id *)malloc((size_t)n * sizeof(sx_body_id));
    lw->n = n;
    if (lw->w == NULL || lw->boxes == NULL) return 0;
    cd.shape = sx_box_shape((sx_real)(0.75 * SHELF_BOXES + 1.0), SX_R(1.0));
    for (k = 0; k < shelves; ++k) {
        sx_body_id shelf;
        bd.position = sx_v2(SX_R(0.0), (sx_real)(SHELF_SPACING * k - 1.0));
        if (sx_create_body(lw->w, &bd, &shelf) != SX_OK) return 0;
        if (sx_body_add_collider(lw->w, shelf, &cd, NULL) != SX_OK) return 0;
    }
    bd.type = SX_BODY_DYNAMIC;
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
    for (k = 0; k < n; ++k) {
        int shelf = k / SHELF_BOXES, column = k % SHELF_BOXES;
        bd.position = sx_v2((sx_real)(1.5 * (column - 0.5 * (SHELF_BOXES - 1))),
                            (sx_real)(SHELF_SPACING * shelf + 0.5));
        if (sx_create_body(lw->w, &bd, &lw->boxes[k]) != SX_OK) return 0;
        if (sx_body_add_collider(lw->w, lw->boxes[k], &cd, NULL) != SX_OK) return 0;
    }
    t0 = now_ms();
    for (lw->settle_steps = 0; lw->settle_steps < MAX_SETTLE_STEPS; ++lw->settle_steps) {
        if (sx_world_awake_body_count(lw->w) == 0) break;
        if (sx_world_step(lw->w, SX_R(1.0) / SX_R(60.0)) != SX_OK) return 0;
    }
    lw->settle_ms = now_ms() - t0;
    return sx_world_awake_body_count(lw->w) == 0;
}

static void life_free(life_world *lw) {
    sx_world_destroy(lw->w);
    free(lw->boxes);
    lw->w = NULL;
    lw->boxes = NULL;
}

typedef struct life_row {
    const char *figure;
    int n;
    double ms;
    int ok;
} life_row;

static void life_print(FILE *csv, const life_row *r, double per) {
    printf("%-28s %7d %11.3f %13.1f  %s\n", r->figure, r->n, r->ms, per, r->ok ? "ok" : "FAILED");
    if (csv != NULL) fprintf(csv, "%s,%d,%.6f,%.3f,%d\n", r->figure, r->n, r->ms, per, r->ok);
}

/* sx_world_set_gravity on n sleeping boxes: it wakes all of them. */
static int life_gravity(FILE *csv, int n) {
    life_world lw = {0};
    life_row r = {"set_gravity (wakes all)", n, 0.0, 0};
    if (life_build(&lw, n)) {
        double t0 = now_ms();
        sx_status s = sx_world_set_gravity(lw.w, sx_v2(SX_R(0.0), SX_R(-9.0)));
        r.ms = now_ms() - t0;
        r.ok = s == SX_OK && sx_world_awake_body_count(lw.w) == n;
        printf("%-28s %7d %11.3f %13s  (%d steps to sleep, %.0f ms)\n", "  settle", n, lw.settle_ms,
               "", lw.settle_steps, lw.settle_ms);
    }
    life_print(csv, &r, r.ms * 1e6 / n);
    life_free(&lw);
    return r.ok ? 0 : 1;
}

/* One step of the sleeping world, then waking one box and stepping once,
 * then destroying the n boxes one by one. */
static int life_destroy(FILE *csv, int n) {
    life_world lw = {0};
    life_row asleep = {"step, all asleep", n, 0.0, 0};
    life_row wake = {"wake one box + step", n, 0.0, 0};
    life_row destroy = {"destroy one by one", n, 0.0, 0};
    int k;
    if (life_build(&lw, n)) {
        /* the step after the last box fell asleep freezes the contacts: the
         * one timed is the next, a sleeping world's steady state */
        sx_status s = sx_world_step(lw.w, SX_R(1.0) / SX_R(60.0));
        double t0 = now_ms();
        if (s == SX_OK) s = sx_world_step(lw.w, SX_R(1.0) / SX_R(60.0));
        asleep.ms = now_ms() - t0;
        asleep.ok = s == SX_OK && sx_world_awake_body_count(lw.w) == 0;
        t0 = now_ms();
        s = sx_body_set_awake(lw.w, lw.boxes[0], true);
        if (s == SX_OK) s = sx_world_step(lw.w, SX_R(1.0) / SX_R(60.0));
        wake.ms = now_ms() - t0;
        wake.ok = s == SX_OK && sx_world_awake_body_count(lw.w) == 1;
        destroy.ok = 1;
        t0 = now_ms();
        for (k = 0; k < n; ++k) {
            if (sx_destroy_body(lw.w, lw.boxes[k]) != SX_OK) destroy.ok = 0;
        }
        destroy.ms = now_ms() - t0;
        destroy.ok = destroy.ok && sx_world_body_count(lw.w) == n / SHELF_BOXES &&
                     sx_world_contact_count(lw.w) == 0 &&
                     sx_world_step(lw.w, SX_R(1.0) / SX_R(60.0)) == SX_OK &&
                     sx_world_contact_count(lw.w) == 0;
        printf("%-28s %7d %11.3f %13s  (%d steps to sleep, %.0f ms)\n", "  settle", n, lw.settle_ms,
               "", lw.settle_steps, lw.settle_ms);
    }
    life_print(csv, &asleep, asleep.ms * 1e6 / n);
    life_print(csv, &wake, wake.ms * 1e6 / n);
    life_print(csv, &destroy, destroy.ms * 1e6 / n);
    life_free(&lw);
    return (asleep.ok ? 0 : 1) + (wake.ok ? 0 : 1) + (destroy.ok ? 0 : 1);
}

int bench_lifecycle_run(const char *out_dir, int smoke) {
    static const int full[] = {20000, 50000};
    static const int small[] = {1000, 2000};
    const int *sizes = smoke ? small : full;
    char path[1100];
    FILE *csv;
    int i, failures = 0;
    snprintf(path, sizeof path, "%s/lifecycle.csv", out_dir);
    csv = fopen(path, "w");
    if (csv == NULL) {
        fprintf(stderr, "sepax_bench: cannot write %s\n", path);
        return 1;
    }
    fprintf(csv, "figure,bodies,ms,ns_per_body,ok\n");
    printf("\nsepax lifecycle benchmark%s: unit boxes asleep apart on static shelves of %d; "
           "single runs, CPU time\n",
           smoke ? " (smoke)" : "", SHELF_BOXES);
    printf("%-28s %7s %11s %13s\n", "figure", "bodies", "ms", "ns per body");
    for (i = 0; i < 2; ++i)
        failures += life_gravity(csv, sizes[i]);
    for (i = 0; i < 2; ++i)
        failures += life_destroy(csv, sizes[i]);
    fclose(csv);
    if (failures) fprintf(stderr, "sepax_bench: %d lifecycle checks failed\n", failures);
    return failures;
}
