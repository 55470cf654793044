/* sepax — the broadphase: which collider pairs are worth a narrowphase call.
 *
 * Two sets (world_broadphase.h has the layout). The fixed and sleeping
 * colliders sit in an array sorted by lower x, searched from the first box
 * that could reach a query (binary search, bounded by the widest narrow
 * box), plus the short list of wide boxes (over 8 times the median width:
 * grounds, walls); that set changes only when a collider joins it, leaves
 * it or is moved while in it, so a sleeping pile or a static level costs
 * nothing per step.
 *
 * The moving colliders have fat boxes: their bounds grown by a margin,
 * kept while the bounds stay inside. While few leave their fat box per
 * call (a resting pile, a few bodies moving through a level), they live in
 * a dynamic AABB tree (aabb_tree.c) and the pairs whose fat boxes overlap
 * (the candidates) persist from call to call in a list sorted by key: only
 * the colliders re-inserted or changed (kind, bounds) query the tree and
 * the fixed set for new candidates, which are sorted and merged in while
 * the candidates whose fat boxes parted drop out, and the answer is the
 * candidates whose exact bounds overlap. When many leave their fat box (a
 * rain: a query each would cost more), the call sweeps the moving bounds on
 * x instead, in an order kept from call to call so its insertion sort costs
 * about one pass, band by horizontal band (a sweep of the whole world met
 * every box of a column: a rain, a tall pile), and queries the fixed set
 * with each; the tree and the candidates are rebuilt when the world calms
 * down (with hysteresis: the rebuild costs a query per collider). Either way
 * the answer is the pairs whose bounds overlap, the same as testing every
 * collider against every other, in key order, so contacts, solver order and
 * the determinism hashes depend on neither the margin, nor the tree's shape,
 * nor the mode.
 * A sweep costs every moving collider every call; the tree, only those
 * that left their fat box.
 *
 * Pairs with no awake dynamic collider (static-static, static-kinematic,
 * kinematic-kinematic, anything with a sleeping body) are not reported:
 * nothing there can respond; the one exception is a moving kinematic body
 * meeting a sleeping one, which must wake it. */
#include <stdlib.h>

#include <string.h>

#include "world_array.h"
#include "world_broadphase.h"

void sx_broadphase_init(sx_broadphase *bp) {
    memset(bp, 0, sizeof(*bp));
    sx_tree_init(&bp->tree);
}

void sx_broadphase_free(sx_broadphase *bp) {
    sx_tree_free(&bp->tree);
    sx_free(bp->order, (size_t)bp->order_capacity * sizeof(int));
    sx_free(bp->sorted, (size_t)bp->sorted_capacity * sizeof(sx_sorted_box));
    sx_free(bp->band_start, (size_t)bp->band_start_capacity * sizeof(int));
    sx_free(bp->band_items, (size_t)bp->band_items_capacity * sizeof(int));
    sx_free(bp->mark, (size_t)bp->mark_capacity);
    sx_free(bp->proxy, (size_t)bp->proxy_capacity * sizeof(int));
    sx_free(bp->fat, (size_t)bp->fat_capacity * sizeof(sx_aabb));
    sx_free(bp->qmark, (size_t)bp->qmark_capacity);
    sx_free(bp->requery, (size_t)bp->requery_capacity * sizeof(int));
    sx_free(bp->hits, (size_t)bp->hit_capacity * sizeof(int));
    sx_free(bp->cand, (size_t)bp->cand_capacity * sizeof(uint64_t));
    sx_free(bp->cand_next, (size_t)bp->cand_next_capacity * sizeof(uint64_t));
    sx_free(bp->fresh, (size_t)bp->fresh_capacity * sizeof(uint64_t));
    sx_free(bp->pairs, (size_t)bp->pair_capacity * sizeof(uint64_t));
    sx_free(bp->scratch, (size_t)bp->scratch_capacity * sizeof(uint64_t));
    sx_free(bp->fixed, (size_t)bp->fixed_capacity * sizeof(sx_sorted_box));
    sx_free(bp->fixed_next, (size_t)bp->fixed_next_capacity * sizeof(sx_sorted_box));
    sx_free(bp->added, (size_t)bp->added_capacity * sizeof(sx_sorted_box));
    sx_free(bp->wide, (size_t)bp->wide_capacity * sizeof(int));
    sx_free(bp->touched, (size_t)bp->touched_capacity * sizeof(int));
    sx_free(bp->tmark, (size_t)bp->tmark_capacity);
    sx_broadphase_init(bp);
}

static bool sx_kinds_pair(unsigned char a, unsigned char b) {
    if (a == SX_BP_AWAKE || b == SX_BP_AWAKE) return true;
    return (a == SX_BP_MOVING_KINEMATIC && b == SX_BP_ASLEEP) ||
           (a == SX_BP_ASLEEP && b == SX_BP_MOVING_KINEMATIC);
}

/* Sorts the new candidates' keys ascending: an LSD radix sort over the
 * packed key (lo << bits | hi, bits enough for any slot), a byte per pass.
 * Linear in the pairs, and it needs no comparison callback. */
static sx_status sx_sort_fresh(sx_broadphase *bp, int slot_count) {
    int bits = 1, passes, pass, i, n = bp->fresh_count;
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
        uint64_t k = bp->fresh[i];
        bp->fresh[i] = ((k >> 32) << bits) | (k & 0xFFFFFFFFu);
    }
    src = bp->fresh;
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
        bp->fresh[i] = ((k >> bits) << 32) | (k & (((uint64_t)1 << bits) - 1u));
    }
    return SX_OK;
}

static sx_status sx_add_fresh(sx_broadphase *bp, int a, int b) {
    void *p = bp->fresh;
    int lo = a < b ? a : b, hi = a < b ? b : a;
    if (bp->fresh_count == bp->fresh_capacity) {
        sx_status s =
            sx_reserve_array(&p, &bp->fresh_capacity, bp->fresh_count + 1, sizeof(uint64_t));
        bp->fresh = (uint64_t *)p;
        if (s != SX_OK) return s;
    }
    bp->fresh[bp->fresh_count++] = ((uint64_t)(uint32_t)lo << 32) | (uint64_t)(uint32_t)hi;
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

/* Appends a box to bp->added; false when the array could not grow. */
static bool sx_push_added(sx_broadphase *bp, sx_aabb box, int slot, unsigned char kind) {
    sx_sorted_box *e;
    void *p = bp->added;
    bool ok = sx_grow_array(&p, &bp->added_capacity, bp->added_count + 1, sizeof(sx_sorted_box));
    bp->added = (sx_sorted_box *)p;
    if (!ok) return false;
    e = &bp->added[bp->added_count++];
    e->box = box;
    e->slot = slot;
    e->kind = kind;
    return true;
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
        if (!sx_push_added(bp, aabbs[slot], slot, kind[slot])) return SX_ERR_NO_MEMORY;
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

/* Swaps two key buffers with their capacities: the double-buffered lists
 * trade places instead of copying. */
static void sx_swap_keys(uint64_t **a, int *a_capacity, uint64_t **b, int *b_capacity) {
    uint64_t *t = *a;
    int c = *a_capacity;
    *a = *b;
    *a_capacity = *b_capacity;
    *b = t;
    *b_capacity = c;
}

/* The index of the first of boxes[0..count) (sorted by lower x) whose lower
 * x is not below from: binary search. */
static int sx_first_from(const sx_sorted_box *boxes, int count, sx_real from) {
    int i = 0, hi = count;
    while (i < hi) {
        int mid = i + (hi - i) / 2;
        if (boxes[mid].box.lower.x < from)
            i = mid + 1;
        else
            hi = mid;
    }
    return i;
}

/* Walks the fixed set's boxes that overlap `box`: the narrow ones from the
 * first whose lower x could reach it (binary search, bounded by the widest
 * narrow box), then the wide list. Start with *at = -1; NULL at the end. */
static const sx_sorted_box *sx_fixed_next(const sx_broadphase *bp, sx_aabb box, int *at) {
    int i = *at + 1;
    if (*at < 0) i = sx_first_from(bp->fixed, bp->fixed_count, box.lower.x - bp->wide_limit);
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

/* Above one in this many moving colliders out of their fat box in one
 * call, the call sweeps instead of using the tree. */
#define SX_SWEEP_SHARE 4
/* What the tree costs per collider out of its fat box (out, in, a query of
 * both sets, the merge), in the sweep's visits of one box by another: a
 * tree call re-inserting 10,000 falling boxes took about 300 times a visit,
 * more in a dense pile (its queries meet more neighbours). A sweep costs
 * its visits plus SX_SWEEP_BASE a box (the x order, the bands, the fixed
 * set's query: 22,000 resting boxes swept in a third of the time a return
 * to the tree took), so a sweeping world returns after the calm calls
 * whose sweeps would cost as much as the return: one or two. It leaves
 * the tree at the same share whatever its sweep costs (a wider share,
 * tried, made a pile in motion query the tree at 2 us a box where a sweep
 * took 0.3). */
#define SX_QUERY_VISITS 300
#define SX_SWEEP_BASE 150

/* Grows the per-slot arrays to slot_count: new proxies -1, new marks 0. */
static sx_status sx_grow_slots(sx_broadphase *bp, int slot_count) {
    int old = bp->proxy_capacity, i;
    void *p = bp->proxy;
    bool ok = sx_grow_array(&p, &bp->proxy_capacity, slot_count, sizeof(int));
    bp->proxy = (int *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    for (i = old; i < bp->proxy_capacity; ++i)
        bp->proxy[i] = -1;
    p = bp->fat;
    ok = sx_grow_array(&p, &bp->fat_capacity, slot_count, sizeof(sx_aabb));
    bp->fat = (sx_aabb *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    p = bp->qmark;
    ok = sx_grow_zeroed(&p, &bp->qmark_capacity, slot_count, 1);
    bp->qmark = (unsigned char *)p;
    return ok ? SX_OK : SX_ERR_NO_MEMORY;
}

/* Queues a slot to look for new candidates (once per call). */
static sx_status sx_requery(sx_broadphase *bp, int slot) {
    if (bp->qmark[slot]) return SX_OK;
    if (!sx_push_int(&bp->requery, &bp->requery_count, &bp->requery_capacity, slot)) {
        return SX_ERR_NO_MEMORY;
    }
    bp->qmark[slot] = 1;
    return SX_OK;
}

/* The tree box of a moving collider: its bounds grown by the margin. A
 * collider whose bounds are not finite gets the whole plane, so it meets
 * every collider, as sx_aabb_overlaps says its bounds do. */
static sx_aabb sx_fat_box(sx_aabb b, sx_real margin) {
    if (!(sx_vec2_is_finite(b.lower) && sx_vec2_is_finite(b.upper))) {
        return sx_aabb_make(sx_v2(-SX_REAL_MAX, -SX_REAL_MAX), sx_v2(SX_REAL_MAX, SX_REAL_MAX));
    }
    return sx_aabb_fatten(b, margin);
}

/* Appends to bp->hits the moving colliders of the sweep order whose
 * bounds overlap box: from the first whose lower x could reach it (binary
 * search, bounded by the widest box) to the first past it. */
static sx_status sx_sorted_hits(sx_broadphase *bp, sx_aabb box) {
    int i = sx_first_from(bp->sorted, bp->order_count, box.lower.x - bp->sorted_width);
    for (; i < bp->order_count; ++i) {
        const sx_sorted_box *b = &bp->sorted[i];
        if (b->box.lower.x > box.upper.x) break;
        if (sx_aabb_overlaps(box, b->box) &&
            !sx_push_int(&bp->hits, &bp->hit_count, &bp->hit_capacity, b->slot)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    return SX_OK;
}

/* The new candidates of a queued slot a: hits (in bp->hits) of kinds that
 * pair, and for a moving collider its fixed-set candidates too (fixed and
 * sleeping colliders never pair among themselves). */
static sx_status sx_fresh_of(sx_broadphase *bp, const unsigned char *kind, int a) {
    int k;
    sx_status s;
    for (k = 0; k < bp->hit_count; ++k) {
        int b = bp->hits[k];
        if (b == a || !sx_kinds_pair(kind[a], kind[b])) continue;
        s = sx_add_fresh(bp, a, b);
        if (s != SX_OK) return s;
    }
    if (!sx_is_fixed_kind(kind[a])) {
        const sx_sorted_box *f;
        int at = -1;
        while ((f = sx_fixed_next(bp, bp->fat[a], &at)) != NULL) {
            if (!sx_kinds_pair(kind[a], f->kind)) continue;
            s = sx_add_fresh(bp, a, f->slot);
            if (s != SX_OK) return s;
        }
    }
    return SX_OK;
}

/* Few moving colliders left their fat box: they are re-inserted in the
 * tree (built whole if the last call swept), and the queued slots query
 * it. */
static sx_status sx_tree_moving(sx_broadphase *bp, const unsigned char *kind, const int *moving,
                                int moving_count) {
    int i;
    sx_status s;
    /* the sweep order goes stale while the tree serves: the next sweep
     * sorts afresh rather than insertion-sort an order long out of date */
    bp->order_count = 0;
    if (!bp->tree_valid) {
        /* after a sweep: the tree and the candidates are found afresh */
        s = sx_tree_build(&bp->tree, moving, bp->fat, moving_count, bp->proxy);
        if (s != SX_OK) return s;
        bp->tree_valid = true;
        bp->cand_count = 0;
        for (i = 0; i < moving_count; ++i) {
            s = sx_requery(bp, moving[i]);
            if (s != SX_OK) return s;
        }
    } else {
        for (i = 0; i < moving_count; ++i) {
            int m = moving[i];
            if (!bp->qmark[m]) continue;
            if (bp->proxy[m] >= 0) sx_tree_remove(&bp->tree, bp->proxy[m]);
            bp->proxy[m] = sx_tree_insert(&bp->tree, bp->fat[m], m);
            if (bp->proxy[m] < 0) return SX_ERR_NO_MEMORY;
        }
    }
    bp->fresh_count = 0;
    for (i = 0; i < bp->requery_count; ++i) {
        int a = bp->requery[i];
        bp->qmark[a] = 0;
        bp->hit_count = 0;
        s = sx_tree_query(&bp->tree, bp->fat[a], &bp->hits, &bp->hit_count, &bp->hit_capacity);
        if (s == SX_OK) s = sx_fresh_of(bp, kind, a);
        if (s != SX_OK) return s;
    }
    bp->requery_count = 0;
    return SX_OK;
}

/* Puts the moving colliders' fat boxes in sweep order (by lower x, ties by
 * slot): last call's order for those still moving, restored by an
 * insertion sort (about one pass: few boxes changed), and the newcomers
 * sorted on their own and merged in (a thousand bodies created in a grid
 * would make the insertion sort quadratic). */
static sx_status sx_order_moving(sx_broadphase *bp, const sx_aabb *boxes,
                                 const unsigned char *kind, int slot_count, const int *moving,
                                 int moving_count) {
    void *p = bp->mark;
    int i, j, n = 0, out = 0;
    bool ok = sx_grow_zeroed(&p, &bp->mark_capacity, slot_count, 1);
    bp->mark = (unsigned char *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    p = bp->order;
    ok = sx_grow_array(&p, &bp->order_capacity, moving_count + 1, sizeof(int));
    bp->order = (int *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    for (i = 0; i < moving_count; ++i)
        bp->mark[moving[i]] = 1;
    for (i = 0; i < bp->order_count; ++i) {
        int c = bp->order[i];
        if (c < slot_count && bp->mark[c] == 1) {
            bp->order[n++] = c;
            bp->mark[c] = 2;
        }
    }
    for (i = 1; i < n; ++i) {
        int c = bp->order[i];
        sx_real x = boxes[c].lower.x;
        j = i - 1;
        while (j >= 0) {
            int d = bp->order[j];
            sx_real y = boxes[d].lower.x;
            if (y < x || (y == x && d < c)) break;
            bp->order[j + 1] = d;
            --j;
        }
        bp->order[j + 1] = c;
    }
    bp->added_count = 0;
    for (i = 0; i < moving_count; ++i) {
        int c = moving[i];
        if (bp->mark[c] == 1 && !sx_push_added(bp, boxes[c], c, kind[c])) return SX_ERR_NO_MEMORY;
        bp->mark[c] = 0;
    }
    if (bp->added_count > 1)
        qsort(bp->added, (size_t)bp->added_count, sizeof(sx_sorted_box), sx_box_cmp);
    p = bp->sorted;
    ok = sx_grow_array(&p, &bp->sorted_capacity, n + bp->added_count, sizeof(sx_sorted_box));
    bp->sorted = (sx_sorted_box *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    bp->sorted_width = SX_R(0.0);
    for (i = 0, j = 0; i <= n; ++i) {
        sx_sorted_box e;
        if (i < n) {
            e.box = boxes[bp->order[i]];
            e.slot = bp->order[i];
            e.kind = kind[e.slot];
        }
        while (j < bp->added_count && (i == n || sx_box_before(&bp->added[j], &e)))
            bp->sorted[out++] = bp->added[j++];
        if (i < n) bp->sorted[out++] = e;
    }
    p = bp->order;
    ok = sx_grow_array(&p, &bp->order_capacity, out, sizeof(int));
    bp->order = (int *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    for (i = 0; i < out; ++i) {
        const sx_aabb *b = &bp->sorted[i].box;
        bp->order[i] = bp->sorted[i].slot;
        bp->sorted_width = sx_maxr(bp->sorted_width, b->upper.x - b->lower.x);
    }
    bp->order_count = out;
    return SX_OK;
}

/* Most bands of a sweep (a box in many bands is listed in each). */
#define SX_MAX_BANDS 65536

/* The band of height y: bands of equal height from `bottom`, the last one
 * open upwards (monotonic in y, which the pairs' dedup relies on). */
static int sx_band_of(sx_real y, sx_real bottom, sx_real per_height, int bands) {
    sx_real b = (y - bottom) * per_height;
    if (!(b > SX_R(0.0))) return 0;
    return b < (sx_real)(bands - 1) ? (int)b : bands - 1;
}

/* Splits the sweep's n boxes into horizontal bands twice their mean height,
 * each band's boxes in x order (a box in every band it reaches): a box then
 * visits the boxes of its x range in its own bands only, where a sweep of
 * the whole world on x visited every box of a column (a rain, a tall pile,
 * a grid of pyramids). Returns the band count, 0 when the scratch could
 * not grow; *bottom_out and *per_height_out place the bands. */
static int sx_sweep_bands(sx_broadphase *bp, int n, sx_real *bottom_out, sx_real *per_height_out) {
    sx_real bottom = SX_R(0.0), top = SX_R(0.0), heights = SX_R(0.0), per_height = SX_R(0.0);
    int bands = 1, i, b, total = 0;
    int *start, *next;
    void *p;
    for (i = 0; i < n; ++i) {
        const sx_aabb *x = &bp->sorted[i].box;
        if (i == 0 || x->lower.y < bottom) bottom = x->lower.y;
        if (i == 0 || x->upper.y > top) top = x->upper.y;
        heights += x->upper.y - x->lower.y;
    }
    if (n > 1 && heights > SX_R(0.0) && sx_is_finite(top - bottom) && sx_is_finite(heights)) {
        sx_real k = (top - bottom) / (SX_R(2.0) * heights / (sx_real)n);
        sx_real most = (sx_real)(n < SX_MAX_BANDS ? n : SX_MAX_BANDS);
        if (k >= SX_R(2.0)) {
            bands = k < most ? (int)k : (int)most;
            per_height = (sx_real)bands / (top - bottom);
        }
    }
    p = bp->band_start;
    if (!sx_grow_array(&p, &bp->band_start_capacity, 2 * (bands + 1), sizeof(int))) return 0;
    bp->band_start = (int *)p;
    start = bp->band_start;
    next = start + bands + 1;
    memset(start, 0, (size_t)(bands + 1) * sizeof(int));
    for (i = 0; i < n; ++i) {
        const sx_aabb *x = &bp->sorted[i].box;
        int lo = sx_band_of(x->lower.y, bottom, per_height, bands);
        int hi = sx_band_of(x->upper.y, bottom, per_height, bands);
        for (b = lo; b <= hi; ++b)
            ++start[b + 1];
    }
    for (b = 0; b < bands; ++b) {
        start[b + 1] += start[b];
        next[b] = start[b];
    }
    total = start[bands];
    p = bp->band_items;
    if (!sx_grow_array(&p, &bp->band_items_capacity, total, sizeof(int))) return 0;
    bp->band_items = (int *)p;
    for (i = 0; i < n; ++i) {
        const sx_aabb *x = &bp->sorted[i].box;
        int lo = sx_band_of(x->lower.y, bottom, per_height, bands);
        int hi = sx_band_of(x->upper.y, bottom, per_height, bands);
        for (b = lo; b <= hi; ++b)
            bp->band_items[next[b]++] = i;
    }
    *bottom_out = bottom;
    *per_height_out = per_height;
    return bands;
}

/* Many moving colliders left their fat box (a rain, a scene's first step):
 * re-inserting and querying them all would cost more than a sweep, which
 * finds every pair of moving bounds that overlap, cache-friendly, in one
 * pass over the x order of each horizontal band, and then each moving
 * collider's fixed-set pairs. A pair is reported by the band of the higher
 * of its two lower edges, the one band both boxes are sure to share, so
 * once. That is the answer itself (no candidates kept: the call that next
 * uses the tree builds it and finds the candidates afresh). */
static sx_status sx_sweep_moving(sx_broadphase *bp, const sx_aabb *aabbs,
                                 const unsigned char *kind, int slot_count, const int *moving,
                                 int moving_count) {
    int i, j, n, band, bands;
    int64_t visits = 0;
    sx_real bottom = SX_R(0.0), per_height = SX_R(0.0);
    sx_status s = sx_order_moving(bp, aabbs, kind, slot_count, moving, moving_count);
    if (s != SX_OK) return s;
    bp->tree_valid = false;
    bp->cand_count = 0;
    for (i = 0; i < bp->requery_count; ++i)
        bp->qmark[bp->requery[i]] = 0;
    bp->requery_count = 0;
    for (i = 0; i < moving_count; ++i)
        bp->proxy[moving[i]] = 0; /* has a fat box; no leaf */
    bp->fresh_count = 0;
    n = bp->order_count;
    bands = sx_sweep_bands(bp, n, &bottom, &per_height);
    if (bands == 0) return SX_ERR_NO_MEMORY;
    for (band = 0; band < bands; ++band) {
        const int *items = bp->band_items + bp->band_start[band];
        int m = bp->band_start[band + 1] - bp->band_start[band];
        for (i = 0; i < m; ++i) {
            const sx_sorted_box *a = &bp->sorted[items[i]];
            for (j = i + 1; j < m; ++j) {
                const sx_sorted_box *b = &bp->sorted[items[j]];
                if (b->box.lower.x > a->box.upper.x) break;
                ++visits;
                if (!sx_kinds_pair(a->kind, b->kind)) continue;
                if (b->box.lower.y > a->box.upper.y || b->box.upper.y < a->box.lower.y) continue;
                if (bands > 1 &&
                    sx_band_of(sx_maxr(a->box.lower.y, b->box.lower.y), bottom, per_height,
                               bands) != band) {
                    continue;
                }
                s = sx_add_fresh(bp, a->slot, b->slot);
                if (s != SX_OK) return s;
            }
        }
    }
    for (i = 0; i < n; ++i) {
        const sx_sorted_box *a = &bp->sorted[i];
        const sx_sorted_box *f;
        int at = -1;
        while ((f = sx_fixed_next(bp, a->box, &at)) != NULL) {
            if (!sx_kinds_pair(a->kind, f->kind)) continue;
            s = sx_add_fresh(bp, a->slot, f->slot);
            if (s != SX_OK) return s;
        }
    }
    bp->sweep_visits = visits;
    bp->sweep_boxes = n;
    s = sx_sort_fresh(bp, slot_count);
    if (s != SX_OK) return s;
    /* the sorted pairs are the answer */
    sx_swap_keys(&bp->pairs, &bp->pair_capacity, &bp->fresh, &bp->fresh_capacity);
    bp->pair_count = bp->fresh_count;
    bp->fresh_count = 0;
    return SX_OK;
}

sx_status sx_broadphase_query_fixed(const sx_broadphase *bp, sx_aabb box, int **out, int *count,
                                    int *capacity) {
    const sx_sorted_box *b;
    int at = -1;
    while ((b = sx_fixed_next(bp, box, &at)) != NULL) {
        if (!sx_push_int(out, count, capacity, b->slot)) return SX_ERR_NO_MEMORY;
    }
    return SX_OK;
}

/* Merges the sorted new candidates into the kept ones (those still in
 * range, of kinds that pair, with fat boxes that overlap) and writes the
 * answer: the candidates whose exact bounds overlap, in key order. */
static sx_status sx_merge_candidates(sx_broadphase *bp, const sx_aabb *aabbs,
                                     const unsigned char *kind, int slot_count) {
    int i = 0, j = 0, out = 0, need = bp->cand_count + bp->fresh_count;
    void *p = bp->cand_next;
    bool ok = sx_grow_array(&p, &bp->cand_next_capacity, need, sizeof(uint64_t));
    bp->cand_next = (uint64_t *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    p = bp->pairs;
    ok = sx_grow_array(&p, &bp->pair_capacity, need, sizeof(uint64_t));
    bp->pairs = (uint64_t *)p;
    if (!ok) return SX_ERR_NO_MEMORY;
    bp->pair_count = 0;
    while (i < bp->cand_count || j < bp->fresh_count) {
        uint64_t key;
        int a, b;
        if (j >= bp->fresh_count || (i < bp->cand_count && bp->cand[i] < bp->fresh[j])) {
            key = bp->cand[i++];
            a = (int)(key >> 32);
            b = (int)(key & 0xFFFFFFFFu);
            if (b >= slot_count || kind[a] == SX_BP_OUT || kind[b] == SX_BP_OUT ||
                !sx_kinds_pair(kind[a], kind[b]) ||
                !sx_aabb_overlaps(bp->fat[a], bp->fat[b])) {
                continue;
            }
        } else {
            /* found by a query: valid as it is; once, whatever repeats it */
            key = bp->fresh[j];
            while (j < bp->fresh_count && bp->fresh[j] == key)
                ++j;
            if (i < bp->cand_count && bp->cand[i] == key) ++i;
            a = (int)(key >> 32);
            b = (int)(key & 0xFFFFFFFFu);
        }
        bp->cand_next[out++] = key;
        if (sx_aabb_overlaps(aabbs[a], aabbs[b])) bp->pairs[bp->pair_count++] = key;
    }
    sx_swap_keys(&bp->cand, &bp->cand_capacity, &bp->cand_next, &bp->cand_next_capacity);
    bp->cand_count = out;
    return SX_OK;
}

sx_status sx_broadphase_update(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                               int slot_count, const int *moving, int moving_count,
                               sx_real fat_margin) {
    int i, escaped;
    sx_status s;
    bp->pair_count = 0;
    s = sx_grow_slots(bp, slot_count);
    if (s != SX_OK) return s;
    /* many colliders changed at once (a pile fell asleep): the tree is
     * dropped and built again when needed rather than taken apart leaf by
     * leaf */
    if (bp->tree_valid && bp->touched_count > bp->tree.leaf_count / SX_SWEEP_SHARE) {
        bp->tree_valid = false;
    }
    /* colliders that changed kind or bounds leave the tree (a moving one
     * comes back below) and look for candidates again */
    for (i = 0; i < bp->touched_count; ++i) {
        int slot = bp->touched[i];
        if (slot >= slot_count) continue;
        if (bp->proxy[slot] >= 0 && bp->tree_valid) sx_tree_remove(&bp->tree, bp->proxy[slot]);
        bp->proxy[slot] = -1;
        if (kind[slot] == SX_BP_OUT) continue;
        if (sx_is_fixed_kind(kind[slot])) bp->fat[slot] = aabbs[slot];
        s = sx_requery(bp, slot);
        if (s != SX_OK) return s;
    }
    s = sx_update_fixed(bp, aabbs, kind, slot_count);
    if (s != SX_OK) return s;
    /* moving colliders whose bounds left their fat box get a new one */
    escaped = 0;
    for (i = 0; i < moving_count; ++i) {
        int m = moving[i];
        if (bp->proxy[m] >= 0 && sx_aabb_contains(bp->fat[m], aabbs[m])) continue;
        bp->fat[m] = sx_fat_box(aabbs[m], fat_margin);
        s = sx_requery(bp, m);
        if (s != SX_OK) return s;
        ++escaped;
    }
    /* Hysteresis: going back to the tree costs a build and a query per
     * moving collider, so a sweeping world returns only after `calm` calls
     * in a row calmer than the share that makes a tree world sweep (bodies
     * falling from rest in step leave their fat boxes every other call at
     * first): as many as pay for the return. */
    {
        int64_t cost = bp->sweep_visits + (int64_t)SX_SWEEP_BASE * bp->sweep_boxes;
        int64_t calm = cost > 0 ? (int64_t)SX_QUERY_VISITS * bp->sweep_boxes / cost : 1;
        if (calm < 1) calm = 1;
        if (bp->tree_valid) {
            bp->calm_calls = escaped > moving_count / SX_SWEEP_SHARE ? 0 : (int)calm;
        } else if (escaped > moving_count / (4 * SX_SWEEP_SHARE)) {
            bp->calm_calls = 0;
        } else {
            ++bp->calm_calls;
        }
        if (bp->calm_calls < calm) {
            return sx_sweep_moving(bp, aabbs, kind, slot_count, moving, moving_count);
        }
    }
    s = sx_tree_moving(bp, kind, moving, moving_count);
    if (s != SX_OK) return s;
    s = sx_sort_fresh(bp, slot_count);
    if (s != SX_OK) return s;
    return sx_merge_candidates(bp, aabbs, kind, slot_count);
}

sx_status sx_broadphase_query(sx_broadphase *bp, const sx_aabb *aabbs, sx_aabb box, int **out,
                              int *count, int *capacity) {
    const sx_sorted_box *b;
    int at = -1, i;
    sx_status s;
    while ((b = sx_fixed_next(bp, box, &at)) != NULL) {
        if (!sx_push_int(out, count, capacity, b->slot)) return SX_ERR_NO_MEMORY;
    }
    /* the moving colliders by their fat boxes, kept where the bounds
     * overlap */
    bp->hit_count = 0;
    if (bp->tree_valid) {
        s = sx_tree_query(&bp->tree, box, &bp->hits, &bp->hit_count, &bp->hit_capacity);
    } else {
        s = sx_sorted_hits(bp, box);
    }
    if (s != SX_OK) return s;
    for (i = 0; i < bp->hit_count; ++i) {
        int slot = bp->hits[i];
        if (sx_aabb_overlaps(aabbs[slot], box) && !sx_push_int(out, count, capacity, slot)) {
            return SX_ERR_NO_MEMORY;
        }
    }
    return SX_OK;
}
