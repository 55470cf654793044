/* sepax — a dynamic AABB tree (private): a binary tree of boxes whose
 * leaves carry an int (the broadphase's collider slot). Inserting picks the
 * sibling by the surface-area heuristic (perimeter in 2D) and rebalances on
 * the way up by single rotations that keep the heights within one, so a
 * query visits O(log n + hits) nodes whatever order the leaves came in.
 * Erin Catto's "Dynamic Bounding Volume Hierarchies" (GDC 2019) explains
 * the design; this is our own code. */
#ifndef SEPAX_AABB_TREE_H
#define SEPAX_AABB_TREE_H

#include "core.h"

typedef struct sx_tree_node {
    sx_aabb box;
    int parent; /* -1 at the root; the free-list link while free */
    int child1, child2; /* -1 at a leaf */
    int height;         /* 0 at a leaf, -1 while free */
    int item;           /* a leaf's value, -1 inside */
} sx_tree_node;

typedef struct sx_aabb_tree {
    sx_tree_node *nodes;
    int node_capacity, node_count; /* node_count: high-water mark of used slots */
    int root, free_list;
    int leaf_count;
    int *stack; /* query scratch */
    int stack_capacity;
} sx_aabb_tree;

void sx_tree_init(sx_aabb_tree *t);
void sx_tree_free(sx_aabb_tree *t);
/* Adds a leaf with box and item; its node index, or -1 when out of memory
 * (the tree is then unchanged). */
int sx_tree_insert(sx_aabb_tree *t, sx_aabb box, int item);
/* Removes the leaf `leaf` (an index sx_tree_insert returned). */
void sx_tree_remove(sx_aabb_tree *t, int leaf);
/* Replaces the tree with one holding a leaf per item, items[0..count),
 * with box boxes[item], built top down (split at the median centre along
 * the longer side): better queries than inserting one by one, at the cost
 * of every leaf. leaf_of[item] receives each item's leaf. SX_ERR_NO_MEMORY
 * when the nodes could not grow (the tree is then unchanged). */
sx_status sx_tree_build(sx_aabb_tree *t, const int *items, const sx_aabb *boxes, int count,
                        int *leaf_of);
/* Appends to *out the items of the leaves whose boxes overlap box (touching
 * counts, sx_aabb_overlaps), in tree order. SX_ERR_NO_MEMORY when an array
 * could not grow. */
sx_status sx_tree_query(sx_aabb_tree *t, sx_aabb box, int **out, int *count, int *capacity);

#endif /* SEPAX_AABB_TREE_H */
