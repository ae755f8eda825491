/* The exact solve of the rigid joint rows of every joint tree (Baraff, "Linear-
 * time dynamics using Lagrange multipliers", SIGGRAPH 1996), in place of
 * Gauss-Seidel for them. See joint_tree.c. */
#ifndef TB_JOINT_TREE_H
#define TB_JOINT_TREE_H

#include <stdbool.h>
#include <stddef.h>

#include "solver.h"

struct tb_jt_node;
struct tb_jt_joint;
struct tb_jt_cold;
struct tb_jt_link;
struct tb_jt_key;

/* Step scratch, grown as needed and kept by the world. */
typedef struct tb_joint_tree {
  struct tb_jt_node* nodes;
  int node_count, node_capacity;
  struct tb_jt_joint* joints; /* the joint nodes' rows, by slot (node order) */
  int joint_capacity;
  struct tb_jt_cold* cold; /* by node: what the substitutions do not read */
  int cold_capacity;
  struct tb_jt_link* links; /* the build's: the nodes' places in the graph, before they are sorted */
  int link_capacity;
  int* order; /* the build's breadth-first order, parents before children; the nodes are then stored in it */
  int order_capacity;
  int* place; /* the build's: where each node goes in that order */
  int place_capacity;
  int* body_scratch; /* per awake body: union-find parent and flag, then its node */
  int body_capacity;
  int* edges; /* per body node: its constraint nodes (CSR, first[] in body nodes) */
  int edge_capacity;
  int* edge_joints; /* per edge: its joint's slot * 2, + 1 where the body is the joint's A (body_mass) */
  int edge_joint_capacity;
  int* components; /* tree k is nodes [components[k], components[k + 1]) */
  int component_count, component_capacity;
  struct tb_jt_key* keys;      /* per step joint: what its place in the trees depends on (joint_tree.c) */
  int key_count, key_capacity; /* key_count: of the last build, -1 when none holds */
  int key_bodies;              /* the awake body count of the last build */
  tb_softness softness;        /* of the biased pass */
  int factored_for;            /* the relax passes' factorisation is of this position update (-1: none) */
  int rows_for;                /* the joint nodes' rows and K_c are of this position update (-1: none) */
  double compliance;           /* g of the current factorisation (G = g K_c) */
} tb_joint_tree;

struct tb_world;

void tb_joint_tree_free(tb_joint_tree* t);
/* Bytes its arrays hold. */
size_t tb_joint_tree_bytes(const tb_joint_tree* t);
/* After the joints are prepared: finds the groups of jointed bodies that form
 * trees (a group with a loop stays with Gauss-Seidel), marks their joints
 * in_tree and orders the nodes. false when out of memory (then no
 * joint is in a tree and Gauss-Seidel solves them all). */
bool tb_joint_tree_build(struct tb_world* w, const tb_step_context* ctx);
/* One exact solve of every tree's rigid rows at the current positions and
 * velocities, with the biased softness or (use_bias false) rigid. */
void tb_joint_tree_solve(struct tb_world* w, tb_step_context* ctx, bool use_bias);
/* Writes the rows' impulses back to the joints: after each substep's passes,
 * before anything else reads them (the next warm start, tb_joint_store). */
void tb_joint_tree_store(struct tb_world* w);

#endif
