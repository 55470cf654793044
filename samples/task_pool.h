/* sepax sample — a small job system for sx_world_def's task callbacks, on
 * POSIX threads (compile with -pthread). A game with a job system of its
 * own (flecs workers, enkiTS, a thread pool) hands that one instead; this
 * is what the two callbacks must do, in few lines:
 *
 *     sx_task_pool pool;
 *     sx_world_def def = sx_default_world_def();
 *     sx_task_pool_start(&pool, 2);              (the caller and one thread)
 *     sx_task_pool_use(&pool, &def);
 *     world = sx_world_create(&def);
 *     ... step ...
 *     sx_world_destroy(world);
 *     sx_task_pool_stop(&pool);
 *
 * Tasks wait in a queue until a worker takes their ranges, oldest first;
 * several may be under way at once (Box2D v3, which the benchmark runs on
 * this pool too, enqueues one task per worker for its solver and finishes
 * them after). The thread that calls finish is worker 0 and runs ranges of
 * the task it waits for, and only of that one: a task of another caller
 * may wait on a task that cannot start while this thread waits. The pool's
 * threads are workers 1 .. count - 1. Ranges are taken under one mutex: a
 * task is a few hundred ranges at most. It needs nothing of sepax but the
 * callback types, which it restates, so other engines' callbacks of the
 * same shape can use it. */
#ifndef SEPAX_SAMPLES_TASK_POOL_H
#define SEPAX_SAMPLES_TASK_POOL_H

#include <pthread.h>
#include <stdbool.h>

#define SX_TASK_POOL_MAX 16
#define SX_TASK_POOL_QUEUE 64

/* sx_task_fn's shape (sepax/world.h) */
typedef void sx_task_pool_fn(int start, int end, int worker, void *context);

typedef struct sx_task_pool sx_task_pool;

typedef struct sx_task_pool_thread {
    sx_task_pool *pool;
    pthread_t thread;
    int worker;
} sx_task_pool_thread;

typedef struct sx_task_pool_task {
    sx_task_pool_fn *fn;
    void *context;
    unsigned long order; /* enqueue order: the oldest task's ranges go first */
    int items, range, next, running;
    bool used;
} sx_task_pool_task;

struct sx_task_pool {
    sx_task_pool_thread threads[SX_TASK_POOL_MAX];
    sx_task_pool_task tasks[SX_TASK_POOL_QUEUE];
    int count; /* workers, the caller included */
    unsigned long enqueued;
    pthread_mutex_t lock;
    pthread_cond_t wake, done;
    bool quit;
};

/* Takes the next range of task t (lock held): false when none is left. */
static bool sx_task_pool_take(sx_task_pool_task *t, int *start, int *end) {
    if (!t->used || t->next >= t->items) return false;
    *start = t->next;
    *end = t->next + t->range < t->items ? t->next + t->range : t->items;
    t->next = *end;
    t->running++;
    return true;
}

/* Runs [start, end) of t with the lock released, then counts it done. */
static void sx_task_pool_run(sx_task_pool *p, sx_task_pool_task *t, int start, int end,
                             int worker) {
    pthread_mutex_unlock(&p->lock);
    t->fn(start, end, worker, t->context);
    pthread_mutex_lock(&p->lock);
    if (--t->running == 0 && t->next >= t->items) pthread_cond_broadcast(&p->done);
}

/* The oldest task with a range left (lock held), or NULL. */
static sx_task_pool_task *sx_task_pool_oldest(sx_task_pool *p) {
    sx_task_pool_task *best = NULL;
    int i;
    for (i = 0; i < SX_TASK_POOL_QUEUE; ++i) {
        sx_task_pool_task *t = &p->tasks[i];
        if (t->used && t->next < t->items && (best == NULL || t->order < best->order)) best = t;
    }
    return best;
}

static void *sx_task_pool_main(void *arg) {
    sx_task_pool_thread *th = (sx_task_pool_thread *)arg;
    sx_task_pool *p = th->pool;
    pthread_mutex_lock(&p->lock);
    while (!p->quit) {
        sx_task_pool_task *t = sx_task_pool_oldest(p);
        int start, end;
        if (t != NULL && sx_task_pool_take(t, &start, &end))
            sx_task_pool_run(p, t, start, end, th->worker);
        else
            pthread_cond_wait(&p->wake, &p->lock);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

/* sx_enqueue_task_fn: NULL when the queue is full (the task ran inline). */
static void *sx_task_pool_enqueue(sx_task_pool_fn *fn, int item_count, int min_range,
                                  void *task_context, void *user_context) {
    sx_task_pool *p = (sx_task_pool *)user_context;
    sx_task_pool_task *t = NULL;
    /* about four ranges a worker, so one slow range does not hold the rest */
    int range = item_count / (4 * p->count), i;
    if (range < min_range) range = min_range;
    if (range < 1) range = 1;
    pthread_mutex_lock(&p->lock);
    for (i = 0; i < SX_TASK_POOL_QUEUE && t == NULL; ++i) {
        if (!p->tasks[i].used) t = &p->tasks[i];
    }
    if (t == NULL) {
        pthread_mutex_unlock(&p->lock);
        fn(0, item_count, 0, task_context);
        return NULL;
    }
    t->fn = fn;
    t->context = task_context;
    t->order = p->enqueued++;
    t->items = item_count;
    t->range = range;
    t->next = 0;
    t->running = 0;
    t->used = true;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    return t;
}

/* sx_finish_task_fn. */
static void sx_task_pool_finish(void *user_task, void *user_context) {
    sx_task_pool *p = (sx_task_pool *)user_context;
    sx_task_pool_task *t = (sx_task_pool_task *)user_task;
    int start, end;
    pthread_mutex_lock(&p->lock);
    while (sx_task_pool_take(t, &start, &end))
        sx_task_pool_run(p, t, start, end, 0);
    while (t->running > 0)
        pthread_cond_wait(&p->done, &p->lock);
    t->used = false;
    pthread_mutex_unlock(&p->lock);
}

/* Starts count - 1 threads (count: 1 .. SX_TASK_POOL_MAX workers, the
 * caller included). false if a thread could not be started (count then
 * says how many run; stop the pool all the same). */
static bool sx_task_pool_start(sx_task_pool *p, int count) {
    int i;
    if (count < 1 || count > SX_TASK_POOL_MAX) return false;
    p->count = 1;
    p->quit = false;
    p->enqueued = 0;
    for (i = 0; i < SX_TASK_POOL_QUEUE; ++i)
        p->tasks[i].used = false;
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->wake, NULL);
    pthread_cond_init(&p->done, NULL);
    for (i = 1; i < count; ++i) {
        p->threads[i].pool = p;
        p->threads[i].worker = i;
        if (pthread_create(&p->threads[i].thread, NULL, sx_task_pool_main, &p->threads[i]) != 0)
            return false;
        p->count = i + 1;
    }
    return true;
}

static void sx_task_pool_stop(sx_task_pool *p) {
    int i;
    pthread_mutex_lock(&p->lock);
    p->quit = true;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    for (i = 1; i < p->count; ++i)
        pthread_join(p->threads[i].thread, NULL);
    pthread_mutex_destroy(&p->lock);
    pthread_cond_destroy(&p->wake);
    pthread_cond_destroy(&p->done);
}

#ifdef SX_MAX_WORKERS /* sepax/world.h included first */
/* Hands the pool to a sepax world definition. */
static void sx_task_pool_use(sx_task_pool *p, sx_world_def *def) {
    def->enqueue_task = sx_task_pool_enqueue;
    def->finish_task = sx_task_pool_finish;
    def->worker_count = p->count;
    def->user_task_context = p;
}
#endif

#endif /* SEPAX_SAMPLES_TASK_POOL_H */
