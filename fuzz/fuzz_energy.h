/* sepax fuzzing and tests — the energy audit: steps a world through the
 * public stages, exactly as sx_world_step does, and checks after every
 * sub-step that the total energy of the audited bodies never rises above its
 * start plus what gravity and the applied forces put in, within rounding.
 *
 * The energy. With a constant acceleration acc per body (gravity x gravity
 * scale + force / mass), the potential energy is -m acc . x, and what
 * gravity and the forces put in is its decrease: the total energy
 * KE - m acc . x is the start plus that work. The step's integrator,
 * symplectic Euler (v += h acc in sx_world_apply_forces, then x += h v in
 * sx_world_integrate), does not keep that sum exactly: it keeps
 *     E = KE - m acc . x + h m acc . v / 2
 * (expand one sub-step: the h^2 terms cancel), so a free body's E stays put
 * to rounding while KE - m acc . x wobbles by h m |acc . v| / 2. E is what is
 * checked.
 *
 * The allowances, each derived from what the stage does:
 *  - impacts: an impact at time t of the sub-step changes a body's velocity
 *    by dv; sx_world_integrate moves it with the new velocity and then by
 *    the time-of-impact shift -dv t, which changes E by
 *    m acc . dv (t - h / 2) besides the impact's own change of kinetic
 *    energy (<= 0, the promise under test). That is at most
 *    h |acc| |m dv| / 2, and |m dv| is at most the impulses of the impact
 *    pass on the body: per point x_n sqrt(1 + mu^2) (its friction is at most
 *    mu x_n). Summed over the points of the last solve's impacts, both
 *    bodies of each.
 *  - the rounding of a two-point impact: the impact pass solves both points
 *    of a two-point contact together, a 2x2 system of condition number up
 *    to 1000 (the block solver's limit, SX_BLOCK_MAX_CONDITION in
 *    contact_solver.c), so its impulses x are exact only within about
 *    1000 epsilon relative; impulses off by dx change the energy by about
 *    dx . K x, at most 2 x 1000 epsilon times the energy of the impulses
 *    alone (1/2 x . K x; bounded here per body by (sum x)^2 / m +
 *    (sum |r| x)^2 / I, widened by 1 + mu for friction).
 *  - separation: sx_world_separate moves positions only; its change of E
 *    (the work of lifting a body out of an overlap, or of letting it sink
 *    into its place) is measured and added, and it must leave every
 *    velocity exactly as it was.
 *  - rounding: the state is sx_real, the sums here are double. Each
 *    sub-step rounds every velocity and position a bounded number of times
 *    (the kick, the impulses of each contact, the drift), each time by at
 *    most epsilon / 2 relative, which moves E by at most epsilon times the
 *    energy scale S = sum of m |v|^2 + I w^2 + m |acc| (|x| + h |v|) per
 *    rounding; FZ_ENERGY_ROUNDINGS of them per sub-step are allowed (in
 *    random pinched piles at mass ratios up to 10^6 the excess without this
 *    allowance stayed below 0.21 epsilon S per sub-step).
 * Kinematic bodies do work the audit does not see (leave them out), and
 * damping, sleep and the speed limit only take energy out but shift the
 * h m acc . v / 2 term (leave them off). */
#ifndef SEPAX_FUZZ_ENERGY_H
#define SEPAX_FUZZ_ENERGY_H

#include <float.h>
#include <math.h>

#include "sepax/sepax.h"

#define FZ_ENERGY_MAX_BODIES 16
/* Roundings of the energy scale allowed per sub-step (see above). */
#ifndef FZ_ENERGY_ROUNDINGS
#define FZ_ENERGY_ROUNDINGS 16.0
#endif

typedef struct fz_energy {
    sx_world *world;
    sx_vec2 gravity;
    int sub_steps;
    double dt, h;
    /* the largest collider friction among the audited bodies and the static
     * ones they touch */
    double max_friction;
    int count;
    sx_body_id bodies[FZ_ENERGY_MAX_BODIES];
    sx_vec2 force[FZ_ENERGY_MAX_BODIES];
    double gravity_scale[FZ_ENERGY_MAX_BODIES];
    double start;     /* E at the start (J) */
    double allowance; /* impacts + separation + rounding so far (J) */
    double energy;    /* E after the last sub-step (J) */
    double worst;     /* largest E - (start + allowance) seen (J) */
    double scale;     /* the energy scale S of the last sub-step (J) */
    int sub_steps_run;
    bool velocities_kept; /* every separation left the velocities alone */
} fz_energy;

static inline double fz_energy_epsilon(void) {
    return sizeof(sx_real) == sizeof(float) ? (double)FLT_EPSILON : (double)DBL_EPSILON;
}

/* Body i's acceleration from gravity and its constant force. */
static inline void fz_energy_accel(const fz_energy *e, int i, double m, double *ax, double *ay) {
    *ax = e->gravity_scale[i] * (double)e->gravity.x + (m > 0.0 ? (double)e->force[i].x / m : 0.0);
    *ay = e->gravity_scale[i] * (double)e->gravity.y + (m > 0.0 ? (double)e->force[i].y / m : 0.0);
}

/* E of the audited bodies (J); *scale = S. */
static inline double fz_energy_measure(const fz_energy *e, double *scale) {
    double total = 0.0, s = 0.0;
    int i;
    for (i = 0; i < e->count; ++i) {
        sx_vec2 v = sx_body_get_linear_velocity(e->world, e->bodies[i]);
        sx_vec2 x = sx_body_get_world_center(e->world, e->bodies[i]);
        double m = (double)sx_body_get_mass(e->world, e->bodies[i]);
        double inertia = (double)sx_body_get_inertia(e->world, e->bodies[i]);
        double w = (double)sx_body_get_angular_velocity(e->world, e->bodies[i]);
        double vx = (double)v.x, vy = (double)v.y, ax, ay, kinetic;
        fz_energy_accel(e, i, m, &ax, &ay);
        kinetic = 0.5 * (m * (vx * vx + vy * vy) + inertia * w * w);
        total += kinetic - m * (ax * (double)x.x + ay * (double)x.y) +
                 0.5 * e->h * m * (ax * vx + ay * vy);
        s += 2.0 * kinetic +
             m * sqrt(ax * ax + ay * ay) *
                 (fabs((double)x.x) + fabs((double)x.y) + e->h * (fabs(vx) + fabs(vy)));
    }
    if (scale != NULL) *scale = s;
    return total;
}

/* Starts an audit of `count` dynamic bodies (at most FZ_ENERGY_MAX_BODIES)
 * of a world whose def had `sub_steps` and `gravity`, stepped with `dt`;
 * forces[i] (NULL: none) is applied to body i before every step and
 * gravity_scales[i] (NULL: all 1) is the body's gravity scale. */
static inline void fz_energy_begin(fz_energy *e, sx_world *world, sx_vec2 gravity, int sub_steps,
                                   double dt, const sx_body_id *bodies, const sx_vec2 *forces,
                                   const double *gravity_scales, int count, double max_friction) {
    int i;
    e->world = world;
    e->gravity = gravity;
    e->sub_steps = sub_steps;
    e->dt = dt;
    e->h = (double)((sx_real)dt / (sx_real)sub_steps);
    if (!(e->h > 0.0)) {
        /* as sx_world_step: a denormal dt is one sub-step of dt */
        e->h = (double)(sx_real)dt;
        e->sub_steps = 1;
    }
    e->max_friction = max_friction;
    e->count = count < FZ_ENERGY_MAX_BODIES ? count : FZ_ENERGY_MAX_BODIES;
    for (i = 0; i < e->count; ++i) {
        e->bodies[i] = bodies[i];
        e->force[i] = forces != NULL ? forces[i] : sx_v2_zero();
        e->gravity_scale[i] = gravity_scales != NULL ? gravity_scales[i] : 1.0;
    }
    e->start = fz_energy_measure(e, &e->scale);
    e->energy = e->start;
    e->allowance = 0.0;
    e->worst = -HUGE_VAL;
    e->sub_steps_run = 0;
    e->velocities_kept = true;
}

/* The index of body `id` among the audited ones, -1 if not audited. */
static inline int fz_energy_index(const fz_energy *e, sx_body_id id) {
    int i;
    for (i = 0; i < e->count; ++i) {
        if (e->bodies[i].index == id.index && e->bodies[i].generation == id.generation) return i;
    }
    return -1;
}

/* |acc| of the audited body `id`, 0 for any other (static) body. */
static inline double fz_energy_accel_of(const fz_energy *e, sx_body_id id) {
    int i = fz_energy_index(e, id);
    double ax, ay;
    if (i < 0) return 0.0;
    fz_energy_accel(e, i, (double)sx_body_get_mass(e->world, id), &ax, &ay);
    return sqrt(ax * ax + ay * ay);
}

/* The block solver's largest condition number (SX_BLOCK_MAX_CONDITION in
 * src/contact_solver.c). */
#define FZ_ENERGY_BLOCK_CONDITION 1000.0

/* A bound on the energy of contact c's impact impulses alone on the audited
 * body `id` (0 for any other: static), friction widened in by 1 + mu. */
static inline double fz_energy_alone(const fz_energy *e, sx_body_id id, const sx_contact_data *c) {
    double p = 0.0, l = 0.0, m, inertia, widen = 1.0 + e->max_friction;
    sx_vec2 centre;
    int k;
    if (fz_energy_index(e, id) < 0) return 0.0;
    m = (double)sx_body_get_mass(e->world, id);
    inertia = (double)sx_body_get_inertia(e->world, id);
    centre = sx_body_get_world_center(e->world, id);
    for (k = 0; k < c->count; ++k) {
        double x = fabs((double)c->impact_impulses[k]);
        p += x;
        l += x * (double)sx_length(sx_sub(c->points[k], centre));
    }
    if (!(m > 0.0)) return 0.0;
    return 0.5 * widen * widen * (p * p / m + (inertia > 0.0 ? l * l / inertia : 0.0));
}

/* The impacts' allowances of the last solve (see the top of the file). */
static inline double fz_energy_impact_allowance(const fz_energy *e) {
    double sum = 0.0, block = 0.0, widen = sqrt(1.0 + e->max_friction * e->max_friction);
    int n = sx_world_contact_count(e->world), i, k;
    for (i = 0; i < n; ++i) {
        sx_contact_data c;
        double impulse = 0.0;
        if (sx_world_get_contact(e->world, i, &c) != SX_OK) continue;
        for (k = 0; k < c.count; ++k)
            impulse += fabs((double)c.impact_impulses[k]);
        if (impulse > 0.0) {
            sum += impulse * (fz_energy_accel_of(e, c.body_a) + fz_energy_accel_of(e, c.body_b));
        }
        if (c.count == 2 && c.impact_impulses[0] > SX_R(0.0) && c.impact_impulses[1] > SX_R(0.0))
            block += fz_energy_alone(e, c.body_a, &c) + fz_energy_alone(e, c.body_b, &c);
    }
    return 0.5 * e->h * widen * sum + 2.0 * FZ_ENERGY_BLOCK_CONDITION * fz_energy_epsilon() * block;
}

/* True when body i's velocities equal those saved in v and w. */
static inline bool fz_energy_same_velocity(const fz_energy *e, int i, sx_vec2 v, sx_real w) {
    sx_vec2 now = sx_body_get_linear_velocity(e->world, e->bodies[i]);
    return now.x == v.x && now.y == v.y &&
           sx_body_get_angular_velocity(e->world, e->bodies[i]) == w;
}

/* One step of dt through the stages of sx_world_step (begin_step and
 * collide once, then per sub-step forces, solve, integrate, separate),
 * audited; returns the first status that is not SX_OK (the audit then stops
 * counting). */
static inline sx_status fz_energy_step(fz_energy *e) {
    sx_real h = (sx_real)e->h;
    sx_vec2 v[FZ_ENERGY_MAX_BODIES];
    sx_real w[FZ_ENERGY_MAX_BODIES];
    sx_status st;
    int s, i;
    for (i = 0; i < e->count; ++i) {
        if (e->force[i].x != SX_R(0.0) || e->force[i].y != SX_R(0.0)) {
            st = sx_body_apply_force(e->world, e->bodies[i], e->force[i]);
            if (st != SX_OK) return st;
        }
    }
    if ((st = sx_world_begin_step(e->world, (sx_real)e->dt)) != SX_OK) return st;
    if ((st = sx_world_collide(e->world)) != SX_OK) return st;
    for (s = 0; s < e->sub_steps; ++s) {
        double before, after, scale;
        if ((st = sx_world_apply_forces(e->world, h)) != SX_OK) return st;
        if ((st = sx_world_solve(e->world, h)) != SX_OK) return st;
        e->allowance += fz_energy_impact_allowance(e);
        if ((st = sx_world_integrate(e->world, h)) != SX_OK) return st;
        before = fz_energy_measure(e, NULL);
        for (i = 0; i < e->count; ++i) {
            v[i] = sx_body_get_linear_velocity(e->world, e->bodies[i]);
            w[i] = sx_body_get_angular_velocity(e->world, e->bodies[i]);
        }
        if ((st = sx_world_separate(e->world, h)) != SX_OK) return st;
        for (i = 0; i < e->count; ++i)
            e->velocities_kept = e->velocities_kept && fz_energy_same_velocity(e, i, v[i], w[i]);
        after = fz_energy_measure(e, &scale);
        e->allowance += after - before;
        e->allowance += FZ_ENERGY_ROUNDINGS * fz_energy_epsilon() * scale;
        e->energy = after;
        e->scale = scale;
        if (after - (e->start + e->allowance) > e->worst)
            e->worst = after - (e->start + e->allowance);
        ++e->sub_steps_run;
    }
    {
        /* continuous collision moves bodies back along their paths and
         * pays for any height regained from their velocities, in E (the
         * h m acc . v / 2 term included): no allowance beyond rounding */
        double scale;
        if ((st = sx_world_continuous(e->world)) != SX_OK) return st;
        e->energy = fz_energy_measure(e, &scale);
        e->allowance += FZ_ENERGY_ROUNDINGS * fz_energy_epsilon() * scale;
        if (e->energy - (e->start + e->allowance) > e->worst)
            e->worst = e->energy - (e->start + e->allowance);
    }
    if ((st = sx_world_clear_forces(e->world)) != SX_OK) return st;
    return sx_world_update_sleep(e->world, (sx_real)e->dt);
}

/* Whether the audit held so far: E never above the start plus the
 * allowances, and separation never touched a velocity. */
static inline bool fz_energy_held(const fz_energy *e) {
    return e->velocities_kept && e->worst <= 0.0;
}

#endif
