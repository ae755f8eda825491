/* A small C interface to Box2D 2.4.1 for the reference suites: worlds, dynamic
 * bodies, circle/polygon/box fixtures, forces and mass properties.
 *
 * The C suites cannot include Box2D's C++ headers, so everything they need goes
 * through these b2s_* functions (implemented in b2_shim.cpp). Box2D has no error
 * path of its own (bad input trips an assert inside the library), so the shim
 * checks polygon input first and reports a rejection by returning 0.
 *
 * Bodies are always dynamic and never fall asleep (tumble has no sleeping), so
 * a slow body keeps integrating exactly like tumble's. Other shim files may add
 * collision helpers; this one is about bodies and mass only. */
#ifndef TB_B2_SHIM_H
#define TB_B2_SHIM_H

#ifdef __cplusplus
extern "C" {
#endif

/* Box2D's b2_maxPolygonVertices. */
#define B2S_MAX_POLYGON_VERTICES 8

typedef struct b2s_world b2s_world; /* opaque: a b2World */
typedef struct b2s_body b2s_body;   /* opaque: a b2Body owned by its world */

/* Mass properties in double. inertia is about the centre of mass (tumble's
 * convention); inertia_origin is Box2D's own value, about the shape's or the
 * body's origin. inertia = inertia_origin - mass |center|^2, evaluated in double. */
typedef struct b2s_mass {
  double mass;
  double cx, cy;
  double inertia;
  double inertia_origin;
} b2s_mass;

typedef struct b2s_body_def {
  float x, y, angle; /* body origin and angle */
  float vx, vy, w;   /* linear velocity (of the centre of mass) and angular velocity */
  float linear_damping, angular_damping;
  float gravity_scale; /* default 1 */
  int fixed_rotation;  /* default 0 */
} b2s_body_def;

/* What the tests read back from a body, as Box2D stores it (float). */
typedef struct b2s_body_state {
  float x, y;   /* body origin */
  float angle;  /* the sweep angle (not wrapped) */
  float cx, cy; /* centre of mass, world */
  float vx, vy; /* velocity of the centre of mass */
  float w;
} b2s_body_state;

b2s_world* b2s_world_create(float gx, float gy);
void b2s_world_destroy(b2s_world* world);
/* One b2World::Step. */
void b2s_world_step(b2s_world* world, float dt, int velocity_iterations, int position_iterations);

b2s_body_def b2s_default_body_def(void);
/* A dynamic body with sleeping disabled; NULL on bad input. */
b2s_body* b2s_body_create(b2s_world* world, const b2s_body_def* def);

/* Fixtures; each recomputes the body's mass. Return 1 on success, 0 if rejected. */
int b2s_body_add_circle(b2s_body* body, float cx, float cy, float radius, float density);
/* xy holds count points (x0, y0, x1, y1, ...); Box2D takes their convex hull. */
int b2s_body_add_polygon(b2s_body* body, const float* xy, int count, float density);
int b2s_body_add_box(b2s_body* body, float hx, float hy, float cx, float cy, float angle, float density);

/* Forces act over the next step (Box2D clears them after every step). */
void b2s_body_apply_force(b2s_body* body, float fx, float fy, float px, float py);
void b2s_body_apply_force_to_center(b2s_body* body, float fx, float fy);
void b2s_body_apply_torque(b2s_body* body, float torque);
void b2s_body_apply_linear_impulse(b2s_body* body, float jx, float jy, float px, float py);
void b2s_body_apply_angular_impulse(b2s_body* body, float impulse);

void b2s_body_get_state(const b2s_body* body, b2s_body_state* out);
/* The body's mass, local centre of mass and inertia (see b2s_mass). */
void b2s_body_get_mass(const b2s_body* body, b2s_mass* out);

/* 1 if Box2D's b2PolygonShape::Set accepts the points without tripping one of
 * its asserts: 3..8 finite points, at least 3 left after Box2D's welding (at
 * 0.5 * b2_linearSlop), and an area clearly above b2_epsilon. */
int b2s_polygon_is_valid(const float* xy, int count);

/* Mass properties of the polygon Box2D builds from the points at a density
 * (b2PolygonShape::Set then ComputeMass). On success returns 1 and, when hull_xy
 * is not NULL, writes Box2D's hull vertices (counter-clockwise, at most
 * B2S_MAX_POLYGON_VERTICES pairs) and their number to *hull_count. Returns 0 if
 * the points are rejected (see b2s_polygon_is_valid). */
int b2s_polygon_mass(const float* xy, int count, float density, b2s_mass* out, float* hull_xy, int* hull_count);

#ifdef __cplusplus
}
#endif

#endif
