/* sepax flecs module: the glue between flecs components and a sepax world.
 *
 * The idea: the components are the only truth a game sees, and the sepax
 * world is a mirror the module keeps in step with them. Once per fixed step
 * the PreStep systems walk the SxTransform/SxBody/SxCollider columns and push
 * into the world only what differs from the world's own state (a teleport, a
 * new velocity, a new type), so an untouched body is never woken; new
 * entities get their world body here. The stage systems then call the
 * world's public stage functions (all physics lives in src/), and the
 * PostStep systems copy positions and velocities back into the columns. The
 * module keeps no state of its own beyond the entity <-> body handles, so
 * nothing can go stale. Component hooks free a body when its entity dies or
 * loses its components; they touch only the sepax world, never flecs
 * structure, so they are safe in deferred mode.
 *
 * The fixed step is an accumulator in the SxPhysicsUpdate phase: flecs timers
 * fire at most once per frame, while a long frame must run several steps. The
 * driver runs the systems tagged with the physics tags itself with ecs_run,
 * in entity-id order, passing the step length as `param` (an sx_real) so the
 * stages see exactly the value sx_world_step would compute. */
#include "sepax_flecs.h"

#include <stdlib.h>
#include <string.h>

ECS_COMPONENT_DECLARE(SxTransform);
ECS_COMPONENT_DECLARE(SxBody);
ECS_COMPONENT_DECLARE(SxCollider);
ECS_COMPONENT_DECLARE(SxPhysicsSettings);
ECS_COMPONENT_DECLARE(SxPhysicsTime);
ECS_COMPONENT_DECLARE(SxContacts);
ECS_COMPONENT_DECLARE(SxPhysicsWorld);
ECS_COMPONENT_DECLARE(SxContactEvent);

ECS_DECLARE(SxPhysicsUpdate);
ECS_DECLARE(SxPhysicsPreStep);
ECS_DECLARE(SxPhysicsApplyForces);
ECS_DECLARE(SxPhysicsCollide);
ECS_DECLARE(SxPhysicsSolve);
ECS_DECLARE(SxPhysicsIntegrate);
ECS_DECLARE(SxPhysicsSeparate);
ECS_DECLARE(SxPhysicsPostStep);
ECS_DECLARE(SxContactBegin);
ECS_DECLARE(SxContactEnd);
ECS_DECLARE(SxSensorBegin);
ECS_DECLARE(SxSensorEnd);

/* Frame time that is this close (in fixed steps) to a whole number of steps
 * counts as that number: 0.1 s frames at 1/60 s must give 6 steps although
 * 0.1 / (1/60) rounds either way in binary. */
#define SX_ECS_TICK_TOLERANCE 1e-6

/* Contacts read from the world per call when publishing SxContacts (a
 * buffer on the stack, under 13 KiB in the double build). */
#define SX_ECS_CONTACT_BATCH 128

/* Most systems one physics tag runs per step (ours and the game's). */
#define SX_ECS_MAX_PHASE_SYSTEMS 64

/* What the module created in the world for one entity, and the body
 * parameters it was built with (those without a world setter rebuild it).
 * Every step reads each link twice (push, copy-out): it holds only the
 * SxBody fields it compares, to stay near one cache line. */
typedef struct sx_ecs_link {
    ecs_entity_t entity; /* 0: a free slot */
    sx_body_id body;
    sx_collider_id collider;
    /* What the world holds, as of the last build, push or copy-out: a
     * component equal to it was not written by the game, and an unchanged
     * rotation keeps its angle (no atan2 per resting body and step). */
    sx_vec2 position, velocity;
    sx_rot rotation;
    sx_real angle, angular_velocity;
    sx_real mass, linear_damping, angular_damping, gravity_scale;
    sx_body_type type;
    bool fixed_rotation, bullet;
    bool has_collider;
    bool collider_dirty;
} sx_ecs_link;

typedef struct sx_ecs_doomed {
    uint64_t id; /* sx_body_id_to_u64 or sx_collider_id_to_u64 */
    bool collider;
} sx_ecs_doomed;

typedef struct sx_ecs_state {
    sx_world *world;
    /* entity -> link: link_of, indexed by the entity's index (its low 32
     * bits, dense in flecs), holds 1 + the link's place in `links` (0:
     * none), 4 bytes for each entity of the game; the links lie together,
     * made in the order the module first met the entities (a table's
     * order), so a step streams through them; freed places are reused */
    int32_t *link_of;
    uint32_t link_of_cap;
    sx_ecs_link *links;
    int32_t link_count, link_cap;
    int32_t *free_links;
    uint32_t free_count, free_cap;
    ecs_entity_t *body_entity; /* by body slot index */
    int32_t body_entity_cap;
    double accumulator;
    int64_t steps;
    SxContact *contacts, *previous, *scratch;
    int32_t contact_count, previous_count;
    int32_t contact_cap, previous_cap, scratch_cap;
    /* bodies and colliders whose entity died while the world was locked (a
     * query or draw callback of it deleted the entity): destroyed at the
     * next step */
    sx_ecs_doomed *doomed;
    int32_t doomed_count, doomed_cap;
} sx_ecs_state;

/* ---- links ------------------------------------------------------------- */

static sx_ecs_link *sx_ecs_find(const sx_ecs_state *st, ecs_entity_t e) {
    uint32_t index = (uint32_t)e;
    int32_t at = index < st->link_of_cap ? st->link_of[index] : 0;
    return at > 0 && st->links[at - 1].entity == e ? &st->links[at - 1] : NULL;
}

/* Grows an int32 array to hold `need` entries (new ones zeroed); false
 * out of memory or for 0 or more than 2^30. */
static bool sx_ecs_grow_ints(int32_t **items, uint32_t *cap, uint32_t need) {
    uint32_t n = *cap ? *cap : 1024;
    int32_t *grown;
    if (need == 0 || need > (1u << 30)) return false; /* index + 1 wrapped, or absurd */
    if (need <= *cap) return true;
    while (n < need)
        n *= 2;
    grown = (int32_t *)realloc(*items, (size_t)n * sizeof(*grown));
    if (grown == NULL) return false;
    memset(grown + *cap, 0, (size_t)(n - *cap) * sizeof(*grown));
    *items = grown;
    *cap = n;
    return true;
}

/* Remembers what the world now holds for the link's body. */
static void sx_ecs_cache(sx_ecs_link *link, sx_vec2 position, sx_real angle, sx_vec2 velocity,
                         sx_real angular_velocity) {
    link->position = position;
    link->angle = angle;
    link->rotation = sx_rot_make(angle);
    link->velocity = velocity;
    link->angular_velocity = angular_velocity;
}

static bool sx_ecs_remember_entity(sx_ecs_state *st, sx_body_id body, ecs_entity_t e) {
    int32_t index = (int32_t)body.index;
    if (index >= st->body_entity_cap) {
        int32_t cap = st->body_entity_cap ? st->body_entity_cap : 64;
        ecs_entity_t *grown;
        while (cap <= index)
            cap *= 2;
        grown = (ecs_entity_t *)realloc(st->body_entity, (size_t)cap * sizeof(*grown));
        if (grown == NULL) return false;
        memset(grown + st->body_entity_cap, 0,
               (size_t)(cap - st->body_entity_cap) * sizeof(*grown));
        st->body_entity = grown;
        st->body_entity_cap = cap;
    }
    st->body_entity[index] = e;
    return true;
}

static ecs_entity_t sx_ecs_entity_at(const sx_ecs_state *st, sx_body_id body) {
    if ((int32_t)body.index >= st->body_entity_cap) return 0;
    return st->body_entity[body.index];
}

/* Attaches the entity's collider; a positive SxBody.mass scales the density
 * so the body weighs exactly that. */
static void sx_ecs_attach(sx_ecs_state *st, sx_ecs_link *link, const SxBody *b,
                          const SxCollider *c) {
    sx_collider_def def = sx_default_collider_def();
    def.shape = c->shape;
    def.density = c->density;
    def.friction = c->friction;
    def.restitution = c->restitution;
    def.filter = c->filter;
    def.sensor = c->sensor;
    if (c->part_count > 0) {
        /* a compound: its parts act as one collider */
        sx_compound view;
        view.parts = c->parts;
        view.count = c->part_count;
        if (b != NULL && b->mass > SX_R(0.0)) {
            sx_mass_data unit = sx_compound_mass(&view, SX_R(1.0));
            if (unit.mass > SX_R(0.0)) def.density = b->mass / unit.mass;
        }
        link->has_collider =
            sx_body_add_compound(st->world, link->body, &view, &def, &link->collider) == SX_OK;
        link->collider_dirty = false;
        return;
    }
    if (b != NULL && b->mass > SX_R(0.0)) {
        sx_mass_data unit = sx_shape_mass(&c->shape, SX_R(1.0));
        if (unit.mass > SX_R(0.0)) def.density = b->mass / unit.mass;
    }
    link->has_collider =
        sx_body_add_collider(st->world, link->body, &def, &link->collider) == SX_OK;
    link->collider_dirty = false;
}

/* Creates the world body (and collider) of an entity from its components;
 * b == NULL makes static geometry. */
static void sx_ecs_build(sx_ecs_state *st, ecs_entity_t e, sx_ecs_link *link, const SxTransform *t,
                         const SxBody *b, const SxCollider *c) {
    sx_body_def def = sx_default_body_def();
    def.position = t->position;
    def.angle = t->angle;
    sx_ecs_cache(link, t->position, t->angle, b != NULL ? b->velocity : sx_v2_zero(),
                 b != NULL ? b->angular_velocity : SX_R(0.0));
    if (b != NULL) {
        def.type = b->type;
        def.linear_velocity = b->velocity;
        def.angular_velocity = b->angular_velocity;
        def.linear_damping = b->linear_damping;
        def.angular_damping = b->angular_damping;
        def.gravity_scale = b->gravity_scale;
        def.fixed_rotation = b->fixed_rotation;
        def.bullet = b->bullet;
        link->type = b->type;
        link->mass = b->mass;
        link->linear_damping = b->linear_damping;
        link->angular_damping = b->angular_damping;
        link->gravity_scale = b->gravity_scale;
        link->fixed_rotation = b->fixed_rotation;
        link->bullet = b->bullet;
    }
    link->has_collider = false;
    link->collider_dirty = false;
    if (sx_create_body(st->world, &def, &link->body) != SX_OK) {
        link->body = sx_body_id_from_u64(0);
        return;
    }
    if (!sx_ecs_remember_entity(st, link->body, e)) return;
    if (c != NULL) sx_ecs_attach(st, link, b, c);
}

static void sx_ecs_unlink(sx_ecs_state *st, ecs_entity_t e);

static sx_ecs_link *sx_ecs_link_new(sx_ecs_state *st, ecs_entity_t e) {
    uint32_t index = (uint32_t)e;
    int32_t at;
    sx_ecs_link *link;
    if (!sx_ecs_grow_ints(&st->link_of, &st->link_of_cap, index + 1u)) return NULL;
    /* a recycled index whose previous entity left without its hooks */
    at = st->link_of[index];
    if (at > 0 && st->links[at - 1].entity != 0) sx_ecs_unlink(st, st->links[at - 1].entity);
    if (st->free_count > 0) {
        at = st->free_links[--st->free_count];
    } else {
        if (st->link_count == st->link_cap) {
            /* moves the links: no caller holds one across this call */
            int32_t cap = st->link_cap ? 2 * st->link_cap : 1024;
            sx_ecs_link *grown = (sx_ecs_link *)realloc(st->links, (size_t)cap * sizeof(*grown));
            if (grown == NULL) return NULL;
            st->links = grown;
            st->link_cap = cap;
        }
        at = st->link_count++;
    }
    link = &st->links[at];
    memset(link, 0, sizeof(*link));
    link->entity = e;
    st->link_of[index] = at + 1;
    return link;
}

/* Destroys a body (collider false) or collider now, or at the next step if
 * the world is locked; out of memory, it stays in the world. */
static void sx_ecs_destroy(sx_ecs_state *st, uint64_t id, bool collider) {
    sx_status s = collider ? sx_destroy_collider(st->world, sx_collider_id_from_u64(id))
                           : sx_destroy_body(st->world, sx_body_id_from_u64(id));
    if (s != SX_ERR_LOCKED) return;
    if (st->doomed_count == st->doomed_cap) {
        int32_t cap = st->doomed_cap ? 2 * st->doomed_cap : 16;
        sx_ecs_doomed *grown =
            (sx_ecs_doomed *)realloc(st->doomed, (size_t)cap * sizeof(sx_ecs_doomed));
        if (grown == NULL) return;
        st->doomed = grown;
        st->doomed_cap = cap;
    }
    st->doomed[st->doomed_count].id = id;
    st->doomed[st->doomed_count].collider = collider;
    st->doomed_count++;
}

static void sx_ecs_unlink(sx_ecs_state *st, ecs_entity_t e) {
    sx_ecs_link *link = sx_ecs_find(st, e);
    if (link == NULL) return;
    if (sx_body_is_valid(st->world, link->body)) {
        if ((int32_t)link->body.index < st->body_entity_cap) st->body_entity[link->body.index] = 0;
        sx_ecs_destroy(st, sx_body_id_to_u64(link->body), false);
    }
    link->entity = 0;
    st->link_of[(uint32_t)e] = 0;
    /* the place is reused; out of memory, it stays unused */
    if (!sx_ecs_grow_ints(&st->free_links, &st->free_cap, st->free_count + 1u)) return;
    st->free_links[st->free_count++] = (int32_t)(link - st->links);
}

/* ---- hooks: an entity's body lives as long as its components ------------- */

static void sx_ecs_body_removed(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    int32_t i;
    /* ecs_fini: the state's ctx_free destroys the whole world at once, so
     * destroying body by body (each dropping its contacts) is wasted work */
    if (ecs_is_fini(it->world)) return;
    /* The collider, if it stays, comes back as static geometry next step. */
    for (i = 0; i < it->count; ++i)
        sx_ecs_unlink(st, it->entities[i]);
}

static void sx_ecs_collider_removed(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    int32_t i;
    if (ecs_is_fini(it->world)) return; /* as in sx_ecs_body_removed */
    for (i = 0; i < it->count; ++i) {
        ecs_entity_t e = it->entities[i];
        sx_ecs_link *link = sx_ecs_find(st, e);
        if (link == NULL) continue;
        if (!ecs_has(it->world, e, SxBody)) {
            sx_ecs_unlink(st, e);
        } else if (link->has_collider) {
            sx_ecs_destroy(st, sx_collider_id_to_u64(link->collider), true);
            link->has_collider = false;
        }
    }
}

static void sx_ecs_collider_set(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    int32_t i;
    for (i = 0; i < it->count; ++i) {
        sx_ecs_link *link = sx_ecs_find(st, it->entities[i]);
        if (link != NULL) link->collider_dirty = true;
    }
}

/* SxCollider owns its compound parts: lifecycle hooks copy, move and free
 * the array so a component value never shares it with another. A plain
 * collider (part_count 0) costs a branch per element on structural moves. */
static sx_compound_part *sx_ecs_copy_parts(const sx_compound_part *parts, int32_t count) {
    sx_compound_part *copy;
    if (parts == NULL || count <= 0) return NULL;
    copy = (sx_compound_part *)malloc((size_t)count * sizeof(*copy));
    if (copy != NULL) memcpy(copy, parts, (size_t)count * sizeof(*copy));
    return copy;
}

static void sx_ecs_collider_ctor(void *ptr, int32_t count, const ecs_type_info_t *ti) {
    (void)ti;
    memset(ptr, 0, (size_t)count * sizeof(SxCollider));
}

static void sx_ecs_collider_dtor(void *ptr, int32_t count, const ecs_type_info_t *ti) {
    SxCollider *c = (SxCollider *)ptr;
    int32_t i;
    (void)ti;
    for (i = 0; i < count; ++i) {
        free((void *)(uintptr_t)c[i].parts);
        c[i].parts = NULL;
        c[i].part_count = 0;
    }
}

static void sx_ecs_collider_copy(void *dst_ptr, const void *src_ptr, int32_t count,
                                 const ecs_type_info_t *ti) {
    SxCollider *dst = (SxCollider *)dst_ptr;
    const SxCollider *src = (const SxCollider *)src_ptr;
    int32_t i;
    (void)ti;
    for (i = 0; i < count; ++i) {
        sx_compound_part *parts;
        if (&dst[i] == &src[i]) continue;
        parts = sx_ecs_copy_parts(src[i].parts, src[i].part_count);
        free((void *)(uintptr_t)dst[i].parts);
        dst[i] = src[i];
        dst[i].parts = parts;
        /* out of memory: a plain collider of the fallback shape */
        if (parts == NULL) dst[i].part_count = 0;
    }
}

static void sx_ecs_collider_move(void *dst_ptr, void *src_ptr, int32_t count,
                                 const ecs_type_info_t *ti) {
    SxCollider *dst = (SxCollider *)dst_ptr;
    SxCollider *src = (SxCollider *)src_ptr;
    int32_t i;
    (void)ti;
    for (i = 0; i < count; ++i) {
        if (&dst[i] == &src[i]) continue;
        free((void *)(uintptr_t)dst[i].parts);
        dst[i] = src[i];
        src[i].parts = NULL;
        src[i].part_count = 0;
    }
}

static void sx_ecs_state_free(void *ctx) {
    sx_ecs_state *st = (sx_ecs_state *)ctx;
    free(st->link_of);
    free(st->links);
    free(st->free_links);
    sx_world_destroy(st->world);
    free(st->body_entity);
    free(st->contacts);
    free(st->previous);
    free(st->scratch);
    free(st->doomed);
    free(st);
}

/* ---- PreStep: components -> world ---------------------------------------- */

static bool sx_ecs_params_differ(const SxBody *b, const sx_ecs_link *link) {
    return b->mass != link->mass || b->linear_damping != link->linear_damping ||
           b->angular_damping != link->angular_damping || b->gravity_scale != link->gravity_scale ||
           b->fixed_rotation != link->fixed_rotation;
}

/* Pushes what the game changed since the last copy-out into the world. */
static void sx_ecs_push(sx_ecs_state *st, ecs_entity_t e, sx_ecs_link *link, const SxTransform *t,
                        SxBody *b, const SxCollider *c) {
    sx_world *w = st->world;
    if (b != NULL && sx_ecs_params_differ(b, link)) {
        sx_destroy_body(w, link->body);
        sx_ecs_build(st, e, link, t, b, c);
        return;
    }
    if (b != NULL && b->type != link->type) {
        sx_body_set_type(w, link->body, b->type);
        link->type = b->type;
    }
    if (b != NULL && b->bullet != link->bullet) {
        sx_body_set_bullet(w, link->body, b->bullet);
        link->bullet = b->bullet;
    }
    if (t->position.x != link->position.x || t->position.y != link->position.y ||
        t->angle != link->angle) {
        sx_body_set_transform(w, link->body, t->position, t->angle);
        link->position = t->position;
        link->angle = t->angle;
        link->rotation = sx_rot_make(t->angle);
    }
    if (b != NULL) {
        if (b->velocity.x != link->velocity.x || b->velocity.y != link->velocity.y) {
            sx_body_set_linear_velocity(w, link->body, b->velocity);
            link->velocity = b->velocity;
        }
        if (b->angular_velocity != link->angular_velocity) {
            sx_body_set_angular_velocity(w, link->body, b->angular_velocity);
            link->angular_velocity = b->angular_velocity;
        }
    }
    if (c != NULL && (!link->has_collider || link->collider_dirty)) {
        if (link->has_collider) sx_destroy_collider(w, link->collider);
        sx_ecs_attach(st, link, b, c);
    }
}

static void sx_ecs_sync_statics(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    const SxTransform *t = ecs_field(it, SxTransform, 0);
    const SxCollider *c = ecs_field(it, SxCollider, 1);
    int32_t i;
    for (i = 0; i < it->count; ++i) {
        ecs_entity_t e = it->entities[i];
        sx_ecs_link *link = sx_ecs_find(st, e);
        if (link == NULL) {
            link = sx_ecs_link_new(st, e);
            if (link != NULL) sx_ecs_build(st, e, link, &t[i], NULL, &c[i]);
        } else {
            sx_ecs_push(st, e, link, &t[i], NULL, &c[i]);
        }
    }
}

static void sx_ecs_sync_bodies(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    const SxTransform *t = ecs_field(it, SxTransform, 0);
    SxBody *b = ecs_field(it, SxBody, 1);
    const SxCollider *c = ecs_field(it, SxCollider, 2);
    sx_world *w = st->world;
    int32_t i;
    for (i = 0; i < it->count; ++i) {
        ecs_entity_t e = it->entities[i];
        const SxCollider *ci = c != NULL ? &c[i] : NULL;
        sx_ecs_link *link = sx_ecs_find(st, e);
        SxBody *bi = &b[i];
        if (link == NULL) {
            link = sx_ecs_link_new(st, e);
            if (link == NULL) continue;
            sx_ecs_build(st, e, link, &t[i], bi, ci);
        } else {
            sx_ecs_push(st, e, link, &t[i], bi, ci);
        }
        if (bi->force.x != SX_R(0.0) || bi->force.y != SX_R(0.0)) {
            sx_body_apply_force(w, link->body, bi->force);
        }
        if (bi->torque != SX_R(0.0)) sx_body_apply_torque(w, link->body, bi->torque);
        if (bi->impulse.x != SX_R(0.0) || bi->impulse.y != SX_R(0.0)) {
            sx_body_apply_impulse(w, link->body, bi->impulse);
        }
        if (bi->angular_impulse != SX_R(0.0)) {
            sx_body_apply_angular_impulse(w, link->body, bi->angular_impulse);
        }
        /* cleared only where set: a resting component's cache line is not
         * written each step */
        if (bi->force.x != SX_R(0.0) || bi->force.y != SX_R(0.0)) bi->force = sx_v2_zero();
        if (bi->torque != SX_R(0.0)) bi->torque = SX_R(0.0);
        if (bi->impulse.x != SX_R(0.0) || bi->impulse.y != SX_R(0.0)) bi->impulse = sx_v2_zero();
        if (bi->angular_impulse != SX_R(0.0)) bi->angular_impulse = SX_R(0.0);
    }
}

/* the stage length the driver hands each system: the step or the sub-step */
static sx_real sx_ecs_h(const ecs_iter_t *it) {
    return it->param != NULL ? *(const sx_real *)it->param : (sx_real)it->delta_time;
}

static void sx_ecs_begin_step(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    SxPhysicsWorld *pw = ecs_field(it, SxPhysicsWorld, 0);
    int32_t i;
    /* what died in a callback of the locked world (stale handles, if the
     * body went first or the world was rebuilt, are answered harmlessly) */
    for (i = 0; i < st->doomed_count; ++i) {
        if (st->doomed[i].collider) {
            sx_destroy_collider(st->world, sx_collider_id_from_u64(st->doomed[i].id));
        } else {
            sx_destroy_body(st->world, sx_body_id_from_u64(st->doomed[i].id));
        }
    }
    st->doomed_count = 0;
    sx_world_begin_step(pw->world, sx_ecs_h(it));
}

/* ---- the stages: the world's public functions, nothing else --------------- */

static void sx_ecs_apply_forces_system(ecs_iter_t *it) {
    sx_world_apply_forces(ecs_field(it, SxPhysicsWorld, 0)->world, sx_ecs_h(it));
}
static void sx_ecs_collide_system(ecs_iter_t *it) {
    sx_world_collide(ecs_field(it, SxPhysicsWorld, 0)->world);
}
static void sx_ecs_solve_system(ecs_iter_t *it) {
    sx_world_solve(ecs_field(it, SxPhysicsWorld, 0)->world, sx_ecs_h(it));
}
static void sx_ecs_integrate_system(ecs_iter_t *it) {
    sx_world_integrate(ecs_field(it, SxPhysicsWorld, 0)->world, sx_ecs_h(it));
}
static void sx_ecs_separate_system(ecs_iter_t *it) {
    sx_world_separate(ecs_field(it, SxPhysicsWorld, 0)->world, sx_ecs_h(it));
}

/* ---- PostStep: world -> components, contacts, events ---------------------- */

static void sx_ecs_end_step(ecs_iter_t *it) {
    sx_world *w = ecs_field(it, SxPhysicsWorld, 0)->world;
    const SxPhysicsSettings *s = ecs_field(it, SxPhysicsSettings, 1);
    sx_world_continuous(w);
    sx_world_clear_forces(w);
    if (s->enable_sleep) sx_world_update_sleep(w, sx_ecs_h(it));
}

static void sx_ecs_copy_out(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    SxTransform *t = ecs_field(it, SxTransform, 0);
    SxBody *b = ecs_field(it, SxBody, 1);
    sx_world *w = st->world;
    int32_t i;
    for (i = 0; i < it->count; ++i) {
        sx_ecs_link *link = sx_ecs_find(st, it->entities[i]);
        sx_body_state state;
        if (link == NULL || sx_body_get_state(w, link->body, &state) != SX_OK) continue;
        if (state.transform.q.c != link->rotation.c || state.transform.q.s != link->rotation.s) {
            link->rotation = state.transform.q;
            link->angle = sx_rot_angle(state.transform.q);
        }
        link->position = state.transform.p;
        link->velocity = state.linear_velocity;
        link->angular_velocity = state.angular_velocity;
        t[i].position = link->position;
        t[i].angle = link->angle;
        b[i].velocity = link->velocity;
        b[i].angular_velocity = link->angular_velocity;
        b[i].awake = state.awake;
    }
}

static bool sx_ecs_contact_before(const SxContact *a, const SxContact *b) {
    return a->entity_a < b->entity_a || (a->entity_a == b->entity_a && a->entity_b < b->entity_b);
}

static int sx_ecs_contact_cmp(const void *pa, const void *pb) {
    const SxContact *a = (const SxContact *)pa;
    const SxContact *b = (const SxContact *)pb;
    return sx_ecs_contact_before(a, b) ? -1 : sx_ecs_contact_before(b, a) ? 1 : 0;
}

/* Sorts items[0, n) by (entity_a, entity_b), stable, through scratch (n
 * items). The world lists its contacts by collider pair, which follows the
 * entities' order wherever they were made in one order, so the list comes
 * nearly sorted: runs already in order are found and merged pairwise. qsort
 * took a fresh buffer from malloc each step (pages the kernel zeroes, for
 * a large list) and called the comparison through a pointer. */
static void sx_ecs_sort_contacts(SxContact *items, int32_t n, SxContact *scratch) {
    SxContact *src = items, *dst = scratch;
    int32_t j = 1;
    while (j < n && !sx_ecs_contact_before(&items[j], &items[j - 1]))
        ++j;
    if (j >= n) return;
    for (;;) {
        int32_t i = 0, runs = 0;
        while (i < n) {
            /* one run [i, mid), the next [mid, end), merged into dst */
            int32_t mid = i + 1, end, a, b, k = i;
            while (mid < n && !sx_ecs_contact_before(&src[mid], &src[mid - 1]))
                ++mid;
            end = mid < n ? mid + 1 : n;
            while (end < n && !sx_ecs_contact_before(&src[end], &src[end - 1]))
                ++end;
            for (a = i, b = mid; a < mid && b < end;)
                dst[k++] = sx_ecs_contact_before(&src[b], &src[a]) ? src[b++] : src[a++];
            while (a < mid)
                dst[k++] = src[a++];
            while (b < end)
                dst[k++] = src[b++];
            ++runs;
            i = end;
        }
        /* the pass's merged runs are in dst */
        if (runs <= 1) {
            if (dst != items) memcpy(items, dst, (size_t)n * sizeof(*items));
            return;
        }
        src = dst;
        dst = dst == scratch ? items : scratch;
    }
}

static const SxContact *sx_ecs_find_contact(const SxContact *items, int32_t count, ecs_entity_t a,
                                            ecs_entity_t b) {
    SxContact key;
    memset(&key, 0, sizeof(key));
    key.entity_a = a < b ? a : b;
    key.entity_b = a < b ? b : a;
    if (count == 0) return NULL;
    return (const SxContact *)bsearch(&key, items, (size_t)count, sizeof(SxContact),
                                      sx_ecs_contact_cmp);
}

/* Emits one event on each entity of a pair, normal from self to other. */
static void sx_ecs_emit_pair(ecs_world_t *world, ecs_entity_t event, ecs_entity_t a, ecs_entity_t b,
                             const SxContact *c) {
    ecs_id_t id = ecs_id(SxCollider);
    ecs_type_t type;
    SxContactEvent ev;
    int side;
    type.array = &id;
    type.count = 1;
    for (side = 0; side < 2; ++side) {
        ecs_entity_t self = side == 0 ? a : b;
        ecs_entity_t other = side == 0 ? b : a;
        ecs_event_desc_t desc;
        if (!ecs_is_alive(world, self) || !ecs_has(world, self, SxCollider)) continue;
        memset(&ev, 0, sizeof(ev));
        ev.self = self;
        ev.other = other;
        if (c != NULL) {
            ev.point = c->point;
            ev.normal = self == c->entity_a ? c->normal : sx_neg(c->normal);
        }
        memset(&desc, 0, sizeof(desc));
        desc.event = event;
        desc.ids = &type;
        desc.entity = self;
        desc.param = &ev;
        /* ecs_enqueue copies the payload into the command queue when the
         * world is deferred (inside a system) and emits now otherwise. */
        ecs_enqueue(world, &desc);
    }
}

static bool sx_ecs_reserve(SxContact **items, int32_t *cap, int32_t count) {
    SxContact *grown;
    int32_t n = *cap ? *cap : 64;
    if (count <= *cap) return true;
    while (n < count)
        n *= 2;
    grown = (SxContact *)realloc(*items, (size_t)n * sizeof(SxContact));
    if (grown == NULL) return false;
    *items = grown;
    *cap = n;
    return true;
}

static void sx_ecs_publish_contacts(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    SxContacts *out = ecs_field(it, SxContacts, 0);
    sx_world *w = st->world;
    int32_t n = sx_world_contact_count(w), i, kept = 0;
    sx_collider_id prev_a = {0, 0}, prev_b = {0, 0};
    sx_contact_events events;
    sx_sensor_events sensors;
    SxContact *swap_items = st->previous;
    int32_t swap_cap = st->previous_cap;

    /* last step's buffer becomes `previous` (for end events) */
    st->previous = st->contacts;
    st->previous_cap = st->contact_cap;
    st->previous_count = st->contact_count;
    st->contacts = swap_items;
    st->contact_cap = swap_cap;
    st->contact_count = 0;
    if (!sx_ecs_reserve(&st->contacts, &st->contact_cap, n)) n = 0;
    for (i = 0; i < n;) {
        /* in batches: the light read walks the world's list once */
        sx_contact_pair batch[SX_ECS_CONTACT_BATCH];
        int32_t got = sx_world_get_contact_pairs(w, i, batch, SX_ECS_CONTACT_BATCH), k;
        if (got == 0) break;
        i += got;
        for (k = 0; k < got; ++k) {
            const sx_contact_pair *d = &batch[k];
            SxContact *c = &st->contacts[kept];
            ecs_entity_t ea, eb;
            /* a compound's part pairs follow one another: one SxContact per
             * collider pair, with the first part pair's normal and point and
             * every part pair's points counted */
            if (kept > 0 && d->collider_a.index == prev_a.index &&
                d->collider_a.generation == prev_a.generation &&
                d->collider_b.index == prev_b.index &&
                d->collider_b.generation == prev_b.generation) {
                st->contacts[kept - 1].point_count += d->count;
                continue;
            }
            prev_a = d->collider_a;
            prev_b = d->collider_b;
            ea = sx_ecs_entity_at(st, d->body_a);
            eb = sx_ecs_entity_at(st, d->body_b);
            c->point_count = d->count;
            c->point = d->points[0];
            if (ea <= eb) {
                c->entity_a = ea;
                c->entity_b = eb;
                c->normal = d->normal;
            } else {
                c->entity_a = eb;
                c->entity_b = ea;
                c->normal = sx_neg(d->normal);
            }
            ++kept;
        }
    }
    if (kept > 1) {
        if (sx_ecs_reserve(&st->scratch, &st->scratch_cap, kept)) {
            sx_ecs_sort_contacts(st->contacts, kept, st->scratch);
        } else {
            qsort(st->contacts, (size_t)kept, sizeof(SxContact), sx_ecs_contact_cmp);
        }
    }
    st->contact_count = kept;
    out->items = st->contacts;
    out->count = kept;

    events = sx_world_get_contact_events(w);
    for (i = 0; i < events.begin_count; ++i) {
        ecs_entity_t a = sx_ecs_entity_at(st, events.begin[i].body_a);
        ecs_entity_t b = sx_ecs_entity_at(st, events.begin[i].body_b);
        if (a == 0 || b == 0) continue;
        sx_ecs_emit_pair(it->world, SxContactBegin, a, b,
                         sx_ecs_find_contact(st->contacts, st->contact_count, a, b));
    }
    for (i = 0; i < events.end_count; ++i) {
        ecs_entity_t a = sx_ecs_entity_at(st, events.end[i].body_a);
        ecs_entity_t b = sx_ecs_entity_at(st, events.end[i].body_b);
        if (a == 0 || b == 0) continue;
        sx_ecs_emit_pair(it->world, SxContactEnd, a, b,
                         sx_ecs_find_contact(st->previous, st->previous_count, a, b));
    }
    sensors = sx_world_get_sensor_events(w);
    for (i = 0; i < sensors.begin_count; ++i) {
        ecs_entity_t a = sx_ecs_entity_at(st, sensors.begin[i].sensor_body);
        ecs_entity_t b = sx_ecs_entity_at(st, sensors.begin[i].visitor_body);
        if (a != 0 && b != 0) sx_ecs_emit_pair(it->world, SxSensorBegin, a, b, NULL);
    }
    for (i = 0; i < sensors.end_count; ++i) {
        ecs_entity_t a = sx_ecs_entity_at(st, sensors.end[i].sensor_body);
        ecs_entity_t b = sx_ecs_entity_at(st, sensors.end[i].visitor_body);
        if (a != 0 && b != 0) sx_ecs_emit_pair(it->world, SxSensorEnd, a, b, NULL);
    }
}

/* ---- the fixed-step driver ------------------------------------------------- */

static int sx_ecs_entity_cmp(const void *pa, const void *pb) {
    ecs_entity_t a = *(const ecs_entity_t *)pa, b = *(const ecs_entity_t *)pb;
    return a < b ? -1 : a > b;
}

/* Runs every system whose DependsOn is `tag`, in entity-id order. */
static void sx_ecs_run_phase(ecs_world_t *world, ecs_entity_t tag, sx_real h) {
    ecs_entity_t systems[SX_ECS_MAX_PHASE_SYSTEMS];
    int32_t n = 0, i;
    ecs_iter_t it = ecs_each_id(world, ecs_pair(EcsDependsOn, tag));
    while (ecs_each_next(&it)) {
        for (i = 0; i < it.count && n < SX_ECS_MAX_PHASE_SYSTEMS; ++i) {
            if (ecs_has_id(world, it.entities[i], EcsSystem)) systems[n++] = it.entities[i];
        }
    }
    qsort(systems, (size_t)n, sizeof(systems[0]), sx_ecs_entity_cmp);
    for (i = 0; i < n; ++i)
        ecs_run(world, systems[i], (ecs_ftime_t)h, &h);
}

static void sx_ecs_drive(ecs_iter_t *it) {
    sx_ecs_state *st = (sx_ecs_state *)it->ctx;
    const SxPhysicsSettings *s = ecs_field(it, SxPhysicsSettings, 0);
    sx_real fixed = s->fixed_time_step;
    int32_t sub_steps = s->sub_steps, max_steps = s->max_steps_per_frame, steps, k, j;
    sx_vec2 g = sx_world_get_gravity(st->world);
    SxPhysicsTime *clock = ecs_field(it, SxPhysicsTime, 1);
    sx_world_def now;

    if (!(fixed > SX_R(0.0)) || sub_steps < 1 || sub_steps > SX_MAX_SUB_STEPS || max_steps < 1) {
        return;
    }
    if (g.x != s->gravity.x || g.y != s->gravity.y) sx_world_set_gravity(st->world, s->gravity);
    sx_world_get_def(st->world, &now);
    if (now.velocity_iterations != s->velocity_iterations ||
        now.position_iterations != s->position_iterations) {
        /* refused counts (< 1, < 0) leave the world's as they were */
        sx_world_set_iterations(st->world, s->velocity_iterations, s->position_iterations);
    }
    if (now.enable_continuous != s->enable_continuous) {
        sx_world_enable_continuous(st->world, s->enable_continuous);
    }
    st->accumulator += (double)it->delta_time;
    steps = (int32_t)(st->accumulator / (double)fixed + SX_ECS_TICK_TOLERANCE);
    if (steps > max_steps) {
        steps = max_steps;
        st->accumulator = 0.0;
    } else {
        st->accumulator -= (double)steps * (double)fixed;
        if (st->accumulator < 0.0) st->accumulator = 0.0;
    }
    for (k = 0; k < steps; ++k) {
        /* the same h as sx_world_step(world, fixed) */
        sx_real h = fixed / (sx_real)sub_steps;
        sx_ecs_run_phase(it->world, SxPhysicsPreStep, fixed);
        sx_ecs_run_phase(it->world, SxPhysicsCollide, fixed);
        for (j = 0; j < sub_steps; ++j) {
            sx_ecs_run_phase(it->world, SxPhysicsApplyForces, h);
            sx_ecs_run_phase(it->world, SxPhysicsSolve, h);
            sx_ecs_run_phase(it->world, SxPhysicsIntegrate, h);
            sx_ecs_run_phase(it->world, SxPhysicsSeparate, h);
        }
        sx_ecs_run_phase(it->world, SxPhysicsPostStep, fixed);
        ++st->steps;
    }
    clock->alpha = (sx_real)(st->accumulator / (double)fixed);
    if (clock->alpha >= SX_R(1.0)) clock->alpha = SX_R(0.0); /* the tick tolerance's rounding */
    clock->frame_steps = steps;
    clock->steps = st->steps;
}

/* ---- public helpers ----------------------------------------------------------- */

SxBody sx_ecs_body(sx_body_type type) {
    SxBody b;
    memset(&b, 0, sizeof(b));
    b.type = type;
    b.gravity_scale = SX_R(1.0);
    b.awake = true;
    return b;
}

SxCollider sx_ecs_collider(sx_shape shape) {
    sx_collider_def def = sx_default_collider_def();
    SxCollider c;
    memset(&c, 0, sizeof(c));
    c.shape = shape;
    c.density = def.density;
    c.friction = def.friction;
    c.restitution = def.restitution;
    c.filter = def.filter;
    c.sensor = def.sensor;
    return c;
}

sx_status sx_ecs_set_outline(ecs_world_t *world, ecs_entity_t e, const sx_vec2 *points,
                             int32_t count, const SxCollider *base) {
    size_t scratch_bytes;
    void *scratch;
    sx_shape *shapes;
    sx_compound_part *parts;
    SxCollider c;
    int n = 0, i;
    sx_status s;
    if (world == NULL || points == NULL || count < 3 || !ecs_is_alive(world, e)) {
        return SX_ERR_INVALID_ARG;
    }
    scratch_bytes = sx_decompose_scratch_bytes(count);
    if (scratch_bytes == 0) return SX_ERR_CAPACITY;
    scratch = malloc(scratch_bytes);
    shapes = (sx_shape *)malloc((size_t)(count - 2) * sizeof(sx_shape));
    if (scratch == NULL || shapes == NULL) {
        free(scratch);
        free(shapes);
        return SX_ERR_NO_MEMORY;
    }
    s = sx_decompose_polygon(points, count, scratch, scratch_bytes, shapes, count - 2, &n, NULL);
    free(scratch);
    parts = s == SX_OK && n > 0 ? (sx_compound_part *)malloc((size_t)n * sizeof(*parts)) : NULL;
    if (s == SX_OK && parts == NULL) s = n > 0 ? SX_ERR_NO_MEMORY : SX_ERR_DEGENERATE;
    if (s != SX_OK) {
        free(shapes);
        return s;
    }
    for (i = 0; i < n; ++i)
        parts[i] = sx_compound_part_make(shapes[i], sx_xform_identity());
    free(shapes);
    c = base != NULL ? *base : sx_ecs_collider(sx_circle_shape(sx_v2_zero(), SX_R(0.5)));
    c.shape = parts[0].shape;
    c.parts = parts;
    c.part_count = n;
    /* the copy hook copies the parts into the component */
    ecs_set_ptr(world, e, SxCollider, &c);
    free(parts);
    return SX_OK;
}

void sx_ecs_apply_force(ecs_world_t *world, ecs_entity_t e, sx_vec2 force) {
    SxBody *b;
    if (world == NULL || !ecs_is_alive(world, e)) return;
    b = ecs_get_mut(world, e, SxBody);
    if (b != NULL) b->force = sx_add(b->force, force);
}

void sx_ecs_apply_impulse(ecs_world_t *world, ecs_entity_t e, sx_vec2 impulse) {
    SxBody *b;
    if (world == NULL || !ecs_is_alive(world, e)) return;
    b = ecs_get_mut(world, e, SxBody);
    if (b != NULL) b->impulse = sx_add(b->impulse, impulse);
}

sx_world *sx_ecs_world(const ecs_world_t *world) {
    const SxPhysicsWorld *pw;
    if (world == NULL || ecs_id(SxPhysicsWorld) == 0) return NULL;
    pw = ecs_singleton_get(world, SxPhysicsWorld);
    return pw != NULL ? pw->world : NULL;
}

/* The module's state in this flecs world (SxBody's hooks own it), or NULL. */
static const sx_ecs_state *sx_ecs_state_of(const ecs_world_t *world) {
    const ecs_type_hooks_t *hooks;
    if (world == NULL || ecs_id(SxBody) == 0) return NULL;
    hooks = ecs_get_hooks(world, SxBody);
    return hooks != NULL ? (const sx_ecs_state *)hooks->ctx : NULL;
}

int64_t sx_ecs_step_count(const ecs_world_t *world) {
    const sx_ecs_state *st = sx_ecs_state_of(world);
    return st != NULL ? st->steps : 0;
}

ecs_entity_t sx_ecs_entity_of(const ecs_world_t *world, sx_body_id body) {
    const sx_ecs_state *st = sx_ecs_state_of(world);
    if (st == NULL || !sx_body_is_valid(st->world, body)) return 0;
    return sx_ecs_entity_at(st, body);
}

ecs_entity_t sx_ecs_cast_ray(const ecs_world_t *world, const sx_ray_input *ray,
                             sx_world_ray_hit *out) {
    const sx_ecs_state *st = sx_ecs_state_of(world);
    sx_world_ray_hit hit;
    if (out != NULL) memset(out, 0, sizeof(*out));
    if (st == NULL || !sx_world_cast_ray(st->world, ray, &hit)) return 0;
    if (out != NULL) *out = hit;
    return sx_ecs_entity_of(world, hit.body);
}

ecs_entity_t sx_ecs_cast_shape(const ecs_world_t *world, const sx_shape *shape, sx_xform xf,
                               sx_vec2 translation, const sx_filter *filter,
                               sx_world_shape_hit *out) {
    const sx_ecs_state *st = sx_ecs_state_of(world);
    sx_world_shape_hit hit;
    if (out != NULL) memset(out, 0, sizeof(*out));
    if (st == NULL || !sx_world_cast_shape(st->world, shape, xf, translation, filter, &hit)) {
        return 0;
    }
    if (out != NULL) *out = hit;
    return sx_ecs_entity_of(world, hit.body);
}

sx_body_id sx_ecs_body_of(const ecs_world_t *world, ecs_entity_t e) {
    const sx_ecs_state *st = sx_ecs_state_of(world);
    const sx_ecs_link *link = st != NULL ? sx_ecs_find(st, e) : NULL;
    sx_body_id none = {0, 0};
    return link != NULL && sx_body_is_valid(st->world, link->body) ? link->body : none;
}

/* ---- import ------------------------------------------------------------------- */

static void sx_ecs_reflect(ecs_world_t *world) {
#ifdef SX_DOUBLE
    ecs_entity_t real = ecs_id(ecs_f64_t);
#else
    ecs_entity_t real = ecs_id(ecs_f32_t);
#endif
    ecs_entity_t vec2 =
        ecs_struct(world, {.entity = ecs_entity(world, {.name = "SxVec2"}),
                           .members = {{.name = "x", .type = real}, {.name = "y", .type = real}}});
    ecs_struct(world,
               {.entity = ecs_id(SxTransform),
                .members = {{.name = "position", .type = vec2}, {.name = "angle", .type = real}}});
    ecs_struct(world, {.entity = ecs_id(SxBody),
                       .members = {{.name = "type", .type = ecs_id(ecs_i32_t)},
                                   {.name = "velocity", .type = vec2},
                                   {.name = "angular_velocity", .type = real},
                                   {.name = "mass", .type = real},
                                   {.name = "force", .type = vec2},
                                   {.name = "torque", .type = real},
                                   {.name = "impulse", .type = vec2},
                                   {.name = "angular_impulse", .type = real},
                                   {.name = "linear_damping", .type = real},
                                   {.name = "angular_damping", .type = real},
                                   {.name = "gravity_scale", .type = real},
                                   {.name = "fixed_rotation", .type = ecs_id(ecs_bool_t)},
                                   {.name = "bullet", .type = ecs_id(ecs_bool_t)},
                                   {.name = "awake", .type = ecs_id(ecs_bool_t)}}});
    ecs_struct(world, {.entity = ecs_id(SxPhysicsSettings),
                       .members = {{.name = "gravity", .type = vec2},
                                   {.name = "fixed_time_step", .type = real},
                                   {.name = "sub_steps", .type = ecs_id(ecs_i32_t)},
                                   {.name = "max_steps_per_frame", .type = ecs_id(ecs_i32_t)},
                                   {.name = "enable_sleep", .type = ecs_id(ecs_bool_t)},
                                   {.name = "velocity_iterations", .type = ecs_id(ecs_i32_t)},
                                   {.name = "position_iterations", .type = ecs_id(ecs_i32_t)},
                                   {.name = "enable_continuous", .type = ecs_id(ecs_bool_t)}}});
    ecs_struct(world, {.entity = ecs_id(SxPhysicsTime),
                       .members = {{.name = "alpha", .type = real},
                                   {.name = "frame_steps", .type = ecs_id(ecs_i32_t)},
                                   {.name = "steps", .type = ecs_id(ecs_i64_t)}}});
}

static ecs_entity_t sx_ecs_event_type(ecs_world_t *world, const char *name) {
    ecs_entity_desc_t edesc;
    ecs_component_desc_t cdesc;
    memset(&edesc, 0, sizeof(edesc));
    memset(&cdesc, 0, sizeof(cdesc));
    edesc.name = name;
    cdesc.entity = ecs_entity_init(world, &edesc);
    cdesc.type.size = ECS_SIZEOF(SxContactEvent);
    cdesc.type.alignment = ECS_ALIGNOF(SxContactEvent);
    return ecs_component_init(world, &cdesc);
}

/* A system run by the driver (not by the main pipeline) under `tag`. */
static void sx_ecs_system(ecs_world_t *world, const char *name, ecs_entity_t tag,
                          ecs_iter_action_t fn, sx_ecs_state *st, const ecs_term_t *terms,
                          int32_t term_count) {
    ecs_system_desc_t desc;
    ecs_entity_desc_t edesc;
    ecs_id_t add[2];
    int32_t i;
    memset(&desc, 0, sizeof(desc));
    memset(&edesc, 0, sizeof(edesc));
    add[0] = ecs_dependson(tag);
    add[1] = 0;
    edesc.name = name;
    edesc.add = add;
    desc.entity = ecs_entity_init(world, &edesc);
    for (i = 0; i < term_count; ++i)
        desc.query.terms[i] = terms[i];
    desc.callback = fn;
    desc.ctx = st;
    ecs_system_init(world, &desc);
}

void SepaxPhysicsImport(ecs_world_t *world) {
    sx_world_def def = sx_default_world_def();
    SxPhysicsSettings settings;
    sx_ecs_state *st;
    ecs_term_t world_term, terms[3];

    ECS_MODULE(world, SepaxPhysics);
    ECS_IMPORT(world, FlecsMeta);

    ECS_COMPONENT_DEFINE(world, SxTransform);
    ECS_COMPONENT_DEFINE(world, SxBody);
    ECS_COMPONENT_DEFINE(world, SxCollider);
    ECS_COMPONENT_DEFINE(world, SxPhysicsSettings);
    ECS_COMPONENT_DEFINE(world, SxPhysicsTime);
    ECS_COMPONENT_DEFINE(world, SxContacts);
    ECS_COMPONENT_DEFINE(world, SxPhysicsWorld);
    ECS_COMPONENT_DEFINE(world, SxContactEvent);
    ECS_TAG_DEFINE(world, SxPhysicsPreStep);
    ECS_TAG_DEFINE(world, SxPhysicsApplyForces);
    ECS_TAG_DEFINE(world, SxPhysicsCollide);
    ECS_TAG_DEFINE(world, SxPhysicsSolve);
    ECS_TAG_DEFINE(world, SxPhysicsIntegrate);
    ECS_TAG_DEFINE(world, SxPhysicsSeparate);
    ECS_TAG_DEFINE(world, SxPhysicsPostStep);
    /* events with a payload must be components of the payload's type */
    SxContactBegin = sx_ecs_event_type(world, "SxContactBegin");
    SxContactEnd = sx_ecs_event_type(world, "SxContactEnd");
    SxSensorBegin = sx_ecs_event_type(world, "SxSensorBegin");
    SxSensorEnd = sx_ecs_event_type(world, "SxSensorEnd");
    ECS_TAG_DEFINE(world, SxPhysicsUpdate);
    ecs_add_id(world, SxPhysicsUpdate, EcsPhase);
    ecs_add_pair(world, SxPhysicsUpdate, EcsDependsOn, EcsOnUpdate);
    sx_ecs_reflect(world);

    /* a body or a collider brings its transform along */
    ecs_add_pair(world, ecs_id(SxBody), EcsWith, ecs_id(SxTransform));
    ecs_add_pair(world, ecs_id(SxCollider), EcsWith, ecs_id(SxTransform));

    st = (sx_ecs_state *)calloc(1, sizeof(*st));
    ecs_assert(st != NULL, ECS_OUT_OF_MEMORY, NULL);
    st->world = sx_world_create(&def);
    ecs_assert(st->world != NULL, ECS_OUT_OF_MEMORY, NULL);

    /* SxBody's hooks own the state: its ctx_free runs after every on_remove */
    ecs_set_hooks(world, SxBody,
                  {.on_remove = sx_ecs_body_removed, .ctx = st, .ctx_free = sx_ecs_state_free});
    ecs_set_hooks(world, SxCollider,
                  {.ctor = sx_ecs_collider_ctor,
                   .dtor = sx_ecs_collider_dtor,
                   .copy = sx_ecs_collider_copy,
                   .move = sx_ecs_collider_move,
                   .on_set = sx_ecs_collider_set,
                   .on_remove = sx_ecs_collider_removed,
                   .ctx = st});

    memset(&settings, 0, sizeof(settings));
    settings.gravity = def.gravity;
    settings.fixed_time_step = SX_R(1.0) / SX_R(60.0);
    settings.sub_steps = def.sub_steps;
    settings.max_steps_per_frame = 8;
    settings.enable_sleep = def.enable_sleep;
    settings.velocity_iterations = def.velocity_iterations;
    settings.position_iterations = def.position_iterations;
    settings.enable_continuous = def.enable_continuous;
    ecs_singleton_set_ptr(world, SxPhysicsSettings, &settings);
    ecs_singleton_set(world, SxPhysicsTime, {SX_R(0.0), 0, 0});
    ecs_singleton_set(world, SxPhysicsWorld, {st->world});
    ecs_singleton_set(world, SxContacts, {NULL, 0});

    memset(&world_term, 0, sizeof(world_term));
    world_term.id = ecs_id(SxPhysicsWorld);
    world_term.src.id = ecs_id(SxPhysicsWorld);
    world_term.inout = EcsInOut;

    /* the driver */
    memset(terms, 0, sizeof(terms));
    terms[0].id = ecs_id(SxPhysicsSettings);
    terms[0].src.id = ecs_id(SxPhysicsSettings);
    terms[0].inout = EcsIn;
    terms[1].id = ecs_id(SxPhysicsTime);
    terms[1].src.id = ecs_id(SxPhysicsTime);
    terms[1].inout = EcsOut;
    {
        ecs_system_desc_t desc;
        ecs_entity_desc_t edesc;
        ecs_id_t add[2];
        memset(&desc, 0, sizeof(desc));
        memset(&edesc, 0, sizeof(edesc));
        add[0] = ecs_dependson(SxPhysicsUpdate);
        add[1] = 0;
        edesc.name = "SxFixedStep";
        edesc.add = add;
        desc.entity = ecs_entity_init(world, &edesc);
        desc.query.terms[0] = terms[0];
        desc.query.terms[1] = terms[1];
        desc.callback = sx_ecs_drive;
        desc.ctx = st;
        ecs_system_init(world, &desc);
    }

    /* PreStep: events of the step start empty, then static geometry, then
     * bodies (so a fresh scene's bodies are created in that order) */
    sx_ecs_system(world, "SxBeginStep", SxPhysicsPreStep, sx_ecs_begin_step, st, &world_term, 1);
    memset(terms, 0, sizeof(terms));
    terms[0].id = ecs_id(SxTransform);
    terms[0].inout = EcsIn;
    terms[1].id = ecs_id(SxCollider);
    terms[1].inout = EcsIn;
    terms[2].id = ecs_id(SxBody);
    terms[2].oper = EcsNot;
    terms[2].inout = EcsInOutNone;
    sx_ecs_system(world, "SxSyncStatics", SxPhysicsPreStep, sx_ecs_sync_statics, st, terms, 3);
    memset(terms, 0, sizeof(terms));
    terms[0].id = ecs_id(SxTransform);
    terms[0].inout = EcsIn;
    terms[1].id = ecs_id(SxBody);
    terms[1].inout = EcsInOut;
    terms[2].id = ecs_id(SxCollider);
    terms[2].oper = EcsOptional;
    terms[2].inout = EcsIn;
    sx_ecs_system(world, "SxSyncBodies", SxPhysicsPreStep, sx_ecs_sync_bodies, st, terms, 3);

    sx_ecs_system(world, "SxApplyForces", SxPhysicsApplyForces, sx_ecs_apply_forces_system, st,
                  &world_term, 1);
    sx_ecs_system(world, "SxCollide", SxPhysicsCollide, sx_ecs_collide_system, st, &world_term, 1);
    sx_ecs_system(world, "SxSolve", SxPhysicsSolve, sx_ecs_solve_system, st, &world_term, 1);
    sx_ecs_system(world, "SxIntegrate", SxPhysicsIntegrate, sx_ecs_integrate_system, st,
                  &world_term, 1);
    sx_ecs_system(world, "SxSeparate", SxPhysicsSeparate, sx_ecs_separate_system, st, &world_term,
                  1);

    memset(terms, 0, sizeof(terms));
    terms[0] = world_term;
    terms[1].id = ecs_id(SxPhysicsSettings);
    terms[1].src.id = ecs_id(SxPhysicsSettings);
    terms[1].inout = EcsIn;
    sx_ecs_system(world, "SxEndStep", SxPhysicsPostStep, sx_ecs_end_step, st, terms, 2);
    memset(terms, 0, sizeof(terms));
    terms[0].id = ecs_id(SxTransform);
    terms[0].inout = EcsOut;
    terms[1].id = ecs_id(SxBody);
    terms[1].inout = EcsInOut;
    sx_ecs_system(world, "SxCopyOut", SxPhysicsPostStep, sx_ecs_copy_out, st, terms, 2);
    memset(terms, 0, sizeof(terms));
    terms[0].id = ecs_id(SxContacts);
    terms[0].src.id = ecs_id(SxContacts);
    terms[0].inout = EcsOut;
    sx_ecs_system(world, "SxPublishContacts", SxPhysicsPostStep, sx_ecs_publish_contacts, st, terms,
                  1);
}
