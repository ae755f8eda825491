#!/usr/bin/env bash
# Smoke test of tumble-viewer: a scripted run in SDL's offscreen video driver
# (EGL with Mesa's llvmpipe: no display, no GPU), checked through what the
# viewer prints. Usage: tools/viewer_smoke.sh [path/to/tumble-viewer]
# Exits non-zero when the viewer fails or an expected line is missing.
set -u
viewer=${1:-build/tumble-viewer}
if [ ! -x "$viewer" ]; then
  echo "viewer_smoke: $viewer is not built (make viewer)" >&2
  exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
log=$tmp/log

# Under `make sanitize` the viewer keeps ASan's memory-error checks and UBSan,
# but not LeakSanitizer: SDL's video and EGL drivers are dlopen'ed and closed
# again, so what they leave at exit shows as leaks from "<unknown module>" that
# no suppression can name (measured: 1.06 MB in 261 blocks, not one from
# tumble or the viewer). A build without ASan ignores the variable.
SDL_VIDEODRIVER=offscreen MESA_SHADER_CACHE_DISABLE=true ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" \
  timeout 120 "$viewer" --scene pyramid_20 --frames 120 --script --screenshot "$tmp/last.ppm" >"$log" 2>&1
status=$?
sed 's/^/   | /' "$log"
failures=0
fail() {
  echo "viewer_smoke: FAIL: $*"
  failures=$((failures + 1))
}
[ "$status" -eq 0 ] || fail "exit status $status"

# expect REGEX WHAT: some line of the log matches the extended regex
expect() {
  grep -Eq -- "$1" "$log" || fail "no line for $2 (/$1/)"
}
expect '^video driver offscreen, OpenGL ' "the offscreen GL context"
expect '^scene [0-9]+/[0-9]+: pyramid_20: ' "the first scene"
expect '^paused at t = 0\.033 s' "pause"
expect '^step 3: t = 0\.050 s' "a single step while paused (s)"
expect '^step 4: t = 0\.067 s' "a single step while paused (right arrow)"
expect '^running at t = 0\.067 s' "resume"
expect "^dragging body [0-9]+ 'top' " "a drag of the pyramid's top box"
expect '^zoom in: ' "zoom in"
expect '^zoom out: ' "zoom out"
expect '^pan: centre ' "pan"
for s in shapes joints aabbs contacts normals com masses; do
  expect "^$s off\$" "switching $s off"
  expect "^$s on\$" "switching $s on"
done
expect '^camera fitted: ' "fit the camera"
expect '^restart pyramid_20$' "restart"
expect '^scene [0-9]+/[0-9]+: mass_ratio: ' "the next scene"
[ "$(grep -Ec '^scene [0-9]+/[0-9]+: pyramid_20: ' "$log")" -eq 3 ] ||
  fail "pyramid_20 loaded 3 times (start, restart, previous scene)"
expect '^no dynamic body at ' "a click on empty space"
expect '^exit after 120 frames: scene pyramid_20, ' "the frame limit"

# The dragged box moved up and right with the mouse by more than a metre.
moved=$(sed -nE 's/^released body [0-9]+: moved by \(([-0-9.]+), ([-0-9.]+)\) m, ([0-9.]+) m$/\1 \2 \3/p' "$log")
if [ -z "$moved" ]; then
  fail "no release line"
else
  read -r dx dy d <<<"$moved"
  awk -v dx="$dx" -v dy="$dy" -v d="$d" 'BEGIN { exit !(dx > 0 && dy > 0 && d > 1.0) }' ||
    fail "the dragged body moved by ($dx, $dy), $d m: expected up and right, more than 1 m"
fi
# The last frame, read back from GL, shows something: at least 1% of the
# pixels differ from the background (the pyramid, the ground, the overlay).
shot=$(sed -nE 's/^screenshot .*: ([0-9]+)x([0-9]+), ([0-9]+) pixels differ from the background$/\1 \2 \3/p' "$log")
if [ -z "$shot" ]; then
  fail "no screenshot line"
else
  read -r w h drawn <<<"$shot"
  [ "$drawn" -gt $((w * h / 100)) ] || fail "the last frame is (nearly) blank: $drawn of $((w * h)) pixels drawn"
  [ "$(stat -c %s "$tmp/last.ppm")" -gt $((w * h * 3)) ] || fail "the screenshot file is short"
fi
if grep -Eq 'tumble-viewer: ' "$log"; then fail "the viewer reported errors"; fi

if [ "$failures" -ne 0 ]; then
  echo "viewer_smoke: $failures check(s) failed"
  exit 1
fi
echo "viewer_smoke: ok (pause, step, drag ${d} m, zoom, pan, 7 switches, restart, next/previous scene, 120 frames)"
