/* Exact solve of the rigid joint rows of joint trees.
 *
 * Why: a rigid row solved softly by Gauss-Seidel holds a load F only stretched
 * by F / (m_eff omega^2), and omega cannot exceed about 1.5 / h before the
 * iteration goes unstable. A 100-link chain then hangs with centimetre gaps at
 * its top, whatever the iteration count. Solved exactly, the rows can be made
 * as stiff as wanted.
 *
 * How (Baraff 1996): the velocity change dv of the bodies and the impulse
 * increments dl of the rows satisfy the symmetric system
 *   [  M   -J^T ] [dv]   [ 0                     ]
 *   [ -J   -G   ] [dl] = [ Cdot + b C + G l_acc  ]
 * (first line: M dv = J^T dl; second: -(K + G) dl = Cdot + b C + G l_acc with
 * K = J M^-1 J^T), the soft-constraint equation with compliance G = g K_c (K_c:
 * the row block's own effective-mass inverse, g = impulse_scale / mass_scale of
 * the softness, b its bias rate). Its graph has a node per dynamic body (3
 * unknowns) and one per joint (its rows); when that graph is a forest,
 * eliminating children before parents fills nothing in, so the solve costs
 * O(nodes) small blocks:
 *   factor, children first:  D_i = H_ii - sum_c H_ci^T D_c^-1 H_ci,
 *                            y_i = b_i - sum_c H_ci^T D_c^-1 y_c;
 *   back, parents first:     x_i = D_i^-1 (y_i - H_ip x_p).
 * A joint row block is only ever a leaf or an inner node with G > 0 or with
 * body children, so every D is invertible. Static and kinematic bodies are not
 * nodes (their velocity is fixed), so a bridge pinned at both ends is a tree.
 * A group of jointed bodies with a loop, or with a joint on a dynamic body
 * that cannot turn (zero inverse inertia), stays with Gauss-Seidel. Computed in double: the
 * blocks of a gram body next to a tonne body span many decades.
 *
 * Geometric stiffness (Andrews, Teichmann and Kry 2017). A joint's force f at
 * arm r turns its body back when the body turns by a: the torque r(a) x f has
 * d/da = -r . f, a stiffness k = r . f (> 0 when f pulls the anchor outward, a
 * taut chain). The rows hold the anchors' velocities but the arms are those of
 * the substep's start, so that restoring torque is integrated explicitly: a
 * light link between heavy loads turns with omega^2 = k / I and the substep is
 * unstable once h omega > 2 (a 670:1 ball shook its chain apart at 4
 * substeps). Taking the torque at the substep's end, linearised, adds h^2 k to
 * the body's inertia in M dv = J^T dl (k from the rows' accumulated impulse p:
 * h^2 k = h r . p). The warm start already turned the body by I^-1 tau with
 * the plain inertia, so the body's right-hand side takes -h^2 k I^-1 tau (the
 * total, not the increment, sees the stiffer inertia). Only the excess over
 * I is added, h^2 k - I when positive: the mode stays at h omega <= 1, and a
 * body whose mode is already stable (a pendulum: h^2 k / I ~ 1e-4) is solved
 * as before; the slowed turn would otherwise lengthen its period by that
 * fraction. The relax pass, which only removes the bias velocity, keeps I. */
#include "memory.h"
#include "joint_tree.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "joint.h"
#include "math_internal.h"
#include "pool.h"
#include "relax_activity.h"
#include "units.h"
#include "world.h"

/* The tree softness: the drift of a tree's rows is corrected at h omega = 8,
 * far stiffer than Gauss-Seidel allows (h omega ~ 1.5), and their compliance
 * is g = 1 / (h omega (2 zeta + h omega)) ~ 1 / 100 of the row's own inverse
 * effective mass. The relax pass uses a compliance of 1e-6: rigid to a
 * millionth, yet every leaf block stays invertible and well conditioned in
 * double (1e-9 left relax impulses wrong by tens of percent). */
#define TB_TREE_H_OMEGA 8.0f
#define TB_TREE_RELAX_COMPLIANCE 1e-6
/* How fast the drift correction may pull a row together (m/s, or rad/s for an
 * angle row). At h omega = 8 the bias rate is 160 / s at 60 Hz and 4
 * substeps: a joint made 0.4 m apart (the churn of the stress suite links
 * each new box to the last one so) was snapped shut at 280 m/s, and its
 * light chain, whipped on by the next ones, once reached 1e19 m/s and left
 * the world non-finite. Within the cap, a load's stretch of millimetres is
 * corrected as before (0.4 m/s at 2.5 mm). */
#define TB_TREE_MAX_CORRECTION_SPEED tb_meters(4.0f)

/* The nodes are split by what reads them, because the substitutions stream
 * every node of a tree once per pass (rain: 21,000 nodes, about 30 times a
 * step) and their time follows the bytes they stream (472-byte nodes holding
 * everything: 256 bytes of padding each made rain 1.10x slower). A node holds
 * its place and its blocks of the factorisation; a joint's rows are in
 * tree->joints (its slot, in node order); what only the build, the
 * factorisation and the store read is in tree->cold (by node). */
typedef struct tb_jt_node {
  int parent;                 /* node index, -1 for a root */
  int children, children_end; /* its children: nodes [children, children_end) (breadth-first: adjacent) */
  int ref;                    /* body: solver index; joint: its slot in tree->joints */
  int8_t dof;                 /* 3 for a body, the row count for a joint */
  bool body;                  /* a body node (else a joint's rows) */
  bool lone;                  /* of a tree of one joint, solved without D and H (solve_lone_joint) */
  bool two_rows;              /* of a tree whose joints all have two rows (substitute) */
  bool point;                 /* joint: its rows are a point's two, x then y (eliminate_point_*) */
  double stiff;               /* body: the geometric stiffness added to its inertia */
  double y[3];                /* right-hand side, then the solution */
  double d[3][3];             /* D, then D^-1 */
  double dh[3][3];            /* D^-1 H_{i,parent}: dof x the parent's dof (the substitutions' only H) */
} tb_jt_node;

/* A joint node's rows, what its right-hand side reads. */
typedef struct tb_jt_joint {
  int sa, sb; /* the solver bodies of A and B */
  /* the rows' accumulated impulses (*impulse[r] of its tb_jt_cold), kept here
   * while the passes add to them: the joint records are scattered, and
   * reading them in every pass missed the cache. Loaded by a step's first
   * biased prepare (see prepare), written back by tb_joint_tree_store. */
  float acc[3];
  tb_rigid_rows rows;
  double kc[3][3]; /* K_c, the row block's own effective-mass inverse (G = g K_c) */
} tb_jt_joint;

/* What only the build, the factorisation and the store read, by node. */
typedef struct tb_jt_cold {
  float hp[3][3];    /* H_{i,parent}: dof x the parent's dof (Jacobian entries, exact in float) */
  int first, count;  /* body: its edges in tree->edges */
  int a, b;          /* joint: the nodes of bodies A and B, -1 for a static or kinematic one */
  int joint;         /* joint: its index */
  float* impulse[3]; /* joint: where the rows' accumulated impulses live */
  /* joint, a point's: its anchors and the centres' offset at the step start,
   * for its rows in the step's later substeps (point_rows) */
  tb_vec2 frame_a, frame_b, delta_center;
} tb_jt_cold;

/* A node's place in the graph, as the build finds it (before the nodes are
 * sorted): the fields of the node records that say so, in one record of 44
 * bytes, which the build searches and then writes out in order. */
typedef struct tb_jt_link {
  int parent, dof, ref;
  int a, b, sa, sb;           /* joint */
  int first, count;           /* body */
  int children, children_end; /* after the breadth-first search */
} tb_jt_link;

/* What a step joint's place in the trees depends on: the joint, its solver
 * bodies and its rigid rows, and whether each body is a node that can turn
 * (flags); `in_tree` is the build's answer for it. */
typedef struct tb_jt_key {
  int32_t joint, solver_a, solver_b;
  int8_t rigid_rows;
  uint8_t flags;
  bool in_tree;
} tb_jt_key;

void tb_joint_tree_free(tb_joint_tree* t) {
  tb_mem_free(t->nodes, (size_t)t->node_capacity * sizeof *t->nodes);
  tb_mem_free(t->joints, (size_t)t->joint_capacity * sizeof *t->joints);
  tb_mem_free(t->cold, (size_t)t->cold_capacity * sizeof *t->cold);
  tb_mem_free(t->order, (size_t)t->order_capacity * sizeof *t->order);
  tb_mem_free(t->links, (size_t)t->link_capacity * sizeof *t->links);
  tb_mem_free(t->place, (size_t)t->place_capacity * sizeof *t->place);
  tb_mem_free(t->body_scratch, (size_t)t->body_capacity * sizeof *t->body_scratch);
  tb_mem_free(t->edges, (size_t)t->edge_capacity * sizeof *t->edges);
  tb_mem_free(t->edge_joints, (size_t)t->edge_joint_capacity * sizeof *t->edge_joints);
  tb_mem_free(t->components, (size_t)t->component_capacity * sizeof *t->components);
  tb_mem_free(t->keys, (size_t)t->key_capacity * sizeof *t->keys);
  memset(t, 0, sizeof *t);
}

static int find(int* parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

/* A solver body that is a node: dynamic, free to move and to turn. */
static bool is_node_body(const tb_step_context* ctx, int s) {
  return s != ctx->static_index && ctx->states[s].inv_mass > 0.0f;
}

static bool joint_fits(const tb_step_context* ctx, const tb_step_joint* j) {
  if (j->rigid_rows == 0) return false; /* skipped, or nothing rigid */
  int s[2] = {j->solver_a, j->solver_b};
  for (int k = 0; k < 2; ++k)
    if (is_node_body(ctx, s[k]) && !(ctx->states[s[k]].inv_inertia > 0.0f)) return false;
  return is_node_body(ctx, s[0]) || is_node_body(ctx, s[1]);
}

static int add_node(tb_joint_tree* t, int dof, int ref) {
  t->links[t->node_count] = (tb_jt_link){.parent = -1, .dof = dof, .ref = ref, .a = -1, .b = -1};
  return t->node_count++;
}

static tb_jt_key joint_key(const tb_world* w, const tb_step_context* ctx, int k) {
  const tb_step_joint* j = &w->step_joint_info[k];
  int s[2] = {j->solver_a, j->solver_b};
  uint8_t flags = 0;
  for (int e = 0; e < 2; ++e) {
    if (is_node_body(ctx, s[e])) flags |= (uint8_t)(1 << e);
    if (ctx->states[s[e]].inv_inertia > 0.0f) flags |= (uint8_t)(4 << e);
  }
  return (tb_jt_key){w->step_joints[k], j->solver_a, j->solver_b, j->rigid_rows, flags, false};
}

/* Whether the trees of the last build still hold: the same awake bodies and
 * step joints, each with the same key (a world whose joints and awake set do
 * not change keeps its trees, and the build is a pass over the keys). Records
 * the keys of this step either way. */
static bool same_topology(tb_world* w, const tb_step_context* ctx) {
  tb_joint_tree* t = &w->joint_tree;
  int joints = w->step_joint_count;
  bool same = t->key_count == joints && t->key_bodies == w->awake_count;
  t->key_count = -1; /* (valid again once a build or this check succeeds) */
  if (!tb_array_reserve((void**)&t->keys, &t->key_capacity, joints, sizeof *t->keys)) return false;
  for (int k = 0; k < joints; ++k) {
    tb_jt_key key = joint_key(w, ctx, k);
    const tb_jt_key* old = &t->keys[k];
    if (same && (old->joint != key.joint || old->solver_a != key.solver_a || old->solver_b != key.solver_b ||
                 old->rigid_rows != key.rigid_rows || old->flags != key.flags)) {
      same = false;
    }
    if (!same) t->keys[k] = key;
  }
  if (!same) return false;
  for (int k = 0; k < joints; ++k) {
    w->step_joint_info[k].in_tree = t->keys[k].in_tree;
    if (t->keys[k].in_tree) tb_joint_at(w, t->keys[k].joint)->in_tree = true; /* tb_joint_prepare cleared it */
  }
  t->key_count = joints;
  return true;
}

/* Breadth-first from root over the nodes whose parent is `unvisited`: sets
 * their parents (-1 for the root) and children ranges, writes them to the
 * order from `at` on and returns where they end. */
static int breadth_first(tb_joint_tree* t, int body_nodes, int root, int unvisited, int at) {
  tb_jt_link* links = t->links;
  links[root].parent = -1;
  t->order[at] = root;
  int end = at + 1;
  for (int q = at; q < end; ++q) {
    int i = t->order[q];
    tb_jt_link* n = &links[i];
    int around = i < body_nodes ? n->count : 2;
    n->children = end;
    for (int e = 0; e < around; ++e) {
      int m = i < body_nodes ? t->edges[n->first + e] : (e == 0 ? n->a : n->b);
      if (m < 0 || links[m].parent != unvisited) continue;
      links[m].parent = i;
      t->order[end++] = m;
    }
    n->children_end = end;
  }
  return end;
}

bool tb_joint_tree_build(tb_world* w, const tb_step_context* ctx) {
  tb_joint_tree* t = &w->joint_tree;
  int bodies = w->awake_count, joints = w->step_joint_count;
  t->factored_for = t->rows_for = -1;
  t->softness = tb_make_softness(TB_TREE_H_OMEGA * ctx->inv_h / TB_TWO_PI_F, w->joint_damping_ratio, ctx->h);
  if (joints > 0 && same_topology(w, ctx)) return true;
  t->node_count = 0;
  if (joints == 0) {
    t->key_count = -1;
    return true;
  }
  if (!tb_array_reserve((void**)&t->nodes, &t->node_capacity, bodies + joints, sizeof *t->nodes) ||
      !tb_array_reserve((void**)&t->joints, &t->joint_capacity, joints, sizeof *t->joints) ||
      !tb_array_reserve((void**)&t->cold, &t->cold_capacity, bodies + joints, sizeof *t->cold) ||
      !tb_array_reserve((void**)&t->order, &t->order_capacity, bodies + joints, sizeof *t->order) ||
      !tb_array_reserve((void**)&t->links, &t->link_capacity, bodies + joints, sizeof *t->links) ||
      !tb_array_reserve((void**)&t->place, &t->place_capacity, bodies + joints, sizeof *t->place) ||
      !tb_array_reserve((void**)&t->body_scratch, &t->body_capacity, 2 * bodies, sizeof *t->body_scratch) ||
      !tb_array_reserve((void**)&t->edges, &t->edge_capacity, 2 * joints, sizeof *t->edges) ||
      !tb_array_reserve((void**)&t->edge_joints, &t->edge_joint_capacity, 2 * joints, sizeof *t->edge_joints) ||
      !tb_array_reserve((void**)&t->components, &t->component_capacity, bodies + joints + 1, sizeof *t->components))
    return false;

  /* Groups of dynamic bodies linked by joints (union-find). A group whose
   * joints close a loop, or that has a rigid row the tree cannot take, stays
   * with Gauss-Seidel as a whole: stiff exact rows next to soft iterated ones
   * on the same bodies fight (a 100 x 100 joint grid turned jittery). */
  int *uf = t->body_scratch, *gs_only = t->body_scratch + bodies;
  tb_step_joint* info = w->step_joint_info; /* (not the joint records: one pass fewer over them) */
  for (int i = 0; i < bodies; ++i) uf[i] = i, gs_only[i] = 0;
  for (int k = 0; k < joints; ++k) {
    const tb_step_joint* j = &info[k];
    if (j->rigid_rows == 0) continue;
    bool na = is_node_body(ctx, j->solver_a), nb = is_node_body(ctx, j->solver_b);
    int root = find(uf, na ? j->solver_a : j->solver_b);
    if (na && nb) {
      int other = find(uf, j->solver_b);
      if (other == root) {
        gs_only[root] = 1; /* closes a loop */
      } else {
        int lo = root < other ? root : other, hi = root < other ? other : root;
        uf[hi] = lo;
        gs_only[lo] |= gs_only[hi];
        root = lo;
      }
    }
    if (!joint_fits(ctx, j)) gs_only[root] = 1;
  }
  for (int k = 0; k < joints; ++k) {
    tb_step_joint* j = &info[k];
    j->in_tree = joint_fits(ctx, j) && !gs_only[find(uf, is_node_body(ctx, j->solver_a) ? j->solver_a : j->solver_b)];
    if (j->in_tree) tb_joint_at(w, w->step_joints[k])->in_tree = true; /* tb_joint_prepare cleared it */
  }

  /* nodes: body nodes first (awake order), then joint nodes */
  int* body_node = t->body_scratch;
  for (int i = 0; i < bodies; ++i) body_node[i] = -1;
  for (int k = 0; k < joints; ++k) {
    const tb_step_joint* j = &info[k];
    if (!j->in_tree) continue;
    if (is_node_body(ctx, j->solver_a)) body_node[j->solver_a] = 0;
    if (is_node_body(ctx, j->solver_b)) body_node[j->solver_b] = 0;
  }
  for (int i = 0; i < bodies; ++i)
    if (body_node[i] == 0) body_node[i] = add_node(t, 3, i);
  int body_nodes = t->node_count;
  for (int k = 0; k < joints; ++k) {
    const tb_step_joint* j = &info[k];
    if (!j->in_tree) continue;
    int n = add_node(t, j->rigid_rows, w->step_joints[k]);
    t->links[n].a = is_node_body(ctx, j->solver_a) ? body_node[j->solver_a] : -1;
    t->links[n].b = is_node_body(ctx, j->solver_b) ? body_node[j->solver_b] : -1;
    t->links[n].sa = j->solver_a;
    t->links[n].sb = j->solver_b;
    if (t->links[n].a >= 0) t->links[t->links[n].a].count += 1;
    if (t->links[n].b >= 0) t->links[t->links[n].b].count += 1;
  }
  /* body -> joint edges (CSR) */
  int at = 0;
  for (int b = 0; b < body_nodes; ++b) {
    t->links[b].first = at;
    at += t->links[b].count;
    t->links[b].count = 0;
  }
  for (int n = body_nodes; n < t->node_count; ++n) {
    int ends[2] = {t->links[n].a, t->links[n].b};
    for (int e = 0; e < 2; ++e)
      if (ends[e] >= 0) t->edges[t->links[ends[e]].first + t->links[ends[e]].count++] = n;
  }

  /* Each tree breadth-first from its centre: parents before children, each
   * tree one run of the order (its start in components). The centre (the
   * middle of a longest path, found by two searches) gives the fewest levels:
   * the factorisation and the substitutions are chains of dependent small
   * solves from the leaves to the root and back, and the branches below the
   * root run side by side (a chain rooted at one end is one long chain). */
  for (int n = 0; n < t->node_count; ++n) t->links[n].parent = -2;
  int ordered = 0;
  t->component_count = 0;
  for (int start = 0; start < t->node_count; ++start) {
    if (t->links[start].parent != -2) continue;
    int end = breadth_first(t, body_nodes, start, -2, ordered);
    for (int q = ordered; q < end; ++q) t->links[t->order[q]].parent = -3;
    int far = t->order[end - 1]; /* a farthest node from start: one end of a longest path */
    breadth_first(t, body_nodes, far, -3, ordered);
    int length = 0, centre = t->order[end - 1]; /* the other end */
    for (int i = centre; t->links[i].parent >= 0; i = t->links[i].parent) length += 1;
    for (int k = 0; k < length / 2; ++k) centre = t->links[centre].parent;
    for (int q = ordered; q < end; ++q) t->links[t->order[q]].parent = -4;
    t->components[t->component_count++] = ordered;
    ordered = breadth_first(t, body_nodes, centre, -4, ordered);
  }
  t->components[t->component_count] = ordered;

  /* The nodes are written in that order (node q is order[q]), so that every
   * sweep of the solve walks them front to back or back to front: their
   * places in the graph, and y zeroed (a substitution reads all three); the
   * rest the factorisation and the right-hand sides write before they read. */
  for (int q = 0; q < ordered; ++q) t->place[t->order[q]] = q;
  for (int e = 0; e < at; ++e) t->edges[e] = t->place[t->edges[e]];
  int slots = 0;
  for (int q = 0; q < ordered; ++q) {
    int old = t->order[q];
    const tb_jt_link* l = &t->links[old];
    tb_jt_node* n = &t->nodes[q];
    tb_jt_cold* cold = &t->cold[q];
    n->parent = l->parent >= 0 ? t->place[l->parent] : -1;
    n->dof = (int8_t)l->dof;
    n->body = old < body_nodes;
    n->point = false; /* (a joint's: set with its rows, see prepare) */
    n->children = l->children;
    n->children_end = l->children_end;
    n->stiff = 0.0;
    n->y[0] = n->y[1] = n->y[2] = 0.0;
    cold->first = l->first;
    cold->count = l->count;
    cold->a = !n->body && l->a >= 0 ? t->place[l->a] : -1;
    cold->b = !n->body && l->b >= 0 ? t->place[l->b] : -1;
    cold->joint = n->body ? -1 : l->ref;
    if (n->body) {
      n->ref = l->ref;
    } else {
      n->ref = slots;
      t->joints[slots].sa = l->sa;
      t->joints[slots].sb = l->sb;
      slots += 1;
    }
  }
  /* a body's joints for body_mass, one load from its edge (edge -> node ->
   * slot, and the edge's cold record for the side, were a chain of misses) */
  for (int q = 0; q < ordered; ++q) {
    if (!t->nodes[q].body) continue;
    for (int e = t->cold[q].first; e < t->cold[q].first + t->cold[q].count; ++e) {
      int edge = t->edges[e];
      t->edge_joints[e] = 2 * t->nodes[edge].ref + (t->cold[edge].a == q);
    }
  }
  for (int k = 0; k < t->component_count; ++k) {
    int from = t->components[k], to = t->components[k + 1], joints_in = 0;
    bool two_rows = true;
    for (int q = from; q < to; ++q) {
      joints_in += !t->nodes[q].body;
      two_rows &= t->nodes[q].body || t->nodes[q].dof == 2;
    }
    for (int q = from; q < to; ++q) t->nodes[q].lone = joints_in == 1, t->nodes[q].two_rows = two_rows;
  }
  /* the keys' answers, for the next steps' same_topology (not when the keys
   * could not grow: out of memory, every step builds) */
  if (t->key_capacity >= joints) {
    for (int k = 0; k < joints; ++k) t->keys[k].in_tree = info[k].in_tree;
    t->key_count = joints;
    t->key_bodies = bodies;
  }
  return true;
}

/* ---- small dense blocks (at most 3 x 3) ----------------------------------- */

/* The small loops run at most 3 times: unrolled whole, their sums of
 * different rows interleave (the order within each sum is kept). */
#define UNROLLED _Pragma("GCC unroll 3")

/* In place inverse of the leading n x n block; zero when singular (the rows
 * then make no correction). n is a constant where it is inlined (invert). */
static inline __attribute__((always_inline)) void invert_n(int n, double m[3][3]) {
  double r[3][3];
  double det;
  if (n == 1) {
    det = m[0][0];
    r[0][0] = 1.0;
  } else if (n == 2) {
    det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    r[0][0] = m[1][1], r[0][1] = -m[0][1], r[1][0] = -m[1][0], r[1][1] = m[0][0];
  } else {
    r[0][0] = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    r[0][1] = m[0][2] * m[2][1] - m[0][1] * m[2][2];
    r[0][2] = m[0][1] * m[1][2] - m[0][2] * m[1][1];
    r[1][0] = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    r[1][1] = m[0][0] * m[2][2] - m[0][2] * m[2][0];
    r[1][2] = m[0][2] * m[1][0] - m[0][0] * m[1][2];
    r[2][0] = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    r[2][1] = m[0][1] * m[2][0] - m[0][0] * m[2][1];
    r[2][2] = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    det = m[0][0] * r[0][0] + m[0][1] * r[1][0] + m[0][2] * r[2][0];
  }
  double inv = det != 0.0 && isfinite(det) ? 1.0 / det : 0.0;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) m[i][k] = r[i][k] * inv;
}

static void invert(double m[3][3], int n) {
  switch (n) {
    case 1: invert_n(1, m); break;
    case 2: invert_n(2, m); break;
    default: invert_n(3, m); break;
  }
}

/* A row block's Jacobian on one of its bodies, as a k x 3 block with the sign
 * of H: +ja on body A, -jb on body B (see the file comment). */
static void joint_block(const tb_jt_joint* joint, bool side_a, float out[3][3]) {
  if (side_a)
    memcpy(out, joint->rows.ja, sizeof joint->rows.ja);
  else
    UNROLLED for (int r = 0; r < 3; ++r) UNROLLED for (int c = 0; c < 3; ++c) out[r][c] = -joint->rows.jb[r][c];
}

/* The inverse mass of a solver body times a 3-vector (x, y, angle). */
static void inv_mass_times(const tb_solver_body* s, const float j[3], double out[3]) {
  out[0] = (double)s->inv_mass * j[0];
  out[1] = (double)s->inv_mass * j[1];
  out[2] = (double)s->inv_inertia * j[2];
}

/* ---- block kernels by shape --------------------------------------------------
 * A child and its parent are a body (3 unknowns) and a joint's rows (1 to 3):
 * the kernels below take the two sizes as constants (BY_SHAPE) so that the
 * compiler unrolls their small loops; the operations and their order are
 * those of the loops with variable bounds, so the results are the same. */

/* Calls kernel(nd, pd, ...) with the sizes nd (child) and pd (parent) as constants. */
#define BY_SHAPE(nd, pd, kernel, ...)                              \
  do {                                                             \
    int shape_ = (nd)*4 + (pd);                                    \
    switch (shape_) {                                              \
      case 3 * 4 + 1: kernel(3, 1, __VA_ARGS__); break;            \
      case 3 * 4 + 2: kernel(3, 2, __VA_ARGS__); break;            \
      case 3 * 4 + 3: kernel(3, 3, __VA_ARGS__); break;            \
      case 1 * 4 + 3: kernel(1, 3, __VA_ARGS__); break;            \
      case 2 * 4 + 3: kernel(2, 3, __VA_ARGS__); break;            \
      default: kernel(shape_ / 4, shape_ % 4, __VA_ARGS__); break; \
    }                                                              \
  } while (0)

/* D_p -= H_ip^T D_i^-1 H_ip (D_i already inverted), keeping D_i^-1 H_ip for
 * the substitutions */
static inline __attribute__((always_inline)) void eliminate(int nd, int pd, tb_jt_node* n, float hp[3][3],
                                                            tb_jt_node* p) {
  double dh[3][3] = {{0.0}};
  UNROLLED for (int r = 0; r < nd; ++r) UNROLLED for (int c = 0; c < pd; ++c) UNROLLED for (int s = 0; s < nd; ++s)
      dh[r][c] += n->d[r][s] * hp[s][c];
  UNROLLED for (int c = 0; c < pd; ++c) UNROLLED for (int e = 0; e < pd; ++e) UNROLLED for (int r = 0; r < nd; ++r)
      p->d[c][e] -= hp[r][c] * dh[r][e];
  memcpy(n->dh, dh, sizeof dh);
}

/* eliminate for a body child of a point joint, and a point joint child of a
 * body (a chain's links, a ragdoll's limbs). A point's rows are x and y:
 * J = [e_r | lever] on each body, so H between them holds exact zeros and
 * +-1 (3 x 2 below a joint, 2 x 3 below a body). The kernels leave out the
 * products with those zeros and keep every other operation and its order:
 * the same results (up to the sign of an exact zero), with a third fewer
 * multiplications than the dense eliminate. */
static inline __attribute__((always_inline)) void eliminate_point_body(tb_jt_node* n, float hp[3][3], tb_jt_node* p) {
  /* hp = [[s, 0], [0, s], [l0, l1]] */
  UNROLLED for (int r = 0; r < 3; ++r) UNROLLED for (int c = 0; c < 2; ++c) n->dh[r][c] =
      n->d[r][c] * hp[c][c] + n->d[r][2] * hp[2][c];
  UNROLLED for (int c = 0; c < 2; ++c) UNROLLED for (int e = 0; e < 2; ++e) p->d[c][e] =
      (p->d[c][e] - hp[c][c] * n->dh[c][e]) - hp[2][c] * n->dh[2][e];
}

static inline __attribute__((always_inline)) void eliminate_point_joint(tb_jt_node* n, float hp[3][3], tb_jt_node* p) {
  /* hp = [[s, 0, l0], [0, s, l1]] */
  UNROLLED for (int r = 0; r < 2; ++r) {
    n->dh[r][0] = n->d[r][0] * hp[0][0];
    n->dh[r][1] = n->d[r][1] * hp[1][1];
    n->dh[r][2] = n->d[r][0] * hp[0][2] + n->d[r][1] * hp[1][2];
  }
  UNROLLED for (int e = 0; e < 3; ++e) {
    p->d[0][e] -= hp[0][0] * n->dh[0][e];
    p->d[1][e] -= hp[1][1] * n->dh[1][e];
    p->d[2][e] = (p->d[2][e] - hp[0][2] * n->dh[0][e]) - hp[1][2] * n->dh[1][e];
  }
}

/* forward: y_p -= H_ip^T D_i^-1 y_i, as (D_i^-1 H_ip)^T y_i (D_i is symmetric).
 * y_p is the parent's y, kept in registers over its children: summed in the
 * node, each product waited on the store of the last (rain's first 300
 * steps took 0.94 to 0.96 of the time). */
static inline __attribute__((always_inline)) void forward(int nd, int pd, const tb_jt_node* n, double y_p[3]) {
  UNROLLED for (int c = 0; c < pd; ++c) UNROLLED for (int r = 0; r < nd; ++r) y_p[c] -= n->dh[r][c] * n->y[r];
}

/* back: y_i = D_i^-1 (y_i - H_ip x_p), as D_i^-1 y_i - (D_i^-1 H_ip) x_p: one
 * product with D_i^-1 per node and substitution, not one each way (the sums
 * in registers, as in forward) */
static inline __attribute__((always_inline)) void back(int nd, int pd, tb_jt_node* n, const tb_jt_node* p) {
  double rhs[3] = {n->y[0], n->y[1], n->y[2]}, x[3] = {0.0, 0.0, 0.0};
  UNROLLED for (int r = 0; r < nd; ++r) {
    x[r] = 0.0;
    UNROLLED for (int s = 0; s < nd; ++s) x[r] += n->d[r][s] * rhs[s];
  }
  if (p != NULL) {
    double x_p[3] = {p->y[0], p->y[1], p->y[2]};
    UNROLLED for (int r = 0; r < nd; ++r) UNROLLED for (int c = 0; c < pd; ++c) x[r] -= n->dh[r][c] * x_p[c];
  }
  UNROLLED for (int r = 0; r < nd; ++r) n->y[r] = x[r];
}

/* ---- the solve -------------------------------------------------------------- */

/* K_c of a joint's k rows (k a constant where inlined, joint_rows). */
static inline __attribute__((always_inline)) void block_mass(int k, tb_jt_joint* n, const tb_solver_body* a,
                                                             const tb_solver_body* b) {
  double ma[3][3], mb[3][3]; /* M^-1 J^T columns of each row */
  UNROLLED for (int r = 0; r < k; ++r) {
    inv_mass_times(a, n->rows.ja[r], ma[r]);
    inv_mass_times(b, n->rows.jb[r], mb[r]);
  }
  UNROLLED for (int r = 0; r < k; ++r) {
    const float* ja = n->rows.ja[r];
    const float* jb = n->rows.jb[r];
    UNROLLED for (int s = 0; s < k; ++s) {
      double kc = 0.0;
      UNROLLED for (int c = 0; c < 3; ++c) kc += ja[c] * ma[s][c] + jb[c] * mb[s][c];
      n->kc[r][s] = kc;
    }
  }
}

/* A joint's rows, K_c and H toward its parent at the current positions. They
 * depend on the positions only: computed by the first factorisation after a
 * position update (the relax one) and read again by the biased one of the
 * next substep. */
static void joint_rows(tb_world* w, const tb_step_context* ctx, const tb_jt_node* n, tb_jt_joint* j, tb_jt_cold* cold) {
  const tb_solver_body* a = &ctx->states[j->sa];
  const tb_solver_body* b = &ctx->states[j->sb];
  tb_joint_rigid_rows(tb_joint_at(w, cold->joint), a, b, &j->rows, cold->impulse);
  switch (n->dof) {
    case 1: block_mass(1, j, a, b); break;
    case 2: block_mass(2, j, a, b); break;
    default: block_mass(3, j, a, b); break;
  }
  if (n->parent >= 0 && !n->lone) joint_block(j, cold->a == n->parent, cold->hp);
}

/* joint_rows for a point's two rows (n->point) after a step's first
 * substep, from the anchors and offset the first kept: the joint record, all
 * over memory, is not read. */
static void point_rows(const tb_step_context* ctx, const tb_jt_node* n, tb_jt_joint* j, tb_jt_cold* cold) {
  const tb_solver_body* a = &ctx->states[j->sa];
  const tb_solver_body* b = &ctx->states[j->sb];
  tb_vec2 ra, rb, d;
  tb_joint_arms(cold->frame_a, cold->frame_b, cold->delta_center, a, b, &ra, &rb, &d);
  j->rows.count = 0;
  tb_joint_add_point_rows(&j->rows, ra, rb, d);
  block_mass(2, j, a, b);
  if (n->parent >= 0 && !n->lone) joint_block(j, cold->a == n->parent, cold->hp);
}

/* H of a body toward its parent joint: the transpose of the joint's block. */
static void body_block(float hp[3][3], const tb_jt_joint* joint, bool side_a) {
  float sign = side_a ? 1.0f : -1.0f;
  const float(*j)[3] = side_a ? joint->rows.ja : joint->rows.jb;
  UNROLLED for (int r = 0; r < 3; ++r) UNROLLED for (int c = 0; c < 3; ++c) hp[r][c] = sign * j[c][r];
}

/* h k of a joint's point rows on the side of body A or B (the file comment):
 * r . p, the arm r read back from the rows (the x row's arm is -r.y, the y
 * row's r.x), p the point's accumulated impulse (-p acts on A). */
static double point_twist(const tb_jt_joint* joint, bool side_a) {
  int r = joint->rows.point;
  if (r < 0) return 0.0;
  tb_vec2 p = {joint->acc[r], joint->acc[r + 1]};
  if (side_a) return -tb_dot((tb_vec2){joint->rows.ja[r + 1][2], -joint->rows.ja[r][2]}, p);
  return tb_dot((tb_vec2){joint->rows.jb[r + 1][2], -joint->rows.jb[r][2]}, p);
}

/* A body node's block of D, its mass and inertia, with the geometric
 * stiffness beyond the inertia in the biased factorisation (file comment;
 * its joints' impulses already loaded). */
static void body_mass(const tb_joint_tree* t, const tb_step_context* ctx, tb_jt_node* n, int i, bool use_bias) {
  const tb_solver_body* s = &ctx->states[n->ref];
  n->stiff = 0.0;
  if (use_bias) {
    double twist = 0.0; /* h k (the rows' r . p) */
    const tb_jt_cold* cold = &t->cold[i];
    for (int e = cold->first; e < cold->first + cold->count; ++e) {
      int edge_joint = t->edge_joints[e];
      twist += point_twist(&t->joints[edge_joint >> 1], (edge_joint & 1) != 0);
    }
    n->stiff = tb_maxd((double)ctx->h * twist - 1.0 / (double)s->inv_inertia, 0.0);
  }
  memset(n->d, 0, sizeof n->d);
  n->d[0][0] = n->d[1][1] = 1.0 / (double)s->inv_mass;
  n->d[2][2] = 1.0 / (double)s->inv_inertia + n->stiff;
}

/* A joint's block of D: -G = -g K_c. */
static void joint_compliance(tb_jt_node* n, const tb_jt_joint* j, double g) {
  memset(n->d, 0, sizeof n->d);
  for (int r = 0; r < n->dof; ++r)
    for (int c = 0; c < n->dof; ++c) n->d[r][c] = -g * j->kc[r][c];
}

/* What a factorisation reads besides the bodies' masses, for every tree: the
 * joints' blocks -G = -g K_c (and, new positions, their rows), the
 * accumulated impulses (the biased pass, after tb_joint_tree_store), and a
 * body's H from its parent joint's rows (parents first). A tree of one joint
 * gets only its rows and impulses (its D and H: prepare_lone). */
static void prepare(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_joint_tree* t = &w->joint_tree;
  double g = use_bias ? (double)t->softness.impulse_scale / (double)t->softness.mass_scale : TB_TREE_RELAX_COMPLIANCE;
  bool fresh = t->rows_for != ctx->position_updates;
  t->rows_for = ctx->position_updates;
  t->compliance = g;
  /* The rows' impulses come from the joint records in a step's first biased
   * solve (warm started, or scaled or zeroed by the joints' prepare) and in
   * every biased solve without warm starting (zeroed each substep). After
   * the first, acc holds what tb_joint_tree_store wrote, unchanged since (the
   * warm starts only read it): the biased prepare then needs no joint record. */
  bool reload = use_bias && (ctx->position_updates == 0 || !ctx->enable_warm_starting);
  bool first = ctx->position_updates == 0; /* a step's first rows: from the joint records */
  for (int i = 0; i < t->node_count; ++i) {
    tb_jt_node* n = &t->nodes[i];
    /* the joint records lie all over memory: ask eight nodes ahead (they
     * waited on the first read of each, 2.5% of rain's step) */
    if (i + 8 < t->node_count && !t->nodes[i + 8].body && ((fresh && (first || !t->nodes[i + 8].point)) || reload)) {
      const char* r = (const char*)tb_joint_at(w, t->cold[i + 8].joint);
      for (size_t line = 0; line < sizeof(tb_joint); line += 64) __builtin_prefetch(r + line);
    }
    if (n->body) {
      if (fresh && n->parent >= 0 && !n->lone)
        body_block(t->cold[i].hp, &t->joints[t->nodes[n->parent].ref], t->cold[n->parent].a == i);
      continue;
    }
    tb_jt_joint* j = &t->joints[n->ref];
    if (fresh && (first || !n->point)) {
      joint_rows(w, ctx, n, j, &t->cold[i]);
      n->point = j->rows.point == 0 && n->dof == 2;
      if (n->point) {
        const tb_joint* record = tb_joint_at(w, t->cold[i].joint);
        t->cold[i].frame_a = record->frame_a;
        t->cold[i].frame_b = record->frame_b;
        t->cold[i].delta_center = record->delta_center;
      }
    } else if (fresh) {
      point_rows(ctx, n, j, &t->cold[i]);
    }
    if (reload)
      for (int r = 0; r < n->dof; ++r) j->acc[r] = *t->cold[i].impulse[r];
    if (!n->lone) joint_compliance(n, j, g);
  }
}

/* What prepare leaves out for a tree of one joint, for the factorisation
 * when solve_lone_joint declines: its H blocks and the joint's block. */
static void prepare_lone(tb_joint_tree* t, int from, int to) {
  for (int q = from; q < to; ++q) {
    tb_jt_node* n = &t->nodes[q];
    if (n->parent < 0) continue;
    if (n->body)
      body_block(t->cold[q].hp, &t->joints[t->nodes[n->parent].ref], t->cold[n->parent].a == q);
    else
      joint_block(&t->joints[n->ref], t->cold[q].a == n->parent, t->cold[q].hp);
  }
  for (int q = from; q < to; ++q)
    if (!t->nodes[q].body) joint_compliance(&t->nodes[q], &t->joints[t->nodes[q].ref], t->compliance);
}

/* The factorisation of the tree of nodes [from, to) at the current positions
 * (prepared): every block and D^-1, children first, D_i -= H_ci^T D_c^-1
 * H_ci over its children (adjacent nodes, taken last to first). It depends on
 * the positions (the rows) and on the pass kind (compliance, geometric
 * stiffness), not on the velocities, so the relax passes of one substep
 * share it (see tb_joint_tree_solve). */
static void factor(tb_joint_tree* t, const tb_step_context* ctx, int from, int to, bool use_bias) {
  for (int q = to - 1; q >= from; --q) {
    tb_jt_node* n = &t->nodes[q];
    if (n->body) body_mass(t, ctx, n, q, use_bias);
    for (int c = n->children_end - 1; c >= n->children; --c) {
      tb_jt_node* child = &t->nodes[c];
      if (child->body && n->point)
        eliminate_point_body(child, t->cold[c].hp, n);
      else if (!child->body && child->point)
        eliminate_point_joint(child, t->cold[c].hp, n);
      else
        BY_SHAPE(child->dof, n->dof, eliminate, child, t->cold[c].hp, n);
    }
    invert(n->d, n->dof);
  }
}

/* The right-hand side of a joint node's k rows (k and biased constants where
 * inlined): Cdot + b C + G l_acc, with G l_acc = g (K_c l_acc); a relax pass
 * (biased false) has no correction term. */
static inline __attribute__((always_inline)) void joint_rhs(int k, bool biased, const tb_joint_tree* t,
                                                            const tb_step_context* ctx, tb_jt_node* n, double bias) {
  const tb_jt_joint* j = &t->joints[n->ref];
  const tb_solver_body* a = &ctx->states[j->sa];
  const tb_solver_body* b = &ctx->states[j->sb];
  double avx = a->v.x, avy = a->v.y, aw = a->w, bvx = b->v.x, bvy = b->v.y, bw = b->w;
  double acc[3];
  UNROLLED for (int s = 0; s < k; ++s) acc[s] = j->acc[s];
  UNROLLED for (int r = 0; r < k; ++r) {
    const float* ja = j->rows.ja[r];
    const float* jb = j->rows.jb[r];
    double cdot = (double)jb[0] * bvx + (double)jb[1] * bvy + (double)jb[2] * bw -
                  ((double)ja[0] * avx + (double)ja[1] * avy + (double)ja[2] * aw);
    double held = 0.0; /* (K_c l_acc)_r */
    UNROLLED for (int s = 0; s < k; ++s) held += j->kc[r][s] * acc[s];
    if (biased) {
      double correction = bias * (double)j->rows.c[r], most = (double)TB_TREE_MAX_CORRECTION_SPEED;
      cdot += correction > most ? most : correction < -most ? -most : correction;
    }
    n->y[r] = cdot + t->compliance * held;
  }
}

/* The right-hand side of a body node: zero, but for the geometric stiffness. */
static inline __attribute__((always_inline)) void body_rhs(const tb_joint_tree* t, const tb_step_context* ctx, int i) {
  tb_jt_node* n = &t->nodes[i];
  n->y[0] = n->y[1] = n->y[2] = 0.0;
  if (n->stiff == 0.0) return;
  /* the warm start turned the body by I^-1 tau with the plain inertia */
  double torque = 0.0;
  const tb_jt_cold* cold = &t->cold[i];
  for (int e = 0; e < cold->count; ++e) {
    int edge = t->edges[cold->first + e];
    const tb_jt_joint* joint = &t->joints[t->nodes[edge].ref];
    bool side_a = t->cold[edge].a == i;
    for (int r = 0; r < t->nodes[edge].dof; ++r)
      torque += side_a ? -(double)joint->rows.ja[r][2] * joint->acc[r] : (double)joint->rows.jb[r][2] * joint->acc[r];
  }
  n->y[2] = -n->stiff * (double)ctx->states[n->ref].inv_inertia * torque;
}

/* The right-hand side of one node at the current velocities and impulses
 * (biased a constant where inlined; bias is 0 in a relax pass). */
static inline __attribute__((always_inline)) void node_rhs_kind(bool biased, const tb_joint_tree* t,
                                                                const tb_step_context* ctx, int i, double bias) {
  tb_jt_node* n = &t->nodes[i];
  if (n->body) {
    body_rhs(t, ctx, i);
    return;
  }
  switch (n->dof) {
    case 1: joint_rhs(1, biased, t, ctx, n, bias); break;
    case 2: joint_rhs(2, biased, t, ctx, n, bias); break;
    default: joint_rhs(3, biased, t, ctx, n, bias); break;
  }
}

/* Whether a later relax pass solves the tree of nodes [from, to): when one
 * of its bodies still moves (relax_activity.h). */
static bool tree_active(const tb_step_context* ctx, const tb_joint_tree* t, int from, int to) {
  for (int q = from; q < to; ++q)
    if (t->nodes[q].body && tb_relax_active(ctx, t->nodes[q].ref)) return true;
  return false;
}

/* One tree, nodes [from, to): the two substitutions through the
 * factorisation, and the velocity changes and impulses. use_bias and
 * two_rows are constants where inlined (substitute): in a tree whose joints
 * all have two rows (revolute chains, ragdolls) every block's shape follows
 * from its kind, a branch that the breadth-first order (a level is all
 * bodies or all joints) makes predictable, instead of a jump by shape. */
static inline __attribute__((always_inline)) void substitute_kind(tb_world* w, tb_step_context* ctx, int from, int to,
                                                                  bool use_bias, bool two_rows) {
  tb_joint_tree* t = &w->joint_tree;
  double bias = use_bias ? (double)t->softness.bias_rate : 0.0;
  /* forward, children first: y_i = b_i - sum_c H_ci^T D_c^-1 y_c */
  for (int q = to - 1; q >= from; --q) {
    tb_jt_node* n = &t->nodes[q];
    if (two_rows && !n->body)
      joint_rhs(2, use_bias, t, ctx, n, bias);
    else
      node_rhs_kind(use_bias, t, ctx, q, bias);
    double y[3] = {n->y[0], n->y[1], n->y[2]};
    for (int c = n->children_end - 1; c >= n->children; --c) {
      const tb_jt_node* child = &t->nodes[c];
      if (!two_rows)
        BY_SHAPE(child->dof, n->dof, forward, child, y);
      else if (child->body)
        forward(3, 2, child, y);
      else
        forward(2, 3, child, y);
    }
    UNROLLED for (int r = 0; r < 3; ++r) n->y[r] = y[r];
  }
  /* back, parents first: y becomes the solution x_i = D_i^-1 (y_i - H_ip x_p),
   * and with it a body's velocity change or a joint's impulses */
  for (int q = from; q < to; ++q) {
    tb_jt_node* n = &t->nodes[q];
    const tb_jt_node* p = n->parent >= 0 ? &t->nodes[n->parent] : NULL;
    if (!two_rows)
      BY_SHAPE(n->dof, p != NULL ? p->dof : 3, back, n, p);
    else if (n->body)
      back(3, 2, n, p);
    else
      back(2, 3, n, p);
    if (!n->body) {
      float* acc = t->joints[n->ref].acc;
      if (two_rows)
        UNROLLED for (int r = 0; r < 2; ++r) acc[r] += (float)n->y[r];
      else
        for (int r = 0; r < n->dof; ++r) acc[r] += (float)n->y[r];
      continue;
    }
    tb_solver_body* s = &ctx->states[n->ref];
    tb_vec2 dv = {(float)n->y[0], (float)n->y[1]};
    s->v = (tb_vec2){s->v.x + dv.x, s->v.y + dv.y};
    s->w += (float)n->y[2];
    if (!use_bias && ctx->relax_record) tb_relax_note(ctx, n->ref, tb_relax_speed(ctx, n->ref, dv, (float)n->y[2]));
  }
}

static void substitute(tb_world* w, tb_step_context* ctx, int from, int to, bool use_bias) {
  bool two_rows = w->joint_tree.nodes[from].two_rows;
  if (use_bias && two_rows)
    substitute_kind(w, ctx, from, to, true, true);
  else if (use_bias)
    substitute_kind(w, ctx, from, to, true, false);
  else if (two_rows)
    substitute_kind(w, ctx, from, to, false, true);
  else
    substitute_kind(w, ctx, from, to, false, false);
}

/* A tree of one joint (its bodies have no other tree joint), solved without
 * the factorisation: the joint's K is its own K_c, so dl = -((1 + g) K_c)^-1
 * r with r its right-hand side, and the bodies take M^-1 J^T dl. The same
 * solve as the elimination (in another order of sums), in a fraction of its
 * steps: a door on a hinge, a pendulum, a wheel on its axle. false, and
 * nothing done, when a body needs the geometric stiffness (the general
 * factorisation has it). */
static inline __attribute__((always_inline)) bool solve_lone_kind(int k, tb_joint_tree* t, tb_step_context* ctx,
                                                                  int from, int to, int q, bool use_bias) {
  tb_jt_node* n = &t->nodes[q];
  tb_jt_joint* j = &t->joints[n->ref];
  const tb_jt_cold* cold = &t->cold[q];
  tb_solver_body* a = &ctx->states[j->sa];
  tb_solver_body* b = &ctx->states[j->sb];
  if (use_bias) {
    double h = (double)ctx->h;
    if ((cold->a >= 0 && h * point_twist(j, true) > 1.0 / (double)a->inv_inertia) ||
        (cold->b >= 0 && h * point_twist(j, false) > 1.0 / (double)b->inv_inertia)) {
      prepare_lone(t, from, to);
      return false;
    }
  }
  double s[3][3] = {{0.0}};
  UNROLLED for (int r = 0; r < k; ++r) UNROLLED for (int c = 0; c < k; ++c) s[r][c] =
      j->kc[r][c] + t->compliance * j->kc[r][c];
  invert_n(k, s);
  double bias = use_bias ? (double)t->softness.bias_rate : 0.0;
  if (bias != 0.0) /* (a zero bias rate: the relax kind) */
    joint_rhs(k, true, t, ctx, n, bias);
  else
    joint_rhs(k, false, t, ctx, n, bias);
  double dl[3] = {0.0, 0.0, 0.0};
  UNROLLED for (int r = 0; r < k; ++r) {
    UNROLLED for (int c = 0; c < k; ++c) dl[r] -= s[r][c] * n->y[c];
    j->acc[r] += (float)dl[r];
  }
  /* M^-1 J^T dl: -ja on A, +jb on B */
  for (int side = 0; side < 2; ++side) {
    if ((side == 0 ? cold->a : cold->b) < 0) continue; /* static or kinematic: not a node */
    tb_solver_body* body = side == 0 ? a : b;
    double p[3] = {0.0, 0.0, 0.0};
    UNROLLED for (int r = 0; r < k; ++r) {
      const float* row = side == 0 ? j->rows.ja[r] : j->rows.jb[r];
      double l = side == 0 ? -dl[r] : dl[r];
      UNROLLED for (int c = 0; c < 3; ++c) p[c] += (double)row[c] * l;
    }
    tb_vec2 dv = {(float)((double)body->inv_mass * p[0]), (float)((double)body->inv_mass * p[1])};
    float dw = (float)((double)body->inv_inertia * p[2]);
    body->v = (tb_vec2){body->v.x + dv.x, body->v.y + dv.y};
    body->w += dw;
    int index = side == 0 ? j->sa : j->sb;
    if (!use_bias && ctx->relax_record) tb_relax_note(ctx, index, tb_relax_speed(ctx, index, dv, dw));
  }
  return true;
}

static bool solve_lone_joint(tb_joint_tree* t, tb_step_context* ctx, int from, int to, bool use_bias) {
  int joint = from;
  while (t->nodes[joint].body) ++joint;
  switch (t->nodes[joint].dof) { /* the row count as a constant: the small loops unrolled, the same operations */
    case 1: return solve_lone_kind(1, t, ctx, from, to, joint, use_bias);
    case 2: return solve_lone_kind(2, t, ctx, from, to, joint, use_bias);
    default: return solve_lone_kind(3, t, ctx, from, to, joint, use_bias);
  }
}

void tb_joint_tree_solve(tb_world* w, tb_step_context* ctx, bool use_bias) {
  tb_joint_tree* t = &w->joint_tree;
  if (t->node_count == 0) return;
  /* the relax passes after one position update see the same rows and share
   * one factorisation (made in the first, which solves every tree) */
  bool refactor = use_bias || t->factored_for != ctx->position_updates;
  if (refactor) prepare(w, ctx, use_bias);
  t->factored_for = use_bias ? -1 : ctx->position_updates;
  for (int k = 0; k < t->component_count; ++k) {
    int from = t->components[k], to = t->components[k + 1];
    if (!use_bias && !tree_active(ctx, t, from, to)) continue;
    if (t->nodes[from].lone && solve_lone_joint(t, ctx, from, to, use_bias)) continue;
    if (refactor) factor(t, ctx, from, to, use_bias);
    substitute(w, ctx, from, to, use_bias);
  }
}

void tb_joint_tree_store(tb_world* w) {
  tb_joint_tree* t = &w->joint_tree;
  for (int i = 0; i < t->node_count; ++i) {
    const tb_jt_node* n = &t->nodes[i];
    if (!n->body)
      for (int r = 0; r < n->dof; ++r) *t->cold[i].impulse[r] = t->joints[n->ref].acc[r];
  }
}

size_t tb_joint_tree_bytes(const tb_joint_tree* t) {
  return (size_t)t->node_capacity * sizeof *t->nodes + (size_t)t->joint_capacity * sizeof *t->joints +
         (size_t)t->cold_capacity * sizeof *t->cold + (size_t)t->order_capacity * sizeof *t->order +
         (size_t)t->link_capacity * sizeof *t->links + (size_t)t->place_capacity * sizeof *t->place +
         (size_t)t->body_capacity * sizeof *t->body_scratch + (size_t)t->edge_capacity * sizeof *t->edges +
         (size_t)t->edge_joint_capacity * sizeof *t->edge_joints +
         (size_t)t->component_capacity * sizeof *t->components + (size_t)t->key_capacity * sizeof *t->keys;
}
