// The C interface of b2_distance_shim.h over Box2D 2.4.1 (distance, shape cast, TOI, ray casts).
#include "b2_distance_shim.h"

#include <box2d/b2_distance.h>
#include <box2d/b2_time_of_impact.h>
#include <box2d/box2d.h>

#include <cmath>

namespace {

bool finite(float a) { return std::isfinite(a); }

// Copies a proxy's points into a b2Vec2 buffer that outlives the b2DistanceProxy using it (Set keeps a pointer).
bool to_b2(const b2d_proxy* p, b2Vec2* buffer, b2DistanceProxy* proxy) {
  if (p == nullptr || p->count < 1 || p->count > b2_maxPolygonVertices) return false;
  if (!finite(p->radius) || p->radius < 0.0f) return false;
  for (int i = 0; i < p->count; ++i) {
    if (!finite(p->x[i]) || !finite(p->y[i])) return false;
    buffer[i].Set(p->x[i], p->y[i]);
  }
  proxy->Set(buffer, p->count, p->radius);
  return true;
}

bool to_b2(const b2d_transform& t, b2Transform* xf) {
  if (!finite(t.px) || !finite(t.py) || !finite(t.c) || !finite(t.s)) return false;
  xf->p.Set(t.px, t.py);
  xf->q.c = t.c;  // set directly: b2Rot(angle) would recompute cos/sin and round differently
  xf->q.s = t.s;
  return true;
}

bool to_b2(const b2d_sweep* s, b2Sweep* sweep) {
  if (s == nullptr) return false;
  const float v[] = {s->lcx, s->lcy, s->c1x, s->c1y, s->c2x, s->c2y, s->a1, s->a2};
  for (float x : v)
    if (!finite(x)) return false;
  sweep->localCenter.Set(s->lcx, s->lcy);
  sweep->c0.Set(s->c1x, s->c1y);
  sweep->c.Set(s->c2x, s->c2y);
  sweep->a0 = s->a1;
  sweep->a = s->a2;
  sweep->alpha0 = 0.0f;
  return true;
}

bool to_b2(const b2d_ray* r, b2RayCastInput* in) {
  if (r == nullptr || !finite(r->p1x) || !finite(r->p1y) || !finite(r->p2x) || !finite(r->p2y) ||
      !finite(r->max_fraction))
    return false;
  in->p1.Set(r->p1x, r->p1y);
  in->p2.Set(r->p2x, r->p2y);
  in->maxFraction = r->max_fraction;
  return true;
}

int ray_cast(const b2Shape& shape, const b2Transform& xf, const b2RayCastInput& in, b2d_ray_output* out) {
  b2RayCastOutput o;
  if (!shape.RayCast(&o, in, xf, 0)) return 0;
  out->nx = o.normal.x;
  out->ny = o.normal.y;
  out->fraction = o.fraction;
  return 1;
}

}  // namespace

extern "C" {

int b2d_distance(const b2d_proxy* a, b2d_transform xa, const b2d_proxy* b, b2d_transform xb, int use_radii,
                 b2d_distance_output* out) {
  if (out == nullptr) return 0;
  b2Vec2 va[b2_maxPolygonVertices], vb[b2_maxPolygonVertices];
  b2DistanceInput in;
  if (!to_b2(a, va, &in.proxyA) || !to_b2(b, vb, &in.proxyB)) return 0;
  if (!to_b2(xa, &in.transformA) || !to_b2(xb, &in.transformB)) return 0;
  in.useRadii = use_radii != 0;
  b2SimplexCache cache;
  cache.count = 0;
  b2DistanceOutput o;
  b2Distance(&o, &cache, &in);
  out->ax = o.pointA.x;
  out->ay = o.pointA.y;
  out->bx = o.pointB.x;
  out->by = o.pointB.y;
  out->distance = o.distance;
  out->iterations = o.iterations;
  return 1;
}

int b2d_shape_cast(const b2d_proxy* a, b2d_transform xa, const b2d_proxy* b, b2d_transform xb, float tx, float ty,
                   b2d_cast_output* out) {
  if (out == nullptr || !finite(tx) || !finite(ty)) return 0;
  b2Vec2 va[b2_maxPolygonVertices], vb[b2_maxPolygonVertices];
  b2ShapeCastInput in;
  if (!to_b2(a, va, &in.proxyA) || !to_b2(b, vb, &in.proxyB)) return 0;
  if (!to_b2(xa, &in.transformA) || !to_b2(xb, &in.transformB)) return 0;
  in.translationB.Set(tx, ty);
  b2ShapeCastOutput o;
  bool hit = b2ShapeCast(&o, &in);
  out->px = o.point.x;
  out->py = o.point.y;
  out->nx = o.normal.x;
  out->ny = o.normal.y;
  out->fraction = o.lambda;
  out->iterations = o.iterations;
  out->hit = hit ? 1 : 0;
  return 1;
}

int b2d_time_of_impact(const b2d_proxy* a, const b2d_sweep* sa, const b2d_proxy* b, const b2d_sweep* sb, float t_max,
                       b2d_toi_output* out) {
  if (out == nullptr || !finite(t_max) || t_max < 0.0f || t_max > 1.0f) return 0;
  b2Vec2 va[b2_maxPolygonVertices], vb[b2_maxPolygonVertices];
  b2TOIInput in;
  if (!to_b2(a, va, &in.proxyA) || !to_b2(b, vb, &in.proxyB)) return 0;
  if (!to_b2(sa, &in.sweepA) || !to_b2(sb, &in.sweepB)) return 0;
  in.tMax = t_max;
  b2TOIOutput o;
  b2TimeOfImpact(&o, &in);
  out->state = static_cast<int>(o.state);
  out->t = o.t;
  return 1;
}

float b2d_linear_slop(void) { return b2_linearSlop; }

int b2d_ray_cast_circle(float cx, float cy, float radius, b2d_transform xf, const b2d_ray* ray, b2d_ray_output* out) {
  b2Transform t;
  b2RayCastInput in;
  if (out == nullptr || !finite(cx) || !finite(cy) || !finite(radius) || radius <= 0.0f) return 0;
  if (!to_b2(xf, &t) || !to_b2(ray, &in)) return 0;
  b2CircleShape circle;
  circle.m_p.Set(cx, cy);
  circle.m_radius = radius;
  return ray_cast(circle, t, in, out);
}

int b2d_ray_cast_polygon(const float* xy, int count, b2d_transform xf, const b2d_ray* ray, b2d_ray_output* out) {
  b2Transform t;
  b2RayCastInput in;
  if (out == nullptr || xy == nullptr || count < 3 || count > b2_maxPolygonVertices) return 0;
  if (!to_b2(xf, &t) || !to_b2(ray, &in)) return 0;
  // Fill the polygon directly: b2PolygonShape::Set would recompute a hull (and may reorder or weld), while the
  // comparison wants exactly the caller's vertices. The normals are what Set computes: Cross(edge, 1), normalised.
  b2PolygonShape polygon;
  for (int i = 0; i < count; ++i) {
    if (!finite(xy[2 * i]) || !finite(xy[2 * i + 1])) return 0;
    polygon.m_vertices[i].Set(xy[2 * i], xy[2 * i + 1]);
  }
  for (int i = 0; i < count; ++i) {
    b2Vec2 edge = polygon.m_vertices[(i + 1) % count] - polygon.m_vertices[i];
    if (edge.LengthSquared() <= b2_epsilon * b2_epsilon) return 0;
    polygon.m_normals[i] = b2Cross(edge, 1.0f);
    polygon.m_normals[i].Normalize();
  }
  polygon.m_count = count;
  return ray_cast(polygon, t, in, out);
}

int b2d_ray_cast_edge(float x1, float y1, float x2, float y2, b2d_transform xf, const b2d_ray* ray,
                      b2d_ray_output* out) {
  b2Transform t;
  b2RayCastInput in;
  if (out == nullptr || !finite(x1) || !finite(y1) || !finite(x2) || !finite(y2)) return 0;
  if (!to_b2(xf, &t) || !to_b2(ray, &in)) return 0;
  b2EdgeShape edge;
  edge.SetTwoSided(b2Vec2(x1, y1), b2Vec2(x2, y2));
  return ray_cast(edge, t, in, out);
}

}  // extern "C"
