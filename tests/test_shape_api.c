/* One shape's geometry in the world (issue 24): point tests, ray casts and
 * closest points on a single shape against closed forms, on rotated and
 * offset bodies; replacing a shape's geometry in place (mass, broad phase,
 * contacts, sleep, type change) and the refusals that leave the world as it
 * was. */
#include <string.h>

#include "test_util.h"

#define PI_F 3.14159265358979f

/* Coordinates here are a few metres; a rotation by cosf/sinf and a transform
 * round each coordinate to about 4 ulp of 10 m (4e-6 m). 2e-5 m leaves room
 * for the ray and GJK arithmetic on top, and is far below any of the
 * differences the tests look at (>= 1 cm). */
#define TOL 2e-5

#define assert_vec_near(got, want, tol)     \
  do {                                      \
    ck_assert_near((got).x, (want).x, tol); \
    ck_assert_near((got).y, (want).y, tol); \
  } while (0)

static tb_vec2 world_of(tb_transform xf, tb_vec2 local) {
  return (tb_vec2){xf.p.x + xf.q.c * local.x - xf.q.s * local.y, xf.p.y + xf.q.s * local.x + xf.q.c * local.y};
}
static tb_vec2 rotate(tb_transform xf, tb_vec2 v) {
  return (tb_vec2){xf.q.c * v.x - xf.q.s * v.y, xf.q.s * v.x + xf.q.c * v.y};
}

static tb_body_id make_body(tb_world_id w, tb_body_type type, float x, float y, float angle) {
  tb_body_def bd = tb_default_body_def();
  bd.type = type;
  bd.position = (tb_vec2){x, y};
  bd.angle = angle;
  tb_body_id b = tb_create_body(w, &bd);
  ck_assert(!tb_body_id_is_null(b));
  return b;
}

static tb_shape_id add_box(tb_body_id b, float hx, float hy, float density) {
  tb_polygon box;
  ck_assert_int_eq(tb_make_box(hx, hy, &box), TB_OK);
  tb_shape_def sd = tb_default_shape_def();
  sd.density = density;
  tb_shape_id s = tb_create_polygon_shape(b, &sd, &box);
  ck_assert(!tb_shape_id_is_null(s));
  return s;
}

static tb_shape_id add_circle(tb_body_id b, tb_vec2 center, float r) {
  tb_circle c = {center, r};
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id s = tb_create_circle_shape(b, &sd, &c);
  ck_assert(!tb_shape_id_is_null(s));
  return s;
}

/* ---- point tests ----------------------------------------------------------- */

START_TEST(test_point_on_a_rotated_box) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 3.0f, 2.0f, PI_F / 6.0f);
  tb_shape_id box = add_box(b, 1.0f, 0.5f, 1.0f);
  tb_transform xf = tb_body_get_transform(b);
  /* inside and outside by 0.01 m or more in the box's own frame */
  const tb_vec2 inside[] = {{0, 0}, {0.99f, 0.49f}, {-0.99f, -0.49f}, {0, 0.49f}};
  const tb_vec2 outside[] = {{1.01f, 0}, {0, 0.51f}, {-1.01f, 0.2f}, {1.0f, 0.6f}};
  for (int i = 0; i < 4; ++i) {
    ck_assert_msg(tb_shape_test_point(box, world_of(xf, inside[i])), "inside %d", i);
    ck_assert_msg(!tb_shape_test_point(box, world_of(xf, outside[i])), "outside %d", i);
  }
  /* the world point (3.9, 2.0) lies at local (0.78, -0.45): inside, though
   * the unrotated box would hold it too; (3.0, 2.7) is local (0.35, 0.61): out */
  ck_assert(tb_shape_test_point(box, (tb_vec2){3.9f, 2.0f}));
  ck_assert(!tb_shape_test_point(box, (tb_vec2){3.0f, 2.7f}));
  /* a segment contains nothing, even its own points */
  tb_segment seg = {{-1, 2}, {1, 2}};
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id s = tb_create_segment_shape(b, &sd, &seg);
  ck_assert(!tb_shape_test_point(s, world_of(xf, (tb_vec2){0, 2})));
  /* a disabled body's shape is still tested (world queries skip it) */
  ck_assert_int_eq(tb_body_set_enabled(b, false), TB_OK);
  ck_assert(tb_shape_test_point(box, world_of(xf, (tb_vec2){0.5f, 0})));
  tb_destroy_world(w);
}
END_TEST

/* ---- ray casts ------------------------------------------------------------- */

START_TEST(ray_against_a_box_on_a_rotated_body) {
  tb_world_id w = tbt_world(0, 0);
  const float angle = PI_F / 6.0f;
  tb_body_id b = make_body(w, TB_STATIC_BODY, 2.0f, 1.0f, angle);
  tb_shape_id box = add_box(b, 1.0f, 0.5f, 1.0f);
  tb_transform xf = tb_body_get_transform(b);
  /* in the box's frame the ray runs from (-3, 0.2) along +x for 6 m: it enters
   * the face x = -1 at fraction 2/6, point (-1, 0.2), normal (-1, 0) */
  tb_vec2 origin = world_of(xf, (tb_vec2){-3.0f, 0.2f}), translation = rotate(xf, (tb_vec2){6.0f, 0.0f});
  tb_ray_result r = tb_shape_ray_cast(box, origin, translation);
  ck_assert(r.hit);
  ck_assert(r.shape.index1 == box.index1 && r.shape.generation == box.generation);
  ck_assert_near(r.fraction, 1.0 / 3.0, TOL / 6.0); /* a length error over the 6 m ray */
  tb_vec2 p = world_of(xf, (tb_vec2){-1.0f, 0.2f}), n = rotate(xf, (tb_vec2){-1.0f, 0.0f});
  assert_vec_near(r.point, p, TOL);
  assert_vec_near(r.normal, n, TOL);
  /* the same ray cast down from above, along local -y: enters y = 0.5 at 1/4 */
  r = tb_shape_ray_cast(box, world_of(xf, (tb_vec2){0.3f, 1.5f}), rotate(xf, (tb_vec2){0.0f, -4.0f}));
  ck_assert(r.hit);
  ck_assert_near(r.fraction, 0.25, TOL / 4.0);
  n = rotate(xf, (tb_vec2){0.0f, 1.0f});
  assert_vec_near(r.normal, n, TOL);
  /* too short (ends 0.1 m before the face), passing beside, starting inside */
  r = tb_shape_ray_cast(box, origin, rotate(xf, (tb_vec2){1.9f, 0.0f}));
  ck_assert(!r.hit && r.fraction == 1.0f && tb_shape_id_is_null(r.shape));
  r = tb_shape_ray_cast(box, world_of(xf, (tb_vec2){-3.0f, 0.6f}), translation);
  ck_assert(!r.hit);
  r = tb_shape_ray_cast(box, world_of(xf, (tb_vec2){0.0f, 0.0f}), translation);
  ck_assert(!r.hit);
  /* the ray sees the shape alone: another shape in front of it does not matter */
  add_circle(b, (tb_vec2){-2.0f, 0.2f}, 0.3f);
  r = tb_shape_ray_cast(box, origin, translation);
  ck_assert(r.hit);
  ck_assert_near(r.fraction, 1.0 / 3.0, TOL / 6.0);
  tb_destroy_world(w);
}
END_TEST

START_TEST(ray_against_circles_capsules_and_chains) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_id b = make_body(w, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f);
  /* circle of radius 1 at (5, 0): a ray along +x from the origin enters at x = 4 */
  tb_shape_id c = add_circle(b, (tb_vec2){5.0f, 0.0f}, 1.0f);
  tb_ray_result r = tb_shape_ray_cast(c, (tb_vec2){0, 0}, (tb_vec2){10, 0});
  ck_assert(r.hit);
  ck_assert_near(r.fraction, 0.4, TOL / 10.0);
  ck_assert_near(r.point.x, 4.0, TOL);
  ck_assert_near(r.normal.x, -1.0, TOL);
  /* a ray at height 0.6 enters where x = 5 - sqrt(1 - 0.36) = 4.2, normal (-0.8, 0.6) */
  r = tb_shape_ray_cast(c, (tb_vec2){0, 0.6f}, (tb_vec2){10, 0});
  ck_assert(r.hit);
  ck_assert_near(r.point.x, 4.2, TOL);
  ck_assert_near(r.normal.x, -0.8, TOL);
  ck_assert_near(r.normal.y, 0.6, TOL);
  /* a capsule from (0, 3) to (4, 3), radius 0.5, hit from above at x = 2: y = 3.5 */
  tb_capsule cap = {{0, 3}, {4, 3}, 0.5f};
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id k = tb_create_capsule_shape(b, &sd, &cap);
  r = tb_shape_ray_cast(k, (tb_vec2){2, 10}, (tb_vec2){0, -10});
  ck_assert(r.hit);
  ck_assert_near(r.point.y, 3.5, TOL);
  ck_assert_near(r.fraction, 0.65, TOL / 10.0);
  /* a chain from (-5, -2) to (5, -2) faces up (left of its direction): hit
   * from above, not from below */
  const tb_vec2 pts[2] = {{-5, -2}, {5, -2}};
  tb_chain_def cd = tb_default_chain_def();
  cd.points = pts;
  cd.count = 2;
  tb_chain_id chain = tb_create_chain(b, &cd);
  tb_shape_id seg;
  ck_assert_int_eq(tb_chain_get_segments(chain, &seg, 1), 1);
  r = tb_shape_ray_cast(seg, (tb_vec2){1, 0}, (tb_vec2){0, -4});
  ck_assert(r.hit);
  ck_assert_near(r.fraction, 0.5, TOL / 4.0);
  ck_assert_near(r.normal.y, 1.0, TOL);
  r = tb_shape_ray_cast(seg, (tb_vec2){1, -4}, (tb_vec2){0, 4});
  ck_assert(!r.hit);
  tb_destroy_world(w);
}
END_TEST

/* ---- closest points ---------------------------------------------------------- */

START_TEST(closest_point_on_a_capsule) {
  tb_world_id w = tbt_world(0, 0);
  /* a capsule from local (-1, 0) to (1, 0), radius 0.5, on a body at (0, 5)
   * turned a quarter turn: its axis runs along world y */
  tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 0.0f, 5.0f, 0.5f * PI_F);
  tb_capsule cap = {{-1, 0}, {1, 0}, 0.5f};
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id k = tb_create_capsule_shape(b, &sd, &cap);
  tb_transform xf = tb_body_get_transform(b);
  /* beyond the end: local target (3, 2) is nearest the core end (1, 0), and
   * the surface lies 0.5 from it towards the target: (1, 0) + 0.5 (2, 2)/sqrt(8) */
  float h = 0.5f / sqrtf(2.0f);
  tb_vec2 got = tb_shape_get_closest_point(k, world_of(xf, (tb_vec2){3, 2}));
  tb_vec2 want = world_of(xf, (tb_vec2){1.0f + h, h});
  assert_vec_near(got, want, TOL);
  /* beside the middle: straight across, local (0.3, 2) -> (0.3, 0.5) */
  got = tb_shape_get_closest_point(k, world_of(xf, (tb_vec2){0.3f, 2.0f}));
  want = world_of(xf, (tb_vec2){0.3f, 0.5f});
  assert_vec_near(got, want, TOL);
  /* inside the rounding (0.45 from the core) and inside the core: the target itself */
  tb_vec2 in = world_of(xf, (tb_vec2){0.2f, 0.45f});
  got = tb_shape_get_closest_point(k, in);
  ck_assert(got.x == in.x && got.y == in.y);
  in = world_of(xf, (tb_vec2){-0.5f, 0.0f});
  got = tb_shape_get_closest_point(k, in);
  ck_assert(got.x == in.x && got.y == in.y);
  tb_destroy_world(w);
}
END_TEST

START_TEST(closest_point_on_boxes_circles_and_segments) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_id b = make_body(w, TB_STATIC_BODY, 1.0f, -2.0f, PI_F / 3.0f);
  tb_transform xf = tb_body_get_transform(b);
  tb_shape_id box = add_box(b, 1.0f, 0.5f, 1.0f);
  /* local (3, 0.2) -> face point (1, 0.2); local (2, 3) -> corner (1, 0.5) */
  tb_vec2 got = tb_shape_get_closest_point(box, world_of(xf, (tb_vec2){3, 0.2f}));
  tb_vec2 want = world_of(xf, (tb_vec2){1, 0.2f});
  assert_vec_near(got, want, TOL);
  got = tb_shape_get_closest_point(box, world_of(xf, (tb_vec2){2, 3}));
  want = world_of(xf, (tb_vec2){1, 0.5f});
  assert_vec_near(got, want, TOL);
  /* a circle of radius 2 at local (5, 0): target local (5, 7) -> (5, 2) */
  tb_shape_id c = add_circle(b, (tb_vec2){5, 0}, 2.0f);
  got = tb_shape_get_closest_point(c, world_of(xf, (tb_vec2){5, 7}));
  want = world_of(xf, (tb_vec2){5, 2});
  assert_vec_near(got, want, TOL);
  /* a segment: the nearest point of the segment, also for a point on its line */
  tb_segment seg = {{-4, 4}, {-2, 4}};
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id s = tb_create_segment_shape(b, &sd, &seg);
  got = tb_shape_get_closest_point(s, world_of(xf, (tb_vec2){-3, 6}));
  want = world_of(xf, (tb_vec2){-3, 4});
  assert_vec_near(got, want, TOL);
  got = tb_shape_get_closest_point(s, world_of(xf, (tb_vec2){0, 4}));
  want = world_of(xf, (tb_vec2){-2, 4});
  assert_vec_near(got, want, TOL);
  tb_destroy_world(w);
}
END_TEST

/* ---- replacing geometry ------------------------------------------------------ */

static bool count_hit(tb_shape_id shape, void* context) {
  (void)shape;
  *(int*)context += 1;
  return true;
}

static int shapes_at(tb_world_id w, tb_vec2 p) {
  int n = 0;
  ck_assert_int_eq(tb_world_overlap_point(w, p, tb_default_query_filter(), count_hit, &n), TB_OK);
  return n;
}

START_TEST(set_circle_recomputes_mass_and_keeps_the_handle) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 1.0f, 2.0f, 0.0f);
  tb_shape_id s = add_box(b, 1.0f, 1.0f, 2.0f);
  int marker = 0;
  ck_assert_int_eq(tb_shape_set_user_data(s, &marker), TB_OK);
  ck_assert_int_eq(tb_shape_set_friction(s, 0.25f), TB_OK);
  /* box 2 x 2 at density 2: 8 kg */
  ck_assert_near(tb_body_get_mass(b), 8.0, 1e-5);
  tb_circle c = {{0.5f, 0.0f}, 0.3f};
  ck_assert_int_eq(tb_shape_set_circle(s, &c), TB_OK);
  ck_assert_int_eq(tb_shape_get_type(s), TB_SHAPE_CIRCLE);
  tb_circle back;
  ck_assert_int_eq(tb_shape_get_circle(s, &back), TB_OK);
  ck_assert(memcmp(&back, &c, sizeof c) == 0);
  tb_polygon none;
  ck_assert_int_ne(tb_shape_get_polygon(s, &none), TB_OK);
  /* m = pi r^2 rho, centre at the circle's, I = m r^2 / 2 about it (float
   * rounding of the double computation: 1e-6 relative) */
  double m = 3.14159265358979 * 0.09 * 2.0;
  ck_assert_rel(tb_body_get_mass(b), m, 1e-6);
  ck_assert_near(tb_body_get_local_center(b).x, 0.5, 1e-7);
  ck_assert_near(tb_body_get_local_center(b).y, 0.0, 1e-7);
  ck_assert_rel(tb_body_get_rotational_inertia(b), 0.5 * m * 0.09, 1e-6);
  /* the material, filter and user data stay */
  ck_assert_ptr_eq(tb_shape_get_user_data(s), &marker);
  ck_assert_near(tb_shape_get_friction(s), 0.25, 0.0);
  ck_assert_near(tb_shape_get_density(s), 2.0, 0.0);
  /* the bounding box and the broad phase follow at once, without a step:
   * the circle spans x in [1.2, 1.8] about (1.5, 2) */
  tb_aabb box = tb_shape_get_aabb(s);
  ck_assert_near(box.lower.x, 1.2, 1e-6);
  ck_assert_near(box.upper.x, 1.8, 1e-6);
  ck_assert_near(box.upper.y, 2.3, 1e-6);
  ck_assert_int_eq(shapes_at(w, (tb_vec2){1.5f, 2.25f}), 1);
  ck_assert_int_eq(shapes_at(w, (tb_vec2){0.2f, 2.0f}), 0); /* inside the old box only */
  /* and back to a polygon: a 1 x 3 box offset to (0, 1) at density 2: 6 kg,
   * I = m (1 + 9) / 12 about its centre */
  tb_polygon p;
  ck_assert_int_eq(tb_make_offset_box(0.5f, 1.5f, (tb_vec2){0, 1}, 0.0f, &p), TB_OK);
  ck_assert_int_eq(tb_shape_set_polygon(s, &p), TB_OK);
  ck_assert_int_eq(tb_shape_get_type(s), TB_SHAPE_POLYGON);
  ck_assert_rel(tb_body_get_mass(b), 6.0, 1e-6);
  ck_assert_near(tb_body_get_local_center(b).y, 1.0, 1e-6);
  ck_assert_rel(tb_body_get_rotational_inertia(b), 6.0 * 10.0 / 12.0, 1e-5);
  /* a capsule from (0, 0) to (2, 0), radius 0.5: rectangle 2 x 1 plus a disc,
   * m = rho (2 + pi/4) */
  tb_capsule cap = {{0, 0}, {2, 0}, 0.5f};
  ck_assert_int_eq(tb_shape_set_capsule(s, &cap), TB_OK);
  ck_assert_int_eq(tb_shape_get_type(s), TB_SHAPE_CAPSULE);
  ck_assert_rel(tb_body_get_mass(b), 2.0 * (2.0 + 3.14159265358979 / 4.0), 1e-6);
  ck_assert_near(tb_body_get_local_center(b).x, 1.0, 1e-6);
  /* a segment has no area: the body falls back to the default mass of 1 */
  tb_segment seg = {{-1, 0}, {1, 0}};
  ck_assert_int_eq(tb_shape_set_segment(s, &seg), TB_OK);
  ck_assert_int_eq(tb_shape_get_type(s), TB_SHAPE_SEGMENT);
  ck_assert_near(tb_body_get_mass(b), 1.0, 0.0);
  ck_assert(tb_shape_is_valid(s));
  ck_assert_int_eq(tb_body_get_shape_count(b), 1);
  tb_destroy_world(w);
}
END_TEST

/* A ball resting on the ground is made larger: its contact ends, the broad
 * phase finds it again and the ball rests on its new radius. A body on top of
 * a static shape that shrinks away wakes and falls. */
START_TEST(set_geometry_refreshes_contacts) {
  tb_world_id w = tbt_world(0, -10);
  tb_body_id ground = make_body(w, TB_STATIC_BODY, 0.0f, 0.0f, 0.0f);
  tb_polygon floor;
  tb_make_offset_box(10.0f, 0.5f, (tb_vec2){0.0f, -0.5f}, 0.0f, &floor);
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id floor_shape = tb_create_polygon_shape(ground, &sd, &floor);
  tb_body_id ball = make_body(w, TB_DYNAMIC_BODY, 0.0f, 0.5f, 0.0f);
  tb_shape_id disc = add_circle(ball, (tb_vec2){0, 0}, 0.5f);
  for (int i = 0; i < 60; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_body_get_contact_capacity(ball), 1);
  /* resting: sunk less than the linear slop (0.005 m) */
  ck_assert_near(tb_body_get_position(ball).y, 0.5, 0.005);
  tb_circle big = {{0, 0}, 1.0f};
  ck_assert_int_eq(tb_shape_set_circle(disc, &big), TB_OK);
  ck_assert_int_eq(tb_body_get_contact_capacity(ball), 0); /* ended; found again by the next step */
  ck_assert(tb_body_is_awake(ball));
  tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_int_eq(tb_body_get_contact_capacity(ball), 1);
  /* the new disc overlaps the floor by 0.5 m; the solver pushes it out */
  for (int i = 0; i < 120; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_near(tb_body_get_position(ball).y, 1.0, 0.005);
  /* let it sleep, then shrink the floor from under it: it wakes and falls */
  for (int i = 0; i < 120 && tb_body_is_awake(ball); ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert(!tb_body_is_awake(ball));
  tb_polygon far_floor;
  tb_make_offset_box(1.0f, 0.5f, (tb_vec2){20.0f, -0.5f}, 0.0f, &far_floor);
  ck_assert_int_eq(tb_shape_set_polygon(floor_shape, &far_floor), TB_OK);
  ck_assert(tb_body_is_awake(ball));
  for (int i = 0; i < 30; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  ck_assert_msg(tb_body_get_position(ball).y < 0.0f, "the ball stayed up: y = %g",
                (double)tb_body_get_position(ball).y);
  tb_destroy_world(w);
}
END_TEST

/* A disabled body has no proxies; its shape's new geometry is what enabling
 * it puts into the broad phase. */
START_TEST(set_geometry_on_a_disabled_body) {
  tb_world_id w = tbt_world(0, 0);
  tb_body_id b = make_body(w, TB_DYNAMIC_BODY, 0.0f, 0.0f, 0.0f);
  tb_shape_id s = add_circle(b, (tb_vec2){0, 0}, 0.5f);
  ck_assert_int_eq(tb_body_set_enabled(b, false), TB_OK);
  tb_circle c = {{3, 0}, 0.5f};
  ck_assert_int_eq(tb_shape_set_circle(s, &c), TB_OK);
  ck_assert_int_eq(shapes_at(w, (tb_vec2){3, 0}), 0);
  ck_assert_int_eq(tb_body_set_enabled(b, true), TB_OK);
  ck_assert_int_eq(shapes_at(w, (tb_vec2){3, 0}), 1);
  ck_assert_int_eq(shapes_at(w, (tb_vec2){0, 0}), 0);
  tb_destroy_world(w);
}
END_TEST

/* Two worlds built and changed by the same calls hash the same, also after
 * steps: the change is deterministic. */
static tb_world_id built_and_changed(void) {
  tb_world_id w = tbt_world(0, -10);
  tb_body_id ground = make_body(w, TB_STATIC_BODY, 0, 0, 0);
  add_box(ground, 10.0f, 0.5f, 1.0f);
  tb_body_id a = tbt_box_body(w, 0.0f, 1.0f, 0.5f, 0.5f);
  tb_body_id b = tbt_box_body(w, 0.2f, 2.0f, 0.5f, 0.5f);
  for (int i = 0; i < 30; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  tb_shape_id s;
  tb_body_get_shapes(a, &s, 1);
  tb_capsule cap = {{-0.6f, 0}, {0.6f, 0}, 0.4f};
  ck_assert_int_eq(tb_shape_set_capsule(s, &cap), TB_OK);
  tb_body_get_shapes(b, &s, 1);
  tb_circle c = {{0, 0}, 0.6f};
  ck_assert_int_eq(tb_shape_set_circle(s, &c), TB_OK);
  for (int i = 0; i < 60; ++i) tb_world_step(w, 1.0f / 60.0f, 4);
  return w;
}

START_TEST(set_geometry_is_deterministic) {
  tb_world_id w1 = built_and_changed(), w2 = built_and_changed();
  ck_assert(tb_world_hash(w1) == tb_world_hash(w2));
  tb_destroy_world(w1);
  tb_destroy_world(w2);
}
END_TEST

static Suite* shape_api_suite(void) {
  Suite* s = suite_create("shape_api");
  TCase* tc = tcase_create("shape_api");
  tcase_add_test(tc, test_point_on_a_rotated_box);
  tcase_add_test(tc, ray_against_a_box_on_a_rotated_body);
  tcase_add_test(tc, ray_against_circles_capsules_and_chains);
  tcase_add_test(tc, closest_point_on_a_capsule);
  tcase_add_test(tc, closest_point_on_boxes_circles_and_segments);
  tcase_add_test(tc, set_circle_recomputes_mass_and_keeps_the_handle);
  tcase_add_test(tc, set_geometry_refreshes_contacts);
  tcase_add_test(tc, set_geometry_on_a_disabled_body);
  tcase_add_test(tc, set_geometry_is_deterministic);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(shape_api_suite)
