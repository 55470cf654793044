/* sepax — continuous collision: fast bodies swept to their time of impact
 * at the end of the step.
 *
 * The step's contacts are found once, at collide, with margins and bounds
 * grown by how far each body can move at its speed then: a body that keeps
 * to that straight motion meets every wall through a speculative contact.
 * What that misses is motion collide did not foresee: a body knocked on
 * faster than it was going, or one turning so far that a contact's
 * linearised separation no longer holds (a spinning blade). So collide
 * records each awake dynamic body's pose and foreseen end (sx_ccd_record,
 * filled in by the bounds pass of world.c, which reads the body anyway),
 * sx_world_continuous lists the bodies that strayed, turned or are bullets
 * (sx_ccd_list: a few lane operations per body skip the others) and whose
 * farthest point moved at least their gate, an eighth of their thinnest
 * width (sx_under_gate: one that moves less cannot tunnel), and of
 * those only one that went farther than its recorded velocity allows,
 * strayed from the path it foresaw or turned, by more than half its
 * thinnest extent at its farthest point, or a fast bullet, is
 * swept from the recorded pose to the final one against the colliders its
 * swept box meets in the broadphase (conservative advancement, distance.c)
 * and put back at the earliest time of impact, keeping its velocity. Box2D
 * v3 sweeps every fast body against static geometry, after the solver, in
 * the same way; sweeping only what the speculative contacts cannot cover
 * keeps slow and ordinary fast bodies free. */
#include <stdlib.h>

#include "distance.h"
#include "simd.h"
#include "world_array.h"
#include "world_body.h"
#include "world_broadphase.h"
#include "world_ccd.h"
#include "world_internal.h"

/* A bullet the continuous stage moves (sx_bullets_meet): its motion over
 * the step, the box of its path (grown by its reach and half the margin),
 * its first time of impact with another bullet, and whether it is swept. */
typedef struct sx_ccd_bullet {
    int slot;
    bool swept;
    sx_real lower, upper, max_ext, toi;
    sx_aabb box;
    sx_motion m;
} sx_ccd_bullet;

sx_status sx_ccd_record(sx_world *world) {
    uint32_t stamp = world->ccd_stamp + 1u;
    world->ccd_dt = SX_R(0.0);
    if (!world->def.enable_continuous || !(world->step_dt > SX_R(0.0))) return SX_OK;
    if (!sx_grow_zeroed((void **)&world->ccd_recs, &world->ccd_rec_capacity, world->body_slots,
                        sizeof(sx_ccd_rec)) ||
        !sx_grow_zeroed((void **)&world->ccd_poses, &world->ccd_pose_capacity, world->body_slots,
                        sizeof(sx_ccd_pose))) {
        return SX_ERR_NO_MEMORY;
    }
    /* 0 is never a live stamp: fresh (zeroed) slots never match */
    if (stamp == 0u) stamp = 1u;
    world->ccd_stamp = stamp;
    world->ccd_kinematic_moving = 0;
    world->ccd_sweep_count = 0;
    world->ccd_dt = world->step_dt;
    world->ccd_h = SX_R(0.0);
    return SX_OK;
}

void sx_ccd_forget(sx_world *world, int slot) {
    /* also no sweep this step: a new body in a reused slot has no record */
    if (slot < world->ccd_rec_capacity) world->ccd_recs[slot].stamp = 0u;
    if (slot < world->ccd_pose_capacity) world->ccd_poses[slot].ext_valid = false;
}

void sx_ccd_free(sx_world *world) {
    sx_free(world->ccd_recs, (size_t)world->ccd_rec_capacity * sizeof(sx_ccd_rec));
    sx_free(world->ccd_poses, (size_t)world->ccd_pose_capacity * sizeof(sx_ccd_pose));
    sx_free(world->ccd_found, (size_t)world->ccd_found_capacity * sizeof(int));
    sx_free(world->ccd_sweep, (size_t)world->ccd_sweep_capacity * sizeof(int));
    sx_free(world->ccd_bullets, (size_t)world->ccd_bullet_capacity * sizeof(sx_ccd_bullet));
}

/* The proxy of part k of a collider, in its body's frame. */
static bool sx_part_proxy(const sx_collider *c, int k, sx_proxy *out) {
    if (c->part_count == 0) return sx_proxy_make(&c->shape, NULL, out) == SX_OK;
    return sx_proxy_make(&c->parts[k].shape, &c->parts[k].offset, out) == SX_OK;
}

static int sx_part_count(const sx_collider *c) { return c->part_count > 0 ? c->part_count : 1; }

/* The farthest reach of a body's colliders from its centre of mass, and its
 * thinnest half extent (a disc's radius, a polygon's least distance from
 * its vertices' mean to an edge, plus rounding; never below the slop). */
static void sx_measure_extents(const sx_world *world, int slot, sx_real *max_ext,
                               sx_real *min_ext) {
    sx_vec2 lc = world->sims[slot].local_center;
    int ci, k, i;
    *max_ext = SX_R(0.0);
    *min_ext = SX_REAL_MAX;
    for (ci = world->infos[slot].first_collider; ci >= 0; ci = world->colliders[ci].next) {
        const sx_collider *c = &world->colliders[ci];
        if (c->sensor) continue;
        for (k = 0; k < sx_part_count(c); ++k) {
            sx_proxy p;
            sx_real thin = SX_R(0.0);
            if (!sx_part_proxy(c, k, &p)) continue;
            for (i = 0; i < p.count; ++i)
                *max_ext = sx_maxr(*max_ext, sx_length(sx_sub(p.p[i], lc)) + p.radius);
            if (p.count >= 3) {
                sx_vec2 mean = sx_v2_zero();
                for (i = 0; i < p.count; ++i)
                    mean = sx_add(mean, p.p[i]);
                mean = sx_scale(mean, SX_R(1.0) / (sx_real)p.count);
                thin = SX_REAL_MAX;
                for (i = 0; i < p.count; ++i) {
                    sx_vec2 e = sx_normalize(sx_sub(p.p[(i + 1) % p.count], p.p[i]));
                    thin = sx_minr(thin, sx_absr(sx_cross(e, sx_sub(mean, p.p[i]))));
                }
            }
            *min_ext = sx_minr(*min_ext, thin + p.radius);
        }
    }
    *min_ext = sx_maxr(*min_ext, world->linear_slop);
}

/* sx_measure_extents, cached in the pose record until sx_ccd_forget (the
 * body's colliders or mass changed), with the size gate (sx_under_gate). */
static void sx_body_extents(sx_world *world, int slot, sx_real *max_ext, sx_real *min_ext) {
    sx_ccd_pose *p = &world->ccd_poses[slot];
    if (!p->ext_valid) {
        sx_measure_extents(world, slot, &p->max_ext, &p->min_ext);
        /* a quarter of the sound bound (min_ext, half the width): a gated
         * body ends at most that deep in a wall, an overlap its contact
         * then solves like any other */
        p->gate = SX_R(0.25) * p->min_ext;
        p->ext_valid = true;
    }
    *max_ext = p->max_ext;
    *min_ext = p->min_ext;
}

/* The turn of body b since its recorded rotation q0: the representative of
 * the change of angle nearest to w dt (a turn of several half turns in a
 * step is told from its remainder by the velocity). */
static sx_real sx_turn(const sx_body_sim *b, sx_rot q0, sx_real dt) {
    sx_real guess = b->w * dt;
    sx_real diff = sx_rot_angle(sx_rot_inv_mul(q0, b->xf.q)) - guess;
    sx_real k = sx_floor((diff + SX_PI) / (SX_R(2.0) * SX_PI));
    return guess + diff - k * (SX_R(2.0) * SX_PI);
}

/* The motion of body slot over the step. */
static sx_motion sx_body_motion(const sx_world *world, int slot) {
    const sx_body_sim *b = &world->sims[slot];
    const sx_ccd_rec *r = &world->ccd_recs[slot];
    sx_motion m;
    m.local_center = b->local_center;
    m.c0 = r->center;
    m.c1 = b->center;
    m.angle1 = sx_rot_angle(b->xf.q);
    m.angle0 = m.angle1 - sx_turn(b, r->q, world->ccd_dt);
    return m;
}

/* Body slot standing still where it is now. */
static sx_motion sx_body_still(const sx_world *world, int slot) {
    const sx_body_sim *b = &world->sims[slot];
    sx_motion m;
    m.local_center = b->local_center;
    m.c0 = m.c1 = b->center;
    m.angle0 = m.angle1 = sx_rot_angle(b->xf.q);
    return m;
}

/* The earliest time of impact of body slot's colliders, moving by m, with
 * collider cj (all parts of both), moving by *other or (NULL) standing at
 * its final pose, below *t_min. */
static void sx_sweep_pair(const sx_world *world, int slot, const sx_motion *m, int cj,
                          const sx_motion *other, sx_real *t_min) {
    const sx_collider *oc = &world->colliders[cj];
    /* the others at their final poses: the body is put back along its own
     * path while they stay where the step left them (as Box2D v3 does) */
    sx_motion mo = other != NULL ? *other : sx_body_still(world, oc->body);
    int ci, ka, kb;
    for (ci = world->infos[slot].first_collider; ci >= 0; ci = world->colliders[ci].next) {
        const sx_collider *c = &world->colliders[ci];
        if (c->sensor || !sx_filters_collide(&c->filter, &oc->filter)) continue;
        for (ka = 0; ka < sx_part_count(c); ++ka) {
            sx_proxy pa;
            if (!sx_part_proxy(c, ka, &pa)) continue;
            for (kb = 0; kb < sx_part_count(oc); ++kb) {
                sx_proxy pb;
                sx_toi_output o;
                if (!sx_part_proxy(oc, kb, &pb)) continue;
                sx_proxy_toi(&pa, m, &pb, &mo, world->linear_slop, &o);
                if (o.state == SX_TOI_STARTS_CLOSE && sx_length_sq(o.normal) > SX_R(0.0)) {
                    /* already touching: its contact holds it, unless the
                     * motion (a fast turn the contact's linearisation
                     * misses) takes it deeper than it started; cores that
                     * touch are left to the contact */
                    sx_real g0 = sx_dot(sx_sub(o.point_b, o.point_a), o.normal);
                    sx_proxy_toi(&pa, m, &pb, &mo, g0 - SX_R(0.25) * world->linear_slop, &o);
                }
                if ((o.state == SX_TOI_HIT || o.state == SX_TOI_ITERATION_LIMIT) &&
                    o.fraction > SX_R(0.0) && o.fraction < *t_min) {
                    *t_min = o.fraction;
                }
            }
        }
    }
}

/* Whether body slot is a bullet the continuous stage moves along its own
 * path (sx_bullets_meet): awake and dynamic since collide. */
static bool sx_moving_bullet(const sx_world *world, int slot) {
    return world->infos[slot].bullet && world->sims[slot].dynamic &&
           slot < world->ccd_rec_capacity && world->ccd_recs[slot].stamp == world->ccd_stamp;
}

/* Sweeps body slot along m; puts it at its first time of impact (t, or
 * earlier). */
static sx_status sx_sweep_body(sx_world *world, int slot, const sx_motion *m, sx_real max_ext,
                               bool bullet, sx_real t) {
    sx_body_sim *b = &world->sims[slot];
    sx_aabb box = sx_aabb_fatten(sx_aabb_make(sx_vmin(m->c0, m->c1), sx_vmax(m->c0, m->c1)),
                                 max_ext + world->margin);
    int i;
    sx_status s;
    world->ccd_found_count = 0;
    /* a body that is not a bullet meets only static and kinematic
     * colliders: the moving set matters only when a kinematic one moves */
    if (bullet || world->ccd_kinematic_moving) {
        s = sx_broadphase_query(&world->bp, world->aabbs, box, &world->ccd_found,
                                &world->ccd_found_count, &world->ccd_found_capacity);
    } else {
        s = sx_broadphase_query_fixed(&world->bp, box, &world->ccd_found, &world->ccd_found_count,
                                      &world->ccd_found_capacity);
    }
    if (s != SX_OK) return s;
    for (i = 0; i < world->ccd_found_count; ++i) {
        int cj = world->ccd_found[i];
        const sx_collider *oc = &world->colliders[cj];
        const sx_body_sim *o = &world->sims[oc->body];
        if (oc->body == slot || !oc->alive || oc->sensor) continue;
        if (o->dynamic && !bullet) continue;
        /* bullets against bullets: sx_bullets_meet, both moving */
        if (bullet && sx_moving_bullet(world, oc->body)) continue;
        /* the broadphase holds a moving collider's bounds grown by its
         * reach; the sweep meets it where it ended */
        if (o->moving) {
            sx_aabb ob = sx_collider_aabb(oc, o->xf);
            sx_vec2 mid = sx_scale(sx_add(ob.lower, ob.upper), SX_R(0.5));
            sx_real reach = max_ext + world->margin + sx_length(sx_sub(ob.upper, mid));
            if (!sx_aabb_overlaps(ob, box) ||
                sx_distance_sq(sx_closest_point_on_segment(m->c0, m->c1, mid, NULL), mid) >
                    reach * reach) {
                continue;
            }
        }
        sx_sweep_pair(world, slot, m, cj, NULL, &t);
    }
    if (t < SX_R(1.0)) {
        sx_vec2 back = sx_lerp(m->c0, m->c1, t);
        sx_real turn = (t - SX_R(1.0)) * (m->angle1 - m->angle0);
        sx_real lift, ke, drift, k = SX_R(1.0);
        sx_vec2 f = sx_add(sx_scale(world->def.gravity, b->gravity_scale / b->inv_mass), b->force);
        /* the work gravity and the applied force and torque did over the
         * dropped part of the path is paid back from the velocity, so the
         * move adds no energy; a move the motion cannot pay for (a slow body
         * driven by a large force, pushed along by the position correction)
         * is not made */
        lift = -sx_dot(f, sx_sub(back, b->center)) - b->torque * turn;
        ke = SX_R(0.5) * sx_dot(b->v, b->v) / b->inv_mass;
        if (b->inv_inertia > SX_R(0.0)) ke += SX_R(0.5) * b->w * b->w / b->inv_inertia;
        /* The energy symplectic Euler keeps, the one that sets how high the
         * body goes next, also holds h (f . v + torque w) / 2 (h: the last
         * sub-step). That term is negative for a body moving against the
         * force and slowing it raises it, so then the scale k pays it too:
         * ke k^2 + drift k = ke + drift - lift, whose root lies in (0, 1);
         * divided by ke (|drift| < ke there) nothing overflows. Moving with
         * the force the term only drops. */
        drift = SX_R(0.5) * world->ccd_h * (sx_dot(f, b->v) + b->torque * b->w);
        if (lift > SX_R(0.0) && drift < SX_R(0.0)) {
            sx_real rest = ke + drift - lift, d = drift / ke;
            if (!(rest > SX_R(0.0))) return SX_OK;
            k = SX_R(0.5) * (sx_sqrt(d * d + SX_R(4.0) * (rest / ke)) - d);
            if (!(k <= SX_R(1.0))) k = SX_R(1.0); /* an infinite ke: nothing to pay */
        } else if (lift > SX_R(0.0)) {
            if (!(lift < ke)) return SX_OK;
            k = sx_sqrt(SX_R(1.0) - lift / ke);
        }
        b->center = back;
        b->xf.q = sx_rot_make(m->angle0 + t * (m->angle1 - m->angle0));
        sx_body_sync_origin(b);
        b->v = sx_scale(b->v, k);
        b->w *= k;
    }
    return SX_OK;
}

/* Whether body slot, listed by sx_ccd_list (it strayed, turned or is a
 * bullet), needs the sweep: it went farther than its collide-time velocity
 * allows, or its farthest point strayed from the path collide foresaw (or
 * turned, or for a bullet moved) by more than half its thinnest extent. */
static bool sx_needs_sweep(sx_world *world, int slot) {
    const sx_body_sim *b = &world->sims[slot];
    const sx_ccd_rec *p = &world->ccd_recs[slot];
    sx_real max_ext, min_ext, moved = sx_length(sx_sub(b->center, p->center)), path, thin;
    sx_rot dq = sx_rot_inv_mul(p->q, b->xf.q);
    bool bullet = world->bullet_count > 0 && world->infos[slot].bullet;
    if (moved > sx_length(sx_sub(p->end, p->center)) + SX_R(0.5) * world->margin) return true;
    sx_body_extents(world, slot, &max_ext, &min_ext);
    path = bullet ? moved : sx_length(sx_sub(b->center, p->end));
    thin = SX_R(0.5) * min_ext;
    /* a small turn by its sine; past a quarter of the angular slop by its
     * angle (a turn of several half turns told by the velocity), which
     * under a quarter turn is at most pi/2 times its sine: the arc tangent
     * only when that bound does not settle it */
    if (dq.c >= SX_R(0.0) && sx_absr(b->w * world->ccd_dt) < SX_R(0.5) * SX_PI) {
        sx_real s = sx_absr(dq.s),
                bound = s > SX_R(0.25) * SX_ANGULAR_SLOP ? SX_R(0.5) * SX_PI * s : s;
        if (!(bound * max_ext + path > thin)) return false;
        if (bound == s) return true;
    }
    return sx_absr(sx_turn(b, p->q, world->ccd_dt)) * max_ext + path > thin;
}

/* Whether body slot, where the step left it (b; its record r), strayed
 * from the end its collide-time velocity foresaw by more than half the
 * margin (gravity bends the path by far less), turned by more than a
 * quarter of the angular slop (less moves no point far enough to matter),
 * or is a bullet: the bodies sx_needs_sweep then tests with their
 * extents. */
static bool sx_strayed(const sx_world *world, int slot, const sx_body_sim *b, const sx_ccd_rec *r) {
    sx_real dx = b->center.x - r->end.x, dy = b->center.y - r->end.y;
    /* the turn since collide: sx_rot_inv_mul(r->q, b->xf.q) */
    sx_real c = r->q.c * b->xf.q.c + r->q.s * b->xf.q.s;
    sx_real s = r->q.c * b->xf.q.s - r->q.s * b->xf.q.c;
    return dx * dx + dy * dy > SX_R(0.25) * world->margin * world->margin || c < SX_R(0.0) ||
           sx_absr(s) > SX_R(0.25) * SX_ANGULAR_SLOP ||
           (world->bullet_count > 0 && world->infos[slot].bullet);
}

/* The size gate: whether every point of body slot (b; its record r) moved
 * over the step less than its gate, an eighth of its thinnest width. A
 * convex body cannot pass a zero-thickness wall by moving less than half
 * its width (its middle stays on its side, and the contact pushes it back
 * out there), nor, by the widths of the Minkowski difference, another
 * body: such a body is never swept. The farthest point moves at most
 * |d| + |turn| max_ext, and under a quarter turn |turn| <= |s| / c (the
 * tangent): c |d| + |s| max_ext < c gate, compared squared. */
static bool sx_under_gate(sx_world *world, int slot, const sx_body_sim *b, const sx_ccd_rec *r) {
    const sx_ccd_pose *p = &world->ccd_poses[slot];
    sx_real dx = b->center.x - r->center.x, dy = b->center.y - r->center.y;
    sx_real c = r->q.c * b->xf.q.c + r->q.s * b->xf.q.s;
    sx_real s = r->q.c * b->xf.q.s - r->q.s * b->xf.q.c;
    sx_real wdt = b->w * world->ccd_dt, room;
    sx_real max_ext, min_ext;
    if (!p->ext_valid) sx_body_extents(world, slot, &max_ext, &min_ext);
    /* a turn of a quarter or more, or a velocity that could tell a turn of
     * several half turns (sx_turn), goes on to the full test */
    if (!(c > SX_R(0.0)) || !(wdt * wdt < SX_R(0.25) * SX_PI * SX_PI)) return false;
    room = c * p->gate - sx_absr(s) * p->max_ext;
    return room > SX_R(0.0) && c * c * (dx * dx + dy * dy) < room * room;
}

/* Lists in ccd_sweep the awake dynamic bodies collide recorded that
 * strayed, turned or are bullets (sx_strayed). It runs for every moving
 * body each step, so a first test, in four lanes, skips those that did
 * neither: the body's rotation and centre less its recorded rotation and
 * foreseen end, squared lane by lane, none above its bound. A turn
 * sx_strayed lists moves the rotation by at least the sine it tests, and
 * a distance it lists has a coordinate of at least 1/sqrt(2) of it: the
 * bounds (a little below those halves of the squares: rounding, and
 * rotations up to a tenth off unit length) never skip a body sx_strayed
 * lists. */
static sx_status sx_ccd_list(sx_world *world) {
    const sx_real turn = SX_R(0.25) * SX_ANGULAR_SLOP;
    const sx_real near_sq = SX_R(0.45) * SX_R(0.25) * world->margin * world->margin;
    const sx_real turn_sq = SX_R(0.4) * turn * turn;
    const sx_r4 bound = sx_r4_set(turn_sq, turn_sq, near_sq, near_sq);
    const sx_body_sim *sims = world->sims;
    const sx_ccd_rec *recs = world->ccd_recs;
    const int *active = world->active_bodies;
    const uint32_t stamp = world->ccd_stamp;
    const bool bullets = world->bullet_count > 0;
    const int n = world->active_body_count, cap = world->ccd_rec_capacity;
    int k;
    world->ccd_sweep_count = 0;
    for (k = 0; k < n; ++k) {
        const int slot = active[k];
        const sx_body_sim *b;
        const sx_ccd_rec *r;
        sx_r4 d;
        /* recorded at this collide (a body changed since is forgotten; one
         * created since may lie past the records) */
        if (slot >= cap) continue;
        r = &recs[slot];
        if (r->stamp != stamp) continue;
        b = &sims[slot];
        d = sx_r4_sub(sx_r4_load2x2(&b->xf.q.c, &b->center.x), sx_r4_load2x2(&r->q.c, &r->end.x));
        if (!sx_m4_any(sx_r4_gt(sx_r4_mul(d, d), bound)) &&
            !(bullets && world->infos[slot].bullet)) {
            continue;
        }
        if (!b->dynamic || !b->awake || !sx_strayed(world, slot, b, r)) continue;
        if (sx_under_gate(world, slot, b, r)) continue;
        if (!sx_push_int(&world->ccd_sweep, &world->ccd_sweep_count, &world->ccd_sweep_capacity,
                         slot)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    return SX_OK;
}

bool sx_paths_meet(sx_vec2 a0, sx_vec2 da, sx_vec2 b0, sx_vec2 db, sx_real r) {
    sx_vec2 p = sx_sub(b0, a0), u = sx_sub(db, da);
    sx_real uu = sx_dot(u, u), t = SX_R(0.0);
    if (uu > SX_R(0.0)) t = sx_clampr(-sx_dot(p, u) / uu, SX_R(0.0), SX_R(1.0));
    /* NaN answers true: the exact test decides */
    return !(sx_length_sq(sx_mul_add(p, t, u)) > r * r);
}

static int sx_bullet_cmp(const void *pa, const void *pb) {
    const sx_ccd_bullet *a = (const sx_ccd_bullet *)pa, *b = (const sx_ccd_bullet *)pb;
    if (a->lower != b->lower) return a->lower < b->lower ? -1 : 1;
    return (a->slot > b->slot) - (a->slot < b->slot);
}

/* Bullets against bullets, both moving along their paths of the step: a
 * bullet's bounds in the broadphase are not grown by its travel (a volley
 * would pair each bullet with all the others), so two bullets that meet
 * within the step have no contact, and sweeping one against where the
 * other ended would let them pass through each other. The moving bullets'
 * path boxes are swept and pruned along the axis they crowd least; each
 * pair whose bounding discs come within the margin along the two straight
 * paths gets its time of impact, and both keep their earliest. Fills
 * world->ccd_bullets, sorted; returns how many, or -1 out of memory. */
static int sx_bullets_meet(sx_world *world) {
    sx_ccd_bullet *list;
    sx_real width[2] = {SX_R(0.0), SX_R(0.0)}, lo[2] = {SX_REAL_MAX, SX_REAL_MAX},
            hi[2] = {-SX_REAL_MAX, -SX_REAL_MAX};
    int k, i, j, n = 0, axis;
    for (k = 0; k < world->active_body_count; ++k) {
        int slot = world->active_bodies[k];
        sx_ccd_bullet *e;
        sx_real min_ext;
        sx_vec2 mid;
        if (!sx_moving_bullet(world, slot)) continue;
        if (!sx_grow_zeroed((void **)&world->ccd_bullets, &world->ccd_bullet_capacity, n + 1,
                            sizeof(sx_ccd_bullet))) {
            return -1;
        }
        e = &world->ccd_bullets[n++];
        e->slot = slot;
        e->swept = world->ccd_poses[slot].swept;
        sx_body_extents(world, slot, &e->max_ext, &min_ext);
        e->m = sx_body_motion(world, slot);
        e->toi = SX_R(1.0);
        e->box = sx_aabb_fatten(sx_aabb_make(sx_vmin(e->m.c0, e->m.c1), sx_vmax(e->m.c0, e->m.c1)),
                                e->max_ext + SX_R(0.5) * world->margin);
        mid = sx_scale(sx_add(e->box.lower, e->box.upper), SX_R(0.5));
        width[0] += e->box.upper.x - e->box.lower.x;
        width[1] += e->box.upper.y - e->box.lower.y;
        lo[0] = sx_minr(lo[0], mid.x);
        lo[1] = sx_minr(lo[1], mid.y);
        hi[0] = sx_maxr(hi[0], mid.x);
        hi[1] = sx_maxr(hi[1], mid.y);
    }
    if (n < 2) return n;
    list = world->ccd_bullets;
    /* the axis on which the boxes overlap least: their total width against
     * the spread of their middles */
    axis = width[1] * (hi[0] - lo[0]) < width[0] * (hi[1] - lo[1]) ? 1 : 0;
    for (i = 0; i < n; ++i) {
        list[i].lower = axis == 0 ? list[i].box.lower.x : list[i].box.lower.y;
        list[i].upper = axis == 0 ? list[i].box.upper.x : list[i].box.upper.y;
    }
    qsort(list, (size_t)n, sizeof(sx_ccd_bullet), sx_bullet_cmp);
    for (i = 0; i < n; ++i) {
        sx_ccd_bullet *a = &list[i];
        for (j = i + 1; j < n && list[j].lower <= a->upper; ++j) {
            sx_ccd_bullet *b = &list[j];
            sx_real t = SX_R(1.0);
            int cj;
            if ((!a->swept && !b->swept) || !sx_aabb_overlaps(a->box, b->box)) continue;
            if (!sx_paths_meet(a->m.c0, sx_sub(a->m.c1, a->m.c0), b->m.c0, sx_sub(b->m.c1, b->m.c0),
                               a->max_ext + b->max_ext + world->margin)) {
                continue;
            }
            for (cj = world->infos[b->slot].first_collider; cj >= 0;
                 cj = world->colliders[cj].next) {
                if (world->colliders[cj].alive && !world->colliders[cj].sensor)
                    sx_sweep_pair(world, a->slot, &a->m, cj, &b->m, &t);
            }
            a->toi = sx_minr(a->toi, t);
            b->toi = sx_minr(b->toi, t);
        }
    }
    return n;
}

sx_status sx_world_continuous(sx_world *world) {
    int k, n;
    sx_status s;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    if (!(world->ccd_dt > SX_R(0.0))) return SX_OK;
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    world->lane_gaps_current = false; /* the sweeps move bodies back */
    /* the bodies that strayed, turned or are bullets; of those, the ones
     * that need it are swept, and the bullets last, against the others'
     * final poses */
    s = sx_ccd_list(world);
    if (s != SX_OK) return s;
    n = 0;
    for (k = 0; k < world->ccd_sweep_count; ++k) {
        int slot = world->ccd_sweep[k];
        if (sx_needs_sweep(world, slot)) {
            world->ccd_poses[slot].swept = true;
            world->ccd_sweep[n++] = slot;
        }
    }
    world->ccd_sweep_count = n;
    s = SX_OK;
    for (k = 0; k < world->ccd_sweep_count && s == SX_OK; ++k) {
        int slot = world->ccd_sweep[k];
        sx_motion m;
        sx_real max_ext, min_ext;
        if (world->bullet_count > 0 && world->infos[slot].bullet) continue;
        sx_body_extents(world, slot, &max_ext, &min_ext);
        m = sx_body_motion(world, slot);
        s = sx_sweep_body(world, slot, &m, max_ext, false, SX_R(1.0));
    }
    /* the bullets last: against each other, both moving, then against the
     * others where the step (and the sweeps above) left them */
    if (s == SX_OK && world->bullet_count > 0) {
        n = sx_bullets_meet(world);
        if (n < 0) s = SX_ERR_NO_MEMORY;
        for (k = 0; k < n && s == SX_OK; ++k) {
            const sx_ccd_bullet *e = &world->ccd_bullets[k];
            if (e->swept) s = sx_sweep_body(world, e->slot, &e->m, e->max_ext, true, e->toi);
        }
    }
    for (k = 0; k < world->ccd_sweep_count; ++k)
        world->ccd_poses[world->ccd_sweep[k]].swept = false;
    if (s != SX_OK) return s;
    world->ccd_sweep_count = 0;
    /* once per collide */
    world->ccd_dt = SX_R(0.0);
    return SX_OK;
}

sx_status sx_body_set_bullet(sx_world *world, sx_body_id body, bool bullet) {
    int slot;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    slot = sx_body_slot(world, body);
    if (slot < 0) return SX_ERR_STALE_HANDLE;
    world->bullet_count += (bullet ? 1 : 0) - (world->infos[slot].bullet ? 1 : 0);
    world->infos[slot].bullet = bullet;
    return SX_OK;
}

bool sx_body_is_bullet(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot >= 0 && world->infos[slot].bullet;
}
