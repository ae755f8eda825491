/* Length units per metre (tumble.h, "memory, hooks and units"). */
#include "units.h"

#include <math.h>

#include "broad_phase.h"
#include "error.h"
#include "memory.h"

tb_length_scale tb_units = {1.0f,           TB_LINEAR_SLOP, TB_SPECULATIVE_DISTANCE,
                            TB_AABB_MARGIN, TB_MAX_SPEED,   TB_MAX_GRAVITY};

tb_result tb_set_length_units_per_meter(float units) {
  if (!(units >= 1.0e-3f && units <= 1.0e3f)) /* NaN fails too */
    return tb_fail(NULL, TB_ERR_INVALID_ARGUMENT,
                   "tb_set_length_units_per_meter: units_per_meter = %g must be finite and in [1e-3, 1e3]",
                   (double)units);
  tb_result r = tb_refuse_while_worlds_exist("tb_set_length_units_per_meter");
  if (r != TB_OK) return r;
  tb_units = (tb_length_scale){units,
                               TB_LINEAR_SLOP * units,
                               TB_SPECULATIVE_DISTANCE * units,
                               TB_AABB_MARGIN * units,
                               TB_MAX_SPEED * units,
                               TB_MAX_GRAVITY * units};
  return TB_OK;
}

float tb_get_length_units_per_meter(void) { return tb_units.units_per_meter; }
