/* sepax — distance between shapes (GJK), shape casts and time of impact
 * (conservative advancement on that distance).
 *
 * Every shape is a convex core (1 to SX_MAX_POLYGON_VERTICES points) plus a
 * radius. GJK walks the Minkowski difference B - A of the cores with a
 * simplex of at most three support points, keeping the sub-simplex closest
 * to the origin, until a new support point brings it no closer: the closest
 * point's barycentric weights then give the closest points of both cores,
 * and the radii are taken off along the normal. All of it happens in A's
 * frame, with B's points placed there once.
 *
 * A cast or a time of impact advances the motion by the gap over a bound of
 * the closing speed along the current normal (Mirtich's conservative
 * advancement): the separation of the two cores along a fixed axis equals
 * the gap at the start and shrinks at most that fast, and the distance is
 * never below it, so no advance passes the contact. */
#include "distance.h"

#include <string.h>

#include "sepax/collide.h"

sx_status sx_proxy_make(const sx_shape *s, const sx_xform *offset, sx_proxy *out) {
    int i;
    memset(out, 0, sizeof(*out));
    if (s == NULL) return SX_ERR_INVALID_ARG;
    switch (s->type) {
    case SX_SHAPE_CIRCLE:
        out->p[0] = s->u.circle.center;
        out->radius = s->u.circle.radius;
        out->count = 1;
        break;
    case SX_SHAPE_SEGMENT:
        out->p[0] = s->u.segment.a;
        out->p[1] = s->u.segment.b;
        out->count = 2;
        break;
    case SX_SHAPE_CAPSULE:
        out->p[0] = s->u.capsule.a;
        out->p[1] = s->u.capsule.b;
        out->radius = s->u.capsule.radius;
        out->count = 2;
        break;
    case SX_SHAPE_POLYGON:
        if (s->u.polygon.count < 3 || s->u.polygon.count > SX_MAX_POLYGON_VERTICES) {
            return SX_ERR_INVALID_ARG;
        }
        out->count = s->u.polygon.count;
        for (i = 0; i < out->count; ++i)
            out->p[i] = s->u.polygon.vertices[i];
        out->radius = s->u.polygon.radius;
        break;
    default: return SX_ERR_INVALID_ARG;
    }
    if (out->radius != out->radius || out->radius < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    if (!sx_is_finite(out->radius)) return SX_ERR_NONFINITE;
    for (i = 0; i < out->count; ++i) {
        if (offset != NULL) out->p[i] = sx_xform_point(*offset, out->p[i]);
        if (!sx_vec2_is_finite(out->p[i])) return SX_ERR_NONFINITE;
    }
    return SX_OK;
}

/* ---- GJK ------------------------------------------------------------------ */

/* A simplex vertex: w = b[ib] - a[ia], with its barycentric weight u. */
typedef struct sx_simplex_vertex {
    sx_vec2 w;
    int ia, ib;
    sx_real u;
} sx_simplex_vertex;

typedef struct sx_gjk_result {
    sx_vec2 pa, pb;   /* closest points of the cores, working frame */
    sx_real distance; /* between the cores */
    int iterations;
    bool overlap; /* the cores touch or cross */
} sx_gjk_result;

static int sx_support(const sx_vec2 *p, int n, sx_vec2 d) {
    int i, best = 0;
    sx_real m = sx_dot(p[0], d);
    for (i = 1; i < n; ++i) {
        sx_real x = sx_dot(p[i], d);
        if (x > m) {
            m = x;
            best = i;
        }
    }
    return best;
}

/* The point of segment s[i]-s[j] closest to the origin: its weights in
 * *ui, *uj (one of them 0 in an end-point region) and its squared length. */
static sx_real sx_segment_closest(const sx_simplex_vertex *s, int i, int j, sx_real *ui,
                                  sx_real *uj) {
    sx_vec2 e = sx_sub(s[j].w, s[i].w);
    sx_real d1 = -sx_dot(s[i].w, e), d2 = sx_dot(s[j].w, e);
    sx_vec2 p;
    if (!(d1 > SX_R(0.0))) {
        *ui = SX_R(1.0);
        *uj = SX_R(0.0);
        return sx_dot(s[i].w, s[i].w);
    }
    if (!(d2 > SX_R(0.0))) {
        *ui = SX_R(0.0);
        *uj = SX_R(1.0);
        return sx_dot(s[j].w, s[j].w);
    }
    *ui = d2 / (d1 + d2);
    *uj = d1 / (d1 + d2);
    p = sx_add(sx_scale(s[i].w, *ui), sx_scale(s[j].w, *uj));
    return sx_dot(p, p);
}

/* Keeps the vertices of s with a positive weight, in order. */
static int sx_simplex_compact(sx_simplex_vertex *s, int n) {
    int i, k = 0;
    for (i = 0; i < n; ++i) {
        if (s[i].u > SX_R(0.0)) s[k++] = s[i];
    }
    return k;
}

/* Reduces the simplex to the feature closest to the origin and sets the
 * weights; returns the new count (3: the origin is inside the triangle). */
static int sx_simplex_solve(sx_simplex_vertex *s, int n) {
    if (n == 1) {
        s[0].u = SX_R(1.0);
        return 1;
    }
    if (n == 2) {
        sx_segment_closest(s, 0, 1, &s[0].u, &s[1].u);
        return sx_simplex_compact(s, 2);
    }
    {
        sx_real area = sx_cross(sx_sub(s[1].w, s[0].w), sx_sub(s[2].w, s[0].w));
        sx_real l0 = sx_cross(s[1].w, s[2].w), l1 = sx_cross(s[2].w, s[0].w);
        sx_real l2 = sx_cross(s[0].w, s[1].w);
        static const int edges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
        sx_real best = SX_REAL_MAX, ui = SX_R(0.0), uj = SX_R(0.0);
        int e, be = 0;
        if (area != SX_R(0.0) && l0 * area > SX_R(0.0) && l1 * area > SX_R(0.0) &&
            l2 * area > SX_R(0.0)) {
            s[0].u = l0 / area;
            s[1].u = l1 / area;
            s[2].u = l2 / area;
            return 3;
        }
        /* outside (or a flat triangle): the closest of the three edges */
        for (e = 0; e < 3; ++e) {
            sx_real a, b, d = sx_segment_closest(s, edges[e][0], edges[e][1], &a, &b);
            if (d < best) {
                best = d;
                be = e;
                ui = a;
                uj = b;
            }
        }
        s[0].u = s[1].u = s[2].u = SX_R(0.0);
        s[edges[be][0]].u = ui;
        s[edges[be][1]].u = uj;
        return sx_simplex_compact(s, 3);
    }
}

/* GJK between the cores a (na points) and b (nb points), both in one
 * frame. */
static void sx_gjk(const sx_vec2 *a, int na, const sx_vec2 *b, int nb, sx_gjk_result *r) {
    sx_simplex_vertex s[3];
    sx_real scale = SX_R(0.0);
    int n = 1, i, iter;
    sx_vec2 v = sx_v2_zero();
    for (i = 0; i < na; ++i)
        scale = sx_maxr(scale, sx_maxr(sx_absr(a[i].x), sx_absr(a[i].y)));
    for (i = 0; i < nb; ++i)
        scale = sx_maxr(scale, sx_maxr(sx_absr(b[i].x), sx_absr(b[i].y)));
    s[0].ia = 0;
    s[0].ib = 0;
    s[0].w = sx_sub(b[0], a[0]);
    s[0].u = SX_R(1.0);
    r->overlap = false;
    for (iter = 1; iter <= SX_GJK_MAX_ITERATIONS; ++iter) {
        sx_real vv, tiny;
        int ia, ib, k;
        bool known = false;
        sx_vec2 wn;
        r->iterations = iter;
        n = sx_simplex_solve(s, n);
        if (n == 3) {
            r->overlap = true;
            break;
        }
        v = sx_v2_zero();
        for (k = 0; k < n; ++k)
            v = sx_add(v, sx_scale(s[k].w, s[k].u));
        vv = sx_dot(v, v);
        /* a gap below the rounding of the coordinates is contact */
        tiny = SX_R(64.0) * SX_REAL_EPSILON * scale;
        if (!(vv > tiny * tiny)) {
            r->overlap = true;
            break;
        }
        ia = sx_support(a, na, v);
        ib = sx_support(b, nb, sx_neg(v));
        for (k = 0; k < n; ++k)
            known = known || (s[k].ia == ia && s[k].ib == ib);
        if (known) break;
        wn = sx_sub(b[ib], a[ia]);
        /* the new point is no closer along v than the simplex: converged */
        if (vv - sx_dot(v, wn) <= SX_R(16.0) * SX_REAL_EPSILON * vv) break;
        s[n].w = wn;
        s[n].ia = ia;
        s[n].ib = ib;
        s[n].u = SX_R(0.0);
        ++n;
    }
    r->pa = sx_v2_zero();
    r->pb = sx_v2_zero();
    for (i = 0; i < n; ++i) {
        r->pa = sx_add(r->pa, sx_scale(a[s[i].ia], s[i].u));
        r->pb = sx_add(r->pb, sx_scale(b[s[i].ib], s[i].u));
    }
    r->distance = r->overlap ? SX_R(0.0) : sx_length(sx_sub(r->pb, r->pa));
}

/* False when the coordinates overflowed on the way (far beyond SX_HUGE). */
static bool sx_gjk_finite(const sx_gjk_result *g) {
    return sx_vec2_is_finite(g->pa) && sx_vec2_is_finite(g->pb) && sx_is_finite(g->distance);
}

/* The gap of the rounded shapes (negative when overlapping) and the unit
 * normal from A to B; false when the cores touch or cross (no normal). */
static bool sx_gap(const sx_gjk_result *g, sx_real ra, sx_real rb, sx_real *gap, sx_vec2 *n) {
    sx_vec2 d = sx_sub(g->pb, g->pa);
    sx_real m = sx_maxr(sx_absr(d.x), sx_absr(d.y));
    if (g->overlap || !(g->distance > SX_R(0.0)) || !(m > SX_R(0.0))) return false;
    /* scaled by the larger component first: a gap down among the
     * denormals still gives a unit normal */
    d = sx_v2(d.x / m, d.y / m);
    *n = sx_scale(d, SX_R(1.0) / sx_length(d));
    *gap = g->distance - ra - rb;
    return true;
}

static sx_status sx_check_pair(const sx_shape *a, const sx_shape *b, sx_proxy *pa, sx_proxy *pb) {
    sx_status s = sx_proxy_make(a, NULL, pa);
    if (s == SX_OK) s = sx_proxy_make(b, NULL, pb);
    return s;
}

/* B's points placed by rel, false if any is not finite. */
static bool sx_place(const sx_proxy *b, sx_xform rel, sx_vec2 *out) {
    int i;
    for (i = 0; i < b->count; ++i) {
        out[i] = sx_xform_point(rel, b->p[i]);
        if (!sx_vec2_is_finite(out[i])) return false;
    }
    return true;
}

static sx_status sx_distance_run(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                                 sx_distance_output *out) {
    sx_proxy pa, pb;
    sx_vec2 bp[SX_MAX_POLYGON_VERTICES], n;
    sx_gjk_result g;
    sx_real gap;
    sx_status s;
    if (out == NULL) return SX_ERR_INVALID_ARG;
    memset(out, 0, sizeof(*out));
    s = sx_check_pair(a, b, &pa, &pb);
    if (s != SX_OK) return s;
    if (!sx_xform_is_finite(xa) || !sx_xform_is_finite(xb)) return SX_ERR_NONFINITE;
    if (!sx_place(&pb, sx_xform_inv_mul(xa, xb), bp)) return SX_ERR_NONFINITE;
    sx_gjk(pa.p, pa.count, bp, pb.count, &g);
    if (!sx_gjk_finite(&g)) return SX_ERR_NONFINITE;
    out->iterations = g.iterations;
    if (sx_gap(&g, pa.radius, pb.radius, &gap, &n)) {
        out->normal = sx_rotate(xa.q, n);
        if (gap > SX_R(0.0)) {
            out->distance = gap;
            out->point_a = sx_xform_point(xa, sx_mul_add(g.pa, pa.radius, n));
            out->point_b = sx_xform_point(xa, sx_mul_add(g.pb, -pb.radius, n));
        } else {
            /* rounded overlap: the middle of the overlap along the normal */
            sx_vec2 mid = sx_mul_add(g.pa, pa.radius + SX_R(0.5) * gap, n);
            out->overlap = gap < SX_R(0.0);
            out->point_a = out->point_b = sx_xform_point(xa, mid);
        }
        return SX_OK;
    }
    {
        /* the cores touch or cross: the manifold's normal and deepest point */
        sx_manifold m;
        out->overlap = true;
        out->point_a = out->point_b = sx_xform_point(xa, g.pa);
        if (sx_collide(a, xa, b, xb, &m) > 0) {
            int k = m.count > 1 && m.points[1].depth > m.points[0].depth ? 1 : 0;
            out->normal = m.normal;
            out->point_a = out->point_b = m.points[k].point;
        }
    }
    return SX_OK;
}

sx_status sx_shape_distance(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                            sx_distance_output *out) {
    sx_status s = sx_distance_run(a, xa, b, xb, out);
    if (s == SX_OK && !(sx_is_finite(out->distance) && sx_vec2_is_finite(out->point_a) &&
                        sx_vec2_is_finite(out->point_b) && sx_vec2_is_finite(out->normal))) {
        /* the answer overflowed sx_real on its way back to world space */
        s = SX_ERR_NONFINITE;
    }
    if (s != SX_OK && out != NULL) memset(out, 0, sizeof(*out));
    return s;
}

/* ---- shape cast --------------------------------------------------------- */

static sx_status sx_cast_run(const sx_shape *a, sx_xform xa, sx_vec2 translation,
                             sx_real max_fraction, const sx_shape *b, sx_xform xb,
                             sx_shape_cast_output *out) {
    sx_proxy pa, pb;
    sx_vec2 b0[SX_MAX_POLYGON_VERTICES], bt[SX_MAX_POLYGON_VERTICES], u, n = sx_v2_zero();
    sx_real t = SX_R(0.0), gap = SX_R(0.0), rate = SX_R(0.0);
    sx_gjk_result g;
    sx_status s;
    int iter, i;
    bool apart = false;
    if (out == NULL) return SX_ERR_INVALID_ARG;
    memset(out, 0, sizeof(*out));
    s = sx_check_pair(a, b, &pa, &pb);
    if (s != SX_OK) return s;
    if (!sx_xform_is_finite(xa) || !sx_xform_is_finite(xb) || !sx_vec2_is_finite(translation) ||
        !sx_is_finite(max_fraction)) {
        return SX_ERR_NONFINITE;
    }
    if (max_fraction < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    if (!sx_place(&pb, sx_xform_inv_mul(xa, xb), b0)) return SX_ERR_NONFINITE;
    /* in A's frame at the start: A moving by u is B moving by -u */
    u = sx_inv_rotate(xa.q, translation);
    if (!sx_vec2_is_finite(sx_scale(u, max_fraction))) return SX_ERR_NONFINITE;
    for (iter = 1; iter <= SX_TOI_MAX_ITERATIONS; ++iter) {
        for (i = 0; i < pb.count; ++i)
            bt[i] = sx_mul_add(b0[i], -t, u);
        sx_gjk(pa.p, pa.count, bt, pb.count, &g);
        if (!sx_gjk_finite(&g)) {
            memset(out, 0, sizeof(*out));
            return SX_ERR_NONFINITE;
        }
        out->iterations = iter;
        apart = sx_gap(&g, pa.radius, pb.radius, &gap, &n);
        if (!apart || gap <= SX_CAST_TARGET + SX_TOI_TOLERANCE) break;
        rate = sx_dot(u, n);
        /* moving apart along a separating axis: never closer */
        if (!(rate > SX_R(0.0))) return SX_OK;
        t += (gap - SX_CAST_TARGET) / rate;
        if (!(t <= max_fraction)) return SX_OK;
    }
    out->hit = true;
    if (!apart) {
        /* overlapping (at the start, or within rounding of contact) */
        sx_vec2 mtv;
        out->fraction = t;
        out->point = sx_xform_point(xa, sx_mul_add(g.pb, t, u));
        if (t == SX_R(0.0) && sx_mtv(a, xa, b, xb, &mtv) && sx_length_sq(mtv) > SX_R(0.0)) {
            out->normal = sx_normalize(mtv);
        } else {
            out->normal = sx_neg(sx_normalize(translation));
        }
        return SX_OK;
    }
    /* the rest of the gap along the normal: exact for a face, short of
     * contact for a curve */
    out->normal = sx_neg(sx_rotate(xa.q, n));
    out->point = sx_xform_point(xa, sx_mul_add(sx_mul_add(g.pb, -pb.radius, n), t, u));
    rate = sx_dot(u, n);
    if (t > SX_R(0.0) && rate > SX_R(0.0) && gap > SX_R(0.0)) {
        t = sx_minr(t + gap / rate, max_fraction);
    }
    out->fraction = t;
    return SX_OK;
}

sx_status sx_shape_cast(const sx_shape *a, sx_xform xa, sx_vec2 translation, sx_real max_fraction,
                        const sx_shape *b, sx_xform xb, sx_shape_cast_output *out) {
    sx_status s = sx_cast_run(a, xa, translation, max_fraction, b, xb, out);
    if (s == SX_OK && !(sx_is_finite(out->fraction) && sx_vec2_is_finite(out->point) &&
                        sx_vec2_is_finite(out->normal))) {
        s = SX_ERR_NONFINITE;
    }
    if (s != SX_OK && out != NULL) memset(out, 0, sizeof(*out));
    return s;
}

/* ---- time of impact ------------------------------------------------------ */

static sx_xform sx_motion_at(const sx_motion *m, sx_real t) {
    sx_xform x;
    x.q = sx_rot_make(m->angle0 + t * (m->angle1 - m->angle0));
    x.p = sx_sub(sx_lerp(m->c0, m->c1, t), sx_rotate(x.q, m->local_center));
    return x;
}

/* The farthest core point from the centre of rotation. */
static sx_real sx_proxy_reach(const sx_proxy *p, sx_vec2 center) {
    sx_real r = SX_R(0.0);
    int i;
    for (i = 0; i < p->count; ++i)
        r = sx_maxr(r, sx_length(sx_sub(p->p[i], center)));
    return r;
}

void sx_proxy_toi(const sx_proxy *a, const sx_motion *ma, const sx_proxy *b, const sx_motion *mb,
                  sx_real target, sx_toi_output *out) {
    sx_vec2 bp[SX_MAX_POLYGON_VERTICES], n = sx_v2_zero(), dc;
    sx_real t = SX_R(0.0), gap = SX_R(0.0), spin;
    sx_xform xa = sx_motion_at(ma, SX_R(0.0));
    sx_gjk_result g;
    int iter;
    memset(out, 0, sizeof(*out));
    /* how fast the turns can close the gap, per unit fraction */
    spin = sx_absr(ma->angle1 - ma->angle0) * sx_proxy_reach(a, ma->local_center) +
           sx_absr(mb->angle1 - mb->angle0) * sx_proxy_reach(b, mb->local_center);
    dc = sx_sub(sx_sub(mb->c1, mb->c0), sx_sub(ma->c1, ma->c0));
    for (iter = 1; iter <= SX_TOI_MAX_ITERATIONS; ++iter) {
        sx_xform xb = sx_motion_at(mb, t);
        sx_real rate;
        xa = sx_motion_at(ma, t);
        out->iterations = iter;
        if (!sx_place(b, sx_xform_inv_mul(xa, xb), bp)) {
            /* overflow far out: nothing to say past here */
            out->state = SX_TOI_SEPARATED;
            out->fraction = SX_R(1.0);
            return;
        }
        sx_gjk(a->p, a->count, bp, b->count, &g);
        if (!sx_gjk_finite(&g)) {
            /* overflow far out: nothing to say past here */
            memset(out, 0, sizeof(*out));
            out->state = SX_TOI_SEPARATED;
            out->fraction = SX_R(1.0);
            return;
        }
        if (!sx_gap(&g, a->radius, b->radius, &gap, &n)) {
            /* cores touching: only at the start (each advance stops short) */
            out->state = t == SX_R(0.0) ? SX_TOI_STARTS_CLOSE : SX_TOI_HIT;
            out->fraction = t;
            out->point_a = out->point_b = sx_xform_point(xa, g.pa);
            return;
        }
        n = sx_rotate(xa.q, n);
        out->normal = n;
        out->point_a = sx_xform_point(xa, g.pa);
        out->point_b = sx_xform_point(xa, g.pb);
        out->point_a = sx_mul_add(out->point_a, a->radius, n);
        out->point_b = sx_mul_add(out->point_b, -b->radius, n);
        out->fraction = t;
        if (gap <= target + SX_TOI_TOLERANCE) {
            out->state = t == SX_R(0.0) ? SX_TOI_STARTS_CLOSE : SX_TOI_HIT;
            return;
        }
        rate = spin - sx_dot(dc, n);
        if (!(rate > SX_R(0.0))) break;
        t += (gap - target) / rate;
        if (!(t < SX_R(1.0))) break;
    }
    if (iter > SX_TOI_MAX_ITERATIONS) {
        out->state = SX_TOI_ITERATION_LIMIT;
        return;
    }
    out->state = SX_TOI_SEPARATED;
    out->fraction = SX_R(1.0);
    out->normal = sx_v2_zero();
}

static bool sx_motion_is_finite(const sx_motion *m) {
    return sx_vec2_is_finite(m->local_center) && sx_vec2_is_finite(m->c0) &&
           sx_vec2_is_finite(m->c1) && sx_is_finite(m->angle0) && sx_is_finite(m->angle1) &&
           sx_is_finite(m->angle1 - m->angle0) && sx_vec2_is_finite(sx_sub(m->c1, m->c0));
}

sx_status sx_time_of_impact(const sx_shape *a, const sx_motion *ma, const sx_shape *b,
                            const sx_motion *mb, sx_real target, sx_toi_output *out) {
    sx_proxy pa, pb;
    sx_status s;
    if (out == NULL) return SX_ERR_INVALID_ARG;
    memset(out, 0, sizeof(*out));
    if (ma == NULL || mb == NULL) return SX_ERR_INVALID_ARG;
    s = sx_check_pair(a, b, &pa, &pb);
    if (s != SX_OK) return s;
    if (!sx_motion_is_finite(ma) || !sx_motion_is_finite(mb) || !sx_is_finite(target)) {
        return SX_ERR_NONFINITE;
    }
    if (target < SX_R(0.0)) return SX_ERR_INVALID_ARG;
    sx_proxy_toi(&pa, ma, &pb, mb, target, out);
    if (!(sx_vec2_is_finite(out->point_a) && sx_vec2_is_finite(out->point_b) &&
          sx_vec2_is_finite(out->normal))) {
        memset(out, 0, sizeof(*out));
        return SX_ERR_NONFINITE;
    }
    return SX_OK;
}
