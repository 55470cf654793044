/* sepax — the impact pass: restitution resolved one impact at a time, in
 * time-of-impact order, before each sub-step's velocity iterations (the
 * design and why below). */
#include <string.h>

#include "contact_math.h"
#include "world_array.h"
#include "world_body.h"
#include "world_contact.h"
#include "world_internal.h"

/* ---- impacts ----------------------------------------------------------------
 *
 * Restitution is resolved by an impact pass that runs once per sub-step,
 * before the warm start and the velocity iterations. Why a pass of its
 * own: the velocity iterations solve every contact of the sub-step at once,
 * and a simultaneous solve cannot produce a Newton's cradle. With the
 * speculative margin (20 mm) wider than the cradle's 1 mm gaps, all four
 * contacts of the row exist from the first sub-step; three of them have no
 * approach speed yet, so they get no restitution, and the row shares the
 * impulse inelastically (the last ball left at 0.63 m/s with 46 % of the
 * energy). Real impacts happen one after the other, in time order, and each
 * one changes the velocities that decide the next. So the pass:
 *
 * - takes the contacts that approach faster than the restitution threshold
 *   and close their gap within the sub-step (approach x h >= gap), with the
 *   time of impact gap / approach (0 when touching or overlapping);
 * - resolves them in order of that time (a heap; ties by contact index, so
 *   the order is deterministic), each contact at most SX_IMPACTS_PER_CONTACT
 *   times per sub-step, and after each one re-examines the contacts of its
 *   two bodies (itself included) with the new velocities: the impulse runs
 *   down a chain (the cradle: 1-2, then 2-3, then 3-4, all within the
 *   sub-step in which 0-1 touches), and a second wave can follow the first;
 * - resolves a contact as a block: both points of a two-point manifold (a box
 *   landing flat) at once, by the same 2x2 complementarity solve as the
 *   iterations, asking each approaching point to leave at e times its
 *   approach speed (points slower than the threshold: to stop), so a flat
 *   landing bounces flat with no spurious spin; then Coulomb friction on the
 *   impulse of the impact (|t| <= mu x normal impulse);
 * - keeps these impulses apart from the iterations' accumulators: the
 *   iterations clamp their own sums and cannot take the rebound back (the old
 *   design, a restitution pass after the iterations, had to fight them, and
 *   deferred speculative impacts to the next sub-step, which made the rebound
 *   depend on where the impact fell on the sub-step grid);
 * - corrects positions for the time of impact: a body that changes velocity
 *   by dv at time t of the sub-step really moved with its old velocity until
 *   t, so integrating with the new one over the whole sub-step puts it off
 *   by dv x t. The pass records the shift -dv x t (and -dw x t) per body and
 *   sx_world_integrate applies it, so a ball that meets the ground 2 cm below
 *   it rebounds from the ground and not from 2 cm above it (the bounce
 *   height stays right at any sub-step count). The shifted start positions
 *   also give the exact times of the later impacts of a chain, and the gaps
 *   the iterations aim at are updated with the shifts.
 *
 * Energy: an impact asks only approaching points to leave at e x their
 * approach speed, so for e <= 1 the kinetic energy cannot grow (the change is
 * 1/2 sum x_i (1 - e_i) vn_i <= 0 over the points that push); the friction
 * impulse only reduces the sliding speed. That holds for each impulse on the
 * velocities it meets, so for any chain of them at any mass ratio, as long
 * as those are the bodies' own velocities. Hence the pass runs before the
 * warm start: after it, a light body pinched under a heavy one carried the
 * last sub-step's support impulses as velocity towards the heavy one, the
 * pass bounced that, and the iterations could not take back a rebound (the
 * bounced impulse doubled every sub-step). Momentum: every impulse acts on
 * both bodies, equal and opposite. Cost: one scan of the contacts with
 * restitution per sub-step; the heap and the contact lists per body are built
 * only in sub-steps that have an impact. Known limits: an exchange beyond
 * the per-contact cap within one sub-step is left to the (inelastic)
 * iterations; positions are corrected for linear motion only (no gravity or
 * rotation within the sub-step). */

/* How many times the impact pass may resolve one contact within a sub-step.
 * Once is enough for a single wave down a row; a second wave (two balls of a
 * cradle swung together) meets contacts the first one already resolved. The
 * cap is what guarantees the pass ends (a ball jammed between two walls would
 * otherwise bounce between them for ever). */
#define SX_IMPACTS_PER_CONTACT 4

/* The approach speed from which contacts bounce: the restitution threshold,
 * less a relative 1e-4. An approach equal to the threshold must bounce, but
 * the speed computed along a contact normal carries round-off (a 1 m/s
 * impact measured along a float normal of length 1 - 6e-8 is 0.99999994
 * m/s); the margin is far below anything physical. */
static sx_real sx_bounce_threshold(const sx_world *world) {
    return world->def.restitution_threshold * (SX_R(1.0) - SX_R(1e-4));
}

static bool sx_movable(const sx_body_sim *b) {
    return b->inv_mass > SX_R(0.0) || b->inv_inertia > SX_R(0.0);
}

/* The separation of point p at the start positions moved by the impact
 * shifts of its bodies (linearised in the turn). */
static sx_real sx_shifted_gap(const sx_world *world, const sx_contact *c,
                              const sx_contact_point *p) {
    const sx_impact_body *a = &world->impact_bodies[c->body_a];
    const sx_impact_body *b = &world->impact_bodies[c->body_b];
    sx_vec2 d = sx_sub(sx_add(b->shift, sx_cross_sv(b->turn, p->anchor_b)),
                       sx_add(a->shift, sx_cross_sv(a->turn, p->anchor_a)));
    return p->gap + sx_dot(d, c->normal);
}

/* True when contact c has a point approaching at the restitution threshold
 * or faster that closes its gap within the sub-step; *time = the earliest
 * such point's time of impact (0 .. h). `shifted`: read the gaps with the
 * impact shifts (false before the first impact of the sub-step). */
static bool sx_impact_time(const sx_world *world, const sx_contact *c, sx_real h, bool shifted,
                           sx_real *time) {
    const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    sx_real threshold = sx_bounce_threshold(world);
    bool found = false;
    int k;
    for (k = 0; k < c->count; ++k) {
        const sx_contact_point *p = &c->points[k];
        sx_real approach = -sx_point_speed(a->v, a->w, b->v, b->w, p->anchor_a, p->anchor_b, c->normal);
        sx_real gap, t;
        if (!(approach > SX_R(0.0)) || approach < threshold) continue;
        gap = shifted ? sx_shifted_gap(world, c, p) : p->gap;
        if (approach * h < gap) continue;
        t = gap > SX_R(0.0) ? gap / approach : SX_R(0.0);
        if (!found || t < *time) *time = t;
        found = true;
    }
    return found;
}

/* Resolves the impact of contact c at time t of the sub-step: every point
 * that approaches and closes its gap within the sub-step leaves at e times
 * its approach speed (e = 0 for points slower than the threshold), both
 * points together when the manifold's block is well conditioned; then
 * friction; then the bodies' time-of-impact shifts. */
static void sx_resolve_impact(sx_world *world, sx_contact *c, sx_real h, sx_real t) {
    sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
    sx_impact_body *sa = &world->impact_bodies[c->body_a], *sb = &world->impact_bodies[c->body_b];
    sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
    sx_real threshold = sx_bounce_threshold(world), e = c->restitution;
    /* the rebound speed stays within the step's speed limit (world.h): a
     * restitution of 1e19 would otherwise fling the bodies (and their
     * time-of-impact shifts) out of range, or overflow */
    sx_real max_rebound = sx_minr(SX_HUGE / h, SX_REAL_MAX), rebound[2] = {SX_R(0.0), SX_R(0.0)};
    sx_vec2 n = c->normal, tangent = sx_cross_vs(n, SX_R(1.0));
    sx_vec2 va = a->v, vb = b->v, va0 = a->v, vb0 = b->v;
    sx_real wa = a->w, wb = b->w, wa0 = a->w, wb0 = b->w;
    sx_real bias[2] = {SX_R(0.0), SX_R(0.0)}, x[2] = {SX_R(0.0), SX_R(0.0)};
    bool closing[2] = {false, false}, solved = false;
    int k;
    for (k = 0; k < c->count; ++k) {
        sx_contact_point *p = &c->points[k];
        sx_real vn = sx_point_speed(va, wa, vb, wb, p->anchor_a, p->anchor_b, n), approach = -vn;
        if (!(approach > SX_R(0.0)) || approach * h < sx_shifted_gap(world, c, p)) continue;
        closing[k] = true;
        /* leave at e x approach: vn' = vn + (K x)_k >= e x approach, i.e.
         * K x + bias >= 0 with bias = vn - e x approach */
        if (approach >= threshold) rebound[k] = sx_minr(e * approach, max_rebound);
        bias[k] = vn - rebound[k];
    }
    if (c->count == 2 && closing[0] && closing[1] && c->block_solve) {
        if (sx_solve_lcp2(&c->block, bias[0], bias[1], &x[0], &x[1]) && x[0] <= SX_IMPULSE_LIMIT &&
            x[1] <= SX_IMPULSE_LIMIT) {
            sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, c->points[0].anchor_a, c->points[0].anchor_b, sx_scale(n, x[0]));
            sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, c->points[1].anchor_a, c->points[1].anchor_b, sx_scale(n, x[1]));
            solved = true;
        }
    }
    if (!solved) {
        /* one point, or an ill-conditioned pair: one point after the other,
         * each a single Newton impact on the current velocities */
        for (k = 0; k < c->count; ++k) {
            sx_contact_point *p = &c->points[k];
            sx_real approach;
            if (!closing[k]) continue;
            approach = -sx_point_speed(va, wa, vb, wb, p->anchor_a, p->anchor_b, n);
            if (!(approach > SX_R(0.0))) continue;
            if (approach >= threshold && !(e * approach <= max_rebound)) {
                x[k] = p->normal_mass * (approach + max_rebound);
            } else {
                x[k] = p->normal_mass * (SX_R(1.0) + (approach >= threshold ? e : SX_R(0.0))) *
                       approach;
            }
            x[k] = sx_bounded_impulse(x[k]);
            sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, p->anchor_a, p->anchor_b, sx_scale(n, x[k]));
        }
    }
    for (k = 0; k < c->count; ++k) {
        sx_contact_point *p = &c->points[k];
        sx_real limit = c->friction * x[k], lambda;
        p->impact_impulse += x[k];
        if (!(limit > SX_R(0.0))) continue;
        lambda = -p->tangent_mass * sx_point_speed(va, wa, vb, wb, p->anchor_a, p->anchor_b, tangent);
        lambda = sx_bounded_impulse(sx_clampr(lambda, -limit, limit));
        sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, p->anchor_a, p->anchor_b, sx_scale(tangent, lambda));
    }
    /* until t the bodies moved with their old velocities */
    sa->shift = sx_mul_sub(sa->shift, t, sx_sub(va, va0));
    sa->turn -= t * (wa - wa0);
    sb->shift = sx_mul_sub(sb->shift, t, sx_sub(vb, vb0));
    sb->turn -= t * (wb - wb0);
    sx_store_velocities(a, va, wa, b, vb, wb);
}

/* The heap of pending impacts, ordered by (time, contact index). */
static bool sx_impact_before(const sx_impact_contact *ic, int i, int j) {
    return ic[i].time < ic[j].time || (ic[i].time == ic[j].time && i < j);
}

static void sx_heap_place(sx_world *world, int pos, int contact) {
    world->impact_heap[pos] = contact;
    world->impact_contacts[contact].where = pos;
}

static void sx_heap_up(sx_world *world, int pos) {
    int contact = world->impact_heap[pos];
    while (pos > 0) {
        int parent = (pos - 1) / 2, other = world->impact_heap[parent];
        if (!sx_impact_before(world->impact_contacts, contact, other)) break;
        sx_heap_place(world, pos, other);
        pos = parent;
    }
    sx_heap_place(world, pos, contact);
}

static void sx_heap_down(sx_world *world, int pos, int count) {
    int contact = world->impact_heap[pos];
    for (;;) {
        int child = 2 * pos + 1, pick;
        if (child >= count) break;
        pick = world->impact_heap[child];
        if (child + 1 < count &&
            sx_impact_before(world->impact_contacts, world->impact_heap[child + 1], pick)) {
            pick = world->impact_heap[++child];
        }
        if (!sx_impact_before(world->impact_contacts, pick, contact)) break;
        sx_heap_place(world, pos, pick);
        pos = child;
    }
    sx_heap_place(world, pos, contact);
}

/* Removes the entry at pos from a heap of *count entries. */
static void sx_heap_remove(sx_world *world, int pos, int *count) {
    int last = world->impact_heap[--*count];
    if (pos == *count) return;
    sx_heap_place(world, pos, last);
    sx_heap_up(world, pos);
    sx_heap_down(world, world->impact_contacts[last].where, *count);
}

/* Queues contact i at `time`, or moves it if already queued. */
static void sx_heap_set(sx_world *world, int i, sx_real time, int *count) {
    sx_impact_contact *ic = &world->impact_contacts[i];
    int pos = ic->where;
    ic->time = time;
    if (pos < 0) {
        pos = (*count)++;
        sx_heap_place(world, pos, i);
    }
    sx_heap_up(world, pos);
    sx_heap_down(world, ic->where, *count);
}

/* A contact the impact pass must look at. */
static bool sx_impact_candidate(const sx_world *world, const sx_contact *c) {
    return c->restitution > SX_R(0.0) && sx_contact_is_active(world, c);
}

static bool sx_impact_reserve(sx_world *world) {
    int contacts = world->contact_count, bodies = world->body_slots;
    void *p;
    bool ok;
    p = world->impact_bodies;
    /* only the active bodies' entries are reset per pass: the others (static
     * bodies, read as zero shifts) must start at zero */
    ok = sx_grow_zeroed(&p, &world->impact_body_capacity, bodies, sizeof(sx_impact_body));
    world->impact_bodies = (sx_impact_body *)p;
    if (!ok) return false;
    p = world->impact_adjacency;
    ok = sx_grow_array(&p, &world->impact_adjacency_capacity, 2 * contacts, sizeof(int));
    world->impact_adjacency = (int *)p;
    if (!ok) return false;
    p = world->impact_heap;
    ok = sx_grow_array(&p, &world->impact_heap_capacity, contacts, sizeof(int));
    world->impact_heap = (int *)p;
    if (!ok) return false;
    p = world->impact_contacts;
    ok = sx_grow_array(&p, &world->impact_contact_capacity, contacts, sizeof(sx_impact_contact));
    world->impact_contacts = (sx_impact_contact *)p;
    return ok;
}

/* The contact lists per movable body that the pass walks after each impact
 * (contacts with restitution only: the others never take part in the pass).
 * The active bodies are reset for the shifts integrate applies to them; the
 * bodies of the contacts too, which are not always active ones: a body put
 * to sleep between the step's collide and a solve called on its own keeps
 * its contacts, and its entry from an earlier pass would index past the
 * adjacency array. Each body's list is placed at the first contact that
 * names it. */
static void sx_impact_lists(sx_world *world) {
    int i, k;
    for (i = 0; i < world->active_body_count; ++i)
        memset(&world->impact_bodies[world->active_bodies[i]], 0, sizeof(sx_impact_body));
    for (i = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        if (!sx_impact_candidate(world, c)) continue;
        memset(&world->impact_bodies[c->body_a], 0, sizeof(sx_impact_body));
        memset(&world->impact_bodies[c->body_b], 0, sizeof(sx_impact_body));
        world->impact_bodies[c->body_a].start = -1;
        world->impact_bodies[c->body_b].start = -1;
    }
    for (i = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        if (!sx_impact_candidate(world, c)) continue;
        if (sx_movable(&world->sims[c->body_a])) world->impact_bodies[c->body_a].count++;
        if (sx_movable(&world->sims[c->body_b])) world->impact_bodies[c->body_b].count++;
    }
    for (i = 0, k = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        int side;
        if (!sx_impact_candidate(world, c)) continue;
        for (side = 0; side < 2; ++side) {
            sx_impact_body *body = &world->impact_bodies[side ? c->body_b : c->body_a];
            if (body->start >= 0) continue;
            body->start = k;
            k += body->count;
            body->count = 0;
        }
    }
    for (i = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        sx_impact_body *a = &world->impact_bodies[c->body_a], *b = &world->impact_bodies[c->body_b];
        world->impact_contacts[i].where = -1;
        world->impact_contacts[i].count = 0;
        if (!sx_impact_candidate(world, c)) continue;
        if (sx_movable(&world->sims[c->body_a])) world->impact_adjacency[a->start + a->count++] = i;
        if (sx_movable(&world->sims[c->body_b])) world->impact_adjacency[b->start + b->count++] = i;
    }
}

/* After an impact of contact c at time `now`: the velocities of both its
 * bodies changed, so their other contacts are looked at again (queued,
 * moved, or taken off the heap). */
static void sx_impact_requeue(sx_world *world, const sx_contact *c, sx_real h, sx_real now,
                              int *queued) {
    int side, k;
    sx_real t;
    for (side = 0; side < 2; ++side) {
        const sx_impact_body *body = &world->impact_bodies[side ? c->body_b : c->body_a];
        if (!sx_movable(&world->sims[side ? c->body_b : c->body_a])) continue;
        for (k = 0; k < body->count; ++k) {
            int j = world->impact_adjacency[body->start + k];
            int where = world->impact_contacts[j].where;
            if (world->impact_contacts[j].count >= SX_IMPACTS_PER_CONTACT) continue;
            if (sx_impact_time(world, &world->contacts[j], h, true, &t)) {
                /* an impact cannot come before the one that caused it */
                sx_heap_set(world, j, t > now ? t : now, queued);
            } else if (where >= 0) {
                sx_heap_remove(world, where, queued);
                world->impact_contacts[j].where = -1;
            }
        }
    }
}

/* The iterations aim at the gaps between the shifted start positions. */
static void sx_impact_shift_gaps(sx_world *world) {
    int i, k;
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        const sx_impact_body *a = &world->impact_bodies[c->body_a];
        const sx_impact_body *b = &world->impact_bodies[c->body_b];
        if (!sx_contact_is_active(world, c)) continue;
        if (a->turn == SX_R(0.0) && b->turn == SX_R(0.0) && a->shift.x == SX_R(0.0) &&
            a->shift.y == SX_R(0.0) && b->shift.x == SX_R(0.0) && b->shift.y == SX_R(0.0)) {
            continue;
        }
        for (k = 0; k < c->count; ++k)
            c->points[k].gap = sx_shifted_gap(world, c, &c->points[k]);
    }
}

bool sx_contacts_impacts(sx_world *world, sx_real h) {
    int first = -1, i, queued = 0;
    sx_real now = SX_R(0.0), t;
    if (world->impact_shifts_pending) {
        /* a solve without an integrate since: its corrections are void */
        memset(world->impact_bodies, 0,
               (size_t)world->impact_body_capacity * sizeof(sx_impact_body));
        world->impact_shifts_pending = false;
    }
    /* the common case, no impact in this sub-step, costs this scan only,
     * and a world without restitution not even that */
    for (i = 0; i < world->contact_count && first < 0 && world->bouncy_contacts > 0; ++i) {
        const sx_contact *c = &world->contacts[i];
        if (sx_impact_candidate(world, c) && sx_impact_time(world, c, h, false, &t)) first = i;
    }
    if (first < 0) return true;
    if (!sx_impact_reserve(world)) return false;
    world->impact_shifts_pending = true;

    sx_impact_lists(world);

    for (i = first; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        if (sx_impact_candidate(world, c) && sx_impact_time(world, c, h, false, &t)) {
            sx_heap_set(world, i, t, &queued);
        }
    }
    while (queued > 0) {
        int current = world->impact_heap[0];
        sx_contact *c = &world->contacts[current];
        sx_heap_remove(world, 0, &queued);
        world->impact_contacts[current].where = -1;
        world->impact_contacts[current].count++;
        if (world->impact_contacts[current].time > now) now = world->impact_contacts[current].time;
        sx_resolve_impact(world, c, h, now);
        sx_impact_requeue(world, c, h, now, &queued);
    }

    sx_impact_shift_gaps(world);
    return true;
}

void sx_contacts_apply_impact_shifts(sx_world *world) {
    int k;
    if (!world->impact_shifts_pending) return;
    for (k = 0; k < world->active_body_count; ++k) {
        int i = world->active_bodies[k];
        sx_impact_body *s;
        sx_body_sim *b = &world->sims[i];
        if (i >= world->impact_body_capacity) continue;
        s = &world->impact_bodies[i];
        if (world->infos[i].alive && b->moving && b->awake) {
            /* a shift that overflowed (an impulse at the bound on a
             * light body) is dropped: the speed limit has the velocity */
            if ((s->shift.x != SX_R(0.0) || s->shift.y != SX_R(0.0) || s->turn != SX_R(0.0)) &&
                sx_vec2_is_finite(s->shift) && sx_is_finite(s->turn)) {
                b->center = sx_add(b->center, s->shift);
                if (s->turn != SX_R(0.0)) b->xf.q = sx_rot_integrate(b->xf.q, s->turn);
                sx_body_sync_origin(b);
            }
        }
        s->shift = sx_v2_zero();
        s->turn = SX_R(0.0);
    }
    world->impact_shifts_pending = false;
}
