/* Graph colouring of constraints: constraints of one colour share no moving
 * body, so a colour's constraints can be solved four at a time (wide.h) and
 * in any order, by one thread or split into ranges. */
#ifndef TB_COLOR_H
#define TB_COLOR_H

#include <stdint.h>

#define TB_COLORS 24 /* colours in one round */

/* Greedy colouring of the constraints in waiting (constraint k, body a, body
 * b; a body index < 0 for a body that does not move), from colour first on:
 * each takes the first colour that neither of its moving bodies uses, written
 * to color[k]. Bodies that never move under impulses (static, kinematic) are
 * shared freely: their velocity is written back unchanged. A round has
 * TB_COLORS colours; the constraints that find none wait for the next round,
 * which starts with every colour free again (colours first + TB_COLORS r +
 * 0..TB_COLORS-1 in round r). Ordinary scenes take one round. A pile-up's
 * bodies touch hundreds of others: with one round, the contacts left over
 * were solved one by one, each alone in a block of four (688 bytes a contact,
 * 360 of the 527 MB of 1,000 bodies created at one point). bits: scratch of
 * one word per body index; waiting is reordered. Returns the next free
 * colour: one past the last colour used (first when nothing waits). */
int tb_color_rounds(int bodies, uint32_t* bits, int32_t* waiting, int left, int first, int32_t* color);

#endif
