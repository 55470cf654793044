/* sepax tests — shared support (see test_support.h). */
#include <stdio.h>

#include "test_support.h"

static void sx_test_assert_handler(const char *expression, const char *file, int line,
                                   void *context) {
    (void)context;
    print_error("SX_ASSERT(%s) failed\n", expression);
    _fail(file, line);
}

void sx_test_route_asserts(void) { sx_set_assert_handler(sx_test_assert_handler, NULL); }

static size_t s_group_live_bytes;

int sx_test_group_setup(void **state) {
    (void)state;
    sx_test_route_asserts();
    s_group_live_bytes = sx_live_bytes();
    return 0;
}

int sx_test_group_teardown(void **state) {
    (void)state;
    if (sx_live_bytes() != s_group_live_bytes) {
        print_error("sepax: %lu bytes leaked by this group\n",
                    (unsigned long)(sx_live_bytes() - s_group_live_bytes));
        return -1;
    }
    return 0;
}

void sx_test_assert_near(double a, double b, double tol, const char *ea, const char *eb,
                         const char *file, int line) {
    double d = a - b;
    if (d < 0) d = -d;
    if (!(d <= tol)) {
        print_error("%s = %.17g and %s = %.17g differ by %.3g > %.3g\n", ea, a, eb, b, d, tol);
        _fail(file, line);
    }
}

sx_test_rng sx_test_rng_make(uint64_t seed) {
    sx_test_rng r;
    r.state = seed;
    return r;
}

uint64_t sx_test_rng_next(sx_test_rng *rng) {
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double sx_test_rng_unit(sx_test_rng *rng) {
    return (double)(sx_test_rng_next(rng) >> 11) * (1.0 / 9007199254740992.0);
}

sx_real sx_test_rng_range(sx_test_rng *rng, double lo, double hi) {
    return (sx_real)(lo + (hi - lo) * sx_test_rng_unit(rng));
}

int sx_test_comb_outline(sx_vec2 *p, int teeth) {
    int n = 0, k;
    p[n++] = sx_v2(SX_R(0.0), SX_R(0.0));
    p[n++] = sx_v2((sx_real)(2 * teeth - 1), SX_R(0.0));
    for (k = teeth - 1; k >= 0; --k) {
        sx_real x0 = (sx_real)(2 * k), x1 = x0 + SX_R(1.0);
        p[n++] = sx_v2(x1, SX_R(3.0));
        p[n++] = sx_v2(x0, SX_R(3.0));
        if (k > 0) {
            p[n++] = sx_v2(x0, SX_R(1.0));
            p[n++] = sx_v2(x0 - SX_R(1.0), SX_R(1.0));
        }
    }
    return n;
}

sx_shape sx_test_random_ngon(sx_test_rng *rng, int n, double rmin, double rmax) {
    sx_vec2 pts[SX_MAX_POLYGON_VERTICES];
    sx_shape shape;
    int k;
    assert_true(n >= 3 && n <= SX_MAX_POLYGON_VERTICES);
    for (k = 0; k < n; ++k) {
        sx_real a = SX_R(2.0) * SX_PI * (sx_real)k / (sx_real)n;
        sx_real r = sx_test_rng_range(rng, rmin, rmax);
        pts[k] = sx_v2(r * sx_cos(a), r * sx_sin(a));
    }
    assert_int_equal(sx_polygon_shape(pts, n, SX_R(0.0), &shape), SX_OK);
    return shape;
}

sx_body_id sx_test_body(sx_world *w, sx_body_type type, sx_vec2 p, sx_shape shape,
                        sx_collider_id *collider) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id id;
    bd.type = type;
    bd.position = p;
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    cd.shape = shape;
    assert_int_equal(sx_body_add_collider(w, id, &cd, collider), SX_OK);
    return id;
}

sx_body_id sx_test_body_turned(sx_world *w, sx_body_type type, sx_vec2 p, sx_real angle,
                               const sx_collider_def *cd) {
    sx_body_def bd = sx_default_body_def();
    sx_body_id id;
    bd.type = type;
    bd.position = p;
    bd.angle = angle;
    assert_int_equal(sx_create_body(w, &bd, &id), SX_OK);
    assert_int_equal(sx_body_add_collider(w, id, cd, NULL), SX_OK);
    return id;
}
