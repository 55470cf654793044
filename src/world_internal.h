/* sepax — private layout of the world, shared by the .c files of the world
 * layer (world*.c, body*.c, broadphase.c, contact_solver.c, island.c,
 * sensor.c). Nothing here is public.
 *
 * Bodies live in two dense arrays indexed by slot: sx_body_sim holds the
 * small state every stage of the step reads and writes (transform, centre of
 * mass, velocities, inverse mass, accumulators), sx_body_info the cold data
 * (generation, mass, user data, collider list). Colliders and contacts are
 * dense arrays too. Arrays only grow (doubling), so a warmed-up world
 * allocates nothing per step. */
#ifndef SEPAX_WORLD_INTERNAL_H
#define SEPAX_WORLD_INTERNAL_H

#include <string.h>

#include "aabb_tree.h"
#include "core.h"
#include "sepax/collide.h"
#include "sepax/compound.h"
#include "sepax/world.h"

/* Hot per-body state. Static and disabled bodies keep inv_mass and
 * inv_inertia at zero and their velocities at zero, so the solver can treat
 * every body alike. */
typedef struct sx_body_sim {
    sx_xform xf;          /* body origin frame */
    sx_vec2 center;       /* world centre of mass */
    sx_vec2 local_center; /* centre of mass in the body frame */
    sx_vec2 v;
    sx_real w;
    sx_real inv_mass, inv_inertia;
    sx_vec2 force;
    sx_real torque;
    sx_vec2 impulse;
    sx_real angular_impulse;
    sx_real linear_damping, angular_damping, gravity_scale;
    /* true for enabled dynamic bodies: the ones forces and contacts move */
    bool dynamic;
    /* true for enabled dynamic and kinematic bodies: the ones that integrate */
    bool moving;
    /* false while the body sleeps: forces, integration and pairs with other
     * sleeping or static bodies skip it */
    bool awake;
} sx_body_sim;

typedef struct sx_body_info {
    uint32_t generation; /* bumped on destroy; never 0; retired at UINT32_MAX */
    bool alive;
    bool enabled;
    bool fixed_rotation;
    bool enable_sleep;
    bool bullet; /* swept against dynamic bodies too (world_ccd.c) */
    sx_body_type type;
    sx_real mass, inertia;
    void *user_data;
    int first_collider; /* -1 when none */
    int next_free;      /* free-list link while dead */
    sx_real sleep_time; /* seconds spent below the sleep speeds */
    int island;         /* while asleep: the island it fell asleep with */
    /* while asleep in an island: its next member (-1 at the end); the chain
     * starts at the island's root, so a wake touches the island only */
    int island_next;
} sx_body_info;

typedef struct sx_collider {
    sx_shape shape; /* unused by a compound */
    /* a compound collider: the world's own copy of its parts (NULL and 0
     * for a plain collider, which then has exactly one implicit part) */
    sx_compound_part *parts;
    int part_count;
    /* a compound's parts' fattened bounds, part_count of them, found with
     * the collider's bounds (NULL for a plain collider) */
    sx_aabb *part_boxes;
    sx_real density, friction, restitution;
    sx_filter filter;
    bool sensor;
    bool alive;
    uint32_t generation;
    int body; /* slot of the owning body */
    /* the cached bounds in world->aabbs no longer fit (teleport of a body
     * the step does not move) */
    bool aabb_stale;
    /* how far any point of the collider can move in the step its bounds
     * were found for (|v| + |w| x its farthest point from the centre of
     * mass, times the step): its bounds and its contacts' speculative
     * margin grow by this, so a fast body meets in the step's collide what
     * it will reach before the next one */
    sx_real reach;
    /* a radius about its body's centre of mass that holds it at any angle
     * (set with reach, for the colliders the step moves) */
    sx_real bound_radius;
    int next;      /* next collider of the same body, -1 at the end */
    int next_free; /* free-list link while dead */
    void *user_data;
} sx_collider;

/* A two-point manifold's 2x2 normal effective-mass matrix K (symmetric)
 * and its inverse. */
typedef struct sx_block2 {
    sx_real k11, k12, k22, inv11, inv12, inv22;
} sx_block2;

typedef struct sx_contact_point {
    /* from each centre of mass to the point, world: the levers the solver
     * applies impulses at (of collide time, then moved through the
     * sub-steps: sx_slide_levers in contact_solver.c) */
    sx_vec2 anchor_a, anchor_b;
    /* the same two anchors in their body frames: turned with the bodies,
     * they give the point's separation as the bodies move through the
     * sub-steps (sx_current_gap in contact_solver.c) */
    sx_vec2 rel_a, rel_b;
    sx_vec2 point;      /* midway point at collide time, world */
    sx_real separation; /* at collide time: < 0 overlap, > 0 gap */
    /* separation - (normal . (centre_b + anchor_b - centre_a - anchor_a)) at
     * collide time: the current separation is this plus the normal
     * component of the anchors' current offset */
    sx_real base;
    /* the separation at the start of this sub-step, shifted by the impacts
     * of this sub-step (see sx_contacts_impacts): what the solve aims at */
    sx_real gap;
    /* accumulated impulses of the velocity iterations (warm started) */
    sx_real normal_impulse, tangent_impulse;
    /* normal impulse of this sub-step's impact pass: kept apart, so the
     * clamping of the iterations cannot take the rebound back */
    sx_real impact_impulse;
    sx_real normal_mass, tangent_mass;
    uint32_t id;
} sx_contact_point;

typedef struct sx_contact {
    uint64_t key; /* collider_a << 32 | collider_b, collider_a < collider_b */
    int collider_a, collider_b;
    /* the part of each collider (0 for a plain one): a compound has one
     * contact per touching part pair; the list is sorted by (key, part_a,
     * part_b) */
    int part_a, part_b;
    int body_a, body_b;
    sx_vec2 normal; /* world, from A to B, at collide time (kept for the step) */
    sx_real friction, restitution;
    int count;
    sx_contact_point points[2];
    /* two-point manifolds: the 2x2 normal effective-mass matrix K and its
     * inverse, when K is well conditioned (block_solve) */
    sx_block2 block;
    bool block_solve;
    /* just moved back from the frozen store by a wake during collide: it
     * existed before, so it reports no begin event */
    bool thawed;
} sx_contact;

/* The solver's compact view of the step (contact_solver.c), rebuilt by each
 * solve from the contacts and bodies: the velocity passes stream through
 * these arrays and touch nothing else.
 *
 * A solver body is the velocity of one body that takes part in an active
 * contact and moves (dynamic or kinematic); entry 0 is every body that does
 * not move, with zero velocity, which the passes read and write like any
 * other (zero inverse mass keeps it at exactly zero) so no pass branches on
 * the body type. */
typedef struct sx_solver_body {
    sx_vec2 v;
    sx_real w;
} sx_solver_body;

/* A contact point as the velocity passes see it: the anchors enter only as
 * their moments about the normal and the tangent (anchor x normal, anchor x
 * tangent), which is all a pass needs of them. */
typedef struct sx_constraint_point {
    sx_real rn_a, rn_b, rt_a, rt_b;
    sx_real gap;
    sx_real normal_impulse, tangent_impulse;
    sx_real normal_mass, tangent_mass;
} sx_constraint_point;

/* An active contact as the velocity passes see it: solver body indices, the
 * bodies' inverse masses copied in (no body record is read), and the points. */
typedef struct sx_constraint {
    int body_a, body_b; /* solver body indices (0: the body that does not move) */
    int contact;        /* index in world->contacts, for the impulses' way back */
    int count;
    sx_vec2 normal;
    sx_real friction;
    sx_real inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
    sx_constraint_point points[2];
    sx_block2 block;
    bool block_solve;
    /* both bodies dynamic: soft contacts take the softer stiffness */
    bool both_dynamic;
} sx_constraint;

/* What the broadphase needs to know of a collider. Pairs are reported when
 * one side is AWAKE, or a MOVING_KINEMATIC body meets an ASLEEP one (so it
 * can wake it); FIXED and ASLEEP never pair among themselves. */
enum {
    SX_BP_OUT = 0,          /* not colliding: dead, disabled or a sensor */
    SX_BP_FIXED,            /* static, or kinematic at rest */
    SX_BP_AWAKE,            /* dynamic and awake */
    SX_BP_MOVING_KINEMATIC, /* kinematic with a non-zero velocity */
    SX_BP_ASLEEP            /* dynamic and asleep */
};

/* The broadphase (broadphase.c) keeps two sets. The others (FIXED, ASLEEP)
 * sit in an array sorted by lower x that changes only when a collider joins
 * or leaves that set or moves while in it (the few boxes much wider than
 * the rest on a short list of their own). The colliders the step moves
 * (AWAKE, MOVING_KINEMATIC) have fat boxes (bounds grown by a margin) and
 * sit in a dynamic AABB tree with their candidate pairs kept from call to
 * call while few leave their fat box, or are swept on x when many do. */
typedef struct sx_sorted_box {
    sx_aabb box;
    int slot;
    unsigned char kind;
} sx_sorted_box;

typedef struct sx_broadphase {
    /* the moving colliders' fat boxes: in the tree while few of them move
     * out of their fat box per call (tree_valid), otherwise swept on x in
     * an order kept from call to call (order, sorted; mark: scratch per
     * slot) */
    sx_aabb_tree tree;
    bool tree_valid;
    int calm_calls; /* sweeping calls in a row with few colliders out of their fat box */
    int *order;
    int order_count, order_capacity;
    sx_sorted_box *sorted;
    int sorted_capacity;
    sx_real sorted_width; /* the widest box in sorted */
    unsigned char *mark;
    int mark_capacity;
    int *proxy;         /* per collider slot: its tree leaf, -1 when none */
    sx_aabb *fat;       /* per collider slot: the box its candidates were found for */
    unsigned char *qmark; /* per collider slot: 1 while in requery */
    int proxy_capacity, fat_capacity, qmark_capacity;
    int *requery; /* slots that look for new candidates in this call */
    int requery_count, requery_capacity;
    int *hits; /* query scratch */
    int hit_count, hit_capacity;
    /* the candidate pairs, sorted by key, and the scratch of their merge */
    uint64_t *cand, *cand_next;
    int cand_count, cand_capacity, cand_next_capacity;
    uint64_t *fresh; /* new candidates of this call */
    int fresh_count, fresh_capacity;
    uint64_t *pairs; /* the call's answer: candidates whose bounds overlap */
    int pair_count, pair_capacity;
    uint64_t *scratch; /* radix-sort buffer, as large as fresh */
    int scratch_capacity;
    sx_sorted_box *fixed, *fixed_next; /* the other set, sorted by lower x */
    int fixed_count, fixed_capacity, fixed_next_capacity;
    sx_sorted_box *added; /* scratch: boxes joining the fixed set */
    int added_count, added_capacity;
    int *wide; /* indices into fixed of the boxes wider than wide_limit */
    int wide_count, wide_capacity;
    sx_real wide_limit;
    /* collider slots whose fixed-set entry may be out of date: they changed
     * kind or bounds since the last call (mark[] keeps them unique) */
    int *touched;
    int touched_count, touched_capacity;
    unsigned char *tmark; /* one per collider slot: 1 while in touched */
    int tmark_capacity;
} sx_broadphase;

/* Per body, for the impact pass: the position and angle correction that
 * puts the body where its piecewise-linear motion through this sub-step's
 * impacts ends (applied by sx_world_integrate), and its slice of the
 * contact adjacency. */
typedef struct sx_impact_body {
    sx_vec2 shift;
    sx_real turn;
    int start, count;
} sx_impact_body;

/* Per body, for the solver's energy guard (contact_solver.c): the velocities
 * before the warm start; the group of bodies the contacts join (union-find
 * link, the root itself once built; epoch: the build that last made the body
 * a member); credit: the kinetic energy the solver took from the body that
 * it may give back (kept from sub-step to sub-step); at a group's root the
 * group's sums: f (energy the solve gave), a (energy of the velocity changes
 * alone), credit_sum and mass_sum. */
typedef struct sx_group_body {
    sx_vec2 v;
    sx_real w;
    sx_real credit;
    sx_real f, a, credit_sum, mass_sum;
    int parent;
    unsigned epoch;
} sx_group_body;

/* Per contact, for the impact pass: the time of impact within the sub-step,
 * the position in the heap (-1: not queued) and how many times the pass
 * resolved it in this sub-step. */
typedef struct sx_impact_contact {
    sx_real time;
    int where;
    int count;
} sx_impact_contact;

/* Where a body was when the step's collide ran (world_ccd.c): the
 * continuous pass sweeps it from there; stamp tells which collide. */
typedef struct sx_ccd_pose {
    sx_vec2 center;
    sx_rot q;
    /* where its collide-time velocity takes it by the step's end: the
     * look-ahead its bounds and margins were grown by */
    sx_vec2 end;
    uint32_t stamp;
    /* the body's reach from its centre of mass and thinnest half extent,
     * kept until its colliders or mass change (ext_valid) */
    sx_real max_ext, min_ext;
    bool ext_valid;
    bool swept; /* while the continuous stage runs: it is to be swept */
} sx_ccd_pose;

struct sx_world {
    sx_world_def def;
    sx_real linear_slop;
    sx_real margin; /* speculative distance */
    /* the step the next collide looks ahead over (sx_world_begin_step; 0:
     * none, the margin alone) */
    sx_real step_dt;

    sx_body_sim *sims;
    sx_body_info *infos;
    int body_slots, body_free, body_count;
    int sim_capacity, info_capacity;

    sx_collider *colliders;
    sx_aabb *aabbs;         /* fattened bounds, per collider slot */
    unsigned char *bp_kind; /* per collider slot: 0 out, 1 fixed, 2 dynamic */
    int collider_slots, collider_free;
    int collider_capacity, aabb_capacity, kind_capacity;

    sx_contact *contacts, *old_contacts;
    int contact_count, old_contact_count, contact_capacity, old_contact_capacity;
    /* Contacts of sleeping bodies, out of the step's list so a sleeping
     * island costs nothing per step; unordered. A wake sets thaw_pending and
     * the next collide moves the contacts that have an awake body back. */
    sx_contact *frozen, *thaw;
    int frozen_count, frozen_capacity, thaw_count, thaw_capacity;
    bool thaw_pending;
    /* the bodies woken since the last thaw (thaw_mark: 1 per listed body
     * slot, room for every slot); thaw_all: a wake could not be listed, the
     * thaw tests every frozen contact */
    int *thaw_bodies;
    int thaw_body_count, thaw_body_capacity;
    unsigned char *thaw_mark;
    int thaw_mark_capacity;
    bool thaw_all;
    /* Contacts removed since the last collide (a body or collider
     * destroyed): they stay in place with count 0 (body_contacts.c) */
    int contact_dead, frozen_dead;
    /* Which contacts each body has (body_contacts.c): per body slot the
     * first entry of its chain, valid while its stamp equals the epoch; per
     * entry 2 p + side (p: position in contacts, then in frozen) the next
     * entry of the same body. Built on demand; by_body_valid goes false
     * when a list moves. */
    int *by_body_head, *by_body_next;
    uint32_t *by_body_stamp;
    int by_body_head_capacity, by_body_next_capacity, by_body_stamp_capacity;
    uint32_t by_body_epoch;
    bool by_body_valid;

    /* The bodies the step moves (alive, enabled, and dynamic and awake, or
     * kinematic) and the colliding colliders of the bodies that are not
     * fixed (awake dynamic or moving kinematic), both in slot order, so a
     * sleeping or static body costs nothing per step. Rebuilt by
     * sx_world_refresh_sets after anything sets sets_dirty: a body woke,
     * slept, appeared, left, changed type or velocity, or a collider came or
     * went. */
    int *active_bodies, *active_colliders;
    int active_body_count, active_collider_count, active_body_capacity, active_collider_capacity;
    /* the sensors of enabled bodies, in slot order (same refresh) */
    int *sensor_colliders;
    int sensor_collider_count, sensor_collider_capacity;
    int *visitors; /* sensor scratch */
    int visitor_count, visitor_capacity;
    bool sets_dirty;
    /* Bodies that only woke or fell asleep since the last refresh, while
     * sets_dirty is false (sx_world_note_awake): the refresh redoes them
     * and their colliders alone (woken_mark: 1 per listed body slot;
     * changed, collider_mark, set_scratch, set_keep: its scratch). */
    int *woken, *changed, *set_scratch;
    int woken_count, woken_capacity, changed_count, changed_capacity, set_scratch_capacity;
    unsigned char *woken_mark, *collider_mark;
    int woken_mark_capacity, collider_mark_capacity;
    bool *set_keep;
    int set_keep_capacity;

    sx_broadphase bp;

    /* continuous collision (world_ccd.c): per body slot its pose at the last
     * collide, the stamp of that collide, and the query scratch */
    sx_ccd_pose *ccd_poses;
    int ccd_pose_capacity;
    uint32_t ccd_stamp;
    sx_real ccd_dt; /* the step the recorded poses start (0: none) */
    int ccd_kinematic_moving; /* a kinematic body moves this step (sx_ccd_record) */
    int *ccd_sweep;           /* the bodies that may need the sweep this step */
    int ccd_sweep_count, ccd_sweep_capacity;
    sx_real ccd_elapsed; /* sub-step time separated since the record */
    bool ccd_marked;     /* ccd_sweep holds the bodies as they end the step */
    bool ccd_recording;  /* collide's bounds pass records the poses */
    int bullet_count; /* live bodies with the bullet flag (body.c, world_ccd.c) */
    int *ccd_found;
    int ccd_found_count, ccd_found_capacity;
    struct sx_ccd_bullet *ccd_bullets; /* the moving bullets (world_ccd.c) */
    int ccd_bullet_capacity;

    sx_contact_event *begin_events, *end_events;
    int begin_count, begin_capacity, end_count, end_capacity;

    /* sensor overlaps of the last and the current collide, sorted keys
     * sensor << 32 | visitor */
    uint64_t *sensor_pairs, *old_sensor_pairs;
    int sensor_count, old_sensor_count, sensor_capacity, old_sensor_capacity;
    sx_sensor_event *sensor_begin, *sensor_end;
    int sensor_begin_count, sensor_begin_capacity, sensor_end_count, sensor_end_capacity;

    /* scratch of the impact pass (contact_solver.c), grown on demand */
    /* scratch of the solver's energy guard (contact_solver.c): per body
     * slot, and the slots of the bodies in a group (members); groups_ready:
     * the last gather built the groups */
    sx_group_body *group_bodies;
    int *group_members;
    int group_body_capacity, group_member_capacity, group_member_count;
    unsigned group_epoch;
    bool groups_ready;
    bool groups_driven; /* some active contact has a kinematic body */
    sx_impact_body *impact_bodies;      /* per body slot */
    int *impact_adjacency;              /* contact indices grouped by body */
    int *impact_heap;                   /* contact indices ordered by (time, index) */
    sx_impact_contact *impact_contacts; /* per contact */
    int impact_body_capacity, impact_adjacency_capacity, impact_heap_capacity;
    int impact_contact_capacity;
    /* true between an impact pass that moved bodies and the integrate that
     * applies the moves */
    bool impact_shifts_pending;

    /* the solver's compact arrays (sx_constraint above); solver_index maps
     * a body slot to its solver body while a solve runs, 0 otherwise */
    sx_solver_body *solver_bodies;
    int *solver_slots; /* per solver body: its body slot */
    int *solver_index; /* per body slot */
    sx_constraint *constraints;
    int solver_body_count, constraint_count;
    int solver_body_capacity, solver_slot_capacity, solver_index_capacity;
    int constraint_capacity;
    /* the arrays hold the current solve's gather (from the warm start to
     * the scatter after the passes) */
    bool solver_gathered;

    int *island_parent; /* union-find scratch, per body slot */
    sx_real *island_time;
    int parent_capacity, time_capacity;

    /* Walks that call user callbacks (queries with a callback, debug draw)
     * under way, nested ones included: while non-zero, the calls that would
     * change what a walk visits answer SX_ERR_LOCKED. */
    int lock_depth;
    /* sx_world_destroy was called from a callback: the outermost walk
     * destroys the world when it returns */
    bool destroy_pending;
};

/* True while a callback of the world runs (see lock_depth). */
static inline bool sx_world_locked(const sx_world *world) { return world->lock_depth > 0; }

/* True when the solver must work on a contact: at least one of its bodies
 * is dynamic and awake. */
static inline bool sx_contact_is_active(const sx_world *world, const sx_contact *c) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    return (a->dynamic && a->awake) || (b->dynamic && b->awake);
}

/* The collider as a compound: its own parts, or for a plain collider a
 * one-part view of its shape built in *tmp. */
static inline sx_compound sx_collider_compound(const sx_collider *c, sx_compound_part *tmp) {
    sx_compound view;
    if (c->part_count > 0) {
        view.parts = c->parts;
        view.count = c->part_count;
    } else {
        tmp->shape = c->shape;
        tmp->offset = sx_xform_identity();
        view.parts = tmp;
        view.count = 1;
    }
    return view;
}

/* Tight world bounds of a collider on a body placed by xf. */
static inline sx_aabb sx_collider_aabb(const sx_collider *c, sx_xform xf) {
    if (c->part_count > 0) {
        sx_compound view;
        view.parts = c->parts;
        view.count = c->part_count;
        return sx_compound_aabb(&view, xf);
    }
    return sx_shape_aabb(&c->shape, xf);
}

/* True if two colliders placed by xa and xb overlap (touching counts). */
static inline bool sx_colliders_overlap(const sx_collider *a, sx_xform xa, const sx_collider *b,
                                        sx_xform xb) {
    sx_compound_part ta, tb;
    sx_compound va, vb;
    if (a->part_count == 0 && b->part_count == 0) return sx_overlap(&a->shape, xa, &b->shape, xb);
    va = sx_collider_compound(a, &ta);
    vb = sx_collider_compound(b, &tb);
    return sx_compound_overlap_compound(&va, xa, &vb, xb);
}

/* Every array of a world holds at most SX_WORLD_MAX_ITEMS (2^30 - 1)
 * elements, so a count plus one, twice a count, or the sum of two counts,
 * the needs the callers compute, never overflow an int. */

/* Grows *array (elements of `size` bytes, *capacity of them) to hold at least
 * `need`, doubling up to SX_WORLD_MAX_ITEMS; copies the old contents.
 * SX_ERR_CAPACITY when need > SX_WORLD_MAX_ITEMS, SX_ERR_NO_MEMORY when the
 * bytes do not fit a size_t or the allocator fails (the array is then
 * unchanged). */
sx_status sx_reserve_array(void **array, int *capacity, int need, size_t size);
/* sx_reserve_array == SX_OK, for callers that answer any failure alike. */
bool sx_grow_array(void **array, int *capacity, int need, size_t size);
/* sx_grow_array that zeroes the elements it adds. */
bool sx_grow_zeroed(void **array, int *capacity, int need, size_t size);
/* Appends value to a growing int array; false when out of memory. */
bool sx_push_int(int **array, int *count, int *capacity, int value);

/* world.c */
/* Rebuilds the active sets if sets_dirty, and every collider's broadphase
 * kind and stale bounds with them; otherwise redoes the bodies noted by
 * sx_world_note_awake. */
sx_status sx_world_refresh_sets(sx_world *world);
/* Notes that a body woke or fell asleep and nothing else changed: the next
 * refresh of the active sets redoes it alone (or everything, if memory for
 * the note runs out). */
void sx_world_note_awake(sx_world *world, int slot);

/* world_ccd.c */
/* Starts the record of where the moving bodies are, for the continuous
 * pass at the end of the step (sx_world_collide calls it, and its bounds
 * pass fills the poses in). */
sx_status sx_ccd_record(sx_world *world);
/* Frees its arrays (sx_world_destroy). */
void sx_ccd_free(sx_world *world);
/* Forgets body slot's cached extents and pose (its colliders or mass
 * changed, or it was just created). */
void sx_ccd_forget(sx_world *world, int slot);

/* Whether two points moving straight from a0 by da and from b0 by db over
 * a step come within r of each other (the closest approach; NaN: true). */
bool sx_paths_meet(sx_vec2 a0, sx_vec2 da, sx_vec2 b0, sx_vec2 db, sx_real r);

/* world.c: lists in ccd_sweep the bodies that may need the sweep (the
 * continuous pass's fallback when the step's last sx_world_separate did not
 * list them). */
sx_status sx_ccd_mark(sx_world *world);

/* True if two collision filters let their colliders collide (sx_filter). */
static inline bool sx_filters_collide(const sx_filter *a, const sx_filter *b) {
    if (a->group == b->group && a->group != 0) return a->group > 0;
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

/* broadphase.c */
void sx_broadphase_init(sx_broadphase *bp);
void sx_broadphase_free(sx_broadphase *bp);
/* Notes that a collider changed kind or bounds while not moving (its
 * fixed-set entry must be redone). */
sx_status sx_broadphase_touch(sx_broadphase *bp, int slot, int slot_count);
/* Finds the pairs of colliders whose bounds overlap and whose kinds (SX_BP_*)
 * call for a pair; `moving` lists the AWAKE and MOVING_KINEMATIC colliders
 * in slot order; `fat_margin` (>= 0) is how far a moving collider's tree box
 * reaches past its bounds. Fills bp->pairs sorted ascending by key (lower
 * slot in the high half). */
sx_status sx_broadphase_update(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                               int slot_count, const int *moving, int moving_count,
                               sx_real fat_margin);

/* Appends to *out the slots of the colliders in the broadphase (not OUT)
 * whose bounds (aabbs, as of the last update) overlap box, in no particular
 * order. */
sx_status sx_broadphase_query(sx_broadphase *bp, const sx_aabb *aabbs, sx_aabb box, int **out,
                              int *count, int *capacity);
/* The same for the fixed set only (static colliders, kinematic ones at rest
 * and sleeping ones): logarithmic, where the moving set is not. */
sx_status sx_broadphase_query_fixed(const sx_broadphase *bp, sx_aabb box, int **out, int *count,
                                    int *capacity);

/* contact_solver.c */
/* Once per collide: the effective masses and the block-solve matrices of
 * the new contacts, from their anchors (fixed for the step). */
void sx_contacts_prepare(sx_world *world);
/* Start of a sub-step's solve: gathers the solver's compact arrays, every
 * active point's gap from the current positions, and the warm start on the
 * solver's copies of the velocities only: the bodies keep their own for the
 * impact pass, and sx_contacts_solve redoes the warm start on what the
 * impacts left if there were any. false when the arrays could not grow
 * (nothing done; sx_contacts_solve then refuses). */
bool sx_contacts_gather(sx_world *world);
/* After the passes: scales down the impulses of each group of touching
 * bodies that got more energy from the warm start and the passes than the
 * solver took from it before (its credit), and keeps the credit left. */
void sx_contacts_energy_guard(sx_world *world, sx_real h);
/* The impact pass (restitution): false when its scratch could not grow (the
 * pass is then skipped). */
bool sx_contacts_impacts(sx_world *world, sx_real h);
/* `passes` velocity passes over the active contacts, on the arrays the warm
 * start gathered (velocities and gaps read again after an impact pass that
 * changed them; velocities and impulses handed back after): soft
 * (push-out of the overlap at the world's contact stiffness) when
 * contact_hertz > 0, otherwise rigid. false without a gather (no pass
 * made). */
bool sx_contacts_solve(sx_world *world, sx_real h, int passes);
/* Moves the bodies by the corrections of the last impact pass and clears
 * them (called by sx_world_integrate). */
void sx_contacts_apply_impact_shifts(sx_world *world);
void sx_contacts_free(sx_world *world);
/* The relax passes of sx_world_separate: the gaps from the positions after
 * integrate, then `passes` rigid passes. */
bool sx_contacts_relax(sx_world *world, sx_real h, int passes);

/* sensor.c */
/* Finds the sensor overlaps at the current positions and records the sensor
 * events against the last call's overlaps. */
sx_status sx_sensors_update(sx_world *world);
/* Frees the sensor arrays. */
void sx_sensors_free(sx_world *world);
/* Forgets the overlaps of a destroyed collider (no end event, as for
 * contacts). */
void sx_sensors_remove_collider(sx_world *world, int collider);

/* island.c */
/* Wakes a body and, if it sleeps, every body of the island it fell asleep
 * with. */
void sx_wake_body(sx_world *world, int slot);

/* body.c */
/* Recomputes the mass properties of a body from its colliders. */
void sx_body_update_mass(sx_world *world, int slot);
/* Recomputes xf.p from the centre of mass and rotation. */
void sx_body_sync_origin(sx_body_sim *sim);
/* The slot of a live body or collider, or -1 (NULL world, null or stale
 * handle). */
int sx_body_slot(const sx_world *world, sx_body_id id);
int sx_collider_slot(const sx_world *world, sx_collider_id id);

/* body_contacts.c */
/* Removes every contact involving the collider slot (tombstones until the
 * next collide) and wakes the bodies of those contacts. */
void sx_world_remove_contacts_of(sx_world *world, int collider);
/* Wakes a body and every body it has a contact with (a static body moved
 * from under a sleeping pile must not leave the pile floating). */
void sx_wake_touching(sx_world *world, int slot);
/* Drops the tombstones of the step's contact list (keeping its order). */
void sx_world_purge_contacts(sx_world *world);
/* Contact `index` of the live contacts (the step's, then the frozen ones),
 * tombstones skipped; index must be below their number. */
const sx_contact *sx_world_live_contact(const sx_world *world, int index);

#endif /* SEPAX_WORLD_INTERNAL_H */
