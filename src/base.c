/* sepax — the base layer: version, status strings, the assert handler and the
 * allocator hooks with their live-byte counter. These are the library's only
 * process-wide state; both are meant to be set once at start-up. */
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

static sx_alloc_fn *s_alloc = sx_default_alloc;
static sx_free_fn *s_free = sx_default_free;
static void *s_alloc_context = NULL;
static size_t s_live_bytes = 0;

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
    if (p != NULL) s_live_bytes += size;
    return p;
}

void sx_free(void *memory, size_t size) {
    if (memory == NULL) return;
    SX_ASSERT(size <= s_live_bytes);
    s_live_bytes -= size;
    s_free(memory, size, s_alloc_context);
}

size_t sx_live_bytes(void) { return s_live_bytes; }
