// The C interface of b2_shim.h over Box2D 2.4.1 (bodies and mass only).
#include "b2_shim.h"

#include <box2d/box2d.h>

#include <cmath>
#include <new>

struct b2s_world {
  b2World world;
  explicit b2s_world(const b2Vec2& gravity) : world(gravity) {}
};

namespace {

b2Body* to_b2(b2s_body* body) { return reinterpret_cast<b2Body*>(body); }
const b2Body* to_b2(const b2s_body* body) { return reinterpret_cast<const b2Body*>(body); }

bool finite(float a) { return std::isfinite(a); }

// Box2D's own welding in b2PolygonShape::Set: a point closer than 0.5 * b2_linearSlop to an earlier kept point is
// dropped. Returns the number of points kept in ps.
int weld(const float* xy, int count, b2Vec2* ps) {
  int n = 0;
  for (int i = 0; i < count; ++i) {
    b2Vec2 v(xy[2 * i], xy[2 * i + 1]);
    bool unique = true;
    for (int j = 0; j < n && unique; ++j)
      unique = !(b2DistanceSquared(v, ps[j]) < ((0.5f * b2_linearSlop) * (0.5f * b2_linearSlop)));
    if (unique) ps[n++] = v;
  }
  return n;
}

// Box2D mass data (inertia about the shape's or body's origin) with the inertia also shifted to the centre of mass:
// I_c = I_origin - m |c|^2, in double so that the shift adds no rounding of its own.
b2s_mass to_mass(float mass, const b2Vec2& center, float inertia_origin) {
  b2s_mass m;
  m.mass = mass;
  m.cx = center.x;
  m.cy = center.y;
  m.inertia_origin = inertia_origin;
  m.inertia = m.inertia_origin - m.mass * (m.cx * m.cx + m.cy * m.cy);
  return m;
}

}  // namespace

extern "C" {

b2s_world* b2s_world_create(float gx, float gy) {
  if (!finite(gx) || !finite(gy)) return nullptr;
  return new (std::nothrow) b2s_world(b2Vec2(gx, gy));
}

void b2s_world_destroy(b2s_world* world) { delete world; }

void b2s_world_step(b2s_world* world, float dt, int velocity_iterations, int position_iterations) {
  if (world == nullptr) return;
  world->world.Step(dt, velocity_iterations, position_iterations);
}

b2s_body_def b2s_default_body_def(void) {
  b2s_body_def def = {};
  def.gravity_scale = 1.0f;
  return def;
}

b2s_body* b2s_body_create(b2s_world* world, const b2s_body_def* def) {
  if (world == nullptr || def == nullptr) return nullptr;
  b2BodyDef bd;
  bd.type = b2_dynamicBody;
  bd.position.Set(def->x, def->y);
  bd.angle = def->angle;
  bd.linearVelocity.Set(def->vx, def->vy);
  bd.angularVelocity = def->w;
  bd.linearDamping = def->linear_damping;
  bd.angularDamping = def->angular_damping;
  bd.gravityScale = def->gravity_scale;
  bd.fixedRotation = def->fixed_rotation != 0;
  bd.allowSleep = false;  // tumble never puts a body to sleep
  return reinterpret_cast<b2s_body*>(world->world.CreateBody(&bd));
}

int b2s_body_add_circle(b2s_body* body, float cx, float cy, float radius, float density) {
  if (body == nullptr || !finite(cx) || !finite(cy) || !(radius > 0.0f) || !finite(radius) || !(density >= 0.0f))
    return 0;
  b2CircleShape circle;
  circle.m_p.Set(cx, cy);
  circle.m_radius = radius;
  b2FixtureDef fd;
  fd.shape = &circle;
  fd.density = density;
  return to_b2(body)->CreateFixture(&fd) != nullptr;
}

int b2s_body_add_polygon(b2s_body* body, const float* xy, int count, float density) {
  if (body == nullptr || !b2s_polygon_is_valid(xy, count) || !(density >= 0.0f)) return 0;
  b2Vec2 pts[B2S_MAX_POLYGON_VERTICES];
  for (int i = 0; i < count; ++i) pts[i].Set(xy[2 * i], xy[2 * i + 1]);
  b2PolygonShape poly;
  poly.Set(pts, count);
  b2FixtureDef fd;
  fd.shape = &poly;
  fd.density = density;
  return to_b2(body)->CreateFixture(&fd) != nullptr;
}

int b2s_body_add_box(b2s_body* body, float hx, float hy, float cx, float cy, float angle, float density) {
  if (body == nullptr || !(hx > 0.0f) || !(hy > 0.0f) || !finite(hx) || !finite(hy) || !finite(cx) || !finite(cy) ||
      !finite(angle) || !(density >= 0.0f))
    return 0;
  b2PolygonShape box;
  box.SetAsBox(hx, hy, b2Vec2(cx, cy), angle);
  b2FixtureDef fd;
  fd.shape = &box;
  fd.density = density;
  return to_b2(body)->CreateFixture(&fd) != nullptr;
}

void b2s_body_apply_force(b2s_body* body, float fx, float fy, float px, float py) {
  if (body != nullptr) to_b2(body)->ApplyForce(b2Vec2(fx, fy), b2Vec2(px, py), true);
}

void b2s_body_apply_force_to_center(b2s_body* body, float fx, float fy) {
  if (body != nullptr) to_b2(body)->ApplyForceToCenter(b2Vec2(fx, fy), true);
}

void b2s_body_apply_torque(b2s_body* body, float torque) {
  if (body != nullptr) to_b2(body)->ApplyTorque(torque, true);
}

void b2s_body_apply_linear_impulse(b2s_body* body, float jx, float jy, float px, float py) {
  if (body != nullptr) to_b2(body)->ApplyLinearImpulse(b2Vec2(jx, jy), b2Vec2(px, py), true);
}

void b2s_body_apply_angular_impulse(b2s_body* body, float impulse) {
  if (body != nullptr) to_b2(body)->ApplyAngularImpulse(impulse, true);
}

void b2s_body_get_state(const b2s_body* body, b2s_body_state* out) {
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
}

void b2s_body_get_mass(const b2s_body* body, b2s_mass* out) {
  if (body == nullptr || out == nullptr) return;
  const b2Body* b = to_b2(body);
  // GetInertia() is about the body origin: m_I + m |localCenter|^2 (in float).
  *out = to_mass(b->GetMass(), b->GetLocalCenter(), b->GetInertia());
}

int b2s_polygon_is_valid(const float* xy, int count) {
  if (xy == nullptr || count < 3 || count > b2_maxPolygonVertices) return 0;
  for (int i = 0; i < 2 * count; ++i)
    if (!finite(xy[i])) return 0;
  b2Vec2 ps[b2_maxPolygonVertices];
  int n = weld(xy, count, ps);
  if (n < 3) return 0;  // Set() would assert (and fall back to a 2 x 2 box)
  // Set() and ComputeMass() assert area > b2_epsilon. The hull's area is at least that of the largest triangle of
  // its points; demanding 4 b2_epsilon of it leaves room for Box2D's float rounding (and excludes collinear sets,
  // for which the gift wrapping would find fewer than 3 vertices).
  double largest = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        double ax = (double)ps[j].x - ps[i].x, ay = (double)ps[j].y - ps[i].y;
        double bx = (double)ps[k].x - ps[i].x, by = (double)ps[k].y - ps[i].y;
        double a = 0.5 * std::fabs(ax * by - ay * bx);
        if (a > largest) largest = a;
      }
  return largest > 4.0 * (double)b2_epsilon;
}

int b2s_polygon_mass(const float* xy, int count, float density, b2s_mass* out, float* hull_xy, int* hull_count) {
  if (out == nullptr || !b2s_polygon_is_valid(xy, count) || !finite(density)) return 0;
  b2Vec2 pts[B2S_MAX_POLYGON_VERTICES];
  for (int i = 0; i < count; ++i) pts[i].Set(xy[2 * i], xy[2 * i + 1]);
  b2PolygonShape poly;
  poly.Set(pts, count);
  b2MassData md;
  poly.ComputeMass(&md, density);
  // Box2D 2.4.1: md.I is about the shape origin, not the centroid.
  *out = to_mass(md.mass, md.center, md.I);
  if (hull_xy != nullptr) {
    for (int i = 0; i < poly.m_count; ++i) {
      hull_xy[2 * i] = poly.m_vertices[i].x;
      hull_xy[2 * i + 1] = poly.m_vertices[i].y;
    }
  }
  if (hull_count != nullptr) *hull_count = poly.m_count;
  return 1;
}

}  // extern "C"
