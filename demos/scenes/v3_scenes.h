/* The scenes of Box2D v3's benchmark (its benchmark/main.c and
 * shared/benchmarks.c) that tumble's catalogue did not have in v3's form,
 * built as v3 builds them: same bodies, shapes, joints, materials, spawn
 * schedules and motors (v3_scenes.c). The catalogue (scenes.c) lists them
 * under v3's names. Private to demos/scenes/. */
#ifndef TUMBLE_V3_SCENES_H
#define TUMBLE_V3_SCENES_H

#include "tumble.h"

void build_compounds(tb_world_id world, float scale);
void build_junkyard(tb_world_id world, float scale);
void update_junkyard(tb_world_id world, int step);
void build_rain(tb_world_id world, float scale);
void update_rain(tb_world_id world, int step);
void build_spinner(tb_world_id world, float scale);
void build_tumbler(tb_world_id world, float scale);
void build_washer(tb_world_id world, float scale);

#endif /* TUMBLE_V3_SCENES_H */
