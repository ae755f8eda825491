#!/usr/bin/env bash
# tumble beside Box2D v3 on v3's benchmark scenes (make bench-v3, issue 21).
#   tools/bench_v3.sh BENCH_DIR RUNS V3_TREE [SCENE ...]
# Interleaved: for each run, for each scene, one tumble process then one v3
# process (bench_v3_tumble / bench_v3_box2d: build, step 0 untimed, steps
# 1..N-1 timed in process CPU time, 60 Hz x 4 substeps, one thread). A scene's
# figure is the minimum over the runs (the least disturbed on a shared machine);
# the ratio is tumble's minimum over v3's. Writes BENCH_DIR/v3/runs.txt (every
# run) and BENCH_DIR/v3/REPORT.md (the table, the counts, v3's commit).
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
  echo "and per contact, pairs counted as contacts):"
  echo
  echo '```'
  for s in "${scenes[@]}"; do grep -E "^(tumble|box2d_v3) $s " "$out/runs.txt" | tail -n 2 | cut -d' ' -f1,2,5-; done
  echo '```'
} >"$out/REPORT.md"
cat "$out/REPORT.md"
