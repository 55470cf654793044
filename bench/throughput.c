/* sepax benchmarks — the throughput scenes of docs/scenes.md on every engine of
 * the run, single thread: large_pyramid (ms per step and the top box's sag,
 * with the sub-step front of sepax and Box2D v3), mostly_asleep (a large
 * sleeping world plus a small awake group against the group alone), rain
 * (ms per step against body count), and three scenes of Box2D v3's own
 * benchmark set rebuilt from their published descriptions: many_pyramids,
 * tumbler and smash. Each scene draws one picture with every engine: bars of
 * ms per step, or curves against body count for rain.
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

/* ---- shared by the scenes ---------------------------------------------------- */

/* The bar chart of a scene: ms[g * SCENE_ENGINE_COUNT + e] for each group g
 * (an engine that did not run has 0), linked from REPORT.md. */
static int scene_bars(const char *out_dir, const char *scene, const char *file, const char *title,
                      const char *const *groups, int ngroups, const double *ms) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", out_dir, file);
    if (!svg_bars_write(path, title, "ms per step (single thread; shorter is faster)", groups,
                        ngroups, engine_names, SCENE_ENGINE_COUNT, ms)) {
        fprintf(stderr, "sepax_bench: cannot write %s\n", path);
        return 1;
    }
    md("\n![%s](%s)\n", scene, file);
    return 0;
}

/* One headline note for a scene where sepax is slower than some peers,
 * naming each of them with sepax's time over theirs. */
static void note_slower(const char *scene, const double ms[SCENE_ENGINE_COUNT]) {
    char peers[200] = "";
    size_t len = 0;
    for (int e = 1; e < SCENE_ENGINE_COUNT; ++e) {
        if (!(ms[e] > 0) || !(ms[SCENE_SEPAX] > ms[e]) || len >= sizeof peers) continue;
        len += (size_t)snprintf(peers + len, sizeof peers - len, "%s %.2fx %s", len ? "," : "",
                                ms[SCENE_SEPAX] / ms[e], engine_names[e]);
    }
    if (len > 0) speed_note("%s: sepax %.2f ms/step,%s", scene, ms[SCENE_SEPAX], peers);
}

/* Steps an engine's world once untimed (the first step builds the engines'
 * trees and contact sets), then `steps` - 1 timed: ms per step of steps
 * 2..steps, as docs/scenes.md times them. *first_ms gets the first step's time. */
static double time_after_first(int e, void *w, int steps, double *first_ms) {
    double t0 = now_ms();
    engines[e]->step(w, 1);
    double t1 = now_ms();
    if (first_ms) *first_ms = t1 - t0;
    engines[e]->step(w, steps - 1);
    return (now_ms() - t1) / (double)(steps > 1 ? steps - 1 : 1);
}

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
    r->ms = time_after_first(e, w, steps, NULL);
    scene_state s;
    engines[e]->get(w, d->count - 1, &s);
    engines[e]->destroy(w);
    r->engine = e;
    r->c = *c;
    r->top_y = s.y;
    r->top_x = s.x;
    return 1;
}

/* sepax and Box2D v3 (SSE2) at their defaults on two workers (sepax: the
 * job system of samples/task_pool.h; v3: its own scheduler), against one,
 * all timed by the wall clock (CPU time adds up the threads), in
 * alternating rounds; the least of each. */
static int pyramid_workers(const scene_def *d, int steps) {
    static const int engines_2w[2] = {SCENE_SEPAX, SCENE_BOX2D3};
    double best[2][2] = {{0, 0}, {0, 0}};
    int failures = 0;
    out("\ntwo workers (wall clock, the least of 2 alternating rounds; single-thread figures "
        "above are CPU time):\n");
    md("```\n");
    out("%-14s %-36s %9s %9s %9s\n", "engine", "configuration", "ms/step", "x 1 worker", "sag");
    for (int round = 0; round < 2; ++round) {
        for (int k = 0; k < 2; ++k) {
            int e = engines_2w[k];
            if (!engine_runs(e)) continue;
            for (int w = 0; w < 2; ++w) {
                scene_config c = default_config(e, 1.0 / 60.0);
                c.workers = w + 1;
                void *world = engines[e]->create(d, &c);
                if (!world) {
                    ++failures;
                    continue;
                }
                engines[e]->step(world, 1);
                double t0 = wall_ms();
                engines[e]->step(world, steps - 1);
                double ms = (wall_ms() - t0) / (double)(steps > 1 ? steps - 1 : 1);
                scene_state s;
                engines[e]->get(world, d->count - 1, &s);
                engines[e]->destroy(world);
                if (best[k][w] == 0 || ms < best[k][w]) best[k][w] = ms;
                if (round == 1) {
                    char cfg[96], det[96];
                    config_name(e, &c, cfg, sizeof cfg);
                    out("%-14s %-36s %9.2f %9.2f %9.3f\n", engine_names[e], cfg, best[k][w],
                        best[k][w] / best[k][0], 99.5 - s.y);
                    snprintf(det, sizeof det, "top_y=%.4f;workers=%d;wall_clock=1", s.y, c.workers);
                    csv_row("large_pyramid_workers", e, &c, d->count - 1, steps, best[k][w],
                            "top_y_drop", 99.5 - s.y, det);
                }
            }
        }
    }
    md("```\n");
    if (best[0][1] > 0 && best[1][1] > 0)
        out("two workers: sepax %.2f ms against box2d3 %.2f ms (%.2fx)\n", best[0][1], best[1][1],
            best[0][1] / best[1][1]);
    return failures;
}

int large_pyramid(int steps, const char *out_dir) {
    scene_def d;
    if (!scene_init(&d, 5100)) return 1;
    build_pyramid(&d, 100, 100.0);
    out("\n## large_pyramid: base 100 (%d boxes), %d steps of 1/60 s, time of steps 2..%d\n\n",
        d.count - 1, steps, steps);
    md("```\n");
    out("%-14s %-28s %9s %9s %9s %9s\n", "engine", "configuration", "ms/step", "sx/this", "top y",
        "sag");
    /* Every engine at its defaults, then the sub-step front of sepax and of
     * Box2D v3 (1, 2 and 8 sub-steps beside the default 4). */
    enum { MAXRUNS = 24 };
    pyramid_run runs[MAXRUNS];
    int nr = 0, failures = 0;
    double sx_default_ms = 0.0, default_ms[SCENE_ENGINE_COUNT] = {0};
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
                if (pass == 0) default_ms[e] = r->ms;
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
    failures += pyramid_workers(&d, steps);
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
            !best                    ? "(no sepax configuration sags so little)"
            : best->ms <= runs[i].ms ? "dominates it"
                                     : "sags less but is slower");
        if (!best || best->ms > runs[i].ms)
            speed_note("large_pyramid: no sepax configuration matches box2d3 %s (%.2f ms, sag "
                       "%.3f m)%s",
                       a, runs[i].ms, 99.5 - runs[i].top_y, best ? " at no more time" : "");
    }
    /* The picture: sag against ms per step, one series per engine. */
    {
        svg_point pts[MAXRUNS];
        static char labels[MAXRUNS][96];
        char path[1200];
        for (int i = 0; i < nr; ++i) {
            const scene_config def = default_config(runs[i].engine, 1.0 / 60.0);
            char cfg[80];
            config_name(runs[i].engine, &runs[i].c, cfg, sizeof cfg);
            snprintf(labels[i], sizeof labels[i], "%s%s", cfg,
                     runs[i].c.sub_steps == def.sub_steps ? " (default)" : "");
            pts[i].x = runs[i].ms;
            /* floor: a log axis cannot show a sag of 0 */
            pts[i].y = 99.5 - runs[i].top_y > 1e-4 ? 99.5 - runs[i].top_y : 1e-4;
            pts[i].series = runs[i].engine;
            pts[i].label = labels[i];
        }
        snprintf(path, sizeof path, "%s/large_pyramid.svg", out_dir);
        if (!svg_plot_write(path, "large_pyramid: top-box sag against ms per step", "ms per step",
                            "sag of the top box (m)", pts, nr, engine_names, SCENE_ENGINE_COUNT)) {
            fprintf(stderr, "sepax_bench: cannot write %s\n", path);
            ++failures;
        }
        md("\n![large_pyramid](large_pyramid.svg)\n");
    }
    static const char *const group[1] = {""};
    failures +=
        scene_bars(out_dir, "large_pyramid, default configurations", "large_pyramid_bars.svg",
                   "large_pyramid: base 100 (5,050 boxes), each engine's default "
                   "configuration",
                   group, 1, default_ms);
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

int mostly_asleep(int resting, int steps, const char *out_dir) {
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
    /* the bars: row 0 the mixed world, row 1 the awake group alone */
    double mixed[2 * SCENE_ENGINE_COUNT] = {0};
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
        mixed[SCENE_ENGINE_COUNT + e] = ms_alone;
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
    note_slower("mostly_asleep", mixed);
    char g0[64], g1[64];
    snprintf(g0, sizeof g0, "%d asleep + 200 awake", resting);
    snprintf(g1, sizeof g1, "the 200 awake alone");
    const char *const groups[2] = {g0, g1};
    failures += scene_bars(out_dir, "mostly_asleep", "mostly_asleep.svg",
                           "mostly_asleep: a sleeping world and its 200 awake boxes alone", groups,
                           2, mixed);
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
        double at_k[SCENE_ENGINE_COUNT];
        for (int e = 0; e < SCENE_ENGINE_COUNT; ++e)
            at_k[e] = ms[e][k];
        char scene[32];
        snprintf(scene, sizeof scene, "rain %d", sizes[k]);
        note_slower(scene, at_k);
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

/* ---- Box2D v3's benchmark scenes ----------------------------------------------- */

/* What one engine's run of a scene reports. */
typedef struct scene_result {
    double ms, first_ms, err;
    char details[160];
} scene_result;

typedef int (*scene_run_fn)(const void *ctx, int e, const scene_config *c, scene_result *r);

/* Runs a scene on every engine at its default knobs (dt 1/60), prints and
 * records a row per engine, notes where sepax is slower, draws the bars. */
static int run_on_engines(const char *scene, const char *err_name, int bodies, int steps,
                          scene_run_fn fn, const void *ctx, const char *out_dir,
                          const char *title) {
    md("```\n");
    out("%-14s %9s %11s %8s %12s  %s\n", "engine", "ms/step", "step 1 (ms)", "sx/this", err_name,
        "details");
    double ms[SCENE_ENGINE_COUNT] = {0};
    int failures = 0;
    for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
        if (!engine_runs(e)) continue;
        const scene_config c = default_config(e, 1.0 / 60.0);
        scene_result r;
        memset(&r, 0, sizeof r);
        if (!fn(ctx, e, &c, &r)) {
            fprintf(stderr, "sepax_bench: %s: %s failed\n", scene, engine_names[e]);
            ++failures;
            continue;
        }
        ms[e] = r.ms;
        out("%-14s %9.3f %11.1f %8.2f %12.4g  %s\n", engine_names[e], r.ms, r.first_ms,
            ms[SCENE_SEPAX] / r.ms, r.err, r.details);
        csv_row(scene, e, &c, bodies, steps, r.ms, err_name, r.err, r.details);
    }
    md("```\n");
    out("sx/this = sepax's ms / this row's ms (< 1: sepax is slower); steps 2..%d timed, "
        "single thread, each engine's default knobs at dt 1/60.\n",
        steps);
    note_slower(scene, ms);
    char file[64];
    snprintf(file, sizeof file, "%s.svg", scene);
    static const char *const group[1] = {""};
    failures += scene_bars(out_dir, scene, file, title, group, 1, ms);
    return failures;
}

/* Builds the scene in engine e and times it (time_after_first); NULL when
 * the engine cannot build it. */
static void *create_and_time(const scene_def *d, int e, const scene_config *c, int steps,
                             scene_result *r) {
    void *w = engines[e]->create(d, c);
    if (w) r->ms = time_after_first(e, w, steps, &r->first_ms);
    return w;
}

/* many_pyramids (upstream benchmark/many_pyramids, after docs/scenes.md): a grid
 * of rows x columns pyramids of base 10 (55 unit boxes each), 11 m apart both
 * ways as upstream places them; each pyramid stands on its own static
 * segment 10.5 m long (upstream lays one long segment under each row). The
 * figure: the largest drop of a pyramid's top box (starts 9.5 m above its
 * ground). */
typedef struct pyramids_ctx {
    scene_def d;
    int *tops;
    int count, steps;
} pyramids_ctx;

static int pyramids_run(const void *ctx, int e, const scene_config *c, scene_result *r) {
    const pyramids_ctx *p = ctx;
    void *w = create_and_time(&p->d, e, c, p->steps, r);
    if (!w) return 0;
    double worst = 0.0, sum = 0.0;
    int down = 0;
    for (int k = 0; k < p->count; ++k) {
        scene_state s;
        engines[e]->get(w, p->tops[k], &s);
        const double drop = p->d.bodies[p->tops[k]].y - s.y;
        worst = fmax(worst, drop);
        sum += drop;
        down += drop > 0.5;
    }
    engines[e]->destroy(w);
    r->err = worst;
    snprintf(r->details, sizeof r->details, "mean_top_drop=%.4f;tops_down_over_0.5m=%d",
             sum / p->count, down);
    return 1;
}

int many_pyramids(int rows, int columns, int steps, const char *out_dir) {
    enum { BASE = 10 };
    const double pitch = BASE + 1.0;
    pyramids_ctx p;
    p.count = rows * columns;
    p.steps = steps;
    p.tops = malloc((size_t)p.count * sizeof *p.tops);
    if (!p.tops || !scene_init(&p.d, p.count * (1 + BASE * (BASE + 1) / 2))) {
        free(p.tops);
        return 1;
    }
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            const double cx = (j - 0.5 * (columns - 1)) * pitch, gy = i * pitch;
            set_segment(scene_add(&p.d, 0, cx, gy, 0.0), -0.5 * pitch + 0.25, 0.0,
                        0.5 * pitch - 0.25, 0.0);
            add_pyramid(&p.d, BASE, cx, gy);
            p.tops[i * columns + j] = p.d.count - 1;
        }
    }
    const int boxes = p.d.count - p.count;
    out("\n## many_pyramids: %d x %d pyramids of base %d (%d boxes), each on its own static "
        "segment, %d steps of 1/60 s\n\n",
        rows, columns, BASE, boxes, steps);
    char title[96];
    snprintf(title, sizeof title, "many_pyramids: %d x %d pyramids of base %d (%d boxes)", rows,
             columns, BASE, boxes);
    int failures = run_on_engines("many_pyramids", "max top drop m", boxes, steps, pyramids_run, &p,
                                  out_dir, title);
    scene_free(&p.d);
    free(p.tops);
    return failures;
}

/* tumbler (upstream benchmark/tumbler, after docs/scenes.md): a hollow box of four
 * walls 1 m thick centred 10 m from its middle at (0, 10) (19 m inside),
 * turning at upstream's 25 degrees per second. Upstream drives a dynamic box
 * with a revolute motor; the scene interface has no joints, so here the four
 * walls are kinematic bodies sharing one origin, as in upstream's washer.
 *
 * It is filled over time through the engines' add(): every 4th step a row of
 * 18 boxes 0.7 m apart, 6.5 m above the middle (inside the circle the walls
 * never cross), starts falling at 6 m/s. Rows keep 0.44 m apart while they
 * fall (all accelerate alike), so a row never lands on the previous one; a
 * spot where a box already is (the pile or a rebound) is skipped. The boxes
 * are 0.25 m tall and 0.25 to 0.5 m wide (half-extents 0.125 x 0.125..0.25,
 * the same sequence for every engine): about half the tumbler's area once
 * full (upstream: 2,025 squares of half-extent 0.125, a third). Timed: the
 * steps once all are in. The figure: boxes outside the walls in the
 * tumbler's frame (must be 0). */
enum { TUMBLER_ROW = 18, TUMBLER_ROW_EVERY = 4 };
static const double TUMBLER_CY = 10.0, TUMBLER_INNER = 9.5, TUMBLER_SPAWN_DY = 6.5,
                    TUMBLER_PITCH = 0.7, TUMBLER_V0 = 6.0;

typedef struct tumbler_ctx {
    scene_def walls, boxes;
    int steps, max_fill_steps;
} tumbler_ctx;

/* Adds a row of boxes, leaving out each spot with a box centre closer than
 * 0.56 m across (two boxes' widest half-diagonals) and 0.4 m up or down (a
 * tilted box's half-diagonal and a new box's half-height; the previous row
 * is 0.42-0.44 m below, by each engine's integrator); returns the number
 * added, -1 when the engine refuses one. */
static int tumbler_spawn(const tumbler_ctx *t, int e, void *w, int added) {
    unsigned char taken[TUMBLER_ROW] = {0};
    const double y = TUMBLER_CY + TUMBLER_SPAWN_DY, x0 = -0.5 * TUMBLER_PITCH * (TUMBLER_ROW - 1);
    for (int i = 0; i < added; ++i) {
        scene_state s;
        engines[e]->get(w, t->walls.count + i, &s);
        if (fabs(s.y - y) >= 0.4) continue;
        for (int k = 0; k < TUMBLER_ROW; ++k)
            if (fabs(s.x - (x0 + TUMBLER_PITCH * k)) < 0.56) taken[k] = 1;
    }
    int n = 0;
    for (int k = 0; k < TUMBLER_ROW && added + n < t->boxes.count; ++k) {
        if (taken[k]) continue;
        scene_body b = t->boxes.bodies[added + n];
        b.x = x0 + TUMBLER_PITCH * k;
        b.y = y;
        b.vy = -TUMBLER_V0;
        if (engines[e]->add(w, &b) < 0) return -1;
        ++n;
    }
    return n;
}

static int tumbler_run(const void *ctx, int e, const scene_config *c, scene_result *r) {
    const tumbler_ctx *t = ctx;
    void *w = engines[e]->create(&t->walls, c);
    if (!w) return 0;
    int added = 0, fill = 0;
    while (added < t->boxes.count && fill < t->max_fill_steps) {
        if (fill % TUMBLER_ROW_EVERY == 0) {
            const int n = tumbler_spawn(t, e, w, added);
            if (n < 0) {
                engines[e]->destroy(w);
                return 0;
            }
            added += n;
        }
        engines[e]->step(w, 1);
        ++fill;
    }
    r->ms = time_after_first(e, w, t->steps, &r->first_ms);
    scene_state wall;
    engines[e]->get(w, 0, &wall);
    const double cs = cos(wall.angle), sn = sin(wall.angle);
    int escaped = 0;
    for (int i = 0; i < added; ++i) {
        scene_state s;
        engines[e]->get(w, t->walls.count + i, &s);
        const double dx = s.x, dy = s.y - TUMBLER_CY;
        escaped +=
            fabs(cs * dx + sn * dy) > TUMBLER_INNER || fabs(-sn * dx + cs * dy) > TUMBLER_INNER;
    }
    engines[e]->destroy(w);
    r->err = escaped;
    snprintf(r->details, sizeof r->details, "boxes=%d;fill_steps=%d;wall_angle=%.3f", added, fill,
             wall.angle);
    return 1;
}

int tumbler(int boxes, int steps, const char *out_dir) {
    tumbler_ctx t;
    t.steps = steps;
    /* twice the steps of rows never skipped: a pile that keeps the spawn row
     * busy for long stops the fill (the details print the boxes in) */
    t.max_fill_steps = 2 * TUMBLER_ROW_EVERY * (boxes / TUMBLER_ROW + 1);
    if (!scene_init(&t.walls, 4)) return 1;
    if (!scene_init(&t.boxes, boxes)) {
        scene_free(&t.walls);
        return 1;
    }
    static const double walls[4][4] = {{0.5, 10.0, 10.0, 0.0},
                                       {0.5, 10.0, -10.0, 0.0},
                                       {10.0, 0.5, 0.0, 10.0},
                                       {10.0, 0.5, 0.0, -10.0}};
    for (int k = 0; k < 4; ++k) {
        scene_body *b = scene_add(&t.walls, 0, 0.0, TUMBLER_CY, 0.0);
        b->kinematic = 1;
        b->w = 25.0 * PI / 180.0;
        set_offset_box(b, walls[k][0], walls[k][1], walls[k][2], walls[k][3]);
    }
    bench_rng rng = bench_rng_make(91);
    for (int i = 0; i < boxes; ++i)
        set_box(scene_add(&t.boxes, 1, 0.0, 0.0, 0.0), bench_rng_range(&rng, 0.125, 0.25), 0.125);
    out("\n## tumbler: kinematic box 19 m inside turning at 25 deg/s, filled with %d boxes "
        "(0.25 m x 0.25..0.5 m) added in rows; %d steps of 1/60 s timed once full\n\n",
        boxes, steps);
    char title[96];
    snprintf(title, sizeof title, "tumbler: %d boxes in a turning box, once full", boxes);
    int failures =
        run_on_engines("tumbler", "escaped boxes", boxes, steps, tumbler_run, &t, out_dir, title);
    scene_free(&t.walls);
    scene_free(&t.boxes);
    return failures;
}

/* smash (upstream benchmark/smash): zero gravity; a ram (box of half-extent
 * 4, density 8) at 40 m/s into a block of columns x rows touching squares of
 * half-extent 0.2 (upstream: 120 x 80) with its left face at x = 29.8.
 * Upstream creates the block asleep and starts the ram at x = -20; the scene
 * interface cannot create sleeping bodies, so the block is awake from the
 * start and the ram starts at x = 20, 5.8 m from it (contact at step 9): the
 * timed steps are the smash. The figure: momentum drift, |P_end - P_0| / |P_0|
 * (no gravity, no static body: contacts only exchange momentum); details:
 * the ram's speed at the end. */
typedef struct smash_ctx {
    scene_def d;
    int steps;
} smash_ctx;

static int smash_run(const void *ctx, int e, const scene_config *c, scene_result *r) {
    const smash_ctx *m = ctx;
    void *w = create_and_time(&m->d, e, c, m->steps, r);
    if (!w) return 0;
    double p0x = 0.0, p0y = 0.0, px = 0.0, py = 0.0, ram_vx = 0.0;
    for (int i = 0; i < m->d.count; ++i) {
        const scene_body *b = &m->d.bodies[i];
        const double mass = b->density * 4.0 * b->shape.hx * b->shape.hy;
        scene_state s;
        engines[e]->get(w, i, &s);
        p0x += mass * b->vx;
        p0y += mass * b->vy;
        px += mass * s.vx;
        py += mass * s.vy;
        if (i == 0) ram_vx = s.vx;
    }
    engines[e]->destroy(w);
    r->err = hypot(px - p0x, py - p0y) / hypot(p0x, p0y);
    snprintf(r->details, sizeof r->details, "ram_vx_end=%.3f", ram_vx);
    return 1;
}

int smash(int columns, int rows, int steps, const char *out_dir) {
    smash_ctx m;
    m.steps = steps;
    if (!scene_init(&m.d, 1 + columns * rows)) return 1;
    m.d.gx = m.d.gy = 0.0;
    scene_body *ram = scene_add(&m.d, 1, 20.0, 0.0, 0.0);
    set_box(ram, 4.0, 4.0);
    ram->density = 8.0;
    ram->vx = 40.0;
    for (int i = 0; i < columns; ++i)
        for (int j = 0; j < rows; ++j)
            set_box(scene_add(&m.d, 1, 30.0 + 0.4 * i, 0.4 * (j - 0.5 * rows), 0.0), 0.2, 0.2);
    out("\n## smash: zero gravity, a ram (8 x 8 m, density 8) at 40 m/s into %d x %d touching "
        "squares of 0.4 m, %d steps of 1/60 s\n\n",
        columns, rows, steps);
    char title[96];
    snprintf(title, sizeof title, "smash: a ram into %d touching squares", columns * rows);
    int failures = run_on_engines("smash", "momentum drift", columns * rows, steps, smash_run, &m,
                                  out_dir, title);
    scene_free(&m.d);
    return failures;
}

/* ---- bullets ----------------------------------------------------------------- */

/* bullets: zero gravity; `projectiles` bullets (circles r 0.05, boxes 0.1 m
 * square and capsules 0.16 m long, by turns, spinning up to 30 rad/s) fired
 * from x in [-24, -16] at 200-1000 m/s, aimed within +-0.2 rad of +x at y in
 * [-8, 8], at a wall of 64 thin dynamic boxes (5 cm x 25 cm, stacked on
 * x = 0, y in [-8, 8]) with a thin static wall (10 cm x 40 m) at x = 4
 * behind it. The figure: the projectiles past the static wall at the end
 * whose flight, traced back along their velocity to its far face (x =
 * 4.05), crosses it within its span (y in +-20): tunnelled; the others
 * went around an end. Details: those around the ends, and those past the dynamic
 * wall's line too, where only a bullet sweep against dynamic bodies holds
 * them (a projectile may also get there by knocking a box aside). */
typedef struct bullets_ctx {
    scene_def d;
    int first, count, steps;
} bullets_ctx;

static int bullets_run(const void *ctx, int e, const scene_config *c, scene_result *r) {
    const bullets_ctx *b = ctx;
    void *w = create_and_time(&b->d, e, c, b->steps, r);
    if (!w) return 0;
    int tunnelled = 0, around = 0, past_boxes = 0;
    for (int i = b->first; i < b->first + b->count; ++i) {
        scene_state s;
        engines[e]->get(w, i, &s);
        /* past the wall: through it if its flight, traced back to the
         * wall's far face, crosses it within its 40 m span; beyond its
         * ends, it was deflected around them */
        if (!(s.x < 4.05)) {
            double y = s.vx > 0.0 ? s.y - (s.x - 4.05) * s.vy / s.vx : s.y;
            tunnelled += fabs(y) < 20.0;
            around += !(fabs(y) < 20.0);
        }
        past_boxes += !(s.x < 0.025);
    }
    engines[e]->destroy(w);
    r->err = tunnelled;
    snprintf(r->details, sizeof r->details,
             "tunnelled=%d;around_the_ends=%d;past_box_line=%d;of=%d", tunnelled, around,
             past_boxes, b->count);
    return 1;
}

int bullets(int projectiles, int steps, const char *out_dir) {
    bullets_ctx b;
    b.steps = steps;
    b.count = projectiles;
    if (!scene_init(&b.d, projectiles + 80)) return 1;
    b.d.gx = 0.0;
    b.d.gy = 0.0;
    set_box(scene_add(&b.d, 0, 4.0, 0.0, 0.0), 0.05, 20.0);
    for (int k = 0; k < 64; ++k)
        set_box(scene_add(&b.d, 1, 0.0, -8.0 + 0.25 * k + 0.125, 0.0), 0.025, 0.125);
    b.first = b.d.count;
    bench_rng rng = bench_rng_make(23);
    for (int i = 0; i < projectiles; ++i) {
        const double speed = bench_rng_range(&rng, 200.0, 1000.0);
        const double aim = bench_rng_range(&rng, -0.2, 0.2);
        const double x = bench_rng_range(&rng, -24.0, -16.0), y = bench_rng_range(&rng, -8.0, 8.0);
        scene_body *p = scene_add(&b.d, 1, x, y + x * tan(aim), bench_rng_range(&rng, -3.0, 3.0));
        p->vx = speed * cos(aim);
        p->vy = speed * sin(aim);
        p->w = bench_rng_range(&rng, -30.0, 30.0);
        p->bullet = 1;
        p->friction = 0.2;
        if (i % 3 == 0)
            set_circle(p, 0.05);
        else if (i % 3 == 1)
            set_box(p, 0.05, 0.05);
        else
            set_capsule(p, 0.05, 0.03);
    }
    out("\n## bullets: %d bullets at 200-1000 m/s (circles, boxes, capsules) at a wall of 64 "
        "thin dynamic boxes (5 cm) before a thin static wall (10 cm), no gravity; %d steps of "
        "1/60 s\n\n",
        projectiles, steps);
    char title[96];
    snprintf(title, sizeof title, "bullets: %d projectiles at thin walls", projectiles);
    int failures = run_on_engines("bullets", "tunnelled", projectiles, steps, bullets_run, &b,
                                  out_dir, title);
    scene_free(&b.d);
    return failures;
}
