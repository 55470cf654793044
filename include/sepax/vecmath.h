/* sepax — value-type math: scalars, 2D vectors, rotations, rigid transforms,
 * 3x3 affine matrices and axis-aligned boxes. Everything here is static inline
 * on small structs passed by value, so the compiler sees through it in the
 * collision loops.
 *
 * Two representations of a placement live side by side on purpose. sx_xform
 * (position + cos/sin pair) is what the library computes with: it is rigid by
 * construction and cheap to invert. sx_mat3 is the 3x3 homogeneous matrix of
 * the course material (points have w = 1, vectors w = 0, A*B applies B first)
 * for users who build scale and shear into their placements; the two convert
 * into each other. The perpendicular of (x, y) is (-y, x) everywhere: a
 * counter-clockwise quarter turn, so the outward normal of a CCW polygon edge
 * d is -perp(d).
 *
 * The name is vecmath.h, not math.h: a header called math.h shadows the C
 * library's <math.h> for a program that puts include/sepax itself on its
 * include path. */
#ifndef SEPAX_VECMATH_H
#define SEPAX_VECMATH_H

#include <math.h>

#include "base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- scalars ------------------------------------------------------------ */

static inline sx_real sx_minr(sx_real a, sx_real b) { return a < b ? a : b; }
static inline sx_real sx_maxr(sx_real a, sx_real b) { return a > b ? a : b; }
static inline sx_real sx_absr(sx_real a) { return a < SX_R(0.0) ? -a : a; }
/** Clamps a to [lo, hi] (lo <= hi expected; lo wins otherwise). */
static inline sx_real sx_clampr(sx_real a, sx_real lo, sx_real hi) {
    /* max(lo, hi) keeps "lo wins" when the bounds are crossed and a > hi. */
    return a < lo ? lo : (a > hi ? sx_maxr(lo, hi) : a);
}
/** True unless a is NaN or +-infinity. */
static inline bool sx_is_finite(sx_real a) { return (a - a) == (a - a); }

#ifdef SX_DOUBLE
static inline sx_real sx_sqrt(sx_real a) { return sqrt(a); }
static inline sx_real sx_sin(sx_real a) { return sin(a); }
static inline sx_real sx_cos(sx_real a) { return cos(a); }
static inline sx_real sx_atan2(sx_real y, sx_real x) { return atan2(y, x); }
static inline sx_real sx_floor(sx_real a) { return floor(a); }
#else
static inline sx_real sx_sqrt(sx_real a) { return sqrtf(a); }
static inline sx_real sx_sin(sx_real a) { return sinf(a); }
static inline sx_real sx_cos(sx_real a) { return cosf(a); }
static inline sx_real sx_atan2(sx_real y, sx_real x) { return atan2f(y, x); }
static inline sx_real sx_floor(sx_real a) { return floorf(a); }
#endif

/* ---- sx_vec2 ------------------------------------------------------------ */

/** A 2D vector or point, in metres (or length units). */
typedef struct sx_vec2 {
    sx_real x, y;
} sx_vec2;

static inline sx_vec2 sx_v2(sx_real x, sx_real y) {
    sx_vec2 v;
    v.x = x;
    v.y = y;
    return v;
}
static inline sx_vec2 sx_v2_zero(void) { return sx_v2(SX_R(0.0), SX_R(0.0)); }
static inline sx_vec2 sx_add(sx_vec2 a, sx_vec2 b) { return sx_v2(a.x + b.x, a.y + b.y); }
static inline sx_vec2 sx_sub(sx_vec2 a, sx_vec2 b) { return sx_v2(a.x - b.x, a.y - b.y); }
static inline sx_vec2 sx_neg(sx_vec2 a) { return sx_v2(-a.x, -a.y); }
/** s * v */
static inline sx_vec2 sx_scale(sx_vec2 v, sx_real s) { return sx_v2(s * v.x, s * v.y); }
/** a + s * b */
static inline sx_vec2 sx_mul_add(sx_vec2 a, sx_real s, sx_vec2 b) {
    return sx_v2(a.x + s * b.x, a.y + s * b.y);
}
/** a - s * b */
static inline sx_vec2 sx_mul_sub(sx_vec2 a, sx_real s, sx_vec2 b) {
    return sx_v2(a.x - s * b.x, a.y - s * b.y);
}
/** Component-wise product. */
static inline sx_vec2 sx_mul_cw(sx_vec2 a, sx_vec2 b) { return sx_v2(a.x * b.x, a.y * b.y); }
static inline sx_real sx_dot(sx_vec2 a, sx_vec2 b) { return a.x * b.x + a.y * b.y; }
/** 2D cross product a x b = a.x*b.y - a.y*b.x: positive when b is counter-
 *  clockwise of a. */
static inline sx_real sx_cross(sx_vec2 a, sx_vec2 b) { return a.x * b.y - a.y * b.x; }
/** v x s = (s*v.y, -s*v.x): the vector-by-scalar cross (z-axis on the right). */
static inline sx_vec2 sx_cross_vs(sx_vec2 v, sx_real s) { return sx_v2(s * v.y, -s * v.x); }
/** s x v = (-s*v.y, s*v.x): angular velocity s crossed with arm v gives the
 *  velocity of the arm's tip. */
static inline sx_vec2 sx_cross_sv(sx_real s, sx_vec2 v) { return sx_v2(-s * v.y, s * v.x); }
/** The perpendicular (-y, x): v turned a quarter turn counter-clockwise. */
static inline sx_vec2 sx_perp(sx_vec2 v) { return sx_v2(-v.y, v.x); }
static inline sx_real sx_length_sq(sx_vec2 v) { return v.x * v.x + v.y * v.y; }
static inline sx_real sx_length(sx_vec2 v) { return sx_sqrt(v.x * v.x + v.y * v.y); }
static inline sx_real sx_distance_sq(sx_vec2 a, sx_vec2 b) { return sx_length_sq(sx_sub(b, a)); }
static inline sx_real sx_distance(sx_vec2 a, sx_vec2 b) { return sx_length(sx_sub(b, a)); }

/** True unless a component is NaN or +-infinity. */
static inline bool sx_vec2_is_finite(sx_vec2 v) { return sx_is_finite(v.x) && sx_is_finite(v.y); }
/** Unit vector along v and v's length in *length (may be NULL). A vector too
 *  short to normalise (length <= SX_REAL_EPSILON, or not finite) gives the zero
 *  vector and *length = 0: the caller can tell "no direction" apart. */
static inline sx_vec2 sx_normalize_len(sx_vec2 v, sx_real *length) {
    sx_real len = sx_length(v);
    sx_real k = SX_R(1.0);
    if (!sx_is_finite(len) && sx_vec2_is_finite(v)) {
        /* The squares overflowed although v is finite (|x| > 1e19 in float):
         * measure v / k, k its largest component, whose length is in [1, 2]. */
        k = sx_maxr(sx_absr(v.x), sx_absr(v.y));
        v = sx_v2(v.x / k, v.y / k);
        len = sx_length(v);
    }
    if (!(len > SX_REAL_EPSILON) || !sx_is_finite(k * len)) {
        if (length) *length = SX_R(0.0);
        return sx_v2_zero();
    }
    if (length) *length = k * len;
    sx_real inv = SX_R(1.0) / len;
    return sx_v2(v.x * inv, v.y * inv);
}
/** Unit vector along v; the zero vector (and anything too short or not
 *  finite) stays zero. */
static inline sx_vec2 sx_normalize(sx_vec2 v) { return sx_normalize_len(v, NULL); }
/** True if |v| is within 100 epsilon of 1. */
static inline bool sx_is_normalized(sx_vec2 v) {
    /* |v| = 1 + d gives |v|^2 = 1 + 2d: the bound on the square is doubled. */
    sx_real e = SX_R(1.0) - sx_length_sq(v);
    return e > SX_R(-200.0) * SX_REAL_EPSILON && e < SX_R(200.0) * SX_REAL_EPSILON;
}
/** a + t (b - a) */
static inline sx_vec2 sx_lerp(sx_vec2 a, sx_vec2 b, sx_real t) {
    return sx_v2(a.x + t * (b.x - a.x), a.y + t * (b.y - a.y));
}
static inline sx_vec2 sx_vmin(sx_vec2 a, sx_vec2 b) {
    return sx_v2(sx_minr(a.x, b.x), sx_minr(a.y, b.y));
}
static inline sx_vec2 sx_vmax(sx_vec2 a, sx_vec2 b) {
    return sx_v2(sx_maxr(a.x, b.x), sx_maxr(a.y, b.y));
}
static inline sx_vec2 sx_vabs(sx_vec2 a) { return sx_v2(sx_absr(a.x), sx_absr(a.y)); }
/** Component-wise clamp of v to [lo, hi]. */
static inline sx_vec2 sx_vclamp(sx_vec2 v, sx_vec2 lo, sx_vec2 hi) {
    return sx_v2(sx_clampr(v.x, lo.x, hi.x), sx_clampr(v.y, lo.y, hi.y));
}
/** True if each component differs by at most tol. */
static inline bool sx_approx_equal(sx_vec2 a, sx_vec2 b, sx_real tol) {
    return sx_absr(a.x - b.x) <= tol && sx_absr(a.y - b.y) <= tol;
}

/* ---- sx_rot ------------------------------------------------------------- */

/** A rotation as its cosine and sine (unit length). */
typedef struct sx_rot {
    sx_real c, s;
} sx_rot;

static inline sx_rot sx_rot_identity(void) {
    sx_rot q;
    q.c = SX_R(1.0);
    q.s = SX_R(0.0);
    return q;
}
/** The rotation by `angle` radians, counter-clockwise. */
static inline sx_rot sx_rot_make(sx_real angle) {
    sx_rot q;
    q.c = sx_cos(angle);
    q.s = sx_sin(angle);
    return q;
}
/** The angle of q in (-pi, pi]. */
static inline sx_real sx_rot_angle(sx_rot q) {
    sx_real a = sx_atan2(q.s, q.c);
    /* atan2 gives -pi on the negative x axis when the sine is -0 or rounds
     * there (sx_rot_make(-SX_PI), sx_rot_inv of a half turn): that is +pi. */
    return a == -SX_PI ? SX_PI : a;
}
/** q rescaled to unit length (identity if q is zero or not finite). */
static inline sx_rot sx_rot_normalize(sx_rot q) {
    sx_real len;
    sx_vec2 u = sx_normalize_len(sx_v2(q.c, q.s), &len);
    sx_rot r;
    if (len == SX_R(0.0)) return sx_rot_identity();
    r.c = u.x;
    r.s = u.y;
    return r;
}
/** q advanced by a small angle d (first order, renormalised): the integrator's
 *  rotation update. */
static inline sx_rot sx_rot_integrate(sx_rot q, sx_real d) {
    sx_rot r;
    r.c = q.c - d * q.s;
    r.s = q.s + d * q.c;
    return sx_rot_normalize(r);
}
/** Rotates v by q. */
static inline sx_vec2 sx_rotate(sx_rot q, sx_vec2 v) {
    return sx_v2(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y);
}
/** Rotates v by the inverse of q. */
static inline sx_vec2 sx_inv_rotate(sx_rot q, sx_vec2 v) {
    return sx_v2(q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y);
}
/** q * r: rotate by r, then by q. */
static inline sx_rot sx_rot_mul(sx_rot q, sx_rot r) {
    sx_rot t;
    t.c = q.c * r.c - q.s * r.s;
    t.s = q.s * r.c + q.c * r.s;
    return t;
}
/** inverse(q) * r: the rotation of r relative to q. */
static inline sx_rot sx_rot_inv_mul(sx_rot q, sx_rot r) {
    sx_rot t;
    t.c = q.c * r.c + q.s * r.s;
    t.s = q.c * r.s - q.s * r.c;
    return t;
}
static inline sx_rot sx_rot_inv(sx_rot q) {
    sx_rot t;
    t.c = q.c;
    t.s = -q.s;
    return t;
}

/* ---- sx_xform ----------------------------------------------------------- */

/** A rigid transform: rotate by q, then translate by p. Maps a shape's local
 *  coordinates to world coordinates. */
typedef struct sx_xform {
    sx_vec2 p;
    sx_rot q;
} sx_xform;

static inline sx_xform sx_xform_identity(void) {
    sx_xform x;
    x.p = sx_v2_zero();
    x.q = sx_rot_identity();
    return x;
}
/** The transform placing a local origin at `position`, turned by `angle`
 *  radians counter-clockwise. */
static inline sx_xform sx_xform_make(sx_vec2 position, sx_real angle) {
    sx_xform x;
    x.p = position;
    x.q = sx_rot_make(angle);
    return x;
}
/** Local point to world: q v + p. */
static inline sx_vec2 sx_xform_point(sx_xform x, sx_vec2 v) {
    return sx_add(sx_rotate(x.q, v), x.p);
}
/** World point to local: q^-1 (v - p). */
static inline sx_vec2 sx_xform_inv_point(sx_xform x, sx_vec2 v) {
    return sx_inv_rotate(x.q, sx_sub(v, x.p));
}
/** Local direction to world (rotation only). */
static inline sx_vec2 sx_xform_vector(sx_xform x, sx_vec2 v) { return sx_rotate(x.q, v); }
/** World direction to local (rotation only). */
static inline sx_vec2 sx_xform_inv_vector(sx_xform x, sx_vec2 v) { return sx_inv_rotate(x.q, v); }
/** A * B: applies B first, then A. */
static inline sx_xform sx_xform_mul(sx_xform a, sx_xform b) {
    sx_xform c;
    c.q = sx_rot_mul(a.q, b.q);
    c.p = sx_add(sx_rotate(a.q, b.p), a.p);
    return c;
}
/** inverse(A) * B: B expressed in A's frame. Used to move shape B into shape
 *  A's local frame before colliding. */
static inline sx_xform sx_xform_inv_mul(sx_xform a, sx_xform b) {
    sx_xform c;
    c.q = sx_rot_inv_mul(a.q, b.q);
    c.p = sx_inv_rotate(a.q, sx_sub(b.p, a.p));
    return c;
}
/** The inverse transform. */
static inline sx_xform sx_xform_invert(sx_xform a) {
    sx_xform c;
    c.q = sx_rot_inv(a.q);
    c.p = sx_neg(sx_inv_rotate(a.q, a.p));
    return c;
}
static inline bool sx_xform_is_finite(sx_xform x) {
    return sx_vec2_is_finite(x.p) && sx_is_finite(x.q.c) && sx_is_finite(x.q.s);
}

/* ---- sx_mat3 ------------------------------------------------------------ */

/** A 3x3 matrix, row-major: m[row][col]. As an affine 2D transform the last
 *  row is (0 0 1), points are columns (x y 1) and vectors (x y 0). */
typedef struct sx_mat3 {
    sx_real m[3][3];
} sx_mat3;

static inline sx_mat3 sx_mat3_make(sx_real a, sx_real b, sx_real c, sx_real d, sx_real e, sx_real f,
                                   sx_real g, sx_real h, sx_real i) {
    sx_mat3 r;
    r.m[0][0] = a;
    r.m[0][1] = b;
    r.m[0][2] = c;
    r.m[1][0] = d;
    r.m[1][1] = e;
    r.m[1][2] = f;
    r.m[2][0] = g;
    r.m[2][1] = h;
    r.m[2][2] = i;
    return r;
}
static inline sx_mat3 sx_mat3_identity(void) {
    return sx_mat3_make(SX_R(1.0), SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(1.0), SX_R(0.0), SX_R(0.0),
                        SX_R(0.0), SX_R(1.0));
}
/** [1 0 x; 0 1 y; 0 0 1] */
static inline sx_mat3 sx_mat3_translation(sx_real x, sx_real y) {
    return sx_mat3_make(SX_R(1.0), SX_R(0.0), x, SX_R(0.0), SX_R(1.0), y, SX_R(0.0), SX_R(0.0),
                        SX_R(1.0));
}
/** [sx 0 0; 0 sy 0; 0 0 1] */
static inline sx_mat3 sx_mat3_scale(sx_real sx, sx_real sy) {
    return sx_mat3_make(sx, SX_R(0.0), SX_R(0.0), SX_R(0.0), sy, SX_R(0.0), SX_R(0.0), SX_R(0.0),
                        SX_R(1.0));
}
/** [cos -sin 0; sin cos 0; 0 0 1]: counter-clockwise by `angle` radians. */
static inline sx_mat3 sx_mat3_rotation(sx_real angle) {
    sx_real c = sx_cos(angle), s = sx_sin(angle);
    return sx_mat3_make(c, -s, SX_R(0.0), s, c, SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(1.0));
}
/** A * B (applies B first, then A). */
static inline sx_mat3 sx_mat3_mul(sx_mat3 a, sx_mat3 b) {
    sx_mat3 r;
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
        }
    }
    return r;
}
static inline sx_mat3 sx_mat3_transpose(sx_mat3 a) {
    return sx_mat3_make(a.m[0][0], a.m[1][0], a.m[2][0], a.m[0][1], a.m[1][1], a.m[2][1], a.m[0][2],
                        a.m[1][2], a.m[2][2]);
}
/** M (x y 1): a point, translation applies. The result is divided by w when
 *  the last row is not (0 0 1) and w is non-zero (projective matrices). */
static inline sx_vec2 sx_mat3_transform_point(sx_mat3 a, sx_vec2 p) {
    sx_real x = a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2];
    sx_real y = a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2];
    sx_real w = a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2];
    if (w != SX_R(1.0) && w != SX_R(0.0)) {
        x /= w;
        y /= w;
    }
    return sx_v2(x, y);
}
/** M (x y 0): a direction, translation ignored. */
static inline sx_vec2 sx_mat3_transform_vector(sx_mat3 a, sx_vec2 v) {
    return sx_v2(a.m[0][0] * v.x + a.m[0][1] * v.y, a.m[1][0] * v.x + a.m[1][1] * v.y);
}
static inline sx_real sx_mat3_determinant(sx_mat3 a) {
    return a.m[0][0] * (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) -
           a.m[0][1] * (a.m[1][0] * a.m[2][2] - a.m[1][2] * a.m[2][0]) +
           a.m[0][2] * (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]);
}
/** Writes the inverse of a into *out and returns true; returns false (and
 *  writes the identity) when a is singular: |det| at most 16 epsilon times the
 *  product of a's row lengths, or anything not finite. */
static inline bool sx_mat3_inverse(sx_mat3 a, sx_mat3 *out) {
    sx_real det = sx_mat3_determinant(a);
    sx_real scale = SX_R(1.0);
    int i, j;
    for (i = 0; i < 3; ++i) {
        sx_real r = sx_sqrt(a.m[i][0] * a.m[i][0] + a.m[i][1] * a.m[i][1] + a.m[i][2] * a.m[i][2]);
        scale *= r;
    }
    if (!sx_is_finite(det) || !sx_is_finite(scale) ||
        !(sx_absr(det) > SX_R(16.0) * SX_REAL_EPSILON * scale)) {
        *out = sx_mat3_identity();
        return false;
    }
    sx_real inv = SX_R(1.0) / det;
    sx_mat3 r;
    r.m[0][0] = (a.m[1][1] * a.m[2][2] - a.m[1][2] * a.m[2][1]) * inv;
    r.m[0][1] = (a.m[0][2] * a.m[2][1] - a.m[0][1] * a.m[2][2]) * inv;
    r.m[0][2] = (a.m[0][1] * a.m[1][2] - a.m[0][2] * a.m[1][1]) * inv;
    r.m[1][0] = (a.m[1][2] * a.m[2][0] - a.m[1][0] * a.m[2][2]) * inv;
    r.m[1][1] = (a.m[0][0] * a.m[2][2] - a.m[0][2] * a.m[2][0]) * inv;
    r.m[1][2] = (a.m[0][2] * a.m[1][0] - a.m[0][0] * a.m[1][2]) * inv;
    r.m[2][0] = (a.m[1][0] * a.m[2][1] - a.m[1][1] * a.m[2][0]) * inv;
    r.m[2][1] = (a.m[0][1] * a.m[2][0] - a.m[0][0] * a.m[2][1]) * inv;
    r.m[2][2] = (a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0]) * inv;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            if (!sx_is_finite(r.m[i][j])) {
                *out = sx_mat3_identity();
                return false;
            }
        }
    }
    *out = r;
    return true;
}
/** The matrix of a rigid transform: [c -s px; s c py; 0 0 1]. */
static inline sx_mat3 sx_mat3_from_xform(sx_xform x) {
    return sx_mat3_make(x.q.c, -x.q.s, x.p.x, x.q.s, x.q.c, x.p.y, SX_R(0.0), SX_R(0.0), SX_R(1.0));
}
/** Extracts the rigid part of an affine matrix: the translation column and the
 *  rotation of the first column. Returns true when a is rigid (orthonormal
 *  2x2 block with determinant +1 and last row (0 0 1), each within `tol`);
 *  false when it carries scale, shear, reflection or projection (then *out
 *  still holds the rotation of the first column and the translation column,
 *  or the identity if those are not finite or the first column is zero). */
static inline bool sx_mat3_to_xform(sx_mat3 a, sx_real tol, sx_xform *out) {
    sx_vec2 c0 = sx_v2(a.m[0][0], a.m[1][0]);
    sx_vec2 c1 = sx_v2(a.m[0][1], a.m[1][1]);
    sx_real len;
    sx_vec2 u = sx_normalize_len(c0, &len);
    sx_xform x;
    if (len == SX_R(0.0) || !sx_is_finite(a.m[0][2]) || !sx_is_finite(a.m[1][2])) {
        *out = sx_xform_identity();
        return false;
    }
    x.q.c = u.x;
    x.q.s = u.y;
    x.p = sx_v2(a.m[0][2], a.m[1][2]);
    *out = x;
    return sx_absr(len - SX_R(1.0)) <= tol && sx_absr(sx_length(c1) - SX_R(1.0)) <= tol &&
           sx_absr(sx_dot(c0, c1)) <= tol && sx_cross(c0, c1) > SX_R(0.0) &&
           sx_absr(a.m[2][0]) <= tol && sx_absr(a.m[2][1]) <= tol &&
           sx_absr(a.m[2][2] - SX_R(1.0)) <= tol;
}

/* ---- sx_aabb ------------------------------------------------------------ */

/** An axis-aligned bounding box, lower <= upper component-wise when valid. */
typedef struct sx_aabb {
    sx_vec2 lower, upper;
} sx_aabb;

static inline sx_aabb sx_aabb_make(sx_vec2 lower, sx_vec2 upper) {
    sx_aabb b;
    b.lower = lower;
    b.upper = upper;
    return b;
}
/** Valid: finite and lower <= upper. */
static inline bool sx_aabb_is_valid(sx_aabb a) {
    return sx_vec2_is_finite(a.lower) && sx_vec2_is_finite(a.upper) && a.lower.x <= a.upper.x &&
           a.lower.y <= a.upper.y;
}
/** The smallest box around `count` points. count <= 0 or points == NULL
 *  gives an invalid box (lower = +max, upper = -max) that is the identity of
 *  sx_aabb_union; so does any NaN or infinite point (the box of the others
 *  would silently leave it out). */
static inline sx_aabb sx_aabb_from_points(const sx_vec2 *points, int count) {
    const sx_aabb empty =
        sx_aabb_make(sx_v2(SX_REAL_MAX, SX_REAL_MAX), sx_v2(-SX_REAL_MAX, -SX_REAL_MAX));
    sx_aabb b = empty;
    bool finite = true;
    int i;
    if (points == NULL) return b;
    for (i = 0; i < count; ++i) {
        /* Checked separately: min/max would drop a NaN again at the next point. */
        finite = finite && sx_vec2_is_finite(points[i]);
        b.lower = sx_vmin(b.lower, points[i]);
        b.upper = sx_vmax(b.upper, points[i]);
    }
    return finite ? b : empty;
}
static inline sx_aabb sx_aabb_union(sx_aabb a, sx_aabb b) {
    return sx_aabb_make(sx_vmin(a.lower, b.lower), sx_vmax(a.upper, b.upper));
}
/** True if the boxes overlap; touching edges count. */
static inline bool sx_aabb_overlaps(sx_aabb a, sx_aabb b) {
    return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || a.lower.x > b.upper.x ||
             a.lower.y > b.upper.y);
}
/** True if a contains b entirely (shared edges count). */
static inline bool sx_aabb_contains(sx_aabb a, sx_aabb b) {
    return a.lower.x <= b.lower.x && a.lower.y <= b.lower.y && b.upper.x <= a.upper.x &&
           b.upper.y <= a.upper.y;
}
/** True if p is inside a or on its boundary. */
static inline bool sx_aabb_contains_point(sx_aabb a, sx_vec2 p) {
    return a.lower.x <= p.x && p.x <= a.upper.x && a.lower.y <= p.y && p.y <= a.upper.y;
}
static inline sx_vec2 sx_aabb_center(sx_aabb a) {
    return sx_v2(SX_R(0.5) * (a.lower.x + a.upper.x), SX_R(0.5) * (a.lower.y + a.upper.y));
}
/** Half-widths. */
static inline sx_vec2 sx_aabb_extents(sx_aabb a) {
    return sx_v2(SX_R(0.5) * (a.upper.x - a.lower.x), SX_R(0.5) * (a.upper.y - a.lower.y));
}
static inline sx_real sx_aabb_perimeter(sx_aabb a) {
    return SX_R(2.0) * ((a.upper.x - a.lower.x) + (a.upper.y - a.lower.y));
}
static inline sx_real sx_aabb_area(sx_aabb a) {
    return (a.upper.x - a.lower.x) * (a.upper.y - a.lower.y);
}
/** a grown by `margin` on every side (the broadphase's fat box). */
static inline sx_aabb sx_aabb_fatten(sx_aabb a, sx_real margin) {
    return sx_aabb_make(sx_v2(a.lower.x - margin, a.lower.y - margin),
                        sx_v2(a.upper.x + margin, a.upper.y + margin));
}
/** The point of a closest to p (p itself when inside). */
static inline sx_vec2 sx_aabb_closest_point(sx_aabb a, sx_vec2 p) {
    return sx_vclamp(p, a.lower, a.upper);
}
/** True if the disc (center, radius) touches or overlaps a. */
static inline bool sx_aabb_overlaps_circle(sx_aabb a, sx_vec2 center, sx_real radius) {
    return sx_distance_sq(sx_aabb_closest_point(a, center), center) <= radius * radius;
}

#ifdef __cplusplus
}
#endif

#endif /* SEPAX_VECMATH_H */
