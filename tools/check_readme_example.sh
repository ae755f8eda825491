#!/usr/bin/env bash
# Compiles and runs the two C examples of README.md against an installed
# tumble (PREFIX, e.g. from `make install PREFIX=...`), the way a user would:
# flags from `pkg-config --cflags --libs tumble` (the first ```c block) and
# `... tumble-render` (the block that includes tumble_render.h), and run
# without LD_LIBRARY_PATH (the .pc files' rpath finds the libraries). The
# render example must write a valid, non-empty PNG.
# Usage: tools/check_readme_example.sh PREFIX
set -euo pipefail
prefix=${1:?usage: check_readme_example.sh PREFIX}
readme=$(pwd)/README.md
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
fail() { echo "check_readme_example: $*" >&2; exit 1; }

# block N (1-based) of the ```c blocks of README.md
c_block() { awk -v want="$1" '/^```c$/ {n++; if (n == want) on=1; next} /^```$/ && on {exit} on' "$readme"; }
blocks=$(grep -c '^```c$' "$readme")
c_block 1 > "$dir/example.c"
for ((i = 2; i <= blocks; i++)); do
  if c_block "$i" | grep -q '#include "tumble_render.h"'; then c_block "$i" > "$dir/render_example.c"; fi
done
[ -s "$dir/example.c" ] || fail "README.md has no \`\`\`c example"
[ -s "$dir/render_example.c" ] || fail "README.md has no \`\`\`c example that includes tumble_render.h"

build() { # source package
  # shellcheck disable=SC2046 # pkg-config's flags are words
  ${CC:-cc} -std=c17 -Wall -Wextra -Wpedantic -Werror "$dir/$1.c" $(pkg-config --cflags --libs "$2") -o "$dir/$1"
}
build example tumble
build render_example tumble-render
(cd "$dir" && env -u LD_LIBRARY_PATH ./example > out.txt) || fail "the embedding example did not run"
echo "== README example: compiled with pkg-config tumble, ran without LD_LIBRARY_PATH ($(wc -l < "$dir/out.txt") lines of output)"

(cd "$dir" && env -u LD_LIBRARY_PATH MESA_SHADER_CACHE_DISABLE=true ./render_example > /dev/null) ||
  fail "the render example did not run"
png=$(cd "$dir" && ls ./*.png 2>/dev/null | head -1)
[ -n "$png" ] || fail "the render example wrote no PNG"
png=$dir/${png#./}
size=$(wc -c < "$png")
# signature, an IHDR chunk first with a width and height > 0, an IEND chunk last
[ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "$png: not a PNG signature"
[ "$(head -c 16 "$png" | tail -c 4)" = IHDR ] || fail "$png: no IHDR chunk first"
width=$(head -c 20 "$png" | tail -c 4 | od -An -tu1 | awk '{print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4}')
height=$(head -c 24 "$png" | tail -c 4 | od -An -tu1 | awk '{print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4}')
[ "$width" -gt 0 ] && [ "$height" -gt 0 ] || fail "$png: size ${width}x$height"
[ "$(tail -c 8 "$png" | head -c 4)" = IEND ] || fail "$png: no IEND chunk last"
[ "$size" -gt 1000 ] || fail "$png: only $size bytes"
echo "== README render example: compiled with pkg-config tumble-render, wrote a ${width}x$height PNG ($size bytes)"
