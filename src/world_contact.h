/* sepax — contacts and the solver's constraints: the manifolds collide
 * keeps per touching collider (or part) pair, and the compact arrays the
 * velocity passes of contact_solver.c stream through. */
#ifndef SEPAX_WORLD_CONTACT_H
#define SEPAX_WORLD_CONTACT_H

#include "core.h"
#include "simd.h"
#include "sepax/world.h"

/* A two-point manifold's 2x2 normal effective-mass matrix K (symmetric)
 * and its inverse. */
typedef struct sx_block2 {
    sx_real k11, k12, k22, inv11, inv12, inv22;
} sx_block2;

typedef struct sx_contact_point {
    /* from each centre of mass to the point, world: the levers the solver
     * applies impulses at (of the collide that searched the manifold: a
     * kept manifold keeps them, see sx_contact.held) */
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

/* A plain pair's manifold as the narrowphase found it, in A's frame, with
 * B's pose relative to A then: while B moves less than the keep tolerance
 * relative to A, the next collides answer from it (sx_kept_manifold_now in
 * world.c) instead of the narrowphase. */
typedef struct sx_kept_manifold {
    sx_xform rel;       /* B's frame in A's frame */
    sx_vec2 normal;     /* A's frame */
    sx_vec2 point[2];   /* the midway points, A's frame */
    sx_vec2 on_b[2];    /* B's surface points, B's frame */
    sx_real depth[2];
    sx_real margin;     /* the speculative margin it was found with */
    bool valid;         /* false: a compound's part pair, never kept */
} sx_kept_manifold;

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
    sx_kept_manifold kept;
    /* this collide answered from the kept manifold: the levers, frames,
     * masses and normal are the old contact's (the reported points and
     * depths alone follow the kept manifold), and a solver lane filled
     * from them may stand (sx_gather_items) */
    bool held;
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
    /* to four reals: the wide passes move a body as one row of four lanes */
    sx_real pad;
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

/* SX_LANES constraints of one colour side by side, lane i holding
 * constraint i (contact_solver.c's wide passes): the fields of
 * sx_constraint, one array of SX_LANES per field. Lanes past a colour's
 * last constraint are padding: no contact (-1), zero masses, bodies the
 * sink entry. */
typedef struct sx_bundle {
    int body_a[SX_LANES], body_b[SX_LANES];
    int contact[SX_LANES];
    sx_real nx[SX_LANES], ny[SX_LANES]; /* the normal (the tangent is (ny, -nx)) */
    sx_real friction[SX_LANES];
    sx_real inv_mass_a[SX_LANES], inv_inertia_a[SX_LANES], inv_mass_b[SX_LANES],
        inv_inertia_b[SX_LANES];
    /* 1 or 0: a two-point contact; its block solve */
    sx_real two[SX_LANES], block_solve[SX_LANES];
    sx_real rn_a[2][SX_LANES], rn_b[2][SX_LANES], rt_a[2][SX_LANES], rt_b[2][SX_LANES];
    sx_real gap[2][SX_LANES];
    sx_real normal_impulse[2][SX_LANES], tangent_impulse[2][SX_LANES];
    sx_real normal_mass[2][SX_LANES], tangent_mass[2][SX_LANES];
    /* a two-point contact's friction row: the mean levers and mass */
    sx_real row_rt_a[SX_LANES], row_rt_b[SX_LANES], row_mass[SX_LANES];
    sx_real k11[SX_LANES], k12[SX_LANES], k22[SX_LANES], inv11[SX_LANES], inv12[SX_LANES],
        inv22[SX_LANES];
} sx_bundle;

/* What the sub-steps after a bundle's fill need to find its lanes' gaps
 * again from the bodies' poses (sx_current_gap, lane-wise): the contacts'
 * body slots (-1: a padding lane), anchors in their body frames and bases.
 * Apart from sx_bundle, which the passes stream through. */
typedef struct sx_bundle_frame {
    int slot_a[SX_LANES], slot_b[SX_LANES];
    sx_real rel_ax[2][SX_LANES], rel_ay[2][SX_LANES], rel_bx[2][SX_LANES], rel_by[2][SX_LANES];
    sx_real base[2][SX_LANES];
} sx_bundle_frame;

/* One colour of the solve, in the order the passes take them: `count`
 * constraints from world->constraints[first] (solved one at a time) or
 * `count` bundles from world->bundles[first] (wide). */
typedef struct sx_colour_span {
    int first, count;
    bool wide;
} sx_colour_span;

/* A constraint as the gather's colouring sees it, and where its fill
 * went (`at`: its constraint, or 4 x bundle + lane), with what the fill
 * read that may change between two collides: the contact's identity and
 * point count, its solver bodies, their inverse masses and types (what
 * the energy guard's groups follow from too). */
typedef struct sx_colour_item {
    uint64_t key;
    int contact, part_a, part_b, count;
    int body_a, body_b, colour, at;
    bool wide; /* in a bundle (else a one-at-a-time constraint) */
    bool dynamic_a, dynamic_b;
    sx_real inv_mass_a, inv_inertia_a, inv_mass_b, inv_inertia_b;
    sx_real friction;
} sx_colour_item;

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

/* contact_solver.c */
/* The effective masses and the block-solve matrix of contact c, from its
 * anchors (fixed for the step): the collide prepares each contact as it
 * makes or thaws it, while the contact is at hand. */
void sx_contact_prepare(const sx_world *world, sx_contact *c);
/* Every contact prepared again (a body's mass changed since the collide),
 * and the count of contacts with restitution. */
void sx_contacts_prepare(sx_world *world);
/* The end of a collide that prepared each contact it made: the solver's
 * kept fill and the effective masses follow the new contacts. */
void sx_contacts_prepared(sx_world *world);
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
void sx_solver_hand_back(sx_world *world);
bool sx_solver_lane_impulses(const sx_world *world, int contact, sx_real normal[2],
                             sx_real tangent[2]);
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

/* body_contacts.c */
/* Removes every contact involving the collider slot (tombstones until the
 * next collide) and wakes the bodies of those contacts. */
void sx_world_remove_contacts_of(sx_world *world, int collider);
/* Drops the tombstones of the step's contact list (keeping its order). */
void sx_world_purge_contacts(sx_world *world);
/* Contact `index` of the live contacts (the step's, then the frozen ones),
 * tombstones skipped; index must be below their number. */
const sx_contact *sx_world_live_contact(const sx_world *world, int index);

#endif /* SEPAX_WORLD_CONTACT_H */
