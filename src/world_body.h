/* sepax — bodies and colliders as the world layer stores them.
 *
 * Bodies live in two dense arrays indexed by slot: sx_body_sim holds the
 * small state every stage of the step reads and writes (transform, centre of
 * mass, velocities, inverse mass, accumulators), sx_body_info the cold data
 * (generation, mass, user data, collider list). Colliders are a dense array
 * too, each on its body's list. */
#ifndef SEPAX_WORLD_BODY_H
#define SEPAX_WORLD_BODY_H

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
    bool alive; /* its generation: world->collider_generations */
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

/* True if two collision filters let their colliders collide (sx_filter). */
static inline bool sx_filters_collide(const sx_filter *a, const sx_filter *b) {
    if (a->group == b->group && a->group != 0) return a->group > 0;
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

/* body.c */
/* Recomputes the mass properties of a body from its colliders. */
void sx_body_update_mass(sx_world *world, int slot);
/* Recomputes xf.p from the centre of mass and rotation (inline: the
 * integrate stage calls it for every moving body every sub-step). */
static inline void sx_body_sync_origin(sx_body_sim *sim) {
    sim->xf.p = sx_sub(sim->center, sx_rotate(sim->xf.q, sim->local_center));
}
/* Keeps a body within the speed limit of a sub-step of length h (see
 * body.c). */
void sx_body_limit_speed(sx_body_sim *b, sx_real h);

/* Half the limit of a sub-step of length h: within it sx_body_limit_speed leaves
 * a body as it is (its two divisions paid once per stage, not per body). */
typedef struct sx_half_limit {
    sx_real h, wmax, vhalf;
} sx_half_limit;

static inline sx_half_limit sx_half_limit_of(sx_real h) {
    sx_half_limit l;
    l.h = h;
    l.wmax = sx_minr(SX_MAX_ROTATION / h, SX_REAL_MAX);
    l.vhalf = SX_R(0.5) * sx_minr(SX_HUGE / h, SX_REAL_MAX);
    return l;
}

/* sx_body_limit_speed, skipped for a body within half the limit. */
static SX_ALWAYS_INLINE void sx_limit_speed_past_half(sx_body_sim *b, const sx_half_limit *l) {
    if (!(sx_absr(b->w) <= l->wmax && sx_absr(b->v.x) <= l->vhalf && sx_absr(b->v.y) <= l->vhalf))
        sx_body_limit_speed(b, l->h);
}

/* The slot of a live body or collider, or -1 (NULL world, null or stale
 * handle). */
int sx_body_slot(const sx_world *world, sx_body_id id);
int sx_collider_slot(const sx_world *world, sx_collider_id id);
/* sx_body_slot for a call that answers a status: -1 with *status
 * SX_ERR_INVALID_ARG for a NULL world or SX_ERR_STALE_HANDLE for a null or
 * stale handle, otherwise the slot with *status SX_OK. */
int sx_body_slot_checked(const sx_world *world, sx_body_id id, sx_status *status);

#endif /* SEPAX_WORLD_BODY_H */
