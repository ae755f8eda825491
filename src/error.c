#include "error.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "memory.h"
#include "world.h"
#include "units.h"

static _Thread_local char last_message[TB_ERROR_MESSAGE_CAPACITY];
static _Thread_local tb_result last_code = TB_OK;

tb_result tb_fail(struct tb_world* world, tb_result r, const char* fmt, ...) {
  char body[TB_ERROR_MESSAGE_CAPACITY - 32];
  va_list args;
  va_start(args, fmt);
  vsnprintf(body, sizeof body, fmt, args);
  va_end(args);
  snprintf(last_message, sizeof last_message, "%s: %s", tb_result_name(r), body);
  last_code = r;
  if (world != NULL) {
    memcpy(world->last_error, last_message, sizeof world->last_error);
  }
  tb_log(last_message);
  return r;
}

const char* tb_last_error(void) { return last_message; }
tb_result tb_last_result(void) { return last_code; }

void tb_clear_error(void) {
  last_message[0] = '\0';
  last_code = TB_OK;
}

const char* tb_result_name(tb_result r) {
  switch (r) {
    case TB_OK: return "TB_OK";
    case TB_ERR_NULL_ARGUMENT: return "TB_ERR_NULL_ARGUMENT";
    case TB_ERR_INVALID_ARGUMENT: return "TB_ERR_INVALID_ARGUMENT";
    case TB_ERR_STALE_HANDLE: return "TB_ERR_STALE_HANDLE";
    case TB_ERR_FOREIGN_HANDLE: return "TB_ERR_FOREIGN_HANDLE";
    case TB_ERR_DEGENERATE_POLYGON: return "TB_ERR_DEGENERATE_POLYGON";
    case TB_ERR_TOO_MANY_VERTICES: return "TB_ERR_TOO_MANY_VERTICES";
    case TB_ERR_OUT_OF_MEMORY: return "TB_ERR_OUT_OF_MEMORY";
    case TB_ERR_CAPACITY: return "TB_ERR_CAPACITY";
    case TB_ERR_LOCKED: return "TB_ERR_LOCKED";
    case TB_ERR_WRONG_BODY_TYPE: return "TB_ERR_WRONG_BODY_TYPE";
    case TB_ERR_NUMERIC: return "TB_ERR_NUMERIC";
  }
  return "TB_ERR_UNKNOWN";
}

tb_result tb_check_non_negative(struct tb_world* w, const char* fn, const char* name, float x) {
  if (isfinite(x) && fabsf(x) <= TB_MAX_VALUE && x >= 0.0f) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be >= 0 and finite", fn, name, (double)x);
}

tb_result tb_check_positive(struct tb_world* w, const char* fn, const char* name, float x) {
  if (isfinite(x) && fabsf(x) <= TB_MAX_VALUE && x > 0.0f) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be > 0 and finite", fn, name, (double)x);
}

tb_result tb_check_restitution(struct tb_world* w, const char* fn, const char* name, float x) {
  if (x >= 0.0f && x <= 1.0f) return TB_OK; /* false for NaN */
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be in [0, 1]", fn, name, (double)x);
}

tb_result tb_check_angle(struct tb_world* w, const char* fn, const char* name, float x) {
  if (isfinite(x) && fabsf(x) <= TB_MAX_ANGLE) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT, "%s: %s = %g must be finite and within TB_MAX_ANGLE (1e6 rad)", fn, name,
                 (double)x);
}

tb_result tb_check_gravity(struct tb_world* w, const char* fn, const char* name, tb_vec2 g) {
  if (isfinite(g.x) && isfinite(g.y) && sqrtf(g.x * g.x + g.y * g.y) <= tb_units.max_gravity) return TB_OK;
  return tb_fail(w, TB_ERR_INVALID_ARGUMENT,
                 "%s: %s = (%g, %g) must be finite and at most TB_MAX_GRAVITY (%g units/s^2) long", fn, name,
                 (double)g.x, (double)g.y, (double)tb_units.max_gravity);
}
