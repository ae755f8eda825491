/* The viewer's scripted input (--script): a fixed sequence of SDL events
 * pushed into SDL's queue frame by frame, so that they go through the same
 * handlers as a person's keys and mouse. The smoke test runs it under
 * SDL_VIDEODRIVER=offscreen and reads what the viewer prints.
 *
 * The sequence (frame: what): 2 space (pause), 4 s and 5 right arrow (two
 * single steps), 6 space (run), 10 left button down on a body, 11..40 the
 * mouse moving up and right, 41 left button up, 44 wheel up (zoom in), 46
 * wheel down, 48..50 a right-button drag (pan), 52..65 keys 1..7 twice each
 * (every debug-draw switch off and on again), 66 c (fit the camera), 68 r
 * (restart), 70 n (next scene), 80 p (previous scene), 85 a left click on
 * empty space. */
#ifndef TUMBLE_VIEWER_SCRIPT_H
#define TUMBLE_VIEWER_SCRIPT_H

#include <stdbool.h>
#include <stdint.h>

/* The window pixel (window coordinates) of a body worth dragging, chosen by
 * the viewer; false when the scene has none. */
typedef bool viewer_grab_fn(void* context, int* x, int* y);

typedef struct viewer_script {
  uint32_t window_id;
  int width, height; /* window size, in window coordinates */
  viewer_grab_fn* grab;
  void* context;
  int grab_x, grab_y; /* where the drag started */
  bool grabbing;
} viewer_script;

/* The frame after the last scripted event. */
int viewer_script_length(void);
/* Pushes the events of this frame (0, 1, ...). false when SDL refused one. */
bool viewer_script_push(viewer_script* script, int frame);

#endif
