/* Contacts: a pair of shapes whose fat AABBs overlap, with its manifold. */
#ifndef TB_CONTACT_H
#define TB_CONTACT_H

#include "manifold.h"
#include "manifold_reuse.h"
#include "tumble.h"

enum {
  TB_CONTACT_TOUCHING = 1 << 0, /* manifold has points (sensor: shapes overlap) */
  TB_CONTACT_SENSOR = 1 << 1,
  TB_CONTACT_ENABLED = 1 << 2, /* not disabled by the pre-solve callback */
  TB_CONTACT_EVENTS = 1 << 3,  /* begin/end events wanted */
  TB_CONTACT_HIT_EVENTS = 1 << 4,
  TB_CONTACT_PRE_SOLVE = 1 << 5
};

typedef struct tb_contact_edge {
  int body;
  int prev, next; /* edge keys (contact * 2 + side) in the body's list, -1 at the ends */
} tb_contact_edge;

typedef struct tb_contact {
  int shape_a, shape_b; /* ordered so that a collide function takes (A, B) */
  tb_contact_edge edges[2];
  tb_manifold manifold;    /* points carry the impulses kept for warm starting */
  tb_patch patch;          /* where the touching features end (the solver stops a point that slid off) */
  tb_manifold_cache cache; /* the manifold as last collided, for reuse (manifold_reuse.h) */
  float friction, restitution;
  float rolling_resistance; /* coefficient times radius (m) */
  float tangent_speed;
  float rolling_impulse;
  /* The overlap the bodies' approach drove in (approach speed x dt when it
   * began, then only shrinking with the overlap): the contact solver's soft
   * push takes it out, with momentum, not the momentum-free push-out (see
   * contact_solver.c). */
  float impact_depth;
  uint32_t flags;
  uint32_t walk_stamp; /* the narrow phase that last met it (tb_contacts_update), 0: none yet */
} tb_contact;

struct tb_world;

/* Creates the contact of two shapes that passed the filters. false when out of
 * memory. The new contact waits at the head of its moving bodies' lists, out
 * of order, until tb_contacts_sort_new (the broad phase calls it after each
 * batch of new pairs). */
bool tb_contact_create(struct tb_world* w, int shape_a, int shape_b);
/* Sorts the new contacts into their bodies' lists (see link_edge in contact.c). */
void tb_contacts_sort_new(struct tb_world* w);
/* Removes a contact; reports an end event when it was touching (and wants events). */
void tb_contact_destroy(struct tb_world* w, int contact);
/* Destroys every contact of a body (all its shapes), or of one shape when shape >= 0. */
void tb_contacts_destroy_of_body(struct tb_world* w, int body, int shape);
/* Narrow phase for the contacts of awake bodies; records begin, end, hit and
 * sensor events, wakes sleeping bodies that start being touched, and lists
 * the touching contacts the solver must handle in world->step_contacts. */
void tb_contacts_update(struct tb_world* w);
/* Whether another solid shape continues the face or closes the corner at one
 * end of contact's patch (max_end: the end at slide_max; see contact.c); if
 * so, that end is removed from the patch (slide limit +-FLT_MAX) for as long
 * as the manifold lasts. */
bool tb_contact_face_runs_on(struct tb_world* w, int contact, bool max_end);
/* Whether a pair of shape types has a manifold function (segment-segment has none). */
bool tb_shape_types_collide(tb_shape_type a, tb_shape_type b);

#endif
