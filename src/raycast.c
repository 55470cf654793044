/* sepax — ray casts against every shape.
 *
 * The ray is moved into the shape's local frame first, so a shape far from
 * the world origin is cast against with small numbers, and its direction is
 * split into a unit vector and a length: every routine below measures
 * distances along the unit direction and divides by the length once at the
 * end. Each shape is exact: circles solve the quadratic in its cancellation-
 * free form, segments intersect two lines, polygons clip the ray against the
 * edge half-planes (slab clipping), and rounded shapes (capsules, rounded
 * polygons) take the first hit over their offset edges and their corner
 * circles. That last step is exact because every one of those pieces lies in
 * the closed shape, so none can be reached before the ray has entered it, and
 * the boundary is made of them. A ray that starts inside (or on) a solid shape
 * hits it at once, with the normal facing back along the ray. */
#include "query.h"

/* A hit in the local frame: distance along the unit direction and the
 * outward normal facing the ray. */
typedef struct local_hit {
    sx_real distance;
    sx_vec2 normal;
} local_hit;

/* The ray in the local frame: origin o, unit direction u, and the longest
 * distance along u that counts (max_fraction x |translation|). */
typedef struct local_ray {
    sx_vec2 o, u;
    sx_real max_distance;
} local_ray;

static bool starts_inside(local_hit *hit, const local_ray *ray) {
    hit->distance = SX_R(0.0);
    hit->normal = sx_neg(ray->u);
    return true;
}

/* The disc of radius r around c. With m = o - c and b the distance to the
 * closest approach, the entry distance b - sqrt(r^2 - h^2) is rewritten as
 * (|m|^2 - r^2) / (b + sqrt(r^2 - h^2)): the same number without the
 * cancellation of the textbook root when the ray starts close to the circle.
 * h, the miss distance, comes from a cross product, accurate at grazing. */
static bool cast_circle(sx_vec2 c, sx_real r, const local_ray *ray, local_hit *hit) {
    sx_vec2 m = sx_sub(ray->o, c);
    sx_real c2 = sx_dot(m, m) - r * r;
    sx_real b, h, q2, dist;
    if (c2 <= SX_R(0.0)) return starts_inside(hit, ray);
    b = -sx_dot(m, ray->u);
    if (!(b > SX_R(0.0))) return false;
    h = sx_absr(sx_cross(ray->u, m));
    q2 = (r - h) * (r + h);
    if (q2 < SX_R(0.0)) return false;
    dist = c2 / (b + sx_sqrt(q2));
    if (dist > ray->max_distance) return false;
    hit->distance = dist;
    if (!sx_query_unit(sx_mul_add(m, dist, ray->u), &hit->normal)) hit->normal = sx_neg(ray->u);
    return true;
}

/* A two-sided segment a-b of non-zero length: o + t u = a + v e solved with
 * cross products. A ray along the segment's own line meets its nearer end
 * point (or starts on it). */
static bool cast_segment(sx_vec2 a, sx_vec2 b, const local_ray *ray, local_hit *hit) {
    const sx_real tol = SX_QUERY_REL_TOLERANCE;
    sx_vec2 e = sx_sub(b, a), en, w = sx_sub(a, ray->o);
    sx_real elen, denom, scale, t, v;
    if (!sx_query_unit(e, &en)) return cast_circle(a, SX_R(0.0), ray, hit);
    elen = sx_dot(e, en);
    denom = sx_cross(ray->u, en);
    scale = sx_maxr(elen, sx_length(w));
    if (sx_absr(denom) <= tol) {
        sx_real ta, tb;
        /* cross(w, en) is the distance of the origin from the line. A ray
         * this close to parallel that still crosses the segment does so
         * within 2 x scale of its origin, so it starts within 2 tol scale of
         * the line: every such ray counts as running along it. */
        if (sx_absr(sx_cross(w, en)) > SX_R(2.0) * tol * scale) return false;
        ta = sx_dot(w, ray->u);
        tb = sx_dot(sx_sub(b, ray->o), ray->u);
        if (sx_maxr(ta, tb) < SX_R(0.0)) return false;
        t = sx_maxr(sx_minr(ta, tb), SX_R(0.0));
        if (t > ray->max_distance) return false;
        hit->distance = t;
        hit->normal = sx_neg(ray->u);
        return true;
    }
    t = sx_cross(w, en) / denom;
    v = sx_cross(w, ray->u) / denom;
    /* Slack of a few ulps of the configuration's size, so a ray through an
     * end point, or starting on the segment, is not lost to rounding. */
    if (t < -tol * scale || v < -tol * scale || v > elen + tol * scale) return false;
    t = sx_maxr(t, SX_R(0.0));
    if (t > ray->max_distance) return false;
    hit->distance = t;
    hit->normal = sx_perp(en);
    if (sx_dot(hit->normal, ray->u) > SX_R(0.0)) hit->normal = sx_neg(hit->normal);
    return true;
}

/* One face of a rounded shape: the edge v1-v2 (unit direction en, length
 * elen) pushed out by r along its outward unit normal n. Only entry counts:
 * the ray must be outside the face's line and moving in. */
static bool cast_offset_edge(sx_vec2 v1, sx_vec2 en, sx_real elen, sx_vec2 n, sx_real r,
                             const local_ray *ray, local_hit *hit) {
    sx_vec2 w = sx_sub(ray->o, v1);
    sx_real dn = sx_dot(n, ray->u);
    sx_real sep, dist, along;
    if (!(dn < SX_R(0.0))) return false;
    sep = sx_dot(n, w) - r;
    if (sep < SX_R(0.0)) return false;
    dist = sep / -dn;
    along = sx_dot(w, en) + dist * sx_dot(ray->u, en);
    if (along < SX_R(0.0) || along > elen || dist > ray->max_distance) return false;
    hit->distance = dist;
    hit->normal = n;
    return true;
}

static void keep_first(bool found, const local_hit *candidate, bool *any, local_hit *best) {
    if (found && (!*any || candidate->distance < best->distance)) {
        *best = *candidate;
        *any = true;
    }
}

static bool cast_capsule(const sx_capsule *cap, const local_ray *ray, local_hit *hit) {
    sx_real r = cap->radius, elen;
    sx_vec2 e = sx_sub(cap->b, cap->a), en, left, q;
    local_hit h;
    bool any = false;
    if (r == SX_R(0.0)) return cast_segment(cap->a, cap->b, ray, hit);
    if (!sx_query_unit(e, &en)) return cast_circle(cap->a, r, ray, hit);
    q = sx_closest_point_on_segment(cap->a, cap->b, ray->o, NULL);
    if (sx_distance_sq(q, ray->o) <= r * r) return starts_inside(hit, ray);
    elen = sx_dot(e, en);
    left = sx_perp(en);
    keep_first(cast_offset_edge(cap->a, en, elen, left, r, ray, &h), &h, &any, hit);
    keep_first(cast_offset_edge(cap->a, en, elen, sx_neg(left), r, ray, &h), &h, &any, hit);
    keep_first(cast_circle(cap->a, r, ray, &h), &h, &any, hit);
    keep_first(cast_circle(cap->b, r, ray, &h), &h, &any, hit);
    return any;
}

/* Slab clipping: the ray's parameter interval [lower, upper] shrinks at each
 * edge plane it enters or leaves; the polygon is hit where the last entry
 * happens, if the interval is still non-empty. No plane entered at a positive
 * distance means the origin is already inside. */
static bool cast_sharp_polygon(const sx_polygon *poly, const local_ray *ray, local_hit *hit) {
    sx_real lower = SX_R(0.0), upper = ray->max_distance;
    int i, index = -1;
    for (i = 0; i < poly->count; ++i) {
        sx_real num = sx_dot(poly->normals[i], sx_sub(poly->vertices[i], ray->o));
        sx_real den = sx_dot(poly->normals[i], ray->u);
        if (den == SX_R(0.0)) {
            if (num < SX_R(0.0)) return false;
        } else if (den < SX_R(0.0) && num < lower * den) {
            /* Entering, at num / den > lower (den < 0 flips the test). */
            lower = num / den;
            index = i;
        } else if (den > SX_R(0.0) && num < upper * den) {
            upper = num / den;
        }
        if (upper < lower) return false;
    }
    if (index < 0) return starts_inside(hit, ray);
    hit->distance = lower;
    hit->normal = poly->normals[index];
    return true;
}

static bool cast_rounded_polygon(const sx_polygon *poly, const local_ray *ray, local_hit *hit) {
    sx_real r = poly->radius, best_sep = -SX_REAL_MAX;
    int i, n = poly->count;
    local_hit h;
    bool any = false;
    for (i = 0; i < n; ++i) {
        sx_real sep = sx_dot(poly->normals[i], sx_sub(ray->o, poly->vertices[i]));
        best_sep = sx_maxr(best_sep, sep);
    }
    if (best_sep <= SX_R(0.0)) return starts_inside(hit, ray);
    if (best_sep <= r) {
        /* Outside the core but maybe within r of it: check the edges. */
        for (i = 0; i < n; ++i) {
            sx_vec2 q = sx_closest_point_on_segment(poly->vertices[i], poly->vertices[(i + 1) % n],
                                                    ray->o, NULL);
            if (sx_distance_sq(q, ray->o) <= r * r) return starts_inside(hit, ray);
        }
    }
    for (i = 0; i < n; ++i) {
        sx_vec2 v1 = poly->vertices[i], en;
        sx_vec2 e = sx_sub(poly->vertices[(i + 1) % n], v1);
        if (sx_query_unit(e, &en)) {
            keep_first(cast_offset_edge(v1, en, sx_dot(e, en), poly->normals[i], r, ray, &h), &h,
                       &any, hit);
        }
        keep_first(cast_circle(v1, r, ray, &h), &h, &any, hit);
    }
    return any;
}

bool sx_ray_cast(const sx_shape *s, sx_xform x, const sx_ray_input *ray, sx_ray_hit *out) {
    local_ray lr;
    local_hit h;
    sx_vec2 d, point;
    sx_real len, f;
    bool found;
    if (out != NULL) {
        out->point = sx_v2_zero();
        out->normal = sx_v2_zero();
        out->fraction = SX_R(0.0);
        out->hit = false;
    }
    if (ray == NULL || !sx_query_shape_ok(s) || !sx_xform_is_finite(x) ||
        !sx_vec2_is_finite(ray->origin) || !sx_vec2_is_finite(ray->translation) ||
        !sx_is_finite(ray->max_fraction) || ray->max_fraction < SX_R(0.0)) {
        return false;
    }
    lr.o = sx_xform_inv_point(x, ray->origin);
    d = sx_xform_inv_vector(x, ray->translation);
    if (!sx_vec2_is_finite(lr.o) || !sx_query_unit(d, &lr.u)) return false;
    len = sx_dot(d, lr.u);
    lr.max_distance = ray->max_fraction * len;
    if (!sx_is_finite(lr.max_distance)) lr.max_distance = SX_REAL_MAX;
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        found = cast_circle(s->u.circle.center, s->u.circle.radius, &lr, &h);
        break;
    case SX_SHAPE_SEGMENT: found = cast_segment(s->u.segment.a, s->u.segment.b, &lr, &h); break;
    case SX_SHAPE_CAPSULE: found = cast_capsule(&s->u.capsule, &lr, &h); break;
    default:
        found = s->u.polygon.radius > SX_R(0.0) ? cast_rounded_polygon(&s->u.polygon, &lr, &h)
                                                : cast_sharp_polygon(&s->u.polygon, &lr, &h);
        break;
    }
    if (!found) return false;
    f = sx_minr(h.distance / len, ray->max_fraction);
    point = sx_mul_add(ray->origin, f, ray->translation);
    /* Only coordinates near SX_REAL_MAX can overflow on the way back. */
    if (!sx_is_finite(f) || !sx_vec2_is_finite(point)) return false;
    if (out != NULL) {
        out->fraction = f;
        out->point = point;
        out->normal = sx_xform_vector(x, h.normal);
        out->hit = true;
    }
    return true;
}
