/* sepax — world queries (bounds, point, shape overlap, closest ray hit) and
 * the debug-draw walk.
 *
 * Every query visits the colliders of enabled bodies in slot order and asks
 * the narrowphase about each one at the bodies' current transforms, so the
 * answers are exact and deterministic and never depend on when collide last
 * ran. The price is a cost linear in the number of colliders; a bounding
 * volume tree shared with the broadphase would make it logarithmic.
 *
 * While a walk calls the user back, the world is locked (lock_depth): the
 * calls that add or remove bodies and colliders or run the step refuse with
 * SX_ERR_LOCKED, as Box2D v3 refuses them in a locked world and Chipmunk in
 * a query. The walk can then hold pointers into the collider and contact
 * arrays across a callback, a query never reports a collider its own
 * callback made, and the debug draw never reads the parts of a compound
 * freed under it. sx_world_destroy from a callback waits for the outermost
 * walk to return, and the walks stop calling back once it is asked for. */
#include <stdint.h>

#include <string.h>

#include "world_body.h"
#include "world_contact.h"
#include "world_internal.h"

/* The collider and body handles of collider slot i. */
static void sx_handles(const sx_world *world, int i, sx_collider_id *c, sx_body_id *b) {
    const sx_collider *col = &world->colliders[i];
    c->index = (uint32_t)i;
    c->generation = world->collider_generations[i];
    b->index = (uint32_t)col->body;
    b->generation = world->infos[col->body].generation;
}

/* True if collider slot i takes part in queries and drawing. */
static bool sx_queryable(const sx_world *world, int i) {
    const sx_collider *c = &world->colliders[i];
    return c->alive && world->infos[c->body].enabled;
}

/* Starts a walk that calls back: the world is locked until sx_walk_end.
 * The lock count is the one field a const walk writes; the world was
 * allocated by sx_world_create, never defined const, so writing it through
 * the cast is defined. */
static sx_world *sx_walk_begin(const sx_world *world) {
    sx_world *w = (sx_world *)(uintptr_t)world;
    w->lock_depth++;
    return w;
}

/* Ends a walk; the outermost one carries out a destroy asked for by a
 * callback (the world is then gone). */
static void sx_walk_end(sx_world *world) {
    if (--world->lock_depth > 0 || !world->destroy_pending) return;
    world->destroy_pending = false;
    sx_world_destroy(world);
}

/* What a query tests for each collider. */
typedef enum sx_query_kind { SX_QUERY_AABB, SX_QUERY_POINT, SX_QUERY_SHAPE } sx_query_kind;

typedef struct sx_query {
    sx_query_kind kind;
    sx_aabb box;
    sx_vec2 point;
    const sx_shape *shape;
    sx_xform xf;
} sx_query;

/* True if part `index` of the view (placed by xf) answers the query. */
static bool sx_query_part(const sx_query *q, const sx_compound_part *part, sx_xform xf) {
    sx_xform px = sx_xform_mul(xf, part->offset);
    if (!sx_aabb_overlaps(sx_shape_aabb(&part->shape, px), q->box)) return false;
    switch (q->kind) {
    case SX_QUERY_POINT: return sx_contains_point(&part->shape, px, q->point);
    case SX_QUERY_SHAPE: return sx_overlap(&part->shape, px, q->shape, q->xf);
    case SX_QUERY_AABB:
    default: return true;
    }
}

static int sx_run_query(const sx_world *world, const sx_query *q, sx_query_fn *fn, void *context) {
    int i, found = 0;
    sx_world *locked = fn != NULL ? sx_walk_begin(world) : NULL;
    for (i = 0; i < world->collider_slots; ++i) {
        const sx_collider *c;
        sx_xform xf;
        sx_collider_id cid;
        sx_body_id bid;
        bool hit = false;
        if (!sx_queryable(world, i)) continue;
        c = &world->colliders[i];
        xf = world->sims[c->body].xf;
        if (c->part_count > 0) {
            int k;
            /* a compound answers through its parts: a point or box in a
             * notch of its outline misses */
            if (!sx_aabb_overlaps(sx_collider_aabb(c, xf), q->box)) continue;
            for (k = 0; k < c->part_count && !hit; ++k)
                hit = sx_query_part(q, &c->parts[k], xf);
        } else {
            if (!sx_aabb_overlaps(sx_shape_aabb(&c->shape, xf), q->box)) continue;
            switch (q->kind) {
            case SX_QUERY_POINT: hit = sx_contains_point(&c->shape, xf, q->point); break;
            case SX_QUERY_SHAPE: hit = sx_overlap(&c->shape, xf, q->shape, q->xf); break;
            case SX_QUERY_AABB:
            default: hit = true; break;
            }
        }
        if (!hit) continue;
        ++found;
        sx_handles(world, i, &cid, &bid);
        if (fn != NULL && (!fn(cid, bid, context) || world->destroy_pending)) break;
    }
    if (locked != NULL) sx_walk_end(locked);
    return found;
}

int sx_world_query_aabb(const sx_world *world, sx_aabb box, sx_query_fn *fn, void *context) {
    sx_query q;
    if (world == NULL || !sx_vec2_is_finite(box.lower) || !sx_vec2_is_finite(box.upper) ||
        !sx_aabb_is_valid(box)) {
        return 0;
    }
    memset(&q, 0, sizeof(q));
    q.kind = SX_QUERY_AABB;
    q.box = box;
    return sx_run_query(world, &q, fn, context);
}

int sx_world_query_point(const sx_world *world, sx_vec2 point, sx_query_fn *fn, void *context) {
    sx_query q;
    if (world == NULL || !sx_vec2_is_finite(point)) return 0;
    memset(&q, 0, sizeof(q));
    q.kind = SX_QUERY_POINT;
    q.point = point;
    q.box = sx_aabb_make(point, point);
    return sx_run_query(world, &q, fn, context);
}

int sx_world_query_shape(const sx_world *world, const sx_shape *shape, sx_xform xf, sx_query_fn *fn,
                         void *context) {
    sx_query q;
    if (world == NULL || shape == NULL || sx_shape_validate(shape) != SX_OK ||
        !sx_xform_is_finite(xf)) {
        return 0;
    }
    memset(&q, 0, sizeof(q));
    q.kind = SX_QUERY_SHAPE;
    q.shape = shape;
    q.xf = xf;
    q.box = sx_shape_aabb(shape, xf);
    return sx_run_query(world, &q, fn, context);
}

bool sx_world_cast_ray(const sx_world *world, const sx_ray_input *ray, sx_world_ray_hit *out) {
    sx_ray_input r;
    bool any = false;
    int i;
    if (out != NULL) memset(out, 0, sizeof(*out));
    if (world == NULL || ray == NULL || out == NULL) return false;
    r = *ray;
    for (i = 0; i < world->collider_slots; ++i) {
        const sx_collider *c;
        sx_ray_hit hit;
        int part = 0;
        if (!sx_queryable(world, i)) continue;
        c = &world->colliders[i];
        if (c->part_count > 0) {
            sx_compound view;
            view.parts = c->parts;
            view.count = c->part_count;
            if (!sx_compound_ray_cast(&view, world->sims[c->body].xf, &r, &hit, &part) ||
                !hit.hit) {
                continue;
            }
        } else if (!sx_ray_cast(&c->shape, world->sims[c->body].xf, &r, &hit) || !hit.hit) {
            continue;
        }
        /* strictly closer only: equal fractions keep the lower slot */
        if (any && !(hit.fraction < out->fraction)) continue;
        any = true;
        sx_handles(world, i, &out->collider, &out->body);
        out->point = hit.point;
        out->normal = hit.normal;
        out->fraction = hit.fraction;
        out->part = part;
        /* later colliders only matter if they are hit sooner */
        r.max_fraction = hit.fraction;
    }
    return any;
}

/* The colliders, then the contact points, through the callbacks of draw,
 * until a callback asks for the world's destruction. */
static void sx_draw_walk(const sx_world *world, const sx_debug_draw *draw) {
    int i, k;
    for (i = 0; i < world->collider_slots; ++i) {
        const sx_collider *c;
        sx_xform xf;
        if (!sx_queryable(world, i)) continue;
        c = &world->colliders[i];
        xf = world->sims[c->body].xf;
        if (draw->draw_shape != NULL) {
            sx_compound_part tmp;
            sx_compound view = sx_collider_compound(c, &tmp);
            /* a compound draws part by part, each placed by its offset */
            for (k = 0; k < view.count; ++k) {
                draw->draw_shape(&view.parts[k].shape, sx_xform_mul(xf, view.parts[k].offset),
                                 world->infos[c->body].type, c->sensor, draw->context);
                if (world->destroy_pending) return;
            }
        }
        if (draw->draw_aabb != NULL) {
            draw->draw_aabb(sx_collider_aabb(c, xf), draw->context);
            if (world->destroy_pending) return;
        }
    }
    if (draw->draw_contact != NULL) {
        for (i = 0; i < world->contact_count + world->frozen_count; ++i) {
            const sx_contact *c = i < world->contact_count
                                      ? &world->contacts[i]
                                      : &world->frozen[i - world->contact_count];
            for (k = 0; k < c->count; ++k) {
                draw->draw_contact(c->points[k].point, c->normal, -c->points[k].separation,
                                   draw->context);
                if (world->destroy_pending) return;
            }
        }
    }
}

sx_status sx_world_draw(const sx_world *world, const sx_debug_draw *draw) {
    sx_world *locked;
    if (world == NULL || draw == NULL) return SX_ERR_INVALID_ARG;
    locked = sx_walk_begin(world);
    sx_draw_walk(locked, draw);
    sx_walk_end(locked);
    return SX_OK;
}

/* ---- shape casts ---------------------------------------------------------- */

/* The first hit of the cast on collider slot i (the earliest of its parts);
 * false for a miss. */
static bool sx_cast_collider(const sx_world *world, int i, const sx_shape *shape, sx_xform xf,
                             sx_vec2 translation, sx_aabb swept, sx_world_shape_hit *out) {
    const sx_collider *c = &world->colliders[i];
    sx_xform bx = world->sims[c->body].xf;
    sx_compound_part tmp;
    sx_compound view;
    bool any = false;
    int k;
    if (!sx_aabb_overlaps(sx_collider_aabb(c, bx), swept)) return false;
    view = sx_collider_compound(c, &tmp);
    for (k = 0; k < view.count; ++k) {
        sx_shape_cast_output o;
        sx_xform px = sx_xform_mul(bx, view.parts[k].offset);
        if (!sx_aabb_overlaps(sx_shape_aabb(&view.parts[k].shape, px), swept)) continue;
        if (sx_shape_cast(shape, xf, translation, SX_R(1.0), &view.parts[k].shape, px, &o) !=
                SX_OK ||
            !o.hit || (any && !(o.fraction < out->fraction))) {
            continue;
        }
        any = true;
        sx_handles(world, i, &out->collider, &out->body);
        out->point = o.point;
        out->normal = o.normal;
        out->fraction = o.fraction;
        out->part = k;
    }
    return any;
}

/* The swept bounds of a cast, false for bad input. */
static bool sx_cast_bounds(const sx_world *world, const sx_shape *shape, sx_xform xf,
                           sx_vec2 translation, sx_aabb *swept) {
    sx_aabb a;
    sx_xform end = xf;
    if (world == NULL || shape == NULL || sx_shape_validate(shape) != SX_OK ||
        !sx_xform_is_finite(xf) || !sx_vec2_is_finite(translation)) {
        return false;
    }
    end.p = sx_add(xf.p, translation);
    if (!sx_vec2_is_finite(end.p)) return false;
    a = sx_shape_aabb(shape, xf);
    *swept = sx_aabb_union(a, sx_shape_aabb(shape, end));
    return sx_aabb_is_valid(*swept);
}

static bool sx_cast_sees(const sx_world *world, int i, const sx_filter *filter) {
    const sx_collider *c = &world->colliders[i];
    if (!sx_queryable(world, i) || c->sensor) return false;
    return filter == NULL || sx_filters_collide(filter, &c->filter);
}

bool sx_world_cast_shape(const sx_world *world, const sx_shape *shape, sx_xform xf,
                         sx_vec2 translation, const sx_filter *filter, sx_world_shape_hit *out) {
    sx_aabb swept;
    sx_xform end;
    bool any = false;
    int i;
    if (out != NULL) memset(out, 0, sizeof(*out));
    if (out == NULL || !sx_cast_bounds(world, shape, xf, translation, &swept)) return false;
    for (i = 0; i < world->collider_slots; ++i) {
        sx_world_shape_hit h;
        if (!sx_cast_sees(world, i, filter) ||
            !sx_cast_collider(world, i, shape, xf, translation, swept, &h)) {
            continue;
        }
        /* strictly closer only: equal fractions keep the lower slot */
        if (any && !(h.fraction < out->fraction)) continue;
        any = true;
        *out = h;
        /* later colliders only matter if they are hit sooner */
        end = xf;
        end.p = sx_mul_add(xf.p, h.fraction, translation);
        swept = sx_aabb_union(sx_shape_aabb(shape, xf), sx_shape_aabb(shape, end));
    }
    return any;
}

int sx_world_cast_shape_all(const sx_world *world, const sx_shape *shape, sx_xform xf,
                            sx_vec2 translation, const sx_filter *filter, sx_shape_cast_fn *fn,
                            void *context) {
    sx_aabb swept;
    sx_world *locked;
    int i, found = 0;
    if (!sx_cast_bounds(world, shape, xf, translation, &swept)) return 0;
    locked = fn != NULL ? sx_walk_begin(world) : NULL;
    for (i = 0; i < world->collider_slots; ++i) {
        sx_world_shape_hit h;
        if (!sx_cast_sees(world, i, filter) ||
            !sx_cast_collider(world, i, shape, xf, translation, swept, &h)) {
            continue;
        }
        ++found;
        if (fn != NULL && (!fn(&h, context) || world->destroy_pending)) break;
    }
    if (locked != NULL) sx_walk_end(locked);
    return found;
}
