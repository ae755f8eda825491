#include "error.h"

#include <stdarg.h>
#include <stdio.h>

static _Thread_local char last_message[512];
static _Thread_local tb_render_result last_code = TB_RENDER_OK;

tb_render_result tbr_fail(tb_render_result code, const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  vsnprintf(last_message, sizeof last_message, fmt, args);
  va_end(args);
  last_code = code;
  return code;
}

const char* tb_render_last_error(void) { return last_message; }

tb_render_result tb_render_last_result(void) { return last_code; }

const char* tb_render_result_name(tb_render_result r) {
  switch (r) {
    case TB_RENDER_OK: return "TB_RENDER_OK";
    case TB_RENDER_ERR_NULL_ARGUMENT: return "TB_RENDER_ERR_NULL_ARGUMENT";
    case TB_RENDER_ERR_INVALID_ARGUMENT: return "TB_RENDER_ERR_INVALID_ARGUMENT";
    case TB_RENDER_ERR_STALE_HANDLE: return "TB_RENDER_ERR_STALE_HANDLE";
    case TB_RENDER_ERR_OUT_OF_MEMORY: return "TB_RENDER_ERR_OUT_OF_MEMORY";
    case TB_RENDER_ERR_CONTEXT: return "TB_RENDER_ERR_CONTEXT";
    case TB_RENDER_ERR_WORLD: return "TB_RENDER_ERR_WORLD";
    case TB_RENDER_ERR_IO: return "TB_RENDER_ERR_IO";
    case TB_RENDER_ERR_NO_FFMPEG: return "TB_RENDER_ERR_NO_FFMPEG";
    case TB_RENDER_ERR_ENCODE: return "TB_RENDER_ERR_ENCODE";
  }
  return "TB_RENDER_ERR_UNKNOWN";
}
