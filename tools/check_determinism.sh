#!/bin/sh
# Same scene, same hash at -O0 and -O2 (see tools/determinism.c).
set -e
a=$("$1")
b=$("$2")
if [ "$a" != "$b" ]; then
  echo "determinism: FAILED: -O2 hash $a, -O0 hash $b" >&2
  exit 1
fi
echo "determinism: -O0 and -O2 builds agree after 1,000 steps (hash $a)"
