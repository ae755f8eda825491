// The workload of tools/bench_tree.c ("predictive" scenario) on Box2D 2.4.1's
// b2DynamicTree, so the two trees are timed on the same machine in the same
// `make bench` run: 10,000 boxes in a random walk, move every proxy each step
// (Box2D enlarges by 0.1 m and 4x the displacement, as tumble's predictive
// scenario does), then query the fat box of each re-inserted proxy for pairs.
#include <box2d/box2d.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

const int N = 10000;
const float AREA = 200.0f, MAX_SPEED = 3.0f, DT = 1.0f / 60.0f;
const int WARMUP = 60, STEPS = 200, RUNS = 7;

unsigned rng_state;
float rnd(float lo, float hi) {  // the same xorshift as bench_tree.c
  unsigned x = rng_state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  rng_state = x;
  return lo + (hi - lo) * static_cast<float>(static_cast<double>(x) / 4294967296.0);
}

struct Body {
  b2Vec2 p, v;
  float size;
  int proxy;
};

Body bodies[N];
unsigned char moved[N];
int move_buffer[N];

b2AABB box(const Body& b) {
  b2AABB a;
  a.lowerBound = b.p;
  a.upperBound = b2Vec2(b.p.x + b.size, b.p.y + b.size);
  return a;
}

struct PairQuery {
  const b2DynamicTree* tree;
  int self;
  long pairs;
  bool QueryCallback(int proxy) {
    int other = static_cast<int>(reinterpret_cast<intptr_t>(tree->GetUserData(proxy)));
    if (other == self || (moved[other] && other < self)) return true;
    pairs += 1;
    return true;
  }
};

int step(b2DynamicTree& tree, long* pairs) {
  int count = 0;
  for (int i = 0; i < N; ++i) {
    Body& b = bodies[i];
    b.v.x += rnd(-0.5f, 0.5f);
    b.v.y += rnd(-0.5f, 0.5f);
    b.v.x = std::min(std::max(b.v.x, -MAX_SPEED), MAX_SPEED);
    b.v.y = std::min(std::max(b.v.y, -MAX_SPEED), MAX_SPEED);
    b.p.x += DT * b.v.x;
    b.p.y += DT * b.v.y;
    if (b.p.x < 0.0f || b.p.x > AREA) b.v.x = -b.v.x;
    if (b.p.y < 0.0f || b.p.y > AREA) b.v.y = -b.v.y;
    if (tree.MoveProxy(b.proxy, box(b), b2Vec2(DT * b.v.x, DT * b.v.y))) {
      moved[i] = 1;
      move_buffer[count++] = i;
    }
  }
  for (int k = 0; k < count; ++k) {
    PairQuery q{&tree, move_buffer[k], 0};
    tree.Query(&q, tree.GetFatAABB(bodies[move_buffer[k]].proxy));
    *pairs += q.pairs;
  }
  for (int k = 0; k < count; ++k) moved[move_buffer[k]] = 0;
  return count;
}

double run(int* height) {
  b2DynamicTree tree;
  rng_state = 12345u;
  for (int i = 0; i < N; ++i) {
    Body& b = bodies[i];
    b.p = b2Vec2(rnd(0.0f, AREA), rnd(0.0f, AREA));
    b.v = b2Vec2(rnd(-2.0f, 2.0f), rnd(-2.0f, 2.0f));
    b.size = rnd(0.2f, 1.0f);
    b.proxy = tree.CreateProxy(box(b), reinterpret_cast<void*>(static_cast<intptr_t>(i)));
  }
  std::fill(moved, moved + N, 0);
  long pairs = 0;
  for (int s = 0; s < WARMUP; ++s) step(tree, &pairs);
  auto t0 = std::chrono::steady_clock::now();
  for (int s = 0; s < STEPS; ++s) step(tree, &pairs);
  auto t1 = std::chrono::steady_clock::now();
  *height = tree.GetHeight();
  return std::chrono::duration<double, std::milli>(t1 - t0).count() / STEPS;
}

}  // namespace

int main() {
  std::vector<double> ms;
  int height = 0;
  for (int k = 0; k < RUNS; ++k) ms.push_back(run(&height));
  std::sort(ms.begin(), ms.end());
  std::printf("box2d 2.4.1 predictive %.3f ms/step median (min %.3f, max %.3f) | height %d\n", ms[RUNS / 2], ms[0],
              ms[RUNS - 1], height);
  return 0;
}
