/* sepax — shape constructors, the polygon builder's last step (normals and
 * centroid from a valid hull), validation, mass properties and bounds.
 *
 * Constructors of circles, segments, capsules and boxes are plain value
 * builders that never fail; sx_shape_validate says whether a value is usable.
 * Polygons only come out of sx_polygon_from_hull (and the builders that feed
 * it), which refuses anything that is not a finite, non-degenerate,
 * counter-clockwise convex hull, so code downstream can trust every polygon.
 * Mass properties are exact sums of simple parts (triangles, rectangles,
 * disc sectors) taken about a reference point near the shape's centre in the
 * wide real of wide.h, so a unit box 1e5 m from the origin keeps its inertia.
 * Bounds are the hot-path functions: they trust the shape but clamp the
 * polygon count and never return NaN. */
#include "wide.h"

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

/* ---- polygons --------------------------------------------------------------- */

/* Outward unit normal of the edge a -> b of a CCW polygon, normalised in the
 * wide type so even edges near SX_REAL_EPSILON long get a unit normal. */
static sx_vec2 edge_normal(sx_vec2 a, sx_vec2 b) {
    sx_wvec2 e = sx_wdiff(b, a);
    sx_wide len = sx_wsqrt(sx_wdot(e, e));
    return sx_narrow(sx_wv(e.y / len, -e.x / len));
}

/* Area moments of a shape about a reference point `origin` near its centre
 * (so the sums stay small relative to the shape even far from the world
 * origin): area, first moment (area times centroid offset) and polar second
 * moment, all for unit density. */
typedef struct area_moments {
    sx_wvec2 origin;
    sx_wide area;
    sx_wvec2 first;
    sx_wide second;
} area_moments;

/* Adds a part of the given area whose centroid is `c` (relative to the
 * origin) and whose polar second moment about its own centroid is `own`. */
static void add_part(area_moments *m, sx_wide area, sx_wvec2 c, sx_wide own) {
    m->area += area;
    m->first = sx_wadd(m->first, sx_wscale(c, area));
    m->second += own + area * sx_wdot(c, c);
}

/* A polygon rounded by r is its core, plus one r-thick rectangle on the
 * outside of each edge, plus a circular sector at each vertex spanning the
 * angle between the two adjacent edge normals; the sectors' angles sum to
 * 2 pi, so together they are one disc, and the sum is exact. */
static area_moments polygon_moments(const sx_polygon *p, sx_real radius) {
    area_moments m;
    sx_wvec2 v[SX_MAX_POLYGON_VERTICES];
    sx_wide r = (sx_wide)radius;
    int i, n = p->count;
    m.origin = sx_wv(SX_W(0.0), SX_W(0.0));
    for (i = 0; i < n; ++i)
        m.origin = sx_wadd(m.origin, sx_widen(p->vertices[i]));
    m.origin = sx_wscale(m.origin, SX_W(1.0) / (sx_wide)n);
    m.area = SX_W(0.0);
    m.first = sx_wv(SX_W(0.0), SX_W(0.0));
    m.second = SX_W(0.0);
    for (i = 0; i < n; ++i)
        v[i] = sx_wsub(sx_widen(p->vertices[i]), m.origin);
    /* Core: a fan of triangles (origin, v_i, v_i+1); the origin (the vertex
     * average) is inside the convex polygon. */
    for (i = 0; i < n; ++i) {
        sx_wvec2 e1 = v[i], e2 = v[(i + 1) % n];
        sx_wide d = sx_wcross(e1, e2);
        m.area += SX_W(0.5) * d;
        m.first = sx_wadd(m.first, sx_wscale(sx_wadd(e1, e2), d / SX_W(6.0)));
        m.second += d / SX_W(12.0) * (sx_wdot(e1, e1) + sx_wdot(e1, e2) + sx_wdot(e2, e2));
    }
    if (r > SX_W(0.0)) {
        for (i = 0; i < n; ++i) {
            sx_wvec2 a = v[i], b = v[(i + 1) % n], prev = v[(i + n - 1) % n];
            sx_wvec2 e = sx_wsub(b, a), ep = sx_wsub(a, prev);
            sx_wide len = sx_wsqrt(sx_wdot(e, e)), len_p = sx_wsqrt(sx_wdot(ep, ep));
            sx_wvec2 nrm, nrm_p, u;
            sx_wide theta, k, area;
            if (!(len > SX_W(0.0)) || !(len_p > SX_W(0.0))) continue;
            nrm = sx_wv(e.y / len, -e.x / len);
            nrm_p = sx_wv(ep.y / len_p, -ep.x / len_p);
            area = len * r;
            add_part(&m, area,
                     sx_wadd(sx_wscale(sx_wadd(a, b), SX_W(0.5)), sx_wscale(nrm, SX_W(0.5) * r)),
                     area * (len * len + r * r) / SX_W(12.0));
            /* Corner sector at a, from nrm_p to nrm; its centroid lies on the
             * bisector at 4 r sin(theta/2) / (3 theta) from a. */
            theta = sx_watan2(sx_wcross(nrm_p, nrm), sx_wdot(nrm_p, nrm));
            if (!(theta > SX_W(0.0))) continue;
            u = sx_wv(sx_wcos(SX_W(0.5) * theta) * nrm_p.x - sx_wsin(SX_W(0.5) * theta) * nrm_p.y,
                      sx_wsin(SX_W(0.5) * theta) * nrm_p.x + sx_wcos(SX_W(0.5) * theta) * nrm_p.y);
            k = SX_W(4.0) * r * sx_wsin(SX_W(0.5) * theta) / (SX_W(3.0) * theta);
            area = SX_W(0.5) * theta * r * r;
            add_part(&m, area, sx_wadd(a, sx_wscale(u, k)),
                     SX_W(0.25) * theta * r * r * r * r - area * k * k);
        }
    }
    return m;
}

/* The centroid of the sharp core, or false when its area, summed in the
 * wide real about the vertex average, is not positive or the centroid is not
 * finite. A hull that passes sx_validate_hull has a positive area in exact
 * arithmetic, but far beyond SX_HUGE (coordinates ~1e18 in the float build)
 * the rounding of a sliver's moments can make it zero or negative: no mass
 * properties can be had from such a polygon, and it is refused as
 * degenerate by the builder and by sx_shape_validate alike. */
static bool core_centroid(const sx_polygon *p, sx_vec2 *centroid) {
    area_moments m = polygon_moments(p, SX_R(0.0));
    sx_wvec2 c;
    if (!(m.area > SX_W(0.0))) return false;
    c = sx_wadd(m.origin, sx_wscale(m.first, SX_W(1.0) / m.area));
    *centroid = sx_narrow(c);
    return sx_vec2_is_finite(*centroid);
}

/* SX_OK when a valid shape's area and rotational inertia at unit density
 * fit sx_real, SX_ERR_NONFINITE when either overflows it (both are summed in
 * the wide real, which does not overflow for finite input): a circle of
 * radius 1e10 in the float build is a fine geometric value, but a body made
 * of it would have an infinite mass or inertia. */
static sx_status validate_mass(const sx_shape *shape) {
    sx_wide area, inertia;
    sx_wvec2 center;
    sx_shape_wide_mass(shape, &area, &center, &inertia);
    if (!(area <= (sx_wide)SX_REAL_MAX) || !(inertia <= (sx_wide)SX_REAL_MAX)) {
        return SX_ERR_NONFINITE;
    }
    return SX_OK;
}

sx_status sx_polygon_from_hull(const sx_hull *hull, sx_real radius, sx_shape *out) {
    sx_shape s;
    sx_polygon *p = &s.u.polygon;
    int i, n;
    if (hull == NULL || out == NULL) return SX_ERR_INVALID_ARG;
    n = hull->count;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return SX_ERR_INVALID_ARG;
    if (!sx_is_finite(radius)) return SX_ERR_NONFINITE;
    if (radius < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    for (i = 0; i < n; ++i) {
        if (!sx_vec2_is_finite(hull->points[i])) return SX_ERR_NONFINITE;
    }
    if (sx_warea2(hull->points, n) == SX_W(0.0)) return SX_ERR_DEGENERATE;
    if (!sx_validate_hull(hull, SX_R(0.0))) return SX_ERR_INVALID_ARG;
    s.type = SX_SHAPE_POLYGON;
    p->count = n;
    p->radius = SX_R(0.0);
    for (i = 0; i < n; ++i) {
        p->vertices[i] = hull->points[i];
        p->normals[i] = edge_normal(hull->points[i], hull->points[(i + 1) % n]);
    }
    for (i = n; i < SX_MAX_POLYGON_VERTICES; ++i) {
        p->vertices[i] = sx_v2_zero();
        p->normals[i] = sx_v2_zero();
    }
    if (!core_centroid(p, &p->centroid)) return SX_ERR_DEGENERATE;
    p->radius = radius;
    if (validate_mass(&s) != SX_OK) return SX_ERR_NONFINITE;
    *out = s;
    return SX_OK;
}

sx_status sx_polygon_shape_ex(const sx_vec2 *points, int count, sx_real radius,
                              sx_real weld_tolerance, sx_shape *out) {
    sx_hull hull;
    sx_status st;
    if (points == NULL || out == NULL || count < 0) return SX_ERR_INVALID_ARG;
    if (!sx_is_finite(radius)) return SX_ERR_NONFINITE;
    if (radius < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    st = sx_compute_hull(points, count, weld_tolerance, &hull);
    if (st != SX_OK) return st;
    return sx_polygon_from_hull(&hull, radius, out);
}

sx_status sx_polygon_shape(const sx_vec2 *points, int count, sx_real radius, sx_shape *out) {
    return sx_polygon_shape_ex(points, count, radius, SX_WELD_TOLERANCE, out);
}

/* ---- validation ------------------------------------------------------------- */

static sx_status validate_radius(sx_real radius) {
    if (!sx_is_finite(radius)) return SX_ERR_NONFINITE;
    return radius < SX_R(0.0) ? SX_ERR_INVALID_ARG : SX_OK;
}

static sx_status validate_polygon(const sx_polygon *p) {
    sx_hull hull;
    sx_vec2 c;
    sx_real min_cos;
    int i, n = p->count;
    if (n < 3 || n > SX_MAX_POLYGON_VERTICES) return SX_ERR_INVALID_ARG;
    for (i = 0; i < n; ++i) {
        if (!sx_vec2_is_finite(p->vertices[i]) || !sx_vec2_is_finite(p->normals[i])) {
            return SX_ERR_NONFINITE;
        }
    }
    if (!sx_vec2_is_finite(p->centroid)) return SX_ERR_NONFINITE;
    if (validate_radius(p->radius) != SX_OK) return validate_radius(p->radius);
    for (i = 0; i < n; ++i)
        hull.points[i] = p->vertices[i];
    hull.count = n;
    if (sx_warea2(hull.points, n) == SX_W(0.0)) return SX_ERR_DEGENERATE;
    if (!sx_validate_hull(&hull, SX_R(0.0))) return SX_ERR_INVALID_ARG;
    /* A stored normal may lean from its edge by up to the angular slop: an
     * offset box far from the origin rounds its vertices, not its normals.
     * But only as far as that rounding explains: the edge's far end may sit
     * off the line through its near end (with the stored normal) by a few
     * ulps of the coordinates, no more. The narrowphase takes each face as
     * that line, and the clipping takes the vertices: a 22 m edge whose
     * normal leaned 0.4 degrees (9 cm off at the far end) made the manifold
     * and the MTV of the same pair disagree by 18 cm. */
    min_cos = sx_cos(SX_ANGULAR_SLOP);
    for (i = 0; i < n; ++i) {
        sx_vec2 nrm = p->normals[i], v0 = p->vertices[i], v1 = p->vertices[(i + 1) % n];
        sx_wide scale = (sx_wide)sx_maxr(sx_maxr(sx_absr(v0.x), sx_absr(v0.y)),
                                         sx_maxr(sx_absr(v1.x), sx_absr(v1.y)));
        sx_wide off = sx_wdot(sx_widen(nrm), sx_wdiff(v1, v0)); /* wide: no overflow */
        if (!sx_is_normalized(nrm)) return SX_ERR_INVALID_ARG;
        if (sx_dot(nrm, edge_normal(v0, v1)) < min_cos) return SX_ERR_INVALID_ARG;
        if (!((off < SX_W(0.0) ? -off : off) <= SX_W(64.0) * (sx_wide)SX_REAL_EPSILON * scale)) {
            return SX_ERR_INVALID_ARG;
        }
    }
    /* Positive area in the arithmetic the mass properties use (see
     * core_centroid): what the builder refuses is refused here too. */
    if (!core_centroid(p, &c)) return SX_ERR_DEGENERATE;
    return SX_OK;
}

sx_status sx_shape_validate(const sx_shape *shape) {
    sx_status st;
    if (shape == NULL) return SX_ERR_INVALID_ARG;
    switch (shape->type) {
    case SX_SHAPE_CIRCLE:
        if (!sx_vec2_is_finite(shape->u.circle.center)) return SX_ERR_NONFINITE;
        st = validate_radius(shape->u.circle.radius);
        break;
    case SX_SHAPE_SEGMENT: {
        /* no area: no mass to overflow */
        const sx_segment *s = &shape->u.segment;
        sx_real len;
        if (!sx_vec2_is_finite(s->a) || !sx_vec2_is_finite(s->b)) return SX_ERR_NONFINITE;
        sx_normalize_len(sx_sub(s->b, s->a), &len);
        return len == SX_R(0.0) ? SX_ERR_DEGENERATE : SX_OK;
    }
    case SX_SHAPE_CAPSULE: {
        const sx_capsule *c = &shape->u.capsule;
        if (!sx_vec2_is_finite(c->a) || !sx_vec2_is_finite(c->b)) return SX_ERR_NONFINITE;
        st = validate_radius(c->radius);
        break;
    }
    case SX_SHAPE_POLYGON: st = validate_polygon(&shape->u.polygon); break;
    default: return SX_ERR_INVALID_ARG;
    }
    return st != SX_OK ? st : validate_mass(shape);
}

/* ---- mass properties ---------------------------------------------------------- */

/* Moments of a shape already validated. */
static area_moments shape_moments(const sx_shape *shape) {
    area_moments m;
    m.area = SX_W(0.0);
    m.first = sx_wv(SX_W(0.0), SX_W(0.0));
    m.second = SX_W(0.0);
    m.origin = sx_wv(SX_W(0.0), SX_W(0.0));
    switch (shape->type) {
    case SX_SHAPE_CIRCLE: {
        sx_wide r = (sx_wide)shape->u.circle.radius;
        m.origin = sx_widen(shape->u.circle.center);
        m.area = SX_WPI * r * r;
        m.second = SX_W(0.5) * m.area * r * r;
        break;
    }
    case SX_SHAPE_SEGMENT:
        m.origin = sx_wscale(sx_wadd(sx_widen(shape->u.segment.a), sx_widen(shape->u.segment.b)),
                             SX_W(0.5));
        break;
    case SX_SHAPE_CAPSULE: {
        /* A 2r x L rectangle plus two half discs; each half disc's second
         * moment about the capsule centre follows from its own centroid,
         * 4r / (3 pi) from its flat side, by the parallel-axis theorem. */
        const sx_capsule *c = &shape->u.capsule;
        sx_wvec2 d = sx_wdiff(c->b, c->a);
        sx_wide len = sx_wsqrt(sx_wdot(d, d)), r = (sx_wide)c->radius;
        sx_wide rect = SX_W(2.0) * r * len, disc = SX_WPI * r * r;
        m.origin = sx_wscale(sx_wadd(sx_widen(c->a), sx_widen(c->b)), SX_W(0.5));
        m.area = rect + disc;
        m.second = rect * (len * len + SX_W(4.0) * r * r) / SX_W(12.0) +
                   disc * (SX_W(0.5) * r * r + SX_W(0.25) * len * len) +
                   SX_W(4.0) / SX_W(3.0) * r * r * r * len;
        break;
    }
    case SX_SHAPE_POLYGON: m = polygon_moments(&shape->u.polygon, shape->u.polygon.radius); break;
    default: break;
    }
    return m;
}

static sx_wvec2 moments_centroid(const area_moments *m) {
    if (!(m->area > SX_W(0.0))) return m->origin;
    return sx_wadd(m->origin, sx_wscale(m->first, SX_W(1.0) / m->area));
}

sx_real sx_shape_area(const sx_shape *shape) {
    area_moments m;
    if (sx_shape_validate(shape) != SX_OK) return SX_R(0.0);
    m = shape_moments(shape);
    return (sx_real)m.area;
}

sx_vec2 sx_shape_centroid(const sx_shape *shape) {
    area_moments m;
    if (shape != NULL && shape->type == SX_SHAPE_SEGMENT && sx_vec2_is_finite(shape->u.segment.a) &&
        sx_vec2_is_finite(shape->u.segment.b)) {
        return sx_lerp(shape->u.segment.a, shape->u.segment.b, SX_R(0.5));
    }
    if (sx_shape_validate(shape) != SX_OK) return sx_v2_zero();
    m = shape_moments(shape);
    return sx_narrow(moments_centroid(&m));
}

void sx_shape_wide_mass(const sx_shape *shape, sx_wide *area, sx_wvec2 *center, sx_wide *inertia) {
    area_moments m = shape_moments(shape);
    sx_wide j = SX_W(0.0);
    *center = moments_centroid(&m);
    if (m.area > SX_W(0.0)) {
        /* Parallel-axis theorem, from the reference point to the centroid;
         * the reference is near the centroid so little cancels. */
        j = m.second - sx_wdot(m.first, m.first) / m.area;
        if (!(j > SX_W(0.0))) j = SX_W(0.0);
        *area = m.area;
    } else {
        *area = SX_W(0.0);
    }
    *inertia = j;
}

sx_mass_data sx_shape_mass(const sx_shape *shape, sx_real density) {
    sx_mass_data md;
    sx_wide rho, area, inertia;
    sx_wvec2 center;
    md.mass = SX_R(0.0);
    md.center = sx_v2_zero();
    md.rotational_inertia = SX_R(0.0);
    if (!sx_is_finite(density) || density < SX_R(0.0)) return md;
    if (sx_shape_validate(shape) != SX_OK) return md;
    sx_shape_wide_mass(shape, &area, &center, &inertia);
    rho = (sx_wide)density;
    md.center = sx_narrow(center);
    if (!(area > SX_W(0.0))) return md;
    md.mass = (sx_real)(rho * area);
    md.rotational_inertia = (sx_real)(rho * inertia);
    return md;
}

/* ---- bounds ------------------------------------------------------------------- */

/* The empty box at the transform's origin (or the world origin): the answer
 * for a shape that has no meaningful bounds. */
static sx_aabb point_box(sx_xform x) {
    sx_vec2 p = sx_vec2_is_finite(x.p) ? x.p : sx_v2_zero();
    return sx_aabb_make(p, p);
}

static sx_aabb points_box(sx_xform x, const sx_vec2 *v, int n, sx_real radius) {
    sx_vec2 lo = sx_xform_point(x, v[0]), hi = lo, r = sx_v2(radius, radius);
    int i;
    for (i = 1; i < n; ++i) {
        sx_vec2 w = sx_xform_point(x, v[i]);
        lo = sx_vmin(lo, w);
        hi = sx_vmax(hi, w);
    }
    return sx_aabb_make(sx_sub(lo, r), sx_add(hi, r));
}

sx_aabb sx_shape_aabb(const sx_shape *shape, sx_xform x) {
    sx_aabb b;
    if (shape == NULL) return point_box(x);
    switch (shape->type) {
    case SX_SHAPE_CIRCLE:
        b = points_box(x, &shape->u.circle.center, 1, shape->u.circle.radius);
        break;
    case SX_SHAPE_SEGMENT: {
        sx_vec2 v[2];
        v[0] = shape->u.segment.a;
        v[1] = shape->u.segment.b;
        b = points_box(x, v, 2, SX_R(0.0));
        break;
    }
    case SX_SHAPE_CAPSULE: {
        sx_vec2 v[2];
        v[0] = shape->u.capsule.a;
        v[1] = shape->u.capsule.b;
        b = points_box(x, v, 2, shape->u.capsule.radius);
        break;
    }
    case SX_SHAPE_POLYGON: {
        const sx_polygon *p = &shape->u.polygon;
        if (p->count < 1 || p->count > SX_MAX_POLYGON_VERTICES) return point_box(x);
        b = points_box(x, p->vertices, p->count, p->radius);
        break;
    }
    default: return point_box(x);
    }
    /* NaN anywhere, or a negative radius, fails this. */
    if (!(b.lower.x <= b.upper.x && b.lower.y <= b.upper.y)) return point_box(x);
    return b;
}

static sx_real max_dot(const sx_vec2 *v, int n, sx_vec2 axis) {
    sx_real best = sx_dot(v[0], axis);
    int i;
    for (i = 1; i < n; ++i)
        best = sx_maxr(best, sx_dot(v[i], axis));
    return best;
}

static sx_real shape_support(const sx_shape *shape, sx_vec2 axis) {
    switch (shape->type) {
    case SX_SHAPE_CIRCLE:
        return sx_dot(shape->u.circle.center, axis) + shape->u.circle.radius * sx_length(axis);
    case SX_SHAPE_SEGMENT:
        return sx_maxr(sx_dot(shape->u.segment.a, axis), sx_dot(shape->u.segment.b, axis));
    case SX_SHAPE_CAPSULE:
        return sx_maxr(sx_dot(shape->u.capsule.a, axis), sx_dot(shape->u.capsule.b, axis)) +
               shape->u.capsule.radius * sx_length(axis);
    case SX_SHAPE_POLYGON: {
        const sx_polygon *p = &shape->u.polygon;
        if (p->count < 1 || p->count > SX_MAX_POLYGON_VERTICES) return SX_R(0.0);
        return max_dot(p->vertices, p->count, axis) + p->radius * sx_length(axis);
    }
    default: return SX_R(0.0);
    }
}

sx_real sx_shape_support(const sx_shape *shape, sx_vec2 axis) {
    sx_real h;
    if (shape == NULL) return SX_R(0.0);
    h = shape_support(shape, axis);
    return h == h ? h : SX_R(0.0); /* NaN in the shape or the axis */
}
