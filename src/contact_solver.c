/* sepax — the contact solver: sequential impulses on velocities, then
 * positional correction.
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
 * tunnelling. An overlapping point only asks for vn >= 0; the overlap itself
 * is removed by moving positions (sx_contacts_separate), never by adding
 * velocity, so overlap does not turn into kinetic energy.
 *
 * Restitution is a last pass over the points that pushed and were
 * approaching faster than the threshold: they leave at e times the approach
 * speed measured before the solve. An impact caught by a speculative point
 * is deferred to the next sub-step, when the surfaces touch, so the rebound
 * starts from the surface and not from the gap; and the rebound impulse is
 * capped at e times the impulse that stopped the approach (Poisson), which
 * keeps chains of contacts solved together from creating energy.
 *
 * Positions: each pass recomputes every point's separation from the surface
 * points stored in the body frames by collide, and moves the two bodies
 * apart along the normal by a fraction of the overlap beyond the slop, the
 * move split by inverse mass and inverse inertia (a pseudo-impulse that
 * changes positions only). */
#include "world_internal.h"

/* Largest condition estimate k11^2 / det(K) of a two-point contact's mass
 * matrix for which the block solver is used (Box2D's value: beyond it the
 * 2x2 solve amplifies round-off more than it gains). */
#define SX_BLOCK_MAX_CONDITION SX_R(1000.0)

void sx_contacts_prepare(sx_world *world) {
    int i, k;
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
        sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
        sx_vec2 n = c->normal, t = sx_cross_vs(n, SX_R(1.0));
        if (!sx_contact_is_active(world, c)) continue;
        for (k = 0; k < c->count; ++k) {
            sx_contact_point *p = &c->points[k];
            sx_vec2 ra = p->anchor_a, rb = p->anchor_b, dv, impulse;
            sx_real rna = sx_cross(ra, n), rnb = sx_cross(rb, n);
            sx_real rta = sx_cross(ra, t), rtb = sx_cross(rb, t);
            sx_real kn = ma + mb + ia * rna * rna + ib * rnb * rnb;
            sx_real kt = ma + mb + ia * rta * rta + ib * rtb * rtb;
            p->normal_mass = kn > SX_R(0.0) ? SX_R(1.0) / kn : SX_R(0.0);
            p->tangent_mass = kt > SX_R(0.0) ? SX_R(1.0) / kt : SX_R(0.0);
            p->max_normal_impulse = SX_R(0.0);
            dv = sx_sub(sx_add(b->v, sx_cross_sv(b->w, rb)), sx_add(a->v, sx_cross_sv(a->w, ra)));
            p->relative_velocity = sx_dot(dv, n);
            /* warm start with last sub-step's accumulated impulses */
            impulse = sx_add(sx_scale(n, p->normal_impulse), sx_scale(t, p->tangent_impulse));
            a->v = sx_mul_sub(a->v, ma, impulse);
            a->w -= ia * sx_cross(ra, impulse);
            b->v = sx_mul_add(b->v, mb, impulse);
            b->w += ib * sx_cross(rb, impulse);
        }
        c->block_solve = false;
        if (c->count == 2) {
            const sx_contact_point *p1 = &c->points[0], *p2 = &c->points[1];
            sx_real r1a = sx_cross(p1->anchor_a, n), r1b = sx_cross(p1->anchor_b, n);
            sx_real r2a = sx_cross(p2->anchor_a, n), r2b = sx_cross(p2->anchor_b, n);
            sx_real det;
            c->k11 = ma + mb + ia * r1a * r1a + ib * r1b * r1b;
            c->k22 = ma + mb + ia * r2a * r2a + ib * r2b * r2b;
            c->k12 = ma + mb + ia * r1a * r2a + ib * r1b * r2b;
            det = c->k11 * c->k22 - c->k12 * c->k12;
            /* Solve the two points together only when K is well conditioned:
             * points almost on top of each other make K nearly singular, and
             * the sequential solve handles them. */
            if (c->k11 * c->k11 < SX_BLOCK_MAX_CONDITION * det) {
                sx_real inv_det = SX_R(1.0) / det;
                c->inv11 = c->k22 * inv_det;
                c->inv22 = c->k11 * inv_det;
                c->inv12 = -c->k12 * inv_det;
                c->block_solve = true;
            }
        }
    }
}

/* The relative normal velocity a point's constraint wants to be >= 0: a
 * speculative point (gap s > 0) may approach at s / h. */
static sx_real sx_normal_error(const sx_contact_point *p, sx_real vn, sx_real inv_h) {
    return p->separation > SX_R(0.0) ? vn + p->separation * inv_h : vn;
}

/* Solves both normal constraints of a two-point contact at once: the 2x2
 * linear complementarity problem K x + b >= 0, x >= 0, x . (K x + b) = 0
 * for the accumulated impulses x, by trying its four cases in turn (both
 * points push; only the first; only the second; neither). One point at a
 * time, the two points of a face resting on a face undo each other's work,
 * which shows as a stack that rocks. Returns false if no case fits (round-off
 * on a degenerate K), leaving the velocities untouched. */
static bool sx_block_solve(const sx_contact *c, sx_contact_point *p1, sx_contact_point *p2,
                           sx_real vn1, sx_real vn2, sx_real inv_h, sx_real *x1, sx_real *x2) {
    sx_real a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    /* b = error of the current velocities minus what the current impulses did */
    sx_real b1 = sx_normal_error(p1, vn1, inv_h) - (c->k11 * a1 + c->k12 * a2);
    sx_real b2 = sx_normal_error(p2, vn2, inv_h) - (c->k12 * a1 + c->k22 * a2);
    sx_real y1, y2;
    /* both push: x = -K^-1 b */
    y1 = -(c->inv11 * b1 + c->inv12 * b2);
    y2 = -(c->inv12 * b1 + c->inv22 * b2);
    if (y1 >= SX_R(0.0) && y2 >= SX_R(0.0)) goto done;
    /* only the first pushes; the second must then separate */
    y1 = -b1 / c->k11;
    y2 = SX_R(0.0);
    if (y1 >= SX_R(0.0) && c->k12 * y1 + b2 >= SX_R(0.0)) goto done;
    y1 = SX_R(0.0);
    y2 = -b2 / c->k22;
    if (y2 >= SX_R(0.0) && c->k12 * y2 + b1 >= SX_R(0.0)) goto done;
    y1 = SX_R(0.0);
    y2 = SX_R(0.0);
    if (b1 >= SX_R(0.0) && b2 >= SX_R(0.0)) goto done;
    return false;
done:
    *x1 = y1;
    *x2 = y2;
    return true;
}

/* Applies an impulse along `dir` at the two anchors of a point. */
static void sx_apply(sx_vec2 *va, sx_real *wa, sx_vec2 *vb, sx_real *wb, sx_real ma, sx_real ia,
                     sx_real mb, sx_real ib, const sx_contact_point *p, sx_vec2 impulse) {
    *va = sx_mul_sub(*va, ma, impulse);
    *wa -= ia * sx_cross(p->anchor_a, impulse);
    *vb = sx_mul_add(*vb, mb, impulse);
    *wb += ib * sx_cross(p->anchor_b, impulse);
}

static sx_real sx_point_speed(sx_vec2 va, sx_real wa, sx_vec2 vb, sx_real wb,
                              const sx_contact_point *p, sx_vec2 dir) {
    sx_vec2 dv =
        sx_sub(sx_add(vb, sx_cross_sv(wb, p->anchor_b)), sx_add(va, sx_cross_sv(wa, p->anchor_a)));
    return sx_dot(dv, dir);
}

void sx_contacts_solve(sx_world *world, sx_real h) {
    sx_real inv_h = SX_R(1.0) / h;
    int i, k;
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
        sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
        sx_vec2 va = a->v, vb = b->v, n = c->normal, t = sx_cross_vs(n, SX_R(1.0));
        sx_real wa = a->w, wb = b->w;
        bool solved = false;
        if (!sx_contact_is_active(world, c)) continue;
        /* Friction first, with the normal impulses of the last pass (or of
         * the warm start): the normal constraints then have the last word,
         * so a pass never ends with a point moving into the surface. A
         * frictionless contact costs nothing here. */
        if (c->friction > SX_R(0.0)) {
            for (k = 0; k < c->count; ++k) {
                sx_contact_point *p = &c->points[k];
                sx_real limit = c->friction * p->normal_impulse;
                sx_real lambda = -p->tangent_mass * sx_point_speed(va, wa, vb, wb, p, t);
                sx_real total = sx_clampr(p->tangent_impulse + lambda, -limit, limit);
                lambda = total - p->tangent_impulse;
                p->tangent_impulse = total;
                sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, p, sx_scale(t, lambda));
            }
        }
        if (c->block_solve) {
            sx_contact_point *p1 = &c->points[0], *p2 = &c->points[1];
            sx_real x1, x2;
            sx_real vn1 = sx_point_speed(va, wa, vb, wb, p1, n);
            sx_real vn2 = sx_point_speed(va, wa, vb, wb, p2, n);
            if (sx_block_solve(c, p1, p2, vn1, vn2, inv_h, &x1, &x2)) {
                sx_real d1 = x1 - p1->normal_impulse, d2 = x2 - p2->normal_impulse;
                sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, p1, sx_scale(n, d1));
                sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, p2, sx_scale(n, d2));
                p1->normal_impulse = x1;
                p2->normal_impulse = x2;
                p1->max_normal_impulse = sx_maxr(p1->max_normal_impulse, x1);
                p2->max_normal_impulse = sx_maxr(p2->max_normal_impulse, x2);
                solved = true;
            }
        }
        if (!solved) {
            for (k = 0; k < c->count; ++k) {
                sx_contact_point *p = &c->points[k];
                sx_real vn = sx_point_speed(va, wa, vb, wb, p, n);
                sx_real lambda = -p->normal_mass * sx_normal_error(p, vn, inv_h);
                sx_real total = sx_maxr(p->normal_impulse + lambda, SX_R(0.0));
                lambda = total - p->normal_impulse;
                p->normal_impulse = total;
                p->max_normal_impulse = sx_maxr(p->max_normal_impulse, total);
                sx_apply(&va, &wa, &vb, &wb, ma, ia, mb, ib, p, sx_scale(n, lambda));
            }
        }
        a->v = va;
        a->w = wa;
        b->v = vb;
        b->w = wb;
    }
}

void sx_contacts_restitution(sx_world *world) {
    sx_real threshold = world->def.restitution_threshold;
    /* a point closer than this at collide time is touching; farther, it is
     * speculative and its impact is deferred to the sub-step it touches in */
    sx_real touching = SX_R(0.25) * world->linear_slop;
    int i, k;
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        sx_body_sim *a, *b;
        sx_real ma, ia, mb, ib;
        sx_vec2 n = c->normal;
        if (c->restitution == SX_R(0.0) || !sx_contact_is_active(world, c)) continue;
        a = &world->sims[c->body_a];
        b = &world->sims[c->body_b];
        ma = a->inv_mass;
        ia = a->inv_inertia;
        mb = b->inv_mass;
        ib = b->inv_inertia;
        for (k = 0; k < c->count; ++k) {
            sx_contact_point *p = &c->points[k];
            sx_vec2 dv, impulse;
            sx_real vn, lambda, total;
            sx_real approach = sx_minr(p->relative_velocity, p->pending_approach);
            sx_real compression = p->normal_impulse + p->pending_impulse;
            p->pending_approach = SX_R(0.0);
            p->pending_impulse = SX_R(0.0);
            if (approach > -threshold || p->max_normal_impulse == SX_R(0.0)) continue;
            if (p->separation > touching) {
                /* The speculative solve stopped the bodies at the surface, at
                 * the end of this sub-step. Bouncing now would launch them from
                 * the gap, higher than the surface by (1 + e) x gap; the next
                 * sub-step bounces them from the surface with this speed. */
                p->pending_approach = approach;
                p->pending_impulse = compression;
                continue;
            }
            dv = sx_sub(sx_add(b->v, sx_cross_sv(b->w, p->anchor_b)),
                        sx_add(a->v, sx_cross_sv(a->w, p->anchor_a)));
            vn = sx_dot(dv, n);
            lambda = -p->normal_mass * (vn + c->restitution * approach);
            /* Poisson's bound: the rebound impulse is at most e times the
             * impulse that stopped the approach. For one contact it is the
             * same answer; in a chain of contacts solved together it keeps
             * each point from returning more than it absorbed, which would
             * create energy. */
            lambda = sx_minr(lambda, c->restitution * compression);
            total = sx_maxr(p->normal_impulse + lambda, SX_R(0.0));
            lambda = total - p->normal_impulse;
            p->normal_impulse = total;
            impulse = sx_scale(n, lambda);
            a->v = sx_mul_sub(a->v, ma, impulse);
            a->w -= ia * sx_cross(p->anchor_a, impulse);
            b->v = sx_mul_add(b->v, mb, impulse);
            b->w += ib * sx_cross(p->anchor_b, impulse);
        }
    }
}

/* Turns a body by a small angle (the pseudo-impulse's rotation) and keeps
 * its origin consistent with the moved centre of mass. */
static void sx_move_body(sx_body_sim *b, sx_vec2 dp, sx_real angle) {
    b->center = sx_add(b->center, dp);
    if (angle != SX_R(0.0)) b->xf.q = sx_rot_integrate(b->xf.q, angle);
    sx_body_sync_origin(b);
}

void sx_contacts_separate(sx_world *world, sx_real h) {
    int iterations = world->def.position_iterations, it, i, k;
    sx_real slop = world->linear_slop, beta = world->def.correction_factor;
    sx_real max_move;
    if (iterations == 0) return;
    /* spread the speed limit over the passes of one sub-step */
    max_move = world->def.max_correction_speed * h / (sx_real)iterations;
    for (it = 0; it < iterations; ++it) {
        for (i = 0; i < world->contact_count; ++i) {
            sx_contact *c = &world->contacts[i];
            sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
            sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
            if (!sx_contact_is_active(world, c)) continue;
            for (k = 0; k < c->count; ++k) {
                const sx_contact_point *p = &c->points[k];
                sx_vec2 pa = sx_xform_point(a->xf, p->local_a);
                sx_vec2 pb = sx_xform_point(b->xf, p->local_b);
                sx_vec2 n = sx_rotate(a->xf.q, c->local_normal);
                sx_real s = sx_dot(sx_sub(pb, pa), n), correction, kn, rna, rnb, lambda;
                sx_vec2 mid, ra, rb, impulse;
                if (s >= -slop) continue;
                correction = sx_maxr(beta * (s + slop), -max_move);
                mid = sx_scale(sx_add(pa, pb), SX_R(0.5));
                ra = sx_sub(mid, a->center);
                rb = sx_sub(mid, b->center);
                rna = sx_cross(ra, n);
                rnb = sx_cross(rb, n);
                kn = ma + mb + ia * rna * rna + ib * rnb * rnb;
                if (!(kn > SX_R(0.0))) continue;
                lambda = -correction / kn;
                impulse = sx_scale(n, lambda);
                if (ma > SX_R(0.0) || ia > SX_R(0.0)) {
                    sx_move_body(a, sx_scale(impulse, -ma), -ia * sx_cross(ra, impulse));
                }
                if (mb > SX_R(0.0) || ib > SX_R(0.0)) {
                    sx_move_body(b, sx_scale(impulse, mb), ib * sx_cross(rb, impulse));
                }
            }
        }
    }
}
