// The dynamics benchmark of tools/bench_dynamics.c on Box2D 2.4.1: the same six
// performance scenes (demos/scenes/scenes.c), rebuilt with Box2D's API from the
// same parameters, stepped at 60 Hz with 8 velocity / 3 position iterations
// (Box2D's defaults) and with 4 / 2. Same options, output and CSV columns as the
// tumble side; see the comment there for what is measured and how.
//
// Differences that come from Box2D 2.4.1 itself, not from the scenes: polygons
// carry a 0.01 m skin (b2_polygonRadius), the shelves of many_pyramids are
// two-sided edges, and "contacts" counts b2Contact::IsTouching() (no speculative
// contacts in 2.4.1).
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <box2d/box2d.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

namespace {

const float PI_F = 3.14159265358979f;

int scaled(int full, float scale, int minimum) {
  if (!(scale > 0.0f && scale <= 1.0f)) scale = 1.0f;
  int n = static_cast<int>(std::lround(static_cast<float>(full) * scale));
  return n < minimum ? minimum : n;
}

// The pyramid's top box, when the scene has one (for the standing check).
b2Body* g_top = nullptr;

b2Body* body_at(b2World* world, b2BodyType type, float x, float y, float angle) {
  b2BodyDef bd;
  bd.type = type;
  bd.position.Set(x, y);
  bd.angle = angle;
  return world->CreateBody(&bd);
}

void add_shape(b2Body* body, const b2Shape* shape, float density, float friction = 0.6f) {
  b2FixtureDef fd;
  fd.shape = shape;
  fd.density = density;
  fd.friction = friction;
  body->CreateFixture(&fd);
}

void add_box(b2Body* body, float hx, float hy, float density, float friction = 0.6f) {
  b2PolygonShape box;
  box.SetAsBox(hx, hy);
  add_shape(body, &box, density, friction);
}

void add_offset_box(b2Body* body, float hx, float hy, float cx, float cy, float density) {
  b2PolygonShape box;
  box.SetAsBox(hx, hy, b2Vec2(cx, cy), 0.0f);
  add_shape(body, &box, density);
}

void add_circle(b2Body* body, float radius, float density) {
  b2CircleShape c;
  c.m_radius = radius;
  add_shape(body, &c, density);
}

void ground(b2World* world, float hx, float hy) {
  b2Body* g = body_at(world, b2_staticBody, 0.0f, 0.0f, 0.0f);
  add_offset_box(g, hx, hy, 0.0f, -hy, 1.0f);
}

void pyramid(b2World* world, int base, float h, float cx, float y0, bool tag_top) {
  b2PolygonShape box;
  box.SetAsBox(h, h);
  for (int i = 0; i < base; ++i) {
    float y = y0 + static_cast<float>(2 * i + 1) * h;
    for (int j = i; j < base; ++j) {
      float x = cx + static_cast<float>(2 * (j - i) + i + 1 - base) * h;
      b2Body* b = body_at(world, b2_dynamicBody, x, y, 0.0f);
      add_shape(b, &box, 1.0f);
      if (tag_top && i == base - 1) g_top = b;
    }
  }
}

float rain_rnd(uint32_t* state, float lo, float hi) {  // as in scenes.c
  uint32_t x = *state;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  *state = x;
  return lo + (hi - lo) * static_cast<float>(static_cast<double>(x) / 4294967296.0);
}

void build_large_pyramid(b2World* world, float scale) {
  world->SetGravity(b2Vec2(0.0f, -10.0f));
  ground(world, 100.0f, 1.0f);
  pyramid(world, scaled(100, scale, 1), 0.5f, 0.0f, 0.0f, true);
}

void build_many_pyramids(b2World* world, float scale) {
  world->SetGravity(b2Vec2(0.0f, -10.0f));
  const int base = 10;
  const float h = 0.5f;
  int rows = scaled(20, scale, 1), columns = scaled(20, scale, 1);
  float slot = 2.0f * h * static_cast<float>(base + 1);
  float width = slot * static_cast<float>(columns);
  b2Body* g = body_at(world, b2_staticBody, 0.0f, 0.0f, 0.0f);
  for (int r = 0; r < rows; ++r) {
    float y = slot * static_cast<float>(r);
    b2EdgeShape e;
    e.SetTwoSided(b2Vec2(-0.5f * width, y), b2Vec2(0.5f * width, y));
    add_shape(g, &e, 1.0f);
  }
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      float cx = -0.5f * width + (static_cast<float>(c) + 0.5f) * slot;
      pyramid(world, base, h, cx, slot * static_cast<float>(r), false);
    }
  }
}

void build_joint_grid(b2World* world, float scale) {
  world->SetGravity(b2Vec2(0.0f, -10.0f));
  int n = scaled(100, scale, 2);
  std::vector<b2Body*> bodies(static_cast<size_t>(n) * static_cast<size_t>(n));
  b2CircleShape circle;
  circle.m_radius = 0.4f;
  b2FixtureDef fd;
  fd.shape = &circle;
  fd.density = 1.0f;
  fd.friction = 0.6f;
  fd.filter.categoryBits = 0x0002;
  fd.filter.maskBits = 0xFFFF ^ 0x0002;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      bool anchor = j == 0 && i >= n / 2 - 3 && i <= n / 2 + 3;
      float x = static_cast<float>(i) - 0.5f * static_cast<float>(n - 1), y = -static_cast<float>(j);
      b2Body* b = body_at(world, anchor ? b2_staticBody : b2_dynamicBody, x, y, 0.0f);
      b->CreateFixture(&fd);
      bodies[static_cast<size_t>(i * n + j)] = b;
      b2RevoluteJointDef jd;
      if (i > 0) {
        jd.bodyA = bodies[static_cast<size_t>((i - 1) * n + j)];
        jd.bodyB = b;
        jd.localAnchorA.Set(0.5f, 0.0f);
        jd.localAnchorB.Set(-0.5f, 0.0f);
        world->CreateJoint(&jd);
      }
      if (j > 0) {
        jd.bodyA = bodies[static_cast<size_t>(i * n + j - 1)];
        jd.bodyB = b;
        jd.localAnchorA.Set(0.0f, -0.5f);
        jd.localAnchorB.Set(0.0f, 0.5f);
        world->CreateJoint(&jd);
      }
    }
  }
}

void build_rain(b2World* world, float scale) {
  world->SetGravity(b2Vec2(0.0f, -10.0f));
  b2Body* g = body_at(world, b2_staticBody, 0.0f, 0.0f, 0.0f);
  add_offset_box(g, 21.0f, 1.0f, 0.0f, -1.0f, 1.0f);
  add_offset_box(g, 1.0f, 25.0f, -21.0f, 25.0f, 1.0f);
  add_offset_box(g, 1.0f, 25.0f, 21.0f, 25.0f, 1.0f);

  if (!(scale > 0.0f && scale <= 1.0f)) scale = 1.0f;
  int count = static_cast<int>(std::lround(2000.0f * scale * scale));
  if (count < 1) count = 1;
  const int columns = 25;
  const float cell_w = 38.0f / static_cast<float>(columns), cell_h = 1.125f;
  uint32_t rng = 20240601u;
  for (int k = 0; k < count; ++k) {
    int c = k % columns, r = k / columns;
    bool circle = rain_rnd(&rng, 0.0f, 1.0f) < 0.5f;
    float s = rain_rnd(&rng, 0.15f, 0.35f);
    float angle = rain_rnd(&rng, -PI_F, PI_F);
    float jx = rain_rnd(&rng, -1.0f, 1.0f), jy = rain_rnd(&rng, -1.0f, 1.0f);
    float extent = circle ? s : 1.41421356f * s;
    float x = -19.0f + (static_cast<float>(c) + 0.5f) * cell_w + jx * (0.5f * cell_w - extent);
    float y = 10.0f + (static_cast<float>(r) + 0.5f) * cell_h + jy * (0.5f * cell_h - extent);
    b2Body* b = body_at(world, b2_dynamicBody, x, y, circle ? 0.0f : angle);
    if (circle) {
      add_circle(b, s, 1.0f);
    } else {
      add_box(b, s, s, 1.0f);
    }
  }
}

void build_smash(b2World* world, float scale) {
  world->SetGravity(b2Vec2(0.0f, 0.0f));
  b2BodyDef bd;
  bd.type = b2_dynamicBody;
  bd.position.Set(-20.0f, 0.0f);
  bd.linearVelocity.Set(40.0f, 0.0f);
  b2Body* p = world->CreateBody(&bd);
  add_box(p, 4.0f, 4.0f, 8.0f);

  int columns = scaled(120, scale, 1), rows = scaled(80, scale, 1);
  const float d = 0.4f;
  b2PolygonShape box;
  box.SetAsBox(0.5f * d, 0.5f * d);
  b2BodyDef gd;
  gd.type = b2_dynamicBody;
  gd.awake = false;
  for (int i = 0; i < columns; ++i) {
    for (int j = 0; j < rows; ++j) {
      gd.position.Set(30.0f + static_cast<float>(i) * d, (static_cast<float>(j) - 0.5f * static_cast<float>(rows)) * d);
      b2Body* b = world->CreateBody(&gd);
      add_shape(b, &box, 1.0f);
    }
  }
}

void build_tumbler(b2World* world, float scale) {
  world->SetGravity(b2Vec2(0.0f, -10.0f));
  b2BodyDef bd;
  bd.type = b2_kinematicBody;
  bd.position.Set(0.0f, 10.0f);
  bd.angularVelocity = 25.0f * PI_F / 180.0f;
  b2Body* c = world->CreateBody(&bd);
  add_offset_box(c, 0.5f, 10.0f, 10.0f, 0.0f, 50.0f);
  add_offset_box(c, 0.5f, 10.0f, -10.0f, 0.0f, 50.0f);
  add_offset_box(c, 10.0f, 0.5f, 0.0f, 10.0f, 50.0f);
  add_offset_box(c, 10.0f, 0.5f, 0.0f, -10.0f, 50.0f);

  const int full = 45;
  int n = scaled(full, scale, 1);
  b2PolygonShape box;
  box.SetAsBox(0.125f, 0.125f);
  float y = -0.2f * static_cast<float>(full) + 10.0f;
  for (int i = 0; i < n; ++i) {
    float x = -0.2f * static_cast<float>(full);
    for (int j = 0; j < n; ++j) {
      b2Body* b = body_at(world, b2_dynamicBody, x, y, 0.0f);
      add_shape(b, &box, 1.0f);
      x += 0.4f;
    }
    y += 0.4f;
  }
}

struct Scene {
  const char* name;
  void (*build)(b2World*, float);
  int default_steps;
  b2AABB bounds;  // as in scenes.c
};

b2AABB box_of(float x0, float y0, float x1, float y1) {
  b2AABB a;
  a.lowerBound.Set(x0, y0);
  a.upperBound.Set(x1, y1);
  return a;
}

const Scene k_scenes[] = {
    {"large_pyramid", build_large_pyramid, 500, box_of(-105.0f, -5.0f, 105.0f, 105.0f)},
    {"many_pyramids", build_many_pyramids, 200, box_of(-115.0f, -5.0f, 115.0f, 225.0f)},
    {"joint_grid", build_joint_grid, 500, box_of(-160.0f, -160.0f, 160.0f, 10.0f)},
    {"rain_2000", build_rain, 1000, box_of(-25.0f, -5.0f, 25.0f, 110.0f)},
    {"smash", build_smash, 300, box_of(-100.0f, -300.0f, 400.0f, 300.0f)},
    {"tumbler_kinematic", build_tumbler, 750, box_of(-16.0f, -6.0f, 16.0f, 26.0f)},
};
const int SCENE_COUNT = static_cast<int>(sizeof k_scenes / sizeof k_scenes[0]);

// ------------------------------------------------------------- measuring --

double now_ms() {
  timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

long max_rss_kb() {
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

uint64_t fnv_float(uint64_t h, float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  for (int k = 0; k < 4; ++k) {
    h ^= (bits >> (8 * k)) & 0xffu;
    h *= 1099511628211ull;
  }
  return h;
}

std::vector<b2Body*> bodies_in_creation_order(b2World* world) {
  std::vector<b2Body*> list;
  for (b2Body* b = world->GetBodyList(); b != nullptr; b = b->GetNext()) list.push_back(b);
  std::reverse(list.begin(), list.end());  // Box2D lists the newest first
  return list;
}

uint64_t state_hash(b2World* world) {
  uint64_t h = 14695981039346656037ull;
  for (b2Body* b : bodies_in_creation_order(world)) {
    b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
    h = fnv_float(h, p.x);
    h = fnv_float(h, p.y);
    h = fnv_float(h, b->GetAngle());
    h = fnv_float(h, v.x);
    h = fnv_float(h, v.y);
    h = fnv_float(h, b->GetAngularVelocity());
  }
  return h;
}

struct Options {
  const char* scene = nullptr;
  int runs = 3;
  int steps = 0;  // 0: the scene's default
  float scale = 1.0f;
  bool quick = false;
  bool no_sleep = false;
  const char* csv = nullptr;
  int iterations = 0;  // 0: both 8/3 and 4/2; 8 or 4: only that one
};

struct RunResult {
  double ms_mean, ms_worst;
  uint64_t hash;
};

struct SceneResult {
  int bodies = 0, awake = 0, contacts = 0, joints = 0, outside = 0;
  double mass = 0.0;
  float top_dx = 0.0f, top_dy = 0.0f;
  bool has_top = false;
};

RunResult run_once(const Scene& s, const Options& o, int steps, int vel, int pos, SceneResult* out) {
  b2World world(b2Vec2(0.0f, -10.0f));
  g_top = nullptr;
  s.build(&world, o.scale);
  if (o.no_sleep) world.SetAllowSleeping(false);  // also wakes every body
  b2Vec2 top0 = g_top != nullptr ? g_top->GetPosition() : b2Vec2(0.0f, 0.0f);
  const float dt = 1.0f / 60.0f;
  double total = 0.0, worst = 0.0;
  for (int k = 0; k < steps; ++k) {
    double t0 = now_ms();
    world.Step(dt, vel, pos);
    double t1 = now_ms();
    total += t1 - t0;
    worst = std::max(worst, t1 - t0);
  }
  if (out != nullptr) {
    *out = SceneResult();
    out->bodies = world.GetBodyCount();
    out->joints = world.GetJointCount();
    for (b2Contact* c = world.GetContactList(); c != nullptr; c = c->GetNext()) out->contacts += c->IsTouching();
    for (b2Body* b = world.GetBodyList(); b != nullptr; b = b->GetNext()) {
      if (b->GetType() == b2_staticBody) continue;
      out->awake += b->IsAwake();
      out->mass += b->GetMass();
      b2Vec2 p = b->GetPosition();
      out->outside += !(p.x >= s.bounds.lowerBound.x && p.x <= s.bounds.upperBound.x && p.y >= s.bounds.lowerBound.y &&
                        p.y <= s.bounds.upperBound.y);
    }
    if (g_top != nullptr) {
      out->has_top = true;
      out->top_dx = g_top->GetPosition().x - top0.x;
      out->top_dy = g_top->GetPosition().y - top0.y;
    }
  }
  return RunResult{steps > 0 ? total / steps : 0.0, worst, state_hash(&world)};
}

// Runs one scene at one iteration setting in this process and prints one row.
void bench_scene(const Scene& s, const Options& o, int vel, int pos) {
  int steps = o.steps > 0 ? o.steps : s.default_steps;
  long rss0 = max_rss_kb();
  run_once(s, o, std::min(steps, 60), vel, pos, nullptr);  // warm-up
  std::vector<double> ms;
  double worst = 0.0;
  uint64_t hash = 0;
  bool deterministic = true;
  SceneResult r;
  for (int k = 0; k < o.runs; ++k) {
    RunResult rr = run_once(s, o, steps, vel, pos, &r);
    ms.push_back(rr.ms_mean);
    worst = std::max(worst, rr.ms_worst);
    if (k > 0 && rr.hash != hash) deterministic = false;
    hash = rr.hash;
  }
  std::sort(ms.begin(), ms.end());
  long rss1 = max_rss_kb();
  char engine[32];
  std::snprintf(engine, sizeof engine, "box2d-%d/%d%s", vel, pos, o.no_sleep ? "-ns" : "");
  std::printf("%-12s %-14s %5.2f %6d %6d %7d %6d %5d %4d %8.3f %8.3f %8.3f %8.1f %8.1f %016llx %4d %10.0f%s\n", engine,
              s.name, static_cast<double>(o.scale), r.bodies, r.awake, r.contacts, r.joints, steps, o.runs,
              ms[ms.size() / 2], ms[0], worst, static_cast<double>(rss1) / 1024.0,
              static_cast<double>(rss1 - rss0) / 1024.0, static_cast<unsigned long long>(hash), r.outside, r.mass,
              deterministic ? "" : "  NOT DETERMINISTIC");
  if (r.has_top) {
    bool standing = std::fabs(r.top_dx) < 2.0f && r.top_dy > -2.0f;
    std::printf("%-12s %-14s top box: dx %+.3f m, dy %+.3f m -> %s\n", engine, s.name, static_cast<double>(r.top_dx),
                static_cast<double>(r.top_dy), standing ? "standing" : "FALLEN");
  }
  std::fflush(stdout);
  if (o.csv != nullptr) {
    FILE* f = std::fopen(o.csv, "a");
    if (f == nullptr) {
      std::perror(o.csv);
      return;
    }
    std::fseek(f, 0, SEEK_END);
    if (std::ftell(f) == 0) {
      std::fprintf(f,
                   "time,engine,scene,scale,steps,runs,bodies,awake,contacts,joints,ms_median,ms_min,ms_worst_step,"
                   "peak_rss_kb,delta_rss_kb,hash,outside,mass,top_dx,top_dy,deterministic\n");
    }
    std::fprintf(f, "%lld,%s,%s,%.3f,%d,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,%ld,%ld,%016llx,%d,%.1f,%s,%s,%d\n",
                 static_cast<long long>(std::time(nullptr)), engine, s.name, static_cast<double>(o.scale), steps,
                 o.runs, r.bodies, r.awake, r.contacts, r.joints, ms[ms.size() / 2], ms[0], worst, rss1, rss1 - rss0,
                 static_cast<unsigned long long>(hash), r.outside, r.mass,
                 r.has_top ? std::to_string(r.top_dx).c_str() : "", r.has_top ? std::to_string(r.top_dy).c_str() : "",
                 deterministic ? 1 : 0);
    std::fclose(f);
  }
}

void usage(const char* argv0) {
  std::fprintf(stderr,
               "usage: %s [--scene NAME] [--runs N] [--steps N] [--scale S] [--quick] [--no-sleep] [--csv FILE] "
               "[--iterations 8|4]\n",
               argv0);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  bool runs_set = false, scale_set = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    bool has_value = i + 1 < argc;
    if (a == "--scene" && has_value) {
      o.scene = argv[++i];
    } else if (a == "--runs" && has_value) {
      o.runs = std::atoi(argv[++i]);
      runs_set = true;
    } else if (a == "--steps" && has_value) {
      o.steps = std::atoi(argv[++i]);
    } else if (a == "--scale" && has_value) {
      o.scale = static_cast<float>(std::atof(argv[++i]));
      scale_set = true;
    } else if (a == "--csv" && has_value) {
      o.csv = argv[++i];
    } else if (a == "--iterations" && has_value) {
      o.iterations = std::atoi(argv[++i]);
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--no-sleep") {
      o.no_sleep = true;
    } else {
      usage(argv[0]);
      return 2;
    }
  }
  if (o.quick) {
    if (!runs_set) o.runs = 1;
    if (!scale_set) o.scale = 0.5f;
  }
  if (o.runs < 1 || !(o.scale > 0.0f && o.scale <= 1.0f) || o.steps < 0 ||
      (o.iterations != 0 && o.iterations != 8 && o.iterations != 4)) {
    usage(argv[0]);
    return 2;
  }
  bool found = o.scene == nullptr;
  for (int k = 0; k < SCENE_COUNT; ++k) found = found || std::strcmp(k_scenes[k].name, o.scene) == 0;
  if (!found) {
    std::fprintf(stderr, "unknown scene '%s' (scenes:", o.scene);
    for (int k = 0; k < SCENE_COUNT; ++k) std::fprintf(stderr, " %s", k_scenes[k].name);
    std::fprintf(stderr, ")\n");
    return 2;
  }

  // Debian's libbox2d 2.4.1 still reports b2_version 2.4.0.
  std::printf(
      "Box2D 2.4.1 (b2_version %d.%d.%d) dynamics bench: 60 Hz, single thread, %d run(s) after a warm-up, "
      "scale %.2f\n",
      b2_version.major, b2_version.minor, b2_version.revision, o.runs, static_cast<double>(o.scale));
  std::printf("%-12s %-14s %5s %6s %6s %7s %6s %5s %4s %8s %8s %8s %8s %8s %-16s %4s %10s\n", "engine", "scene",
              "scale", "bodies", "awake", "contact", "joints", "steps", "runs", "med ms", "min ms", "worst", "peak MB",
              "+MB", "state hash", "out", "mass kg");
  std::fflush(stdout);
  const int settings[2][2] = {{8, 3}, {4, 2}};
  int failures = 0;
  for (int k = 0; k < SCENE_COUNT; ++k) {
    if (o.scene != nullptr && std::strcmp(k_scenes[k].name, o.scene) != 0) continue;
    for (const auto& it : settings) {
      if (o.iterations != 0 && o.iterations != it[0]) continue;
      // Each scene in its own process, so that ru_maxrss is that scene's peak.
      pid_t pid = fork();
      if (pid == 0) {
        bench_scene(k_scenes[k], o, it[0], it[1]);
        std::fflush(stdout);
        _exit(0);
      }
      int status = 0;
      if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "%s (%d/%d) failed\n", k_scenes[k].name, it[0], it[1]);
        failures += 1;
      }
    }
  }
  return failures == 0 ? 0 : 1;
}
