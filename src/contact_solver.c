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
 * its answer. A point still separated by a gap s > 0 is speculative: it may
 * approach at up to s / h, closing the gap exactly in this sub-step, so fast
 * bodies stop at the surface instead of tunnelling. An overlapping point only
 * asks for vn >= 0; the overlap itself is removed by moving positions
 * (sx_contacts_separate), never by adding velocity, so overlap does not turn
 * into kinetic energy. Restitution is a last pass over the points that pushed
 * and were approaching faster than the threshold: they leave at e times the
 * approach speed measured before the solve.
 *
 * Positions: each pass recomputes every point's separation from the surface
 * points stored in the body frames by collide, and moves the two bodies
 * apart along the normal by a fraction of the overlap beyond the slop, the
 * move split by inverse mass and inverse inertia (a pseudo-impulse that
 * changes positions only). */
#include "world_internal.h"

void sx_contacts_prepare(sx_world *world, sx_real h) {
    int i, k;
    SX_UNUSED(h);
    for (i = 0; i < world->contact_count; ++i) {
        sx_contact *c = &world->contacts[i];
        sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
        sx_real ma = a->inv_mass, ia = a->inv_inertia, mb = b->inv_mass, ib = b->inv_inertia;
        sx_vec2 n = c->normal, t = sx_cross_vs(n, SX_R(1.0));
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
    }
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
        for (k = 0; k < c->count; ++k) {
            sx_contact_point *p = &c->points[k];
            sx_vec2 dv = sx_sub(sx_add(vb, sx_cross_sv(wb, p->anchor_b)),
                                sx_add(va, sx_cross_sv(wa, p->anchor_a)));
            sx_real vn = sx_dot(dv, n), lambda, total;
            sx_vec2 impulse;
            if (p->separation > SX_R(0.0)) {
                lambda = -p->normal_mass * (vn + p->separation * inv_h);
            } else {
                lambda = -p->normal_mass * vn;
            }
            total = sx_maxr(p->normal_impulse + lambda, SX_R(0.0));
            lambda = total - p->normal_impulse;
            p->normal_impulse = total;
            p->max_normal_impulse = sx_maxr(p->max_normal_impulse, total);
            impulse = sx_scale(n, lambda);
            va = sx_mul_sub(va, ma, impulse);
            wa -= ia * sx_cross(p->anchor_a, impulse);
            vb = sx_mul_add(vb, mb, impulse);
            wb += ib * sx_cross(p->anchor_b, impulse);
        }
        /* friction after the normal impulses, so the cone uses this pass's
         * normal impulse; a frictionless contact costs nothing here */
        if (c->friction > SX_R(0.0)) {
            for (k = 0; k < c->count; ++k) {
                sx_contact_point *p = &c->points[k];
                sx_vec2 dv = sx_sub(sx_add(vb, sx_cross_sv(wb, p->anchor_b)),
                                    sx_add(va, sx_cross_sv(wa, p->anchor_a)));
                sx_real limit = c->friction * p->normal_impulse;
                sx_real lambda = -p->tangent_mass * sx_dot(dv, t);
                sx_real total = sx_clampr(p->tangent_impulse + lambda, -limit, limit);
                sx_vec2 impulse;
                lambda = total - p->tangent_impulse;
                p->tangent_impulse = total;
                impulse = sx_scale(t, lambda);
                va = sx_mul_sub(va, ma, impulse);
                wa -= ia * sx_cross(p->anchor_a, impulse);
                vb = sx_mul_add(vb, mb, impulse);
                wb += ib * sx_cross(p->anchor_b, impulse);
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
        if (c->restitution == SX_R(0.0)) continue;
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
