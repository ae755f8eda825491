/* The stress suite (issue 7): scenes that push the engine to its limits, each
 * with a numeric pass criterion. Every test runs at the default settings
 * (tb_default_world_def(), 60 Hz, 4 substeps) unless its comment says which
 * switch it changes and why. `make stress` runs them all and writes
 * results/STRESS.md; `make test` runs the fast subset (stress_fast).
 *
 * A test fills a stress_result: the measured figure as text, pass or fail,
 * and the world hash at a fixed step for the determinism checks. */
#ifndef TB_STRESS_H
#define TB_STRESS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "tumble.h"

#define STRESS_DT (1.0f / 60.0f)
#define STRESS_SUBSTEPS 4
#define STRESS_G 10.0 /* |default gravity| (m/s^2) */

typedef struct stress_result {
  bool pass;
  char figure[320]; /* the measured figures, as the report prints them */
} stress_result;

typedef struct stress_test {
  const char* name;
  const char* criterion; /* one line for the report */
  bool fast;             /* part of the `make test` subset */
  void (*run)(stress_result* out);
} stress_test;

/* Appends printf-style text to out->figure. */
void stress_note(stress_result* out, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

/* ---- worlds and bodies -------------------------------------------------- */

/* --perturb SEED: the dynamic bodies the helpers below make (and the drum's
 * load of one_hour) start moved by up to STRESS_PERTURB_METERS in x and y,
 * drawn from SEED anew in each world (0, the default: not moved). A test
 * whose figure is one draw of a chaotic pile shows its spread over seeds:
 * a change that only moves rounding moves it as much as a micrometre does. */
#define STRESS_PERTURB_METERS 1e-6f
extern uint32_t stress_perturb_seed;
/* Moves p by this world's next draw (nothing when the seed is 0). */
void stress_perturb(tb_vec2* p);
/* Deterministic random numbers (xorshift32), uniform in [lo, hi]: float
 * rounding can return hi itself. */
float stress_uniform(unsigned* state, float lo, float hi);

/* A world from tb_default_world_def(); sleep switched as asked. */
tb_world_id stress_world(bool enable_sleep);
/* One step at 60 Hz, 4 substeps; false (and a message on stderr) on error. */
bool stress_step(tb_world_id w);
/* A static ground box whose top surface is y = top, spanning x0 +- half_width. */
tb_body_id stress_ground(tb_world_id w, float x0, float top, float half_width);
/* A dynamic box body (density 1, friction 0.6 unless sd says otherwise). */
tb_body_id stress_box(tb_world_id w, tb_vec2 p, float angle, float hx, float hy, const tb_shape_def* sd);
tb_body_id stress_circle(tb_world_id w, tb_vec2 p, float r, const tb_shape_def* sd);
/* A column of `count` boxes of half-size h on the surface y = y0 at x = x0;
 * returns the top box. */
tb_body_id stress_column(tb_world_id w, float x0, float y0, int count, float h);
/* A pyramid: rows of base, base - 1, ... boxes of half-size h, touching, each
 * row centred on the one below, standing on y = y0 around x0; returns the top. */
tb_body_id stress_pyramid(tb_world_id w, float x0, float y0, int base, float h);

/* ---- measurements ------------------------------------------------------- */

/* Every body of the world that has a shape, in creation order (malloc'd;
 * free it). */
tb_body_id* stress_bodies(tb_world_id w, int* count);
/* Kinetic + gravitational potential energy (J, y = 0 as zero) of the dynamic
 * bodies in the list, in double. */
double stress_energy(const tb_body_id* bodies, int count);
/* Whether every body's placement and velocity are finite. */
bool stress_all_finite(const tb_body_id* bodies, int count);
/* The largest linear speed of the dynamic bodies in the list (m/s). */
double stress_peak_speed(const tb_body_id* bodies, int count);
/* The deepest overlap (m, >= 0) over the touching contacts of these bodies. */
double stress_deepest_overlap(const tb_body_id* bodies, int count);
/* How far the deepest overlap at a touching point of these bodies goes
 * beyond the depth its contact force explains (m, >= 0; see stress_util.c). */
double stress_deepest_excess_overlap(const tb_body_id* bodies, int count);
/* The contacts' spring rates omega (rad/s) at the default settings and the
 * stress step, as tumble.h documents them: 2 pi contact_hertz, twice that
 * against static bodies, both capped at h omega = 3 per substep. A point of
 * effective mass m_n is a spring m_n omega^2. */
void stress_contact_omegas(double* dynamic, double* against_static);
/* The spacing of floats at |x| (one ULP), in metres. */
double stress_ulp(float x);

/* ---- memory ------------------------------------------------------------- */

/* Heap bytes currently allocated through malloc/calloc/realloc by the engine
 * and this program (counted by heap_count.c through the linker's --wrap), and
 * the number of allocation calls so far. */
long long stress_heap_live_bytes(void);
long long stress_heap_alloc_calls(void);
/* The most heap bytes live at once since the last stress_heap_reset_peak
 * (a moving realloc counts its old and new block). */
long long stress_heap_peak_bytes(void);
void stress_heap_reset_peak(void);
/* Resident set size of the process (bytes), from /proc/self/statm; -1 if
 * unavailable. */
long long stress_rss_bytes(void);

/* ---- the tests, one group per file -------------------------------------- */

void stress_stack_15(stress_result* out);
void stress_stack_30(stress_result* out);
void stress_pyramid_20(stress_result* out);
void stress_pyramid_100(stress_result* out);
void stress_card_house(stress_result* out);
void stress_arch(stress_result* out);

void stress_mass_ratio_100(stress_result* out);
void stress_mass_ratio_400(stress_result* out);
void stress_mass_ratio_1000(stress_result* out);
void stress_ball_and_chain(stress_result* out);
void stress_mass_ratio_edge(stress_result* out);
/* The Markdown table of the last stress_mass_ratio_edge run, for the report. */
void stress_mass_ratio_edge_table(FILE* f);

void stress_overlap_boxes(stress_result* out);
void stress_overlap_circles(stress_result* out);
void stress_pileup_300(stress_result* out);
void stress_pileup_1000(stress_result* out);

void stress_bullets(stress_result* out);
void stress_spinner(stress_result* out);

void stress_scale_offset(stress_result* out);
void stress_tiny_boxes(stress_result* out);
void stress_large_boxes(stress_result* out);

void stress_one_hour(stress_result* out);
void stress_churn(stress_result* out);

/* ---- the scenes, shared with the determinism check ---------------------- */

/* Each creates a world with the settings its test uses (sleep on or off) and
 * builds that test's scene in it: the tests start from these, and so does the
 * determinism check, so the scene it hashes is the one the test runs. */
tb_world_id stress_new_stack(int count);
tb_world_id stress_new_pyramid(float x0, float y0, int base, float h);
tb_world_id stress_new_card_house(void);
tb_world_id stress_new_arch(void);
tb_world_id stress_new_mass_ratio(float ratio);
tb_world_id stress_new_ball_and_chain(void);
tb_world_id stress_new_heavy_on_light(float ratio);
tb_world_id stress_new_heavy_pendulum(float ratio);
tb_world_id stress_new_overlap_boxes(void);
tb_world_id stress_new_overlap_circles(void);
/* `count` bodies created at one point in a U (pileup.c). */
tb_world_id stress_new_pileup(int count);
tb_world_id stress_new_bullets(void);
/* The spinner's two planks are returned through the pointers (either may be
 * NULL). */
tb_world_id stress_new_spinner(tb_body_id* free_plank, tb_body_id* dropped);
/* one_hour's turning drum. */
tb_world_id stress_new_drum(void);
/* churn changes its world every step: this runs the test's first `steps`
 * steps and returns the world's hash after the last. */
uint64_t stress_churn_hash(int steps);

/* Hashes of the stress scenes after a fixed number of steps, one line per
 * scene ("name hash"), written to `out`. With runs = 2 each scene is run
 * twice in-process, and false is returned when the two runs differ. */
bool stress_print_hashes(FILE* out, int runs);

#endif
