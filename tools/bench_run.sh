#!/bin/sh
# Runs the whole benchmark of issue 6 and writes its results:
#   tools/bench_run.sh BENCH_BIN_DIR RESULTS_DIR [quick]
# RESULTS_DIR gets machine.txt, perf.csv + profile.csv (performance scenes,
# both engines), bench.csv + scenes.tsv (accuracy sweep), scaling.csv,
# skip.csv, REPORT.md and plots/*.png. "quick" runs the smaller, shorter
# versions (make bench-quick). Stops at the first failing program (NaN, a
# failed step, a crash), so the exit status tells CI the bench is broken.
set -eu
bin=$1
out=$2
mode=${3:-full}
quick=
[ "$mode" = quick ] && quick=--quick

mkdir -p "$out/plots"
rm -f "$out/perf.csv" "$out/profile.csv" "$out/plots/"*.dat "$out/plots/"*.png

{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "machine: $(uname -srm), $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //'), $(nproc) cores"
  echo "compilers: $(${CC:-cc} --version | head -n1); $(${CXX:-c++} --version | head -n1); Box2D 2.4.1 (Debian libbox2d)"
  echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "mode: $mode"
} > "$out/machine.txt"

echo "== performance scenes (tumble, Box2D 2.4.1 at 8/3 and 4/2)"
"$bin/bench_dynamics" $quick --csv "$out/perf.csv" --profile-csv "$out/profile.csv"
"$bin/bench_dynamics_b2" $quick --csv "$out/perf.csv"
echo "== accuracy sweep"
"$bin/bench_accuracy" $quick --csv "$out/bench.csv" --meta "$out/scenes.tsv"
echo "== step time against body count"
"$bin/bench_accuracy" $quick --scaling --csv "$out/scaling.csv"
echo "== skip costs"
"$bin/bench_skip" $quick --csv "$out/skip.csv"
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
