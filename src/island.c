/* sepax — sleeping: islands of touching bodies that rest together sleep
 * together.
 *
 * After each step every awake dynamic body accumulates the time it has spent
 * slower than the sleep speeds. Contacts between two awake dynamic bodies
 * join them into islands (union-find over body slots, rebuilt each step: it
 * costs one pass over bodies and contacts and needs no bookkeeping when
 * contacts come and go). An island sleeps only when its most restless body
 * has rested long enough, so a stack never half-sleeps with its top still
 * sliding. A sleeping body remembers its island's root, which is how waking
 * one body wakes the island: a falling box that lands on a sleeping pile
 * wakes the whole pile, not just the box it hit. */
#include "world_array.h"
#include "world_body.h"
#include "world_contact.h"
#include "world_internal.h"
#include "world_island.h"

static int sx_find(int *parent, int i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]]; /* path halving */
        i = parent[i];
    }
    return i;
}

static void sx_union(int *parent, int a, int b) {
    int ra = sx_find(parent, a), rb = sx_find(parent, b);
    /* the lower slot becomes the root: the same islands on every run */
    if (ra < rb)
        parent[rb] = ra;
    else if (rb < ra)
        parent[ra] = rb;
}

static void sx_wake_one(sx_world *world, int slot) {
    void *p = world->thaw_mark;
    world->sims[slot].awake = true;
    sx_world_solver_changed(world);
    /* its contacts may wait in the frozen store: the next thaw looks at the
     * contacts of the bodies listed here */
    world->thaw_pending = true;
    if (sx_grow_zeroed(&p, &world->thaw_mark_capacity, world->body_slots, 1)) {
        world->thaw_mark = (unsigned char *)p;
        if (!world->thaw_mark[slot]) {
            if (sx_push_int(&world->thaw_bodies, &world->thaw_body_count,
                            &world->thaw_body_capacity, slot)) {
                world->thaw_mark[slot] = 1;
            } else {
                world->thaw_all = true;
            }
        }
    } else {
        world->thaw_all = true;
    }
    sx_world_note_awake(world, slot);
    world->infos[slot].sleep_time = SX_R(0.0);
    world->infos[slot].island = -1;
    world->infos[slot].island_next = -1;
}

void sx_wake_body(sx_world *world, int slot) {
    int island = world->infos[slot].island, i, next;
    if (world->sims[slot].awake) return;
    if (island < 0) {
        sx_wake_one(world, slot);
        return;
    }
    /* Every member of a sleeping island sleeps and lives until the island
     * wakes whole (destroying, retyping or moving a member wakes it first),
     * so the chain from the root is the island. */
    for (i = island; i >= 0; i = next) {
        SX_ASSERT(world->infos[i].alive && !world->sims[i].awake &&
                  world->infos[i].island == island);
        next = world->infos[i].island_next;
        sx_wake_one(world, i);
    }
}

int sx_world_awake_body_count(const sx_world *world) {
    int i, n = 0;
    if (world == NULL) return 0;
    for (i = 0; i < world->body_slots; ++i) {
        if (world->infos[i].alive && world->sims[i].dynamic && world->sims[i].awake) ++n;
    }
    return n;
}

/* Grows the union-find scratch to one entry per body slot. */
static bool sx_island_scratch(sx_world *world) {
    void *p = world->island_parent;
    bool ok = sx_grow_array(&p, &world->parent_capacity, world->body_slots, sizeof(int));
    world->island_parent = (int *)p;
    if (!ok) return false;
    p = world->island_time;
    ok = sx_grow_array(&p, &world->time_capacity, world->body_slots, sizeof(sx_real));
    world->island_time = (sx_real *)p;
    return ok;
}

/* A kinematic body that moves: what it carries or pushes is not at rest. */
static bool sx_kinematic_moves(const sx_body_sim *b) {
    return b->moving && !b->dynamic &&
           (b->v.x != SX_R(0.0) || b->v.y != SX_R(0.0) || b->w != SX_R(0.0));
}

/* Each active body becomes an island of its own; each awake dynamic one
 * adds dt to its rest time if it is slower than the sleep speeds, and
 * starts again from zero otherwise. */
static void sx_rest_times(sx_world *world, sx_real dt) {
    int *parent = world->island_parent;
    sx_real *rest = world->island_time;
    sx_real lin = world->def.sleep_linear_speed, ang = world->def.sleep_angular_speed;
    int ak;
    /* only awake bodies take part: a sleeping one costs nothing */
    for (ak = 0; ak < world->active_body_count; ++ak) {
        int i = world->active_bodies[ak];
        sx_body_sim *b = &world->sims[i];
        sx_body_info *info = &world->infos[i];
        parent[i] = i;
        rest[i] = SX_REAL_MAX;
        if (!b->dynamic || !b->awake) continue;
        if (!info->enable_sleep || sx_length_sq(b->v) > lin * lin || sx_absr(b->w) > ang) {
            info->sleep_time = SX_R(0.0);
        } else {
            info->sleep_time += dt;
        }
    }
}

/* Joins the islands of the awake dynamic bodies each contact touches, and
 * takes the rest time of the bodies that a contact shows not at rest. */
static void sx_join_islands(sx_world *world) {
    int i;
    for (i = 0; i < world->contact_count; ++i) {
        const sx_contact *c = &world->contacts[i];
        const sx_body_sim *a = &world->sims[c->body_a], *b = &world->sims[c->body_b];
        bool da = a->dynamic && a->awake, db = b->dynamic && b->awake;
        int k;
        /* Positional correction moves bodies without giving them speed: a
         * body still being pushed out of an overlap deeper than twice the
         * slop (resting contacts stay within about one) is not at rest. */
        for (k = 0; k < c->count; ++k) {
            if (c->points[k].separation < -SX_R(2.0) * world->linear_slop) {
                if (da) world->infos[c->body_a].sleep_time = SX_R(0.0);
                if (db) world->infos[c->body_b].sleep_time = SX_R(0.0);
            }
        }
        if (da && db) {
            sx_union(world->island_parent, c->body_a, c->body_b);
        } else if (da && sx_kinematic_moves(b)) {
            /* carried or pushed by a moving kinematic body: not at rest */
            world->infos[c->body_a].sleep_time = SX_R(0.0);
        } else if (db && sx_kinematic_moves(a)) {
            world->infos[c->body_b].sleep_time = SX_R(0.0);
        }
    }
}

/* Puts to sleep the islands whose least rested body has rested
 * time_to_sleep, each member remembering its island's root. */
static void sx_sleep_islands(sx_world *world) {
    int *parent = world->island_parent;
    sx_real *rest = world->island_time;
    int ak;
    /* the island's rest time is its least rested body's */
    for (ak = 0; ak < world->active_body_count; ++ak) {
        int r, i = world->active_bodies[ak];
        if (!world->sims[i].dynamic || !world->sims[i].awake) continue;
        r = sx_find(parent, i);
        rest[r] = sx_minr(rest[r], world->infos[i].sleep_time);
    }
    for (ak = 0; ak < world->active_body_count; ++ak) {
        int r, i = world->active_bodies[ak];
        sx_body_sim *b = &world->sims[i];
        if (!b->dynamic || !b->awake) continue;
        r = sx_find(parent, i);
        if (rest[r] < world->def.time_to_sleep) continue;
        b->awake = false;
        sx_world_solver_changed(world);
        b->v = sx_v2_zero();
        b->w = SX_R(0.0);
        world->infos[i].island = r;
        world->infos[i].island_next = -1;
        sx_world_note_awake(world, i);
    }
    /* Chain each new sleeping island's members behind its root (the root is
     * a member: the union-find ran over these very bodies). The active
     * bodies were all awake, so those asleep now fell asleep just above. */
    for (ak = 0; ak < world->active_body_count; ++ak) {
        int i = world->active_bodies[ak];
        int r = world->infos[i].island;
        if (world->sims[i].awake || r == i) continue;
        world->infos[i].island_next = world->infos[r].island_next;
        world->infos[r].island_next = i;
    }
}

sx_status sx_world_update_sleep(sx_world *world, sx_real dt) {
    sx_status s;
    if (world == NULL) return SX_ERR_INVALID_ARG;
    if (sx_world_locked(world)) return SX_ERR_LOCKED;
    if (!sx_is_finite(dt)) return SX_ERR_NONFINITE;
    if (!(dt > SX_R(0.0))) return SX_ERR_INVALID_ARG;
    if (!world->def.enable_sleep) return SX_OK;
    if (!sx_island_scratch(world)) return SX_ERR_NO_MEMORY;
    s = sx_world_refresh_sets(world);
    if (s != SX_OK) return s;
    sx_world_purge_contacts(world);
    sx_rest_times(world, dt);
    sx_join_islands(world);
    sx_sleep_islands(world);
    return SX_OK;
}
