// Box2D 2.4.1 behind the bench engine interface (tools/bench/engine.h).
#include <box2d/box2d.h>

#include <new>
#include <vector>

#include "bench/engine.h"

namespace {

struct Box2dWorld {
  b2World world;
  bench_setting setting;
  double spring_k;
  float restitution_threshold;
  std::vector<b2Body*> bodies;
  Box2dWorld(const bench_world_def* def, const bench_setting* s)
      : world(b2Vec2(static_cast<float>(def->gravity_x), static_cast<float>(def->gravity_y))),
        setting(*s),
        spring_k(def->spring_k),
        restitution_threshold(static_cast<float>(def->restitution_threshold)) {
    world.SetAllowSleeping(def->enable_sleep);
  }
};

Box2dWorld* as_world(void* w) { return static_cast<Box2dWorld*>(w); }

void* create(const bench_world_def* def, const bench_setting* setting) {
  return new (std::nothrow) Box2dWorld(def, setting);
}

void destroy(void* world) { delete as_world(world); }

int add_body(void* world, const bench_body_def* def) {
  Box2dWorld* w = as_world(world);
  b2BodyDef bd;
  bd.type = def->type == BENCH_STATIC      ? b2_staticBody
            : def->type == BENCH_KINEMATIC ? b2_kinematicBody
                                           : b2_dynamicBody;
  bd.position.Set(static_cast<float>(def->x), static_cast<float>(def->y));
  bd.angle = static_cast<float>(def->angle);
  bd.linearVelocity.Set(static_cast<float>(def->vx), static_cast<float>(def->vy));
  bd.angularVelocity = static_cast<float>(def->w);
  bd.bullet = def->bullet;
  bd.awake = def->awake;
  w->bodies.push_back(w->world.CreateBody(&bd));
  return static_cast<int>(w->bodies.size()) - 1;
}

int add_fixture(Box2dWorld* w, int body, const b2Shape* shape, const bench_material* m) {
  b2FixtureDef fd;
  fd.shape = shape;
  fd.density = static_cast<float>(m->density);
  fd.friction = static_cast<float>(m->friction);
  fd.restitution = static_cast<float>(m->restitution);
  fd.restitutionThreshold = w->restitution_threshold;
  fd.filter.groupIndex = static_cast<int16>(m->group);
  return w->bodies[static_cast<size_t>(body)]->CreateFixture(&fd) != nullptr ? 0 : 1;
}

int add_box(void* world, int body, double hx, double hy, double cx, double cy, double angle, const bench_material* m) {
  b2PolygonShape box;
  box.SetAsBox(static_cast<float>(hx), static_cast<float>(hy), b2Vec2(static_cast<float>(cx), static_cast<float>(cy)),
               static_cast<float>(angle));
  return add_fixture(as_world(world), body, &box, m);
}

int add_circle(void* world, int body, double radius, double cx, double cy, const bench_material* m) {
  b2CircleShape c;
  c.m_p.Set(static_cast<float>(cx), static_cast<float>(cy));
  c.m_radius = static_cast<float>(radius);
  return add_fixture(as_world(world), body, &c, m);
}

int add_revolute(void* world, int a, int b, double x, double y) {
  Box2dWorld* w = as_world(world);
  b2RevoluteJointDef jd;
  jd.Initialize(w->bodies[static_cast<size_t>(a)], w->bodies[static_cast<size_t>(b)],
                b2Vec2(static_cast<float>(x), static_cast<float>(y)));
  return w->world.CreateJoint(&jd) != nullptr ? 0 : 1;
}

int step(void* world) {
  Box2dWorld* w = as_world(world);
  if (w->spring_k > 0.0) {
    for (b2Body* b : w->bodies) {
      if (b->GetType() != b2_dynamicBody) continue;
      b2Vec2 c = b->GetWorldCenter();
      float k = static_cast<float>(w->spring_k);
      b->ApplyForceToCenter(b2Vec2(-k * c.x, -k * c.y), true);
    }
  }
  w->world.Step(static_cast<float>(w->setting.dt), w->setting.velocity_iterations, w->setting.position_iterations);
  return 0;
}

void get_state(void* world, int body, bench_state* out) {
  const b2Body* b = as_world(world)->bodies[static_cast<size_t>(body)];
  out->x = b->GetPosition().x;
  out->y = b->GetPosition().y;
  out->angle = b->GetAngle();
  out->cx = b->GetWorldCenter().x;
  out->cy = b->GetWorldCenter().y;
  out->vx = b->GetLinearVelocity().x;
  out->vy = b->GetLinearVelocity().y;
  out->w = b->GetAngularVelocity();
  out->awake = b->IsAwake();
}

double mass(void* world, int body) { return as_world(world)->bodies[static_cast<size_t>(body)]->GetMass(); }

double inertia(void* world, int body) {
  const b2Body* b = as_world(world)->bodies[static_cast<size_t>(body)];
  // GetInertia is about the body origin; take it to the centre of mass
  b2Vec2 c = b->GetLocalCenter();
  return b->GetInertia() - b->GetMass() * b2Dot(c, c);
}

void counts(void* world, int* bodies, int* contacts, int* joints) {
  b2World& w = as_world(world)->world;
  *bodies = w.GetBodyCount();
  *joints = w.GetJointCount();
  int touching = 0;
  for (b2Contact* c = w.GetContactList(); c != nullptr; c = c->GetNext()) touching += c->IsTouching();
  *contacts = touching;
}

}  // namespace

extern "C" const bench_engine bench_box2d_engine = {
    "box2d", b2_polygonRadius, create, destroy, add_body, add_box, add_circle, add_revolute,
    step,    get_state,        mass,   inertia, counts,
};
