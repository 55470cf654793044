/* sepax — islands and sleep: a body falls asleep with the island of bodies
 * its contacts join (island.c), and a wake wakes the whole island. */
#ifndef SEPAX_WORLD_ISLAND_H
#define SEPAX_WORLD_ISLAND_H

#include "sepax/world.h"

/* island.c */
/* Wakes a body and, if it sleeps, every body of the island it fell asleep
 * with. */
void sx_wake_body(sx_world *world, int slot);

/* body_contacts.c */
/* Wakes a body and every body it has a contact with (a static body moved
 * from under a sleeping pile must not leave the pile floating). */
void sx_wake_touching(sx_world *world, int slot);

#endif /* SEPAX_WORLD_ISLAND_H */
