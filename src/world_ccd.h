/* sepax — continuous collision (world_ccd.c): where each moving body was at
 * the step's collide, so the pass at the end of the step can sweep it from
 * there. */
#ifndef SEPAX_WORLD_CCD_H
#define SEPAX_WORLD_CCD_H

#include "core.h"
#include "sepax/world.h"

/* An awake dynamic body as the step's collide found it, per body slot: its
 * rotation and the end its velocity then foresaw side by side (the
 * stage's test reads them with the body's rotation and centre), its
 * centre, and which collide (stamp; 0: none). */
typedef struct sx_ccd_rec {
    sx_rot q;
    sx_vec2 end;
    sx_vec2 center;
    uint32_t stamp;
} sx_ccd_rec;

/* Per body slot, beside its record: its reach from its centre of mass and
 * thinnest half extent, kept until its colliders or mass change
 * (ext_valid). */
typedef struct sx_ccd_pose {
    sx_real max_ext, min_ext;
    sx_real gate; /* the motion under which it is never swept (sx_under_gate) */
    bool ext_valid;
    bool swept; /* while the continuous stage runs: it is to be swept */
} sx_ccd_pose;

/* world_ccd.c */
/* Starts the record of where the moving bodies are, for the continuous
 * pass at the end of the step (sx_world_collide calls it, and its bounds
 * pass fills each body's record in). */
sx_status sx_ccd_record(sx_world *world);
/* Frees its arrays (sx_world_destroy). */
void sx_ccd_free(sx_world *world);
/* Forgets body slot's cached extents and record (its colliders or mass
 * changed, or it was just created). */
void sx_ccd_forget(sx_world *world, int slot);
/* Whether two points moving straight from a0 by da and from b0 by db over
 * a step come within r of each other (the closest approach; NaN: true). */
bool sx_paths_meet(sx_vec2 a0, sx_vec2 da, sx_vec2 b0, sx_vec2 db, sx_real r);

#endif /* SEPAX_WORLD_CCD_H */
