/* Turns the bench's CSV files into results/REPORT.md and the gnuplot inputs
 * (issue 6). Reads, in the results directory:
 *   bench.csv    accuracy sweep (tools/bench_accuracy.c)
 *   scenes.tsv   what each accuracy scene measures
 *   scaling.csv  step time against pyramid size (bench_accuracy --scaling)
 *   perf.csv     performance scenes (tools/bench_dynamics.c and _b2.cpp)
 *   profile.csv  tumble's per-stage profile of the performance scenes
 *   skip.csv     cost of what a scene does not use (tools/bench_skip.c)
 *   machine.txt  where it ran (written by tools/bench_run.sh)
 * Missing optional files leave their section out. Rows of engine "box2d_v3"
 * (make bench-v3's bench_accuracy_v3) add Box2D v3 to the headline, the
 * scene tables and the plots; without them the report is as before. Writes
 * REPORT.md, and under
 * plots/: one data file per scene and engine (sweep points and their Pareto
 * front) and plots.gp, which gnuplot turns into the PNGs.
 *
 *   build/bench/bench_report RESULTS_DIR
 *
 * Exit status 1 when bench.csv is missing or has a broken row (ok = 0). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_FIELDS 24
#define MAX_ROWS 2048
#define FIELD_LEN 200
/* zero errors cannot go on a log axis: they are drawn at this floor */
#define ERROR_FLOOR 1e-12

typedef struct table {
  int rows, cols;
  char header[MAX_FIELDS][FIELD_LEN];
  char (*cell)[MAX_FIELDS][FIELD_LEN];
} table;

static bool read_table(const char* dir, const char* name, char sep, table* t) {
  char path[512], line[4096];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  memset(t, 0, sizeof *t);
  FILE* f = fopen(path, "r");
  if (f == NULL) return false;
  t->cell = calloc(MAX_ROWS, sizeof *t->cell);
  if (t->cell == NULL) exit(1);
  int row = -1;
  while (fgets(line, sizeof line, f) != NULL && row < MAX_ROWS) {
    line[strcspn(line, "\r\n")] = '\0';
    if (line[0] == '\0') continue;
    char(*out)[FIELD_LEN] = row < 0 ? t->header : t->cell[row];
    int col = 0;
    char* p = line;
    while (col < MAX_FIELDS) {
      char* end = strchr(p, sep);
      size_t n = end != NULL ? (size_t)(end - p) : strlen(p);
      if (n >= FIELD_LEN) n = FIELD_LEN - 1;
      memcpy(out[col], p, n);
      out[col][n] = '\0';
      col += 1;
      if (end == NULL) break;
      p = end + 1;
    }
    if (row < 0) t->cols = col;
    row += 1;
  }
  t->rows = row < 0 ? 0 : row;
  fclose(f);
  return true;
}

static int column(const table* t, const char* name) {
  for (int c = 0; c < t->cols; ++c) {
    if (strcmp(t->header[c], name) == 0) return c;
  }
  fprintf(stderr, "bench_report: no column '%s'\n", name);
  exit(1);
}

static const char* get(const table* t, int row, const char* name) { return t->cell[row][column(t, name)]; }
static double num(const table* t, int row, const char* name) { return atof(get(t, row, name)); }

/* ---------------------------------------------------------------- sweep -- */

typedef struct point {
  double cost, error;
  int row;
  bool pareto;
} point;

static int by_cost(const void* a, const void* b) {
  const point *x = a, *y = b;
  if (x->cost != y->cost) return (x->cost > y->cost) - (x->cost < y->cost);
  return (x->error > y->error) - (x->error < y->error);
}

/* Marks the points no other point beats in both cost and error; sorts by cost. */
static void mark_pareto(point* p, int n) {
  qsort(p, (size_t)n, sizeof *p, by_cost);
  double best = INFINITY;
  for (int i = 0; i < n; ++i) {
    p[i].pareto = p[i].error < best;
    if (p[i].pareto) best = p[i].error;
  }
}

static int collect(const table* t, const char* scene, const char* engine, point* out) {
  int n = 0;
  for (int r = 0; r < t->rows; ++r) {
    if (strcmp(get(t, r, "scene"), scene) != 0 || strcmp(get(t, r, "engine"), engine) != 0) continue;
    point p = {num(t, r, "ms_per_60hz_frame"), fmax(num(t, r, "error"), ERROR_FLOOR), r, false};
    out[n++] = p;
  }
  return n;
}

static int default_row(const table* t, const char* scene, const char* engine) {
  for (int r = 0; r < t->rows; ++r) {
    if (strcmp(get(t, r, "scene"), scene) == 0 && strcmp(get(t, r, "engine"), engine) == 0 &&
        atoi(get(t, r, "is_default")) == 1)
      return r;
  }
  return -1;
}

static void setting_label(const table* t, int r, char* out, size_t size) {
  if (strcmp(get(t, r, "engine"), "tumble") == 0) {
    snprintf(out, size, "%s Hz, %s substeps, %s", get(t, r, "hz"), get(t, r, "substeps"), get(t, r, "integrator"));
  } else if (strcmp(get(t, r, "engine"), "box2d_v3") == 0) {
    snprintf(out, size, "%s Hz, %s substeps", get(t, r, "hz"), get(t, r, "substeps"));
  } else {
    snprintf(out, size, "%s Hz, %s/%s iterations", get(t, r, "hz"), get(t, r, "velocity_iterations"),
             get(t, r, "position_iterations"));
  }
}

/* "2.3e-03" style, "0" for exact zeros */
static void fmt(double v, char* out, size_t size) {
  if (v == 0.0) {
    snprintf(out, size, "0");
  } else {
    snprintf(out, size, "%.3g", v);
  }
}

/* a cell of a scene's defaults table: "%.4f" ms, or an error as fmt writes it */
static void value_cell(const table* t, int r, const char* col, char* out, size_t size) {
  if (strcmp(col, "ms_per_60hz_frame") == 0) {
    snprintf(out, size, "%.4f", num(t, r, col));
  } else {
    fmt(num(t, r, col), out, size);
  }
}

static void ratio(double a, double b, char* out, size_t size) {
  if (b == 0.0 && a == 0.0) {
    snprintf(out, size, "1 (both 0)");
  } else if (b == 0.0) {
    snprintf(out, size, "inf (Box2D 0)");
  } else {
    snprintf(out, size, "%.3g", a / b);
  }
}

/* tumble's default row against another engine's default row in one scene */
typedef struct comparison {
  char tumble[32], other[32], error_ratio[32], time_ratio[32];
  bool err_worse, slower;
  const char* verdict;
} comparison;

static comparison compare(const table* t, int rt, int ro) {
  comparison c;
  double et = num(t, rt, "error"), eo = num(t, ro, "error");
  double ct = num(t, rt, "ms_per_60hz_frame"), co = num(t, ro, "ms_per_60hz_frame");
  fmt(et, c.tumble, sizeof c.tumble);
  fmt(eo, c.other, sizeof c.other);
  ratio(et, eo, c.error_ratio, sizeof c.error_ratio);
  ratio(ct, co, c.time_ratio, sizeof c.time_ratio);
  /* a tie: errors within 1% or both at float round-off (1e-6); times within
   * 10%, the run-to-run spread of microsecond scenes on a shared machine */
  c.err_worse = et > eo * 1.01 && et > 1e-6;
  c.slower = ct > co * 1.10;
  c.verdict = c.err_worse && c.slower ? "**tumble worse: less accurate and slower**"
              : c.err_worse           ? "**tumble less accurate**"
              : c.slower              ? "tumble as accurate or better, but slower"
                                      : "tumble as accurate or better, not slower";
  return c;
}

/* the scenes where tumble's default is worse than another engine's */
typedef struct worse_list {
  int count;
  char line[64][256];
} worse_list;

static void note_worse(worse_list* w, const char* scene, const char* metric, const char* other, const comparison* c) {
  if (!(c->err_worse || c->slower) || w->count >= 64) return;
  snprintf(w->line[w->count++], sizeof w->line[0], "%s (%s): tumble %s, %s %s (error ratio %s); time ratio %s%s", scene,
           metric, c->tumble, other, c->other, c->error_ratio, c->time_ratio, c->err_worse ? "" : " (only slower)");
}

static void print_worse(FILE* md, const worse_list* w, const char* other) {
  if (w->count == 0) return;
  fprintf(md, "Where tumble's default is worse than %s's default:\n\n", other);
  for (int i = 0; i < w->count; ++i) fprintf(md, "- %s\n", w->line[i]);
  fprintf(md, "\n");
}

static void write_sweep_data(const char* dir, const char* scene, const char* engine, point* p, int n) {
  char path[512];
  snprintf(path, sizeof path, "%s/plots/%s_%s.dat", dir, scene, engine);
  FILE* f = fopen(path, "w");
  if (f == NULL) {
    perror(path);
    exit(1);
  }
  fprintf(f, "# ms_per_60hz_frame error pareto\n");
  for (int i = 0; i < n; ++i) fprintf(f, "%.6g %.6g %d\n", p[i].cost, p[i].error, p[i].pareto ? 1 : 0);
  fprintf(f, "\n\n# pareto front\n");
  for (int i = 0; i < n; ++i) {
    if (p[i].pareto) fprintf(f, "%.6g %.6g\n", p[i].cost, p[i].error);
  }
  fclose(f);
}

/* ----------------------------------------------------------------- main -- */

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s RESULTS_DIR\n", argv[0]);
    return 2;
  }
  const char* dir = argv[1];
  table acc, meta, scaling, perf, profile, skip;
  if (!read_table(dir, "bench.csv", ',', &acc) || acc.rows == 0) {
    fprintf(stderr, "bench_report: %s/bench.csv is missing or empty\n", dir);
    return 1;
  }
  bool have_meta = read_table(dir, "scenes.tsv", '\t', &meta);
  bool have_scaling = read_table(dir, "scaling.csv", ',', &scaling) && scaling.rows > 0;
  bool have_perf = read_table(dir, "perf.csv", ',', &perf) && perf.rows > 0;
  bool have_profile = read_table(dir, "profile.csv", ',', &profile) && profile.rows > 0;
  bool have_skip = read_table(dir, "skip.csv", ',', &skip) && skip.rows > 0;
  int broken = 0;
  bool have_v3 = false;
  for (int r = 0; r < acc.rows; ++r) {
    broken += atoi(get(&acc, r, "ok")) != 1;
    have_v3 = have_v3 || strcmp(get(&acc, r, "engine"), "box2d_v3") == 0;
  }

  /* scenes in file order */
  const char* scenes[256];
  int scene_count = 0;
  for (int r = 0; r < acc.rows; ++r) {
    const char* s = get(&acc, r, "scene");
    bool seen = false;
    for (int k = 0; k < scene_count; ++k) seen = seen || strcmp(scenes[k], s) == 0;
    if (!seen && scene_count < 256) scenes[scene_count++] = s;
  }

  char path[512];
  snprintf(path, sizeof path, "%s/REPORT.md", dir);
  FILE* md = fopen(path, "w");
  snprintf(path, sizeof path, "%s/plots/plots.gp", dir);
  FILE* gp = fopen(path, "w");
  if (md == NULL || gp == NULL) {
    perror("bench_report");
    return 1;
  }
  fprintf(gp,
          "# written by tools/bench_report.c: error against cost per accuracy scene\n"
          "set terminal pngcairo size 800,560 font 'sans,10'\n"
          "set logscale xy\nset grid\nset key top right\nset format y '10^{%%L}'\n"
          "set xlabel 'ms per 1/60 s of simulated time (log)'\n");

  fprintf(md, "# tumble benchmark: run time against error, beside Box2D 2.4.1%s\n\n", have_v3 ? " and Box2D v3" : "");
  if (have_v3) {
    fprintf(md,
            "Regenerate with `make bench-v3 BOX2D_V3_DIR=<a Box2D v3 tree>`: the accuracy scenes of `make bench` with "
            "Box2D v3 added (`BENCH_V3_ACCURACY=only` leaves out v3's speed scenes, `BENCH_V3_QUICK=1` runs the "
            "quick sweep). ");
  } else {
    fprintf(md,
            "Regenerate everything with `make bench` (about 15 minutes); `make bench-quick` runs a smaller sweep "
            "in about a minute. ");
  }
  char line[512];
  snprintf(path, sizeof path, "%s/machine.txt", dir);
  FILE* mf = fopen(path, "r");
  if (mf != NULL) {
    fprintf(md, "This run:\n\n");
    while (fgets(line, sizeof line, mf) != NULL) fprintf(md, "    %s", line);
    fclose(mf);
    fprintf(md, "\n");
  } else {
    fprintf(md, "\n\n");
  }
  fprintf(md,
          "How it is measured: every accuracy scene is written once (`tools/bench_accuracy.c`) against a small "
          "interface with a tumble and a Box2D 2.4.1 back end, so both engines get the same bodies, materials and "
          "start states (Box2D's bodies are placed 0.01 m further out per polygon, its `b2_polygonRadius` skin). "
          "Sleep is off. Each error is taken against a closed form (far_pyramid: against the same engine's run at "
          "the origin). Cost is the time spent in the engine's step call only, as **ms per 1/60 s of simulated "
          "time** (ms per step x (1/60) / dt), so that time steps compare at equal simulated time; it is the "
          "minimum over several runs. Defaults: tumble 60 Hz, 4 substeps, midpoint free flight (the library default; "
          "bodies in contact or jointed use the solver's semi-implicit Euler); Box2D 60 Hz, "
          "8 velocity / 3 position iterations. Sweeps: tumble substeps 1, 2, 4, 8, 16 x time steps 1/30 ... 1/240 "
          "(x integrators euler, midpoint, rk4 where only gravity and forces move the bodies); Box2D iterations "
          "4/2, 8/3, 16/6, 32/12 x the same time steps (pyramid_100 up to 120 Hz only). All rows are in "
          "`bench.csv`; errors of exactly 0 are drawn at 1e-12 on the log axes.%s%s\n\n",
          have_v3 ? " Box2D v3 (rows `box2d_v3`, built only by `make bench-v3`) runs the same scenes through its C API "
                    "(`tools/bench_engine_v3.c`) with its own defaults (contact and joint softness, continuous "
                    "collision); its polygons have no skin. Its default is 60 Hz, 4 substeps, and its sweep substeps "
                    "1, 2, 4, 8 x the same time steps. As in 2.4.1, mass_spring's spring force is applied once "
                    "before each step and held over v3's substeps."
                  : "",
          broken > 0 ? " **Some rows are marked broken (ok = 0): a step failed or a metric was NaN.**" : "");

  /* headline table */
  if (have_v3) {
    fprintf(md, "## Headline: tumble's default against Box2D 2.4.1's and Box2D v3's defaults\n\n");
  } else {
    fprintf(md, "## Headline: tumble's default against Box2D's default\n\n");
  }
  fprintf(
      md,
      "Error ratio < 1: tumble is more accurate; time ratio < 1: tumble is faster. Ties: errors within 1%% (or "
      "both below 1e-6, float round-off), times within 10%% (the spread of scenes that step in microseconds).%s\n\n",
      have_v3 ? " Box2D is 2.4.1, v3 is Box2D v3; ms is ms per 1/60 s of simulated time (at the defaults' 60 Hz, "
                "ms per step)."
              : "");
  if (have_v3) {
    fprintf(
        md,
        "| scene | error | tumble | Box2D | v3 | tumble ms | Box2D ms | v3 ms | error ratio | time ratio | verdict | "
        "error ratio to v3 | time ratio to v3 | verdict against v3 |\n");
    fprintf(md, "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | --- |\n");
  } else {
    fprintf(md, "| scene | error | tumble | Box2D | error ratio | time ratio | verdict |\n");
    fprintf(md, "| --- | --- | ---: | ---: | ---: | ---: | --- |\n");
  }
  static worse_list worse_b2, worse_v3;
  for (int k = 0; k < scene_count; ++k) {
    const char* s = scenes[k];
    int rt = default_row(&acc, s, "tumble"), rb = default_row(&acc, s, "box2d");
    if (rt < 0 || rb < 0) continue;
    const char* metric = "error";
    for (int m = 0; have_meta && m < meta.rows; ++m) {
      if (strcmp(get(&meta, m, "scene"), s) == 0) metric = get(&meta, m, "error");
    }
    comparison cb = compare(&acc, rt, rb);
    note_worse(&worse_b2, s, metric, "Box2D", &cb);
    if (!have_v3) {
      fprintf(md, "| [%s](#%s) | %s | %s | %s | %s | %s | %s |\n", s, s, metric, cb.tumble, cb.other, cb.error_ratio,
              cb.time_ratio, cb.verdict);
      continue;
    }
    int rv = default_row(&acc, s, "box2d_v3");
    comparison cv = {"-", "-", "-", "-", false, false, "-"};
    char v3_ms[32] = "-";
    if (rv >= 0) {
      cv = compare(&acc, rt, rv);
      note_worse(&worse_v3, s, metric, "v3", &cv);
      snprintf(v3_ms, sizeof v3_ms, "%.4f", num(&acc, rv, "ms_per_60hz_frame"));
    }
    fprintf(md, "| [%s](#%s) | %s | %s | %s | %s | %.4f | %.4f | %s | %s | %s | %s | %s | %s | %s |\n", s, s, metric,
            cb.tumble, cb.other, cv.other, num(&acc, rt, "ms_per_60hz_frame"), num(&acc, rb, "ms_per_60hz_frame"),
            v3_ms, cb.error_ratio, cb.time_ratio, cb.verdict, cv.error_ratio, cv.time_ratio, cv.verdict);
  }
  fprintf(md, "\n");
  print_worse(md, &worse_b2, "Box2D");
  print_worse(md, &worse_v3, "Box2D v3");

  /* targets */
  fprintf(md, "## Targets of issue 6\n\n");
  for (int k = 0; k < scene_count; ++k) {
    const char* s = scenes[k];
    if (strcmp(s, "projectile") != 0 && strcmp(s, "constant_spin") != 0) continue;
    double limit = strcmp(s, "projectile") == 0 ? 1e-4 : 1e-5;
    int rt = default_row(&acc, s, "tumble");
    if (rt < 0) continue;
    double best = INFINITY;
    char best_label[128] = "";
    for (int r = 0; r < acc.rows; ++r) {
      if (strcmp(get(&acc, r, "scene"), s) != 0 || strcmp(get(&acc, r, "engine"), "tumble") != 0) continue;
      if (strcmp(get(&acc, r, "hz"), "60") != 0) continue;
      if (num(&acc, r, "error") < best) {
        best = num(&acc, r, "error");
        setting_label(&acc, r, best_label, sizeof best_label);
      }
    }
    fprintf(md, "- %s within %g: default %.3g -> %s; best at 60 Hz %.3g (%s)\n", s, limit, num(&acc, rt, "error"),
            num(&acc, rt, "error") <= limit ? "**met**" : "**not met**", best, best_label);
  }
  fprintf(md,
          "- every accuracy scene at lower or equal error and step time than Box2D's default: see the verdict "
          "column above.\n\n");

  /* per scene */
  fprintf(md, "## Accuracy scenes\n\n");
  for (int k = 0; k < scene_count; ++k) {
    const char* s = scenes[k];
    int mrow = -1;
    for (int m = 0; have_meta && m < meta.rows; ++m) {
      if (strcmp(get(&meta, m, "scene"), s) == 0) mrow = m;
    }
    fprintf(md, "### %s\n\n", s);
    if (mrow >= 0) fprintf(md, "%s.\n\n", get(&meta, mrow, "definition"));
    int rt = default_row(&acc, s, "tumble"), rb = default_row(&acc, s, "box2d");
    int rv = have_v3 ? default_row(&acc, s, "box2d_v3") : -1;
    if (rt >= 0 && rb >= 0) {
      if (have_v3) {
        fprintf(md,
                "| at the defaults | tumble (60 Hz, 4 substeps) | Box2D (60 Hz, 8/3) | ratio | "
                "Box2D v3 (60 Hz, 4 substeps) | ratio to v3 |\n");
        fprintf(md, "| --- | ---: | ---: | ---: | ---: | ---: |\n");
      } else {
        fprintf(md, "| at the defaults | tumble (60 Hz, 4 substeps) | Box2D (60 Hz, 8/3) | ratio |\n");
        fprintf(md, "| --- | ---: | ---: | ---: |\n");
      }
      const char* cols[4] = {"error", "metric2", "metric3", "ms_per_60hz_frame"};
      for (int c = 0; c < 4; ++c) {
        const char* name = c == 3 ? "ms per 1/60 s" : mrow >= 0 ? get(&meta, mrow, cols[c]) : cols[c];
        if (name[0] == '\0') continue;
        char a[32], b[32], q[32];
        value_cell(&acc, rt, cols[c], a, sizeof a);
        value_cell(&acc, rb, cols[c], b, sizeof b);
        ratio(num(&acc, rt, cols[c]), num(&acc, rb, cols[c]), q, sizeof q);
        fprintf(md, "| %s | %s | %s | %s |", name, a, b, q);
        if (have_v3) {
          char v[32] = "-", qv[32] = "-";
          if (rv >= 0) {
            value_cell(&acc, rv, cols[c], v, sizeof v);
            ratio(num(&acc, rt, cols[c]), num(&acc, rv, cols[c]), qv, sizeof qv);
          }
          fprintf(md, " %s | %s |", v, qv);
        }
        fprintf(md, c == 3 ? "\n\n" : "\n");
      }
    }
    /* the Pareto fronts, as data for the plot and as a line in the report */
    static point pts[512];
    const char* engines[3] = {"tumble", "box2d", "box2d_v3"};
    const char* engine_names[3] = {"tumble", "Box2D", "Box2D v3"};
    bool v3_plotted = false;
    for (int e = 0; e < (have_v3 ? 3 : 2); ++e) {
      int n = collect(&acc, s, engines[e], pts);
      if (n == 0) continue;
      v3_plotted = v3_plotted || e == 2;
      mark_pareto(pts, n);
      write_sweep_data(dir, s, engines[e], pts, n);
      fprintf(md, "%s's Pareto front (cheapest first): ", engine_names[e]);
      bool first = true;
      for (int i = 0; i < n; ++i) {
        if (!pts[i].pareto) continue;
        char label[128], ev[32];
        setting_label(&acc, pts[i].row, label, sizeof label);
        fmt(num(&acc, pts[i].row, "error"), ev, sizeof ev);
        fprintf(md, "%s%s (%.4f ms, %s)", first ? "" : "; ", label, pts[i].cost, ev);
        first = false;
      }
      fprintf(md, ".\n\n");
    }
    fprintf(md, "![%s](plots/%s.png)\n\n", s, s);
    const char* ylabel = mrow >= 0 ? get(&meta, mrow, "error") : "error";
    fprintf(
        gp,
        "set output '%s.png'\nset title '%s: error against cost (filled: Pareto front, ringed: default)' noenhanced\n"
        "set ylabel '%s (log; 0 drawn at %g)' noenhanced\n",
        s, s, ylabel, ERROR_FLOOR);
    fprintf(gp,
            "plot '%s_tumble.dat' index 0 using 1:2 with points pt 6 ps 1.2 lc rgb '#1f77b4' title 'tumble sweep', \\\n"
            "     '%s_tumble.dat' index 1 using 1:2 with linespoints pt 7 ps 1.2 lw 2 lc rgb '#1f77b4' "
            "title 'tumble Pareto front', \\\n"
            "     '%s_box2d.dat' index 0 using 1:2 with points pt 4 ps 1.2 lc rgb '#d62728' title 'Box2D 2.4.1 "
            "sweep', \\\n"
            "     '%s_box2d.dat' index 1 using 1:2 with linespoints pt 5 ps 1.2 lw 2 lc rgb '#d62728' "
            "title 'Box2D Pareto front'",
            s, s, s, s);
    if (v3_plotted) {
      fprintf(gp,
              ", \\\n     '%s_box2d_v3.dat' index 0 using 1:2 with points pt 8 ps 1.2 lc rgb '#2ca02c' "
              "title 'Box2D v3 sweep', \\\n"
              "     '%s_box2d_v3.dat' index 1 using 1:2 with linespoints pt 9 ps 1.2 lw 2 lc rgb '#2ca02c' "
              "title 'Box2D v3 Pareto front'",
              s, s);
    }
    if (rt >= 0 && rb >= 0 && rv >= 0) {
      fprintf(gp,
              ", \\\n     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz; 4 "
              "substeps / 8-3 / v3 4 substeps)'\n%.6g %.6g\n%.6g %.6g\n%.6g %.6g\ne\n",
              num(&acc, rt, "ms_per_60hz_frame"), fmax(num(&acc, rt, "error"), ERROR_FLOOR),
              num(&acc, rb, "ms_per_60hz_frame"), fmax(num(&acc, rb, "error"), ERROR_FLOOR),
              num(&acc, rv, "ms_per_60hz_frame"), fmax(num(&acc, rv, "error"), ERROR_FLOOR));
    } else if (rt >= 0 && rb >= 0) {
      fprintf(gp,
              ", \\\n     '-' using 1:2 with points pt 6 ps 3.5 lw 2 lc rgb 'black' title 'defaults (60 Hz, 4 "
              "substeps / 8-3)'\n%.6g %.6g\n%.6g %.6g\ne\n",
              num(&acc, rt, "ms_per_60hz_frame"), fmax(num(&acc, rt, "error"), ERROR_FLOOR),
              num(&acc, rb, "ms_per_60hz_frame"), fmax(num(&acc, rb, "error"), ERROR_FLOOR));
    } else {
      fprintf(gp, "\n");
    }
  }

  /* performance scenes */
  if (have_perf) {
    fprintf(md, "## Performance scenes\n\n");
    fprintf(md,
            "Single thread, 60 Hz; tumble at 4 substeps, Box2D at 8/3 and 4/2. Each scene runs in its own "
            "process: a warm-up run, then several timed runs on fresh worlds; median and minimum of the runs' "
            "mean ms per step. Peak memory is the process's `ru_maxrss` (getrusage) at the end, its growth "
            "since before the first world in brackets. Contacts count touching manifolds (tumble includes "
            "speculative ones).\n\n");
    fprintf(md,
            "| scene | engine | bodies | awake | contacts | joints | median ms | min ms | ratio to Box2D 8/3 | "
            "peak MB (+MB) | state hash |\n");
    fprintf(md, "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n");
    for (int r = 0; r < perf.rows; ++r) {
      const char* scene = get(&perf, r, "scene");
      double b2 = 0.0;
      for (int q = 0; q < perf.rows; ++q) {
        if (strcmp(get(&perf, q, "scene"), scene) == 0 && strcmp(get(&perf, q, "engine"), "box2d-8/3") == 0)
          b2 = num(&perf, q, "ms_median");
      }
      char rt[32];
      ratio(num(&perf, r, "ms_median"), b2, rt, sizeof rt);
      fprintf(md, "| %s | %s | %s | %s | %s | %s | %.3f | %.3f | %s | %.1f (+%.1f) | `%s` |\n", scene,
              get(&perf, r, "engine"), get(&perf, r, "bodies"), get(&perf, r, "awake"), get(&perf, r, "contacts"),
              get(&perf, r, "joints"), num(&perf, r, "ms_median"), num(&perf, r, "ms_min"), rt,
              num(&perf, r, "peak_rss_kb") / 1024.0, num(&perf, r, "delta_rss_kb") / 1024.0, get(&perf, r, "hash"));
    }
    fprintf(md,
            "\nTarget: large_pyramid and many_pyramids at most 0.33 x Box2D 2.4.1's step time (ratio column, "
            "tumble-4 rows).\n\n");
  }
  if (have_profile) {
    fprintf(md, "### tumble's per-step profile (`tb_world_get_profile`), mean over the last timed run\n\n");
    fprintf(md,
            "| scene | step ms | broad phase | narrow phase | solver | continuous | islands | awake bodies | "
            "awake contacts | awake joints | pairs | new pairs | swept |\n");
    fprintf(md, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (int r = 0; r < profile.rows; ++r) {
      fprintf(md, "| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.0f | %.0f | %.0f | %.0f | %.1f | %.1f |\n",
              get(&profile, r, "scene"), num(&profile, r, "step"), num(&profile, r, "broad_phase"),
              num(&profile, r, "narrow_phase"), num(&profile, r, "solver"), num(&profile, r, "continuous"),
              num(&profile, r, "islands"), num(&profile, r, "awake_bodies"), num(&profile, r, "awake_contacts"),
              num(&profile, r, "awake_joints"), num(&profile, r, "pairs"), num(&profile, r, "new_pairs"),
              num(&profile, r, "swept"));
    }
    fprintf(md, "\n");
  }

  /* scaling */
  if (have_scaling) {
    fprintf(md, "## Step time against body count\n\n");
    fprintf(md,
            "A pyramid of unit boxes of base 10 to 140 (55 to 9,870 bodies), sleep off, 30 untimed steps then "
            "timed ones; tumble 60 Hz / 4 substeps, Box2D 60 Hz / 8-3.\n\n");
    fprintf(md, "| base | bodies | tumble ms | Box2D ms | ratio |\n| ---: | ---: | ---: | ---: | ---: |\n");
    snprintf(path, sizeof path, "%s/plots/scaling.dat", dir);
    FILE* sd = fopen(path, "w");
    if (sd == NULL) {
      perror(path);
      return 1;
    }
    fprintf(sd, "# bodies tumble_ms box2d_ms\n");
    for (int r = 0; r < scaling.rows; ++r) {
      if (strcmp(get(&scaling, r, "engine"), "tumble") != 0) continue;
      for (int q = 0; q < scaling.rows; ++q) {
        if (strcmp(get(&scaling, q, "engine"), "box2d") != 0 ||
            strcmp(get(&scaling, q, "base"), get(&scaling, r, "base")) != 0)
          continue;
        double t = num(&scaling, r, "ms_step_min"), b = num(&scaling, q, "ms_step_min");
        fprintf(md, "| %s | %s | %.3f | %.3f | %.3g |\n", get(&scaling, r, "base"), get(&scaling, r, "bodies"), t, b,
                t / b);
        fprintf(sd, "%s %.6g %.6g\n", get(&scaling, r, "bodies"), t, b);
      }
    }
    fclose(sd);
    fprintf(md, "\n![step time against body count](plots/scaling.png)\n\n");
    fprintf(gp,
            "set output 'scaling.png'\nset title 'pyramids of base 10 to 140: step time against body count'\n"
            "set xlabel 'bodies (log)'\nset ylabel 'ms per step (log)'\nset format y '%%g'\nset key top left\n"
            "plot 'scaling.dat' using 1:2 with linespoints pt 7 lw 2 lc rgb '#1f77b4' title 'tumble (4 substeps)', \\\n"
            "     'scaling.dat' using 1:3 with linespoints pt 5 lw 2 lc rgb '#d62728' title 'Box2D 2.4.1 (8/3)'\n");
  }

  /* skip costs */
  if (have_skip) {
    fprintf(md, "## What a scene does not use costs nothing\n\n");
    fprintf(md, "| measurement | baseline ms/step | with it ms/step | ratio | bound | result |\n");
    fprintf(md, "| --- | ---: | ---: | ---: | ---: | --- |\n");
    for (int r = 0; r < skip.rows; ++r) {
      fprintf(md, "| %s | %.4f | %.4f | %.3f | %s | %s |\n", get(&skip, r, "what"), num(&skip, r, "baseline_ms"),
              num(&skip, r, "with_ms"), num(&skip, r, "ratio"), get(&skip, r, "bound"), get(&skip, r, "result"));
    }
    fprintf(md, "\nSee `tools/bench_skip.c` for the worlds; the times are the minimum over the runs.\n\n");
  }
  fclose(md);
  fclose(gp);
  if (broken > 0) fprintf(stderr, "bench_report: %d broken row(s) in bench.csv\n", broken);
  return broken > 0 ? 1 : 0;
}
