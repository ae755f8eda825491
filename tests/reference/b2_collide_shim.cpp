// The C interface of b2_collide_shim.h over Box2D 2.4.1's contact manifolds.
#include "b2_collide_shim.h"

#include <box2d/box2d.h>

namespace {

b2Transform to_b2(b2c_transform xf) {
  b2Transform t;
  t.p.Set(xf.x, xf.y);
  t.q.c = xf.c;  // the caller's rotation bits, not recomputed from an angle
  t.q.s = xf.s;
  return t;
}

void to_b2(const b2c_polygon* p, b2PolygonShape* out) {
  out->m_count = p->count;
  for (int i = 0; i < p->count; ++i) {
    out->m_vertices[i].Set(p->vertices[i][0], p->vertices[i][1]);
    out->m_normals[i].Set(p->normals[i][0], p->normals[i][1]);
  }
  out->m_centroid.Set(p->centroid[0], p->centroid[1]);
}

// Fills out from Box2D's manifold, evaluated at the transforms with the shapes' radii.
void report(const b2Manifold& m, const b2Transform& xfa, float ra, const b2Transform& xfb, float rb,
            b2c_manifold* out) {
  *out = b2c_manifold{};
  out->point_count = m.pointCount;
  if (m.pointCount == 0) return;
  out->type = m.type == b2Manifold::e_circles ? B2C_CIRCLES : (m.type == b2Manifold::e_faceA ? B2C_FACE_A : B2C_FACE_B);
  out->local_normal[0] = m.localNormal.x;
  out->local_normal[1] = m.localNormal.y;
  out->local_point[0] = m.localPoint.x;
  out->local_point[1] = m.localPoint.y;
  b2WorldManifold wm;
  wm.Initialize(&m, xfa, ra, xfb, rb);
  out->normal[0] = wm.normal.x;
  out->normal[1] = wm.normal.y;
  for (int i = 0; i < m.pointCount; ++i) {
    out->points[i][0] = wm.points[i].x;
    out->points[i][1] = wm.points[i].y;
    out->separations[i] = wm.separations[i];
    out->ids[i] = m.points[i].id.key;
  }
}

}  // namespace

extern "C" {

float b2c_polygon_radius(void) { return b2_polygonRadius; }

void b2c_collide_circles(float ax, float ay, float ar, b2c_transform xfa, float bx, float by, float br,
                         b2c_transform xfb, b2c_manifold* out) {
  b2CircleShape a, b;
  a.m_p.Set(ax, ay);
  a.m_radius = ar;
  b.m_p.Set(bx, by);
  b.m_radius = br;
  b2Transform ta = to_b2(xfa), tb = to_b2(xfb);
  b2Manifold m = {};  // Box2D sets the type only when it reports points
  b2CollideCircles(&m, &a, ta, &b, tb);
  report(m, ta, a.m_radius, tb, b.m_radius, out);
}

void b2c_collide_polygon_and_circle(const b2c_polygon* a, b2c_transform xfa, float bx, float by, float br,
                                    b2c_transform xfb, b2c_manifold* out) {
  b2PolygonShape pa;
  to_b2(a, &pa);
  b2CircleShape b;
  b.m_p.Set(bx, by);
  b.m_radius = br;
  b2Transform ta = to_b2(xfa), tb = to_b2(xfb);
  b2Manifold m = {};  // Box2D sets the type only when it reports points
  b2CollidePolygonAndCircle(&m, &pa, ta, &b, tb);
  report(m, ta, pa.m_radius, tb, b.m_radius, out);
}

void b2c_collide_polygons(const b2c_polygon* a, b2c_transform xfa, const b2c_polygon* b, b2c_transform xfb,
                          b2c_manifold* out) {
  b2PolygonShape pa, pb;
  to_b2(a, &pa);
  to_b2(b, &pb);
  b2Transform ta = to_b2(xfa), tb = to_b2(xfb);
  b2Manifold m = {};  // Box2D sets the type only when it reports points
  b2CollidePolygons(&m, &pa, ta, &pb, tb);
  report(m, ta, pa.m_radius, tb, pb.m_radius, out);
}

void b2c_collide_edge_and_circle(float x1, float y1, float x2, float y2, b2c_transform xfa, float bx, float by,
                                 float br, b2c_transform xfb, b2c_manifold* out) {
  b2EdgeShape a;
  a.SetTwoSided(b2Vec2(x1, y1), b2Vec2(x2, y2));
  b2CircleShape b;
  b.m_p.Set(bx, by);
  b.m_radius = br;
  b2Transform ta = to_b2(xfa), tb = to_b2(xfb);
  b2Manifold m = {};  // Box2D sets the type only when it reports points
  b2CollideEdgeAndCircle(&m, &a, ta, &b, tb);
  report(m, ta, a.m_radius, tb, b.m_radius, out);
}

void b2c_collide_edge_and_polygon(float x1, float y1, float x2, float y2, b2c_transform xfa, const b2c_polygon* b,
                                  b2c_transform xfb, b2c_manifold* out) {
  b2EdgeShape a;
  a.SetTwoSided(b2Vec2(x1, y1), b2Vec2(x2, y2));
  b2PolygonShape pb;
  to_b2(b, &pb);
  b2Transform ta = to_b2(xfa), tb = to_b2(xfb);
  b2Manifold m = {};  // Box2D sets the type only when it reports points
  b2CollideEdgeAndPolygon(&m, &a, ta, &pb, tb);
  report(m, ta, a.m_radius, tb, pb.m_radius, out);
}

}  // extern "C"
