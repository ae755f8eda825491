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
    tb_chain_segment chain_segment;
  } geom;
  int body;       /* owning body's slot */
  int prev, next; /* the body's shape list, -1 at the ends */
  float density, friction, restitution, rolling_resistance, tangent_speed;
  tb_filter filter;
  bool sensor;
  bool enable_sensor_events, enable_contact_events, enable_hit_events, enable_pre_solve_events;
  /* broad phase */
  int proxy; /* leaf in the tree of its body type, -1 when not in a tree */
  int tree;  /* which tree: the body type when the proxy was made */
  bool in_move_buffer;
  tb_aabb aabb;     /* tight, at the body's current transform */
  tb_aabb fat_aabb; /* its proxy's box as the tree holds it: the narrow phase reads this, not the tree */
  float margin;     /* how far its fat box reaches beyond aabb (tb_broad_phase_create_proxy) */
  int chain;        /* the chain this segment belongs to, -1 for other shapes */
  void* user_data;
} tb_shape;

struct tb_world;
/* Checks that proto can join the body's broad phase and reserves room for
 * `proxies` more proxies: after TB_OK, tb_shape_link of that many cannot fail. */
tb_result tb_shape_prepare(struct tb_world* w, int body, const tb_shape* proto, int proxies, const char* fn);
/* Links a prepared proto into an allocated shape slot (mass not updated). */
void tb_shape_link(struct tb_world* w, int body, int index, const tb_shape* proto);
/* Prepares, allocates and links one shape to a body and the broad phase (mass
 * not updated). Returns its index, or -1 (error recorded, nothing changed). */
int tb_shape_attach(struct tb_world* w, int body, const tb_shape* proto, const char* fn);
/* Unlinks and frees a shape: its contacts end, its proxy goes (mass not updated). */
void tb_shape_detach(struct tb_world* w, int shape);

#endif
