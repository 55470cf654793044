/* sepax tests — the world's limits, reached from the inside.
 *
 * A white-box test: it reads and sets the world's private layout
 * (src/world_internal.h) to stand at limits that the public API would need
 * terabytes of memory or billions of calls to reach: arrays at
 * SX_WORLD_MAX_ITEMS elements, body or collider slots at the end of their
 * count, and a slot at the end of its generations. The public behaviour at
 * each limit (a status, never an overflow) is what it checks; test_world.c
 * checks the limits that the public API reaches. */
#include <stdlib.h>
#include <string.h>

#include "../../src/world_array.h"
#include "../../src/world_internal.h"
#include "test_support.h"

/* An allocator that refuses every block and records the requests, so a
 * growth to a huge capacity is asked for but never made. */
typedef struct refusing_allocator {
    int calls;
    size_t last;
} refusing_allocator;

static void *refusing_alloc(size_t size, void *context) {
    refusing_allocator *r = (refusing_allocator *)context;
    r->calls++;
    r->last = size;
    return NULL;
}

static void refusing_free(void *memory, size_t size, void *context) {
    (void)memory;
    (void)size;
    (void)context;
}

/* Regression (issue 28): the doubling of sx_grow_array overflowed an int
 * past 2^30 (UBSan: 1073741824 * 2). It now stops at SX_WORLD_MAX_ITEMS,
 * and a need beyond it is SX_ERR_CAPACITY without asking the allocator. */
static void array_growth_stops_at_the_item_limit(void **state) {
    refusing_allocator r = {0, 0};
    void *array = NULL;
    int capacity;
    (void)state;
    sx_set_allocator(refusing_alloc, refusing_free, &r);
    /* past the limit: refused before any allocation */
    capacity = 0;
    assert_int_equal(sx_reserve_array(&array, &capacity, SX_WORLD_MAX_ITEMS + 1, 8),
                     SX_ERR_CAPACITY);
    assert_int_equal(r.calls, 0);
    assert_false(sx_grow_array(&array, &capacity, SX_WORLD_MAX_ITEMS + 1, 8));
    assert_int_equal(r.calls, 0);
    /* doubling 2^29 + 1 would pass the limit: the limit is asked for */
    capacity = (1 << 29) + 1;
    assert_int_equal(sx_reserve_array(&array, &capacity, capacity + 1, 8), SX_ERR_NO_MEMORY);
    assert_int_equal(r.calls, 1);
    assert_true(r.last == (size_t)SX_WORLD_MAX_ITEMS * 8u);
    /* a failed growth changes nothing */
    assert_int_equal(capacity, (1 << 29) + 1);
    assert_null(array);
    /* below the limit it doubles as before */
    capacity = 1 << 20;
    assert_int_equal(sx_reserve_array(&array, &capacity, capacity + 1, 4), SX_ERR_NO_MEMORY);
    assert_true(r.last == ((size_t)1 << 21) * 4u);
    /* at the limit exactly: the limit, once */
    capacity = SX_WORLD_MAX_ITEMS - 1;
    assert_int_equal(sx_reserve_array(&array, &capacity, SX_WORLD_MAX_ITEMS, 1), SX_ERR_NO_MEMORY);
    assert_true(r.last == (size_t)SX_WORLD_MAX_ITEMS);
    sx_set_allocator(NULL, NULL, NULL);
    /* a real growth still works and keeps the contents */
    capacity = 0;
    assert_int_equal(sx_reserve_array(&array, &capacity, 3, sizeof(int)), SX_OK);
    assert_int_equal(capacity, 16);
    ((int *)array)[2] = 7;
    assert_int_equal(sx_reserve_array(&array, &capacity, 17, sizeof(int)), SX_OK);
    assert_int_equal(capacity, 32);
    assert_int_equal(((int *)array)[2], 7);
    sx_free(array, (size_t)capacity * sizeof(int));
}

static sx_world *make_world_with_a_body(sx_body_id *body) {
    sx_world_def wd = sx_default_world_def();
    sx_body_def bd = sx_default_body_def();
    sx_world *w = sx_world_create(&wd);
    assert_non_null(w);
    bd.type = SX_BODY_DYNAMIC;
    assert_int_equal(sx_create_body(w, &bd, body), SX_OK);
    return w;
}

/* With SX_WORLD_MAX_ITEMS body slots in use and none free, one more body is
 * SX_ERR_CAPACITY (the slot count is set from the inside: the arrays are
 * not that large, and the call must not touch them). */
static void the_body_after_the_last_slot_is_refused_with_capacity(void **state) {
    sx_body_id a, b = {5, 5};
    sx_body_def bd = sx_default_body_def();
    sx_world *w = make_world_with_a_body(&a);
    int slots;
    (void)state;
    slots = w->body_slots;
    w->body_slots = SX_WORLD_MAX_ITEMS;
    assert_int_equal(sx_create_body(w, &bd, &b), SX_ERR_CAPACITY);
    assert_true(sx_body_id_is_null(b));
    w->body_slots = slots;
    assert_int_equal(sx_create_body(w, &bd, &b), SX_OK);
    assert_int_equal(sx_world_body_count(w), 2);
    sx_world_destroy(w);
}

static void the_collider_after_the_last_slot_is_refused_with_capacity(void **state) {
    sx_body_id a;
    sx_collider_id c = {5, 5};
    sx_collider_def cd = sx_default_collider_def();
    sx_world *w = make_world_with_a_body(&a);
    int slots;
    (void)state;
    assert_int_equal(sx_body_add_collider(w, a, &cd, NULL), SX_OK);
    slots = w->collider_slots;
    w->collider_slots = SX_WORLD_MAX_ITEMS;
    assert_int_equal(sx_body_add_collider(w, a, &cd, &c), SX_ERR_CAPACITY);
    assert_true(c.index == 0 && c.generation == 0);
    w->collider_slots = slots;
    assert_int_equal(sx_body_add_collider(w, a, &cd, &c), SX_OK);
    sx_world_destroy(w);
}

/* Regression (issue 28): after 2^32 - 1 destroy/create cycles of one slot
 * the generation wrapped to 1 and the slot's very first handle named the
 * new body. The slot's generation is set near the end from the inside
 * instead of looping four billion times: its last generation is handed out
 * once, and then the slot is retired, never reused. */
static void a_body_slot_is_retired_after_its_last_generation(void **state) {
    sx_body_id first, last_but_one, last, next;
    sx_body_def bd = sx_default_body_def();
    sx_world *w = make_world_with_a_body(&first);
    int k;
    (void)state;
    assert_int_equal(first.index, 0);
    assert_int_equal(first.generation, 1);
    /* the live body of slot 0 jumps to generation 2^32 - 2 */
    w->infos[0].generation = UINT32_MAX - 1;
    last_but_one.index = 0;
    last_but_one.generation = UINT32_MAX - 1;
    assert_true(sx_body_is_valid(w, last_but_one));
    assert_false(sx_body_is_valid(w, first));
    /* destroyed, the slot is reused once more with the last generation */
    assert_int_equal(sx_destroy_body(w, last_but_one), SX_OK);
    assert_int_equal(sx_create_body(w, &bd, &last), SX_OK);
    assert_int_equal(last.index, 0);
    assert_true(last.generation == UINT32_MAX);
    /* destroyed again, it is retired: new bodies take other slots, and no
     * handle of slot 0 comes back to life */
    assert_int_equal(sx_destroy_body(w, last), SX_OK);
    for (k = 0; k < 4; ++k) {
        assert_int_equal(sx_create_body(w, &bd, &next), SX_OK);
        assert_int_equal(next.index, 1);
        assert_int_equal(next.generation, (uint32_t)k + 1u);
        assert_false(sx_body_is_valid(w, first));
        assert_false(sx_body_is_valid(w, last_but_one));
        assert_false(sx_body_is_valid(w, last));
        assert_int_equal(sx_destroy_body(w, last), SX_ERR_STALE_HANDLE);
        assert_int_equal(sx_body_set_linear_velocity(w, first, sx_v2(SX_R(1.0), SX_R(0.0))),
                         SX_ERR_STALE_HANDLE);
        assert_int_equal(sx_destroy_body(w, next), SX_OK);
    }
    assert_int_equal(sx_world_body_count(w), 0);
    /* the retired slot stays dead through steps */
    assert_int_equal(sx_create_body(w, &bd, &next), SX_OK);
    assert_int_equal(sx_world_step(w, SX_R(1.0) / SX_R(60.0)), SX_OK);
    assert_int_equal(sx_world_body_count(w), 1);
    assert_false(w->infos[0].alive);
    sx_world_destroy(w);
}

static void a_collider_slot_is_retired_after_its_last_generation(void **state) {
    sx_body_id body;
    sx_collider_id first, last, next;
    sx_collider_def cd = sx_default_collider_def();
    sx_world *w = make_world_with_a_body(&body);
    int k;
    (void)state;
    assert_int_equal(sx_body_add_collider(w, body, &cd, &first), SX_OK);
    assert_int_equal(first.index, 0);
    w->collider_generations[0] = UINT32_MAX - 1;
    last.index = 0;
    last.generation = UINT32_MAX - 1;
    assert_int_equal(sx_destroy_collider(w, last), SX_OK);
    assert_int_equal(sx_body_add_collider(w, body, &cd, &last), SX_OK);
    assert_int_equal(last.index, 0);
    assert_true(last.generation == UINT32_MAX);
    assert_int_equal(sx_destroy_collider(w, last), SX_OK);
    for (k = 0; k < 4; ++k) {
        assert_int_equal(sx_body_add_collider(w, body, &cd, &next), SX_OK);
        assert_int_equal(next.index, 1);
        assert_false(sx_collider_is_valid(w, first));
        assert_false(sx_collider_is_valid(w, last));
        assert_int_equal(sx_destroy_collider(w, first), SX_ERR_STALE_HANDLE);
        assert_int_equal(sx_destroy_collider(w, next), SX_OK);
    }
    /* no collider left: the dynamic body has the unit mass of an empty one */
    assert_near(sx_body_get_mass(w, body), 1.0, 0.0);
    sx_world_destroy(w);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(array_growth_stops_at_the_item_limit),
        cmocka_unit_test(the_body_after_the_last_slot_is_refused_with_capacity),
        cmocka_unit_test(the_collider_after_the_last_slot_is_refused_with_capacity),
        cmocka_unit_test(a_body_slot_is_retired_after_its_last_generation),
        cmocka_unit_test(a_collider_slot_is_retired_after_its_last_generation),
    };
    return cmocka_run_group_tests_name("limits", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
