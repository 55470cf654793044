/* sepax tests — determinism: the same scene and command sequence give the
 * same state, bit for bit.
 *
 * A scene (a pyramid, mixed shapes, a kinematic paddle, a sensor) runs 240
 * steps while a fixed script creates and destroys bodies and colliders,
 * applies forces, torques and impulses, teleports and sets velocities; then
 * every body's position, angle and velocities are hashed (FNV-1a over the
 * bytes of each sx_real) with the contact count. Within one program: two runs
 * give the same hash, and a run with one impulse changed by one ulp gives a
 * different one (so the hash does see the state). The hash is printed as
 *
 *     sepax determinism hash: <16 hex digits>
 *
 * and `make determinism` builds this program with the library at -O0, -O2
 * and -O3 and checks the three hashes agree: the results do not depend on
 * the optimisation level. That holds because the library is compiled with
 * -ffp-contract=off (no fused multiply-add contraction, which would round
 * a*b+c once instead of twice at some levels and not others), never with
 * -ffast-math or any flag that lets the compiler reassociate, and because
 * the library's own order of work is fixed (bodies, colliders and pairs in
 * slot order; no threads, no hashing of pointers). x86-64 evaluates float and
 * double in SSE registers at every level (FLT_EVAL_METHOD 0), so no excess
 * precision differs between levels either. Measured with gcc 12 on x86-64:
 * -O0, -O2 and -O3 give the same hash; -O2 -march=haswell (which has FMA)
 * gives that same hash with -ffp-contract=off and a different one with
 * -ffp-contract=fast. Across compilers, C libraries (sinf/cosf/atan2f) or
 * CPU architectures the hash may differ.
 *
 * Both hashes are compared with the values pinned below, so a change of the
 * answers fails here even when every other test still passes. */
#include <stdio.h>
#include <string.h>

#include "test_support.h"

/* ---- the pinned hashes -------------------------------------------------------
 *
 * What the scene and the narrowphase hash to, one line per build, with the
 * toolchain CI uses (gcc 12, glibc, x86-64). The float line holds for the
 * SSE and the SIMD=0 builds, every optimisation level and SAN=1; the double
 * line for SX_REAL=double. When a change alters the answers on purpose (a
 * solver fix, a new narrowphase route), the failure prints the line to put
 * here: replace the build's line with it and say in the commit message why
 * the answers changed. Never update a line to make an unexplained failure
 * pass. */
typedef struct det_pin {
    const char *build;
    uint64_t state, narrowphase;
} det_pin;

static const det_pin det_pins[] = {
    /* build    state hash             narrowphase hash */
    {"float", 0xc85f167e445f7786ull, 0x4d1bf48ab77e19cbull},
    {"double", 0x6e559b13d4de8298ull, 0x8963162b0ec798e3ull},
};

#ifdef SX_DOUBLE
#define DET_PIN (&det_pins[1])
#else
#define DET_PIN (&det_pins[0])
#endif

static uint64_t det_run(bool nudge);
static uint64_t narrowphase_hash(void);

/* Fails, printing the line to pin (both hashes as they are now), when `got`
 * is not the pinned `want`. */
static void det_check_pin(const char *what, uint64_t got, uint64_t want) {
    const det_pin *pin = DET_PIN;
    if (got == want) return;
    printf("sepax determinism: the %s hash of the %s build is %016llx, pinned %016llx.\n"
           "  The answers changed. If that is intended, replace the %s line of det_pins in\n"
           "  tests/test_determinism.c with the line below and give the reason in the commit\n"
           "  message; otherwise find the change that did it.\n"
           "    {\"%s\", 0x%016llxull, 0x%016llxull},\n",
           what, pin->build, (unsigned long long)got, (unsigned long long)want, pin->build,
           pin->build, (unsigned long long)det_run(false), (unsigned long long)narrowphase_hash());
    fail_msg("%s hash %016llx differs from the pinned %016llx", what, (unsigned long long)got,
             (unsigned long long)want);
}

#define DT (SX_R(1.0) / SX_R(60.0))

typedef struct det_hash {
    uint64_t h;
} det_hash;

static void det_add(det_hash *d, const void *p, size_t n) {
    const unsigned char *b = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i) {
        d->h ^= b[i];
        d->h *= 1099511628211ull;
    }
}

static void det_add_real(det_hash *d, sx_real v) {
    if (v == SX_R(0.0)) v = SX_R(0.0); /* -0 and +0 hash alike */
    det_add(d, &v, sizeof v);
}

static sx_body_id det_body(sx_world *w, sx_body_type type, sx_vec2 p, sx_real angle,
                           const sx_shape *shape, bool sensor) {
    sx_collider_def cd = sx_default_collider_def();
    cd.shape = *shape;
    cd.sensor = sensor;
    cd.restitution = type == SX_BODY_DYNAMIC && (p.x > SX_R(3.0)) ? SX_R(0.4) : SX_R(0.0);
    return sx_test_body_turned(w, type, p, angle, &cd);
}

/* Runs the scene and its script; `nudge` changes one impulse by one ulp. */
static uint64_t det_run(bool nudge) {
    sx_world_def def = sx_default_world_def();
    sx_world *w;
    sx_test_rng rng = sx_test_rng_make(77u);
    sx_shape ground = sx_box_shape(SX_R(15.0), SX_R(1.0)), box = sx_box_shape(SX_R(0.5), SX_R(0.5));
    sx_shape paddle = sx_box_shape(SX_R(1.5), SX_R(0.1)), zone = sx_box_shape(SX_R(2.0), SX_R(2.0));
    sx_body_id ids[64], stir;
    det_hash d;
    int n = 0, i, j, s, slots = 0;
    def.enable_sleep = true;
    w = sx_world_create(&def);
    assert_non_null(w);
    det_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)), SX_R(0.0), &ground, false);
    det_body(w, SX_BODY_STATIC, sx_v2(SX_R(8.0), SX_R(2.0)), SX_R(0.0), &zone, true);
    for (i = 0; i < 6; ++i) {
        for (j = i; j < 6; ++j) {
            sx_vec2 p = sx_v2((sx_real)((double)(i + 1) * 0.5 + (double)(j - i) - 6.0),
                              (sx_real)((double)(2 * i + 1) * 0.5));
            ids[n++] = det_body(w, SX_BODY_DYNAMIC, p, SX_R(0.0), &box, false);
        }
    }
    for (i = 0; i < 12; ++i) {
        sx_vec2 p = sx_v2(sx_test_rng_range(&rng, 2.0, 10.0), sx_test_rng_range(&rng, 1.0, 8.0));
        sx_shape sh;
        switch (i % 3) {
        case 0: sh = sx_circle_shape(sx_v2_zero(), sx_test_rng_range(&rng, 0.2, 0.4)); break;
        case 1:
            sh = sx_capsule_shape(sx_v2(SX_R(-0.3), SX_R(0.0)), sx_v2(SX_R(0.3), SX_R(0.0)),
                                  SX_R(0.15));
            break;
        default: sh = sx_test_random_ngon(&rng, 6, 0.2, 0.4); break;
        }
        ids[n++] = det_body(w, SX_BODY_DYNAMIC, p, sx_test_rng_range(&rng, 0.0, 3.0), &sh, false);
    }
    {
        sx_body_def bd = sx_default_body_def();
        sx_collider_def cd = sx_default_collider_def();
        bd.type = SX_BODY_KINEMATIC;
        bd.position = sx_v2(SX_R(-10.0), SX_R(1.0));
        bd.angular_velocity = SX_R(2.0);
        assert_int_equal(sx_create_body(w, &bd, &stir), SX_OK);
        cd.shape = paddle;
        assert_int_equal(sx_body_add_collider(w, stir, &cd, NULL), SX_OK);
    }
    for (s = 0; s < 240; ++s) {
        /* the script */
        if (s == 20) {
            sx_real jx = SX_R(4.0);
            if (nudge) jx = jx + jx * SX_REAL_EPSILON;
            assert_int_equal(sx_body_apply_impulse_at_point(w, ids[n - 1], sx_v2(jx, SX_R(2.0)),
                                                            sx_v2(SX_R(5.0), SX_R(5.0))),
                             SX_OK);
        }
        if (s >= 30 && s < 90)
            assert_int_equal(sx_body_apply_force(w, ids[3], sx_v2(SX_R(-3.0), SX_R(0.0))), SX_OK);
        if (s == 45) assert_int_equal(sx_body_apply_torque(w, ids[25], SX_R(5.0)), SX_OK);
        if (s == 60) {
            assert_int_equal(sx_destroy_body(w, ids[20]), SX_OK);
            ids[20] =
                det_body(w, SX_BODY_DYNAMIC, sx_v2(SX_R(0.0), SX_R(8.0)), SX_R(0.3), &box, false);
        }
        if (s == 80)
            assert_int_equal(
                sx_body_set_transform(w, ids[22], sx_v2(SX_R(6.0), SX_R(6.0)), SX_R(1.0)), SX_OK);
        if (s == 100)
            assert_int_equal(sx_body_set_linear_velocity(w, ids[23], sx_v2(SX_R(-6.0), SX_R(3.0))),
                             SX_OK);
        if (s == 120) assert_int_equal(sx_body_set_angular_velocity(w, ids[24], SX_R(-4.0)), SX_OK);
        if (s == 140) {
            sx_collider_def cd = sx_default_collider_def();
            cd.shape =
                sx_offset_box_shape(SX_R(0.2), SX_R(0.6), sx_v2(SX_R(0.4), SX_R(0.0)), SX_R(0.5));
            cd.density = SX_R(3.0);
            assert_int_equal(sx_body_add_collider(w, ids[10], &cd, NULL), SX_OK);
        }
        if (s == 160) assert_int_equal(sx_body_set_type(w, ids[0], SX_BODY_STATIC), SX_OK);
        if (s == 180)
            assert_int_equal(sx_world_set_gravity(w, sx_v2(SX_R(1.0), SX_R(-9.0))), SX_OK);
        if (s == 200)
            assert_int_equal(sx_body_apply_angular_impulse(w, ids[n - 2], SX_R(1.5)), SX_OK);
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    }
    d.h = 14695981039346656037ull;
    for (i = 0; i < n; ++i) {
        sx_vec2 p = sx_body_get_position(w, ids[i]), v = sx_body_get_linear_velocity(w, ids[i]);
        det_add_real(&d, p.x);
        det_add_real(&d, p.y);
        det_add_real(&d, sx_body_get_angle(w, ids[i]));
        det_add_real(&d, v.x);
        det_add_real(&d, v.y);
        det_add_real(&d, sx_body_get_angular_velocity(w, ids[i]));
        slots += sx_body_is_awake(w, ids[i]) ? 1 : 0;
    }
    det_add_real(&d, sx_body_get_angle(w, stir));
    i = sx_world_contact_count(w);
    det_add(&d, &i, sizeof i);
    det_add(&d, &slots, sizeof slots);
    sx_world_destroy(w);
    return d.h;
}

static void same_scene_and_commands_give_bit_identical_state(void **state) {
    uint64_t a = det_run(false), b = det_run(false), c = det_run(true);
    (void)state;
    printf("sepax determinism hash: %016llx\n", (unsigned long long)a);
    printf("  second run %016llx, with one impulse one ulp larger %016llx\n", (unsigned long long)b,
           (unsigned long long)c);
    assert_true(a == b);
    assert_true(a != c);
    det_check_pin("state", a, DET_PIN->state);
}

/* A random shape of kind k (0 circle, 1 segment, 2 capsule, 3 box, 4 sharp
 * 3..8-gon, 5 rounded 3..8-gon), about unit size. */
static sx_shape det_shape(sx_test_rng *rng, int k) {
    sx_vec2 a = sx_v2(sx_test_rng_range(rng, -1.0, 1.0), sx_test_rng_range(rng, -1.0, 1.0));
    sx_vec2 b = sx_v2(sx_test_rng_range(rng, -1.0, 1.0), sx_test_rng_range(rng, -1.0, 1.0));
    sx_shape s;
    switch (k) {
    case 0: return sx_circle_shape(a, sx_test_rng_range(rng, 0.1, 1.0));
    case 1: return sx_segment_shape(a, b);
    case 2: return sx_capsule_shape(a, b, sx_test_rng_range(rng, 0.05, 0.5));
    case 3: return sx_box_shape(sx_test_rng_range(rng, 0.1, 1.0), sx_test_rng_range(rng, 0.1, 1.0));
    default:
        s = sx_test_random_ngon(rng, 3 + (int)(sx_test_rng_next(rng) % 6u), 0.3, 1.2);
        if (k == 5) s.u.polygon.radius = sx_test_rng_range(rng, 0.02, 0.3);
        return s;
    }
}

/* Hashes one pair's narrowphase answers: overlap, MTV and the manifolds at
 * margins 0 and 0.05, in the given order. */
static void det_add_pair(det_hash *d, const sx_shape *a, sx_xform xa, const sx_shape *b,
                         sx_xform xb) {
    sx_manifold m[2];
    sx_vec2 mtv;
    int ov = sx_overlap(a, xa, b, xb), hit = sx_mtv(a, xa, b, xb, &mtv), c, j;
    det_add(d, &ov, sizeof ov);
    det_add(d, &hit, sizeof hit);
    det_add_real(d, mtv.x);
    det_add_real(d, mtv.y);
    (void)sx_collide(a, xa, b, xb, &m[0]);
    (void)sx_collide_ex(a, xa, b, xb, SX_R(0.05), &m[1]);
    for (c = 0; c < 2; ++c) {
        det_add(d, &m[c].count, sizeof m[c].count);
        det_add_real(d, m[c].normal.x);
        det_add_real(d, m[c].normal.y);
        for (j = 0; j < m[c].count; ++j) {
            det_add_real(d, m[c].points[j].point.x);
            det_add_real(d, m[c].points[j].point.y);
            det_add_real(d, m[c].points[j].depth);
            det_add(d, &m[c].points[j].id, sizeof m[c].points[j].id);
        }
    }
}

/* Hashes every narrowphase answer over random pairs of every kind and
 * order, in four kinds of placement: unit shapes near the origin; turned
 * by multiples of a quarter turn (exact zeros in the rotations: the signs
 * of zero and the axis-aligned box path); 1e4 m from the origin; and moved
 * onto touching by the MTV, give or take a few ulps (the rounding ties of
 * the reference face and the touch rescue). The float build's SSE loops
 * and fused routines (src/narrow_core.c, src/collide.c) and the portable
 * ones (make ... SIMD=0) must print the same hash, as must every
 * optimisation level (see .ci/run). */
static uint64_t narrowphase_hash(void) {
    sx_test_rng rng = sx_test_rng_make(2026u);
    det_hash d;
    int ka, kb, i, mode;
    d.h = 14695981039346656037ull;
    for (mode = 0; mode < 4; ++mode) {
        for (ka = 0; ka < 6; ++ka) {
            for (kb = 0; kb < 6; ++kb) {
                for (i = 0; i < (mode == 0 ? 2000 : 500); ++i) {
                    sx_shape a = det_shape(&rng, ka), b = det_shape(&rng, kb);
                    double ra = sx_test_rng_range(&rng, -4.0, 4.0);
                    double rb = sx_test_rng_range(&rng, -4.0, 4.0);
                    double o = mode == 2 ? 1e4 : 0.0;
                    sx_xform xa, xb;
                    if (mode == 1) {
                        ra = (double)(sx_test_rng_next(&rng) % 4u) * 1.5707963267948966;
                        rb = (double)(sx_test_rng_next(&rng) % 4u) * 1.5707963267948966;
                    }
                    xa = sx_xform_make(sx_v2(sx_test_rng_range(&rng, o - 3.0, o + 3.0),
                                             sx_test_rng_range(&rng, -o - 3.0, -o + 3.0)),
                                       (sx_real)ra);
                    xb = sx_xform_make(sx_add(xa.p, sx_v2(sx_test_rng_range(&rng, -2.5, 2.5),
                                                          sx_test_rng_range(&rng, -2.5, 2.5))),
                                       (sx_real)rb);
                    if (mode == 3) {
                        sx_vec2 v;
                        if (sx_mtv(&b, xb, &a, xa, &v)) {
                            double f =
                                1.0 + (double)((int)(sx_test_rng_next(&rng) % 9u) - 4) * 1e-7;
                            xb.p = sx_add(xb.p, sx_scale(v, (sx_real)f));
                        }
                    }
                    det_add_pair(&d, &a, xa, &b, xb);
                }
            }
        }
    }
    return d.h;
}

static void narrowphase_answers_hash_the_same_every_run(void **state) {
    uint64_t a = narrowphase_hash(), b = narrowphase_hash();
    (void)state;
    printf("sepax narrowphase hash: %016llx\n", (unsigned long long)a);
    assert_true(a == b);
    det_check_pin("narrowphase", a, DET_PIN->narrowphase);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(same_scene_and_commands_give_bit_identical_state),
        cmocka_unit_test(narrowphase_answers_hash_the_same_every_run),
    };
    return cmocka_run_group_tests_name("determinism", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
