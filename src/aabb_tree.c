/* sepax — the dynamic AABB tree (aabb_tree.h). Nodes live in one array
 * with a free list, so a warmed-up tree allocates nothing; a leaf keeps its
 * node index for as long as it lives (the broadphase stores it per
 * collider). Rebalancing is the AVL single rotation: when one child of a
 * node is more than one level taller than the other, the taller child takes
 * the node's place and hands its shorter child down. */
#include "aabb_tree.h"

#include <string.h>

#include "world_array.h"

void sx_tree_init(sx_aabb_tree *t) {
    memset(t, 0, sizeof(*t));
    t->root = -1;
    t->free_list = -1;
}

void sx_tree_free(sx_aabb_tree *t) {
    sx_free(t->nodes, (size_t)t->node_capacity * sizeof(sx_tree_node));
    sx_free(t->stack, (size_t)t->stack_capacity * sizeof(int));
    sx_tree_init(t);
}

/* A free node, or -1 when the array could not grow. */
static int sx_tree_alloc(sx_aabb_tree *t) {
    int n;
    if (t->free_list >= 0) {
        n = t->free_list;
        t->free_list = t->nodes[n].parent;
    } else {
        void *p = t->nodes;
        if (!sx_grow_array(&p, &t->node_capacity, t->node_count + 1, sizeof(sx_tree_node))) {
            return -1;
        }
        t->nodes = (sx_tree_node *)p;
        n = t->node_count++;
    }
    t->nodes[n].parent = -1;
    t->nodes[n].child1 = -1;
    t->nodes[n].child2 = -1;
    t->nodes[n].height = 0;
    t->nodes[n].item = -1;
    return n;
}

static void sx_tree_release(sx_aabb_tree *t, int n) {
    t->nodes[n].parent = t->free_list;
    t->nodes[n].height = -1;
    t->free_list = n;
}

static int sx_maxi(int a, int b) { return a > b ? a : b; }

/* Puts `to` where `from` hung under `parent` (or at the root). */
static void sx_tree_relink(sx_aabb_tree *t, int parent, int from, int to) {
    if (parent < 0) {
        t->root = to;
    } else if (t->nodes[parent].child1 == from) {
        t->nodes[parent].child1 = to;
    } else {
        t->nodes[parent].child2 = to;
    }
}

/* Rotates the taller child of a up if the heights differ by more than one;
 * the index of the node now in a's place. */
static int sx_tree_balance(sx_aabb_tree *t, int a) {
    sx_tree_node *n = t->nodes;
    int b, c, up, other, keep, tall, shorter, diff;
    if (n[a].height < 2) return a;
    b = n[a].child1;
    c = n[a].child2;
    diff = n[c].height - n[b].height;
    if (diff >= -1 && diff <= 1) return a;
    /* up: the taller child; other: a's child that stays */
    up = diff > 1 ? c : b;
    other = diff > 1 ? b : c;
    tall = n[up].child1;
    shorter = n[up].child2;
    if (n[tall].height < n[shorter].height) {
        int x = tall;
        tall = shorter;
        shorter = x;
    }
    /* up takes a's place, keeps its taller child and adopts a; a adopts
     * up's shorter child in up's old position */
    n[up].parent = n[a].parent;
    sx_tree_relink(t, n[a].parent, a, up);
    n[up].child1 = a;
    n[up].child2 = tall;
    n[a].parent = up;
    keep = other;
    if (diff > 1) {
        n[a].child1 = keep;
        n[a].child2 = shorter;
    } else {
        n[a].child1 = shorter;
        n[a].child2 = keep;
    }
    n[shorter].parent = a;
    n[a].box = sx_aabb_union(n[keep].box, n[shorter].box);
    n[a].height = 1 + sx_maxi(n[keep].height, n[shorter].height);
    n[up].box = sx_aabb_union(n[a].box, n[tall].box);
    n[up].height = 1 + sx_maxi(n[a].height, n[tall].height);
    return up;
}

/* Refits the boxes and heights from node i up to the root, rebalancing. */
static void sx_tree_refit(sx_aabb_tree *t, int i) {
    while (i >= 0) {
        sx_tree_node *n;
        int c1, c2;
        i = sx_tree_balance(t, i);
        n = t->nodes;
        c1 = n[i].child1;
        c2 = n[i].child2;
        n[i].height = 1 + sx_maxi(n[c1].height, n[c2].height);
        n[i].box = sx_aabb_union(n[c1].box, n[c2].box);
        i = n[i].parent;
    }
}

int sx_tree_insert(sx_aabb_tree *t, sx_aabb box, int item) {
    int leaf = sx_tree_alloc(t), parent, sibling, old_parent;
    sx_tree_node *n;
    if (leaf < 0) return -1;
    /* the parent the leaf needs; allocated first so a failure leaves the
     * tree as it was */
    parent = t->root >= 0 ? sx_tree_alloc(t) : -1;
    if (t->root >= 0 && parent < 0) {
        sx_tree_release(t, leaf);
        return -1;
    }
    n = t->nodes;
    n[leaf].box = box;
    n[leaf].item = item;
    ++t->leaf_count;
    if (t->root < 0) {
        t->root = leaf;
        return leaf;
    }
    /* Descend to the sibling that adds the least perimeter: at each node,
     * pairing with the node itself costs the perimeter of the union, while
     * going down costs what the node grows by plus what the child grows. */
    sibling = t->root;
    while (n[sibling].height > 0) {
        int c1 = n[sibling].child1, c2 = n[sibling].child2;
        sx_real here = SX_R(2.0) * sx_aabb_perimeter(sx_aabb_union(n[sibling].box, box));
        sx_real grow = here - SX_R(2.0) * sx_aabb_perimeter(n[sibling].box);
        sx_real u1 = sx_aabb_perimeter(sx_aabb_union(n[c1].box, box));
        sx_real u2 = sx_aabb_perimeter(sx_aabb_union(n[c2].box, box));
        sx_real cost1 = grow + (n[c1].height > 0 ? u1 - sx_aabb_perimeter(n[c1].box) : u1);
        sx_real cost2 = grow + (n[c2].height > 0 ? u2 - sx_aabb_perimeter(n[c2].box) : u2);
        if (here < cost1 && here < cost2) break;
        sibling = cost1 <= cost2 ? c1 : c2;
    }
    old_parent = n[sibling].parent;
    n[parent].parent = old_parent;
    n[parent].box = sx_aabb_union(box, n[sibling].box);
    n[parent].height = n[sibling].height + 1;
    n[parent].child1 = sibling;
    n[parent].child2 = leaf;
    sx_tree_relink(t, old_parent, sibling, parent);
    n[sibling].parent = parent;
    n[leaf].parent = parent;
    sx_tree_refit(t, old_parent);
    return leaf;
}

void sx_tree_remove(sx_aabb_tree *t, int leaf) {
    sx_tree_node *n = t->nodes;
    int parent = n[leaf].parent, grand, sibling;
    --t->leaf_count;
    sx_tree_release(t, leaf);
    if (parent < 0) {
        t->root = -1;
        return;
    }
    grand = n[parent].parent;
    sibling = n[parent].child1 == leaf ? n[parent].child2 : n[parent].child1;
    sx_tree_relink(t, grand, parent, sibling);
    n[sibling].parent = grand;
    sx_tree_release(t, parent);
    sx_tree_refit(t, grand);
}

sx_status sx_tree_query(sx_aabb_tree *t, sx_aabb box, int **out, int *count, int *capacity) {
    int top = 0;
    if (t->root < 0) return SX_OK;
    /* a depth-first walk needs at most height + 1 entries */
    if (t->stack_capacity < t->nodes[t->root].height + 2) {
        void *p = t->stack;
        if (!sx_grow_array(&p, &t->stack_capacity, t->nodes[t->root].height + 2, sizeof(int))) {
            return SX_ERR_NO_MEMORY;
        }
        t->stack = (int *)p;
    }
    t->stack[top++] = t->root;
    while (top > 0) {
        const sx_tree_node *n = &t->nodes[t->stack[--top]];
        if (!sx_aabb_overlaps(n->box, box)) continue;
        if (n->height == 0) {
            if (!sx_push_int(out, count, capacity, n->item)) return SX_ERR_NO_MEMORY;
        } else {
            t->stack[top++] = n->child2;
            t->stack[top++] = n->child1;
        }
    }
    return SX_OK;
}

/* The centre of a leaf's box on an axis (0: x, 1: y), doubled (no halving
 * needed to compare). */
static sx_real sx_leaf_key(const sx_tree_node *n, int leaf, int axis) {
    const sx_aabb *b = &n[leaf].box;
    return axis == 0 ? b->lower.x + b->upper.x : b->lower.y + b->upper.y;
}

/* Reorders leaves[lo, hi) so that the leaf at mid has its place by key and
 * none before it is greater, none after it smaller (quickselect with the
 * middle element as pivot: the leaves come in an order with no adversary). */
static void sx_select(const sx_tree_node *n, int *leaves, int lo, int hi, int mid, int axis) {
    while (hi - lo > 1) {
        sx_real pivot = sx_leaf_key(n, leaves[lo + (hi - lo) / 2], axis);
        int i = lo, j = hi - 1;
        while (i <= j) {
            while (sx_leaf_key(n, leaves[i], axis) < pivot)
                ++i;
            while (sx_leaf_key(n, leaves[j], axis) > pivot)
                --j;
            if (i <= j) {
                int x = leaves[i];
                leaves[i++] = leaves[j];
                leaves[j--] = x;
            }
        }
        if (mid <= j) {
            hi = j + 1;
        } else if (mid >= i) {
            lo = i;
        } else {
            return;
        }
    }
}

/* Builds the subtree of leaves[lo, hi) (hi > lo) under parent: split at the
 * median centre along the longer side of the centres' bounds. */
static int sx_build_node(sx_aabb_tree *t, int *leaves, int lo, int hi, int parent) {
    sx_tree_node *n = t->nodes;
    int node, mid, axis, i;
    sx_aabb c;
    if (hi - lo == 1) {
        n[leaves[lo]].parent = parent;
        return leaves[lo];
    }
    c.lower = c.upper = sx_aabb_center(n[leaves[lo]].box);
    for (i = lo + 1; i < hi; ++i) {
        sx_vec2 p = sx_aabb_center(n[leaves[i]].box);
        c.lower = sx_vmin(c.lower, p);
        c.upper = sx_vmax(c.upper, p);
    }
    axis = c.upper.x - c.lower.x >= c.upper.y - c.lower.y ? 0 : 1;
    mid = lo + (hi - lo) / 2;
    sx_select(n, leaves, lo, hi, mid, axis);
    node = sx_tree_alloc(t); /* room reserved by sx_tree_build: never fails */
    n = t->nodes;
    n[node].parent = parent;
    n[node].child1 = sx_build_node(t, leaves, lo, mid, node);
    n[node].child2 = sx_build_node(t, leaves, mid, hi, node);
    n = t->nodes;
    n[node].box = sx_aabb_union(n[n[node].child1].box, n[n[node].child2].box);
    n[node].height = 1 + sx_maxi(n[n[node].child1].height, n[n[node].child2].height);
    return node;
}

sx_status sx_tree_build(sx_aabb_tree *t, const int *items, const sx_aabb *boxes, int count,
                        int *leaf_of) {
    int i, *leaves;
    void *p = t->nodes;
    if (!sx_grow_array(&p, &t->node_capacity, 2 * count, sizeof(sx_tree_node))) {
        return SX_ERR_NO_MEMORY;
    }
    t->nodes = (sx_tree_node *)p;
    p = t->stack;
    /* the leaf list, in the query stack's room (a query needs less) */
    if (!sx_grow_array(&p, &t->stack_capacity, count + 1, sizeof(int))) return SX_ERR_NO_MEMORY;
    t->stack = (int *)p;
    leaves = t->stack;
    t->node_count = 0;
    t->free_list = -1;
    t->root = -1;
    t->leaf_count = count;
    for (i = 0; i < count; ++i) {
        int leaf = sx_tree_alloc(t);
        t->nodes[leaf].box = boxes[items[i]];
        t->nodes[leaf].item = items[i];
        leaf_of[items[i]] = leaf;
        leaves[i] = leaf;
    }
    if (count > 0) t->root = sx_build_node(t, leaves, 0, count, -1);
    return SX_OK;
}
