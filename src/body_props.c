/* sepax — what a game changes while a world runs: the world's solver
 * settings, a body's enabled flag, gravity scale, damping and fixed
 * rotation, a collider's material and filter; the iteration of bodies and
 * colliders, their bounds, and the sx_<object>_create/destroy names.
 *
 * Every setter validates its value first and changes nothing on error, as
 * the creators do. A change that alters what the solver sees of a contact
 * (material, filter, mass) wakes the body, so a sleeping island never keeps
 * a value the game replaced; contacts rebuild their mixed friction and
 * restitution at every collide, so nothing else is cached. */
#include "world_body.h"
#include "world_contact.h"
#include "world_internal.h"
#include "world_island.h"
#include "world_sensor.h"

/* ---- world settings ------------------------------------------------------- */

sx_status sx_world_get_def(const sx_world *world, sx_world_def *out) {
    if (world == NULL || out == NULL) return SX_ERR_INVALID_ARG;
    *out = world->def;
    return SX_OK;
}

sx_status sx_world_set_sub_steps(sx_world *world, int sub_steps) {
    if (world == NULL || sub_steps < 1) return SX_ERR_INVALID_ARG;
    world->def.sub_steps = sub_steps;
    return SX_OK;
}

sx_status sx_world_set_iterations(sx_world *world, int velocity_iterations,
                                  int position_iterations) {
    if (world == NULL || velocity_iterations < 1 || position_iterations < 0) {
        return SX_ERR_INVALID_ARG;
    }
    world->def.velocity_iterations = velocity_iterations;
    world->def.position_iterations = position_iterations;
    return SX_OK;
}

sx_status sx_world_enable_continuous(sx_world *world, bool enable) {
    if (world == NULL) return SX_ERR_INVALID_ARG;
    world->def.enable_continuous = enable;
    return SX_OK;
}

/* ---- iteration and bounds -------------------------------------------------- */

int sx_world_get_bodies(const sx_world *world, sx_body_id *out, int capacity) {
    int i, n = 0;
    if (world == NULL) return 0;
    for (i = 0; i < world->body_slots; ++i) {
        if (!world->infos[i].alive) continue;
        if (out != NULL && n < capacity) {
            out[n].index = (uint32_t)i;
            out[n].generation = world->infos[i].generation;
        }
        ++n;
    }
    return n;
}

int sx_body_get_colliders(const sx_world *world, sx_body_id body, sx_collider_id *out,
                          int capacity) {
    int slot = sx_body_slot(world, body), c, n = 0;
    if (slot < 0) return 0;
    for (c = world->infos[slot].first_collider; c >= 0; c = world->colliders[c].next) {
        if (out != NULL && n < capacity) {
            out[n].index = (uint32_t)c;
            out[n].generation = world->collider_generations[c];
        }
        ++n;
    }
    return n;
}

sx_aabb sx_body_get_aabb(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body), c;
    sx_aabb box;
    sx_xform xf;
    if (slot < 0) return sx_aabb_make(sx_v2_zero(), sx_v2_zero());
    xf = world->sims[slot].xf;
    box = sx_aabb_make(xf.p, xf.p);
    for (c = world->infos[slot].first_collider; c >= 0; c = world->colliders[c].next) {
        sx_aabb cb = sx_collider_aabb(&world->colliders[c], xf);
        box = c == world->infos[slot].first_collider ? cb : sx_aabb_union(box, cb);
    }
    return box;
}

sx_aabb sx_collider_get_aabb(const sx_world *world, sx_collider_id collider) {
    int slot = sx_collider_slot(world, collider);
    const sx_collider *c;
    if (slot < 0) return sx_aabb_make(sx_v2_zero(), sx_v2_zero());
    c = &world->colliders[slot];
    return sx_collider_aabb(c, world->sims[c->body].xf);
}

/* ---- one naming pattern ---------------------------------------------------- */

sx_status sx_body_create(sx_world *world, const sx_body_def *def, sx_body_id *out) {
    return sx_create_body(world, def, out);
}

sx_status sx_body_destroy(sx_world *world, sx_body_id body) { return sx_destroy_body(world, body); }

sx_status sx_collider_create(sx_world *world, sx_body_id body, const sx_collider_def *def,
                             sx_collider_id *out) {
    return sx_body_add_collider(world, body, def, out);
}

sx_status sx_collider_destroy(sx_world *world, sx_collider_id collider) {
    return sx_destroy_collider(world, collider);
}

/* ---- body properties ------------------------------------------------------- */

/* The status of a damping, friction, restitution or density value. */
static sx_status sx_check_nonnegative(sx_real value) {
    if (!sx_is_finite(value)) return SX_ERR_NONFINITE;
    return value < SX_R(0.0) ? SX_ERR_INVALID_ARG : SX_OK;
}

sx_status sx_body_set_enabled(sx_world *world, sx_body_id body, bool enabled) {
    sx_status s;
    int slot = sx_body_slot_checked(world, body, &s), c;
    sx_body_info *info;
    if (slot < 0) return s;
    info = &world->infos[slot];
    if (info->enabled == enabled) return SX_OK;
    for (c = info->first_collider; c >= 0; c = world->colliders[c].next) {
        if (!enabled) {
            /* as a destroy: whatever rested on it wakes, no end events */
            sx_world_remove_contacts_of(world, c);
            sx_sensors_remove_collider(world, c);
        }
        world->colliders[c].aabb_stale = true;
    }
    info->enabled = enabled;
    sx_body_update_mass(world, slot);
    if (enabled) sx_wake_body(world, slot);
    return SX_OK;
}

bool sx_body_is_enabled(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot >= 0 && world->infos[slot].enabled;
}

sx_status sx_body_set_gravity_scale(sx_world *world, sx_body_id body, sx_real scale) {
    sx_status s;
    int slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    if (!sx_is_finite(scale)) return SX_ERR_NONFINITE;
    world->sims[slot].gravity_scale = scale;
    sx_wake_body(world, slot);
    return SX_OK;
}

sx_real sx_body_get_gravity_scale(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : world->sims[slot].gravity_scale;
}

/* Sets the linear or the angular damping of a body. */
static sx_status sx_set_damping(sx_world *world, sx_body_id body, sx_real damping, bool angular) {
    sx_status s;
    int slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    s = sx_check_nonnegative(damping);
    if (s != SX_OK) return s;
    if (angular)
        world->sims[slot].angular_damping = damping;
    else
        world->sims[slot].linear_damping = damping;
    return SX_OK;
}

sx_status sx_body_set_linear_damping(sx_world *world, sx_body_id body, sx_real damping) {
    return sx_set_damping(world, body, damping, false);
}

sx_real sx_body_get_linear_damping(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : world->sims[slot].linear_damping;
}

sx_status sx_body_set_angular_damping(sx_world *world, sx_body_id body, sx_real damping) {
    return sx_set_damping(world, body, damping, true);
}

sx_real sx_body_get_angular_damping(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot < 0 ? SX_R(0.0) : world->sims[slot].angular_damping;
}

sx_status sx_body_set_fixed_rotation(sx_world *world, sx_body_id body, bool fixed) {
    sx_status s;
    int slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    world->infos[slot].fixed_rotation = fixed;
    sx_body_update_mass(world, slot);
    sx_wake_body(world, slot);
    return SX_OK;
}

bool sx_body_is_fixed_rotation(const sx_world *world, sx_body_id body) {
    int slot = sx_body_slot(world, body);
    return slot >= 0 && world->infos[slot].fixed_rotation;
}

sx_status sx_body_set_user_data(sx_world *world, sx_body_id body, void *user_data) {
    sx_status s;
    int slot = sx_body_slot_checked(world, body, &s);
    if (slot < 0) return s;
    world->infos[slot].user_data = user_data;
    return SX_OK;
}

/* ---- collider properties --------------------------------------------------- */

/* The collider a setter changes, or NULL with *status set. */
static sx_collider *sx_setter_collider(sx_world *world, sx_collider_id collider,
                                       sx_status *status) {
    int slot;
    if (world == NULL) {
        *status = SX_ERR_INVALID_ARG;
        return NULL;
    }
    slot = sx_collider_slot(world, collider);
    *status = slot < 0 ? SX_ERR_STALE_HANDLE : SX_OK;
    return slot < 0 ? NULL : &world->colliders[slot];
}

/* The collider a getter reads, or NULL. */
static const sx_collider *sx_getter_collider(const sx_world *world, sx_collider_id collider) {
    int slot = sx_collider_slot(world, collider);
    return slot < 0 ? NULL : &world->colliders[slot];
}

/* The collider a material setter changes, or NULL with *status set (a bad
 * handle or value). Wakes its body: the next collide mixes the new value. */
static sx_collider *sx_material_target(sx_world *world, sx_collider_id collider, sx_real value,
                                       sx_status *status) {
    sx_collider *c = sx_setter_collider(world, collider, status);
    if (c == NULL) return NULL;
    *status = sx_check_nonnegative(value);
    if (*status != SX_OK) return NULL;
    sx_wake_body(world, c->body);
    return c;
}

sx_status sx_collider_set_friction(sx_world *world, sx_collider_id collider, sx_real friction) {
    sx_status s;
    sx_collider *c = sx_material_target(world, collider, friction, &s);
    if (c != NULL) c->friction = friction;
    return s;
}

sx_real sx_collider_get_friction(const sx_world *world, sx_collider_id collider) {
    const sx_collider *c = sx_getter_collider(world, collider);
    return c == NULL ? SX_R(0.0) : c->friction;
}

sx_status sx_collider_set_restitution(sx_world *world, sx_collider_id collider,
                                      sx_real restitution) {
    sx_status s;
    sx_collider *c = sx_material_target(world, collider, restitution, &s);
    if (c != NULL) c->restitution = restitution;
    return s;
}

sx_real sx_collider_get_restitution(const sx_world *world, sx_collider_id collider) {
    const sx_collider *c = sx_getter_collider(world, collider);
    return c == NULL ? SX_R(0.0) : c->restitution;
}

sx_status sx_collider_set_density(sx_world *world, sx_collider_id collider, sx_real density) {
    sx_status s;
    sx_collider *c = sx_material_target(world, collider, density, &s);
    if (c == NULL) return s;
    c->density = density;
    sx_body_update_mass(world, c->body);
    return SX_OK;
}

sx_real sx_collider_get_density(const sx_world *world, sx_collider_id collider) {
    const sx_collider *c = sx_getter_collider(world, collider);
    return c == NULL ? SX_R(0.0) : c->density;
}

sx_status sx_collider_set_filter(sx_world *world, sx_collider_id collider, sx_filter filter) {
    sx_status s;
    sx_collider *c = sx_setter_collider(world, collider, &s);
    if (c == NULL) return s;
    c->filter = filter;
    sx_wake_body(world, c->body);
    return SX_OK;
}

sx_filter sx_collider_get_filter(const sx_world *world, sx_collider_id collider) {
    const sx_collider *c = sx_getter_collider(world, collider);
    sx_filter none = {0u, 0u, 0};
    return c == NULL ? none : c->filter;
}

bool sx_collider_is_sensor(const sx_world *world, sx_collider_id collider) {
    const sx_collider *c = sx_getter_collider(world, collider);
    return c != NULL && c->sensor;
}

sx_status sx_collider_set_user_data(sx_world *world, sx_collider_id collider, void *user_data) {
    sx_status s;
    sx_collider *c = sx_setter_collider(world, collider, &s);
    if (c == NULL) return s;
    c->user_data = user_data;
    return SX_OK;
}

void *sx_collider_get_user_data(const sx_world *world, sx_collider_id collider) {
    const sx_collider *c = sx_getter_collider(world, collider);
    return c == NULL ? NULL : c->user_data;
}
