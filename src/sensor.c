/* sepax — sensors: colliders with no response that report what overlaps
 * them.
 *
 * Each collide asks the broadphase's sets which colliders' bounds overlap
 * each sensor's, then runs the boolean overlap (the narrowphase's fast path,
 * no manifold) on those. A world with no sensor spends nothing here. The overlaps are kept as
 * a sorted list of pair keys; comparing it with the previous list (one merge
 * walk) gives the begin and end events, in a deterministic order. */
#include <string.h>

#include "world_array.h"
#include "world_body.h"
#include "world_broadphase.h"
#include "world_internal.h"
#include "world_sensor.h"

void sx_sensors_free(sx_world *world) {
    sx_free(world->visitors, (size_t)world->visitor_capacity * sizeof(int));
    sx_free(world->sensor_colliders, (size_t)world->sensor_collider_capacity * sizeof(int));
    sx_free(world->sensor_pairs, (size_t)world->sensor_capacity * sizeof(uint64_t));
    sx_free(world->old_sensor_pairs, (size_t)world->old_sensor_capacity * sizeof(uint64_t));
    sx_free(world->sensor_begin, (size_t)world->sensor_begin_capacity * sizeof(sx_sensor_event));
    sx_free(world->sensor_end, (size_t)world->sensor_end_capacity * sizeof(sx_sensor_event));
}

static bool sx_sensor_sees(const sx_world *world, const sx_collider *sensor, const sx_collider *c) {
    const sx_filter *a = &sensor->filter, *b = &c->filter;
    if (!c->alive || c->sensor || c->body == sensor->body || !world->infos[c->body].enabled) {
        return false;
    }
    if (world->infos[c->body].type == SX_BODY_STATIC &&
        world->infos[sensor->body].type == SX_BODY_STATIC) {
        return false;
    }
    if (a->group == b->group && a->group != 0) return a->group > 0;
    return (a->category & b->mask) != 0 && (b->category & a->mask) != 0;
}

static sx_status sx_push_sensor_event(sx_world *world, uint64_t key, bool begin) {
    sx_sensor_event **events = begin ? &world->sensor_begin : &world->sensor_end;
    int *count = begin ? &world->sensor_begin_count : &world->sensor_end_count;
    int *capacity = begin ? &world->sensor_begin_capacity : &world->sensor_end_capacity;
    int s = (int)(key >> 32), v = (int)(key & 0xFFFFFFFFu);
    sx_sensor_event *e;
    if (*count == *capacity) {
        void *p = *events;
        sx_status st = sx_reserve_array(&p, capacity, *count + 1, sizeof(sx_sensor_event));
        *events = (sx_sensor_event *)p;
        if (st != SX_OK) return st;
    }
    e = &(*events)[(*count)++];
    e->sensor.index = (uint32_t)s;
    e->sensor.generation = world->collider_generations[s];
    e->visitor.index = (uint32_t)v;
    e->visitor.generation = world->collider_generations[v];
    e->sensor_body.index = (uint32_t)world->colliders[s].body;
    e->sensor_body.generation = world->infos[world->colliders[s].body].generation;
    e->visitor_body.index = (uint32_t)world->colliders[v].body;
    e->visitor_body.generation = world->infos[world->colliders[v].body].generation;
    return SX_OK;
}

/* Sorts a few ints ascending (insertion sort: a sensor sees few colliders). */
static void sx_sort_ints(int *a, int n) {
    int i;
    for (i = 1; i < n; ++i) {
        int x = a[i], j = i - 1;
        while (j >= 0 && a[j] > x) {
            a[j + 1] = a[j];
            --j;
        }
        a[j + 1] = x;
    }
}

sx_status sx_sensors_update(sx_world *world) {
    uint64_t *swap;
    int i, j, k, v, cap;
    swap = world->old_sensor_pairs;
    world->old_sensor_pairs = world->sensor_pairs;
    world->sensor_pairs = swap;
    cap = world->old_sensor_capacity;
    world->old_sensor_capacity = world->sensor_capacity;
    world->sensor_capacity = cap;
    world->old_sensor_count = world->sensor_count;
    world->sensor_count = 0;

    /* sensors in slot order, visitors in slot order: the keys come out
     * sorted without a sort */
    for (k = 0; k < world->sensor_collider_count; ++k) {
        const sx_collider *s;
        sx_xform xs;
        sx_aabb box;
        sx_status st;
        i = world->sensor_colliders[k];
        s = &world->colliders[i];
        xs = world->sims[s->body].xf;
        box = sx_collider_aabb(s, xs);
        /* the broadphase's sets hold every colliding collider's (fattened)
         * bounds as of this collide */
        world->visitor_count = 0;
        st = sx_broadphase_query(&world->bp, world->aabbs, box, &world->visitors, &world->visitor_count,
                                 &world->visitor_capacity);
        if (st != SX_OK) return st;
        /* visitors in slot order: the keys come out sorted */
        sx_sort_ints(world->visitors, world->visitor_count);
        for (v = 0; v < world->visitor_count; ++v) {
            const sx_collider *c;
            sx_xform xc;
            j = world->visitors[v];
            c = &world->colliders[j];
            if (!sx_sensor_sees(world, s, c)) continue;
            xc = world->sims[c->body].xf;
            if (!sx_colliders_overlap(s, xs, c, xc)) continue;
            if (world->sensor_count == world->sensor_capacity) {
                void *p = world->sensor_pairs;
                st = sx_reserve_array(&p, &world->sensor_capacity, world->sensor_count + 1,
                                      sizeof(uint64_t));
                world->sensor_pairs = (uint64_t *)p;
                if (st != SX_OK) return st;
            }
            world->sensor_pairs[world->sensor_count++] =
                ((uint64_t)(uint32_t)i << 32) | (uint64_t)(uint32_t)j;
        }
    }

    i = 0;
    j = 0;
    while (i < world->sensor_count || j < world->old_sensor_count) {
        bool has_new = i < world->sensor_count, has_old = j < world->old_sensor_count;
        uint64_t kn = has_new ? world->sensor_pairs[i] : 0,
                 ko = has_old ? world->old_sensor_pairs[j] : 0;
        if (has_new && has_old && kn == ko) {
            ++i;
            ++j;
        } else if (!has_old || (has_new && kn < ko)) {
            sx_status st = sx_push_sensor_event(world, kn, true);
            if (st != SX_OK) return st;
            ++i;
        } else {
            sx_status st = sx_push_sensor_event(world, ko, false);
            if (st != SX_OK) return st;
            ++j;
        }
    }
    return SX_OK;
}

void sx_sensors_remove_collider(sx_world *world, int collider) {
    int i, n = 0;
    for (i = 0; i < world->sensor_count; ++i) {
        uint64_t key = world->sensor_pairs[i];
        if ((int)(key >> 32) == collider || (int)(key & 0xFFFFFFFFu) == collider) continue;
        world->sensor_pairs[n++] = key;
    }
    world->sensor_count = n;
}

sx_sensor_events sx_world_get_sensor_events(const sx_world *world) {
    sx_sensor_events e;
    memset(&e, 0, sizeof(e));
    if (world == NULL) return e;
    e.begin = world->sensor_begin;
    e.begin_count = world->sensor_begin_count;
    e.end = world->sensor_end;
    e.end_count = world->sensor_end_count;
    return e;
}
