/* Islands and sleep.
 *
 * The awake set is one array of body indices (world->awake); a body's place in
 * it is its awake_index and also the index of its solver body, so the solver
 * walks awake bodies contiguously and a sleeping body costs nothing per step.
 *
 * An island is a set of dynamic bodies linked by touching contacts and joints;
 * static and kinematic bodies end an island instead of joining two. Awake
 * islands are found each step by a search that starts only from bodies that
 * have rested for TB_TIME_TO_SLEEP, so an active scene pays next to nothing.
 * An island whose bodies all rested that long falls asleep as a whole: its
 * bodies leave the awake set and are kept as a persistent sleeping island (a
 * linked list of bodies) so that touching any of them wakes exactly that
 * island, with its contacts and warm-start impulses intact. */
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "world.h"

typedef struct tb_island {
  int first_body; /* linked through body->island_next */
  int body_count;
} tb_island;

size_t tb_island_size(void) { return sizeof(tb_island); }

void tb_islands_free(tb_world* w) { tb_pool_free(&w->islands); }

static tb_island* island_at(tb_world* w, int i) { return (tb_island*)tb_pool_at(&w->islands, i); }

static bool awake_push(tb_world* w, int body) {
  if (!tb_array_reserve((void**)&w->awake, &w->awake_capacity, w->awake_count + 1, sizeof(int))) return false;
  tb_body* b = tb_body_at(w, body);
  b->awake_index = w->awake_count;
  b->sleep_time = 0.0f;
  w->awake[w->awake_count++] = body;
  w->walked_joints_valid = false; /* (collect_joints walks the awake bodies) */
  w->layout_valid = false;        /* (the contacts' colours are by solver body) */
  return true;
}

/* Swap-remove: the last awake body takes the hole (a deterministic order). */
static void awake_remove(tb_world* w, int body) {
  tb_body* b = tb_body_at(w, body);
  int hole = b->awake_index;
  int last = w->awake[--w->awake_count];
  w->awake[hole] = last;
  tb_body_at(w, last)->awake_index = hole;
  b->awake_index = -1;
  w->walked_joints_valid = false;
  w->layout_valid = false;
}

static void wake_island(tb_world* w, int island) {
  tb_island* is = island_at(w, island);
  if (!tb_array_reserve((void**)&w->awake, &w->awake_capacity, w->awake_count + is->body_count, sizeof(int)))
    return; /* out of memory: the island sleeps on */
  for (int k = is->first_body; k >= 0;) {
    tb_body* b = tb_body_at(w, k);
    int next = b->island_next;
    b->sleep_island = -1;
    b->island_next = -1;
    awake_push(w, k);
    k = next;
  }
  tb_pool_release(&w->islands, island);
}

void tb_wake_body(tb_world* w, int body) {
  tb_body* b = tb_body_at(w, body);
  if (b->type == TB_STATIC_BODY || !b->enabled) return;
  if (b->awake_index >= 0) {
    b->sleep_time = 0.0f;
  } else if (b->sleep_island >= 0) {
    wake_island(w, b->sleep_island);
  } else {
    awake_push(w, body);
  }
}

void tb_wake_all(tb_world* w) {
  for (int i = 0; i < w->islands.high; ++i)
    if (tb_pool_alive(&w->islands, i)) wake_island(w, i);
}

void tb_remove_body_from_sets(tb_world* w, int body) {
  tb_body* b = tb_body_at(w, body);
  if (b->awake_index >= 0) awake_remove(w, body);
  if (b->sleep_island >= 0) {
    tb_island* is = island_at(w, b->sleep_island);
    int* link = &is->first_body;
    while (*link != body) link = &tb_body_at(w, *link)->island_next;
    *link = b->island_next;
    is->body_count -= 1;
    if (is->body_count == 0) tb_pool_release(&w->islands, b->sleep_island);
    b->sleep_island = -1;
    b->island_next = -1;
  }
}

bool tb_add_body_to_sets(tb_world* w, int body, bool awake) {
  tb_body* b = tb_body_at(w, body);
  b->awake_index = b->sleep_island = b->island_next = -1;
  if (b->type == TB_STATIC_BODY || !b->enabled) return true;
  if (awake) return awake_push(w, body);
  int island = tb_pool_alloc(&w->islands);
  if (island < 0) return false;
  b = tb_body_at(w, body);
  *island_at(w, island) = (tb_island){body, 1};
  b->sleep_island = island;
  return true;
}

/* Puts the island of awake bodies listed in members[0..count) to sleep. */
static void sleep_island(tb_world* w, const int* members, int count) {
  int island = tb_pool_alloc(&w->islands);
  if (island < 0) return; /* out of memory: it stays awake */
  tb_island* is = island_at(w, island);
  is->first_body = -1;
  is->body_count = 0;
  for (int k = count - 1; k >= 0; --k) {
    int body = members[k];
    tb_body* b = tb_body_at(w, body);
    awake_remove(w, body);
    b->linear_velocity = (tb_vec2){0.0f, 0.0f};
    b->angular_velocity = 0.0f;
    b->force = (tb_vec2){0.0f, 0.0f};
    b->torque = 0.0f;
    b->sleep_island = island;
    b->island_next = is->first_body;
    is->first_body = body;
    is->body_count += 1;
  }
}

/* Calls visit(other) for each body linked to `body` by a touching, enabled,
 * non-sensor contact or by a joint. */
#define FOR_EACH_LINK(w, body, other, visit)                                           \
  do {                                                                                 \
    for (int key_ = tb_body_at(w, body)->contact_list; key_ >= 0;) {                   \
      const tb_contact* c_ = (const tb_contact*)tb_pool_at(&(w)->contacts, key_ >> 1); \
      int next_ = c_->edges[key_ & 1].next;                                            \
      const uint32_t need_ = TB_CONTACT_TOUCHING | TB_CONTACT_ENABLED;                 \
      if ((c_->flags & need_) == need_ && !(c_->flags & TB_CONTACT_SENSOR)) {          \
        int other = c_->edges[(key_ & 1) ^ 1].body;                                    \
        visit;                                                                         \
      }                                                                                \
      key_ = next_;                                                                    \
    }                                                                                  \
    for (int key_ = tb_body_at(w, body)->joint_list; key_ >= 0;) {                     \
      const tb_joint* j_ = tb_joint_at(w, key_ >> 1);                                  \
      int next_ = j_->edges[key_ & 1].next;                                            \
      int other = j_->edges[(key_ & 1) ^ 1].body;                                      \
      visit;                                                                           \
      key_ = next_;                                                                    \
    }                                                                                  \
  } while (0)

/* The awake island of `seed` (whose mark must be clear): depth-first search
 * over dynamic bodies, marking by awake index; members doubles as the stack.
 * Returns the member count; *resting tells whether every member and every
 * kinematic body it touches rested for TB_TIME_TO_SLEEP. */
/* The island of seed (awake bodies, by BFS), marking its members by awake
 * index; *resting: whether all of them (and the kinematic bodies they touch)
 * have rested for TB_TIME_TO_SLEEP. With give_up, the search stops at the
 * first body that has not: the island cannot sleep, and what was visited is
 * marked MARK_AWAKE, which ends any later search of this step that reaches
 * it the same way (a pile with one body still moving was searched whole
 * every step: 4% of compounds and junkyard). */
enum { MARK_NONE, MARK_SEEN, MARK_AWAKE };

static int collect_island(tb_world* w, int seed, int* members, int* mark, bool* resting, bool give_up) {
  int count = 0, top = 0;
  *resting = true;
  mark[tb_body_at(w, seed)->awake_index] = MARK_SEEN;
  members[count++] = seed;
  while (top < count && (*resting || !give_up)) {
    int body = members[top++];
    const tb_body* b = tb_body_at(w, body);
    if (b->sleep_time < TB_TIME_TO_SLEEP) *resting = false;
    if (b->type != TB_DYNAMIC_BODY) continue; /* kinematic bodies end the island */
    FOR_EACH_LINK(w, body, other, {
      const tb_body* o = tb_body_at(w, other);
      if (o->type == TB_STATIC_BODY || o->awake_index < 0) {
      } else if (o->type == TB_KINEMATIC_BODY) {
        if (o->sleep_time < TB_TIME_TO_SLEEP) *resting = false; /* a moving platform keeps it awake */
      } else if (mark[o->awake_index] == MARK_AWAKE) {
        *resting = false; /* part of an island already found awake */
      } else if (mark[o->awake_index] == MARK_NONE) {
        mark[o->awake_index] = MARK_SEEN;
        members[count++] = other;
      }
    });
  }
  if (!*resting)
    for (int k = 0; k < count; ++k) mark[tb_body_at(w, members[k])->awake_index] = MARK_AWAKE;
  return count;
}

void tb_sleep_island_of(tb_world* w, int body) {
  int n = w->awake_count;
  if (tb_body_at(w, body)->awake_index < 0) return;
  if (!tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, 2 * n, sizeof(int))) return;
  memset(w->scratch, 0, (size_t)n * sizeof(int));
  bool resting;
  int count = collect_island(w, body, w->scratch + n, w->scratch, &resting, false);
  sleep_island(w, w->scratch + n, count);
}

void tb_update_sleep(tb_world* w) {
  if (!w->enable_sleep) return;
  int n = w->awake_count;
  bool any = false;
  for (int i = 0; i < n && !any; ++i) any = tb_body_at(w, w->awake[i])->sleep_time >= TB_TIME_TO_SLEEP;
  if (!any) return;
  /* scratch: [0, n) marks by awake index, [n, 2n) the island being searched,
   * [2n, 3n) the bodies of the islands that fall asleep, one after the other
   * (at most 64 islands per step; more wait for the next step). */
  if (!tb_array_reserve((void**)&w->scratch, &w->scratch_capacity, 3 * n, sizeof(int))) return;
  int* mark = w->scratch;
  int* members = w->scratch + n;
  int* sleepers = w->scratch + 2 * n;
  int sleeper_count = 0;
  int island_starts[64];
  int island_count = 0;
  memset(mark, 0, (size_t)n * sizeof(int));
  for (int i = 0; i < n; ++i) {
    int seed = w->awake[i];
    if (mark[i] || tb_body_at(w, seed)->sleep_time < TB_TIME_TO_SLEEP) continue;
    bool resting;
    int count = collect_island(w, seed, members, mark, &resting, true);
    if (!resting || island_count == (int)(sizeof island_starts / sizeof island_starts[0])) continue;
    island_starts[island_count++] = sleeper_count;
    memcpy(sleepers + sleeper_count, members, (size_t)count * sizeof(int));
    sleeper_count += count;
  }
  /* after the search (sleeping changes the awake order it walks) */
  for (int k = 0; k < island_count; ++k) {
    int start = island_starts[k];
    int end = k + 1 < island_count ? island_starts[k + 1] : sleeper_count;
    sleep_island(w, sleepers + start, end - start);
  }
}
