/* tumble: a 2D rigid-body physics engine for games.
 *
 * One header, C17, no dependency beyond libc and libm.
 *
 * Conventions
 * - Units: metres, kilograms, seconds, radians. Tuned for objects of 0.05 to 50 m.
 *   Games in other length units (pixels) set tb_set_length_units_per_meter
 *   first; the metre values below then scale (see "memory, hooks and units").
 * - Mass ratios: supported up to 1e3:1 between bodies that touch or are jointed
 *   (60 Hz, 4 substeps). Contacts are springs of contact_hertz, so a light body
 *   under a heavy one sinks by the load over its spring: a 1 kg box under 1 t sinks
 *   3 cm, under 10 t it is crushed through (the spring would need 24 cm). Joints
 *   open with the ratio: 5 mm at 1e3 (1 m link), 2.4 cm at 1e4, 11 cm at 1e6; 8
 *   substeps quarter that, but do not stiffen contacts. Beyond the range nothing
 *   is reported: the stress suite's mass_ratio_edge table (results/STRESS.md)
 *   shows how it fails.
 * - Objects are reached through handles (tb_world_id, tb_body_id, tb_shape_id) that
 *   carry a generation: a stale handle (its object, or its whole world, was
 *   destroyed) or a foreign one is reported as an error, never dereferenced. No
 *   handle is ever handed out twice, also across worlds that reuse a world slot.
 * - Definitions are plain structs. The one rule for defaults: start every definition
 *   from its tb_default_*_def() function, then change the fields you care about.
 * - Every entry point validates its input (NULL, NaN/Inf, negative sizes, degenerate
 *   polygons, bad time steps, stale handles, values outside the ranges documented
 *   here). A rejected call changes nothing, returns an error code (functions that
 *   create return an invalid handle; getters return zero, false, NULL or a null
 *   handle, and a rotation or transform the identity, angle 0) and leaves a
 *   readable message in tb_last_error() and, when the world is known, in
 *   tb_world_last_error().
 * - What the engine produces stays within its own limits: bodies stop at the
 *   edge of the world (TB_MAX_LENGTH), and getters that combine values
 *   (energy, momenta, point velocities, joint forces and torques) saturate at
 *   +-TB_MAX_VALUE instead of overflowing, so a getter's value is always one
 *   its setter accepts.
 * - Not thread-safe: use one world from one thread at a time.
 */
#ifndef TUMBLE_H
#define TUMBLE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define TB_VERSION_MAJOR 0
#define TB_VERSION_MINOR 1
#define TB_VERSION_PATCH 0

/* Largest vertex count of a convex polygon; more points are an error, never cut. */
#ifndef TB_MAX_POLYGON_VERTICES
#define TB_MAX_POLYGON_VERTICES 8
#endif

/* Points of a hull closer than this (metres) are welded into one. */
#define TB_LINEAR_SLOP 0.005f

/* Largest accepted coordinate or size (metres). Beyond it a float cannot place
 * anything to the centimetre, so larger values are rejected as bad input. The
 * world ends there: a body that moves to its edge stops with its shapes
 * inside and loses its velocity outwards. */
#define TB_MAX_LENGTH 1.0e7f
/* Largest accepted magnitude of any other quantity (velocity, force, impulse,
 * torque, density, damping, mass, inertia; gravity has TB_MAX_GRAVITY). */
#define TB_MAX_VALUE 1.0e18f
/* Largest accepted magnitude of an angle (radians: body angles, reference
 * angles, angle limits, offsets). A float there still resolves 0.06 rad. */
#define TB_MAX_ANGLE 1.0e6f
/* Largest accepted length of the world's gravity (m/s^2, about 1000 g). A
 * resting body sinks into its support until the contact's spring carries its
 * weight, by g / w^2 with w = 2 pi f. At the default step (60 Hz, 4 substeps)
 * the stiffest contact has f = 0.48 x 240 Hz = 115 Hz, so 1e4 m/s^2 sinks
 * 0.019 m: within a contact's reach (TB_SPECULATIVE_DISTANCE, 0.02 m) and less
 * than half the thinnest object the engine is tuned for (0.05 m). Longer
 * substeps h sink more (about g h^2 / 9). The gravity a body feels,
 * gravity_scale times the world's, is clamped to this length too. */
#define TB_MAX_GRAVITY 1.0e4f

/* Largest accepted tb_world_def.maximum_linear_speed (m/s). Measured: at it
 * the continuous pass still stops a body at a 1 cm wall with steps of 1 s;
 * with 1e7 m per step and more, every body left a closed room. */
#define TB_MAX_SPEED 1.0e6f

/* Most relax passes per substep (tb_world_def.relax_iterations). */
#define TB_MAX_RELAX_ITERATIONS 64

/* ---------------------------------------------------------------- results -- */

typedef enum tb_result {
  TB_OK = 0,
  TB_ERR_NULL_ARGUMENT,      /* a required pointer was NULL */
  TB_ERR_INVALID_ARGUMENT,   /* NaN, infinite, negative or out-of-range value */
  TB_ERR_STALE_HANDLE,       /* the object was destroyed (or the handle is garbage) */
  TB_ERR_FOREIGN_HANDLE,     /* the handle belongs to another world */
  TB_ERR_DEGENERATE_POLYGON, /* < 3 distinct points, collinear or near-zero area */
  TB_ERR_TOO_MANY_VERTICES,  /* more than TB_MAX_POLYGON_VERTICES hull points */
  TB_ERR_OUT_OF_MEMORY,
  TB_ERR_CAPACITY,        /* a fixed limit (e.g. number of worlds) is reached */
  TB_ERR_LOCKED,          /* a change from inside tb_world_step or a query/draw callback */
  TB_ERR_WRONG_BODY_TYPE, /* e.g. mass data on a static body */
  /* the step was taken, but a NaN or an out-of-range value appeared in it (a
   * body's state, a mix callback's result) and was contained (see the message) */
  TB_ERR_NUMERIC
} tb_result;

/* The short name of a result code, e.g. "TB_ERR_STALE_HANDLE". */
const char* tb_result_name(tb_result r);

/* The message of the last rejected call on this thread ("" when none). */
const char* tb_last_error(void);
tb_result tb_last_result(void);
/* Forget the last error of this thread. */
void tb_clear_error(void);

/* -------------------------------------------- memory, hooks and units -- */

/* Global settings, shared by all worlds. Each setter may be called only while
 * no world exists (before the first tb_create_world, or after the last
 * tb_destroy_world); while one does it is refused with TB_ERR_LOCKED and
 * nothing changes. So a world never sees them change, and threads that step
 * their own worlds only ever read them. Like the rest of the library, the
 * setters are not thread-safe: call them from one thread while no other
 * thread is inside tumble. */

/* Every block tumble allocates is requested with this alignment (bytes; the
 * solver keeps 16-byte vectors in its blocks). */
#define TB_ALLOCATION_ALIGNMENT 16

/* Allocates size (> 0) bytes aligned to alignment (a power of two, at least
 * TB_ALLOCATION_ALIGNMENT); returns NULL when out of memory. */
typedef void* tb_alloc_fn(size_t size, size_t alignment, void* context);
/* Frees a block from the alloc function; size is the size it was allocated
 * with (so a game's allocator needs no header). Never called with NULL. */
typedef void tb_free_fn(void* memory, size_t size, void* context);

/* The library's own: malloc (aligned_alloc where malloc aligns less than
 * the alignment asked for) and free. */
void* tb_default_alloc(size_t size, size_t alignment, void* context);
void tb_default_free(void* memory, size_t size, void* context);

/* Routes every allocation of tumble through alloc and free, with context.
 * Both are required (pass tb_default_alloc and tb_default_free to go back).
 * Only while no world and no tb_dynamic_tree exists (else TB_ERR_LOCKED: their
 * blocks came from the allocator in place). What tumble keeps between
 * worlds (see tb_get_retained_byte_count) moves to the new allocator: it is
 * copied into blocks from alloc and its old blocks go back to the old free
 * function, so each allocator frees only its own blocks; TB_ERR_OUT_OF_MEMORY
 * (nothing changed) when the copy cannot be allocated.
 * When alloc returns NULL, the call that needed the memory fails cleanly: a
 * creator returns the null handle with TB_ERR_OUT_OF_MEMORY and the world is
 * as before; tb_world_step returns TB_ERR_OUT_OF_MEMORY and leaves a
 * consistent world in which what could not be allocated was skipped (a new
 * contact is found again on a later step, an event is dropped, or the whole
 * solve waits for the next step). */
tb_result tb_set_allocator(tb_alloc_fn* alloc, tb_free_fn* free, void* context);

/* Receives each message tumble records in tb_last_error() (a rejected call,
 * an out-of-memory step, a contained numeric problem), and the message of a
 * failed internal-consistency check before the assert function runs. It must
 * not call back into tumble. */
typedef void tb_log_fn(const char* message, void* context);
/* Sets the log function; NULL (the default) logs nothing. Only while no world
 * exists (else TB_ERR_LOCKED). */
tb_result tb_set_log_function(tb_log_fn* log, void* context);

/* Called when tumble finds its own state inconsistent (a bug in tumble, never
 * a bad argument: those are errors). After it returns tumble calls abort():
 * the state cannot be trusted any more; a game may stop in a debugger or
 * write a crash report first. */
typedef void tb_assert_fn(const char* condition, const char* file, int line, void* context);
/* Sets the assert function; NULL (the default) writes the message to stderr
 * when no log function is set. Only while no world exists (else
 * TB_ERR_LOCKED). */
tb_result tb_set_assert_function(tb_assert_fn* assert_fn, void* context);

/* Bytes tumble holds outside any world (from the allocator's point of view):
 * the handle history of world slots, 2 bytes per body, shape, chain and
 * joint slot the slot's earlier worlds used (see tb_create_world). */
size_t tb_get_retained_byte_count(void);

/* Bytes a world holds, by part, from the allocator's point of view: the sums of
 * the sizes of its live blocks. Blocks grow and are kept (no allocation in a
 * steady step), so these are capacities, not what is in use. */
typedef struct tb_memory_stats {
  size_t world;       /* the world's own record */
  size_t bodies;      /* the body pool and the awake set */
  size_t shapes;      /* the shape pool, and chains: their pool and segment lists */
  size_t contacts;    /* the contact pool and the pair set */
  size_t joints;      /* the joint pool */
  size_t broad_phase; /* the three bounding-volume trees and the move buffer */
  size_t islands;     /* sleeping islands */
  size_t solver;      /* step scratch: solver bodies, constraints, colours, joint trees */
  size_t events;      /* contact and sensor event arrays */
  /* generations that earlier worlds in this world slot left, so that no
   * handle is handed out twice (tb_create_world) */
  size_t handle_history;
  size_t total; /* the sum of the parts; tb_world_get_byte_count */
} tb_memory_stats;

/* tb_world_get_byte_count and tb_world_get_memory_stats are in the world
 * section (they take a world handle). */

/* Length units per metre, for games that work in other units (e.g. 100 for
 * pixels at 100 px/m), default 1: finite and in [1e-3, 1e3] (else
 * TB_ERR_INVALID_ARGUMENT). Only while no world exists (else TB_ERR_LOCKED).
 * Every length tolerance inside tumble is in these units: TB_LINEAR_SLOP (the
 * hull weld distance, the shortest segment, capsule and joint length),
 * TB_SPECULATIVE_DISTANCE, the broad phase's AABB margin, the continuous
 * pass's target gap, the cast tolerance, and so are the defaults and limits
 * that are lengths, speeds or accelerations: the world's gravity
 * ((0, -10) x units), maximum_linear_speed, hit_event_threshold,
 * restitution_threshold, contact_push_max_velocity, TB_MAX_SPEED and
 * TB_MAX_GRAVITY, a body's sleep_threshold, a distance joint's length, the
 * debug draw's normal_length. The macros keep their values in metres:
 * multiply them by tb_get_length_units_per_meter(). TB_MAX_LENGTH stays as it
 * is (it is where a float stops resolving the slop at 1 unit = 1 m; larger
 * units per metre make the world smaller in metres, not in units).
 * tb_default_*_def() read the setting when called: set it first. A power of
 * two gives bit for bit the same motion as metres, scaled. */
tb_result tb_set_length_units_per_meter(float units_per_meter);
float tb_get_length_units_per_meter(void);

/* ------------------------------------------------------------------ math -- */

/* Inline helpers on these types (vectors, rotations, transforms, boxes, a
 * spring-damper step) are in tumble_math.h. */

typedef struct tb_vec2 {
  float x, y;
} tb_vec2;

/* A rotation as a unit complex number: (cos angle, sin angle). */
typedef struct tb_rot {
  float c, s;
} tb_rot;

/* A rigid transform: world = p + q * local. */
typedef struct tb_transform {
  tb_vec2 p;
  tb_rot q;
} tb_transform;

typedef struct tb_aabb {
  tb_vec2 lower, upper;
} tb_aabb;

/* Mass properties. rotational_inertia is about the centre of mass (kg m^2). */
typedef struct tb_mass_data {
  float mass;
  tb_vec2 center;
  float rotational_inertia;
} tb_mass_data;

/* --------------------------------------------------------------- handles -- */

/* Handles: index + 1 (so a zeroed handle is the null handle) and a generation. */
typedef struct tb_world_id {
  uint16_t index1;
  uint16_t generation;
} tb_world_id;

typedef struct tb_body_id {
  int32_t index1;
  uint16_t world0;
  uint16_t generation;
} tb_body_id;

typedef struct tb_shape_id {
  int32_t index1;
  uint16_t world0;
  uint16_t generation;
} tb_shape_id;

typedef struct tb_chain_id {
  int32_t index1;
  uint16_t world0;
  uint16_t generation;
} tb_chain_id;

typedef struct tb_joint_id {
  int32_t index1;
  uint16_t world0;
  uint16_t generation;
} tb_joint_id;

static inline bool tb_world_id_is_null(tb_world_id id) { return id.index1 == 0; }
static inline bool tb_body_id_is_null(tb_body_id id) { return id.index1 == 0; }
static inline bool tb_shape_id_is_null(tb_shape_id id) { return id.index1 == 0; }
static inline bool tb_chain_id_is_null(tb_chain_id id) { return id.index1 == 0; }
static inline bool tb_joint_id_is_null(tb_joint_id id) { return id.index1 == 0; }

/* Equality of handles (every field, the generation included), and a handle
 * packed into one uint64_t (for a game's own tables, or as a hash key) and
 * back: tb_*_id_from_u64(tb_*_id_to_u64(id)) equals id, and the null handle
 * packs to 0. Bodies, shapes, chains and joints pack index1 into the low 32
 * bits, then the world slot, then the generation; worlds index1, then the
 * generation. A packed handle is only good in the process that made it. */
static inline uint64_t tb_world_id_to_u64(tb_world_id id) {
  return (uint64_t)id.index1 | (uint64_t)id.generation << 16;
}
static inline bool tb_world_id_equal(tb_world_id a, tb_world_id b) {
  return tb_world_id_to_u64(a) == tb_world_id_to_u64(b);
}
static inline tb_world_id tb_world_id_from_u64(uint64_t x) {
  tb_world_id out = {(uint16_t)x, (uint16_t)(x >> 16)};
  return out;
}
static inline uint64_t tb_body_id_to_u64(tb_body_id id) {
  return (uint64_t)(uint32_t)id.index1 | (uint64_t)id.world0 << 32 | (uint64_t)id.generation << 48;
}
static inline bool tb_body_id_equal(tb_body_id a, tb_body_id b) { return tb_body_id_to_u64(a) == tb_body_id_to_u64(b); }
static inline tb_body_id tb_body_id_from_u64(uint64_t x) {
  tb_body_id out = {(int32_t)(uint32_t)x, (uint16_t)(x >> 32), (uint16_t)(x >> 48)};
  return out;
}
static inline uint64_t tb_shape_id_to_u64(tb_shape_id id) {
  return (uint64_t)(uint32_t)id.index1 | (uint64_t)id.world0 << 32 | (uint64_t)id.generation << 48;
}
static inline bool tb_shape_id_equal(tb_shape_id a, tb_shape_id b) {
  return tb_shape_id_to_u64(a) == tb_shape_id_to_u64(b);
}
static inline tb_shape_id tb_shape_id_from_u64(uint64_t x) {
  tb_shape_id out = {(int32_t)(uint32_t)x, (uint16_t)(x >> 32), (uint16_t)(x >> 48)};
  return out;
}
static inline uint64_t tb_chain_id_to_u64(tb_chain_id id) {
  return (uint64_t)(uint32_t)id.index1 | (uint64_t)id.world0 << 32 | (uint64_t)id.generation << 48;
}
static inline bool tb_chain_id_equal(tb_chain_id a, tb_chain_id b) {
  return tb_chain_id_to_u64(a) == tb_chain_id_to_u64(b);
}
static inline tb_chain_id tb_chain_id_from_u64(uint64_t x) {
  tb_chain_id out = {(int32_t)(uint32_t)x, (uint16_t)(x >> 32), (uint16_t)(x >> 48)};
  return out;
}
static inline uint64_t tb_joint_id_to_u64(tb_joint_id id) {
  return (uint64_t)(uint32_t)id.index1 | (uint64_t)id.world0 << 32 | (uint64_t)id.generation << 48;
}
static inline bool tb_joint_id_equal(tb_joint_id a, tb_joint_id b) {
  return tb_joint_id_to_u64(a) == tb_joint_id_to_u64(b);
}
static inline tb_joint_id tb_joint_id_from_u64(uint64_t x) {
  tb_joint_id out = {(int32_t)(uint32_t)x, (uint16_t)(x >> 32), (uint16_t)(x >> 48)};
  return out;
}

/* ----------------------------------------------------------------- world -- */

/* Integrator for bodies moved only by gravity, applied forces and the force field. */
typedef enum tb_integrator {
  TB_INTEGRATOR_SEMI_IMPLICIT_EULER = 0, /* symplectic; the solver's own scheme */
  TB_INTEGRATOR_MIDPOINT,                /* explicit midpoint, RK2 */
  TB_INTEGRATOR_RK4                      /* classical Runge-Kutta, 4 stages */
} tb_integrator;

/* What a force-field callback sees of a body. Position and angle are of the
 * centre of mass. */
typedef struct tb_body_state {
  tb_body_id body;
  tb_vec2 center;
  float angle;
  tb_vec2 linear_velocity;
  float angular_velocity;
  float mass;
  float rotational_inertia;
  void* user_data;
} tb_body_state;

/* A force field f(t, body state) -> (force at the centre of mass, torque). It is
 * called for every awake dynamic body at each integrator stage, so it must be a
 * pure function of its arguments. It must not call back into the world. */
typedef void tb_force_field_fn(double time, const tb_body_state* state, void* context, tb_vec2* force, float* torque);

/* Decides whether two shapes may collide, after the filter bits (optional). It is
 * called when the broad phase finds a new pair and when the continuous pass
 * sweeps a fast body past a shape; it must not change the world. */
typedef bool tb_custom_filter_fn(tb_shape_id a, tb_shape_id b, void* context);

struct tb_manifold;
/* Called for each touching, non-sensor contact of shapes that enable pre-solve
 * events, after the narrow phase and before the solver; return false to disable
 * the contact for this step (e.g. one-way platforms). Must not change the world. */
typedef bool tb_pre_solve_fn(tb_shape_id a, tb_shape_id b, const struct tb_manifold* manifold, void* context);

/* Mixes two shapes' friction or restitution into the contact's. A friction
 * must come out >= 0 and at most TB_MAX_VALUE, a restitution in [0, 1]; any
 * other result (NaN included) is not used: the contact takes the default
 * rule and tb_world_step returns TB_ERR_NUMERIC naming the callback. */
typedef float tb_mix_fn(float a, float b, void* context);

typedef struct tb_world_def {
  tb_vec2 gravity;                /* m/s^2, default (0, -10), at most TB_MAX_GRAVITY long */
  tb_integrator integrator;       /* default midpoint: exact under constant forces */
  tb_force_field_fn* force_field; /* optional, default NULL */
  void* force_field_context;
  /* Contact hit events are reported above this approach speed (m/s, default 1). */
  float hit_event_threshold;
  tb_custom_filter_fn* custom_filter; /* optional */
  void* custom_filter_context;
  tb_pre_solve_fn* pre_solve; /* optional */
  void* pre_solve_context;
  /* Mixing rules, fixed when a contact is created. Defaults: friction
   * sqrt(fa fb) (a frictionless shape makes the contact frictionless),
   * restitution max(ra, rb) (a bouncy shape bounces on anything). Contacts
   * obey Coulomb's law per point: |tangent impulse| <= friction * normal impulse. */
  tb_mix_fn* friction_mix;
  tb_mix_fn* restitution_mix;
  void* mix_context;

  /* Solver tuning (see "One step" in DESIGN.md). Contacts are soft constraints:
   * a spring of contact_hertz (> 0, default 120; twice that against static
   * and kinematic bodies; capped at 0.48 times the substep rate, 115 Hz at
   * 60 Hz and 4 substeps) with contact_damping_ratio (>= 0, default 10) that
   * pushes overlapping shapes apart no faster than contact_push_max_velocity
   * (m/s, >= 0, default 3). Each substep ends with up to relax_iterations
   * (1 to TB_MAX_RELAX_ITERATIONS, default 8) passes over the contacts and
   * joints without position bias; the passes stop early once one changes no
   * contact's speed by more than 1e-5 m/s: a box at rest takes one, a settled
   * 30-box column two, a sliding box four. Fewer passes are faster; tall stacks and heavy loads on light bodies
   * then jitter and may buckle. The rigid parts of joints that form trees (chains,
   * ragdolls, bridges: any joint graph without a loop through dynamic bodies)
   * are solved exactly and held at a stiffness of 8 / substep (rad/s) with
   * joint_damping_ratio (default 2, i.e. over-damped); a joint that closes a
   * loop uses joint_hertz (> 0, default 60) for its drift correction, capped
   * like contacts at 0.48 times the substep rate (115 Hz at 60 Hz and 4
   * substeps): stiffer, Gauss-Seidel overshoots and the loop gains energy. */
  float contact_hertz;
  float contact_damping_ratio;
  float contact_push_max_velocity;
  int relax_iterations;
  float joint_hertz;
  float joint_damping_ratio;
  /* Restitution applies to approach speeds above this (m/s, >= 0, default 1). */
  float restitution_threshold;
  /* Speed caps, a guard against blow-ups: every dynamic and kinematic body
   * moves at most maximum_linear_speed (m/s, > 0 and at most TB_MAX_SPEED,
   * default 1000) and turns at most a quarter turn per step (pi / 2 / time_step
   * rad/s, 94 rad/s at 60 Hz), whether it touches anything or not, under
   * every integrator. A velocity set beyond the caps is accepted (up to
   * TB_MAX_VALUE) and brought within them by the next step; the velocities a
   * step leaves are within them. With continuous on, a dynamic body does not
   * pass through a static one at any speed the caps allow. */
  float maximum_linear_speed;
  bool enable_sleep;         /* default true: resting islands fall asleep */
  bool enable_continuous;    /* default true: fast bodies are swept (no tunnelling) */
  bool enable_warm_starting; /* default true */
  /* default false: tb_world_get_profile's stage times are measured (seven
   * reads of the clock a step, 0.18 us on the benchmark machine: a quarter of
   * a one-body step); its counts are kept either way */
  bool enable_profile;
  void* user_data;
} tb_world_def;

tb_world_def tb_default_world_def(void);

/* Create a world; returns the null handle on error (see tb_last_error()).
 * At most 128 worlds exist at once. Each of the 128 world slots holds 65,536
 * worlds in turn and is then retired (TB_ERR_CAPACITY once all are), so a world
 * handle never matches a later world; sooner when its worlds have reused one
 * object slot 32,768 times. A slot keeps 2 bytes per body, shape, chain and
 * joint slot its worlds ever used, so that the next world there never
 * reissues an old object handle. */
tb_world_id tb_create_world(const tb_world_def* def);
tb_result tb_destroy_world(tb_world_id world);
bool tb_world_is_valid(tb_world_id world);

/* Shortest accepted substep, time_step / substeps (seconds). The solver
 * divides distances by the substep (position bias, speculative contacts):
 * shorter, a distance within TB_MAX_LENGTH would become a speed beyond
 * TB_MAX_VALUE, and the reciprocal of a tiny step overflows. */
#define TB_MIN_SUBSTEP (TB_MAX_LENGTH / TB_MAX_VALUE)

/* Longest accepted time step (seconds): 30 Hz. The step collides once, and
 * up to this step the solver keeps every gallery scene (demos/scenes) stable
 * at every substep count (tests/scenes/test_scenes.c,
 * gallery_is_stable_at_every_accepted_step). Steps up to 1 s were once
 * accepted and were not stable: bodies move farther per step than
 * the contacts found at its start describe (a tumbler's kinematic walls
 * sweep past the bodies inside; at 1/15 s bodies left it whatever the
 * substeps), and with one substep of 0.1 s joints exploded (ragdolls) and
 * chains flew apart; a wheel-joint car reached 1.6e13 m/s at 1 s. A game
 * rendering slower than 30 Hz takes several steps per frame. */
#define TB_MAX_TIME_STEP (1.0f / 30.0f)

/* Advance by time_step seconds (finite, at most TB_MAX_TIME_STEP), split into
 * substeps (1 to 64; 4 is a good default at 60 Hz), each at least
 * TB_MIN_SUBSTEP (1e-11 s) long. */
tb_result tb_world_step(tb_world_id world, float time_step, int substeps);

/* Gravity: finite, at most TB_MAX_GRAVITY long. */
tb_result tb_world_set_gravity(tb_world_id world, tb_vec2 gravity);
tb_vec2 tb_world_get_gravity(tb_world_id world);
tb_result tb_world_set_integrator(tb_world_id world, tb_integrator integrator);
tb_integrator tb_world_get_integrator(tb_world_id world);
tb_result tb_world_set_force_field(tb_world_id world, tb_force_field_fn* fn, void* context);
/* Replaces the pre-solve callback of the world definition (NULL removes it);
 * not from inside the step. */
tb_result tb_world_set_pre_solve(tb_world_id world, tb_pre_solve_fn* fn, void* context);
/* Simulated time: the sum of all time steps taken (seconds). */
double tb_world_get_time(tb_world_id world);
/* Switches and tuning of the world definition, changeable between steps (same
 * ranges as in tb_world_def). Turning sleep off wakes every body. */
tb_result tb_world_enable_sleeping(tb_world_id world, bool enable);
bool tb_world_is_sleeping_enabled(tb_world_id world);
tb_result tb_world_enable_continuous(tb_world_id world, bool enable);
bool tb_world_is_continuous_enabled(tb_world_id world);
tb_result tb_world_enable_warm_starting(tb_world_id world, bool enable);
tb_result tb_world_enable_profile(tb_world_id world, bool enable);
bool tb_world_is_profile_enabled(tb_world_id world);
tb_result tb_world_set_contact_tuning(tb_world_id world, float hertz, float damping_ratio, float push_max_velocity);
tb_result tb_world_set_relax_iterations(tb_world_id world, int iterations);
int tb_world_get_relax_iterations(tb_world_id world); /* 0 for an invalid world */
tb_result tb_world_set_joint_tuning(tb_world_id world, float hertz, float damping_ratio);
tb_result tb_world_set_restitution_threshold(tb_world_id world, float speed);
tb_result tb_world_set_maximum_linear_speed(tb_world_id world, float speed);
void* tb_world_get_user_data(tb_world_id world);
tb_result tb_world_set_user_data(tb_world_id world, void* user_data);

typedef struct tb_counts {
  int body_count;
  int awake_body_count; /* enabled, non-static bodies that are simulated */
  int shape_count;
  int step_count;
  int contact_count;  /* pairs of shapes whose fat bounding boxes overlap */
  int touching_count; /* contacts with manifold points (speculative included) */
  int tree_height;    /* tallest of the broad phase's trees */
  int joint_count;
  int awake_contact_count; /* touching contacts the solver handled last step */
  int sleeping_island_count;
} tb_counts;

tb_counts tb_world_get_counts(tb_world_id world);

/* Where the last tb_world_step spent its time, in milliseconds of a monotonic
 * wall clock, and what it worked on. All zero before the first step. The
 * stages add up to about the whole step; the rest is bookkeeping. The times
 * are measured only while the world's profile is enabled (enable_profile in
 * tb_world_def, tb_world_enable_profile), and are 0 otherwise; the counts
 * are filled in every step. */
typedef struct tb_profile {
  float step;         /* the whole tb_world_step */
  float broad_phase;  /* moving proxies in the trees and finding new pairs */
  float narrow_phase; /* manifolds of the awake bodies' contacts */
  float solver;       /* integration, constraints (contacts and joints), substeps */
  float continuous;   /* time-of-impact sweeps of fast bodies and bullets */
  float islands;      /* sleep bookkeeping: island search, islands falling asleep */
  int awake_body_count;
  int awake_contact_count; /* touching contacts the solver handled */
  int awake_joint_count;   /* joints the solver handled */
  int pair_count;          /* contacts (pairs with overlapping fat boxes) */
  int new_pair_count;      /* pairs the broad phase found this step */
  int continuous_count;    /* bodies swept by continuous collision */
  /* relax passes of the step over its substeps: each substep's repeat until
   * no contact speed changes by more than 1e-5 m/s, at most relax_iterations;
   * a contact whose bodies touch nothing else converges within one pass */
  int relax_pass_count;
} tb_profile;

tb_profile tb_world_get_profile(tb_world_id world);

/* The bytes the world holds, from the allocator's point of view (0 on error:
 * a null or stale handle); tb_memory_stats.total. */
size_t tb_world_get_byte_count(tb_world_id world);
/* Fills *stats with the world's bytes by part (tb_memory_stats; zeroed on
 * error). Errors: NULL stats, a null or stale world. */
tb_result tb_world_get_memory_stats(tb_world_id world, tb_memory_stats* stats);

/* A 64-bit hash of the whole world: everything a public call can change and
 * everything a step carries over to the next. That is the world's settings
 * (gravity, integrator, solver tuning, switches, time and step count); every
 * body's placement, velocities, forces, mass, damping, flags (bullet, sleep,
 * enabled, fixed rotation) and sleep state (awake order, sleeping islands,
 * rest timer, threshold); every shape's geometry, material, filter and event
 * flags; chains; every joint's definition, limits, motor, spring, target and
 * accumulated impulses; the contacts with their warm-start impulses; the
 * broad phase's trees and queued proxies; the events of the last step.
 * Pointers the caller passes (user data, callbacks and their contexts) count
 * only as set or not set, so the hash is the same on every run and in any
 * world slot. Not covered: the profile (its switch and wall-clock times) and which free slot
 * the next object takes. Equal states give equal hashes; use it to check
 * determinism or that a rejected call changed nothing. */
uint64_t tb_world_hash(tb_world_id world);

/* The message of the last call rejected on this world ("" when none). */
const char* tb_world_last_error(tb_world_id world);

/* ---------------------------------------------------------------- bodies -- */

typedef enum tb_body_type {
  TB_STATIC_BODY = 0,    /* never moves; infinite mass */
  TB_KINEMATIC_BODY = 1, /* moves with its velocity; ignores forces; infinite mass */
  TB_DYNAMIC_BODY = 2    /* moved by forces; mass from its shapes */
} tb_body_type;

typedef struct tb_body_def {
  tb_body_type type;       /* default static */
  tb_vec2 position;        /* world position of the body origin */
  float angle;             /* radians, within TB_MAX_ANGLE */
  tb_vec2 linear_velocity; /* of the body origin, m/s */
  float angular_velocity;  /* rad/s */
  float linear_damping;    /* >= 0, 1/s: v <- v / (1 + h c) per substep */
  float angular_damping;   /* >= 0, 1/s */
  float gravity_scale;     /* default 1; the product with gravity is clamped to TB_MAX_GRAVITY */
  bool fixed_rotation;
  bool enabled; /* default true */
  /* A bullet is swept against dynamic bodies too, not only static ones (for
   * small fast bodies such as projectiles). Default false. */
  bool is_bullet;
  bool enable_sleep; /* default true: the body may fall asleep when at rest */
  bool is_awake;     /* default true: false creates it asleep */
  /* Below this speed (m/s; rotation counts as speed at the body's extent) the
   * body counts as at rest. >= 0, default 0.05. */
  float sleep_threshold;
  void* user_data;
} tb_body_def;

tb_body_def tb_default_body_def(void);

tb_body_id tb_create_body(tb_world_id world, const tb_body_def* def);
/* Destroys the body and all its shapes. */
tb_result tb_destroy_body(tb_body_id body);
bool tb_body_is_valid(tb_body_id body);
tb_world_id tb_body_get_world(tb_body_id body);

tb_body_type tb_body_get_type(tb_body_id body);
tb_result tb_body_set_type(tb_body_id body, tb_body_type type);

/* The body origin and angle. */
tb_vec2 tb_body_get_position(tb_body_id body);
float tb_body_get_angle(tb_body_id body);
tb_rot tb_body_get_rotation(tb_body_id body);
tb_transform tb_body_get_transform(tb_body_id body);
tb_result tb_body_set_transform(tb_body_id body, tb_vec2 position, float angle);

/* Centre of mass, in body and in world coordinates. */
tb_vec2 tb_body_get_local_center(tb_body_id body);
tb_vec2 tb_body_get_world_center(tb_body_id body);

/* Linear velocity is that of the centre of mass. */
tb_vec2 tb_body_get_linear_velocity(tb_body_id body);
tb_result tb_body_set_linear_velocity(tb_body_id body, tb_vec2 v);
float tb_body_get_angular_velocity(tb_body_id body);
tb_result tb_body_set_angular_velocity(tb_body_id body, float w);
/* Velocity of the material point at a world point: v + w x r. */
tb_vec2 tb_body_get_point_velocity(tb_body_id body, tb_vec2 world_point);

float tb_body_get_linear_damping(tb_body_id body);
tb_result tb_body_set_linear_damping(tb_body_id body, float damping);
float tb_body_get_angular_damping(tb_body_id body);
tb_result tb_body_set_angular_damping(tb_body_id body, float damping);
float tb_body_get_gravity_scale(tb_body_id body);
tb_result tb_body_set_gravity_scale(tb_body_id body, float scale);
bool tb_body_is_fixed_rotation(tb_body_id body);
tb_result tb_body_set_fixed_rotation(tb_body_id body, bool fixed);
bool tb_body_is_enabled(tb_body_id body);
tb_result tb_body_set_enabled(tb_body_id body, bool enabled);
void* tb_body_get_user_data(tb_body_id body);
tb_result tb_body_set_user_data(tb_body_id body, void* user_data);

/* Sleep. A body sleeps with its whole island (the bodies it touches or is
 * jointed to, through dynamic bodies) once they all stayed below their sleep
 * threshold for TB_TIME_TO_SLEEP. Setting a body awake wakes its island; setting
 * it asleep puts its island to sleep. Forces, impulses, velocities, a new
 * transform, joints, destroying a shape or changing its density wake a body;
 * adding a shape wakes it when it touches or is jointed to something (so a
 * body created asleep can get its shapes and stay asleep). */
#define TB_TIME_TO_SLEEP 0.5f
bool tb_body_is_awake(tb_body_id body);
tb_result tb_body_set_awake(tb_body_id body, bool awake);
bool tb_body_is_sleep_enabled(tb_body_id body);
tb_result tb_body_enable_sleep(tb_body_id body, bool enable);
float tb_body_get_sleep_threshold(tb_body_id body);
tb_result tb_body_set_sleep_threshold(tb_body_id body, float speed);
bool tb_body_is_bullet(tb_body_id body);
tb_result tb_body_set_bullet(tb_body_id body, bool bullet);
/* Number of joints attached to the body, and up to capacity of their handles. */
int tb_body_get_joint_count(tb_body_id body);
int tb_body_get_joints(tb_body_id body, tb_joint_id* out, int capacity);

/* Forces and torques act over the next step and are then cleared. Impulses
 * change the velocity at once: dV = J / M, dw = (r x J) / I. Only dynamic bodies
 * respond; on other bodies these calls succeed and do nothing. */
tb_result tb_body_apply_force(tb_body_id body, tb_vec2 force, tb_vec2 world_point);
tb_result tb_body_apply_force_to_center(tb_body_id body, tb_vec2 force);
tb_result tb_body_apply_torque(tb_body_id body, float torque);
tb_result tb_body_apply_linear_impulse(tb_body_id body, tb_vec2 impulse, tb_vec2 world_point);
tb_result tb_body_apply_linear_impulse_to_center(tb_body_id body, tb_vec2 impulse);
tb_result tb_body_apply_angular_impulse(tb_body_id body, float impulse);
/* The force and torque accumulated for the next step (torque about the centre). */
tb_vec2 tb_body_get_force(tb_body_id body);
float tb_body_get_torque(tb_body_id body);

/* Mass (kg) and rotational inertia about the centre of mass (kg m^2). */
float tb_body_get_mass(tb_body_id body);
float tb_body_get_rotational_inertia(tb_body_id body);
tb_mass_data tb_body_get_mass_data(tb_body_id body);
/* Override the mass computed from shapes (dynamic bodies only; mass > 0,
 * inertia >= 0, finite centre). Adding or removing a shape, or
 * tb_body_reset_mass_data(), recomputes the mass from the shapes again. */
tb_result tb_body_set_mass_data(tb_body_id body, tb_mass_data mass_data);
tb_result tb_body_reset_mass_data(tb_body_id body);

tb_vec2 tb_body_get_world_point(tb_body_id body, tb_vec2 local_point);
tb_vec2 tb_body_get_local_point(tb_body_id body, tb_vec2 world_point);
tb_vec2 tb_body_get_world_vector(tb_body_id body, tb_vec2 local_vector);
tb_vec2 tb_body_get_local_vector(tb_body_id body, tb_vec2 world_vector);

/* 1/2 M V^2 + 1/2 I w^2 (J). These three saturate at +-TB_MAX_VALUE. */
float tb_body_get_kinetic_energy(tb_body_id body);
/* P = M V (kg m/s). */
tb_vec2 tb_body_get_linear_momentum(tb_body_id body);
/* L about a world point: I w + (X - point) x M V (kg m^2/s). */
float tb_body_get_angular_momentum(tb_body_id body, tb_vec2 world_point);

/* ---------------------------------------------------------------- shapes -- */

typedef enum tb_shape_type {
  TB_SHAPE_CIRCLE = 0,
  TB_SHAPE_CAPSULE,
  TB_SHAPE_SEGMENT,
  TB_SHAPE_POLYGON,
  TB_SHAPE_CHAIN_SEGMENT /* one segment of a chain (see tb_create_chain) */
} tb_shape_type;

typedef struct tb_circle {
  tb_vec2 center; /* body-local */
  float radius;   /* > 0 */
} tb_circle;

/* Two half discs joined by a rectangle: the points within radius of segment c1-c2. */
typedef struct tb_capsule {
  tb_vec2 center1, center2;
  float radius; /* > 0 */
} tb_capsule;

/* A line segment: no area, no mass. */
typedef struct tb_segment {
  tb_vec2 point1, point2;
} tb_segment;

/* A convex polygon, counter-clockwise, optionally rounded by radius (the set of
 * points within radius of the core polygon). Make one with tb_make_polygon or
 * tb_make_box*; the fields are filled by them. */
typedef struct tb_polygon {
  tb_vec2 vertices[TB_MAX_POLYGON_VERTICES];
  tb_vec2 normals[TB_MAX_POLYGON_VERTICES];
  tb_vec2 centroid;
  float radius;
  int count;
} tb_polygon;

/* The convex hull of points: near-duplicates (closer than TB_LINEAR_SLOP) are
 * welded, interior and collinear points dropped. Errors: NULL, count < 3, NaN,
 * fewer than 3 distinct points, all collinear, near-zero area, or a hull of more
 * than TB_MAX_POLYGON_VERTICES points. radius >= 0 rounds the corners. */
tb_result tb_make_polygon(const tb_vec2* points, int count, float radius, tb_polygon* out);
/* A box of half-extents hx, hy centred on the body origin. */
tb_result tb_make_box(float hx, float hy, tb_polygon* out);
/* A box centred at center (body-local), rotated by angle (within TB_MAX_ANGLE). */
tb_result tb_make_offset_box(float hx, float hy, tb_vec2 center, float angle, tb_polygon* out);
/* A box with rounded corners: core half-extents hx, hy plus radius. */
tb_result tb_make_rounded_box(float hx, float hy, float radius, tb_polygon* out);

/* Which shapes collide. Shapes A and B may collide when
 *   (A.category_bits & B.mask_bits) != 0 && (B.category_bits & A.mask_bits) != 0,
 * except that a shared non-zero group_index overrides the bits: the same
 * positive group always collides, the same negative group never does. */
typedef struct tb_filter {
  uint64_t category_bits; /* default 1 */
  uint64_t mask_bits;     /* default all bits */
  int32_t group_index;    /* default 0 */
} tb_filter;

tb_filter tb_default_filter(void);

typedef struct tb_shape_def {
  float density;     /* kg/m^2, >= 0, default 1 */
  float friction;    /* >= 0, default 0.6 */
  float restitution; /* in [0, 1] (1: elastic), default 0 */
  /* Rolling resistance coefficient (>= 0, default 0): a torque of up to
   * rolling_resistance * normal force * radius opposes relative rolling, where
   * radius is the rounding radius of a circle, capsule or rounded polygon
   * (the larger of the two shapes' coefficient * radius is used). */
  float rolling_resistance;
  /* Surface speed (m/s, default 0) clockwise around the shape, i.e. to the
   * right along the top of a box: a conveyor belt. A contact drives its
   * bodies at the sum of its shapes' speeds. */
  float tangent_speed;
  tb_filter filter;
  /* A sensor detects overlaps (sensor events) and never pushes anything. */
  bool is_sensor;
  bool enable_sensor_events;    /* default true: this shape is seen by sensors */
  bool enable_contact_events;   /* default true: begin/end events */
  bool enable_hit_events;       /* default false */
  bool enable_pre_solve_events; /* default false */
  void* user_data;
} tb_shape_def;

tb_shape_def tb_default_shape_def(void);

/* Attach a shape to a body. The body's mass, centre and inertia are recomputed. */
tb_shape_id tb_create_circle_shape(tb_body_id body, const tb_shape_def* def, const tb_circle* circle);
tb_shape_id tb_create_capsule_shape(tb_body_id body, const tb_shape_def* def, const tb_capsule* capsule);
tb_shape_id tb_create_segment_shape(tb_body_id body, const tb_shape_def* def, const tb_segment* segment);
tb_shape_id tb_create_polygon_shape(tb_body_id body, const tb_shape_def* def, const tb_polygon* polygon);
tb_result tb_destroy_shape(tb_shape_id shape);
bool tb_shape_is_valid(tb_shape_id shape);

tb_shape_type tb_shape_get_type(tb_shape_id shape);
tb_body_id tb_shape_get_body(tb_shape_id shape);
float tb_shape_get_density(tb_shape_id shape);
/* Changing the density recomputes the body's mass. */
tb_result tb_shape_set_density(tb_shape_id shape, float density);
float tb_shape_get_friction(tb_shape_id shape);
tb_result tb_shape_set_friction(tb_shape_id shape, float friction);
float tb_shape_get_restitution(tb_shape_id shape);
tb_result tb_shape_set_restitution(tb_shape_id shape, float restitution);
float tb_shape_get_rolling_resistance(tb_shape_id shape);
tb_result tb_shape_set_rolling_resistance(tb_shape_id shape, float rolling_resistance);
float tb_shape_get_tangent_speed(tb_shape_id shape);
tb_result tb_shape_set_tangent_speed(tb_shape_id shape, float speed);
tb_filter tb_shape_get_filter(tb_shape_id shape);
/* A new filter ends the shape's current contacts; allowed pairs return next step. */
tb_result tb_shape_set_filter(tb_shape_id shape, tb_filter filter);
bool tb_shape_is_sensor(tb_shape_id shape);
void* tb_shape_get_user_data(tb_shape_id shape);
tb_result tb_shape_set_user_data(tb_shape_id shape, void* user_data);
/* The shape's own mass properties, in body coordinates. */
tb_mass_data tb_shape_get_mass_data(tb_shape_id shape);
/* The tight world-space bounding box at the body's current transform. */
tb_aabb tb_shape_get_aabb(tb_shape_id shape);
/* The geometry, in body coordinates; the call fails on a shape of another type. */
tb_result tb_shape_get_circle(tb_shape_id shape, tb_circle* out);
tb_result tb_shape_get_capsule(tb_shape_id shape, tb_capsule* out);
tb_result tb_shape_get_segment(tb_shape_id shape, tb_segment* out);
tb_result tb_shape_get_polygon(tb_shape_id shape, tb_polygon* out);

/* Mass properties of bare geometry at a density (kg/m^2), in its own coordinates. */
tb_mass_data tb_compute_circle_mass(const tb_circle* circle, float density);
tb_mass_data tb_compute_capsule_mass(const tb_capsule* capsule, float density);
tb_mass_data tb_compute_polygon_mass(const tb_polygon* polygon, float density);

/* Geometry of one shape, at its body's current transform (world coordinates).
 * These read the shape whatever its body's state (asleep, disabled) and its
 * filter and sensor flag, and may be called from inside callbacks. Errors: a
 * null, stale or foreign shape; a point, origin or translation that is not
 * finite or beyond TB_MAX_LENGTH; a zero translation. */

/* Whether the shape contains a world point, boundary included. Segments and
 * chain segments contain nothing (false). false on error. */
bool tb_shape_test_point(tb_shape_id shape, tb_vec2 point);
struct tb_ray_result;
/* A ray from origin to origin + translation against this shape alone, as
 * tb_world_cast_ray sees it: the first point where it enters the shape, the
 * surface normal there and the fraction of the translation. A ray that starts
 * inside the shape does not hit it; a segment is hit from either side, a
 * chain segment only from its front (left) side. On a miss or an error .hit
 * is false, .fraction 1 and the rest zero (tb_ray_result is declared with the
 * queries below). */
struct tb_ray_result tb_shape_ray_cast(tb_shape_id shape, tb_vec2 origin, tb_vec2 translation);
/* The point of the shape nearest to a world point: the point itself when the
 * shape contains it, else the nearest point of its surface (rounding
 * included). For segments, the nearest point of the segment. (0, 0) on error. */
tb_vec2 tb_shape_get_closest_point(tb_shape_id shape, tb_vec2 target);

/* Replace a shape's geometry in place, in body coordinates. The shape keeps
 * its handle, material, filter, flags and user data, and may change type (a
 * box made a circle is then a circle: tb_shape_get_type tells). As when a
 * shape is created, the body's mass, centre and inertia are recomputed from
 * its shapes (a mass set by tb_body_set_mass_data is replaced). The shape's
 * contacts end (with end events when they touched), and the bodies it touched
 * wake; the broad phase finds its new pairs at the next step. The body wakes.
 * Errors: as for tb_create_*_shape (NULL, bad or degenerate geometry, a mass
 * that overflows at the shape's density, a box beyond TB_MAX_LENGTH at the
 * body's place), a chain segment (its geometry belongs to the chain), a call
 * from inside tb_world_step or a callback (TB_ERR_LOCKED). A refused call
 * changes nothing. */
tb_result tb_shape_set_circle(tb_shape_id shape, const tb_circle* circle);
tb_result tb_shape_set_capsule(tb_shape_id shape, const tb_capsule* capsule);
tb_result tb_shape_set_segment(tb_shape_id shape, const tb_segment* segment);
tb_result tb_shape_set_polygon(tb_shape_id shape, const tb_polygon* polygon);

/* ------------------------------------------------------------- collision -- */

/* Contacts are created this far before shapes touch (metres), so that the solver
 * can stop fast bodies without sweeping ("speculative" contacts). */
#define TB_SPECULATIVE_DISTANCE (4.0f * TB_LINEAR_SLOP)

/* One contact point. Feature ids stay the same while the same pair of features
 * (vertex/edge) touch, so the solver can warm-start from the last impulse. */
typedef struct tb_manifold_point {
  tb_vec2 point;    /* world point, midway between the two surfaces */
  float separation; /* signed gap along the normal; negative when overlapping */
  uint32_t id;      /* feature id */
  /* Impulses the solver applied at this point in the last substep of the
   * last step (N s; 0 from the tb_collide_* functions), along the normal and
   * along the tangent (n.y, -n.x). Divide by the substep, time_step /
   * substeps, for the contact force. A bounce (restitution), applied after
   * the substeps, is not in them: the next step starts from these. */
  float normal_impulse;
  float tangent_impulse;
} tb_manifold_point;

/* The contact of two convex shapes: 0, 1 or 2 points and a unit normal that
 * points from shape A to shape B. Points are reported while the separation is
 * below TB_SPECULATIVE_DISTANCE. */
typedef struct tb_manifold {
  tb_vec2 normal;
  tb_manifold_point points[2];
  int point_count;
} tb_manifold;

/* Contact manifolds of every pair of shape types, each shape placed by its
 * transform. Swapping the arguments gives the same points with the normal
 * reversed (each unordered pair has one function, named A first).
 * Errors give an empty manifold and a message naming the argument (shape a or
 * b, xfa or xfb): a NULL shape (TB_ERR_NULL_ARGUMENT); a shape that the shape
 * and mass functions refuse, or a transform that is not finite, beyond
 * TB_MAX_LENGTH or not a unit rotation (TB_ERR_INVALID_ARGUMENT). Refused
 * shapes: points, centres or radii not finite or beyond TB_MAX_LENGTH; a
 * circle or capsule radius not > 0; a polygon radius < 0; capsule centres or
 * segment points that coincide; a polygon whose count is outside 3 to
 * TB_MAX_POLYGON_VERTICES or that tb_make_polygon could not have made. */
tb_manifold tb_collide_circles(const tb_circle* a, tb_transform xfa, const tb_circle* b, tb_transform xfb);
tb_manifold tb_collide_capsule_and_circle(const tb_capsule* a, tb_transform xfa, const tb_circle* b, tb_transform xfb);
tb_manifold tb_collide_capsules(const tb_capsule* a, tb_transform xfa, const tb_capsule* b, tb_transform xfb);
tb_manifold tb_collide_segment_and_circle(const tb_segment* a, tb_transform xfa, const tb_circle* b, tb_transform xfb);
tb_manifold tb_collide_segment_and_capsule(const tb_segment* a, tb_transform xfa, const tb_capsule* b,
                                           tb_transform xfb);
tb_manifold tb_collide_segment_and_polygon(const tb_segment* a, tb_transform xfa, const tb_polygon* b,
                                           tb_transform xfb);
tb_manifold tb_collide_polygon_and_circle(const tb_polygon* a, tb_transform xfa, const tb_circle* b, tb_transform xfb);
tb_manifold tb_collide_polygon_and_capsule(const tb_polygon* a, tb_transform xfa, const tb_capsule* b,
                                           tb_transform xfb);
tb_manifold tb_collide_polygons(const tb_polygon* a, tb_transform xfa, const tb_polygon* b, tb_transform xfb);

/* A convex shape as GJK sees it: up to TB_MAX_POLYGON_VERTICES points plus a
 * radius (a circle is 1 point, a capsule or segment 2, a polygon its vertices). */
typedef struct tb_shape_proxy {
  tb_vec2 points[TB_MAX_POLYGON_VERTICES];
  int count;
  float radius;
} tb_shape_proxy;

/* -------------------------------------------------------------- geometry -- */

/* Queries on bare geometry (no world needed): bounding boxes, point tests,
 * closest points and ray casts of a circle, capsule, segment or polygon placed
 * by a transform (its local frame to world). Every function checks what it is
 * given: a NULL pointer is TB_ERR_NULL_ARGUMENT; geometry the shape functions
 * would refuse (see tb_collide_circles), a transform that is not finite, beyond
 * TB_MAX_LENGTH or not a unit rotation (|c^2 + s^2 - 1| <= 1e-3), or a point
 * not finite or beyond TB_MAX_LENGTH is TB_ERR_INVALID_ARGUMENT. A refused
 * call returns the value it documents for errors and leaves the message in
 * tb_last_error(). */

/* The tight world box around the geometry at xf (a capsule's and rounded
 * polygon's radius included). On error the zero box at the origin. */
tb_aabb tb_compute_circle_aabb(const tb_circle* circle, tb_transform xf);
tb_aabb tb_compute_capsule_aabb(const tb_capsule* capsule, tb_transform xf);
tb_aabb tb_compute_segment_aabb(const tb_segment* segment, tb_transform xf);
tb_aabb tb_compute_polygon_aabb(const tb_polygon* polygon, tb_transform xf);

/* Whether the world point lies in the geometry at xf, boundary included (a
 * rounded polygon is its core plus everything within radius). A segment has
 * no area and contains nothing: tb_point_in_segment is false for valid input
 * too, as for tb_world_overlap_point. On error false. */
bool tb_point_in_circle(const tb_circle* circle, tb_transform xf, tb_vec2 point);
bool tb_point_in_capsule(const tb_capsule* capsule, tb_transform xf, tb_vec2 point);
bool tb_point_in_segment(const tb_segment* segment, tb_transform xf, tb_vec2 point);
bool tb_point_in_polygon(const tb_polygon* polygon, tb_transform xf, tb_vec2 point);

/* The world point of the geometry at xf closest to a world point. The shapes
 * are solid: a point inside a circle, capsule or polygon (rounding included)
 * is its own closest point, returned unchanged; one outside gets a point on
 * the (rounded) surface. On error the zero vector. */
tb_vec2 tb_closest_point_on_circle(const tb_circle* circle, tb_transform xf, tb_vec2 point);
tb_vec2 tb_closest_point_on_capsule(const tb_capsule* capsule, tb_transform xf, tb_vec2 point);
tb_vec2 tb_closest_point_on_segment(const tb_segment* segment, tb_transform xf, tb_vec2 point);
tb_vec2 tb_closest_point_on_polygon(const tb_polygon* polygon, tb_transform xf, tb_vec2 point);

/* A ray from origin along origin + fraction * translation, fraction in
 * [0, max_fraction] (world; finite, within TB_MAX_LENGTH; max_fraction >= 0,
 * usually 1). */
typedef struct tb_ray_input {
  tb_vec2 origin;
  tb_vec2 translation;
  float max_fraction;
} tb_ray_input;

/* What a ray or shape cast hit. On a miss (or an error) everything is zero. */
typedef struct tb_cast_output {
  tb_vec2 point;  /* world: where the ray enters, or the contact point on A's surface */
  tb_vec2 normal; /* unit surface normal at the hit (of the shape, or of A towards B) */
  float fraction; /* of the translation, in [0, max_fraction] (shape casts: [0, 1]) */
  int iterations; /* of a shape cast; 0 for rays */
  bool hit;
} tb_cast_output;

/* Ray casts against the geometry at xf. The ray hits where it enters the
 * shape, with the outward normal there: a capsule and a rounded polygon are
 * hit on their rounded surface (radius included), as they collide. A ray that
 * starts strictly inside a circle, capsule or polygon does not hit it (as
 * tb_world_cast_ray); one that starts on the surface going in hits at fraction
 * 0. A segment is hit from either side, its normal facing the ray's origin; a
 * ray along its line does not hit it. A zero translation hits nothing (TB_OK).
 * Returns TB_OK or the error; out is always written (zero on a miss). */
tb_result tb_ray_cast_circle(const tb_ray_input* ray, const tb_circle* circle, tb_transform xf, tb_cast_output* out);
tb_result tb_ray_cast_capsule(const tb_ray_input* ray, const tb_capsule* capsule, tb_transform xf, tb_cast_output* out);
tb_result tb_ray_cast_segment(const tb_ray_input* ray, const tb_segment* segment, tb_transform xf, tb_cast_output* out);
tb_result tb_ray_cast_polygon(const tb_ray_input* ray, const tb_polygon* polygon, tb_transform xf, tb_cast_output* out);

/* A convex hull: 3 to TB_MAX_POLYGON_VERTICES points, counter-clockwise,
 * without near-duplicate or collinear points. */
typedef struct tb_hull {
  tb_vec2 points[TB_MAX_POLYGON_VERTICES];
  int count;
} tb_hull;

/* The hull of points, by the rules and errors of tb_make_polygon (welding,
 * collinear and interior points dropped; degenerate input or more than
 * TB_MAX_POLYGON_VERTICES hull points refused). On error out->count is 0,
 * which every function taking a hull refuses. */
tb_result tb_compute_hull(const tb_vec2* points, int count, tb_hull* out);
/* The polygon of a hull, rounded by radius (>= 0, within TB_MAX_LENGTH). The
 * hull must be one tb_compute_hull could have made (count 3 to
 * TB_MAX_POLYGON_VERTICES, finite points, none of them dropped when its hull
 * is taken again): else TB_ERR_INVALID_ARGUMENT (count, points, radius) or
 * TB_ERR_DEGENERATE_POLYGON. On error out is not written. */
tb_result tb_make_polygon_from_hull(const tb_hull* hull, float radius, tb_polygon* out);
/* The polygon of a hull turned by angle (within TB_MAX_ANGLE) and then moved
 * to position (body-local), optionally rounded; errors as
 * tb_make_polygon_from_hull, and TB_ERR_DEGENERATE_POLYGON when the placed
 * polygon collapses in float far from the origin. */
tb_result tb_make_offset_polygon(const tb_hull* hull, tb_vec2 position, float angle, tb_polygon* out);
tb_result tb_make_offset_rounded_polygon(const tb_hull* hull, tb_vec2 position, float angle, float radius,
                                         tb_polygon* out);
/* A rounded box (core half-extents hx, hy plus radius) centred at center and
 * rotated by angle; errors as tb_make_offset_box and tb_make_rounded_box. */
tb_result tb_make_offset_rounded_box(float hx, float hy, tb_vec2 center, float angle, float radius, tb_polygon* out);
/* The polygon placed by xf: vertices and centroid transformed, normals
 * rotated, radius kept. out may be polygon. Errors: NULL, a polygon the shape
 * functions refuse or a bad transform (TB_ERR_INVALID_ARGUMENT), a result
 * that collapses in float far out (TB_ERR_DEGENERATE_POLYGON); on error out
 * is not written. */
tb_result tb_transform_polygon(const tb_polygon* polygon, tb_transform xf, tb_polygon* out);

/* ------------------------------------------------------------- distance -- */

/* Distance, shape cast and time of impact of convex shapes seen as proxies
 * (tb_shape_proxy: a core of 1 to TB_MAX_POLYGON_VERTICES points inflated by a
 * radius). The points need not be a hull: GJK only takes support points, so
 * interior and repeated points are harmless. A proxy is good when its count is
 * in 1..TB_MAX_POLYGON_VERTICES, its radius >= 0 and its points and radius
 * finite and within TB_MAX_LENGTH; the functions below refuse any other
 * (TB_ERR_INVALID_ARGUMENT), and transforms as the geometry queries do. They
 * return TB_OK or the error, and always write their output: on error a miss
 * (no hit, distance FLT_MAX, state TB_TOI_FAILED at fraction 0). */

/* A proxy of count points and radius, in the caller's frame. On bad input
 * (NULL points, count outside 1..TB_MAX_POLYGON_VERTICES, a point or radius
 * not finite, negative or beyond TB_MAX_LENGTH) a proxy of count 0, which
 * every query refuses, and the error. */
tb_shape_proxy tb_make_proxy(const tb_vec2* points, int count, float radius);
/* The same with each point turned by angle (within TB_MAX_ANGLE) and then
 * moved by position; errors as tb_make_proxy, and a bad position or angle. */
tb_shape_proxy tb_make_offset_proxy(const tb_vec2* points, int count, float radius, tb_vec2 position, float angle);
/* The proxies of the geometry types, in the geometry's own frame (a circle is
 * 1 point, a capsule or segment 2, a polygon its vertices). Refused geometry
 * (as for the geometry queries) gives a proxy of count 0 and the error. */
tb_shape_proxy tb_make_circle_proxy(const tb_circle* circle);
tb_shape_proxy tb_make_capsule_proxy(const tb_capsule* capsule);
tb_shape_proxy tb_make_segment_proxy(const tb_segment* segment);
tb_shape_proxy tb_make_polygon_proxy(const tb_polygon* polygon);

typedef struct tb_segment_distance_output {
  tb_vec2 closest1, closest2; /* closest points on segment 1 and segment 2 */
  float fraction1, fraction2; /* closest_i = p_i + fraction_i (q_i - p_i), in [0, 1] */
  float distance_sq;          /* |closest2 - closest1|^2 */
} tb_segment_distance_output;

/* Closest points of segments p1-q1 and p2-q2 (either may have zero length).
 * Parallel overlapping segments have a whole family of closest pairs: the one
 * in the middle of the overlap is returned, so it does not jump between ends.
 * A point not finite or beyond TB_MAX_LENGTH is an error (TB_ERR_INVALID_ARGUMENT):
 * the result is then zero but distance_sq FLT_MAX. */
tb_segment_distance_output tb_segment_distance(tb_vec2 p1, tb_vec2 q1, tb_vec2 p2, tb_vec2 q2);

/* Warm start of tb_shape_distance: the vertex indices of the last simplex.
 * Zero it (count = 0) before the first call for a pair of proxies and pass it
 * to every later call for that pair; each call updates it. A cache that does
 * not fit the proxies (indices beyond their counts) is ignored (cold start). */
typedef struct tb_simplex_cache {
  uint8_t count;
  uint8_t index_a[3];
  uint8_t index_b[3];
} tb_simplex_cache;

typedef struct tb_distance_input {
  tb_shape_proxy proxy_a, proxy_b; /* each in its own frame */
  tb_transform xf_a, xf_b;         /* each proxy's frame to world */
} tb_distance_input;

/* Distance between the rounded shapes (radii included), clamped at 0. With the
 * surfaces apart, point_a and point_b lie on the two surfaces and normal is
 * the unit direction from point_a to point_b. When the rounded surfaces
 * overlap but the cores do not, both points are the midpoint of the two
 * surface points and normal is still the direction between the cores; when
 * the cores overlap, both points are a common point of the cores and normal
 * is zero. */
typedef struct tb_distance_output {
  tb_vec2 point_a, point_b; /* world */
  tb_vec2 normal;           /* unit, from A to B; zero when the cores overlap */
  float distance;           /* >= 0 */
  int iterations;           /* support point evaluations */
  int simplex_count;        /* 1 vertex, 2 edge, 3 overlap of the cores */
} tb_distance_output;

/* GJK distance between two placed proxies, computed in A's frame, so that far
 * from the origin only their relative placement counts. cache may be NULL. */
tb_result tb_shape_distance(const tb_distance_input* input, tb_simplex_cache* cache, tb_distance_output* output);

/* The tolerance (metres) to which shape casts converge: at the reported
 * fraction the gap between the rounded surfaces is in [0, TB_CAST_TOLERANCE]. */
#define TB_CAST_TOLERANCE 1.0e-4f

typedef struct tb_shape_cast_input {
  tb_shape_proxy proxy_a, proxy_b; /* each in its own frame */
  tb_transform xf_a, xf_b;         /* placement at the start of the cast */
  tb_vec2 translation_b;           /* world translation of B over the cast (A stays) */
} tb_shape_cast_input;

/* Sweeps B by fraction * translation_b, fraction in [0, 1], without rotation
 * (translation_b finite, each component within TB_MAX_LENGTH). hit is the
 * first fraction at which the rounded shapes come within TB_CAST_TOLERANCE,
 * never past the true contact; point is the contact point on A's surface and
 * normal A's surface normal there, towards B. Shapes that already touch or
 * overlap hit at fraction 0 (normal zero if their cores overlap). */
tb_result tb_shape_cast(const tb_shape_cast_input* input, tb_cast_output* output);

/* The motion of a body over an interval, by its centre of mass: position and
 * angle linear in the fraction t from t = 0 to t = 1. Points finite and within
 * TB_MAX_LENGTH; angles finite (the engine's own sweeps carry body angles,
 * which may wind beyond TB_MAX_ANGLE), at most TB_MAX_VALUE. */
typedef struct tb_sweep {
  tb_vec2 local_center; /* centre of mass in body coordinates */
  tb_vec2 c1, c2;       /* world centre of mass at t = 0 and t = 1 */
  float a1, a2;         /* angle at t = 0 and t = 1 (radians) */
} tb_sweep;

/* The body transform (of the body origin, not the centre) at fraction t of
 * the sweep. No checks: the caller's sweep and t are used as they are. */
tb_transform tb_sweep_transform(const tb_sweep* sweep, float t);

typedef struct tb_toi_input {
  tb_shape_proxy proxy_a, proxy_b; /* body coordinates */
  tb_sweep sweep_a, sweep_b;
  float max_fraction; /* the interval searched is [0, max_fraction], within [0, 1] */
  /* The gap between the rounded surfaces to stop at: TB_LINEAR_SLOP is a good
   * target, leaving room for contacts; finite and >= -(radius_a + radius_b). */
  float target;
  /* > 0 and finite: the gap at a hit is target +- tolerance; 0.25 *
   * TB_LINEAR_SLOP is what the engine uses. */
  float tolerance;
} tb_toi_input;

typedef enum tb_toi_state {
  TB_TOI_HIT = 0,    /* the gap reaches target (within tolerance) at fraction */
  TB_TOI_SEPARATED,  /* the gap stays above target over [0, max_fraction]; fraction = max_fraction */
  TB_TOI_OVERLAPPED, /* already closer than target - tolerance at 0; fraction = 0 */
  TB_TOI_FAILED      /* bad input, or no convergence: fraction is still a safe
                        time (the gap stays above target up to it) */
} tb_toi_state;

typedef struct tb_toi_output {
  tb_toi_state state;
  float fraction;
  int iterations; /* advancement steps (one GJK call each) */
} tb_toi_output;

/* Time of impact of two moving proxies by conservative advancement: never
 * steps past the first time the gap falls to the target, also for contacts
 * made by rotation that end again before max_fraction. */
tb_result tb_time_of_impact(const tb_toi_input* input, tb_toi_output* output);

/* ---------------------------------------------------------------- chains -- */

/* A chain: a polyline (open) or polygon outline (loop) of segments for terrain
 * and walls. Chains are one-sided: shapes collide only with the left side of
 * each segment, walking from points[i] to points[i + 1]. So terrain listed left
 * to right faces up, a counter-clockwise loop holds things inside it and a
 * clockwise loop keeps them out. Each segment knows its neighbours ("ghost
 * vertices"), so a body sliding across a joint of a flat or concave chain
 * meets a smooth surface and never catches on the corner. */
typedef struct tb_chain_segment {
  tb_vec2 ghost1; /* the vertex before point1 (= point1 at the start of an open chain) */
  tb_segment segment;
  tb_vec2 ghost2; /* the vertex after point2 (= point2 at the end of an open chain) */
} tb_chain_segment;

typedef struct tb_chain_def {
  const tb_vec2* points; /* body-local, at least 2 (3 for a loop) */
  int count;
  bool is_loop;
  float friction;    /* default 0.6 */
  float restitution; /* in [0, 1], default 0 */
  tb_filter filter;
  bool enable_sensor_events; /* default true */
  void* user_data;           /* given to every segment shape */
} tb_chain_def;

tb_chain_def tb_default_chain_def(void);

/* Creates one TB_SHAPE_CHAIN_SEGMENT shape per segment. Errors: NULL, too few
 * points, non-finite points, consecutive points closer than TB_LINEAR_SLOP. */
tb_chain_id tb_create_chain(tb_body_id body, const tb_chain_def* def);
tb_result tb_destroy_chain(tb_chain_id chain);
bool tb_chain_is_valid(tb_chain_id chain);
int tb_chain_get_segment_count(tb_chain_id chain);
/* Up to capacity of the chain's segment shapes, in order; returns the number written. */
int tb_chain_get_segments(tb_chain_id chain, tb_shape_id* out, int capacity);
tb_result tb_shape_get_chain_segment(tb_shape_id shape, tb_chain_segment* out);

/* Chain segment manifolds (A is the chain segment; nothing from behind it).
 * Errors as for the other manifolds; the chain segment's ghost vertices must
 * be finite and within TB_MAX_LENGTH too. */
tb_manifold tb_collide_chain_segment_and_circle(const tb_chain_segment* a, tb_transform xfa, const tb_circle* b,
                                                tb_transform xfb);
tb_manifold tb_collide_chain_segment_and_capsule(const tb_chain_segment* a, tb_transform xfa, const tb_capsule* b,
                                                 tb_transform xfb);
tb_manifold tb_collide_chain_segment_and_polygon(const tb_chain_segment* a, tb_transform xfa, const tb_polygon* b,
                                                 tb_transform xfb);

/* ---------------------------------------------------------------- joints -- */

/* Joints constrain two bodies. Anchors are in each body's own frame (relative
 * to the body origin). Every joint can be created and destroyed at any time
 * outside the step, also while its bodies sleep (it wakes them). Rigid parts
 * of a joint are held exactly where the joints form a tree, and otherwise as
 * soft constraints with the world's joint_hertz and joint_damping_ratio for
 * drift (see tb_world_def); springs use their own hertz and damping ratio
 * (hertz 0 means no spring). Errors: both bodies the same, bodies of different
 * worlds, non-finite numbers, angles (reference angles, angle limits, angular
 * offsets) beyond TB_MAX_ANGLE, lower > upper limits, negative forces, hertz
 * or damping ratios. */
typedef enum tb_joint_type {
  TB_JOINT_DISTANCE = 0,
  TB_JOINT_MOTOR,
  TB_JOINT_MOUSE,
  TB_JOINT_PRISMATIC,
  TB_JOINT_REVOLUTE,
  TB_JOINT_WELD,
  TB_JOINT_WHEEL
} tb_joint_type;

/* Keeps two anchor points at a distance: rigid, or a spring of hertz with
 * min/max length limits. Default: rigid, length 1, limits 0 and TB_MAX_LENGTH. */
typedef struct tb_distance_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 local_anchor_a, local_anchor_b;
  float length; /* rest length, >= TB_LINEAR_SLOP */
  bool enable_spring;
  float hertz, damping_ratio; /* >= 0 */
  bool enable_limit;
  float min_length, max_length;
  bool enable_motor;
  float max_motor_force;  /* N, >= 0 */
  float motor_speed;      /* m/s, lengthening */
  bool collide_connected; /* default false: the two bodies do not collide */
  void* user_data;
} tb_distance_joint_def;

/* A shared point (pin): B rotates about the anchor relative to A. The angle is
 * angle_b - angle_a - reference_angle. */
typedef struct tb_revolute_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 local_anchor_a, local_anchor_b;
  float reference_angle;
  bool enable_limit;
  float lower_angle, upper_angle; /* radians, lower <= upper */
  bool enable_motor;
  float max_motor_torque; /* N m, >= 0 */
  float motor_speed;      /* rad/s */
  bool enable_spring;     /* a torsional spring towards angle 0 */
  float hertz, damping_ratio;
  bool collide_connected;
  void* user_data;
} tb_revolute_joint_def;

/* B slides along an axis fixed in A, without relative rotation. */
typedef struct tb_prismatic_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 local_anchor_a, local_anchor_b;
  tb_vec2 local_axis_a; /* unit (normalised on creation), default (1, 0) */
  float reference_angle;
  bool enable_limit;
  float lower_translation, upper_translation; /* metres, lower <= upper */
  bool enable_motor;
  float max_motor_force; /* N, >= 0 */
  float motor_speed;     /* m/s */
  bool enable_spring;    /* towards translation 0 */
  float hertz, damping_ratio;
  bool collide_connected;
  void* user_data;
} tb_prismatic_joint_def;

/* Glues B to A. Hertz 0 makes that part rigid; otherwise a spring. */
typedef struct tb_weld_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 local_anchor_a, local_anchor_b;
  float reference_angle;
  float linear_hertz, angular_hertz; /* >= 0, default 0 (rigid) */
  float linear_damping_ratio, angular_damping_ratio;
  bool collide_connected;
  void* user_data;
} tb_weld_joint_def;

/* A wheel (B) on a suspension axis fixed in A: a spring along the axis, free
 * rotation with an optional motor. Default spring 1 Hz, damping ratio 0.7. */
typedef struct tb_wheel_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 local_anchor_a, local_anchor_b;
  tb_vec2 local_axis_a; /* unit, default (0, 1) */
  bool enable_spring;   /* default true */
  float hertz, damping_ratio;
  bool enable_limit;
  float lower_translation, upper_translation;
  bool enable_motor;
  float max_motor_torque; /* N m, >= 0 */
  float motor_speed;      /* rad/s */
  bool collide_connected;
  void* user_data;
} tb_wheel_joint_def;

/* Pulls a point of B (the target's position at creation, kept in B's frame)
 * towards a moving world target with a soft spring, at most max_force. For
 * dragging with the mouse. body_a is only a reference (usually the ground).
 * Default 5 Hz, damping ratio 0.7, max_force 1000 N. */
typedef struct tb_mouse_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 target; /* world point */
  float hertz, damping_ratio;
  float max_force;        /* N, >= 0 */
  bool collide_connected; /* default true */
  void* user_data;
} tb_mouse_joint_def;

/* Drives B towards a pose relative to A (linear_offset: B's centre in A's
 * frame; angular_offset: angle_b - angle_a) with at most max_force and
 * max_torque; for top-down friction and animated bodies. correction_factor in
 * [0, 1] (default 0.3) is the fraction of the pose error corrected per step.
 * Defaults: max_force 1 N, max_torque 1 N m. */
typedef struct tb_motor_joint_def {
  tb_body_id body_a, body_b;
  tb_vec2 linear_offset;
  float angular_offset;
  float max_force, max_torque;
  float correction_factor;
  bool collide_connected;
  void* user_data;
} tb_motor_joint_def;

tb_distance_joint_def tb_default_distance_joint_def(void);
tb_revolute_joint_def tb_default_revolute_joint_def(void);
tb_prismatic_joint_def tb_default_prismatic_joint_def(void);
tb_weld_joint_def tb_default_weld_joint_def(void);
tb_wheel_joint_def tb_default_wheel_joint_def(void);
tb_mouse_joint_def tb_default_mouse_joint_def(void);
tb_motor_joint_def tb_default_motor_joint_def(void);

/* Create a joint; returns the null handle on error (see tb_last_error()). */
tb_joint_id tb_create_distance_joint(tb_world_id world, const tb_distance_joint_def* def);
tb_joint_id tb_create_revolute_joint(tb_world_id world, const tb_revolute_joint_def* def);
tb_joint_id tb_create_prismatic_joint(tb_world_id world, const tb_prismatic_joint_def* def);
tb_joint_id tb_create_weld_joint(tb_world_id world, const tb_weld_joint_def* def);
tb_joint_id tb_create_wheel_joint(tb_world_id world, const tb_wheel_joint_def* def);
tb_joint_id tb_create_mouse_joint(tb_world_id world, const tb_mouse_joint_def* def);
tb_joint_id tb_create_motor_joint(tb_world_id world, const tb_motor_joint_def* def);
/* Destroying a body destroys its joints. */
tb_result tb_destroy_joint(tb_joint_id joint);
bool tb_joint_is_valid(tb_joint_id joint);

tb_joint_type tb_joint_get_type(tb_joint_id joint);
tb_body_id tb_joint_get_body_a(tb_joint_id joint);
tb_body_id tb_joint_get_body_b(tb_joint_id joint);
tb_vec2 tb_joint_get_local_anchor_a(tb_joint_id joint);
tb_vec2 tb_joint_get_local_anchor_b(tb_joint_id joint);
bool tb_joint_get_collide_connected(tb_joint_id joint);
tb_result tb_joint_set_collide_connected(tb_joint_id joint, bool collide);
void* tb_joint_get_user_data(tb_joint_id joint);
tb_result tb_joint_set_user_data(tb_joint_id joint, void* user_data);
/* The force (N) and torque (N m) the joint applied to body B in the last
 * substep of the last step (its impulse over the substep), saturated at
 * +-TB_MAX_VALUE; the motor torque and force getters likewise. */
tb_vec2 tb_joint_get_constraint_force(tb_joint_id joint);
float tb_joint_get_constraint_torque(tb_joint_id joint);

/* Distance joint. */
tb_result tb_distance_joint_set_length(tb_joint_id joint, float length);
float tb_distance_joint_get_length(tb_joint_id joint);
float tb_distance_joint_get_current_length(tb_joint_id joint);
tb_result tb_distance_joint_set_spring(tb_joint_id joint, bool enable, float hertz, float damping_ratio);
tb_result tb_distance_joint_set_limits(tb_joint_id joint, bool enable, float min_length, float max_length);

/* Revolute joint. */
float tb_revolute_joint_get_angle(tb_joint_id joint);
tb_result tb_revolute_joint_set_limits(tb_joint_id joint, bool enable, float lower, float upper);
tb_result tb_revolute_joint_set_motor(tb_joint_id joint, bool enable, float speed, float max_torque);
tb_result tb_revolute_joint_set_spring(tb_joint_id joint, bool enable, float hertz, float damping_ratio);
float tb_revolute_joint_get_motor_torque(tb_joint_id joint);

/* Prismatic joint. */
float tb_prismatic_joint_get_translation(tb_joint_id joint);
float tb_prismatic_joint_get_speed(tb_joint_id joint);
tb_result tb_prismatic_joint_set_limits(tb_joint_id joint, bool enable, float lower, float upper);
tb_result tb_prismatic_joint_set_motor(tb_joint_id joint, bool enable, float speed, float max_force);
tb_result tb_prismatic_joint_set_spring(tb_joint_id joint, bool enable, float hertz, float damping_ratio);
float tb_prismatic_joint_get_motor_force(tb_joint_id joint);

/* Weld joint. */
tb_result tb_weld_joint_set_stiffness(tb_joint_id joint, float linear_hertz, float linear_damping_ratio,
                                      float angular_hertz, float angular_damping_ratio);

/* Wheel joint. */
tb_result tb_wheel_joint_set_motor(tb_joint_id joint, bool enable, float speed, float max_torque);
tb_result tb_wheel_joint_set_spring(tb_joint_id joint, bool enable, float hertz, float damping_ratio);
float tb_wheel_joint_get_motor_torque(tb_joint_id joint);

/* Mouse joint. */
tb_result tb_mouse_joint_set_target(tb_joint_id joint, tb_vec2 target);
tb_vec2 tb_mouse_joint_get_target(tb_joint_id joint);

/* Motor joint. */
tb_result tb_motor_joint_set_offsets(tb_joint_id joint, tb_vec2 linear_offset, float angular_offset);

/* --------------------------------------------------------------- queries -- */

/* Which shapes a query sees: those with (shape.category_bits & mask_bits) != 0
 * and (shape.mask_bits & category_bits) != 0. Queries never see destroyed shapes
 * nor the shapes of disabled bodies; sensors are seen unless skip_sensors. */
typedef struct tb_query_filter {
  uint64_t category_bits; /* default 1 */
  uint64_t mask_bits;     /* default all bits */
  bool skip_sensors;      /* default false */
} tb_query_filter;

tb_query_filter tb_default_query_filter(void);

/* Overlap callbacks: return false to stop the query. */
typedef bool tb_overlap_fn(tb_shape_id shape, void* context);

/* Cast callbacks get each hit (point, normal at the surface, fraction of the
 * translation) in no particular order. Return -1 to ignore this shape, 0 to stop,
 * the fraction to clip the cast to this hit (closest hit), 1 to go on unclipped. */
typedef float tb_cast_fn(tb_shape_id shape, tb_vec2 point, tb_vec2 normal, float fraction, void* context);

typedef struct tb_ray_result {
  tb_shape_id shape;
  tb_vec2 point;
  tb_vec2 normal;
  float fraction;
  bool hit;
} tb_ray_result;

/* Rays go from origin to origin + translation (translation must not be zero).
 * A ray that starts inside a shape does not hit that shape. */
tb_result tb_world_cast_ray(tb_world_id world, tb_vec2 origin, tb_vec2 translation, tb_query_filter filter,
                            tb_cast_fn* fn, void* context);
/* The closest hit; when there is none (or on error) .hit is false, .fraction
 * 1 and the rest zero, as for a ray that hits nothing. */
tb_ray_result tb_world_cast_ray_closest(tb_world_id world, tb_vec2 origin, tb_vec2 translation, tb_query_filter filter);
/* Every hit, nearest first: writes up to capacity into out and the number of hits
 * (which may exceed capacity) into *count. */
tb_result tb_world_cast_ray_all(tb_world_id world, tb_vec2 origin, tb_vec2 translation, tb_query_filter filter,
                                tb_ray_result* out, int capacity, int* count);
/* Shapes whose bounding box overlaps the box. */
tb_result tb_world_overlap_aabb(tb_world_id world, tb_aabb aabb, tb_query_filter filter, tb_overlap_fn* fn,
                                void* context);
/* Shapes that contain the point (segments contain nothing). */
tb_result tb_world_overlap_point(tb_world_id world, tb_vec2 point, tb_query_filter filter, tb_overlap_fn* fn,
                                 void* context);
/* Shapes that overlap a convex proxy placed by a transform. */
tb_result tb_world_overlap_shape(tb_world_id world, const tb_shape_proxy* proxy, tb_transform transform,
                                 tb_query_filter filter, tb_overlap_fn* fn, void* context);
/* A convex proxy swept along translation: the shapes it hits, as with rays. */
tb_result tb_world_cast_shape(tb_world_id world, const tb_shape_proxy* proxy, tb_transform transform,
                              tb_vec2 translation, tb_query_filter filter, tb_cast_fn* fn, void* context);

/* ---------------------------------------------------------------- events -- */

/* Events of the last step, as arrays the game reads after tb_world_step (they
 * stay valid until the next step or the world's destruction). No callbacks run
 * inside the step for these. Shape handles in end events may already be stale
 * when the end was caused by destroying the shape or its body. */
typedef struct tb_contact_begin_event {
  tb_shape_id shape_a, shape_b;
  tb_manifold manifold;
} tb_contact_begin_event;

typedef struct tb_contact_end_event {
  tb_shape_id shape_a, shape_b;
} tb_contact_end_event;

/* A contact that began with an approach speed above the world's threshold. */
typedef struct tb_contact_hit_event {
  tb_shape_id shape_a, shape_b;
  tb_vec2 point;
  tb_vec2 normal;       /* from A to B */
  float approach_speed; /* m/s, > 0 */
} tb_contact_hit_event;

typedef struct tb_contact_events {
  const tb_contact_begin_event* begin_events;
  const tb_contact_end_event* end_events;
  const tb_contact_hit_event* hit_events;
  int begin_count, end_count, hit_count;
} tb_contact_events;

tb_contact_events tb_world_get_contact_events(tb_world_id world);

typedef struct tb_sensor_event {
  tb_shape_id sensor, visitor;
} tb_sensor_event;

typedef struct tb_sensor_events {
  const tb_sensor_event* begin_events;
  const tb_sensor_event* end_events;
  int begin_count, end_count;
} tb_sensor_events;

tb_sensor_events tb_world_get_sensor_events(tb_world_id world);

/* A contact as the game can inspect it. */
typedef struct tb_contact_data {
  tb_shape_id shape_a, shape_b;
  tb_manifold manifold;
  float friction, restitution; /* mixed */
  bool touching;               /* the manifold has points */
  bool enabled;                /* false when the pre-solve callback disabled it */
} tb_contact_data;

/* Up to capacity of the body's contacts (sensor overlaps excluded); returns the
 * number written. tb_body_get_contact_capacity tells how many there are. */
int tb_body_get_contact_capacity(tb_body_id body);
int tb_body_get_contact_data(tb_body_id body, tb_contact_data* out, int capacity);

/* Number of shapes on a body, and up to capacity of their handles. */
int tb_body_get_shape_count(tb_body_id body);
int tb_body_get_shapes(tb_body_id body, tb_shape_id* out, int capacity);

/* ------------------------------------------------------------ debug draw -- */

/* Debug draw: the world hands its shapes, joints, contacts and bounding boxes to
 * the game's drawing functions, in world coordinates (metres), with a colour
 * that tells each body's state. Games plug in their own renderer; the
 * off-screen renderer libtumble-render (tumble_render.h) draws through it with
 * OpenGL.
 *
 * Fill a tb_debug_draw from tb_default_debug_draw(), set the callbacks you have
 * (a NULL callback means "skip what it would draw") and the switches, then call
 * tb_world_draw between steps. Order: static bodies' shapes, then the other
 * bodies' shapes, joints, AABBs, contacts, centres of mass, masses. */

/* A colour: red, green, blue in [0, 1] (sRGB, as a screen shows them) and
 * alpha (1 opaque, 0 invisible). */
typedef struct tb_color {
  float r, g, b, a;
} tb_color;

/* The colours tb_world_draw uses; tb_default_debug_draw() fills them. A body's
 * shapes take the first that applies: disabled, static, kinematic, asleep,
 * bullet, awake. Sensor shapes take sensor (nothing inside) or sensor_active
 * (some shape overlaps them), whatever their body. */
typedef struct tb_debug_colors {
  tb_color static_body;
  tb_color kinematic_body;
  tb_color awake_body; /* dynamic and simulated */
  tb_color asleep_body;
  tb_color bullet_body; /* awake and is_bullet */
  tb_color disabled_body;
  tb_color sensor;
  tb_color sensor_active;
  tb_color joint;
  tb_color aabb;
  tb_color contact_point;     /* touching (negative separation) */
  tb_color speculative_point; /* within TB_SPECULATIVE_DISTANCE, not yet touching */
  tb_color contact_normal;    /* from shape A to shape B */
  tb_color text;              /* masses */
} tb_debug_colors;

/* Draws a convex polygon placed by transform: count (3 to
 * TB_MAX_POLYGON_VERTICES) vertices in the polygon's frame, counter-clockwise,
 * rounded by radius (>= 0: the points within radius of the polygon). Chains of
 * boxes, walls and grounds come through here. */
typedef void tb_draw_solid_polygon_fn(tb_transform transform, const tb_vec2* vertices, int count, float radius,
                                      tb_color color, void* context);
/* Draws a disc; transform.p is its centre and transform.q its rotation, for a
 * mark (e.g. a radius towards transform.q) that shows the disc turning. */
typedef void tb_draw_solid_circle_fn(tb_transform transform, float radius, tb_color color, void* context);
/* Draws a capsule: the points within radius of the segment p1-p2 (world). */
typedef void tb_draw_solid_capsule_fn(tb_vec2 p1, tb_vec2 p2, float radius, tb_color color, void* context);
/* Draws a line segment (segment shapes, chain segments, joints, AABB sides,
 * contact normals). */
typedef void tb_draw_segment_fn(tb_vec2 p1, tb_vec2 p2, tb_color color, void* context);
/* Draws a dot of size pixels across, whatever the zoom (contact points, joint
 * anchors). */
typedef void tb_draw_point_fn(tb_vec2 p, float size, tb_color color, void* context);
/* Draws a frame: transform.p is a body's centre of mass and transform.q its
 * rotation (e.g. a short red x axis and green y axis). */
typedef void tb_draw_transform_fn(tb_transform transform, void* context);
/* Draws text at a world point (optional; used for masses). */
typedef void tb_draw_string_fn(tb_vec2 p, const char* text, tb_color color, void* context);

typedef struct tb_debug_draw {
  tb_draw_solid_polygon_fn* draw_solid_polygon;
  tb_draw_solid_circle_fn* draw_solid_circle;
  tb_draw_solid_capsule_fn* draw_solid_capsule;
  tb_draw_segment_fn* draw_segment;
  tb_draw_point_fn* draw_point;
  tb_draw_transform_fn* draw_transform;
  tb_draw_string_fn* draw_string;
  void* context; /* handed to every callback */

  /* What to draw. Defaults: shapes and joints. */
  bool draw_shapes;
  bool draw_joints;
  bool draw_aabbs;           /* each shape's tight AABB, as four segments */
  bool draw_contact_points;  /* manifold points of touching, non-sensor contacts */
  bool draw_contact_normals; /* a segment of normal_length from each point */
  bool draw_centers_of_mass; /* through draw_transform, for non-static bodies */
  bool draw_masses;          /* "<mass> kg" at each dynamic body's centre */
  /* Draw only what overlaps drawing_bounds (e.g. the camera's view); default
   * false: everything. */
  bool use_drawing_bounds;
  tb_aabb drawing_bounds;
  float normal_length; /* metres, > 0, default 0.3 */
  float point_size;    /* pixels, > 0, default 5 */
  tb_debug_colors colors;
} tb_debug_draw;

/* Callbacks NULL, shapes and joints on, the default colours. */
tb_debug_draw tb_default_debug_draw(void);

/* Draws the world through the callbacks, which run with the world locked
 * (reads are fine; changes get TB_ERR_LOCKED). Errors: NULL draw, a null or
 * stale world, a call from inside tb_world_step or a callback (TB_ERR_LOCKED), non-finite or
 * non-positive normal_length or point_size, drawing bounds that are not finite,
 * reach beyond TB_MAX_LENGTH or have lower > upper (when used), a colour
 * component outside [0, 1] (NaN included). The world is never changed. */
tb_result tb_world_draw(tb_world_id world, const tb_debug_draw* draw);

/* ---------------------------------------------------------- dynamic tree -- */

/* A dynamic AABB tree for the game's own use (its own broad phase, trigger
 * volumes, AI sight lines, particles): the bounding volume hierarchy the world
 * uses for its shapes, on boxes and user data the game supplies. Each proxy
 * holds a fat box (its box grown by the tree's margin on every side),
 * category bits and a user data pointer. A tree of n proxies is at most about
 * 1.44 log2 n high whatever the insertion order; the same calls give the
 * same tree. Not thread-safe: use one tree from one thread at a time.
 *
 * Proxy ids are >= 0 and stay the same for the proxy's life. An id that is
 * not a live proxy (negative, never handed out, destroyed) is refused with
 * TB_ERR_INVALID_ARGUMENT; a destroyed proxy's id may be handed out again to
 * a later proxy, so drop ids when you destroy their proxies. Boxes must be
 * finite, within TB_MAX_LENGTH and have lower <= upper. Changes (every call
 * that takes a non-const tree) from inside a query or ray cast callback of
 * the same tree are refused with TB_ERR_LOCKED; nested queries are allowed.
 * A refused call changes nothing. */
typedef struct tb_dynamic_tree tb_dynamic_tree;

#define TB_NULL_PROXY (-1)

/* An empty tree whose fat boxes are the boxes given grown by margin (metres,
 * finite, 0 to TB_MAX_LENGTH; 0 stores the boxes as they are, as Box2D v3's
 * tree does; the world's trees use 0.1). NULL on error. */
tb_dynamic_tree* tb_dynamic_tree_create(float margin);
tb_result tb_dynamic_tree_destroy(tb_dynamic_tree* tree);

/* Inserts a proxy for a box; returns its id, or TB_NULL_PROXY on error. */
int32_t tb_dynamic_tree_create_proxy(tb_dynamic_tree* tree, tb_aabb aabb, uint64_t category_bits, void* user_data);
tb_result tb_dynamic_tree_destroy_proxy(tb_dynamic_tree* tree, int32_t proxy);
/* The proxy's box is now aabb and is expected to move by about displacement
 * before the next call ({0, 0}: no prediction). The proxy is re-inserted,
 * with a new fat box stretched along displacement, only when aabb leaves its
 * fat box or the fat box has grown more than twice the one it would get now;
 * *reinserted (may be NULL) tells whether it was. displacement: finite, each
 * component within TB_MAX_LENGTH. */
tb_result tb_dynamic_tree_move_proxy(tb_dynamic_tree* tree, int32_t proxy, tb_aabb aabb, tb_vec2 displacement,
                                     bool* reinserted);
/* Rebuilds the whole hierarchy top-down (for sets that stopped changing, e.g.
 * a level just loaded): ids, fat boxes and user data are kept. */
tb_result tb_dynamic_tree_rebuild(tb_dynamic_tree* tree);

/* Query callback: a proxy whose fat box overlaps the query box (touching
 * counts); return false to stop the query. */
typedef bool tb_dynamic_tree_query_fn(int32_t proxy, void* user_data, void* context);
/* Calls fn for every proxy with (category_bits & mask_bits) != 0 whose fat box
 * overlaps aabb, in no particular order. */
tb_result tb_dynamic_tree_query(const tb_dynamic_tree* tree, tb_aabb aabb, uint64_t mask_bits,
                                tb_dynamic_tree_query_fn* fn, void* context);

/* The segment origin + t translation for 0 <= t <= max_fraction (origin and
 * translation finite and within TB_MAX_LENGTH, max_fraction in [0,
 * TB_MAX_LENGTH]). A zero translation tests the point origin. */
typedef struct tb_dynamic_tree_ray_input {
  tb_vec2 origin;
  tb_vec2 translation;
  float max_fraction;
} tb_dynamic_tree_ray_input;

/* Ray callback: a proxy whose fat box the segment, clipped to the current max
 * fraction, touches (input holds that clipped segment). Cast against your own
 * object and return: 0 to stop, a negative value to ignore this proxy, the
 * hit's fraction to clip the ray there (closest hit), or input->max_fraction
 * to go on unclipped (a value at or above the current max fraction changes
 * nothing, as does NaN). */
typedef float tb_dynamic_tree_ray_fn(const tb_dynamic_tree_ray_input* input, int32_t proxy, void* user_data,
                                     void* context);
/* Calls fn for the proxies with (category_bits & mask_bits) != 0 whose fat box
 * the segment touches, nearer boxes first along each branch (not a global
 * sort: keep the closest hit by clipping). */
tb_result tb_dynamic_tree_ray_cast(const tb_dynamic_tree* tree, const tb_dynamic_tree_ray_input* input,
                                   uint64_t mask_bits, tb_dynamic_tree_ray_fn* fn, void* context);

/* Checks the tree's invariants: links, free list, counts, heights, category
 * bits, every internal box the union of its children's, one user data slot
 * per proxy. TB_OK, or TB_ERR_INVALID_ARGUMENT naming what is broken (only
 * memory corruption breaks them). */
tb_result tb_dynamic_tree_validate(const tb_dynamic_tree* tree);

/* The bytes the tree holds through the allocator (tb_set_allocator): its
 * record, its nodes and the proxies' user data slots; 0 for NULL. */
size_t tb_dynamic_tree_get_byte_count(const tb_dynamic_tree* tree);
/* Edges on the longest root-to-leaf path (0 for an empty or one-proxy tree). */
int tb_dynamic_tree_get_height(const tb_dynamic_tree* tree);
int tb_dynamic_tree_get_proxy_count(const tb_dynamic_tree* tree);
/* The sum of the internal nodes' perimeters over the root's: lower is a better
 * tree (0 with fewer than two proxies). */
float tb_dynamic_tree_get_area_ratio(const tb_dynamic_tree* tree);
/* Getters of a proxy: NULL, a zero box, 0 for a bad tree or id. */
void* tb_dynamic_tree_get_user_data(const tb_dynamic_tree* tree, int32_t proxy);
tb_aabb tb_dynamic_tree_get_fat_aabb(const tb_dynamic_tree* tree, int32_t proxy);
uint64_t tb_dynamic_tree_get_category_bits(const tb_dynamic_tree* tree, int32_t proxy);
tb_result tb_dynamic_tree_set_user_data(tb_dynamic_tree* tree, int32_t proxy, void* user_data);
tb_result tb_dynamic_tree_set_category_bits(tb_dynamic_tree* tree, int32_t proxy, uint64_t category_bits);

#ifdef __cplusplus
}
#endif

#endif /* TUMBLE_H */
