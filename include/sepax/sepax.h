/* sepax — umbrella header: 2D collision detection (SAT + MTV) and impulse
 * physics in plain C99. Include this, link libsepax. */
#ifndef SEPAX_H
#define SEPAX_H

#include "base.h"
#include "vecmath.h"
#include "shape.h"
#include "collide.h"
#include "compound.h"
#include "world.h"

#endif /* SEPAX_H */
