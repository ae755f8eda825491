/* Error reporting: every rejected call records a code and a message that names
 * the function and the argument (thread-local, and on the world when known). */
#ifndef TB_ERROR_H
#define TB_ERROR_H

#include "tumble.h"

struct tb_world;

#if defined(__GNUC__)
#define TB_PRINTF(a, b) __attribute__((format(printf, a, b)))
#else
#define TB_PRINTF(a, b)
#endif

/* Records the error and returns r, so callers can write `return tb_fail(...)`. */
tb_result tb_fail(struct tb_world* world, tb_result r, const char* fmt, ...) TB_PRINTF(3, 4);

/* The shared range checks: record "fn: name = x must be >= 0 (> 0) and
 * finite" and return its code, or TB_OK. */
tb_result tb_check_non_negative(struct tb_world* world, const char* fn, const char* name, float x);
tb_result tb_check_positive(struct tb_world* world, const char* fn, const char* name, float x);
/* The ranges of tumble.h: a restitution in [0, 1], an angle within
 * TB_MAX_ANGLE, a gravity no longer than TB_MAX_GRAVITY (all finite). */
tb_result tb_check_restitution(struct tb_world* world, const char* fn, const char* name, float x);
tb_result tb_check_angle(struct tb_world* world, const char* fn, const char* name, float x);
tb_result tb_check_gravity(struct tb_world* world, const char* fn, const char* name, tb_vec2 g);

#define TB_ERROR_MESSAGE_CAPACITY 256

#endif
