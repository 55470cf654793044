/* sepax — bodies and colliders: creation and destruction through handles,
 * mass properties from the colliders' densities, getters and setters, and the
 * force and impulse accumulators.
 *
 * A handle is a slot index plus the generation the slot had when the object
 * was made. Destroying an object bumps its slot's generation, so every old
 * handle stops matching and is answered with SX_ERR_STALE_HANDLE; the slot
 * goes on a free list and is reused, until its generation reaches
 * UINT32_MAX: then it is retired, since one more would wrap. Generations
 * start at 1, so the all-zero handle is never live. Input is validated here,
 * once; the step trusts it. */
#include <string.h>

#include "world_array.h"
#include "world_body.h"
#include "world_broadphase.h"
#include "world_ccd.h"
#include "world_contact.h"
#include "world_internal.h"
#include "world_island.h"
#include "world_sensor.h"

/* ---- handles ------------------------------------------------------------ */

uint64_t sx_body_id_to_u64(sx_body_id id) {
    return ((uint64_t)id.generation << 32) | (uint64_t)id.index;
}

sx_body_id sx_body_id_from_u64(uint64_t bits) {
    sx_body_id id;
    id.index = (uint32_t)(bits & 0xFFFFFFFFu);
    id.generation = (uint32_t)(bits >> 32);
    return id;
}

bool sx_body_id_is_null(sx_body_id id) { return id.index == 0 && id.generation == 0; }

uint64_t sx_collider_id_to_u64(sx_collider_id id) {
    return ((uint64_t)id.generation << 32) | (uint64_t)id.index;
}

sx_collider_id sx_collider_id_from_u64(uint64_t bits) {
    sx_collider_id id;
    id.index = (uint32_t)(bits & 0xFFFFFFFFu);
    id.generation = (uint32_t)(bits >> 32);
    return id;
}

/* The slot of a live body, or -1. */
int sx_body_slot(const sx_world *world, sx_body_id id) {
    const sx_body_info *info;
    if (world == NULL || id.generation == 0 || id.index >= (uint32_t)world->body_slots) return -1;
    info = &world->infos[id.index];
    if (!info->alive || info->generation != id.generation) return -1;
    return (int)id.index;
}

int sx_body_slot_checked(const sx_world *world, sx_body_id id, sx_status *status) {
    int slot;
    if (world == NULL) {
        *status = SX_ERR_INVALID_ARG;
        return -1;
    }
    slot = sx_body_slot(world, id);
    *status = slot < 0 ? SX_ERR_STALE_HANDLE : SX_OK;
    return slot;
}

int sx_collider_slot(const sx_world *world, sx_collider_id id) {
    const sx_collider *c;
    if (world == NULL || id.generation == 0 || id.index >= (uint32_t)world->collider_slots) {
        return -1;
    }
    c = &world->colliders[id.index];
    if (!c->alive || world->collider_generations[id.index] != id.generation) return -1;
    return (int)id.index;
}

bool sx_body_is_valid(const sx_world *world, sx_body_id body) {
    return sx_body_slot(world, body) >= 0;
}

bool sx_collider_is_valid(const sx_world *world, sx_collider_id collider) {
    return sx_collider_slot(world, collider) >= 0;
}

sx_body_id sx_collider_get_body(const sx_world *world, sx_collider_id collider) {
    sx_body_id id = {0, 0};
    int slot = sx_collider_slot(world, collider);
    if (slot < 0) return id;
    id.index = (uint32_t)world->colliders[slot].body;
    id.generation = world->infos[id.index].generation;
    return id;
}

/* ---- defaults ----------------------------------------------------------- */

sx_body_def sx_default_body_def(void) {
    sx_body_def d;
    d.type = SX_BODY_STATIC;
    d.position = sx_v2_zero();
    d.angle = SX_R(0.0);
    d.linear_velocity = sx_v2_zero();
    d.angular_velocity = SX_R(0.0);
    d.linear_damping = SX_R(0.0);
    d.angular_damping = SX_R(0.0);
    d.gravity_scale = SX_R(1.0);
    d.fixed_rotation = false;
    d.enable_sleep = true;
    d.enabled = true;
    d.bullet = false;
    d.user_data = NULL;
    return d;
}

sx_collider_def sx_default_collider_def(void) {
    sx_collider_def d;
    d.shape = sx_circle_shape(sx_v2_zero(), SX_R(0.5));
    d.density = SX_R(1.0);
    d.friction = SX_R(0.6);
    d.restitution = SX_R(0.0);
    d.filter.category = 1u;
    d.filter.mask = 0xFFFFFFFFu;
    d.filter.group = 0;
    d.sensor = false;
    d.user_data = NULL;
    return d;
}

/* ---- the speed limit ---------------------------------------------------- */

/* Keeps a body within the speed limit of a sub-step of length h (world.h,
 * SX_MAX_ROTATION): it turns at most SX_MAX_ROTATION and moves at most
 * SX_HUGE. A faster velocity keeps its direction and is scaled down to the
 * limit; so does an infinite one (a finite torque on a tiny inertia, or a
 * huge h, overflows); a NaN velocity (never expected) becomes 0. Far above
 * any physical speed, so ordinary scenes never meet it. */
void sx_body_limit_speed(sx_body_sim *b, sx_real h) {
    sx_real wmax = sx_minr(SX_MAX_ROTATION / h, SX_REAL_MAX);
    sx_real vmax = sx_minr(SX_HUGE / h, SX_REAL_MAX);
    sx_real m = sx_maxr(sx_absr(b->v.x), sx_absr(b->v.y));
    if (!(sx_absr(b->w) <= wmax)) {
        b->w = b->w > SX_R(0.0) ? wmax : (b->w < SX_R(0.0) ? -wmax : SX_R(0.0));
    }
    if (!(m <= vmax) || b->v.x != b->v.x || b->v.y != b->v.y) {
        /* the direction, from the components scaled by the largest (or from
         * the infinite ones alone), then the limit along it */
        sx_vec2 d;
        sx_real len;
        if (sx_is_finite(m)) {
            d = sx_v2(b->v.x / m, b->v.y / m);
        } else {
            d = sx_v2(sx_is_finite(b->v.x) ? SX_R(0.0) : b->v.x,
                      sx_is_finite(b->v.y) ? SX_R(0.0) : b->v.y);
            d = sx_v2(d.x > SX_R(0.0) ? SX_R(1.0) : (d.x < SX_R(0.0) ? SX_R(-1.0) : SX_R(0.0)),
                      d.y > SX_R(0.0) ? SX_R(1.0) : (d.y < SX_R(0.0) ? SX_R(-1.0) : SX_R(0.0)));
        }
        len = sx_length(d);
        b->v = len > SX_R(0.0) ? sx_scale(d, vmax / len) : sx_v2_zero();
    } else if (m > SX_R(0.5) * vmax) {
        /* within the limit per component, maybe not in length */
        sx_vec2 d = sx_v2(b->v.x / m, b->v.y / m);
        sx_real len = sx_length(d);
        if (m > vmax / len) b->v = sx_scale(d, vmax / len);
    }
}

/* ---- mass --------------------------------------------------------------- */

/* Sets the flags and inverse masses that the stages read from the type,
 * enabled state and mass. */
static void sx_body_refresh_sim(sx_world *world, int slot) {
    sx_body_sim *sim = &world->sims[slot];
    const sx_body_info *info = &world->infos[slot];
    sx_real old_inv_mass = sim->inv_mass, old_inv_inertia = sim->inv_inertia;
    world->sets_dirty = true;
    sx_world_solver_changed(world);
    sim->dynamic = info->enabled && info->type == SX_BODY_DYNAMIC;
    sim->moving = info->enabled && info->type != SX_BODY_STATIC;
    if (sim->dynamic) {
        sim->inv_mass = SX_R(1.0) / info->mass;
        sim->inv_inertia = info->inertia > SX_R(0.0) ? SX_R(1.0) / info->inertia : SX_R(0.0);
    } else {
        sim->inv_mass = SX_R(0.0);
        sim->inv_inertia = SX_R(0.0);
    }
    if (sim->inv_mass != old_inv_mass || sim->inv_inertia != old_inv_inertia)
        world->masses_changed = true;
    if (!sim->moving) {
        sim->v = sx_v2_zero();
        sim->w = SX_R(0.0);
    }
    if (info->fixed_rotation && sim->dynamic) sim->w = SX_R(0.0);
}

void sx_body_update_mass(sx_world *world, int slot) {
    sx_body_info *info = &world->infos[slot];
    sx_body_sim *sim = &world->sims[slot];
    sx_real mass = SX_R(0.0), inertia = SX_R(0.0);
    sx_vec2 weighted = sx_v2_zero(), lc = sx_v2_zero();
    int c;
    sx_ccd_forget(world, slot);
    if (info->type == SX_BODY_DYNAMIC) {
        for (c = info->first_collider; c >= 0; c = world->colliders[c].next) {
            const sx_collider *col = &world->colliders[c];
            sx_mass_data md;
            if (col->density == SX_R(0.0)) continue;
            if (col->part_count > 0) {
                sx_compound view;
                view.parts = col->parts;
                view.count = col->part_count;
                /* area-weighted centroid, parallel-axis inertia of the parts */
                md = sx_compound_mass(&view, col->density);
            } else {
                md = sx_shape_mass(&col->shape, col->density);
            }
            mass += md.mass;
            weighted = sx_mul_add(weighted, md.mass, md.center);
            /* parallel-axis theorem: inertia about the body origin first */
            inertia += md.rotational_inertia + md.mass * sx_length_sq(md.center);
        }
        if (mass > SX_R(0.0) && sx_is_finite(SX_R(1.0) / mass)) {
            lc = sx_scale(weighted, SX_R(1.0) / mass);
            inertia -= mass * sx_length_sq(lc);
            if (inertia < SX_R(0.0)) inertia = SX_R(0.0);
        } else {
            /* a dynamic body must respond to forces: give it a unit mass,
             * and no rotation since it has no extent to spin (also when the
             * mass is so small that 1 / mass overflows: a valid shape of
             * area 1e-39, or 1e-35 m^2 at density 1e-5) */
            mass = SX_R(1.0);
            inertia = SX_R(0.0);
        }
        if (!sx_is_finite(mass) || !sx_is_finite(inertia) || !sx_vec2_is_finite(lc)) {
            /* shapes far beyond SX_HUGE: the sums overflowed (inf / inf
             * would make the centre NaN). The body becomes as heavy as a
             * real can say, with no rotation and its centre at its origin. */
            mass = SX_REAL_MAX;
            inertia = SX_R(0.0);
            lc = sx_v2_zero();
        }
        /* an inertia so small that 1 / inertia overflows (a needle of a
         * shape) would give an infinite inverse and inf x 0 = NaN in the
         * step: such a body does not rotate */
        if (inertia > SX_R(0.0) && !sx_is_finite(SX_R(1.0) / inertia)) inertia = SX_R(0.0);
        if (info->fixed_rotation) inertia = SX_R(0.0);
    }
    info->mass = mass;
    info->inertia = inertia;
    /* keep the body origin where it is; move the centre of mass (the
     * contacts' anchors reach from it: prepared again, like a new mass) */
    if (lc.x != sim->local_center.x || lc.y != sim->local_center.y) world->masses_changed = true;
    sim->local_center = lc;
    sim->center = sx_xform_point(sim->xf, lc);
    sx_body_refresh_sim(world, slot);
}

/* ---- creation and destruction ------------------------------------------ */

/* Grows both body arrays; each keeps its own capacity so a failure half way
 * leaves both consistent. */
static bool sx_reserve_bodies(sx_world *world, int need) {
    void *sims = world->sims, *infos = world->infos;
    bool ok = sx_grow_array(&sims, &world->sim_capacity, need, sizeof(sx_body_sim));
    world->sims = (sx_body_sim *)sims;
    if (!ok) return false;
    ok = sx_grow_array(&infos, &world->info_capacity, need, sizeof(sx_body_info));
    world->infos = (sx_body_info *)infos;
    return ok;
}

sx_status sx_create_body(sx_world *world, const sx_body_def *def, sx_body_id *out) {
    int slot;
    sx_body_sim *sim;
    sx_body_info *info;
    uint32_t generation;
    if (out != NULL) {
        out->index = 0;
        out->generation = 0;
    }
    if (world == NULL || def == NULL || out == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    if (def->type != SX_BODY_STATIC && def->type != SX_BODY_KINEMATIC &&
        def->type != SX_BODY_DYNAMIC) {
        return SX_ERR_INVALID_ARG;
    }
    if (!sx_vec2_is_finite(def->position) || !sx_is_finite(def->angle) ||
        !sx_vec2_is_finite(def->linear_velocity) || !sx_is_finite(def->angular_velocity) ||
        !sx_is_finite(def->linear_damping) || !sx_is_finite(def->angular_damping) ||
        !sx_is_finite(def->gravity_scale)) {
        return SX_ERR_NONFINITE;
    }
    if (def->linear_damping < SX_R(0.0) || def->angular_damping < SX_R(0.0)) {
        return SX_ERR_INVALID_ARG;
    }
    if (world->body_free >= 0) {
        slot = world->body_free;
        world->body_free = world->infos[slot].next_free;
        generation = world->infos[slot].generation;
    } else {
        if (world->body_slots >= SX_WORLD_MAX_ITEMS) return SX_ERR_CAPACITY;
        if (!sx_reserve_bodies(world, world->body_slots + 1)) return SX_ERR_NO_MEMORY;
        slot = world->body_slots++;
        generation = 1;
    }
    sim = &world->sims[slot];
    info = &world->infos[slot];
    memset(sim, 0, sizeof(*sim));
    memset(info, 0, sizeof(*info));
    /* a reused slot must not inherit an impact correction still pending */
    if (slot < world->impact_body_capacity) {
        memset(&world->impact_bodies[slot], 0, sizeof(world->impact_bodies[slot]));
    }
    /* nor the energy credit of the body that had the slot (its destroy
     * ended the groups linked with it) */
    if (slot < world->group_body_capacity) {
        memset(&world->group_bodies[slot], 0, sizeof(world->group_bodies[slot]));
    }
    info->generation = generation;
    info->alive = true;
    info->enabled = def->enabled;
    info->fixed_rotation = def->fixed_rotation;
    info->enable_sleep = def->enable_sleep;
    info->bullet = def->bullet;
    world->bullet_count += def->bullet ? 1 : 0;
    info->type = def->type;
    info->user_data = def->user_data;
    info->first_collider = -1;
    info->next_free = -1;
    info->island = -1;
    info->island_next = -1;
    info->sleep_time = SX_R(0.0);
    sim->awake = true;
    sim->xf = sx_xform_make(def->position, def->angle);
    sim->center = sim->xf.p;
    sim->local_center = sx_v2_zero();
    sim->v = def->linear_velocity;
    sim->w = def->angular_velocity;
    world->limited_h = SX_R(0.0);
    sim->force = sx_v2_zero();
    sim->impulse = sx_v2_zero();
    sim->linear_damping = def->linear_damping;
    sim->angular_damping = def->angular_damping;
    sim->gravity_scale = def->gravity_scale;
    sx_body_update_mass(world, slot);
    world->body_count++;
    out->index = (uint32_t)slot;
    out->generation = generation;
    return SX_OK;
}

/* Moves a dead slot to its next generation and returns true, or returns
 * false when the slot has handed out its last one (UINT32_MAX): going on
 * would wrap to 1 and revalidate the slot's first handle, so the slot is
 * retired instead (never put on the free list; stale handles of it stay
 * stale for good). A world loses a slot per 2^32 - 1 reuses of it. */
static bool sx_generation_next(uint32_t *generation) {
    if (*generation == UINT32_MAX) return false;
    ++*generation;
    return true;
}

/* Unlinks nothing: frees the collider slot (the caller fixes the list). */
static void sx_free_collider_slot(sx_world *world, int slot) {
    sx_collider *c = &world->colliders[slot];
    sx_world_remove_contacts_of(world, slot);
    sx_sensors_remove_collider(world, slot);
    if (c->parts != NULL) {
        sx_free(c->parts, (size_t)c->part_count * sizeof(sx_compound_part));
        sx_free(c->part_boxes, (size_t)c->part_count * sizeof(sx_aabb));
        c->parts = NULL;
        c->part_boxes = NULL;
        c->part_count = 0;
    }
    c->alive = false;
    c->next_free = -1;
    if (sx_generation_next(&world->collider_generations[slot])) {
        c->next_free = world->collider_free;
        world->collider_free = slot;
    }
    /* bp_kind keeps the old kind: the next refresh of the sets sees the
     * change and takes the collider out of the broadphase */
    world->sets_dirty = true;
}

sx_status sx_destroy_body(sx_world *world, sx_body_id body) {
    int slot, c, next;
    sx_body_info *info;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    slot = sx_body_slot(world, body);
    if (slot < 0) return SX_ERR_STALE_HANDLE;
    info = &world->infos[slot];
    /* what rested on it must be able to fall */
    sx_wake_body(world, slot);
    for (c = info->first_collider; c >= 0; c = next) {
        next = world->colliders[c].next;
        sx_free_collider_slot(world, c);
    }
    info->first_collider = -1;
    info->alive = false;
    /* the energy guard's groups name its slot: linked again at the next
     * collide, whatever its contacts look like then */
    world->groups_linked = false;
    world->bullet_count -= info->bullet ? 1 : 0;
    world->sets_dirty = true;
    info->next_free = -1;
    if (sx_generation_next(&info->generation)) {
        info->next_free = world->body_free;
        world->body_free = slot;
    }
    world->body_count--;
    return SX_OK;
}

/* Validates the material fields of a collider def (all but the shape). */
static sx_status sx_check_material(const sx_collider_def *def) {
    if (!sx_is_finite(def->density) || !sx_is_finite(def->friction) ||
        !sx_is_finite(def->restitution)) {
        return SX_ERR_NONFINITE;
    }
    if (def->density < SX_R(0.0) || def->friction < SX_R(0.0) || def->restitution < SX_R(0.0)) {
        return SX_ERR_INVALID_ARG;
    }
    return SX_OK;
}

/* The box lies within SX_HUGE of the body origin in every coordinate (false
 * for NaN). Colliders reaching farther are refused: the narrowphase promises
 * precision only within SX_HUGE, and beyond it its answers (depths of 1e22
 * for a segment of extent 1e30) would feed the solver garbage. */
static bool sx_box_within_huge(sx_aabb b) {
    return b.lower.x >= -SX_HUGE && b.lower.y >= -SX_HUGE && b.upper.x <= SX_HUGE &&
           b.upper.y <= SX_HUGE;
}

/* Validates a collider def: the status sx_body_add_collider returns. */
static sx_status sx_check_collider_def(const sx_collider_def *def) {
    sx_status s = sx_shape_validate(&def->shape);
    if (s != SX_OK) return s;
    s = sx_check_material(def);
    if (s != SX_OK) return s;
    if (!sx_box_within_huge(sx_shape_aabb(&def->shape, sx_xform_identity()))) {
        return SX_ERR_INVALID_ARG;
    }
    return SX_OK;
}

/* Grows the three per-collider arrays, each with its own capacity. */
static bool sx_reserve_colliders(sx_world *world, int need) {
    void *c = world->colliders, *a = world->aabbs, *k = world->bp_kind;
    void *g = world->collider_generations;
    bool ok = sx_grow_array(&c, &world->collider_capacity, need, sizeof(sx_collider));
    world->colliders = (sx_collider *)c;
    if (!ok) return false;
    ok = sx_grow_array(&a, &world->aabb_capacity, need, sizeof(sx_aabb));
    world->aabbs = (sx_aabb *)a;
    if (!ok) return false;
    ok = sx_grow_array(&k, &world->kind_capacity, need, sizeof(unsigned char));
    world->bp_kind = (unsigned char *)k;
    if (!ok) return false;
    ok = sx_grow_array(&g, &world->generation_capacity, need, sizeof(uint32_t));
    world->collider_generations = (uint32_t *)g;
    return ok;
}

/* Takes a collider slot for a checked def on body slot bslot. `parts` (NULL
 * for a plain collider) is an sx_alloc'ed array of part_count parts that the
 * collider takes over; on error it is freed here. */
static sx_status sx_attach_collider(sx_world *world, int bslot, const sx_collider_def *def,
                                    sx_compound_part *parts, int part_count, sx_collider_id *out) {
    int slot, *link;
    sx_collider *c;
    uint32_t generation;
    sx_aabb *boxes = NULL;
    if (parts != NULL) {
        boxes = (sx_aabb *)sx_alloc((size_t)part_count * sizeof(sx_aabb));
        if (boxes == NULL) {
            sx_free(parts, (size_t)part_count * sizeof(sx_compound_part));
            return SX_ERR_NO_MEMORY;
        }
    }
    if (world->collider_free >= 0) {
        slot = world->collider_free;
        world->collider_free = world->colliders[slot].next_free;
        generation = world->collider_generations[slot];
    } else {
        sx_status fail = SX_OK;
        if (world->collider_slots >= SX_WORLD_MAX_ITEMS) {
            fail = SX_ERR_CAPACITY;
        } else if (!sx_reserve_colliders(world, world->collider_slots + 1)) {
            fail = SX_ERR_NO_MEMORY;
        }
        if (fail != SX_OK) {
            sx_free(parts, (size_t)part_count * sizeof(sx_compound_part));
            sx_free(boxes, (size_t)part_count * sizeof(sx_aabb));
            return fail;
        }
        slot = world->collider_slots++;
        generation = 1;
        world->bp_kind[slot] = SX_BP_OUT;
    }
    c = &world->colliders[slot];
    memset(c, 0, sizeof(*c));
    if (parts != NULL) {
        /* a compound: its first part's shape stands in the plain field so
         * no reader ever sees an uninitialised shape */
        c->shape = parts[0].shape;
        c->parts = parts;
        c->part_boxes = boxes;
        c->part_count = part_count;
    } else {
        c->shape = def->shape;
    }
    c->density = def->density;
    c->friction = def->friction;
    c->restitution = def->restitution;
    c->filter = def->filter;
    c->sensor = def->sensor;
    c->alive = true;
    c->aabb_stale = true;
    c->reach = SX_R(0.0);
    world->sets_dirty = true;
    world->collider_generations[slot] = generation;
    c->body = bslot;
    c->next = -1;
    c->next_free = -1;
    c->user_data = def->user_data;
    /* append, so mass sums run in creation order (deterministic) */
    link = &world->infos[bslot].first_collider;
    while (*link >= 0)
        link = &world->colliders[*link].next;
    *link = slot;
    sx_body_update_mass(world, bslot);
    if (out != NULL) {
        out->index = (uint32_t)slot;
        out->generation = generation;
    }
    return SX_OK;
}

/* The checks every collider attach starts with. */
static sx_status sx_attach_prologue(sx_world *world, sx_body_id body, const sx_collider_def *def,
                                    sx_collider_id *out, int *bslot) {
    if (out != NULL) {
        out->index = 0;
        out->generation = 0;
    }
    if (world == NULL || def == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    *bslot = sx_body_slot(world, body);
    if (*bslot < 0) return SX_ERR_STALE_HANDLE;
    return SX_OK;
}

sx_status sx_body_add_collider(sx_world *world, sx_body_id body, const sx_collider_def *def,
                               sx_collider_id *out) {
    int bslot = -1;
    sx_status s = sx_attach_prologue(world, body, def, out, &bslot);
    if (s != SX_OK) return s;
    s = sx_check_collider_def(def);
    if (s != SX_OK) return s;
    return sx_attach_collider(world, bslot, def, NULL, 0, out);
}

sx_status sx_body_add_compound(sx_world *world, sx_body_id body, const sx_compound *compound,
                               const sx_collider_def *def, sx_collider_id *out) {
    int bslot = -1, i;
    sx_compound_part *parts;
    sx_status s = sx_attach_prologue(world, body, def, out, &bslot);
    if (s != SX_OK) return s;
    if (compound == NULL) return SX_ERR_INVALID_ARG;
    s = sx_compound_validate(compound);
    if (s != SX_OK) return s;
    s = sx_check_material(def);
    if (s != SX_OK) return s;
    if (!sx_box_within_huge(sx_compound_aabb(compound, sx_xform_identity()))) {
        return SX_ERR_INVALID_ARG;
    }
    if ((size_t)compound->count > SIZE_MAX / sizeof(sx_compound_part)) return SX_ERR_CAPACITY;
    parts = (sx_compound_part *)sx_alloc((size_t)compound->count * sizeof(sx_compound_part));
    if (parts == NULL) return SX_ERR_NO_MEMORY;
    memcpy(parts, compound->parts, (size_t)compound->count * sizeof(sx_compound_part));
    /* Stored with the rotations the compound functions place them by, so
     * the world's own placements (contacts, AABBs, queries, drawing) agree. */
    for (i = 0; i < compound->count; ++i)
        parts[i].offset = sx_compound_part_placement(sx_xform_identity(), &compound->parts[i]);
    return sx_attach_collider(world, bslot, def, parts, compound->count, out);
}

sx_status sx_body_add_outline(sx_world *world, sx_body_id body, const sx_vec2 *points, int count,
                              const sx_collider_def *def, sx_collider_id *out) {
    int bslot = -1, part_count = 0, i;
    size_t scratch_bytes, shape_bytes;
    void *scratch;
    sx_shape *shapes;
    sx_compound_part *parts;
    sx_status s = sx_attach_prologue(world, body, def, out, &bslot);
    if (s != SX_OK) return s;
    if (points == NULL || count < 3) return SX_ERR_INVALID_ARG;
    s = sx_check_material(def);
    if (s != SX_OK) return s;
    for (i = 0; i < count; ++i) {
        if (!sx_vec2_is_finite(points[i])) return SX_ERR_NONFINITE;
    }
    for (i = 0; i < count; ++i) {
        if (!sx_box_within_huge(sx_aabb_make(points[i], points[i]))) return SX_ERR_INVALID_ARG;
    }
    scratch_bytes = sx_decompose_scratch_bytes(count);
    if (scratch_bytes == 0 || (size_t)(count - 2) > SIZE_MAX / sizeof(sx_compound_part)) {
        return SX_ERR_CAPACITY;
    }
    shape_bytes = (size_t)(count - 2) * sizeof(sx_shape);
    scratch = sx_alloc(scratch_bytes);
    shapes = (sx_shape *)sx_alloc(shape_bytes);
    if (scratch == NULL || shapes == NULL) {
        sx_free(scratch, scratch_bytes);
        sx_free(shapes, shape_bytes);
        return SX_ERR_NO_MEMORY;
    }
    s = sx_decompose_polygon(points, count, scratch, scratch_bytes, shapes, count - 2, &part_count,
                             NULL);
    sx_free(scratch, scratch_bytes);
    if (s == SX_OK && part_count < 1) s = SX_ERR_DEGENERATE;
    if (s != SX_OK) {
        sx_free(shapes, shape_bytes);
        return s;
    }
    parts = (sx_compound_part *)sx_alloc((size_t)part_count * sizeof(sx_compound_part));
    if (parts == NULL) {
        sx_free(shapes, shape_bytes);
        return SX_ERR_NO_MEMORY;
    }
    for (i = 0; i < part_count; ++i)
        parts[i] = sx_compound_part_make(shapes[i], sx_xform_identity());
    sx_free(shapes, shape_bytes);
    return sx_attach_collider(world, bslot, def, parts, part_count, out);
}

int sx_collider_get_part_count(const sx_world *world, sx_collider_id collider) {
    int slot = sx_collider_slot(world, collider);
    if (slot < 0) return 0;
    return world->colliders[slot].part_count > 0 ? world->colliders[slot].part_count : 1;
}

sx_status sx_collider_get_part(const sx_world *world, sx_collider_id collider, int index,
                               sx_compound_part *out) {
    int slot;
    const sx_collider *c;
    if (world == NULL || out == NULL) return SX_ERR_INVALID_ARG;
    slot = sx_collider_slot(world, collider);
    if (slot < 0) return SX_ERR_STALE_HANDLE;
    c = &world->colliders[slot];
    if (index < 0 || index >= (c->part_count > 0 ? c->part_count : 1)) return SX_ERR_INVALID_ARG;
    if (c->part_count > 0) {
        *out = c->parts[index];
    } else {
        *out = sx_compound_part_make(c->shape, sx_xform_identity());
    }
    return SX_OK;
}

sx_status sx_destroy_collider(sx_world *world, sx_collider_id collider) {
    int slot, bslot, *link;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    slot = sx_collider_slot(world, collider);
    if (slot < 0) return SX_ERR_STALE_HANDLE;
    bslot = world->colliders[slot].body;
    sx_wake_body(world, bslot);
    link = &world->infos[bslot].first_collider;
    while (*link != slot)
        link = &world->colliders[*link].next;
    *link = world->colliders[slot].next;
    sx_free_collider_slot(world, slot);
    sx_body_update_mass(world, bslot);
    return SX_OK;
}

/* ---- getters ------------------------------------------------------------ */

sx_body_type sx_body_get_type(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_BODY_STATIC : world->infos[slot].type;
}

sx_vec2 sx_body_get_position(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? sx_v2_zero() : world->sims[slot].xf.p;
}

sx_real sx_body_get_angle(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : sx_rot_angle(world->sims[slot].xf.q);
}

sx_xform sx_body_get_transform(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? sx_xform_identity() : world->sims[slot].xf;
}

sx_vec2 sx_body_get_world_center(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? sx_v2_zero() : world->sims[slot].center;
}

sx_vec2 sx_body_get_local_center(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? sx_v2_zero() : world->sims[slot].local_center;
}

sx_vec2 sx_body_get_linear_velocity(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? sx_v2_zero() : world->sims[slot].v;
}

sx_real sx_body_get_angular_velocity(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : world->sims[slot].w;
}

sx_real sx_body_get_mass(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : world->infos[slot].mass;
}

sx_real sx_body_get_inertia(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : world->infos[slot].inertia;
}

void *sx_body_get_user_data(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? NULL : world->infos[slot].user_data;
}

bool sx_body_is_awake(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot >= 0 && world->infos[slot].type != SX_BODY_STATIC && world->sims[slot].awake;
}

sx_status sx_body_get_state(const sx_world *world, sx_body_id body, sx_body_state *out) {
    int slot = sx_body_slot(world, body);
    const sx_body_sim *sim;
    if (out == NULL) return SX_ERR_INVALID_ARG;
    if (slot < 0) {
        out->transform = sx_xform_identity();
        out->linear_velocity = sx_v2_zero();
        out->angular_velocity = SX_R(0.0);
        out->awake = false;
        return world == NULL ? SX_ERR_INVALID_ARG : SX_ERR_STALE_HANDLE;
    }
    sim = &world->sims[slot];
    out->transform = sim->xf;
    out->linear_velocity = sim->v;
    out->angular_velocity = sim->w;
    out->awake = world->infos[slot].type != SX_BODY_STATIC && sim->awake;
    return SX_OK;
}

sx_status sx_body_set_awake(sx_world *world, sx_body_id body, bool awake) {
    int slot;
    sx_body_sim *sim;
    sx_status s;
    slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    sim = &world->sims[slot];
    if (!sim->dynamic) return SX_OK;
    if (awake) {
        sx_wake_body(world, slot);
    } else if (sim->awake) {
        sim->awake = false;
        sx_world_solver_changed(world);
        sim->v = sx_v2_zero();
        sim->w = SX_R(0.0);
        world->infos[slot].island = -1;
        world->sets_dirty = true;
    }
    return SX_OK;
}

sx_status sx_body_set_sleep_enabled(sx_world *world, sx_body_id body, bool enable) {
    int slot;
    sx_status s;
    slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    world->infos[slot].enable_sleep = enable;
    if (!enable) sx_wake_body(world, slot);
    return SX_OK;
}

bool sx_body_is_sleep_enabled(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot >= 0 && world->infos[slot].enable_sleep;
}

/* ---- setters ------------------------------------------------------------ */

sx_status sx_body_set_transform(sx_world *world, sx_body_id body, sx_vec2 position, sx_real angle) {
    int slot, c;
    sx_body_sim *sim;
    sx_status s;
    slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    if (!sx_vec2_is_finite(position) || !sx_is_finite(angle)) return SX_ERR_NONFINITE;
    sim = &world->sims[slot];
    sx_wake_touching(world, slot);
    sim->xf = sx_xform_make(position, angle);
    sim->center = sx_xform_point(sim->xf, sim->local_center);
    world->lane_gaps_current = false;
    for (c = world->infos[slot].first_collider; c >= 0; c = world->colliders[c].next)
        world->colliders[c].aabb_stale = true;
    world->sets_dirty = true;
    return SX_OK;
}

sx_status sx_body_set_linear_velocity(sx_world *world, sx_body_id body, sx_vec2 v) {
    int slot;
    sx_status s;
    slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    if (!sx_vec2_is_finite(v)) return SX_ERR_NONFINITE;
    if (world->infos[slot].type != SX_BODY_STATIC) {
        sx_wake_body(world, slot);
        world->sims[slot].v = v;
        world->limited_h = SX_R(0.0); /* the speed limit looks again */
        world->sets_dirty = true;     /* a kinematic body may start or stop */
    }
    return SX_OK;
}

sx_status sx_body_set_angular_velocity(sx_world *world, sx_body_id body, sx_real w) {
    int slot;
    const sx_body_info *info;
    sx_status s;
    slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    if (!sx_is_finite(w)) return SX_ERR_NONFINITE;
    info = &world->infos[slot];
    if (info->type == SX_BODY_KINEMATIC ||
        (info->type == SX_BODY_DYNAMIC && world->sims[slot].inv_inertia > SX_R(0.0))) {
        sx_wake_body(world, slot);
        world->sims[slot].w = w;
        world->limited_h = SX_R(0.0);
        world->sets_dirty = true;
    }
    return SX_OK;
}

sx_status sx_body_set_type(sx_world *world, sx_body_id body, sx_body_type type) {
    int slot;
    sx_status s;
    slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    if (type != SX_BODY_STATIC && type != SX_BODY_KINEMATIC && type != SX_BODY_DYNAMIC) {
        return SX_ERR_INVALID_ARG;
    }
    sx_wake_touching(world, slot);
    world->infos[slot].type = type;
    sx_body_update_mass(world, slot);
    return SX_OK;
}

/* ---- forces and impulses ------------------------------------------------ */

/* The simulated state of a body that accepts forces, or NULL (static,
 * kinematic or disabled: they ignore forces). *status gets the answer. */
static sx_body_sim *sx_force_target(sx_world *world, sx_body_id body, sx_status *status) {
    int slot = sx_body_slot_checked(world, body, status);
    if (slot < 0) return NULL;
    if (world->infos[slot].type != SX_BODY_DYNAMIC) return NULL;
    sx_wake_body(world, slot);
    return &world->sims[slot];
}

/* Adds a linear and an angular part to the force (impulse false) or impulse
 * accumulators of sim, or refuses with SX_ERR_NONFINITE when a sum would not
 * be finite: a huge but finite force at a far point (or many huge ones)
 * overflows, and an infinite accumulator becomes NaN in the step (inf x 0
 * for a body without rotational inertia, inf - inf in the solver). */
static sx_status sx_accumulate(sx_body_sim *sim, sx_vec2 linear, sx_real angular, bool impulse) {
    sx_vec2 l;
    sx_real a;
    if (sim == NULL) return SX_OK;
    l = sx_add(impulse ? sim->impulse : sim->force, linear);
    a = (impulse ? sim->angular_impulse : sim->torque) + angular;
    if (!sx_vec2_is_finite(l) || !sx_is_finite(a)) return SX_ERR_NONFINITE;
    if (impulse) {
        sim->impulse = l;
        sim->angular_impulse = a;
    } else {
        sim->force = l;
        sim->torque = a;
    }
    return SX_OK;
}

/* A force (impulse false) or an impulse: `linear` through the centre of
 * mass and `angular` about it, or with a point (world) `linear` at that
 * point, its moment about the centre of mass taking the place of
 * `angular`. */
static sx_status sx_apply(sx_world *world, sx_body_id body, sx_vec2 linear, sx_real angular,
                          const sx_vec2 *point, bool impulse) {
    sx_status s;
    sx_body_sim *sim = sx_force_target(world, body, &s);
    if (s != SX_OK) return s;
    if (!sx_vec2_is_finite(linear) || !sx_is_finite(angular) ||
        (point != NULL && !sx_vec2_is_finite(*point))) {
        return SX_ERR_NONFINITE;
    }
    if (sim == NULL) return SX_OK;
    if (point != NULL) angular = sx_cross(sx_sub(*point, sim->center), linear);
    return sx_accumulate(sim, linear, angular, impulse);
}

sx_status sx_body_apply_force(sx_world *world, sx_body_id body, sx_vec2 force) {
    return sx_apply(world, body, force, SX_R(0.0), NULL, false);
}

sx_status sx_body_apply_force_at_point(sx_world *world, sx_body_id body, sx_vec2 force,
                                       sx_vec2 point) {
    return sx_apply(world, body, force, SX_R(0.0), &point, false);
}

sx_status sx_body_apply_torque(sx_world *world, sx_body_id body, sx_real torque) {
    return sx_apply(world, body, sx_v2_zero(), torque, NULL, false);
}

sx_status sx_body_apply_impulse(sx_world *world, sx_body_id body, sx_vec2 impulse) {
    return sx_apply(world, body, impulse, SX_R(0.0), NULL, true);
}

sx_status sx_body_apply_impulse_at_point(sx_world *world, sx_body_id body, sx_vec2 impulse,
                                         sx_vec2 point) {
    return sx_apply(world, body, impulse, SX_R(0.0), &point, true);
}

sx_status sx_body_apply_angular_impulse(sx_world *world, sx_body_id body, sx_real impulse) {
    return sx_apply(world, body, sx_v2_zero(), impulse, NULL, true);
}
