/* sepax tests — the math layer (include/sepax/vecmath.h): scalars, sx_vec2,
 * sx_rot, sx_xform, sx_mat3 and sx_aabb.
 *
 * Every function is checked twice: against values worked out by hand (exact
 * where the arithmetic is exact, otherwise within SX_TEST_EPS), and against
 * the algebraic laws it must obey (inverse round trips, composition order,
 * det(AB) = det(A) det(B), ...) on a few hundred to a few thousand random
 * cases drawn from fixed seeds. Random cases use tolerances scaled by the
 * magnitude of the values involved (and, for matrix inverses, by the
 * condition number), so the same test is meaningful in the float and the
 * double build. Bad input (NaN, infinities, zero vectors, singular matrices)
 * is checked against the answer the header documents. */
#include <math.h>

#include "test_support.h"

#define PI_D 3.14159265358979323846
#define R_NAN ((sx_real)NAN)
#define R_INF ((sx_real)INFINITY)
#define EPS_D ((double)SX_REAL_EPSILON)

/* ---- helpers ------------------------------------------------------------- */

static sx_vec2 rnd_vec(sx_test_rng *rng, double lo, double hi) {
    sx_real x = sx_test_rng_range(rng, lo, hi);
    sx_real y = sx_test_rng_range(rng, lo, hi);
    return sx_v2(x, y);
}

static sx_xform rnd_xform(sx_test_rng *rng) {
    sx_vec2 p = rnd_vec(rng, -10.0, 10.0);
    return sx_xform_make(p, sx_test_rng_range(rng, -PI_D, PI_D));
}

static sx_mat3 rnd_mat3(sx_test_rng *rng) {
    sx_mat3 a;
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j)
            a.m[i][j] = sx_test_rng_range(rng, -2.0, 2.0);
    }
    return a;
}

/* Frobenius norm, in double. */
static double mat3_norm(sx_mat3 a) {
    double s = 0.0;
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j)
            s += (double)a.m[i][j] * (double)a.m[i][j];
    }
    return sqrt(s);
}

static double row_norm_product(sx_mat3 a) {
    double p = 1.0;
    int i;
    for (i = 0; i < 3; ++i) {
        p *= sqrt((double)a.m[i][0] * (double)a.m[i][0] + (double)a.m[i][1] * (double)a.m[i][1] +
                  (double)a.m[i][2] * (double)a.m[i][2]);
    }
    return p;
}

static void mat3_near_at(sx_mat3 a, sx_mat3 b, double tol, const char *ea, const char *eb,
                         const char *file, int line) {
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            sx_test_assert_near((double)a.m[i][j], (double)b.m[i][j], tol, ea, eb, file, line);
        }
    }
}
#define assert_mat3_near(a, b, tol)                                                                \
    mat3_near_at((a), (b), (double)(tol), #a, #b, __FILE__, __LINE__)

static void mat3_equal_at(sx_mat3 a, sx_mat3 b, const char *file, int line) {
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            if (!(a.m[i][j] == b.m[i][j])) {
                print_error("entry [%d][%d]: %.17g != %.17g\n", i, j, (double)a.m[i][j],
                            (double)b.m[i][j]);
                _fail(file, line);
            }
        }
    }
}
#define assert_mat3_equal(a, b) mat3_equal_at((a), (b), __FILE__, __LINE__)

static bool mat3_is_identity(sx_mat3 a) {
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            if (!(a.m[i][j] == (i == j ? SX_R(1.0) : SX_R(0.0)))) return false;
        }
    }
    return true;
}

/* a - b wrapped into (-pi, pi]. */
static double angle_diff(double a, double b) {
    double d = fmod(a - b, 2.0 * PI_D);
    if (d > PI_D) d -= 2.0 * PI_D;
    if (d <= -PI_D) d += 2.0 * PI_D;
    return d;
}

static bool is_nan(sx_real a) { return a != a; }

/* ---- scalars ------------------------------------------------------------- */

static void scalar_min_max_abs_pick_the_right_value(void **state) {
    (void)state;
    assert_true(sx_minr(SX_R(-2.0), SX_R(3.0)) == SX_R(-2.0));
    assert_true(sx_minr(SX_R(3.0), SX_R(-2.0)) == SX_R(-2.0));
    assert_true(sx_maxr(SX_R(-2.0), SX_R(3.0)) == SX_R(3.0));
    assert_true(sx_maxr(SX_R(3.0), SX_R(-2.0)) == SX_R(3.0));
    assert_true(sx_absr(SX_R(-2.5)) == SX_R(2.5));
    assert_true(sx_absr(SX_R(2.5)) == SX_R(2.5));
    assert_true(sx_absr(SX_R(0.0)) == SX_R(0.0));
    /* Infinities order like any other value. */
    assert_true(sx_minr(-R_INF, SX_R(3.0)) == -R_INF);
    assert_true(sx_maxr(R_INF, SX_R(3.0)) == R_INF);
    assert_true(sx_minr(R_INF, SX_R(3.0)) == SX_R(3.0));
    assert_true(sx_maxr(SX_R(3.0), -R_INF) == SX_R(3.0));
    assert_true(sx_absr(-R_INF) == R_INF);
    /* NaN: a failed comparison selects the second argument, so a NaN in
     * either place is either passed on (second) or dropped (first). This is
     * what makes a NaN point poison sx_aabb_from_points (tested below). */
    assert_true(sx_minr(R_NAN, SX_R(1.0)) == SX_R(1.0));
    assert_true(is_nan(sx_minr(SX_R(1.0), R_NAN)));
    assert_true(sx_maxr(R_NAN, SX_R(1.0)) == SX_R(1.0));
    assert_true(is_nan(sx_maxr(SX_R(1.0), R_NAN)));
    assert_true(is_nan(sx_absr(R_NAN)));
}

static void clamp_keeps_inside_values_and_clamps_outside_ones(void **state) {
    (void)state;
    assert_true(sx_clampr(SX_R(0.5), SX_R(-1.0), SX_R(2.0)) == SX_R(0.5));
    assert_true(sx_clampr(SX_R(-3.0), SX_R(-1.0), SX_R(2.0)) == SX_R(-1.0));
    assert_true(sx_clampr(SX_R(7.0), SX_R(-1.0), SX_R(2.0)) == SX_R(2.0));
    assert_true(sx_clampr(SX_R(-1.0), SX_R(-1.0), SX_R(2.0)) == SX_R(-1.0));
    assert_true(sx_clampr(SX_R(2.0), SX_R(-1.0), SX_R(2.0)) == SX_R(2.0));
    assert_true(sx_clampr(R_INF, SX_R(-1.0), SX_R(2.0)) == SX_R(2.0));
    assert_true(sx_clampr(-R_INF, SX_R(-1.0), SX_R(2.0)) == SX_R(-1.0));
    assert_true(sx_clampr(SX_R(5.0), -R_INF, R_INF) == SX_R(5.0));
    /* NaN is not clamped (both comparisons fail): it comes back as NaN. */
    assert_true(is_nan(sx_clampr(R_NAN, SX_R(-1.0), SX_R(2.0))));
}

static void clamp_with_crossed_bounds_returns_lo(void **state) {
    (void)state;
    /* lo = 3 > hi = 1: "lo wins" whatever a is. */
    assert_true(sx_clampr(SX_R(0.0), SX_R(3.0), SX_R(1.0)) == SX_R(3.0));
    assert_true(sx_clampr(SX_R(2.0), SX_R(3.0), SX_R(1.0)) == SX_R(3.0));
    assert_true(sx_clampr(SX_R(5.0), SX_R(3.0), SX_R(1.0)) == SX_R(3.0));
}

static void is_finite_rejects_nan_and_both_infinities(void **state) {
    (void)state;
    assert_true(sx_is_finite(SX_R(0.0)));
    assert_true(sx_is_finite(-SX_R(0.0)));
    assert_true(sx_is_finite(SX_R(-12.5)));
    assert_true(sx_is_finite(SX_REAL_MAX));
    assert_true(sx_is_finite(-SX_REAL_MAX));
    assert_true(sx_is_finite(SX_REAL_EPSILON * SX_REAL_EPSILON * SX_REAL_EPSILON));
    assert_false(sx_is_finite(R_NAN));
    assert_false(sx_is_finite(R_INF));
    assert_false(sx_is_finite(-R_INF));
    assert_false(sx_is_finite(SX_REAL_MAX * SX_R(2.0)));
}

static void sqrt_sin_cos_atan2_floor_match_libm(void **state) {
    (void)state;
    assert_near(sx_sqrt(SX_R(2.0)), sqrt(2.0), SX_TEST_EPS);
    assert_near(sx_sin(SX_R(0.5)), sin(0.5), SX_TEST_EPS);
    assert_near(sx_cos(SX_R(0.5)), cos(0.5), SX_TEST_EPS);
    assert_near(sx_atan2(SX_R(1.0), SX_R(-1.0)), 0.75 * PI_D, SX_TEST_EPS);
    assert_true(sx_floor(SX_R(-1.5)) == SX_R(-2.0));
    assert_true(sx_floor(SX_R(2.75)) == SX_R(2.0));
}

/* ---- sx_vec2 ------------------------------------------------------------- */

static void vec2_arithmetic_matches_hand_values(void **state) {
    sx_vec2 a = sx_v2(SX_R(1.0), SX_R(-2.0)), b = sx_v2(SX_R(3.0), SX_R(0.5));
    (void)state;
    assert_true(a.x == SX_R(1.0) && a.y == SX_R(-2.0));
    assert_vec2_near(sx_v2_zero(), sx_v2(SX_R(0.0), SX_R(0.0)), 0.0);
    assert_vec2_near(sx_add(a, b), sx_v2(SX_R(4.0), SX_R(-1.5)), 0.0);
    assert_vec2_near(sx_sub(a, b), sx_v2(SX_R(-2.0), SX_R(-2.5)), 0.0);
    assert_vec2_near(sx_neg(a), sx_v2(SX_R(-1.0), SX_R(2.0)), 0.0);
    assert_vec2_near(sx_scale(a, SX_R(-1.5)), sx_v2(SX_R(-1.5), SX_R(3.0)), 0.0);
    assert_vec2_near(sx_mul_add(a, SX_R(2.0), b), sx_v2(SX_R(7.0), SX_R(-1.0)), 0.0);
    assert_vec2_near(sx_mul_sub(a, SX_R(2.0), b), sx_v2(SX_R(-5.0), SX_R(-3.0)), 0.0);
    assert_vec2_near(sx_mul_cw(a, b), sx_v2(SX_R(3.0), SX_R(-1.0)), 0.0);
}

static void vec2_add_sub_neg_obey_the_group_laws(void **state) {
    sx_test_rng rng = sx_test_rng_make(101);
    int k;
    (void)state;
    for (k = 0; k < 1000; ++k) {
        sx_vec2 a = rnd_vec(&rng, -10.0, 10.0), b = rnd_vec(&rng, -10.0, 10.0);
        sx_real s = sx_test_rng_range(&rng, -3.0, 3.0);
        double tol = 30.0 * SX_TEST_EPS;
        assert_vec2_near(sx_add(a, b), sx_add(b, a), 0.0);
        assert_vec2_near(sx_sub(sx_add(a, b), b), a, tol);
        assert_vec2_near(sx_add(a, sx_neg(a)), sx_v2_zero(), 0.0);
        assert_vec2_near(sx_sub(a, b), sx_add(a, sx_neg(b)), 0.0);
        assert_vec2_near(sx_mul_add(a, s, b), sx_add(a, sx_scale(b, s)), 0.0);
        assert_vec2_near(sx_mul_sub(a, s, b), sx_sub(a, sx_scale(b, s)), 0.0);
        assert_vec2_near(sx_mul_cw(a, b), sx_mul_cw(b, a), 0.0);
    }
}

static void dot_and_cross_match_hand_values(void **state) {
    sx_vec2 a = sx_v2(SX_R(2.0), SX_R(3.0)), b = sx_v2(SX_R(-1.0), SX_R(4.0));
    sx_vec2 ex = sx_v2(SX_R(1.0), SX_R(0.0)), ey = sx_v2(SX_R(0.0), SX_R(1.0));
    (void)state;
    assert_true(sx_dot(a, b) == SX_R(10.0));
    assert_true(sx_cross(a, b) == SX_R(11.0));
    assert_true(sx_cross(b, a) == SX_R(-11.0));
    assert_true(sx_cross(a, a) == SX_R(0.0));
    assert_true(sx_dot(ex, ey) == SX_R(0.0));
    /* y is a quarter turn counter-clockwise of x: positive. */
    assert_true(sx_cross(ex, ey) == SX_R(1.0));
    assert_true(sx_cross(ey, ex) == SX_R(-1.0));
}

static void cross_is_positive_when_b_is_counter_clockwise_of_a(void **state) {
    sx_test_rng rng = sx_test_rng_make(102);
    int k;
    (void)state;
    for (k = 0; k < 1000; ++k) {
        sx_real r = sx_test_rng_range(&rng, 0.5, 5.0);
        sx_real t = sx_test_rng_range(&rng, -PI_D, PI_D);
        sx_real turn = sx_test_rng_range(&rng, 0.05, PI_D - 0.05);
        sx_vec2 a = sx_scale(sx_v2(sx_cos(t), sx_sin(t)), r);
        sx_vec2 b = sx_rotate(sx_rot_make(turn), sx_v2(SX_R(2.0) * a.x, SX_R(2.0) * a.y));
        double r2 = 2.0 * (double)r * (double)r;
        assert_true(sx_cross(a, b) > SX_R(0.0));
        assert_true(sx_cross(b, a) < SX_R(0.0));
        /* |a||b| sin(turn) and |a||b| cos(turn). */
        assert_near(sx_cross(a, b), r2 * sin((double)turn), 50.0 * SX_TEST_EPS);
        assert_near(sx_dot(a, b), r2 * cos((double)turn), 50.0 * SX_TEST_EPS);
    }
}

static void cross_vs_and_cross_sv_are_the_3d_cross_products(void **state) {
    sx_vec2 v = sx_v2(SX_R(2.0), SX_R(3.0));
    sx_test_rng rng = sx_test_rng_make(103);
    int k;
    (void)state;
    /* v x (s z) = (s vy, -s vx); (s z) x v = (-s vy, s vx). */
    assert_vec2_near(sx_cross_vs(v, SX_R(2.0)), sx_v2(SX_R(6.0), SX_R(-4.0)), 0.0);
    assert_vec2_near(sx_cross_sv(SX_R(2.0), v), sx_v2(SX_R(-6.0), SX_R(4.0)), 0.0);
    /* An arm along +x spinning counter-clockwise: its tip moves along +y. */
    assert_vec2_near(sx_cross_sv(SX_R(3.0), sx_v2(SX_R(2.0), SX_R(0.0))),
                     sx_v2(SX_R(0.0), SX_R(6.0)), 0.0);
    for (k = 0; k < 500; ++k) {
        sx_vec2 arm = rnd_vec(&rng, -2.0, 2.0), w = rnd_vec(&rng, -2.0, 2.0);
        sx_real omega = sx_test_rng_range(&rng, -3.0, 3.0);
        sx_real dt = SX_R(1e-3);
        sx_vec2 tip = sx_cross_sv(omega, arm);
        sx_vec2 moved = sx_rotate(sx_rot_make(omega * dt), arm);
        sx_vec2 fd = sx_scale(sx_sub(moved, arm), SX_R(1.0) / dt);
        assert_vec2_near(tip, sx_neg(sx_cross_vs(arm, omega)), 0.0);
        assert_vec2_near(tip, sx_scale(sx_perp(arm), omega), 0.0);
        /* Finite difference of the rotating arm: O(dt) truncation plus the
         * float rounding of a difference divided by dt. */
        assert_vec2_near(fd, tip, 0.02 + (double)(4.0f * FLT_EPSILON) * 4.0 / (double)dt);
        /* Triple-product identity: (omega z x arm) . w = omega cross(arm, w). */
        assert_near(sx_dot(tip, w), (double)omega * (double)sx_cross(arm, w), 20.0 * SX_TEST_EPS);
    }
}

static void perp_is_a_counter_clockwise_quarter_turn(void **state) {
    sx_test_rng rng = sx_test_rng_make(104);
    int k;
    (void)state;
    assert_vec2_near(sx_perp(sx_v2(SX_R(1.0), SX_R(0.0))), sx_v2(SX_R(0.0), SX_R(1.0)), 0.0);
    assert_vec2_near(sx_perp(sx_v2(SX_R(2.0), SX_R(3.0))), sx_v2(SX_R(-3.0), SX_R(2.0)), 0.0);
    for (k = 0; k < 500; ++k) {
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        assert_vec2_near(sx_perp(sx_perp(v)), sx_neg(v), 0.0);
        assert_true(sx_dot(v, sx_perp(v)) == SX_R(0.0));
        assert_near(sx_cross(v, sx_perp(v)), sx_length_sq(v), 0.0);
        assert_vec2_near(sx_perp(v), sx_rotate(sx_rot_make(SX_R(0.5) * SX_PI), v),
                         100.0 * SX_TEST_EPS);
    }
}

static void length_and_distance_match_hand_values(void **state) {
    sx_test_rng rng = sx_test_rng_make(105);
    int k;
    (void)state;
    assert_true(sx_length(sx_v2(SX_R(3.0), SX_R(-4.0))) == SX_R(5.0));
    assert_true(sx_length_sq(sx_v2(SX_R(3.0), SX_R(-4.0))) == SX_R(25.0));
    assert_true(sx_length(sx_v2_zero()) == SX_R(0.0));
    assert_true(sx_distance(sx_v2(SX_R(1.0), SX_R(1.0)), sx_v2(SX_R(4.0), SX_R(5.0))) == SX_R(5.0));
    assert_true(sx_distance_sq(sx_v2(SX_R(1.0), SX_R(1.0)), sx_v2(SX_R(4.0), SX_R(5.0))) ==
                SX_R(25.0));
    for (k = 0; k < 1000; ++k) {
        sx_vec2 a = rnd_vec(&rng, -100.0, 100.0), b = rnd_vec(&rng, -100.0, 100.0);
        double l = (double)sx_length(a);
        assert_near(l * l, sx_length_sq(a), SX_TEST_EPS * (double)sx_length_sq(a));
        assert_true(sx_distance(a, b) == sx_distance(b, a));
        assert_true(sx_distance_sq(a, b) == sx_length_sq(sx_sub(a, b)));
        assert_true(sx_length(a) >= sx_absr(a.x) && sx_length(a) >= sx_absr(a.y));
    }
}

static void normalize_gives_a_unit_vector_and_reports_the_length(void **state) {
    sx_test_rng rng = sx_test_rng_make(106);
    sx_real len = SX_R(-1.0);
    int k;
    (void)state;
    assert_vec2_near(sx_normalize_len(sx_v2(SX_R(3.0), SX_R(4.0)), &len),
                     sx_v2(SX_R(0.6), SX_R(0.8)), SX_TEST_EPS);
    assert_near(len, 5.0, SX_TEST_EPS);
    assert_vec2_near(sx_normalize(sx_v2(SX_R(0.0), SX_R(-7.0))), sx_v2(SX_R(0.0), SX_R(-1.0)), 0.0);
    for (k = 0; k < 1000; ++k) {
        sx_vec2 v = rnd_vec(&rng, -100.0, 100.0);
        sx_vec2 u = sx_normalize_len(v, &len);
        assert_true(sx_is_normalized(u));
        assert_near(len, sx_length(v), 0.0);
        assert_vec2_near(sx_scale(u, len), v, 100.0 * SX_TEST_EPS);
        assert_vec2_near(sx_normalize(v), u, 0.0);
    }
}

static void normalize_of_zero_tiny_or_non_finite_gives_zero_and_length_zero(void **state) {
    sx_real len;
    sx_vec2 u;
    sx_vec2 bad[6];
    int k;
    (void)state;
    bad[0] = sx_v2_zero();
    /* At and below the documented threshold length <= SX_REAL_EPSILON. */
    bad[1] = sx_v2(SX_REAL_EPSILON, SX_R(0.0));
    bad[2] = sx_v2(SX_R(1e-20), SX_R(-1e-20));
    bad[3] = sx_v2(R_NAN, SX_R(1.0));
    bad[4] = sx_v2(SX_R(1.0), R_INF);
    bad[5] = sx_v2(-R_INF, -R_INF);
    for (k = 0; k < 6; ++k) {
        len = SX_R(-1.0);
        u = sx_normalize_len(bad[k], &len);
        assert_true(u.x == SX_R(0.0) && u.y == SX_R(0.0));
        assert_true(len == SX_R(0.0));
        u = sx_normalize_len(bad[k], NULL);
        assert_true(u.x == SX_R(0.0) && u.y == SX_R(0.0));
        assert_false(sx_is_normalized(u));
    }
    /* Just above the threshold there is a direction again. */
    u = sx_normalize_len(sx_v2(SX_R(0.0), SX_R(2.0) * SX_REAL_EPSILON), &len);
    assert_vec2_near(u, sx_v2(SX_R(0.0), SX_R(1.0)), 0.0);
    assert_true(len == SX_R(2.0) * SX_REAL_EPSILON);
}

/* A huge but finite vector has a finite length and a direction, even where
 * the naive x*x + y*y overflows (1e30 squared is 1e60 > FLT_MAX): normalize
 * gives the direction and the true length. Only a vector whose length itself
 * exceeds SX_REAL_MAX counts as "not finite" and gives zero. sx_length on its
 * own stays the plain fast formula (it is not promised to survive overflow). */
static void normalize_of_a_huge_vector_does_not_overflow(void **state) {
#ifdef SX_DOUBLE
    const sx_real big = 1e300;
#else
    const sx_real big = 1e30f;
#endif
    sx_real len = SX_R(-1.0);
    sx_vec2 u;
    (void)state;
    u = sx_normalize_len(sx_v2(big, -big), &len);
    assert_vec2_near(u, sx_v2(SX_R(0.70710678118654752), SX_R(-0.70710678118654752)), SX_TEST_EPS);
    assert_true(sx_is_normalized(u));
    assert_near((double)len / (double)big, sqrt(2.0), SX_TEST_EPS);
    u = sx_normalize_len(sx_v2(SX_R(0.0), SX_R(0.5) * SX_REAL_MAX), &len);
    assert_vec2_near(u, sx_v2(SX_R(0.0), SX_R(1.0)), 0.0);
    assert_true(len == SX_R(0.5) * SX_REAL_MAX);
    assert_vec2_near(sx_normalize(sx_v2(SX_R(3.0) * big, SX_R(4.0) * big)),
                     sx_v2(SX_R(0.6), SX_R(0.8)), SX_TEST_EPS);
    /* |(MAX, MAX)| = sqrt(2) MAX is not representable: documented zero. */
    u = sx_normalize_len(sx_v2(SX_REAL_MAX, SX_REAL_MAX), &len);
    assert_true(u.x == SX_R(0.0) && u.y == SX_R(0.0) && len == SX_R(0.0));
}

static void is_normalized_accepts_lengths_within_100_epsilon_of_one(void **state) {
    sx_test_rng rng = sx_test_rng_make(107);
    int k;
    (void)state;
    assert_true(sx_is_normalized(sx_v2(SX_R(1.0), SX_R(0.0))));
    assert_true(sx_is_normalized(sx_v2(SX_R(0.6), SX_R(-0.8))));
    /* |v| = 1 + 50 eps and 1 - 50 eps: inside. 1 + 150 eps: outside. */
    assert_true(sx_is_normalized(sx_v2(SX_R(1.0) + SX_R(50.0) * SX_REAL_EPSILON, SX_R(0.0))));
    assert_true(sx_is_normalized(sx_v2(SX_R(0.0), SX_R(1.0) - SX_R(50.0) * SX_REAL_EPSILON)));
    assert_false(sx_is_normalized(sx_v2(SX_R(1.0) + SX_R(150.0) * SX_REAL_EPSILON, SX_R(0.0))));
    assert_false(sx_is_normalized(sx_v2(SX_R(0.0), SX_R(1.0) - SX_R(150.0) * SX_REAL_EPSILON)));
    assert_false(sx_is_normalized(sx_v2(SX_R(0.5), SX_R(0.5))));
    assert_false(sx_is_normalized(sx_v2_zero()));
    assert_false(sx_is_normalized(sx_v2(R_NAN, SX_R(0.0))));
    assert_false(sx_is_normalized(sx_v2(R_INF, SX_R(0.0))));
    for (k = 0; k < 500; ++k) {
        sx_real t = sx_test_rng_range(&rng, -PI_D, PI_D);
        assert_true(sx_is_normalized(sx_v2(sx_cos(t), sx_sin(t))));
    }
}

static void lerp_interpolates_and_extrapolates(void **state) {
    sx_vec2 a = sx_v2(SX_R(1.0), SX_R(2.0)), b = sx_v2(SX_R(5.0), SX_R(-2.0));
    (void)state;
    assert_vec2_near(sx_lerp(a, b, SX_R(0.0)), a, 0.0);
    assert_vec2_near(sx_lerp(a, b, SX_R(1.0)), b, 0.0);
    assert_vec2_near(sx_lerp(a, b, SX_R(0.25)), sx_v2(SX_R(2.0), SX_R(1.0)), 0.0);
    assert_vec2_near(sx_lerp(a, b, SX_R(0.5)), sx_v2(SX_R(3.0), SX_R(0.0)), 0.0);
    assert_vec2_near(sx_lerp(a, b, SX_R(2.0)), sx_v2(SX_R(9.0), SX_R(-6.0)), 0.0);
    assert_vec2_near(sx_lerp(a, b, SX_R(-1.0)), sx_v2(SX_R(-3.0), SX_R(6.0)), 0.0);
}

static void vmin_vmax_vabs_vclamp_work_per_component(void **state) {
    sx_vec2 a = sx_v2(SX_R(1.0), SX_R(-4.0)), b = sx_v2(SX_R(-2.0), SX_R(3.0));
    sx_vec2 lo = sx_v2(SX_R(-1.0), SX_R(-1.0)), hi = sx_v2(SX_R(2.0), SX_R(0.5));
    (void)state;
    assert_vec2_near(sx_vmin(a, b), sx_v2(SX_R(-2.0), SX_R(-4.0)), 0.0);
    assert_vec2_near(sx_vmax(a, b), sx_v2(SX_R(1.0), SX_R(3.0)), 0.0);
    assert_vec2_near(sx_vabs(a), sx_v2(SX_R(1.0), SX_R(4.0)), 0.0);
    assert_vec2_near(sx_vclamp(a, lo, hi), sx_v2(SX_R(1.0), SX_R(-1.0)), 0.0);
    assert_vec2_near(sx_vclamp(b, lo, hi), sx_v2(SX_R(-1.0), SX_R(0.5)), 0.0);
    assert_vec2_near(sx_vclamp(sx_v2(SX_R(0.0), SX_R(0.0)), lo, hi), sx_v2_zero(), 0.0);
}

static void approx_equal_is_an_inclusive_per_component_tolerance(void **state) {
    sx_vec2 a = sx_v2(SX_R(1.0), SX_R(2.0));
    (void)state;
    assert_true(sx_approx_equal(a, a, SX_R(0.0)));
    assert_true(sx_approx_equal(a, sx_v2(SX_R(1.5), SX_R(2.0)), SX_R(0.5)));
    assert_true(sx_approx_equal(a, sx_v2(SX_R(1.0), SX_R(1.5)), SX_R(0.5)));
    assert_false(sx_approx_equal(a, sx_v2(SX_R(1.5), SX_R(2.0)), SX_R(0.25)));
    assert_false(sx_approx_equal(a, sx_v2(SX_R(1.0), SX_R(2.5)), SX_R(0.25)));
    /* Per component, not Euclidean: both off by 0.5 still passes tol 0.5. */
    assert_true(sx_approx_equal(a, sx_v2(SX_R(1.5), SX_R(2.5)), SX_R(0.5)));
    assert_false(sx_approx_equal(a, sx_v2(R_NAN, SX_R(2.0)), SX_R(1.0)));
    assert_false(sx_approx_equal(a, sx_v2(SX_R(1.0), R_INF), SX_R(1.0)));
}

static void vec2_is_finite_checks_both_components(void **state) {
    (void)state;
    assert_true(sx_vec2_is_finite(sx_v2(SX_R(1.0), -SX_REAL_MAX)));
    assert_false(sx_vec2_is_finite(sx_v2(R_NAN, SX_R(0.0))));
    assert_false(sx_vec2_is_finite(sx_v2(SX_R(0.0), R_NAN)));
    assert_false(sx_vec2_is_finite(sx_v2(R_INF, SX_R(0.0))));
    assert_false(sx_vec2_is_finite(sx_v2(SX_R(0.0), -R_INF)));
}

/* ---- sx_rot -------------------------------------------------------------- */

static void rot_make_matches_hand_values(void **state) {
    sx_rot q;
    (void)state;
    q = sx_rot_identity();
    assert_true(q.c == SX_R(1.0) && q.s == SX_R(0.0));
    q = sx_rot_make(SX_R(0.0));
    assert_true(q.c == SX_R(1.0) && q.s == SX_R(0.0));
    q = sx_rot_make(SX_PI / SX_R(6.0));
    assert_near(q.c, sqrt(3.0) / 2.0, SX_TEST_EPS);
    assert_near(q.s, 0.5, SX_TEST_EPS);
    q = sx_rot_make(SX_R(-0.5) * SX_PI);
    assert_near(q.c, 0.0, SX_TEST_EPS);
    assert_near(q.s, -1.0, SX_TEST_EPS);
}

static void rot_angle_round_trips_over_minus_pi_to_pi(void **state) {
    sx_test_rng rng = sx_test_rng_make(201);
    sx_rot q;
    sx_real a;
    int k;
    (void)state;
    for (k = 0; k < 2000; ++k) {
        sx_real t = sx_test_rng_range(&rng, -PI_D, PI_D);
        a = sx_rot_angle(sx_rot_make(t));
        assert_near(angle_diff((double)a, (double)t), 0.0, SX_TEST_EPS);
        assert_true(a > -SX_PI && a <= SX_PI);
    }
    /* Angles outside the range come back wrapped. */
    assert_near(sx_rot_angle(sx_rot_make(SX_R(1.5) * SX_PI)), -0.5 * PI_D, SX_TEST_EPS);
    assert_near(sx_rot_angle(sx_rot_make(SX_R(-2.5) * SX_PI)), -0.5 * PI_D, SX_TEST_EPS);
    /* The half turn is +pi, never -pi, whichever sign the sine rounds to. */
    a = sx_rot_angle(sx_rot_make(SX_PI));
    assert_near(angle_diff((double)a, PI_D), 0.0, SX_TEST_EPS);
    assert_true(a > -SX_PI && a <= SX_PI);
    a = sx_rot_angle(sx_rot_make(-SX_PI));
    assert_true(a > -SX_PI && a <= SX_PI);
    q.c = SX_R(-1.0);
    q.s = -SX_R(0.0);
    assert_true(sx_rot_angle(q) == SX_PI);
    q.s = SX_R(0.0);
    assert_true(sx_rot_angle(q) == SX_PI);
    assert_true(sx_rot_angle(sx_rot_inv(q)) == SX_PI);
}

static void rot_normalize_rescales_and_zero_or_non_finite_gives_identity(void **state) {
    sx_rot q, r;
    sx_rot bad[4];
    int k;
    (void)state;
    q.c = SX_R(3.0);
    q.s = SX_R(-4.0);
    r = sx_rot_normalize(q);
    assert_near(r.c, 0.6, SX_TEST_EPS);
    assert_near(r.s, -0.8, SX_TEST_EPS);
    q.c = SX_R(1e-3);
    q.s = SX_R(0.0);
    r = sx_rot_normalize(q);
    assert_true(r.c == SX_R(1.0) && r.s == SX_R(0.0));
    bad[0].c = SX_R(0.0);
    bad[0].s = SX_R(0.0);
    bad[1].c = R_NAN;
    bad[1].s = SX_R(1.0);
    bad[2].c = SX_R(0.0);
    bad[2].s = R_INF;
    bad[3].c = R_NAN;
    bad[3].s = R_NAN;
    for (k = 0; k < 4; ++k) {
        r = sx_rot_normalize(bad[k]);
        assert_true(r.c == SX_R(1.0) && r.s == SX_R(0.0));
    }
    /* Huge but finite: still a direction, like sx_normalize. */
    q.c = SX_R(-0.5) * SX_REAL_MAX;
    q.s = SX_R(0.5) * SX_REAL_MAX;
    r = sx_rot_normalize(q);
    assert_near(r.c, -sqrt(0.5), SX_TEST_EPS);
    assert_near(r.s, sqrt(0.5), SX_TEST_EPS);
}

static void rot_integrate_small_steps_add_up_to_the_angle(void **state) {
    const int n = 1000;
    const double total = 1.2;
    sx_real d = (sx_real)(total / n);
    /* Each first-order step turns by atan(d) instead of d: short by d^3/3. */
    double truncation = n * (double)d * (double)d * (double)d / 3.0;
    double rounding = n * 4.0 * EPS_D;
    sx_rot q = sx_rot_make(SX_R(0.3)), back;
    int k;
    (void)state;
    /* One step by hand: (1, 0) + d (0, 1), renormalised: angle atan(d). */
    back = sx_rot_integrate(sx_rot_identity(), SX_R(0.1));
    assert_near(sx_rot_angle(back), atan(0.1), SX_TEST_EPS);
    assert_near(back.c, 1.0 / sqrt(1.01), SX_TEST_EPS);
    for (k = 0; k < n; ++k)
        q = sx_rot_integrate(q, d);
    assert_true(sx_is_normalized(sx_v2(q.c, q.s)));
    assert_near(sx_rot_angle(q), 0.3 + total - truncation, truncation + rounding);
    back = q;
    for (k = 0; k < n; ++k)
        back = sx_rot_integrate(back, -d);
    assert_near(sx_rot_angle(back), 0.3, 2.0 * (truncation + rounding));
    assert_true(sx_is_normalized(sx_v2(back.c, back.s)));
    /* A zero step changes nothing but the rounding of the renormalisation. */
    back = sx_rot_integrate(q, SX_R(0.0));
    assert_near(back.c, q.c, SX_TEST_EPS);
    assert_near(back.s, q.s, SX_TEST_EPS);
}

static void rotate_and_inv_rotate_undo_each_other(void **state) {
    sx_test_rng rng = sx_test_rng_make(202);
    sx_rot quarter = sx_rot_make(SX_R(0.5) * SX_PI);
    int k;
    (void)state;
    assert_vec2_near(sx_rotate(quarter, sx_v2(SX_R(1.0), SX_R(0.0))), sx_v2(SX_R(0.0), SX_R(1.0)),
                     SX_TEST_EPS);
    assert_vec2_near(sx_rotate(quarter, sx_v2(SX_R(2.0), SX_R(3.0))), sx_v2(SX_R(-3.0), SX_R(2.0)),
                     4.0 * SX_TEST_EPS);
    assert_vec2_near(sx_inv_rotate(quarter, sx_v2(SX_R(1.0), SX_R(0.0))),
                     sx_v2(SX_R(0.0), SX_R(-1.0)), SX_TEST_EPS);
    for (k = 0; k < 1000; ++k) {
        sx_rot q = sx_rot_make(sx_test_rng_range(&rng, -PI_D, PI_D));
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        double tol = 20.0 * SX_TEST_EPS;
        assert_vec2_near(sx_inv_rotate(q, sx_rotate(q, v)), v, tol);
        assert_vec2_near(sx_rotate(q, sx_inv_rotate(q, v)), v, tol);
        assert_near(sx_length(sx_rotate(q, v)), sx_length(v), tol);
        assert_vec2_near(sx_inv_rotate(q, v), sx_rotate(sx_rot_inv(q), v), 0.0);
    }
}

static void rot_mul_composes_by_adding_angles(void **state) {
    sx_test_rng rng = sx_test_rng_make(203);
    sx_rot h = sx_rot_mul(sx_rot_make(SX_R(0.5) * SX_PI), sx_rot_make(SX_R(0.5) * SX_PI));
    int k;
    (void)state;
    assert_near(h.c, -1.0, SX_TEST_EPS);
    assert_near(h.s, 0.0, SX_TEST_EPS);
    for (k = 0; k < 1000; ++k) {
        sx_real a = sx_test_rng_range(&rng, -PI_D, PI_D), b = sx_test_rng_range(&rng, -PI_D, PI_D);
        sx_rot qa = sx_rot_make(a), qb = sx_rot_make(b);
        sx_rot ab = sx_rot_mul(qa, qb);
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        assert_near(angle_diff((double)sx_rot_angle(ab), (double)a + (double)b), 0.0,
                    4.0 * SX_TEST_EPS);
        assert_true(sx_is_normalized(sx_v2(ab.c, ab.s)));
        /* q * r rotates by r first, then by q (commutative in 2D, but the
         * point images must agree with the nested rotations). */
        assert_vec2_near(sx_rotate(ab, v), sx_rotate(qa, sx_rotate(qb, v)), 40.0 * SX_TEST_EPS);
    }
}

static void rot_inv_mul_gives_the_relative_rotation_and_rot_inv_undoes(void **state) {
    sx_test_rng rng = sx_test_rng_make(204);
    sx_rot q = sx_rot_make(SX_R(0.25) * SX_PI), r;
    int k;
    (void)state;
    r = sx_rot_inv(q);
    assert_near(r.c, sqrt(0.5), SX_TEST_EPS);
    assert_near(r.s, -sqrt(0.5), SX_TEST_EPS);
    for (k = 0; k < 1000; ++k) {
        sx_real a = sx_test_rng_range(&rng, -PI_D, PI_D), b = sx_test_rng_range(&rng, -PI_D, PI_D);
        sx_rot qa = sx_rot_make(a), qb = sx_rot_make(b);
        sx_rot rel = sx_rot_inv_mul(qa, qb), ref = sx_rot_mul(sx_rot_inv(qa), qb);
        sx_rot one = sx_rot_mul(qa, sx_rot_inv(qa));
        assert_near(rel.c, ref.c, 0.0);
        assert_near(rel.s, ref.s, 0.0);
        assert_near(angle_diff((double)sx_rot_angle(rel), (double)b - (double)a), 0.0,
                    4.0 * SX_TEST_EPS);
        /* qa * (qa^-1 qb) = qb */
        ref = sx_rot_mul(qa, rel);
        assert_near(ref.c, qb.c, 4.0 * SX_TEST_EPS);
        assert_near(ref.s, qb.s, 4.0 * SX_TEST_EPS);
        assert_near(one.c, 1.0, SX_TEST_EPS);
        assert_near(one.s, 0.0, SX_TEST_EPS);
        assert_true(sx_rot_inv(sx_rot_inv(qa)).s == qa.s);
    }
}

/* ---- sx_xform ------------------------------------------------------------ */

static void xform_make_places_the_origin_and_turns(void **state) {
    sx_xform x = sx_xform_make(sx_v2(SX_R(2.0), SX_R(3.0)), SX_R(0.5) * SX_PI);
    sx_xform id = sx_xform_identity();
    sx_vec2 v = sx_v2(SX_R(-1.5), SX_R(4.0));
    (void)state;
    assert_vec2_near(x.p, sx_v2(SX_R(2.0), SX_R(3.0)), 0.0);
    assert_near(x.q.c, 0.0, SX_TEST_EPS);
    assert_near(x.q.s, 1.0, SX_TEST_EPS);
    assert_vec2_near(sx_xform_point(x, sx_v2_zero()), x.p, 0.0);
    assert_vec2_near(sx_xform_point(x, sx_v2(SX_R(1.0), SX_R(0.0))), sx_v2(SX_R(2.0), SX_R(4.0)),
                     SX_TEST_EPS);
    assert_vec2_near(sx_xform_inv_point(x, sx_v2(SX_R(2.0), SX_R(4.0))),
                     sx_v2(SX_R(1.0), SX_R(0.0)), SX_TEST_EPS);
    /* Directions ignore the translation. */
    assert_vec2_near(sx_xform_vector(x, sx_v2(SX_R(1.0), SX_R(0.0))), sx_v2(SX_R(0.0), SX_R(1.0)),
                     SX_TEST_EPS);
    assert_vec2_near(sx_xform_inv_vector(x, sx_v2(SX_R(0.0), SX_R(1.0))),
                     sx_v2(SX_R(1.0), SX_R(0.0)), SX_TEST_EPS);
    assert_vec2_near(sx_xform_point(id, v), v, 0.0);
    assert_vec2_near(sx_xform_inv_point(id, v), v, 0.0);
    assert_vec2_near(sx_xform_vector(id, v), v, 0.0);
}

static void xform_point_and_vector_round_trip_through_their_inverses(void **state) {
    sx_test_rng rng = sx_test_rng_make(301);
    int k;
    (void)state;
    for (k = 0; k < 1000; ++k) {
        sx_xform x = rnd_xform(&rng);
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        double tol = 40.0 * SX_TEST_EPS;
        assert_vec2_near(sx_xform_inv_point(x, sx_xform_point(x, v)), v, tol);
        assert_vec2_near(sx_xform_point(x, sx_xform_inv_point(x, v)), v, tol);
        assert_vec2_near(sx_xform_inv_vector(x, sx_xform_vector(x, v)), v, tol);
        assert_vec2_near(sx_xform_vector(x, v), sx_rotate(x.q, v), 0.0);
        /* Distances are preserved (rigid). */
        assert_near(sx_distance(sx_xform_point(x, v), x.p), sx_length(v), tol);
    }
}

static void xform_mul_applies_b_first(void **state) {
    sx_xform a = sx_xform_make(sx_v2(SX_R(1.0), SX_R(0.0)), SX_R(0.5) * SX_PI);
    sx_xform b = sx_xform_make(sx_v2(SX_R(2.0), SX_R(0.0)), SX_R(0.0));
    sx_xform ab = sx_xform_mul(a, b), ba = sx_xform_mul(b, a);
    sx_test_rng rng = sx_test_rng_make(302);
    int k;
    (void)state;
    /* A(B(0)) = A((2, 0)) = (1, 0) + quarter turn of (2, 0) = (1, 2). */
    assert_vec2_near(ab.p, sx_v2(SX_R(1.0), SX_R(2.0)), SX_TEST_EPS);
    /* B(A(0)) = B((1, 0)) = (3, 0): the order matters. */
    assert_vec2_near(ba.p, sx_v2(SX_R(3.0), SX_R(0.0)), SX_TEST_EPS);
    assert_near(sx_rot_angle(ab.q), 0.5 * PI_D, SX_TEST_EPS);
    assert_vec2_near(sx_xform_point(ab, sx_v2(SX_R(1.0), SX_R(0.0))), sx_v2(SX_R(1.0), SX_R(3.0)),
                     2.0 * SX_TEST_EPS);
    for (k = 0; k < 1000; ++k) {
        sx_xform x = rnd_xform(&rng), y = rnd_xform(&rng), z = rnd_xform(&rng);
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        double tol = 100.0 * SX_TEST_EPS;
        sx_xform l = sx_xform_mul(sx_xform_mul(x, y), z), r = sx_xform_mul(x, sx_xform_mul(y, z));
        assert_vec2_near(sx_xform_point(sx_xform_mul(x, y), v),
                         sx_xform_point(x, sx_xform_point(y, v)), tol);
        assert_vec2_near(sx_xform_vector(sx_xform_mul(x, y), v),
                         sx_xform_vector(x, sx_xform_vector(y, v)), tol);
        assert_vec2_near(l.p, r.p, tol);
        assert_near(l.q.c, r.q.c, 4.0 * SX_TEST_EPS);
        assert_near(l.q.s, r.q.s, 4.0 * SX_TEST_EPS);
    }
}

static void xform_inv_mul_equals_mul_of_the_inverse(void **state) {
    sx_test_rng rng = sx_test_rng_make(303);
    int k;
    (void)state;
    for (k = 0; k < 1000; ++k) {
        sx_xform a = rnd_xform(&rng), b = rnd_xform(&rng);
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        sx_xform rel = sx_xform_inv_mul(a, b), ref = sx_xform_mul(sx_xform_invert(a), b);
        double tol = 100.0 * SX_TEST_EPS;
        assert_vec2_near(rel.p, ref.p, tol);
        assert_near(rel.q.c, ref.q.c, 2.0 * SX_TEST_EPS);
        assert_near(rel.q.s, ref.q.s, 2.0 * SX_TEST_EPS);
        /* B's local point seen from A's frame. */
        assert_vec2_near(sx_xform_point(rel, v), sx_xform_inv_point(a, sx_xform_point(b, v)), tol);
        /* a * (a^-1 b) = b */
        ref = sx_xform_mul(a, rel);
        assert_vec2_near(ref.p, b.p, tol);
    }
}

static void xform_invert_round_trips(void **state) {
    sx_test_rng rng = sx_test_rng_make(304);
    sx_xform x = sx_xform_make(sx_v2(SX_R(1.0), SX_R(2.0)), SX_R(0.5) * SX_PI);
    sx_xform inv = sx_xform_invert(x);
    int k;
    (void)state;
    /* x maps v to (1 - v.y, 2 + v.x); the inverse maps w to (w.y - 2, 1 - w.x). */
    assert_vec2_near(inv.p, sx_v2(SX_R(-2.0), SX_R(1.0)), SX_TEST_EPS);
    assert_near(sx_rot_angle(inv.q), -0.5 * PI_D, SX_TEST_EPS);
    for (k = 0; k < 1000; ++k) {
        sx_xform a = rnd_xform(&rng);
        sx_xform one = sx_xform_mul(a, sx_xform_invert(a));
        sx_xform twice = sx_xform_invert(sx_xform_invert(a));
        sx_vec2 w = rnd_vec(&rng, -10.0, 10.0);
        double tol = 100.0 * SX_TEST_EPS;
        assert_vec2_near(one.p, sx_v2_zero(), tol);
        assert_near(one.q.c, 1.0, 2.0 * SX_TEST_EPS);
        assert_near(one.q.s, 0.0, 2.0 * SX_TEST_EPS);
        one = sx_xform_mul(sx_xform_invert(a), a);
        assert_vec2_near(one.p, sx_v2_zero(), tol);
        assert_vec2_near(twice.p, a.p, tol);
        assert_true(twice.q.c == a.q.c && twice.q.s == a.q.s);
        assert_vec2_near(sx_xform_point(sx_xform_invert(a), w), sx_xform_inv_point(a, w), tol);
    }
}

static void xform_is_finite_rejects_nan_and_infinity_anywhere(void **state) {
    sx_xform x = sx_xform_identity();
    (void)state;
    assert_true(sx_xform_is_finite(x));
    x.p.x = R_NAN;
    assert_false(sx_xform_is_finite(x));
    x = sx_xform_identity();
    x.p.y = -R_INF;
    assert_false(sx_xform_is_finite(x));
    x = sx_xform_identity();
    x.q.c = R_INF;
    assert_false(sx_xform_is_finite(x));
    x = sx_xform_identity();
    x.q.s = R_NAN;
    assert_false(sx_xform_is_finite(x));
    assert_false(sx_xform_is_finite(sx_xform_make(sx_v2_zero(), R_NAN)));
}

/* ---- sx_mat3 ------------------------------------------------------------- */

static void mat3_constructors_have_the_course_entries(void **state) {
    sx_mat3 a = sx_mat3_make(SX_R(1.0), SX_R(2.0), SX_R(3.0), SX_R(4.0), SX_R(5.0), SX_R(6.0),
                             SX_R(7.0), SX_R(8.0), SX_R(9.0));
    sx_mat3 r = sx_mat3_rotation(SX_PI / SX_R(6.0));
    double c = sqrt(3.0) / 2.0, s = 0.5;
    (void)state;
    /* Row-major: m[row][col]. */
    assert_true(a.m[0][1] == SX_R(2.0) && a.m[1][0] == SX_R(4.0) && a.m[2][1] == SX_R(8.0));
    assert_true(mat3_is_identity(sx_mat3_identity()));
    assert_mat3_equal(sx_mat3_translation(SX_R(2.0), SX_R(-3.0)),
                      sx_mat3_make(SX_R(1.0), SX_R(0.0), SX_R(2.0), SX_R(0.0), SX_R(1.0),
                                   SX_R(-3.0), SX_R(0.0), SX_R(0.0), SX_R(1.0)));
    assert_mat3_equal(sx_mat3_scale(SX_R(2.0), SX_R(-0.5)),
                      sx_mat3_make(SX_R(2.0), SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(-0.5),
                                   SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(1.0)));
    /* [cos -sin 0; sin cos 0; 0 0 1] */
    assert_near(r.m[0][0], c, SX_TEST_EPS);
    assert_near(r.m[0][1], -s, SX_TEST_EPS);
    assert_near(r.m[1][0], s, SX_TEST_EPS);
    assert_near(r.m[1][1], c, SX_TEST_EPS);
    assert_true(r.m[0][2] == SX_R(0.0) && r.m[1][2] == SX_R(0.0));
    assert_true(r.m[2][0] == SX_R(0.0) && r.m[2][1] == SX_R(0.0) && r.m[2][2] == SX_R(1.0));
    assert_vec2_near(
        sx_mat3_transform_point(sx_mat3_rotation(SX_R(0.5) * SX_PI), sx_v2(SX_R(1.0), SX_R(0.0))),
        sx_v2(SX_R(0.0), SX_R(1.0)), SX_TEST_EPS);
}

static void mat3_mul_matches_the_hand_product(void **state) {
    sx_mat3 a = sx_mat3_make(SX_R(1.0), SX_R(2.0), SX_R(3.0), SX_R(4.0), SX_R(5.0), SX_R(6.0),
                             SX_R(7.0), SX_R(8.0), SX_R(9.0));
    sx_mat3 b = sx_mat3_make(SX_R(9.0), SX_R(8.0), SX_R(7.0), SX_R(6.0), SX_R(5.0), SX_R(4.0),
                             SX_R(3.0), SX_R(2.0), SX_R(1.0));
    (void)state;
    assert_mat3_equal(sx_mat3_mul(a, b),
                      sx_mat3_make(SX_R(30.0), SX_R(24.0), SX_R(18.0), SX_R(84.0), SX_R(69.0),
                                   SX_R(54.0), SX_R(138.0), SX_R(114.0), SX_R(90.0)));
    assert_mat3_equal(sx_mat3_mul(b, a),
                      sx_mat3_make(SX_R(90.0), SX_R(114.0), SX_R(138.0), SX_R(54.0), SX_R(69.0),
                                   SX_R(84.0), SX_R(18.0), SX_R(24.0), SX_R(30.0)));
}

static void mat3_mul_applies_b_first_translate_then_rotate_differs(void **state) {
    sx_mat3 t = sx_mat3_translation(SX_R(2.0), SX_R(0.0));
    sx_mat3 r = sx_mat3_rotation(SX_R(0.5) * SX_PI);
    sx_mat3 tr = sx_mat3_mul(t, r), rt = sx_mat3_mul(r, t);
    sx_vec2 p = sx_v2(SX_R(1.0), SX_R(0.0));
    sx_test_rng rng = sx_test_rng_make(401);
    int k;
    (void)state;
    /* T*R: rotate (1,0) to (0,1), then translate to (2,1). */
    assert_mat3_near(tr,
                     sx_mat3_make(SX_R(0.0), SX_R(-1.0), SX_R(2.0), SX_R(1.0), SX_R(0.0), SX_R(0.0),
                                  SX_R(0.0), SX_R(0.0), SX_R(1.0)),
                     SX_TEST_EPS);
    assert_vec2_near(sx_mat3_transform_point(tr, p), sx_v2(SX_R(2.0), SX_R(1.0)), SX_TEST_EPS);
    /* R*T: translate (1,0) to (3,0), then rotate to (0,3). */
    assert_mat3_near(rt,
                     sx_mat3_make(SX_R(0.0), SX_R(-1.0), SX_R(0.0), SX_R(1.0), SX_R(0.0), SX_R(2.0),
                                  SX_R(0.0), SX_R(0.0), SX_R(1.0)),
                     SX_TEST_EPS);
    assert_vec2_near(sx_mat3_transform_point(rt, p), sx_v2(SX_R(0.0), SX_R(3.0)),
                     4.0 * SX_TEST_EPS);
    /* Scale then translate: S first (2,0) -> T (4,0); T first (3,0) -> S (6,0). */
    assert_vec2_near(
        sx_mat3_transform_point(sx_mat3_mul(t, sx_mat3_scale(SX_R(2.0), SX_R(1.0))), p),
        sx_v2(SX_R(4.0), SX_R(0.0)), 0.0);
    assert_vec2_near(
        sx_mat3_transform_point(sx_mat3_mul(sx_mat3_scale(SX_R(2.0), SX_R(1.0)), t), p),
        sx_v2(SX_R(6.0), SX_R(0.0)), 0.0);
    for (k = 0; k < 1000; ++k) {
        sx_mat3 a = rnd_mat3(&rng), b = rnd_mat3(&rng);
        sx_vec2 v = rnd_vec(&rng, -3.0, 3.0);
        double tol = 200.0 * EPS_D * mat3_norm(a) * mat3_norm(b) * 5.0;
        /* Affine: keep the last rows (0 0 1) so points need no division. */
        a.m[2][0] = a.m[2][1] = b.m[2][0] = b.m[2][1] = SX_R(0.0);
        a.m[2][2] = b.m[2][2] = SX_R(1.0);
        assert_vec2_near(sx_mat3_transform_point(sx_mat3_mul(a, b), v),
                         sx_mat3_transform_point(a, sx_mat3_transform_point(b, v)), tol);
        assert_vec2_near(sx_mat3_transform_vector(sx_mat3_mul(a, b), v),
                         sx_mat3_transform_vector(a, sx_mat3_transform_vector(b, v)), tol);
    }
}

static void mat3_points_use_w_one_and_vectors_w_zero(void **state) {
    sx_mat3 t = sx_mat3_translation(SX_R(5.0), SX_R(-2.0));
    sx_mat3 a = sx_mat3_make(SX_R(2.0), SX_R(0.0), SX_R(1.0), SX_R(0.0), SX_R(3.0), SX_R(-1.0),
                             SX_R(0.0), SX_R(0.0), SX_R(1.0));
    sx_mat3 proj = sx_mat3_make(SX_R(2.0), SX_R(0.0), SX_R(2.0), SX_R(0.0), SX_R(2.0), SX_R(4.0),
                                SX_R(0.0), SX_R(0.0), SX_R(2.0));
    sx_mat3 horizon = sx_mat3_make(SX_R(1.0), SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(1.0), SX_R(0.0),
                                   SX_R(1.0), SX_R(0.0), SX_R(-1.0));
    sx_vec2 p = sx_v2(SX_R(1.0), SX_R(1.0));
    (void)state;
    assert_vec2_near(sx_mat3_transform_point(t, p), sx_v2(SX_R(6.0), SX_R(-1.0)), 0.0);
    assert_vec2_near(sx_mat3_transform_vector(t, p), p, 0.0);
    assert_vec2_near(sx_mat3_transform_point(a, p), sx_v2(SX_R(3.0), SX_R(2.0)), 0.0);
    assert_vec2_near(sx_mat3_transform_vector(a, p), sx_v2(SX_R(2.0), SX_R(3.0)), 0.0);
    assert_vec2_near(sx_mat3_transform_point(sx_mat3_scale(SX_R(2.0), SX_R(-3.0)), p),
                     sx_v2(SX_R(2.0), SX_R(-3.0)), 0.0);
    assert_vec2_near(sx_mat3_transform_vector(sx_mat3_scale(SX_R(2.0), SX_R(-3.0)), p),
                     sx_v2(SX_R(2.0), SX_R(-3.0)), 0.0);
    /* Projective last row: (2+2, 2+4, 2) divided by w = 2. */
    assert_vec2_near(sx_mat3_transform_point(proj, p), sx_v2(SX_R(2.0), SX_R(3.0)), 0.0);
    /* w = 0 (a point at infinity): no division, the raw (x, y) comes back. */
    assert_vec2_near(sx_mat3_transform_point(horizon, p), p, 0.0);
}

static void mat3_identity_is_neutral_and_transpose_swaps(void **state) {
    sx_test_rng rng = sx_test_rng_make(402);
    sx_mat3 a = sx_mat3_make(SX_R(1.0), SX_R(2.0), SX_R(3.0), SX_R(4.0), SX_R(5.0), SX_R(6.0),
                             SX_R(7.0), SX_R(8.0), SX_R(9.0));
    int k;
    (void)state;
    assert_mat3_equal(sx_mat3_transpose(a),
                      sx_mat3_make(SX_R(1.0), SX_R(4.0), SX_R(7.0), SX_R(2.0), SX_R(5.0), SX_R(8.0),
                                   SX_R(3.0), SX_R(6.0), SX_R(9.0)));
    for (k = 0; k < 500; ++k) {
        sx_mat3 x = rnd_mat3(&rng), y = rnd_mat3(&rng);
        sx_vec2 v = rnd_vec(&rng, -3.0, 3.0);
        assert_mat3_equal(sx_mat3_mul(sx_mat3_identity(), x), x);
        assert_mat3_equal(sx_mat3_mul(x, sx_mat3_identity()), x);
        assert_mat3_equal(sx_mat3_transpose(sx_mat3_transpose(x)), x);
        /* (XY)^T = Y^T X^T, bit for bit: the same products summed in the same order. */
        assert_mat3_equal(sx_mat3_transpose(sx_mat3_mul(x, y)),
                          sx_mat3_mul(sx_mat3_transpose(y), sx_mat3_transpose(x)));
        assert_vec2_near(sx_mat3_transform_point(sx_mat3_identity(), v), v, 0.0);
        assert_vec2_near(sx_mat3_transform_vector(sx_mat3_identity(), v), v, 0.0);
    }
}

static void mat3_mul_is_associative_on_random_matrices(void **state) {
    sx_test_rng rng = sx_test_rng_make(403);
    int k;
    (void)state;
    for (k = 0; k < 1000; ++k) {
        sx_mat3 a = rnd_mat3(&rng), b = rnd_mat3(&rng), c = rnd_mat3(&rng);
        sx_mat3 l = sx_mat3_mul(sx_mat3_mul(a, b), c), r = sx_mat3_mul(a, sx_mat3_mul(b, c));
        /* Each entry is a sum of 9 triple products bounded by the norms
         * (measured worst: 0.66 eps times the product of the norms). */
        double tol = 4.0 * EPS_D * mat3_norm(a) * mat3_norm(b) * mat3_norm(c);
        assert_mat3_near(l, r, tol);
    }
}

static void mat3_determinant_matches_hand_values_and_the_product_rule(void **state) {
    sx_test_rng rng = sx_test_rng_make(404);
    int k;
    (void)state;
    assert_true(sx_mat3_determinant(sx_mat3_identity()) == SX_R(1.0));
    assert_true(sx_mat3_determinant(sx_mat3_translation(SX_R(7.0), SX_R(-3.0))) == SX_R(1.0));
    assert_true(sx_mat3_determinant(sx_mat3_scale(SX_R(2.0), SX_R(3.0))) == SX_R(6.0));
    assert_true(sx_mat3_determinant(sx_mat3_scale(SX_R(1.0), SX_R(-1.0))) == SX_R(-1.0));
    assert_near(sx_mat3_determinant(sx_mat3_rotation(SX_R(0.7))), 1.0, SX_TEST_EPS);
    assert_true(
        sx_mat3_determinant(sx_mat3_make(SX_R(1.0), SX_R(2.0), SX_R(3.0), SX_R(4.0), SX_R(5.0),
                                         SX_R(6.0), SX_R(7.0), SX_R(8.0), SX_R(9.0))) == SX_R(0.0));
    /* 2 (3*4 - 2*1) - (-1)(1*4 - 2*0) + 0 = 20 + 4 = 24 */
    assert_true(sx_mat3_determinant(sx_mat3_make(SX_R(2.0), SX_R(-1.0), SX_R(0.0), SX_R(1.0),
                                                 SX_R(3.0), SX_R(2.0), SX_R(0.0), SX_R(1.0),
                                                 SX_R(4.0))) == SX_R(24.0));
    for (k = 0; k < 1000; ++k) {
        sx_mat3 a = rnd_mat3(&rng), b = rnd_mat3(&rng);
        double da = (double)sx_mat3_determinant(a), db = (double)sx_mat3_determinant(b);
        double na = row_norm_product(a), nb = row_norm_product(b);
        double scale = row_norm_product(sx_mat3_mul(a, b)) + na * nb;
        /* Measured worst: 0.8 eps * scale. */
        assert_near(sx_mat3_determinant(sx_mat3_mul(a, b)), da * db, 8.0 * EPS_D * scale);
        assert_near(sx_mat3_determinant(sx_mat3_transpose(a)), da, 16.0 * EPS_D * na);
        /* Hadamard's bound: |det| <= product of the row lengths. */
        assert_true(fabs(da) <= na * (1.0 + 8.0 * EPS_D));
    }
}

static void mat3_inverse_matches_hand_values(void **state) {
    sx_mat3 inv;
    sx_mat3 a = sx_mat3_make(SX_R(2.0), SX_R(-1.0), SX_R(0.0), SX_R(1.0), SX_R(3.0), SX_R(2.0),
                             SX_R(0.0), SX_R(1.0), SX_R(4.0));
    (void)state;
    assert_true(sx_mat3_inverse(sx_mat3_translation(SX_R(2.0), SX_R(3.0)), &inv));
    assert_mat3_equal(inv, sx_mat3_translation(SX_R(-2.0), SX_R(-3.0)));
    assert_true(sx_mat3_inverse(sx_mat3_scale(SX_R(2.0), SX_R(-4.0)), &inv));
    assert_mat3_equal(inv, sx_mat3_scale(SX_R(0.5), SX_R(-0.25)));
    assert_true(sx_mat3_inverse(sx_mat3_rotation(SX_R(0.7)), &inv));
    assert_mat3_near(inv, sx_mat3_rotation(SX_R(-0.7)), SX_TEST_EPS);
    assert_mat3_near(inv, sx_mat3_transpose(sx_mat3_rotation(SX_R(0.7))), SX_TEST_EPS);
    /* Adjugate of the det-24 matrix above, divided by 24. */
    assert_true(sx_mat3_inverse(a, &inv));
    assert_mat3_near(
        inv,
        sx_mat3_make(SX_R(10.0) / SX_R(24.0), SX_R(4.0) / SX_R(24.0), SX_R(-2.0) / SX_R(24.0),
                     SX_R(-4.0) / SX_R(24.0), SX_R(8.0) / SX_R(24.0), SX_R(-4.0) / SX_R(24.0),
                     SX_R(1.0) / SX_R(24.0), SX_R(-2.0) / SX_R(24.0), SX_R(7.0) / SX_R(24.0)),
        SX_TEST_EPS);
    /* Singularity is relative to the scale: a small but well-shaped matrix
     * is invertible. */
    assert_true(sx_mat3_inverse(sx_mat3_scale(SX_R(1e-3), SX_R(1e-3)), &inv));
    assert_near(inv.m[0][0], 1e3, 1e3 * SX_TEST_EPS);
}

static void mat3_inverse_round_trips_on_random_invertible_matrices(void **state) {
    sx_test_rng rng = sx_test_rng_make(405);
    int k, done = 0;
    (void)state;
    for (k = 0; k < 2000; ++k) {
        sx_mat3 a = rnd_mat3(&rng), inv;
        double cond, tol;
        if (!sx_mat3_inverse(a, &inv)) {
            assert_true(mat3_is_identity(inv));
            continue;
        }
        ++done;
        /* Entry errors of A A^-1 - I grow with the condition number
         * |A| |A^-1| (Frobenius), times the rounding of a few operations
         * (measured worst: 0.82 eps * cond). */
        cond = mat3_norm(a) * mat3_norm(inv);
        tol = 4.0 * EPS_D * cond;
        assert_mat3_near(sx_mat3_mul(a, inv), sx_mat3_identity(), tol);
        assert_mat3_near(sx_mat3_mul(inv, a), sx_mat3_identity(), tol);
    }
    assert_true(done > 1900);
}

static void mat3_inverse_of_translate_rotate_scale_is_the_reversed_product(void **state) {
    sx_test_rng rng = sx_test_rng_make(409);
    int k;
    (void)state;
    for (k = 0; k < 1000; ++k) {
        sx_vec2 p = rnd_vec(&rng, -10.0, 10.0), v = rnd_vec(&rng, -10.0, 10.0);
        sx_real t = sx_test_rng_range(&rng, -PI_D, PI_D);
        sx_real sx = sx_test_rng_range(&rng, 0.25, 4.0), sy = sx_test_rng_range(&rng, -4.0, -0.25);
        sx_mat3 m = sx_mat3_mul(sx_mat3_translation(p.x, p.y),
                                sx_mat3_mul(sx_mat3_rotation(t), sx_mat3_scale(sx, sy)));
        /* (T R S)^-1 = S^-1 R^-1 T^-1 */
        sx_mat3 ref =
            sx_mat3_mul(sx_mat3_scale(SX_R(1.0) / sx, SX_R(1.0) / sy),
                        sx_mat3_mul(sx_mat3_rotation(-t), sx_mat3_translation(-p.x, -p.y)));
        sx_mat3 inv;
        double tol = 100.0 * SX_TEST_EPS * mat3_norm(ref);
        assert_true(sx_mat3_inverse(m, &inv));
        assert_mat3_near(inv, ref, tol);
        assert_vec2_near(sx_mat3_transform_point(inv, sx_mat3_transform_point(m, v)), v, tol);
    }
}

static void mat3_inverse_of_singular_matrix_returns_false_and_writes_identity(void **state) {
    sx_test_rng rng = sx_test_rng_make(406);
    sx_mat3 bad[7];
    sx_mat3 out;
    int k;
    (void)state;
    bad[0] = sx_mat3_scale(SX_R(0.0), SX_R(1.0));
    bad[1] = sx_mat3_scale(SX_R(3.0), SX_R(0.0));
    bad[2] = sx_mat3_make(SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(0.0), SX_R(0.0),
                          SX_R(0.0), SX_R(0.0), SX_R(0.0));
    /* Rank 2: row 2 = row 0 + row 1, exactly. */
    bad[3] = sx_mat3_make(SX_R(1.0), SX_R(2.0), SX_R(3.0), SX_R(4.0), SX_R(5.0), SX_R(6.0),
                          SX_R(5.0), SX_R(7.0), SX_R(9.0));
    bad[4] = sx_mat3_identity();
    bad[4].m[1][2] = R_NAN;
    bad[5] = sx_mat3_identity();
    bad[5].m[0][0] = R_INF;
    bad[6] = sx_mat3_translation(R_NAN, R_NAN);
    for (k = 0; k < 7; ++k) {
        out = rnd_mat3(&rng);
        assert_false(sx_mat3_inverse(bad[k], &out));
        assert_true(mat3_is_identity(out));
    }
    /* Rank 1: u v^T, with u and v random (entries rounded, so only nearly). */
    for (k = 0; k < 500; ++k) {
        sx_vec2 u01 = rnd_vec(&rng, -2.0, 2.0), v01 = rnd_vec(&rng, -2.0, 2.0);
        sx_real u2 = sx_test_rng_range(&rng, -2.0, 2.0), v2 = sx_test_rng_range(&rng, -2.0, 2.0);
        sx_real u[3], v[3];
        sx_mat3 a;
        int i, j;
        u[0] = u01.x;
        u[1] = u01.y;
        u[2] = u2;
        v[0] = v01.x;
        v[1] = v01.y;
        v[2] = v2;
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j)
                a.m[i][j] = u[i] * v[j];
        }
        out = rnd_mat3(&rng);
        assert_false(sx_mat3_inverse(a, &out));
        assert_true(mat3_is_identity(out));
    }
}

static void mat3_from_xform_agrees_with_xform_on_points_and_vectors(void **state) {
    sx_test_rng rng = sx_test_rng_make(407);
    sx_xform x = sx_xform_make(sx_v2(SX_R(3.0), SX_R(-1.0)), SX_R(0.25));
    sx_mat3 m = sx_mat3_from_xform(x);
    int k;
    (void)state;
    /* [c -s px; s c py; 0 0 1] */
    assert_mat3_equal(m, sx_mat3_make(x.q.c, -x.q.s, SX_R(3.0), x.q.s, x.q.c, SX_R(-1.0), SX_R(0.0),
                                      SX_R(0.0), SX_R(1.0)));
    assert_mat3_near(
        m, sx_mat3_mul(sx_mat3_translation(SX_R(3.0), SX_R(-1.0)), sx_mat3_rotation(SX_R(0.25))),
        SX_TEST_EPS);
    for (k = 0; k < 1000; ++k) {
        sx_xform a = rnd_xform(&rng), b = rnd_xform(&rng), back;
        sx_mat3 ma = sx_mat3_from_xform(a);
        sx_vec2 v = rnd_vec(&rng, -10.0, 10.0);
        double tol = 100.0 * SX_TEST_EPS;
        assert_vec2_near(sx_mat3_transform_point(ma, v), sx_xform_point(a, v), tol);
        assert_vec2_near(sx_mat3_transform_vector(ma, v), sx_xform_vector(a, v), tol);
        assert_mat3_near(sx_mat3_from_xform(sx_xform_mul(a, b)),
                         sx_mat3_mul(ma, sx_mat3_from_xform(b)), tol);
        assert_true(sx_mat3_to_xform(ma, SX_R(1e-4), &back));
        assert_vec2_near(back.p, a.p, 0.0);
        assert_near(back.q.c, a.q.c, SX_TEST_EPS);
        assert_near(back.q.s, a.q.s, SX_TEST_EPS);
        assert_vec2_near(sx_xform_point(back, v), sx_mat3_transform_point(ma, v), tol);
        {
            sx_mat3 inv;
            assert_true(sx_mat3_inverse(ma, &inv));
            assert_mat3_near(inv, sx_mat3_from_xform(sx_xform_invert(a)), tol);
        }
    }
}

static void mat3_to_xform_accepts_rigid_matrices_within_tolerance(void **state) {
    sx_test_rng rng = sx_test_rng_make(408);
    sx_xform out;
    sx_mat3 m;
    int k;
    (void)state;
    for (k = 0; k < 500; ++k) {
        sx_real t = sx_test_rng_range(&rng, -PI_D, PI_D);
        sx_vec2 p = rnd_vec(&rng, -10.0, 10.0);
        m = sx_mat3_mul(sx_mat3_translation(p.x, p.y), sx_mat3_rotation(t));
        assert_true(sx_mat3_to_xform(m, SX_R(1e-4), &out));
        assert_near(angle_diff((double)sx_rot_angle(out.q), (double)t), 0.0, SX_TEST_EPS);
        assert_vec2_near(out.p, p, 0.0);
    }
    /* Off by 1e-4 in one entry: accepted with tol 1e-3, rejected with 1e-5. */
    m = sx_mat3_rotation(SX_R(0.4));
    m.m[0][1] += SX_R(1e-4);
    assert_true(sx_mat3_to_xform(m, SX_R(1e-3), &out));
    assert_false(sx_mat3_to_xform(m, SX_R(1e-5), &out));
    assert_near(sx_rot_angle(out.q), 0.4, SX_TEST_EPS);
}

static void mat3_to_xform_rejects_scale_shear_reflection_projection_but_extracts(void **state) {
    const sx_real tol = SX_R(1e-4);
    const sx_real t = SX_R(0.7);
    sx_mat3 tr = sx_mat3_mul(sx_mat3_translation(SX_R(3.0), SX_R(4.0)), sx_mat3_rotation(t));
    sx_mat3 m;
    sx_xform out;
    (void)state;
    /* Uniform scale (applied first: T R S). */
    assert_false(sx_mat3_to_xform(sx_mat3_mul(tr, sx_mat3_scale(SX_R(2.0), SX_R(2.0))), tol, &out));
    assert_near(sx_rot_angle(out.q), 0.7, SX_TEST_EPS);
    assert_vec2_near(out.p, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    assert_true(sx_is_normalized(sx_v2(out.q.c, out.q.s)));
    /* Non-uniform scale. */
    assert_false(sx_mat3_to_xform(sx_mat3_mul(tr, sx_mat3_scale(SX_R(1.0), SX_R(0.5))), tol, &out));
    assert_near(sx_rot_angle(out.q), 0.7, SX_TEST_EPS);
    assert_vec2_near(out.p, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    /* Shear x += 0.5 y: the first column is untouched, so is the rotation. */
    m = sx_mat3_make(SX_R(1.0), SX_R(0.5), SX_R(0.0), SX_R(0.0), SX_R(1.0), SX_R(0.0), SX_R(0.0),
                     SX_R(0.0), SX_R(1.0));
    assert_false(sx_mat3_to_xform(sx_mat3_mul(tr, m), tol, &out));
    assert_near(sx_rot_angle(out.q), 0.7, SX_TEST_EPS);
    assert_vec2_near(out.p, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    /* Reflection y -> -y: orthonormal columns but determinant -1. */
    assert_false(
        sx_mat3_to_xform(sx_mat3_mul(tr, sx_mat3_scale(SX_R(1.0), SX_R(-1.0))), tol, &out));
    assert_near(sx_rot_angle(out.q), 0.7, SX_TEST_EPS);
    assert_vec2_near(out.p, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    /* Projective last rows. */
    m = tr;
    m.m[2][0] = SX_R(0.1);
    assert_false(sx_mat3_to_xform(m, tol, &out));
    assert_near(sx_rot_angle(out.q), 0.7, SX_TEST_EPS);
    assert_vec2_near(out.p, sx_v2(SX_R(3.0), SX_R(4.0)), 0.0);
    m = tr;
    m.m[2][1] = SX_R(-0.1);
    assert_false(sx_mat3_to_xform(m, tol, &out));
    m = tr;
    m.m[2][2] = SX_R(2.0);
    assert_false(sx_mat3_to_xform(m, tol, &out));
    assert_near(sx_rot_angle(out.q), 0.7, SX_TEST_EPS);
    /* Nothing to extract: identity. */
    m = tr;
    m.m[0][0] = m.m[1][0] = SX_R(0.0);
    out = sx_xform_make(sx_v2(SX_R(9.0), SX_R(9.0)), SX_R(1.0));
    assert_false(sx_mat3_to_xform(m, tol, &out));
    assert_true(out.p.x == SX_R(0.0) && out.p.y == SX_R(0.0) && out.q.c == SX_R(1.0) &&
                out.q.s == SX_R(0.0));
    m = tr;
    m.m[1][0] = R_NAN;
    assert_false(sx_mat3_to_xform(m, tol, &out));
    assert_true(out.q.c == SX_R(1.0) && out.q.s == SX_R(0.0) && out.p.x == SX_R(0.0));
    m = tr;
    m.m[0][2] = R_INF;
    assert_false(sx_mat3_to_xform(m, tol, &out));
    assert_true(out.q.c == SX_R(1.0) && out.q.s == SX_R(0.0) && out.p.x == SX_R(0.0));
    m = tr;
    m.m[1][1] = R_NAN;
    assert_false(sx_mat3_to_xform(m, tol, &out));
    assert_true(sx_xform_is_finite(out));
}

/* ---- sx_aabb ------------------------------------------------------------- */

static sx_aabb box(double lx, double ly, double ux, double uy) {
    return sx_aabb_make(sx_v2((sx_real)lx, (sx_real)ly), sx_v2((sx_real)ux, (sx_real)uy));
}

static void aabb_make_and_is_valid(void **state) {
    sx_aabb a = box(-1.0, 2.0, 3.0, 8.0);
    (void)state;
    assert_vec2_near(a.lower, sx_v2(SX_R(-1.0), SX_R(2.0)), 0.0);
    assert_vec2_near(a.upper, sx_v2(SX_R(3.0), SX_R(8.0)), 0.0);
    assert_true(sx_aabb_is_valid(a));
    assert_true(sx_aabb_is_valid(box(1.0, 1.0, 1.0, 1.0)));
    assert_false(sx_aabb_is_valid(box(2.0, 0.0, 1.0, 1.0)));
    assert_false(sx_aabb_is_valid(box(0.0, 2.0, 1.0, 1.0)));
    assert_false(
        sx_aabb_is_valid(sx_aabb_make(sx_v2(R_NAN, SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(1.0)))));
    assert_false(
        sx_aabb_is_valid(sx_aabb_make(sx_v2(SX_R(0.0), SX_R(0.0)), sx_v2(SX_R(1.0), R_INF))));
    assert_false(
        sx_aabb_is_valid(sx_aabb_make(sx_v2(-R_INF, SX_R(0.0)), sx_v2(SX_R(1.0), SX_R(1.0)))));
}

static void aabb_from_points_is_the_tightest_box(void **state) {
    sx_vec2 pts[4];
    sx_aabb b;
    sx_test_rng rng = sx_test_rng_make(501);
    int k;
    (void)state;
    pts[0] = sx_v2(SX_R(1.0), SX_R(5.0));
    pts[1] = sx_v2(SX_R(-2.0), SX_R(3.0));
    pts[2] = sx_v2(SX_R(4.0), SX_R(-1.0));
    pts[3] = sx_v2(SX_R(0.0), SX_R(0.0));
    b = sx_aabb_from_points(pts, 4);
    assert_vec2_near(b.lower, sx_v2(SX_R(-2.0), SX_R(-1.0)), 0.0);
    assert_vec2_near(b.upper, sx_v2(SX_R(4.0), SX_R(5.0)), 0.0);
    b = sx_aabb_from_points(pts, 1);
    assert_vec2_near(b.lower, pts[0], 0.0);
    assert_vec2_near(b.upper, pts[0], 0.0);
    assert_true(sx_aabb_is_valid(b));
    for (k = 0; k < 200; ++k) {
        sx_vec2 many[16];
        int n = 1 + (int)(sx_test_rng_next(&rng) % 16), i;
        for (i = 0; i < n; ++i)
            many[i] = rnd_vec(&rng, -50.0, 50.0);
        b = sx_aabb_from_points(many, n);
        assert_true(sx_aabb_is_valid(b));
        for (i = 0; i < n; ++i)
            assert_true(sx_aabb_contains_point(b, many[i]));
        /* Tight: every side is touched by some point. */
        {
            bool lx = false, ly = false, ux = false, uy = false;
            for (i = 0; i < n; ++i) {
                lx = lx || many[i].x == b.lower.x;
                ly = ly || many[i].y == b.lower.y;
                ux = ux || many[i].x == b.upper.x;
                uy = uy || many[i].y == b.upper.y;
            }
            assert_true(lx && ly && ux && uy);
        }
    }
}

static void aabb_from_no_points_is_the_identity_of_union(void **state) {
    sx_vec2 p = sx_v2(SX_R(1.0), SX_R(1.0));
    sx_aabb e[3], a = box(-1.0, 2.0, 3.0, 8.0), u;
    int k;
    (void)state;
    e[0] = sx_aabb_from_points(NULL, 0);
    e[1] = sx_aabb_from_points(&p, 0);
    e[2] = sx_aabb_from_points(NULL, 5);
    for (k = 0; k < 3; ++k) {
        assert_false(sx_aabb_is_valid(e[k]));
        assert_true(e[k].lower.x == SX_REAL_MAX && e[k].lower.y == SX_REAL_MAX);
        assert_true(e[k].upper.x == -SX_REAL_MAX && e[k].upper.y == -SX_REAL_MAX);
        u = sx_aabb_union(e[k], a);
        assert_vec2_near(u.lower, a.lower, 0.0);
        assert_vec2_near(u.upper, a.upper, 0.0);
        u = sx_aabb_union(a, e[k]);
        assert_vec2_near(u.lower, a.lower, 0.0);
        assert_vec2_near(u.upper, a.upper, 0.0);
        assert_false(sx_aabb_overlaps(e[k], a));
    }
    e[0] = sx_aabb_from_points(&p, -3);
    assert_false(sx_aabb_is_valid(e[0]));
}

static void aabb_from_points_with_a_nan_point_is_invalid(void **state) {
    sx_vec2 pts[3];
    (void)state;
    pts[0] = sx_v2(SX_R(0.0), SX_R(0.0));
    pts[1] = sx_v2(R_NAN, SX_R(1.0));
    pts[2] = sx_v2(SX_R(2.0), SX_R(2.0));
    assert_false(sx_aabb_is_valid(sx_aabb_from_points(pts, 3)));
    pts[1] = sx_v2(SX_R(1.0), R_NAN);
    assert_false(sx_aabb_is_valid(sx_aabb_from_points(pts, 3)));
}

static void aabb_union_contains_both_boxes(void **state) {
    sx_test_rng rng = sx_test_rng_make(502);
    sx_aabb u = sx_aabb_union(box(0.0, 0.0, 1.0, 1.0), box(2.0, -1.0, 3.0, 0.5));
    int k;
    (void)state;
    assert_vec2_near(u.lower, sx_v2(SX_R(0.0), SX_R(-1.0)), 0.0);
    assert_vec2_near(u.upper, sx_v2(SX_R(3.0), SX_R(1.0)), 0.0);
    for (k = 0; k < 500; ++k) {
        sx_vec2 p[2], q[2];
        sx_aabb a, b;
        p[0] = rnd_vec(&rng, -10.0, 10.0);
        p[1] = rnd_vec(&rng, -10.0, 10.0);
        q[0] = rnd_vec(&rng, -10.0, 10.0);
        q[1] = rnd_vec(&rng, -10.0, 10.0);
        a = sx_aabb_from_points(p, 2);
        b = sx_aabb_from_points(q, 2);
        u = sx_aabb_union(a, b);
        assert_true(sx_aabb_is_valid(u));
        assert_true(sx_aabb_contains(u, a) && sx_aabb_contains(u, b));
        assert_true(sx_aabb_overlaps(u, a) && sx_aabb_overlaps(u, b));
        assert_true(sx_aabb_perimeter(u) >= sx_aabb_perimeter(a));
        /* The union of two boxes is the box of all four corners. */
        {
            sx_vec2 all[4];
            sx_aabb ref;
            all[0] = p[0];
            all[1] = p[1];
            all[2] = q[0];
            all[3] = q[1];
            ref = sx_aabb_from_points(all, 4);
            assert_vec2_near(u.lower, ref.lower, 0.0);
            assert_vec2_near(u.upper, ref.upper, 0.0);
        }
    }
}

static void aabb_overlaps_counts_touching_and_rejects_separation_on_either_axis(void **state) {
    sx_aabb a = box(0.0, 0.0, 2.0, 2.0);
    sx_aabb cases[9];
    bool expect[9];
    int k;
    (void)state;
    cases[0] = box(1.0, 1.0, 3.0, 3.0); /* partial overlap */
    expect[0] = true;
    cases[1] = box(2.0, 0.5, 3.0, 1.5); /* touching the right edge */
    expect[1] = true;
    cases[2] = box(2.0, 2.0, 3.0, 3.0); /* touching at a corner */
    expect[2] = true;
    cases[3] = box(0.5, 0.5, 1.0, 1.0); /* inside */
    expect[3] = true;
    cases[4] = box(-1.0, -1.0, 3.0, 3.0); /* around */
    expect[4] = true;
    cases[5] = box(2.5, 0.5, 3.0, 1.5); /* separated on x only */
    expect[5] = false;
    cases[6] = box(0.5, -3.0, 1.5, -0.5); /* separated on y only */
    expect[6] = false;
    cases[7] = box(-3.0, 0.0, -0.001, 2.0); /* just left */
    expect[7] = false;
    cases[8] = box(0.0, 2.001, 2.0, 3.0); /* just above */
    expect[8] = false;
    for (k = 0; k < 9; ++k) {
        assert_true(sx_aabb_overlaps(a, cases[k]) == expect[k]);
        assert_true(sx_aabb_overlaps(cases[k], a) == expect[k]);
    }
}

static void aabb_contains_whole_boxes_with_shared_edges(void **state) {
    sx_aabb a = box(0.0, 0.0, 4.0, 2.0);
    (void)state;
    assert_true(sx_aabb_contains(a, a));
    assert_true(sx_aabb_contains(a, box(1.0, 0.5, 2.0, 1.5)));
    assert_true(sx_aabb_contains(a, box(0.0, 0.0, 4.0, 1.0)));
    assert_false(sx_aabb_contains(a, box(-0.5, 0.5, 2.0, 1.5)));
    assert_false(sx_aabb_contains(a, box(1.0, -0.5, 2.0, 1.5)));
    assert_false(sx_aabb_contains(a, box(1.0, 0.5, 4.5, 1.5)));
    assert_false(sx_aabb_contains(a, box(1.0, 0.5, 2.0, 2.5)));
    assert_false(sx_aabb_contains(box(1.0, 0.5, 2.0, 1.5), a));
}

static void aabb_contains_point_counts_the_boundary(void **state) {
    sx_aabb a = box(-1.0, -2.0, 3.0, 4.0);
    (void)state;
    assert_true(sx_aabb_contains_point(a, sx_v2(SX_R(0.0), SX_R(0.0))));
    assert_true(sx_aabb_contains_point(a, sx_v2(SX_R(-1.0), SX_R(-2.0))));
    assert_true(sx_aabb_contains_point(a, sx_v2(SX_R(3.0), SX_R(4.0))));
    assert_true(sx_aabb_contains_point(a, sx_v2(SX_R(3.0), SX_R(0.0))));
    assert_true(sx_aabb_contains_point(a, sx_v2(SX_R(0.0), SX_R(-2.0))));
    assert_false(sx_aabb_contains_point(a, sx_v2(SX_R(3.001), SX_R(0.0))));
    assert_false(sx_aabb_contains_point(a, sx_v2(SX_R(-1.001), SX_R(0.0))));
    assert_false(sx_aabb_contains_point(a, sx_v2(SX_R(0.0), SX_R(4.001))));
    assert_false(sx_aabb_contains_point(a, sx_v2(SX_R(0.0), SX_R(-2.001))));
    assert_false(sx_aabb_contains_point(a, sx_v2(R_NAN, SX_R(0.0))));
}

static void aabb_center_extents_perimeter_area_match_hand_values(void **state) {
    sx_aabb a = box(-1.0, 2.0, 3.0, 8.0);
    sx_aabb pt = box(1.0, 1.0, 1.0, 1.0);
    (void)state;
    assert_vec2_near(sx_aabb_center(a), sx_v2(SX_R(1.0), SX_R(5.0)), 0.0);
    assert_vec2_near(sx_aabb_extents(a), sx_v2(SX_R(2.0), SX_R(3.0)), 0.0);
    assert_true(sx_aabb_perimeter(a) == SX_R(20.0));
    assert_true(sx_aabb_area(a) == SX_R(24.0));
    assert_vec2_near(sx_aabb_center(pt), sx_v2(SX_R(1.0), SX_R(1.0)), 0.0);
    assert_vec2_near(sx_aabb_extents(pt), sx_v2_zero(), 0.0);
    assert_true(sx_aabb_perimeter(pt) == SX_R(0.0));
    assert_true(sx_aabb_area(pt) == SX_R(0.0));
    assert_true(sx_aabb_area(box(0.0, 0.0, 5.0, 0.0)) == SX_R(0.0));
    assert_true(sx_aabb_perimeter(box(0.0, 0.0, 5.0, 0.0)) == SX_R(10.0));
}

static void aabb_fatten_grows_every_side_by_the_margin(void **state) {
    sx_aabb a = sx_aabb_fatten(box(-1.0, 2.0, 3.0, 8.0), SX_R(0.5));
    (void)state;
    assert_vec2_near(a.lower, sx_v2(SX_R(-1.5), SX_R(1.5)), 0.0);
    assert_vec2_near(a.upper, sx_v2(SX_R(3.5), SX_R(8.5)), 0.0);
    assert_true(sx_aabb_contains(a, box(-1.0, 2.0, 3.0, 8.0)));
    assert_true(sx_aabb_perimeter(a) == SX_R(24.0));
    a = sx_aabb_fatten(box(-1.0, 2.0, 3.0, 8.0), SX_R(0.0));
    assert_vec2_near(a.lower, sx_v2(SX_R(-1.0), SX_R(2.0)), 0.0);
    assert_vec2_near(a.upper, sx_v2(SX_R(3.0), SX_R(8.0)), 0.0);
}

static void aabb_closest_point_clamps_outside_and_keeps_inside(void **state) {
    sx_aabb a = box(0.0, 0.0, 2.0, 1.0);
    sx_test_rng rng = sx_test_rng_make(503);
    int k;
    (void)state;
    assert_vec2_near(sx_aabb_closest_point(a, sx_v2(SX_R(0.5), SX_R(0.5))),
                     sx_v2(SX_R(0.5), SX_R(0.5)), 0.0);
    assert_vec2_near(sx_aabb_closest_point(a, sx_v2(SX_R(-3.0), SX_R(0.5))),
                     sx_v2(SX_R(0.0), SX_R(0.5)), 0.0);
    assert_vec2_near(sx_aabb_closest_point(a, sx_v2(SX_R(1.0), SX_R(5.0))),
                     sx_v2(SX_R(1.0), SX_R(1.0)), 0.0);
    assert_vec2_near(sx_aabb_closest_point(a, sx_v2(SX_R(3.0), SX_R(-2.0))),
                     sx_v2(SX_R(2.0), SX_R(0.0)), 0.0);
    for (k = 0; k < 500; ++k) {
        sx_vec2 p = rnd_vec(&rng, -5.0, 5.0);
        sx_vec2 c = sx_aabb_closest_point(a, p);
        sx_vec2 other = sx_v2(sx_test_rng_range(&rng, 0.0, 2.0), sx_test_rng_range(&rng, 0.0, 1.0));
        assert_true(sx_aabb_contains_point(a, c));
        /* No point of the box is closer. */
        assert_true(sx_distance_sq(p, c) <= sx_distance_sq(p, other));
        if (sx_aabb_contains_point(a, p)) assert_vec2_near(c, p, 0.0);
    }
}

static void aabb_overlaps_circle_handles_edges_and_corners(void **state) {
    sx_aabb a = box(0.0, 0.0, 2.0, 2.0);
    sx_test_rng rng = sx_test_rng_make(504);
    int k;
    (void)state;
    assert_true(sx_aabb_overlaps_circle(a, sx_v2(SX_R(1.0), SX_R(1.0)), SX_R(0.1)));
    assert_true(sx_aabb_overlaps_circle(a, sx_v2(SX_R(1.0), SX_R(1.0)), SX_R(0.0)));
    /* Touching the right edge (distance exactly 1) counts. */
    assert_true(sx_aabb_overlaps_circle(a, sx_v2(SX_R(3.0), SX_R(1.0)), SX_R(1.0)));
    assert_false(sx_aabb_overlaps_circle(a, sx_v2(SX_R(3.001), SX_R(1.0)), SX_R(1.0)));
    assert_true(sx_aabb_overlaps_circle(a, sx_v2(SX_R(1.0), SX_R(-0.5)), SX_R(0.5)));
    assert_false(sx_aabb_overlaps_circle(a, sx_v2(SX_R(1.0), SX_R(-0.6)), SX_R(0.5)));
    /* Corner region: centre (2.8, 2.8), radius 1. The circle's bounding
     * square [1.8, 3.8]^2 overlaps the box, but the corner (2, 2) is
     * 0.8 sqrt(2) = 1.13 away: no contact. */
    assert_false(sx_aabb_overlaps_circle(a, sx_v2(SX_R(2.8), SX_R(2.8)), SX_R(1.0)));
    assert_false(sx_aabb_overlaps_circle(a, sx_v2(SX_R(-0.8), SX_R(-0.8)), SX_R(1.0)));
    /* (2.6, 2.6): 0.6 sqrt(2) = 0.85 from the corner. */
    assert_true(sx_aabb_overlaps_circle(a, sx_v2(SX_R(2.6), SX_R(2.6)), SX_R(1.0)));
    /* Touching the corner exactly: (2 + 3, 2 + 4) at radius 5. */
    assert_true(sx_aabb_overlaps_circle(a, sx_v2(SX_R(5.0), SX_R(6.0)), SX_R(5.0)));
    assert_false(sx_aabb_overlaps_circle(a, sx_v2(SX_R(1.0), R_NAN), SX_R(5.0)));
    for (k = 0; k < 1000; ++k) {
        sx_vec2 c = rnd_vec(&rng, -4.0, 6.0);
        sx_real r = sx_test_rng_range(&rng, 0.0, 2.0);
        /* Reference in double: per-axis distance outside the box. */
        double dx = fmax(0.0, fmax(-(double)c.x, (double)c.x - 2.0));
        double dy = fmax(0.0, fmax(-(double)c.y, (double)c.y - 2.0));
        double d = sqrt(dx * dx + dy * dy);
        if (fabs(d - (double)r) < 1e-3) continue;
        assert_true(sx_aabb_overlaps_circle(a, c, r) == (d < (double)r));
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(scalar_min_max_abs_pick_the_right_value),
        cmocka_unit_test(clamp_keeps_inside_values_and_clamps_outside_ones),
        cmocka_unit_test(clamp_with_crossed_bounds_returns_lo),
        cmocka_unit_test(is_finite_rejects_nan_and_both_infinities),
        cmocka_unit_test(sqrt_sin_cos_atan2_floor_match_libm),
        cmocka_unit_test(vec2_arithmetic_matches_hand_values),
        cmocka_unit_test(vec2_add_sub_neg_obey_the_group_laws),
        cmocka_unit_test(dot_and_cross_match_hand_values),
        cmocka_unit_test(cross_is_positive_when_b_is_counter_clockwise_of_a),
        cmocka_unit_test(cross_vs_and_cross_sv_are_the_3d_cross_products),
        cmocka_unit_test(perp_is_a_counter_clockwise_quarter_turn),
        cmocka_unit_test(length_and_distance_match_hand_values),
        cmocka_unit_test(normalize_gives_a_unit_vector_and_reports_the_length),
        cmocka_unit_test(normalize_of_zero_tiny_or_non_finite_gives_zero_and_length_zero),
        cmocka_unit_test(normalize_of_a_huge_vector_does_not_overflow),
        cmocka_unit_test(is_normalized_accepts_lengths_within_100_epsilon_of_one),
        cmocka_unit_test(lerp_interpolates_and_extrapolates),
        cmocka_unit_test(vmin_vmax_vabs_vclamp_work_per_component),
        cmocka_unit_test(approx_equal_is_an_inclusive_per_component_tolerance),
        cmocka_unit_test(vec2_is_finite_checks_both_components),
        cmocka_unit_test(rot_make_matches_hand_values),
        cmocka_unit_test(rot_angle_round_trips_over_minus_pi_to_pi),
        cmocka_unit_test(rot_normalize_rescales_and_zero_or_non_finite_gives_identity),
        cmocka_unit_test(rot_integrate_small_steps_add_up_to_the_angle),
        cmocka_unit_test(rotate_and_inv_rotate_undo_each_other),
        cmocka_unit_test(rot_mul_composes_by_adding_angles),
        cmocka_unit_test(rot_inv_mul_gives_the_relative_rotation_and_rot_inv_undoes),
        cmocka_unit_test(xform_make_places_the_origin_and_turns),
        cmocka_unit_test(xform_point_and_vector_round_trip_through_their_inverses),
        cmocka_unit_test(xform_mul_applies_b_first),
        cmocka_unit_test(xform_inv_mul_equals_mul_of_the_inverse),
        cmocka_unit_test(xform_invert_round_trips),
        cmocka_unit_test(xform_is_finite_rejects_nan_and_infinity_anywhere),
        cmocka_unit_test(mat3_constructors_have_the_course_entries),
        cmocka_unit_test(mat3_mul_matches_the_hand_product),
        cmocka_unit_test(mat3_mul_applies_b_first_translate_then_rotate_differs),
        cmocka_unit_test(mat3_points_use_w_one_and_vectors_w_zero),
        cmocka_unit_test(mat3_identity_is_neutral_and_transpose_swaps),
        cmocka_unit_test(mat3_mul_is_associative_on_random_matrices),
        cmocka_unit_test(mat3_determinant_matches_hand_values_and_the_product_rule),
        cmocka_unit_test(mat3_inverse_matches_hand_values),
        cmocka_unit_test(mat3_inverse_round_trips_on_random_invertible_matrices),
        cmocka_unit_test(mat3_inverse_of_translate_rotate_scale_is_the_reversed_product),
        cmocka_unit_test(mat3_inverse_of_singular_matrix_returns_false_and_writes_identity),
        cmocka_unit_test(mat3_from_xform_agrees_with_xform_on_points_and_vectors),
        cmocka_unit_test(mat3_to_xform_accepts_rigid_matrices_within_tolerance),
        cmocka_unit_test(mat3_to_xform_rejects_scale_shear_reflection_projection_but_extracts),
        cmocka_unit_test(aabb_make_and_is_valid),
        cmocka_unit_test(aabb_from_points_is_the_tightest_box),
        cmocka_unit_test(aabb_from_no_points_is_the_identity_of_union),
        cmocka_unit_test(aabb_from_points_with_a_nan_point_is_invalid),
        cmocka_unit_test(aabb_union_contains_both_boxes),
        cmocka_unit_test(aabb_overlaps_counts_touching_and_rejects_separation_on_either_axis),
        cmocka_unit_test(aabb_contains_whole_boxes_with_shared_edges),
        cmocka_unit_test(aabb_contains_point_counts_the_boundary),
        cmocka_unit_test(aabb_center_extents_perimeter_area_match_hand_values),
        cmocka_unit_test(aabb_fatten_grows_every_side_by_the_margin),
        cmocka_unit_test(aabb_closest_point_clamps_outside_and_keeps_inside),
        cmocka_unit_test(aabb_overlaps_circle_handles_edges_and_corners),
    };
    return cmocka_run_group_tests_name("math", tests, sx_test_group_setup, sx_test_group_teardown);
}
