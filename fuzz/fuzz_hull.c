/* libFuzzer harness: convex hulls and boxes from arbitrary points.
 *
 * tb_make_polygon either refuses the points with a documented error and a
 * message, or returns a polygon that is: 3..TB_MAX_POLYGON_VERTICES input points
 * (never invented ones), strictly convex and counter-clockwise, with unit
 * outward normals and its centroid inside, containing every input point (up to
 * the welding and collinearity slop), of positive finite mass, accepted by
 * tb_create_polygon_shape, and the same bits when made again. Boxes likewise. */
#include "fuzz_common.h"

static tb_world_id world;
static tb_body_id body;

static void init(void) {
  if (!tb_world_id_is_null(world)) return;
  tb_world_def wd = tb_default_world_def();
  world = tb_create_world(&wd);
  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  body = tb_create_body(world, &bd);
}

/* The polygon invariants; points may be NULL (boxes: no input points). */
static void check_polygon(const tb_polygon* p, const tb_vec2* points, int count, float radius) {
  int n = p->count;
  FUZZ_CHECK(n >= 3 && n <= TB_MAX_POLYGON_VERTICES, "count %d", n);
  FUZZ_CHECK(p->radius == radius, "radius %g", (double)p->radius);
  float scale = 0.0f;
  for (int i = 0; i < n; ++i) {
    FUZZ_CHECK(fuzz_vec_finite(p->vertices[i]), "vertex %d", i);
    scale = fmaxf(scale, fmaxf(fabsf(p->vertices[i].x), fabsf(p->vertices[i].y)));
    if (points != NULL) { /* a hull vertex is one of the input points, bit for bit */
      bool found = false;
      for (int k = 0; k < count && !found; ++k)
        found = p->vertices[i].x == points[k].x && p->vertices[i].y == points[k].y;
      FUZZ_CHECK(found, "vertex %d (%g, %g) is not an input point", i, (double)p->vertices[i].x,
                 (double)p->vertices[i].y);
    }
  }
  double area = 0.0;
  for (int i = 0; i < n; ++i) {
    tb_vec2 a = p->vertices[i], b = p->vertices[(i + 1) % n], c = p->vertices[(i + 2) % n];
    double ex = (double)b.x - a.x, ey = (double)b.y - a.y, fx = (double)c.x - b.x, fy = (double)c.y - b.y;
    FUZZ_CHECK(ex * fy - ey * fx > 0.0, "corner %d is not a strict left turn", (i + 1) % n);
    area += 0.5 * ((double)a.x * b.y - (double)a.y * b.x);
    tb_vec2 nrm = p->normals[i];
    double len = sqrt(ex * ex + ey * ey);
    FUZZ_CHECK(fabs((double)nrm.x * nrm.x + (double)nrm.y * nrm.y - 1.0) < 1e-5, "normal %d not unit", i);
    FUZZ_CHECK(fabs((nrm.x * ey - nrm.y * ex) / len - 1.0) < 1e-4, "normal %d is not the outward normal of its edge",
               i);
    /* the centroid is inside (the differences in double: in float they round
     * by half a step of the coordinates, 0.25 m at 4e6 m, more than a sliver's
     * width) */
    FUZZ_CHECK((double)nrm.x * ((double)p->centroid.x - a.x) + (double)nrm.y * ((double)p->centroid.y - a.y) < 0.0,
               "centroid outside edge %d", i);
  }
  if (points != NULL) {
    FUZZ_CHECK(area >= (double)TB_LINEAR_SLOP * TB_LINEAR_SLOP * 0.999, "area %g below slop^2", area);
    /* every input point is inside, up to the slop of welding (one slop) and of
     * dropping nearly collinear vertices (half a slop each), plus float
     * rounding of the edge's offset at this scale */
    double tol = 2.0 * TB_LINEAR_SLOP + 1e-6 * scale;
    for (int k = 0; k < count; ++k)
      for (int i = 0; i < n; ++i) {
        double d = (double)p->normals[i].x * ((double)points[k].x - p->vertices[i].x) +
                   (double)p->normals[i].y * ((double)points[k].y - p->vertices[i].y);
        FUZZ_CHECK(d <= tol, "input point %d lies %g m outside edge %d", k, d, i);
      }
  }
  tb_mass_data md = tb_compute_polygon_mass(p, 1.0f);
  FUZZ_CHECK(isfinite(md.mass) && md.mass > 0.0f, "mass %g (%s)", (double)md.mass, tb_last_error());
  FUZZ_CHECK(isfinite(md.rotational_inertia) && md.rotational_inertia >= 0.0f, "inertia %g",
             (double)md.rotational_inertia);
  FUZZ_CHECK(fuzz_vec_finite(md.center), "mass centre not finite");
  tb_shape_def sd = tb_default_shape_def();
  sd.density = 1e-6f; /* keeps the mass in range for polygons up to TB_MAX_LENGTH */
  tb_shape_id s = tb_create_polygon_shape(body, &sd, p);
  FUZZ_CHECK(!tb_shape_id_is_null(s) || tb_last_result() == TB_ERR_INVALID_ARGUMENT,
             "a polygon tumble made is refused: %s", tb_last_error());
  if (!tb_shape_id_is_null(s)) FUZZ_CHECK(tb_destroy_shape(s) == TB_OK, "destroy: %s", tb_last_error());
}

static void check_refusal(tb_result r) {
  FUZZ_CHECK(r == TB_ERR_DEGENERATE_POLYGON || r == TB_ERR_TOO_MANY_VERTICES || r == TB_ERR_INVALID_ARGUMENT,
             "unexpected %s", tb_result_name(r));
  FUZZ_CHECK(tb_last_result() == r && strlen(tb_last_error()) > 0, "no message for %s", tb_result_name(r));
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  init();
  fuzz_input in = {data, size, 0};
  uint8_t mode = fuzz_u8(&in);
  tb_vec2 points[24];
  int count = 0;
  if (mode & 1) { /* raw float bits: NaN, infinities, huge and tiny values */
    while (count < 24 && in.size - in.at >= 8) {
      memcpy(&points[count], in.data + in.at, 8);
      in.at += 8;
      count += 1;
    }
  } else { /* a grid at one of several scales, from a millimetre to kilometres */
    static const float scales[4] = {1e-4f, 1e-3f, 1e-2f, 1.0f};
    float scale = scales[(mode >> 1) & 3];
    float offset = (mode & 8) ? 1000.0f : 0.0f;
    while (count < 24 && in.size - in.at >= 4) {
      int16_t x, y;
      memcpy(&x, in.data + in.at, 2);
      memcpy(&y, in.data + in.at + 2, 2);
      in.at += 4;
      points[count++] = (tb_vec2){offset + scale * x, offset + scale * y};
    }
  }
  float radius = (mode & 16) ? 0.05f : 0.0f;

  tb_polygon p, again;
  tb_clear_error();
  tb_result r = tb_make_polygon(points, count, radius, &p);
  if (r != TB_OK) {
    check_refusal(r);
  } else {
    check_polygon(&p, points, count, radius);
    memset(&again, 0, sizeof again);
    FUZZ_CHECK(tb_make_polygon(points, count, radius, &again) == TB_OK && memcmp(&p, &again, sizeof p) == 0,
               "not deterministic");
  }

  /* a box from the first point's bits: half extents, centre, angle */
  if (count >= 2) {
    float hx = fabsf(points[0].x), hy = fabsf(points[0].y);
    if (!(mode & 1)) hx += 0.001f, hy += 0.001f;
    tb_clear_error();
    r = tb_make_offset_box(hx, hy, points[1], (mode & 32) ? points[0].x : 0.0f, &p);
    if (r != TB_OK)
      check_refusal(r);
    else
      check_polygon(&p, NULL, 0, 0.0f);
  }
  return 0;
}
