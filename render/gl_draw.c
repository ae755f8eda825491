#include "gl_draw.h"

#include <GL/gl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "font.h"

#define PI_F 3.14159265358979f
/* Outline and line width in pixels: thin enough for 0.25 m boxes seen from
 * far, thick enough to read after the 4x multisample resolve. */
#define LINE_PIXELS 1.5f
/* Room for the outline of a rounded polygon: 8 corners of up to 24 arc points. */
#define MAX_LOOP 256

typedef struct vertex {
  float x, y;
  float r, g, b, a;
} vertex;

typedef struct batch {
  vertex* items;
  int count, capacity;
} batch;

struct tbr_gl {
  tbr_camera camera;
  float ppm; /* pixels per metre */
  batch world, screen;
  bool dropped; /* out of memory: some triangles were lost */
};

tbr_gl* tbr_gl_create(void) { return calloc(1, sizeof(tbr_gl)); }

void tbr_gl_destroy(tbr_gl* gl) {
  if (gl == NULL) return;
  free(gl->world.items);
  free(gl->screen.items);
  free(gl);
}

tb_color tbr_gl_fill_color(tb_color c) { return (tb_color){0.55f * c.r, 0.55f * c.g, 0.55f * c.b, c.a}; }

/* ---- batching ---------------------------------------------------------------- */

static void triangle(tbr_gl* gl, batch* b, tb_vec2 p0, tb_vec2 p1, tb_vec2 p2, tb_color c) {
  if (b->count + 3 > b->capacity) {
    int capacity = b->capacity ? 2 * b->capacity : 4096;
    vertex* items = realloc(b->items, sizeof *items * (size_t)capacity);
    if (items == NULL) {
      gl->dropped = true;
      return;
    }
    b->items = items;
    b->capacity = capacity;
  }
  tb_vec2 p[3] = {p0, p1, p2};
  for (int k = 0; k < 3; ++k) b->items[b->count++] = (vertex){p[k].x, p[k].y, c.r, c.g, c.b, c.a};
}

static void quad(tbr_gl* gl, batch* b, tb_vec2 p0, tb_vec2 p1, tb_vec2 p2, tb_vec2 p3, tb_color c) {
  triangle(gl, b, p0, p1, p2, c);
  triangle(gl, b, p0, p2, p3, c);
}

/* ---- geometry in world space ----------------------------------------------------- */

static tb_vec2 v2(float x, float y) { return (tb_vec2){x, y}; }
static tb_vec2 add(tb_vec2 a, tb_vec2 b) { return v2(a.x + b.x, a.y + b.y); }
static tb_vec2 sub(tb_vec2 a, tb_vec2 b) { return v2(a.x - b.x, a.y - b.y); }
static tb_vec2 scale(float s, tb_vec2 a) { return v2(s * a.x, s * a.y); }
static float dot(tb_vec2 a, tb_vec2 b) { return a.x * b.x + a.y * b.y; }
static tb_vec2 rotate(tb_rot q, tb_vec2 v) { return v2(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y); }
static tb_vec2 unit(tb_vec2 v) {
  float len = sqrtf(dot(v, v));
  return len > 0.0f ? scale(1.0f / len, v) : v2(1.0f, 0.0f);
}
/* Outward normal of the edge a -> b of a counter-clockwise loop. */
static tb_vec2 edge_normal(tb_vec2 a, tb_vec2 b) {
  tb_vec2 d = unit(sub(b, a));
  return v2(d.y, -d.x);
}

/* Arc points around centre from angle a0 to a1 (counter-clockwise), spaced so
 * that the chord error stays below a quarter pixel. */
static int arc(const tbr_gl* gl, tb_vec2 centre, float radius, float a0, float a1, tb_vec2* out, int room) {
  float sweep = a1 - a0;
  float pixels = radius * gl->ppm;
  int steps = (int)ceilf(sweep / (2.0f * acosf(fmaxf(0.0f, 1.0f - 0.25f / fmaxf(pixels, 0.25f))) + 1e-6f));
  if (steps < 1) steps = 1;
  if (steps > 48) steps = 48;
  if (steps + 1 > room) steps = room - 1;
  for (int k = 0; k <= steps; ++k) {
    float a = a0 + sweep * (float)k / (float)steps;
    out[k] = add(centre, v2(radius * cosf(a), radius * sinf(a)));
  }
  return steps + 1;
}

/* A convex counter-clockwise loop: filled with fill, outlined inside its edge
 * with outline. */
static void loop_shape(tbr_gl* gl, const tb_vec2* p, int n, tb_color fill, tb_color outline) {
  if (n < 3) return;
  tb_vec2 c = {0.0f, 0.0f};
  for (int i = 0; i < n; ++i) c = add(c, p[i]);
  c = scale(1.0f / (float)n, c);
  /* the outline is at most a third of the inradius, so tiny shapes stay solid */
  float inradius = INFINITY;
  for (int i = 0; i < n; ++i) {
    tb_vec2 a = p[i], b = p[(i + 1) % n];
    if (dot(sub(b, a), sub(b, a)) == 0.0f) continue;
    inradius = fminf(inradius, dot(sub(a, c), edge_normal(a, b)));
  }
  float width = fminf(LINE_PIXELS / gl->ppm, inradius / 3.0f);
  tb_vec2 inner[MAX_LOOP];
  for (int i = 0; i < n; ++i) {
    tb_vec2 prev = p[(i + n - 1) % n], next = p[(i + 1) % n];
    tb_vec2 n0 = edge_normal(prev, p[i]), n1 = edge_normal(p[i], next);
    float k = 1.0f + dot(n0, n1);
    inner[i] = k > 1e-3f ? sub(p[i], scale(width / k, add(n0, n1))) : sub(p[i], scale(width, n1));
  }
  for (int i = 0; i < n; ++i) triangle(gl, &gl->world, c, inner[i], inner[(i + 1) % n], fill);
  for (int i = 0; i < n; ++i) {
    int j = (i + 1) % n;
    quad(gl, &gl->world, p[i], p[j], inner[j], inner[i], outline);
  }
}

/* A line of LINE_PIXELS (times width_factor) with square ends. */
static void line(tbr_gl* gl, tb_vec2 a, tb_vec2 b, float width_factor, tb_color color) {
  float half = 0.5f * width_factor * LINE_PIXELS / gl->ppm;
  tb_vec2 d = scale(half, unit(sub(b, a)));
  tb_vec2 n = v2(-d.y, d.x);
  a = sub(a, d);
  b = add(b, d);
  quad(gl, &gl->world, sub(a, n), sub(b, n), add(b, n), add(a, n), color);
}

static void disc(tbr_gl* gl, tb_vec2 centre, float radius, tb_color color) {
  tb_vec2 p[MAX_LOOP];
  int n = arc(gl, centre, radius, 0.0f, 2.0f * PI_F, p, MAX_LOOP) - 1; /* the last point repeats the first */
  if (n < 8) n = arc(gl, centre, radius, 0.0f, 2.0f * PI_F, p, 9) - 1;
  for (int i = 0; i < n; ++i) triangle(gl, &gl->world, centre, p[i], p[(i + 1) % n], color);
}

/* ---- debug-draw callbacks -------------------------------------------------------- */

static void draw_solid_polygon(tb_transform xf, const tb_vec2* vertices, int count, float radius, tb_color color,
                               void* context) {
  tbr_gl* gl = context;
  if (count < 3 || count > TB_MAX_POLYGON_VERTICES) return;
  tb_vec2 w[TB_MAX_POLYGON_VERTICES];
  for (int i = 0; i < count; ++i) w[i] = add(xf.p, rotate(xf.q, vertices[i]));
  tb_vec2 loop[MAX_LOOP];
  int n = 0;
  if (radius <= 0.0f) {
    for (int i = 0; i < count; ++i) loop[n++] = w[i];
  } else {
    /* round each corner with an arc from the previous edge's normal to the next one's */
    const int room = MAX_LOOP / TB_MAX_POLYGON_VERTICES;
    for (int i = 0; i < count; ++i) {
      tb_vec2 n0 = edge_normal(w[(i + count - 1) % count], w[i]), n1 = edge_normal(w[i], w[(i + 1) % count]);
      float a0 = atan2f(n0.y, n0.x), a1 = atan2f(n1.y, n1.x);
      if (a1 < a0) a1 += 2.0f * PI_F;
      n += arc(gl, w[i], radius, a0, a1, loop + n, room);
    }
  }
  loop_shape(gl, loop, n, tbr_gl_fill_color(color), color);
}

static void draw_solid_circle(tb_transform xf, float radius, tb_color color, void* context) {
  tbr_gl* gl = context;
  tb_vec2 loop[MAX_LOOP];
  int n = arc(gl, xf.p, radius, 0.0f, 2.0f * PI_F, loop, MAX_LOOP) - 1;
  if (n < 12) n = arc(gl, xf.p, radius, 0.0f, 2.0f * PI_F, loop, 13) - 1;
  loop_shape(gl, loop, n, tbr_gl_fill_color(color), color);
  /* the rotation mark: a radius along the body's x axis */
  if (radius * gl->ppm >= 4.0f) line(gl, xf.p, add(xf.p, scale(radius, v2(xf.q.c, xf.q.s))), 1.0f, color);
}

static void draw_solid_capsule(tb_vec2 p1, tb_vec2 p2, float radius, tb_color color, void* context) {
  tbr_gl* gl = context;
  tb_vec2 d = unit(sub(p2, p1));
  float a = atan2f(d.y, d.x);
  tb_vec2 loop[MAX_LOOP];
  int n = arc(gl, p2, radius, a - 0.5f * PI_F, a + 0.5f * PI_F, loop, MAX_LOOP / 2);
  n += arc(gl, p1, radius, a + 0.5f * PI_F, a + 1.5f * PI_F, loop + n, MAX_LOOP / 2);
  loop_shape(gl, loop, n, tbr_gl_fill_color(color), color);
}

static void draw_segment(tb_vec2 p1, tb_vec2 p2, tb_color color, void* context) { line(context, p1, p2, 1.0f, color); }

static void draw_point(tb_vec2 p, float size, tb_color color, void* context) {
  tbr_gl* gl = context;
  disc(gl, p, 0.5f * size / gl->ppm, color);
}

static void draw_transform(tb_transform xf, void* context) {
  tbr_gl* gl = context;
  float length = 16.0f / gl->ppm; /* 16 pixels at any zoom */
  line(gl, xf.p, add(xf.p, scale(length, v2(xf.q.c, xf.q.s))), 1.0f, (tb_color){0.95f, 0.25f, 0.25f, 1.0f});
  line(gl, xf.p, add(xf.p, scale(length, v2(-xf.q.s, xf.q.c))), 1.0f, (tb_color){0.25f, 0.90f, 0.25f, 1.0f});
}

static void draw_string(tb_vec2 p, const char* text, tb_color color, void* context) {
  tbr_gl* gl = context;
  tb_vec2 px = tbr_camera_to_pixel(&gl->camera, p);
  tbr_gl_text(gl, px.x + 4.0f, px.y - 4.0f - TBR_FONT_HEIGHT, 1.0f, text, color);
}

tb_debug_draw tbr_gl_debug_draw(tbr_gl* gl) {
  tb_debug_draw d = tb_default_debug_draw();
  d.draw_solid_polygon = draw_solid_polygon;
  d.draw_solid_circle = draw_solid_circle;
  d.draw_solid_capsule = draw_solid_capsule;
  d.draw_segment = draw_segment;
  d.draw_point = draw_point;
  d.draw_transform = draw_transform;
  d.draw_string = draw_string;
  d.context = gl;
  d.use_drawing_bounds = true;
  d.drawing_bounds = tbr_camera_view(&gl->camera);
  d.normal_length = 24.0f / gl->ppm; /* 24 pixels */
  return d;
}

/* ---- frames ---------------------------------------------------------------------- */

void tbr_gl_begin(tbr_gl* gl, const tbr_camera* camera, tb_color background) {
  gl->camera = *camera;
  gl->ppm = tbr_camera_pixels_per_metre(camera);
  gl->world.count = 0;
  gl->screen.count = 0;
  gl->dropped = false;
  glViewport(0, 0, camera->width, camera->height);
  glClearColor(background.r, background.g, background.b, background.a);
  glClear(GL_COLOR_BUFFER_BIT);
}

void tbr_gl_rect(tbr_gl* gl, float x, float y, float width, float height, tb_color color) {
  quad(gl, &gl->screen, v2(x, y), v2(x + width, y), v2(x + width, y + height), v2(x, y + height), color);
}

void tbr_gl_text(tbr_gl* gl, float x, float y, float pixel, const char* text, tb_color color) {
  for (const char* s = text; *s != '\0'; ++s, x += TBR_FONT_ADVANCE * pixel) {
    const uint8_t* rows = tbr_font_glyph(*s);
    float top = y + (float)tbr_font_descent(*s) * pixel;
    for (int r = 0; r < TBR_FONT_HEIGHT; ++r) {
      for (int c = 0; c < TBR_FONT_WIDTH; ++c) {
        if (rows[r] & (0x10u >> c)) tbr_gl_rect(gl, x + (float)c * pixel, top + (float)r * pixel, pixel, pixel, color);
      }
    }
  }
}

/* The overlay's layout: font pixels scale with the image height (one per 360
 * rows: 2 at 720p, 1 for thumbnails), the title one larger. */
typedef struct overlay_layout {
  float small, big, pad, gap;
  int width, height; /* the image */
} overlay_layout;

static overlay_layout layout_for(int width, int height) {
  overlay_layout l;
  l.small = fmaxf(1.0f, floorf((float)height / 360.0f + 0.5f));
  l.big = l.small + 1.0f;
  l.pad = 4.0f * l.small;
  l.gap = 3.0f * l.small;
  l.width = width;
  l.height = height;
  return l;
}

/* Walks the wrapped pieces of the lines: draws them when gl is not NULL;
 * returns the panel's size (pads included); the panel's corner is at (pad, pad). */
static tb_vec2 overlay_walk(tbr_gl* gl, const overlay_layout* l, const char* const* lines, int count) {
  float x = 2.0f * l->pad, y = 2.0f * l->pad, text_width = 0.0f;
  for (int i = 0; i < count; ++i) {
    float px = i == 0 ? l->big : l->small;
    tb_color c = i == 0 ? (tb_color){1.0f, 1.0f, 1.0f, 1.0f} : (tb_color){0.78f, 0.80f, 0.85f, 1.0f};
    /* whole characters that fit between the panel's text margins */
    float room = (float)l->width - 4.0f * l->pad + (float)(TBR_FONT_ADVANCE - TBR_FONT_WIDTH) * px;
    int max_chars = (int)(room / ((float)TBR_FONT_ADVANCE * px));
    const char* text = lines[i];
    do {
      char piece[TBR_FONT_MAX_LINE + 1];
      int n = tbr_font_wrap(text, max_chars, piece, sizeof piece);
      text += n;
      text_width = fmaxf(text_width, (float)tbr_font_text_width(piece) * px);
      if (gl != NULL) tbr_gl_text(gl, x, y, px, piece, c);
      y += TBR_FONT_LINE_HEIGHT * px + l->gap;
    } while (*text != '\0');
  }
  return v2(text_width + 2.0f * l->pad, y - l->gap);
}

int tbr_gl_overlay_height(const char* const* lines, int count, int width, int height) {
  if (count <= 0) return 0;
  overlay_layout l = layout_for(width, height);
  return (int)ceilf(l.pad + overlay_walk(NULL, &l, lines, count).y);
}

void tbr_gl_overlay(tbr_gl* gl, const char* const* lines, int count) {
  if (count <= 0) return;
  overlay_layout l = layout_for(gl->camera.width, gl->camera.height);
  tb_vec2 size = overlay_walk(NULL, &l, lines, count);
  tbr_gl_rect(gl, l.pad, l.pad, size.x, size.y, (tb_color){0.0f, 0.0f, 0.0f, 0.55f});
  overlay_walk(gl, &l, lines, count);
}

static void draw_batch(const batch* b) {
  if (b->count == 0) return;
  glVertexPointer(2, GL_FLOAT, sizeof(vertex), &b->items[0].x);
  glColorPointer(4, GL_FLOAT, sizeof(vertex), &b->items[0].r);
  glDrawArrays(GL_TRIANGLES, 0, b->count);
}

bool tbr_gl_flush(tbr_gl* gl) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  tb_aabb view = tbr_camera_view(&gl->camera);
  glOrtho(view.lower.x, view.upper.x, view.lower.y, view.upper.y, -1.0, 1.0);
  draw_batch(&gl->world);
  glLoadIdentity();
  glOrtho(0.0, gl->camera.width, gl->camera.height, 0.0, -1.0, 1.0);
  draw_batch(&gl->screen);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  gl->world.count = 0;
  gl->screen.count = 0;
  bool ok = !gl->dropped;
  gl->dropped = false;
  return ok;
}
