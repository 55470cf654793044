/* sepax — the base layer: version, status strings, the assert handler and the
 * allocator hooks with their live-byte counter. These are the library's only
 * process-wide state. The hooks are plain pointers, set once at start-up
 * before any world exists (then only read, so threads may share them); the
 * counter is updated by every allocation of every world, from whatever
 * thread owns that world, so it is atomic. */
#include <stdio.h>
#include <stdlib.h>

#include "core.h"

int sx_version(void) { return SX_VERSION; }

bool sx_real_is_double(void) {
#ifdef SX_DOUBLE
    return true;
#else
    return false;
#endif
}

const char *sx_status_str(sx_status status) {
    switch (status) {
    case SX_OK: return "ok";
    case SX_ERR_INVALID_ARG: return "invalid argument";
    case SX_ERR_DEGENERATE: return "degenerate input";
    case SX_ERR_NONFINITE: return "non-finite input (NaN or infinity)";
    case SX_ERR_CAPACITY: return "capacity exceeded";
    case SX_ERR_NO_MEMORY: return "out of memory";
    case SX_ERR_STALE_HANDLE: return "stale or invalid handle";
    case SX_ERR_LOCKED: return "world locked: called from one of its callbacks";
    case SX_STATUS_COUNT: break;
    }
    return "unknown status";
}

/* ---- assert ------------------------------------------------------------- */

static void sx_default_assert(const char *expression, const char *file, int line, void *context) {
    SX_UNUSED(context);
    fprintf(stderr, "sepax: assertion failed: %s (%s:%d)\n", expression, file, line);
    abort();
}

static sx_assert_fn *s_assert_handler = sx_default_assert;
static void *s_assert_context = NULL;

void sx_set_assert_handler(sx_assert_fn *handler, void *context) {
    s_assert_handler = handler ? handler : sx_default_assert;
    s_assert_context = handler ? context : NULL;
}

void sx_assert_failed(const char *expression, const char *file, int line) {
    s_assert_handler(expression, file, line, s_assert_context);
}

/* ---- allocation --------------------------------------------------------- */

static void *sx_default_alloc(size_t size, void *context) {
    SX_UNUSED(context);
    return malloc(size);
}

static void sx_default_free(void *memory, size_t size, void *context) {
    SX_UNUSED(size);
    SX_UNUSED(context);
    free(memory);
}

/* The counter's atomic operations. Relaxed order: the count orders no other
 * memory, it only has to lose no update. GCC and clang have had the
 * __atomic builtins since 4.7 / 3.1 (in -std=c99 -pedantic too); other
 * compilers need C11 atomics. */
#if defined(__GNUC__) || defined(__clang__)
typedef size_t sx_atomic_size;
static size_t sx_atomic_add(sx_atomic_size *a, size_t v) {
    return __atomic_add_fetch(a, v, __ATOMIC_RELAXED);
}
static size_t sx_atomic_fetch_sub(sx_atomic_size *a, size_t v) {
    return __atomic_fetch_sub(a, v, __ATOMIC_RELAXED);
}
static size_t sx_atomic_load(sx_atomic_size *a) { return __atomic_load_n(a, __ATOMIC_RELAXED); }
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L && !defined(__STDC_NO_ATOMICS__)
#include <stdatomic.h>
typedef _Atomic size_t sx_atomic_size;
static size_t sx_atomic_add(sx_atomic_size *a, size_t v) {
    return atomic_fetch_add_explicit(a, v, memory_order_relaxed) + v;
}
static size_t sx_atomic_fetch_sub(sx_atomic_size *a, size_t v) {
    return atomic_fetch_sub_explicit(a, v, memory_order_relaxed);
}
static size_t sx_atomic_load(sx_atomic_size *a) {
    return atomic_load_explicit(a, memory_order_relaxed);
}
#else
#error "sepax needs atomic operations: build src/base.c with GCC, clang or a C11 compiler"
#endif

static sx_alloc_fn *s_alloc = sx_default_alloc;
static sx_free_fn *s_free = sx_default_free;
static void *s_alloc_context = NULL;
static sx_atomic_size s_live_bytes = 0;

void sx_set_allocator(sx_alloc_fn *alloc, sx_free_fn *free_fn, void *context) {
    if (alloc != NULL && free_fn != NULL) {
        s_alloc = alloc;
        s_free = free_fn;
        s_alloc_context = context;
    } else {
        s_alloc = sx_default_alloc;
        s_free = sx_default_free;
        s_alloc_context = NULL;
    }
}

void *sx_alloc(size_t size) {
    void *p;
    if (size == 0) return NULL;
    p = s_alloc(size, s_alloc_context);
    if (p != NULL) (void)sx_atomic_add(&s_live_bytes, size);
    return p;
}

void sx_free(void *memory, size_t size) {
    size_t before;
    if (memory == NULL) return;
    before = sx_atomic_fetch_sub(&s_live_bytes, size);
    /* a size larger than what is live: not a block of sx_alloc, or the
     * wrong size */
    SX_ASSERT(size <= before);
    s_free(memory, size, s_alloc_context);
}

size_t sx_live_bytes(void) { return sx_atomic_load(&s_live_bytes); }
