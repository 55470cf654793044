/* sepax tests — separate worlds on separate threads.
 *
 * The library promises (base.h, world.h) that worlds share nothing, so two
 * threads may each create, step and destroy their own worlds at the same
 * time, with the default allocator or with a thread-safe custom one. Each
 * worker runs the same small scene in a loop and compares the final state,
 * bit for bit, with the state the main thread got from the same scene run
 * alone: any shared state that one thread's world leaks into the other's
 * shows up as a different digest, a failed allocation, or (for an unsafe
 * live-byte counter) an assertion. make test SAN=thread runs this program
 * under ThreadSanitizer, which reports any data race between the workers.
 *
 * cmocka's assertions are not thread-safe (they longjmp), so the workers only
 * record what they saw and the main thread asserts after joining them. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"
/* after sepax's headers: sx_task_pool_use needs sx_world_def */
#include "../samples/task_pool.h"

#define DT (SX_R(1.0) / SX_R(60.0))
#define WORKERS 2
#define STEPS 30

/* A small pile that touches, collides and allocates as it grows: a ground
 * box and a column of boxes and circles dropped on it. */
static sx_world *make_scene(int bodies, sx_body_id *ids) {
    sx_world_def wd = sx_default_world_def();
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_body_id ground;
    sx_world *w = sx_world_create(&wd);
    int i;
    if (w == NULL) return NULL;
    bd.position = sx_v2(SX_R(0.0), SX_R(-1.0));
    cd.shape = sx_box_shape(SX_R(20.0), SX_R(1.0));
    if (sx_create_body(w, &bd, &ground) != SX_OK ||
        sx_body_add_collider(w, ground, &cd, NULL) != SX_OK) {
        sx_world_destroy(w);
        return NULL;
    }
    bd.type = SX_BODY_DYNAMIC;
    for (i = 0; i < bodies; ++i) {
        bd.position = sx_v2(SX_R(0.1) * (sx_real)(i % 3), SX_R(0.5) + SX_R(1.05) * (sx_real)i);
        cd.shape = i % 2 == 0 ? sx_box_shape(SX_R(0.5), SX_R(0.5))
                              : sx_circle_shape(sx_v2_zero(), SX_R(0.5));
        if (sx_create_body(w, &bd, &ids[i]) != SX_OK ||
            sx_body_add_collider(w, ids[i], &cd, NULL) != SX_OK) {
            sx_world_destroy(w);
            return NULL;
        }
    }
    return w;
}

/* FNV-1a over the bytes of the bodies' positions, angles and velocities. */
static uint64_t digest(const sx_world *w, const sx_body_id *ids, int bodies) {
    uint64_t h = 1469598103934665603ull;
    int i;
    for (i = 0; i < bodies; ++i) {
        sx_real v[6];
        const unsigned char *p = (const unsigned char *)v;
        size_t k;
        sx_vec2 x = sx_body_get_position(w, ids[i]), u = sx_body_get_linear_velocity(w, ids[i]);
        v[0] = x.x;
        v[1] = x.y;
        v[2] = sx_body_get_angle(w, ids[i]);
        v[3] = u.x;
        v[4] = u.y;
        v[5] = sx_body_get_angular_velocity(w, ids[i]);
        for (k = 0; k < sizeof v; ++k)
            h = (h ^ p[k]) * 1099511628211ull;
    }
    return h;
}

/* One run of the scene: create, step, read the digest, destroy. 0 when the
 * world could not be made or a step failed. */
static uint64_t run_scene(int bodies) {
    sx_body_id ids[32];
    sx_world *w = make_scene(bodies, ids);
    uint64_t h;
    int s;
    if (w == NULL) return 0;
    for (s = 0; s < STEPS; ++s) {
        if (sx_world_step(w, DT) != SX_OK) {
            sx_world_destroy(w);
            return 0;
        }
    }
    h = digest(w, ids, bodies);
    sx_world_destroy(w);
    return h;
}

typedef struct worker {
    pthread_t thread;
    int bodies, rounds;
    uint64_t expected;
    int mismatches; /* rounds whose digest differed from the lone run's */
} worker;

static void *work(void *arg) {
    worker *wk = (worker *)arg;
    int r;
    for (r = 0; r < wk->rounds; ++r) {
        if (run_scene(wk->bodies) != wk->expected) wk->mismatches++;
    }
    return NULL;
}

/* Runs WORKERS threads, each `rounds` times its own scene (worker k drops
 * 6 + 5 k bodies, so the worlds differ), and checks every round's state
 * against the lone run and that every byte came back. */
static void run_workers(int rounds) {
    worker wk[WORKERS];
    size_t live = sx_live_bytes();
    int k;
    for (k = 0; k < WORKERS; ++k) {
        memset(&wk[k], 0, sizeof wk[k]);
        wk[k].bodies = 6 + 5 * k;
        wk[k].rounds = rounds;
        wk[k].expected = run_scene(wk[k].bodies);
        assert_true(wk[k].expected != 0);
    }
    assert_true(sx_live_bytes() == live);
    for (k = 0; k < WORKERS; ++k)
        assert_int_equal(pthread_create(&wk[k].thread, NULL, work, &wk[k]), 0);
    for (k = 0; k < WORKERS; ++k)
        assert_int_equal(pthread_join(wk[k].thread, NULL), 0);
    for (k = 0; k < WORKERS; ++k)
        assert_int_equal(wk[k].mismatches, 0);
    assert_true(sx_live_bytes() == live);
}

static void two_threads_create_step_and_destroy_their_own_worlds(void **state) {
    (void)state;
    run_workers(200);
}

/* A custom allocator must be thread-safe itself (base.h); this one counts
 * its blocks and bytes under a mutex. */
typedef struct locked_counter {
    pthread_mutex_t lock;
    long blocks;
    size_t bytes;
} locked_counter;

static void *counting_alloc(size_t size, void *context) {
    locked_counter *c = (locked_counter *)context;
    void *p = malloc(size);
    pthread_mutex_lock(&c->lock);
    if (p != NULL) {
        c->blocks++;
        c->bytes += size;
    }
    pthread_mutex_unlock(&c->lock);
    return p;
}

static void counting_free(void *memory, size_t size, void *context) {
    locked_counter *c = (locked_counter *)context;
    pthread_mutex_lock(&c->lock);
    c->blocks--;
    c->bytes -= size;
    pthread_mutex_unlock(&c->lock);
    free(memory);
}

static void two_threads_share_a_thread_safe_custom_allocator(void **state) {
    locked_counter c;
    (void)state;
    memset(&c, 0, sizeof c);
    assert_int_equal(pthread_mutex_init(&c.lock, NULL), 0);
    /* set once, before any world exists, as base.h asks */
    sx_set_allocator(counting_alloc, counting_free, &c);
    run_workers(100);
    sx_set_allocator(NULL, NULL, NULL);
    /* every block and byte the worlds took came back through the hook */
    assert_int_equal(c.blocks, 0);
    assert_true(c.bytes == 0);
    assert_int_equal(pthread_mutex_destroy(&c.lock), 0);
}

/* ---- a world's own steps on a job system (sx_world_def.enqueue_task) ----- */

/* A pyramid of base 20 on the ground (about 600 broadphase pairs, above the
 * fewest worth a task), an L-shaped compound dropped on it (its pairs are
 * collided in the walk) and a box whose filter lets it pass through the
 * boxes (pairs that make no contact). Built and stepped on the test's own
 * thread, so it asserts as it goes. */
#define JOB_BODIES 212
#define JOB_STEPS 150

static sx_world *make_job_scene(const sx_world_def *wd, sx_body_id *ids) {
    sx_body_def bd = sx_default_body_def();
    sx_collider_def cd = sx_default_collider_def();
    sx_compound_part parts[2];
    sx_compound l_shape;
    sx_world *w = sx_world_create(wd);
    int i, j, n = 0;
    assert_non_null(w);
    sx_test_body(w, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-1.0)),
                 sx_box_shape(SX_R(40.0), SX_R(1.0)), NULL);
    for (i = 0; i < 20; ++i) {
        for (j = i; j < 20; ++j) {
            sx_vec2 p = sx_v2((sx_real)(i + 1) * SX_R(0.5) + (sx_real)(j - i) - SX_R(10.0),
                              (sx_real)(2 * i + 1) * SX_R(0.5));
            ids[n++] = sx_test_body(w, SX_BODY_DYNAMIC, p, sx_box_shape(SX_R(0.5), SX_R(0.5)), NULL);
        }
    }
    parts[0] = sx_compound_part_make(sx_box_shape(SX_R(1.0), SX_R(0.25)), sx_xform_identity());
    parts[1] = sx_compound_part_make(sx_box_shape(SX_R(0.25), SX_R(1.0)),
                                     sx_xform_make(sx_v2(SX_R(0.75), SX_R(0.75)), SX_R(0.0)));
    l_shape.parts = parts;
    l_shape.count = 2;
    bd.type = SX_BODY_DYNAMIC;
    bd.position = sx_v2(SX_R(-3.0), SX_R(23.0));
    assert_int_equal(sx_create_body(w, &bd, &ids[n]), SX_OK);
    assert_int_equal(sx_body_add_compound(w, ids[n++], &l_shape, &cd, NULL), SX_OK);
    cd.shape = sx_box_shape(SX_R(0.5), SX_R(0.5));
    cd.filter.mask = 0; /* meets nothing */
    ids[n++] = sx_test_body_turned(w, SX_BODY_DYNAMIC, sx_v2(SX_R(2.0), SX_R(25.0)), SX_R(0.0), &cd);
    assert_int_equal(n, JOB_BODIES);
    return w;
}

/* The digest of the job scene after JOB_STEPS steps with these settings. */
static uint64_t run_job_scene(const sx_world_def *wd) {
    sx_body_id ids[JOB_BODIES];
    sx_world *w = make_job_scene(wd, ids);
    uint64_t h;
    int s;
    for (s = 0; s < JOB_STEPS; ++s)
        assert_int_equal(sx_world_step(w, DT), SX_OK);
    h = digest(w, ids, JOB_BODIES);
    sx_world_destroy(w);
    return h;
}

/* Job systems of the test's own: each counts its tasks. `ranges`: how many
 * ranges it runs before returning NULL (the rest never run); -1 for all. */
typedef struct serial_jobs {
    int tasks, ranges;
} serial_jobs;

static void *serial_enqueue(sx_task_fn *task, int item_count, int min_range, void *task_context,
                            void *user_context) {
    serial_jobs *j = (serial_jobs *)user_context;
    int start, run = 0;
    j->tasks++;
    for (start = 0; start < item_count && (j->ranges < 0 || run < j->ranges); start += min_range) {
        int end = start + min_range < item_count ? start + min_range : item_count;
        task(start, end, 1, task_context);
        ++run;
    }
    return NULL;
}

static void never_finish(void *user_task, void *user_context) {
    (void)user_task;
    (void)user_context;
    fail_msg("finish_task called for a task enqueue_task ran already");
}

/* Counts the tasks of a pool (the same pool's enqueue underneath). */
typedef struct counted_pool {
    sx_task_pool pool;
    int tasks;
} counted_pool;

static void *counted_enqueue(sx_task_fn *task, int item_count, int min_range, void *task_context,
                             void *user_context) {
    counted_pool *c = (counted_pool *)user_context;
    c->tasks++;
    return sx_task_pool_enqueue(task, item_count, min_range, task_context, &c->pool);
}

static void counted_finish(void *user_task, void *user_context) {
    sx_task_pool_finish(user_task, &((counted_pool *)user_context)->pool);
}

/* The narrowphase's manifolds found by two and by three threads of a pool,
 * by a job system that runs each task before it returns, and by one that
 * drops all but the first range of each (the walk collides the rest):
 * the same bits as one thread, step after step. */
static void a_job_system_steps_a_world_to_the_same_bits(void **state) {
    sx_world_def wd = sx_default_world_def();
    serial_jobs serial = {0, -1}, partial = {0, 1};
    counted_pool pool;
    uint64_t alone, h;
    int workers;
    (void)state;
    wd.enable_sleep = false;
    alone = run_job_scene(&wd);
    for (workers = 2; workers <= 3; ++workers) {
        sx_world_def pd = wd;
        assert_true(sx_task_pool_start(&pool.pool, workers));
        pool.tasks = 0;
        sx_task_pool_use(&pool.pool, &pd);
        pd.enqueue_task = counted_enqueue;
        pd.finish_task = counted_finish;
        pd.user_task_context = &pool;
        h = run_job_scene(&pd);
        sx_task_pool_stop(&pool.pool);
        assert_true(h == alone);
        /* one task a collide: every step's pairs went through the pool */
        assert_int_equal(pool.tasks, JOB_STEPS);
    }
    {
        sx_world_def sd = wd;
        sd.enqueue_task = serial_enqueue;
        sd.finish_task = never_finish;
        sd.worker_count = 2;
        sd.user_task_context = &serial;
        assert_true(run_job_scene(&sd) == alone);
        assert_int_equal(serial.tasks, JOB_STEPS);
        sd.user_task_context = &partial;
        assert_true(run_job_scene(&sd) == alone);
        assert_int_equal(partial.tasks, JOB_STEPS);
        /* worker_count 1: no task at all */
        sd.worker_count = 1;
        serial.tasks = 0;
        sd.user_task_context = &serial;
        assert_true(run_job_scene(&sd) == alone);
        assert_int_equal(serial.tasks, 0);
    }
}

static void a_world_refuses_half_a_job_system_and_bad_worker_counts(void **state) {
    sx_world_def wd = sx_default_world_def();
    const char *field = NULL;
    serial_jobs serial = {0, -1};
    (void)state;
    wd.enqueue_task = serial_enqueue;
    assert_int_equal(sx_world_def_validate(&wd, &field), SX_ERR_INVALID_ARG);
    assert_string_equal(field, "finish_task");
    assert_null(sx_world_create(&wd));
    wd.enqueue_task = NULL;
    wd.finish_task = never_finish;
    assert_int_equal(sx_world_def_validate(&wd, &field), SX_ERR_INVALID_ARG);
    assert_string_equal(field, "enqueue_task");
    wd.enqueue_task = serial_enqueue;
    wd.user_task_context = &serial;
    wd.worker_count = 0;
    assert_int_equal(sx_world_def_validate(&wd, &field), SX_ERR_INVALID_ARG);
    assert_string_equal(field, "worker_count");
    wd.worker_count = SX_MAX_WORKERS + 1;
    assert_int_equal(sx_world_def_validate(&wd, &field), SX_ERR_CAPACITY);
    assert_string_equal(field, "worker_count");
    assert_null(sx_world_create(&wd));
    wd.worker_count = SX_MAX_WORKERS;
    assert_int_equal(sx_world_def_validate(&wd, &field), SX_OK);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(two_threads_create_step_and_destroy_their_own_worlds),
        cmocka_unit_test(two_threads_share_a_thread_safe_custom_allocator),
        cmocka_unit_test(a_job_system_steps_a_world_to_the_same_bits),
        cmocka_unit_test(a_world_refuses_half_a_job_system_and_bad_worker_counts),
    };
    int failed;
    /* An SX_ASSERT in a worker must not longjmp into cmocka from the wrong
     * thread: the default handler (print and abort) stays installed. */
    size_t live = sx_live_bytes();
    failed = cmocka_run_group_tests_name("threads", tests, NULL, NULL);
    if (sx_live_bytes() != live) {
        print_error("sepax: %lu bytes leaked\n", (unsigned long)(sx_live_bytes() - live));
        failed++;
    }
    return failed;
}
