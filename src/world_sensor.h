/* sepax — sensors (sensor.c): the overlaps of sensor colliders with the
 * others, and the begin and end events they give. */
#ifndef SEPAX_WORLD_SENSOR_H
#define SEPAX_WORLD_SENSOR_H

#include "sepax/world.h"

/* sensor.c */
/* Finds the sensor overlaps at the current positions and records the sensor
 * events against the last call's overlaps. */
sx_status sx_sensors_update(sx_world *world);
/* Frees the sensor arrays. */
void sx_sensors_free(sx_world *world);
/* Forgets the overlaps of a destroyed collider (no end event, as for
 * contacts). */
void sx_sensors_remove_collider(sx_world *world, int collider);

#endif /* SEPAX_WORLD_SENSOR_H */
