/* sepax — the world struct, which ties the world layer's parts together:
 * bodies and colliders (world_body.h), contacts and the solver's arrays
 * (world_contact.h), the broadphase (world_broadphase.h), continuous
 * collision (world_ccd.h), the events, the active sets and the scratch of
 * each stage. Nothing here is public. */
#ifndef SEPAX_WORLD_INTERNAL_H
#define SEPAX_WORLD_INTERNAL_H

#include "core.h"
#include "sepax/world.h"
#include "world_body.h"
#include "world_broadphase.h"
#include "world_ccd.h"
#include "world_contact.h"

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
    /* per collider slot: bumped on destroy; never 0; retired at UINT32_MAX.
     * Beside the colliders, not in them: a contact's handles are read for
     * every contact a step (the flecs module's publishing), and a 240-byte
     * collider a contact was a cache miss each. */
    uint32_t *collider_generations;
    int collider_slots, collider_free;
    int collider_capacity, aabb_capacity, kind_capacity, generation_capacity;

    sx_contact *contacts, *old_contacts;
    int contact_count, old_contact_count, contact_capacity, old_contact_capacity;
    /* With a job system (sx_world_def.enqueue_task): each broadphase pair's
     * manifold, found in parallel before the pair walk makes the contacts
     * in pair order. pair_counts[i]: its point count, -1 for a compound
     * pair (the walk collides it), -2 for a pair no task reached. */
    sx_manifold *pair_manifolds;
    int *pair_counts;
    int pair_manifold_capacity, pair_count_capacity;
    bool pairs_found; /* this collide's walk reads them */
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

    /* continuous collision (world_ccd.c): per body slot its record at the
     * last collide (stamped) and its extents, and the query scratch */
    sx_ccd_rec *ccd_recs;
    int ccd_rec_capacity;
    sx_ccd_pose *ccd_poses;
    int ccd_pose_capacity;
    uint32_t ccd_stamp;
    sx_real ccd_dt;           /* the step the records start (0: none) */
    sx_real ccd_h;            /* the sub-step of the last integrate since then (0: none) */
    int ccd_kinematic_moving; /* a kinematic body moves this step (sx_ccd_record) */
    int *ccd_sweep;           /* the bodies that may need the sweep this step */
    int ccd_sweep_count, ccd_sweep_capacity;
    bool ccd_recording; /* collide's bounds pass records the bodies */
    int bullet_count;   /* live bodies with the bullet flag (body.c, world_ccd.c) */
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
    /* the solver slots (solver_slots[1 ..]) the groups were last linked
     * from, and whether those groups still stand (nothing but a collide's
     * fill whose items name the same bodies, of the same kinds, in the same
     * order, keeps them) */
    int *group_slots;
    int group_slot_count, group_slot_capacity;
    bool groups_linked;
    sx_impact_body *impact_bodies;      /* per body slot */
    int *impact_adjacency;              /* contact indices grouped by body */
    int *impact_heap;                   /* contact indices ordered by (time, index) */
    sx_impact_contact *impact_contacts; /* per contact */
    int impact_body_capacity, impact_adjacency_capacity, impact_heap_capacity;
    int impact_contact_capacity;
    /* true between an impact pass that moved bodies and the integrate that
     * applies the moves */
    bool impact_shifts_pending;
    /* contacts with restitution, counted as the collide makes and thaws
     * them (where a contact's restitution is set): none, and the impact pass
     * skips its scan of every contact (removals since leave the count high,
     * which only costs the scan) */
    int bouncy_contacts;

    /* the solver's compact arrays (sx_constraint, world_contact.h); solver_index maps
     * a body slot to its solver body while a solve runs, 0 otherwise */
    sx_solver_body *solver_bodies;
    int *solver_slots; /* per solver body: its body slot */
    int *solver_index; /* per body slot */
    sx_constraint *constraints;
    int solver_body_count, constraint_count;
    int solver_body_capacity, solver_slot_capacity, solver_index_capacity;
    int constraint_capacity;
    /* the colours of the gather (contact_solver.c): spans in solve order,
     * the wide colours' bundles, and the colouring's scratch (per active
     * contact, per colour, per solver body) */
    sx_colour_span *spans;
    sx_bundle *bundles;
    sx_bundle_frame *bundle_frames; /* one per bundle */
    sx_colour_item *colour_items;
    int *colour_cursor;
    int *body_colour;
    int span_count, bundle_count, bundle_frame_capacity;
    int span_capacity, bundle_capacity, colour_item_capacity, colour_cursor_capacity;
    int body_colour_capacity;
    /* The colours and the wide passes' lanes are filled once per collide
     * and kept for the sub-steps after it (each then refreshes gaps and
     * impulses only), while every item is still what it was (the colours
     * and slots past the collide too, see fill_count below):
     * fill_serial is contact_serial at the fill (bumped by every collide),
     * fill_count the number of items, fill_valid false when another
     * gather wrote over the arrays; fill_fresh: its accumulated impulses
     * are the contacts' (the last pass handed them back, and the energy
     * guard scaled none since). */
    unsigned contact_serial, fill_serial;
    /* collides so far, and their count at the last fill: a lane filled at
     * the collide before this one may be held by this one (sx_gather_items) */
    unsigned collides, fill_collides;
    /* every awake moving body's velocity meets the speed limit of a sub-step
     * of limited_h (0: not known); the stages that set velocities keep it,
     * the caller's velocities and new bodies clear it (world.c,
     * sx_limit_speeds_unless_met) */
    sx_real limited_h;
    /* a body's inverse mass or inertia changed since the contacts' effective
     * masses were prepared (by the caller, between stages): solve and
     * separate prepare them again before using them */
    bool masses_changed;
    /* Bumped by whatever changes the solver's bodies or active contacts
     * between two collides (a body's mass, type, awake state; a contact
     * removed): while it and contact_serial are what the fill saw
     * (fill_epoch), a gather skips the walk that compares every item. */
    unsigned solver_epoch, fill_epoch;
    /* colours of fewer constraints than this are solved one at a time (0:
     * the solver's own threshold; tests set it to compare the paths) */
    int wide_min_colour;
    /* the fill's item count, solver body count and threshold: its colours
     * and lane slots are kept by a later collide whose items name the same
     * solver bodies in the same order (only their data is filled again) */
    int fill_count, fill_body_count, fill_min_colour;
    bool fill_valid, fill_fresh;
    /* hand_back_later: set by sx_world_solve for all but the last sub-step
     * of a step (step_solves of step_dt / h since sx_world_begin_step), whose
     * last pass leaves the wide lanes' impulses in the lanes
     * (impulses_in_lanes) until a reader needs them on the contacts
     * (sx_solver_hand_back); the next sub-step's kept fill starts from them */
    bool hand_back_later, impulses_in_lanes;
    int step_solves;
    /* the wide lanes' gaps are the bodies' current poses' (the position
     * pass found them and moved no body): the next kept gather takes them
     * as they are; whatever moves a body ends it (integrate, continuous,
     * sx_body_set_transform; a collide or a change of the solver's bodies
     * ends the kept fill itself) */
    bool lane_gaps_current;
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

/* Notes a change to the solver's bodies or active contacts (solver_epoch). */
static inline void sx_world_solver_changed(sx_world *world) { world->solver_epoch++; }

/* True when the solver must work on a contact: at least one of its bodies
 * is dynamic and awake. */
static inline bool sx_contact_is_active(const sx_world *world, const sx_contact *c) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    return (a->dynamic && a->awake) || (b->dynamic && b->awake);
}

/* world.c */
/* Rebuilds the active sets if sets_dirty, and every collider's broadphase
 * kind and stale bounds with them; otherwise redoes the bodies noted by
 * sx_world_note_awake. */
sx_status sx_world_refresh_sets(sx_world *world);
/* Notes that a body woke or fell asleep and nothing else changed: the next
 * refresh of the active sets redoes it alone (or everything, if memory for
 * the note runs out). */
void sx_world_note_awake(sx_world *world, int slot);

#endif /* SEPAX_WORLD_INTERNAL_H */
