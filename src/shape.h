/* Shapes attached to bodies, with their material. */
#ifndef TB_SHAPE_H
#define TB_SHAPE_H

#include "tumble.h"

typedef struct tb_shape {
  tb_shape_type type;
  union {
    tb_circle circle;
    tb_capsule capsule;
    tb_segment segment;
    tb_polygon polygon;
  } geom;
  int body;       /* owning body's slot */
  int prev, next; /* the body's shape list, -1 at the ends */
  float density, friction, restitution;
  void* user_data;
} tb_shape;

#endif
