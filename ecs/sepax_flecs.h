/* sepax flecs module — rigid-body physics for flecs 4 worlds.
 *
 * A whole program (make test compiles this block as C, the next one as C++
 * with the flecs C++ API, and runs both):
 *
 * ```c
 * #include <stdio.h>
 * #include "sepax_flecs.h"
 *
 * static void on_contact(ecs_iter_t *it) {
 *     const SxContactEvent *ev = it->param;
 *     printf("%s touches %s\n", ecs_get_name(it->world, ev->self),
 *            ecs_get_name(it->world, ev->other));
 * }
 *
 * int main(void) {
 *     ecs_world_t *world = ecs_init();
 *     ECS_IMPORT(world, SepaxPhysics);
 *     ecs_entity_t ground = ecs_entity(world, {.name = "ground"});
 *     ecs_entity_t box = ecs_entity(world, {.name = "box"});
 *     SxCollider slab = sx_ecs_collider(sx_box_shape(20, 1)); // no SxBody: static
 *     SxBody body = sx_ecs_body(SX_BODY_DYNAMIC);
 *     SxCollider cube = sx_ecs_collider(sx_box_shape(0.5, 0.5));
 *     ecs_set(world, ground, SxTransform, {.position = {0, -1}});
 *     ecs_set_ptr(world, ground, SxCollider, &slab);
 *     ecs_set(world, box, SxTransform, {.position = {0, 4}});
 *     ecs_set_ptr(world, box, SxBody, &body);
 *     ecs_set_ptr(world, box, SxCollider, &cube);
 *     ecs_observer(world, {.query.terms = {{.id = ecs_id(SxCollider)}},
 *                          .events = {SxContactBegin},
 *                          .callback = on_contact});
 *     for (int i = 0; i < 120; ++i) ecs_progress(world, 1.0f / 60.0f);
 *     printf("box at y = %.2f\n", (double)ecs_get(world, box, SxTransform)->position.y);
 *     return ecs_fini(world);
 * }
 * ```
 *
 * ```cpp
 * #include <cstdio>
 * #include "sepax_flecs.h"
 *
 * int main() {
 *     flecs::world ecs;
 *     ECS_IMPORT(ecs, SepaxPhysics);
 *     ecs.entity("ground")
 *         .set<SxTransform>({{0, -1}, 0})
 *         .set<SxCollider>(sx_ecs_collider(sx_box_shape(20, 1)));
 *     flecs::entity box = ecs.entity("box")
 *         .set<SxTransform>({{0, 4}, 0})
 *         .set<SxBody>(sx_ecs_body(SX_BODY_DYNAMIC))
 *         .set<SxCollider>(sx_ecs_collider(sx_box_shape(0.5, 0.5)));
 *     ecs.observer<SxCollider>().event(SxContactBegin).each(
 *         [](flecs::iter &it, size_t row, SxCollider &) {
 *             const SxContactEvent *ev = static_cast<const SxContactEvent *>(it.param());
 *             std::printf("%s touches %s\n", it.entity(row).name().c_str(),
 *                         it.world().entity(ev->other).name().c_str());
 *         });
 *     for (int i = 0; i < 120; ++i) ecs.progress(1.0f / 60.0f);
 *     std::printf("box at y = %.2f\n", double(box.get<SxTransform>().position.y));
 * }
 * ```
 *
 * Build (FLECS: the directory of flecs 4's flecs.c and flecs.h; flecs.c
 * needs POSIX declarations under -std=c99):
 *
 * ```sh
 * ECS=$(pkg-config --variable=ecsdir sepax)
 * cc -std=c99 -D_POSIX_C_SOURCE=200809L -c $FLECS/flecs.c -o flecs.o
 * cc -std=c99 -c $ECS/sepax_flecs.c -I$FLECS $(pkg-config --cflags sepax)
 * cc -std=c99 -o game game.c sepax_flecs.o flecs.o -I$ECS -I$FLECS \
 *    $(pkg-config --cflags --libs sepax) -Wl,-rpath,$(pkg-config --variable=libdir sepax) \
 *    -lpthread -lm
 * c++ -std=c++17 -o game_cpp game.cpp sepax_flecs.o flecs.o -I$ECS -I$FLECS \
 *    $(pkg-config --cflags --libs sepax) -Wl,-rpath,$(pkg-config --variable=libdir sepax) \
 *    -lpthread -lm
 * ```
 *
 * The components are the truth: once per fixed step the module copies what
 * the game wrote into SxTransform (a teleport) and SxBody (velocity, type,
 * damping, accumulated forces and impulses) into a sepax world, runs the
 * world's public stage functions, and copies positions and velocities back.
 * An entity with SxBody is a body (with or without SxCollider); an entity with
 * SxCollider but no SxBody is static geometry. Adding SxBody or SxCollider
 * adds SxTransform (identity) when it is missing.
 *
 * Physics runs in the phase SxPhysicsUpdate (after EcsOnUpdate): a fixed
 * time step with an accumulator, SxPhysicsSettings.max_steps_per_frame at
 * most per frame. Each fixed step runs the systems of these tags in order,
 * collision once per step and the other stage tags once per sub-step:
 *
 *   SxPhysicsPreStep      copy components into the world, sx_world_begin_step
 *   SxPhysicsCollide      sx_world_collide             (once per step)
 *   SxPhysicsApplyForces  sx_world_apply_forces     \
 *   SxPhysicsSolve        sx_world_solve             |  sub_steps times,
 *   SxPhysicsIntegrate    sx_world_integrate         |  h = fixed_time_step
 *   SxPhysicsSeparate     sx_world_separate         /       / sub_steps
 *   SxPhysicsPostStep     clear forces, update sleep, copy the world back
 *                         into the components, fill SxContacts, emit events
 *
 * A game puts its own system between stages by giving it one of these tags
 * as its DependsOn phase (`.phase = SxPhysicsSolve` in ecs_system_desc_t's
 * ECS_SYSTEM or ecs_dependson(SxPhysicsSolve)): the main pipeline ignores
 * these tags; the module runs their systems itself (up to 64 per tag), in
 * creation order after its own. All of a frame's steps run inside the SxPhysicsUpdate phase, so
 * structural changes made by these systems or by observers of the contact
 * events (deleting an entity, adding SxBody) are deferred as usual: they take
 * effect when the phase's commands are merged, after the frame's last step. */
#ifndef SEPAX_FLECS_H
#define SEPAX_FLECS_H

#include <sepax/sepax.h>

#include "flecs.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Where an entity is: the body origin and angle (radians). Writing it
 *  teleports the body at the next step (velocities are kept). */
typedef struct SxTransform {
    sx_vec2 position;
    sx_real angle;
} SxTransform;

/** A rigid body. Zero-initialised it is a static body with gravity scale 0:
 *  start from sx_ecs_body(type). After each step velocity and
 *  angular_velocity hold the world's values; writing them sets the velocity
 *  at the next step. */
typedef struct SxBody {
    sx_body_type type;
    sx_vec2 velocity;         /**< of the centre of mass, m/s */
    sx_real angular_velocity; /**< rad/s */
    /** kg; 0 = from the colliders' densities. A positive mass scales the
     *  collider's density to give it (a body without a collider weighs 1 kg,
     *  as in the plain world). Changing it rebuilds the body. */
    sx_real mass;
    /** Accumulators: forces (N) and torque (N m) act over the next fixed
     *  step, impulses (N s, N m s) once; the module zeroes them after
     *  applying them. See sx_ecs_apply_force / sx_ecs_apply_impulse. */
    sx_vec2 force;
    sx_real torque;
    sx_vec2 impulse;
    sx_real angular_impulse;
    /** As sx_body_def; changing one of them rebuilds the world body (its
     *  contacts restart from scratch). */
    sx_real linear_damping;
    sx_real angular_damping;
    sx_real gravity_scale;
    bool fixed_rotation;
    /** As sx_body_def.bullet: swept against dynamic bodies too (continuous
     *  collision). Changing it takes effect at the next step. */
    bool bullet;
    /** Output: false while the body sleeps. */
    bool awake;
} SxBody;

/** A collider attached to the entity's body (or, without SxBody, static
 *  geometry). Fields as sx_collider_def; start from sx_ecs_collider(shape).
 *  Writing a different value rebuilds the collider. */
typedef struct SxCollider {
    sx_shape shape;
    sx_real density;
    sx_real friction;
    sx_real restitution;
    sx_filter filter;
    bool sensor;
    /** A compound (concave) collider: part_count > 0 convex parts, each
     *  with its offset in the body frame, attached as ONE collider
     *  (sx_body_add_compound); `shape` is then ignored. The component owns
     *  its parts: the module's copy hook copies the array, so
     *  ecs_set(world, e, SxCollider, {..., .parts = p, .part_count = n})
     *  leaves p to the caller, and deleting the entity or removing the
     *  component frees the copy. Change the parts by setting a whole new
     *  value (never write through the pointer). sx_ecs_set_outline builds
     *  one from a concave outline. NULL and 0: a plain collider. */
    const sx_compound_part *parts;
    int32_t part_count;
} SxCollider;

/** Singleton: the physics settings, read at every frame. */
typedef struct SxPhysicsSettings {
    sx_vec2 gravity;         /**< m/s^2; default (0, -10) */
    sx_real fixed_time_step; /**< s, > 0; default 1/60 */
    /** 1 .. SX_MAX_SUB_STEPS; default 5 (the world's default). Settings
     *  out of range (this, fixed_time_step or max_steps_per_frame) run no
     *  step until they are fixed. */
    int32_t sub_steps;
    /** Most fixed steps one frame runs (>= 1; default 8); the time beyond
     *  it is dropped, so a long frame slows the simulation down instead of
     *  spiralling. */
    int32_t max_steps_per_frame;
    /** Lets resting groups of bodies fall asleep (sx_world_update_sleep
     *  runs after each step). Default true. Turning it off keeps bodies
     *  that already sleep asleep until something touches or moves them. */
    bool enable_sleep;
    /** Solver iterations per sub-step, as sx_world_def: velocity (>= 1,
     *  default 3) and position (>= 0, default 1). */
    int32_t velocity_iterations;
    int32_t position_iterations;
    /** Continuous collision, as sx_world_def.enable_continuous (fast
     *  bodies swept to their time of impact; bullets against dynamic
     *  bodies too). Default true. */
    bool enable_continuous;
} SxPhysicsSettings;

/** Singleton, written by the module every frame: where the fixed-step clock
 *  stands. `alpha` is the time left in the accumulator after this frame's
 *  steps, as a fraction of fixed_time_step, in [0, 1): a game that renders
 *  between fixed steps draws each body at lerp(previous, current, alpha),
 *  with `previous` saved by a system of its own in the SxPhysicsPreStep
 *  phase (see the top of this file). */
typedef struct SxPhysicsTime {
    sx_real alpha;
    int32_t frame_steps; /**< fixed steps run in this frame */
    int64_t steps;       /**< fixed steps run since the import */
} SxPhysicsTime;

/** One contact of the last fixed step (collider pairs with a manifold; a
 *  compound collider touching on several parts is still one SxContact: the
 *  normal and point of its first touching part pair, point_count summed over
 *  all of them). */
typedef struct SxContact {
    ecs_entity_t entity_a, entity_b; /**< entity_a < entity_b */
    sx_vec2 normal;                  /**< unit, from entity_a to entity_b */
    sx_vec2 point;                   /**< first contact point, world */
    int32_t point_count;
} SxContact;

/** Singleton: the contacts of the last fixed step, sorted by (entity_a,
 *  entity_b). Owned by the module; valid until the next step. */
typedef struct SxContacts {
    const SxContact *items;
    int32_t count;
} SxContacts;

/** Singleton: the module's world, for queries and debug drawing
 *  (sx_world_draw, sx_world_cast_ray, ...). Do not create or destroy bodies
 *  in it: the components own them. An entity deleted (or stripped of its
 *  components) from a query or draw callback of this world, which is then
 *  locked (sx_world_is_locked), keeps its body there until the next fixed
 *  step removes it. */
typedef struct SxPhysicsWorld {
    sx_world *world;
} SxPhysicsWorld;

/** The payload of SxContactBegin / SxContactEnd, emitted once on each of the
 *  two entities (with self and other swapped) when their colliders start or
 *  stop touching. Observe with ecs_observer({ .query.terms =
 *  {{ ecs_id(SxCollider) }}, .events = { SxContactBegin }, ... }) and read
 *  it->param. normal and point are those of the contact (for an end, of the
 *  last step it existed); the normal points from self to other. Deleting an
 *  entity ends its contacts without an end event. */
typedef struct SxContactEvent {
    ecs_entity_t self, other;
    sx_vec2 normal;
    sx_vec2 point;
} SxContactEvent;

extern ECS_COMPONENT_DECLARE(SxTransform);
extern ECS_COMPONENT_DECLARE(SxBody);
extern ECS_COMPONENT_DECLARE(SxCollider);
extern ECS_COMPONENT_DECLARE(SxPhysicsSettings);
extern ECS_COMPONENT_DECLARE(SxPhysicsTime);
extern ECS_COMPONENT_DECLARE(SxContacts);
extern ECS_COMPONENT_DECLARE(SxPhysicsWorld);
extern ECS_COMPONENT_DECLARE(SxContactEvent);

/** The phase in which physics runs (depends on EcsOnUpdate). */
extern ECS_DECLARE(SxPhysicsUpdate);
/** The tags ordering the systems of one fixed step (see the top). */
extern ECS_DECLARE(SxPhysicsPreStep);
extern ECS_DECLARE(SxPhysicsApplyForces);
extern ECS_DECLARE(SxPhysicsCollide);
extern ECS_DECLARE(SxPhysicsSolve);
extern ECS_DECLARE(SxPhysicsIntegrate);
extern ECS_DECLARE(SxPhysicsSeparate);
extern ECS_DECLARE(SxPhysicsPostStep);
/** Custom events carrying an SxContactEvent. */
extern ECS_DECLARE(SxContactBegin);
extern ECS_DECLARE(SxContactEnd);
/** A collider started or stopped overlapping a sensor collider; emitted on
 *  the sensor's entity and on the visitor's, as the contact events (normal
 *  and point are zero). */
extern ECS_DECLARE(SxSensorBegin);
extern ECS_DECLARE(SxSensorEnd);

/** The module: ECS_IMPORT(world, SepaxPhysics). */
void SepaxPhysicsImport(ecs_world_t *world);

/** A body of the given type with gravity scale 1 and everything else 0. */
SxBody sx_ecs_body(sx_body_type type);
/** sx_default_collider_def's values with this shape. */
SxCollider sx_ecs_collider(sx_shape shape);

/** Decomposes a simple, possibly concave outline (points in the entity's
 *  body frame, any winding) with sx_decompose_polygon and sets the entity's
 *  SxCollider to the resulting compound, with the material, filter and
 *  sensor fields of `base` (sx_ecs_collider's defaults when NULL). Returns
 *  SX_OK, or without touching the entity: SX_ERR_INVALID_ARG (NULL world or
 *  points, count < 3, a dead entity), SX_ERR_NO_MEMORY, or the status of
 *  sx_decompose_polygon (SX_ERR_NONFINITE for NaN/Inf, SX_ERR_INVALID_ARG for
 *  a self-intersecting outline, SX_ERR_DEGENERATE for a collinear one). */
sx_status sx_ecs_set_outline(ecs_world_t *world, ecs_entity_t e, const sx_vec2 *points,
                             int32_t count, const SxCollider *base);

/** Adds a force (N, at the centre of mass) to the entity's SxBody force
 *  accumulator: it acts over the next fixed step. Ignored without SxBody. */
void sx_ecs_apply_force(ecs_world_t *world, ecs_entity_t e, sx_vec2 force);
/** Adds a linear impulse (N s) to the entity's SxBody, applied at the next
 *  fixed step. Ignored without SxBody. */
void sx_ecs_apply_impulse(ecs_world_t *world, ecs_entity_t e, sx_vec2 impulse);
/** The module's sepax world (NULL before the import). */
sx_world *sx_ecs_world(const ecs_world_t *world);
/** The entity whose body this is (from a ray cast, a query or a contact of
 *  the module's world); 0 for a NULL world, a null or stale handle, or a
 *  body the module did not create. */
ecs_entity_t sx_ecs_entity_of(const ecs_world_t *world, sx_body_id body);
/** Casts a ray (sx_world_cast_ray) through the module's world: the entity
 *  of the closest collider hit (its body's entity, or the static
 *  collider's), with the hit in *out (may be NULL); 0 for no hit, bad input,
 *  or a hit on a body the module did not create. */
ecs_entity_t sx_ecs_cast_ray(const ecs_world_t *world, const sx_ray_input *ray,
                             sx_world_ray_hit *out);
/** Casts a shape (sx_world_cast_shape, filter NULL: every collider) through
 *  the module's world: the entity first hit, with the hit in *out (may be
 *  NULL); 0 as sx_ecs_cast_ray. */
ecs_entity_t sx_ecs_cast_shape(const ecs_world_t *world, const sx_shape *shape, sx_xform xf,
                               sx_vec2 translation, const sx_filter *filter,
                               sx_world_shape_hit *out);
/** The module's body of an entity (the null handle before the entity's
 *  first fixed step, after its SxBody or SxCollider is removed, or for a
 *  NULL world). */
sx_body_id sx_ecs_body_of(const ecs_world_t *world, ecs_entity_t e);
/** Fixed steps run since the import. */
int64_t sx_ecs_step_count(const ecs_world_t *world);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_FLECS_H */
