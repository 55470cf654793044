/* sepax benchmarks — the Box2D v3 world behind the scene interface of
 * bench/scenes.h: one body and one shape per scene body, stepped by
 * b2World_Step(dt, subStepCount) on one thread (workerCount 1, no task
 * system: v3 then runs its parallel loops inline), or with
 * scene_config.workers > 1 on that many threads of v3's own scheduler.
 *
 * Every file of bench/box2d3/ is compiled once per Box2D v3 build (scalar,
 * SSE2, AVX2) with B3_SUFFIX naming the build; the Makefile links them with
 * that build's objects into one relocatable object and hides every symbol
 * but those whose names end in box2d3_<build> (B3_EXPORT), so the three
 * builds live side by side in one bench program.
 *
 * v3 is used as shipped: real capsules, polygons without a skin (radius 0
 * unless the scene gives one), its default soft contacts, restitution
 * threshold and speculative margin. Rotations go in and out through exact
 * cos/sin and atan2 (v3's own b2MakeRot and b2Rot_GetAngle are
 * approximations), so every engine starts from the same numbers. */
#include <box2d/box2d.h>

#include <math.h>
#include <stdlib.h>

#include "b3_export.h"
#include "scenes.h"

typedef struct b3_world {
    b2WorldId world;
    b2BodyId *bodies;
    int count;
    float dt;
    int sub_steps;
} b3_world;

static b2Rot exact_rot(double angle) {
    b2Rot q = {(float)cos(angle), (float)sin(angle)};
    return q;
}

static b2Vec2 v2(double x, double y) {
    b2Vec2 v = {(float)x, (float)y};
    return v;
}

static int add_shape(b2BodyId body, const scene_body *sb) {
    const bench_shape *s = &sb->shape;
    b2ShapeDef sd = b2DefaultShapeDef();
    sd.density = (float)sb->density;
    sd.material.friction = (float)sb->friction;
    sd.material.restitution = (float)sb->restitution;
    switch (s->kind) {
    case BENCH_CIRCLE: {
        b2Circle c = {v2(s->v[0][0], s->v[0][1]), (float)s->radius};
        b2CreateCircleShape(body, &sd, &c);
        return 1;
    }
    case BENCH_SEGMENT: {
        b2Segment g = {v2(s->v[0][0], s->v[0][1]), v2(s->v[1][0], s->v[1][1])};
        b2CreateSegmentShape(body, &sd, &g);
        return 1;
    }
    case BENCH_CAPSULE: {
        b2Capsule c = {v2(s->v[0][0], s->v[0][1]), v2(s->v[1][0], s->v[1][1]), (float)s->radius};
        b2CreateCapsuleShape(body, &sd, &c);
        return 1;
    }
    case BENCH_BOX: {
        b2Polygon p = b2MakeBox((float)s->hx, (float)s->hy);
        b2CreatePolygonShape(body, &sd, &p);
        return 1;
    }
    default: {
        b2Vec2 pts[BENCH_MAX_VERTICES];
        for (int i = 0; i < s->count && i < BENCH_MAX_VERTICES; ++i)
            pts[i] = v2(s->v[i][0], s->v[i][1]);
        b2Hull hull = b2ComputeHull(pts, s->count);
        if (hull.count == 0) return 0;
        b2Polygon p = b2MakePolygon(&hull, (float)s->radius);
        b2CreatePolygonShape(body, &sd, &p);
        return 1;
    }
    }
}

static void b3_destroy(void *w) {
    b3_world *bw = w;
    if (!bw) return;
    if (b2World_IsValid(bw->world)) b2DestroyWorld(bw->world);
    free(bw->bodies);
    free(bw);
}

static int b3_add(void *w, const scene_body *b) {
    b3_world *bw = w;
    b2BodyId *grown = realloc(bw->bodies, (size_t)(bw->count + 1) * sizeof *grown);
    if (!grown) return -1;
    bw->bodies = grown;
    b2BodyDef bd = b2DefaultBodyDef();
    bd.type = b->kinematic ? b2_kinematicBody : b->dynamic ? b2_dynamicBody : b2_staticBody;
    bd.position = v2(b->x, b->y);
    bd.rotation = exact_rot(b->angle);
    bd.linearVelocity = v2(b->vx, b->vy);
    bd.isBullet = b->bullet != 0;
    bd.angularVelocity = (float)b->w;
    b2BodyId id = b2CreateBody(bw->world, &bd);
    if (!add_shape(id, b)) return -1;
    bw->bodies[bw->count] = id;
    return bw->count++;
}

static void *b3_create(const scene_def *def, const scene_config *cfg) {
    b3_world *bw = calloc(1, sizeof *bw);
    if (!bw) return NULL;
    b2WorldDef wd = b2DefaultWorldDef();
    wd.gravity = v2(def->gx, def->gy);
    wd.enableSleep = def->sleep != 0;
    /* more than one: v3's own scheduler (no task callbacks given) */
    wd.workerCount = cfg->workers > 1 ? cfg->workers : 1;
    bw->world = b2CreateWorld(&wd);
    bw->dt = (float)cfg->dt;
    bw->sub_steps = cfg->sub_steps > 0 ? cfg->sub_steps : 1;
    for (int i = 0; i < def->count; ++i) {
        if (b3_add(bw, &def->bodies[i]) < 0) {
            b3_destroy(bw);
            return NULL;
        }
    }
    return bw;
}

static void b3_step(void *w, int steps) {
    b3_world *bw = w;
    for (int i = 0; i < steps; ++i)
        b2World_Step(bw->world, bw->dt, bw->sub_steps);
}

static void b3_get(void *w, int body, scene_state *o) {
    b3_world *bw = w;
    b2BodyId id = bw->bodies[body];
    b2Vec2 p = b2Body_GetPosition(id);
    b2Rot q = b2Body_GetRotation(id);
    b2Vec2 v = b2Body_GetLinearVelocity(id);
    o->x = (double)p.x;
    o->y = (double)p.y;
    o->angle = atan2((double)q.s, (double)q.c);
    o->vx = (double)v.x;
    o->vy = (double)v.y;
    o->w = (double)b2Body_GetAngularVelocity(id);
}

static int b3_awake(void *w) {
    b3_world *bw = w;
    return b2World_GetAwakeBodyCount(bw->world);
}

const scene_engine B3_EXPORT(scene_box2d3_) = {b3_create, b3_step, b3_get, b3_destroy, b3_add, b3_awake};
