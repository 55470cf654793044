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
 * One call of sx_world_step(world, dt) runs the public stages
 *
 *   sx_world_begin_step(dt)   clears the events, sets the collide's look-ahead
 *   sx_world_collide()        broadphase + narrowphase into the contact list
 *
 * once, then for each of `sub_steps` sub-steps of length h = dt / sub_steps
 *
 *   sx_world_apply_forces(h)  v += h (g * gravity_scale + F / m) + J / m
 *   sx_world_solve(h)         impacts, then impulses on velocities
 *   sx_world_integrate(h)     positions from the new velocities
 *   sx_world_separate(h)      positional correction (or the relax pass)
 *
 * and then sx_world_continuous() (fast bodies swept to their time of impact),
 * sx_world_clear_forces() and sx_world_update_sleep(dt). Contacts
 * are found once per step; inside the sub-steps each contact point's
 * separation follows the bodies' motion (its anchors turn with the bodies,
 * the normal stays), so the sub-steps stay accurate without running the
 * narrowphase again; across steps, a touching pair whose bodies moved less
 * than manifold_keep_slops relative to each other keeps its contact points
 * the same way instead of searching them again, and its solver constraint
 * (anchors, effective masses, the lane it was filled into) with them. This is
 * symplectic Euler (velocities first, then positions with the new
 * velocities). Callers such as the flecs systems may run the stages
 * themselves, in this order, with their own code in between; a mass that
 * code changes (a collider added or destroyed, a type or density set) is
 * seen by the next sx_world_solve and sx_world_separate.
 *
 * Speed limit: in one sub-step a body turns at most SX_MAX_ROTATION and
 * moves at most SX_HUGE (in length units: see SX_HUGE in base.h for worlds
 * whose length_units_per_meter differs from SX_LENGTH_UNITS_PER_METER).
 * sx_world_apply_forces and sx_world_integrate scale faster velocities down
 * to the limit (direction kept), so a finite torque on a tiny inertia, a
 * huge impulse or a huge dt gives a fast body, never an infinite or NaN
 * state. At the default 60 Hz and 5 sub-steps the rotation
 * limit is 471 rad/s (4500 rpm); a faster spin needs more sub-steps (the
 * rotation update, q + h w q' renormalised, turns by atan(h w), less than a
 * quarter turn per sub-step, whatever w is).
 *
 * Fast bodies: contacts are found once per step, from the positions the
 * step starts at, for every pair of shapes whose gap is within the
 * speculative margin (speculative_slops x the linear slop: 2 cm by default)
 * plus how far each body can move in the step at the velocity it starts
 * with; the solver then lets no contact close by more than its gap. So a
 * body moving straight at a collider stops at it however fast it goes. A
 * contact's normal and points are those of the step's start, so a fast
 * body that turns, or one deflected by a third body within the step towards
 * a collider it had no contact with, could end the step overlapping that
 * collider (past the middle of a thin one, to be pushed out on the far
 * side): the continuous stage (sx_world_continuous, on by default:
 * sx_world_def.enable_continuous) sweeps such bodies back to their time of
 * impact. A bullet relies on that sweep as Box2D v3's do: its bounds are
 * not grown by its travel, and its contacts with other awake dynamic
 * bodies are made only where the two motions bring them within the margin,
 * so a volley of bullets does not pair each with its neighbours.
 *
 * Sleeping: islands of touching bodies that stay slow fall asleep and cost
 * no solver work until something touches or pushes them. Around the step: contact begin/end events,
 * world queries (bounds, point, shape, ray) and a debug-draw callback interface.
 *
 * Callbacks: the world calls user code only from the queries with a
 * callback (sx_world_query_aabb, _point, _shape) and from sx_world_draw,
 * never from inside the step (contact and sensor events are arrays read
 * after it). While such a callback runs the world is locked
 * (sx_world_is_locked): creating or destroying bodies and colliders, and
 * running sx_world_step or any of its stages, answer SX_ERR_LOCKED and
 * change nothing, as Box2D v3 and Chipmunk refuse them in their callbacks;
 * collect the handles and act once the query returns. Every other call
 * works in a callback and its effect shows in the rest of the walk: getters,
 * other queries and ray casts, forces and impulses, velocities, teleports,
 * body types, waking and sleeping, gravity, clearing the events.
 * sx_world_destroy from a callback stops the walk (no further callback) and
 * frees the world when the outermost query or draw returns. The lock is a
 * count in the world, so the queries with a callback and sx_world_draw,
 * although they take a const world, must not run on one world from two
 * threads at once (sx_world_cast_ray and the queries without a callback
 * only read it).
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
#include "vecmath.h"
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
SX_API uint64_t sx_body_id_to_u64(sx_body_id id);
/** Unpacks sx_body_id_to_u64's value. 0 gives the null handle. */
SX_API sx_body_id sx_body_id_from_u64(uint64_t bits);
/** True for the null body handle. */
SX_API bool sx_body_id_is_null(sx_body_id id);
/** Packs a collider handle into 64 bits, as sx_body_id_to_u64. */
SX_API uint64_t sx_collider_id_to_u64(sx_collider_id id);
/** Unpacks sx_collider_id_to_u64's value. */
SX_API sx_collider_id sx_collider_id_from_u64(uint64_t bits);

/* ---- world -------------------------------------------------------------- */

/** Most workers a world's task system may name (sx_world_def.worker_count). */
#define SX_MAX_WORKERS 64

/** A parallel loop's body: items [start, end) of a task, run by worker
 *  `worker` (0 .. worker_count - 1; a worker runs one range at a time).
 *  task_context is the world's, to pass back unchanged. */
typedef void sx_task_fn(int start, int end, int worker, void *task_context);

/** The game's job system runs `task` over items [0, item_count), split into
 *  ranges of at least min_range items (the last may be shorter), on up to
 *  worker_count workers at once, and returns a handle for finish_task; or it
 *  runs the whole task before returning and returns NULL. user_context is
 *  sx_world_def.user_task_context. */
typedef void *sx_enqueue_task_fn(sx_task_fn *task, int item_count, int min_range,
                                 void *task_context, void *user_context);

/** Waits until every range of the task enqueue_task returned `user_task`
 *  for has run (never called for NULL). */
typedef void sx_finish_task_fn(void *user_task, void *user_context);

/** World settings. Start from sx_default_world_def() and change fields. */
typedef struct sx_world_def {
    /** Gravity in m/s^2. Default (0, -10). */
    sx_vec2 gravity;
    /** Sub-steps per sx_world_step, 1 .. SX_MAX_SUB_STEPS. Default 5: each
     *  runs the solver stages with h = dt / sub_steps on the step's
     *  contacts, which stiffens stacks (a sub-step buys more stiffness than
     *  a pass: 5 x 3 passes hold stacks and piles still where 4 x 4 sway). */
    int sub_steps;
    /** Sequential-impulse passes of sx_world_solve per sub-step,
     *  1 .. SX_MAX_ITERATIONS. Default 3. */
    int velocity_iterations;
    /** Passes of sx_world_separate per sub-step, 0 .. SX_MAX_ITERATIONS (0
     *  turns it off): positional correction with rigid contacts
     *  (contact_hertz 0), relax passes with soft ones. Default 1. */
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
    /** 0 (default): rigid contacts, overlap removed by the positional
     *  correction of sx_world_separate (no kinetic energy added). > 0: soft
     *  contacts, the frequency (Hz) of the stiff damped spring that pushes
     *  overlapping bodies apart in sx_world_solve's passes, capped at a
     *  quarter of the sub-step rate and doubled against static and kinematic
     *  bodies; sx_world_separate then runs relax passes (the same passes
     *  without the push-out, which take its velocity back). */
    sx_real contact_hertz;
    /** Damping ratio of that spring (>= 0; 1 is critical). Default 10: a
     *  push-out that does not overshoot. */
    sx_real contact_damping_ratio;
    /** Approach speed (m/s) below which contacts do not bounce: restitution
     *  only applies to impacts at this speed or faster (to round-off: an
     *  approach within 1e-4 of it, relative, counts as equal), so resting
     *  bodies do not jitter. Default 1 m/s (>= 0). */
    sx_real restitution_threshold;
    /** Speculative contact margin in units of the linear slop (>= 0): shapes
     *  closer than this get contact points before they touch, and the solver
     *  lets them close exactly the gap in one sub-step. Default 4. */
    sx_real speculative_slops;
    /** How far a touching pair's bodies may move relative to each other, in
     *  linear slops (0 .. 1), before the pair's contact points are found
     *  again: until then each collide moves the reported points with the
     *  bodies (off by at most this much from a fresh search), keeps the
     *  solver's anchors and effective masses of the search, and skips the
     *  narrowphase and the contact's preparation, which a resting pile
     *  spends most of its collide on. 0 searches every touching pair every
     *  step. Default 0.25. */
    sx_real manifold_keep_slops;
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
    /** Continuous collision (sx_world_continuous, as Box2D v3's
     *  enableContinuous): fast dynamic bodies are swept against static and
     *  kinematic colliders, bullets against dynamic ones too; a bullet's
     *  bounds are then not grown by its travel, and its contacts with other
     *  awake dynamic bodies are made only where their motions over the step
     *  bring them within the margin. false: no sweep at all (bullets
     *  included) and no record of poses at collide; every fast body, bullets
     *  included, then has only its speculative contacts, grown by its whole
     *  step's travel (see "Fast bodies" above). Default true. */
    bool enable_continuous;
    /** A job system for the step's parallel loops (as Box2D v3's
     *  enqueueTask / finishTask): enqueue_task and finish_task both set, or
     *  both NULL (the default: one thread). The loops: the narrowphase of the
     *  collide stage, each broadphase pair's manifold on its own; the contacts
     *  are then made from them in pair order, so a world steps to the same
     *  bits with any job system and any worker_count. Tasks are enqueued and
     *  finished from inside sx_world_step (and sx_world_collide), on the
     *  thread that calls it. */
    sx_enqueue_task_fn *enqueue_task;
    sx_finish_task_fn *finish_task;
    /** Workers the job system runs a task on, 1 .. SX_MAX_WORKERS. Default 1.
     *  With 1, no task is enqueued. */
    int worker_count;
    /** Handed to enqueue_task and finish_task. Default NULL. */
    void *user_task_context;
} sx_world_def;

/** The default world settings documented field by field in sx_world_def. */
SX_API sx_world_def sx_default_world_def(void);

/** Creates a world. Returns NULL when def is NULL, a field is out of its
 *  documented range or not finite (sx_world_def_validate names the field),
 *  or memory runs out. */
SX_API sx_world *sx_world_create(const sx_world_def *def);

/** Destroys the world and everything in it (NULL is ignored). Every handle of
 *  it becomes meaningless. Called from a query or draw callback of this
 *  world, it stops the walk (no further callback) and the world goes when
 *  the outermost query or draw returns (the world pointer stays usable
 *  until then). */
SX_API void sx_world_destroy(sx_world *world);

/** True while a query or draw callback of this world runs (see "Callbacks"
 *  above): creation, destruction and the step answer SX_ERR_LOCKED. False
 *  for NULL. */
SX_API bool sx_world_is_locked(const sx_world *world);

/** Sets the gravity and wakes every sleeping body (one pass over the body
 *  slots; each island wakes at the cost of its own bodies).
 *  SX_ERR_INVALID_ARG (NULL world), SX_ERR_NONFINITE. */
SX_API sx_status sx_world_set_gravity(sx_world *world, sx_vec2 gravity);
/** The gravity (zero for a NULL world). */
SX_API sx_vec2 sx_world_get_gravity(const sx_world *world);
/** Number of live bodies. */
SX_API int sx_world_body_count(const sx_world *world);
/** Number of live dynamic bodies that are awake. */
SX_API int sx_world_awake_body_count(const sx_world *world);
/** The world's linear slop: 0.005 x length_units_per_meter. */
SX_API sx_real sx_world_linear_slop(const sx_world *world);

/* ---- the step and its stages -------------------------------------------- */

/** Advances the world by dt seconds: begin_step(dt) and collide, then for
 *  each sub-step apply_forces, solve, integrate and separate with h = dt /
 *  sub_steps, then clear_forces and update_sleep(dt)
 *  (a dt so small that dt / sub_steps rounds to 0 is one sub-step of dt).
 *  Errors, with the world left
 *  untouched: SX_ERR_INVALID_ARG (NULL world, dt <= 0), SX_ERR_NONFINITE (dt
 *  NaN or infinite), SX_ERR_LOCKED (called from a callback of the world;
 *  the stages below answer it too). SX_ERR_NO_MEMORY: the contact list or
 *  the impact pass's scratch could not grow; SX_ERR_CAPACITY: a list would
 *  pass SX_WORLD_MAX_ITEMS (more than 2^30 - 1 broadphase pairs or
 *  contacts); either way the step stops after the stages already run. */
SX_API sx_status sx_world_step(sx_world *world, sx_real dt);

/** Stage 1: for every enabled, awake dynamic body, v += h (gravity x gravity_scale +
 *  F / m) + J / m and w += h (T / I) + L / I, then damping
 *  v *= 1 / (1 + h c), then the speed limit (h w within SX_MAX_ROTATION, h
 *  |v| within SX_HUGE). F, T are the force and torque accumulators (kept: they
 *  act over every sub-step of a step until sx_world_clear_forces); J, L the
 *  impulse accumulators, applied once and cleared here. Static and kinematic
 *  bodies are untouched. Errors: SX_ERR_INVALID_ARG (NULL, h <= 0),
 *  SX_ERR_NONFINITE, SX_ERR_LOCKED. */
SX_API sx_status sx_world_apply_forces(sx_world *world, sx_real h);

/** Stage 2 (once per step, after sx_world_begin_step): finds the touching
 *  (or within the speculative margin, grown by how far each collider can
 *  move in the step) collider pairs and builds their manifolds, their
 *  anchors and effective masses for the step's sub-steps. Pairs are found
 *  by sort-and-sweep over the colliders' bounds; pairs without an awake dynamic body (static,
 *  kinematic or sleeping on both sides), colliders of one body, filtered
 *  pairs and sensors are skipped, and the contacts of sleeping bodies are
 *  carried over unchanged. Contacts persist across calls by collider pair,
 *  and each point keeps its accumulated impulses while its feature id
 *  persists (warm starting). An awake body that touches a sleeping one wakes
 *  its island. Pairs that start or stop having a manifold are recorded as
 *  contact events; then the sensors are updated (sensor events). Errors:
 *  SX_ERR_INVALID_ARG (NULL), SX_ERR_NO_MEMORY, SX_ERR_CAPACITY (a list
 *  would pass SX_WORLD_MAX_ITEMS), SX_ERR_LOCKED. */
SX_API sx_status sx_world_collide(sx_world *world);

/** Stage 6 (once per step, after the sub-steps; sx_world_step runs it):
 *  continuous collision; nothing when sx_world_def.enable_continuous is
 *  false. An awake dynamic body is swept from where it was
 *  at the step's sx_world_collide to where the sub-steps left it (its centre
 *  of mass on a straight path, its angle turning evenly) when the
 *  speculative contacts of that collide may have missed part of its motion:
 *  it went farther than its speed at collide time allowed, or strayed from
 *  that straight path (knocked on or deflected), or turned, by more than
 *  half its thinnest extent at its farthest point (a spinning blade).
 *  Bullets (sx_body_def.bullet) are swept whenever they move that much. The
 *  sweep (sx_time_of_impact, target SX_LINEAR_SLOP) runs against static and
 *  kinematic colliders, and for bullets against dynamic ones too, all at
 *  their final poses; sensors and filtered pairs are skipped. A body that
 *  would hit is put back at its earliest time of impact, just short of
 *  contact: the rest of the step's motion is dropped and its velocity kept
 *  (the next collide finds the contact and the solver stops it there),
 *  scaled down just enough to pay for the work gravity and the applied
 *  force and torque did over the dropped part, so no energy is added (a
 *  move back its motion cannot pay for, as for a slow body driven by a
 *  large force, is not made). A body that starts the step
 *  within the target of a collider is left to its contact until it gets a
 *  quarter slop deeper than it started (a fast turn pressed into a contact
 *  can sink that much a step); shapes whose cores already touch are left to
 *  the contact. Bullets meet each other with both moving: the bullets'
 *  paths are swept and pruned, each pair whose bounding discs come within
 *  the margin along their straight paths gets its time of impact, and both
 *  are put back to their earliest (then each is swept against the others
 *  at their final poses). Two fast dynamic bodies that are not bullets are
 *  not swept against each other (their speculative contacts hold them
 *  while each keeps to its straight path), and a body put back may overlap
 *  another dynamic body until the next step separates them. A body whose colliders
 *  or mass change between sx_world_collide and this stage is not swept.
 *  Cost: the step's last sx_world_separate, in the pass over the bodies it
 *  makes anyway, lists those that strayed from their foreseen path by half
 *  the margin, turned by a quarter of the angular slop, or are bullets;
 *  this stage looks at those alone (a driver whose last stage before this
 *  one is not sx_world_separate costs one pass over the moving bodies
 *  here). Errors:
 *  SX_ERR_INVALID_ARG (NULL), SX_ERR_LOCKED, SX_ERR_NO_MEMORY (the query
 *  scratch could not grow). Without a collide since the last call: SX_OK,
 *  nothing moves. */
SX_API sx_status sx_world_continuous(sx_world *world);

/** Stage 3: the contacts of the last collide, on velocities. Each point's
 *  separation at the current positions (the anchors of collide time turned
 *  with the bodies), then the impact pass (restitution), on the velocities
 *  the bodies arrive with: the contacts approaching at the restitution
 *  threshold or faster that close their gap within this sub-step are
 *  resolved one at a time in order of their time of impact, each
 *  approaching point leaving at e times its approach speed
 *  (e = max(e_a, e_b); both points of a two-point contact at once), with
 *  Coulomb friction on that impulse; after each impact the other contacts
 *  of its two bodies are looked at again with the new velocities, so an
 *  impulse travels down a row of touching bodies (Newton's cradle). Each
 *  impact also records the time-of-impact correction of its bodies'
 *  positions, applied by sx_world_integrate. Then the warm start (the last
 *  sub-step's accumulated impulses) and `velocity_iterations` passes of
 *  Coulomb friction (|tangent impulse| <= mu x normal impulse,
 *  mu = sqrt(mu_a mu_b)) and non-penetration (accumulated normal impulse
 *  >= 0; a speculative point may close its gap in this sub-step but not
 *  more); the two normal constraints of a two-point contact are solved
 *  together, exactly (a 2x2 complementarity problem). Energy: with every
 *  restitution <= 1 no impulse of the impact pass adds kinetic energy, for
 *  chained and simultaneous impacts at any mass ratio; the warm start and
 *  the passes never give a group of touching bodies more energy than they
 *  took from the same bodies in earlier sub-steps (a heavy body on a light
 *  support that the passes cannot hold exactly sags and springs back;
 *  beyond that the group's impulses are scaled down), the energy being the
 *  one the step conserves (kinetic, less m acc . x, plus h m acc . v / 2,
 *  acc = gravity x gravity scale + force / mass; kinematic bodies' work
 *  aside). Penetration is not turned into velocity here (see
 *  sx_world_separate). Errors: SX_ERR_INVALID_ARG (NULL, h <= 0),
 *  SX_ERR_NONFINITE, SX_ERR_NO_MEMORY (scratch could not grow: without the
 *  impact pass's the pass is skipped, without the energy guard's the
 *  passes start cold; the passes still run; without the passes' own,
 *  none run), SX_ERR_LOCKED. */
SX_API sx_status sx_world_solve(sx_world *world, sx_real h);

/** Stage 4: symplectic Euler positions: centre of mass += h v, rotation
 *  advanced by h w (renormalised), for awake dynamic and kinematic bodies,
 *  after the speed limit of stage 1 (for what the solver added);
 *  then the time-of-impact corrections of the last solve's impacts (a body
 *  whose velocity changed by dv at time t of the sub-step moves by -dv t,
 *  since it kept its old velocity until t).
 *  Errors: SX_ERR_INVALID_ARG (NULL, h <= 0), SX_ERR_NONFINITE, SX_ERR_LOCKED. */
SX_API sx_status sx_world_integrate(sx_world *world, sx_real h);

/** Stage 5: with rigid contacts (contact_hertz 0), removes overlap left
 *  after integration by moving positions only (velocities are not touched,
 *  so no kinetic energy is ever added): for `position_iterations` passes,
 *  each contact point's current separation s (from the anchors stored by
 *  collide, turned with the bodies, along the normal of collide time) gives
 *  the correction C = max(correction_factor (s + slop),
 *  -max_correction_speed h / position_iterations) when s < -slop, applied
 *  as a pseudo-impulse split by inverse mass and inverse inertia. With soft
 *  contacts, `position_iterations` relax passes instead: the velocity
 *  passes of sx_world_solve without the push-out. We chose positional correction over a
 *  Baumgarte velocity bias because a bias turns overlap into velocity, which
 *  comes out as kinetic energy (bodies created overlapping fly apart); split
 *  impulses would do the same work with a second set of velocities.
 *  Errors: SX_ERR_INVALID_ARG (NULL, h <= 0), SX_ERR_NONFINITE,
 *  SX_ERR_NO_MEMORY (the relax passes' scratch could not grow: no pass),
 *  SX_ERR_LOCKED. */
SX_API sx_status sx_world_separate(sx_world *world, sx_real h);

/** Clears every body's force and torque accumulators (the last stage of a
 *  step). Errors: SX_ERR_INVALID_ARG (NULL), SX_ERR_LOCKED. */
SX_API sx_status sx_world_clear_forces(sx_world *world);

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
 *  SX_ERR_NO_MEMORY (the scratch arrays could not grow; nothing sleeps),
 *  SX_ERR_LOCKED. */
SX_API sx_status sx_world_update_sleep(sx_world *world, sx_real dt);

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
SX_API int sx_world_contact_count(const sx_world *world);
/** Copies contact `index` (0 .. count-1) into *out. SX_ERR_INVALID_ARG for
 *  NULL or an index out of range. */
SX_API sx_status sx_world_get_contact(const sx_world *world, int index, sx_contact_data *out);

/** A contact's pair, normal and points without its depths and impulses: the
 *  light read for copying every contact each step. */
typedef struct sx_contact_pair {
    sx_collider_id collider_a, collider_b;
    sx_body_id body_a, body_b;
    /** As sx_contact_data. */
    int part_a, part_b;
    sx_vec2 normal;
    int count;
    sx_vec2 points[2];
} sx_contact_pair;

/** Copies contacts first, first + 1, ... (the indices of sx_world_get_contact)
 *  into out[0 .. capacity-1] and returns how many it copied: fewer than
 *  capacity at the end of the list, 0 for NULL, capacity < 1 or first
 *  outside 0 .. count-1. One call walks the list once. */
SX_API int sx_world_get_contact_pairs(const sx_world *world, int first, sx_contact_pair *out,
                                      int capacity);

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
SX_API sx_contact_events sx_world_get_contact_events(const sx_world *world);

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
SX_API sx_sensor_events sx_world_get_sensor_events(const sx_world *world);

/** Forgets the recorded contact and sensor events. SX_ERR_INVALID_ARG for
 *  NULL. */
SX_API sx_status sx_world_clear_events(sx_world *world);

/** The first stage of a step of dt seconds: clears the contact and sensor
 *  events and tells the next sx_world_collide how far ahead it looks (each
 *  collider's bounds and speculative margin grow by how far its points can
 *  move in dt at their current velocities, so a fast body's contacts exist
 *  before it reaches them). sx_world_step calls it first. Errors:
 *  SX_ERR_INVALID_ARG (NULL world, dt <= 0), SX_ERR_NONFINITE. */
SX_API sx_status sx_world_begin_step(sx_world *world, sx_real dt);

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
    /** A fast body that must not pass through other dynamic bodies either
     *  (a projectile): continuous collision sweeps it against dynamic bodies
     *  as well as static and kinematic ones, and against other bullets with
     *  both moving (see sx_world_continuous). It then relies on that sweep:
     *  its bounds are not grown by its travel, and it pairs with another
     *  awake dynamic body only where their motions over the step bring
     *  them within the margin, so many bullets flying together cost little
     *  (with sx_world_def.enable_continuous off it keeps the grown bounds).
     *  Default false. */
    bool bullet;
    void *user_data; /**< returned by sx_body_get_user_data; default NULL */
} sx_body_def;

/** The default body settings (a static body at the origin). */
SX_API sx_body_def sx_default_body_def(void);

/** Creates a body. *out receives its handle (the null handle on error).
 *  Errors: SX_ERR_INVALID_ARG (NULL world/def/out, unknown type, negative
 *  damping), SX_ERR_NONFINITE, SX_ERR_NO_MEMORY, SX_ERR_CAPACITY
 *  (SX_WORLD_MAX_ITEMS body slots in use or retired: see sx_destroy_body),
 *  SX_ERR_LOCKED (from a callback). A dynamic body without colliders of
 *  positive mass gets mass 1 kg and no rotational inertia (contacts cannot
 *  turn it; its own angular velocity, if set, is kept). */
SX_API sx_status sx_create_body(sx_world *world, const sx_body_def *def, sx_body_id *out);

/** Destroys a body, its colliders and its contacts, and wakes its island and
 *  the bodies it touched. Cost: what it touches (its island, its contacts);
 *  the first destruction, teleport or retype after a collide also indexes
 *  the contacts by body, in one pass that the ones after it share. Its slot
 *  is reused by a later body with the next generation, or retired after
 *  generation 2^32 - 1 (so no old handle ever names a new body; colliders'
 *  slots likewise). SX_ERR_INVALID_ARG (NULL world), SX_ERR_LOCKED (from a
 *  callback), SX_ERR_STALE_HANDLE. */
SX_API sx_status sx_destroy_body(sx_world *world, sx_body_id body);

/** True if the handle names a live body of this world. */
SX_API bool sx_body_is_valid(const sx_world *world, sx_body_id body);

/* Getters answer a stale handle or NULL world with zero values (identity
 * transform, SX_BODY_STATIC, NULL user data). */

/** Body type. */
SX_API sx_body_type sx_body_get_type(const sx_world *world, sx_body_id body);
/** World position of the body origin. */
SX_API sx_vec2 sx_body_get_position(const sx_world *world, sx_body_id body);
/** Angle in (-pi, pi]. */
SX_API sx_real sx_body_get_angle(const sx_world *world, sx_body_id body);
/** The body frame (origin and rotation). */
SX_API sx_xform sx_body_get_transform(const sx_world *world, sx_body_id body);
/** World centre of mass. */
SX_API sx_vec2 sx_body_get_world_center(const sx_world *world, sx_body_id body);
/** Centre of mass in the body frame. */
SX_API sx_vec2 sx_body_get_local_center(const sx_world *world, sx_body_id body);
/** Velocity of the centre of mass (m/s). */
SX_API sx_vec2 sx_body_get_linear_velocity(const sx_world *world, sx_body_id body);
/** Angular velocity (rad/s, counter-clockwise positive). */
SX_API sx_real sx_body_get_angular_velocity(const sx_world *world, sx_body_id body);
/** Mass in kg (0 for static and kinematic bodies). */
SX_API sx_real sx_body_get_mass(const sx_world *world, sx_body_id body);
/** Rotational inertia about the centre of mass, kg m^2 (0 when fixed or not
 *  dynamic). */
SX_API sx_real sx_body_get_inertia(const sx_world *world, sx_body_id body);
/** The user data of the body def. */
SX_API void *sx_body_get_user_data(const sx_world *world, sx_body_id body);
/** False while the body sleeps (static bodies: always false). */
SX_API bool sx_body_is_awake(const sx_world *world, sx_body_id body);

/** What a renderer or an ECS copies back after each step, in one call. */
typedef struct sx_body_state {
    sx_xform transform;      /**< as sx_body_get_transform */
    sx_vec2 linear_velocity; /**< as sx_body_get_linear_velocity */
    sx_real angular_velocity;
    bool awake; /**< as sx_body_is_awake */
} sx_body_state;

/** The body's transform, velocities and awake flag: the four getters'
 *  answers, with one check of the handle. Errors: SX_ERR_INVALID_ARG (NULL
 *  world or out), SX_ERR_STALE_HANDLE; *out (when not NULL) then holds the
 *  getters' answers for a stale handle: the identity, zero velocities, not
 *  awake. */
SX_API sx_status sx_body_get_state(const sx_world *world, sx_body_id body, sx_body_state *out);

/** Wakes a sleeping dynamic body and its island (awake = true), or puts this
 *  body to sleep now, velocities zeroed (awake = false; it wakes as
 *  documented at sx_world_update_sleep, so a body still touching an awake
 *  one wakes again at the next collide). SX_ERR_INVALID_ARG (NULL),
 *  SX_ERR_STALE_HANDLE. Static and kinematic bodies ignore it (SX_OK). */
SX_API sx_status sx_body_set_awake(sx_world *world, sx_body_id body, bool awake);

/** Makes a body a bullet or not (sx_body_def.bullet). SX_ERR_INVALID_ARG
 *  (NULL world), SX_ERR_STALE_HANDLE. */
SX_API sx_status sx_body_set_bullet(sx_world *world, sx_body_id body, bool bullet);
/** True if the body is a bullet (false for a stale handle). */
SX_API bool sx_body_is_bullet(const sx_world *world, sx_body_id body);

/** Allows or forbids sleeping for this body (sx_body_def.enable_sleep);
 *  forbidding wakes it. SX_ERR_INVALID_ARG (NULL), SX_ERR_STALE_HANDLE. */
SX_API sx_status sx_body_set_sleep_enabled(sx_world *world, sx_body_id body, bool enable);
/** The body's enable_sleep; false for a stale handle. */
SX_API bool sx_body_is_sleep_enabled(const sx_world *world, sx_body_id body);

/** Teleports the body: its origin to `position`, its angle to `angle`.
 *  Velocities are kept; the body and the bodies it touches wake. SX_ERR_INVALID_ARG (NULL),
 * SX_ERR_STALE_HANDLE, SX_ERR_NONFINITE. */
SX_API sx_status sx_body_set_transform(sx_world *world, sx_body_id body, sx_vec2 position,
                                       sx_real angle);
/** Sets the centre-of-mass velocity (ignored by static bodies, which stay at
 *  rest). Errors as sx_body_set_transform. */
SX_API sx_status sx_body_set_linear_velocity(sx_world *world, sx_body_id body, sx_vec2 v);
/** Sets the angular velocity (ignored by static bodies and fixed rotation).
 *  Errors as sx_body_set_transform. */
SX_API sx_status sx_body_set_angular_velocity(sx_world *world, sx_body_id body, sx_real w);
/** Changes the body type; mass and inertia are recomputed (a body that
 *  becomes static stops). SX_ERR_INVALID_ARG for an unknown type. */
SX_API sx_status sx_body_set_type(sx_world *world, sx_body_id body, sx_body_type type);

/* Forces and impulses ACCUMULATE until the step applies them (forces over
 * the whole step, impulses once), and wake the body. Static and
 * kinematic bodies ignore them (SX_OK). Errors: SX_ERR_INVALID_ARG (NULL world),
 * SX_ERR_STALE_HANDLE, SX_ERR_NONFINITE (a NaN/Inf argument, or a sum that
 * would overflow: a huge force at a far point, or huge forces added up; the
 * accumulators are then left as they were). */

/** Adds a force (N) at the centre of mass. */
SX_API sx_status sx_body_apply_force(sx_world *world, sx_body_id body, sx_vec2 force);
/** Adds a force (N) at a world point: also adds the torque
 *  (point - centre of mass) x force. */
SX_API sx_status sx_body_apply_force_at_point(sx_world *world, sx_body_id body, sx_vec2 force,
                                              sx_vec2 point);
/** Adds a torque (N m). */
SX_API sx_status sx_body_apply_torque(sx_world *world, sx_body_id body, sx_real torque);
/** Adds a linear impulse (N s) at the centre of mass. */
SX_API sx_status sx_body_apply_impulse(sx_world *world, sx_body_id body, sx_vec2 impulse);
/** Adds a linear impulse (N s) at a world point: also adds the angular
 *  impulse (point - centre of mass) x impulse. */
SX_API sx_status sx_body_apply_impulse_at_point(sx_world *world, sx_body_id body, sx_vec2 impulse,
                                                sx_vec2 point);
/** Adds an angular impulse (N m s). */
SX_API sx_status sx_body_apply_angular_impulse(sx_world *world, sx_body_id body, sx_real impulse);

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
SX_API sx_collider_def sx_default_collider_def(void);

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
 *  (SX_WORLD_MAX_ITEMS collider slots in use or retired); SX_ERR_LOCKED
 *  (from a callback). */
SX_API sx_status sx_body_add_collider(sx_world *world, sx_body_id body, const sx_collider_def *def,
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
SX_API sx_status sx_body_add_compound(sx_world *world, sx_body_id body, const sx_compound *compound,
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
SX_API sx_status sx_body_add_outline(sx_world *world, sx_body_id body, const sx_vec2 *points,
                                     int count, const sx_collider_def *def, sx_collider_id *out);

/** Number of parts of a collider: a compound's part count, 1 for a plain
 *  collider, 0 for a stale handle or NULL world. */
SX_API int sx_collider_get_part_count(const sx_world *world, sx_collider_id collider);

/** Copies part `index` of a collider (a plain collider has one part: its
 *  shape with the identity offset) into *out. SX_ERR_INVALID_ARG (NULL,
 *  index out of range), SX_ERR_STALE_HANDLE. */
SX_API sx_status sx_collider_get_part(const sx_world *world, sx_collider_id collider, int index,
                                      sx_compound_part *out);

/** Removes a collider (and its contacts) and updates its body's mass.
 *  SX_ERR_INVALID_ARG (NULL), SX_ERR_LOCKED (from a callback),
 *  SX_ERR_STALE_HANDLE. */
SX_API sx_status sx_destroy_collider(sx_world *world, sx_collider_id collider);

/** True if the handle names a live collider of this world. */
SX_API bool sx_collider_is_valid(const sx_world *world, sx_collider_id collider);

/** The body a collider is attached to (null handle if stale). */
SX_API sx_body_id sx_collider_get_body(const sx_world *world, sx_collider_id collider);

/* ---- queries ------------------------------------------------------------ */

/* Queries see the colliders of enabled bodies, sensors included, at their
 * current transforms, visited in collider-slot order (deterministic). They
 * test every collider (cost linear in the collider count: there is no
 * bounding-volume tree yet). */

/** Called for each collider a query finds; return false to stop the query.
 *  The world is locked meanwhile (see "Callbacks" at the top): fn may push,
 *  move, wake or inspect what it finds, while creating or destroying bodies
 *  and colliders answers SX_ERR_LOCKED, so a query never reports a collider
 *  made during it. */
typedef bool sx_query_fn(sx_collider_id collider, sx_body_id body, void *context);

/** Reports every collider whose tight bounds overlap `box` (for a compound:
 *  the bounds of one of its parts). fn may be NULL
 *  (just count). Returns the number of colliders reported (0 for a NULL
 *  world or an invalid or non-finite box). */
SX_API int sx_world_query_aabb(const sx_world *world, sx_aabb box, sx_query_fn *fn, void *context);

/** Reports every collider whose shape contains `point` (boundary included,
 *  as sx_contains_point). Returns the count (0 for bad input). */
SX_API int sx_world_query_point(const sx_world *world, sx_vec2 point, sx_query_fn *fn,
                                void *context);

/** Reports every collider that overlaps `shape` placed by `xf` (as
 *  sx_overlap: touching counts). Returns the count (0 for bad input, an
 *  invalid shape included). */
SX_API int sx_world_query_shape(const sx_world *world, const sx_shape *shape, sx_xform xf,
                                sx_query_fn *fn, void *context);

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
SX_API bool sx_world_cast_ray(const sx_world *world, const sx_ray_input *ray,
                              sx_world_ray_hit *out);

/** A hit of a world shape cast. */
typedef struct sx_world_shape_hit {
    sx_collider_id collider;
    sx_body_id body;
    sx_vec2 point;    /**< world point of the collider's surface where the shape touches it */
    sx_vec2 normal;   /**< unit surface normal there, facing the cast shape */
    sx_real fraction; /**< the shape touches after moving fraction x translation */
    int part;         /**< the compound part hit first (0 for a plain collider) */
} sx_world_shape_hit;

/** Called for each collider sx_world_cast_shape_all hits; return false to
 *  stop. The world is locked meanwhile, as during a query callback. */
typedef bool sx_shape_cast_fn(const sx_world_shape_hit *hit, void *context);

/** Sweeps `shape` placed by xf along `translation` (world, metres; the shape
 *  does not turn) against every collider whose filter collides with
 *  `filter` (the rule of sx_filter; NULL: every collider) and returns true
 *  with the first hit in *out (on equal fractions, the lower collider
 *  slot). Each collider is cast as sx_shape_cast casts (the fraction is
 *  where the surfaces meet, never past it; a collider the shape already
 *  touches or overlaps is hit at fraction 0, with the normal of sx_mtv).
 *  Sensors are not hit, nor are the colliders of disabled bodies. false,
 *  with *out zeroed, for no hit or bad input (NULL pointers, an invalid
 *  shape, a non-finite transform or translation). */
SX_API bool sx_world_cast_shape(const sx_world *world, const sx_shape *shape, sx_xform xf,
                                sx_vec2 translation, const sx_filter *filter,
                                sx_world_shape_hit *out);

/** As sx_world_cast_shape, but reports every collider the sweep hits (each
 *  once, with its first hit) in collider-slot order, not sorted by
 *  fraction. fn may be NULL (just count). Returns the number reported (0 for
 *  bad input). */
SX_API int sx_world_cast_shape_all(const sx_world *world, const sx_shape *shape, sx_xform xf,
                                   sx_vec2 translation, const sx_filter *filter,
                                   sx_shape_cast_fn *fn, void *context);

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
 *  in slot order then contacts in contact order. The world is locked while
 *  they run, as during a query callback (see "Callbacks" at the top); the
 *  shape pointer passed to draw_shape is valid during that call only.
 *  SX_ERR_INVALID_ARG for NULL world or draw. */
SX_API sx_status sx_world_draw(const sx_world *world, const sx_debug_draw *draw);

/* ---- run-time properties, iteration and naming ----------------------------- */

/* Naming: every object is made by sx_<object>_create and freed by
 * sx_<object>_destroy (sx_world_create, sx_body_create, sx_collider_create).
 * sx_create_body, sx_destroy_body, sx_body_add_collider and
 * sx_destroy_collider are the same functions under their first names; both
 * stay. */

/** Checks a world def without creating anything: SX_OK when sx_world_create
 *  would accept it. SX_ERR_INVALID_ARG for a NULL def or a field below its
 *  documented range (or outside it for a bounded real such as
 *  correction_factor), SX_ERR_NONFINITE for a NaN or infinite field,
 *  SX_ERR_CAPACITY for sub_steps above SX_MAX_SUB_STEPS, an iteration count
 *  above SX_MAX_ITERATIONS or body_capacity above SX_WORLD_MAX_ITEMS. When
 *  `field` is not NULL it receives the name of the first refused field
 *  ("gravity", "sub_steps", ...; "def" for a NULL def), or NULL for SX_OK. */
SX_API sx_status sx_world_def_validate(const sx_world_def *def, const char **field);

/** Copies the world's current settings (sx_world_create's def with the
 *  changes of the setters below and sx_world_set_gravity) into *out.
 *  SX_ERR_INVALID_ARG for NULL. */
SX_API sx_status sx_world_get_def(const sx_world *world, sx_world_def *out);

/** Sets the sub-steps of sx_world_step (>= 1; see sx_world_def). Errors,
 *  with the world untouched: SX_ERR_INVALID_ARG (NULL, sub_steps < 1). */
SX_API sx_status sx_world_set_sub_steps(sx_world *world, int sub_steps);

/** Turns continuous collision on or off (sx_world_def.enable_continuous),
 *  from the next sx_world_collide on. SX_ERR_INVALID_ARG for NULL. */
SX_API sx_status sx_world_enable_continuous(sx_world *world, bool enable);

/** Sets the solver's iterations per sub-step: velocity (>= 1) and position
 *  (>= 0; 0 turns sx_world_separate off), as in sx_world_def. Errors, with
 *  the world untouched: SX_ERR_INVALID_ARG (NULL, a count out of range). */
SX_API sx_status sx_world_set_iterations(sx_world *world, int velocity_iterations,
                                         int position_iterations);

/** Copies the handles of the world's live bodies, in slot order
 *  (deterministic), into out[0 .. capacity-1] and returns how many live
 *  bodies there are: call with capacity 0 (out may then be NULL) to learn
 *  the count, then with an array that large. 0 for a NULL world; a negative
 *  capacity counts as 0. */
SX_API int sx_world_get_bodies(const sx_world *world, sx_body_id *out, int capacity);

/** Copies the handles of a body's colliders, in the order they were added,
 *  as sx_world_get_bodies, and returns how many it has (0 for a stale
 *  handle or NULL world). */
SX_API int sx_body_get_colliders(const sx_world *world, sx_body_id body, sx_collider_id *out,
                                 int capacity);

/** Tight world bounds of the body's colliders at its current transform (the
 *  union over its colliders; for a compound, over its parts). A body without
 *  colliders gives the empty box at its origin (lower == upper); a stale
 *  handle or NULL world the zero box. */
SX_API sx_aabb sx_body_get_aabb(const sx_world *world, sx_body_id body);

/** Tight world bounds of one collider at its body's current transform (the
 *  zero box for a stale handle or NULL world). */
SX_API sx_aabb sx_collider_get_aabb(const sx_world *world, sx_collider_id collider);

/** Creates a body: sx_create_body under the sx_<object>_create name. */
SX_API sx_status sx_body_create(sx_world *world, const sx_body_def *def, sx_body_id *out);
/** Destroys a body: sx_destroy_body under the sx_<object>_destroy name. */
SX_API sx_status sx_body_destroy(sx_world *world, sx_body_id body);
/** Attaches a collider to a body: sx_body_add_collider under the
 *  sx_<object>_create name. */
SX_API sx_status sx_collider_create(sx_world *world, sx_body_id body, const sx_collider_def *def,
                                    sx_collider_id *out);
/** Removes a collider: sx_destroy_collider under the sx_<object>_destroy
 *  name. */
SX_API sx_status sx_collider_destroy(sx_world *world, sx_collider_id collider);

/* Body setters below answer SX_ERR_INVALID_ARG for a NULL world and
 * SX_ERR_STALE_HANDLE for a stale handle, and leave the body untouched on
 * every error. Getters answer a stale handle or NULL world with the zero
 * value (false, 0). */

/** Enables or disables a body (sx_body_def.enabled). A disabled body neither
 *  moves nor collides nor is seen by queries: its contacts and sensor
 *  overlaps end without end events (as when it is destroyed), the bodies
 *  they touched wake, and its velocities are zeroed. Enabling it puts it
 *  back where it was (or where sx_body_set_transform moved it), awake. */
SX_API sx_status sx_body_set_enabled(sx_world *world, sx_body_id body, bool enabled);
/** The body's enabled flag. */
SX_API bool sx_body_is_enabled(const sx_world *world, sx_body_id body);

/** Sets the gravity scale (any finite value: 0 floats, negative rises);
 *  wakes the body. SX_ERR_NONFINITE for NaN/Inf. */
SX_API sx_status sx_body_set_gravity_scale(sx_world *world, sx_body_id body, sx_real scale);
/** The gravity scale. */
SX_API sx_real sx_body_get_gravity_scale(const sx_world *world, sx_body_id body);

/** Sets the linear damping (1/s, >= 0; see sx_body_def). SX_ERR_NONFINITE
 *  for NaN/Inf, SX_ERR_INVALID_ARG for a negative value. */
SX_API sx_status sx_body_set_linear_damping(sx_world *world, sx_body_id body, sx_real damping);
/** The linear damping (1/s). */
SX_API sx_real sx_body_get_linear_damping(const sx_world *world, sx_body_id body);
/** Sets the angular damping (1/s, >= 0). Errors as
 *  sx_body_set_linear_damping. */
SX_API sx_status sx_body_set_angular_damping(sx_world *world, sx_body_id body, sx_real damping);
/** The angular damping (1/s). */
SX_API sx_real sx_body_get_angular_damping(const sx_world *world, sx_body_id body);

/** Locks (true) or frees the body's rotation; the inertia is recomputed
 *  (sx_body_get_inertia is 0 while locked) and locking stops its spin. Wakes
 *  the body. */
SX_API sx_status sx_body_set_fixed_rotation(sx_world *world, sx_body_id body, bool fixed);
/** The body's fixed_rotation flag. */
SX_API bool sx_body_is_fixed_rotation(const sx_world *world, sx_body_id body);

/** Replaces the body's user data (sx_body_get_user_data). */
SX_API sx_status sx_body_set_user_data(sx_world *world, sx_body_id body, void *user_data);

/* Collider setters answer SX_ERR_INVALID_ARG for a NULL world and
 * SX_ERR_STALE_HANDLE for a stale handle, leave the collider untouched on
 * every error, and wake its body (contacts pick the new value up at the next
 * collide). Getters answer a stale handle or NULL world with 0. */

/** Sets the friction (>= 0; mixed as sx_collider_def). SX_ERR_NONFINITE for
 *  NaN/Inf, SX_ERR_INVALID_ARG for a negative value. */
SX_API sx_status sx_collider_set_friction(sx_world *world, sx_collider_id collider,
                                          sx_real friction);
/** The friction coefficient. */
SX_API sx_real sx_collider_get_friction(const sx_world *world, sx_collider_id collider);
/** Sets the restitution (>= 0). Errors as sx_collider_set_friction. */
SX_API sx_status sx_collider_set_restitution(sx_world *world, sx_collider_id collider,
                                             sx_real restitution);
/** The restitution. */
SX_API sx_real sx_collider_get_restitution(const sx_world *world, sx_collider_id collider);
/** Sets the density (kg/m^2, >= 0) and recomputes the body's mass, centre of
 *  mass and inertia as sx_body_add_collider does (the body origin stays
 *  put). Errors as sx_collider_set_friction. */
SX_API sx_status sx_collider_set_density(sx_world *world, sx_collider_id collider, sx_real density);
/** The density (kg/m^2). */
SX_API sx_real sx_collider_get_density(const sx_world *world, sx_collider_id collider);
/** Sets the collision filter; pairs it now excludes lose their contact (with
 *  an end event) at the next collide. */
SX_API sx_status sx_collider_set_filter(sx_world *world, sx_collider_id collider, sx_filter filter);
/** The collision filter (all zero for a stale handle). */
SX_API sx_filter sx_collider_get_filter(const sx_world *world, sx_collider_id collider);
/** True for a sensor collider. */
SX_API bool sx_collider_is_sensor(const sx_world *world, sx_collider_id collider);
/** Replaces the collider's user data. */
SX_API sx_status sx_collider_set_user_data(sx_world *world, sx_collider_id collider,
                                           void *user_data);
/** The collider's user data (sx_collider_def.user_data; NULL if stale). */
SX_API void *sx_collider_get_user_data(const sx_world *world, sx_collider_id collider);

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_WORLD_H */
