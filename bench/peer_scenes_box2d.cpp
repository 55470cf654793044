/* sepax benchmarks — the Box2D 2.4 world behind the scene interface of
 * bench/scenes.h: one b2Body and one b2Fixture per scene body, stepped by
 * b2World::Step(dt, velocityIterations, positionIterations), called
 * sub_steps times with dt / sub_steps per scene step.
 *
 * Box2D is used as shipped: polygons keep their skin b2_polygonRadius
 * (2 x linearSlop = 1 cm), which is how Box2D stacks rest (the skins touch,
 * the cores stay 2 cm apart), so a Box2D pyramid stands about 2 cm per row
 * taller than the others. Box2D 2.4 has no capsule: a capsule becomes the
 * hexagon through its four side points and its two tips (same length and
 * width, corners cut), said in bench/README.md. Static segments are
 * b2EdgeShape. */
#include <box2d/box2d.h>

#include <cmath>
#include <vector>

#include "scenes.h"

namespace {

struct World {
    b2World world{b2Vec2(0.0f, -10.0f)};
    std::vector<b2Body *> bodies;
    float dt = 1.0f / 60.0f;
    int vel = 8, pos = 3;
    int calls = 1;
};

void add_fixture(b2Body *body, const scene_body &sb) {
    const bench_shape &s = sb.shape;
    b2FixtureDef fd;
    fd.density = (float)sb.density;
    fd.friction = (float)sb.friction;
    fd.restitution = (float)sb.restitution;
    b2CircleShape circle;
    b2EdgeShape edge;
    b2PolygonShape poly;
    switch (s.kind) {
    case BENCH_CIRCLE:
        circle.m_p.Set((float)s.v[0][0], (float)s.v[0][1]);
        circle.m_radius = (float)s.radius;
        fd.shape = &circle;
        break;
    case BENCH_SEGMENT:
        edge.SetTwoSided(b2Vec2((float)s.v[0][0], (float)s.v[0][1]),
                         b2Vec2((float)s.v[1][0], (float)s.v[1][1]));
        fd.shape = &edge;
        break;
    case BENCH_CAPSULE: {
        /* The hexagon through the capsule's sides and tips. */
        double ax = s.v[0][0], ay = s.v[0][1], bx = s.v[1][0], by = s.v[1][1];
        double dx = bx - ax, dy = by - ay, len = std::sqrt(dx * dx + dy * dy);
        double ux = dx / len, uy = dy / len, r = s.radius;
        b2Vec2 v[6] = {
            b2Vec2((float)(ax - ux * r), (float)(ay - uy * r)),
            b2Vec2((float)(ax + uy * r), (float)(ay - ux * r)),
            b2Vec2((float)(bx + uy * r), (float)(by - ux * r)),
            b2Vec2((float)(bx + ux * r), (float)(by + uy * r)),
            b2Vec2((float)(bx - uy * r), (float)(by + ux * r)),
            b2Vec2((float)(ax - uy * r), (float)(ay + ux * r)),
        };
        poly.Set(v, 6);
        fd.shape = &poly;
        break;
    }
    case BENCH_BOX:
        poly.SetAsBox((float)s.hx, (float)s.hy);
        fd.shape = &poly;
        break;
    default: {
        b2Vec2 v[BENCH_MAX_VERTICES];
        for (int i = 0; i < s.count; ++i)
            v[i].Set((float)s.v[i][0], (float)s.v[i][1]);
        poly.Set(v, s.count);
        fd.shape = &poly;
        break;
    }
    }
    body->CreateFixture(&fd);
}

} // namespace

namespace {

int box2d_add(void *world, const scene_body *sb) {
    World *w = static_cast<World *>(world);
    b2BodyDef bd;
    bd.type = sb->kinematic ? b2_kinematicBody : sb->dynamic ? b2_dynamicBody : b2_staticBody;
    bd.position.Set((float)sb->x, (float)sb->y);
    bd.angle = (float)sb->angle;
    bd.linearVelocity.Set((float)sb->vx, (float)sb->vy);
    bd.angularVelocity = (float)sb->w;
    bd.bullet = sb->bullet != 0;
    b2Body *body = w->world.CreateBody(&bd);
    add_fixture(body, *sb);
    w->bodies.push_back(body);
    return (int)w->bodies.size() - 1;
}

void *box2d_create(const scene_def *def, const scene_config *cfg) {
    World *w = new World;
    w->world.SetGravity(b2Vec2((float)def->gx, (float)def->gy));
    w->world.SetAllowSleeping(def->sleep != 0);
    w->calls = cfg->sub_steps > 0 ? cfg->sub_steps : 1;
    w->dt = (float)(cfg->dt / w->calls);
    w->vel = cfg->vel_iters;
    w->pos = cfg->pos_iters;
    w->bodies.reserve((size_t)def->count);
    for (int i = 0; i < def->count; ++i)
        box2d_add(w, &def->bodies[i]);
    return w;
}

/* A scene step of dt is `calls` Box2D steps of dt / calls: how Box2D 2.4
 * users sub-step. */
void box2d_step(void *world, int steps) {
    World *w = static_cast<World *>(world);
    for (int i = 0; i < steps * w->calls; ++i)
        w->world.Step(w->dt, w->vel, w->pos);
}

void box2d_get(void *world, int body, scene_state *out) {
    const b2Body *b = static_cast<World *>(world)->bodies[(size_t)body];
    out->x = b->GetPosition().x;
    out->y = b->GetPosition().y;
    out->angle = b->GetAngle();
    out->vx = b->GetLinearVelocity().x;
    out->vy = b->GetLinearVelocity().y;
    out->w = b->GetAngularVelocity();
}

void box2d_destroy(void *world) { delete static_cast<World *>(world); }

int box2d_awake(void *world) {
    int n = 0;
    for (const b2Body *b : static_cast<World *>(world)->bodies)
        n += b->GetType() != b2_staticBody && b->IsAwake();
    return n;
}

} // namespace

extern "C" const scene_engine scene_box2d = {box2d_create, box2d_step,  box2d_get,
                                             box2d_destroy, box2d_add, box2d_awake};
