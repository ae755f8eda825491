/* A C interface to Box2D 2.4.1 for the dynamics reference suite: worlds with
 * static, kinematic and dynamic bodies, box/circle/edge fixtures with their
 * material (density, friction, restitution), revolute joints, stepping and
 * reading a body's state back.
 *
 * The C suites cannot include Box2D's C++ headers, so everything goes through
 * these b2y_* functions (implemented in b2_dynamics_shim.cpp). Box2D has no
 * error path of its own (bad input trips an assert inside the library), so the
 * shim checks its input and reports a rejection by returning 0 or NULL.
 *
 * Box2D's polygons and edges carry a skin of b2_polygonRadius (B2Y_POLYGON_RADIUS,
 * 0.01 m) around their core: a polygon's surface is 0.01 m outside the
 * vertices given, and the position solver lets surfaces overlap by
 * b2_linearSlop (B2Y_LINEAR_SLOP, 0.005 m). Circles have no skin. */
#ifndef TB_B2_DYNAMICS_SHIM_H
#define TB_B2_DYNAMICS_SHIM_H

#ifdef __cplusplus
extern "C" {
#endif

#define B2Y_POLYGON_RADIUS 0.01f
#define B2Y_LINEAR_SLOP 0.005f

typedef struct b2y_world b2y_world; /* opaque: a b2World */
typedef struct b2y_body b2y_body;   /* opaque: a b2Body owned by its world */

typedef enum b2y_body_type { B2Y_STATIC = 0, B2Y_KINEMATIC = 1, B2Y_DYNAMIC = 2 } b2y_body_type;

/* A fixture's material; restitution_threshold is Box2D 2.4.1's per-fixture
 * speed (m/s) above which restitution applies (its default is 1). */
typedef struct b2y_material {
  float density, friction, restitution, restitution_threshold;
} b2y_material;

/* What the tests read back from a body, as Box2D stores it (float). */
typedef struct b2y_state {
  float x, y;   /* body origin */
  float angle;  /* the sweep angle (not wrapped) */
  float cx, cy; /* centre of mass, world */
  float vx, vy; /* velocity of the centre of mass */
  float w;
  int awake;
} b2y_state;

/* Box2D's defaults: density 1, friction 0.2 (tumble's is 0.6: set it), no
 * restitution, threshold 1 m/s. */
b2y_material b2y_default_material(void);

b2y_world* b2y_world_create(float gx, float gy);
void b2y_world_destroy(b2y_world* world);
/* Whether bodies may fall asleep (Box2D's default: yes). */
void b2y_world_set_allow_sleeping(b2y_world* world, int allow);
/* One b2World::Step. */
void b2y_world_step(b2y_world* world, float dt, int velocity_iterations, int position_iterations);

/* A body at (x, y) turned by angle; NULL on bad input. */
b2y_body* b2y_body_create(b2y_world* world, b2y_body_type type, float x, float y, float angle);
void b2y_body_set_velocity(b2y_body* body, float vx, float vy, float w);
void b2y_body_set_bullet(b2y_body* body, int bullet);

/* Fixtures; each recomputes the body's mass. Return 1 on success, 0 if rejected. */
int b2y_body_add_box(b2y_body* body, float hx, float hy, float cx, float cy, float angle, const b2y_material* m);
int b2y_body_add_circle(b2y_body* body, float cx, float cy, float radius, const b2y_material* m);
/* A two-sided edge (body-local points). */
int b2y_body_add_edge(b2y_body* body, float x1, float y1, float x2, float y2, const b2y_material* m);

void b2y_body_get_state(const b2y_body* body, b2y_state* out);
float b2y_body_get_mass(const b2y_body* body);

/* A revolute joint pinning a and b at a world point (b2RevoluteJointDef::Initialize);
 * 1 on success. */
int b2y_revolute_joint_create(b2y_world* world, b2y_body* a, b2y_body* b, float wx, float wy);

#ifdef __cplusplus
}
#endif

#endif
