/* sepax tests — the dynamic AABB tree against brute force.
 *
 * A white-box test of src/aabb_tree.c: random boxes are inserted, removed,
 * moved (removed and inserted again) and the whole set rebuilt top down;
 * after every change the tree's structure holds (parents and children
 * agree, heights are exact, every node's box holds its children's, the
 * tree built top down is balanced within one level, the one grown leaf by
 * leaf stays shallow: its single rotations do not promise AVL balance)
 * and every query
 * returns exactly the boxes that overlap it. Fixed seeds. */
#include <stdlib.h>
#include <string.h>

#include "../../src/aabb_tree.h"
#include "test_support.h"

#define ITEMS 300

/* Checks the subtree at n; its height. Counts its leaves into *leaves. */
static int check_node(const sx_aabb_tree *t, int n, int parent, bool balanced, int *leaves) {
    const sx_tree_node *x = &t->nodes[n];
    int h1, h2;
    assert_int_equal(x->parent, parent);
    if (x->height == 0) {
        assert_int_equal(x->child1, -1);
        ++*leaves;
        return 0;
    }
    h1 = check_node(t, x->child1, n, balanced, leaves);
    h2 = check_node(t, x->child2, n, balanced, leaves);
    assert_int_equal(x->height, 1 + (h1 > h2 ? h1 : h2));
    if (balanced) assert_true(h1 - h2 <= 1 && h2 - h1 <= 1);
    assert_true(sx_aabb_contains(x->box, t->nodes[x->child1].box));
    assert_true(sx_aabb_contains(x->box, t->nodes[x->child2].box));
    return x->height;
}

static int int_cmp(const void *a, const void *b) {
    int x = *(const int *)a, y = *(const int *)b;
    return x < y ? -1 : (x > y ? 1 : 0);
}

/* The tree's structure, and queries against brute force over the live
 * items. */
static void check_tree(sx_aabb_tree *t, const sx_aabb *boxes, const bool *live, bool balanced,
                       sx_test_rng *rng) {
    int leaves = 0, q, i, live_count = 0;
    int *out = NULL, count = 0, capacity = 0;
    for (i = 0; i < ITEMS; ++i)
        live_count += live[i] ? 1 : 0;
    if (t->root >= 0) check_node(t, t->root, -1, balanced, &leaves);
    assert_int_equal(leaves, live_count);
    assert_int_equal(t->leaf_count, live_count);
    for (q = 0; q < 20; ++q) {
        sx_real x = sx_test_rng_range(rng, -50.0, 50.0), y = sx_test_rng_range(rng, -50.0, 50.0);
        sx_real r = sx_test_rng_range(rng, 0.0, 15.0);
        sx_aabb box = sx_aabb_make(sx_v2(x - r, y - r), sx_v2(x + r, y + r));
        int expect[ITEMS], n = 0;
        count = 0;
        assert_int_equal(sx_tree_query(t, box, &out, &count, &capacity), SX_OK);
        for (i = 0; i < ITEMS; ++i) {
            if (live[i] && sx_aabb_overlaps(boxes[i], box)) expect[n++] = i;
        }
        assert_int_equal(count, n);
        if (count > 1) qsort(out, (size_t)count, sizeof(int), int_cmp);
        for (i = 0; i < n; ++i)
            assert_int_equal(out[i], expect[i]);
    }
    sx_free(out, (size_t)capacity * sizeof(int));
}

static sx_aabb random_box(sx_test_rng *rng) {
    sx_real x = sx_test_rng_range(rng, -50.0, 50.0), y = sx_test_rng_range(rng, -50.0, 50.0);
    sx_real w = sx_test_rng_range(rng, 0.0, 3.0), h = sx_test_rng_range(rng, 0.0, 3.0);
    /* now and then a wide one, as a ground or a wall */
    if (sx_test_rng_next(rng) % 20u == 0) w *= SX_R(20.0);
    return sx_aabb_make(sx_v2(x, y), sx_v2(x + w, y + h));
}

static void tree_queries_equal_brute_force_through_insert_remove_move_and_rebuild(void **state) {
    sx_aabb_tree t;
    sx_test_rng rng = sx_test_rng_make(20261126u);
    sx_aabb boxes[ITEMS];
    bool live[ITEMS];
    int leaf[ITEMS], items[ITEMS], round, i;
    (void)state;
    memset(live, 0, sizeof(live));
    sx_tree_init(&t);
    check_tree(&t, boxes, live, false, &rng); /* empty */
    for (round = 0; round < 40; ++round) {
        for (i = 0; i < 60; ++i) {
            int k = (int)(sx_test_rng_next(&rng) % ITEMS);
            if (live[k]) {
                sx_tree_remove(&t, leaf[k]);
                live[k] = false;
                /* half the removed come back elsewhere: a move */
                if (sx_test_rng_next(&rng) % 2u == 0) continue;
            }
            boxes[k] = random_box(&rng);
            leaf[k] = sx_tree_insert(&t, boxes[k], k);
            assert_true(leaf[k] >= 0);
            live[k] = true;
        }
        check_tree(&t, boxes, live, false, &rng);
        /* 300 leaves: a balanced tree is 9 levels deep */
        if (t.root >= 0) assert_true(t.nodes[t.root].height <= 16);
        if (round % 10 == 9) {
            /* rebuilt top down from the live items: the queries still agree
             * (the median split is balanced within one level too) and the
             * leaves it names are the ones later removes take */
            int n = 0;
            for (i = 0; i < ITEMS; ++i) {
                if (live[i]) items[n++] = i;
            }
            assert_int_equal(sx_tree_build(&t, items, boxes, n, leaf), SX_OK);
            check_tree(&t, boxes, live, true, &rng);
        }
    }
    /* all out again: an empty tree */
    for (i = 0; i < ITEMS; ++i) {
        if (live[i]) {
            sx_tree_remove(&t, leaf[i]);
            live[i] = false;
        }
    }
    check_tree(&t, boxes, live, false, &rng);
    assert_int_equal(t.root, -1);
    sx_tree_free(&t);
}

/* A thousand equal boxes (a grid of identical bodies on a scene's first
 * step): the top-down build must still split them and the queries find
 * every one. */
static void tree_built_from_identical_boxes_answers_every_query(void **state) {
    sx_aabb_tree t;
    sx_test_rng rng = sx_test_rng_make(7u);
    static sx_aabb boxes[ITEMS];
    bool live[ITEMS];
    int leaf[ITEMS], items[ITEMS], i;
    (void)state;
    for (i = 0; i < ITEMS; ++i) {
        boxes[i] = sx_aabb_make(sx_v2(SX_R(1.0), SX_R(1.0)), sx_v2(SX_R(2.0), SX_R(2.0)));
        items[i] = i;
        live[i] = true;
    }
    sx_tree_init(&t);
    assert_int_equal(sx_tree_build(&t, items, boxes, ITEMS, leaf), SX_OK);
    check_tree(&t, boxes, live, true, &rng);
    assert_true(t.nodes[t.root].height <= 10); /* 2^9 > 300: a balanced split */
    sx_tree_free(&t);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tree_queries_equal_brute_force_through_insert_remove_move_and_rebuild),
        cmocka_unit_test(tree_built_from_identical_boxes_answers_every_query),
    };
    return cmocka_run_group_tests_name("aabb tree", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
