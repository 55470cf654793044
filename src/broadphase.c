/* sepax — the broadphase: which collider pairs are worth a narrowphase call.
 *
 * Sort and sweep on x. The colliders are kept in an array ordered by the
 * lower x of their (fattened) bounds; the order survives from one call to the
 * next, so the insertion sort that restores it costs about one pass when
 * bodies move a little per step. The sweep then visits, for each collider,
 * only the colliders whose lower x lies inside its x extent, and tests their
 * y extents. Pairs with no awake dynamic collider (static-static,
 * static-kinematic, kinematic-kinematic, anything with a sleeping body) are
 * not reported: nothing there can respond; the one exception is a moving
 * kinematic body meeting a sleeping one, which must wake it. Pairs come out sorted by key, so the
 * contact list and the solver's order are the same on every run (determinism). */
#include "world_internal.h"

void sx_broadphase_init(sx_broadphase *bp) { memset(bp, 0, sizeof(*bp)); }

void sx_broadphase_free(sx_broadphase *bp) {
    sx_free(bp->order, (size_t)bp->order_capacity * sizeof(int));
    sx_free(bp->mark, (size_t)bp->mark_capacity);
    sx_free(bp->pairs, (size_t)bp->pair_capacity * sizeof(uint64_t));
    sx_free(bp->scratch, (size_t)bp->scratch_capacity * sizeof(uint64_t));
    sx_free(bp->sorted, (size_t)bp->sorted_capacity * sizeof(sx_sorted_box));
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
        bool ok = sx_grow_array(&p, &bp->pair_capacity, bp->pair_count + 1, sizeof(uint64_t));
        bp->pairs = (uint64_t *)p;
        if (!ok) return SX_ERR_NO_MEMORY;
    }
    bp->pairs[bp->pair_count++] = ((uint64_t)(uint32_t)lo << 32) | (uint64_t)(uint32_t)hi;
    return SX_OK;
}

sx_status sx_broadphase_update(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                               int slot_count) {
    void *p;
    int i, n = 0;
    bool ok;
    bp->pair_count = 0;
    p = bp->mark;
    ok = sx_grow_array(&p, &bp->mark_capacity, slot_count, 1);
    bp->mark = (unsigned char *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    p = bp->order;
    ok = sx_grow_array(&p, &bp->order_capacity, slot_count, sizeof(int));
    bp->order = (int *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    if (slot_count > 0) memset(bp->mark, 0, (size_t)slot_count);

    /* keep last call's order for the colliders still in, then append the
     * newcomers in slot order */
    for (i = 0; i < bp->order_count; ++i) {
        int c = bp->order[i];
        if (c < slot_count && kind[c] != SX_BP_OUT) {
            bp->order[n++] = c;
            bp->mark[c] = 1;
        }
    }
    for (i = 0; i < slot_count; ++i) {
        if (kind[i] != SX_BP_OUT && bp->mark[i] == 0) bp->order[n++] = i;
    }
    bp->order_count = n;

    /* insertion sort by lower x; ties broken by slot so the order is total */
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

    /* the sweep reads the bounds in sorted order: copy them next to each
     * other once instead of chasing the slot index for every candidate */
    p = bp->sorted;
    ok = sx_grow_array(&p, &bp->sorted_capacity, n, sizeof(sx_sorted_box));
    bp->sorted = (sx_sorted_box *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    for (i = 0; i < n; ++i) {
        int c = bp->order[i];
        bp->sorted[i].box = aabbs[c];
        bp->sorted[i].slot = c;
        bp->sorted[i].kind = kind[c];
    }
    for (i = 0; i < n; ++i) {
        const sx_sorted_box *a = &bp->sorted[i];
        int j;
        for (j = i + 1; j < n; ++j) {
            const sx_sorted_box *b = &bp->sorted[j];
            if (b->box.lower.x > a->box.upper.x) break;
            if (!sx_kinds_pair(a->kind, b->kind)) continue;
            if (b->box.lower.y > a->box.upper.y || b->box.upper.y < a->box.lower.y) continue;
            if (sx_add_pair(bp, a->slot, b->slot) != SX_OK) return SX_ERR_NO_MEMORY;
        }
    }
    return sx_sort_pairs(bp, slot_count);
}
