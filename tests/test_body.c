/* Bodies and worlds through the public API: placement, transforms, momentum,
 * energy, mass overrides, shapes, user data, handles. */
#include <string.h>

#include "test_util.h"

START_TEST(transforms_round_trip) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_def bd = tb_default_body_def();
  bd.position = (tb_vec2){3.0f, -2.0f};
  bd.angle = 0.6f;
  tb_body_id b = tb_create_body(w, &bd);
  tb_vec2 local = {1.5f, 0.25f};
  tb_vec2 world = tb_body_get_world_point(b, local);
  ck_assert_near(world.x, 3.0 + cos(0.6) * 1.5 - sin(0.6) * 0.25, 1e-6);
  ck_assert_near(world.y, -2.0 + sin(0.6) * 1.5 + cos(0.6) * 0.25, 1e-6);
  tb_vec2 back = tb_body_get_local_point(b, world);
  ck_assert_near(back.x, 1.5, 1e-6);
  ck_assert_near(back.y, 0.25, 1e-6);
  tb_vec2 v = tb_body_get_world_vector(b, (tb_vec2){1.0f, 0.0f});
  ck_assert_near(v.x, cos(0.6), 1e-7);
  ck_assert_near(v.y, sin(0.6), 1e-7);
  tb_vec2 lv = tb_body_get_local_vector(b, v);
  ck_assert_near(lv.x, 1.0, 1e-6);
  ck_assert_near(lv.y, 0.0, 1e-6);
  tb_transform xf = tb_body_get_transform(b);
  ck_assert_float_eq(xf.p.x, 3.0f);
  ck_assert_near(xf.q.s, sin(0.6), 1e-7);
  ck_assert_int_eq(tb_body_set_transform(b, (tb_vec2){-1.0f, 1.0f}, -0.3f), TB_OK);
  ck_assert_float_eq(tb_body_get_position(b).x, -1.0f);
  ck_assert_float_eq(tb_body_get_angle(b), -0.3f);
  tb_destroy_world(w);
}
END_TEST

/* P = M V; L about a point q = I w + (X - q) x M V; E = M V^2/2 + I w^2/2;
 * the velocity of a material point p is V + w x (p - X). */
START_TEST(momentum_and_energy) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_id b = tbt_box_body(w, 2.0f, 1.0f, 1.0f, 0.5f); /* m = 2, I = 2 * 5 / 12 */
  tb_body_set_linear_velocity(b, (tb_vec2){3.0f, -1.0f});
  tb_body_set_angular_velocity(b, 2.0f);
  double m = 2.0, inertia = 2.0 * 5.0 / 12.0;
  ck_assert_rel(tb_body_get_linear_momentum(b).x, 6.0, 1e-6);
  ck_assert_rel(tb_body_get_linear_momentum(b).y, -2.0, 1e-6);
  ck_assert_rel(tb_body_get_kinetic_energy(b), 0.5 * m * 10.0 + 0.5 * inertia * 4.0, 1e-6);
  ck_assert_rel(tb_body_get_angular_momentum(b, (tb_vec2){2.0f, 1.0f}), inertia * 2.0, 1e-6);
  /* about the origin: r = (2, 1), r x P = 2 * -2 - 1 * 6 = -10 */
  ck_assert_rel(tb_body_get_angular_momentum(b, (tb_vec2){0.0f, 0.0f}), inertia * 2.0 - 10.0, 1e-6);
  tb_vec2 pv = tb_body_get_point_velocity(b, (tb_vec2){3.0f, 1.0f}); /* r = (1, 0): w x r = (0, 2) */
  ck_assert_near(pv.x, 3.0, 1e-6);
  ck_assert_near(pv.y, 1.0, 1e-6);
  /* free motion conserves P, L and E exactly in the absence of forces */
  double l0 = tb_body_get_angular_momentum(b, (tb_vec2){0, 0}), e0 = tb_body_get_kinetic_energy(b);
  for (int i = 0; i < 100; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_rel(tb_body_get_kinetic_energy(b), e0, 1e-6);
  /* L about a fixed point: |r| grows to ~8 m, so float positions give ~1e-6 relative */
  ck_assert_rel(tb_body_get_angular_momentum(b, (tb_vec2){0, 0}), l0, 1e-5);
  tb_destroy_world(w);
}
END_TEST

START_TEST(mass_data_override_and_reset) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_id b = tbt_box_body(w, 0.0f, 0.0f, 1.0f, 1.0f);
  ck_assert_rel(tb_body_get_mass(b), 4.0, 1e-6);
  tb_body_set_angular_velocity(b, 1.0f);
  ck_assert_int_eq(tb_body_set_mass_data(b, (tb_mass_data){10.0f, {0.5f, 0.0f}, 3.0f}), TB_OK);
  ck_assert_float_eq(tb_body_get_mass(b), 10.0f);
  ck_assert_float_eq(tb_body_get_rotational_inertia(b), 3.0f);
  ck_assert_float_eq(tb_body_get_world_center(b).x, 0.5f);
  /* the origin stays; the new centre's velocity is V + w x dc (material point) */
  ck_assert_float_eq(tb_body_get_position(b).x, 0.0f);
  ck_assert_near(tb_body_get_linear_velocity(b).y, 0.5, 1e-6);
  tb_body_apply_angular_impulse(b, 3.0f);
  ck_assert_near(tb_body_get_angular_velocity(b), 2.0, 1e-6);
  ck_assert_int_eq(tb_body_reset_mass_data(b), TB_OK);
  ck_assert_rel(tb_body_get_mass(b), 4.0, 1e-6);
  ck_assert_float_eq(tb_body_get_local_center(b).x, 0.0f);
  /* adding a shape also recomputes from the shapes */
  tb_body_set_mass_data(b, (tb_mass_data){10.0f, {0.0f, 0.0f}, 3.0f});
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{0, 0}, 0.1f};
  tb_create_circle_shape(b, &sd, &c);
  ck_assert_rel(tb_body_get_mass(b), 4.0 + 3.14159265 * 0.01, 1e-6);
  /* a shape's density change too */
  tb_shape_id shapes[2];
  ck_assert_int_eq(tb_body_get_shapes(b, shapes, 2), 2);
  ck_assert_int_eq(tb_body_get_shape_count(b), 2);
  for (int i = 0; i < 2; ++i)
    if (tb_shape_get_type(shapes[i]) == TB_SHAPE_CIRCLE) tb_shape_set_density(shapes[i], 0.0f);
  ck_assert_rel(tb_body_get_mass(b), 4.0, 1e-6);
  tb_destroy_world(w);
}
END_TEST

START_TEST(body_types) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_id b = tbt_box_body(w, 0.0f, 0.0f, 1.0f, 1.0f);
  tb_body_set_linear_velocity(b, (tb_vec2){1.0f, 0.0f});
  ck_assert_int_eq(tb_body_set_type(b, TB_STATIC_BODY), TB_OK);
  ck_assert_int_eq(tb_body_get_type(b), TB_STATIC_BODY);
  ck_assert_float_eq(tb_body_get_mass(b), 0.0f);
  ck_assert_float_eq(tb_body_get_linear_velocity(b).x, 0.0f);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_float_eq(tb_body_get_position(b).y, 0.0f);
  ck_assert_int_eq(tb_body_set_type(b, TB_DYNAMIC_BODY), TB_OK);
  ck_assert_rel(tb_body_get_mass(b), 4.0, 1e-6);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert(tb_body_get_position(b).y < 0.0f);
  tb_destroy_world(w);
}
END_TEST

START_TEST(shapes_and_user_data) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  int tag_b = 1, tag_s = 2, tag_w = 3;
  tb_world_set_user_data(w, &tag_w);
  ck_assert_ptr_eq(tb_world_get_user_data(w), &tag_w);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.user_data = &tag_b;
  tb_body_id b = tb_create_body(w, &bd);
  ck_assert_ptr_eq(tb_body_get_user_data(b), &tag_b);
  ck_assert_int_eq(tb_world_get_integrator(w), TB_INTEGRATOR_MIDPOINT);
  tb_shape_def sd = tb_default_shape_def();
  sd.user_data = &tag_s;
  sd.friction = 0.25f;
  sd.restitution = 0.5f;
  tb_capsule cap = {{-1, 0}, {1, 0}, 0.25f};
  tb_shape_id s = tb_create_capsule_shape(b, &sd, &cap);
  ck_assert_ptr_eq(tb_shape_get_user_data(s), &tag_s);
  ck_assert_float_eq(tb_shape_get_friction(s), 0.25f);
  ck_assert_float_eq(tb_shape_get_restitution(s), 0.5f);
  ck_assert_float_eq(tb_shape_get_density(s), 1.0f);
  ck_assert_int_eq(tb_shape_get_type(s), TB_SHAPE_CAPSULE);
  tb_body_id owner = tb_shape_get_body(s);
  ck_assert(owner.index1 == b.index1 && owner.generation == b.generation);
  tb_capsule back;
  ck_assert_int_eq(tb_shape_get_capsule(s, &back), TB_OK);
  ck_assert_float_eq(back.radius, 0.25f);
  tb_segment seg = {{0, 0}, {0, 1}};
  tb_shape_id s2 = tb_create_segment_shape(b, &sd, &seg);
  tb_counts c = tb_world_get_counts(w);
  ck_assert_int_eq(c.body_count, 1);
  ck_assert_int_eq(c.shape_count, 2);
  tb_destroy_shape(s2);
  ck_assert(!tb_shape_is_valid(s2));
  ck_assert(tb_shape_is_valid(s));
  ck_assert_int_eq(tb_destroy_body(b), TB_OK);
  ck_assert(!tb_shape_is_valid(s)); /* the body's shapes go with it */
  c = tb_world_get_counts(w);
  ck_assert_int_eq(c.body_count, 0);
  ck_assert_int_eq(c.shape_count, 0);
  tb_destroy_world(w);
}
END_TEST

START_TEST(world_table_and_settings) {
  tb_world_id ids[200];
  int made = 0;
  tb_world_def def = tb_default_world_def();
  for (; made < 200; ++made) {
    ids[made] = tb_create_world(&def);
    if (tb_world_id_is_null(ids[made])) break;
  }
  ck_assert_int_eq(tb_last_result(), TB_ERR_CAPACITY);
  ck_assert_int_gt(made, 100); /* 128, less any world another test left open */
  for (int i = 0; i < made; ++i) ck_assert_int_eq(tb_destroy_world(ids[i]), TB_OK);
  tb_world_id w = tb_create_world(&def);
  ck_assert(!tb_world_id_is_null(w));
  ck_assert_float_eq(tb_world_get_gravity(w).y, -10.0f);
  tb_world_set_gravity(w, (tb_vec2){1.0f, 2.0f});
  ck_assert_float_eq(tb_world_get_gravity(w).x, 1.0f);
  for (int i = 0; i < 3; ++i) tb_world_step(w, 1.0f / 32.0f, 1);
  ck_assert(fabs(tb_world_get_time(w) - 3.0 / 32.0) < 1e-12);
  ck_assert_int_eq(tb_world_get_counts(w).step_count, 3);
  tb_destroy_world(w);
}
END_TEST

/* Same calls, same bits: two worlds built and stepped alike hash alike. */
START_TEST(deterministic_hash) {
  uint64_t hashes[2];
  for (int run = 0; run < 2; ++run) {
    tb_world_id w = tbt_world(0.0f, -10.0f);
    for (int i = 0; i < 50; ++i) {
      tb_body_id b = tbt_box_body(w, (float)i, 0.0f, 0.5f, 0.25f);
      tb_body_apply_force(b, (tb_vec2){(float)i, 1.0f}, (tb_vec2){(float)i + 0.3f, 0.1f});
      if (i % 7 == 3) tb_destroy_body(b);
    }
    for (int i = 0; i < 100; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
    hashes[run] = tb_world_hash(w);
    tb_destroy_world(w);
  }
  ck_assert_uint_eq(hashes[0], hashes[1]);
}
END_TEST

/* A filter change takes effect at the next step: two boxes resting one on the
 * other with masks that exclude each other fall through; a filter that lets
 * them collide again makes the contact come back without either moving. */
START_TEST(filter_change_refinds_pairs) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_id a = tbt_box_body(w, 0.0f, 0.0f, 0.5f, 0.5f);
  tb_body_id b = tbt_box_body(w, 0.0f, 0.9f, 0.5f, 0.5f);
  tb_shape_id sa;
  ck_assert_int_eq(tb_body_get_shapes(a, &sa, 1), 1);
  tb_filter apart = tb_default_filter();
  apart.mask_bits = 0;
  ck_assert_int_eq(tb_shape_set_filter(sa, apart), TB_OK);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_body_get_contact_capacity(a), 0);
  ck_assert_int_eq(tb_shape_set_filter(sa, tb_default_filter()), TB_OK);
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_body_get_contact_capacity(a), 1);
  ck_assert_int_eq(tb_body_get_contact_capacity(b), 1);
  tb_destroy_world(w);
}
END_TEST

/* A negative group keeps its shapes apart, and the broad phase skips the parts
 * of its trees that hold one group alone (tb_tree_query_apart): a column of
 * boxes of one group has no contacts; taking the middle box out of the group
 * brings back its two, and putting it back ends them. */
START_TEST(group_change_refinds_pairs) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_id boxes[5];
  tb_shape_id shapes[5];
  tb_filter group = tb_default_filter();
  group.group_index = -3;
  for (int i = 0; i < 5; ++i) {
    boxes[i] = tbt_box_body(w, 0.0f, 0.9f * (float)i, 0.5f, 0.5f);
    ck_assert_int_eq(tb_body_get_shapes(boxes[i], &shapes[i], 1), 1);
    ck_assert_int_eq(tb_shape_set_filter(shapes[i], group), TB_OK);
  }
  tb_world_step(w, 1.0f / 60.0f, 4);
  for (int i = 0; i < 5; ++i) ck_assert_int_eq(tb_body_get_contact_capacity(boxes[i]), 0);
  ck_assert_int_eq(tb_shape_set_filter(shapes[2], tb_default_filter()), TB_OK);
  tb_world_step(w, 1.0f / 60.0f, 4);
  const int touched[5] = {0, 1, 2, 1, 0};
  for (int i = 0; i < 5; ++i) ck_assert_int_eq(tb_body_get_contact_capacity(boxes[i]), touched[i]);
  ck_assert_int_eq(tb_shape_set_filter(shapes[2], group), TB_OK);
  tb_world_step(w, 1.0f / 60.0f, 4);
  for (int i = 0; i < 5; ++i) ck_assert_int_eq(tb_body_get_contact_capacity(boxes[i]), 0);
  tb_destroy_world(w);
}
END_TEST

/* A body placed on the edge of the world (its origin at TB_MAX_LENGTH) has a
 * box that reaches beyond it. A change that must insert its shapes anew is
 * refused with a message that says why, and leaves the world as it was; a
 * filter change needs no new box. */
START_TEST(body_beyond_max_length) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_id b = tbt_box_body(w, 0.0f, 0.0f, 2.0f, 2.0f); /* floats there are 1 m apart: reach 2 m beyond */
  ck_assert_int_eq(tb_body_set_transform(b, (tb_vec2){TB_MAX_LENGTH, 0.0f}, 0.0f), TB_OK);
  tb_shape_id s;
  ck_assert_int_eq(tb_body_get_shapes(b, &s, 1), 1);
  ck_assert_int_eq(tb_shape_set_filter(s, tb_default_filter()), TB_OK);
  uint64_t before = tb_world_hash(w);
  ck_assert_int_eq(tb_body_set_type(b, TB_KINEMATIC_BODY), TB_ERR_INVALID_ARGUMENT);
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "tb_body_set_type: the shape's box reaches beyond TB_MAX_LENGTH"));
  ck_assert_uint_eq(tb_world_hash(w), before);
  ck_assert_int_eq(tb_body_get_type(b), TB_DYNAMIC_BODY);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{2.0f, 0.0f}, 0.5f};
  ck_assert(!tb_shape_is_valid(tb_create_circle_shape(b, &sd, &c)));
  ck_assert_ptr_nonnull(strstr(tb_last_error(), "beyond TB_MAX_LENGTH"));
  ck_assert_uint_eq(tb_world_hash(w), before);
  ck_assert_int_eq(tb_body_set_enabled(b, false), TB_OK);
  before = tb_world_hash(w);
  ck_assert_int_eq(tb_body_set_enabled(b, true), TB_ERR_INVALID_ARGUMENT);
  ck_assert_uint_eq(tb_world_hash(w), before);
  ck_assert(!tb_body_is_enabled(b));
  /* moved back, it can enter the broad phase again */
  ck_assert_int_eq(tb_body_set_transform(b, (tb_vec2){0.0f, 0.0f}, 0.0f), TB_OK);
  ck_assert_int_eq(tb_body_set_enabled(b, true), TB_OK);
  ck_assert_int_eq(tb_body_set_type(b, TB_KINEMATIC_BODY), TB_OK);
  tb_destroy_world(w);
}
END_TEST

/* The world ends at TB_MAX_LENGTH (issue 23 item 7): a body that a legal
 * velocity carries there stops at the edge, its shapes still inside, and loses
 * its speed outwards, so everything its getters return its setters accept
 * and its shapes can still be added to. Dynamic and kinematic alike, on both
 * axes and both sides. */
START_TEST(bodies_stop_at_the_edge_of_the_world) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  ck_assert_int_eq(tb_world_set_maximum_linear_speed(w, 1.0e6f), TB_OK);
  const tb_vec2 directions[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int k = 0; k < 8; ++k) {
    tb_vec2 d = directions[k % 4];
    tb_body_id b = tbt_box_body(w, d.x * (TB_MAX_LENGTH - 1000.0f), d.y * (TB_MAX_LENGTH - 1000.0f), 0.5f, 0.5f);
    if (k >= 4) ck_assert_int_eq(tb_body_set_type(b, TB_KINEMATIC_BODY), TB_OK);
    /* 1e5 m/s covers the last 1000 m in the first of 60 steps */
    ck_assert_int_eq(tb_body_set_linear_velocity(b, (tb_vec2){1.0e5f * d.x, 1.0e5f * d.y + 3.0f}), TB_OK);
    for (int i = 0; i < 60; ++i) ck_assert_int_eq(tb_world_step(w, 1.0f / 60.0f, 4), TB_OK);
    tb_vec2 p = tb_body_get_position(b), v = tb_body_get_linear_velocity(b);
    ck_assert_float_le(fabsf(p.x), TB_MAX_LENGTH);
    ck_assert_float_le(fabsf(p.y), TB_MAX_LENGTH);
    ck_assert_float_ge(fabsf(d.x * p.x + d.y * p.y), TB_MAX_LENGTH - 10.0f); /* it got there */
    ck_assert_float_eq(d.x * v.x + d.y * v.y, 0.0f);
    ck_assert_int_eq(tb_body_set_transform(b, p, tb_body_get_angle(b)), TB_OK);
    ck_assert_int_eq(tb_body_set_linear_velocity(b, v), TB_OK);
    tb_circle c = {{0.0f, 0.0f}, 0.25f};
    tb_shape_def sd = tb_default_shape_def();
    ck_assert(tb_shape_is_valid(tb_create_circle_shape(b, &sd, &c)));
    ck_assert_int_eq(tb_body_set_type(b, k >= 4 ? TB_DYNAMIC_BODY : TB_KINEMATIC_BODY), TB_OK);
    ck_assert_int_eq(tb_destroy_body(b), TB_OK);
  }
  tb_destroy_world(w);
}
END_TEST

/* Energy and momenta of the heaviest, fastest body the setters accept: the
 * products overflow a float (1/2 1e18 kg (1e18 m/s)^2 = 5e53 J), and the
 * getters report them saturated at TB_MAX_VALUE, finite. */
START_TEST(derived_getters_stay_within_max_value) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_id b = tbt_box_body(w, 0.0f, 0.0f, 0.5f, 0.5f);
  ck_assert_int_eq(tb_body_set_mass_data(b, (tb_mass_data){TB_MAX_VALUE, {0.0f, 0.0f}, TB_MAX_VALUE}), TB_OK);
  ck_assert_int_eq(tb_body_set_linear_velocity(b, (tb_vec2){TB_MAX_VALUE, -TB_MAX_VALUE}), TB_OK);
  ck_assert_int_eq(tb_body_set_angular_velocity(b, TB_MAX_VALUE), TB_OK);
  ck_assert_float_eq(tb_body_get_kinetic_energy(b), TB_MAX_VALUE);
  tb_vec2 p = tb_body_get_linear_momentum(b);
  ck_assert_float_eq(p.x, TB_MAX_VALUE);
  ck_assert_float_eq(p.y, -TB_MAX_VALUE);
  ck_assert_float_eq(tb_body_get_angular_momentum(b, (tb_vec2){0.0f, 0.0f}), TB_MAX_VALUE);
  ck_assert_float_eq(tb_body_get_angular_momentum(b, (tb_vec2){TB_MAX_LENGTH, TB_MAX_LENGTH}), TB_MAX_VALUE);
  tb_vec2 v = tb_body_get_point_velocity(b, (tb_vec2){0.0f, TB_MAX_LENGTH}); /* 1e18 - 1e18 x 1e7 */
  ck_assert_float_eq(v.x, -TB_MAX_VALUE);
  ck_assert_float_eq(v.y, -TB_MAX_VALUE);
  /* ordinary values are the exact products */
  ck_assert_int_eq(tb_body_set_mass_data(b, (tb_mass_data){2.0f, {0.0f, 0.0f}, 0.5f}), TB_OK);
  ck_assert_int_eq(tb_body_set_linear_velocity(b, (tb_vec2){3.0f, 4.0f}), TB_OK);
  ck_assert_int_eq(tb_body_set_angular_velocity(b, 2.0f), TB_OK);
  ck_assert_float_eq(tb_body_get_kinetic_energy(b), 26.0f); /* 1/2 2 25 + 1/2 0.5 4 */
  ck_assert_float_eq(tb_body_get_linear_momentum(b).y, 8.0f);
  tb_destroy_world(w);
}
END_TEST

/* Shapes each within TB_MAX_VALUE add up beyond it: two discs of 0.6e18 kg,
 * 1e6 m apart (parallel axis: 1.2e18 kg x (5e5 m)^2 = 3e29 kg m^2). The body
 * reports its mass data saturated at TB_MAX_VALUE, which
 * tb_body_set_mass_data accepts back. */
START_TEST(summed_mass_saturates_at_max_value) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  sd.density = 0.6e18f / 3.14159265f; /* a unit disc of 0.6e18 kg */
  const float x[2] = {-5.0e5f, 5.0e5f};
  for (int i = 0; i < 2; ++i) {
    tb_circle c = {{x[i], 0.0f}, 1.0f};
    ck_assert(tb_shape_is_valid(tb_create_circle_shape(b, &sd, &c)));
  }
  tb_mass_data md = tb_body_get_mass_data(b);
  ck_assert_float_eq(md.mass, TB_MAX_VALUE);
  ck_assert_float_eq(md.rotational_inertia, TB_MAX_VALUE);
  ck_assert_float_eq(md.center.x, 0.0f);
  ck_assert_int_eq(tb_body_set_mass_data(b, md), TB_OK);
  tb_destroy_world(w);
}
END_TEST

static Suite* body_suite(void) {
  Suite* s = suite_create("body");
  TCase* tc = tcase_create("body");
  tcase_add_test(tc, transforms_round_trip);
  tcase_add_test(tc, momentum_and_energy);
  tcase_add_test(tc, mass_data_override_and_reset);
  tcase_add_test(tc, body_types);
  tcase_add_test(tc, shapes_and_user_data);
  tcase_add_test(tc, world_table_and_settings);
  tcase_add_test(tc, deterministic_hash);
  tcase_add_test(tc, filter_change_refinds_pairs);
  tcase_add_test(tc, group_change_refinds_pairs);
  tcase_add_test(tc, body_beyond_max_length);
  tcase_add_test(tc, bodies_stop_at_the_edge_of_the_world);
  tcase_add_test(tc, derived_getters_stay_within_max_value);
  tcase_add_test(tc, summed_mass_saturates_at_max_value);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(body_suite)
