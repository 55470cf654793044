/* sepax — growing arrays (world_array.h): doubling up to
 * SX_WORLD_MAX_ITEMS, with the byte count checked against size_t. */
#include "world_array.h"

#include <stdint.h>
#include <string.h>

sx_status sx_reserve_array(void **array, int *capacity, int need, size_t size) {
    int cap = *capacity;
    void *fresh;
    if (need <= cap) return SX_OK;
    if (need > SX_WORLD_MAX_ITEMS) return SX_ERR_CAPACITY;
    if (cap < 16) cap = 16;
    /* doubling, but never past the limit: 2 x cap stays below INT_MAX */
    while (cap < need)
        cap = cap > SX_WORLD_MAX_ITEMS / 2 ? SX_WORLD_MAX_ITEMS : 2 * cap;
    /* where size_t is narrower than the byte count (32-bit targets), the
     * exact need may still fit when the doubled capacity does not */
    if ((size_t)cap > SIZE_MAX / size) cap = need;
    if ((size_t)cap > SIZE_MAX / size) return SX_ERR_NO_MEMORY;
    fresh = sx_alloc((size_t)cap * size);
    if (fresh == NULL) return SX_ERR_NO_MEMORY;
    if (*array != NULL) {
        memcpy(fresh, *array, (size_t)*capacity * size);
        sx_free(*array, (size_t)*capacity * size);
    }
    *array = fresh;
    *capacity = cap;
    return SX_OK;
}

bool sx_grow_array(void **array, int *capacity, int need, size_t size) {
    return sx_reserve_array(array, capacity, need, size) == SX_OK;
}

bool sx_grow_zeroed(void **array, int *capacity, int need, size_t size) {
    int old = *capacity;
    if (!sx_grow_array(array, capacity, need, size)) return false;
    if (*capacity > old) {
        memset((unsigned char *)*array + (size_t)old * size, 0, (size_t)(*capacity - old) * size);
    }
    return true;
}

bool sx_push_int(int **array, int *count, int *capacity, int value) {
    if (*count == *capacity) {
        void *p = *array;
        bool ok = sx_grow_array(&p, capacity, *count + 1, sizeof(int));
        *array = (int *)p;
        if (!ok) return false;
    }
    (*array)[(*count)++] = value;
    return true;
}
