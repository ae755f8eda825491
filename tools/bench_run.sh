#!/bin/sh
# Runs the whole benchmark of issue 6 and writes its results:
#   tools/bench_run.sh BENCH_BIN_DIR RESULTS_DIR [quick]
# RESULTS_DIR gets machine.txt, perf.csv + profile.csv (performance scenes,
# both engines), bench.csv + scenes.tsv (accuracy sweep), scaling.csv,
# skip.csv, REPORT.md and plots/*.png. "quick" runs the smaller, shorter
# versions (make bench-quick). Stops at the first failing program (NaN, a
# failed step, a crash), so the exit status tells CI the bench is broken.
#
#   tools/bench_run.sh BENCH_BIN_DIR RESULTS_DIR v3|v3-quick V3_TREE
# (make bench-v3, issue 21): only the accuracy sweep, by bench_accuracy_v3
# (tumble, Box2D 2.4.1 and the Box2D v3 built from V3_TREE), its report and
# plots; v3-quick is its --quick sweep.
set -eu
bin=$1
out=$2
mode=${3:-full}
quick=
case "$mode" in quick | v3-quick) quick=--quick ;; esac
v3=
case "$mode" in v3 | v3-quick) v3=${4:?tools/bench_run.sh: $mode needs the v3 tree} ;; esac

mkdir -p "$out/plots"
rm -f "$out/perf.csv" "$out/profile.csv" "$out/plots/"*.dat "$out/plots/"*.png

{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "machine: $(uname -srm), $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //'), $(nproc) cores"
  echo "compilers: $(${CC:-cc} --version | head -n1); $(${CXX:-c++} --version | head -n1); Box2D 2.4.1 (Debian libbox2d)"
  [ -z "$v3" ] || echo "Box2D v3: commit $(git -C "$v3" rev-parse HEAD 2>/dev/null || echo unknown) of $v3 (cmake Release)"
  echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "mode: $mode"
} > "$out/machine.txt"

if [ -n "$v3" ]; then
  echo "== accuracy sweep (tumble, Box2D 2.4.1, Box2D v3)"
  "$bin/bench_accuracy_v3" $quick --csv "$out/bench.csv" --meta "$out/scenes.tsv"
else
  echo "== performance scenes (tumble, Box2D 2.4.1 at 8/3 and 4/2)"
  "$bin/bench_dynamics" $quick --csv "$out/perf.csv" --profile-csv "$out/profile.csv"
  "$bin/bench_dynamics_b2" $quick --csv "$out/perf.csv"
  echo "== accuracy sweep"
  "$bin/bench_accuracy" $quick --csv "$out/bench.csv" --meta "$out/scenes.tsv"
  echo "== step time against body count"
  "$bin/bench_accuracy" $quick --scaling --csv "$out/scaling.csv"
  echo "== skip costs"
  "$bin/bench_skip" $quick --csv "$out/skip.csv"
fi
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)" >> "$out/machine.txt"
echo "== report and plots"
"$bin/bench_report" "$out"
if command -v gnuplot >/dev/null 2>&1; then
  (cd "$out/plots" && gnuplot plots.gp)
else
  echo "gnuplot not found: no plots (tools/deps.sh bench installs it)" >&2
  exit 1
fi
echo "written: $out/REPORT.md, $out/bench.csv, $out/plots/"
