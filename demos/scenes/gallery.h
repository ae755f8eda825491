/* The demo scenes of the gallery (gallery.c): builders, update hooks and world
 * configuration that the catalogue (scenes.c) lists. Private to demos/scenes/;
 * use the catalogue (scenes.h) instead. */
#ifndef TUMBLE_GALLERY_H
#define TUMBLE_GALLERY_H

#include "tumble.h"

void build_bullet_block(tb_world_id world, float scale);
void update_bullet_block(tb_world_id world, int step);
void build_card_house(tb_world_id world, float scale);
void build_pendulum(tb_world_id world, float scale);
void build_double_pendulum(tb_world_id world, float scale);
void build_chain_bridge(tb_world_id world, float scale);
void build_ragdolls(tb_world_id world, float scale);
void build_car(tb_world_id world, float scale);
void build_dominoes(tb_world_id world, float scale);
void build_tumbler_mixed(tb_world_id world, float scale);
void build_rain_over_time(tb_world_id world, float scale);
void update_rain_over_time(tb_world_id world, int step);
void build_conveyor(tb_world_id world, float scale);
void update_conveyor(tb_world_id world, int step);
void configure_one_way_platform(tb_world_def* def);
void build_one_way_platform(tb_world_id world, float scale);
void build_sensors(tb_world_id world, float scale);
void update_sensors(tb_world_id world, int step);

#endif /* TUMBLE_GALLERY_H */
