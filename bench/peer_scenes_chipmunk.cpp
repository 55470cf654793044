/* sepax benchmarks — the Chipmunk 7 world behind the scene interface of
 * bench/scenes.h: one cpBody and one cpShape per scene body, stepped by
 * cpSpaceStep(dt / sub_steps), sub_steps times per scene step, with
 * cpSpaceSetIterations(vel_iters).
 *
 * Mass and inertia come from the shapes' densities (cpShapeSetDensity), as
 * in the other engines. Chipmunk multiplies the two shapes' friction and
 * elasticity where Box2D and sepax take sqrt(mu_a mu_b) and max(e_a, e_b):
 * each shape gets sqrt(mu) and sqrt(e), so a contact between equal values
 * mixes to the same number in all three engines. Sleeping uses Chipmunk's
 * own idle time (0.5 s, as sepax's time_to_sleep). Chipmunk has no
 * continuous collision: scene_body.bullet is ignored. Collision slop is left at
 * Chipmunk's default (0.1 length units: Chipmunk lets stacks sink that deep
 * by design; the scenes report it). */
#include <chipmunk/chipmunk.h>

#include <cmath>
#include <vector>

#include "scenes.h"

namespace {

struct World {
    cpSpace *space = nullptr;
    std::vector<cpBody *> bodies;
    std::vector<cpShape *> shapes;
    double dt = 1.0 / 60.0;
    int calls = 1;
};

cpShape *make_shape(cpBody *body, const bench_shape &s, double angle, double x, double y,
                    bool is_static) {
    /* Static shapes live on the space's static body, so their geometry is
     * placed in world coordinates here. */
    cpTransform t = is_static ? cpTransformRigid(cpv(x, y), angle) : cpTransformIdentity;
    switch (s.kind) {
    case BENCH_CIRCLE:
        return cpCircleShapeNew(body, s.radius,
                                cpTransformPoint(t, cpv(s.v[0][0], s.v[0][1])));
    case BENCH_SEGMENT:
    case BENCH_CAPSULE:
        return cpSegmentShapeNew(body, cpTransformPoint(t, cpv(s.v[0][0], s.v[0][1])),
                                 cpTransformPoint(t, cpv(s.v[1][0], s.v[1][1])), s.radius);
    case BENCH_BOX: {
        cpVect v[4] = {cpv(-s.hx, -s.hy), cpv(s.hx, -s.hy), cpv(s.hx, s.hy), cpv(-s.hx, s.hy)};
        return cpPolyShapeNew(body, 4, v, t, 0.0);
    }
    default: {
        cpVect v[BENCH_MAX_VERTICES];
        for (int i = 0; i < s.count; ++i)
            v[i] = cpv(s.v[i][0], s.v[i][1]);
        return cpPolyShapeNew(body, s.count, v, t, 0.0);
    }
    }
}

} // namespace

namespace {

int chipmunk_add(void *world, const scene_body *sb) {
    World *w = static_cast<World *>(world);
    const bool moving = sb->dynamic || sb->kinematic;
    cpBody *body = cpSpaceGetStaticBody(w->space);
    if (sb->dynamic)
        body = cpSpaceAddBody(w->space, cpBodyNew(0.0, 0.0));
    else if (sb->kinematic)
        body = cpSpaceAddBody(w->space, cpBodyNewKinematic());
    /* The body is placed before its shape joins the space: the spatial index
     * takes the shape's box at insertion and pairs it with every box it
     * overlaps then, so shapes inserted at the origin would all pair with
     * each other (memory and the first step quadratic in the body count). */
    if (moving) {
        cpBodySetPosition(body, cpv(sb->x, sb->y));
        cpBodySetAngle(body, sb->angle);
        cpBodySetVelocity(body, cpv(sb->vx, sb->vy));
        cpBodySetAngularVelocity(body, sb->w);
    }
    cpShape *shape = make_shape(body, sb->shape, sb->angle, sb->x, sb->y, !moving);
    cpShapeSetFriction(shape, std::sqrt(sb->friction));
    cpShapeSetElasticity(shape, std::sqrt(sb->restitution));
    if (sb->dynamic) cpShapeSetDensity(shape, sb->density);
    cpSpaceAddShape(w->space, shape);
    w->bodies.push_back(body);
    w->shapes.push_back(shape);
    return (int)w->bodies.size() - 1;
}

void *chipmunk_create(const scene_def *def, const scene_config *cfg) {
    World *w = new World;
    w->space = cpSpaceNew();
    cpSpaceSetGravity(w->space, cpv(def->gx, def->gy));
    cpSpaceSetIterations(w->space, cfg->vel_iters);
    cpSpaceSetSleepTimeThreshold(w->space, def->sleep ? 0.5 : INFINITY);
    w->calls = cfg->sub_steps > 0 ? cfg->sub_steps : 1;
    w->dt = cfg->dt / w->calls;
    for (int i = 0; i < def->count; ++i)
        chipmunk_add(w, &def->bodies[i]);
    return w;
}

/* A scene step of dt is `calls` Chipmunk steps of dt / calls. */
void chipmunk_step(void *world, int steps) {
    World *w = static_cast<World *>(world);
    for (int i = 0; i < steps * w->calls; ++i)
        cpSpaceStep(w->space, w->dt);
}

void chipmunk_get(void *world, int body, scene_state *out) {
    const cpBody *b = static_cast<World *>(world)->bodies[(size_t)body];
    cpVect p = cpBodyGetPosition(b), v = cpBodyGetVelocity(b);
    out->x = p.x;
    out->y = p.y;
    out->angle = cpBodyGetAngle(b);
    out->vx = v.x;
    out->vy = v.y;
    out->w = cpBodyGetAngularVelocity(b);
}

void chipmunk_destroy(void *world) {
    World *w = static_cast<World *>(world);
    for (cpShape *s : w->shapes) {
        cpSpaceRemoveShape(w->space, s);
        cpShapeFree(s);
    }
    for (cpBody *b : w->bodies) {
        if (b == cpSpaceGetStaticBody(w->space)) continue;
        cpSpaceRemoveBody(w->space, b);
        cpBodyFree(b);
    }
    cpSpaceFree(w->space);
    delete w;
}

int chipmunk_awake(void *world) {
    int n = 0;
    World *w = static_cast<World *>(world);
    for (cpBody *b : w->bodies)
        n += cpBodyGetType(b) == CP_BODY_TYPE_DYNAMIC && !cpBodyIsSleeping(b);
    return n;
}

} // namespace

extern "C" const scene_engine scene_chipmunk = {chipmunk_create,  chipmunk_step, chipmunk_get,
                                                chipmunk_destroy, chipmunk_add,  chipmunk_awake};
