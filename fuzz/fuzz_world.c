/* sepax fuzzing — a world driven by an arbitrary command sequence.
 *
 * The bytes choose a world def (often the default, sometimes fuzzed fields,
 * out-of-range and non-finite ones included), then up to WLD_MAX_COMMANDS
 * commands: create and destroy bodies (any type value, any def values) and
 * colliders (any shape from fuzz_input.h, any density, friction,
 * restitution, filter, sensor flag), apply forces, torques and impulses
 * (also at points), teleport, set velocities, retype, wake or put to sleep,
 * set the gravity, step with any dt (NaN, negative, zero, huge), run single
 * stages with any h, and query (bounds, point, shape, ray, contacts, events,
 * debug draw). Handles are picked among the live ones, the destroyed ones,
 * the null handle and garbage. Checked after every command:
 *
 *  - every call answers with a known status, and with the documented one
 *    where the input decides it (stale handle, NaN/Inf argument, negative
 *    damping or density, unknown type, dt <= 0, bad world def -> NULL); a
 *    fully valid call succeeds; on error *out gets the null handle;
 *  - every live handle is valid, every destroyed handle (and a collider of a
 *    destroyed body) stale, getters answer stale handles with zero values,
 *    the body count matches;
 *  - "sane" input (every accepted value finite and within modest ranges:
 *    shapes of 1 cm to 10 m, densities 0.01 to 100, speeds up to 100 m/s,
 *    forces up to 1e4 N, dt up to 0.1 s, positions within 1e3 m) keeps every
 *    live body's position, angle and velocities finite (and not NaN); any
 *    input keeps them, and mass and inertia, free of NaN (see
 *    WLD_STRICT_NAN);
 *  - queries and contacts are well formed (unit normals, 1..2 points,
 *    hits within the ray);
 *  - after sx_world_destroy, sx_live_bytes() is back where it started.
 *
 * An input whose first byte is 2 mod 4 builds a pinched scene instead and
 * steps it under fuzz_energy.h's energy audit (see "pinched scenes" below):
 * light bodies under heavy ones at mass ratios past 10^6, any restitution,
 * and the total energy never above its start plus the work of gravity and
 * the applied forces, within the allowances derived there. */
#include "fuzz_energy.h"
#include "fuzz_input.h"

#define WLD_MAX_COMMANDS 48
#define WLD_MAX_BODIES 16
#define WLD_MAX_COLLIDERS 32
#define WLD_MAX_STALE 32
#define WLD_MAX_STEPS 12

/* WLD_STRICT_NAN=2 (the default) demands "never NaN" of every input: any
 * forces, torques, speeds, masses, restitution and dt, positions beyond
 * SX_HUGE included (colliders reaching beyond it are refused, and the step's
 * speed limit keeps velocities finite). -DWLD_STRICT_NAN=1 demands it only
 * of input whose shapes and positions stay within SX_HUGE, and 0 only of
 * sane input (for triaging a failure). */
#ifndef WLD_STRICT_NAN
#define WLD_STRICT_NAN 2
#endif

/* -DWLD_DEBUG prints the commands of an input (for reproducers). */
#ifdef WLD_DEBUG
#define WLD_LOG(...) fprintf(stderr, __VA_ARGS__)
#else
#define WLD_LOG(...) ((void)0)
#endif

typedef struct wld_state {
    sx_world *w;
    sx_body_id bodies[WLD_MAX_BODIES];
    int body_count;
    sx_collider_id colliders[WLD_MAX_COLLIDERS];
    int collider_body[WLD_MAX_COLLIDERS]; /* index into bodies */
    int collider_count;
    sx_body_id stale_bodies[WLD_MAX_STALE];
    int stale_body_count;
    sx_collider_id stale_colliders[WLD_MAX_STALE];
    int stale_collider_count;
    bool sane; /* every accepted value within the modest ranges */
    /* no accepted shape or position beyond SX_HUGE, the range the library
     * promises precision for (beyond it the narrowphase's own overflow
     * regime, see fuzz/crashes/README.md, feeds the solver garbage) */
    bool bounded;
    int steps;
} wld_state;

static bool wld_in(sx_real v, double limit) {
    return sx_is_finite(v) && (double)sx_absr(v) <= limit;
}
static bool wld_vin(sx_vec2 v, double limit) { return wld_in(v.x, limit) && wld_in(v.y, limit); }

/* A real for a world command: usually a moderate value, sometimes any
 * decoded one (NaN, Inf, huge, tiny). */
static sx_real wld_real(fz_reader *r, double typical) {
    uint8_t t = fz_u8(r);
    if (t % 4u != 0u) return (sx_real)((double)fz_int8(r) / 128.0 * typical);
    return fz_real(r);
}

static sx_vec2 wld_vec(fz_reader *r, double typical) {
    sx_vec2 v;
    v.x = wld_real(r, typical);
    v.y = wld_real(r, typical);
    return v;
}

static sx_body_id wld_pick_body(fz_reader *r, const wld_state *s, int *live_index) {
    uint8_t k = fz_u8(r);
    sx_body_id id = {0, 0};
    *live_index = -1;
    if (k % 8u < 5u && s->body_count > 0) {
        *live_index = (int)(fz_u8(r) % (unsigned)s->body_count);
        return s->bodies[*live_index];
    }
    if (k % 8u < 7u && s->stale_body_count > 0)
        return s->stale_bodies[fz_u8(r) % (unsigned)s->stale_body_count];
    if (k % 2u) { /* garbage: a generation no slot reaches in one input */
        id.index = fz_u8(r);
        id.generation = 0x10000u + fz_u8(r);
    }
    return id;
}

static sx_collider_id wld_pick_collider(fz_reader *r, const wld_state *s, int *live_index) {
    uint8_t k = fz_u8(r);
    sx_collider_id id = {0, 0};
    *live_index = -1;
    if (k % 8u < 5u && s->collider_count > 0) {
        *live_index = (int)(fz_u8(r) % (unsigned)s->collider_count);
        return s->colliders[*live_index];
    }
    if (k % 8u < 7u && s->stale_collider_count > 0)
        return s->stale_colliders[fz_u8(r) % (unsigned)s->stale_collider_count];
    if (k % 2u) { /* garbage: a generation no slot reaches in one input */
        id.index = fz_u8(r);
        id.generation = 0x10000u + fz_u8(r);
    }
    return id;
}

static void wld_forget_collider(wld_state *s, int i) {
    if (s->stale_collider_count < WLD_MAX_STALE)
        s->stale_colliders[s->stale_collider_count++] = s->colliders[i];
    s->colliders[i] = s->colliders[s->collider_count - 1];
    s->collider_body[i] = s->collider_body[s->collider_count - 1];
    --s->collider_count;
}

static void wld_forget_body(wld_state *s, int b) {
    int i;
    for (i = s->collider_count - 1; i >= 0; --i)
        if (s->collider_body[i] == b) wld_forget_collider(s, i);
    if (s->stale_body_count < WLD_MAX_STALE) s->stale_bodies[s->stale_body_count++] = s->bodies[b];
    s->bodies[b] = s->bodies[s->body_count - 1];
    for (i = 0; i < s->collider_count; ++i)
        if (s->collider_body[i] == s->body_count - 1) s->collider_body[i] = b;
    --s->body_count;
}

/* The status a call must give when its only inputs are a handle and some
 * reals: stale first, then non-finite. */
static void wld_expect(sx_status st, bool live, bool finite_args, bool huge_args) {
    FZ_CHECK(fz_status_known(st));
    if (!live)
        FZ_CHECK(st == SX_ERR_STALE_HANDLE);
    else if (!finite_args)
        FZ_CHECK(st == SX_ERR_NONFINITE);
    else if (huge_args) /* a sum that would overflow is refused */
        FZ_CHECK(st == SX_OK || st == SX_ERR_NONFINITE);
    else
        FZ_CHECK(st == SX_OK);
}

/* Whether the state must be free of NaN: for sane input always; with
 * -DWLD_STRICT_NAN=1 for any input within SX_HUGE, with =2 for any input. */
static bool wld_nan_checked(const wld_state *s) {
    return s->sane || (WLD_STRICT_NAN >= 1 && s->bounded) || WLD_STRICT_NAN >= 2;
}

/* The light contact read gives the full read's pair, normal and points,
 * bit for bit. */
static bool wld_pair_is(const sx_contact_pair *p, const sx_contact_data *d) {
    return sx_body_id_to_u64(p->body_a) == sx_body_id_to_u64(d->body_a) &&
           sx_body_id_to_u64(p->body_b) == sx_body_id_to_u64(d->body_b) &&
           sx_collider_id_to_u64(p->collider_a) == sx_collider_id_to_u64(d->collider_a) &&
           sx_collider_id_to_u64(p->collider_b) == sx_collider_id_to_u64(d->collider_b) &&
           p->part_a == d->part_a && p->part_b == d->part_b && p->count == d->count &&
           d->count >= 0 && d->count <= 2 &&
           memcmp(&p->normal, &d->normal, sizeof(d->normal)) == 0 &&
           memcmp(p->points, d->points, (size_t)d->count * sizeof(d->points[0])) == 0;
}

static void wld_check_world(const wld_state *s) {
    int i;
    FZ_CHECK(sx_world_body_count(s->w) == s->body_count);
    FZ_CHECK(sx_world_awake_body_count(s->w) >= 0 &&
             sx_world_awake_body_count(s->w) <= s->body_count);
    for (i = 0; i < s->body_count; ++i) {
        sx_body_id b = s->bodies[i];
        sx_vec2 p = sx_body_get_position(s->w, b), v = sx_body_get_linear_velocity(s->w, b);
        sx_real a = sx_body_get_angle(s->w, b), av = sx_body_get_angular_velocity(s->w, b);
        sx_xform x = sx_body_get_transform(s->w, b);
        sx_vec2 c = sx_body_get_world_center(s->w, b);
        FZ_CHECK(sx_body_is_valid(s->w, b));
        WLD_LOG("  body %u:%u p (%g, %g) a %g v (%g, %g) w %g\n", b.index, b.generation,
                (double)p.x, (double)p.y, (double)a, (double)v.x, (double)v.y, (double)av);
        FZ_CHECK(!fz_is_nan(sx_body_get_mass(s->w, b)) && !fz_is_nan(sx_body_get_inertia(s->w, b)));
        if (wld_nan_checked(s)) {
            FZ_CHECK(!fz_is_nan(p.x) && !fz_is_nan(p.y) && !fz_is_nan(v.x) && !fz_is_nan(v.y));
            FZ_CHECK(!fz_is_nan(a) && !fz_is_nan(av) && !fz_is_nan(x.q.c) && !fz_is_nan(x.q.s));
            FZ_CHECK(!fz_is_nan(c.x) && !fz_is_nan(c.y));
        }
        FZ_CHECK(sx_body_get_mass(s->w, b) >= SX_R(0.0));
        if (s->sane) {
            FZ_CHECK(sx_vec2_is_finite(p) && sx_vec2_is_finite(v) && sx_vec2_is_finite(c));
            FZ_CHECK(sx_is_finite(a) && sx_is_finite(av));
            FZ_CHECK(fz_is_unit(sx_v2(x.q.c, x.q.s)));
        }
    }
    for (i = 0; i < s->stale_body_count; ++i) {
        sx_body_id b = s->stale_bodies[i];
        FZ_CHECK(!sx_body_is_valid(s->w, b));
        FZ_CHECK(fz_vec_eq(sx_body_get_position(s->w, b), sx_v2_zero()));
        FZ_CHECK(fz_vec_eq(sx_body_get_linear_velocity(s->w, b), sx_v2_zero()));
        FZ_CHECK(sx_body_get_mass(s->w, b) == SX_R(0.0));
        FZ_CHECK(sx_body_get_type(s->w, b) == SX_BODY_STATIC);
        FZ_CHECK(!sx_body_is_awake(s->w, b));
        FZ_CHECK(sx_destroy_body(s->w, b) == SX_ERR_STALE_HANDLE);
    }
    for (i = 0; i < s->collider_count; ++i) {
        sx_body_id owner = sx_collider_get_body(s->w, s->colliders[i]);
        FZ_CHECK(sx_collider_is_valid(s->w, s->colliders[i]));
        FZ_CHECK(owner.index == s->bodies[s->collider_body[i]].index &&
                 owner.generation == s->bodies[s->collider_body[i]].generation);
    }
    for (i = 0; i < s->stale_collider_count; ++i) {
        FZ_CHECK(!sx_collider_is_valid(s->w, s->stale_colliders[i]));
        FZ_CHECK(sx_body_id_is_null(sx_collider_get_body(s->w, s->stale_colliders[i])));
        FZ_CHECK(sx_destroy_collider(s->w, s->stale_colliders[i]) == SX_ERR_STALE_HANDLE);
    }
    {
        int n = sx_world_contact_count(s->w), k, j;
        sx_contact_data cd;
        sx_contact_pair pairs[8];
        FZ_CHECK(n >= 0);
        FZ_CHECK(sx_world_get_contact(s->w, n, &cd) == SX_ERR_INVALID_ARG);
        FZ_CHECK(sx_world_get_contact(s->w, -1, &cd) == SX_ERR_INVALID_ARG);
        FZ_CHECK(sx_world_get_contact_pairs(s->w, n, pairs, 8) == 0);
        FZ_CHECK(sx_world_get_contact_pairs(s->w, -1, pairs, 8) == 0);
        if (n > 0) {
            /* the list's tail, past any tombstones, read both ways */
            FZ_CHECK(sx_world_get_contact_pairs(s->w, n - 1, pairs, 8) == 1);
            FZ_CHECK(sx_world_get_contact(s->w, n - 1, &cd) == SX_OK);
            FZ_CHECK(wld_pair_is(&pairs[0], &cd));
        }
        FZ_CHECK(sx_world_get_contact_pairs(s->w, 0, pairs, 8) == (n < 8 ? n : 8));
        for (k = 0; k < n && k < 8; ++k) {
            FZ_CHECK(sx_world_get_contact(s->w, k, &cd) == SX_OK);
            FZ_CHECK(wld_pair_is(&pairs[k], &cd));
            FZ_CHECK(cd.count >= 1 && cd.count <= 2);
            if (!wld_nan_checked(s)) continue;
            FZ_CHECK(!fz_is_nan(cd.normal.x) && !fz_is_nan(cd.normal.y));
            for (j = 0; j < cd.count; ++j) {
                FZ_CHECK(!fz_is_nan(cd.depths[j]) && !fz_is_nan(cd.normal_impulses[j]) &&
                         !fz_is_nan(cd.tangent_impulses[j]));
                FZ_CHECK(!fz_is_nan(cd.points[j].x) && !fz_is_nan(cd.points[j].y));
            }
            if (s->sane) {
                FZ_CHECK(fz_is_unit(cd.normal));
                for (j = 0; j < cd.count; ++j)
                    FZ_CHECK(sx_is_finite(cd.depths[j]) && sx_is_finite(cd.normal_impulses[j]) &&
                             sx_vec2_is_finite(cd.points[j]));
            }
        }
    }
}

static void wld_create_body(fz_reader *r, wld_state *s) {
    sx_body_def bd = sx_default_body_def();
    sx_body_id id = {7, 7};
    uint8_t t = fz_u8(r), flags = fz_u8(r);
    sx_status st;
    bool finite, sane;
    bd.type = (sx_body_type)(t % 4u); /* 3 is not a type */
    bd.bullet = (t & 4u) != 0;
    bd.position = wld_vec(r, 20.0);
    if (flags & 1u) bd.angle = wld_real(r, 4.0);
    if (flags & 2u) bd.linear_velocity = wld_vec(r, 20.0);
    if (flags & 4u) bd.angular_velocity = wld_real(r, 20.0);
    if (flags & 8u) bd.linear_damping = wld_real(r, 2.0);
    if (flags & 16u) bd.angular_damping = wld_real(r, 2.0);
    if (flags & 32u) bd.gravity_scale = wld_real(r, 4.0);
    bd.fixed_rotation = (flags & 64u) != 0;
    bd.enabled = (flags & 128u) == 0 || fz_u8(r) % 2u;
    st = sx_create_body(s->w, &bd, &id);
    WLD_LOG("create body type %d p (%g, %g) angle %g v (%g, %g) w %g damp %g %g gs %g fixed %d "
            "enabled %d bullet %d -> %d (%u:%u)\n",
            (int)bd.type, (double)bd.position.x, (double)bd.position.y, (double)bd.angle,
            (double)bd.linear_velocity.x, (double)bd.linear_velocity.y, (double)bd.angular_velocity,
            (double)bd.linear_damping, (double)bd.angular_damping, (double)bd.gravity_scale,
            (int)bd.fixed_rotation, (int)bd.enabled, (int)bd.bullet, (int)st, id.index,
            id.generation);
    FZ_CHECK(fz_status_known(st));
    finite = sx_vec2_is_finite(bd.position) && sx_is_finite(bd.angle) &&
             sx_vec2_is_finite(bd.linear_velocity) && sx_is_finite(bd.angular_velocity) &&
             sx_is_finite(bd.linear_damping) && sx_is_finite(bd.angular_damping) &&
             sx_is_finite(bd.gravity_scale);
    if (t % 4u == 3u)
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else if (!finite)
        FZ_CHECK(st == SX_ERR_NONFINITE);
    else if (bd.linear_damping < SX_R(0.0) || bd.angular_damping < SX_R(0.0))
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else
        FZ_CHECK(st == SX_OK);
    if (st != SX_OK) {
        FZ_CHECK(sx_body_id_is_null(id));
        return;
    }
    FZ_CHECK(!sx_body_id_is_null(id) && id.generation >= 1);
    FZ_CHECK(sx_body_id_from_u64(sx_body_id_to_u64(id)).index == id.index);
    sane = wld_vin(bd.position, 1e3) && wld_in(bd.angle, 1e3) &&
           wld_vin(bd.linear_velocity, 100.0) && wld_in(bd.angular_velocity, 100.0) &&
           wld_in(bd.linear_damping, 1e3) && wld_in(bd.angular_damping, 1e3) &&
           wld_in(bd.gravity_scale, 10.0);
    s->sane = s->sane && sane;
    s->bounded = s->bounded && wld_vin(bd.position, (double)SX_HUGE);
    if (s->body_count < WLD_MAX_BODIES) {
        s->bodies[s->body_count++] = id;
    } else { /* no room to track it: destroy it again */
        FZ_CHECK(sx_destroy_body(s->w, id) == SX_OK);
        if (s->stale_body_count < WLD_MAX_STALE) s->stale_bodies[s->stale_body_count++] = id;
    }
}

static void wld_add_collider(fz_reader *r, wld_state *s) {
    sx_collider_def cd = sx_default_collider_def();
    sx_collider_id id = {7, 7};
    int b;
    sx_body_id body = wld_pick_body(r, s, &b);
    uint8_t flags = fz_u8(r);
    sx_status st, shape_st;
    bool sane;
    if (flags % 4u == 0u) {
        cd.shape = fz_shape(r);
    } else { /* a modest box or circle, most of the time */
        sx_real a = SX_R(0.05) + (sx_real)(fz_u8(r) % 32u) / SX_R(16.0);
        sx_real c = SX_R(0.05) + (sx_real)(fz_u8(r) % 32u) / SX_R(16.0);
        cd.shape = flags % 4u == 1u ? sx_circle_shape(sx_v2_zero(), a) : sx_box_shape(a, c);
    }
    if (flags & 4u) cd.density = wld_real(r, 10.0);
    if (flags & 8u) cd.friction = wld_real(r, 2.0);
    if (flags & 16u) cd.restitution = wld_real(r, 2.0);
    cd.sensor = (flags & 32u) != 0 && fz_u8(r) % 2u;
    if (flags & 64u) {
        cd.filter.category = (uint32_t)fz_u8(r);
        cd.filter.mask = (uint32_t)fz_u8(r);
        cd.filter.group = fz_int8(r) / 32;
    }
    st = sx_body_add_collider(s->w, body, &cd, (flags & 128u) ? NULL : &id);
    WLD_LOG("add collider to %u:%u shape type %d extent %g area %g density %g friction %g "
            "restitution %g sensor %d -> %d\n",
            body.index, body.generation, (int)cd.shape.type, (double)fz_shape_extent(&cd.shape),
            (double)sx_shape_area(&cd.shape), (double)cd.density, (double)cd.friction,
            (double)cd.restitution, (int)cd.sensor, (int)st);
    FZ_CHECK(fz_status_known(st));
    shape_st = sx_shape_validate(&cd.shape);
    if (b < 0 && shape_st == SX_OK && sx_is_finite(cd.density) && sx_is_finite(cd.friction) &&
        sx_is_finite(cd.restitution) && cd.density >= SX_R(0.0) && cd.friction >= SX_R(0.0) &&
        cd.restitution >= SX_R(0.0))
        FZ_CHECK(st == SX_ERR_STALE_HANDLE);
    if (shape_st != SX_OK) FZ_CHECK(st != SX_OK);
    if (!(sx_is_finite(cd.density) && sx_is_finite(cd.friction) && sx_is_finite(cd.restitution)))
        FZ_CHECK(st != SX_OK);
    if (cd.density < SX_R(0.0) || cd.friction < SX_R(0.0) || cd.restitution < SX_R(0.0))
        FZ_CHECK(st != SX_OK);
    if (b >= 0 && shape_st == SX_OK && sx_is_finite(cd.density) && sx_is_finite(cd.friction) &&
        sx_is_finite(cd.restitution) && cd.density >= SX_R(0.0) && cd.friction >= SX_R(0.0) &&
        cd.restitution >= SX_R(0.0)) {
        /* a shape reaching beyond SX_HUGE from the body origin is refused */
        sx_aabb box = sx_shape_aabb(&cd.shape, sx_xform_identity());
        bool within = box.lower.x >= -SX_HUGE && box.lower.y >= -SX_HUGE &&
                      box.upper.x <= SX_HUGE && box.upper.y <= SX_HUGE;
        FZ_CHECK(st == (within ? SX_OK : SX_ERR_INVALID_ARG));
    }
    if (st != SX_OK) {
        if (!(flags & 128u)) FZ_CHECK(id.index == 0 && id.generation == 0);
        return;
    }
    {
        sx_real e = fz_shape_extent(&cd.shape);
        sx_aabb box = sx_shape_aabb(&cd.shape, sx_xform_identity());
        sx_real w = sx_minr(box.upper.x - box.lower.x, box.upper.y - box.lower.y);
        sane =
            e <= SX_R(10.0) && w >= SX_R(0.01) &&
            (cd.density == SX_R(0.0) || (cd.density >= SX_R(0.01) && cd.density <= SX_R(100.0))) &&
            cd.friction <= SX_R(10.0) && cd.restitution <= SX_R(1.0);
        /* slender or rounded polygons: the shape's own area must be sane too */
        sane = sane && (cd.density == SX_R(0.0) || sx_shape_area(&cd.shape) >= SX_R(1e-4));
    }
    s->sane = s->sane && sane;
    s->bounded = s->bounded && fz_shape_extent(&cd.shape) <= SX_HUGE;
    if (flags & 128u) return; /* untracked: its body's destruction removes it */
    if (s->collider_count < WLD_MAX_COLLIDERS) {
        s->colliders[s->collider_count] = id;
        s->collider_body[s->collider_count] = b;
        ++s->collider_count;
    } else {
        FZ_CHECK(sx_destroy_collider(s->w, id) == SX_OK);
        if (s->stale_collider_count < WLD_MAX_STALE)
            s->stale_colliders[s->stale_collider_count++] = id;
    }
}

static void wld_push(fz_reader *r, wld_state *s) {
    int b;
    sx_body_id body = wld_pick_body(r, s, &b);
    uint8_t op = fz_u8(r);
    sx_vec2 v = wld_vec(r, op % 2u ? 1e3 : 20.0), p = sx_v2_zero();
    /* a body far away: the lever arm of a point force may overflow */
    bool far = !wld_vin(sx_body_get_world_center(s->w, body), 1e15);
    sx_real a;
    sx_status st;
    bool finite;
    WLD_LOG("push op %d body %u:%u v (%g, %g)\n", (int)(op % 10u), body.index, body.generation,
            (double)v.x, (double)v.y);
    switch (op % 10u) {
    case 0:
        st = sx_body_apply_force(s->w, body, v);
        wld_expect(st, b >= 0, sx_vec2_is_finite(v), !wld_vin(v, 1e15));
        s->sane = s->sane && (st != SX_OK || wld_vin(v, 1e4));
        break;
    case 1:
        p = wld_vec(r, 20.0);
        WLD_LOG("  at point (%g, %g)\n", (double)p.x, (double)p.y);
        st = sx_body_apply_force_at_point(s->w, body, v, p);
        finite = sx_vec2_is_finite(v) && sx_vec2_is_finite(p);
        wld_expect(st, b >= 0, finite, far || !wld_vin(v, 1e15) || !wld_vin(p, 1e15));
        s->sane = s->sane && (st != SX_OK || (wld_vin(v, 1e4) && wld_vin(p, 1e3)));
        break;
    case 2:
        a = v.x;
        st = sx_body_apply_torque(s->w, body, a);
        wld_expect(st, b >= 0, sx_is_finite(a), !wld_in(a, 1e15));
        s->sane = s->sane && (st != SX_OK || wld_in(a, 1e4));
        break;
    case 3:
        st = sx_body_apply_impulse(s->w, body, v);
        wld_expect(st, b >= 0, sx_vec2_is_finite(v), !wld_vin(v, 1e15));
        s->sane = s->sane && (st != SX_OK || wld_vin(v, 1e2));
        break;
    case 4:
        p = wld_vec(r, 20.0);
        WLD_LOG("  at point (%g, %g)\n", (double)p.x, (double)p.y);
        st = sx_body_apply_impulse_at_point(s->w, body, v, p);
        wld_expect(st, b >= 0, sx_vec2_is_finite(v) && sx_vec2_is_finite(p),
                   far || !wld_vin(v, 1e15) || !wld_vin(p, 1e15));
        s->sane = s->sane && (st != SX_OK || (wld_vin(v, 1e2) && wld_vin(p, 1e3)));
        break;
    case 5:
        a = v.y;
        st = sx_body_apply_angular_impulse(s->w, body, a);
        wld_expect(st, b >= 0, sx_is_finite(a), !wld_in(a, 1e15));
        s->sane = s->sane && (st != SX_OK || wld_in(a, 1e2));
        break;
    case 6: /* teleport */
        a = wld_real(r, 4.0);
        st = sx_body_set_transform(s->w, body, v, a);
        wld_expect(st, b >= 0, sx_vec2_is_finite(v) && sx_is_finite(a), false);
        s->sane = s->sane && (st != SX_OK || (wld_vin(v, 1e3) && wld_in(a, 1e3)));
        s->bounded = s->bounded && (st != SX_OK || wld_vin(v, (double)SX_HUGE));
        if (st == SX_OK && wld_vin(v, 1e3)) {
            sx_vec2 q = sx_body_get_position(s->w, body);
            FZ_CHECK(sx_distance(q, v) <= SX_R(1e-4) * (SX_R(1.0) + sx_length(v)));
        }
        break;
    case 7:
        st = sx_body_set_linear_velocity(s->w, body, v);
        wld_expect(st, b >= 0, sx_vec2_is_finite(v), !wld_vin(v, 1e15));
        s->sane = s->sane && (st != SX_OK || wld_vin(v, 100.0));
        break;
    case 8:
        st = sx_body_set_angular_velocity(s->w, body, v.x);
        wld_expect(st, b >= 0, sx_is_finite(v.x), false);
        s->sane = s->sane && (st != SX_OK || wld_in(v.x, 100.0));
        break;
    default: {
        uint8_t t = fz_u8(r);
        if (t % 2u) {
            st = sx_body_set_awake(s->w, body, (t & 2u) != 0);
            FZ_CHECK(st == (b >= 0 ? SX_OK : SX_ERR_STALE_HANDLE));
        } else {
            st = sx_body_set_type(s->w, body, (sx_body_type)((t >> 1) % 4u));
            FZ_CHECK(fz_status_known(st));
            if (b < 0)
                FZ_CHECK(st != SX_OK);
            else if ((t >> 1) % 4u == 3u)
                FZ_CHECK(st == SX_ERR_INVALID_ARG);
            else
                FZ_CHECK(st == SX_OK);
        }
        break;
    }
    }
}

/* A step, or one stage, with any dt. */
static void wld_step(fz_reader *r, wld_state *s) {
    uint8_t k = fz_u8(r);
    sx_real dt;
    sx_status st;
    bool finite, positive;
    if (k % 4u != 0u)
        dt = SX_R(1.0) / (sx_real)(30 + 30 * (k % 3u));
    else
        dt = fz_real(r);
    finite = sx_is_finite(dt);
    positive = dt > SX_R(0.0);
    if (s->steps >= WLD_MAX_STEPS && finite && positive) return; /* keep inputs fast */
    WLD_LOG("stage %d dt %g\n", (int)((k >> 2) % 8u), (double)dt);
    switch ((k >> 2) % 8u) {
    case 0: st = sx_world_apply_forces(s->w, dt); break;
    case 1: st = sx_world_solve(s->w, dt); break;
    case 2: st = sx_world_integrate(s->w, dt); break;
    case 3: st = sx_world_separate(s->w, dt); break;
    case 4: st = sx_world_update_sleep(s->w, dt); break;
    case 5:
        st = sx_world_collide(s->w);
        FZ_CHECK(st == SX_OK);
        return;
    case 6:
        if (k & 32u) {
            st = sx_world_continuous(s->w);
            FZ_CHECK(st == SX_OK);
            return;
        }
        st = sx_world_step(s->w, dt);
        break;
    default: st = sx_world_step(s->w, dt); break;
    }
    FZ_CHECK(fz_status_known(st));
    if (!finite)
        FZ_CHECK(st == SX_ERR_NONFINITE || st == SX_ERR_INVALID_ARG);
    else if (!positive)
        FZ_CHECK(st == SX_ERR_INVALID_ARG);
    else
        FZ_CHECK(st == SX_OK);
    if (st == SX_OK) {
        ++s->steps;
        s->sane = s->sane && dt <= SX_R(0.1) && dt >= SX_R(1e-4);
    }
}

static bool wld_count_fn(sx_collider_id c, sx_body_id b, void *context) {
    (void)c;
    (void)b;
    ++*(int *)context;
    return true;
}

typedef struct wld_draw_ctx {
    int shapes;
    bool check_nan;
} wld_draw_ctx;

static void wld_draw_shape(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                           void *context) {
    wld_draw_ctx *c = (wld_draw_ctx *)context;
    (void)shape;
    (void)type;
    (void)sensor;
    if (c->check_nan) FZ_CHECK(!fz_is_nan(xf.p.x) && !fz_is_nan(xf.p.y));
    ++c->shapes;
}

static void wld_draw_contact(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context) {
    const wld_draw_ctx *c = (const wld_draw_ctx *)context;
    if (c->check_nan)
        FZ_CHECK(!fz_is_nan(point.x) && !fz_is_nan(point.y) && !fz_is_nan(normal.x) &&
                 !fz_is_nan(depth));
}

static void wld_query(fz_reader *r, wld_state *s) {
    uint8_t k = fz_u8(r);
    int seen = 0, n;
    switch (k % 5u) {
    case 0: {
        sx_aabb box;
        box.lower = wld_vec(r, 20.0);
        box.upper = sx_add(box.lower, wld_vec(r, 20.0));
        n = sx_world_query_aabb(s->w, box, wld_count_fn, &seen);
        FZ_CHECK(n >= 0 && n == seen);
        break;
    }
    case 1:
        n = sx_world_query_point(s->w, wld_vec(r, 20.0), wld_count_fn, &seen);
        FZ_CHECK(n >= 0 && n == seen);
        break;
    case 2: {
        sx_shape sh = fz_shape(r);
        bool sane;
        sx_xform xf = fz_xform(r, &sane);
        n = sx_world_query_shape(s->w, &sh, xf, wld_count_fn, &seen);
        FZ_CHECK(n >= 0 && n == seen);
        if (sx_shape_validate(&sh) != SX_OK) FZ_CHECK(n == 0);
        break;
    }
    case 3: {
        sx_ray_input ray;
        sx_world_ray_hit hit;
        bool h;
        ray.origin = wld_vec(r, 20.0);
        ray.translation = wld_vec(r, 40.0);
        ray.max_fraction = fz_u8(r) % 2u ? SX_R(1.0) : wld_real(r, 2.0);
        h = sx_world_cast_ray(s->w, &ray, &hit);
        if (h) {
            FZ_CHECK(hit.fraction >= SX_R(0.0) && hit.fraction <= ray.max_fraction);
            FZ_CHECK(sx_collider_is_valid(s->w, hit.collider));
            if (wld_nan_checked(s)) FZ_CHECK(!fz_is_nan(hit.normal.x) && !fz_is_nan(hit.normal.y));
            if (s->sane && sx_vec2_is_finite(ray.translation) && sx_vec2_is_finite(ray.origin))
                FZ_CHECK(fz_is_unit(hit.normal) && sx_vec2_is_finite(hit.point));
        } else {
            FZ_CHECK(hit.fraction == SX_R(0.0) && sx_body_id_is_null(hit.body));
        }
        break;
    }
    default: {
        sx_debug_draw dd;
        wld_draw_ctx ctx;
        sx_contact_events ce = sx_world_get_contact_events(s->w);
        sx_sensor_events se = sx_world_get_sensor_events(s->w);
        FZ_CHECK(ce.begin_count >= 0 && ce.end_count >= 0);
        FZ_CHECK(se.begin_count >= 0 && se.end_count >= 0);
        memset(&dd, 0, sizeof dd);
        dd.draw_shape = wld_draw_shape;
        dd.draw_contact = wld_draw_contact;
        ctx.shapes = 0;
        ctx.check_nan = wld_nan_checked(s);
        dd.context = &ctx;
        FZ_CHECK(sx_world_draw(s->w, &dd) == SX_OK);
        FZ_CHECK(sx_world_draw(s->w, NULL) == SX_ERR_INVALID_ARG);
        if (k & 8u) FZ_CHECK(sx_world_clear_events(s->w) == SX_OK);
        break;
    }
    }
}

static sx_world *wld_create(fz_reader *r, bool *sane) {
    sx_world_def d = sx_default_world_def();
    uint8_t flags = fz_u8(r);
    bool valid;
    sx_world *w;
    *sane = true;
    if (flags % 2u) {
        uint8_t more = fz_u8(r);
        d.gravity = wld_vec(r, 20.0);
        d.sub_steps = (int)(fz_u8(r) % 6u); /* 0 is out of range */
        d.velocity_iterations = (int)(fz_u8(r) % 6u);
        d.position_iterations = (int)(fz_u8(r) % 4u) - (more % 8u == 0u ? 1 : 0);
        if (more & 8u) d.correction_factor = wld_real(r, 1.0);
        if (more & 16u) d.max_correction_speed = wld_real(r, 10.0);
        if (more & 32u) d.restitution_threshold = wld_real(r, 2.0);
        if (more & 64u) d.speculative_slops = wld_real(r, 8.0);
        if (more & 128u) d.length_units_per_meter = wld_real(r, 4.0);
        d.enable_sleep = (flags & 2u) != 0;
        if (flags & 4u) d.time_to_sleep = wld_real(r, 1.0);
        if (flags & 8u) d.sleep_linear_speed = wld_real(r, 0.5);
        if (flags & 16u) d.body_capacity = (int)fz_u8(r) - 8;
        d.enable_continuous = (flags & 32u) == 0;
    }
    valid = sx_vec2_is_finite(d.gravity) && d.sub_steps >= 1 && d.velocity_iterations >= 1 &&
            d.position_iterations >= 0 && sx_is_finite(d.correction_factor) &&
            d.correction_factor > SX_R(0.0) && d.correction_factor <= SX_R(1.0) &&
            sx_is_finite(d.max_correction_speed) && d.max_correction_speed > SX_R(0.0) &&
            sx_is_finite(d.restitution_threshold) && d.restitution_threshold >= SX_R(0.0) &&
            sx_is_finite(d.speculative_slops) && d.speculative_slops >= SX_R(0.0) &&
            sx_is_finite(d.length_units_per_meter) && d.length_units_per_meter > SX_R(0.0) &&
            d.body_capacity >= 0 && sx_is_finite(d.sleep_linear_speed) &&
            d.sleep_linear_speed >= SX_R(0.0) && sx_is_finite(d.time_to_sleep) &&
            d.time_to_sleep > SX_R(0.0);
    w = sx_world_create(&d);
    WLD_LOG("world gravity (%g, %g) sub %d vel %d pos %d cf %g mcs %g rt %g ss %g lu %g sleep %d "
            "continuous %d\n",
            (double)d.gravity.x, (double)d.gravity.y, d.sub_steps, d.velocity_iterations,
            d.position_iterations, (double)d.correction_factor, (double)d.max_correction_speed,
            (double)d.restitution_threshold, (double)d.speculative_slops,
            (double)d.length_units_per_meter, (int)d.enable_sleep, (int)d.enable_continuous);
    FZ_CHECK((w != NULL) == valid);
    *sane = wld_vin(d.gravity, 100.0) && d.max_correction_speed <= SX_R(100.0) &&
            d.speculative_slops <= SX_R(100.0) && d.length_units_per_meter >= SX_R(0.1) &&
            d.length_units_per_meter <= SX_R(10.0);
    return w;
}

/* ---- pinched scenes under the energy audit ---------------------------------
 * (Each byte is read in its own statement: two reads among the arguments of
 * one call are made in an order C leaves open, and gcc and clang differed,
 * so an input found by the clang fuzzer replayed as another scene in the
 * gcc test build.)
 *
 * An input whose first byte is 2 mod 4 builds a scene instead (the command
 * interpreter reads such a byte as "default world def" and ignores its bit
 * 1, so each command input has an equal with that bit clear, and the corpus
 * files that had it set were rewritten so): a static ground, sometimes walls
 * and a slanted block to pinch against, and 2 to WLD_PINCH_BODIES bodies
 * of masses 10^-2 to 10^4 kg per square metre and sizes 2 cm to 1.5 m (mass
 * ratios past 10^6) stacked on top of one another so that light ones are
 * pinched, with any restitution in [0, 1], friction, velocities, spins,
 * gravity scales and constant forces; then up to WLD_PINCH_STEPS steps
 * through fuzz_energy.h's audit, which checks after every sub-step that the
 * total energy stays within its start plus what gravity and the forces put
 * in (the allowances and their derivation are in fuzz_energy.h). Also: every
 * stage answers SX_OK and no state turns NaN or infinite. */
#define WLD_PINCH_BODIES 8
#define WLD_PINCH_STEPS 16

/* A value in [lo, hi] on a log scale, from one byte. */
static double wld_log_range(fz_reader *r, double lo, double hi) {
    return lo * pow(hi / lo, (double)fz_u8(r) / 255.0);
}

static sx_shape wld_pinch_shape(fz_reader *r, double size) {
    uint8_t k = fz_u8(r);
    sx_real s = (sx_real)size, t = (sx_real)(size * (0.3 + 0.7 * (double)fz_u8(r) / 255.0));
    switch (k % 4u) {
    case 0: return sx_circle_shape(sx_v2_zero(), s);
    case 1: return sx_box_shape(s, t);
    case 2: return sx_capsule_shape(sx_v2(-s + t, SX_R(0.0)), sx_v2(s - t, SX_R(0.0)), t);
    default: {
        sx_vec2 p[6];
        sx_shape shape;
        int n = 3 + (int)(k / 4u % 4u), i;
        for (i = 0; i < n; ++i) {
            double a = 6.283185307179586 * (double)i / (double)n;
            p[i] = sx_v2((sx_real)(size * cos(a)), (sx_real)(size * sin(a)));
        }
        FZ_CHECK(sx_polygon_shape(p, n, SX_R(0.0), &shape) == SX_OK);
        return shape;
    }
    }
}

static void wld_pinch_static(sx_world *w, sx_vec2 p, sx_real angle, sx_shape shape, double friction,
                             double restitution) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    bd.position = p;
    bd.angle = angle;
    FZ_CHECK(sx_create_body(w, &bd, &id) == SX_OK);
    cd.shape = shape;
    cd.friction = (sx_real)friction;
    cd.restitution = (sx_real)restitution;
    FZ_CHECK(sx_body_add_collider(w, id, &cd, NULL) == SX_OK);
}

/* A restitution: often 0, 1/2 or 1, else any in [0, 1]. */
static double wld_pinch_restitution(fz_reader *r) {
    uint8_t k = fz_u8(r);
    switch (k % 4u) {
    case 0: return 0.0;
    case 1: return 1.0;
    case 2: return 0.5;
    default: return (double)(k / 4u) / 63.0;
    }
}

static void wld_pinch_scene(fz_reader *r) {
    static const double thresholds[4] = {1.0, 0.0, 0.25, 3.0};
    static const double slops[4] = {4.0, 0.0, 1.0, 16.0};
    static const double scales[8] = {1.0, 1.0, 1.0, 1.0, 0.5, 2.0, 0.0, -1.0};
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_body_id bodies[WLD_PINCH_BODIES];
    sx_vec2 forces[WLD_PINCH_BODIES];
    double gravity_scales[WLD_PINCH_BODIES], max_friction, top = 0.0, dt;
    uint8_t k = fz_u8(r), layout = fz_u8(r);
    int n = 2 + (int)(fz_u8(r) % (WLD_PINCH_BODIES - 1)), i, steps;
    fz_energy audit;
    def.enable_sleep = false;
    def.sub_steps = 1 + (int)(k % 8u);
    def.velocity_iterations = 1 + (int)(k / 8u % 8u);
    def.position_iterations = (int)(k / 64u);
    def.restitution_threshold = (sx_real)thresholds[layout % 4u];
    def.speculative_slops = (sx_real)slops[layout / 4u % 4u];
    switch (layout / 16u % 4u) {
    case 0: def.gravity = sx_v2(SX_R(0.0), SX_R(-10.0)); break;
    case 1: def.gravity = sx_v2(SX_R(0.0), SX_R(-30.0)); break;
    case 2:
        def.gravity.x = (sx_real)fz_int8(r) / SX_R(8.0);
        def.gravity.y = (sx_real)fz_int8(r) / SX_R(8.0);
        break;
    default: def.gravity = sx_v2_zero(); break;
    }
    dt = 1.0 / (30.0 * (double)(1 + layout / 64u % 4u));
    w = sx_world_create(&def);
    FZ_CHECK(w != NULL);
    max_friction = (double)fz_u8(r) / 128.0;
    wld_pinch_static(w, sx_v2(SX_R(0.0), SX_R(-1.0)), SX_R(0.0),
                     sx_box_shape(SX_R(20.0), SX_R(1.0)), max_friction, wld_pinch_restitution(r));
    if (layout & 128u) { /* walls 2 m apart and a slanted block to wedge against */
        double e = wld_pinch_restitution(r);
        wld_pinch_static(w, sx_v2(SX_R(-1.5), SX_R(2.0)), SX_R(0.0),
                         sx_box_shape(SX_R(0.5), SX_R(3.0)), max_friction, e);
        wld_pinch_static(w, sx_v2(SX_R(1.5), SX_R(2.0)), SX_R(0.0),
                         sx_box_shape(SX_R(0.5), SX_R(3.0)), max_friction, e);
        wld_pinch_static(w, sx_v2(SX_R(0.9), SX_R(0.2)), (sx_real)fz_int8(r) / SX_R(128.0),
                         sx_box_shape(SX_R(0.4), SX_R(0.2)), max_friction, e);
    }
    for (i = 0; i < n; ++i) {
        sx_body_def bd = sx_default_body_def();
        sx_collider_def cd = sx_default_collider_def();
        double size = wld_log_range(r, 0.02, 1.5), density = wld_log_range(r, 1e-2, 1e4), accel;
        uint8_t flags = fz_u8(r);
        bd.type = SX_BODY_DYNAMIC;
        /* on top of the last, touching or a little into it or above it */
        bd.position.x = (sx_real)((double)fz_int8(r) / 128.0 * size);
        bd.position.y = (sx_real)(top + size * (0.9 + 0.2 * (double)fz_u8(r) / 255.0));
        top = (double)bd.position.y + size;
        bd.angle = (sx_real)fz_int8(r) / SX_R(40.0);
        if (flags & 1u) {
            bd.linear_velocity.x = (sx_real)fz_int8(r) / SX_R(12.8);
            bd.linear_velocity.y = (sx_real)fz_int8(r) / SX_R(12.8);
        }
        if (flags & 2u) bd.angular_velocity = (sx_real)fz_int8(r) / SX_R(12.8);
        bd.fixed_rotation = (flags & 4u) != 0;
        gravity_scales[i] = scales[flags / 8u % 8u];
        bd.gravity_scale = (sx_real)gravity_scales[i];
        FZ_CHECK(sx_create_body(w, &bd, &bodies[i]) == SX_OK);
        cd.shape = wld_pinch_shape(r, size);
        cd.density = (sx_real)density;
        cd.friction = (sx_real)(max_friction * (double)fz_u8(r) / 255.0);
        cd.restitution = (sx_real)wld_pinch_restitution(r);
        FZ_CHECK(sx_body_add_collider(w, bodies[i], &cd, NULL) == SX_OK);
        WLD_LOG("  body %d: shape %d size %g density %g at (%g, %g) angle %g v (%g, %g) w %g "
                "fixed %d gravity x %g friction %g restitution %g\n",
                i, (int)cd.shape.type, size, density, (double)bd.position.x, (double)bd.position.y,
                (double)bd.angle, (double)bd.linear_velocity.x, (double)bd.linear_velocity.y,
                (double)bd.angular_velocity, (int)bd.fixed_rotation, gravity_scales[i],
                (double)cd.friction, (double)cd.restitution);
        /* a constant force of up to 10 m/s^2 on the body's mass */
        accel = flags & 64u ? 10.0 / 128.0 : 0.0;
        forces[i].x = (sx_real)(accel * (double)fz_int8(r) * (double)sx_body_get_mass(w, bodies[i]));
        forces[i].y = (sx_real)(accel * (double)fz_int8(r) * (double)sx_body_get_mass(w, bodies[i]));
    }
    WLD_LOG("pinch: %d bodies, sub %d vel %d pos %d threshold %g slops %g gravity (%g, %g) dt %g "
            "friction <= %g walls %d\n",
            n, def.sub_steps, def.velocity_iterations, def.position_iterations,
            (double)def.restitution_threshold, (double)def.speculative_slops, (double)def.gravity.x,
            (double)def.gravity.y, dt, max_friction, (layout & 128u) != 0);
    fz_energy_begin(&audit, w, def.gravity, def.sub_steps, dt, bodies, forces, gravity_scales, n,
                    max_friction);
    steps = 1 + (int)(fz_u8(r) % WLD_PINCH_STEPS);
    for (i = 0; i < steps; ++i) {
        int b;
        FZ_CHECK(fz_energy_step(&audit) == SX_OK);
        WLD_LOG("  step %d: E %.9g start %.9g allowance %.9g worst %.3g\n", i, audit.energy,
                audit.start, audit.allowance, audit.worst);
        for (b = 0; b < n; ++b) {
            FZ_CHECK(sx_vec2_is_finite(sx_body_get_world_center(w, bodies[b])));
            FZ_CHECK(sx_vec2_is_finite(sx_body_get_linear_velocity(w, bodies[b])));
            FZ_CHECK(sx_is_finite(sx_body_get_angular_velocity(w, bodies[b])));
        }
        FZ_CHECK(audit.velocities_kept);
        FZ_CHECK(fz_energy_held(&audit));
    }
    sx_world_destroy(w);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fz_reader r = fz_reader_make(data, size);
    size_t live = sx_live_bytes();
    wld_state s;
    int c;
    memset(&s, 0, sizeof s);
    if (size > 0 && data[0] % 4u == 2u) {
        r.pos = 1;
        wld_pinch_scene(&r);
        FZ_CHECK(sx_live_bytes() == live);
        return 0;
    }
    FZ_CHECK(sx_world_create(NULL) == NULL);
    s.w = wld_create(&r, &s.sane);
    s.bounded = true;
    if (s.w == NULL) {
        FZ_CHECK(sx_live_bytes() == live);
        return 0;
    }
    for (c = 0; c < WLD_MAX_COMMANDS && r.pos < r.size; ++c) {
        uint8_t cmd = fz_u8(&r);
        switch (cmd % 10u) {
        case 0:
        case 1: wld_create_body(&r, &s); break;
        case 2: {
            int b;
            sx_body_id id = wld_pick_body(&r, &s, &b);
            sx_status st = sx_destroy_body(s.w, id);
            WLD_LOG("destroy body %u:%u -> %d\n", id.index, id.generation, (int)st);
            FZ_CHECK(st == (b >= 0 ? SX_OK : SX_ERR_STALE_HANDLE));
            if (b >= 0) wld_forget_body(&s, b);
            break;
        }
        case 3:
        case 4: wld_add_collider(&r, &s); break;
        case 5: {
            int k;
            sx_collider_id id = wld_pick_collider(&r, &s, &k);
            sx_status st = sx_destroy_collider(s.w, id);
            WLD_LOG("destroy collider %u:%u -> %d\n", id.index, id.generation, (int)st);
            FZ_CHECK(st == (k >= 0 ? SX_OK : SX_ERR_STALE_HANDLE));
            if (k >= 0) wld_forget_collider(&s, k);
            break;
        }
        case 6: wld_push(&r, &s); break;
        case 7: wld_query(&r, &s); break;
        case 8: {
            sx_vec2 g = wld_vec(&r, 20.0);
            sx_status st = sx_world_set_gravity(s.w, g);
            WLD_LOG("gravity (%g, %g)\n", (double)g.x, (double)g.y);
            FZ_CHECK(st == (sx_vec2_is_finite(g) ? SX_OK : SX_ERR_NONFINITE));
            s.sane = s.sane && (st != SX_OK || wld_vin(g, 100.0));
            break;
        }
        default: wld_step(&r, &s); break;
        }
        wld_check_world(&s);
    }
    /* A few plain steps at the end, so every input is also simulated. */
    for (c = 0; c < 3; ++c) {
        FZ_CHECK(sx_world_step(s.w, SX_R(1.0) / SX_R(60.0)) == SX_OK);
        wld_check_world(&s);
    }
    sx_world_destroy(s.w);
    FZ_CHECK(sx_live_bytes() == live);
    return 0;
}
