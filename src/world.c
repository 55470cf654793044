/* sepax — the world: creation, the step, and the stages that do not belong to
 * the contact solver (applying forces, collision detection, integration).
 *
 * The step is symplectic Euler split into public stages so that other
 * drivers (the flecs systems) run exactly the code sx_world_step runs.
 * Collision runs once per step, before the sub-steps: each contact point
 * keeps its anchors in both body frames, and the solver reads its
 * separation from the bodies' current positions, so the sub-steps need no
 * narrowphase of their own (the first world re-ran collision every
 * sub-step, which was most of its cost). Each collider's bounds and
 * speculative margin grow by how far it can move in the step, so a fast
 * body's contacts exist before it reaches them. Contacts are rebuilt into a
 * second buffer and matched against the previous one by collider pair (both
 * lists are sorted by pair key, so matching is one merge walk) and by
 * feature id, which carries the accumulated impulses over for warm
 * starting. Buffers only grow; a warmed-up world allocates nothing per
 * step. */
#include <stdlib.h>
#include <string.h>

#include "collide_world.h"
#include "world_array.h"
#include "world_body.h"
#include "world_broadphase.h"
#include "world_ccd.h"
#include "world_contact.h"
#include "world_internal.h"
#include "world_island.h"
#include "world_sensor.h"

sx_world_def sx_default_world_def(void) {
    sx_world_def d;
    d.gravity = sx_v2(SX_R(0.0), SX_R(-10.0));
    d.sub_steps = 5;
    d.velocity_iterations = 3;
    d.position_iterations = 1;
    d.correction_factor = SX_R(0.2);
    d.max_correction_speed = SX_R(3.0);
    d.contact_hertz = SX_R(0.0);
    d.contact_damping_ratio = SX_R(10.0);
    d.restitution_threshold = SX_R(1.0);
    d.speculative_slops = SX_R(4.0);
    d.manifold_keep_slops = SX_R(0.25);
    d.length_units_per_meter = SX_LENGTH_UNITS_PER_METER;
    d.body_capacity = 0;
    d.enable_sleep = true;
    d.sleep_linear_speed = SX_R(0.05) * SX_LENGTH_UNITS_PER_METER;
    d.sleep_angular_speed = SX_R(2.0) / SX_R(180.0) * SX_PI;
    d.time_to_sleep = SX_R(0.5);
    d.enable_contact_events = true;
    d.enable_continuous = true;
    d.enqueue_task = NULL;
    d.finish_task = NULL;
    d.worker_count = 1;
    d.user_task_context = NULL;
    return d;
}

/* The first field of d that sx_world_create refuses, with its status. */
sx_status sx_world_def_validate(const sx_world_def *d, const char **field) {
    const char *bad = NULL;
    sx_status s = SX_ERR_NONFINITE;
    if (d == NULL) {
        bad = "def";
        s = SX_ERR_INVALID_ARG;
    } else if (!sx_vec2_is_finite(d->gravity)) {
        bad = "gravity";
    } else if (!sx_is_finite(d->correction_factor)) {
        bad = "correction_factor";
    } else if (!sx_is_finite(d->max_correction_speed)) {
        bad = "max_correction_speed";
    } else if (!sx_is_finite(d->contact_hertz)) {
        bad = "contact_hertz";
    } else if (!sx_is_finite(d->contact_damping_ratio)) {
        bad = "contact_damping_ratio";
    } else if (!sx_is_finite(d->restitution_threshold)) {
        bad = "restitution_threshold";
    } else if (!sx_is_finite(d->speculative_slops)) {
        bad = "speculative_slops";
    } else if (!sx_is_finite(d->manifold_keep_slops)) {
        bad = "manifold_keep_slops";
    } else if (!sx_is_finite(d->length_units_per_meter)) {
        bad = "length_units_per_meter";
    } else if (!sx_is_finite(d->sleep_linear_speed)) {
        bad = "sleep_linear_speed";
    } else if (!sx_is_finite(d->sleep_angular_speed)) {
        bad = "sleep_angular_speed";
    } else if (!sx_is_finite(d->time_to_sleep)) {
        bad = "time_to_sleep";
    } else {
        s = SX_ERR_INVALID_ARG;
        if (d->sub_steps < 1) {
            bad = "sub_steps";
        } else if (d->velocity_iterations < 1) {
            bad = "velocity_iterations";
        } else if (d->position_iterations < 0) {
            bad = "position_iterations";
        } else if (!(d->correction_factor > SX_R(0.0) && d->correction_factor <= SX_R(1.0))) {
            bad = "correction_factor";
        } else if (!(d->max_correction_speed > SX_R(0.0))) {
            bad = "max_correction_speed";
        } else if (d->contact_hertz < SX_R(0.0)) {
            bad = "contact_hertz";
        } else if (d->contact_damping_ratio < SX_R(0.0)) {
            bad = "contact_damping_ratio";
        } else if (d->restitution_threshold < SX_R(0.0)) {
            bad = "restitution_threshold";
        } else if (d->speculative_slops < SX_R(0.0)) {
            bad = "speculative_slops";
        } else if (!(d->manifold_keep_slops >= SX_R(0.0) && d->manifold_keep_slops <= SX_R(1.0))) {
            bad = "manifold_keep_slops";
        } else if (!(d->length_units_per_meter > SX_R(0.0))) {
            bad = "length_units_per_meter";
        } else if (d->body_capacity < 0) {
            bad = "body_capacity";
        } else if (d->sleep_linear_speed < SX_R(0.0)) {
            bad = "sleep_linear_speed";
        } else if (d->sleep_angular_speed < SX_R(0.0)) {
            bad = "sleep_angular_speed";
        } else if (!(d->time_to_sleep > SX_R(0.0))) {
            bad = "time_to_sleep";
        } else if ((d->enqueue_task == NULL) != (d->finish_task == NULL)) {
            bad = d->enqueue_task == NULL ? "enqueue_task" : "finish_task";
        } else if (d->worker_count < 1) {
            bad = "worker_count";
        }
    }
    /* a step costs sub_steps x iterations passes: bounded, so it returns */
    if (bad == NULL) {
        s = SX_ERR_CAPACITY;
        if (d->sub_steps > SX_MAX_SUB_STEPS) {
            bad = "sub_steps";
        } else if (d->velocity_iterations > SX_MAX_ITERATIONS) {
            bad = "velocity_iterations";
        } else if (d->position_iterations > SX_MAX_ITERATIONS) {
            bad = "position_iterations";
        } else if (d->body_capacity > SX_WORLD_MAX_ITEMS) {
            bad = "body_capacity";
        } else if (d->worker_count > SX_MAX_WORKERS) {
            bad = "worker_count";
        }
    }
    if (field != NULL) *field = bad;
    return bad == NULL ? SX_OK : s;
}

sx_world *sx_world_create(const sx_world_def *def) {
    sx_world *w;
    if (sx_world_def_validate(def, NULL) != SX_OK) return NULL;
    w = (sx_world *)sx_alloc(sizeof(sx_world));
    if (w == NULL) return NULL;
    memset(w, 0, sizeof(*w));
    w->def = *def;
    /* the one length scale: SX_LINEAR_SLOP's 5 mm, at this world's units */
    w->linear_slop = SX_R(0.005) * def->length_units_per_meter;
    w->margin = def->speculative_slops * w->linear_slop;
    w->body_free = -1;
    w->collider_free = -1;
    sx_broadphase_init(&w->bp);
    if (def->body_capacity > 0) {
        void *sims = NULL, *infos = NULL;
        bool ok = sx_grow_array(&sims, &w->sim_capacity, def->body_capacity, sizeof(sx_body_sim));
        w->sims = (sx_body_sim *)sims;
        ok = ok &&
             sx_grow_array(&infos, &w->info_capacity, def->body_capacity, sizeof(sx_body_info));
        w->infos = (sx_body_info *)infos;
        if (!ok) {
            sx_world_destroy(w);
            return NULL;
        }
    }
    return w;
}

void sx_world_destroy(sx_world *world) {
    int i;
    if (world == NULL) return;
    if (sx_world_locked(world)) {
        /* the walk that called back is still reading it */
        world->destroy_pending = true;
        return;
    }
    for (i = 0; i < world->collider_slots; ++i) {
        sx_collider *c = &world->colliders[i];
        if (c->alive && c->parts != NULL) {
            sx_free(c->parts, (size_t)c->part_count * sizeof(sx_compound_part));
            sx_free(c->part_boxes, (size_t)c->part_count * sizeof(sx_aabb));
        }
    }
    sx_free(world->sims, (size_t)world->sim_capacity * sizeof(sx_body_sim));
    sx_free(world->infos, (size_t)world->info_capacity * sizeof(sx_body_info));
    sx_free(world->colliders, (size_t)world->collider_capacity * sizeof(sx_collider));
    sx_free(world->aabbs, (size_t)world->aabb_capacity * sizeof(sx_aabb));
    sx_free(world->bp_kind, (size_t)world->kind_capacity);
    sx_free(world->collider_generations, (size_t)world->generation_capacity * sizeof(uint32_t));
    sx_free(world->contacts, (size_t)world->contact_capacity * sizeof(sx_contact));
    sx_free(world->old_contacts, (size_t)world->old_contact_capacity * sizeof(sx_contact));
    sx_free(world->pair_manifolds, (size_t)world->pair_manifold_capacity * sizeof(sx_manifold));
    sx_free(world->pair_counts, (size_t)world->pair_count_capacity * sizeof(int));
    sx_free(world->frozen, (size_t)world->frozen_capacity * sizeof(sx_contact));
    sx_free(world->thaw, (size_t)world->thaw_capacity * sizeof(sx_contact));
    sx_free(world->active_bodies, (size_t)world->active_body_capacity * sizeof(int));
    sx_free(world->active_colliders, (size_t)world->active_collider_capacity * sizeof(int));
    sx_free(world->woken, (size_t)world->woken_capacity * sizeof(int));
    sx_free(world->thaw_bodies, (size_t)world->thaw_body_capacity * sizeof(int));
    sx_free(world->thaw_mark, (size_t)world->thaw_mark_capacity);
    sx_free(world->woken_mark, (size_t)world->woken_mark_capacity);
    sx_free(world->changed, (size_t)world->changed_capacity * sizeof(int));
    sx_free(world->collider_mark, (size_t)world->collider_mark_capacity);
    sx_free(world->set_scratch, (size_t)world->set_scratch_capacity * sizeof(int));
    sx_free(world->set_keep, (size_t)world->set_keep_capacity * sizeof(bool));
    sx_broadphase_free(&world->bp);
    sx_ccd_free(world);
    sx_contacts_free(world);
    sx_free(world->begin_events, (size_t)world->begin_capacity * sizeof(sx_contact_event));
    sx_free(world->end_events, (size_t)world->end_capacity * sizeof(sx_contact_event));
    sx_sensors_free(world);
    sx_free(world->by_body_head, (size_t)world->by_body_head_capacity * sizeof(int));
    sx_free(world->by_body_next, (size_t)world->by_body_next_capacity * sizeof(int));
    sx_free(world->by_body_stamp, (size_t)world->by_body_stamp_capacity * sizeof(uint32_t));
    sx_free(world->island_parent, (size_t)world->parent_capacity * sizeof(int));
    sx_free(world->island_time, (size_t)world->time_capacity * sizeof(sx_real));
    sx_free(world, sizeof(sx_world));
}

sx_status sx_world_set_gravity(sx_world *world, sx_vec2 gravity) {
    int i;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (!sx_vec2_is_finite(gravity)) return SX_ERR_NONFINITE;
    world->def.gravity = gravity;
    /* what rested under the old gravity need not rest under the new one */
    for (i = 0; i < world->body_slots; ++i) {
        if (world->infos[i].alive && !world->sims[i].awake) sx_wake_body(world, i);
    }
    return SX_OK;
}

bool sx_world_is_locked(const sx_world *world) { return world != NULL && sx_world_locked(world); }

sx_vec2 sx_world_get_gravity(const sx_world *world) {
    return world == NULL ? sx_v2_zero() : world->def.gravity;
}

int sx_world_body_count(const sx_world *world) { return world == NULL ? 0 : world->body_count; }

sx_real sx_world_linear_slop(const sx_world *world) {
    return world == NULL ? SX_R(0.0) : world->linear_slop;
}

/* The answer every stage gives to a bad world or time step. */
static sx_status sx_check_step(const sx_world *world, sx_real h) {
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    if (!sx_is_finite(h)) return SX_ERR_NONFINITE;
    if (!(h > SX_R(0.0))) return SX_ERR_INVALID_ARG;
    return SX_OK;
}

/* How far a moving collider's broadphase box reaches past its bounds, in
 * linear slops (5 cm at the default scale): a larger box is re-inserted
 * less often but keeps more candidate pairs to test each step, and makes
 * the sweep's boxes wider. */
#define SX_FAT_SLOPS SX_R(10.0)

/* ---- active sets ------------------------------------------------------------ */

/* The fattened bounds of a collider (half the margin on each side: bounds
 * meet when the gap < margin, plus the collider's reach over the step) into
 * world->aabbs; a compound's are the union of its parts', each kept in
 * part_boxes for the part-pair culling of the narrowphase. */
static void sx_collider_bounds(sx_world *world, int slot) {
    sx_collider *c = &world->colliders[slot];
    const sx_body_sim *b = &world->sims[c->body];
    sx_xform xf = b->xf;
    sx_aabb u;
    sx_real half = SX_R(0.5) * world->margin, reach = SX_R(0.0);
    bool moves = world->step_dt > SX_R(0.0) &&
                 (b->v.x != SX_R(0.0) || b->v.y != SX_R(0.0) || b->w != SX_R(0.0));
    if (c->part_count > 0) {
        int k;
        for (k = 0; k < c->part_count; ++k) {
            sx_aabb pb = sx_shape_aabb(&c->parts[k].shape, sx_xform_mul(xf, c->parts[k].offset));
            c->part_boxes[k] = pb;
            u = k == 0 ? pb : sx_aabb_union(u, pb);
        }
    } else {
        u = sx_shape_aabb(&c->shape, xf);
    }
    /* the farthest point of the bounds from the centre of mass bounds the
     * lever of the turn, and the disc a bullet pair's test uses (only
     * worlds with bullets read it) */
    if (moves || world->bullet_count > 0) {
        sx_real far = sx_length(
            sx_vmax(sx_vabs(sx_sub(u.lower, b->center)), sx_vabs(sx_sub(u.upper, b->center))));
        c->bound_radius = far;
        if (moves) {
            reach = world->step_dt * (sx_length(b->v) + sx_absr(b->w) * far);
            if (!sx_is_finite(reach)) reach = SX_R(0.0);
        }
    }
    c->reach = reach;
    /* a bullet's bounds are not grown by its travel when the continuous
     * stage sweeps it (against bullets too, both moving): a volley would
     * otherwise pair each bullet with all the others; its margin keeps the
     * reach for the pairs its bounds do meet */
    if (world->bullet_count > 0 && world->def.enable_continuous && b->dynamic &&
        world->infos[c->body].bullet) {
        reach = SX_R(0.0);
    }
    if (c->part_count > 0) {
        int k;
        for (k = 0; k < c->part_count; ++k)
            c->part_boxes[k] = sx_aabb_fatten(c->part_boxes[k], half + reach);
    }
    world->aabbs[slot] = sx_aabb_fatten(u, half + reach);
    /* in collide's bounds pass (which reads this body already): where an
     * awake dynamic body starts the step, for the continuous stage
     * (world_ccd.c; sx_ccd_record made room for every body slot); never
     * from the bounds a later stage finds */
    if (world->ccd_recording) {
        if (b->dynamic && b->awake) {
            sx_ccd_rec *r = &world->ccd_recs[c->body];
            r->q = b->xf.q;
            r->end = sx_mul_add(b->center, world->step_dt, b->v);
            r->center = b->center;
            r->stamp = world->ccd_stamp;
        } else if (b->v.x != SX_R(0.0) || b->v.y != SX_R(0.0) || b->w != SX_R(0.0)) {
            world->ccd_kinematic_moving = 1;
        }
    }
}

/* Brings collider i's broadphase kind up to date with its body; *kind
 * receives it. Bodies the step does not move keep their bounds: they are
 * recomputed when the body stops (its last move came after the last
 * bounds) or is teleported (aabb_stale); collide recomputes the others. */
static sx_status sx_refresh_collider(sx_world *world, int i, unsigned char *kind_out) {
    sx_collider *c = &world->colliders[i];
    const sx_body_sim *b = &world->sims[c->body];
    unsigned char prev = world->bp_kind[i], kind = SX_BP_OUT;
    if (!c->alive || c->sensor || !world->infos[c->body].enabled) {
        kind = SX_BP_OUT;
    } else if (b->dynamic) {
        kind = b->awake ? SX_BP_AWAKE : SX_BP_ASLEEP;
    } else if (b->moving && (b->v.x != SX_R(0.0) || b->v.y != SX_R(0.0) || b->w != SX_R(0.0))) {
        kind = SX_BP_MOVING_KINEMATIC;
    } else {
        kind = SX_BP_FIXED;
    }
    world->bp_kind[i] = kind;
    *kind_out = kind;
    if (kind == SX_BP_OUT) {
        return prev != SX_BP_OUT ? sx_broadphase_touch(&world->bp, i, world->collider_slots) : SX_OK;
    }
    if (kind != prev || c->aabb_stale) {
        sx_collider_bounds(world, i);
        c->aabb_stale = false;
        return sx_broadphase_touch(&world->bp, i, world->collider_slots);
    }
    return SX_OK;
}

static bool sx_kind_moves(unsigned char kind) {
    return kind == SX_BP_AWAKE || kind == SX_BP_MOVING_KINEMATIC;
}

static int sx_int_cmp(const void *pa, const void *pb) {
    int a = *(const int *)pa, b = *(const int *)pb;
    return a < b ? -1 : (a > b ? 1 : 0);
}

void sx_world_note_awake(sx_world *world, int slot) {
    void *p = world->woken_mark;
    if (world->sets_dirty) return; /* the full rebuild sees it */
    if (!sx_grow_zeroed(&p, &world->woken_mark_capacity, world->body_slots, 1)) {
        world->sets_dirty = true;
        return;
    }
    world->woken_mark = (unsigned char *)p;
    if (world->woken_mark[slot]) return;
    if (!sx_push_int(&world->woken, &world->woken_count, &world->woken_capacity, slot)) {
        world->sets_dirty = true;
        return;
    }
    world->woken_mark[slot] = 1;
}

/* Merges into *list (sorted slots, *count of them) the sorted `changed`
 * slots that `keep` says belong, dropping the listed slots marked in
 * `mark`: the list stays in slot order at a cost of the list plus the
 * changes. */
static sx_status sx_merge_slots(sx_world *world, int **list, int *count, int *capacity,
                                const unsigned char *mark, const int *changed, int changed_count,
                                const bool *keep) {
    int i = 0, j = 0, n = 0;
    void *p = world->set_scratch;
    if (!sx_grow_array(&p, &world->set_scratch_capacity, *count + changed_count, sizeof(int))) {
        return SX_ERR_NO_MEMORY;
    }
    world->set_scratch = (int *)p;
    while (i < *count || j < changed_count) {
        if (j >= changed_count || (i < *count && (*list)[i] < changed[j])) {
            int v = (*list)[i++];
            if (!mark[v]) world->set_scratch[n++] = v;
        } else {
            if (i < *count && (*list)[i] == changed[j]) ++i;
            if (keep[j]) world->set_scratch[n++] = changed[j];
            ++j;
        }
    }
    {
        int *t = *list, c = *capacity;
        *list = world->set_scratch;
        *capacity = world->set_scratch_capacity;
        world->set_scratch = t;
        world->set_scratch_capacity = c;
    }
    *count = n;
    return SX_OK;
}

/* The active sets after bodies only woke or fell asleep (sx_world_note_awake):
 * those bodies and their colliders are redone and merged in, at a cost of
 * the active sets plus the changes, where the full rebuild walks every
 * slot (a sleeping world of 20,000 bodies paid that for each wake). */
static sx_status sx_refresh_woken(sx_world *world) {
    int i, k = world->woken_count, nc = 0;
    void *p;
    sx_status s = SX_OK;
    /* (qsort's array may not be NULL, even for no elements) */
    if (k > 1) qsort(world->woken, (size_t)k, sizeof(int), sx_int_cmp);
    p = world->set_keep;
    if (!sx_grow_array(&p, &world->set_keep_capacity, k, sizeof(bool))) return SX_ERR_NO_MEMORY;
    world->set_keep = (bool *)p;
    for (i = 0; i < k; ++i) {
        const sx_body_sim *b = &world->sims[world->woken[i]];
        world->set_keep[i] = world->infos[world->woken[i]].alive && b->moving && b->awake;
    }
    s = sx_merge_slots(world, &world->active_bodies, &world->active_body_count,
                       &world->active_body_capacity, world->woken_mark, world->woken, k,
                       world->set_keep);
    if (s != SX_OK) return s;
    /* their colliders: kinds redone, listed in slot order */
    world->changed_count = 0;
    for (i = 0; i < k; ++i) {
        int c;
        if (!world->infos[world->woken[i]].alive) continue;
        for (c = world->infos[world->woken[i]].first_collider; c >= 0; c = world->colliders[c].next) {
            if (!sx_push_int(&world->changed, &world->changed_count, &world->changed_capacity, c)) {
                return SX_ERR_NO_MEMORY;
            }
        }
    }
    nc = world->changed_count;
    if (nc > 1) qsort(world->changed, (size_t)nc, sizeof(int), sx_int_cmp);
    p = world->set_keep;
    if (!sx_grow_array(&p, &world->set_keep_capacity, nc, sizeof(bool))) return SX_ERR_NO_MEMORY;
    world->set_keep = (bool *)p;
    p = world->collider_mark;
    if (!sx_grow_zeroed(&p, &world->collider_mark_capacity, world->collider_slots, 1)) {
        return SX_ERR_NO_MEMORY;
    }
    world->collider_mark = (unsigned char *)p;
    for (i = 0; i < nc; ++i) {
        unsigned char kind;
        s = sx_refresh_collider(world, world->changed[i], &kind);
        if (s != SX_OK) return s;
        world->set_keep[i] = sx_kind_moves(kind);
        world->collider_mark[world->changed[i]] = 1;
    }
    s = sx_merge_slots(world, &world->active_colliders, &world->active_collider_count,
                       &world->active_collider_capacity, world->collider_mark, world->changed, nc,
                       world->set_keep);
    for (i = 0; i < nc; ++i)
        world->collider_mark[world->changed[i]] = 0;
    return s;
}

/* Forgets the bodies noted by sx_world_note_awake. */
static void sx_clear_woken(sx_world *world) {
    int i;
    for (i = 0; i < world->woken_count; ++i)
        world->woken_mark[world->woken[i]] = 0;
    world->woken_count = 0;
}

sx_status sx_world_refresh_sets(sx_world *world) {
    int i;
    sx_status s;
    if (!world->sets_dirty) {
        if (world->woken_count == 0) return SX_OK;
        s = sx_refresh_woken(world);
        /* on failure the full rebuild redoes everything next time */
        if (s != SX_OK) world->sets_dirty = true;
        sx_clear_woken(world);
        return s;
    }
    sx_clear_woken(world);
    world->active_body_count = 0;
    world->active_collider_count = 0;
    world->sensor_collider_count = 0;
    for (i = 0; i < world->body_slots; ++i) {
        const sx_body_sim *b = &world->sims[i];
        if (world->infos[i].alive && b->moving && b->awake &&
            !sx_push_int(&world->active_bodies, &world->active_body_count,
                         &world->active_body_capacity, i)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    for (i = 0; i < world->collider_slots; ++i) {
        const sx_collider *c = &world->colliders[i];
        unsigned char kind;
        if (c->alive && c->sensor && world->infos[c->body].enabled &&
            !sx_push_int(&world->sensor_colliders, &world->sensor_collider_count,
                         &world->sensor_collider_capacity, i)) {
            return SX_ERR_NO_MEMORY;
        }
        s = sx_refresh_collider(world, i, &kind);
        if (s != SX_OK) return s;
        if (sx_kind_moves(kind) &&
            !sx_push_int(&world->active_colliders, &world->active_collider_count,
                         &world->active_collider_capacity, i)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    world->sets_dirty = false;
    return SX_OK;
}

/* ---- the speed limit ---------------------------------------------------- */

/* The speed limit for every awake moving body before the solver reads the
 * velocities: dynamic bodies meet it in sx_world_apply_forces already, but a
 * kinematic body's velocity is whatever the caller set (an angular velocity
 * of -FLT_MAX made w x r overflow in the solver and a contact's tangent
 * impulse NaN), and the stages may be called on their own. A no-op for any
 * velocity within half the limit, so ordinary scenes are unchanged bit for
 * bit. */
static void sx_limit_speeds(sx_world *world, sx_real h) {
    sx_half_limit l = sx_half_limit_of(h);
    int k;
    for (k = 0; k < world->active_body_count; ++k) {
        sx_body_sim *b = &world->sims[world->active_bodies[k]];
        if (b->moving && b->awake) sx_limit_speed_past_half(b, &l);
    }
    world->limited_h = h;
}

/* sx_limit_speeds, unless every velocity is known to meet the limit of h
 * already (limited_h: the limit of a longer sub-step is the stricter). In a
 * step, after the first sub-step's solve, the later solves and the rigid
 * position pass read velocities that the last walk, apply_forces and
 * integrate limited and nothing else changed: the walk finds nothing. */
static void sx_limit_speeds_unless_met(sx_world *world, sx_real h) {
    if (!(h <= world->limited_h)) sx_limit_speeds(world, h);
}

/* The contacts' effective masses are prepared by the collide; a caller
 * running the stages may change a body's mass in between (a collider
 * destroyed, a type set). A stale effective mass, prepared for a body made
 * far lighter since, moves it by the correction x old mass / new mass, an
 * overflow to Inf and then NaN: solve and separate prepare them again. Only
 * after such a change, so a step's sub-steps are untouched. */
static void sx_refresh_effective_masses(sx_world *world) {
    if (world->masses_changed) sx_contacts_prepare(world);
}

/* ---- stage 1: forces ---------------------------------------------------- */

sx_status sx_world_apply_forces(sx_world *world, sx_real h) {
    sx_status s = sx_check_step(world, h);
    sx_vec2 g;
    sx_half_limit l;
    int k;
    if (s != SX_OK) return s;
    g = world->def.gravity;
    l = sx_half_limit_of(h);
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    for (k = 0; k < world->active_body_count; ++k) {
        sx_body_sim *b = &world->sims[world->active_bodies[k]];
        sx_vec2 accel;
        if (!b->dynamic || !b->awake) continue;
        accel = sx_add(sx_scale(g, b->gravity_scale), sx_scale(b->force, b->inv_mass));
        b->v = sx_add(sx_mul_add(b->v, h, accel), sx_scale(b->impulse, b->inv_mass));
        b->w = b->w + h * (b->torque * b->inv_inertia) + b->angular_impulse * b->inv_inertia;
        /* implicit damping: stable for any h, exact decay for small h */
        if (b->linear_damping > SX_R(0.0)) {
            b->v = sx_scale(b->v, SX_R(1.0) / (SX_R(1.0) + h * b->linear_damping));
        }
        if (b->angular_damping > SX_R(0.0)) {
            b->w = b->w / (SX_R(1.0) + h * b->angular_damping);
        }
        sx_limit_speed_past_half(b, &l);
        b->impulse = sx_v2_zero();
        b->angular_impulse = SX_R(0.0);
    }
    /* the dynamic bodies meet h's limit, the others what they met */
    world->limited_h = sx_minr(world->limited_h, h);
    return SX_OK;
}

sx_status sx_world_clear_forces(sx_world *world) {
    int i;
    sx_status s;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    /* forces wake their body, so only the active ones hold any */
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    for (i = 0; i < world->active_body_count; ++i) {
        world->sims[world->active_bodies[i]].force = sx_v2_zero();
        world->sims[world->active_bodies[i]].torque = SX_R(0.0);
    }
    return SX_OK;
}

/* ---- stage 2: collision ------------------------------------------------- */

/* Copies the warm-starting impulses of the old contact's point with the
 * same feature id, if any. */
static void sx_match_point(sx_contact_point *p, const sx_contact *old) {
    int k;
    p->normal_impulse = SX_R(0.0);
    p->tangent_impulse = SX_R(0.0);
    if (old == NULL) return;
    for (k = 0; k < old->count; ++k) {
        if (old->points[k].id == p->id) {
            p->normal_impulse = old->points[k].normal_impulse;
            p->tangent_impulse = old->points[k].tangent_impulse;
            return;
        }
    }
}

/* A frictionless contact's tangent rows are never solved, so a tangent
 * impulse from when the pair had friction (warm-started, never clamped)
 * would push the bodies along the surface for ever: none is kept. */
static void sx_drop_tangent_impulses(sx_contact *c) {
    int k;
    if (c->friction > SX_R(0.0)) return;
    for (k = 0; k < c->count; ++k)
        c->points[k].tangent_impulse = SX_R(0.0);
}

/* The handles of contact c's colliders and bodies, as the public views
 * (events, sx_world_get_contact, sx_world_get_contact_pairs) give them. */
static sx_contact_event sx_contact_handles(const sx_world *world, const sx_contact *c) {
    sx_contact_event e;
    e.collider_a.index = (uint32_t)c->collider_a;
    e.collider_a.generation = world->collider_generations[c->collider_a];
    e.collider_b.index = (uint32_t)c->collider_b;
    e.collider_b.generation = world->collider_generations[c->collider_b];
    e.body_a.index = (uint32_t)c->body_a;
    e.body_a.generation = world->infos[c->body_a].generation;
    e.body_b.index = (uint32_t)c->body_b;
    e.body_b.generation = world->infos[c->body_b].generation;
    return e;
}

/* Appends the event of contact c to an event array. */
static sx_status sx_push_event(const sx_world *world, const sx_contact *c,
                               sx_contact_event **events, int *count, int *capacity) {
    sx_contact_event *e;
    if (*count == *capacity) {
        void *p = *events;
        sx_status s = sx_reserve_array(&p, capacity, *count + 1, sizeof(sx_contact_event));
        *events = (sx_contact_event *)p;
        if (s != SX_OK) return s;
    }
    e = &(*events)[(*count)++];
    *e = sx_contact_handles(world, c);
    return SX_OK;
}

/* The index past the run of contacts with the key of contacts[i] (a
 * compound pair has one contact per touching part pair, all with one key). */
static int sx_skip_run(const sx_contact *contacts, int count, int i) {
    uint64_t key = contacts[i].key;
    while (i < count && contacts[i].key == key)
        ++i;
    return i;
}

/* Ends the old pairs with keys below `below` (UINT64_MAX: all, as a key's
 * collider_a < collider_b): one end event per collider pair when the world
 * reports events, however many part pairs touched; *old_index moves past
 * them. */
static sx_status sx_end_old_pairs(sx_world *world, int *old_index, uint64_t below) {
    int j = *old_index;
    while (j < world->old_contact_count && world->old_contacts[j].key < below) {
        if (world->def.enable_contact_events) {
            sx_status s = sx_push_event(world, &world->old_contacts[j], &world->end_events,
                                        &world->end_count, &world->end_capacity);
            if (s != SX_OK) return s;
        }
        j = sx_skip_run(world->old_contacts, world->old_contact_count, j);
    }
    *old_index = j;
    return SX_OK;
}

/* The events of the collide walk's pair `key`: it began when it made
 * contacts (from `first` on) and had none, it ended when it had some
 * (old_contacts[old_begin, old_end)) and made none. */
static sx_status sx_pair_events(sx_world *world, int first, int old_begin, int old_end) {
    bool made = world->contact_count > first, had = old_end > old_begin;
    if (!world->def.enable_contact_events || made == had) return SX_OK;
    if (made) {
        return sx_push_event(world, &world->contacts[first], &world->begin_events,
                             &world->begin_count, &world->begin_capacity);
    }
    return sx_push_event(world, &world->old_contacts[old_begin], &world->end_events,
                         &world->end_count, &world->end_capacity);
}

sx_contact_events sx_world_get_contact_events(const sx_world *world) {
    sx_contact_events e;
    memset(&e, 0, sizeof(e));
    if (world == NULL) return e;
    e.begin = world->begin_events;
    e.begin_count = world->begin_count;
    e.end = world->end_events;
    e.end_count = world->end_count;
    return e;
}

sx_status sx_world_begin_step(sx_world *world, sx_real dt) {
    sx_status s = sx_check_step(world, dt);
    if (s != SX_OK) return s;
    world->step_dt = dt;
    world->step_solves = 0;
    return sx_world_clear_events(world);
}

sx_status sx_world_clear_events(sx_world *world) {
    if (world == NULL) return SX_ERR_INVALID_ARG;
    world->begin_count = 0;
    world->end_count = 0;
    world->sensor_begin_count = 0;
    world->sensor_end_count = 0;
    return SX_OK;
}

/* Room for one more contact in the current list. */
static sx_status sx_reserve_contact(sx_world *world) {
    void *p = world->contacts;
    sx_status s;
    if (world->contact_count < world->contact_capacity) return SX_OK;
    s = sx_reserve_array(&p, &world->contact_capacity, world->contact_count + 1,
                         sizeof(sx_contact));
    world->contacts = (sx_contact *)p;
    return s;
}

/* True when a contact waits for a sleeping dynamic body: the solver skips it
 * and the broadphase does not find its pair again. */
static bool sx_contact_sleeps(const sx_world *world, const sx_contact *c) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    return !sx_contact_is_active(world, c) &&
           ((a->dynamic && !a->awake) || (b->dynamic && !b->awake));
}

/* Appends a copy of c to a growing contact array (sx_reserve_array's
 * status). */
static sx_status sx_push_contact(sx_contact **array, int *count, int *capacity,
                                 const sx_contact *c) {
    if (*count == *capacity) {
        void *p = *array;
        sx_status s = sx_reserve_array(&p, capacity, *count + 1, sizeof(sx_contact));
        *array = (sx_contact *)p;
        if (s != SX_OK) return s;
    }
    (*array)[(*count)++] = *c;
    return SX_OK;
}

/* Moves the sleeping contacts of the current list into the frozen store. */
/* sx_freeze_contacts when the frozen store is empty and most contacts
 * freeze (a pile fell asleep), from the first sleeping contact `first`:
 * the list's buffer becomes the store (the sleeping contacts compacted in
 * place) and the few awake ones move to the store's old buffer, so the
 * pile's contacts are neither copied nor written to fresh pages. Same
 * contents and order as the copying way. */
static sx_status sx_freeze_by_swap(sx_world *world, int first, int sleeping) {
    int i, f = 0, m = first, awake = world->contact_count - sleeping;
    void *p = world->frozen;
    sx_status s = sx_reserve_array(&p, &world->frozen_capacity, awake, sizeof(sx_contact));
    sx_contact *list = world->contacts;
    world->frozen = (sx_contact *)p;
    if (s != SX_OK) return s;
    if (first > 0) memcpy(world->frozen, list, (size_t)first * sizeof(sx_contact));
    for (i = first; i < world->contact_count; ++i) {
        if (sx_contact_sleeps(world, &list[i])) {
            if (f != i) list[f] = list[i];
            ++f;
        } else {
            world->frozen[m++] = list[i];
        }
    }
    {
        int c = world->contact_capacity;
        world->contacts = world->frozen;
        world->contact_capacity = world->frozen_capacity;
        world->contact_count = m;
        world->frozen = list;
        world->frozen_capacity = c;
        world->frozen_count = f;
    }
    return SX_OK;
}

static sx_status sx_freeze_contacts(sx_world *world) {
    int i, n = 0;
    for (i = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        if (sx_contact_sleeps(world, c)) {
            sx_status s;
            if (n == i) {
                /* the first to freeze (rare: a step where bodies fell
                 * asleep): how many follow decides the way */
                int j, sleeping = 0;
                void *p = world->frozen;
                for (j = i; j < world->contact_count; ++j)
                    sleeping += sx_contact_sleeps(world, &world->contacts[j]) ? 1 : 0;
                if (world->frozen_count == 0 && sleeping > world->contact_count / 2) {
                    return sx_freeze_by_swap(world, i, sleeping);
                }
                /* room for all that follow in one allocation (a pile of
                 * 20,000 falling asleep grew the store seven times) */
                s = sx_reserve_array(&p, &world->frozen_capacity,
                                     world->frozen_count + sleeping, sizeof(sx_contact));
                world->frozen = (sx_contact *)p;
                if (s != SX_OK) return s;
            }
            s = sx_push_contact(&world->frozen, &world->frozen_count, &world->frozen_capacity, c);
            if (s != SX_OK) return s;
        } else {
            /* in place until the first gap: most steps freeze nothing */
            if (n != i) world->contacts[n] = *c;
            ++n;
        }
    }
    world->contact_count = n;
    return SX_OK;
}

/* The contact list's order: key, then (part_a, part_b) for a compound's
 * several contacts with one key. */
static int sx_contact_key_cmp(const void *pa, const void *pb) {
    const sx_contact *a = (const sx_contact *)pa, *b = (const sx_contact *)pb;
    if (a->key != b->key) return a->key < b->key ? -1 : 1;
    if (a->part_a != b->part_a) return a->part_a < b->part_a ? -1 : 1;
    if (a->part_b != b->part_b) return a->part_b < b->part_b ? -1 : 1;
    return 0;
}

/* The first contact of the list (sorted by key) with a key at or above
 * `key`. */
static int sx_key_lower_bound(const sx_contact *list, int count, uint64_t key) {
    int lo = 0, hi = count;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (list[mid].key < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* True when the sorted list holds a contact with this key. */
static bool sx_has_key(const sx_contact *list, int count, uint64_t key) {
    int lo = sx_key_lower_bound(list, count, key);
    return lo < count && list[lo].key == key;
}

/* Moves the frozen contacts that have an awake dynamic body again into the
 * current list (kept sorted by key), if a body woke since the last call;
 * drops the contacts removed since then. A pair
 * the list already holds keeps the list's contact. Only a contact with a
 * body woken since the last call (thaw_mark) can have become active: the
 * others are passed over on their body indices alone, without reading the
 * bodies. */
static sx_status sx_thaw_contacts(sx_world *world) {
    int i, j, out, n = 0, k = 0;
    void *p;
    sx_status s;
    bool thaw = world->thaw_pending, all = world->thaw_all;
    const unsigned char *woke;
    p = world->thaw_mark;
    /* bodies created since the last wake have slots past the marks */
    if (thaw && !all && !sx_grow_zeroed(&p, &world->thaw_mark_capacity, world->body_slots, 1)) {
        all = true;
    }
    world->thaw_mark = (unsigned char *)p;
    woke = world->thaw_mark;
    world->thaw_pending = false;
    world->thaw_all = false;
    world->thaw_count = 0;
    for (i = 0; i < world->frozen_count; ++i) {
        const sx_contact *c = &world->frozen[i];
        if (c->count == 0) continue; /* a tombstone (body_contacts.c) */
        if (!thaw || (!all && !woke[c->body_a] && !woke[c->body_b]) ||
            !sx_contact_is_active(world, c)) {
            /* kept in place until the first gap: a wake thaws a few
             * contacts of a large store, which then moves little */
            if (n != i) world->frozen[n] = *c;
            ++n;
            continue;
        }
        if (sx_has_key(world->contacts, world->contact_count, c->key)) continue;
        s = sx_push_contact(&world->thaw, &world->thaw_count, &world->thaw_capacity, c);
        if (s != SX_OK) return s;
    }
    world->frozen_count = n;
    world->frozen_dead = 0;
    for (i = 0; i < world->thaw_body_count; ++i)
        world->thaw_mark[world->thaw_bodies[i]] = 0;
    world->thaw_body_count = 0;
    k = world->thaw_count;
    if (k == 0) return SX_OK;
    /* a mass may have changed while the contacts slept */
    for (i = 0; i < k; ++i) {
        sx_contact_prepare(world, &world->thaw[i]);
        if (world->thaw[i].restitution > SX_R(0.0)) world->bouncy_contacts++;
    }
    /* (key, part_a, part_b) is unique: the order is total, the same on every run */
    qsort(world->thaw, (size_t)k, sizeof(sx_contact), sx_contact_key_cmp);
    p = world->contacts;
    s = sx_reserve_array(&p, &world->contact_capacity, world->contact_count + k,
                         sizeof(sx_contact));
    world->contacts = (sx_contact *)p;
    if (s != SX_OK) return s;
    /* merge from the back */
    i = world->contact_count - 1;
    j = k - 1;
    out = world->contact_count + k - 1;
    while (j >= 0) {
        if (i >= 0 && world->contacts[i].key > world->thaw[j].key) {
            world->contacts[out--] = world->contacts[i--];
        } else {
            world->contacts[out--] = world->thaw[j--];
        }
    }
    world->contact_count += k;
    return SX_OK;
}

/* Appends the contact of manifold m (m->count >= 1) between part pa of
 * collider key >> 32 and part pb of collider key & 0xFFFFFFFF, matching the
 * warm-starting impulses against the pair's old contacts
 * old_contacts[old_begin, old_end) with the same parts. `held`: m came from
 * the old contact's kept manifold, whose levers, frames and masses then
 * stand (only the reported points and depths follow m), so the solver's
 * lane filled from it may stand too (sx_gather_items). */
static sx_status sx_add_contact(sx_world *world, uint64_t key, int pa, int pb, const sx_manifold *m,
                                int old_begin, int old_end, const sx_kept_manifold *kept,
                                bool held) {
    int ia = (int)(key >> 32), ib = (int)(key & 0xFFFFFFFFu), k;
    const sx_collider *ca = &world->colliders[ia], *cb = &world->colliders[ib];
    const sx_body_sim *ba = &world->sims[ca->body], *bb = &world->sims[cb->body];
    const sx_contact *old = NULL;
    sx_contact *c;
    sx_status s;
    for (k = old_begin; k < old_end; ++k) {
        if (world->old_contacts[k].part_a == pa && world->old_contacts[k].part_b == pb) {
            old = &world->old_contacts[k];
            break;
        }
    }
    /* an awake body touching a sleeping one wakes its island */
    if (!ba->awake) sx_wake_body(world, ca->body);
    if (!bb->awake) sx_wake_body(world, cb->body);
    s = sx_reserve_contact(world);
    if (s != SX_OK) return s;
    c = &world->contacts[world->contact_count++];
    c->key = key;
    c->collider_a = ia;
    c->collider_b = ib;
    c->part_a = pa;
    c->part_b = pb;
    c->body_a = ca->body;
    c->body_b = cb->body;
    c->normal = m->normal;
    c->friction = sx_sqrt(ca->friction * cb->friction);
    c->restitution = sx_maxr(ca->restitution, cb->restitution);
    c->count = m->count;
    /* (the held normal and anchors are world vectors of the search: A may
     * not have turned since by more than the keep angle, as B may not
     * relative to A) */
    c->held = held && old != NULL && old->count == m->count &&
              sx_dot(m->normal, old->normal) > SX_R(0.0) &&
              sx_absr(sx_cross(m->normal, old->normal)) * world->def.length_units_per_meter <=
                  world->def.manifold_keep_slops * world->linear_slop;
    if (c->held) {
        c->normal = old->normal;
        c->block = old->block;
        c->block_solve = old->block_solve;
        for (k = 0; k < m->count; ++k) {
            sx_contact_point *p = &c->points[k];
            *p = old->points[k];
            p->point = m->points[k].point;
            p->separation = -m->points[k].depth;
            p->gap = p->separation;
            p->impact_impulse = SX_R(0.0);
        }
    }
    for (k = 0; k < m->count && !c->held; ++k) {
        const sx_manifold_point *mp = &m->points[k];
        sx_contact_point *p = &c->points[k];
        sx_vec2 d;
        memset(p, 0, sizeof(*p));
        p->point = mp->point;
        /* each body's lever reaches its own surface point (depth apart
         * along the normal): with a speculative gap of a whole step's
         * approach, the midway point put the lever of a ball off by half the
         * gap and its friction at impact with it */
        p->anchor_a = sx_sub(sx_mul_add(mp->point, SX_R(0.5) * mp->depth, m->normal), ba->center);
        p->anchor_b = sx_sub(sx_mul_sub(mp->point, SX_R(0.5) * mp->depth, m->normal), bb->center);
        p->rel_a = sx_inv_rotate(ba->xf.q, p->anchor_a);
        p->rel_b = sx_inv_rotate(bb->xf.q, p->anchor_b);
        p->separation = -mp->depth;
        d = sx_add(sx_sub(bb->center, ba->center), sx_sub(p->anchor_b, p->anchor_a));
        p->base = p->separation - sx_dot(d, m->normal);
        p->gap = p->separation;
        p->id = mp->id;
        sx_match_point(p, old);
    }
    if (kept != NULL)
        c->kept = *kept;
    else
        c->kept.valid = false;
    sx_drop_tangent_impulses(c);
    if (!c->held) sx_contact_prepare(world, c);
    if (c->restitution > SX_R(0.0)) world->bouncy_contacts++;
    return SX_OK;
}

/* The speculative margin of the pair (ca, cb): the world's, plus how far
 * each collider reaches over the step. */
static sx_real sx_pair_margin(const sx_world *world, const sx_collider *ca,
                              const sx_collider *cb) {
    return world->margin + ca->reach + cb->reach;
}

/* The narrowphase of a pair in which at least one collider is a compound:
 * one manifold per part pair within the margin, in (part_a, part_b) order,
 * so each touching part pair is its own contact for the solver, with its
 * own feature ids and warm-starting impulses. Parts are culled first by
 * their bounds (fattened by half the margin, as the broadphase's; found once
 * with the collider's bounds, in its part_boxes). */
static sx_status sx_collide_parts(sx_world *world, uint64_t key, int old_begin, int old_end) {
    int ia = (int)(key >> 32), ib = (int)(key & 0xFFFFFFFFu), i, j;
    const sx_collider *ca = &world->colliders[ia], *cb = &world->colliders[ib];
    sx_xform xa = world->sims[ca->body].xf, xb = world->sims[cb->body].xf;
    sx_compound_part ta, tb;
    sx_compound va = sx_collider_compound(ca, &ta), vb = sx_collider_compound(cb, &tb);
    /* a plain collider's one part box is its own bounds */
    const sx_aabb *boxes_a = ca->part_count > 0 ? ca->part_boxes : &world->aabbs[ia];
    const sx_aabb *boxes_b = cb->part_count > 0 ? cb->part_boxes : &world->aabbs[ib];
    for (i = 0; i < va.count; ++i) {
        sx_xform xi;
        if (!sx_aabb_overlaps(boxes_a[i], world->aabbs[ib])) continue;
        xi = sx_xform_mul(xa, va.parts[i].offset);
        for (j = 0; j < vb.count; ++j) {
            sx_manifold m;
            sx_status s;
            if (!sx_aabb_overlaps(boxes_a[i], boxes_b[j])) continue;
            if (sx_collide_world(&va.parts[i].shape, xi, &vb.parts[j].shape,
                                 sx_xform_mul(xb, vb.parts[j].offset),
                                 sx_pair_margin(world, ca, cb), &m) <= 0) {
                continue;
            }
            s = sx_add_contact(world, key, i, j, &m, old_begin, old_end, NULL, false);
            if (s != SX_OK) return s;
        }
    }
    return SX_OK;
}

/* Whether a pair with a bullet may meet in the step: each collider stays
 * in a disc of its bound_radius about its body's centre of mass, which
 * moves straight at its collide-time velocity; the pair gets a contact only
 * if those discs come within the margin of each other over the step. The
 * whole travel's margin otherwise pairs every bullet of a volley with the
 * others flying beside it; the bullet's sweep (world_ccd.c) covers what
 * the straight motion does not. Other pairs, and a bullet against a static,
 * kinematic or sleeping collider, keep the whole margin. */
static bool sx_bullet_pair_may_meet(const sx_world *world, const sx_collider *ca,
                                    const sx_collider *cb) {
    const sx_body_sim *a = &world->sims[ca->body], *b = &world->sims[cb->body];
    if (world->bullet_count == 0 || !world->def.enable_continuous || !a->dynamic || !b->dynamic ||
        !a->awake || !b->awake ||
        !(world->infos[ca->body].bullet || world->infos[cb->body].bullet)) {
        return true;
    }
    return sx_paths_meet(a->center, sx_scale(a->v, world->step_dt), b->center,
                         sx_scale(b->v, world->step_dt),
                         ca->bound_radius + cb->bound_radius + world->margin);
}

/* What sx_pair_manifold answers besides a point count: a compound pair (one
 * manifold per part pair, sx_collide_parts), and in pair_counts a pair no
 * task range reached; a count with SX_PAIR_KEPT set came from the pair's
 * kept manifold. */
#define SX_PAIR_PARTS (-1)
#define SX_PAIR_NOT_FOUND (-2)
#define SX_PAIR_KEPT 0x100

/* Pair (xa, xb, margin)'s manifold from the kept manifold of its old
 * contact, while B has moved less than the keep tolerance relative to A
 * since it was found: its points follow B's half of the move, its depths
 * B's move along the normal. False when it moved farther, or turned, or a
 * one-point contact's margin grew past what it was found with by more than
 * the tolerance (a second point could have come within reach; two points
 * are all a manifold holds). */
static bool sx_kept_manifold_now(const sx_world *world, const sx_contact *old, sx_xform xa,
                                 sx_xform xb, sx_real margin, sx_manifold *m) {
    const sx_kept_manifold *k = &old->kept;
    sx_real tol = world->def.manifold_keep_slops * world->linear_slop;
    sx_xform rel;
    sx_rot turn;
    int j;
    if (!k->valid || !(tol > SX_R(0.0)) || (old->count < 2 && !(margin <= k->margin + tol)))
        return false;
    rel = sx_xform_inv_mul(xa, xb);
    /* a turn of B is held to the angle that moves a point a metre away as far */
    turn = sx_rot_inv_mul(k->rel.q, rel.q);
    if (!(turn.c > SX_R(0.0) && sx_absr(turn.s) * world->def.length_units_per_meter <= tol))
        return false;
    for (j = 0; j < old->count; ++j) {
        sx_vec2 b0 = sx_mul_sub(k->point[j], SX_R(0.5) * k->depth[j], k->normal);
        sx_vec2 d = sx_sub(sx_xform_point(rel, k->on_b[j]), b0);
        if (!(sx_dot(d, d) <= tol * tol)) return false;
        m->points[j].point = sx_xform_point(xa, sx_mul_add(k->point[j], SX_R(0.5), d));
        m->points[j].depth = k->depth[j] - sx_dot(d, k->normal);
        m->points[j].id = old->points[j].id;
    }
    m->normal = sx_rotate(xa.q, k->normal);
    m->count = old->count;
    return true;
}

/* Manifold m of pair (xa, xb), found with margin, as kept for later collides. */
static void sx_keep_manifold(sx_kept_manifold *k, const sx_manifold *m, sx_xform xa, sx_xform xb,
                             sx_real margin) {
    int j;
    k->rel = sx_xform_inv_mul(xa, xb);
    k->normal = sx_inv_rotate(xa.q, m->normal);
    for (j = 0; j < m->count; ++j) {
        const sx_manifold_point *p = &m->points[j];
        k->point[j] = sx_xform_inv_point(xa, p->point);
        k->depth[j] = p->depth;
        k->on_b[j] = sx_xform_inv_point(xb, sx_mul_sub(p->point, SX_R(0.5) * p->depth, m->normal));
    }
    k->margin = margin;
    k->valid = true;
}

/* The old contact whose kept manifold pair `key` may answer from: the
 * pair's one old contact, of a plain pair (NULL: none). */
static const sx_contact *sx_kept_candidate(const sx_world *world, int old_begin, int old_end) {
    if (old_end - old_begin != 1) return NULL;
    return world->old_contacts[old_begin].kept.valid ? &world->old_contacts[old_begin] : NULL;
}

/* The manifold of broadphase pair `key` (reads the world only): its point
 * count, 0 for a pair that gets no contact, or SX_PAIR_PARTS; with
 * SX_PAIR_KEPT set when old's kept manifold gave it. */
static int sx_pair_manifold(const sx_world *world, uint64_t key, const sx_contact *old,
                            sx_manifold *m) {
    int ia = (int)(key >> 32), ib = (int)(key & 0xFFFFFFFFu);
    const sx_collider *ca = &world->colliders[ia], *cb = &world->colliders[ib];
    sx_xform xa, xb;
    sx_real margin;
    if (ca->body == cb->body || !sx_filters_collide(&ca->filter, &cb->filter) ||
        !sx_bullet_pair_may_meet(world, ca, cb)) {
        return 0;
    }
    if (ca->part_count > 0 || cb->part_count > 0) return SX_PAIR_PARTS;
    xa = world->sims[ca->body].xf;
    xb = world->sims[cb->body].xf;
    margin = sx_pair_margin(world, ca, cb);
    if (old != NULL && old->body_a == ca->body && old->body_b == cb->body &&
        sx_kept_manifold_now(world, old, xa, xb, margin, m)) {
        return m->count | SX_PAIR_KEPT;
    }
    return sx_collide_world(&ca->shape, xa, &cb->shape, xb, margin, m);
}

/* The narrowphase of pair i of the broadphase (`key`): its contacts,
 * warm-started from its old ones old_contacts[old_begin, old_end); its
 * manifold from the parallel tasks when they found it. A manifold the
 * narrowphase found is kept with the contact; one from a kept manifold
 * passes that on unchanged (the tolerance holds from where it was found). */
static sx_status sx_collide_pair(sx_world *world, int i, uint64_t key, int old_begin,
                                 int old_end) {
    sx_manifold local;
    const sx_manifold *m = &local;
    const sx_contact *old = sx_kept_candidate(world, old_begin, old_end);
    sx_kept_manifold fresh;
    int n = world->pairs_found ? world->pair_counts[i] : SX_PAIR_NOT_FOUND;
    if (n == SX_PAIR_NOT_FOUND) {
        n = sx_pair_manifold(world, key, old, &local);
    } else if (n > 0) {
        m = &world->pair_manifolds[i];
    }
    if (n == SX_PAIR_PARTS) return sx_collide_parts(world, key, old_begin, old_end);
    if (n == 0) return SX_OK;
    /* (held unless a mass or centre of mass changed since the contacts
     * were last prepared: the collide then prepares every contact) */
    if ((n & SX_PAIR_KEPT) && old != NULL)
        return sx_add_contact(world, key, 0, 0, m, old_begin, old_end, &old->kept,
                              !world->masses_changed);
    {
        const sx_collider *ca = &world->colliders[key >> 32];
        const sx_collider *cb = &world->colliders[key & 0xFFFFFFFFu];
        sx_keep_manifold(&fresh, m, world->sims[ca->body].xf, world->sims[cb->body].xf,
                         sx_pair_margin(world, ca, cb));
    }
    return sx_add_contact(world, key, 0, 0, m, old_begin, old_end, &fresh, false);
}

/* A range of the broadphase's pairs for a worker of the job system. */
static void sx_pairs_task(int start, int end, int worker, void *context) {
    sx_world *world = (sx_world *)context;
    int i, at;
    (void)worker;
    if (start < 0) start = 0;
    if (end > world->bp.pair_count) end = world->bp.pair_count;
    /* the range's old contacts, walked beside its pairs as the collide's
     * walk does (both in key order): one search for the range */
    at = start < end ? sx_key_lower_bound(world->old_contacts, world->old_contact_count,
                                          world->bp.pairs[start])
                     : 0;
    for (i = start; i < end; ++i) {
        uint64_t key = world->bp.pairs[i];
        int from;
        while (at < world->old_contact_count && world->old_contacts[at].key < key)
            ++at;
        from = at;
        while (at < world->old_contact_count && world->old_contacts[at].key == key)
            ++at;
        world->pair_counts[i] = sx_pair_manifold(world, key, sx_kept_candidate(world, from, at),
                                                 &world->pair_manifolds[i]);
    }
}

/* Pairs a task range takes at least, and the fewest pairs worth a task:
 * below them the job system's hand-over costs more than the manifolds. */
#define SX_PAIRS_PER_RANGE 64
#define SX_PARALLEL_MIN_PAIRS 256

/* With a job system: every pair's manifold, in parallel, before the walk.
 * Without room for them the walk collides each pair itself, as it does a
 * pair no range reached (SX_PAIR_NOT_FOUND). */
static void sx_find_pairs(sx_world *world) {
    const sx_world_def *d = &world->def;
    int n = world->bp.pair_count, i;
    void *p, *task;
    world->pairs_found = false;
    if (d->enqueue_task == NULL || d->worker_count < 2 || n < SX_PARALLEL_MIN_PAIRS) return;
    p = world->pair_manifolds;
    if (!sx_grow_array(&p, &world->pair_manifold_capacity, n, sizeof(sx_manifold))) return;
    world->pair_manifolds = (sx_manifold *)p;
    p = world->pair_counts;
    if (!sx_grow_array(&p, &world->pair_count_capacity, n, sizeof(int))) return;
    world->pair_counts = (int *)p;
    for (i = 0; i < n; ++i)
        world->pair_counts[i] = SX_PAIR_NOT_FOUND;
    task = d->enqueue_task(sx_pairs_task, n, SX_PAIRS_PER_RANGE, world, d->user_task_context);
    if (task != NULL) d->finish_task(task, d->user_task_context);
    world->pairs_found = true;
}

sx_status sx_world_collide(sx_world *world) {
    sx_contact *swap;
    int i, old_index = 0, cap;
    sx_status s;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    /* the lists move from here on: the per-body chains go, and the
     * solver's fill with them (the impulses warm-start from the contacts) */
    sx_solver_hand_back(world);
    sx_world_purge_contacts(world);
    world->by_body_valid = false;
    world->contact_serial++;
    world->collides++;

    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    s = sx_ccd_record(world);
    if (s != SX_OK) return s;
    /* the bounds of the colliders the step moves (and their bodies' poses
     * for the continuous stage) */
    world->ccd_recording = world->ccd_dt > SX_R(0.0);
    for (i = 0; i < world->active_collider_count; ++i)
        sx_collider_bounds(world, world->active_colliders[i]);
    world->ccd_recording = false;
    s = sx_broadphase_update(&world->bp, world->aabbs, world->bp_kind, world->collider_slots,
                             world->active_colliders, world->active_collider_count,
                             SX_FAT_SLOPS * world->linear_slop);
    if (s != SX_OK) return s;

    /* Contacts of sleeping bodies leave the list for the frozen store (the
     * pile keeps its contacts, reports no end events, and warm-starts when it
     * wakes); those of bodies woken since the last collide come back. */
    if (world->thaw_pending || world->frozen_dead > 0) {
        s = sx_thaw_contacts(world);
        if (s != SX_OK) return s;
    }
    s = sx_freeze_contacts(world);
    if (s != SX_OK) return s;

    swap = world->old_contacts;
    world->old_contacts = world->contacts;
    world->contacts = swap;
    cap = world->old_contact_capacity;
    world->old_contact_capacity = world->contact_capacity;
    world->contact_capacity = cap;
    world->old_contact_count = world->contact_count;
    world->contact_count = 0;
    /* counted as the contacts are made and thawed */
    world->bouncy_contacts = 0;
    /* the tasks read the old contacts' kept manifolds */
    sx_find_pairs(world);
    /* the pairs in key order, the old contacts (sorted by key) beside them:
     * a pair's old contacts warm-start its new ones, and the begin and end
     * events fall out of the comparison */
    for (i = 0; i < world->bp.pair_count; ++i) {
        uint64_t key = world->bp.pairs[i];
        int first = world->contact_count, old_begin;
        s = sx_end_old_pairs(world, &old_index, key);
        if (s != SX_OK) return s;
        /* the old contacts of this pair: one, or one per part pair */
        old_begin = old_index;
        while (old_index < world->old_contact_count && world->old_contacts[old_index].key == key)
            ++old_index;
        s = sx_collide_pair(world, i, key, old_begin, old_index);
        if (s != SX_OK) return s;
        s = sx_pair_events(world, first, old_begin, old_index);
        if (s != SX_OK) return s;
    }
    s = sx_end_old_pairs(world, &old_index, UINT64_MAX);
    if (s != SX_OK) return s;
    /* an awake body touching a sleeping island woke it: its contacts join
     * this step as they are (no begin event: they touched all along) */
    if (world->thaw_pending) {
        s = sx_thaw_contacts(world);
        if (s != SX_OK) return s;
    }
    sx_contacts_prepared(world);
    return sx_sensors_update(world);
}

int sx_world_contact_count(const sx_world *world) {
    if (world == NULL) return 0;
    return world->contact_count + world->frozen_count - world->contact_dead - world->frozen_dead;
}

sx_status sx_world_get_contact(const sx_world *world, int index, sx_contact_data *out) {
    const sx_contact *c;
    sx_contact_event handles;
    sx_real lane_normal[2], lane_tangent[2];
    bool lanes;
    int k;
    if (world == NULL || out == NULL || index < 0 || index >= sx_world_contact_count(world)) {
        return SX_ERR_INVALID_ARG;
    }
    /* the step's contacts first, then those of sleeping bodies */
    c = sx_world_live_contact(world, index);
    /* between two sub-steps of a step run by its stages, a wide lane may
     * hold the impulses (sx_world_solve) */
    lanes = index < world->contact_count &&
            sx_solver_lane_impulses(world, index, lane_normal, lane_tangent);
    memset(out, 0, sizeof(*out));
    handles = sx_contact_handles(world, c);
    out->collider_a = handles.collider_a;
    out->collider_b = handles.collider_b;
    out->body_a = handles.body_a;
    out->body_b = handles.body_b;
    out->part_a = c->part_a;
    out->part_b = c->part_b;
    out->normal = c->normal;
    out->count = c->count;
    for (k = 0; k < c->count; ++k) {
        out->points[k] = c->points[k].point;
        out->depths[k] = -c->points[k].separation;
        out->normal_impulses[k] = lanes ? lane_normal[k] : c->points[k].normal_impulse;
        out->tangent_impulses[k] = lanes ? lane_tangent[k] : c->points[k].tangent_impulse;
        out->impact_impulses[k] = c->points[k].impact_impulse;
    }
    return SX_OK;
}

int sx_world_get_contact_pairs(const sx_world *world, int first, sx_contact_pair *out,
                               int capacity) {
    int total, p, skip, n = 0;
    bool dense;
    if (world == NULL || out == NULL || capacity < 1 || first < 0 ||
        first >= sx_world_contact_count(world)) {
        return 0;
    }
    /* the live list as sx_world_live_contact numbers it, walked once: the
     * step's contacts, then the frozen ones, tombstones (count 0) skipped */
    total = world->contact_count + world->frozen_count;
    dense = world->contact_dead + world->frozen_dead == 0;
    p = dense ? first : 0;
    skip = dense ? 0 : first;
    for (; p < total && n < capacity; ++p) {
        const sx_contact *c = p < world->contact_count ? &world->contacts[p]
                                                       : &world->frozen[p - world->contact_count];
        sx_contact_pair *o = &out[n];
        sx_contact_event handles;
        if (c->count == 0) continue;
        if (skip > 0) {
            --skip;
            continue;
        }
        handles = sx_contact_handles(world, c);
        o->collider_a = handles.collider_a;
        o->collider_b = handles.collider_b;
        o->body_a = handles.body_a;
        o->body_b = handles.body_b;
        o->part_a = c->part_a;
        o->part_b = c->part_b;
        o->normal = c->normal;
        o->count = c->count;
        o->points[0] = c->points[0].point;
        o->points[1] = c->count > 1 ? c->points[1].point : sx_v2_zero();
        ++n;
    }
    return n;
}

/* ---- stage 3: solve ------------------------------------------------------ */

/* The sub-steps of h the step sx_world_begin_step began has (1 without a
 * sensible ratio). */
static int sx_step_sub_steps(const sx_world *world, sx_real h) {
    sx_real r = world->step_dt / h;
    return r >= SX_R(1.0) && r <= (sx_real)SX_MAX_SUB_STEPS ? (int)(r + SX_R(0.5)) : 1;
}

sx_status sx_world_solve(sx_world *world, sx_real h) {
    sx_status s = sx_check_step(world, h);
    bool warmed, impacts, solved;
    if (s != SX_OK) return s;
    /* the impact pass works on the active bodies */
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    sx_world_purge_contacts(world);
    sx_refresh_effective_masses(world);
    sx_limit_speeds_unless_met(world, h);
    /* the gather warm-starts the solver's copies only: restitution first,
     * impact by impact in time order, on the bodies' own velocities
     * (contact_solver.c says why); then the warm start and the passes solve
     * what rests and slides */
    /* the impulses reach the contacts at the step's last sub-step (and
     * whenever something reads them there before: sx_solver_hand_back);
     * the ones between are read by nothing but the next sub-step's solve */
    world->hand_back_later = ++world->step_solves < sx_step_sub_steps(world, h);
    warmed = sx_contacts_gather(world);
    impacts = sx_contacts_impacts(world, h);
    solved = sx_contacts_solve(world, h, world->def.velocity_iterations);
    world->hand_back_later = false;
    if (solved) sx_contacts_energy_guard(world, h);
    /* what the impulses did stays within the limit too: the solver's store
     * limited the bodies it changed, and the guard's blend of two limited
     * velocities is limited; the impacts' bodies (a rare pass) are walked */
    if (world->impact_shifts_pending)
        sx_limit_speeds(world, h);
    else
        world->limited_h = sx_minr(world->limited_h, h);
    return warmed && impacts && solved ? SX_OK : SX_ERR_NO_MEMORY;
}

/* ---- stage 4: integrate -------------------------------------------------- */

sx_status sx_world_integrate(sx_world *world, sx_real h) {
    sx_status s = sx_check_step(world, h);
    sx_half_limit l;
    int i;
    if (s != SX_OK) return s;
    l = sx_half_limit_of(h);
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    world->lane_gaps_current = false;
    for (i = 0; i < world->active_body_count; ++i) {
        sx_body_sim *b = &world->sims[world->active_bodies[i]];
        if (!b->moving || !b->awake) continue;
        sx_limit_speed_past_half(b, &l); /* what the solver added, too */
        b->center = sx_mul_add(b->center, h, b->v);
        if (b->w != SX_R(0.0)) b->xf.q = sx_rot_integrate(b->xf.q, h * b->w);
        sx_body_sync_origin(b);
    }
    /* the time-of-impact corrections of this sub-step's impacts */
    sx_contacts_apply_impact_shifts(world);
    world->ccd_h = h; /* continuous collision pays the integrator's energy with it */
    return SX_OK;
}

/* ---- stage 5: separate --------------------------------------------------- */

sx_status sx_world_separate(sx_world *world, sx_real h) {
    sx_status s = sx_check_step(world, h);
    bool relaxed;
    if (s != SX_OK) return s;
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    sx_world_purge_contacts(world);
    sx_refresh_effective_masses(world);
    relaxed = sx_contacts_relax(world, h, world->def.position_iterations);
    /* soft contacts relax velocities; the rigid position pass moves bodies only */
    if (world->def.contact_hertz > SX_R(0.0)) world->limited_h = SX_R(0.0);
    sx_limit_speeds_unless_met(world, h);
    return relaxed ? SX_OK : SX_ERR_NO_MEMORY;
}

/* ---- the step ------------------------------------------------------------- */

sx_status sx_world_step(sx_world *world, sx_real dt) {
    sx_status s = sx_check_step(world, dt);
    sx_real h;
    int i, steps;
    if (s != SX_OK) return s;
    steps = world->def.sub_steps;
    h = dt / (sx_real)steps;
    if (!(h > SX_R(0.0))) {
        /* dt among the few smallest denormals: its sub-step rounds to 0,
         * which every stage refuses; one sub-step of dt instead */
        h = dt;
        steps = 1;
    }
    sx_world_begin_step(world, dt);
    s = sx_world_collide(world);
    if (s != SX_OK) return s;
    for (i = 0; i < steps; ++i) {
        sx_world_apply_forces(world, h);
        s = sx_world_solve(world, h);
        if (s != SX_OK) {
            sx_solver_hand_back(world);
            return s;
        }
        sx_world_integrate(world, h);
        sx_world_separate(world, h);
    }
    s = sx_world_continuous(world);
    if (s != SX_OK) return s;
    sx_world_clear_forces(world);
    return sx_world_update_sleep(world, dt);
}
