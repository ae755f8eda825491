/* The render library's last error, per thread (tb_render_last_error). */
#ifndef TBR_ERROR_H
#define TBR_ERROR_H

#include "tumble_render.h"

/* Records code and the printf-style message; returns code. */
tb_render_result tbr_fail(tb_render_result code, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
