#include "color.h"

#include <string.h>

int tb_color_rounds(int bodies, uint32_t* bits, int32_t* waiting, int left, int first, int32_t* color) {
  int colors = first;
  while (left > 0) {
    memset(bits, 0, (size_t)bodies * sizeof(uint32_t));
    int still = 0, most = 0; /* colours this round has used */
    for (int i = 0; i < left; ++i) {
      int k = waiting[3 * i], a = waiting[3 * i + 1], b = waiting[3 * i + 2];
      uint32_t used = (a >= 0 ? bits[a] : 0u) | (b >= 0 ? bits[b] : 0u);
      if (!(~used & ((1u << TB_COLORS) - 1u))) { /* no colour left in this round */
        waiting[3 * still] = k;
        waiting[3 * still + 1] = a;
        waiting[3 * still + 2] = b;
        still += 1;
        continue;
      }
      int c = __builtin_ctz(~used);
      if (a >= 0) bits[a] |= 1u << c;
      if (b >= 0) bits[b] |= 1u << c;
      color[k] = colors + c;
      most = c + 1 > most ? c + 1 : most;
    }
    left = still;
    /* the last round ends at its last used colour: the callers loop over
     * the colours (a lone contact went through 24 empty ones, twice a step) */
    colors += still > 0 ? TB_COLORS : most;
  }
  return colors;
}
