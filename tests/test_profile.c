/* The per-step profile: stage times that add up to the step (measured while
 * the profile is enabled), and counts that agree with tb_world_get_counts. */
#include "test_util.h"

static tb_world_id pyramid_world(int base) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  ck_assert_int_eq(tb_world_enable_profile(w, true), TB_OK);
  tb_body_def gd = tb_default_body_def();
  tb_body_id ground = tb_create_body(w, &gd);
  tb_polygon box;
  tb_make_box(50.0f, 0.5f, &box);
  tb_shape_def sd = tb_default_shape_def();
  tb_create_polygon_shape(ground, &sd, &box);
  for (int row = 0; row < base; ++row)
    for (int i = 0; i < base - row; ++i)
      tbt_box_body(w, (float)i - 0.5f * (float)(base - row) + 0.5f, 1.0f + (float)row, 0.5f, 0.5f);
  return w;
}

START_TEST(zero_before_the_first_step) {
  tb_world_id w = pyramid_world(5);
  tb_profile p = tb_world_get_profile(w);
  ck_assert(p.step == 0.0f && p.solver == 0.0f && p.awake_body_count == 0 && p.pair_count == 0);
  tb_destroy_world(w);
}
END_TEST

START_TEST(stages_add_up_and_counts_agree) {
  tb_world_id w = pyramid_world(20);
  for (int k = 0; k < 30; ++k) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
  tb_profile p = tb_world_get_profile(w);
  tb_counts c = tb_world_get_counts(w);
  ck_assert(p.step > 0.0f && p.solver > 0.0f && p.narrow_phase > 0.0f);
  ck_assert(p.broad_phase >= 0.0f && p.continuous >= 0.0f && p.islands >= 0.0f);
  /* The stages are disjoint intervals inside the step; rounding each to float
   * may add a few ulps. */
  float sum = p.broad_phase + p.narrow_phase + p.solver + p.continuous + p.islands;
  ck_assert_msg(sum <= p.step * 1.0001f, "stages %g > step %g", (double)sum, (double)p.step);
  /* Nothing falls asleep within 0.5 s, so the awake counts are the world's. */
  ck_assert_int_eq(p.awake_body_count, c.awake_body_count);
  ck_assert_int_eq(p.awake_body_count, 210);
  ck_assert_int_eq(p.awake_contact_count, c.awake_contact_count);
  ck_assert_int_eq(p.pair_count, c.contact_count);
  ck_assert_int_eq(p.awake_joint_count, 0);
  ck_assert_int_eq(p.continuous_count, 0);
  tb_destroy_world(w);
}
END_TEST

/* Off by default: the stage times read 0 and cost no clock reads, the counts
 * are kept; on and off again between steps; the switch is not part of the
 * state (the hash, what a step computes). */
START_TEST(times_only_while_enabled) {
  ck_assert(!tb_default_world_def().enable_profile);
  tb_world_id w = pyramid_world(10), twin = pyramid_world(10);
  ck_assert_int_eq(tb_world_enable_profile(w, false), TB_OK);
  ck_assert(!tb_world_is_profile_enabled(w) && tb_world_is_profile_enabled(twin));
  ck_assert(tb_world_hash(w) == tb_world_hash(twin));
  for (int k = 0; k < 3; ++k) {
    ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
    ck_assert_int_eq(tb_world_step(twin, 1.0f / 60.0f, 4), TB_OK);
  }
  tb_profile off = tb_world_get_profile(w), on = tb_world_get_profile(twin);
  ck_assert(off.step == 0.0f && off.broad_phase == 0.0f && off.narrow_phase == 0.0f && off.solver == 0.0f &&
            off.continuous == 0.0f && off.islands == 0.0f);
  ck_assert(on.step > 0.0f && on.solver > 0.0f);
  ck_assert_int_eq(off.awake_body_count, 55);
  ck_assert_int_eq(off.awake_contact_count, on.awake_contact_count);
  ck_assert_int_eq(off.pair_count, on.pair_count);
  ck_assert(tb_world_hash(w) == tb_world_hash(twin));
  ck_assert_int_eq(tb_world_enable_profile(w, true), TB_OK);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
  ck_assert(tb_world_is_profile_enabled(w) && tb_world_get_profile(w).step > 0.0f);
  ck_assert_int_eq(tb_world_enable_profile(w, false), TB_OK);
  ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
  ck_assert(tb_world_get_profile(w).step == 0.0f);
  tb_destroy_world(w);
  tb_destroy_world(twin);
}
END_TEST

START_TEST(new_pairs_counted_once) {
  /* Two boxes dropped apart on the ground: the pairs appear in the first step
   * and are not new after that. */
  tb_world_id w = pyramid_world(0);
  tbt_box_body(w, -3.0f, 0.9f, 0.5f, 0.5f);
  tbt_box_body(w, 3.0f, 0.9f, 0.5f, 0.5f);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_world_get_profile(w).new_pair_count, 2);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_world_get_profile(w).new_pair_count, 0);
  ck_assert_int_eq(tb_world_get_profile(w).pair_count, 2);
  tb_destroy_world(w);
}
END_TEST

START_TEST(fast_body_is_counted) {
  tb_world_id w = pyramid_world(0);
  tb_body_id b = tbt_box_body(w, 0.0f, 10.0f, 0.1f, 0.1f);
  tb_body_set_linear_velocity(b, (tb_vec2){30.0f, 0.0f});
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_world_get_profile(w).continuous_count, 1);
  tb_destroy_world(w);
}
END_TEST

/* Relax passes. A box held on a slope by friction (gravity tilted 20 degrees,
 * friction 0.6 against tan 20 = 0.36) has one contact and nothing else: its
 * relax rounds converge within one pass, one pass a substep but where eight
 * rounds do not reach 1e-5 m/s (measured: 483 passes in 480 substeps; when
 * the passes repeated over all contacts instead, 2,153). A box on top gives
 * the lower one two contacts: the passes repeat, up to relax_iterations (8)
 * a substep (measured: 8 in every substep). */
START_TEST(relax_passes_counted) {
  const float tilt = 20.0f * 3.14159265f / 180.0f;
  for (int stacked = 0; stacked < 2; ++stacked) {
    tb_world_id w = pyramid_world(0);
    tb_world_set_gravity(w, (tb_vec2){10.0f * sinf(tilt), -10.0f * cosf(tilt)});
    tb_world_enable_sleeping(w, false);
    tbt_box_body(w, 0.0f, 1.0f, 0.5f, 0.5f);
    if (stacked) tbt_box_body(w, 0.0f, 2.0f, 0.5f, 0.5f);
    int total = 0, most = 0;
    for (int k = 0; k < 120; ++k) {
      ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
      int passes = tb_world_get_profile(w).relax_pass_count;
      ck_assert_int_ge(passes, 4);
      ck_assert_int_le(passes, 4 * 8);
      total += passes;
      most = passes > most ? passes : most;
    }
    tbt_report("TB_PROFILE_VERBOSE", "relax passes, %s: %d in 120 steps of 4 substeps, at most %d a step",
               stacked ? "two boxes" : "one box", total, most);
    if (stacked)
      ck_assert_int_gt(total, 2 * 480);
    else
      ck_assert_int_le(total, 480 + 48); /* at most 1 in 10 substeps with a second pass */
    tb_destroy_world(w);
  }
}
END_TEST

START_TEST(stale_world_is_rejected) {
  tb_world_id w = pyramid_world(3);
  tb_world_step(w, 1.0f / 60.0f, 4);
  tb_destroy_world(w);
  tb_profile p = tb_world_get_profile(w);
  ck_assert(p.step == 0.0f && p.awake_body_count == 0);
  ck_assert_int_eq(tb_last_result(), TB_ERR_STALE_HANDLE);
}
END_TEST

static Suite* profile_suite(void) {
  Suite* s = suite_create("profile");
  TCase* tc = tcase_create("profile");
  tcase_add_test(tc, zero_before_the_first_step);
  tcase_add_test(tc, stages_add_up_and_counts_agree);
  tcase_add_test(tc, times_only_while_enabled);
  tcase_add_test(tc, new_pairs_counted_once);
  tcase_add_test(tc, fast_body_is_counted);
  tcase_add_test(tc, relax_passes_counted);
  tcase_add_test(tc, stale_world_is_rejected);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(profile_suite)
