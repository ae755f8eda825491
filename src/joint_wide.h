/* Revolute joints solved four at a time: coloured so that no two of a
 * colour share a moving body and packed into blocks of four lanes (wide.h),
 * their point (unless a joint tree solves it, joint_tree.c) and their angle
 * rows (spring, motor, limits). Every other joint is solved one at a time
 * (joint.c). See joint_wide.c. */
#ifndef TB_JOINT_WIDE_H
#define TB_JOINT_WIDE_H

#include <stdbool.h>
#include <stddef.h>

#include "solver.h"

struct tb_wide_joint;
struct tb_wide_angles;

/* Step scratch, grown as needed and kept by the world. */
typedef struct tb_wide_joints {
  struct tb_wide_joint* blocks;
  int block_count, block_capacity;
  struct tb_wide_angles* angles; /* beside the blocks: their angle rows */
  int angle_capacity;
} tb_wide_joints;

struct tb_world;
struct tb_joint;

/* Whether a prepared joint is one the wide joints take: a revolute joint
 * that is not skipped, its bodies' masses within the bounds of joint_wide.c. */
bool tb_wide_joint_fits(const struct tb_joint* j, const tb_step_context* ctx);
void tb_wide_joints_free(tb_wide_joints* wj);
size_t tb_wide_joints_bytes(const tb_wide_joints* wj);
/* After the joints are prepared and the joint trees built: takes the step
 * joints it can solve (w->step_joint_info), moves them to the end of the
 * step joints and their info (the others keep their order) and sets
 * w->scalar_joint_count to the others' count. Out of memory it takes none. */
void tb_wide_joints_build(struct tb_world* w, const tb_step_context* ctx);
void tb_wide_joints_warm_start(struct tb_world* w, tb_step_context* ctx);
/* One pass over the blocks, biased or (use_bias false) a relax pass, which
 * skips the blocks whose bodies have settled and notes what it moves
 * (relax_activity.h). */
void tb_wide_joints_solve(struct tb_world* w, tb_step_context* ctx, bool use_bias);
/* After the substeps: the impulses back into the joints (for the getters and
 * the next step's warm start), and what the getters report (tb_joint_store). */
void tb_wide_joints_store(struct tb_world* w, const tb_step_context* ctx);

#endif
