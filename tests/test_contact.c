/* Broad phase to contacts: filtering, pair lifetime, events, sensors, callbacks. */
#include <string.h>

#include "test_util.h"

static tb_body_id make_body(tb_world_id w, tb_body_type type, float x, float y) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = (tb_vec2){x, y};
  return tb_create_body(w, &bd);
}

static tb_shape_id add_circle(tb_body_id b, const tb_shape_def* sd, float r) {
  tb_circle c = {{0.0f, 0.0f}, r};
  tb_shape_id s = tb_create_circle_shape(b, sd, &c);
  ck_assert(!tb_shape_id_is_null(s));
  return s;
}

/* Two overlapping unit circles with the given filters and body types:
 * does a touching contact appear after one step? */
static int touching_after_step(tb_filter fa, tb_filter fb, tb_body_type ta, tb_body_type tb, bool same_body) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sa = tb_default_shape_def(), sb = tb_default_shape_def();
  sa.filter = fa;
  sb.filter = fb;
  tb_body_id a = make_body(w, ta, 0.0f, 0.0f);
  tb_body_id b = same_body ? a : make_body(w, tb, 1.0f, 0.0f);
  add_circle(a, &sa, 1.0f);
  if (same_body) {
    tb_circle c = {{1.0f, 0.0f}, 1.0f};
    tb_create_circle_shape(a, &sb, &c);
  } else {
    add_circle(b, &sb, 1.0f);
  }
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  int touching = tb_world_get_counts(w).touching_count;
  tb_destroy_world(w);
  return touching;
}

START_TEST(filter_truth_table) {
  const tb_filter def = tb_default_filter();
  const tb_body_type D = TB_DYNAMIC_BODY, S = TB_STATIC_BODY, K = TB_KINEMATIC_BODY;
  struct row {
    tb_filter a, b;
    tb_body_type ta, tb;
    bool same_body;
    int expect;
    const char* why;
  } rows[] = {
      {def, def, D, D, false, 1, "defaults collide"},
      {{2, ~2ull, 0}, def, D, D, false, 1, "A's mask ~2 holds B's category 1, B's mask holds A's 2"},
      {{2, 1, 0}, {1, 1, 0}, D, D, false, 0, "A's category 2 is not in B's mask 1"},
      {{1, ~1ull, 0}, {1, ~0ull, 0}, D, D, false, 0, "B's category 1 is not in A's mask ~1"},
      {{2, 1, 0}, {1, 2, 0}, D, D, false, 1, "each category is in the other's mask"},
      {{2, 0, 3}, {4, 0, 3}, D, D, false, 1, "the same positive group collides whatever the bits"},
      {{1, ~0ull, -3}, {1, ~0ull, -3}, D, D, false, 0, "the same negative group never collides"},
      {{1, ~0ull, -3}, {1, ~0ull, -4}, D, D, false, 1, "different negative groups: the bits decide"},
      {{1, 0, -3}, {1, ~0ull, 5}, D, D, false, 0, "different groups: the bits decide (mask 0)"},
      {{2, 1, 0}, {1, 2, 0}, S, D, false, 1, "each category in the other's mask, against a static body"},
      {{2, 1, 0}, {1, 1, 0}, D, S, false, 0, "A's category 2 is not in the static B's mask 1"},
      {{2, 0, 3}, {4, 0, 3}, S, D, false, 1, "a positive group shared with a static body, masks 0"},
      {{2, 0, 3}, {4, 0, 3}, D, K, false, 1, "a positive group shared with a kinematic body, masks 0"},
      {def, def, D, D, true, 0, "shapes of one body never collide"},
      {def, def, S, S, false, 0, "two static bodies"},
      {def, def, K, S, false, 0, "kinematic and static"},
      {def, def, K, K, false, 0, "two kinematic bodies"},
      {def, def, K, D, false, 1, "kinematic and dynamic"},
      {def, def, S, D, false, 1, "static and dynamic"},
  };
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; ++i) {
    int got = touching_after_step(rows[i].a, rows[i].b, rows[i].ta, rows[i].tb, rows[i].same_body);
    ck_assert_msg(got == rows[i].expect, "row %zu (%s): %d touching, want %d", i, rows[i].why, got, rows[i].expect);
  }
}
END_TEST

static bool refuse_all(tb_shape_id a, tb_shape_id b, void* ctx) {
  (void)a;
  (void)b;
  *(int*)ctx += 1;
  return false;
}

START_TEST(custom_filter_and_segments) {
  int calls = 0;
  tb_world_def wd = tb_default_world_def();
  wd.gravity = (tb_vec2){0, 0};
  wd.custom_filter = refuse_all;
  wd.custom_filter_context = &calls;
  tb_world_id w = tb_create_world(&wd);
  tb_shape_def sd = tb_default_shape_def();
  add_circle(make_body(w, TB_DYNAMIC_BODY, 0, 0), &sd, 1.0f);
  add_circle(make_body(w, TB_DYNAMIC_BODY, 1, 0), &sd, 1.0f);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(calls, 1); /* asked once for the one new pair */
  ck_assert_int_eq(tb_world_get_counts(w).contact_count, 0);
  tb_destroy_world(w);
  /* segments have no area: two crossing segments make no contact */
  w = tbt_world(0.0f, 0.0f);
  tb_segment s1 = {{-1, 0}, {1, 0}}, s2 = {{0, -1}, {0, 1}};
  tb_create_segment_shape(make_body(w, TB_DYNAMIC_BODY, 0, 0), &sd, &s1);
  tb_create_segment_shape(make_body(w, TB_DYNAMIC_BODY, 0, 0), &sd, &s2);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_world_get_counts(w).contact_count, 0);
  tb_destroy_world(w);
}
END_TEST

/* A ball lowered onto the ground: exactly one begin; lifted away: one end. */
START_TEST(begin_and_end_events) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  tb_body_id ground = make_body(w, TB_STATIC_BODY, 0, 0);
  tb_polygon box;
  tb_make_box(10.0f, 0.5f, &box);
  tb_shape_id ground_shape = tb_create_polygon_shape(ground, &sd, &box);
  tb_body_id ball = make_body(w, TB_DYNAMIC_BODY, 0.0f, 2.0f);
  tb_shape_id ball_shape = add_circle(ball, &sd, 0.5f);
  tb_body_set_linear_velocity(ball, (tb_vec2){0.0f, -1.0f});
  int begins = 0, ends = 0, steps = 0;
  while (begins == 0 && steps < 200) {
    tb_world_step(w, 1.0f / 60.0f, 4);
    ++steps;
    tb_contact_events ev = tb_world_get_contact_events(w);
    begins += ev.begin_count;
    ends += ev.end_count;
    if (ev.begin_count == 1) {
      /* the pair is ordered polygon (A) then circle (B); normal points up to the ball */
      ck_assert(ev.begin_events[0].shape_a.index1 == ground_shape.index1);
      ck_assert(ev.begin_events[0].shape_b.index1 == ball_shape.index1);
      ck_assert_near(ev.begin_events[0].manifold.normal.y, 1.0, 1e-5);
      ck_assert_int_eq(ev.begin_events[0].manifold.point_count, 1);
    }
  }
  ck_assert_int_eq(begins, 1);
  /* the speculative margin: it begins before the surfaces meet. The manifold is
   * from the step's start, 1/60 m higher than the ball is now. */
  float gap = tb_body_get_position(ball).y - 0.5f - 0.5f + 1.0f / 60.0f;
  ck_assert_msg(gap > 0.0f && gap <= TB_SPECULATIVE_DISTANCE + 1e-5f, "gap %g", (double)gap);
  tb_body_set_linear_velocity(ball, (tb_vec2){0.0f, 0.0f});
  for (int i = 0; i < 60; ++i) {
    tb_world_step(w, 1.0f / 60.0f, 4);
    begins += tb_world_get_contact_events(w).begin_count;
    ends += tb_world_get_contact_events(w).end_count;
  }
  ck_assert_int_eq(begins, 1);
  ck_assert_int_eq(ends, 0);
  ck_assert_int_eq(tb_body_get_contact_capacity(ball), 1);
  tb_contact_data cd;
  ck_assert_int_eq(tb_body_get_contact_data(ball, &cd, 1), 1);
  ck_assert(cd.touching && cd.enabled);
  ck_assert_near(cd.friction, 0.6, 1e-6);
  tb_body_set_transform(ball, (tb_vec2){0.0f, 5.0f}, 0.0f);
  for (int i = 0; i < 10; ++i) {
    tb_world_step(w, 1.0f / 60.0f, 4);
    begins += tb_world_get_contact_events(w).begin_count;
    ends += tb_world_get_contact_events(w).end_count;
  }
  ck_assert_int_eq(begins, 1);
  ck_assert_int_eq(ends, 1);
  ck_assert_int_eq(tb_world_get_counts(w).contact_count, 0); /* fat boxes apart: contact gone */
  tb_destroy_world(w);
}
END_TEST

START_TEST(destroying_a_touching_shape_ends_its_contact) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  add_circle(make_body(w, TB_STATIC_BODY, 0, 0), &sd, 1.0f);
  tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 1.5f, 0);
  tb_shape_id s = add_circle(b, &sd, 1.0f);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_world_get_counts(w).touching_count, 1);
  ck_assert_int_eq(tb_destroy_shape(s), TB_OK);
  ck_assert_int_eq(tb_world_get_counts(w).contact_count, 0);
  tb_world_step(w, 1.0f / 60.0f, 4); /* events of a step start empty ... */
  ck_assert_int_eq(tb_world_get_contact_events(w).end_count, 0);
  tb_destroy_world(w);
}
END_TEST

START_TEST(hit_events) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon box;
  tb_make_box(10.0f, 0.5f, &box);
  tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0, 0), &sd, &box);
  sd.enable_hit_events = true;
  tb_body_id fast = make_body(w, TB_DYNAMIC_BODY, -3.0f, 1.6f);
  add_circle(fast, &sd, 0.5f);
  tb_body_set_linear_velocity(fast, (tb_vec2){0.0f, -5.0f});
  tb_body_id slow = make_body(w, TB_DYNAMIC_BODY, 3.0f, 1.6f);
  add_circle(slow, &sd, 0.5f);
  tb_body_set_linear_velocity(slow, (tb_vec2){0.0f, -0.5f}); /* under the 1 m/s threshold */
  int hits = 0;
  float speed = 0.0f;
  for (int i = 0; i < 30; ++i) {
    tb_world_step(w, 1.0f / 60.0f, 4);
    tb_contact_events ev = tb_world_get_contact_events(w);
    for (int k = 0; k < ev.hit_count; ++k) {
      ++hits;
      speed = ev.hit_events[k].approach_speed;
      ck_assert_near(ev.hit_events[k].normal.y, 1.0, 1e-5);
      ck_assert_near(ev.hit_events[k].point.x, -3.0, 1e-4);
    }
  }
  ck_assert_int_eq(hits, 1);
  ck_assert_near(speed, 5.0, 1e-4);
  tb_destroy_world(w);
}
END_TEST

/* A sensor reports a visitor passing through, and never pushes. */
START_TEST(sensor_events) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  sd.is_sensor = true;
  tb_polygon box;
  tb_make_box(1.0f, 1.0f, &box);
  tb_shape_id sensor = tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0, 0), &sd, &box);
  ck_assert(tb_shape_is_sensor(sensor));
  sd = tb_default_shape_def();
  tb_body_id ball = make_body(w, TB_DYNAMIC_BODY, -3.0f, 0.0f);
  tb_shape_id ball_shape = add_circle(ball, &sd, 0.25f);
  sd.enable_sensor_events = false;                               /* this one is invisible to sensors */
  tb_body_id ghost = make_body(w, TB_DYNAMIC_BODY, -3.0f, 0.9f); /* clear of the ball */
  add_circle(ghost, &sd, 0.25f);
  tb_body_set_linear_velocity(ball, (tb_vec2){3.0f, 0.0f});
  tb_body_set_linear_velocity(ghost, (tb_vec2){3.0f, 0.0f});
  int begins = 0, ends = 0, contact_begins = 0;
  float x_begin = 0.0f, x_end = 0.0f;
  for (int i = 0; i < 120; ++i) {
    tb_world_step(w, 1.0f / 60.0f, 4);
    tb_sensor_events ev = tb_world_get_sensor_events(w);
    for (int k = 0; k < ev.begin_count; ++k) {
      ck_assert(ev.begin_events[k].sensor.index1 == sensor.index1);
      ck_assert(ev.begin_events[k].visitor.index1 == ball_shape.index1);
      x_begin = tb_body_get_position(ball).x;
    }
    if (ev.end_count > 0) x_end = tb_body_get_position(ball).x;
    begins += ev.begin_count;
    ends += ev.end_count;
    contact_begins += tb_world_get_contact_events(w).begin_count;
  }
  ck_assert_int_eq(begins, 1);
  ck_assert_int_eq(ends, 1);
  ck_assert_int_eq(contact_begins, 0); /* sensor overlaps are not contacts */
  /* overlap starts at x = -1.25 and ends at 1.25; events come at the next
   * step, and a step that lands exactly on the edge (separation 0, not yet an
   * overlap) adds one more: two steps of 0.05 m */
  ck_assert_near(x_begin, -1.25, 0.11);
  ck_assert_near(x_end, 1.25, 0.11);
  ck_assert_float_eq(tb_body_get_linear_velocity(ball).x, 3.0f);
  ck_assert_int_eq(tb_body_get_contact_capacity(ball), 0);
  tb_destroy_world(w);
}
END_TEST

static bool one_way(tb_shape_id a, tb_shape_id b, const tb_manifold* m, void* ctx) {
  (void)a;
  (void)b;
  *(int*)ctx += 1;
  return m->normal.y > 0.5f; /* only contacts pushing B upward stay */
}

static float mix_min(float a, float b, void* ctx) {
  (void)ctx;
  return a < b ? a : b;
}

START_TEST(pre_solve_and_mixing) {
  int calls = 0;
  tb_world_def wd = tb_default_world_def();
  wd.gravity = (tb_vec2){0, 0};
  wd.pre_solve = one_way;
  wd.pre_solve_context = &calls;
  wd.friction_mix = mix_min;
  tb_world_id w = tb_create_world(&wd);
  tb_shape_def sd = tb_default_shape_def();
  sd.enable_pre_solve_events = true;
  sd.friction = 0.2f;
  sd.restitution = 0.3f;
  tb_polygon box;
  tb_make_box(2.0f, 0.1f, &box);
  tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0, 0), &sd, &box);
  sd.friction = 0.8f;
  sd.restitution = 0.7f;
  tb_body_id above = make_body(w, TB_DYNAMIC_BODY, -1.0f, 0.3f);
  add_circle(above, &sd, 0.25f);
  tb_body_id below = make_body(w, TB_DYNAMIC_BODY, 1.0f, -0.3f);
  add_circle(below, &sd, 0.25f);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_ge(calls, 2);
  tb_contact_data cd;
  ck_assert_int_eq(tb_body_get_contact_data(above, &cd, 1), 1);
  ck_assert(cd.touching && cd.enabled);
  ck_assert_float_eq(cd.friction, 0.2f);    /* the custom rule: min */
  ck_assert_float_eq(cd.restitution, 0.7f); /* the default rule: max */
  ck_assert_int_eq(tb_body_get_contact_data(below, &cd, 1), 1);
  ck_assert(cd.touching && !cd.enabled);
  tb_destroy_world(w);
}
END_TEST

/* The callback can be set, swapped and removed after creation: with it the
 * lower ball's contact is disabled, without it the same contact pushes. */
START_TEST(pre_solve_set_later) {
  int calls = 0;
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  sd.enable_pre_solve_events = true;
  tb_polygon box;
  tb_make_box(2.0f, 0.1f, &box);
  tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0, 0), &sd, &box);
  tb_body_id below = make_body(w, TB_DYNAMIC_BODY, 1.0f, -0.3f);
  add_circle(below, &sd, 0.25f);
  ck_assert_int_eq(tb_world_set_pre_solve(w, one_way, &calls), TB_OK);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_ge(calls, 1);
  tb_contact_data cd;
  ck_assert_int_eq(tb_body_get_contact_data(below, &cd, 1), 1);
  ck_assert(cd.touching && !cd.enabled);
  ck_assert_int_eq(tb_world_set_pre_solve(w, NULL, NULL), TB_OK);
  int before = calls;
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(calls, before);
  ck_assert_int_eq(tb_body_get_contact_data(below, &cd, 1), 1);
  ck_assert(cd.touching && cd.enabled);
  tb_destroy_world(w);
  ck_assert_int_eq(tb_world_set_pre_solve(w, one_way, &calls), TB_ERR_STALE_HANDLE);
}
END_TEST

/* Records the manifold the solver is about to warm-start from. */
static bool record_manifold(tb_shape_id a, tb_shape_id b, const tb_manifold* m, void* context) {
  (void)a;
  (void)b;
  *(tb_manifold*)context = *m;
  return true;
}

/* A box resting flush on a box of its width: shifted across the lower box's
 * centre line by 0.2 mm, each end of the contact edge switches from one
 * box's corner to the other's, so both points get new feature ids while
 * staying where they were. They keep their impulses (the warm start) rather
 * than starting cold; a cold start dropped the load for a substep and, in a
 * 30-box column, grew into a topple. */
START_TEST(impulses_follow_points_whose_id_changed) {
  tb_manifold seen = {{0.0f, 0.0f}, {{{0.0f, 0.0f}, 0.0f, 0, 0.0f, 0.0f}}, 0};
  tb_world_def wd = tb_default_world_def();
  wd.enable_sleep = false;
  wd.pre_solve = record_manifold;
  wd.pre_solve_context = &seen;
  tb_world_id w = tb_create_world(&wd);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon ground, box;
  tb_make_box(5.0f, 0.5f, &ground);
  tb_make_box(0.5f, 0.5f, &box);
  tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0.0f, -0.5f), &sd, &ground);
  tb_create_polygon_shape(make_body(w, TB_DYNAMIC_BODY, 0.0f, 0.5f), &sd, &box);
  sd.enable_pre_solve_events = true;
  tb_body_id top = make_body(w, TB_DYNAMIC_BODY, 1e-4f, 1.5f);
  tb_create_polygon_shape(top, &sd, &box);
  for (int i = 0; i < 60; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  tb_contact_data before;
  ck_assert_int_eq(tb_body_get_contact_data(top, &before, 1), 1);
  ck_assert_int_eq(before.manifold.point_count, 2);
  /* each point carries half the top box's weight, 1 kg x 10 m/s^2 x h / 2 */
  float h = 1.0f / 240.0f;
  for (int k = 0; k < 2; ++k) ck_assert_float_eq_tol(before.manifold.points[k].normal_impulse, 5.0f * h, 0.05f * h);
  tb_vec2 p = tb_body_get_position(top);
  ck_assert_int_eq(tb_body_set_transform(top, (tb_vec2){-1e-4f, p.y}, 0.0f), TB_OK);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(seen.point_count, 2);
  for (int k = 0; k < 2; ++k) {
    bool same_id = false;
    for (int j = 0; j < 2; ++j) same_id |= seen.points[k].id == before.manifold.points[j].id;
    ck_assert_msg(!same_id, "point %d kept its feature id %x: the shift no longer switches features", k,
                  seen.points[k].id);
    ck_assert_float_eq_tol(seen.points[k].normal_impulse, 5.0f * h, 0.05f * h);
  }
  tb_destroy_world(w);
}
END_TEST

START_TEST(default_mixing_is_geometric_mean) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  sd.friction = 0.25f;
  add_circle(make_body(w, TB_STATIC_BODY, 0, 0), &sd, 1.0f);
  sd.friction = 0.64f;
  tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 1.5f, 0);
  add_circle(b, &sd, 1.0f);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_contact_data cd;
  ck_assert_int_eq(tb_body_get_contact_data(b, &cd, 1), 1);
  ck_assert_near(cd.friction, 0.4, 1e-6);
  tb_destroy_world(w);
}
END_TEST

static float mix_returns(float a, float b, void* ctx) {
  (void)a, (void)b;
  return *(const float*)ctx;
}

/* A mix callback's result outside its material's range (issue 23 item 9) is
 * not used: the contact takes the default rule, the step that made the
 * contact reports TB_ERR_NUMERIC naming the callback, and the bodies move on.
 * A ball dropped 0.5 m comes to rest on the floor (a NaN restitution used to
 * freeze it in the air). */
START_TEST(mix_results_out_of_range_use_the_default_rule) {
  const float bad_friction[] = {-1.0f, NAN, INFINITY, -INFINITY};
  const float bad_restitution[] = {-1.0f, NAN, INFINITY, 1.5f};
  for (int which = 0; which < 2; ++which) {
    for (int i = 0; i < 4; ++i) {
      float value = which == 0 ? bad_friction[i] : bad_restitution[i];
      tb_world_def wd = tb_default_world_def();
      if (which == 0)
        wd.friction_mix = mix_returns;
      else
        wd.restitution_mix = mix_returns;
      wd.mix_context = &value;
      tb_world_id w = tb_create_world(&wd);
      tb_shape_def sd = tb_default_shape_def();
      tb_polygon floor;
      tb_make_box(2.0f, 0.1f, &floor);
      tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0, 0), &sd, &floor);
      sd.friction = 0.36f;
      sd.restitution = 0.25f;
      tb_body_id ball = make_body(w, TB_DYNAMIC_BODY, 0.0f, 0.85f);
      add_circle(ball, &sd, 0.25f);
      int reports = 0;
      for (int k = 0; k < 120; ++k) {
        tb_result r = tb_world_step(w, 1.0f / 60.0f, 4);
        if (r == TB_OK) continue;
        ck_assert_int_eq(r, TB_ERR_NUMERIC);
        ck_assert_ptr_nonnull(strstr(tb_last_error(), which == 0 ? "friction_mix" : "restitution_mix"));
        reports += 1;
      }
      ck_assert_int_eq(reports, 1); /* one contact, mixed once */
      tb_contact_data cd;
      ck_assert_int_eq(tb_body_get_contact_data(ball, &cd, 1), 1);
      ck_assert_float_eq(cd.friction, sqrtf(0.6f * 0.36f)); /* the default rules: sqrt(fa fb) */
      ck_assert_float_eq(cd.restitution, 0.25f);            /* and max(ra, rb) */
      /* at rest on the floor: the centre 0.1 + 0.25 above its middle, within the contact's reach */
      ck_assert_near(tb_body_get_position(ball).y, 0.35, TB_SPECULATIVE_DISTANCE);
      ck_assert_near(tb_body_get_linear_velocity(ball).y, 0.0, 0.05);
      tb_destroy_world(w);
    }
  }
}
END_TEST

/* TB_MAX_GRAVITY is the gravity a contact holds at the default step (60 Hz,
 * 4 substeps): a resting body sinks g / w^2 = 1e4 / (2 pi 115.2 Hz)^2 =
 * 0.019 m, within TB_SPECULATIVE_DISTANCE, so a 5 cm box stays on a 5 cm
 * floor. A body's gravity_scale cannot take it past that: a scale of 1e6 in a
 * 10 m/s^2 world is clamped to TB_MAX_GRAVITY (unclamped, 1e7 m/s^2 pushed
 * the box through the floor). */
START_TEST(gravity_at_its_limit_is_held) {
  const float world_gravity[2] = {TB_MAX_GRAVITY, 10.0f}, scale[2] = {1.0f, 1.0e6f};
  for (int k = 0; k < 2; ++k) {
    tb_world_id w = tbt_world(0.0f, -world_gravity[k]);
    tb_shape_def sd = tb_default_shape_def();
    tb_polygon floor;
    tb_make_box(1.0f, 0.025f, &floor);
    tb_create_polygon_shape(make_body(w, TB_STATIC_BODY, 0, 0), &sd, &floor);
    tb_body_id box = tbt_box_body(w, 0.0f, 0.05f, 0.025f, 0.025f);
    ck_assert_int_eq(tb_body_set_gravity_scale(box, scale[k]), TB_OK);
    for (int i = 0; i < 120; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
    ck_assert_near(tb_body_get_position(box).y, 0.05, TB_SPECULATIVE_DISTANCE);
    tb_destroy_world(w);
  }
}
END_TEST

/* Pairs come and go with the fat AABBs. A step's manifolds use the positions
 * at its start, so after each step the touching contacts must be exactly the
 * circle pairs closer than the speculative distance before it (brute force). */
START_TEST(touching_pairs_match_brute_force) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  unsigned seed = 7;
  enum { N = 400 };
  tb_body_id bodies[N];
  float radius[N];
  for (int i = 0; i < N; ++i) {
    bodies[i] = make_body(w, TB_DYNAMIC_BODY, tbt_rand(&seed, 0, 40), tbt_rand(&seed, 0, 40));
    radius[i] = tbt_rand(&seed, 0.2f, 1.0f);
    add_circle(bodies[i], &sd, radius[i]);
    tb_body_set_linear_velocity(bodies[i], (tb_vec2){tbt_rand(&seed, -3, 3), tbt_rand(&seed, -3, 3)});
  }
  int checked = 0, max_touching = 0;
  for (int step = 0; step < 120; ++step) {
    int must = 0, may = 0; /* float slack of 1e-4 m around the threshold */
    for (int i = 0; i < N; ++i) {
      tb_vec2 pi = tb_body_get_position(bodies[i]);
      for (int j = i + 1; j < N; ++j) {
        tb_vec2 pj = tb_body_get_position(bodies[j]);
        double dx = pi.x - pj.x, dy = pi.y - pj.y;
        double gap = sqrt(dx * dx + dy * dy) - radius[i] - radius[j];
        must += gap < TB_SPECULATIVE_DISTANCE - 1e-4;
        may += gap < TB_SPECULATIVE_DISTANCE + 1e-4;
      }
    }
    tb_world_step(w, 1.0f / 60.0f, 4);
    int touching = tb_world_get_counts(w).touching_count;
    ck_assert_msg(touching >= must && touching <= may, "step %d: %d touching, brute force %d..%d", step, touching, must,
                  may);
    checked += 1;
    if (touching > max_touching) max_touching = touching;
  }
  ck_assert_int_gt(max_touching, 10); /* the scene is busy enough to mean something */
  ck_assert_int_eq(checked, 120);
  tb_counts c = tb_world_get_counts(w);
  ck_assert_int_le(c.tree_height, 2 * 9 + 2); /* ~2 log2(400) */
  ck_assert_int_ge(c.contact_count, c.touching_count);
  tb_destroy_world(w);
}
END_TEST

/* A moving body's contacts are listed in the order of their shape pairs
 * (the solver's order; see link_edge in contact.c), however many arrive in
 * one step and in whatever order the broad phase finds them. The new ones of
 * a step are merged into the sorted rest in one go: a pile of 40 circles at
 * one point gives every body 39 new contacts at once (odd run lengths for
 * the merge), and a second pile dropped into the first merges new contacts
 * into lists that already hold some. */
static int pair_index(const tb_contact_data* c, tb_shape_id own) {
  tb_shape_id other = c->shape_a.index1 == own.index1 ? c->shape_b : c->shape_a;
  return (int)other.index1;
}

static void check_lists_sorted(const tb_body_id* bodies, const tb_shape_id* shapes, int count, int want_at_least) {
  tb_contact_data data[128];
  int longest = 0;
  for (int i = 0; i < count; ++i) {
    int n = tb_body_get_contact_data(bodies[i], data, 128);
    ck_assert_int_le(n, 128);
    for (int k = 1; k < n; ++k)
      ck_assert_msg(pair_index(&data[k - 1], shapes[i]) < pair_index(&data[k], shapes[i]),
                    "body %d: contact %d (shape %d) listed before contact %d (shape %d)", i, k - 1,
                    pair_index(&data[k - 1], shapes[i]), k, pair_index(&data[k], shapes[i]));
    if (n > longest) longest = n;
  }
  ck_assert_int_ge(longest, want_at_least);
}

START_TEST(contact_lists_stay_sorted_in_a_pile) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_shape_def sd = tb_default_shape_def();
  enum { N = 40 };
  tb_body_id bodies[2 * N];
  tb_shape_id shapes[2 * N];
  for (int i = 0; i < N; ++i) {
    bodies[i] = make_body(w, TB_DYNAMIC_BODY, 0.0f, 0.0f);
    shapes[i] = add_circle(bodies[i], &sd, 0.5f);
  }
  tb_world_step(w, 1.0f / 60.0f, 4);
  check_lists_sorted(bodies, shapes, N, N - 1);
  for (int i = N; i < 2 * N; ++i) {
    bodies[i] = make_body(w, TB_DYNAMIC_BODY, 0.1f, 0.0f);
    shapes[i] = add_circle(bodies[i], &sd, 0.5f);
  }
  tb_world_step(w, 1.0f / 60.0f, 4);
  check_lists_sorted(bodies, shapes, 2 * N, N);
  tb_destroy_world(w);
}
END_TEST

static Suite* contact_suite(void) {
  Suite* s = suite_create("contact");
  TCase* tc = tcase_create("contact");
  tcase_add_test(tc, filter_truth_table);
  tcase_add_test(tc, custom_filter_and_segments);
  tcase_add_test(tc, begin_and_end_events);
  tcase_add_test(tc, destroying_a_touching_shape_ends_its_contact);
  tcase_add_test(tc, hit_events);
  tcase_add_test(tc, sensor_events);
  tcase_add_test(tc, pre_solve_and_mixing);
  tcase_add_test(tc, pre_solve_set_later);
  tcase_add_test(tc, impulses_follow_points_whose_id_changed);
  tcase_add_test(tc, default_mixing_is_geometric_mean);
  tcase_add_test(tc, mix_results_out_of_range_use_the_default_rule);
  tcase_add_test(tc, gravity_at_its_limit_is_held);
  tcase_add_test(tc, touching_pairs_match_brute_force);
  tcase_add_test(tc, contact_lists_stay_sorted_in_a_pile);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(contact_suite)
