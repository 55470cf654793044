/* sepax — growing arrays, the one way the world layer allocates: every
 * array of a world (bodies, colliders, contacts, scratch) only grows, by
 * doubling, so a warmed-up world allocates nothing per step. */
#ifndef SEPAX_WORLD_ARRAY_H
#define SEPAX_WORLD_ARRAY_H

#include "core.h"
#include "sepax/world.h"

/* Every array of a world holds at most SX_WORLD_MAX_ITEMS (2^30 - 1)
 * elements, so a count plus one, twice a count, or the sum of two counts,
 * the needs the callers compute, never overflow an int. */

/* Grows *array (elements of `size` bytes, *capacity of them) to hold at least
 * `need`, doubling up to SX_WORLD_MAX_ITEMS; copies the old contents.
 * SX_ERR_CAPACITY when need > SX_WORLD_MAX_ITEMS, SX_ERR_NO_MEMORY when the
 * bytes do not fit a size_t or the allocator fails (the array is then
 * unchanged). */
sx_status sx_reserve_array(void **array, int *capacity, int need, size_t size);
/* sx_reserve_array == SX_OK, for callers that answer any failure alike. */
bool sx_grow_array(void **array, int *capacity, int need, size_t size);
/* sx_grow_array that zeroes the elements it adds. */
bool sx_grow_zeroed(void **array, int *capacity, int need, size_t size);
/* Appends value to a growing int array; false when out of memory. */
bool sx_push_int(int **array, int *count, int *capacity, int value);

#endif /* SEPAX_WORLD_ARRAY_H */
