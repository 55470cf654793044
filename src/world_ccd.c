/* sepax — continuous collision: fast bodies swept to their time of impact
 * at the end of the step.
 *
 * The step's contacts are found once, at collide, with margins and bounds
 * grown by how far each body can move at its speed then: a body that keeps
 * to that straight motion meets every wall through a speculative contact.
 * What that misses is motion collide did not foresee: a body knocked on
 * faster than it was going, or one turning so far that a contact's
 * linearised separation no longer holds (a spinning blade). So collide
 * records each awake dynamic body's pose and velocity (sx_ccd_record), and
 * after the sub-steps sx_world_continuous looks at each of them: only one
 * that went farther than its recorded velocity allows, strayed from the
 * path it foresaw or turned, by more than half its thinnest extent at its
 * farthest point, or a fast bullet, is
 * swept from the recorded pose to the final one against the colliders its
 * swept box meets in the broadphase (conservative advancement, distance.c)
 * and put back at the earliest time of impact, keeping its velocity. Box2D
 * v3 sweeps every fast body against static geometry, after the solver, in
 * the same way; sweeping only what the speculative contacts cannot cover
 * keeps slow and ordinary fast bodies free. */
#include "distance.h"
#include "world_array.h"
#include "world_body.h"
#include "world_broadphase.h"
#include "world_ccd.h"
#include "world_internal.h"

sx_status sx_ccd_record(sx_world *world) {
    int k;
    uint32_t stamp = world->ccd_stamp + 1u;
    world->ccd_dt = SX_R(0.0);
    if (!(world->step_dt > SX_R(0.0))) return SX_OK;
    if (!sx_grow_zeroed((void **)&world->ccd_poses, &world->ccd_pose_capacity, world->body_slots,
                        sizeof(sx_ccd_pose))) {
        return SX_ERR_NO_MEMORY;
    }
    /* 0 is never a live stamp: fresh (zeroed) slots never match */
    if (stamp == 0u) stamp = 1u;
    world->ccd_stamp = stamp;
    world->ccd_kinematic_moving = 0;
    for (k = 0; k < world->active_body_count; ++k) {
        int slot = world->active_bodies[k];
        const sx_body_sim *b = &world->sims[slot];
        sx_ccd_pose *p = &world->ccd_poses[slot];
        /* only the awake dynamic bodies are swept (their stamp says so) */
        if (!b->dynamic || !b->awake) {
            if (b->v.x != SX_R(0.0) || b->v.y != SX_R(0.0) || b->w != SX_R(0.0)) {
                world->ccd_kinematic_moving = 1;
            }
            continue;
        }
        p->center = b->center;
        p->q = b->xf.q;
        p->v = b->v;
        p->stamp = stamp;
    }
    world->ccd_dt = world->step_dt;
    return SX_OK;
}

void sx_ccd_forget(sx_world *world, int slot) {
    /* also no sweep this step: a new body in a reused slot has no pose */
    if (slot < world->ccd_pose_capacity) {
        world->ccd_poses[slot].ext_valid = false;
        world->ccd_poses[slot].stamp = 0u;
    }
}

void sx_ccd_free(sx_world *world) {
    sx_free(world->ccd_poses, (size_t)world->ccd_pose_capacity * sizeof(sx_ccd_pose));
    sx_free(world->ccd_found, (size_t)world->ccd_found_capacity * sizeof(int));
    sx_free(world->ccd_sweep, (size_t)world->ccd_sweep_capacity * sizeof(int));
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

/* sx_measure_extents, cached in the pose record until sx_ccd_forget. */
static void sx_body_extents(sx_world *world, int slot, sx_real *max_ext, sx_real *min_ext) {
    sx_ccd_pose *p = &world->ccd_poses[slot];
    if (!p->ext_valid) {
        sx_measure_extents(world, slot, &p->max_ext, &p->min_ext);
        p->ext_valid = true;
    }
    *max_ext = p->max_ext;
    *min_ext = p->min_ext;
}

/* The turn of body slot since its recorded pose: the representative of the
 * change of angle nearest to w dt (a turn of several half turns in a step
 * is told from its remainder by the velocity). */
static sx_real sx_turn(const sx_body_sim *b, const sx_ccd_pose *p, sx_real dt) {
    sx_real guess = b->w * dt;
    sx_real diff = sx_rot_angle(sx_rot_inv_mul(p->q, b->xf.q)) - guess;
    sx_real k = sx_floor((diff + SX_PI) / (SX_R(2.0) * SX_PI));
    return guess + diff - k * (SX_R(2.0) * SX_PI);
}

/* The motion of body slot over the step. */
static sx_motion sx_body_motion(const sx_world *world, int slot) {
    const sx_body_sim *b = &world->sims[slot];
    const sx_ccd_pose *p = &world->ccd_poses[slot];
    sx_motion m;
    m.local_center = b->local_center;
    m.c0 = p->center;
    m.c1 = b->center;
    m.angle1 = sx_rot_angle(b->xf.q);
    m.angle0 = m.angle1 - sx_turn(b, p, world->ccd_dt);
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
 * the colliders of body other (all parts of both), below *t_min. */
static void sx_sweep_pair(const sx_world *world, int slot, const sx_motion *m, int cj,
                          sx_real *t_min) {
    const sx_collider *oc = &world->colliders[cj];
    /* the others at their final poses: the body is put back along its own
     * path while they stay where the step left them (as Box2D v3 does) */
    sx_motion mo = sx_body_still(world, oc->body);
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

/* Sweeps body slot along m; puts it at its first time of impact. */
static sx_status sx_sweep_body(sx_world *world, int slot, const sx_motion *m, sx_real max_ext,
                               bool bullet) {
    sx_body_sim *b = &world->sims[slot];
    sx_aabb box = sx_aabb_fatten(sx_aabb_make(sx_vmin(m->c0, m->c1), sx_vmax(m->c0, m->c1)),
                                 max_ext + world->margin);
    sx_real t = SX_R(1.0);
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
        sx_sweep_pair(world, slot, m, cj, &t);
    }
    if (t < SX_R(1.0)) {
        sx_vec2 back = sx_lerp(m->c0, m->c1, t);
        sx_real turn = (t - SX_R(1.0)) * (m->angle1 - m->angle0), lift, ke, k = SX_R(1.0);
        /* the work gravity and the applied force and torque did over the
         * dropped part of the path is paid back from the velocity, so the
         * move adds no energy; a move the motion cannot pay for (a slow body
         * driven by a large force, pushed along by the position correction)
         * is not made */
        lift =
            -sx_dot(sx_add(sx_scale(world->def.gravity, b->gravity_scale / b->inv_mass), b->force),
                    sx_sub(back, b->center)) -
            b->torque * turn;
        ke = SX_R(0.5) * sx_dot(b->v, b->v) / b->inv_mass;
        if (b->inv_inertia > SX_R(0.0)) ke += SX_R(0.5) * b->w * b->w / b->inv_inertia;
        if (lift > SX_R(0.0)) {
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

/* Whether body slot needs the sweep, and its motion and reach if so. */
static bool sx_needs_sweep(sx_world *world, int slot) {
    const sx_body_sim *b = &world->sims[slot];
    const sx_ccd_pose *p = &world->ccd_poses[slot];
    sx_vec2 d = sx_sub(b->center, p->center);
    /* where it ended against where collide foresaw (gravity bends the path
     * by far less than the margin) */
    sx_vec2 off = sx_mul_add(d, -world->ccd_dt, p->v);
    sx_real half = SX_R(0.5) * world->margin, max_ext, min_ext, sweep, moved;
    sx_rot dq = sx_rot_inv_mul(p->q, b->xf.q);
    /* turns under a quarter of the angular slop move no point far enough
     * to matter, and are not worth the extents */
    bool turned = dq.c < SX_R(0.0) || sx_absr(dq.s) > SX_R(0.25) * SX_ANGULAR_SLOP;
    /* the cold body data only when there are bullets at all */
    bool bullet = world->bullet_count > 0 && world->infos[slot].bullet;
    /* leaving its collide-time bounds (going farther than dt |v| + half)
     * strays more than half from that end point too: one test for both */
    if (!(sx_length_sq(off) > half * half) && !turned && !bullet) return false;
    sx_body_extents(world, slot, &max_ext, &min_ext);
    moved = sx_length(d);
    /* how far its farthest point strayed: the turn (a small one by its
     * sine), the bend of its path, and for a bullet the whole path */
    sweep = (turned ? sx_absr(sx_turn(b, p, world->ccd_dt)) : sx_absr(dq.s)) * max_ext +
            (bullet ? moved : sx_length(off));
    return moved > world->ccd_dt * sx_length(p->v) + half || sweep > SX_R(0.5) * min_ext;
}

sx_status sx_world_continuous(sx_world *world) {
    int pass, k;
    sx_status s;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    if (!(world->ccd_dt > SX_R(0.0))) return SX_OK;
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    /* one pass over the moving bodies finds those to sweep; then the others
     * are swept, and the bullets last, against the others' final poses */
    for (k = 0; k < world->active_body_count; ++k) {
        int slot = world->active_bodies[k];
        /* the stamp marks the bodies that were awake and dynamic at collide
         * (a body changed since is swept as it was then, harmlessly) */
        if (slot >= world->ccd_pose_capacity || world->ccd_poses[slot].stamp != world->ccd_stamp ||
            !sx_needs_sweep(world, slot) || !world->sims[slot].dynamic) {
            continue;
        }
        if (!sx_push_int(&world->ccd_sweep, &world->ccd_sweep_count, &world->ccd_sweep_capacity,
                         slot)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    for (pass = 0; pass < (world->bullet_count > 0 ? 2 : 1); ++pass) {
        for (k = 0; k < world->ccd_sweep_count; ++k) {
            int slot = world->ccd_sweep[k];
            sx_motion m;
            sx_real max_ext, min_ext;
            if (world->bullet_count > 0 && world->infos[slot].bullet != (pass == 1)) continue;
            sx_body_extents(world, slot, &max_ext, &min_ext);
            m = sx_body_motion(world, slot);
            s = sx_sweep_body(world, slot, &m, max_ext, pass == 1);
            if (s != SX_OK) return s;
        }
    }
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
