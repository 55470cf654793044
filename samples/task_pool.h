/* sepax sample — a small job system for sx_world_def's task callbacks, on
 * POSIX threads (compile with -pthread). A game with a job system of its
 * own (flecs workers, enkiTS, a thread pool) hands that one instead; this
 * is what the two callbacks must do, in the fewest lines that do it:
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
 * One task at a time (sepax finishes each task before it enqueues the
 * next). The calling thread is worker 0 and runs ranges too while it waits
 * in finish; the pool's threads are workers 1 .. count - 1. Ranges are taken
 * under one mutex: a task is a few hundred ranges at most. */
#ifndef SEPAX_SAMPLES_TASK_POOL_H
#define SEPAX_SAMPLES_TASK_POOL_H

#include <pthread.h>
#include <stdbool.h>

#include "sepax/sepax.h"

#define SX_TASK_POOL_MAX 16

typedef struct sx_task_pool sx_task_pool;

typedef struct sx_task_pool_thread {
    sx_task_pool *pool;
    pthread_t thread;
    int worker;
} sx_task_pool_thread;

struct sx_task_pool {
    sx_task_pool_thread threads[SX_TASK_POOL_MAX];
    int count; /* workers, the caller included */
    pthread_mutex_t lock;
    pthread_cond_t wake, done;
    bool quit;
    /* the task under way: items [next, items) are not taken yet */
    sx_task_fn *task;
    void *context;
    int items, range, next, running;
};

/* Takes the next range of the task under way (lock held): false when none
 * is left. */
static bool sx_task_pool_take(sx_task_pool *p, int *start, int *end) {
    if (p->task == NULL || p->next >= p->items) return false;
    *start = p->next;
    *end = p->next + p->range < p->items ? p->next + p->range : p->items;
    p->next = *end;
    p->running++;
    return true;
}

/* Runs [start, end) with the lock released, then counts it done. */
static void sx_task_pool_run(sx_task_pool *p, int start, int end, int worker) {
    sx_task_fn *task = p->task;
    void *context = p->context;
    pthread_mutex_unlock(&p->lock);
    task(start, end, worker, context);
    pthread_mutex_lock(&p->lock);
    if (--p->running == 0 && p->next >= p->items) pthread_cond_broadcast(&p->done);
}

static void *sx_task_pool_main(void *arg) {
    sx_task_pool_thread *t = (sx_task_pool_thread *)arg;
    sx_task_pool *p = t->pool;
    int start, end;
    pthread_mutex_lock(&p->lock);
    while (!p->quit) {
        if (sx_task_pool_take(p, &start, &end))
            sx_task_pool_run(p, start, end, t->worker);
        else
            pthread_cond_wait(&p->wake, &p->lock);
    }
    pthread_mutex_unlock(&p->lock);
    return NULL;
}

static void *sx_task_pool_enqueue(sx_task_fn *task, int item_count, int min_range,
                                  void *task_context, void *user_context) {
    sx_task_pool *p = (sx_task_pool *)user_context;
    /* about four ranges a worker, so one slow range does not hold the rest */
    int range = item_count / (4 * p->count);
    pthread_mutex_lock(&p->lock);
    p->task = task;
    p->context = task_context;
    p->items = item_count;
    p->range = range > min_range ? range : (min_range > 0 ? min_range : 1);
    p->next = 0;
    p->running = 0;
    pthread_cond_broadcast(&p->wake);
    pthread_mutex_unlock(&p->lock);
    return p;
}

static void sx_task_pool_finish(void *user_task, void *user_context) {
    sx_task_pool *p = (sx_task_pool *)user_context;
    int start, end;
    (void)user_task;
    pthread_mutex_lock(&p->lock);
    while (sx_task_pool_take(p, &start, &end))
        sx_task_pool_run(p, start, end, 0);
    while (p->running > 0)
        pthread_cond_wait(&p->done, &p->lock);
    p->task = NULL;
    pthread_mutex_unlock(&p->lock);
}

/* Starts count - 1 threads (count: 1 .. SX_TASK_POOL_MAX workers, the
 * caller included). false if a thread could not be started. */
static bool sx_task_pool_start(sx_task_pool *p, int count) {
    int i;
    if (count < 1 || count > SX_TASK_POOL_MAX) return false;
    p->count = 1;
    p->quit = false;
    p->task = NULL;
    p->items = p->next = p->running = 0;
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

/* Hands the pool to a world definition. */
static void sx_task_pool_use(sx_task_pool *p, sx_world_def *def) {
    def->enqueue_task = sx_task_pool_enqueue;
    def->finish_task = sx_task_pool_finish;
    def->worker_count = p->count;
    def->user_task_context = p;
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

#endif /* SEPAX_SAMPLES_TASK_POOL_H */
