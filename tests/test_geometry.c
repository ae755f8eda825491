/* Mass properties against closed forms (relative error <= 1e-5).
 * Why 1e-5: inputs are floats (relative rounding 6e-8) and tumble integrates in
 * double, so the only error is the final rounding to float plus the rounding of
 * the inputs; 1e-5 leaves a margin of 100x for inputs of mixed magnitude. */
#include "test_util.h"

#define PI 3.14159265358979323846
#define TOL 1e-5

START_TEST(disc) {
  tb_circle c = {{0.3f, -0.2f}, 0.7f};
  tb_mass_data md = tb_compute_circle_mass(&c, 2.0f);
  double m = 2.0 * PI * 0.7 * 0.7;
  ck_assert_rel(md.mass, m, TOL);
  ck_assert_rel(md.rotational_inertia, 0.5 * m * 0.7 * 0.7, TOL);
  ck_assert_float_eq(md.center.x, 0.3f);
  ck_assert_float_eq(md.center.y, -0.2f);
}
END_TEST

/* Box of sides a, b: I = m (a^2 + b^2) / 12, also rotated and offset. */
START_TEST(box) {
  const float hx = 1.5f, hy = 0.25f;
  tb_polygon p;
  ck_assert_int_eq(tb_make_offset_box(hx, hy, (tb_vec2){2.0f, -3.0f}, 0.7f, &p), TB_OK);
  tb_mass_data md = tb_compute_polygon_mass(&p, 3.0f);
  double a = 2.0 * hx, b = 2.0 * hy, m = 3.0 * a * b;
  ck_assert_rel(md.mass, m, TOL);
  ck_assert_rel(md.rotational_inertia, m * (a * a + b * b) / 12.0, TOL);
  ck_assert_near(md.center.x, 2.0, 1e-6);
  ck_assert_near(md.center.y, -3.0, 1e-6);
}
END_TEST

/* Right triangle with legs a, b: m = rho a b / 2, I_c = m (a^2 + b^2) / 18. */
START_TEST(right_triangle) {
  const float a = 3.0f, b = 1.25f;
  tb_vec2 pts[3] = {{0.0f, 0.0f}, {a, 0.0f}, {0.0f, b}};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, 3, 0.0f, &p), TB_OK);
  tb_mass_data md = tb_compute_polygon_mass(&p, 1.0f);
  double m = 0.5 * a * b;
  ck_assert_rel(md.mass, m, TOL);
  ck_assert_rel(md.rotational_inertia, m * (a * a + b * b) / 18.0, TOL);
  ck_assert_near(md.center.x, a / 3.0, 1e-6);
  ck_assert_near(md.center.y, b / 3.0, 1e-6);
}
END_TEST

/* Regular n-gon of circumradius R: I = (m R^2 / 6)(1 + 2 cos^2(pi/n)),
 * area = n R^2 sin(2 pi / n) / 2. */
START_TEST(regular_ngon) {
  for (int n = 3; n <= TB_MAX_POLYGON_VERTICES; ++n) {
    const double R = 0.8;
    tb_vec2 pts[TB_MAX_POLYGON_VERTICES];
    for (int i = 0; i < n; ++i)
      pts[i] = (tb_vec2){(float)(R * cos(2.0 * PI * i / n + 0.3)), (float)(R * sin(2.0 * PI * i / n + 0.3))};
    tb_polygon p;
    ck_assert_int_eq(tb_make_polygon(pts, n, 0.0f, &p), TB_OK);
    ck_assert_int_eq(p.count, n);
    tb_mass_data md = tb_compute_polygon_mass(&p, 1.0f);
    double m = 0.5 * n * R * R * sin(2.0 * PI / n);
    double c = cos(PI / n);
    ck_assert_rel(md.mass, m, TOL);
    ck_assert_rel(md.rotational_inertia, m * R * R / 6.0 * (1.0 + 2.0 * c * c), TOL);
    ck_assert_near(md.center.x, 0.0, 1e-6);
    ck_assert_near(md.center.y, 0.0, 1e-6);
  }
}
END_TEST

/* Capsule: rectangle 2r x L plus a full disc split in two halves at +-L/2.
 * For the halves, |p|^2 integrated over a half disc offset by L/2 gives
 * m_d (L^2/4 + r^2/2) + m_d L (4 r / 3 pi) in total for both (m_d = rho pi r^2). */
START_TEST(capsule) {
  const double r = 0.3, L = 2.0;
  tb_capsule cap = {{-1.0f, 0.0f}, {1.0f, 0.0f}, 0.3f};
  tb_mass_data md = tb_compute_capsule_mass(&cap, 1.0f);
  double m_rect = 2.0 * r * L, m_disc = PI * r * r;
  double inertia =
      m_rect * (L * L + 4.0 * r * r) / 12.0 + m_disc * (L * L / 4.0 + r * r / 2.0) + m_disc * L * 4.0 * r / (3.0 * PI);
  ck_assert_rel(md.mass, m_rect + m_disc, TOL);
  ck_assert_rel(md.rotational_inertia, inertia, TOL);
  /* a tilted, offset capsule has the same mass properties about its centre */
  tb_capsule tilted = {{4.0f, 5.0f}, {4.0f + 2.0f * 0.6f, 5.0f + 2.0f * 0.8f}, 0.3f};
  tb_mass_data mt = tb_compute_capsule_mass(&tilted, 1.0f);
  ck_assert_rel(mt.rotational_inertia, inertia, TOL);
  ck_assert_near(mt.center.x, 4.6, 1e-6);
  ck_assert_near(mt.center.y, 5.8, 1e-6);
}
END_TEST

/* Rounded box: core 2hx x 2hy, four side slabs and four quarter discs. A
 * quarter disc at apex a has second moment about the box centre
 * m |a|^2 + 2 m a.c + m r^2/2, its centroid c at 4r/(3 pi) along both axes. */
START_TEST(rounded_box) {
  const double hx = 1.0, hy = 0.5, r = 0.2;
  tb_polygon p;
  ck_assert_int_eq(tb_make_rounded_box((float)hx, (float)hy, (float)r, &p), TB_OK);
  tb_mass_data md = tb_compute_polygon_mass(&p, 1.0f);
  double m_core = 4 * hx * hy, i_core = m_core * (4 * hx * hx + 4 * hy * hy) / 12.0;
  double m_tb = 2 * hx * r, i_tb = m_tb * (4 * hx * hx + r * r) / 12.0 + m_tb * (hy + r / 2) * (hy + r / 2);
  double m_lr = 2 * hy * r, i_lr = m_lr * (4 * hy * hy + r * r) / 12.0 + m_lr * (hx + r / 2) * (hx + r / 2);
  double m_q = PI * r * r / 4.0, d = 4.0 * r / (3.0 * PI);
  double i_q = m_q * (hx * hx + hy * hy) + 2.0 * m_q * (hx * d + hy * d) + m_q * r * r / 2.0;
  double mass = m_core + 2 * m_tb + 2 * m_lr + 4 * m_q;
  ck_assert_rel(md.mass, mass, TOL);
  ck_assert_rel(md.rotational_inertia, i_core + 2 * i_tb + 2 * i_lr + 4 * i_q, TOL);
  ck_assert_near(md.center.x, 0.0, 1e-6);
  ck_assert_near(md.center.y, 0.0, 1e-6);
}
END_TEST

/* Any rounded convex polygon has area A + P r + pi r^2 (Steiner's formula), and
 * a rounded equilateral triangle keeps its centroid at the centre. */
START_TEST(rounded_triangle_area) {
  const double R = 1.0, r = 0.25;
  tb_vec2 pts[3];
  for (int i = 0; i < 3; ++i) pts[i] = (tb_vec2){(float)(R * cos(2 * PI * i / 3)), (float)(R * sin(2 * PI * i / 3))};
  tb_polygon p;
  ck_assert_int_eq(tb_make_polygon(pts, 3, (float)r, &p), TB_OK);
  tb_mass_data md = tb_compute_polygon_mass(&p, 1.0f);
  double side = R * sqrt(3.0), area = sqrt(3.0) / 4.0 * side * side;
  ck_assert_rel(md.mass, area + 3 * side * r + PI * r * r, TOL);
  ck_assert_near(md.center.x, 0.0, 1e-6);
  ck_assert_near(md.center.y, 0.0, 1e-6);
  /* and its inertia lies between the core's and the circumscribing disc's */
  tb_polygon core = p;
  core.radius = 0.0f;
  ck_assert(md.rotational_inertia > tb_compute_polygon_mass(&core, 1.0f).rotational_inertia);
  ck_assert(md.rotational_inertia < 0.5 * md.mass * (R + r) * (R + r));
}
END_TEST

/* A body of several shapes: M = sum m_i, centre = mass-weighted centroids,
 * I about the centre = sum (I_i + m_i d_i^2) (parallel-axis theorem). */
START_TEST(compound_body) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){10.0f, 20.0f};
  bd.angle = 0.5f;
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_circle c = {{-1.0f, 0.0f}, 0.5f};
  ck_assert(!tb_shape_id_is_null(tb_create_circle_shape(b, &sd, &c)));
  tb_polygon box;
  tb_make_offset_box(1.0f, 0.5f, (tb_vec2){2.0f, 1.0f}, 0.0f, &box);
  sd.density = 2.0f;
  tb_shape_id box_shape = tb_create_polygon_shape(b, &sd, &box);
  ck_assert(!tb_shape_id_is_null(box_shape));

  double m1 = PI * 0.25, i1 = 0.5 * m1 * 0.25, x1 = -1, y1 = 0;
  double m2 = 2.0 * 2.0 * 1.0, i2 = m2 * (4.0 + 1.0) / 12.0, x2 = 2, y2 = 1;
  double m = m1 + m2, cx = (m1 * x1 + m2 * x2) / m, cy = (m1 * y1 + m2 * y2) / m;
  double inertia = i1 + m1 * ((x1 - cx) * (x1 - cx) + (y1 - cy) * (y1 - cy)) + i2 +
                   m2 * ((x2 - cx) * (x2 - cx) + (y2 - cy) * (y2 - cy));
  ck_assert_rel(tb_body_get_mass(b), m, TOL);
  ck_assert_rel(tb_body_get_rotational_inertia(b), inertia, TOL);
  tb_vec2 lc = tb_body_get_local_center(b);
  ck_assert_near(lc.x, cx, 1e-6);
  ck_assert_near(lc.y, cy, 1e-6);
  /* world centre = position + R(angle) local centre */
  tb_vec2 wc = tb_body_get_world_center(b);
  ck_assert_near(wc.x, 10.0 + cos(0.5) * cx - sin(0.5) * cy, 1e-5);
  ck_assert_near(wc.y, 20.0 + sin(0.5) * cx + cos(0.5) * cy, 1e-5);
  /* removing a shape recomputes: only the circle is left */
  ck_assert_int_eq(tb_destroy_shape(box_shape), TB_OK);
  ck_assert_rel(tb_body_get_mass(b), m1, TOL);
  ck_assert_rel(tb_body_get_rotational_inertia(b), i1, TOL);
  ck_assert_near(tb_body_get_local_center(b).x, -1.0, 1e-6);
  tb_destroy_world(w);
}
END_TEST

/* The same polygons 1e4 m from the origin lose no precision: the fan is taken
 * about a point inside the polygon, not about the origin. */
START_TEST(far_from_origin) {
  const float far = 1.0e4f;
  tb_polygon p;
  ck_assert_int_eq(tb_make_offset_box(0.5f, 0.25f, (tb_vec2){far, -far}, 0.0f, &p), TB_OK);
  tb_mass_data md = tb_compute_polygon_mass(&p, 1.0f);
  ck_assert_rel(md.mass, 0.5, TOL);
  ck_assert_rel(md.rotational_inertia, 0.5 * (1.0 + 0.25) / 12.0, TOL);
  ck_assert_near(md.center.x, far, 1e-3); /* one float step at 1e4 is 9.8e-4 */
  ck_assert_near(md.center.y, -far, 1e-3);

  tb_vec2 tri[3] = {{far, far}, {far + 3.0f, far}, {far, far + 1.25f}};
  ck_assert_int_eq(tb_make_polygon(tri, 3, 0.0f, &p), TB_OK);
  md = tb_compute_polygon_mass(&p, 1.0f);
  ck_assert_rel(md.mass, 0.5 * 3.0 * 1.25, TOL);
  ck_assert_rel(md.rotational_inertia, md.mass * (9.0 + 1.5625) / 18.0, TOL);
}
END_TEST

START_TEST(segment_has_no_mass) {
  tb_world_id w = tbt_world(0.0f, -10.0f);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  tb_body_id b = tb_create_body(w, &bd);
  tb_segment s = {{-1.0f, 0.0f}, {1.0f, 0.0f}};
  tb_shape_def sd = tb_default_shape_def();
  tb_shape_id sh = tb_create_segment_shape(b, &sd, &s);
  ck_assert(!tb_shape_id_is_null(sh));
  ck_assert_float_eq(tb_shape_get_mass_data(sh).mass, 0.0f);
  /* a dynamic body without area gets unit mass and no rotational inertia */
  ck_assert_float_eq(tb_body_get_mass(b), 1.0f);
  ck_assert_float_eq(tb_body_get_rotational_inertia(b), 0.0f);
  tb_destroy_world(w);
}
END_TEST

START_TEST(shape_aabb) {
  tb_world_id w = tbt_world(0.0f, 0.0f);
  tb_body_def bd = tb_default_body_def();
  bd.position = (tb_vec2){1.0f, 2.0f};
  bd.angle = (float)(PI / 2);
  tb_body_id b = tb_create_body(w, &bd);
  tb_shape_def sd = tb_default_shape_def();
  tb_polygon box;
  tb_make_rounded_box(2.0f, 1.0f, 0.1f, &box);
  tb_aabb a = tb_shape_get_aabb(tb_create_polygon_shape(b, &sd, &box));
  /* rotated a quarter turn: half extents swap, plus the rounding */
  ck_assert_near(a.lower.x, 1.0 - 1.1, 1e-5);
  ck_assert_near(a.upper.x, 1.0 + 1.1, 1e-5);
  ck_assert_near(a.lower.y, 2.0 - 2.1, 1e-5);
  ck_assert_near(a.upper.y, 2.0 + 2.1, 1e-5);
  tb_capsule cap = {{0.0f, 0.0f}, {1.0f, 0.0f}, 0.5f};
  a = tb_shape_get_aabb(tb_create_capsule_shape(b, &sd, &cap));
  ck_assert_near(a.lower.x, 0.5, 1e-5);
  ck_assert_near(a.upper.y, 3.5, 1e-5); /* (1, 0) maps to (1, 3), plus r */
  tb_destroy_world(w);
}
END_TEST

static Suite* geometry_suite(void) {
  Suite* s = suite_create("geometry");
  TCase* tc = tcase_create("mass");
  tcase_add_test(tc, disc);
  tcase_add_test(tc, box);
  tcase_add_test(tc, right_triangle);
  tcase_add_test(tc, regular_ngon);
  tcase_add_test(tc, capsule);
  tcase_add_test(tc, rounded_box);
  tcase_add_test(tc, rounded_triangle_area);
  tcase_add_test(tc, compound_body);
  tcase_add_test(tc, far_from_origin);
  tcase_add_test(tc, segment_has_no_mass);
  tcase_add_test(tc, shape_aabb);
  suite_add_tcase(s, tc);
  return s;
}

TB_TEST_MAIN(geometry_suite)
