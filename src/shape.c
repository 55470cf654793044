/* sepax — shape constructors, the polygon builder's last step (normals and
 * centroid from a valid hull), validation, mass properties and bounds.
 *
 * Constructors of circles, segments, capsules and boxes are plain value
 * builders that never fail; sx_shape_validate says whether a value is usable.
 * Polygons only come out of sx_polygon_from_hull (and the builders that feed
 * it), which refuses anything that is not a finite, non-degenerate,
 * counter-clockwise convex hull, so code downstream can trust every polygon. */
#include "core.h"

sx_shape sx_circle_shape(sx_vec2 center, sx_real radius) {
    sx_shape s;
    s.type = SX_SHAPE_CIRCLE;
    s.u.circle.center = center;
    s.u.circle.radius = radius;
    return s;
}

sx_shape sx_point_shape(sx_vec2 p) { return sx_circle_shape(p, SX_R(0.0)); }

sx_shape sx_segment_shape(sx_vec2 a, sx_vec2 b) {
    sx_shape s;
    s.type = SX_SHAPE_SEGMENT;
    s.u.segment.a = a;
    s.u.segment.b = b;
    return s;
}

sx_shape sx_capsule_shape(sx_vec2 a, sx_vec2 b, sx_real radius) {
    sx_shape s;
    s.type = SX_SHAPE_CAPSULE;
    s.u.capsule.a = a;
    s.u.capsule.b = b;
    s.u.capsule.radius = radius;
    return s;
}

sx_shape sx_offset_box_shape(sx_real half_width, sx_real half_height, sx_vec2 center,
                             sx_real angle) {
    sx_shape s;
    sx_polygon *p = &s.u.polygon;
    sx_xform x;
    int i;
    x.p = center;
    x.q = angle == SX_R(0.0) ? sx_rot_identity() : sx_rot_make(angle);
    s.type = SX_SHAPE_POLYGON;
    p->count = 4;
    p->radius = SX_R(0.0);
    p->vertices[0] = sx_xform_point(x, sx_v2(-half_width, -half_height));
    p->vertices[1] = sx_xform_point(x, sx_v2(half_width, -half_height));
    p->vertices[2] = sx_xform_point(x, sx_v2(half_width, half_height));
    p->vertices[3] = sx_xform_point(x, sx_v2(-half_width, half_height));
    p->normals[0] = sx_rotate(x.q, sx_v2(SX_R(0.0), SX_R(-1.0)));
    p->normals[1] = sx_rotate(x.q, sx_v2(SX_R(1.0), SX_R(0.0)));
    p->normals[2] = sx_rotate(x.q, sx_v2(SX_R(0.0), SX_R(1.0)));
    p->normals[3] = sx_rotate(x.q, sx_v2(SX_R(-1.0), SX_R(0.0)));
    p->centroid = center;
    for (i = 4; i < SX_MAX_POLYGON_VERTICES; ++i) {
        p->vertices[i] = sx_v2_zero();
        p->normals[i] = sx_v2_zero();
    }
    return s;
}

sx_shape sx_box_shape(sx_real half_width, sx_real half_height) {
    return sx_offset_box_shape(half_width, half_height, sx_v2_zero(), SX_R(0.0));
}

sx_status sx_polygon_from_hull(const sx_hull *hull, sx_real radius, sx_shape *out) {
    sx_shape s;
    sx_polygon *p = &s.u.polygon;
    sx_vec2 origin, c;
    sx_real area2 = SX_R(0.0);
    int i, n;
    if (hull == NULL || out == NULL) return SX_ERR_INVALID_ARG;
    n = hull->count;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return SX_ERR_INVALID_ARG;
    if (!sx_is_finite(radius)) return SX_ERR_NONFINITE;
    if (radius < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    for (i = 0; i < n; ++i) {
        if (!sx_vec2_is_finite(hull->points[i])) return SX_ERR_NONFINITE;
    }
    s.type = SX_SHAPE_POLYGON;
    p->count = n;
    p->radius = radius;
    /* Centroid by triangle fan about the first vertex: sums stay small
     * relative to the polygon's size even far from the origin. */
    origin = hull->points[0];
    c = sx_v2_zero();
    for (i = 0; i < n; ++i) {
        sx_vec2 e1 = sx_sub(hull->points[i], origin);
        sx_vec2 e2 = sx_sub(hull->points[(i + 1) % n], origin);
        sx_vec2 e = sx_sub(hull->points[(i + 1) % n], hull->points[i]);
        sx_real len;
        sx_real a2 = sx_cross(e1, e2);
        area2 += a2;
        c = sx_mul_add(c, a2, sx_add(e1, e2));
        p->vertices[i] = hull->points[i];
        p->normals[i] = sx_normalize_len(sx_v2(e.y, -e.x), &len);
        if (len == SX_R(0.0)) return SX_ERR_DEGENERATE;
    }
    if (!(area2 > SX_R(0.0)) || !sx_is_finite(area2)) return SX_ERR_DEGENERATE;
    p->centroid = sx_add(origin, sx_scale(c, SX_R(1.0) / (SX_R(3.0) * area2)));
    for (i = n; i < SX_MAX_POLYGON_VERTICES; ++i) {
        p->vertices[i] = sx_v2_zero();
        p->normals[i] = sx_v2_zero();
    }
    *out = s;
    return SX_OK;
}
