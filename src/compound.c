/* sepax — compound colliders: several convex parts that act as one collider.
 *
 * Most queries are the union of the per-part narrowphase answers (AABB,
 * overlap, manifolds, ray casts, containment), built on the public functions
 * of collide.h. Mass properties add the parts' own moments about the
 * compound's centre of mass (parallel-axis theorem) in the wide real.
 *
 * The minimum translation is the interesting part: one part's MTV may push
 * the compound straight into another part of the other shape, so the answer
 * must clear all part pairs at once. For a direction d the set of shifts t d
 * that leave a convex pair overlapping is an interval, so walking t up from
 * 0 and jumping to the end of whichever pair's interval t is inside of finds
 * the first shift that clears all pairs along d. A pair's exit along d comes
 * from the support functions: for any axis n with n.d > 0, moving A by
 * (h_A(-n) + h_B(n)) / (n.d) separates the pair along n, and for polygons the
 * smallest such value over the normals of both parts is exact (they are the
 * normals of the Minkowski difference). Curved pairs (circles, capsules,
 * rounded polygons) take that value as a separating upper bound and bisect
 * down to the touching shift with sx_overlap. The length of the clearing
 * push is not a convex function of the direction, so the direction is
 * searched: each penetrating pair's MTV direction and edge normals, the
 * corner directions that satisfy two pairs' MTVs at once, a coarse ring, and
 * a local pattern search around the best. Every push tried is a complete
 * clearing walk, so whatever is returned separates. */
#include "sepax/compound.h"
#include "wide.h"

/* A pair counts as penetrating when its MTV is longer than this: the
 * containment band of collide.h, far below any contact tolerance. */
#define COMPOUND_CLEAR_TOLERANCE (SX_LINEAR_SLOP * SX_R(1.0e-3))
/* Axes this close to perpendicular to a push direction give no useful bound
 * (the push along them would be enormous). */
#define COMPOUND_MIN_AXIS_DOT SX_R(1.0e-4)
/* Relative precision of the bisection for curved pairs, and its cap. */
#define COMPOUND_BISECT_REL SX_R(1.0e-6)
#define COMPOUND_BISECT_MAX 64
/* Gaps between overlap intervals narrower than this fraction of the push
 * are stepped over, probed at this many evenly spaced points. */
#define COMPOUND_GAP_REL SX_R(1.0e-2)
#define COMPOUND_GAP_PROBES 4
/* Penetrating pairs whose MTVs are combined two by two into corner
 * directions (the first ones found, in part order). */
#define COMPOUND_MAX_CONSTRAINTS 16
/* Angle steps (radians) of the direction refinement: from 8 degrees down
 * to about 0.01 degree, where the push length changes by under 1e-8
 * relative. */
#define COMPOUND_REFINE_START SX_R(0.14)
#define COMPOUND_REFINE_END SX_R(2.0e-4)
#define COMPOUND_REFINE_MAX_STEPS 64
/* Evenly spaced extra push directions tried on every penetrating query. */
#define COMPOUND_RING_DIRECTIONS 32
/* A part offset's rotation must be unit length within this (a rotation
 * built by sx_rot_make is within a few ulps; 1e-3 only catches garbage). */
#define COMPOUND_ROT_TOLERANCE SX_R(1.0e-3)

sx_compound_part sx_compound_part_make(sx_shape shape, sx_xform offset) {
    sx_compound_part p;
    p.shape = shape;
    p.offset = offset;
    return p;
}

/* A rotation this close to unit length (squared length within 16 epsilon
 * of 1: sx_rot_make's are within a few ulps) is used as it is. */
#define COMPOUND_ROT_EXACT (SX_R(16.0) * SX_REAL_EPSILON)

sx_xform sx_compound_part_placement(sx_xform x, const sx_compound_part *p) {
    sx_xform o;
    sx_real len2;
    if (p == NULL) return x;
    o = p->offset;
    len2 = o.q.c * o.q.c + o.q.s * o.q.s;
    if (sx_absr(len2 - SX_R(1.0)) > COMPOUND_ROT_EXACT && len2 > SX_R(0.0) && sx_is_finite(len2)) {
        sx_real k = SX_R(1.0) / sx_sqrt(len2);
        o.q.c *= k;
        o.q.s *= k;
    }
    return sx_xform_mul(x, o);
}

sx_status sx_compound_validate(const sx_compound *c) {
    int i;
    if (c == NULL || c->count < 1 || c->parts == NULL) return SX_ERR_INVALID_ARG;
    for (i = 0; i < c->count; ++i) {
        const sx_compound_part *p = &c->parts[i];
        sx_status st;
        sx_real len2;
        if (!sx_xform_is_finite(p->offset)) return SX_ERR_NONFINITE;
        len2 = p->offset.q.c * p->offset.q.c + p->offset.q.s * p->offset.q.s;
        if (sx_absr(len2 - SX_R(1.0)) > COMPOUND_ROT_TOLERANCE) return SX_ERR_INVALID_ARG;
        st = sx_shape_validate(&p->shape);
        if (st != SX_OK) return st;
    }
    return SX_OK;
}

/* One side of a pair query: a compound, or a plain shape as a one-part
 * compound, placed in the world. */
typedef struct side {
    const sx_compound_part *parts;
    const sx_shape *single;
    sx_xform x;
    int count;
} side;

static side compound_side(const sx_compound *c, sx_xform x) {
    side s;
    s.parts = c->parts;
    s.single = NULL;
    s.x = x;
    s.count = c->count;
    return s;
}

static side shape_side(const sx_shape *shape, sx_xform x) {
    side s;
    s.parts = NULL;
    s.single = shape;
    s.x = x;
    s.count = 1;
    return s;
}

static const sx_shape *side_part(const side *s, int i, sx_xform *world) {
    if (s->single != NULL) {
        *world = s->x;
        return s->single;
    }
    *world = sx_compound_part_placement(s->x, &s->parts[i]);
    return &s->parts[i].shape;
}

static bool compound_usable(const sx_compound *c) {
    return c != NULL && c->parts != NULL && c->count > 0;
}

sx_aabb sx_compound_aabb(const sx_compound *c, sx_xform x) {
    side s;
    sx_aabb box;
    int i;
    if (!compound_usable(c) || !sx_xform_is_finite(x)) {
        sx_vec2 at = sx_vec2_is_finite(x.p) ? x.p : sx_v2_zero();
        return sx_aabb_make(at, at);
    }
    s = compound_side(c, x);
    box = sx_aabb_make(sx_v2(SX_REAL_MAX, SX_REAL_MAX), sx_v2(-SX_REAL_MAX, -SX_REAL_MAX));
    for (i = 0; i < s.count; ++i) {
        sx_xform wx;
        const sx_shape *shape = side_part(&s, i, &wx);
        box = sx_aabb_union(box, sx_shape_aabb(shape, wx));
    }
    return box;
}

/* The centre of a part (unit-density mass properties from the wide real, so
 * a part whose mass overflows sx_real still weighs a finite amount here) in
 * the compound's frame. */
static sx_wvec2 part_mass(const sx_compound_part *p, sx_wide *area, sx_wide *inertia) {
    sx_wvec2 local;
    sx_xform o = sx_compound_part_placement(sx_xform_identity(), p);
    sx_shape_wide_mass(&p->shape, area, &local, inertia);
    return sx_wv((sx_wide)o.p.x + ((sx_wide)o.q.c * local.x - (sx_wide)o.q.s * local.y),
                 (sx_wide)o.p.y + ((sx_wide)o.q.s * local.x + (sx_wide)o.q.c * local.y));
}

sx_mass_data sx_compound_mass(const sx_compound *c, sx_real density) {
    sx_mass_data md;
    sx_wide area = SX_W(0.0), inertia = SX_W(0.0), rho, a, j;
    sx_wvec2 first = sx_wv(SX_W(0.0), SX_W(0.0)), mean = first, center, ci;
    int i;
    md.mass = SX_R(0.0);
    md.center = sx_v2_zero();
    md.rotational_inertia = SX_R(0.0);
    if (!sx_is_finite(density) || density < SX_R(0.0)) return md;
    if (sx_compound_validate(c) != SX_OK) return md;
    /* Unit-density moments of each part, in the wide real: mass is then
     * area. Parts too heavy for sx_real (a circle of radius 1e30 in the
     * float build) are summed here without overflow, and the result rounds
     * to infinity exactly as sx_shape_mass of that part does. */
    for (i = 0; i < c->count; ++i) {
        ci = part_mass(&c->parts[i], &a, &j);
        area += a;
        first = sx_wadd(first, sx_wscale(ci, a));
        mean = sx_wadd(mean, ci);
    }
    if (!(area > SX_W(0.0))) return md;
    center = sx_wscale(first, SX_W(1.0) / area);
    if ((area - area) + (center.x - center.x) + (center.y - center.y) != SX_W(0.0)) {
        /* Overflow even in the wide real (an infinite area, inf / inf):
         * the plain mean of the part centres, finite since every part
         * validated, and infinite mass and inertia (zero for density 0). */
        sx_real big = density > SX_R(0.0) ? (sx_real)INFINITY : SX_R(0.0);
        md.center = sx_narrow(sx_wscale(mean, SX_W(1.0) / (sx_wide)c->count));
        md.mass = big;
        md.rotational_inertia = big;
        return md;
    }
    for (i = 0; i < c->count; ++i) {
        sx_wvec2 r;
        ci = part_mass(&c->parts[i], &a, &j);
        r = sx_wsub(ci, center);
        inertia += j + a * sx_wdot(r, r);
    }
    rho = (sx_wide)density;
    md.mass = (sx_real)(rho * area);
    md.center = sx_narrow(center);
    md.rotational_inertia = (sx_real)(rho * inertia);
    return md;
}

/* The bounding-box prefilter of a part pair, loose by the rounding of the
 * narrowphase at the boxes' magnitude: sx_overlap counts shapes whose exact
 * gap is a few ulps of their coordinates as touching (it works in one
 * shape's frame), so boxes that miss by less must still reach it, or the
 * compound would disagree with its parts. */
static bool boxes_may_touch(sx_aabb a, sx_aabb b) {
    sx_real s = sx_maxr(sx_maxr(sx_maxr(sx_absr(a.lower.x), sx_absr(a.lower.y)),
                                sx_maxr(sx_absr(a.upper.x), sx_absr(a.upper.y))),
                        sx_maxr(sx_maxr(sx_absr(b.lower.x), sx_absr(b.lower.y)),
                                sx_maxr(sx_absr(b.upper.x), sx_absr(b.upper.y))));
    sx_real g = SX_R(64.0) * SX_REAL_EPSILON * sx_maxr(s, SX_R(1.0));
    return sx_aabb_overlaps(sx_aabb_fatten(a, g), b);
}

static sx_xform shifted(sx_xform x, sx_vec2 t) {
    x.p = sx_add(x.p, t);
    return x;
}

/* The pairs of parts (A's part i, B's part j, in that order) whose boxes
 * may touch: every query over two sides walks them. A's parts are shifted
 * by `shift` when `is_shifted`, and their boxes grown by `grow` (>= 0).
 * Use: part_pairs_begin, then while (part_pairs_next(&p)) read p.i, p.sa,
 * p.xa, p.j, p.sb, p.xb. */
typedef struct part_pairs {
    const side *a, *b;
    sx_vec2 shift;
    bool is_shifted;
    sx_real grow;
    int i, j;
    const sx_shape *sa, *sb;
    sx_xform xa, xb;
    sx_aabb box_a;
} part_pairs;

static void part_pairs_begin(part_pairs *p, const side *a, const side *b, bool is_shifted,
                             sx_vec2 shift, sx_real grow) {
    p->a = a;
    p->b = b;
    p->is_shifted = is_shifted;
    p->shift = shift;
    p->grow = grow;
    p->i = -1;
    p->j = b->count;
}

static bool part_pairs_next(part_pairs *p) {
    for (;;) {
        if (++p->j >= p->b->count) {
            if (++p->i >= p->a->count) return false;
            p->sa = side_part(p->a, p->i, &p->xa);
            if (p->is_shifted) p->xa = shifted(p->xa, p->shift);
            p->box_a = sx_shape_aabb(p->sa, p->xa);
            if (p->grow > SX_R(0.0)) p->box_a = sx_aabb_fatten(p->box_a, p->grow);
            p->j = 0;
            if (p->b->count == 0) continue;
        }
        p->sb = side_part(p->b, p->j, &p->xb);
        if (boxes_may_touch(p->box_a, sx_shape_aabb(p->sb, p->xb))) return true;
    }
}

/* ---- overlap ------------------------------------------------------------ */

static bool sides_overlap(const side *a, const side *b) {
    part_pairs p;
    part_pairs_begin(&p, a, b, false, sx_v2_zero(), SX_R(0.0));
    while (part_pairs_next(&p))
        if (sx_overlap(p.sa, p.xa, p.sb, p.xb)) return true;
    return false;
}

bool sx_compound_overlap(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    side sa, sb;
    if (!compound_usable(a) || b == NULL) return false;
    sa = compound_side(a, xa);
    sb = shape_side(b, xb);
    return sides_overlap(&sa, &sb);
}

bool sx_compound_overlap_compound(const sx_compound *a, sx_xform xa, const sx_compound *b,
                                  sx_xform xb) {
    side sa, sb;
    if (!compound_usable(a) || !compound_usable(b)) return false;
    sa = compound_side(a, xa);
    sb = compound_side(b, xb);
    return sides_overlap(&sa, &sb);
}

/* ---- minimum translation ------------------------------------------------ */

/* The pair overlaps by more than the clearing tolerance. */
static bool penetrates(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb) {
    sx_vec2 m;
    if (!sx_mtv(a, xa, b, xb, &m)) return false;
    return sx_length_sq(m) > COMPOUND_CLEAR_TOLERANCE * COMPOUND_CLEAR_TOLERANCE;
}

/* Support of a placed shape along a world direction. */
static sx_real world_support(const sx_shape *s, sx_xform x, sx_vec2 n) {
    return sx_shape_support(s, sx_inv_rotate(x.q, n)) + sx_dot(n, x.p);
}

static bool is_curved(const sx_shape *s) {
    return s->type == SX_SHAPE_CIRCLE || s->type == SX_SHAPE_CAPSULE ||
           (s->type == SX_SHAPE_POLYGON && s->u.polygon.radius > SX_R(0.0));
}

/* Up to SX_MAX_POLYGON_VERTICES world edge normals of a shape (one per
 * segment or capsule, none for a circle); returns the count. */
static int world_normals(const sx_shape *s, sx_xform x, sx_vec2 *out) {
    int i, n = 0;
    switch (s->type) {
    case SX_SHAPE_POLYGON:
        n = s->u.polygon.count;
        if (n < 0 || n > SX_MAX_POLYGON_VERTICES) return 0;
        for (i = 0; i < n; ++i)
            out[i] = sx_rotate(x.q, s->u.polygon.normals[i]);
        return n;
    case SX_SHAPE_SEGMENT:
        out[0] = sx_normalize(sx_rotate(x.q, sx_perp(sx_sub(s->u.segment.b, s->u.segment.a))));
        return 1;
    case SX_SHAPE_CAPSULE:
        out[0] = sx_normalize(sx_rotate(x.q, sx_perp(sx_sub(s->u.capsule.b, s->u.capsule.a))));
        return 1;
    default: return 0;
    }
}

/* Bound from one axis (taken in both signs) on the push along d that
 * separates the pair. */
static sx_real axis_bound(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_vec2 d,
                          sx_vec2 n, sx_real best) {
    sx_real nd = sx_dot(n, d);
    if (nd < SX_R(0.0)) {
        n = sx_neg(n);
        nd = -nd;
    }
    if (nd < COMPOUND_MIN_AXIS_DOT) return best;
    return sx_minr(best, (world_support(a, xa, sx_neg(n)) + world_support(b, xb, n)) / nd);
}

/* The push along unit d (>= 0) that takes the pair from penetrating to
 * touching.
 *
 * Never shorter than the pair's own MTV: no push in any direction clears a
 * pair by less than its minimum translation, so in exact arithmetic the
 * floor changes nothing. But the support functions here are taken in world
 * space while sx_mtv works in a part's frame, and far from the origin the
 * two round differently: a point exactly on the corner of a 2e5-wide box
 * whose centre lies 1.4e5 from the origin is 2^-7 m (one float ulp there)
 * inside it for sx_mtv, which decides whether the walk must go on, and on
 * the box's faces for the supports, which then give a push of 0. Without
 * the floor the walk stood still on that pair in every direction, and the
 * compound MTV fell back to the bounding boxes, which round like the
 * supports and left the pair penetrating. */
static sx_real pair_exit(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                         sx_vec2 d) {
    sx_vec2 normals[SX_MAX_POLYGON_VERTICES], m;
    sx_real hi, lo = SX_R(0.0), depth = SX_R(0.0);
    int i, n, iter;
    hi = axis_bound(a, xa, b, xb, d, d, SX_REAL_MAX);
    n = world_normals(a, xa, normals);
    for (i = 0; i < n; ++i)
        hi = axis_bound(a, xa, b, xb, d, normals[i], hi);
    n = world_normals(b, xb, normals);
    for (i = 0; i < n; ++i)
        hi = axis_bound(a, xa, b, xb, d, normals[i], hi);
    if (sx_mtv(a, xa, b, xb, &m)) {
        /* depth stays 0 for an MTV too short to normalise or not finite. */
        sx_vec2 axis = sx_normalize_len(m, &depth);
        if (depth > SX_R(0.0)) hi = axis_bound(a, xa, b, xb, d, axis, hi);
    }
    if (!(hi > depth)) return depth;
    if (!is_curved(a) && !is_curved(b)) return hi;
    /* The overlapping shifts form an interval that starts at or before 0
     * and ends at or before hi: bisect for its end. */
    if (sx_overlap(a, shifted(xa, sx_scale(d, hi)), b, xb)) return hi;
    for (iter = 0; iter < COMPOUND_BISECT_MAX && hi - lo > COMPOUND_BISECT_REL * hi; ++iter) {
        sx_real mid = SX_R(0.5) * (lo + hi);
        if (sx_overlap(a, shifted(xa, sx_scale(d, mid)), b, xb)) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return sx_maxr(hi, depth);
}

/* A pair that penetrates when a is pushed to t along d: returns the pair's
 * indices through *pi, *pj. Touching is no obstacle (the guarantee allows
 * it), and far from the origin a pair the walk has just pushed to touching
 * stays touching within rounding for pushes much longer than the probe
 * spacing: counting it would creep the walk along by probe steps until its
 * budget ran out. */
static bool find_penetration_at(const side *a, const side *b, sx_vec2 d, sx_real t, int *pi,
                                int *pj) {
    part_pairs p;
    part_pairs_begin(&p, a, b, true, sx_scale(d, t), SX_R(0.0));
    while (part_pairs_next(&p)) {
        if (penetrates(p.sa, p.xa, p.sb, p.xb)) {
            *pi = p.i;
            *pj = p.j;
            return true;
        }
    }
    return false;
}

/* The smallest push along unit d, found by walking through the pairs'
 * overlap intervals; returns false when it is not below `best` or the walk
 * does not settle within its sweep budget. Where the walk comes to rest, the
 * next COMPOUND_GAP_REL of the push is probed: a gap narrower than that
 * between two pairs' intervals is stepped over, so pushing a little more
 * than the MTV (as a solver does) does not run into another part. */
static bool clear_along(const side *a, const side *b, sx_vec2 d, sx_real best, sx_real *out) {
    sx_real t = SX_R(0.0);
    /* 64-bit: two compounds of 2^15 parts would overflow an int here (the
     * product of two int counts, doubled, still fits an int64_t) */
    int64_t sweep, sweeps = 2 * (int64_t)a->count * (int64_t)b->count + 4;
    for (sweep = 0; sweep < sweeps; ++sweep) {
        bool moved = false;
        int i, j, k;
        for (i = 0; i < a->count; ++i) {
            sx_xform xa;
            const sx_shape *sa = side_part(a, i, &xa);
            for (j = 0; j < b->count; ++j) {
                sx_xform xb, xt;
                const sx_shape *sb = side_part(b, j, &xb);
                xt = shifted(xa, sx_scale(d, t));
                if (!boxes_may_touch(sx_shape_aabb(sa, xt), sx_shape_aabb(sb, xb))) continue;
                if (!penetrates(sa, xt, sb, xb)) continue;
                t += pair_exit(sa, xt, sb, xb, d);
                moved = true;
                if (!(t < best)) return false;
            }
        }
        for (k = 1; k <= COMPOUND_GAP_PROBES && !moved; ++k) {
            sx_real probe = t + t * COMPOUND_GAP_REL * (sx_real)k / (sx_real)COMPOUND_GAP_PROBES;
            if (find_penetration_at(a, b, d, probe, &i, &j)) {
                sx_xform xa, xb;
                const sx_shape *sa = side_part(a, i, &xa);
                const sx_shape *sb = side_part(b, j, &xb);
                xa = shifted(xa, sx_scale(d, probe));
                t = probe + pair_exit(sa, xa, sb, xb, d);
                moved = true;
                if (!(t < best)) return false;
            }
        }
        if (!moved) {
            *out = t;
            return true;
        }
    }
    return false;
}

/* Tries the push directions suggested by pair (sa, sb): its own MTV
 * direction and both signs of every edge normal of the two parts. */
static void try_pair_directions(const side *a, const side *b, const sx_shape *sa, sx_xform xa,
                                const sx_shape *sb, sx_xform xb, sx_vec2 pair_mtv, sx_real *best,
                                sx_vec2 *best_dir) {
    sx_vec2 dirs[1 + 4 * SX_MAX_POLYGON_VERTICES], normals[SX_MAX_POLYGON_VERTICES];
    int nd = 0, i, n;
    dirs[nd++] = sx_normalize(pair_mtv);
    n = world_normals(sa, xa, normals);
    for (i = 0; i < n; ++i) {
        dirs[nd++] = normals[i];
        dirs[nd++] = sx_neg(normals[i]);
    }
    n = world_normals(sb, xb, normals);
    for (i = 0; i < n; ++i) {
        dirs[nd++] = normals[i];
        dirs[nd++] = sx_neg(normals[i]);
    }
    for (i = 0; i < nd; ++i) {
        sx_real t;
        if (!sx_is_normalized(dirs[i])) continue;
        if (clear_along(a, b, dirs[i], *best, &t)) {
            *best = t;
            *best_dir = dirs[i];
        }
    }
}

/* Push along d until the two sides' bounding boxes are apart along x or y:
 * always separating, used only when no candidate direction settled. */
static sx_real aabb_clearance(const side *a, const side *b, sx_vec2 d) {
    sx_aabb ba = sx_aabb_make(sx_v2(SX_REAL_MAX, SX_REAL_MAX), sx_v2(-SX_REAL_MAX, -SX_REAL_MAX));
    sx_aabb bb = ba;
    sx_real t = SX_REAL_MAX;
    int i;
    for (i = 0; i < a->count; ++i) {
        sx_xform x;
        const sx_shape *s = side_part(a, i, &x);
        ba = sx_aabb_union(ba, sx_shape_aabb(s, x));
    }
    for (i = 0; i < b->count; ++i) {
        sx_xform x;
        const sx_shape *s = side_part(b, i, &x);
        bb = sx_aabb_union(bb, sx_shape_aabb(s, x));
    }
    if (d.x > COMPOUND_MIN_AXIS_DOT) t = sx_minr(t, (bb.upper.x - ba.lower.x) / d.x);
    if (d.x < -COMPOUND_MIN_AXIS_DOT) t = sx_minr(t, (bb.lower.x - ba.upper.x) / d.x);
    if (d.y > COMPOUND_MIN_AXIS_DOT) t = sx_minr(t, (bb.upper.y - ba.lower.y) / d.y);
    if (d.y < -COMPOUND_MIN_AXIS_DOT) t = sx_minr(t, (bb.lower.y - ba.upper.y) / d.y);
    return sx_maxr(t, SX_R(0.0));
}

/* The push that meets two penetration constraints at once (t . n_i =
 * depth_i for both pairs' MTVs): the corner direction when a shape sits in
 * a concave corner of the other side, which no single pair suggests.
 * Returns false for (near-)parallel constraints. */
static bool corner_direction(sx_vec2 mi, sx_vec2 mj, sx_vec2 *dir) {
    sx_real di, dj, det;
    sx_vec2 ni = sx_normalize_len(mi, &di), nj = sx_normalize_len(mj, &dj), t;
    det = sx_cross(ni, nj);
    if (sx_absr(det) < COMPOUND_MIN_AXIS_DOT) return false;
    t = sx_v2((di * nj.y - ni.y * dj) / det, (ni.x * dj - di * nj.x) / det);
    *dir = sx_normalize(t);
    return sx_is_normalized(*dir);
}

/* Pattern search over the push angle around the best candidate: the
 * candidates are exact for flat contacts, but against curved ones (a disc
 * in a concave corner) the best direction lies between them. Every push
 * tried is a full clearing walk, so the result stays separating. */
static void refine_direction(const side *a, const side *b, sx_real *best, sx_vec2 *best_dir) {
    sx_real step = COMPOUND_REFINE_START;
    int iter;
    for (iter = 0; iter < COMPOUND_REFINE_MAX_STEPS && step > COMPOUND_REFINE_END; ++iter) {
        bool improved = false;
        int k;
        for (k = -1; k <= 1 && !improved; k += 2) {
            sx_vec2 d = sx_rotate(sx_rot_make((sx_real)k * step), *best_dir);
            sx_real t;
            if (clear_along(a, b, d, *best, &t)) {
                *best = t;
                *best_dir = d;
                improved = true;
            }
        }
        if (!improved) step *= SX_R(0.5);
    }
}

static bool sides_mtv(const side *a, const side *b, sx_vec2 *mtv) {
    sx_vec2 constraints[COMPOUND_MAX_CONSTRAINTS];
    sx_real best = SX_REAL_MAX, deepest = SX_R(0.0);
    sx_vec2 best_dir = sx_v2_zero(), deep_dir = sx_v2(SX_R(1.0), SX_R(0.0));
    bool any = false;
    int i, j, nc = 0, penetrating = 0;
    part_pairs p;
    if (mtv != NULL) *mtv = sx_v2_zero();
    part_pairs_begin(&p, a, b, false, sx_v2_zero(), SX_R(0.0));
    while (part_pairs_next(&p)) {
        sx_vec2 m;
        if (!sx_mtv(p.sa, p.xa, p.sb, p.xb, &m)) continue;
        any = true;
        if (mtv == NULL) return true;
        if (sx_length_sq(m) <= COMPOUND_CLEAR_TOLERANCE * COMPOUND_CLEAR_TOLERANCE) continue;
        ++penetrating;
        if (sx_length(m) > deepest) {
            deepest = sx_length(m);
            deep_dir = sx_normalize(m);
        }
        if (nc < COMPOUND_MAX_CONSTRAINTS) constraints[nc++] = m;
        try_pair_directions(a, b, p.sa, p.xa, p.sb, p.xb, m, &best, &best_dir);
    }
    if (penetrating == 0) return any;
    for (i = 0; i < nc; ++i) {
        for (j = i + 1; j < nc; ++j) {
            sx_vec2 d;
            sx_real t;
            if (!corner_direction(constraints[i], constraints[j], &d)) continue;
            if (clear_along(a, b, d, best, &t)) {
                best = t;
                best_dir = d;
            }
        }
    }
    /* Deep overlaps can be cleared sooner in a direction no contact
     * suggests (pushing a wall out from under a disc, not the disc out
     * through the wall): a coarse ring of directions catches those. */
    for (i = 0; i < COMPOUND_RING_DIRECTIONS; ++i) {
        sx_real t, angle = SX_R(2.0) * SX_PI * (sx_real)i / (sx_real)COMPOUND_RING_DIRECTIONS;
        sx_vec2 d = sx_v2(sx_cos(angle), sx_sin(angle));
        if (clear_along(a, b, d, best, &t)) {
            best = t;
            best_dir = d;
        }
    }
    if (best < SX_REAL_MAX) {
        refine_direction(a, b, &best, &best_dir);
        *mtv = sx_scale(best_dir, best);
    } else {
        *mtv = sx_scale(deep_dir, aabb_clearance(a, b, deep_dir));
    }
    return true;
}

/* Far beyond SX_HUGE (16 times) the clearing walk works with B's origin as
 * the working origin. The MTV does not depend on where the pair is, but the
 * walk takes its supports in world space, where an ulp there can exceed the
 * pair: the supports are noise, every exit falls back to the pair's MTV and
 * the walk spends its whole budget. Within the promised range the world
 * frame is kept: there the walk rounds as the caller's world does, which is
 * what lets an answer one ulp long clear the pair when added to A's
 * position. */
static void sides_recentre(side *a, side *b) {
    sx_real far = SX_R(16.0) * SX_HUGE;
    sx_vec2 pa = sx_sub(a->x.p, b->x.p);
    if (!(sx_maxr(sx_maxr(sx_absr(a->x.p.x), sx_absr(a->x.p.y)),
                  sx_maxr(sx_absr(b->x.p.x), sx_absr(b->x.p.y))) > far) ||
        !sx_vec2_is_finite(pa)) {
        return;
    }
    a->x.p = pa;
    b->x.p = sx_v2_zero();
}

bool sx_compound_mtv(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                     sx_vec2 *mtv) {
    side sa, sb;
    if (mtv != NULL) *mtv = sx_v2_zero();
    if (!compound_usable(a) || b == NULL) return false;
    sa = compound_side(a, xa);
    sb = shape_side(b, xb);
    sides_recentre(&sa, &sb);
    return sides_mtv(&sa, &sb, mtv);
}

bool sx_compound_mtv_compound(const sx_compound *a, sx_xform xa, const sx_compound *b, sx_xform xb,
                              sx_vec2 *mtv) {
    side sa, sb;
    if (mtv != NULL) *mtv = sx_v2_zero();
    if (!compound_usable(a) || !compound_usable(b)) return false;
    sa = compound_side(a, xa);
    sb = compound_side(b, xb);
    sides_recentre(&sa, &sb);
    return sides_mtv(&sa, &sb, mtv);
}

/* ---- manifolds ---------------------------------------------------------- */

static int sides_collide(const side *a, const side *b, sx_real margin, sx_compound_manifold *out,
                         int capacity) {
    int n = 0;
    sx_real grow = sx_is_finite(margin) && margin > SX_R(0.0) ? margin : SX_R(0.0);
    part_pairs p;
    part_pairs_begin(&p, a, b, false, sx_v2_zero(), grow);
    while (n < capacity && part_pairs_next(&p)) {
        if (sx_collide_ex(p.sa, p.xa, p.sb, p.xb, margin, &out[n].manifold) > 0) {
            out[n].part_a = p.i;
            out[n].part_b = p.j;
            ++n;
        }
    }
    return n;
}

int sx_compound_collide(const sx_compound *a, sx_xform xa, const sx_shape *b, sx_xform xb,
                        sx_real margin, sx_compound_manifold *out, int capacity) {
    side sa, sb;
    if (!compound_usable(a) || b == NULL || out == NULL || capacity < 1) return 0;
    sa = compound_side(a, xa);
    sb = shape_side(b, xb);
    return sides_collide(&sa, &sb, margin, out, capacity);
}

int sx_compound_collide_compound(const sx_compound *a, sx_xform xa, const sx_compound *b,
                                 sx_xform xb, sx_real margin, sx_compound_manifold *out,
                                 int capacity) {
    side sa, sb;
    if (!compound_usable(a) || !compound_usable(b) || out == NULL || capacity < 1) return 0;
    sa = compound_side(a, xa);
    sb = compound_side(b, xb);
    return sides_collide(&sa, &sb, margin, out, capacity);
}

/* ---- queries ------------------------------------------------------------ */

bool sx_compound_ray_cast(const sx_compound *c, sx_xform x, const sx_ray_input *ray,
                          sx_ray_hit *out, int *part) {
    sx_ray_hit best, h;
    int i, best_part = -1;
    best.point = sx_v2_zero();
    best.normal = sx_v2_zero();
    best.fraction = SX_R(0.0);
    best.hit = false;
    if (compound_usable(c) && ray != NULL) {
        side s = compound_side(c, x);
        for (i = 0; i < s.count; ++i) {
            sx_xform wx;
            const sx_shape *shape = side_part(&s, i, &wx);
            if (!sx_ray_cast(shape, wx, ray, &h)) continue;
            if (best_part < 0 || h.fraction < best.fraction) {
                best = h;
                best_part = i;
            }
        }
    }
    if (out != NULL) *out = best;
    if (part != NULL) *part = best_part;
    return best_part >= 0;
}

bool sx_compound_contains_point(const sx_compound *c, sx_xform x, sx_vec2 p, int *part) {
    int i;
    if (part != NULL) *part = -1;
    if (!compound_usable(c)) return false;
    for (i = 0; i < c->count; ++i) {
        if (sx_contains_point(&c->parts[i].shape, sx_compound_part_placement(x, &c->parts[i]), p)) {
            if (part != NULL) *part = i;
            return true;
        }
    }
    return false;
}
