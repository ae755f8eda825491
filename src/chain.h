/* Chains: a run of one-sided segment shapes that know their neighbours. */
#ifndef TB_CHAIN_H
#define TB_CHAIN_H

#include "tumble.h"

typedef struct tb_chain {
  int body;
  int* shapes; /* segment shape indices, in order */
  int count;
  bool loop;
} tb_chain;

#endif
