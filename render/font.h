/* A 5 x 7 pixel bitmap font of printable ASCII (32 to 126), drawn for the
 * demos' overlay. Each glyph is 7 rows, top first; bit 4 of a row is the
 * leftmost pixel. Characters outside the range show as '?'. The letters with
 * descenders (g p q y) are drawn tbr_font_descent() pixels lower, so a line
 * takes TBR_FONT_LINE_HEIGHT pixels. */
#ifndef TBR_FONT_H
#define TBR_FONT_H

#include <stddef.h>
#include <stdint.h>

#define TBR_FONT_WIDTH 5
#define TBR_FONT_HEIGHT 7
/* Horizontal distance from one character to the next, in font pixels. */
#define TBR_FONT_ADVANCE 6
#define TBR_FONT_LINE_HEIGHT 9

const uint8_t* tbr_font_glyph(char c);
/* Font pixels the glyph is drawn below the others (0 or 2). */
int tbr_font_descent(char c);
/* Width of the text in font pixels (no trailing gap). */
int tbr_font_text_width(const char* text);

/* The longest line tbr_font_wrap hands out. */
#define TBR_FONT_MAX_LINE 512
/* Copies into piece the first line of text that holds at most max_chars
 * characters (and fits piece_size with its NUL), broken at the last space that
 * allows it, or cut when a word alone is longer; returns how far the next line
 * starts in text (past the spaces at the break; at its end when it all fit). */
int tbr_font_wrap(const char* text, int max_chars, char* piece, size_t piece_size);

#endif
