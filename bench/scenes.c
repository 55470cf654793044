/* sepax benchmarks — the accuracy scenes of docs/scenes.md (bounce, incline,
 * pyramid20, stack20, cradle, projectile, pileup, mass_ratio,
 * overlap_recovery, consistency) on sepax and its peers, single thread, and
 * the driver of all world scenes (bench/throughput.c has the throughput
 * ones).
 *
 * Each accuracy scene has a known answer or a conserved quantity; each
 * engine runs it over a sweep of its knobs (time step, sub-steps or Step
 * calls per frame, iterations), and every configuration is reported as
 * error against ms per 1/60 s frame, drawn as one SVG plot per scene
 * (bench/svg_plot.c). Everything printed is also written to REPORT.md, and
 * every row to scenes.csv; the headline table (does a sepax configuration
 * beat every peer on each scene, or by how much does it miss) ends REPORT.md
 * and is also written alone to headline.md. */
#define _POSIX_C_SOURCE 200809L
#include "scene_common.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- accuracy scenes: knob sweeps ------------------------------------------- */

/* The sweep of one accuracy scene, to the same effective steps for every
 * engine: each engine at dt = 1/30, 1/60, 1/120, 1/240 with its standard
 * knobs, then at 1/60 with other sub-steps (sepax, Box2D v3: 1, 2, 8) or
 * more Step calls per frame (Box2D 2.4, Chipmunk: 8 and 16, i.e. effective
 * steps of 1/480 and 1/960 as sepax's and v3's 4 sub-steps at 1/120 and
 * 1/240) and other iteration counts (2, 4, 16). */
#define SWEEP_MAX 12

static int sweep_configs(int e, scene_config *c) {
    static const int hz[4] = {30, 60, 120, 240};
    int n = 0;
    for (int i = 0; i < 4; ++i)
        c[n++] = default_config(e, 1.0 / hz[i]);
    scene_config base = default_config(e, 1.0 / 60.0);
    if (e == SCENE_SEPAX || e == SCENE_BOX2D3) {
        static const int subs[3] = {1, 2, 8};
        for (int i = 0; i < 3; ++i) {
            c[n] = base;
            c[n++].sub_steps = subs[i];
        }
    } else {
        static const int calls[2] = {8, 16};
        for (int i = 0; i < 2; ++i) {
            c[n] = base;
            c[n++].sub_steps = calls[i];
        }
        static const int iters[3] = {2, 4, 16};
        for (int i = 0; i < 3; ++i) {
            c[n] = base;
            c[n].vel_iters = iters[i];
            if (e == SCENE_BOX2D) c[n].pos_iters = iters[i] >= 8 ? 6 : 2;
            ++n;
        }
    }
    return n;
}

/* What an accuracy scene measures on one run: its error and details. Its
 * cost is measured apart (below). */
typedef struct acc_result {
    double error;
    char details[160];
} acc_result;

typedef int (*acc_scene_fn)(int e, const scene_config *c, int smoke, acc_result *r);

/* Appends to a result's details, never past the buffer (a blown-up run can
 * print very long numbers). */
static void det_add(acc_result *r, const char *fmt, ...) {
    size_t len = strlen(r->details);
    if (len + 1 >= sizeof r->details) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(r->details + len, sizeof r->details - len, fmt, ap);
    va_end(ap);
}

/* ---- timing by replay ----------------------------------------------------------- */

/* A scene measures its error by reading body states between steps, often
 * every step; a clock read around each step would add its own cost (tens of
 * ns) to cells that are a fraction of a microsecond. So the scenes create
 * and step their timed worlds through rec_create / rec_step, which record
 * each world's description, knobs and step count; the cost is then measured
 * by replaying the recording: each world built again (untimed) and stepped
 * its whole count under one pair of clock reads. The replays of every
 * configuration of a sweep run in rounds (each round replays all of them
 * once), and the median over the rounds is reported. Worlds that are only a
 * reference (consistency's run at dt/2) are created directly and not
 * timed. */
#define REC_WORLDS 6

typedef struct rec_world {
    void *live; /* the world while the scene runs */
    scene_def def;
    scene_config cfg;
    long steps;
} rec_world;

typedef struct recording {
    int engine, n;
    rec_world w[REC_WORLDS];
} recording;

static recording *rec_now;

static void rec_free(recording *r) {
    for (int i = 0; i < r->n; ++i)
        free(r->w[i].def.bodies);
    r->n = 0;
}

static void *rec_create(int e, const scene_def *d, const scene_config *c) {
    void *w = engines[e]->create(d, c);
    if (!w || !rec_now || rec_now->n == REC_WORLDS) return w;
    rec_world *rw = &rec_now->w[rec_now->n];
    rw->def = *d;
    rw->def.bodies = malloc((size_t)(d->count > 0 ? d->count : 1) * sizeof *d->bodies);
    if (!rw->def.bodies) return w;
    memcpy(rw->def.bodies, d->bodies, (size_t)d->count * sizeof *d->bodies);
    rw->def.capacity = d->count;
    rw->cfg = *c;
    rw->steps = 0;
    rw->live = w;
    ++rec_now->n;
    return w;
}

static void rec_step(int e, void *w, int steps) {
    /* the newest world at that address: a destroyed world's may be reused */
    if (rec_now)
        for (int i = rec_now->n - 1; i >= 0; --i)
            if (rec_now->w[i].live == w) {
                rec_now->w[i].steps += steps;
                break;
            }
    engines[e]->step(w, steps);
}

static void rec_destroy(int e, void *w) {
    if (rec_now)
        for (int i = rec_now->n - 1; i >= 0; --i)
            if (rec_now->w[i].live == w) {
                rec_now->w[i].live = NULL;
                break;
            }
    engines[e]->destroy(w);
}

/* ms per step of one replay of a recording (NaN when a world cannot be
 * built again). */
static double rec_replay(const recording *r) {
    double ms = 0.0;
    long steps = 0;
    for (int i = 0; i < r->n; ++i) {
        const rec_world *rw = &r->w[i];
        void *w = engines[r->engine]->create(&rw->def, &rw->cfg);
        if (!w) return (double)NAN;
        double t0 = now_ms();
        for (long left = rw->steps; left > 0; left -= 1000000)
            engines[r->engine]->step(w, left > 1000000 ? 1000000 : (int)left);
        ms += now_ms() - t0;
        steps += rw->steps;
        engines[r->engine]->destroy(w);
    }
    return steps > 0 ? ms / (double)steps : (double)NAN;
}

/* ---- the sweep and its summary ---------------------------------------------------- */

/* Replay rounds per sweep (the cost is their median). */
#define ROUNDS 5

/* For each accuracy scene: every configuration's ms per 1/60 s frame (the
 * median and each round's) and error, kept for the verdicts once all sweeps
 * have run. */
typedef struct sweep_point {
    int engine, is_default;
    double ms, err;
    double ms_round[ROUNDS];
    char cfg[96];
} sweep_point;

typedef struct sweep_summary {
    char scene[32];
    char metric[64];
    int n, rounds;
    double noise; /* median over the points of (max - min) / median across rounds */
    sweep_point p[SCENE_ENGINE_COUNT * SWEEP_MAX];
} sweep_summary;

#define SUMMARY_MAX 16
static sweep_summary summaries[SUMMARY_MAX];
static int summary_count;

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(const double *v, int n) {
    double t[ROUNDS * SCENE_ENGINE_COUNT * SWEEP_MAX];
    if (n <= 0) return (double)NAN;
    memcpy(t, v, (size_t)n * sizeof *v);
    qsort(t, (size_t)n, sizeof *t, cmp_double);
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

static int run_sweep(const char *scene, const char *err_name, const char *what, acc_scene_fn fn,
                     const char *out_dir, int smoke) {
    enum { NP = SCENE_ENGINE_COUNT * SWEEP_MAX };
    static recording recs[NP];
    static scene_config cfgs[NP];
    static acc_result res[NP];
    static sweep_summary scratch;
    sweep_summary *sum = summary_count < SUMMARY_MAX ? &summaries[summary_count++] : &scratch;
    int failures = 0;
    memset(sum, 0, sizeof *sum);
    snprintf(sum->scene, sizeof sum->scene, "%s", scene);
    snprintf(sum->metric, sizeof sum->metric, "%s", err_name);
    sum->rounds = smoke ? 1 : ROUNDS;
    /* Errors first: each configuration once, recorded. */
    for (int e = 0; e < SCENE_ENGINE_COUNT; ++e) {
        if (!engine_in_sweeps(e) || !engine_runs(e)) continue;
        scene_config cs[SWEEP_MAX];
        int nc = sweep_configs(e, cs);
        for (int i = 0; i < nc && sum->n < NP; ++i) {
            recording *rc = &recs[sum->n];
            rc->engine = e;
            rc->n = 0;
            rec_now = rc;
            memset(&res[sum->n], 0, sizeof res[sum->n]);
            int ok = fn(e, &cs[i], smoke, &res[sum->n]);
            rec_now = NULL;
            if (!ok) {
                fprintf(stderr, "sepax_bench: %s: %s failed\n", scene, engine_names[e]);
                rec_free(rc);
                ++failures;
                continue;
            }
            sweep_point *sp = &sum->p[sum->n];
            sp->engine = e;
            sp->is_default = i == 1; /* dt 1/60 with the standard knobs */
            sp->err = res[sum->n].error;
            config_name(e, &cs[i], sp->cfg, sizeof sp->cfg);
            cfgs[sum->n] = cs[i];
            ++sum->n;
        }
    }
    /* Then the costs: rounds of replays of every configuration. */
    for (int k = 0; k < sum->rounds; ++k)
        for (int i = 0; i < sum->n; ++i)
            sum->p[i].ms_round[k] = frame_ms(rec_replay(&recs[i]), &cfgs[i]);
    double spread[NP];
    for (int i = 0; i < sum->n; ++i) {
        sweep_point *sp = &sum->p[i];
        sp->ms = median(sp->ms_round, sum->rounds);
        double lo = sp->ms_round[0], hi = lo;
        for (int k = 1; k < sum->rounds; ++k) {
            lo = fmin(lo, sp->ms_round[k]);
            hi = fmax(hi, sp->ms_round[k]);
        }
        spread[i] = sp->ms > 0 ? (hi - lo) / sp->ms : 0.0;
        rec_free(&recs[i]);
    }
    sum->noise = median(spread, sum->n);

    out("\n## %s: %s\n\n", scene, what);
    md("```\n");
    out("%-12s %-28s %9s %9s %12s  %s\n", "engine", "configuration", "ms/step", "ms/frame",
        err_name, "details");
    svg_point pts[NP];
    static char labels[NP][112];
    for (int i = 0; i < sum->n; ++i) {
        const sweep_point *sp = &sum->p[i];
        const double ms_step = sp->ms * cfgs[i].dt * 60.0;
        out("%-12s %-28s %9.4f %9.4f %12.4g  %s\n", engine_names[sp->engine], sp->cfg, ms_step,
            sp->ms, sp->err, res[i].details);
        csv_row(scene, sp->engine, &cfgs[i], 0, 0, ms_step, err_name, sp->err, res[i].details);
        snprintf(labels[i], sizeof labels[i], "%s%s", sp->cfg, sp->is_default ? " (default)" : "");
        pts[i].x = sp->ms;
        pts[i].y = sp->err;
        pts[i].series = sp->engine;
        pts[i].label = labels[i];
    }
    out("ms/frame = ms per 1/60 s of simulated time (the plot's x axis), the median of %d "
        "rounds; the spread of a configuration's rounds, (max - min) / median, is %.0f %% at "
        "the median configuration.\n",
        sum->rounds, 100.0 * sum->noise);
    md("```\n");
    char path[1200], file[64], title[160];
    snprintf(file, sizeof file, "%s.svg", scene);
    snprintf(path, sizeof path, "%s/%s", out_dir, file);
    snprintf(title, sizeof title, "%s: %s against ms per 1/60 s frame", scene, err_name);
    if (!svg_plot_write(path, title, "ms per 1/60 s of simulated time", err_name, pts, sum->n,
                        engine_names, SCENE_ENGINE_COUNT)) {
        fprintf(stderr, "sepax_bench: cannot write %s\n", path);
        ++failures;
    }
    md("\n![%s](%s)\n", scene, file);
    return failures;
}

/* bounce: a circle r 0.5 dropped from 2 m (its bottom 2 m above the ground)
 * with restitution e on ground of the same e; the first apex over the drop
 * height against e^2. Error: mean |apex/drop - e^2| over e = 0.2, 0.5, 0.8. */
static int bounce_run(int e, const scene_config *c, int smoke, acc_result *r) {
    static const double es[3] = {0.2, 0.5, 0.8};
    double err = 0.0;
    for (int k = 0; k < 3; ++k) {
        scene_def d;
        if (!scene_init(&d, 4)) return 0;
        add_ground(&d, 100.0);
        d.bodies[0].restitution = es[k];
        scene_body *b = scene_add(&d, 1, 0.0, 2.5, 0.0);
        set_circle(b, 0.5);
        b->restitution = es[k];
        void *w = rec_create(e, &d, c);
        scene_free(&d);
        if (!w) return 0;
        const int steps = smoke ? 5 : (int)ceil(1.5 / c->dt);
        double apex = -1.0, prev_vy = -1.0;
        int bounced = 0;
        for (int i = 0; i < steps; ++i) {
            rec_step(e, w, 1);
            scene_state s;
            engines[e]->get(w, 1, &s);
            if (s.vy > 0.0) bounced = 1;
            if (bounced && s.y > apex) apex = s.y;
            if (bounced && prev_vy > 0.0 && s.vy <= 0.0) break;
            prev_vy = s.vy;
        }
        rec_destroy(e, w);
        double ratio = apex > 0.0 ? (apex - 0.5) / 2.0 : 0.0;
        err += fabs(ratio - es[k] * es[k]) / 3.0;
        det_add(r, "e=%.1f:%.4f(%.4f) ", es[k], ratio, es[k] * es[k]);
    }
    r->error = err;
    return 1;
}

/* incline: a box (half-extent 0.5) on a static ramp at 0.25 rad; mu = 0.5
 * (sticks: tan 0.25 = 0.2553), 0.1 and 0 (slides at g (sin - mu cos)).
 * Acceleration measured from the velocity along the ramp between t = 0.5 s
 * and 2 s (after the landing transient). Error: mean |a - exact| in m/s^2. */
static int incline_run(int e, const scene_config *c, int smoke, acc_result *r) {
    static const double mus[3] = {0.5, 0.1, 0.0};
    const double th = 0.25, sn = sin(th), cs = cos(th);
    double err = 0.0;
    for (int k = 0; k < 3; ++k) {
        scene_def d;
        if (!scene_init(&d, 4)) return 0;
        scene_body *ramp = scene_add(&d, 0, 0.0, 0.0, th);
        set_box(ramp, 30.0, 0.5);
        ramp->friction = mus[k];
        /* On the top face, 10 m up the slope. */
        scene_body *b = scene_add(&d, 1, 10.0 * cs - 1.0 * sn, 10.0 * sn + 1.0 * cs, th);
        set_box(b, 0.5, 0.5);
        b->friction = mus[k];
        void *w = rec_create(e, &d, c);
        scene_free(&d);
        if (!w) return 0;
        const int n0 = (int)lround(0.5 / c->dt), n1 = smoke ? n0 + 2 : (int)lround(2.0 / c->dt);
        double v0 = 0.0, v1 = 0.0;
        for (int i = 1; i <= n1; ++i) {
            rec_step(e, w, 1);
            scene_state s;
            engines[e]->get(w, 1, &s);
            double along = -(s.vx * cs + s.vy * sn); /* down the slope */
            if (i == n0) v0 = along;
            if (i == n1) v1 = along;
        }
        rec_destroy(e, w);
        double a = (v1 - v0) / ((n1 - n0) * c->dt);
        double exact = mus[k] >= tan(th) ? 0.0 : 10.0 * (sn - mus[k] * cs);
        err += fabs(a - exact) / 3.0;
        det_add(r, "mu=%.1f:%.4f(%.4f) ", mus[k], a, exact);
    }
    r->error = err;
    return 1;
}

/* Largest overlap beyond the slop between any two boxes of a pyramid, or a
 * box and the ground, measured by sepax's own narrowphase on the reported
 * poses (exact squares: Box2D's 1 cm skin shows as a gap). */
static double pyramid_penetration(void *w, int e, int count) {
    scene_state st[256];
    sx_shape box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    double worst = 0.0;
    for (int i = 1; i < count && i < 256; ++i)
        engines[e]->get(w, i, &st[i]);
    for (int i = 1; i < count && i < 256; ++i) {
        sx_xform xi =
            sx_xform_make(sx_v2((sx_real)st[i].x, (sx_real)st[i].y), (sx_real)st[i].angle);
        double ground = 0.0 - (st[i].y - 0.5 * (fabs(cos(st[i].angle)) + fabs(sin(st[i].angle))));
        if (ground > worst) worst = ground;
        for (int j = i + 1; j < count && j < 256; ++j) {
            double dx = st[j].x - st[i].x, dy = st[j].y - st[i].y;
            if (dx * dx + dy * dy > 2.1) continue;
            sx_xform xj =
                sx_xform_make(sx_v2((sx_real)st[j].x, (sx_real)st[j].y), (sx_real)st[j].angle);
            sx_manifold m;
            if (sx_collide(&box, xi, &box, xj, &m) > 0)
                for (int k = 0; k < m.count; ++k)
                    if ((double)m.points[k].depth > worst) worst = (double)m.points[k].depth;
        }
    }
    return worst > 0.005 ? worst - 0.005 : 0.0;
}

/* pyramid20: base 20 on the ground, 10 s. Error: the top box's drift, its
 * displacement between t = 1 s (settled) and t = 10 s; also the largest
 * penetration beyond the 5 mm slop (sampled every 0.25 s), the final
 * top y (starts 19.5) and the top's largest displacement from t = 1 s of
 * any sample after it (a pyramid that sways reads at t = 10 s wherever its
 * swing is). */
static int pyramid20_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 220)) return 0;
    build_pyramid(&d, 20, 100.0);
    const int top = d.count - 1, count = d.count;
    void *w = rec_create(e, &d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(10.0 / c->dt), n1 = (int)lround(1.0 / c->dt);
    const int every = (int)lround(0.25 / c->dt);
    double pen = 0.0, swing = 0.0;
    scene_state s1 = {0, 0, 0, 0, 0, 0}, s;
    for (int i = 1; i <= n; ++i) {
        rec_step(e, w, 1);
        if (i == n1) engines[e]->get(w, top, &s1);
        if (i % every == 0 || i == n) {
            double p = pyramid_penetration(w, e, count);
            if (p > pen) pen = p;
            if (i > n1) {
                engines[e]->get(w, top, &s);
                if (hypot(s.x - s1.x, s.y - s1.y) > swing) swing = hypot(s.x - s1.x, s.y - s1.y);
            }
        }
    }
    engines[e]->get(w, top, &s);
    rec_destroy(e, w);
    if (n < n1) s1 = s;
    r->error = hypot(s.x - s1.x, s.y - s1.y);
    if (r->error < 1e-7) r->error = 1e-7;
    snprintf(r->details, sizeof r->details,
             "top_y=%.4f top_x=%.4f max_pen_beyond_slop=%.4f max_drift=%.3g", s.y, s.x, pen, swing);
    return 1;
}

/* stack20: 20 boxes (half-extent 0.5) in a column, alternate rows shifted
 * +-0.01 m, 10 s. Error: the largest lateral creep of a box from where it
 * started; details: top y (starts 19.5), the largest penetration beyond
 * the slop (as pyramid20) and the largest creep of any sample (every
 * 0.25 s): a column that sways reads at t = 10 s wherever its swing is. */
static int stack20_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 24)) return 0;
    add_ground(&d, 100.0);
    for (int i = 0; i < 20; ++i)
        set_box(scene_add(&d, 1, i % 2 ? 0.01 : -0.01, 0.5 + i, 0.0), 0.5, 0.5);
    const int count = d.count;
    double x0[24];
    for (int i = 0; i < count; ++i)
        x0[i] = d.bodies[i].x;
    void *w = rec_create(e, &d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(10.0 / c->dt), every = (int)lround(0.25 / c->dt);
    double pen = 0.0, swing = 0.0;
    scene_state s;
    for (int i = 1; i <= n; ++i) {
        rec_step(e, w, 1);
        if (i % every == 0 || i == n) {
            double p = pyramid_penetration(w, e, count);
            if (p > pen) pen = p;
            for (int k = 1; k < count; ++k) {
                engines[e]->get(w, k, &s);
                if (fabs(s.x - x0[k]) > swing) swing = fabs(s.x - x0[k]);
            }
        }
    }
    double creep = 0.0;
    for (int i = 1; i < count; ++i) {
        engines[e]->get(w, i, &s);
        if (fabs(s.x - x0[i]) > creep) creep = fabs(s.x - x0[i]);
    }
    rec_destroy(e, w);
    r->error = creep > 1e-7 ? creep : 1e-7;
    snprintf(r->details, sizeof r->details, "top_y=%.4f max_pen_beyond_slop=%.4f max_creep=%.5f",
             s.y, pen, swing);
    return 1;
}

/* cradle: five circles r 0.5 in a row, 1 mm gaps, e = 1, mu = 0, no
 * gravity; the first moves at 2 m/s. After 1 s the last should leave at
 * 2 m/s and the others rest. Error: |v_last - 2| + the sum of the others'
 * |v|; details: momentum and kinetic energy (both start at 1.571 for
 * 0.785 kg bodies). The speed stays clear of the engines' restitution
 * thresholds (1 m/s in sepax and both Box2Ds: below it they do not
 * bounce). */
#define CRADLE_SPEED 2.0

static int cradle_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 8)) return 0;
    d.gy = 0.0;
    for (int i = 0; i < 5; ++i) {
        scene_body *b = scene_add(&d, 1, i * 1.001, 0.0, 0.0);
        set_circle(b, 0.5);
        b->friction = 0.0;
        b->restitution = 1.0;
        if (i == 0) b->vx = CRADLE_SPEED;
    }
    void *w = rec_create(e, &d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(1.0 / c->dt);
    rec_step(e, w, n);
    double err = 0.0, p = 0.0, ke = 0.0;
    const double m = PI * 0.25;
    scene_state s;
    for (int i = 0; i < 5; ++i) {
        engines[e]->get(w, i, &s);
        err += i == 4 ? fabs(s.vx - CRADLE_SPEED) : hypot(s.vx, s.vy);
        p += m * s.vx;
        ke += 0.5 * m * (s.vx * s.vx + s.vy * s.vy);
    }
    engines[e]->get(w, 4, &s);
    rec_destroy(e, w);
    r->error = err > 1e-7 ? err : 1e-7;
    snprintf(r->details, sizeof r->details,
             "v_last=%.4f momentum=%.4f energy=%.4f (%.4f, %.4f)", s.vx, p, ke, m * CRADLE_SPEED,
             0.5 * m * CRADLE_SPEED * CRADLE_SPEED);
    return 1;
}

/* ---- helpers of the conservation and contact scenes -------------------------- */

/* Mass and moment of inertia of a scene body from its shape and density
 * (boxes, circles and sharp polygons: what these scenes use). */
static void body_mass(const scene_body *b, double *m, double *inertia) {
    const bench_shape *s = &b->shape;
    if (s->kind == BENCH_CIRCLE) {
        *m = b->density * PI * s->radius * s->radius;
        *inertia = 0.5 * *m * s->radius * s->radius;
    } else if (s->kind == BENCH_BOX) {
        *m = b->density * 4.0 * s->hx * s->hy;
        *inertia = *m * (s->hx * s->hx + s->hy * s->hy) / 3.0;
    } else { /* polygon about its centroid (the origin): triangle fan */
        double area = 0.0, i0 = 0.0;
        for (int k = 0; k < s->count; ++k) {
            const double *p = s->v[k], *q = s->v[(k + 1) % s->count];
            double cr = p[0] * q[1] - p[1] * q[0];
            area += 0.5 * cr;
            i0 += cr *
                  (p[0] * p[0] + p[0] * q[0] + q[0] * q[0] + p[1] * p[1] + p[1] * q[1] +
                   q[1] * q[1]) /
                  12.0;
        }
        *m = b->density * area;
        *inertia = b->density * i0;
    }
}

/* Radius of the circle around a shape's local origin that holds it. */
static double shape_reach(const bench_shape *s) {
    if (s->kind == BENCH_BOX) return hypot(s->hx, s->hy);
    double r = 0.0;
    for (int k = 0; k < s->count; ++k) {
        double d = hypot(s->v[k][0], s->v[k][1]);
        if (d > r) r = d;
    }
    return r + s->radius;
}

/* Largest overlap between any two bodies of a scene (dynamic against dynamic
 * or static), measured as pyramid_penetration does: sepax's sx_collide on
 * the poses the engine reports, on the exact shapes of the description (so
 * Box2D's 1 cm polygon skin reads as a gap). Returns the raw depth in m. */
static double scene_max_depth(void *w, int e, const scene_def *d) {
    enum { MAXB = 64 };
    sx_shape sh[MAXB];
    sx_xform xf[MAXB];
    double px[MAXB], py[MAXB], reach[MAXB];
    int n = d->count < MAXB ? d->count : MAXB;
    for (int i = 0; i < n; ++i) {
        const scene_body *b = &d->bodies[i];
        scene_state s = {b->x, b->y, b->angle, 0, 0, 0};
        if (b->dynamic) engines[e]->get(w, i, &s);
        if (!sepax_shape(&b->shape, &sh[i])) return 0.0;
        xf[i] = sx_xform_make(sx_v2((sx_real)s.x, (sx_real)s.y), (sx_real)s.angle);
        px[i] = s.x;
        py[i] = s.y;
        reach[i] = shape_reach(&b->shape);
    }
    double worst = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (!d->bodies[i].dynamic && !d->bodies[j].dynamic) continue;
            if (hypot(px[j] - px[i], py[j] - py[i]) > reach[i] + reach[j]) continue;
            sx_manifold m;
            if (sx_collide(&sh[i], xf[i], &sh[j], xf[j], &m) > 0)
                for (int k = 0; k < m.count; ++k)
                    if ((double)m.points[k].depth > worst) worst = (double)m.points[k].depth;
        }
    return worst;
}

/* ---- projectile ------------------------------------------------------------------ */

/* projectile: a circle r 0.5 launched from the origin at (3, 8) m/s, no
 * contacts, 2 s. Error: distance to the parabola at t = n dt; details: the
 * distance to symplectic Euler's closed form with the engine's own step
 * (dt / sub_steps: sub-steps or Step calls), i.e. what is left once the integrator's known
 * O(h) error is taken out (rounding, damping, anything else). */
static int projectile_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 2)) return 0;
    const double vx0 = 3.0, vy0 = 8.0, g = 10.0;
    scene_body *b = scene_add(&d, 1, 0.0, 0.0, 0.0);
    set_circle(b, 0.5);
    b->vx = vx0;
    b->vy = vy0;
    void *w = rec_create(e, &d, c);
    scene_free(&d);
    if (!w) return 0;
    const int n = smoke ? 3 : (int)lround(2.0 / c->dt);
    rec_step(e, w, n);
    scene_state s;
    engines[e]->get(w, 0, &s);
    rec_destroy(e, w);
    const double t = n * c->dt;
    const double xe = vx0 * t, ye = vy0 * t - 0.5 * g * t * t;
    /* Symplectic Euler, m steps of h: v_k = vy0 - g h k, y_m = sum h v_k. */
    const int sub = c->sub_steps > 0 ? c->sub_steps : 1;
    const double h = c->dt / sub, m = (double)n * sub;
    const double y_euler = h * m * vy0 - g * h * h * m * (m + 1.0) * 0.5;
    r->error = hypot(s.x - xe, s.y - ye);
    if (r->error < 1e-9) r->error = 1e-9;
    snprintf(r->details, sizeof r->details,
             "x=%.5f(%.5f) y=%.5f(%.5f) vy=%.4f(%.4f) dev_from_euler=%.3g", s.x, xe, s.y, ye, s.vy,
             vy0 - g * t, hypot(s.x - xe, s.y - y_euler));
    return 1;
}

/* ---- pileup ---------------------------------------------------------------------- */

/* 40 bodies (circles r 0.4 and 0.8 x 0.6 boxes in turn) on a ring of radius
 * 7..9 m, thrown towards its centre at 3..5 m/s with +-0.15 rad of aim
 * error, zero gravity, friction 0.5, restitution 0: they meet around
 * t = 1.8 s and make a pile that keeps the drift of the total momentum. */
static void build_pileup(scene_def *d) {
    bench_rng rng = bench_rng_make(5);
    d->gy = 0.0;
    const int n = 40;
    for (int i = 0; i < n; ++i) {
        double a = 2.0 * PI * (double)i / (double)n;
        double rad = 8.0 + bench_rng_range(&rng, -1.0, 1.0);
        scene_body *b = scene_add(d, 1, rad * cos(a), rad * sin(a), bench_rng_range(&rng, -PI, PI));
        if (i % 2)
            set_box(b, 0.4, 0.3);
        else
            set_circle(b, 0.4);
        double sp = bench_rng_range(&rng, 3.0, 5.0), da = bench_rng_range(&rng, -0.15, 0.15);
        b->vx = -sp * cos(a + da);
        b->vy = -sp * sin(a + da);
        b->friction = 0.5;
    }
}

/* pileup: 4 s. Error: the drift of the linear momentum |P(T) - P(0)| /
 * sum m |v0|, plus that of the angular momentum about the origin
 * |L(T) - L(0)| / sum m |r0| |v0| (contact and friction impulses conserve
 * both; position corrections that move bodies without a matching impulse
 * change L), plus the largest kinetic energy gain max_t KE(t) / KE(0) - 1
 * (clamped at 0: inelastic impacts may only lose energy). Each part and the
 * final KE / KE(0) are in the details. P, L and KE at t = 0 are read back
 * from the engine, so a float engine's rounding of the initial values is
 * not counted as drift. */
static int pileup_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 48)) return 0;
    build_pileup(&d);
    const int count = d.count;
    double mass[48], inertia[48], pscale = 0.0, lscale = 0.0;
    for (int i = 0; i < count; ++i) {
        const scene_body *b = &d.bodies[i];
        body_mass(b, &mass[i], &inertia[i]);
        pscale += mass[i] * hypot(b->vx, b->vy);
        lscale += mass[i] * hypot(b->x, b->y) * hypot(b->vx, b->vy);
    }
    void *w = rec_create(e, &d, c);
    scene_free(&d);
    if (!w) return 0;
    /* Momenta and energy of the state as the engine holds it (its own
     * rounding of the initial values) before and after each step. */
    double now[4] = {0}, start[4] = {0};
    const int n = smoke ? 3 : (int)lround(4.0 / c->dt);
    double gain = 0.0;
    for (int k = 0; k <= n; ++k) {
        if (k > 0) {
            rec_step(e, w, 1);
        }
        now[0] = now[1] = now[2] = now[3] = 0.0; /* px, py, L, KE */
        for (int i = 0; i < count; ++i) {
            scene_state s;
            engines[e]->get(w, i, &s);
            now[0] += mass[i] * s.vx;
            now[1] += mass[i] * s.vy;
            now[2] += mass[i] * (s.x * s.vy - s.y * s.vx) + inertia[i] * s.w;
            now[3] += 0.5 * mass[i] * (s.vx * s.vx + s.vy * s.vy) + 0.5 * inertia[i] * s.w * s.w;
        }
        if (k == 0) memcpy(start, now, sizeof start);
        if (now[3] / start[3] - 1.0 > gain) gain = now[3] / start[3] - 1.0;
    }
    rec_destroy(e, w);
    const double dp = hypot(now[0] - start[0], now[1] - start[1]) / pscale;
    const double dl = fabs(now[2] - start[2]) / lscale;
    r->error = dp + dl + gain;
    if (r->error < 1e-12) r->error = 1e-12;
    snprintf(r->details, sizeof r->details,
             "momentum_drift=%.3g ang_momentum_drift=%.3g energy_gain=%.3g ke_end/ke0=%.4f", dp, dl,
             gain, now[3] / start[3]);
    return 1;
}

/* ---- mass_ratio ------------------------------------------------------------------ */

/* mass_ratio: two cases on docs/scenes.md's ground, 5 s from rest, boxes placed
 * touching: (a) a 1 m box of density 100 on a 1 m box of density 1 (100:1);
 * (b) a 20 x 1 m plank (density 1, 20 kg) on two 1 m boxes under its ends.
 * Error: the largest penetration beyond the 5 mm slop between any two bodies
 * over the run (every step, sepax narrowphase on the reported poses, as
 * pyramid20; clamped at 1e-6 m for the log plot); details: the raw largest
 * depth of each case and where the top body ends (starts at y 1.5). */
static int mass_ratio_run(int e, const scene_config *c, int smoke, acc_result *r) {
    double worst = 0.0;
    for (int k = 0; k < 2; ++k) {
        scene_def d;
        if (!scene_init(&d, 4)) return 0;
        add_ground(&d, 100.0);
        if (k == 0) {
            set_box(scene_add(&d, 1, 0.0, 0.5, 0.0), 0.5, 0.5);
            scene_body *heavy = scene_add(&d, 1, 0.0, 1.5, 0.0);
            set_box(heavy, 0.5, 0.5);
            heavy->density = 100.0;
        } else {
            set_box(scene_add(&d, 1, -9.5, 0.5, 0.0), 0.5, 0.5);
            set_box(scene_add(&d, 1, 9.5, 0.5, 0.0), 0.5, 0.5);
            set_box(scene_add(&d, 1, 0.0, 1.5, 0.0), 10.0, 0.5);
        }
        const int top = d.count - 1;
        void *w = rec_create(e, &d, c);
        if (!w) {
            scene_free(&d);
            return 0;
        }
        const int n = smoke ? 3 : (int)lround(5.0 / c->dt);
        double depth = 0.0;
        for (int i = 1; i <= n; ++i) {
            rec_step(e, w, 1);
            double dd = scene_max_depth(w, e, &d);
            if (dd > depth) depth = dd;
        }
        scene_state s;
        engines[e]->get(w, top, &s);
        rec_destroy(e, w);
        scene_free(&d);
        if (depth - 0.005 > worst) worst = depth - 0.005;
        det_add(r, "%s:max_depth=%.4f top_y=%.4f ", k == 0 ? "100:1" : "plank", depth, s.y);
    }
    r->error = worst > 1e-6 ? worst : 1e-6;
    return 1;
}

/* ---- overlap_recovery ------------------------------------------------------------ */

/* overlap_recovery: docs/scenes.md's base-4 pyramid (10 boxes of half-extent 0.5,
 * 1 kg) created squeezed so that every box overlaps its neighbours and the
 * bottom row the ground by a fraction f of its size (rows and columns f m
 * closer), f = 0.25 and 0.5; 3 s with gravity. Error: the largest speed any
 * box reaches (m/s; the ideal push-out is slow); details per case: the time
 * the deepest overlap first falls below 1 cm (-1: never), the energy
 * gained beyond what separating needs (max over the run of KE + PE minus the
 * larger of the end state's KE + PE and the exact separated pyramid's PE, in
 * J, clamped at 0: the end state counts so that Box2D's skin, which rests
 * its rows higher, is not read as a gain) and the final top y (the exact pyramid's top rests
 * at 3.5). */
static int overlap_run(int e, const scene_config *c, int smoke, acc_result *r) {
    static const double fs[2] = {0.25, 0.5};
    double vmax = 0.0;
    for (int k = 0; k < 2; ++k) {
        const double f = fs[k], sp = 1.0 - f;
        const int base = 4;
        scene_def d;
        if (!scene_init(&d, 12)) return 0;
        add_ground(&d, 100.0);
        double e_rest = 0.0;
        for (int i = 0; i < base; ++i)
            for (int j = i; j < base; ++j) {
                set_box(scene_add(&d, 1, (i + 1) * 0.5 * sp + (j - i) * sp - base * 0.5 * sp,
                                  0.5 - f + i * sp, 0.0),
                        0.5, 0.5);
                e_rest += 10.0 * (0.5 + i);
            }
        const int count = d.count, top = count - 1;
        void *w = rec_create(e, &d, c);
        if (!w) {
            scene_free(&d);
            return 0;
        }
        const int n = smoke ? 3 : (int)lround(3.0 / c->dt);
        double v = 0.0, emax = -INFINITY, t_sep = -1.0, en = 0.0;
        for (int i = 1; i <= n; ++i) {
            rec_step(e, w, 1);
            en = 0.0;
            for (int b = 1; b < count; ++b) {
                scene_state s;
                engines[e]->get(w, b, &s);
                double sp2 = s.vx * s.vx + s.vy * s.vy;
                if (sqrt(sp2) > v) v = sqrt(sp2);
                en += 0.5 * sp2 + 0.5 * (1.0 / 6.0) * s.w * s.w + 10.0 * s.y;
            }
            if (en > emax) emax = en;
            if (t_sep < 0.0 && scene_max_depth(w, e, &d) < 0.01) t_sep = i * c->dt;
        }
        scene_state s;
        engines[e]->get(w, top, &s);
        rec_destroy(e, w);
        scene_free(&d);
        if (v > vmax) vmax = v;
        det_add(r, "f=%.2f:vmax=%.3f t_sep=%.3f excess_J=%.3f top_y=%.3f ", f, v, t_sep,
                fmax(0.0, emax - fmax(en, e_rest)), s.y);
    }
    r->error = vmax > 1e-7 ? vmax : 1e-7;
    return 1;
}

/* ---- consistency ----------------------------------------------------------------- */

/* A chaotic scene: 40 bodies (circles, boxes, pentagons and hexagons of size
 * 0.3..0.5 m in turn, random angles) on a jittered 8 x 5 grid dropped into a
 * container 12 m wide; they tumble and pile up. */
static void build_tumble(scene_def *d) {
    bench_rng rng = bench_rng_make(11);
    add_ground(d, 7.0);
    set_box(scene_add(d, 0, -6.5, 6.0, 0.0), 0.5, 6.0);
    set_box(scene_add(d, 0, 6.5, 6.0, 0.0), 0.5, 6.0);
    for (int i = 0; i < 40; ++i) {
        double x = -4.9 + 1.4 * (i % 8) + bench_rng_range(&rng, -0.1, 0.1);
        double y = 1.5 + 1.4 * (i / 8) + bench_rng_range(&rng, -0.1, 0.1);
        scene_body *b = scene_add(d, 1, x, y, bench_rng_range(&rng, -PI, PI));
        double s = bench_rng_range(&rng, 0.3, 0.5);
        switch (i % 4) {
        case 0: set_circle(b, s); break;
        case 1: set_box(b, s, s * 0.7); break;
        case 2: set_ngon(b, 5, s); break;
        default: set_ngon(b, 6, s); break;
        }
        b->vx = bench_rng_range(&rng, -2.0, 2.0);
    }
}

/* consistency: the tumble scene run for 2 s at dt and again at dt / 2 (all
 * other knobs equal). Error: the RMS distance between the two runs' body
 * positions at t = 1 s (Erez et al.'s consistency measure: a method whose
 * answer moves less when the step is halved is closer to converged); ms per
 * step is the dt run's. Details: the same at 0.25, 0.5, 1 and 2 s. At 0.5 s
 * most bodies are still in flight (the difference is the integrator's, like
 * projectile); by 2 s the pile is chaotic enough that every engine at every
 * setting differs by 0.1-0.5 m (the runs have decorrelated), so 1 s, after
 * the first impacts, is the figure. */
/* RMS distance between the dynamic bodies (from index first) of two worlds. */
static double rms_distance(int e, void *w, void *w2, int first, int count, double *worst) {
    double sum = 0.0;
    *worst = 0.0;
    for (int i = first; i < count; ++i) {
        scene_state a, b;
        engines[e]->get(w, i, &a);
        engines[e]->get(w2, i, &b);
        double dd = hypot(a.x - b.x, a.y - b.y);
        sum += dd * dd;
        if (dd > *worst) *worst = dd;
    }
    return sqrt(sum / (count - first));
}

static int consistency_run(int e, const scene_config *c, int smoke, acc_result *r) {
    scene_def d;
    if (!scene_init(&d, 44)) return 0;
    build_tumble(&d);
    const int count = d.count, first = 3;
    scene_config half = *c;
    half.dt = c->dt * 0.5;
    void *w = rec_create(e, &d, c);
    void *w2 = engines[e]->create(&d, &half);
    scene_free(&d);
    if (!w || !w2) {
        if (w) rec_destroy(e, w);
        if (w2) rec_destroy(e, w2);
        return 0;
    }
    static const double marks[4] = {0.25, 0.5, 1.0, 2.0};
    double at[4] = {0}, worst = 0.0;
    int done = 0;
    for (int k = 0; k < 4; ++k) {
        const int upto = smoke ? k + 1 : (int)lround(marks[k] / c->dt);
        rec_step(e, w, upto - done);
        engines[e]->step(w2, 2 * (upto - done));
        done = upto;
        at[k] = rms_distance(e, w, w2, first, count, &worst);
        det_add(r, "t=%.2f:%.3g ", done * c->dt, at[k]);
    }
    rec_destroy(e, w);
    rec_destroy(e, w2);
    r->error = at[2] > 1e-9 ? at[2] : 1e-9;
    det_add(r, "max=%.3g", worst);
    return 1;
}

/* ---- headline table (continued) --------------------------------------------- */

/* Errors within 2 % count as equal (measurement noise, and the floors some
 * metrics clamp to): a peer configuration whose error is at most 2 % above
 * sepax's is taken to reach it. */
#define SUMMARY_ERR_TOL 1.02
/* Costs within 10 % count as equal (timing noise on this shared machine): a
 * sepax configuration must be more than 10 % cheaper than a peer's matching
 * one to beat it. */
#define SUMMARY_MS_TOL 1.10

/* A point's cost in one round, or its median (round < 0). */
static double pms(const sweep_point *q, int round) { return round < 0 ? q->ms : q->ms_round[round]; }

/* Cheapest configuration of engine e reaching error <= err (x the
 * tolerance) in a round; NULL when none does. */
static const sweep_point *cheapest_at(const sweep_summary *s, int e, double err, int round) {
    const sweep_point *best = NULL;
    for (int i = 0; i < s->n; ++i) {
        const sweep_point *q = &s->p[i];
        if (q->engine != e || q->err > err * SUMMARY_ERR_TOL) continue;
        if (!best || pms(q, round) < pms(best, round)) best = q;
    }
    return best;
}

/* Engine e's most accurate configuration (the cheaper one on a tie). */
static const sweep_point *most_accurate(const sweep_summary *s, int e) {
    const sweep_point *best = NULL;
    for (int i = 0; i < s->n; ++i) {
        const sweep_point *q = &s->p[i];
        if (q->engine != e) continue;
        if (!best || q->err < best->err || (q->err == best->err && q->ms < best->ms)) best = q;
    }
    return best;
}

/* Most accurate configuration of engine e costing at most ms; NULL if none. */
static const sweep_point *best_within(const sweep_summary *s, int e, double ms) {
    const sweep_point *best = NULL;
    for (int i = 0; i < s->n; ++i) {
        const sweep_point *q = &s->p[i];
        if (q->engine != e || q->ms > ms) continue;
        if (!best || q->err < best->err || (q->err == best->err && q->ms < best->ms)) best = q;
    }
    return best;
}

static int is_peer(int k) { return k != SCENE_SEPAX && engine_in_sweeps(k) && engine_runs(k); }

/* Does sepax point q beat peer k in a round: no configuration of k reaches
 * q's error at a cost no more than 10 % above q's. */
static int beats(const sweep_summary *s, const sweep_point *q, int k, int round) {
    const sweep_point *pk = cheapest_at(s, k, q->err, round);
    return !pk || pms(pk, round) > pms(q, round) * SUMMARY_MS_TOL;
}

static int beats_all(const sweep_summary *s, const sweep_point *q, int round) {
    for (int k = 0; k < SCENE_ENGINE_COUNT; ++k)
        if (is_peer(k) && !beats(s, q, k, round)) return 0;
    return 1;
}

/* Does some sepax configuration beat every peer in a round. */
static int scene_won(const sweep_summary *s, int round) {
    for (int i = 0; i < s->n; ++i)
        if (s->p[i].engine == SCENE_SEPAX && beats_all(s, &s->p[i], round)) return 1;
    return 0;
}

/* snprintf that truncates quietly: the table cells nest strings whose
 * bounds the compiler cannot see (and warns about under the sanitizers). */
static void fmt_to(char *buf, size_t size, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, size, fmt, ap);
    va_end(ap);
}

/* Where sepax stands against peer k on one scene, in words, when none of its
 * configurations beats that peer: how much slower it is at the peer's best
 * error, or, when it never reaches that error, how much worse its error is
 * at the peer's cost. */
static void gap_words(const sweep_summary *s, int k, char *buf, size_t size) {
    const sweep_point *pb = most_accurate(s, k);
    if (!pb) {
        fmt_to(buf, size, "%s did not run", engine_names[k]);
        return;
    }
    const sweep_point *sx = cheapest_at(s, SCENE_SEPAX, pb->err, -1);
    if (sx) {
        fmt_to(buf, size, "%.2fx slower than %s at its best error %.3g (%s, %.3g ms)",
               sx->ms / pb->ms, engine_names[k], pb->err, pb->cfg, pb->ms);
        return;
    }
    const sweep_point *eq = best_within(s, SCENE_SEPAX, pb->ms);
    if (eq) {
        fmt_to(buf, size,
               "never reaches %s's best error %.3g (%s, %.3g ms); at that cost sepax's "
               "error is %.3g (%.3gx)",
               engine_names[k], pb->err, pb->cfg, pb->ms, eq->err, eq->err / pb->err);
        return;
    }
    const sweep_point *sb = most_accurate(s, SCENE_SEPAX);
    fmt_to(buf, size,
           "never reaches %s's best error %.3g (%s, %.3g ms); sepax's best is %.3g (%.3gx) "
           "at %.3g ms (%.2fx that cost)",
           engine_names[k], pb->err, pb->cfg, pb->ms, sb ? sb->err : 0.0,
           sb && pb->err > 0 ? sb->err / pb->err : 0.0, sb ? sb->ms : 0.0,
           sb ? sb->ms / pb->ms : 0.0);
}

/* Writes to stdout, REPORT.md and the headline file. */
static void out_both(FILE *hf, const char *fmt, ...) {
    char buf[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    out("%s", buf);
    fputs(buf, hf);
}

/* The headline table. A scene is won in one round of timings when a sepax
 * configuration beats every peer (no configuration of the peer reaches its
 * error at a cost no more than 10 % above); the verdict is the majority of
 * the rounds. The row shows, at the median costs, the most accurate winning
 * configuration and what each peer needs to match its error, and the
 * cheapest winner; otherwise, for each peer not beaten, the gap at that
 * peer's most accurate configuration. Also written alone to
 * out_dir/headline.md for the README. */
static int write_summary(const char *out_dir, int smoke) {
    if (summary_count == 0 && speed_note_count() == 0) return 0;
    char path[1200];
    fmt_to(path, sizeof path, "%s/headline.md", out_dir);
    FILE *hf = fopen(path, "w");
    if (!hf) {
        fprintf(stderr, "sepax_bench: cannot write %s: %s\n", path, strerror(errno));
        return 1;
    }
    if (smoke) {
        /* a few steps per scene: the figures show that the scenes run, nothing more */
        out_both(hf, "\n## Headline\n\nSmoke run (a few steps per scene): nothing is judged, "
                     "no verdicts. `make bench-scenes` runs the scenes in full and judges them.\n");
        fclose(hf);
        return 0;
    }
    out("\n## Headline: does sepax beat every peer?\n\n"
        "For each scene: a sepax configuration *beats* a peer when that peer has no "
        "configuration reaching the same error (within 2 %%) at a cost no more than 10 %% above "
        "(ms per 1/60 s frame; a peer that never reaches the error in its sweep is beaten). "
        "Every engine is swept to the same effective steps. Costs are replayed in %d rounds; a "
        "scene is won when sepax beats every peer in a majority of the rounds, and the noise "
        "column is the median spread of a configuration's rounds. The cells use the median "
        "costs: the most accurate winning configuration and what each peer needs to match its "
        "error, and the cheapest winner; otherwise, for each peer not beaten, the gap at that "
        "peer's most accurate configuration.\n\n",
        ROUNDS);
    out_both(hf, "| scene | metric | verdict | noise | sepax configuration | sepax ms, error |");
    for (int k = 0; k < SCENE_ENGINE_COUNT; ++k)
        if (is_peer(k)) out_both(hf, " %s |", engine_names[k]);
    out_both(hf, " cheapest winner |\n| --- | --- | --- | --- | --- | --- |");
    for (int k = 0; k < SCENE_ENGINE_COUNT; ++k)
        if (is_peer(k)) out_both(hf, " --- |");
    out_both(hf, " --- |\n");
    int losses = 0, reach_count = 0;
    static char lost[SUMMARY_MAX][1400];
    static char reach[SUMMARY_MAX * SCENE_ENGINE_COUNT][300];
    for (int si = 0; si < summary_count; ++si) {
        const sweep_summary *s = &summaries[si];
        int rounds_won = 0;
        for (int r = 0; r < s->rounds; ++r)
            rounds_won += scene_won(s, r);
        const int won = 2 * rounds_won > s->rounds;
        /* At the median costs: the most accurate sepax point that beats
         * every peer (the cheaper on a tie), the cheapest one, how many do,
         * and per peer the most accurate sepax point that beats it. */
        const sweep_point *win = NULL, *cheap = NULL;
        const sweep_point *beat_k[SCENE_ENGINE_COUNT] = {NULL};
        int nwin = 0, nsx = 0;
        for (int i = 0; i < s->n; ++i) {
            const sweep_point *q = &s->p[i];
            if (q->engine != SCENE_SEPAX) continue;
            ++nsx;
            for (int k = 0; k < SCENE_ENGINE_COUNT; ++k)
                if (is_peer(k) && beats(s, q, k, -1) && (!beat_k[k] || q->err < beat_k[k]->err))
                    beat_k[k] = q;
            if (!beats_all(s, q, -1)) continue;
            ++nwin;
            if (!win || q->err < win->err || (q->err == win->err && q->ms < win->ms)) win = q;
            if (!cheap || q->ms < cheap->ms || (q->ms == cheap->ms && q->err < cheap->err))
                cheap = q;
        }
        char cell[SCENE_ENGINE_COUNT][480];
        const sweep_point *sx_best = most_accurate(s, SCENE_SEPAX);
        for (int k = 0; k < SCENE_ENGINE_COUNT; ++k) {
            if (!is_peer(k)) continue;
            const sweep_point *pk = win ? cheapest_at(s, k, win->err, -1) : NULL;
            if (win && pk)
                fmt_to(cell[k], sizeof cell[k],
                       "matches the error at %.3g ms (%s): sepax %.2fx its cost", pk->ms, pk->cfg,
                       win->ms / pk->ms);
            else if (win)
                fmt_to(cell[k], sizeof cell[k], "never reaches %.3g (its best: %.3g at %.3g ms)",
                       win->err, most_accurate(s, k) ? most_accurate(s, k)->err : 0.0,
                       most_accurate(s, k) ? most_accurate(s, k)->ms : 0.0);
            else if (beat_k[k])
                fmt_to(cell[k], sizeof cell[k], "beaten by sepax at %s (%.3g ms, %.3g)",
                       beat_k[k]->cfg, beat_k[k]->ms, beat_k[k]->err);
            else
                gap_words(s, k, cell[k], sizeof cell[k]);
            /* A peer whose most accurate configuration reaches an error no
             * sepax configuration reaches: said whatever the verdict (a win
             * at the cheap end does not make up for it). */
            const sweep_point *pb = most_accurate(s, k);
            if (win && pb && sx_best && pb->err * SUMMARY_ERR_TOL < sx_best->err) {
                size_t len = strlen(cell[k]);
                fmt_to(cell[k] + len, sizeof cell[k] - len,
                       "; its best, %.3g (%s, %.3g ms), is beyond every sepax configuration "
                       "(best %.3g)",
                       pb->err, pb->cfg, pb->ms, sx_best->err);
                if (reach_count < SUMMARY_MAX * SCENE_ENGINE_COUNT)
                    fmt_to(reach[reach_count++], sizeof reach[0],
                           "%s: %s reaches %.3g (%s, %.3g ms); sepax's best is %.3g (%s, %.3g "
                           "ms)",
                           s->scene, engine_names[k], pb->err, pb->cfg, pb->ms, sx_best->err,
                           sx_best->cfg, sx_best->ms);
            }
        }
        const sweep_point *shown = win ? win : sx_best;
        /* A '|' inside a cell would end it: the metric names use it for
         * absolute values. */
        char metric[128];
        size_t mlen = 0;
        for (const char *c = s->metric; *c && mlen + 3 < sizeof metric; ++c) {
            if (*c == '|') metric[mlen++] = '\\';
            metric[mlen++] = *c;
        }
        metric[mlen] = '\0';
        char verdict[128];
        if (won)
            fmt_to(verdict, sizeof verdict,
                   "**sepax wins** (%d of %d rounds; %d of %d configurations at the median)",
                   rounds_won, s->rounds, nwin, nsx);
        else
            fmt_to(verdict, sizeof verdict, "sepax does not win (%d of %d rounds)", rounds_won,
                   s->rounds);
        char cheap_cell[256] = "-";
        if (cheap) {
            double need = INFINITY;
            for (int k = 0; k < SCENE_ENGINE_COUNT; ++k) {
                const sweep_point *pk = is_peer(k) ? cheapest_at(s, k, cheap->err, -1) : NULL;
                if (pk && pk->ms < need) need = pk->ms;
            }
            if (isfinite(need))
                fmt_to(cheap_cell, sizeof cheap_cell,
                       "%s (%.3g ms, %.3g): %.2fx the cheapest peer match", cheap->cfg, cheap->ms,
                       cheap->err, cheap->ms / need);
            else
                fmt_to(cheap_cell, sizeof cheap_cell, "%s (%.3g ms, %.3g): no peer matches",
                       cheap->cfg, cheap->ms, cheap->err);
        }
        out_both(hf, "| %s | %s | %s | +-%.0f %% | %s | %.3g ms, %.3g |", s->scene, metric, verdict,
                 50.0 * s->noise, shown ? shown->cfg : "-", shown ? shown->ms : 0.0,
                 shown ? shown->err : 0.0);
        for (int k = 0; k < SCENE_ENGINE_COUNT; ++k)
            if (is_peer(k)) out_both(hf, " %s |", cell[k]);
        out_both(hf, " %s |\n", cheap_cell);
        if (!won) {
            size_t len = 0;
            fmt_to(lost[losses], sizeof lost[losses], "%s (", s->scene);
            for (int k = 0; k < SCENE_ENGINE_COUNT; ++k) {
                if (!is_peer(k)) continue;
                len = strlen(lost[losses]);
                if (beat_k[k])
                    fmt_to(lost[losses] + len, sizeof lost[losses] - len, "beats %s; ",
                           engine_names[k]);
                else
                    fmt_to(lost[losses] + len, sizeof lost[losses] - len, "%s; ", cell[k]);
            }
            len = strlen(lost[losses]);
            if (len >= 2) lost[losses][len - 2] = ')', lost[losses][len - 1] = '\0';
            ++losses;
        }
    }
    if (losses == 0)
        out_both(hf, reach_count ? "\nsepax beats every peer on every accuracy scene of this run, "
                                   "on some only at the cheap end (below).\n"
                                 : "\nsepax beats every peer on every accuracy scene of this "
                                   "run.\n");
    else {
        out_both(hf, "\n**Where sepax does not win** (%d of %d scenes):\n", losses, summary_count);
        for (int i = 0; i < losses; ++i)
            out_both(hf, "- %s\n", lost[i]);
    }
    if (reach_count > 0) {
        out_both(hf, "\n**Scenes sepax wins only at the cheap end** (a peer reaches an error no "
                     "sepax configuration reaches):\n");
        for (int i = 0; i < reach_count; ++i)
            out_both(hf, "- %s\n", reach[i]);
    }
    if (speed_note_count() > 0) {
        out_both(hf, "\n**Throughput scenes where sepax is slower** (same run, ms per step):\n");
        for (int i = 0; i < speed_note_count(); ++i)
            out_both(hf, "- %s\n", speed_note_text(i));
    }
    fclose(hf);
    return 0;
}

/* ---- driver ------------------------------------------------------------------ */

int bench_scenes_run(const char *out_dir, int smoke, int level) {
    if (!report_open(out_dir)) return 1;
    speed_notes_smoke(smoke);
    md("# sepax world benchmarks\n\nGenerated by `sepax_bench --scenes%s%s` (sx_real = %s). "
       "Scene definitions: docs/scenes.md; method: bench/README.md. Data: "
       "scenes.csv.\n\nEngines:\n",
       smoke ? " --smoke" : "",
       level == 1   ? " --quick"
       : level == 2 ? " --full"
                    : "",
       sizeof(sx_real) == sizeof(double) ? "double" : "float");
    for (int e = 0; e < SCENE_ENGINE_COUNT; ++e)
        md("- `%s`: %s%s\n", engine_names[e], engine_builds[e],
           engine_runs(e) ? "" : " (not run: this CPU lacks it)");
    printf("\nsepax world scenes%s: sepax, Box2D v3, Box2D 2.4, Chipmunk 7 in the same run, "
           "single thread\n",
           smoke ? " (smoke)" : "");

    /* SX_BENCH_SCENE=name runs that scene only (a prefix is enough). */
    const char *only = getenv("SX_BENCH_SCENE");
#define WANT(name) (!only || strncmp(only, name, strlen(only)) == 0)
    int failures = 0;
    if (WANT("large_pyramid"))
        failures += large_pyramid(smoke ? 3 : level == 1 ? 100 : level == 2 ? 500 : 200, out_dir);
    if (WANT("mostly_asleep"))
        failures += mostly_asleep(smoke ? 2000 : 20000, smoke ? 3 : 60, out_dir);
    if (WANT("rain")) {
        static const int smoke_sizes[1] = {200};
        static const int sizes[4] = {1000, 4000, 16000, 64000};
        if (smoke)
            failures += rain(smoke_sizes, 1, 3, 1e3, out_dir);
        else if (level == 1)
            failures += rain(sizes, 2, 60, 5e3, out_dir);
        else if (level == 2)
            failures += rain(sizes, 4, 100, 120e3, out_dir);
        else
            failures += rain(sizes, 3, 100, 8e3, out_dir);
    }
    /* Box2D v3's benchmark scenes; steps by level (default, --quick, --full),
     * sized in bench/README.md */
    static const int pyramids_steps[3] = {40, 20, 200}, tumbler_steps[3] = {200, 60, 750},
                     smash_steps[3] = {100, 40, 300};
    if (WANT("many_pyramids"))
        failures += smoke ? many_pyramids(2, 2, 3, out_dir)
                          : many_pyramids(20, 20, pyramids_steps[level], out_dir);
    if (WANT("tumbler"))
        failures += smoke ? tumbler(100, 3, out_dir) : tumbler(2000, tumbler_steps[level], out_dir);
    if (WANT("bullets"))
        failures += smoke ? bullets(20, 3, out_dir) : bullets(400, level == 1 ? 60 : 120, out_dir);
    if (WANT("smash"))
        failures += smoke ? smash(20, 10, 3, out_dir) : smash(120, 80, smash_steps[level], out_dir);
    /* The accuracy sweeps, in report order. */
    static const struct {
        const char *scene, *err_name, *what;
        acc_scene_fn fn;
    } sweeps[] = {
        {"bounce", "mean |apex/drop - e^2|",
         "circle r 0.5 dropped 2 m, e = 0.2, 0.5, 0.8; first apex / drop "
         "against e^2 (details: measured(exact))",
         bounce_run},
        {"incline", "mean |a - exact| m/s^2",
         "box on a 0.25 rad ramp, mu = 0.5 (sticks), 0.1, 0; acceleration "
         "between t = 0.5 and 2 s (details: measured(exact))",
         incline_run},
        {"pyramid20", "top drift m",
         "base-20 pyramid, 10 s; top box displacement between t = 1 s and "
         "10 s; max penetration beyond 5 mm slop (sepax narrowphase on the "
         "poses; Box2D's 1 cm skin reads as 0)",
         pyramid20_run},
        {"stack20", "lateral creep m",
         "20 boxes in a column, alternate rows shifted +-0.01 m, 10 s; "
         "largest lateral creep of a box",
         stack20_run},
        {"cradle", "|v_last - 2| + sum |v_others| m/s",
         "five circles r 0.5, 1 mm gaps, e = 1, mu = 0, no gravity, the first "
         "at 2 m/s; velocities after 1 s",
         cradle_run},
        {"projectile", "|p - parabola| m",
         "circle launched at (3, 8) m/s, no contacts, 2 s; distance to the "
         "parabola (details: measured(exact), distance to symplectic "
         "Euler's closed form at the engine's own step)",
         projectile_run},
        {"pileup", "momentum drift + energy gain",
         "40 circles and boxes thrown together in zero gravity, e = 0, "
         "4 s; |dP| / sum m|v0| + |dL| / sum m|r0||v0| + max(0, max KE / "
         "KE0 - 1)",
         pileup_run},
        {"mass_ratio", "max penetration beyond slop m",
         "density-100 box on a density-1 box on the ground, and a 20 m plank "
         "on two 1 m boxes, 5 s; largest overlap beyond 5 mm (every step, "
         "clamped at 1e-6)",
         mass_ratio_run},
        {"overlap_recovery", "max speed m/s",
         "base-4 pyramid created 25 % and 50 % overlapping (boxes and "
         "ground), 3 s; largest speed reached (details: time to separate, "
         "energy gained beyond separating in J, top y)",
         overlap_run},
        {"consistency", "rms |x(dt) - x(dt/2)| m",
         "40 mixed bodies tumbling into a container, run at dt and at dt/2; "
         "RMS distance between the two runs' positions at t = 1 s (details: "
         "at 0.25, 0.5, 1, 2 s)",
         consistency_run},
    };
    for (size_t k = 0; k < sizeof sweeps / sizeof sweeps[0]; ++k) {
        if (WANT(sweeps[k].scene))
            failures += run_sweep(sweeps[k].scene, sweeps[k].err_name, sweeps[k].what, sweeps[k].fn,
                                  out_dir, smoke);
    }
#undef WANT
    failures += write_summary(out_dir, smoke);
    report_close();
    printf("\nscene rows in %s/scenes.csv, plots and REPORT.md in %s\n", out_dir, out_dir);
    return failures;
}
