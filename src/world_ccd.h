/* sepax — continuous collision (world_ccd.c): where each moving body was at
 * the step's collide, so the pass at the end of the step can sweep it from
 * there. */
#ifndef SEPAX_WORLD_CCD_H
#define SEPAX_WORLD_CCD_H

#include "core.h"
#include "sepax/world.h"

/* Where a body was when the step's collide ran (world_ccd.c): the
 * continuous pass sweeps it from there; stamp tells which collide. */
typedef struct sx_ccd_pose {
    sx_vec2 center;
    sx_rot q;
    sx_vec2 v; /* at collide: the look-ahead its bounds and margins were grown by */
    uint32_t stamp;
    /* the body's reach from its centre of mass and thinnest half extent,
     * kept until its colliders or mass change (ext_valid) */
    sx_real max_ext, min_ext;
    bool ext_valid;
} sx_ccd_pose;

/* world_ccd.c */
/* Records where the moving bodies are, for the continuous pass at the end
 * of the step (sx_world_collide calls it). */
sx_status sx_ccd_record(sx_world *world);
/* Frees its arrays (sx_world_destroy). */
void sx_ccd_free(sx_world *world);
/* Forgets body slot's cached extents and pose (its colliders or mass
 * changed, or it was just created). */
void sx_ccd_forget(sx_world *world, int slot);

#endif /* SEPAX_WORLD_CCD_H */
