#!/usr/bin/env bash
# tumble beside Box2D v3 on v3's benchmark scenes (make bench-v3, issue 21).
#   tools/bench_v3.sh BENCH_DIR RUNS V3_TREE [SCENE ...]
# Interleaved: for each run, for each scene, one tumble process then one v3
# process (bench_v3_tumble / bench_v3_box2d: build, step 0 untimed, steps
# 1..N-1 timed in process CPU time, 60 Hz x 4 substeps, one thread). A scene's
# figure is the minimum over the runs (the least disturbed on a shared machine);
# the ratio is tumble's minimum over v3's. Writes BENCH_DIR/v3/runs.txt (every
# run) and BENCH_DIR/v3/REPORT.md (the table, the counts, v3's commit).
# Then the small-pyramid scaling rows (pyramid_base_N, N = 5, 10, 20, 40, 100,
# sleeping off, interleaved the same way): a table of step time against body
# count and the plot BENCH_DIR/v3/scaling.png (when gnuplot is there).
set -euo pipefail
bench=$1 runs=$2 tree=$3
shift 3
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(compounds joint_grid junkyard large_pyramid many_pyramids rain smash spinner tumbler washer)
out=$bench/v3
mkdir -p "$out"
: >"$out/runs.txt"
: >"$out/errors.txt"
for ((r = 1; r <= runs; ++r)); do
  for s in "${scenes[@]}"; do
    # a scene tumble's catalogue does not have (yet) is reported, not fatal
    "$bench/bench_v3_tumble" "$s" >>"$out/runs.txt" 2>>"$out/errors.txt" || echo "tumble $s - missing" >>"$out/runs.txt"
    "$bench/bench_v3_box2d" "$s" >>"$out/runs.txt"
  done
  echo "run $r of $runs done" >&2
done
bases=(5 10 20 40 100)
: >"$out/scaling_runs.txt"
for ((r = 1; r <= runs; ++r)); do
  for b in "${bases[@]}"; do
    "$bench/bench_v3_tumble" "pyramid_base_$b" >>"$out/scaling_runs.txt"
    "$bench/bench_v3_box2d" "pyramid_base_$b" >>"$out/scaling_runs.txt"
  done
  echo "scaling run $r of $runs done" >&2
done
# body count (the boxes, not the ground), tumble's and v3's minimum ms per step
for b in "${bases[@]}"; do
  awk -v s="pyramid_base_$b" -v n=$((b * (b + 1) / 2)) '
    $2 == s && $1 == "tumble" { if (t == "" || $4 < t) t = $4 }
    $2 == s && $1 == "box2d_v3" { if (v == "" || $4 < v) v = $4 }
    END { printf "%d %d %.4f %.4f\n", substr(s, 14), n, t, v }' "$out/scaling_runs.txt"
done >"$out/scaling.dat"
if command -v gnuplot >/dev/null 2>&1; then
  gnuplot <<GP
set terminal pngcairo size 800,560
set output "$out/scaling.png"
set title "Pyramids of base 5 to 100, sleeping off, 60 Hz x 4 substeps, 1 thread"
set logscale xy
set xlabel "boxes"
set ylabel "ms per step (min of $runs interleaved runs)"
set key top left
set grid
plot "$out/scaling.dat" using 2:3 with linespoints title "tumble", "$out/scaling.dat" using 2:4 with linespoints title "Box2D v3"
GP
else
  echo "gnuplot not found: no scaling plot (tools/deps.sh bench installs it)" >&2
fi
commit=$(git -C "$tree" rev-parse HEAD 2>/dev/null || echo unknown)
{
  echo "# tumble beside Box2D v3 ($(date -u +%Y-%m-%d), v3 commit $commit)"
  echo
  echo "One thread, 60 Hz x 4 substeps, process CPU time per step of steps 1..N-1 (v3's protocol), minimum of"
  echo "$runs interleaved runs per engine; tumble's scenes with v3's sleep settings. \`make bench-v3 BOX2D_V3_DIR=...\`."
  echo
  echo "| scene | steps | tumble ms/step | v3 ms/step | tumble / v3 |"
  echo "| --- | ---: | ---: | ---: | ---: |"
  for s in "${scenes[@]}"; do
    awk -v s="$s" '
      $2 == s && $1 == "tumble" && $4 != "-" { if (t == "" || $4 < t) t = $4; steps = $3 }
      $2 == s && $1 == "box2d_v3" { if (v == "" || $4 < v) v = $4; steps = $3 }
      END {
        if (t == "") printf "| %s | %d | no such scene in tumble | %.3f | - |\n", s, steps, v;
        else printf "| %s | %d | %.3f | %.3f | %.2f |\n", s, steps, t, v, t / v }' "$out/runs.txt"
  done
  echo
  echo "Counts at the end of the last run (bodies, shapes, joints; pairs = shape pairs whose fat boxes overlap;"
  echo "touching = tumble's contacts with manifold points; coloured = constraints in v3's graph colours; bytes = tumble's"
  echo "world memory (tb_world_get_memory_stats), body_bytes and contact_bytes its body and contact parts per body"
  echo "and per contact, pairs counted as contacts; relax = tumble's relax passes per substep over the timed steps,"
  echo "at most its relax_iterations, 8: v3 runs one):"
  echo
  echo '```'
  for s in "${scenes[@]}"; do grep -E "^(tumble|box2d_v3) $s " "$out/runs.txt" | tail -n 2 | cut -d' ' -f1,2,5-; done
  echo '```'
  echo
  echo "Small pyramids (pyramid_base_N: large_pyramid's layout with a base of N boxes, sleeping off, 500 steps;"
  echo "plot: scaling.png):"
  echo
  echo "| base | boxes | tumble ms/step | v3 ms/step | tumble / v3 |"
  echo "| ---: | ---: | ---: | ---: | ---: |"
  awk '{ printf "| %d | %d | %.3f | %.3f | %.2f |\n", $1, $2, $3, $4, $3 / $4 }' "$out/scaling.dat"
} >"$out/REPORT.md"
cat "$out/REPORT.md"
