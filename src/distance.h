/* sepax — private interface of src/distance.c for the world's continuous
 * collision (src/world_ccd.c): shapes as point-set proxies, and the time of
 * impact between two proxies, so the world can sweep compound parts placed
 * in their body's frame without building shapes. */
#ifndef SEPAX_DISTANCE_H
#define SEPAX_DISTANCE_H

#include "core.h"
#include "sepax/collide.h"

/** A convex core: 1..SX_MAX_POLYGON_VERTICES points plus a radius, in some
 *  frame (the shape's own, or its body's). */
typedef struct sx_proxy {
    sx_vec2 p[SX_MAX_POLYGON_VERTICES];
    sx_real radius;
    int count;
} sx_proxy;

/** The proxy of a shape, its points placed by *offset (NULL: the shape's own
 *  frame). SX_OK, SX_ERR_INVALID_ARG (unusable shape) or SX_ERR_NONFINITE. */
sx_status sx_proxy_make(const sx_shape *s, const sx_xform *offset, sx_proxy *out);

/** sx_time_of_impact on proxies whose frames follow the motions (checked
 *  by the caller: finite). A negative target asks for the first overlap of
 *  that depth of the rounded parts (the cores touching end it too). */
void sx_proxy_toi(const sx_proxy *a, const sx_motion *ma, const sx_proxy *b, const sx_motion *mb,
                  sx_real target, sx_toi_output *out);

#endif /* SEPAX_DISTANCE_H */
