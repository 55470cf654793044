/* sepax tests — the base layer: status strings, version, allocator hooks and
 * their live-byte counter, and the assert handler. */
#include <string.h>

#include "test_support.h"

static void status_strings_are_distinct_and_never_null(void **state) {
    int i, j;
    (void)state;
    for (i = 0; i < SX_STATUS_COUNT; ++i) {
        assert_non_null(sx_status_str((sx_status)i));
        for (j = 0; j < i; ++j) {
            assert_string_not_equal(sx_status_str((sx_status)i), sx_status_str((sx_status)j));
        }
    }
    assert_string_equal(sx_status_str(SX_OK), "ok");
    assert_string_equal(sx_status_str((sx_status)999), "unknown status");
    assert_string_equal(sx_status_str((sx_status)-1), "unknown status");
}

static void version_matches_header_and_real_type_matches_build(void **state) {
    (void)state;
    assert_int_equal(sx_version(), SX_VERSION);
#ifdef SX_DOUBLE
    assert_true(sx_real_is_double());
    assert_int_equal(sizeof(sx_real), sizeof(double));
#else
    assert_false(sx_real_is_double());
    assert_int_equal(sizeof(sx_real), sizeof(float));
#endif
}

typedef struct counting_allocator {
    int allocs, frees;
    size_t last_size;
} counting_allocator;

static void *counting_alloc(size_t size, void *context) {
    counting_allocator *c = (counting_allocator *)context;
    c->allocs++;
    c->last_size = size;
    return test_malloc(size);
}

static void counting_free(void *memory, size_t size, void *context) {
    counting_allocator *c = (counting_allocator *)context;
    c->frees++;
    c->last_size = size;
    test_free(memory);
}

static void allocator_hooks_see_every_block_and_live_bytes_balance(void **state) {
    counting_allocator c = {0, 0, 0};
    size_t before = sx_live_bytes();
    void *p, *q;
    (void)state;
    sx_set_allocator(counting_alloc, counting_free, &c);
    p = sx_alloc(100);
    q = sx_alloc(28);
    assert_non_null(p);
    assert_non_null(q);
    assert_int_equal(c.allocs, 2);
    assert_int_equal(sx_live_bytes() - before, 128);
    sx_free(p, 100);
    assert_int_equal(c.last_size, 100);
    sx_free(q, 28);
    sx_free(NULL, 0);
    assert_int_equal(c.frees, 2);
    assert_int_equal(sx_live_bytes(), before);
    assert_null(sx_alloc(0));
    assert_int_equal(c.allocs, 2);
    sx_set_allocator(NULL, NULL, NULL);
    p = sx_alloc(16);
    assert_non_null(p);
    assert_int_equal(c.allocs, 2);
    sx_free(p, 16);
    assert_int_equal(sx_live_bytes(), before);
}

static int s_assert_calls;
static char s_assert_expr[64];

static void recording_handler(const char *expression, const char *file, int line, void *context) {
    (void)file;
    (void)line;
    s_assert_calls += *(int *)context;
    strncpy(s_assert_expr, expression, sizeof s_assert_expr - 1);
}

static void assert_handler_receives_the_failed_expression(void **state) {
    int weight = 1;
    (void)state;
    s_assert_calls = 0;
    sx_set_assert_handler(recording_handler, &weight);
    sx_assert_failed("x > 0", __FILE__, __LINE__);
    assert_int_equal(s_assert_calls, 1);
    assert_string_equal(s_assert_expr, "x > 0");
    sx_test_route_asserts();
}

static void tolerances_derive_from_the_length_scale(void **state) {
    (void)state;
    assert_near(SX_LINEAR_SLOP, 0.005 * (double)SX_LENGTH_UNITS_PER_METER, 1e-9);
    assert_true(SX_WELD_TOLERANCE < SX_LINEAR_SLOP);
    assert_true(SX_SPECULATIVE_DISTANCE > SX_LINEAR_SLOP);
    assert_true(SX_R(1.0) + SX_REAL_EPSILON > SX_R(1.0));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(status_strings_are_distinct_and_never_null),
        cmocka_unit_test(version_matches_header_and_real_type_matches_build),
        cmocka_unit_test(allocator_hooks_see_every_block_and_live_bytes_balance),
        cmocka_unit_test(assert_handler_receives_the_failed_expression),
        cmocka_unit_test(tolerances_derive_from_the_length_scale),
    };
    return cmocka_run_group_tests_name("base", tests, sx_test_group_setup, sx_test_group_teardown);
}
