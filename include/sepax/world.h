/* sepax — the rigid-body world: bodies, colliders, and the step.
 *
 * A world owns bodies (static, kinematic or dynamic) and the colliders
 * attached to them. Bodies and colliders are named by small handles (index +
 * generation) that pack into a uint64_t; a destroyed object's handle goes
 * stale and every call answers it with SX_ERR_STALE_HANDLE (or a zero value
 * for getters) instead of touching another object that reused the slot. A
 * slot hands out generations 1 .. 2^32 - 1 and is then retired, never
 * reused: a stale handle stays stale for good, at the cost of one slot's
 * memory per 2^32 - 1 destroy/create cycles of that slot.
 *
 * One call of sx_world_step(world, dt) runs, for each of `sub_steps` sub-steps
 * of length h = dt / sub_steps, the public stages
 *
 *   sx_world_apply_forces(h)  v += h (g * gravity_scale + F / m) + J / m
 *   sx_world_collide()        broadphase + narrowphase into the contact list
 *   sx_world_solve(h)         sequential impulses on velocities
 *   sx_world_integrate(h)     positions from the new velocities
 *   sx_world_separate(h)      positional correction of what still overlaps
 *
 * and then sx_world_clear_forces() and sx_world_update_sleep(dt). This is
 * symplectic Euler (velocities first, then positions with the new
 * velocities). Callers such as the flecs systems may run the stages
 * themselves, in this order, with their own code in between.
 *
 * Speed limit: in one sub-step a body turns at most SX_MAX_ROTATION and
 * moves at most SX_HUGE (in length units: see SX_HUGE in base.h for worlds
 * whose length_units_per_meter differs from SX_LENGTH_UNITS_PER_METER).
 * sx_world_apply_forces and sx_world_integrate scale faster velocities down
 * to the limit (direction kept), so a finite torque on a tiny inertia, a
 * huge impulse or a huge dt gives a fast body, never an infinite or NaN
 * state. At the default 60 Hz and 4 sub-steps the rotation
 * limit is 377 rad/s (3600 rpm); a faster spin needs more sub-steps (the
 * rotation update, q + h w q' renormalised, turns by atan(h w), less than a
 * quarter turn per sub-step, whatever w is).
 *
 * No continuous collision yet: fast bodies can tunnel. Contacts come from
 * the positions at the start of each sub-step, for shapes within the
 * speculative margin (speculative_slops x the linear slop: 2 cm by
 * default), and the solver stops a body only at the contacts it has. A body
 * that covers d = |v| dt / sub_steps in one sub-step can end it overlapping
 * a collider it had no contact with by up to d minus the margin (then
 * sx_world_separate pushes it out the shortest way, which past the middle
 * of a thin collider is the far side), and once d exceeds about the margin
 * plus both thicknesses it can cross the collider outright. Keep d below
 * half the thinner thickness (a 10 cm wall at 60 Hz and 4 sub-steps: below
 * 12 m/s), or add sub-steps; bullets and thin walls need care.
 *
 * Sleeping: islands of touching bodies that stay slow fall asleep and cost
 * no solver work until something touches or pushes them. Around the step: contact begin/end events,
 * world queries (bounds, point, shape, ray) and a debug-draw callback interface.
 *
 * Units: metres, kilograms, seconds, radians. The contact tolerance (the
 * linear slop, 5 mm at one length unit per metre) scales with the world's
 * length_units_per_meter.
 *
 * Threads: a world is used by one thread at a time (no call on a world may
 * overlap another call on the same world, getters and queries included;
 * callbacks run on the calling thread). Different worlds share no state:
 * any number of threads may each create, step, query and destroy their own
 * worlds at the same time, without locking, with the default allocator or a
 * thread-safe custom one (base.h: set the allocator and assert hooks once,
 * before the first world). A world may move from one thread to another
 * between calls if the program orders the hand-over (a mutex, a join). */
#ifndef SEPAX_WORLD_H
#define SEPAX_WORLD_H

#include "base.h"
#include "math.h"
#include "shape.h"
#include "collide.h"
#include "compound.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest rotation (radians) of a body in one sub-step: a quarter turn
 *  (see "Speed limit" above). */
#define SX_MAX_ROTATION (SX_R(0.5) * SX_PI)

/** Most bodies, and most colliders, one world holds: 2^30 - 1 (a body or
 *  collider more is SX_ERR_CAPACITY). The same bound holds for every list a
 *  world keeps (contacts, broadphase pairs, sensor overlaps, events): a
 *  step that would need more stops with SX_ERR_CAPACITY. Memory runs out
 *  first on most machines (a body with one collider takes about 400 bytes
 *  in the float build, 700 in the double one). */
#define SX_WORLD_MAX_ITEMS 0x3FFFFFFF

/** Most sub-steps per step (sx_world_def.sub_steps). */
#define SX_MAX_SUB_STEPS 256

/** Most velocity iterations, and most position iterations, per sub-step
 *  (sx_world_def). With SX_MAX_SUB_STEPS, a step makes at most 65,536
 *  solver passes over its contacts. */
#define SX_MAX_ITERATIONS 256

/* ---- handles ------------------------------------------------------------ */

/** An opaque world. Create with sx_world_create, free with sx_world_destroy. */
typedef struct sx_world sx_world;

/** Handle of a body: slot index and generation. The all-zero value is the
 *  null handle; live handles always have a generation >= 1. */
typedef struct sx_body_id {
    uint32_t index;
    uint32_t generation;
} sx_body_id;

/** Handle of a collider, as sx_body_id. */
typedef struct sx_collider_id {
    uint32_t index;
    uint32_t generation;
} sx_collider_id;

/** Packs a body handle into 64 bits (generation in the high half); the null
 *  handle packs to 0. */
uint64_t sx_body_id_to_u64(sx_body_id id);
/** Unpacks sx_body_id_to_u64's value. 0 gives the null handle. */
sx_body_id sx_body_id_from_u64(uint64_t bits);
/** True for the null body handle. */
bool sx_body_id_is_null(sx_body_id id);
/** Packs a collider handle into 64 bits, as sx_body_id_to_u64. */
uint64_t sx_collider_id_to_u64(sx_collider_id id);
/** Unpacks sx_collider_id_to_u64's value. */
sx_collider_id sx_collider_id_from_u64(uint64_t bits);

/* ---- world -------------------------------------------------------------- */

/** World settings. Start from sx_default_world_def() and change fields. */
typedef struct sx_world_def {
    /** Gravity in m/s^2. Default (0, -10). */
    sx_vec2 gravity;
    /** Sub-steps per sx_world_step, 1 .. SX_MAX_SUB_STEPS. Default 4: each
     *  runs every stage with h = dt / sub_steps, which stiffens stacks and
     *  shortens the distance a fast body covers between two collision
     *  passes. */
    int sub_steps;
    /** Sequential-impulse iterations per sub-step, 1 .. SX_MAX_ITERATIONS.
     *  Default 4. */
    int velocity_iterations;
    /** Positional-correction iterations per sub-step, 0 .. SX_MAX_ITERATIONS
     *  (0 turns sx_world_separate off). Default 2. */
    int position_iterations;
    /** Fraction of the overlap beyond the slop that one correction iteration
     *  removes, in (0, 1]. Default 0.2 (Baumgarte's classic value: larger
     *  values overshoot in stacks). */
    sx_real correction_factor;
    /** Largest speed (m/s) at which sx_world_separate moves a contact point
     *  out of an overlap (each of the position_iterations passes of a
     *  sub-step moves it at most max_correction_speed x h /
     *  position_iterations); a deep overlap is removed over several steps
     *  instead of in one jump. Default 3 m/s (> 0). */
    sx_real max_correction_speed;
    /** Approach speed (m/s) below which contacts do not bounce: restitution
     *  only applies to impacts at this speed or faster (to round-off: an
     *  approach within 1e-4 of it, relative, counts as equal), so resting
     *  bodies do not jitter. Default 1 m/s (>= 0). */
    sx_real restitution_threshold;
    /** Speculative contact margin in units of the linear slop (>= 0): shapes
     *  closer than this get contact points before they touch, and the solver
     *  lets them close exactly the gap in one sub-step. Default 4. */
    sx_real speculative_slops;
    /** Length units per metre (> 0): scales the linear slop (5 mm at 1).
     *  Default SX_LENGTH_UNITS_PER_METER. It does not scale SX_HUGE, which
     *  is fixed at compile time (see base.h). */
    sx_real length_units_per_meter;
    /** Number of bodies to reserve room for at creation, 0 ..
     *  SX_WORLD_MAX_ITEMS. Default 0. */
    int body_capacity;
    /** Lets groups of touching bodies that stay slow fall asleep (see
     *  sx_world_update_sleep). Default true. */
    bool enable_sleep;
    /** Speeds under which a body counts as at rest: linear (m/s, >= 0,
     *  default 0.05 x SX_LENGTH_UNITS_PER_METER: rescale it with
     *  length_units_per_meter) and angular (rad/s, >= 0, default 2 degrees
     *  per second). */
    sx_real sleep_linear_speed;
    sx_real sleep_angular_speed;
    /** Seconds a whole island must stay at rest before it sleeps (> 0).
     *  Default 0.5. */
    sx_real time_to_sleep;
    /** Builds the contact begin/end events each collide (one merge pass over
     *  the old and new contact lists). false: none are built and
     *  sx_world_get_contact_events stays empty. Default true. Sensor events
     *  cost nothing in a world without sensors. */
    bool enable_contact_events;
} sx_world_def;

/** The default world settings documented field by field in sx_world_def. */
sx_world_def sx_default_world_def(void);

/** Checks world settings: SX_OK, or the reason sx_world_create refuses
 *  them: SX_ERR_INVALID_ARG (NULL, or a field below its documented range or
 *  outside it for a bounded real such as correction_factor);
 *  SX_ERR_NONFINITE (a NaN or infinite real); SX_ERR_CAPACITY (sub_steps
 *  above SX_MAX_SUB_STEPS, an iteration count above SX_MAX_ITERATIONS, or
 *  body_capacity above SX_WORLD_MAX_ITEMS). */
sx_status sx_world_def_validate(const sx_world_def *def);

/** Creates a world. Returns NULL when sx_world_def_validate(def) is not
 *  SX_OK, or when memory runs out (body_capacity bodies are reserved
 *  here). */
sx_world *sx_world_create(const sx_world_def *def);

/** Destroys the world and everything in it (NULL is ignored). Every handle of
 *  it becomes meaningless. */
void sx_world_destroy(sx_world *world);

/** Sets the gravity and wakes every sleeping body. SX_ERR_INVALID_ARG (NULL
 *  world), SX_ERR_NONFINITE. */
sx_status sx_world_set_gravity(sx_world *world, sx_vec2 gravity);
/** The gravity (zero for a NULL world). */
sx_vec2 sx_world_get_gravity(const sx_world *world);
/** Number of live bodies. */
int sx_world_body_count(const sx_world *world);
/** Number of live dynamic bodies that are awake. */
int sx_world_awake_body_count(const sx_world *world);
/** The world's linear slop: 0.005 x length_units_per_meter. */
sx_real sx_world_linear_slop(const sx_world *world);

/* ---- the step and its stages -------------------------------------------- */

/** Advances the world by dt seconds: clears the contact and sensor events,
 *  then for each sub-step runs apply_forces, collide, solve, integrate and
 *  separate with h = dt / sub_steps, then clear_forces and update_sleep(dt)
 *  (a dt so small that dt / sub_steps rounds to 0 is one sub-step of dt).
 *  Errors, with the world left
 *  untouched: SX_ERR_INVALID_ARG (NULL world, dt <= 0), SX_ERR_NONFINITE (dt
 *  NaN or infinite). SX_ERR_NO_MEMORY: the contact list or the impact
 *  pass's scratch could not grow; SX_ERR_CAPACITY: a list would pass
 *  SX_WORLD_MAX_ITEMS (more than 2^30 - 1 broadphase pairs or contacts);
 *  either way the step stops after the stages already run. */
sx_status sx_world_step(sx_world *world, sx_real dt);

/** Stage 1: for every enabled, awake dynamic body, v += h (gravity x gravity_scale +
 *  F / m) + J / m and w += h (T / I) + L / I, then damping
 *  v *= 1 / (1 + h c), then the speed limit (h w within SX_MAX_ROTATION, h
 *  |v| within SX_HUGE). F, T are the force and torque accumulators (kept: they
 *  act over every sub-step of a step until sx_world_clear_forces); J, L the
 *  impulse accumulators, applied once and cleared here. Static and kinematic
 *  bodies are untouched. Errors: SX_ERR_INVALID_ARG (NULL, h <= 0),
 *  SX_ERR_NONFINITE. */
sx_status sx_world_apply_forces(sx_world *world, sx_real h);

/** Stage 2: finds the touching (or within the speculative margin) collider
 *  pairs and builds their manifolds. Pairs are found by sort-and-sweep over
 *  the colliders' bounds; pairs without an awake dynamic body (static,
 *  kinematic or sleeping on both sides), colliders of one body, filtered
 *  pairs and sensors are skipped, and the contacts of sleeping bodies are
 *  carried over unchanged. Contacts persist across calls by collider pair,
 *  and each point keeps its accumulated impulses while its feature id
 *  persists (warm starting). An awake body that touches a sleeping one wakes
 *  its island. Pairs that start or stop having a manifold are recorded as
 *  contact events; then the sensors are updated (sensor events). Errors:
 *  SX_ERR_INVALID_ARG (NULL), SX_ERR_NO_MEMORY, SX_ERR_CAPACITY (a list
 *  would pass SX_WORLD_MAX_ITEMS). */
sx_status sx_world_collide(sx_world *world);

/** Stage 3: the contacts of the last collide, on velocities. Warm start,
 *  then the impact pass (restitution): the contacts approaching at the
 *  restitution threshold or faster that close their gap within this
 *  sub-step are resolved one at a time in order of their time of impact,
 *  each at most once per sub-step, each approaching point leaving at e times
 *  its approach speed (e = max(e_a, e_b); both points of a two-point contact
 *  at once), with Coulomb friction on that impulse; after each impact the
 *  other contacts of its two bodies are looked at again with the new
 *  velocities, so an impulse travels down a row of touching bodies (Newton's
 *  cradle). Each impact also records the time-of-impact correction of its
 *  bodies' positions, applied by sx_world_integrate. Then
 *  `velocity_iterations` passes of Coulomb friction (|tangent impulse| <= mu
 *  x normal impulse, mu = sqrt(mu_a mu_b)) and non-penetration (accumulated
 *  normal impulse >= 0; a speculative point may close its gap in this
 *  sub-step but not more); the two normal constraints of a two-point contact
 *  are solved together, exactly (a 2x2 complementarity problem). With every
 *  restitution <= 1 no impulse of this stage adds kinetic energy, and
 *  penetration is not turned into velocity here (see sx_world_separate).
 *  Errors: SX_ERR_INVALID_ARG (NULL, h <= 0), SX_ERR_NONFINITE,
 *  SX_ERR_NO_MEMORY (the impact pass's scratch could not grow: the pass is
 *  skipped, the iterations still run). */
sx_status sx_world_solve(sx_world *world, sx_real h);

/** Stage 4: symplectic Euler positions: centre of mass += h v, rotation
 *  advanced by h w (renormalised), for awake dynamic and kinematic bodies,
 *  after the speed limit of stage 1 (for what the solver added);
 *  then the time-of-impact corrections of the last solve's impacts (a body
 *  whose velocity changed by dv at time t of the sub-step moves by -dv t,
 *  since it kept its old velocity until t).
 *  Errors: SX_ERR_INVALID_ARG (NULL, h <= 0), SX_ERR_NONFINITE. */
sx_status sx_world_integrate(sx_world *world, sx_real h);

/** Stage 5: removes overlap left after integration by moving positions only
 *  (velocities are not touched, so no kinetic energy is ever added): for
 *  `position_iterations` passes, each contact point's current separation s
 *  (from the anchors stored by collide, moved with the bodies) gives the
 *  correction C = max(correction_factor (s + slop), -max_correction_speed h /
 *  position_iterations) when s < -slop, applied as a pseudo-impulse split by
 *  inverse mass and inverse inertia. We chose positional correction over a
 *  Baumgarte velocity bias because a bias turns overlap into velocity, which
 *  comes out as kinetic energy (bodies created overlapping fly apart); split
 *  impulses would do the same work with a second set of velocities.
 *  Errors: SX_ERR_INVALID_ARG (NULL, h <= 0), SX_ERR_NONFINITE. */
sx_status sx_world_separate(sx_world *world, sx_real h);

/** Clears every body's force and torque accumulators (the last stage of a
 *  step). Errors: SX_ERR_INVALID_ARG (NULL). */
sx_status sx_world_clear_forces(sx_world *world);

/** After a step of length dt: bodies slower than the sleep speeds gain dt of
 *  rest time (others drop to 0); dynamic bodies joined by contacts form
 *  islands, and an island whose every body has rested time_to_sleep seconds
 *  falls asleep (velocities zeroed). Sleeping bodies cost nothing: no forces,
 *  no integration, no pairs with static or other sleeping bodies. An island
 *  wakes whole when an awake body touches one of its bodies, when one of its
 *  bodies is destroyed, when the API pushes, moves or sets the velocity of
 *  one of them, or when a body or collider it rests on is moved, retyped or
 *  destroyed. A body touching a moving kinematic body never sleeps. Does
 *  nothing when enable_sleep is false. sx_world_step calls it last.
 *  Errors: SX_ERR_INVALID_ARG (NULL, dt <= 0), SX_ERR_NONFINITE,
 *  SX_ERR_NO_MEMORY (the scratch arrays could not grow; nothing sleeps). */
sx_status sx_world_update_sleep(sx_world *world, sx_real dt);

/* ---- contacts ------------------------------------------------------------ */

/** A contact of the last collide, for inspection. */
typedef struct sx_contact_data {
    sx_collider_id collider_a, collider_b;
    sx_body_id body_a, body_b;
    /** World unit normal from A to B. */
    sx_vec2 normal;
    /** Number of points, 1..2. */
    int count;
    /** World points (midway between the surfaces at collide time). */
    sx_vec2 points[2];
    /** Overlap at collide time (> 0 overlapping, < 0 speculative gap). */
    sx_real depths[2];
    /** Accumulated normal and tangent impulses of the last solve's velocity
     *  iterations (N s). */
    sx_real normal_impulses[2];
    sx_real tangent_impulses[2];
    /** Normal impulses of the last solve's impact pass (N s): non-zero for
     *  an impact resolved with restitution in that sub-step. */
    sx_real impact_impulses[2];
    /** The parts of a compound collider this contact is between (0 for a
     *  plain collider): a compound has one contact per touching part pair,
     *  listed after one another in (part_a, part_b) order. */
    int part_a, part_b;
} sx_contact_data;

/** Number of contacts from the last sx_world_collide, the carried contacts
 *  of sleeping bodies included (0 for NULL). */
int sx_world_contact_count(const sx_world *world);
/** Copies contact `index` (0 .. count-1) into *out. SX_ERR_INVALID_ARG for
 *  NULL or an index out of range. */
sx_status sx_world_get_contact(const sx_world *world, int index, sx_contact_data *out);

/* ---- contact events ------------------------------------------------------ */

/** Two colliders that started or stopped touching. "Touching" is having a
 *  contact manifold: shapes within the speculative margin of each other, so
 *  a resting contact that rocks by a fraction of a millimetre does not
 *  flicker. A compound collider counts as one collider: it begins touching
 *  when its first part pair gets a manifold and ends when its last one
 *  loses it (one event each, whichever parts touch). Handles are those of the colliders and bodies
 * at the time. */
typedef struct sx_contact_event {
    sx_collider_id collider_a, collider_b;
    sx_body_id body_a, body_b;
} sx_contact_event;

/** Read-only views of the events recorded since the last
 *  sx_world_clear_events (sx_world_step clears at its start, so after a step
 *  they are that step's events, over all its sub-steps). Within each array
 *  the order is deterministic (by collider pair within a collide call). A
 *  pair that began and ended within one step appears in both arrays.
 *  Destroying a body or collider removes its contacts without an end event.
 *  The pointers are valid until the next call that changes the world. */
typedef struct sx_contact_events {
    const sx_contact_event *begin;
    int begin_count;
    const sx_contact_event *end;
    int end_count;
} sx_contact_events;

/** The events recorded since the last clear (all empty for NULL). */
sx_contact_events sx_world_get_contact_events(const sx_world *world);

/** A collider that started or stopped overlapping a sensor (touching
 *  counts). A sensor sees the non-sensor colliders of other enabled bodies
 *  that its filter accepts, except that a sensor on a static body does not
 *  see other static bodies. */
typedef struct sx_sensor_event {
    sx_collider_id sensor, visitor;
    sx_body_id sensor_body, visitor_body;
} sx_sensor_event;

/** Sensor events, recorded and cleared as the contact events (destroying a
 *  collider forgets its overlaps without an end event). Each collide tests
 *  every sensor against every collider's bounds (cost: sensors x
 *  colliders), then the overlap of the candidates. */
typedef struct sx_sensor_events {
    const sx_sensor_event *begin;
    int begin_count;
    const sx_sensor_event *end;
    int end_count;
} sx_sensor_events;

/** The sensor events recorded since the last clear (empty for NULL). */
sx_sensor_events sx_world_get_sensor_events(const sx_world *world);

/** Forgets the recorded contact and sensor events. SX_ERR_INVALID_ARG for
 *  NULL. */
sx_status sx_world_clear_events(sx_world *world);

/* ---- bodies ------------------------------------------------------------- */

typedef enum sx_body_type {
    SX_BODY_STATIC = 0, /**< never moves; infinite mass */
    SX_BODY_KINEMATIC,  /**< moves by its velocity only; infinite mass */
    SX_BODY_DYNAMIC     /**< moved by forces and contacts */
} sx_body_type;

/** Body settings. Start from sx_default_body_def(). */
typedef struct sx_body_def {
    sx_body_type type;        /**< default SX_BODY_STATIC */
    sx_vec2 position;         /**< origin of the body frame, world; default 0 */
    sx_real angle;            /**< radians; default 0 */
    sx_vec2 linear_velocity;  /**< of the centre of mass, m/s; default 0 */
    sx_real angular_velocity; /**< rad/s; default 0 */
    sx_real linear_damping;   /**< 1/s, >= 0; default 0 */
    sx_real angular_damping;  /**< 1/s, >= 0; default 0 */
    sx_real gravity_scale;    /**< multiplies the world gravity; default 1 */
    bool fixed_rotation;      /**< infinite inertia; default false */
    bool enabled;             /**< false: neither moves nor collides; default true */
    /** false: the body never sleeps, nor does any island it belongs to (a
     *  player character); default true. The world's enable_sleep still
     *  switches sleeping off for every body. */
    bool enable_sleep;
    void *user_data; /**< returned by sx_body_get_user_data; default NULL */
} sx_body_def;

/** The default body settings (a static body at the origin). */
sx_body_def sx_default_body_def(void);

/** Creates a body. *out receives its handle (the null handle on error).
 *  Errors: SX_ERR_INVALID_ARG (NULL world/def/out, unknown type, negative
 *  damping), SX_ERR_NONFINITE, SX_ERR_NO_MEMORY, SX_ERR_CAPACITY
 *  (SX_WORLD_MAX_ITEMS body slots in use or retired: see sx_destroy_body).
 *  A dynamic body without colliders of positive mass gets mass 1 kg and no
 *  rotational inertia (contacts cannot turn it; its own angular velocity,
 *  if set, is kept). */
sx_status sx_create_body(sx_world *world, const sx_body_def *def, sx_body_id *out);

/** Destroys a body, its colliders and its contacts. Its slot is reused by a
 *  later body with the next generation, or retired after generation
 *  2^32 - 1 (so no old handle ever names a new body; colliders' slots
 *  likewise). SX_ERR_INVALID_ARG (NULL world), SX_ERR_STALE_HANDLE. */
sx_status sx_destroy_body(sx_world *world, sx_body_id body);

/** True if the handle names a live body of this world. */
bool sx_body_is_valid(const sx_world *world, sx_body_id body);

/* Getters answer a stale handle or NULL world with zero values (identity
 * transform, SX_BODY_STATIC, NULL user data). */

/** Body type. */
sx_body_type sx_body_get_type(const sx_world *world, sx_body_id body);
/** World position of the body origin. */
sx_vec2 sx_body_get_position(const sx_world *world, sx_body_id body);
/** Angle in (-pi, pi]. */
sx_real sx_body_get_angle(const sx_world *world, sx_body_id body);
/** The body frame (origin and rotation). */
sx_xform sx_body_get_transform(const sx_world *world, sx_body_id body);
/** World centre of mass. */
sx_vec2 sx_body_get_world_center(const sx_world *world, sx_body_id body);
/** Centre of mass in the body frame. */
sx_vec2 sx_body_get_local_center(const sx_world *world, sx_body_id body);
/** Velocity of the centre of mass (m/s). */
sx_vec2 sx_body_get_linear_velocity(const sx_world *world, sx_body_id body);
/** Angular velocity (rad/s, counter-clockwise positive). */
sx_real sx_body_get_angular_velocity(const sx_world *world, sx_body_id body);
/** Mass in kg (0 for static and kinematic bodies). */
sx_real sx_body_get_mass(const sx_world *world, sx_body_id body);
/** Rotational inertia about the centre of mass, kg m^2 (0 when fixed or not
 *  dynamic). */
sx_real sx_body_get_inertia(const sx_world *world, sx_body_id body);
/** The user data of the body def. */
void *sx_body_get_user_data(const sx_world *world, sx_body_id body);
/** False while the body sleeps (static bodies: always false). */
bool sx_body_is_awake(const sx_world *world, sx_body_id body);

/** Wakes a sleeping dynamic body and its island (awake = true), or puts this
 *  body to sleep now, velocities zeroed (awake = false; it wakes as
 *  documented at sx_world_update_sleep, so a body still touching an awake
 *  one wakes again at the next collide). SX_ERR_INVALID_ARG (NULL),
 *  SX_ERR_STALE_HANDLE. Static and kinematic bodies ignore it (SX_OK). */
sx_status sx_body_set_awake(sx_world *world, sx_body_id body, bool awake);

/** Allows or forbids sleeping for this body (sx_body_def.enable_sleep);
 *  forbidding wakes it. SX_ERR_INVALID_ARG (NULL), SX_ERR_STALE_HANDLE. */
sx_status sx_body_set_sleep_enabled(sx_world *world, sx_body_id body, bool enable);
/** The body's enable_sleep; false for a stale handle. */
bool sx_body_is_sleep_enabled(const sx_world *world, sx_body_id body);

/** Teleports the body: its origin to `position`, its angle to `angle`.
 *  Velocities are kept; the body and the bodies it touches wake. SX_ERR_INVALID_ARG (NULL),
 * SX_ERR_STALE_HANDLE, SX_ERR_NONFINITE. */
sx_status sx_body_set_transform(sx_world *world, sx_body_id body, sx_vec2 position, sx_real angle);
/** Sets the centre-of-mass velocity (ignored by static bodies, which stay at
 *  rest). Errors as sx_body_set_transform. */
sx_status sx_body_set_linear_velocity(sx_world *world, sx_body_id body, sx_vec2 v);
/** Sets the angular velocity (ignored by static bodies and fixed rotation).
 *  Errors as sx_body_set_transform. */
sx_status sx_body_set_angular_velocity(sx_world *world, sx_body_id body, sx_real w);
/** Changes the body type; mass and inertia are recomputed (a body that
 *  becomes static stops). SX_ERR_INVALID_ARG for an unknown type. */
sx_status sx_body_set_type(sx_world *world, sx_body_id body, sx_body_type type);

/* Forces and impulses ACCUMULATE until the step applies them (forces over
 * the whole step, impulses once), and wake the body. Static and
 * kinematic bodies ignore them (SX_OK). Errors: SX_ERR_INVALID_ARG (NULL world),
 * SX_ERR_STALE_HANDLE, SX_ERR_NONFINITE (a NaN/Inf argument, or a sum that
 * would overflow: a huge force at a far point, or huge forces added up; the
 * accumulators are then left as they were). */

/** Adds a force (N) at the centre of mass. */
sx_status sx_body_apply_force(sx_world *world, sx_body_id body, sx_vec2 force);
/** Adds a force (N) at a world point: also adds the torque
 *  (point - centre of mass) x force. */
sx_status sx_body_apply_force_at_point(sx_world *world, sx_body_id body, sx_vec2 force,
                                       sx_vec2 point);
/** Adds a torque (N m). */
sx_status sx_body_apply_torque(sx_world *world, sx_body_id body, sx_real torque);
/** Adds a linear impulse (N s) at the centre of mass. */
sx_status sx_body_apply_impulse(sx_world *world, sx_body_id body, sx_vec2 impulse);
/** Adds a linear impulse (N s) at a world point: also adds the angular
 *  impulse (point - centre of mass) x impulse. */
sx_status sx_body_apply_impulse_at_point(sx_world *world, sx_body_id body, sx_vec2 impulse,
                                         sx_vec2 point);
/** Adds an angular impulse (N m s). */
sx_status sx_body_apply_angular_impulse(sx_world *world, sx_body_id body, sx_real impulse);

/* ---- colliders ---------------------------------------------------------- */

/** Collision filter. Two colliders collide when (a.category & b.mask) and
 *  (b.category & a.mask) are both non-zero, except that colliders of the
 *  same non-zero group always collide (group > 0) or never do (group < 0). */
typedef struct sx_filter {
    uint32_t category; /**< default 1 */
    uint32_t mask;     /**< default all bits */
    int32_t group;     /**< default 0 */
} sx_filter;

/** Collider settings. Start from sx_default_collider_def(). */
typedef struct sx_collider_def {
    /** The shape in the body frame. Default: a circle of radius 0.5 at the
     *  body origin. Checked with sx_shape_validate. */
    sx_shape shape;
    sx_real density;  /**< kg/m^2, >= 0; default 1 */
    sx_real friction; /**< >= 0; default 0.6; mixed as sqrt(mu_a mu_b) */
    /** >= 0; default 0; mixed as max(e_a, e_b). Above 1 a bounce adds
     *  energy; the rebound speed is capped by the speed limit (SX_HUGE per
     *  sub-step, see "Speed limit"). */
    sx_real restitution;
    sx_filter filter;
    /** A sensor takes part in no contact (it has no response); it reports
     *  the colliders overlapping it as sensor events. Default false. */
    bool sensor;
    void *user_data; /**< default NULL */
} sx_collider_def;

/** The default collider settings (see each field). */
sx_collider_def sx_default_collider_def(void);

/** Attaches a collider to a body and updates the body's mass, centre of mass
 *  and inertia from the colliders' densities (the body origin stays where it
 *  is). Should the mass properties overflow (a density near SX_REAL_MAX),
 *  the body gets mass SX_REAL_MAX, no rotational inertia and its centre of
 *  mass at its origin, never NaN. *out (may be NULL) receives the handle,
 *  the null handle on error.
 *  Errors: the status of sx_shape_validate for a bad shape (among them
 *  SX_ERR_NONFINITE for a shape whose mass properties overflow sx_real);
 *  SX_ERR_INVALID_ARG (NULL world/def, negative density, friction or
 *  restitution, a shape reaching farther than SX_HUGE from the body origin
 *  in x or y: beyond it the narrowphase has no precision left to offer the
 *  solver); SX_ERR_NONFINITE (non-finite density, friction or
 *  restitution); SX_ERR_STALE_HANDLE; SX_ERR_NO_MEMORY; SX_ERR_CAPACITY
 *  (SX_WORLD_MAX_ITEMS collider slots in use or retired). */
sx_status sx_body_add_collider(sx_world *world, sx_body_id body, const sx_collider_def *def,
                               sx_collider_id *out);

/** Attaches a compound collider: the convex parts of `compound` (each with
 *  its offset in the body frame) act as ONE collider with one handle, one
 *  set of material fields and one filter. The world copies the parts (the
 *  caller's array need not outlive the call). def->shape is ignored; the
 *  other fields of def apply to every part. Mass from def->density: the
 *  area-weighted centroid of the parts and their inertia moved by the
 *  parallel-axis theorem (sx_compound_mass; overlapping parts count twice).
 *  The broadphase sees the union of the parts' bounds; the narrowphase
 *  makes one contact (up to 2 points) per touching part pair, with the
 *  part indices in sx_contact_data and warm starting per part pair; queries
 *  and ray casts test the parts (a point or box in a notch of a U misses);
 *  sx_world_draw calls draw_shape once per part. Errors as
 *  sx_body_add_collider, plus SX_ERR_INVALID_ARG for a NULL compound and
 *  the status of sx_compound_validate (count < 1 or a NULL parts array:
 *  SX_ERR_INVALID_ARG; a bad part: its shape's status). */
sx_status sx_body_add_compound(sx_world *world, sx_body_id body, const sx_compound *compound,
                               const sx_collider_def *def, sx_collider_id *out);

/** Decomposes a simple, possibly concave outline (points in the body frame,
 *  any winding) with sx_decompose_polygon and attaches the parts as one
 *  compound collider (sx_body_add_compound). Errors: as
 *  sx_body_add_collider for world, body and def (def->shape is ignored);
 *  SX_ERR_INVALID_ARG for NULL points or count < 3 and (after
 *  SX_ERR_NONFINITE for NaN/Inf) for a point farther than SX_HUGE from the
 *  body origin in x or y; otherwise the status of
 *  sx_decompose_polygon (SX_ERR_NONFINITE for NaN/Inf, SX_ERR_INVALID_ARG
 *  for a self-intersecting outline such as a bow-tie, SX_ERR_DEGENERATE for
 *  all-collinear or zero-area outlines); SX_ERR_CAPACITY for count above
 *  SX_DECOMPOSE_MAX_POINTS (or SX_WORLD_MAX_ITEMS collider slots in use);
 *  SX_ERR_NO_MEMORY. */
sx_status sx_body_add_outline(sx_world *world, sx_body_id body, const sx_vec2 *points, int count,
                              const sx_collider_def *def, sx_collider_id *out);

/** Number of parts of a collider: a compound's part count, 1 for a plain
 *  collider, 0 for a stale handle or NULL world. */
int sx_collider_get_part_count(const sx_world *world, sx_collider_id collider);

/** Copies part `index` of a collider (a plain collider has one part: its
 *  shape with the identity offset) into *out. SX_ERR_INVALID_ARG (NULL,
 *  index out of range), SX_ERR_STALE_HANDLE. */
sx_status sx_collider_get_part(const sx_world *world, sx_collider_id collider, int index,
                               sx_compound_part *out);

/** Removes a collider (and its contacts) and updates its body's mass.
 *  SX_ERR_INVALID_ARG (NULL), SX_ERR_STALE_HANDLE. */
sx_status sx_destroy_collider(sx_world *world, sx_collider_id collider);

/** True if the handle names a live collider of this world. */
bool sx_collider_is_valid(const sx_world *world, sx_collider_id collider);

/** The body a collider is attached to (null handle if stale). */
sx_body_id sx_collider_get_body(const sx_world *world, sx_collider_id collider);

/* ---- queries ------------------------------------------------------------ */

/* Queries see the colliders of enabled bodies, sensors included, at their
 * current transforms, visited in collider-slot order (deterministic). They
 * test every collider (cost linear in the collider count: there is no
 * bounding-volume tree yet). */

/** Called for each collider a query finds; return false to stop the query. */
typedef bool sx_query_fn(sx_collider_id collider, sx_body_id body, void *context);

/** Reports every collider whose tight bounds overlap `box` (for a compound:
 *  the bounds of one of its parts). fn may be NULL
 *  (just count). Returns the number of colliders reported (0 for a NULL
 *  world or an invalid or non-finite box). */
int sx_world_query_aabb(const sx_world *world, sx_aabb box, sx_query_fn *fn, void *context);

/** Reports every collider whose shape contains `point` (boundary included,
 *  as sx_contains_point). Returns the count (0 for bad input). */
int sx_world_query_point(const sx_world *world, sx_vec2 point, sx_query_fn *fn, void *context);

/** Reports every collider that overlaps `shape` placed by `xf` (as
 *  sx_overlap: touching counts). Returns the count (0 for bad input, an
 *  invalid shape included). */
int sx_world_query_shape(const sx_world *world, const sx_shape *shape, sx_xform xf, sx_query_fn *fn,
                         void *context);

/** The closest hit of a world ray cast. */
typedef struct sx_world_ray_hit {
    sx_collider_id collider;
    sx_body_id body;
    sx_vec2 point;    /**< world hit point */
    sx_vec2 normal;   /**< unit surface normal at the hit, facing the ray */
    sx_real fraction; /**< hit = origin + fraction x translation */
    int part;         /**< the compound part hit (0 for a plain collider) */
} sx_world_ray_hit;

/** Casts a ray (see sx_ray_input) against every collider and returns true
 *  with the closest hit in *out (on equal fractions, the lower collider
 *  slot). false, with *out zeroed, for no hit or bad input (NULL pointers,
 *  non-finite ray, zero translation). */
bool sx_world_cast_ray(const sx_world *world, const sx_ray_input *ray, sx_world_ray_hit *out);

/* ---- debug draw ------------------------------------------------------------ */

/** Callbacks for sx_world_draw; any may be NULL (that kind is not drawn). The
 *  library calls them; it draws nothing itself. */
typedef struct sx_debug_draw {
    /** Once per collider of an enabled body: its shape in local space and
     *  the body transform that places it, with the body's type and whether
     *  the collider is a sensor. */
    void (*draw_shape)(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                       void *context);
    /** Once per contact point of the last collide: the point, the unit
     *  normal from A to B and the depth (> 0 overlapping, < 0 speculative). */
    void (*draw_contact)(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context);
    /** Once per collider of an enabled body: its tight world bounds. */
    void (*draw_aabb)(sx_aabb box, void *context);
    /** Passed to every callback. */
    void *context;
} sx_debug_draw;

/** Calls the debug-draw callbacks for the world's current state, colliders
 *  in slot order then contacts in contact order. SX_ERR_INVALID_ARG for
 *  NULL world or draw. */
sx_status sx_world_draw(const sx_world *world, const sx_debug_draw *draw);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_WORLD_H */
