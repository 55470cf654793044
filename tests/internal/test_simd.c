/* sepax tests — the lane operations of src/simd.h.
 *
 * A white-box test of the one SIMD header: the same assertions run on the
 * SSE2 lanes of the float build, on the double build's pairs of SSE2
 * registers and on the portable lanes (make test SIMD=0), so passing in
 * every build is what shows the paths agree, NaN, signed zeros and ties
 * included. */
#include <math.h>
#include <string.h>

#include "../../src/simd.h"
#include "test_support.h"

/* The bits of a real, so that -0 and NaN payloads compare exactly. */
static int same_bits(sx_real a, sx_real b) { return memcmp(&a, &b, sizeof a) == 0; }

static void lanes_load_store_and_arithmetic_are_exact(void **state) {
    sx_real in[4] = {SX_R(1.5), SX_R(-2.0), SX_R(0.1), SX_R(3.0)}, out[4];
    sx_r4 a = sx_r4_load(in), b = sx_r4_set(SX_R(0.25), SX_R(4.0), SX_R(0.2), SX_R(-3.0));
    int i;
    (void)state;
    sx_r4_store(out, a);
    for (i = 0; i < 4; ++i)
        assert_true(same_bits(out[i], in[i]));
    for (i = 0; i < 4; ++i) {
        sx_real x = in[i], y = sx_r4_lane(b, i);
        assert_true(same_bits(sx_r4_lane(sx_r4_add(a, b), i), x + y));
        assert_true(same_bits(sx_r4_lane(sx_r4_sub(a, b), i), x - y));
        assert_true(same_bits(sx_r4_lane(sx_r4_mul(a, b), i), x * y));
        assert_true(same_bits(sx_r4_lane(sx_r4_div(a, b), i), x / y));
        /* rounded twice, as the scalar code without contraction */
        {
            volatile sx_real p = x * y;
            assert_true(same_bits(sx_r4_lane(sx_r4_mul_add(a, b, a), i), p + x));
        }
    }
    assert_true(same_bits(sx_r4_lane(sx_r4_sqrt(sx_r4_set1(SX_R(2.0))), 2), sx_sqrt(SX_R(2.0))));
    assert_true(same_bits(sx_r4_lane(sx_r4_zero(), 3), SX_R(0.0)));
}

static void min_max_and_clamp_follow_the_sse_rules(void **state) {
    sx_real nan = (sx_real)NAN;
    sx_r4 a = sx_r4_set(nan, SX_R(1.0), SX_R(-0.0), SX_R(2.0));
    sx_r4 b = sx_r4_set(SX_R(5.0), nan, SX_R(0.0), SX_R(1.0));
    sx_r4 lo = sx_r4_set1(SX_R(-1.0)), hi = sx_r4_set1(SX_R(1.0));
    (void)state;
    /* the second operand when either is NaN or on a tie (-0 against +0) */
    assert_true(same_bits(sx_r4_lane(sx_r4_min(a, b), 0), SX_R(5.0)));
    assert_true(isnan(sx_r4_lane(sx_r4_min(a, b), 1)));
    assert_true(same_bits(sx_r4_lane(sx_r4_min(a, b), 2), SX_R(0.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_min(a, b), 3), SX_R(1.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_max(a, b), 0), SX_R(5.0)));
    assert_true(isnan(sx_r4_lane(sx_r4_max(a, b), 1)));
    assert_true(same_bits(sx_r4_lane(sx_r4_max(a, b), 2), SX_R(0.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_max(a, b), 3), SX_R(2.0)));
    /* NaN clamps to the low bound; an inverted range gives the high one */
    assert_true(same_bits(sx_r4_lane(sx_r4_clamp(a, lo, hi), 0), SX_R(-1.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_clamp(a, lo, hi), 3), SX_R(1.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_clamp(b, hi, lo), 0), SX_R(-1.0)));
    /* sign operations act on the sign bit */
    assert_true(same_bits(sx_r4_lane(sx_r4_abs(a), 2), SX_R(0.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_neg(b), 2), SX_R(-0.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_abs(sx_r4_neg(b)), 3), SX_R(1.0)));
}

static void comparisons_masks_and_select(void **state) {
    sx_real nan = (sx_real)NAN;
    sx_r4 a = sx_r4_set(SX_R(1.0), SX_R(2.0), nan, SX_R(-0.0));
    sx_r4 b = sx_r4_set(SX_R(2.0), SX_R(2.0), SX_R(0.0), SX_R(0.0));
    (void)state;
    assert_int_equal(sx_m4_bits(sx_r4_lt(a, b)), 1);
    assert_int_equal(sx_m4_bits(sx_r4_le(a, b)), 1 | 2 | 8);
    assert_int_equal(sx_m4_bits(sx_r4_gt(b, a)), 1);
    assert_int_equal(sx_m4_bits(sx_r4_ge(b, a)), 1 | 2 | 8);
    assert_int_equal(sx_m4_bits(sx_r4_eq(a, b)), 2 | 8);
    assert_int_equal(sx_m4_bits(sx_r4_unordered(a, b)), 4);
    assert_int_equal(sx_m4_bits(sx_m4_or(sx_r4_lt(a, b), sx_r4_unordered(a, b))), 1 | 4);
    assert_int_equal(sx_m4_bits(sx_m4_and(sx_r4_le(a, b), sx_r4_ge(a, b))), 2 | 8);
    assert_int_equal(sx_m4_bits(sx_m4_andnot(sx_r4_lt(a, b), sx_r4_le(a, b))), 2 | 8);
    assert_true(sx_m4_any(sx_r4_unordered(a, b)));
    assert_false(sx_m4_all(sx_r4_le(a, b)));
    assert_true(sx_m4_all(sx_r4_eq(b, b)));
    {
        sx_r4 s = sx_r4_select(sx_r4_lt(a, b), a, b);
        assert_true(same_bits(sx_r4_lane(s, 0), SX_R(1.0)));
        assert_true(same_bits(sx_r4_lane(s, 1), SX_R(2.0)));
        assert_true(same_bits(sx_r4_lane(s, 2), SX_R(0.0)));
        assert_true(same_bits(sx_r4_lane(s, 3), SX_R(0.0)));
    }
}

/* The lane moves name their order: each lane checked by value. */
static void lane_moves_follow_their_names(void **state) {
    sx_real in[4] = {SX_R(1.0), SX_R(2.0), SX_R(3.0), SX_R(4.0)}, two[2];
    sx_r4 a = sx_r4_load(in), b = sx_r4_set(SX_R(5.0), SX_R(6.0), SX_R(7.0), SX_R(8.0));
    sx_real want[][4] = {{1, 2, 0, 0}, {3, 4, 7, 8},   {1, 2, 3, 4}, {2, 1, 4, 3}, {3, 4, 1, 2},
                         {1, 2, 5, 6}, {1, 2, 7, 8},   {1, 3, 5, 7}, {2, 4, 6, 8}, {3, 3, 3, 3},
                         {4, 4, 4, 4}, {-1, 2, 3, -4}, {1, 2, 1, 2}};
    sx_r4 got[13];
    int i, k;
    (void)state;
    got[0] = sx_r4_load2(in);
    got[1] = sx_r4_load_low(b, &in[2]);
    got[2] = sx_r4_load2x2(&in[0], &in[2]);
    got[3] = sx_r4_swap_pairs(a);
    got[4] = sx_r4_swap_halves(a);
    got[5] = sx_r4_low_halves(a, b);
    got[6] = sx_r4_low_high(a, b);
    got[7] = sx_r4_evens(a, b);
    got[8] = sx_r4_odds(a, b);
    got[9] = sx_r4_splat2(a);
    got[10] = sx_r4_splat3(a);
    got[11] = sx_r4_flip_signs(a, sx_r4_set(SX_R(-0.0), SX_R(0.0), SX_R(0.0), SX_R(-0.0)));
    got[12] = sx_r4_load_high(a, &in[0]);
    for (k = 0; k < 13; ++k) {
        for (i = 0; i < 4; ++i)
            assert_true(same_bits(sx_r4_lane(got[k], i), want[k][i]));
    }
    assert_true(same_bits(sx_r4_first(b), SX_R(5.0)));
    sx_r4_store_low(two, b);
    assert_true(same_bits(two[0], SX_R(5.0)) && same_bits(two[1], SX_R(6.0)));
    sx_r4_store_high(two, b);
    assert_true(same_bits(two[0], SX_R(7.0)) && same_bits(two[1], SX_R(8.0)));
    /* the sign of a zero and of a NaN flips too */
    assert_true(
        same_bits(sx_r4_first(sx_r4_flip_signs(sx_r4_zero(), sx_r4_set1(SX_R(-0.0)))), SX_R(-0.0)));
    assert_true(signbit(sx_r4_first(sx_r4_flip_signs(
                    sx_r4_set1((sx_real)NAN), sx_r4_set1(SX_R(-0.0))))) != signbit((sx_real)NAN));
}

/* Horizontal minimum and maximum: halves first, then pairs, so NaN and
 * signed zeros land where sx_r4_min's rule puts them, the same in both
 * paths. */
static void lane_reductions_and_finite_tests(void **state) {
    sx_real nan = (sx_real)NAN;
    sx_r4 a = sx_r4_set(SX_R(3.0), SX_R(-1.0), SX_R(2.0), SX_R(5.0));
    sx_r4 z = sx_r4_set(SX_R(0.0), SX_R(-0.0), SX_R(-0.0), SX_R(0.0));
    sx_r4 n = sx_r4_set(SX_R(1.0), nan, SX_R(2.0), SX_R(0.5));
    int i;
    (void)state;
    for (i = 0; i < 4; ++i) {
        assert_true(same_bits(sx_r4_lane(sx_r4_min_lanes(a), i), SX_R(-1.0)));
        assert_true(same_bits(sx_r4_lane(sx_r4_max_lanes(a), i), SX_R(5.0)));
    }
    /* min(z, [z2, z3, z0, z1]) = [-0, 0, 0, -0]; then with its pairs
     * swapped: [0, -0, -0, 0] */
    assert_true(same_bits(sx_r4_first(sx_r4_min_lanes(z)), SX_R(0.0)));
    assert_true(same_bits(sx_r4_lane(sx_r4_min_lanes(z), 1), SX_R(-0.0)));
    /* [1, nan, 2, 0.5] with its halves swapped: [2, 0.5, 2, nan]; then
     * with its pairs swapped: [2, 2, nan, 2] */
    assert_true(same_bits(sx_r4_first(sx_r4_max_lanes(n)), SX_R(2.0)));
    assert_true(isnan(sx_r4_lane(sx_r4_max_lanes(n), 2)));
    assert_true(same_bits(sx_r4_lane(sx_r4_max_lanes(n), 3), SX_R(2.0)));
    assert_true(sx_r4_any_nan(n));
    assert_false(sx_r4_any_nan(a));
    assert_true(sx_r4_all_finite(a));
    assert_false(sx_r4_all_finite(sx_r4_set(SX_R(1.0), SX_R(1.0), (sx_real)INFINITY, SX_R(1.0))));
    assert_false(sx_r4_all_finite(n));
}

/* Integer lanes chosen by a mask, as the narrowphase keeps a face index
 * beside the separation that chose it. */
static void integer_lanes_follow_a_mask(void **state) {
    sx_r4 a = sx_r4_set(SX_R(1.0), SX_R(5.0), (sx_real)NAN, SX_R(-2.0));
    sx_r4 b = sx_r4_set1(SX_R(0.0));
    int32_t out[4];
    (void)state;
    sx_i4_store(out, sx_i4_select(sx_r4_gt(a, b), sx_i4_set1(7), sx_i4_set1(-3)));
    assert_int_equal(out[0], 7);
    assert_int_equal(out[1], 7);
    assert_int_equal(out[2], -3);
    assert_int_equal(out[3], -3);
}

/* The transpose the wide solver moves bodies with: four records of four
 * reals in, the lanes of each field out, and back again bit for bit (a
 * NaN's payload and a zero's sign included). The all-true mask selects
 * every lane. */
static void transpose_and_the_true_mask(void **state) {
    sx_real in[4][4], out[4];
    sx_r4 r[4];
    int i, j;
    (void)state;
    for (i = 0; i < 4; ++i)
        for (j = 0; j < 4; ++j)
            in[i][j] = (sx_real)(10 * i + j) + SX_R(0.5);
    in[2][1] = SX_R(-0.0);
    in[3][3] = (sx_real)NAN;
    for (i = 0; i < 4; ++i)
        r[i] = sx_r4_load(in[i]);
    sx_r4_transpose(&r[0], &r[1], &r[2], &r[3]);
    for (j = 0; j < 4; ++j) {
        sx_r4_store(out, r[j]);
        for (i = 0; i < 4; ++i) {
            if (i == 3 && j == 3)
                assert_true(isnan(out[i]));
            else
                assert_true(same_bits(out[i], in[i][j]));
        }
    }
    sx_r4_transpose(&r[0], &r[1], &r[2], &r[3]);
    for (i = 0; i < 4; ++i) {
        sx_r4_store(out, r[i]);
        for (j = 0; j < 4; ++j)
            assert_true(memcmp(&out[j], &in[i][j], sizeof(sx_real)) == 0);
    }
    assert_int_equal(sx_m4_bits(sx_m4_true()), 15);
    sx_r4_store(out, sx_r4_select(sx_m4_true(), r[1], r[0]));
    assert_true(same_bits(out[2], in[1][2]));
    assert_int_equal(sx_m4_bits(sx_m4_andnot(sx_m4_true(), sx_m4_true())), 0);
}

/* The solver's SX_LANES-wide lanes (eight in the AVX2 float build, else
 * sx_r4's four) against plain C on every lane, NaN, signed zeros and ties
 * included: the same rules as sx_r4, so that a lane answers alike in every
 * width. */
/* Arithmetic on a NaN gives a NaN; which payload the compiler's folding of
 * the plain C side keeps is not the lanes' to decide. */
static int same_or_nan(sx_real a, sx_real b) { return (isnan(a) && isnan(b)) || same_bits(a, b); }

static void wide_lanes_follow_the_scalar_rules(void **state) {
    sx_real nan = (sx_real)NAN;
    sx_real a_in[8] = {SX_R(0.25), nan,        SX_R(-0.0), SX_R(2.0),
                       SX_R(0.1),  SX_R(-3.0), SX_R(7.0),  SX_R(0.0)};
    sx_real b_in[8] = {SX_R(1.5), SX_R(1.0),  SX_R(0.0), SX_R(2.0),
                       nan,       SX_R(-3.0), SX_R(3.0), SX_R(-0.0)};
    sx_real out[8];
    sx_rw a, b;
    int i, lt = 0, le = 0, gt = 0, ge = 0;
    (void)state;
    /* the AVX2 float build is the eight-lane one */
#if defined(__AVX2__) && !defined(SX_DOUBLE) && !defined(SX_NO_SIMD)
    assert_int_equal(SX_LANES, 8);
#else
    assert_int_equal(SX_LANES, 4);
#endif
    a = sx_rw_load(a_in);
    b = sx_rw_load(b_in);
    sx_rw_store(out, a);
    for (i = 0; i < SX_LANES; ++i) {
        sx_real x = a_in[i], y = b_in[i];
        assert_true(same_bits(out[i], x));
        assert_true(same_bits(sx_rw_lane(a, i), x));
        assert_true(same_or_nan(sx_rw_lane(sx_rw_add(a, b), i), x + y));
        assert_true(same_or_nan(sx_rw_lane(sx_rw_sub(a, b), i), x - y));
        assert_true(same_or_nan(sx_rw_lane(sx_rw_mul(a, b), i), x * y));
        assert_true(same_or_nan(sx_rw_lane(sx_rw_div(a, b), i), x / y));
        assert_true(same_bits(sx_rw_lane(sx_rw_min(a, b), i), x < y ? x : y));
        assert_true(same_bits(sx_rw_lane(sx_rw_max(a, b), i), x > y ? x : y));
        assert_true(signbit(sx_rw_lane(sx_rw_neg(a), i)) != signbit(x));
        assert_true(same_bits(sx_rw_lane(sx_rw_set1(y), i), y));
        assert_true(same_bits(sx_rw_lane(sx_rw_zero(), i), SX_R(0.0)));
        assert_true(same_bits(sx_rw_lane(sx_rw_select(sx_rw_lt(a, b), a, b), i), x < y ? x : y));
        lt |= (x < y) << i;
        le |= (x <= y) << i;
        gt |= (x > y) << i;
        ge |= (x >= y) << i;
    }
    assert_int_equal(sx_mw_bits(sx_rw_lt(a, b)), lt);
    assert_int_equal(sx_mw_bits(sx_rw_le(a, b)), le);
    assert_int_equal(sx_mw_bits(sx_rw_gt(a, b)), gt);
    assert_int_equal(sx_mw_bits(sx_rw_ge(a, b)), ge);
    assert_int_equal(sx_mw_bits(sx_mw_and(sx_rw_le(a, b), sx_rw_ge(a, b))), le & ge);
    assert_int_equal(sx_mw_bits(sx_mw_or(sx_rw_lt(a, b), sx_rw_gt(a, b))), lt | gt);
    assert_int_equal(sx_mw_bits(sx_mw_andnot(sx_rw_lt(a, b), sx_rw_le(a, b))), le & ~lt);
    assert_int_equal(sx_mw_bits(sx_mw_true()), (1 << SX_LANES) - 1);
    assert_true(sx_mw_all(sx_mw_true()));
    assert_false(sx_mw_all(sx_rw_le(a, b)));
    assert_true(sx_mw_any(sx_rw_lt(a, b)));
    assert_false(sx_mw_any(sx_mw_andnot(sx_mw_true(), sx_mw_true())));
}

/* The solver's move of bodies into lanes: records of four reals picked by
 * index, each field into the lanes of one register, and back; a record
 * named by several lanes (the padding lanes' sink) keeps the last lane's
 * values, as lane-order stores leave it. */
static void wide_gather_and_scatter_move_records(void **state) {
    sx_real rec[10][4], back[10][4];
    int idx[8] = {3, 0, 9, 5, 9, 1, 7, 2};
    sx_rw f[4];
    int i, j, k;
    (void)state;
    for (i = 0; i < 10; ++i)
        for (j = 0; j < 4; ++j)
            rec[i][j] = back[i][j] = (sx_real)(10 * i + j) + SX_R(0.5);
    rec[5][1] = SX_R(-0.0);
    sx_rw_gather4(&rec[0][0], idx, &f[0], &f[1], &f[2], &f[3]);
    for (j = 0; j < 4; ++j) {
        for (i = 0; i < SX_LANES; ++i)
            assert_true(same_bits(sx_rw_lane(f[j], i), rec[idx[i]][j]));
    }
    /* the same records named by address */
    {
        const sx_real *at[8];
        for (i = 0; i < SX_LANES; ++i)
            at[i] = rec[idx[i]];
        for (j = 0; j < 4; ++j)
            f[j] = sx_rw_zero();
        sx_rw_gather4p(at, &f[0], &f[1], &f[2], &f[3]);
        for (j = 0; j < 4; ++j) {
            for (i = 0; i < SX_LANES; ++i)
                assert_true(same_bits(sx_rw_lane(f[j], i), rec[idx[i]][j]));
        }
    }
    /* lane l's fields become l + 100 * field, then go back */
    for (j = 0; j < 4; ++j) {
        sx_real v[8];
        for (i = 0; i < SX_LANES; ++i)
            v[i] = (sx_real)(i + 100 * j);
        f[j] = sx_rw_load(v);
    }
    sx_rw_scatter4(&back[0][0], idx, f[0], f[1], f[2], f[3]);
    for (k = 0; k < 10; ++k) {
        int last = -1;
        for (i = 0; i < SX_LANES; ++i)
            if (idx[i] == k) last = i;
        for (j = 0; j < 4; ++j) {
            sx_real want =
                last >= 0 ? (sx_real)(last + 100 * j) : (sx_real)(10 * k + j) + SX_R(0.5);
            assert_true(same_bits(back[k][j], want));
        }
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(lanes_load_store_and_arithmetic_are_exact),
        cmocka_unit_test(min_max_and_clamp_follow_the_sse_rules),
        cmocka_unit_test(comparisons_masks_and_select),
        cmocka_unit_test(lane_moves_follow_their_names),
        cmocka_unit_test(lane_reductions_and_finite_tests),
        cmocka_unit_test(integer_lanes_follow_a_mask),
        cmocka_unit_test(transpose_and_the_true_mask),
        cmocka_unit_test(wide_lanes_follow_the_scalar_rules),
        cmocka_unit_test(wide_gather_and_scatter_move_records),
    };
    return cmocka_run_group_tests_name("simd", tests, sx_test_group_setup, sx_test_group_teardown);
}
