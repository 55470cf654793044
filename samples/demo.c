/* sepax demo — the main sample: a flecs scene stepped by the SepaxPhysics
 * module. A ground between two walls, a pyramid of boxes, a concave static
 * cup (an outline attached as one compound collider with
 * sx_ecs_set_outline) and a stream of mixed shapes (circles, boxes, capsules,
 * triangles) spawned by an ordinary flecs system, so the spawning is a
 * structural change made in deferred mode. Prints a line per simulated
 * second and writes the final frame as an SVG drawn through the world's
 * debug-draw interface (sx_world_draw).
 *
 *   make demo                       (runs build/demo build/demo/final.svg)
 *   build/demo [out.svg] [seconds]  (defaults: build/demo/final.svg, 8)
 *
 * The scene is plain data written into components; the module turns it into
 * sepax bodies, steps them at a fixed 60 Hz and writes the results back. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "sepax_flecs.h"

#define DEMO_SPAWN_COUNT 160
#define DEMO_SPAWN_PERIOD 0.04 /* seconds between two spawned shapes */
#define DEMO_PIXELS_PER_METER 24.0

static ecs_entity_t spawn(ecs_world_t *world, sx_body_type type, sx_vec2 p, sx_real angle,
                          sx_shape shape) {
    ecs_entity_t e = ecs_new(world);
    SxTransform t;
    t.position = p;
    t.angle = angle;
    ecs_set_ptr(world, e, SxTransform, &t);
    if (type != SX_BODY_STATIC) {
        SxBody b = sx_ecs_body(type);
        ecs_set_ptr(world, e, SxBody, &b);
    }
    {
        SxCollider c = sx_ecs_collider(shape);
        ecs_set_ptr(world, e, SxCollider, &c);
    }
    return e;
}

/* A cup: a concave outline attached as ONE static compound collider
 * (sx_ecs_set_outline splits it into convex parts with sx_decompose_polygon;
 * the world treats the parts as a single collider). Returns the number of
 * parts, 0 on failure. */
static int add_cup(ecs_world_t *world, sx_vec2 at) {
    static const sx_vec2 outline[] = {
        {SX_R(-3.0), SX_R(2.0)}, {SX_R(-2.6), SX_R(2.0)}, {SX_R(-1.6), SX_R(0.4)},
        {SX_R(1.6), SX_R(0.4)},  {SX_R(2.6), SX_R(2.0)},  {SX_R(3.0), SX_R(2.0)},
        {SX_R(1.8), SX_R(0.0)},  {SX_R(-1.8), SX_R(0.0)},
    };
    enum { N = sizeof(outline) / sizeof(outline[0]) };
    ecs_entity_t cup = ecs_entity(world, {.name = "cup"});
    SxTransform t;
    const SxCollider *c;
    t.position = at;
    t.angle = SX_R(0.0);
    ecs_set_ptr(world, cup, SxTransform, &t);
    if (sx_ecs_set_outline(world, cup, outline, N, NULL) != SX_OK) return 0;
    c = ecs_get(world, cup, SxCollider);
    return c != NULL ? (int)c->part_count : 0;
}

/* ---- the stream: a game system that spawns shapes -------------------------- */

typedef struct demo_stream {
    double clock;
    int spawned;
    uint32_t seed;
} demo_stream;

static sx_real demo_random(demo_stream *s, double lo, double hi) {
    s->seed = s->seed * 1664525u + 1013904223u; /* a fixed LCG: the same run every time */
    return (sx_real)(lo + (hi - lo) * (double)(s->seed >> 8) / 16777216.0);
}

static void spawn_stream(ecs_iter_t *it) {
    demo_stream *s = (demo_stream *)it->ctx;
    s->clock += (double)it->delta_time;
    while (s->clock >= DEMO_SPAWN_PERIOD && s->spawned < DEMO_SPAWN_COUNT) {
        sx_vec2 p = sx_v2(demo_random(s, -9.0, 9.0), demo_random(s, 17.0, 19.0));
        sx_real angle = demo_random(s, 0.0, 3.0);
        sx_shape shape;
        switch (s->spawned % 4) {
        case 0: shape = sx_circle_shape(sx_v2(0, 0), demo_random(s, 0.2, 0.4)); break;
        case 1: shape = sx_box_shape(demo_random(s, 0.2, 0.4), demo_random(s, 0.2, 0.4)); break;
        case 2:
            shape = sx_capsule_shape(sx_v2(SX_R(-0.3), 0), sx_v2(SX_R(0.3), 0), SX_R(0.18));
            break;
        default: {
            sx_vec2 tri[3] = {{SX_R(-0.4), SX_R(-0.3)}, {SX_R(0.4), SX_R(-0.3)}, {0, SX_R(0.4)}};
            if (sx_polygon_shape(tri, 3, SX_R(0.0), &shape) != SX_OK) {
                shape = sx_box_shape(SX_R(0.3), SX_R(0.3));
            }
        } break;
        }
        /* it->world is deferred here: the new entities appear at the merge */
        spawn(it->world, SX_BODY_DYNAMIC, p, angle, shape);
        s->clock -= DEMO_SPAWN_PERIOD;
        ++s->spawned;
    }
}

/* Counts the contacts that begin: an observer of the module's event. Each
 * begin reaches both entities of the pair; count it once, on the entity with
 * the smaller id. */
static void count_begins(ecs_iter_t *it) {
    const SxContactEvent *ev = (const SxContactEvent *)it->param;
    int *begins = (int *)it->ctx;
    if (ev->self < ev->other) ++*begins;
}

/* ---- SVG through the debug-draw callbacks ---------------------------------- */

typedef struct svg_out {
    FILE *f;
} svg_out;

static double px(sx_real x) { return (double)x * DEMO_PIXELS_PER_METER; }
static double py(sx_real y) { return -(double)y * DEMO_PIXELS_PER_METER; }

static void svg_shape(const sx_shape *shape, sx_xform xf, sx_body_type type, bool sensor,
                      void *context) {
    FILE *f = ((svg_out *)context)->f;
    const char *fill = type == SX_BODY_STATIC      ? "#9aa0a6"
                       : type == SX_BODY_KINEMATIC ? "#7cc576"
                                                   : "#5b8def";
    const char *style = sensor ? "fill=\"none\" stroke=\"#e0a000\"" : "stroke=\"#1f2430\"";
    int i;
    switch (shape->type) {
    case SX_SHAPE_CIRCLE: {
        sx_vec2 c = sx_xform_point(xf, shape->u.circle.center);
        sx_vec2 r = sx_xform_point(
            xf, sx_add(shape->u.circle.center, sx_v2(shape->u.circle.radius, SX_R(0.0))));
        fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\" %s/>\n", px(c.x),
                py(c.y), px(shape->u.circle.radius), fill, style);
        fprintf(f, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#1f2430\"/>\n",
                px(c.x), py(c.y), px(r.x), py(r.y));
    } break;
    case SX_SHAPE_SEGMENT:
    case SX_SHAPE_CAPSULE: {
        sx_vec2 a = sx_xform_point(xf, shape->type == SX_SHAPE_SEGMENT ? shape->u.segment.a
                                                                       : shape->u.capsule.a);
        sx_vec2 b = sx_xform_point(xf, shape->type == SX_SHAPE_SEGMENT ? shape->u.segment.b
                                                                       : shape->u.capsule.b);
        double w = shape->type == SX_SHAPE_SEGMENT ? 1.0 : 2.0 * px(shape->u.capsule.radius);
        fprintf(f,
                "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#1f2430\" "
                "stroke-width=\"%.2f\" stroke-linecap=\"round\"/>\n",
                px(a.x), py(a.y), px(b.x), py(b.y), w + 2.0);
        fprintf(f,
                "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" "
                "stroke-width=\"%.2f\" stroke-linecap=\"round\"/>\n",
                px(a.x), py(a.y), px(b.x), py(b.y), fill, w);
    } break;
    case SX_SHAPE_POLYGON:
        fprintf(f, "<polygon points=\"");
        for (i = 0; i < shape->u.polygon.count; ++i) {
            sx_vec2 v = sx_xform_point(xf, shape->u.polygon.vertices[i]);
            fprintf(f, "%.2f,%.2f ", px(v.x), py(v.y));
        }
        fprintf(f, "\" fill=\"%s\" %s stroke-linejoin=\"round\"/>\n", fill, style);
        break;
    default: break;
    }
}

static void svg_contact(sx_vec2 point, sx_vec2 normal, sx_real depth, void *context) {
    FILE *f = ((svg_out *)context)->f;
    sx_vec2 tip = sx_add(point, sx_scale(normal, SX_R(0.25)));
    (void)depth;
    fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"1.6\" fill=\"#d93025\"/>\n", px(point.x),
            py(point.y));
    fprintf(f,
            "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"#d93025\" "
            "stroke-width=\"0.8\"/>\n",
            px(point.x), py(point.y), px(tip.x), py(tip.y));
}

static int write_svg(const sx_world *world, const char *path, int seconds) {
    sx_debug_draw draw;
    svg_out out;
    out.f = fopen(path, "w");
    if (out.f == NULL) return 0;
    fprintf(out.f,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"%.0f %.0f %.0f %.0f\" "
            "width=\"%.0f\" height=\"%.0f\">\n",
            -16.5 * DEMO_PIXELS_PER_METER, -21.0 * DEMO_PIXELS_PER_METER,
            33.0 * DEMO_PIXELS_PER_METER, 22.5 * DEMO_PIXELS_PER_METER,
            33.0 * DEMO_PIXELS_PER_METER, 22.5 * DEMO_PIXELS_PER_METER);
    fprintf(out.f,
            "<rect x=\"%.0f\" y=\"%.0f\" width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n",
            -16.5 * DEMO_PIXELS_PER_METER, -21.0 * DEMO_PIXELS_PER_METER);
    draw.draw_shape = svg_shape;
    draw.draw_contact = svg_contact;
    draw.draw_aabb = NULL;
    draw.context = &out;
    sx_world_draw(world, &draw);
    fprintf(
        out.f,
        "<text x=\"%.0f\" y=\"%.0f\" font-family=\"sans-serif\" font-size=\"16\">sepax + flecs: "
        "%d bodies after %d s</text>\n</svg>\n",
        -16.0 * DEMO_PIXELS_PER_METER, -20.0 * DEMO_PIXELS_PER_METER, sx_world_body_count(world),
        seconds);
    return fclose(out.f) == 0;
}

int main(int argc, char **argv) {
    const char *svg = argc > 1 ? argv[1] : "build/demo/final.svg";
    int seconds = argc > 2 ? atoi(argv[2]) : 8;
    ecs_world_t *world;
    demo_stream stream = {0.0, 0, 12345u};
    int frame, i, j, parts, begins = 0;
    double elapsed = 0.0;
    int64_t steps_before = 0;

    if (seconds < 1 || seconds > 3600) {
        fprintf(stderr, "usage: demo [out.svg] [seconds 1..3600]\n");
        return 2;
    }
    world = ecs_init();
    ECS_IMPORT(world, SepaxPhysics);

    /* ground (top at y = 0) and walls */
    spawn(world, SX_BODY_STATIC, sx_v2(SX_R(0.0), SX_R(-0.5)), SX_R(0.0),
          sx_box_shape(SX_R(16.0), SX_R(0.5)));
    spawn(world, SX_BODY_STATIC, sx_v2(SX_R(-15.5), SX_R(10.0)), SX_R(0.0),
          sx_box_shape(SX_R(0.5), SX_R(10.0)));
    spawn(world, SX_BODY_STATIC, sx_v2(SX_R(15.5), SX_R(10.0)), SX_R(0.0),
          sx_box_shape(SX_R(0.5), SX_R(10.0)));
    /* a pyramid of 8 on the left */
    for (i = 0; i < 8; ++i) {
        for (j = i; j < 8; ++j) {
            sx_vec2 p = sx_v2(SX_R(-9.0) + (sx_real)(i + 1) * SX_R(0.5) + (sx_real)(j - i),
                              (sx_real)(2 * i + 1) * SX_R(0.5));
            spawn(world, SX_BODY_DYNAMIC, p, SX_R(0.0), sx_box_shape(SX_R(0.5), SX_R(0.5)));
        }
    }
    /* the concave cup, fixed in mid-air on the right */
    parts = add_cup(world, sx_v2(SX_R(6.0), SX_R(4.0)));
    printf("sepax demo: ground, walls, a pyramid of 36 boxes, a cup (one compound collider of %d "
           "convex parts), "
           "%d falling shapes; fixed step 1/60 s, %d s\n",
           parts, DEMO_SPAWN_COUNT, seconds);

    ecs_system(world, {.entity = ecs_entity(world, {.name = "SpawnStream",
                                                    .add = ecs_ids(ecs_dependson(EcsOnUpdate))}),
                       .callback = spawn_stream,
                       .ctx = &stream});

    ecs_observer(world, {.query.terms = {{ecs_id(SxCollider)}},
                         .events = {SxContactBegin},
                         .callback = count_begins,
                         .ctx = &begins});

    for (frame = 1; frame <= 60 * seconds; ++frame) {
        clock_t start = clock();
        ecs_progress(world, (ecs_ftime_t)(1.0 / 60.0));
        elapsed += (double)(clock() - start) / CLOCKS_PER_SEC;
        if (frame % 60 == 0) {
            const sx_world *w = sx_ecs_world(world);
            int64_t steps = sx_ecs_step_count(world);
            printf("t = %2d s: %4d bodies, %4d awake, %4d contacts (%4d began), %.3f ms per step\n",
                   frame / 60, sx_world_body_count(w), sx_world_awake_body_count(w),
                   ecs_singleton_get(world, SxContacts)->count, begins,
                   steps > steps_before ? 1000.0 * elapsed / (double)(steps - steps_before) : 0.0);
            elapsed = 0.0;
            steps_before = steps;
            begins = 0;
        }
    }
    if (!write_svg(sx_ecs_world(world), svg, seconds)) {
        fprintf(stderr, "demo: could not write %s\n", svg);
        ecs_fini(world);
        return 1;
    }
    printf("final frame: %s\n", svg);
    return ecs_fini(world);
}
