#!/usr/bin/env bash
# Compiles and runs the embedding example of README.md (its first ```c block)
# against the freshly built library, so the README's code keeps compiling.
set -euo pipefail
build=${1:-build}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
awk '/^```c$/ {on=1; next} /^```$/ && on {exit} on' README.md > "$dir/example.c"
if [ ! -s "$dir/example.c" ]; then echo "README.md has no \`\`\`c example" >&2; exit 1; fi
${CC:-cc} -std=c17 -Wall -Wextra -Wpedantic -Werror -Iinclude "$dir/example.c" "$build/libtumble.a" -lm -o "$dir/example"
"$dir/example" > "$dir/out.txt"
echo "== README example: compiled and ran ($(wc -l < "$dir/out.txt") lines of output)"
