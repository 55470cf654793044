/* sepax — private helpers shared by the point queries (query.c) and the ray
 * casts (raycast.c): the input checks every query starts with, a unit vector
 * that survives tiny and huge inputs, and the relative tolerance of the
 * parametric line tests. Nothing here is part of the public contract. */
#ifndef SEPAX_QUERY_H
#define SEPAX_QUERY_H

#include "core.h"
#include "sepax/collide.h"

/* Relative tolerance of the parametric line tests (segment-segment and
 * ray-segment). Rounding in a 2D cross product of two vectors is a few ulps of
 * the product of their lengths, and the differences that feed it carry a few
 * more, so 16 epsilon is the smallest |sin(angle)| these routines treat as "not
 * parallel" (about 1.9e-6 rad in float, 3.6e-15 rad in double). The same
 * factor, scaled by the lengths involved, is the slack allowed on a
 * dimensionless line parameter before a touch at an end point is lost. */
#define SX_QUERY_REL_TOLERANCE (SX_R(16.0) * SX_REAL_EPSILON)

/* Unit vector along v, computed after dividing by v's largest component so
 * that neither tiny (denormal) nor huge vectors lose their direction. Returns
 * false, leaving *out untouched, for the zero vector or a non-finite one. */
static inline bool sx_query_unit(sx_vec2 v, sx_vec2 *out) {
    sx_real m = sx_maxr(sx_absr(v.x), sx_absr(v.y));
    sx_vec2 w;
    sx_real len;
    if (!(m > SX_R(0.0)) || !sx_is_finite(m)) return false;
    w = sx_v2(v.x / m, v.y / m);
    len = sx_length(w);
    *out = sx_v2(w.x / len, w.y / len);
    return true;
}

static inline bool sx_query_radius_ok(sx_real r) { return sx_is_finite(r) && r >= SX_R(0.0); }

/* True when a shape can be queried: known type, finite coordinates, a finite
 * non-negative radius, a polygon count in 3..SX_MAX_POLYGON_VERTICES. Queries
 * answer anything else as "not there" instead of reading garbage. */
static inline bool sx_query_shape_ok(const sx_shape *s) {
    int i;
    if (s == NULL) return false;
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        return sx_vec2_is_finite(s->u.circle.center) && sx_query_radius_ok(s->u.circle.radius);
    case SX_SHAPE_SEGMENT:
        return sx_vec2_is_finite(s->u.segment.a) && sx_vec2_is_finite(s->u.segment.b);
    case SX_SHAPE_CAPSULE:
        return sx_vec2_is_finite(s->u.capsule.a) && sx_vec2_is_finite(s->u.capsule.b) &&
               sx_query_radius_ok(s->u.capsule.radius);
    case SX_SHAPE_POLYGON:
        if (s->u.polygon.count < 3 || s->u.polygon.count > SX_MAX_POLYGON_VERTICES) return false;
        if (!sx_query_radius_ok(s->u.polygon.radius)) return false;
        for (i = 0; i < s->u.polygon.count; ++i) {
            if (!sx_vec2_is_finite(s->u.polygon.vertices[i]) ||
                !sx_vec2_is_finite(s->u.polygon.normals[i])) {
                return false;
            }
        }
        return true;
    default: return false;
    }
}

#endif /* SEPAX_QUERY_H */
