/* sepax — private: a wider real for the shape layer's exactness-sensitive
 * arithmetic (hull orientation tests, polygon mass sums).
 *
 * Orientation signs decide the convex hull, and a wrong sign makes a gift
 * wrap skip or revisit points; mass sums subtract large moments. Both are
 * computed one precision step above sx_real: double in the float build (where
 * the cross product of two float differences is then almost always exact),
 * long double in the double build. The shape layer (shape.c, hull.c) and
 * the polygon work of the collide layer (compound.c, decompose.c) use it. */
#ifndef SEPAX_WIDE_H
#define SEPAX_WIDE_H

#include "core.h"
#include "sepax/shape.h"

#ifdef SX_DOUBLE
typedef long double sx_wide;
#define SX_W(x) (x##L)
#define SX_WIDE_EPSILON LDBL_EPSILON
static inline sx_wide sx_wsqrt(sx_wide a) { return sqrtl(a); }
static inline sx_wide sx_wsin(sx_wide a) { return sinl(a); }
static inline sx_wide sx_wcos(sx_wide a) { return cosl(a); }
static inline sx_wide sx_watan2(sx_wide y, sx_wide x) { return atan2l(y, x); }
#else
typedef double sx_wide;
#define SX_W(x) (x)
#define SX_WIDE_EPSILON DBL_EPSILON
static inline sx_wide sx_wsqrt(sx_wide a) { return sqrt(a); }
static inline sx_wide sx_wsin(sx_wide a) { return sin(a); }
static inline sx_wide sx_wcos(sx_wide a) { return cos(a); }
static inline sx_wide sx_watan2(sx_wide y, sx_wide x) { return atan2(y, x); }
#endif

#define SX_WPI SX_W(3.14159265358979323846264338327950288)

typedef struct sx_wvec2 {
    sx_wide x, y;
} sx_wvec2;

static inline sx_wvec2 sx_wv(sx_wide x, sx_wide y) {
    sx_wvec2 v;
    v.x = x;
    v.y = y;
    return v;
}
/** v widened. */
static inline sx_wvec2 sx_widen(sx_vec2 v) { return sx_wv((sx_wide)v.x, (sx_wide)v.y); }
/** b - a, subtracted in the wide type. */
static inline sx_wvec2 sx_wdiff(sx_vec2 b, sx_vec2 a) {
    return sx_wv((sx_wide)b.x - (sx_wide)a.x, (sx_wide)b.y - (sx_wide)a.y);
}
static inline sx_wvec2 sx_wadd(sx_wvec2 a, sx_wvec2 b) { return sx_wv(a.x + b.x, a.y + b.y); }
static inline sx_wvec2 sx_wsub(sx_wvec2 a, sx_wvec2 b) { return sx_wv(a.x - b.x, a.y - b.y); }
static inline sx_wvec2 sx_wscale(sx_wvec2 v, sx_wide s) { return sx_wv(s * v.x, s * v.y); }
static inline sx_wide sx_wdot(sx_wvec2 a, sx_wvec2 b) { return a.x * b.x + a.y * b.y; }
static inline sx_wide sx_wcross(sx_wvec2 a, sx_wvec2 b) { return a.x * b.y - a.y * b.x; }
static inline sx_vec2 sx_narrow(sx_wvec2 v) { return sx_v2((sx_real)v.x, (sx_real)v.y); }

/** Signed distance of v from the line through a and b, positive on the left
 *  of a -> b. When a and b coincide the line is undefined and the distance
 *  from a is returned (so callers treat v as far from any line). */
static inline sx_wide sx_wline_distance(sx_vec2 a, sx_vec2 b, sx_vec2 v) {
    sx_wvec2 e = sx_wdiff(b, a), w = sx_wdiff(v, a);
    sx_wide len = sx_wsqrt(sx_wdot(e, e));
    if (!(len > SX_W(0.0))) return sx_wsqrt(sx_wdot(w, w));
    return sx_wcross(e, w) / len;
}

/** Twice the signed area of the polygon v[0..n), summed as a fan about its
 *  first vertex in the wide type (exactly zero for collinear points with
 *  short binary expansions, such as integer or float coordinates in the
 *  float build). */
static inline sx_wide sx_warea2(const sx_vec2 *v, int n) {
    sx_wide a2 = SX_W(0.0);
    int i;
    for (i = 1; i + 1 < n; ++i)
        a2 += sx_wcross(sx_wdiff(v[i], v[0]), sx_wdiff(v[i + 1], v[0]));
    return a2;
}

/* Unit-density mass properties of a shape that passes sx_shape_validate, in
 * the wide real (shape.c): *area (the mass), *center (centre of mass) and
 * *inertia (polar second moment about that centre, >= 0). sx_shape_mass is
 * these times the density, rounded to sx_real; a shape whose mass overflows
 * sx_real still has finite wide values here (except near the top of the wide
 * range). */
void sx_shape_wide_mass(const sx_shape *shape, sx_wide *area, sx_wvec2 *center, sx_wide *inertia);

#endif /* SEPAX_WIDE_H */
