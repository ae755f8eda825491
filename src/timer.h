/* A monotonic wall clock for the per-step profile (tb_profile). */
#ifndef TB_TIMER_H
#define TB_TIMER_H

/* Milliseconds since an arbitrary fixed point; only differences mean anything. */
double tb_clock_ms(void);

#endif /* TB_TIMER_H */
