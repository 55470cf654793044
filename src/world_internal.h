/* sepax — private layout of the world, shared by world.c, body.c,
 * broadphase.c and contact_solver.c. Nothing here is public.
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
    uint32_t generation; /* bumped on destroy; never 0 */
    bool alive;
    bool enabled;
    bool fixed_rotation;
    sx_body_type type;
    sx_real mass, inertia;
    void *user_data;
    int first_collider; /* -1 when none */
    int next_free;      /* free-list link while dead */
    sx_real sleep_time; /* seconds spent below the sleep speeds */
    int island;         /* while asleep: the island it fell asleep with */
} sx_body_info;

typedef struct sx_collider {
    sx_shape shape; /* unused by a compound */
    /* a compound collider: the world's own copy of its parts (NULL and 0
     * for a plain collider, which then has exactly one implicit part) */
    sx_compound_part *parts;
    int part_count;
    /* during collide: where its parts' fattened bounds start in
     * world->part_boxes (compounds only) */
    int part_box;
    sx_real density, friction, restitution;
    sx_filter filter;
    bool sensor;
    bool alive;
    uint32_t generation;
    int body;      /* slot of the owning body */
    int next;      /* next collider of the same body, -1 at the end */
    int next_free; /* free-list link while dead */
    void *user_data;
} sx_collider;

typedef struct sx_contact_point {
    sx_vec2 anchor_a, anchor_b; /* from each centre of mass to the point, world */
    sx_vec2 local_a, local_b;   /* each surface point in its body frame */
    sx_vec2 point;              /* midway point at collide time, world */
    sx_real separation;         /* at collide time: < 0 overlap, > 0 gap */
    sx_real normal_impulse, tangent_impulse, max_normal_impulse;
    sx_real normal_mass, tangent_mass;
    sx_real relative_velocity; /* normal velocity before the solve */
    /* approach velocity (< 0) of an impact deferred by a speculative point to
     * the sub-step in which it touches; 0 when none */
    sx_real pending_approach;
    /* the normal impulse that stopped that deferred impact */
    sx_real pending_impulse;
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
    sx_vec2 normal;       /* world, from A to B, at collide time */
    sx_vec2 local_normal; /* the normal in A's body frame */
    sx_real friction, restitution;
    int count;
    sx_contact_point points[2];
    /* two-point manifolds: the 2x2 normal effective-mass matrix K and its
     * inverse, when K is well conditioned (block_solve) */
    sx_real k11, k12, k22, inv11, inv12, inv22;
    bool block_solve;
    /* carried unchanged through collide while its bodies sleep */
    bool frozen;
} sx_contact;

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

/* Sort-and-sweep broadphase: keeps the colliders ordered by the lower x of
 * their bounds across calls, so the insertion sort is near linear when
 * bodies move a little per step. */
typedef struct sx_sorted_box {
    sx_aabb box;
    int slot;
    unsigned char kind;
} sx_sorted_box;

typedef struct sx_broadphase {
    int *order;
    int order_count, order_capacity;
    unsigned char *mark; /* scratch, one per collider slot */
    int mark_capacity;
    uint64_t *pairs;
    int pair_count, pair_capacity;
    uint64_t *scratch; /* radix-sort buffer, as large as pairs */
    int scratch_capacity;
    sx_sorted_box *sorted; /* bounds in sweep order */
    int sorted_capacity;
} sx_broadphase;

struct sx_world {
    sx_world_def def;
    sx_real linear_slop;
    sx_real margin; /* speculative distance */

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

    sx_broadphase bp;

    sx_contact_event *begin_events, *end_events;
    int begin_count, begin_capacity, end_count, end_capacity;

    /* sensor overlaps of the last and the current collide, sorted keys
     * sensor << 32 | visitor */
    uint64_t *sensor_pairs, *old_sensor_pairs;
    int sensor_count, old_sensor_count, sensor_capacity, old_sensor_capacity;
    sx_sensor_event *sensor_begin, *sensor_end;
    int sensor_begin_count, sensor_begin_capacity, sensor_end_count, sensor_end_capacity;

    /* per collide: the fattened bounds of every compound's parts, found
     * once per call (not once per pair) */
    sx_aabb *part_boxes;
    int part_box_capacity;

    int *island_parent; /* union-find scratch, per body slot */
    sx_real *island_time;
    int parent_capacity, time_capacity;
};

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

/* Grows *array (elements of `size` bytes, *capacity of them) to hold at least
 * `need`, doubling; copies the old contents. false when out of memory (the
 * array is then unchanged). */
bool sx_grow_array(void **array, int *capacity, int need, size_t size);

/* broadphase.c */
void sx_broadphase_init(sx_broadphase *bp);
void sx_broadphase_free(sx_broadphase *bp);
/* Finds the pairs of colliders whose bounds overlap and whose kinds (SX_BP_*)
 * call for a pair. Fills bp->pairs sorted ascending by key (lower slot in the
 * high half). */
sx_status sx_broadphase_update(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                               int slot_count);

/* contact_solver.c */
void sx_contacts_prepare(sx_world *world);
void sx_contacts_solve(sx_world *world, sx_real h);
void sx_contacts_restitution(sx_world *world);
void sx_contacts_separate(sx_world *world, sx_real h);

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
/* Removes every contact involving the collider slot and wakes the bodies
 * of those contacts. */
void sx_world_remove_contacts_of(sx_world *world, int collider);
/* Recomputes xf.p from the centre of mass and rotation. */
void sx_body_sync_origin(sx_body_sim *sim);

#endif /* SEPAX_WORLD_INTERNAL_H */
