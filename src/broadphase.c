/* sepax — the broadphase: which collider pairs are worth a narrowphase call.
 *
 * Two sets (world_internal.h has the layout). The colliders the step moves
 * are swept on x: kept in an array ordered by the lower x of their
 * (fattened) bounds, an order that survives from one call to the next, so
 * the insertion sort that restores it costs about one pass when bodies move
 * a little per step; the sweep visits, for each collider, only the colliders
 * whose lower x lies inside its x extent and tests their y extents. Each
 * moving collider then searches the set of fixed and sleeping colliders,
 * sorted by lower x, from the first box that could reach it (binary search,
 * bounded by the widest narrow box), plus the short list of wide boxes (over
 * 8 times the median width: grounds, walls). That set changes only when a
 * collider joins it, leaves it or is moved while in it: the entries of those
 * colliders are redone and merged in (linear in the set, once per change,
 * not per step), so a sleeping pile or a static level costs nothing per
 * step: a scene that is mostly asleep costs about what its awake bodies
 * cost, where one sweep over every collider paid for the sleepers each step.
 * Newcomers are sorted apart and merged, because an insertion sort of many
 * new colliders at once is quadratic. Enlarged bounds for moving colliders
 * (kept while the body stays inside them, as in a dynamic tree) gave no gain
 * and more narrowphase pairs, so the bounds are recomputed every collide and
 * the sweep stays exact (bench/README.md has the scenes that show it).
 * Pairs with no awake dynamic collider (static-static,
 * static-kinematic, kinematic-kinematic, anything with a sleeping body) are
 * not reported: nothing there can respond; the one exception is a moving
 * kinematic body meeting a sleeping one, which must wake it. Pairs come out sorted by key, so the
 * contact list and the solver's order are the same on every run (determinism). */
#include <stdlib.h>

#include "world_internal.h"

void sx_broadphase_init(sx_broadphase *bp) { memset(bp, 0, sizeof(*bp)); }

void sx_broadphase_free(sx_broadphase *bp) {
    sx_free(bp->order, (size_t)bp->order_capacity * sizeof(int));
    sx_free(bp->mark, (size_t)bp->mark_capacity);
    sx_free(bp->pairs, (size_t)bp->pair_capacity * sizeof(uint64_t));
    sx_free(bp->scratch, (size_t)bp->scratch_capacity * sizeof(uint64_t));
    sx_free(bp->sorted, (size_t)bp->sorted_capacity * sizeof(sx_sorted_box));
    sx_free(bp->fixed, (size_t)bp->fixed_capacity * sizeof(sx_sorted_box));
    sx_free(bp->fixed_next, (size_t)bp->fixed_next_capacity * sizeof(sx_sorted_box));
    sx_free(bp->added, (size_t)bp->added_capacity * sizeof(sx_sorted_box));
    sx_free(bp->wide, (size_t)bp->wide_capacity * sizeof(int));
    sx_free(bp->touched, (size_t)bp->touched_capacity * sizeof(int));
    sx_free(bp->tmark, (size_t)bp->tmark_capacity);
    memset(bp, 0, sizeof(*bp));
}

static bool sx_kinds_pair(unsigned char a, unsigned char b) {
    if (a == SX_BP_AWAKE || b == SX_BP_AWAKE) return true;
    return (a == SX_BP_MOVING_KINEMATIC && b == SX_BP_ASLEEP) ||
           (a == SX_BP_ASLEEP && b == SX_BP_MOVING_KINEMATIC);
}

/* Sorts the pair keys ascending: an LSD radix sort over the packed key
 * (lo << bits | hi, bits enough for any slot), a byte per pass. Linear in
 * the pairs, and it needs no comparison callback. */
static sx_status sx_sort_pairs(sx_broadphase *bp, int slot_count) {
    int bits = 1, passes, pass, i, n = bp->pair_count;
    uint64_t *src, *dst;
    void *p;
    bool ok;
    if (n < 2) return SX_OK;
    while (bits < 32 && ((int64_t)1 << bits) < (int64_t)slot_count)
        ++bits;
    p = bp->scratch;
    ok = sx_grow_array(&p, &bp->scratch_capacity, n, sizeof(uint64_t));
    bp->scratch = (uint64_t *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    for (i = 0; i < n; ++i) {
        uint64_t k = bp->pairs[i];
        bp->pairs[i] = ((k >> 32) << bits) | (k & 0xFFFFFFFFu);
    }
    src = bp->pairs;
    dst = bp->scratch;
    passes = (2 * bits + 7) / 8;
    for (pass = 0; pass < passes; ++pass) {
        int count[257];
        int shift = 8 * pass;
        uint64_t *t;
        memset(count, 0, sizeof(count));
        for (i = 0; i < n; ++i)
            count[((src[i] >> shift) & 0xFFu) + 1]++;
        for (i = 0; i < 256; ++i)
            count[i + 1] += count[i];
        for (i = 0; i < n; ++i)
            dst[count[(src[i] >> shift) & 0xFFu]++] = src[i];
        t = src;
        src = dst;
        dst = t;
    }
    for (i = 0; i < n; ++i) {
        uint64_t k = src[i];
        bp->pairs[i] = ((k >> bits) << 32) | (k & (((uint64_t)1 << bits) - 1u));
    }
    return SX_OK;
}

static sx_status sx_add_pair(sx_broadphase *bp, int a, int b) {
    void *p = bp->pairs;
    int lo = a < b ? a : b, hi = a < b ? b : a;
    if (bp->pair_count == bp->pair_capacity) {
        sx_status s =
            sx_reserve_array(&p, &bp->pair_capacity, bp->pair_count + 1, sizeof(uint64_t));
        bp->pairs = (uint64_t *)p;
        if (s != SX_OK) return s;
    }
    bp->pairs[bp->pair_count++] = ((uint64_t)(uint32_t)lo << 32) | (uint64_t)(uint32_t)hi;
    return SX_OK;
}

static bool sx_is_fixed_kind(unsigned char k) { return k == SX_BP_FIXED || k == SX_BP_ASLEEP; }

sx_status sx_broadphase_touch(sx_broadphase *bp, int slot, int slot_count) {
    void *p = bp->tmark;
    bool ok = sx_grow_zeroed(&p, &bp->tmark_capacity, slot_count, 1);
    bp->tmark = (unsigned char *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    if (bp->tmark[slot]) return SX_OK;
    if (!sx_push_int(&bp->touched, &bp->touched_count, &bp->touched_capacity, slot)) {
        return SX_ERR_NO_MEMORY;
    }
    bp->tmark[slot] = 1;
    return SX_OK;
}

/* Orders boxes by lower x, then slot: a total order, the same on every run. */
static bool sx_box_before(const sx_sorted_box *a, const sx_sorted_box *b) {
    return a->box.lower.x < b->box.lower.x ||
           (a->box.lower.x == b->box.lower.x && a->slot < b->slot);
}

static int sx_box_cmp(const void *pa, const void *pb) {
    const sx_sorted_box *a = (const sx_sorted_box *)pa, *b = (const sx_sorted_box *)pb;
    return sx_box_before(a, b) ? -1 : (sx_box_before(b, a) ? 1 : 0);
}

static int sx_real_cmp(const void *pa, const void *pb) {
    sx_real a = *(const sx_real *)pa, b = *(const sx_real *)pb;
    return a < b ? -1 : (a > b ? 1 : 0);
}

/* Redoes the fixed set's entries of the touched colliders: the kept entries
 * stay in order, the new ones are sorted among themselves and merged in
 * (linear in the set plus k log k for k changes), then the wide boxes are
 * listed again. */
static sx_status sx_update_fixed(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                                 int slot_count) {
    int i, j, n = 0, out;
    void *p;
    bool ok;
    sx_real sample[65];
    int samples = 0;
    if (bp->touched_count == 0) return SX_OK;
    bp->added_count = 0;
    for (i = 0; i < bp->touched_count; ++i) {
        int slot = bp->touched[i];
        if (slot >= slot_count || !sx_is_fixed_kind(kind[slot])) continue;
        p = bp->added;
        ok = sx_grow_array(&p, &bp->added_capacity, bp->added_count + 1, sizeof(sx_sorted_box));
        bp->added = (sx_sorted_box *)p;
        if (!ok) return SX_ERR_NO_MEMORY;
        bp->added[bp->added_count].box = aabbs[slot];
        bp->added[bp->added_count].slot = slot;
        bp->added[bp->added_count++].kind = kind[slot];
    }
    if (bp->added_count > 1)
        qsort(bp->added, (size_t)bp->added_count, sizeof(sx_sorted_box), sx_box_cmp);
    p = bp->fixed_next;
    ok = sx_grow_array(&p, &bp->fixed_next_capacity, bp->fixed_count + bp->added_count,
                       sizeof(sx_sorted_box));
    bp->fixed_next = (sx_sorted_box *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    /* merge the kept entries (not touched, still fixed) with the added */
    j = 0;
    out = 0;
    for (i = 0; i < bp->fixed_count; ++i) {
        const sx_sorted_box *e = &bp->fixed[i];
        if (e->slot >= slot_count || bp->tmark[e->slot] || !sx_is_fixed_kind(kind[e->slot]))
            continue;
        while (j < bp->added_count && sx_box_before(&bp->added[j], e))
            bp->fixed_next[out++] = bp->added[j++];
        bp->fixed_next[out++] = *e;
    }
    while (j < bp->added_count)
        bp->fixed_next[out++] = bp->added[j++];
    {
        sx_sorted_box *t = bp->fixed;
        int c = bp->fixed_capacity;
        bp->fixed = bp->fixed_next;
        bp->fixed_capacity = bp->fixed_next_capacity;
        bp->fixed_next = t;
        bp->fixed_next_capacity = c;
    }
    bp->fixed_count = out;
    for (i = 0; i < bp->touched_count; ++i)
        bp->tmark[bp->touched[i]] = 0;
    bp->touched_count = 0;

    /* wide boxes: over 8 times the median width of an even sample */
    n = bp->fixed_count;
    for (i = 0; i < 65 && i < n; ++i) {
        const sx_aabb *b = &bp->fixed[(int)((int64_t)i * n / (n < 65 ? n : 65))].box;
        sample[samples++] = b->upper.x - b->lower.x;
    }
    if (samples > 0) qsort(sample, (size_t)samples, sizeof(sx_real), sx_real_cmp);
    bp->wide_limit = samples > 0 ? SX_R(8.0) * sample[samples / 2] : SX_R(0.0);
    bp->wide_count = 0;
    for (i = 0; i < n; ++i) {
        const sx_aabb *b = &bp->fixed[i].box;
        if (!(b->upper.x - b->lower.x <= bp->wide_limit) &&
            !sx_push_int(&bp->wide, &bp->wide_count, &bp->wide_capacity, i)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    return SX_OK;
}

static bool sx_y_overlap(const sx_aabb *a, const sx_aabb *b) {
    return !(b->lower.y > a->upper.y || b->upper.y < a->lower.y);
}

/* Walks the fixed set's boxes that overlap `box`: the narrow ones from the
 * first whose lower x could reach it (binary search, bounded by the widest
 * narrow box), then the wide list. Start with *at = -1; NULL at the end. */
static const sx_sorted_box *sx_fixed_next(const sx_broadphase *bp, sx_aabb box, int *at) {
    int i = *at + 1;
    if (*at < 0) {
        const sx_real from = box.lower.x - bp->wide_limit;
        int hi = bp->fixed_count;
        i = 0;
        while (i < hi) {
            int mid = i + (hi - i) / 2;
            if (bp->fixed[mid].box.lower.x < from)
                i = mid + 1;
            else
                hi = mid;
        }
    }
    for (; i < bp->fixed_count; ++i) {
        const sx_sorted_box *b = &bp->fixed[i];
        if (b->box.lower.x > box.upper.x) {
            i = bp->fixed_count;
            break;
        }
        if (b->box.upper.x - b->box.lower.x > bp->wide_limit) continue; /* on the wide list */
        if (sx_aabb_overlaps(box, b->box)) {
            *at = i;
            return b;
        }
    }
    for (i -= bp->fixed_count; i < bp->wide_count; ++i) {
        const sx_sorted_box *b = &bp->fixed[bp->wide[i]];
        if (sx_aabb_overlaps(box, b->box)) {
            *at = bp->fixed_count + i;
            return b;
        }
    }
    *at = bp->fixed_count + bp->wide_count;
    return NULL;
}

/* Pairs one moving box with the fixed set. */
static sx_status sx_query_fixed(sx_broadphase *bp, const sx_sorted_box *a) {
    const sx_sorted_box *b;
    int at = -1;
    while ((b = sx_fixed_next(bp, a->box, &at)) != NULL) {
        if (!sx_kinds_pair(a->kind, b->kind)) continue;
        if (sx_add_pair(bp, a->slot, b->slot) != SX_OK) return SX_ERR_NO_MEMORY;
    }
    return SX_OK;
}

sx_status sx_broadphase_update(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                               int slot_count, const int *moving, int moving_count) {
    void *p;
    int i, n = 0;
    bool ok;
    sx_status s;
    bp->pair_count = 0;
    s = sx_update_fixed(bp, aabbs, kind, slot_count);
    if (s != SX_OK) return s;
    p = bp->mark;
    ok = sx_grow_zeroed(&p, &bp->mark_capacity, slot_count, 1);
    bp->mark = (unsigned char *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    p = bp->order;
    ok = sx_grow_array(&p, &bp->order_capacity, moving_count + 1, sizeof(int));
    bp->order = (int *)p;
    if (!ok) return SX_ERR_NO_MEMORY;

    /* keep last call's order for the colliders still moving */
    for (i = 0; i < moving_count; ++i)
        bp->mark[moving[i]] = 1;
    for (i = 0; i < bp->order_count; ++i) {
        int c = bp->order[i];
        if (c < slot_count && bp->mark[c] == 1) {
            bp->order[n++] = c;
            bp->mark[c] = 2;
        }
    }
    /* insertion sort of those by lower x (ties broken by slot so the order
     * is total): about one pass, as they moved a little since */
    for (i = 1; i < n; ++i) {
        int c = bp->order[i], j = i - 1;
        sx_real x = aabbs[c].lower.x;
        while (j >= 0) {
            int d = bp->order[j];
            sx_real y = aabbs[d].lower.x;
            if (y < x || (y == x && d < c)) break;
            bp->order[j + 1] = d;
            --j;
        }
        bp->order[j + 1] = c;
    }
    /* the newcomers (woken, created, started) sorted on their own and
     * merged in: a thousand bodies created in a grid would make the
     * insertion sort quadratic */
    bp->added_count = 0;
    for (i = 0; i < moving_count; ++i) {
        int c = moving[i];
        if (bp->mark[c] == 1) {
            p = bp->added;
            ok = sx_grow_array(&p, &bp->added_capacity, bp->added_count + 1, sizeof(sx_sorted_box));
            bp->added = (sx_sorted_box *)p;
            if (!ok) return SX_ERR_NO_MEMORY;
            bp->added[bp->added_count].box = aabbs[c];
            bp->added[bp->added_count].slot = c;
            bp->added[bp->added_count++].kind = kind[c];
        }
        bp->mark[c] = 0;
    }
    if (bp->added_count > 1)
        qsort(bp->added, (size_t)bp->added_count, sizeof(sx_sorted_box), sx_box_cmp);

    p = bp->sorted;
    ok = sx_grow_array(&p, &bp->sorted_capacity, n + bp->added_count, sizeof(sx_sorted_box));
    bp->sorted = (sx_sorted_box *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    {
        int j = 0, out = 0;
        for (i = 0; i < n; ++i) {
            sx_sorted_box e;
            e.box = aabbs[bp->order[i]];
            e.slot = bp->order[i];
            e.kind = kind[e.slot];
            while (j < bp->added_count && sx_box_before(&bp->added[j], &e))
                bp->sorted[out++] = bp->added[j++];
            bp->sorted[out++] = e;
        }
        while (j < bp->added_count)
            bp->sorted[out++] = bp->added[j++];
        n = out;
    }
    p = bp->order;
    ok = sx_grow_array(&p, &bp->order_capacity, n, sizeof(int));
    bp->order = (int *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    for (i = 0; i < n; ++i)
        bp->order[i] = bp->sorted[i].slot;
    bp->order_count = n;

    for (i = 0; i < n; ++i) {
        const sx_sorted_box *a = &bp->sorted[i];
        int j;
        for (j = i + 1; j < n; ++j) {
            const sx_sorted_box *b = &bp->sorted[j];
            if (b->box.lower.x > a->box.upper.x) break;
            if (!sx_kinds_pair(a->kind, b->kind)) continue;
            if (!sx_y_overlap(&a->box, &b->box)) continue;
            if (sx_add_pair(bp, a->slot, b->slot) != SX_OK) return SX_ERR_NO_MEMORY;
        }
        s = sx_query_fixed(bp, a);
        if (s != SX_OK) return s;
    }
    return sx_sort_pairs(bp, slot_count);
}

sx_status sx_broadphase_query(const sx_broadphase *bp, sx_aabb box, int **out, int *count,
                              int *capacity) {
    const sx_sorted_box *b;
    int at = -1, i;
    while ((b = sx_fixed_next(bp, box, &at)) != NULL) {
        if (!sx_push_int(out, count, capacity, b->slot)) return SX_ERR_NO_MEMORY;
    }
    /* the moving set is small: a plain pass, stopping past box on x */
    for (i = 0; i < bp->order_count; ++i) {
        b = &bp->sorted[i];
        if (b->box.lower.x > box.upper.x) break;
        if (sx_aabb_overlaps(box, b->box) && !sx_push_int(out, count, capacity, b->slot)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    return SX_OK;
}
