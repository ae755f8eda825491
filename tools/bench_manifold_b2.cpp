// Box2D 2.4.1 half of the manifold benchmark (see tools/bench_manifold.c for the
// build command). Shapes are converted to Box2D's types before the clock starts,
// so only b2Collide* (and, when asked, b2WorldManifold::Initialize) is timed.
#include <box2d/box2d.h>

#include <chrono>
#include <vector>

#include "../tests/reference/b2_collide_shim.h"

namespace {

b2Transform to_b2(const b2c_transform& xf) {
  b2Transform t;
  t.p.Set(xf.x, xf.y);
  t.q.c = xf.c;
  t.q.s = xf.s;
  return t;
}

b2PolygonShape to_b2(const b2c_polygon& p) {
  b2PolygonShape s;
  s.m_count = p.count;
  for (int i = 0; i < p.count; ++i) {
    s.m_vertices[i].Set(p.vertices[i][0], p.vertices[i][1]);
    s.m_normals[i].Set(p.normals[i][0], p.normals[i][1]);
  }
  s.m_centroid.Set(p.centroid[0], p.centroid[1]);
  return s;
}

b2CircleShape circle(const float* c) {
  b2CircleShape s;
  s.m_p.Set(c[0], c[1]);
  s.m_radius = c[2];
  return s;
}

b2EdgeShape edge(const float* e) {
  b2EdgeShape s;
  s.SetTwoSided(b2Vec2(e[0], e[1]), b2Vec2(e[2], e[3]));
  return s;
}

// Times `repeat` sweeps of collide(i) over n configurations; ns per call.
template <class Collide>
double run(int n, int repeat, bool with_world, const std::vector<b2Transform>& xa, const std::vector<b2Transform>& xb,
           const std::vector<float>& ra, const std::vector<float>& rb, double* checksum, Collide collide) {
  double sum = 0.0;
  auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeat; ++r) {
    for (int i = 0; i < n; ++i) {
      b2Manifold m;
      collide(i, &m);
      sum += m.pointCount;
      if (with_world && m.pointCount > 0) {
        b2WorldManifold wm;
        wm.Initialize(&m, xa[i], ra[i], xb[i], rb[i]);
        sum += wm.separations[0] + wm.points[0].x;
      }
    }
  }
  auto stop = std::chrono::steady_clock::now();
  *checksum += sum;
  return std::chrono::duration<double, std::nano>(stop - start).count() / (double(n) * repeat);
}

}  // namespace

// pair: 0 circles, 1 polygon-circle, 2 polygons, 3 edge-circle, 4 edge-polygon.
// a and b: arrays of n shapes: circles as (x, y, r) triplets, polygons as
// b2c_polygon, edges as (x1, y1, x2, y2). Returns ns per manifold.
extern "C" double b2bench_run(int pair, const void* a, const void* b, const b2c_transform* xfa,
                              const b2c_transform* xfb, int n, int repeat, int with_world, double* checksum) {
  std::vector<b2Transform> xa(n), xb(n);
  std::vector<float> ra(n), rb(n);
  for (int i = 0; i < n; ++i) xa[i] = to_b2(xfa[i]), xb[i] = to_b2(xfb[i]);
  const float* fa = static_cast<const float*>(a);
  const float* fb = static_cast<const float*>(b);
  const b2c_polygon* pa = static_cast<const b2c_polygon*>(a);
  const b2c_polygon* pb = static_cast<const b2c_polygon*>(b);
  std::vector<b2CircleShape> ca, cb;
  std::vector<b2PolygonShape> qa, qb;
  std::vector<b2EdgeShape> ea;
  for (int i = 0; i < n; ++i) {
    switch (pair) {
      case 0: ca.push_back(circle(fa + 3 * i)), cb.push_back(circle(fb + 3 * i)); break;
      case 1: qa.push_back(to_b2(pa[i])), cb.push_back(circle(fb + 3 * i)); break;
      case 2: qa.push_back(to_b2(pa[i])), qb.push_back(to_b2(pb[i])); break;
      case 3: ea.push_back(edge(fa + 4 * i)), cb.push_back(circle(fb + 3 * i)); break;
      default: ea.push_back(edge(fa + 4 * i)), qb.push_back(to_b2(pb[i])); break;
    }
    ra[i] = pair == 0 ? ca[i].m_radius : b2_polygonRadius;
    rb[i] = pair == 2 || pair == 4 ? b2_polygonRadius : cb[i].m_radius;
  }
  bool w = with_world != 0;
  switch (pair) {
    case 0:
      return run(n, repeat, w, xa, xb, ra, rb, checksum,
                 [&](int i, b2Manifold* m) { b2CollideCircles(m, &ca[i], xa[i], &cb[i], xb[i]); });
    case 1:
      return run(n, repeat, w, xa, xb, ra, rb, checksum,
                 [&](int i, b2Manifold* m) { b2CollidePolygonAndCircle(m, &qa[i], xa[i], &cb[i], xb[i]); });
    case 2:
      return run(n, repeat, w, xa, xb, ra, rb, checksum,
                 [&](int i, b2Manifold* m) { b2CollidePolygons(m, &qa[i], xa[i], &qb[i], xb[i]); });
    case 3:
      return run(n, repeat, w, xa, xb, ra, rb, checksum,
                 [&](int i, b2Manifold* m) { b2CollideEdgeAndCircle(m, &ea[i], xa[i], &cb[i], xb[i]); });
    default:
      return run(n, repeat, w, xa, xb, ra, rb, checksum,
                 [&](int i, b2Manifold* m) { b2CollideEdgeAndPolygon(m, &ea[i], xa[i], &qb[i], xb[i]); });
  }
}
