/* sepax — private: the impulse arithmetic the contact solver
 * (contact_solver.c) and the impact pass (contact_impact.c) share: the bound
 * on accumulated impulses, applying an impulse at two anchors, the relative
 * speed at a point and the 2x2 complementarity solve of a face's two points. */
#ifndef SEPAX_CONTACT_MATH_H
#define SEPAX_CONTACT_MATH_H

#include "world_body.h"
#include "world_contact.h"

/* Bound on every accumulated impulse, so that an impulse, and its moment
 * about an anchor within a few SX_HUGE, stay finite. An effective mass near
 * the top of the range (a body of mass SX_REAL_MAX against a static one: 1 /
 * its inverse mass) times any speed overflowed: the impulse became inf, the
 * static body's velocity 0 x inf = NaN. Far beyond any physical impulse
 * (5e31 N s in float), so ordinary scenes never meet it. */
#define SX_IMPULSE_LIMIT (SX_REAL_MAX / (SX_R(64.0) * SX_HUGE))

/* x within [-SX_IMPULSE_LIMIT, SX_IMPULSE_LIMIT]; NaN (inf x 0 of an
 * overflowed velocity) becomes 0. */
static inline sx_real sx_bounded_impulse(sx_real x) {
    if (x >= -SX_IMPULSE_LIMIT) return x <= SX_IMPULSE_LIMIT ? x : SX_IMPULSE_LIMIT;
    return x < -SX_IMPULSE_LIMIT ? -SX_IMPULSE_LIMIT : SX_R(0.0);
}

/* Applies an impulse along `dir` at the two anchors of a point. */
static inline void sx_apply(sx_vec2 *va, sx_real *wa, sx_vec2 *vb, sx_real *wb, sx_real ma,
                            sx_real ia, sx_real mb, sx_real ib, sx_vec2 ra, sx_vec2 rb,
                            sx_vec2 impulse) {
    *va = sx_mul_sub(*va, ma, impulse);
    *wa -= ia * sx_cross(ra, impulse);
    *vb = sx_mul_add(*vb, mb, impulse);
    *wb += ib * sx_cross(rb, impulse);
}

/* Stores the velocities a pass computed for the two bodies of a contact:
 * static and kinematic bodies keep theirs (for them the pass only added 0 x
 * impulse, which is rounding at best and NaN from an overflow). */
static inline void sx_store_velocities(sx_body_sim *a, sx_vec2 va, sx_real wa, sx_body_sim *b, sx_vec2 vb,
                                sx_real wb) {
    if (a->dynamic) {
        a->v = va;
        a->w = wa;
    }
    if (b->dynamic) {
        b->v = vb;
        b->w = wb;
    }
}

/* Solves both normal constraints of a two-point contact at once: the 2x2
 * linear complementarity problem K x + b >= 0, x >= 0, x . (K x + b) = 0
 * for the accumulated impulses x, by trying its four cases in turn (both
 * points push; only the first; only the second; neither). One point at a
 * time, the two points of a face resting on a face undo each other's work,
 * which shows as a stack that rocks. Returns false if no case fits (round-off
 * on a degenerate K), leaving the velocities untouched. */
static inline bool sx_solve_lcp2(const sx_block2 *k, sx_real b1, sx_real b2, sx_real *x1,
                                 sx_real *x2) {
    sx_real y1, y2;
    /* both push: x = -K^-1 b */
    y1 = -(k->inv11 * b1 + k->inv12 * b2);
    y2 = -(k->inv12 * b1 + k->inv22 * b2);
    if (y1 >= SX_R(0.0) && y2 >= SX_R(0.0)) goto done;
    /* only the first pushes; the second must then separate */
    y1 = -b1 / k->k11;
    y2 = SX_R(0.0);
    if (y1 >= SX_R(0.0) && k->k12 * y1 + b2 >= SX_R(0.0)) goto done;
    y1 = SX_R(0.0);
    y2 = -b2 / k->k22;
    if (y2 >= SX_R(0.0) && k->k12 * y2 + b1 >= SX_R(0.0)) goto done;
    y1 = SX_R(0.0);
    y2 = SX_R(0.0);
    if (b1 >= SX_R(0.0) && b2 >= SX_R(0.0)) goto done;
    return false;
done:
    *x1 = y1;
    *x2 = y2;
    return true;
}

/* The relative velocity of the anchors of a point along dir. */
static inline sx_real sx_point_speed(sx_vec2 va, sx_real wa, sx_vec2 vb, sx_real wb, sx_vec2 ra,
                                     sx_vec2 rb, sx_vec2 dir) {
    sx_vec2 dv = sx_sub(sx_add(vb, sx_cross_sv(wb, rb)), sx_add(va, sx_cross_sv(wa, ra)));
    return sx_dot(dv, dir);
}

#endif /* SEPAX_CONTACT_MATH_H */
