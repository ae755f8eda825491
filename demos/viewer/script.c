#include "script.h"

#include <SDL.h>
#include <stdio.h>

#define DRAG_START 10
#define DRAG_FRAMES 30

static bool push(SDL_Event* e) {
  if (SDL_PushEvent(e) < 0) {
    fprintf(stderr, "tumble-viewer: script: %s\n", SDL_GetError());
    return false;
  }
  return true;
}

static bool key(const viewer_script* s, SDL_Keycode sym) {
  SDL_Event e;
  SDL_zero(e);
  e.type = SDL_KEYDOWN;
  e.key.windowID = s->window_id;
  e.key.state = SDL_PRESSED;
  e.key.keysym.sym = sym;
  e.key.keysym.scancode = SDL_GetScancodeFromKey(sym);
  return push(&e);
}

static bool motion(const viewer_script* s, int x, int y, uint32_t buttons) {
  SDL_Event e;
  SDL_zero(e);
  e.type = SDL_MOUSEMOTION;
  e.motion.windowID = s->window_id;
  e.motion.state = buttons;
  e.motion.x = x;
  e.motion.y = y;
  return push(&e);
}

static bool button(const viewer_script* s, bool down, uint8_t which, int x, int y) {
  SDL_Event e;
  SDL_zero(e);
  e.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
  e.button.windowID = s->window_id;
  e.button.button = which;
  e.button.state = down ? SDL_PRESSED : SDL_RELEASED;
  e.button.clicks = 1;
  e.button.x = x;
  e.button.y = y;
  return motion(s, x, y, down ? 0 : SDL_BUTTON(which)) && push(&e);
}

static bool wheel(const viewer_script* s, int x, int y, int notches) {
  SDL_Event e;
  SDL_zero(e);
  e.type = SDL_MOUSEWHEEL;
  e.wheel.windowID = s->window_id;
  e.wheel.y = notches;
  e.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
  return motion(s, x, y, 0) && push(&e);
}

int viewer_script_length(void) { return 86; }

bool viewer_script_push(viewer_script* s, int frame) {
  int cx = s->width / 2, cy = s->height / 2;
  if (frame > DRAG_START && frame <= DRAG_START + DRAG_FRAMES && s->grabbing) {
    int k = frame - DRAG_START;
    return motion(s, s->grab_x + 3 * k, s->grab_y - 4 * k, SDL_BUTTON_LMASK);
  }
  if (frame >= 52 && frame < 66) return key(s, SDLK_1 + (frame - 52) / 2);
  switch (frame) {
    case 2: return key(s, SDLK_SPACE);
    case 4: return key(s, SDLK_s);
    case 5: return key(s, SDLK_RIGHT);
    case 6: return key(s, SDLK_SPACE);
    case DRAG_START:
      if (!s->grab(s->context, &s->grab_x, &s->grab_y)) {
        printf("script: no body to drag\n");
        return true;
      }
      s->grabbing = true;
      return button(s, true, SDL_BUTTON_LEFT, s->grab_x, s->grab_y);
    case DRAG_START + DRAG_FRAMES + 1:
      if (!s->grabbing) return true;
      s->grabbing = false;
      return button(s, false, SDL_BUTTON_LEFT, s->grab_x + 3 * DRAG_FRAMES, s->grab_y - 4 * DRAG_FRAMES);
    case 44: return wheel(s, cx, cy, 1);
    case 46: return wheel(s, cx, cy, -1);
    case 48: return button(s, true, SDL_BUTTON_RIGHT, cx, cy);
    case 49: return motion(s, cx + 40, cy + 20, SDL_BUTTON_RMASK);
    case 50: return button(s, false, SDL_BUTTON_RIGHT, cx + 40, cy + 20);
    case 66: return key(s, SDLK_c);
    case 68: return key(s, SDLK_r);
    case 70: return key(s, SDLK_n);
    case 80: return key(s, SDLK_p);
    case 85: /* the top-right corner: sky in every scene */
      return button(s, true, SDL_BUTTON_LEFT, s->width - 3, 2) && button(s, false, SDL_BUTTON_LEFT, s->width - 3, 2);
    default: return true;
  }
}
