/* Dynamics benchmark: the six performance scenes of the catalogue
 * (demos/scenes/scenes.c: large_pyramid, many_pyramids, joint_grid, rain,
 * smash, tumbler) stepped by tumble at 60 Hz with 4 substeps, single-threaded.
 * tools/bench_dynamics_b2.cpp runs the same scenes on Box2D 2.4.1 at 8/3 and
 * 4/2 velocity/position iterations and prints the same columns.
 *
 *   make bench-quick        both engines, --quick (about a minute)
 *   build/bench/bench_dynamics [--scene NAME] [--runs N] [--steps N]
 *       [--scale S] [--quick] [--no-sleep] [--csv FILE]
 *
 * Per scene, in its own forked process (so that ru_maxrss is that scene's):
 * one warm-up run (a fresh world, min(steps, 60) steps, not timed), then
 * --runs timed runs (default 3), each on a fresh world built from scratch for
 * the scene's default steps (or --steps). Only tb_world_step is timed, each
 * step on its own with clock_gettime(CLOCK_MONOTONIC). A run's figure is its
 * mean ms per step; the row gives the median and the minimum over the runs and
 * the worst single step of all runs; tumble's per-stage profile
 * (tb_world_get_profile) averaged over the last run's steps is printed and,
 * with --profile-csv, appended to that file. After the last run: bodies (static ones
 * included), awake bodies, touching contacts (manifolds with points,
 * speculative ones included), joints, peak RSS of the process and its growth
 * since before the first world ("+MB"), an FNV-1a hash of every body's
 * position, angle and velocities (tb_scene_state_hash; equal across runs or the
 * row says NOT DETERMINISTIC), the number of non-static bodies that left the
 * scene's bounds and the total dynamic mass (the same in both engines when the
 * scenes match). For large_pyramid also the drift of the top box: standing
 * when it moved less than 2 m sideways and sank less than 2 m.
 *
 * --quick: 1 run and scale 0.5 (a quarter of the bodies) unless --runs or
 * --scale say otherwise. --no-sleep turns sleeping off after the build (bodies
 * created asleep wake up; the engine column gets "-ns"), to time the solver on
 * every body rather than how soon a scene falls asleep. --csv appends one row per scene (header when the
 * file is empty). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../demos/scenes/scenes.h"

#define SUBSTEPS 4
#define WARMUP_STEPS 60

typedef struct options {
  const char* scene;
  int runs, steps;
  float scale;
  bool quick, no_sleep;
  const char* csv;
  const char* profile_csv;
} options;

typedef struct run_result {
  double ms_mean, ms_worst;
  uint64_t hash;
} run_result;

/* tb_world_get_profile summed over the timed steps of a run. */
typedef struct profile_sum {
  double step, broad_phase, narrow_phase, solver, continuous, islands;
  double awake_bodies, awake_contacts, awake_joints, pairs, new_pairs, swept;
  int steps;
} profile_sum;

static void profile_add(profile_sum* p, tb_profile q) {
  p->step += q.step, p->broad_phase += q.broad_phase, p->narrow_phase += q.narrow_phase;
  p->solver += q.solver, p->continuous += q.continuous, p->islands += q.islands;
  p->awake_bodies += q.awake_body_count, p->awake_contacts += q.awake_contact_count;
  p->awake_joints += q.awake_joint_count, p->pairs += q.pair_count, p->new_pairs += q.new_pair_count;
  p->swept += q.continuous_count;
  p->steps += 1;
}

typedef struct scene_result {
  profile_sum profile;
  tb_counts counts;
  int outside;
  double mass;
  bool has_top;
  float top_dx, top_dy;
} scene_result;

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static long max_rss_kb(void) {
  struct rusage u;
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

static int compare_double(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static double dynamic_mass(tb_world_id world) {
  int n = tb_scene_collect_bodies(world, NULL, 0);
  tb_body_id* bodies = malloc(sizeof *bodies * (size_t)(n > 0 ? n : 1));
  if (bodies == NULL) return 0.0;
  n = tb_scene_collect_bodies(world, bodies, n);
  double mass = 0.0;
  for (int i = 0; i < n; ++i) mass += (double)tb_body_get_mass(bodies[i]);
  free(bodies);
  return mass;
}

static run_result run_once(const tb_scene* s, const options* o, int steps, scene_result* out) {
  tb_world_def wd = tb_default_world_def();
  wd.enable_profile = true; /* the stage times are reported */
  tb_world_id world = tb_create_world(&wd);
  if (tb_world_id_is_null(world)) {
    fprintf(stderr, "tb_create_world: %s\n", tb_last_error());
    exit(1);
  }
  s->build(world, o->scale);
  if (o->no_sleep) tb_world_enable_sleeping(world, false);
  tb_body_id top = tb_scene_find_body(world, "top");
  tb_vec2 top0 = tb_body_id_is_null(top) ? (tb_vec2){0.0f, 0.0f} : tb_body_get_position(top);
  double total = 0.0, worst = 0.0;
  profile_sum profile = {0};
  for (int k = 0; k < steps; ++k) {
    if (s->update != NULL) s->update(world, k);
    double t0 = now_ms();
    tb_result r = tb_world_step(world, 1.0f / 60.0f, SUBSTEPS);
    double t1 = now_ms();
    if (r != TB_OK) {
      fprintf(stderr, "%s: step %d: %s (%s)\n", s->name, k, tb_result_name(r), tb_world_last_error(world));
      exit(1);
    }
    total += t1 - t0;
    if (t1 - t0 > worst) worst = t1 - t0;
    profile_add(&profile, tb_world_get_profile(world));
  }
  if (out != NULL) {
    memset(out, 0, sizeof *out);
    out->profile = profile;
    out->counts = tb_world_get_counts(world);
    out->outside = tb_scene_count_outside(world, s->bounds);
    out->mass = dynamic_mass(world);
    if (!tb_body_id_is_null(top)) {
      tb_vec2 p = tb_body_get_position(top);
      out->has_top = true;
      out->top_dx = p.x - top0.x;
      out->top_dy = p.y - top0.y;
    }
  }
  run_result rr = {steps > 0 ? total / steps : 0.0, worst, tb_scene_state_hash(world)};
  tb_destroy_world(world);
  return rr;
}

/* Runs one scene in this process and prints one row. */
static void bench_scene(const tb_scene* s, const options* o) {
  int steps = o->steps > 0 ? o->steps : s->default_steps;
  long rss0 = max_rss_kb();
  run_once(s, o, steps < WARMUP_STEPS ? steps : WARMUP_STEPS, NULL);
  double* ms = malloc(sizeof *ms * (size_t)o->runs);
  if (ms == NULL) exit(1);
  double worst = 0.0;
  uint64_t hash = 0;
  bool deterministic = true;
  scene_result r = {0};
  for (int k = 0; k < o->runs; ++k) {
    run_result rr = run_once(s, o, steps, &r);
    ms[k] = rr.ms_mean;
    if (rr.ms_worst > worst) worst = rr.ms_worst;
    if (k > 0 && rr.hash != hash) deterministic = false;
    hash = rr.hash;
  }
  qsort(ms, (size_t)o->runs, sizeof ms[0], compare_double);
  long rss1 = max_rss_kb();
  const char* engine = o->no_sleep ? "tumble-4-ns" : "tumble-4";
  printf("%-12s %-14s %5.2f %6d %6d %7d %6d %5d %4d %8.3f %8.3f %8.3f %8.1f %8.1f %016llx %4d %10.0f%s\n", engine,
         s->name, (double)o->scale, r.counts.body_count, r.counts.awake_body_count, r.counts.touching_count,
         r.counts.joint_count, steps, o->runs, ms[o->runs / 2], ms[0], worst, (double)rss1 / 1024.0,
         (double)(rss1 - rss0) / 1024.0, (unsigned long long)hash, r.outside, r.mass,
         deterministic ? "" : "  NOT DETERMINISTIC");
  bool standing = fabsf(r.top_dx) < 2.0f && r.top_dy > -2.0f;
  if (r.has_top) {
    printf("%-12s %-14s top box: dx %+.3f m, dy %+.3f m -> %s\n", engine, s->name, (double)r.top_dx, (double)r.top_dy,
           standing ? "standing" : "FALLEN");
  }
  if (r.profile.steps > 0) {
    const profile_sum* p = &r.profile;
    double n = p->steps;
    printf(
        "%-12s %-14s profile ms/step: step %.3f = broad %.3f + narrow %.3f + solver %.3f + continuous %.3f + "
        "islands %.3f; mean awake bodies %.0f, contacts %.0f, joints %.0f, pairs %.0f, new pairs %.1f, swept %.1f\n",
        engine, s->name, p->step / n, p->broad_phase / n, p->narrow_phase / n, p->solver / n, p->continuous / n,
        p->islands / n, p->awake_bodies / n, p->awake_contacts / n, p->awake_joints / n, p->pairs / n, p->new_pairs / n,
        p->swept / n);
    if (o->profile_csv != NULL) {
      FILE* f = fopen(o->profile_csv, "a");
      if (f == NULL) {
        perror(o->profile_csv);
      } else {
        fseek(f, 0, SEEK_END);
        if (ftell(f) == 0) {
          fprintf(f,
                  "engine,scene,scale,steps,step,broad_phase,narrow_phase,solver,continuous,islands,awake_bodies,"
                  "awake_contacts,awake_joints,pairs,new_pairs,swept\n");
        }
        fprintf(f, "%s,%s,%.3f,%d,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.1f,%.1f,%.1f,%.1f,%.2f,%.2f\n", engine, s->name,
                (double)o->scale, p->steps, p->step / n, p->broad_phase / n, p->narrow_phase / n, p->solver / n,
                p->continuous / n, p->islands / n, p->awake_bodies / n, p->awake_contacts / n, p->awake_joints / n,
                p->pairs / n, p->new_pairs / n, p->swept / n);
        fclose(f);
      }
    }
  }
  fflush(stdout);
  if (o->csv != NULL) {
    FILE* f = fopen(o->csv, "a");
    if (f == NULL) {
      perror(o->csv);
    } else {
      fseek(f, 0, SEEK_END);
      if (ftell(f) == 0) {
        fprintf(f,
                "time,engine,scene,scale,steps,runs,bodies,awake,contacts,joints,ms_median,ms_min,ms_worst_step,"
                "peak_rss_kb,delta_rss_kb,hash,outside,mass,top_dx,top_dy,deterministic\n");
      }
      fprintf(f, "%lld,%s,%s,%.3f,%d,%d,%d,%d,%d,%d,%.4f,%.4f,%.4f,%ld,%ld,%016llx,%d,%.1f,", (long long)time(NULL),
              engine, s->name, (double)o->scale, steps, o->runs, r.counts.body_count, r.counts.awake_body_count,
              r.counts.touching_count, r.counts.joint_count, ms[o->runs / 2], ms[0], worst, rss1, rss1 - rss0,
              (unsigned long long)hash, r.outside, r.mass);
      if (r.has_top) {
        fprintf(f, "%f,%f,", (double)r.top_dx, (double)r.top_dy);
      } else {
        fprintf(f, ",,");
      }
      fprintf(f, "%d\n", deterministic ? 1 : 0);
      fclose(f);
    }
  }
  free(ms);
}

static void usage(const char* argv0) {
  fprintf(stderr,
          "usage: %s [--scene NAME] [--runs N] [--steps N] [--scale S] [--quick] [--no-sleep] [--csv FILE]\n"
          "       [--profile-csv FILE]\n",
          argv0);
}

int main(int argc, char** argv) {
  options o = {NULL, 3, 0, 1.0f, false, false, NULL, NULL};
  bool runs_set = false, scale_set = false;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    bool has_value = i + 1 < argc;
    if (strcmp(a, "--scene") == 0 && has_value) {
      o.scene = argv[++i];
    } else if (strcmp(a, "--runs") == 0 && has_value) {
      o.runs = atoi(argv[++i]);
      runs_set = true;
    } else if (strcmp(a, "--steps") == 0 && has_value) {
      o.steps = atoi(argv[++i]);
    } else if (strcmp(a, "--scale") == 0 && has_value) {
      o.scale = (float)atof(argv[++i]);
      scale_set = true;
    } else if (strcmp(a, "--csv") == 0 && has_value) {
      o.csv = argv[++i];
    } else if (strcmp(a, "--profile-csv") == 0 && has_value) {
      o.profile_csv = argv[++i];
    } else if (strcmp(a, "--quick") == 0) {
      o.quick = true;
    } else if (strcmp(a, "--no-sleep") == 0) {
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
  if (o.runs < 1 || !(o.scale > 0.0f && o.scale <= 1.0f) || o.steps < 0) {
    usage(argv[0]);
    return 2;
  }
  int count = 0;
  const tb_scene* scenes = tb_scenes(&count);
  if (o.scene != NULL) {
    const tb_scene* s = tb_scene_find(o.scene);
    if (s == NULL || !tb_scene_is_performance(s)) {
      fprintf(stderr, "unknown performance scene '%s' (scenes:", o.scene);
      for (int k = 0; k < count; ++k) {
        if (tb_scene_is_performance(&scenes[k])) fprintf(stderr, " %s", scenes[k].name);
      }
      fprintf(stderr, ")\n");
      return 2;
    }
  }

  printf("tumble %d.%d.%d dynamics bench: 60 Hz, %d substeps, single thread, %d run(s) after a warm-up, scale %.2f\n",
         TB_VERSION_MAJOR, TB_VERSION_MINOR, TB_VERSION_PATCH, SUBSTEPS, o.runs, (double)o.scale);
  printf("%-12s %-14s %5s %6s %6s %7s %6s %5s %4s %8s %8s %8s %8s %8s %-16s %4s %10s\n", "engine", "scene", "scale",
         "bodies", "awake", "contact", "joints", "steps", "runs", "med ms", "min ms", "worst", "peak MB", "+MB",
         "state hash", "out", "mass kg");
  fflush(stdout);
  int failures = 0;
  for (int k = 0; k < count; ++k) {
    const tb_scene* s = &scenes[k];
    if (!tb_scene_is_performance(s)) continue;
    if (o.scene != NULL && strcmp(s->name, o.scene) != 0) continue;
    pid_t pid = fork();
    if (pid == 0) {
      bench_scene(s, &o);
      fflush(stdout);
      _exit(0);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      fprintf(stderr, "%s failed\n", s->name);
      failures += 1;
    }
  }
  return failures == 0 ? 0 : 1;
}
