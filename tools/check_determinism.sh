#!/bin/sh
# Same scene, same hash at -O0 and -O3 (see tools/determinism.c).
set -e
a=$("$1")
b=$("$2")
if [ "$a" != "$b" ]; then
  echo "determinism: FAILED: -O3 hash $a, -O0 hash $b" >&2
  exit 1
fi
echo "determinism: -O0 and -O3 builds agree after 1,000 steps (hash $a)"
