/* sepax — private: what the world layer asks of the collide layer beyond the
 * public collide.h. world.c includes this instead of the whole narrowphase
 * interface (narrow.h). */
#ifndef SEPAX_COLLIDE_WORLD_H
#define SEPAX_COLLIDE_WORLD_H

#include "core.h"
#include "sepax/collide.h"

/* sx_collide_ex with the world's reference-face hysteresis
 * (SX_WORLD_REFERENCE_HYSTERESIS, narrow.h): what the world's contacts use,
 * so that a contact between two nearly equal faces keeps its reference face
 * (and feature ids) from step to step. */
int sx_collide_world(const sx_shape *a, sx_xform xa, const sx_shape *b, sx_xform xb, sx_real margin,
                     sx_manifold *out);

#endif /* SEPAX_COLLIDE_WORLD_H */
