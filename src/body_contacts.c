/* sepax — the contacts of one body: finding them without a scan of every
 * contact, and removing them without compacting the lists each time.
 *
 * The contact lists are rebuilt by every collide (the step's, sorted by
 * collider pair) or only appended to and filtered there (the frozen store of
 * sleeping islands), so a per-body list kept up to date would cost the step
 * work for the rare destruction or teleport that needs it. Instead the
 * per-body chains are built on demand, in one pass over both lists, and stay
 * valid until a list moves (the next collide, or the purge below): a batch of
 * destructions or teleports between two steps pays one pass plus what each
 * touches. A removed contact stays in place with no points (a tombstone), so
 * the chains stay valid; the next collide drops the tombstones of both lists
 * (the frozen store in its thaw pass), and solve, separate and update_sleep
 * purge the step's list first if it holds any. Readers of the lists skip
 * them meanwhile. Removal keeps the order of what remains, as the eager
 * compaction it replaces did, so the solver sees the same contacts in the
 * same order. */
#include <string.h>

#include "world_array.h"
#include "world_contact.h"
#include "world_internal.h"
#include "world_island.h"

/* The contact at position p of the step's list followed by the frozen
 * store. */
static sx_contact *sx_contact_at(sx_world *world, int p) {
    return p < world->contact_count ? &world->contacts[p]
                                    : &world->frozen[p - world->contact_count];
}

/* Builds the per-body chains if the lists moved since the last build;
 * false when out of memory (the callers then scan). */
static bool sx_index_contacts(sx_world *world) {
    int total = world->contact_count + world->frozen_count, p, side;
    int *head, *next;
    uint32_t *stamp, epoch;
    void *q;
    bool ok;
    if (world->by_body_valid) return true;
    q = world->by_body_head;
    ok = sx_grow_array(&q, &world->by_body_head_capacity, world->body_slots, sizeof(int));
    world->by_body_head = (int *)q;
    if (!ok) return false;
    q = world->by_body_stamp;
    ok = sx_grow_zeroed(&q, &world->by_body_stamp_capacity, world->body_slots, sizeof(uint32_t));
    world->by_body_stamp = (uint32_t *)q;
    if (!ok) return false;
    q = world->by_body_next;
    ok = sx_grow_array(&q, &world->by_body_next_capacity, 2 * total, sizeof(int));
    world->by_body_next = (int *)q;
    if (!ok) return false;
    /* a stamp from an earlier build means an empty chain; on wrap-around
     * every stamp is reset so none can match by age */
    if (++world->by_body_epoch == 0) {
        memset(world->by_body_stamp, 0, (size_t)world->by_body_stamp_capacity * sizeof(uint32_t));
        world->by_body_epoch = 1;
    }
    head = world->by_body_head;
    next = world->by_body_next;
    stamp = world->by_body_stamp;
    epoch = world->by_body_epoch;
    for (p = total - 1; p >= 0; --p) {
        const sx_contact *c = sx_contact_at(world, p);
        if (c->count == 0) continue;
        for (side = 0; side < 2; ++side) {
            int b = side ? c->body_b : c->body_a;
            if (stamp[b] != epoch) {
                stamp[b] = epoch;
                head[b] = -1;
            }
            next[2 * p + side] = head[b];
            head[b] = 2 * p + side;
        }
    }
    world->by_body_valid = true;
    return true;
}

/* A walk over the live contacts of one body: the chain when it could be
 * built, else every position. */
typedef struct sx_contact_walk {
    int slot;
    int entry; /* chain: the next entry, -1 at the end */
    int p;     /* scan: the next position */
    bool scan;
} sx_contact_walk;

static sx_contact_walk sx_walk_contacts(sx_world *world, int slot) {
    sx_contact_walk w;
    w.slot = slot;
    w.p = 0;
    w.entry = -1;
    w.scan = !sx_index_contacts(world);
    if (!w.scan && slot < world->by_body_stamp_capacity &&
        world->by_body_stamp[slot] == world->by_body_epoch) {
        w.entry = world->by_body_head[slot];
    }
    return w;
}

/* The position of the walk's next live contact, or -1. Tombstoning the
 * contacts returned does not disturb the walk. */
static int sx_next_contact(sx_world *world, sx_contact_walk *w) {
    int total = world->contact_count + world->frozen_count;
    if (w->scan) {
        while (w->p < total) {
            const sx_contact *c = sx_contact_at(world, w->p++);
            if (c->count > 0 && (c->body_a == w->slot || c->body_b == w->slot)) return w->p - 1;
        }
        return -1;
    }
    while (w->entry >= 0) {
        int p = w->entry >> 1;
        w->entry = world->by_body_next[w->entry];
        /* a chain may outlive its body (destroyed, its slot reused), but
         * all its contacts are tombstones then */
        if (sx_contact_at(world, p)->count > 0) return p;
    }
    return -1;
}

void sx_world_remove_contacts_of(sx_world *world, int collider) {
    sx_contact_walk w = sx_walk_contacts(world, world->colliders[collider].body);
    int p;
    while ((p = sx_next_contact(world, &w)) >= 0) {
        sx_contact *c = sx_contact_at(world, p);
        if (c->collider_a != collider && c->collider_b != collider) continue;
        /* whatever rested on the collider must be able to fall */
        sx_wake_body(world, c->body_a);
        sx_wake_body(world, c->body_b);
        c->count = 0;
        sx_world_solver_changed(world);
        if (p < world->contact_count)
            world->contact_dead++;
        else
            world->frozen_dead++;
    }
}

void sx_wake_touching(sx_world *world, int slot) {
    sx_contact_walk w = sx_walk_contacts(world, slot);
    int p;
    sx_wake_body(world, slot);
    while ((p = sx_next_contact(world, &w)) >= 0) {
        const sx_contact *c = sx_contact_at(world, p);
        sx_wake_body(world, c->body_a == slot ? c->body_b : c->body_a);
    }
}

void sx_world_purge_contacts(sx_world *world) {
    int i, n = 0;
    if (world->contact_dead == 0) return;
    /* the lanes name contacts by index, which the purge moves */
    sx_solver_hand_back(world);
    for (i = 0; i < world->contact_count; ++i) {
        if (world->contacts[i].count == 0) continue;
        if (n != i) world->contacts[n] = world->contacts[i];
        ++n;
    }
    world->contact_count = n;
    world->contact_dead = 0;
    sx_world_solver_changed(world);
    world->by_body_valid = false;
}

const sx_contact *sx_world_live_contact(const sx_world *world, int index) {
    int total = world->contact_count + world->frozen_count, p;
    if (world->contact_dead + world->frozen_dead == 0) {
        return index < world->contact_count ? &world->contacts[index]
                                            : &world->frozen[index - world->contact_count];
    }
    /* only between a destruction and the next collide */
    for (p = 0; p < total; ++p) {
        const sx_contact *c = p < world->contact_count ? &world->contacts[p]
                                                       : &world->frozen[p - world->contact_count];
        if (c->count > 0 && index-- == 0) return c;
    }
    return NULL;
}
