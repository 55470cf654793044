/* sepax — the contact solver: sequential impulses on velocities, then
 * positional correction, on the contacts of the step's one collide.
 *
 * The contacts are prepared once per collide (effective masses, the block
 * matrices, anchors fixed for the step). Each sub-step then reads every
 * point's separation from the bodies' current positions (the anchors turned
 * with the bodies, along the normal of collide time: first order in the
 * motion of a step), which is what the speculative and positional terms
 * aim at.
 *
 * Data: each sub-step's gather walks the contacts once and copies what
 * the velocity passes read into compact arrays, warm-starting the copies (world_contact.h,
 * sx_constraint and sx_solver_body); the passes touch nothing else, and the
 * last one hands the impulses back to the contacts as it goes. The passes
 * are bound by the chain of dependent operations within a contact (each
 * impulse waits on the velocities the last one left), so what pays is
 * fewer operations on that chain, not fewer bytes, and more chains at once.
 *
 * Wide: the rigid passes solve independent constraints side by side,
 * SX_LANES per sx_rw (four in SSE2 lanes, eight in the float build with
 * AVX2: make SIMD=avx2). The gather colours the constraints
 * so that no two of a colour share a body the solver moves, in a way that
 * keeps each body's impulses in contact order (see "the wide passes"), so
 * the wide solver answers bit for bit what the one-at-a-time pass answers,
 * in every build, and the scalar path stays the reference. The lanes are
 * filled at the first gather after a collide (levers, masses, normals: all
 * fixed for the step) and kept through the step's sub-steps, which only
 * refresh the gaps (without a walk over the contacts while solver_epoch
 * says nothing changed); the colours and lane slots outlive the collide
 * while its contacts name the same solver bodies in the same order, as a
 * resting pile's do. Colours too small for a bundle stay one at a time.
 * With four lanes, the bundles of a colour are solved two side by side,
 * phase by phase, so that the core has two chains at once.
 *
 * Velocities: each contact point is a constraint on the relative normal
 * velocity vn of the two bodies at the point. The solver visits the points in
 * turn (Gauss-Seidel), computes the impulse that would make the constraint
 * exact, and clamps the point's *accumulated* impulse rather than the
 * increment: the accumulated normal impulse stays >= 0 (contacts push, never
 * pull) and the accumulated friction impulse stays inside the Coulomb cone
 * |t| <= mu n. Clamping the sum lets an iteration take back part of an
 * earlier one, which is what makes the method converge, and the sums carry
 * over to the next sub-step (warm starting) so a resting stack starts near
 * its answer. The two points of a face resting on a face are solved
 * together (a 2x2 complementarity problem, solved exactly by trying its four
 * cases), which keeps stacks from rocking. A point still separated by a gap
 * s > 0 is speculative: it may approach at up to s / h, closing the gap
 * exactly in this sub-step, so fast bodies stop at the surface instead of
 * tunnelling. With rigid contacts (the default) an overlapping point only
 * asks for vn >= 0; the overlap itself is removed by moving positions
 * (sx_contacts_relax), never by adding velocity, so overlap does not turn
 * into kinetic energy. With soft contacts (contact_hertz > 0) the overlap is
 * a stiff damped spring whose push-out the relax passes take back.
 *
 * Restitution is not part of these iterations: an impact pass before them
 * (and before the warm start reaches the bodies) resolves the impacts one
 * at a time in time-of-impact order (contact_impact.c gives the design and
 * why), with impulses kept apart from the iterations' accumulators. After them an energy guard makes sure that the
 * warm start and the iterations never give a group of touching bodies more
 * energy than they took from it before (see "the energy guard").
 *
 * Positions: each pass reads every point's current separation and moves
 * the two bodies apart along the normal by a fraction of the overlap beyond
 * the slop, the move split by inverse mass and inverse inertia (a
 * pseudo-impulse that changes positions only). */
#include <stddef.h>
#include <string.h>

#include "contact_math.h"
#include "simd.h"
#include "world_array.h"
#include "world_body.h"
#include "world_contact.h"
#include "world_internal.h"

/* Largest condition estimate k11^2 / det(K) of a two-point contact's mass
 * matrix for which the block solver is used (Box2D's value: beyond it the
 * 2x2 solve amplifies round-off more than it gains). */
#define SX_BLOCK_MAX_CONDITION SX_R(1000.0)

/* ---- the energy guard --------------------------------------------------------
 *
 * The iterations start from the last sub-step's accumulated impulses (warm
 * starting), which is what lets a few of them hold a resting stack, and a
 * heavy body on a light one at all: at a mass ratio of 1000 an iteration
 * moves the pair's impulse by about a thousandth of what the heavy body
 * needs, so the support is carried from sub-step to sub-step. But a warm
 * start is a guess applied blindly, at the points the bodies touch now, and
 * what it gives where it no longer fits the iterations do not always take
 * back: a frictionless capsule spinning on end gains energy from nothing,
 * and a heavy body rolling or wedging on a pinched light one is pushed along
 * by its last impulses sub-step after sub-step.
 *
 * The guard: per group of bodies the contacts join (a union-find over the
 * contacts each sub-step; static and kinematic bodies join nothing), it
 * measures the energy the warm start and the iterations gave the group (see
 * sx_groups_measure for which energy and why) and lets it be positive only
 * within the group's credit: the energy the solver took from the same bodies
 * in earlier sub-steps. Beyond it, the group's impulses and their velocity
 * changes are scaled down until the credit is spent (the energy is a
 * parabola in the scale factor, through 0 at 0). What is left of a group's
 * credit is shared among its bodies by mass and kept for the next sub-step.
 * So over any run the iterations give back at most what they took out. A
 * guard per sub-step (credit 0) is too strict: a heavy body that sags into
 * its support and springs back, which is how too few iterations at a high
 * mass ratio hold it, gains energy on the way back up, and stopped there it
 * sinks into its support. Stacks, pyramids and cradles take energy out far
 * more than the iterations ever give back, and the guard leaves them as they
 * were, bit for bit. The cost: one pass over the contacts (the groups) and
 * three over the bodies in contact per sub-step. */

static int sx_group_root(sx_group_body *gb, int i) {
    while (gb[i].parent != i) {
        gb[i].parent = gb[gb[i].parent].parent; /* path halving */
        i = gb[i].parent;
    }
    return i;
}

/* Room for the groups of every body slot (groups_ready: there is; without
 * it, sx_groups_link leaves no groups). */
static void sx_groups_reserve(sx_world *world) {
    void *p = world->group_bodies;
    world->groups_ready =
        sx_grow_zeroed(&p, &world->group_body_capacity, world->body_slots, sizeof(sx_group_body));
    world->group_bodies = (sx_group_body *)p;
    p = world->group_members;
    world->groups_ready = world->groups_ready && sx_grow_array(&p, &world->group_member_capacity,
                                                               world->body_slots, sizeof(int));
    world->group_members = (int *)p;
}

/* Makes every dynamic body of an active contact a member of a group, and
 * the two dynamic bodies of a contact members of the same one (after
 * sx_groups_reserve). */
static void sx_groups_link(sx_world *world) {
    sx_group_body *gb;
    void *p;
    unsigned epoch;
    int i, side;
    world->group_member_count = 0;
    world->groups_driven = false;
    world->groups_linked = false;
    if (!world->groups_ready) return;
    gb = world->group_bodies;
    if (++world->group_epoch == 0u) {
        /* wrapped: no stale epoch may equal the new one */
        for (i = 0; i < world->group_body_capacity; ++i)
            gb[i].epoch = 0u;
        world->group_epoch = 1u;
    }
    epoch = world->group_epoch;
    for (i = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        int root[2] = {-1, -1};
        if (!sx_contact_is_active(world, c)) continue;
        for (side = 0; side < 2; ++side) {
            int slot = side ? c->body_b : c->body_a;
            if (!world->sims[slot].dynamic) {
                world->groups_driven = world->groups_driven || world->sims[slot].moving;
                continue;
            }
            if (gb[slot].epoch != epoch) {
                gb[slot].epoch = epoch;
                gb[slot].parent = slot;
                world->group_members[world->group_member_count++] = slot;
            }
            root[side] = sx_group_root(gb, slot);
        }
        /* the lower slot becomes the root: the same groups on every run */
        if (root[0] >= 0 && root[1] >= 0 && root[0] != root[1]) {
            if (root[0] < root[1])
                gb[root[1]].parent = root[0];
            else
                gb[root[0]].parent = root[1];
        }
    }
    for (i = 0; i < world->group_member_count; ++i) {
        int slot = world->group_members[i];
        gb[slot].parent = sx_group_root(gb, slot);
    }
    /* the solver bodies they came from (named by the same walk) */
    p = world->group_slots;
    if (sx_grow_array(&p, &world->group_slot_capacity, world->solver_body_count, sizeof(int))) {
        world->group_slots = (int *)p;
        world->group_slot_count = world->solver_body_count;
        memcpy(world->group_slots, world->solver_slots,
               (size_t)world->solver_body_count * sizeof(int));
        world->groups_linked = true;
    }
}

static void sx_groups_build(sx_world *world) {
    sx_groups_reserve(world);
    sx_groups_link(world);
}

/* Whether the linked groups still stand for the items a collide's walk just
 * named: the same solver bodies in the same order as the fill the groups
 * were linked with (pattern), of the same kinds (kinds), from the same body
 * slots. The groups are a function of those alone: the items are the
 * active contacts in order, and the link walks them. (Key-ordered contacts
 * name the same slots whenever the pattern holds and no body was destroyed,
 * which ends the groups itself; the slots are compared all the same, at the
 * cost of one pass over the solver bodies.) */
static bool sx_groups_stand(const sx_world *world, bool pattern, bool kinds) {
    return pattern && kinds && world->groups_linked && world->groups_ready &&
           world->group_slot_count == world->solver_body_count &&
           memcmp(world->group_slots, world->solver_slots,
                  (size_t)world->solver_body_count * sizeof(int)) == 0;
}

/* A contact's group (after sx_groups_build): the root of a dynamic body of
 * it. */
static int sx_group_of(const sx_world *world, const sx_contact *c) {
    int slot = world->sims[c->body_a].dynamic ? c->body_a : c->body_b;
    return world->group_bodies[slot].parent;
}

/* The velocity of body `slot`'s point at offset r from its centre when the
 * body is not dynamic (a moving kinematic body; 0 for a static one), else 0:
 * the dynamic bodies' share is in their change of kinetic energy. */
static sx_vec2 sx_driven_velocity(const sx_world *world, int slot, sx_vec2 r) {
    const sx_body_sim *b = &world->sims[slot];
    if (b->dynamic || !b->moving) return sx_v2_zero();
    return sx_add(b->v, sx_cross_sv(b->w, r));
}

/* Per group, at its root: f = the energy the warm start and the
 * iterations gave the group, a = the kinetic energy of its velocity changes
 * alone (f is s^2 a + s (f - a) for the impulses scaled by s), and the sums
 * of its bodies' credits and masses. The energy is the one the step
 * conserves: symplectic Euler (v += h acc, then x += h v) keeps E = KE - m
 * acc.x + h m acc.v / 2 exactly for a constant acceleration acc (gravity x
 * gravity scale + force / mass; likewise h torque w / 2 for a torque), not
 * KE - m acc.x. So a velocity
 * change dv from the solver changes E by (v1 - v0).(v1 + v0) m / 2 (free of
 * the cancellation of a difference of squares) less h m acc.dv / 2: a body
 * the solver holds at rest changes nothing (the support takes back what the
 * kick of gravity gave), as it should. The work of kinematic bodies is taken
 * off: a kinematic body that pushes is a source the guard must not stop. */
static void sx_groups_measure(sx_world *world, sx_real h) {
    sx_group_body *gb = world->group_bodies;
    int i, k;
    /* (the sums were cleared with the velocities before: sx_contacts_solve) */
    if (world->groups_driven) sx_solver_hand_back(world);
    for (i = 0; i < world->contact_count && world->groups_driven; ++i) {
        const sx_contact *c = &world->contacts[i];
        sx_vec2 t = sx_cross_vs(c->normal, SX_R(1.0));
        sx_group_body *root;
        if (!sx_contact_is_active(world, c)) continue;
        root = &gb[sx_group_of(world, c)];
        for (k = 0; k < c->count; ++k) {
            const sx_contact_point *p = &c->points[k];
            sx_vec2 impulse =
                sx_add(sx_scale(c->normal, p->normal_impulse), sx_scale(t, p->tangent_impulse));
            sx_vec2 driven = sx_sub(sx_driven_velocity(world, c->body_b, p->anchor_b),
                                    sx_driven_velocity(world, c->body_a, p->anchor_a));
            root->f += sx_dot(impulse, driven);
        }
    }
    for (i = 0; i < world->group_member_count; ++i) {
        int slot = world->group_members[i];
        const sx_body_sim *b = &world->sims[slot];
        sx_group_body *g = &gb[slot], *root = &gb[g->parent];
        sx_vec2 dv = sx_sub(b->v, g->v);
        sx_real dw = b->w - g->w;
        if (b->inv_mass > SX_R(0.0)) {
            sx_real m = SX_R(1.0) / b->inv_mass;
            /* m acc = m g gravity_scale + force */
            sx_vec2 weight = sx_mul_add(b->force, m * b->gravity_scale, world->def.gravity);
            root->f += SX_R(0.5) * (m * sx_dot(dv, sx_add(b->v, g->v)) - h * sx_dot(weight, dv));
            root->a += SX_R(0.5) * m * sx_dot(dv, dv);
            root->mass_sum += m;
        }
        if (b->inv_inertia > SX_R(0.0)) {
            sx_real inertia = SX_R(1.0) / b->inv_inertia;
            root->f += SX_R(0.5) * (inertia * dw * (b->w + g->w) - h * b->torque * dw);
            root->a += SX_R(0.5) * inertia * dw * dw;
        }
        root->credit_sum += g->credit;
    }
}

/* The factor for a group's impulses: 1 when f is within the credit C, else
 * the largest s in [0, 1) with s^2 a + s (f - a) <= C. A measure that
 * overflowed (masses near the top of the range) leaves the group as it is. */
static sx_real sx_group_factor(const sx_group_body *root) {
    sx_real b = root->f - root->a, c = root->credit_sum, s;
    if (!(root->f > c) || !sx_is_finite(root->f) || !sx_is_finite(root->a) || !sx_is_finite(c))
        return SX_R(1.0);
    if (!(root->a > SX_R(0.0))) return SX_R(0.0);
    /* the larger root of a s^2 + b s - c (c >= 0: a root >= 0) */
    s = (sx_sqrt(b * b + SX_R(4.0) * root->a * c) - b) / (SX_R(2.0) * root->a);
    return s >= SX_R(0.0) && s < SX_R(1.0) ? s : SX_R(0.0);
}

/* Scales the velocity changes of every group whose f is above its credit by
 * the group's factor and shares out each group's credit left (what it had,
 * less what it got) among its bodies by mass; then, if some group was
 * scaled, its contacts' impulses (the two touch different data, so the
 * bodies' walk goes first and tells whether the contacts' is needed). */
static void sx_groups_settle(sx_world *world) {
    sx_group_body *gb = world->group_bodies;
    bool scaled = false;
    int i, k;
    for (i = 0; i < world->group_member_count; ++i) {
        int slot = world->group_members[i];
        sx_body_sim *b = &world->sims[slot];
        sx_group_body *g = &gb[slot];
        const sx_group_body *root = &gb[g->parent];
        sx_real factor = sx_group_factor(root), left;
        if (factor == SX_R(1.0)) {
            left = root->credit_sum - root->f;
        } else {
            scaled = true;
            left = SX_R(0.0);          /* all of it spent */
            if (factor == SX_R(0.0)) { /* exactly the velocities before */
                b->v = g->v;
                b->w = g->w;
            } else {
                b->v = sx_mul_add(g->v, factor, sx_sub(b->v, g->v));
                b->w = g->w + factor * (b->w - g->w);
            }
        }
        /* a body without mass (a dynamic body of zero density) holds none */
        g->credit = left > SX_R(0.0) && b->inv_mass > SX_R(0.0) && root->mass_sum > SX_R(0.0)
                        ? left * (SX_R(1.0) / b->inv_mass / root->mass_sum)
                        : SX_R(0.0);
        if (!sx_is_finite(g->credit)) g->credit = SX_R(0.0);
    }
    if (scaled) sx_solver_hand_back(world);
    for (i = 0; i < world->contact_count && scaled; ++i) {
        sx_contact *c = &world->contacts[i];
        sx_real factor;
        if (!sx_contact_is_active(world, c)) continue;
        factor = sx_group_factor(&gb[sx_group_of(world, c)]);
        if (factor == SX_R(1.0)) continue;
        world->fill_fresh = false; /* the kept fill's impulses are stale */
        for (k = 0; k < c->count; ++k) {
            c->points[k].normal_impulse *= factor;
            c->points[k].tangent_impulse *= factor;
        }
    }
}

void sx_contacts_energy_guard(sx_world *world, sx_real h) {
    if (!world->groups_ready) return;
    sx_groups_measure(world, h);
    sx_groups_settle(world);
}

/* The normal effective masses of contact c's points, and its block, from
 * its levers. */
static void sx_normal_masses(const sx_world *world, sx_contact *c) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
    sx_vec2 n = c->normal;
    sx_real k[2] = {SX_R(0.0), SX_R(0.0)}, rna[2], rnb[2], det;
    int i;
    for (i = 0; i < c->count; ++i) {
        sx_contact_point *p = &c->points[i];
        rna[i] = sx_cross(p->anchor_a, n);
        rnb[i] = sx_cross(p->anchor_b, n);
        k[i] = ma + mb + ia * rna[i] * rna[i] + ib * rnb[i] * rnb[i];
        p->normal_mass = k[i] > SX_R(0.0) ? SX_R(1.0) / k[i] : SX_R(0.0);
    }
    c->block_solve = false;
    if (c->count != 2) return;
    c->block.k11 = k[0];
    c->block.k22 = k[1];
    c->block.k12 = ma + mb + ia * rna[0] * rna[1] + ib * rnb[0] * rnb[1];
    det = c->block.k11 * c->block.k22 - c->block.k12 * c->block.k12;
    /* Solve the two points together only when K is well conditioned: points
     * almost on top of each other make K nearly singular, and the
     * sequential solve handles them. */
    if (c->block.k11 * c->block.k11 < SX_BLOCK_MAX_CONDITION * det) {
        sx_real inv_det = SX_R(1.0) / det;
        c->block.inv11 = c->block.k22 * inv_det;
        c->block.inv22 = c->block.k11 * inv_det;
        c->block.inv12 = -c->block.k12 * inv_det;
        c->block_solve = true;
    }
}

void sx_contact_prepare(const sx_world *world, sx_contact *c) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    sx_real m = a->inv_mass + b->inv_mass, ia = a->inv_inertia, ib = b->inv_inertia;
    sx_vec2 t = sx_cross_vs(c->normal, SX_R(1.0));
    int k;
    for (k = 0; k < c->count; ++k) {
        sx_contact_point *p = &c->points[k];
        sx_real rta = sx_cross(p->anchor_a, t), rtb = sx_cross(p->anchor_b, t);
        sx_real kt = m + ia * rta * rta + ib * rtb * rtb;
        p->tangent_mass = kt > SX_R(0.0) ? SX_R(1.0) / kt : SX_R(0.0);
    }
    sx_normal_masses(world, c);
}

void sx_contacts_prepared(sx_world *world) {
    world->contact_serial++;
    world->masses_changed = false;
}

void sx_contacts_prepare(sx_world *world) {
    int i;
    sx_contacts_prepared(world);
    world->bouncy_contacts = 0;
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        if (c->restitution > SX_R(0.0)) world->bouncy_contacts++;
        sx_contact_prepare(world, c);
    }
}

/* The separation of point p at the bodies' current positions: the anchors
 * turned with their bodies, along the normal of collide time (the
 * first-order update the sub-steps need between two collides). */
static sx_real sx_current_gap(const sx_body_sim *a, const sx_body_sim *b, sx_vec2 n,
                              const sx_contact_point *p) {
    sx_vec2 ra = sx_rotate(a->xf.q, p->rel_a), rb = sx_rotate(b->xf.q, p->rel_b);
    sx_vec2 d = sx_add(sx_sub(b->center, a->center), sx_sub(rb, ra));
    return p->base + sx_dot(d, n);
}

static void sx_update_gaps(const sx_world *world, sx_contact *c) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    int k;
    for (k = 0; k < c->count; ++k)
        c->points[k].gap = sx_current_gap(a, b, c->normal, &c->points[k]);
}

/* The relative normal velocity a point's constraint wants to be >= 0: a
 * speculative point (gap s > 0) may approach at s / h. */
static sx_real sx_normal_error(const sx_constraint_point *p, sx_real vn, sx_real inv_h) {
    return p->gap > SX_R(0.0) ? vn + p->gap * inv_h : vn;
}

/* The block solve of the velocity iterations: the LCP for the accumulated
 * impulses x of both points, b = error of the current velocities minus what
 * the current impulses did. */
static bool sx_block_solve(const sx_constraint *c, const sx_constraint_point *p1,
                           const sx_constraint_point *p2, sx_real vn1, sx_real vn2, sx_real inv_h,
                           sx_real *x1, sx_real *x2) {
    sx_real a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    sx_real b1 = sx_normal_error(p1, vn1, inv_h) - (c->block.k11 * a1 + c->block.k12 * a2);
    sx_real b2 = sx_normal_error(p2, vn2, inv_h) - (c->block.k12 * a1 + c->block.k22 * a2);
    return sx_solve_lcp2(&c->block, b1, b2, x1, x2);
}

/* The relative speed along dir (normal or tangent) at a point whose anchors
 * have the moments r_a x dir and r_b x dir. */
static inline sx_real sx_lever_speed(sx_vec2 va, sx_real wa, sx_vec2 vb, sx_real wb, sx_vec2 dir,
                                     sx_real r_a, sx_real r_b) {
    return sx_dot(sx_sub(vb, va), dir) + wb * r_b - wa * r_a;
}

/* An impulse lambda along dir at a point whose anchors have the moments r_a
 * x dir and r_b x dir. */
static inline void sx_lever_apply(sx_vec2 *va, sx_real *wa, sx_vec2 *vb, sx_real *wb, sx_real ma,
                                  sx_real ia, sx_real mb, sx_real ib, sx_vec2 dir, sx_real r_a,
                                  sx_real r_b, sx_real lambda) {
    sx_vec2 impulse = sx_scale(dir, lambda);
    *va = sx_mul_sub(*va, ma, impulse);
    *wa -= ia * (lambda * r_a);
    *vb = sx_mul_add(*vb, mb, impulse);
    *wb += ib * (lambda * r_b);
}

/* A soft contact (Catto, "Soft Constraints", GDC 2011): the overlap is a
 * stiff spring of frequency `hertz` and damping ratio `zeta` solved
 * implicitly over the sub-step h, which makes the push-out a velocity bias
 * bias_rate x overlap and weakens the constraint by mass_scale (impulse
 * leak impulse_scale). Stable for any stiffness at a given h. */
typedef struct sx_softness {
    sx_real bias_rate, mass_scale, impulse_scale;
} sx_softness;

static sx_softness sx_make_softness(sx_real hertz, sx_real zeta, sx_real h) {
    sx_softness s;
    sx_real omega = SX_R(2.0) * SX_PI * hertz, a1 = SX_R(2.0) * zeta + h * omega;
    sx_real a2 = h * omega * a1, a3 = SX_R(1.0) / (SX_R(1.0) + a2);
    if (!(hertz > SX_R(0.0)) || !(a1 > SX_R(0.0))) {
        s.bias_rate = SX_R(0.0);
        s.mass_scale = SX_R(1.0);
        s.impulse_scale = SX_R(0.0);
        return s;
    }
    s.bias_rate = omega / a1;
    s.mass_scale = a2 * a3;
    s.impulse_scale = a3;
    return s;
}

/* The normal constraint of one point, one at a time: rigid for a
 * speculative point (it may close its gap and no more) and in the relax
 * pass, soft for an overlapping point in the soft pass. The relax pass
 * leaves speculative points alone: the next sub-step's solve, after its
 * impact pass, limits their approach (a relax pass that did would stop a
 * ball at the surface before the impact pass could see it arrive). */
static void sx_solve_normal_point(sx_constraint_point *p, sx_vec2 n, sx_vec2 *va, sx_real *wa,
                                  sx_vec2 *vb, sx_real *wb, sx_real ma, sx_real ia, sx_real mb,
                                  sx_real ib, sx_real inv_h, const sx_softness *soft,
                                  sx_real max_push, bool relax) {
    sx_real vn, lambda, total;
    if (relax && p->gap > SX_R(0.0)) return;
    vn = sx_lever_speed(*va, *wa, *vb, *wb, n, p->rn_a, p->rn_b);
    if (p->gap > SX_R(0.0)) {
        lambda = -p->normal_mass * (vn + p->gap * inv_h);
    } else if (soft != NULL) {
        sx_real bias = sx_maxr(soft->mass_scale * soft->bias_rate * p->gap, -max_push);
        lambda = -p->normal_mass * (soft->mass_scale * vn + bias) -
                 soft->impulse_scale * p->normal_impulse;
    } else {
        lambda = -p->normal_mass * vn;
    }
    total = sx_bounded_impulse(sx_maxr(p->normal_impulse + lambda, SX_R(0.0)));
    lambda = total - p->normal_impulse;
    p->normal_impulse = total;
    sx_lever_apply(va, wa, vb, wb, ma, ia, mb, ib, n, p->rn_a, p->rn_b, lambda);
}

/* The friction of a two-point contact as one constraint: the tangent
 * rows of the two points differ only in the levers' components along the
 * normal (r x t = -r . n), which the two points of a face share, so solved
 * one after the other they did the same work twice, on the longest chain
 * of dependent operations of a pass. One row at the mean lever, within mu
 * times the sum of the normal impulses; the total is shared between the
 * points in proportion to their normal impulses (each within its own
 * cone), which is what the warm start and the contact reports see. */
static SX_ALWAYS_INLINE void sx_friction_row2(sx_constraint *c, sx_vec2 *va, sx_real *wa,
                                              sx_vec2 *vb, sx_real *wb, sx_vec2 t) {
    sx_constraint_point *p1 = &c->points[0], *p2 = &c->points[1];
    sx_real rta = SX_R(0.5) * (p1->rt_a + p2->rt_a), rtb = SX_R(0.5) * (p1->rt_b + p2->rt_b);
    sx_real mass = SX_R(0.5) * (p1->tangent_mass + p2->tangent_mass);
    sx_real normal = p1->normal_impulse + p2->normal_impulse, limit = c->friction * normal;
    sx_real old = p1->tangent_impulse + p2->tangent_impulse;
    sx_real lambda = -mass * sx_lever_speed(*va, *wa, *vb, *wb, t, rta, rtb);
    sx_real total = sx_bounded_impulse(sx_clampr(old + lambda, -limit, limit));
    p1->tangent_impulse = normal > SX_R(0.0) ? total * (p1->normal_impulse / normal)
                                             : SX_R(0.5) * total;
    p2->tangent_impulse = total - p1->tangent_impulse;
    sx_lever_apply(va, wa, vb, wb, c->inv_mass_a, c->inv_inertia_a, c->inv_mass_b,
                   c->inv_inertia_b, t, rta, rtb, total - old);
}

/* One constraint of a pass, one at a time: sx_constraints_pass's scalar
 * path (soft when sft is set, a relax pass when relax). */
static SX_ALWAYS_INLINE void sx_constraint_solve(sx_world *world, sx_constraint *c,
                                                 sx_solver_body *bodies, sx_real inv_h,
                                                 const sx_softness *sft, sx_real max_push,
                                                 bool relax, bool last) {
    sx_solver_body *a = &bodies[c->body_a], *b = &bodies[c->body_b];
    sx_real ma = c->inv_mass_a, ia = c->inv_inertia_a, mb = c->inv_mass_b, ib = c->inv_inertia_b;
    sx_vec2 va = a->v, vb = b->v, n = c->normal, t = sx_cross_vs(n, SX_R(1.0));
    sx_real wa = a->w, wb = b->w;
    bool solved = false;
    int k;
    /* Friction first, with the normal impulses of the last pass (or of
     * the warm start): the normal constraints then have the last word,
     * so a pass never ends with a point moving into the surface. A
     * frictionless contact costs nothing here. */
    if (c->friction > SX_R(0.0) && c->count == 2) {
        sx_friction_row2(c, &va, &wa, &vb, &wb, t);
    } else if (c->friction > SX_R(0.0)) {
        for (k = 0; k < c->count; ++k) {
            sx_constraint_point *p = &c->points[k];
            sx_real limit = c->friction * p->normal_impulse;
            sx_real lambda =
                -p->tangent_mass * sx_lever_speed(va, wa, vb, wb, t, p->rt_a, p->rt_b);
            sx_real total =
                sx_bounded_impulse(sx_clampr(p->tangent_impulse + lambda, -limit, limit));
            lambda = total - p->tangent_impulse;
            p->tangent_impulse = total;
            sx_lever_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, t, p->rt_a, p->rt_b, lambda);
        }
    }
    /* the rigid passes solve a face's two points together */
    if (c->block_solve && sft == NULL &&
        (!relax || (c->points[0].gap <= SX_R(0.0) && c->points[1].gap <= SX_R(0.0)))) {
        sx_constraint_point *p1 = &c->points[0], *p2 = &c->points[1];
        sx_real x1, x2;
        sx_real vn1 = sx_lever_speed(va, wa, vb, wb, n, p1->rn_a, p1->rn_b);
        sx_real vn2 = sx_lever_speed(va, wa, vb, wb, n, p2->rn_a, p2->rn_b);
        /* an overflowed solution (not <= the bound: inf or NaN) is
         * left to the point-by-point solve below, which bounds it */
        if (sx_block_solve(c, p1, p2, vn1, vn2, inv_h, &x1, &x2) && x1 <= SX_IMPULSE_LIMIT &&
            x2 <= SX_IMPULSE_LIMIT) {
            sx_real d1 = x1 - p1->normal_impulse, d2 = x2 - p2->normal_impulse;
            sx_lever_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, n, p1->rn_a, p1->rn_b, d1);
            sx_lever_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, n, p2->rn_a, p2->rn_b, d2);
            p1->normal_impulse = x1;
            p2->normal_impulse = x2;
            solved = true;
        }
    }
    if (!solved) {
        for (k = 0; k < c->count; ++k) {
            sx_solve_normal_point(&c->points[k], n, &va, &wa, &vb, &wb, ma, ia, mb, ib, inv_h,
                                  sft, max_push, relax);
        }
    }
    a->v = va;
    a->w = wa;
    b->v = vb;
    b->w = wb;
    if (last) {
        sx_contact_point *out = world->contacts[c->contact].points;
        for (k = 0; k < c->count; ++k) {
            out[k].normal_impulse = c->points[k].normal_impulse;
            out[k].tangent_impulse = c->points[k].tangent_impulse;
        }
    }
}

/* ---- the wide passes -----------------------------------------------------
 *
 * The rigid velocity pass, SX_LANES constraints at a time (sx_rw lanes:
 * four in SSE2, eight in AVX2). The gather colours the constraints: each takes
 * colour 1 + the largest colour given so far to either of its bodies that
 * the solver moves, walking them in contact order. No two constraints of a
 * colour share such a body, and the constraints of every body have rising
 * colours in contact order, so solving colour after colour applies to each
 * body the very impulses, in the very order, that the contact-order pass
 * does: the answers stay bit for bit those of the one-at-a-time pass, in
 * every build. (Greedy colouring, the first colour free at both bodies,
 * gives fewer colours but reorders a body's impulses, and the pyramids
 * lost accuracy with it.) Entry 0, the bodies the solver does not move, is
 * read by every lane and stays exactly zero.
 *
 * Within a bundle, each lane runs the scalar pass's operations in
 * their order (no fused multiply-add); its branches (two-point friction
 * row or a single point, the block solve's four cases and its fallback to
 * point by point, speculative or overlapping points) are computed for the
 * lanes that need any and chosen per lane with masks, so a lane that does
 * not take a branch keeps its values bit for bit. Padding lanes have zero
 * masses and write to a sink entry past the solver bodies. Colours of
 * fewer than SX_WIDE_MIN_COLOUR constraints (a stack: one per colour) stay
 * on the scalar path, where a bundle would be mostly padding. The lane
 * width changes which lanes share a register, never a lane's operations,
 * so every width answers alike too. Nor does solving a colour's bundles
 * side by side (they share no moved body, entry 0 and the sink stay
 * zero), which is why a wide colour keeps a span of its own. The soft
 * passes, the relax passes, the energy guard and the impact pass stay
 * scalar; the positional pass takes the colours too, and finds the
 * separations of a wide colour's lanes together (sx_push_by_colour). */

/* Colours of fewer constraints than this are solved one at a time (four
 * lanes: below it the pyramids gained nothing and a stack lost; with eight
 * lanes a half-filled bundle still beats the scalar pass, and eight
 * measured slower than four). */
#define SX_WIDE_MIN_COLOUR 4

/* sx_rw_gather4 moves records of four reals: a solver body is one. */
typedef char sx_solver_body_is_four_reals[sizeof(sx_solver_body) == 4 * sizeof(sx_real) ? 1 : -1];

/* SX_LANES solver bodies' velocities into lanes (vx, vy, w; pad kept). */
static SX_ALWAYS_INLINE void sx_lanes_load(const sx_solver_body *bodies, const int *idx, sx_rw *vx,
                                           sx_rw *vy, sx_rw *w, sx_rw *pad) {
    sx_rw_gather4((const sx_real *)(const void *)bodies, idx, vx, vy, w, pad);
}

static SX_ALWAYS_INLINE void sx_lanes_store(sx_solver_body *bodies, const int *idx, sx_rw vx,
                                            sx_rw vy, sx_rw w, sx_rw pad) {
    sx_rw_scatter4((sx_real *)(void *)bodies, idx, vx, vy, w, pad);
}

/* The two bodies of SX_LANES constraints, lane-wise. */
typedef struct sx_lanes_pair {
    sx_rw vax, vay, wa, pa, vbx, vby, wb, pb;
} sx_lanes_pair;

/* sx_lever_speed, lane-wise. */
static SX_ALWAYS_INLINE sx_rw sx_lanes_speed(const sx_lanes_pair *v, sx_rw dx, sx_rw dy, sx_rw r_a,
                                             sx_rw r_b) {
    sx_rw ex = sx_rw_sub(v->vbx, v->vax), ey = sx_rw_sub(v->vby, v->vay);
    sx_rw s = sx_rw_add(sx_rw_mul(ex, dx), sx_rw_mul(ey, dy));
    return sx_rw_sub(sx_rw_add(s, sx_rw_mul(v->wb, r_b)), sx_rw_mul(v->wa, r_a));
}

/* sx_lever_apply, lane-wise, in the lanes of mask m only (the selects
 * skipped when m holds every lane, the common case). */
static SX_ALWAYS_INLINE void sx_lanes_apply(sx_lanes_pair *v, sx_mw m, sx_rw ma, sx_rw ia, sx_rw mb,
                                            sx_rw ib, sx_rw dx, sx_rw dy, sx_rw r_a, sx_rw r_b,
                                            sx_rw lambda) {
    sx_rw ix = sx_rw_mul(lambda, dx), iy = sx_rw_mul(lambda, dy);
    if (sx_mw_all(m)) {
        v->vax = sx_rw_sub(v->vax, sx_rw_mul(ma, ix));
        v->vay = sx_rw_sub(v->vay, sx_rw_mul(ma, iy));
        v->wa = sx_rw_sub(v->wa, sx_rw_mul(ia, sx_rw_mul(lambda, r_a)));
        v->vbx = sx_rw_add(v->vbx, sx_rw_mul(mb, ix));
        v->vby = sx_rw_add(v->vby, sx_rw_mul(mb, iy));
        v->wb = sx_rw_add(v->wb, sx_rw_mul(ib, sx_rw_mul(lambda, r_b)));
        return;
    }
    v->vax = sx_rw_select(m, sx_rw_sub(v->vax, sx_rw_mul(ma, ix)), v->vax);
    v->vay = sx_rw_select(m, sx_rw_sub(v->vay, sx_rw_mul(ma, iy)), v->vay);
    v->wa = sx_rw_select(m, sx_rw_sub(v->wa, sx_rw_mul(ia, sx_rw_mul(lambda, r_a))), v->wa);
    v->vbx = sx_rw_select(m, sx_rw_add(v->vbx, sx_rw_mul(mb, ix)), v->vbx);
    v->vby = sx_rw_select(m, sx_rw_add(v->vby, sx_rw_mul(mb, iy)), v->vby);
    v->wb = sx_rw_select(m, sx_rw_add(v->wb, sx_rw_mul(ib, sx_rw_mul(lambda, r_b))), v->wb);
}

/* sx_bounded_impulse, lane-wise. */
static SX_ALWAYS_INLINE sx_rw sx_lanes_bounded(sx_rw x) {
    sx_rw hi = sx_rw_set1(SX_IMPULSE_LIMIT), lo = sx_rw_set1(-SX_IMPULSE_LIMIT);
    sx_mw in = sx_rw_le(x, hi);
    sx_rw inside;
    if (sx_mw_all(sx_mw_and(in, sx_rw_ge(x, lo)))) return x; /* the common case */
    inside = sx_rw_select(in, x, hi);
    sx_rw below = sx_rw_select(sx_rw_lt(x, lo), lo, sx_rw_zero());
    return sx_rw_select(sx_rw_ge(x, lo), inside, below);
}

/* sx_clampr(a, -limit, limit), lane-wise. */
static SX_ALWAYS_INLINE sx_rw sx_lanes_clamp(sx_rw a, sx_rw limit) {
    sx_rw lo = sx_rw_neg(limit);
    sx_rw above = sx_rw_select(sx_rw_gt(a, limit), sx_rw_max(lo, limit), a);
    return sx_rw_select(sx_rw_lt(a, lo), lo, above);
}

/* sx_normal_error, lane-wise. */
static SX_ALWAYS_INLINE sx_rw sx_lanes_error(sx_rw vn, sx_rw gap, sx_rw inv_h) {
    return sx_rw_select(sx_rw_gt(gap, sx_rw_zero()), sx_rw_add(vn, sx_rw_mul(gap, inv_h)), vn);
}

/* The warm start of a bundle (sx_warm_start lane-wise). */
static void sx_bundle_warm_start(sx_solver_body *bodies, const sx_bundle *u) {
    sx_lanes_pair v;
    /* the tangent (n.y, -n.x): sx_cross_vs(n, 1), exactly */
    sx_rw nx = sx_rw_load(u->nx), ny = sx_rw_load(u->ny), tx = ny, ty = sx_rw_neg(nx);
    sx_rw ma = sx_rw_load(u->inv_mass_a), ia = sx_rw_load(u->inv_inertia_a);
    sx_rw mb = sx_rw_load(u->inv_mass_b), ib = sx_rw_load(u->inv_inertia_b);
    sx_mw all = sx_mw_true(), two = sx_rw_gt(sx_rw_load(u->two), sx_rw_zero());
    int k;
    sx_lanes_load(bodies, u->body_a, &v.vax, &v.vay, &v.wa, &v.pa);
    sx_lanes_load(bodies, u->body_b, &v.vbx, &v.vby, &v.wb, &v.pb);
    for (k = 0; k < 2; ++k) {
        sx_mw m = k == 0 ? all : two;
        sx_rw ni = sx_rw_load(u->normal_impulse[k]), ti = sx_rw_load(u->tangent_impulse[k]);
        sx_rw ix = sx_rw_add(sx_rw_mul(ni, nx), sx_rw_mul(ti, tx));
        sx_rw iy = sx_rw_add(sx_rw_mul(ni, ny), sx_rw_mul(ti, ty));
        sx_rw ma_ =
            sx_rw_add(sx_rw_mul(ni, sx_rw_load(u->rn_a[k])), sx_rw_mul(ti, sx_rw_load(u->rt_a[k])));
        sx_rw mb_ =
            sx_rw_add(sx_rw_mul(ni, sx_rw_load(u->rn_b[k])), sx_rw_mul(ti, sx_rw_load(u->rt_b[k])));
        v.vax = sx_rw_select(m, sx_rw_sub(v.vax, sx_rw_mul(ma, ix)), v.vax);
        v.vay = sx_rw_select(m, sx_rw_sub(v.vay, sx_rw_mul(ma, iy)), v.vay);
        v.wa = sx_rw_select(m, sx_rw_sub(v.wa, sx_rw_mul(ia, ma_)), v.wa);
        v.vbx = sx_rw_select(m, sx_rw_add(v.vbx, sx_rw_mul(mb, ix)), v.vbx);
        v.vby = sx_rw_select(m, sx_rw_add(v.vby, sx_rw_mul(mb, iy)), v.vby);
        v.wb = sx_rw_select(m, sx_rw_add(v.wb, sx_rw_mul(ib, mb_)), v.wb);
    }
    sx_lanes_store(bodies, u->body_a, v.vax, v.vay, v.wa, v.pa);
    sx_lanes_store(bodies, u->body_b, v.vbx, v.vby, v.wb, v.pb);
}

/* sx_solve_lcp2 for the lanes in `solved`: the first of its four cases that
 * fits, in *x1 and *x2; returns the lanes where one fits. */
static SX_ALWAYS_INLINE sx_mw sx_lanes_lcp2(const sx_bundle *u, sx_mw solved, sx_rw b1, sx_rw b2,
                                            sx_rw *x1, sx_rw *x2) {
    sx_rw zero = sx_rw_zero();
    sx_rw inv11 = sx_rw_load(u->inv11), inv12 = sx_rw_load(u->inv12);
    sx_rw inv22 = sx_rw_load(u->inv22);
    sx_rw y1 = sx_rw_neg(sx_rw_add(sx_rw_mul(inv11, b1), sx_rw_mul(inv12, b2)));
    sx_rw y2 = sx_rw_neg(sx_rw_add(sx_rw_mul(inv12, b1), sx_rw_mul(inv22, b2)));
    sx_mw c1 = sx_mw_and(sx_rw_ge(y1, zero), sx_rw_ge(y2, zero)), c2, c3, c4;
    sx_rw k11, k12, k22, z1, z2;
    if (sx_mw_all(sx_mw_or(c1, sx_mw_andnot(solved, sx_mw_true())))) {
        /* both points push in every lane that solves as a block (a resting
         * face): the other cases and their divisions unneeded */
        *x1 = y1;
        *x2 = y2;
        return sx_mw_and(solved, c1);
    }
    k11 = sx_rw_load(u->k11);
    k12 = sx_rw_load(u->k12);
    k22 = sx_rw_load(u->k22);
    z1 = sx_rw_div(sx_rw_neg(b1), k11);
    c2 = sx_mw_and(sx_rw_ge(z1, zero), sx_rw_ge(sx_rw_add(sx_rw_mul(k12, z1), b2), zero));
    z2 = sx_rw_div(sx_rw_neg(b2), k22);
    c3 = sx_mw_and(sx_rw_ge(z2, zero), sx_rw_ge(sx_rw_add(sx_rw_mul(k12, z2), b1), zero));
    c4 = sx_mw_and(sx_rw_ge(b1, zero), sx_rw_ge(b2, zero));
    *x1 = sx_rw_select(c1, y1, sx_rw_select(c2, z1, zero));
    *x2 = sx_rw_select(c1, y2, sx_rw_select(c2, zero, sx_rw_select(c3, z2, zero)));
    return sx_mw_and(solved, sx_mw_or(sx_mw_or(c1, c2), sx_mw_or(c3, c4)));
}

/* The last pass hands a bundle's accumulated impulses back to its contacts
 * (the next sub-step's warm start, the contact reports). */
static void sx_bundle_hand_back(sx_world *world, const sx_bundle *u) {
    int i;
    for (i = 0; i < SX_LANES; ++i) {
        sx_contact_point *out;
        if (u->contact[i] < 0) continue;
        out = world->contacts[u->contact[i]].points;
        out[0].normal_impulse = u->normal_impulse[0][i];
        out[0].tangent_impulse = u->tangent_impulse[0][i];
        if (u->two[i] > SX_R(0.0)) {
            out[1].normal_impulse = u->normal_impulse[1][i];
            out[1].tangent_impulse = u->tangent_impulse[1][i];
        }
    }
}

/* The wide lanes' impulses onto their contacts, if a last pass left them in
 * the lanes (hand_back_later): for whatever reads the contacts' impulses
 * before the next kept fill does (the energy guard's settle and its
 * kinematic measure, a fill from scratch). */
void sx_solver_hand_back(sx_world *world) {
    int s, i;
    if (!world->impulses_in_lanes) return;
    world->impulses_in_lanes = false;
    for (s = 0; s < world->span_count; ++s) {
        const sx_colour_span *span = &world->spans[s];
        for (i = span->first; span->wide && i < span->first + span->count; ++i)
            sx_bundle_hand_back(world, &world->bundles[i]);
    }
}

/* Contact `contact`'s accumulated impulses while they are in a lane
 * (impulses_in_lanes): true with them in normal[] and tangent[], false
 * when the contact's own are current. The fill's items are in contact
 * order: a binary search finds its item. */
bool sx_solver_lane_impulses(const sx_world *world, int contact, sx_real normal[2],
                             sx_real tangent[2]) {
    const sx_colour_item *items = world->colour_items;
    int lo = 0, hi = world->fill_count, k;
    const sx_bundle *u;
    if (!world->impulses_in_lanes) return false;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (items[mid].contact < contact)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == world->fill_count || items[lo].contact != contact || !items[lo].wide) return false;
    u = &world->bundles[items[lo].at / SX_LANES];
    for (k = 0; k < 2; ++k) {
        normal[k] = u->normal_impulse[k][items[lo].at % SX_LANES];
        tangent[k] = u->tangent_impulse[k][items[lo].at % SX_LANES];
    }
    return true;
}

/* A bundle's lanes through a pass: its bodies' velocities and its
 * accumulated impulses. */
typedef struct sx_bundle_lanes {
    sx_lanes_pair v;
    sx_rw n1, n2, t1, t2;
} sx_bundle_lanes;

static SX_ALWAYS_INLINE void sx_bundle_begin(const sx_solver_body *bodies, const sx_bundle *u,
                                             sx_bundle_lanes *s) {
    sx_lanes_load(bodies, u->body_a, &s->v.vax, &s->v.vay, &s->v.wa, &s->v.pa);
    sx_lanes_load(bodies, u->body_b, &s->v.vbx, &s->v.vby, &s->v.wb, &s->v.pb);
    s->n1 = sx_rw_load(u->normal_impulse[0]);
    s->n2 = sx_rw_load(u->normal_impulse[1]);
    s->t1 = sx_rw_load(u->tangent_impulse[0]);
    s->t2 = sx_rw_load(u->tangent_impulse[1]);
}

/* The friction (sx_friction_row2, or a one-point contact's point). */
static SX_ALWAYS_INLINE void sx_bundle_friction(const sx_bundle *u, sx_bundle_lanes *s, sx_mw row,
                                                sx_mw single) {
    sx_rw zero = sx_rw_zero();
    sx_rw nx = sx_rw_load(u->nx), ny = sx_rw_load(u->ny);
    sx_rw ma = sx_rw_load(u->inv_mass_a), ia = sx_rw_load(u->inv_inertia_a);
    sx_rw mb = sx_rw_load(u->inv_mass_b), ib = sx_rw_load(u->inv_inertia_b);
    sx_rw friction = sx_rw_load(u->friction);
    sx_rw tx = ny, ty = sx_rw_neg(nx);
    if (sx_mw_any(row)) {
        sx_rw rta = sx_rw_load(u->row_rt_a), rtb = sx_rw_load(u->row_rt_b);
        sx_rw normal = sx_rw_add(s->n1, s->n2), limit = sx_rw_mul(friction, normal);
        sx_rw old = sx_rw_add(s->t1, s->t2);
        sx_rw lambda =
            sx_rw_mul(sx_rw_neg(sx_rw_load(u->row_mass)), sx_lanes_speed(&s->v, tx, ty, rta, rtb));
        sx_rw total = sx_lanes_bounded(sx_lanes_clamp(sx_rw_add(old, lambda), limit));
        sx_rw share =
            sx_rw_select(sx_rw_gt(normal, zero), sx_rw_mul(total, sx_rw_div(s->n1, normal)),
                         sx_rw_mul(sx_rw_set1(SX_R(0.5)), total));
        if (sx_mw_all(row)) {
            s->t1 = share;
            s->t2 = sx_rw_sub(total, share);
        } else {
            s->t1 = sx_rw_select(row, share, s->t1);
            s->t2 = sx_rw_select(row, sx_rw_sub(total, share), s->t2);
        }
        sx_lanes_apply(&s->v, row, ma, ia, mb, ib, tx, ty, rta, rtb, sx_rw_sub(total, old));
    }
    if (sx_mw_any(single)) {
        sx_rw rta = sx_rw_load(u->rt_a[0]), rtb = sx_rw_load(u->rt_b[0]);
        sx_rw limit = sx_rw_mul(friction, s->n1);
        sx_rw lambda = sx_rw_mul(sx_rw_neg(sx_rw_load(u->tangent_mass[0])),
                                 sx_lanes_speed(&s->v, tx, ty, rta, rtb));
        sx_rw total = sx_lanes_bounded(sx_lanes_clamp(sx_rw_add(s->t1, lambda), limit));
        sx_lanes_apply(&s->v, single, ma, ia, mb, ib, tx, ty, rta, rtb, sx_rw_sub(total, s->t1));
        s->t1 = sx_rw_select(single, total, s->t1);
    }
}

/* The normal points: the block solve where it applies and succeeds, the
 * others point by point (sx_solve_normal_point, rigid). */
static SX_ALWAYS_INLINE void sx_bundle_normals(const sx_bundle *u, sx_bundle_lanes *s,
                                               sx_rw inv_h) {
    sx_rw zero = sx_rw_zero();
    sx_rw nx = sx_rw_load(u->nx), ny = sx_rw_load(u->ny);
    sx_rw ma = sx_rw_load(u->inv_mass_a), ia = sx_rw_load(u->inv_inertia_a);
    sx_rw mb = sx_rw_load(u->inv_mass_b), ib = sx_rw_load(u->inv_inertia_b);
    sx_rw rna1 = sx_rw_load(u->rn_a[0]), rnb1 = sx_rw_load(u->rn_b[0]);
    sx_rw rna2 = sx_rw_load(u->rn_a[1]), rnb2 = sx_rw_load(u->rn_b[1]);
    sx_rw g1 = sx_rw_load(u->gap[0]), g2 = sx_rw_load(u->gap[1]);
    sx_rw vn1 = sx_lanes_speed(&s->v, nx, ny, rna1, rnb1), vn2;
    sx_rw err1 = sx_lanes_error(vn1, g1, inv_h);
    sx_mw solved = sx_rw_gt(sx_rw_load(u->block_solve), zero), rest;
    if (sx_mw_any(solved)) {
        sx_rw k11 = sx_rw_load(u->k11), k12 = sx_rw_load(u->k12), k22 = sx_rw_load(u->k22);
        sx_rw bound = sx_rw_set1(SX_IMPULSE_LIMIT);
        sx_rw b1, b2, x1, x2;
        vn2 = sx_lanes_speed(&s->v, nx, ny, rna2, rnb2);
        b1 = sx_rw_sub(err1, sx_rw_add(sx_rw_mul(k11, s->n1), sx_rw_mul(k12, s->n2)));
        b2 = sx_rw_sub(sx_lanes_error(vn2, g2, inv_h),
                       sx_rw_add(sx_rw_mul(k12, s->n1), sx_rw_mul(k22, s->n2)));
        solved = sx_lanes_lcp2(u, solved, b1, b2, &x1, &x2);
        solved = sx_mw_and(solved, sx_mw_and(sx_rw_le(x1, bound), sx_rw_le(x2, bound)));
        sx_lanes_apply(&s->v, solved, ma, ia, mb, ib, nx, ny, rna1, rnb1, sx_rw_sub(x1, s->n1));
        sx_lanes_apply(&s->v, solved, ma, ia, mb, ib, nx, ny, rna2, rnb2, sx_rw_sub(x2, s->n2));
        s->n1 = sx_rw_select(solved, x1, s->n1);
        s->n2 = sx_rw_select(solved, x2, s->n2);
    }
    rest = sx_mw_andnot(solved, sx_mw_true());
    if (sx_mw_any(rest)) {
        sx_rw total, lambda;
        sx_mw rest2 = sx_mw_and(rest, sx_rw_gt(sx_rw_load(u->two), zero));
        lambda = sx_rw_mul(sx_rw_neg(sx_rw_load(u->normal_mass[0])), err1);
        total = sx_lanes_bounded(sx_rw_max(sx_rw_add(s->n1, lambda), zero));
        sx_lanes_apply(&s->v, rest, ma, ia, mb, ib, nx, ny, rna1, rnb1, sx_rw_sub(total, s->n1));
        s->n1 = sx_rw_select(rest, total, s->n1);
        if (sx_mw_any(rest2)) {
            vn2 = sx_lanes_speed(&s->v, nx, ny, rna2, rnb2);
            lambda =
                sx_rw_mul(sx_rw_neg(sx_rw_load(u->normal_mass[1])), sx_lanes_error(vn2, g2, inv_h));
            total = sx_lanes_bounded(sx_rw_max(sx_rw_add(s->n2, lambda), zero));
            sx_lanes_apply(&s->v, rest2, ma, ia, mb, ib, nx, ny, rna2, rnb2,
                           sx_rw_sub(total, s->n2));
            s->n2 = sx_rw_select(rest2, total, s->n2);
        }
    }
}

static SX_ALWAYS_INLINE void sx_bundle_end(sx_solver_body *bodies, sx_bundle *u,
                                           const sx_bundle_lanes *s) {
    sx_lanes_store(bodies, u->body_a, s->v.vax, s->v.vay, s->v.wa, s->v.pa);
    sx_lanes_store(bodies, u->body_b, s->v.vbx, s->v.vby, s->v.wb, s->v.pb);
    sx_rw_store(u->normal_impulse[0], s->n1);
    sx_rw_store(u->normal_impulse[1], s->n2);
    sx_rw_store(u->tangent_impulse[0], s->t1);
    sx_rw_store(u->tangent_impulse[1], s->t2);
}

/* The friction kinds of a bundle's lanes: a two-point contact's row, or
 * a one-point contact's point. */
static SX_ALWAYS_INLINE void sx_bundle_kinds(const sx_bundle *u, sx_mw *row, sx_mw *single) {
    sx_rw zero = sx_rw_zero();
    sx_mw two = sx_rw_gt(sx_rw_load(u->two), zero), rubs = sx_rw_gt(sx_rw_load(u->friction), zero);
    *row = sx_mw_and(rubs, two);
    *single = sx_mw_andnot(two, rubs);
}

/* One rigid pass over a bundle: sx_constraint_solve's rigid branches for
 * SX_LANES constraints at once. */
static void sx_bundle_solve(sx_world *world, sx_bundle *u, sx_rw inv_h, bool last) {
    sx_bundle_lanes s;
    sx_mw row, single;
    sx_bundle_kinds(u, &row, &single);
    sx_bundle_begin(world->solver_bodies, u, &s);
    sx_bundle_friction(u, &s, row, single);
    sx_bundle_normals(u, &s, inv_h);
    sx_bundle_end(world->solver_bodies, u, &s);
    if (last) sx_bundle_hand_back(world, u);
}

/* Bundles of a colour share no body the solver moves: solved phase by
 * phase, two of them (each lane's operations as sx_bundle_solve's) put
 * their chains of dependent operations side by side in the instruction
 * stream, where one bundle after the other left the core waiting on one
 * chain at a time. Written out, as the bundles' lanes stay in registers
 * that way (an array of them went through memory and lost the gain; four
 * side by side spilled to the stack). */
static void sx_bundle_solve2(sx_world *world, sx_bundle *u, sx_rw inv_h, bool last) {
    sx_solver_body *bodies = world->solver_bodies;
    sx_bundle_lanes s0, s1;
    sx_mw row0, single0, row1, single1;
    sx_bundle_kinds(&u[0], &row0, &single0);
    sx_bundle_kinds(&u[1], &row1, &single1);
    sx_bundle_begin(bodies, &u[0], &s0);
    sx_bundle_begin(bodies, &u[1], &s1);
    sx_bundle_friction(&u[0], &s0, row0, single0);
    sx_bundle_friction(&u[1], &s1, row1, single1);
    sx_bundle_normals(&u[0], &s0, inv_h);
    sx_bundle_normals(&u[1], &s1, inv_h);
    sx_bundle_end(bodies, &u[0], &s0);
    sx_bundle_end(bodies, &u[1], &s1);
    if (last) {
        sx_bundle_hand_back(world, &u[0]);
        sx_bundle_hand_back(world, &u[1]);
    }
}

/* One pass over the constraints, colour by colour: sx_world_solve's (soft
 * when the world's contacts are) or a relax pass. `last`: the last pass of
 * the solve also hands each constraint's impulses back to its contact as
 * it goes (the stores overlap the solve, where a walk of their own waited
 * on memory). */
static void sx_constraints_pass(sx_world *world, sx_real h, bool relax, bool last) {
    sx_real inv_h = SX_R(1.0) / h;
    /* the stiffness follows the sub-step (a spring faster than a quarter of
     * the sub-step rate is not resolved by it); contacts with a body the
     * solver cannot move are twice as stiff, as they have half the masses
     * to share the overlap */
    sx_real hertz = sx_minr(world->def.contact_hertz, SX_R(0.25) * inv_h);
    sx_softness moving = sx_make_softness(hertz, world->def.contact_damping_ratio, h);
    sx_softness fixed = sx_make_softness(SX_R(2.0) * hertz, world->def.contact_damping_ratio, h);
    sx_real max_push = world->def.max_correction_speed;
    bool soft = !relax && world->def.contact_hertz > SX_R(0.0);
    sx_solver_body *bodies = world->solver_bodies;
    sx_rw inv_h4 = sx_rw_set1(inv_h);
    /* (a constraint solved one at a time always hands its impulses back) */
    bool hand_back = last && !world->hand_back_later;
    int s, i;
    for (s = 0; s < world->span_count; ++s) {
        const sx_colour_span *span = &world->spans[s];
        int end = span->first + span->count;
        if (span->wide) {
            /* a span is one colour: its bundles share no moved body, and
             * are solved two at a time (four at a time spilled the lanes
             * to the stack and measured slower; eight lanes: one at a
             * time, the pairing measured no faster there) */
            for (i = span->first; SX_LANES <= 4 && i + 2 <= end; i += 2)
                sx_bundle_solve2(world, &world->bundles[i], inv_h4, hand_back);
            for (; i < end; ++i)
                sx_bundle_solve(world, &world->bundles[i], inv_h4, hand_back);
            continue;
        }
        for (i = span->first; i < end; ++i) {
            sx_constraint *c = &world->constraints[i];
            const sx_softness *sft = NULL;
            if (soft) sft = c->both_dynamic ? &moving : &fixed;
            sx_constraint_solve(world, c, bodies, inv_h, sft, max_push, relax, last);
        }
    }
}

/* Grows the solver's arrays for the current contacts and bodies. */
static bool sx_solver_reserve(sx_world *world) {
    /* the bodies, the static entry 0 and the wide passes' sink */
    int contacts = world->contact_count, bodies = 2 * contacts + 2;
    void *p;
    bool ok;
    p = world->solver_bodies;
    ok = sx_grow_array(&p, &world->solver_body_capacity, bodies, sizeof(sx_solver_body));
    world->solver_bodies = (sx_solver_body *)p;
    if (!ok) return false;
    p = world->solver_slots;
    ok = sx_grow_array(&p, &world->solver_slot_capacity, bodies, sizeof(int));
    world->solver_slots = (int *)p;
    if (!ok) return false;
    p = world->body_colour;
    ok = sx_grow_array(&p, &world->body_colour_capacity, bodies, sizeof(int));
    world->body_colour = (int *)p;
    if (!ok) return false;
    /* zeroed: a body slot maps to no solver body until a gather names it */
    p = world->solver_index;
    ok = sx_grow_zeroed(&p, &world->solver_index_capacity, world->body_slots, sizeof(int));
    world->solver_index = (int *)p;
    if (!ok) return false;
    p = world->constraints;
    ok = sx_grow_array(&p, &world->constraint_capacity, contacts, sizeof(sx_constraint));
    world->constraints = (sx_constraint *)p;
    if (!ok) return false;
    /* at most one colour per constraint (and one span without colours) */
    p = world->spans;
    ok = sx_grow_array(&p, &world->span_capacity, contacts + 1, sizeof(sx_colour_span));
    world->spans = (sx_colour_span *)p;
    if (!ok) return false;
    p = world->colour_cursor;
    ok = sx_grow_array(&p, &world->colour_cursor_capacity, contacts + 1, sizeof(int));
    world->colour_cursor = (int *)p;
    if (!ok) return false;
    p = world->colour_items;
    ok = sx_grow_array(&p, &world->colour_item_capacity, contacts, sizeof(sx_colour_item));
    world->colour_items = (sx_colour_item *)p;
    return ok;
}

/* The solver body of a body slot, given one the first time it is named:
 * bodies that do not move share entry 0. */
static int sx_solver_body_of(sx_world *world, int slot) {
    const sx_body_sim *sim = &world->sims[slot];
    int j = world->solver_index[slot];
    if (j != 0 || !sim->moving) return j;
    j = world->solver_body_count++;
    world->solver_index[slot] = j;
    world->solver_slots[j] = slot;
    world->solver_bodies[j].v = sim->v;
    world->solver_bodies[j].w = sim->w;
    world->solver_bodies[j].pad = SX_R(0.0);
    world->body_colour[j] = -1;
    return j;
}

/* The warm start of one constraint on its solver bodies (last sub-step's
 * accumulated impulses applied again). */
static void sx_warm_start(sx_world *world, const sx_constraint *c) {
    sx_solver_body *a = &world->solver_bodies[c->body_a], *b = &world->solver_bodies[c->body_b];
    sx_real ma = c->inv_mass_a, ia = c->inv_inertia_a, mb = c->inv_mass_b, ib = c->inv_inertia_b;
    sx_vec2 n = c->normal, t = sx_cross_vs(n, SX_R(1.0));
    sx_vec2 va = a->v, vb = b->v;
    sx_real wa = a->w, wb = b->w;
    int k;
    for (k = 0; k < c->count; ++k) {
        const sx_constraint_point *p = &c->points[k];
        sx_vec2 impulse = sx_add(sx_scale(n, p->normal_impulse), sx_scale(t, p->tangent_impulse));
        va = sx_mul_sub(va, ma, impulse);
        wa -= ia * (p->normal_impulse * p->rn_a + p->tangent_impulse * p->rt_a);
        vb = sx_mul_add(vb, mb, impulse);
        wb += ib * (p->normal_impulse * p->rn_b + p->tangent_impulse * p->rt_b);
    }
    a->v = va;
    a->w = wa;
    b->v = vb;
    b->w = wb;
}

/* Fills constraint c from contact i (solver bodies a and b). `warm`: the
 * start of a solve: the impact impulses zeroed, and without room for the
 * energy guard the accumulated impulses too. */
static void sx_constraint_fill(sx_world *world, int i, int body_a, int body_b, sx_constraint *c,
                               bool warm) {
    sx_contact *ct = &world->contacts[i];
    const sx_body_sim *a = &world->sims[ct->body_a], *b = &world->sims[ct->body_b];
    int k;
    c->body_a = body_a;
    c->body_b = body_b;
    c->contact = i;
    c->count = ct->count;
    c->normal = ct->normal;
    c->friction = ct->friction;
    c->inv_mass_a = a->inv_mass;
    c->inv_inertia_a = a->inv_inertia;
    c->inv_mass_b = b->inv_mass;
    c->inv_inertia_b = b->inv_inertia;
    for (k = 0; k < ct->count; ++k) {
        const sx_contact_point *src = &ct->points[k];
        sx_constraint_point *p = &c->points[k];
        p->rn_a = sx_cross(src->anchor_a, ct->normal);
        p->rn_b = sx_cross(src->anchor_b, ct->normal);
        p->rt_a = sx_cross(src->anchor_a, sx_cross_vs(ct->normal, SX_R(1.0)));
        p->rt_b = sx_cross(src->anchor_b, sx_cross_vs(ct->normal, SX_R(1.0)));
        p->gap = src->gap;
        p->normal_impulse = src->normal_impulse;
        p->tangent_impulse = src->tangent_impulse;
        p->normal_mass = src->normal_mass;
        p->tangent_mass = src->tangent_mass;
    }
    c->block = ct->block;
    c->block_solve = ct->block_solve;
    c->both_dynamic = a->dynamic && b->dynamic;
    if (warm) {
        for (k = 0; k < ct->count; ++k) {
            ct->points[k].impact_impulse = SX_R(0.0);
            if (!world->groups_ready) {
                /* no room for the energy guard: start cold instead, from
                 * which the passes only take energy out (friction aside) */
                c->points[k].normal_impulse = SX_R(0.0);
                c->points[k].tangent_impulse = SX_R(0.0);
            }
        }
    }
}

/* Contact ct's new gaps into item it's kept constraint or lane (the fill
 * stays otherwise); its impacts start again. */
static void sx_item_put_gaps(sx_world *world, const sx_colour_item *it, sx_contact *ct) {
    int k;
    for (k = 0; k < ct->count; ++k) {
        ct->points[k].impact_impulse = SX_R(0.0);
        if (it->wide)
            world->bundles[it->at / SX_LANES].gap[k][it->at % SX_LANES] = ct->points[k].gap;
        else
            world->constraints[it->at].points[k].gap = ct->points[k].gap;
    }
}

/* Contact ct's accumulated impulses into item it's kept constraint or lane
 * (as sx_constraint_fill reads them: zeros for a cold start). */
static void sx_item_put_impulses(sx_world *world, const sx_colour_item *it,
                                 const sx_contact *ct) {
    int k;
    for (k = 0; k < ct->count; ++k) {
        const sx_contact_point *src = &ct->points[k];
        sx_real ni = src->normal_impulse, ti = src->tangent_impulse;
        if (!world->groups_ready) ni = ti = SX_R(0.0);
        if (it->wide) {
            sx_bundle *u = &world->bundles[it->at / SX_LANES];
            int l = it->at % SX_LANES;
            u->normal_impulse[k][l] = ni;
            u->tangent_impulse[k][l] = ti;
        } else {
            sx_constraint_point *p = &world->constraints[it->at].points[k];
            p->normal_impulse = ni;
            p->tangent_impulse = ti;
        }
    }
}

/* Lane l of frame f as padding: no bodies, zero anchors and bases (a gap
 * of 0, as sx_lane_pad's). */
static void sx_frame_pad(sx_bundle_frame *f, int l) {
    int k;
    f->slot_a[l] = f->slot_b[l] = -1;
    for (k = 0; k < 2; ++k) {
        f->rel_ax[k][l] = f->rel_ay[k][l] = f->rel_bx[k][l] = f->rel_by[k][l] = SX_R(0.0);
        f->base[k][l] = SX_R(0.0);
    }
}

/* Lane l of frame f from contact ct (a one-point contact's second point as
 * padding). */
static void sx_frame_fill(sx_bundle_frame *f, int l, const sx_contact *ct) {
    int k;
    f->slot_a[l] = ct->body_a;
    f->slot_b[l] = ct->body_b;
    for (k = 0; k < 2; ++k) {
        const sx_contact_point *p = &ct->points[k];
        bool real = k < ct->count;
        f->rel_ax[k][l] = real ? p->rel_a.x : SX_R(0.0);
        f->rel_ay[k][l] = real ? p->rel_a.y : SX_R(0.0);
        f->rel_bx[k][l] = real ? p->rel_b.x : SX_R(0.0);
        f->rel_by[k][l] = real ? p->rel_b.y : SX_R(0.0);
        f->base[k][l] = real ? p->base : SX_R(0.0);
    }
}

/* A body's rotation and centre of mass, four reals in a row: one load a
 * lane (sx_bundle_gaps). */
typedef char sx_sim_pose_in_a_row[offsetof(sx_body_sim, center) ==
                                          offsetof(sx_body_sim, xf) + offsetof(sx_xform, q) +
                                              2 * sizeof(sx_real) &&
                                      offsetof(sx_rot, s) == sizeof(sx_real)
                                  ? 1
                                  : -1];

/* Bundle u's gaps at the bodies' current poses from its frame f:
 * sx_current_gap's operations lane by lane, so the same bits as the
 * contacts' gaps. A sub-step's gather reads a contact's 48 bytes of frame
 * here instead of its 232 bytes, and writes no gap back to it. */
static SX_ALWAYS_INLINE void sx_frame_gaps(const sx_world *world, const sx_bundle *u,
                                           const sx_bundle_frame *f, sx_rw *gaps) {
    static const sx_real nowhere[4] = {SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(0.0)};
    const sx_real *pa[SX_LANES], *pb[SX_LANES];
    sx_rw nx = sx_rw_load(u->nx), ny = sx_rw_load(u->ny), ex, ey, ac, as, bc, bs, ax, ay, bx, by;
    int l, k;
    for (l = 0; l < SX_LANES; ++l) {
        /* a padding lane: zero poses (with zero anchors and base, a gap of 0) */
        pa[l] = f->slot_a[l] < 0 ? nowhere : &world->sims[f->slot_a[l]].xf.q.c;
        pb[l] = f->slot_b[l] < 0 ? nowhere : &world->sims[f->slot_b[l]].xf.q.c;
    }
    sx_rw_gather4p(pa, &ac, &as, &ax, &ay);
    sx_rw_gather4p(pb, &bc, &bs, &bx, &by);
    ex = sx_rw_sub(bx, ax);
    ey = sx_rw_sub(by, ay);
    for (k = 0; k < 2; ++k) {
        sx_rw rx = sx_rw_load(f->rel_ax[k]), ry = sx_rw_load(f->rel_ay[k]);
        sx_rw tx = sx_rw_load(f->rel_bx[k]), ty = sx_rw_load(f->rel_by[k]);
        sx_rw rax = sx_rw_sub(sx_rw_mul(ac, rx), sx_rw_mul(as, ry));
        sx_rw ray = sx_rw_add(sx_rw_mul(as, rx), sx_rw_mul(ac, ry));
        sx_rw rbx = sx_rw_sub(sx_rw_mul(bc, tx), sx_rw_mul(bs, ty));
        sx_rw rby = sx_rw_add(sx_rw_mul(bs, tx), sx_rw_mul(bc, ty));
        sx_rw dx = sx_rw_add(ex, sx_rw_sub(rbx, rax)), dy = sx_rw_add(ey, sx_rw_sub(rby, ray));
        sx_rw g = sx_rw_add(sx_rw_load(f->base[k]), sx_rw_add(sx_rw_mul(dx, nx), sx_rw_mul(dy, ny)));
        /* a one-point contact's second point keeps its gap of 0 */
        if (k == 1) g = sx_rw_select(sx_rw_gt(sx_rw_load(u->two), sx_rw_zero()), g, sx_rw_zero());
        gaps[k] = g;
    }
}

static void sx_bundle_gaps(const sx_world *world, sx_bundle *u, const sx_bundle_frame *f) {
    sx_rw gaps[2];
    sx_frame_gaps(world, u, f, gaps);
    sx_rw_store(u->gap[0], gaps[0]);
    sx_rw_store(u->gap[1], gaps[1]);
}

/* The lanes of bundle u (bits, lane l as 1 << l) with a point the position
 * pass may move: a separation not clearly above -slop (the pass looks at
 * each such point itself; the others it would skip). The gaps go into the
 * lanes: the next sub-step's, if the pass moves no body. */
static int sx_bundle_overlaps(const sx_world *world, sx_bundle *u, const sx_bundle_frame *f,
                              sx_real slop) {
    sx_rw gaps[2], lo = sx_rw_set1(-slop);
    sx_frame_gaps(world, u, f, gaps);
    sx_rw_store(u->gap[0], gaps[0]);
    sx_rw_store(u->gap[1], gaps[1]);
    /* a one-point contact's second gap is 0, clear of -slop */
    return (1 << SX_LANES) - 1 -
           sx_mw_bits(sx_mw_and(sx_rw_ge(gaps[0], lo), sx_rw_ge(gaps[1], lo)));
}

/* Lane l of bundle u as padding: zero masses, bodies `sink`. */
static void sx_lane_pad(sx_bundle *u, int l, int sink) {
    int k;
    u->body_a[l] = sink;
    u->body_b[l] = sink;
    u->contact[l] = -1;
    u->nx[l] = u->ny[l] = SX_R(0.0);
    u->friction[l] = SX_R(0.0);
    u->inv_mass_a[l] = u->inv_inertia_a[l] = u->inv_mass_b[l] = u->inv_inertia_b[l] = SX_R(0.0);
    u->two[l] = u->block_solve[l] = SX_R(0.0);
    for (k = 0; k < 2; ++k) {
        u->rn_a[k][l] = u->rn_b[k][l] = u->rt_a[k][l] = u->rt_b[k][l] = SX_R(0.0);
        u->gap[k][l] = u->normal_impulse[k][l] = u->tangent_impulse[k][l] = SX_R(0.0);
        u->normal_mass[k][l] = u->tangent_mass[k][l] = SX_R(0.0);
    }
    u->row_rt_a[l] = u->row_rt_b[l] = u->row_mass[l] = SX_R(0.0);
    u->k11[l] = u->k22[l] = SX_R(1.0);
    u->k12[l] = u->inv11[l] = u->inv12[l] = u->inv22[l] = SX_R(0.0);
}

/* Lane l of bundle u from item it's contact at the start of a solve: the
 * values sx_constraint_fill gives a constraint, written straight into the
 * lane (no constraint copied in between). */
static void sx_lane_fill(sx_world *world, sx_bundle *u, int l, const sx_colour_item *it) {
    sx_contact *ct = &world->contacts[it->contact];
    sx_vec2 n = ct->normal, t = sx_cross_vs(ct->normal, SX_R(1.0));
    /* no room for the energy guard: start cold (sx_constraint_fill) */
    bool cold = !world->groups_ready;
    sx_real rt_a[2] = {SX_R(0.0), SX_R(0.0)}, rt_b[2] = {SX_R(0.0), SX_R(0.0)};
    sx_real tangent_mass[2] = {SX_R(0.0), SX_R(0.0)};
    int k;
    sx_frame_fill(&world->bundle_frames[u - world->bundles], l, ct);
    u->body_a[l] = it->body_a;
    u->body_b[l] = it->body_b;
    u->contact[l] = it->contact;
    u->nx[l] = n.x;
    u->ny[l] = n.y;
    u->friction[l] = ct->friction;
    /* the walk just copied the bodies' masses into the item */
    u->inv_mass_a[l] = it->inv_mass_a;
    u->inv_inertia_a[l] = it->inv_inertia_a;
    u->inv_mass_b[l] = it->inv_mass_b;
    u->inv_inertia_b[l] = it->inv_inertia_b;
    u->two[l] = ct->count == 2 ? SX_R(1.0) : SX_R(0.0);
    u->block_solve[l] = ct->count == 2 && ct->block_solve ? SX_R(1.0) : SX_R(0.0);
    for (k = 0; k < 2; ++k) {
        sx_contact_point *p = &ct->points[k];
        if (k >= ct->count) {
            /* a one-point contact's second point: zeros, never chosen */
            u->rn_a[k][l] = u->rn_b[k][l] = u->rt_a[k][l] = u->rt_b[k][l] = SX_R(0.0);
            u->gap[k][l] = u->normal_impulse[k][l] = u->tangent_impulse[k][l] = SX_R(0.0);
            u->normal_mass[k][l] = u->tangent_mass[k][l] = SX_R(0.0);
            continue;
        }
        rt_a[k] = sx_cross(p->anchor_a, t);
        rt_b[k] = sx_cross(p->anchor_b, t);
        tangent_mass[k] = p->tangent_mass;
        u->rn_a[k][l] = sx_cross(p->anchor_a, n);
        u->rn_b[k][l] = sx_cross(p->anchor_b, n);
        u->rt_a[k][l] = rt_a[k];
        u->rt_b[k][l] = rt_b[k];
        u->gap[k][l] = p->gap;
        u->normal_impulse[k][l] = cold ? SX_R(0.0) : p->normal_impulse;
        u->tangent_impulse[k][l] = cold ? SX_R(0.0) : p->tangent_impulse;
        u->normal_mass[k][l] = p->normal_mass;
        u->tangent_mass[k][l] = p->tangent_mass;
        p->impact_impulse = SX_R(0.0);
    }
    if (ct->count == 2) {
        u->row_rt_a[l] = SX_R(0.5) * (rt_a[0] + rt_a[1]);
        u->row_rt_b[l] = SX_R(0.5) * (rt_b[0] + rt_b[1]);
        u->row_mass[l] = SX_R(0.5) * (tangent_mass[0] + tangent_mass[1]);
    } else {
        u->row_rt_a[l] = u->row_rt_b[l] = u->row_mass[l] = SX_R(0.0);
    }
    if (ct->count == 2 && ct->block_solve) {
        u->k11[l] = ct->block.k11;
        u->k12[l] = ct->block.k12;
        u->k22[l] = ct->block.k22;
        u->inv11[l] = ct->block.inv11;
        u->inv12[l] = ct->block.inv12;
        u->inv22[l] = ct->block.inv22;
    } else {
        u->k11[l] = u->k22[l] = SX_R(1.0);
        u->k12[l] = u->inv11[l] = u->inv12[l] = u->inv22[l] = SX_R(0.0);
    }
}

/* The warm start of every constraint, colour by colour (each body's
 * impulses in contact order, as the passes take them); `gaps`: first the
 * gaps again from the contacts (after an impact pass shifted them). */
static void sx_solver_warm_start(sx_world *world, bool gaps) {
    int s, i, k, l;
    for (s = 0; s < world->span_count; ++s) {
        const sx_colour_span *span = &world->spans[s];
        int end = span->first + span->count;
        for (i = span->first; i < end; ++i) {
            if (span->wide) {
                sx_bundle *u = &world->bundles[i];
                for (l = 0; l < SX_LANES && gaps; ++l) {
                    const sx_contact *ct;
                    if (u->contact[l] < 0) continue;
                    ct = &world->contacts[u->contact[l]];
                    for (k = 0; k < ct->count; ++k)
                        u->gap[k][l] = ct->points[k].gap;
                }
                sx_bundle_warm_start(world->solver_bodies, u);
            } else {
                sx_constraint *c = &world->constraints[i];
                for (k = 0; k < c->count && gaps; ++k)
                    c->points[k].gap = world->contacts[c->contact].points[k].gap;
                sx_warm_start(world, c);
            }
        }
    }
}

/* The gather's refresh of a kept fill's accumulated impulses from the
 * contacts (as sx_constraint_fill reads them), when the energy guard
 * scaled some or the solve starts cold; the gaps the gather's walk
 * refreshed. */
static void sx_solver_refresh(sx_world *world) {
    int i;
    for (i = 0; i < world->fill_count; ++i) {
        const sx_colour_item *it = &world->colour_items[i];
        sx_item_put_impulses(world, it, &world->contacts[it->contact]);
    }
}

/* Ends a gather that could not finish: no solver body stays named. */
static void sx_solver_unname(sx_world *world) {
    int i;
    for (i = 1; i < world->solver_body_count; ++i)
        world->solver_index[world->solver_slots[i]] = 0;
    world->solver_body_count = 0;
    world->constraint_count = 0;
    world->span_count = 0;
    world->fill_valid = false;
}

/* The gather of a pass that does not start a solve (the relax passes) and
 * of soft contacts: one span in contact order, solved one at a time.
 * `warm`: the start of a solve (see sx_solver_gather). */
static void sx_gather_sequential(sx_world *world, bool warm) {
    int i;
    if (warm) sx_groups_build(world);
    world->constraint_count = 0;
    /* one span in contact order, solved one at a time */
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *ct = &world->contacts[i];
        sx_constraint *c;
        int a, b;
        if (!sx_contact_is_active(world, ct)) continue;
        if (warm) sx_update_gaps(world, ct);
        c = &world->constraints[world->constraint_count++];
        a = sx_solver_body_of(world, ct->body_a);
        b = sx_solver_body_of(world, ct->body_b);
        sx_constraint_fill(world, i, a, b, c, warm);
        if (warm) sx_warm_start(world, c);
    }
    world->spans[0].first = 0;
    world->spans[0].count = world->constraint_count;
    world->spans[0].wide = false;
    world->span_count = 1;
    world->fill_valid = false;
}

/* Fills item it into the slot the last fill gave it (lane or constraint). */
static void sx_item_fill(sx_world *world, const sx_colour_item *it) {
    if (it->wide)
        sx_lane_fill(world, &world->bundles[it->at / SX_LANES], it->at % SX_LANES, it);
    else
        sx_constraint_fill(world, it->contact, it->body_a, it->body_b, &world->constraints[it->at],
                           true);
}

/* The colour threshold of the wide passes (see wide_min_colour). */
static int sx_min_colour(const sx_world *world) {
    return world->wide_min_colour > 0 ? world->wide_min_colour : SX_WIDE_MIN_COLOUR;
}

/* Whether item it (as the last walk wrote it) was made from contact ct as
 * it is now: the walk's i-th contact, naming solver bodies a and b, with
 * the same key, parts, point count, masses and kinds. */
static bool sx_item_is(const sx_world *world, const sx_colour_item *it, const sx_contact *ct,
                       int i, int a, int b) {
    const sx_body_sim *sa = &world->sims[ct->body_a], *sb = &world->sims[ct->body_b];
    return it->contact == i && it->key == ct->key && it->part_a == ct->part_a &&
           it->part_b == ct->part_b && it->count == ct->count && it->body_a == a &&
           it->body_b == b && it->inv_mass_a == sa->inv_mass &&
           it->inv_inertia_a == sa->inv_inertia && it->inv_mass_b == sb->inv_mass &&
           it->inv_inertia_b == sb->inv_inertia && it->dynamic_a == sa->dynamic &&
           it->dynamic_b == sb->dynamic;
}

/* Walks the active contacts into the colour items: each point's gap from the
 * current positions, the bodies named in the solver. Returns the item count
 * and sets *same when every item is the one the kept fill was made from
 * (its new gaps then go straight into the fill), *pattern when the items
 * name the solver bodies the fill's did, in the same order (its colours and
 * lane slots still hold). `fill`: each item that keeps the pattern is
 * filled into its slot at once, while its contact is at hand (the start of
 * a solve after a collide; a later fill writes over them if the pattern
 * breaks). */
static int sx_gather_items(sx_world *world, bool fill, bool *same_out, bool *pattern_out,
                           bool *kinds_out, bool *any_held) {
    sx_colour_item *items = world->colour_items;
    int i, n = 0;
    bool same = world->fill_valid && world->fill_serial == world->contact_serial;
    bool pattern = world->fill_valid && world->fill_min_colour == sx_min_colour(world);
    bool kinds = true;
    /* lanes filled after the last collide, with gaps that only their
     * frames give (no impact pass reads the contacts'); their impulses are
     * the contacts' unless the energy guard scaled some or the solve
     * starts cold */
    bool hold = fill && world->fill_valid && world->fill_collides + 1 == world->collides &&
                world->bouncy_contacts == 0;
    bool impulses = !world->fill_fresh || !world->groups_ready;
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *ct = &world->contacts[i];
        const sx_body_sim *sa = &world->sims[ct->body_a], *sb = &world->sims[ct->body_b];
        sx_colour_item *it = &items[n];
        int a, b;
        bool held;
        if (!sx_contact_is_active(world, ct)) continue;
        a = sx_solver_body_of(world, ct->body_a);
        b = sx_solver_body_of(world, ct->body_b);
        ++n;
        if (same && n <= world->fill_count && sx_item_is(world, it, ct, i, a, b)) {
            /* the new gaps into the kept fill, while the contact is at hand */
            sx_update_gaps(world, ct);
            sx_item_put_gaps(world, it, ct);
            continue;
        }
        same = false;
        /* the colours follow from the solver bodies alone; the energy
         * guard's groups from them and the bodies' kinds */
        pattern = pattern && n <= world->fill_count && it->body_a == a && it->body_b == b;
        /* (read only where the pattern holds: past the fill's items they
         * were never written) */
        kinds = kinds && pattern && it->dynamic_a == sa->dynamic && it->dynamic_b == sb->dynamic;
        /* a wide lane filled after the collide before this one stands for
         * the same contact in the same slot, with the same friction, whose
         * manifold this collide kept (held): its levers, masses and normal
         * are the search's, which the kept manifold's tolerance says still
         * nearly hold; its gaps follow the bodies from its frame
         * (sx_solver_gather) */
        held = hold && pattern && it->wide && ct->held && it->friction == ct->friction &&
               sx_item_is(world, it, ct, i, a, b);
        *any_held = *any_held || held;
        /* (a held contact's gaps are read by nothing before the next walk,
         * bar a fill from scratch, which updates them itself) */
        if (!held) sx_update_gaps(world, ct);
        it->key = ct->key;
        it->contact = i;
        it->part_a = ct->part_a;
        it->part_b = ct->part_b;
        it->count = ct->count;
        it->body_a = a;
        it->body_b = b;
        it->inv_mass_a = sa->inv_mass;
        it->inv_inertia_a = sa->inv_inertia;
        it->inv_mass_b = sb->inv_mass;
        it->inv_inertia_b = sb->inv_inertia;
        it->dynamic_a = sa->dynamic;
        it->dynamic_b = sb->dynamic;
        it->friction = ct->friction;
        if (held && impulses) sx_item_put_impulses(world, it, ct);
        if (fill && pattern && !held) sx_item_fill(world, it);
    }
    *same_out = same;
    *pattern_out = pattern && n == world->fill_count;
    *kinds_out = kinds;
    return n;
}

/* Colours the n items in contact order (one past the last colour either
 * moved body has had: the wide passes above say why) and places each colour:
 * as bundles of SX_LANES lanes when it has at least SX_WIDE_MIN_COLOUR, else
 * as constraints solved one at a time. Returns the colour count. */
static int sx_colour_items(sx_world *world, int n) {
    sx_colour_item *items = world->colour_items;
    int i, colours = 0;
    int min_colour = sx_min_colour(world);
    for (i = 0; i < n; ++i) {
        sx_colour_item *it = &items[i];
        int ca = it->body_a != 0 ? world->body_colour[it->body_a] : -1;
        int cb = it->body_b != 0 ? world->body_colour[it->body_b] : -1;
        it->colour = (ca > cb ? ca : cb) + 1;
        if (it->body_a != 0) world->body_colour[it->body_a] = it->colour;
        if (it->body_b != 0) world->body_colour[it->body_b] = it->colour;
        if (it->colour >= colours) colours = it->colour + 1;
    }
    for (i = 0; i < colours; ++i)
        world->colour_cursor[i] = 0;
    for (i = 0; i < n; ++i)
        world->colour_cursor[items[i].colour]++;
    for (i = 0; i < colours; ++i) {
        sx_colour_span *span = &world->spans[i];
        int count = world->colour_cursor[i];
        span->wide = count >= min_colour;
        if (span->wide) {
            span->first = world->bundle_count;
            span->count = (count + SX_LANES - 1) / SX_LANES;
            world->bundle_count += span->count;
            world->colour_cursor[i] = SX_LANES * span->first;
        } else {
            span->first = world->constraint_count;
            span->count = count;
            world->constraint_count += count;
            world->colour_cursor[i] = span->first;
        }
    }
    world->span_count = colours;
    return colours;
}

/* Fills the placed colours' constraints and lanes (padding lanes write to
 * a sink body), then makes neighbouring colours of the same kind one span;
 * false when the bundles could not grow. */
static bool sx_fill_colours(sx_world *world, int n, int colours, bool held) {
    sx_colour_item *items = world->colour_items;
    int i, k, sink;
    void *p;
    p = world->bundles;
    if (!sx_grow_array(&p, &world->bundle_capacity, world->bundle_count, sizeof(sx_bundle)))
        return false;
    world->bundles = (sx_bundle *)p;
    p = world->bundle_frames;
    if (!sx_grow_array(&p, &world->bundle_frame_capacity, world->bundle_count,
                       sizeof(sx_bundle_frame)))
        return false;
    world->bundle_frames = (sx_bundle_frame *)p;
    sink = world->solver_body_count;
    world->solver_bodies[sink].v = sx_v2_zero();
    world->solver_bodies[sink].w = SX_R(0.0);
    world->solver_bodies[sink].pad = SX_R(0.0);
    for (i = 0; i < n; ++i) {
        sx_colour_item *it = &items[i];
        /* (again the same bits, unless the walk held the item's lane) */
        if (held) sx_update_gaps(world, &world->contacts[it->contact]);
        it->at = world->colour_cursor[it->colour]++;
        it->wide = world->spans[it->colour].wide;
        if (it->wide) {
            sx_lane_fill(world, &world->bundles[it->at / SX_LANES], it->at % SX_LANES, it);
        } else {
            sx_constraint_fill(world, it->contact, it->body_a, it->body_b,
                               &world->constraints[it->at], true);
        }
    }
    for (i = 0; i < colours; ++i) {
        const sx_colour_span *span = &world->spans[i];
        int at;
        if (!span->wide) continue;
        for (at = world->colour_cursor[i]; at < SX_LANES * (span->first + span->count); ++at) {
            sx_lane_pad(&world->bundles[at / SX_LANES], at % SX_LANES, sink);
            sx_frame_pad(&world->bundle_frames[at / SX_LANES], at % SX_LANES);
        }
    }
    /* colours in a row solved one at a time are one span for the passes
     * (their constraints follow each other; a stack is one constraint per
     * colour); a wide colour stays a span of its own, as the passes solve
     * its bundles two at a time, which only bundles of one colour allow */
    for (i = 0, k = 0; i < colours; ++i) {
        const sx_colour_span *span = &world->spans[i];
        if (k > 0 && !span->wide && !world->spans[k - 1].wide)
            world->spans[k - 1].count += span->count;
        else
            world->spans[k++] = *span;
    }
    world->span_count = k;
    return true;
}

/* The gather of a sub-step after the fill's, nothing it was made from
 * changed since (same collide, same solver_epoch): the solver bodies the
 * fill's walk named, and each item's new gaps into the fill, without the
 * walk over every contact that checks each item. */
static void sx_gather_kept(sx_world *world) {
    const sx_colour_item *items = world->colour_items;
    /* Without restitution the contacts' own gaps and impact impulses are
     * not read before the next walk refreshes them (the impact pass skips
     * its work, and the impulses stay 0): the lanes' gaps come from their
     * frames, the one-at-a-time constraints' from their contacts. */
    bool frames = world->bouncy_contacts == 0;
    int i, j;
    /* solver_index stays 0: only a walk's naming reads it */
    for (j = 1; j < world->fill_body_count; ++j) {
        int slot = world->solver_slots[j];
        world->solver_bodies[j].v = world->sims[slot].v;
        world->solver_bodies[j].w = world->sims[slot].w;
        world->solver_bodies[j].pad = SX_R(0.0);
    }
    world->solver_body_count = world->fill_body_count;
    if (frames) {
        for (i = 0; i < world->constraint_count; ++i) {
            sx_constraint *c = &world->constraints[i];
            sx_contact *ct = &world->contacts[c->contact];
            sx_update_gaps(world, ct);
            for (j = 0; j < ct->count; ++j)
                c->points[j].gap = ct->points[j].gap;
        }
        /* (the position pass that found them moved no body since) */
        for (i = 0; i < world->bundle_count && !world->lane_gaps_current; ++i)
            sx_bundle_gaps(world, &world->bundles[i], &world->bundle_frames[i]);
        return;
    }
    for (i = 0; i < world->fill_count; ++i) {
        const sx_colour_item *it = &items[i];
        sx_contact *ct = &world->contacts[it->contact];
        sx_update_gaps(world, ct);
        sx_item_put_gaps(world, it, ct);
    }
}

/* Fills the n items into the colours and lane slots the last fill gave
 * them (the same pattern of solver bodies), unless the walk did (`filled`),
 * and the padding: what sx_fill_colours would write, without colouring and
 * placing again. */
static void sx_refill_colours(sx_world *world, int n, bool filled) {
    int i, l, sink = world->solver_body_count;
    world->solver_bodies[sink].v = sx_v2_zero();
    world->solver_bodies[sink].w = SX_R(0.0);
    world->solver_bodies[sink].pad = SX_R(0.0);
    for (i = 0; i < n && !filled; ++i)
        sx_item_fill(world, &world->colour_items[i]);
    for (i = 0; i < world->bundle_count; ++i) {
        for (l = 0; l < SX_LANES; ++l) {
            if (world->bundles[i].contact[l] < 0) {
                sx_lane_pad(&world->bundles[i], l, sink);
                sx_frame_pad(&world->bundle_frames[i], l);
            }
        }
    }
}

/* Notes the fill the arrays now hold (n items). */
static void sx_fill_made(sx_world *world, int n) {
    world->fill_serial = world->contact_serial;
    world->fill_collides = world->collides;
    world->fill_epoch = world->solver_epoch;
    world->fill_count = n;
    world->fill_body_count = world->solver_body_count;
    world->fill_min_colour = sx_min_colour(world);
    world->fill_valid = true;
}

/* Copies the active contacts and their bodies' velocities into the solver's
 * arrays; false when they could not grow (nothing copied). `warm`: the
 * start of a solve: each point's gap from the current positions, the
 * impact impulses zeroed, the constraints coloured for the wide passes
 * (rigid contacts), and the warm start on the solver bodies only (the
 * bodies keep their own velocities for the impact pass). The colours and
 * lanes of the last gather are kept while every item is unchanged. */
static bool sx_solver_gather(sx_world *world, bool warm) {
    int n;
    bool same, pattern = false, collide = false, kinds = false, held = false;
    bool kept = warm && !(world->def.contact_hertz > SX_R(0.0)) && world->fill_valid &&
                world->fill_serial == world->contact_serial &&
                world->fill_epoch == world->solver_epoch;
    int i;
    /* a kept fill goes on from the impulses in its lanes; any other gather
     * reads the contacts' */
    if (!kept) sx_solver_hand_back(world);
    if (!sx_solver_reserve(world)) return false;
    world->solver_bodies[0].v = sx_v2_zero();
    world->solver_bodies[0].w = SX_R(0.0);
    world->solver_bodies[0].pad = SX_R(0.0);
    world->solver_body_count = 1;
    if (!warm || world->def.contact_hertz > SX_R(0.0)) {
        sx_gather_sequential(world, warm);
        world->solver_gathered = true;
        return true;
    }
    if (kept) {
        sx_gather_kept(world);
        n = world->fill_count;
        same = true;
    } else {
        /* after a collide: the items are filled as the walk goes, which
         * needs room for the groups (a cold start without it); the groups
         * are linked after it, unless the last link still stands (a resting
         * pile's contacts name the same bodies step after step) */
        collide = !(world->fill_valid && world->fill_serial == world->contact_serial);
        if (collide) sx_groups_reserve(world);
        n = sx_gather_items(world, collide, &same, &pattern, &kinds, &held);
        if (collide && !sx_groups_stand(world, pattern, kinds)) sx_groups_link(world);
    }
    if (same && n == world->fill_count) {
        /* the energy guard's groups follow from the items too: kept, unless
         * the last build found no room */
        if (!world->groups_ready) sx_groups_build(world);
        if (!world->fill_fresh || !world->groups_ready) sx_solver_refresh(world);
        world->fill_epoch = world->solver_epoch;
        sx_solver_warm_start(world, false);
        world->solver_gathered = true;
        return true;
    }
    if (!collide) sx_groups_build(world);
    if (pattern) {
        sx_refill_colours(world, n, collide);
        /* the held lanes' gaps from their frames (the others' the same
         * bits as their contacts': sx_frame_gaps) */
        for (i = 0; i < world->bundle_count && held; ++i)
            sx_bundle_gaps(world, &world->bundles[i], &world->bundle_frames[i]);
    } else {
        world->fill_valid = false;
        world->constraint_count = 0;
        world->bundle_count = 0;
        if (!sx_fill_colours(world, n, sx_colour_items(world, n), held)) {
            sx_solver_unname(world);
            return false;
        }
    }
    sx_fill_made(world, n);
    sx_solver_warm_start(world, false);
    world->solver_gathered = true;
    return true;
}

/* The velocities of the solver bodies into the dynamic bodies (static and
 * kinematic bodies keep theirs: for them the passes only added 0 x impulse,
 * which is rounding at best and NaN from an overflow), within the speed
 * limit of sub-step h (an impulse at its bound on a light body overflows
 * its velocity): the bodies the passes changed are limited here, so the
 * step need not walk every body again. */
static void sx_solver_store_velocities(sx_world *world, sx_real h) {
    sx_half_limit l = sx_half_limit_of(h);
    int i;
    for (i = 1; i < world->solver_body_count; ++i) {
        sx_body_sim *sim = &world->sims[world->solver_slots[i]];
        if (sim->dynamic) {
            sim->v = world->solver_bodies[i].v;
            sim->w = world->solver_bodies[i].w;
            sx_limit_speed_past_half(sim, &l);
        }
    }
}

/* Hands the velocities of the dynamic bodies back (static and kinematic
 * bodies keep theirs) and ends the gather; the last pass handed the
 * accumulated impulses to the contacts (warm start of the next sub-step,
 * contact reports). */
static void sx_solver_scatter(sx_world *world, sx_real h) {
    int i;
    sx_solver_store_velocities(world, h);
    for (i = 1; i < world->solver_body_count; ++i)
        world->solver_index[world->solver_slots[i]] = 0;
    world->solver_body_count = 0;
    world->solver_gathered = false;
}

/* Gathers (unless the start of the solve did), makes `passes` passes, scatters;
 * false when the solver's arrays could not grow (no pass made). */
static bool sx_solver_run(sx_world *world, sx_real h, int passes, bool relax) {
    int it;
    if (!world->solver_gathered) {
        if (passes <= 0) return true;
        if (!sx_solver_gather(world, false)) return false;
    }
    for (it = 0; it < passes; ++it)
        sx_constraints_pass(world, h, relax, it == passes - 1);
    /* the last pass handed every impulse back, or left the wide lanes'
     * where they are: either way a kept fill holds the ones to go on from */
    if (passes > 0) {
        world->fill_fresh = true;
        world->impulses_in_lanes = world->hand_back_later && world->bundle_count > 0;
    }
    sx_solver_scatter(world, h);
    return true;
}

bool sx_contacts_gather(sx_world *world) {
    return sx_solver_gather(world, true) && world->groups_ready;
}

/* Turns a body by a small angle (the pseudo-impulse's rotation) and keeps
 * its origin consistent with the moved centre of mass. */
static void sx_move_body(sx_body_sim *b, sx_vec2 dp, sx_real angle) {
    b->center = sx_add(b->center, dp);
    if (angle != SX_R(0.0)) b->xf.q = sx_rot_integrate(b->xf.q, angle);
    sx_body_sync_origin(b);
}

/* The positional correction of contact c's points, one after the other
 * (each sees the moves of the one before); whether it moved a body. */
static bool sx_push_contact(sx_world *world, sx_contact *c, sx_real slop, sx_real beta,
                            sx_real max_move) {
    sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
    sx_vec2 n = c->normal;
    bool moved = false;
    int k;
    for (k = 0; k < c->count; ++k) {
        const sx_contact_point *p = &c->points[k];
        sx_real s = sx_current_gap(a, b, n, p), correction, lambda, rna, rnb;
        if (s >= -slop || !(p->normal_mass > SX_R(0.0))) continue;
        moved = true;
        correction = sx_maxr(beta * (s + slop), -max_move);
        rna = sx_cross(p->anchor_a, n);
        rnb = sx_cross(p->anchor_b, n);
        lambda = -correction * p->normal_mass;
        if (!sx_is_finite(lambda)) {
            /* an effective mass near SX_REAL_MAX (a body of that mass
             * against a static one): the pseudo-impulse overflows, and
             * inf x 1 / mass made the position -inf. The same moves, as
             * fractions of 1 / mass. */
            sx_real kn = ma + mb + ia * rna * rna + ib * rnb * rnb;
            if (!(kn > SX_R(0.0))) continue;
            if (ma > SX_R(0.0) || ia > SX_R(0.0))
                sx_move_body(a, sx_scale(n, correction * (ma / kn)), correction * (ia * rna / kn));
            if (mb > SX_R(0.0) || ib > SX_R(0.0))
                sx_move_body(b, sx_scale(n, -correction * (mb / kn)), -correction * (ib * rnb / kn));
            continue;
        }
        if (ma > SX_R(0.0) || ia > SX_R(0.0))
            sx_move_body(a, sx_scale(n, -lambda * ma), -ia * lambda * rna);
        if (mb > SX_R(0.0) || ib > SX_R(0.0))
            sx_move_body(b, sx_scale(n, lambda * mb), ib * lambda * rnb);
    }
    return moved;
}

/* One position pass in the order of the solve's colours, while its fill
 * still holds the active contacts: the same moves as in contact order (a
 * colour comes after every colour whose contacts share a moved body with
 * it, and the contacts of a colour share none), and the wide colours'
 * lanes find their separations four or eight at a time from their frames,
 * so only contacts with a point near overlap are looked at one by one. */
static bool sx_push_by_colour(sx_world *world, sx_real slop, sx_real beta, sx_real max_move) {
    bool moved = false;
    int s, i, l;
    for (s = 0; s < world->span_count; ++s) {
        const sx_colour_span *span = &world->spans[s];
        int end = span->first + span->count;
        for (i = span->first; i < end; ++i) {
            if (span->wide) {
                sx_bundle *u = &world->bundles[i];
                int lanes = sx_bundle_overlaps(world, u, &world->bundle_frames[i], slop);
                for (l = 0; lanes != 0; ++l, lanes >>= 1) {
                    if ((lanes & 1) && sx_push_contact(world, &world->contacts[u->contact[l]], slop,
                                                       beta, max_move))
                        moved = true;
                }
            } else if (sx_push_contact(world, &world->contacts[world->constraints[i].contact], slop,
                                       beta, max_move)) {
                moved = true;
            }
        }
    }
    return moved;
}

/* The rigid contacts' positional correction: each overlap beyond the slop
 * is reduced by correction_factor of it (at most max_correction_speed h per
 * sub-step) by moving the two bodies along the normal, split by inverse
 * mass and inertia (a pseudo-impulse: velocities, and so the kinetic
 * energy, untouched). */
static void sx_contacts_push_out(sx_world *world, sx_real h, int passes) {
    sx_real slop = world->linear_slop, beta = world->def.correction_factor, max_move;
    /* the fill of this sub-step's solve, unchanged since (the colours name
     * exactly the active contacts) */
    bool by_colour = world->fill_valid && world->fill_serial == world->contact_serial &&
                     world->fill_epoch == world->solver_epoch;
    int it, i;
    if (passes <= 0) return;
    max_move = world->def.max_correction_speed * h / (sx_real)passes;
    for (it = 0; it < passes; ++it) {
        if (by_colour) {
            /* the last pass's gaps stand if it moved nothing */
            world->lane_gaps_current = !sx_push_by_colour(world, slop, beta, max_move);
            continue;
        }
        for (i = 0; i < world->contact_count; ++i) {
            sx_contact *c = &world->contacts[i];
            if (sx_contact_is_active(world, c)) sx_push_contact(world, c, slop, beta, max_move);
        }
    }
}

bool sx_contacts_solve(sx_world *world, sx_real h, int passes) {
    int i;
    if (!world->solver_gathered) return false;
    if (world->impact_shifts_pending) {
        /* the impact pass changed velocities and gaps: the warm start of the
         * gather is redone on the velocities the impacts left */
        for (i = 1; i < world->solver_body_count; ++i) {
            const sx_body_sim *sim = &world->sims[world->solver_slots[i]];
            world->solver_bodies[i].v = sim->v;
            world->solver_bodies[i].w = sim->w;
        }
        sx_solver_warm_start(world, true);
    }
    /* the energy guard measures from the velocities before the warm start
     * (and its sums start here: one walk of the members fewer) */
    for (i = 0; i < world->group_member_count && world->groups_ready; ++i) {
        int slot = world->group_members[i];
        sx_group_body *g = &world->group_bodies[slot];
        g->v = world->sims[slot].v;
        g->w = world->sims[slot].w;
        g->f = SX_R(0.0);
        g->a = SX_R(0.0);
        g->credit_sum = SX_R(0.0);
        g->mass_sum = SX_R(0.0);
    }
    return sx_solver_run(world, h, passes, false);
}

bool sx_contacts_relax(sx_world *world, sx_real h, int passes) {
    int i;
    if (!(world->def.contact_hertz > SX_R(0.0))) {
        sx_contacts_push_out(world, h, passes);
        return true;
    }
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        if (sx_contact_is_active(world, c)) sx_update_gaps(world, c);
    }
    return sx_solver_run(world, h, passes, true);
}

void sx_contacts_free(sx_world *world) {
    sx_free(world->solver_bodies, (size_t)world->solver_body_capacity * sizeof(sx_solver_body));
    sx_free(world->solver_slots, (size_t)world->solver_slot_capacity * sizeof(int));
    sx_free(world->solver_index, (size_t)world->solver_index_capacity * sizeof(int));
    sx_free(world->constraints, (size_t)world->constraint_capacity * sizeof(sx_constraint));
    sx_free(world->spans, (size_t)world->span_capacity * sizeof(sx_colour_span));
    sx_free(world->bundles, (size_t)world->bundle_capacity * sizeof(sx_bundle));
    sx_free(world->bundle_frames, (size_t)world->bundle_frame_capacity * sizeof(sx_bundle_frame));
    sx_free(world->colour_items, (size_t)world->colour_item_capacity * sizeof(sx_colour_item));
    sx_free(world->colour_cursor, (size_t)world->colour_cursor_capacity * sizeof(int));
    sx_free(world->body_colour, (size_t)world->body_colour_capacity * sizeof(int));
    sx_free(world->group_bodies, (size_t)world->group_body_capacity * sizeof(sx_group_body));
    sx_free(world->group_members, (size_t)world->group_member_capacity * sizeof(int));
    sx_free(world->group_slots, (size_t)world->group_slot_capacity * sizeof(int));
    sx_free(world->impact_bodies, (size_t)world->impact_body_capacity * sizeof(sx_impact_body));
    sx_free(world->impact_adjacency, (size_t)world->impact_adjacency_capacity * sizeof(int));
    sx_free(world->impact_heap, (size_t)world->impact_heap_capacity * sizeof(int));
    sx_free(world->impact_contacts,
            (size_t)world->impact_contact_capacity * sizeof(sx_impact_contact));
}
