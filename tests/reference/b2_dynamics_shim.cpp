// The C interface of b2_dynamics_shim.h over Box2D 2.4.1 (bodies, fixtures, joints, stepping).
#include "b2_dynamics_shim.h"

#include <box2d/box2d.h>

#include <cmath>
#include <new>

struct b2y_world {
  b2World world;
  explicit b2y_world(const b2Vec2& gravity) : world(gravity) {}
};

namespace {

b2Body* to_b2(b2y_body* body) { return reinterpret_cast<b2Body*>(body); }
const b2Body* to_b2(const b2y_body* body) { return reinterpret_cast<const b2Body*>(body); }

bool finite(float a) { return std::isfinite(a); }

bool material_ok(const b2y_material* m) {
  return m != nullptr && finite(m->density) && m->density >= 0.0f && finite(m->friction) && m->friction >= 0.0f &&
         finite(m->restitution) && m->restitution >= 0.0f && finite(m->restitution_threshold) &&
         m->restitution_threshold >= 0.0f;
}

int add_fixture(b2y_body* body, const b2Shape* shape, const b2y_material* m) {
  b2FixtureDef fd;
  fd.shape = shape;
  fd.density = m->density;
  fd.friction = m->friction;
  fd.restitution = m->restitution;
  fd.restitutionThreshold = m->restitution_threshold;
  return to_b2(body)->CreateFixture(&fd) != nullptr;
}

}  // namespace

extern "C" {

b2y_material b2y_default_material(void) {
  b2FixtureDef fd;
  b2y_material m;
  m.density = 1.0f;
  m.friction = fd.friction;
  m.restitution = fd.restitution;
  m.restitution_threshold = fd.restitutionThreshold;
  return m;
}

b2y_world* b2y_world_create(float gx, float gy) {
  if (!finite(gx) || !finite(gy)) return nullptr;
  return new (std::nothrow) b2y_world(b2Vec2(gx, gy));
}

void b2y_world_destroy(b2y_world* world) { delete world; }

void b2y_world_set_allow_sleeping(b2y_world* world, int allow) {
  if (world != nullptr) world->world.SetAllowSleeping(allow != 0);
}

void b2y_world_step(b2y_world* world, float dt, int velocity_iterations, int position_iterations) {
  if (world == nullptr || !(dt > 0.0f) || !finite(dt) || velocity_iterations < 1 || position_iterations < 0) return;
  world->world.Step(dt, velocity_iterations, position_iterations);
}

b2y_body* b2y_body_create(b2y_world* world, b2y_body_type type, float x, float y, float angle) {
  if (world == nullptr || !finite(x) || !finite(y) || !finite(angle)) return nullptr;
  if (type != B2Y_STATIC && type != B2Y_KINEMATIC && type != B2Y_DYNAMIC) return nullptr;
  b2BodyDef bd;
  bd.type = type == B2Y_STATIC ? b2_staticBody : type == B2Y_KINEMATIC ? b2_kinematicBody : b2_dynamicBody;
  bd.position.Set(x, y);
  bd.angle = angle;
  return reinterpret_cast<b2y_body*>(world->world.CreateBody(&bd));
}

void b2y_body_set_velocity(b2y_body* body, float vx, float vy, float w) {
  if (body == nullptr || !finite(vx) || !finite(vy) || !finite(w)) return;
  to_b2(body)->SetLinearVelocity(b2Vec2(vx, vy));
  to_b2(body)->SetAngularVelocity(w);
}

void b2y_body_set_bullet(b2y_body* body, int bullet) {
  if (body != nullptr) to_b2(body)->SetBullet(bullet != 0);
}

int b2y_body_add_box(b2y_body* body, float hx, float hy, float cx, float cy, float angle, const b2y_material* m) {
  if (body == nullptr || !material_ok(m) || !(hx > 0.0f) || !(hy > 0.0f) || !finite(hx) || !finite(hy) || !finite(cx) ||
      !finite(cy) || !finite(angle))
    return 0;
  b2PolygonShape box;
  box.SetAsBox(hx, hy, b2Vec2(cx, cy), angle);
  return add_fixture(body, &box, m);
}

int b2y_body_add_circle(b2y_body* body, float cx, float cy, float radius, const b2y_material* m) {
  if (body == nullptr || !material_ok(m) || !finite(cx) || !finite(cy) || !(radius > 0.0f) || !finite(radius)) return 0;
  b2CircleShape circle;
  circle.m_p.Set(cx, cy);
  circle.m_radius = radius;
  return add_fixture(body, &circle, m);
}

int b2y_body_add_edge(b2y_body* body, float x1, float y1, float x2, float y2, const b2y_material* m) {
  if (body == nullptr || !material_ok(m) || !finite(x1) || !finite(y1) || !finite(x2) || !finite(y2)) return 0;
  b2Vec2 a(x1, y1), b(x2, y2);
  if (b2DistanceSquared(a, b) <= b2_linearSlop * b2_linearSlop) return 0;
  b2EdgeShape edge;
  edge.SetTwoSided(a, b);
  return add_fixture(body, &edge, m);
}

void b2y_body_get_state(const b2y_body* body, b2y_state* out) {
  if (body == nullptr || out == nullptr) return;
  const b2Body* b = to_b2(body);
  const b2Vec2& p = b->GetPosition();
  const b2Vec2& c = b->GetWorldCenter();
  const b2Vec2& v = b->GetLinearVelocity();
  out->x = p.x;
  out->y = p.y;
  out->angle = b->GetAngle();
  out->cx = c.x;
  out->cy = c.y;
  out->vx = v.x;
  out->vy = v.y;
  out->w = b->GetAngularVelocity();
  out->awake = b->IsAwake() ? 1 : 0;
}

float b2y_body_get_mass(const b2y_body* body) { return body != nullptr ? to_b2(body)->GetMass() : 0.0f; }

int b2y_revolute_joint_create(b2y_world* world, b2y_body* a, b2y_body* b, float wx, float wy) {
  if (world == nullptr || a == nullptr || b == nullptr || a == b || !finite(wx) || !finite(wy)) return 0;
  b2RevoluteJointDef jd;
  jd.Initialize(to_b2(a), to_b2(b), b2Vec2(wx, wy));
  return world->world.CreateJoint(&jd) != nullptr;
}

}  // extern "C"
