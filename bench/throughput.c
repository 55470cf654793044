/* sepax benchmarks — the throughput scenes of docs/scenes.md on every engine of
 * the run, single thread: large_pyramid (ms per step and the top box's sag,
 * with the sub-step front of sepax and Box2D v3), mostly_asleep (a large
 * sleeping world plus a small awake group against the group alone) and rain
 * (ms per step against body count).
 *
 * Timing: wall clock around the stepping only, world creation excluded; the
 * first step is left out where it builds the engines' trees (docs/scenes.md:
 * time steps 2..N). These scenes run long enough per engine (>= 0.1 s) that
 * one run per configuration is kept; their verdicts are ratios in the same
 * run. */
#define _POSIX_C_SOURCE 200809L
#include "scene_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- large_pyramid --------------------------------------------------------- */

typedef struct pyramid_run {
    int engine;
    scene_config c;
    double ms, top_y, top_x;
} pyramid_run;

/* Builds the pyramid in engine e with knobs c, steps it, and times steps
 * 2..steps. Returns 0 when the engine cannot build it. */
static int pyramid_once(const scene_def *d, int e, const scene_config *c, int steps,
                        pyramid_run *r) {
    void *w = engines[e]->create(d, c);
    if (!w) return 0;
    engines[e]->step(w, 1);
    double t0 = now_ms();
    engines[e]->step(w, steps - 1);
    r->ms = (now_ms() - t0) / (double)(steps > 1 ? steps - 1 : 1);
    scene_state s;
    engines[e]->get(w, d->count - 1, &s);
    engines[e]->destroy(w);
    r->engine = e;
    r->c = *c;
    r->top_y = s.y;
    r->top_x = s.x;
    return 1;
}

int large_pyramid(int steps, const char *out_dir) {
    scene_def d;
    if (!scene_init(&d, 5100)) return 1;
    build_pyramid(&d, 100, 100.0);
    out("\n## large_pyramid: base 100 (%d boxes), %d steps of 1/60 s, time of steps 2..%d\n\n",
        d.count - 1, steps, steps);
    md("```\n");
    out("%-14s %-28s %9s %9s %9s %9s\n", "engine", "configuration", "ms/step", "sx/this",
        "top y", "sag");
    /* Every engine at its defaults, then the sub-step front of sepax and of
     * Box2D v3 (1, 2 and 8 sub-steps beside the default 4). */
    enum { MAXRUNS = 24 };
    pyramid_run runs[MAXRUNS];
    int nr = 0, failures = 0;
    double sx_default_ms = 0.0;
    for (int pass = 0; pass < 2; ++pass) {
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
            if (!engine_runs(e)) continue;
            static const int subs[3] = {1, 2, 8};
            int variants = pass == 0 ? 1 : (e == SCENE_SEPAX || e == SCENE_BOX2D3) ? 3 : 0;
            for (int v = 0; v < variants && nr < MAXRUNS; ++v) {
                scene_config c = default_config(e, 1.0 / 60.0);
                if (pass == 1) c.sub_steps = subs[v];
                pyramid_run *r = &runs[nr];
                if (!pyramid_once(&d, e, &c, steps, r)) {
                    fprintf(stderr, "sepax_bench: large_pyramid: %s failed to build\n",
                            engine_names[e]);
                    ++failures;
                    continue;
                }
                ++nr;
                if (e == SCENE_SEPAX && pass == 0) sx_default_ms = r->ms;
                char cfg[96], det[96];
                config_name(e, &c, cfg, sizeof cfg);
                out("%-14s %-28s %9.2f %9.2f %9.3f %9.3f\n", engine_names[e], cfg, r->ms,
                    sx_default_ms / r->ms, r->top_y, 99.5 - r->top_y);
                snprintf(det, sizeof det, "top_y=%.4f;top_dx=%.4f", r->top_y, r->top_x);
                csv_row("large_pyramid", e, &c, d.count - 1, steps, r->ms, "top_y_drop",
                        99.5 - r->top_y, det);
            }
        }
    }
    md("```\n");
    out("sx/this = sepax's default ms / this row's ms (< 1: sepax's default is slower). The top "
        "box starts at y 99.5; sag = 99.5 - top y.\n");
    /* The front: for each Box2D v3 configuration, the cheapest sepax one
     * that sags no more, and whether it is also no slower. */
    out("\nfront: for each box2d3 configuration, the cheapest sepax configuration with no more "
        "sag\n");
    for (int i = 0; i < nr; ++i) {
        if (runs[i].engine != SCENE_BOX2D3) continue;
        const pyramid_run *best = NULL;
        for (int j = 0; j < nr; ++j) {
            const pyramid_run *q = &runs[j];
            if (q->engine != SCENE_SEPAX || 99.5 - q->top_y > 99.5 - runs[i].top_y) continue;
            if (!best || q->ms < best->ms) best = q;
        }
        char a[96], b[96] = "none";
        config_name(SCENE_BOX2D3, &runs[i].c, a, sizeof a);
        if (best) config_name(SCENE_SEPAX, &best->c, b, sizeof b);
        out("  box2d3 %-14s %7.2f ms sag %7.3f: sepax %-28s %s\n", a, runs[i].ms,
            99.5 - runs[i].top_y, b,
            !best                      ? "(no sepax configuration sags so little)"
            : best->ms <= runs[i].ms ? "dominates it"
                                     : "sags less but is slower");
        if (!best || best->ms > runs[i].ms)
            speed_note("large_pyramid: no sepax configuration matches box2d3 %s (%.2f ms, sag "
                       "%.3f m)%s",
                       a, runs[i].ms, 99.5 - runs[i].top_y,
                       best ? " at no more time" : "");
    }
    /* The picture: sag against ms per step, one series per engine. */
    {
        svg_point pts[MAXRUNS];
        static char labels[MAXRUNS][96];
        char path[1200];
        for (int i = 0; i < nr; ++i) {
            config_name(runs[i].engine, &runs[i].c, labels[i], sizeof labels[i]);
            pts[i].x = runs[i].ms;
            /* floor: a log axis cannot show a sag of 0 */
            pts[i].y = 99.5 - runs[i].top_y > 1e-4 ? 99.5 - runs[i].top_y : 1e-4;
            pts[i].series = runs[i].engine;
            pts[i].label = labels[i];
        }
        snprintf(path, sizeof path, "%s/large_pyramid.svg", out_dir);
        if (!svg_plot_write(path, "large_pyramid: top-box sag against ms per step",
                            "ms per step", "sag of the top box (m)", pts, nr, engine_names,
                            SCENE_ENGINE_COUNT)) {
            fprintf(stderr, "sepax_bench: cannot write %s\n", path);
            ++failures;
        }
        md("\n![large_pyramid](large_pyramid.svg)\n");
    }
    scene_free(&d);
    return failures;
}

/* ---- mostly_asleep ---------------------------------------------------------- */

/* 200 awake boxes: 20 columns of 10, dropped with 0.2 m gaps left of x = 0. */
static void add_awake_group(scene_def *d) {
    for (int c = 0; c < 20; ++c)
        for (int r = 0; r < 10; ++r)
            set_box(scene_add(d, 1, -400.0 + 3.0 * c, 0.7 + 1.2 * r, 0.0), 0.5, 0.5);
}

static double time_steps(int e, void *w, int steps) {
    double t0 = now_ms();
    engines[e]->step(w, steps);
    return (now_ms() - t0) / (double)steps;
}

int mostly_asleep(int resting, int steps) {
    scene_def d, a;
    if (!scene_init(&d, resting + 300)) return 1;
    if (!scene_init(&a, 300)) return 1;
    d.sleep = a.sleep = 1;
    /* One long ground under both groups. */
    const double extent = 1.5 * resting + 500.0;
    set_box(scene_add(&d, 0, 0.0, -1.0, 0.0), extent, 1.0);
    for (int i = 0; i < resting; ++i)
        set_box(scene_add(&d, 1, 1.5 * i, 0.5, 0.0), 0.5, 0.5);
    set_box(scene_add(&a, 0, 0.0, -1.0, 0.0), extent, 1.0);
    add_awake_group(&a);

    out("\n## mostly_asleep: %d resting boxes (left to fall asleep) + 200 awake, against the 200 "
        "alone, %d steps\n\n",
        resting, steps);
    md("```\n");
    out("%-14s %8s %8s %12s %12s %9s %9s\n", "engine", "asleep", "settle", "mixed ms", "alone ms",
        "ratio", "awake end");
    int failures = 0;
    double mixed[SCENE_ENGINE_COUNT] = {0};
    for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
        if (!engine_runs(e)) continue;
        scene_config c = default_config(e, 1.0 / 60.0);
        void *w = engines[e]->create(&d, &c);
        if (!w) {
            ++failures;
            continue;
        }
        /* Let the resting boxes fall asleep, then add the awake group. */
        int settle = 0;
        while (engines[e]->awake(w) > 0 && settle < 600) {
            engines[e]->step(w, 10);
            settle += 10;
        }
        const int asleep = resting - engines[e]->awake(w);
        for (int i = 1; i < a.count; ++i)
            if (engines[e]->add(w, &a.bodies[i]) < 0) ++failures;
        double ms_mixed = time_steps(e, w, steps);
        const int awake_after = engines[e]->awake(w);
        engines[e]->destroy(w);
        void *w2 = engines[e]->create(&a, &c);
        if (!w2) {
            ++failures;
            continue;
        }
        double ms_alone = time_steps(e, w2, steps);
        engines[e]->destroy(w2);
        mixed[e] = ms_mixed;
        out("%-14s %8d %8d %12.3f %12.3f %9.2f %9d\n", engine_names[e], asleep, settle, ms_mixed,
            ms_alone, ms_mixed / ms_alone, awake_after);
        char det[128];
        snprintf(det, sizeof det, "asleep=%d;ms_alone=%.4f;awake_end=%d", asleep, ms_alone,
                 awake_after);
        csv_row("mostly_asleep", e, &c, resting + 200, steps, ms_mixed, "cost_ratio",
                ms_mixed / ms_alone, det);
        if (e == SCENE_SEPAX && ms_mixed > 2.0 * ms_alone)
            speed_note("mostly_asleep: %d sleeping + 200 awake cost %.1fx the 200 alone "
                       "(target <= 2)",
                       resting, ms_mixed / ms_alone);
    }
    md("```\n");
    out("ratio = mixed / alone (sepax's target: <= 2). Chipmunk's and Box2D 2.4's sleep timers "
        "differ from sepax's; 'asleep' says how many resting boxes each engine put to sleep.\n");
    for (int e = 1; e < SCENE_ENGINE_COUNT; ++e)
        if (mixed[e] > 0 && mixed[SCENE_SEPAX] > mixed[e])
            speed_note("mostly_asleep: sepax %.3f ms/step, %.2fx %s", mixed[SCENE_SEPAX],
                       mixed[SCENE_SEPAX] / mixed[e], engine_names[e]);
    scene_free(&d);
    scene_free(&a);
    return failures;
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

int rain(const int *sizes, int nsizes, int steps, double cap_ms, const char *out_dir) {
    out("\n## rain: mixed shapes (circles, boxes, capsules, 3..8-gons) falling into a container, "
        "time of steps 2..%d of 1/60 s (the first builds the engines' trees)\n\n",
        steps + 1);
    md("```\n");
    out("%-14s %8s %10s %12s %8s\n", "engine", "bodies", "ms/step", "step 1 (ms)", "sx/this");
    double ms[SCENE_ENGINE_COUNT][8] = {{0}};
    int failures = 0;
    for (int k = 0; k < nsizes && k < 8; ++k) {
        scene_def d;
        if (!scene_init(&d, sizes[k] + 8)) return 1;
        build_rain(&d, sizes[k], 77);
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
            if (!engine_runs(e)) continue;
            scene_config c = default_config(e, 1.0 / 60.0);
            /* A peer's first step at 64,000 bodies once grew past the
             * machine's memory: above 16,000 bodies Box2D 2.4 and Chipmunk
             * run only when asked. */
            if ((e == SCENE_BOX2D || e == SCENE_CHIPMUNK) && sizes[k] > 16000 &&
                !getenv("SX_BENCH_RAIN_PEERS_LARGE")) {
                out("%-14s %8d %10s  (skipped above 16,000 bodies: set "
                    "SX_BENCH_RAIN_PEERS_LARGE=1)\n",
                    engine_names[e], sizes[k], "-");
                continue;
            }
            void *w = engines[e]->create(&d, &c);
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
            engines[e]->step(w, 1);
            double t0 = now_ms(), elapsed = 0.0;
            t_first = t0 - t_first;
            int done = 0;
            while (done < steps && elapsed < cap_ms) {
                int chunk = steps - done < 5 ? steps - done : 5;
                engines[e]->step(w, chunk);
                done += chunk;
                elapsed = now_ms() - t0;
            }
            ms[e][k] = elapsed / (double)done;
            engines[e]->destroy(w);
            out("%-14s %8d %10.3f %12.1f %8.2f", engine_names[e], sizes[k], ms[e][k], t_first,
                ms[SCENE_SEPAX][k] / ms[e][k]);
            if (done < steps)
                out("  (stopped after %d steps: %.0f s cap)\n", done, cap_ms / 1000.0);
            else
                out("\n");
            char det[64];
            snprintf(det, sizeof det, "first_step_ms=%.3f", t_first);
            csv_row("rain", e, &c, sizes[k], done, ms[e][k], "none", 0.0, det);
        }
        scene_free(&d);
        for (int e = 1; e < SCENE_ENGINE_COUNT; ++e)
            if (ms[e][k] > 0 && ms[SCENE_SEPAX][k] > ms[e][k])
                speed_note("rain %d: sepax %.2f ms/step, %.2fx %s", sizes[k], ms[SCENE_SEPAX][k],
                           ms[SCENE_SEPAX][k] / ms[e][k], engine_names[e]);
    }
    if (nsizes >= 2) {
        out("log-log slope of ms/step against n (least squares, 1 = linear):");
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int m = 0;
            /* over the sizes the engine ran */
            for (int k = 0; k < nsizes && k < 8; ++k) {
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
