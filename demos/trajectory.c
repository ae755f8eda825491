/* The first demo: a box thrown upward with a spin, printed as a table of its
 * trajectory (time, centre of mass, angle, velocity, kinetic energy). It stays
 * the `make demo` target until the rendering demos land. */
#include <stdio.h>

#include "tumble.h"

int main(void) {
  tb_world_def wd = tb_default_world_def();
  tb_world_id world = tb_create_world(&wd);

  tb_body_def bd = tb_default_body_def();
  bd.type = TB_DYNAMIC_BODY;
  bd.position = (tb_vec2){0.0f, 1.0f};
  bd.linear_velocity = (tb_vec2){2.0f, 8.0f};
  bd.angular_velocity = 3.0f;
  tb_body_id box = tb_create_body(world, &bd);

  tb_polygon shape;
  tb_make_box(0.5f, 0.25f, &shape);
  tb_shape_def sd = tb_default_shape_def();
  tb_create_polygon_shape(box, &sd, &shape);

  printf("a 1 x 0.5 m box (%.2f kg, I = %.4f kg m^2) thrown at (2, 8) m/s spinning at 3 rad/s\n",
         (double)tb_body_get_mass(box), (double)tb_body_get_rotational_inertia(box));
  printf("%6s %9s %9s %9s %9s %9s %9s\n", "t [s]", "x [m]", "y [m]", "angle", "vx", "vy", "KE [J]");
  for (int step = 0; step <= 96; ++step) {
    if (step % 8 == 0) {
      tb_vec2 c = tb_body_get_world_center(box), v = tb_body_get_linear_velocity(box);
      printf("%6.3f %9.4f %9.4f %9.4f %9.4f %9.4f %9.4f\n", tb_world_get_time(world), (double)c.x, (double)c.y,
             (double)tb_body_get_angle(box), (double)v.x, (double)v.y, (double)tb_body_get_kinetic_energy(box));
    }
    if (tb_world_step(world, 1.0f / 60.0f, 4) != TB_OK) {
      fprintf(stderr, "step failed: %s\n", tb_last_error());
      return 1;
    }
  }
  tb_destroy_world(world);
  return 0;
}
