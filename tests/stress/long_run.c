/* Long runs: one hour of simulated time of a busy scene, and a world where
 * bodies and joints are created and destroyed every step. */
#include <math.h>
#include <stdlib.h>

#include "stress.h"

/* ---- one hour in a turning drum --------------------------------------------- */

/* A kinematic drum centred at (0, 10) turning at 25 deg/s: four walls 1 m
 * thick around an inner square of 12 m. Inside, 120 bodies on a 12 x 10
 * lattice 0.9 m apart: boxes, circles and capsules in turn, sizes 0.15 to
 * 0.35 m. The drum keeps tumbling them for the whole hour (sleep off). */
#define DRUM_Y 10.0f
#define DRUM_HALF 6.0f
#define DRUM_SPEED (25.0f * 3.14159265f / 180.0f)

tb_world_id stress_new_drum(void) {
  tb_world_id w = stress_world(false);
  tb_body_def dd = tb_default_body_def();
  dd.type = TB_KINEMATIC_BODY;
  dd.position = (tb_vec2){0.0f, DRUM_Y};
  dd.angular_velocity = DRUM_SPEED;
  tb_body_id drum = tb_create_body(w, &dd);
  tb_shape_def sd = tb_default_shape_def();
  const float t = 0.5f, c = DRUM_HALF + t;
  const tb_vec2 centres[4] = {{c, 0.0f}, {-c, 0.0f}, {0.0f, c}, {0.0f, -c}};
  for (int k = 0; k < 4; ++k) {
    tb_polygon wall;
    float hx = k < 2 ? t : c + t, hy = k < 2 ? c + t : t;
    tb_make_offset_box(hx, hy, centres[k], 0.0f, &wall);
    tb_create_polygon_shape(drum, &sd, &wall);
  }
  for (int i = 0; i < 120; ++i) {
    int col = i % 12, row = i / 12;
    tb_vec2 p = {-4.95f + 0.9f * (float)col, DRUM_Y - 4.95f + 0.9f * (float)row};
    float size = 0.15f + 0.2f * (float)((i * 7) % 11) / 10.0f;
    tb_body_def bd = tb_default_body_def();
    bd.type = TB_DYNAMIC_BODY;
    bd.position = p;
    stress_perturb(&bd.position);
    tb_body_id b = tb_create_body(w, &bd);
    if (i % 3 == 0) {
      tb_polygon box;
      tb_make_box(size, size, &box);
      tb_create_polygon_shape(b, &sd, &box);
    } else if (i % 3 == 1) {
      tb_circle circle = {{0.0f, 0.0f}, size};
      tb_create_circle_shape(b, &sd, &circle);
    } else {
      tb_capsule capsule = {{-size, 0.0f}, {size, 0.0f}, 0.5f * size};
      tb_create_capsule_shape(b, &sd, &capsule);
    }
  }
  return w;
}

#define HOUR_STEPS 216000
#define WARM_UP_STEPS 21600 /* the first 6 minutes: scratch buffers reach their size */

/* Checked every simulated second:
 * - every body finite, and none lost: a body farther than the inner
 *   half-diagonal + 1 m from the drum's centre has passed through a wall;
 * - total energy below that of every body at the drum's highest point moving
 *   at twice the walls' fastest speed (omega times the half-diagonal): the
 *   drum lifts bodies and collisions with its moving walls kick them, but a
 *   rolling load stays far below that, and a blow-up passes it at once;
 * - memory flat: the engine's live heap (and the process's RSS) may reach a
 *   new high-water mark now and then as scratch buffers grow to the busiest
 *   step so far, but a leak grows with time: the peak heap of the second half
 *   hour must not exceed the first half hour's (after a 6-minute warm-up). */
void stress_one_hour(stress_result* out) {
  long long heap0 = stress_heap_live_bytes(), rss0 = stress_rss_bytes();
  tb_world_id w = stress_new_drum();
  int n = 0;
  tb_body_id* b = stress_bodies(w, &n); /* the drum first */
  const double reach = DRUM_HALF * sqrt(2.0);
  double bound = 0.0;
  for (int i = 1; i < n; ++i) {
    double m = tb_body_get_mass(b[i]), v = 2.0 * DRUM_SPEED * reach;
    bound += m * (STRESS_G * (DRUM_Y + reach) + 0.5 * v * v);
  }
  double e_max = -INFINITY, e_first = 0.0, e_last = 0.0;
  long long first_half = 0, second_half = 0, rss_half = 0;
  int lost = 0, seconds = 0, seconds_first = 0, seconds_last = 0;
  bool finite = true;
  for (int step = 1; step <= HOUR_STEPS && finite; ++step) {
    finite = stress_step(w);
    if (step % 60 != 0) continue;
    finite = finite && stress_all_finite(b, n);
    seconds += 1;
    double e = stress_energy(b, n);
    e_max = fmax(e_max, e);
    if (step <= WARM_UP_STEPS) e_first += e, seconds_first += 1;
    if (step > HOUR_STEPS - WARM_UP_STEPS) e_last += e, seconds_last += 1;
    for (int i = 1; i < n; ++i) {
      tb_vec2 p = tb_body_get_world_center(b[i]);
      if (hypot(p.x, (double)p.y - DRUM_Y) > reach + 1.0) lost += 1;
    }
    long long heap = stress_heap_live_bytes() - heap0;
    long long* half = step <= HOUR_STEPS / 2 ? &first_half : &second_half;
    if (step > WARM_UP_STEPS && heap > *half) *half = heap;
    if (step == HOUR_STEPS / 2) rss_half = stress_rss_bytes();
  }
  long long rss_end = stress_rss_bytes();
  out->pass = finite && seconds == HOUR_STEPS / 60 && lost == 0 && e_max < bound && second_half <= first_half;
  stress_note(out,
              "%d s simulated, %s, %d bodies lost; energy max %.4g J (bound %.4g), mean %.4g J in the first and "
              "%.4g J in the last 6 min; engine heap peak %lld B in the first half hour, %lld B in the second; RSS "
              "%lld kB at the start, %lld kB at half time, %lld kB at the end",
              seconds, finite ? "all finite" : "NOT FINITE", lost, e_max, bound, e_first / seconds_first,
              e_last / (seconds_last > 0 ? seconds_last : 1), first_half, second_half, rss0 / 1024, rss_half / 1024,
              rss_end / 1024);
  free(b);
  tb_destroy_world(w);
}

/* ---- create and destroy every step ------------------------------------------- */

#define CHURN_STEPS 100000
#define CHURN_ALIVE 20 /* bodies alive at once: each lives 20 steps */
#define STALE_KEPT 64  /* recent stale handles checked every step */

/* Handles as 64-bit keys (kind, index, generation), to find reissues. */
static uint64_t body_key(tb_body_id b) { return (1ull << 48) | ((uint64_t)(uint32_t)b.index1 << 16) | b.generation; }
static uint64_t joint_key(tb_joint_id j) { return (2ull << 48) | ((uint64_t)(uint32_t)j.index1 << 16) | j.generation; }
static int by_key(const void* a, const void* b) {
  uint64_t x = *(const uint64_t*)a, y = *(const uint64_t*)b;
  return (x > y) - (x < y);
}

/* Every step: a new box body (falling onto the ground) jointed by a revolute
 * joint to the previous one; the oldest body destroyed once 20 are alive
 * (taking its joints with it); and a transient body and distance joint created
 * and destroyed at once. Slots are reused last in, first out, so the
 * transient's slot is reused every step: past 65,535 reuses its 16-bit
 * generation would wrap, and the pool must retire the slot instead.
 * - Stale handles never resolve: the very first transient body and joint, and
 *   the 64 most recently destroyed bodies and joints, are invalid after every
 *   step; no handle is ever handed out twice (400,000 handles compared).
 * - No leak: after the world is destroyed the heap is back where it started,
 *   but for the handle history the world slot keeps: at most 2 B per body,
 *   shape and joint slot ever handed out (less when an earlier world in the
 *   slot already used as many), so that the slot's next world never reissues a
 *   handle of this one; bodies and their one shape share a layout. (This
 *   world reuses a slot 65,535 times, so its world slot retires instead and
 *   keeps nothing: tb_pool_end_life.) A second, small world then leaves at
 *   most its own history: 2 B for each of its body and shape.
 * - Flat: scratch buffers and pools keep their largest size, so the live heap
 *   may step up to a new high-water mark now and then; a leak grows it with
 *   the step count. So the second half's peak must not exceed the first
 *   half's (from step 10,000), not counting what the pools take in steps that
 *   retire the transient's slot (a fresh slot, and maybe a grown array). */
typedef struct churn_stats {
  bool ok; /* the list of handles could be allocated */
  int issued, failures, resolved, reissued;
  long long heap_10k, first_half, second_half, retire_growth, leaked, history, second_world;
  tb_counts counts;
  uint64_t hash; /* tb_world_hash after the last step */
} churn_stats;

/* Runs `steps` steps of the churn (the test runs CHURN_STEPS; the determinism
 * check hashes a prefix). */
static churn_stats churn(int steps) {
  churn_stats s = {0};
  long long heap0 = stress_heap_live_bytes();
  tb_world_id w = stress_world(true);
  stress_ground(w, 0.0f, 0.0f, 50.0f);
  tb_body_id alive[CHURN_ALIVE] = {{0, 0, 0}};
  tb_body_id stale_bodies[STALE_KEPT] = {{0, 0, 0}};
  tb_joint_id stale_joints[STALE_KEPT] = {{0, 0, 0}};
  int stale_b = 0, stale_j = 0;
  tb_body_id first_transient = {0, 0, 0};
  tb_joint_id first_transient_joint = {0, 0, 0};
  long long heap_prev = 0;
  int32_t transient_index = -1;
  int32_t body_slots = 0, joint_slots = 0; /* the highest index1 of each */
  uint64_t* keys = malloc(sizeof *keys * 4 * (size_t)steps);
  tb_shape_def sd = tb_default_shape_def();
  for (int step = 0; step < steps && keys != NULL; ++step) {
    int slot = step % CHURN_ALIVE;
    tb_body_id prev = alive[(step + CHURN_ALIVE - 1) % CHURN_ALIVE];
    if (!tb_body_id_is_null(alive[slot])) {
      tb_joint_id joints[4];
      int nj = tb_body_get_joints(alive[slot], joints, 4);
      if (tb_destroy_body(alive[slot]) != TB_OK) s.failures += 1;
      stale_bodies[stale_b++ % STALE_KEPT] = alive[slot];
      for (int k = 0; k < nj && k < 4; ++k) stale_joints[stale_j++ % STALE_KEPT] = joints[k];
    }
    float x = -40.0f + (float)(step % 80);
    alive[slot] = stress_box(w, (tb_vec2){x, 3.0f}, 0.0f, 0.3f, 0.3f, &sd);
    keys[s.issued++] = body_key(alive[slot]);
    if (!tb_body_id_is_null(prev)) {
      tb_revolute_joint_def jd = tb_default_revolute_joint_def();
      jd.body_a = prev;
      jd.body_b = alive[slot];
      jd.local_anchor_a = (tb_vec2){0.3f, 0.3f};
      jd.local_anchor_b = (tb_vec2){-0.3f, 0.3f};
      tb_joint_id j = tb_create_revolute_joint(w, &jd);
      if (tb_joint_id_is_null(j)) s.failures += 1;
      keys[s.issued++] = joint_key(j);
    }
    /* the transient: created, jointed, destroyed within the step */
    tb_body_id t = stress_box(w, (tb_vec2){0.0f, 20.0f}, 0.0f, 0.2f, 0.2f, &sd);
    tb_distance_joint_def dj = tb_default_distance_joint_def();
    dj.body_a = alive[slot];
    dj.body_b = t;
    tb_joint_id tj = tb_create_distance_joint(w, &dj);
    if (tb_body_id_is_null(t) || tb_joint_id_is_null(tj)) s.failures += 1;
    keys[s.issued++] = body_key(t);
    keys[s.issued++] = joint_key(tj);
    if (step == 0) first_transient = t, first_transient_joint = tj;
    body_slots = t.index1 > body_slots ? t.index1 : body_slots;
    body_slots = alive[slot].index1 > body_slots ? alive[slot].index1 : body_slots;
    joint_slots = tj.index1 > joint_slots ? tj.index1 : joint_slots;
    bool retired = transient_index >= 0 && t.index1 != transient_index;
    transient_index = t.index1;
    if (tb_destroy_joint(tj) != TB_OK || tb_destroy_body(t) != TB_OK) s.failures += 1;
    if (!stress_step(w)) s.failures += 1;

    s.resolved += tb_body_is_valid(first_transient) + tb_joint_is_valid(first_transient_joint);
    for (int k = 0; k < STALE_KEPT; ++k) {
      if (k < stale_b) s.resolved += tb_body_is_valid(stale_bodies[k]);
      if (k < stale_j) s.resolved += tb_joint_is_valid(stale_joints[k]);
    }
    long long heap = stress_heap_live_bytes() - heap0;
    if (step == 10000) s.heap_10k = heap;
    if (retired && heap > heap_prev) s.retire_growth += heap - heap_prev;
    heap_prev = heap;
    long long* half = step < steps / 2 ? &s.first_half : &s.second_half;
    if (step >= 10000 && heap - (half == &s.second_half ? s.retire_growth : 0) > *half) *half = heap;
  }
  s.counts = tb_world_get_counts(w);
  s.hash = tb_world_hash(w);
  tb_destroy_world(w);
  s.ok = keys != NULL;
  if (keys != NULL) {
    qsort(keys, (size_t)s.issued, sizeof keys[0], by_key);
    for (int i = 1; i < s.issued; ++i) s.reissued += keys[i] == keys[i - 1];
  }
  free(keys);
  s.history = 2 * (2 * (long long)body_slots + joint_slots);
  /* less if earlier worlds in the slot left a history (freed when the slot retires) */
  s.leaked = stress_heap_live_bytes() - heap0;
  long long after_first = stress_heap_live_bytes();
  tb_world_id again = stress_world(true);
  stress_ground(again, 0.0f, 0.0f, 50.0f);
  stress_step(again);
  tb_destroy_world(again);
  s.second_world = stress_heap_live_bytes() - after_first;
  return s;
}

void stress_churn(stress_result* out) {
  churn_stats s = churn(CHURN_STEPS);
  out->pass = s.ok && s.failures == 0 && s.resolved == 0 && s.reissued == 0 && s.leaked <= s.history &&
              s.second_world >= 0 && s.second_world <= 2 * 2 && s.second_half <= s.first_half;
  stress_note(out,
              "%d steps, %d handles, %d failed calls; stale handles resolved %d times, reissued %d; engine heap "
              "%lld B at step 10,000, peak %lld B in steps 10,000-50,000 and %lld B after (+%lld B for retired "
              "slots); %lld B left after tb_destroy_world (at most the %lld B handle history its slot keeps), %lld B "
              "more after a second, small world (at most 4 B); %d bodies, %d joints alive at the end",
              CHURN_STEPS, s.issued, s.failures, s.resolved, s.reissued, s.heap_10k, s.first_half, s.second_half,
              s.retire_growth, s.leaked, s.history, s.second_world, s.counts.body_count, s.counts.joint_count);
}

uint64_t stress_churn_hash(int steps) { return churn(steps).hash; }
