/* Box2D v3 behind the bench engine interface (tools/bench/engine.h), through
 * v3's C API. Built only by `make bench-v3 BOX2D_V3_DIR=...` (mk/bench_v3.mk),
 * against the v3 tree given there; never by make bench, make test or CI.
 *
 * What it does for each call is what tools/bench_engine_b2.cpp does for
 * Box2D 2.4.1, with v3's defaults for everything the interface does not set
 * (contact hertz, damping, speculative distance, continuous collision on).
 * Two places differ on purpose:
 * - angles: v3 keeps a body's rotation as a cosine/sine pair and its own
 *   b2MakeRot / b2Rot_GetAngle are fast approximations (errors of order 1e-3
 *   rad), which would tilt the inclines and swamp constant_spin's angle error.
 *   Rotations are built here from cos/sin and read back with atan2, in double.
 * - unwrapped angles: 2.4.1 and tumble report a body's angle without wrapping
 *   (constant_spin turns 6 rad); v3's rotation wraps at pi. After each step
 *   the wrapper counts, from v3's body move events, the moved bodies whose
 *   rotation crossed the wrap at pi (no atan2 there: this cost is inside the
 *   timed step call, a few multiplications per moved body); v3 caps a body's
 *   turn at pi/4 a step (B2_MAX_ROTATION), well inside the pi this needs.
 * v3's polygons have no skin (radius 0), so polygon_skin is 0. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "bench/engine.h"
#include "box2d/box2d.h"

#define V3_PI 3.14159265358979323846

/* A body's rotation when the wrapper last saw it, and how many times it has
 * turned through the wrap at pi since (+1 counter-clockwise). */
typedef struct v3_turns {
  b2Rot q;
  int turns;
} v3_turns;

typedef struct v3_world {
  b2WorldId id;
  bench_setting setting;
  double spring_k;
  b2BodyId* bodies;
  v3_turns* turns; /* of each body */
  int count, capacity;
} v3_world;

static b2Rot rot(double angle) {
  b2Rot q = {(float)cos(angle), (float)sin(angle)};
  return q;
}

static double rot_angle(b2Rot q) { return atan2((double)q.s, (double)q.c); }

static void* v3_create(const bench_world_def* def, const bench_setting* setting) {
  v3_world* w = calloc(1, sizeof *w);
  if (w == NULL) return NULL;
  w->setting = *setting;
  w->spring_k = def->spring_k;
  b2WorldDef wd = b2DefaultWorldDef();
  wd.gravity = (b2Vec2){(float)def->gravity_x, (float)def->gravity_y};
  wd.enableSleep = def->enable_sleep;
  wd.restitutionThreshold = (float)def->restitution_threshold;
  wd.workerCount = 1;
  w->id = b2CreateWorld(&wd);
  if (!b2World_IsValid(w->id)) {
    free(w);
    return NULL;
  }
  return w;
}

static void v3_destroy(void* world) {
  v3_world* w = world;
  if (w == NULL) return;
  b2DestroyWorld(w->id);
  free(w->bodies);
  free(w->turns);
  free(w);
}

static int v3_add_body(void* world, const bench_body_def* def) {
  v3_world* w = world;
  if (w->count == w->capacity) {
    int capacity = w->capacity ? 2 * w->capacity : 64;
    b2BodyId* bodies = realloc(w->bodies, sizeof *bodies * (size_t)capacity);
    if (bodies == NULL) return -1;
    w->bodies = bodies;
    v3_turns* turns = realloc(w->turns, sizeof *turns * (size_t)capacity);
    if (turns == NULL) return -1;
    w->turns = turns;
    w->capacity = capacity;
  }
  b2BodyDef bd = b2DefaultBodyDef();
  bd.type = def->type == BENCH_STATIC      ? b2_staticBody
            : def->type == BENCH_KINEMATIC ? b2_kinematicBody
                                           : b2_dynamicBody;
  bd.position = (b2Pos){(float)def->x, (float)def->y};
  bd.rotation = rot(def->angle);
  bd.linearVelocity = (b2Vec2){(float)def->vx, (float)def->vy};
  bd.angularVelocity = (float)def->w;
  bd.isBullet = def->bullet;
  bd.isAwake = def->awake;
  /* the body's index, to find its angle from a move event */
  bd.userData = (void*)(uintptr_t)w->count;
  b2BodyId b = b2CreateBody(w->id, &bd);
  if (!b2Body_IsValid(b)) return -1;
  w->bodies[w->count] = b;
  w->turns[w->count].q = bd.rotation;
  w->turns[w->count].turns = (int)floor((def->angle - rot_angle(bd.rotation)) / (2.0 * V3_PI) + 0.5);
  return w->count++;
}

static b2ShapeDef shape_def(const bench_material* m) {
  b2ShapeDef sd = b2DefaultShapeDef();
  sd.density = (float)m->density;
  sd.material.friction = (float)m->friction;
  sd.material.restitution = (float)m->restitution;
  sd.filter.groupIndex = m->group;
  return sd;
}

static int v3_add_box(void* world, int body, double hx, double hy, double cx, double cy, double angle,
                      const bench_material* m) {
  v3_world* w = world;
  b2Polygon box = b2MakeOffsetBox((float)hx, (float)hy, (b2Vec2){(float)cx, (float)cy}, rot(angle));
  b2ShapeDef sd = shape_def(m);
  return b2Shape_IsValid(b2CreatePolygonShape(w->bodies[body], &sd, &box)) ? 0 : 1;
}

static int v3_add_circle(void* world, int body, double radius, double cx, double cy, const bench_material* m) {
  v3_world* w = world;
  b2Circle c = {{(float)cx, (float)cy}, (float)radius};
  b2ShapeDef sd = shape_def(m);
  return b2Shape_IsValid(b2CreateCircleShape(w->bodies[body], &sd, &c)) ? 0 : 1;
}

static int v3_add_revolute(void* world, int a, int b, double x, double y) {
  v3_world* w = world;
  b2Pos p = {(float)x, (float)y};
  b2RevoluteJointDef jd = b2DefaultRevoluteJointDef();
  jd.base.bodyIdA = w->bodies[a];
  jd.base.bodyIdB = w->bodies[b];
  jd.base.localFrameA.p = b2Body_GetLocalPoint(w->bodies[a], p);
  jd.base.localFrameB.p = b2Body_GetLocalPoint(w->bodies[b], p);
  return b2Joint_IsValid(b2CreateRevoluteJoint(w->id, &jd)) ? 0 : 1;
}

static int v3_step(void* world) {
  v3_world* w = world;
  if (w->spring_k > 0.0) {
    float k = (float)w->spring_k;
    for (int i = 0; i < w->count; ++i) {
      b2BodyId b = w->bodies[i];
      if (b2Body_GetType(b) != b2_dynamicBody) continue;
      b2Pos c = b2Body_GetWorldCenter(b);
      b2Body_ApplyForceToCenter(b, (b2Vec2){-k * (float)c.x, -k * (float)c.y}, true);
    }
  }
  b2World_Step(w->id, (float)w->setting.dt, w->setting.substeps);
  b2BodyEvents events = b2World_GetBodyEvents(w->id);
  for (int i = 0; i < events.moveCount; ++i) {
    const b2BodyMoveEvent* e = &events.moveEvents[i];
    v3_turns* t = &w->turns[(uintptr_t)e->userData];
    b2Rot a = t->q, b = e->transform.q;
    /* the sine changed sign: the short arc from a to b crossed the x axis,
     * at pi (where the angle wraps) when its chord crosses at x < 0, that is
     * when sin(b - a) and b.s - a.s differ in sign */
    if ((a.s < 0.0f) != (b.s < 0.0f) && (a.c * b.s - b.c * a.s) * (b.s - a.s) < 0.0f) t->turns += b.s < a.s ? 1 : -1;
    t->q = b;
  }
  return 0;
}

static void v3_get_state(void* world, int body, bench_state* out) {
  v3_world* w = world;
  b2BodyId b = w->bodies[body];
  b2Pos p = b2Body_GetPosition(b), c = b2Body_GetWorldCenter(b);
  b2Vec2 v = b2Body_GetLinearVelocity(b);
  out->x = p.x;
  out->y = p.y;
  out->angle = rot_angle(b2Body_GetRotation(b)) + 2.0 * V3_PI * w->turns[body].turns;
  out->cx = c.x;
  out->cy = c.y;
  out->vx = v.x;
  out->vy = v.y;
  out->w = b2Body_GetAngularVelocity(b);
  out->awake = b2Body_IsAwake(b);
}

static double v3_mass(void* world, int body) { return b2Body_GetMass(((v3_world*)world)->bodies[body]); }

/* v3's rotational inertia is already about the centre of mass */
static double v3_inertia(void* world, int body) {
  return b2Body_GetRotationalInertia(((v3_world*)world)->bodies[body]);
}

/* touching contacts (with manifold points, speculative ones included, as
 * tumble counts them): each is on both of its bodies' lists, static ones too */
static void v3_counts(void* world, int* bodies, int* contacts, int* joints) {
  v3_world* w = world;
  b2Counters c = b2World_GetCounters(w->id);
  *bodies = c.bodyCount;
  *joints = c.jointCount;
  int ends = 0, capacity = 0;
  b2ContactData* data = NULL;
  for (int i = 0; i < w->count; ++i) {
    int need = b2Body_GetContactCapacity(w->bodies[i]);
    if (need > capacity) {
      b2ContactData* grown = realloc(data, sizeof *grown * (size_t)need);
      if (grown == NULL) break;
      data = grown;
      capacity = need;
    }
    ends += b2Body_GetContactData(w->bodies[i], data, capacity);
  }
  free(data);
  *contacts = ends / 2;
}

const bench_engine bench_box2d_v3_engine = {
    "box2d_v3",      0.0,     v3_create,    v3_destroy, v3_add_body, v3_add_box, v3_add_circle,
    v3_add_revolute, v3_step, v3_get_state, v3_mass,    v3_inertia,  v3_counts,
};
