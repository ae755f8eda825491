/* Length units (tb_set_length_units_per_meter): the length tolerances of the
 * engine in the game's units. Set only while no world exists, so every world
 * sees them constant and threads only read them. */
#ifndef TB_UNITS_H
#define TB_UNITS_H

typedef struct tb_length_scale {
  float units_per_meter;
  float linear_slop;          /* TB_LINEAR_SLOP */
  float speculative_distance; /* TB_SPECULATIVE_DISTANCE */
  float aabb_margin;          /* the broad phase's fattening */
  float max_speed;            /* TB_MAX_SPEED */
  float max_gravity;          /* TB_MAX_GRAVITY */
} tb_length_scale;

/* The current scale (all at their metre values by default). */
extern tb_length_scale tb_units;

/* A length (or speed, acceleration) given in metres, in the game's units:
 * exactly x at the default of 1. */
static inline float tb_meters(float x) { return x * tb_units.units_per_meter; }

#endif
