/* sepax — the broadphase: which colliders' bounds overlap, found from a
 * sorted array of the colliders that do not move and a dynamic AABB tree of
 * those that do (broadphase.c). */
#ifndef SEPAX_WORLD_BROADPHASE_H
#define SEPAX_WORLD_BROADPHASE_H

#include "aabb_tree.h"
#include "core.h"

/* What the broadphase needs to know of a collider. Pairs are reported when
 * one side is AWAKE, or a MOVING_KINEMATIC body meets an ASLEEP one (so it
 * can wake it); FIXED and ASLEEP never pair among themselves. */
enum {
    SX_BP_OUT = 0,          /* not colliding: dead, disabled or a sensor */
    SX_BP_FIXED,            /* static, or kinematic at rest */
    SX_BP_AWAKE,            /* dynamic and awake */
    SX_BP_MOVING_KINEMATIC, /* kinematic with a non-zero velocity */
    SX_BP_ASLEEP            /* dynamic and asleep */
};

/* The broadphase (broadphase.c) keeps two sets. The others (FIXED, ASLEEP)
 * sit in an array sorted by lower x that changes only when a collider joins
 * or leaves that set or moves while in it (the few boxes much wider than
 * the rest on a short list of their own). The colliders the step moves
 * (AWAKE, MOVING_KINEMATIC) have fat boxes (bounds grown by a margin) and
 * sit in a dynamic AABB tree with their candidate pairs kept from call to
 * call while few leave their fat box, or are swept on x when many do. */
typedef struct sx_sorted_box {
    sx_aabb box;
    int slot;
    unsigned char kind;
} sx_sorted_box;

typedef struct sx_broadphase {
    /* the moving colliders' fat boxes: in the tree while few of them move
     * out of their fat box per call (tree_valid), otherwise swept on x in
     * an order kept from call to call (order, sorted; mark: scratch per
     * slot) */
    sx_aabb_tree tree;
    bool tree_valid;
    int calm_calls; /* sweeping calls in a row with few colliders out of their fat box */
    /* the last sweep: its boxes and how many times one met another on x */
    int64_t sweep_visits;
    int sweep_boxes;
    int *order;
    int order_count, order_capacity;
    sx_sorted_box *sorted;
    int sorted_capacity;
    sx_real sorted_width; /* the widest box in sorted */
    /* the sweep's horizontal bands: band b's boxes (indices into sorted, in
     * x order) are band_items[band_start[b] .. band_start[b + 1]); the
     * second half of band_start is the scratch that fills them */
    int *band_start, *band_items;
    int band_start_capacity, band_items_capacity;
    unsigned char *mark;
    int mark_capacity;
    int *proxy;           /* per collider slot: its tree leaf, -1 when none */
    sx_aabb *fat;         /* per collider slot: the box its candidates were found for */
    unsigned char *qmark; /* per collider slot: 1 while in requery */
    int proxy_capacity, fat_capacity, qmark_capacity;
    int *requery; /* slots that look for new candidates in this call */
    int requery_count, requery_capacity;
    int *hits; /* query scratch */
    int hit_count, hit_capacity;
    /* the candidate pairs, sorted by key, and the scratch of their merge */
    uint64_t *cand, *cand_next;
    int cand_count, cand_capacity, cand_next_capacity;
    uint64_t *fresh; /* new candidates of this call */
    int fresh_count, fresh_capacity;
    uint64_t *pairs; /* the call's answer: candidates whose bounds overlap */
    int pair_count, pair_capacity;
    uint64_t *scratch; /* radix-sort buffer, as large as fresh */
    int scratch_capacity;
    sx_sorted_box *fixed, *fixed_next; /* the other set, sorted by lower x */
    int fixed_count, fixed_capacity, fixed_next_capacity;
    sx_sorted_box *added; /* scratch: boxes joining the fixed set */
    int added_count, added_capacity;
    int *wide; /* indices into fixed of the boxes wider than wide_limit */
    int wide_count, wide_capacity;
    sx_real wide_limit;
    /* collider slots whose fixed-set entry may be out of date: they changed
     * kind or bounds since the last call (mark[] keeps them unique) */
    int *touched;
    int touched_count, touched_capacity;
    unsigned char *tmark; /* one per collider slot: 1 while in touched */
    int tmark_capacity;
} sx_broadphase;

/* broadphase.c */
void sx_broadphase_init(sx_broadphase *bp);
void sx_broadphase_free(sx_broadphase *bp);
/* Notes that a collider changed kind or bounds while not moving (its
 * fixed-set entry must be redone). */
sx_status sx_broadphase_touch(sx_broadphase *bp, int slot, int slot_count);
/* Finds the pairs of colliders whose bounds overlap and whose kinds (SX_BP_*)
 * call for a pair; `moving` lists the AWAKE and MOVING_KINEMATIC colliders
 * in slot order; `fat_margin` (>= 0) is how far a moving collider's tree box
 * reaches past its bounds. Fills bp->pairs sorted ascending by key (lower
 * slot in the high half). */
sx_status sx_broadphase_update(sx_broadphase *bp, const sx_aabb *aabbs, const unsigned char *kind,
                               int slot_count, const int *moving, int moving_count,
                               sx_real fat_margin);

/* Appends to *out the slots of the colliders in the broadphase (not OUT)
 * whose bounds (aabbs, as of the last update) overlap box, in no particular
 * order. */
sx_status sx_broadphase_query(sx_broadphase *bp, const sx_aabb *aabbs, sx_aabb box, int **out,
                              int *count, int *capacity);
/* The same for the fixed set only (static colliders, kinematic ones at rest
 * and sleeping ones): logarithmic, where the moving set is not. */
sx_status sx_broadphase_query_fixed(const sx_broadphase *bp, sx_aabb box, int **out, int *count,
                                    int *capacity);

#endif /* SEPAX_WORLD_BROADPHASE_H */
